//! YAML reader for the YAML form of RTC Profiles (spec chapter 3.2, schema chapter 7,
//! constraint samples chapter 8.2), including the dialect RTCBuilder writes (see
//! `spec/NOTES.md`: `"rtcExt::properties"`, `constraint*Type`, `occerrence`, date maps with
//! `fractionalSecond` / `millisecond` / `timezone`, null actions, `transMethods`).
//!
//! The file is parsed into a `serde_norway` [`Value`] tree which is then mapped onto the
//! model: by our own line reader (`yaml_fast`) when the file is one block-style document of
//! one-line scalars (what RTCBuilder writes), else by `serde_norway`. `Value` carries no
//! source marks, so positions are recovered with a `Locator`: the tree is walked in document
//! order (mappings keep their order) while a cursor moves forward through the source text
//! looking for each key. This is exact for block-style YAML, which is
//! what RTCBuilder writes, and a close approximation for flow style.
//!
//! Hostile input: the `Value` is built by our own seed, which counts nodes and depth as it goes
//! and rejects documents that nest deeper than [`Limits::max_depth`] or whose aliases expand to
//! more than [`MAX_NODES`] nodes (alias bombs) as soon as the limit is passed. `serde_norway` itself stops at a nesting of 128 and after
//! `100 × events` alias jumps; both of its errors are reported with their own codes too.

use super::{DocParts, Documented, Limits, Parsed};
use crate::diagnostic::{codes, Diagnostic};
use crate::model::fields::{Fields, Kind};
use crate::model::*;
use serde::de::{DeserializeSeed, MapAccess, SeqAccess, Visitor};
use serde_norway::{Mapping, Value};
use std::borrow::Cow;
use std::fmt;

/// Upper bound of the number of YAML nodes (after alias expansion) a document may have. The
/// actual limit is `min(MAX_NODES, 100_000 + file size)`: without aliases a document cannot have
/// more nodes than bytes, so only alias expansion can reach it. A genuine profile has a few
/// thousand nodes.
pub const MAX_NODES: usize = 2_000_000;

/// True when the bytes look like a YAML document with a top-level `rtcProfile` key: a line that
/// starts (column 0) with `rtcProfile:`, `"rtcProfile":` or `'rtcProfile':`, or a flow mapping
/// `{rtcProfile: …`. Only the first 64 KiB are looked at; nothing is parsed.
pub fn is_profile(bytes: &[u8]) -> bool {
    has_root_key(bytes, "rtcProfile")
}

/// True when the bytes look like a YAML document with the top-level key `key`, by the rule of
/// [`is_profile`] (`rtsProfile` finds RT System profiles).
pub fn has_root_key(bytes: &[u8], key: &str) -> bool {
    let head = &bytes[..bytes.len().min(64 * 1024)];
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let k = key.as_bytes();
    let quoted = |q: u8| [&[q][..], k, &[q][..]].concat();
    let (dq, sq) = (quoted(b'"'), quoted(b'\''));
    head.split(|&b| b == b'\n').any(|line| {
        let line = line.strip_prefix(b"{").unwrap_or(line);
        let line = line.strip_prefix(b"--- ").unwrap_or(line);
        [k, &dq[..], &sq[..]].iter().any(|k| {
            line.strip_prefix(*k).is_some_and(|rest| {
                let rest = trim_start_blank(rest);
                rest.first() == Some(&b':')
            })
        })
    })
}

fn trim_start_blank(s: &[u8]) -> &[u8] {
    let n = s.iter().take_while(|&&b| b == b' ' || b == b'\t').count();
    &s[n..]
}

/// The root mapping of the first YAML document with the top-level key `root_key`, and a reader
/// on it. The common case (one block-style document) is read by our own line reader; anything
/// it does not handle — and every error — goes through serde_norway. `what` names the kind of
/// profile in the errors, `hint` says how one starts.
fn root_reader<'a>(
    bytes: &'a [u8],
    file: &'a str,
    limits: &Limits,
    root_key: &str,
    what: &str,
    hint: &str,
) -> Result<(Mapping, Reader<'a>), Diagnostic> {
    // A byte order mark (Windows editors write one) is no part of the first document: without
    // it, `---` on the first line is the document marker.
    let src = source(bytes, file, limits)?;
    let src = src.strip_prefix('\u{feff}').unwrap_or(src);
    let value = match super::yaml_fast::parse(src, limits.max_depth, root_key) {
        Some(v) => Some(v),
        None => slow_value(src.as_bytes(), file, limits, root_key)?,
    };
    let Some(value) = value else {
        return Err(Diagnostic::error(
            codes::SHAPE,
            file,
            format!("not an {what}: no YAML document has a top-level `{root_key}` key"),
        )
        .with_hint(hint));
    };
    let Value::Mapping(root) = untag(value) else {
        return Err(Diagnostic::error(
            codes::SHAPE,
            file,
            format!("not an {what}: the root is not a mapping"),
        ));
    };
    let r = Reader {
        file,
        loc: Locator::new(src),
        diags: Vec::new(),
        empties: super::dialect::EmptyUnknowns::default(),
        written_as: Vec::new(),
    };
    Ok((root, r))
}

/// Reads an RTC Profile from YAML bytes.
///
/// Errors: `ENCODING` (not UTF-8), `MALFORMED` (YAML syntax, with serde_norway's line:column),
/// `TOO_DEEP`, `YAML_STRUCTURE` (alias bomb), `SHAPE` (no document whose root mapping has
/// `rtcProfile`). Everything else — unknown keys, values of the wrong shape — becomes a warning
/// and is kept as an [`Extra`] on the nearest node.
pub fn parse(bytes: &[u8], file: &str, limits: &Limits) -> Result<Parsed, Diagnostic> {
    let (root, mut r) = root_reader(
        bytes,
        file,
        limits,
        "rtcProfile",
        "RTC Profile",
        "a YAML RTC Profile starts with `rtcProfile:` (spec chapter 7)",
    )?;
    let profile: Profile = r.document(&root, "rtcProfile", |r, v, pos, p| r.profile(v, pos, p));
    Ok(Parsed::read(
        profile,
        r.written_as,
        &r.empties,
        "key",
        file,
        r.diags,
    ))
}

/// The mapping of RT System profiles (`rtsProfile`), on this module's value builder, limits and
/// locator.
#[path = "rts_yaml.rs"]
pub(super) mod rts;

/// The bytes as text: UTF-8, and no flow collections nested beyond the depth limit.
fn source<'b>(bytes: &'b [u8], file: &str, limits: &Limits) -> Result<&'b str, Diagnostic> {
    let src = match std::str::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => {
            let valid = &bytes[..e.valid_up_to()];
            // The prefix is valid UTF-8 by construction.
            let prefix = std::str::from_utf8(valid).unwrap_or("");
            return Err(Diagnostic::error(
                codes::ENCODING,
                file,
                format!("invalid UTF-8 byte sequence at byte {}", e.valid_up_to()),
            )
            .at(Pos::at_offset(prefix, prefix.len()))
            .with_hint("YAML profiles must be UTF-8; re-save the file as UTF-8"));
        }
    };

    if let Some((off, depth)) = flow_depth_exceeds(src, limits.max_depth) {
        return Err(Diagnostic::error(
            codes::TOO_DEEP,
            file,
            format!(
                "YAML flow collections nest deeper than the limit of {} levels ({depth} `[`/`{{` \
                 open here)",
                limits.max_depth
            ),
        )
        .at(Locator::new(src).pos(off))
        .with_hint("RTC Profiles nest about 15 levels; the file is probably not a profile"));
    }
    Ok(src)
}

