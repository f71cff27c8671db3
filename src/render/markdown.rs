//! GitHub-flavoured Markdown output that is also a valid mdBook `src/` folder.
//!
//! Layout (all links relative, `.md`):
//! - `index.md` — the catalogue (components by category, links to the type and interface
//!   indexes); `README.md` is the same page, for GitHub's folder view (it is not in the book);
//! - `SUMMARY.md` — the mdBook table of contents: components nested under their category page,
//!   data types under the type index, interfaces under the interface index;
//! - `categories/<slug>.md`, `components/<slug>.md`, `types.md`, `types/<slug>.md`,
//!   `interfaces.md`, `interfaces/<slug>.md` (the indexes sit at the root so that no type slug
//!   can collide with them).
//!
//! Rows carry explicit `<a id="…"></a>` anchors from [`Component::anchors`], so links never
//! depend on a Markdown engine's heading-id rules. All profile text goes through [`inline`] or
//! [`block`]: it can neither break a table nor inject HTML, links, images or mdBook directives.

use super::facts;
use super::text::{
    category_name, component_cols, facts_cell, facts_table, names_facts, peers_cell, Markup,
};
use super::{RenderContext, Renderer};
use crate::catalog::{Catalog, Component, InterfaceRef, PortRef};
use crate::i18n::Lang;
use crate::model::{self, ActionKind, Direction, PortDirection};
use crate::output::Sink;
use rayon::prelude::*;
use std::fmt::Write as _;

/// At most this many "connects to" peers are listed per port (shared with Doxygen).
pub use super::text::PEER_CAP;

/// Writes the Markdown pages.
pub struct MarkdownRenderer;

/// `writeln!` into a `String`, which cannot fail.
macro_rules! w {
    ($dst:expr) => { $dst.push('\n') };
    ($dst:expr, $($arg:tt)*) => { let _ = writeln!($dst, $($arg)*); };
}

/// Escapes one character of profile text for Markdown; `None` when it is safe as is.
fn escape_char(ch: char) -> Option<&'static str> {
    Some(match ch {
        '\\' => "\\\\",
        '`' => "\\`",
        '*' => "\\*",
        '_' => "\\_",
        '[' => "\\[",
        ']' => "\\]",
        '|' => "\\|",
        '#' => "\\#",
        '~' => "\\~",
        '!' => "\\!",
        '$' => "\\$",
        '<' => "&lt;",
        '>' => "&gt;",
        '&' => "&amp;",
        // `{{#include …}}` and friends are mdBook directives.
        '{' => "&#123;",
        '}' => "&#125;",
        _ => return None,
    })
}

/// Escapes one line; a leading list, heading-underline or ordered-list marker is neutralised.
fn escape_line(line: &str, out: &mut String) {
    let line = line.trim_start();
    let chars: Vec<char> = line.chars().collect();
    let digits = chars.iter().take_while(|c| c.is_ascii_digit()).count();
    // `1.` / `1)` start an ordered list only when followed by white space or the end.
    let ordered = (1..=9).contains(&digits)
        && matches!(chars.get(digits), Some('.' | ')'))
        && chars.get(digits + 1).is_none_or(|c| c.is_whitespace());
    for (i, &ch) in chars.iter().enumerate() {
        let at_marker = (i == 0 && matches!(ch, '-' | '+' | '=')) || (ordered && i == digits);
        if at_marker {
            out.push('\\');
            out.push(ch);
        } else if let Some(e) = escape_char(ch) {
            out.push_str(e);
        } else if ch == '\t' {
            out.push(' ');
        } else if !ch.is_control() {
            out.push(ch);
        }
    }
}

/// Escapes profile text for an inline context (table cell, heading, link text, list item):
/// one physical line; line breaks become `<br>`.
pub fn inline(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 8);
    let s = s.trim();
    for (i, line) in s.lines().enumerate() {
        if i > 0 {
            out.push_str("<br>");
        }
        escape_line(line.trim_end(), &mut out);
    }
    out
}

