//! Building blocks shared by the text renderers (Markdown and Doxygen).
//!
//! Both renderers lay out the same tables of [`Fact`]s and the same peer lists; they differ
//! only in how text is escaped, how a cross-reference is written and how a table looks, which
//! is what a [`Markup`] says.

use super::facts::{self, Fact};
use crate::catalog::{Catalog, InterfaceRef, Output, Page, PortRef};
use crate::i18n::Lang;
use crate::model::{self, ActionKind, Direction, PortDirection};

/// The code spans of a line of profile text, as HTML renders them (Markdown's single-backtick
/// spans): `(start, end)` char indices of each opening and closing backtick, the content
/// between them not blank, and free of `|` unless `pipes` (a Markdown table cell would split
/// at it). Every output shows them as code, so a profile's `` `count` `` reads the same
/// everywhere.
pub fn code_spans(chars: &[char], pipes: bool) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if chars[i] == '`' {
            if let Some(len) = chars[i + 1..].iter().position(|&c| c == '`') {
                let content = &chars[i + 1..i + 1 + len];
                if (pipes || !content.contains(&'|')) && content.iter().any(|c| !c.is_whitespace())
                {
                    out.push((i, i + 1 + len));
                    i += len + 2;
                    continue;
                }
            }
        }
        i += 1;
    }
    out
}

/// The syntax of one text output format.
pub trait Markup {
    /// The output whose pages this syntax writes: links come from [`Catalog::href`] for it.
    const OUTPUT: Output;
    /// Escapes plain text for an inline position (a table cell, a heading).
    fn esc(s: &str) -> String;
    /// A cross-reference with plain `text`; `target` (a URL or a label) is generated and safe.
    fn link(text: &str, target: &str) -> String;
    /// Bold text; `escaped` is already escaped.
    fn bold(escaped: &str) -> String;
    /// A table with plain-text `headers`; the cells of `rows` are already escaped.
    fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]);
    /// Inline code; `s` is a generated identifier.
    fn code(s: &str) -> String;
    /// A paragraph of already escaped text.
    fn paragraph(out: &mut String, escaped: &str);
    /// A bulleted list of plain-text items.
    fn list(out: &mut String, items: &[&str]);
    /// A heading of `level` (2 or 3) on `page`, with the stable `anchor`.
    fn heading(out: &mut String, page: &Page, level: usize, anchor: &str, text: &str);
    /// A table cell of already escaped text with the stable `anchor` of `page`.
    fn anchored(page: &Page, anchor: &str, escaped: &str) -> String;
    /// A link on page `from` to page `to` (a data type's or interface's), as a table cell.
    fn page_ref(cat: &Catalog, from: &Page, to: &Page) -> String;
    /// The target of a link on page `from` to page `to`, for [`Markup::link`].
    fn page_target(cat: &Catalog, from: &Page, to: &Page) -> String {
        cat.href(from, to, None, Self::OUTPUT)
    }
}

/// One port of a peer component: its component, the component's name, the port's label and
/// the link target from the page being written.
pub struct PeerPort {
    pub component: usize,
    pub component_name: String,
    pub port: String,
    pub target: String,
}

/// A data port peer, linked from page `from`.
pub fn port_peer<M: Markup>(cat: &Catalog, from: &Page, r: &PortRef) -> Option<PeerPort> {
    let (ci, port) = cat.resolve_port(r)?;
    let pc = &cat.components[ci];
    Some(PeerPort {
        component: ci,
        component_name: pc.profile.name().to_string(),
        port: model::non_empty(&pc.profile.data_ports[port].name)
            .unwrap_or("")
            .to_string(),
        target: cat.href(
            from,
            cat.component_page(ci),
            Some(&pc.anchors.data_ports[port]),
            M::OUTPUT,
        ),
    })
}

