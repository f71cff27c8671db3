//! The HTML catalogue site: index, component, data-type, interface, category and vendor pages,
//! search, sitemap, 404 and diagnostics.
//!
//! Pages are views built in Rust (plain, serialisable structs: every value is still raw text)
//! and rendered by minijinja templates from `themes/default`, compiled into the binary. Template
//! auto-escaping escapes every value; the only pre-built HTML handed to templates is in fields
//! whose names end in `_html` or `_svg`: Markdown sanitised by [`markdown::to_html`] or SVG built
//! by [`svg`] with every profile string escaped. One minijinja environment serves all pages, and
//! pages are rendered in parallel. Links are relative, so the site works from `file://`.

mod builtins;
mod dataflow;
mod diagnostics;
mod history;
mod manual;
use history::{has_feed, has_history};
pub use manual::ManualRenderer;
pub mod markdown;
mod native;
pub mod readme;
pub mod repo;
pub mod search;
pub mod svg;
mod system_svg;
pub use system_svg::standalone_system_diagram;
pub mod systems;

use super::facts::{self, Fact, FactKind};
use super::view::facets::{facet_index_view, facet_view, FacetKind, FacetView};
use super::view::types::TypeKind;
use super::view::{self, component::ComponentView, Linked};
use super::{RenderContext, Renderer, SiteOptions};
use crate::catalog::{
    Catalog, Component, ComponentIx, Facet, Ix, Output, Page, PageKind, PerEntry,
};
use crate::i18n::Lang;
use crate::model::{documented, non_empty, ExtraKind};
use crate::output::Sink;

use anyhow::{Context, Result};
use minijinja::{Environment, Value};
use rayon::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// At most this many components are listed under "connects to" per port; the rest are on the
/// type or interface page (a common type can be used by hundreds of components).
pub use super::facts::PEER_COMPONENTS_CAP;

/// Port names shown per connected component (then "+N").
pub use super::facts::PEER_PORTS_SHOWN;

/// Above this many components the index page lists categories with counts instead of every
/// component (each category page still lists all of its components).
pub const INDEX_FULL_LIST_MAX: usize = 2000;

/// The built-in theme: (file name, contents). Templates end in `.html`; the rest are assets
/// copied to the site root.
pub const DEFAULT_THEME: &[(&str, &str)] = &[
    ("404.html", include_str!("../../../themes/default/404.html")),
    (
        "favicon.svg",
        include_str!("../../../themes/default/favicon.svg"),
    ),
    (
        "base.html",
        include_str!("../../../themes/default/base.html"),
    ),
    (
        "component.html",
        include_str!("../../../themes/default/component.html"),
    ),
    (
        "diagnostics.html",
        include_str!("../../../themes/default/diagnostics.html"),
    ),
    (
        "facet.html",
        include_str!("../../../themes/default/facet.html"),
    ),
    (
        "facets.html",
        include_str!("../../../themes/default/facets.html"),
    ),
    (
        "filter.js",
        include_str!("../../../themes/default/filter.js"),
    ),
    (
        "history.html",
        include_str!("../../../themes/default/history.html"),
    ),
    (
        "index.html",
        include_str!("../../../themes/default/index.html"),
    ),
    (
        "interface.html",
        include_str!("../../../themes/default/interface.html"),
    ),
    (
        "interfaces.html",
        include_str!("../../../themes/default/interfaces.html"),
    ),
    (
        "manual.css",
        include_str!("../../../themes/default/manual.css"),
    ),
    (
        "manual.html",
        include_str!("../../../themes/default/manual.html"),
    ),
    (
        "macros.html",
        include_str!("../../../themes/default/macros.html"),
    ),
    (
        "dataflow.html",
        include_str!("../../../themes/default/dataflow.html"),
    ),
    (
        "search.html",
        include_str!("../../../themes/default/search.html"),
    ),
    (
        "search.js",
        include_str!("../../../themes/default/search.js"),
    ),
    (
        "style.css",
        include_str!("../../../themes/default/style.css"),
    ),
    (
        "system.html",
        include_str!("../../../themes/default/system.html"),
    ),
    (
        "system_sections.html",
        include_str!("../../../themes/default/system_sections.html"),
    ),
    (
        "systems.html",
        include_str!("../../../themes/default/systems.html"),
    ),
    (
        "type.html",
        include_str!("../../../themes/default/type.html"),
    ),
    (
        "types.html",
        include_str!("../../../themes/default/types.html"),
    ),
    (
        "whats_new.html",
        include_str!("../../../themes/default/whats_new.html"),
    ),
];

/// Assets written to the site root (after theme overrides).
const ASSETS: &[&str] = &["style.css", "search.js", "filter.js", "favicon.svg"];

/// Reads theme file `name`: the user's theme directory wins, else the built-in file.
fn theme_file(dir: Option<&Path>, name: &str) -> Result<Option<String>> {
    if name.contains('/') || name.contains('\\') || name.starts_with('.') {
        return Ok(None);
    }
    if let Some(d) = dir {
        let p = d.join(name);
        if p.is_file() {
            return std::fs::read_to_string(&p)
                .map(Some)
                .with_context(|| format!("cannot read theme file `{}`", p.display()));
        }
    }
    Ok(DEFAULT_THEME
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, s)| s.to_string()))
}

/// Renders the HTML site.
pub struct HtmlRenderer;

/// A link: text and relative URL.
#[derive(Debug, Clone, Serialize)]
pub struct Link {
    pub text: String,
    pub href: String,
}

/// A stability mark under a page's title (the macro `stability_line` of `macros.html`), from
/// its view; the replacement's `href` is empty when the catalogue does not have it.
#[derive(Debug, Clone, Serialize)]
pub(super) struct StabilityLine {
    class: &'static str,
    headline: String,
    use_before: &'static str,
    use_after: &'static str,
    replacement: Option<Link>,
    note: Option<String>,
}

impl StabilityLine {
    pub(super) fn of(
        cat: &Catalog,
        from: &crate::catalog::Page,
        v: Option<&view::StabilityView<'_>>,
        out: Output,
    ) -> Option<StabilityLine> {
        let v = v?;
        let (use_before, use_after) = v.replacement.as_ref().map_or(("", ""), |r| (r.0, r.1));
        Some(StabilityLine {
            class: v.class,
            headline: v.headline.clone(),
            use_before,
            use_after,
            replacement: v.replacement.as_ref().map(|(_, _, r)| Link {
                text: r.text.clone(),
                href: r.target(cat, from, out).unwrap_or_default(),
            }),
            note: v.note.map(str::to_string),
        })
    }
}

/// One labelled value; exactly one of `text` (escaped by the template) or `html` (sanitised).
#[derive(Debug, Clone, Serialize)]
pub struct Field {
    pub label: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub html: Option<String>,
}

impl From<Fact> for Field {
    /// Plain values are escaped by the template; free text becomes sanitised Markdown.
    fn from(f: Fact) -> Field {
        let (text, html) = match f.kind {
            FactKind::Value => (Some(f.value), None),
            FactKind::Text => (None, Some(markdown::to_html(&f.value))),
            FactKind::Phrase => (None, Some(markdown::phrase_to_html(&f.value))),
        };
        Field {
            label: f.label.into_owned(),
            text,
            html,
        }
    }
}

/// The fields of a section: `description` (free text shown first, when the section has one)
/// followed by `facts`.
fn fields(
    lang: Lang,
    description: Option<&Option<crate::model::Text>>,
    facts: Vec<Fact>,
) -> Vec<Field> {
    let lead = description.and_then(|d| non_empty(d)).map(|d| Field {
        label: lang.t("description").to_string(),
        text: None,
        html: Some(markdown::to_html(d)),
    });
    lead.into_iter()
        .chain(facts.into_iter().map(Field::from))
        .collect()
}

