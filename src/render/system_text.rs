//! The body of an RT System's page in the text outputs (Markdown and Doxygen), written once
//! through the [`Markup`] of each: summary, instances, configuration used, connectors, orders,
//! groups and every value of the file. Host data is left out unless `show_host`, as on the HTML
//! pages.

use super::text::{pairs_table, Markup};
use super::view::system::{system_view, EndView, Link, SystemView};
use crate::catalog::systems::{end_port_name, System};
use crate::catalog::Catalog;
use crate::i18n::Lang;
use crate::model::system::PortEnd;
use crate::model::{non_empty, Text};

/// How a page links and heads its sections.
pub struct Targets<'a> {
    /// Writes a section heading: (out, anchor, text).
    pub heading: &'a dyn Fn(&mut String, &str, &str),
    /// The wiring diagram, shown in its section right after the summary (where the HTML page
    /// shows it).
    pub wiring: Wiring<'a>,
}

/// A system's wiring diagram in a text output: its section's heading, the drawing (an image
/// or a Mermaid block, which the output writes) and, under it, its notes (what the drawing
/// leaves out, what its outlines mean).
pub struct Wiring<'a> {
    pub caption: &'a str,
    pub drawing: &'a dyn Fn(&mut String),
    pub notes: &'a [String],
}

impl<'a> Targets<'a> {
    pub fn new(
        heading: &'a dyn Fn(&mut String, &str, &str),
        caption: &'a str,
        drawing: &'a dyn Fn(&mut String),
        notes: &'a [String],
    ) -> Self {
        Targets {
            heading,
            wiring: Wiring {
                caption,
                drawing,
                notes,
            },
        }
    }
}

/// The caption of a system's wiring diagram, in every output.
pub fn wiring_caption(s: &crate::catalog::systems::System, lang: Lang) -> String {
    format!("{} {}", lang.t("sys_wiring"), s.display_name())
}

fn wiring_section<M: Markup>(out: &mut String, t: &Targets<'_>) {
    let w = &t.wiring;
    (t.heading)(out, "sec-wiring", w.caption);
    (w.drawing)(out);
    for n in w.notes {
        M::paragraph(out, &M::esc(&format!("{n}.")));
    }
}

fn txt(v: &Option<Text>) -> String {
    non_empty(v).unwrap_or("").to_string()
}

fn end(e: &Option<PortEnd>) -> String {
    e.as_ref()
        .map(|e| format!("{}.{}", txt(&e.instance_name), end_port_name(e)))
        .unwrap_or_default()
}

/// A view link as text of `M`: linked when it has a target.
fn link<M: Markup>(l: &Link) -> String {
    if l.href.is_empty() {
        M::esc(&l.text)
    } else {
        M::link(&l.text, &l.href)
    }
}

/// A connector end as text: `instance.port`, the port linked to its component's row.
fn end_text<M: Markup>(e: &EndView) -> String {
    let port = link::<M>(&e.port);
    match &e.instance {
        Some(i) => format!("{}.{port}", M::esc(&i.text)),
        None => port,
    }
}

/// Writes the sections of system `s`'s page (`from`, for its links) from its view
/// ([`system_view`]), the same values the HTML page shows; `site` is (show host data, the
/// `source-url` template).
pub fn system_body<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    s: &System,
    lang: Lang,
    site: (bool, Option<&str>),
    t: &Targets<'_>,
) {
    let show_host = site.0;
    let v = system_view(cat, s, lang, site, M::OUTPUT);
    let p = &s.profile;
    let source_label = lang.t("source");
    let mut facts: Vec<Vec<String>> = v
        .summary
        .iter()
        .map(|kv| match &v.source_url {
            Some(url) if kv.key == source_label => vec![M::esc(&kv.key), M::link(&kv.value, url)],
            _ => vec![M::esc(&kv.key), M::esc(&kv.value)],
        })
        .chain(
            v.properties
                .iter()
                .map(|kv| vec![M::esc(&kv.key), M::esc(&kv.value)]),
        )
        .collect();
    for l in &p.version_up_logs {
        facts.push(vec![M::esc(lang.t("version_up_logs")), M::esc(l)]);
    }
    for x in &p.systems {
        facts.push(vec![
            M::esc(lang.t("sys_subsystems")),
            M::esc(&txt(&x.path)),
        ]);
    }
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &facts);
    if v.hidden > 0 {
        M::paragraph(
            out,
            &M::esc(&format!("{} {}", v.hidden, lang.t("sys_host_hidden"))),
        );
    }
    wiring_section::<M>(out, t);
    instances::<M>(out, &v, lang, show_host, t);
    configuration::<M>(out, &v, lang, t);
    connectors::<M>(out, &v, lang, t);
    orders_and_groups::<M>(out, &v, lang, t);
    if !v.history.rows.is_empty() {
        (t.heading)(out, "change-history", lang.t("change_history"));
        let here = cat.page_of_system(s);
        let full = here
            .zip(v.history_page.as_ref())
            .map(|(from, to)| (cat, from, to));
        let intro = lang.t("history_intro_system");
        super::text::history_body::<M>(out, &v.history, intro, full, lang);
    }
    (t.heading)(out, "all-values", lang.t("sys_all_values"));
    let pairs = v.all_values.iter().map(|kv| (&kv.key, &kv.value));
    pairs_table::<M, _, _>(out, [lang.t("extra_path"), lang.t("value")], pairs);
}

