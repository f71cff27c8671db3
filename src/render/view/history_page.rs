//! The history pages: the whole history of a component, an RT System or an IDL file
//! ([`HistoryPageView`]), the catalogue's What's new ([`WhatsNewView`]) and the entries of the
//! Atom feed ([`feed_entries`]). Built once from the catalogue's histories
//! ([`crate::catalog::history`]), shown by every output.

pub use super::history::{by_severity, ChangeRow};
use super::history::{committed, row, HistoryRow};
use crate::catalog::history::{Change, Entry, HistoryOf};
use crate::catalog::{Catalog, Component, Page, TypeIx};
use crate::i18n::Lang;
use serde::Serialize;

/// Changes listed on What's new, newest first; older ones are on the history pages (the page
/// says how many it leaves out).
pub const WHATS_NEW_MAX: usize = 2000;

/// Entries in the Atom feed, newest first.
pub const FEED_MAX: usize = 100;

/// The link of a commit of component `c` to its file: the `{commit}` form of its source's
/// `source-url`, else of the site's. The same link on the component page and the history pages.
pub fn commit_url(
    cat: &Catalog,
    c: &Component,
    source_url: Option<&str>,
    commit: &str,
    path: &str,
) -> Option<String> {
    crate::render::html::repo::history_file_urls(&cat.sources, c.origin.as_ref(), source_url)(
        commit, path,
    )
}

/// The `[[source]]` the file of a history was read from (`None`: the input directory).
fn origin_of(cat: &Catalog, of: HistoryOf) -> Option<&crate::model::Origin> {
    match of {
        HistoryOf::Component(ci) => cat[ci].origin.as_ref(),
        HistoryOf::System(si) => cat.systems.get(si.get())?.origin.as_ref(),
        HistoryOf::Idl(fi) => cat.idl.files.get(fi)?.origin.as_ref(),
    }
}

/// The link of a commit of the file of `of` (commit, path), as [`commit_url`] makes it.
fn commit_url_of<'c>(
    cat: &'c Catalog,
    of: HistoryOf,
    source_url: Option<&'c str>,
) -> impl Fn(&str, &str) -> Option<String> + 'c {
    crate::render::html::repo::history_file_urls(&cat.sources, origin_of(cat, of), source_url)
}

/// The date of the current file of `of`, which git did not date: a component's or a system's
/// `updateDate` ([`update_date`]); `None` for an IDL file.
fn current_date_of(cat: &Catalog, of: HistoryOf) -> Option<String> {
    match of {
        HistoryOf::Component(ci) => current_file_date(&cat[ci]),
        HistoryOf::System(si) => update_date(&cat.systems.get(si.get())?.profile.update_date),
        HistoryOf::Idl(_) => None,
    }
}

/// The type an IDL file's change is to, when it has a page: the change path starts with
/// `idl/<scoped name>` ([`crate::diff::compare_idl_files`]).
fn changed_type(cat: &Catalog, of: HistoryOf, c: &Change) -> Option<TypeIx> {
    if !matches!(of, HistoryOf::Idl(_)) {
        return None;
    }
    let name = c.path.strip_prefix("idl/")?.split('/').next()?;
    cat.data_type_index(name)
        .map(TypeIx::Data)
        .or_else(|| cat.interface_index_of(name).map(TypeIx::Interface))
}

/// The label of a severity (`breaking`, `warning`, `info`).
pub fn severity_label(severity: &str, lang: Lang) -> &'static str {
    match severity {
        "breaking" => lang.t("severity_breaking"),
        "warning" => lang.t("severity_warning"),
        _ => lang.t("severity_info"),
    }
}

/// One item of a history page: a version shown on its own, or a run of versions that changed
/// nothing of the specification, folded.
#[derive(Debug, Clone, Serialize)]
pub struct HistoryItem {
    /// What the History section of the page of the component (system, type) shows for it; for
    /// a folded run, its summary is all the page shows.
    pub row: HistoryRow,
    /// A version shown on its own; `None` for a folded run.
    pub version: Option<VersionItem>,
}

