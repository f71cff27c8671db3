//! A fast path for the YAML that RTCBuilder and people write: one block-style document of
//! mappings, sequences and one-line scalars (plain, `'…'` or `"…"`), with comments.
//!
//! libyaml and serde's event layer cost about 350 instructions per byte of a YAML profile (four
//! times the XML reader's); this reader builds the same [`Value`] in one pass over the lines.
//! It accepts only what it fully understands and returns `None` for anything else — flow
//! collections other than an empty `[]` or `{}`, block scalars (`|`, `>`), anchors, aliases,
//! tags, multi-line scalars, several documents, tabs, control characters, duplicate keys, keys
//! that are not strings, escapes other than `\\ \" \/ \n \t \r \0 \uXXXX`, integers beyond 64
//! bits, hex/octal/binary and `.inf`/`.nan` — and the caller then parses the file with
//! serde_norway as before, which also produces every error message. Plain scalars are typed
//! as serde_norway types them (null, booleans, numbers through its own `Number` parser, else
//! strings).
//!
//! A differential property test (below) holds the two readers equal on generated and mutated
//! documents: whenever this reader returns a value, serde_norway returns the same one, in the
//! same key order.

use serde_norway::{Mapping, Value};

/// Implicit keys longer than this are left to libyaml, which limits simple keys to 1,024
/// characters.
const MAX_KEY: usize = 1000;

/// One line with content (blank and comment-only lines are dropped).
#[derive(Clone, Copy)]
struct Line {
    /// Column of the first content byte (spaces only).
    indent: usize,
    /// Byte range of the content in the source, without the line break.
    start: usize,
    end: usize,
}

/// The document's root value when the whole source is in the subset this reader handles and
/// the root is a mapping with the key `root_key` (`rtcProfile`, or `rtsProfile` for system
/// profiles); `None` otherwise.
pub(crate) fn parse(src: &str, max_depth: usize, root_key: &str) -> Option<Value> {
    if !plain_text(src.as_bytes()) {
        return None;
    }
    let lines = lines(src)?;
    let first = *lines.first()?;
    let mut p = Parser {
        src,
        lines,
        i: 0,
        max_depth,
    };
    let root = p.map(first.indent, 1)?;
    if p.i != p.lines.len() {
        return None;
    }
    match &root {
        Value::Mapping(m) if m.contains_key(root_key) => Some(root),
        _ => None,
    }
}

/// False when the bytes hold anything that makes YAML's character rules matter: tabs, control
/// characters, a carriage return not followed by a line feed, a byte order mark, and the
/// non-printable or line-breaking characters U+0080–U+009F, U+2028, U+2029, U+FFFE, U+FFFF.
fn plain_text(b: &[u8]) -> bool {
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        match c {
            // A run of printable ASCII and line feeds passes sixteen bytes per step (scanned
            // only from such a byte, so text outside ASCII is not tested block by block).
            b'\n' | 0x20..=0x7e => {
                let plain = |c: u8| (0x20..=0x7e).contains(&c) | (c == b'\n');
                i += crate::bytes::run_len(&b[i..], plain, plain);
                continue;
            }
            b'\r' if b.get(i + 1) == Some(&b'\n') => {}
            0xc2 if b.get(i + 1).is_some_and(|&n| n < 0xa0) => return false,
            0xe2 if b.get(i + 1) == Some(&0x80) && matches!(b.get(i + 2), Some(0xa8 | 0xa9)) => {
                return false
            }
            0xef if matches!(
                (b.get(i + 1), b.get(i + 2)),
                (Some(0xbb), Some(0xbf)) | (Some(0xbf), Some(0xbe | 0xbf))
            ) =>
            {
                return false
            }
            0x80..=0xff => {}
            _ => return false,
        }
        i += 1;
    }
    true
}

