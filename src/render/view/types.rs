//! The page of a data type or a service interface: one view for both ("a type"), with its
//! uses grouped by role (producers/consumers for a data type, providers/requirers for an
//! interface, and ports of other kinds).

use super::Linked;
use crate::catalog::{Catalog, InterfaceRef, Page, PageKind, PortRef};
use crate::i18n::Lang;
use crate::model::non_empty;

/// Which of the two a type page documents.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TypeKind {
    Data,
    Interface,
}

impl TypeKind {
    /// The page kind of the kind's index.
    pub fn index_kind(self) -> PageKind {
        match self {
            TypeKind::Data => PageKind::DataTypes,
            TypeKind::Interface => PageKind::Interfaces,
        }
    }

    /// The label key of the kind's index (`data_types`, `interfaces`).
    pub fn index_key(self) -> &'static str {
        match self {
            TypeKind::Data => "data_types",
            TypeKind::Interface => "interfaces",
        }
    }
}

/// One port (or interface of a service port) using the type: its component, the port, and
/// the type as that profile spells it.
pub struct UseRow<'a> {
    pub component: Linked<'a>,
    pub port: Linked<'a>,
    pub written: String,
}

/// The uses of one role, under a heading with a stable anchor.
pub struct UseGroup<'a> {
    pub anchor: &'static str,
    pub label: &'static str,
    pub rows: Vec<UseRow<'a>>,
}

/// Everything a type page says.
pub struct TypeView<'a> {
    pub kind: TypeKind,
    pub page: &'a Page,
    /// The index page of its kind (data types or interfaces).
    pub index: &'a Page,
    pub name: &'a str,
    /// An interface some component requires and none provides.
    pub unprovided: bool,
    pub spellings: &'a [String],
    pub idl_files: &'a [String],
    /// The non-empty role groups, in order.
    pub uses: Vec<UseGroup<'a>>,
    /// The connectors of RT Systems carrying a data type, linked to their system.
    pub carried_by: Vec<Linked<'a>>,
    /// The data types whose fields (or typedef) hold this one, linked to their pages.
    pub contained_in: Vec<Linked<'a>>,
}

/// The row of a use by component `ci`: `port` (its text) linked to `anchor` on the component's
/// page, and the type as the profile writes it.
fn use_row<'a>(
    cat: &'a Catalog,
    ci: usize,
    port: &str,
    anchor: &'a str,
    written: &str,
) -> UseRow<'a> {
    let c = &cat.components[ci];
    let page = cat.component_page(ci);
    UseRow {
        component: Linked::new(&c.display_name(), Some(page), None),
        port: Linked::new(port, Some(page), Some(anchor)),
        written: written.to_string(),
    }
}

fn port_rows<'a>(cat: &'a Catalog, refs: &[PortRef]) -> Vec<UseRow<'a>> {
    refs.iter()
        .filter_map(|r| {
            let (ci, pi) = cat.resolve_port(r)?;
            let c = &cat.components[ci];
            let port = &c.profile.data_ports[pi];
            let name = port.name.as_deref().unwrap_or_default();
            let written = non_empty(&port.type_).unwrap_or("");
            Some(use_row(cat, ci, name, &c.anchors.data_ports[pi], written))
        })
        .collect()
}

fn interface_rows<'a>(cat: &'a Catalog, refs: &[InterfaceRef]) -> Vec<UseRow<'a>> {
    refs.iter()
        .filter_map(|r| {
            let (ci, pi, ii) = cat.resolve_interface(r)?;
            let c = &cat.components[ci];
            let sp = &c.profile.service_ports[pi];
            let i = &sp.interfaces[ii];
            let name = format!(
                "{}.{}",
                sp.name.as_deref().unwrap_or(""),
                i.name.as_deref().unwrap_or("")
            );
            let written = non_empty(&i.type_).unwrap_or("");
            Some(use_row(
                cat,
                ci,
                &name,
                &c.anchors.interfaces[pi][ii],
                written,
            ))
        })
        .collect()
}

fn groups<'a>(list: [(&'static str, &'static str, Vec<UseRow<'a>>); 3]) -> Vec<UseGroup<'a>> {
    list.into_iter()
        .filter(|(_, _, rows)| !rows.is_empty())
        .map(|(anchor, label, rows)| UseGroup {
            anchor,
            label,
            rows,
        })
        .collect()
}