fn instances<M: Markup>(
    out: &mut String,
    v: &SystemView,
    lang: Lang,
    show_host: bool,
    t: &Targets<'_>,
) {
    (t.heading)(out, "instances", lang.t("instances"));
    let cols = v.comment_columns();
    let rows: Vec<Vec<String>> = v
        .instances
        .iter()
        .map(|r| {
            let mut row = vec![
                M::esc(&r.name),
                r.component
                    .as_ref()
                    .map(link::<M>)
                    .unwrap_or_else(|| M::esc(lang.t("sys_not_in_catalogue"))),
                M::esc(&r.id),
                r.drift
                    .as_ref()
                    .map(|d| M::esc(&format!("{} {d}", lang.t("sys_drift"))))
                    .unwrap_or_default(),
                M::esc(&r.active_set),
                M::esc(&r.contexts),
                M::esc(&r.required),
                M::esc(&composite_text(r, lang)),
            ];
            if cols.instances {
                row.push(M::esc(&r.comment));
            }
            if show_host {
                row.push(M::esc(&r.path_uri));
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
        lang.t("sys_required"),
        lang.t("sys_composite"),
    ];
    if cols.instances {
        heads.push(lang.t("comment"));
    }
    if show_host {
        heads.push(lang.t("sys_path_uri"));
    }
    M::table(out, &heads, &rows);
}

/// The composite type of an instance with its members (`PeriodicECShared; Members: A0, B0`)
/// or the composites it is a member of (`None; member of CompositeRTC`).
fn composite_text(r: &super::view::system::InstanceRow, lang: Lang) -> String {
    let mut parts = vec![r.composite.clone()];
    let names = |l: &[Link]| {
        l.iter()
            .map(|x| x.text.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if !r.members.is_empty() {
        parts.push(format!("{}: {}", lang.t("sys_members"), names(&r.members)));
    }
    if !r.member_of.is_empty() {
        parts.push(format!(
            "{} {}",
            lang.t("sys_member_of"),
            names(&r.member_of)
        ));
    }
    parts.retain(|p| !p.is_empty());
    parts.join("; ")
}

fn configuration<M: Markup>(out: &mut String, v: &SystemView, lang: Lang, t: &Targets<'_>) {
    let mut rows: Vec<Vec<String>> = Vec::new();
    for ic in &v.configs {
        for set in &ic.sets {
            let id = M::esc(&set.id);
            // An empty set says so (it is a value of the file, not nothing).
            if set.rows.is_empty() {
                rows.push(vec![
                    M::esc(&ic.instance),
                    id.clone(),
                    String::new(),
                    M::esc(lang.t("fact_none")),
                    String::new(),
                    String::new(),
                ]);
            }
            for r in &set.rows {
                let value = if r.differs {
                    M::bold(&M::esc(&r.value))
                } else {
                    M::esc(&r.value)
                };
                let note = if set.pseudo {
                    lang.t("sys_pseudo").to_string()
                } else {
                    r.note.clone()
                };
                rows.push(vec![
                    M::esc(&ic.instance),
                    id.clone(),
                    M::esc(&r.name),
                    value,
                    M::esc(&r.default),
                    M::esc(&note),
                ]);
            }
        }
    }
    if rows.is_empty() {
        return;
    }
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

/// A section of connectors: the heading `(anchor, title key)`, then a table of the connectors
/// in `rows`: their name (with a note, such as how the file saved a connector it saved
/// in-port first), id, source and target, then the cells of `rest` under the headers keyed
/// `rest_keys`.
fn connector_table<'a, M: Markup>(
    out: &mut String,
    lang: Lang,
    t: &Targets<'_>,
    (anchor, title): (&str, &str),
    rest_keys: &[&str],
    rows: impl Iterator<Item = ([&'a str; 2], Option<&'a str>, [&'a EndView; 2], Vec<String>)>,
) {
    (t.heading)(out, anchor, lang.t(title));
    let rows: Vec<Vec<String>> = rows
        .map(|([name, id], note, [source, target], rest)| {
            let name = match note {
                Some(n) => M::esc(&format!("{name} ({n})")),
                None => M::esc(name),
            };
            let mut row = vec![
                name,
                M::esc(id),
                end_text::<M>(source),
                end_text::<M>(target),
            ];
            row.extend(rest);
            row
        })
        .collect();
    if rows.is_empty() {
        // As the HTML page: the heading, then a dash (not a table of headers only).
        M::paragraph(out, "—");
        return;
    }
    let headers: Vec<&str> = [
        "sys_connector",
        "sys_connector_id",
        "sys_source",
        "sys_target",
    ]
    .iter()
    .chain(rest_keys)
    .map(|k| lang.t(k))
    .collect();
    M::table(out, &headers, &rows);
}

fn connectors<M: Markup>(out: &mut String, v: &SystemView, lang: Lang, t: &Targets<'_>) {
    let cols = v.comment_columns();
    // The Comment column, last, only when some row has a comment.
    let keys =
        |all: &'static [&'static str], comment: bool| &all[..all.len() - usize::from(!comment)];
    connector_table::<M>(
        out,
        lang,
        t,
        ("data-connectors", "sys_data_connectors_h"),
        keys(
            &[
                "type",
                "sys_interface_type",
                "sys_dataflow",
                "sys_subscription",
                "sys_push_interval",
                "comment",
            ],
            cols.data,
        ),
        v.data_connectors.iter().map(|c| {
            let mut rest = vec![
                c.data_type.as_ref().map(link::<M>).unwrap_or_default(),
                M::esc(&c.interface_type),
                M::esc(&c.dataflow_type),
                M::esc(&c.subscription_type),
                M::esc(&c.push_interval),
            ];
            if cols.data {
                rest.push(M::esc(&c.comment));
            }
            let note = c.saved_as.as_deref();
            ([&*c.name, &*c.id], note, [&c.source, &c.target], rest)
        }),
    );
    connector_table::<M>(
        out,
        lang,
        t,
        ("service-connectors", "sys_service_connectors_h"),
        keys(&["interfaces", "sys_trans_method", "comment"], cols.service),
        v.service_connectors.iter().map(|c| {
            let ifaces: Vec<String> = c.interfaces.iter().map(link::<M>).collect();
            let mut rest = vec![ifaces.join(", "), M::esc(&c.trans_method)];
            if cols.service {
                rest.push(M::esc(&c.comment));
            }
            ([&*c.name, &*c.id], None, [&c.source, &c.target], rest)
        }),
    );
}

fn orders_and_groups<M: Markup>(out: &mut String, v: &SystemView, lang: Lang, t: &Targets<'_>) {
    let rows: Vec<Vec<String>> = v
        .orders
        .iter()
        .flat_map(|o| {
            o.targets.iter().map(move |r| {
                vec![
                    M::esc(o.kind),
                    M::esc(&r.sequence),
                    M::esc(&r.instance),
                    M::esc(&r.context),
                    M::esc(&r.condition),
                ]
            })
        })
        .collect();
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
    if !v.groups.is_empty() {
        (t.heading)(out, "groups", lang.t("sys_groups"));
        let pairs = v.groups.iter().map(|g| (&g.id, g.members.join(", ")));
        pairs_table::<M, _, _>(out, [lang.t("sys_groups"), lang.t("sys_members")], pairs);
    }
}

/// The connectors carrying data type `name` as (text, system) for a list, each from its
/// out-port to its in-port ([`Catalog::reversed_data_connectors`]).
pub fn carrying<'a>(cat: &'a Catalog, name: &str) -> Vec<(String, &'a System)> {
    // The connectors come system by system: each system's directions are found once.
    let mut reversed: Option<(&System, Vec<bool>)> = None;
    cat.connectors_carrying(name)
        .into_iter()
        .map(|(s, k)| {
            let c = &s.profile.data_port_connectors[k];
            if !reversed.as_ref().is_some_and(|r| std::ptr::eq(r.0, s)) {
                reversed = Some((s, cat.reversed_data_connectors(s)));
            }
            let turned = reversed
                .as_ref()
                .is_some_and(|r| r.1.get(k).copied().unwrap_or(false));
            let (from, to) = if turned {
                (&c.target, &c.source)
            } else {
                (&c.source, &c.target)
            };
            (
                format!("{}: {} → {}", s.display_name(), end(from), end(to)),
                s,
            )
        })
        .collect()
}