/// The content lines; `None` when a document marker or directive makes the file more than one
/// plain document. A first line `---` (alone, or with a comment) is allowed and skipped.
fn lines(src: &str) -> Option<Vec<Line>> {
    let b = src.as_bytes();
    let mut out = Vec::with_capacity(b.len() / 24);
    let mut start = 0;
    let mut seen_content = false;
    while start < b.len() {
        let nl = memchr::memchr(b'\n', &b[start..]).map_or(b.len(), |n| start + n);
        let mut end = nl;
        if end > start && b[end - 1] == b'\r' {
            end -= 1;
        }
        let indent = b[start..end].iter().take_while(|&&c| c == b' ').count();
        let content = &b[start + indent..end];
        let line_start = start;
        start = nl + 1;
        if content.is_empty() || content[0] == b'#' {
            continue;
        }
        if indent == 0 && (marker(content, b"---") || marker(content, b"...")) {
            let alone = content.len() == 3 || is_comment_tail(&content[3..]);
            if seen_content || !content.starts_with(b"---") || !alone {
                return None;
            }
            seen_content = true;
            continue;
        }
        if indent == 0 && content[0] == b'%' {
            return None;
        }
        seen_content = true;
        out.push(Line {
            indent,
            start: line_start + indent,
            end,
        });
    }
    Some(out)
}

/// True when `content` starts with the three-byte marker followed by the end or a space.
fn marker(content: &[u8], m: &[u8]) -> bool {
    content.starts_with(m) && content.get(3).is_none_or(|&c| c == b' ')
}

/// True when the bytes are spaces, optionally followed by a comment that starts after a space.
fn is_comment_tail(rest: &[u8]) -> bool {
    let n = rest.iter().take_while(|&&c| c == b' ').count();
    n == rest.len() || (n > 0 && rest[n] == b'#')
}

fn is_item(c: &str) -> bool {
    c == "-" || c.starts_with("- ")
}

struct Parser<'a> {
    src: &'a str,
    lines: Vec<Line>,
    i: usize,
    max_depth: usize,
}

/// What the start of a line's content is.
enum Head<'a> {
    /// `key:` and the text after the colon (with its leading spaces).
    Key(Value, &'a str),
    /// Not a key: a scalar.
    Scalar,
}

impl<'a> Parser<'a> {
    fn content(&self, l: Line) -> &'a str {
        &self.src[l.start..l.end]
    }

    fn next(&self) -> Option<Line> {
        self.lines.get(self.i).copied()
    }

    /// The value of a key or item written on the following lines: a more indented block, a
    /// sequence at the same indent (after a key only), or null.
    fn nested(&mut self, n: usize, depth: usize, after_key: bool) -> Option<Value> {
        match self.next() {
            Some(l) if l.indent > n => {
                if is_item(self.content(l)) {
                    self.seq(l.indent, depth + 1)
                } else {
                    self.map(l.indent, depth + 1)
                }
            }
            Some(l) if after_key && l.indent == n && is_item(self.content(l)) => {
                self.seq(n, depth + 1)
            }
            _ => Some(Value::Null),
        }
    }

    fn map(&mut self, n: usize, depth: usize) -> Option<Value> {
        if depth >= self.max_depth {
            return None;
        }
        let mut m = Mapping::new();
        while let Some(l) = self.next() {
            if l.indent < n {
                break;
            }
            let c = self.content(l);
            if l.indent > n || is_item(c) {
                return None;
            }
            let Head::Key(key, rest) = head(c)? else {
                return None;
            };
            self.i += 1;
            let rest = rest.trim_start_matches(' ');
            let value = if rest.is_empty() || rest.starts_with('#') {
                self.nested(n, depth, true)?
            } else {
                // A more indented line after it (a multi-line scalar) ends the loop below.
                scalar(rest)?
            };
            match m.entry(key) {
                serde_norway::mapping::Entry::Occupied(_) => return None,
                serde_norway::mapping::Entry::Vacant(e) => {
                    e.insert(value);
                }
            }
        }
        Some(Value::Mapping(m))
    }

    fn seq(&mut self, n: usize, depth: usize) -> Option<Value> {
        if depth >= self.max_depth {
            return None;
        }
        let mut items = Vec::new();
        while let Some(l) = self.next() {
            let c = self.content(l);
            if l.indent > n {
                return None;
            }
            if l.indent < n || !is_item(c) {
                break;
            }
            let rest = c[1..].trim_start_matches(' ');
            if rest.is_empty() || rest.starts_with('#') {
                self.i += 1;
                items.push(self.nested(n, depth, false)?);
            } else if is_item(rest) {
                return None;
            } else if let Head::Key(..) = head(rest)? {
                // `- key: value`: a mapping whose keys sit at the column of `key`.
                let col = rest.as_ptr() as usize - self.src.as_ptr() as usize;
                let indent = l.indent + (col - l.start);
                self.lines[self.i] = Line {
                    indent,
                    start: col,
                    end: l.end,
                };
                items.push(self.map(indent, depth + 1)?);
            } else {
                self.i += 1;
                items.push(scalar(rest)?);
            }
        }
        Some(Value::Sequence(items))
    }
}

