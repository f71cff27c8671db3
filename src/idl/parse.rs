//! The recursive-descent parser: preprocessed tokens → [`IdlDefinition`]s (CORBA 3 IDL as
//! OpenRTM and its users write it, OMG IDL 3.5 chapter 7 grammar).
//!
//! Every nesting (scopes, types, expressions) counts against `max_depth`, so hostile input
//! ends in a diagnostic, never in a stack overflow. After a syntax error the parser recovers
//! at the next `;` or the `}` closing the current scope, at the level where the error
//! happened (a bad member loses that member only; a bad declaration only itself).
//!
//! Repository ids follow CORBA 3 §10.7.5: `IDL:` + prefix + the identifiers of the scoped name
//! below the scope where the prefix was set + `:1.0`; `#pragma prefix` lasts to the end of its
//! scope; `#pragma ID`/`#pragma version`, `typeid` and `typeprefix` are applied after the file
//! is read, so they may come before or after the declaration they name.

use super::doc::parse_doc;
use super::expr::{text_of, Eval, Value};
use super::lex::{lex_line, Tok, Token};
use super::{codes, IdlOptions};
use crate::diagnostic::Diagnostic;
use crate::model::idl::*;
use crate::model::Pos;
use std::collections::HashMap;

/// A syntax error, already reported.
pub(crate) struct PErr;
type PResult<T> = Result<T, PErr>;

enum OverrideKind {
    Id(String),
    Version(String),
    Prefix(String),
}

struct Override {
    /// The names the pragma's name may stand for, innermost scope first (IDL name lookup: the
    /// scope the pragma stands in, then each enclosing one); the first declared one is meant.
    target: Vec<String>,
    kind: OverrideKind,
    pos: Pos,
}

pub(crate) struct Parsed {
    pub definitions: Vec<IdlDefinition>,
    pub doc: Option<Box<IdlDoc>>,
    pub diagnostics: Vec<Diagnostic>,
}

struct Parser<'o> {
    toks: Vec<Token>,
    i: usize,
    file: String,
    opts: &'o IdlOptions,
    diags: Vec<Diagnostic>,
    scope: Vec<String>,
    /// The prefix in effect and the scope depth where it was set.
    prefix: (String, usize),
    docs_before: Vec<String>,
    docs_after: Vec<String>,
    pragmas: Vec<(Pos, String)>,
    overrides: Vec<Override>,
    consts: HashMap<String, Value>,
    depth: usize,
    file_doc: Option<Box<IdlDoc>>,
    /// A struct, union or enum being declared inside a typedef (`typedef struct X {…} Y;`):
    /// its `}` is followed by the typedef's names, not by `;`.
    declarator_follows: bool,
}

/// Parses one file's preprocessed tokens.
pub(crate) fn parse(toks: Vec<Token>, file: &str, opts: &IdlOptions) -> Parsed {
    let mut p = Parser {
        toks,
        i: 0,
        file: file.to_string(),
        opts,
        diags: Vec::new(),
        scope: Vec::new(),
        prefix: (String::new(), 0),
        docs_before: Vec::new(),
        docs_after: Vec::new(),
        pragmas: Vec::new(),
        overrides: Vec::new(),
        consts: HashMap::new(),
        depth: 0,
        file_doc: None,
        declarator_follows: false,
    };
    if p.toks.last().is_none_or(|t| t.tok != Tok::Eof) {
        p.toks.push(Token {
            tok: Tok::Eof,
            pos: Pos::default(),
        });
    }
    let mut defs = Vec::new();
    p.definitions(&mut defs, true);
    // A file doc comment that documents nothing else (`/*! @file … */` at the end).
    let _ = p.take_doc();
    p.apply_overrides(&mut defs);
    Parsed {
        definitions: defs,
        doc: p.file_doc,
        diagnostics: p.diags,
    }
}

fn strip_escape(w: &str) -> String {
    w.strip_prefix('_').unwrap_or(w).to_string()
}

fn to_const_value(v: Value) -> Option<IdlConstValue> {
    Some(match v {
        Value::Int(i) => {
            if let Ok(x) = i64::try_from(i) {
                IdlConstValue::Integer(x)
            } else {
                IdlConstValue::Unsigned(u64::try_from(i).ok()?)
            }
        }
        Value::Float(f) => IdlConstValue::Float(f),
        Value::Str(s) => IdlConstValue::String(s),
        Value::Char(c) => IdlConstValue::Char(c.to_string()),
        Value::Bool(b) => IdlConstValue::Boolean(b),
        Value::Enumerator(e) => IdlConstValue::Enumerator(e),
    })
}

const SKIPPED: &[&str] = &[
    "valuetype",
    "eventtype",
    "component",
    "home",
    "porttype",
    "connector",
    "import",
    "custom",
];

/// What stands before a declaration's keyword: its doc comment and its position.
#[derive(Clone)]
struct Head {
    doc: Option<Box<IdlDoc>>,
    pos: Pos,
}

/// A declaration of kind `$kind` named `$name` with `$head`: its scoped name and repository id
/// in the current scope, the doc comment, position and file, then the fields of its own kind.
macro_rules! declared {
    ($p:ident, $kind:ident, $name:expr, $head:expr, { $($own:tt)* }) => {{
        let name: String = $name;
        let head: Head = $head;
        $kind {
            scoped_name: $p.scoped(&name),
            repository_id: $p.repo_id(&name),
            name,
            doc: head.doc,
            pos: head.pos,
            file: $p.file.clone(),
            $($own)*
        }
    }};
}

