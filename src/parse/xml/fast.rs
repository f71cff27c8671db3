//! A fast path for the element tree of the XML that RTCBuilder writes: elements with ASCII
//! names, double- or single-quoted attributes, namespace declarations, text with the five
//! entities and character references, comments, and an XML declaration at the start.
//!
//! quick-xml's namespace reader looks at every start tag's attributes twice (once for the
//! declarations); this builder reads a tag once, and builds the same [`Node`] tree with the same positions, through the same helpers
//! ([`add_text`], [`unescape_attr`], [`PosCursor`]) as [`build_tree`]. It returns `None` for
//! anything else — CDATA sections, processing instructions, a DOCTYPE, non-ASCII or odd names,
//! unquoted or duplicate attributes, `<` or `>` in attribute values, undeclared prefixes,
//! mismatched or missing end tags, text outside the root, nesting at the depth limit, a root
//! that is not `RtcProfile` — and the caller then runs [`build_tree`], which also produces
//! every error. A differential property test holds the two equal on generated and mutated
//! documents.

use super::{add_text, close, is_ascii_name_byte, is_name, is_ns_declaration};
use super::{is_schema_plumbing, unescape_attr, Attr, Node, Ns, TreeBuilder};
use std::borrow::Cow;

/// An attribute as written: name, offset of the name, raw value.
type RawAttr<'t> = (&'t str, usize, &'t str);

/// The most attributes a tag may have on this path (duplicates are looked for pairwise).
const MAX_ATTRS: usize = 64;

/// One namespace binding: prefix (`""` for the default namespace) and what it resolves to.
struct Binding<'t> {
    prefix: &'t str,
    ns: Option<Ns>,
}

/// The tree of `text` when it is in the subset this builder reads and its root is an RTC
/// profile; `None` otherwise.
pub(super) fn build<'t>(text: &'t str, file: &str, max_depth: usize) -> Option<Node<'t>> {
    let mut b = TreeBuilder::new(text, file, max_depth);
    let bytes = text.as_bytes();
    let mut i = 0;
    if text.starts_with("<?xml ") {
        let end = text.find("?>")?;
        let decl = &bytes[6..end];
        if !decl.iter().all(|c| {
            c.is_ascii_alphanumeric()
                || matches!(c, b' ' | b'=' | b'"' | b'\'' | b'.' | b'_' | b'-')
        }) {
            return None;
        }
        i = end + 2;
    }
    let mut stack: Vec<Node<'t>> = Vec::new();
    // Bindings in scope, innermost last; `scopes[k]` is where element k's bindings start.
    let mut bindings: Vec<Binding<'t>> = Vec::new();
    let mut scopes: Vec<usize> = Vec::new();
    // The raw attributes of the tag being read, the same list for every tag.
    let mut raw: Vec<RawAttr<'t>> = Vec::new();
    let mut root: Option<Node<'t>> = None;
    while i < bytes.len() {
        if bytes[i] != b'<' {
            let end = memchr::memchr(b'<', &bytes[i..]).map_or(bytes.len(), |n| i + n);
            text_run(&mut b, &mut stack, i, end)?;
            i = end;
            continue;
        }
        let rest = &bytes[i + 1..];
        match rest.first()? {
            b'/' => {
                let end = i + 2 + memchr::memchr(b'>', &rest[1..])?;
                let name = &text[i + 2..end];
                let node = stack.pop()?;
                if node.qname != name {
                    return None;
                }
                bindings.truncate(scopes.pop()?);
                close(node, &mut stack, &mut root);
                i = end + 1;
            }
            b'!' if rest.starts_with(b"!--") => {
                let body = i + 4;
                let end = body + memchr::memmem::find(&bytes[body..], b"--")?;
                if bytes.get(end + 2) != Some(&b'>') {
                    return None;
                }
                i = end + 3;
            }
            b'!' | b'?' => return None,
            _ => {
                if (root.is_some() && stack.is_empty()) || stack.len() >= b.max_depth {
                    return None;
                }
                let (node, empty, next) =
                    start_tag(&mut b, &mut bindings, &mut scopes, &mut raw, i)?;
                if empty {
                    bindings.truncate(scopes.pop()?);
                    close(node, &mut stack, &mut root);
                } else {
                    stack.push(node);
                }
                i = next;
            }
        }
    }
    if !stack.is_empty() {
        return None;
    }
    root.filter(|r| r.local == "RtcProfile" && r.ns.is_rtc_family())
}

