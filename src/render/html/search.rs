//! The client-side search index, built once at build time.
//!
//! `search-index.js` assigns one object to `window.RTCDOC_INDEX` (see [`index_js`]); loading
//! it with a `<script>` tag works from `file://` (where `fetch()` is forbidden). Every
//! document kind has entries: components, data types, interfaces and RT Systems. Tokens are lower-case
//! words in three ranked groups (name, identifiers, prose: see [`Groups`]). Latin words are also split at camelCase and
//! `::` boundaries; runs of CJK characters become overlapping bigrams (a lone character stays a
//! unigram), so Japanese text needs no dictionary. Text is read in NFKC first ([`nfkc`]: full-
//! and half-width forms are one). `search.js` tokenizes queries the same way and matches each
//! query token as a prefix of some entry token.

use crate::catalog::{Catalog, ComponentIx, Ix};
use crate::i18n::Lang;
use crate::model::{documented, non_empty};
use crate::types::canonical_type;
use rayon::prelude::*;
use std::borrow::Cow;

/// Whether `c` is written without spaces between words (kana, CJK ideographs, full-width forms).
pub fn is_cjk(c: char) -> bool {
    matches!(c as u32,
        0x3040..=0x30FF   // hiragana, katakana
        | 0x3400..=0x4DBF // CJK extension A
        | 0x4E00..=0x9FFF // CJK unified ideographs
        | 0xF900..=0xFAFF // compatibility ideographs
        | 0xFF66..=0xFF9F // half-width katakana
        | 0xAC00..=0xD7AF // hangul syllables
    )
}

/// Splits `text` into search tokens (see the module documentation); pushes them onto `out`,
/// duplicates included (the caller sorts and de-duplicates). Tokens borrow from `text` unless
/// lower-casing changed them.
pub fn tokenize<'a>(text: &'a str, out: &mut Vec<Cow<'a, str>>) {
    let bytes = text.as_bytes();
    // Start of the current word or CJK run (byte offset), and which of the two it is.
    let mut start: Option<(usize, bool)> = None;
    let mut i = 0;
    while i < bytes.len() {
        // ASCII (most of the text, even Japanese profiles' identifiers) is classed by its byte;
        // anything else by its character.
        let (class, len) = match bytes[i] {
            b if b.is_ascii() => ((b.is_ascii_alphanumeric() || b == b'_').then_some(false), 1),
            _ => match text[i..].chars().next() {
                Some(c) if is_cjk(c) => (Some(true), c.len_utf8()),
                Some(c) => (c.is_alphanumeric().then_some(false), c.len_utf8()),
                None => break,
            },
        };
        match (start, class) {
            (Some((_, a)), Some(b)) if a == b => {}
            _ => {
                if let Some((s, cjk)) = start {
                    flush(&text[s..i], cjk, out);
                }
                start = class.map(|cjk| (i, cjk));
            }
        }
        i += len;
    }
    if let Some((s, cjk)) = start {
        flush(&text[s..], cjk, out);
    }
}

/// The tokens of one word (itself and its camelCase / digit parts) or one CJK run
/// (overlapping bigrams, or the lone character).
fn flush<'a>(run: &'a str, cjk: bool, out: &mut Vec<Cow<'a, str>>) {
    if cjk {
        // Each character with the next one; a lone character stands for itself.
        let mut prev = 0;
        for (i, c) in run.char_indices().skip(1) {
            out.push(Cow::Borrowed(&run[prev..i + c.len_utf8()]));
            prev = i;
        }
        if prev == 0 {
            out.push(Cow::Borrowed(run));
        }
        return;
    }
    out.push(lower(run));
    // An ASCII word by its bytes (for ASCII the character classes are the byte ones: no
    // decoding), any other by its characters.
    if run.is_ascii() {
        let boundary = |p: char, c: char| {
            (p.is_ascii_lowercase() && c.is_ascii_uppercase())
                || (p.is_ascii_alphabetic() && c.is_ascii_digit())
                || (p.is_ascii_digit() && c.is_ascii_alphabetic())
        };
        push_parts(run, run.bytes().map(char::from).enumerate(), boundary, out);
    } else {
        let boundary = |p: char, c: char| {
            (p.is_lowercase() && c.is_uppercase())
                || (p.is_alphabetic() && c.is_ascii_digit())
                || (p.is_ascii_digit() && c.is_alphabetic())
        };
        push_parts(run, run.char_indices(), boundary, out);
    }
}

/// The camelCase / digit parts of a word (`UsbCamera` → usb, camera), from its characters
/// with their byte offsets and the test of a boundary between two characters; only when there
/// are two parts or more.
fn push_parts<'a>(
    run: &'a str,
    chars: impl Iterator<Item = (usize, char)>,
    boundary: impl Fn(char, char) -> bool,
    out: &mut Vec<Cow<'a, str>>,
) {
    let mut part_start = 0;
    let mut prev: Option<char> = None;
    for (i, c) in chars {
        if let Some(p) = prev {
            if boundary(p, c) {
                out.push(lower(&run[part_start..i]));
                part_start = i;
            }
        }
        prev = Some(c);
    }
    if part_start > 0 {
        out.push(lower(&run[part_start..]));
    }
}

/// `s` lower-cased (as `str::to_lowercase`), borrowed when it already is.
fn lower(s: &str) -> Cow<'_, str> {
    if s.bytes().all(|b| !b.is_ascii_uppercase() && b.is_ascii()) {
        Cow::Borrowed(s)
    } else if s.is_ascii() {
        Cow::Owned(s.to_ascii_lowercase())
    } else {
        Cow::Owned(s.to_lowercase())
    }
}

/// Tokenizes the first [`MAX_DESCRIPTION`] characters of `s`, read as prose
/// ([`crate::model::prose`]: RTCBuilder's `<br/>` is a line break, not a word).
fn add<'a>(tokens: &mut Vec<Cow<'a, str>>, s: Option<&'a str>) {
    let Some(s) = s else { return };
    let head = |s: &str| {
        s.char_indices()
            .nth(MAX_DESCRIPTION)
            .map_or(s.len(), |(i, _)| i)
    };
    match nfkc(crate::model::prose(s)) {
        Cow::Borrowed(s) => tokenize(&s[..head(s)], tokens),
        Cow::Owned(o) => {
            let mut own = Vec::new();
            tokenize(&o[..head(&o)], &mut own);
            tokens.extend(own.into_iter().map(|t| Cow::Owned(t.into_owned())));
        }
    }
}

/// `s` in Unicode normalisation form NFKC, as `search.js` reads queries: full-width `Ｋｏｂｕｋｉ`
/// is `Kobuki`, half-width `ｶﾒﾗ` is `カメラ`. Borrowed when it already is (ASCII, most Japanese).
pub fn nfkc(s: Cow<'_, str>) -> Cow<'_, str> {
    use unicode_normalization::{is_nfkc_quick, IsNormalized, UnicodeNormalization};
    if s.is_ascii() || is_nfkc_quick(s.chars()) == IsNormalized::Yes {
        return s;
    }
    Cow::Owned(s.nfkc().collect())
}

/// Longest description text indexed per description, in characters (keeps entries small).
const MAX_DESCRIPTION: usize = 400;

/// The three token groups of an entry, ranked: the entry's name; identifiers (port,
/// configuration, field and operation names, data and interface types); prose (descriptions,
/// category, vendor). A match in an earlier group ranks higher.
#[derive(Default)]
struct Groups<'a> {
    name: Vec<Cow<'a, str>>,
    ids: Vec<Cow<'a, str>>,
    text: Vec<Cow<'a, str>>,
}