/// [`fields`] of a view's row: its free-text description first, then its facts.
fn lead_fields(lang: Lang, description: Option<&str>, facts: &[Fact]) -> Vec<Field> {
    let lead = description.map(|d| Field {
        label: lang.t("description").to_string(),
        text: None,
        html: Some(markdown::to_html(d)),
    });
    lead.into_iter()
        .chain(facts.iter().cloned().map(Field::from))
        .collect()
}

/// Facts as (key, value) rows of a two-column table.
fn key_values(facts: Vec<Fact>) -> Vec<KeyValue> {
    facts
        .into_iter()
        .map(|f| KeyValue {
            key: f.label.into_owned(),
            value: f.value,
        })
        .collect()
}

/// A component in lists (index, category and vendor pages).
#[derive(Debug, Clone, Serialize)]
pub struct ComponentSummary {
    pub name: String,
    /// Path from the site root (`components/x.html`).
    pub path: String,
    pub version: String,
    pub vendor: String,
    pub vendor_slug: String,
    pub category: String,
    pub category_slug: String,
    /// The `[[source]]` the profile was read from (empty: the input directory).
    pub source: String,
    pub summary: String,
    pub data_ports: usize,
    pub service_ports: usize,
    pub configurations: usize,
    /// Its implementation: `ok` (the code matches the profile), `drift`, or empty (no code
    /// read); the index filters by it.
    pub implementation: &'static str,
}

#[derive(Serialize)]
struct PortTypeRef {
    text: String,
    href: Option<String>,
}

/// The cells a data port row and a service interface row share, flattened into each row's
/// template context (`p.anchor`, `p.name`, …).
#[derive(Serialize)]
struct PortCells {
    anchor: String,
    /// "since 1.1.0": the version that added it ([`view::component::PortView::since`]).
    since: Option<String>,
    direction: String,
    dir_class: &'static str,
    name: String,
    type_ref: Option<PortTypeRef>,
    /// The description, then the other facts.
    details: Vec<Field>,
    peers: Vec<Link>,
    peers_more: Option<Link>,
}

#[derive(Serialize)]
struct DataPortRow {
    #[serde(flatten)]
    port: PortCells,
    unit: String,
    events: Vec<EventRow>,
}

#[derive(Serialize)]
struct EventRow {
    name: String,
    fields: Vec<Field>,
}

#[derive(Serialize)]
struct ServicePortRow {
    anchor: String,
    since: Option<String>,
    name: String,
    details: Vec<Field>,
    interfaces: Vec<InterfaceRow>,
}

#[derive(Serialize)]
struct InterfaceRow {
    #[serde(flatten)]
    port: PortCells,
}

#[derive(Serialize)]
struct ConfigurationRow {
    anchor: String,
    since: Option<String>,
    name: String,
    type_: String,
    default: String,
    unit: String,
    constraint: String,
    widget: String,
    details: Vec<Field>,
}

/// Which optional columns of a component page's table have a value in some row: a column
/// empty in every row is left out.
#[derive(Serialize, Default)]
struct Columns {
    unit: bool,
    constraint: bool,
    widget: bool,
    description: bool,
    peers: bool,
    /// The number of columns shown (the `colspan` of a row spanning the table).
    span: usize,
}

impl Columns {
    /// `span` from the `always` columns shown in any case and the optional ones.
    fn counted(mut self, always: usize) -> Columns {
        self.span = always + self.shown().count();
        self
    }

    /// The label keys of the optional columns shown, in table order (after the `always` ones).
    fn shown(&self) -> impl Iterator<Item = &'static str> {
        [
            (self.unit, "unit"),
            (self.constraint, "constraint"),
            (self.widget, "widget"),
            (self.description, "description"),
            (self.peers, "connects_to"),
        ]
        .into_iter()
        .filter_map(|(shown, key)| shown.then_some(key))
    }
}

/// One target environment: its number (1-based, as listed) and facts.
#[derive(Serialize)]
struct TargetBlock {
    number: usize,
    fields: Vec<Field>,
}

#[derive(Serialize)]
struct ActionRow {
    name: &'static str,
    implemented: bool,
    details: Vec<Field>,
}

#[derive(Serialize)]
struct KeyValue {
    key: String,
    value: String,
}

#[derive(Serialize)]
struct ExtraRow {
    kind: &'static str,
    name: String,
    value: String,
}

impl ExtraRow {
    /// The row of an extra value of the profile and its kind.
    fn of((f, kind): &(Fact, ExtraKind)) -> ExtraRow {
        ExtraRow {
            kind: match kind {
                ExtraKind::Attribute => "attribute",
                ExtraKind::Element => "element",
                ExtraKind::Key => "key",
            },
            name: f.label.to_string(),
            value: f.value.clone(),
        }
    }
}

#[derive(Serialize)]
struct ComponentPage {
    root: &'static str,
    title: String,
    /// `<meta name="description">`: the first line of the description, else what it is.
    description: String,
    crumbs: Vec<Link>,
    name: String,
    stability: Option<StabilityLine>,
    summary_html: Option<String>,
    header: Vec<Field>,
    document: Vec<Field>,
    /// The folder's README, sanitised ([`readme`]); `None` when there is none or it is blank.
    readme_html: Option<String>,
    diagram_svg: String,
    data_ports: Vec<DataPortRow>,
    data_cols: Columns,
    service_ports: Vec<ServicePortRow>,
    service_cols: Columns,
    configurations: Vec<ConfigurationRow>,
    config_cols: Columns,
    actions: Vec<ActionRow>,
    action_cols: Columns,
    lifecycle_svg: String,
    parameters: Vec<KeyValue>,
    language: Vec<Field>,
    targets: Vec<TargetBlock>,
    properties: Vec<KeyValue>,
    version_up_logs: Vec<String>,
    extras: Vec<ExtraRow>,
    /// The systems with an instance of the component.
    systems: Vec<Link>,
    /// RTCBuilder's backups of the profile: older versions, not components.
    backups: Vec<facts::BackupRow>,
    /// The Implementation section ([`facts::ImplementationSection`]).
    implementation: Option<facts::ImplementationSection>,
    /// The neighbourhood drawing (empty when no component connects to this one).
    neighbourhood_svg: String,
    /// The neighbourhood as a list, by port.
    neighbourhood: Vec<NeighbourhoodRow>,
    /// The History section: the latest versions of the profile, and the note on older ones.
    history: Vec<crate::render::view::history::HistoryRow>,
    history_older: Option<String>,
    /// The component's history page (its whole history), from this page.
    history_page: Option<String>,
}

/// One port of the neighbourhood list: the port, its relation (`fed by`, `feeds`, …), the
/// type, and its neighbours as `peers` / `peers_more` (shown like a "connects to" cell).
#[derive(Serialize)]
struct NeighbourhoodRow {
    port: Link,
    relation: &'static str,
    type_ref: Option<PortTypeRef>,
    peers: Vec<Link>,
    peers_more: Option<Link>,
}

#[derive(Serialize)]
struct PortUse {
    component: Link,
    port: Link,
}

