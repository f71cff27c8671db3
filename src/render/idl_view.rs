//! What a data-type or interface page shows of its IDL definition: the fields of a struct or
//! exception, the values of an enum, the cases of a union, what a typedef names, and an
//! interface's operations, attributes and bases — each type linked to its own page when the
//! catalogue has one. Shared by the renderers; the definitions come from [`crate::idl`].

use crate::catalog::Catalog;
use crate::idl::{IdlDefinition, IdlDoc, IdlField, IdlParamDirection, IdlType};
use serde::Serialize;

/// A type as written, with the page of the named type it is (or holds, for a sequence).
#[derive(Debug, Clone, Serialize, PartialEq, Eq)]
pub struct TypeRef {
    pub text: String,
    /// Relative to the site root (`types/rtc-time.html`), when there is such a page.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub page: Option<String>,
}

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
}

impl Linker<'_> {
    fn page_of(&self, scoped: &str) -> Option<String> {
        if let Some(t) = self.catalog.data_type(scoped) {
            return Some(format!("types/{}.html", t.slug));
        }
        self.catalog
            .interface(scoped)
            .map(|i| format!("interfaces/{}.html", i.slug))
    }

    fn type_ref(&self, ty: &IdlType) -> TypeRef {
        let mut inner = ty;
        while let IdlType::Sequence { element, .. } = inner {
            inner = element;
        }
        let page = match inner {
            IdlType::Named { name, resolved } => {
                self.page_of(resolved.as_deref().unwrap_or(name.as_str()))
            }
            _ => None,
        };
        TypeRef {
            text: ty.to_idl(),
            page,
        }
    }

    fn field(&self, f: &IdlField, labels: String) -> FieldView {
        FieldView {
            name: f.name.clone(),
            ty: self.type_ref(&f.ty),
            array: f.array.iter().map(|b| format!("[{}]", b.expr)).collect(),
            doc: brief(f.doc.as_ref()),
            labels,
        }
    }
}

/// The view of the definition of `name` (any spelling the catalogue accepts), or `None` when no
/// IDL file read defines it. A typedef is shown as what it is, with the type it names linked.
pub fn definition(catalog: &Catalog, name: &str) -> Option<DefinitionView> {
    let scoped = crate::types::canonical_type(name);
    let item = catalog
        .idl
        .find(&scoped)
        .or_else(|| catalog.idl.find(name))?;
    let d = item.definition;
    let l = Linker { catalog };
    let doc = d.doc();
    let mut v = DefinitionView {
        kind: d.kind_word(),
        scoped_name: d.scoped_name().to_string(),
        repository_id: d.repository_id().to_string(),
        file: item.file.path.clone(),
        line: d.pos().line,
        brief: brief(doc),
        details: doc
            .map(|d| {
                if d.brief.is_empty() {
                    // The first paragraph is the brief already.
                    d.details
                        .split_once("\n\n")
                        .map(|(_, rest)| rest.trim().to_string())
                        .unwrap_or_default()
                } else {
                    d.details.trim().to_string()
                }
            })
            .unwrap_or_default(),
        fields: Vec::new(),
        values: Vec::new(),
        switch: None,
        aliases: None,
        operations: Vec::new(),
        attributes: Vec::new(),
        bases: Vec::new(),
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
                    doc: brief(x.doc.as_ref()),
                })
                .collect()
        }
        IdlDefinition::Union(u) => {
            v.switch = Some(l.type_ref(&u.switch_type));
            v.fields = u
                .cases
                .iter()
                .map(|c| {
                    let mut labels: Vec<String> =
                        c.labels.iter().map(|x| format!("case {x}")).collect();
                    if c.is_default {
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
            v.attributes = i
                .attributes
                .iter()
                .map(|a| AttributeView {
                    name: a.name.clone(),
                    ty: l.type_ref(&a.ty),
                    readonly: a.readonly,
                    doc: brief(a.doc.as_ref()),
                })
                .collect();
            v.operations =
                i.operations
                    .iter()
                    .map(|o| {
                        let doc_of = |name: &str| {
                            o.doc
                                .as_ref()
                                .and_then(|d| d.params.iter().find(|p| p.name == name))
                                .map(|p| p.text.clone())
                        };
                        OperationView {
                            name: o.name.clone(),
                            returns: o.return_type.as_ref().map(|t| l.type_ref(t)).unwrap_or(
                                TypeRef {
                                    text: "void".into(),
                                    page: None,
                                },
                            ),
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
                                        .or_else(|| p.doc.as_ref().map(|d| brief(Some(d))))
                                        .unwrap_or_default(),
                                })
                                .collect(),
                            raises: o.raises.iter().map(|t| l.type_ref(t)).collect(),
                            doc: brief(o.doc.as_ref()),
                            returns_doc: o
                                .doc
                                .as_ref()
                                .and_then(|d| d.returns.clone())
                                .unwrap_or_default(),
                        }
                    })
                    .collect();
        }
        _ => {}
    }
    Some(v)
}