/// Whether a line's content starts with a key. `None` for content this reader leaves alone.
fn head(c: &str) -> Option<Head<'_>> {
    let b = c.as_bytes();
    if b[0] == b'"' || b[0] == b'\'' {
        let (text, after) = quoted(c)?;
        let t = after.trim_start_matches(' ');
        if let Some(rest) = t.strip_prefix(':') {
            if rest.is_empty() || rest.starts_with(' ') {
                return (c.len() - after.len() <= MAX_KEY)
                    .then_some(Head::Key(Value::String(text), rest));
            }
        }
        return Some(Head::Scalar);
    }
    // A plain key ends at the first `: ` or a final `:`, unless a comment (` #`) comes first.
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b':' if i + 1 == b.len() || b[i + 1] == b' ' => {
                let key = c[..i].trim_end_matches(' ');
                if key.is_empty() || i > MAX_KEY || starts_with_indicator(key) {
                    return None;
                }
                return match plain(key)? {
                    v @ Value::String(_) => Some(Head::Key(v, &c[i + 1..])),
                    _ => None,
                };
            }
            b'#' if i > 0 && b[i - 1] == b' ' => return Some(Head::Scalar),
            _ => {}
        }
        i += 1;
    }
    Some(Head::Scalar)
}

/// True when a plain scalar may not start like this (YAML indicators; `-`, `?`, `:` followed by
/// a space or the end).
fn starts_with_indicator(s: &str) -> bool {
    let b = s.as_bytes();
    match b[0] {
        b',' | b'[' | b']' | b'{' | b'}' | b'#' | b'&' | b'*' | b'!' | b'|' | b'>' | b'\''
        | b'"' | b'%' | b'@' | b'`' => true,
        b'-' | b'?' | b':' => b.get(1).is_none_or(|&c| c == b' '),
        _ => false,
    }
}

/// A one-line scalar value (no leading spaces), with an optional trailing comment.
fn scalar(rest: &str) -> Option<Value> {
    if rest.starts_with(['"', '\'']) {
        let (text, after) = quoted(rest)?;
        return is_comment_tail(after.as_bytes()).then_some(Value::String(text));
    }
    // Empty flow collections, as in `ports: []`.
    for (open, empty) in [
        ("[]", Value::Sequence(Vec::new())),
        ("{}", Value::Mapping(Mapping::new())),
    ] {
        if let Some(after) = rest.strip_prefix(open) {
            return is_comment_tail(after.as_bytes()).then_some(empty);
        }
    }
    if starts_with_indicator(rest) {
        return None;
    }
    let text = match rest.find(" #") {
        Some(c) => &rest[..c],
        None => rest,
    }
    .trim_end_matches(' ');
    if text.contains(": ") || text.ends_with(':') {
        return None;
    }
    plain(text)
}

/// A quoted scalar at the start of `s` that closes on this line: its value and the text after
/// the closing quote.
fn quoted(s: &str) -> Option<(String, &str)> {
    let q = s.as_bytes()[0];
    let body = &s[1..];
    // Most quoted scalars have no escape: when the first quote (or, in `"…"`, backslash) closes
    // the scalar, its text is copied in one piece.
    let b = body.as_bytes();
    let stop = if q == b'"' {
        memchr::memchr2(b'"', b'\\', b)
    } else {
        memchr::memchr(b'\'', b)
    };
    let i = stop?;
    if b[i] == q && !(q == b'\'' && b.get(i + 1) == Some(&b'\'')) {
        return Some((body[..i].to_owned(), &body[i + 1..]));
    }
    let mut out = String::new();
    let mut chars = body.char_indices();
    while let Some((i, ch)) = chars.next() {
        match ch {
            '\'' if q == b'\'' => {
                if body[i + 1..].starts_with('\'') {
                    chars.next();
                    out.push('\'');
                } else {
                    return Some((out, &body[i + 1..]));
                }
            }
            '"' if q == b'"' => return Some((out, &body[i + 1..])),
            '\\' if q == b'"' => {
                let (_, e) = chars.next()?;
                out.push(match e {
                    '\\' => '\\',
                    '"' => '"',
                    '/' => '/',
                    'n' => '\n',
                    't' => '\t',
                    'r' => '\r',
                    '0' => '\0',
                    'u' => {
                        let hex = body.get(i + 2..i + 6)?;
                        if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                            return None;
                        }
                        let c = char::from_u32(u32::from_str_radix(hex, 16).ok()?)?;
                        for _ in 0..4 {
                            chars.next();
                        }
                        c
                    }
                    _ => return None,
                });
            }
            c => out.push(c),
        }
    }
    None
}

