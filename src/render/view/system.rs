//! The page of an RT System: summary, instances, configuration used, connectors, orders,
//! groups and every value of the file, built once for the HTML site, Markdown and Doxygen.
//! Host data is left out unless `show_host`. Links are resolved for one output
//! ([`Catalog::href`]); everything else is plain text.

use crate::catalog::systems::{
    check_configuration, end_port_name, ConfigCheck, EndLink, PortLink, System,
};
use crate::catalog::{Catalog, Output, Page};
use crate::i18n::Lang;
use crate::model::system::{PortEnd, RtSystem};
use crate::model::{non_empty, Text};
use serde::Serialize;

/// A link resolved for one output: text and target (empty: no link).
#[derive(Debug, Clone, Serialize)]
pub struct Link {
    pub text: String,
    pub href: String,
}

/// A labelled value.
#[derive(Debug, Clone, Serialize)]
pub struct KeyValue {
    pub key: String,
    pub value: String,
}

fn txt(v: &Option<Text>) -> String {
    non_empty(v).unwrap_or("").to_string()
}

#[derive(Debug, Clone, Serialize)]
pub struct InstanceRow {
    pub anchor: String,
    pub name: String,
    pub component: Option<Link>,
    pub id: String,
    pub drift: Option<String>,
    pub active_set: String,
    pub contexts: String,
    pub required: String,
    pub composite: String,
    /// A composite instance's members (its participants), each linked to its row when it is
    /// an instance of the system.
    pub members: Vec<Link>,
    /// The composite instances this instance is a member of, linked to their rows.
    pub member_of: Vec<Link>,
    pub comment: String,
    pub path_uri: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct ConfRow {
    pub name: String,
    pub value: String,
    pub default: String,
    pub differs: bool,
    /// `ok`, `undeclared`, `bad-type`, `violated`, `unknown` (component not in the catalogue).
    pub status: &'static str,
    pub note: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct ConfSet {
    pub id: String,
    pub active: bool,
    pub pseudo: bool,
    pub rows: Vec<ConfRow>,
}

#[derive(Debug, Clone, Serialize)]
pub struct InstanceConfig {
    pub instance: String,
    pub anchor: String,
    pub sets: Vec<ConfSet>,
}

#[derive(Debug, Clone, Serialize)]
pub struct EndView {
    pub instance: Option<Link>,
    pub port: Link,
}

#[derive(Debug, Clone, Serialize)]
pub struct DataConnRow {
    pub name: String,
    pub id: String,
    /// The out-port end: where the data comes from, whichever end the file names first.
    pub source: EndView,
    /// The in-port end.
    pub target: EndView,
    /// For a connector the file saved in-port first: how it saved it (`saved as: Dst0.in →
    /// Src0.out`), so that the table shows the data flow and loses nothing.
    pub saved_as: Option<String>,
    pub data_type: Option<Link>,
    pub interface_type: String,
    pub dataflow_type: String,
    pub subscription_type: String,
    pub push_interval: String,
    pub comment: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct ServiceConnRow {
    pub name: String,
    pub id: String,
    pub source: EndView,
    pub target: EndView,
    pub interfaces: Vec<Link>,
    pub trans_method: String,
    pub comment: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct OrderRow {
    pub sequence: String,
    pub instance: String,
    pub context: String,
    pub condition: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct OrderView {
    pub kind: &'static str,
    pub targets: Vec<OrderRow>,
}

#[derive(Debug, Clone, Serialize)]
pub struct GroupView {
    pub id: String,
    pub members: Vec<String>,
}

/// Everything a system page says (the wiring drawing aside).
pub struct SystemView {
    pub name: String,
    pub summary: Vec<KeyValue>,
    pub properties: Vec<KeyValue>,
    /// How many host values were left out.
    pub hidden: usize,
    pub instances: Vec<InstanceRow>,
    pub configs: Vec<InstanceConfig>,
    pub data_connectors: Vec<DataConnRow>,
    pub service_connectors: Vec<ServiceConnRow>,
    pub orders: Vec<OrderView>,
    pub groups: Vec<GroupView>,
    /// Every value of the file as (path, value).
    pub all_values: Vec<KeyValue>,
    /// Where the "Source" of the summary links: the file in its repository (`source-url`, a
    /// `[[source]]`'s template at the pinned commit).
    pub source_url: Option<String>,
    /// The History section: the latest versions of the file ([`super::history`]).
    pub history: super::history::HistoryView,
    /// The system's history page (every version), when it has a history.
    pub history_page: Option<crate::catalog::Page>,
}

/// Which tables of a system page have a comment in some row: a Comment column empty in every
/// row is left out (as the component page leaves out its empty columns).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct CommentColumns {
    pub instances: bool,
    pub data: bool,
    pub service: bool,
}

impl SystemView {
    pub fn comment_columns(&self) -> CommentColumns {
        CommentColumns {
            instances: self.instances.iter().any(|r| !r.comment.is_empty()),
            data: self.data_connectors.iter().any(|c| !c.comment.is_empty()),
            service: self
                .service_connectors
                .iter()
                .any(|c| !c.comment.is_empty()),
        }
    }
}

/// What the connector rows of system `s` link through: other pages of the catalogue (`href`)
/// and the rows of this page (`local`).
struct Links<'a> {
    cat: &'a Catalog,
    s: &'a System,
    href: &'a dyn Fn(&Page, Option<&str>) -> String,
    local: &'a dyn Fn(&str) -> String,
}

/// Link of a connector end: the instance row, and the port on the component page when the
/// component and its port are in the catalogue (else the instance row).
fn end_view(links: &Links<'_>, e: &Option<PortEnd>, link: &EndLink) -> EndView {
    let &Links {
        cat,
        s,
        href,
        local,
    } = links;
    let port_name = e.as_ref().map(end_port_name).unwrap_or("").to_string();
    let Some(i) = link.instance else {
        let inst = e
            .as_ref()
            .map(|e| txt(&e.instance_name))
            .unwrap_or_default();
        return EndView {
            instance: None,
            port: Link {
                text: format!("{inst}.{port_name}"),
                href: String::new(),
            },
        };
    };
    let anchor = &s.instances[i].anchor;
    let name = txt(&s.profile.components[i].instance_name);
    let comp = cat.instance_component(s, i);
    let to = s.instances[i]
        .component_index
        .map(|ci| cat.component_page(ci));
    let port_href = match (comp, to, &link.port) {
        (Some(c), Some(to), Some(PortLink::Data { index, .. })) => {
            href(to, Some(&c.anchors.data_ports[*index]))
        }
        (Some(c), Some(to), Some(PortLink::Service { index, .. })) => {
            href(to, Some(&c.anchors.service_ports[*index]))
        }
        _ => local(anchor),
    };
    EndView {
        instance: Some(Link {
            text: name,
            href: local(anchor),
        }),
        port: Link {
            text: port_name,
            href: port_href,
        },
    }
}

/// The summary of system `s`: its id, vendor, version, dates, comment and file, those given.
fn summary_facts(s: &System, lang: Lang) -> Vec<KeyValue> {
    let p = &s.profile;
    let parts = p.id_parts.as_ref();
    let part = |f: fn(&crate::model::system::SystemIdParts) -> &Option<Text>| {
        parts.map(|x| txt(f(x))).unwrap_or_default()
    };
    let kv = |k: &str, v: String| KeyValue {
        key: lang.t(k).to_string(),
        value: v,
    };
    let mut summary = vec![
        kv("sys_id", txt(&p.id)),
        kv("vendor", part(|x| &x.vendor)),
        kv("version", part(|x| &x.version)),
        kv("sys_format_version", txt(&p.version)),
        kv("sys_abstract", txt(&p.abstract_)),
        kv("creation_date", txt(&p.creation_date)),
        kv("update_date", txt(&p.update_date)),
        kv("comment", txt(&p.comment)),
        kv("source", s.source.clone()),
    ];
    summary.retain(|f| !f.value.is_empty());
    summary
}

/// The properties of system profile `p`; host data only when `show_host`.
fn visible_properties(p: &RtSystem, show_host: bool) -> Vec<KeyValue> {
    p.properties
        .iter()
        .filter(|q| {
            show_host
                || !(q.private
                    || q.value
                        .as_deref()
                        .is_some_and(crate::catalog::systems::is_naming_path))
        })
        .map(|q| KeyValue {
            key: txt(&q.name),
            value: txt(&q.value),
        })
        .collect()
}

/// A link to another page of the catalogue (with an anchor on it).
type PageHref<'a> = dyn Fn(&Page, Option<&str>) -> String + 'a;

/// The instances of system `s`, each linked to its component's page, a composite's members
/// and the composites an instance is a member of to their rows (`local`).
fn instance_rows(
    (cat, s, lang): (&Catalog, &System, Lang),
    show_host: bool,
    (href, local): (&PageHref<'_>, &dyn Fn(&str) -> String),
) -> Vec<InstanceRow> {
    // An instance named by a composite: linked to its row (the first of that name).
    let row_link = |name: &str| Link {
        text: name.to_string(),
        href: s
            .profile
            .components
            .iter()
            .position(|k| non_empty(&k.instance_name) == Some(name))
            .map(|j| local(&s.instances[j].anchor))
            .unwrap_or_default(),
    };
    s.profile
        .components
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let comp = cat.instance_component(s, i);
            let contexts = c
                .execution_contexts
                .iter()
                .map(|ec| {
                    let rate = txt(&ec.rate);
                    let mut t = txt(&ec.kind);
                    if !rate.is_empty() {
                        t.push_str(&format!(" {rate} Hz"));
                    }
                    let id = txt(&ec.id);
                    if !id.is_empty() {
                        t = format!("{id}: {t}");
                    }
                    t
                })
                .collect::<Vec<_>>()
                .join("; ");
            InstanceRow {
                anchor: s.instances[i].anchor.clone(),
                name: txt(&c.instance_name),
                component: comp.map(|k| Link {
                    text: k.display_name().into_owned(),
                    href: s.instances[i]
                        .component_index
                        .map(|ci| href(cat.component_page(ci), None))
                        .unwrap_or_default(),
                }),
                id: txt(&c.id),
                drift: s.instances[i].version_drift.clone(),
                active_set: txt(&c.active_configuration_set),
                contexts,
                // Yes or no in the page's language, as the lifecycle table says whether an
                // action is implemented; a value that is no boolean, as written.
                required: match c.required() {
                    Some(r) => lang.t(if r { "yes" } else { "no" }).to_string(),
                    None => txt(&c.is_required),
                },
                composite: txt(&c.composite_type),
                members: c.member_names().into_iter().map(&row_link).collect(),
                member_of: s
                    .profile
                    .composites_of(non_empty(&c.instance_name).unwrap_or(""))
                    .filter_map(|k| non_empty(&k.instance_name))
                    .map(&row_link)
                    .collect(),
                comment: txt(&c.comment),
                path_uri: if show_host {
                    txt(&c.path_uri)
                } else {
                    String::new()
                },
            }
        })
        .collect()
}

/// The configuration each instance of system `s` uses, next to its component's defaults.
fn instance_configs(cat: &Catalog, s: &System, lang: Lang) -> Vec<InstanceConfig> {
    s.profile
        .components
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.configuration_sets.is_empty())
        .map(|(i, c)| {
            let comp = cat.instance_component(s, i);
            let active = txt(&c.active_configuration_set);
            let sets = c
                .configuration_sets
                .iter()
                .map(|set| {
                    let rows =
                        set.configuration_data
                            .iter()
                            .map(|d| {
                                let n = txt(&d.name);
                                let v = d.data.as_deref().unwrap_or("").to_string();
                                let decl = comp.and_then(|k| {
                                    k.profile.configurations().iter().find(|x| {
                                        x.name.as_deref().map(str::trim) == Some(n.trim())
                                    })
                                });
                                let default = decl
                                    .and_then(|x| x.default_value.as_deref())
                                    .unwrap_or("")
                                    .to_string();
                                let (status, note) = match comp {
                                    _ if set.pseudo => ("ok", String::new()),
                                    None => ("unknown", String::new()),
                                    Some(k) => match check_configuration(k, &n, &v) {
                                        ConfigCheck::Ok => ("ok", String::new()),
                                        ConfigCheck::Undeclared => {
                                            ("undeclared", lang.t("sys_undeclared").to_string())
                                        }
                                        ConfigCheck::BadType(w) => ("bad-type", w),
                                        ConfigCheck::Violated(w) => ("violated", w),
                                    },
                                };
                                ConfRow {
                                    differs: decl.is_some() && !set.pseudo && default != v,
                                    name: n,
                                    value: v,
                                    default,
                                    status,
                                    note,
                                }
                            })
                            .collect();
                    let id = txt(&set.id);
                    ConfSet {
                        active: id == active,
                        pseudo: set.pseudo,
                        id,
                        rows,
                    }
                })
                .collect();
            InstanceConfig {
                instance: txt(&c.instance_name),
                anchor: s.instances[i].anchor.clone(),
                sets,
            }
        })
        .collect()
}

/// A connector end as plain text: `instance.port`.
fn end_plain(e: &EndView) -> String {
    match &e.instance {
        Some(i) => format!("{}.{}", i.text, e.port.text),
        None => e.port.text.clone(),
    }
}

/// The row of data connector `c` with its ends (out-port end first) and data type linked.
fn data_row(
    cat: &Catalog,
    href: &dyn Fn(&Page, Option<&str>) -> String,
    c: &crate::model::system::DataPortConnector,
    (source, target): (EndView, EndView),
    saved_as: Option<String>,
) -> DataConnRow {
    DataConnRow {
        name: txt(&c.name),
        id: txt(&c.connector_id),
        source,
        target,
        saved_as,
        data_type: non_empty(&c.data_type).map(|t| Link {
            text: t.to_string(),
            href: cat
                .data_type_index(t)
                .map(|d| href(cat.data_type_page(d), None))
                .unwrap_or_default(),
        }),
        interface_type: txt(&c.interface_type),
        dataflow_type: txt(&c.dataflow_type),
        subscription_type: txt(&c.subscription_type),
        push_interval: txt(&c.push_interval),
        comment: txt(&c.comment),
    }
}

/// The connectors of system `s`: the data connectors with their data type linked (from their
/// out-port to their in-port, [`Catalog::reversed_data_connectors`]), the service connectors
/// with the interfaces of the ports they join; the ends of both linked.
fn connector_rows(links: &Links<'_>, lang: Lang) -> (Vec<DataConnRow>, Vec<ServiceConnRow>) {
    let &Links { cat, s, href, .. } = links;
    let p = &s.profile;
    let reversed = cat.reversed_data_connectors(s);
    let data = p
        .data_port_connectors
        .iter()
        .zip(&s.data_connectors)
        .zip(reversed)
        .map(|((c, l), turned)| {
            let (source, target) = (
                end_view(links, &c.source, &l.source),
                end_view(links, &c.target, &l.target),
            );
            let saved_as = turned.then(|| {
                format!(
                    "{}: {} → {}",
                    lang.t("sys_saved_as"),
                    end_plain(&source),
                    end_plain(&target)
                )
            });
            let (source, target) = if turned {
                (target, source)
            } else {
                (source, target)
            };
            data_row(cat, href, c, (source, target), saved_as)
        })
        .collect();
    let service = p
        .service_port_connectors
        .iter()
        .zip(&s.service_connectors)
        .map(|(c, l)| {
            let mut interfaces: Vec<Link> = Vec::new();
            for end in [&l.source, &l.target] {
                let (Some(i), Some(PortLink::Service { index, .. })) = (end.instance, &end.port)
                else {
                    continue;
                };
                let Some(comp) = cat.instance_component(s, i) else {
                    continue;
                };
                for iface in &comp.profile.service_ports[*index].interfaces {
                    let Some(t) = non_empty(&iface.type_) else {
                        continue;
                    };
                    if interfaces.iter().any(|x| x.text == t) {
                        continue;
                    }
                    interfaces.push(Link {
                        text: t.to_string(),
                        href: cat
                            .interface_index_of(t)
                            .map(|d| href(cat.interface_page(d), None))
                            .unwrap_or_default(),
                    });
                }
            }
            ServiceConnRow {
                name: txt(&c.name),
                id: txt(&c.connector_id),
                source: end_view(links, &c.source, &l.source),
                target: end_view(links, &c.target, &l.target),
                interfaces,
                trans_method: txt(&c.trans_method),
                comment: txt(&c.comment),
            }
        })
        .collect();
    (data, service)
}

/// The execution orders of system profile `p`, each target with its condition.
fn order_views(p: &RtSystem, lang: Lang) -> Vec<OrderView> {
    p.orders
        .iter()
        .map(|o| OrderView {
            kind: o.kind.xml_name(),
            targets: o
                .targets
                .iter()
                .map(|t| {
                    let tc = t.target_component.as_ref();
                    let mut condition = Vec::new();
                    if let Some(w) = t.wait_time.as_ref().map(|w| txt(&w.wait_time)) {
                        condition.push(format!("{} {w} ms", lang.t("sys_wait")));
                    }
                    if let Some(pr) = &t.preceding {
                        let after: Vec<String> = pr
                            .preceding_components
                            .iter()
                            .map(|c| txt(&c.instance_name))
                            .collect();
                        condition.push(format!(
                            "{} {} ({} {} ms, {})",
                            lang.t("sys_after"),
                            after.join(", "),
                            lang.t("sys_timeout"),
                            txt(&pr.timeout),
                            txt(&pr.sending_timing)
                        ));
                    }
                    OrderRow {
                        sequence: txt(&t.sequence),
                        instance: tc.map(|c| txt(&c.instance_name)).unwrap_or_default(),
                        context: tc.map(|c| txt(&c.id)).unwrap_or_default(),
                        condition: condition.join("; "),
                    }
                })
                .collect(),
        })
        .collect()
}

/// Builds the view of system `s` with its links for output `out`.
pub fn system_view(
    cat: &Catalog,
    s: &System,
    lang: Lang,
    (show_host, source_url): (bool, Option<&str>),
    out: Output,
) -> SystemView {
    let here = cat.page_of_system(s);
    let href = |to: &Page, anchor: Option<&str>| -> String {
        here.map(|from| cat.href(from, to, anchor, out))
            .unwrap_or_default()
    };
    // An instance's row of this page: only the HTML page has row anchors.
    let local = |anchor: &str| -> String {
        match out {
            Output::Html | Output::Manual => format!("#{anchor}"),
            Output::Markdown | Output::Doxygen => String::new(),
        }
    };
    let p: &RtSystem = &s.profile;
    let name = s.display_name().into_owned();
    let summary = summary_facts(s, lang);
    let properties = visible_properties(p, show_host);
    let hidden = if show_host {
        0
    } else {
        crate::catalog::systems::host_values(p)
    };

    let instances = instance_rows((cat, s, lang), show_host, (&href, &local));

    let configs = instance_configs(cat, s, lang);

    let links = Links {
        cat,
        s,
        href: &href,
        local: &local,
    };
    let (data_connectors, service_connectors) = connector_rows(&links, lang);

    let orders = order_views(p, lang);
    let groups: Vec<GroupView> = p
        .groups
        .iter()
        .map(|g| GroupView {
            id: txt(&g.group_id),
            members: g.members.iter().map(|m| txt(&m.instance_name)).collect(),
        })
        .collect();

    SystemView {
        name,
        summary,
        properties,
        hidden,
        instances,
        configs,
        data_connectors,
        service_connectors,
        orders,
        groups,
        all_values: crate::catalog::systems::all_values(p, show_host)
            .into_iter()
            .map(|(key, value)| KeyValue { key, value })
            .collect(),
        source_url: crate::render::html::repo::document_source_url(
            &cat.sources,
            s.origin.as_ref(),
            &s.source,
            source_url,
        ),
        history: super::history::HistoryView::of(
            &s.history,
            lang,
            &crate::render::html::repo::history_file_urls(
                &cat.sources,
                s.origin.as_ref(),
                source_url,
            ),
            (
                super::history_page::update_date(&s.profile.update_date).as_deref(),
                &|_| (None, None),
            ),
        ),
        history_page: cat
            .systems
            .iter()
            .position(|x| x.source == s.source)
            .and_then(|si| {
                cat.history_page_of(crate::catalog::history::HistoryOf::System(
                    crate::catalog::Ix::new(si),
                ))
            })
            .cloned(),
    }
}
