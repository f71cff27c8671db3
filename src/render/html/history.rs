//! The history pages of the site (`history.html`: the whole history of a component, an RT
//! System or an IDL file; `whats_new.html`: every change of the catalogue) and the Atom feed
//! `feed.xml`, from the views of [`crate::render::view::history_page`].

use super::{crumbs_home, ctx, page_title, Job, Link, PageContext, Site, SiteOptions};
use crate::catalog::{Catalog, Output, Page, PageKind};
use crate::render::view::history_page::{
    feed_entries, history_page_view, rfc3339, whats_new_view, WhatsNewRow,
};
use serde::Serialize;

/// The feed's path below the site root.
pub const FEED: &str = "feed.xml";

/// Something (a component, a system, an IDL file) has a history: the What's new page exists.
pub(super) fn has_history(catalog: &Catalog) -> bool {
    catalog.pages().iter().any(|p| p.kind == PageKind::WhatsNew)
}

/// The site has an Atom feed: some history, and a base URL to make its links absolute.
pub(super) fn has_feed(catalog: &Catalog, opts: &SiteOptions) -> bool {
    opts.base_url.is_some() && has_history(catalog)
}

/// One change of What's new as the template shows it.
#[derive(Serialize)]
struct NewsRow<'a> {
    link: Link,
    #[serde(flatten)]
    row: &'a WhatsNewRow,
}

#[derive(Serialize)]
struct Day<'a> {
    id: String,
    heading: String,
    rows: Vec<NewsRow<'a>>,
}

/// The jobs of the history pages (none without a history).
pub(super) fn pages<'a>(site: &'a Site<'a>) -> Vec<Job<'a>> {
    let (cat, lang) = (site.catalog, site.lang);
    let Some(here) = cat.pages().iter().find(|p| p.kind == PageKind::WhatsNew) else {
        return Vec::new();
    };
    let mut jobs = vec![Job {
        path: here.path_in(Output::Html),
        template: "whats_new.html",
        context: PageContext::Lazy(Box::new(move || {
            let mut v = whats_new_view(cat, site.opts.source_url.as_deref(), lang);
            for r in v.days.iter_mut().flat_map(|(_, rows)| rows) {
                link_type(cat, here, &mut r.change);
            }
            let days: Vec<Day<'_>> = v
                .days
                .iter()
                .map(|(day, rows)| {
                    let (id, heading) = crate::render::view::history_page::day_heading(day, lang);
                    Day {
                        id,
                        heading,
                        rows: rows
                            .iter()
                            .map(|r| NewsRow {
                                link: Link {
                                    text: r.name.clone(),
                                    href: cat
                                        .history_page_of(r.of)
                                        .map(|to| cat.href(here, to, Some(&r.anchor), Output::Html))
                                        .unwrap_or_default(),
                                },
                                row: r,
                            })
                            .collect(),
                    }
                })
                .collect();
            minijinja::context! {
                root => "",
                title => page_title(site, lang.t("whats_new")),
                crumbs => ctx(&crumbs_home(lang, "")),
                days => ctx(&days),
                more => (v.more > 0).then(|| lang.t("whats_new_more").replace("{n}", &v.more.to_string())),
                sources => v.sources,
                categories => v.categories,
                severities => ["breaking", "warning", "info"]
                    .iter()
                    .map(|s| Link {
                        text: crate::render::view::history_page::severity_label(s, lang).to_string(),
                        href: s.to_string(),
                    })
                    .map(|l| ctx(&l))
                    .collect::<Vec<_>>(),
            }
        })),
    }];
    for of in cat.histories() {
        let Some(page) = cat.history_page_of(of) else {
            continue;
        };
        jobs.push(Job {
            path: page.path_in(Output::Html),
            template: "history.html",
            context: PageContext::Lazy(Box::new(move || {
                let Some(mut v) = history_page_view(cat, of, site.opts.source_url.as_deref(), lang)
                else {
                    return minijinja::Value::UNDEFINED;
                };
                let root = "../";
                let mut crumbs = crumbs_home(lang, root);
                crumbs.extend(v.back.map(|to| Link {
                    text: v.name.clone(),
                    href: cat.href(v.page, to, None, Output::Html),
                }));
                for c in v
                    .items
                    .iter_mut()
                    .filter_map(|it| it.version.as_mut())
                    .flat_map(|version| &mut version.changes)
                {
                    link_type(cat, v.page, c);
                }
                let types: Vec<Link> = v
                    .types
                    .iter()
                    .map(|l| Link {
                        text: l.text.clone(),
                        href: l.target(cat, v.page, Output::Html).unwrap_or_default(),
                    })
                    .collect();
                let heading = lang.t("history_page_title").replace("{name}", &v.name);
                minijinja::context! {
                    root => root,
                    title => page_title(site, &heading),
                    heading => heading,
                    intro => v.intro,
                    types => ctx(&types),
                    crumbs => ctx(&crumbs),
                    items => ctx(&v.items),
                }
            })),
        });
    }
    jobs
}

