//! Doxygen input: `.dox` pages plus a ready `Doxyfile` (spec 10.7: Doxygen is the route to
//! HTML, LaTeX and man pages).
//!
//! Layout: `Doxyfile`, `mainpage.dox` (`\mainpage`), `categories/<slug>.dox`,
//! `components/<slug>.dox`, `types.dox` + `types/<slug>.dox`, `interfaces.dox` +
//! `interfaces/<slug>.dox`. Running `doxygen` in the folder writes `html/`, `latex/`, `man/` and
//! the tag file `rtcdoc.tag`.
//!
//! Labels are globally unique, prefixed and `[a-z0-9_]` only: `rtc_comp_<slug>`,
//! `rtc_type_<slug>`, `rtc_if_<slug>`, `rtc_cat_<slug>`, `rtc_types`, `rtc_interfaces`; section
//! and row anchors are `<page label>__<anchor>` (a double underscore, which no slug contains, so
//! a row anchor can never equal another page's label). The page tree is
//! mainpage → category pages → component pages, mainpage → type index → type pages and
//! mainpage → interface index → interface pages: every page is the target of exactly one
//! `\subpage`; all other links are `\ref`.
//!
//! Escaping choices: pages are written as `///` comment blocks, so a `*/` in profile text cannot
//! end the comment; the Doxyfile sets `MARKDOWN_SUPPORT = NO` (no Markdown syntax to neutralise;
//! tables are Doxygen's HTML `<table>` commands) and `AUTOLINK_SUPPORT = NO`; profile text goes
//! through [`text`] (every Doxygen metacharacter backslash-escaped, line breaks as `<br>`, never
//! a raw newline, so no profile line can start a Doxygen list), page titles through [`title`].

use super::text::{
    category_name, component_cols, component_sections, interface_index_table, names_facts,
    type_index_table, Markup,
};
use super::{RenderContext, Renderer};
use crate::catalog::{Catalog, Component, InterfaceRef, Output, Page, PageKind, PortRef};
use crate::i18n::Lang;
use crate::model::{self};
use crate::output::Sink;
use rayon::prelude::*;
use std::fmt::Write as _;

/// At most this many "connects to" peers are listed per port (shared with Markdown).
pub use super::text::PEER_CAP;

/// Writes the `.dox` pages and the `Doxyfile`.
pub struct DoxygenRenderer;

/// A `///` comment line into a `String` (cannot fail).
macro_rules! d {
    ($dst:expr) => { $dst.push_str("///\n") };
    ($dst:expr, $($arg:tt)*) => {{
        $dst.push_str("/// ");
        let _ = writeln!($dst, $($arg)*);
    }};
}

/// Bytes after which [`push_escaped_chars`] may write something other than the byte itself:
/// the always-escaped characters, `#` and `:` (escaped in full mode), `-` (dash runs), and
/// control characters (ASCII, DEL, and 0xC2, the lead byte of U+0080–U+009F).
static DOX_SPECIAL: [bool; 256] = super::byte_set(true, b"\\@<>&%$\"#:-\x7f\xc2");

/// Whether `s` comes out of [`push_escaped_chars`] unchanged, decided bytewise: true for most
/// profile text (a single `-` or `:` is plain; two in a row are not).
fn needs_no_escaping(s: &str) -> bool {
    let b = s.as_bytes();
    b.iter().enumerate().all(|(i, &c)| match c {
        b'-' | b':' => b.get(i + 1) != Some(&c),
        _ => !DOX_SPECIAL[usize::from(c)],
    })
}

fn push_escaped(s: &str, out: &mut String, full: bool) {
    if needs_no_escaping(s) {
        out.push_str(s);
    } else {
        push_escaped_chars(s, out, full);
    }
}