/// A service interface peer (`port / interface`), linked from page `from`.
pub fn iface_peer<M: Markup>(cat: &Catalog, from: &Page, r: &InterfaceRef) -> Option<PeerPort> {
    let (ci, port, interface) = cat.resolve_interface(r)?;
    let pc = &cat.components[ci];
    let sp = &pc.profile.service_ports[port];
    Some(PeerPort {
        component: ci,
        component_name: pc.profile.name().to_string(),
        port: format!(
            "{} / {}",
            model::non_empty(&sp.name).unwrap_or(""),
            model::non_empty(&sp.interfaces[interface].name).unwrap_or("")
        ),
        target: cat.href(
            from,
            cat.component_page(ci),
            Some(&pc.anchors.interfaces[port][interface]),
            M::OUTPUT,
        ),
    })
}

/// Facts as a two-column table (label, value).
pub fn facts_table<M: Markup>(out: &mut String, lang: Lang, facts: &[Fact]) {
    let rows: Vec<Vec<String>> = facts
        .iter()
        .map(|f| vec![M::esc(&f.label), M::esc(&f.value)])
        .collect();
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &rows);
}

/// A table whose columns from `keep` on are left out when they are empty in every row (a
/// component without units gets no Unit column).
fn sparse_table<M: Markup>(out: &mut String, keep: usize, headers: &[&str], rows: &[Vec<String>]) {
    let shown: Vec<usize> = (0..headers.len())
        .filter(|&i| i < keep || rows.iter().any(|r| r.get(i).is_some_and(|c| !c.is_empty())))
        .collect();
    if shown.len() == headers.len() {
        return M::table(out, headers, rows);
    }
    let heads: Vec<&str> = shown.iter().map(|&i| headers[i]).collect();
    let rows: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            shown
                .iter()
                .map(|&i| r.get(i).cloned().unwrap_or_default())
                .collect()
        })
        .collect();
    M::table(out, &heads, &rows);
}

/// Facts inside one cell: bold label, colon, value; one line each.
pub fn facts_cell<M: Markup>(facts: &[Fact]) -> String {
    let mut out = String::new();
    for (i, f) in facts.iter().enumerate() {
        if i > 0 {
            out.push_str("<br>");
        }
        out.push_str(&M::bold(&M::esc(&f.label)));
        out.push_str(": ");
        out.push_str(&M::esc(&f.value));
    }
    out
}

/// The "connects to" cell of a port of component `ci`, as the HTML site has it
/// ([`facts::peer_groups`]): the other components' ports grouped by component, one link each
/// (to its first port), at most [`facts::PEER_COMPONENTS_CAP`] components, then a link to the
/// type or interface page (`rest`) saying how many more there are.
pub fn peers_cell<M: Markup, R>(
    ci: usize,
    refs: &[R],
    component: impl Fn(&R) -> usize,
    resolve: impl Fn(&R) -> Option<PeerPort>,
    rest: Option<String>,
    more_key: &str,
    lang: Lang,
) -> String {
    // Grouped by the references' component handles first: only the groups shown are resolved.
    let (groups, total) = facts::peer_groups(ci, refs, component);
    let mut parts: Vec<String> = groups
        .iter()
        .filter_map(|(_, list)| {
            let ports: Vec<PeerPort> = list.iter().filter_map(|r| resolve(r)).collect();
            let first = ports.first()?;
            let names: Vec<&str> = ports.iter().map(|p| p.port.as_str()).collect();
            Some(M::link(
                &facts::peer_text(&first.component_name, &names, " · "),
                &first.target,
            ))
        })
        .collect();
    if total > groups.len() {
        let more = format!("+{} — {}", total - groups.len(), lang.t(more_key));
        parts.push(match rest {
            Some(target) => M::link(&more, &target),
            None => M::esc(&more),
        });
    }
    parts.join("<br>")
}

