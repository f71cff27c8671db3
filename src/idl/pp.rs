//! The preprocessor: conditionals, object-like macros, includes and pragmas, over the tokens of
//! the lexer (so every token keeps its position in the file it was written in).
//!
//! Each file is read as a document of its own. Its `#include`s are followed for their
//! *directives only* — the macros they define and the guards they set — while their
//! declarations are left to the included file's own reading. This keeps every definition in
//! exactly one [`super::IdlFile`] (the one it is written in), keeps every position an original
//! one, and means the CORBA rule that a `#pragma prefix` ends with its file holds by
//! construction. (An `#include` placed inside a module would textually nest the included
//! declarations there; such files are rare and get an info diagnostic from the parser.)

use super::decode::decode;
use super::expr::{Eval, Value};
use super::lex::{lex, lex_line, Tok, Token};
use super::{codes, IdlOptions, SourceFile, Tree};
use crate::diagnostic::Diagnostic;
use crate::model::idl::{IdlInclude, IdlPragma};
use crate::model::Pos;
use std::collections::{HashMap, HashSet};
use std::rc::Rc;

/// A file after decoding and lexing (done once, whoever includes it).
pub(crate) struct Lexed {
    pub encoding: &'static str,
    pub tokens: Vec<Token>,
}

/// All source files, lexed lazily, and the diagnostics reported so far (each once).
pub(crate) struct Sources<'a> {
    pub files: &'a [SourceFile],
    pub opts: &'a IdlOptions,
    lexed: Vec<Option<Rc<Lexed>>>,
    by_path: HashMap<String, Vec<usize>>,
    by_name: HashMap<String, Vec<usize>>,
    pub diagnostics: Vec<Diagnostic>,
    seen: HashSet<(String, Option<Pos>, &'static str, String)>,
    cycles: HashSet<Vec<usize>>,
}

/// `a\b/./c/../d.idl` → `a/b/d.idl`.
pub(crate) fn normalize(path: &str) -> String {
    let mut parts: Vec<&str> = Vec::new();
    for p in path.split(['/', '\\']) {
        match p {
            "" | "." => {}
            ".." => {
                if parts.last().is_some_and(|l| *l != "..") {
                    parts.pop();
                } else {
                    parts.push("..");
                }
            }
            _ => parts.push(p),
        }
    }
    parts.join("/")
}

/// The file name of a path, with `/` or `\\` between folders.
pub(crate) fn file_name(path: &str) -> &str {
    path.rsplit(['/', '\\']).next().unwrap_or(path)
}

/// Whether a `<…>` include names a file an ORB's IDL compiler supplies itself (`<orb.idl>`,
/// TAO's and omniORB's folders): no project has it among its IDL files, so its absence is
/// only an info. Any other `<…>` include (`<BasicDataType.idl>`, as labs include OpenRTM's
/// types) is a file the project's build finds on its include path, and its absence is a
/// warning as a quoted include's is.
fn orb_supplied(name: &str) -> bool {
    const FILES: &[&str] = &[
        "orb.idl",
        "corba.idl",
        "ir.idl",
        "iop.idl",
        "giop.idl",
        "messaging.idl",
        "pollable.idl",
        "timebase.idl",
        "cosnaming.idl",
    ];
    const FOLDERS: &[&str] = &["tao", "orbsvcs", "omniorb4", "omniorb", "omnidynamic"];
    let lower = normalize(name).to_ascii_lowercase();
    let first = lower.split('/').next().unwrap_or("");
    FOLDERS.contains(&first) || FILES.contains(&file_name(&lower))
}

fn dir_of(path: &str) -> &str {
    match path.rfind(['/', '\\']) {
        Some(i) => &path[..i],
        None => "",
    }
}

impl<'a> Sources<'a> {
    pub fn new(files: &'a [SourceFile], opts: &'a IdlOptions) -> Self {
        let mut by_path: HashMap<String, Vec<usize>> = HashMap::new();
        let mut by_name: HashMap<String, Vec<usize>> = HashMap::new();
        for (i, f) in files.iter().enumerate() {
            by_path.entry(normalize(&f.path)).or_default().push(i);
            by_name
                .entry(file_name(&f.path).to_ascii_lowercase())
                .or_default()
                .push(i);
        }
        Sources {
            files,
            opts,
            lexed: vec![None; files.len()],
            by_path,
            by_name,
            diagnostics: Vec::new(),
            seen: HashSet::new(),
            cycles: HashSet::new(),
        }
    }

