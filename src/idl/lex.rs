//! The IDL lexer: text → tokens with 1-based line/column positions (columns count characters).
//!
//! Hand-written rather than generated (logos) because three things IDL needs are contextual
//! and easier to say in code than in a token grammar: a `#` only starts a preprocessor
//! directive at the start of a line (and the directive then runs to the end of the line,
//! continuation lines and block comments included); doc comments (`/** */`, `/*! */`, `///`,
//! `//!`, and their trailing `<` forms) are tokens while plain comments are not; and `>>` must be
//! splittable by the parser inside `sequence<sequence<long>>`. Keywords are not token kinds:
//! a word is an identifier and the parser decides by context, which is what lets CORBA-3 files
//! use IDL-4 keywords (`map`, `bitset`, `int8`) as names.
//!
//! The lexer never fails: a character it does not know becomes a [`Tok::Bad`] token, which the
//! preprocessor reports only when it is in an active region. Only an unterminated block
//! comment and the token limit stop it (reported as [`LexOutput::fatal`]).

use crate::model::Pos;

/// A token.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Tok {
    /// A word as written (an escaped identifier keeps its `_`).
    Ident(String),
    Int {
        value: u64,
        raw: String,
    },
    Float {
        value: f64,
        raw: String,
    },
    Char {
        value: char,
        raw: String,
    },
    Str {
        value: String,
        raw: String,
    },
    Punct(&'static str),
    /// A doc comment, text stripped; `after` for the trailing `<` forms.
    Doc {
        text: String,
        after: bool,
    },
    Directive(Box<Directive>),
    /// Something that is not a token, with the reason.
    Bad(String),
    /// Produced by the preprocessor: an active `#pragma` (text after the word `pragma`).
    Pragma(String),
    /// Produced by the preprocessor where an `#include` stood.
    IncludeMark,
    Eof,
}

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Token {
    pub tok: Tok,
    pub pos: Pos,
}

impl Token {
    /// The token as written, for expression texts and messages.
    pub fn lexeme(&self) -> String {
        match &self.tok {
            Tok::Ident(s) => s.clone(),
            Tok::Int { raw, .. }
            | Tok::Float { raw, .. }
            | Tok::Char { raw, .. }
            | Tok::Str { raw, .. } => raw.clone(),
            Tok::Punct(p) => (*p).to_string(),
            Tok::Doc { .. } => "doc comment".into(),
            Tok::Directive(_) => "directive".into(),
            Tok::Bad(_) => "?".into(),
            Tok::Pragma(_) => "#pragma".into(),
            Tok::IncludeMark => "#include".into(),
            Tok::Eof => "end of file".into(),
        }
    }
    /// How a message names the token: `` `}` ``, `` identifier `foo` ``, `end of file`.
    pub fn describe(&self) -> String {
        match &self.tok {
            Tok::Ident(s) => format!("`{s}`"),
            Tok::Int { raw, .. } | Tok::Float { raw, .. } => format!("number `{raw}`"),
            Tok::Char { raw, .. } => format!("character literal {raw}"),
            Tok::Str { raw, .. } => format!("string literal {}", shorten(raw)),
            Tok::Punct(p) => format!("`{p}`"),
            Tok::Bad(m) => m.clone(),
            Tok::Eof => "end of file".into(),
            _ => self.lexeme(),
        }
    }
}

fn shorten(s: &str) -> String {
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}

/// A preprocessor directive line.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Directive {
    /// The word after `#` (`include`, `ifdef`, …); empty for a null directive.
    pub name: String,
    /// The rest of the line, comments removed and continuation lines joined, trimmed.
    pub raw: String,
    /// Where `raw` starts.
    pub raw_pos: Pos,
}

/// The lexer's result.
pub(crate) struct LexOutput {
    pub tokens: Vec<Token>,
    /// A fatal problem that stopped lexing: (position, message, is-limit).
    pub fatal: Option<(Pos, String, bool)>,
}

const PUNCT2: [&str; 9] = ["::", "<<", ">>", "&&", "||", "==", "!=", "<=", ">="];
const PUNCT1: &str = ";{}()<>,=[]:+-*/%~!&|^?.#";