/// The neighbourhood section of component `ci` ([`crate::render::neighbourhood`]): a table by
/// port — the port, its type, `fed by` / `feeds` / `used by` / `uses`, and the neighbour
/// components, each linked, with a `+N` link to the type or interface page when capped; or
/// the sentence saying no component connects to it.
pub fn neighbourhood_section<M: Markup>(out: &mut String, cat: &Catalog, ci: usize, lang: Lang) {
    use crate::render::neighbourhood as nb;
    let page = cat.component_page(ci);
    M::heading(out, page, 2, "sec-neighbourhood", lang.t("neighbourhood"));
    let n = nb::neighbourhood(cat, ci);
    if n.is_empty() {
        M::paragraph(out, &M::esc(lang.t("neighbourhood_none")));
        return;
    }
    M::paragraph(out, &M::esc(lang.t("neighbourhood_intro")));
    let rows: Vec<Vec<String>> = nb::rows(cat, ci, &n)
        .iter()
        .map(|r| {
            let mut parts: Vec<String> = r
                .neighbours
                .iter()
                .map(|k| {
                    let names: Vec<&str> = k.ports.iter().map(String::as_str).collect();
                    M::link(
                        &facts::peer_text(&k.name, &names, " · "),
                        &cat.href(page, k.page, Some(k.anchor), M::OUTPUT),
                    )
                })
                .collect();
            if r.more > 0 {
                parts.push(M::link(
                    &nb::more_text(r, lang),
                    &M::page_target(cat, page, r.type_page),
                ));
            }
            vec![
                M::link(&r.port, &cat.href(page, page, Some(r.anchor), M::OUTPUT)),
                M::page_ref(cat, page, r.type_page),
                M::esc(lang.t(r.relation)),
                parts.join("<br>"),
            ]
        })
        .collect();
    M::table(
        out,
        &[
            lang.t("port"),
            lang.t("type"),
            lang.t("direction"),
            lang.t("connects_to"),
        ],
        &rows,
    );
}

/// The category and vendor facets of each component ([`Catalog::category_of_each`],
/// [`Catalog::vendor_of_each`]), computed once per render.
pub fn facets_of_each(cat: &Catalog) -> Vec<(usize, usize)> {
    cat.category_of_each()
        .into_iter()
        .zip(cat.vendor_of_each())
        .collect()
}

/// A category's display name; the empty category has a translated name.
pub fn category_name(name: &str, lang: Lang) -> String {
    if name.is_empty() {
        lang.t("fact_uncategorized").to_string()
    } else {
        name.to_string()
    }
}

/// The spellings and IDL files of a data type or interface as a facts table (nothing when
/// both are empty).
pub fn names_facts<M: Markup>(out: &mut String, lang: Lang, spellings: &[String], idl: &[String]) {
    let mut f = Vec::new();
    if !spellings.is_empty() {
        f.push(Fact::new(lang.t("fact_spellings"), spellings.join(", ")));
    }
    let idl = crate::catalog::idl_file_names(idl);
    if !idl.is_empty() {
        f.push(Fact::new(lang.t("fact_idl_files"), idl.join("\n")));
    }
    if !f.is_empty() {
        facts_table::<M>(out, lang, &f);
    }
}

/// Column headers of a component list.
pub fn component_cols(lang: Lang) -> [&'static str; 4] {
    [
        lang.t("name"),
        lang.t("description"),
        lang.t("vendor"),
        lang.t("version"),
    ]
}

fn esc_opt<M: Markup>(s: &Option<crate::model::Text>) -> String {
    model::non_empty(s).map(M::esc).unwrap_or_default()
}