struct Site<'a> {
    catalog: &'a Catalog,
    opts: &'a SiteOptions,
    lang: Lang,
    /// The output the links are made for: the HTML site, or a system manual.
    out: Output,
    summaries: Vec<ComponentSummary>,
    /// The category facet of each component ([`Catalog::category_of_each`]).
    category_of: PerEntry<Component, usize>,
    /// The vendor facet of each component ([`Catalog::vendor_of_each`]).
    vendor_of: PerEntry<Component, usize>,
    /// Where README links go ([`readme::Targets`]).
    readme_targets: std::sync::Arc<readme::Targets>,
    /// The lifecycle diagram in the site's language, made once.
    lifecycle: svg::LifecycleDiagram,
}

impl<'a> Site<'a> {
    /// The site of `catalog` for output `out` (the HTML site, or a system manual), without
    /// the component summaries (the lists' rows, made in parallel by the site).
    fn new(catalog: &'a Catalog, opts: &'a SiteOptions, out: Output) -> Site<'a> {
        let lang = opts.language;
        Site {
            catalog,
            opts,
            lang,
            out,
            summaries: Vec::new(),
            category_of: catalog.category_of_each(),
            vendor_of: catalog.vendor_of_each(),
            readme_targets: std::sync::Arc::new(readme::Targets::new(
                catalog,
                opts.source_url.as_deref(),
                "../",
                |ci| catalog.component_page(ci).path("html"),
            )),
            lifecycle: svg::LifecycleDiagram::new(&svg::LifecycleLabels {
                title: lang.t("lifecycle_diagram"),
                created: lang.t("state_created"),
                inactive: lang.t("state_inactive"),
                active: lang.t("state_active"),
                error: lang.t("state_error"),
                finalized: lang.t("state_finalized"),
                ec_events: lang.t("ec_events"),
                fsm: lang.t("fsm_actions"),
                implemented: lang.t("legend_implemented"),
                not_implemented: lang.t("legend_not_implemented"),
            }),
        }
    }

    /// The id an anchor of page `page` is defined under in this output ([`Page::anchor_in`]).
    fn anchor(&self, page: &Page, anchor: &str) -> String {
        page.anchor_in(anchor, self.out)
    }

    fn t(&self, key: &str) -> &'static str {
        self.lang.t(key)
    }

    fn component_path(&self, ci: ComponentIx) -> String {
        self.catalog.component_page(ci).path("html")
    }

    /// The neighbourhood of a component page's view ([`crate::render::neighbourhood`]): its
    /// drawing (empty when it has none) and its list.
    fn neighbourhood(&self, v: &ComponentView<'_>) -> (String, Vec<NeighbourhoodRow>) {
        use crate::render::neighbourhood as nb;
        let (cat, ci, rows) = (self.catalog, v.ci, &v.neighbourhood);
        if rows.is_empty() {
            return (String::new(), Vec::new());
        }
        let here = v.page;
        let href = |to: &crate::catalog::Page, anchor: Option<&str>| {
            if std::ptr::eq(to, here) {
                anchor.map(|a| format!("#{a}")).unwrap_or_default()
            } else {
                cat.href(here, to, anchor, crate::catalog::Output::Html)
            }
        };
        let (inst, conns) = nb::wiring(cat, ci, rows, self.lang, &href);
        let me = cat[ci].display_name();
        let svg = system_svg::system_diagram_with(
            &format!("{} {me}", self.t("neighbourhood_of")),
            &inst,
            &conns,
            crate::layout::wiring::Effort::Quick,
            " neighbourhood-diagram",
        );
        let list = rows
            .iter()
            .map(|r| NeighbourhoodRow {
                port: Link {
                    text: r.port.clone(),
                    href: format!("#{}", r.anchor),
                },
                relation: self.t(r.relation()),
                type_ref: Some(PortTypeRef {
                    text: r.type_name.to_string(),
                    href: Some(href(r.type_page, None)),
                }),
                peers: r
                    .neighbours
                    .iter()
                    .map(|n| {
                        let names: Vec<&str> = n.ports.iter().map(String::as_str).collect();
                        Link {
                            text: facts::peer_text(&n.name, &names, " · "),
                            href: href(n.page, Some(n.anchor)),
                        }
                    })
                    .collect(),
                peers_more: (r.more > 0).then(|| Link {
                    text: nb::more_text(r, self.lang),
                    href: href(r.type_page, None),
                }),
            })
            .collect();
        (svg, list)
    }

    fn summary(&self, ci: ComponentIx) -> ComponentSummary {
        let c = &self.catalog[ci];
        let b = &c.profile.basic_info;
        // Every component is in one category and one vendor facet (computed once, not
        // looked up by name for each component).
        let facet_slug = |facets: &[Facet], of: &PerEntry<Component, usize>| {
            facets
                .get(of[ci])
                .map(|f| f.slug.clone())
                .unwrap_or_default()
        };
        ComponentSummary {
            name: c.display_name().into_owned(),
            path: self.catalog.component_page(ci).path("html"),
            version: non_empty(&b.version).unwrap_or("").to_string(),
            vendor: documented("vendor", &b.vendor).unwrap_or("").to_string(),
            vendor_slug: facet_slug(&self.catalog.vendors, &self.vendor_of),
            category: documented("category", &b.category)
                .unwrap_or("")
                .to_string(),
            category_slug: facet_slug(&self.catalog.categories, &self.category_of),
            source: c
                .origin
                .as_ref()
                .map(|o| o.source.clone())
                .unwrap_or_default(),
            summary: documented("description", &b.description)
                .map(|d| markdown::first_line(d, 160))
                .unwrap_or_default(),
            data_ports: c.profile.data_ports.len(),
            service_ports: c.profile.service_ports.len(),
            configurations: c.profile.configurations().len(),
            implementation: match &c.implementation {
                Some(_) if c.recovered.is_some() => "recovered",
                Some(i) if i.drift.is_empty() => "ok",
                Some(_) => "drift",
                None => "",
            },
        }
    }

    /// The summaries of `components`, sorted by name case-insensitively (real catalogues mix
    /// `camera`, `Camera` and `CAMERA_rtc`), then by page path (same-named components).
    fn sorted_summaries(&self, components: &[ComponentIx]) -> Vec<&ComponentSummary> {
        let mut list: Vec<(String, &ComponentSummary)> = components
            .iter()
            .filter_map(|&i| self.summaries.get(i.get()))
            .map(|s| (s.name.to_lowercase(), s))
            .collect();
        list.sort_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.path.cmp(&b.1.path)));
        list.into_iter().map(|(_, s)| s).collect()
    }

    /// A link of a view as the site writes it, from component pages (one folder down).
    fn link(&self, from: &Page, l: &Linked<'_>) -> Option<Link> {
        Some(Link {
            text: l.text.clone(),
            href: l.target(self.catalog, from, self.out)?,
        })
    }

    fn peers(&self, from: &Page, p: &view::Peers<'_>) -> (Vec<Link>, Option<Link>) {
        (
            p.shown.iter().filter_map(|l| self.link(from, l)).collect(),
            p.more.as_ref().and_then(|l| self.link(from, l)),
        )
    }

    fn type_ref(&self, from: &Page, t: &Option<Linked<'_>>) -> Option<PortTypeRef> {
        t.as_ref().map(|t| PortTypeRef {
            text: t.text.clone(),
            href: t.target(self.catalog, from, self.out),
        })
    }

    /// The cells of a data port or service interface row: its `(anchor, since, name)`, its
    /// direction and its type, linked from `from`.
    fn port_cells(&self, from: &Page, p: &view::component::PortView<'_>) -> PortCells {
        let (peers, peers_more) = self.peers(from, &p.peers);
        PortCells {
            anchor: p.anchor.to_string(),
            since: self.since(p.since),
            direction: p.direction.label.clone(),
            dir_class: p.direction.class,
            name: p.name.to_string(),
            type_ref: self.type_ref(from, &p.type_),
            details: lead_fields(self.lang, p.description, &p.details),
            peers,
            peers_more,
        }
    }

    /// The "since" badge of a row: `since 1.1.0`.
    fn since(&self, since: Option<&str>) -> Option<String> {
        since.map(|v| self.t("since").replace("{v}", v))
    }

    fn component_page(&self, ci: ComponentIx) -> ComponentPage {
        let v = view::component::component_view(
            self.catalog,
            ci,
            (self.category_of[ci], self.vendor_of[ci]),
            self.opts.source_url.as_deref(),
            self.lang,
        );
        self.component_context(&v)
    }

    /// The data port rows of a component page, from its view.
    fn data_port_rows(&self, v: &ComponentView<'_>) -> Vec<DataPortRow> {
        let (lang, page) = (self.lang, v.page);
        v.data_ports
            .iter()
            .map(|dp| DataPortRow {
                port: self.port_cells(page, &dp.port),
                unit: dp.unit.to_string(),
                events: dp
                    .events
                    .iter()
                    .map(|(name, f)| EventRow {
                        name: name.to_string(),
                        fields: fields(lang, None, f.clone()),
                    })
                    .collect(),
            })
            .collect()
    }

    /// The service port rows of a component page, with their interfaces, from its view.
    fn service_port_rows(&self, v: &ComponentView<'_>) -> Vec<ServicePortRow> {
        let (lang, page) = (self.lang, v.page);
        v.service_ports
            .iter()
            .map(|sp| ServicePortRow {
                anchor: sp.anchor.to_string(),
                since: self.since(sp.since),
                name: sp.name.to_string(),
                details: fields(lang, None, sp.details.clone()),
                interfaces: sp
                    .interfaces
                    .iter()
                    .map(|i| InterfaceRow {
                        port: self.port_cells(page, &i.port),
                    })
                    .collect(),
            })
            .collect()
    }

    /// The way back from a component page: the catalogue, then its category.
    fn component_crumbs(&self, v: &ComponentView<'_>) -> Vec<Link> {
        let page = v.page;
        let index = self.catalog.site_page(PageKind::Index);
        vec![
            Link {
                text: self.t("catalogue").to_string(),
                href: self.catalog.href(page, index, None, Output::Html),
            },
            Link {
                text: v.category.text.clone(),
                href: v
                    .category
                    .target(self.catalog, page, Output::Html)
                    .unwrap_or_default(),
            },
        ]
    }

    /// The basic information of a component page; "Source" links to the file in its
    /// repository when `source-url` is set.
    fn component_header(&self, v: &ComponentView<'_>) -> Vec<Field> {
        let lang = self.lang;
        let mut header = fields(lang, None, v.basic.clone());
        // `source-url`: "Source" links to the file in its repository.
        if let Some(url) = &v.source_url {
            let label = lang.t("source");
            if let Some(f) = header.iter_mut().rev().find(|f| f.label == label) {
                let path = f.text.take().unwrap_or_default();
                f.html = Some(repo::source_link_html(url, &path));
            }
        }
        header
    }

    /// The template context of a component page, from its view.
    fn component_context(&self, v: &ComponentView<'_>) -> ComponentPage {
        let lang = self.lang;
        let page = v.page;
        let crumbs = self.component_crumbs(v);
        let header = self.component_header(v);
        let data_ports = self.data_port_rows(v);
        let service_ports = self.service_port_rows(v);
        let configurations = configuration_rows(lang, v);
        let actions = action_rows(lang, v);
        let (diagram_svg, lifecycle_svg) = self.component_diagrams(v, &actions);
        let (neighbourhood_svg, neighbourhood) = self.neighbourhood(v);
        let description = match v.lead {
            Some(d) => markdown::first_line(d, 160),
            None => format!("{}: {} — {}", v.name, self.t("component"), self.opts.title),
        };
        ComponentPage {
            root: "../",
            title: format!("{} — {}", v.name, self.opts.title),
            description,
            crumbs,
            summary_html: v.lead.map(markdown::to_html),
            stability: StabilityLine::of(self.catalog, v.page, v.stability.as_ref(), self.out),
            name: v.name.clone(),
            header,
            document: fields(lang, None, v.document.clone()),
            readme_html: v
                .readme
                .map(|r| readme::readme_html(r, &self.readme_targets))
                .filter(|h| !h.trim().is_empty()),
            diagram_svg,
            neighbourhood_svg,
            neighbourhood,
            data_cols: Columns {
                unit: data_ports.iter().any(|r| !r.unit.is_empty()),
                description: data_ports
                    .iter()
                    .any(|r| !r.port.details.is_empty() || !r.events.is_empty()),
                peers: data_ports.iter().any(|r| !r.port.peers.is_empty()),
                ..Columns::default()
            }
            .counted(3),
            data_ports,
            service_cols: {
                let rows = || service_ports.iter().flat_map(|sp| &sp.interfaces);
                Columns {
                    description: rows().any(|r| !r.port.details.is_empty()),
                    peers: rows().any(|r| !r.port.peers.is_empty()),
                    ..Columns::default()
                }
                .counted(3)
            },
            service_ports,
            config_cols: Columns {
                unit: configurations.iter().any(|r| !r.unit.is_empty()),
                constraint: configurations.iter().any(|r| !r.constraint.is_empty()),
                widget: configurations.iter().any(|r| !r.widget.is_empty()),
                description: configurations.iter().any(|r| !r.details.is_empty()),
                ..Columns::default()
            }
            .counted(3),
            configurations,
            action_cols: Columns {
                description: actions.iter().any(|r| !r.details.is_empty()),
                ..Columns::default()
            }
            .counted(2),
            actions,
            lifecycle_svg,
            parameters: v
                .parameters
                .iter()
                .map(|(key, value)| KeyValue {
                    key: key.to_string(),
                    value: value.to_string(),
                })
                .collect(),
            language: fields(lang, None, v.language.clone()),
            targets: v
                .targets
                .iter()
                .map(|(number, f)| TargetBlock {
                    number: *number,
                    fields: fields(lang, None, f.clone()),
                })
                .collect(),
            properties: key_values(v.properties.clone()),
            version_up_logs: v.version_up_logs.iter().map(|s| s.to_string()).collect(),
            extras: v.extras.iter().map(ExtraRow::of).collect(),
            systems: v
                .systems
                .iter()
                .filter_map(|l| self.link(page, l))
                .collect(),
            backups: facts::BackupRow::of(&self.catalog[v.ci], lang),
            implementation: v.implementation.clone(),
            history: v.history.rows.clone(),
            history_older: v.history.older_note(lang),
            history_page: v
                .history_page
                .map(|to| self.catalog.href(page, to, None, Output::Html)),
        }
    }

    /// The component diagram and the lifecycle diagram of a component page.
    fn component_diagrams(&self, v: &ComponentView<'_>, actions: &[ActionRow]) -> (String, String) {
        let data: Vec<svg::DiagramDataPort> = v
            .data_ports
            .iter()
            .map(|dp| svg::DiagramDataPort {
                side: dp.side,
                name: dp.port.name.to_string(),
                type_label: dp.port.type_short.clone(),
                class: dp.port.direction.class,
                anchor: self.anchor(v.page, dp.port.anchor),
            })
            .collect();
        let service: Vec<svg::DiagramServicePort> = v
            .service_ports
            .iter()
            .map(|sp| svg::DiagramServicePort {
                side: sp.side,
                name: sp.name.to_string(),
                anchor: self.anchor(v.page, sp.anchor),
                interfaces: sp
                    .interfaces
                    .iter()
                    .map(|i| svg::DiagramInterface {
                        provided: i.provided,
                        label: i.port.name.to_string(),
                        type_label: i.port.type_short.clone(),
                        anchor: self.anchor(v.page, i.port.anchor),
                    })
                    .collect(),
            })
            .collect();
        let diagram = svg::component_diagram(
            v.profile_name,
            &format!("{} — {}", self.t("component_diagram"), v.profile_name),
            &data,
            &service,
        );
        let implemented = |name: &str| actions.iter().any(|a| a.name == name && a.implemented);
        let lifecycle = self.lifecycle.render(&implemented);
        (diagram, lifecycle)
    }
}

