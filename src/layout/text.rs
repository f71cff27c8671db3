//! Text metrics for the diagrams: a width estimate and line wrapping. The SVG is drawn without
//! a font at hand, so widths are estimated per character, erring wide so that a name measured
//! here fits the box drawn around it in a browser.

/// Approximate rendered width of `s` in pixels at `px` sans-serif, erring wide so that no
/// label is cut at the SVG edge: CJK glyphs are square, capitals and `m`/`w` wider than the
/// average letter (DejaVu Sans, the Debian default, sets `TimedRGBDCameraImage` at ~0.66 em a
/// character), narrow letters and punctuation narrower.
pub fn text_width(s: &str, px: f32) -> f32 {
    s.chars()
        .map(|c| {
            let em = match c {
                _ if (c as u32) >= 0x2E80 => 1.0,
                'M' | 'W' | 'm' | 'w' => 0.9,
                'I' => 0.4,
                'A'..='Z' => 0.74,
                'i' | 'j' | 'l' | 't' | 'f' | 'r' | '.' | ',' | ':' | ';' | '\'' | '|' => 0.4,
                _ => 0.62,
            };
            px * em
        })
        .sum()
}

/// Width of bold text (`font-weight: 700` sets about 8 % wider in DejaVu Sans and system-ui).
pub fn bold_width(s: &str, px: f32) -> f32 {
    text_width(s, px) * 1.1
}

/// Cuts `s` into lines no wider than `max` (by `width`), breaking after `_ . : / - ,` and
/// spaces or before a capital that follows a small letter (`ManipulatorCommon|Interface`), and
/// inside a word only when one word alone is too wide. Never drops a character: the lines
/// joined give `s` back (spaces at a break are kept at the end of the line).
pub fn wrap(s: &str, max: f32, width: &dyn Fn(&str) -> f32) -> Vec<String> {
    if width(s) <= max || s.is_empty() {
        return vec![s.to_string()];
    }
    // Pieces between break opportunities.
    let mut pieces: Vec<String> = Vec::new();
    let mut cur = String::new();
    let mut prev: Option<char> = None;
    for c in s.chars() {
        if let Some(p) = prev {
            if c.is_uppercase() && p.is_lowercase() && !cur.is_empty() {
                pieces.push(std::mem::take(&mut cur));
            }
        }
        cur.push(c);
        if matches!(c, '_' | '.' | ':' | '/' | '-' | ',' | ' ') {
            pieces.push(std::mem::take(&mut cur));
        }
        prev = Some(c);
    }
    if !cur.is_empty() {
        pieces.push(cur);
    }
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for piece in pieces {
        let joined = format!("{line}{piece}");
        if width(&joined) <= max {
            line = joined;
            continue;
        }
        if !line.is_empty() {
            lines.push(std::mem::take(&mut line));
        }
        if width(&piece) <= max {
            line = piece;
            continue;
        }
        // One piece wider than a line: cut it by characters.
        for c in piece.chars() {
            let mut next = line.clone();
            next.push(c);
            if width(&next) > max && !line.is_empty() {
                lines.push(std::mem::take(&mut line));
                line.push(c);
            } else {
                line = next;
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
        let name = "ManipulatorCommonInterface_Middle.ManipulatorCommonInterface_Middle";
        let lines = wrap(name, 170.0, &w);
        assert!(lines.len() >= 2, "{lines:?}");
        assert_eq!(lines.concat(), name);
        assert!(lines.iter().all(|l| w(l) <= 170.0), "{lines:?}");
        assert_eq!(wrap("short", 170.0, &w), vec!["short"]);
        // One long word without break opportunities is cut by characters.
        let long = "x".repeat(100);
        let lines = wrap(&long, 60.0, &w);
        assert_eq!(lines.concat(), long);
        assert!(lines.iter().all(|l| w(l) <= 60.0));
        // CJK characters are a whole em wide.
        assert_eq!(text_width("画像", 10.0), 20.0);
    }
}
