//! The page of a data type or a service interface: one view for both ("a type"), with its
//! uses grouped by role (producers/consumers for a data type, providers/requirers for an
//! interface, and ports of other kinds).

use super::Linked;
use crate::catalog::{
    Catalog, InterfaceRef, Ix, Page, PageKind, PortRef, Role, TypeEntry, TypeIx, Uses,
};
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

    /// The handles of the catalogue's entries of the kind, in order.
    pub fn entries(self, cat: &Catalog) -> Vec<TypeIx> {
        match self {
            TypeKind::Data => Ix::all(cat.data_types.len()).map(TypeIx::Data).collect(),
            TypeKind::Interface => Ix::all(cat.interfaces.len())
                .map(TypeIx::Interface)
                .collect(),
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

/// An operation or attribute of an interface that uses the type ([`crate::catalog::IdlUse`]).
pub struct InterfaceUseRow<'a> {
    /// The interface's name, and its page.
    pub interface: &'a str,
    pub page: Option<&'a Page>,
    /// The operation or attribute, and its anchor on the interface's page (`op-…`, `attr-…`).
    pub member: &'a str,
    pub anchor: String,
    /// How it uses the type: `parameter goal`, `result`, `attribute`, `raised`.
    pub how: String,
}

/// The rows of a type's [`TypeEntry::used_by`], and how many interfaces they name.
fn interface_uses<'a>(
    cat: &'a Catalog,
    uses: &'a [crate::catalog::IdlUse],
    lang: Lang,
) -> (Vec<InterfaceUseRow<'a>>, usize) {
    use crate::catalog::IdlUseRole as R;
    let rows: Vec<InterfaceUseRow<'a>> = uses
        .iter()
        .map(|u| {
            let attribute = u.role == R::Attribute
                || (u.role == R::Raises && !is_operation(cat, &u.interface, &u.member));
            let how = match (u.role, &u.parameter) {
                (R::Parameter, Some(p)) => format!("{} {p}", lang.t("idl_use_parameter")),
                (R::Parameter, None) => lang.t("idl_use_parameter").to_string(),
                (R::Result, _) => lang.t("idl_use_result").to_string(),
                (R::Attribute, _) => lang.t("idl_use_attribute").to_string(),
                (R::Raises, _) => lang.t("idl_use_raises").to_string(),
            };
            InterfaceUseRow {
                interface: &u.interface,
                page: cat
                    .interface_index_of(&u.interface)
                    .map(|i| cat.interface_page(i)),
                member: &u.member,
                anchor: format!("{}{}", if attribute { "attr-" } else { "op-" }, u.member),
                how,
            }
        })
        .collect();
    (rows, distinct_interfaces(uses))
}

/// How many interfaces `uses` names (they come interface by interface).
fn distinct_interfaces(uses: &[crate::catalog::IdlUse]) -> usize {
    uses.iter()
        .enumerate()
        .filter(|(k, u)| *k == 0 || uses[k - 1].interface != u.interface)
        .count()
}

/// Whether `member` of interface `interface` is an operation (else an attribute).
fn is_operation(cat: &Catalog, interface: &str, member: &str) -> bool {
    match cat.idl.find(interface).map(|i| i.definition) {
        Some(crate::idl::IdlDefinition::Interface(i)) => {
            i.operations.iter().any(|o| o.name == member)
        }
        _ => true,
    }
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
    /// Its stability mark, shown under the title.
    pub stability: Option<super::StabilityView<'a>>,
    pub spellings: &'a [String],
    pub idl_files: &'a [String],
    /// The non-empty role groups, in order.
    pub uses: Vec<UseGroup<'a>>,
    /// The connectors of RT Systems carrying a data type, linked to their system.
    pub carried_by: Vec<Linked<'a>>,
    /// The data types whose fields (or typedef) hold this one, linked to their pages.
    pub contained_in: Vec<Linked<'a>>,
    /// The IDL file defining it: its Source link and latest versions ([`super::idl_file`]).
    pub idl_file: Option<super::idl_file::IdlFileView<'a>>,
    /// The operations and attributes of interfaces that use it, and how many interfaces
    /// those are.
    pub used_by: Vec<InterfaceUseRow<'a>>,
    pub used_by_interfaces: usize,
}

/// A use of a type (a data port, an interface of a service port) as a row of the type's page.
pub trait UseRef {
    fn row<'a>(&self, cat: &'a Catalog) -> Option<UseRow<'a>>;
}

impl UseRef for PortRef {
    fn row<'a>(&self, cat: &'a Catalog) -> Option<UseRow<'a>> {
        let (ci, pi) = cat.resolve_port(self)?;
        let c = &cat[ci];
        let port = &c.profile.data_ports[pi];
        let page = cat.component_page(ci);
        Some(UseRow {
            component: Linked::new(&c.display_name(), Some(page), None),
            port: Linked::new(
                port.name.as_deref().unwrap_or_default(),
                Some(page),
                Some(&c.anchors.data_ports[pi]),
            ),
            written: non_empty(&port.type_).unwrap_or("").to_string(),
        })
    }
}