/// What a history page shows of a version beside its row.
#[derive(Debug, Clone, Serialize)]
pub struct VersionItem {
    /// `v-<commit or backup>`.
    pub anchor: String,
    /// Its version string and label (the release is marked beside it, once).
    pub heading: String,
    /// A release (a new version string).
    pub release: bool,
    /// Every change from the version before.
    pub changes: Vec<ChangeRow>,
}

/// The history page of a component, an RT System or an IDL file.
#[derive(Debug, Clone)]
pub struct HistoryPageView<'a> {
    pub page: &'a Page,
    /// The page of what it is the history of (the component's, the system's); `None` for an
    /// IDL file.
    pub back: Option<&'a Page>,
    pub of: HistoryOf,
    /// The component's or system's name, the IDL file's path.
    pub name: String,
    /// What the page lists (the kind of file and its versions).
    pub intro: &'static str,
    /// The pages of the types an IDL file defines (its data types and interfaces with a
    /// page), in the file's order of definition; empty for the others.
    pub types: Vec<super::Linked<'a>>,
    pub items: Vec<HistoryItem>,
}

/// The anchor of entry `e` on its history page.
pub fn entry_anchor(e: &Entry) -> String {
    let label = if e.commit.is_none() && e.backup.is_none() {
        "working-copy"
    } else {
        e.label()
    };
    format!("v-{}", crate::slug::slugify(label))
}

/// The pages of the types IDL file `fi` defines, in its order of definition (nested ones
/// after their module's).
fn types_defined<'a>(cat: &'a Catalog, fi: usize) -> Vec<super::Linked<'a>> {
    let Some(file) = cat.idl.files.get(fi) else {
        return Vec::new();
    };
    let mut names = Vec::new();
    let mut stack: Vec<&crate::idl::IdlDefinition> = file.definitions.iter().rev().collect();
    while let Some(d) = stack.pop() {
        names.push(d.scoped_name().to_string());
        stack.extend(d.children().iter().rev());
    }
    let mut seen = std::collections::HashSet::new();
    names
        .into_iter()
        .filter(|n| seen.insert(n.clone()))
        .filter_map(|n| {
            let t = cat
                .data_type_index(&n)
                .map(TypeIx::Data)
                .or_else(|| cat.interface_index_of(&n).map(TypeIx::Interface))?;
            Some(super::Linked::new(&n, Some(cat.type_page(t)), None))
        })
        .collect()
}

/// The history page of `of` (`None` when it has no history).
pub fn history_page_view<'a>(
    cat: &'a Catalog,
    of: HistoryOf,
    source_url: Option<&str>,
    lang: Lang,
) -> Option<HistoryPageView<'a>> {
    let page = cat.history_page_of(of)?;
    let url = commit_url_of(cat, of, source_url);
    let mut items = Vec::new();
    let h = cat.history_of(of);
    let current = current_date_of(cat, of);
    let about = |c: &Change| {
        (
            changed_type(cat, of, c),
            super::history::reach_text(cat, of, c, lang),
        )
    };
    let mut i = 0;
    while i < h.len() {
        let e = &h[i];
        if e.stands_out() {
            let row = row(e, committed(h), lang, &url, (current.as_deref(), &about));
            let version = VersionItem {
                anchor: entry_anchor(e),
                heading: [e.version.as_deref().unwrap_or(""), row.label.as_str()]
                    .iter()
                    .filter(|s| !s.is_empty())
                    .copied()
                    .collect::<Vec<_>>()
                    .join(" · "),
                release: e.release && !e.first,
                changes: by_severity(&e.changes, &about, lang),
            };
            items.push(HistoryItem {
                row,
                version: Some(version),
            });
            i += 1;
            continue;
        }
        let run = h[i..].iter().take_while(|e| !e.stands_out()).count();
        items.push(HistoryItem {
            row: super::history::folded(run, lang),
            version: None,
        });
        i += run;
    }
    let (intro, types) = match of {
        HistoryOf::Component(_) => (lang.t("history_page_intro"), Vec::new()),
        HistoryOf::System(_) => (lang.t("history_page_intro_system"), Vec::new()),
        HistoryOf::Idl(fi) => (lang.t("history_page_intro_idl"), types_defined(cat, fi)),
    };
    Some(HistoryPageView {
        page,
        back: cat.page_of_history(of),
        of,
        name: cat.history_name(of),
        intro,
        types,
        items,
    })
}