fn punct1(c: u8) -> Option<&'static str> {
    const ALL: [&str; 25] = [
        ";", "{", "}", "(", ")", "<", ">", ",", "=", "[", "]", ":", "+", "-", "*", "/", "%", "~",
        "!", "&", "|", "^", "?", ".", "#",
    ];
    PUNCT1.bytes().position(|b| b == c).map(|i| ALL[i])
}

struct Lexer<'a> {
    s: &'a str,
    b: &'a [u8],
    i: usize,
    line: u32,
    col: u32,
    at_line_start: bool,
    in_directive: bool,
    max_tokens: usize,
    out: Vec<Token>,
}

/// Lexes a whole file.
pub(crate) fn lex(text: &str, max_tokens: usize) -> LexOutput {
    let mut l = Lexer {
        s: text,
        b: text.as_bytes(),
        i: 0,
        line: 1,
        col: 1,
        at_line_start: true,
        in_directive: false,
        max_tokens,
        out: Vec::new(),
    };
    let fatal = l.run();
    LexOutput {
        tokens: l.out,
        fatal,
    }
}

/// Lexes the text of one directive line (positions start at `start`).
pub(crate) fn lex_line(text: &str, start: Pos) -> Vec<Token> {
    let mut l = Lexer {
        s: text,
        b: text.as_bytes(),
        i: 0,
        line: start.line,
        col: start.column,
        at_line_start: false,
        in_directive: true,
        max_tokens: usize::MAX,
        out: Vec::new(),
    };
    let _ = l.run();
    l.out
}

fn is_ident_start(c: u8) -> bool {
    c.is_ascii_alphabetic() || c == b'_'
}
fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

impl<'a> Lexer<'a> {
    fn pos(&self) -> Pos {
        Pos::new(self.line, self.col)
    }
    fn peek(&self, k: usize) -> u8 {
        self.b.get(self.i + k).copied().unwrap_or(0)
    }
    /// Advances one byte, keeping line and column (a `\r\n` pair is one line end, a lone `\r`
    /// is one too; UTF-8 continuation bytes do not count as columns).
    fn bump(&mut self) {
        let c = self.b[self.i];
        self.i += 1;
        match c {
            b'\n' => {
                self.line += 1;
                self.col = 1;
            }
            b'\r' => {
                if self.peek(0) != b'\n' {
                    self.line += 1;
                    self.col = 1;
                }
            }
            _ if c & 0xC0 == 0x80 => {}
            _ => self.col += 1,
        }
    }
    fn push(&mut self, tok: Tok, pos: Pos) -> Result<(), (Pos, String, bool)> {
        if self.out.len() >= self.max_tokens {
            return Err((
                pos,
                format!(
                    "the file has more than {} tokens (the limit against hostile input)",
                    self.max_tokens
                ),
                true,
            ));
        }
        self.out.push(Token { tok, pos });
        self.at_line_start = false;
        Ok(())
    }

    /// A doc comment between a name and a `}` on the name's line (`TWO_BIT /// Two bits.`,
    /// the last enumerator) describes that name, as after a `,` ([`Lexer::line_comment`]).
    fn last_enumerator_docs(&mut self) {
        for i in 1..self.out.len().saturating_sub(1) {
            let (before, rest) = self.out.split_at_mut(i);
            let (Some(prev), [doc, next, ..]) = (before.last(), rest) else {
                continue;
            };
            if let (Tok::Ident(_), Tok::Doc { after, .. }, Tok::Punct("}")) =
                (&prev.tok, &mut doc.tok, &next.tok)
            {
                if prev.pos.line == doc.pos.line {
                    *after = true;
                }
            }
        }
    }

    fn run(&mut self) -> Option<(Pos, String, bool)> {
        match self.run_inner() {
            Ok(()) => {
                self.last_enumerator_docs();
                let p = self.pos();
                self.out.push(Token {
                    tok: Tok::Eof,
                    pos: p,
                });
                None
            }
            Err(e) => {
                let p = self.pos();
                self.out.push(Token {
                    tok: Tok::Eof,
                    pos: p,
                });
                Some(e)
            }
        }
    }

