//! Diagnostics: what the readers, the catalogue and `check` report about profiles.
//!
//! Every diagnostic has a stable code (see [`crate::diagnostic::codes`]), a severity, a message,
//! the file and — where the input has one — the line and column, plus an optional hint.

use crate::model::Pos;
use serde::Serialize;

/// How serious a diagnostic is.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, serde::Deserialize,
)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
    Info,
}

impl std::fmt::Display for Severity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        })
    }
}

/// How many of `items` there are at each of three levels (`level`: 0 for the most severe, to
/// 2), and how many of each code; the counts of a `check` or `diff` summary.
pub fn tally<T>(
    items: &[T],
    level: impl Fn(&T) -> usize,
    code: impl Fn(&T) -> &str,
) -> ([usize; 3], std::collections::BTreeMap<String, usize>) {
    let mut levels = [0; 3];
    let mut by_code = std::collections::BTreeMap::new();
    for item in items {
        levels[level(item).min(2)] += 1;
        *by_code.entry(code(item).to_string()).or_default() += 1;
    }
    (levels, by_code)
}

/// The entry of a code registry (`check`'s rules, `diff`'s codes) whose code is `code`, in any
/// case and with blanks around it.
pub fn registry_entry<T>(
    table: &'static [T],
    code: &str,
    code_and_name: impl Fn(&T) -> (&str, &str),
) -> Option<&'static T> {
    let code = code.trim();
    table.iter().find(|e| {
        let (c, name) = code_and_name(e);
        c.eq_ignore_ascii_case(code) || name.eq_ignore_ascii_case(code)
    })
}

/// For serde's `unknown field `titel`, expected one of `title`, …`: `; did you mean `title`?`
/// when one of the keys is near the unknown one, else nothing.
pub fn unknown_field_hint(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `") else {
        return String::new();
    };
    let Some((unknown, expected)) = rest.split_once('`') else {
        return String::new();
    };
    let keys = expected.split('`').skip(1).step_by(2);
    crate::suggest::typo(unknown, keys)
        .map(|k| format!("; did you mean `{k}`?"))
        .unwrap_or_default()
}

/// `--explain` text of a registry entry: `CODE (name) — summary`, then each part as a paragraph.
pub fn explanation(code: &str, name: &str, summary: &str, parts: &[&str]) -> String {
    let mut s = format!("{code} ({name}) — {summary}\n");
    for p in parts {
        s.push('\n');
        s.push_str(p);
        s.push('\n');
    }
    s
}

/// A code of the readers (RTC001–RTC029: the profile and IDL readers, the walk and the
/// catalogue), not of a check rule. A reader's error means the file could not be read.
pub fn is_reader_code(code: &str) -> bool {
    code.strip_prefix("RTC")
        .and_then(|n| n.parse::<u16>().ok())
        .is_some_and(|n| n < 30)
        && code.len() == 6
}

/// `n` and `word`, with an `s` unless `n` is 1 (`1 warning`, `3 infos`).
pub fn counted(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}

/// One finding about one file.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Diagnostic {
    pub severity: Severity,
    /// Stable rule code, e.g. `RTC001`.
    pub code: &'static str,
    pub message: String,
    /// The file as shown to the user (relative to the input directory where possible).
    pub file: String,
    /// Line and column (1-based) where the input has them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pos: Option<Pos>,
    /// What to do about it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hint: Option<String>,
    /// The other place a finding is at (the profile element of a difference the code has):
    /// SARIF's `relatedLocations`, a note in the human output.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub related: Option<Box<Related>>,
}

/// A second location of a [`Diagnostic`], with what is there.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Related {
    pub file: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pos: Option<Pos>,
    pub message: String,
}

/// [`Diagnostic`] as `catalog.json` has it.
#[derive(serde::Deserialize)]
#[serde(rename_all = "camelCase")]
struct DiagnosticRead {
    severity: Severity,
    code: String,
    message: String,
    file: String,
    #[serde(default)]
    pos: Option<Pos>,
    #[serde(default)]
    hint: Option<String>,
    #[serde(default)]
    related: Option<Box<Related>>,
}

