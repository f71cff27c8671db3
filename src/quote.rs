//! Values quoted in rtcdoc's messages (findings, changes): as Markdown code spans that read
//! back whole, whatever backticks the value holds. Every output reads a message's code spans by
//! CommonMark's rule (`render::text::code_spans`), so a value quoted with a bare pair of
//! backticks that itself holds one (`` 1`5 ``) would break the message into pieces of code.

use std::fmt;

/// `s` as one code span of Markdown: fenced by one backtick more than its longest run of
/// backticks, padded with a space where needed (CommonMark's rule), so that a value holding
/// backticks reads whole.
pub fn code_span(s: &str) -> String {
    Code(s).to_string()
}

/// `s` as one word of a POSIX shell, for a command a message tells the user to run: as is when
/// it holds only characters no shell reads specially, else in single quotes.
pub fn shell_word(s: &str) -> String {
    let plain = !s.is_empty()
        && s.bytes()
            .all(|b| b.is_ascii_alphanumeric() || b"_./:=@%+,-".contains(&b));
    if plain {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

/// A value quoted as one code span where it is formatted (`format!("value {}", Code(v))`):
/// [`code_span`] without a string of its own.
#[derive(Debug, Clone, Copy)]
pub struct Code<'a>(pub &'a str);

impl fmt::Display for Code<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.0;
        let mut longest = 0;
        let mut run = 0;
        for c in s.chars() {
            run = if c == '`' { run + 1 } else { 0 };
            longest = longest.max(run);
        }
        // A space inside each fence, where the value starts or ends with a backtick (which
        // would join the fence) or starts and ends with a space (which a reader strips once).
        let spaced = s.starts_with(' ') && s.ends_with(' ') && s.chars().any(|c| c != ' ');
        let pad = if s.starts_with('`') || s.ends_with('`') || spaced {
            " "
        } else {
            ""
        };
        for _ in 0..=longest {
            f.write_str("`")?;
        }
        f.write_str(pad)?;
        f.write_str(s)?;
        f.write_str(pad)?;
        for _ in 0..=longest {
            f.write_str("`")?;
        }
        Ok(())
    }
}