/// The first document whose root mapping has `root_key`, read with serde_norway. Each
/// document is built into a `Value` by a seed that counts nodes and depth as it goes (so an
/// alias bomb or a deep nest is stopped early).
pub(super) fn slow_value(
    bytes: &[u8],
    file: &str,
    limits: &Limits,
    root_key: &str,
) -> Result<Option<Value>, Diagnostic> {
    let mut state = CountState {
        nodes: 0,
        max_nodes: MAX_NODES.min(100_000 + bytes.len()),
        max_depth: limits.max_depth,
    };
    for doc in serde_norway::Deserializer::from_slice(bytes) {
        state.nodes = 0;
        let v = untag(
            BuildSeed {
                state: &mut state,
                depth: 0,
            }
            .deserialize(doc)
            .map_err(|e| yaml_error(e, file, limits))?,
        );
        if matches!(&v, Value::Mapping(m) if m.contains_key(root_key)) {
            return Ok(Some(v));
        }
    }
    Ok(None)
}

/// Cheap pre-scan for deeply nested flow collections (`[[[[…`), which libyaml handles in
/// quadratic time (stale simple keys) long before serde_norway's depth limit is reached.
/// Counts `[`/`{` that start a token, skipping quoted scalars and comments; returns the offset
/// and depth where `max_depth` is exceeded.
fn flow_depth_exceeds(src: &str, max_depth: usize) -> Option<(usize, usize)> {
    let b = src.as_bytes();
    // No deeper than the number of brackets: most profiles have a few `[]` at most.
    memchr::memchr2_iter(b'[', b'{', b).nth(max_depth)?;
    let mut depth = 0usize;
    let mut i = 0;
    // Whether the previous significant byte allows a token to start here.
    let mut token_start = true;
    while i < b.len() {
        let c = b[i];
        match c {
            b'\n' => token_start = true,
            b' ' | b'\t' | b'\r' => {}
            b'#' if i == 0 || matches!(b[i - 1], b' ' | b'\t' | b'\n' | b'\r') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            b'"' | b'\'' if token_start => {
                i += 1;
                while i < b.len() && b[i] != c {
                    i += if c == b'"' && b[i] == b'\\' { 2 } else { 1 };
                }
                token_start = false;
            }
            b'[' | b'{' if token_start => {
                depth += 1;
                if depth > max_depth {
                    return Some((i, depth));
                }
            }
            b']' | b'}' if depth > 0 => {
                depth -= 1;
                token_start = false;
            }
            b':' | b'-' | b',' | b'?' => token_start = true,
            _ => token_start = false,
        }
        i += 1;
    }
    None
}

fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// Returns the inner value of a tagged value (`!tag value`).
fn untag(v: Value) -> Value {
    match v {
        Value::Tagged(t) => untag(t.value),
        v => v,
    }
}

fn untag_ref(v: &Value) -> &Value {
    match v {
        Value::Tagged(t) => untag_ref(&t.value),
        v => v,
    }
}

/// Maps a serde_norway error to a diagnostic with its position.
fn yaml_error(e: serde_norway::Error, file: &str, limits: &Limits) -> Diagnostic {
    let msg = e.to_string();
    let pos = e
        .location()
        .map(|l| Pos::new(to_u32(l.line()), to_u32(l.column())));
    let d = if msg.contains(TOO_DEEP_MSG) || msg.contains("recursion limit exceeded") {
        Diagnostic::error(
            codes::TOO_DEEP,
            file,
            format!(
                "YAML collections nest deeper than the limit of {} levels",
                limits.max_depth.min(127)
            ),
        )
        .with_hint("RTC Profiles nest about 15 levels; the file is probably not a profile")
    } else if msg.contains(BOMB_MSG) || msg.contains("repetition limit exceeded") {
        Diagnostic::error(
            codes::YAML_STRUCTURE,
            file,
            "YAML aliases expand too much (too many nodes or alias repetitions): rejected as \
             a possible alias bomb",
        )
        .with_hint("RTC Profiles need no anchors or aliases; write the values out")
    } else {
        let text = msg.split(" at line ").next().unwrap_or(&msg).to_string();
        Diagnostic::error(codes::MALFORMED, file, format!("invalid YAML: {text}"))
    };
    match pos {
        Some(p) => d.at(p),
        None => d,
    }
}

const TOO_DEEP_MSG: &str = "rtcdoc: nesting too deep";
const BOMB_MSG: &str = "rtcdoc: alias expansion too large";

// ---------------------------------------------------------------------------------------------
// Building a `Value` while enforcing the depth and size limits.

struct CountState {
    nodes: usize,
    max_nodes: usize,
    max_depth: usize,
}

/// Builds one node (and its subtree) of a document, counting nodes and nesting depth. Aliases
/// are replayed by serde_norway as their events, so expanded nodes are counted too. Tags
/// (`!tag value`) are dropped: the value stands for itself.
struct BuildSeed<'s> {
    state: &'s mut CountState,
    depth: usize,
}

impl<'de> DeserializeSeed<'de> for BuildSeed<'_> {
    type Value = Value;
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl BuildSeed<'_> {
    fn bump<E: serde::de::Error>(&mut self) -> Result<(), E> {
        self.state.nodes += 1;
        if self.state.nodes > self.state.max_nodes {
            return Err(E::custom(BOMB_MSG));
        }
        Ok(())
    }
    fn child(&mut self) -> BuildSeed<'_> {
        BuildSeed {
            state: self.state,
            depth: self.depth + 1,
        }
    }
    fn enter<E: serde::de::Error>(&mut self) -> Result<(), E> {
        self.bump()?;
        if self.depth + 1 > self.state.max_depth {
            return Err(E::custom(TOO_DEEP_MSG));
        }
        Ok(())
    }
    fn leaf<E: serde::de::Error>(mut self, v: Value) -> Result<Value, E> {
        self.bump().map(|_| v)
    }
}

impl<'de> Visitor<'de> for BuildSeed<'_> {
    type Value = Value;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("any YAML value")
    }
    fn visit_bool<E: serde::de::Error>(self, b: bool) -> Result<Value, E> {
        self.leaf(Value::Bool(b))
    }
    fn visit_i64<E: serde::de::Error>(self, n: i64) -> Result<Value, E> {
        self.leaf(Value::Number(n.into()))
    }
    fn visit_u64<E: serde::de::Error>(self, n: u64) -> Result<Value, E> {
        self.leaf(Value::Number(n.into()))
    }
    fn visit_f64<E: serde::de::Error>(self, n: f64) -> Result<Value, E> {
        self.leaf(Value::Number(n.into()))
    }
    fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<Value, E> {
        self.leaf(Value::String(s.to_owned()))
    }
    fn visit_string<E: serde::de::Error>(self, s: String) -> Result<Value, E> {
        self.leaf(Value::String(s))
    }
    fn visit_unit<E: serde::de::Error>(self) -> Result<Value, E> {
        self.leaf(Value::Null)
    }
    fn visit_none<E: serde::de::Error>(self) -> Result<Value, E> {
        self.leaf(Value::Null)
    }
    fn visit_some<D: serde::Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
    fn visit_newtype_struct<D: serde::Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
    fn visit_enum<A: serde::de::EnumAccess<'de>>(mut self, data: A) -> Result<Value, A::Error> {
        use serde::de::VariantAccess;
        self.enter()?;
        let (_, variant): (serde::de::IgnoredAny, _) = data.variant()?;
        variant.newtype_variant_seed(self.child())
    }
    fn visit_seq<A: SeqAccess<'de>>(mut self, mut seq: A) -> Result<Value, A::Error> {
        self.enter()?;
        let mut items = Vec::new();
        while let Some(v) = seq.next_element_seed(self.child())? {
            items.push(v);
        }
        Ok(Value::Sequence(items))
    }
    fn visit_map<A: MapAccess<'de>>(mut self, mut map: A) -> Result<Value, A::Error> {
        self.enter()?;
        let mut mapping = Mapping::new();
        while let Some(key) = map.next_key_seed(self.child())? {
            match mapping.entry(untag(key)) {
                serde_norway::mapping::Entry::Occupied(e) => {
                    return Err(serde::de::Error::custom(duplicate_key(e.key())));
                }
                serde_norway::mapping::Entry::Vacant(e) => {
                    e.insert(map.next_value_seed(self.child())?);
                }
            }
        }
        Ok(Value::Mapping(mapping))
    }
}

