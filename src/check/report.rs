//! Output of `rtcdoc check`: human (rustc-like, via `codespan-reporting`), JSON and SARIF.
//!
//! JSON schema (version 1, stable; documented in `book/src/check.md`):
//! ```text
//! {"version": 1,
//!  "diagnostics": [{"code", "severity": "error|warning|info", "message", "file",
//!                   "line": n|null, "column": n|null, "hint": s|null}],
//!  "summary": {"errors", "warnings", "infos", "byCode": {"RTC101": n, …}},
//!  "coverage": {"documented", "total", "percent",
//!               "components": [{"source", "name", "documented", "total", "percent"}]}}
//! ```
//! SARIF: 2.1.0, one run, `tool.driver.rules` = the whole registry, one result per diagnostic.

use super::{registry, Report};
use crate::diagnostic::{Diagnostic, Severity};
use codespan_reporting::diagnostic::{Diagnostic as CsDiagnostic, Label, Severity as CsSeverity};
use codespan_reporting::files::{Files, SimpleFiles};
use codespan_reporting::term::{self, termcolor::WriteColor};
use serde::Serialize;
use serde_json::{json, Value};
use std::collections::HashMap;

/// Version of the JSON output shape; bumped on incompatible changes.
pub const JSON_VERSION: u32 = 1;

#[derive(Serialize)]
struct JsonDiagnostic<'a> {
    code: &'a str,
    severity: Severity,
    message: &'a str,
    file: &'a str,
    line: Option<u32>,
    column: Option<u32>,
    hint: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    related: Option<&'a crate::diagnostic::Related>,
}

/// The JSON document of a report.
pub fn to_json(report: &Report) -> Value {
    let diags: Vec<JsonDiagnostic> = report
        .diagnostics
        .iter()
        .map(|d| JsonDiagnostic {
            code: d.code,
            severity: d.severity,
            message: &d.message,
            file: &d.file,
            line: d.pos.map(|p| p.line),
            column: d.pos.map(|p| p.column),
            hint: d.hint.as_deref(),
            related: d.related.as_deref(),
        })
        .collect();
    json!({
        "version": JSON_VERSION,
        "diagnostics": diags,
        "summary": report.summary,
        "coverage": report.coverage,
    })
}

fn sarif_level(s: Severity) -> &'static str {
    match s {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info => "note",
    }
}

/// Percent-encodes a relative path for a SARIF `uri` (keeps `/`, unreserved characters and
/// sub-delimiters).
pub fn path_to_uri(path: &str) -> String {
    let path = path.replace('\\', "/");
    let mut out = String::with_capacity(path.len());
    for b in path.bytes() {
        // Unreserved characters and the sub-delimiters a path segment may hold as they are
        // (RFC 3986 §3.3: `lib+ext`, not `lib%2Bext`, which a reader may not match with the
        // file); `:` is encoded, as a first segment's colon would read as a scheme.
        if b.is_ascii_alphanumeric() || b"-._~/!$&'()*+,;=@".contains(&b) {
            out.push(b as char);
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// The SARIF 2.1.0 log of a report (for GitHub code scanning).
pub fn to_sarif(report: &Report) -> Value {
    let rules: Vec<Value> = registry::RULES
        .iter()
        .map(|r| {
            json!({
                "id": r.code,
                "name": r.name,
                "shortDescription": {"text": r.summary},
                "fullDescription": {"text": format!("{} (spec {})", r.explanation, r.spec)},
                "help": {"text": r.hint},
                "defaultConfiguration": {"level": sarif_level(r.severity)},
            })
        })
        .collect();
    let index: HashMap<&str, usize> = registry::RULES
        .iter()
        .enumerate()
        .map(|(i, r)| (r.code, i))
        .collect();
    let results: Vec<Value> = report
        .diagnostics
        .iter()
        .map(|d| {
            let mut physical = json!({"artifactLocation": {"uri": path_to_uri(&d.file)}});
            if let Some(p) = d.pos {
                physical["region"] = json!({"startLine": p.line, "startColumn": p.column.max(1)});
            }
            let text = match &d.hint {
                Some(h) => format!("{}\nhelp: {h}", d.message),
                None => d.message.clone(),
            };
            let mut r = json!({
                "ruleId": d.code,
                "level": sarif_level(d.severity),
                "message": {"text": text},
                "locations": [{"physicalLocation": physical}],
            });
            if let Some(i) = index.get(d.code) {
                r["ruleIndex"] = json!(i);
            }
            if let Some(rel) = &d.related {
                let mut physical = json!({"artifactLocation": {"uri": path_to_uri(&rel.file)}});
                if let Some(p) = rel.pos {
                    physical["region"] =
                        json!({"startLine": p.line, "startColumn": p.column.max(1)});
                }
                r["relatedLocations"] = json!([{
                    "id": 1,
                    "physicalLocation": physical,
                    "message": {"text": rel.message},
                }]);
            }
            r
        })
        .collect();
    json!({
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {
                "name": "rtcdoc",
                "version": env!("CARGO_PKG_VERSION"),
                "rules": rules,
            }},
            "results": results,
            // Columns count characters (Unicode code points), not UTF-16 units.
            "columnKind": "unicodeCodePoints",
        }],
    })
}