impl<'a> Groups<'a> {
    /// An item's `name` among the ids, its documentation `doc` among the text.
    fn item(&mut self, name: Option<&'a str>, doc: Option<&'a str>) {
        add(&mut self.ids, name);
        add(&mut self.text, doc);
    }

    /// `name|ids|text`, each a space-separated sorted list. A token is left out of a group when
    /// it is a prefix of a token of the same or an earlier group: queries match tokens by
    /// prefix, so it would find nothing more (this halves Japanese prose, whose bigrams
    /// repeat).
    fn encode(self) -> String {
        let groups = [
            sorted_unique(&self.name),
            sorted_unique(&self.ids),
            sorted_unique(&self.text),
        ];
        // The tokens of the earlier groups, sorted (borrowed: no copy of any token).
        let mut earlier: Vec<&str> = Vec::new();
        let mut out = String::new();
        for (gi, g) in groups.iter().enumerate() {
            if gi > 0 {
                out.push('|');
            }
            let mut first = true;
            // The first earlier token not below `t`: `g` is sorted, so it only moves forward.
            let mut at = 0;
            for (i, &t) in g.iter().enumerate() {
                // The name keeps every token (an exact name match ranks first).
                let covered = gi > 0
                    && (g.get(i + 1).is_some_and(|n| n.starts_with(t)) || {
                        while earlier.get(at).is_some_and(|e| *e < t) {
                            at += 1;
                        }
                        earlier.get(at).is_some_and(|n| n.starts_with(t))
                    });
                if covered {
                    continue;
                }
                if !first {
                    out.push(' ');
                }
                first = false;
                out.push_str(t);
            }
            if gi < 2 {
                earlier = merge_sorted(&earlier, g);
            }
        }
        out
    }
}

/// The tokens sorted, each once. They are sorted by their first eight bytes as a number first
/// (tokens hold no NUL byte, so zero padding orders a prefix first, as string order does): most
/// comparisons end there, without comparing the strings.
fn sorted_unique<'s>(tokens: &'s [Cow<'_, str>]) -> Vec<&'s str> {
    let mut keyed: Vec<(u64, &str)> = tokens
        .iter()
        .map(|t| {
            let mut head = [0u8; 8];
            let b = t.as_bytes();
            let n = b.len().min(8);
            head[..n].copy_from_slice(&b[..n]);
            (u64::from_be_bytes(head), t.as_ref())
        })
        .collect();
    keyed.sort_unstable();
    keyed.dedup_by(|a, b| a.1 == b.1);
    keyed.into_iter().map(|(_, t)| t).collect()
}

/// The tokens of two sorted lists, sorted (a merge: both are sorted already).
fn merge_sorted<'s>(a: &[&'s str], b: &[&'s str]) -> Vec<&'s str> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if a[i] <= b[j] {
            out.push(a[i]);
            i += 1;
        } else {
            out.push(b[j]);
            j += 1;
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

/// One entry of the search index: what a result shows (kind letter, name, page, the meta line
/// and the summary) and its tokens (`name|ids|text`, [`Groups::encode`]).
struct Entry {
    kind: &'static str,
    name: String,
    href: String,
    meta: String,
    summary: String,
    groups: String,
}

/// Entries per details file (`search/e<N>.js`: the meta line and summary of entries
/// `N * DETAILS_BLOCK ..`), fetched for the results shown.
const DETAILS_BLOCK: usize = 64;

/// A token file (`search/t<N>.js`) is closed once it holds this many bytes.
const SHARD_BYTES: usize = 24 * 1024;

/// Writes the search index, split so that a query downloads only what it needs (see
/// `search.js`), each file through `emit(path, bytes)`:
/// - `search-index.js`, loaded on first use: `window.RTCDOC_INDEX = {b, d, e, h, kinds, s, v}`;
///   `e` holds each entry's `[kind, name, href]` (`href` short: [`short_href`], with `h` the
///   folder of each kind; components first, in catalogue order, then
///   data types, interfaces and RT Systems), `kinds` a label per kind letter, `s` the first
///   token of each token file, `b` the prefixes that have a file of their own (below), `d`
///   [`DETAILS_BLOCK`], `v` the format (2).
/// - `search/t<N>.js`, the token files: the inverted index, tokens in UTF-16 order (the order
///   of JavaScript's `<`), cut in files of about [`SHARD_BYTES`]; each token
///   followed by its postings, `[token, posting…, token, posting…]`, each posting
///   `entry * 3 + group` (group 0 the name, 1 the identifiers, 2 the prose) as the difference
///   from the one before (a string starts the next token). A query token reads the
///   keys it is a prefix of, which lie in one file, or two.
/// - `search/b<N>.js`, one per prefix of `b`: a prefix whose keys lie in more than one token
///   file (`c`, `ti`: what one typed letter asks) has its best match per entry precomputed,
///   `entry * 6 + class` (class `group * 2`, plus one unless a key is the prefix itself) as
///   differences, so that a short query never downloads every token file it spans.
/// - `search/e<N>.js`: the meta line and summary of [`DETAILS_BLOCK`] entries.
/// - `search/p<N>.js` and `search/f<N>.js`: the port part ([`write_ports`]), for `in:`,
///   `out:`, `provides:`, `requires:` and `feeds:` queries: the types by the file of their
///   key, and each component's in-ports; `p` in the first file says how many `p` files.
///
/// Every file but the first is `RTCDOC_SHARD(kind, N, data);` (a `<script>` can load it from
/// `file://`, where `fetch()` is forbidden). The JSON is escaped so that no `<`, `>` or `&`
/// appears literally (a `</script>` in a profile cannot end a script element).
pub fn write_index(
    catalog: &Catalog,
    lang: Lang,
    emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    write_index_with(catalog, lang, INDEX_BATCH, emit)
}

/// [`write_index`] with the component entries made `batch` at a time.
fn write_index_with(
    catalog: &Catalog,
    lang: Lang,
    batch: usize,
    emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let mut inv = Inverted::default();
    let mut heads: Vec<serde_json::Value> = Vec::new();
    let mut details: Vec<serde_json::Value> = Vec::new();
    let mut block = 0usize;
    let mut dirs: std::collections::BTreeMap<&'static str, String> = Default::default();
    let mut add_entry = |e: Entry, emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>| {
        let n = heads.len() as u32;
        inv.add(n, &e.groups);
        // Each kind's folder is its first entry's (the pages of a kind share one).
        let dir = dirs.entry(e.kind).or_insert_with(|| {
            e.href
                .rsplit_once('/')
                .map_or(String::new(), |(d, _)| format!("{d}/"))
        });
        heads.push(serde_json::json!([
            e.kind,
            e.name,
            short_href(dir, &e.href)
        ]));
        details.push(serde_json::json!([e.meta, e.summary]));
        if details.len() == DETAILS_BLOCK {
            emit(
                &format!("search/e{block}.js"),
                shard_js(
                    "e",
                    block,
                    &serde_json::Value::Array(std::mem::take(&mut details)),
                ),
            )?;
            block += 1;
        }
        anyhow::Ok(())
    };
    // The component entries are built in parallel, a batch at a time, and added in catalogue
    // order; only one batch's text is held, never every entry's.
    let n = catalog.components.len();
    for start in (0..n).step_by(batch.max(1)) {
        let made: Vec<Entry> = (start..n.min(start.saturating_add(batch)))
            .into_par_iter()
            .map(|ci| component_entry(catalog, Ix::new(ci)))
            .collect();
        for e in made {
            add_entry(e, emit)?;
        }
    }
    for (ti, t) in Ix::enumerate(&catalog.data_types) {
        let page = catalog.data_type_page(ti).path("html");
        add_entry(
            idl_entry(catalog, "t", page, (&t.name, &t.spellings), lang),
            emit,
        )?;
    }
    for (ii, t) in Ix::enumerate(&catalog.interfaces) {
        let page = catalog.interface_page(ii).path("html");
        add_entry(
            idl_entry(catalog, "i", page, (&t.name, &t.spellings), lang),
            emit,
        )?;
    }
    for e in system_entries(catalog) {
        add_entry(e, emit)?;
    }
    if !details.is_empty() {
        emit(
            &format!("search/e{block}.js"),
            shard_js("e", block, &serde_json::Value::Array(details)),
        )?;
    }
    let (starts, prefixes) = inv.write(emit)?;
    let port_files = write_ports(catalog, emit)?;
    let kinds = serde_json::json!({
        "c": lang.t("component"),
        "t": lang.t("data_type"),
        "i": lang.t("interface"),
        "s": lang.t("system"),
        "in": lang.t("in"),
        "out": lang.t("out"),
        "provides": lang.t("provided"),
        "requires": lang.t("required"),
    });
    let first = serde_json::json!({
        "v": 2,
        "e": heads,
        "kinds": kinds,
        "s": starts,
        "b": prefixes,
        "d": DETAILS_BLOCK,
        "h": dirs,
        "p": port_files,
        "f": FEEDS_BLOCK,
    });
    let mut js = b"window.RTCDOC_INDEX=".to_vec();
    js.extend_from_slice(entry_js(&first).as_bytes());
    js.extend_from_slice(b";\n");
    emit("search-index.js", js)
}

/// `href` as the first file holds it: `x` for `DIR/x.html` where `DIR/` is `dir` (the
/// folder of the kind's pages, `h` in the first file) and `x` has no `/`; else `/` and the whole
/// `href` (never the start of a relative one).
fn short_href<'a>(dir: &str, href: &'a str) -> Cow<'a, str> {
    match href.strip_prefix(dir).and_then(|h| h.strip_suffix(".html")) {
        Some(h) if !dir.is_empty() && !h.contains('/') && !h.is_empty() => Cow::Borrowed(h),
        _ => Cow::Owned(format!("/{href}")),
    }
}

