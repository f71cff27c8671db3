//! A tokenizer for the three languages RTCBuilder generates (C++, Python, Java): identifiers,
//! string literals (decoded), numbers and punctuation, each with its line and column; comments
//! and C++ preprocessor lines are dropped, so a callback or a registration that is commented
//! out (`// addInPort(…)`, `#def onActivated`, `/* RTC::ReturnCode_t X::onFinalize() … */`) is
//! not code. Brackets are matched once (`Tokens::close`), so the extractors walk a tree of
//! balanced groups instead of matching text.
//!
//! Why not tree-sitter: what the check reads is a handful of call and declaration shapes
//! (`addInPort("x", m_xIn)`, `InPort<T> m_xIn;`, `def onExecute(self, ec_id):`), and what
//! makes reading them robust is exactly what this lexer does — comments, strings (raw, triple
//! quoted, prefixed), continuation lines and bracket nesting — while a grammar would add three
//! C parsers (tens of MB of generated C, minutes of build on 2 cores, a C toolchain for the
//! wheels) and still not expand macros. Every input is read in one linear pass with a bounded
//! nesting depth.

use crate::model::Pos;

/// The languages an implementation is read in.
#[derive(
    Debug,
    Clone,
    Copy,
    Default,
    PartialEq,
    Eq,
    PartialOrd,
    Ord,
    Hash,
    serde::Serialize,
    serde::Deserialize,
)]
pub enum Language {
    #[default]
    #[serde(rename = "C++")]
    Cpp,
    Python,
    Java,
}

