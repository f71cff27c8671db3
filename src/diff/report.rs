//! Output of `rtcdoc diff`: human (coloured like `check`), JSON, Markdown (a pull-request
//! comment) and GitHub workflow annotations.
//!
//! JSON schema (format 1, stable; documented in `book/src/diff.md`):
//! ```text
//! {"formatVersion": 1,
//!  "old": "…", "new": "…",
//!  "changes": [{"severity": "breaking|warning|info", "code", "name", "component", "path",
//!               "old": s|null, "new": s|null, "message",
//!               "file": s|null, "line": n|null, "column": n|null, "oldFile": s|null,
//!               "oldLine"?: n, "oldColumn"?: n}],
//!  "summary": {"breaking", "warning", "info", "byCode": {"DIFF104": n, …},
//!              "components": {"old", "new", "matched", "changed", "added", "removed"},
//!              "systems": {"old", "new", "matched", "changed", "added", "removed"},
//!              "idl": {"old", "new", "matched", "changed", "added", "removed"},
//!              "failOn": "breaking|warning|info|never", "failed": bool}}
//! ```

use super::{Change, Diff, Level};
use codespan_reporting::term::termcolor::{Color, ColorSpec, WriteColor};
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Version of the JSON output shape; bumped on incompatible changes.
pub const FORMAT_VERSION: u32 = 1;

fn fail_on_name(fail_on: Option<Level>) -> String {
    fail_on.map_or("never".into(), |l| l.to_string())
}

/// The JSON document of a comparison of `old` and `new` (the sides as given).
pub fn to_json(diff: &Diff, old: &str, new: &str, fail_on: Option<Level>) -> Value {
    let s = diff.summary();
    json!({
        "formatVersion": FORMAT_VERSION,
        "old": old,
        "new": new,
        "changes": diff.changes,
        "summary": {
            "breaking": s.breaking,
            "warning": s.warning,
            "info": s.info,
            "byCode": s.by_code,
            "components": diff.components,
            "systems": diff.systems,
            "idl": diff.idl,
            "failOn": fail_on_name(fail_on),
            "failed": s.fails(fail_on),
        },
    })
}

/// The one-line summary: `1 breaking, 2 warnings, 3 infos in 2 of 11 matched component(s); 1
/// added, 0 removed`, and when a side has RT System profiles `; 1 of 2 matched system(s)
/// changed, 0 added, 0 removed`, and when a side has IDL `; 1 of 12 matched IDL definition(s)
/// changed, 1 added, 0 removed`.
pub fn one_line(diff: &Diff) -> String {
    let c = &diff.components;
    format!(
        "{} in {} of {} matched component(s); {} added, {} removed{}{}",
        diff.summary().counts(),
        c.changed,
        c.matched,
        c.added,
        c.removed,
        systems_line(diff),
        idl_line(diff)
    )
}

/// `; 1 of 12 matched IDL definition(s) changed, 1 added, 0 removed`, or nothing when neither
/// side has IDL.
fn idl_line(diff: &Diff) -> String {
    let s = &diff.idl;
    if s.old + s.new == 0 {
        return String::new();
    }
    format!(
        "; {} of {} matched IDL definition(s) changed, {} added, {} removed",
        s.changed, s.matched, s.added, s.removed
    )
}

/// `; 1 of 2 matched system(s) changed, 0 added, 0 removed`, or nothing without systems.
fn systems_line(diff: &Diff) -> String {
    let s = &diff.systems;
    if s.old + s.new == 0 {
        return String::new();
    }
    format!(
        "; {} of {} matched system(s) changed, {} added, {} removed",
        s.changed, s.matched, s.added, s.removed
    )
}

/// Changes grouped by component: components with breaking changes first, then those with
/// warnings, then the rest, each group by id; inside a component by severity, then path.
fn by_component(changes: &[Change]) -> Vec<(&str, Vec<&Change>)> {
    let mut groups: BTreeMap<&str, Vec<&Change>> = BTreeMap::new();
    for c in changes {
        groups.entry(c.component.as_str()).or_default().push(c);
    }
    let mut out: Vec<(&str, Vec<&Change>)> = groups.into_iter().collect();
    for (_, v) in &mut out {
        v.sort_by(|a, b| (a.severity, &a.path, a.code).cmp(&(b.severity, &b.path, b.code)));
    }
    out.sort_by(|a, b| {
        let worst = |v: &[&Change]| v.iter().map(|c| c.severity).min();
        (worst(&a.1), a.0).cmp(&(worst(&b.1), b.0))
    });
    out
}

