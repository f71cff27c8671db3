//! GitHub-flavoured Markdown output that is also a valid mdBook `src/` folder.
//!
//! Layout (all links relative, `.md`):
//! - `index.md` — the catalogue (components by category, links to the type and interface
//!   indexes); `README.md` is the same page, for GitHub's folder view (it is not in the book);
//! - `SUMMARY.md` — the mdBook table of contents: components nested under their category page,
//!   data types under the type index, interfaces under the interface index, vendors under the
//!   vendor index;
//! - `categories/<slug>.md`, `components/<slug>.md`, `types.md`, `types/<slug>.md`,
//!   `interfaces.md`, `interfaces/<slug>.md`, `vendors.md`, `vendors/<slug>.md`,
//!   `systems.md`, `systems/<slug>.md` (the indexes sit at the root so that no slug can collide
//!   with them).
//!
//! Paths and links come from the catalogue ([`Page::path_in`], [`Catalog::href`]): nothing
//! here spells a page path.
//!
//! Rows carry explicit `<a id="…"></a>` anchors from [`Component::anchors`], so links never
//! depend on a Markdown engine's heading-id rules. All profile text goes through [`inline`] or
//! [`block`]: it can neither break a table nor inject HTML, links, images or mdBook directives.

use super::text::{component_sections, component_table, facets_of_each, Markup};
use super::text::{facet_index_page, facet_page, systems_index_page, type_index_page, type_page};
use super::view::component::component_view;
use super::view::facets::{component_rows, facet_index_view, facet_view, FacetKind};
use super::view::front::{front_view, systems_index_view};
use super::view::types::{entry_view, type_index_view, TypeKind};
use super::view::Linked;
use super::{RenderContext, Renderer};
use crate::catalog::pages::{MARKDOWN_README, MARKDOWN_SUMMARY};
use crate::catalog::{
    Catalog, Component, ComponentIx, Ix, Output, Page, PageKind, PerEntry, SystemIx,
};
use crate::i18n::Lang;
use crate::output::Sink;
use rayon::prelude::*;
use std::fmt::Write as _;

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
        // Smart punctuation would curl straight quotes and apostrophes.
        '\'' => "\\'",
        '"' => "\\\"",
        '<' => "&lt;",
        '>' => "&gt;",
        '&' => "&amp;",
        // `{{#include …}}` and friends are mdBook directives.
        '{' => "&#123;",
        '}' => "&#125;",
        _ => return None,
    })
}

/// Bytes after which [`escape_line_chars`] may write something other than the byte itself:
/// Markdown and HTML metacharacters, quotes (smart punctuation), tabs and other control
/// characters (ASCII, DEL, and 0xC2, the lead byte of U+0080–U+009F).
static LINE_SPECIAL: [bool; 256] = super::byte_set(true, b"\\`*_[]|#~!$<>&{}'\"\x7f\xc2");

/// Escapes one line; a leading list, heading-underline or ordered-list marker is neutralised.
/// A line that cannot start a list and holds no special byte or smart-punctuation run
/// (`--`, `...`) is copied as is.
fn escape_line(line: &str, out: &mut String) {
    let line = line.trim_start();
    let b = line.as_bytes();
    let may_start_list = matches!(b.first(), Some(b'-' | b'+' | b'=' | b'0'..=b'9'));
    if !may_start_list
        && !b.iter().any(|&c| LINE_SPECIAL[usize::from(c)])
        && memchr::memmem::find(b, b"--").is_none()
        && memchr::memmem::find(b, b"...").is_none()
    {
        out.push_str(line);
    } else {
        escape_line_chars(line, out);
    }
}

