//! Near matches of a name nothing is called: the one helper behind every "did you mean"
//! (`graph --component`, RTC403's hint). A name is offered only when it is similar to what was
//! written — the same but for case, one containing the other, or a few edits away — never just
//! because it is the least far of unrelated names.

/// The edit distance between two strings, by characters: insertions, deletions, substitutions
/// and swaps of two neighbours (`prot` is one edit from `port`) each count one.
pub fn distance(a: &str, b: &str) -> usize {
    within(a, b, usize::MAX).unwrap_or(usize::MAX)
}

/// [`distance`] when it is at most `limit`: two rows of the table whose least values are over
/// the limit (a swap reaches two rows back) end the computation.
fn within(a: &str, b: &str, limit: usize) -> Option<usize> {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    // Three rows of the table: two back (for swaps), the last one and the current one.
    let mut two: Vec<usize> = vec![0; b.len() + 1];
    let mut last: Vec<usize> = (0..=b.len()).collect();
    let mut last_least = 0;
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        let mut least = i;
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (last[j - 1] + cost).min(last[j] + 1).min(cur[j - 1] + 1);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                cur[j] = cur[j].min(two[j - 2] + 1);
            }
            least = least.min(cur[j]);
        }
        if least > limit && last_least >= limit {
            return None;
        }
        last_least = least;
        two = std::mem::replace(&mut last, cur);
    }
    Some(last[b.len()]).filter(|&d| d <= limit)
}

/// The candidate nearest to `word` when it is a typo of it ([`Lowered::edits`]: case ignored,
/// at most a third of its characters, at least one, differ); the first of equally near ones.
/// What a key or a code of a configuration file is checked against.
pub fn typo<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let w = Lowered::new(word.trim());
    candidates
        .into_iter()
        .filter_map(|c| w.edits(&Lowered::new(c)).map(|d| (d, c)))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// How far `candidate` is from `want` when it is near (case ignored), `None` when it is not:
/// 0 when one contains the other (the contained one of 3 characters or more), else the edit
/// distance when it is at most a third of `want`'s length (at least 1).
pub fn nearness(want: &str, candidate: &str) -> Option<usize> {
    Lowered::new(want).nearness(&Lowered::new(candidate))
}

/// A name in lower case with its length in characters, made once for comparing it with many
/// ([`Lowered::nearness`] is [`nearness`]).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct Lowered {
    text: String,
    chars: usize,
}

impl Lowered {
    pub fn new(s: &str) -> Lowered {
        let text = s.to_lowercase();
        let chars = text.chars().count();
        Lowered { text, chars }
    }

    /// [`nearness`] of `candidate` to this name.
    pub fn nearness(&self, candidate: &Lowered) -> Option<usize> {
        let (w, c) = (&self.text, &candidate.text);
        let (lw, lc) = (self.chars, candidate.chars);
        // One can contain the other only when it is not longer.
        if w == c
            || (lw >= 3 && lw < lc && c.contains(w.as_str()))
            || (lc >= 3 && lc < lw && w.contains(c.as_str()))
        {
            return Some(0);
        }
        self.edits(candidate)
    }

    /// The edit distance of `candidate` from this name when it is at most a third of this
    /// name's length (at least 1), case ignored; `None` otherwise. Cheap for names of other
    /// lengths: what looks through many names (RTC403's hint, over an IDL's types) asks this.
    pub fn edits(&self, candidate: &Lowered) -> Option<usize> {
        // Lengths further apart than the threshold cannot be within it.
        let limit = (self.chars / 3).max(1);
        if self.chars.abs_diff(candidate.chars) > limit {
            return None;
        }
        within(&self.text, &candidate.text, limit)
    }
}

/// The candidates near `want` ([`nearness`]), nearest first (then in name order), each once,
/// at most `max`.
pub fn nearest<'a>(
    want: &str,
    candidates: impl IntoIterator<Item = &'a str>,
    max: usize,
) -> Vec<&'a str> {
    let mut near: Vec<(usize, &str)> = candidates
        .into_iter()
        .filter_map(|c| nearness(want, c).map(|d| (d, c)))
        .collect();
    near.sort_unstable();
    near.dedup_by(|a, b| a.1 == b.1);
    near.into_iter().take(max).map(|(_, c)| c).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances() {
        assert_eq!(distance("", "abc"), 3);
        assert_eq!(distance("abc", ""), 3);
        assert_eq!(distance("prot", "port"), 1);
        assert_eq!(distance("ignroe", "ignore"), 1);
        assert_eq!(typo("prot", ["port", "open"]), Some("port"));
        assert_eq!(typo("xyz", ["port", "open"]), None);
        assert_eq!(distance("kitten", "sitting"), 3);
        assert_eq!(distance("カメラ", "カメラ"), 0);
    }

    #[test]
    fn only_similar_names_are_offered() {
        let names = ["Camera", "CameraViewer", "Motor", "SeqIn", "ConsoleIn"];
        // A typo, a case slip and a part of a name find theirs …
        assert_eq!(nearest("Camrea", names, 5), ["Camera"]);
        assert_eq!(nearest("camera", names, 5), ["Camera", "CameraViewer"]);
        assert_eq!(nearest("Viewer", names, 5), ["CameraViewer"]);
        // … a name like none of them finds nothing.
        assert!(nearest("NoSuch", names, 5).is_empty());
        assert!(nearest("X", names, 5).is_empty());
        // Two letters contain nothing: `In` is no near match of every `…In`.
        assert!(nearest("In", names, 5).is_empty());
    }
}