/// `RTCDOC_SHARD("kind",n,data);` with `data` escaped ([`entry_js`]).
fn shard_js(kind: &str, n: usize, data: &serde_json::Value) -> Vec<u8> {
    format!("RTCDOC_SHARD(\"{kind}\",{n},{});\n", entry_js(data)).into_bytes()
}

/// [`shard_js`] of the JSON array whose items' text is `items` (comma-separated), escaped.
fn shard_text(kind: &str, n: usize, items: &str) -> Vec<u8> {
    let mut out = format!("RTCDOC_SHARD(\"{kind}\",{n},[");
    push_js_safe_json(&mut out, items);
    out.push_str("]);\n");
    out.into_bytes()
}

/// The inverted index: each distinct token and its postings (`entry * 3 + group`, ascending:
/// entries are added in order, groups in order within an entry).
#[derive(Default)]
struct Inverted {
    /// Each distinct token and its position in `postings`.
    ids: std::collections::HashMap<Box<str>, u32>,
    postings: Vec<Postings>,
}

/// One token's postings, ascending, held as the differences from each to the next in LEB128
/// (most take one byte: at 10,000 profiles 1.5 million postings in about 2 MB instead of 6 MB
/// of `u32`s and as much again of spare capacity).
#[derive(Default)]
struct Postings {
    bytes: Vec<u8>,
    last: Option<u32>,
}

impl Postings {
    /// Adds `p`, not below the last one; the last one again is not added.
    fn push(&mut self, p: u32) {
        if self.last == Some(p) {
            return;
        }
        let mut d = p - self.last.unwrap_or(0);
        self.last = Some(p);
        loop {
            let low = (d & 0x7f) as u8;
            d >>= 7;
            if d == 0 {
                self.bytes.push(low);
                return;
            }
            self.bytes.push(low | 0x80);
        }
    }

    /// The differences: the first posting, then from each to the next.
    fn deltas(&self) -> impl Iterator<Item = u32> + '_ {
        let mut at = 0;
        std::iter::from_fn(move || {
            let mut v = 0u32;
            let mut shift = 0;
            loop {
                let b = *self.bytes.get(at)?;
                at += 1;
                v |= u32::from(b & 0x7f) << shift;
                shift += 7;
                if b & 0x80 == 0 {
                    return Some(v);
                }
            }
        })
    }

    /// The postings.
    fn values(&self) -> impl Iterator<Item = u32> + '_ {
        self.deltas().scan(0u32, |sum, d| {
            *sum += d;
            Some(*sum)
        })
    }
}

impl Inverted {
    /// Adds entry `n`'s tokens, `name|ids|text` ([`Groups::encode`]).
    fn add(&mut self, n: u32, groups: &str) {
        for (g, group) in groups.split('|').enumerate().take(3) {
            for t in group.split(' ').filter(|t| !t.is_empty()) {
                let id = match self.ids.get(t) {
                    Some(&id) => id,
                    None => {
                        let id = self.postings.len() as u32;
                        self.ids.insert(t.into(), id);
                        self.postings.push(Postings::default());
                        id
                    }
                };
                self.postings[id as usize].push(n * 3 + g as u32);
            }
        }
    }

