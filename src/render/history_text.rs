//! The history pages for Markdown and Doxygen, from their views
//! ([`crate::render::view::history_page`]): the whole history of a component, an RT System or
//! an IDL file, and What's new. One `Markup`-generic function per page writes both formats.

use super::text::Markup;
use super::view::history_page::{
    history_page_view, whats_new_view, HistoryItem, HistoryPageView, WhatsNewView,
};
use super::view::Linked;
use crate::catalog::history::HistoryOf;
use crate::catalog::{Catalog, PageKind};
use crate::i18n::Lang;

/// The page of every version of `of` (`None` when it has no history).
pub fn history_page<M: Markup>(
    cat: &Catalog,
    of: HistoryOf,
    source_url: Option<&str>,
    lang: Lang,
) -> Option<(String, String)> {
    let v = history_page_view(cat, of, source_url, lang)?;
    let mut out = String::new();
    let mut crumbs = vec![Linked::new(
        lang.t("catalogue"),
        Some(cat.site_page(PageKind::Index)),
        None,
    )];
    crumbs.extend(v.back.map(|to| Linked::new(&v.name, Some(to), None)));
    let title = lang.t("history_page_title").replace("{name}", &v.name);
    M::page_head(&mut out, cat, v.page, &title, &crumbs);
    M::paragraph(&mut out, &M::esc(v.intro));
    if !v.types.is_empty() {
        let links: Vec<String> = v
            .types
            .iter()
            .filter_map(|l| Some(M::link(&l.text, &l.target(cat, v.page, M::OUTPUT)?)))
            .collect();
        let label = M::esc(lang.t("history_idl_types"));
        M::paragraph(&mut out, &format!("{label}: {}", links.join(", ")));
    }
    for item in &v.items {
        history_item::<M>(&mut out, cat, &v, item, lang);
    }
    Some((v.page.path_in(M::OUTPUT), out))
}

/// One version (its facts and every change), or a folded run of versions.
fn history_item<M: Markup>(
    out: &mut String,
    cat: &Catalog,
    v: &HistoryPageView<'_>,
    item: &HistoryItem,
    lang: Lang,
) {
    let r = &item.row;
    let Some(version) = &item.version else {
        M::paragraph(out, &M::esc(&r.summary));
        return;
    };
    M::heading(out, v.page, 2, &version.anchor, &version.heading);
    let commit = match &r.url {
        Some(url) => M::link(&r.label, url),
        None => M::esc(&r.label),
    };
    let rows: Vec<Vec<String>> = [
        (lang.t("history_date"), M::esc(&r.date)),
        (lang.t("history_commit"), commit),
        (lang.t("history_author"), M::esc(&r.author)),
        (lang.t("history_subject"), M::esc(&r.subject)),
        (lang.t("history_changes"), M::esc(&r.summary)),
    ]
    .into_iter()
    .filter(|(_, value)| !value.is_empty())
    .map(|(label, value)| vec![M::esc(label), value])
    .collect();
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &rows);
    if version.release {
        M::paragraph(out, &M::esc(lang.t("history_release_note")));
    }
    if !version.changes.is_empty() {
        let rows: Vec<Vec<String>> = version
            .changes
            .iter()
            .map(|c| {
                vec![
                    M::esc(&c.severity_label),
                    M::esc(&c.code),
                    match c.about {
                        Some(t) => M::page_link(cat, v.page, cat.type_page(t), None, &c.path),
                        None => M::esc(&c.path),
                    },
                    super::text::message_and_reach::<M>(c),
                ]
            })
            .collect();
        M::table(
            out,
            &[
                lang.t("severity"),
                lang.t("code"),
                lang.t("extra_path"),
                lang.t("message"),
            ],
            &rows,
        );
    }
}

/// What's new: every change, newest first, grouped by day, as a plain list.
pub fn whats_new_page<M: Markup>(
    cat: &Catalog,
    source_url: Option<&str>,
    lang: Lang,
) -> Option<(String, String)> {
    let page = cat.pages().iter().find(|p| p.kind == PageKind::WhatsNew)?;
    let v: WhatsNewView = whats_new_view(cat, source_url, lang);
    let mut out = String::new();
    let crumbs = [Linked::new(
        lang.t("catalogue"),
        Some(cat.site_page(PageKind::Index)),
        None,
    )];
    M::page_head(&mut out, cat, page, lang.t("whats_new"), &crumbs);
    M::paragraph(&mut out, &M::esc(lang.t("whats_new_intro")));
    if v.days.is_empty() {
        M::paragraph(&mut out, &M::esc(lang.t("whats_new_none")));
    }
    for (day, rows) in &v.days {
        let (anchor, heading) = crate::render::view::history_page::day_heading(day, lang);
        M::heading(&mut out, page, 2, &anchor, &heading);
        let items: Vec<String> = rows
            .iter()
            .map(|r| {
                // A system's or IDL file's kind is part of the link, as on the HTML page.
                let name = match r.kind.is_empty() {
                    true => r.name.clone(),
                    false => format!("{} ({})", r.name, r.kind),
                };
                let component = match cat.history_page_of(r.of) {
                    Some(to) => M::page_link(cat, page, to, Some(&r.anchor), &name),
                    None => M::esc(&name),
                };
                let path = match r.change.about {
                    Some(t) => M::page_link(cat, page, cat.type_page(t), None, &r.change.path),
                    None => M::esc(&r.change.path),
                };
                let commit = match &r.url {
                    Some(url) => M::link(&r.label, url),
                    None => M::esc(&r.label),
                };
                let mut head = component;
                if !r.version.is_empty() {
                    head = format!("{head} {}", M::esc(&r.version));
                }
                if !r.date.is_empty() {
                    head = format!("{head} · {}", M::esc(&r.date));
                }
                format!(
                    "{head} · {commit} — {} {} {}: {}",
                    M::esc(&r.change.severity_label),
                    M::esc(&r.change.code),
                    path,
                    super::text::message_and_reach::<M>(&r.change)
                )
            })
            .collect();
        M::linked_list(&mut out, &items);
    }
    if v.more > 0 {
        M::paragraph(
            &mut out,
            &M::esc(&lang.t("whats_new_more").replace("{n}", &v.more.to_string())),
        );
    }
    Some((page.path_in(M::OUTPUT), out))
}

/// Both kinds of history page for one output: What's new, then each history (components,
/// systems, IDL files).
pub fn pages<M: Markup>(
    cat: &Catalog,
    source_url: Option<&str>,
    lang: Lang,
) -> Vec<(String, String)> {
    use rayon::prelude::*;
    let mut out: Vec<(String, String)> = whats_new_page::<M>(cat, source_url, lang)
        .into_iter()
        .collect();
    let all: Vec<HistoryOf> = cat.histories().collect();
    out.par_extend(
        all.into_par_iter()
            .filter_map(|of| history_page::<M>(cat, of, source_url, lang)),
    );
    out
}