/// The message serde_norway gives a duplicate mapping key.
fn duplicate_key(key: &Value) -> String {
    match key {
        Value::Null => "duplicate entry with null key".to_string(),
        Value::Bool(b) => format!("duplicate entry with key `{b}`"),
        Value::Number(n) => format!("duplicate entry with key {n}"),
        Value::String(s) => format!("duplicate entry with key {s:?}"),
        _ => "duplicate entry in YAML map".to_string(),
    }
}

// ---------------------------------------------------------------------------------------------
// Positions.

/// Recovers line:column of keys by scanning the source forward in document order.
struct Locator<'a> {
    src: &'a str,
    line_starts: Vec<usize>,
    cursor: usize,
    /// Bytes the key search may still scan; bounds the work for alias-expanded documents, whose
    /// keys are not found again further on.
    budget: usize,
}

impl<'a> Locator<'a> {
    fn new(src: &'a str) -> Self {
        let mut line_starts = vec![0];
        line_starts.extend(memchr::memchr_iter(b'\n', src.as_bytes()).map(|i| i + 1));
        Locator {
            src,
            line_starts,
            cursor: 0,
            budget: src.len().saturating_mul(32).saturating_add(1 << 20),
        }
    }

    /// Line and column (1-based, columns in characters) of a byte offset.
    fn pos(&self, off: usize) -> Pos {
        let off = off.min(self.src.len());
        let line = self.line_starts.partition_point(|&s| s <= off);
        let start = self.line_starts[line.saturating_sub(1)];
        let col = self.src.get(start..off).map_or(0, |s| s.chars().count());
        Pos::new(to_u32(line), to_u32(col + 1))
    }

    /// Position of the next key `key` at or after the cursor (plain, `"…"` or `'…'`, followed
    /// by `:`); moves the cursor past the key. Falls back to the cursor position.
    fn key(&mut self, key: &str) -> Pos {
        if key.is_empty() {
            return self.pos(self.cursor);
        }
        let src = self.src;
        let step = key.chars().next().map_or(1, char::len_utf8);
        let mut from = self.cursor;
        // The key is usually a few bytes ahead: for a short key, look for its first byte and
        // compare; a long one (an explicit `? key`) gets a linear-time searcher. A UTF-8 needle
        // only matches at character boundaries, so byte offsets are string offsets.
        let needle = key.as_bytes();
        let long = (needle.len() > 64).then(|| memchr::memmem::Finder::new(needle));
        let find = |hay: &[u8]| {
            if let Some(f) = &long {
                return f.find(hay);
            }
            let mut at = 0;
            while let Some(i) = memchr::memchr(needle[0], &hay[at..]) {
                if hay[at + i..].starts_with(needle) {
                    return Some(at + i);
                }
                at += i + 1;
            }
            None
        };
        while let Some(i) = src.get(from..).and_then(|s| find(s.as_bytes())) {
            let at = from + i;
            self.budget = self.budget.saturating_sub(i + 1);
            if self.budget == 0 {
                break;
            }
            let end = at + key.len();
            let before = src[..at].chars().next_back();
            let after = &src[end..];
            match before {
                Some(q @ ('"' | '\'')) => {
                    if let Some(rest) = after.strip_prefix(q) {
                        if rest.trim_start_matches([' ', '\t']).starts_with(':') {
                            self.cursor = end + 1;
                            return self.pos(at - 1);
                        }
                    }
                }
                None | Some(' ' | '\t' | '\n' | '\r' | '{' | ',' | '[' | '?') => {
                    let rest = after.trim_start_matches([' ', '\t']);
                    if let Some(r) = rest.strip_prefix(':') {
                        if r.is_empty() || r.starts_with([' ', '\t', '\r', '\n', ',', '}', ']']) {
                            self.cursor = end;
                            return self.pos(at);
                        }
                    }
                }
                _ => {}
            }
            from = at + step;
        }
        self.pos(self.cursor)
    }

    /// Position of the next sequence item (the next `-`, or the next token in flow style);
    /// moves the cursor past a `-`, or onto the flow token.
    fn item(&mut self) -> Pos {
        let bytes = self.src.as_bytes();
        let mut i = self.cursor;
        while i < bytes.len() {
            match bytes[i] {
                // The `:` of the key found last: a scalar after it is that key's value (the
                // previous item's last one, as in `isRequired: true`), not this item. It ends at
                // the end of its line, or in flow style at a `,`, `}` or `]` outside quotes; a
                // flow collection after the `:` holds the items.
                b':' => {
                    let rest = &bytes[i + 1..];
                    let blank = rest
                        .iter()
                        .take_while(|&&c| c == b' ' || c == b'\t')
                        .count();
                    match rest.get(blank) {
                        None | Some(b'[' | b'{' | b'\r' | b'\n' | b'#') => i += 1,
                        Some(_) => i = scalar_end(self.src, i + 1 + blank),
                    }
                }
                b' ' | b'\t' | b'\r' | b'\n' | b',' | b'[' | b'}' => i += 1,
                b'#' => {
                    while i < bytes.len() && bytes[i] != b'\n' {
                        i += 1;
                    }
                }
                b'-' => {
                    self.cursor = i + 1;
                    return self.pos(i);
                }
                _ => {
                    self.cursor = i;
                    break;
                }
            }
        }
        self.pos(i.min(bytes.len()))
    }

    /// The scalar written after the key just found (`key: <text>`), up to the end of the line
    /// (or `,`/`}`/`]` in flow style), without a trailing comment, and the offset of its end.
    fn raw_after_key(&self) -> Option<(&'a str, usize)> {
        let src = self.src;
        let rest = src.get(self.cursor..)?;
        let skipped = rest.len() - rest.trim_start_matches([' ', '\t']).len();
        let rest = rest[skipped..].strip_prefix(':')?;
        let start = self.cursor + skipped + 1;
        let line_end = rest.find('\n').map_or(src.len(), |n| start + n);
        let mut text = &src[start..line_end];
        if let Some(c) = text.find(" #") {
            text = &text[..c];
        }
        let text = text.trim();
        // In flow style the scalar ends at `,`, `}` or `]` (unless quoted).
        let text = if text.starts_with(['"', '\'']) {
            text
        } else {
            text.split([',', '}', ']'])
                .next()
                .unwrap_or(text)
                .trim_end()
        };
        // End of the scalar text (text is a sub-slice of src).
        let end = (text.as_ptr() as usize - src.as_ptr() as usize) + text.len();
        Some((text, end.min(line_end)))
    }

    /// The raw text of the next scalar sequence item (`- 2.10`, `[2.4, 2.10]`), and the
    /// offset of its end.
    fn raw_item(&self) -> Option<(&'a str, usize)> {
        let src = self.src;
        let rest = src.get(self.cursor..)?;
        let skipped = rest.len() - rest.trim_start_matches([' ', '\t']).len();
        let start = self.cursor + skipped;
        let end = scalar_end(src, start);
        Some((&src[start..end], end))
    }
}

// ---------------------------------------------------------------------------------------------
// Pass 3: Value → model.

struct Reader<'a> {
    file: &'a str,
    loc: Locator<'a>,
    diags: Vec<Diagnostic>,
    /// Empty unknown keys: summarised in one note.
    empties: super::dialect::EmptyUnknowns,
    /// Keys read under an older spelling, for [`Profile::written_as`].
    written_as: Vec<WrittenAs>,
}

/// Keys of one node read under an older spelling: (field, key as written, position, writer).
type Aliases = Vec<(&'static str, String, Pos, &'static str)>;

/// rtc-template writes `doc` for `"rtcDoc::doc"`: recorded in `al`.
fn doc_alias(n: &str, kp: Pos, al: &mut Aliases) {
    if n == "doc" {
        al.push(("rtcDoc::doc", n.into(), kp, super::dialect::RTC_TEMPLATE));
    }
}

