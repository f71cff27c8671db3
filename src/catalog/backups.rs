//! RTCBuilder's backups: every save keeps the previous profile beside the new one as
//! `RTC.xml<yyyymmddhhmmss>` (local time of the save, e.g. `RTC.xml20150726072022`). A backup
//! is an older *version* of the `RTC.xml` in its folder, never a component of its own: it is
//! read once (its model kept here for the history of the component), listed on the component
//! page, and otherwise left out of the index, the search, the peers, the type pages, the counts,
//! `check` and `diff`. A backup whose `RTC.xml` is gone is reported (RTC013), not dropped.

use crate::model::Profile;
use serde::{Deserialize, Serialize};

/// One backup file of a component profile. In the JSON a backup is a document of its own:
/// its path as `source` and, when it could be read, its whole `profile` (nothing is lost).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
#[serde(rename_all = "camelCase", from = "BackupRead")]
pub struct Backup {
    /// Path relative to the input directory, forward slashes.
    pub source: String,
    /// When RTCBuilder saved it, from the file name: `2015-07-26 07:20:22` (local time of the
    /// save; the name has no time zone). `None` when the digits are not a date.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub saved: Option<String>,
    /// The profile it holds, or why it could not be read.
    #[serde(flatten)]
    pub content: BackupContent,
}

/// What a backup file gave: in the JSON, its whole `profile` or the `error` that kept it from
/// being read.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
#[serde(rename_all = "camelCase")]
pub enum BackupContent {
    /// The profile as the backup holds it (for the component's history, and in the JSON).
    Profile(Box<Profile>),
    /// Why the backup could not be read (a Shift_JIS file declaring UTF-8, a truncated save):
    /// shown beside it instead of an error about the component.
    Error(String),
}

/// A backup as catalog.json has it, read leniently: a profile wins over an error, and a
/// backup with neither (a hand-edited file) reads as unreadable instead of failing the whole
/// catalogue.
#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct BackupRead {
    source: String,
    saved: Option<String>,
    error: Option<String>,
    profile: Option<Box<Profile>>,
}

impl From<BackupRead> for Backup {
    fn from(b: BackupRead) -> Backup {
        Backup {
            source: b.source,
            saved: b.saved,
            content: match (b.profile, b.error) {
                (Some(p), _) => BackupContent::Profile(p),
                (None, Some(e)) => BackupContent::Error(e),
                (None, None) => BackupContent::Error("the backup could not be read".to_string()),
            },
        }
    }
}

impl Backup {
    /// A backup read as a profile.
    pub fn read(source: String, profile: Box<Profile>) -> Backup {
        Backup {
            saved: saved_at(&source),
            content: BackupContent::Profile(profile),
            source,
        }
    }

    /// A backup that could not be read as a profile, with the reason.
    pub fn unreadable(source: String, error: String) -> Backup {
        Backup {
            saved: saved_at(&source),
            content: BackupContent::Error(error),
            source,
        }
    }

    /// The component name and version the backup declares (its BasicInfo then).
    pub fn declares(&self) -> (Option<&str>, Option<&str>) {
        match &self.content {
            BackupContent::Profile(p) => (
                crate::model::non_empty(&p.basic_info.name),
                crate::model::non_empty(&p.basic_info.version),
            ),
            BackupContent::Error(_) => (None, None),
        }
    }

    /// The file name alone (`RTC.xml20150726072022`).
    pub fn file_name(&self) -> &str {
        self.source.rsplit('/').next().unwrap_or(&self.source)
    }

    /// The input-relative path of the profile this is a backup of: `RTC.xml` in its folder.
    pub fn profile_path(&self) -> String {
        match self.source.rsplit_once('/') {
            Some((dir, _)) => format!("{dir}/RTC.xml"),
            None => "RTC.xml".to_string(),
        }
    }
}

use crate::walk::backup_timestamp as timestamp;
pub use crate::walk::is_backup_name;

