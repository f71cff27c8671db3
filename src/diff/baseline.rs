//! A baseline of accepted changes: the file `rtcdoc diff --write-baseline FILE` writes and
//! `--baseline FILE` reads. Each `[[accept]]` entry names one change — its code, its component
//! and the element changed (the change's path, never a line), with its values — and a reason a
//! reviewer wrote. A change an entry names is accepted: listed, but it does not count towards
//! `--fail-on`; a change no entry names counts as always; an entry whose change is gone is
//! stale, reported with its place in the file.
//!
//! An entry matches a change when the code, the element, the old and new values and the
//! component are the same, the component compared by its vendor, category and name (the
//! version left out, as components are matched: a version bump does not stale the file), and,
//! for a change of no component (an unreadable file), the file too. The message and the file
//! are for people and are not compared.
//!
//! An entry whose reason is empty or still the placeholder `--write-baseline` writes is
//! refused (the file is an error, exit status 2): a baseline is reviewed, and the reason is
//! what the review leaves.

use super::policy::{Standing, Status};
use super::{codes, Change, Diff, Level};
use anyhow::{bail, Context, Result};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;
use toml::Spanned;

/// The reason `--write-baseline` writes into a new entry.
pub const PLACEHOLDER: &str = "TODO: why this change is accepted";

/// Version of the file's shape.
pub const VERSION: u32 = 1;

/// One `[[accept]]` entry.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub code: String,
    pub component: String,
    /// The change's path inside the component (`dataPorts/odometry/type`); empty for the
    /// component as a whole.
    pub element: String,
    #[serde(default)]
    pub old: Option<String>,
    #[serde(default)]
    pub new: Option<String>,
    /// NEW's file of the change (else OLD's), as the report names it.
    #[serde(default)]
    pub file: Option<String>,
    /// The change's message, for people.
    #[serde(default)]
    pub message: Option<String>,
    pub reason: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Doc {
    version: Option<Spanned<u32>>,
    #[serde(default)]
    accept: Vec<Spanned<Entry>>,
}

/// A baseline file read.
#[derive(Debug, Clone, Default)]
pub struct Baseline {
    /// The file, as the user named it.
    pub file: String,
    /// The entries, each with its line and column in the file.
    pub entries: Vec<(Entry, crate::model::Pos)>,
}

/// An entry no change matches any more.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Stale {
    pub entry: Entry,
    /// `FILE:line:column` of the entry.
    pub at: String,
    pub line: u32,
    pub column: u32,
}

fn is_placeholder(reason: &str) -> bool {
    let r = reason.trim();
    r.is_empty() || r == PLACEHOLDER || r.to_ascii_uppercase().starts_with("TODO:")
}

/// Reads the baseline at `path` (`shown` as the user named it). `reviewed`: an entry without
/// a reason (empty, or the placeholder) is an error, as `--baseline` wants; otherwise such
/// entries are kept (`--write-baseline` keeps the reasons of an existing file).
pub fn read(path: &Path, shown: &str, reviewed: bool) -> Result<Baseline> {
    let text = std::fs::read_to_string(path).with_context(|| {
        format!("baseline `{shown}`: cannot read it (write one with --write-baseline FILE)")
    })?;
    parse(&text, shown, reviewed)
}

