//! Word-level differences of long text values (descriptions, documentation): what a change
//! message shows instead of both texts in full. A text is long past [`LONG`] characters or
//! when it holds a line break (RTCBuilder's `<br/>` counts as one, as the component page
//! breaks the line there, [`crate::model::prose`]).
//!
//! The texts are split into words (runs of letters and digits), runs of white space, and every
//! other character on its own (so a Japanese text, which has no spaces, is compared character
//! by character); the pieces are matched with Myers' algorithm (the `similar` crate), after the
//! common start and end are set aside. Long unchanged runs keep [`CONTEXT`] words each side.

use std::borrow::Cow;

/// A text longer than this many characters is long.
pub const LONG: usize = 80;

/// Words of context kept on each side of a change; an unchanged run longer than twice this is
/// cut to its ends around an ellipsis.
pub const CONTEXT: usize = 6;

/// Most words of the changed middle (after the common start and end) matched word by word;
/// a longer middle is shown as deleted and inserted whole (the matching is quadratic at worst).
const MAX_TOKENS: usize = 4000;

/// One piece of a word-level difference.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Piece {
    /// Text both sides have.
    Same(String),
    /// Text only the old side has.
    Deleted(String),
    /// Text only the new side has.
    Inserted(String),
    /// Unchanged text left out (shown as `…`).
    Elided,
}

/// Whether a text value is long (a word-level difference shows its change).
pub fn is_long(s: &str) -> bool {
    let s = crate::model::prose(s);
    s.contains('\n') || s.chars().count() > LONG
}

/// Whether a change from `old` to `new` is shown word by word: either side is long.
pub fn applies(old: Option<&str>, new: Option<&str>) -> bool {
    old.is_some_and(is_long) || new.is_some_and(is_long)
}

/// The text as it reads: RTCBuilder's `<br/>` a line break, `\r\n` a `\n`.
fn readable(s: &str) -> Cow<'_, str> {
    let s = crate::model::prose(s);
    if s.contains('\r') {
        Cow::Owned(s.replace("\r\n", "\n").replace('\r', "\n"))
    } else {
        s
    }
}

/// The words of `s` (see the module's documentation).
fn tokens(s: &str) -> Vec<&str> {
    #[derive(PartialEq)]
    enum Class {
        Word,
        Space,
        Other,
    }
    let class = |c: char| {
        if c.is_whitespace() {
            Class::Space
        } else if c.is_alphanumeric() && (c.is_ascii() || c.len_utf8() <= 2) || c == '_' {
            Class::Word
        } else {
            Class::Other
        }
    };
    let mut out = Vec::new();
    let mut start = 0;
    let mut last: Option<Class> = None;
    for (i, c) in s.char_indices() {
        let k = class(c);
        let joins = match &last {
            Some(l) => *l == k && k != Class::Other,
            None => true,
        };
        if !joins {
            out.push(&s[start..i]);
            start = i;
        }
        last = Some(k);
    }
    if start < s.len() {
        out.push(&s[start..]);
    }
    out
}

/// The word-level difference of `old` and `new` (absent: empty), the unchanged runs cut to
/// their context.
pub fn pieces(old: Option<&str>, new: Option<&str>) -> Vec<Piece> {
    let (o, n) = (readable(old.unwrap_or("")), readable(new.unwrap_or("")));
    let (a, b) = (tokens(&o), tokens(&n));
    let prefix = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let suffix = a[prefix..]
        .iter()
        .rev()
        .zip(b[prefix..].iter().rev())
        .take_while(|(x, y)| x == y)
        .count();
    let (am, bm) = (&a[prefix..a.len() - suffix], &b[prefix..b.len() - suffix]);
    // (tag, text): 0 same, 1 deleted, 2 inserted.
    let mut runs: Vec<(u8, String)> = Vec::new();
    let mut push = |tag: u8, words: &[&str]| {
        if words.is_empty() {
            return;
        }
        match runs.last_mut() {
            Some((t, text)) if *t == tag => text.push_str(&words.concat()),
            _ => runs.push((tag, words.concat())),
        }
    };
    push(0, &a[..prefix]);
    if am.len() + bm.len() > MAX_TOKENS {
        push(1, am);
        push(2, bm);
    } else {
        for op in similar::capture_diff_slices(similar::Algorithm::Myers, am, bm) {
            let (tag, old_range, new_range) = op.as_tag_tuple();
            match tag {
                similar::DiffTag::Equal => push(0, &am[old_range]),
                similar::DiffTag::Delete => push(1, &am[old_range]),
                similar::DiffTag::Insert => push(2, &bm[new_range]),
                similar::DiffTag::Replace => {
                    push(1, &am[old_range]);
                    push(2, &bm[new_range]);
                }
            }
        }
    }
    push(0, &a[a.len() - suffix..]);
    let count = runs.len();
    let mut out = Vec::with_capacity(count + 2);
    for (i, (tag, text)) in runs.into_iter().enumerate() {
        match tag {
            1 => out.push(Piece::Deleted(text)),
            2 => out.push(Piece::Inserted(text)),
            _ => cut(&text, i > 0, i + 1 < count, &mut out),
        }
    }
    out
}