/// Escapes free text (a description) as Markdown paragraphs: blank lines separate paragraphs,
/// other line breaks are kept as `<br>`.
pub fn block(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 8);
    let norm = s.replace("\r\n", "\n").replace('\r', "\n");
    let mut para: Vec<&str> = Vec::new();
    fn flush(para: &mut Vec<&str>, out: &mut String) {
        if para.is_empty() {
            return;
        }
        if !out.is_empty() {
            out.push_str("\n\n");
        }
        for (i, l) in para.iter().enumerate() {
            if i > 0 {
                out.push_str("<br>\n");
            }
            escape_line(l.trim_end(), out);
        }
        para.clear();
    }
    for line in norm.lines() {
        if line.trim().is_empty() {
            flush(&mut para, &mut out);
        } else {
            para.push(line);
        }
    }
    flush(&mut para, &mut out);
    out
}

/// A Markdown link with escaped text; `href` is generated (slugs, anchors) and safe.
fn link(text: &str, href: &str) -> String {
    format!("[{}]({href})", inline(text))
}

/// Markdown syntax for the shared [`super::text`] helpers.
struct Md;

impl Markup for Md {
    fn esc(s: &str) -> String {
        inline(s)
    }
    fn link(text: &str, target: &str) -> String {
        link(text, target)
    }
    fn bold(escaped: &str) -> String {
        format!("**{escaped}**")
    }
    fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]) {
        table(out, headers, rows)
    }
}

/// A GFM table; cells are already escaped. An empty cell becomes a space.
fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]) {
    let head: Vec<String> = headers.iter().map(|h| inline(h)).collect();
    w!(out, "| {} |", head.join(" | "));
    w!(out, "|{}", "---|".repeat(headers.len()));
    for r in rows {
        let cells: Vec<&str> = r
            .iter()
            .map(|c| if c.is_empty() { " " } else { c.as_str() })
            .collect();
        w!(out, "| {} |", cells.join(" | "));
    }
    w!(out);
}

/// A section heading with a stable explicit anchor before it.
fn heading(out: &mut String, level: usize, anchor: &str, text: &str) {
    w!(out, "<a id=\"{anchor}\"></a>");
    w!(out);
    w!(out, "{} {}", "#".repeat(level), inline(text));
    w!(out);
}

fn opt(s: &Option<String>) -> String {
    model::non_empty(s).map(inline).unwrap_or_default()
}

fn component_href(c: &Component) -> String {
    format!("../components/{}.md", c.slug)
}

/// The category facet slug of a component (every component is in exactly one facet).
fn category_slugs(cat: &Catalog) -> Vec<usize> {
    let mut of = vec![0; cat.components.len()];
    for (fi, f) in cat.categories.iter().enumerate() {
        for &ci in &f.components {
            of[ci] = fi;
        }
    }
    of
}

/// A data port peer as (text, link).
fn port_peer(cat: &Catalog, r: &PortRef) -> (String, String) {
    let pc = &cat.components[r.component];
    let pn = model::non_empty(&pc.profile.data_ports[r.port].name).unwrap_or("");
    (
        format!("{} / {pn}", pc.profile.name()),
        format!("{}#{}", component_href(pc), pc.anchors.data_ports[r.port]),
    )
}

/// A service interface peer as (text, link).
fn iface_peer(cat: &Catalog, r: &InterfaceRef) -> (String, String) {
    let pc = &cat.components[r.component];
    let sp = &pc.profile.service_ports[r.port];
    let iname = model::non_empty(&sp.interfaces[r.interface].name).unwrap_or("");
    (
        format!(
            "{} / {} / {iname}",
            pc.profile.name(),
            model::non_empty(&sp.name).unwrap_or("")
        ),
        format!(
            "{}#{}",
            component_href(pc),
            pc.anchors.interfaces[r.port][r.interface]
        ),
    )
}