    /// Reports a diagnostic unless the same one was reported already (an included file's
    /// directives run once per includer).
    pub fn report(&mut self, d: Diagnostic) {
        let key = (d.file.clone(), d.pos, d.code, d.message.clone());
        if self.seen.insert(key) {
            self.diagnostics.push(d);
        }
    }

    /// Decodes and lexes file `i` (once).
    pub fn lexed(&mut self, i: usize) -> Rc<Lexed> {
        if let Some(l) = &self.lexed[i] {
            return l.clone();
        }
        let f = &self.files[i];
        let path = f.path.clone();
        let l = if f.bytes.len() as u64 > self.opts.max_file_size {
            self.report(
                Diagnostic::error(
                    codes::LIMIT,
                    &path,
                    // Read to one byte past the limit: the size beyond it is not known.
                    format!(
                        "file is larger than the limit of {} bytes; it is not read",
                        self.opts.max_file_size
                    ),
                )
                .with_hint("if the file is genuine, raise `max-file-size` in rtcdoc.toml or pass --max-file-size BYTES"),
            );
            Lexed {
                encoding: "UTF-8",
                tokens: vec![Token {
                    tok: Tok::Eof,
                    pos: Pos::new(1, 1),
                }],
            }
        } else {
            let d = decode(&f.bytes);
            if d.lossy {
                self.report(
                    Diagnostic::warning(
                        codes::ENCODING,
                        &path,
                        "the file is neither UTF-8, EUC-JP nor Shift_JIS; undecodable bytes were replaced (read as EUC-JP)",
                    )
                    .with_hint("save the file as UTF-8"),
                );
            } else if d.encoding != "UTF-8" {
                self.report(Diagnostic::info(
                    codes::ENCODING,
                    &path,
                    format!("the file is not UTF-8; it was read as {}", d.encoding),
                ));
            }
            let out = lex(&d.text, self.opts.max_tokens);
            if let Some((pos, msg, limit)) = out.fatal {
                let code = if limit { codes::LIMIT } else { codes::SYNTAX };
                let hint = if limit {
                    "no real IDL file comes near this fixed limit: look for a macro that expands without end, or split the file"
                } else {
                    "close the comment with `*/`"
                };
                self.report(Diagnostic::error(code, &path, msg).at(pos).with_hint(hint));
            }
            Lexed {
                encoding: d.encoding,
                tokens: out.tokens,
            }
        };
        let l = Rc::new(l);
        self.lexed[i] = Some(l.clone());
        l
    }

    /// Resolves an include name written in file `from`, as a C preprocessor with the IDL
    /// search path as its `-I` folders would, and leniently (profiles and IDL files name
    /// their includes by paths of their authors' machines): relative to that file; then by
    /// file name among the files of its own tree; then through the search path; then by file
    /// name among the search path's files. A file of another tree (another `[[source]]`, or
    /// the input directory for a source's file) is not on the including file's include path:
    /// `Err(Some(i))` names the copy found there, `Err(None)` says there is none.
    pub fn resolve_include(&self, from: usize, name: &str) -> Result<usize, Option<usize>> {
        let tree = &self.files[from].tree;
        let own = |i: &usize| self.files[*i].tree == *tree;
        let searched = |i: &usize| self.files[*i].tree == Tree::SearchPath;
        let at = |p: &str, ok: &dyn Fn(&usize) -> bool| {
            self.by_path
                .get(p)
                .and_then(|v| v.iter().copied().find(|i| ok(i)))
        };
        let base = dir_of(&self.files[from].path);
        let rel = if base.is_empty() {
            normalize(name)
        } else {
            normalize(&format!("{base}/{name}"))
        };
        if let Some(i) = at(&rel, &|i| own(i) || searched(i)) {
            return Ok(i);
        }
        let by_name = self.by_file_name(from, name);
        if let Some(i) = by_name.iter().copied().find(own) {
            return Ok(i);
        }
        for dir in &self.opts.search_path {
            let p = normalize(&format!("{dir}/{name}"));
            if let Some(i) = at(&p, &|i| own(i) || searched(i)) {
                return Ok(i);
            }
        }
        if let Some(i) = by_name.iter().copied().find(searched) {
            return Ok(i);
        }
        Err(by_name.first().copied())
    }