/// One line of at most [`CELL_CHARS`] characters.
fn single_line(s: &str) -> String {
    let one: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
    if one.chars().count() > CELL_CHARS {
        format!("{}…", one.chars().take(CELL_CHARS - 1).collect::<String>())
    } else {
        one
    }
}

/// Text for a Markdown table cell ([`one_line`]) that may hold `` `code` `` spans, as messages
/// do: outside the spans `\`, `<` and `>` are escaped; inside them nothing is (Markdown shows
/// a code span as written); `|` is escaped everywhere, as a table needs.
fn cell(s: &str) -> String {
    text(s, true)
}

/// [`cell`] for a list item: the same, but `|` is no special character there.
fn item(s: &str) -> String {
    text(s, false)
}

fn text(s: &str, table: bool) -> String {
    let one = single_line(s);
    let mut out = String::with_capacity(one.len() + 8);
    // Only balanced spans are code: an odd last backtick is text.
    let spans = one.matches('`').count() / 2 * 2;
    let mut ticks = 0;
    for c in one.chars() {
        let in_code = ticks % 2 == 1;
        match c {
            '`' => {
                if ticks < spans {
                    ticks += 1;
                    out.push('`');
                } else {
                    out.push_str("\\`");
                }
            }
            '|' if table => out.push_str("\\|"),
            '\\' if !in_code => out.push_str("\\\\"),
            '<' if !in_code => out.push_str("&lt;"),
            '>' if !in_code => out.push_str("&gt;"),
            c => out.push(c),
        }
    }
    out
}

/// A value as a code span in a table cell: shown as written, whatever it holds (a fence
/// longer than its longest run of backticks, padded where it starts or ends with one; `|`
/// escaped for the table).
fn code_cell(s: &Option<String>) -> String {
    match s {
        None => "—".into(),
        Some(s) if s.is_empty() => "(empty)".into(),
        Some(s) => code_span(&single_line(s), true),
    }
}

fn code_span(s: &str, table: bool) -> String {
    let longest = s.split(|c| c != '`').map(str::len).max().unwrap_or(0);
    let fence = "`".repeat(longest + 1);
    let pad = if s.starts_with('`') || s.ends_with('`') {
        " "
    } else {
        ""
    };
    let body = if table {
        s.replace('|', "\\|")
    } else {
        s.to_string()
    };
    format!("{fence}{pad}{body}{pad}{fence}")
}

/// Longest cell text: long descriptions and constraint formulas stay readable in a table.
const CELL_CHARS: usize = 400;

/// GitHub refuses comments over 65,536 characters; stay well below.
const MARKDOWN_LIMIT: usize = 60_000;

fn icon(l: Level) -> &'static str {
    match l {
        Level::Breaking => "🔴",
        Level::Warning => "🟡",
        Level::Info => "🔵",
    }
}

