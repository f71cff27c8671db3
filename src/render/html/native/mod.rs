//! The component, data type and interface pages of the built-in theme, written by Rust code
//! instead of by running the templates `base.html` + `component.html` (`type.html`,
//! `interface.html`), with `macros.html`, in minijinja.
//!
//! Component pages are most of a site (10,000 of 14,000 files for 10,000 profiles) and running
//! their template was a third of the build's instructions; a type page lists every port using
//! the type, thousands in a large catalogue. When the theme directory overrides none of the
//! templates a page kind stands for, [`component_page`] and [`type_page`] write the page
//! directly, byte for byte what the templates produce: the tests render every page both ways
//! and compare (the examples, the fixtures, a catalogue using every part of an IDL definition,
//! generated catalogues and, when present, the real-world corpus). The templates stay the
//! documented source of the markup and are what a theme that overrides one of them runs. A
//! change to a template must be made here too — the tests fail until it is.

mod types;

use super::svg::esc_into;
use super::{Columns, ComponentPage, EventRow, Field, KeyValue, PortCells, PortTypeRef};
use crate::i18n::Lang;
use crate::render::view::history::HistoryRow;
pub(super) use types::type_page;

/// The template globals the page prints.
pub(super) struct Globals<'a> {
    pub lang: Lang,
    pub site_title: &'a str,
    pub has_diagnostics: bool,
    pub has_systems: bool,
    /// Something has a history (a component, a system, an IDL file): the What's new page exists.
    pub has_history: bool,
    /// The site has an Atom feed (`feed.xml`).
    pub has_feed: bool,
    pub generator: &'a str,
}

/// Writes HTML: `raw` markup as is, `text`/`label` escaped as `{{ … }}` prints a string.
struct Out<'a> {
    buf: String,
    g: &'a Globals<'a>,
}

