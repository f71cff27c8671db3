//! Gating pull requests with `rtcdoc diff`: the `[diff]` policy of rtcdoc.toml (each key on the
//! fixture pair `tests/fixtures/diff-gate/{old,new}`, and its mistakes), the baseline of
//! accepted changes (accepted, stale, a new breaking change failing, a reason required,
//! `--write-baseline` keeping the reasons) in every output format, and `--since REV`.
//!
//! The pair: `Nav` loses its port `cmd` (DIFF102) and its `odometry` carries another type
//! (DIFF104); `components/Legacy/Odo` flips its port `ticks` (DIFF103), changes a default
//! (DIFF201) and its description (DIFF307); neither raises its version (DIFF208 twice).

use crate::common;
use common::git;
use common::{root, rtcdoc, write};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    root().join("tests/fixtures/diff-gate")
}

/// `rtcdoc diff old new ARGS --format json` in the fixture folder: the exit status and the
/// document.
fn run(args: &[&str]) -> (i32, Value) {
    run_in(&fixture(), &[&["diff", "old", "new"], args].concat())
}

fn run_in(dir: &Path, args: &[&str]) -> (i32, Value) {
    let mut all = args.to_vec();
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

/// `(code, severity, status)` of every change, sorted.
fn standings(json: &Value) -> Vec<(String, String, String)> {
    let s = |c: &Value, k: &str| c[k].as_str().unwrap_or("").to_string();
    let mut v: Vec<(String, String, String)> = json["changes"]
        .as_array()
        .expect("changes")
        .iter()
        .map(|c| (s(c, "code"), s(c, "severity"), s(c, "status")))
        .collect();
    v.sort();
    v
}

fn row(code: &str, severity: &str, status: &str) -> (String, String, String) {
    (code.into(), severity.into(), status.into())
}

/// `[breaking, warning, info, accepted, ignored, stale]` of the summary.
fn counts(json: &Value) -> [u64; 6] {
    [
        "breaking", "warning", "info", "accepted", "ignored", "stale",
    ]
    .map(|k| json["summary"][k].as_u64().unwrap_or(u64::MAX))
}

#[test]
fn without_a_policy_or_baseline_every_change_counts() {
    let (code, json) = run(&[]);
    assert_eq!(code, 1);
    assert_eq!(counts(&json), [3, 3, 1, 0, 0, 0]);
    assert!(standings(&json).iter().all(|(_, _, s)| s.is_empty()));
    assert_eq!(json["baseline"], Value::Null);
    assert_eq!(json["stale"], serde_json::json!([]));
}

#[test]
fn ignore_drops_codes_and_categories_from_the_counts_but_not_from_the_list() {
    let (code, json) = run(&["--config", "policy/ignore.toml"]);
    assert_eq!(code, 1, "the breaking changes still fail");
    assert_eq!(counts(&json), [3, 0, 0, 0, 4, 0]);
    assert_eq!(
        standings(&json),
        [
            row("DIFF102", "breaking", ""),
            row("DIFF103", "breaking", ""),
            row("DIFF104", "breaking", ""),
            row("DIFF201", "warning", "ignored"),
            row("DIFF208", "warning", "ignored"),
            row("DIFF208", "warning", "ignored"),
            row("DIFF307", "info", "ignored"),
        ]
    );
    // byCode counts what counts.
    assert_eq!(json["summary"]["byCode"].as_object().unwrap().len(), 3);
    // --fail-on warning: the ignored warnings do not fail.
    let (_, json) = run(&["--config", "policy/ignore.toml", "--fail-on", "info"]);
    assert_eq!(json["summary"]["failed"], true);
}

#[test]
fn except_takes_a_code_back_out_of_an_ignored_category() {
    let (_, json) = run(&["--config", "policy/except.toml"]);
    assert_eq!(counts(&json), [3, 1, 1, 0, 2, 0]);
    let s = standings(&json);
    assert!(s.contains(&row("DIFF201", "warning", "")), "{s:?}");
    assert!(s.contains(&row("DIFF208", "warning", "ignored")), "{s:?}");
}

#[test]
fn ignore_only_ignores_a_code_in_the_files_its_globs_match() {
    let (code, json) = run(&["--config", "policy/ignore-only.toml"]);
    assert_eq!(code, 1);
    let s = standings(&json);
    // Legacy's DIFF103 is ignored; Nav's DIFF104 is not below components/Legacy.
    assert!(s.contains(&row("DIFF103", "breaking", "ignored")), "{s:?}");
    assert!(s.contains(&row("DIFF104", "breaking", "")), "{s:?}");
    assert_eq!(counts(&json), [2, 3, 1, 0, 1, 0]);
    // The globs are relative to the input, wherever it is: from the repository root too.
    let (_, json) = run_in(
        &root(),
        &[
            "diff",
            "tests/fixtures/diff-gate/old",
            "tests/fixtures/diff-gate/new",
            "--config",
            "tests/fixtures/diff-gate/policy/ignore-only.toml",
        ],
    );
    assert_eq!(counts(&json), [2, 3, 1, 0, 1, 0]);
}

#[test]
fn severity_overrides_the_registry_and_the_most_specific_entry_wins() {
    let (code, json) = run(&["--config", "policy/severity.toml"]);
    assert_eq!(code, 1);
    let s = standings(&json);
    assert!(s.contains(&row("DIFF201", "breaking", "")), "{s:?}");
    assert!(s.contains(&row("DIFF208", "info", "")), "{s:?}");
    assert!(s.contains(&row("DIFF103", "warning", "")), "{s:?}");
    assert_eq!(counts(&json), [3, 1, 3, 0, 0, 0]);
    let d103 = json["changes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["code"] == "DIFF103")
        .unwrap();
    assert_eq!(d103["defaultSeverity"], "breaking");
}

#[test]
fn an_unknown_key_or_code_is_an_error_with_the_nearest_one() {
    for (file, says) in [
        (
            "policy/unknown-key.toml",
            "policy/unknown-key.toml:2:1: unknown field `ignroe`",
        ),
        ("policy/unknown-key.toml", "did you mean `ignore`?"),
        (
            "policy/unknown-code.toml",
            "policy/unknown-code.toml:2:22: [diff] ignore: no change has the code or name `DIFF1O4`; did you mean `DIFF104`?",
        ),
    ] {
        let out = rtcdoc(&["diff", "old", "new", "--config", file], &fixture());
        assert_eq!(out.status.code(), Some(2), "{file}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{file}: {err}");
    }
    // Any table: the hint is the config's, not the diff's.
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "rtcdoc.toml", "[serve]\nprot = 1\n");
    let out = rtcdoc(&["check", "."], dir.path());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("did you mean `port`?"), "{err}");
}

