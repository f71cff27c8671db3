//! `rtcdoc diff` on the drift of a component's implementation (DIFF261, DIFF361, DIFF362,
//! DIFF363): a pull request that edits only the code (`tests/fixtures/diff-drift/{old,new}`,
//! one Python component whose profile is the same on both sides), code that appears and
//! disappears, a registration that can no longer be read, every output format, `--fail-on`,
//! and a git revision whose source files are read at that revision.

use crate::common;
use common::git;
use common::{root, rtcdoc, write};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The codes these tests exercise (`diff::every_code_from_a_one_edit_pair` counts them).
pub const CODES: [&str; 4] = ["DIFF261", "DIFF361", "DIFF362", "DIFF363"];

fn fixture() -> PathBuf {
    root().join("tests/fixtures/diff-drift")
}

fn run(dir: &Path, args: &[&str]) -> (i32, Value) {
    let mut all = vec!["diff"];
    all.extend_from_slice(args);
    all.extend(["--format", "json"]);
    let out = rtcdoc(&all, dir);
    let json: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code().expect("exit code"), json)
}

fn changes(json: &Value) -> Vec<&Value> {
    json["changes"]
        .as_array()
        .expect("changes")
        .iter()
        .collect()
}

/// `CODE path` of every change, in the output's order.
fn listed(json: &Value) -> Vec<String> {
    changes(json)
        .iter()
        .map(|c| {
            format!(
                "{} {}",
                c["code"].as_str().unwrap_or(""),
                c["path"].as_str().unwrap_or("")
            )
        })
        .collect()
}

fn find<'a>(json: &'a Value, code: &str, path: &str) -> &'a Value {
    changes(json)
        .into_iter()
        .find(|c| c["code"] == code && c["path"] == path)
        .unwrap_or_else(|| panic!("no {code} at {path}: {json:#}"))
}

fn status(dir: &Path, args: &[&str]) -> i32 {
    rtcdoc(args, dir).status.code().expect("exit code")
}

fn read(rel: &str) -> String {
    std::fs::read_to_string(fixture().join(rel)).expect("fixture")
}

const COMPONENT: &str = "RTC:Lab:Test:SensorGUI:1.0.0";
const NEW_CODE: &str = "new/SensorGUI/SensorGUI.py";

#[test]
fn a_pull_request_that_edits_only_the_code_is_caught() {
    // The profiles are the same file; only the code differs.
    assert_eq!(read("old/SensorGUI/RTC.xml"), read("new/SensorGUI/RTC.xml"));
    let d = fixture();
    let (code, json) = run(&d, &["old", "new"]);
    assert_eq!(code, 0, "nothing breaking: --fail-on breaking passes");
    // The spec array's stale version is drift on both sides (at another line in NEW): no change.
    assert_eq!(
        listed(&json),
        [
            "DIFF361 actions/onActivated",
            "DIFF261 configurationSet/scale/defaultValue",
            "DIFF261 dataPorts/distance_sensor",
            "DIFF261 dataPorts/ir_sensor",
        ],
        "{json:#}"
    );
    assert_eq!(json["summary"]["warning"], 3);
    assert_eq!(json["summary"]["info"], 1);
    assert_eq!(json["summary"]["components"]["changed"], 1);

    // Registered by the code only: at the registration in NEW's code.
    let c = find(&json, "DIFF261", "dataPorts/distance_sensor");
    assert_eq!(c["severity"], "warning");
    assert_eq!(c["name"], "drift-introduced");
    assert_eq!(c["component"], COMPONENT);
    assert_eq!(c["file"], NEW_CODE);
    assert_eq!(c["line"], 35);
    assert_eq!(c["column"], 14);
    assert_eq!(c["oldFile"], "old/SensorGUI/RTC.xml");
    assert_eq!(c["old"], Value::Null);
    assert_eq!(c["new"], "profile: — / code: DataInPort");
    assert_eq!(
        c["message"],
        "the code and the profile now disagree on `dataPorts/distance_sensor` (RTC802, registered by the code, not declared in the profile): the profile says nothing / the code says `DataInPort`; in NEW's code at `new/SensorGUI/SensorGUI.py:35`"
    );
    // Declared by the profile only: nothing in the code to point at, so the profile element.
    let c = find(&json, "DIFF261", "dataPorts/ir_sensor");
    assert_eq!(c["file"], "new/SensorGUI/RTC.xml");
    assert_eq!(c["line"], 15);
    let m = c["message"].as_str().unwrap_or("");
    assert!(
        m.contains("(RTC801, declared in the profile, not registered by the code): the profile says `DataInPort` / the code says nothing; NEW's code has nothing there (the profile at `new/SensorGUI/RTC.xml:15`)"),
        "{m}"
    );
    // Both sides' values.
    let c = find(&json, "DIFF261", "configurationSet/scale/defaultValue");
    assert!(
        c["message"]
            .as_str()
            .unwrap_or("")
            .contains("(RTC806, another default): the profile says `1.0` / the code says `2.0`; in NEW's code at `new/SensorGUI/SensorGUI.py:34`"),
        "{c:#}"
    );
    assert_eq!(c["new"], "profile: 1.0 / code: 2.0");
    // Resolved: where it was in OLD.
    let c = find(&json, "DIFF361", "actions/onActivated");
    assert_eq!(c["severity"], "info");
    assert_eq!(c["name"], "drift-resolved");
    assert_eq!(
        c["old"],
        "profile: implemented=\"false\" / code: implemented"
    );
    assert_eq!(c["new"], Value::Null);
    assert_eq!(c["file"], "new/SensorGUI/RTC.xml");
    assert_eq!(c["oldFile"], "old/SensorGUI/SensorGUI.py");
    assert_eq!(c["oldLine"], 40);
    assert!(
        c["message"]
            .as_str()
            .unwrap_or("")
            .starts_with("the code and the profile agree again on `actions/onActivated` (RTC807, "),
        "{c:#}"
    );

    // --fail-on: introduced drift is a warning.
    assert_eq!(
        status(&d, &["diff", "old", "new", "--fail-on", "warning"]),
        1
    );
    assert_eq!(status(&d, &["diff", "old", "new", "--fail-on", "never"]), 0);
    let (code, json) = run(&d, &["old", "new", "--fail-on", "warning"]);
    assert_eq!((code, &json["summary"]["failed"]), (1, &Value::Bool(true)));
}

