//! `rtcdoc diff` on sides that hold only IDL (issue #55): folders, single `.idl` files and
//! `REV:PATH` of git, on the pair `tests/fixtures/diff/idl-only/{old,new}/idl/Lab.idl`, whose
//! types no profile uses. Every change is classified as the history of an IDL file classifies
//! it, located in the IDL files, and a breaking one fails the diff.

use crate::common;
use common::OutputWithin;
use common::{root, rtcdoc, write};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    root().join("tests/fixtures/diff/idl-only")
}

fn run(dir: &Path, args: &[&str]) -> (i32, Value, String) {
    let mut all = vec!["diff"];
    all.extend_from_slice(args);
    all.extend(["--format", "json"]);
    let out = rtcdoc(&all, dir);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    let json: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\n{stderr}",
            String::from_utf8_lossy(&out.stdout)
        )
    });
    (out.status.code().expect("exit code"), json, stderr)
}

fn changes(json: &Value) -> &Vec<Value> {
    json["changes"].as_array().expect("changes")
}

/// (code, path) of every change, sorted.
fn coded(json: &Value) -> Vec<(String, String)> {
    let mut v: Vec<(String, String)> = changes(json)
        .iter()
        .map(|c| {
            (
                c["code"].as_str().unwrap_or("").to_string(),
                c["path"].as_str().unwrap_or("").to_string(),
            )
        })
        .collect();
    v.sort();
    v
}

/// What the fixture pair changes, each change once per definition that holds it (Pose's
/// member is gone from `Lab::Pose` and from the parameter of `Lab::Nav::go`).
const EXPECTED: &[(&str, &str)] = &[
    ("DIFF131", "idl/Lab::Busy/fields/code"),
    // Once, at `Lab::Pose` itself: not again inside `Lab::Nav`'s `go(in Pose p)`.
    ("DIFF132", "idl/Lab::Pose/fields/heading"),
    ("DIFF137", "idl/Lab::Path"),
    ("DIFF139", "idl/Lab::Nav/operations/stop"),
    ("DIFF140", "idl/Lab::Gone"),
    ("DIFF231", "idl/Lab::Mode/values/STOP"),
    ("DIFF232", "idl/Lab::Nav/operations/status"),
    ("DIFF308", "idl/Lab::MAX_SPEED"),
    ("DIFF308", "idl/Lab::Nav/bases"),
    ("DIFF334", "idl/Lab::Added"),
    ("DIFF334", "idl/Lab::Other"),
];

fn expected() -> Vec<(String, String)> {
    EXPECTED
        .iter()
        .map(|(c, p)| (c.to_string(), p.to_string()))
        .collect()
}

/// The line (1-based) of the first line of `file` containing `text`.
fn line_of(file: &Path, text: &str) -> u64 {
    let body = std::fs::read_to_string(file).expect("fixture");
    body.lines()
        .position(|l| l.contains(text))
        .map(|i| i as u64 + 1)
        .unwrap_or_else(|| panic!("`{text}` not in {}", file.display()))
}

fn the<'a>(json: &'a Value, code: &str, path: &str) -> &'a Value {
    changes(json)
        .iter()
        .find(|c| c["code"] == code && c["path"] == path)
        .unwrap_or_else(|| panic!("no {code} at {path}: {json:#}"))
}

