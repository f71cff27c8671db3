//! Constant expressions, shared by `const` declarations, bounds and array sizes (IDL 7.4.1.4.4:
//! `| ^ & << >> + - * / % ~` and unary `- +`) and by `#if` (which adds `! && || == != < > <= >=
//! ?:`). Precedence climbing over a fixed table of levels; the only recursion that grows with
//! the input is a parenthesis (and `?:`), which counts against the nesting limit, so
//! 100,000 `(` are an error rather than a stack overflow. Unary operators are applied in a loop.

use super::lex::{Tok, Token};
use crate::model::Pos;

/// A value during evaluation.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Value {
    Int(i128),
    Float(f64),
    Str(String),
    Char(char),
    Bool(bool),
    /// An enumerator, by scoped name.
    Enumerator(String),
}

impl Value {
    fn truthy(&self) -> bool {
        match self {
            Value::Int(i) => *i != 0,
            Value::Float(f) => *f != 0.0,
            Value::Bool(b) => *b,
            _ => true,
        }
    }
}

/// What an evaluation gives: `Ok(None)` when the expression is well-formed but refers to
/// something whose value is not known here.
pub(crate) type EvalResult = Result<Option<Value>, (Pos, String)>;

pub(crate) struct Eval<'t, F: FnMut(&str) -> Option<Value>> {
    pub toks: &'t [Token],
    pub i: usize,
    depth: usize,
    max_depth: usize,
    pp: bool,
    resolve: F,
}

const IDL_LEVELS: &[&[&str]] = &[
    &["|"],
    &["^"],
    &["&"],
    &["<<", ">>"],
    &["+", "-"],
    &["*", "/", "%"],
];
const PP_LEVELS: &[&[&str]] = &[
    &["||"],
    &["&&"],
    &["|"],
    &["^"],
    &["&"],
    &["==", "!="],
    &["<", ">", "<=", ">="],
    &["<<", ">>"],
    &["+", "-"],
    &["*", "/", "%"],
];

impl<'t, F: FnMut(&str) -> Option<Value>> Eval<'t, F> {
    pub fn new(toks: &'t [Token], i: usize, max_depth: usize, pp: bool, resolve: F) -> Self {
        Eval {
            toks,
            i,
            depth: 0,
            max_depth,
            pp,
            resolve,
        }
    }

