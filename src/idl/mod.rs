//! The IDL reader: OMG IDL (CORBA 3) files as OpenRTM and its users write them → a typed,
//! serializable model of their declarations, with doc comments, repository ids and
//! cross-file name resolution.
//!
//! # Pipeline
//! ```text
//! SourceFile (path, bytes)
//!   ─decode─▶ text (UTF-8 / EUC-JP / Shift_JIS, BOM, CRLF/CR)        decode.rs
//!   ─lex────▶ tokens + doc comments + directive lines (once per file)  lex.rs
//!   ─pp─────▶ the file's own tokens, conditionals and macros applied;  pp.rs
//!             includes followed for their directives only
//!   ─parse──▶ IdlDefinition tree, repository ids, doc comments         parse.rs, doc.rs, expr.rs
//!   ─index──▶ IdlSet: every file, names resolved by IDL scoping rules,  (this file)
//!             lookups by scoped name, simple name or repository id
//! ```
//! No I/O: the caller hands in every file (those found below the input and on the IDL search
//! path); an `#include` is resolved among them (relative to the including file, then through
//! [`IdlOptions::search_path`], then by file name, since profiles and IDL files name
//! their includes by paths of their authors' machines).
//!
//! # Why hand-written
//! No crate we found reads these files faithfully (a DDS-oriented parser rejects CORBA-3 names
//! such as a field called `map`; tree-sitter-idl fails on `#ifdef`; a pest grammar drops
//! comments). The grammar is small, and a hand-written lexer and recursive-descent parser keep
//! what a documentation tool needs and generated parsers drop: doc comments in place,
//! original positions through includes, recovery after an error, and explicit limits on every
//! kind of nesting (see [`IdlOptions`]).
//!
//! # Diagnostics
//! `file:line:col: error[RTC02x]: message` with a hint, through [`crate::diagnostic`]; the
//! codes are in [`codes`] and documented in `check --explain`. Each diagnostic is reported once
//! even when a file is included by many others.

pub(crate) mod decode;
mod doc;
mod expr;
mod lex;
mod parse;
pub(crate) mod pp;

pub use crate::model::idl::*;

use crate::diagnostic::Diagnostic;
use crate::model::Pos;
use std::collections::{HashMap, HashSet};

/// One input file: the path shown to users (relative to the input or the IDL search path
/// root, `/`-separated), its bytes and the tree it belongs to.
#[derive(Debug, Clone)]
pub struct SourceFile {
    pub path: String,
    pub bytes: Vec<u8>,
    pub tree: Tree,
}

impl SourceFile {
    /// A file of the input directory ([`Tree::Input`]).
    pub fn new(path: impl Into<String>, bytes: impl Into<Vec<u8>>) -> Self {
        SourceFile {
            path: path.into(),
            bytes: bytes.into(),
            tree: Tree::Input,
        }
    }

    /// The same file, of `tree`.
    pub fn in_tree(self, tree: Tree) -> Self {
        SourceFile { tree, ..self }
    }
}

/// The tree of files a file was read from. An include is looked for as a C preprocessor
/// looks for it: in the including file's own tree (its folder first), then on the IDL search
/// path; never in another tree. Each `[[source]]` is a repository built on its own, so
/// another source's copy of a file is not what its build includes: it is named in the
/// RTC022 warning instead of being used.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub enum Tree {
    /// The input directory (every file of a caller that names no trees).
    #[default]
    Input,
    /// A `[[source]]` repository, by name.
    Source(String),
    /// A directory of the IDL search path (`--idl-path`, `idl-path`): searched from every tree.
    SearchPath,
}

impl std::fmt::Display for Tree {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Tree::Input => f.write_str("the input directory"),
            Tree::Source(name) => write!(f, "the source `{name}`"),
            Tree::SearchPath => f.write_str("the IDL path"),
        }
    }
}

