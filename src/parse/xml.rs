//! XML reader for `RTC.xml` profiles (spec chapter 3.1, XSD chapter 6).
//!
//! Reading happens in three passes, each O(n) in the file size:
//!
//! 1. `decode`: bytes → text. UTF-8 (with or without BOM) is the default; an encoding named in
//!    the XML declaration (Shift_JIS, EUC-JP, …) is decoded with `encoding_rs`. Invalid bytes are
//!    an error pointing at the first bad byte.
//! 2. `build_tree` (or `xml_fast` for the common shape of file): text → a small element tree
//!    with namespaces resolved *by URI* and every element and attribute carrying its
//!    line:column. Hostile input (entity declarations, undefined entities, too deep nesting) is
//!    rejected while streaming.
//! 3. The mapping pass (`map_*` functions): tree → [`Profile`]. Whatever the spec does not define
//!    for a node is kept in that node's `extra` list and reported as a warning, so nothing in a
//!    profile is lost.

use super::{Limits, Parsed};
use crate::diagnostic::{codes, Diagnostic};
use crate::model::*;
use quick_xml::events::Event as XmlEvent;
use quick_xml::name::ResolveResult;
use quick_xml::reader::{NsReader, Reader};
use std::borrow::Cow;

/// Namespace URI of the basic profile (XSD 6.1).
pub const NS_RTC: &str = "http://www.openrtp.org/namespaces/rtc";
/// Namespace URI of the document profile (XSD 6.2).
pub const NS_RTC_DOC: &str = "http://www.openrtp.org/namespaces/rtc_doc";
/// Namespace URI of the extended profile (XSD 6.3).
pub const NS_RTC_EXT: &str = "http://www.openrtp.org/namespaces/rtc_ext";
/// XML Schema instance namespace (`xsi:type`).
pub const NS_XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";

/// Hard cap on nesting, whatever `Limits::max_depth` says: the mapping pass recurses over the
/// tree, and this keeps the stack bounded.
const HARD_MAX_DEPTH: usize = 1024;

/// True when the bytes look like an XML document whose root element is `RtcProfile`.
///
/// Skips a BOM, the XML declaration, comments, processing instructions and a DOCTYPE, then
/// looks at the local name of the first element only; `RtsProfile` (system profiles) and
/// anything that is not XML give `false`.
pub fn is_profile(bytes: &[u8]) -> bool {
    matches!(root_element(bytes), Root::Element(name) if name == "RtcProfile")
}

/// What the head of an XML file shows about its root element.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Root {
    /// The local name of the first element (`RtcProfile`, `RtsProfile`, …).
    Element(String),
    /// Only a prolog (declaration, comments, white space): the file ends before its root.
    Truncated,
    /// Not XML: the first thing after the prolog is neither an element nor white space.
    NotXml,
}

/// The root element of an XML document, from its head (UTF-8, UTF-16 with BOM).
pub fn root_element(bytes: &[u8]) -> Root {
    // UTF-16 needs decoding before a byte-oriented look; only the head is needed.
    let utf16 = match bytes {
        [0xFF, 0xFE, ..] => Some(encoding_rs::UTF_16LE),
        [0xFE, 0xFF, ..] => Some(encoding_rs::UTF_16BE),
        _ => None,
    };
    if let Some(enc) = utf16 {
        let head = &bytes[2..bytes.len().min(64 * 1024)];
        let (text, _) = enc.decode_without_bom_handling(head);
        return first_element(text.as_bytes());
    }
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    first_element(bytes)
}

fn first_element(bytes: &[u8]) -> Root {
    let mut reader = Reader::from_reader(bytes);
    // A prolog longer than this many events is not something we want to scan.
    for _ in 0..10_000 {
        match reader.read_event() {
            Ok(XmlEvent::Start(e)) | Ok(XmlEvent::Empty(e)) => {
                return Root::Element(
                    String::from_utf8_lossy(e.local_name().as_ref()).into_owned(),
                );
            }
            Ok(XmlEvent::Decl(_))
            | Ok(XmlEvent::Comment(_))
            | Ok(XmlEvent::PI(_))
            | Ok(XmlEvent::DocType(_)) => {}
            Ok(XmlEvent::Text(t)) if t.iter().all(u8::is_ascii_whitespace) => {}
            Ok(XmlEvent::Eof) => return Root::Truncated,
            _ => return Root::NotXml,
        }
    }
    Root::NotXml
}

/// Reads an RTC Profile from XML bytes.
///
/// Errors (never panics) on input that is not well-formed XML, uses a bad encoding, declares
/// entities, references undefined entities, nests deeper than `limits.max_depth`, or whose root
/// element is not `RtcProfile`. Missing elements are not errors: the model has defaults and the
/// `check` stage reports them. Unknown content becomes `extra` entries plus warnings.
pub fn parse(bytes: &[u8], file: &str, limits: &Limits) -> Result<Parsed, Diagnostic> {
    let text = decode(bytes, file)?;
    let root = match fast::build(&text, file, limits.max_depth.min(HARD_MAX_DEPTH)) {
        Some(root) => root,
        None => build_tree(&text, file, limits)?,
    };
    let mut m = Mapper {
        file,
        diags: Vec::new(),
        empties: super::dialect::EmptyUnknowns::default(),
        written_as: Vec::new(),
    };
    let mut profile = map_profile(&mut m, &root);
    profile.written_as = std::mem::take(&mut m.written_as);
    if let Some(d) = m.empties.note(file, profile.pos, "attribute") {
        m.diags.push(d);
    }
    Ok(Parsed {
        profile,
        diagnostics: m.diags,
    })
}

#[path = "xml_fast.rs"]
mod fast;

/// The mapping of RT System profiles (`RtsProfile`), on this module's decoder and tree.
#[path = "rts_xml.rs"]
pub(super) mod rts;

// ---------------------------------------------------------------------------------------------
// Pass 1: decoding
// ---------------------------------------------------------------------------------------------

/// Bytes → text, honouring a BOM or the encoding named in the XML declaration.
fn decode<'a>(bytes: &'a [u8], file: &str) -> Result<Cow<'a, str>, Diagnostic> {
    if let Some(rest) = bytes.strip_prefix(b"\xEF\xBB\xBF") {
        return utf8(rest, file).map(Cow::Borrowed);
    }
    match bytes {
        [0xFF, 0xFE, rest @ ..] => return decode_with(encoding_rs::UTF_16LE, rest, file),
        [0xFE, 0xFF, rest @ ..] => return decode_with(encoding_rs::UTF_16BE, rest, file),
        _ => {}
    }
    let Some((label, label_at)) = declared_encoding(bytes) else {
        return utf8(bytes, file).map(Cow::Borrowed);
    };
    let Some(enc) = encoding_rs::Encoding::for_label(label.as_bytes()) else {
        return Err(Diagnostic::error(
            codes::ENCODING,
            file,
            format!("unknown encoding `{label}` in the XML declaration"),
        )
        .at(Pos::new(1, label_at as u32 + 1))
        .with_hint("save the file as UTF-8 or declare a known encoding such as Shift_JIS"));
    };
    // Without a BOM the declaration itself was readable as ASCII, so a UTF-16 label is wrong;
    // the bytes are treated as UTF-8 (what encoding_rs calls the output encoding).
    if enc == encoding_rs::UTF_8 || enc == encoding_rs::UTF_16LE || enc == encoding_rs::UTF_16BE {
        return utf8(bytes, file).map(Cow::Borrowed);
    }
    decode_with(enc, bytes, file)
}

