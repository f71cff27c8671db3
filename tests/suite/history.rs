//! A component's history (`history` in catalog.json, the History section of its page): the
//! commits of a git work tree that changed its profile (renames followed), RTCBuilder's backups
//! in a folder without git, each version compared with the one before by the diff engine.

use crate::common;
use common::history_repo::{
    build, build_source_project, codes, commit_versions, edit as with, git, page,
};
use common::write;
use common::OutputWithin;
use serde_json::Value;
use std::path::Path;

const PROFILE: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:Lab:Mobile:Base:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="Base" rtc:vendor="Lab" rtc:category="Mobile" rtc:version="1.0.0" rtc:componentType="STATIC" rtc:activityType="PERIODIC" rtc:componentKind="DataFlowComponent" rtc:executionType="PeriodicExecutionContext" rtc:executionRate="100.0"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataInPort" rtc:name="cmd" rtc:type="RTC::TimedVelocity2D"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="odometry" rtc:type="RTC::TimedPose2D"/>
  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="C++"/>
</rtc:RtcProfile>
"#;

const STATUS_PORT: &str = r#"  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="status" rtc:type="RTC::TimedLong"/>
  <rtc:Language"#;

/// The versions the tests commit, oldest first: (subject, profile).
fn versions() -> Vec<(&'static str, String)> {
    let added = with(PROFILE, &[("  <rtc:Language", STATUS_PORT)]);
    // Attribute order and indentation only.
    let reformatted = with(
        &added,
        &[
            (
                r#"rtc:portType="DataInPort" rtc:name="cmd""#,
                r#"rtc:name="cmd"   rtc:portType="DataInPort""#,
            ),
            ("  <rtc:Language", "<rtc:Language"),
        ],
    );
    let renamed = with(
        &reformatted,
        &[(r#"rtc:name="cmd""#, r#"rtc:name="velocity""#)],
    );
    let released = with(
        &renamed,
        &[
            (":Base:1.0.0\"", ":Base:2.0.0\""),
            ("rtc:version=\"1.0.0\"", "rtc:version=\"2.0.0\""),
        ],
    );
    vec![
        ("First version", PROFILE.to_string()),
        ("Add the status port", added),
        ("Reformat", reformatted),
        ("Rename cmd to velocity", renamed),
        ("Release 2.0.0", released),
    ]
}

/// A work tree with the commits of [`versions`] on `Base/RTC.xml`, then the folder moved to
/// `mobile/Base`.
fn repository(d: &Path) -> bool {
    if !commit_versions(d, versions()) {
        return false;
    }
    std::fs::create_dir_all(d.join("mobile")).unwrap();
    let date = "2024-01-09 10:00:00 +0900";
    assert!(git(d, &["mv", "Base", "mobile/Base"], date));
    assert!(git(d, &["commit", "-q", "-m", "Move to mobile/"], date));
    true
}

fn build_json(input: &Path, out: &Path, extra: &[&str]) -> Value {
    let mut args = vec!["-f", "json"];
    args.extend_from_slice(extra);
    build(input, out, &args);
    serde_json::from_str(&page(out, "catalog.json")).unwrap()
}

#[test]
fn git_history_of_a_work_tree_follows_the_move() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    std::fs::create_dir_all(&repo).unwrap();
    if !repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let json = build_json(&repo, &dir.path().join("site"), &[]);
    let c = &json["components"]["RTC:Lab:Mobile:Base:2.0.0"];
    let h = c["history"].as_array().expect("a history");
    let subjects: Vec<&str> = h.iter().map(|e| e["subject"].as_str().unwrap()).collect();
    assert_eq!(
        subjects,
        [
            "Move to mobile/",
            "Release 2.0.0",
            "Rename cmd to velocity",
            "Reformat",
            "Add the status port",
            "First version"
        ],
        "{h:#?}"
    );
    // The path at each commit: the move is followed.
    assert_eq!(h[0]["file"], "mobile/Base/RTC.xml");
    assert_eq!(h[1]["file"], "Base/RTC.xml");
    assert_eq!(h[5]["file"], "Base/RTC.xml");
    for e in h {
        assert_eq!(e["author"], "Tester");
        assert_eq!(e["commit"].as_str().unwrap().len(), 40);
    }
    assert_eq!(h[0]["date"], "2024-01-09T10:00:00+09:00");
    // The move and the reformatting change nothing of the specification.
    assert!(h[0]["changes"].as_array().unwrap().is_empty(), "{h:#?}");
    assert!(h[3]["changes"].as_array().unwrap().is_empty(), "{h:#?}");
    // The release: a new version string.
    assert_eq!(h[1]["release"], true);
    assert_eq!(h[1]["version"], "2.0.0");
    assert_eq!(h[2]["version"], "1.0.0");
    assert!(h[2].get("release").is_none());
    // The rename breaks connections, without a version bump: DIFF208 too.
    let renamed = codes(&h[2]);
    assert!(renamed.contains(&"DIFF208"), "{renamed:?}");
    assert!(
        h[2]["changes"]
            .as_array()
            .unwrap()
            .iter()
            .any(|c| c["severity"] == "breaking" && c["path"] == "dataPorts/cmd"),
        "{h:#?}"
    );
    // The added port, as `rtcdoc diff` writes it.
    let added = &h[4]["changes"][0];
    assert_eq!(added["code"], "DIFF301", "{h:#?}");
    assert_eq!(added["path"], "dataPorts/status");
    assert_eq!(added["file"], "Base/RTC.xml");
    assert_eq!(h[5]["first"], true);
    assert!(h[5]["changes"].as_array().unwrap().is_empty());

    // catalog.json is read back with its history.
    let bytes = std::fs::read(dir.path().join("site/catalog.json")).unwrap();
    let read = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").unwrap();
    let back = &read.catalog.components[0].history;
    assert_eq!(back.len(), 6);
    assert_eq!(back[2].subject.as_deref(), Some("Rename cmd to velocity"));
    assert_eq!(
        serde_json::to_value(back).unwrap(),
        json["components"]["RTC:Lab:Mobile:Base:2.0.0"]["history"]
    );

    // `--history 2`: the two newest commits; `--history 0`: none.
    let json = build_json(&repo, &dir.path().join("site2"), &["--history", "2"]);
    let h = json["components"]["RTC:Lab:Mobile:Base:2.0.0"]["history"]
        .as_array()
        .unwrap();
    assert_eq!(h.len(), 2);
    assert_eq!(h[1]["first"], true);
    let json = build_json(&repo, &dir.path().join("site3"), &["--history", "0"]);
    assert!(json["components"]["RTC:Lab:Mobile:Base:2.0.0"]
        .get("history")
        .is_none());
}

#[test]
fn uncommitted_edits_are_a_version_of_their_own() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    std::fs::create_dir_all(&repo).unwrap();
    if !repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let (_, last) = versions().pop().unwrap();
    write(
        &repo,
        "mobile/Base/RTC.xml",
        &with(&last, &[(r#"rtc:name="odometry""#, r#"rtc:name="pose""#)]),
    );
    let json = build_json(&repo, &dir.path().join("site"), &[]);
    let h = json["components"]["RTC:Lab:Mobile:Base:2.0.0"]["history"]
        .as_array()
        .unwrap();
    assert_eq!(h.len(), 7);
    assert!(h[0].get("commit").is_none(), "{:#?}", h[0]);
    assert_eq!(h[0]["file"], "mobile/Base/RTC.xml");
    assert!(codes(&h[0]).contains(&"DIFF208"), "{:#?}", h[0]);
    assert_eq!(h[1]["subject"], "Move to mobile/");
}

#[test]
fn backups_are_the_history_without_git() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let v = versions();
    write(&input, "Base/RTC.xml20240101090000", &v[0].1);
    write(&input, "Base/RTC.xml20240102090000", &v[1].1);
    write(&input, "Base/RTC.xml20240103090000", "<rtc:RtcProfile");
    write(&input, "Base/RTC.xml", &v[4].1);
    let json = build_json(&input, &dir.path().join("site"), &[]);
    let h = json["components"]["RTC:Lab:Mobile:Base:2.0.0"]["history"]
        .as_array()
        .unwrap();
    let files: Vec<&str> = h.iter().map(|e| e["file"].as_str().unwrap()).collect();
    assert_eq!(
        files,
        [
            "Base/RTC.xml",
            "Base/RTC.xml20240103090000",
            "Base/RTC.xml20240102090000",
            "Base/RTC.xml20240101090000"
        ],
        "{h:#?}"
    );
    assert_eq!(h[1]["backup"], "Base/RTC.xml20240103090000");
    assert_eq!(h[1]["date"], "2024-01-03 09:00:00");
    // The truncated backup stays, with why; the file is compared with the one before it.
    assert!(h[1]["error"].as_str().is_some(), "{:#?}", h[1]);
    assert!(h[1]["changes"].as_array().unwrap().is_empty());
    assert_eq!(h[0]["release"], true);
    assert_eq!(codes(&h[0]), ["DIFF306", "DIFF102", "DIFF301"]);
    assert_eq!(codes(&h[2]), ["DIFF301"]);
    assert_eq!(h[3]["first"], true);
}

/// A backup whose name holds no date of the calendar (month 13) cannot be placed among the
/// versions: it is left out of the history, with a note saying why and what to do, and the
/// real oldest backup stays the first version (not compared with it: no false DIFF102). It is
/// still listed as a backup of the component.
#[test]
fn a_backup_named_with_an_impossible_date_is_left_out_of_the_history_with_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let v = versions();
    write(&input, "Base/RTC.xml20240101090000", &v[0].1);
    write(&input, "Base/RTC.xml20201345999999", &v[1].1);
    write(&input, "Base/RTC.xml", &v[1].1);
    let out = dir.path().join("site");
    // The catalogue built as JSON, and what the build printed.
    let build_json = || {
        let o = common::rtcdoc(
            &[
                "build",
                input.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "-f",
                "json",
            ],
            dir.path(),
        );
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        (o, err)
    };
    let (o, err) = build_json();
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("warning: history: the backup `Base/RTC.xml20201345999999` has no valid save date and time in the name"),
        "{err}"
    );
    assert!(err.contains("rename it by the time it was saved"), "{err}");
    let json: Value = serde_json::from_str(&page(&out, "catalog.json")).unwrap();
    let c = &json["components"]["RTC:Lab:Mobile:Base:1.0.0"];
    let h = c["history"].as_array().unwrap();
    let files: Vec<&str> = h.iter().map(|e| e["file"].as_str().unwrap()).collect();
    assert_eq!(
        files,
        ["Base/RTC.xml", "Base/RTC.xml20240101090000"],
        "{h:#?}"
    );
    assert_eq!(h[1]["first"], true);
    assert_eq!(codes(&h[0]), ["DIFF301"]);
    let backups: Vec<&str> = c["backups"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["source"].as_str().unwrap())
        .collect();
    assert_eq!(
        backups,
        ["Base/RTC.xml20201345999999", "Base/RTC.xml20240101090000"]
    );
    assert!(c["backups"][0].get("saved").is_none());

    // Renamed by its save time, as the note says, it takes its place among the versions.
    std::fs::rename(
        input.join("Base/RTC.xml20201345999999"),
        input.join("Base/RTC.xml20240102090000"),
    )
    .unwrap();
    let (o, err) = build_json();
    assert!(o.status.success() && !err.contains("history:"), "{err}");
    let json: Value = serde_json::from_str(&page(&out, "catalog.json")).unwrap();
    let h = json["components"]["RTC:Lab:Mobile:Base:1.0.0"]["history"]
        .as_array()
        .unwrap()
        .clone();
    assert_eq!(h.len(), 3, "{h:#?}");
    assert_eq!(h[1]["file"], "Base/RTC.xml20240102090000");
}

