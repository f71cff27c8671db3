//! A component's history as the catalogue keeps it: its past versions (the commits that changed
//! its file, RTCBuilder's backups), newest first, each with the changes from the version before
//! it as `rtcdoc diff` classifies them. Plain data here; `crate::history` reads git and the
//! backups and fills it in (this layer knows neither git nor the diff engine).

use crate::model::is_false;
use serde::{Deserialize, Serialize};

/// One version of a component profile and what changed to reach it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Entry {
    /// The commit that wrote this version (40 hex digits); `None` for a backup.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub commit: Option<String>,
    /// The RTCBuilder backup holding this version (catalogue path, `…/RTC.xml20150726072022`);
    /// `None` for a commit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub backup: Option<String>,
    /// The profile's path in its repository at that commit (it follows renames); the backup's
    /// path for a backup.
    pub file: String,
    /// The commit's author date (ISO 8601 with its offset), or the backup's save time from its
    /// name (`2015-07-26 07:20:22`, local time).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub date: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub author: Option<String>,
    /// The first line of the commit message.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub subject: Option<String>,
    /// The component's version string in this version (BasicInfo's, else the id's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub version: Option<String>,
    /// The version string differs from the one before: a release.
    #[serde(default, skip_serializing_if = "is_false")]
    pub release: bool,
    /// The oldest version read: there is nothing before it to compare it with.
    #[serde(default, skip_serializing_if = "is_false")]
    pub first: bool,
    /// The file's path at the version before, when this version has it at another path (a
    /// folder renamed or moved, followed by git or by the component id): "moved from".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moved_from: Option<String>,
    /// Why this version could not be read (it stays in the history, without changes; the next
    /// version is compared with the one before it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The changes from the previous readable version, each the object `rtcdoc diff --format
    /// json` writes; empty for a version that changed nothing of the specification
    /// (whitespace, formatting, attribute order), which the pages fold.
    #[serde(default)]
    pub changes: Vec<Change>,
}

impl Entry {
    /// Changes of `severity` (`breaking`, `warning`, `info`).
    pub fn count(&self, severity: &str) -> usize {
        self.changes
            .iter()
            .filter(|c| c.severity == severity)
            .count()
    }

    /// Shown on its own (not folded): the first version, a release, a version that could not
    /// be read, one whose file moved, or one that changed the specification.
    pub fn stands_out(&self) -> bool {
        self.first
            || self.release
            || self.error.is_some()
            || self.moved_from.is_some()
            || !self.changes.is_empty()
    }

    /// The file as it is, not a commit or backup: uncommitted edits, or the newest version of
    /// a profile kept outside git beside its backups.
    pub fn is_current(&self) -> bool {
        self.commit.is_none() && self.backup.is_none()
    }

    /// The commit's short form (12 digits), else the backup's file name, else the file's.
    pub fn label(&self) -> &str {
        match (&self.commit, &self.backup) {
            (Some(c), _) => c.get(..12).unwrap_or(c),
            (None, Some(b)) => b.rsplit('/').next().unwrap_or(b),
            (None, None) => &self.file,
        }
    }
}

/// One classified change: the object (field for field) `rtcdoc diff --format json` writes. The
/// diff engine fills it with its own severity and `'static` code names (`crate::diff::Change`);
/// the catalogue keeps it with plain strings (the default parameters), as `catalog.json`
/// reads it back.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Change<Severity = String, Code = String> {
    /// `breaking`, `warning` or `info`.
    pub severity: Severity,
    /// Stable code (`DIFF104`).
    pub code: Code,
    /// The code's short name (`data-port-type-changed`).
    pub name: Code,
    /// The component id (`RTC:vendor:category:name:version`, NEW's version when both sides
    /// have the component), with the language or file in parentheses when several profiles
    /// share the id.
    pub component: String,
    /// Slash-separated path to the changed item inside the component
    /// (`dataPorts/odometry/type`); empty for the component as a whole.
    pub path: String,
    pub old: Option<String>,
    pub new: Option<String>,
    pub message: String,
    /// The NEW side's file of the component (as the user can open it), when it has one.
    pub file: Option<String>,
    /// Line and column in `file` of the changed item, or of the nearest enclosing one.
    pub line: Option<u32>,
    pub column: Option<u32>,
    /// The OLD side's file of the component.
    pub old_file: Option<String>,
    /// Line and column in `old_file` of an item that exists only there (a removed port,
    /// interface, parameter or component).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old_line: Option<u32>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old_column: Option<u32>,
}