/// How to read IDL, and the limits against hostile input.
#[derive(Debug, Clone)]
pub struct IdlOptions {
    /// Macros defined before every file: `NAME` (defined as `1`) or `NAME=VALUE`.
    pub defines: Vec<String>,
    /// Directories (display-path prefixes of the given files, e.g. `idl` or
    /// `openrtm/rtm/idl`) searched for an include after the including file's own tree.
    pub search_path: Vec<String>,
    /// Largest file read, in bytes (default 16 MiB).
    pub max_file_size: u64,
    /// Deepest nesting of scopes, types, expressions and `#if`s (default 64).
    pub max_depth: usize,
    /// Deepest chain of includes (default 32).
    pub max_include_depth: usize,
    /// Most tokens in one file, after macro expansion (default 2,000,000 ≈ a 10 MB file).
    pub max_tokens: usize,
}

impl Default for IdlOptions {
    fn default() -> Self {
        IdlOptions {
            defines: Vec::new(),
            search_path: Vec::new(),
            max_file_size: 16 * 1024 * 1024,
            max_depth: 64,
            max_include_depth: 32,
            max_tokens: 2_000_000,
        }
    }
}

/// Codes of the IDL reader's diagnostics (RTC020–RTC029), spelled once with the loader's in
/// [`crate::diagnostic::codes`].
pub mod codes {
    pub use crate::diagnostic::codes::{
        IDL_DIRECTIVE as DIRECTIVE, IDL_ENCODING as ENCODING, IDL_INCLUDE as INCLUDE,
        IDL_INCLUDE_CYCLE as INCLUDE_CYCLE, IDL_LIMIT as LIMIT, IDL_PREPROCESSOR as PREPROCESSOR,
        IDL_REDEFINITION as REDEFINITION, IDL_SKIPPED as SKIPPED, IDL_SYNTAX as SYNTAX,
        IDL_UNRESOLVED as UNRESOLVED,
    };
}

/// Where a definition is: the file and the index path through nested definitions.
#[derive(Debug, Clone, PartialEq, Eq)]
struct DefLoc {
    file: usize,
    path: Vec<usize>,
}

/// Every file read, their diagnostics, and lookups over all their definitions.
#[derive(Debug, Clone, Default)]
pub struct IdlSet {
    pub files: Vec<IdlFile>,
    /// Sorted by file and position.
    pub diagnostics: Vec<Diagnostic>,
    by_scoped: HashMap<String, Vec<DefLoc>>,
    by_repo_id: HashMap<String, Vec<DefLoc>>,
    by_simple: HashMap<String, Vec<String>>,
}

impl IdlSet {
    /// No IDL file was read.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }
}

/// In `catalog.json`: the files with their definitions (the diagnostics are the catalogue's).
impl serde::Serialize for IdlSet {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("IdlSet", 1)?;
        st.serialize_field("files", &self.files)?;
        st.end()
    }
}

/// Read back from `catalog.json`: the files, with the lookups built again (names were
/// resolved when the files were read, and are kept in the definitions).
impl<'de> serde::Deserialize<'de> for IdlSet {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(serde::Deserialize)]
        struct Files {
            files: Vec<IdlFile>,
        }
        Ok(IdlSet::from_files(Files::deserialize(d)?.files))
    }
}

impl IdlSet {
    /// The set of files read back (from `catalog.json`), with the lookups built again: names
    /// were resolved when the files were read, and are kept in the definitions.
    pub fn from_files(files: Vec<IdlFile>) -> IdlSet {
        let mut set = IdlSet {
            files,
            ..IdlSet::default()
        };
        set.build_index(&mut Vec::new());
        set
    }
}

/// A definition found by a lookup, with the file it is in.
#[derive(Debug, Clone, Copy)]
pub struct IdlItem<'a> {
    pub file: &'a IdlFile,
    pub definition: &'a IdlDefinition,
}

/// A syntax error at a name an object-like macro replaced, or right after one on the same
/// line, gets a hint that says so: `#define A` (an include guard) makes `module A {` read
/// `module {`, and the error alone points at the `{`.
fn macro_hint(d: Diagnostic, expansions: &[pp::Expansion]) -> Diagnostic {
    let Some(at) = d.pos.filter(|_| d.code == codes::SYNTAX) else {
        return d;
    };
    let Some(e) = expansions
        .iter()
        .rev()
        .find(|e| e.pos.line == at.line && e.pos.column <= at.column)
    else {
        return d;
    };
    let m = &e.about;
    let place = match &m.defined {
        Some((file, pos)) => format!(" at {file}:{}:{}", pos.line, pos.column),
        None => String::new(),
    };
    let name = &m.name;
    let what = if m.text.is_empty() {
        format!("`{name}` here is a macro defined empty{place} (an include guard?), so the preprocessor removed it")
    } else {
        format!(
            "`{name}` here is a macro defined{place} as `{}`, so the preprocessor replaced it",
            m.text
        )
    };
    d.with_hint(format!(
        "{what}: give the macro another name (`{name}_IDL`) or rename this `{name}`"
    ))
}

