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
//!               "oldLine"?: n, "oldColumn"?: n,
//!               "status"?: "accepted|ignored", "reason"?: s, "defaultSeverity"?: s,
//!               "reach"?: [{"component", "role": "producer|consumer|provider|requirer|other"}]}],
//!  "impact": {"connectors": n, "systems": [{"system", "connectors"}],
//!             "lostProducers": [{"type", "components": [id]}], "lostProviders": [same],
//!             "reached": [id], "summary": s|null},
//!  "baseline": s|null,
//!  "stale": [{"code", "component", "element", "old"?, "new"?, "file"?, "message"?, "reason",
//!             "at", "line", "column"}],
//!  "summary": {"breaking", "warning", "info", "byCode": {"DIFF104": n, …},
//!              "accepted", "ignored", "stale",
//!              "components": {"old", "new", "matched", "changed", "added", "removed"},
//!              "systems": {"old", "new", "matched", "changed", "added", "removed"},
//!              "idl": {"old", "new", "matched", "changed", "added", "removed"},
//!              "failOn": "breaking|warning|info|never", "failed": bool}}
//! ```
//!
//! The counts of the summary (and `byCode`) are of the changes that count: a change a baseline
//! accepts or the `[diff]` policy ignores is listed with its `status`, and counted apart; so is
//! the `impact` (a change's `reach` is given whatever its standing; see [`super::impact`]).