#[test]
fn two_idl_folders_are_compared_type_by_type() {
    let dir = fixture();
    let (exit, json, stderr) = run(&dir, &["old", "new"]);
    assert_eq!(exit, 1, "a breaking change fails: {json:#}\n{stderr}");
    assert_eq!(coded(&json), expected(), "{json:#}");
    assert_eq!(json["summary"]["breaking"], 5, "{json:#}");
    let idl = &json["summary"]["idl"];
    assert_eq!(
        (
            &idl["old"],
            &idl["new"],
            &idl["matched"],
            &idl["changed"],
            &idl["added"],
            &idl["removed"]
        ),
        (
            &Value::from(8),
            &Value::from(9),
            &Value::from(7),
            &Value::from(6),
            &Value::from(2),
            &Value::from(1)
        ),
        "{json:#}"
    );
    // Located in the IDL files: an added operation at its line in NEW, a removed member at
    // its line in OLD (its struct in NEW), a removed type at its line in OLD.
    let (old, new) = (dir.join("old/idl/Lab.idl"), dir.join("new/idl/Lab.idl"));
    let c = the(&json, "DIFF232", "idl/Lab::Nav/operations/status");
    assert_eq!(c["file"], "new/idl/Lab.idl");
    assert_eq!(c["line"], line_of(&new, "long status();"), "{c:#}");
    assert_eq!(c["component"], "new/idl/Lab.idl");
    let c = the(&json, "DIFF132", "idl/Lab::Pose/fields/heading");
    assert_eq!(c["oldFile"], "old/idl/Lab.idl");
    assert_eq!(c["oldLine"], line_of(&old, "double heading;"), "{c:#}");
    assert_eq!(c["line"], line_of(&new, "struct Pose"), "{c:#}");
    let c = the(&json, "DIFF140", "idl/Lab::Gone");
    assert_eq!(c["oldLine"], line_of(&old, "struct Gone"), "{c:#}");
    let c = the(&json, "DIFF139", "idl/Lab::Nav/operations/stop");
    assert_eq!(c["line"], line_of(&new, "void stop("), "{c:#}");

    // The human report lists them, with the file:line, and does not say that nothing changed.
    let out = rtcdoc(&["diff", "old", "new"], &dir);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("breaking[DIFF132] idl/Lab::Pose/fields/heading"),
        "{text}"
    );
    assert!(
        text.contains(&format!(
            "--> new/idl/Lab.idl:{}:",
            line_of(&new, "long status();")
        )),
        "{text}"
    );
    assert!(
        text.contains("5 breaking, 2 warnings, 4 infos in 0 of 0 matched component(s); 0 added, 0 removed; 6 of 7 matched IDL definition(s) changed, 2 added, 1 removed"),
        "{text}"
    );
    // --fail-on never: the same changes, exit 0.
    let (exit, json, _) = run(&dir, &["old", "new", "--fail-on", "never"]);
    assert_eq!((exit, coded(&json)), (0, expected()));
}

/// The changes are the ones the history of the IDL file gives for the same two versions:
/// one classification ([`rtcdoc::diff::compare_idl_files`]).
#[test]
fn the_diff_and_the_history_of_an_idl_file_agree() {
    let read = |side: &str| {
        let path = fixture().join(side).join("idl/Lab.idl");
        let bytes = std::fs::read(&path).expect("fixture");
        rtcdoc::idl::read(
            &[rtcdoc::idl::SourceFile::new("idl/Lab.idl", bytes)],
            &Default::default(),
        )
    };
    let history = rtcdoc::diff::compare_idl_files(&read("old"), &read("new"), "idl/Lab.idl");
    let mut from_history: Vec<(String, String)> = history
        .iter()
        .map(|c| (c.code.to_string(), c.path.clone()))
        .collect();
    from_history.sort();
    assert_eq!(from_history, expected());
    let (_, json, _) = run(&fixture(), &["old", "new"]);
    for c in &history {
        let d = the(&json, c.code, &c.path);
        assert_eq!(d["severity"], c.severity.to_string(), "{d:#}");
        assert_eq!(d["line"].as_u64(), c.line.map(u64::from), "{d:#}");
    }
}

#[test]
fn two_idl_files_are_a_pair_of_sides() {
    let dir = fixture();
    let (exit, json, stderr) = run(&dir, &["old/idl/Lab.idl", "new/idl/Lab.idl"]);
    assert_eq!(exit, 1, "{stderr}");
    assert_eq!(coded(&json), expected(), "{json:#}");
    assert_eq!(
        the(&json, "DIFF232", "idl/Lab::Nav/operations/status")["file"],
        "new/idl/Lab.idl"
    );
    // The same file on both sides: nothing changed.
    let (exit, json, _) = run(&dir, &["new/idl/Lab.idl", "new/idl/Lab.idl"]);
    assert_eq!((exit, coded(&json)), (0, Vec::new()));
}

fn git(dir: &Path, args: &[&str]) -> bool {
    std::process::Command::new("git")
        .args(args)
        .current_dir(dir)
        .env("GIT_CONFIG_NOSYSTEM", "1")
        .env("HOME", dir)
        .env("GIT_AUTHOR_NAME", "t")
        .env("GIT_AUTHOR_EMAIL", "t@example.com")
        .env("GIT_COMMITTER_NAME", "t")
        .env("GIT_COMMITTER_EMAIL", "t@example.com")
        .output_within(common::COMMAND_LIMIT)
        .map(|o| o.status.success())
        .unwrap_or(false)
}

