//! The History section of a page: the latest versions of its file (a component profile's commits
//! and RTCBuilder backups, an RT System profile's commits, [`crate::catalog::history`]), newest
//! first, versions without a change to the specification folded into one row. Built once,
//! shown by every output.

use crate::catalog::history::Entry;
use crate::i18n::Lang;
use serde::Serialize;

/// Rows shown on a page; the whole history is in catalog.json.
pub const ROWS: usize = 10;

/// Changes spelled out in one row (breaking first); the row says how many more there are, on
/// the history page.
pub const ROW_CHANGES: usize = 5;

/// One change as the pages list it.
#[derive(Debug, Clone, Serialize)]
pub struct ChangeRow {
    /// `breaking`, `warning` or `info` (the class and the filter value).
    pub severity: String,
    /// Its label in the page's language.
    pub severity_label: String,
    pub code: String,
    pub path: String,
    pub message: String,
    /// The data type or interface an IDL file's change is to, when it has a page.
    #[serde(skip)]
    pub about: Option<crate::catalog::TypeIx>,
    /// The other components of the catalogue that the change reaches (they use the port's
    /// type, the interface or the IDL definition it is to), as the history page says it
    /// ([`reach_text`]); `None` on the other pages and for a change that reaches none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reach: Option<String>,
    /// The link to that page, from the page showing the change (set by the HTML writer).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub href: Option<String>,
    /// The message as HTML when it is a long text's word-level difference
    /// ([`crate::word_diff`]): the deleted words in `<del>`, the inserted ones in `<ins>`, the
    /// line breaks as `<br>`; the HTML pages show it instead of `message`.
    pub html: Option<String>,
}

impl ChangeRow {
    /// The row of change `c`, about the type `about` (an IDL file's change), reaching `reach`.
    pub fn of(
        c: &crate::catalog::history::Change,
        (about, reach): (Option<crate::catalog::TypeIx>, Option<String>),
        lang: Lang,
    ) -> ChangeRow {
        ChangeRow {
            severity: c.severity.clone(),
            severity_label: super::history_page::severity_label(&c.severity, lang).to_string(),
            code: c.code.clone(),
            path: c.path.clone(),
            message: c.message.clone(),
            about,
            reach,
            href: None,
            html: words_html(c),
        }
    }
}

/// A change's message as HTML, when it is its long text's word-level difference.
fn words_html(c: &crate::catalog::history::Change) -> Option<String> {
    use crate::word_diff::{message, pieces, Piece};
    let (old, new) = (c.old.as_deref(), c.new.as_deref());
    if message(old, new)? != c.message {
        return None;
    }
    let mut out = String::from("changed: ");
    let text = |s: &str, out: &mut String| {
        for (i, line) in s.split('\n').enumerate() {
            if i > 0 {
                out.push_str("<br>");
            }
            // Writing to a String cannot fail.
            let _ = crate::render::html::svg::esc_into(out, line);
        }
    };
    for p in pieces(old, new) {
        match p {
            Piece::Same(s) => text(&s, &mut out),
            Piece::Deleted(s) => {
                out.push_str("<del>");
                text(&s, &mut out);
                out.push_str("</del>");
            }
            Piece::Inserted(s) => {
                out.push_str("<ins>");
                text(&s, &mut out);
                out.push_str("</ins>");
            }
            Piece::Elided => out.push('…'),
        }
    }
    Some(out)
}

/// What a history page says of each change beside its message: the type it is to (an IDL
/// file's change) and what it reaches ([`reach_text`]).
pub type Annotate<'a> = &'a dyn Fn(
    &crate::catalog::history::Change,
) -> (Option<crate::catalog::TypeIx>, Option<String>);

/// The rows of a version's changes: breaking first, then warnings, then the rest, each in the
/// diff's order (by path), as `rtcdoc diff` lists them; `annotate` names the type of each
/// change (an IDL file's) and its reach.
pub fn by_severity(
    changes: &[crate::catalog::history::Change],
    annotate: Annotate,
    lang: Lang,
) -> Vec<ChangeRow> {
    let rank = |c: &crate::catalog::history::Change| match c.severity.as_str() {
        "breaking" => 0,
        "warning" => 1,
        _ => 2,
    };
    let mut sorted: Vec<&crate::catalog::history::Change> = changes.iter().collect();
    sorted.sort_by_key(|c| rank(c));
    sorted
        .into_iter()
        .map(|c| ChangeRow::of(c, annotate(c), lang))
        .collect()
}