/// A point in time to sort history entries by: seconds since 1970 in UTC from an ISO 8601
/// date with its offset (`2024-01-02T10:00:00+09:00`, a commit's), or read as UTC without one
/// (`2015-07-26 07:20:22`, a backup's local save time); `None` when it is no such date.
pub fn instant(date: &str) -> Option<i64> {
    let b = date.trim().as_bytes();
    let num = |r: std::ops::Range<usize>| -> Option<i64> {
        let s = std::str::from_utf8(b.get(r)?).ok()?;
        s.bytes()
            .all(|c| c.is_ascii_digit())
            .then(|| s.parse().ok())?
    };
    let (y, m, d) = (num(0..4)?, num(5..7)?, num(8..10)?);
    let (hh, mm, ss) = if b.len() >= 19 {
        (num(11..13)?, num(14..16)?, num(17..19)?)
    } else {
        (0, 0, 0)
    };
    // The offset, after the fraction of a second if any.
    let at = 19 + fraction_len(date.trim());
    let offset = match b.get(at) {
        Some(sign @ (b'+' | b'-')) => {
            let o = num(at + 1..at + 3)? * 3600 + num(at + 4..at + 6)? * 60;
            if *sign == b'+' {
                o
            } else {
                -o
            }
        }
        _ => 0,
    };
    // Days from the civil date (Howard Hinnant's algorithm).
    let y2 = if m <= 2 { y - 1 } else { y };
    let era = y2.div_euclid(400);
    let yoe = y2 - era * 400;
    let doy = (153 * (m + if m > 2 { -3 } else { 9 }) + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    let days = era * 146097 + doe - 719468;
    Some(days * 86400 + hh * 3600 + mm * 60 + ss - offset)
}

/// Every history entry of the catalogue, newest first: (what it is the history of, entry
/// position), the current files first (each is the newest version of its file), then ordered
/// by date (entries without one last), then page order (components, systems, IDL files), then
/// history order.
fn entries_newest_first(cat: &Catalog) -> Vec<(HistoryOf, usize)> {
    let mut all: Vec<((bool, Option<i64>), HistoryOf, usize)> = cat
        .histories()
        .flat_map(|of| {
            let zone = local_offset(cat, of);
            cat.history_of(of).iter().enumerate().map(move |(ei, e)| {
                let date = entry_date(cat, of, e, zone);
                ((e.is_current(), date.as_deref().and_then(instant)), of, ei)
            })
        })
        .collect();
    all.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
    all.into_iter().map(|(_, of, ei)| (of, ei)).collect()
}

/// The UTC offset (`+09:00`) of the machine a component's backups were saved on, which their
/// names do not say: that of its commits (their author dates), else of its profile's dates.
/// Systems and IDL files have no backups: their commits' offset.
fn local_offset(cat: &Catalog, of: HistoryOf) -> Option<&str> {
    fn offset(d: &str) -> Option<&str> {
        zone_of(d.trim())
    }
    cat.history_of(of)
        .iter()
        .filter(|e| e.backup.is_none())
        .filter_map(|e| e.date.as_deref().and_then(offset))
        .next()
        .or_else(|| {
            let HistoryOf::Component(ci) = of else {
                return None;
            };
            let b = &cat[ci].profile.basic_info;
            [&b.update_date, &b.creation_date]
                .into_iter()
                .find_map(|d| d.as_deref().and_then(offset))
        })
}

/// The date of entry `e` of the history of `of`: a backup's in the zone of `zone`
/// ([`zoned_date`]); for the current file, which git did not date, its profile's `updateDate`
/// (RTCBuilder sets it when it saves).
fn entry_date<'e>(
    cat: &Catalog,
    of: HistoryOf,
    e: &'e Entry,
    zone: Option<&str>,
) -> Option<std::borrow::Cow<'e, str>> {
    zoned_date(e, zone).or_else(|| {
        e.is_current()
            .then(|| current_date_of(cat, of))
            .flatten()
            .map(Into::into)
    })
}