/// Types a plain scalar as serde_norway does: null, boolean, a number by serde_norway's own
/// `Number` parser, else a string. `None` for texts this reader leaves to serde_norway (hex,
/// octal and binary integers, `.5`, `.inf`, and integers beyond 64 bits, which serde_norway
/// reports as an error).
fn plain(text: &str) -> Option<Value> {
    match text {
        "~" | "null" | "Null" | "NULL" => return Some(Value::Null),
        "true" | "True" | "TRUE" => return Some(Value::Bool(true)),
        "false" | "False" | "FALSE" => return Some(Value::Bool(false)),
        _ => {}
    }
    // Only a digit, a sign or a dot can start a number.
    if !matches!(text.as_bytes()[0], b'0'..=b'9' | b'+' | b'-' | b'.') {
        return Some(Value::String(text.to_owned()));
    }
    let body = text.strip_prefix(['+', '-']).unwrap_or(text);
    if body.starts_with('.') || ["0x", "0o", "0b"].iter().any(|p| body.starts_with(p)) {
        return None;
    }
    match text.parse::<serde_norway::Number>() {
        Ok(n) => Some(Value::Number(n)),
        // Digits that are no number: too large (an error in serde_norway), unless a leading
        // zero makes them a string.
        Err(_) if !body.is_empty() && body.bytes().all(|b| b.is_ascii_digit()) => {
            (body.len() > 1 && body.starts_with('0')).then(|| Value::String(text.to_owned()))
        }
        Err(_) => Some(Value::String(text.to_owned())),
    }
}

#[cfg(test)]
mod tests {
    use super::parse;
    use crate::parse::{test_support::fast_agrees, yaml::slow_value, Limits};
    use proptest::prelude::*;
    use proptest::strategy::ValueTree;

    /// serde_norway's reading of the same text, printed (`Debug` shows mapping order).
    fn slow(src: &str) -> String {
        match slow_value(src.as_bytes(), "t.yaml", &Limits::default(), "rtcProfile") {
            Ok(Some(v)) => format!("{v:?}"),
            other => format!("no value: {other:?}"),
        }
    }

    fn fast(src: &str) -> Option<String> {
        parse(src, Limits::default().max_depth, "rtcProfile").map(|v| format!("{v:?}"))
    }

    #[test]
    fn reads_the_common_forms_like_serde_norway() {
        let docs = [
            "rtcProfile:\n  a: 1\n  b: x\n",
            "---\nrtcProfile:\n  \"rtcDoc::doc\":\n    description: \"見る \\\"x\\\" \\u00e9\"\n",
            "# c\nrtcProfile: # c\n  list:\n  - a\n  - 'it''s'\n  -   x: 1\n      y: 2\n  - \n    z: ~\n",
            "rtcProfile:\r\n  version: 1.0.0\r\n  n: -5\r\n  f: 2.50\r\n  e: 1e3\r\n  z: 007\r\n",
            "rtcProfile:\n  k:\n    - - 1\n",
            "rtcProfile:\n  t: true\n  F: False\n  n: null\n  empty:\n  s: a#b # comment\n",
            "rtcProfile:\n  seq:\n    -\n      - a\n    - b\n  url: http://x/y?z=1\n",
        ];
        let mut accepted = 0;
        for d in docs {
            if let Some(v) = fast(d) {
                accepted += 1;
                assert_eq!(v, slow(d), "{d:?}");
            }
        }
        // All but the nested compact sequence (`- - 1`), which is left to serde_norway.
        assert_eq!(accepted, docs.len() - 1);
    }