/// The sections of a component page after its title and lead text: basic info, Document
/// Profile, data ports, service ports, configuration, lifecycle, system parameters, language,
/// properties, version history and extras — the same tables in every text format.
///
/// The vendor in the basic info links to the page of `vendor` ([`Catalog::vendor_of_each`]).
pub fn component_sections<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    ci: usize,
    vendor: usize,
    lang: Lang,
) {
    let c = &cat.components[ci];
    let p = &c.profile;
    let page = cat.component_page(ci);
    M::heading(out, page, 2, "sec-basic-info", lang.t("fact_basic_info"));
    let vendor_label = lang.t("vendor");
    let rows: Vec<Vec<String>> = facts::basic_info(c, lang)
        .iter()
        .map(|f| {
            let value = match cat.vendors.get(vendor) {
                Some(_) if f.label == vendor_label => M::link(
                    &f.value,
                    &M::page_target(cat, page, cat.vendor_page(vendor)),
                ),
                _ => M::esc(&f.value),
            };
            vec![M::esc(&f.label), value]
        })
        .collect();
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &rows);

    if let Some(doc) = &p.basic_info.doc {
        let f = facts::document(doc, lang);
        if !f.is_empty() {
            M::heading(out, page, 2, "sec-document", lang.t("fact_document"));
            facts_table::<M>(out, lang, &f);
        }
    }

    if !p.data_ports.is_empty() {
        M::heading(out, page, 2, "sec-data-ports", lang.t("data_ports"));
        let rows: Vec<Vec<String>> = p
            .data_ports
            .iter()
            .enumerate()
            .map(|(pi, port)| {
                let dir = match port.direction() {
                    Some(PortDirection::In) => M::esc(lang.t("in")),
                    Some(PortDirection::Out) => M::esc(lang.t("out")),
                    _ => esc_opt::<M>(&port.port_type),
                };
                let dt = port
                    .type_
                    .as_deref()
                    .and_then(|t| cat.data_type_index(t))
                    .map(|ti| cat.data_type_page(ti));
                let ty = match dt {
                    Some(to) => M::page_ref(cat, page, to),
                    None => esc_opt::<M>(&port.type_),
                };
                let desc = port
                    .doc
                    .as_ref()
                    .map(|d| esc_opt::<M>(&d.description))
                    .unwrap_or_default();
                let peers = cat.data_port_peers(ci, pi);
                let rest = dt.map(|to| M::page_target(cat, page, to));
                vec![
                    M::anchored(page, &c.anchors.data_ports[pi], &esc_opt::<M>(&port.name)),
                    dir,
                    ty,
                    desc,
                    facts_cell::<M>(&facts::data_port(port, lang)),
                    peers_cell::<M, _>(
                        ci,
                        peers,
                        |r| cat.port_component(r).unwrap_or(usize::MAX),
                        |r| port_peer::<M>(cat, page, r),
                        rest,
                        "more_on_type_page",
                        lang,
                    ),
                ]
            })
            .collect();
        sparse_table::<M>(
            out,
            3,
            &[
                lang.t("name"),
                lang.t("direction"),
                lang.t("data_type"),
                lang.t("description"),
                lang.t("fact_details"),
                lang.t("connects_to"),
            ],
            &rows,
        );
    }

    if !p.service_ports.is_empty() {
        M::heading(out, page, 2, "sec-service-ports", lang.t("service_ports"));
        for (si, sp) in p.service_ports.iter().enumerate() {
            M::heading(
                out,
                page,
                3,
                &c.anchors.service_ports[si],
                model::non_empty(&sp.name).unwrap_or("?"),
            );
            let pf = facts::service_port(sp, lang);
            if !pf.is_empty() {
                facts_table::<M>(out, lang, &pf);
            }
            if sp.interfaces.is_empty() {
                continue;
            }
            let rows: Vec<Vec<String>> = sp
                .interfaces
                .iter()
                .enumerate()
                .map(|(ii, i)| {
                    let dir = match i.direction_kind() {
                        Some(Direction::Provided) => M::esc(lang.t("provided")),
                        Some(Direction::Required) => M::esc(lang.t("required")),
                        None => esc_opt::<M>(&i.direction),
                    };
                    let it = i
                        .type_
                        .as_deref()
                        .and_then(|t| cat.interface_index_of(t))
                        .map(|ii| cat.interface_page(ii));
                    let ty = match it {
                        Some(to) => M::page_ref(cat, page, to),
                        None => esc_opt::<M>(&i.type_),
                    };
                    let desc = i
                        .doc
                        .as_ref()
                        .map(|d| esc_opt::<M>(&d.description))
                        .unwrap_or_default();
                    let peers = cat.interface_peers(ci, si, ii);
                    let rest = it.map(|to| M::page_target(cat, page, to));
                    vec![
                        M::anchored(page, &c.anchors.interfaces[si][ii], &esc_opt::<M>(&i.name)),
                        dir,
                        ty,
                        desc,
                        facts_cell::<M>(&facts::service_interface(i, lang)),
                        peers_cell::<M, _>(
                            ci,
                            peers,
                            |r| cat.interface_component(r).unwrap_or(usize::MAX),
                            |r| iface_peer::<M>(cat, page, r),
                            rest,
                            "more_on_interface_page",
                            lang,
                        ),
                    ]
                })
                .collect();
            sparse_table::<M>(
                out,
                3,
                &[
                    lang.t("interface"),
                    lang.t("direction"),
                    lang.t("type"),
                    lang.t("description"),
                    lang.t("fact_details"),
                    lang.t("connects_to"),
                ],
                &rows,
            );
        }
    }

    neighbourhood_section::<M>(out, cat, ci, lang);

    let confs = p.configurations();
    if !confs.is_empty() {
        M::heading(out, page, 2, "sec-configuration", lang.t("configuration"));
        let rows: Vec<Vec<String>> = confs
            .iter()
            .enumerate()
            .map(|(k, cf)| {
                vec![
                    M::anchored(page, &c.anchors.configurations[k], &esc_opt::<M>(&cf.name)),
                    esc_opt::<M>(&cf.type_),
                    esc_opt::<M>(&cf.default_value),
                    facts::configuration_unit(cf)
                        .map(M::esc)
                        .unwrap_or_default(),
                    facts::configuration_constraint(cf)
                        .map(|s| M::esc(&s))
                        .unwrap_or_default(),
                    cf.doc
                        .as_ref()
                        .map(|d| esc_opt::<M>(&d.description))
                        .unwrap_or_default(),
                    facts_cell::<M>(&facts::configuration(cf, lang)),
                ]
            })
            .collect();
        sparse_table::<M>(
            out,
            3,
            &[
                lang.t("name"),
                lang.t("type"),
                lang.t("default_value"),
                lang.t("unit"),
                lang.t("constraint"),
                lang.t("description"),
                lang.t("fact_details"),
            ],
            &rows,
        );
    }

    M::heading(out, page, 2, "sec-lifecycle", lang.t("actions"));
    let rows: Vec<Vec<String>> = ActionKind::ALL
        .iter()
        .map(|&k| {
            let a = p.action(k);
            let (d, pre, post) = facts::action_description(a);
            let implemented = match a {
                Some(a) if a.is_implemented() => lang.t("yes"),
                _ => lang.t("no"),
            };
            vec![
                M::code(k.callback_name()),
                M::esc(implemented),
                d.map(M::esc).unwrap_or_default(),
                pre.map(M::esc).unwrap_or_default(),
                post.map(M::esc).unwrap_or_default(),
            ]
        })
        .collect();
    sparse_table::<M>(
        out,
        2,
        &[
            lang.t("fact_callback"),
            lang.t("implemented"),
            lang.t("description"),
            lang.t("pre_condition"),
            lang.t("post_condition"),
        ],
        &rows,
    );

    if !p.parameters.is_empty() {
        M::heading(out, page, 2, "sec-system-parameters", lang.t("parameters"));
        let rows: Vec<Vec<String>> = p
            .parameters
            .iter()
            .map(|par| {
                let (n, v) = facts::parameter(par);
                vec![M::esc(n), M::esc(v)]
            })
            .collect();
        M::table(out, &[lang.t("name"), lang.t("default_value")], &rows);
    }

    if let Some(l) = &p.language {
        let lf = facts::language(l, lang);
        let targets: Vec<(usize, Vec<Fact>)> = l
            .targets
            .iter()
            .map(|t| facts::target(t, lang))
            .enumerate()
            .filter(|(_, f)| !f.is_empty())
            .collect();
        if !lf.is_empty() || !targets.is_empty() {
            M::heading(out, page, 2, "sec-language", lang.t("language"));
            if !lf.is_empty() {
                facts_table::<M>(out, lang, &lf);
            }
            for (ti, tf) in &targets {
                M::paragraph(
                    out,
                    &M::bold(&format!("{} {}", M::esc(lang.t("fact_target")), ti + 1)),
                );
                facts_table::<M>(out, lang, tf);
            }
        }
    }

    let props = facts::component_properties(p, lang);
    if !props.is_empty() {
        M::heading(out, page, 2, "sec-properties", lang.t("properties"));
        let rows: Vec<Vec<String>> = props
            .iter()
            .map(|f| vec![M::esc(&f.label), M::esc(&f.value)])
            .collect();
        M::table(out, &[lang.t("name"), lang.t("fact_value")], &rows);
    }

    let logs = facts::version_up_logs(p);
    if !logs.is_empty() {
        M::heading(
            out,
            page,
            2,
            "sec-version-history",
            lang.t("version_up_logs"),
        );
        M::list(out, &logs);
    }

    let backups = facts::BackupRow::of(c, lang);
    if !backups.is_empty() {
        M::heading(out, page, 2, "sec-backups", lang.t("backups"));
        M::paragraph(out, &M::esc(lang.t("backups_intro")));
        let rows: Vec<Vec<String>> = backups
            .iter()
            .map(|b| vec![M::code(&b.file), M::esc(&b.saved), M::esc(&b.declares)])
            .collect();
        M::table(
            out,
            &[
                lang.t("backup_file"),
                lang.t("backup_saved"),
                lang.t("backup_declares"),
            ],
            &rows,
        );
    }

    let extras = facts::extras(p);
    if !extras.is_empty() {
        M::heading(out, page, 2, "sec-extra", lang.t("extra"));
        facts_table::<M>(out, lang, &extras);
    }
}