/// The save time a backup's name encodes (`yyyymmddhhmmss`, or just `yyyymmdd`), as
/// `YYYY-MM-DD hh:mm:ss`; `None` when the digits are no date and time of a calendar (month 13,
/// 31 February, hour 24): such a backup has no place among the versions of its profile, and the
/// history leaves it out (with a note).
pub fn saved_at(path: &str) -> Option<String> {
    let name = path.rsplit('/').next().unwrap_or(path);
    let d = timestamp(name)?;
    let num = |r: std::ops::Range<usize>| d.get(r).and_then(|s| s.parse::<u32>().ok());
    let (y, mo, day) = (num(0..4)?, num(4..6)?, num(6..8)?);
    if !(1990..=2999).contains(&y)
        || !(1..=12).contains(&mo)
        || !(1..=days_in(y, mo)).contains(&day)
    {
        return None;
    }
    match d.len() {
        8 => Some(format!("{y:04}-{mo:02}-{day:02}")),
        14 => {
            let (h, mi, s) = (num(8..10)?, num(10..12)?, num(12..14)?);
            (h < 24 && mi < 60 && s < 61)
                .then(|| format!("{y:04}-{mo:02}-{day:02} {h:02}:{mi:02}:{s:02}"))
        }
        _ => None,
    }
}

/// The days of month `m` (1–12) of year `y` (Gregorian).
fn days_in(y: u32, m: u32) -> u32 {
    match m {
        2 if y % 4 == 0 && (y % 100 != 0 || y % 400 == 0) => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        _ => 31,
    }
}

impl crate::catalog::Catalog {
    /// Takes in the backups read (after [`crate::catalog::Catalog::build`]): each joins the
    /// component whose profile is the `RTC.xml` beside it, oldest first. One whose `RTC.xml`
    /// does not exist (`exists` says, by input-relative path) is reported once per folder
    /// (RTC013); one whose `RTC.xml` exists but is no component (it failed to read, or was
    /// excluded) is kept in [`crate::catalog::Catalog::detached_backups`].
    pub fn attach_backups(&mut self, mut backups: Vec<Backup>, exists: &dyn Fn(&str) -> bool) {
        backups.sort_by(|a, b| a.source.cmp(&b.source));
        let by_source: std::collections::HashMap<&str, usize> = self
            .components
            .iter()
            .enumerate()
            .map(|(i, c)| (c.source.as_str(), i))
            .collect();
        let mut attach: Vec<(usize, Backup)> = Vec::new();
        let mut orphans: std::collections::BTreeMap<String, Vec<String>> = Default::default();
        let mut detached = Vec::new();
        for b in backups {
            let of = b.profile_path();
            match by_source.get(of.as_str()) {
                Some(&i) => attach.push((i, b)),
                None => {
                    if !exists(&of) {
                        orphans.entry(of).or_default().push(b.source.clone());
                    }
                    detached.push(b);
                }
            }
        }
        for (i, b) in attach {
            self.components[i].backups.push(b);
        }
        for c in &mut self.components {
            // Oldest first: by the date in the name (the names sort as the dates do).
            c.backups.sort_by(|a, b| a.file_name().cmp(b.file_name()));
        }
        for (of, files) in orphans {
            let newest = files.iter().max().cloned().unwrap_or_default();
            let names: Vec<&str> = files
                .iter()
                .map(|f| f.rsplit('/').next().unwrap_or(f))
                .collect();
            self.diagnostics.push(
                crate::diagnostic::Diagnostic::warning(
                    crate::diagnostic::codes::ORPHAN_BACKUP,
                    &newest,
                    format!(
                        "{} RTCBuilder backup(s) ({}) but no {of} beside them: the profile was deleted or renamed, and the backups are not documented",
                        files.len(),
                        names.join(", ")
                    ),
                )
                .with_hint(format!(
                    "to document the component, copy the newest backup `{}` to `RTC.xml` in the same folder; otherwise delete the backups",
                    newest.rsplit('/').next().unwrap_or(&newest)
                )),
            );
        }
        crate::diagnostic::sort(&mut self.diagnostics);
        self.detached_backups = detached;
    }

