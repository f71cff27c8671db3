//! Doxygen input: `.dox` pages plus a ready `Doxyfile` (spec 10.7: Doxygen is the route to
//! HTML, LaTeX and man pages).
//!
//! Layout: `Doxyfile`, `mainpage.dox` (`\mainpage`), `categories/<slug>.dox`,
//! `components/<slug>.dox`, `types.dox` + `types/<slug>.dox`, `interfaces.dox` +
//! `interfaces/<slug>.dox`, `vendors.dox` + `vendors/<slug>.dox`, `systems.dox` +
//! `systems/<slug>.dox`. Running `doxygen` in the folder writes `html/`, `latex/`, `man/` and
//! the tag file `rtcdoc.tag`.
//!
//! Labels ([`Page::doxygen_label`], [`Page::anchor_in`]) are globally unique, prefixed and
//! `[a-z0-9_]` only: `rtc_comp_<slug>`, `rtc_type_<slug>`, `rtc_if_<slug>`, `rtc_cat_<slug>`,
//! `rtc_vendor_<slug>`, `rtc_sys_<slug>`, `rtc_types`, `rtc_interfaces`, `rtc_vendors`,
//! `rtc_systems`; section and row anchors are `<page label>__<anchor>` (a double underscore,
//! which no slug contains, so a row anchor can never equal another page's label). Every link
//! is [`Catalog::href`]: nothing here spells a label. The page tree is mainpage → category
//! pages → component pages, mainpage → type index → type pages, mainpage → interface index →
//! interface pages, mainpage → vendor index → vendor pages and mainpage → system index →
//! system pages: every page is the target of exactly one `\subpage`; all other links are
//! `\ref`.
//!
//! Escaping choices: pages are written as `///` comment blocks, so a `*/` in profile text cannot
//! end the comment; the Doxyfile sets `MARKDOWN_SUPPORT = NO` (no Markdown syntax to neutralise;
//! tables are Doxygen's HTML `<table>` commands) and `AUTOLINK_SUPPORT = NO`; profile text goes
//! through [`text`] (every Doxygen metacharacter backslash-escaped, line breaks as `<br>`, never
//! a raw newline, so no profile line can start a Doxygen list), page titles through [`title`].

use super::text::{component_sections, component_table, facets_of_each, Markup};
use super::text::{facet_index_page, facet_page, systems_index_page, type_index_page, type_page};
use super::view::component::component_view;
use super::view::facets::{component_rows, facet_index_view, facet_view, FacetKind};
use super::view::front::{front_view, systems_index_view};
use super::view::types::{entry_view, type_index_view, TypeKind};
use super::view::Linked;
use super::{RenderContext, Renderer};
use crate::catalog::{
    Catalog, Component, ComponentIx, Ix, Output, Page, PageKind, PerEntry, SystemIx,
};
use crate::i18n::Lang;
use crate::output::Sink;
use rayon::prelude::*;
use std::fmt::Write as _;

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
static DOX_SPECIAL: [bool; 256] = super::byte_set(true, b"\\@<>&%$\"#:-`\x7f\xc2");

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
    push_escaped_in(s, out, full, true);
}

