//! Documentation coverage of the IDL the catalogue uses: RTC506 (struct, exception and union
//! fields), RTC507 (enum values), RTC508 (interface operations and attributes) without a doc
//! comment.
//!
//! Only definitions the catalogue's ports reach are counted: every data type entry (port types
//! and, after [`Catalog::attach_idl`], the types they contain and the types interfaces use)
//! and every service interface a port names, with its base interfaces. A type defined in
//! several files (vendored copies) counts once, at the definition lookups return (the first
//! full definition in file order). OpenRTM's own IDL given through `--idl-path` counts when a
//! port uses it, like the catalogue's own files: its documentation is what the pages show.

use super::registry as r;
use super::rules::Findings;
use crate::catalog::Catalog;
use crate::diagnostic::Diagnostic;
use crate::idl::{IdlDefinition, IdlDoc, IdlItem};
use serde::Serialize;

/// Documentation coverage of one IDL definition.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct IdlCoverage {
    /// Scoped name (`RTC::TimedLong`).
    pub name: String,
    /// `struct`, `exception`, `union`, `enum` or `interface`.
    pub kind: &'static str,
    /// The IDL file holding the definition counted (display path).
    pub file: String,
    /// Fields, values, operations and attributes with a doc comment.
    pub documented: usize,
    pub total: usize,
    /// `documented / total` in percent.
    pub percent: f64,
}

/// A doc comment that says something.
fn documented(doc: Option<&IdlDoc>) -> bool {
    doc.is_some_and(|d| !d.text.trim().is_empty() || !d.brief.trim().is_empty())
}

/// The definitions counted, each once, in catalogue order: data types by name, then
/// interfaces by name, each followed by its base interfaces not met before.
fn counted(cat: &Catalog) -> Vec<IdlItem<'_>> {
    let mut seen = std::collections::HashSet::new();
    let mut out = Vec::new();
    for t in &cat.data_types {
        if let Some(item) = cat.idl.find(&t.name) {
            if seen.insert(item.definition.scoped_name()) {
                out.push(item);
            }
        }
    }
    let mut queue: Vec<IdlItem<'_>> = Vec::new();
    for t in &cat.interfaces {
        queue.extend(cat.idl.find(&t.name));
        while let Some(item) = queue.pop() {
            let IdlDefinition::Interface(i) = item.definition else {
                continue;
            };
            if !seen.insert(item.definition.scoped_name()) {
                continue;
            }
            out.push(item);
            // Bases after the interface, first base first.
            for b in i.bases.iter().rev() {
                let name = match b {
                    crate::idl::IdlType::Named { name, resolved } => {
                        resolved.as_deref().unwrap_or(name)
                    }
                    _ => continue,
                };
                queue.extend(cat.idl.find(name));
            }
        }
    }
    out
}

/// Counts (and, with `out`, reports) the undocumented members of one definition.
fn members(item: IdlItem<'_>, out: Option<&mut Vec<Diagnostic>>) -> Option<IdlCoverage> {
    let d = item.definition;
    let scoped = d.scoped_name();
    let mut sink = Findings {
        file: &item.file.path,
        out: Vec::new(),
    };
    let mut documented_n = 0;
    let mut total = 0;
    let mut count = |ok: bool, code: &'static str, pos, what: String, s: &mut Findings| {
        total += 1;
        if ok {
            documented_n += 1;
        } else if out.is_some() {
            s.emit(code, pos, format!("{what} has no doc comment"));
        }
    };
    let kind = d.kind_word();
    match d {
        IdlDefinition::Struct(x) => {
            for f in &x.fields {
                let what = format!("field `{}` of struct `{scoped}`", f.name);
                count(
                    documented(f.doc.as_deref()),
                    r::DOC_IDL_FIELD,
                    f.pos,
                    what,
                    &mut sink,
                );
            }
        }
        IdlDefinition::Exception(x) => {
            for f in &x.fields {
                let what = format!("field `{}` of exception `{scoped}`", f.name);
                count(
                    documented(f.doc.as_deref()),
                    r::DOC_IDL_FIELD,
                    f.pos,
                    what,
                    &mut sink,
                );
            }
        }
        IdlDefinition::Union(x) => {
            for c in &x.cases {
                let f = &c.field;
                let what = format!("case `{}` of union `{scoped}`", f.name);
                count(
                    documented(f.doc.as_deref()),
                    r::DOC_IDL_FIELD,
                    f.pos,
                    what,
                    &mut sink,
                );
            }
        }
        IdlDefinition::Enum(x) => {
            for v in &x.values {
                let what = format!("value `{}` of enum `{scoped}`", v.name);
                count(
                    documented(v.doc.as_deref()),
                    r::DOC_IDL_ENUMERATOR,
                    v.pos,
                    what,
                    &mut sink,
                );
            }
        }
        IdlDefinition::Interface(x) => {
            for o in &x.operations {
                let what = format!("operation `{}` of interface `{scoped}`", o.name);
                count(
                    documented(o.doc.as_deref()),
                    r::DOC_IDL_OPERATION,
                    o.pos,
                    what,
                    &mut sink,
                );
            }
            for a in &x.attributes {
                let what = format!("attribute `{}` of interface `{scoped}`", a.name);
                count(
                    documented(a.doc.as_deref()),
                    r::DOC_IDL_OPERATION,
                    a.pos,
                    what,
                    &mut sink,
                );
            }
        }
        // Typedefs, forward declarations and the rest have no members to document.
        _ => return None,
    }
    if let Some(o) = out {
        o.extend(sink.out);
    }
    Some(IdlCoverage {
        name: scoped.to_string(),
        kind,
        file: item.file.path.clone(),
        documented: documented_n,
        total,
        percent: super::percent(documented_n, total),
    })
}

/// RTC506–RTC508 over the IDL the catalogue uses.
pub(crate) fn diagnostics(cat: &Catalog) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for item in counted(cat) {
        members(item, Some(&mut out));
    }
    out
}

/// The coverage of every IDL definition counted that has members (in catalogue order).
pub(crate) fn coverage(cat: &Catalog) -> Vec<IdlCoverage> {
    counted(cat)
        .into_iter()
        .filter_map(|item| members(item, None))
        .filter(|c| c.total > 0)
        .collect()
}
