//! Pass 2 of the XML reader: text → a small element tree, namespaces resolved by URI, every
//! element and attribute carrying its line:column; hostile input (entity declarations,
//! undefined entities, too deep nesting) rejected while streaming.

use super::*;
// ---------------------------------------------------------------------------------------------
// Pass 2: element tree
// ---------------------------------------------------------------------------------------------

/// Which namespace a name is in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Ns {
    Rtc,
    Doc,
    Ext,
    Xsi,
    /// No namespace (unprefixed attribute, or element without a default namespace).
    None,
    Other(String),
}

impl Ns {
    pub(super) fn from_uri(uri: &[u8]) -> Ns {
        match uri {
            b"http://www.openrtp.org/namespaces/rtc" => Ns::Rtc,
            b"http://www.openrtp.org/namespaces/rtc_doc" => Ns::Doc,
            b"http://www.openrtp.org/namespaces/rtc_ext" => Ns::Ext,
            b"http://www.w3.org/2001/XMLSchema-instance" => Ns::Xsi,
            _ => Ns::Other(String::from_utf8_lossy(uri).into_owned()),
        }
    }
    pub(super) fn uri(&self) -> Option<Text> {
        match self {
            Ns::Rtc => Some(NS_RTC.into()),
            Ns::Doc => Some(NS_RTC_DOC.into()),
            Ns::Ext => Some(NS_RTC_EXT.into()),
            Ns::Xsi => Some(NS_XSI.into()),
            Ns::None => None,
            Ns::Other(u) => Some(u.as_str().into()),
        }
    }
    /// The reader is lenient about which of the three RTC namespaces (or none) a known name
    /// uses: real files mix them up (`rtc:position` for `rtcExt:position`).
    pub(super) fn is_rtc_family(&self) -> bool {
        matches!(self, Ns::Rtc | Ns::Doc | Ns::Ext | Ns::None)
    }
}

#[derive(Debug)]
pub(super) struct Attr<'t> {
    pub(super) qname: Cow<'t, str>,
    pub(super) ns: Ns,
    pub(super) local: Cow<'t, str>,
    pub(super) value: Cow<'t, str>,
    pub(super) pos: Pos,
}

impl Attr<'_> {
    /// The local name when the attribute may carry a known RTC field.
    pub(super) fn key(&self) -> Option<&str> {
        self.ns.is_rtc_family().then_some(&*self.local)
    }
}

#[derive(Debug)]
pub(super) struct Node<'t> {
    pub(super) qname: Cow<'t, str>,
    pub(super) ns: Ns,
    pub(super) local: Cow<'t, str>,
    /// Attributes, without the plumbing (`xmlns*`, `xsi:type`, schema locations).
    pub(super) attrs: Vec<Attr<'t>>,
    pub(super) children: Vec<Node<'t>>,
    /// All character data directly inside the element, unescaped and EOL-normalised.
    pub(super) text: String,
    /// Position of the first non-whitespace character data.
    pub(super) text_pos: Option<Pos>,
    pub(super) pos: Pos,
}

impl Node<'_> {
    /// The local name when the element may be a known RTC element.
    pub(super) fn key(&self) -> Option<&str> {
        self.ns.is_rtc_family().then_some(&*self.local)
    }
    /// Lower-cased key, for the case-insensitive constraint vocabulary (spec 8.1 vs XSD).
    pub(super) fn key_lower(&self) -> Option<String> {
        self.key().map(str::to_ascii_lowercase)
    }
    pub(super) fn has_text(&self) -> bool {
        !is_blank(&self.text)
    }
}

pub(super) struct TreeBuilder<'t, 'f> {
    pub(super) text: &'t str,
    pub(super) file: &'f str,
    pub(super) cursor: PosCursor<'t>,
    pub(super) max_depth: usize,
}

impl<'t, 'f> TreeBuilder<'t, 'f> {
    pub(super) fn new(text: &'t str, file: &'f str, max_depth: usize) -> Self {
        TreeBuilder {
            text,
            file,
            cursor: PosCursor::new(text),
            max_depth,
        }
    }