/// The table of every data type with its producer, consumer and other counts; `name` makes
/// the first cell (a link to the type's page).
pub fn type_index_table<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    lang: Lang,
    name: impl Fn(&Page) -> String,
) {
    let rows: Vec<Vec<String>> = cat
        .data_types
        .iter()
        .enumerate()
        .map(|(ti, t)| {
            vec![
                name(cat.data_type_page(ti)),
                t.producers.len().to_string(),
                t.consumers.len().to_string(),
                t.others.len().to_string(),
            ]
        })
        .collect();
    M::table(
        out,
        &[
            lang.t("data_type"),
            lang.t("producers"),
            lang.t("consumers"),
            lang.t("fact_others"),
        ],
        &rows,
    );
}

/// The table of every interface with its provider, requirer and other counts, flagging
/// interfaces nobody provides; `name` makes the link to the interface's page.
pub fn interface_index_table<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    lang: Lang,
    name: impl Fn(&Page) -> String,
) {
    let rows: Vec<Vec<String>> = cat
        .interfaces
        .iter()
        .enumerate()
        .map(|(ii, t)| {
            let mut cell = name(cat.interface_page(ii));
            if t.is_unprovided() {
                cell.push_str(&format!(" ({})", M::esc(lang.t("not_provided"))));
            }
            vec![
                cell,
                t.providers.len().to_string(),
                t.requirers.len().to_string(),
                t.others.len().to_string(),
            ]
        })
        .collect();
    M::table(
        out,
        &[
            lang.t("interface"),
            lang.t("providers"),
            lang.t("requirers"),
            lang.t("fact_others"),
        ],
        &rows,
    );
}