#[test]
fn resolved_drift_alone_is_information() {
    // NEW is the generated code, which agrees with the profile.
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    write(d, "old/SensorGUI/RTC.xml", &read("new/SensorGUI/RTC.xml"));
    write(
        d,
        "old/SensorGUI/SensorGUI.py",
        &read("new/SensorGUI/SensorGUI.py"),
    );
    let generated = root().join("tests/fixtures/implementation/python-generated");
    for f in ["RTC.xml", "SensorGUI.py"] {
        let text = std::fs::read_to_string(generated.join(f)).expect("fixture");
        write(d, &format!("new/SensorGUI/{f}"), &text);
    }
    let (code, json) = run(d, &["old", "new", "--fail-on", "warning"]);
    assert_eq!(code, 0, "{json:#}");
    assert_eq!(
        listed(&json),
        [
            "DIFF361 basicInfo/version",
            "DIFF361 configurationSet/scale/defaultValue",
            "DIFF361 dataPorts/distance_sensor",
            "DIFF361 dataPorts/ir_sensor",
        ],
        "{json:#}"
    );
    assert!(changes(&json).iter().all(|c| c["severity"] == "info"
        && c["message"]
            .as_str()
            .unwrap_or("")
            .starts_with("the code and the profile agree again on ")));
    assert_eq!(status(d, &["diff", "old", "new", "--fail-on", "info"]), 1);
}

#[test]
fn a_registration_that_can_no_longer_be_read_is_not_a_resolution() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let code = read("new/SensorGUI/SensorGUI.py");
    // The port's name is its constructor's (the one OpenRTM's PortBase runs under).
    let dynamic = code.replace(
        "OpenRTM_aist.InPort(\"distance_sensor\", self._d_ir_sensor)",
        "OpenRTM_aist.InPort(self._port_name, self._d_ir_sensor)",
    );
    assert_ne!(code, dynamic);
    for (side, text) in [("old", &code), ("new", &dynamic)] {
        write(
            d,
            &format!("{side}/SensorGUI/RTC.xml"),
            &read("new/SensorGUI/RTC.xml"),
        );
        write(d, &format!("{side}/SensorGUI/SensorGUI.py"), text);
    }
    let (_, json) = run(d, &["old", "new"]);
    assert_eq!(
        listed(&json),
        [
            "DIFF361 dataPorts/distance_sensor",
            "DIFF361 dataPorts/ir_sensor"
        ],
        "{json:#}"
    );
    for c in changes(&json) {
        let m = c["message"].as_str().unwrap_or("");
        assert!(
            m.contains("is no longer found, but not verified either: NEW's code registers")
                && m.contains("through a name or macro that cannot be read (RTC810)")
                && !m.contains("agree again"),
            "{m}"
        );
    }
}