/// The `rtcdoc diff` codes of an element added to a component (`crate::diff::codes`: a port, a
/// provided or required interface, a configuration parameter), whose change path names it.
/// Spelled here because the catalogue comes before the diff engine; `tests/suite/history_pages.rs`
/// holds them equal.
pub const ADDED_CODES: [&str; 4] = ["DIFF301", "DIFF302", "DIFF211", "DIFF303"];

/// What names a version in a "since" note: its version string, else its date (the day).
pub fn version_or_date(e: &Entry) -> Option<String> {
    e.version
        .as_deref()
        .map(str::trim)
        .filter(|v| !v.is_empty())
        .map(str::to_string)
        .or_else(|| {
            e.date
                .as_deref()
                .map(|d| d.get(..10).unwrap_or(d).to_string())
        })
}

/// When each element of a history (newest first) was added: the change path of every element
/// an entry after the oldest one added, with the version (else the date) of the newest such
/// entry. An element added, removed and added again is dated by its last addition. A version
/// string an older entry already had is no answer ("since 1.0.0" when 1.0.0 first came
/// without it): such an entry is named by its date — for the current file, which git did not
/// date, by `current_date` (its profile's `updateDate`) — and an entry with neither gets no
/// note rather than a wrong one.
pub fn since(
    history: &[Entry],
    current_date: Option<&str>,
) -> std::collections::BTreeMap<String, String> {
    let mut out = std::collections::BTreeMap::new();
    let mut seen = std::collections::BTreeSet::new();
    for e in history.iter().rev() {
        let version = e
            .version
            .as_deref()
            .map(str::trim)
            .filter(|v| !v.is_empty());
        let new_version = version.is_some_and(|v| !seen.contains(v));
        if let Some(v) = version {
            seen.insert(v.to_string());
        }
        if e.first {
            continue;
        }
        let date = e
            .date
            .as_deref()
            .or(current_date.filter(|_| e.is_current()))
            .map(|d| d.trim())
            .map(|d| d.get(..10).unwrap_or(d).to_string());
        let label = match (new_version, date) {
            (false, Some(day)) => Some(day),
            (false, None) if version.is_some() => None,
            _ => version_or_date(e),
        };
        for c in e
            .changes
            .iter()
            .filter(|c| ADDED_CODES.contains(&c.code.as_str()))
        {
            // Without a right name for the addition: no note, and not an older addition's.
            match &label {
                Some(l) => out.insert(c.path.clone(), l.clone()),
                None => out.remove(&c.path),
            };
        }
    }
    out
}

impl super::Catalog {
    /// Fills in what the components' histories give once they are read: each component's
    /// [`since`] (only for its elements that still exist; the interfaces of a service port added
    /// whole take the port's) and the history pages.
    pub fn history_attached(&mut self) {
        use rayon::prelude::*;
        self.components.par_iter_mut().for_each(|c| {
            let updated = crate::model::non_empty(&c.profile.basic_info.update_date);
            let mut since = since(&c.history, updated);
            if since.is_empty() {
                // Nothing added in the history: nothing to keep (the usual case without one).
                c.since = since;
                return;
            }
            let keys = ElementKeys::of(&c.profile);
            // The interfaces of a service port added whole came with it (the diff names the
            // port only).
            for (port, interfaces) in keys.service_ports.iter().zip(&keys.interfaces) {
                if let Some(v) = since.get(port).cloned() {
                    for i in interfaces {
                        since.entry(i.clone()).or_insert_with(|| v.clone());
                    }
                }
            }
            since.retain(|k, _| keys.all().any(|x| x == k));
            c.since = since;
        });
        self.index_history_pages();
    }
}