/// [`push_escaped_chars`]; `spans`: code spans become `<tt>` (not inside one: its backticks are
/// text).
fn push_escaped_in(s: &str, out: &mut String, full: bool, spans: bool) {
    let chars: Vec<char> = s.chars().collect();
    // Code spans become `<tt>` (Markdown is off in the Doxyfile): code, as the site shows it.
    let spans = if spans {
        super::text::code_spans(&chars, true)
    } else {
        Vec::new()
    };
    let mut span = spans.iter().peekable();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if let Some(&&sp) = span.peek() {
            if i == sp.open {
                out.push_str("<tt>");
                let inner: String = sp.content(&chars).iter().collect();
                push_escaped_in(&inner, out, full, false);
                out.push_str("</tt>");
                span.next();
                i = sp.close + 1;
                continue;
            }
        }
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

/// Escapes a page or section title. Doxygen shows a title twice: as the page's heading (and in
/// the navigation), where its escapes work, and in the HTML `<title>`, where it copies most of
/// them verbatim (`\&` shows as `\&amp;`, `\#` as `\#`). So a title escapes only what Doxygen
/// would otherwise read: `\` `@` (commands), `<` `>` (tags), `&` as the entity `&amp;` (right in
/// both places), before a name only (an ASCII letter, `_` or any non-ASCII character) `%`
/// (`%word` drops the `%`), `#` and a `::` that starts a word (`#word`, `#~word` and `::word`
/// are link requests), `$` before `Word:` (an RCS keyword), and a leading `-` (a list). `$x`,
/// `"`, `a::b`, `#1` and dash runs stay plain: titles get no typographic dashes.
/// Line breaks and tabs become spaces; control characters are dropped.
pub fn title(s: &str) -> String {
    let one_line = s.split_whitespace().collect::<Vec<_>>().join(" ");
    let chars: Vec<char> = one_line.chars().collect();
    let name_start = |i: usize| {
        chars
            .get(i)
            .is_some_and(|&c| c.is_ascii_alphabetic() || c == '_' || !c.is_ascii())
    };
    let mut out = String::with_capacity(one_line.len() + 8);
    for (i, &ch) in chars.iter().enumerate() {
        let escaped = match ch {
            '\\' | '@' | '<' | '>' => true,
            '%' => name_start(i + 1),
            // `#~Name` is a link request too (a destructor).
            '#' => name_start(i + 1) || chars.get(i + 1) == Some(&'~'),
            // `$Word: … $` is an RCS keyword.
            '$' => {
                let word = chars[i + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_alphanumeric() || **c == '_')
                    .count();
                word > 0 && chars.get(i + 1 + word) == Some(&':')
            }
            // A leading `-` (or `-#`) starts a list.
            '-' => i == 0,
            // The first colon of a `::` that starts a word (not `a::b`).
            ':' => {
                chars.get(i + 1) == Some(&':')
                    && name_start(i + 2)
                    && !(i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_'))
                    && chars.get(i.wrapping_sub(1)) != Some(&':')
            }
            _ => false,
        };
        match ch {
            '&' => out.push_str("&amp;"),
            c if c.is_control() => {}
            c => {
                if escaped {
                    out.push('\\');
                }
                out.push(c);
            }
        }
    }
    if out.is_empty() {
        out.push('?');
    }
    out
}

/// A Doxygen label from any slug or anchor: `[a-z0-9-]` → `[a-z0-9_]`.
pub use crate::catalog::pages::doxygen_label as label;

/// The output this module writes.
const DOX: Output = Output::Doxygen;

/// The label of page `to` for `\ref` / `\subpage` ([`Catalog::href`]).
fn target(cat: &Catalog, to: &Page) -> String {
    cat.href(to, to, None, DOX)
}

/// `\ref label "text"` with escaped text.
fn refer(label: &str, text_: &str) -> String {
    format!("\\ref {label} \"{}\"", text(text_))
}

/// Doxygen syntax for the shared [`super::text`] helpers.
struct Dox;

impl Markup for Dox {
    const OUTPUT: Output = Output::Doxygen;
    fn esc(s: &str) -> String {
        text(s)
    }
    fn message_line(line: &str, out: &mut String) {
        push_escaped(line, out, true);
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
    fn stability(out: &mut String, escaped: &str, deprecated: bool) {
        if deprecated {
            // Doxygen's own mark: a "Deprecated" paragraph, and the page in its Deprecated List.
            d!(out, "\\deprecated {escaped}");
            d!(out);
        } else {
            Self::paragraph(out, escaped);
        }
    }
    fn linked_list(out: &mut String, items: &[String]) {
        d!(out, "<ul>");
        for l in items {
            d!(out, "<li>{l}</li>");
        }
        d!(out, "</ul>");
        d!(out);
    }
    fn heading(out: &mut String, page: &Page, level: usize, anchor: &str, text: &str) {
        let command = if level <= 2 { "section" } else { "subsection" };
        d!(
            out,
            "\\{command} {} {}",
            page.anchor_in(anchor, DOX),
            title(text)
        );
        d!(out);
    }
    fn anchored(page: &Page, anchor: &str, escaped: &str) -> String {
        format!("\\anchor {} {escaped}", page.anchor_in(anchor, DOX))
    }
    /// A link to a whole page whose text is its title is a bare `\\ref`: Doxygen writes the
    /// title itself (a quoted link text is shown as written, escapes and all).
    fn page_link(
        cat: &Catalog,
        from: &Page,
        to: &Page,
        anchor: Option<&str>,
        text_: &str,
    ) -> String {
        let label = cat.href(from, to, anchor, DOX);
        if anchor.is_none() && text_ == to.title {
            format!("\\ref {label}")
        } else {
            refer(&label, text_)
        }
    }
    fn page_ref(cat: &Catalog, from: &Page, to: &Page) -> String {
        format!("\\ref {}", cat.href(from, to, None, DOX))
    }
    fn child_link(cat: &Catalog, from: &Page, to: &Page, _text: &str) -> String {
        format!("\\subpage {}", cat.href(from, to, None, DOX))
    }
    /// Doxygen writes each `\\ref`ed page's own title: the crumbs' texts are not needed.
    fn page_head(out: &mut String, cat: &Catalog, page: &Page, text_: &str, crumbs: &[Linked<'_>]) {
        d!(out, "\\page {} {}", target(cat, page), title(text_));
        d!(out);
        let refs: Vec<String> = crumbs
            .iter()
            .filter(|l| l.to.is_some_and(|(to, _)| DOX.carries(to.kind)))
            .filter_map(|l| l.target(cat, page, DOX))
            .map(|t| format!("\\ref {t}"))
            .collect();
        d!(out, "<p>{}</p>", refs.join(" › "));
        d!(out);
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

fn section(out: &mut String, page: &Page, anchor: &str, heading: &str) {
    d!(
        out,
        "\\section {} {}",
        page.anchor_in(anchor, DOX),
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

fn component_page(
    cat: &Catalog,
    ci: ComponentIx,
    facets: (usize, usize),
    source_url: Option<&str>,
    lang: Lang,
) -> String {
    let v = component_view(cat, ci, facets, source_url, lang);
    let page = v.page;
    let mut out = String::with_capacity(4096);
    d!(out, "\\page {} {}", target(cat, page), title(&v.name));
    d!(out);
    d!(
        out,
        "<p>\\ref {} › {}</p>",
        home(cat),
        super::text::linked::<Dox>(cat, page, &v.category)
    );
    d!(out);
    super::text::stability_line::<Dox>(&mut out, cat, page, v.stability.as_ref());
    if let Some(desc) = v.lead {
        paragraphs(&mut out, desc);
    }
    component_sections::<Dox>(&mut out, cat, &v, lang);
    // The README as plain paragraphs of its Markdown source: Doxygen's own Markdown and HTML
    // would read it differently from the site, and its commands are not to be run.
    if let Some(r) = v.readme.filter(|r| !r.text.trim().is_empty()) {
        section(&mut out, page, "sec-readme", lang.t("readme"));
        paragraphs(&mut out, &r.text);
    }
    out
}

/// The label of the front page (`\mainpage`).
fn home(cat: &Catalog) -> String {
    target(cat, cat.site_page(PageKind::Index))
}

/// The line under an entry page's title: the front page › the index of `kind`.
fn crumbs(out: &mut String, cat: &Catalog, kind: PageKind) {
    d!(
        out,
        "<p>\\ref {} › \\ref {}</p>",
        home(cat),
        target(cat, cat.site_page(kind))
    );
    d!(out);
}

/// The line under an index page's title: the front page.
fn crumb_home(out: &mut String, cat: &Catalog) {
    d!(out, "<p>\\ref {}</p>", home(cat));
    d!(out);
}

/// `systems/<slug>.dox`, and its wiring diagram as an SVG file beside it (its stem:
/// [`Page::path`]), shown after the summary as on the HTML page (`\image html`: the Doxyfile's
/// `IMAGE_PATH` names the folder; Graphviz is not needed).
fn system_page(
    cat: &Catalog,
    si: SystemIx,
    lang: Lang,
    site: (bool, Option<&str>),
) -> (String, String) {
    let s = &cat[si];
    let page = cat.system_page(si);
    let w = super::wiring::system_wiring(cat, s, lang, &|_, _| String::new());
    let caption = super::system_text::wiring_caption(s, lang);
    let svg = super::html::standalone_system_diagram(
        &caption,
        &w.instances,
        &w.connectors,
        w.drawing_notes(),
    );
    // No caption: the section's heading says what it is, and the drawing has its title.
    let drawing = |out: &mut String| {
        d!(out, "\\image html {}", page.file_name("svg"));
        d!(out);
    };
    let mut out = String::new();
    d!(
        out,
        "\\page {} {}",
        target(cat, page),
        title(&s.display_name())
    );
    d!(out);
    crumbs(&mut out, cat, PageKind::Systems);
    let head = |o: &mut String, anchor: &str, text_: &str| section(o, page, anchor, text_);
    let notes = w.notes(true);
    let targets = super::system_text::Targets::new(&head, &caption, &drawing, &notes);
    super::system_text::system_body::<Dox>(&mut out, cat, s, lang, site, &targets);
    (out, svg)
}

/// `index.dox` (`\\mainpage`) from the front page's view: the counts, every category and
/// index as a subpage (the page tree), then every component by category.
fn mainpage(cat: &Catalog, site_title: &str, lang: Lang) -> String {
    let v = front_view(cat, lang);
    let page = v.page;
    let mut out = String::new();
    d!(out, "\\mainpage {}", title(site_title));
    d!(out);
    let mut stats = vec![format!("{}: {}", text(lang.t("components")), v.components)];
    stats.extend(
        ["data_types", "interfaces"]
            .iter()
            .filter_map(|k| v.index(k))
            .map(|i| format!("{}: {}", text(lang.t(i.key)), i.count)),
    );
    d!(out, "<p>{}</p>", stats.join(" · "));
    d!(out);
    Dox::heading(&mut out, page, 2, "catalogue", lang.t("fact_catalogue"));
    d!(out, "<ul>");
    let counted = (v.categories.iter().map(|g| (g.page, g.members.len())))
        .chain(v.indexes.iter().map(|i| (i.page, i.count)));
    for (to, count) in counted {
        d!(out, "<li>\\subpage {} ({count})</li>", target(cat, to));
    }
    for p in std::iter::once(v.dataflow).chain(v.whats_new) {
        d!(out, "<li>\\subpage {}</li>", target(cat, p));
    }
    d!(out, "</ul>");
    d!(out);
    Dox::heading(&mut out, page, 2, "components", lang.t("components"));
    for g in &v.categories {
        // The section of a category is named after its page (`rtc_main__rtc_cat_<slug>`).
        d!(
            out,
            "\\subsection {} {}",
            page.anchor_in(&target(cat, g.page), DOX),
            title(&g.name)
        );
        d!(out);
        let rows = component_rows(cat, g.members.iter().copied());
        component_table::<Dox>(&mut out, cat, page, &rows, false, lang);
    }
    out
}

/// `dataflow.dox`: which groups of components can feed which.
fn dataflow_page(cat: &Catalog, lang: Lang) -> String {
    let page = cat.site_page(PageKind::DataFlow);
    let mut out = String::new();
    d!(
        out,
        "\\page {} {}",
        target(cat, page),
        title(lang.t("dataflow"))
    );
    d!(out);
    crumb_home(&mut out, cat);
    super::text::dataflow_body::<Dox>(&mut out, cat, page, lang);
    out
}

/// A Doxyfile string value: quoted, with `\` and `"` escaped and no line breaks.
fn doxyfile_string(s: &str) -> String {
    let one = s.split_whitespace().collect::<Vec<_>>().join(" ");
    format!("\"{}\"", one.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The `Doxyfile`: relative paths only, warnings are errors, HTML + LaTeX + man + tag file;
/// `images`, the folders of the images the pages show (`IMAGE_PATH`, when there are any).
pub fn doxyfile(site_title: &str, lang: Lang, inputs: &[String], images: &[String]) -> String {
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
    // The systems' wiring drawings (`\image html`), beside their pages.
    if !images.is_empty() {
        let _ = writeln!(s, "{:<22} = {}", "IMAGE_PATH", images.join(" "));
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
    let of = facets_of_each(cat);
    let mut out = other_pages(cat, site_title, lang, (false, None));
    out.par_extend(
        (0..cat.components.len())
            .into_par_iter()
            .map(Ix::new)
            .map(|ci| component_entry(cat, &of, ci, lang, None)),
    );
    out
}

fn component_path(cat: &Catalog, ci: ComponentIx) -> String {
    cat.component_page(ci).path_in(DOX)
}

/// The path and text of component `ci`'s page.
fn component_entry(
    cat: &Catalog,
    of: &PerEntry<Component, (usize, usize)>,
    ci: ComponentIx,
    lang: Lang,
    source_url: Option<&str>,
) -> (String, String) {
    (
        component_path(cat, ci),
        component_page(cat, ci, of[ci], source_url, lang),
    )
}

/// Every file but the component pages, the Doxyfile included (its INPUT lists every page).
fn other_pages(
    cat: &Catalog,
    site_title: &str,
    lang: Lang,
    site: (bool, Option<&str>),
) -> Vec<(String, String)> {
    let mut out = vec![
        (
            cat.site_page(PageKind::Index).path_in(DOX),
            mainpage(cat, site_title, lang),
        ),
        (
            cat.site_page(PageKind::DataTypes).path_in(DOX),
            type_index_page::<Dox>(cat, &type_index_view(cat, TypeKind::Data), "", lang),
        ),
        (
            cat.site_page(PageKind::Interfaces).path_in(DOX),
            type_index_page::<Dox>(cat, &type_index_view(cat, TypeKind::Interface), "", lang),
        ),
    ];
    out.par_extend((0..cat.categories.len()).into_par_iter().map(|fi| {
        let v = facet_view(cat, FacetKind::Category, fi, lang);
        (v.page.path_in(DOX), facet_page::<Dox>(cat, &v, "", lang))
    }));
    for kind in [TypeKind::Data, TypeKind::Interface] {
        out.par_extend(kind.entries(cat).into_par_iter().map(|i| {
            let v = entry_view(cat, i, lang, site.1);
            (v.page.path_in(DOX), type_page::<Dox>(cat, &v, "", lang))
        }));
    }
    out.push((
        cat.site_page(PageKind::Vendors).path_in(DOX),
        facet_index_page::<Dox>(
            cat,
            &facet_index_view(cat, FacetKind::Vendor, lang),
            "",
            lang,
        ),
    ));
    out.push((
        cat.site_page(PageKind::DataFlow).path_in(DOX),
        dataflow_page(cat, lang),
    ));
    out.par_extend((0..cat.vendors.len()).into_par_iter().map(|fi| {
        let v = facet_view(cat, FacetKind::Vendor, fi, lang);
        (v.page.path_in(DOX), facet_page::<Dox>(cat, &v, "", lang))
    }));
    let mut drawings: Vec<(String, String)> = Vec::new();
    if !cat.systems.is_empty() {
        out.push((
            cat.site_page(PageKind::Systems).path_in(DOX),
            systems_index_page::<Dox>(cat, &systems_index_view(cat), "", lang),
        ));
        let (pages, svgs): (Vec<_>, Vec<_>) = (0..cat.systems.len())
            .into_par_iter()
            .map(Ix::new)
            .map(|si| {
                let page = cat.system_page(si);
                let (text, svg) = system_page(cat, si, lang, site);
                ((page.path_in(DOX), text), (page.path("svg"), svg))
            })
            .unzip();
        out.extend(pages);
        drawings = svgs;
    }
    out.extend(super::history_text::pages::<Dox>(cat, site.1, lang));
    let mut inputs: Vec<String> = out.iter().map(|(p, _)| p.clone()).collect();
    // Same order as before: category pages, then components, then types and interfaces.
    let at = 3 + cat.categories.len();
    inputs.splice(
        at..at,
        Ix::all(cat.components.len()).map(|ci| component_path(cat, ci)),
    );
    let mut images: Vec<String> = drawings
        .iter()
        .filter_map(|(p, _)| Some(std::path::Path::new(p).parent()?.to_str()?.to_string()))
        .collect();
    images.dedup();
    out.push((
        "Doxyfile".into(),
        doxyfile(site_title, lang, &inputs, &images),
    ));
    // The systems' drawings: images (`IMAGE_PATH`), not inputs.
    out.extend(drawings);
    out
}

impl Renderer for DoxygenRenderer {
    fn name(&self) -> &'static str {
        "doxygen"
    }
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize> {
        let (cat, lang) = (ctx.catalog, ctx.site.language);
        let pages = other_pages(
            cat,
            &ctx.site.title,
            lang,
            (ctx.site.show_host_data, ctx.site.source_url.as_deref()),
        );
        pages
            .par_iter()
            .try_for_each(|(path, text)| out.write(path, text.as_bytes()))?;
        // Component pages are the bulk: written as they are rendered, never all held at once.
        let of = facets_of_each(cat);
        (0..cat.components.len())
            .into_par_iter()
            .map(Ix::new)
            .try_for_each(|ci| {
                let (path, text) =
                    component_entry(cat, &of, ci, lang, ctx.site.source_url.as_deref());
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
    fn a_code_span_holding_backticks_is_one_tt() {
        let mut out = String::new();
        push_escaped_chars("a ``k`1`` b <c>", &mut out, false);
        assert_eq!(out, "a <tt>k`1</tt> b \\<c\\>");
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
        assert_eq!(
            title("A & B #1 #team 100% %d %1 $x \"q\" a--b \\ @ #_x #日本 ::h RTC::X"),
            r#"A &amp; B #1 \#team 100% \%d %1 $x "q" a--b \\ \@ \#_x \#日本 \::h RTC::X"#
        );
        assert_eq!(
            title("- R&D $Date: 1 $ $x #~Foo a-b"),
            r"\- R&amp;D \$Date: 1 $ $x \#~Foo a-b"
        );
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
        let d = doxyfile("My \"cat\"", Lang::Ja, &["mainpage.dox".into()], &[]);
        assert!(d.contains(r#"PROJECT_NAME           = "My \"cat\"""#));
        assert!(d.contains("OUTPUT_LANGUAGE        = Japanese"));
        assert!(d.contains("WARN_AS_ERROR          = FAIL_ON_WARNINGS"));
        assert!(!d.contains("= /"));
    }
}