impl UseRef for InterfaceRef {
    fn row<'a>(&self, cat: &'a Catalog) -> Option<UseRow<'a>> {
        let (ci, pi, ii) = cat.resolve_interface(self)?;
        let c = &cat[ci];
        let sp = &c.profile.service_ports[pi];
        let i = &sp.interfaces[ii];
        let page = cat.component_page(ci);
        Some(UseRow {
            component: Linked::new(&c.display_name(), Some(page), None),
            port: Linked::new(
                &format!(
                    "{}.{}",
                    sp.name.as_deref().unwrap_or(""),
                    i.name.as_deref().unwrap_or("")
                ),
                Some(page),
                Some(&c.anchors.interfaces[pi][ii]),
            ),
            written: non_empty(&i.type_).unwrap_or("").to_string(),
        })
    }
}

/// The heading anchor and label of a role's group.
fn role_heading(role: Role, lang: Lang) -> (&'static str, &'static str) {
    match role {
        Role::Producer => ("sec-producers", lang.t("producers")),
        Role::Consumer => ("sec-consumers", lang.t("consumers")),
        Role::Provider => ("sec-providers", lang.t("providers")),
        Role::Requirer => ("sec-requirers", lang.t("requirers")),
        Role::Other => ("sec-others", lang.t("fact_others")),
    }
}

/// The view of a type entry of either kind: its uses grouped by role (the non-empty groups),
/// the system connectors carrying a data type, the types holding it, the IDL file defining it
/// (`source_url`: the site's `source-url` template).
fn type_view<'a, U>(
    cat: &'a Catalog,
    t: &'a TypeEntry<U>,
    kind: TypeKind,
    page: &'a Page,
    lang: Lang,
    source_url: Option<&str>,
) -> TypeView<'a>
where
    U: Uses,
    U::Ref: UseRef,
{
    let index = cat.site_page(kind.index_kind());
    let carried_by = match kind {
        TypeKind::Data => crate::render::system_text::carrying(cat, &t.name)
            .into_iter()
            .filter_map(|(text, s)| {
                let page = cat.page_of_system(s)?;
                Some(Linked::new(&text, Some(page), Some("data-connectors")))
            })
            .collect(),
        TypeKind::Interface => Vec::new(),
    };
    let (used_by, used_by_interfaces) = interface_uses(cat, &t.used_by, lang);
    TypeView {
        kind,
        page,
        index,
        name: &t.name,
        unprovided: t.is_unprovided(),
        stability: super::stability_view(cat, t.stability.as_ref(), lang),
        spellings: &t.spellings,
        idl_files: &t.idl_files,
        uses: t
            .uses
            .by_role()
            .into_iter()
            .filter_map(|(role, refs)| {
                let rows: Vec<UseRow> = refs.iter().filter_map(|r| r.row(cat)).collect();
                let (anchor, label) = role_heading(role, lang);
                (!rows.is_empty()).then_some(UseGroup {
                    anchor,
                    label,
                    rows,
                })
            })
            .collect(),
        carried_by,
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
        idl_file: super::idl_file::idl_file_view(cat, &t.name, lang, source_url),
        used_by,
        used_by_interfaces,
    }
}

/// The view of entry `i` of `kind` ([`Catalog::data_types`], [`Catalog::interfaces`]);
/// `source_url` is the site's `source-url` template.
pub fn entry_view<'a>(
    cat: &'a Catalog,
    t: TypeIx,
    lang: Lang,
    source_url: Option<&str>,
) -> TypeView<'a> {
    let page = cat.type_page(t);
    match t {
        TypeIx::Data(i) => type_view(cat, &cat[i], TypeKind::Data, page, lang, source_url),
        TypeIx::Interface(i) => {
            type_view(cat, &cat[i], TypeKind::Interface, page, lang, source_url)
        }
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
    /// How many interfaces use it in their operations and attributes.
    pub interfaces: usize,
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

/// A type entry's row of its index.
fn index_row<'a, U: Uses>(page: &'a Page, t: &'a TypeEntry<U>) -> TypeIndexRow<'a> {
    TypeIndexRow {
        page,
        name: &t.name,
        other_spellings: other_spellings(&t.name, &t.spellings),
        counts: t.uses.by_role().map(|(_, refs)| refs.len()),
        interfaces: distinct_interfaces(&t.used_by),
        unprovided: t.is_unprovided(),
    }
}

/// The view of the index of `kind`: every data type or interface of the catalogue, in order.
pub fn type_index_view(cat: &Catalog, kind: TypeKind) -> TypeIndexView<'_> {
    let rows = match kind {
        TypeKind::Data => Ix::enumerate(&cat.data_types)
            .map(|(ti, t)| index_row(cat.data_type_page(ti), t))
            .collect(),
        TypeKind::Interface => Ix::enumerate(&cat.interfaces)
            .map(|(ii, t)| index_row(cat.interface_page(ii), t))
            .collect(),
    };
    TypeIndexView {
        kind,
        page: cat.site_page(kind.index_kind()),
        rows,
    }
}
