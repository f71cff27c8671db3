//! Building blocks shared by the text renderers (Markdown and Doxygen).
//!
//! Both renderers lay out the same tables of [`Fact`]s and the same peer lists; they differ
//! only in how text is escaped, how a cross-reference is written and how a table looks, which
//! is what a [`Markup`] says.

use super::facts::{self, Fact};
use super::view::component::{ComponentView, PortView};
use super::view::facets::{ComponentRow, FacetIndexView, FacetView};
use super::view::front::SystemsIndexView;
use super::view::types::{TypeIndexView, TypeKind, TypeView};
use super::view::{Linked, Peers};
use crate::catalog::{Catalog, Component, Ix, Output, Page, PerEntry};
use crate::i18n::Lang;

/// A code span of a line of text: `chars[open..=close]`, fenced by runs of `fence` backticks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CodeSpan {
    pub open: usize,
    pub close: usize,
    pub fence: usize,
}

impl CodeSpan {
    /// The code between the fences, as CommonMark shows it: one space stripped from each end
    /// when both ends have one (``` `` a`b `` ``` is `` a`b ``).
    pub fn content<'c>(&self, chars: &'c [char]) -> &'c [char] {
        let inner = &chars[self.open + self.fence..=self.close - self.fence];
        match inner {
            [' ', middle @ .., ' '] if middle.iter().any(|&c| c != ' ') => middle,
            _ => inner,
        }
    }
}

/// The code spans of a line of profile text, as CommonMark reads them (a run of backticks
/// opens a span that the next run of as many backticks closes, so ``` ``a`b`` ``` holds a
/// backtick), the content not blank, and free of `|` unless `pipes` (a Markdown table cell
/// would split at it). Every output shows them as code, so a profile's `` `count` `` reads
/// the same everywhere.
pub fn code_spans(chars: &[char], pipes: bool) -> Vec<CodeSpan> {
    let run = |at: usize| chars[at..].iter().take_while(|&&c| c == '`').count();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if chars[i] != '`' {
            i += 1;
            continue;
        }
        let fence = run(i);
        let mut j = i + fence;
        let mut close = None;
        while j < chars.len() {
            if chars[j] == '`' {
                let n = run(j);
                if n == fence {
                    close = Some(j + n - 1);
                    break;
                }
                j += n;
            } else {
                j += 1;
            }
        }
        if let Some(close) = close {
            let span = CodeSpan {
                open: i,
                close,
                fence,
            };
            let content = &chars[i + fence..=close - fence];
            if (pipes || !content.contains(&'|')) && content.iter().any(|c| !c.is_whitespace()) {
                out.push(span);
                i = close + 1;
                continue;
            }
        }
        i += fence;
    }
    out
}

pub use crate::quote::code_span;

