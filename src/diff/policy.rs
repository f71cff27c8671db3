//! The `[diff]` policy of `rtcdoc.toml`: which changes a team ignores and which severity a code
//! has for it, in the vocabulary of `buf breaking` (`ignore`, `ignore-only`, `except`).
//!
//! ```toml
//! [diff]
//! ignore = ["DIFF3xx", "DIFF208"]             # codes, names or categories
//! except = ["DIFF304"]                        # re-enabled from the categories of `ignore`
//! ignore-only = { "DIFF103" = ["components/Legacy/**"] }   # a code in some files only
//! severity = { "DIFF201" = "breaking", "DIFF13x" = "warning" }
//! ```
//!
//! A *category* names the codes of a digit: `DIFF1xx` every breaking change, `DIFF13x` the
//! IDL-level breaking changes (the numbering of [`super::codes`]). A code or category that names
//! no change is an error with the nearest code; so is an `except` that re-enables nothing.
//!
//! The policy is applied once, to the finished list of changes ([`Policy::apply`]): severities
//! first (the most specific selector wins: a code over `DIFF13x` over `DIFF1xx`), then what is
//! ignored. Nothing is dropped: an ignored change stays in the list, marked, and is counted
//! apart ([`Status::Ignored`]).

use super::codes::{self, Level};
use super::{Change, Diff};
use anyhow::{bail, Result};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// `[diff]` as written (checked by [`Policy::new`] when the file is read).
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct DiffConfig {
    /// Codes, names or categories whose changes never count.
    pub ignore: Option<Vec<Spanned<String>>>,
    /// Codes (or categories) ignored only in the files the globs match (input-relative).
    pub ignore_only: Option<BTreeMap<String, Spanned<Vec<String>>>>,
    /// Codes taken back out of the categories of `ignore`.
    pub except: Option<Vec<Spanned<String>>>,
    /// Another severity for codes or categories: `breaking`, `warning` or `info`.
    pub severity: Option<BTreeMap<String, Spanned<String>>>,
}

/// What the policy and the baseline made of one change.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub enum Status {
    /// It counts: towards the summary's severities and `--fail-on`.
    #[default]
    Counts,
    /// `[diff] ignore` or `ignore-only` selects it.
    Ignored,
    /// An entry of the `--baseline` file accepts it, for this reason.
    Accepted(String),
}

/// A change's [`Status`], and its registry severity when `[diff] severity` changed it.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Standing {
    pub status: Status,
    pub default_severity: Option<Level>,
    /// The experimental item a breaking change was relaxed to a warning for
    /// ([`super::stability`]: `` component `X` ``).
    pub relaxed: Option<String>,
}

/// A code, or the codes of a category.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Selector {
    Code(&'static str),
    /// `DIFF1` for `DIFF1xx`, `DIFF13` for `DIFF13x`.
    Category(String),
}

impl Selector {
    fn parse(written: &str) -> std::result::Result<Selector, String> {
        let s = written.trim();
        if let Some(c) = codes::code(s) {
            return Ok(Selector::Code(c.code));
        }
        let upper = s.to_ascii_uppercase();
        if let Some(digits) = upper.strip_prefix("DIFF").filter(|d| d.len() == 3) {
            let open = digits.chars().rev().take_while(|c| *c == 'X').count();
            let fixed = &digits[..3 - open];
            if (1..=2).contains(&open) && fixed.chars().all(|c| c.is_ascii_digit()) {
                let prefix = format!("DIFF{fixed}");
                if codes::CODES.iter().any(|c| c.code.starts_with(&prefix)) {
                    return Ok(Selector::Category(prefix));
                }
                return Err(format!(
                    "no change has a code in the category `{s}`; the categories are DIFF0xx (the comparison itself), DIFF1xx (breaking), DIFF2xx (warnings) and DIFF3xx (information), and their tens (DIFF13x: IDL, DIFF15x: RT Systems; see `rtcdoc diff --explain CODE` and the guide's table of codes)"
                ));
            }
        }
        let candidates = codes::CODES.iter().flat_map(|c| [c.code, c.name]);
        let hint = match crate::suggest::typo(s, candidates) {
            Some(near) => format!("did you mean `{near}`?"),
            None => "write a code (`DIFF104`), its name (`data-port-type-changed`) or a category (`DIFF1xx`, `DIFF13x`)".to_string(),
        };
        Err(format!("no change has the code or name `{s}`; {hint}"))
    }

