//! The component page's view: everything the page says, built once per component and handed
//! to every output (the HTML page context in `render::html`, the Markdown and Doxygen
//! sections in `render::text`). Renderers decide how it looks, never what it says.

use super::{Dir, Linked, Peers};
use crate::catalog::{Catalog, ComponentIx, Ix, Page};
use crate::i18n::Lang;
use crate::model::{self, documented, non_empty, ActionKind, Direction, PortDirection};
use crate::readme::Readme;
use crate::render::facts::{self, BackupRow, Fact};
use crate::render::neighbourhood::{self as nb, NeighbourRow};
use crate::types::{canonical_type, short_name};

/// What a data port row and a service interface row both say.
pub struct PortView<'a> {
    pub anchor: &'a str,
    /// The version (else date) that added it, when younger than the oldest version read
    /// ([`crate::catalog::history::since`]).
    pub since: Option<&'a str>,
    pub name: &'a str,
    pub direction: Dir,
    /// The data type or interface as written, linked to its page when the catalogue has one.
    pub type_: Option<Linked<'a>>,
    /// The short type name the component diagram shows (`TimedLong` for `RTC::TimedLong`).
    pub type_short: String,
    pub description: Option<&'a str>,
    /// Its other facts (not its name, direction, type, unit or description).
    pub details: Vec<Fact>,
    /// The components at the other end.
    pub peers: Peers<'a>,
}

/// A data port row.
pub struct DataPortView<'a> {
    pub port: PortView<'a>,
    pub side: model::PortSide,
    pub unit: &'a str,
    /// Its events: name and facts.
    pub events: Vec<(&'a str, Vec<Fact>)>,
}

/// A service interface row of a service port.
pub struct InterfaceView<'a> {
    pub port: PortView<'a>,
    pub provided: bool,
}

/// A service port with its interfaces.
pub struct ServicePortView<'a> {
    pub anchor: &'a str,
    /// The version (else date) that added it, when younger than the oldest version read
    /// ([`crate::catalog::history::since`]).
    pub since: Option<&'a str>,
    pub name: &'a str,
    pub side: model::PortSide,
    pub details: Vec<Fact>,
    pub interfaces: Vec<InterfaceView<'a>>,
}

/// A configuration parameter row.
pub struct ConfigurationView<'a> {
    pub anchor: &'a str,
    /// The version (else date) that added it, when younger than the oldest version read
    /// ([`crate::catalog::history::since`]).
    pub since: Option<&'a str>,
    pub name: &'a str,
    pub type_: &'a str,
    pub default: &'a str,
    pub unit: &'a str,
    pub constraint: String,
    pub widget: String,
    pub description: Option<&'a str>,
    /// Its other facts (not the columns above).
    pub details: Vec<Fact>,
}

/// A lifecycle action row.
pub struct ActionView {
    pub kind: ActionKind,
    pub implemented: bool,
    /// Its Document Profile: description, pre- and post-condition.
    pub details: Vec<Fact>,
}

/// Everything a component page says.
pub struct ComponentView<'a> {
    pub ci: ComponentIx,
    pub page: &'a Page,
    /// The name shown (with what tells components of one name apart).
    pub name: String,
    /// The name the profile declares (the component diagram's box).
    pub profile_name: &'a str,
    /// The category, linked to its page.
    pub category: Linked<'a>,
    /// The description: the page's lead text (free text).
    pub lead: Option<&'a str>,
    /// Its stability mark, shown under the title.
    pub stability: Option<super::StabilityView<'a>>,
    /// Basic information; the vendor's fact links to [`ComponentView::vendor`], the source's
    /// to [`ComponentView::source_url`].
    pub basic: Vec<Fact>,
    pub vendor: Option<&'a Page>,
    /// The URL of the profile in its repository (`source-url`).
    pub source_url: Option<String>,
    /// The Document Profile.
    pub document: Vec<Fact>,
    pub readme: Option<&'a Readme>,
    /// The Implementation section: the code read and how it agrees with the profile.
    pub implementation: Option<facts::ImplementationSection>,
    pub data_ports: Vec<DataPortView<'a>>,
    pub service_ports: Vec<ServicePortView<'a>>,
    pub configurations: Vec<ConfigurationView<'a>>,
    pub actions: Vec<ActionView>,
    /// System parameters: (name, default value).
    pub parameters: Vec<(&'a str, &'a str)>,
    pub language: Vec<Fact>,
    /// The target environments with facts: (number from 1, facts).
    pub targets: Vec<(usize, Vec<Fact>)>,
    pub properties: Vec<Fact>,
    pub version_up_logs: Vec<&'a str>,
    pub extras: Vec<(Fact, model::ExtraKind)>,
    /// The systems with an instance of the component, linked, naming the instances.
    pub systems: Vec<Linked<'a>>,
    pub backups: Vec<BackupRow>,
    /// The History section: the latest versions of the profile ([`super::history`]).
    pub history: super::history::HistoryView,
    /// The component's history page, which the History section links.
    pub history_page: Option<&'a Page>,
    /// The components one connector away, by port ([`crate::render::neighbourhood`]): empty
    /// when no component connects to this one.
    pub neighbourhood: Vec<NeighbourRow<'a>>,
}

