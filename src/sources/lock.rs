//! `rtcdoc.lock`: the commit every `[[source]]` is pinned at, beside `rtcdoc.toml`.
//!
//! A small TOML file, written by rtcdoc in a stable form (sources sorted by name, one key per
//! line, always the same order) so that it diffs well and can be committed:
//!
//! ```toml
//! # rtcdoc.lock: …
//! version = 1
//!
//! [[source]]
//! name = "camera"
//! git = "https://github.com/org/camera.git"
//! rev = "v1.2.0"
//! commit = "0123456789abcdef0123456789abcdef01234567"
//! ```

use anyhow::{bail, Context, Result};
use serde::Deserialize;
use std::path::Path;

/// The lock file's name.
pub const FILE_NAME: &str = "rtcdoc.lock";

/// The format written.
const VERSION: u32 = 1;

/// One source as locked.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub name: String,
    pub git: String,
    #[serde(default)]
    pub rev: Option<String>,
    pub commit: String,
}

/// The whole file.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lock {
    #[serde(default)]
    pub version: Option<u32>,
    #[serde(default, rename = "source")]
    pub sources: Vec<Entry>,
}

impl Lock {
    pub fn find(&self, name: &str) -> Option<&Entry> {
        self.sources.iter().find(|e| e.name == name)
    }

    /// Sorted by name, with the version written.
    pub fn sort(&mut self) {
        self.version = Some(VERSION);
        self.sources.sort_by(|a, b| a.name.cmp(&b.name));
    }
}

/// What a new lock changes against the old one.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Changes {
    /// `(name, old commit or None, new commit)` of every source added or moved.
    pub moved: Vec<(String, Option<String>, String)>,
    /// Sources the lock had and the configuration has no more.
    pub removed: Vec<String>,
}

impl Changes {
    pub fn is_empty(&self) -> bool {
        self.moved.is_empty() && self.removed.is_empty()
    }

    /// One line: `camera 0123456 -> 89abcde, arm added, old removed`.
    pub fn describe(&self) -> String {
        let mut parts: Vec<String> = self
            .moved
            .iter()
            .map(|(n, old, new)| match old {
                // Only its `git` or `rev` changed: it pins the same commit.
                Some(o) if o == new => {
                    format!("{n} still at {} (its git or rev changed)", short(new))
                }
                Some(o) => format!("{n} {} -> {}", short(o), short(new)),
                None => format!("{n} added at {}", short(new)),
            })
            .collect();
        parts.extend(self.removed.iter().map(|n| format!("{n} removed")));
        if parts.is_empty() {
            "no source moved".into()
        } else {
            parts.join(", ")
        }
    }
}

fn short(commit: &str) -> &str {
    commit.get(..12).unwrap_or(commit)
}

/// What `new` changes against `old`.
pub fn changes(old: Option<&Lock>, new: &Lock) -> Changes {
    let mut c = Changes::default();
    for e in &new.sources {
        let before = old.and_then(|o| o.find(&e.name));
        if before.map(|b| b.commit.as_str()) != Some(e.commit.as_str())
            || before.is_some_and(|b| b.git != e.git || b.rev != e.rev)
        {
            c.moved.push((
                e.name.clone(),
                before.map(|b| b.commit.clone()),
                e.commit.clone(),
            ));
        }
    }
    if let Some(old) = old {
        for e in &old.sources {
            if new.find(&e.name).is_none() {
                c.removed.push(e.name.clone());
            }
        }
    }
    c
}