#[test]
fn the_component_page_has_a_history_section_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    std::fs::create_dir_all(&repo).unwrap();
    if !repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    write(
        &repo,
        "rtcdoc.toml",
        "source-url = \"https://example.org/lab/blob/{commit}/{path}\"\n",
    );
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "html,markdown,doxygen"]);
    let html = page(&site, "html/components/base.html");
    assert!(
        html.contains("<li><a href=\"#change-history\">History</a></li>"),
        "{html}"
    );
    let section = &html[html
        .find("<section id=\"change-history\">")
        .expect("a History section")..];
    let section = &section[..section.find("</section>").unwrap()];
    // Newest first; the move said (not folded), the reformatting folded; the release marked;
    // the rename's breaking changes spelled out; each commit linked to its file at that commit.
    let rows: Vec<&str> = section.split("<tr>").skip(2).collect();
    assert_eq!(rows.len(), 6, "{section}");
    assert!(
        rows[0].contains("moved from Base/RTC.xml, no change to the specification"),
        "{}",
        rows[0]
    );
    assert!(rows[0].contains("Move to mobile/"), "{}", rows[0]);
    assert!(rows[1].contains("2.0.0 (release)"), "{}", rows[1]);
    assert!(rows[1].contains("Release 2.0.0"), "{}", rows[1]);
    assert!(rows[2].contains("Rename cmd to velocity"), "{}", rows[2]);
    assert!(
        rows[2].contains("1 breaking, 1 warning, 1 info<ul>"),
        "{}",
        rows[2]
    );
    let item = |severity: &str, path: &str| {
        format!("<li><span class=\"sev {severity}\">{severity}</span> <code>{path}</code>: ")
    };
    assert!(
        rows[2].contains(&item("breaking", "dataPorts/cmd")),
        "{}",
        rows[2]
    );
    assert!(
        rows[2].contains(&format!(
            "{}<code>Base</code> has breaking changes but keeps version 1.0.0",
            item("warning", "basicInfo/version")
        )),
        "{}",
        rows[2]
    );
    assert!(
        rows[2].contains(&item("info", "dataPorts/velocity")),
        "{}",
        rows[2]
    );
    assert!(rows[3].contains("1 version without changes"), "{}", rows[3]);
    assert!(rows[4].contains("1 info"), "{}", rows[4]);
    assert!(
        rows[5].contains("first version in the history"),
        "{}",
        rows[5]
    );
    assert!(
        rows[2].contains("<a href=\"https://example.org/lab/blob/"),
        "{}",
        rows[2]
    );
    assert!(rows[2].contains("/Base/RTC.xml\"><code>"), "{}", rows[2]);

    let md = page(&site, "markdown/components/base.md");
    assert!(md.contains("## History"), "{md}");
    assert!(md.contains("Rename cmd to velocity"), "{md}");
    assert!(md.contains("2.0.0 (release)"), "{md}");
    let dox = page(&site, "doxygen/components/base.dox");
    assert!(dox.contains("Rename cmd to velocity"), "{dox}");

    // The native writer and the template say the same, byte for byte.
    let theme = dir.path().join("theme");
    write(
        &theme,
        "component.html",
        &std::fs::read_to_string(common::root().join("themes/default/component.html")).unwrap(),
    );
    let templated = dir.path().join("templated");
    build(
        &repo,
        &templated,
        &["-f", "html", "--theme", theme.to_str().unwrap()],
    );
    assert_eq!(html, page(&templated, "components/base.html"));
}

