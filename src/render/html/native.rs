//! The component page of the built-in theme, written by Rust code instead of by running the
//! templates `base.html` + `component.html` in minijinja.
//!
//! Component pages are most of a site (10,000 of 14,000 files for 10,000 profiles) and running
//! their template was a third of the build's instructions. When the theme directory overrides
//! neither `base.html` nor `component.html`, [`component_page`] writes the page directly, byte
//! for byte what the templates produce: the tests render every page both ways and compare (the
//! examples, the hostile fixtures, generated catalogues and, when present, the real-world
//! corpus). The templates stay the documented source of the markup and are what a theme that
//! overrides either file runs. A change to either template must be made here too — the tests
//! fail until it is.

use super::svg::esc_into;
use super::{ComponentPage, Field, KeyValue, PortTypeRef};
use crate::i18n::Lang;

/// The template globals the page prints.
pub(super) struct Globals<'a> {
    pub lang: Lang,
    pub site_title: &'a str,
    pub has_diagnostics: bool,
    pub has_systems: bool,
    /// Some component has a history: the What's new page exists.
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
        let Some(r) = r else { return };
        match r.href.as_deref() {
            Some(href) if !href.is_empty() => {
                self.raw("<a href=\"");
                self.text(href);
                self.raw("\"><code>");
                self.text(&r.text);
                self.raw("</code></a>");
            }
            _ => {
                self.raw("<code>");
                self.text(&r.text);
                self.raw("</code>");
            }
        }
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
    fn port_row_start(
        &mut self,
        anchor: &str,
        dir_class: &str,
        direction: &str,
        (name, since): (&str, &Option<String>),
        type_ref: &Option<PortTypeRef>,
        type_key: &str,
    ) {
        self.raw("<tr id=\"");
        self.text(anchor);
        self.raw("\">\n");
        self.td("direction");
        self.raw("<span class=\"dir ");
        self.text(dir_class);
        self.raw("\">");
        self.text(direction);
        self.raw("</span></td>\n<th scope=\"row\"><code>");
        self.text(name);
        self.raw("</code>");
        self.since(since);
        self.raw("</th>\n");
        self.td(type_key);
        self.type_link(type_ref);
        self.raw("</td>\n");
    }

    /// The "connects to" cell when `shown`, and the end of the row.
    fn peers_cell(&mut self, shown: bool, peers: &[super::Link], more: &Option<super::Link>) {
        if shown {
            self.td("connects_to");
            self.peers(peers, more);
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

    /// The description cell of a port or parameter row: `<td class="desc" data-label>`.
    fn td_desc(&mut self) {
        self.raw("<td class=\"desc\" data-label=\"");
        self.label("description");
        self.raw("\">");
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

    /// A section holding one table: `<section id>`, `<h2>`, the table-wrap `<div>`, `<table>`
    /// with `class` (none when empty), the header row of `heads` labels and `<tbody>`.
    fn table_start(&mut self, id: &str, key: &str, class: &str, heads: &[&str]) {
        self.section_start(id, false, key);
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

    /// Closes what [`Out::table_start`] opened.
    fn table_end(&mut self) {
        self.raw("</tbody>\n</table>\n</div>\n</section>");
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
}

/// The whole component page, as `component.html` (extending `base.html`) renders `page`.
pub(super) fn component_page(page: &ComponentPage, g: &Globals<'_>) -> String {
    // The drawings are most of a large page; the rest is rarely over 24 KB.
    let drawings = page.diagram_svg.len() + page.lifecycle_svg.len() + page.neighbourhood_svg.len();
    let mut o = Out {
        buf: String::with_capacity(24 * 1024 + drawings),
        g,
    };
    base_top(&mut o, page);
    main_block(&mut o, page);
    base_bottom(&mut o);
    // Pages wait in the writer's queue: keep only what they use (a page is about 20 KB).
    o.buf.shrink_to_fit();
    o.buf
}

/// `base.html` up to `{% block main %}`.
fn base_top(o: &mut Out<'_>, page: &ComponentPage) {
    let root = page.root;
    o.raw("<!DOCTYPE html>\n<html lang=\"");
    o.text(o.g.lang.tag());
    o.raw("\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<meta name=\"generator\" content=\"");
    o.text(o.g.generator);
    o.raw("\">\n<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; object-src 'none'; base-uri 'none'; form-action 'self'\">\n<title>");
    o.text(&page.title);
    o.raw("</title>\n<meta name=\"description\" content=\"");
    o.text(if page.description.is_empty() {
        &page.title
    } else {
        &page.description
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
    o.raw("</a>\n<nav class=\"site-nav\" aria-label=\"");
    o.label("main_nav");
    o.raw("\">\n<ul>\n");
    for (path, key) in [
        ("index.html", "components"),
        ("types/index.html", "data_types"),
        ("interfaces/index.html", "interfaces"),
        ("categories/index.html", "categories"),
        ("vendors/index.html", "vendors"),
        ("dataflow.html", "dataflow"),
    ] {
        o.raw("<li><a href=\"");
        o.text(root);
        o.raw(path);
        o.raw("\">");
        o.label(key);
        o.raw("</a></li>\n");
    }
    if o.g.has_history {
        o.raw("<li><a href=\"");
        o.text(root);
        o.raw("whats-new.html\">");
        o.label("whats_new");
        o.raw("</a></li>\n");
    }
    if o.g.has_systems {
        o.raw("<li><a href=\"");
        o.text(root);
        o.raw("systems/index.html\">");
        o.label("systems");
        o.raw("</a></li>\n");
    }
    if o.g.has_diagnostics {
        o.raw("<li><a href=\"");
        o.text(root);
        o.raw("diagnostics.html\">");
        o.label("diagnostics");
        o.raw("</a></li>");
    }
    o.raw("\n</ul>\n</nav>\n<form class=\"search\" role=\"search\" action=\"");
    o.text(root);
    o.raw("search.html\" method=\"get\">\n<label for=\"search-input\" class=\"visually-hidden\">");
    o.label("search");
    o.raw("</label>\n<input id=\"search-input\" name=\"q\" type=\"search\" placeholder=\"");
    o.label("search_placeholder");
    o.raw("\" autocomplete=\"off\" aria-describedby=\"search-help\" aria-controls=\"search-popup\">\n<span id=\"search-help\" class=\"visually-hidden\">");
    o.label("search_help");
    o.raw("</span>\n<div id=\"search-popup\" class=\"search-popup\" hidden></div>\n</form>\n</div>\n</header>\n");
    if !page.crumbs.is_empty() {
        o.raw("<nav class=\"crumbs\" aria-label=\"");
        o.label("breadcrumbs");
        o.raw("\">\n<ol>\n");
        for c in &page.crumbs {
            o.link_item(false, &c.href, &c.text);
        }
        o.raw("<li aria-current=\"page\">");
        o.text(&page.name);
        o.raw("</li>\n</ol>\n</nav>");
    }
    o.raw("\n<main id=\"main\">\n");
}

/// `base.html` after `{% endblock %}` of `main`.
fn base_bottom(o: &mut Out<'_>) {
    o.raw("\n</main>\n<footer class=\"site-footer\">\n<p>");
    o.text(o.g.site_title);
    o.raw(" · ");
    o.text(o.g.generator);
    o.raw("</p>\n</footer>\n</body>\n</html>");
}

/// `component.html`'s `{% block main %}`.
fn main_block(o: &mut Out<'_>, p: &ComponentPage) {
    o.raw("\n<article class=\"component\">\n<h1>");
    o.text(&p.name);
    o.raw("</h1>\n");
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
    if p.data_ports.is_empty() {
        return;
    }
    let cols = &p.data_cols;
    let mut heads = vec!["direction", "name", "type"];
    heads.extend(cols.unit.then_some("unit"));
    heads.extend(cols.description.then_some("description"));
    heads.extend(cols.peers.then_some("connects_to"));
    o.table_start("data-ports", "data_ports", "ports", &heads);
    for r in &p.data_ports {
        o.port_row_start(
            &r.anchor,
            r.dir_class,
            &r.direction,
            (&r.name, &r.since),
            &r.type_ref,
            "type",
        );
        if cols.unit {
            o.td("unit");
            o.text(&r.unit);
            o.raw("</td>\n");
        }
        if cols.description {
            o.td_desc();
            o.fields(&r.details);
            if !r.events.is_empty() {
                o.raw("<div class=\"events\"><strong>");
                o.label("events");
                o.raw("</strong>\n<ul>\n");
                for e in &r.events {
                    o.raw("<li><code>");
                    o.text(&e.name);
                    o.raw("</code>");
                    o.fields(&e.fields);
                    o.raw("</li>\n");
                }
                o.raw("</ul>\n</div>");
            }
            o.raw("</td>\n");
        }
        o.peers_cell(cols.peers, &r.peers, &r.peers_more);
    }
    o.table_end();
}

fn service_ports(o: &mut Out<'_>, p: &ComponentPage) {
    if p.service_ports.is_empty() {
        return;
    }
    o.section_start("service-ports", false, "service_ports");
    o.raw("<div class=\"table-wrap\">\n");
    let cols = &p.service_cols;
    let mut heads = vec!["direction", "name", "interface_type"];
    heads.extend(cols.description.then_some("description"));
    heads.extend(cols.peers.then_some("connects_to"));
    o.table_head("ports", &heads);
    for sp in &p.service_ports {
        o.raw("<tbody>\n<tr id=\"");
        o.text(&sp.anchor);
        o.raw("\" class=\"sport\"><th scope=\"rowgroup\" colspan=\"");
        o.raw(&cols.span.to_string());
        o.raw("\"><span class=\"dir service\">");
        o.label("port");
        o.raw("</span> <code>");
        o.text(&sp.name);
        o.raw("</code>");
        o.since(&sp.since);
        o.fields(&sp.details);
        o.raw("</th></tr>\n");
        for i in &sp.interfaces {
            o.port_row_start(
                &i.anchor,
                i.dir_class,
                &i.direction,
                (&i.name, &i.since),
                &i.type_ref,
                "interface_type",
            );
            if cols.description {
                o.td_desc();
                o.fields(&i.details);
                o.raw("</td>\n");
            }
            o.peers_cell(cols.peers, &i.peers, &i.peers_more);
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
        o.text(&r.port.text);
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
    if p.configurations.is_empty() {
        return;
    }
    let cols = &p.config_cols;
    let mut heads = vec!["name", "type", "default_value"];
    heads.extend(cols.unit.then_some("unit"));
    heads.extend(cols.constraint.then_some("constraint"));
    heads.extend(cols.widget.then_some("widget"));
    heads.extend(cols.description.then_some("description"));
    o.table_start("configuration", "configuration", "config", &heads);
    for c in &p.configurations {
        o.raw("<tr id=\"");
        o.text(&c.anchor);
        o.raw("\">\n<th scope=\"row\"><code>");
        o.text(&c.name);
        o.raw("</code>");
        o.since(&c.since);
        o.raw("</th>\n");
        o.td("type");
        o.raw("<code>");
        o.text(&c.type_);
        o.raw("</code></td>\n");
        o.td("default_value");
        o.raw("<code>");
        o.text(&c.default);
        o.raw("</code></td>\n");
        for (shown, key, value) in [
            (cols.unit, "unit", &c.unit),
            (cols.constraint, "constraint", &c.constraint),
            (cols.widget, "widget", &c.widget),
        ] {
            if shown {
                o.td(key);
                o.text(value);
                o.raw("</td>\n");
            }
        }
        if cols.description {
            o.td_desc();
            o.fields(&c.details);
            o.raw("</td>\n");
        }
        o.raw("</tr>\n");
    }
    o.table_end();
}

fn lifecycle(o: &mut Out<'_>, p: &ComponentPage) {
    o.section_start("lifecycle", false, "actions");
    o.raw("<div class=\"diagram-wrap\">");
    o.raw(&p.lifecycle_svg);
    o.raw("</div>\n<div class=\"table-wrap\">\n");
    let heads: &[&str] = if p.action_cols.description {
        &["callback", "implemented", "description"]
    } else {
        &["callback", "implemented"]
    };
    o.table_head("actions", heads);
    o.raw("<tbody>\n");
    for a in &p.actions {
        o.raw("<tr id=\"action-");
        o.text(a.name);
        o.raw(if a.implemented {
            "\" class=\"impl\">\n<th scope=\"row\"><code>"
        } else {
            "\" class=\"not-impl\">\n<th scope=\"row\"><code>"
        });
        o.text(a.name);
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
        if p.action_cols.description {
            o.td("description");
            o.fields(&a.details);
            o.raw("</td>\n");
        }
        o.raw("</tr>\n");
    }
    o.table_end();
}

/// The parameters or properties section (`id` is also its label key): nothing when `rows` is
/// empty; values in `<code>` when `code`; the value cells labelled as `heads[1]`.
fn key_value_table(o: &mut Out<'_>, id: &str, heads: &[&str], rows: &[KeyValue], code: bool) {
    if rows.is_empty() {
        return;
    }
    o.table_start(id, id, "", heads);
    for kv in rows {
        o.raw("<tr><th scope=\"row\"><code>");
        o.text(&kv.key);
        o.raw("</code></th>");
        o.td(heads[1]);
        if code {
            o.raw("<code>");
        }
        o.text(&kv.value);
        o.raw(if code {
            "</code></td></tr>\n"
        } else {
            "</td></tr>\n"
        });
    }
    o.table_end();
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
            o.raw("<h3>");
            o.label("targets");
            o.raw("</h3>\n");
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
            o.raw("<li><a href=\"");
            o.text(&l.href);
            o.raw("\">");
            o.text(&l.text);
            o.raw("</a></li>\n");
        }
        o.raw("</ul>\n</section>\n\n");
    }
    if !p.backups.is_empty() {
        o.section_start("backups", false, "backups");
        o.raw("<p>");
        o.label("backups_intro");
        o.raw("</p>\n<div class=\"table-wrap\">\n");
        o.table_head("", &["backup_file", "backup_saved", "backup_declares"]);
        o.raw("<tbody>\n");
        for b in &p.backups {
            o.raw("<tr><th scope=\"row\"><code>");
            o.text(&b.file);
            o.raw("</code></th>");
            o.td("backup_saved");
            o.text(&b.saved);
            o.raw("</td>");
            o.td("backup_declares");
            o.text(&b.declares);
            o.raw("</td></tr>\n");
        }
        o.raw("</tbody>\n</table>\n</div>\n</section>\n\n");
    }
    history_section(o, p);
    if !p.extras.is_empty() {
        o.table_start("extra", "extra", "", &["extra_path", "extra_kind", "value"]);
        for e in &p.extras {
            o.raw("<tr><th scope=\"row\"><code>");
            o.text(&e.name);
            o.raw("</code></th>");
            o.td("extra_kind");
            o.text(e.kind);
            o.raw("</td>");
            o.td("value");
            o.text(&e.value);
            o.raw("</td></tr>\n");
        }
        o.table_end();
    }
}

/// The History section (`{% if history %}` in `component.html`).
fn history_section(o: &mut Out<'_>, p: &ComponentPage) {
    if p.history.is_empty() {
        return;
    }
    o.section_start("change-history", false, "change_history");
    o.raw("<p>");
    o.label("history_intro");
    o.raw("</p>\n<div class=\"table-wrap\">\n");
    o.table_head(
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
    o.raw("<tbody>\n");
    for h in &p.history {
        // A folded row has no version: no empty row header (axe: empty-table-header).
        if h.version.is_empty() {
            o.raw("<tr><td></td>");
        } else {
            o.raw("<tr><th scope=\"row\">");
            o.text(&h.version);
            o.raw("</th>");
        }
        o.td("history_date");
        o.text(&h.date);
        o.raw("</td>");
        o.td("history_commit");
        if let Some(url) = &h.url {
            o.raw("<a href=\"");
            o.text(url);
            o.raw("\"><code>");
            o.text(&h.label);
            o.raw("</code></a>");
        } else if !h.label.is_empty() {
            o.raw("<code>");
            o.text(&h.label);
            o.raw("</code>");
        }
        o.raw("</td>");
        o.td("history_author");
        o.text(&h.author);
        o.raw("</td>");
        o.td("history_subject");
        o.text(&h.subject);
        o.raw("</td>");
        o.td("history_changes");
        o.text(&h.summary);
        if !h.breaking.is_empty() {
            o.raw("<ul>");
            for b in &h.breaking {
                o.raw("<li>");
                o.text(b);
                o.raw("</li>");
            }
            o.raw("</ul>");
        }
        o.raw("</td></tr>\n");
    }
    o.raw("</tbody>\n</table>\n</div>\n");
    if let Some(n) = &p.history_older {
        o.raw("<p>");
        o.text(n);
        o.raw("</p>\n");
    }
    if let Some(href) = &p.history_page {
        o.raw("<p><a href=\"");
        o.text(href);
        o.raw("\">");
        o.label("history_full");
        o.raw("</a></p>\n");
    }
    o.raw("</section>\n\n");
}
