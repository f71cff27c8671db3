//! RTCBuilder's backups (`RTC.xml<yyyymmddhhmmss>`) are older versions of the profile beside
//! them, never components: the fixture `tests/fixtures/backups` is a workspace shaped like a
//! real lab's (a wizard-placeholder backup that declares UTF-8 and holds Shift_JIS, an older
//! version that disagrees with the profile, a folder whose RTC.xml is gone).

use crate::common;
use common::*;
use std::path::Path;

fn fixture() -> std::path::PathBuf {
    root().join("tests/fixtures/backups")
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn read(p: &Path) -> String {
    common::read_page(p)
}

#[test]
fn backups_are_versions_not_components() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let o = rtcdoc(
        &[
            "build",
            fixture().to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "-f",
            "html,json,markdown",
        ],
        dir.path(),
    );
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains(
            "note: 4 RTCBuilder backups (older versions of 2 profiles) are not documented as components"
        ),
        "{err}"
    );
    assert!(err.contains("built 2 component profiles into"), "{err}");
    // No finding about a backup's content: the Shift_JIS one is listed, not an RTC005 error.
    assert!(!err.contains("RTC005"), "{err}");
    assert!(err.contains("warning[RTC013]"), "{err}");

    let json: serde_json::Value =
        serde_json::from_str(&read(&out.join("json/catalog.json"))).unwrap();
    let ids: Vec<&String> = json["components"].as_object().unwrap().keys().collect();
    assert_eq!(
        ids,
        [
            "RTC:Lab:Control:Motor:1.0.0",
            "RTC:Lab:Control:PIDController:1.1.0"
        ]
    );
    let backups = &json["components"]["RTC:Lab:Control:PIDController:1.1.0"]["backups"];
    assert_eq!(backups[0]["source"], "PIDController/RTC.xml20150701100000");
    assert_eq!(backups[0]["saved"], "2015-07-01 10:00:00");
    assert!(backups[0]["error"]
        .as_str()
        .unwrap()
        .contains("not valid UTF-8"));
    assert_eq!(backups[1]["saved"], "2015-07-26 07:20:22");
    // A readable backup is a document of its own in the JSON: its whole profile.
    assert_eq!(backups[1]["profile"]["basicInfo"]["version"], "1.0.0");
    assert_eq!(backups[1]["profile"]["dataPorts"][1]["name"], "output");
    assert!(backups[0]["profile"].is_null());
    // catalog.json, backups and all, reads back to the same bytes.
    let bytes = std::fs::read(out.join("json/catalog.json")).unwrap();
    let back = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").expect("reads back");
    let mut again = Vec::new();
    rtcdoc::render::json::write_json_with(&back.catalog, &back.title, false, &mut again).unwrap();
    assert!(again == bytes, "catalog.json round trip differs");
    // The backup's port `output` and placeholders appear nowhere as a component.
    let html = out.join("html");
    for page in [
        "index.html",
        "search-index.js",
        "components/motor.html",
        "types/rtc-timeddouble.html",
    ] {
        let text = read(&html.join(page));
        for bad in [
            "ModuleName",
            "VenderName",
            "RTC.xml2015",
            "RTC.xml2014",
            "Gone",
        ] {
            assert!(!text.contains(bad), "{page} mentions {bad}");
        }
    }
    assert!(!html.join("components/gone.html").exists());
    assert!(!html.join("components/modulename.html").exists());
    // The component page lists its backups with their dates, oldest first.
    let page = read(&html.join("components/pidcontroller.html"));
    let a = page
        .find("<code>RTC.xml20150701100000</code></th><td data-label=\"Saved\">2015-07-01 10:00:00</td><td data-label=\"Declares\">could not be read: ")
        .expect("first backup row");
    let b = page
        .find("<code>RTC.xml20150726072022</code></th><td data-label=\"Saved\">2015-07-26 07:20:22</td><td data-label=\"Declares\">PIDController 1.0.0</td>")
        .expect("second backup row");
    assert!(a < b);
    let md = read(&out.join("markdown/components/pidcontroller.md"));
    assert!(md.contains("`RTC.xml20150726072022`"), "{md}");
    assert!(md.contains("2015-07-26 07:20:22"), "{md}");
}

