//! Text metrics for the diagrams: a width estimate and line wrapping. The SVG is drawn without
//! a font at hand, so widths are estimated per character, erring wide so that a name measured
//! here fits the box drawn around it in a browser.

/// Approximate rendered width of `s` in pixels at `px` sans-serif, erring wide so that no
/// label is cut at the SVG edge: CJK glyphs are square, capitals and `m`/`w` wider than the
/// average letter (DejaVu Sans, the Debian default, sets `TimedRGBDCameraImage` at ~0.66 em a
/// character), narrow letters and punctuation narrower.
pub fn text_width(s: &str, px: f32) -> f32 {
    s.chars().map(|c| advance(c, px)).sum()
}

/// The width of a character in em (see [`text_width`]).
const fn em(c: char) -> f32 {
    match c {
        _ if (c as u32) >= 0x2E80 => 1.0,
        'M' | 'W' | 'm' | 'w' => 0.9,
        'I' => 0.4,
        'A'..='Z' => 0.74,
        'i' | 'j' | 'l' | 't' | 'f' | 'r' | '.' | ',' | ':' | ';' | '\'' | '|' => 0.4,
        _ => 0.62,
    }
}

/// [`em`] of the ASCII characters, looked up (most names are ASCII).
const ASCII_EM: [f32; 128] = {
    let mut t = [0.0; 128];
    let mut c = 0;
    while c < 128 {
        t[c] = em(c as u8 as char);
        c += 1;
    }
    t
};

/// The width of one character at `px` (see [`text_width`]).
#[inline]
fn advance(c: char, px: f32) -> f32 {
    let em = match ASCII_EM.get(c as usize) {
        Some(&e) => e,
        None => em(c),
    };
    px * em
}

/// Width of bold text (`font-weight: 700` sets about 8 % wider in DejaVu Sans and system-ui).
pub fn bold_width(s: &str, px: f32) -> f32 {
    text_width(s, px) * 1.1
}

/// A size and weight of the sans-serif text measured by [`text_width`] and [`bold_width`].
#[derive(Debug, Clone, Copy)]
pub struct Font {
    pub px: f32,
    pub bold: bool,
}

impl Font {
    /// Regular text at `px`.
    pub fn regular(px: f32) -> Font {
        Font { px, bold: false }
    }

    /// Bold text at `px`.
    pub fn bold(px: f32) -> Font {
        Font { px, bold: true }
    }

    /// The width of `s`.
    pub fn width(self, s: &str) -> f32 {
        if self.bold {
            bold_width(s, self.px)
        } else {
            text_width(s, self.px)
        }
    }

    /// The sum of the characters' widths, continued from `sum` (a text's width, measured as
    /// [`text_width`] adds up, before [`Font::finish`]).
    fn add(self, sum: f32, s: &str) -> f32 {
        s.chars().fold(sum, |acc, c| acc + advance(c, self.px))
    }

    /// The width of a text whose characters add up to `sum`.
    fn finish(self, sum: f32) -> f32 {
        if self.bold {
            sum * 1.1
        } else {
            sum
        }
    }
}

/// Cuts `s` into lines no wider than `max` in `font`, breaking after `_ . : / - ,` and spaces
/// or before a capital that follows a small letter (`ManipulatorCommon|Interface`), and inside
/// a word only when one word alone is too wide. Never drops a character: the lines joined give
/// `s` back (spaces at a break are kept at the end of the line). A line's width is added up
/// as it grows (the same additions in the same order as measuring it whole), not measured
/// again for each piece.
pub fn wrap(s: &str, max: f32, font: Font) -> Vec<String> {
    match one_line(s, max, font) {
        Some(_) => vec![s.to_string()],
        None => wrap_lines(s, max, font),
    }
}

/// The width of `s` when it stays on one line (it fits, or is empty); `None` when it wraps.
fn one_line(s: &str, max: f32, font: Font) -> Option<f32> {
    let whole = font.width(s);
    (whole <= max || s.is_empty()).then_some(whole)
}

/// [`wrap`], and the width of the widest line (`font.width` of each line, the largest; 0 for
/// no line wider than 0): a text that fits on one line is measured once, not twice.
pub fn wrap_measured(s: &str, max: f32, font: Font) -> (Vec<String>, f32) {
    if let Some(whole) = one_line(s, max, font) {
        return (vec![s.to_string()], f32::max(0.0, whole));
    }
    let lines = wrap_lines(s, max, font);
    let widest = lines.iter().map(|l| font.width(l)).fold(0.0, f32::max);
    (lines, widest)
}