/// What a history is of: a component profile, an RT System profile, or an IDL file (its
/// position in [`crate::idl::IdlSet::files`]). Each with a history has its history page, and
/// its versions are on What's new and in the feed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum HistoryOf {
    Component(super::ComponentIx),
    System(super::SystemIx),
    Idl(usize),
}

/// Where the history page of each component (system, IDL file) is in the page list, if it has
/// one.
pub(super) type Slots = Vec<Option<usize>>;

impl super::Catalog {
    /// The history of `of`, newest first (empty without one).
    pub fn history_of(&self, of: HistoryOf) -> &[Entry] {
        match of {
            HistoryOf::Component(ci) => &self[ci].history,
            HistoryOf::System(si) => self
                .systems
                .get(si.get())
                .map_or(&[][..], |s| s.history.as_slice()),
            HistoryOf::Idl(fi) => self
                .idl
                .files
                .get(fi)
                .and_then(|f| self.idl_history.get(&f.path))
                .map_or(&[][..], Vec::as_slice),
        }
    }

    /// Everything with a history, in page order: the components, the systems, the IDL files.
    pub fn histories(&self) -> impl Iterator<Item = HistoryOf> + '_ {
        let components = super::Ix::all(self.components.len()).map(HistoryOf::Component);
        let systems = super::Ix::all(self.systems.len()).map(HistoryOf::System);
        let idl = (0..self.idl.files.len()).map(HistoryOf::Idl);
        components
            .chain(systems)
            .chain(idl)
            .filter(|&of| !self.history_of(of).is_empty())
    }

    /// The history page of component `ci`, when it has a history.
    pub fn history_page(&self, ci: super::ComponentIx) -> Option<&super::Page> {
        self.history_page_of(HistoryOf::Component(ci))
    }

    /// The history page of `of`, when it has a history.
    pub fn history_page_of(&self, of: HistoryOf) -> Option<&super::Page> {
        let starts = &self.page_starts;
        let at = match of {
            HistoryOf::Component(ci) => starts.history.get(ci.get()),
            HistoryOf::System(si) => starts.system_history.get(si.get()),
            HistoryOf::Idl(fi) => starts.idl_history.get(fi),
        };
        self.pages.get((*at?)?)
    }

    /// The position in [`crate::idl::IdlSet::files`] of `file`, a reference into it (as a
    /// lookup of the set gives it): found from its address, without a scan of the files.
    pub fn idl_file_index(&self, file: &crate::idl::IdlFile) -> Option<usize> {
        let files = &self.idl.files;
        let size = std::mem::size_of::<crate::idl::IdlFile>().max(1);
        let at = (file as *const crate::idl::IdlFile as usize)
            .checked_sub(files.as_ptr() as usize)?
            / size;
        files
            .get(at)
            .is_some_and(|f| std::ptr::eq(f, file))
            .then_some(at)
    }

    /// The page of what `of` is the history of: the component's or the system's page; `None`
    /// for an IDL file, which has no page of its own.
    pub fn page_of_history(&self, of: HistoryOf) -> Option<&super::Page> {
        match of {
            HistoryOf::Component(ci) => Some(self.component_page(ci)),
            HistoryOf::System(si) => Some(self.system_page(si)),
            HistoryOf::Idl(_) => None,
        }
    }

    /// The name of what `of` is the history of: the component's or the system's display
    /// name, the IDL file's path.
    pub fn history_name(&self, of: HistoryOf) -> String {
        match of {
            HistoryOf::Component(ci) => self[ci].display_name().into_owned(),
            HistoryOf::System(si) => self
                .systems
                .get(si.get())
                .map(|s| s.display_name().into_owned())
                .unwrap_or_default(),
            HistoryOf::Idl(fi) => self
                .idl
                .files
                .get(fi)
                .map(|f| f.path.clone())
                .unwrap_or_default(),
        }
    }

    /// Appends the history pages to `pages` (What's new, then a page per component, system and
    /// IDL file with a history: `history/<slug>`, `system-history/<slug>`,
    /// `idl-history/<slug of the path>`); where each one is, per component, system and file.
    pub(super) fn history_pages(&self, pages: &mut Vec<super::Page>) -> (Slots, Slots, Slots) {
        use super::{Page, PageKind};
        let mut at = (
            vec![None; self.components.len()],
            vec![None; self.systems.len()],
            vec![None; self.idl.files.len()],
        );
        if self.histories().next().is_none() {
            return at;
        }
        pages.push(Page {
            kind: PageKind::WhatsNew,
            id: String::new(),
            stem: "whats-new".into(),
            title: String::new(),
        });
        // The IDL files' slugs, from their paths: unique among them (`-2`, `-3`, … when two
        // paths slug alike).
        let mut taken = std::collections::HashSet::new();
        for of in self.histories() {
            let (kind, id, stem, slot) = match of {
                HistoryOf::Component(ci) => {
                    let c = &self[ci];
                    let stem = format!("history/{}", c.slug);
                    (
                        PageKind::ComponentHistory,
                        c.id.to_string(),
                        stem,
                        &mut at.0[ci.get()],
                    )
                }
                HistoryOf::System(si) => {
                    let s = &self.systems[si.get()];
                    let stem = format!("system-history/{}", s.slug);
                    (
                        PageKind::SystemHistory,
                        s.source.clone(),
                        stem,
                        &mut at.1[si.get()],
                    )
                }
                HistoryOf::Idl(fi) => {
                    let path = &self.idl.files[fi].path;
                    let base = super::slugify(path);
                    let mut slug = base.clone();
                    let mut k = 1;
                    while !taken.insert(slug.clone()) {
                        k += 1;
                        slug = format!("{base}-{k}");
                    }
                    let stem = format!("idl-history/{slug}");
                    (PageKind::IdlHistory, path.clone(), stem, &mut at.2[fi])
                }
            };
            *slot = Some(pages.len());
            pages.push(Page {
                kind,
                id,
                stem,
                title: self.history_name(of),
            });
        }
        at
    }
}

