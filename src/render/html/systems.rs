//! The pages of RT Systems: `systems/index.html` and one page per system (summary, wiring
//! diagram, instances, configuration used, connectors, orders, groups and every value of the
//! file). Host data (host names, IORs, endpoints, naming paths) is left out unless the site is
//! built with `show-host-data = true`; the page says how many values were left out.

use super::system_svg::{standalone_system_diagram, system_diagram};
use super::{crumbs_home, crumbs_section, ctx, page_title, Job, KeyValue, Link, PageContext, Site};
use crate::catalog::systems::{check_configuration, end_port_name, ConfigCheck, PortLink, System};
use crate::model::system::{PortEnd, RtSystem};
use crate::model::{non_empty, Text};
use serde::Serialize;

const ROOT: &str = "../";

/// The page path of a system ([`Catalog::pages`]).
pub fn system_path(cat: &crate::catalog::Catalog, s: &System) -> String {
    cat.page_of_system(s)
        .map(|p| p.path("html"))
        .unwrap_or_default()
}

fn txt(v: &Option<Text>) -> String {
    non_empty(v).unwrap_or("").to_string()
}

#[derive(Serialize)]
struct SystemRow {
    name: String,
    href: String,
    version: String,
    vendor: String,
    instances: usize,
    connectors: usize,
}

#[derive(Serialize)]
struct InstanceRow {
    anchor: String,
    name: String,
    component: Option<Link>,
    id: String,
    drift: Option<String>,
    active_set: String,
    contexts: String,
    required: String,
    composite: String,
    comment: String,
    path_uri: String,
}

#[derive(Serialize)]
struct ConfRow {
    name: String,
    value: String,
    default: String,
    differs: bool,
    /// `ok`, `undeclared`, `bad-type`, `violated`, `unknown` (component not in the catalogue).
    status: &'static str,
    note: String,
}

#[derive(Serialize)]
struct ConfSet {
    id: String,
    active: bool,
    pseudo: bool,
    rows: Vec<ConfRow>,
}

#[derive(Serialize)]
struct InstanceConfig {
    instance: String,
    anchor: String,
    sets: Vec<ConfSet>,
}

#[derive(Serialize)]
struct EndView {
    instance: Option<Link>,
    port: Link,
}

#[derive(Serialize)]
struct DataConnRow {
    name: String,
    id: String,
    source: EndView,
    target: EndView,
    data_type: Option<Link>,
    interface_type: String,
    dataflow_type: String,
    subscription_type: String,
    push_interval: String,
    comment: String,
}

#[derive(Serialize)]
struct ServiceConnRow {
    name: String,
    id: String,
    source: EndView,
    target: EndView,
    interfaces: Vec<Link>,
    trans_method: String,
    comment: String,
}

#[derive(Serialize)]
struct OrderRow {
    sequence: String,
    instance: String,
    context: String,
    condition: String,
}

#[derive(Serialize)]
struct OrderView {
    kind: &'static str,
    targets: Vec<OrderRow>,
}

#[derive(Serialize)]
struct GroupView {
    id: String,
    members: Vec<String>,
}