    fn run_inner(&mut self) -> Result<(), (Pos, String, bool)> {
        while self.i < self.b.len() {
            let c = self.b[self.i];
            let start = self.pos();
            match c {
                b'\n' | b'\r' => {
                    self.bump();
                    self.at_line_start = true;
                }
                b' ' | b'\t' | 0x0b | 0x0c => self.bump(),
                b'/' if self.peek(1) == b'/' => self.line_comment(start)?,
                b'/' if self.peek(1) == b'*' => self.block_comment(start)?,
                b'#' if self.at_line_start && !self.in_directive => self.directive(start)?,
                b'L' if self.peek(1) == b'"' || self.peek(1) == b'\'' => {
                    self.bump();
                    self.quoted(start, true)?;
                }
                b'"' | b'\'' => self.quoted(start, false)?,
                _ if is_ident_start(c) => {
                    let s = self.i;
                    while self.i < self.b.len() && is_ident(self.b[self.i]) {
                        self.bump();
                    }
                    let word = self.s[s..self.i].to_string();
                    self.push(Tok::Ident(word), start)?;
                }
                _ if c.is_ascii_digit() || (c == b'.' && self.peek(1).is_ascii_digit()) => {
                    self.number(start)?
                }
                _ => {
                    let two = self.s.get(self.i..self.i + 2).unwrap_or("");
                    if let Some(p) = PUNCT2.iter().find(|p| **p == two) {
                        self.bump();
                        self.bump();
                        self.push(Tok::Punct(p), start)?;
                    } else if let Some(p) = punct1(c) {
                        self.bump();
                        self.push(Tok::Punct(p), start)?;
                    } else {
                        let ch = self.s[self.i..].chars().next().unwrap_or('\u{FFFD}');
                        for _ in 0..ch.len_utf8() {
                            self.bump();
                        }
                        self.push(Tok::Bad(format!("unexpected character `{ch}`")), start)?;
                    }
                }
            }
        }
        Ok(())
    }

    fn line_comment(&mut self, start: Pos) -> Result<(), (Pos, String, bool)> {
        let s = self.i;
        while self.i < self.b.len() && self.b[self.i] != b'\n' && self.b[self.i] != b'\r' {
            self.bump();
        }
        if self.in_directive {
            return Ok(());
        }
        let body = &self.s[s + 2..self.i];
        let (doc, rest) = if let Some(r) = body.strip_prefix('/') {
            (!r.starts_with('/'), r)
        } else if let Some(r) = body.strip_prefix('!') {
            (true, r)
        } else {
            (false, body)
        };
        if doc {
            let (marked, rest) = match rest.strip_prefix('<') {
                Some(r) => (true, r),
                None => (false, rest),
            };
            // A `///` on the line of a declaration, after its `;` or `,`, describes that
            // declaration (`Style style; /// How the map is stored.`), as its writer meant
            // and as `///<` says: read as a doc comment before the next declaration, it moved
            // every such text one member down and lost the last one. (The last enumerator,
            // without a `,`, is [`Lexer::last_enumerator_docs`]'.)
            let after = marked
                || self.out.last().is_some_and(|t| {
                    t.pos.line == start.line && matches!(t.tok, Tok::Punct(";" | ","))
                });
            let text = rest
                .strip_prefix(' ')
                .unwrap_or(rest)
                .trim_end()
                .to_string();
            let keep = self.at_line_start;
            self.push(Tok::Doc { text, after }, start)?;
            self.at_line_start = keep;
        }
        Ok(())
    }

    /// Moves past a block comment, from its `/*` (at `start`) to just after its `*/`.
    fn comment_end(&mut self, start: Pos) -> Result<(), (Pos, String, bool)> {
        self.bump();
        self.bump();
        loop {
            if self.i >= self.b.len() {
                return Err((
                    start,
                    "unterminated comment: `/*` has no closing `*/`".into(),
                    false,
                ));
            }
            if self.b[self.i] == b'*' && self.peek(1) == b'/' {
                self.bump();
                self.bump();
                return Ok(());
            }
            self.bump();
        }
    }