    fn matches(&self, code: &str) -> bool {
        match self {
            Selector::Code(c) => *c == code,
            Selector::Category(prefix) => code.starts_with(prefix.as_str()),
        }
    }

    /// How specific it is: a code over a ten over a hundred.
    fn rank(&self) -> usize {
        match self {
            Selector::Code(_) => 9,
            Selector::Category(prefix) => prefix.len(),
        }
    }

    /// Whether some code is selected by both.
    fn overlaps(&self, other: &Selector) -> bool {
        codes::CODES
            .iter()
            .any(|c| self.matches(c.code) && other.matches(c.code))
    }
}

/// `[diff]` checked and compiled.
#[derive(Debug, Clone, Default)]
pub struct Policy {
    ignore: Vec<Selector>,
    except: Vec<Selector>,
    ignore_only: Vec<(Selector, globset::GlobSet)>,
    severity: Vec<(Selector, Level)>,
}

fn level(written: &str) -> Option<Level> {
    match written {
        "breaking" => Some(Level::Breaking),
        "warning" => Some(Level::Warning),
        "info" => Some(Level::Info),
        _ => None,
    }
}

impl Policy {
    /// Checks `[diff]`; `at` names the place of a value (`rtcdoc.toml:3:10`) in the errors.
    pub fn new(c: &DiffConfig, at: &dyn Fn(Range<usize>) -> String) -> Result<Policy> {
        let selector = |key: &str, s: &str, span: Range<usize>| {
            Selector::parse(s).map_err(|e| anyhow::anyhow!("{}: [diff] {key}: {e}", at(span)))
        };
        let mut p = Policy::default();
        for s in c.ignore.iter().flatten() {
            p.ignore.push(selector("ignore", s.get_ref(), s.span())?);
        }
        for s in c.except.iter().flatten() {
            let sel = selector("except", s.get_ref(), s.span())?;
            if !p.ignore.iter().any(|i| i.overlaps(&sel)) {
                bail!(
                    "{}: [diff] except: `{}` is not in any category of `ignore`, so it re-enables nothing; `except` takes codes back out of the categories `ignore` names (ignore = [\"DIFF3xx\"], except = [\"DIFF304\"])",
                    at(s.span()),
                    s.get_ref()
                );
            }
            p.except.push(sel);
        }
        for (key, globs) in c.ignore_only.iter().flatten() {
            let sel = selector("ignore-only", key, globs.span())?;
            if globs.get_ref().is_empty() {
                bail!(
                    "{}: [diff] ignore-only: `{key}` has no glob, so it ignores nothing; list the files it is ignored in, relative to the input (\"components/Legacy/**\"), or move the code to `ignore`",
                    at(globs.span())
                );
            }
            let set = crate::walk::glob_set(globs.get_ref()).map_err(|(pattern, e)| {
                anyhow::anyhow!(
                    "{}: [diff] ignore-only: `{key}`: `{pattern}` is not a valid glob ({e}); write a path relative to the input, with `*` within a folder and `**` across folders",
                    at(globs.span())
                )
            })?;
            p.ignore_only.push((sel, set));
        }
        let mut severity: Vec<(Selector, Level, &str)> = Vec::new();
        for (key, value) in c.severity.iter().flatten() {
            let sel = selector("severity", key, value.span())?;
            let Some(l) = level(value.get_ref().trim()) else {
                let near = crate::suggest::typo(value.get_ref(), ["breaking", "warning", "info"])
                    .map(|n| format!(" (did you mean `{n}`?)"))
                    .unwrap_or_default();
                bail!(
                    "{}: [diff] severity: `{key}` = `{}` is no severity{near}; write \"breaking\", \"warning\" or \"info\"",
                    at(value.span()),
                    value.get_ref()
                );
            };
            if let Some((_, _, first)) = severity.iter().find(|(s, _, _)| *s == sel) {
                bail!(
                    "{}: [diff] severity: `{key}` names the same codes as `{first}`; keep one of them",
                    at(value.span())
                );
            }
            severity.push((sel, l, key));
        }
        p.severity = severity.into_iter().map(|(s, l, _)| (s, l)).collect();
        Ok(p)
    }

    /// Whether the policy does anything.
    pub fn is_empty(&self) -> bool {
        self.ignore.is_empty() && self.ignore_only.is_empty() && self.severity.is_empty()
    }

    /// The severity `[diff] severity` gives `code`, if it names it (the most specific entry).
    fn severity_of(&self, code: &str) -> Option<Level> {
        self.severity
            .iter()
            .filter(|(s, _)| s.matches(code))
            .max_by_key(|(s, _)| s.rank())
            .map(|(_, l)| *l)
    }