    /// `106 RTCBuilder backups (older versions of 41 profiles) are not documented as
    /// components`, when there are any.
    pub fn backup_note(&self) -> Option<String> {
        let mut profiles: std::collections::BTreeSet<String> = self
            .components
            .iter()
            .filter(|c| !c.backups.is_empty())
            .map(|c| c.source.clone())
            .collect();
        profiles.extend(self.detached_backups.iter().map(Backup::profile_path));
        let files = self
            .components
            .iter()
            .map(|c| c.backups.len())
            .sum::<usize>()
            + self.detached_backups.len();
        (files > 0).then(|| match (files, profiles.len()) {
            (1, _) => "1 RTCBuilder backup (an older version of 1 profile) is not documented as a component".to_string(),
            (f, 1) => format!("{f} RTCBuilder backups (older versions of 1 profile) are not documented as components"),
            (f, p) => format!("{f} RTCBuilder backups (older versions of {p} profiles) are not documented as components"),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_dates() {
        assert!(is_backup_name("RTC.xml20150726072022"));
        assert!(is_backup_name("RTC.xml20230831164412.xml"));
        assert!(!is_backup_name("RTC.xml"));
        assert!(!is_backup_name("RTC.xml.bak"));
        assert!(!is_backup_name("RTC.xml2015a"));
        assert_eq!(
            saved_at("a/b/RTC.xml20150726072022").as_deref(),
            Some("2015-07-26 07:20:22")
        );
        assert_eq!(saved_at("RTC.xml20150726").as_deref(), Some("2015-07-26"));
        assert_eq!(saved_at("RTC.xml20151399072022"), None);
        assert_eq!(saved_at("RTC.xml20201345999999"), None);
        assert_eq!(saved_at("RTC.xml20230231120000"), None);
        assert_eq!(saved_at("RTC.xml20150726240000"), None);
        assert_eq!(
            saved_at("RTC.xml20240229235959").as_deref(),
            Some("2024-02-29 23:59:59")
        );
        assert_eq!(saved_at("RTC.xml21000229"), None);
        assert_eq!(saved_at("RTC.xml201507260720"), None);
        let b = Backup::unreadable("x/RTC.xml20150726072022".into(), "bad".into());
        assert_eq!(b.profile_path(), "x/RTC.xml");
        assert_eq!(b.file_name(), "RTC.xml20150726072022");
    }

    /// A backup is, in the JSON, its source and save time with either its whole `profile` or
    /// the `error` that kept it from being read, and reads back as it was written.
    #[test]
    fn json_has_the_profile_or_the_error() {
        let mut profile = Profile::default();
        profile.basic_info.name = Some("Camera".into());
        let read = Backup::read("c/RTC.xml20150726072022".into(), Box::new(profile));
        let bad = Backup::unreadable("c/RTC.xml20160101000000".into(), "truncated".into());
        for (b, key, absent) in [(&read, "profile", "error"), (&bad, "error", "profile")] {
            let json = serde_json::to_string(b).expect("serialises");
            let start = format!(
                r#"{{"source":"{}","saved":"{}","{key}":"#,
                b.source,
                b.saved.as_deref().unwrap_or("")
            );
            assert!(json.starts_with(&start), "{json}");
            assert!(!json.contains(&format!(r#""{absent}":"#)), "{json}");
            let back: Backup = serde_json::from_str(&json).expect("reads back");
            assert_eq!(&back, b);
        }
        assert_eq!(read.declares(), (Some("Camera"), None));
        assert_eq!(bad.declares(), (None, None));
        // A hand-edited catalog.json: neither key reads as unreadable, both as the profile.
        let neither: Backup = serde_json::from_str(r#"{"source":"c/RTC.xml1","error":null}"#)
            .expect("reads as unreadable");
        assert!(matches!(neither.content, BackupContent::Error(_)));
        let both: Backup = serde_json::from_str(
            r#"{"source":"c/RTC.xml1","error":"x","profile":{"basicInfo":{"name":"Camera"}}}"#,
        )
        .expect("reads the profile");
        assert_eq!(both.declares(), (Some("Camera"), None));
    }
}