/// Byte range to underline for a 1-based line/column (columns count characters): the XML tag
/// name (`<rtc:DataPorts`), attribute name (`rtc:activityType`) or the YAML key / word starting
/// there. `None` when the position is
/// outside the text.
pub fn span_at(text: &str, line: u32, column: u32) -> Option<std::ops::Range<usize>> {
    let mut start = 0usize;
    for _ in 1..line {
        start += text[start..].find('\n')? + 1;
    }
    let line_text = &text[start..];
    let line_text = &line_text[..line_text.find('\n').unwrap_or(line_text.len())];
    let line_text = line_text.strip_suffix('\r').unwrap_or(line_text);
    let col_off = line_text
        .char_indices()
        .nth(column.saturating_sub(1) as usize)
        .map(|(i, _)| i)
        .unwrap_or(line_text.len());
    let rest = &line_text[col_off..];
    let len = if let Some(tag) = rest.strip_prefix('<') {
        1 + tag
            .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
            .unwrap_or(tag.len())
    } else {
        // A word: up to white space, `>`, an XML attribute's `=`, or a YAML key's `:` (one
        // followed by white space or the end; `rtc:activityType` is one attribute name).
        let b = rest.as_bytes();
        rest.char_indices()
            .find(|&(i, c)| {
                c.is_whitespace()
                    || c == '>'
                    || c == '='
                    || (c == ':' && b.get(i + 1).is_none_or(|n| n.is_ascii_whitespace()))
            })
            .map_or(rest.len(), |(i, _)| i)
    };
    let len = if len == 0 {
        rest.chars().next().map_or(0, char::len_utf8)
    } else {
        len
    };
    Some(start + col_off..start + col_off + len)
}

/// Which diagnostics the human output prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verbosity {
    /// Errors only.
    Quiet,
    /// Errors and warnings.
    Normal,
    /// Everything, infos included.
    Verbose,
}

impl Verbosity {
    fn shows(self, s: Severity) -> bool {
        match s {
            Severity::Error => true,
            Severity::Warning => self != Verbosity::Quiet,
            Severity::Info => self == Verbosity::Verbose,
        }
    }
}

/// Writes diagnostics like rustc: `severity[CODE]: message`, ` ┌─ file:line:col`, the source
/// line with a caret under the element, and `= help: hint`. `source` returns the text of a
/// file (by the name in the diagnostic), or `None` when it cannot be shown (the diagnostic is
/// then printed without a snippet).
/// Source lines longer than this (bytes) are not shown in snippets: far above the longest
/// line of the published profiles (781 bytes), it keeps a hostile one-line file with thousands
/// of findings from printing its whole line for each of them.
const MAX_SNIPPET_LINE: usize = 2000;

pub fn write_human(
    out: &mut dyn WriteColor,
    diagnostics: &[Diagnostic],
    verbosity: Verbosity,
    source: &mut dyn FnMut(&str) -> Option<String>,
) -> std::io::Result<()> {
    let mut files = SimpleFiles::new();
    let mut ids: HashMap<String, Option<usize>> = HashMap::new();
    let config = term::Config::default();
    for d in diagnostics.iter().filter(|d| verbosity.shows(d.severity)) {
        let sev = match d.severity {
            Severity::Error => CsSeverity::Error,
            Severity::Warning => CsSeverity::Warning,
            Severity::Info => CsSeverity::Note,
        };
        let mut cs = CsDiagnostic::new(sev)
            .with_code(d.code)
            .with_message(&d.message);
        let id = *ids
            .entry(d.file.clone())
            .or_insert_with(|| source(&d.file).map(|t| files.add(d.file.clone(), t)));
        let mut labelled = false;
        if let (Some(id), Some(p)) = (id, d.pos) {
            // The line comes from the file's line index; a line too long to show (a minified
            // or hostile file) gets no snippet, only the position in a note.
            let line = files
                .line_range(id, (p.line as usize).saturating_sub(1))
                .ok()
                .filter(|r| r.len() <= MAX_SNIPPET_LINE);
            if let Some(range) = line.and_then(|l| {
                let f = files.get(id).ok()?;
                let r = span_at(f.source().get(l.start..l.end)?, 1, p.column)?;
                Some(l.start + r.start..l.start + r.end)
            }) {
                cs = cs.with_labels(vec![Label::primary(id, range)]);
                labelled = true;
            }
        }
        let mut notes = Vec::new();
        if !labelled {
            notes.push(match d.pos {
                Some(p) => format!("in {}:{}:{}", d.file, p.line, p.column),
                None => format!("in {}", d.file),
            });
        }
        if let Some(r) = &d.related {
            notes.push(match r.pos {
                Some(p) => format!("{}: {}:{}:{}", r.message, r.file, p.line, p.column),
                None => format!("{}: {}", r.message, r.file),
            });
        }
        if let Some(h) = &d.hint {
            notes.push(format!("help: {h}"));
        }
        cs = cs.with_notes(notes);
        if d.severity == Severity::Info {
            // codespan calls its lowest severity `note`; rtcdoc's is `info`, as in the
            // summary line (`3 infos`), the JSON, `--explain` and `diff`: the header is
            // written aside and renamed (it comes first, before any text of the finding).
            let mut buf = if out.supports_color() {
                term::termcolor::Buffer::ansi()
            } else {
                term::termcolor::Buffer::no_color()
            };
            term::emit_to_write_style(&mut buf, &config, &files, &cs)
                .map_err(|e| std::io::Error::other(e.to_string()))?;
            out.write_all(&info_header(buf.into_inner()))?;
        } else {
            term::emit_to_write_style(out, &config, &files, &cs)
                .map_err(|e| std::io::Error::other(e.to_string()))?;
        }
    }
    Ok(())
}