fn push_escaped_chars(s: &str, out: &mut String, full: bool) {
    let chars: Vec<char> = s.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        match ch {
            '\\' | '@' | '<' | '>' | '&' | '%' | '$' | '"' => {
                out.push('\\');
                out.push(ch);
            }
            '#' if full => out.push_str("\\#"),
            ':' if full && chars.get(i + 1) == Some(&':') => {
                out.push_str("\\::");
                i += 1;
            }
            '-' if chars.get(i + 1) == Some(&'-') => {
                // `--` and `---` become dashes in Doxygen; `\--` / `\---` keep them literal.
                let mut n = chars[i..].iter().take_while(|&&c| c == '-').count();
                i += n - 1;
                while n > 0 {
                    match n {
                        1 => {
                            out.push('-');
                            n = 0;
                        }
                        3 => {
                            out.push_str("\\---");
                            n = 0;
                        }
                        _ => {
                            out.push_str("\\--");
                            n -= 2;
                        }
                    }
                }
            }
            '\t' => out.push(' '),
            c if c.is_control() => {}
            c => out.push(c),
        }
        i += 1;
    }
}

/// Escapes profile text for Doxygen body text (table cells, paragraphs, `\ref` link text):
/// `\ @ < > & % $ " #`, `::` and dash runs are escaped, line breaks become `<br>`; the result is
/// one physical line.
pub fn text(s: &str) -> String {
    let s = crate::model::prose(s);
    let mut out = String::with_capacity(s.len() + 8);
    for (i, line) in s.trim().lines().enumerate() {
        if i > 0 {
            out.push_str("<br>");
        }
        push_escaped(line.trim(), &mut out, true);
    }
    out
}

/// Escapes a page or section title: titles are not auto-linked, so `#` and `::` stay plain
/// (they would otherwise show as `\#` in the HTML `<title>`, which Doxygen copies verbatim);
/// everything Doxygen would interpret is escaped and line breaks become spaces.
pub fn title(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 8);
    let one_line = s.split_whitespace().collect::<Vec<_>>().join(" ");
    push_escaped(&one_line, &mut out, false);
    if out.is_empty() {
        out.push('?');
    }
    out
}

/// A Doxygen label from any slug or anchor: `[a-z0-9-]` → `[a-z0-9_]`.
pub fn label(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

/// The Doxygen page name of a type's or interface's page: `rtc_type_<slug>`, `rtc_if_<slug>`.
fn page_label(page: &Page) -> String {
    let slug = page.stem.rsplit('/').next().unwrap_or(&page.stem);
    match page.kind {
        PageKind::Interface => format!("rtc_if_{}", label(slug)),
        _ => format!("rtc_type_{}", label(slug)),
    }
}

fn comp_label(c: &Component) -> String {
    format!("rtc_comp_{}", label(&c.slug))
}

fn anchor_label(c: &Component, anchor: &str) -> String {
    format!("{}__{}", comp_label(c), label(anchor))
}

/// `\ref label "text"` with escaped text.
fn refer(label: &str, text_: &str) -> String {
    format!("\\ref {label} \"{}\"", text(text_))
}

fn opt(s: &Option<crate::model::Text>) -> String {
    model::non_empty(s).map(text).unwrap_or_default()
}

/// Doxygen syntax for the shared [`super::text`] helpers.
struct Dox;

impl Markup for Dox {
    fn esc(s: &str) -> String {
        text(s)
    }
    fn link(text_: &str, target: &str) -> String {
        refer(target, text_)
    }
    fn bold(escaped: &str) -> String {
        format!("<b>{escaped}</b>")
    }
    fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]) {
        table(out, headers, rows)
    }
    fn code(s: &str) -> String {
        format!("<tt>{s}</tt>")
    }
    fn paragraph(out: &mut String, escaped: &str) {
        d!(out, "<p>{escaped}</p>");
    }
    fn list(out: &mut String, items: &[&str]) {
        d!(out, "<ul>");
        for l in items {
            d!(out, "<li>{}</li>", text(l));
        }
        d!(out, "</ul>");
        d!(out);
    }
    fn heading(out: &mut String, c: &Component, level: usize, anchor: &str, text: &str) {
        let command = if level <= 2 { "section" } else { "subsection" };
        d!(
            out,
            "\\{command} {} {}",
            anchor_label(c, anchor),
            title(text)
        );
        d!(out);
    }
    fn anchored(c: &Component, anchor: &str, escaped: &str) -> String {
        format!("\\anchor {} {escaped}", anchor_label(c, anchor))
    }
    fn page_ref(page: &Page) -> String {
        format!("\\ref {}", Self::page_target(page))
    }
    fn page_target(page: &Page) -> String {
        page_label(page)
    }
    fn port_peer(cat: &Catalog, r: &PortRef) -> Option<(String, String)> {
        port_peer(cat, r)
    }
    fn iface_peer(cat: &Catalog, r: &InterfaceRef) -> Option<(String, String)> {
        iface_peer(cat, r)
    }
}

fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]) {
    d!(out, "<table>");
    let head: String = headers
        .iter()
        .map(|h| format!("<th>{}</th>", text(h)))
        .collect();
    d!(out, "<tr>{head}</tr>");
    for r in rows {
        // As `d!(out, "<tr>…</tr>")` writes it.
        out.push_str("/// <tr>");
        for c in r {
            out.push_str("<td>");
            out.push_str(c);
            out.push_str("</td>");
        }
        out.push_str("</tr>\n");
    }
    d!(out, "</table>");
    d!(out);
}

fn section(out: &mut String, page: &str, anchor: &str, heading: &str) {
    d!(
        out,
        "\\section {page}__{} {}",
        label(anchor),
        title(heading)
    );
    d!(out);
}

/// Free text as `<p>` paragraphs (blank lines separate them).
fn paragraphs(out: &mut String, s: &str) {
    let norm = s.replace("\r\n", "\n").replace('\r', "\n");
    for para in norm.split("\n\n").map(str::trim).filter(|p| !p.is_empty()) {
        d!(out, "<p>{}</p>", text(para));
    }
    d!(out);
}

fn port_peer(cat: &Catalog, r: &PortRef) -> Option<(String, String)> {
    let (ci, port) = cat.resolve_port(r)?;
    let pc = &cat.components[ci];
    let pn = model::non_empty(&pc.profile.data_ports[port].name).unwrap_or("");
    Some((
        format!("{} / {pn}", pc.profile.name()),
        anchor_label(pc, &pc.anchors.data_ports[port]),
    ))
}

fn iface_peer(cat: &Catalog, r: &InterfaceRef) -> Option<(String, String)> {
    let (ci, port, interface) = cat.resolve_interface(r)?;
    let pc = &cat.components[ci];
    let sp = &pc.profile.service_ports[port];
    let iname = model::non_empty(&sp.interfaces[interface].name).unwrap_or("");
    Some((
        format!(
            "{} / {} / {iname}",
            pc.profile.name(),
            model::non_empty(&sp.name).unwrap_or("")
        ),
        anchor_label(pc, &pc.anchors.interfaces[port][interface]),
    ))
}

fn component_page(cat: &Catalog, ci: usize, cat_label: &str, lang: Lang) -> String {
    let c = &cat.components[ci];
    let p = &c.profile;
    let page = comp_label(c);
    let mut out = String::with_capacity(4096);
    d!(out, "\\page {page} {}", title(p.name()));
    d!(out);
    d!(out, "<p>\\ref index › \\ref {cat_label}</p>");
    d!(out);
    if let Some(desc) = model::non_empty(&p.basic_info.description) {
        paragraphs(&mut out, desc);
    }

    component_sections::<Dox>(&mut out, cat, ci, lang);
    let used = super::system_text::used_in(cat, ci);
    if !used.is_empty() {
        section(&mut out, &page, "sec-systems", lang.t("sys_used_by"));
        d!(out, "<ul>");
        for (text_, s) in used {
            d!(out, "<li>{}</li>", refer(&sys_label(s), &text_));
        }
        d!(out, "</ul>");
        d!(out);
    }
    // The README as plain paragraphs of its Markdown source: Doxygen's own Markdown and HTML
    // would read it differently from the site, and its commands are not to be run.
    if let Some(r) = c.readme.as_ref().filter(|r| !r.text.trim().is_empty()) {
        section(&mut out, &page, "sec-readme", lang.t("readme"));
        paragraphs(&mut out, &r.text);
    }
    out
}