/// The syntax of one text output format.
pub trait Markup {
    /// The output whose pages this syntax writes: links come from [`Catalog::href`] for it.
    const OUTPUT: Output;
    /// Escapes plain text for an inline position (a table cell, a heading).
    fn esc(s: &str) -> String;
    /// Escapes a message of rtcdoc's (a change's): each line escaped by
    /// [`Markup::message_line`], the lines joined by `<br>` (a long text's word-level difference
    /// breaks its lines where the text does, as the component page shows it); a line break
    /// inside a code span (a value it quotes) is a space, the ends are trimmed.
    fn message(s: &str) -> String {
        let chars: Vec<char> = s.trim().replace("\r\n", "\n").chars().collect();
        let spans = code_spans(&chars, true);
        let mut lines = vec![String::new()];
        let mut k = 0;
        for (i, &c) in chars.iter().enumerate() {
            while spans.get(k).is_some_and(|sp| sp.close < i) {
                k += 1;
            }
            let inside = spans.get(k).is_some_and(|sp| sp.open <= i);
            let line = lines.last_mut().expect("one line at least");
            match c {
                '\r' | '\n' if inside => line.push(' '),
                '\r' | '\n' => lines.push(String::new()),
                c => line.push(c),
            }
        }
        let mut out = String::with_capacity(s.len() + 8);
        for (i, line) in lines.iter().enumerate() {
            if i > 0 {
                out.push_str("<br>");
            }
            Self::message_line(line.trim(), &mut out);
        }
        out
    }
    /// Escapes one line of a message of rtcdoc's onto `out`: its code spans (the values it
    /// quotes) kept as written, without reading profile markup such as `<br/>` in them.
    fn message_line(line: &str, out: &mut String);
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
    fn list(out: &mut String, items: &[&str]) {
        let escaped: Vec<String> = items.iter().map(|l| Self::esc(l)).collect();
        Self::linked_list(out, &escaped);
    }
    /// A bulleted list of already escaped items (links).
    fn linked_list(out: &mut String, items: &[String]);
    /// A heading of `level` (2 or 3) on `page`, with the stable `anchor`.
    fn heading(out: &mut String, page: &Page, level: usize, anchor: &str, text: &str);
    /// A table cell of already escaped text with the stable `anchor` of `page`.
    fn anchored(page: &Page, anchor: &str, escaped: &str) -> String;
    /// The page's title and, under it, the way back (`crumbs`: the front page, then an index).
    fn page_head(out: &mut String, cat: &Catalog, page: &Page, title: &str, crumbs: &[Linked<'_>]);
    /// A short paragraph that stands out (a warning about the page's subject).
    fn note(out: &mut String, text: &str) {
        Self::paragraph(out, &Self::bold(&Self::esc(text)));
    }
    /// The stability line of a page ([`stability_line`]), already escaped; `deprecated` for a
    /// deprecated entry (Doxygen's `\deprecated`).
    fn stability(out: &mut String, escaped: &str, deprecated: bool) {
        let _ = deprecated;
        Self::paragraph(out, escaped);
    }
    /// A link on page `from` to page `to` (a data type's or interface's), as a table cell.
    fn page_ref(cat: &Catalog, from: &Page, to: &Page) -> String;
    /// A link with `text` on page `from` to page `to` (to its `anchor` if given).
    fn page_link(
        cat: &Catalog,
        from: &Page,
        to: &Page,
        anchor: Option<&str>,
        text: &str,
    ) -> String {
        Self::link(text, &cat.href(from, to, anchor, Self::OUTPUT))
    }
    /// A link on page `from` to page `to` that hangs `to` under `from` in the output's page
    /// tree (Doxygen's `\\subpage`); elsewhere a link with `text`.
    fn child_link(cat: &Catalog, from: &Page, to: &Page, text: &str) -> String {
        Self::page_link(cat, from, to, None, text)
    }
    /// The target of a link on page `from` to page `to`, for [`Markup::link`].
    fn page_target(cat: &Catalog, from: &Page, to: &Page) -> String {
        cat.href(from, to, None, Self::OUTPUT)
    }
}

/// A two-column table of plain-text pairs, each cell escaped.
pub fn pairs_table<M: Markup, A: AsRef<str>, B: AsRef<str>>(
    out: &mut String,
    headers: [&str; 2],
    pairs: impl IntoIterator<Item = (A, B)>,
) {
    let rows: Vec<Vec<String>> = pairs
        .into_iter()
        .map(|(a, b)| vec![M::esc(a.as_ref()), M::esc(b.as_ref())])
        .collect();
    M::table(out, &headers, &rows);
}

/// Facts as a two-column table (label, value).
pub fn facts_table<M: Markup>(out: &mut String, lang: Lang, facts: &[Fact]) {
    let pairs = facts.iter().map(|f| (&f.label, &f.value));
    pairs_table::<M, _, _>(out, [lang.t("fact_field"), lang.t("fact_value")], pairs);
}

/// A table whose columns from `keep` on are left out when they are empty in every row (a
/// component without units gets no Unit column).
pub(super) fn sparse_table<M: Markup>(
    out: &mut String,
    keep: usize,
    headers: &[&str],
    rows: &[Vec<String>],
) {
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

/// The neighbourhood section of a component page from its view: a table by port — the port,
/// its type, `fed by` / `feeds` / `used by` / `uses`, and the neighbour components, each
/// linked, with a `+N` link to the type or interface page when capped; or the sentence saying
/// no component connects to it.
fn neighbourhood_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    v: &ComponentView<'_>,
    lang: Lang,
) {
    use crate::render::neighbourhood as nb;
    let page = v.page;
    M::heading(out, page, 2, "sec-neighbourhood", lang.t("neighbourhood"));
    if v.neighbourhood.is_empty() {
        M::paragraph(out, &M::esc(lang.t("neighbourhood_none")));
        return;
    }
    M::paragraph(out, &M::esc(lang.t("neighbourhood_intro")));
    let rows: Vec<Vec<String>> = v
        .neighbourhood
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
                M::esc(lang.t(r.relation())),
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
pub fn facets_of_each(cat: &Catalog) -> PerEntry<Component, (usize, usize)> {
    let (category, vendor) = (cat.category_of_each(), cat.vendor_of_each());
    PerEntry::new(
        Ix::all(cat.components.len())
            .map(|ci| (category[ci], vendor[ci]))
            .collect(),
    )
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

/// A view's link as a cell: linked when it has a target the output writes, else plain.
pub fn linked<M: Markup>(cat: &Catalog, from: &Page, l: &Linked<'_>) -> String {
    match l.to {
        Some((to, anchor)) if M::OUTPUT.carries(to.kind) => {
            M::page_link(cat, from, to, anchor, &l.text)
        }
        _ => M::esc(&l.text),
    }
}

/// A section of links (`(anchor, title)` its heading), left out when there are none.
fn links_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    page: &Page,
    (anchor, title): (&str, &str),
    links: &[Linked<'_>],
) {
    if links.is_empty() {
        return;
    }
    M::heading(out, page, 2, anchor, title);
    let items: Vec<String> = links.iter().map(|l| linked::<M>(cat, page, l)).collect();
    M::linked_list(out, &items);
}

/// The way back from an entry page: the front page (named by the site's title), then `index`
/// (named by its label) if given.
pub fn crumbs<'a>(
    cat: &'a Catalog,
    site_title: &str,
    index: Option<(&'a Page, &str)>,
) -> Vec<Linked<'a>> {
    let home = Linked::new(
        site_title,
        Some(cat.site_page(crate::catalog::PageKind::Index)),
        None,
    );
    std::iter::once(home)
        .chain(index.map(|(page, label)| Linked::new(label, Some(page), None)))
        .collect()
}

/// The start of a page: its title and the way back ([`crumbs`]: the front page, then `index`
/// if given).
fn head<M: Markup>(
    cat: &Catalog,
    (page, title): (&Page, &str),
    site_title: &str,
    index: Option<(&Page, &str)>,
) -> String {
    let mut out = String::new();
    M::page_head(&mut out, cat, page, title, &crumbs(cat, site_title, index));
    out
}

/// A list of components as a table (name, description, vendor, version) on page `from`;
/// `parent`: the components hang from `from` in the page tree.
pub fn component_table<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    from: &Page,
    rows: &[ComponentRow<'_>],
    parent: bool,
    lang: Lang,
) {
    let cells: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let name = match r.name.to {
                Some((to, _)) if parent => M::child_link(cat, from, to, &r.name.text),
                _ => linked::<M>(cat, from, &r.name),
            };
            vec![
                name,
                M::esc(r.description),
                M::esc(r.vendor),
                M::esc(r.version),
            ]
        })
        .collect();
    M::table(out, &component_cols(lang), &cells);
}

/// A category's or vendor's page from its view: title and the way back, the other spellings
/// met, and its components.
pub fn facet_page<M: Markup>(
    cat: &Catalog,
    v: &FacetView<'_>,
    site_title: &str,
    lang: Lang,
) -> String {
    let index = (v.index, lang.t(v.kind.index_key()));
    let mut out = head::<M>(cat, (v.page, &v.name), site_title, Some(index));
    if !v.variants.is_empty() {
        let names: Vec<String> = v.variants.iter().map(|n| M::esc(n)).collect();
        M::paragraph(
            &mut out,
            &format!("{}: {}", M::esc(lang.t("facet_variants")), names.join(", ")),
        );
    }
    component_table::<M>(&mut out, cat, v.page, &v.components, v.parent, lang);
    out
}

/// The index of the categories or vendors from its view: each one linked, with its number of
/// components.
pub fn facet_index_page<M: Markup>(
    cat: &Catalog,
    v: &FacetIndexView<'_>,
    site_title: &str,
    lang: Lang,
) -> String {
    let mut out = head::<M>(cat, (v.page, lang.t(v.kind.index_key())), site_title, None);
    let items: Vec<String> = v
        .facets
        .iter()
        .filter_map(|f| {
            let (to, _) = f.name.to?;
            Some(format!(
                "{} ({})",
                M::child_link(cat, v.page, to, &f.name.text),
                f.count
            ))
        })
        .collect();
    if items.is_empty() {
        M::paragraph(&mut out, &M::esc(lang.t("empty_facets")));
    } else {
        M::linked_list(&mut out, &items);
    }
    out
}

/// The index of RT Systems from its view: each system linked, with its version, vendor and
/// counts.
pub fn systems_index_page<M: Markup>(
    cat: &Catalog,
    v: &SystemsIndexView<'_>,
    site_title: &str,
    lang: Lang,
) -> String {
    let mut out = head::<M>(cat, (v.page, lang.t("systems")), site_title, None);
    M::paragraph(&mut out, &M::esc(lang.t("systems_intro")));
    let rows: Vec<Vec<String>> = v
        .systems
        .iter()
        .map(|s| {
            let name = match s.name.to {
                Some((to, _)) => M::child_link(cat, v.page, to, &s.name.text),
                None => M::esc(&s.name.text),
            };
            vec![
                name,
                M::esc(s.version),
                M::esc(s.vendor),
                s.instances.to_string(),
                s.connectors.to_string(),
            ]
        })
        .collect();
    M::table(
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

/// A port's "connects to" cell from its view: one link per peer component, then "+N — …".
fn peers_cell<M: Markup>(cat: &Catalog, from: &Page, p: &Peers<'_>) -> String {
    p.shown
        .iter()
        .chain(&p.more)
        .map(|l| linked::<M>(cat, from, l))
        .collect::<Vec<_>>()
        .join("<br>")
}

/// Facts inside one cell, after the row's description and before its events.
fn details_cell<M: Markup>(facts: &[Fact], events: &[(&str, Vec<Fact>)]) -> String {
    let mut cell = facts_cell::<M>(facts);
    for (name, f) in events {
        if !cell.is_empty() {
            cell.push_str("<br>");
        }
        cell.push_str(&M::bold(&M::esc(name)));
        if !f.is_empty() {
            cell.push_str("<br>");
            cell.push_str(&facts_cell::<M>(f));
        }
    }
    cell
}

/// The sections of a component page after its title and lead text, from its view: basic
/// info, Document Profile, data ports, service ports, configuration, lifecycle, system
/// parameters, language, properties, version history, backups, extras and the systems using
/// it — the same tables in every text format.
pub fn component_sections<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    v: &ComponentView<'_>,
    lang: Lang,
) {
    let page = v.page;
    if v.implementation.as_ref().is_some_and(|i| i.recovered) {
        M::paragraph(out, &M::bold(&M::esc(lang.t("impl_recovered_note"))));
    }
    M::heading(out, page, 2, "sec-basic-info", lang.t("fact_basic_info"));
    let (vendor_label, source_label) = (lang.t("vendor"), lang.t("source"));
    let rows: Vec<Vec<String>> = v
        .basic
        .iter()
        .map(|f| {
            let value = match (v.vendor, &v.source_url) {
                (Some(to), _) if f.label == vendor_label => {
                    M::link(&f.value, &M::page_target(cat, page, to))
                }
                (_, Some(url)) if f.label == source_label => M::link(&f.value, url),
                _ => M::esc(&f.value),
            };
            vec![M::esc(&f.label), value]
        })
        .collect();
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &rows);

    if !v.document.is_empty() {
        M::heading(out, page, 2, "sec-document", lang.t("fact_document"));
        facts_table::<M>(out, lang, &v.document);
    }
    data_ports_section::<M>(out, cat, v, lang);
    service_ports_section::<M>(out, cat, v, lang);
    neighbourhood_section::<M>(out, cat, v, lang);
    configuration_section::<M>(out, v, lang);

    M::heading(out, page, 2, "sec-lifecycle", lang.t("actions"));
    let rows: Vec<Vec<String>> = v
        .actions
        .iter()
        .map(|a| {
            let implemented = lang.t(if a.implemented { "yes" } else { "no" });
            vec![
                M::code(a.kind.callback_name()),
                M::esc(implemented),
                facts_cell::<M>(&a.details),
            ]
        })
        .collect();
    sparse_table::<M>(
        out,
        2,
        &[
            lang.t("fact_callback"),
            lang.t("implemented"),
            lang.t("fact_details"),
        ],
        &rows,
    );

    environment_sections::<M>(out, v, lang);

    history_section::<M>(out, cat, page, (&v.history, v.history_page), lang);

    if !v.extras.is_empty() {
        M::heading(out, page, 2, "sec-extra", lang.t("extra"));
        let extras: Vec<Fact> = v.extras.iter().map(|(f, _)| f.clone()).collect();
        facts_table::<M>(out, lang, &extras);
    }

    links_section::<M>(
        out,
        cat,
        page,
        ("sec-systems", lang.t("sys_used_by")),
        &v.systems,
    );
}

/// The system parameters, language and targets, properties, version history and backups of
/// a component page, each section when it has something to show.
fn environment_sections<M: Markup>(out: &mut String, v: &ComponentView<'_>, lang: Lang) {
    let page = v.page;
    if !v.parameters.is_empty() {
        M::heading(out, page, 2, "sec-system-parameters", lang.t("parameters"));
        let headers = [lang.t("name"), lang.t("default_value")];
        pairs_table::<M, _, _>(out, headers, v.parameters.iter().copied());
    }

    if !v.language.is_empty() || !v.targets.is_empty() {
        M::heading(out, page, 2, "sec-language", lang.t("language"));
        if !v.language.is_empty() {
            facts_table::<M>(out, lang, &v.language);
        }
        for (number, tf) in &v.targets {
            M::paragraph(
                out,
                &M::bold(&format!("{} {number}", M::esc(lang.t("fact_target")))),
            );
            facts_table::<M>(out, lang, tf);
        }
    }

    if !v.properties.is_empty() {
        M::heading(out, page, 2, "sec-properties", lang.t("properties"));
        let pairs = v.properties.iter().map(|f| (&f.label, &f.value));
        pairs_table::<M, _, _>(out, [lang.t("name"), lang.t("fact_value")], pairs);
    }

    if !v.version_up_logs.is_empty() {
        M::heading(
            out,
            page,
            2,
            "sec-version-history",
            lang.t("version_up_logs"),
        );
        M::list(out, &v.version_up_logs);
    }

    if !v.backups.is_empty() {
        M::heading(out, page, 2, "sec-backups", lang.t("backups"));
        M::paragraph(out, &M::esc(lang.t("backups_intro")));
        let rows: Vec<Vec<String>> = v
            .backups
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
    if let Some(im) = &v.implementation {
        implementation_section::<M>(out, page, im, lang);
    }
}

/// The Implementation section: the language and state, the files read (linked at the pinned
/// commit), the differences as a table, what could not be verified.
fn implementation_section<M: Markup>(
    out: &mut String,
    page: &Page,
    im: &crate::render::facts::ImplementationSection,
    lang: Lang,
) {
    M::heading(out, page, 2, "sec-implementation", lang.t("implementation"));
    M::paragraph(out, &M::esc(lang.t(im.intro)));
    M::paragraph(out, &M::bold(&M::esc(&im.summary)));
    M::paragraph(out, &M::bold(&M::esc(lang.t("impl_files"))));
    let files: Vec<String> = im
        .files
        .iter()
        .map(|f| match &f.href {
            Some(h) => M::link(&f.text, h),
            None => M::esc(&f.text),
        })
        .collect();
    M::linked_list(out, &files);
    if !im.rows.is_empty() {
        let rows: Vec<Vec<String>> = im
            .rows
            .iter()
            .map(|r| {
                vec![
                    M::esc(&r.element),
                    M::esc(&r.profile),
                    M::esc(&r.code),
                    M::esc(&format!("{} ({})", r.at, r.rule)),
                ]
            })
            .collect();
        M::table(
            out,
            &[
                lang.t("impl_element"),
                lang.t("impl_profile_says"),
                lang.t("impl_code_says"),
                lang.t("impl_where"),
            ],
            &rows,
        );
    }
    for (label, items) in [
        ("impl_unread", &im.unread),
        ("impl_unverified", &im.unverified),
    ] {
        if !items.is_empty() {
            M::paragraph(out, &M::esc(lang.t(label)));
            let items: Vec<String> = items.iter().map(|u| M::esc(u)).collect();
            M::linked_list(out, &items);
        }
    }
}

/// A name with its "since" note (the version that added it): `status (since 1.1.0)`.
fn since_text(name: &str, since: Option<&str>, lang: Lang) -> String {
    match since {
        Some(v) => format!("{name} ({})", lang.t("since").replace("{v}", v)),
        None => name.to_string(),
    }
}

/// [`since_text`], escaped for a table cell.
fn named<M: Markup>(name: &str, since: Option<&str>, lang: Lang) -> String {
    M::esc(&since_text(name, since, lang))
}

/// A port table row: name, direction and type, the `middle` cells, then description, details
/// (with `events` after them) and peers.
fn port_row<M: Markup>(
    cat: &Catalog,
    page: &Page,
    p: &PortView<'_>,
    middle: Option<String>,
    events: &[(&str, Vec<Fact>)],
    lang: Lang,
) -> Vec<String> {
    let mut row = vec![
        M::anchored(page, p.anchor, &named::<M>(p.name, p.since, lang)),
        M::esc(&p.direction.label),
        p.type_
            .as_ref()
            .map(|t| linked::<M>(cat, page, t))
            .unwrap_or_default(),
    ];
    row.extend(middle);
    row.extend([
        p.description.map(M::esc).unwrap_or_default(),
        details_cell::<M>(&p.details, events),
        peers_cell::<M>(cat, page, &p.peers),
    ]);
    row
}

/// A table of [`port_row`]s under the headers `name`, direction, `type`, the `middle` ones,
/// description, details and peers; an empty optional column is left out.
fn port_table<M: Markup>(
    out: &mut String,
    lang: Lang,
    (name, type_, middle): (&str, &str, Option<&str>),
    rows: &[Vec<String>],
) {
    let mut headers = vec![lang.t(name), lang.t("direction"), lang.t(type_)];
    headers.extend(middle.map(|k| lang.t(k)));
    headers.extend(["description", "fact_details", "connects_to"].map(|k| lang.t(k)));
    sparse_table::<M>(out, 3, &headers, rows);
}

fn data_ports_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    v: &ComponentView<'_>,
    lang: Lang,
) {
    if v.data_ports.is_empty() {
        return;
    }
    let page = v.page;
    M::heading(out, page, 2, "sec-data-ports", lang.t("data_ports"));
    let rows: Vec<Vec<String>> = v
        .data_ports
        .iter()
        .map(|dp| port_row::<M>(cat, page, &dp.port, Some(M::esc(dp.unit)), &dp.events, lang))
        .collect();
    port_table::<M>(out, lang, ("name", "data_type", Some("unit")), &rows);
}

fn service_ports_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    v: &ComponentView<'_>,
    lang: Lang,
) {
    if v.service_ports.is_empty() {
        return;
    }
    let page = v.page;
    M::heading(out, page, 2, "sec-service-ports", lang.t("service_ports"));
    for sp in &v.service_ports {
        M::heading(
            out,
            page,
            3,
            sp.anchor,
            &since_text(
                if sp.name.is_empty() { "?" } else { sp.name },
                sp.since,
                lang,
            ),
        );
        if !sp.details.is_empty() {
            facts_table::<M>(out, lang, &sp.details);
        }
        if sp.interfaces.is_empty() {
            continue;
        }
        let rows: Vec<Vec<String>> = sp
            .interfaces
            .iter()
            .map(|i| port_row::<M>(cat, page, &i.port, None, &[], lang))
            .collect();
        port_table::<M>(out, lang, ("interface", "type", None), &rows);
    }
}