/// The configuration rows of a component page, from its view.
fn configuration_rows(lang: Lang, v: &ComponentView<'_>) -> Vec<ConfigurationRow> {
    v.configurations
        .iter()
        .map(|conf| ConfigurationRow {
            anchor: conf.anchor.to_string(),
            since: conf.since.map(|at| lang.t("since").replace("{v}", at)),
            name: conf.name.to_string(),
            type_: conf.type_.to_string(),
            default: conf.default.to_string(),
            unit: conf.unit.to_string(),
            constraint: conf.constraint.clone(),
            widget: conf.widget.clone(),
            details: lead_fields(lang, conf.description, &conf.details),
        })
        .collect()
}

/// The lifecycle action rows of a component page, from its view.
fn action_rows(lang: Lang, v: &ComponentView<'_>) -> Vec<ActionRow> {
    v.actions
        .iter()
        .map(|a| ActionRow {
            name: a.kind.callback_name(),
            implemented: a.implemented,
            details: fields(lang, None, a.details.clone()),
        })
        .collect()
}

/// A page to render: output path, template and context. The context of the many per-item
/// pages (facets, types, interfaces) is built only when the page is rendered, so that their
/// contexts are never all in memory at once.
struct Job<'a> {
    path: String,
    template: &'static str,
    context: PageContext<'a>,
}

