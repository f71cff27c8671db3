//! The client-side search index, built once at build time.
//!
//! `search-index.js` assigns one array to `window.RTCDOC_INDEX`; loading it with a `<script>`
//! tag works from `file://` (where `fetch()` is forbidden). Each entry is
//! `[name, slug, category, vendor, summary, tokens]`; `tokens` is a space-separated, de-duplicated
//! list of lower-case words from the name, description, port, interface and parameter names,
//! data and interface types, category and vendor. Latin words are also split at camelCase and
//! `::` boundaries; runs of CJK characters become overlapping bigrams (a lone character stays a
//! unigram), so Japanese text needs no dictionary. `search.js` tokenizes queries the same way
//! and matches each query token as a prefix of some entry token.

use crate::catalog::Catalog;
use crate::model::non_empty;
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
    // Start of the current word or CJK run (byte offset), and which of the two it is.
    let mut start: Option<(usize, bool)> = None;
    for (i, c) in text.char_indices() {
        let class = if is_cjk(c) {
            Some(true)
        } else if c.is_alphanumeric() || c == '_' {
            Some(false)
        } else {
            None
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
    // camelCase / digit boundaries: UsbCamera → usb, camera (only when there are two parts
    // or more).
    let mut part_start = 0;
    let mut prev: Option<char> = None;
    for (i, c) in run.char_indices() {
        if let Some(p) = prev {
            let boundary = (p.is_lowercase() && c.is_uppercase())
                || (p.is_alphabetic() && c.is_ascii_digit())
                || (p.is_ascii_digit() && c.is_alphabetic());
            if boundary {
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

/// Tokenizes the first [`MAX_DESCRIPTION`] characters of `s`.
fn add<'a>(tokens: &mut Vec<Cow<'a, str>>, s: Option<&'a str>) {
    if let Some(s) = s {
        let end = s
            .char_indices()
            .nth(MAX_DESCRIPTION)
            .map_or(s.len(), |(i, _)| i);
        tokenize(&s[..end], tokens);
    }
}

/// Longest description text indexed per component, in characters (keeps entries small).
const MAX_DESCRIPTION: usize = 400;

/// Builds the contents of `search-index.js`. The JSON is escaped so that no `<`, `>` or `&`
/// appears literally (a `</script>` in a profile cannot end a script element).
pub fn index_js(catalog: &Catalog) -> String {
    // Entries are built in parallel; the indexed collect keeps catalogue order.
    let entries: Vec<serde_json::Value> = catalog
        .components
        .par_iter()
        .map(|c| {
            let p = &c.profile;
            let b = &p.basic_info;
            // Canonical type names are made first: tokens borrow from them.
            let types: Vec<String> = p
                .port_types()
                .filter_map(|t| non_empty(t).map(canonical_type))
                .collect();
            let mut tokens: Vec<Cow<'_, str>> = Vec::new();
            add(&mut tokens, Some(p.name()));
            add(&mut tokens, c.qualifier.as_deref());
            add(&mut tokens, non_empty(&b.category));
            add(&mut tokens, non_empty(&b.vendor));
            add(&mut tokens, non_empty(&b.description));
            if let Some(d) = &b.doc {
                add(&mut tokens, non_empty(&d.description));
            }
            for d in &p.data_ports {
                add(&mut tokens, non_empty(&d.name));
                for e in &d.events {
                    add(&mut tokens, non_empty(&e.name));
                }
            }
            for s in &p.service_ports {
                add(&mut tokens, non_empty(&s.name));
                for i in &s.interfaces {
                    add(&mut tokens, non_empty(&i.name));
                }
            }
            for t in &types {
                add(&mut tokens, Some(t));
            }
            for conf in p.configurations() {
                add(&mut tokens, non_empty(&conf.name));
            }
            tokens.sort_unstable();
            tokens.dedup();
            let summary = non_empty(&b.description)
                .map(|d| super::markdown::first_line(d, 90))
                .unwrap_or_default();
            serde_json::json!([
                c.display_name(),
                c.slug,
                non_empty(&b.category).unwrap_or(""),
                non_empty(&b.vendor).unwrap_or(""),
                summary,
                tokens.join(" "),
            ])
        })
        .collect();
    let mut entries = entries;
    entries.extend(system_entries(catalog));
    let json = serde_json::to_string(&entries).unwrap_or_else(|_| "[]".into());
    // 10,000 components make megabytes of each: not all three at once.
    drop(entries);
    let mut out = String::with_capacity(json.len() + 64);
    out.push_str("window.RTCDOC_INDEX=");
    push_js_safe_json(&mut out, &json);
    out.push_str(";\n");
    out
}

/// One entry per RT System, after the components: `[name, slug, "RT System", vendor, comment,
/// tokens, path]` — the seventh element, the page path, tells `search.js` it is not a component.
/// Tokens: the system's name, vendor, comment, instance names, component names, port names of
/// the connectors and their data types.
fn system_entries(catalog: &Catalog) -> Vec<serde_json::Value> {
    catalog
        .systems
        .iter()
        .map(|s| {
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
            let mut tokens: Vec<Cow<'_, str>> = Vec::new();
            add(&mut tokens, Some(p.name()));
            add(&mut tokens, Some(vendor));
            add(&mut tokens, non_empty(&p.comment));
            add(&mut tokens, non_empty(&p.abstract_));
            for c in &p.components {
                add(&mut tokens, non_empty(&c.instance_name));
                add(
                    &mut tokens,
                    c.id_parts.as_ref().and_then(|x| non_empty(&x.name)),
                );
            }
            for c in &p.data_port_connectors {
                for e in [&c.source, &c.target].into_iter().flatten() {
                    add(&mut tokens, non_empty(&e.short_name));
                }
            }
            for t in &types {
                add(&mut tokens, Some(t));
            }
            tokens.push(Cow::Borrowed("system"));
            tokens.sort_unstable();
            tokens.dedup();
            let summary = non_empty(&p.comment)
                .or_else(|| non_empty(&p.abstract_))
                .map(|d| super::markdown::first_line(d, 90))
                .unwrap_or_default();
            serde_json::json!([
                p.name(),
                s.slug,
                "RT System",
                vendor,
                summary,
                tokens.join(" "),
                super::systems::system_path(catalog, s),
            ])
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
    for ch in json.chars() {
        match ch {
            '<' => out.push_str("\\u003c"),
            '>' => out.push_str("\\u003e"),
            '&' => out.push_str("\\u0026"),
            '\u{2028}' => out.push_str("\\u2028"),
            '\u{2029}' => out.push_str("\\u2029"),
            c => out.push(c),
        }
    }
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

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 2048, ..Default::default() })]
        /// The slice-based tokenizer gives exactly the tokens of the reference.
        #[test]
        fn tokenize_matches_the_reference(
            parts in proptest::collection::vec(
                proptest::sample::select(&[
                    "Usb", "camera", "RTC", "::", "Timed", "Long2", "x86", "_", " ", "-", "画像",
                    "を", "カメラ", "İ", "ΟΔΟΣ", "Σ", "ß", "é", "3D", "a1b2", "\u{1F600}", "ｶ",
                ][..]),
                0..12,
            ),
        ) {
            let text = parts.concat();
            let mut tokens = Vec::new();
            tokenize(&text, &mut tokens);
            let fast: BTreeSet<String> = tokens.into_iter().map(Cow::into_owned).collect();
            let mut slow = BTreeSet::new();
            reference(&text, &mut slow);
            proptest::prop_assert_eq!(fast, slow, "{:?}", text);
        }
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

    #[test]
    fn script_cannot_break_out() {
        let s = js_safe_json(r#"["</script><script>alert(1)</script>"]"#);
        assert!(!s.contains('<') && !s.contains('>'));
    }
}