/// Reads every file: each is a document of its own; includes resolve among them.
pub fn read(files: &[SourceFile], opts: &IdlOptions) -> IdlSet {
    let mut src = pp::Sources::new(files, opts);
    let mut out = Vec::with_capacity(files.len());
    for (i, f) in files.iter().enumerate() {
        let pre = pp::preprocess(&mut src, i);
        let parsed = parse::parse(pre.tokens, &f.path, opts);
        for d in parsed.diagnostics {
            src.report(macro_hint(d, &pre.expansions));
        }
        out.push(IdlFile {
            path: f.path.clone(),
            origin: None,
            idl_path: f.tree == Tree::SearchPath,
            encoding: pre.encoding.to_string(),
            doc: parsed.doc,
            includes: pre.includes,
            pragmas: pre.pragmas,
            definitions: parsed.definitions,
        });
    }
    let mut diagnostics = std::mem::take(&mut src.diagnostics);
    drop(src);
    let mut set = IdlSet {
        files: out,
        ..IdlSet::default()
    };
    set.build_index(&mut diagnostics);
    set.resolve_names(&mut diagnostics);
    crate::diagnostic::sort(&mut diagnostics);
    set.diagnostics = diagnostics;
    set
}

fn index_defs(
    defs: &[IdlDefinition],
    file: usize,
    path: &mut Vec<usize>,
    f: &mut impl FnMut(&IdlDefinition, DefLoc),
) {
    for (k, d) in defs.iter().enumerate() {
        path.push(k);
        f(
            d,
            DefLoc {
                file,
                path: path.clone(),
            },
        );
        index_defs(d.children(), file, path, f);
        path.pop();
    }
}

impl IdlSet {
    fn build_index(&mut self, diags: &mut Vec<Diagnostic>) {
        let mut by_scoped: HashMap<String, Vec<DefLoc>> = HashMap::new();
        let mut by_repo_id: HashMap<String, Vec<DefLoc>> = HashMap::new();
        for (fi, file) in self.files.iter().enumerate() {
            // Same name twice in this file (modules reopen and forward declarations precede
            // definitions legally).
            let mut seen: HashMap<String, Pos> = HashMap::new();
            index_defs(&file.definitions, fi, &mut Vec::new(), &mut |d, loc| {
                let scoped = d.scoped_name();
                if scoped.is_empty() {
                    return;
                }
                if !matches!(d, IdlDefinition::Module(_) | IdlDefinition::Forward(_)) {
                    if let Some(first) = seen.get(scoped) {
                        diags.push(
                            Diagnostic::warning(
                                codes::REDEFINITION,
                                &file.path,
                                format!(
                                    "`{scoped}` is declared again (first at line {}, column {})",
                                    first.line, first.column
                                ),
                            )
                            .at(d.pos())
                            .with_hint("rename one of them, or remove the duplicate"),
                        );
                    } else {
                        seen.insert(scoped.to_string(), d.pos());
                    }
                }
                if !d.repository_id().is_empty() {
                    by_repo_id
                        .entry(d.repository_id().to_string())
                        .or_default()
                        .push(loc.clone());
                }
                by_scoped.entry(scoped.to_string()).or_default().push(loc);
            });
        }
        let mut by_simple: HashMap<String, Vec<String>> = HashMap::new();
        let mut names: Vec<&String> = by_scoped.keys().collect();
        names.sort();
        for n in names {
            let simple = n.rsplit("::").next().unwrap_or(n);
            by_simple
                .entry(simple.to_string())
                .or_default()
                .push(n.clone());
        }
        self.by_scoped = by_scoped;
        self.by_repo_id = by_repo_id;
        self.by_simple = by_simple;
    }