/// One row of the History section.
#[derive(Debug, Clone, Serialize)]
pub struct HistoryRow {
    /// The commit's first 12 digits, the backup's file name, or "working copy"; empty for a
    /// folded row.
    pub label: String,
    /// The file at that commit in its repository (a `source-url` with `{commit}`).
    pub url: Option<String>,
    pub date: String,
    pub author: String,
    pub subject: String,
    /// The version string, marked when it is a release (a new version string).
    pub version: String,
    /// What changed, in counts by severity ("1 breaking, 2 info"), or what the row is (the
    /// first version, versions folded, a version that could not be read).
    pub summary: String,
    /// The changes, spelled out, breaking first (at most [`ROW_CHANGES`]).
    pub changes: Vec<ChangeRow>,
    /// How many more changes the version has, on the history page ("and 3 more …"), when
    /// there are more than [`ROW_CHANGES`].
    pub more: Option<String>,
    /// The version's anchor on the history page (empty for a folded row).
    pub anchor: String,
}

/// The History section: its rows and how many versions are not shown.
#[derive(Debug, Clone, Default)]
pub struct HistoryView {
    pub rows: Vec<HistoryRow>,
    /// Versions older than the last row (catalog.json has them).
    pub older: usize,
}

impl HistoryView {
    /// The section of the history `h` (a component's, a system's); `url` makes the link of a
    /// commit's file (commit, path); `current_date` dates the current file's row, which git
    /// did not date (a component's profile's `updateDate`); `annotate` gives each change's
    /// type and reach.
    pub fn of(
        h: &[Entry],
        lang: Lang,
        url: &dyn Fn(&str, &str) -> Option<String>,
        (current_date, annotate): (Option<&str>, Annotate),
    ) -> Self {
        let mut rows = Vec::new();
        let mut i = 0;
        while i < h.len() && rows.len() < ROWS {
            if h[i].stands_out() {
                rows.push(row(
                    &h[i],
                    committed(h),
                    lang,
                    url,
                    (current_date, annotate),
                ));
                i += 1;
                continue;
            }
            let run = h[i..].iter().take_while(|e| !e.stands_out()).count();
            rows.push(folded(run, lang));
            i += run;
        }
        HistoryView {
            rows,
            older: h.len() - i,
        }
    }

    /// The sentence under the table when older versions are not shown.
    pub fn older_note(&self, lang: Lang) -> Option<String> {
        (self.older > 0).then(|| {
            lang.t("history_older")
                .replace("{n}", &self.older.to_string())
        })
    }
}

/// The row of `run` versions without a change to the specification, folded.
pub fn folded(run: usize, lang: Lang) -> HistoryRow {
    HistoryRow {
        label: String::new(),
        url: None,
        date: String::new(),
        author: String::new(),
        subject: String::new(),
        version: String::new(),
        summary: lang
            .t(if run == 1 {
                "history_folded_one"
            } else {
                "history_folded"
            })
            .replace("{n}", &run.to_string()),
        changes: Vec::new(),
        more: None,
        anchor: String::new(),
    }
}

/// Whether a history has commits (then its current file, when it is a version, is a working
/// copy not committed yet; without them it is the current file beside its backups).
pub fn committed(h: &[Entry]) -> bool {
    h.iter().any(|e| e.commit.is_some())
}