    /// Moves past one character (every byte of its UTF-8 sequence) and gives it back.
    fn char(&mut self) -> &'a str {
        let start = self.i;
        self.bump();
        while self.i < self.b.len() && self.b[self.i] & 0xC0 == 0x80 {
            self.bump();
        }
        &self.s[start..self.i]
    }

    fn block_comment(&mut self, start: Pos) -> Result<(), (Pos, String, bool)> {
        let s = self.i;
        self.comment_end(start)?;
        if self.in_directive {
            return Ok(());
        }
        let body = &self.s[s + 2..self.i - 2];
        let marker = body.as_bytes().first().copied();
        let doc = match marker {
            Some(b'!') => true,
            Some(b'*') => !body[1..].starts_with('*') && body.len() > 1,
            _ => false,
        };
        if doc {
            let rest = &body[1..];
            let (after, rest) = match rest.strip_prefix('<') {
                Some(r) => (true, r),
                None => (false, rest),
            };
            let keep = self.at_line_start;
            self.push(
                Tok::Doc {
                    text: strip_block(rest),
                    after,
                },
                start,
            )?;
            self.at_line_start = keep;
        }
        Ok(())
    }

    fn directive(&mut self, start: Pos) -> Result<(), (Pos, String, bool)> {
        self.bump(); // '#'
        while matches!(self.peek(0), b' ' | b'\t') {
            self.bump();
        }
        let s = self.i;
        while self.i < self.b.len() && is_ident(self.b[self.i]) {
            self.bump();
        }
        let name = self.s[s..self.i].to_string();
        while matches!(self.peek(0), b' ' | b'\t') {
            self.bump();
        }
        let raw_pos = self.pos();
        let mut raw = String::new();
        // The rest of the line: continuation lines joined, comments replaced by a space.
        while self.i < self.b.len() {
            let c = self.b[self.i];
            if c == b'\n' || c == b'\r' {
                break;
            }
            if c == b'\\' && matches!(self.peek(1), b'\n' | b'\r') {
                self.bump();
                self.bump();
                if self.b.get(self.i - 1) == Some(&b'\r') && self.peek(0) == b'\n' {
                    self.bump();
                }
                raw.push(' ');
                continue;
            }
            if c == b'/' && self.peek(1) == b'/' {
                while self.i < self.b.len() && !matches!(self.b[self.i], b'\n' | b'\r') {
                    self.bump();
                }
                break;
            }
            if c == b'/' && self.peek(1) == b'*' {
                let cs = self.pos();
                self.comment_end(cs)?;
                raw.push(' ');
                continue;
            }
            raw.push_str(self.char());
        }
        let raw = raw.trim_end().to_string();
        self.push(
            Tok::Directive(Box::new(Directive { name, raw, raw_pos })),
            start,
        )?;
        self.at_line_start = true;
        Ok(())
    }

    fn number(&mut self, start: Pos) -> Result<(), (Pos, String, bool)> {
        let s = self.i;
        let b = self.b;
        let n = b.len();
        if b[self.i] == b'0' && matches!(self.peek(1), b'x' | b'X') {
            self.bump();
            self.bump();
            while self.i < n && b[self.i].is_ascii_hexdigit() {
                self.bump();
            }
            let raw = &self.s[s..self.i];
            let tok = match u64::from_str_radix(&raw[2..], 16) {
                Ok(value) if raw.len() > 2 => Tok::Int {
                    value,
                    raw: raw.into(),
                },
                Ok(_) => Tok::Bad(format!("hexadecimal literal `{raw}` has no digits")),
                Err(_) => Tok::Bad(format!("integer literal `{raw}` is too large")),
            };
            return self.push(tok, start);
        }
        let mut float = false;
        while self.i < n && b[self.i].is_ascii_digit() {
            self.bump();
        }
        if self.i < n && b[self.i] == b'.' {
            float = true;
            self.bump();
            while self.i < n && b[self.i].is_ascii_digit() {
                self.bump();
            }
        }
        if self.i < n
            && matches!(b[self.i], b'e' | b'E')
            && (self.peek(1).is_ascii_digit()
                || (matches!(self.peek(1), b'+' | b'-') && self.peek(2).is_ascii_digit()))
        {
            float = true;
            self.bump();
            self.bump();
            while self.i < n && b[self.i].is_ascii_digit() {
                self.bump();
            }
        }
        let digits_end = self.i;
        // Fixed-point literal suffix `d` (`1.5d`).
        if self.i < n && matches!(b[self.i], b'd' | b'D') {
            float = true;
            self.bump();
        }
        let raw = self.s[s..self.i].to_string();
        let digits = &self.s[s..digits_end];
        let tok = if float {
            match digits.parse::<f64>() {
                Ok(value) => Tok::Float { value, raw },
                Err(_) => Tok::Bad(format!("malformed number `{raw}`")),
            }
        } else if digits.len() > 1 && digits.starts_with('0') {
            match u64::from_str_radix(&digits[1..], 8) {
                Ok(value) => Tok::Int { value, raw },
                Err(_) => Tok::Bad(format!("malformed octal literal `{raw}`")),
            }
        } else {
            match digits.parse::<u64>() {
                Ok(value) => Tok::Int { value, raw },
                Err(_) => Tok::Bad(format!("integer literal `{raw}` is too large")),
            }
        };
        if self.i < n && is_ident(b[self.i]) {
            // `12abc`: report once for the whole word.
            while self.i < n && is_ident(b[self.i]) {
                self.bump();
            }
            let raw = &self.s[s..self.i];
            return self.push(Tok::Bad(format!("malformed number `{raw}`")), start);
        }
        self.push(tok, start)
    }

    /// A string or character literal (the `L` of a wide one already consumed).
    fn quoted(&mut self, start: Pos, wide: bool) -> Result<(), (Pos, String, bool)> {
        let raw_start = if wide { self.i - 1 } else { self.i };
        let q = self.b[self.i];
        self.bump();
        let mut value = String::new();
        let mut bad: Option<String> = None;
        loop {
            if self.i >= self.b.len() || matches!(self.b[self.i], b'\n' | b'\r') {
                let what = if q == b'"' { "string" } else { "character" };
                let raw = &self.s[raw_start..self.i];
                return self.push(
                    Tok::Bad(format!(
                        "unterminated {what} literal {}",
                        shorten(raw.trim_end())
                    )),
                    start,
                );
            }
            let c = self.b[self.i];
            if c == q {
                self.bump();
                break;
            }
            if c == b'\\' {
                self.bump();
                let e = self.peek(0);
                if e == 0 && self.i >= self.b.len() {
                    continue;
                }
                let simple = match e {
                    b'n' => Some('\n'),
                    b't' => Some('\t'),
                    b'v' => Some('\x0b'),
                    b'b' => Some('\x08'),
                    b'r' => Some('\r'),
                    b'f' => Some('\x0c'),
                    b'a' => Some('\x07'),
                    b'\\' => Some('\\'),
                    b'?' => Some('?'),
                    b'\'' => Some('\''),
                    b'"' => Some('"'),
                    _ => None,
                };
                if let Some(ch) = simple {
                    self.bump();
                    value.push(ch);
                    continue;
                }
                let (radix, max, skip) = match e {
                    b'x' => (16, 2, 1),
                    b'u' => (16, 4, 1),
                    b'0'..=b'7' => (8, 3, 0),
                    _ => (0, 0, 0),
                };
                if radix == 0 {
                    if e == b'\n' || e == b'\r' {
                        continue;
                    }
                    bad.get_or_insert_with(|| "unknown escape sequence".into());
                    continue;
                }
                for _ in 0..skip {
                    self.bump();
                }
                let ds = self.i;
                while self.i < self.b.len()
                    && self.i - ds < max
                    && (self.b[self.i] as char).is_digit(radix)
                {
                    self.bump();
                }
                match u32::from_str_radix(&self.s[ds..self.i], radix)
                    .ok()
                    .and_then(char::from_u32)
                {
                    Some(ch) => value.push(ch),
                    None => {
                        bad.get_or_insert_with(|| "malformed numeric escape".into());
                    }
                }
                continue;
            }
            value.push_str(self.char());
        }
        let raw = self.s[raw_start..self.i].to_string();
        if let Some(m) = bad {
            return self.push(Tok::Bad(format!("{m} in literal {}", shorten(&raw))), start);
        }
        let tok = if q == b'"' {
            Tok::Str { value, raw }
        } else {
            let mut it = value.chars();
            match (it.next(), it.next()) {
                (Some(ch), None) => Tok::Char { value: ch, raw },
                _ => Tok::Bad(format!(
                    "character literal {raw} must hold exactly one character"
                )),
            }
        };
        self.push(tok, start)
    }
}