fn configuration_section<M: Markup>(out: &mut String, v: &ComponentView<'_>, lang: Lang) {
    if v.configurations.is_empty() {
        return;
    }
    let page = v.page;
    M::heading(out, page, 2, "sec-configuration", lang.t("configuration"));
    let rows: Vec<Vec<String>> = v
        .configurations
        .iter()
        .map(|cf| {
            vec![
                M::anchored(page, cf.anchor, &named::<M>(cf.name, cf.since, lang)),
                M::esc(cf.type_),
                M::esc(cf.default),
                M::esc(cf.unit),
                M::esc(&cf.constraint),
                M::esc(&cf.widget),
                cf.description.map(M::esc).unwrap_or_default(),
                facts_cell::<M>(&cf.details),
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
            lang.t("fact_widget"),
            lang.t("description"),
            lang.t("fact_details"),
        ],
        &rows,
    );
}

/// A data type's or interface's page from its view: title and crumbs, spellings and IDL
/// files, the IDL definition, the ports using it by role, and the system connectors carrying
/// it. One function for both kinds and for Markdown and Doxygen.
/// The stability mark under a page's title: `**Deprecated since 2.0** — use X. Note`, the
/// replacement linked when the catalogue has it.
pub fn stability_line<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    page: &Page,
    s: Option<&crate::render::view::StabilityView<'_>>,
) {
    let Some(s) = s else {
        return;
    };
    let mut line = M::bold(&M::esc(&s.headline));
    if let Some((before, after, r)) = &s.replacement {
        // The spaces around the replacement kept, which escaping a piece alone would trim.
        let spaced = |words: &str| {
            let lead = if words.starts_with(' ') { " " } else { "" };
            let trail = if words.ends_with(' ') { " " } else { "" };
            let inner = words.trim();
            if inner.is_empty() {
                lead.to_string()
            } else {
                format!("{lead}{}{trail}", M::esc(inner))
            }
        };
        line.push_str(" — ");
        line.push_str(&spaced(before));
        line.push_str(&linked::<M>(cat, page, r));
        line.push_str(&spaced(after));
    }
    if let Some(n) = s.note {
        line.push_str(". ");
        line.push_str(&M::esc(n));
    }
    M::stability(out, &line, s.deprecated);
}