#[test]
fn a_baseline_accepts_exactly_its_changes() {
    let (code, json) = run(&["--baseline", "baseline/accepts.toml"]);
    assert_eq!(code, 0, "every breaking change is accepted");
    assert_eq!(counts(&json), [0, 3, 1, 3, 0, 0]);
    assert_eq!(json["baseline"], "baseline/accepts.toml");
    let d104 = json["changes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["code"] == "DIFF104")
        .unwrap();
    assert_eq!(d104["status"], "accepted");
    assert_eq!(d104["severity"], "breaking");
    assert_eq!(
        d104["reason"],
        "the whole lab moved to 3D poses (issue #12)"
    );
    // --fail-on warning: the warnings are not in the baseline and still fail.
    let (code, _) = run(&[
        "--baseline",
        "baseline/accepts.toml",
        "--fail-on",
        "warning",
    ]);
    assert_eq!(code, 1);
}

#[test]
fn a_stale_entry_is_reported_and_a_new_breaking_change_still_fails() {
    let (code, json) = run(&["--baseline", "baseline/stale-and-new.toml"]);
    assert_eq!(code, 1, "DIFF102 of `cmd` and DIFF103 are in no entry");
    assert_eq!(counts(&json), [2, 3, 1, 1, 0, 1]);
    let stale = json["stale"].as_array().unwrap();
    assert_eq!(stale.len(), 1);
    assert_eq!(stale[0]["element"], "dataPorts/scan");
    assert_eq!(stale[0]["at"], "baseline/stale-and-new.toml:17:1");
    assert_eq!(
        (stale[0]["line"].as_u64(), stale[0]["column"].as_u64()),
        (Some(17), Some(1))
    );
    // The human report: the accepted change with its reason, the stale entry, the counts.
    let out = rtcdoc(
        &[
            "diff",
            "old",
            "new",
            "--baseline",
            "baseline/stale-and-new.toml",
        ],
        &fixture(),
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("accepted (baseline): the whole lab moved to 3D poses (issue #12)"),
        "{text}"
    );
    assert!(
        text.contains("warning: baseline/stale-and-new.toml:17:1: stale baseline entry: DIFF102 on `RTC:Gate:Mobile:Nav:1.0.0` `dataPorts/scan`"),
        "{text}"
    );
    assert!(
        text.contains("rtcdoc diff: 2 breaking, 3 warnings, 1 info, 1 accepted (baseline), 1 stale baseline entry in 2 of 2 matched component(s)"),
        "{text}"
    );
}

#[test]
fn every_format_shows_the_accepted_and_ignored_counts() {
    let args = [
        "diff",
        "old",
        "new",
        "--baseline",
        "baseline/stale-and-new.toml",
        "--config",
        "policy/ignore.toml",
    ];
    let counts_line = "2 breaking, 0 warnings, 0 infos, 1 accepted (baseline), 4 ignored (policy), 1 stale baseline entry";
    let format = |f: &str| {
        let out = rtcdoc(&[&args[..], &["--format", f]].concat(), &fixture());
        assert_eq!(out.status.code(), Some(1), "{f}");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let human = format("human");
    assert!(human.contains(counts_line), "{human}");
    assert!(
        !human.contains("DIFF208"),
        "ignored changes are only counted: {human}"
    );
    let markdown = format("markdown");
    assert!(
        markdown.contains(&format!("## rtcdoc diff: {counts_line}")),
        "{markdown}"
    );
    assert!(
        markdown.contains("| ✅ breaking (accepted) | DIFF104"),
        "{markdown}"
    );
    assert!(
        markdown.contains("— accepted (baseline): the whole lab moved to 3D poses (issue #12) |"),
        "{markdown}"
    );
    assert!(
        markdown.contains("### Stale baseline entries"),
        "{markdown}"
    );
    assert!(
        markdown.contains("`baseline/stale-and-new.toml:17:1` DIFF102"),
        "{markdown}"
    );
    let github = format("github");
    assert!(github.contains(counts_line), "{github}");
    assert!(
        github.lines().any(|l| l.starts_with("::notice ")
            && l.contains("title=DIFF104 data-port-type-changed (accepted)")),
        "{github}"
    );
    assert!(
        github.contains(
            "::warning file=baseline/stale-and-new.toml,line=17,col=1,title=stale baseline entry::"
        ),
        "{github}"
    );
    assert!(!github.contains("DIFF208"), "{github}");
    assert_eq!(github.matches("::error ").count(), 2, "{github}");
    // Everything accepted or ignored: the check passes.
    let out = rtcdoc(
        &[
            "diff",
            "old",
            "new",
            "--config",
            "policy/ignore.toml",
            "--baseline",
            "baseline/accepts.toml",
            "--format",
            "markdown",
        ],
        &fixture(),
    );
    let all_ignored = String::from_utf8_lossy(&out.stdout);
    assert!(all_ignored.contains("the check passes"), "{all_ignored}");
    // --verbose lists the ignored changes too, marked.
    let out = rtcdoc(&[&args[..], &["--verbose"]].concat(), &fixture());
    let verbose = String::from_utf8_lossy(&out.stdout);
    assert!(
        verbose.contains("DIFF208") && verbose.contains("ignored (policy)"),
        "{verbose}"
    );
}

#[test]
fn an_entry_without_a_reason_is_refused() {
    let out = rtcdoc(
        &[
            "diff",
            "old",
            "new",
            "--baseline",
            "baseline/no-reason.toml",
        ],
        &fixture(),
    );
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("baseline/no-reason.toml:7:1: the entry accepting DIFF102 on `RTC:Gate:Mobile:Nav:2.0.0` at `dataPorts/cmd` has no reason"),
        "{err}"
    );
    let out = rtcdoc(
        &["diff", "old", "new", "--baseline", "baseline/none.toml"],
        &fixture(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr)
        .contains("baseline `baseline/none.toml`: cannot read it"));
}

#[test]
fn write_baseline_writes_the_failing_changes_sorted_and_keeps_reasons() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("baseline.toml");
    let file_s = file.to_str().unwrap();
    let (code, json) = run(&["--write-baseline", file_s]);
    assert_eq!(code, 0, "what it wrote is accepted");
    assert_eq!(counts(&json), [0, 3, 1, 3, 0, 0]);
    let first = std::fs::read_to_string(&file).unwrap();
    assert_eq!(first.matches("\n[[accept]]\n").count(), 3, "{first}");
    assert_eq!(
        first
            .matches("reason = \"TODO: why this change is accepted\"")
            .count(),
        3
    );
    // Sorted by component, then element: Nav's cmd, Nav's odometry, Odo's ticks.
    let at = |s: &str| first.find(s).unwrap_or_else(|| panic!("{s} in {first}"));
    assert!(at("element = \"dataPorts/cmd\"") < at("element = \"dataPorts/odometry/type\""));
    assert!(
        at("element = \"dataPorts/odometry/type\"") < at("element = \"dataPorts/ticks/portType\"")
    );
    // Not reviewed yet: refused.
    let out = rtcdoc(&["diff", "old", "new", "--baseline", file_s], &fixture());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("has no reason"));
    // Deterministic, and a rewrite keeps the reasons given.
    let (_, _) = run(&["--write-baseline", file_s]);
    assert_eq!(std::fs::read_to_string(&file).unwrap(), first);
    let reviewed = first.replacen(
        "reason = \"TODO: why this change is accepted\"",
        "reason = \"cmd moved to the Planner\"",
        1,
    );
    std::fs::write(&file, &reviewed).unwrap();
    let out = rtcdoc(
        &[
            "diff",
            "old",
            "new",
            "--write-baseline",
            file_s,
            "--fail-on",
            "warning",
        ],
        &fixture(),
    );
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("wrote 6 baseline entries") && err.contains("(1 with the reason it had)"),
        "{err}"
    );
    let again = std::fs::read_to_string(&file).unwrap();
    assert!(
        again.contains("reason = \"cmd moved to the Planner\""),
        "{again}"
    );
    assert_eq!(
        again.matches("\n[[accept]]\n").count(),
        6,
        "warnings too with --fail-on warning"
    );
    // A file that is not a baseline is not overwritten.
    let other = dir.path().join("notes.toml");
    std::fs::write(&other, "title = \"x\"\n").unwrap();
    let out = rtcdoc(
        &[
            "diff",
            "old",
            "new",
            "--write-baseline",
            other.to_str().unwrap(),
        ],
        &fixture(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("exists and is not a baseline"));
    assert_eq!(std::fs::read_to_string(&other).unwrap(), "title = \"x\"\n");
}