    fn resolve_names(&mut self, diags: &mut Vec<Diagnostic>) {
        let known: HashSet<String> = self.by_scoped.keys().cloned().collect();
        // Every interface's bases (scoped names), so that a name an interface inherits is
        // found in its scope (CORBA: an interface's scope holds its bases' declarations).
        let mut bases: HashMap<String, Vec<String>> = HashMap::new();
        for file in &self.files {
            collect_bases(&file.definitions, &mut Vec::new(), &known, &mut bases);
        }
        for file in &mut self.files {
            let mut unresolved: Vec<(String, Pos)> = Vec::new();
            let mut r = Resolver {
                known: &known,
                bases: &bases,
                scope: Vec::new(),
                unresolved: &mut unresolved,
            };
            r.defs(&mut file.definitions);
            let mut reported = HashSet::new();
            for (name, pos) in unresolved {
                if reported.insert(name.clone()) {
                    diags.push(
                        Diagnostic::info(
                            codes::UNRESOLVED,
                            &file.path,
                            format!("type `{name}` is not defined in any IDL file read"),
                        )
                        .at(pos)
                        .with_hint("add the IDL file that defines it (e.g. the OpenRTM IDL directory) with --idl-path"),
                    );
                }
            }
        }
    }

    fn get(&self, loc: &DefLoc) -> Option<IdlItem<'_>> {
        let file = self.files.get(loc.file)?;
        let mut defs = &file.definitions;
        let mut found = None;
        for &k in &loc.path {
            let d = defs.get(k)?;
            found = Some(d);
            defs = match d {
                IdlDefinition::Module(m) => &m.definitions,
                IdlDefinition::Interface(i) => &i.definitions,
                _ => defs,
            };
        }
        found.map(|definition| IdlItem { file, definition })
    }

    /// Every definition `name` names: a scoped name (`RTC::TimedLong`, `::RTC::TimedLong`),
    /// a repository id (`IDL:RTC/TimedLong:1.0`, also with a prefix), or a name without
    /// module when only one definition has it (`TimedLong`). In file order.
    pub fn find_all(&self, name: &str) -> Vec<IdlItem<'_>> {
        let locs = self.locate(name.trim());
        locs.iter().filter_map(|l| self.get(l)).collect()
    }

    /// The definition `name` names (see [`IdlSet::find_all`]): a full definition rather than
    /// a forward declaration, the first in file order among equals.
    pub fn find(&self, name: &str) -> Option<IdlItem<'_>> {
        let all = self.find_all(name);
        all.iter()
            .find(|i| !matches!(i.definition, IdlDefinition::Forward(_)))
            .or(all.first())
            .copied()
    }

    /// What [`NearNames::of`] looks through: the last names of the types (no modules) this
    /// set defines, made once for every name looked up.
    pub fn near_names(&self) -> NearNames {
        let mut names: Vec<(crate::suggest::Lowered, String, Vec<String>)> = self
            .by_simple
            .iter()
            .map(|(simple, scoped)| {
                let types: Vec<String> = scoped
                    .iter()
                    .filter(|s| {
                        self.find(s)
                            .is_some_and(|i| !matches!(i.definition, IdlDefinition::Module(_)))
                    })
                    .cloned()
                    .collect();
                (crate::suggest::Lowered::new(simple), simple.clone(), types)
            })
            .filter(|(_, _, types)| !types.is_empty())
            .collect();
        names.sort_unstable();
        NearNames { names }
    }

    /// The scoped names a lookup would return (for callers that only need the key).
    pub fn scoped_name_of(&self, name: &str) -> Option<String> {
        self.find(name)
            .map(|i| i.definition.scoped_name().to_string())
    }

    /// The canonical spelling of a type name ([`crate::types::canonical_type`]), a
    /// repository id resolved against the ids of the definitions read (a `#pragma prefix`,
    /// `ID` or `version` included): `IDL:example.com/Lab/Pose:1.0` is `Lab::Pose` when a file
    /// read defines it under that id. Any other name, or an id no file defines, is spelled as
    /// [`crate::types::canonical_type`] spells it.
    pub fn canonical_name(&self, name: &str) -> String {
        let trimmed = name.trim();
        if trimmed.starts_with("IDL:") {
            if let Some(l) = self.by_repo_id.get(trimmed).and_then(|l| l.first()) {
                if let Some(item) = self.get(l) {
                    return crate::types::canonical_type(item.definition.scoped_name());
                }
            }
        }
        crate::types::canonical_type(name)
    }

    fn locate(&self, name: &str) -> Vec<DefLoc> {
        if let Some(rest) = name.strip_prefix("IDL:") {
            if let Some(l) = self.by_repo_id.get(name) {
                return l.clone();
            }
            // A repository id this set does not have as such (other version or prefix):
            // try the name parts, longest first.
            let body = rest.rsplit_once(':').map_or(rest, |(b, _)| b);
            let parts: Vec<&str> = body.split('/').collect();
            for k in 0..parts.len() {
                let scoped = parts[k..].join("::");
                if let Some(l) = self.by_scoped.get(&scoped) {
                    return l.clone();
                }
            }
            return Vec::new();
        }
        let name = name.strip_prefix("::").unwrap_or(name);
        if let Some(l) = self.by_scoped.get(name) {
            return l.clone();
        }
        let simple = name.rsplit("::").next().unwrap_or(name);
        let Some(cands) = self.by_simple.get(simple) else {
            return Vec::new();
        };
        let suffix = format!("::{name}");
        let matching: Vec<&String> = cands.iter().filter(|c| c.ends_with(&suffix)).collect();
        match matching.as_slice() {
            [one] => self.by_scoped.get(*one).cloned().unwrap_or_default(),
            _ => Vec::new(),
        }
    }
}