/// Calls `f` on each mapping item of a list value, with its position. Items are located one by
/// one, just before `f` reads them: the locator moves forward in document order.
fn each_item<'v>(
    r: &mut Reader,
    v: &'v Value,
    name: &str,
    pos: Pos,
    sink: &mut Extras,
    mut f: impl FnMut(&mut Reader, &'v Mapping, Pos),
) {
    let list = r.seq(v, name, pos, sink);
    for (i, it) in list.iter().enumerate() {
        if let Some((m, ip)) = r.map_item(it, name, i, sink) {
            f(r, m, ip);
        }
    }
}

/// Text of a scalar key (keys are normally strings).
fn key_text(k: &Value) -> String {
    key_str(k).into_owned()
}

/// [`key_text`], borrowed from a string key (nearly every key).
fn key_str(k: &Value) -> Cow<'_, str> {
    match untag_ref(k) {
        Value::String(s) => Cow::Borrowed(s),
        Value::Bool(b) => Cow::Borrowed(if *b { "true" } else { "false" }),
        Value::Number(n) => Cow::Owned(n.to_string()),
        Value::Null => Cow::Borrowed("~"),
        _ => Cow::Borrowed("(complex key)"),
    }
}

fn describe(v: &Value) -> &'static str {
    match untag_ref(v) {
        Value::Null => "nothing",
        Value::Bool(_) | Value::Number(_) | Value::String(_) => "a scalar",
        Value::Sequence(_) => "a list",
        Value::Mapping(_) => "a mapping",
        Value::Tagged(_) => "a tagged value",
    }
}

/// A date map `{year, month, day, hour, minute, second}` (spec chapter 7 `dateType`) with
/// RTCBuilder's optional `fractionalSecond`, `millisecond` and `timezone` (minutes east of UTC).
#[derive(Default)]
struct DateParts {
    ymdhms: [Option<i64>; 6],
    fraction: Option<Text>,
    millisecond: Option<i64>,
    timezone: Option<i64>,
}

impl DateParts {
    fn iso(&self) -> Option<Text> {
        let [Some(y), Some(mo), Some(d), Some(h), Some(mi), Some(s)] = self.ymdhms else {
            return None;
        };
        let mut out = format!("{y:04}-{mo:02}-{d:02}T{h:02}:{mi:02}:{s:02}");
        match (self.millisecond, &self.fraction) {
            (Some(ms), _) if ms != 0 => out.push_str(&format!(".{ms:03}")),
            (_, Some(f)) => {
                let digits = f
                    .split_once('.')
                    .map_or("", |(_, d)| d)
                    .trim_end_matches('0');
                if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
                    out.push('.');
                    out.push_str(digits);
                }
            }
            _ => {}
        }
        if let Some(tz) = self.timezone {
            let sign = if tz < 0 { '-' } else { '+' };
            let a = tz.unsigned_abs();
            out.push_str(&format!("{sign}{:02}:{:02}", a / 60, a % 60));
        }
        Some(out.into())
    }
}

/// Condition operator names (spec 2.3.22–2.3.41, chapter 7 and 8.2), matched
/// case-insensitively.
enum Op {
    Not,
    And,
    Or,
    IsNull,
    Compare(Comparison),
    Like,
    Between,
}

fn op_of(name: &str) -> Option<Op> {
    let l = name.to_ascii_lowercase();
    match l.as_str() {
        "not" => Some(Op::Not),
        "and" => Some(Op::And),
        "or" => Some(Op::Or),
        "propertyisnull" => Some(Op::IsNull),
        "propertyislike" => Some(Op::Like),
        "propertyisbetween" => Some(Op::Between),
        _ => l
            .strip_prefix("propertyis")
            .and_then(Comparison::from_suffix)
            .map(Op::Compare),
    }
}

/// The three constraint forms (spec 2.3.18–2.3.21): chapter 7 `constraintUnit` /
/// `constraintList` / `constraintHash`, RTCBuilder `…Type`.
#[derive(Clone, Copy, PartialEq)]
enum Form {
    Unit,
    List,
    Hash,
}

fn form_of(name: &str) -> Option<Form> {
    match name.to_ascii_lowercase().as_str() {
        "constraintunit" | "constraintunittype" => Some(Form::Unit),
        "constraintlist" | "constraintlisttype" => Some(Form::List),
        "constrainthash" | "constrainthashtype" => Some(Form::Hash),
        _ => None,
    }
}