/// The data port's direction: label and class (`in`, `out`, `event`, `other`).
fn port_dir(lang: Lang, p: &model::DataPort) -> Dir {
    match p.direction() {
        Some(PortDirection::In) => Dir::new(lang.t("in"), "in"),
        Some(PortDirection::Out) => Dir::new(lang.t("out"), "out"),
        Some(PortDirection::Event) => Dir::new(lang.t("event"), "event"),
        None => Dir::new(non_empty(&p.port_type).unwrap_or(""), "other"),
    }
}

fn short(t: &Option<model::Text>) -> String {
    non_empty(t)
        .map(|t| short_name(&canonical_type(t)).to_string())
        .unwrap_or_default()
}

/// The change path of each element "since" notes can be on (none without a history).
fn since_keys(c: &crate::catalog::Component) -> crate::catalog::history::ElementKeys {
    if c.since.is_empty() {
        crate::catalog::history::ElementKeys::default()
    } else {
        crate::catalog::history::ElementKeys::of(&c.profile)
    }
}

/// The "since" note of the element with change path `key` ([`since_keys`]).
fn since<'a>(c: &'a crate::catalog::Component, key: Option<&String>) -> Option<&'a str> {
    key.and_then(|k| c.since.get(k)).map(String::as_str)
}

/// Each of `items`, a list of component `c`'s profile, with its index, its anchor (of
/// `anchors`) and its "since" note (by the change paths `keys` of [`since_keys`]).
fn anchored<'a, 'k, T>(
    c: &'a crate::catalog::Component,
    items: &'a [T],
    (anchors, keys): (&'a [String], &'k [String]),
) -> impl Iterator<Item = (usize, &'a T, &'a str, Option<&'a str>)> + 'k
where
    'a: 'k,
{
    items
        .iter()
        .enumerate()
        .map(move |(i, x)| (i, x, anchors[i].as_str(), since(c, keys.get(i))))
}

/// The data ports of component `ci`, each with its type linked and its peers.
fn data_port_views(cat: &Catalog, ci: ComponentIx, lang: Lang) -> Vec<DataPortView<'_>> {
    let c = &cat[ci];
    let keys = since_keys(c);
    anchored(
        c,
        &c.profile.data_ports,
        (&c.anchors.data_ports, &keys.data_ports),
    )
    .map(|(pi, dp, anchor, since)| {
        let ti = cat.port_type(ci, pi);
        let type_page = ti.map(|ti| cat.data_type_page(ti));
        let peers = Peers::of(
            ci,
            cat.data_port_peers(ci, pi),
            |r| cat.port_component(r).unwrap_or(Ix::NONE),
            |r| {
                let (pc, port) = cat.resolve_port(r)?;
                let comp = &cat[pc];
                Some((
                    pc,
                    comp.profile.data_ports[port]
                        .name
                        .as_deref()
                        .unwrap_or_default()
                        .to_string(),
                    comp.anchors.data_ports[port].as_str(),
                ))
            },
            cat,
            type_page,
            lang.t("more_on_type_page"),
        );
        DataPortView {
            side: dp.side(),
            unit: facts::data_port_unit(dp).unwrap_or(""),
            events: dp
                .events
                .iter()
                .map(|e| (e.name.as_deref().unwrap_or_default(), facts::event(e, lang)))
                .collect(),
            port: PortView {
                anchor,
                since,
                name: dp.name.as_deref().unwrap_or_default(),
                direction: port_dir(lang, dp),
                type_: non_empty(&dp.type_).map(|t| Linked::new(t, type_page, None)),
                type_short: short(&dp.type_),
                description: dp.doc.as_ref().and_then(|d| non_empty(&d.description)),
                details: facts::data_port_attributes_without_unit(dp, lang),
                peers,
            },
        }
    })
    .collect()
}