    /// Writes the token files and the prefix files; returns the first token of each token
    /// file and the prefixes that have a file.
    fn write(
        self,
        emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>,
    ) -> anyhow::Result<(Vec<String>, Vec<String>)> {
        // The tokens sorted as the browser compares them, each with its postings' position.
        let mut by_token: Vec<(&str, u32)> = self.ids.iter().map(|(t, &i)| (&**t, i)).collect();
        by_token.sort_unstable_by(|a, b| utf16_cmp(a.0, b.0));
        let (sorted, order): (Vec<&str>, Vec<u32>) = by_token.into_iter().unzip();
        // Token files: consecutive tokens until one holds SHARD_BYTES, written as the JSON
        // array's text (`"token",d,d,"token",d`: a token is a JSON string, the rest numbers).
        let mut starts: Vec<String> = Vec::new();
        let mut cut: Vec<usize> = Vec::new();
        let mut body = String::new();
        for (k, &i) in order.iter().enumerate() {
            if body.is_empty() {
                starts.push(if k == 0 {
                    String::new()
                } else {
                    sorted[k].to_string()
                });
                cut.push(k);
            } else {
                body.push(',');
            }
            body.push_str(&serde_json::Value::from(sorted[k]).to_string());
            for d in self.postings[i as usize].deltas() {
                body.push(',');
                body.push_str(&d.to_string());
            }
            if body.len() >= SHARD_BYTES {
                let n = starts.len() - 1;
                emit(&format!("search/t{n}.js"), shard_text("t", n, &body))?;
                body.clear();
            }
        }
        if !body.is_empty() || starts.is_empty() {
            if starts.is_empty() {
                starts.push(String::new());
                cut.push(0);
            }
            let n = starts.len() - 1;
            emit(&format!("search/t{n}.js"), shard_text("t", n, &body))?;
        }
        // Prefixes whose keys lie in two files or more: the prefixes of the longest common
        // prefix of the tokens either side of each cut.
        let mut prefixes: Vec<&str> = Vec::new();
        for &k in cut.iter().skip(1) {
            let (a, b) = (sorted[k - 1], sorted[k]);
            let common: usize = a
                .chars()
                .zip(b.chars())
                .take_while(|(x, y)| x == y)
                .map(|(x, _)| x.len_utf8())
                .sum();
            let p = &b[..common];
            prefixes.extend(p.char_indices().map(|(i, c)| &p[..i + c.len_utf8()]));
        }
        prefixes.sort_unstable_by(|a, b| utf16_cmp(a, b));
        prefixes.dedup();
        let mut best: Vec<u8> = Vec::new();
        for (n, p) in prefixes.iter().enumerate() {
            let lo = sorted.partition_point(|t| utf16_cmp(t, p).is_lt());
            let hi = lo + sorted[lo..].partition_point(|t| t.starts_with(p));
            best.clear();
            for k in lo..hi {
                let exact = sorted[k].len() == p.len();
                for post in self.postings[order[k] as usize].values() {
                    let (e, g) = ((post / 3) as usize, (post % 3) as u8);
                    let class = g * 2 + u8::from(!exact);
                    if best.len() <= e {
                        best.resize(e + 1, u8::MAX);
                    }
                    best[e] = best[e].min(class);
                }
            }
            let list: Vec<u32> = best
                .iter()
                .enumerate()
                .filter(|(_, &c)| c != u8::MAX)
                .map(|(e, &c)| e as u32 * 6 + u32::from(c))
                .collect();
            emit(
                &format!("search/b{n}.js"),
                shard_js("b", n, &serde_json::json!(deltas(&list))),
            )?;
        }
        Ok((starts, prefixes.into_iter().map(String::from).collect()))
    }
}

/// Ascending numbers as the first and the differences from each to the next.
fn deltas(list: &[u32]) -> Vec<u32> {
    let mut prev = 0;
    list.iter()
        .map(|&p| {
            let d = p - prev;
            prev = p;
            d
        })
        .collect()
}

/// `a` and `b` compared as JavaScript compares strings: by UTF-16 code units.
fn utf16_cmp(a: &str, b: &str) -> std::cmp::Ordering {
    if a.is_ascii() && b.is_ascii() {
        return a.cmp(b);
    }
    a.encode_utf16().cmp(b.encode_utf16())
}

/// A port of the index's `ports` part: `[component, name]` when its anchor is the one
/// `search.js` makes from the name (`prefix`, then the name lower-cased with `_` and `.` as
/// `-`: `person_count` → `port-person-count`), else `[component, name, anchor]`.
fn port_js(component: usize, name: &str, prefix: &str, anchor: &str) -> serde_json::Value {
    let plain = name
        .bytes()
        .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'.');
    let derived = anchor.strip_prefix(prefix).is_some_and(|rest| {
        rest.len() == name.len()
            && rest.bytes().zip(name.bytes()).all(|(a, n)| {
                a == match n {
                    b'_' | b'.' => b'-',
                    n => n.to_ascii_lowercase(),
                }
            })
    });
    if plain && derived {
        serde_json::json!([component, name])
    } else {
        serde_json::json!([component, name, anchor])
    }
}

/// The key a type is found by in port queries, as `search.js` `portKey` makes it from a
/// query: lower-cased, without a leading `::`, the identifier after the last `:` (`RTC::TimedLong`
/// → `timedlong`), or, of a repository id, after the last `/` and before the version
/// (`IDL:RTC/TimedLong:1.0` → `timedlong`).
fn port_key(name: &str) -> String {
    let k = name.to_lowercase();
    let k = k.strip_prefix("::").unwrap_or(&k);
    let last = match k.strip_prefix("idl:") {
        Some(id) => {
            let id = id.rsplit_once(':').map_or(id, |(id, _version)| id);
            id.rsplit('/').next().unwrap_or(id)
        }
        None => k.rsplit(':').next().unwrap_or(k),
    };
    last.to_string()
}

/// The port file of `key`, of `files` (FNV-1a of its UTF-16 code units, as `search.js`
/// `portFile`).
fn port_bucket(key: &str, files: usize) -> usize {
    let mut h: u32 = 0x811c_9dc5;
    for u in key.encode_utf16() {
        h ^= u32::from(u);
        h = h.wrapping_mul(0x0100_0193);
    }
    h as usize % files.max(1)
}

/// Components per file of `search/f<N>.js` (`feeds:`): each component's in-ports.
const FEEDS_BLOCK: usize = 512;

/// Writes the port part of the index, for `in:`, `out:`, `provides:`, `requires:` and
/// `feeds:` queries; returns how many port files there are (`p` in the first file).
///
/// - `search/p<N>.js`: `{"d": [type…], "i": [interface…]}`, the types whose keys
///   ([`port_key`] of the name and of each spelling) [`port_bucket`] puts in file `N` (a type
///   in as many files as its keys have; about [`SHARD_BYTES`] per file). Each type is
///   `[name, [spelling…], [out-port…], [in-port…]]` and each interface
///   `[name, [spelling…], [provided…], [required…]]`, in [`Catalog::data_types`] /
///   [`Catalog::interfaces`] order, those with a port (an IDL-only type has none to list): one
///   entry per catalogue type, which already is the matching rule of the type pages (two
///   spellings, or a repository id and a scoped name, that the catalogue keys as one type are
///   one entry; [`crate::idl::IdlSet::canonical_name`]). The port lists are the entry's
///   producers and consumers (providers and requirers), each port `[component, name, anchor]`
///   ([`port_js`]: the anchor left out when `search.js` can make it): `component` is the
///   component's position in `e` (component entries come first, in catalogue order), `name`
///   the port's (`port.interface` for a service interface) and `anchor` its row on the
///   component page ([`crate::catalog::Anchors`]). The spellings are those met in the profiles
///   other than the name, plus the IDL repository id of the definition when the catalogue has
///   it.
/// - `search/k0.js`: every key, sorted: a query typed a key at a time reads a port file only
///   for a key the catalogue has.
/// - `search/f<N>.js`: for the [`FEEDS_BLOCK`] components from `N * FEEDS_BLOCK`, each one's
///   in-ports that have a type, `[name, port file of the type's name]`: `feeds:C.port` reads
///   the in-port's file, then its type's.
fn write_ports(
    catalog: &Catalog,
    emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>,
) -> anyhow::Result<usize> {
    write_ports_with(catalog, SHARD_BYTES, emit)
}