impl<'de> serde::Deserialize<'de> for Diagnostic {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let r = DiagnosticRead::deserialize(d)?;
        Ok(Diagnostic {
            severity: r.severity,
            code: crate::model::intern(r.code),
            message: r.message,
            file: r.file,
            pos: r.pos,
            hint: r.hint,
            related: r.related,
        })
    }
}

impl Diagnostic {
    pub fn new(
        severity: Severity,
        code: &'static str,
        file: &str,
        message: impl Into<String>,
    ) -> Self {
        Diagnostic {
            severity,
            code,
            message: message.into(),
            file: file.to_string(),
            pos: None,
            hint: None,
            related: None,
        }
    }
    pub fn error(code: &'static str, file: &str, message: impl Into<String>) -> Self {
        Self::new(Severity::Error, code, file, message)
    }
    pub fn warning(code: &'static str, file: &str, message: impl Into<String>) -> Self {
        Self::new(Severity::Warning, code, file, message)
    }
    pub fn info(code: &'static str, file: &str, message: impl Into<String>) -> Self {
        Self::new(Severity::Info, code, file, message)
    }
    /// Sets the position (ignored when unknown, i.e. line 0).
    pub fn at(mut self, pos: Pos) -> Self {
        if !pos.is_unknown() {
            self.pos = Some(pos);
        }
        self
    }
    /// Names a second location (see [`Diagnostic::related`]).
    pub fn with_related(
        mut self,
        file: &str,
        pos: Option<Pos>,
        message: impl Into<String>,
    ) -> Self {
        self.related = Some(Box::new(Related {
            file: file.to_string(),
            pos: pos.filter(|p| !p.is_unknown()),
            message: message.into(),
        }));
        self
    }
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
    /// A file that could not be read.
    pub fn io(file: &str, err: &std::io::Error) -> Self {
        Self::error(codes::IO, file, format!("cannot read file: {err}"))
    }
}

/// Sorts diagnostics the way every output shows them: by file, position, severity, code and
/// message (a total order, so output is deterministic). The sort is stable and runs on every
/// core (rayon's merge sort: the same order as `slice::sort_by`).
pub fn sort(diagnostics: &mut [Diagnostic]) {
    use rayon::slice::ParallelSliceMut;
    diagnostics.par_sort_by(|a, b| {
        (&a.file, a.pos, a.severity, a.code, &a.message)
            .cmp(&(&b.file, b.pos, b.severity, b.code, &b.message))
    });
}

impl Diagnostic {
    /// The finding as the command line prints it: the one-liner with its file named `file` (as
    /// the user can open it), then `  = help: …` when it has a hint.
    pub fn cli_text(&self, file: &str) -> String {
        let mut s = String::new();
        // Writing to a String cannot fail.
        let _ = self.write_line(&mut s, file);
        if let Some(h) = &self.hint {
            s.push_str("\n  = help: ");
            s.push_str(h);
        }
        s
    }

    fn write_line(&self, f: &mut impl std::fmt::Write, file: &str) -> std::fmt::Result {
        write!(f, "{file}")?;
        if let Some(p) = self.pos {
            write!(f, ":{}:{}", p.line, p.column)?;
        }
        write!(f, ": {}[{}]: {}", self.severity, self.code, self.message)
    }
}

impl std::fmt::Display for Diagnostic {
    /// `file:line:col: severity[CODE]: message`, the compiler-style one-liner.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.write_line(f, &self.file)
    }
}