    pub(super) fn err(
        &mut self,
        code: &'static str,
        offset: usize,
        msg: impl Into<String>,
    ) -> Diagnostic {
        let pos = self.cursor.pos(offset);
        Diagnostic::error(code, self.file, msg).at(pos)
    }
}

/// Text → element tree of an RTC profile (root `RtcProfile`); see [`build_any_tree`].
pub(super) fn build_tree<'t>(
    text: &'t str,
    file: &str,
    limits: &Limits,
) -> Result<Node<'t>, Diagnostic> {
    let root = build_any_tree(text, file, limits)?;
    if root.local != "RtcProfile" || !root.ns.is_rtc_family() {
        return Err(Diagnostic::error(
            codes::SHAPE,
            file,
            format!(
                "root element is `{}`, not `rtc:RtcProfile`: not an RTC component profile",
                root.qname
            ),
        )
        .at(root.pos));
    }
    Ok(root)
}

/// Text → element tree, whatever the root element (RT System profiles use this too). Streams
/// through quick-xml's `NsReader`; O(n) time and memory.
pub(super) fn build_any_tree<'t>(
    text: &'t str,
    file: &str,
    limits: &Limits,
) -> Result<Node<'t>, Diagnostic> {
    let mut b = TreeBuilder::new(text, file, limits.max_depth.min(HARD_MAX_DEPTH));
    let mut reader = NsReader::from_str(text);
    {
        let cfg = reader.config_mut();
        // End names are checked here against our own stack, for clearer messages.
        cfg.check_end_names = false;
        cfg.expand_empty_elements = false;
        cfg.trim_text(false);
    }
    let mut stack: Vec<Node> = Vec::new();
    let mut root: Option<Node> = None;
    loop {
        let before = usize::try_from(reader.buffer_position()).unwrap_or(usize::MAX);
        let (ns, event) = match reader.read_resolved_event() {
            Ok((ns, ev)) => (own_ns(ns), ev),
            Err(e) => {
                let at = usize::try_from(reader.error_position()).unwrap_or(before);
                return Err(malformed(&mut b, e, at, &stack));
            }
        };
        let (e, is_empty) = match event {
            XmlEvent::Start(e) => (e, false),
            XmlEvent::Empty(e) => (e, true),
            XmlEvent::Eof => break,
            other => {
                other_event(&mut b, &mut stack, &mut root, other, before)?;
                continue;
            }
        };
        let ns = ns.map_err(|p| {
            b.err(
                codes::MALFORMED,
                before,
                format!("namespace prefix `{p}` is not declared (no `xmlns:{p}=\"…\"`)"),
            )
        })?;
        if root.is_some() && stack.is_empty() {
            return Err(b.err(
                codes::MALFORMED,
                before,
                "a second root element after the end of the document element",
            ));
        }
        if stack.len() >= b.max_depth {
            return Err(b
                .err(
                    codes::TOO_DEEP,
                    before,
                    format!(
                        "elements nest deeper than the limit of {} levels",
                        b.max_depth
                    ),
                )
                .with_hint("if the file is genuine, raise `max-depth` in rtcdoc.toml or pass --max-depth N (up to 1024)"));
        }
        let qname = sub(text, e.name().as_ref());
        if !is_name(&qname) {
            return Err(b.err(
                codes::MALFORMED,
                before,
                format!("`<{qname}` is not a valid element name"),
            ));
        }
        let local = sub(text, e.local_name().as_ref());
        let pos = b.cursor.pos(before);
        let mut attrs = Vec::new();
        // Duplicates are found by `Seen` in linear time: quick-xml's own check compares each
        // attribute with all earlier ones, which a tag with 200,000 attributes turns into
        // minutes.
        let mut seen = Seen::default();
        for a in e.attributes().with_checks(false) {
            let a = a.map_err(|err| {
                b.err(
                    codes::MALFORMED,
                    before,
                    format!("bad attribute in `<{qname}>`: {}", attr_error(&err)),
                )
            })?;
            let key = a.key.as_ref();
            if !seen.insert(sub(text, key)) {
                return Err(b.err(
                    codes::MALFORMED,
                    before,
                    format!("bad attribute in `<{qname}>`: the same attribute is written twice"),
                ));
            }
            let key_off = offset_in(text, key).unwrap_or(before);
            if is_ns_declaration(key) {
                continue;
            }
            let aq = sub(text, key);
            let (ans, alocal) = reader.resolve_attribute(a.key);
            let ans = own_ns(ans).map_err(|p| {
                b.err(
                    codes::MALFORMED,
                    key_off,
                    format!("namespace prefix `{p}` of attribute `{aq}` is not declared"),
                )
            })?;
            let alocal = sub(text, alocal.as_ref());
            if is_schema_plumbing(&ans, &alocal) {
                continue;
            }
            let raw = sub(text, &a.value);
            let value_off = offset_in(text, &a.value).unwrap_or(key_off);
            let value = unescape_attr(raw)
                .map_err(|(rel, msg)| entity_error(&mut b, value_off + rel, msg))?;
            let apos = b.cursor.pos(key_off);
            attrs.push(Attr {
                qname: aq,
                ns: ans,
                local: alocal,
                value,
                pos: apos,
            });
        }
        let node = Node {
            qname,
            ns,
            local,
            attrs,
            children: Vec::new(),
            text: String::new(),
            text_pos: None,
            pos,
        };
        if is_empty {
            close(node, &mut stack, &mut root);
        } else {
            stack.push(node);
        }
    }
    if let Some(open) = stack.last() {
        let (q, p) = (open.qname.clone(), open.pos);
        return Err(Diagnostic::error(
            codes::MALFORMED,
            file,
            format!("unclosed element `{q}`: the file ends before its end tag (truncated file?)"),
        )
        .at(p));
    }
    let Some(root) = root else {
        let end = text.len();
        return Err(b.err(
            codes::MALFORMED,
            end,
            "no root element: the file is empty or contains no XML element",
        ));
    };
    Ok(root)
}