/// The labels `rtcdoc diff` keys the items of a list by (ports, interfaces, parameters): the
/// trimmed name (`(unnamed)` when blank), and `name#2`, `name#3`, … for a repeated one.
pub fn item_labels<'a>(names: impl Iterator<Item = Option<&'a str>>) -> Vec<String> {
    let bases = names.map(|n| {
        n.map(str::trim)
            .filter(|s| !s.is_empty())
            .unwrap_or("(unnamed)")
            .to_string()
    });
    super::numbered(bases, |base, k| format!("{base}#{k}"))
}

/// The change path of each element a "since" note can be on, in profile order: what
/// [`since`] keys by (`dataPorts/status`, `servicePorts/svc/interfaces/map`,
/// `configurations/gain`).
#[derive(Debug, Clone, Default)]
pub struct ElementKeys {
    pub data_ports: Vec<String>,
    pub service_ports: Vec<String>,
    /// One per service interface, per service port.
    pub interfaces: Vec<Vec<String>>,
    pub configurations: Vec<String>,
}

impl ElementKeys {
    pub fn of(p: &crate::model::Profile) -> ElementKeys {
        let keys = super::per_element(
            p,
            ["dataPorts", "servicePorts", "configurations"],
            |port| format!("{port}/interfaces"),
            |list, names| {
                let labels = item_labels(names);
                labels.into_iter().map(|l| format!("{list}/{l}")).collect()
            },
        );
        ElementKeys {
            data_ports: keys.data_ports,
            service_ports: keys.service_ports,
            interfaces: keys.interfaces,
            configurations: keys.configurations,
        }
    }

