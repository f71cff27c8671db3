//! A component's history as the catalogue keeps it: its past versions (the commits that changed
//! its file, RTCBuilder's backups), newest first, each with the changes from the version before
//! it as `rtcdoc diff` classifies them. Plain data here; `crate::history` reads git and the
//! backups and fills it in (this layer knows neither git nor the diff engine).

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

fn is_false(b: &bool) -> bool {
    !*b
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
    /// be read, or one that changed the specification.
    pub fn stands_out(&self) -> bool {
        self.first || self.release || self.error.is_some() || !self.changes.is_empty()
    }

    /// The commit's short form (12 digits), else the backup's file name.
    pub fn label(&self) -> &str {
        match (&self.commit, &self.backup) {
            (Some(c), _) => c.get(..12).unwrap_or(c),
            (None, Some(b)) => b.rsplit('/').next().unwrap_or(b),
            (None, None) => &self.file,
        }
    }
}

/// One classified change, the same object (field for field) as a change of `rtcdoc diff
/// --format json`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Change {
    /// `breaking`, `warning` or `info`.
    pub severity: String,
    pub code: String,
    pub name: String,
    pub component: String,
    pub path: String,
    pub old: Option<String>,
    pub new: Option<String>,
    pub message: String,
    pub file: Option<String>,
    pub line: Option<u32>,
    pub column: Option<u32>,
    pub old_file: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old_line: Option<u32>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old_column: Option<u32>,
}