#[test]
fn a_source_repository_gives_its_history_up_to_the_pinned_commit() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    std::fs::create_dir_all(&repo).unwrap();
    if !repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    // A commit whose profile cannot be read, then the fix.
    let (_, last) = versions().pop().unwrap();
    write(&repo, "mobile/Base/RTC.xml", &last[..200]);
    assert!(git(
        &repo,
        &["commit", "-q", "-am", "Broken"],
        "2024-01-10 10:00:00 +0900"
    ));
    write(&repo, "mobile/Base/RTC.xml", &last);
    assert!(git(
        &repo,
        &["commit", "-q", "-am", "Fix"],
        "2024-01-11 10:00:00 +0900"
    ));
    let out = build_source_project(dir.path(), "json,html");
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("json/catalog.json")).unwrap())
            .unwrap();
    let c = &json["components"]["RTC:Lab:Mobile:Base:2.0.0"];
    assert_eq!(c["source"], "lab/mobile/Base/RTC.xml");
    let h = c["history"].as_array().expect("a history");
    let subjects: Vec<&str> = h.iter().map(|e| e["subject"].as_str().unwrap()).collect();
    assert_eq!(subjects.len(), 8, "{subjects:?}");
    assert_eq!(&subjects[..3], ["Fix", "Broken", "Move to mobile/"]);
    // The broken version stays, with why; the fix is compared with the version before it.
    assert_eq!(
        h[1]["error"],
        "line 2, column 1: unclosed tag: `<` without a matching `>` (truncated file?)"
    );
    assert!(
        h[0]["changes"].as_array().unwrap().is_empty(),
        "{:#?}",
        h[0]
    );
    assert_eq!(h[0]["file"], "mobile/Base/RTC.xml");
    // The page links each commit to the file in the source's repository at that commit.
    let html = std::fs::read_to_string(out.join("html/components/base.html")).unwrap();
    let commit = h[3]["commit"].as_str().unwrap();
    assert!(
        html.contains(&format!(
            "<a href=\"https://git.example.org/lab/blob/{commit}/Base/RTC.xml\"><code>{}</code></a>",
            &commit[..12]
        )),
        "{html}"
    );
    assert!(html.contains("could not be read: "), "{html}");
}

