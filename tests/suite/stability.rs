//! Stability marks (issue 54): a component, data type or interface marked experimental, stable
//! or deprecated, by its profile's `rtcdoc.stability` properties or by `[stability]` of
//! rtcdoc.toml (which wins); shown on every page format and in catalog.json, relaxing `diff`
//! for experimental items, and `check` warning where a deprecated type is used (RTC407).
//!
//! The fixture `tests/fixtures/stability`: Camera is deprecated by its profile (replaced by
//! NewCamera), NewCamera is experimental by its profile, Viewer is experimental by its profile
//! and stable by rtcdoc.toml; `Img::OldImage` and `Img::OldCameraService` are deprecated by
//! rtcdoc.toml.

use crate::common;
use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    common::root().join("tests/fixtures/stability")
}

/// `rtcdoc build` of the fixture (its rtcdoc.toml read) in `formats`, into `out`.
fn build(out: &Path, formats: &str) {
    let input = fixture();
    let o = common::rtcdoc(
        &[
            "build",
            input.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--format",
            formats,
            "--history",
            "0",
        ],
        &common::root(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

fn catalog(out: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(out.join("catalog.json")).unwrap()).unwrap()
}

#[test]
fn both_sources_and_the_file_wins_in_catalog_json() {
    let dir = tempfile::tempdir().unwrap();
    build(dir.path(), "json");
    let c = catalog(dir.path());
    let camera = &c["components"]["RTC:Lab:Sensor:Camera:1.0.0"]["stability"];
    assert_eq!(camera["status"], "deprecated");
    assert_eq!(camera["since"], "2.0");
    assert_eq!(camera["replacement"], "NewCamera");
    assert_eq!(camera["note"], "Removed in 3.0.");
    assert_eq!(camera["origin"], "profile");
    // Experimental by its profile, stable by rtcdoc.toml: the file wins.
    let viewer = &c["components"]["RTC:Lab:View:Viewer:1.0.0"]["stability"];
    assert_eq!(viewer["status"], "stable");
    assert_eq!(viewer["origin"], "config");
    let old = &c["interfaces"]["Img::OldCameraService"]["stability"];
    assert_eq!(old["status"], "deprecated");
    assert_eq!(old["replacement"], "Img::CameraService");
    assert_eq!(
        c["dataTypes"]["Img::OldImage"]["stability"]["status"],
        "deprecated"
    );
    assert!(c["dataTypes"]["Img::Image"].get("stability").is_none());
}

#[test]
fn every_page_format_shows_the_mark_with_the_replacement_linked() {
    let dir = tempfile::tempdir().unwrap();
    build(dir.path(), "html,markdown,doxygen");
    let html = common::read_page(&dir.path().join("html/components/camera.html"));
    assert!(
        html.contains(r#"<p class="stability deprecated" role="note"><strong>Deprecated since 2.0</strong> — use <a href="../components/newcamera.html"><code>NewCamera</code></a>. Removed in 3.0.</p>"#),
        "{html}"
    );
    let html = common::read_page(&dir.path().join("html/components/newcamera.html"));
    assert!(html.contains("<strong>Experimental</strong>"), "{html}");
    let html = common::read_page(&dir.path().join("html/components/viewer.html"));
    assert!(html.contains("<strong>Stable since 1.0</strong>"), "{html}");
    let html = common::read_page(&dir.path().join("html/types/img-oldimage.html"));
    assert!(
        html.contains(r#"— use <a href="../types/img-image.html"><code>Img::Image</code></a></p>"#),
        "{html}"
    );
    let html = common::read_page(&dir.path().join("html/interfaces/img-oldcameraservice.html"));
    assert!(
        html.contains("The old service has no exposure control."),
        "{html}"
    );
    let md = std::fs::read_to_string(dir.path().join("markdown/components/camera.md")).unwrap();
    assert!(
        md.contains("**Deprecated since 2.0** — use [NewCamera](../components/newcamera.md). Removed in 3.0."),
        "{md}"
    );
    let md = std::fs::read_to_string(dir.path().join("markdown/types/img-oldimage.md")).unwrap();
    assert!(
        md.contains("**Deprecated since 2.0** — use [Img::Image]("),
        "{md}"
    );
    let dox: String = common::tree(&dir.path().join("doxygen"))
        .into_iter()
        .map(|(_, bytes)| String::from_utf8_lossy(&bytes).into_owned())
        .collect();
    assert!(
        dox.contains("/// \\deprecated <b>Deprecated since 2.0</b> — use \\ref "),
        "{dox}"
    );
    assert!(dox.contains("<p><b>Experimental</b></p>"), "{dox}");
}

#[test]
fn japanese_pages_say_it_in_japanese() {
    let dir = tempfile::tempdir().unwrap();
    let input = fixture();
    let o = common::rtcdoc(
        &[
            "build",
            input.to_str().unwrap(),
            "-o",
            dir.path().to_str().unwrap(),
            "--language",
            "ja",
            "--history",
            "0",
        ],
        &common::root(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = common::read_page(&dir.path().join("components/camera.html"));
    assert!(
        html.contains("<strong>2.0 から非推奨</strong> — 代わりに <a href=\"../components/newcamera.html\"><code>NewCamera</code></a> を使用"),
        "{html}"
    );
}

#[test]
fn check_warns_where_a_deprecated_type_is_used_naming_the_replacement() {
    let input = fixture();
    let found = common::findings(&common::root(), input.to_str().unwrap(), &["RTC407"]);
    let messages: Vec<&str> = found
        .iter()
        .map(|d| d["message"].as_str().unwrap())
        .collect();
    assert_eq!(found.len(), 4, "{messages:#?}");
    assert!(messages.contains(
        &"data port `image` uses `Img::OldImage`, deprecated since 2.0; use `Img::Image` instead"
    ));
    assert!(messages.contains(
        &"service interface `cam` of port `control` uses `Img::OldCameraService`, deprecated since 2.0; use `Img::CameraService` instead (The old service has no exposure control.)"
    ));
    let hint = found[0]["hint"].as_str().unwrap();
    assert!(hint.contains("`Img::"), "{hint}");
}

/// A profile of a component `Comp` whose one provided interface has `interface` as its type,
/// with `properties` (XML) in its BasicInfo.
fn profile(interface: &str, properties: &str) -> String {
    let good =
        std::fs::read_to_string(common::root().join("tests/fixtures/check/RTC407-good/A.xml"))
            .unwrap();
    good.replace("Svc::NewService", interface).replace(
        "    <rtcDoc:Doc rtcDoc:description=\"A test component\"/>\n",
        &format!("    <rtcDoc:Doc rtcDoc:description=\"A test component\"/>\n{properties}"),
    )
}

fn diff(dir: &Path, new: &str, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["diff", "old", new];
    args.extend(extra);
    common::rtcdoc(&args, dir)
}

#[test]
fn diff_relaxes_breaking_changes_of_experimental_items_to_warnings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "old/A.xml", &profile("Svc::One", ""));
    common::write(d, "new/A.xml", &profile("Svc::Two", ""));
    let experimental =
        "    <rtcExt:Properties rtcExt:name=\"rtcdoc.stability\" rtcExt:value=\"experimental\"/>\n";
    common::write(d, "marked/A.xml", &profile("Svc::Two", experimental));
    // Before: the interface's type changed, a breaking change.
    let o = diff(d, "new", &[]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("breaking[DIFF107]"), "{out}");
    // The component marked experimental on the NEW side: a warning, saying why.
    let o = diff(d, "marked", &[]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("warning[DIFF107]"), "{out}");
    assert!(
        out.contains("(relaxed: experimental — component `Comp` is experimental)"),
        "{out}"
    );
    let o = diff(d, "marked", &["--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let c = json["changes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["code"] == "DIFF107")
        .unwrap();
    assert_eq!(c["severity"], "warning");
    assert_eq!(c["defaultSeverity"], "breaking");
    assert_eq!(c["relaxed"], "experimental");
    assert_eq!(c["relaxedFor"], "component `Comp`");
    for format in ["markdown", "github"] {
        let o = diff(d, "marked", &["--format", format]);
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(out.contains("relaxed: experimental"), "{format}: {out}");
    }
}

#[test]
fn diff_relaxes_for_an_experimental_interface_of_rtcdoc_toml() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "old/A.xml", &profile("Svc::One", ""));
    common::write(d, "new/A.xml", &profile("Svc::Two", ""));
    common::write(
        d,
        "new/rtcdoc.toml",
        "[stability.\"Svc::Two\"]\nstatus = \"experimental\"\n",
    );
    let o = diff(d, "new", &[]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(
        out.contains("(relaxed: experimental — interface `Svc::Two` is experimental)"),
        "{out}"
    );
}

#[test]
fn bad_configuration_is_an_error_or_a_warning_with_a_hint() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "in/A.xml", &profile("Svc::One", ""));
    // An unknown status: an error at its place, with the nearest status.
    common::write(
        d,
        "in/rtcdoc.toml",
        "[stability.\"Svc::One\"]\nstatus = \"experimantal\"\n",
    );
    let o = common::rtcdoc(&["check", "in"], d);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("rtcdoc.toml:2:10"), "{err}");
    assert!(err.contains("did you mean `experimental`?"), "{err}");
    // An unknown key of a table.
    common::write(
        d,
        "in/rtcdoc.toml",
        "[stability.\"Svc::One\"]\nstatus = \"deprecated\"\nreplacment = \"X\"\n",
    );
    let o = common::rtcdoc(&["check", "in"], d);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("replacment"), "{err}");
    // A key naming nothing: RTC408 at the key, with the nearest name.
    common::write(
        d,
        "in/rtcdoc.toml",
        "title = \"x\"\n\n[stability.\"Svc::Onne\"]\nstatus = \"deprecated\"\n",
    );
    let found = common::findings(d, "in", &["RTC408"]);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!(found[0]["severity"], "warning");
    assert_eq!(found[0]["line"], 3, "{found:#?}");
    assert_eq!(found[0]["file"], "in/rtcdoc.toml");
    assert!(
        found[0]["message"]
            .as_str()
            .unwrap()
            .contains("`Svc::Onne` names no component"),
        "{found:#?}"
    );
    assert!(
        found[0]["hint"]
            .as_str()
            .unwrap()
            .contains("did you mean `Svc::One`?"),
        "{found:#?}"
    );
}