    fn skip_trivia(&mut self) {
        while let Some(t) = self.toks.get(self.i) {
            match t.tok {
                Tok::Doc { .. } | Tok::Pragma(_) | Tok::IncludeMark => self.i += 1,
                _ => break,
            }
        }
    }
    fn peek(&mut self) -> Option<&'t Token> {
        self.skip_trivia();
        self.toks.get(self.i)
    }
    fn punct(&mut self) -> Option<&'static str> {
        match self.peek() {
            Some(Token {
                tok: Tok::Punct(p), ..
            }) => Some(p),
            _ => None,
        }
    }
    fn here(&mut self) -> Pos {
        self.peek()
            .map(|t| t.pos)
            .or_else(|| self.toks.last().map(|t| t.pos))
            .unwrap_or_default()
    }

    /// A whole expression (`?:` in `#if`).
    pub fn expr(&mut self) -> EvalResult {
        let c = self.binary(0)?;
        if self.pp && self.punct() == Some("?") {
            let a = self.nested()?;
            if self.punct() != Some(":") {
                let p = self.here();
                return Err((p, "expected `:` in `?:` expression".into()));
            }
            let b = self.nested()?;
            return Ok(match c {
                Some(c) => {
                    if c.truthy() {
                        a
                    } else {
                        b
                    }
                }
                None => None,
            });
        }
        Ok(c)
    }

    /// The expression after the current token (a `?`, `:` or `(`), one level deeper.
    fn nested(&mut self) -> EvalResult {
        self.i += 1;
        self.enter()?;
        let v = self.expr();
        self.depth -= 1;
        v
    }

    fn enter(&mut self) -> Result<(), (Pos, String)> {
        self.depth += 1;
        if self.depth > self.max_depth {
            let p = self.here();
            return Err((
                p,
                format!(
                    "expression nests deeper than {} levels (the nesting limit)",
                    self.max_depth
                ),
            ));
        }
        Ok(())
    }

    fn binary(&mut self, level: usize) -> EvalResult {
        let levels = if self.pp { PP_LEVELS } else { IDL_LEVELS };
        if level >= levels.len() {
            return self.unary();
        }
        let mut lhs = self.binary(level + 1)?;
        while let Some(op) = self.punct().filter(|p| levels[level].contains(p)) {
            let pos = self.here();
            self.i += 1;
            let rhs = self.binary(level + 1)?;
            lhs = match (lhs, rhs) {
                (Some(a), Some(b)) => binop(op, a, b).map_err(|m| (pos, m))?,
                _ => None,
            };
        }
        Ok(lhs)
    }

    fn unary(&mut self) -> EvalResult {
        let mut ops = Vec::new();
        while let Some(op) = self
            .punct()
            .filter(|p| matches!(*p, "-" | "+" | "~") || (self.pp && *p == "!"))
        {
            ops.push((op, self.here()));
            self.i += 1;
        }
        let mut v = self.primary()?;
        for (op, pos) in ops.into_iter().rev() {
            v = match v {
                Some(v) => unop(op, v).map_err(|m| (pos, m))?,
                None => None,
            };
        }
        Ok(v)
    }

    fn primary(&mut self) -> EvalResult {
        let Some(t) = self.peek() else {
            let p = self.here();
            return Err((
                p,
                "expected an expression, found the end of the line".into(),
            ));
        };
        let pos = t.pos;
        match &t.tok {
            Tok::Int { value, .. } => {
                self.i += 1;
                Ok(Some(Value::Int(*value as i128)))
            }
            Tok::Float { value, .. } => {
                self.i += 1;
                Ok(Some(Value::Float(*value)))
            }
            Tok::Char { value, .. } => {
                self.i += 1;
                Ok(Some(Value::Char(*value)))
            }
            Tok::Str { .. } => {
                // Adjacent string literals concatenate.
                let mut s = String::new();
                while let Some(Token {
                    tok: Tok::Str { value, .. },
                    ..
                }) = self.peek()
                {
                    s.push_str(value);
                    self.i += 1;
                }
                Ok(Some(Value::Str(s)))
            }
            Tok::Ident(w) if w == "TRUE" => {
                self.i += 1;
                Ok(Some(Value::Bool(true)))
            }
            Tok::Ident(w) if w == "FALSE" => {
                self.i += 1;
                Ok(Some(Value::Bool(false)))
            }
            Tok::Ident(_) | Tok::Punct("::") => {
                let name = self.scoped_name()?;
                Ok((self.resolve)(&name))
            }
            Tok::Punct("(") => {
                let v = self.nested()?;
                if self.punct() != Some(")") {
                    let t = self.peek().map(|t| t.describe()).unwrap_or_default();
                    let p = self.here();
                    return Err((p, format!("expected `)` in expression, found {t}")));
                }
                self.i += 1;
                Ok(v)
            }
            _ => Err((
                pos,
                format!("expected an expression, found {}", t.describe()),
            )),
        }
    }

    fn scoped_name(&mut self) -> Result<String, (Pos, String)> {
        let mut name = String::new();
        if self.punct() == Some("::") {
            name.push_str("::");
            self.i += 1;
        }
        loop {
            match self.peek() {
                Some(Token {
                    tok: Tok::Ident(w), ..
                }) => {
                    name.push_str(w.strip_prefix('_').unwrap_or(w));
                    self.i += 1;
                }
                _ => {
                    let p = self.here();
                    return Err((p, "expected a name after `::`".into()));
                }
            }
            if self.punct() == Some("::") {
                name.push_str("::");
                self.i += 1;
            } else {
                return Ok(name);
            }
        }
    }
}

fn as_f64(v: &Value) -> Option<f64> {
    match v {
        Value::Int(i) => Some(*i as f64),
        Value::Float(f) => Some(*f),
        _ => None,
    }
}

fn int_range(v: i128) -> Result<Option<Value>, String> {
    if v < i64::MIN as i128 || v > u64::MAX as i128 {
        Err("integer overflow in constant expression".into())
    } else {
        Ok(Some(Value::Int(v)))
    }
}

fn binop(op: &str, a: Value, b: Value) -> Result<Option<Value>, String> {
    use Value::*;
    match (&a, &b) {
        (Int(x), Int(y)) => {
            let (x, y) = (*x, *y);
            let r = match op {
                "|" => x | y,
                "^" => x ^ y,
                "&" => x & y,
                "+" => x + y,
                "-" => x - y,
                "*" => x
                    .checked_mul(y)
                    .ok_or("integer overflow in constant expression")?,
                "/" | "%" => {
                    if y == 0 {
                        return Err("division by zero in constant expression".into());
                    }
                    if op == "/" {
                        x / y
                    } else {
                        x % y
                    }
                }
                "<<" | ">>" => {
                    if !(0..64).contains(&y) {
                        return Err(format!("shift by {y} is out of range (0 to 63)"));
                    }
                    if op == "<<" {
                        ((x as u64) << y) as i128
                    } else {
                        x >> y
                    }
                }
                "&&" => ((x != 0) && (y != 0)) as i128,
                "||" => ((x != 0) || (y != 0)) as i128,
                "==" => (x == y) as i128,
                "!=" => (x != y) as i128,
                "<" => (x < y) as i128,
                ">" => (x > y) as i128,
                "<=" => (x <= y) as i128,
                ">=" => (x >= y) as i128,
                _ => return Ok(None),
            };
            int_range(r)
        }
        (Int(_) | Float(_), Int(_) | Float(_)) => {
            let (Some(x), Some(y)) = (as_f64(&a), as_f64(&b)) else {
                return Ok(None);
            };
            Ok(Some(match op {
                "+" => Float(x + y),
                "-" => Float(x - y),
                "*" => Float(x * y),
                "/" => {
                    if y == 0.0 {
                        return Err("division by zero in constant expression".into());
                    }
                    Float(x / y)
                }
                _ => return Ok(None),
            }))
        }
        (Bool(x), Bool(y)) => Ok(match op {
            "|" => Some(Bool(*x | *y)),
            "&" => Some(Bool(*x & *y)),
            "^" => Some(Bool(*x ^ *y)),
            _ => None,
        }),
        _ => Ok(None),
    }
}

