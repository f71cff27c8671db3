//! The data-flow page of the site: for categories and for vendors, a layered drawing of which
//! groups can feed which (the wiring layout, one box per group) and the table of every flow.
//! The drawing holds the groups with the most port pairs, at most [`DRAWN_GROUPS`], and the
//! heaviest flows between them, at most [`DRAWN_FLOWS`]; the caption says how many groups and
//! flows it leaves out, and the table lists every flow (never dropped silently).

use super::system_svg::system_diagram;
use super::{crumbs_home, ctx, page_title, Job, Link, PageContext, Site};
use crate::catalog::{Output, PageKind};
use crate::render::facts::{self, FlowRow};
use serde::Serialize;

/// Most groups drawn in one drawing, and most flows between them: measured on the real corpus
/// (46 categories, 274 flows), a drawing of 30 groups and every flow was 14,000 px wide.
pub const DRAWN_GROUPS: usize = 12;
pub const DRAWN_FLOWS: usize = 24;

#[derive(Serialize)]
struct FlowRowView {
    from: Link,
    to: Link,
    pairs: u64,
    types: Vec<Link>,
    more_types: usize,
}

#[derive(Serialize)]
struct Section {
    id: &'static str,
    heading: &'static str,
    svg: String,
    /// Groups and flows between groups that the drawing leaves out (the table has them).
    not_drawn: usize,
    flows_not_drawn: usize,
    rows: Vec<FlowRowView>,
}

/// The drawing of `rows` ([`crate::render::wiring::dataflow_wiring`] with the caps).
fn drawing(site: &Site<'_>, title: &str, rows: &[FlowRow<'_>]) -> (String, usize, usize) {
    let here = site.catalog.site_page(PageKind::DataFlow);
    let (inst, conns, not_drawn, flows_not_drawn) = crate::render::wiring::dataflow_wiring(
        rows,
        site.lang,
        &|to| site.catalog.href(here, to, None, Output::Html),
        Some((DRAWN_GROUPS, DRAWN_FLOWS)),
    );
    if inst.is_empty() {
        return (String::new(), not_drawn, flows_not_drawn);
    }
    (
        system_diagram(title, &inst, &conns),
        not_drawn,
        flows_not_drawn,
    )
}

/// `dataflow.html`.
pub(super) fn page<'a>(site: &'a Site<'a>) -> Job<'a> {
    let cat = site.catalog;
    let lang = site.lang;
    let here = cat.site_page(PageKind::DataFlow);
    let link = |text: &str, to: &crate::catalog::Page| Link {
        text: text.to_string(),
        href: cat.href(here, to, None, Output::Html),
    };
    let sections: Vec<Section> = facts::DATAFLOW_SECTIONS
        .iter()
        .map(|&(grouping, id, key)| {
            let rows = facts::dataflow_rows(cat, grouping, lang);
            let title = format!("{} — {}", lang.t("dataflow"), lang.t(key));
            let (svg, not_drawn, flows_not_drawn) = drawing(site, &title, &rows);
            Section {
                id,
                heading: lang.t(key),
                svg,
                not_drawn,
                flows_not_drawn,
                rows: rows
                    .iter()
                    .map(|r| FlowRowView {
                        from: link(&r.from.0, r.from.1),
                        to: link(&r.to.0, r.to.1),
                        pairs: r.pairs,
                        types: r.types.iter().map(|(n, p)| link(n, p)).collect(),
                        more_types: r.more_types,
                    })
                    .collect(),
            }
        })
        .collect();
    Job {
        path: here.path_in(Output::Html),
        template: "dataflow.html",
        context: PageContext::Ready(minijinja::context! {
            root => "",
            title => page_title(site, lang.t("dataflow")),
            crumbs => ctx(&crumbs_home(lang, "")),
            sections => ctx(&sections),
        }),
    }
}