/// The Markdown report, for a pull-request comment: a summary line, then one section per
/// component (breaking first) with a table of its breaking changes and warnings and a folded
/// list of its informational changes.
pub fn to_markdown(diff: &Diff, old: &str, new: &str, fail_on: Option<Level>) -> String {
    let s = diff.summary();
    let mut out = String::new();
    let verdict = if s.fails(fail_on) {
        format!("fails (`--fail-on {}`)", fail_on_name(fail_on))
    } else {
        "passes".to_string()
    };
    let _ = writeln!(out, "## rtcdoc diff: {}\n", s.counts());
    let c = &diff.components;
    let _ = writeln!(
        out,
        "Comparing {} → {}: {} of {} matched component(s) changed, {} added, {} removed{}{}; the check {verdict}.\n",
        code_span(&single_line(old), false),
        code_span(&single_line(new), false),
        c.changed,
        c.matched,
        c.added,
        c.removed,
        systems_line(diff),
        idl_line(diff)
    );
    if diff.changes.is_empty() {
        out.push_str("No changes.\n");
        return out;
    }
    let groups = by_component(&diff.changes);
    for (i, (component, changes)) in groups.iter().enumerate() {
        let mut section = String::new();
        let title = if component.is_empty() {
            "Inputs".to_string()
        } else {
            code_span(&single_line(component), false)
        };
        let count = |l: Level| changes.iter().filter(|c| c.severity == l).count();
        let _ = writeln!(
            section,
            "### {title}\n\n{} breaking, {} warning(s), {} info(s)\n",
            count(Level::Breaking),
            count(Level::Warning),
            count(Level::Info)
        );
        let serious: Vec<&&Change> = changes
            .iter()
            .filter(|c| c.severity != Level::Info)
            .collect();
        if !serious.is_empty() {
            section.push_str("| | Code | Path | Old | New | What |\n|---|---|---|---|---|---|\n");
            for ch in serious {
                let _ = writeln!(
                    section,
                    "| {} {} | {} `{}` | {} | {} | {} | {} |",
                    icon(ch.severity),
                    ch.severity,
                    ch.code,
                    ch.name,
                    code_cell(&Some(ch.path.clone()).filter(|p| !p.is_empty())),
                    code_cell(&ch.old),
                    code_cell(&ch.new),
                    cell(&ch.message)
                );
            }
            section.push('\n');
        }
        let infos: Vec<&&Change> = changes
            .iter()
            .filter(|c| c.severity == Level::Info)
            .collect();
        if !infos.is_empty() {
            let _ = writeln!(
                section,
                "<details><summary>{} informational change(s)</summary>\n",
                infos.len()
            );
            for ch in infos {
                let path = if ch.path.is_empty() {
                    String::new()
                } else {
                    format!("{} ", code_span(&single_line(&ch.path), false))
                };
                let _ = writeln!(
                    section,
                    "- {} {}{} — {}",
                    ch.code,
                    path,
                    ch.name,
                    item(&ch.message)
                );
            }
            section.push_str("\n</details>\n\n");
        }
        if out.len() + section.len() > MARKDOWN_LIMIT {
            let _ = writeln!(
                out,
                "… and {} more component(s): run `rtcdoc diff` locally for the whole list.",
                groups.len() - i
            );
            break;
        }
        out.push_str(&section);
    }
    out
}

/// Escapes the message of a workflow command.
fn gh_data(s: &str) -> String {
    s.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// Escapes a property of a workflow command.
fn gh_prop(s: &str) -> String {
    gh_data(s).replace(':', "%3A").replace(',', "%2C")
}

/// GitHub workflow annotations: `::error` for breaking changes, `::warning` for warnings,
/// `::notice` for infos, at the NEW side's file and line where there is one; then the summary.
pub fn to_github(diff: &Diff) -> String {
    let mut out = String::new();
    for c in &diff.changes {
        let cmd = match c.severity {
            Level::Breaking => "error",
            Level::Warning => "warning",
            Level::Info => "notice",
        };
        let mut props = Vec::new();
        if let Some(f) = &c.file {
            props.push(format!("file={}", gh_prop(f)));
            if let Some(l) = c.line {
                props.push(format!("line={l}"));
                if let Some(col) = c.column {
                    props.push(format!("col={col}"));
                }
            }
        }
        props.push(format!(
            "title={}",
            gh_prop(&format!("{} {}", c.code, c.name))
        ));
        let what = if c.path.is_empty() {
            c.component.clone()
        } else {
            format!("{} {}", c.component, c.path)
        };
        let _ = writeln!(
            out,
            "::{cmd} {}::{}",
            props.join(","),
            gh_data(&format!("{what}: {}", c.message))
        );
    }
    let _ = writeln!(out, "rtcdoc diff: {}", one_line(diff));
    out
}

/// Which changes the human output prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verbosity {
    /// Breaking changes only, no summary.
    Quiet,
    /// Everything.
    Normal,
}