/// The date of component `c`'s current file, which git did not date: its profile's
/// `updateDate` (RTCBuilder sets it when it saves), in whole seconds (RTCBuilder writes
/// milliseconds); `None` when it has none that reads as a date.
pub fn current_file_date(c: &crate::catalog::Component) -> Option<String> {
    update_date(&c.profile.basic_info.update_date)
}

/// A profile's `updateDate` as the date of its current file (see [`current_file_date`]).
pub fn update_date(written: &Option<crate::model::Text>) -> Option<String> {
    let d = crate::model::non_empty(written)?.trim();
    let d = match fraction_len(d) {
        0 => d.to_string(),
        f => format!("{}{}", &d[..19], &d[19 + f..]),
    };
    instant(&d).is_some().then_some(d)
}

/// The heading of a day of What's new and its anchor: a date, the current files
/// ([`CURRENT_FILES`]) or the versions without a date (empty).
pub fn day_heading(day: &str, lang: Lang) -> (String, String) {
    match day {
        "" => ("d-none".to_string(), lang.t("history_no_date").to_string()),
        CURRENT_FILES => (
            "d-current".to_string(),
            lang.t("history_current_files").to_string(),
        ),
        _ => (format!("d-{day}"), day.to_string()),
    }
}

/// The day of What's new that holds the current files (uncommitted edits, or profiles kept
/// outside git beside their backups): listed first.
pub const CURRENT_FILES: &str = "current";

/// The length of the fraction of a second after a trimmed ISO 8601 date's seconds (`.159` in
/// `2017-04-13T00:13:08.159+09:00`, as RTCBuilder writes), 0 without one.
fn fraction_len(d: &str) -> usize {
    match d.as_bytes().get(19) {
        Some(b'.') => {
            1 + d.as_bytes()[20..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count()
        }
        _ => 0,
    }
}

/// The UTC offset (`+09:00`) a trimmed ISO 8601 date ends with, if any.
fn zone_of(d: &str) -> Option<&str> {
    let f = fraction_len(d);
    d.get(19 + f..25 + f).filter(|o| o.starts_with(['+', '-']))
}

/// An entry's date with a time zone where it has none (a backup's, `YYYY-MM-DD hh:mm:ss` in
/// the saving machine's local time) and `zone` is known, so that it orders among commits.
fn zoned_date<'e>(
    e: &'e crate::catalog::history::Entry,
    zone: Option<&str>,
) -> Option<std::borrow::Cow<'e, str>> {
    let d = e.date.as_deref()?.trim();
    match zone {
        Some(z) if e.backup.is_some() && d.len() == 19 => {
            Some(format!("{}T{}{z}", &d[..10], &d[11..19]).into())
        }
        _ => Some(d.into()),
    }
}

/// One change on What's new.
#[derive(Debug, Clone, Serialize)]
pub struct WhatsNewRow {
    /// What changed: a component, an RT System, an IDL file.
    #[serde(skip)]
    pub of: HistoryOf,
    /// The component's or system's name, the IDL file's path.
    pub name: String,
    /// What kind of file it is, for a system or an IDL file ("RT System", "IDL file"); empty
    /// for a component.
    pub kind: String,
    /// The entry's anchor on its history page.
    pub anchor: String,
    pub version: String,
    pub date: String,
    /// The commit (12 digits) or backup.
    pub label: String,
    pub url: Option<String>,
    /// The `[[source]]` the file was read from (empty: the input directory).
    pub source: String,
    /// The component's category as written (empty for a system or an IDL file).
    pub category: String,
    pub change: ChangeRow,
}

/// What's new: the changes, newest first, grouped by day.
#[derive(Debug, Clone, Default)]
pub struct WhatsNewView {
    /// (day, its changes): `YYYY-MM-DD`, or empty for versions without a date.
    pub days: Vec<(String, Vec<WhatsNewRow>)>,
    /// Changes not listed (past [`WHATS_NEW_MAX`]).
    pub more: usize,
    /// The sources and categories the rows have (the filter's choices), sorted.
    pub sources: Vec<String>,
    pub categories: Vec<String>,
}

