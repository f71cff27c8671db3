//! What a data-type or interface page shows of its IDL definition: the fields of a struct or
//! exception, the values of an enum, the cases of a union, what a typedef names, and an
//! interface's operations, attributes and bases — each type linked to its own page when the
//! catalogue has one. Shared by the renderers; the definitions come from [`crate::idl`].

use super::text::Markup;
use crate::i18n::Lang;
use crate::idl::{IdlDefinition, IdlDoc, IdlField, IdlParamDirection, IdlType};
use serde::Serialize;

/// A type as written, with the page of the named type it is (or holds, for a sequence).
#[derive(Debug, Clone, Serialize, PartialEq, Eq)]
pub struct TypeRef {
    pub text: String,
    /// Relative to the site root (`types/rtc-time.html`), when there is such a page.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub page: Option<String>,
    /// The catalogue entry of that page (for the Markdown and Doxygen links).
    #[serde(skip)]
    pub entry: Option<TypeIx>,
}

use crate::catalog::{Catalog, Page, TypeIx};

#[derive(Debug, Clone, Serialize)]
pub struct FieldView {
    pub name: String,
    pub ty: TypeRef,
    /// `[3][4]` for an array field.
    pub array: String,
    pub doc: String,
    /// Union case labels (`case 1, 2` / `default`).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub labels: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct ValueView {
    pub name: String,
    pub doc: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct ParamView {
    pub direction: &'static str,
    pub ty: TypeRef,
    pub name: String,
    pub doc: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct OperationView {
    pub name: String,
    pub returns: TypeRef,
    pub oneway: bool,
    pub params: Vec<ParamView>,
    pub raises: Vec<TypeRef>,
    pub doc: String,
    /// The `@return` text.
    pub returns_doc: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct AttributeView {
    pub name: String,
    pub ty: TypeRef,
    pub readonly: bool,
    pub doc: String,
}

/// The definition of one type or interface, ready for a page.
#[derive(Debug, Clone, Serialize)]
pub struct DefinitionView {
    /// `struct`, `enum`, `union`, `typedef`, `exception`, `interface`, …
    pub kind: &'static str,
    pub scoped_name: String,
    pub repository_id: String,
    /// The IDL file, relative to the input or to its `--idl-path` directory.
    pub file: String,
    pub line: u32,
    pub brief: String,
    pub details: String,
    pub fields: Vec<FieldView>,
    pub values: Vec<ValueView>,
    /// A union's discriminator type.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub switch: Option<TypeRef>,
    /// What a typedef names.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub aliases: Option<TypeRef>,
    pub operations: Vec<OperationView>,
    pub attributes: Vec<AttributeView>,
    pub bases: Vec<TypeRef>,
    /// The operations of an interface's bases (theirs too, each base once, nearest first):
    /// a provider implements them as well.
    pub inherited: Vec<InheritedView>,
}

impl DefinitionView {
    /// Every type the definition names (fields, values' types, a union's switch, what a
    /// typedef names, operations' returns, parameters and exceptions, attributes, bases and
    /// what the bases give), for a renderer that links them its own way (a system manual).
    pub fn type_refs_mut(&mut self) -> Vec<&mut TypeRef> {
        fn ops<'a>(out: &mut Vec<&'a mut TypeRef>, o: &'a mut [OperationView]) {
            for op in o {
                out.push(&mut op.returns);
                out.extend(op.params.iter_mut().map(|p| &mut p.ty));
                out.extend(op.raises.iter_mut());
            }
        }
        let mut out: Vec<&mut TypeRef> = Vec::new();
        out.extend(self.fields.iter_mut().map(|f| &mut f.ty));
        out.extend(self.switch.iter_mut());
        out.extend(self.aliases.iter_mut());
        ops(&mut out, &mut self.operations);
        out.extend(self.attributes.iter_mut().map(|a| &mut a.ty));
        out.extend(self.bases.iter_mut());
        for g in &mut self.inherited {
            out.push(&mut g.base);
            ops(&mut out, &mut g.operations);
            out.extend(g.attributes.iter_mut().map(|a| &mut a.ty));
        }
        out
    }
}

/// The operations and attributes an interface inherits from one base, each shown on the base's
/// page.
#[derive(Debug, Clone, Serialize)]
pub struct InheritedView {
    pub base: TypeRef,
    pub operations: Vec<OperationView>,
    pub attributes: Vec<AttributeView>,
}

/// The documentation of `doc` for a page in `lang`: the `@if jp` (or `ja`) part of OpenRTM's
/// bilingual comments for Japanese, the rest for English; a comment written in one language
/// only is shown in it for both.
fn in_lang(doc: Option<&IdlDoc>, lang: Lang) -> Option<&IdlDoc> {
    let d = doc?;
    let ja = d
        .languages
        .iter()
        .find(|l| matches!(l.lang.as_str(), "jp" | "ja"))
        .map(|l| &*l.doc);
    let en = d
        .languages
        .iter()
        .find(|l| matches!(l.lang.as_str(), "en" | "eng"))
        .map(|l| &*l.doc);
    let empty = |x: &IdlDoc| x.brief.is_empty() && x.details.is_empty();
    Some(match (lang, ja, en) {
        (Lang::Ja, Some(j), _) if !empty(j) => j,
        (Lang::En, _, Some(e)) if !empty(e) => e,
        (_, Some(j), _) if empty(d) && !empty(j) => j,
        _ => d,
    })
}

/// Everything of `d` after its brief and details, in reading order, each part a paragraph:
/// the sections (`Title: text`), the parameters and return value (`with_params`: an operation
/// shows them apart), the exceptions, notes, see-also and every other tag (`pre: …`), so that
/// nothing a comment says is left off its page.
fn more(d: &IdlDoc, lang: Lang, with_params: bool) -> Vec<String> {
    let mut out = Vec::new();
    let mut push = |label: &str, text: &str| {
        let text = text.trim();
        match (label.is_empty(), text.is_empty()) {
            (_, true) if label.is_empty() => {}
            (true, _) => out.push(text.to_string()),
            (false, true) => out.push(label.to_string()),
            (false, false) => out.push(format!("{label}: {text}")),
        }
    };
    for sec in &d.sections {
        push(&sec.title, &sec.text);
    }
    if with_params {
        for p in &d.params {
            push(&p.name, &p.text);
        }
        if let Some(r) = &d.returns {
            push(lang.t("idl_returns"), r);
        }
    }
    for e in &d.exceptions {
        push(&format!("{} {}", lang.t("idl_raises"), e.name), &e.text);
    }
    for n in &d.notes {
        push(lang.t("idl_note"), n);
    }
    for x in &d.see {
        push(lang.t("idl_see"), x);
    }
    for t in &d.tags {
        let label = match t.tag.as_str() {
            "pre" => lang.t("pre_condition"),
            "post" => lang.t("post_condition"),
            other => other,
        };
        push(label, &t.text);
    }
    out
}

/// All of a member's documentation (a field, value, attribute, parameter or operation) on one
/// line, for a table cell: the brief, then [`more`].
fn line(doc: Option<&IdlDoc>, lang: Lang, with_params: bool) -> String {
    let Some(d) = in_lang(doc, lang) else {
        return String::new();
    };
    let mut parts = vec![brief(Some(d)), after_brief(d).to_string()];
    parts.extend(more(d, lang, with_params));
    parts.retain(|p| !p.is_empty());
    parts
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The details that [`brief`] does not show: all of them after a brief, else all but their
/// first paragraph (which is the brief).
fn after_brief(d: &IdlDoc) -> &str {
    if !d.brief.is_empty() {
        &d.details
    } else {
        d.details.split_once("\n\n").map_or("", |(_, rest)| rest)
    }
}

/// One line of documentation: the brief, else the first paragraph.
fn brief(doc: Option<&IdlDoc>) -> String {
    doc.map(|d| {
        if d.brief.is_empty() {
            d.details
                .split("\n\n")
                .next()
                .unwrap_or("")
                .trim()
                .to_string()
        } else {
            d.brief.clone()
        }
    })
    .unwrap_or_default()
}

/// Resolves type names to the catalogue's pages.
struct Linker<'a> {
    catalog: &'a Catalog,
    lang: Lang,
}

impl Linker<'_> {
    fn entry_of(&self, scoped: &str) -> Option<(TypeIx, String)> {
        let c = self.catalog;
        if let Some(i) = c.data_type_index(scoped) {
            return Some((TypeIx::Data(i), c.data_type_page(i).path("html")));
        }
        let i = c.interface_index_of(scoped)?;
        Some((TypeIx::Interface(i), c.interface_page(i).path("html")))
    }

    fn type_ref(&self, ty: &IdlType) -> TypeRef {
        let mut inner = ty;
        while let IdlType::Sequence { element, .. } = inner {
            inner = element;
        }
        let found = match inner {
            IdlType::Named { name, resolved } => {
                self.entry_of(resolved.as_deref().unwrap_or(name.as_str()))
            }
            _ => None,
        };
        TypeRef {
            text: ty.to_idl(),
            page: found.as_ref().map(|(_, p)| p.clone()),
            entry: found.map(|(e, _)| e),
        }
    }

    fn field(&self, f: &IdlField, labels: String) -> FieldView {
        FieldView {
            name: f.name.clone(),
            ty: self.type_ref(&f.ty),
            array: f.array.iter().map(|b| format!("[{}]", b.expr)).collect(),
            doc: line(f.doc.as_deref(), self.lang, true),
            labels,
        }
    }
}

/// The operations and attributes interface `i` inherits, by base: its bases, then theirs, breadth first, each
/// interface once (whatever cycles the input has), `i` itself never.
fn inherited(l: &Linker<'_>, i: &crate::idl::IdlInterface) -> Vec<InheritedView> {
    let idl = &l.catalog.idl;
    let mut seen = std::collections::HashSet::from([i.scoped_name.clone()]);
    let mut queue: std::collections::VecDeque<IdlType> = i.bases.iter().cloned().collect();
    let mut out = Vec::new();
    while let Some(b) = queue.pop_front() {
        let IdlType::Named { name, resolved } = &b else {
            continue;
        };
        let Some(item) = idl.find(resolved.as_deref().unwrap_or(name)) else {
            continue;
        };
        let IdlDefinition::Interface(base) = item.definition else {
            continue;
        };
        if !seen.insert(base.scoped_name.clone()) {
            continue;
        }
        queue.extend(base.bases.iter().cloned());
        if base.operations.is_empty() && base.attributes.is_empty() {
            continue;
        }
        let found = l.entry_of(&base.scoped_name);
        out.push(InheritedView {
            base: TypeRef {
                text: base.scoped_name.clone(),
                page: found.as_ref().map(|(_, p)| p.clone()),
                entry: found.map(|(e, _)| e),
            },
            operations: base
                .operations
                .iter()
                .map(|o| operation_view(l, o))
                .collect(),
            attributes: base
                .attributes
                .iter()
                .map(|a| attribute_view(l, a))
                .collect(),
        });
    }
    out
}

/// The view of attribute `a` of an interface, its type linked.
fn attribute_view(l: &Linker<'_>, a: &crate::idl::IdlAttribute) -> AttributeView {
    AttributeView {
        name: a.name.clone(),
        ty: l.type_ref(&a.ty),
        readonly: a.readonly,
        doc: line(a.doc.as_deref(), l.lang, true),
    }
}

/// The view of operation `o` of an interface, its types linked.
fn operation_view(l: &Linker<'_>, o: &crate::idl::IdlOperation) -> OperationView {
    let doc = in_lang(o.doc.as_deref(), l.lang);
    let doc_of = |name: &str| {
        doc.and_then(|d| d.params.iter().find(|p| p.name == name))
            .map(|p| p.text.clone())
    };
    OperationView {
        name: o.name.clone(),
        returns: o
            .return_type
            .as_ref()
            .map(|t| l.type_ref(t))
            .unwrap_or(TypeRef {
                text: "void".into(),
                page: None,
                entry: None,
            }),
        oneway: o.oneway,
        params: o
            .params
            .iter()
            .map(|p| ParamView {
                direction: match p.direction {
                    IdlParamDirection::In => "in",
                    IdlParamDirection::Out => "out",
                    IdlParamDirection::Inout => "inout",
                },
                ty: l.type_ref(&p.ty),
                name: p.name.clone(),
                doc: doc_of(&p.name)
                    .or_else(|| p.doc.as_deref().map(|d| line(Some(d), l.lang, true)))
                    .unwrap_or_default(),
            })
            .collect(),
        raises: o.raises.iter().map(|t| l.type_ref(t)).collect(),
        doc: line(o.doc.as_deref(), l.lang, false),
        returns_doc: doc.and_then(|d| d.returns.clone()).unwrap_or_default(),
    }
}

/// The view of the definition of `name` (any spelling the catalogue accepts), or `None` when no
/// IDL file read defines it. A typedef is shown as what it is, with the type it names linked.
pub fn definition(catalog: &Catalog, name: &str, lang: Lang) -> Option<DefinitionView> {
    let scoped = crate::types::canonical_type(name);
    let item = catalog
        .idl
        .find(&scoped)
        .or_else(|| catalog.idl.find(name))?;
    let d = item.definition;
    let l = Linker { catalog, lang };
    let doc = in_lang(d.doc(), lang);
    let mut v = DefinitionView {
        kind: d.kind_word(),
        scoped_name: d.scoped_name().to_string(),
        repository_id: d.repository_id().to_string(),
        file: item.file.path.clone(),
        line: d.pos().line,
        brief: brief(doc),
        details: doc
            .map(|d| {
                let mut parts = vec![after_brief(d).trim().to_string()];
                parts.extend(more(d, lang, true));
                parts.retain(|p| !p.is_empty());
                parts.join("\n\n")
            })
            .unwrap_or_default(),
        fields: Vec::new(),
        values: Vec::new(),
        switch: None,
        aliases: None,
        operations: Vec::new(),
        attributes: Vec::new(),
        bases: Vec::new(),
        inherited: Vec::new(),
    };
    match d {
        IdlDefinition::Struct(s) => {
            v.fields = s.fields.iter().map(|f| l.field(f, String::new())).collect()
        }
        IdlDefinition::Exception(e) => {
            v.fields = e.fields.iter().map(|f| l.field(f, String::new())).collect()
        }
        IdlDefinition::Enum(e) => {
            v.values = e
                .values
                .iter()
                .map(|x| ValueView {
                    name: x.name.clone(),
                    doc: line(x.doc.as_deref(), lang, true),
                })
                .collect()
        }
        IdlDefinition::Union(u) => {
            v.switch = Some(l.type_ref(&u.switch_type));
            v.fields = u
                .cases
                .iter()
                .map(|c| {
                    // `default:` is the case's default flag (the reader may list it among the
                    // labels too): said once.
                    let mut labels: Vec<String> = c
                        .labels
                        .iter()
                        .filter(|x| x.trim() != "default")
                        .map(|x| format!("case {x}"))
                        .collect();
                    if c.is_default || c.labels.iter().any(|x| x.trim() == "default") {
                        labels.push("default".into());
                    }
                    l.field(&c.field, labels.join(", "))
                })
                .collect()
        }
        IdlDefinition::Typedef(t) => {
            let mut r = l.type_ref(&t.ty);
            for b in &t.array {
                r.text.push_str(&format!("[{}]", b.expr));
            }
            v.aliases = Some(r);
        }
        IdlDefinition::Interface(i) => {
            v.bases = i.bases.iter().map(|b| l.type_ref(b)).collect();
            v.attributes = i.attributes.iter().map(|a| attribute_view(&l, a)).collect();
            v.operations = i.operations.iter().map(|o| operation_view(&l, o)).collect();
            v.inherited = inherited(&l, i);
        }
        _ => {}
    }
    Some(v)
}

/// The fields of a struct or exception, or the cases of a union (`union`: with their labels),
/// as a table; `ty` writes a type.
fn fields_table<M: Markup>(
    out: &mut String,
    fields: &[FieldView],
    union: bool,
    lang: Lang,
    ty: &dyn Fn(&TypeRef) -> String,
) {
    let rows: Vec<Vec<String>> = fields
        .iter()
        .map(|f| {
            let mut row = Vec::new();
            if union {
                row.push(M::esc(&f.labels));
            }
            row.push(M::esc(&format!("{}{}", f.name, f.array)));
            row.push(ty(&f.ty));
            row.push(M::esc(&f.doc));
            row
        })
        .collect();
    let mut cols = Vec::new();
    if union {
        cols.push(lang.t("idl_cases"));
    }
    cols.extend([lang.t("idl_field"), lang.t("type"), lang.t("description")]);
    M::table(out, &cols, &rows);
}

/// The operations of an interface as a table: name, return type, parameters, exceptions and
/// documentation; `ty` writes a type (linked to its page when it has one).
fn operations_table<M: Markup>(
    out: &mut String,
    operations: &[OperationView],
    lang: Lang,
    ty: &dyn Fn(&TypeRef) -> String,
) {
    let rows: Vec<Vec<String>> = operations
        .iter()
        .map(|o| {
            let params: Vec<String> = o
                .params
                .iter()
                .map(|p| {
                    let mut s =
                        format!("{} {} {}", M::esc(p.direction), ty(&p.ty), M::esc(&p.name));
                    if !p.doc.is_empty() {
                        s.push_str(&format!(": {}", M::esc(&p.doc)));
                    }
                    s
                })
                .collect();
            let raises: Vec<String> = o.raises.iter().map(ty).collect();
            let mut doc = M::esc(&o.doc);
            if !o.returns_doc.is_empty() {
                doc.push_str(&format!(
                    " {}: {}",
                    M::esc(lang.t("idl_returns")),
                    M::esc(&o.returns_doc)
                ));
            }
            let name = if o.oneway {
                format!("oneway {}", o.name)
            } else {
                o.name.clone()
            };
            vec![
                M::esc(&name),
                ty(&o.returns),
                params.join("; "),
                raises.join(", "),
                doc,
            ]
        })
        .collect();
    // A column empty in every row (no operation raises anything) is left out.
    super::text::sparse_table::<M>(
        out,
        2,
        &[
            lang.t("idl_operations"),
            lang.t("idl_returns"),
            lang.t("idl_params"),
            lang.t("idl_raises"),
            lang.t("description"),
        ],
        &rows,
    );
}

/// The inherited operations and attributes of an interface, a table of each per base: each
/// linked to the base's page, with its documentation.
fn inherited_tables<M: Markup>(
    out: &mut String,
    inherited: &[InheritedView],
    lang: Lang,
    ty: &dyn Fn(&TypeRef) -> String,
) {
    for g in inherited {
        let base = ty(&g.base);
        M::paragraph(
            out,
            &format!("{} {base}", M::esc(lang.t("idl_inherited_from"))),
        );
        // A member's name linked to the base's page, its note, and its documentation.
        let row = |name: &str, note: &str, doc: &str| {
            let link = ty(&TypeRef {
                text: name.to_string(),
                ..g.base.clone()
            });
            vec![format!("{link}{note}"), M::esc(doc)]
        };
        let readonly = format!(" ({})", M::esc(lang.t("idl_readonly")));
        let operations = g.operations.iter().map(|o| row(&o.name, "", &o.doc));
        let attributes = g.attributes.iter().map(|a| {
            let note = if a.readonly { readonly.as_str() } else { "" };
            row(&a.name, note, &a.doc)
        });
        for (key, rows) in [
            ("idl_operations", operations.collect::<Vec<_>>()),
            ("idl_attributes", attributes.collect()),
        ] {
            if !rows.is_empty() {
                M::table(out, &[lang.t(key), lang.t("description")], &rows);
            }
        }
    }
}

/// The definition of `name` as Markdown or Doxygen (through [`Markup`]): where it is defined,
/// its documentation, and tables of its fields, values, operations and attributes, with types
/// linked to their pages from page `from`. `heading` writes a level-2 section heading. Nothing when no IDL
/// defines the type.
pub fn write_definition<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    from: &Page,
    name: &str,
    lang: Lang,
    heading: &dyn Fn(&mut String, &str, &str),
) {
    let Some(d) = definition(cat, name, lang) else {
        M::paragraph(out, &M::esc(lang.t("idl_no_definition")));
        return;
    };
    let ty = |r: &TypeRef| -> String {
        match r.entry {
            Some(TypeIx::Data(i)) => {
                M::link(&r.text, &M::page_target(cat, from, cat.data_type_page(i)))
            }
            Some(TypeIx::Interface(i)) => {
                M::link(&r.text, &M::page_target(cat, from, cat.interface_page(i)))
            }
            None => M::esc(&r.text),
        }
    };
    heading(
        out,
        "sec-definition",
        &format!("{} ({})", lang.t("idl_definition"), d.kind),
    );
    let mut at = format!("{} {}:{}", lang.t("idl_defined_in"), d.file, d.line);
    if !d.repository_id.is_empty() {
        at.push_str(&format!(" · {}", d.repository_id));
    }
    M::paragraph(out, &M::esc(&at));
    for text in [&d.brief, &d.details] {
        if !text.is_empty() {
            M::paragraph(out, &M::esc(text));
        }
    }
    for (key, r) in [("idl_aliases", &d.aliases), ("idl_switch", &d.switch)] {
        if let Some(r) = r {
            M::paragraph(out, &format!("{}: {}", M::esc(lang.t(key)), ty(r)));
        }
    }
    if !d.bases.is_empty() {
        let b: Vec<String> = d.bases.iter().map(ty).collect();
        M::paragraph(
            out,
            &format!("{}: {}", M::esc(lang.t("idl_bases")), b.join(", ")),
        );
    }
    if !d.fields.is_empty() {
        fields_table::<M>(out, &d.fields, d.kind == "union", lang, &ty);
    }
    if !d.values.is_empty() {
        let pairs = d.values.iter().map(|v| (&v.name, &v.doc));
        let headers = [lang.t("idl_values"), lang.t("description")];
        super::text::pairs_table::<M, _, _>(out, headers, pairs);
    }
    if !d.operations.is_empty() {
        operations_table::<M>(out, &d.operations, lang, &ty);
    }
    inherited_tables::<M>(out, &d.inherited, lang, &ty);
    if !d.attributes.is_empty() {
        let rows: Vec<Vec<String>> = d
            .attributes
            .iter()
            .map(|a| {
                let name = if a.readonly {
                    format!("{} ({})", a.name, lang.t("idl_readonly"))
                } else {
                    a.name.clone()
                };
                vec![M::esc(&name), ty(&a.ty), M::esc(&a.doc)]
            })
            .collect();
        super::text::sparse_table::<M>(
            out,
            2,
            &[
                lang.t("idl_attributes"),
                lang.t("type"),
                lang.t("description"),
            ],
            &rows,
        );
    }
    let t = cat.data_type(name).filter(|t| !t.contained_in.is_empty());
    if let Some(t) = t {
        let items: Vec<String> = t
            .contained_in
            .iter()
            .map(|n| match cat.data_type_index(n) {
                Some(c) => M::link(n, &M::page_target(cat, from, cat.data_type_page(c))),
                None => M::esc(n),
            })
            .collect();
        M::paragraph(
            out,
            &format!(
                "{}: {}",
                M::esc(lang.t("idl_contained_in")),
                items.join(", ")
            ),
        );
    }
}