    /// Whether a change is ignored; `files` are its files relative to their side's input.
    fn ignores(&self, change: &Change, files: &[String]) -> bool {
        let code = change.code;
        (self.ignore.iter().any(|s| s.matches(code))
            && !self.except.iter().any(|s| s.matches(code)))
            || self.ignore_only.iter().any(|(s, globs)| {
                s.matches(code) && files.iter().any(|f| globs.is_match(f.as_str()))
            })
    }

    /// Applies the policy to the finished comparison: severities, then what is ignored.
    /// `files` gives a change's files relative to the input of their side (NEW's, then OLD's),
    /// as the globs of `ignore-only` are written.
    pub fn apply(&self, diff: &mut Diff, files: &dyn Fn(&Change) -> Vec<String>) {
        if self.is_empty() {
            return;
        }
        diff.gate.resize(diff.changes.len(), Standing::default());
        for (change, standing) in diff.changes.iter_mut().zip(diff.gate.iter_mut()) {
            if let Some(l) = self.severity_of(change.code) {
                if l != change.severity {
                    standing.default_severity.get_or_insert(change.severity);
                    change.severity = l;
                }
            }
            if self.ignores(change, &files(change)) {
                standing.status = Status::Ignored;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn policy(text: &str) -> Result<Policy> {
        #[derive(Deserialize)]
        struct Doc {
            diff: DiffConfig,
        }
        let doc: Doc = toml::from_str(text).map_err(|e| anyhow::anyhow!("{e}"))?;
        Policy::new(&doc.diff, &|span| format!("at {}", span.start))
    }

    #[test]
    fn selectors_are_codes_names_and_categories() {
        assert_eq!(Selector::parse("diff104"), Ok(Selector::Code("DIFF104")));
        assert_eq!(
            Selector::parse("data-port-type-changed"),
            Ok(Selector::Code("DIFF104"))
        );
        assert_eq!(
            Selector::parse("DIFF1xx"),
            Ok(Selector::Category("DIFF1".into()))
        );
        assert_eq!(
            Selector::parse("DIFF13X"),
            Ok(Selector::Category("DIFF13".into()))
        );
        let e = Selector::parse("DIFF4xx").unwrap_err();
        assert!(e.contains("no change has a code in the category"), "{e}");
        let e = Selector::parse("DIFF1004").unwrap_err();
        assert!(e.contains("did you mean `DIFF104`?"), "{e}");
        let e = Selector::parse("data-port-typ-changed").unwrap_err();
        assert!(e.contains("did you mean `data-port-type-changed`?"), "{e}");
        let e = Selector::parse("something").unwrap_err();
        assert!(e.contains("write a code"), "{e}");
    }

    #[test]
    fn the_most_specific_severity_wins() {
        let p = policy(
            "[diff]\nseverity = { \"DIFF1xx\" = \"warning\", \"DIFF13x\" = \"info\", \"DIFF131\" = \"breaking\" }\n",
        )
        .unwrap();
        assert_eq!(p.severity_of("DIFF104"), Some(Level::Warning));
        assert_eq!(p.severity_of("DIFF134"), Some(Level::Info));
        assert_eq!(p.severity_of("DIFF131"), Some(Level::Breaking));
        assert_eq!(p.severity_of("DIFF201"), None);
    }

    #[test]
    fn mistakes_are_errors_with_a_hint() {
        for (text, says) in [
            (
                "[diff]\nignore = [\"DIFF999\"]\n",
                "no change has the code or name `DIFF999`",
            ),
            (
                "[diff]\nignore = [\"DIFF3xx\"]\nexcept = [\"DIFF104\"]\n",
                "re-enables nothing",
            ),
            (
                "[diff]\nseverity = { DIFF104 = \"fatal\" }\n",
                "is no severity",
            ),
            (
                "[diff]\nseverity = { DIFF104 = \"warnign\" }\n",
                "did you mean `warning`?",
            ),
            (
                "[diff]\nseverity = { DIFF104 = \"info\", data-port-type-changed = \"warning\" }\n",
                "names the same codes",
            ),
            ("[diff]\nignore-only = { DIFF103 = [] }\n", "has no glob"),
            (
                "[diff]\nignore-only = { DIFF103 = [\"a/[\"] }\n",
                "is not a valid glob",
            ),
        ] {
            let e = policy(text).unwrap_err().to_string();
            assert!(e.contains(says), "{text}: {e}");
            assert!(e.starts_with("at "), "{e}");
        }
    }
}
