//! The system manual (`-f manual`): for each RT System one self-contained HTML file, to read
//! or to print (a PDF by headless Chromium's `--print-to-pdf`). A title page (the profile's
//! name, version, vendor, abstract and dates), the contents, the system (its wiring drawing,
//! instances, configuration, connectors, orders), a chapter per component it uses (from the
//! component page's context: basic information, document, data and service ports, parameters,
//! actions) and an appendix of every data type and interface those name, and the ones their
//! definitions name in turn.
//!
//! The pages are sections of the file ([`Output::Manual`]): every link is an anchor of it,
//! and a link to a page the manual does not hold (a component of another system, a category)
//! is left as text ([`unlink_missing`]). The style sheets (the site's `style.css` and the
//! print rules of `manual.css`) are inline and the drawings are inline SVG: the file makes no
//! request (its Content-Security-Policy allows none). Host data is left out as on the system
//! page unless `show-host-data` is set.

use super::{ctx, Link, Site};
use crate::catalog::systems::System;
use crate::catalog::{ComponentIx, Output, Page, TypeIx};
use crate::render::idl_view::{self, DefinitionView};
use crate::render::view::system::system_view;
use crate::render::view::types::{entry_view, TypeKind};
use crate::render::{RenderContext, Renderer};
use anyhow::{Context, Result};
use serde::Serialize;
use std::collections::BTreeSet;

/// Writes the system manuals.
pub struct ManualRenderer;

/// The list of the manuals, beside them.
const INDEX: &str = "index.html";

/// A component's chapter: its section id, the prefix of its rows' ids, the instances of the
/// system it runs as (linked to their rows) and its page's context.
#[derive(Serialize)]
struct Chapter {
    sid: String,
    pre: String,
    instances: Vec<Link>,
    page: super::ComponentPage,
}

/// A data type or interface of the appendix.
#[derive(Serialize)]
struct TypeSection {
    sid: String,
    pre: String,
    data: bool,
    name: String,
    spellings: Vec<String>,
    idl_files: Vec<String>,
    def: Option<DefinitionView>,
    stability: Option<super::StabilityLine>,
}

impl Renderer for ManualRenderer {
    fn name(&self) -> &'static str {
        "manual"
    }

    fn render(&self, rc: &RenderContext<'_>, out: &dyn crate::output::Sink) -> Result<usize> {
        let (catalog, opts) = (rc.catalog, rc.site);
        let env = super::HtmlRenderer::environment(opts, catalog);
        let site = Site::new(catalog, opts, Output::Manual);
        let css = style(&site)?;
        let tmpl = env
            .get_template("manual.html")
            .context("theme template `manual.html`")?;
        let mut list = Vec::with_capacity(catalog.systems.len());
        for s in &catalog.systems {
            let Some(page) = catalog.page_of_system(s) else {
                continue;
            };
            let file = page.file_name("html");
            let html = tmpl
                .render(manual_context(&site, s, page, &css))
                .with_context(|| format!("rendering the manual of system `{}`", s.source))?;
            out.write_owned(&file, unlink_missing(&html).into_bytes())?;
            list.push(Link {
                text: s.display_name().into_owned(),
                href: file,
            });
        }
        let index = env
            .get_template("manual.html")?
            .render(minijinja::context! { style => minijinja::Value::from_safe_string(css), manuals => ctx(&list), title => opts.title.clone() })
            .context("rendering the list of manuals")?;
        out.write_owned(INDEX, index.into_bytes())?;
        Ok(list.len() + 1)
    }
}

/// The inline style sheet: the site's `style.css` and the print rules of `manual.css` (either
/// overridden by the theme), made safe to stand in a `<style>` element.
fn style(site: &Site<'_>) -> Result<String> {
    let dir = site.opts.theme_dir.as_deref();
    let mut css = String::new();
    for name in ["style.css", "manual.css"] {
        css.push_str(&super::theme_file(dir, name)?.unwrap_or_default());
        css.push('\n');
    }
    // A style sheet ends at the first `</style`: a theme's text never closes it early.
    Ok(css.replace("</", "<\\/"))
}