    /// The files named like `name` (case-insensitively; of those, the ones of the same case
    /// when there are any), best first: the closest to `from` by path, then the shallowest (a
    /// project's `idl/X.idl`, not its `idl/test/X.idl` or a vendored copy deeper down), then
    /// the first in order. `from` itself is not one.
    fn by_file_name(&self, from: usize, name: &str) -> Vec<usize> {
        let Some(cands) = self.by_name.get(&file_name(name).to_ascii_lowercase()) else {
            return Vec::new();
        };
        let from_path = normalize(&self.files[from].path);
        let common = |i: usize| {
            let p = normalize(&self.files[i].path);
            p.split('/')
                .zip(from_path.split('/'))
                .take_while(|(a, b)| a == b)
                .count()
        };
        let exact: Vec<usize> = cands
            .iter()
            .copied()
            .filter(|&i| file_name(&self.files[i].path) == file_name(name))
            .collect();
        let mut pool = if exact.is_empty() {
            cands.clone()
        } else {
            exact
        };
        pool.retain(|&i| i != from);
        let depth = |i: usize| self.files[i].path.split(['/', '\\']).count();
        pool.sort_by(|&a, &b| {
            common(b)
                .cmp(&common(a))
                .then(depth(a).cmp(&depth(b)))
                .then(a.cmp(&b))
        });
        pool
    }
}

#[derive(Clone)]
struct Macro {
    tokens: Vec<Token>,
    function_like: bool,
    /// What a use of it tells the parser's errors, shared by every use.
    about: std::rc::Rc<MacroAbout>,
}

/// A macro as an error message names it.
#[derive(Debug)]
pub(crate) struct MacroAbout {
    pub name: String,
    /// What it stands for, as written (empty: a use vanishes).
    pub text: String,
    /// Where `#define` wrote it (file and position); `None` for a define given to rtcdoc.
    pub defined: Option<(String, Pos)>,
}

impl Macro {
    fn new(
        name: &str,
        tokens: Vec<Token>,
        function_like: bool,
        defined: Option<(String, Pos)>,
    ) -> Macro {
        let text: Vec<String> = tokens.iter().map(Token::lexeme).collect();
        let about = std::rc::Rc::new(MacroAbout {
            name: name.to_string(),
            text: text.join(" "),
            defined,
        });
        Macro {
            tokens,
            function_like,
            about,
        }
    }
}

/// A name of the file that an object-like macro replaced (the parser's errors at or right
/// after it say so: `#define A` as an include guard makes `module A {` read `module {`).
#[derive(Debug, Clone)]
pub(crate) struct Expansion {
    pub pos: Pos,
    pub about: std::rc::Rc<MacroAbout>,
}

struct Cond {
    parent_active: bool,
    active: bool,
    taken: bool,
    else_seen: bool,
    pos: Pos,
    what: &'static str,
}

/// The preprocessed tokens of one root file, with its includes and pragmas.
pub(crate) struct Preprocessed {
    pub encoding: &'static str,
    pub tokens: Vec<Token>,
    pub includes: Vec<IdlInclude>,
    pub pragmas: Vec<IdlPragma>,
    /// The macro uses of the file, in order.
    pub expansions: Vec<Expansion>,
}

struct Pp<'s, 'a> {
    src: &'s mut Sources<'a>,
    defines: HashMap<String, Macro>,
    stack: Vec<usize>,
    out: Vec<Token>,
    includes: Vec<IdlInclude>,
    pragmas: Vec<IdlPragma>,
    expansions: Vec<Expansion>,
    over_limit: bool,
}

/// Preprocesses file `root`.
pub(crate) fn preprocess(src: &mut Sources<'_>, root: usize) -> Preprocessed {
    let mut defines = HashMap::new();
    for d in &src.opts.defines {
        let (name, value) = d.split_once('=').unwrap_or((d.as_str(), "1"));
        let name = name.trim();
        let tokens = strip_eof(lex_line(value, Pos::default()));
        defines.insert(name.to_string(), Macro::new(name, tokens, false, None));
    }
    let encoding = src.lexed(root).encoding;
    let mut pp = Pp {
        src,
        defines,
        stack: Vec::new(),
        out: Vec::new(),
        includes: Vec::new(),
        pragmas: Vec::new(),
        expansions: Vec::new(),
        over_limit: false,
    };
    pp.run_file(root, true);
    let end = pp
        .src
        .lexed(root)
        .tokens
        .last()
        .map(|t| t.pos)
        .unwrap_or_default();
    pp.out.push(Token {
        tok: Tok::Eof,
        pos: end,
    });
    Preprocessed {
        encoding,
        tokens: pp.out,
        includes: pp.includes,
        pragmas: pp.pragmas,
        expansions: pp.expansions,
    }
}