pub fn type_page<M: Markup>(
    cat: &Catalog,
    v: &TypeView<'_>,
    site_title: &str,
    lang: Lang,
) -> String {
    let page = v.page;
    let index = (v.index, lang.t(v.kind.index_key()));
    let mut out = head::<M>(cat, (page, v.name), site_title, Some(index));
    stability_line::<M>(&mut out, cat, page, v.stability.as_ref());
    if v.unprovided {
        M::note(&mut out, lang.t("not_provided"));
    }
    names_facts::<M>(&mut out, lang, v.spellings, v.idl_files);
    super::idl_view::write_definition::<M>(&mut out, cat, page, v.name, lang, &|o, a, text| {
        M::heading(o, page, 2, a, text)
    });
    if let Some(f) = &v.idl_file {
        idl_file_section::<M>(&mut out, cat, page, f, lang);
    }
    links_section::<M>(
        &mut out,
        cat,
        page,
        ("contained-in", lang.t("idl_contained_in")),
        &v.contained_in,
    );
    interface_uses_section::<M>(&mut out, cat, v, lang);
    if v.kind == TypeKind::Interface && v.uses.is_empty() {
        M::paragraph(&mut out, &M::esc(lang.t("interface_no_components")));
    }
    let cols = [lang.t("component"), lang.t("fact_port"), lang.t("type")];
    for g in &v.uses {
        M::heading(&mut out, page, 2, g.anchor, g.label);
        let rows: Vec<Vec<String>> = g
            .rows
            .iter()
            .map(|r| {
                vec![
                    linked::<M>(cat, page, &r.component),
                    linked::<M>(cat, page, &r.port),
                    M::esc(&r.written),
                ]
            })
            .collect();
        M::table(&mut out, &cols, &rows);
    }
    links_section::<M>(
        &mut out,
        cat,
        page,
        ("sec-system-connectors", lang.t("sys_carried_by")),
        &v.carried_by,
    );
    out
}