/// The template context of system `s`'s manual: the system page's, and its chapters and
/// appendix.
fn manual_context(site: &Site<'_>, s: &System, page: &Page, css: &str) -> minijinja::Value {
    let components = components_used(s);
    let chapters: Vec<Chapter> = components
        .iter()
        .map(|(ci, instances)| chapter(site, s, *ci, instances))
        .collect();
    let appendix = appendix(site, s, &chapters);
    let system = site.system_page(s);
    minijinja::context! {
        style => minijinja::Value::from_safe_string(css.to_string()),
        sid => page.section_id(),
        chapters => ctx(&chapters),
        data_types => ctx(&appendix.iter().filter(|t| t.data).collect::<Vec<_>>()),
        interfaces => ctx(&appendix.iter().filter(|t| !t.data).collect::<Vec<_>>()),
        ..system
    }
}

/// The components the instances of `s` are, in the order of their first instance, each with
/// the indexes of its instances.
fn components_used(s: &System) -> Vec<(ComponentIx, Vec<usize>)> {
    let mut used: Vec<(ComponentIx, Vec<usize>)> = Vec::new();
    for i in 0..s.instances.len() {
        let Some(ci) = s.instances[i].component_index else {
            continue;
        };
        match used.iter_mut().find(|(c, _)| *c == ci) {
            Some((_, list)) => list.push(i),
            None => used.push((ci, vec![i])),
        }
    }
    used
}

/// The chapter of component `ci`, which `instances` of system `s` are.
fn chapter(site: &Site<'_>, s: &System, ci: ComponentIx, instances: &[usize]) -> Chapter {
    let mut page = site.component_page(ci);
    // "Connects to" lists the components of the whole catalogue with a matching port: in a
    // system's manual the connectors say what each port connects to.
    for cols in [&mut page.data_cols, &mut page.service_cols] {
        if cols.peers {
            cols.peers = false;
            cols.span -= 1;
        }
    }
    let sid = site.catalog.component_page(ci).section_id();
    let s_instances = instances
        .iter()
        .filter_map(|&i| {
            let c = s.profile.components.get(i)?;
            Some(Link {
                text: crate::model::non_empty(&c.instance_name)
                    .unwrap_or("")
                    .to_string(),
                href: format!("#{}", s.instances.get(i)?.anchor),
            })
        })
        .collect();
    Chapter {
        pre: format!("{sid}--"),
        sid,
        instances: s_instances,
        page,
    }
}

/// The data types and interfaces the chapters' ports and the connectors of `s` link to, and
/// those their definitions name, data types first, each kind in the catalogue's order.
fn appendix(site: &Site<'_>, s: &System, chapters: &[Chapter]) -> Vec<TypeSection> {
    let cat = site.catalog;
    let all: Vec<TypeIx> = [TypeKind::Data, TypeKind::Interface]
        .into_iter()
        .flat_map(|k| k.entries(cat))
        .collect();
    // What the views link to: the sections of types (`#types-…`, `#interfaces-…`).
    let mut linked: Vec<String> = Vec::new();
    for c in chapters {
        let ports = c.page.data_ports.iter().map(|r| &r.port);
        let interfaces = c.page.service_ports.iter().flat_map(|sp| &sp.interfaces);
        for cells in ports.chain(interfaces.map(|i| &i.port)) {
            linked.extend(cells.type_ref.as_ref().and_then(|t| t.href.clone()));
        }
    }
    let v = system_view(
        cat,
        s,
        site.lang,
        (site.opts.show_host_data, None),
        Output::Manual,
    );
    for c in &v.data_connectors {
        linked.extend(c.data_type.iter().map(|l| l.href.clone()));
    }
    for c in &v.service_connectors {
        linked.extend(c.interfaces.iter().map(|l| l.href.clone()));
    }
    let sids: Vec<String> = all.iter().map(|&t| cat.type_page(t).section_id()).collect();
    let mut wanted: BTreeSet<usize> = BTreeSet::new();
    let mut queue: Vec<usize> = Vec::new();
    let mut want = |k: usize, queue: &mut Vec<usize>| {
        if wanted.insert(k) {
            queue.push(k);
        }
    };
    for href in &linked {
        let sid = href.strip_prefix('#').unwrap_or(href);
        if let Some(k) = sids.iter().position(|x| x == sid) {
            want(k, &mut queue);
        }
    }
    let mut defs: Vec<(usize, Option<DefinitionView>)> = Vec::new();
    while let Some(k) = queue.pop() {
        let v = entry_view(cat, all[k], site.lang, None);
        let mut def = idl_view::definition(cat, v.name, site.lang);
        for r in def.iter_mut().flat_map(DefinitionView::type_refs_mut) {
            if let Some(e) = r.entry.and_then(|e| all.iter().position(|&x| x == e)) {
                want(e, &mut queue);
            }
        }
        defs.push((k, def));
    }
    defs.sort_by_key(|(k, _)| *k);
    defs.into_iter()
        .map(|(k, def)| type_section(site, all[k], def, &wanted, &all))
        .collect()
}