fn strip_eof(mut v: Vec<Token>) -> Vec<Token> {
    if v.last().is_some_and(|t| t.tok == Tok::Eof) {
        v.pop();
    }
    v
}

/// The first word of a directive's text, and the rest after it.
fn first_word(raw: &str) -> (&str, &str) {
    let raw = raw.trim_start();
    let end = raw
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(raw.len());
    (&raw[..end], &raw[end..])
}

impl Pp<'_, '_> {
    fn path(&self, i: usize) -> String {
        self.src.files[i].path.clone()
    }

    fn run_file(&mut self, idx: usize, emit: bool) {
        let lexed = self.src.lexed(idx);
        let path = self.path(idx);
        self.stack.push(idx);
        let mut conds: Vec<Cond> = Vec::new();
        for t in &lexed.tokens {
            let active = conds.last().is_none_or(|c| c.active);
            let d = match &t.tok {
                Tok::Directive(d) => d,
                Tok::Eof => continue,
                _ => {
                    if active && emit {
                        self.emit_token(t, &path);
                    }
                    continue;
                }
            };
            let (word, _) = first_word(&d.raw);
            match d.name.as_str() {
                "ifdef" | "ifndef" => {
                    if word.is_empty() && active {
                        self.err(&path, t.pos, format!("`#{}` needs a macro name", d.name));
                    }
                    let defined = self.defines.contains_key(word);
                    let on = active && (defined == (d.name == "ifdef"));
                    self.push_cond(&mut conds, &path, t.pos, active, on, "#ifdef");
                }
                "if" => {
                    let on = active && self.eval_if(&path, d.raw.as_str(), d.raw_pos);
                    self.push_cond(&mut conds, &path, t.pos, active, on, "#if");
                }
                "elif" => match conds.last_mut() {
                    Some(c) if !c.else_seen => {
                        let try_it = c.parent_active && !c.taken;
                        let on = try_it && {
                            let raw = d.raw.clone();
                            self.eval_if(&path, &raw, d.raw_pos)
                        };
                        if let Some(c) = conds.last_mut() {
                            c.active = on;
                            c.taken |= on;
                        }
                    }
                    Some(_) => self.err(&path, t.pos, "`#elif` after `#else`".into()),
                    None => self.err(&path, t.pos, "`#elif` without `#if`".into()),
                },
                "else" => match conds.last_mut() {
                    Some(c) if !c.else_seen => {
                        c.active = c.parent_active && !c.taken;
                        c.taken = true;
                        c.else_seen = true;
                    }
                    Some(_) => self.err(&path, t.pos, "a second `#else` for one `#if`".into()),
                    None => self.err(&path, t.pos, "`#else` without `#if`".into()),
                },
                "endif" => {
                    if conds.pop().is_none() {
                        self.err(&path, t.pos, "`#endif` without `#if`".into());
                    }
                }
                _ if !active => {}
                "define" => self.define(&path, d.raw.as_str(), d.raw_pos, t.pos),
                "undef" => {
                    self.defines.remove(word);
                }
                "include" => self.include(idx, &path, d.raw.trim(), t.pos, emit),
                "pragma" => {
                    if emit {
                        self.pragmas.push(IdlPragma {
                            text: d.raw.trim().to_string(),
                            pos: t.pos,
                        });
                        self.out.push(Token {
                            tok: Tok::Pragma(d.raw.trim().to_string()),
                            pos: t.pos,
                        });
                    }
                }
                "error" => self.src.report(
                    Diagnostic::error(
                        codes::PREPROCESSOR,
                        &path,
                        format!("#error {}", d.raw.trim()),
                    )
                    .at(t.pos)
                    .with_hint("the file stops the build on purpose here: define or undefine the macros its #if tests expect (pass the IDL directory of the installation it was written for), or exclude the file"),
                ),
                "warning" => self.src.report(
                    Diagnostic::warning(
                        codes::DIRECTIVE,
                        &path,
                        format!("#warning {}", d.raw.trim()),
                    )
                    .at(t.pos),
                ),
                // `#line` is accepted and has no effect: positions stay those of the file as
                // it is, which is where a reader can find the text.
                "line" | "ident" | "sccs" | "" => {}
                n if n.bytes().all(|b| b.is_ascii_digit()) => {}
                other => self.src.report(
                    Diagnostic::warning(
                        codes::DIRECTIVE,
                        &path,
                        format!("unknown preprocessor directive `#{other}`; the line is ignored"),
                    )
                    .at(t.pos)
                    .with_hint("IDL preprocessors know #include, #define, #undef, #if, #ifdef, #ifndef, #elif, #else, #endif, #pragma, #error, #line"),
                ),
            }
        }
        for c in conds {
            self.err(
                &path,
                c.pos,
                format!("`{}` has no matching `#endif`", c.what),
            );
        }
        self.stack.pop();
    }