/// The operations and attributes of interfaces using the type, interface by interface.
fn interface_uses_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    v: &TypeView<'_>,
    lang: Lang,
) {
    if v.used_by.is_empty() {
        return;
    }
    let page = v.page;
    let title = format!("{} ({})", lang.t("idl_used_by"), v.used_by_interfaces);
    M::heading(out, page, 2, "used-by-interfaces", &title);
    let rows: Vec<Vec<String>> = v
        .used_by
        .iter()
        .map(|u| {
            let interface = match u.page {
                Some(to) => M::page_link(cat, page, to, None, u.interface),
                None => M::esc(u.interface),
            };
            vec![interface, M::code(u.member), M::esc(&u.how)]
        })
        .collect();
    M::table(
        out,
        &[lang.t("interface"), lang.t("idl_member"), lang.t("idl_use")],
        &rows,
    );
}

/// The index of the data types or of the interfaces from its view: each linked, with its
/// numbers of uses by role; an interface nobody provides is flagged.
pub fn type_index_page<M: Markup>(
    cat: &Catalog,
    v: &TypeIndexView<'_>,
    site_title: &str,
    lang: Lang,
) -> String {
    let page = v.page;
    let mut out = head::<M>(cat, (page, lang.t(v.kind.index_key())), site_title, None);
    let rows: Vec<Vec<String>> = v
        .rows
        .iter()
        .map(|r| {
            let mut cell = M::child_link(cat, page, r.page, &r.page.title);
            if r.unprovided {
                cell.push_str(&format!(" ({})", M::esc(lang.t("not_provided"))));
            }
            let interfaces = (v.kind == TypeKind::Data).then(|| r.interfaces.to_string());
            std::iter::once(cell)
                .chain(r.counts.iter().map(usize::to_string))
                .chain(interfaces)
                .collect()
        })
        .collect();
    if rows.is_empty() {
        let key = match v.kind {
            TypeKind::Data => "empty_types",
            TypeKind::Interface => "empty_interfaces",
        };
        M::paragraph(&mut out, &M::esc(lang.t(key)));
        return out;
    }
    let headers = match v.kind {
        TypeKind::Data => [
            lang.t("data_type"),
            lang.t("producers"),
            lang.t("consumers"),
        ],
        TypeKind::Interface => [
            lang.t("interface"),
            lang.t("providers"),
            lang.t("requirers"),
        ],
    };
    let mut heads = vec![headers[0], headers[1], headers[2], lang.t("fact_others")];
    if v.kind == TypeKind::Data {
        heads.push(lang.t("idl_used_by"));
    }
    M::table(&mut out, &heads, &rows);
    out
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

/// The History section of a component page: the latest versions, newest first, with their
/// counts of changes by severity and the breaking changes spelled out.
fn history_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    page: &Page,
    (h, full): (&crate::render::view::history::HistoryView, Option<&Page>),
    lang: Lang,
) {
    if h.rows.is_empty() {
        return;
    }
    M::heading(out, page, 2, "sec-change-history", lang.t("change_history"));
    let full = full.map(|to| (cat, page, to));
    history_body::<M>(out, h, lang.t("history_intro"), full, lang);
}