fn unop(op: &str, v: Value) -> Result<Option<Value>, String> {
    Ok(match (op, v) {
        ("-", Value::Int(i)) => return int_range(-i),
        ("-", Value::Float(f)) => Some(Value::Float(-f)),
        ("+", v @ (Value::Int(_) | Value::Float(_))) => Some(v),
        ("~", Value::Int(i)) => Some(Value::Int(if i < 0 { !i } else { (!(i as u64)) as i128 })),
        ("~", Value::Bool(b)) => Some(Value::Bool(!b)),
        ("!", v) => Some(Value::Int(!v.truthy() as i128)),
        _ => None,
    })
}

/// The tokens of an expression as text: lexemes joined by single spaces, except inside `::`
/// names and next to brackets.
pub(crate) fn text_of(toks: &[Token]) -> String {
    let mut s = String::new();
    let mut prev: Option<&str> = None;
    // Whether `prev` is a unary sign (it followed an operator or opened the expression).
    let mut prev_unary = false;
    for t in toks {
        if matches!(
            t.tok,
            Tok::Doc { .. } | Tok::Pragma(_) | Tok::IncludeMark | Tok::Eof
        ) {
            continue;
        }
        let lx = t.lexeme();
        let tight = matches!(prev, Some("::") | Some("(") | Some("~") | None)
            || lx == "::" && !matches!(prev, Some(p) if is_op(p))
            || lx == ")"
            || (matches!(prev, Some("-") | Some("+")) && prev_unary);
        if !tight {
            s.push(' ');
        }
        s.push_str(&lx);
        let cur = match &t.tok {
            Tok::Punct(p) => p,
            _ => "x",
        };
        prev_unary = matches!(cur, "-" | "+") && prev.is_none_or(|p| is_op(p) || p == "(");
        prev = Some(cur);
    }
    s
}

fn is_op(p: &str) -> bool {
    matches!(
        p,
        "|" | "^" | "&" | "<<" | ">>" | "+" | "-" | "*" | "/" | "%" | "," | "=" | "<" | ">"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::idl::lex::lex;

    fn eval(s: &str, pp: bool) -> EvalResult {
        let toks = lex(s, usize::MAX).tokens;
        let mut e = Eval::new(&toks, 0, 64, pp, |n: &str| {
            (n == "TEN").then_some(Value::Int(10))
        });
        e.expr()
    }

    #[test]
    fn arithmetic_follows_idl_precedence() {
        assert_eq!(eval("1 + 2 * 3", false), Ok(Some(Value::Int(7))));
        assert_eq!(eval("(1 + 2) * 3", false), Ok(Some(Value::Int(9))));
        assert_eq!(eval("1 << 4 | 1", false), Ok(Some(Value::Int(17))));
        assert_eq!(eval("- - 5", false), Ok(Some(Value::Int(5))));
        assert_eq!(eval("TEN * 2", false), Ok(Some(Value::Int(20))));
        assert_eq!(eval("UNKNOWN + 1", false), Ok(None));
        assert_eq!(eval("1.5 * 2", false), Ok(Some(Value::Float(3.0))));
        assert_eq!(
            eval("\"a\" \"b\"", false),
            Ok(Some(Value::Str("ab".into())))
        );
        assert!(eval("1 / 0", false).is_err());
        assert!(eval("(1", false).is_err());
        assert_eq!(eval("1 && 0 || 2 == 2", true), Ok(Some(Value::Int(1))));
        assert_eq!(eval("!0 ? 3 : 4", true), Ok(Some(Value::Int(3))));
        assert_eq!(eval("~0", false), Ok(Some(Value::Int(u64::MAX as i128))));
    }

    #[test]
    fn deep_parentheses_are_an_error_not_a_crash() {
        let s = format!("{}1{}", "(".repeat(100_000), ")".repeat(100_000));
        assert!(eval(&s, false).unwrap_err().1.contains("nests deeper"));
        let s = format!("{}1", "-".repeat(100_000));
        assert_eq!(eval(&s, false), Ok(Some(Value::Int(1))));
    }

    #[test]
    fn text_is_readable() {
        let toks = lex("( RTC :: MAX + 1 ) * - 2", usize::MAX).tokens;
        assert_eq!(text_of(&toks), "(RTC::MAX + 1) * -2");
    }
}