/// The kind of file `of` is, as What's new and the feed name it beside a system or an IDL
/// file (empty for a component).
fn kind_label(of: HistoryOf, lang: Lang) -> &'static str {
    match of {
        HistoryOf::Component(_) => "",
        HistoryOf::System(_) => lang.t("system"),
        HistoryOf::Idl(_) => lang.t("idl_file"),
    }
}

/// The catalogue's What's new: the changes of every history (components, RT Systems, IDL
/// files), newest first.
pub fn whats_new_view(cat: &Catalog, source_url: Option<&str>, lang: Lang) -> WhatsNewView {
    let mut v = WhatsNewView::default();
    let mut shown = 0;
    for (of, ei) in entries_newest_first(cat) {
        let e = &cat.history_of(of)[ei];
        if e.changes.is_empty() {
            continue;
        }
        let take = e.changes.len().min(WHATS_NEW_MAX - shown);
        v.more += e.changes.len() - take;
        if take == 0 {
            continue;
        }
        shown += take;
        let date = entry_date(cat, of, e, None)
            .map(|d| d.into_owned())
            .unwrap_or_default();
        let day = if e.is_current() {
            CURRENT_FILES.to_string()
        } else {
            date.get(..10).unwrap_or(&date).to_string()
        };
        let source = origin_of(cat, of)
            .map(|o| o.source.clone())
            .unwrap_or_default();
        let category = match of {
            HistoryOf::Component(ci) => {
                crate::model::non_empty(&cat[ci].profile.basic_info.category)
            }
            _ => None,
        }
        .unwrap_or("")
        .to_string();
        let (name, kind) = (cat.history_name(of), kind_label(of, lang).to_string());
        let url = e
            .commit
            .as_deref()
            .and_then(|commit| commit_url_of(cat, of, source_url)(commit, &e.file));
        let rows: Vec<WhatsNewRow> = e.changes[..take]
            .iter()
            .map(|ch| WhatsNewRow {
                of,
                name: name.clone(),
                kind: kind.clone(),
                anchor: entry_anchor(e),
                version: e.version.clone().unwrap_or_default(),
                date: super::history::shown_date(&date),
                label: e.label().to_string(),
                url: url.clone(),
                source: source.clone(),
                category: category.clone(),
                change: ChangeRow::of(
                    ch,
                    (
                        changed_type(cat, of, ch),
                        super::history::reach_text(cat, of, ch, lang),
                    ),
                    lang,
                ),
            })
            .collect();
        match v.days.last_mut() {
            Some((d, list)) if *d == day => list.extend(rows),
            _ => v.days.push((day, rows)),
        }
    }
    let rows = || v.days.iter().flat_map(|(_, r)| r);
    let mut sources: Vec<String> = rows().map(|r| r.source.clone()).collect();
    let mut categories: Vec<String> = rows().map(|r| r.category.clone()).collect();
    for l in [&mut sources, &mut categories] {
        l.sort();
        l.dedup();
        l.retain(|s| !s.is_empty());
    }
    v.sources = sources;
    v.categories = categories;
    v
}

/// One entry of the Atom feed: a version with changes.
#[derive(Debug, Clone)]
pub struct FeedEntry<'a> {
    /// The history page and the version's anchor there (the entry's link and id).
    pub page: &'a Page,
    pub anchor: String,
    /// `name version: subject`, the kind of file after a system's or an IDL file's name.
    pub title: String,
    /// RFC 3339 (`2024-01-02T10:00:00+09:00`).
    pub updated: String,
    pub author: String,
    /// The summary line and then one line per change.
    pub text: String,
}

/// A date of a history entry in RFC 3339: a commit's as is (git's strict ISO 8601), a backup's
/// local time as UTC.
pub fn rfc3339(date: &str) -> Option<String> {
    instant(date)?;
    let d = date.trim();
    Some(if let Some(o) = zone_of(d) {
        format!("{}T{}{o}", &d[..10], &d[11..19])
    } else if d.len() >= 19 {
        format!("{}T{}Z", &d[..10], &d[11..19])
    } else {
        format!("{}T00:00:00Z", &d[..10])
    })
}