impl Site<'_> {
    fn instance_label(&self, s: &System, i: usize) -> (String, Option<&crate::catalog::Component>) {
        let inst = &s.profile.components[i];
        (
            txt(&inst.instance_name),
            self.catalog.instance_component(s, i),
        )
    }

    /// Link of a connector end: the instance row, and the port on the component page when the
    /// component and its port are in the catalogue (else the instance row).
    fn end_view(
        &self,
        s: &System,
        e: &Option<PortEnd>,
        link: &crate::catalog::systems::EndLink,
    ) -> EndView {
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
        let (name, comp) = self.instance_label(s, i);
        let cat = self.catalog;
        let to = comp
            .and_then(|c| cat.component_index(&c.id))
            .map(|ci| cat.component_page(ci));
        let from = cat.page_of_system(s);
        let port_href = match (comp, to, from, &link.port) {
            (Some(c), Some(to), Some(from), Some(PortLink::Data { index, .. })) => cat.href(
                from,
                to,
                Some(&c.anchors.data_ports[*index]),
                crate::catalog::Output::Html,
            ),
            (Some(c), Some(to), Some(from), Some(PortLink::Service { index, .. })) => cat.href(
                from,
                to,
                Some(&c.anchors.service_ports[*index]),
                crate::catalog::Output::Html,
            ),
            _ => format!("#{anchor}"),
        };
        EndView {
            instance: Some(Link {
                text: name,
                href: format!("#{anchor}"),
            }),
            port: Link {
                text: port_name,
                href: port_href,
            },
        }
    }

    fn system_page(&self, s: &System) -> minijinja::Value {
        let lang = self.lang;
        let show_host = self.opts.show_host_data;
        let p: &RtSystem = &s.profile;
        let name = p.name().to_string();
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
        let properties: Vec<KeyValue> = p
            .properties
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
            .collect();
        let hidden = if show_host {
            0
        } else {
            crate::catalog::systems::host_values(p)
        };

        // Instances.
        let instances: Vec<InstanceRow> = p
            .components
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let comp = self.catalog.instance_component(s, i);
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
                        href: self
                            .catalog
                            .component_index(&k.id)
                            .map(|ci| {
                                format!("{ROOT}{}", self.catalog.component_page(ci).path("html"))
                            })
                            .unwrap_or_default(),
                    }),
                    id: txt(&c.id),
                    drift: s.instances[i].version_drift.clone(),
                    active_set: txt(&c.active_configuration_set),
                    contexts,
                    required: txt(&c.is_required),
                    composite: txt(&c.composite_type),
                    comment: txt(&c.comment),
                    path_uri: if show_host {
                        txt(&c.path_uri)
                    } else {
                        String::new()
                    },
                }
            })
            .collect();

        // Configuration used, per instance, next to the component's defaults.
        let configs: Vec<InstanceConfig> = p
            .components
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.configuration_sets.is_empty())
            .map(|(i, c)| {
                let comp = self.catalog.instance_component(s, i);
                let active = txt(&c.active_configuration_set);
                let sets = c
                    .configuration_sets
                    .iter()
                    .map(|set| {
                        let rows = set
                            .configuration_data
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
            .collect();

        // Connectors.
        let data_connectors: Vec<DataConnRow> = p
            .data_port_connectors
            .iter()
            .zip(&s.data_connectors)
            .map(|(c, l)| DataConnRow {
                name: txt(&c.name),
                id: txt(&c.connector_id),
                source: self.end_view(s, &c.source, &l.source),
                target: self.end_view(s, &c.target, &l.target),
                data_type: non_empty(&c.data_type).map(|t| Link {
                    text: t.to_string(),
                    href: self
                        .catalog
                        .data_type_index(t)
                        .map(|d| format!("{ROOT}{}", self.catalog.data_type_page(d).path("html")))
                        .unwrap_or_default(),
                }),
                interface_type: txt(&c.interface_type),
                dataflow_type: txt(&c.dataflow_type),
                subscription_type: txt(&c.subscription_type),
                push_interval: txt(&c.push_interval),
                comment: txt(&c.comment),
            })
            .collect();
        let service_connectors: Vec<ServiceConnRow> = p
            .service_port_connectors
            .iter()
            .zip(&s.service_connectors)
            .map(|(c, l)| {
                let mut interfaces: Vec<Link> = Vec::new();
                for end in [&l.source, &l.target] {
                    let (Some(i), Some(PortLink::Service { index, .. })) =
                        (end.instance, &end.port)
                    else {
                        continue;
                    };
                    let Some(comp) = self.catalog.instance_component(s, i) else {
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
                            href: self
                                .catalog
                                .interface_index_of(t)
                                .map(|d| {
                                    format!("{ROOT}{}", self.catalog.interface_page(d).path("html"))
                                })
                                .unwrap_or_default(),
                        });
                    }
                }
                ServiceConnRow {
                    name: txt(&c.name),
                    id: txt(&c.connector_id),
                    source: self.end_view(s, &c.source, &l.source),
                    target: self.end_view(s, &c.target, &l.target),
                    interfaces,
                    trans_method: txt(&c.trans_method),
                    comment: txt(&c.comment),
                }
            })
            .collect();

        // Orders and groups.
        let orders: Vec<OrderView> = p
            .orders
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
            .collect();
        let groups: Vec<GroupView> = p
            .groups
            .iter()
            .map(|g| GroupView {
                id: txt(&g.group_id),
                members: g.members.iter().map(|m| txt(&m.instance_name)).collect(),
            })
            .collect();

        // The diagram.
        let cat = self.catalog;
        let here = cat.page_of_system(s);
        let link = |to: &crate::catalog::Page, a: &str| match here {
            Some(from) => cat.href(from, to, Some(a), crate::catalog::Output::Html),
            None => String::new(),
        };
        let (wire, conns) = crate::render::wiring::system_wiring(cat, s, lang, &link);
        let diagram_title = format!("{} {name}", lang.t("sys_wiring"));
        let diagram_svg = system_diagram(&diagram_title, &wire, &conns);
        let diagram_text = format!(
            "{}: {} {}, {} {}, {} {}.",
            diagram_title,
            p.components.len(),
            lang.t("instances").to_lowercase(),
            p.data_port_connectors.len(),
            lang.t("sys_data_connectors"),
            p.service_port_connectors.len(),
            lang.t("sys_service_connectors"),
        );

        minijinja::context! {
            root => ROOT,
            title => page_title(self, &format!("{name} {}", lang.t("system"))),
            name => name,
            crumbs => ctx(&crumbs_section(lang, ROOT, "systems")),
            summary => ctx(&summary),
            version_up_logs => ctx(&p.version_up_logs),
            subsystems => ctx(&p.systems.iter().map(|x| txt(&x.path)).collect::<Vec<_>>()),
            properties => ctx(&properties),
            hidden => hidden,
            diagram_svg => diagram_svg,
            diagram_text => diagram_text,
            diagram_file => drawing_path(self.catalog, s).rsplit('/').next().unwrap_or_default().to_string(),
            instances => ctx(&instances),
            show_path => show_host,
            configs => ctx(&configs),
            data_connectors => ctx(&data_connectors),
            service_connectors => ctx(&service_connectors),
            orders => ctx(&orders),
            groups => ctx(&groups),
            all_values => ctx(&crate::catalog::systems::all_values(p, show_host).into_iter().map(|(key, value)| KeyValue { key, value }).collect::<Vec<_>>()),
        }
    }
}