use super::{Change, Diff, Level, Status};
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
    let changes: Vec<Value> = diff
        .changes
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let mut v = json!(c);
            if let Some(o) = v.as_object_mut() {
                match diff.status(i) {
                    Status::Counts => {}
                    Status::Ignored => {
                        o.insert("status".into(), json!("ignored"));
                    }
                    Status::Accepted(reason) => {
                        o.insert("status".into(), json!("accepted"));
                        o.insert("reason".into(), json!(reason));
                    }
                }
                if let Some(d) = diff.default_severity(i) {
                    o.insert("defaultSeverity".into(), json!(d));
                }
                let reach = diff.reach(i);
                if !reach.is_empty() {
                    o.insert("reach".into(), json!(reach));
                }
                if let Some(item) = diff.relaxed(i) {
                    o.insert("relaxed".into(), json!("experimental"));
                    o.insert("relaxedFor".into(), json!(item));
                }
            }
            v
        })
        .collect();
    let stale: Vec<Value> = diff
        .stale
        .iter()
        .map(|st| {
            let e = &st.entry;
            let mut v = json!({
                "code": e.code,
                "component": e.component,
                "element": e.element,
                "reason": e.reason,
                "at": st.at,
                "line": st.line,
                "column": st.column,
            });
            if let Some(o) = v.as_object_mut() {
                for (k, x) in [
                    ("old", &e.old),
                    ("new", &e.new),
                    ("file", &e.file),
                    ("message", &e.message),
                ] {
                    if let Some(x) = x {
                        o.insert(k.into(), json!(x));
                    }
                }
            }
            v
        })
        .collect();
    json!({
        "formatVersion": FORMAT_VERSION,
        "old": old,
        "new": new,
        "changes": changes,
        "impact": diff.impact(),
        "baseline": diff.baseline,
        "stale": stale,
        "summary": {
            "breaking": s.breaking,
            "warning": s.warning,
            "info": s.info,
            "byCode": s.by_code,
            "accepted": s.accepted,
            "ignored": s.ignored,
            "stale": s.stale,
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
/// Each change with its [`Status`]; the changes the policy ignores only when `ignored`. A
/// component's worst severity is of the changes that count.
fn by_component(diff: &Diff, ignored: bool) -> Vec<(&str, Vec<Shown<'_>>)> {
    let mut groups: BTreeMap<&str, Vec<Shown>> = BTreeMap::new();
    for (i, c) in diff.changes.iter().enumerate() {
        let status = diff.status(i);
        if ignored || *status != Status::Ignored {
            groups
                .entry(c.component.as_str())
                .or_default()
                .push((c, status, i));
        }
    }
    let mut out: Vec<(&str, Vec<Shown>)> = groups.into_iter().collect();
    for (_, v) in &mut out {
        v.sort_by(|(a, _, _), (b, _, _)| {
            (a.severity, &a.path, a.code).cmp(&(b.severity, &b.path, b.code))
        });
    }
    out.sort_by(|a, b| {
        let worst = |v: &[Shown]| {
            v.iter()
                .filter(|(_, s, _)| **s == Status::Counts)
                .map(|(c, _, _)| c.severity)
                .min()
        };
        let worst = |v: &[Shown]| worst(v).map_or((1, Level::Info), |l| (0, l));
        (worst(&a.1), a.0).cmp(&(worst(&b.1), b.0))
    });
    out
}

/// A change shown, its standing and its position in the changes.
type Shown<'a> = (&'a Change, &'a Status, usize);

/// `accepted (baseline): REASON` or `ignored (policy)` for a change that does not count.
fn standing_note(status: &Status) -> Option<String> {
    match status {
        Status::Counts => None,
        Status::Ignored => Some("ignored (policy)".into()),
        Status::Accepted(reason) => Some(format!("accepted (baseline): {reason}")),
    }
}

/// The sentence of a stale baseline entry.
fn stale_message(st: &super::baseline::Stale) -> String {
    let e = &st.entry;
    let what = if e.element.is_empty() {
        String::new()
    } else {
        format!(" `{}`", e.element)
    };
    format!(
        "stale baseline entry: {} on `{}`{what} is no longer a change; remove the entry (or write the file again with --write-baseline, which keeps the other reasons)",
        e.code, e.component
    )
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
/// list of its informational changes; a change a baseline accepts is marked with its reason,
/// one the policy ignores is only counted; then the stale baseline entries.
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
    out.push_str(&markdown_impact(diff));
    let stale = markdown_stale(diff);
    if diff.changes.is_empty() {
        out.push_str("No changes.\n");
        out.push_str(&stale);
        return out;
    }
    let groups = by_component(diff, false);
    if groups.is_empty() {
        let _ = writeln!(
            out,
            "No changes but the {} the `[diff]` policy ignores.",
            s.ignored
        );
    }
    for (i, (component, changes)) in groups.iter().enumerate() {
        let section = markdown_section(component, changes, diff);
        if out.len() + section.len() + stale.len() > MARKDOWN_LIMIT {
            let _ = writeln!(
                out,
                "… and {} more component(s): run `rtcdoc diff` locally for the whole list.",
                groups.len() - i
            );
            break;
        }
        out.push_str(&section);
    }
    out.push_str(&stale);
    out
}

/// The impact of the changes that count, as a list (nothing when they reach nothing), and the
/// reach of each change, folded.
fn markdown_impact(diff: &Diff) -> String {
    let impact = diff.impact();
    let parts = impact.parts();
    if parts.is_empty() {
        return String::new();
    }
    let mut out = String::from("**Impact:**\n\n");
    for p in &parts {
        let _ = writeln!(out, "- {}", item(p));
    }
    out.push('\n');
    let reaching: Vec<(usize, &Change)> = diff
        .changes
        .iter()
        .enumerate()
        .filter(|(i, _)| !diff.reach(*i).is_empty())
        .collect();
    if !reaching.is_empty() {
        let _ = writeln!(
            out,
            "<details><summary>What each change reaches</summary>\n"
        );
        for (i, c) in reaching {
            let line = super::impact::reach_line(diff.reach(i), true).unwrap_or_default();
            let _ = writeln!(
                out,
                "- {} {} {} — {}",
                c.code,
                code_span(&single_line(&c.component), false),
                code_span(&single_line(&c.path), false),
                item(&line)
            );
        }
        out.push_str("\n</details>\n\n");
    }
    out
}

/// ` — reaches 2 components` after the message of the `i`-th change in the Markdown report, or nothing.
fn reach_note(diff: &Diff, i: usize) -> String {
    super::impact::reach_line(diff.reach(i), false)
        .map(|l| format!(" — {l}"))
        .unwrap_or_default()
}

/// The section of one component in the Markdown report.
fn markdown_section(component: &str, changes: &[Shown], diff: &Diff) -> String {
    let mut section = String::new();
    let title = if component.is_empty() {
        "Inputs".to_string()
    } else {
        code_span(&single_line(component), false)
    };
    let count = |l: Level| {
        changes
            .iter()
            .filter(|(c, s, _)| c.severity == l && **s == Status::Counts)
            .count()
    };
    let accepted = changes
        .iter()
        .filter(|(_, s, _)| matches!(s, Status::Accepted(_)))
        .count();
    let _ = writeln!(
        section,
        "### {title}\n\n{} breaking, {} warning(s), {} info(s){}\n",
        count(Level::Breaking),
        count(Level::Warning),
        count(Level::Info),
        if accepted > 0 {
            format!(", {accepted} accepted (baseline)")
        } else {
            String::new()
        }
    );
    let serious: Vec<&Shown> = changes
        .iter()
        .filter(|(c, _, _)| c.severity != Level::Info)
        .collect();
    if !serious.is_empty() {
        section.push_str("| | Code | Path | Old | New | What |\n|---|---|---|---|---|---|\n");
        for (ch, status, i) in serious {
            let reach = reach_note(diff, *i);
            let (mark, what) = match standing_note(status) {
                Some(note) => (
                    format!("✅ {} (accepted)", ch.severity),
                    format!("{}{reach} — {note}", ch.message),
                ),
                None => (
                    format!("{} {}", icon(ch.severity), ch.severity),
                    format!("{}{reach}", ch.message),
                ),
            };
            let _ = writeln!(
                section,
                "| {mark} | {} `{}` | {} | {} | {} | {} |",
                ch.code,
                ch.name,
                code_cell(&Some(ch.path.clone()).filter(|p| !p.is_empty())),
                code_cell(&ch.old),
                code_cell(&ch.new),
                cell(&what)
            );
        }
        section.push('\n');
    }
    let infos: Vec<&Shown> = changes
        .iter()
        .filter(|(c, _, _)| c.severity == Level::Info)
        .collect();
    if !infos.is_empty() {
        let _ = writeln!(
            section,
            "<details><summary>{} informational change(s)</summary>\n",
            infos.len()
        );
        for (ch, status, i) in infos {
            let path = if ch.path.is_empty() {
                String::new()
            } else {
                format!("{} ", code_span(&single_line(&ch.path), false))
            };
            let note = standing_note(status)
                .map(|n| format!(" ({n})"))
                .unwrap_or_default();
            let _ = writeln!(
                section,
                "- {} {}{} — {}",
                ch.code,
                path,
                ch.name,
                item(&format!("{}{}{note}", ch.message, reach_note(diff, *i)))
            );
        }
        section.push_str("\n</details>\n\n");
    }
    section
}

/// The stale baseline entries, as a Markdown section (nothing when there are none).
fn markdown_stale(diff: &Diff) -> String {
    if diff.stale.is_empty() {
        return String::new();
    }
    let mut out = format!(
        "### Stale baseline entries\n\n{} entr{} of {} accept{} a change that is gone: remove {} (or write the file again with `--write-baseline`, which keeps the other reasons).\n\n",
        diff.stale.len(),
        if diff.stale.len() == 1 { "y" } else { "ies" },
        code_span(diff.baseline.as_deref().unwrap_or("the baseline"), false),
        if diff.stale.len() == 1 { "s" } else { "" },
        if diff.stale.len() == 1 { "it" } else { "them" },
    );
    for st in &diff.stale {
        let e = &st.entry;
        let element = if e.element.is_empty() {
            String::new()
        } else {
            format!(" {}", code_span(&single_line(&e.element), false))
        };
        let _ = writeln!(
            out,
            "- {} {} {}{element} — {}",
            code_span(&st.at, false),
            e.code,
            code_span(&single_line(&e.component), false),
            item(&e.reason)
        );
    }
    out.push('\n');
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
/// `::notice` for infos and for the changes a baseline accepts (with the reason), at the NEW
/// side's file and line where there is one; `::warning` at the baseline's line for a stale
/// entry; then the summary. The changes the policy ignores are only counted.
pub fn to_github(diff: &Diff) -> String {
    let mut out = String::new();
    if let Some(summary) = diff.impact().summary {
        let _ = writeln!(
            out,
            "::notice title={}::{}",
            gh_prop("rtcdoc diff impact"),
            gh_data(&summary)
        );
    }
    for (i, c) in diff.changes.iter().enumerate() {
        let status = diff.status(i);
        let cmd = match (status, c.severity) {
            (Status::Ignored, _) => continue,
            (Status::Accepted(_), _) | (_, Level::Info) => "notice",
            (_, Level::Breaking) => "error",
            (_, Level::Warning) => "warning",
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
        let accepted = if matches!(status, Status::Accepted(_)) {
            " (accepted)"
        } else {
            ""
        };
        props.push(format!(
            "title={}",
            gh_prop(&format!("{} {}{accepted}", c.code, c.name))
        ));
        let what = if c.path.is_empty() {
            c.component.clone()
        } else {
            format!("{} {}", c.component, c.path)
        };
        let note = standing_note(status)
            .map(|n| format!(" ({n})"))
            .unwrap_or_default();
        let _ = writeln!(
            out,
            "::{cmd} {}::{}",
            props.join(","),
            gh_data(&format!("{what}: {}{note}", c.message))
        );
    }
    for st in &diff.stale {
        let file = diff.baseline.as_deref().unwrap_or("");
        let _ = writeln!(
            out,
            "::warning file={},line={},col={},title={}::{}",
            gh_prop(file),
            st.line,
            st.column,
            gh_prop("stale baseline entry"),
            gh_data(&stale_message(st))
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
    /// Everything but the changes the policy ignores.
    Normal,
    /// Everything, the changes the policy ignores too.
    Verbose,
}

/// The human report: `severity[CODE] component: path: message` in the colours of `check`
/// (breaking red, warning yellow, info blue), with `old → new` and the file, then the summary.
/// A change a baseline accepts is marked `accepted (baseline): REASON` (in green), one the
/// policy ignores `ignored (policy)` (only with [`Verbosity::Verbose`]); the stale baseline
/// entries are warnings before the summary.
pub fn write_human(
    out: &mut dyn WriteColor,
    diff: &Diff,
    verbosity: Verbosity,
    revs: [&str; 2],
) -> std::io::Result<()> {
    if verbosity != Verbosity::Quiet {
        write_human_impact(out, diff, verbosity)?;
    }
    for (component, changes) in by_component(diff, verbosity == Verbosity::Verbose) {
        let shown: Vec<&Shown> = changes
            .iter()
            .filter(|(c, s, _)| {
                verbosity != Verbosity::Quiet
                    || (c.severity == Level::Breaking && **s == Status::Counts)
            })
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
        for (c, status, i) in shown {
            write_human_change(out, c, status, revs)?;
            let names = verbosity == Verbosity::Verbose;
            if let Some(line) = super::impact::reach_line(diff.reach(*i), names) {
                writeln!(out, "      {line}")?;
            }
        }
    }
    if verbosity != Verbosity::Quiet {
        for st in &diff.stale {
            out.set_color(ColorSpec::new().set_fg(Some(Color::Yellow)).set_bold(true))?;
            write!(out, "warning")?;
            out.reset()?;
            writeln!(out, ": {}: {}", st.at, stale_message(st))?;
        }
        writeln!(out, "rtcdoc diff: {}", one_line(diff))?;
    }
    Ok(())
}

/// `Impact: …` (bold), the summary of [`Diff::impact`], before the list (nothing when the
/// changes reach nothing); with [`Verbosity::Verbose`], the components of each lost type.
fn write_human_impact(
    out: &mut dyn WriteColor,
    diff: &Diff,
    verbosity: Verbosity,
) -> std::io::Result<()> {
    let impact = diff.impact();
    let Some(summary) = &impact.summary else {
        return Ok(());
    };
    out.set_color(ColorSpec::new().set_bold(true))?;
    write!(out, "Impact:")?;
    out.reset()?;
    writeln!(out, " {summary}")?;
    if verbosity == Verbosity::Verbose {
        for (lost, what) in [
            (&impact.lost_producers, "consumed"),
            (&impact.lost_providers, "required"),
        ] {
            for l in lost {
                writeln!(
                    out,
                    "  {} is still {what} by {}",
                    l.type_name,
                    l.components.join(", ")
                )?;
            }
        }
    }
    writeln!(out)
}

/// One change of the human report.
fn write_human_change(
    out: &mut dyn WriteColor,
    c: &Change,
    status: &Status,
    revs: [&str; 2],
) -> std::io::Result<()> {
    // A side read at a git revision names its files `REV:path`, as `git show` opens them.
    let [old_rev, new_rev] = revs;
    let colour = match (status, c.severity) {
        (Status::Counts, Level::Breaking) => Color::Red,
        (Status::Counts, Level::Warning) => Color::Yellow,
        (Status::Counts, Level::Info) => Color::Blue,
        (Status::Accepted(_), _) => Color::Green,
        (Status::Ignored, _) => Color::White,
    };
    out.set_color(ColorSpec::new().set_fg(Some(colour)).set_bold(true))?;
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
    if let Some(note) = standing_note(status) {
        out.set_color(ColorSpec::new().set_fg(Some(colour)))?;
        writeln!(out, "      {note}")?;
        out.reset()?;
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
            Some(l) => writeln!(out, "      --> {new_rev}{f}:{l}:{}", c.column.unwrap_or(1))?,
            None => writeln!(out, "      --> {new_rev}{f}")?,
        }
        out.reset()?;
    } else if let Some(f) = &c.old_file {
        writeln!(out, "      (was {old_rev}{f})")?;
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