#[test]
fn write_baseline_keeps_the_reasons_of_both_the_baseline_and_the_file_it_rewrites() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("baseline.toml");
    let file_s = file.to_str().unwrap();
    run(&["--write-baseline", file_s]);
    let first = std::fs::read_to_string(&file).unwrap();
    let todo = "reason = \"TODO: why this change is accepted\"";
    // The released baseline explains the first change; the file being rewritten (a branch's
    // copy) explains the second. Rewriting the branch's copy against the release keeps both.
    let released = dir.path().join("released.toml");
    std::fs::write(
        &released,
        first.replacen(todo, "reason = \"from the release\"", 1),
    )
    .unwrap();
    let nth = |text: &str, n: usize| text.match_indices(todo).nth(n).unwrap().0;
    let mut branch = first.clone();
    branch.replace_range(
        nth(&first, 1)..nth(&first, 1) + todo.len(),
        "reason = \"from the branch\"",
    );
    std::fs::write(&file, &branch).unwrap();
    let out = rtcdoc(
        &[
            "diff",
            "old",
            "new",
            "--baseline",
            released.to_str().unwrap(),
            "--write-baseline",
            file_s,
        ],
        &fixture(),
    );
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("(2 with the reason it had)"), "{err}");
    let again = std::fs::read_to_string(&file).unwrap();
    assert!(again.contains("reason = \"from the release\""), "{again}");
    assert!(again.contains("reason = \"from the branch\""), "{again}");
    assert_eq!(again.matches(todo).count(), 1, "{again}");
}