fn component_page(cat: &Catalog, ci: usize, cat_slug: &str, title: &str, lang: Lang) -> String {
    let c = &cat.components[ci];
    let p = &c.profile;
    let mut out = String::with_capacity(4096);
    w!(out, "# {}", inline(p.name()));
    w!(out);
    let category = model::non_empty(&p.basic_info.category).unwrap_or("");
    w!(
        out,
        "{} › {}",
        link(title, "../index.md"),
        link(
            &category_name(category, lang),
            &format!("../categories/{cat_slug}.md")
        )
    );
    w!(out);
    if let Some(d) = model::non_empty(&p.basic_info.description) {
        w!(out, "{}", block(d));
        w!(out);
    }

    heading(&mut out, 2, "sec-basic-info", lang.t("fact_basic_info"));
    facts_table::<Md>(&mut out, lang, &facts::basic_info(c, lang));

    if let Some(doc) = &p.basic_info.doc {
        let f = facts::document(doc, lang);
        if !f.is_empty() {
            heading(&mut out, 2, "sec-document", lang.t("fact_document"));
            facts_table::<Md>(&mut out, lang, &f);
        }
    }

    if !p.data_ports.is_empty() {
        heading(&mut out, 2, "sec-data-ports", lang.t("data_ports"));
        let rows: Vec<Vec<String>> = p
            .data_ports
            .iter()
            .enumerate()
            .map(|(pi, port)| {
                let dir = match port.direction() {
                    Some(PortDirection::In) => lang.t("in").to_string(),
                    Some(PortDirection::Out) => lang.t("out").to_string(),
                    _ => opt(&port.port_type),
                };
                let ty = match port.type_.as_deref().and_then(|t| cat.data_type(t)) {
                    Some(t) => link(&t.name, &format!("../types/{}.md", t.slug)),
                    None => opt(&port.type_),
                };
                let desc = port
                    .doc
                    .as_ref()
                    .map(|d| opt(&d.description))
                    .unwrap_or_default();
                let peers: Vec<(String, String)> = cat
                    .data_port_peers(ci, pi)
                    .iter()
                    .map(|r| port_peer(cat, r))
                    .collect();
                let rest = port
                    .type_
                    .as_deref()
                    .and_then(|t| cat.data_type(t))
                    .map(|t| format!("../types/{}.md", t.slug));
                vec![
                    format!(
                        "<a id=\"{}\"></a>{}",
                        c.anchors.data_ports[pi],
                        opt(&port.name)
                    ),
                    dir,
                    ty,
                    desc,
                    facts_cell::<Md>(&facts::data_port(port, lang)),
                    peers_cell::<Md>(peers, rest, lang),
                ]
            })
            .collect();
        table(
            &mut out,
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
        heading(&mut out, 2, "sec-service-ports", lang.t("service_ports"));
        for (si, sp) in p.service_ports.iter().enumerate() {
            heading(
                &mut out,
                3,
                &c.anchors.service_ports[si],
                model::non_empty(&sp.name).unwrap_or("?"),
            );
            let pf = facts::service_port(sp, lang);
            if !pf.is_empty() {
                facts_table::<Md>(&mut out, lang, &pf);
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
                        Some(Direction::Provided) => lang.t("provided").to_string(),
                        Some(Direction::Required) => lang.t("required").to_string(),
                        None => opt(&i.direction),
                    };
                    let ty = match i.type_.as_deref().and_then(|t| cat.interface(t)) {
                        Some(t) => link(&t.name, &format!("../interfaces/{}.md", t.slug)),
                        None => opt(&i.type_),
                    };
                    let desc = i
                        .doc
                        .as_ref()
                        .map(|d| opt(&d.description))
                        .unwrap_or_default();
                    let peers: Vec<(String, String)> = cat
                        .interface_peers(ci, si, ii)
                        .iter()
                        .map(|r| iface_peer(cat, r))
                        .collect();
                    let rest = i
                        .type_
                        .as_deref()
                        .and_then(|t| cat.interface(t))
                        .map(|t| format!("../interfaces/{}.md", t.slug));
                    vec![
                        format!(
                            "<a id=\"{}\"></a>{}",
                            c.anchors.interfaces[si][ii],
                            opt(&i.name)
                        ),
                        dir,
                        ty,
                        desc,
                        facts_cell::<Md>(&facts::service_interface(i, lang)),
                        peers_cell::<Md>(peers, rest, lang),
                    ]
                })
                .collect();
            table(
                &mut out,
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

    let confs = p.configurations();
    if !confs.is_empty() {
        heading(&mut out, 2, "sec-configuration", lang.t("configuration"));
        let rows: Vec<Vec<String>> = confs
            .iter()
            .enumerate()
            .map(|(k, cf)| {
                vec![
                    format!(
                        "<a id=\"{}\"></a>{}",
                        c.anchors.configurations[k],
                        opt(&cf.name)
                    ),
                    opt(&cf.type_),
                    opt(&cf.default_value),
                    opt(&cf.unit),
                    facts::configuration_constraint(cf)
                        .map(|s| inline(&s))
                        .unwrap_or_default(),
                    cf.doc
                        .as_ref()
                        .map(|d| opt(&d.description))
                        .unwrap_or_default(),
                    facts_cell::<Md>(&facts::configuration(cf, lang)),
                ]
            })
            .collect();
        table(
            &mut out,
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

    heading(&mut out, 2, "sec-lifecycle", lang.t("actions"));
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
                format!("`{}`", k.callback_name()),
                implemented.to_string(),
                d.map(inline).unwrap_or_default(),
                pre.map(inline).unwrap_or_default(),
                post.map(inline).unwrap_or_default(),
            ]
        })
        .collect();
    table(
        &mut out,
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
        heading(&mut out, 2, "sec-system-parameters", lang.t("parameters"));
        let rows: Vec<Vec<String>> = p
            .parameters
            .iter()
            .map(|par| {
                let (n, v) = facts::parameter(par);
                vec![inline(n), inline(v)]
            })
            .collect();
        table(&mut out, &[lang.t("name"), lang.t("default_value")], &rows);
    }

    if let Some(l) = &p.language {
        let lf = facts::language(l, lang);
        if !lf.is_empty() || !l.targets.is_empty() {
            heading(&mut out, 2, "sec-language", lang.t("language"));
            if !lf.is_empty() {
                facts_table::<Md>(&mut out, lang, &lf);
            }
            for (ti, t) in l.targets.iter().enumerate() {
                let tf = facts::target(t, lang);
                if tf.is_empty() {
                    continue;
                }
                w!(out, "**{} {}**", inline(lang.t("fact_target")), ti + 1);
                w!(out);
                facts_table::<Md>(&mut out, lang, &tf);
            }
        }
    }

    let props = facts::component_properties(p, lang);
    if !props.is_empty() {
        heading(&mut out, 2, "sec-properties", lang.t("properties"));
        let rows: Vec<Vec<String>> = props
            .iter()
            .map(|f| vec![inline(&f.label), inline(&f.value)])
            .collect();
        table(&mut out, &[lang.t("name"), lang.t("fact_value")], &rows);
    }

    let logs = facts::version_up_logs(p);
    if !logs.is_empty() {
        heading(
            &mut out,
            2,
            "sec-version-history",
            lang.t("version_up_logs"),
        );
        for l in logs {
            w!(out, "- {}", inline(l));
        }
        w!(out);
    }

    let extras = facts::extras(p);
    if !extras.is_empty() {
        heading(&mut out, 2, "sec-extra", lang.t("extra"));
        facts_table::<Md>(&mut out, lang, &extras);
    }
    out
}

fn port_ref_rows(cat: &Catalog, refs: &[PortRef]) -> Vec<Vec<String>> {
    refs.iter()
        .map(|r| {
            let c = &cat.components[r.component];
            let port = &c.profile.data_ports[r.port];
            vec![
                link(c.profile.name(), &component_href(c)),
                link(
                    model::non_empty(&port.name).unwrap_or("?"),
                    &format!("{}#{}", component_href(c), c.anchors.data_ports[r.port]),
                ),
                opt(&port.type_),
            ]
        })
        .collect()
}

fn iface_ref_rows(cat: &Catalog, refs: &[InterfaceRef]) -> Vec<Vec<String>> {
    refs.iter()
        .map(|r| {
            let c = &cat.components[r.component];
            let sp = &c.profile.service_ports[r.port];
            let i = &sp.interfaces[r.interface];
            vec![
                link(c.profile.name(), &component_href(c)),
                link(
                    &format!(
                        "{} / {}",
                        model::non_empty(&sp.name).unwrap_or("?"),
                        model::non_empty(&i.name).unwrap_or("?")
                    ),
                    &format!(
                        "{}#{}",
                        component_href(c),
                        c.anchors.interfaces[r.port][r.interface]
                    ),
                ),
                opt(&i.type_),
            ]
        })
        .collect()
}

fn type_page(cat: &Catalog, ti: usize, title: &str, lang: Lang) -> String {
    let t = &cat.data_types[ti];
    let mut out = String::new();
    w!(out, "# {}", inline(&t.name));
    w!(out);
    w!(
        out,
        "{} › {}",
        link(title, "../index.md"),
        link(lang.t("data_types"), "../types.md")
    );
    w!(out);
    names_facts::<Md>(&mut out, lang, &t.spellings, &t.idl_files);
    let cols = [lang.t("component"), lang.t("fact_port"), lang.t("type")];
    for (anchor, key, refs) in [
        ("sec-producers", "producers", &t.producers),
        ("sec-consumers", "consumers", &t.consumers),
        ("sec-others", "fact_others", &t.others),
    ] {
        if refs.is_empty() {
            continue;
        }
        heading(&mut out, 2, anchor, lang.t(key));
        table(&mut out, &cols, &port_ref_rows(cat, refs));
    }
    out
}

fn interface_page(cat: &Catalog, ii: usize, title: &str, lang: Lang) -> String {
    let t = &cat.interfaces[ii];
    let mut out = String::new();
    w!(out, "# {}", inline(&t.name));
    w!(out);
    w!(
        out,
        "{} › {}",
        link(title, "../index.md"),
        link(lang.t("interfaces"), "../interfaces.md")
    );
    w!(out);
    if t.is_unprovided() {
        w!(out, "> **{}**", inline(lang.t("not_provided")));
        w!(out);
    }
    names_facts::<Md>(&mut out, lang, &t.spellings, &t.idl_files);
    let cols = [lang.t("component"), lang.t("fact_port"), lang.t("type")];
    for (anchor, key, refs) in [
        ("sec-providers", "providers", &t.providers),
        ("sec-requirers", "requirers", &t.requirers),
        ("sec-others", "fact_others", &t.others),
    ] {
        if refs.is_empty() {
            continue;
        }
        heading(&mut out, 2, anchor, lang.t(key));
        table(&mut out, &cols, &iface_ref_rows(cat, refs));
    }
    out
}

fn component_rows(cat: &Catalog, members: &[usize], prefix: &str) -> Vec<Vec<String>> {
    members
        .iter()
        .map(|&ci| {
            let c = &cat.components[ci];
            let b = &c.profile.basic_info;
            vec![
                link(
                    c.profile.name(),
                    &format!("{prefix}components/{}.md", c.slug),
                ),
                opt(&b.description),
                opt(&b.vendor),
                opt(&b.version),
            ]
        })
        .collect()
}

fn index_page(cat: &Catalog, title: &str, lang: Lang) -> String {
    let mut out = String::new();
    w!(out, "# {}", inline(title));
    w!(out);
    w!(
        out,
        "{}: {} · {}: {} · {}: {}",
        inline(lang.t("components")),
        cat.components.len(),
        link(lang.t("data_types"), "types.md"),
        cat.data_types.len(),
        link(lang.t("interfaces"), "interfaces.md"),
        cat.interfaces.len()
    );
    w!(out);
    heading(&mut out, 2, "sec-components", lang.t("components"));
    for f in &cat.categories {
        w!(
            out,
            "### {}",
            link(
                &category_name(&f.name, lang),
                &format!("categories/{}.md", f.slug)
            )
        );
        w!(out);
        table(
            &mut out,
            &component_cols(lang),
            &component_rows(cat, &f.components, ""),
        );
    }
    out
}

fn category_page(cat: &Catalog, fi: usize, title: &str, lang: Lang) -> String {
    let f = &cat.categories[fi];
    let mut out = String::new();
    w!(out, "# {}", inline(&category_name(&f.name, lang)));
    w!(out);
    w!(
        out,
        "{} › {}",
        link(title, "../index.md"),
        inline(lang.t("categories"))
    );
    w!(out);
    table(
        &mut out,
        &component_cols(lang),
        &component_rows(cat, &f.components, "../"),
    );
    out
}

fn type_index_page(cat: &Catalog, title: &str, lang: Lang) -> String {
    let mut out = String::new();
    w!(out, "# {}", inline(lang.t("data_types")));
    w!(out);
    w!(out, "{}", link(title, "index.md"));
    w!(out);
    let rows: Vec<Vec<String>> = cat
        .data_types
        .iter()
        .map(|t| {
            vec![
                link(&t.name, &format!("types/{}.md", t.slug)),
                t.producers.len().to_string(),
                t.consumers.len().to_string(),
                t.others.len().to_string(),
            ]
        })
        .collect();
    table(
        &mut out,
        &[
            lang.t("data_type"),
            lang.t("producers"),
            lang.t("consumers"),
            lang.t("fact_others"),
        ],
        &rows,
    );
    out
}

fn interface_index_page(cat: &Catalog, title: &str, lang: Lang) -> String {
    let mut out = String::new();
    w!(out, "# {}", inline(lang.t("interfaces")));
    w!(out);
    w!(out, "{}", link(title, "index.md"));
    w!(out);
    let rows: Vec<Vec<String>> = cat
        .interfaces
        .iter()
        .map(|t| {
            let mut name = link(&t.name, &format!("interfaces/{}.md", t.slug));
            if t.is_unprovided() {
                name.push_str(&format!(" ({})", inline(lang.t("not_provided"))));
            }
            vec![
                name,
                t.providers.len().to_string(),
                t.requirers.len().to_string(),
                t.others.len().to_string(),
            ]
        })
        .collect();
    table(
        &mut out,
        &[
            lang.t("interface"),
            lang.t("providers"),
            lang.t("requirers"),
            lang.t("fact_others"),
        ],
        &rows,
    );
    out
}

/// Link text for `SUMMARY.md`: one line, escaped like everything else.
fn summary_item(out: &mut String, indent: usize, text: &str, href: &str) {
    w!(out, "{}- {}", "    ".repeat(indent), link(text, href));
}

/// The mdBook table of contents. Every page appears exactly once (a page missing from
/// `SUMMARY.md` is not built by mdBook and links to it would break); components are nested
/// under their category so the navigation stays foldable.
fn summary(cat: &Catalog, title: &str, lang: Lang) -> String {
    let mut out = String::new();
    w!(out, "# Summary");
    w!(out);
    w!(out, "{}", link(title, "index.md"));
    w!(out);
    if !cat.components.is_empty() {
        w!(out, "# {}", inline(lang.t("components")));
        w!(out);
        for f in &cat.categories {
            summary_item(
                &mut out,
                0,
                &category_name(&f.name, lang),
                &format!("categories/{}.md", f.slug),
            );
            for &ci in &f.components {
                let c = &cat.components[ci];
                summary_item(
                    &mut out,
                    1,
                    c.profile.name(),
                    &format!("components/{}.md", c.slug),
                );
            }
        }
        w!(out);
    }
    w!(out, "# {}", inline(lang.t("fact_catalogue")));
    w!(out);
    summary_item(&mut out, 0, lang.t("data_types"), "types.md");
    for t in &cat.data_types {
        summary_item(&mut out, 1, &t.name, &format!("types/{}.md", t.slug));
    }
    summary_item(&mut out, 0, lang.t("interfaces"), "interfaces.md");
    for t in &cat.interfaces {
        summary_item(&mut out, 1, &t.name, &format!("interfaces/{}.md", t.slug));
    }
    out
}

/// Renders every page as (relative path, content), in a fixed order.
pub fn pages(cat: &Catalog, title: &str, lang: Lang) -> Vec<(String, String)> {
    let of = category_slugs(cat);
    let index = index_page(cat, title, lang);
    let mut out = vec![
        ("SUMMARY.md".to_string(), summary(cat, title, lang)),
        ("README.md".to_string(), index.clone()),
        ("index.md".to_string(), index),
        ("types.md".into(), type_index_page(cat, title, lang)),
        (
            "interfaces.md".into(),
            interface_index_page(cat, title, lang),
        ),
    ];
    out.par_extend((0..cat.categories.len()).into_par_iter().map(|fi| {
        (
            format!("categories/{}.md", cat.categories[fi].slug),
            category_page(cat, fi, title, lang),
        )
    }));
    out.par_extend((0..cat.components.len()).into_par_iter().map(|ci| {
        let c = &cat.components[ci];
        (
            format!("components/{}.md", c.slug),
            component_page(cat, ci, &cat.categories[of[ci]].slug, title, lang),
        )
    }));
    out.par_extend((0..cat.data_types.len()).into_par_iter().map(|ti| {
        (
            format!("types/{}.md", cat.data_types[ti].slug),
            type_page(cat, ti, title, lang),
        )
    }));
    out.par_extend((0..cat.interfaces.len()).into_par_iter().map(|ii| {
        (
            format!("interfaces/{}.md", cat.interfaces[ii].slug),
            interface_page(cat, ii, title, lang),
        )
    }));
    out
}

impl Renderer for MarkdownRenderer {
    fn name(&self) -> &'static str {
        "markdown"
    }
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize> {
        let pages = pages(ctx.catalog, &ctx.site.title, ctx.site.language);
        pages
            .par_iter()
            .try_for_each(|(path, text)| out.write(path, text.as_bytes()))?;
        Ok(pages.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inline_escapes_every_metacharacter() {
        assert_eq!(inline("a|b"), "a\\|b");
        assert_eq!(inline("<b>x</b>"), "&lt;b&gt;x&lt;/b&gt;");
        assert_eq!(inline("A & B"), "A &amp; B");
        assert_eq!(inline("`code`"), "\\`code\\`");
        assert_eq!(inline("*em* _u_"), "\\*em\\* \\_u\\_");
        assert_eq!(inline("[x](y)"), "\\[x\\](y)");
        assert_eq!(inline("![i](y)"), "\\!\\[i\\](y)");
        assert_eq!(inline("# h"), "\\# h");
        assert_eq!(inline("- item"), "\\- item");
        assert_eq!(inline("+ item"), "\\+ item");
        assert_eq!(inline("> quote"), "&gt; quote");
        assert_eq!(inline("1. one"), "1\\. one");
        assert_eq!(inline("12) x"), "12\\) x");
        assert_eq!(inline("0.5.0"), "0.5.0");
        assert_eq!(inline("3."), "3\\.");
        assert_eq!(inline("==="), "\\===");
        assert_eq!(inline("a\\b"), "a\\\\b");
        assert_eq!(inline("~~s~~"), "\\~\\~s\\~\\~");
        assert_eq!(inline("$HOME"), "\\$HOME");
        assert_eq!(
            inline("{{#include x}}"),
            "&#123;&#123;\\#include x&#125;&#125;"
        );
        assert_eq!(inline("one\ntwo\r\n- three"), "one<br>two<br>\\- three");
        assert_eq!(inline("a\u{7}b\tc"), "ab c");
        assert_eq!(inline("日本語 1.5"), "日本語 1.5");
    }

    #[test]
    fn block_keeps_paragraphs_and_breaks() {
        assert_eq!(block("a\nb\n\n# c"), "a<br>\nb\n\n\\# c");
        assert_eq!(block("    code?"), "code?");
        assert_eq!(
            block("<script>x</script>"),
            "&lt;script&gt;x&lt;/script&gt;"
        );
    }
}