fn port_rows(cat: &Catalog, refs: &[PortRef]) -> Vec<Vec<String>> {
    refs.iter()
        .filter_map(|r| {
            let (ci, pi) = cat.resolve_port(r)?;
            let c = &cat.components[ci];
            let port = &c.profile.data_ports[pi];
            Some(vec![
                format!("\\ref {}", comp_label(c)),
                refer(
                    &anchor_label(c, &c.anchors.data_ports[pi]),
                    model::non_empty(&port.name).unwrap_or("?"),
                ),
                opt(&port.type_),
            ])
        })
        .collect()
}

fn iface_rows(cat: &Catalog, refs: &[InterfaceRef]) -> Vec<Vec<String>> {
    refs.iter()
        .filter_map(|r| {
            let (ci, pi, ii) = cat.resolve_interface(r)?;
            let c = &cat.components[ci];
            let sp = &c.profile.service_ports[pi];
            let i = &sp.interfaces[ii];
            Some(vec![
                format!("\\ref {}", comp_label(c)),
                refer(
                    &anchor_label(c, &c.anchors.interfaces[pi][ii]),
                    &format!(
                        "{} / {}",
                        model::non_empty(&sp.name).unwrap_or("?"),
                        model::non_empty(&i.name).unwrap_or("?")
                    ),
                ),
                opt(&i.type_),
            ])
        })
        .collect()
}

fn type_page(cat: &Catalog, ti: usize, lang: Lang) -> String {
    let t = &cat.data_types[ti];
    let page = format!("rtc_type_{}", label(&t.slug));
    let mut out = String::new();
    d!(out, "\\page {page} {}", title(&t.name));
    d!(out);
    d!(out, "<p>\\ref index › \\ref rtc_types</p>");
    d!(out);
    names_facts::<Dox>(&mut out, lang, &t.spellings, &t.idl_files);
    super::idl_view::write_definition::<Dox>(&mut out, cat, &t.name, lang, &|o, a, text| {
        section(o, &page, a, text)
    });
    let cols = [lang.t("component"), lang.t("fact_port"), lang.t("type")];
    for (anchor, key, refs) in [
        ("sec-producers", "producers", &t.producers),
        ("sec-consumers", "consumers", &t.consumers),
        ("sec-others", "fact_others", &t.others),
    ] {
        if !refs.is_empty() {
            section(&mut out, &page, anchor, lang.t(key));
            table(&mut out, &cols, &port_rows(cat, refs));
        }
    }
    let carried = super::system_text::carrying(cat, &t.name);
    if !carried.is_empty() {
        section(
            &mut out,
            &page,
            "sec-system-connectors",
            lang.t("sys_carried_by"),
        );
        d!(out, "<ul>");
        for (text_, s) in carried {
            d!(out, "<li>{}</li>", refer(&sys_label(s), &text_));
        }
        d!(out, "</ul>");
        d!(out);
    }
    out
}

fn sys_label(s: &crate::catalog::systems::System) -> String {
    format!("rtc_sys_{}", label(&s.slug))
}

/// `systems.dox`: every RT System with its counts.
fn system_index(cat: &Catalog, lang: Lang) -> String {
    let mut out = String::new();
    d!(out, "\\page rtc_systems {}", title(lang.t("systems")));
    d!(out);
    d!(out, "<p>\\ref index</p>");
    d!(out);
    d!(out, "<p>{}</p>", text(lang.t("systems_intro")));
    d!(out);
    let rows: Vec<Vec<String>> = cat
        .systems
        .iter()
        .map(|s| {
            let parts = s.profile.id_parts.as_ref();
            vec![
                format!("\\subpage {}", sys_label(s)),
                parts.map(|x| opt(&x.version)).unwrap_or_default(),
                parts.map(|x| opt(&x.vendor)).unwrap_or_default(),
                s.profile.components.len().to_string(),
                (s.profile.data_port_connectors.len() + s.profile.service_port_connectors.len())
                    .to_string(),
            ]
        })
        .collect();
    table(
        &mut out,
        &[
            lang.t("system"),
            lang.t("version"),
            lang.t("vendor"),
            lang.t("instances"),
            lang.t("sys_connector"),
        ],
        &rows,
    );
    out
}