impl Out<'_> {
    fn raw(&mut self, s: &str) {
        self.buf.push_str(s);
    }

    fn text(&mut self, s: &str) {
        // Writing to a String cannot fail.
        let _ = esc_into(&mut self.buf, s);
    }

    /// `{% if s %}open{{ s }}close{% endif %}`.
    fn text_if(&mut self, open: &str, s: &str, close: &str) {
        if !s.is_empty() {
            self.raw(open);
            self.text(s);
            self.raw(close);
        }
    }

    /// `{{ s|wbr }}`: escaped, `<wbr>` between the words of a name.
    fn name(&mut self, s: &str) {
        let _ = super::svg::esc_wbr_into(&mut self.buf, s);
    }

    /// `{{ s|code_spans }}`: escaped, code spans as `<code>`.
    fn text_with_code(&mut self, s: &str) {
        let _ = super::svg::esc_code_into(&mut self.buf, s);
    }

    /// `{{ t.key }}`.
    fn label(&mut self, key: &str) {
        let s = self.g.lang.t(key);
        self.text(s);
    }

    /// `fields(list)` (see `builtins::fields`).
    fn fields(&mut self, list: &[Field]) {
        if list.is_empty() {
            return;
        }
        self.raw("<dl class=\"fields\">\n");
        for f in list {
            self.raw("<dt>");
            self.text(&f.label);
            self.raw("</dt><dd>");
            match (&f.html, &f.text) {
                (Some(h), _) if !h.is_empty() => self.raw(h),
                (_, Some(t)) => self.text(t),
                _ => {}
            }
            self.raw("</dd>\n");
        }
        self.raw("</dl>");
    }

    /// `{% if x.since %} <span class="since">{{ x.since }}</span>{% endif %}`.
    fn since(&mut self, since: &Option<String>) {
        if let Some(s) = since {
            self.raw(" <span class=\"since\">");
            self.text(s);
            self.raw("</span>");
        }
    }

    /// `type_link(r)` (see `builtins::type_link`).
    fn type_link(&mut self, r: &Option<PortTypeRef>) {
        if let Some(r) = r {
            let href = r.href.as_deref().filter(|h| !h.is_empty());
            self.code_link(href, &r.text);
        }
    }

    /// `<a href="href"><code>text</code></a>`, or only `<code>text</code>` without `href`.
    fn code_link(&mut self, href: Option<&str>, text: &str) {
        if let Some(href) = href {
            self.raw("<a href=\"");
            self.text(href);
            self.raw("\"><code>");
            self.name(text);
            self.raw("</code></a>");
        } else {
            self.code(text);
        }
    }

    /// `<a href="href">text</a>`.
    fn link(&mut self, href: &str, text: &str) {
        self.raw("<a href=\"");
        self.text(href);
        self.raw("\">");
        self.text(text);
        self.raw("</a>");
    }

    /// `<code>text</code>`.
    fn code(&mut self, text: &str) {
        self.raw("<code>");
        self.name(text);
        self.raw("</code>");
    }

    /// `peers(row)` (see `builtins::peers`).
    fn peers(&mut self, peers: &[super::Link], more: &Option<super::Link>) {
        if peers.is_empty() {
            self.raw("<span class=\"none\">—</span>");
            return;
        }
        self.raw("<ul class=\"peers\">\n");
        for l in peers {
            self.link_item(false, &l.href, &l.text);
        }
        if let Some(m) = more {
            self.link_item(true, &m.href, &m.text);
        }
        self.raw("</ul>");
    }

    /// The cells a data port row and a service interface row share: direction, name and type
    /// (labelled `type_key`).
    fn port_row_start(&mut self, c: &PortCells, type_key: &str) {
        self.row_start(&c.anchor);
        self.td("direction");
        self.raw("<span class=\"dir ");
        self.text(c.dir_class);
        self.raw("\">");
        self.text(&c.direction);
        self.raw("</span></td>\n");
        self.name_cell(&c.name, &c.since);
        self.td(type_key);
        self.type_link(&c.type_ref);
        self.raw("</td>\n");
    }

    /// `<tr id="anchor">` and its line break.
    fn row_start(&mut self, anchor: &str) {
        self.raw("<tr id=\"");
        self.text(anchor);
        self.raw("\">\n");
    }

    /// The row header of a port or parameter: `<th scope="row"><code>name</code>`, the since
    /// badge, `</th>` and a line break.
    fn name_cell(&mut self, name: &str, since: &Option<String>) {
        self.raw("<th scope=\"row\"><code>");
        self.name(name);
        self.raw("</code>");
        self.since(since);
        self.raw("</th>\n");
    }

    /// `<tr><th scope="row"><code>key</code></th>`: a row of a key-value table opened.
    fn key_row_start(&mut self, key: &str) {
        self.raw("<tr><th scope=\"row\"><code>");
        self.name(key);
        self.raw("</code></th>");
    }

    /// The end of a port row: its description cell (when the table has one) with what `more`
    /// writes after the facts, its "connects to" cell (when the table has one), `</tr>`.
    fn port_row_end(&mut self, c: &PortCells, cols: &super::Columns, more: impl FnOnce(&mut Self)) {
        if cols.description {
            self.desc_cell(&c.details, more);
        }
        if cols.peers {
            self.td("connects_to");
            self.peers(&c.peers, &c.peers_more);
            self.raw("</td>\n");
        }
        self.raw("</tr>\n");
    }

    /// `<td data-label="{{ t.key }}">`: the label stacked rows (cards) show at narrow widths.
    fn td(&mut self, key: &str) {
        self.raw("<td data-label=\"");
        self.label(key);
        self.raw("\">");
    }

    /// `<td data-label="{{ t.key }}">{{ value }}</td>`, then `end`.
    fn cell(&mut self, key: &str, value: &str, end: &str) {
        self.td(key);
        self.text(value);
        self.raw("</td>");
        self.raw(end);
    }

    /// [`Out::cell`] with the value in `<code>`.
    fn code_cell(&mut self, key: &str, value: &str, end: &str) {
        self.td(key);
        self.code(value);
        self.raw("</td>");
        self.raw(end);
    }

    /// The description cell of a port or parameter row: `<td class="desc" data-label>`,
    /// `fields(details)` and what `more` writes after them.
    fn desc_cell(&mut self, details: &[Field], more: impl FnOnce(&mut Self)) {
        self.raw("<td class=\"desc\" data-label=\"");
        self.label("description");
        self.raw("\">");
        self.fields(details);
        more(self);
        self.raw("</td>\n");
    }

    /// `<li[ class="more"]><a href="href">text</a></li>` and a line break.
    fn link_item(&mut self, more: bool, href: &str, text: &str) {
        self.raw(if more {
            "<li class=\"more\"><a href=\""
        } else {
            "<li><a href=\""
        });
        self.text(href);
        self.raw("\">");
        self.text(text);
        self.raw("</a></li>\n");
    }

    /// `<th scope="col">{{ t.key }}</th>` for each key.
    fn head_cells(&mut self, keys: &[&str]) {
        for k in keys {
            self.raw("<th scope=\"col\">");
            self.label(k);
            self.raw("</th>");
        }
    }

    /// `{% if cond %}<li><a href="#id">{{ t.key }}</a></li>{% endif %}` and its line break.
    fn toc_entry(&mut self, cond: bool, id: &str, key: &str) {
        self.toc_item(cond, id, key);
        self.raw("\n");
    }

    /// [`Out::toc_entry`] without the line break.
    fn toc_item(&mut self, cond: bool, id: &str, key: &str) {
        if cond {
            self.raw("<li><a href=\"#");
            self.raw(id);
            self.raw("\">");
            self.label(key);
            self.raw("</a></li>");
        }
    }

    /// A section holding one table of `rows`, nothing when there are none: `<section id>`,
    /// `<h2>{{ t.key }}</h2>`, the table (`class` and `heads` as [`Out::table_wrap`]), `row`
    /// for each row, and the ends of all.
    fn table<T>(
        &mut self,
        (id, key): (&str, &str),
        (class, heads): (&str, &[&str]),
        rows: &[T],
        mut row: impl FnMut(&mut Self, &T),
    ) {
        if rows.is_empty() {
            return;
        }
        self.section_start(id, false, key);
        self.table_wrap(class, heads);
        for r in rows {
            row(self, r);
        }
        self.table_wrap_end();
        self.raw("</section>");
    }

    /// The table-wrap `<div>`, `<table>` with `class` (none when empty), the header row of
    /// `heads` labels and `<tbody>`.
    fn table_wrap(&mut self, class: &str, heads: &[&str]) {
        self.raw("<div class=\"table-wrap\">\n");
        self.table_head(class, heads);
        self.raw("<tbody>\n");
    }

    /// `<table[ class]>` and its header row.
    fn table_head(&mut self, class: &str, heads: &[&str]) {
        if class.is_empty() {
            self.raw("<table>\n<thead><tr>");
        } else {
            self.raw("<table class=\"");
            self.raw(class);
            self.raw("\">\n<thead><tr>");
        }
        self.head_cells(heads);
        self.raw("</tr></thead>\n");
    }

    /// Closes what [`Out::table_wrap`] opened.
    fn table_wrap_end(&mut self) {
        self.raw("</tbody>\n</table>\n</div>\n");
    }

    /// `<section id="…"[ class="card"]>` + `<h2>{{ t.key }}</h2>`.
    fn section_start(&mut self, id: &str, card: bool, key: &str) {
        self.raw("<section id=\"");
        self.raw(id);
        self.raw(if card {
            "\" class=\"card\">\n<h2>"
        } else {
            "\">\n<h2>"
        });
        self.label(key);
        self.raw("</h2>\n");
    }

    /// `{{ t.key }}` between the markup `open` and `close`.
    fn label_in(&mut self, open: &str, key: &str, close: &str) {
        self.raw(open);
        self.label(key);
        self.raw(close);
    }
}

