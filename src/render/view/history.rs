//! The History section of a page: the latest versions of its file (a component profile's commits
//! and RTCBuilder backups, an RT System profile's commits, [`crate::catalog::history`]), newest
//! first, versions without a change to the specification folded into one row. Built once,
//! shown by every output.

use crate::catalog::history::Entry;
use crate::i18n::Lang;
use serde::Serialize;

/// Rows shown on a page; the whole history is in catalog.json.
pub const ROWS: usize = 10;

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
    /// The breaking changes, spelled out (`path`: message), and DIFF208 when the version was
    /// not raised with them.
    pub breaking: Vec<String>,
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
    /// did not date (a component's profile's `updateDate`).
    pub fn of(
        h: &[Entry],
        lang: Lang,
        url: &dyn Fn(&str, &str) -> Option<String>,
        current_date: Option<&str>,
    ) -> Self {
        let mut rows = Vec::new();
        let mut i = 0;
        while i < h.len() && rows.len() < ROWS {
            if h[i].stands_out() {
                rows.push(row(&h[i], committed(h), lang, url, current_date));
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
        breaking: Vec::new(),
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
    current_date: Option<&str>,
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
    } else if e.changes.is_empty() {
        lang.t("history_no_spec_change").to_string()
    } else {
        let mut parts = Vec::new();
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
        breaking: e
            .changes
            .iter()
            // DIFF208: breaking changes without a version bump, flagged beside them.
            .filter(|c| c.severity == "breaking" || c.code == "DIFF208")
            .map(|c| {
                if c.path.is_empty() {
                    c.message.clone()
                } else {
                    format!("{}: {}", c.path, c.message)
                }
            })
            .collect(),
    }
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