/// An unchanged run, cut to [`CONTEXT`] words after the change before it (`after`) and before
/// the change after it (`before`).
fn cut(text: &str, after: bool, before: bool, out: &mut Vec<Piece>) {
    let words = tokens(text);
    let space = |i: usize| {
        words
            .get(i)
            .is_some_and(|w| w.starts_with(char::is_whitespace))
    };
    let keep = CONTEXT * 2; // a word and the space after it
                            // The ends kept with the space beside the ellipsis: "stack to … the laser".
    let mut head = if after { keep.min(words.len()) } else { 0 };
    if head > 0 && space(head) {
        head += 1;
    }
    let mut tail = if before {
        words.len().saturating_sub(keep)
    } else {
        words.len()
    };
    if tail < words.len() && tail > 0 && space(tail - 1) {
        tail -= 1;
    }
    if head + 2 >= tail {
        out.push(Piece::Same(text.to_string()));
        return;
    }
    if head > 0 {
        out.push(Piece::Same(words[..head].concat()));
    }
    out.push(Piece::Elided);
    if tail < words.len() {
        out.push(Piece::Same(words[tail..].concat()));
    }
}

/// The difference as text: deleted words as `[-…-]`, inserted ones as `{+…+}` (the marks of
/// `git diff --word-diff=plain`), left-out text as `…`.
pub fn textual(pieces: &[Piece]) -> String {
    let mut out = String::new();
    for p in pieces {
        match p {
            Piece::Same(s) => out.push_str(s),
            Piece::Deleted(s) => {
                out.push_str("[-");
                out.push_str(s);
                out.push_str("-]");
            }
            Piece::Inserted(s) => {
                out.push_str("{+");
                out.push_str(s);
                out.push_str("+}");
            }
            Piece::Elided => out.push('…'),
        }
    }
    out
}

/// The message of a long text changed from `old` to `new`: "changed: " and the word-level
/// difference as text ([`textual`]); `None` when neither is long ([`applies`]).
pub fn message(old: Option<&str>, new: Option<&str>) -> Option<String> {
    applies(old, new).then(|| format!("changed: {}", textual(&pieces(old, new))))
}

#[cfg(test)]
mod tests {
    use super::*;

    const OLD: &str = "This component reads the laser scanner and publishes the nearest obstacle distance for the navigation stack to use.";

    #[test]
    fn a_long_text_shows_only_the_words_that_changed() {
        let new = OLD.replace("nearest obstacle", "closest obstacle's");
        let m = message(Some(OLD), Some(&new)).expect("long");
        assert_eq!(
            m,
            "changed: … the laser scanner and publishes the [-nearest-]{+closest+} obstacle{+'s+} distance for the navigation stack to use."
        );
        assert!(!m.contains("This component"), "{m}");
    }

    #[test]
    fn short_texts_are_not_long_but_a_line_break_is() {
        assert!(message(Some("a"), Some("b")).is_none());
        assert!(is_long("first<br/>second"));
        assert!(is_long("first\nsecond"));
        assert!(!is_long(&"x".repeat(LONG)));
        assert!(is_long(&"x".repeat(LONG + 1)));
    }

    #[test]
    fn a_br_tag_is_a_line_break_and_japanese_is_compared_by_character() {
        let p = pieces(
            Some("一行目<br/>障害物までの距離"),
            Some("一行目<br/>障害物までの最短距離"),
        );
        assert_eq!(
            p,
            [
                Piece::Same("一行目\n障害物までの".into()),
                Piece::Inserted("最短".into()),
                Piece::Same("距離".into()),
            ]
        );
    }

    #[test]
    fn an_absent_side_is_all_inserted_and_a_huge_middle_is_whole() {
        assert_eq!(pieces(None, Some(OLD)), [Piece::Inserted(OLD.to_string())]);
        let a = "a ".repeat(MAX_TOKENS);
        let b = "b ".repeat(MAX_TOKENS);
        let p = pieces(Some(&a), Some(&b));
        assert!(
            matches!(
                &p[..],
                [Piece::Deleted(_), Piece::Inserted(_), Piece::Same(_)]
            ),
            "{p:?}"
        );
    }
}