/// A repository whose two commits hold OLD's and NEW's `idl/Lab.idl` (the second titled
/// "this breaks IDL"), and a text file that is neither a profile nor IDL.
fn repository() -> Option<tempfile::TempDir> {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    if !git(d, &["init", "-q"]) {
        println!("skipped: git not available");
        return None;
    }
    for (side, title) in [("old", "first"), ("new", "this breaks IDL")] {
        let text =
            std::fs::read_to_string(fixture().join(side).join("idl/Lab.idl")).expect("fixture");
        write(d, "idl/Lab.idl", &text);
        write(d, "notes/readme.txt", "not IDL {\n");
        assert!(git(d, &["add", "-A"]));
        assert!(git(d, &["commit", "-q", "-m", title]));
    }
    Some(dir)
}

#[test]
fn revisions_of_an_idl_folder_and_file_are_compared() {
    let Some(dir) = repository() else { return };
    let d = dir.path();
    for (old, new) in [
        ("HEAD~1:idl", "HEAD:idl"),
        ("HEAD~1:idl", "idl"),
        ("HEAD~1:idl/Lab.idl", "HEAD:idl/Lab.idl"),
        ("HEAD~1:idl/Lab.idl", "idl/Lab.idl"),
    ] {
        let (exit, json, stderr) = run(d, &[old, new]);
        assert_eq!(exit, 1, "{old} {new}: {stderr}");
        assert_eq!(coded(&json), expected(), "{old} {new}: {json:#}");
        let c = the(&json, "DIFF132", "idl/Lab::Pose/fields/heading");
        assert_eq!(c["oldFile"], "idl/Lab.idl", "{old} {new}: {c:#}");
        assert_eq!(c["file"], "idl/Lab.idl", "{old} {new}: {c:#}");
    }
    // Human output names the files as git opens them.
    let out = rtcdoc(&["diff", "HEAD~1:idl", "HEAD:idl"], d);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("--> HEAD~1:idl/Lab.idl:"), "{text}");
    assert!(text.contains("--> HEAD:idl/Lab.idl:"), "{text}");
}

#[test]
fn messages_about_a_revision_name_it_as_typed() {
    let Some(dir) = repository() else { return };
    let d = dir.path();
    for (args, said) in [
        (
            ["HEAD:notes/readme.txt", "idl"],
            "OLD `HEAD:notes/readme.txt`: `HEAD:notes/readme.txt` is neither XML nor YAML",
        ),
        (
            ["idl", "HEAD:notes"],
            "NEW `HEAD:notes`: nothing to document",
        ),
        (
            ["HEAD:idl", "HEAD~7:idl"],
            "NEW `HEAD~7:idl`: git cannot find it",
        ),
    ] {
        let out = rtcdoc(&["diff", args[0], args[1]], d);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(said), "{args:?}: {err}");
        assert!(!err.contains("rtcdoc-diff-"), "{args:?}: {err}");
        assert!(
            !err.contains(&std::env::temp_dir().to_string_lossy().to_string()),
            "{args:?}: {err}"
        );
    }
}

/// Beside profiles, a type no port carries is compared on its own, and a type a port carries
/// (or one it holds) is reported with the port only, not again on its own.
#[test]
fn beside_profiles_types_no_port_carries_are_compared_too() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let from = root().join("tests/fixtures/diff/DIFF131");
    for side in ["old", "new"] {
        let profile =
            std::fs::read_to_string(from.join(side).join("Nav/RTC.xml")).expect("fixture");
        write(d, &format!("{side}/Nav/RTC.xml"), &profile);
        let idl = std::fs::read_to_string(from.join(side).join("idl/Nav.idl")).expect("fixture");
        let extra = if side == "new" { "void flush(); " } else { "" };
        write(
            d,
            &format!("{side}/idl/Nav.idl"),
            &format!(
                "{idl}\nmodule Nav {{ interface Logger {{ void log(in string s); {extra}}}; }};\n"
            ),
        );
    }
    let (exit, json, stderr) = run(d, &["old", "new"]);
    assert_eq!(exit, 1, "{stderr}");
    let paths: Vec<(String, String)> = coded(&json);
    assert!(
        paths.contains(&(
            "DIFF131".into(),
            "dataPorts/odometry/type/fields/speed".into()
        )),
        "{json:#}"
    );
    assert!(
        paths.contains(&("DIFF232".into(), "idl/Nav::Logger/operations/flush".into())),
        "{json:#}"
    );
    assert!(
        !paths
            .iter()
            .any(|(_, p)| p.starts_with("idl/Nav::TimedOdometry")),
        "reported with the port only: {json:#}"
    );
    assert_eq!(json["summary"]["idl"]["changed"], 2, "{json:#}");
}
