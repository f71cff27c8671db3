//! The body of an RT System's page in the text outputs (Markdown and Doxygen), written once
//! through the [`Markup`] of each: summary, instances, configuration used, connectors, orders,
//! groups and every value of the file. Host data is left out unless `show_host`, as on the HTML
//! pages.

use super::text::Markup;
use crate::catalog::systems::{
    all_values, check_configuration, end_port_name, host_values, is_naming_path, ConfigCheck,
    System,
};
use crate::catalog::{Catalog, Component, Page};
use crate::i18n::Lang;
use crate::model::system::PortEnd;
use crate::model::{non_empty, Text};

/// How a page links and heads its sections.
pub struct Targets<'a> {
    /// The link target of a component's page.
    pub component: &'a dyn Fn(&Component) -> String,
    /// Writes a section heading: (out, anchor, text).
    pub heading: &'a dyn Fn(&mut String, &str, &str),
}

fn txt(v: &Option<Text>) -> String {
    non_empty(v).unwrap_or("").to_string()
}

fn end(e: &Option<PortEnd>) -> String {
    e.as_ref()
        .map(|e| format!("{}.{}", txt(&e.instance_name), end_port_name(e)))
        .unwrap_or_default()
}

/// Writes the sections of system `s`'s page (`from`, for its links).
pub fn system_body<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    from: &Page,
    s: &System,
    lang: Lang,
    show_host: bool,
    t: &Targets<'_>,
) {
    let p = &s.profile;
    let parts = p.id_parts.as_ref();
    let mut facts: Vec<Vec<String>> = [
        ("sys_id", txt(&p.id)),
        ("vendor", parts.map(|x| txt(&x.vendor)).unwrap_or_default()),
        (
            "version",
            parts.map(|x| txt(&x.version)).unwrap_or_default(),
        ),
        ("sys_format_version", txt(&p.version)),
        ("sys_abstract", txt(&p.abstract_)),
        ("creation_date", txt(&p.creation_date)),
        ("update_date", txt(&p.update_date)),
        ("comment", txt(&p.comment)),
        ("source", s.source.clone()),
    ]
    .into_iter()
    .filter(|(_, v)| !v.is_empty())
    .map(|(k, v)| vec![M::esc(lang.t(k)), M::esc(&v)])
    .collect();
    for q in &p.properties {
        let host = q.private || q.value.as_deref().is_some_and(is_naming_path);
        if show_host || !host {
            facts.push(vec![M::esc(&txt(&q.name)), M::esc(&txt(&q.value))]);
        }
    }
    for v in &p.version_up_logs {
        facts.push(vec![M::esc(lang.t("version_up_logs")), M::esc(v)]);
    }
    for x in &p.systems {
        facts.push(vec![
            M::esc(lang.t("sys_subsystems")),
            M::esc(&txt(&x.path)),
        ]);
    }
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &facts);
    let hidden = host_values(p);
    if !show_host && hidden > 0 {
        M::paragraph(
            out,
            &M::esc(&format!("{hidden} {}", lang.t("sys_host_hidden"))),
        );
    }

    // Instances.
    (t.heading)(out, "instances", lang.t("instances"));
    let rows: Vec<Vec<String>> = p
        .components
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let comp = match cat.instance_component(s, i) {
                Some(k) => M::link(&k.display_name(), &(t.component)(k)),
                None => M::esc(lang.t("sys_not_in_catalogue")),
            };
            let drift = s.instances[i]
                .version_drift
                .as_ref()
                .map(|v| M::esc(&format!("{} {v}", lang.t("sys_drift"))))
                .unwrap_or_default();
            let ecs = c
                .execution_contexts
                .iter()
                .map(|ec| {
                    let rate = txt(&ec.rate);
                    let mut x = format!("{}: {}", txt(&ec.id), txt(&ec.kind));
                    if !rate.is_empty() {
                        x.push_str(&format!(" {rate} Hz"));
                    }
                    x
                })
                .collect::<Vec<_>>()
                .join("; ");
            let mut row = vec![
                M::esc(&txt(&c.instance_name)),
                comp,
                M::esc(&txt(&c.id)),
                drift,
                M::esc(&txt(&c.active_configuration_set)),
                M::esc(&ecs),
                M::esc(&txt(&c.composite_type)),
            ];
            if show_host {
                row.push(M::esc(&txt(&c.path_uri)));
            }
            row
        })
        .collect();
    let mut heads = vec![
        lang.t("instance"),
        lang.t("component"),
        lang.t("sys_component_id"),
        lang.t("sys_version_drift"),
        lang.t("sys_active_set"),
        lang.t("sys_contexts"),
        lang.t("sys_composite"),
    ];
    if show_host {
        heads.push(lang.t("sys_path_uri"));
    }
    M::table(out, &heads, &rows);

    // Configuration used.
    let mut rows: Vec<Vec<String>> = Vec::new();
    for (i, c) in p.components.iter().enumerate() {
        let comp = cat.instance_component(s, i);
        for set in &c.configuration_sets {
            // An empty set says so (it is a value of the file, not nothing).
            if set.configuration_data.is_empty() {
                rows.push(vec![
                    M::esc(&txt(&c.instance_name)),
                    M::esc(&txt(&set.id)),
                    String::new(),
                    M::esc(lang.t("fact_none")),
                    String::new(),
                    String::new(),
                ]);
            }
            for d in &set.configuration_data {
                let n = txt(&d.name);
                let v = d.data.as_deref().unwrap_or("").to_string();
                let default = comp
                    .and_then(|k| {
                        k.profile
                            .configurations()
                            .iter()
                            .find(|x| x.name.as_deref().map(str::trim) == Some(n.trim()))
                    })
                    .and_then(|x| x.default_value.as_deref())
                    .unwrap_or("")
                    .to_string();
                let note = match comp {
                    _ if set.pseudo => lang.t("sys_pseudo").to_string(),
                    None => String::new(),
                    Some(k) => match check_configuration(k, &n, &v) {
                        ConfigCheck::Ok => String::new(),
                        ConfigCheck::Undeclared => lang.t("sys_undeclared").to_string(),
                        ConfigCheck::BadType(w) | ConfigCheck::Violated(w) => w,
                    },
                };
                let value = if !set.pseudo && comp.is_some() && default != v {
                    M::bold(&M::esc(&v))
                } else {
                    M::esc(&v)
                };
                rows.push(vec![
                    M::esc(&txt(&c.instance_name)),
                    M::esc(&txt(&set.id)),
                    M::esc(&n),
                    value,
                    M::esc(&default),
                    M::esc(&note),
                ]);
            }
        }
    }
    if !rows.is_empty() {
        (t.heading)(out, "configuration", lang.t("sys_configuration"));
        M::table(
            out,
            &[
                lang.t("instance"),
                lang.t("sys_set"),
                lang.t("name"),
                lang.t("value"),
                lang.t("sys_component_default"),
                lang.t("description"),
            ],
            &rows,
        );
    }

    // Connectors.
    (t.heading)(out, "data-connectors", lang.t("sys_data_connectors_h"));
    let rows: Vec<Vec<String>> = p
        .data_port_connectors
        .iter()
        .map(|c| {
            let ty = match non_empty(&c.data_type) {
                Some(x) => match cat.data_type_index(x) {
                    Some(d) => M::link(x, &M::page_target(cat, from, cat.data_type_page(d))),
                    None => M::esc(x),
                },
                None => String::new(),
            };
            vec![
                M::esc(&txt(&c.name)),
                M::esc(&end(&c.source)),
                M::esc(&end(&c.target)),
                ty,
                M::esc(&txt(&c.interface_type)),
                M::esc(&txt(&c.dataflow_type)),
                M::esc(&txt(&c.subscription_type)),
                M::esc(&txt(&c.push_interval)),
            ]
        })
        .collect();
    M::table(
        out,
        &[
            lang.t("sys_connector"),
            lang.t("sys_source"),
            lang.t("sys_target"),
            lang.t("type"),
            lang.t("sys_interface_type"),
            lang.t("sys_dataflow"),
            lang.t("sys_subscription"),
            lang.t("sys_push_interval"),
        ],
        &rows,
    );
    (t.heading)(
        out,
        "service-connectors",
        lang.t("sys_service_connectors_h"),
    );
    let rows: Vec<Vec<String>> = p
        .service_port_connectors
        .iter()
        .map(|c| {
            vec![
                M::esc(&txt(&c.name)),
                M::esc(&end(&c.source)),
                M::esc(&end(&c.target)),
                M::esc(&txt(&c.trans_method)),
            ]
        })
        .collect();
    M::table(
        out,
        &[
            lang.t("sys_connector"),
            lang.t("sys_source"),
            lang.t("sys_target"),
            lang.t("sys_trans_method"),
        ],
        &rows,
    );

    // Orders and groups.
    let mut rows: Vec<Vec<String>> = Vec::new();
    for o in &p.orders {
        for tg in &o.targets {
            let tc = tg.target_component.as_ref();
            let mut cond = Vec::new();
            if let Some(w) = &tg.wait_time {
                cond.push(format!("{} {} ms", lang.t("sys_wait"), txt(&w.wait_time)));
            }
            if let Some(pr) = &tg.preceding {
                let after: Vec<String> = pr
                    .preceding_components
                    .iter()
                    .map(|c| txt(&c.instance_name))
                    .collect();
                cond.push(format!("{} {}", lang.t("sys_after"), after.join(", ")));
            }
            rows.push(vec![
                M::esc(o.kind.xml_name()),
                M::esc(&txt(&tg.sequence)),
                M::esc(&tc.map(|c| txt(&c.instance_name)).unwrap_or_default()),
                M::esc(&tc.map(|c| txt(&c.id)).unwrap_or_default()),
                M::esc(&cond.join("; ")),
            ]);
        }
    }
    if !rows.is_empty() {
        (t.heading)(out, "orders", lang.t("sys_orders"));
        M::table(
            out,
            &[
                lang.t("sys_orders"),
                lang.t("sys_sequence"),
                lang.t("instance"),
                lang.t("sys_context"),
                lang.t("sys_condition"),
            ],
            &rows,
        );
    }
    if !p.groups.is_empty() {
        (t.heading)(out, "groups", lang.t("sys_groups"));
        let rows: Vec<Vec<String>> = p
            .groups
            .iter()
            .map(|g| {
                let m: Vec<String> = g.members.iter().map(|m| txt(&m.instance_name)).collect();
                vec![M::esc(&txt(&g.group_id)), M::esc(&m.join(", "))]
            })
            .collect();
        M::table(out, &[lang.t("sys_groups"), lang.t("sys_members")], &rows);
    }

    // Every value.
    (t.heading)(out, "all-values", lang.t("sys_all_values"));
    let rows: Vec<Vec<String>> = all_values(p, show_host)
        .into_iter()
        .map(|(k, v)| vec![M::esc(&k), M::esc(&v)])
        .collect();
    M::table(out, &[lang.t("extra_path"), lang.t("value")], &rows);
}

/// The systems using component `ci` as (system name and instances, system) for a list.
pub fn used_in(cat: &Catalog, ci: usize) -> Vec<(String, &System)> {
    cat.systems_using(ci)
        .into_iter()
        .map(|(s, names)| (format!("{} ({})", s.profile.name(), names.join(", ")), s))
        .collect()
}

/// The connectors carrying data type `name` as (text, system) for a list.
pub fn carrying<'a>(cat: &'a Catalog, name: &str) -> Vec<(String, &'a System)> {
    cat.connectors_carrying(name)
        .into_iter()
        .map(|(s, k)| {
            let c = &s.profile.data_port_connectors[k];
            (
                format!(
                    "{}: {} → {}",
                    s.profile.name(),
                    end(&c.source),
                    end(&c.target)
                ),
                s,
            )
        })
        .collect()
}