    fn err(&mut self, path: &str, pos: Pos, msg: String) {
        self.src.report(
            Diagnostic::error(codes::PREPROCESSOR, path, msg)
                .at(pos)
                .with_hint("balance #if/#ifdef/#ifndef with #endif and write directives as a C preprocessor expects"),
        );
    }

    fn push_cond(
        &mut self,
        conds: &mut Vec<Cond>,
        path: &str,
        pos: Pos,
        parent_active: bool,
        on: bool,
        what: &'static str,
    ) {
        let mut on = on;
        if conds.len() >= self.src.opts.max_depth && parent_active {
            self.src.report(
                Diagnostic::error(
                    codes::LIMIT,
                    path,
                    format!(
                        "conditionals nest deeper than {} levels (the nesting limit)",
                        self.src.opts.max_depth
                    ),
                )
                .at(pos),
            );
            on = false;
        }
        conds.push(Cond {
            parent_active,
            active: on,
            taken: on,
            else_seen: false,
            pos,
            what,
        });
    }

    fn eval_if(&mut self, path: &str, raw: &str, raw_pos: Pos) -> bool {
        let toks = strip_eof(lex_line(raw, raw_pos));
        // `defined X` / `defined(X)` first, then macros, then remaining names are 0.
        let mut pre = Vec::with_capacity(toks.len());
        let mut i = 0;
        while i < toks.len() {
            if let Tok::Ident(w) = &toks[i].tok {
                if w == "defined" {
                    let paren = matches!(toks.get(i + 1).map(|t| &t.tok), Some(Tok::Punct("(")));
                    let at = if paren { i + 2 } else { i + 1 };
                    if let Some(Tok::Ident(n)) = toks.get(at).map(|t| &t.tok) {
                        let v = self.defines.contains_key(n) as u64;
                        pre.push(Token {
                            tok: Tok::Int {
                                value: v,
                                raw: v.to_string(),
                            },
                            pos: toks[i].pos,
                        });
                        i = at + 1;
                        if paren {
                            if matches!(toks.get(i).map(|t| &t.tok), Some(Tok::Punct(")"))) {
                                i += 1;
                            } else {
                                self.err(
                                    path,
                                    toks[i.min(toks.len() - 1)].pos,
                                    "expected `)` after `defined(NAME`".into(),
                                );
                                return false;
                            }
                        }
                        continue;
                    }
                    self.err(path, toks[i].pos, "`defined` needs a macro name".into());
                    return false;
                }
            }
            pre.push(toks[i].clone());
            i += 1;
        }
        let mut expanded = Vec::new();
        for t in pre {
            self.expand(t, &mut expanded, &mut Vec::new());
        }
        for t in &mut expanded {
            if matches!(t.tok, Tok::Ident(_)) {
                t.tok = Tok::Int {
                    value: 0,
                    raw: "0".into(),
                };
            }
        }
        if let Some(b) = expanded.iter().find(|t| matches!(t.tok, Tok::Bad(_))) {
            let m = b.describe();
            self.err(path, b.pos, m);
            return false;
        }
        let max_depth = self.src.opts.max_depth;
        let mut e = Eval::new(&expanded, 0, max_depth, true, |_| Some(Value::Int(0)));
        let r = e.expr();
        let end = e.i;
        match r {
            Ok(v) => {
                if end < expanded.len() {
                    let t = &expanded[end];
                    self.err(
                        path,
                        t.pos,
                        format!("unexpected {} in `#if` expression", t.describe()),
                    );
                    return false;
                }
                matches!(v, Some(Value::Int(x)) if x != 0)
                    || matches!(v, Some(Value::Bool(true)))
                    || matches!(v, Some(Value::Float(f)) if f != 0.0)
            }
            Err((pos, msg)) => {
                self.err(path, pos, msg);
                false
            }
        }
    }