/// Sets the link of change `c` to the page of the type it is to (an IDL file's change), from
/// page `from`.
fn link_type(cat: &Catalog, from: &Page, c: &mut crate::render::view::history_page::ChangeRow) {
    c.href = c
        .about
        .map(|t| cat.href(from, cat.type_page(t), None, Output::Html));
}

/// Escapes text for XML.
fn esc(s: &str) -> String {
    super::svg::esc(s)
}

/// `feed.xml`: an Atom 1.0 feed of the latest versions with changes, newest first. Its ids
/// are the pages' absolute URLs (stable across builds), its dates the commits' (never the
/// build time). `None` without a base URL or a history.
pub(super) fn feed(catalog: &Catalog, opts: &SiteOptions) -> Option<String> {
    if !has_feed(catalog, opts) {
        return None;
    }
    let base = format!("{}/", opts.base_url.as_deref()?.trim_end_matches('/'));
    let lang = opts.language;
    let entries = feed_entries(catalog, lang);
    let news = catalog
        .pages()
        .iter()
        .find(|p| p.kind == PageKind::WhatsNew)?;
    // The newest date of any version when no version has changes.
    let updated = entries
        .first()
        .map(|e| e.updated.clone())
        .or_else(|| {
            catalog
                .histories()
                .flat_map(|of| catalog.history_of(of))
                .filter_map(|e| e.date.as_deref())
                .filter_map(|d| Some((crate::render::view::history_page::instant(d)?, d)))
                .max()
                .and_then(|(_, d)| rfc3339(d))
        })
        .unwrap_or_else(|| "1970-01-01T00:00:00Z".to_string());
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n");
    x.push_str(&format!(
        "<feed xmlns=\"http://www.w3.org/2005/Atom\" xml:lang=\"{}\">\n",
        lang.tag()
    ));
    x.push_str(&format!(
        "  <title>{} — {}</title>\n",
        esc(&opts.title),
        esc(lang.t("whats_new"))
    ));
    x.push_str(&format!("  <id>{}</id>\n", esc(&format!("{base}{FEED}"))));
    x.push_str(&format!(
        "  <link rel=\"self\" type=\"application/atom+xml\" href=\"{}\"/>\n",
        esc(&format!("{base}{FEED}"))
    ));
    x.push_str(&format!(
        "  <link rel=\"alternate\" type=\"text/html\" href=\"{}\"/>\n",
        esc(&format!("{base}{}", news.path_in(Output::Html)))
    ));
    x.push_str(&format!("  <updated>{}</updated>\n", esc(&updated)));
    x.push_str(&format!(
        "  <author><name>{}</name></author>\n",
        esc(&opts.title)
    ));
    x.push_str(&format!(
        "  <generator>{}</generator>\n",
        esc(&crate::render::generator())
    ));
    for e in &entries {
        let url = format!("{base}{}#{}", e.page.path_in(Output::Html), e.anchor);
        x.push_str("  <entry>\n");
        x.push_str(&format!("    <title>{}</title>\n", esc(&e.title)));
        x.push_str(&format!("    <id>{}</id>\n", esc(&url)));
        x.push_str(&format!(
            "    <link rel=\"alternate\" type=\"text/html\" href=\"{}\"/>\n",
            esc(&url)
        ));
        x.push_str(&format!("    <updated>{}</updated>\n", esc(&e.updated)));
        if !e.author.is_empty() {
            x.push_str(&format!(
                "    <author><name>{}</name></author>\n",
                esc(&e.author)
            ));
        }
        x.push_str(&format!(
            "    <content type=\"text\">{}</content>\n",
            esc(&e.text)
        ));
        x.push_str("  </entry>\n");
    }
    x.push_str("</feed>\n");
    Some(x)
}