fn utf8<'a>(bytes: &'a [u8], file: &str) -> Result<&'a str, Diagnostic> {
    std::str::from_utf8(bytes).map_err(|e| {
        let good = bytes
            .get(..e.valid_up_to())
            .and_then(|b| std::str::from_utf8(b).ok())
            .unwrap_or("");
        let b = bytes.get(e.valid_up_to()).copied().unwrap_or(0);
        encoding_error(file, good, &format!("byte 0x{b:02X} is not valid UTF-8"))
    })
}

fn decode_with<'a>(
    enc: &'static encoding_rs::Encoding,
    bytes: &[u8],
    file: &str,
) -> Result<Cow<'a, str>, Diagnostic> {
    let mut decoder = enc.new_decoder_without_bom_handling();
    let cap = decoder
        .max_utf8_buffer_length_without_replacement(bytes.len())
        .unwrap_or(bytes.len().saturating_mul(3));
    let mut out = String::with_capacity(cap);
    let (res, _read) = decoder.decode_to_string_without_replacement(bytes, &mut out, true);
    match res {
        encoding_rs::DecoderResult::InputEmpty => Ok(Cow::Owned(out)),
        encoding_rs::DecoderResult::Malformed(_, _) => Err(encoding_error(
            file,
            &out,
            &format!("bytes that are not valid {}", enc.name()),
        )),
        encoding_rs::DecoderResult::OutputFull => Err(Diagnostic::error(
            codes::ENCODING,
            file,
            format!("could not decode the file as {}", enc.name()),
        )),
    }
}

/// An encoding error just after the correctly decoded prefix `good`.
fn encoding_error(file: &str, good: &str, what: &str) -> Diagnostic {
    let index = LineIndex::new(good);
    let pos = index.pos(good.len());
    Diagnostic::error(
        codes::ENCODING,
        file,
        format!("invalid encoding: {what} at {pos}"),
    )
    .at(pos)
    .with_hint("save the file as UTF-8, or declare its real encoding in the XML declaration")
}

/// The `encoding` pseudo-attribute of an XML declaration at the very start, with the byte
/// offset of the label (the declaration is on line 1, ASCII).
fn declared_encoding(bytes: &[u8]) -> Option<(String, usize)> {
    let head = bytes.get(..bytes.len().min(1024))?;
    if !head.starts_with(b"<?xml") {
        return None;
    }
    let end = head.windows(2).position(|w| w == b"?>")?;
    let decl = head.get(..end)?;
    let at = decl.windows(8).position(|w| w == b"encoding")?;
    let mut i = at + 8;
    let skip_ws = |i: &mut usize| {
        while decl.get(*i).is_some_and(u8::is_ascii_whitespace) {
            *i += 1;
        }
    };
    skip_ws(&mut i);
    if decl.get(i) != Some(&b'=') {
        return None;
    }
    i += 1;
    skip_ws(&mut i);
    let quote = *decl.get(i)?;
    if quote != b'"' && quote != b'\'' {
        return None;
    }
    let start = i + 1;
    let len = decl.get(start..)?.iter().position(|&b| b == quote)?;
    let label = std::str::from_utf8(decl.get(start..start + len)?).ok()?;
    Some((label.trim().to_string(), start))
}

// ---------------------------------------------------------------------------------------------
// Positions
// ---------------------------------------------------------------------------------------------

/// Byte offset → 1-based line:column (columns count characters). Line breaks are LF, CRLF and
/// a lone CR (XML 1.0 §2.11).
struct LineIndex<'a> {
    text: &'a str,
    starts: Vec<usize>,
}

impl<'a> LineIndex<'a> {
    fn new(text: &'a str) -> Self {
        let b = text.as_bytes();
        let mut starts = vec![0];
        for i in memchr::memchr2_iter(b'\n', b'\r', b) {
            if b[i] == b'\n' || b.get(i + 1) != Some(&b'\n') {
                starts.push(i + 1);
            }
        }
        LineIndex { text, starts }
    }

    fn pos(&self, offset: usize) -> Pos {
        let offset = self.boundary(offset);
        self.pos_on(self.line_of(offset), offset)
    }

    /// `offset`, within the text and moved back to a character boundary.
    fn boundary(&self, offset: usize) -> usize {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        offset
    }

    /// Index in `starts` of the line holding `offset`.
    fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset).max(1) - 1
    }

    /// Position of `offset` (a boundary) on line `line` (an index in `starts`).
    fn pos_on(&self, line: usize, offset: usize) -> Pos {
        let start = self.starts.get(line).copied().unwrap_or(0).min(offset);
        let col = self
            .text
            .get(start..offset)
            .map_or(0, |s| s.chars().count());
        Pos::new(
            u32::try_from(line + 1).unwrap_or(u32::MAX),
            u32::try_from(col + 1).unwrap_or(u32::MAX),
        )
    }
}

/// Like [`LineIndex`] but fast for increasing offsets (the streaming case): the line is found
/// by stepping forward from the last one asked for, and columns are counted from the last
/// position when it is on the same line, so long single-line files stay O(n).
struct PosCursor<'a> {
    index: LineIndex<'a>,
    /// The last offset asked for (on a character boundary), its position, and the index of
    /// its line in `index.starts`.
    last: (usize, Pos, usize),
}

impl<'a> PosCursor<'a> {
    fn new(text: &'a str) -> Self {
        PosCursor {
            index: LineIndex::new(text),
            last: (0, Pos::new(1, 1), 0),
        }
    }

    fn pos(&mut self, offset: usize) -> Pos {
        let index = &self.index;
        let starts = &index.starts;
        let off = index.boundary(offset);
        let (last_off, last_pos, last_line) = self.last;
        let (p, line) = if off >= last_off {
            // Step forward a few lines; search beyond that.
            let mut line = last_line;
            let mut steps = 0;
            while line + 1 < starts.len() && starts[line + 1] <= off && steps < 8 {
                line += 1;
                steps += 1;
            }
            if line + 1 < starts.len() && starts[line + 1] <= off {
                line += starts[line + 1..].partition_point(|&s| s <= off);
            }
            let p = if line == last_line {
                // Count only the characters since the last position.
                let n = index
                    .text
                    .get(last_off..off)
                    .map_or(0, |s| s.chars().count());
                Pos::new(last_pos.line, last_pos.column.saturating_add(n as u32))
            } else {
                index.pos_on(line, off)
            };
            (p, line)
        } else {
            let line = index.line_of(off);
            (index.pos_on(line, off), line)
        };
        self.last = (off, p, line);
        p
    }
}

// ---------------------------------------------------------------------------------------------
// Pass 2: element tree
// ---------------------------------------------------------------------------------------------

/// Which namespace a name is in.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Ns {
    Rtc,
    Doc,
    Ext,
    Xsi,
    /// No namespace (unprefixed attribute, or element without a default namespace).
    None,
    Other(String),
}