/// Character data from `start` to `end` (the next `<`): text chunks and references, handed to
/// [`add_text`] one by one as quick-xml's events are.
fn text_run<'t>(
    b: &mut TreeBuilder<'t, '_>,
    stack: &mut [Node<'t>],
    start: usize,
    end: usize,
) -> Option<()> {
    let text = b.text;
    let mut i = start;
    while i < end {
        let amp = memchr::memchr(b'&', &text.as_bytes()[i..end]).map_or(end, |n| i + n);
        if amp > i {
            let chunk = &text[i..amp];
            add_text(b, stack, &super::normalize_eol(chunk), i).ok()?;
        }
        if amp == end {
            break;
        }
        let semi = amp + memchr::memchr(b';', &text.as_bytes()[amp..end])?;
        let name = &text[amp + 1..semi];
        if name.is_empty() || !name.bytes().all(|c| c.is_ascii_alphanumeric() || c == b'#') {
            return None;
        }
        let s = super::resolve_ref(name).ok()?;
        add_text(b, stack, &s, amp).ok()?;
        i = semi + 1;
    }
    Some(())
}

/// The start tag at `at` (`<name attr="v" …>` or `…/>`): the node, whether it is empty, and
/// the offset after the tag. Pushes the tag's namespace bindings and its scope.
fn start_tag<'t>(
    b: &mut TreeBuilder<'t, '_>,
    bindings: &mut Vec<Binding<'t>>,
    scopes: &mut Vec<usize>,
    raw: &mut Vec<RawAttr<'t>>,
    at: usize,
) -> Option<(Node<'t>, bool, usize)> {
    let text = b.text;
    let bytes = text.as_bytes();
    let name_end = at
        + 1
        + bytes[at + 1..]
            .iter()
            .position(|c| !is_ascii_name_byte(c))?;
    let qname = &text[at + 1..name_end];
    if !name_start(qname) {
        return None;
    }
    let (prefix, local) = split(qname)?;
    scopes.push(bindings.len());
    // Raw attributes first: declarations apply to the tag's own name and attributes.
    raw.clear();
    let mut i = name_end;
    let (empty, next) = loop {
        let ws = bytes[i..]
            .iter()
            .take_while(|c| matches!(c, b' ' | b'\t' | b'\n' | b'\r'))
            .count();
        i += ws;
        match bytes.get(i)? {
            b'>' => break (false, i + 1),
            b'/' if bytes.get(i + 1) == Some(&b'>') => break (true, i + 2),
            _ if ws == 0 => return None,
            _ => {}
        }
        let key_start = i;
        let key_len = bytes[i..].iter().position(|c| !is_ascii_name_byte(c))?;
        let key = &text[i..i + key_len];
        if !name_start(key) || bytes.get(i + key_len) != Some(&b'=') {
            return None;
        }
        i += key_len + 1;
        let q = *bytes.get(i)?;
        if q != b'"' && q != b'\'' {
            return None;
        }
        let v_start = i + 1;
        let v_end = v_start + memchr::memchr(q, &bytes[v_start..])?;
        let value = &text[v_start..v_end];
        // A duplicate is looked for among the attributes before it; a tag with very many is
        // left to `build_tree` (whose check stays linear).
        if value.contains(['<', '>'])
            || raw.len() >= MAX_ATTRS
            || raw.iter().any(|&(k, _, _)| k == key)
        {
            return None;
        }
        raw.push((key, key_start, value));
        i = v_end + 1;
    };
    for &(key, _, value) in raw.iter() {
        if key == "xmlns" {
            bindings.push(Binding {
                prefix: "",
                ns: (!value.is_empty()).then(|| Ns::from_uri(value.as_bytes())),
            });
        } else if let Some(p) = key.strip_prefix("xmlns:") {
            if value.is_empty() || p.is_empty() || p == "xml" || p == "xmlns" || p.contains(':') {
                return None;
            }
            bindings.push(Binding {
                prefix: p,
                ns: Some(Ns::from_uri(value.as_bytes())),
            });
        }
    }
    let ns = resolve(bindings, prefix, true)?;
    let pos = b.cursor.pos(at);
    let mut attrs = Vec::new();
    for &(key, key_off, value) in raw.iter() {
        if is_ns_declaration(key.as_bytes()) {
            continue;
        }
        let (aprefix, alocal) = split(key)?;
        let ans = resolve(bindings, aprefix, false)?;
        if is_schema_plumbing(&ans, alocal) {
            continue;
        }
        let value = unescape_attr(Cow::Borrowed(value)).ok()?;
        attrs.push(Attr {
            qname: Cow::Borrowed(key),
            ns: ans,
            local: Cow::Borrowed(alocal),
            value,
            pos: b.cursor.pos(key_off),
        });
    }
    let node = Node {
        qname: Cow::Borrowed(qname),
        ns,
        local: Cow::Borrowed(local),
        attrs,
        children: Vec::new(),
        text: String::new(),
        text_pos: None,
        pos,
    };
    Some((node, empty, next))
}