type LazyContext<'a> = Box<dyn Fn() -> Value + Send + Sync + 'a>;

enum PageContext<'a> {
    Ready(Value),
    Lazy(LazyContext<'a>),
    /// A data type's or interface's page, written by [`native::type_page`] (made only when the
    /// theme overrides none of the templates it stands for).
    Type(Box<dyn Fn() -> TypePage + Send + Sync + 'a>),
}

impl PageContext<'_> {
    fn value(&self) -> Value {
        match self {
            PageContext::Ready(v) => v.clone(),
            PageContext::Lazy(f) => f(),
            PageContext::Type(f) => ctx(&f()),
        }
    }
}

/// Breadcrumbs to the catalogue and a section index (`key` names the section).
fn crumbs_section(lang: Lang, root: &str, key: &str) -> Vec<Link> {
    let mut crumbs = crumbs_home(lang, root);
    crumbs.push(Link {
        text: lang.t(key).to_string(),
        href: "index.html".into(),
    });
    crumbs
}

fn crumbs_home(lang: Lang, root: &str) -> Vec<Link> {
    vec![Link {
        text: lang.t("catalogue").to_string(),
        href: format!("{root}index.html"),
    }]
}

/// Escapes text for XML (sitemap).
fn xml_escape(s: &str) -> String {
    svg::esc(s)
}

impl HtmlRenderer {
    fn environment(opts: &SiteOptions, catalog: &Catalog) -> Environment<'static> {
        let mut env = Environment::new();
        let dir: Option<PathBuf> = opts.theme_dir.clone();
        env.set_loader(move |name| {
            theme_file(dir.as_deref(), name).map_err(|e| {
                minijinja::Error::new(minijinja::ErrorKind::InvalidOperation, e.to_string())
            })
        });
        env.set_formatter(formatter);
        env.add_global("t", Value::from_object(Labels::new(opts.language)));
        env.add_global("lang", opts.language.tag());
        env.add_global("site_title", opts.title.clone());
        env.add_global("has_diagnostics", !catalog.diagnostics.is_empty());
        env.add_global("has_systems", !catalog.systems.is_empty());
        env.add_global("has_history", has_history(catalog));
        env.add_global("has_feed", has_feed(catalog, opts));
        env.add_global("generator", super::generator());
        env.add_function("fields", builtins::fields);
        env.add_function("type_link", builtins::type_link);
        env.add_function("peers", builtins::peers);
        env.add_filter("code_spans", code_spans);
        env.add_filter("wbr", wbr);
        env
    }
}

/// The `t` global: UI labels by key. A map object over the label table, so that the hundred-odd
/// `t.…` lookups of every page are [`crate::i18n::label_index`] over `&str` returning a shared
/// value, not a search of a map keyed by template values.
#[derive(Debug)]
struct Labels {
    /// The labels of one language, in [`crate::i18n::LABELS`] order.
    values: Vec<Value>,
}

impl Labels {
    fn new(lang: crate::i18n::Lang) -> Labels {
        Labels {
            values: lang.labels().map(|(_, v)| Value::from(v)).collect(),
        }
    }
}

impl minijinja::value::Object for Labels {
    fn repr(self: &std::sync::Arc<Self>) -> minijinja::value::ObjectRepr {
        minijinja::value::ObjectRepr::Map
    }
    fn get_value(self: &std::sync::Arc<Self>, key: &Value) -> Option<Value> {
        let i = crate::i18n::label_index(key.as_str()?)?;
        self.values.get(i).cloned()
    }
    fn enumerate(self: &std::sync::Arc<Self>) -> minijinja::value::Enumerator {
        minijinja::value::Enumerator::Values(
            crate::i18n::LABELS
                .iter()
                .map(|&(k, _, _)| Value::from(k))
                .collect(),
        )
    }
}

/// The `code_spans` filter: the text escaped, its code spans as `<code>`
/// ([`svg::esc_code_into`]).
fn code_spans(s: &str) -> Value {
    let mut out = String::with_capacity(s.len() + 16);
    // Writing to a String cannot fail.
    let _ = svg::esc_code_into(&mut out, s);
    Value::from_safe_string(out)
}

/// `{{ name|wbr }}`: the name escaped, with `<wbr>` between its words ([`svg::esc_wbr_into`]).
fn wbr(v: &Value) -> Value {
    let mut out = String::new();
    builtins::put_wbr(&mut out, v);
    Value::from_safe_string(out)
}

/// How `{{ … }}` prints a value: strings are escaped with [`svg::esc_into`] (minijinja's default
/// would also escape `/`, making every URL longer without adding safety), the rest as minijinja
/// does.
fn formatter(
    out: &mut minijinja::Output<'_>,
    state: &minijinja::State<'_, '_>,
    value: &Value,
) -> Result<(), minijinja::Error> {
    if state.auto_escape() == minijinja::AutoEscape::Html && !value.is_safe() {
        if let Some(s) = value.as_str() {
            svg::esc_into(out, s)?;
            return Ok(());
        }
    }
    minijinja::escape_formatter(out, state, value)
}

impl Renderer for HtmlRenderer {
    fn name(&self) -> &'static str {
        "html"
    }

    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> Result<usize> {
        Ok(self.render_some(ctx, out, &|_| true)?.written)
    }
}

/// What [`HtmlRenderer::render_some`] did.
#[derive(Debug, Clone, Default)]
pub struct Rendered {
    /// Files written.
    pub written: usize,
    /// Every file the complete site has (written or not), sorted.
    pub all_paths: Vec<String>,
}