    fn define(&mut self, path: &str, raw: &str, raw_pos: Pos, pos: Pos) {
        let (name, rest) = first_word(raw);
        if name.is_empty() || name.as_bytes()[0].is_ascii_digit() {
            self.err(path, pos, "`#define` needs a macro name".into());
            return;
        }
        let function_like = rest.starts_with('(');
        if function_like {
            self.src.report(
                Diagnostic::warning(
                    codes::DIRECTIVE,
                    path,
                    format!("function-like macro `{name}` is not supported; uses of it are left as they are"),
                )
                .at(pos)
                .with_hint("IDL files rarely need function-like macros; write the declaration out"),
            );
        }
        let offset = raw.len() - rest.len();
        let start = Pos::new(
            raw_pos.line,
            raw_pos.column + raw[..offset].chars().count() as u32,
        );
        let tokens = strip_eof(lex_line(rest, start));
        let defined = Some((path.to_string(), pos));
        self.defines.insert(
            name.to_string(),
            Macro::new(name, tokens, function_like, defined),
        );
    }

    /// RTC022 for an include of `name` in file `idx` (`path`) that is not found: a warning,
    /// an info for an ORB's own `<…>` file; `elsewhere` is a file of that name in another tree,
    /// named so that the copy a lenient search would have taken is not silent.
    fn not_found(
        &mut self,
        idx: usize,
        path: &str,
        name: &str,
        system: bool,
        pos: Pos,
        elsewhere: Option<usize>,
    ) {
        let written = if system {
            format!("<{name}>")
        } else {
            format!("\"{name}\"")
        };
        let files = self.src.files;
        let (message, hint) = match elsewhere {
            None => (
                format!("included file {written} was not found among the IDL files read"),
                "add the directory holding it with --idl-path (e.g. the OpenRTM installation's rtm/idl)".to_string(),
            ),
            Some(other) => (
                format!(
                    "included file {written} was not found in {own} or on the IDL path; {other} has `{}`, which is not used: the files of {other} are not on the include path of {own}",
                    files[other].path,
                    own = files[idx].tree,
                    other = files[other].tree,
                ),
                format!(
                    "add the file to {}, or add the directory holding it with --idl-path (e.g. the OpenRTM installation's rtm/idl)",
                    files[idx].tree
                ),
            ),
        };
        let d = if system && orb_supplied(name) {
            Diagnostic::info(codes::INCLUDE, path, message)
        } else {
            Diagnostic::warning(codes::INCLUDE, path, message)
        };
        self.src.report(d.at(pos).with_hint(hint));
    }

