//! Documentation coverage of the IDL the catalogue uses: RTC506 (struct, exception and union
//! fields), RTC507 (enum values), RTC508 (interface operations and attributes) without a doc
//! comment.
//!
//! Only definitions with a page are counted: every data type entry (port types and, after
//! [`Catalog::attach_idl`], the types they contain and the types interfaces use) and every
//! interface entry (those a port names, every one the input's IDL defines, and their bases). A type defined in
//! several files (vendored copies) counts once, at the definition lookups return (the first
//! full definition in file order). OpenRTM's own IDL given through `--idl-path` counts when a
//! port uses it, like the catalogue's own files: its documentation is what the pages show.

use super::registry as r;
use super::rules::Findings;
use crate::catalog::Catalog;
use crate::diagnostic::Diagnostic;
use crate::idl::{IdlDefinition, IdlDoc, IdlField, IdlItem};
use crate::model::Pos;
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
fn members<'a>(item: IdlItem<'a>, out: Option<&mut Vec<Diagnostic>>) -> Option<IdlCoverage> {
    let d = item.definition;
    let scoped = d.scoped_name();
    let mut sink = Findings {
        file: &item.file.path,
        out: Vec::new(),
    };
    let kind = d.kind_word();
    // Each member counted: its word, name, doc comment, position and the code reporting it.
    let fields = |fs: &'a [IdlField], word| {
        fs.iter()
            .map(move |f| (word, &f.name, f.doc.as_deref(), f.pos, r::DOC_IDL_FIELD))
    };
    let list: Vec<(&str, &String, Option<&IdlDoc>, Pos, &str)> = match d {
        IdlDefinition::Struct(x) => fields(&x.fields, "field").collect(),
        IdlDefinition::Exception(x) => fields(&x.fields, "field").collect(),
        IdlDefinition::Union(x) => x
            .cases
            .iter()
            .map(|c| &c.field)
            .map(|f| ("case", &f.name, f.doc.as_deref(), f.pos, r::DOC_IDL_FIELD))
            .collect(),
        IdlDefinition::Enum(x) => x
            .values
            .iter()
            .map(|v| {
                (
                    "value",
                    &v.name,
                    v.doc.as_deref(),
                    v.pos,
                    r::DOC_IDL_ENUMERATOR,
                )
            })
            .collect(),
        IdlDefinition::Interface(x) => {
            let ops = x
                .operations
                .iter()
                .map(|o| ("operation", &o.name, o.doc.as_deref(), o.pos));
            let attrs = x
                .attributes
                .iter()
                .map(|a| ("attribute", &a.name, a.doc.as_deref(), a.pos));
            ops.chain(attrs)
                .map(|(w, n, doc, pos)| (w, n, doc, pos, r::DOC_IDL_OPERATION))
                .collect()
        }
        // Typedefs, forward declarations and the rest have no members to document.
        _ => return None,
    };
    let total = list.len();
    let mut documented_n = 0;
    for (word, name, doc, pos, code) in list {
        if documented(doc) {
            documented_n += 1;
        } else if out.is_some() {
            let message = format!("{word} `{name}` of {kind} `{scoped}` has no doc comment");
            sink.emit(code, pos, message);
        }
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