/// Strips a block doc comment's body: per line the leading whitespace and `*`s and one space;
/// blank leading and trailing lines removed.
pub(crate) fn strip_block(body: &str) -> String {
    let mut lines: Vec<&str> = Vec::new();
    for line in body.lines() {
        let t = line.trim_start();
        let t = if t.starts_with('*') {
            let t = t.trim_start_matches('*');
            t.strip_prefix(' ').unwrap_or(t)
        } else {
            t
        };
        lines.push(t.trim_end());
    }
    while lines.first().is_some_and(|l| l.is_empty()) {
        lines.remove(0);
    }
    while lines.last().is_some_and(|l| l.is_empty()) {
        lines.pop();
    }
    lines.join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(s: &str) -> Vec<Tok> {
        lex(s, usize::MAX)
            .tokens
            .into_iter()
            .map(|t| t.tok)
            .collect()
    }

    #[test]
    fn literals_and_punctuation() {
        let t = kinds("0x1F 017 42 1.5e3 'a' L\"w\" \"a\\tb\" :: >> ;");
        assert_eq!(
            t[..3],
            [
                Tok::Int {
                    value: 31,
                    raw: "0x1F".into()
                },
                Tok::Int {
                    value: 15,
                    raw: "017".into()
                },
                Tok::Int {
                    value: 42,
                    raw: "42".into()
                },
            ]
        );
        assert!(matches!(t[3], Tok::Float { value, .. } if value == 1500.0));
        assert!(matches!(t[4], Tok::Char { value: 'a', .. }));
        assert!(matches!(&t[5], Tok::Str { value, raw } if value == "w" && raw == "L\"w\""));
        assert!(matches!(&t[6], Tok::Str { value, .. } if value == "a\tb"));
        assert_eq!(
            t[7..11],
            [
                Tok::Punct("::"),
                Tok::Punct(">>"),
                Tok::Punct(";"),
                Tok::Eof
            ]
        );
    }

    #[test]
    fn positions_count_characters_and_all_line_ends() {
        let out = lex("a\r\nb\rc\n  é d", usize::MAX);
        let p: Vec<(u32, u32)> = out
            .tokens
            .iter()
            .map(|t| (t.pos.line, t.pos.column))
            .collect();
        assert_eq!(p, [(1, 1), (2, 1), (3, 1), (4, 3), (4, 5), (4, 6)]);
    }

    #[test]
    fn doc_comments_and_plain_comments() {
        let t = kinds("/** a\n * b */ /* no */ // no\n/// c\n//! d\n//!< e\n///< f\n/**< g */ //// no\n/*! h */ /***/ /**/");
        let docs: Vec<(String, bool)> = t
            .into_iter()
            .filter_map(|t| match t {
                Tok::Doc { text, after } => Some((text, after)),
                _ => None,
            })
            .collect();
        let want = [
            ("a\nb", false),
            ("c", false),
            ("d", false),
            ("e", true),
            ("f", true),
            ("g", true),
            ("h", false),
        ];
        assert_eq!(docs.len(), want.len(), "{docs:?}");
        for (g, w) in docs.iter().zip(want) {
            assert_eq!((g.0.as_str(), g.1), w);
        }
    }

    #[test]
    fn directives_only_at_line_start() {
        let t = kinds("#include <tao/orb.idl> // c\n  # define X 1 \\\n 2\na # b");
        match &t[0] {
            Tok::Directive(d) => assert_eq!(
                (d.name.as_str(), d.raw.as_str()),
                ("include", "<tao/orb.idl>")
            ),
            other => panic!("{other:?}"),
        }
        match &t[1] {
            Tok::Directive(d) => {
                assert_eq!((d.name.as_str(), d.raw.as_str()), ("define", "X 1   2"))
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(t[3], Tok::Punct("#"));
    }

    #[test]
    fn bad_input_is_tokens_not_failures() {
        let out = lex("a $ \"open\n 99999999999999999999999 'ab'", usize::MAX);
        let bad = out
            .tokens
            .iter()
            .filter(|t| matches!(t.tok, Tok::Bad(_)))
            .count();
        assert_eq!(bad, 4);
        assert!(lex("/* never closed", usize::MAX).fatal.is_some());
        assert!(lex("a b c d", 2).fatal.is_some_and(|f| f.2));
    }
}