/// `systems/<slug>.dox`.
fn system_page(cat: &Catalog, si: usize, lang: Lang, show_host: bool) -> String {
    let s = &cat.systems[si];
    let page = sys_label(s);
    let mut out = String::new();
    d!(out, "\\page {page} {}", title(s.profile.name()));
    d!(out);
    d!(out, "<p>\\ref index › \\ref rtc_systems</p>");
    d!(out);
    let component = |c: &Component| comp_label(c);
    let head = |o: &mut String, anchor: &str, text_: &str| section(o, &page, anchor, text_);
    super::system_text::system_body::<Dox>(
        &mut out,
        cat,
        s,
        lang,
        show_host,
        &super::system_text::Targets {
            component: &component,
            heading: &head,
        },
    );
    out
}

fn interface_page(cat: &Catalog, ii: usize, lang: Lang) -> String {
    let t = &cat.interfaces[ii];
    let page = format!("rtc_if_{}", label(&t.slug));
    let mut out = String::new();
    d!(out, "\\page {page} {}", title(&t.name));
    d!(out);
    d!(out, "<p>\\ref index › \\ref rtc_interfaces</p>");
    d!(out);
    if t.is_unprovided() {
        d!(out, "<p><b>{}</b></p>", text(lang.t("not_provided")));
        d!(out);
    }
    names_facts::<Dox>(&mut out, lang, &t.spellings, &t.idl_files);
    super::idl_view::write_definition::<Dox>(&mut out, cat, &t.name, lang, &|o, a, text| {
        section(o, &page, a, text)
    });
    let cols = [lang.t("component"), lang.t("fact_port"), lang.t("type")];
    for (anchor, key, refs) in [
        ("sec-providers", "providers", &t.providers),
        ("sec-requirers", "requirers", &t.requirers),
        ("sec-others", "fact_others", &t.others),
    ] {
        if !refs.is_empty() {
            section(&mut out, &page, anchor, lang.t(key));
            table(&mut out, &cols, &iface_rows(cat, refs));
        }
    }
    out
}

/// Component rows; the first cell is `\subpage` on category pages, `\ref` elsewhere.
fn component_rows(cat: &Catalog, members: &[usize], command: &str) -> Vec<Vec<String>> {
    members
        .iter()
        .map(|&ci| {
            let c = &cat.components[ci];
            let b = &c.profile.basic_info;
            vec![
                format!("\\{command} {}", comp_label(c)),
                opt(&b.description),
                opt(&b.vendor),
                opt(&b.version),
            ]
        })
        .collect()
}

fn cat_label(slug: &str) -> String {
    format!("rtc_cat_{}", label(slug))
}

fn mainpage(cat: &Catalog, site_title: &str, lang: Lang) -> String {
    let mut out = String::new();
    d!(out, "\\mainpage {}", title(site_title));
    d!(out);
    d!(
        out,
        "<p>{}: {} · {}: {} · {}: {}</p>",
        text(lang.t("components")),
        cat.components.len(),
        text(lang.t("data_types")),
        cat.data_types.len(),
        text(lang.t("interfaces")),
        cat.interfaces.len()
    );
    d!(out);
    d!(
        out,
        "\\section rtc_main__catalogue {}",
        title(lang.t("fact_catalogue"))
    );
    d!(out);
    d!(out, "<ul>");
    for f in &cat.categories {
        d!(
            out,
            "<li>\\subpage {} ({})</li>",
            cat_label(&f.slug),
            f.components.len()
        );
    }
    d!(
        out,
        "<li>\\subpage rtc_types ({})</li>",
        cat.data_types.len()
    );
    d!(
        out,
        "<li>\\subpage rtc_interfaces ({})</li>",
        cat.interfaces.len()
    );
    if !cat.systems.is_empty() {
        d!(
            out,
            "<li>\\subpage rtc_systems ({})</li>",
            cat.systems.len()
        );
    }
    d!(out, "</ul>");
    d!(out);
    d!(
        out,
        "\\section rtc_main__components {}",
        title(lang.t("components"))
    );
    d!(out);
    for f in &cat.categories {
        d!(
            out,
            "\\subsection rtc_main__{} {}",
            cat_label(&f.slug),
            title(&category_name(&f.name, lang))
        );
        d!(out);
        table(
            &mut out,
            &component_cols(lang),
            &component_rows(cat, &cat.members(f).collect::<Vec<_>>(), "ref"),
        );
    }
    out
}