/// Resolved namespace → [`Ns`]; `Err(prefix)` for an undeclared prefix.
pub(super) fn own_ns(ns: ResolveResult<'_>) -> Result<Ns, String> {
    match ns {
        ResolveResult::Bound(uri) => Ok(Ns::from_uri(uri.as_ref())),
        ResolveResult::Unbound => Ok(Ns::None),
        ResolveResult::Unknown(p) => Err(String::from_utf8_lossy(&p).into_owned()),
    }
}

/// Everything but start tags and end of file: end tags, text, references, DOCTYPE, ….
pub(super) fn other_event<'t>(
    b: &mut TreeBuilder<'_, '_>,
    stack: &mut Vec<Node<'t>>,
    root: &mut Option<Node<'t>>,
    event: XmlEvent<'_>,
    before: usize,
) -> Result<(), Diagnostic> {
    match event {
        XmlEvent::End(e) => {
            let name = e.name();
            let found = sub(b.text, name.as_ref());
            let Some(node) = stack.pop() else {
                return Err(b.err(
                    codes::MALFORMED,
                    before,
                    format!("end tag `</{found}>` has no matching start tag"),
                ));
            };
            if node.qname != found {
                return Err(b.err(
                    codes::MALFORMED,
                    before,
                    format!(
                        "mismatched end tag: expected `</{}>` (opened at {}), found `</{found}>`",
                        node.qname, node.pos
                    ),
                ));
            }
            close(node, stack, root);
        }
        XmlEvent::Text(t) => {
            let raw = sub(b.text, &t);
            add_text(b, stack, &normalize_eol(&raw), before)?;
        }
        XmlEvent::CData(t) => {
            let raw = sub(b.text, &t);
            add_text(b, stack, &normalize_eol(&raw), before)?;
        }
        XmlEvent::GeneralRef(r) => {
            let name = String::from_utf8_lossy(&r).into_owned();
            let s = resolve_ref(&name).map_err(|msg| entity_error(b, before, msg))?;
            add_text(b, stack, &s, before)?;
        }
        XmlEvent::DocType(d) => {
            // No DTD is defined for profiles; entity declarations are the vector of
            // billion-laughs and external-entity attacks, so they are refused outright.
            let body = String::from_utf8_lossy(&d);
            if body.contains("<!ENTITY") {
                return Err(b
                    .err(
                        codes::ENTITY,
                        before,
                        "entity declarations are not allowed in a profile (DOCTYPE with <!ENTITY>)",
                    )
                    .with_hint("remove the DOCTYPE; RTC profiles do not use a DTD"));
            }
        }
        _ => {}
    }
    Ok(())
}