impl HtmlRenderer {
    /// Renders only the files whose site-relative path `wanted` accepts (used by `serve` to
    /// re-render the pages a change affects); every page's context is still cheap to build,
    /// only the rendering is skipped.
    pub fn render_some(
        &self,
        ctx: &RenderContext<'_>,
        out: &dyn Sink,
        wanted: &(dyn Fn(&str) -> bool + Sync),
    ) -> Result<Rendered> {
        let catalog = ctx.catalog;
        let opts = ctx.site;
        let lang = opts.language;
        let env = Self::environment(opts, catalog);
        let mut site = Site::new(catalog, opts, Output::Html);
        // The summaries are made on every core while every template is compiled once, up
        // front (errors surface before any page is written).
        let (summaries, compiled) = rayon::join(
            || {
                (0..catalog.components.len())
                    .into_par_iter()
                    .map(|i| site.summary(Ix::new(i)))
                    .collect()
            },
            || -> Result<()> {
                for (name, _) in DEFAULT_THEME.iter().filter(|(n, _)| n.ends_with(".html")) {
                    env.get_template(name)
                        .with_context(|| format!("theme template `{name}`"))?;
                }
                Ok(())
            },
        );
        compiled?;
        site.summaries = summaries;
        let site = site;

        let mut all_paths: Vec<String> = Vec::new();
        let mut written = 0usize;
        written += write_files(&site, out, wanted, &mut all_paths)?;
        // Component pages: the bulk of the work, rendered and written in parallel; the search
        // index is built alongside (its JSON serialisation is serial).
        let tmpl = env.get_template("component.html")?;
        let native = native_component_pages(opts);
        let generator = super::generator();
        let globals = native::Globals {
            lang,
            site_title: &opts.title,
            has_diagnostics: !catalog.diagnostics.is_empty(),
            has_systems: !catalog.systems.is_empty(),
            has_history: has_history(catalog),
            has_feed: has_feed(catalog, opts),
            generator: &generator,
        };
        all_paths.extend(Ix::all(catalog.components.len()).map(|ci| site.component_path(ci)));
        // The other pages are listed and rendered beside the component pages, not after them:
        // listing them lays out the data-flow and system drawings and paginates the findings,
        // which would otherwise keep one core busy while the other waits.
        let ((search_written, pages_written), others) = rayon::join(
            || {
                rayon::join(
                    || -> Result<Vec<String>> {
                        // The index's files ([`search::write_index`]) are written or left as
                        // one (`search-index.js` names them all), and listed either way.
                        let mut paths = Vec::new();
                        let write = wanted("search-index.js");
                        search::write_index(catalog, lang, &mut |path, bytes| {
                            paths.push(path.to_string());
                            if write {
                                out.write_owned(path, bytes)?;
                            }
                            Ok(())
                        })?;
                        Ok(paths)
                    },
                    || {
                        render_component_pages(
                            &site,
                            &globals,
                            (!native).then_some(&tmpl),
                            out,
                            wanted,
                        )
                    },
                )
            },
            || render_other_pages(&site, &env, &globals, out, wanted),
        );
        let (other_paths, others_written) = others?;
        let search_paths = search_written?;
        written += search_paths.len() + pages_written? + others_written;
        all_paths.extend(search_paths);
        all_paths.extend(other_paths);

        written += write_feeds(catalog, opts, out, wanted, &mut all_paths)?;
        all_paths.sort();
        Ok(Rendered { written, all_paths })
    }
}

/// The component pages, those `wanted`, rendered and written in parallel: by the built-in
/// writer (`native`), or by `template` when the theme overrides `component.html`. How many
/// were written.
fn render_component_pages(
    site: &Site<'_>,
    globals: &native::Globals<'_>,
    template: Option<&minijinja::Template<'_, '_>>,
    out: &dyn Sink,
    wanted: &(dyn Fn(&str) -> bool + Sync),
) -> Result<usize> {
    (0..site.catalog.components.len())
        .into_par_iter()
        .map(Ix::new)
        .filter(|&ci| wanted(&site.component_path(ci)))
        .map(|ci| -> Result<usize> {
            let page = site.component_page(ci);
            let html = match template {
                None => native::component_page(&page, globals),
                Some(t) => t
                    .render(&page)
                    .with_context(|| format!("rendering component `{}`", page.name))?,
            };
            out.write_owned(&site.component_path(ci), html.into_bytes())?;
            Ok(1)
        })
        .try_reduce(|| 0, |a, b| Ok(a + b))
}

/// The pages other than the component pages ([`other_pages`]), those `wanted` rendered and
/// written in parallel: every page's path, and how many were written.
fn render_other_pages(
    site: &Site<'_>,
    env: &Environment<'_>,
    globals: &native::Globals<'_>,
    out: &dyn Sink,
    wanted: &(dyn Fn(&str) -> bool + Sync),
) -> Result<(Vec<String>, usize)> {
    let pages = other_pages(site);
    let paths = pages.iter().map(|p| p.path.clone()).collect();
    let written = pages
        .par_iter()
        .filter(|pg| wanted(&pg.path))
        .map(|pg| -> Result<usize> {
            let html = match &pg.context {
                PageContext::Type(f) => native::type_page(&f(), globals),
                context => env
                    .get_template(pg.template)?
                    .render(context.value())
                    .with_context(|| format!("rendering `{}`", pg.path))?,
            };
            out.write_owned(&pg.path, html.into_bytes())?;
            Ok(1)
        })
        .try_reduce(|| 0, |a, b| Ok(a + b))?;
    Ok((paths, written))
}

/// The files for other programs, those `wanted`: the sitemap and the Atom feed of the
/// histories (both only with a base URL: their links must be absolute); their paths join
/// `all_paths`. How many were written.
fn write_feeds(
    catalog: &Catalog,
    opts: &SiteOptions,
    out: &dyn Sink,
    wanted: &(dyn Fn(&str) -> bool + Sync),
    all_paths: &mut Vec<String>,
) -> Result<usize> {
    let mut written = 0;
    // Sitemap: every page but the 404, at absolute URLs — which only a base URL gives
    // (the sitemap protocol requires them), so without one there is no sitemap.
    if opts.base_url.is_some() {
        all_paths.push("sitemap.xml".into());
    }
    if has_feed(catalog, opts) {
        all_paths.push(history::FEED.into());
        if wanted(history::FEED) {
            if let Some(feed) = history::feed(catalog, opts) {
                out.write_owned(history::FEED, feed.into_bytes())?;
                written += 1;
            }
        }
    }
    if let Some(base_url) = opts.base_url.as_deref().filter(|_| wanted("sitemap.xml")) {
        let sm = sitemap(catalog, base_url);
        out.write("sitemap.xml", sm.as_bytes())?;
        written += 1;
    }
    Ok(written)
}

/// Writes the files of the site that are no pages (those `wanted`): the theme's assets, the
/// images the READMEs show (each copied once) and each system's wiring drawing as a file of
/// its own; adds every one's path to `all_paths` and returns how many were written.
fn write_files(
    site: &Site<'_>,
    out: &dyn Sink,
    wanted: &(dyn Fn(&str) -> bool + Sync),
    all_paths: &mut Vec<String>,
) -> Result<usize> {
    let mut written = 0;
    for asset in ASSETS {
        all_paths.push(asset.to_string());
        if wanted(asset) {
            let body = theme_file(site.opts.theme_dir.as_deref(), asset)?.unwrap_or_default();
            out.write(asset, body.as_bytes())?;
            written += 1;
        }
    }
    // The images the READMEs show, each copied once.
    for (asset, abs) in site.catalog.readme_assets() {
        all_paths.push(asset.to_string());
        if wanted(asset) {
            out.write_owned(asset, crate::readme::read_asset(abs)?)?;
            written += 1;
        }
    }
    // Each wiring diagram as a file of its own, which the system page links (a large
    // system is easier to read opened alone, zoomed by the browser).
    for (path, svg) in systems::drawings(site) {
        all_paths.push(path.clone());
        if wanted(&path) {
            out.write_owned(&path, svg.into_bytes())?;
            written += 1;
        }
    }
    Ok(written)
}