/// [`write_ports`] with about `shard` bytes per port file.
fn write_ports_with(
    catalog: &Catalog,
    shard: usize,
    emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>,
) -> anyhow::Result<usize> {
    let (items, fed) = port_items(catalog);
    let total: usize = items.iter().map(|(_, j, _)| j.len() + 1).sum();
    let files = total.div_ceil(shard.max(1)).max(1);
    let mut buckets: Vec<[String; 2]> = vec![Default::default(); files];
    for (data, json, keys) in &items {
        let mut at: Vec<usize> = keys.iter().map(|k| port_bucket(k, files)).collect();
        at.sort_unstable();
        at.dedup();
        for b in at {
            let list = &mut buckets[b][usize::from(!data)];
            if !list.is_empty() {
                list.push(',');
            }
            list.push_str(json);
        }
    }
    // Every key, once: a query whose key is none of them needs no port file.
    let mut all_keys: Vec<&str> = items
        .iter()
        .flat_map(|(_, _, keys)| keys.iter().map(String::as_str))
        .collect();
    all_keys.sort_unstable_by(|a, b| utf16_cmp(a, b));
    all_keys.dedup();
    emit(
        "search/k0.js",
        shard_js("k", 0, &serde_json::json!(all_keys)),
    )?;
    for (n, [d, i]) in buckets.iter().enumerate() {
        let text = format!("RTCDOC_SHARD(\"p\",{n},{{\"d\":[{d}],\"i\":[{i}]}});\n");
        emit(&format!("search/p{n}.js"), text.into_bytes())?;
    }
    write_feeds(catalog, &items, fed, files, emit)?;
    Ok(files)
}

/// A type of the port files: whether it is a data type, its JSON text, its keys.
type PortItem = (bool, String, Vec<String>);

/// Each type with ports (data types, then interfaces), and each typed in-port `(component,
/// port, its type's item)`.
fn port_items(catalog: &Catalog) -> (Vec<PortItem>, Vec<(ComponentIx, usize, usize)>) {
    // The name itself is matched as a spelling by `search.js`: not repeated.
    let spellings = |name: &str, met: &[String]| {
        let mut all: Vec<String> = met.iter().filter(|s| *s != name).cloned().collect();
        if let Some(item) = catalog.idl.find(name) {
            let id = item.definition.repository_id();
            if !id.is_empty() && !all.iter().any(|s| s == id) {
                all.push(id.to_string());
            }
        }
        all.sort();
        all
    };
    // A type as its JSON text, `[name, [spelling…], [port…], [port…]]`, and its keys.
    let item = |name: &String, names: Vec<String>, ports: [Vec<serde_json::Value>; 2]| {
        let keys: Vec<String> = std::iter::once(name)
            .chain(&names)
            .map(|n| port_key(n))
            .collect();
        let [a, b] = ports;
        (entry_js(&serde_json::json!([name, names, a, b])), keys)
    };
    // Each type as its JSON text and its keys; the in-ports of each data type, to list them
    // per component for `feeds:`.
    let mut items: Vec<PortItem> = Vec::new();
    let mut fed: Vec<(ComponentIx, usize, usize)> = Vec::new();
    for t in catalog
        .data_types
        .iter()
        .filter(|t| !t.uses.producers.is_empty() || !t.uses.consumers.is_empty())
    {
        let names = spellings(&t.name, &t.spellings);
        let port = |r: &crate::catalog::PortRef| {
            let (ci, pi) = catalog.resolve_port(r)?;
            let c = &catalog[ci];
            let name = c.profile.data_ports[pi].name.as_deref().unwrap_or("");
            Some(port_js(ci.get(), name, "port-", &c.anchors.data_ports[pi]))
        };
        let ports = |l: &[crate::catalog::PortRef]| -> Vec<serde_json::Value> {
            l.iter().filter_map(port).collect()
        };
        for r in &t.uses.consumers {
            if let Some((ci, pi)) = catalog.resolve_port(r) {
                fed.push((ci, pi, items.len()));
            }
        }
        let (json, keys) = item(
            &t.name,
            names,
            [ports(&t.uses.producers), ports(&t.uses.consumers)],
        );
        items.push((true, json, keys));
    }
    for t in catalog
        .interfaces
        .iter()
        .filter(|t| !t.uses.providers.is_empty() || !t.uses.requirers.is_empty())
    {
        let names = spellings(&t.name, &t.spellings);
        let port = |r: &crate::catalog::InterfaceRef| {
            let (ci, pi, ii) = catalog.resolve_interface(r)?;
            let c = &catalog[ci];
            let sp = &c.profile.service_ports[pi];
            let name = format!(
                "{}.{}",
                sp.name.as_deref().unwrap_or(""),
                sp.interfaces[ii].name.as_deref().unwrap_or("")
            );
            Some(port_js(
                ci.get(),
                &name,
                "if-",
                &c.anchors.interfaces[pi][ii],
            ))
        };
        let ports = |l: &[crate::catalog::InterfaceRef]| -> Vec<serde_json::Value> {
            l.iter().filter_map(port).collect()
        };
        let (json, keys) = item(
            &t.name,
            names,
            [ports(&t.uses.providers), ports(&t.uses.requirers)],
        );
        items.push((false, json, keys));
    }
    (items, fed)
}