/// Finishes `node`: attaches it to its parent, or makes it the root.
pub(super) fn close<'t>(node: Node<'t>, stack: &mut [Node<'t>], root: &mut Option<Node<'t>>) {
    match stack.last_mut() {
        Some(parent) => parent.children.push(node),
        None => *root = Some(node),
    }
}

pub(super) fn add_text(
    b: &mut TreeBuilder<'_, '_>,
    stack: &mut [Node],
    s: &str,
    offset: usize,
) -> Result<(), Diagnostic> {
    let blank = is_blank(s);
    match stack.last_mut() {
        Some(node) => {
            if !blank && node.text_pos.is_none() {
                let lead = s.len() - s.trim_start().len();
                node.text_pos = Some(b.cursor.pos(offset + lead));
            }
            node.text.push_str(s);
            Ok(())
        }
        None if blank => Ok(()),
        None => Err(b.err(
            codes::MALFORMED,
            offset + (s.len() - s.trim_start().len()),
            "text outside the root element",
        )),
    }
}

/// True when the text is only white space (Unicode `White_Space`, as `str::trim`), decided
/// byte by byte for the usual ASCII indentation between elements.
pub(super) fn is_blank(s: &str) -> bool {
    s.bytes().all(|b| matches!(b, b' ' | b'\t' | b'\n' | b'\r')) || s.trim().is_empty()
}

/// A byte of an ASCII XML name (`rtc:DataPorts`, `a.b-c_d`).
pub(super) fn is_ascii_name_byte(c: &u8) -> bool {
    NAME_BYTE[usize::from(*c)]
}

/// [`is_ascii_name_byte`] of every byte, looked up: names are scanned a byte at a time.
const NAME_BYTE: [bool; 256] = {
    let mut t = [false; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        t[c] = b.is_ascii_alphanumeric() || matches!(b, b'_' | b':' | b'-' | b'.');
        c += 1;
    }
    t
};

/// A loose check of XML 1.0 `Name` (§2.3): quick-xml accepts anything up to whitespace or `>`.
pub(super) fn is_name(s: &str) -> bool {
    // The usual case, an ASCII name such as `rtc:DataPorts`, decided byte by byte.
    let b = s.as_bytes();
    if b.first()
        .is_some_and(|c| c.is_ascii_alphabetic() || matches!(c, b'_' | b':'))
        && b.iter().all(is_ascii_name_byte)
    {
        return true;
    }
    let mut chars = s.chars();
    let Some(first) = chars.next() else {
        return false;
    };
    let bad = |c: char| {
        c.is_whitespace() || c.is_control() || "<>&\"'=/!?;,()[]{}`^|\\*+$%@#~".contains(c)
    };
    !bad(first) && !first.is_ascii_digit() && !matches!(first, '-' | '.') && !chars.any(bad)
}

/// `part` as text: borrowed without re-validation when it is a slice of `whole` (always the case
/// for what the reader yields from a `&str`), else decoded lossily.
pub(super) fn sub<'t>(whole: &'t str, part: &[u8]) -> Cow<'t, str> {
    offset_in(whole, part)
        .and_then(|off| whole.get(off..off.checked_add(part.len())?))
        .map_or_else(
            || Cow::Owned(String::from_utf8_lossy(part).into_owned()),
            Cow::Borrowed,
        )
}