impl Language {
    pub fn name(self) -> &'static str {
        match self {
            Language::Cpp => "C++",
            Language::Python => "Python",
            Language::Java => "Java",
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Kind {
    Ident,
    /// A string literal (its decoded value in [`Token::value`]).
    Str,
    Number,
    /// One punctuation character, or `::` / `->`.
    Punct,
    Open(u8),
    Close(u8),
}

#[derive(Debug, Clone)]
pub struct Token {
    pub kind: Kind,
    /// Byte range of the token in the text.
    pub start: usize,
    pub end: usize,
    pub pos: Pos,
    /// The decoded value of a string literal.
    pub value: Option<String>,
    /// Python: the token begins a logical line (its column is the line's indentation).
    pub line_start: bool,
}

/// The deepest bracket nesting read; a deeper file is refused (named, never a stack overflow).
pub const MAX_DEPTH: usize = 256;
/// The most tokens read of one file (a 16 MiB file of one-character tokens stays bounded).
pub const MAX_TOKENS: usize = 4_000_000;

pub struct Tokens<'a> {
    pub text: &'a str,
    pub toks: Vec<Token>,
    /// For an opening bracket, the index of its closing one (`toks.len()` when unclosed).
    pub close: Vec<usize>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LexError {
    pub message: String,
    pub pos: Pos,
}

impl<'a> Tokens<'a> {
    pub fn tok(&self, i: usize) -> Option<&Token> {
        self.toks.get(i)
    }
    pub fn src(&self, i: usize) -> &'a str {
        self.toks
            .get(i)
            .map_or("", |t| self.text.get(t.start..t.end).unwrap_or(""))
    }
    /// Whether token `i` is the identifier or punctuation `s`.
    pub fn is(&self, i: usize, s: &str) -> bool {
        self.toks.get(i).is_some_and(|t| {
            matches!(t.kind, Kind::Ident | Kind::Punct) && self.text.get(t.start..t.end) == Some(s)
        })
    }
    pub fn is_open(&self, i: usize, b: u8) -> bool {
        self.toks.get(i).is_some_and(|t| t.kind == Kind::Open(b))
    }
    pub fn is_ident(&self, i: usize) -> bool {
        self.toks.get(i).is_some_and(|t| t.kind == Kind::Ident)
    }
    /// The source text from token `a` to token `b` (exclusive), spaces collapsed.
    pub fn span_text(&self, a: usize, b: usize) -> String {
        let (Some(s), Some(e)) = (
            self.toks.get(a),
            b.checked_sub(1).and_then(|l| self.toks.get(l)),
        ) else {
            return String::new();
        };
        if e.end < s.start {
            return String::new();
        }
        let raw = self.text.get(s.start..e.end).unwrap_or("");
        raw.split_whitespace().collect::<Vec<_>>().join(" ")
    }
    /// The arguments of the group opened at `open` (a `(`, `[` or `{`): the token ranges
    /// between its commas at its own level.
    pub fn args(&self, open: usize) -> Vec<(usize, usize)> {
        let end = self.close.get(open).copied().unwrap_or(open + 1);
        let mut out = Vec::new();
        let mut start = open + 1;
        let mut i = open + 1;
        while i < end {
            match self.toks[i].kind {
                Kind::Open(_) => {
                    i = self.close[i].max(i) + 1;
                    continue;
                }
                Kind::Punct if self.is(i, ",") => {
                    out.push((start, i));
                    start = i + 1;
                }
                _ => {}
            }
            i += 1;
        }
        if start < end || !out.is_empty() {
            out.push((start, end.min(self.toks.len())));
        }
        out
    }
    /// The string an argument range holds when it is only string literals (adjacent ones
    /// joined, as C++ and Python join them), else `None`.
    pub fn literal(&self, (a, b): (usize, usize)) -> Option<String> {
        if a >= b {
            return None;
        }
        let mut s = String::new();
        for t in &self.toks[a..b] {
            s.push_str(t.value.as_deref().filter(|_| t.kind == Kind::Str)?);
        }
        Some(s)
    }
}

/// Reads `text` as `lang`.
pub fn lex(text: &str, lang: Language) -> Result<Tokens<'_>, LexError> {
    let mut l = Lexer {
        b: text.as_bytes(),
        text,
        i: 0,
        line: 1,
        line_start_byte: 0,
        lang,
        toks: Vec::new(),
        at_line_start: true,
    };
    l.run()?;
    let toks = l.toks;
    let mut close = vec![usize::MAX; toks.len()];
    let mut stack: Vec<usize> = Vec::new();
    for (i, t) in toks.iter().enumerate() {
        match t.kind {
            Kind::Open(_) => {
                if stack.len() >= MAX_DEPTH {
                    return Err(LexError {
                        message: format!("brackets nested deeper than {MAX_DEPTH} levels"),
                        pos: t.pos,
                    });
                }
                stack.push(i);
            }
            Kind::Close(_) => {
                // A stray closing bracket (an unbalanced `#if` branch) closes nothing.
                if let Some(o) = stack.pop() {
                    close[o] = i;
                }
            }
            _ => {}
        }
    }
    for o in stack {
        close[o] = toks.len();
    }
    Ok(Tokens { text, toks, close })
}

struct Lexer<'a> {
    b: &'a [u8],
    text: &'a str,
    i: usize,
    line: u32,
    line_start_byte: usize,
    lang: Language,
    toks: Vec<Token>,
    /// Python: no token yet on this logical line.
    at_line_start: bool,
}