fn category_page(cat: &Catalog, fi: usize, lang: Lang) -> String {
    let f = &cat.categories[fi];
    let mut out = String::new();
    d!(
        out,
        "\\page {} {}",
        cat_label(&f.slug),
        title(&category_name(&f.name, lang))
    );
    d!(out);
    d!(out, "<p>\\ref index</p>");
    d!(out);
    table(
        &mut out,
        &component_cols(lang),
        &component_rows(cat, &cat.members(f).collect::<Vec<_>>(), "subpage"),
    );
    out
}

fn type_index(cat: &Catalog, lang: Lang) -> String {
    let mut out = String::new();
    d!(out, "\\page rtc_types {}", title(lang.t("data_types")));
    d!(out);
    d!(out, "<p>\\ref index</p>");
    d!(out);
    type_index_table::<Dox>(&mut out, cat, lang, |page| {
        format!("\\subpage {}", page_label(page))
    });
    out
}

fn interface_index(cat: &Catalog, lang: Lang) -> String {
    let mut out = String::new();
    d!(out, "\\page rtc_interfaces {}", title(lang.t("interfaces")));
    d!(out);
    d!(out, "<p>\\ref index</p>");
    d!(out);
    interface_index_table::<Dox>(&mut out, cat, lang, |page| {
        format!("\\subpage {}", page_label(page))
    });
    out
}

