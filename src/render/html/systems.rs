//! The pages of RT Systems: `systems/index.html` and one page per system (summary, wiring
//! diagram, instances, configuration used, connectors, orders, groups and every value of the
//! file). Host data (host names, IORs, endpoints, naming paths) is left out unless the site is
//! built with `show-host-data = true`; the page says how many values were left out.

use super::system_svg::{standalone_system_diagram, system_diagram};
use super::{crumbs_home, crumbs_section, ctx, page_title, Job, PageContext, Site};
use crate::catalog::systems::System;
use crate::model::system::RtSystem;
use crate::model::{non_empty, Text};
use crate::render::view::front::systems_index_view;
use crate::render::view::system::system_view;
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

impl Site<'_> {
    /// The template context of a system's page (`system.html`), also the system part of its
    /// manual (links for [`Site::out`]).
    pub(super) fn system_page(&self, s: &System) -> minijinja::Value {
        let lang = self.lang;
        let show_host = self.opts.show_host_data;
        let p: &RtSystem = &s.profile;
        let v = system_view(
            self.catalog,
            s,
            lang,
            (show_host, self.opts.source_url.as_deref()),
            self.out,
        );
        let name = v.name.clone();

        // The diagram.
        let cat = self.catalog;
        let here = cat.page_of_system(s);
        let link = |to: &crate::catalog::Page, a: &str| match here {
            Some(from) => cat.href(from, to, Some(a), self.out),
            None => String::new(),
        };
        let w = crate::render::wiring::system_wiring(cat, s, lang, &link);
        let diagram_title = format!("{} {name}", lang.t("sys_wiring"));
        let diagram_svg = system_diagram(&diagram_title, &w.instances, &w.connectors);
        // The caption counts what the file has and names each connector left out, and why.
        let mut diagram_text = format!(
            "{}: {}, {}, {}.",
            diagram_title,
            lang.count(p.components.len() as u64, "sys_instance_count"),
            lang.count(p.data_port_connectors.len() as u64, "sys_data_connectors"),
            lang.count(
                p.service_port_connectors.len() as u64,
                "sys_service_connectors"
            ),
        );
        for n in &w.notes(true) {
            diagram_text.push(' ');
            diagram_text.push_str(n);
            diagram_text.push('.');
        }

        minijinja::context! {
            root => ROOT,
            title => page_title(self, &format!("{name} {}", lang.t("system"))),
            name => name,
            crumbs => ctx(&crumbs_section(lang, ROOT, "systems")),
            summary => ctx(&v.summary),
            version_up_logs => ctx(&p.version_up_logs),
            subsystems => ctx(&p.systems.iter().map(|x| txt(&x.path)).collect::<Vec<_>>()),
            properties => ctx(&v.properties),
            hidden => v.hidden,
            diagram_svg => diagram_svg,
            diagram_text => diagram_text,
            diagram_file => drawing_path(self.catalog, s).rsplit('/').next().unwrap_or_default().to_string(),
            instances => ctx(&v.instances),
            show_path => show_host,
            comment_cols => ctx(&v.comment_columns()),
            configs => ctx(&v.configs),
            data_connectors => ctx(&v.data_connectors),
            service_connectors => ctx(&v.service_connectors),
            orders => ctx(&v.orders),
            groups => ctx(&v.groups),
            all_values => ctx(&v.all_values),
            source_url => v.source_url,
            history => ctx(&v.history.rows),
            history_older => v.history.older_note(lang),
            history_page => here
                .zip(v.history_page.as_ref())
                .map(|(from, to)| cat.href(from, to, None, self.out)),
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
            let w = crate::render::wiring::system_wiring(cat, s, site.lang, &link);
            let title = format!("{} {}", site.lang.t("sys_wiring"), s.display_name());
            (
                drawing_path(site.catalog, s),
                standalone_system_diagram(&title, &w.instances, &w.connectors, w.drawing_notes()),
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
    let v = systems_index_view(catalog);
    let rows: Vec<SystemRow> = v
        .systems
        .iter()
        .map(|s| SystemRow {
            name: s.name.text.clone(),
            // A system's page is beside the index: its file name is the link.
            href: s
                .name
                .to
                .map(|(to, _)| to.file_name("html"))
                .unwrap_or_default(),
            version: s.version.to_string(),
            vendor: s.vendor.to_string(),
            instances: s.instances,
            connectors: s.connectors,
        })
        .collect();
    let mut pages = vec![Job {
        path: v.page.path("html"),
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