/// True when a name made of `[A-Za-z0-9_:.-]` (as scanned) is an XML name: it starts with a
/// letter, `_` or `:` (what [`is_name`] decides for such names).
fn name_start(name: &str) -> bool {
    let ok = name
        .as_bytes()
        .first()
        .is_some_and(|c| c.is_ascii_alphabetic() || matches!(c, b'_' | b':'));
    debug_assert_eq!(ok, is_name(name), "{name:?}");
    ok
}

/// `prefix:local` or `local`; `None` for more than one colon, an empty part, or the reserved
/// prefixes `xml` and `xmlns`.
fn split(qname: &str) -> Option<(&str, &str)> {
    let b = qname.as_bytes();
    let Some(c) = b.iter().position(|&x| x == b':') else {
        return Some(("", qname));
    };
    let (p, l) = (&qname[..c], &qname[c + 1..]);
    if p.is_empty() || l.is_empty() || l.as_bytes().contains(&b':') || p == "xml" || p == "xmlns" {
        return None;
    }
    Some((p, l))
}

/// The namespace of a prefix (`""`: the default namespace, which applies to elements only).
/// `None` for an undeclared prefix.
fn resolve(bindings: &[Binding<'_>], prefix: &str, element: bool) -> Option<Ns> {
    if prefix.is_empty() && !element {
        return Some(Ns::None);
    }
    match bindings.iter().rev().find(|b| b.prefix == prefix) {
        Some(b) => Some(b.ns.clone().unwrap_or(Ns::None)),
        None if prefix.is_empty() => Some(Ns::None),
        None => None,
    }
}

#[cfg(test)]
mod tests {
    use super::super::{build_tree, HARD_MAX_DEPTH};
    use super::build;
    use crate::parse::{test_support::fast_agrees, Limits};
    use proptest::prelude::*;
    use proptest::strategy::ValueTree;

    fn fast(text: &str) -> Option<String> {
        let depth = Limits::default().max_depth.min(HARD_MAX_DEPTH);
        build(text, "t.xml", depth).map(|n| format!("{n:?}"))
    }

    fn slow(text: &str) -> String {
        match build_tree(text, "t.xml", &Limits::default()) {
            Ok(n) => format!("{n:?}"),
            Err(e) => format!("error: {e}"),
        }
    }

    fn xml_files(dir: &std::path::Path) -> Vec<std::path::PathBuf> {
        walkdir::WalkDir::new(dir)
            .into_iter()
            .filter_map(Result::ok)
            .map(|e| e.into_path())
            .filter(|p| p.extension().is_some_and(|x| x == "xml"))
            .collect()
    }

    #[test]
    fn reads_the_example_profiles_like_quick_xml() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
        let files = xml_files(&dir);
        assert!(files.len() >= 5, "{files:?}");
        for p in files {
            let text = std::fs::read_to_string(&p).expect("example");
            // The example RT System profile is not an RTC profile: not for this path.
            if !crate::parse::xml::is_profile(text.as_bytes()) {
                continue;
            }
            let v =
                fast(&text).unwrap_or_else(|| panic!("{} not read by the fast path", p.display()));
            assert_eq!(v, slow(&text), "{}", p.display());
        }
    }

    /// The published profiles in `../shared/corpus`, when present: whatever the fast builder
    /// takes, it builds as the quick-xml builder does.
    #[test]
    fn agrees_on_the_shared_corpus_when_present() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
        let (mut seen, mut taken) = (0, 0);
        for p in xml_files(&dir) {
            let Ok(bytes) = std::fs::read(&p) else {
                continue;
            };
            let Ok(text) = std::str::from_utf8(&bytes) else {
                continue;
            };
            let text = text.strip_prefix('\u{feff}').unwrap_or(text);
            seen += 1;
            if let Some(v) = fast(text) {
                taken += 1;
                assert_eq!(v, slow(text), "{}", p.display());
            }
        }
        eprintln!("fast path: {taken} of {seen} corpus XML files");
    }

    const NS: &str = r#" xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:rtcDoc="http://www.openrtp.org/namespaces/rtc_doc" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance""#;

    #[test]
    fn common_forms() {
        let docs = [
            format!("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n<rtc:RtcProfile{NS} rtc:id=\"RTC:x\" xsi:type=\"rtcExt:t\">\n  <rtc:BasicInfo rtc:name='n' rtcExt:c=\"a &amp; b&#x41;\tc\"/>\n  <!-- c -->\n  <rtcDoc:Doc>text &lt;x&gt;\r\n more</rtcDoc:Doc>\n</rtc:RtcProfile>\n"),
            "<RtcProfile xmlns=\"http://www.openrtp.org/namespaces/rtc\"><a b=\"1\"/>x</RtcProfile>".to_string(),
            format!("<rtc:RtcProfile{NS}><x:y xmlns:x=\"urn:other\" x:z=\"1\"/></rtc:RtcProfile>"),
        ];
        for d in &docs {
            let v = fast(d).unwrap_or_else(|| panic!("not taken: {d}"));
            assert_eq!(v, slow(d), "{d}");
        }
        for d in [
            format!("<rtc:RtcProfile{NS}><![CDATA[x]]></rtc:RtcProfile>"),
            format!("<!DOCTYPE x><rtc:RtcProfile{NS}/>"),
            format!("<rtc:RtcProfile{NS}><?pi x?></rtc:RtcProfile>"),
            format!("<rtc:RtcProfile{NS}><q:a/></rtc:RtcProfile>"),
            format!("<rtc:RtcProfile{NS}><a></b></rtc:RtcProfile>"),
            format!("<rtc:RtcProfile{NS}><a>"),
            format!("<rtc:RtcProfile{NS} a=\"1\" a=\"2\"/>"),
            format!("<rtc:RtcProfile{NS} a=1/>"),
            format!("<rtc:RtcProfile{NS} a=\"x>y\"/>"),
            format!("<rtc:RtcProfile{NS}>&bogus;</rtc:RtcProfile>"),
            format!("<rtc:RtcProfile{NS}/>text"),
            format!("<rtc:RtcProfile{NS}/><second/>"),
            "<other/>".to_string(),
            format!("<rtc:RtcProfile{NS}><日本/></rtc:RtcProfile>"),
        ] {
            assert_eq!(fast(&d), None, "{d}");
        }
        let deep = format!("<rtc:RtcProfile{NS}>{}", "<a>".repeat(100_000));
        assert_eq!(fast(&deep), None);
        // Up to MAX_ATTRS attributes a tag is read here; with more, or a duplicate among
        // them (first, last, far apart), by `build_tree`.
        let attrs = |n: usize| (0..n).map(|k| format!(" a{k}=\"{k}\"")).collect::<String>();
        let many = |extra: &str, n: usize| {
            format!(
                "<rtc:RtcProfile{NS}><x{}{extra}/></rtc:RtcProfile>",
                attrs(n)
            )
        };
        let fits = many("", super::MAX_ATTRS);
        assert_eq!(fast(&fits), Some(slow(&fits)));
        assert_eq!(fast(&many("", super::MAX_ATTRS + 1)), None);
        for dup in [" a0=\"again\"", " a9=\"again\""] {
            let d = many(dup, 20);
            assert_eq!(fast(&d), None, "{d}");
            assert!(slow(&d).starts_with("error"), "{d}");
        }
    }

    /// A generated element: name, attributes, and content (text or child elements).
    #[derive(Debug, Clone)]
    struct E {
        name: &'static str,
        attrs: Vec<(&'static str, &'static str)>,
        content: Vec<C>,
    }

    #[derive(Debug, Clone)]
    enum C {
        Text(&'static str),
        El(E),
        Comment,
    }

    const NAMES: &[&str] = &[
        "rtc:BasicInfo",
        "rtcExt:Properties",
        "rtcDoc:Doc",
        "rtc:DataPorts",
        "Plain",
        "a.b-c_d",
        "xsi:x",
        "q:undeclared",
        "rtc:a:b",
        ":x",
        "_u",
        "n:el",
    ];
    const KEYS: &[&str] = &[
        "rtc:name",
        "rtcExt:value",
        "rtcDoc:description",
        "plain",
        "xsi:type",
        "xsi:other",
        "xmlns:n",
        "xmlns",
        "xml:lang",
        "q:k",
        "rtc:name",
        "n:k",
        "xmlns:n",
    ];
    const VALUES: &[&str] = &[
        "",
        "x",
        "a b",
        "日本語",
        "a &amp; b",
        "&lt;&gt;&quot;&apos;",
        "&#x41;&#66;",
        "tab\there",
        "line\nbreak",
        "cr\r\nlf",
        "&bogus;",
        "&amp",
        "&#0;",
        "it's",
        "say \"hi\"",
        "x>y",
        "x<y",
        "http://www.openrtp.org/namespaces/rtc",
        "urn:other",
    ];
    const TEXTS: &[&str] = &[
        "",
        "\n  ",
        "text",
        " lead and trail ",
        "a &amp; b",
        "&lt;tag&gt;",
        "&#x3042;",
        "\r\n",
        "x\ry",
        "]]>",
        "日本語",
        "&nope;",
        "a & b",
        "\u{3000}",
        "tab\t",
    ];
    const INSERTS: &[&str] = &[
        "<",
        ">",
        "&",
        "\"",
        "'",
        "=",
        " ",
        "/",
        "<!--x-->",
        "<![CDATA[x]]>",
        "<?pi x?>",
        "\r",
        "\n",
        " xmlns:q=\"u\"",
        ":",
        "&amp;",
        "&#0;",
        "<!DOCTYPE x>",
        "--",
        "\t",
        "</a>",
        "<a>",
    ];

    fn element() -> impl Strategy<Value = E> {
        let leaf = (
            prop::sample::select(NAMES),
            prop::collection::vec(
                (prop::sample::select(KEYS), prop::sample::select(VALUES)),
                0..3,
            ),
        )
            .prop_map(|(name, attrs)| E {
                name,
                attrs,
                content: Vec::new(),
            });
        leaf.prop_recursive(4, 30, 4, |inner| {
            (
                prop::sample::select(NAMES),
                prop::collection::vec(
                    (prop::sample::select(KEYS), prop::sample::select(VALUES)),
                    0..3,
                ),
                prop::collection::vec(
                    prop_oneof![
                        2 => inner.prop_map(C::El),
                        2 => prop::sample::select(TEXTS).prop_map(C::Text),
                        1 => Just(C::Comment),
                    ],
                    0..4,
                ),
            )
                .prop_map(|(name, attrs, content)| E {
                    name,
                    attrs,
                    content,
                })
        })
    }

    /// Writes an element; layout choices come from `choices`.
    fn write(e: &E, out: &mut String, choices: &[u8], k: &mut usize) {
        let mut pick = |n: u8| {
            let v = choices.get(*k).copied().unwrap_or(0);
            *k += 1;
            v % n
        };
        out.push('<');
        out.push_str(e.name);
        for (key, value) in &e.attrs {
            out.push_str([" ", "\n  ", "\t", "  "][pick(4) as usize]);
            let q = if pick(3) == 0 { '\'' } else { '"' };
            out.push_str(&format!("{key}={q}{value}{q}"));
        }
        if e.content.is_empty() && pick(2) == 0 {
            out.push_str(if pick(3) == 0 { " />" } else { "/>" });
            return;
        }
        out.push('>');
        for c in &e.content {
            match c {
                C::Text(t) => out.push_str(t),
                C::Comment => out.push_str("<!-- note -->"),
                C::El(child) => write(child, out, choices, k),
            }
        }
        out.push_str("</");
        out.push_str(e.name);
        out.push('>');
    }

    fn document(body: &[C], choices: &[u8]) -> String {
        let mut k = 0;
        let mut out = String::new();
        if choices.first().is_some_and(|c| c % 2 == 0) {
            out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        }
        let root = E {
            name: "rtc:RtcProfile",
            attrs: vec![("rtc:id", "RTC:x")],
            content: body.to_vec(),
        };
        let mut inner = String::new();
        write(&root, &mut inner, choices, &mut k);
        // The namespace declarations go on the root.
        out.push_str(&inner.replacen("<rtc:RtcProfile", &format!("<rtc:RtcProfile{NS}"), 1));
        out.push('\n');
        out
    }

    fn body() -> impl Strategy<Value = Vec<C>> {
        prop::collection::vec(
            prop_oneof![
                3 => element().prop_map(C::El),
                1 => prop::sample::select(TEXTS).prop_map(C::Text),
                1 => Just(C::Comment),
            ],
            0..5,
        )
    }

    /// The property below is only worth something if the fast builder takes most of the
    /// generated documents that quick-xml reads: count them.
    #[test]
    fn takes_most_generated_documents() {
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let strategy = (body(), prop::collection::vec(any::<u8>(), 64));
        let (mut taken, mut readable) = (0, 0);
        for _ in 0..1000 {
            let (b, choices) = strategy.new_tree(&mut runner).expect("tree").current();
            let doc = document(&b, &choices);
            let s = slow(&doc);
            readable += usize::from(!s.starts_with("error"));
            if let Some(v) = fast(&doc) {
                taken += 1;
                assert_eq!(v, s, "{doc}");
            }
        }
        assert!(
            taken * 2 > readable,
            "only {taken} of the {readable} documents quick-xml reads were taken"
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 4096, ..ProptestConfig::default() })]

        /// Whenever the fast builder returns a tree, the quick-xml builder returns the same one.
        #[test]
        fn agrees_with_quick_xml(
            b in body(),
            choices in prop::collection::vec(any::<u8>(), 64),
            edits in prop::collection::vec((any::<usize>(), prop::sample::select(INSERTS)), 0..3),
        ) {
            fast_agrees(&document(&b, &choices), edits, fast, slow)?;
        }
    }
}