#[test]
fn code_that_appears_or_disappears_is_information_and_its_new_drift_a_warning() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let profile = read("new/SensorGUI/RTC.xml");
    write(d, "bare/SensorGUI/RTC.xml", &profile);
    write(d, "coded/SensorGUI/RTC.xml", &profile);
    write(
        d,
        "coded/SensorGUI/SensorGUI.py",
        &read("new/SensorGUI/SensorGUI.py"),
    );

    // Code added: DIFF362, and what it disagrees with the profile on is new drift.
    let (code, json) = run(d, &["bare", "coded", "--fail-on", "warning"]);
    assert_eq!(code, 1);
    assert_eq!(
        listed(&json),
        [
            "DIFF362 ",
            "DIFF261 basicInfo/version",
            "DIFF261 configurationSet/scale/defaultValue",
            "DIFF261 dataPorts/distance_sensor",
            "DIFF261 dataPorts/ir_sensor",
        ],
        "{json:#}"
    );
    let c = find(&json, "DIFF362", "");
    assert_eq!(c["severity"], "info");
    assert_eq!(c["new"], "Python: coded/SensorGUI/SensorGUI.py");
    assert_eq!(c["file"], "coded/SensorGUI/SensorGUI.py");
    assert_eq!(
        c["message"],
        "NEW has code for the component that OLD has not (Python: coded/SensorGUI/SensorGUI.py); 4 drift findings in it, each reported as DIFF261"
    );

    // Code removed: DIFF363 only; the findings are not resolved, only no longer compared.
    let (code, json) = run(d, &["coded", "bare", "--fail-on", "warning"]);
    assert_eq!(code, 0, "{json:#}");
    assert_eq!(listed(&json), ["DIFF363 "], "{json:#}");
    let c = find(&json, "DIFF363", "");
    assert_eq!(c["severity"], "info");
    assert_eq!(c["old"], "Python: coded/SensorGUI/SensorGUI.py");
    assert_eq!(c["oldFile"], "coded/SensorGUI/SensorGUI.py");
    assert!(
        c["message"]
            .as_str()
            .unwrap_or("")
            .ends_with("its 4 drift findings are not resolved, only no longer compared"),
        "{c:#}"
    );

    // The same code on both sides: nothing.
    let (code, json) = run(d, &["coded", "coded"]);
    assert_eq!((code, listed(&json)), (0, Vec::<String>::new()));
}