/// A finding written by codespan as a `note[CODE]`, its header renamed `info[CODE]`.
fn info_header(mut text: Vec<u8>) -> Vec<u8> {
    if let Some(at) = text.windows(5).position(|w| w == b"note[") {
        text[at..at + 4].copy_from_slice(b"info");
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn infos_are_called_info_in_their_header() {
        let d = Diagnostic::info("RTC505", "a.xml", "action `onExecute` has no description");
        for color in [false, true] {
            let mut buf = if color {
                term::termcolor::Buffer::ansi()
            } else {
                term::termcolor::Buffer::no_color()
            };
            write_human(
                &mut buf,
                std::slice::from_ref(&d),
                Verbosity::Verbose,
                &mut |_| None,
            )
            .unwrap();
            let text = String::from_utf8(buf.into_inner()).unwrap();
            assert!(text.contains("info[RTC505]"), "{text:?}");
            assert!(!text.contains("note["), "{text:?}");
        }
    }

    #[test]
    fn long_lines_get_no_snippet() {
        use codespan_reporting::term::termcolor::NoColor;
        let long = format!("<a {}/>", "x=\"1\" ".repeat(500));
        let src = format!("<r>\n{long}\n</r>\n");
        let diags = vec![
            Diagnostic::warning("RTC006", "f.xml", "far right").at(crate::model::Pos::new(2, 9000)),
            Diagnostic::warning("RTC006", "f.xml", "short line").at(crate::model::Pos::new(1, 2)),
        ];
        let mut out = NoColor::new(Vec::new());
        write_human(&mut out, &diags, Verbosity::Normal, &mut |_| {
            Some(src.clone())
        })
        .expect("written");
        let text = String::from_utf8(out.into_inner()).expect("utf-8");
        assert!(
            !text.contains("x=\"1\" x=\"1\""),
            "the long line is not printed"
        );
        assert!(text.contains("in f.xml:2:9000"), "{text}");
        assert!(
            text.contains("1 │ <r>"),
            "short lines keep their snippet: {text}"
        );
    }

    #[test]
    fn spans() {
        let t = "<a>\n  <rtc:DataPorts rtc:name=\"x\"/>\nkey: value\n";
        assert_eq!(&t[span_at(t, 2, 3).unwrap()], "<rtc:DataPorts");
        assert_eq!(&t[span_at(t, 3, 1).unwrap()], "key");
        // An attribute: its whole name, namespace prefix included.
        assert_eq!(&t[span_at(t, 2, 18).unwrap()], "rtc:name");
        let y = "a:
  rtc:x: 1
url: http://h
";
        assert_eq!(&y[span_at(y, 1, 1).unwrap()], "a");
        assert_eq!(&y[span_at(y, 2, 3).unwrap()], "rtc:x");
        assert_eq!(span_at(t, 9, 1), None);
        assert!(span_at(t, 1, 99).is_some());
        let j = "名前: 値\n";
        assert_eq!(&j[span_at(j, 1, 1).unwrap()], "名前");
    }

    #[test]
    fn uris() {
        for (path, uri) in [
            ("a b/RTC.xml", "a%20b/RTC.xml"),
            ("x\\y.xml", "x/y.xml"),
            ("lib+ext/A (1)/RTC.xml", "lib+ext/A%20(1)/RTC.xml"),
            ("c:/x#?%.xml", "c%3A/x%23%3F%25.xml"),
            ("日本/RTC.xml", "%E6%97%A5%E6%9C%AC/RTC.xml"),
        ] {
            assert_eq!(path_to_uri(path), uri, "{path}");
        }
    }
}