/// The last names of an [`IdlSet`]'s types, to find near matches of a name it does not
/// define ([`IdlSet::near_names`]).
#[derive(Debug, Clone, Default)]
pub struct NearNames {
    /// (the last name in lower case, as written, the scoped names of the types that have it)
    names: Vec<(crate::suggest::Lowered, String, Vec<String>)>,
}

impl NearNames {
    /// The scoped names of the types a reader who wrote `name`, which names none, may have
    /// meant: those of the same last name in other modules (`Img::CameraCaptureService` for
    /// `OpenHRP::CameraCaptureService`), then those whose last name is a few edits from it
    /// ([`crate::suggest::Lowered::edits`]: case ignored), nearest first; at most `max`.
    pub fn of(&self, name: &str, max: usize) -> Vec<String> {
        let name = name.trim();
        let simple = match name.strip_prefix("IDL:") {
            Some(rest) => rest
                .rsplit_once(':')
                .map_or(rest, |(b, _)| b)
                .rsplit('/')
                .next()
                .unwrap_or(rest),
            None => name.rsplit("::").next().unwrap_or(name),
        };
        let want = crate::suggest::Lowered::new(simple);
        // (0: the same last name, 1 + distance: a near one; scoped name)
        let mut near: Vec<(usize, &String)> = Vec::new();
        for (lower, written, scoped) in &self.names {
            let rank = if written == simple {
                0
            } else if let Some(d) = want.edits(lower) {
                1 + d
            } else {
                continue;
            };
            near.extend(scoped.iter().map(|s| (rank, s)));
        }
        near.sort_unstable();
        near.into_iter().map(|(_, s)| s.clone()).take(max).collect()
    }
}

/// Resolves `IdlType::Named` by IDL scoping rules: the enclosing scopes from the innermost
/// outward, then the global scope; a name starting with `::` from the global scope only.
/// The bases of every interface in `defs` (in `scope`), resolved from the scope that holds the
/// interface, into `out` by the interface's scoped name.
fn collect_bases(
    defs: &[IdlDefinition],
    scope: &mut Vec<String>,
    known: &HashSet<String>,
    out: &mut HashMap<String, Vec<String>>,
) {
    for d in defs {
        match d {
            IdlDefinition::Module(m) => {
                scope.push(m.name.clone());
                collect_bases(&m.definitions, scope, known, out);
                scope.pop();
            }
            IdlDefinition::Interface(i) => {
                let outer = Resolver {
                    known,
                    bases: &HashMap::new(),
                    scope: scope.clone(),
                    unresolved: &mut Vec::new(),
                };
                let resolved: Vec<String> = i
                    .bases
                    .iter()
                    .filter_map(|b| match b {
                        IdlType::Named { name, .. } => outer.lookup(name),
                        _ => None,
                    })
                    .collect();
                scope.push(i.name.clone());
                out.insert(scope.join("::"), resolved);
                collect_bases(&i.definitions, scope, known, out);
                scope.pop();
            }
            _ => {}
        }
    }
}