/// [`escape_line`] one character at a time (`line` has no leading white space).
fn escape_line_chars(line: &str, out: &mut String) {
    let chars: Vec<char> = line.chars().collect();
    let digits = chars.iter().take_while(|c| c.is_ascii_digit()).count();
    // `1.` / `1)` start an ordered list only when followed by white space or the end.
    let ordered = (1..=9).contains(&digits)
        && matches!(chars.get(digits), Some('.' | ')'))
        && chars.get(digits + 1).is_none_or(|c| c.is_whitespace());
    // Runs of plain `-` and `.` written so far: mdBook 0.5 (pulldown-cmark's smart punctuation,
    // on by default) turns `--`, `---` into dashes and `...` into an ellipsis; a backslash before
    // the second hyphen or the third dot keeps the text as written, for 0.4 alike.
    let (mut hyphens, mut dots) = (0, 0);
    // Code spans are kept as code spans (their content is literal in Markdown).
    let spans = super::text::code_spans(&chars, false);
    let mut span = spans.iter().peekable();
    let mut skip_to = 0;
    for (i, &ch) in chars.iter().enumerate() {
        if i < skip_to {
            continue;
        }
        if let Some(&&sp) = span.peek() {
            if i == sp.open {
                out.extend(&chars[sp.open..=sp.close]);
                skip_to = sp.close + 1;
                span.next();
                (hyphens, dots) = (0, 0);
                continue;
            }
        }
        let at_marker = (i == 0 && matches!(ch, '-' | '+' | '=')) || (ordered && i == digits);
        let smart = (ch == '-' && hyphens == 1) || (ch == '.' && dots == 2);
        (hyphens, dots) = match ch {
            '-' if !at_marker && !smart => (hyphens + 1, 0),
            '.' if !at_marker && !smart => (0, dots + 1),
            _ => (0, 0),
        };
        if at_marker || smart {
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
    let s = crate::model::prose(s);
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
    let norm = crate::model::prose(s)
        .replace("\r\n", "\n")
        .replace('\r', "\n");
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
    const OUTPUT: Output = Output::Markdown;
    fn esc(s: &str) -> String {
        inline(s)
    }
    fn message_line(line: &str, out: &mut String) {
        escape_line(line, out);
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
    fn code(s: &str) -> String {
        format!("`{s}`")
    }
    fn paragraph(out: &mut String, escaped: &str) {
        w!(out, "{escaped}");
        w!(out);
    }
    fn linked_list(out: &mut String, items: &[String]) {
        for l in items {
            w!(out, "- {l}");
        }
        w!(out);
    }
    fn heading(out: &mut String, page: &Page, level: usize, anchor: &str, text: &str) {
        heading(out, level, &page.anchor_in(anchor, MD), text)
    }
    fn anchored(page: &Page, anchor: &str, escaped: &str) -> String {
        format!("<a id=\"{}\"></a>{escaped}", page.anchor_in(anchor, MD))
    }
    fn page_ref(cat: &Catalog, from: &Page, to: &Page) -> String {
        link(&to.title, &cat.href(from, to, None, MD))
    }
    fn page_head(out: &mut String, cat: &Catalog, page: &Page, title: &str, crumbs: &[Linked<'_>]) {
        w!(out, "# {}", inline(title));
        w!(out);
        let links: Vec<String> = crumbs
            .iter()
            .map(|l| super::text::linked::<Md>(cat, page, l))
            .collect();
        w!(out, "{}", links.join(" › "));
        w!(out);
    }
    fn note(out: &mut String, text: &str) {
        w!(out, "> **{}**", inline(text));
        w!(out);
    }
}

/// The output this module writes.
const MD: Output = Output::Markdown;

/// A GFM table; cells are already escaped. An empty cell becomes a space.
fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]) {
    let head: Vec<String> = headers.iter().map(|h| inline(h)).collect();
    w!(out, "| {} |", head.join(" | "));
    w!(out, "|{}", "---|".repeat(headers.len()));
    for r in rows {
        out.push('|');
        for c in r {
            out.push(' ');
            out.push_str(if c.is_empty() { " " } else { c });
            out.push_str(" |");
        }
        out.push('\n');
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

fn component_page(
    cat: &Catalog,
    ci: ComponentIx,
    facets: (usize, usize),
    title: &str,
    lang: Lang,
    readme: &Readmes,
    source_url: Option<&str>,
) -> String {
    let v = component_view(cat, ci, facets, source_url, lang);
    let page = v.page;
    let mut out = String::with_capacity(4096);
    w!(out, "# {}", inline(&v.name));
    w!(out);
    w!(
        out,
        "{} › {}",
        link(title, &home(cat, page)),
        super::text::linked::<Md>(cat, page, &v.category)
    );
    w!(out);
    super::text::stability_line::<Md>(&mut out, cat, page, v.stability.as_ref());
    if let Some(d) = v.lead {
        w!(out, "{}", block(d));
        w!(out);
    }
    component_sections::<Md>(&mut out, cat, &v, lang);
    if let Some(r) = v.readme {
        let html = crate::render::html::readme::readme_html(r, readme);
        if !html.trim().is_empty() {
            heading(&mut out, 2, "sec-readme", lang.t("readme"));
            w!(out, "{}", readme_block(&html));
            w!(out);
        }
    }
    out
}

/// Where the links of the READMEs go in the Markdown output.
type Readmes = std::sync::Arc<crate::render::html::readme::Targets>;

/// The targets of README links from a component page (`components/x.md`).
fn readme_targets(cat: &Catalog, source_url: Option<&str>) -> Readmes {
    let root = cat.site_page(PageKind::Index);
    let up = cat
        .components
        .first()
        .map(|_| cat.root_from(cat.component_page(Ix::new(0)), MD))
        .unwrap_or_default();
    std::sync::Arc::new(crate::render::html::readme::Targets::new(
        cat,
        source_url,
        &up,
        |ci| cat.href(root, cat.component_page(ci), None, MD),
    ))
}

/// The link on page `from` to the front page.
fn home(cat: &Catalog, from: &Page) -> String {
    cat.href(from, cat.site_page(PageKind::Index), None, MD)
}

/// The link on page `from` to the index page of `kind` (types, interfaces, vendors, systems).
fn index_href(cat: &Catalog, from: &Page, kind: PageKind) -> String {
    cat.href(from, cat.site_page(kind), None, MD)
}

/// A README's sanitised HTML as one Markdown HTML block (mdBook and GitHub show it as is): no
/// blank line inside, which would end the block (a blank line's break is written `&#10;`);
/// braces as character references, so `{{#include …}}` is no mdBook directive, and brackets,
/// so that no text of it reads as a Markdown link to a renderer that looked inside the block.
fn readme_block(html: &str) -> String {
    let body = format!("<div class=\"readme\">\n{}</div>", html.trim_end())
        .replace('{', "&#123;")
        .replace('}', "&#125;")
        .replace('[', "&#91;")
        .replace(']', "&#93;");
    let mut out = String::with_capacity(body.len() + 64);
    for (i, line) in body.split('\n').enumerate() {
        if i > 0 && line.trim().is_empty() {
            out.push_str("&#10;");
        } else if i > 0 {
            out.push('\n');
        }
        out.push_str(line);
    }
    out
}

/// `index.md` from the front page's view: the counts with the indexes linked, the systems,
/// data-flow and What's new pages, then every component by category.
fn index_page(cat: &Catalog, title: &str, lang: Lang) -> String {
    let v = front_view(cat, lang);
    let page = v.page;
    let mut out = String::new();
    w!(out, "# {}", inline(title));
    w!(out);
    let mut stats = vec![format!(
        "{}: {}",
        inline(lang.t("components")),
        v.components
    )];
    let to = |key: &str, to: &Page| link(lang.t(key), &cat.href(page, to, None, MD));
    let (systems, counted): (Vec<_>, Vec<_>) = v.indexes.iter().partition(|i| i.key == "systems");
    stats.extend(
        counted
            .iter()
            .map(|i| format!("{}: {}", to(i.key, i.page), i.count)),
    );
    w!(out, "{}", stats.join(" · "));
    w!(out);
    for i in systems {
        w!(out, "{}: {}", to(i.key, i.page), i.count);
        w!(out);
    }
    w!(out, "{}", to("dataflow", v.dataflow));
    w!(out);
    if let Some(news) = v.whats_new {
        w!(out, "{}", to("whats_new", news));
        w!(out);
    }
    heading(&mut out, 2, "sec-components", lang.t("components"));
    for g in &v.categories {
        w!(
            out,
            "### {}",
            link(&g.name, &cat.href(page, g.page, None, MD))
        );
        w!(out);
        let rows = component_rows(cat, g.members.iter().copied());
        component_table::<Md>(&mut out, cat, page, &rows, false, lang);
    }
    out
}

/// An item of `SUMMARY.md` (at the root, beside `index.md`): one line, escaped like
/// everything else.
fn summary_item(out: &mut String, cat: &Catalog, indent: usize, text: &str, to: &Page) {
    let href = cat.href(cat.site_page(PageKind::Index), to, None, MD);
    w!(out, "{}- {}", "    ".repeat(indent), link(text, &href));
}

/// The mdBook table of contents. Every page appears exactly once (a page missing from
/// `SUMMARY.md` is not built by mdBook and links to it would break); components are nested
/// under their category so the navigation stays foldable, vendors under the vendor index.
fn summary<'a>(cat: &'a Catalog, title: &str, lang: Lang) -> String {
    let mut out = String::new();
    w!(out, "# Summary");
    w!(out);
    w!(
        out,
        "{}",
        link(title, &home(cat, cat.site_page(PageKind::Index)))
    );
    w!(out);
    if !cat.components.is_empty() {
        w!(out, "# {}", inline(lang.t("components")));
        w!(out);
        for (fi, f) in cat.categories.iter().enumerate() {
            let text = FacetKind::Category.name(&f.name, lang);
            summary_item(&mut out, cat, 0, &text, cat.category_page(fi));
            for ci in cat.members(f) {
                let page = cat.component_page(ci);
                summary_item(&mut out, cat, 1, &page.title, page);
            }
        }
        w!(out);
    }
    w!(out, "# {}", inline(lang.t("fact_catalogue")));
    w!(out);
    // The indexes of the catalogue, each with its pages under it.
    let titled = |page: &'a Page| (page.title.clone(), page);
    let mut sections = vec![
        (
            PageKind::DataTypes,
            "data_types",
            Ix::all(cat.data_types.len())
                .map(|ti| titled(cat.data_type_page(ti)))
                .collect(),
        ),
        (
            PageKind::Interfaces,
            "interfaces",
            Ix::all(cat.interfaces.len())
                .map(|ii| titled(cat.interface_page(ii)))
                .collect(),
        ),
        (
            PageKind::Vendors,
            "vendors",
            cat.vendors
                .iter()
                .enumerate()
                .map(|(fi, f)| (FacetKind::Vendor.name(&f.name, lang), cat.vendor_page(fi)))
                .collect::<Vec<_>>(),
        ),
    ];
    if !cat.systems.is_empty() {
        let systems = Ix::all(cat.systems.len()).map(|si| titled(cat.system_page(si)));
        sections.push((PageKind::Systems, "systems", systems.collect()));
    }
    sections.push((PageKind::DataFlow, "dataflow", Vec::new()));
    for (kind, label, pages) in sections {
        summary_item(&mut out, cat, 0, lang.t(label), cat.site_page(kind));
        for (text, page) in pages {
            summary_item(&mut out, cat, 1, &text, page);
        }
    }
    // What's new, with each history (components, systems, IDL files) under it.
    if let Some(news) = cat.pages().iter().find(|p| p.kind == PageKind::WhatsNew) {
        summary_item(&mut out, cat, 0, lang.t("whats_new"), news);
        for of in cat.histories() {
            if let Some(page) = cat.history_page_of(of) {
                let text = lang.t("history_page_title").replace("{name}", &page.title);
                summary_item(&mut out, cat, 1, &text, page);
            }
        }
    }
    out
}

/// `dataflow.md`: which groups of components can feed which.
fn dataflow_page(cat: &Catalog, title: &str, lang: Lang) -> String {
    let page = cat.site_page(PageKind::DataFlow);
    let mut out = String::new();
    w!(out, "# {}", inline(lang.t("dataflow")));
    w!(out);
    w!(out, "{}", link(title, &home(cat, page)));
    w!(out);
    super::text::dataflow_body::<Md>(&mut out, cat, page, lang);
    out
}

/// `systems/<slug>.md`, and its wiring diagram as an SVG file (written beside it, with the
/// page's stem: [`Page::path`]) unless it is drawn as a Mermaid block; the diagram's section
/// comes after the summary.
fn system_page(
    cat: &Catalog,
    si: SystemIx,
    title: &str,
    lang: Lang,
    site: (bool, Option<&str>),
    diagrams: super::DiagramFormat,
) -> (String, Option<String>) {
    let s = &cat[si];
    let page = cat.system_page(si);
    let mut out = String::new();
    w!(out, "# {}", inline(&s.display_name()));
    w!(out);
    w!(
        out,
        "{} › {}",
        link(title, &home(cat, page)),
        link(lang.t("systems"), &index_href(cat, page, PageKind::Systems))
    );
    w!(out);
    // The section anchors are the HTML page's (`data-connectors`, …): type pages link them.
    let head = |o: &mut String, anchor: &str, text: &str| heading(o, 2, anchor, text);
    let w = super::wiring::system_wiring(cat, s, lang, &|to, a| cat.href(page, to, Some(a), MD));
    let caption = super::system_text::wiring_caption(s, lang);
    let svg = match diagrams {
        super::DiagramFormat::Mermaid => None,
        super::DiagramFormat::Svg => Some(super::html::standalone_system_diagram(
            &caption,
            &w.instances,
            &w.connectors,
            w.drawing_notes(),
        )),
    };
    let notes = w.notes(matches!(diagrams, super::DiagramFormat::Svg));
    let drawing = |out: &mut String| {
        match diagrams {
            super::DiagramFormat::Mermaid => {
                w!(out, "```mermaid");
                out.push_str(&super::wiring::to_mermaid(
                    &s.display_name(),
                    &w.instances,
                    &w.connectors,
                    &notes,
                ));
                w!(out, "```");
            }
            super::DiagramFormat::Svg => {
                w!(out, "![{}]({})", inline(&caption), page.file_name("svg"));
            }
        }
        w!(out);
    };
    let targets = super::system_text::Targets::new(&head, &caption, &drawing, &notes);
    super::system_text::system_body::<Md>(&mut out, cat, s, lang, site, &targets);
    (out, svg)
}

/// Renders every page as (relative path, content), in a fixed order.
pub fn pages(cat: &Catalog, title: &str, lang: Lang) -> Vec<(String, String)> {
    let of = facets_of_each(cat);
    let readme = readme_targets(cat, None);
    let mut out = other_pages(cat, title, lang, (false, None), super::DiagramFormat::Svg);
    out.par_extend(
        (0..cat.components.len())
            .into_par_iter()
            .map(Ix::new)
            .map(|ci| component_entry(cat, &of, ci, title, lang, &readme, None)),
    );
    out
}

/// The path and text of component `ci`'s page.
fn component_entry(
    cat: &Catalog,
    of: &PerEntry<Component, (usize, usize)>,
    ci: ComponentIx,
    title: &str,
    lang: Lang,
    readme: &Readmes,
    source_url: Option<&str>,
) -> (String, String) {
    (
        cat.component_page(ci).path_in(MD),
        component_page(cat, ci, of[ci], title, lang, readme, source_url),
    )
}

/// Every page but the component pages.
fn other_pages(
    cat: &Catalog,
    title: &str,
    lang: Lang,
    site: (bool, Option<&str>),
    diagrams: super::DiagramFormat,
) -> Vec<(String, String)> {
    let index = index_page(cat, title, lang);
    let mut out = vec![
        (MARKDOWN_SUMMARY.to_string(), summary(cat, title, lang)),
        (MARKDOWN_README.to_string(), index.clone()),
        (cat.site_page(PageKind::Index).path_in(MD), index),
        (
            cat.site_page(PageKind::DataTypes).path_in(MD),
            type_index_page::<Md>(cat, &type_index_view(cat, TypeKind::Data), title, lang),
        ),
        (
            cat.site_page(PageKind::Interfaces).path_in(MD),
            type_index_page::<Md>(cat, &type_index_view(cat, TypeKind::Interface), title, lang),
        ),
        (
            cat.site_page(PageKind::Vendors).path_in(MD),
            facet_index_page::<Md>(
                cat,
                &facet_index_view(cat, FacetKind::Vendor, lang),
                title,
                lang,
            ),
        ),
        (
            cat.site_page(PageKind::DataFlow).path_in(MD),
            dataflow_page(cat, title, lang),
        ),
    ];
    for kind in [FacetKind::Category, FacetKind::Vendor] {
        out.par_extend((0..kind.facets(cat).len()).into_par_iter().map(|fi| {
            let v = facet_view(cat, kind, fi, lang);
            (v.page.path_in(MD), facet_page::<Md>(cat, &v, title, lang))
        }));
    }
    for kind in [TypeKind::Data, TypeKind::Interface] {
        out.par_extend(kind.entries(cat).into_par_iter().map(|i| {
            let v = entry_view(cat, i, lang, site.1);
            (v.page.path_in(MD), type_page::<Md>(cat, &v, title, lang))
        }));
    }
    if !cat.systems.is_empty() {
        out.push((
            cat.site_page(PageKind::Systems).path_in(MD),
            systems_index_page::<Md>(cat, &systems_index_view(cat), title, lang),
        ));
        out.par_extend(
            (0..cat.systems.len())
                .into_par_iter()
                .map(Ix::new)
                .flat_map_iter(|si| {
                    let page = cat.system_page(si);
                    let path = page.path_in(MD);
                    // The wiring diagram beside the page, with its stem.
                    let svg_path = page.path("svg");
                    let (text, svg) = system_page(cat, si, title, lang, site, diagrams);
                    std::iter::once((path, text)).chain(svg.map(|s| (svg_path, s)))
                }),
        );
    }
    out.extend(super::history_text::pages::<Md>(cat, site.1, lang));
    out
}

impl Renderer for MarkdownRenderer {
    fn name(&self) -> &'static str {
        "markdown"
    }
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize> {
        let (cat, title, lang) = (ctx.catalog, &ctx.site.title, ctx.site.language);
        let pages = other_pages(
            cat,
            title,
            lang,
            (ctx.site.show_host_data, ctx.site.source_url.as_deref()),
            ctx.site.markdown_diagrams,
        );
        pages
            .par_iter()
            .try_for_each(|(path, text)| out.write(path, text.as_bytes()))?;
        // Component pages are the bulk: written as they are rendered, never all held at once.
        let of = facets_of_each(cat);
        let source_url = ctx.site.source_url.as_deref();
        let readme = readme_targets(cat, source_url);
        (0..cat.components.len())
            .into_par_iter()
            .map(Ix::new)
            .try_for_each(|ci| {
                let (path, text) = component_entry(cat, &of, ci, title, lang, &readme, source_url);
                out.write(&path, text.as_bytes())
            })?;
        // The images the READMEs show, each copied once (mdBook copies them into the book).
        let assets = cat.readme_assets();
        for (asset, abs) in &assets {
            out.write_owned(asset, crate::readme::read_asset(abs)?)?;
        }
        Ok(pages.len() + cat.components.len() + assets.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 4096, ..Default::default() })]
        /// Lines of text, markup characters, markers, digits, controls (C0, DEL, C1) and
        /// non-ASCII letters escape exactly as character by character.
        #[test]
        fn escape_line_matches_character_by_character(
            line in "[ \t0-9a-z.)\\-+=*_`|<>&{}#!$~'\"\\[\\]\u{0}-\u{1f}\u{7f}\u{80}-\u{9f}\u{a0}é日本\u{2028}]{0,24}"
        ) {
            let (mut fast, mut reference) = (String::new(), String::new());
            escape_line(&line, &mut fast);
            escape_line_chars(line.trim_start(), &mut reference);
            proptest::prop_assert_eq!(fast, reference);
        }
    }

    #[test]
    fn inline_escapes_every_metacharacter() {
        assert_eq!(inline("a|b"), "a\\|b");
        assert_eq!(inline("<b>x</b>"), "&lt;b&gt;x&lt;/b&gt;");
        assert_eq!(inline("A & B"), "A &amp; B");
        // A code span stays a code span (code on the HTML site too); a lone backtick, or a span
        // holding a table's `|`, is escaped.
        assert_eq!(inline("`code`"), "`code`");
        assert_eq!(inline("`<b>` and `x`"), "`<b>` and `x`");
        assert_eq!(inline("a ` b"), "a \\` b");
        assert_eq!(inline("`a|b`"), "\\`a\\|b\\`");
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
        assert_eq!(inline("a -- b --- c"), "a -\\- b -\\-- c");
        assert_eq!(inline("wait... ...."), "wait..\\. ..\\..");
        assert_eq!(inline("it's \"x\""), "it\\'s \\\"x\\\"");
        assert_eq!(inline("<!-- c -->"), "&lt;\\!-\\- c -\\-&gt;");
        assert_eq!(inline("--x"), "\\--x");
        assert_eq!(inline("1.5 0..10 a-b"), "1.5 0..10 a-b");
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