/// The appendix section of type `t` with its definition `def`, whose types link to their
/// sections (the `wanted` entries of `all`) and to nothing else.
fn type_section(
    site: &Site<'_>,
    t: TypeIx,
    mut def: Option<DefinitionView>,
    wanted: &BTreeSet<usize>,
    all: &[TypeIx],
) -> TypeSection {
    let cat = site.catalog;
    let v = entry_view(cat, t, site.lang, None);
    for r in def.iter_mut().flat_map(DefinitionView::type_refs_mut) {
        let held = r
            .entry
            .and_then(|e| all.iter().position(|&x| x == e))
            .filter(|k| wanted.contains(k));
        r.page = held.map(|k| cat.type_page(all[k]).section_id());
    }
    let sid = v.page.section_id();
    TypeSection {
        pre: format!("{sid}--"),
        sid,
        data: v.kind == TypeKind::Data,
        name: v.name.to_string(),
        spellings: v.spellings.to_vec(),
        idl_files: crate::catalog::idl_file_names(v.idl_files),
        def,
        stability: super::StabilityLine::of(cat, v.page, v.stability.as_ref(), site.out),
    }
}

/// `html` with every link to an anchor it does not define made text: the `href` of such a
/// link is dropped (a manual holds some pages of the catalogue; the views link to all).
pub fn unlink_missing(html: &str) -> String {
    let ids: BTreeSet<&str> = attr_values(html, " id=\"").collect();
    let mut out = String::with_capacity(html.len());
    let mut rest = html;
    const HREF: &str = " href=\"#";
    while let Some(at) = rest.find(HREF) {
        let value_start = at + HREF.len();
        let Some(len) = rest[value_start..].find('"') else {
            break;
        };
        let target = &rest[value_start..value_start + len];
        let end = value_start + len + 1;
        if ids.contains(target) {
            out.push_str(&rest[..end]);
        } else {
            out.push_str(&rest[..at]);
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// The values of attribute `prefix` (` id="`) in `html`.
fn attr_values<'a>(html: &'a str, prefix: &'a str) -> impl Iterator<Item = &'a str> + 'a {
    html.match_indices(prefix).filter_map(move |(at, _)| {
        let start = at + prefix.len();
        let len = html[start..].find('"')?;
        Some(&html[start..start + len])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_to_missing_anchors_become_text() {
        let html = r##"<p id="a"><a href="#a">in</a> <a href="#b">out</a> <a href="https://x/#b">web</a></p>"##;
        assert_eq!(
            unlink_missing(html),
            r##"<p id="a"><a href="#a">in</a> <a>out</a> <a href="https://x/#b">web</a></p>"##
        );
    }
}