/// [`read`] on the text of a file.
pub fn parse(text: &str, shown: &str, reviewed: bool) -> Result<Baseline> {
    let at = |offset: usize| crate::model::Pos::at_offset(text, offset);
    let doc: Doc = toml::from_str(text).map_err(|e| {
        let pos = e.span().map_or(crate::model::Pos::new(1, 1), |s| at(s.start));
        anyhow::anyhow!(
            "{shown}:{pos}: {}{} (a baseline has `version = {VERSION}` and [[accept]] entries with code, component, element, old, new, file, message and reason)",
            e.message().trim_end(),
            crate::diagnostic::unknown_field_hint(e.message().trim_end())
        )
    })?;
    if let Some(v) = &doc.version {
        if *v.get_ref() != VERSION {
            bail!(
                "{shown}:{}: baseline version {} is not {VERSION}, the one this rtcdoc reads; write it again with --write-baseline",
                at(v.span().start),
                v.get_ref()
            );
        }
    }
    let mut entries = Vec::with_capacity(doc.accept.len());
    for spanned in doc.accept {
        let pos = at(spanned.span().start);
        let mut e = spanned.into_inner();
        let Some(c) = codes::code(&e.code) else {
            let near = crate::suggest::typo(&e.code, codes::CODES.iter().map(|c| c.code))
                .map(|n| format!("did you mean `{n}`?"))
                .unwrap_or_else(|| "`rtcdoc diff --explain CODE` lists them".into());
            bail!("{shown}:{pos}: no change has the code `{}`; {near}", e.code);
        };
        e.code = c.code.to_string();
        if reviewed && is_placeholder(&e.reason) {
            bail!(
                "{shown}:{pos}: the entry accepting {} on `{}` {} has no reason; write in `reason` why the change is accepted (an entry without one is refused: a baseline is reviewed)",
                e.code,
                e.component,
                if e.element.is_empty() { "(the component)".to_string() } else { format!("at `{}`", e.element) }
            );
        }
        entries.push((e, pos));
    }
    Ok(Baseline {
        file: shown.to_string(),
        entries,
    })
}

/// The part of a component id the baseline compares: the id without its version
/// (`RTC:vendor:category:name`, `RTSystem:vendor:name`), with what follows it (` (Python)`).
fn component_key(component: &str) -> String {
    let (id, rest) = match component.find(" (") {
        Some(i) => component.split_at(i),
        None => (component, ""),
    };
    let parts: Vec<&str> = id.split(':').collect();
    let versioned = match parts.first() {
        Some(&"RTC") => parts.len() == 5,
        Some(&"RTSystem") => parts.len() == 4,
        _ => false,
    };
    if versioned {
        format!("{}{rest}", parts[..parts.len() - 1].join(":"))
    } else {
        component.to_string()
    }
}

type Key = (
    String,
    String,
    String,
    Option<String>,
    Option<String>,
    String,
);

fn key(
    code: &str,
    component: &str,
    element: &str,
    (old, new): (&Option<String>, &Option<String>),
    file: Option<&str>,
) -> Key {
    (
        code.to_string(),
        component_key(component),
        element.to_string(),
        old.clone(),
        new.clone(),
        // The file tells apart the changes of no component (DIFF002 of two files).
        if component.is_empty() {
            file.unwrap_or("").to_string()
        } else {
            String::new()
        },
    )
}

fn change_file(c: &Change) -> Option<&str> {
    c.file.as_deref().or(c.old_file.as_deref())
}

fn key_of_change(c: &Change) -> Key {
    key(
        c.code,
        &c.component,
        &c.path,
        (&c.old, &c.new),
        change_file(c),
    )
}

fn key_of_entry(e: &Entry) -> Key {
    key(
        &e.code,
        &e.component,
        &e.element,
        (&e.old, &e.new),
        e.file.as_deref(),
    )
}

/// Marks the changes the baseline accepts (those the policy ignores stay ignored) and records
/// its stale entries in `diff.stale`.
pub fn apply(diff: &mut Diff, baseline: &Baseline) {
    let mut by_key: BTreeMap<Key, (usize, bool)> = BTreeMap::new();
    for (i, (e, _)) in baseline.entries.iter().enumerate() {
        by_key.entry(key_of_entry(e)).or_insert((i, false));
    }
    diff.gate.resize(diff.changes.len(), Standing::default());
    for (change, standing) in diff.changes.iter().zip(diff.gate.iter_mut()) {
        if let Some((i, used)) = by_key.get_mut(&key_of_change(change)) {
            *used = true;
            if standing.status == Status::Counts {
                standing.status = Status::Accepted(baseline.entries[*i].0.reason.clone());
            }
        }
    }
    let mut stale: Vec<Stale> = baseline
        .entries
        .iter()
        .filter(|(e, _)| by_key.get(&key_of_entry(e)).is_some_and(|(_, used)| !used))
        .map(|(e, pos)| Stale {
            entry: e.clone(),
            at: format!("{}:{pos}", baseline.file),
            line: pos.line,
            column: pos.column,
        })
        .collect();
    stale.dedup();
    diff.stale = stale;
    diff.baseline = Some(baseline.file.clone());
}