/// The sitemap: every page but the 404 (and the diagnostics page when there are none), at
/// absolute URLs below `base_url`.
fn sitemap(catalog: &Catalog, base_url: &str) -> String {
    let mut urls: Vec<String> = catalog
        .pages()
        .iter()
        .filter(|p| match p.kind {
            PageKind::NotFound => false,
            PageKind::Diagnostics => !catalog.diagnostics.is_empty(),
            _ => true,
        })
        .map(|p| p.path("html"))
        .collect();
    urls.sort();
    let base = format!("{}/", base_url.trim_end_matches('/'));
    let mut sm = String::from(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<urlset xmlns=\"http://www.sitemaps.org/schemas/sitemap/0.9\">\n",
    );
    for u in urls {
        sm.push_str("  <url><loc>");
        sm.push_str(&xml_escape(&format!("{base}{u}")));
        sm.push_str("</loc></url>\n");
    }
    sm.push_str("</urlset>\n");
    sm
}

/// Whether component pages are written by [`native::component_page`]: when the theme directory
/// overrides none of the templates it stands for.
fn native_component_pages(opts: &SiteOptions) -> bool {
    !theme_overrides(opts, &["base.html", "macros.html", "component.html"])
}

/// Whether the theme directory overrides any of the built-in templates `files`.
fn theme_overrides(opts: &SiteOptions, files: &[&str]) -> bool {
    opts.theme_dir
        .as_deref()
        .is_some_and(|d| files.iter().any(|f| d.join(f).is_file()))
}

fn ctx<S: Serialize>(v: &S) -> Value {
    Value::from_serialize(v)
}

/// What a data type's or interface's page prints (`type.html`, `interface.html`): the
/// template context, and what [`native::type_page`] writes for the built-in theme. The keys of
/// the other kind are left out.
#[derive(Serialize)]
struct TypePage {
    #[serde(skip)]
    kind: TypeKind,
    root: &'static str,
    title: String,
    name: String,
    crumbs: Vec<Link>,
    stability: Option<StabilityLine>,
    spellings: Vec<String>,
    idl_files: Vec<String>,
    def: Option<crate::render::idl_view::DefinitionView>,
    others: Vec<PortUse>,
    idl_file: Option<IdlFilePage>,
    #[serde(skip_serializing_if = "Option::is_none")]
    contained_in: Option<Vec<Link>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    producers: Option<Vec<PortUse>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    consumers: Option<Vec<PortUse>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    carried_by: Option<Vec<Link>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    unprovided: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    providers: Option<Vec<PortUse>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    requirers: Option<Vec<PortUse>>,
    /// The operations and attributes of interfaces using it, and how many interfaces.
    used_by: Vec<InterfaceUse>,
    used_by_count: usize,
}

/// An operation or attribute of an interface using a type, on the type's page.
#[derive(Serialize)]
struct InterfaceUse {
    interface: Link,
    member: Link,
    how: String,
}

/// The IDL file section of a type's page.
#[derive(Serialize)]
struct IdlFilePage {
    file: String,
    source_url: Option<String>,
    history: Vec<crate::render::view::history::HistoryRow>,
    older: Option<String>,
    /// The file's history page (every version), from the type's page.
    history_page: Option<String>,
}

/// The page of a data type or interface, from its view.
fn type_page(site: &Site<'_>, v: &view::types::TypeView<'_>) -> TypePage {
    let (catalog, lang) = (site.catalog, site.lang);
    let link = |l: &Linked<'_>| Link {
        text: l.text.clone(),
        href: l.target(catalog, v.page, Output::Html).unwrap_or_default(),
    };
    let uses = |anchor: &str| -> Vec<PortUse> {
        v.uses
            .iter()
            .filter(|g| g.anchor == anchor)
            .flat_map(|g| &g.rows)
            .map(|r| PortUse {
                component: link(&r.component),
                port: link(&r.port),
            })
            .collect()
    };
    let (key, crumbs_key) = match v.kind {
        TypeKind::Data => ("data_type", "data_types"),
        TypeKind::Interface => ("interface", "interfaces"),
    };
    let root = "../";
    let data = v.kind == TypeKind::Data;
    TypePage {
        kind: v.kind,
        root,
        title: page_title(site, &format!("{} {}", v.name, lang.t(key))),
        name: v.name.to_string(),
        crumbs: crumbs_section(lang, root, crumbs_key),
        stability: StabilityLine::of(catalog, v.page, v.stability.as_ref(), Output::Html),
        spellings: v.spellings.to_vec(),
        idl_files: crate::catalog::idl_file_names(v.idl_files),
        def: crate::render::idl_view::definition(catalog, v.name, lang),
        others: uses("sec-others"),
        idl_file: v.idl_file.as_ref().map(|f| IdlFilePage {
            file: f.file.clone(),
            source_url: f.source_url.clone(),
            history: f.history.rows.clone(),
            older: f.history.older_note(lang),
            history_page: f
                .history_page
                .map(|to| catalog.href(v.page, to, None, Output::Html)),
        }),
        contained_in: data.then(|| v.contained_in.iter().map(link).collect()),
        producers: data.then(|| uses("sec-producers")),
        consumers: data.then(|| uses("sec-consumers")),
        carried_by: data.then(|| v.carried_by.iter().map(link).collect()),
        unprovided: (!data).then_some(v.unprovided),
        providers: (!data).then(|| uses("sec-providers")),
        requirers: (!data).then(|| uses("sec-requirers")),
        used_by: v
            .used_by
            .iter()
            .map(|u| {
                let page = u.page.map(|p| catalog.href(v.page, p, None, Output::Html));
                let member = u
                    .page
                    .map(|p| catalog.href(v.page, p, Some(&u.anchor), Output::Html));
                InterfaceUse {
                    interface: Link {
                        text: u.interface.to_string(),
                        href: page.unwrap_or_default(),
                    },
                    member: Link {
                        text: u.member.to_string(),
                        href: member.unwrap_or_default(),
                    },
                    how: u.how.clone(),
                }
            })
            .collect(),
        used_by_count: v.used_by_interfaces,
    }
}

/// The index of the data types (`types.html`) or of the interfaces (`interfaces.html`), from
/// its view.
fn type_index_job<'a>(site: &'a Site<'a>, kind: TypeKind) -> Job<'a> {
    let lang = site.lang;
    let v = view::types::type_index_view(site.catalog, kind);
    let root = "../";
    // An entry's page is beside the index: its file name is the link.
    let rows: Vec<Value> = v
        .rows
        .iter()
        .map(|r| {
            let (name, href) = (r.name, r.page.file_name("html"));
            let [first, second, others] = r.counts;
            match kind {
                TypeKind::Data => minijinja::context! {
                    name, href, spellings => r.other_spellings.clone(),
                    producers => first, consumers => second, others,
                    interfaces => r.interfaces,
                },
                TypeKind::Interface => minijinja::context! {
                    name, href, providers => first, requirers => second,
                    unprovided => r.unprovided,
                },
            }
        })
        .collect();
    let key = kind.index_key();
    let (template, list) = match kind {
        TypeKind::Data => ("types.html", minijinja::context! { types => rows }),
        TypeKind::Interface => (
            "interfaces.html",
            minijinja::context! { interfaces => rows },
        ),
    };
    Job {
        path: v.page.path("html"),
        template,
        context: PageContext::Ready(minijinja::context! {
            root => root,
            title => page_title(site, lang.t(key)),
            crumbs => ctx(&crumbs_home(lang, root)),
            ..list
        }),
    }
}