/// The service ports of component `ci`, each with its interfaces, their types linked and
/// their peers.
fn service_port_views(cat: &Catalog, ci: ComponentIx, lang: Lang) -> Vec<ServicePortView<'_>> {
    let c = &cat[ci];
    let keys = since_keys(c);
    let ports = (&c.anchors.service_ports[..], &keys.service_ports[..]);
    anchored(c, &c.profile.service_ports, ports)
        .map(|(si, sp, anchor, since)| ServicePortView {
            anchor,
            name: sp.name.as_deref().unwrap_or_default(),
            since,
            side: sp.side(),
            details: facts::service_port(sp, lang),
            interfaces: anchored(
                c,
                &sp.interfaces,
                (
                    &c.anchors.interfaces[si],
                    keys.interfaces.get(si).map_or(&[], Vec::as_slice),
                ),
            )
            .map(|(ii, i, anchor, since)| {
                let it = cat
                    .interface_type(ci, si, ii)
                    .map(|x| cat.interface_page(x));
                let peers = Peers::of(
                    ci,
                    cat.interface_peers(ci, si, ii),
                    |r| cat.interface_component(r).unwrap_or(Ix::NONE),
                    |r| {
                        let (pc, port, x) = cat.resolve_interface(r)?;
                        let comp = &cat[pc];
                        let sp = &comp.profile.service_ports[port];
                        Some((
                            pc,
                            format!(
                                "{}.{}",
                                sp.name.as_deref().unwrap_or(""),
                                sp.interfaces[x].name.as_deref().unwrap_or("")
                            ),
                            comp.anchors.interfaces[port][x].as_str(),
                        ))
                    },
                    cat,
                    it,
                    lang.t("more_on_interface_page"),
                );
                InterfaceView {
                    provided: i.direction_kind() == Some(Direction::Provided),
                    port: PortView {
                        anchor,
                        name: i.name.as_deref().unwrap_or_default(),
                        since,
                        direction: match i.direction_kind() {
                            Some(Direction::Provided) => Dir::new(lang.t("provided"), "provided"),
                            Some(Direction::Required) => Dir::new(lang.t("required"), "required"),
                            None => Dir::new(non_empty(&i.direction).unwrap_or(""), "other"),
                        },
                        type_: non_empty(&i.type_).map(|t| Linked::new(t, it, None)),
                        type_short: short(&i.type_),
                        description: i.doc.as_ref().and_then(|d| non_empty(&d.description)),
                        details: facts::service_interface(i, lang),
                        peers,
                    },
                }
            })
            .collect(),
        })
        .collect()
}

/// The configuration parameters of component `c`.
fn configuration_views(c: &crate::catalog::Component, lang: Lang) -> Vec<ConfigurationView<'_>> {
    let keys = since_keys(c);
    let configurations = (&c.anchors.configurations[..], &keys.configurations[..]);
    anchored(c, c.profile.configurations(), configurations)
        .map(|(_, conf, anchor, since)| ConfigurationView {
            anchor,
            name: conf.name.as_deref().unwrap_or_default(),
            since,
            type_: non_empty(&conf.type_).unwrap_or(""),
            default: conf.default_value.as_deref().unwrap_or_default(),
            unit: facts::configuration_unit(conf).unwrap_or(""),
            constraint: facts::configuration_constraint(conf, lang).unwrap_or_default(),
            widget: facts::configuration_widget(conf, lang).unwrap_or_default(),
            description: conf.doc.as_ref().and_then(|d| non_empty(&d.description)),
            details: facts::configuration_without_widget(conf, lang),
        })
        .collect()
}