/// A Doxyfile string value: quoted, with `\` and `"` escaped and no line breaks.
fn doxyfile_string(s: &str) -> String {
    let one = s.split_whitespace().collect::<Vec<_>>().join(" ");
    format!("\"{}\"", one.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The `Doxyfile`: relative paths only, warnings are errors, HTML + LaTeX + man + tag file.
pub fn doxyfile(site_title: &str, lang: Lang, inputs: &[String]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Generated by {}. Run `doxygen` in this folder.",
        super::generator()
    );
    let _ = writeln!(
        s,
        "# Writes html/, latex/ (run `make` there for a PDF), man/ and the tag file rtcdoc.tag."
    );
    let settings: Vec<(&str, String)> = vec![
        ("PROJECT_NAME", doxyfile_string(site_title)),
        (
            "OUTPUT_LANGUAGE",
            match lang {
                Lang::En => "English",
                Lang::Ja => "Japanese",
            }
            .into(),
        ),
        ("OUTPUT_DIRECTORY", String::new()),
        ("INPUT_ENCODING", "UTF-8".into()),
        ("FULL_PATH_NAMES", "NO".into()),
        ("RECURSIVE", "NO".into()),
        ("CASE_SENSE_NAMES", "YES".into()),
        // Profile text is escaped for Doxygen's own syntax; Markdown would add a second set of
        // metacharacters and autolinking would try to resolve `A::B` / `#x` as symbols.
        ("MARKDOWN_SUPPORT", "NO".into()),
        ("AUTOLINK_SUPPORT", "NO".into()),
        ("ENABLE_PREPROCESSING", "NO".into()),
        ("EXTRACT_ALL", "NO".into()),
        ("SHOW_FILES", "NO".into()),
        ("SHOW_NAMESPACES", "NO".into()),
        ("QUIET", "YES".into()),
        ("WARNINGS", "YES".into()),
        ("WARN_IF_UNDOCUMENTED", "NO".into()),
        ("WARN_IF_DOC_ERROR", "YES".into()),
        ("WARN_NO_PARAMDOC", "NO".into()),
        ("WARN_AS_ERROR", "FAIL_ON_WARNINGS".into()),
        ("GENERATE_HTML", "YES".into()),
        ("HTML_OUTPUT", "html".into()),
        ("GENERATE_TREEVIEW", "YES".into()),
        ("SEARCHENGINE", "YES".into()),
        ("GENERATE_LATEX", "YES".into()),
        ("LATEX_OUTPUT", "latex".into()),
        ("GENERATE_MAN", "YES".into()),
        ("MAN_OUTPUT", "man".into()),
        ("GENERATE_RTF", "NO".into()),
        ("GENERATE_XML", "NO".into()),
        ("GENERATE_TAGFILE", "rtcdoc.tag".into()),
        ("HAVE_DOT", "NO".into()),
    ];
    for (k, v) in settings {
        let _ = writeln!(s, "{k:<22} = {v}");
    }
    let _ = write!(s, "{:<22} =", "INPUT");
    for i in inputs {
        let _ = write!(s, " \\\n                         {i}");
    }
    s.push('\n');
    s
}

/// Renders every `.dox` page as (relative path, content) plus the Doxyfile, in a fixed order.
pub fn pages(cat: &Catalog, site_title: &str, lang: Lang) -> Vec<(String, String)> {
    let of = cat.category_of_each();
    let mut out = other_pages(cat, site_title, lang, false);
    out.par_extend(
        (0..cat.components.len())
            .into_par_iter()
            .map(|ci| component_entry(cat, &of, ci, lang)),
    );
    out
}

fn component_path(cat: &Catalog, ci: usize) -> String {
    cat.component_page(ci).path_in(Output::Doxygen)
}

/// The path and text of component `ci`'s page.
fn component_entry(cat: &Catalog, of: &[usize], ci: usize, lang: Lang) -> (String, String) {
    (
        component_path(cat, ci),
        component_page(cat, ci, &cat_label(&cat.categories[of[ci]].slug), lang),
    )
}

/// Every file but the component pages, the Doxyfile included (its INPUT lists every page).
fn other_pages(
    cat: &Catalog,
    site_title: &str,
    lang: Lang,
    show_host: bool,
) -> Vec<(String, String)> {
    let mut out = vec![
        (
            cat.site_page(PageKind::Index).path_in(Output::Doxygen),
            mainpage(cat, site_title, lang),
        ),
        (
            cat.site_page(PageKind::DataTypes).path_in(Output::Doxygen),
            type_index(cat, lang),
        ),
        (
            cat.site_page(PageKind::Interfaces).path_in(Output::Doxygen),
            interface_index(cat, lang),
        ),
    ];
    out.par_extend((0..cat.categories.len()).into_par_iter().map(|fi| {
        (
            cat.category_page(fi).path_in(Output::Doxygen),
            category_page(cat, fi, lang),
        )
    }));
    out.par_extend((0..cat.data_types.len()).into_par_iter().map(|ti| {
        (
            cat.data_type_page(ti).path_in(Output::Doxygen),
            type_page(cat, ti, lang),
        )
    }));
    out.par_extend((0..cat.interfaces.len()).into_par_iter().map(|ii| {
        (
            cat.interface_page(ii).path_in(Output::Doxygen),
            interface_page(cat, ii, lang),
        )
    }));
    if !cat.systems.is_empty() {
        out.push((
            cat.site_page(PageKind::Systems).path_in(Output::Doxygen),
            system_index(cat, lang),
        ));
        out.par_extend((0..cat.systems.len()).into_par_iter().map(|si| {
            (
                cat.system_page(si).path_in(Output::Doxygen),
                system_page(cat, si, lang, show_host),
            )
        }));
    }
    let mut inputs: Vec<String> = out.iter().map(|(p, _)| p.clone()).collect();
    // Same order as before: category pages, then components, then types and interfaces.
    let at = 3 + cat.categories.len();
    inputs.splice(
        at..at,
        (0..cat.components.len()).map(|ci| component_path(cat, ci)),
    );
    out.push(("Doxyfile".into(), doxyfile(site_title, lang, &inputs)));
    out
}

impl Renderer for DoxygenRenderer {
    fn name(&self) -> &'static str {
        "doxygen"
    }
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize> {
        let (cat, lang) = (ctx.catalog, ctx.site.language);
        let pages = other_pages(cat, &ctx.site.title, lang, ctx.site.show_host_data);
        pages
            .par_iter()
            .try_for_each(|(path, text)| out.write(path, text.as_bytes()))?;
        // Component pages are the bulk: written as they are rendered, never all held at once.
        let of = cat.category_of_each();
        (0..cat.components.len())
            .into_par_iter()
            .try_for_each(|ci| {
                let (path, text) = component_entry(cat, &of, ci, lang);
                out.write(&path, text.as_bytes())
            })?;
        Ok(pages.len() + cat.components.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 4096, ..Default::default() })]
        /// Text that the bytewise check lets through is exactly what the escaper writes, in
        /// both modes; and the check lets most plain text through (it is not vacuous).
        #[test]
        fn text_passed_unescaped_is_what_the_escaper_writes(
            s in "[ \t0-9a-zA-Z.,()/_'*+=!?;\\-:#@<>&%$\"\u{0}-\u{1f}\u{7f}\u{80}-\u{9f}\u{a0}é日本]{0,24}"
        ) {
            if needs_no_escaping(&s) {
                for full in [true, false] {
                    let mut out = String::new();
                    push_escaped_chars(&s, &mut out, full);
                    proptest::prop_assert_eq!(&out, &s);
                }
            }
        }
    }

    #[test]
    fn plain_text_needs_no_escaping() {
        for s in [
            "Image smoothing - edge detection",
            "RTC:Vendor",
            "2023-05-02",
            "日本語 text",
        ] {
            assert!(needs_no_escaping(s), "{s}");
        }
        for s in ["a--b", "RTC::TimedLong", "#x", "<b>", "tab\there", "\u{85}"] {
            assert!(!needs_no_escaping(s), "{s}");
        }
    }

    #[test]
    fn text_escapes_every_metacharacter() {
        assert_eq!(text(r"a\b"), r"a\\b");
        assert_eq!(text("@param x"), r"\@param x");
        assert_eq!(text(r"\ref foo"), r"\\ref foo");
        assert_eq!(text("<b>&amp;"), r"\<b\>\&amp;");
        assert_eq!(text("100% $HOME"), r"100\% \$HOME");
        assert_eq!(text("say \"hi\" it's"), r#"say \"hi\" it's"#);
        assert_eq!(text("#include x"), r"\#include x");
        assert_eq!(text("RTC::TimedLong"), r"RTC\::TimedLong");
        assert_eq!(text("a:b"), "a:b");
        assert_eq!(
            text("a--b---c----d-----e-f"),
            r"a\--b\---c\--\--d\--\---e-f"
        );
        assert_eq!(text("l1\n- l2\r\n+ l3"), "l1<br>- l2<br>+ l3");
        assert_eq!(text("*/ end"), "*/ end");
        assert_eq!(text("a\u{0}b\tc"), "ab c");
    }

    #[test]
    fn titles_are_one_line_and_keep_type_names() {
        assert_eq!(title("RTC::TimedLong"), "RTC::TimedLong");
        assert_eq!(title("a\nb <c>"), r"a b \<c\>");
        assert_eq!(title(""), "?");
    }

    #[test]
    fn labels_are_plain() {
        assert_eq!(label("port-in-1"), "port_in_1");
        assert!(label("x-ab12cd")
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_'));
    }

    #[test]
    fn doxyfile_has_no_absolute_paths_and_quotes_the_title() {
        let d = doxyfile("My \"cat\"", Lang::Ja, &["mainpage.dox".into()]);
        assert!(d.contains(r#"PROJECT_NAME           = "My \"cat\"""#));
        assert!(d.contains("OUTPUT_LANGUAGE        = Japanese"));
        assert!(d.contains("WARN_AS_ERROR          = FAIL_ON_WARNINGS"));
        assert!(!d.contains("= /"));
    }
}