/// The index of the categories or vendors (`facets.html`), from its view.
fn facet_index_job<'a>(site: &'a Site<'a>, kind: FacetKind) -> Job<'a> {
    let (catalog, lang) = (site.catalog, site.lang);
    let v = facet_index_view(catalog, kind, lang);
    let root = "../";
    let list: Vec<(Link, usize)> = v
        .facets
        .iter()
        .filter_map(|f| {
            // A facet page is beside the index: its file name is the link.
            let (to, _) = f.name.to?;
            let link = Link {
                text: f.name.text.clone(),
                href: to.file_name("html"),
            };
            Some((link, f.count))
        })
        .collect();
    let key = kind.index_key();
    Job {
        path: v.page.path("html"),
        template: "facets.html",
        context: PageContext::Ready(minijinja::context! {
            root => root,
            title => page_title(site, lang.t(key)),
            heading => lang.t(key),
            crumbs => ctx(&crumbs_home(lang, root)),
            facets => ctx(&list),
        }),
    }
}

/// The template context of a category's or vendor's page (`facet.html`), from its view.
fn facet_context(site: &Site<'_>, v: &FacetView<'_>) -> Value {
    let lang = site.lang;
    let root = "../";
    let members: Vec<ComponentIx> = v.components.iter().map(|r| r.ci).collect();
    minijinja::context! {
        root => root,
        title => page_title(site, &v.name),
        heading => v.name.clone(),
        kind => lang.t(v.kind.key()),
        variants => ctx(&v.variants),
        variants_label => lang.t("facet_variants"),
        crumbs => ctx(&crumbs_section(lang, root, v.kind.index_key())),
        components => ctx(&site.sorted_summaries(&members)),
    }
}

/// `<title>` of a page: its own title, then the site's.
fn page_title(site: &Site<'_>, s: &str) -> String {
    format!("{s} — {}", site.opts.title)
}

/// The front page (`index.html`): the components by category (only the categories with
/// counts above [`INDEX_FULL_LIST_MAX`] components), the vendors and sources to filter by.
fn index_job<'a>(site: &'a Site<'a>) -> Job<'a> {
    let catalog = site.catalog;
    #[derive(Serialize)]
    struct Group<'a> {
        name: String,
        slug: &'a str,
        components: Vec<&'a ComponentSummary>,
        count: usize,
    }
    let v = view::front::front_view(catalog, site.lang);
    let full = v.components <= INDEX_FULL_LIST_MAX;
    let count = |key| v.index(key).map_or(0, |i| i.count);
    let counts = (count("data_types"), count("interfaces"), count("systems"));
    let groups: Vec<Group<'_>> = v
        .categories
        .into_iter()
        .map(|g| Group {
            components: if full {
                site.sorted_summaries(&g.members)
            } else {
                Vec::new()
            },
            count: g.members.len(),
            name: g.name,
            slug: g.slug,
        })
        .collect();
    let vendors: Vec<Link> = v
        .vendors
        .into_iter()
        .map(|(text, slug)| Link {
            text,
            href: slug.to_string(),
        })
        .collect();
    Job {
        path: v.page.path("html"),
        template: "index.html",
        context: PageContext::Ready(minijinja::context! {
            root => "",
            title => site.opts.title.clone(),
            is_home => true,
            groups => ctx(&groups),
            vendors => ctx(&vendors),
            sources => v.sources,
            implementations => catalog_has_implementations(site.catalog),
            full_list => full,
            component_count => v.components,
            type_count => counts.0,
            interface_count => counts.1,
            system_count => counts.2,
        }),
    }
}

/// Whether any component's code was read (the index then filters by it).
fn catalog_has_implementations(cat: &Catalog) -> bool {
    cat.components.iter().any(|c| c.implementation.is_some())
}

/// Every page except component pages: its path, template and context.
fn other_pages<'a>(site: &'a Site<'a>) -> Vec<Job<'a>> {
    let catalog = site.catalog;
    let lang = site.lang;
    let title = |s: &str| page_title(site, s);
    let mut pages = Vec::new();

    pages.push(index_job(site));

    // Category and vendor pages.
    for kind in [FacetKind::Category, FacetKind::Vendor] {
        pages.push(facet_index_job(site, kind));
        for fi in 0..kind.facets(catalog).len() {
            pages.push(Job {
                path: kind.page(catalog, fi).path("html"),
                template: "facet.html",
                context: PageContext::Lazy(Box::new(move || {
                    facet_context(site, &facet_view(catalog, kind, fi, lang))
                })),
            });
        }
    }

    // Data types and interfaces.
    let source_url = site.opts.source_url.as_deref();
    for kind in [TypeKind::Data, TypeKind::Interface] {
        pages.push(type_index_job(site, kind));
        let template = match kind {
            TypeKind::Data => "type.html",
            TypeKind::Interface => "interface.html",
        };
        // Written natively unless the theme overrides a template the page stands for.
        let native = !theme_overrides(site.opts, &["base.html", "macros.html", template]);
        for i in kind.entries(catalog) {
            let page =
                move || type_page(site, &view::types::entry_view(catalog, i, lang, source_url));
            pages.push(Job {
                path: catalog.type_page(i).path("html"),
                template,
                context: if native {
                    PageContext::Type(Box::new(page))
                } else {
                    PageContext::Lazy(Box::new(move || ctx(&page())))
                },
            });
        }
    }

    pages.extend(systems::pages(site));
    pages.push(dataflow::page(site));
    pages.extend(history::pages(site));

    // Search, 404 and diagnostics.
    pages.push(Job {
        path: catalog.site_page(PageKind::Search).path("html"),
        template: "search.html",
        context: PageContext::Ready(minijinja::context! {
            root => "",
            title => title(lang.t("search")),
            crumbs => ctx(&crumbs_home(lang, "")),
        }),
    });
    // The 404 page may be served from any path: use absolute links when the base URL is known.
    let root404 = site
        .opts
        .base_url
        .as_deref()
        .map(|b| format!("{}/", b.trim_end_matches('/')))
        // Without a base URL the mount point is unknown: links from the site root ("/") work
        // at any depth when the site is served at the root of its host (`rtcdoc serve`, a
        // custom domain, a user or organisation page). A site in a sub-path sets base-url; a
        // `<base>` element cannot help, it needs the same unknown.
        .unwrap_or_else(|| "/".to_string());
    pages.push(Job {
        path: catalog.site_page(PageKind::NotFound).path("html"),
        template: "404.html",
        context: PageContext::Ready(minijinja::context! {
            root => root404,
            title => title(lang.t("not_found_title")),
        }),
    });
    if !catalog.diagnostics.is_empty() {
        let first = catalog.site_page(PageKind::Diagnostics).path("html");
        for (path, root, view) in diagnostics::views(catalog, &first) {
            let heading = if view.page == 1 {
                lang.t("diagnostics").to_string()
            } else {
                format!(
                    "{} ({} {})",
                    lang.t("diagnostics"),
                    lang.t("diag_page"),
                    view.page
                )
            };
            pages.push(Job {
                path,
                template: "diagnostics.html",
                context: PageContext::Ready(minijinja::context! {
                    root => root,
                    title => title(&heading),
                    crumbs => ctx(&crumbs_home(lang, root)),
                    d => ctx(&view),
                }),
            });
        }
    }
    pages
}