/// Byte offset of `part` inside `whole`, when `part` borrows from it.
pub(super) fn offset_in(whole: &str, part: &[u8]) -> Option<usize> {
    let start = whole.as_ptr() as usize;
    let p = part.as_ptr() as usize;
    let off = p.checked_sub(start)?;
    (off <= whole.len()).then_some(off)
}

/// XML 1.0 §2.11: CRLF and lone CR become LF.
pub(super) fn normalize_eol(s: &str) -> Cow<'_, str> {
    if !s.contains('\r') {
        return Cow::Borrowed(s);
    }
    Cow::Owned(s.replace("\r\n", "\n").replace('\r', "\n"))
}

/// Resolves the name of a reference `&name;`: the five predefined entities and character
/// references. Anything else is refused (no DTD, no expansion ever).
pub(super) fn resolve_ref(name: &str) -> Result<String, String> {
    let s = match name {
        "lt" => "<",
        "gt" => ">",
        "amp" => "&",
        "apos" => "'",
        "quot" => "\"",
        _ => {
            if let Some(num) = name.strip_prefix('#') {
                let code = match num.strip_prefix('x') {
                    Some(hex) => u32::from_str_radix(hex, 16),
                    None => num.parse::<u32>(),
                };
                let c = code
                    .ok()
                    .and_then(char::from_u32)
                    .filter(|&c| c != '\0')
                    .ok_or_else(|| format!("invalid character reference `&{name};`"))?;
                return Ok(c.to_string());
            }
            return Err(format!(
                "reference to undefined entity `&{name};` (only &lt; &gt; &amp; &apos; &quot; and character references are allowed)"
            ));
        }
    };
    Ok(s.to_string())
}

/// Attribute-value normalisation (XML 1.0 §3.3.3, CDATA type): literal tab, CR, LF → space
/// (CRLF → one space), then references resolved. Errors carry the byte offset inside `raw`.
pub(super) fn unescape_attr(raw: Cow<'_, str>) -> Result<Cow<'_, str>, (usize, String)> {
    if !raw
        .bytes()
        .any(|c| matches!(c, b'&' | b'\t' | b'\r' | b'\n'))
    {
        return Ok(raw);
    }
    let raw = &*raw;
    let mut out = String::with_capacity(raw.len());
    let mut rest = raw;
    let mut base = 0;
    while let Some(i) = rest.find(['&', '\t', '\r', '\n']) {
        out.push_str(rest.get(..i).unwrap_or(""));
        let tail = rest.get(i..).unwrap_or("");
        if tail.starts_with("\r\n") {
            out.push(' ');
            rest = tail.get(2..).unwrap_or("");
            base += i + 2;
        } else if tail.starts_with('&') {
            let Some(end) = tail.find(';') else {
                return Err((base + i, "`&` without a closing `;` (write `&amp;`)".into()));
            };
            let name = tail.get(1..end).unwrap_or("");
            out.push_str(&resolve_ref(name).map_err(|m| (base + i, m))?);
            rest = tail.get(end + 1..).unwrap_or("");
            base += i + end + 1;
        } else {
            out.push(' ');
            rest = tail.get(1..).unwrap_or("");
            base += i + 1;
        }
    }
    out.push_str(rest);
    Ok(Cow::Owned(out))
}

pub(super) fn entity_error(b: &mut TreeBuilder<'_, '_>, offset: usize, msg: String) -> Diagnostic {
    let code = if msg.starts_with("reference to undefined entity") {
        codes::ENTITY
    } else {
        codes::MALFORMED
    };
    b.err(code, offset, msg)
}

/// `xmlns` and `xmlns:p` attributes: namespace declarations, not data.
pub(super) fn is_ns_declaration(key: &[u8]) -> bool {
    key == b"xmlns" || key.starts_with(b"xmlns:")
}

/// `xsi:type` (the concrete XSD type) and the schema locations: plumbing, not data.
pub(super) fn is_schema_plumbing(ns: &Ns, local: &str) -> bool {
    *ns == Ns::Xsi
        && matches!(
            local,
            "type" | "schemaLocation" | "noNamespaceSchemaLocation"
        )
}

/// The attribute names of one tag met so far: a short list, or a hash set once the tag has
/// many attributes (so that hostile tags stay linear).
#[derive(Default)]
pub(super) struct Seen<'a> {
    pub(super) small: Vec<Cow<'a, str>>,
    pub(super) big: Option<std::collections::HashSet<Cow<'a, str>>>,
}