/// The human report: `severity[CODE] component: path: message` in the colours of `check`
/// (breaking red, warning yellow, info blue), with `old → new` and the file, then the summary.
pub fn write_human(
    out: &mut dyn WriteColor,
    diff: &Diff,
    verbosity: Verbosity,
    revs: [&str; 2],
) -> std::io::Result<()> {
    // A side read at a git revision names its files `REV:path`, as `git show` opens them.
    let [old_rev, new_rev] = revs;
    let colour = |l: Level| match l {
        Level::Breaking => Color::Red,
        Level::Warning => Color::Yellow,
        Level::Info => Color::Blue,
    };
    for (component, changes) in by_component(&diff.changes) {
        let shown: Vec<&&Change> = changes
            .iter()
            .filter(|c| verbosity == Verbosity::Normal || c.severity == Level::Breaking)
            .collect();
        if shown.is_empty() {
            continue;
        }
        out.set_color(ColorSpec::new().set_bold(true))?;
        writeln!(
            out,
            "{}",
            if component.is_empty() {
                "inputs"
            } else {
                component
            }
        )?;
        out.reset()?;
        for c in shown {
            out.set_color(
                ColorSpec::new()
                    .set_fg(Some(colour(c.severity)))
                    .set_bold(true),
            )?;
            write!(out, "  {}[{}]", c.severity, c.code)?;
            out.reset()?;
            // A message of several lines (a long text's word-level difference) stays indented.
            let message = c.message.replace('\n', "\n      ");
            if c.path.is_empty() {
                writeln!(out, ": {message}")?;
            } else {
                writeln!(out, " {}: {message}", c.path)?;
            }
            // A long text's change is its word-level difference: not both texts again in full.
            let words = crate::word_diff::message(c.old.as_deref(), c.new.as_deref())
                .is_some_and(|m| m == c.message);
            if (c.old.is_some() || c.new.is_some()) && !words {
                let v = |s: &Option<String>| s.clone().unwrap_or_else(|| "(absent)".into());
                writeln!(out, "      {} → {}", v(&c.old), v(&c.new))?;
            }
            // An item that exists only in OLD is shown where it is there.
            let in_old = match (&c.old_file, c.old_line) {
                (Some(f), Some(l)) => Some((f, l)),
                _ => None,
            };
            if let Some((f, l)) = in_old {
                out.set_color(ColorSpec::new().set_fg(Some(Color::Cyan)))?;
                writeln!(
                    out,
                    "      --> {old_rev}{f}:{l}:{}",
                    c.old_column.unwrap_or(1)
                )?;
                out.reset()?;
            } else if let Some(f) = &c.file {
                out.set_color(ColorSpec::new().set_fg(Some(Color::Cyan)))?;
                match c.line {
                    Some(l) => {
                        writeln!(out, "      --> {new_rev}{f}:{l}:{}", c.column.unwrap_or(1))?
                    }
                    None => writeln!(out, "      --> {new_rev}{f}")?,
                }
                out.reset()?;
            } else if let Some(f) = &c.old_file {
                writeln!(out, "      (was {old_rev}{f})")?;
            }
        }
    }
    if verbosity == Verbosity::Normal {
        writeln!(out, "rtcdoc diff: {}", one_line(diff))?;
    }
    Ok(())
}

/// `rtcdoc diff --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum OutputFormat {
    /// Coloured text (like `check`), on standard output.
    #[default]
    Human,
    /// The JSON document of the guide, on standard output.
    Json,
    /// A pull-request comment.
    Markdown,
    /// GitHub workflow annotations (`::error file=…,line=…::…`).
    Github,
}

/// `rtcdoc diff --fail-on`: the least severe change that makes the exit status 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum FailOn {
    /// Breaking changes fail.
    #[default]
    Breaking,
    /// Breaking changes and warnings fail.
    Warning,
    /// Any change fails.
    Info,
    /// Never fail on changes (exit 0 unless the inputs cannot be read).
    Never,
}

impl FailOn {
    pub fn level(self) -> Option<Level> {
        match self {
            FailOn::Breaking => Some(Level::Breaking),
            FailOn::Warning => Some(Level::Warning),
            FailOn::Info => Some(Level::Info),
            FailOn::Never => None,
        }
    }
}