/// The view of data type `ti` ([`Catalog::data_types`]).
pub fn data_type_view(cat: &Catalog, ti: usize, lang: Lang) -> TypeView<'_> {
    let t = &cat.data_types[ti];
    TypeView {
        kind: TypeKind::Data,
        page: cat.data_type_page(ti),
        index: cat.site_page(TypeKind::Data.index_kind()),
        name: &t.name,
        unprovided: false,
        spellings: &t.spellings,
        idl_files: &t.idl_files,
        uses: groups([
            (
                "sec-producers",
                lang.t("producers"),
                port_rows(cat, &t.producers),
            ),
            (
                "sec-consumers",
                lang.t("consumers"),
                port_rows(cat, &t.consumers),
            ),
            (
                "sec-others",
                lang.t("fact_others"),
                port_rows(cat, &t.others),
            ),
        ]),
        carried_by: crate::render::system_text::carrying(cat, &t.name)
            .into_iter()
            .filter_map(|(text, s)| {
                let page = cat.page_of_system(s)?;
                Some(Linked::new(&text, Some(page), Some("data-connectors")))
            })
            .collect(),
        contained_in: t
            .contained_in
            .iter()
            .map(|n| {
                Linked::new(
                    n,
                    cat.data_type_index(n).map(|c| cat.data_type_page(c)),
                    None,
                )
            })
            .collect(),
    }
}

/// The view of interface `ii` ([`Catalog::interfaces`]).
pub fn interface_view(cat: &Catalog, ii: usize, lang: Lang) -> TypeView<'_> {
    let t = &cat.interfaces[ii];
    TypeView {
        kind: TypeKind::Interface,
        page: cat.interface_page(ii),
        index: cat.site_page(TypeKind::Interface.index_kind()),
        name: &t.name,
        unprovided: t.is_unprovided(),
        spellings: &t.spellings,
        idl_files: &t.idl_files,
        uses: groups([
            (
                "sec-providers",
                lang.t("providers"),
                interface_rows(cat, &t.providers),
            ),
            (
                "sec-requirers",
                lang.t("requirers"),
                interface_rows(cat, &t.requirers),
            ),
            (
                "sec-others",
                lang.t("fact_others"),
                interface_rows(cat, &t.others),
            ),
        ]),
        carried_by: Vec::new(),
        contained_in: Vec::new(),
    }
}

/// One entry of the data type or interface index: its page, name, the other spellings
/// met, its numbers of uses by role (producers, consumers, others for a data type; providers,
/// requirers, others for an interface) and whether it is an interface no component provides.
pub struct TypeIndexRow<'a> {
    pub page: &'a Page,
    pub name: &'a str,
    pub other_spellings: Vec<&'a str>,
    pub counts: [usize; 3],
    pub unprovided: bool,
}

/// The index of the data types or of the interfaces.
pub struct TypeIndexView<'a> {
    pub kind: TypeKind,
    pub page: &'a Page,
    pub rows: Vec<TypeIndexRow<'a>>,
}

/// The spellings of a type other than its `name`.
fn other_spellings<'a>(name: &str, spellings: &'a [String]) -> Vec<&'a str> {
    spellings
        .iter()
        .filter(|s| *s != name)
        .map(String::as_str)
        .collect()
}

/// The view of the index of `kind`: every data type or interface of the catalogue, in order.
pub fn type_index_view(cat: &Catalog, kind: TypeKind) -> TypeIndexView<'_> {
    let rows = match kind {
        TypeKind::Data => cat
            .data_types
            .iter()
            .enumerate()
            .map(|(ti, t)| TypeIndexRow {
                page: cat.data_type_page(ti),
                name: &t.name,
                other_spellings: other_spellings(&t.name, &t.spellings),
                counts: [t.producers.len(), t.consumers.len(), t.others.len()],
                unprovided: false,
            })
            .collect(),
        TypeKind::Interface => cat
            .interfaces
            .iter()
            .enumerate()
            .map(|(ii, t)| TypeIndexRow {
                page: cat.interface_page(ii),
                name: &t.name,
                other_spellings: other_spellings(&t.name, &t.spellings),
                counts: [t.providers.len(), t.requirers.len(), t.others.len()],
                unprovided: t.is_unprovided(),
            })
            .collect(),
    };
    TypeIndexView {
        kind,
        page: cat.site_page(kind.index_kind()),
        rows,
    }
}