#[test]
fn every_format_carries_drift() {
    let d = fixture();
    let text = |args: &[&str]| {
        let out = rtcdoc(args, &d);
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let human = text(&["diff", "old", "new"]);
    assert!(
        human.contains(
            "  warning[DIFF261] dataPorts/distance_sensor: the code and the profile now disagree"
        ),
        "{human}"
    );
    assert!(
        human.contains("      --> new/SensorGUI/SensorGUI.py:35:14"),
        "{human}"
    );
    // A resolved finding points where it was in OLD.
    assert!(
        human.contains("  info[DIFF361] actions/onActivated: "),
        "{human}"
    );
    assert!(
        human.contains("      --> old/SensorGUI/SensorGUI.py:40:9"),
        "{human}"
    );
    assert!(human.contains("0 breaking, 3 warnings, 1 info in 1 of 1 matched component(s)"));

    let md = text(&["diff", "old", "new", "--format", "markdown"]);
    assert!(
        md.contains("| 🟡 warning | DIFF261 `drift-introduced` | `dataPorts/distance_sensor` | — | `profile: — / code: DataInPort` |"),
        "{md}"
    );
    assert!(
        md.contains(
            "- DIFF361 `actions/onActivated` drift-resolved — the code and the profile agree again"
        ),
        "{md}"
    );

    let gh = text(&["diff", "old", "new", "--format", "github"]);
    assert!(
        gh.lines().any(|l| l.starts_with(
            "::warning file=new/SensorGUI/SensorGUI.py,line=35,col=14,title=DIFF261 drift-introduced::RTC:Lab:Test:SensorGUI:1.0.0 dataPorts/distance_sensor: "
        )),
        "{gh}"
    );
    assert!(
        gh.lines()
            .any(|l| l
                .starts_with("::notice file=new/SensorGUI/RTC.xml,title=DIFF361 drift-resolved::")),
        "{gh}"
    );

    for (code, level, name) in [
        ("DIFF261", "warning", "drift-introduced"),
        ("DIFF361", "info", "drift-resolved"),
        ("drift-introduced", "warning", "drift-introduced"),
        ("DIFF362", "info", "implementation-added"),
        ("DIFF363", "info", "implementation-removed"),
    ] {
        let e = text(&["diff", "--explain", code]);
        assert!(
            e.contains(name) && e.contains(&format!("Severity: {level}")),
            "{e}"
        );
    }
}

/// A `REV:PATH` side reads the source files at that revision: the code-only edit of the
/// fixture, committed, gives the same changes as the two folders (and no DIFF362, which it
/// would be if the revision had been read without its code).
#[test]
fn a_git_revision_reads_its_source_files() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    if !git(d, &["--version"]) {
        crate::common::missing_tool("git not available");
        return;
    }
    assert!(git(d, &["init", "-q"]));
    assert!(git(d, &["config", "user.name", "Test"]));
    assert!(git(d, &["config", "user.email", "test@example.org"]));
    // The code padded at its end (no line moves) to be larger than its profile, for the
    // size limit below.
    let padded = |rel: &str| format!("{}# {}\n", read(rel), "-".repeat(1_000));
    write(d, "comps/SensorGUI/RTC.xml", &read("old/SensorGUI/RTC.xml"));
    write(
        d,
        "comps/SensorGUI/SensorGUI.py",
        &padded("old/SensorGUI/SensorGUI.py"),
    );
    // A file of another folder without a profile: not needed, not copied (nothing reads it).
    write(d, "tools/SensorGUI.py", "raise SystemExit\n");
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "first"]));
    write(
        d,
        "comps/SensorGUI/SensorGUI.py",
        &padded("new/SensorGUI/SensorGUI.py"),
    );
    let expected = [
        "DIFF361 actions/onActivated",
        "DIFF261 configurationSet/scale/defaultValue",
        "DIFF261 dataPorts/distance_sensor",
        "DIFF261 dataPorts/ir_sensor",
    ];

    // The revision against the work tree.
    let (code, json) = run(d, &["HEAD:comps", "comps", "--fail-on", "warning"]);
    assert_eq!(code, 1);
    assert_eq!(listed(&json), expected, "{json:#}");
    let c = find(&json, "DIFF361", "actions/onActivated");
    assert_eq!(c["oldFile"], "comps/SensorGUI/SensorGUI.py");
    assert_eq!(c["oldLine"], 40);

    // Two revisions: NEW's code is read at its revision too, and its place named in the repository.
    assert!(git(d, &["commit", "-q", "-am", "code only"]));
    let (code, json) = run(d, &["HEAD~1:comps", "HEAD:comps", "--fail-on", "warning"]);
    assert_eq!(code, 1);
    assert_eq!(listed(&json), expected, "{json:#}");
    let c = find(&json, "DIFF261", "dataPorts/distance_sensor");
    assert_eq!(c["file"], "comps/SensorGUI/SensorGUI.py");
    assert_eq!(c["line"], 35);
    let out = rtcdoc(&["diff", "HEAD~1:comps", "HEAD:comps"], d);
    let human = String::from_utf8_lossy(&out.stdout);
    assert!(
        human.contains("--> HEAD:comps/SensorGUI/SensorGUI.py:35:14")
            && human.contains("--> HEAD~1:comps/SensorGUI/SensorGUI.py:40:9"),
        "{human}"
    );
    // The whole tree, and a revision against itself: the same code, nothing.
    let (_, json) = run(d, &["HEAD~1:", "HEAD:"]);
    assert_eq!(listed(&json), expected, "{json:#}");
    let (code, json) = run(d, &["HEAD:comps", "comps"]);
    assert_eq!((code, listed(&json)), (0, Vec::<String>::new()));

    // A source file over --max-file-size is cut as on disk: not read on either side.
    let (_, json) = run(
        d,
        &["HEAD~1:comps", "HEAD:comps", "--max-file-size", "2500"],
    );
    assert_eq!(listed(&json), Vec::<String>::new(), "{json:#}");
    let out = rtcdoc(
        &[
            "check",
            "comps",
            "--max-file-size",
            "2500",
            "--format",
            "json",
        ],
        d,
    );
    let check = String::from_utf8_lossy(&out.stdout);
    assert!(
        check.contains("\"RTC811\"") && !check.contains("\"RTC806\""),
        "the limit leaves the code unread on disk too: {check}"
    );
}