#[test]
fn diff_208_becomes_information_when_every_breaking_change_is_relaxed() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "old/A.xml", &profile("Svc::One", ""));
    common::write(d, "new/A.xml", &profile("Svc::Two", ""));
    // Without the mark: a breaking change under the same version, so DIFF208 warns.
    let o = diff(d, "new", &["--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let bump = |json: &serde_json::Value| {
        json["changes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["code"] == "DIFF208")
            .cloned()
            .expect("a DIFF208")
    };
    assert_eq!(bump(&json)["severity"], "warning");
    // The changed interface experimental: its change is a warning, and DIFF208 information.
    common::write(
        d,
        "new/rtcdoc.toml",
        "[stability.\"Svc::Two\"]\nstatus = \"experimental\"\n",
    );
    let o = diff(d, "new", &["--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let b = bump(&json);
    assert_eq!(b["severity"], "info", "{b}");
    assert_eq!(b["defaultSeverity"], "warning", "{b}");
    assert_eq!(
        b["relaxedFor"], "every breaking change of `RTC:Test:Cat:Comp:1.0.0`",
        "{b}"
    );
    let o = diff(d, "new", &["--fail-on", "warning"]);
    let out = String::from_utf8_lossy(&o.stdout);
    // DIFF107 is still a warning, so --fail-on warning fails; DIFF208 is information.
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("info[DIFF208]"), "{out}");
    assert!(
        out.contains("(relaxed: experimental — every breaking change of `RTC:Test:Cat:Comp:1.0.0` is relaxed)"),
        "{out}"
    );
}

#[test]
fn history_relaxes_the_versions_of_an_experimental_component() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    let experimental =
        "    <rtcExt:Properties rtcExt:name=\"rtcdoc.stability\" rtcExt:value=\"experimental\"/>\n";
    let versions = vec![
        ("first", profile("Svc::One", "")),
        // Marked experimental in the same commit that changes the interface's type.
        ("experimental", profile("Svc::Two", experimental)),
        // The mark removed: the next breaking change is breaking again.
        ("stable", profile("Svc::Three", "")),
    ];
    if !common::history_repo::commit_versions(&repo, versions) {
        common::missing_tool("git");
        return;
    }
    let out = dir.path().join("site");
    common::history_repo::build(&repo, &out, &["-f", "json,html"]);
    let cat: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("json/catalog.json")).unwrap())
            .unwrap();
    let history = cat["components"]["RTC:Test:Cat:Comp:1.0.0"]["history"]
        .as_array()
        .expect("a history");
    let change = |entry: &serde_json::Value, code: &str| {
        entry["changes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["code"] == code)
            .cloned()
            .unwrap_or_else(|| panic!("{code} in {entry}"))
    };
    // Newest first: "stable", then "experimental".
    assert_eq!(history[0]["subject"], "stable");
    assert_eq!(change(&history[0], "DIFF107")["severity"], "breaking");
    assert_eq!(history[1]["subject"], "experimental");
    let relaxed = change(&history[1], "DIFF107");
    assert_eq!(relaxed["severity"], "warning", "{relaxed}");
    assert!(
        relaxed["message"]
            .as_str()
            .unwrap()
            .ends_with("(relaxed: experimental — component `Comp` is experimental)"),
        "{relaxed}"
    );
    let html = common::read_page(&out.join("html/history/comp.html"));
    assert!(
        html.contains("component <code>Comp</code> is experimental"),
        "{html}"
    );
}