    fn include(&mut self, idx: usize, path: &str, raw: &str, pos: Pos, emit: bool) {
        let (name, system) = if let Some(r) = raw.strip_prefix('<') {
            match r.find('>') {
                Some(e) => (&r[..e], true),
                None => {
                    self.err(path, pos, "`#include <` has no closing `>`".into());
                    return;
                }
            }
        } else if let Some(r) = raw.strip_prefix('"') {
            match r.find('"') {
                Some(e) => (&r[..e], false),
                None => {
                    self.err(path, pos, "`#include \"` has no closing `\"`".into());
                    return;
                }
            }
        } else {
            self.err(
                path,
                pos,
                format!("`#include` expects \"FILE\" or <FILE>, found `{raw}`"),
            );
            return;
        };
        let target = self.src.resolve_include(idx, name);
        if emit {
            self.includes.push(IdlInclude {
                name: name.to_string(),
                system,
                resolved: target.ok().map(|t| self.src.files[t].path.clone()),
                pos,
            });
            self.out.push(Token {
                tok: Tok::IncludeMark,
                pos,
            });
        }
        let target = match target {
            Ok(t) => t,
            Err(elsewhere) => {
                self.not_found(idx, path, name, system, pos, elsewhere);
                return;
            }
        };
        if let Some(at) = self.stack.iter().position(|&f| f == target) {
            // A guarded file that is already open adds nothing: skip it quietly, as cpp would.
            if self.guard_defined(target) {
                return;
            }
            let mut cycle: Vec<usize> = self.stack[at..].to_vec();
            let min = cycle
                .iter()
                .enumerate()
                .min_by_key(|(_, &f)| self.src.files[f].path.clone())
                .map(|(i, _)| i)
                .unwrap_or(0);
            cycle.rotate_left(min);
            if self.src.cycles.insert(cycle.clone()) {
                let mut names: Vec<String> = cycle
                    .iter()
                    .map(|&f| self.src.files[f].path.clone())
                    .collect();
                names.push(names[0].clone());
                self.src.report(
                    Diagnostic::error(
                        codes::INCLUDE_CYCLE,
                        path,
                        format!("include cycle: {}", names.join(" → ")),
                    )
                    .at(pos)
                    .with_hint("add an include guard (#ifndef X / #define X / #endif) or remove one of the includes"),
                );
            }
            return;
        }
        if self.stack.len() >= self.src.opts.max_include_depth {
            self.src.report(
                Diagnostic::error(
                    codes::LIMIT,
                    path,
                    format!(
                        "includes nest deeper than {} files (the include depth limit)",
                        self.src.opts.max_include_depth
                    ),
                )
                .at(pos)
                .with_hint("an include chain this deep is a loop the guards miss: add include guards (#ifndef X / #define X / #endif)"),
            );
            return;
        }
        self.run_file(target, false);
    }

    /// Whether file `f` starts with `#ifndef X` for a macro X that is defined now.
    fn guard_defined(&mut self, f: usize) -> bool {
        let lexed = self.src.lexed(f);
        let first = lexed
            .tokens
            .iter()
            .find(|t| !matches!(t.tok, Tok::Doc { .. }));
        match first.map(|t| &t.tok) {
            Some(Tok::Directive(d)) if d.name == "ifndef" => {
                self.defines.contains_key(first_word(&d.raw).0)
            }
            _ => false,
        }
    }

    fn emit_token(&mut self, t: &Token, path: &str) {
        if self.over_limit {
            return;
        }
        match &t.tok {
            Tok::Bad(m) => {
                let m = m.clone();
                self.src.report(
                    Diagnostic::error(codes::SYNTAX, path, m)
                        .at(t.pos)
                        .with_hint("remove or fix the text at this position"),
                );
            }
            Tok::Ident(name) => {
                if let Some(m) = self.defines.get(name).filter(|m| !m.function_like) {
                    self.expansions.push(Expansion {
                        pos: t.pos,
                        about: m.about.clone(),
                    });
                }
                let mut out = std::mem::take(&mut self.out);
                self.expand(t.clone(), &mut out, &mut Vec::new());
                self.out = out;
            }
            _ => self.out.push(t.clone()),
        }
        if self.out.len() > self.src.opts.max_tokens {
            self.over_limit = true;
            self.src.report(
                Diagnostic::error(
                    codes::LIMIT,
                    path,
                    format!(
                        "macro expansion makes more than {} tokens (the limit against hostile input); the rest of the file is not read",
                        self.src.opts.max_tokens
                    ),
                )
                .at(t.pos),
            );
            self.out.truncate(self.src.opts.max_tokens);
        }
    }

    /// Appends `t` to `out`, replacing an object-like macro by its tokens (recursively, each
    /// macro at most once on the way down, as in C), all at the position of the use.
    fn expand(&self, t: Token, out: &mut Vec<Token>, active: &mut Vec<String>) {
        let name = match &t.tok {
            Tok::Ident(n) => n,
            _ => {
                out.push(t);
                return;
            }
        };
        match self.defines.get(name) {
            Some(m)
                if !m.function_like
                    && !active.contains(name)
                    && active.len() < 64
                    && out.len() <= self.src.opts.max_tokens =>
            {
                active.push(name.clone());
                for r in &m.tokens {
                    self.expand(
                        Token {
                            tok: r.tok.clone(),
                            pos: t.pos,
                        },
                        out,
                        active,
                    );
                }
                active.pop();
            }
            _ => out.push(t),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalizes_paths() {
        assert_eq!(normalize("a\\b/./c/../d.idl"), "a/b/d.idl");
        assert_eq!(normalize("../x.idl"), "../x.idl");
    }
}
