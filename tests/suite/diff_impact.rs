//! The impact of a comparison (`diff::impact`): the summary at the top of every report, each
//! change's reach, the gate's standing, and the same reach on the history pages.
//!
//! The pair `tests/fixtures/diff-impact/{old,new}`: the RT System `PatrolRobot` wires Laser's
//! `range` (RTC::RangeData, its only producer) to Mapper's and Avoider's `scan`, and Planner's
//! `Path` (providing Patrol::PathService, its only provider) to Driver's. NEW removes Laser's
//! port and Planner's interface: three connectors break, two components lose their only
//! producer of RTC::RangeData and one its only provider of Patrol::PathService.

use crate::common;
use common::history_repo::{build, commit, init, page};
use common::{root, rtcdoc, write};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

const SUMMARY: &str = "breaks 3 connectors in 1 system (PatrolRobot); 2 components lose their only producer of RTC::RangeData; 1 component loses its only provider of Patrol::PathService; reaches 3 components";

fn fixture() -> PathBuf {
    root().join("tests/fixtures/diff-impact")
}

/// `rtcdoc diff old new ARGS` in `dir`: standard output.
fn diff_in(dir: &Path, args: &[&str]) -> String {
    let out = rtcdoc(&[&["diff", "old", "new"], args].concat(), dir);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn diff(args: &[&str]) -> String {
    diff_in(&fixture(), args)
}

fn json_of(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

#[test]
fn the_human_report_starts_with_the_impact_and_counts_each_changes_reach() {
    let out = diff(&[]);
    assert!(
        out.starts_with(&format!(
            "Impact: {SUMMARY}\n\nRTC:Lab:Patrol:Laser:2.0.0\n"
        )),
        "{out}"
    );
    assert!(
        out.contains("--> old/Laser/RTC.xml:5:3\n      reaches 2 components\n"),
        "{out}"
    );
    let verbose = diff(&["-v"]);
    assert!(verbose.contains("      reaches 2 components: RTC:Lab:Patrol:Avoider:1.0.0 (consumer), RTC:Lab:Patrol:Mapper:1.0.0 (consumer)\n"), "{verbose}");
    assert!(verbose.contains("  RTC::RangeData is still consumed by RTC:Lab:Patrol:Avoider:1.0.0, RTC:Lab:Patrol:Mapper:1.0.0\n"), "{verbose}");
    assert!(
        !diff(&["-q"]).contains("Impact:"),
        "-q prints breaking changes only"
    );
}

#[test]
fn the_json_report_has_the_impact_and_each_changes_reach() {
    let v = json_of(&diff(&["--format", "json"]));
    assert_eq!(
        v["impact"],
        json!({
            "connectors": 3,
            "systems": [{"system": "PatrolRobot", "connectors": 3}],
            "lostProducers": [{"type": "RTC::RangeData", "components": ["RTC:Lab:Patrol:Avoider:1.0.0", "RTC:Lab:Patrol:Mapper:1.0.0"]}],
            "lostProviders": [{"type": "Patrol::PathService", "components": ["RTC:Lab:Patrol:Driver:1.0.0"]}],
            "reached": ["RTC:Lab:Patrol:Avoider:1.0.0", "RTC:Lab:Patrol:Driver:1.0.0", "RTC:Lab:Patrol:Mapper:1.0.0"],
            "summary": SUMMARY,
        })
    );
    let reach = |code: &str| -> Vec<Value> {
        let changes = v["changes"].as_array().expect("changes");
        let c = changes.iter().find(|c| c["code"] == code).expect(code);
        c["reach"].as_array().cloned().unwrap_or_default()
    };
    assert_eq!(
        reach("DIFF102"),
        vec![
            json!({"component": "RTC:Lab:Patrol:Avoider:1.0.0", "role": "consumer"}),
            json!({"component": "RTC:Lab:Patrol:Mapper:1.0.0", "role": "consumer"}),
        ]
    );
    assert_eq!(
        reach("DIFF106"),
        vec![json!({"component": "RTC:Lab:Patrol:Driver:1.0.0", "role": "requirer"})]
    );
    assert!(
        reach("DIFF306").is_empty(),
        "a version change reaches nothing"
    );
}

#[test]
fn the_markdown_report_lists_the_impact_before_the_components() {
    let md = diff(&["--format", "markdown"]);
    let list = "**Impact:**\n\n- breaks 3 connectors in 1 system (PatrolRobot)\n- 2 components lose their only producer of RTC::RangeData\n- 1 component loses its only provider of Patrol::PathService\n- reaches 3 components\n\n<details><summary>What each change reaches</summary>\n\n- DIFF102 `RTC:Lab:Patrol:Laser:2.0.0` `dataPorts/range` — reaches 2 components: RTC:Lab:Patrol:Avoider:1.0.0 (consumer), RTC:Lab:Patrol:Mapper:1.0.0 (consumer)\n- DIFF106 `RTC:Lab:Patrol:Planner:2.0.0` `servicePorts/Path/interfaces/path` — reaches 1 component: RTC:Lab:Patrol:Driver:1.0.0 (requirer)\n\n</details>\n\n### `RTC:Lab:Patrol:Laser:2.0.0`";
    assert!(md.contains(list), "{md}");
    assert!(
        md.contains("| data port `range` was removed — reaches 2 components |"),
        "{md}"
    );
}

#[test]
fn the_github_report_starts_with_an_impact_notice() {
    let gh = diff(&["--format", "github"]);
    assert_eq!(
        gh.lines().next(),
        Some(format!("::notice title=rtcdoc diff impact::{SUMMARY}").as_str())
    );
}

#[test]
fn changes_the_policy_ignores_count_toward_no_impact_but_keep_their_reach() {
    let d = tempfile::tempdir().expect("tempdir");
    for side in ["old", "new"] {
        copy_tree(&fixture().join(side), &d.path().join(side));
    }
    write(
        d.path(),
        "rtcdoc.toml",
        "[diff]\nignore = [\"DIFF102\", \"DIFF142\"]\n",
    );
    let v = json_of(&diff_in(
        d.path(),
        &["--config", "rtcdoc.toml", "--format", "json"],
    ));
    assert_eq!(
        v["impact"]["summary"],
        "breaks 1 connector in 1 system (PatrolRobot); 1 component loses its only provider of Patrol::PathService; reaches 1 component"
    );
    assert_eq!(v["impact"]["lostProducers"], json!([]));
    let changes = v["changes"].as_array().expect("changes");
    let removed = changes
        .iter()
        .find(|c| c["code"] == "DIFF102")
        .expect("DIFF102");
    assert_eq!(removed["status"], "ignored");
    assert_eq!(removed["reach"].as_array().map(Vec::len), Some(2));
}

#[test]
fn a_change_that_reaches_nothing_prints_no_impact() {
    let d = tempfile::tempdir().expect("tempdir");
    let old = common::xml_profile("Solo", &[("DataOutPort", "out", "RTC::TimedLong")]);
    write(d.path(), "old/Solo/RTC.xml", &old);
    write(
        d.path(),
        "new/Solo/RTC.xml",
        &old.replace(r#"rtc:name="out""#, r#"rtc:name="output""#),
    );
    let human = diff_in(d.path(), &[]);
    assert!(
        !human.contains("Impact") && !human.contains("reaches"),
        "{human}"
    );
    let md = diff_in(d.path(), &["--format", "markdown"]);
    assert!(!md.contains("Impact") && !md.contains("reaches"), "{md}");
    let gh = diff_in(d.path(), &["--format", "github"]);
    assert!(!gh.contains("impact"), "{gh}");
    let v = json_of(&diff_in(d.path(), &["--format", "json"]));
    assert_eq!(
        v["impact"],
        json!({"connectors": 0, "systems": [], "lostProducers": [], "lostProviders": [], "reached": [], "summary": null})
    );
}

fn copy_tree(from: &Path, to: &Path) {
    for e in std::fs::read_dir(from).expect("read_dir") {
        let e = e.expect("entry");
        let target = to.join(e.file_name());
        if e.path().is_dir() {
            copy_tree(&e.path(), &target);
        } else {
            std::fs::create_dir_all(to).expect("mkdir");
            std::fs::copy(e.path(), &target).expect("copy");
        }
    }
}

#[test]
fn the_history_page_shows_the_reach_of_a_versions_changes() {
    let d = tempfile::tempdir().expect("tempdir");
    let repo = d.path().join("repo");
    if !init(&repo) {
        return common::missing_tool("git");
    }
    copy_tree(&fixture().join("old"), &repo);
    commit(&repo, 1, "Patrol robot");
    std::fs::remove_dir_all(repo.join("Laser")).expect("rm");
    copy_tree(&fixture().join("new/Laser"), &repo.join("Laser"));
    commit(&repo, 2, "Laser: no range port");
    let site = d.path().join("site");
    build(&repo, &site, &["-f", "html,markdown,doxygen"]);
    let line = "Reaches 2 other components: Avoider (consumer), Mapper (consumer)";
    let html = page(&site, "html/history/laser.html");
    assert!(
        html.contains(&format!(
            "data port <code>range</code> was removed<br><span class=\"reach\">{line}</span></td>"
        )),
        "{html}"
    );
    let md = page(&site, "markdown/history/laser.md");
    assert!(
        md.contains(&format!("data port `range` was removed — {line} |")),
        "{md}"
    );
    let dox = page(&site, "doxygen/history/laser.dox");
    assert!(dox.contains(line), "{dox}");
    // The version change reaches nothing: its row says nothing more.
    assert_eq!(md.matches("Reaches").count(), 1, "{md}");
    // The same reach on the History section of the component page and on What's new.
    let row = format!(
        "data port <code>range</code> was removed <span class=\"reach\">{line}</span></li>"
    );
    let component = page(&site, "html/components/laser.html");
    assert!(component.contains(&row), "{component}");
    let whats_new = page(&site, "html/whats-new.html");
    assert!(
        whats_new.contains(&format!(
            "data port <code>range</code> was removed<br><span class=\"reach\">{line}</span></td>"
        )),
        "{whats_new}"
    );
    let component_md = page(&site, "markdown/components/laser.md");
    assert!(
        component_md.contains(&format!("data port `range` was removed — {line}")),
        "{component_md}"
    );
    let whats_new_md = page(&site, "markdown/whats-new.md");
    assert!(whats_new_md.contains(line), "{whats_new_md}");
}

/// A change inside an IDL definition reaches every component that produces or consumes the
/// type: in `diff`'s report (at each port) and, as `idl/Lab::Pose/…`, on the type page's and
/// the IDL file's history.
#[test]
fn a_change_to_an_idl_definition_reaches_its_producers_and_consumers() {
    let d = tempfile::tempdir().expect("tempdir");
    let repo = d.path().join("new");
    if !init(&repo) {
        return common::missing_tool("git");
    }
    let idl = |field: &str| {
        format!("module Lab {{\n  struct Pose {{\n    double x;\n    {field}\n  }};\n}};\n")
    };
    common::write(&repo, "idl/Lab.idl", &idl("double y;"));
    for (name, dir, port) in [
        ("Localizer", "DataOutPort", "pose"),
        ("Planner", "DataInPort", "pose"),
        ("Viewer", "DataInPort", "pose"),
    ] {
        common::write(
            &repo,
            &format!("{name}/RTC.xml"),
            &common::xml_profile(name, &[(dir, port, "Lab::Pose")]),
        );
    }
    commit(&repo, 1, "Pose");
    let old = d.path().join("old");
    copy_tree(&repo, &old);
    std::fs::remove_dir_all(old.join(".git")).expect("rm .git");
    // `y` becomes a float: a breaking change of the definition, not of any profile.
    common::write(&repo, "idl/Lab.idl", &idl("float y;"));
    commit(&repo, 2, "Pose: float y");
    let json = json_of(&diff_in(d.path(), &["--format", "json"]));
    // `diff` reports the definition's change at each port carrying it, reaching the others.
    let change = json["changes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["code"] == "DIFF134" && c["component"] == "RTC:Test:Cat:Localizer:1.0.0")
        .cloned()
        .unwrap_or_else(|| panic!("no DIFF134 of Localizer: {json}"));
    assert_eq!(
        change["reach"],
        serde_json::json!([{"component": "RTC:Test:Cat:Planner:1.0.0", "role": "consumer"}, {"component": "RTC:Test:Cat:Viewer:1.0.0", "role": "consumer"}]),
        "{change}"
    );
    // The IDL file's history compares the definitions themselves (`idl/Lab::Pose/…`): the
    // change reaches every component carrying the type, on the type page and the IDL file's
    // history page.
    let site = d.path().join("site");
    build(&repo, &site, &["-f", "html,markdown"]);
    let line =
        "Reaches 3 other components: Localizer (producer), Planner (consumer), Viewer (consumer)";
    let type_page = page(&site, "html/types/lab-pose.html");
    assert!(type_page.contains(line), "{type_page}");
    let idl_history = std::fs::read_dir(site.join("html/idl-history"))
        .expect("IDL history pages")
        .map(|e| {
            page(
                &site,
                &format!(
                    "html/idl-history/{}",
                    e.unwrap().file_name().to_string_lossy()
                ),
            )
        })
        .collect::<String>();
    assert!(idl_history.contains(line), "{idl_history}");
}