/// The text of a baseline accepting every change of `diff` that counts (or is accepted) and
/// reaches `level`, sorted; the reason of an entry of `keep` that names the same change is
/// kept (the first baseline of `keep` that gives one wins), the others get [`PLACEHOLDER`].
/// Also the number of entries and of reasons kept.
pub fn write(diff: &Diff, level: Level, keep: &[Baseline]) -> (String, usize, usize) {
    let mut reasons: BTreeMap<Key, &str> = BTreeMap::new();
    for (e, _) in keep.iter().flat_map(|b| &b.entries) {
        if !is_placeholder(&e.reason) {
            reasons.entry(key_of_entry(e)).or_insert(e.reason.as_str());
        }
    }
    let mut chosen: BTreeMap<(String, String, String, Key), (&Change, &str)> = BTreeMap::new();
    for (i, c) in diff.changes.iter().enumerate() {
        if c.severity > level || diff.status(i) == &Status::Ignored {
            continue;
        }
        let k = key_of_change(c);
        let reason = reasons.get(&k).copied().unwrap_or(PLACEHOLDER);
        chosen
            .entry((c.component.clone(), c.path.clone(), c.code.to_string(), k))
            .or_insert((c, reason));
    }
    let q = crate::sources::lock::quoted;
    let mut out = format!(
        "# Changes `rtcdoc diff --baseline` accepts: each [[accept]] entry names one change (its code,\n\
         # component, element and values) and says why it is accepted. Written by `rtcdoc diff\n\
         # --write-baseline`; review it and commit it. An entry whose reason is empty or still starts\n\
         # with \"TODO:\" is refused; an entry whose change is gone is reported as stale.\n\
         version = {VERSION}\n"
    );
    let mut kept = 0;
    for (c, reason) in chosen.values() {
        if *reason != PLACEHOLDER {
            kept += 1;
        }
        out.push_str("\n[[accept]]\n");
        out.push_str(&format!("code = {}\n", q(c.code)));
        out.push_str(&format!("component = {}\n", q(&c.component)));
        out.push_str(&format!("element = {}\n", q(&c.path)));
        for (k, v) in [("old", &c.old), ("new", &c.new)] {
            if let Some(v) = v {
                out.push_str(&format!("{k} = {}\n", q(v)));
            }
        }
        if let Some(f) = change_file(c) {
            out.push_str(&format!("file = {}\n", q(f)));
        }
        out.push_str(&format!("message = {}\n", q(&c.message)));
        out.push_str(&format!("reason = {}\n", q(reason)));
    }
    (out, chosen.len(), kept)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_are_compared_without_their_version() {
        assert_eq!(
            component_key("RTC:Lab:Mobile:Nav:1.0.0"),
            "RTC:Lab:Mobile:Nav"
        );
        assert_eq!(
            component_key("RTC:Lab:Ctl:Robot:1.0 (Python)"),
            "RTC:Lab:Ctl:Robot (Python)"
        );
        assert_eq!(component_key("RTSystem:Lab:Nav:1.0"), "RTSystem:Lab:Nav");
        assert_eq!(component_key("(no id: a/RTC.xml)"), "(no id: a/RTC.xml)");
        assert_eq!(component_key(""), "");
    }

    #[test]
    fn an_entry_without_a_reason_is_refused_where_reviewed() {
        let text = "version = 1\n\n[[accept]]\ncode = \"DIFF104\"\ncomponent = \"RTC:a:b:c:1\"\nelement = \"dataPorts/x/type\"\nreason = \"TODO: why this change is accepted\"\n";
        let e = parse(text, "b.toml", true).unwrap_err().to_string();
        assert!(
            e.starts_with("b.toml:3:1: the entry accepting DIFF104"),
            "{e}"
        );
        assert!(e.contains("has no reason"), "{e}");
        assert_eq!(parse(text, "b.toml", false).unwrap().entries.len(), 1);
        let e = parse(&text.replace("DIFF104", "DIFF1040"), "b.toml", false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("did you mean `DIFF104`?"), "{e}");
        let e = parse("version = 2\n", "b.toml", false)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("b.toml:1:11: baseline version 2"), "{e}");
        let e = parse(
            "[[accept]]\ncode = \"DIFF104\"\nelemnt = \"\"\n",
            "b.toml",
            false,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("elemnt"), "{e}");
    }
}