/// Reads the lock at `path`; `None` when there is none. `update`: the `rtcdoc update` command
/// that writes it again (with the options it needs), for the errors.
pub fn read(path: &Path, update: &str) -> Result<Option<Lock>> {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e).with_context(|| format!("cannot read `{}`", path.display())),
    };
    let lock: Lock = toml::from_str(&text).map_err(|e| {
        let pos = e.span().map_or(crate::model::Pos::new(1, 1), |s| {
            crate::model::Pos::at_offset(&text, s.start)
        });
        anyhow::anyhow!(
            "{}:{pos}: {}; the lock is written by rtcdoc: delete it and run `{update}` to write it again",
            path.display(),
            e.message().trim_end()
        )
    })?;
    if let Some(v) = lock.version.filter(|v| *v != VERSION) {
        bail!(
            "{}: lock format {v}; this rtcdoc writes format {VERSION}: delete it and run `{update}`",
            path.display()
        );
    }
    for e in &lock.sources {
        if e.commit.len() != 40 || !e.commit.bytes().all(|b| b.is_ascii_hexdigit()) {
            bail!(
                "{}: the source `{}` has the commit `{}`, not 40 hex digits; delete the lock and run `{update}`",
                path.display(),
                e.name,
                e.commit
            );
        }
    }
    Ok(Some(lock))
}

/// `s` as a TOML basic string (`C:\\…` keeps its backslashes).
pub(crate) fn quoted(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The text of a lock (sorted by name).
pub fn to_text(lock: &Lock) -> String {
    let mut sorted = lock.clone();
    sorted.sort();
    let mut out = String::from(
        "# rtcdoc.lock: the commit every [[source]] of rtcdoc.toml is documented at.\n\
         # Written by rtcdoc; commit it. `rtcdoc update [NAME…]` moves sources to their current rev.\n",
    );
    out.push_str(&format!("version = {VERSION}\n"));
    for e in &sorted.sources {
        out.push_str("\n[[source]]\n");
        out.push_str(&format!("name = {}\n", quoted(&e.name)));
        out.push_str(&format!("git = {}\n", quoted(&e.git)));
        if let Some(rev) = &e.rev {
            out.push_str(&format!("rev = {}\n", quoted(rev)));
        }
        out.push_str(&format!("commit = {}\n", quoted(&e.commit)));
    }
    out
}

/// Writes the lock (through a temporary file and a rename: never half written).
pub fn write(path: &Path, lock: &Lock) -> Result<()> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let mut tmp = tempfile::NamedTempFile::new_in(dir)
        .with_context(|| format!("cannot write `{}`", path.display()))?;
    std::io::Write::write_all(&mut tmp, to_text(lock).as_bytes())?;
    tmp.persist(path)
        .with_context(|| format!("cannot write `{}`", path.display()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_sorted() {
        let lock = Lock {
            version: Some(1),
            sources: vec![
                Entry {
                    name: "b".into(),
                    git: "file:///b \"q\"".into(),
                    rev: Some("v1".into()),
                    commit: "1".repeat(40),
                },
                Entry {
                    name: "a".into(),
                    git: "../a".into(),
                    rev: None,
                    commit: "a".repeat(40),
                },
            ],
        };
        let text = to_text(&lock);
        assert!(text.find("name = \"a\"").unwrap() < text.find("name = \"b\"").unwrap());
        let back: Lock = toml::from_str(&text).unwrap();
        let mut sorted = lock.clone();
        sorted.sort();
        assert_eq!(back, sorted);
        assert_eq!(to_text(&back), text);
    }

    #[test]
    fn changes_say_what_moved() {
        // Sources as (name, rev, the digit its commit repeats).
        let lock = |sources: &[(&str, &str, char)]| Lock {
            version: Some(1),
            sources: sources
                .iter()
                .map(|&(name, rev, digit)| Entry {
                    name: name.into(),
                    git: "../r".into(),
                    rev: Some(rev.into()),
                    commit: digit.to_string().repeat(40),
                })
                .collect(),
        };
        let old = lock(&[
            ("a", "main", '1'),
            ("b", "main", '2'),
            ("gone", "main", '3'),
        ]);
        let new = lock(&[("a", "main", '4'), ("b", "v1", '2'), ("c", "main", '5')]);
        assert_eq!(
            changes(Some(&old), &new).describe(),
            "a 111111111111 -> 444444444444, b still at 222222222222 (its git or rev changed), c added at 555555555555, gone removed"
        );
        assert_eq!(changes(Some(&new), &new).describe(), "no source moved");
    }
}