    /// Every key: data ports, service ports, their interfaces, configuration parameters.
    pub fn all(&self) -> impl Iterator<Item = &String> {
        self.data_ports
            .iter()
            .chain(&self.service_ports)
            .chain(self.interfaces.iter().flatten())
            .chain(&self.configurations)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The DIFF301 changes of ports added at `paths`.
    fn ports_added(paths: &[&str]) -> Vec<Change> {
        paths
            .iter()
            .map(|p| Change {
                code: "DIFF301".into(),
                path: (*p).into(),
                ..Default::default()
            })
            .collect()
    }

    /// A version string the first version already had names no addition: its date does.
    #[test]
    fn since_names_a_version_only_where_it_is_new() {
        let entry = |version: &str, date: &str, added: &[&str], first: bool| Entry {
            version: Some(version.into()),
            date: Some(format!("{date}T10:00:00+09:00")),
            first,
            changes: ports_added(added),
            ..Default::default()
        };
        // Newest first.
        let history = [
            entry("1.1.0", "2024-05-02", &["dataPorts/c"], false),
            entry("1.1.0", "2024-04-01", &["dataPorts/b"], false),
            entry("1.0.0", "2024-03-05", &["dataPorts/a"], false),
            entry("1.0.0", "2024-01-10", &[], true),
        ];
        let got = since(&history, None);
        let want: Vec<(&str, &str)> = vec![
            ("dataPorts/a", "2024-03-05"),
            ("dataPorts/b", "1.1.0"),
            ("dataPorts/c", "2024-05-02"),
        ];
        assert_eq!(
            got.iter()
                .map(|(k, v)| (k.as_str(), v.as_str()))
                .collect::<Vec<_>>(),
            want
        );
    }

    /// The current file beside RTCBuilder backups of the same version (no git): what it added
    /// is named by its `updateDate`, or has no note, never by the version the backups had.
    #[test]
    fn the_current_file_of_an_old_version_is_named_by_its_update_date() {
        // (version, backup and its save time, what it added), newest first.
        let entry = |version: &str, backup: Option<(&str, &str)>, added: &[&str]| Entry {
            version: Some(version.into()),
            backup: backup.map(|(b, _)| b.into()),
            date: backup.map(|(_, d)| d.into()),
            first: added.is_empty(),
            changes: ports_added(added),
            ..Default::default()
        };
        let history = [
            entry("1.0.0", None, &["dataPorts/b"]),
            entry(
                "1.0.0",
                Some(("c/RTC.xml20170409100337", "2017-04-09 10:03:37")),
                &["dataPorts/a"],
            ),
            entry(
                "0.9.0",
                Some(("c/RTC.xml20170101000000", "2017-01-01 00:00:00")),
                &[],
            ),
        ];
        assert!(history[0].is_current());
        let got = since(&history, Some("2017-11-14T10:00:00"));
        assert_eq!(
            got.get("dataPorts/b").map(String::as_str),
            Some("2017-11-14")
        );
        assert_eq!(got.get("dataPorts/a").map(String::as_str), Some("1.0.0"));
        let got = since(&history, None);
        assert_eq!(got.get("dataPorts/b"), None);
        assert_eq!(got.get("dataPorts/a").map(String::as_str), Some("1.0.0"));
        // Added in 1.0.5, removed, and added again by the undated current file of a version
        // already seen: no note, not 1.0.5's.
        let backup = |name: &'static str, date: &'static str| Some((name, date));
        let mut again = vec![
            entry("1.1.0", None, &["dataPorts/a"]),
            entry("1.1.0", backup("c/RTC.xml3", "2017-03-01 00:00:00"), &[]),
            entry(
                "1.0.5",
                backup("c/RTC.xml2", "2017-02-01 00:00:00"),
                &["dataPorts/a"],
            ),
            entry("1.0.0", backup("c/RTC.xml1", "2017-01-01 00:00:00"), &[]),
        ];
        again[1].first = false;
        assert_eq!(since(&again, None).get("dataPorts/a"), None);
    }
}