/// The path of a system's wiring drawing as a file of its own: beside its page, `.svg`.
fn drawing_path(catalog: &crate::catalog::Catalog, s: &crate::catalog::systems::System) -> String {
    let page = system_path(catalog, s);
    format!("{}.svg", page.trim_end_matches(".html"))
}

/// Every system's wiring drawing as a file of its own: (path, SVG).
pub(super) fn drawings(site: &Site<'_>) -> Vec<(String, String)> {
    site.catalog
        .systems
        .iter()
        .map(|s| {
            let cat = site.catalog;
            let here = cat.page_of_system(s);
            let link = |to: &crate::catalog::Page, a: &str| match here {
                Some(from) => cat.href(from, to, Some(a), crate::catalog::Output::Html),
                None => String::new(),
            };
            let (wire, conns) = crate::render::wiring::system_wiring(cat, s, site.lang, &link);
            let title = format!("{} {}", site.lang.t("sys_wiring"), s.profile.name());
            (
                drawing_path(site.catalog, s),
                standalone_system_diagram(&title, &wire, &conns),
            )
        })
        .collect()
}

/// `systems/index.html` and one page per system; nothing when there are no systems.
pub(super) fn pages<'a>(site: &'a Site<'a>) -> Vec<Job<'a>> {
    let catalog = site.catalog;
    if catalog.systems.is_empty() {
        return Vec::new();
    }
    let lang = site.lang;
    let rows: Vec<SystemRow> = catalog
        .systems
        .iter()
        .map(|s| {
            let parts = s.profile.id_parts.as_ref();
            SystemRow {
                name: s.profile.name().to_string(),
                href: format!("{}.html", s.slug),
                version: parts.map(|p| txt(&p.version)).unwrap_or_default(),
                vendor: parts.map(|p| txt(&p.vendor)).unwrap_or_default(),
                instances: s.profile.components.len(),
                connectors: s.profile.data_port_connectors.len()
                    + s.profile.service_port_connectors.len(),
            }
        })
        .collect();
    let mut pages = vec![Job {
        path: site
            .catalog
            .site_page(crate::catalog::PageKind::Systems)
            .path("html"),
        template: "systems.html",
        context: PageContext::Ready(minijinja::context! {
            root => ROOT,
            title => page_title(site, lang.t("systems")),
            crumbs => ctx(&crumbs_home(lang, ROOT)),
            systems => ctx(&rows),
        }),
    }];
    for s in &catalog.systems {
        pages.push(Job {
            path: system_path(catalog, s),
            template: "system.html",
            context: PageContext::Lazy(Box::new(move || site.system_page(s))),
        });
    }
    pages
}