/// The IDL file section of a type page: the file (linked into its repository) and its latest
/// versions.
fn idl_file_section<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    page: &Page,
    f: &crate::render::view::idl_file::IdlFileView<'_>,
    lang: Lang,
) {
    M::heading(out, page, 2, "sec-idl-file", lang.t("idl_file"));
    let file = match &f.source_url {
        Some(url) => M::link(&f.file, url),
        None => M::code(&f.file),
    };
    M::paragraph(out, &format!("{}: {file}", M::esc(lang.t("source"))));
    if !f.history.rows.is_empty() {
        let full = f.history_page.map(|to| (cat, page, to));
        history_body::<M>(out, &f.history, lang.t("history_intro_idl"), full, lang);
    }
}

/// A History section's text under its heading: `intro`, the table of the latest versions, the
/// note on older ones and the link to the history page `full` (catalogue, this page, the
/// history page) when there is one (component, system and type pages).
pub(super) fn history_body<M: Markup>(
    out: &mut String,
    h: &crate::render::view::history::HistoryView,
    intro: &str,
    full: Option<(&Catalog, &Page, &Page)>,
    lang: Lang,
) {
    M::paragraph(out, &M::esc(intro));
    let rows: Vec<Vec<String>> = h
        .rows
        .iter()
        .map(|r| {
            let label = match (&r.url, r.label.is_empty()) {
                (_, true) => String::new(),
                (Some(url), false) => M::link(&r.label, url),
                (None, false) => M::code(&r.label),
            };
            let mut changes = M::esc(&r.summary);
            let mut each: Vec<String> = r
                .changes
                .iter()
                .map(|c| {
                    let mut item = M::esc(&c.severity_label);
                    if !c.path.is_empty() {
                        item.push_str(&format!(" {}:", M::esc(&c.path)));
                    }
                    format!("{item} {}", message_and_reach::<M>(c))
                })
                .collect();
            each.extend(r.more.as_deref().map(|more| match full {
                Some((cat, from, to)) => M::page_link(cat, from, to, Some(&r.anchor), more),
                None => M::esc(more),
            }));
            if !each.is_empty() {
                changes.push_str(": ");
                changes.push_str(&each.join("; "));
            }
            vec![
                M::esc(&r.version),
                M::esc(&r.date),
                label,
                M::esc(&r.author),
                M::esc(&r.subject),
                changes,
            ]
        })
        .collect();
    M::table(
        out,
        &[
            lang.t("history_version"),
            lang.t("history_date"),
            lang.t("history_commit"),
            lang.t("history_author"),
            lang.t("history_subject"),
            lang.t("history_changes"),
        ],
        &rows,
    );
    if let Some(note) = h.older_note(lang) {
        M::paragraph(out, &M::esc(&note));
    }
    if let Some((cat, from, to)) = full {
        M::paragraph(
            out,
            &M::page_link(cat, from, to, None, lang.t("history_full")),
        );
    }
}

/// A change's message, and what it reaches after a dash when it reaches other components.
pub(crate) fn message_and_reach<M: Markup>(c: &crate::render::view::history::ChangeRow) -> String {
    match &c.reach {
        Some(reach) => format!("{} — {}", M::message(&c.message), M::esc(reach)),
        None => M::message(&c.message),
    }
}
