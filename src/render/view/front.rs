//! The catalogue's front page and the index of RT Systems: what each says, once for every
//! output. The front page counts the catalogue, links the indexes and lists the components by
//! category; the systems index lists every RT System with its counts.

use super::facets::FacetKind;
use super::Linked;
use crate::catalog::{Catalog, ComponentIx, Ix, Page, PageKind};
use crate::i18n::Lang;
use crate::model::non_empty;

/// An index of the catalogue as the front page links it: its label key, page and count.
pub struct IndexLink<'a> {
    /// The label key (`data_types`, `interfaces`, `vendors`, `systems`).
    pub key: &'static str,
    pub page: &'a Page,
    pub count: usize,
}

/// A category on the front page: its name as shown, page and components.
pub struct CategoryGroup<'a> {
    pub name: String,
    pub slug: &'a str,
    pub page: &'a Page,
    /// Its components, in catalogue order.
    pub members: Vec<ComponentIx>,
}

/// The front page.
pub struct FrontView<'a> {
    pub page: &'a Page,
    /// The number of components.
    pub components: usize,
    /// Data types, interfaces, vendors, then systems when there are any.
    pub indexes: Vec<IndexLink<'a>>,
    /// The data-flow page.
    pub dataflow: &'a Page,
    /// What's new (only when something has a history: a component, a system, an IDL file).
    pub whats_new: Option<&'a Page>,
    pub categories: Vec<CategoryGroup<'a>>,
    /// The vendors, for the filter: (name as shown, slug).
    pub vendors: Vec<(String, &'a str)>,
    /// The names of the catalogue's sources, for the filter.
    pub sources: Vec<&'a str>,
}

impl FrontView<'_> {
    /// The index labelled `key` among [`FrontView::indexes`] (none for `systems` when the
    /// catalogue has no systems).
    pub fn index(&self, key: &str) -> Option<&IndexLink<'_>> {
        self.indexes.iter().find(|i| i.key == key)
    }
}

/// The view of the front page.
pub fn front_view(cat: &Catalog, lang: Lang) -> FrontView<'_> {
    let index = |key, kind, count| IndexLink {
        key,
        page: cat.site_page(kind),
        count,
    };
    let mut indexes = vec![
        index("data_types", PageKind::DataTypes, cat.data_types.len()),
        index("interfaces", PageKind::Interfaces, cat.interfaces.len()),
        index("vendors", PageKind::Vendors, cat.vendors.len()),
    ];
    if !cat.systems.is_empty() {
        indexes.push(index("systems", PageKind::Systems, cat.systems.len()));
    }
    let kind = FacetKind::Category;
    FrontView {
        page: cat.site_page(PageKind::Index),
        components: cat.components.len(),
        indexes,
        dataflow: cat.site_page(PageKind::DataFlow),
        whats_new: cat.pages().iter().find(|p| p.kind == PageKind::WhatsNew),
        categories: cat
            .categories
            .iter()
            .enumerate()
            .map(|(fi, f)| CategoryGroup {
                name: kind.name(&f.name, lang),
                slug: &f.slug,
                page: kind.page(cat, fi),
                members: cat.members(f).collect(),
            })
            .collect(),
        vendors: cat
            .vendors
            .iter()
            .map(|f| (FacetKind::Vendor.name(&f.name, lang), f.slug.as_str()))
            .collect(),
        sources: cat.sources.iter().map(|s| s.name.as_str()).collect(),
    }
}

/// An RT System in the systems index.
pub struct SystemRow<'a> {
    pub name: Linked<'a>,
    pub version: &'a str,
    pub vendor: &'a str,
    pub instances: usize,
    pub connectors: usize,
}

/// The index of RT Systems.
pub struct SystemsIndexView<'a> {
    pub page: &'a Page,
    pub systems: Vec<SystemRow<'a>>,
}

/// The view of the index of RT Systems.
pub fn systems_index_view(cat: &Catalog) -> SystemsIndexView<'_> {
    let systems = Ix::enumerate(&cat.systems)
        .map(|(si, s)| {
            let parts = s.profile.id_parts.as_ref();
            SystemRow {
                name: Linked::new(&s.display_name(), Some(cat.system_page(si)), None),
                version: parts.and_then(|p| non_empty(&p.version)).unwrap_or(""),
                vendor: parts.and_then(|p| non_empty(&p.vendor)).unwrap_or(""),
                instances: s.profile.components.len(),
                connectors: s.profile.data_port_connectors.len()
                    + s.profile.service_port_connectors.len(),
            }
        })
        .collect();
    SystemsIndexView {
        page: cat.site_page(PageKind::Systems),
        systems,
    }
}