impl<'a> Seen<'a> {
    /// Adds `key`; false when it was already there.
    pub(super) fn insert(&mut self, key: Cow<'a, str>) -> bool {
        if let Some(set) = &mut self.big {
            return set.insert(key);
        }
        if self.small.contains(&key) {
            return false;
        }
        self.small.push(key);
        if self.small.len() > 16 {
            self.big = Some(self.small.drain(..).collect());
        }
        true
    }
}

pub(super) fn attr_error(e: &quick_xml::events::attributes::AttrError) -> String {
    use quick_xml::events::attributes::AttrError as A;
    match e {
        A::ExpectedEq(_) => "expected `=` after the attribute name".into(),
        A::ExpectedValue(_) => "expected a quoted value after `=`".into(),
        A::UnquotedValue(_) => "attribute value is not quoted".into(),
        A::ExpectedQuote(_, _) => "attribute value has no closing quote".into(),
        A::Duplicated(_, _) => "the same attribute is written twice".into(),
    }
}

/// Turns a quick-xml error into a plain-words diagnostic.
pub(super) fn malformed(
    b: &mut TreeBuilder<'_, '_>,
    e: quick_xml::Error,
    at: usize,
    stack: &[Node],
) -> Diagnostic {
    use quick_xml::errors::{IllFormedError as I, SyntaxError as S};
    use quick_xml::Error as E;
    let (code, msg) = match &e {
        E::Syntax(S::UnclosedTag) => (
            codes::MALFORMED,
            "unclosed tag: `<` without a matching `>` (truncated file?)".to_string(),
        ),
        E::Syntax(S::UnclosedComment) => (codes::MALFORMED, "unclosed comment `<!--`".into()),
        E::Syntax(S::UnclosedCData) => (codes::MALFORMED, "unclosed CDATA section".into()),
        E::Syntax(S::UnclosedDoctype) => (codes::MALFORMED, "unclosed DOCTYPE".into()),
        E::Syntax(S::UnclosedPIOrXmlDecl) => (
            codes::MALFORMED,
            "unclosed processing instruction or XML declaration (`?>` missing)".into(),
        ),
        E::Syntax(S::InvalidBangMarkup) => (
            codes::MALFORMED,
            "invalid markup after `<!` (expected a comment, CDATA or DOCTYPE)".into(),
        ),
        E::IllFormed(I::MismatchedEndTag { expected, found }) => (
            codes::MALFORMED,
            format!("mismatched end tag: expected `</{expected}>`, found `</{found}>`"),
        ),
        E::IllFormed(I::UnmatchedEndTag(t)) => (
            codes::MALFORMED,
            format!("end tag `</{t}>` has no matching start tag"),
        ),
        E::IllFormed(I::UnclosedReference) => (
            codes::MALFORMED,
            "`&` without a closing `;` (write `&amp;` for a literal ampersand)".into(),
        ),
        E::IllFormed(I::MissingEndTag(t)) => (codes::MALFORMED, format!("unclosed element `{t}`")),
        E::Escape(err) => (codes::ENTITY, format!("bad reference: {err}")),
        E::Namespace(err) => (codes::MALFORMED, format!("namespace error: {err}")),
        E::InvalidAttr(err) => (
            codes::MALFORMED,
            format!("bad attribute: {}", attr_error(err)),
        ),
        other => (codes::MALFORMED, format!("malformed XML: {other}")),
    };
    let msg = match stack.last() {
        Some(n) if matches!(e, E::Syntax(S::UnclosedTag)) => {
            format!("{msg} (inside `{}` opened at {})", n.qname, n.pos)
        }
        _ => msg,
    };
    b.err(code, at.min(b.text.len()), msg)
}
