//! Pass 1 of the XML reader: bytes → text, honouring a BOM or the encoding named in the XML
//! declaration; and byte offsets → line:column for every later message.

use super::*;
// ---------------------------------------------------------------------------------------------
// Pass 1: decoding
// ---------------------------------------------------------------------------------------------

/// Bytes → text, honouring a BOM or the encoding named in the XML declaration.
pub(super) fn decode<'a>(bytes: &'a [u8], file: &str) -> Result<Cow<'a, str>, Diagnostic> {
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

pub(super) fn utf8<'a>(bytes: &'a [u8], file: &str) -> Result<&'a str, Diagnostic> {
    std::str::from_utf8(bytes).map_err(|e| {
        let good = bytes
            .get(..e.valid_up_to())
            .and_then(|b| std::str::from_utf8(b).ok())
            .unwrap_or("");
        let b = bytes.get(e.valid_up_to()).copied().unwrap_or(0);
        encoding_error(file, good, &format!("byte 0x{b:02X} is not valid UTF-8"))
    })
}

pub(super) fn decode_with<'a>(
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
pub(super) fn encoding_error(file: &str, good: &str, what: &str) -> Diagnostic {
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
pub(super) fn declared_encoding(bytes: &[u8]) -> Option<(String, usize)> {
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
pub(super) struct LineIndex<'a> {
    pub(super) text: &'a str,
    pub(super) starts: Vec<usize>,
}

impl<'a> LineIndex<'a> {
    pub(super) fn new(text: &'a str) -> Self {
        let b = text.as_bytes();
        let mut starts = vec![0];
        for i in memchr::memchr2_iter(b'\n', b'\r', b) {
            if b[i] == b'\n' || b.get(i + 1) != Some(&b'\n') {
                starts.push(i + 1);
            }
        }
        LineIndex { text, starts }
    }

    pub(super) fn pos(&self, offset: usize) -> Pos {
        let offset = self.boundary(offset);
        self.pos_on(self.line_of(offset), offset)
    }

    /// `offset`, within the text and moved back to a character boundary.
    pub(super) fn boundary(&self, offset: usize) -> usize {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        offset
    }

    /// Index in `starts` of the line holding `offset`.
    pub(super) fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset).max(1) - 1
    }

    /// Position of `offset` (a boundary) on line `line` (an index in `starts`).
    pub(super) fn pos_on(&self, line: usize, offset: usize) -> Pos {
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
pub(super) struct PosCursor<'a> {
    pub(super) index: LineIndex<'a>,
    /// The last offset asked for (on a character boundary), its position, and the index of
    /// its line in `index.starts`.
    pub(super) last: (usize, Pos, usize),
}

impl<'a> PosCursor<'a> {
    pub(super) fn new(text: &'a str) -> Self {
        PosCursor {
            index: LineIndex::new(text),
            last: (0, Pos::new(1, 1), 0),
        }
    }

    pub(super) fn pos(&mut self, offset: usize) -> Pos {
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