/// `git log --follow` of `path` (relative to `dir`): (commit, file) of each version, newest
/// first, the commits that deleted it left out, up to a copy (whose original has a history of
/// its own) — what a component's history lists.
fn follow(dir: &Path, path: &str, limit: usize) -> Vec<(String, String)> {
    let o = std::process::Command::new("git")
        .args(["log", "--follow", "--name-status", "--format=@%H"])
        .arg(format!("--max-count={limit}"))
        .args(["--", path])
        .current_dir(dir)
        .env("GIT_CONFIG_NOSYSTEM", "1")
        .env("HOME", dir)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(o.status.success());
    let mut out = Vec::new();
    for block in String::from_utf8(o.stdout).unwrap().split('@').skip(1) {
        let mut lines = block.lines().filter(|l| !l.is_empty());
        let commit = lines.next().unwrap().to_string();
        let status = lines.next().unwrap();
        if !status.starts_with('D') {
            out.push((commit, status.rsplit('\t').next().unwrap().to_string()));
        }
        if status.starts_with('C') {
            break;
        }
    }
    out
}

/// Several profiles in one repository are read from one log of the whole repository: it must
/// give what `git log --follow` of each file gives — with an input folder inside the
/// repository, a profile added by the root commit only (D: the whole log's), one deleted and
/// added again (where `--follow` takes a similar file, another component's, for the original of
/// a copy: the history starts at the copy), one added later, a
/// renamed folder, a limit, and merges.
#[test]
fn histories_of_many_profiles_are_those_of_git_log_follow() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    std::fs::create_dir_all(&repo).unwrap();
    if !git(&repo, &["init", "-q"], "") {
        crate::common::missing_tool("git not available");
        return;
    }
    assert!(git(&repo, &["config", "user.name", "Tester"], ""));
    assert!(git(&repo, &["config", "user.email", "t@example.org"], ""));
    let profile = |name: &str, rev: usize| {
        PROFILE
            .replace("Base", name)
            .replace("\"odometry\"", &format!("\"odometry{rev}\""))
    };
    let mut day = 0;
    let mut commit = |edits: &[(&str, Option<String>)], subject: &str| {
        for (path, text) in edits {
            match text {
                Some(t) => write(&repo, path, t),
                None => std::fs::remove_file(repo.join(path)).unwrap(),
            }
        }
        day += 1;
        let date = format!("2024-02-{day:02} 10:00:00 +0900");
        assert!(git(&repo, &["add", "-A"], &date));
        assert!(git(&repo, &["commit", "-q", "-m", subject], &date));
    };
    commit(
        &[
            ("lab/A/RTC.xml", Some(profile("A", 0))),
            ("lab/B/RTC.xml", Some(profile("B", 0))),
            ("lab/D/RTC.xml", Some(profile("D", 0))),
            ("notes.txt", Some("unrelated notes\n".repeat(20))),
        ],
        "First",
    );
    commit(
        &[
            ("lab/A/RTC.xml", Some(profile("A", 1))),
            ("lab/D/RTC.xml", Some(profile("D", 1))),
        ],
        "Edit A and D",
    );
    commit(
        &[
            ("lab/A/RTC.xml", Some(profile("A", 2))),
            ("lab/B/RTC.xml", Some(profile("B", 1))),
        ],
        "Edit A and B",
    );
    commit(
        &[
            ("lab/C/RTC.xml", Some(profile("C", 0))),
            ("notes.txt", None),
        ],
        "Add C, drop the notes",
    );
    let b = std::fs::read_to_string(repo.join("lab/B/RTC.xml")).unwrap();
    commit(
        &[("lab/B/RTC.xml", None), ("lab/B2/RTC.xml", Some(b))],
        "Move B",
    );
    commit(&[("lab/A/RTC.xml", None)], "Drop A");
    commit(&[("lab/A/RTC.xml", Some(profile("A", 3)))], "A again");
    commit(
        &[
            ("lab/C/RTC.xml", Some(profile("C", 1))),
            ("lab/D/RTC.xml", Some(profile("D", 2))),
        ],
        "Edit C and D",
    );
    let lab = repo.join("lab");
    let check = |tag: &str| {
        for limit in [100, 2] {
            let out = dir.path().join(format!("site-{tag}-{limit}"));
            let json = build_json(&lab, &out, &["--history", &limit.to_string()]);
            for (id, path) in [
                ("A", "A/RTC.xml"),
                ("B", "B2/RTC.xml"),
                ("C", "C/RTC.xml"),
                ("D", "D/RTC.xml"),
            ] {
                let h = json["components"][format!("RTC:Lab:Mobile:{id}:1.0.0")]["history"]
                    .as_array()
                    .unwrap_or_else(|| panic!("{id}: no history"));
                let got: Vec<(String, String)> = h
                    .iter()
                    .map(|e| {
                        (
                            e["commit"].as_str().unwrap().to_string(),
                            e["file"].as_str().unwrap().to_string(),
                        )
                    })
                    .collect();
                assert_eq!(
                    got,
                    follow(&lab, path, limit),
                    "{tag} {id} --history {limit}"
                );
            }
        }
    };
    check("linear");
    // A merge: each file's history as git simplifies it.
    assert!(git(&repo, &["checkout", "-q", "-b", "side"], ""));
    commit(&[("lab/C/RTC.xml", Some(profile("C", 2)))], "Edit C aside");
    assert!(git(&repo, &["checkout", "-q", "-"], ""));
    commit(&[("lab/A/RTC.xml", Some(profile("A", 4)))], "Edit A");
    assert!(git(
        &repo,
        &["merge", "-q", "--no-ff", "-m", "Merge side", "side"],
        "2024-03-01 10:00:00 +0900"
    ));
    check("merged");
}
