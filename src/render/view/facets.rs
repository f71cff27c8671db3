//! The pages of the category and vendor facets: the index of each facet kind (every category or
//! vendor with its number of components) and one page per facet (its other spellings met and
//! its components). The front page lists the categories the same way ([`super::index`]).

use super::Linked;
use crate::catalog::{Catalog, ComponentIx, Facet, Page, PageKind};
use crate::i18n::Lang;
use crate::model::{documented, non_empty};

/// Which facet a page is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FacetKind {
    Category,
    Vendor,
}

impl FacetKind {
    /// The label key of the kind's index (`categories`, `vendors`).
    pub fn index_key(self) -> &'static str {
        match self {
            FacetKind::Category => "categories",
            FacetKind::Vendor => "vendors",
        }
    }

    /// The label key of one facet of the kind (`category`, `vendor`).
    pub fn key(self) -> &'static str {
        match self {
            FacetKind::Category => "category",
            FacetKind::Vendor => "vendor",
        }
    }

    /// The kind's facets in the catalogue.
    pub fn facets(self, cat: &Catalog) -> &[Facet] {
        match self {
            FacetKind::Category => &cat.categories,
            FacetKind::Vendor => &cat.vendors,
        }
    }

    /// The page of facet `fi` of the kind.
    pub fn page(self, cat: &Catalog, fi: usize) -> &Page {
        match self {
            FacetKind::Category => cat.category_page(fi),
            FacetKind::Vendor => cat.vendor_page(fi),
        }
    }

    /// The index page of the kind.
    pub fn index_page(self, cat: &Catalog) -> &Page {
        cat.site_page(match self {
            FacetKind::Category => PageKind::Categories,
            FacetKind::Vendor => PageKind::Vendors,
        })
    }

    /// A facet's name as shown: the empty facet (components that name none) has a translated
    /// name.
    pub fn name(self, name: &str, lang: Lang) -> String {
        if !name.is_empty() {
            return name.to_string();
        }
        lang.t(match self {
            FacetKind::Category => "no_category",
            FacetKind::Vendor => "no_vendor",
        })
        .to_string()
    }
}

/// A component in a list (the front page, a category or vendor page): its name linked to its
/// page, and its description, vendor and version as written (empty when not given).
pub struct ComponentRow<'a> {
    /// The component.
    pub ci: ComponentIx,
    pub name: Linked<'a>,
    pub description: &'a str,
    pub vendor: &'a str,
    pub version: &'a str,
}

/// The rows of `members`, in the order given.
pub fn component_rows(
    cat: &Catalog,
    members: impl Iterator<Item = ComponentIx>,
) -> Vec<ComponentRow<'_>> {
    members
        .map(|ci| {
            let c = &cat[ci];
            let b = &c.profile.basic_info;
            ComponentRow {
                ci,
                name: Linked::new(&c.display_name(), Some(cat.component_page(ci)), None),
                description: documented("description", &b.description).unwrap_or(""),
                vendor: non_empty(&b.vendor).unwrap_or(""),
                version: non_empty(&b.version).unwrap_or(""),
            }
        })
        .collect()
}

/// One facet in a list: its name linked to its page, and its number of components.
pub struct FacetEntry<'a> {
    pub name: Linked<'a>,
    pub count: usize,
}

/// The facets of `kind`, in catalogue order.
pub fn facet_entries(cat: &Catalog, kind: FacetKind, lang: Lang) -> Vec<FacetEntry<'_>> {
    kind.facets(cat)
        .iter()
        .enumerate()
        .map(|(fi, f)| FacetEntry {
            name: Linked::new(&kind.name(&f.name, lang), Some(kind.page(cat, fi)), None),
            count: f.components.len(),
        })
        .collect()
}

/// The index of a facet kind (`categories/index`, `vendors/index`).
pub struct FacetIndexView<'a> {
    pub kind: FacetKind,
    pub page: &'a Page,
    pub facets: Vec<FacetEntry<'a>>,
}

/// The view of the index of `kind`.
pub fn facet_index_view(cat: &Catalog, kind: FacetKind, lang: Lang) -> FacetIndexView<'_> {
    FacetIndexView {
        kind,
        page: kind.index_page(cat),
        facets: facet_entries(cat, kind, lang),
    }
}

/// The page of one category or vendor.
pub struct FacetView<'a> {
    pub kind: FacetKind,
    pub page: &'a Page,
    /// The index of its kind (the way back).
    pub index: &'a Page,
    /// Its name as shown.
    pub name: String,
    /// The other spellings met, sorted.
    pub variants: &'a [String],
    /// Its components, in catalogue order.
    pub components: Vec<ComponentRow<'a>>,
    /// Whether its components hang from this page in the outputs' page tree (a component is
    /// under its category; a vendor page only links its components).
    pub parent: bool,
}

/// The view of facet `fi` of `kind`.
pub fn facet_view(cat: &Catalog, kind: FacetKind, fi: usize, lang: Lang) -> FacetView<'_> {
    let f = &kind.facets(cat)[fi];
    FacetView {
        kind,
        page: kind.page(cat, fi),
        index: kind.index_page(cat),
        name: kind.name(&f.name, lang),
        variants: &f.variants,
        components: component_rows(cat, cat.members(f)),
        parent: kind == FacetKind::Category,
    }
}