impl Ns {
    fn from_uri(uri: &[u8]) -> Ns {
        match uri {
            b"http://www.openrtp.org/namespaces/rtc" => Ns::Rtc,
            b"http://www.openrtp.org/namespaces/rtc_doc" => Ns::Doc,
            b"http://www.openrtp.org/namespaces/rtc_ext" => Ns::Ext,
            b"http://www.w3.org/2001/XMLSchema-instance" => Ns::Xsi,
            _ => Ns::Other(String::from_utf8_lossy(uri).into_owned()),
        }
    }
    fn uri(&self) -> Option<Text> {
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
    fn is_rtc_family(&self) -> bool {
        matches!(self, Ns::Rtc | Ns::Doc | Ns::Ext | Ns::None)
    }
}

#[derive(Debug)]
struct Attr<'t> {
    qname: Cow<'t, str>,
    ns: Ns,
    local: Cow<'t, str>,
    value: Cow<'t, str>,
    pos: Pos,
}

impl Attr<'_> {
    /// The local name when the attribute may carry a known RTC field.
    fn key(&self) -> Option<&str> {
        self.ns.is_rtc_family().then_some(&*self.local)
    }
}

#[derive(Debug)]
struct Node<'t> {
    qname: Cow<'t, str>,
    ns: Ns,
    local: Cow<'t, str>,
    /// Attributes, without the plumbing (`xmlns*`, `xsi:type`, schema locations).
    attrs: Vec<Attr<'t>>,
    children: Vec<Node<'t>>,
    /// All character data directly inside the element, unescaped and EOL-normalised.
    text: String,
    /// Position of the first non-whitespace character data.
    text_pos: Option<Pos>,
    pos: Pos,
}

impl Node<'_> {
    /// The local name when the element may be a known RTC element.
    fn key(&self) -> Option<&str> {
        self.ns.is_rtc_family().then_some(&*self.local)
    }
    /// Lower-cased key, for the case-insensitive constraint vocabulary (spec 8.1 vs XSD).
    fn key_lower(&self) -> Option<String> {
        self.key().map(str::to_ascii_lowercase)
    }
    fn has_text(&self) -> bool {
        !is_blank(&self.text)
    }
}

struct TreeBuilder<'t, 'f> {
    text: &'t str,
    file: &'f str,
    cursor: PosCursor<'t>,
    max_depth: usize,
}

impl<'t, 'f> TreeBuilder<'t, 'f> {
    fn new(text: &'t str, file: &'f str, max_depth: usize) -> Self {
        TreeBuilder {
            text,
            file,
            cursor: PosCursor::new(text),
            max_depth,
        }
    }

    fn err(&mut self, code: &'static str, offset: usize, msg: impl Into<String>) -> Diagnostic {
        let pos = self.cursor.pos(offset);
        Diagnostic::error(code, self.file, msg).at(pos)
    }
}

/// Text → element tree of an RTC profile (root `RtcProfile`); see [`build_any_tree`].
fn build_tree<'t>(text: &'t str, file: &str, limits: &Limits) -> Result<Node<'t>, Diagnostic> {
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
fn build_any_tree<'t>(text: &'t str, file: &str, limits: &Limits) -> Result<Node<'t>, Diagnostic> {
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
                .with_hint("raise `max_depth` if the file is genuine"));
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
fn own_ns(ns: ResolveResult<'_>) -> Result<Ns, String> {
    match ns {
        ResolveResult::Bound(uri) => Ok(Ns::from_uri(uri.as_ref())),
        ResolveResult::Unbound => Ok(Ns::None),
        ResolveResult::Unknown(p) => Err(String::from_utf8_lossy(&p).into_owned()),
    }
}

/// Everything but start tags and end of file: end tags, text, references, DOCTYPE, ….
fn other_event<'t>(
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
fn close<'t>(node: Node<'t>, stack: &mut [Node<'t>], root: &mut Option<Node<'t>>) {
    match stack.last_mut() {
        Some(parent) => parent.children.push(node),
        None => *root = Some(node),
    }
}

fn add_text(
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
fn is_blank(s: &str) -> bool {
    s.bytes().all(|b| matches!(b, b' ' | b'\t' | b'\n' | b'\r')) || s.trim().is_empty()
}

/// A byte of an ASCII XML name (`rtc:DataPorts`, `a.b-c_d`).
fn is_ascii_name_byte(c: &u8) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, b'_' | b':' | b'-' | b'.')
}

/// A loose check of XML 1.0 `Name` (§2.3): quick-xml accepts anything up to whitespace or `>`.
fn is_name(s: &str) -> bool {
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
fn sub<'t>(whole: &'t str, part: &[u8]) -> Cow<'t, str> {
    offset_in(whole, part)
        .and_then(|off| whole.get(off..off.checked_add(part.len())?))
        .map_or_else(
            || Cow::Owned(String::from_utf8_lossy(part).into_owned()),
            Cow::Borrowed,
        )
}

/// Byte offset of `part` inside `whole`, when `part` borrows from it.
fn offset_in(whole: &str, part: &[u8]) -> Option<usize> {
    let start = whole.as_ptr() as usize;
    let p = part.as_ptr() as usize;
    let off = p.checked_sub(start)?;
    (off <= whole.len()).then_some(off)
}

/// XML 1.0 §2.11: CRLF and lone CR become LF.
fn normalize_eol(s: &str) -> Cow<'_, str> {
    if !s.contains('\r') {
        return Cow::Borrowed(s);
    }
    Cow::Owned(s.replace("\r\n", "\n").replace('\r', "\n"))
}