/// The data-flow page's body for Markdown and Doxygen: the explanation, then for categories and
/// vendors a table of every flow between groups (the most port pairs first).
pub fn dataflow_body<M: Markup>(out: &mut String, cat: &Catalog, page: &Page, lang: Lang) {
    M::paragraph(out, &M::esc(lang.t("dataflow_intro")));
    for (grouping, anchor, key) in facts::DATAFLOW_SECTIONS {
        M::heading(out, page, 2, anchor, lang.t(key));
        let rows = facts::dataflow_rows(cat, grouping, lang);
        if rows.is_empty() {
            M::paragraph(out, &M::esc(lang.t("dataflow_none")));
            continue;
        }
        let cells: Vec<Vec<String>> = rows
            .iter()
            .map(|r| {
                let mut types: Vec<String> = r
                    .types
                    .iter()
                    .map(|(name, to)| M::link(name, &M::page_target(cat, page, to)))
                    .collect();
                if r.more_types > 0 {
                    types.push(M::esc(&format!("+{}", r.more_types)));
                }
                let group =
                    |(name, to): &(String, &Page)| M::link(name, &M::page_target(cat, page, to));
                vec![
                    group(&r.from),
                    group(&r.to),
                    r.pairs.to_string(),
                    types.join(", "),
                ]
            })
            .collect();
        M::table(
            out,
            &[
                lang.t("dataflow_from"),
                lang.t("dataflow_to"),
                lang.t("dataflow_pairs"),
                lang.t("data_types"),
            ],
            &cells,
        );
    }
}