/// Codes of the diagnostics produced while loading profiles and IDL (the `check` rules add their own).
pub mod codes {
    /// The file is not well-formed XML or YAML.
    pub const MALFORMED: &str = "RTC001";
    /// The file is larger than the configured limit.
    pub const TOO_LARGE: &str = "RTC002";
    /// Elements or YAML collections nest deeper than the configured limit.
    pub const TOO_DEEP: &str = "RTC003";
    /// A DOCTYPE with entity declarations, or an entity reference that is not predefined.
    pub const ENTITY: &str = "RTC004";
    /// Bytes that are not valid in the declared (or default UTF-8) encoding.
    pub const ENCODING: &str = "RTC005";
    /// A value the spec does not define; it is kept as an extra property.
    pub const UNKNOWN: &str = "RTC006";
    /// The file could not be read.
    pub const IO: &str = "RTC007";
    /// A YAML alias expands too much (alias bomb) or the YAML structure is not a profile.
    pub const YAML_STRUCTURE: &str = "RTC008";
    /// A value has the wrong shape for its place (e.g. a map where text is expected).
    pub const SHAPE: &str = "RTC009";
    /// Two profiles declare the same component id.
    pub const DUPLICATE_ID: &str = "RTC010";
    /// Empty attributes or keys the spec does not define (one summary note per profile).
    pub const EMPTY_UNKNOWN: &str = "RTC011";
    /// A file named like a profile (`RTC.xml`, a backup `RTC.xml<timestamp>`) is not one.
    pub const NOT_A_PROFILE: &str = "RTC012";
    /// RTCBuilder backups (`RTC.xml<timestamp>`) whose `RTC.xml` is gone.
    pub const ORPHAN_BACKUP: &str = "RTC013";
    /// Two `[[source]]` repositories (or one and the input directory) declare the same
    /// component id.
    pub const DUPLICATE_ACROSS_SOURCES: &str = "RTC014";
    /// A file of a `[[source]]` repository that is not read: a symbolic link or a submodule.
    pub const SOURCE_SKIPPED: &str = "RTC015";
    // The IDL reader's (RTC020–RTC029), used as `crate::idl::codes`.
    /// A syntax error (with the declaration skipped up to the next `;` or `}`).
    pub const IDL_SYNTAX: &str = "RTC020";
    /// A malformed or unbalanced preprocessor directive, or `#error`.
    pub const IDL_PREPROCESSOR: &str = "RTC021";
    /// An `#include` that names no file among those read.
    pub const IDL_INCLUDE: &str = "RTC022";
    /// Files that include each other without include guards.
    pub const IDL_INCLUDE_CYCLE: &str = "RTC023";
    /// A limit against hostile input: file size, nesting, include depth, token count.
    pub const IDL_LIMIT: &str = "RTC024";
    /// The file is not UTF-8 (which encoding was used), or not decodable.
    pub const IDL_ENCODING: &str = "RTC025";
    /// A declaration rtcdoc does not model (valuetype, component, …), skipped.
    pub const IDL_SKIPPED: &str = "RTC026";
    /// A directive or pragma that was ignored: unknown, unsupported, malformed, or naming
    /// nothing.
    pub const IDL_DIRECTIVE: &str = "RTC027";
    /// The same name declared twice in one file.
    pub const IDL_REDEFINITION: &str = "RTC028";
    /// A type name that no IDL file read defines.
    pub const IDL_UNRESOLVED: &str = "RTC029";
}

/// How many names a message lists before `and N more` ([`a_few`]).
pub const A_FEW: usize = 3;

/// `a, b, c and N more`: the first [`A_FEW`] of `names`, and how many others there are (a
/// message naming the other copies of something copied hundreds of times stays short).
pub fn a_few<S: AsRef<str>>(names: &[S]) -> String {
    a_few_of(names, names.len())
}

/// [`a_few`] of a list of `total` names of which `names` are the first.
pub fn a_few_of<S: AsRef<str>>(names: &[S], total: usize) -> String {
    let shown = names.len().min(A_FEW);
    let mut list = names[..shown]
        .iter()
        .map(AsRef::as_ref)
        .collect::<Vec<_>>()
        .join(", ");
    if total > shown {
        list.push_str(&format!(" and {} more", total - shown));
    }
    list
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_few_names_and_how_many_more() {
        assert_eq!(super::a_few::<&str>(&[]), "");
        assert_eq!(super::a_few(&["a", "b"]), "a, b");
        assert_eq!(super::a_few(&["a", "b", "c"]), "a, b, c");
        assert_eq!(
            super::a_few(&["a", "b", "c", "d", "e"]),
            "a, b, c and 2 more"
        );
        assert_eq!(
            super::a_few_of(&["a", "b", "c", "d"], 999),
            "a, b, c and 996 more"
        );
    }

    use super::*;

    #[test]
    fn unknown_fields_are_given_their_typo() {
        assert_eq!(
            unknown_field_hint("unknown field `prot`, expected `port` or `open`"),
            "; did you mean `port`?"
        );
        assert_eq!(unknown_field_hint("invalid type: integer"), "");
    }
}