/// The row of version `e` of a history that has commits or not ([`committed`]); `url` makes
/// the link of a commit's file; `current_date` dates the current file, which git did not date.
pub fn row(
    e: &Entry,
    committed: bool,
    lang: Lang,
    url: &dyn Fn(&str, &str) -> Option<String>,
    (current_date, annotate): (Option<&str>, Annotate),
) -> HistoryRow {
    let label = if e.is_current() {
        lang.t(if committed {
            "history_working_copy"
        } else {
            "history_current_file"
        })
        .to_string()
    } else {
        e.label().to_string()
    };
    let mut version = e.version.clone().unwrap_or_default();
    if e.release && !e.first {
        version = format!("{version} ({})", lang.t("history_release"));
    }
    let summary = if let Some(why) = &e.error {
        format!("{}: {why}", lang.t("history_unreadable"))
    } else if e.first {
        lang.t("history_first").to_string()
    } else {
        let mut parts = Vec::new();
        if let Some(from) = &e.moved_from {
            parts.push(lang.t("history_moved").replace("{file}", from));
        }
        if e.changes.is_empty() {
            parts.push(lang.t("history_no_spec_change").to_string());
        }
        for (sev, key) in [
            ("breaking", "history_n_breaking"),
            ("warning", "history_n_warning"),
            ("info", "history_n_info"),
        ] {
            let n = e.count(sev);
            if n == 1 {
                parts.push(lang.t(&format!("{key}_one")).to_string());
            } else if n > 1 {
                parts.push(lang.t(key).replace("{n}", &n.to_string()));
            }
        }
        parts.join(lang.t("history_separator"))
    };
    HistoryRow {
        url: e.commit.as_deref().and_then(|commit| url(commit, &e.file)),
        label,
        date: shown_date(
            e.date
                .as_deref()
                .or(current_date.filter(|_| e.is_current()))
                .unwrap_or_default(),
        ),
        author: e.author.clone().unwrap_or_default(),
        subject: e.subject.clone().unwrap_or_default(),
        version,
        summary,
        changes: by_severity(&e.changes[..], annotate, lang)
            .into_iter()
            .take(ROW_CHANGES)
            .collect(),
        more: match e.changes.len().saturating_sub(ROW_CHANGES) {
            0 => None,
            1 => Some(lang.t("history_row_more_one").to_string()),
            n => Some(lang.t("history_row_more").replace("{n}", &n.to_string())),
        },
        anchor: super::history_page::entry_anchor(e),
    }
}

/// The reach of change `c` of the history of `of` in the catalogue of the build, as the
/// history pages say it: `Reaches 2 other components: Mapper (consumer), Avoider (consumer)`
/// (the components that use the port's type, the interface or the IDL definition the change
/// is to, today: [`crate::catalog::reach`]); `None` when it reaches none.
pub fn reach_text(
    cat: &crate::catalog::Catalog,
    of: crate::catalog::history::HistoryOf,
    c: &crate::catalog::history::Change,
    lang: Lang,
) -> Option<String> {
    use crate::catalog::history::HistoryOf;
    use crate::catalog::reach::{profile_lookup, subject_of};
    let (subjects, own) = match of {
        HistoryOf::Component(ci) => {
            let p = &cat[ci].profile;
            let lookup = |port: &str, i: Option<&str>| profile_lookup(p, port, i);
            let s = subject_of(&c.path, c.old.as_deref(), c.new.as_deref(), &lookup);
            (s, Some(&cat[ci].id))
        }
        HistoryOf::Idl(_) => (
            subject_of(&c.path, c.old.as_deref(), c.new.as_deref(), &|_, _| {
                Vec::new()
            }),
            None,
        ),
        HistoryOf::System(_) => return None,
    };
    let reach = cat.reach(&subjects, &|x| own.is_some_and(|id| x.id == *id));
    if reach.is_empty() {
        return None;
    }
    let each: Vec<String> = reach
        .iter()
        .map(|r| {
            let name = cat
                .component(&r.component)
                .map_or(r.component.clone(), |x| x.display_name().into_owned());
            let role = lang.t(&format!("history_reach_{}", r.role));
            format!("{name} ({role})")
        })
        .collect();
    let n: std::collections::BTreeSet<&str> = reach.iter().map(|r| r.component.as_str()).collect();
    let key = if n.len() == 1 {
        "history_reach_one"
    } else {
        "history_reach"
    };
    Some(
        lang.t(key)
            .replace("{n}", &n.len().to_string())
            .replace("{list}", &each.join(lang.t("history_separator"))),
    )
}

/// A date as the pages show it: as written, in the zone it was written in, except that UTC is
/// `+00:00` like every other offset. git writes a commit's author date with its own offset
/// (`2024-01-02T10:00:00+09:00`) but UTC as `Z` (`2024-01-02T01:00:00Z`), and one history mixed
/// the two forms. A date without a zone (a backup's local time) is left as it is; the JSON keeps
/// git's text.
pub fn shown_date(date: &str) -> String {
    let d = date.trim();
    match d.strip_suffix(['Z', 'z']) {
        Some(rest) if rest.len() >= 19 && rest.as_bytes().get(10) == Some(&b'T') => {
            format!("{rest}+00:00")
        }
        _ => d.to_string(),
    }
}