/// The header labels of a table: `always`, then the optional columns `cols` shows.
fn heads(always: &[&'static str], cols: &Columns) -> Vec<&'static str> {
    always.iter().copied().chain(cols.shown()).collect()
}

/// The whole component page, as `component.html` (extending `base.html`) renders `page`.
pub(super) fn component_page(page: &ComponentPage, g: &Globals<'_>) -> String {
    // The drawings are most of a large page; the rest is rarely over 24 KB.
    let drawings = page.diagram_svg.len() + page.lifecycle_svg.len() + page.neighbourhood_svg.len();
    let mut o = Out {
        buf: String::with_capacity(24 * 1024 + drawings),
        g,
    };
    base_top(
        &mut o,
        &Head {
            root: page.root,
            title: &page.title,
            description: &page.description,
            crumbs: &page.crumbs,
            current: &page.name,
        },
    );
    main_block(&mut o, page);
    base_bottom(&mut o);
    // Pages wait in the writer's queue: keep only what they use (a page is about 20 KB).
    o.buf.shrink_to_fit();
    o.buf
}

/// What `base.html` prints of a page besides the globals.
struct Head<'p> {
    root: &'p str,
    title: &'p str,
    /// Empty: the title stands for it.
    description: &'p str,
    crumbs: &'p [super::Link],
    /// The last breadcrumb (`{% block current %}`).
    current: &'p str,
}

/// `base.html` up to `{% block main %}`.
fn base_top(o: &mut Out<'_>, page: &Head<'_>) {
    let root = page.root;
    o.raw("<!DOCTYPE html>\n<html lang=\"");
    o.text(o.g.lang.tag());
    o.raw("\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<meta name=\"generator\" content=\"");
    o.text(o.g.generator);
    o.raw("\">\n<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; object-src 'none'; base-uri 'none'; form-action 'self'\">\n<title>");
    o.text(page.title);
    o.raw("</title>\n<meta name=\"description\" content=\"");
    o.text(if page.description.is_empty() {
        page.title
    } else {
        page.description
    });
    o.raw("\">\n<link rel=\"icon\" href=\"");
    o.text(root);
    o.raw("favicon.svg\" type=\"image/svg+xml\">\n<link rel=\"stylesheet\" href=\"");
    o.text(root);
    o.raw("style.css\">\n<script src=\"");
    o.text(root);
    o.raw("search.js\" defer></script>\n");
    if o.g.has_feed {
        o.raw("<link rel=\"alternate\" type=\"application/atom+xml\" href=\"");
        o.text(root);
        o.raw("feed.xml\" title=\"");
        o.label("feed_title");
        o.raw("\">\n");
    }
    o.raw("\n</head>\n<body data-root=\"");
    o.text(root);
    o.raw("\">\n<a class=\"skip\" href=\"#main\">");
    o.label("skip");
    o.raw("</a>\n<header class=\"site-header\">\n<div class=\"bar\">\n<a class=\"brand\" href=\"");
    o.text(root);
    o.raw("index.html\">");
    o.text(o.g.site_title);
    o.raw("</a>\n<form class=\"search\" role=\"search\" action=\"");
    o.text(root);
    o.raw("search.html\" method=\"get\">\n<label for=\"search-input\" class=\"visually-hidden\">");
    o.label("search");
    o.raw("</label>\n<input id=\"search-input\" name=\"q\" type=\"search\" placeholder=\"");
    o.label("search_placeholder");
    o.raw("\" autocomplete=\"off\" aria-describedby=\"search-help\" aria-controls=\"search-popup\">\n<span id=\"search-help\" class=\"visually-hidden\">");
    o.label("search_help");
    o.raw("</span>\n<div id=\"search-popup\" class=\"search-popup\" hidden></div>\n</form>\n");
    o.raw("<nav class=\"site-nav\" aria-label=\"");
    o.label("main_nav");
    o.raw("\">\n<ul>\n");
    for (shown, path, key) in [
        (true, "index.html", "components"),
        (true, "types/index.html", "data_types"),
        (true, "interfaces/index.html", "interfaces"),
        (true, "categories/index.html", "categories"),
        (true, "vendors/index.html", "vendors"),
        (true, "dataflow.html", "dataflow"),
        (o.g.has_history, "whats-new.html", "whats_new"),
        (o.g.has_systems, "systems/index.html", "systems"),
    ] {
        if shown {
            nav_item(o, root, path, key);
            o.raw("\n");
        }
    }
    if o.g.has_diagnostics {
        nav_item(o, root, "diagnostics.html", "diagnostics");
    }
    o.raw("\n</ul>\n</nav>\n</div>\n</header>\n");
    if !page.crumbs.is_empty() {
        o.label_in(
            "<nav class=\"crumbs\" aria-label=\"",
            "breadcrumbs",
            "\">\n<ol>\n",
        );
        for c in page.crumbs {
            o.link_item(false, &c.href, &c.text);
        }
        o.raw("<li aria-current=\"page\">");
        o.text(page.current);
        o.raw("</li>\n</ol>\n</nav>");
    }
    o.raw("\n<main id=\"main\">\n");
}

/// An entry of the site navigation: `<li><a href="{{ root }}path">{{ t.key }}</a></li>`.
fn nav_item(o: &mut Out<'_>, root: &str, path: &str, key: &str) {
    o.raw("<li><a href=\"");
    o.text(root);
    o.raw(path);
    o.raw("\">");
    o.label(key);
    o.raw("</a></li>");
}

/// `base.html` after `{% endblock %}` of `main`.
fn base_bottom(o: &mut Out<'_>) {
    o.raw("\n</main>\n<footer class=\"site-footer\">\n<p>");
    o.text(o.g.site_title);
    o.raw(" · ");
    o.text(o.g.generator);
    o.raw("</p>\n</footer>\n</body>\n</html>");
}

/// `{% if stability %}{{ stability_line(stability) }}{% endif %}` (the macro of `macros.html`).
fn stability_line(o: &mut Out<'_>, s: Option<&super::StabilityLine>) {
    let Some(s) = s else {
        return;
    };
    o.raw("<p class=\"stability ");
    o.text(s.class);
    o.raw("\" role=\"note\"><strong>");
    o.text(&s.headline);
    o.raw("</strong>");
    if let Some(r) = &s.replacement {
        o.raw(" — ");
        o.text(s.use_before);
        if r.href.is_empty() {
            o.code(&r.text);
        } else {
            o.raw("<a href=\"");
            o.text(&r.href);
            o.raw("\">");
            o.code(&r.text);
            o.raw("</a>");
        }
        o.text(s.use_after);
    }
    if let Some(n) = s.note.as_deref().filter(|n| !n.is_empty()) {
        o.raw(". ");
        o.text(n);
    }
    o.raw("</p>\n");
}

/// `component.html`'s `{% block main %}`.
fn main_block(o: &mut Out<'_>, p: &ComponentPage) {
    o.raw("\n<article class=\"component\">\n<h1>");
    o.text(&p.name);
    o.raw("</h1>\n");
    stability_line(o, p.stability.as_ref());
    if p.implementation.as_ref().is_some_and(|i| i.recovered) {
        o.raw("<p class=\"note\"><a href=\"#implementation\">");
        o.label("impl_recovered_note");
        o.raw("</a></p>\n");
    }
    if let Some(s) = p.summary_html.as_deref().filter(|s| !s.is_empty()) {
        o.raw("<div class=\"summary\">");
        o.raw(s);
        o.raw("</div>");
    }
    o.raw("\n<nav class=\"toc\" aria-label=\"");
    o.label("component");
    o.raw("\">\n<ul>\n");
    o.toc_item(!p.document.is_empty(), "document", "document");
    o.toc_entry(p.readme_html.is_some(), "readme", "readme");
    o.toc_entry(true, "diagram", "component_diagram");
    o.toc_entry(!p.data_ports.is_empty(), "data-ports", "data_ports");
    o.toc_entry(
        !p.service_ports.is_empty(),
        "service-ports",
        "service_ports",
    );
    o.toc_entry(true, "neighbourhood", "neighbourhood");
    o.toc_entry(
        !p.configurations.is_empty(),
        "configuration",
        "configuration",
    );
    o.toc_entry(true, "lifecycle", "actions");
    o.toc_entry(!p.parameters.is_empty(), "parameters", "parameters");
    o.toc_entry(
        !p.language.is_empty() || !p.targets.is_empty(),
        "language",
        "language",
    );
    o.toc_entry(!p.properties.is_empty(), "properties", "properties");
    o.toc_entry(!p.version_up_logs.is_empty(), "history", "version_up_logs");
    if !p.systems.is_empty() {
        o.toc_entry(true, "systems", "sys_used_by");
    }
    if !p.backups.is_empty() {
        o.toc_entry(true, "backups", "backups");
    }
    if p.implementation.is_some() {
        o.toc_entry(true, "implementation", "implementation");
    }
    if !p.history.is_empty() {
        o.toc_entry(true, "change-history", "change_history");
    }
    o.toc_entry(!p.extras.is_empty(), "extra", "extra");
    o.raw("</ul>\n</nav>\n\n");

    o.section_start("overview", true, "component");
    o.fields(&p.header);
    o.raw("\n</section>\n\n");

    if !p.document.is_empty() {
        o.section_start("document", true, "document");
        o.fields(&p.document);
        o.raw("\n</section>");
    }
    if let Some(h) = &p.readme_html {
        o.raw("\n\n");
        o.section_start("readme", true, "readme");
        o.raw("<div class=\"readme\">");
        o.raw(h);
        o.raw("</div>\n</section>");
    }
    o.raw("\n\n");

    o.section_start("diagram", false, "component_diagram");
    o.raw("<div class=\"diagram-wrap\"><div class=\"diagram-scroll\">");
    o.raw(&p.diagram_svg);
    o.raw("</div></div>\n</section>\n\n");

    data_ports(o, p);
    o.raw("\n\n");
    service_ports(o, p);
    o.raw("\n\n");
    neighbourhood(o, p);
    o.raw("\n\n");
    configurations(o, p);
    o.raw("\n\n");
    lifecycle(o, p);
    o.raw("\n\n");
    rest(o, p);
    o.raw("\n</article>\n");
}

fn data_ports(o: &mut Out<'_>, p: &ComponentPage) {
    let cols = &p.data_cols;
    let heads = heads(&["direction", "name", "type"], cols);
    o.table(
        ("data-ports", "data_ports"),
        ("ports", &heads),
        &p.data_ports,
        |o, r| {
            o.port_row_start(&r.port, "type");
            if cols.unit {
                o.cell("unit", &r.unit, "\n");
            }
            o.port_row_end(&r.port, cols, |o| events(o, &r.events));
        },
    );
}

/// A data port's events, in its description cell.
fn events(o: &mut Out<'_>, events: &[EventRow]) {
    if events.is_empty() {
        return;
    }
    o.label_in(
        "<div class=\"events\"><strong>",
        "events",
        "</strong>\n<ul>\n",
    );
    for e in events {
        o.raw("<li>");
        o.code(&e.name);
        o.fields(&e.fields);
        o.raw("</li>\n");
    }
    o.raw("</ul>\n</div>");
}

fn service_ports(o: &mut Out<'_>, p: &ComponentPage) {
    if p.service_ports.is_empty() {
        return;
    }
    let cols = &p.service_cols;
    o.section_start("service-ports", false, "service_ports");
    o.raw("<div class=\"table-wrap\">\n");
    o.table_head(
        "ports",
        &heads(&["direction", "name", "interface_type"], cols),
    );
    for sp in &p.service_ports {
        o.raw("<tbody>\n<tr id=\"");
        o.text(&sp.anchor);
        o.raw("\" class=\"sport\"><th scope=\"rowgroup\" colspan=\"");
        o.raw(&cols.span.to_string());
        o.raw("\"><span class=\"dir service\">");
        o.label("port");
        o.raw("</span> ");
        o.code(&sp.name);
        o.since(&sp.since);
        o.fields(&sp.details);
        o.raw("</th></tr>\n");
        for i in &sp.interfaces {
            o.port_row_start(&i.port, "interface_type");
            o.port_row_end(&i.port, cols, |_| {});
        }
        o.raw("</tbody>\n");
    }
    o.raw("</table>\n</div>\n</section>");
}

/// The neighbourhood: its drawing and list, or the sentence saying there is none.
fn neighbourhood(o: &mut Out<'_>, p: &ComponentPage) {
    o.section_start("neighbourhood", false, "neighbourhood");
    if p.neighbourhood.is_empty() {
        o.raw("<p class=\"none\">");
        o.label("neighbourhood_none");
        o.raw("</p>\n</section>");
        return;
    }
    o.raw("<p>");
    o.label("neighbourhood_intro");
    o.raw(" ");
    o.label("neighbourhood_drawing");
    o.raw("</p>\n<div class=\"diagram-wrap\"><div class=\"diagram-scroll\">");
    o.raw(&p.neighbourhood_svg);
    o.raw("</div></div>\n<ul class=\"neighbourhood\">\n");
    for r in &p.neighbourhood {
        o.raw("<li><a href=\"");
        o.text(&r.port.href);
        o.raw("\"><code>");
        o.name(&r.port.text);
        o.raw("</code></a> (");
        o.type_link(&r.type_ref);
        o.raw(") ");
        o.text(r.relation);
        o.raw(":");
        o.peers(&r.peers, &r.peers_more);
        o.raw("</li>\n");
    }
    o.raw("</ul>\n</section>");
}

fn configurations(o: &mut Out<'_>, p: &ComponentPage) {
    let cols = &p.config_cols;
    let heads = heads(&["name", "type", "default_value"], cols);
    let rows = &p.configurations;
    o.table(
        ("configuration", "configuration"),
        ("config", &heads),
        rows,
        |o, c| {
            o.row_start(&c.anchor);
            o.name_cell(&c.name, &c.since);
            o.code_cell("type", &c.type_, "\n");
            o.code_cell("default_value", &c.default, "\n");
            for (shown, key, value) in [
                (cols.unit, "unit", &c.unit),
                (cols.constraint, "constraint", &c.constraint),
                (cols.widget, "widget", &c.widget),
            ] {
                if shown {
                    o.cell(key, value, "\n");
                }
            }
            if cols.description {
                o.desc_cell(&c.details, |_| {});
            }
            o.raw("</tr>\n");
        },
    );
}

fn lifecycle(o: &mut Out<'_>, p: &ComponentPage) {
    o.section_start("lifecycle", false, "actions");
    // A region the keyboard can scroll (the drawing has no link to take the focus).
    o.raw("<div class=\"diagram-wrap\"><div class=\"diagram-scroll\" tabindex=\"0\" role=\"region\" aria-label=\"");
    o.label("actions");
    o.raw("\">");
    o.raw(&p.lifecycle_svg);
    o.raw("</div></div>\n");
    let cols = &p.action_cols;
    o.table_wrap("actions", &heads(&["callback", "implemented"], cols));
    for a in &p.actions {
        o.raw("<tr id=\"action-");
        o.text(a.name);
        o.raw(if a.implemented {
            "\" class=\"impl\">\n<th scope=\"row\"><code>"
        } else {
            "\" class=\"not-impl\">\n<th scope=\"row\"><code>"
        });
        o.name(a.name);
        o.raw("</code></th>\n");
        o.td("implemented");
        if a.implemented {
            o.raw("<span class=\"yes\">✔ ");
            o.label("yes");
        } else {
            o.raw("<span class=\"no\">");
            o.label("no");
        }
        o.raw("</span></td>\n");
        if cols.description {
            o.td("description");
            o.fields(&a.details);
            o.raw("</td>\n");
        }
        o.raw("</tr>\n");
    }
    o.table_wrap_end();
    o.raw("</section>");
}

/// The parameters or properties section (`id` is also its label key): nothing when `rows` is
/// empty; values in `<code>` when `code`; the value cells labelled as `heads[1]`.
fn key_value_table(o: &mut Out<'_>, id: &str, heads: &[&str], rows: &[KeyValue], code: bool) {
    o.table((id, id), ("", heads), rows, |o, kv| {
        o.key_row_start(&kv.key);
        if code {
            o.code_cell(heads[1], &kv.value, "</tr>\n");
        } else {
            o.cell(heads[1], &kv.value, "</tr>\n");
        }
    });
}

/// Parameters, language, properties, version history and extra properties.
fn rest(o: &mut Out<'_>, p: &ComponentPage) {
    key_value_table(
        o,
        "parameters",
        &["name", "default_value"],
        &p.parameters,
        true,
    );
    o.raw("\n\n");
    if !p.language.is_empty() || !p.targets.is_empty() {
        o.section_start("language", true, "language");
        o.fields(&p.language);
        o.raw("\n");
        if !p.targets.is_empty() {
            o.label_in("<h3>", "targets", "</h3>\n");
            for tg in &p.targets {
                o.raw("<div class=\"target\">\n<h4>");
                o.label("fact_target");
                o.raw(" ");
                o.raw(&tg.number.to_string());
                o.raw("</h4>\n");
                o.fields(&tg.fields);
                o.raw("\n</div>\n");
            }
        }
        o.raw("\n</section>");
    }
    o.raw("\n\n");
    key_value_table(o, "properties", &["key", "value"], &p.properties, false);
    o.raw("\n\n");
    if !p.version_up_logs.is_empty() {
        o.section_start("history", false, "version_up_logs");
        o.raw("<ul class=\"history\">\n");
        for v in &p.version_up_logs {
            o.raw("<li>");
            o.text(v);
            o.raw("</li>\n");
        }
        o.raw("</ul>\n</section>");
    }
    o.raw("\n\n");
    if !p.systems.is_empty() {
        o.section_start("systems", false, "sys_used_by");
        o.raw("<ul class=\"links\">\n");
        for l in &p.systems {
            o.link_item(false, &l.href, &l.text);
        }
        o.raw("</ul>\n</section>\n\n");
    }
    if !p.backups.is_empty() {
        o.section_start("backups", false, "backups");
        o.label_in("<p>", "backups_intro", "</p>\n");
        o.table_wrap("", &["backup_file", "backup_saved", "backup_declares"]);
        for b in &p.backups {
            o.key_row_start(&b.file);
            o.cell("backup_saved", &b.saved, "");
            o.cell("backup_declares", &b.declares, "</tr>\n");
        }
        o.table_wrap_end();
        o.raw("</section>\n\n");
    }
    if let Some(im) = &p.implementation {
        implementation_section(o, im);
    }
    history_section(o, p);
    let heads = ["extra_path", "extra_kind", "value"];
    o.table(("extra", "extra"), ("", &heads), &p.extras, |o, e| {
        o.key_row_start(&e.name);
        o.cell("extra_kind", e.kind, "");
        o.cell("value", &e.value, "</tr>\n");
    });
}

/// The History section (`{% if history %}` in `component.html`).
fn history_section(o: &mut Out<'_>, p: &ComponentPage) {
    if p.history.is_empty() {
        return;
    }
    o.section_start("change-history", false, "change_history");
    o.label_in("<p>", "history_intro", "</p>\n");
    history_table(
        o,
        &p.history,
        p.history_older.as_deref(),
        p.history_page.as_deref(),
    );
    if let Some(href) = &p.history_page {
        o.raw("<p><a href=\"");
        o.text(href);
        o.raw("\">");
        o.label("history_full");
        o.raw("</a></p>\n");
    }
    o.raw("</section>\n\n");
}

/// The `history_table` macro: a history's latest versions and the note on older ones;
/// `full_page` is the history page, which a row's "more changes" links.
fn history_table(
    o: &mut Out<'_>,
    rows: &[HistoryRow],
    older: Option<&str>,
    full_page: Option<&str>,
) {
    o.table_wrap(
        "history-table",
        &[
            "history_version",
            "history_date",
            "history_commit",
            "history_author",
            "history_subject",
            "history_changes",
        ],
    );
    for h in rows {
        // A folded row has no version: no empty row header (axe: empty-table-header).
        if h.version.is_empty() {
            o.raw("<tr><td></td>");
        } else {
            o.raw("<tr><th scope=\"row\">");
            o.text(&h.version);
            o.raw("</th>");
        }
        o.cell("history_date", &h.date, "");
        o.td("history_commit");
        match h.url.as_deref().filter(|u| !u.is_empty()) {
            Some(url) => o.code_link(Some(url), &h.label),
            None if !h.label.is_empty() => o.code(&h.label),
            None => {}
        }
        o.raw("</td>");
        o.cell("history_author", &h.author, "");
        o.cell("history_subject", &h.subject, "");
        o.td("history_changes");
        o.text(&h.summary);
        if !h.changes.is_empty() {
            o.raw("<ul>");
            for c in &h.changes {
                o.raw("<li><span class=\"sev ");
                o.text(&c.severity);
                o.raw("\">");
                o.text(&c.severity_label);
                o.raw("</span> ");
                if !c.path.is_empty() {
                    o.code(&c.path);
                    o.raw(": ");
                }
                o.text_with_code(&c.message);
                if let Some(reach) = &c.reach {
                    o.raw(" <span class=\"reach\">");
                    o.text(reach);
                    o.raw("</span>");
                }
                o.raw("</li>");
            }
            if let Some(more) = h.more.as_deref().filter(|m| !m.is_empty()) {
                o.raw("<li>");
                match full_page.filter(|p| !p.is_empty()) {
                    Some(page) => {
                        o.raw("<a href=\"");
                        o.text(page);
                        o.raw("#");
                        o.text(&h.anchor);
                        o.raw("\">");
                        o.text(more);
                        o.raw("</a>");
                    }
                    None => o.text(more),
                }
                o.raw("</li>");
            }
            o.raw("</ul>");
        }
        o.raw("</td></tr>\n");
    }
    o.table_wrap_end();
    if let Some(n) = older.filter(|n| !n.is_empty()) {
        o.raw("<p>");
        o.text(n);
        o.raw("</p>\n");
    }
}

/// The Implementation section of a component page (`component.html`'s `implementation`).
fn implementation_section(o: &mut Out<'_>, im: &crate::render::facts::ImplementationSection) {
    o.section_start("implementation", false, "implementation");
    o.label_in("<p>", im.intro, "</p>\n");
    o.raw(if im.matches {
        "<p class=\"impl-state ok\"><strong>"
    } else {
        "<p class=\"impl-state drift\"><strong>"
    });
    o.text(&im.summary);
    o.raw("</strong></p>\n");
    o.label_in("<h3>", "impl_files", "</h3>\n");
    o.raw("<ul class=\"links\">\n");
    for f in &im.files {
        o.raw("<li>");
        o.code_link(f.href.as_deref(), &f.text);
        o.raw("</li>\n");
    }
    o.raw("</ul>\n");
    if !im.rows.is_empty() {
        o.table_wrap(
            "",
            &[
                "impl_element",
                "impl_profile_says",
                "impl_code_says",
                "impl_where",
            ],
        );
        for r in &im.rows {
            o.key_row_start(&r.element);
            o.cell("impl_profile_says", &r.profile, "");
            o.cell("impl_code_says", &r.code, "");
            o.td("impl_where");
            o.code(&r.at);
            o.raw(" (");
            o.text(r.rule);
            o.raw(")</td></tr>\n");
        }
        o.table_wrap_end();
    }
    for (label, items) in [
        ("impl_unread", &im.unread),
        ("impl_unverified", &im.unverified),
    ] {
        if items.is_empty() {
            continue;
        }
        o.label_in("<p>", label, "</p>\n<ul>\n");
        for u in items {
            o.raw("<li>");
            o.text(u);
            o.raw("</li>\n");
        }
        o.raw("</ul>\n");
    }
    o.raw("</section>\n\n");
}