/// Builds the view of component `ci`. `category` and `vendor` are its facets
/// ([`Catalog::category_of_each`], [`Catalog::vendor_of_each`]); `source_url` the
/// `source-url` template (a component of a `[[source]]` uses its source's instead).
pub fn component_view<'a>(
    cat: &'a Catalog,
    ci: ComponentIx,
    (category, vendor): (usize, usize),
    source_url: Option<&str>,
    lang: Lang,
) -> ComponentView<'a> {
    let c = &cat[ci];
    let p = &c.profile;
    let page = cat.component_page(ci);
    let data_ports = data_port_views(cat, ci, lang);
    let service_ports = service_port_views(cat, ci, lang);
    let configurations = configuration_views(c, lang);
    let actions = ActionKind::ALL
        .iter()
        .map(|&kind| {
            let a = p.action(kind);
            ActionView {
                kind,
                implemented: a.is_some_and(|a| a.is_implemented()),
                details: facts::action(a, lang),
            }
        })
        .collect();
    let (language, targets) = match &p.language {
        Some(l) => (
            facts::language(l, lang),
            l.targets
                .iter()
                .enumerate()
                .map(|(k, t)| (k + 1, facts::target(t, lang)))
                .filter(|(_, f)| !f.is_empty())
                .collect(),
        ),
        None => (Vec::new(), Vec::new()),
    };
    ComponentView {
        ci,
        page,
        name: c.display_name().into_owned(),
        profile_name: p.name(),
        category: Linked::new(
            // RTCBuilder's placeholder `Category` is in the uncategorised group.
            documented("category", &p.basic_info.category).unwrap_or(lang.t("no_category")),
            cat.categories
                .get(category)
                .map(|_| cat.category_page(category)),
            None,
        ),
        // RTCBuilder's placeholder `ModuleDescription` is no lead (the basic facts list it).
        lead: documented("description", &p.basic_info.description),
        stability: super::stability_view(cat, c.stability.as_ref(), lang),
        basic: facts::basic_info(c, lang),
        vendor: cat.vendors.get(vendor).map(|_| cat.vendor_page(vendor)),
        // A profile of a `[[source]]` repository links into that repository at the pinned
        // commit, with the source's template.
        source_url: crate::render::html::repo::document_source_url(
            &cat.sources,
            c.origin.as_ref(),
            &c.source,
            source_url,
        ),
        document: p
            .basic_info
            .doc
            .as_ref()
            .map(|d| facts::document(d, lang))
            .unwrap_or_default(),
        readme: c.readme.as_ref(),
        implementation: facts::ImplementationSection::of(c, lang, &|f| {
            crate::render::html::repo::sibling_source_url(
                &cat.sources,
                c.origin.as_ref(),
                &c.source,
                f,
                source_url,
            )
        }),
        data_ports,
        service_ports,
        configurations,
        actions,
        parameters: p.parameters.iter().map(facts::parameter).collect(),
        language,
        targets,
        properties: facts::component_properties(p, lang),
        version_up_logs: facts::version_up_logs(p),
        extras: facts::extras_with_kind(p),
        systems: cat
            .systems_using(ci)
            .into_iter()
            .map(|(s, names)| {
                Linked::new(
                    &format!("{}: {}", s.display_name(), names.join(", ")),
                    cat.page_of_system(s),
                    None,
                )
            })
            .collect(),
        backups: BackupRow::of(c, lang),
        history_page: cat.history_page(ci),
        history: super::history::HistoryView::of(
            &c.history,
            lang,
            &|commit, path| super::history_page::commit_url(cat, c, source_url, commit, path),
            (
                super::history_page::current_file_date(c).as_deref(),
                &|ch| {
                    let of = crate::catalog::history::HistoryOf::Component(ci);
                    (None, super::history::reach_text(cat, of, ch, lang))
                },
            ),
        ),
        neighbourhood: nb::rows(cat, ci, &nb::neighbourhood(cat, ci)),
    }
}