/// The lines of a text too wide for one (see [`wrap`]).
fn wrap_lines(s: &str, max: f32, font: Font) -> Vec<String> {
    // Pieces between break opportunities (slices of `s`).
    let mut pieces: Vec<&str> = Vec::new();
    let mut start = 0;
    let mut prev: Option<char> = None;
    for (i, c) in s.char_indices() {
        if let Some(p) = prev {
            if c.is_uppercase() && p.is_lowercase() && i > start {
                pieces.push(&s[start..i]);
                start = i;
            }
        }
        if matches!(c, '_' | '.' | ':' | '/' | '-' | ',' | ' ') {
            let end = i + c.len_utf8();
            pieces.push(&s[start..end]);
            start = end;
        }
        prev = Some(c);
    }
    if start < s.len() {
        pieces.push(&s[start..]);
    }
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    // The characters of `line` added up.
    let mut sum = 0.0f32;
    for piece in pieces {
        let joined = font.add(sum, piece);
        if font.finish(joined) <= max {
            line.push_str(piece);
            sum = joined;
            continue;
        }
        if !line.is_empty() {
            lines.push(std::mem::take(&mut line));
        }
        let alone = font.add(0.0, piece);
        if font.finish(alone) <= max {
            // `line` is empty here (just handed over, or never filled).
            line.push_str(piece);
            sum = alone;
            continue;
        }
        // One piece wider than a line: cut it by characters.
        sum = font.add(0.0, &line);
        for c in piece.chars() {
            let mut one = [0u8; 4];
            let next = font.add(sum, c.encode_utf8(&mut one));
            if font.finish(next) > max && !line.is_empty() {
                lines.push(std::mem::take(&mut line));
                line.push(c);
                sum = font.add(0.0, c.encode_utf8(&mut one));
            } else {
                line.push(c);
                sum = next;
            }
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wraps_at_word_parts_and_keeps_every_character() {
        let w = |s: &str| text_width(s, 11.0);
        let font = Font::regular(11.0);
        let name = "ManipulatorCommonInterface_Middle.ManipulatorCommonInterface_Middle";
        let lines = wrap(name, 170.0, font);
        assert!(lines.len() >= 2, "{lines:?}");
        assert_eq!(lines.concat(), name);
        assert!(lines.iter().all(|l| w(l) <= 170.0), "{lines:?}");
        assert_eq!(wrap("short", 170.0, font), vec!["short"]);
        // One long word without break opportunities is cut by characters.
        let long = "x".repeat(100);
        let lines = wrap(&long, 60.0, font);
        assert_eq!(lines.concat(), long);
        assert!(lines.iter().all(|l| w(l) <= 60.0));
        // CJK characters are a whole em wide.
        assert_eq!(text_width("画像", 10.0), 20.0);
    }

    proptest::proptest! {
        /// Any name: the lines give it back whole, none is empty, and each fits unless it is a
        /// single character.
        #[test]
        fn wrapped_lines_keep_every_character_and_fit(
            parts in proptest::collection::vec(
                proptest::sample::select(&["a", "B", "Cam", "_", ".", " ", "-", "画", "w", "x1"][..]),
                0..60,
            ),
            max in 20.0f32..200.0,
        ) {
            let s: String = parts.concat();
            let font = Font::regular(11.0);
            let (lines, widest) = wrap_measured(&s, max, font);
            proptest::prop_assert_eq!(lines.concat(), s.clone());
            if lines.len() > 1 {
                for l in &lines {
                    proptest::prop_assert!(!l.is_empty());
                    proptest::prop_assert!(font.width(l) <= max || l.chars().count() == 1, "{:?}", lines);
                }
            }
            proptest::prop_assert!(widest >= 0.0);
        }
    }

    #[test]
    fn the_measured_wrap_gives_the_widest_line_as_measuring_each_gives_it() {
        for font in [Font::regular(11.0), Font::bold(15.0)] {
            for s in [
                "",
                "short",
                "ManipulatorCommonInterface_Middle.ManipulatorCommonInterface_Middle",
                "画像処理コンポーネント画像処理コンポーネント画像処理",
                &"x".repeat(100),
            ] {
                let (lines, widest) = wrap_measured(s, 60.0, font);
                assert_eq!(lines, wrap(s, 60.0, font), "{s:?}");
                let each = lines.iter().map(|l| font.width(l)).fold(0.0, f32::max);
                assert_eq!(widest.to_bits(), each.to_bits(), "{s:?}");
            }
        }
        // The table of ASCII widths agrees with the rules for every character it holds.
        for c in (0u8..128).map(char::from) {
            assert_eq!(
                advance(c, 11.0).to_bits(),
                (11.0 * em(c)).to_bits(),
                "{c:?}"
            );
        }
    }
}