/// The feed's entries: the latest [`FEED_MAX`] versions with changes and a date, newest first,
/// of every history (components, RT Systems, IDL files).
pub fn feed_entries(cat: &Catalog, lang: Lang) -> Vec<FeedEntry<'_>> {
    let mut out = Vec::new();
    for (of, ei) in entries_newest_first(cat) {
        if out.len() == FEED_MAX {
            break;
        }
        let h = cat.history_of(of);
        let e = &h[ei];
        let (Some(page), Some(updated)) = (
            cat.history_page_of(of),
            entry_date(cat, of, e, local_offset(cat, of))
                .as_deref()
                .and_then(rfc3339),
        ) else {
            continue;
        };
        if e.changes.is_empty() {
            continue;
        }
        let r = row(
            e,
            committed(h),
            lang,
            &|_, _| None,
            (None, &|_| (None, None)),
        );
        let mut title = cat.history_name(of);
        let kind = kind_label(of, lang);
        if !kind.is_empty() {
            title = format!("{title} ({kind})");
        }
        if !r.version.is_empty() {
            title = format!("{title} {}", r.version);
        }
        title = format!(
            "{title}: {}",
            if r.subject.is_empty() {
                &r.summary
            } else {
                &r.subject
            }
        );
        let mut text = r.summary.clone();
        for ch in &e.changes {
            text.push_str(&format!(
                "\n[{}] {} {}: {}",
                severity_label(&ch.severity, lang),
                ch.code,
                ch.path,
                ch.message
            ));
        }
        out.push(FeedEntry {
            page,
            anchor: entry_anchor(e),
            title,
            updated,
            author: e.author.clone().unwrap_or_default(),
            text,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn instants_order_dates_across_offsets() {
        for (date, want) in [
            ("1970-01-01T00:00:00+00:00", Some(0)),
            ("1970-01-01T09:00:00+09:00", Some(0)),
            ("2024-01-02 10:00:00", Some(1_704_189_600)),
            // RTCBuilder's dates have milliseconds.
            ("1970-01-01T09:00:00.159+09:00", Some(0)),
            ("yesterday", None),
        ] {
            assert_eq!(instant(date), want, "{date}");
        }
        assert!(instant("2024-01-02T10:00:00+09:00") < instant("2024-01-02T10:00:00+00:00"));
        for (date, want) in [
            ("2015-07-26 07:20:22", "2015-07-26T07:20:22Z"),
            ("2024-01-02T10:00:00+09:00", "2024-01-02T10:00:00+09:00"),
            ("2017-04-13T00:13:08.159+09:00", "2017-04-13T00:13:08+09:00"),
        ] {
            assert_eq!(rfc3339(date).as_deref(), Some(want), "{date}");
        }
    }

    /// What's new lists at most WHATS_NEW_MAX changes and counts the rest; the feed has at
    /// most FEED_MAX entries, newest first.
    #[test]
    fn whats_new_and_the_feed_are_bounded() {
        use crate::catalog::history::{Change, Entry};
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let opts = crate::build::LoadOptions::default();
        let mut cat = crate::build::load(&root.join("examples"), &opts)
            .unwrap()
            .catalog;
        let change = |i: usize| Change {
            severity: "info".into(),
            code: "DIFF301".into(),
            path: format!("dataPorts/p{i}"),
            message: format!("data port p{i} was added"),
            ..Change::default()
        };
        // 150 versions of 20 changes each, a day apart, newest first.
        let history: Vec<Entry> = (0..150)
            .map(|k| Entry {
                commit: Some(format!("{:040x}", 1000 - k)),
                file: "RTC.xml".into(),
                date: Some(format!(
                    "2024-{:02}-{:02}T00:00:00+00:00",
                    12 - k / 28,
                    28 - k % 28
                )),
                changes: (0..20).map(|i| change(k * 20 + i)).collect(),
                ..Entry::default()
            })
            .collect();
        cat.components[0].history = history;
        cat.history_attached();
        let v = whats_new_view(&cat, None, Lang::En);
        let rows: usize = v.days.iter().map(|(_, r)| r.len()).sum();
        assert_eq!(rows, WHATS_NEW_MAX);
        assert_eq!(v.more, 150 * 20 - WHATS_NEW_MAX);
        let feed = feed_entries(&cat, Lang::En);
        assert_eq!(feed.len(), FEED_MAX);
    }
}