/// Resolves the name of a reference `&name;`: the five predefined entities and character
/// references. Anything else is refused (no DTD, no expansion ever).
fn resolve_ref(name: &str) -> Result<String, String> {
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
fn unescape_attr(raw: Cow<'_, str>) -> Result<Cow<'_, str>, (usize, String)> {
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

fn entity_error(b: &mut TreeBuilder<'_, '_>, offset: usize, msg: String) -> Diagnostic {
    let code = if msg.starts_with("reference to undefined entity") {
        codes::ENTITY
    } else {
        codes::MALFORMED
    };
    b.err(code, offset, msg)
}

/// `xmlns` and `xmlns:p` attributes: namespace declarations, not data.
fn is_ns_declaration(key: &[u8]) -> bool {
    key == b"xmlns" || key.starts_with(b"xmlns:")
}

/// `xsi:type` (the concrete XSD type) and the schema locations: plumbing, not data.
fn is_schema_plumbing(ns: &Ns, local: &str) -> bool {
    *ns == Ns::Xsi
        && matches!(
            local,
            "type" | "schemaLocation" | "noNamespaceSchemaLocation"
        )
}

/// The attribute names of one tag met so far: a short list, or a hash set once the tag has
/// many attributes (so that hostile tags stay linear).
#[derive(Default)]
struct Seen<'a> {
    small: Vec<Cow<'a, str>>,
    big: Option<std::collections::HashSet<Cow<'a, str>>>,
}

impl<'a> Seen<'a> {
    /// Adds `key`; false when it was already there.
    fn insert(&mut self, key: Cow<'a, str>) -> bool {
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

fn attr_error(e: &quick_xml::events::attributes::AttrError) -> String {
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
fn malformed(
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

// ---------------------------------------------------------------------------------------------
// Pass 3: tree → model
// ---------------------------------------------------------------------------------------------

struct Mapper<'f> {
    file: &'f str,
    diags: Vec<Diagnostic>,
    /// Empty unknown attributes (wasanbon writes many): summarised in one note.
    empties: super::dialect::EmptyUnknowns,
    /// Values read under an older spelling, for [`Profile::written_as`].
    written_as: Vec<WrittenAs>,
}

impl Mapper<'_> {
    fn warn(&mut self, pos: Pos, msg: String) {
        self.diags
            .push(Diagnostic::warning(codes::UNKNOWN, self.file, msg).at(pos));
    }

    /// An attribute the spec does not define on `on`. An empty one (`rtcDoc:license=""` on a
    /// configuration doc, as wasanbon writes them by the dozen) says nothing: it is kept, and
    /// counted for the profile's one summary note instead of a warning of its own.
    fn unknown_attr(&mut self, a: &Attr, on: &str, extra: &mut Vec<Extra>) {
        if a.value.trim().is_empty() {
            self.empties.add(&a.qname);
            extra.push(attr_extra(a));
            return;
        }
        self.warn(
            a.pos,
            format!(
                "unknown attribute `{}`{} on {on}; kept as an extra property",
                a.qname,
                foreign(&a.ns)
            ),
        );
        extra.push(attr_extra(a));
    }

    /// An element the spec does not define inside `on` (kept with its whole subtree).
    fn unknown_elem(&mut self, n: &Node, on: &str, extra: &mut Vec<Extra>) {
        self.warn(
            n.pos,
            format!(
                "unknown element `{}`{} in {on}; kept as an extra property",
                n.qname,
                foreign(&n.ns)
            ),
        );
        extra.push(node_extra(n));
    }

    /// A second occurrence of an element or attribute allowed once.
    fn repeated_elem(&mut self, n: &Node, on: &str, extra: &mut Vec<Extra>) {
        self.warn(
            n.pos,
            format!(
                "repeated element `{}` in {on}; only the first is used, this one is kept as an extra property",
                n.qname
            ),
        );
        extra.push(node_extra(n));
    }

    /// Sets a known attribute's field; a duplicate (same local name in two namespaces) goes
    /// to `extra`.
    fn set(&mut self, slot: &mut Option<Text>, a: &Attr, on: &str, extra: &mut Vec<Extra>) {
        if slot.is_some() {
            self.warn(
                a.pos,
                format!(
                    "repeated attribute `{}` on {on}; the first is used, this one is kept as an extra property",
                    a.qname
                ),
            );
            extra.push(attr_extra(a));
        } else {
            *slot = Some((&*a.value).into());
        }
    }

    /// Non-whitespace text directly inside an element that holds no text.
    fn stray_text(&mut self, n: &Node, on: &str, extra: &mut Vec<Extra>) {
        if n.has_text() {
            let pos = n.text_pos.unwrap_or(n.pos);
            self.warn(
                pos,
                format!("unexpected text in {on}; kept as an extra property"),
            );
            extra.push(Extra {
                kind: ExtraKind::Element,
                name: "#text".into(),
                namespace: None,
                value: Some(n.text.as_str().into()),
                children: Vec::new(),
                pos,
            });
        }
    }

    /// Text content of a text-only element (`VersionUpLogs`, `cpus`, `Literal`, …). Its
    /// attributes and child elements are unknown and go to `extra` of the owning node.
    fn text_of(&mut self, n: &Node, on: &str, extra: &mut Vec<Extra>) -> Text {
        if !n.attrs.is_empty() || !n.children.is_empty() {
            let what = format!("`{}` of {on}", n.qname);
            for a in &n.attrs {
                self.unknown_attr(a, &what, extra);
            }
            for c in &n.children {
                self.unknown_elem(c, &what, extra);
            }
        }
        n.text.as_str().into()
    }

    /// Reports every attribute of an element that has none defined.
    fn no_attrs(&mut self, n: &Node, on: &str, extra: &mut Vec<Extra>) {
        for a in &n.attrs {
            self.unknown_attr(a, on, extra);
        }
    }
}

fn foreign(ns: &Ns) -> String {
    match ns {
        Ns::Other(uri) => format!(" (namespace {uri})"),
        _ => String::new(),
    }
}

fn attr_extra(a: &Attr) -> Extra {
    Extra {
        kind: ExtraKind::Attribute,
        name: (&*a.qname).into(),
        namespace: a.ns.uri(),
        value: Some((&*a.value).into()),
        children: Vec::new(),
        pos: a.pos,
    }
}

/// An unknown element with its whole subtree: attributes first, then child elements.
fn node_extra(n: &Node) -> Extra {
    let mut children: Vec<Extra> = n.attrs.iter().map(attr_extra).collect();
    children.extend(n.children.iter().map(node_extra));
    Extra {
        kind: ExtraKind::Element,
        name: (&*n.qname).into(),
        namespace: n.ns.uri(),
        value: n.has_text().then(|| n.text.as_str().into()),
        children,
        pos: n.pos,
    }
}

impl Mapper<'_> {
    /// Records that attribute `a` was read as `field` of `node` under an older spelling.
    fn alias(&mut self, node: &str, field: &str, a: &Attr, dialect: &'static str) {
        self.written_as.push(WrittenAs {
            field: compact_str::format_compact!("{node}.{field}"),
            written_as: (&*a.qname).into(),
            dialect,
            pos: a.pos,
        });
    }
}

/// Records the position of a known attribute in `pos` (by its spec field name).
fn note_pos(pos: &mut AttrPos, a: &Attr) {
    if let Some(f) = a.key().and_then(field_name) {
        pos.note(f, a.pos);
    }
}

/// Non-empty text of a text element (whitespace-only counts as empty).
fn non_blank(s: &str) -> Option<Text> {
    (!s.trim().is_empty()).then(|| s.into())
}

/// spec 2.2 `rtc_profile`, XSD 6.1 `RtcProfile`.
fn map_profile(m: &mut Mapper, n: &Node) -> Profile {
    let on = "profile";
    let mut p = Profile {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        note_pos(&mut p.attr_pos, a);
        let slot = match a.key() {
            Some("id") => &mut p.id,
            Some("version") => &mut p.version,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    let mut seen_basic = false;
    for c in &n.children {
        match c.key() {
            Some("BasicInfo") if !seen_basic => {
                seen_basic = true;
                p.basic_info = map_basic_info(m, c);
            }
            Some("Actions") if p.actions_pos.is_none() => {
                p.actions_pos = Some(c.pos);
                map_actions(m, c, &mut p.actions, &mut extra);
            }
            Some("ConfigurationSet") if p.configuration_set.is_none() => {
                p.configuration_set = Some(map_configuration_set(m, c));
            }
            Some("DataPorts") => p.data_ports.push(map_data_port(m, c)),
            Some("ServicePorts") => p.service_ports.push(map_service_port(m, c)),
            Some("Parameters") => p.parameters.push(map_parameter(m, c)),
            Some("Language") if p.language.is_none() => p.language = Some(map_language(m, c)),
            Some("BasicInfo" | "Actions" | "ConfigurationSet" | "Language") => {
                m.repeated_elem(c, on, &mut extra)
            }
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    p.extra = extra;
    p
}

/// spec 2.3.2 basic info, 2.4.1 doc, 2.5.1 ext.
fn map_basic_info(m: &mut Mapper, n: &Node) -> BasicInfo {
    let on = "basic info";
    let mut b = BasicInfo {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        note_pos(&mut b.attr_pos, a);
        let slot = match a.key() {
            Some("name") => &mut b.name,
            Some("componentType") => &mut b.component_type,
            Some("activityType") => &mut b.activity_type,
            Some("componentKind") => &mut b.component_kind,
            Some("rtcType") => &mut b.rtc_type,
            Some("category") => &mut b.category,
            Some("description") => &mut b.description,
            Some("executionRate") => &mut b.execution_rate,
            Some("executionType") => &mut b.execution_type,
            Some("maxInstances") => &mut b.max_instances,
            Some("vendor") => &mut b.vendor,
            Some("version") => &mut b.version,
            Some("abstract") => &mut b.abstract_,
            Some("hardwareProfile") => &mut b.hardware_profile,
            Some("creationDate") => &mut b.creation_date,
            Some("updateDate") => &mut b.update_date,
            Some("comment") => &mut b.comment,
            Some("saveProject") => &mut b.save_project,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if b.doc.is_none() => b.doc = Some(map_basic_doc(m, c)),
            // XSD 6.3 `VersionUpLogs`; the 9.2 sample writes `VersionUpLog`. Empty ones are
            // common in real files and say nothing.
            Some("VersionUpLogs" | "VersionUpLog") => {
                if let Some(t) = non_blank(&m.text_of(c, on, &mut extra)) {
                    b.version_up_logs.push(t);
                }
            }
            Some("Properties") => b.properties.push(map_property(m, c)),
            Some("Doc") => m.repeated_elem(c, on, &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    b.extra = extra;
    b
}

/// spec 2.4.2 `doc_basic`.
fn map_basic_doc(m: &mut Mapper, n: &Node) -> BasicDoc {
    let on = "basic info doc";
    let mut d = BasicDoc {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("description") => &mut d.description,
            Some("inout") => &mut d.inout,
            Some("algorithm") => &mut d.algorithm,
            Some("creator") => &mut d.creator,
            Some("license") => &mut d.license,
            Some("reference") => &mut d.reference,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    leaf_children(m, n, on, &mut extra);
    d.extra = extra;
    d
}

/// Child elements and text of a node that has none defined.
fn leaf_children(m: &mut Mapper, n: &Node, on: &str, extra: &mut Vec<Extra>) {
    for c in &n.children {
        m.unknown_elem(c, on, extra);
    }
    m.stray_text(n, on, extra);
}

/// spec 2.3.3 actions: the 14 callbacks, kept in document order. Unknown content of the
/// `Actions` element itself goes to the profile's extras.
fn map_actions(m: &mut Mapper, n: &Node, actions: &mut Vec<Action>, extra: &mut Vec<Extra>) {
    let on = "actions";
    m.no_attrs(n, on, extra);
    for c in &n.children {
        let kind = c.key().and_then(ActionKind::from_xml_name);
        match kind {
            Some(k) if actions.iter().all(|a| a.kind != k) => actions.push(map_action(m, c, k)),
            Some(_) => m.repeated_elem(c, on, extra),
            None => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
}

/// spec 2.3.4 `action_status`, 2.4.3 `doc_action`.
fn map_action(m: &mut Mapper, n: &Node, kind: ActionKind) -> Action {
    let on = format!("action {}", kind.xml_name());
    let mut act = Action {
        kind,
        implemented: None,
        doc: None,
        pos: n.pos,
        extra: Vec::new(),
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        match a.key() {
            Some("implemented") => m.set(&mut act.implemented, a, &on, &mut extra),
            _ => m.unknown_attr(a, &on, &mut extra),
        }
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if act.doc.is_none() => {
                let don = format!("{on} doc");
                let mut d = ActionDoc {
                    pos: c.pos,
                    ..Default::default()
                };
                let mut dx = Vec::new();
                for a in &c.attrs {
                    let slot = match a.key() {
                        Some("description") => &mut d.description,
                        Some("preCondition") => &mut d.pre_condition,
                        Some("postCondition") => &mut d.post_condition,
                        _ => {
                            m.unknown_attr(a, &don, &mut dx);
                            continue;
                        }
                    };
                    m.set(slot, a, &don, &mut dx);
                }
                leaf_children(m, c, &don, &mut dx);
                d.extra = dx;
                act.doc = Some(d);
            }
            Some("Doc") => m.repeated_elem(c, &on, &mut extra),
            _ => m.unknown_elem(c, &on, &mut extra),
        }
    }
    m.stray_text(n, &on, &mut extra);
    act.extra = extra;
    act
}

/// spec 2.3.5 `configuration_set`.
fn map_configuration_set(m: &mut Mapper, n: &Node) -> ConfigurationSet {
    let on = "configuration set";
    let mut cs = ConfigurationSet {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    m.no_attrs(n, on, &mut extra);
    for c in &n.children {
        match c.key() {
            Some("Configuration") => cs.configurations.push(map_configuration(m, c)),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    cs.extra = extra;
    cs
}

/// spec 2.3.6 `configuration`, 2.4.4 doc, 2.5.2 ext.
fn map_configuration(m: &mut Mapper, n: &Node) -> Configuration {
    let on = "configuration";
    let mut cf = Configuration {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    let mut aliases = Vec::new();
    for a in &n.attrs {
        note_pos(&mut cf.attr_pos, a);
        let slot = match a.key() {
            Some("name") => &mut cf.name,
            Some("type") => &mut cf.type_,
            Some("defaultValue") => &mut cf.default_value,
            Some("unit") => &mut cf.unit,
            Some("comment") => &mut cf.comment,
            Some("variableName") => &mut cf.variable_name,
            // RTCBuilder 0.1 / rtc-template: `varname` is the variable name.
            Some("varname") => {
                aliases.push(("variableName", a));
                &mut cf.variable_name
            }
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if cf.doc.is_none() => {
                let don = "configuration doc";
                let mut d = ConfigurationDoc {
                    pos: c.pos,
                    ..Default::default()
                };
                let mut dx = Vec::new();
                for a in &c.attrs {
                    let slot = match a.key() {
                        Some("dataname") => &mut d.dataname,
                        Some("defaultValue") => &mut d.default_value,
                        Some("description") => &mut d.description,
                        Some("unit") => &mut d.unit,
                        Some("range") => &mut d.range,
                        Some("constraint") => &mut d.constraint,
                        _ => {
                            m.unknown_attr(a, don, &mut dx);
                            continue;
                        }
                    };
                    m.set(slot, a, don, &mut dx);
                }
                leaf_children(m, c, don, &mut dx);
                d.extra = dx;
                cf.doc = Some(d);
            }
            Some("Properties") => cf.properties.push(map_property(m, c)),
            Some("Constraint") if cf.constraint.is_none() => {
                cf.constraint = Some(map_constraint(m, c))
            }
            Some("Doc" | "Constraint") => m.repeated_elem(c, on, &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    let node = format!("configuration {}", cf.name.as_deref().unwrap_or(""));
    for (field, a) in aliases {
        m.alias(&node, field, a, super::dialect::RTCBUILDER_01);
    }
    cf.extra = extra;
    cf
}

/// spec 2.5 `property` (`rtcExt:Properties`).
fn map_property(m: &mut Mapper, n: &Node) -> Property {
    let on = "property";
    let mut p = Property {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("name") => &mut p.name,
            Some("value") => &mut p.value,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    leaf_children(m, n, on, &mut extra);
    p.extra = extra;
    p
}

/// spec 2.3.7 `dataport`, 2.4.5 doc, 2.5.3 ext; FSM `EventPort`s carry `Event` children.
fn map_data_port(m: &mut Mapper, n: &Node) -> DataPort {
    let on = "data port";
    let mut d = DataPort {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    let mut aliases = Vec::new();
    for a in &n.attrs {
        note_pos(&mut d.attr_pos, a);
        let slot = match a.key() {
            Some("portType") => &mut d.port_type,
            Some("name") => &mut d.name,
            Some("type") => &mut d.type_,
            Some("idlFile") => &mut d.idl_file,
            Some("interfaceType") => &mut d.interface_type,
            Some("dataflowType") => &mut d.dataflow_type,
            Some("subscriptionType") => &mut d.subscription_type,
            // RTCBuilder 0.1 (2009) misspells it.
            Some("subscriprionType") => {
                aliases.push(("subscriptionType", a));
                &mut d.subscription_type
            }
            Some("unit") => &mut d.unit,
            Some("comment") => &mut d.comment,
            Some("variableName") => &mut d.variable_name,
            // RTCBuilder 0.1: `rtcExt:varname` is the variable name.
            Some("varname") => {
                aliases.push(("variableName", a));
                &mut d.variable_name
            }
            Some("position") => &mut d.position,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if d.doc.is_none() => {
                d.doc = Some(map_data_port_doc(m, c, "data port doc"))
            }
            Some("Properties") => d.properties.push(map_property(m, c)),
            Some("Constraint") if d.constraint.is_none() => {
                d.constraint = Some(map_constraint(m, c))
            }
            Some("Event") => d.events.push(map_event(m, c)),
            Some("Doc" | "Constraint") => m.repeated_elem(c, on, &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    let node = format!("dataPort {}", d.name.as_deref().unwrap_or(""));
    for (field, a) in aliases {
        m.alias(&node, field, a, super::dialect::RTCBUILDER_01);
    }
    d.extra = extra;
    d
}

/// spec 2.4.6 `doc_dataport` (also used for FSM event docs, `rtcDoc:event_doc`).
fn map_data_port_doc(m: &mut Mapper, n: &Node, on: &str) -> DataPortDoc {
    let mut d = DataPortDoc {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("description") => &mut d.description,
            Some("type") => &mut d.type_,
            Some("number") => &mut d.number,
            Some("semantics") => &mut d.semantics,
            Some("unit") => &mut d.unit,
            // RTCBuilder writes `occerrence`: accepted silently as the same field.
            Some("occurrence" | "occerrence") => &mut d.occurrence,
            Some("operation") => &mut d.operation,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    leaf_children(m, n, on, &mut extra);
    d.extra = extra;
    d
}

/// An FSM event of an `EventPort` (RTCBuilder 2.x; not in spec v0.2).
fn map_event(m: &mut Mapper, n: &Node) -> Event {
    let on = "event";
    let mut e = Event {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("name") => &mut e.name,
            Some("type") => &mut e.type_,
            Some("source") => &mut e.source,
            Some("target") => &mut e.target,
            Some("condition") => &mut e.condition,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if e.doc.is_none() => e.doc = Some(map_data_port_doc(m, c, "event doc")),
            Some("Doc") => m.repeated_elem(c, on, &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    e.extra = extra;
    e
}

/// spec 2.3.8 `serviceport`, 2.4.7 doc, 2.5.4 ext.
fn map_service_port(m: &mut Mapper, n: &Node) -> ServicePort {
    let on = "service port";
    let mut s = ServicePort {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        note_pos(&mut s.attr_pos, a);
        let slot = match a.key() {
            Some("name") => &mut s.name,
            Some("comment") => &mut s.comment,
            Some("position") => &mut s.position,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if s.doc.is_none() => {
                let don = "service port doc";
                let mut d = ServicePortDoc {
                    pos: c.pos,
                    ..Default::default()
                };
                let mut dx = Vec::new();
                for a in &c.attrs {
                    let slot = match a.key() {
                        Some("description") => &mut d.description,
                        Some("ifdescription") => &mut d.ifdescription,
                        _ => {
                            m.unknown_attr(a, don, &mut dx);
                            continue;
                        }
                    };
                    m.set(slot, a, don, &mut dx);
                }
                leaf_children(m, c, don, &mut dx);
                d.extra = dx;
                s.doc = Some(d);
            }
            Some("Properties") => s.properties.push(map_property(m, c)),
            Some("ServiceInterface") => s.interfaces.push(map_service_interface(m, c)),
            Some("TransMethods") => {
                // spec 2.3.10 `transmission_method`
                let ton = "transmission method";
                let mut t = TransMethod {
                    pos: c.pos,
                    ..Default::default()
                };
                let mut tx = Vec::new();
                for a in &c.attrs {
                    match a.key() {
                        Some("kind") => m.set(&mut t.kind, a, ton, &mut tx),
                        _ => m.unknown_attr(a, ton, &mut tx),
                    }
                }
                leaf_children(m, c, ton, &mut tx);
                t.extra = tx;
                s.trans_methods.push(t);
            }
            Some("Doc") => m.repeated_elem(c, on, &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    s.extra = extra;
    s
}

/// spec 2.3.9 `serviceinterface`, 2.4.8 doc, 2.5.5 ext.
fn map_service_interface(m: &mut Mapper, n: &Node) -> ServiceInterface {
    let on = "service interface";
    let mut s = ServiceInterface {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    let mut aliases = Vec::new();
    for a in &n.attrs {
        note_pos(&mut s.attr_pos, a);
        let slot = match a.key() {
            Some("name") => &mut s.name,
            Some("type") => &mut s.type_,
            Some("direction") => &mut s.direction,
            Some("instanceName") => &mut s.instance_name,
            Some("idlFile") => &mut s.idl_file,
            Some("path") => &mut s.path,
            Some("comment") => &mut s.comment,
            Some("variableName") => &mut s.variable_name,
            // RTCBuilder 0.1: `rtc:varname` is the variable name.
            Some("varname") => {
                aliases.push(("variableName", a));
                &mut s.variable_name
            }
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("Doc") if s.doc.is_none() => {
                let don = "service interface doc";
                let mut d = ServiceInterfaceDoc {
                    pos: c.pos,
                    ..Default::default()
                };
                let mut dx = Vec::new();
                for a in &c.attrs {
                    let slot = match a.key() {
                        Some("description") => &mut d.description,
                        Some("docArgument") => &mut d.doc_argument,
                        Some("docReturn") => &mut d.doc_return,
                        Some("docException") => &mut d.doc_exception,
                        Some("docPreCondition") => &mut d.doc_pre_condition,
                        Some("docPostCondition") => &mut d.doc_post_condition,
                        _ => {
                            m.unknown_attr(a, don, &mut dx);
                            continue;
                        }
                    };
                    m.set(slot, a, don, &mut dx);
                }
                leaf_children(m, c, don, &mut dx);
                d.extra = dx;
                s.doc = Some(d);
            }
            Some("Properties") => s.properties.push(map_property(m, c)),
            Some("Doc") => m.repeated_elem(c, on, &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    let node = format!("serviceInterface {}", s.name.as_deref().unwrap_or(""));
    for (field, a) in aliases {
        m.alias(&node, field, a, super::dialect::RTCBUILDER_01);
    }
    s.extra = extra;
    s
}

/// spec 2.3.11 `parameter`.
fn map_parameter(m: &mut Mapper, n: &Node) -> Parameter {
    let on = "parameter";
    let mut p = Parameter {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("name") => &mut p.name,
            Some("defaultValue") => &mut p.default_value,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    leaf_children(m, n, on, &mut extra);
    p.extra = extra;
    p
}

/// spec 2.3.12 `language`, 2.5.6 `language_ext`.
fn map_language(m: &mut Mapper, n: &Node) -> Language {
    let on = "language";
    let mut l = Language {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        match a.key() {
            Some("kind") => m.set(&mut l.kind, a, on, &mut extra),
            _ => m.unknown_attr(a, on, &mut extra),
        }
    }
    for c in &n.children {
        match c.key() {
            Some("targets") => l.targets.push(map_target(m, c)),
            Some(k) if super::dialect::language_element(k).is_some() => {
                map_language_element(m, c, &mut l)
            }
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    l.extra = extra;
    l
}

/// RTCBuilder 0.1's `<rtc:Language>` names the language by a child element (`<rtc:Cxx
/// rtc:arch="" rtc:os="etc"/>`, `<rtc:Python/>`, `<rtc:Java/>`) instead of `rtc:kind`: that
/// is the kind, and the child's attributes describe the target (`os`, `arch` → cpus,
/// `osVersion`, `langVersion`, `library` children).
fn map_language_element(m: &mut Mapper, c: &Node, l: &mut Language) {
    let Some(kind) = c.key().and_then(super::dialect::language_element) else {
        return;
    };
    let on = format!("language `{}`", c.qname);
    if l.kind.is_none() {
        l.kind = Some(kind.into());
        m.written_as.push(WrittenAs {
            field: "language.kind".into(),
            written_as: (&*c.qname).into(),
            dialect: super::dialect::RTCBUILDER_01,
            pos: c.pos,
        });
    }
    let mut t = Target {
        pos: c.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &c.attrs {
        match a.key() {
            Some("os") => m.set(&mut t.os, a, &on, &mut extra),
            Some("langVersion") => m.set(&mut t.lang_version, a, &on, &mut extra),
            Some("other") => m.set(&mut t.other, a, &on, &mut extra),
            Some("cpuOther") => m.set(&mut t.cpu_other, a, &on, &mut extra),
            Some("arch" | "cpu") => {
                if let Some(v) = non_blank(&a.value) {
                    t.cpus.push(v);
                }
            }
            Some("osVersion" | "osVersions") => {
                if let Some(v) = non_blank(&a.value) {
                    t.os_versions.push(v);
                }
            }
            _ => m.unknown_attr(a, &on, &mut extra),
        }
    }
    for lc in &c.children {
        match lc.key() {
            Some("library" | "libraries") if lc.attrs.is_empty() => {
                let name = m.text_of(lc, &on, &mut extra);
                if let Some(name) = non_blank(&name) {
                    t.libraries.push(Library {
                        name: Some(name),
                        pos: lc.pos,
                        ..Default::default()
                    });
                }
            }
            Some("library" | "libraries") => t.libraries.push(map_library(m, lc)),
            _ => m.unknown_elem(lc, &on, &mut extra),
        }
    }
    m.stray_text(c, &on, &mut extra);
    t.extra = extra;
    // An empty `<rtc:Cxx/>` names the language and nothing more.
    if t != (Target {
        pos: c.pos,
        ..Default::default()
    }) {
        l.targets.push(t);
    }
}

/// spec 2.5.7 `target_environment`.
fn map_target(m: &mut Mapper, n: &Node) -> Target {
    let on = "target environment";
    let mut t = Target {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("langVersion") => &mut t.lang_version,
            Some("os") => &mut t.os,
            Some("other") => &mut t.other,
            Some("cpuOther") => &mut t.cpu_other,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    for c in &n.children {
        match c.key() {
            Some("osVersions") => {
                if let Some(v) = non_blank(&m.text_of(c, on, &mut extra)) {
                    t.os_versions.push(v);
                }
            }
            Some("cpus") => {
                if let Some(v) = non_blank(&m.text_of(c, on, &mut extra)) {
                    t.cpus.push(v);
                }
            }
            Some("libraries") => t.libraries.push(map_library(m, c)),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    t.extra = extra;
    t
}

/// spec 2.5.8 `library`: XSD attribute `name`, PIM `path` (accepted silently).
fn map_library(m: &mut Mapper, n: &Node) -> Library {
    let on = "library";
    let mut l = Library {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        let slot = match a.key() {
            Some("name" | "path") => &mut l.name,
            Some("version") => &mut l.version,
            Some("other") => &mut l.other,
            _ => {
                m.unknown_attr(a, on, &mut extra);
                continue;
            }
        };
        m.set(slot, a, on, &mut extra);
    }
    leaf_children(m, n, on, &mut extra);
    l.extra = extra;
    l
}

// --- constraints (spec 2.3.17–2.3.41, XSD 6.1 `constraint_type`, samples 8.1) ------------------

/// `Constraint` → unit | list | hash. Element names are matched case-insensitively: the 8.1
/// samples write `PropertyIsEqualTo`, the XSD `propertyIsEqualTo`.
fn map_constraint(m: &mut Mapper, n: &Node) -> Constraint {
    let on = "constraint";
    let mut extra = Vec::new();
    m.no_attrs(n, on, &mut extra);
    let mut kind: Option<ConstraintKind> = None;
    for c in &n.children {
        let k = c.key_lower();
        match k.as_deref() {
            Some("constraintunittype" | "constraintlisttype" | "constrainthashtype")
                if kind.is_some() =>
            {
                m.repeated_elem(c, on, &mut extra)
            }
            Some("constraintunittype") => kind = Some(map_unit(m, c, &mut extra)),
            Some("constraintlisttype") => {
                kind = Some(ConstraintKind::List {
                    items: constraint_children(m, c, "constraint list", &mut extra),
                })
            }
            Some("constrainthashtype") => {
                kind = Some(ConstraintKind::Hash {
                    items: constraint_children(m, c, "constraint hash", &mut extra),
                })
            }
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    Constraint {
        kind: kind.unwrap_or(ConstraintKind::Empty),
        pos: n.pos,
        extra,
    }
}

/// The `Constraint` children of a list, hash, `And` or `Or`; anything else goes to `extra`.
fn constraint_children(
    m: &mut Mapper,
    n: &Node,
    on: &str,
    extra: &mut Vec<Extra>,
) -> Vec<Constraint> {
    m.no_attrs(n, on, extra);
    let mut items = Vec::new();
    for c in &n.children {
        match c.key_lower().as_deref() {
            Some("constraint") => items.push(map_constraint(m, c)),
            _ => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    items
}

/// spec 2.3.19 `ConstraintUnitType`: an optional `key` and one condition.
fn map_unit(m: &mut Mapper, n: &Node, extra: &mut Vec<Extra>) -> ConstraintKind {
    let on = "constraint unit";
    let mut key = None;
    let mut key_attr = None;
    for a in &n.attrs {
        match a.key() {
            Some("key") if key.is_none() => {
                key = Some((&*a.value).into());
                key_attr = Some(a);
            }
            _ => m.unknown_attr(a, on, extra),
        }
    }
    let mut condition: Option<Condition> = None;
    for c in &n.children {
        let k = c.key_lower();
        let cond = match k.as_deref() {
            Some(k) => map_condition(m, c, k, extra),
            None => None,
        };
        match cond {
            Some(_) if condition.is_some() => m.repeated_elem(c, on, extra),
            Some(cond) => condition = Some(cond),
            None => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    match condition {
        Some(c) => ConstraintKind::Unit {
            key,
            condition: Box::new(c),
        },
        None => {
            if let Some(a) = key_attr {
                m.warn(
                    a.pos,
                    format!(
                        "constraint unit with key `{}` has no condition; the key is kept as an extra property",
                        a.value
                    ),
                );
                extra.push(attr_extra(a));
            }
            ConstraintKind::Empty
        }
    }
}

/// One condition element (lower-cased local name `k`); `None` when `k` is not a condition.
fn map_condition(m: &mut Mapper, n: &Node, k: &str, extra: &mut Vec<Extra>) -> Option<Condition> {
    let on = format!("`{}`", n.qname);
    let cond = match k {
        // spec 2.3.23 Not: exactly one operand.
        "not" => {
            let mut ops = constraint_children(m, n, &on, extra).into_iter();
            let operand = ops.next().unwrap_or(Constraint {
                kind: ConstraintKind::Empty,
                pos: n.pos,
                extra: Vec::new(),
            });
            for more in ops {
                m.warn(
                    more.pos,
                    format!(
                        "`{}` takes one constraint; this extra one is kept as an extra property",
                        n.qname
                    ),
                );
                extra.push(Extra {
                    kind: ExtraKind::Element,
                    name: "Constraint".into(),
                    namespace: None,
                    value: None,
                    children: Vec::new(),
                    pos: more.pos,
                });
            }
            Condition::Not { operand }
        }
        // spec 2.3.24/25 And/Or: the XSD says two operands, samples and real files use more.
        "and" => Condition::And {
            operands: constraint_children(m, n, &on, extra),
        },
        "or" => Condition::Or {
            operands: constraint_children(m, n, &on, extra),
        },
        // spec 2.3.26 propertyIsNull (XSD: `propertyIsNullType` wrapping `propertyIsNull`).
        "propertyisnull" => {
            m.no_attrs(n, &on, extra);
            for c in &n.children {
                m.unknown_elem(c, &on, extra);
            }
            Condition::IsNull {
                text: non_blank(&n.text),
            }
        }
        "propertyisnulltype" => {
            m.no_attrs(n, &on, extra);
            let mut text = None;
            for c in &n.children {
                match c.key_lower().as_deref() {
                    Some("propertyisnull") if text.is_none() => {
                        text = Some(non_blank(&m.text_of(c, &on, extra)))
                    }
                    _ => m.unknown_elem(c, &on, extra),
                }
            }
            m.stray_text(n, &on, extra);
            Condition::IsNull {
                text: text.flatten(),
            }
        }
        // spec 2.3.38 propertyIsLike: wildCard (XSD) / wildChar (PIM) / wildcard (YAML).
        "propertyislike" => {
            let (mut wild_card, mut single_char, mut escape_char) = (None, None, None);
            for a in &n.attrs {
                let slot = match a.key().map(str::to_ascii_lowercase).as_deref() {
                    Some("wildcard" | "wildchar") => &mut wild_card,
                    Some("singlechar") => &mut single_char,
                    Some("escapechar") => &mut escape_char,
                    _ => {
                        m.unknown_attr(a, &on, extra);
                        continue;
                    }
                };
                m.set(slot, a, &on, extra);
            }
            Condition::Like {
                literal: literal_child(m, n, &on, extra),
                wild_card,
                single_char,
                escape_char,
            }
        }
        // spec 2.3.40 propertyIsBetween: both boundaries inclusive.
        "propertyisbetween" => {
            m.no_attrs(n, &on, extra);
            let (mut lower, mut upper) = (None, None);
            for c in &n.children {
                match c.key_lower().as_deref() {
                    Some("lowerboundary") if lower.is_none() => {
                        lower = Some(m.text_of(c, &on, extra))
                    }
                    Some("upperboundary") if upper.is_none() => {
                        upper = Some(m.text_of(c, &on, extra))
                    }
                    _ => m.unknown_elem(c, &on, extra),
                }
            }
            m.stray_text(n, &on, extra);
            Condition::Between { lower, upper }
        }
        // spec 2.3.27–2.3.37 comparisons: `Literal` + `matchCase` (often absent).
        _ => {
            let comparison = k
                .strip_prefix("propertyis")
                .and_then(Comparison::from_suffix)?;
            let mut match_case = None;
            for a in &n.attrs {
                match a.key().map(str::to_ascii_lowercase).as_deref() {
                    Some("matchcase") => m.set(&mut match_case, a, &on, extra),
                    _ => m.unknown_attr(a, &on, extra),
                }
            }
            Condition::Compare {
                comparison,
                literal: literal_child(m, n, &on, extra),
                match_case,
            }
        }
    };
    Some(cond)
}

/// The text of the `Literal` child; other children and stray text go to `extra`.
fn literal_child(m: &mut Mapper, n: &Node, on: &str, extra: &mut Vec<Extra>) -> Option<Text> {
    let mut literal = None;
    for c in &n.children {
        match c.key_lower().as_deref() {
            Some("literal") if literal.is_none() => literal = Some(m.text_of(c, on, extra)),
            _ => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    literal
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The streaming cursor gives the positions the index gives, for offsets asked in any
        /// order (mostly increasing, as in the reader, with jumps back and far ahead).
        #[test]
        fn pos_cursor_agrees_with_line_index(
            parts in proptest::collection::vec(
                proptest::sample::select(&["a", "é", "日", "\n", "\r\n", "\r", "  ", "<x>"][..]),
                0..200,
            ),
            offsets in proptest::collection::vec(0usize..1200, 1..60),
            sorted in proptest::bool::ANY,
        ) {
            let text: String = parts.concat();
            let mut offsets = offsets;
            if sorted {
                offsets.sort_unstable();
            }
            let index = LineIndex::new(&text);
            let mut cursor = PosCursor::new(&text);
            for o in offsets {
                proptest::prop_assert_eq!(cursor.pos(o), index.pos(o), "offset {} of {:?}", o, text);
            }
        }
    }

    #[test]
    fn line_index_counts_chars_and_cr() {
        let t = "ab\r\ncé\rx";
        let i = LineIndex::new(t);
        assert_eq!(i.pos(0), Pos::new(1, 1));
        assert_eq!(i.pos(4), Pos::new(2, 1));
        assert_eq!(i.pos(7), Pos::new(2, 3));
        assert_eq!(i.pos(8), Pos::new(3, 1));
    }

    #[test]
    fn attr_unescape_normalises() {
        assert_eq!(
            unescape_attr("a\r\nb\tc&#10;&lt;".into()).unwrap(),
            "a b c\n<"
        );
        assert!(matches!(
            unescape_attr("plain".into()),
            Ok(Cow::Borrowed("plain"))
        ));
        assert!(unescape_attr("&foo;".into()).is_err());
    }

    #[test]
    fn declared_encoding_found() {
        let (l, at) = declared_encoding(b"<?xml version='1.0' encoding = \"Shift_JIS\"?>").unwrap();
        assert_eq!(l, "Shift_JIS");
        assert_eq!(at, 32);
    }
}