impl Parser<'_> {
    // ----- tokens -----

    fn skip_trivia(&mut self) {
        while let Some(t) = self.toks.get(self.i) {
            match &t.tok {
                Tok::Doc { text, after } => {
                    if *after {
                        self.docs_after.push(text.clone());
                    } else {
                        self.docs_before.push(text.clone());
                    }
                }
                Tok::Pragma(text) => self.pragmas.push((t.pos, text.clone())),
                Tok::IncludeMark => {
                    if !self.scope.is_empty() {
                        let pos = t.pos;
                        let d = Diagnostic::info(
                            codes::SKIPPED,
                            &self.file,
                            format!(
                                "`#include` inside `{}`: the included file's declarations are read as that file's own, at global scope",
                                self.scope.join("::")
                            ),
                        )
                        .at(pos);
                        self.diags.push(d);
                    }
                }
                _ => return,
            }
            self.i += 1;
        }
    }
    fn peek(&mut self) -> &Token {
        self.skip_trivia();
        let n = self.toks.len() - 1;
        &self.toks[self.i.min(n)]
    }
    fn peek_tok(&mut self) -> Tok {
        self.peek().tok.clone()
    }
    /// The `n`-th token after the next one (0: the next), trivia passed over, without moving.
    fn peek_ahead(&mut self, n: usize) -> Option<&Tok> {
        self.skip_trivia();
        self.toks[self.i..]
            .iter()
            .map(|t| &t.tok)
            .filter(|t| !matches!(t, Tok::Doc { .. } | Tok::Pragma(_) | Tok::IncludeMark))
            .nth(n)
    }
    fn pos(&mut self) -> Pos {
        self.peek().pos
    }
    /// Moves past the next token.
    fn advance(&mut self) {
        self.skip_trivia();
        if self.i < self.toks.len() - 1 {
            self.i += 1;
        }
        self.docs_before.clear();
        self.docs_after.clear();
    }
    fn is_punct(&mut self, p: &str) -> bool {
        matches!(&self.peek().tok, Tok::Punct(q) if *q == p)
    }
    fn is_word(&mut self, w: &str) -> bool {
        matches!(&self.peek().tok, Tok::Ident(q) if q == w)
    }
    /// Consumes the next token when it is the one looked for (`found`); `found` back.
    fn bump_if(&mut self, found: bool) -> bool {
        if found {
            self.advance();
        }
        found
    }
    fn eat_punct(&mut self, p: &str) -> bool {
        let found = self.is_punct(p);
        self.bump_if(found)
    }
    fn eat_word(&mut self, w: &str) -> bool {
        let found = self.is_word(w);
        self.bump_if(found)
    }
    fn at_eof(&mut self) -> bool {
        self.peek().tok == Tok::Eof
    }

    fn error_at(&mut self, pos: Pos, msg: String, hint: &str) -> PErr {
        let d = Diagnostic::error(codes::SYNTAX, &self.file, msg).at(pos);
        let d = if hint.is_empty() {
            d
        } else {
            d.with_hint(hint)
        };
        self.diags.push(d);
        PErr
    }
    fn error_here(&mut self, msg: String, hint: &str) -> PErr {
        let pos = self.pos();
        self.error_at(pos, msg, hint)
    }
    /// The error at the next token: `expected …, found` it.
    fn unexpected(&mut self, expected: &str, hint: &str) -> PErr {
        let found = self.peek().describe();
        self.error_here(format!("expected {expected}, found {found}"), hint)
    }
    /// The word that starts a declaration; an error saying what was `expected` otherwise.
    fn leading_word(&mut self, expected: &str) -> PResult<String> {
        if let Tok::Ident(w) = self.peek_tok() {
            return Ok(w);
        }
        Err(self.unexpected(expected, ""))
    }
    /// Whether the next token is the `}` that closes `what` (the pragmas before it applied); an
    /// error with `hint` at the end of the file.
    fn at_close(&mut self, what: &str, hint: &str) -> PResult<bool> {
        self.apply_pragmas();
        if self.is_punct("}") {
            return Ok(true);
        }
        if self.at_eof() {
            let msg = format!("expected `}}` to close {what}, found end of file");
            return Err(self.error_here(msg, hint));
        }
        Ok(false)
    }
    fn expect_punct(&mut self, p: &str, context: &str, hint: &str) -> PResult<()> {
        if self.eat_punct(p) {
            return Ok(());
        }
        Err(self.unexpected(&format!("`{p}` {context}"), hint))
    }
    fn ident(&mut self, what: &str) -> PResult<(String, Pos)> {
        let t = self.peek();
        if let Tok::Ident(w) = &t.tok {
            let found = (strip_escape(w), t.pos);
            self.advance();
            return Ok(found);
        }
        Err(self.unexpected(
            what,
            "names are identifiers: a letter followed by letters, digits or `_`",
        ))
    }
    /// `item (, item)*`: `item` read again while a `,` follows.
    fn comma_separated(&mut self, mut item: impl FnMut(&mut Self) -> PResult<()>) -> PResult<()> {
        loop {
            item(self)?;
            if !self.eat_punct(",") {
                return Ok(());
            }
        }
    }

    fn enter(&mut self) -> PResult<()> {
        self.depth += 1;
        if self.depth > self.opts.max_depth {
            let pos = self.pos();
            let d = Diagnostic::error(
                codes::LIMIT,
                &self.file,
                format!(
                    "declarations nest deeper than {} levels (the nesting limit)",
                    self.opts.max_depth
                ),
            )
            .at(pos)
            .with_hint(
                "if the file is genuine, raise `max-depth` in rtcdoc.toml or pass --max-depth N",
            );
            self.diags.push(d);
            self.depth -= 1;
            // Nothing sensible can follow inside: skip to the end of the file.
            self.i = self.toks.len() - 1;
            return Err(PErr);
        }
        Ok(())
    }
    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Skips to the next `;` (consumed) or to the `}` that closes the current scope (left
    /// for the caller), whichever comes first at brace depth 0.
    fn recover(&mut self) {
        let start = self.i;
        let mut depth = 0usize;
        loop {
            match self.peek_tok() {
                Tok::Eof => break,
                Tok::Punct("{") => {
                    depth += 1;
                    self.advance();
                }
                Tok::Punct("}") => {
                    if depth == 0 {
                        break;
                    }
                    depth -= 1;
                    self.advance();
                }
                Tok::Punct(";") if depth == 0 => {
                    self.advance();
                    break;
                }
                _ => {
                    self.advance();
                }
            }
        }
        if self.i == start && !self.at_eof() && !self.is_punct("}") {
            self.advance();
        }
        self.docs_before.clear();
        self.docs_after.clear();
    }

    /// Skips to the `}` closing the current braces (left for the caller), `;` included.
    fn skip_to_close(&mut self) {
        let mut depth = 0usize;
        loop {
            match self.peek_tok() {
                Tok::Eof => return,
                Tok::Punct("{") => depth += 1,
                Tok::Punct("}") => {
                    if depth == 0 {
                        return;
                    }
                    depth -= 1;
                }
                _ => {}
            }
            self.advance();
        }
    }

    // ----- docs -----

    fn take_doc(&mut self) -> Option<Box<IdlDoc>> {
        self.skip_trivia();
        let docs = std::mem::take(&mut self.docs_before);
        let mut kept = Vec::new();
        for d in docs {
            let parsed = parse_doc(&d);
            if parsed.labels.iter().any(|l| l.tag == "file") {
                if self.file_doc.is_none() {
                    self.file_doc = Some(Box::new(parsed));
                }
            } else {
                kept.push(d);
            }
        }
        (!kept.is_empty()).then(|| Box::new(parse_doc(&kept.join("\n"))))
    }
    /// Trailing `//!<` / `///<` / `/**<` comments met since the last token.
    fn take_after(&mut self) -> Option<String> {
        self.skip_trivia();
        let docs = std::mem::take(&mut self.docs_after);
        (!docs.is_empty()).then(|| docs.join("\n"))
    }
    fn merge_doc(doc: &mut Option<Box<IdlDoc>>, after: &str) {
        let text = match doc {
            Some(d) => format!("{}\n{after}", d.text),
            None => after.to_string(),
        };
        *doc = Some(Box::new(parse_doc(&text)));
    }
    /// The trailing comments met since the last token (if any), added to each of `docs`.
    fn add_after<'d>(&mut self, docs: impl IntoIterator<Item = &'d mut Option<Box<IdlDoc>>>) {
        if let Some(after) = self.take_after() {
            for doc in docs {
                Self::merge_doc(doc, &after);
            }
        }
    }

    // ----- pragmas and ids -----

    fn apply_pragmas(&mut self) {
        self.skip_trivia();
        for (pos, text) in std::mem::take(&mut self.pragmas) {
            let toks = lex_line(&text, pos);
            let word = match toks.first().map(|t| &t.tok) {
                Some(Tok::Ident(w)) => w.clone(),
                _ => continue,
            };
            let rest = &toks[1..];
            let bad = |p: &mut Self, m: &str| {
                let d = Diagnostic::warning(
                    codes::DIRECTIVE,
                    &p.file,
                    format!("malformed `#pragma {word}`: {m}; it is ignored"),
                )
                .at(pos);
                p.diags.push(d);
            };
            match word.as_str() {
                "prefix" => match rest.first().map(|t| &t.tok) {
                    Some(Tok::Str { value, .. }) => {
                        self.prefix = (value.clone(), self.scope.len());
                    }
                    _ => bad(
                        self,
                        "expected a string, as in `#pragma prefix \"omg.org\"`",
                    ),
                },
                "ID" | "version" => {
                    let mut k = 0;
                    let mut name = String::new();
                    while let Some(t) = rest.get(k) {
                        match &t.tok {
                            Tok::Ident(w) => name.push_str(&strip_escape(w)),
                            Tok::Punct("::") => name.push_str("::"),
                            _ => break,
                        }
                        k += 1;
                    }
                    let target = self.target_name(&name);
                    let kind = match (word.as_str(), rest.get(k).map(|t| &t.tok)) {
                        ("ID", Some(Tok::Str { value, .. })) => OverrideKind::Id(value.clone()),
                        ("version", Some(Tok::Float { raw, .. } | Tok::Int { raw, .. })) => {
                            OverrideKind::Version(raw.clone())
                        }
                        _ => {
                            bad(
                                self,
                                "expected a name and then a string (ID) or major.minor (version)",
                            );
                            continue;
                        }
                    };
                    if name.is_empty() {
                        bad(self, "expected the name of a declaration");
                        continue;
                    }
                    self.overrides.push(Override { target, kind, pos });
                }
                _ => {}
            }
        }
    }

    /// The scoped name a pragma or `typeid` names from the current scope.
    fn target_name(&self, name: &str) -> Vec<String> {
        if let Some(abs) = name.strip_prefix("::") {
            return vec![abs.to_string()];
        }
        (0..=self.scope.len())
            .rev()
            .map(|k| {
                if k == 0 {
                    name.to_string()
                } else {
                    format!("{}::{name}", self.scope[..k].join("::"))
                }
            })
            .collect()
    }

    fn scoped(&self, name: &str) -> String {
        if self.scope.is_empty() {
            name.to_string()
        } else {
            format!("{}::{name}", self.scope.join("::"))
        }
    }
    fn repo_id(&self, name: &str) -> String {
        let (prefix, base) = &self.prefix;
        let mut s = String::from("IDL:");
        if !prefix.is_empty() {
            s.push_str(prefix);
            s.push('/');
        }
        for part in self.scope.iter().skip(*base) {
            s.push_str(part);
            s.push('/');
        }
        s.push_str(name);
        s.push_str(":1.0");
        s
    }

    fn apply_overrides(&mut self, defs: &mut [IdlDefinition]) {
        // Each pragma's name resolved to the first of its candidates this file declares
        // (`#pragma version PortableServer 2.3` inside `module PortableServer` names the module).
        let mut declared = std::collections::HashSet::new();
        walk_ids(defs, &mut |scoped, _| {
            declared.insert(scoped.to_string());
        });
        struct Meant {
            target: String,
            kind: OverrideKind,
            pos: Pos,
        }
        let overrides: Vec<Meant> = std::mem::take(&mut self.overrides)
            .into_iter()
            .map(|o| {
                let first = o.target.first().cloned().unwrap_or_default();
                let meant = o.target.into_iter().find(|t| declared.contains(t));
                Meant {
                    target: meant.unwrap_or(first),
                    kind: o.kind,
                    pos: o.pos,
                }
            })
            .collect();
        let mut used = vec![false; overrides.len()];
        walk_ids(defs, &mut |scoped, id| {
            for (k, o) in overrides.iter().enumerate() {
                if let OverrideKind::Prefix(p) = &o.kind {
                    if let Some(rest) = scoped.strip_prefix(&format!("{}::", o.target)) {
                        let version = id.rsplit_once(':').map_or("1.0", |(_, v)| v).to_string();
                        *id = format!("IDL:{p}/{}:{version}", rest.replace("::", "/"));
                        used[k] = true;
                    } else if scoped == o.target {
                        used[k] = true;
                    }
                }
            }
            for (k, o) in overrides.iter().enumerate() {
                if o.target != scoped {
                    continue;
                }
                match &o.kind {
                    OverrideKind::Version(v) => {
                        if id.starts_with("IDL:") {
                            if let Some((head, _)) = id.rsplit_once(':') {
                                *id = format!("{head}:{v}");
                            }
                        }
                        used[k] = true;
                    }
                    OverrideKind::Id(new) => {
                        *id = new.clone();
                        used[k] = true;
                    }
                    OverrideKind::Prefix(_) => {}
                }
            }
        });
        for (o, u) in overrides.iter().zip(used) {
            if !u {
                let d = Diagnostic::warning(
                    codes::DIRECTIVE,
                    &self.file,
                    format!(
                        "the repository id setting names `{}`, which this file does not declare; it is ignored",
                        o.target
                    ),
                )
                .at(o.pos)
                .with_hint("name a declaration of this file, relative to the scope the pragma stands in");
                self.diags.push(d);
            }
        }
    }

    // ----- definitions -----

    fn definitions(&mut self, out: &mut Vec<IdlDefinition>, top: bool) {
        loop {
            self.apply_pragmas();
            match self.peek_tok() {
                Tok::Eof => return,
                Tok::Punct("}") => {
                    if !top {
                        return;
                    }
                    let _ = self.error_here(
                        "unexpected `}` at top level".into(),
                        "remove the extra `}` or the `};` that closes nothing",
                    );
                    self.advance();
                    continue;
                }
                Tok::Punct(";") => {
                    self.advance();
                    continue;
                }
                _ => {}
            }
            if self.definition(out).is_err() && !self.at_eof() {
                self.recover();
            }
        }
    }

    fn definition(&mut self, out: &mut Vec<IdlDefinition>) -> PResult<()> {
        let head = Head {
            doc: self.take_doc(),
            pos: self.pos(),
        };
        let word = self.leading_word("a declaration (module, struct, interface, typedef, …)")?;
        match word.as_str() {
            "module" => self.module(out, head),
            "struct" => self.structure(out, head),
            "union" => self.union(out, head),
            "enum" => self.enumeration(out, head),
            "typedef" => self.typedef(out, head),
            "const" => self.constant(out, head),
            "native" => {
                let name = self.name_after_keyword("a name after `native`")?;
                self.expect_punct(";", "after native declaration", "")?;
                out.push(IdlDefinition::Native(declared!(
                    self,
                    IdlNative,
                    name,
                    head,
                    {}
                )));
                Ok(())
            }
            "exception" => self.exception(out, head),
            "interface" => self.interface(out, head, None),
            "abstract" | "local" => {
                self.advance();
                if self.is_word("interface") {
                    self.interface(out, head, Some(word))
                } else {
                    self.skip_declaration(out, &word, head.pos)
                }
            }
            "typeid" | "typeprefix" => {
                self.advance();
                let name = self.scoped_name()?;
                let target = self.target_name(&name);
                let value = match self.peek_tok() {
                    Tok::Str { value, .. } => value,
                    _ => {
                        return Err(self.unexpected(&format!("a string after `{word} {name}`"), ""))
                    }
                };
                self.advance();
                self.expect_punct(";", &format!("after `{word}`"), "")?;
                let kind = if word == "typeid" {
                    OverrideKind::Id(value)
                } else {
                    OverrideKind::Prefix(value)
                };
                let pos = head.pos;
                self.overrides.push(Override { target, kind, pos });
                Ok(())
            }
            w if SKIPPED.contains(&w) => self.skip_declaration(out, &word, head.pos),
            _ => Err(self.unexpected(
                "a declaration (module, struct, interface, typedef, …)",
                "check the spelling of the keyword, or a missing `;` on the line before",
            )),
        }
    }

    fn skip_declaration(
        &mut self,
        out: &mut Vec<IdlDefinition>,
        keyword: &str,
        pos: Pos,
    ) -> PResult<()> {
        let mut keyword = keyword.to_string();
        if self.is_word(&keyword) {
            self.advance();
        }
        // `abstract valuetype X`, `custom valuetype X`.
        if let Tok::Ident(w) = self.peek_tok() {
            if matches!(w.as_str(), "valuetype" | "eventtype" | "component" | "home") {
                keyword = format!("{keyword} {w}");
                self.advance();
            }
        }
        let name = match self.peek_tok() {
            Tok::Ident(w) => strip_escape(&w),
            _ => String::new(),
        };
        let mut depth = 0usize;
        loop {
            match self.peek_tok() {
                Tok::Eof => {
                    return Err(self.error_here(
                        format!("`{keyword}` declaration is not closed before the end of the file"),
                        "end it with `;` (after its closing `}`)",
                    ))
                }
                Tok::Punct("{") => depth += 1,
                Tok::Punct("}") => {
                    if depth == 0 {
                        return Err(self.error_here(
                            format!("expected `;` after `{keyword}` declaration, found `}}`"),
                            "",
                        ));
                    }
                    depth -= 1;
                }
                Tok::Punct(";") if depth == 0 => {
                    self.advance();
                    break;
                }
                _ => {}
            }
            self.advance();
        }
        let d = Diagnostic::info(
            codes::SKIPPED,
            &self.file,
            format!(
                "`{keyword}{}` is not modelled by rtcdoc; the declaration is skipped",
                if name.is_empty() {
                    String::new()
                } else {
                    format!(" {name}")
                }
            ),
        )
        .at(pos);
        self.diags.push(d);
        let repository_id = if name.is_empty() || keyword == "import" {
            String::new()
        } else {
            self.repo_id(&name)
        };
        out.push(IdlDefinition::Skipped(IdlSkipped {
            keyword,
            scoped_name: if name.is_empty() {
                String::new()
            } else {
                self.scoped(&name)
            },
            repository_id,
            name,
            pos,
            file: self.file.clone(),
        }));
        Ok(())
    }

    /// Enters scope `name` (pragma prefix saved), runs `f`, leaves.
    fn in_scope<T>(&mut self, name: &str, f: impl FnOnce(&mut Self) -> T) -> PResult<T> {
        self.enter()?;
        self.scope.push(name.to_string());
        let saved = self.prefix.clone();
        let r = f(self);
        self.prefix = saved;
        self.scope.pop();
        self.leave();
        Ok(r)
    }

    /// The body of `name` after its `{`, up to (not including) its `}`, read by `fill` in the
    /// scope of `name`: the definition `make` makes of what was read goes onto `out` also when
    /// a part is broken (reported, the error returned after), so that the declaration is kept.
    fn body<T: Default>(
        &mut self,
        out: &mut Vec<IdlDefinition>,
        name: &str,
        fill: impl FnOnce(&mut Self, &mut T) -> PResult<()>,
        make: impl FnOnce(&Self, T) -> IdlDefinition,
    ) -> PResult<()> {
        let mut read = T::default();
        let r = self.in_scope(name, |p| fill(p, &mut read))?;
        out.push(make(self, read));
        r
    }

    /// The `};` that ends the body of `kind` `name` (`hint`: what to say when the `}` is missing).
    fn close(&mut self, kind: &str, name: &str, hint: &str) -> PResult<()> {
        self.expect_punct("}", &format!("to close {kind} `{name}`"), hint)?;
        if std::mem::take(&mut self.declarator_follows) {
            return Ok(());
        }
        self.expect_punct(
            ";",
            &format!("after the `}}` of {kind} `{name}`"),
            "write `};`",
        )
    }

    /// The name after a declaration's keyword (`what`: what to call it when it is missing).
    fn name_after_keyword(&mut self, what: &str) -> PResult<String> {
        self.advance();
        Ok(self.ident(what)?.0)
    }

    /// The name after the keyword of a `kind` that may be declared forward: `None` when it is
    /// (`kind name;`, pushed onto `out`), the name and `head` back when a body follows.
    fn name_or_forward(
        &mut self,
        out: &mut Vec<IdlDefinition>,
        head: Head,
        kind: &str,
        what: &str,
    ) -> PResult<Option<(String, Head)>> {
        let name = self.name_after_keyword(what)?;
        if !self.eat_punct(";") {
            return Ok(Some((name, head)));
        }
        out.push(IdlDefinition::Forward(
            declared!(self, IdlForward, name, head, {
                of: kind.to_string(),
            }),
        ));
        Ok(None)
    }

    fn module(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        let name = self.name_after_keyword("a module name")?;
        self.expect_punct("{", &format!("after `module {name}`"), "")?;
        let fill = |p: &mut Self, defs: &mut Vec<IdlDefinition>| {
            p.definitions(defs, false);
            Ok(())
        };
        self.body(out, &name, fill, |p, definitions| {
            IdlDefinition::Module(declared!(p, IdlModule, name.clone(), head, { definitions }))
        })?;
        self.close("module", &name, "every `{` needs its `}`")
    }

    fn structure(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        let Some((name, head)) = self.name_or_forward(out, head, "struct", "a struct name")? else {
            return Ok(());
        };
        self.with_members(out, "struct", name, |p, name, fields| {
            IdlDefinition::Struct(declared!(p, IdlStruct, name, head, { fields }))
        })
    }

    /// The `{ members };` of a struct or an exception (`kind`) named `name`: its definition made
    /// by `make` onto `out`.
    fn with_members(
        &mut self,
        out: &mut Vec<IdlDefinition>,
        kind: &str,
        name: String,
        make: impl FnOnce(&Self, String, Vec<IdlField>) -> IdlDefinition,
    ) -> PResult<()> {
        self.expect_punct("{", &format!("after `{kind} {name}`"), "")?;
        let what = format!("{kind} member");
        self.body(
            out,
            &name,
            |p, fields| p.members(fields, &what),
            |p, fields| make(p, name.clone(), fields),
        )?;
        self.close(kind, &name, "")
    }

    fn exception(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        let name = self.name_after_keyword("an exception name")?;
        self.with_members(out, "exception", name, |p, name, fields| {
            IdlDefinition::Exception(declared!(p, IdlException, name, head, { fields }))
        })
    }

    /// Members up to (not including) the closing `}`.
    fn members(&mut self, fields: &mut Vec<IdlField>, what: &str) -> PResult<()> {
        while !self.at_close("the members", "every `{` needs its `};`")? {
            let before = fields.len();
            match self.member(fields, what) {
                Ok(()) => self.add_after(fields[before..].iter_mut().map(|f| &mut f.doc)),
                Err(PErr) => self.recover(),
            }
        }
        Ok(())
    }

    fn member(&mut self, fields: &mut Vec<IdlField>, what: &str) -> PResult<()> {
        let doc = self.take_doc();
        let ty = self.type_spec()?;
        self.comma_separated(|p| {
            let (name, pos, array) = p.declarator(&format!("a {what} name"))?;
            fields.push(IdlField {
                name,
                ty: ty.clone(),
                array,
                doc: doc.clone(),
                pos,
            });
            Ok(())
        })?;
        self.expect_punct(
            ";",
            &format!("after {what}"),
            "each member ends with `;`, as in `long x;`",
        )
    }

    fn declarator(&mut self, what: &str) -> PResult<(String, Pos, Vec<IdlBound>)> {
        let (name, pos) = self.ident(what)?;
        let mut dims = Vec::new();
        while self.eat_punct("[") {
            dims.push(self.bound()?);
            self.expect_punct("]", "after the array size", "")?;
        }
        Ok((name, pos, dims))
    }

    fn union(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        let Some((name, head)) = self.name_or_forward(out, head, "union", "a union name")? else {
            return Ok(());
        };
        if !self.eat_word("switch") {
            return Err(self.unexpected(
                &format!("`switch` after `union {name}`"),
                "a union reads `union U switch (long) { case 1: long a; default: double b; };`",
            ));
        }
        self.expect_punct("(", "after `switch`", "")?;
        let switch_type = self.type_spec()?;
        self.expect_punct(")", "after the switch type", "")?;
        self.expect_punct("{", &format!("to open union `{name}`"), "")?;
        self.body(out, &name, Self::union_cases, |p, cases| {
            IdlDefinition::Union(declared!(p, IdlUnion, name.clone(), head, {
                switch_type,
                cases,
            }))
        })?;
        self.close("union", &name, "")
    }

    fn union_cases(&mut self, cases: &mut Vec<IdlUnionCase>) -> PResult<()> {
        while !self.at_close("the union", "")? {
            match self.union_case() {
                Ok(mut c) => {
                    self.add_after([&mut c.field.doc]);
                    cases.push(c);
                }
                Err(PErr) => self.recover(),
            }
        }
        Ok(())
    }

    fn union_case(&mut self) -> PResult<IdlUnionCase> {
        let doc = self.take_doc();
        let mut labels = Vec::new();
        let mut is_default = false;
        loop {
            if self.eat_word("case") {
                let (text, _) = self.const_expr()?;
                labels.push(text);
            } else if self.eat_word("default") {
                labels.push("default".into());
                is_default = true;
            } else {
                break;
            }
            self.expect_punct(":", "after the case label", "")?;
        }
        if labels.is_empty() {
            return Err(self.unexpected("`case` or `default`", ""));
        }
        let doc = doc.or_else(|| self.take_doc());
        let ty = self.type_spec()?;
        let (name, pos, array) = self.declarator("a union member name")?;
        self.expect_punct(";", "after union member", "each member ends with `;`")?;
        Ok(IdlUnionCase {
            labels,
            is_default,
            field: IdlField {
                name,
                ty,
                array,
                doc,
                pos,
            },
        })
    }

    fn enumeration(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        let name = self.name_after_keyword("an enum name")?;
        self.expect_punct("{", &format!("after `enum {name}`"), "")?;
        let mut values: Vec<IdlEnumerator> = Vec::new();
        let result = self.enumerators(&mut values);
        out.push(IdlDefinition::Enum(
            declared!(self, IdlEnum, name.clone(), head, {
                values,
            }),
        ));
        if result.is_err() {
            // The error is reported; skip the rest of the enumerators to the enum's own `}`.
            self.skip_to_close();
        }
        self.close("enum", &name, "")
    }

    /// The enumerators of an enum up to (not including) its `}`, each a constant of the
    /// enclosing scope.
    fn enumerators(&mut self, values: &mut Vec<IdlEnumerator>) -> PResult<()> {
        loop {
            self.apply_pragmas();
            if self.is_punct("}") {
                return Ok(());
            }
            let doc = self.take_doc();
            let (name, pos) = self.ident("an enumerator name")?;
            let mut e = IdlEnumerator { name, doc, pos };
            self.add_after([&mut e.doc]);
            let comma = self.eat_punct(",");
            self.add_after([&mut e.doc]);
            let scoped = self.scoped(&e.name);
            self.consts
                .insert(scoped.clone(), Value::Enumerator(scoped));
            values.push(e);
            if !comma {
                if !self.is_punct("}") {
                    return Err(self.unexpected(
                        "`,` or `}` after enumerator",
                        "enumerators are separated by `,`",
                    ));
                }
                return Ok(());
            }
        }
    }

    fn typedef(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        self.advance();
        let ty = match self.constructed_in_typedef() {
            Some((kind, name)) => {
                // `typedef struct X {…} Y;`: X declared where the typedef stands, Y an alias.
                let inner = Head {
                    doc: head.doc.clone(),
                    pos: self.pos(),
                };
                self.declarator_follows = true;
                let r = match kind.as_str() {
                    "struct" => self.structure(out, inner),
                    "union" => self.union(out, inner),
                    _ => self.enumeration(out, inner),
                };
                self.declarator_follows = false;
                r?;
                IdlType::Named {
                    name,
                    resolved: None,
                }
            }
            None => self.type_spec()?,
        };
        let start = out.len();
        self.comma_separated(|p| {
            let (name, _, array) = p.declarator("a type name")?;
            out.push(IdlDefinition::Typedef(
                declared!(p, IdlTypedef, name, head.clone(), {
                    ty: ty.clone(),
                    array,
                }),
            ));
            Ok(())
        })?;
        self.expect_punct(
            ";",
            "after typedef",
            "a typedef reads `typedef sequence<long> LongSeq;`",
        )?;
        self.add_after(out[start..].iter_mut().filter_map(|d| match d {
            IdlDefinition::Typedef(t) => Some(&mut t.doc),
            _ => None,
        }));
        Ok(())
    }

    /// The kind and name of a struct, union or enum whose body follows in a typedef
    /// (`typedef struct X {`, `typedef union X switch`, `typedef enum X {`).
    fn constructed_in_typedef(&mut self) -> Option<(String, String)> {
        let Some(Tok::Ident(kind)) = self.peek_ahead(0).cloned() else {
            return None;
        };
        let Some(Tok::Ident(name)) = self.peek_ahead(1).cloned() else {
            return None;
        };
        let body = match kind.as_str() {
            "struct" | "enum" => matches!(self.peek_ahead(2), Some(Tok::Punct("{"))),
            "union" => matches!(self.peek_ahead(2), Some(Tok::Ident(w)) if w == "switch"),
            _ => false,
        };
        body.then_some((kind, name))
    }

    fn constant(&mut self, out: &mut Vec<IdlDefinition>, head: Head) -> PResult<()> {
        self.advance();
        let ty = self.type_spec()?;
        let (name, _) = self.ident("a constant name")?;
        self.expect_punct(
            "=",
            &format!("after `const … {name}`"),
            "a constant reads `const long MAX = 10;`",
        )?;
        let (expr, value) = self.const_expr()?;
        self.expect_punct(";", "after constant", "")?;
        let scoped = self.scoped(&name);
        if let Some(v) = &value {
            self.consts.insert(scoped.clone(), v.clone());
        }
        let mut c = declared!(self, IdlConst, name, head, {
            ty,
            expr,
            value: value.and_then(to_const_value),
        });
        self.add_after([&mut c.doc]);
        out.push(IdlDefinition::Const(c));
        Ok(())
    }

    fn interface(
        &mut self,
        out: &mut Vec<IdlDefinition>,
        head: Head,
        modifier: Option<String>,
    ) -> PResult<()> {
        let Some((name, head)) =
            self.name_or_forward(out, head, "interface", "an interface name")?
        else {
            return Ok(());
        };
        let mut bases = Vec::new();
        if self.eat_punct(":") {
            self.comma_separated(|p| {
                bases.push(p.named_type()?);
                Ok(())
            })?;
        }
        self.expect_punct("{", &format!("after `interface {name}`"), "")?;
        let mut itf = declared!(self, IdlInterface, name.clone(), head, {
            modifier,
            bases,
            attributes: Vec::new(),
            operations: Vec::new(),
            definitions: Vec::new(),
        });
        let r = self.in_scope(&name, |p| p.exports(&mut itf))?;
        out.push(IdlDefinition::Interface(itf));
        r?;
        self.close("interface", &name, "")
    }

    fn exports(&mut self, itf: &mut IdlInterface) -> PResult<()> {
        let what = format!("interface `{}`", itf.name);
        while !self.at_close(&what, "")? {
            if self.eat_punct(";") {
                continue;
            }
            if self.export(itf).is_err() {
                self.recover();
            }
        }
        Ok(())
    }

    fn export(&mut self, itf: &mut IdlInterface) -> PResult<()> {
        let word = self.leading_word("an operation, attribute or type declaration")?;
        match word.as_str() {
            "struct" | "union" | "enum" | "typedef" | "const" | "exception" | "native"
            | "typeid" | "typeprefix" => self.definition(&mut itf.definitions),
            "readonly" | "attribute" => self.attribute(itf),
            _ => self.operation(itf),
        }
    }

    fn attribute(&mut self, itf: &mut IdlInterface) -> PResult<()> {
        let doc = self.take_doc();
        let readonly = self.eat_word("readonly");
        if !self.eat_word("attribute") {
            return Err(self.unexpected("`attribute` after `readonly`", ""));
        }
        let ty = self.type_spec()?;
        let start = itf.attributes.len();
        self.comma_separated(|p| {
            let (name, pos) = p.ident("an attribute name")?;
            itf.attributes.push(IdlAttribute {
                name,
                ty: ty.clone(),
                readonly,
                raises: Vec::new(),
                doc: doc.clone(),
                pos,
            });
            Ok(())
        })?;
        let mut raises = Vec::new();
        while self.is_word("raises") || self.is_word("getraises") || self.is_word("setraises") {
            self.advance();
            raises.extend(self.name_list("exception")?);
        }
        self.expect_punct(";", "after attribute", "")?;
        let added = &mut itf.attributes[start..];
        for a in added.iter_mut() {
            a.raises = raises.clone();
        }
        self.add_after(added.iter_mut().map(|a| &mut a.doc));
        Ok(())
    }

    /// `( Name, Name )`.
    fn name_list(&mut self, what: &str) -> PResult<Vec<IdlType>> {
        self.expect_punct("(", &format!("before the {what} names"), "")?;
        let mut v = Vec::new();
        if self.eat_punct(")") {
            return Ok(v);
        }
        loop {
            v.push(self.named_type()?);
            if self.eat_punct(")") {
                return Ok(v);
            }
            self.expect_punct(",", &format!("between {what} names"), "")?;
        }
    }

    fn operation(&mut self, itf: &mut IdlInterface) -> PResult<()> {
        let doc = self.take_doc();
        let oneway = self.eat_word("oneway");
        let return_type = if self.eat_word("void") {
            None
        } else {
            Some(self.type_spec()?)
        };
        let (name, pos) = self.ident("an operation name")?;
        self.expect_punct(
            "(",
            &format!("after operation name `{name}`"),
            "an operation reads `ReturnType name(in Type arg);`",
        )?;
        let mut params = Vec::new();
        if !self.eat_punct(")") {
            loop {
                let pdoc = self.take_doc();
                let direction = if self.eat_word("in") {
                    IdlParamDirection::In
                } else if self.eat_word("out") {
                    IdlParamDirection::Out
                } else if self.eat_word("inout") {
                    IdlParamDirection::Inout
                } else {
                    return Err(self.unexpected(
                        &format!("`in`, `out` or `inout` before a parameter of `{name}`"),
                        "every parameter starts with its direction: `in long x`",
                    ));
                };
                let ty = self.type_spec()?;
                let (pname, ppos) = self.ident("a parameter name")?;
                let mut p = IdlParam {
                    direction,
                    ty,
                    name: pname,
                    doc: pdoc,
                    pos: ppos,
                };
                let more = self.eat_punct(",");
                self.add_after([&mut p.doc]);
                params.push(p);
                if more {
                    continue;
                }
                self.expect_punct(
                    ")",
                    &format!("after the parameters of `{name}`"),
                    "parameters are separated by `,`",
                )?;
                self.add_after(params.last_mut().map(|p| &mut p.doc));
                break;
            }
        }
        let raises = if self.eat_word("raises") {
            self.name_list("exception")?
        } else {
            Vec::new()
        };
        let mut context = Vec::new();
        if self.eat_word("context") {
            self.expect_punct("(", "after `context`", "")?;
            loop {
                match self.peek_tok() {
                    Tok::Str { value, .. } => {
                        context.push(value);
                        self.advance();
                    }
                    _ => return Err(self.unexpected("a string in `context (…)`", "")),
                }
                if self.eat_punct(")") {
                    break;
                }
                self.expect_punct(",", "between context strings", "")?;
            }
        }
        self.expect_punct(
            ";",
            &format!("after operation `{name}`"),
            "each operation ends with `;`",
        )?;
        let mut op = IdlOperation {
            name,
            return_type,
            oneway,
            params,
            raises,
            context,
            doc,
            pos,
        };
        self.add_after([&mut op.doc]);
        itf.operations.push(op);
        Ok(())
    }

    // ----- types and expressions -----

    fn scoped_name(&mut self) -> PResult<String> {
        let mut name = String::new();
        if self.eat_punct("::") {
            name.push_str("::");
        }
        loop {
            let (part, _) = self.ident("a name")?;
            name.push_str(&part);
            if self.is_punct("::") {
                self.advance();
                name.push_str("::");
            } else {
                return Ok(name);
            }
        }
    }

    /// A scoped name as a type, resolved later.
    fn named_type(&mut self) -> PResult<IdlType> {
        let name = self.scoped_name()?;
        Ok(IdlType::Named {
            name,
            resolved: None,
        })
    }

    fn type_spec(&mut self) -> PResult<IdlType> {
        self.enter()?;
        let r = self.type_spec_inner();
        self.leave();
        r
    }

    fn type_spec_inner(&mut self) -> PResult<IdlType> {
        let word = match self.peek_tok() {
            Tok::Ident(w) => w,
            Tok::Punct("::") => return self.named_type(),
            _ => return Err(self.unexpected("a type", "")),
        };
        use IdlPrimitive as P;
        let prim = |p: P| Ok(IdlType::Primitive { name: p });
        match word.as_str() {
            "unsigned" => {
                self.advance();
                if self.eat_word("short") {
                    prim(P::UnsignedShort)
                } else if self.eat_word("long") {
                    if self.eat_word("long") {
                        prim(P::UnsignedLongLong)
                    } else {
                        prim(P::UnsignedLong)
                    }
                } else {
                    Err(self.unexpected("`short` or `long` after `unsigned`", ""))
                }
            }
            "long" => {
                self.advance();
                if self.eat_word("long") {
                    prim(P::LongLong)
                } else if self.eat_word("double") {
                    prim(P::LongDouble)
                } else {
                    prim(P::Long)
                }
            }
            "short" | "float" | "double" | "char" | "wchar" | "boolean" | "octet" | "any"
            | "Object" | "ValueBase" => {
                self.advance();
                prim(match word.as_str() {
                    "short" => P::Short,
                    "float" => P::Float,
                    "double" => P::Double,
                    "char" => P::Char,
                    "wchar" => P::Wchar,
                    "boolean" => P::Boolean,
                    "octet" => P::Octet,
                    "any" => P::Any,
                    "Object" => P::Object,
                    _ => P::ValueBase,
                })
            }
            "string" | "wstring" => {
                self.advance();
                let bound = if self.eat_punct("<") {
                    let b = self.bound()?;
                    self.close_angle(&word)?;
                    Some(b)
                } else {
                    None
                };
                Ok(IdlType::String {
                    wide: word == "wstring",
                    bound,
                })
            }
            "sequence" => {
                self.advance();
                self.expect_punct(
                    "<",
                    "after `sequence`",
                    "write `sequence<T>` or `sequence<T, N>`",
                )?;
                let element = self.type_spec()?;
                let bound = if self.eat_punct(",") {
                    Some(self.bound()?)
                } else {
                    None
                };
                self.close_angle("sequence")?;
                Ok(IdlType::Sequence {
                    element: Box::new(element),
                    bound,
                })
            }
            "fixed" => {
                self.advance();
                if self.eat_punct("<") {
                    let d = self.bound()?;
                    self.expect_punct(",", "between the digits and the scale of `fixed`", "")?;
                    let s = self.bound()?;
                    self.close_angle("fixed")?;
                    Ok(IdlType::Fixed {
                        digits: Some(d),
                        scale: Some(s),
                    })
                } else {
                    Ok(IdlType::Fixed {
                        digits: None,
                        scale: None,
                    })
                }
            }
            "struct" | "union" | "enum" => Err(self.error_here(
                format!("a `{word}` declared inside another declaration is not supported"),
                "declare it on its own first, then use its name",
            )),
            _ => self.named_type(),
        }
    }

    /// A closing `>`; splits a `>>` (`sequence<sequence<long>>`).
    fn close_angle(&mut self, what: &str) -> PResult<()> {
        if self.eat_punct(">") {
            return Ok(());
        }
        if self.is_punct(">>") {
            let t = &mut self.toks[self.i];
            t.tok = Tok::Punct(">");
            t.pos.column += 1;
            return Ok(());
        }
        Err(self.unexpected(&format!("`>` to close `{what}<…`"), ""))
    }

    fn bound(&mut self) -> PResult<IdlBound> {
        let (expr, value) = self.const_expr()?;
        let value = match value {
            Some(Value::Int(i)) => u64::try_from(i).ok(),
            _ => None,
        };
        Ok(IdlBound { expr, value })
    }

    fn const_expr(&mut self) -> PResult<(String, Option<Value>)> {
        self.skip_trivia();
        let start = self.i;
        let consts = &self.consts;
        let scope = &self.scope;
        let mut e = Eval::new(
            &self.toks,
            start,
            self.opts.max_depth,
            false,
            |name: &str| {
                if let Some(abs) = name.strip_prefix("::") {
                    return consts.get(abs).cloned();
                }
                for k in (0..=scope.len()).rev() {
                    let cand = if k == 0 {
                        name.to_string()
                    } else {
                        format!("{}::{name}", scope[..k].join("::"))
                    };
                    if let Some(v) = consts.get(&cand) {
                        return Some(v.clone());
                    }
                }
                None
            },
        );
        let r = e.expr();
        let end = e.i;
        match r {
            Ok(v) => {
                let text = text_of(&self.toks[start..end]);
                self.i = end;
                self.docs_before.clear();
                self.docs_after.clear();
                Ok((text, v))
            }
            Err((pos, msg)) => {
                self.i = end.max(start);
                Err(self.error_at(pos, msg, ""))
            }
        }
    }
}

/// Calls `f(scoped name, &mut repository id)` for every declaration, depth first.
fn walk_ids(defs: &mut [IdlDefinition], f: &mut impl FnMut(&str, &mut String)) {
    for d in defs {
        match d {
            IdlDefinition::Module(m) => {
                f(&m.scoped_name, &mut m.repository_id);
                walk_ids(&mut m.definitions, f);
            }
            IdlDefinition::Interface(i) => {
                f(&i.scoped_name, &mut i.repository_id);
                walk_ids(&mut i.definitions, f);
            }
            IdlDefinition::Struct(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Union(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Enum(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Typedef(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Const(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Exception(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Forward(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Native(x) => f(&x.scoped_name, &mut x.repository_id),
            IdlDefinition::Skipped(x) => {
                if !x.repository_id.is_empty() {
                    f(&x.scoped_name, &mut x.repository_id)
                }
            }
        }
    }
}