fn copy(from: &Path, to: &Path) {
    for (rel, bytes) in common::tree(from) {
        let p = to.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
}

#[test]
fn since_compares_with_the_same_path_at_a_revision() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    if !git(d, &["--version"]) {
        common::missing_tool("git not available");
        return;
    }
    assert!(git(d, &["init", "-q"]));
    assert!(git(d, &["config", "user.name", "Test"]));
    assert!(git(d, &["config", "user.email", "test@example.org"]));
    copy(&fixture().join("old"), &d.join("robot"));
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "v1"]));
    assert!(git(d, &["tag", "v1.0.0"]));
    std::fs::remove_dir_all(d.join("robot")).unwrap();
    copy(&fixture().join("new"), &d.join("robot"));
    let (code, json) = run_in(d, &["diff", "--since", "v1.0.0", "robot"]);
    assert_eq!(code, 1);
    assert_eq!(json["old"], "v1.0.0:./robot");
    assert_eq!(json["new"], "robot");
    assert_eq!(counts(&json), [3, 3, 1, 0, 0, 0]);
    // As OLD and NEW given whole.
    let (_, whole) = run_in(d, &["diff", "v1.0.0:./robot", "robot"]);
    assert_eq!(whole["changes"], json["changes"]);
    // Without NEW: the configuration's input.
    write(
        d,
        "rtcdoc.toml",
        "input = \"robot\"\n[diff]\nignore = [\"DIFF1xx\"]\n",
    );
    let (code, json) = run_in(d, &["diff", "--since", "v1.0.0"]);
    assert_eq!(code, 0, "{json}");
    assert_eq!(counts(&json), [0, 3, 1, 0, 3, 0]);
    // Inside the folder: `REV:./` is the current directory.
    let (_, json) = run_in(&d.join("robot"), &["diff", "--since", "v1.0.0", "."]);
    assert_eq!(json["old"], "v1.0.0:./");
    assert_eq!(counts(&json)[..3], [3, 3, 1]);
    // A revision is never an option, and --since is OLD.
    for (args, says) in [
        (
            &["diff", "--since=--output=x", "robot"][..],
            "starts with `-`",
        ),
        (
            &["diff", "--since", "v1.0.0:robot", "robot"][..],
            "not REV:PATH",
        ),
        (
            &["diff", "--since", "v1.0.0", "robot", "robot"][..],
            "give only NEW",
        ),
        (
            &["diff", "--since", "v9", "robot"][..],
            "git cannot find it",
        ),
    ] {
        let out = rtcdoc(args, d);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
    }
}