impl Lexer<'_> {
    fn pos(&self, at: usize) -> Pos {
        let col = self
            .text
            .get(self.line_start_byte..at)
            .map_or(0, |s| s.chars().count());
        Pos::new(self.line, u32::try_from(col + 1).unwrap_or(u32::MAX))
    }
    fn newline(&mut self, at: usize) {
        self.line = self.line.saturating_add(1);
        self.line_start_byte = at + 1;
    }
    fn peek(&self, k: usize) -> u8 {
        self.b.get(self.i + k).copied().unwrap_or(0)
    }
    fn push(
        &mut self,
        kind: Kind,
        start: usize,
        value: Option<String>,
        depth: usize,
    ) -> Result<(), LexError> {
        if self.toks.len() >= MAX_TOKENS {
            return Err(LexError {
                message: format!("more than {MAX_TOKENS} tokens"),
                pos: self.pos(start),
            });
        }
        let line_start = self.lang == Language::Python && self.at_line_start && depth == 0;
        self.at_line_start = false;
        let pos = self.pos(start);
        self.toks.push(Token {
            kind,
            start,
            end: self.i,
            pos,
            value,
            line_start,
        });
        Ok(())
    }

    fn run(&mut self) -> Result<(), LexError> {
        let mut depth: usize = 0;
        // A C++ preprocessor directive may start a line (after spaces).
        let mut line_has_code = false;
        while self.i < self.b.len() {
            let c = self.b[self.i];
            let start = self.i;
            match c {
                b'\n' => {
                    self.newline(self.i);
                    self.i += 1;
                    line_has_code = false;
                    if depth == 0 {
                        self.at_line_start = true;
                    }
                }
                b' ' | b'\t' | b'\r' | 0x0c => self.i += 1,
                b'\\'
                    if self.peek(1) == b'\n'
                        || (self.peek(1) == b'\r' && self.peek(2) == b'\n') =>
                {
                    // A continuation line joins the next one.
                    self.i += if self.peek(1) == b'\r' { 2 } else { 1 };
                    self.newline(self.i);
                    self.i += 1;
                }
                b'#' if self.lang == Language::Python => self.skip_line(),
                b'#' if self.lang == Language::Cpp && !line_has_code => self.skip_directive(),
                b'/' if self.lang != Language::Python && self.peek(1) == b'/' => self.skip_line(),
                b'/' if self.lang != Language::Python && self.peek(1) == b'*' => {
                    self.i += 2;
                    while self.i < self.b.len() && !(self.b[self.i] == b'*' && self.peek(1) == b'/')
                    {
                        if self.b[self.i] == b'\n' {
                            self.newline(self.i);
                        }
                        self.i += 1;
                    }
                    self.i = (self.i + 2).min(self.b.len());
                }
                b'"' | b'\'' => {
                    line_has_code = true;
                    if c == b'\'' && self.lang != Language::Python {
                        self.char_literal();
                        self.push(Kind::Number, start, None, depth)?;
                    } else {
                        let v = self.string(0)?;
                        self.push(Kind::Str, start, Some(v), depth)?;
                    }
                }
                b'(' | b'[' | b'{' => {
                    line_has_code = true;
                    self.i += 1;
                    self.push(Kind::Open(c), start, None, depth)?;
                    depth += 1;
                }
                b')' | b']' | b'}' => {
                    line_has_code = true;
                    self.i += 1;
                    depth = depth.saturating_sub(1);
                    self.push(Kind::Close(c), start, None, depth)?;
                }
                c if c.is_ascii_digit() => {
                    line_has_code = true;
                    self.i += 1;
                    while self.i < self.b.len() {
                        let d = self.b[self.i];
                        let sep = d == b'\''
                            && self.lang == Language::Cpp
                            && self.peek(1).is_ascii_alphanumeric();
                        let exponent =
                            (d == b'+' || d == b'-') && matches!(self.b[self.i - 1], b'e' | b'E');
                        if d.is_ascii_alphanumeric() || d == b'.' || d == b'_' || sep || exponent {
                            self.i += 1;
                        } else {
                            break;
                        }
                    }
                    self.push(Kind::Number, start, None, depth)?;
                }
                c if c.is_ascii_alphabetic() || c == b'_' || c == b'$' || c >= 0x80 => {
                    line_has_code = true;
                    while self.i < self.b.len() {
                        let d = self.b[self.i];
                        if d.is_ascii_alphanumeric() || d == b'_' || d == b'$' || d >= 0x80 {
                            self.i += 1;
                        } else {
                            break;
                        }
                    }
                    // A prefixed string literal: L"", u8"", R"(…)" in C++; r'', b"", f"" in Python.
                    let word = &self.text[start..self.i];
                    let q = self.peek(0);
                    if q == b'"' || (q == b'\'' && self.lang == Language::Python) {
                        let raw_prefix = match self.lang {
                            Language::Cpp => matches!(word, "R" | "LR" | "uR" | "UR" | "u8R"),
                            Language::Python => {
                                word.len() <= 2
                                    && word.chars().all(|ch| "rRbBuUfF".contains(ch))
                                    && word.contains(['r', 'R'])
                            }
                            Language::Java => false,
                        };
                        let prefix = match self.lang {
                            Language::Cpp => matches!(word, "L" | "u" | "U" | "u8") || raw_prefix,
                            Language::Python => {
                                word.len() <= 2 && word.chars().all(|ch| "rRbBuUfF".contains(ch))
                            }
                            Language::Java => false,
                        };
                        if prefix {
                            let v = if raw_prefix && self.lang == Language::Cpp {
                                self.cpp_raw_string(start)?
                            } else {
                                self.string(u8::from(raw_prefix))?
                            };
                            self.push(Kind::Str, start, Some(v), depth)?;
                            continue;
                        }
                    }
                    self.push(Kind::Ident, start, None, depth)?;
                }
                _ => {
                    line_has_code = true;
                    let two = (c, self.peek(1));
                    self.i += if matches!(two, (b':', b':') | (b'-', b'>')) {
                        2
                    } else {
                        1
                    };
                    self.push(Kind::Punct, start, None, depth)?;
                }
            }
        }
        Ok(())
    }

    fn skip_line(&mut self) {
        while self.i < self.b.len() && self.b[self.i] != b'\n' {
            self.i += 1;
        }
    }

    /// A preprocessor line, with its continuation lines and any comment in it.
    fn skip_directive(&mut self) {
        while self.i < self.b.len() {
            match self.b[self.i] {
                b'\n' => return,
                b'\\' if self.peek(1) == b'\n' => {
                    self.i += 1;
                    self.newline(self.i);
                }
                b'/' if self.peek(1) == b'*' => {
                    self.i += 2;
                    while self.i < self.b.len() && !(self.b[self.i] == b'*' && self.peek(1) == b'/')
                    {
                        if self.b[self.i] == b'\n' {
                            self.newline(self.i);
                        }
                        self.i += 1;
                    }
                    self.i += 1;
                }
                _ => {}
            }
            self.i += 1;
        }
    }

    fn char_literal(&mut self) {
        self.i += 1;
        while self.i < self.b.len() {
            match self.b[self.i] {
                b'\\' => self.i += 2,
                b'\'' => {
                    self.i += 1;
                    return;
                }
                b'\n' => return,
                _ => self.i += 1,
            }
        }
        self.i = self.i.min(self.b.len());
    }

    /// A quoted string at `self.i` (`raw`: escapes kept as written). Python's triple quotes
    /// span lines; any other string ends at its line's end when unclosed.
    fn string(&mut self, raw: u8) -> Result<String, LexError> {
        let q = self.b[self.i];
        let triple = self.lang == Language::Python && self.peek(1) == q && self.peek(2) == q;
        self.i += if triple { 3 } else { 1 };
        let mut out = String::new();
        let mut seg = self.i;
        while self.i < self.b.len() {
            let c = self.b[self.i];
            if c == q && (!triple || (self.peek(1) == q && self.peek(2) == q)) {
                out.push_str(&self.text[seg..self.i]);
                self.i += if triple { 3 } else { 1 };
                return Ok(out);
            }
            match c {
                b'\n' if !triple => break,
                b'\n' => {
                    self.newline(self.i);
                    self.i += 1;
                }
                b'\\' if raw == 0 => {
                    out.push_str(&self.text[seg..self.i]);
                    let e = self.peek(1);
                    let (s, n) = match e {
                        b'n' => ("\n", 2),
                        b't' => ("\t", 2),
                        b'r' => ("\r", 2),
                        b'0' => ("\0", 2),
                        b'\\' => ("\\", 2),
                        b'"' => ("\"", 2),
                        b'\'' => ("'", 2),
                        b'\n' => {
                            self.newline(self.i + 1);
                            ("", 2)
                        }
                        _ => ("\\", 1),
                    };
                    out.push_str(s);
                    self.i += n;
                    seg = self.i;
                }
                b'\\' => self.i += 2,
                _ => self.i += 1,
            }
        }
        self.i = self.i.min(self.b.len());
        out.push_str(self.text.get(seg..self.i).unwrap_or(""));
        Ok(out)
    }

    /// C++ `R"delim( … )delim"`.
    fn cpp_raw_string(&mut self, start: usize) -> Result<String, LexError> {
        self.i += 1;
        let d0 = self.i;
        while self.i < self.b.len() && self.b[self.i] != b'(' && self.i - d0 <= 16 {
            self.i += 1;
        }
        let delim = format!("){}\"", &self.text[d0..self.i]);
        let body = self.i + 1;
        let Some(rel) = self.text.get(body..).and_then(|t| t.find(&delim)) else {
            return Err(LexError {
                message: "a raw string literal is not closed".into(),
                pos: self.pos(start),
            });
        };
        let v = self.text[body..body + rel].to_string();
        for (k, _) in v.match_indices('\n') {
            self.newline(body + k);
        }
        self.i = body + rel + delim.len();
        Ok(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str, lang: Language) -> Vec<String> {
        let t = lex(text, lang).unwrap();
        (0..t.toks.len())
            .map(|i| match &t.toks[i].kind {
                Kind::Str => format!("{:?}", t.toks[i].value.as_deref().unwrap_or("")),
                _ => t.src(i).to_string(),
            })
            .collect()
    }

    #[test]
    fn comments_and_directives_are_not_code() {
        let k = kinds(
            "#include \"X.h\"\n// addInPort(\"a\", m_a);\n/* RTC::ReturnCode_t X::onFinalize()\n{ return RTC::RTC_OK; } */\naddOutPort(\"b\", m_bOut);",
            Language::Cpp,
        );
        assert_eq!(k, ["addOutPort", "(", "\"b\"", ",", "m_bOut", ")", ";"]);
        let t = lex("/* a\nb */ x", Language::Cpp).unwrap();
        assert_eq!(t.toks[0].pos, Pos::new(2, 6));
    }

    #[test]
    fn strings_are_decoded() {
        let t = lex(
            r#"f("a\"b" "c", R"x(raw)" )x", L"w", u8"v")"#,
            Language::Cpp,
        )
        .unwrap();
        let args = t.args(1);
        assert_eq!(t.literal(args[0]).as_deref(), Some("a\"bc"));
        assert_eq!(t.literal(args[1]).as_deref(), Some("raw)\" "));
        assert_eq!(t.literal(args[2]).as_deref(), Some("w"));
        let p = lex(
            "x = '''a\n'b'''\n# def onActivated(self):\ny = r'\\d'",
            Language::Python,
        )
        .unwrap();
        assert_eq!(p.toks[2].value.as_deref(), Some("a\n'b"));
        assert_eq!(p.toks[3].pos, Pos::new(4, 1));
        assert!(p.toks[3].line_start);
        assert_eq!(p.toks[5].value.as_deref(), Some("\\d"));
    }

    #[test]
    fn python_logical_lines() {
        let p = lex("a = f(\n  1)\n  b", Language::Python).unwrap();
        let starts: Vec<_> = p
            .toks
            .iter()
            .filter(|t| t.line_start)
            .map(|t| t.pos)
            .collect();
        assert_eq!(starts, [Pos::new(1, 1), Pos::new(3, 3)]);
    }

    #[test]
    fn nesting_is_bounded() {
        let deep = "(".repeat(MAX_DEPTH + 1);
        let e = lex(&deep, Language::Cpp).err().unwrap();
        assert!(e.message.contains("nested deeper"), "{e:?}");
        assert!(lex(&"(".repeat(MAX_DEPTH), Language::Java).is_ok());
    }
}