#[test]
fn check_and_diff_ignore_backups() {
    let dir = tempfile::tempdir().unwrap();
    let o = rtcdoc(&["check", fixture().to_str().unwrap()], dir.path());
    let err = stderr(&o);
    // One warning: the folder whose RTC.xml is gone; nothing from the backups' contents.
    assert!(
        err.contains("check: 0 errors, 1 warning, 0 infos; 2 component profiles"),
        "{err}"
    );
    assert!(err.contains("note: 4 RTCBuilder backups"), "{err}");
    // The hint works when followed: copying the newest backup to RTC.xml documents it.
    assert!(
        err.contains(
            "copy the newest backup `RTC.xml20140202000000.xml` to `RTC.xml` in the same folder"
        ),
        "{err}"
    );
    let copy = dir.path().join("lab");
    copy_dir(&fixture(), &copy);
    std::fs::copy(
        copy.join("Gone/RTC.xml20140202000000.xml"),
        copy.join("Gone/RTC.xml"),
    )
    .unwrap();
    let o = rtcdoc(&["check", "lab"], dir.path());
    let err = stderr(&o);
    assert!(
        err.contains("check: 0 errors, 0 warnings, 0 infos; 3 component profiles"),
        "{err}"
    );
    assert!(
        err.contains("note: 4 RTCBuilder backups (older versions of 2 profiles)"),
        "{err}"
    );

    // diff of the workspace against itself with one more backup: nothing changes.
    let new = dir.path().join("new");
    copy_dir(&fixture(), &new);
    std::fs::copy(
        new.join("PIDController/RTC.xml"),
        new.join("PIDController/RTC.xml20160101000000"),
    )
    .unwrap();
    let o = rtcdoc(
        &[
            "diff",
            fixture().to_str().unwrap(),
            "new",
            "--format",
            "json",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["changes"].as_array().map(Vec::len), Some(0), "{v}");
}

#[test]
fn a_backup_with_the_profiles_id_is_no_duplicate_and_never_stands_in_for_a_broken_profile() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let profile = xml_profile("Arm", &[("DataOutPort", "pose", "RTC::TimedPose2D")]);
    write(&input, "Arm/RTC.xml", &profile);
    write(&input, "Arm/RTC.xml20200101120000", &profile);
    let o = rtcdoc(&["check", "in"], dir.path());
    let err = stderr(&o);
    assert!(!err.contains("RTC010"), "{err}");
    assert!(err.contains("1 component profile"), "{err}");

    // The real RTC.xml is broken: the error is reported; the stale backup is not shown instead.
    write(
        &input,
        "Arm/RTC.xml",
        "<rtc:RtcProfile xmlns:rtc=\"x\"><unclosed>",
    );
    let o = rtcdoc(
        &["build", "in", "-o", "site", "-f", "json", "--allow-empty"],
        dir.path(),
    );
    let err = stderr(&o);
    assert!(err.contains("Arm/RTC.xml"), "{err}");
    let json: serde_json::Value =
        serde_json::from_str(&read(&dir.path().join("site/catalog.json"))).unwrap();
    assert_eq!(json["components"].as_object().map(|m| m.len()), Some(0));
    assert!(err.contains("note: 1 RTCBuilder backup (an older version of 1 profile) is not documented as a component"));

    // A backup named on the command line is read as a profile, whatever its name.
    let o = rtcdoc(&["check", "in/Arm/RTC.xml20200101120000"], dir.path());
    assert!(stderr(&o).contains("1 component profile"), "{}", stderr(&o));
}

#[test]
fn only_orphaned_backups_is_nothing_to_document_with_a_hint_that_works() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(
        &input,
        "Arm/RTC.xml20200101120000",
        &xml_profile("Arm", &[]),
    );
    let o = rtcdoc(&["build", "in", "-o", "site"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("1 RTCBuilder backup(s) without their RTC.xml (to document the newest, copy `Arm/RTC.xml20200101120000` to `Arm/RTC.xml`)"),
        "{err}"
    );
    std::fs::copy(
        input.join("Arm/RTC.xml20200101120000"),
        input.join("Arm/RTC.xml"),
    )
    .unwrap();
    let o = rtcdoc(&["build", "in", "-o", "site"], dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.path().join("site/components/arm.html").exists());
}

#[test]
fn include_and_exclude_still_apply_to_backups() {
    let dir = tempfile::tempdir().unwrap();
    let o = rtcdoc(
        &[
            "check",
            fixture().to_str().unwrap(),
            "--exclude",
            "Gone/**",
            "--exclude",
            "**/RTC.xml2015*",
        ],
        dir.path(),
    );
    let err = stderr(&o);
    assert!(err.contains("check: 0 errors, 0 warnings"), "{err}");
    assert!(
        err.contains("note: 0 RTCBuilder") || !err.contains("RTCBuilder backup"),
        "{err}"
    );
}

#[test]
fn serve_keeps_the_backups_when_the_profile_changes_and_sees_new_ones() {
    use rtcdoc::build::{BuildOptions, LoadOptions};
    use rtcdoc::render::{Format, SiteOptions};
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    copy_dir(&fixture(), &input);
    let opts = BuildOptions {
        input: input.clone(),
        output: dir.path().join("unused"),
        formats: vec![Format::Html],
        strict: false,
        load: LoadOptions::default(),
        site: SiteOptions::default(),
    };
    let mut ws = rtcdoc::incremental::Workspace::open(&opts).expect("open");
    let page = |ws: &rtcdoc::incremental::Workspace| {
        String::from_utf8(ws.files()["components/pidcontroller.html"].clone())
            .unwrap()
            .replace("<wbr>", "")
    };
    assert!(page(&ws).contains("RTC.xml20150726072022"));
    // RTCBuilder saves: the profile changes and a new backup appears.
    let p = input.join("PIDController/RTC.xml");
    let text = read(&p).replace("PID control of a joint", "PID control of one joint");
    std::fs::write(&p, &text).unwrap();
    ws.update(std::slice::from_ref(&p)).expect("update");
    assert!(page(&ws).contains("PID control of one joint"));
    assert!(page(&ws).contains("RTC.xml20150726072022"));
    std::fs::write(input.join("PIDController/RTC.xml20161010101010"), &text).unwrap();
    ws.update(&[input.join("PIDController/RTC.xml20161010101010")])
        .expect("update");
    assert!(page(&ws).contains("2016-10-10 10:10:10"));
    assert_eq!(ws.catalog().components.len(), 2);
    assert_eq!(
        ws.catalog()
            .diagnostics
            .iter()
            .filter(|d| d.code == "RTC013")
            .count(),
        1
    );
}

fn copy_dir(from: &Path, to: &Path) {
    for (rel, bytes) in tree(from) {
        let p = to.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
}