    #[test]
    fn reads_the_example_profiles_like_serde_norway() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
        let mut n = 0;
        for e in std::fs::read_dir(dir).expect("examples") {
            let p = e.expect("entry").path().join("RTC.yaml");
            if let Ok(src) = std::fs::read_to_string(&p) {
                let v = fast(&src)
                    .unwrap_or_else(|| panic!("{} not read by the fast path", p.display()));
                assert_eq!(v, slow(&src), "{}", p.display());
                n += 1;
            }
        }
        assert!(n >= 2, "{n} example YAML profiles");
    }

    /// The published YAML profiles in `../shared/corpus`, when present: whatever the fast
    /// reader takes, it reads as serde_norway does.
    #[test]
    fn agrees_on_the_shared_corpus_when_present() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
        let (mut seen, mut taken) = (0, 0);
        for e in walkdir::WalkDir::new(dir)
            .into_iter()
            .filter_map(Result::ok)
        {
            let p = e.path();
            if !p.extension().is_some_and(|x| x == "yaml" || x == "yml") {
                continue;
            }
            let Ok(src) = std::fs::read_to_string(p) else {
                continue;
            };
            seen += 1;
            if let Some(v) = fast(&src) {
                taken += 1;
                assert_eq!(v, slow(&src), "{}", p.display());
            }
        }
        eprintln!("fast path: {taken} of {seen} corpus YAML files");
    }

    #[test]
    fn leaves_everything_else_to_serde_norway() {
        for d in [
            "rtcProfile: &a\n  x: 1\n",
            "rtcProfile:\n  x: *a\n",
            "rtcProfile:\n  x: [1, 2]\n",
            "rtcProfile:\n  x: |\n    text\n",
            "rtcProfile:\n  x: a\n    continued\n",
            "rtcProfile:\n  x: \"open\n    close\"\n",
            "rtcProfile:\n  x: 1\n  x: 2\n",
            "rtcProfile:\n\tx: 1\n",
            "rtcProfile:\n  x: 0x1F\n",
            "rtcProfile:\n  x: .5\n",
            "rtcProfile:\n  x: 123456789012345678901234567890\n",
            "rtcProfile:\n  1: x\n",
            "rtcProfile:\n  x: !tag a\n",
            "rtcProfile:\n  x: \"\\x41\"\n",
            "\u{feff}rtcProfile:\n  x: 1\n",
            "rtcProfile:\n  x: 1\n---\nother: 2\n",
            "%YAML 1.2\n---\nrtcProfile:\n  x: 1\n",
            "other:\n  x: 1\n",
            "rtcProfile:\n  x: a: b\n",
            "rtcProfile:\n  x: a\u{2028}b\n",
        ] {
            assert_eq!(fast(d), None, "{d:?}");
        }
        // Deep nesting is refused before the depth limit, whatever the file's length.
        let mut deep = String::new();
        for i in 0..10_000 {
            deep.push_str(&" ".repeat(i));
            deep.push_str("rtcProfile:\n");
        }
        assert_eq!(fast(&deep), None);
    }

    /// A generated YAML tree.
    #[derive(Debug, Clone)]
    enum N {
        S(&'static str),
        M(Vec<(&'static str, N)>),
        Q(Vec<N>),
    }

    const SCALARS: &[&str] = &[
        "a",
        "abc def",
        "rtcExt::properties",
        "1",
        "0",
        "-1",
        "+1",
        "007",
        "-007",
        "+0",
        "-0",
        "1.5",
        "1.",
        "1e3",
        "1E+3",
        "-2.5e-3",
        "1e999",
        "0x1F",
        "0o17",
        "0b101",
        ".5",
        ".inf",
        "-.inf",
        ".nan",
        "inf",
        "-inf",
        "nan",
        "true",
        "True",
        "TRUE",
        "tRue",
        "yes",
        "off",
        "null",
        "Null",
        "~",
        "",
        " ",
        "a: b",
        "a:b",
        "a #b",
        "a#b",
        "#x",
        "- x",
        "-x",
        "?x",
        "? x",
        ":x",
        "x:",
        "[a]",
        "a]",
        "{a}",
        "a,b",
        "&a",
        "*a",
        "!t",
        "|",
        ">",
        "'q'",
        "\"q\"",
        "it's",
        "say \"hi\"",
        "back\\slash",
        "tab\there",
        "é",
        "日本語",
        "\u{85}",
        "x\u{2028}",
        "---",
        "...",
        "%YAML",
        "@x",
        "`x",
        "12345678901234567890",
        "-9223372036854775809",
        "1_000",
        "123456789012345678901234567890",
        "-00",
        "1:30",
        "2008/04/18 14:00:00:Ver1.0",
        "http://x/y",
        "a  ",
        "  a",
        "line\nbreak",
        "\u{7f}",
        "\r",
        "ctl\u{1}",
    ];
    /// What real profiles hold, drawn three times as often as `SCALARS`.
    const COMMON: &[&str] = &[
        "a",
        "abc def",
        "rtcExt::properties",
        "1",
        "-1",
        "1.5",
        "true",
        "null",
        "",
        "é",
        "日本語",
        "say \"hi\"",
        "it's",
        "a#b",
        "1.0.0",
        "2008/04/18 14:00:00:Ver1.0",
        "http://x/y",
        "a,b",
    ];
    const KEYS: &[&str] = &[
        "name",
        "rtcDoc::doc",
        "a b",
        "x",
        "x",
        "1",
        "true",
        "~",
        "-k",
        "k:",
        "k #",
        "\"k\"",
        "",
        "é",
        "? k",
        "[k]",
        "k]",
        "&k",
        "0x1",
    ];
    const INSERTS: &[&str] = &[
        "#", " #x", ":", ": ", "\t", "'", "\"", "-", "- ", "\n", "\n  ", "[", "{", "&a ", "*a",
        "!t ", "|", ">", "---\n", "...\n", "\r", "\u{feff}", "\\", "%", " ", "  ", "\\u00",
    ];

    fn node() -> impl Strategy<Value = N> {
        let leaf = prop_oneof![
            3 => prop::sample::select(COMMON),
            1 => prop::sample::select(SCALARS),
        ]
        .prop_map(N::S);
        leaf.prop_recursive(4, 40, 5, |inner| {
            prop_oneof![
                prop::collection::vec((prop::sample::select(KEYS), inner.clone()), 0..5)
                    .prop_map(N::M),
                prop::collection::vec(inner, 0..4).prop_map(N::Q),
            ]
        })
    }

    /// Renders a tree as block YAML; every layout choice is taken from `choices`.
    struct R<'c> {
        out: String,
        choices: &'c [u8],
        k: usize,
        step: usize,
        nl: &'static str,
    }

    impl R<'_> {
        fn pick(&mut self, n: u8) -> u8 {
            let v = self.choices.get(self.k).copied().unwrap_or(0);
            self.k += 1;
            v % n
        }
        fn scalar(&mut self, s: &str) -> String {
            match self.pick(3) {
                0 => s.to_string(),
                1 => format!("'{}'", s.replace('\'', "''")),
                _ => {
                    let mut o = String::from("\"");
                    for c in s.chars() {
                        match c {
                            '"' => o.push_str("\\\""),
                            '\\' => o.push_str("\\\\"),
                            '\n' => o.push_str("\\n"),
                            '\t' => o.push_str("\\t"),
                            '/' if self.pick(2) == 0 => o.push_str("\\/"),
                            c if (c as u32) < 0x20 || c == '\u{7f}' || c == '\u{85}' => {
                                o.push_str(&format!("\\u{:04x}", c as u32))
                            }
                            'é' if self.pick(2) == 0 => o.push_str("\\u00E9"),
                            c => o.push(c),
                        }
                    }
                    o.push('"');
                    o
                }
            }
        }
        fn end_line(&mut self) {
            if self.pick(4) == 0 {
                self.out.push_str(" # note");
            }
            self.out.push_str(self.nl);
            if self.pick(6) == 0 {
                let ind = " ".repeat(self.pick(5) as usize);
                self.out.push_str(&format!("{ind}# comment{}", self.nl));
            }
        }
        /// Writes what follows `key:` (`indent`: the key's) or `-` (`after_key` false).
        fn value(&mut self, v: &N, indent: usize, after_key: bool) {
            match v {
                N::S(s) => {
                    let s = self.scalar(s);
                    self.out.push(' ');
                    self.out.push_str(&s);
                    self.end_line();
                }
                // `key:` with nothing after it is null, as `{}` would not be.
                N::M(e) if e.is_empty() && after_key && self.pick(2) == 0 => self.end_line(),
                N::M(e) if e.is_empty() => {
                    self.out.push_str(" {}");
                    self.end_line();
                }
                N::Q(q) if q.is_empty() => {
                    self.out.push_str(" []");
                    self.end_line();
                }
                // `- key: value`: a compact mapping on the item's line.
                N::M(e) if !after_key && self.pick(2) == 0 => {
                    let extra = 1 + self.pick(3) as usize;
                    self.out.push_str(&" ".repeat(extra));
                    let inner = indent + 1 + extra;
                    self.entry(e[0].0, &e[0].1, inner);
                    self.map(&e[1..], inner);
                }
                N::M(e) => {
                    self.end_line();
                    self.map(e, indent + self.step);
                }
                N::Q(q) => {
                    self.end_line();
                    // After a key, a sequence may sit at the key's own indent.
                    let ind = if after_key && self.pick(2) == 0 {
                        indent
                    } else {
                        indent + self.step
                    };
                    self.seq(q, ind);
                }
            }
        }
        fn entry(&mut self, k: &str, v: &N, indent: usize) {
            let k = self.scalar(k);
            self.out.push_str(&k);
            let colon = if self.pick(5) == 0 { " :" } else { ":" };
            self.out.push_str(colon);
            self.value(v, indent, true);
        }
        fn map(&mut self, e: &[(&str, N)], indent: usize) {
            for (k, v) in e {
                self.out.push_str(&" ".repeat(indent));
                self.entry(k, v, indent);
            }
        }
        fn seq(&mut self, q: &[N], indent: usize) {
            for v in q {
                self.out.push_str(&" ".repeat(indent));
                self.out.push('-');
                self.value(v, indent, false);
            }
        }
    }

    fn render(root: &N, extra: &[(&'static str, N)], choices: &[u8]) -> String {
        let mut r = R {
            out: String::new(),
            choices,
            k: 0,
            step: 1,
            nl: "\n",
        };
        r.step = 1 + r.pick(4) as usize;
        r.nl = if r.pick(4) == 0 { "\r\n" } else { "\n" };
        if r.pick(3) == 0 {
            r.out.push_str("---");
            let nl = r.nl;
            r.out.push_str(nl);
        }
        r.out.push_str("rtcProfile:");
        r.value(root, 0, true);
        r.map(extra, 0);
        r.out
    }

    /// The property below is only worth something if the fast reader takes most of the
    /// generated documents that are valid YAML: count them.
    #[test]
    fn takes_most_generated_documents() {
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let strategy = (
            node(),
            prop::collection::vec((prop::sample::select(KEYS), node()), 0..3),
            prop::collection::vec(any::<u8>(), 64),
        );
        let (mut taken, mut agreed, mut readable) = (0, 0, 0);
        for _ in 0..1000 {
            let (root, extra, choices) = strategy.new_tree(&mut runner).expect("tree").current();
            let doc = render(&root, &extra, &choices);
            readable += usize::from(!slow(&doc).starts_with("no value"));
            if let Some(v) = fast(&doc) {
                taken += 1;
                agreed += usize::from(v == slow(&doc));
            }
        }
        assert_eq!(taken, agreed);
        // The rest have anchors, tags, keys that are not strings and the like.
        assert!(
            taken * 2 > readable,
            "only {taken} of the {readable} documents serde_norway reads were taken"
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 4096, ..ProptestConfig::default() })]

        /// Whenever the fast reader returns a value, serde_norway reads the same value.
        #[test]
        fn agrees_with_serde_norway(
            root in node(),
            extra in prop::collection::vec((prop::sample::select(KEYS), node()), 0..3),
            choices in prop::collection::vec(any::<u8>(), 64),
            edits in prop::collection::vec((any::<usize>(), prop::sample::select(INSERTS)), 0..3),
        ) {
            fast_agrees(&render(&root, &extra, &choices), edits, fast, slow)?;
        }
    }
}
