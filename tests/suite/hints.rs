//! A hint that tells the user what to do must work when followed: every configuration key and
//! every flag a hint names exists. Hints live in the rule registry and in the code that makes
//! diagnostics and errors (`with_hint("…")`); both are read here.

use crate::common;
use common::*;
use std::collections::BTreeSet;

/// The string literals of the hints written in the source: the literal arguments of
/// `with_hint(` and `hint:` fields (a `format!` hint: its format string).
fn source_hints() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for entry in walkdir::WalkDir::new(root().join("src")) {
        let entry = entry.unwrap();
        if entry.path().extension().and_then(|e| e.to_str()) != Some("rs") {
            continue;
        }
        let text = std::fs::read_to_string(entry.path()).unwrap();
        let rel = entry
            .path()
            .strip_prefix(root())
            .unwrap()
            .display()
            .to_string();
        for marker in ["with_hint(", "hint:", "let hint ="] {
            for (at, _) in text.match_indices(marker) {
                // The first string literal within the next 200 bytes.
                let rest = &text[at..text.len().min(at + 400)];
                if let Some(q) = rest.find('"') {
                    let lit = &rest[q + 1..];
                    let mut end = 0;
                    let b = lit.as_bytes();
                    while end < b.len() && !(b[end] == b'"' && (end == 0 || b[end - 1] != b'\\')) {
                        end += 1;
                    }
                    out.push((rel.clone(), lit[..end].to_string()));
                }
            }
        }
    }
    out
}

/// Every long flag some subcommand accepts (from `--help`).
fn flags() -> BTreeSet<String> {
    let mut all = BTreeSet::new();
    let dir = tempfile::tempdir().unwrap();
    for cmd in ["build", "check", "diff", "serve", "init"] {
        let o = rtcdoc(&[cmd, "--help"], dir.path());
        let text = String::from_utf8_lossy(&o.stdout).into_owned();
        for w in text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-')) {
            if w.starts_with("--") && w.len() > 2 {
                all.insert(w.to_string());
            }
        }
    }
    all
}

/// Every key of `rtcdoc.toml` (the commented template `rtcdoc init` writes lists them all).
fn config_keys() -> BTreeSet<String> {
    rtcdoc::config::template()
        .lines()
        .filter_map(|l| l.trim_start_matches('#').trim().split_once(" = "))
        .map(|(k, _)| k.trim().to_string())
        .filter(|k| !k.contains(' '))
        .collect()
}

#[test]
fn every_flag_and_configuration_key_a_hint_names_exists() {
    let mut hints: Vec<(String, String)> = source_hints();
    hints.extend(
        rtcdoc::check::RULES
            .iter()
            .map(|r| (format!("rule {}", r.code), r.hint.to_string())),
    );
    // The diff codes' explanations say what to do too.
    hints.extend(
        rtcdoc::diff::codes::CODES
            .iter()
            .map(|c| (format!("diff code {}", c.code), c.explanation.to_string())),
    );
    assert!(hints.len() > 150, "only {} hints found", hints.len());
    let flags = flags();
    assert!(flags.contains("--max-file-size") && flags.contains("--idl-path"));
    let keys = config_keys();
    assert!(keys.contains("max-file-size") && keys.contains("show-host-data"));
    let mut bad = Vec::new();
    for (at, hint) in &hints {
        for w in hint.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_')) {
            if let Some(flag) = w.strip_prefix("--") {
                if !flag.is_empty() && !flags.contains(w) {
                    bad.push(format!("{at}: flag {w} does not exist: {hint}"));
                }
            }
        }
        // A key named with rtcdoc.toml: in backticks, or as `key = value`.
        if hint.contains("rtcdoc.toml") {
            let quoted = hint.split('`').skip(1).step_by(2);
            let assigned = hint
                .split(" = ")
                .next()
                .filter(|_| hint.contains(" = "))
                .and_then(|s| s.split_whitespace().last());
            for k in quoted.chain(assigned) {
                let k = k.split(" = ").next().unwrap_or(k);
                if k.chars()
                    .all(|c| c.is_ascii_lowercase() || c == '-' || c == '_')
                    && !keys.contains(k)
                {
                    bad.push(format!("{at}: rtcdoc.toml has no key `{k}`: {hint}"));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// Following the size hint works: the key it names is accepted and lets the file through.
#[test]
fn the_size_hint_works_when_followed() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(&input, "c/RTC.xml", &xml_profile("c", &[]));
    let o = rtcdoc(&["check", "in", "--max-file-size", "100"], dir.path());
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(
        err.contains("raise `max-file-size` in rtcdoc.toml or pass --max-file-size BYTES"),
        "{err}"
    );
    write(dir.path(), "in/rtcdoc.toml", "max-file-size = 100\n");
    let o = rtcdoc(&["check", "in"], dir.path());
    assert!(String::from_utf8_lossy(&o.stderr).contains("RTC002"));
    write(dir.path(), "in/rtcdoc.toml", "max-file-size = 100000\n");
    let o = rtcdoc(&["check", "in"], dir.path());
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(o.status.success() && !err.contains("RTC002"), "{err}");
}

/// Following RTC404's hint works: the file it names defines the type, and an `idlFile` that
/// names it is neither RTC404 nor RTC405.
#[test]
fn the_idl_file_hint_works_when_followed() {
    let dir = tempfile::tempdir().unwrap();
    let fixture =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/check/RTC404-bad");
    let profile = std::fs::read_to_string(fixture.join("A.xml")).unwrap();
    write(dir.path(), "in/A.xml", &profile);
    write(
        dir.path(),
        "in/idl/Lab.idl",
        &std::fs::read_to_string(fixture.join("idl/Lab.idl")).unwrap(),
    );
    let codes_and_hints = |d: &std::path::Path| -> Vec<(String, String)> {
        common::findings(d, "in", &["RTC404", "RTC405"])
            .iter()
            .map(|f| {
                let s = |k: &str| f[k].as_str().unwrap_or_default().to_string();
                (s("code"), s("hint"))
            })
            .collect()
    };
    let found = codes_and_hints(dir.path());
    assert_eq!(found.len(), 1, "{found:?}");
    let hint = &found[0].1;
    let named = hint
        .strip_prefix("make `idlFile` name `")
        .and_then(|h| h.split_once('`'))
        .map(|(n, _)| n)
        .unwrap_or_else(|| panic!("the hint names a file: {hint}"));
    assert_eq!(named, "Lab.idl", "{hint}");
    write(
        dir.path(),
        "in/A.xml",
        &profile.replace(
            "/home/me/idl/LabTypes.idl",
            &format!("/home/me/idl/{named}"),
        ),
    );
    assert_eq!(codes_and_hints(dir.path()), Vec::new());
}