/// `search/f<N>.js`: each component's typed in-ports (`fed`, from [`port_items`]), in port
/// order, [`FEEDS_BLOCK`] components per file, each port with the port file of its type's name.
fn write_feeds(
    catalog: &Catalog,
    items: &[PortItem],
    mut fed: Vec<(ComponentIx, usize, usize)>,
    files: usize,
    emit: &mut dyn FnMut(&str, Vec<u8>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    // feeds: each component's typed in-ports, in port order, a block of components per file.
    fed.sort_unstable();
    let mut per: Vec<Vec<serde_json::Value>> = vec![Vec::new(); catalog.components.len()];
    for (ci, pi, item) in fed {
        let name = catalog[ci].profile.data_ports[pi]
            .name
            .as_deref()
            .unwrap_or("");
        per[ci.get()].push(serde_json::json!([
            name,
            port_bucket(&items[item].2[0], files)
        ]));
    }
    for (n, block) in per.chunks(FEEDS_BLOCK).enumerate() {
        emit(
            &format!("search/f{n}.js"),
            shard_js("f", n, &serde_json::json!(block)),
        )?;
    }
    Ok(())
}

/// Component entries of the search index made and written per batch by [`index_js`].
const INDEX_BATCH: usize = 1024;

/// One entry as JSON, escaped ([`push_js_safe_json`]: escaping works character by character,
/// so escaping each entry is escaping the whole).
fn entry_js(entry: &serde_json::Value) -> String {
    let json = serde_json::to_string(entry).unwrap_or_else(|_| "null".into());
    let mut out = String::with_capacity(json.len());
    push_js_safe_json(&mut out, &json);
    out
}

/// The search entry of component `ci`.
fn component_entry(catalog: &Catalog, ci: ComponentIx) -> Entry {
    let c = &catalog[ci];
    let p = &c.profile;
    let b = &p.basic_info;
    // Canonical type names are made first: tokens borrow from them.
    let types: Vec<String> = p
        .port_types()
        .filter_map(|t| non_empty(t).map(canonical_type))
        .collect();
    let mut g = Groups::default();
    add(&mut g.name, Some(p.name()));
    add(&mut g.name, c.qualifier.as_deref());
    add(&mut g.text, non_empty(&b.category));
    add(&mut g.text, non_empty(&b.vendor));
    // The `[[source]]` it was read from: searching its name finds its components.
    let source = c.origin.as_ref().map(|o| o.source.as_str());
    add(&mut g.text, source);
    add(&mut g.text, non_empty(&b.description));
    // Everything else the page shows as prose: the abstract (for many RTCBuilder users the
    // only Japanese summary), the Document Profile, the comment, the lifecycle's documentation.
    add(&mut g.text, non_empty(&b.abstract_));
    add(&mut g.text, non_empty(&b.comment));
    if let Some(d) = &b.doc {
        for t in [
            &d.description,
            &d.inout,
            &d.algorithm,
            &d.creator,
            &d.license,
            &d.reference,
        ] {
            add(&mut g.text, non_empty(t));
        }
    }
    for a in &p.actions {
        if let Some(doc) = &a.doc {
            for t in [&doc.description, &doc.pre_condition, &doc.post_condition] {
                add(&mut g.text, non_empty(t));
            }
        }
    }
    for d in &p.data_ports {
        let doc = d.doc.as_ref().and_then(|doc| non_empty(&doc.description));
        g.item(non_empty(&d.name), doc);
        for e in &d.events {
            add(&mut g.ids, non_empty(&e.name));
        }
    }
    for s in &p.service_ports {
        let doc = s.doc.as_ref().and_then(|doc| non_empty(&doc.description));
        g.item(non_empty(&s.name), doc);
        for i in &s.interfaces {
            let doc = i.doc.as_ref().and_then(|doc| non_empty(&doc.description));
            g.item(non_empty(&i.name), doc);
        }
    }
    for t in &types {
        add(&mut g.ids, Some(t));
    }
    for conf in p.configurations() {
        let doc = conf
            .doc
            .as_ref()
            .and_then(|doc| non_empty(&doc.description));
        g.item(non_empty(&conf.name), doc);
    }
    // RTCBuilder's placeholders (`ModuleDescription`, `Category`) are no summary or meta.
    let summary = documented("description", &b.description)
        .map(|d| super::markdown::first_line(d, 90))
        .unwrap_or_default();
    let meta = [
        documented("category", &b.category),
        documented("vendor", &b.vendor),
        source,
    ]
    .into_iter()
    .flatten()
    .collect::<Vec<_>>()
    .join(" · ");
    Entry {
        kind: "c",
        name: c.display_name().into_owned(),
        href: catalog.component_page(ci).path("html"),
        meta,
        summary,
        groups: g.encode(),
    }
}

/// The search entry of a data type (`kind` `t`) or interface (`i`): its spellings, and from
/// its IDL definition (when the catalogue has it) field, value, operation, parameter and
/// attribute names and their documentation.
fn idl_entry(
    catalog: &Catalog,
    kind: &'static str,
    href: String,
    (name, spellings): (&str, &[String]),
    lang: Lang,
) -> Entry {
    let def = crate::render::idl_view::definition(catalog, name, lang);
    let mut g = Groups::default();
    add(&mut g.name, Some(name));
    for s in spellings {
        add(&mut g.ids, Some(s));
    }
    let mut summary = String::new();
    if let Some(d) = &def {
        add(&mut g.text, Some(&d.brief));
        add(&mut g.text, Some(&d.details));
        for f in &d.fields {
            g.item(Some(&f.name), Some(&f.doc));
        }
        for v in &d.values {
            g.item(Some(&v.name), Some(&v.doc));
        }
        for o in &d.operations {
            g.item(Some(&o.name), Some(&o.doc));
            for p in &o.params {
                add(&mut g.ids, Some(&p.name));
            }
        }
        for a in &d.attributes {
            g.item(Some(&a.name), Some(&a.doc));
        }
        summary = super::markdown::first_line(&d.brief, 90);
    }
    let meta = def
        .as_ref()
        .map(|d| format!("{} · {}", d.kind, d.file))
        .unwrap_or_default();
    Entry {
        kind,
        name: name.to_string(),
        href,
        meta,
        summary,
        groups: g.encode(),
    }
}

/// One entry per RT System (`kind` `s`): its name; the instance and component names, the
/// connected ports and their data types; the vendor, comment and abstract as text.
fn system_entries(catalog: &Catalog) -> Vec<Entry> {
    Ix::enumerate(&catalog.systems)
        .map(|(si, s)| {
            let p = &s.profile;
            let vendor = p
                .id_parts
                .as_ref()
                .and_then(|x| non_empty(&x.vendor))
                .unwrap_or("");
            let types: Vec<String> = p
                .data_port_connectors
                .iter()
                .filter_map(|c| non_empty(&c.data_type).map(canonical_type))
                .collect();
            let mut g = Groups::default();
            add(&mut g.name, Some(p.name()));
            add(&mut g.text, Some(vendor));
            add(&mut g.text, non_empty(&p.comment));
            add(&mut g.text, non_empty(&p.abstract_));
            for c in &p.components {
                add(&mut g.ids, non_empty(&c.instance_name));
                add(
                    &mut g.ids,
                    c.id_parts.as_ref().and_then(|x| non_empty(&x.name)),
                );
            }
            for c in &p.data_port_connectors {
                for e in [&c.source, &c.target].into_iter().flatten() {
                    add(&mut g.ids, non_empty(&e.short_name));
                }
            }
            for t in &types {
                add(&mut g.ids, Some(t));
            }
            let summary = non_empty(&p.comment)
                .or_else(|| non_empty(&p.abstract_))
                .map(|d| super::markdown::first_line(d, 90))
                .unwrap_or_default();
            Entry {
                kind: "s",
                name: p.name().to_string(),
                href: catalog.system_page(si).path("html"),
                meta: vendor.to_string(),
                summary,
                groups: g.encode(),
            }
        })
        .collect()
}

/// Escapes characters that could end a script element or break a JS string literal. They only
/// occur inside JSON strings, where `\uXXXX` means the same character.
pub fn js_safe_json(json: &str) -> String {
    let mut out = String::with_capacity(json.len());
    push_js_safe_json(&mut out, json);
    out
}

/// [`js_safe_json`] appended to `out`.
fn push_js_safe_json(out: &mut String, json: &str) {
    // Runs with nothing to escape are copied whole. Every byte escaped starts a character
    // (`<`, `>`, `&`, or E2 80 A8 / A9 for U+2028 / U+2029), so each cut is at a boundary.
    let b = json.as_bytes();
    let (mut copied, mut i) = (0, 0);
    while i < b.len() {
        let (escape, len) = match (b[i], b.get(i + 1..i + 3)) {
            (b'<', _) => ("\\u003c", 1),
            (b'>', _) => ("\\u003e", 1),
            (b'&', _) => ("\\u0026", 1),
            (0xE2, Some([0x80, 0xA8])) => ("\\u2028", 3),
            (0xE2, Some([0x80, 0xA9])) => ("\\u2029", 3),
            _ => {
                i += 1;
                continue;
            }
        };
        out.push_str(&json[copied..i]);
        out.push_str(escape);
        i += len;
        copied = i;
    }
    out.push_str(&json[copied..]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    /// The first implementation (one `String` per word and part), kept as the oracle.
    fn reference(text: &str, out: &mut BTreeSet<String>) {
        let mut word: Vec<char> = Vec::new();
        let mut cjk: Vec<char> = Vec::new();
        let flush_word = |word: &mut Vec<char>, out: &mut BTreeSet<String>| {
            if word.is_empty() {
                return;
            }
            let w: String = word.iter().collect();
            out.insert(w.to_lowercase());
            // camelCase / digit boundaries: UsbCamera → usb, camera.
            let mut part = String::new();
            let mut prev: Option<char> = None;
            let mut parts = Vec::new();
            for &c in word.iter() {
                if let Some(p) = prev {
                    let boundary = (p.is_lowercase() && c.is_uppercase())
                        || (p.is_alphabetic() && c.is_ascii_digit())
                        || (p.is_ascii_digit() && c.is_alphabetic());
                    if boundary && !part.is_empty() {
                        parts.push(std::mem::take(&mut part));
                    }
                }
                part.push(c);
                prev = Some(c);
            }
            if !part.is_empty() {
                parts.push(part);
            }
            if parts.len() > 1 {
                for p in parts {
                    out.insert(p.to_lowercase());
                }
            }
            word.clear();
        };
        let flush_cjk = |cjk: &mut Vec<char>, out: &mut BTreeSet<String>| {
            match cjk.len() {
                0 => {}
                1 => {
                    out.insert(cjk[0].to_string());
                }
                _ => {
                    for w in cjk.windows(2) {
                        out.insert(w.iter().collect());
                    }
                }
            }
            cjk.clear();
        };
        for c in text.chars() {
            if is_cjk(c) {
                flush_word(&mut word, out);
                cjk.push(c);
            } else if c.is_alphanumeric() || c == '_' {
                flush_cjk(&mut cjk, out);
                word.push(c);
            } else {
                flush_word(&mut word, out);
                flush_cjk(&mut cjk, out);
            }
        }
        flush_word(&mut word, out);
        flush_cjk(&mut cjk, out);
    }

    /// The slice-based tokenizer gives exactly the tokens of the reference.
    #[test]
    fn tokenize_matches_the_reference() {
        const PARTS: &[&str] = &[
            "Usb",
            "camera",
            "RTC",
            "::",
            "Timed",
            "Long2",
            "x86",
            "_",
            " ",
            "-",
            "画像",
            "を",
            "カメラ",
            "İ",
            "ΟΔΟΣ",
            "Σ",
            "ß",
            "é",
            "3D",
            "a1b2",
            "\u{1F600}",
            "ｶ",
        ];
        let fast = |text: &str| {
            let mut tokens = Vec::new();
            tokenize(text, &mut tokens);
            tokens
                .into_iter()
                .map(Cow::into_owned)
                .collect::<BTreeSet<String>>()
        };
        let slow = |text: &str| {
            let mut set = BTreeSet::new();
            reference(text, &mut set);
            set
        };
        crate::test_text::agrees((PARTS, 12, Some(2048)), &["3D"], fast, slow);
    }

    /// Full- and half-width forms are indexed as their usual ones (as `search.js` reads a
    /// query), and text already in NFKC is not copied.
    #[test]
    fn width_forms_are_indexed_in_nfkc() {
        let mut t = Vec::new();
        add(&mut t, Some("Ｋｏｂｕｋｉ の ｶﾒﾗ"));
        let set: BTreeSet<String> = t.into_iter().map(Cow::into_owned).collect();
        for want in ["kobuki", "カメ", "メラ", "の"] {
            assert!(set.contains(want), "{want} in {set:?}");
        }
        assert!(matches!(
            nfkc(Cow::Borrowed("画像を取得 RTC")),
            Cow::Borrowed(_)
        ));
    }

    fn toks(s: &str) -> Vec<String> {
        let mut t = Vec::new();
        tokenize(s, &mut t);
        let set: BTreeSet<String> = t.into_iter().map(Cow::into_owned).collect();
        set.into_iter().collect()
    }

    #[test]
    fn latin_words_and_camel_case() {
        assert_eq!(
            toks("UsbCamera RTC::TimedLong"),
            [
                "camera",
                "long",
                "rtc",
                "timed",
                "timedlong",
                "usb",
                "usbcamera"
            ]
        );
    }

    #[test]
    fn japanese_bigrams() {
        assert_eq!(toks("画像処理"), ["像処", "処理", "画像"]);
        assert_eq!(toks("地図 を"), ["を", "地図"]);
        assert_eq!(toks("カメラ画像"), ["カメ", "メラ", "ラ画", "画像"]);
    }

    /// The index's files, by path.
    /// The catalogue of `examples/`.
    fn example_catalog() -> Catalog {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let opts = crate::build::LoadOptions::default();
        crate::build::load(&root.join("examples"), &opts)
            .unwrap()
            .catalog
    }

    fn index_files(cat: &Catalog, batch: usize) -> std::collections::BTreeMap<String, String> {
        let mut files = std::collections::BTreeMap::new();
        write_index_with(cat, Lang::En, batch, &mut |path, bytes| {
            let text = String::from_utf8(bytes)?;
            assert!(
                files.insert(path.to_string(), text).is_none(),
                "{path} twice"
            );
            Ok(())
        })
        .unwrap();
        files
    }

    /// The data of `RTCDOC_SHARD(kind, n, data);`.
    fn shard_data(text: &str) -> serde_json::Value {
        let json = text
            .strip_prefix("RTCDOC_SHARD(")
            .and_then(|t| t.strip_suffix(");\n"))
            .and_then(|t| t.splitn(3, ',').nth(2))
            .unwrap();
        serde_json::from_str(json).unwrap()
    }

    #[test]
    fn the_index_is_the_same_whatever_the_batch() {
        let cat = example_catalog();
        let n = cat.components.len();
        assert!(n > 3, "examples/ has {n} components");
        // One batch holding every entry: the index as it was made before it was streamed.
        let whole = index_files(&cat, usize::MAX);
        for batch in [1, 2, 3, n - 1, INDEX_BATCH] {
            assert_eq!(index_files(&cat, batch), whole, "batches of {batch}");
        }
        let json = whole["search-index.js"]
            .strip_prefix("window.RTCDOC_INDEX=")
            .and_then(|j| j.strip_suffix(";\n"))
            .unwrap();
        let v: serde_json::Value = serde_json::from_str(json).unwrap();
        let e = v["e"].as_array().unwrap();
        let entries = n + cat.data_types.len() + cat.interfaces.len() + cat.systems.len();
        assert_eq!(e.len(), entries);
        // Component entries first, in catalogue order.
        for (ci, c) in cat.components.iter().enumerate() {
            assert_eq!(e[ci][0], "c");
            assert_eq!(e[ci][1], c.display_name().as_ref(), "entry {ci}");
        }
        assert_eq!(v["kinds"]["c"], Lang::En.t("component"));
        // One details file per DETAILS_BLOCK entries, each with its meta and summary.
        let blocks = entries.div_ceil(DETAILS_BLOCK);
        let details: Vec<&String> = whole
            .iter()
            .filter(|(p, _)| p.starts_with("search/e"))
            .map(|(_, t)| t)
            .collect();
        assert_eq!(details.len(), blocks);
        let first = shard_data(&whole["search/e0.js"]);
        assert_eq!(first.as_array().unwrap().len(), entries.min(DETAILS_BLOCK));
        // A token file per entry of `s`; every posting names an entry.
        let starts = v["s"].as_array().unwrap();
        for i in 0..starts.len() {
            let t = shard_data(&whole[&format!("search/t{i}.js")]);
            let mut post = 0;
            for item in t.as_array().unwrap() {
                match item.as_u64() {
                    Some(d) => {
                        post += d;
                        assert!((post as usize) / 3 < entries, "{item}");
                    }
                    None => post = 0,
                }
            }
        }
        assert!(whole.contains_key("search/p0.js") && whole.contains_key("search/f0.js"));
        assert_eq!(v["p"], 1, "the example's ports fit one file");
    }

    #[test]
    fn port_keys_are_the_last_identifier() {
        for (name, key) in [
            ("RTC::TimedLong", "timedlong"),
            ("::RTC::TimedLong", "timedlong"),
            ("TimedLong", "timedlong"),
            ("IDL:RTC/TimedLong:1.0", "timedlong"),
            ("IDL:omg.org/RTC/TimedLong:1.0", "timedlong"),
            ("IDL:TimedLong:1.0", "timedlong"),
            ("IDL:RTC/TimedLong", "timedlong"),
            ("", ""),
        ] {
            assert_eq!(port_key(name), key, "{name}");
        }
        // FNV-1a 32 of the UTF-16 code units ("a": 0xe40c292c, as search.js computes it).
        assert_eq!(port_bucket("a", usize::MAX), 0xe40c_292c);
        assert_eq!(port_bucket("", 7), 0x811c_9dc5 % 7);
        assert_eq!(port_bucket("x", 0), 0);
    }

    /// With small port files: each type is in the file of each of its keys, and once in it;
    /// each component's in-ports in `f` name a port file holding a type that lists the port.
    #[test]
    fn each_type_is_in_the_port_file_of_each_key() {
        let cat = example_catalog();
        let mut files = std::collections::BTreeMap::new();
        let n = write_ports_with(&cat, 256, &mut |path, bytes| {
            files.insert(path.to_string(), shard_data(&String::from_utf8(bytes)?));
            Ok(())
        })
        .unwrap();
        assert!(n > 3, "{n} port files");
        let mut seen = 0;
        for (b, part) in (0..n).map(|b| (b, &files[&format!("search/p{b}.js")])) {
            for t in part["d"]
                .as_array()
                .unwrap()
                .iter()
                .chain(part["i"].as_array().unwrap())
            {
                let names = std::iter::once(&t[0]).chain(t[1].as_array().unwrap());
                let keys: Vec<usize> = names
                    .map(|s| port_bucket(&port_key(s.as_str().unwrap()), n))
                    .collect();
                assert!(keys.contains(&b), "{t} in p{b}, not a file of its keys");
                let listed = files["search/k0.js"].as_array().unwrap();
                for name in std::iter::once(&t[0]).chain(t[1].as_array().unwrap()) {
                    let key = serde_json::json!(port_key(name.as_str().unwrap()));
                    assert!(listed.contains(&key), "{key} in k0");
                }
                for k in keys {
                    let other = &files[&format!("search/p{k}.js")];
                    let kind = if part["d"].as_array().unwrap().contains(t) {
                        "d"
                    } else {
                        "i"
                    };
                    let here = other[kind].as_array().unwrap().iter().filter(|o| *o == t);
                    assert_eq!(here.count(), 1, "{t} once in p{k}");
                }
                seen += 1;
            }
        }
        assert!(
            seen >= cat
                .data_types
                .iter()
                .filter(|t| !t.uses.consumers.is_empty())
                .count()
        );
        let feeds = &files["search/f0.js"];
        let mut typed = 0;
        for (ci, ports) in feeds.as_array().unwrap().iter().enumerate() {
            for p in ports.as_array().unwrap() {
                let (name, b) = (p[0].clone(), p[1].as_u64().unwrap());
                let part = &files[&format!("search/p{b}.js")];
                let lists = part["d"].as_array().unwrap().iter().any(|t| {
                    t[3].as_array()
                        .unwrap()
                        .iter()
                        .any(|q| q[0] == ci && q[1] == name)
                });
                assert!(lists, "component {ci} in-port {name}: not in p{b}");
                typed += 1;
            }
        }
        assert!(typed > 3, "{typed} typed in-ports");
        assert_eq!(feeds.as_array().unwrap().len(), cat.components.len());
    }

    /// Postings of the small token files: the keys of a short prefix span several files, so it
    /// has a file of its own, whose best match per entry is the best of its keys'.
    #[test]
    fn a_prefix_whose_keys_span_files_has_its_own() {
        let mut inv = Inverted::default();
        // 3,000 entries with tokens under `ca`, enough to fill several token files.
        for n in 0..3000u32 {
            inv.add(n, &format!("cat{n:04}|camera{n:04} ca|"));
        }
        inv.add(3000, "ca|dog|");
        let mut files = std::collections::BTreeMap::new();
        let (starts, prefixes) = inv
            .write(&mut |path, bytes| {
                files.insert(path.to_string(), String::from_utf8(bytes)?);
                Ok(())
            })
            .unwrap();
        assert!(starts.len() > 2, "{starts:?}");
        for p in ["c", "ca"] {
            assert!(prefixes.iter().any(|x| x == p), "{p} in {prefixes:?}");
        }
        let at = prefixes.iter().position(|x| x == "ca").unwrap();
        let list: Vec<u64> = shard_data(&files[&format!("search/b{at}.js")])
            .as_array()
            .unwrap()
            .iter()
            .scan(0, |s, d| {
                *s += d.as_u64().unwrap();
                Some(*s)
            })
            .collect();
        // Every entry once: 0..3000 by a prefix of their name (class 1), 3000 by its exact name
        // (class 0); the exact `ca` among the identifiers of 0..3000 ranks below a name prefix.
        assert_eq!(list.len(), 3001);
        assert_eq!(list[0], 1);
        assert_eq!(list[1], 6 + 1);
        assert_eq!(list[3000], 3000 * 6);
    }

    proptest::proptest! {
        /// Postings read back are those added, ascending, each once, whatever their size.
        #[test]
        fn postings_read_back(mut list in proptest::collection::vec(0u32..=u32::MAX, 0..64)) {
            list.sort_unstable();
            let mut p = Postings::default();
            for &v in &list {
                p.push(v);
                p.push(v);
            }
            list.dedup();
            proptest::prop_assert_eq!(p.values().collect::<Vec<_>>(), list.clone());
            proptest::prop_assert_eq!(p.deltas().collect::<Vec<_>>(), deltas(&list));
        }

        /// Escaping byte runs gives what escaping character by character gives (E2 starts
        /// U+2028 and U+2029, and also `…` and `→`, which stay).
        #[test]
        fn js_escaping_matches_the_reference(s in "[<>&a\u{2026}\u{2028}\u{2029}\u{2192}é日\"]{0,24}") {
            let reference: String = s
                .chars()
                .map(|c| match c {
                    '<' => "\\u003c".to_string(),
                    '>' => "\\u003e".to_string(),
                    '&' => "\\u0026".to_string(),
                    '\u{2028}' => "\\u2028".to_string(),
                    '\u{2029}' => "\\u2029".to_string(),
                    c => c.to_string(),
                })
                .collect();
            proptest::prop_assert_eq!(js_safe_json(&s), reference);
        }
    }

    #[test]
    fn script_cannot_break_out() {
        let s = js_safe_json(r#"["</script><script>alert(1)</script>"]"#);
        assert!(!s.contains('<') && !s.contains('>'));
    }
}