impl Reader<'_> {
    /// The document a root mapping holds: the value of `key` read into a `T` by `fill` (the
    /// node placed at the key), any other key of the root kept as an unknown value of it.
    fn document<T: Default + Located>(
        &mut self,
        root: &Mapping,
        key: &str,
        mut fill: impl FnMut(&mut Self, &Value, Pos, &mut T),
    ) -> T {
        let mut node = T::default();
        for (k, v) in root {
            let (name, pos) = self.key(k);
            if name == key {
                *node.pos_mut() = pos;
                fill(self, v, pos, &mut node);
            } else {
                self.unknown(&name, v, pos, "the document root", node.extra_mut());
            }
        }
        node
    }

    /// Key text and its position; moves the locator.
    fn key<'v>(&mut self, k: &'v Value) -> (Cow<'v, str>, Pos) {
        let name = key_str(k);
        let pos = self.loc.key(&name);
        (name, pos)
    }

    fn warn(&mut self, code: &'static str, pos: Pos, msg: String) {
        self.diags
            .push(Diagnostic::warning(code, self.file, msg).at(pos));
    }

    /// An unknown key: kept as an extra, with an `UNKNOWN` warning — or, when its value is
    /// empty (null or `""`), counted for the profile's one summary note.
    fn unknown(&mut self, name: &str, v: &Value, pos: Pos, place: &str, sink: &mut Extras) {
        let empty = match untag_ref(v) {
            Value::Null => true,
            Value::String(t) => t.trim().is_empty(),
            _ => false,
        };
        if empty {
            self.empties.add(name);
            let e = self.extra(name, v, pos);
            sink.push(e);
            return;
        }
        self.warn(
            codes::UNKNOWN,
            pos,
            format!("unknown key `{name}` in {place}; kept as an extra property"),
        );
        let e = self.extra(name, v, pos);
        sink.push(e);
    }

    /// A known key whose value has the wrong shape: kept as an extra, with a `SHAPE` warning.
    fn wrong_shape(&mut self, name: &str, v: &Value, pos: Pos, want: &str, sink: &mut Extras) {
        self.warn(
            codes::SHAPE,
            pos,
            format!(
                "`{name}` should be {want} but is {}; kept as an extra property",
                describe(v)
            ),
        );
        let e = self.extra(name, v, pos);
        sink.push(e);
    }

    /// A key the field table lists for `T`: its value read into `t`, its position noted where
    /// `T` keeps positions, an older spelling recorded in `al`. False for any other key.
    fn scalar<T: Fields>(
        &mut self,
        t: &mut T,
        n: &str,
        v: &Value,
        kp: Pos,
        al: &mut Aliases,
    ) -> bool {
        let Some((def, spelling)) = T::NODE.yaml(n) else {
            return false;
        };
        if let Some(p) = t.attr_pos() {
            p.note(def.field, kp);
        }
        if let Some(d) = spelling.dialect {
            al.push((def.json, n.to_string(), kp, d));
        }
        let value = match def.kind {
            Kind::Text => self.text(v, n, kp, t.extra_mut()),
            Kind::Date => self.date(v, n, kp, t.extra_mut()),
        };
        if let Some(slot) = t.slot(def.field) {
            *slot = value;
        }
        true
    }

    /// A node of scalars only (a doc, a property, a parameter, a library): each key the field
    /// table lists for `T` read into `t`, any other unknown in `place`.
    fn scalars<T: Fields>(&mut self, m: &Mapping, t: &mut T, place: &str) {
        for (k, v) in m {
            let (n, kp) = self.key(k);
            if !self.scalar(t, &n, v, kp, &mut Aliases::new()) {
                self.unknown(&n, v, kp, place, t.extra_mut());
            }
        }
    }

    /// Reads mapping `m` (at `pos`) as the node `T` of the field table: its scalar keys by the
    /// table, every other key by `key` (given the node, whose extras take the unknown ones).
    /// Returns the node and the keys read under an older spelling (`doc` among them).
    fn node<T: Fields + Default>(
        &mut self,
        m: &Mapping,
        pos: Pos,
        mut key: impl FnMut(&mut Self, &str, &Value, Pos, &mut T),
    ) -> (T, Aliases) {
        let mut t = T::default();
        *t.pos_mut() = pos;
        let mut al = Aliases::new();
        for (k, v) in m {
            let (n, kp) = self.key(k);
            if self.scalar(&mut t, &n, v, kp, &mut al) {
                continue;
            }
            doc_alias(&n, kp, &mut al);
            key(self, &n, v, kp, &mut t);
        }
        (t, al)
    }

    /// Reads mapping `m` (at `pos`) as the node `T` of the field table that has only scalar
    /// keys; any other is unknown in `place`.
    fn leaf<T: Fields + Default>(&mut self, m: &Mapping, pos: Pos, place: &str) -> T {
        let mut t = T::default();
        *t.pos_mut() = pos;
        self.scalars(m, &mut t, place);
        t
    }

    /// `"rtcDoc::doc"` (key `n` at `kp`): the doc node `T` when the value is a mapping (else it
    /// goes to `sink`).
    fn doc<T: Fields + Default>(
        &mut self,
        v: &Value,
        n: &str,
        kp: Pos,
        sink: &mut Extras,
        place: &str,
    ) -> Option<T> {
        let m = self.map(v, n, kp, sink)?;
        Some(self.leaf(m, kp, place))
    }

    /// Moves the aliases of a node into [`Profile::written_as`] as `node.field`; the node's
    /// name is made only when there are any (almost never).
    fn flush(&mut self, node: impl FnOnce() -> String, aliases: Aliases) {
        if aliases.is_empty() {
            return;
        }
        let node = node();
        for (field, written, pos, dialect) in aliases {
            self.written_as.push(WrittenAs {
                field: compact_str::format_compact!("{node}.{field}"),
                written_as: written.into(),
                dialect,
                pos,
            });
        }
    }

    /// Converts a subtree to an [`Extra`] (positions of nested keys included).
    fn extra(&mut self, name: &str, v: &Value, pos: Pos) -> Extra {
        let mut e = Extra {
            kind: ExtraKind::Key,
            name: name.into(),
            namespace: None,
            value: None,
            children: crate::model::Extras::new(),
            pos,
        };
        match untag_ref(v) {
            Value::Mapping(m) => {
                for (k, cv) in m {
                    let (n, p) = self.key(k);
                    let c = self.extra(&n, cv, p);
                    e.children.push(c);
                }
            }
            Value::Sequence(s) => {
                for (i, cv) in s.iter().enumerate() {
                    let p = self.loc.item();
                    let c = self.extra(&format!("[{i}]"), cv, p);
                    e.children.push(c);
                }
            }
            other => e.value = self.scalar_text(other, false),
        }
        e
    }

    /// Text of a scalar as written: numbers keep their source spelling (`1000.0`), booleans are
    /// `true`/`false`, null is `None`. `after_key` says whether the locator sits just after the
    /// key of this value (else after a sequence `-`).
    fn scalar_text(&mut self, v: &Value, after_key: bool) -> Option<Text> {
        let raw = if after_key {
            self.loc.raw_after_key()
        } else {
            self.loc.raw_item()
        };
        match untag_ref(v) {
            Value::Null => None,
            Value::Bool(b) => Some(if *b { "true" } else { "false" }.into()),
            Value::Number(n) => {
                let text = raw
                    .map(|(r, _)| r)
                    .filter(|r| r.parse::<serde_norway::Number>().ok().as_ref() == Some(n))
                    .map(Text::from);
                if let Some((_, end)) = raw {
                    self.loc.cursor = end;
                }
                Some(text.unwrap_or_else(|| compact_str::format_compact!("{n}")))
            }
            Value::String(s) => {
                // Skip a one-line value so that its text is not mistaken for a later key.
                if let Some((r, end)) = raw {
                    let unq = r
                        .strip_prefix('"')
                        .and_then(|r| r.strip_suffix('"'))
                        .or_else(|| r.strip_prefix('\'').and_then(|r| r.strip_suffix('\'')))
                        .unwrap_or(r);
                    if unq == s {
                        self.loc.cursor = end;
                    }
                }
                Some(s.as_str().into())
            }
            _ => None,
        }
    }

    /// A text value (chapter 7 `type: text|int|bool|number`).
    fn text(&mut self, v: &Value, name: &str, pos: Pos, sink: &mut Extras) -> Option<Text> {
        match untag_ref(v) {
            Value::Mapping(_) | Value::Sequence(_) => {
                self.wrong_shape(name, v, pos, "a scalar", sink);
                None
            }
            other => self.scalar_text(other, true),
        }
    }

    /// A mapping value; `None` (with nothing reported) for null, a `SHAPE` warning otherwise.
    fn map<'v>(
        &mut self,
        v: &'v Value,
        name: &str,
        pos: Pos,
        sink: &mut Extras,
    ) -> Option<&'v Mapping> {
        match untag_ref(v) {
            Value::Mapping(m) => Some(m),
            Value::Null => None,
            _ => {
                self.wrong_shape(name, v, pos, "a mapping", sink);
                None
            }
        }
    }

    /// A sequence value; empty for null, a `SHAPE` warning otherwise.
    fn seq<'v>(&mut self, v: &'v Value, name: &str, pos: Pos, sink: &mut Extras) -> &'v [Value] {
        match untag_ref(v) {
            Value::Sequence(s) => s,
            Value::Null => &[],
            _ => {
                self.wrong_shape(name, v, pos, "a list", sink);
                &[]
            }
        }
    }

    /// A list of texts (`osVersions`, `cpus`, `"rtcExt::versionUpLogs"`).
    fn texts(&mut self, v: &Value, name: &str, pos: Pos, sink: &mut Extras) -> Vec<Text> {
        let items = self.scalar_items(v, name, pos, sink, "a scalar");
        items.into_iter().map(|(text, _)| text).collect()
    }

    /// The texts of a list of scalars with their positions; other items reported as `SHAPE`
    /// (`want`: what an item should be).
    fn scalar_items(
        &mut self,
        v: &Value,
        name: &str,
        pos: Pos,
        sink: &mut Extras,
        want: &str,
    ) -> Vec<(Text, Pos)> {
        let mut out = Vec::new();
        for (i, item) in self.seq(v, name, pos, sink).iter().enumerate() {
            let p = self.loc.item();
            match untag_ref(item) {
                Value::Mapping(_) | Value::Sequence(_) => {
                    self.wrong_shape(&format!("{name}[{i}]"), item, p, want, sink)
                }
                other => out.extend(self.scalar_text(other, false).map(|text| (text, p))),
            }
        }
        out
    }

    /// One item of a list of mappings, with its position (located now, in document order);
    /// null items are skipped, other non-mapping items reported as `SHAPE`.
    fn map_item<'v>(
        &mut self,
        item: &'v Value,
        name: &str,
        i: usize,
        sink: &mut Extras,
    ) -> Option<(&'v Mapping, Pos)> {
        let p = self.loc.item();
        match untag_ref(item) {
            Value::Mapping(m) => Some((m, p)),
            Value::Null => None,
            _ => {
                self.wrong_shape(&format!("{name}[{i}]"), item, p, "a mapping", sink);
                None
            }
        }
    }

    /// `"rtcExt::property"` (chapter 7) / `"rtcExt::properties"` (RTCBuilder): `[{name, value}]`.
    fn properties(&mut self, v: &Value, name: &str, pos: Pos, sink: &mut Extras) -> Vec<Property> {
        let mut out = Vec::new();
        each_item(self, v, name, pos, sink, |r, m, p| {
            out.push(r.leaf(m, p, "a property"))
        });
        out
    }

    /// `rtcProfile` (spec 2.2, chapter 7 root).
    fn profile(&mut self, v: &Value, pos: Pos, p: &mut Profile) {
        let Some(m) = self.map(v, "rtcProfile", pos, &mut p.extra) else {
            return;
        };
        for (k, v) in m {
            let (n, kp) = self.key(k);
            if self.scalar(p, &n, v, kp, &mut Aliases::new()) {
                continue;
            }
            match &*n {
                "basicInfo" => {
                    p.basic_info.pos = kp;
                    self.basic_info(v, kp, &mut p.basic_info, &mut p.extra);
                }
                "actions" => {
                    p.actions_pos = Some(kp);
                    if let Some(m) = self.map(v, &n, kp, &mut p.extra) {
                        self.actions(m, p);
                    }
                }
                "configurationSet" => {
                    if let Some(m) = self.map(v, &n, kp, &mut p.extra) {
                        p.configuration_set = Some(self.configuration_set(m, kp));
                    }
                }
                // spec 2.3.7, 2.4.5/2.4.6 doc, 2.5.3 ext.
                "dataPorts" => each_item(self, v, &n, kp, &mut p.extra, |r, m, ip| {
                    p.data_ports.push(r.documented(m, ip, "a data port"))
                }),
                "servicePorts" => each_item(self, v, &n, kp, &mut p.extra, |r, m, ip| {
                    p.service_ports.push(r.service_port(m, ip))
                }),
                "parameters" => each_item(self, v, &n, kp, &mut p.extra, |r, m, ip| {
                    p.parameters.push(r.parameter(m, ip))
                }),
                "language" => {
                    if let Some(m) = self.map(v, &n, kp, &mut p.extra) {
                        p.language = Some(self.language(m, kp));
                    }
                }
                _ => self.unknown(&n, v, kp, "rtcProfile", &mut p.extra),
            }
        }
    }

    /// `basicInfo` (spec 2.3.2, 2.4.1/2.4.2 doc, 2.5.1 ext).
    fn basic_info(&mut self, v: &Value, pos: Pos, b: &mut BasicInfo, outer: &mut Extras) {
        let Some(m) = self.map(v, "basicInfo", pos, outer) else {
            return;
        };
        let mut al = Aliases::new();
        for (k, v) in m {
            let (n, kp) = self.key(k);
            if self.scalar(b, &n, v, kp, &mut al) {
                continue;
            }
            if matches!(&*n, "doc" | "versionUpLog") {
                al.push((
                    if n == "doc" {
                        "rtcDoc::doc"
                    } else {
                        "rtcExt::versionUpLogs"
                    },
                    n.to_string(),
                    kp,
                    super::dialect::RTC_TEMPLATE,
                ));
            }
            let x = &mut b.extra;
            match &*n {
                "rtcExt::versionUpLogs" | "rtcExt::versionUpLog" | "versionUpLog" => {
                    b.version_up_logs = self.texts(v, &n, kp, x)
                }
                "rtcExt::property" | "rtcExt::properties" => {
                    b.properties = self.properties(v, &n, kp, x)
                }
                "rtcDoc::doc" | "doc" => b.doc = self.doc(v, &n, kp, x, "basicInfo rtcDoc::doc"),
                _ => self.unknown(&n, v, kp, "basicInfo", x),
            }
        }
        self.flush(|| "basicInfo".into(), al);
    }

    /// A date: a chapter 7 `dateType` map (→ ISO 8601) or a plain string kept as written.
    fn date(&mut self, v: &Value, name: &str, pos: Pos, sink: &mut Extras) -> Option<Text> {
        let m = match untag_ref(v) {
            Value::Mapping(m) => m,
            Value::Sequence(_) => {
                self.wrong_shape(name, v, pos, "a date map or a date string", sink);
                return None;
            }
            other => return self.scalar_text(other, true),
        };
        // Every field written without a value (`year:`, `month:`, … as some generators save an
        // unset date): no date, as if the key were absent (the required-field rule says so
        // once), not a second finding about an incomplete one.
        let blank = |cv: &Value| match untag_ref(cv) {
            Value::Null => true,
            Value::String(t) => t.trim().is_empty(),
            _ => false,
        };
        let date_key = |k: &Value| {
            matches!(
                &*key_text(k),
                "year" | "month" | "day" | "hour" | "minute" | "second"
            )
        };
        if !m.is_empty() && m.iter().all(|(k, cv)| date_key(k) && blank(cv)) {
            return None;
        }
        let mut parts = DateParts::default();
        let mut bad = false;
        for (k, cv) in m {
            let (n, kp) = self.key(k);
            let idx = ["year", "month", "day", "hour", "minute", "second"]
                .iter()
                .position(|f| *f == n);
            let text = match untag_ref(cv) {
                Value::Mapping(_) | Value::Sequence(_) => None,
                other => self.scalar_text(other, true),
            };
            let int = text.as_deref().and_then(|t| t.trim().parse::<i64>().ok());
            match (&*n, idx) {
                (_, Some(i)) => {
                    parts.ymdhms[i] = int;
                    bad |= int.is_none();
                }
                ("fractionalSecond", _) => parts.fraction = text,
                ("millisecond", _) => parts.millisecond = int,
                ("timezone", _) => parts.timezone = int,
                _ => self.unknown(&format!("{name}.{n}"), cv, kp, name, sink),
            }
        }
        match parts.iso() {
            Some(iso) if !bad => Some(iso),
            _ => {
                self.warn(
                    codes::SHAPE,
                    pos,
                    format!(
                        "`{name}` is not a complete date (integer year, month, day, hour, \
                         minute and second); kept as an extra property"
                    ),
                );
                // The entries were located above; they share the date key's position here.
                let e = Extra {
                    kind: ExtraKind::Key,
                    name: name.into(),
                    namespace: None,
                    value: None,
                    children: m
                        .iter()
                        .map(|(k, cv)| Extra {
                            kind: ExtraKind::Key,
                            name: key_text(k).into(),
                            namespace: None,
                            value: match untag_ref(cv) {
                                Value::String(s) => Some(s.as_str().into()),
                                Value::Number(n) => Some(compact_str::format_compact!("{n}")),
                                Value::Bool(b) => Some(if *b { "true" } else { "false" }.into()),
                                _ => None,
                            },
                            children: crate::model::Extras::new(),
                            pos,
                        })
                        .collect(),
                    pos,
                };
                sink.push(e);
                None
            }
        }
    }

    /// `actions` (spec 2.3.3/2.3.4, 2.4.3): each `onX: {implemented, "rtcDoc::doc"}` or null.
    fn actions(&mut self, m: &Mapping, p: &mut Profile) {
        for (k, v) in m {
            let (n, kp) = self.key(k);
            let Some(kind) = ActionKind::from_yaml_name(&n) else {
                self.unknown(&n, v, kp, "actions", &mut p.extra);
                continue;
            };
            let mut a = Action {
                kind,
                implemented: None,
                doc: None,
                pos: kp,
                extra: crate::model::Extras::new(),
            };
            let mut al = Aliases::new();
            if let Some(m) = self.map(v, &n, kp, &mut a.extra) {
                for (k, v) in m {
                    let (n, kp) = self.key(k);
                    if self.scalar(&mut a, &n, v, kp, &mut al) {
                        continue;
                    }
                    doc_alias(&n, kp, &mut al);
                    match &*n {
                        "rtcDoc::doc" | "doc" => {
                            a.doc = self.doc(v, &n, kp, &mut a.extra, "an action's rtcDoc::doc")
                        }
                        _ => self.unknown(&n, v, kp, "an action", &mut a.extra),
                    }
                }
            }
            self.flush(|| format!("actions.{}", kind.yaml_name()), al);
            p.actions.push(a);
        }
    }

    /// `configurationSet` (spec 2.3.5) with its `configuration` list (2.3.6, 2.4.4, 2.5.2).
    fn configuration_set(&mut self, m: &Mapping, pos: Pos) -> ConfigurationSet {
        let mut cs = ConfigurationSet {
            pos,
            ..ConfigurationSet::default()
        };
        for (k, v) in m {
            let (n, kp) = self.key(k);
            if n != "configuration" {
                self.unknown(&n, v, kp, "configurationSet", &mut cs.extra);
                continue;
            }
            // A configuration parameter (spec 2.3.6, 2.4.4 doc, 2.5.2 ext).
            each_item(self, v, &n, kp, &mut cs.extra, |r, m, ip| {
                cs.configurations
                    .push(r.documented(m, ip, "a configuration"))
            });
        }
        cs
    }

    /// A service port (spec 2.3.8, 2.4.7 doc, 2.5.4 ext).
    fn service_port(&mut self, m: &Mapping, pos: Pos) -> ServicePort {
        self.documented_with(
            m,
            pos,
            "a service port",
            |r, n, v, kp, s: &mut ServicePort| {
                let x = &mut s.extra;
                match n {
                    "transMethod" | "transMethods" => each_item(r, v, n, kp, x, |r, m, ip| {
                        s.trans_methods.push(r.leaf(m, ip, "a transMethod"))
                    }),
                    // A service interface (spec 2.3.9, 2.4.8 doc, 2.5.5 ext).
                    "serviceInterface" | "serviceInterfaces" => {
                        each_item(r, v, n, kp, x, |r, m, ip| {
                            s.interfaces
                                .push(r.documented(m, ip, "a service interface"))
                        })
                    }
                    _ => return false,
                }
                true
            },
        )
    }

    /// Reads mapping `m` (at `pos`) as the [`Documented`] node `T`: its scalars by the field
    /// table, `"rtcExt::properties"`, `"rtcDoc::doc"` and (where `T` has one) `constraint`; any
    /// other key unknown in `place` (`a data port`). Its older spellings are recorded as
    /// `label name` (`dataPort out`).
    fn documented<T: Documented>(&mut self, m: &Mapping, pos: Pos, place: &str) -> T {
        self.documented_with(m, pos, place, |_, _, _, _, _| false)
    }

    /// [`Reader::documented`], with any other key read by `other` first (false: not its own).
    fn documented_with<T: Documented>(
        &mut self,
        m: &Mapping,
        pos: Pos,
        place: &str,
        mut other: impl FnMut(&mut Self, &str, &Value, Pos, &mut T) -> bool,
    ) -> T {
        let (t, al) = self.node(m, pos, |r, n, v, kp, t: &mut T| {
            if other(r, n, v, kp, t) {
                return;
            }
            let DocParts {
                properties,
                doc,
                constraint,
                extra: x,
            } = t.parts();
            match (n, constraint) {
                ("rtcExt::property" | "rtcExt::properties", _) => {
                    *properties = r.properties(v, n, kp, x)
                }
                ("rtcDoc::doc" | "doc", _) => {
                    *doc = r.doc(v, n, kp, x, &format!("{place}'s rtcDoc::doc"))
                }
                ("constraint", Some(slot)) => *slot = r.constraint_value(v, n, kp, x),
                _ => r.unknown(n, v, kp, place, x),
            }
        });
        self.flush(|| t.written_as_node(), al);
        t
    }

    /// A system parameter (spec 2.3.11, 5.4).
    fn parameter(&mut self, m: &Mapping, pos: Pos) -> Parameter {
        self.leaf(m, pos, "a parameter")
    }

    /// `language` (spec 2.3.12) with `"rtcExt::targets"` (2.5.6–2.5.8).
    fn language(&mut self, m: &Mapping, pos: Pos) -> Language {
        let (l, _) = self.node(m, pos, |r, n, v, kp, l: &mut Language| match n {
            "rtcExt::targets" | "rtcExt::target" => {
                each_item(r, v, n, kp, &mut l.extra, |r, m, ip| {
                    l.targets.push(r.target(m, ip))
                })
            }
            k if super::dialect::language_element(k).is_some() => r.language_element(n, v, kp, l),
            _ => r.unknown(n, v, kp, "language", &mut l.extra),
        });
        l
    }

    /// rtc-template's `language: {java: {library: [...]}}` (and `cxx:`, `python:`): the key is
    /// the language kind, its map the target (as RTCBuilder 0.1's `<rtc:Cxx/>` element).
    fn language_element(&mut self, n: &str, v: &Value, kp: Pos, l: &mut Language) {
        let Some(kind) = super::dialect::language_element(n) else {
            return;
        };
        if l.kind.is_none() {
            l.kind = Some(kind.into());
            self.written_as.push(WrittenAs {
                field: "language.kind".into(),
                written_as: n.into(),
                dialect: super::dialect::RTC_TEMPLATE,
                pos: kp,
            });
        }
        let Some(m) = self.map(v, n, kp, &mut l.extra) else {
            return;
        };
        let (t, _) = self.node(m, kp, |r, n, v, kp, t: &mut Target| {
            let x = &mut t.extra;
            match n {
                "arch" | "cpus" => t.cpus.extend(r.texts_or_text(v, n, kp, x)),
                "osVersion" | "osVersions" => t.os_versions.extend(r.texts_or_text(v, n, kp, x)),
                "library" | "libraries" => {
                    let names = r.scalar_items(v, n, kp, x, "a library name");
                    t.libraries
                        .extend(names.into_iter().map(|(name, pos)| Library {
                            name: Some(name),
                            pos,
                            ..Library::default()
                        }))
                }
                _ => r.unknown(n, v, kp, "a language target", x),
            }
        });
        l.targets.push(t);
    }

    /// A list of texts, or one text as a list of one (empty text: none).
    fn texts_or_text(&mut self, v: &Value, name: &str, pos: Pos, sink: &mut Extras) -> Vec<Text> {
        match untag_ref(v) {
            Value::Sequence(_) => self.texts(v, name, pos, sink),
            _ => self
                .text(v, name, pos, sink)
                .filter(|t| !t.trim().is_empty())
                .into_iter()
                .collect(),
        }
    }

    fn target(&mut self, m: &Mapping, pos: Pos) -> Target {
        let (t, _) = self.node(m, pos, |r, n, v, kp, t: &mut Target| {
            let x = &mut t.extra;
            match n {
                "osVersions" => t.os_versions = r.texts(v, n, kp, x),
                "cpus" => t.cpus = r.texts(v, n, kp, x),
                "libraries" => each_item(r, v, n, kp, x, |r, m, ip| {
                    t.libraries.push(r.leaf(m, ip, "a library"))
                }),
                _ => r.unknown(n, v, kp, "a target", x),
            }
        });
        t
    }

    // -- Constraints (spec 2.3.17–2.3.41, chapter 7 `constraintRoot`, samples 8.2) ----------

    /// The value of a `constraint:` key (`name`) or of a `not:` operand: a constraint, empty
    /// for null.
    fn constraint_value(
        &mut self,
        v: &Value,
        name: &str,
        pos: Pos,
        sink: &mut Extras,
    ) -> Option<Constraint> {
        match untag_ref(v) {
            Value::Null => Some(Constraint {
                kind: ConstraintKind::Empty,
                pos,
                extra: crate::model::Extras::new(),
            }),
            Value::Mapping(m) => Some(self.constraint_node(m, pos)),
            _ => {
                self.wrong_shape(name, v, pos, "a mapping", sink);
                None
            }
        }
    }

    /// One constraint: a map with one form key (`constraintUnit[Type]`, `constraintList[Type]`,
    /// `constraintHash[Type]`), or directly a unit body (`key` + condition, as in the 8.2
    /// `or` samples), or a wrapper `{constraint: …}`.
    fn constraint_node(&mut self, m: &Mapping, pos: Pos) -> Constraint {
        let mut c = Constraint {
            kind: ConstraintKind::Empty,
            pos,
            extra: crate::model::Extras::new(),
        };
        let keys: Vec<String> = m.keys().map(key_text).collect();
        let has_form = keys.iter().any(|k| form_of(k).is_some());
        let has_unit = keys.iter().any(|k| k == "key" || op_of(k).is_some());
        if !has_form && !has_unit {
            // `{constraint: …}` wrapper (e.g. inside `not`).
            for (k, v) in m {
                let (n, kp) = self.key(k);
                match (&*n, untag_ref(v)) {
                    ("constraint", Value::Mapping(inner))
                        if matches!(c.kind, ConstraintKind::Empty) =>
                    {
                        let mut inner = self.constraint_node(inner, kp);
                        inner.extra.append(&mut c.extra);
                        c = inner;
                    }
                    ("constraint", Value::Null) => {}
                    _ => self.unknown(&n, v, kp, "a constraint", &mut c.extra),
                }
            }
            return c;
        }
        if has_unit && !has_form {
            c.kind = self.unit_body(m, &mut c.extra);
            return c;
        }
        for (k, v) in m {
            let (n, kp) = self.key(k);
            let form = form_of(&n);
            match form {
                Some(f) if matches!(c.kind, ConstraintKind::Empty) => match f {
                    Form::Unit => match untag_ref(v) {
                        Value::Mapping(um) => {
                            c.pos = kp;
                            c.kind = self.unit_body(um, &mut c.extra);
                        }
                        Value::Null => c.pos = kp,
                        _ => self.wrong_shape(&n, v, kp, "a mapping", &mut c.extra),
                    },
                    Form::List | Form::Hash => {
                        c.pos = kp;
                        let items = self.constraint_items(v, &n, kp, &mut c.extra);
                        c.kind = if f == Form::List {
                            ConstraintKind::List { items }
                        } else {
                            ConstraintKind::Hash { items }
                        };
                    }
                },
                Some(_) => {
                    self.warn(
                        codes::SHAPE,
                        kp,
                        format!("a constraint has more than one form; `{n}` kept as an extra"),
                    );
                    let e = self.extra(&n, v, kp);
                    c.extra.push(e);
                }
                None => self.unknown(&n, v, kp, "a constraint", &mut c.extra),
            }
        }
        c
    }

    /// Children of a list / hash / `and` / `or`: a sequence of constraints, or a map with a
    /// `constraint:` sequence (RTCBuilder, `Constraint/Hash2.yaml`).
    fn constraint_items(
        &mut self,
        v: &Value,
        name: &str,
        pos: Pos,
        sink: &mut Extras,
    ) -> Vec<Constraint> {
        match untag_ref(v) {
            Value::Sequence(s) => {
                let mut out = Vec::new();
                for (i, item) in s.iter().enumerate() {
                    let p = self.loc.item();
                    match untag_ref(item) {
                        Value::Mapping(m) => out.push(self.constraint_node(m, p)),
                        Value::Null => out.push(Constraint {
                            kind: ConstraintKind::Empty,
                            pos: p,
                            extra: crate::model::Extras::new(),
                        }),
                        _ => self.wrong_shape(&format!("{name}[{i}]"), item, p, "a mapping", sink),
                    }
                }
                out
            }
            Value::Mapping(m) => {
                let mut out = Vec::new();
                for (k, cv) in m {
                    let (n, kp) = self.key(k);
                    if n == "constraint" {
                        match untag_ref(cv) {
                            Value::Mapping(one) => out.push(self.constraint_node(one, kp)),
                            _ => out.extend(self.constraint_items(cv, &n, kp, sink)),
                        }
                    } else {
                        self.unknown(&n, cv, kp, name, sink);
                    }
                }
                out
            }
            Value::Null => Vec::new(),
            _ => {
                self.wrong_shape(name, v, pos, "a list of constraints", sink);
                Vec::new()
            }
        }
    }

    /// The body of a constraint unit: optional `key` plus exactly one condition.
    fn unit_body(&mut self, m: &Mapping, sink: &mut Extras) -> ConstraintKind {
        let mut key = None;
        let mut condition: Option<Condition> = None;
        for (k, v) in m {
            let (n, kp) = self.key(k);
            if n == "key" {
                key = self.text(v, &n, kp, sink);
                continue;
            }
            let Some(op) = op_of(&n) else {
                self.unknown(&n, v, kp, "a constraint unit", sink);
                continue;
            };
            if condition.is_some() {
                self.warn(
                    codes::SHAPE,
                    kp,
                    format!(
                        "a constraint unit has more than one condition; `{n}` kept as an extra"
                    ),
                );
                let e = self.extra(&n, v, kp);
                sink.push(e);
                continue;
            }
            condition = self.condition(op, &n, v, kp, sink);
        }
        if let (None, Some(k)) = (&condition, &key) {
            sink.push(Extra {
                kind: ExtraKind::Key,
                name: "key".into(),
                namespace: None,
                value: Some(k.clone()),
                children: crate::model::Extras::new(),
                pos: Pos::default(),
            });
        }
        ConstraintKind::unit(key, condition)
    }

    fn condition(
        &mut self,
        op: Op,
        name: &str,
        v: &Value,
        pos: Pos,
        sink: &mut Extras,
    ) -> Option<Condition> {
        match op {
            Op::Not => Some(Condition::Not {
                operand: self.constraint_value(v, name, pos, sink)?,
            }),
            Op::And => Some(Condition::And {
                operands: self.constraint_items(v, name, pos, sink),
            }),
            Op::Or => Some(Condition::Or {
                operands: self.constraint_items(v, name, pos, sink),
            }),
            Op::IsNull => match untag_ref(v) {
                Value::Mapping(m) if m.is_empty() => Some(Condition::IsNull { text: None }),
                Value::Mapping(_) | Value::Sequence(_) => {
                    self.wrong_shape(name, v, pos, "empty or a scalar", sink);
                    Some(Condition::IsNull { text: None })
                }
                other => Some(Condition::IsNull {
                    text: self.scalar_text(other, true),
                }),
            },
            Op::Compare(comparison) => {
                let [literal, match_case] =
                    self.operands(v, name, pos, sink, [&["literal"], &["matchCase"]])?;
                Some(Condition::Compare {
                    comparison,
                    literal,
                    match_case,
                })
            }
            Op::Like => {
                let keys: [&[&str]; 4] = [
                    &["literal"],
                    // XSD `wildCard`, YAML 8.2 `wildcard`, PIM `wildChar` (NOTES).
                    &["wildCard", "wildcard", "wildChar"],
                    &["singleChar"],
                    &["escapeChar"],
                ];
                let [literal, wild_card, single_char, escape_char] =
                    self.operands(v, name, pos, sink, keys)?;
                Some(Condition::Like {
                    literal,
                    wild_card,
                    single_char,
                    escape_char,
                })
            }
            Op::Between => {
                let keys: [&[&str]; 2] = [&["lowerBoundary"], &["upperBoundary"]];
                let [lower, upper] = self.operands(v, name, pos, sink, keys)?;
                Some(Condition::Between { lower, upper })
            }
        }
    }

    /// The texts of an operator's mapping `v` (null: none), one for each slot of `keys` (the
    /// spellings of its key); any other key unknown in `name`.
    fn operands<const N: usize>(
        &mut self,
        v: &Value,
        name: &str,
        pos: Pos,
        sink: &mut Extras,
        keys: [&[&str]; N],
    ) -> Option<[Option<Text>; N]> {
        let mut texts = std::array::from_fn(|_| None);
        if let Value::Null = untag_ref(v) {
            return Some(texts);
        }
        for (k, v) in self.map(v, name, pos, sink)? {
            let (n, kp) = self.key(k);
            match keys.iter().position(|spellings| spellings.contains(&&*n)) {
                Some(i) => texts[i] = self.text(v, &n, kp, sink),
                None => self.unknown(&n, v, kp, name, sink),
            }
        }
        Some(texts)
    }
}

/// The end of the one-line scalar that starts at `start` of `src`: a quoted one at its closing
/// quote, a plain one at a `,`, `]` or `}` (flow style), a ` #` comment or the end of its line,
/// without the blanks before it.
fn scalar_end(src: &str, start: usize) -> usize {
    let line = src[start..].split('\n').next().unwrap_or("");
    let len = match line.chars().next() {
        Some(q @ ('"' | '\'')) => line[1..].find(q).map_or(line.len(), |n| n + 2),
        _ => {
            let l = line.split(" #").next().unwrap_or(line);
            l.find([',', ']', '}']).unwrap_or(l.len())
        }
    };
    start + line[..len].trim_end().len()
}