struct Resolver<'k, 'u> {
    known: &'k HashSet<String>,
    /// Each interface's bases ([`collect_bases`]).
    bases: &'k HashMap<String, Vec<String>>,
    scope: Vec<String>,
    unresolved: &'u mut Vec<(String, Pos)>,
}

impl Resolver<'_, '_> {
    fn defs(&mut self, defs: &mut [IdlDefinition]) {
        for d in defs {
            match d {
                IdlDefinition::Module(m) => {
                    self.scope.push(m.name.clone());
                    self.defs(&mut m.definitions);
                    self.scope.pop();
                }
                IdlDefinition::Struct(s) => self.fields(&mut s.fields),
                IdlDefinition::Exception(s) => self.fields(&mut s.fields),
                IdlDefinition::Union(u) => {
                    self.ty(&mut u.switch_type, u.pos);
                    for c in &mut u.cases {
                        self.ty(&mut c.field.ty, c.field.pos);
                    }
                }
                IdlDefinition::Typedef(t) => self.ty(&mut t.ty, t.pos),
                IdlDefinition::Const(c) => self.ty(&mut c.ty, c.pos),
                IdlDefinition::Interface(i) => {
                    for b in &mut i.bases {
                        self.ty(b, i.pos);
                    }
                    self.scope.push(i.name.clone());
                    for a in &mut i.attributes {
                        self.ty(&mut a.ty, a.pos);
                        for r in &mut a.raises {
                            self.ty(r, a.pos);
                        }
                    }
                    for o in &mut i.operations {
                        if let Some(t) = &mut o.return_type {
                            self.ty(t, o.pos);
                        }
                        for p in &mut o.params {
                            self.ty(&mut p.ty, p.pos);
                        }
                        for r in &mut o.raises {
                            self.ty(r, o.pos);
                        }
                    }
                    self.defs(&mut i.definitions);
                    self.scope.pop();
                }
                IdlDefinition::Enum(_)
                | IdlDefinition::Forward(_)
                | IdlDefinition::Native(_)
                | IdlDefinition::Skipped(_) => {}
            }
        }
    }

    fn fields(&mut self, fields: &mut [IdlField]) {
        for f in fields {
            self.ty(&mut f.ty, f.pos);
        }
    }

    fn ty(&mut self, t: &mut IdlType, pos: Pos) {
        let mut t = t;
        loop {
            match t {
                IdlType::Sequence { element, .. } => t = element,
                IdlType::Named { name, resolved } => {
                    *resolved = self.lookup(name);
                    if resolved.is_none() {
                        self.unresolved.push((name.clone(), pos));
                    }
                    return;
                }
                _ => return,
            }
        }
    }

    fn lookup(&self, name: &str) -> Option<String> {
        if let Some(abs) = name.strip_prefix("::") {
            return self.known.contains(abs).then(|| abs.to_string());
        }
        for k in (0..=self.scope.len()).rev() {
            let cand = if k == 0 {
                name.to_string()
            } else {
                format!("{}::{name}", self.scope[..k].join("::"))
            };
            if self.known.contains(&cand) {
                return Some(cand);
            }
            if k > 0 {
                if let Some(found) = self.inherited(&self.scope[..k].join("::"), name) {
                    return Some(found);
                }
            }
        }
        None
    }

    /// `name` declared in a base of interface `iface`, its bases' bases after (each interface
    /// looked at once, whatever cycles the input has).
    fn inherited(&self, iface: &str, name: &str) -> Option<String> {
        let mut queue: std::collections::VecDeque<&str> =
            self.bases.get(iface)?.iter().map(String::as_str).collect();
        let mut seen: HashSet<&str> = HashSet::from([iface]);
        while let Some(b) = queue.pop_front() {
            if !seen.insert(b) {
                continue;
            }
            let cand = format!("{b}::{name}");
            if self.known.contains(&cand) {
                return Some(cand);
            }
            queue.extend(self.bases.get(b).into_iter().flatten().map(String::as_str));
        }
        None
    }
}
