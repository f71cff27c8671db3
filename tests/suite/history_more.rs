//! History beyond components (issue 25): each RT System profile's commits compared with the
//! system diff engine, each IDL file's commits compared type by type, a profile followed to an
//! older path by its component id when git's `--follow` loses it, and the Source links of
//! system and IDL pages.

use crate::common;
use common::history_repo::{build, build_source_project, codes, commit, edit as with, init, page};
use common::OutputWithin;
use common::{root, write};
use serde_json::Value;
use std::path::Path;

fn fixture(rel: &str) -> String {
    std::fs::read_to_string(root().join("tests/fixtures").join(rel)).unwrap()
}

/// The commits of `systems/NavSystem.xml`, oldest first: the first version, a new version of
/// an instance's component (DIFF251), white space only, a release (a new system id version).
fn system_repository(d: &Path) -> bool {
    if !init(d) {
        return false;
    }
    let v1 = fixture("diff/DIFF251/old/systems/NavSystem.xml");
    let v2 = fixture("diff/DIFF251/new/systems/NavSystem.xml");
    let v3 = with(&v2, &[("    <rts:Components", "\n    <rts:Components")]);
    let v4 = with(
        &v3,
        &[("RTSystem:Lab:NavSystem:1.0", "RTSystem:Lab:NavSystem:2.0")],
    );
    write(
        d,
        "rtcdoc.toml",
        "source-url = \"https://example.org/lab/blob/{commit}/{path}\"\n",
    );
    for (day, (subject, text)) in [
        ("First system", &v1),
        ("Upgrade Base", &v2),
        ("Reformat", &v3),
        ("Release 2.0", &v4),
    ]
    .into_iter()
    .enumerate()
    {
        write(d, "systems/NavSystem.xml", text);
        commit(d, day + 1, subject);
    }
    true
}

#[test]
fn a_system_has_its_history_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !system_repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json,html,markdown,doxygen"]);
    let json: Value = serde_json::from_str(&page(&site, "json/catalog.json")).unwrap();
    let s = &json["systems"]["systems/NavSystem.xml"];
    let h = s["history"].as_array().expect("a history");
    let subjects: Vec<&str> = h.iter().map(|e| e["subject"].as_str().unwrap()).collect();
    assert_eq!(
        subjects,
        ["Release 2.0", "Reformat", "Upgrade Base", "First system"],
        "{h:#?}"
    );
    assert_eq!(h[0]["version"], "2.0");
    assert_eq!(h[0]["release"], true);
    assert_eq!(h[1]["version"], "1.0");
    assert!(h[1]["changes"].as_array().unwrap().is_empty(), "{h:#?}");
    assert_eq!(codes(&h[2]), ["DIFF251"], "{h:#?}");
    let upgrade = &h[2]["changes"][0];
    assert_eq!(upgrade["file"], "systems/NavSystem.xml");
    assert_eq!(upgrade["oldFile"], "systems/NavSystem.xml");
    assert_eq!(upgrade["component"], "RTSystem:Lab:NavSystem:1.0");
    assert_eq!(h[3]["first"], true);

    // Read back with its history.
    let bytes = std::fs::read(site.join("json/catalog.json")).unwrap();
    let read = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").unwrap();
    assert_eq!(
        serde_json::to_value(&read.catalog.systems[0].history).unwrap(),
        s["history"]
    );

    // The system page: a History section, each commit linked to the file at that commit, and
    // the Source linked.
    let html = page(&site, "html/systems/navsystem.html");
    let section = &html[html
        .find("<section id=\"change-history\">")
        .expect("a History section")..];
    let section = &section[..section.find("</section>").unwrap()];
    let rows: Vec<&str> = section.split("<tr>").skip(2).collect();
    assert_eq!(rows.len(), 4, "{section}");
    assert!(rows[0].contains("2.0 (release)"), "{}", rows[0]);
    assert!(rows[1].contains("1 version without changes"), "{}", rows[1]);
    assert!(rows[2].contains("Upgrade Base"), "{}", rows[2]);
    assert!(rows[2].contains("1 warning"), "{}", rows[2]);
    let commit = h[2]["commit"].as_str().unwrap();
    assert!(
        rows[2].contains(&format!(
            "<a href=\"https://example.org/lab/blob/{commit}/systems/NavSystem.xml\"><code>{}</code></a>",
            &commit[..12]
        )),
        "{}",
        rows[2]
    );
    assert!(
        rows[3].contains("first version in the history"),
        "{}",
        rows[3]
    );
    let md = page(&site, "markdown/systems/navsystem.md");
    assert!(md.contains("## History"), "{md}");
    assert!(md.contains("Upgrade Base"), "{md}");
    assert!(md.contains("2.0 (release)"), "{md}");
    let dox = page(&site, "doxygen/systems/navsystem.dox");
    assert!(dox.contains("Upgrade Base"), "{dox}");
    assert!(dox.contains("2.0 (release)"), "{dox}");
}

fn serve_options(input: &Path) -> rtcdoc::build::BuildOptions {
    let mut load = rtcdoc::build::LoadOptions {
        history: 100,
        history_reader: Some(rtcdoc::history::attach),
        ..Default::default()
    };
    load.skip_dirs.push(input.join("site"));
    rtcdoc::build::BuildOptions {
        input: input.to_path_buf(),
        output: input.join("site"),
        formats: vec![rtcdoc::render::Format::Html],
        strict: false,
        load,
        site: rtcdoc::render::SiteOptions::default(),
    }
}

fn text(ws: &rtcdoc::incremental::Workspace, rel: &str) -> String {
    String::from_utf8_lossy(&ws.files()[rel]).to_string()
}

#[test]
fn serve_shows_the_history_and_updates_it_after_an_edit() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !system_repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let arm = common::xml_profile("Arm", &[("DataInPort", "cmd", "RTC::TimedLong")]);
    write(&repo, "Arm/RTC.xml", &arm);
    commit(&repo, 5, "Add Arm");
    let edited = with(&arm, &[("rtc:name=\"cmd\"", "rtc:name=\"target\"")]);
    write(&repo, "Arm/RTC.xml", &edited);
    commit(&repo, 6, "Rename cmd");

    // Opened: the pages carry the history as `build` writes it.
    let opts = serve_options(&repo);
    let mut ws = rtcdoc::incremental::Workspace::open(&opts).unwrap();
    let page = text(&ws, "components/arm.html");
    assert!(page.contains("<section id=\"change-history\">"), "{page}");
    assert!(page.contains("Rename cmd"), "{page}");
    assert!(text(&ws, "systems/navsystem.html").contains("Upgrade Base"));

    // An uncommitted edit: an incremental update, the edited profile's history read again
    // (a working-copy version first), the system's and the rest kept.
    let path = repo.join("Arm/RTC.xml");
    write(
        &repo,
        "Arm/RTC.xml",
        &with(&edited, &[("rtc:name=\"target\"", "rtc:name=\"goal\"")]),
    );
    let r = ws.update(std::slice::from_ref(&path)).unwrap();
    assert!(!r.full, "{r:?}");
    let h = &ws.catalog().components[0].history;
    assert_eq!(h.len(), 3, "{h:#?}");
    assert!(h[0].commit.is_none() && h[0].changes.iter().any(|c| c.severity == "breaking"));
    assert!(text(&ws, "components/arm.html").contains("working copy (not committed)"));
    assert_eq!(ws.catalog().systems[0].history.len(), 4);
    // The same site as a clean start.
    let clean = rtcdoc::incremental::Workspace::open(&opts).unwrap();
    assert_eq!(
        ws.files().keys().collect::<Vec<_>>(),
        clean.files().keys().collect::<Vec<_>>()
    );
    for (k, v) in clean.files() {
        assert!(ws.files()[k] == *v, "{k} differs from a clean start");
    }
    // Only the edited profile's history is read again: a commit to the system file (which
    // this update is not told of) does not show until the system is reloaded.
    let system = repo.join("systems/NavSystem.xml");
    let text = common::read_page(&system);
    std::fs::write(&system, format!("{text}\n")).unwrap();
    write(&repo, "Arm/RTC.xml", &edited); // back as committed
    commit(&repo, 7, "Touch the system");
    let r = ws.update(std::slice::from_ref(&path)).unwrap();
    assert!(!r.full, "{r:?}");
    assert_eq!(ws.catalog().components[0].history.len(), 2);
    assert_eq!(ws.catalog().systems[0].history.len(), 4);
    let r = ws.update(std::slice::from_ref(&system)).unwrap();
    assert!(r.full, "{r:?}");
    assert_eq!(ws.catalog().systems[0].history.len(), 5);
}

/// The commits of `idl/Nav.idl` beside a component using its types, oldest first: the first
/// version, a member added to a type a port carries, a new type, the new type removed again.
fn idl_repository(d: &Path) -> bool {
    if !init(d) {
        return false;
    }
    let v1 = fixture("diff/DIFF131/old/idl/Nav.idl");
    let v2 = fixture("diff/DIFF131/new/idl/Nav.idl");
    let v3 = with(
        &v2,
        &[(
            "  struct Time\n",
            "  struct Battery\n  {\n    double voltage;\n  };\n\n  struct Time\n",
        )],
    );
    write(d, "Nav/RTC.xml", &fixture("diff/DIFF131/old/Nav/RTC.xml"));
    for (day, (subject, text)) in [
        ("First IDL", v1),
        ("Add speed", v2.clone()),
        ("Add Battery", v3),
        ("Drop Battery", v2),
    ]
    .into_iter()
    .enumerate()
    {
        write(d, "idl/Nav.idl", &text);
        commit(d, day + 1, subject);
    }
    true
}

/// The page of `name` among the data type pages of `site` (the page says which type it is in
/// its heading).
fn type_page(site: &Path, dir: &str, ext: &str, name: &str) -> String {
    for e in std::fs::read_dir(site.join(dir)).unwrap() {
        let p = e.unwrap().path();
        if p.extension().and_then(|e| e.to_str()) == Some(ext) {
            let text = common::read_page(&p);
            if text.contains(&format!("<code>{name}</code></h1>"))
                || text.contains(&format!("# {name}\n"))
                || text.contains(&format!("# `{name}`\n"))
                || text.lines().next().is_some_and(|l| l.ends_with(name))
            {
                return text;
            }
        }
    }
    panic!("no page of {name} in {dir}");
}

#[test]
fn an_idl_file_has_its_history_on_the_pages_of_its_types() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !idl_repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json,html,markdown,doxygen"]);
    let json: Value = serde_json::from_str(&page(&site, "json/catalog.json")).unwrap();
    let file = &json["idl"]["files"][0];
    assert_eq!(file["path"], "idl/Nav.idl");
    let h = file["history"].as_array().expect("a history");
    let subjects: Vec<&str> = h.iter().map(|e| e["subject"].as_str().unwrap()).collect();
    assert_eq!(
        subjects,
        ["Drop Battery", "Add Battery", "Add speed", "First IDL"],
        "{h:#?}"
    );
    assert_eq!(codes(&h[0]), ["DIFF140"], "{h:#?}");
    assert_eq!(h[0]["changes"][0]["path"], "idl/Nav::Battery");
    assert_eq!(h[0]["changes"][0]["component"], "idl/Nav.idl");
    assert_eq!(h[0]["changes"][0]["oldFile"], "idl/Nav.idl");
    assert!(h[0]["changes"][0]["oldLine"].as_u64().unwrap() > 0);
    assert_eq!(codes(&h[1]), ["DIFF334"], "{h:#?}");
    // The member added, under the type holding it (no other type holds that one).
    assert_eq!(codes(&h[2]), ["DIFF131"], "{h:#?}");
    assert_eq!(
        h[2]["changes"][0]["path"],
        "idl/Nav::TimedOdometry/fields/speed"
    );
    assert_eq!(h[3]["first"], true);

    // Read back with the history.
    let bytes = std::fs::read(site.join("json/catalog.json")).unwrap();
    let read = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").unwrap();
    assert_eq!(
        serde_json::to_value(&read.catalog.idl_history["idl/Nav.idl"]).unwrap(),
        file["history"]
    );

    // The page of a type the file defines shows the file's history, in every output.
    let html = type_page(&site, "html/types", "html", "Nav::TimedOdometry");
    let section = &html[html
        .find("<section id=\"idl-file\">")
        .expect("an IDL file section")..];
    let section = &section[..section.find("</section>").unwrap()];
    assert!(section.contains("<code>idl/Nav.idl</code>"), "{section}");
    let rows: Vec<&str> = section.split("<tr>").skip(2).collect();
    assert_eq!(rows.len(), 4, "{section}");
    assert!(rows[0].contains("Drop Battery") && rows[0].contains("1 breaking"));
    assert!(
        rows[0].contains(
            "<li><span class=\"sev breaking\">breaking</span> <code>idl/Nav::Battery</code>: "
        ),
        "{}",
        rows[0]
    );
    let iface = type_page(&site, "html/interfaces", "html", "Nav::MapService");
    assert!(iface.contains("<section id=\"idl-file\">"), "{iface}");
    let md = type_page(&site, "markdown/types", "md", "Nav::TimedOdometry");
    assert!(md.contains("## IDL file"), "{md}");
    assert!(md.contains("Drop Battery"), "{md}");
    let dox = type_page(&site, "doxygen/types", "dox", "Nav::TimedOdometry");
    assert!(dox.contains("Drop Battery"), "{dox}");
}

#[test]
fn a_source_repository_links_systems_and_idl_files_at_the_pinned_commit() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !idl_repository(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    write(
        &repo,
        "systems/NavSystem.xml",
        &fixture("diff/DIFF251/old/systems/NavSystem.xml"),
    );
    commit(&repo, 9, "Add the system");
    let out = build_source_project(dir.path(), "json,html,markdown,doxygen");
    let json: Value = serde_json::from_str(&page(&out, "json/catalog.json")).unwrap();
    let pinned = json["sources"][0]["commit"].as_str().unwrap().to_string();
    let system = &json["systems"]["lab/systems/NavSystem.xml"];
    assert_eq!(system["history"][0]["subject"], "Add the system");
    assert_eq!(
        json["idl"]["files"][0]["history"][0]["subject"],
        "Drop Battery"
    );
    let system_url = format!("https://git.example.org/lab/blob/{pinned}/systems/NavSystem.xml");
    let idl_url = format!("https://git.example.org/lab/blob/{pinned}/idl/Nav.idl");
    let html = page(&out, "html/systems/navsystem.html");
    assert!(
        html.contains(&format!(
            "<dd><a href=\"{system_url}\"><code>lab/systems/NavSystem.xml</code></a></dd>"
        )),
        "{html}"
    );
    let md = page(&out, "markdown/systems/navsystem.md");
    assert!(md.contains(&format!("]({system_url})")), "{md}");
    let dox = page(&out, "doxygen/systems/navsystem.dox");
    assert!(dox.contains(&system_url), "{dox}");
    let html = type_page(&out, "html/types", "html", "Nav::TimedOdometry");
    assert!(
        html.contains(&format!(
            "<a href=\"{idl_url}\"><code>lab/idl/Nav.idl</code></a>"
        )),
        "{html}"
    );
    let md = type_page(&out, "markdown/types", "md", "Nav::TimedOdometry");
    assert!(md.contains(&format!("]({idl_url})")), "{md}");
    let dox = type_page(&out, "doxygen/types", "dox", "Nav::TimedOdometry");
    assert!(dox.contains(&idl_url), "{dox}");
}

/// The history of component `RTC:Test:Cat:Base:1.0.0` in the catalog.json of `site`.
fn base_history(site: &Path) -> Vec<Value> {
    history_of(site, "RTC:Test:Cat:Base:1.0.0")
}

/// The history of component `id` in the catalog.json of `site`.
fn history_of(site: &Path, id: &str) -> Vec<Value> {
    let json: Value = serde_json::from_str(&page(site, "catalog.json")).unwrap();
    json["components"][id]["history"]
        .as_array()
        .expect("a history")
        .clone()
}

/// (subject, file) of each history entry.
fn subjects_and_files(h: &[Value]) -> Vec<(&str, &str)> {
    h.iter()
        .map(|e| (e["subject"].as_str().unwrap(), e["file"].as_str().unwrap()))
        .collect()
}

#[test]
fn a_profile_moved_and_rewritten_is_followed_by_its_component_id() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !init(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let base = common::xml_profile("Base", &[("DataInPort", "cmd", "RTC::TimedLong")]);
    write(&repo, "Base/RTC.xml", &base);
    write(
        &repo,
        "Other/RTC.xml",
        &common::xml_profile("Other", &[("DataInPort", "in", "RTC::TimedLong")]),
    );
    commit(&repo, 1, "First");
    let edited = with(&base, &[("rtc:name=\"cmd\"", "rtc:name=\"command\"")]);
    write(&repo, "Base/RTC.xml", &edited);
    commit(&repo, 2, "Edit");
    // The folder renamed and the file rewritten in one commit: too different for git's rename
    // detection. Another profile (another component) goes in the same commit.
    let ports: Vec<(String, String)> = (0..20)
        .map(|i| (format!("out{i}"), "RTC::TimedDouble".to_string()))
        .collect();
    let mut all: Vec<(&str, &str, &str)> = vec![("DataInPort", "command", "RTC::TimedLong")];
    all.extend(
        ports
            .iter()
            .map(|(n, t)| ("DataOutPort", n.as_str(), t.as_str())),
    );
    let rewritten = common::xml_profile("Base", &all);
    std::fs::remove_dir_all(repo.join("Base")).unwrap();
    std::fs::remove_dir_all(repo.join("Other")).unwrap();
    write(&repo, "mobile/base/RTC.xml", &rewritten);
    commit(&repo, 3, "Reorganise");
    // git itself loses it.
    let follow = std::process::Command::new("git")
        .args([
            "log",
            "--follow",
            "--format=%s",
            "--",
            "mobile/base/RTC.xml",
        ])
        .current_dir(&repo)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&follow.stdout).trim(), "Reorganise");

    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json"]);
    let h = base_history(&site);
    let found = subjects_and_files(&h);
    assert_eq!(
        found,
        [
            ("Reorganise", "mobile/base/RTC.xml"),
            ("Edit", "Base/RTC.xml"),
            ("First", "Base/RTC.xml")
        ],
        "{h:#?}"
    );
    // Compared across the move: the ports added, with both files named.
    assert_eq!(codes(&h[0]).len(), 20, "{h:#?}");
    assert!(codes(&h[0]).iter().all(|c| *c == "DIFF301"));
    assert_eq!(h[0]["changes"][0]["oldFile"], "Base/RTC.xml");
    assert_eq!(h[2]["first"], true);
    // `--history 2` stops there.
    let site = dir.path().join("site2");
    build(&repo, &site, &["-f", "json", "--history", "2"]);
    let h = base_history(&site);
    assert_eq!(h.len(), 2);
    assert_eq!(h[1]["subject"], "Edit");
}

#[test]
fn a_profile_copied_then_deleted_later_is_followed_to_the_original() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !init(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let base = common::xml_profile("Base", &[("DataInPort", "cmd", "RTC::TimedLong")]);
    write(&repo, "old/Base/RTC.xml", &base);
    commit(&repo, 1, "First");
    // A copy at a new path (the original stays), edited later, the original deleted later.
    write(&repo, "new/Base/RTC.xml", &base);
    commit(&repo, 2, "Copy");
    let edited = with(&base, &[("rtc:name=\"cmd\"", "rtc:name=\"command\"")]);
    write(&repo, "new/Base/RTC.xml", &edited);
    commit(&repo, 3, "Edit the copy");
    std::fs::remove_dir_all(repo.join("old")).unwrap();
    commit(&repo, 4, "Drop the original");
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json"]);
    let h = base_history(&site);
    let found = subjects_and_files(&h);
    assert_eq!(
        found,
        [
            ("Edit the copy", "new/Base/RTC.xml"),
            ("Copy", "new/Base/RTC.xml"),
            ("First", "old/Base/RTC.xml")
        ],
        "{h:#?}"
    );
    // The copy changed nothing; the original is the first version.
    assert!(h[1]["changes"].as_array().unwrap().is_empty(), "{h:#?}");
    assert_eq!(h[2]["first"], true);
    // The id changes after the copy (a new vendor): the original, which has the id of before,
    // is still found (it was compared with today's id only, and the history stopped at the
    // copy).
    let moved = with(
        &edited,
        &[
            ("RTC:Test:Cat:Base", "RTC:Lab:Cat:Base"),
            ("rtc:vendor=\"Test\"", "rtc:vendor=\"Lab\""),
        ],
    );
    write(&repo, "new/Base/RTC.xml", &moved);
    commit(&repo, 5, "New vendor");
    let site = dir.path().join("site-vendor");
    build(&repo, &site, &["-f", "json"]);
    let h = history_of(&site, "RTC:Lab:Cat:Base:1.0.0");
    let found: Vec<&str> = subjects_and_files(&h).into_iter().map(|(s, _)| s).collect();
    assert_eq!(
        found,
        ["New vendor", "Edit the copy", "Copy", "First"],
        "{h:#?}"
    );
}

#[test]
fn a_copy_whose_original_stays_starts_a_history_of_its_own() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !init(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let ports = [
        ("DataInPort", "cmd", "RTC::TimedLong"),
        ("DataOutPort", "status", "RTC::TimedLong"),
        ("DataOutPort", "odometry", "RTC::TimedDouble"),
    ];
    let original = common::xml_profile("Orig", &ports);
    write(&repo, "Orig/RTC.xml", &original);
    commit(&repo, 1, "First");
    let edited = with(&original, &[("rtc:name=\"cmd\"", "rtc:name=\"command\"")]);
    write(&repo, "Orig/RTC.xml", &edited);
    commit(&repo, 2, "Edit the original");
    // Another component made from a copy of the original, which stays.
    write(&repo, "Base/RTC.xml", &edited.replace("Orig", "Base"));
    commit(&repo, 3, "Copy");
    // git's --follow takes the copy for the original's history.
    let follow = std::process::Command::new("git")
        .args(["log", "--follow", "--format=%s", "--", "Base/RTC.xml"])
        .current_dir(&repo)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    let text = String::from_utf8_lossy(&follow.stdout);
    assert!(text.contains("First"), "{text}");
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json"]);
    let h = base_history(&site);
    assert_eq!(subjects_and_files(&h), [("Copy", "Base/RTC.xml")], "{h:#?}");
    assert_eq!(h[0]["first"], true, "{h:#?}");
}

/// A profile whose file is its newest commit byte for byte is that version (not parsed again),
/// and the same blob, an older version of another profile, is still read for that one.
#[test]
fn a_blob_that_is_one_file_and_another_s_older_version_is_read_for_both() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !init(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let base = common::xml_profile("Base", &[("DataInPort", "cmd", "RTC::TimedLong")]);
    write(&repo, "a/RTC.xml", &base);
    write(&repo, "b/RTC.xml", &base);
    commit(&repo, 1, "Two copies");
    let other = common::xml_profile("Other", &[("DataOutPort", "out", "RTC::TimedLong")]);
    write(&repo, "b/RTC.xml", &other);
    commit(&repo, 2, "The second becomes Other");
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json"]);
    let json: Value = serde_json::from_str(&page(&site, "catalog.json")).unwrap();
    let a = json["components"]["RTC:Test:Cat:Base:1.0.0"]["history"]
        .as_array()
        .expect("a history of a/");
    // The file as it is: the commit itself, no version of its own.
    assert_eq!(a.len(), 1, "{a:#?}");
    assert_eq!(a[0]["subject"], "Two copies");
    assert_eq!(a[0]["version"], "1.0.0");
    assert_eq!(a[0]["first"], true);
    let b = json["components"]["RTC:Test:Cat:Other:1.0.0"]["history"]
        .as_array()
        .expect("a history of b/");
    assert_eq!(b.len(), 2, "{b:#?}");
    // The older version, a's blob, read and compared with the newer.
    assert!(b[1].get("error").is_none(), "{b:#?}");
    assert_eq!(b[1]["first"], true);
    assert!(b[0].get("error").is_none(), "{b:#?}");
    assert!(!codes(&b[0]).is_empty(), "{b:#?}");
}

/// `rtcdoc build INPUT -o OUT -f json` with `env`: its stderr, and the subjects of the history
/// of component `RTC:Lab:Mobile:Base:1.1.0` (from `history_repo`).
fn build_warnings(input: &Path, out: &Path, env: &[(&str, &Path)]) -> (String, Vec<String>) {
    let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"));
    c.args([
        "build",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "-f",
        "json",
    ])
    .current_dir(input)
    .env("NO_COLOR", "1");
    for (k, v) in env {
        c.env(k, v);
    }
    let o = c.output_within(common::COMMAND_LIMIT).unwrap();
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    let json: Value = serde_json::from_str(&page(out, "catalog.json")).unwrap();
    let subjects = json["components"]["RTC:Lab:Mobile:Base:1.1.0"]["history"]
        .as_array()
        .map(|h| {
            h.iter()
                .map(|e| e["subject"].as_str().unwrap_or_default().to_string())
                .collect()
        })
        .unwrap_or_default();
    (err, subjects)
}

/// A temporary directory with `repo`, a work tree of [`common::history_repo::history_repo`];
/// `None` without git.
fn history_repo() -> Option<(tempfile::TempDir, std::path::PathBuf)> {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !common::history_repo::history_repo(&repo) {
        crate::common::missing_tool("git not available");
        return None;
    }
    Some((dir, repo))
}

/// The command in backticks after `before` in a warning line.
fn command_after(err: &str, before: &str) -> Vec<String> {
    let rest = err.split(before).nth(1).expect(before);
    let cmd = rest.split('`').nth(1).expect("a command in backticks");
    cmd.split(' ').map(str::to_string).collect()
}

/// What `rtcdoc serve DIR` prints up to "serving at …" (then it is stopped).
fn serve_first_lines(input: &Path) -> String {
    let input = input.to_string_lossy();
    let (mut child, _, lines) =
        common::serve_until_ready(&["serve", "--port", "0", &input], Path::new("."));
    let _ = child.kill();
    let _ = child.wait();
    lines.join("\n")
}

#[test]
fn a_shallow_clone_is_named_and_the_hint_fetches_the_whole_history() {
    let Some((dir, repo)) = history_repo() else {
        return;
    };
    let clone = dir.path().join("clone");
    let url = format!("file://{}", repo.display());
    let o = std::process::Command::new("git")
        .args(["clone", "-q", "--depth", "1", &url])
        .arg(&clone)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (err, subjects) = build_warnings(&clone, &dir.path().join("s1"), &[]);
    assert_eq!(subjects, ["Rename cmd"], "{err}");
    assert!(
        err.contains("warning: history: the repository at `") && err.contains("is a shallow clone"),
        "{err}"
    );
    // `rtcdoc serve` says the same before it serves.
    let serve = serve_first_lines(&clone);
    assert!(
        serve.contains("warning: history: the repository at `")
            && serve.contains("is a shallow clone"),
        "{serve}"
    );
    // The hint, followed, fetches the whole history: no warning, every commit.
    let hint = command_after(&err, "fetch the whole history (");
    assert_eq!(hint, ["git", "fetch", "--unshallow"]);
    let o = std::process::Command::new(&hint[0])
        .args(&hint[1..])
        .current_dir(&clone)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (err, subjects) = build_warnings(&clone, &dir.path().join("s2"), &[]);
    assert!(!err.contains("warning: history"), "{err}");
    assert_eq!(subjects.len(), 4, "{subjects:?}");
}

#[test]
fn a_repository_git_refuses_is_named_and_the_hint_makes_it_read() {
    // Only root can give the repository to another user (git refuses a repository that another
    // user owns: "dubious ownership").
    let is_root = std::process::Command::new("id")
        .arg("-u")
        .output_within(common::COMMAND_LIMIT)
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !is_root {
        println!("skipped: needs root to give the repository to another user");
        return;
    }
    let Some((dir, repo)) = history_repo() else {
        return;
    };
    for e in walkdir::WalkDir::new(&repo).into_iter().flatten() {
        std::os::unix::fs::lchown(e.path(), Some(4321), Some(4321)).unwrap();
    }
    // A home of its own: the hint writes the user's global git configuration.
    let home = dir.path().join("home");
    std::fs::create_dir_all(&home).unwrap();
    let env = [("HOME", home.as_path())];
    let (err, subjects) = build_warnings(&repo, &dir.path().join("s1"), &env);
    assert!(subjects.is_empty(), "{subjects:?}");
    assert!(
        err.contains("warning: history: git refuses the repository at `"),
        "{err}"
    );
    let hint = command_after(&err, "if you trust it, run ");
    assert_eq!(
        hint[..5],
        ["git", "config", "--global", "--add", "safe.directory"]
    );
    // `rtcdoc diff REV:PATH` there says the same.
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(["diff", "HEAD~1:./", "HEAD:./"])
        .current_dir(&repo)
        .env("HOME", &home)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    let diff_err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{diff_err}");
    assert_eq!(
        command_after(&diff_err, "if you trust it, run "),
        hint,
        "{diff_err}"
    );
    let o = std::process::Command::new(&hint[0])
        .args(&hint[1..])
        .env("HOME", &home)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (err, subjects) = build_warnings(&repo, &dir.path().join("s2"), &env);
    assert!(!err.contains("warning: history"), "{err}");
    assert_eq!(subjects.len(), 4, "{subjects:?}");
}

#[test]
fn a_log_git_cannot_give_is_named_with_git_s_words() {
    let Some((dir, repo)) = history_repo() else {
        return;
    };
    // The first commit's tree is lost (a damaged or partly copied repository).
    let o = std::process::Command::new("git")
        .args(["rev-parse", "HEAD~3^{tree}"])
        .current_dir(&repo)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    let tree = String::from_utf8_lossy(&o.stdout).trim().to_string();
    std::fs::remove_file(repo.join(".git/objects").join(&tree[..2]).join(&tree[2..])).unwrap();
    let (err, subjects) = build_warnings(&repo, &dir.path().join("s"), &[]);
    assert!(subjects.is_empty(), "{subjects:?}");
    assert!(
        err.contains("warning: history: git could not give the history of `Base/RTC.xml` (fatal: "),
        "{err}"
    );
    assert!(
        err.contains("`git log --follow -- Base/RTC.xml` in the input directory says more"),
        "{err}"
    );
}

/// A folder renamed in two commits (the old profile deleted, the new one with the same id
/// added in the next commit): the history goes on at the old path, as `rtcdoc diff` pairs the
/// two by id, and the row says the file moved.
#[test]
fn a_folder_renamed_in_two_commits_is_followed_by_its_component_id() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !init(&repo) {
        println!("skipped: git not available");
        return;
    }
    let base = common::xml_profile("Base", &[("DataInPort", "cmd", "RTC::TimedLong")]);
    write(&repo, "RTC/X/RTC.xml", &base);
    write(
        &repo,
        "RTC/Other/RTC.xml",
        &common::xml_profile("Other", &[("DataInPort", "in", "RTC::TimedLong")]),
    );
    commit(&repo, 1, "First");
    let edited = with(&base, &[("rtc:name=\"cmd\"", "rtc:name=\"command\"")]);
    write(&repo, "RTC/X/RTC.xml", &edited);
    commit(&repo, 2, "Edit");
    std::fs::remove_dir_all(repo.join("RTC/X")).unwrap();
    commit(&repo, 3, "Remove the old folder");
    write(&repo, "RTC/X2.0/RTC.xml", &edited);
    commit(&repo, 4, "Add the new folder");
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json"]);
    let h = base_history(&site);
    let found = subjects_and_files(&h);
    assert_eq!(
        found,
        [
            ("Add the new folder", "RTC/X2.0/RTC.xml"),
            ("Edit", "RTC/X/RTC.xml"),
            ("First", "RTC/X/RTC.xml")
        ],
        "{h:#?}"
    );
    assert_eq!(h[0]["movedFrom"], "RTC/X/RTC.xml", "{h:#?}");
    assert!(h[0]["changes"].as_array().unwrap().is_empty(), "{h:#?}");
    assert_eq!(h[1].get("movedFrom"), None, "{h:#?}");
    assert_eq!(h[2]["first"], true);
    // The rows say it, and the move is not folded away.
    let html = dir.path().join("html");
    build(&repo, &html, &["-f", "html"]);
    let component = page(&html, "components/base.html");
    assert!(
        component.contains("moved from RTC/X/RTC.xml, no change to the specification"),
        "{component}"
    );
    // A deletion further back than the gap looked at is another component's end, not a move.
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    assert!(init(&repo));
    write(&repo, "RTC/X/RTC.xml", &base);
    write(
        &repo,
        "RTC/Other/RTC.xml",
        &common::xml_profile("Other", &[]),
    );
    commit(&repo, 1, "First");
    std::fs::remove_dir_all(repo.join("RTC/X")).unwrap();
    commit(&repo, 2, "Remove");
    for i in 0..rtcdoc::history::MAX_GAP {
        write(&repo, "notes.txt", &format!("{i}"));
        commit(&repo, 3, "Notes");
    }
    write(&repo, "RTC/X2.0/RTC.xml", &base);
    commit(&repo, 4, "Add again");
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "json"]);
    let h = base_history(&site);
    assert_eq!(
        subjects_and_files(&h),
        [("Add again", "RTC/X2.0/RTC.xml")],
        "{h:#?}"
    );
}

/// A lab's folder of clones: the folder is no work tree (or one whose `.gitignore` leaves the
/// clones out), each clone has a `.git` of its own. Each profile has the history of the clone
/// holding it, and the IDL file beside it too; before, the folder's histories were empty.
#[test]
fn a_folder_of_clones_has_the_history_of_each_clone() {
    use common::history_repo::{commit_versions, versions};
    let dir = tempfile::tempdir().unwrap();
    let lab = dir.path().join("lab");
    if !commit_versions(&lab.join("base-rtc"), versions()) {
        crate::common::missing_tool("git not available");
        return;
    }
    let arm: Vec<(&str, String)> = versions()
        .into_iter()
        .map(|(s, t)| {
            (
                s,
                with(
                    &t,
                    &[
                        ("rtc:name=\"Base\"", "rtc:name=\"Arm\""),
                        (":Base:", ":Arm:"),
                    ],
                ),
            )
        })
        .collect();
    let arm_dir = lab.join("clones/arm-rtc");
    assert!(commit_versions(&arm_dir, arm));
    write(
        &arm_dir,
        "idl/Arm.idl",
        "module Lab { struct Pose { double x; }; };\n",
    );
    commit(&arm_dir, 9, "Add the IDL");
    write(
        &arm_dir,
        "idl/Arm.idl",
        "module Lab { struct Pose { double x; double y; }; };\n",
    );
    commit(&arm_dir, 10, "Pose gains y");
    let json_of = |input: &Path, out: &Path| -> Value {
        build(input, out, &["-f", "html,json"]);
        serde_json::from_slice(&std::fs::read(out.join("json/catalog.json")).unwrap()).unwrap()
    };
    let entry_count = |json: &Value, name: &str| {
        json["components"]
            .as_object()
            .unwrap()
            .values()
            .find(|c| c["basicInfo"]["name"] == name)
            .map(|c| c["history"].as_array().map_or(0, Vec::len))
            .unwrap_or_else(|| panic!("{name} in catalog.json"))
    };
    let out = dir.path().join("site");
    let json = json_of(&lab, &out);
    assert_eq!(entry_count(&json, "Base"), 4, "{}", json["components"]);
    assert_eq!(entry_count(&json, "Arm"), 4);
    let arm_page = page(&out, "html/history/arm.html");
    assert!(
        arm_page.contains("Rename cmd") && arm_page.contains("First version"),
        "{arm_page}"
    );
    let idl = serde_json::to_string(&json["idl"]["files"]).unwrap();
    assert!(idl.contains("Pose gains y"), "{idl}");
    // The folder itself a work tree that ignores the clones: still each clone's own history.
    assert!(init(&lab));
    write(&lab, ".gitignore", "base-rtc/\nclones/\n");
    write(&lab, "README.md", "The lab's components.\n");
    commit(&lab, 20, "The catalogue");
    let json = json_of(&lab, &dir.path().join("site2"));
    assert_eq!(entry_count(&json, "Base"), 4);
    assert_eq!(entry_count(&json, "Arm"), 4);
    // A shallow clone among them: its history is cut short, and the warning's command mends it.
    let base = lab.join("base-rtc");
    let url = format!("file://{}", base.display());
    let shallow = lab.join("shallow-rtc");
    let cloned = std::process::Command::new("git")
        .args(["clone", "-q", "--depth", "1", &url])
        .arg(&shallow)
        .status()
        .unwrap();
    assert!(cloned.success());
    write(&lab, ".gitignore", "base-rtc/\nclones/\nshallow-rtc/\n");
    let _ = std::fs::remove_dir_all(base.join("Base"));
    assert!(std::process::Command::new("git")
        .args(["rm", "-q", "-r", "Base"])
        .current_dir(&base)
        .status()
        .unwrap()
        .success());
    commit(&base, 21, "Moved to shallow-rtc");
    let site3 = dir.path().join("site3");
    let o = common::rtcdoc(
        &["build", ".", "-o", site3.to_str().unwrap(), "-f", "json"],
        &lab,
    );
    assert!(o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("the clone `shallow-rtc` is a shallow clone"),
        "{err}"
    );
    let json: Value =
        serde_json::from_slice(&std::fs::read(site3.join("catalog.json")).unwrap()).unwrap();
    assert_eq!(
        entry_count(&json, "Base"),
        1,
        "one commit in the shallow clone"
    );
    // The command the warning gives, run as written where rtcdoc ran.
    let hint = err
        .split("(`git ")
        .nth(1)
        .and_then(|r| r.split("`)").next())
        .unwrap_or_else(|| panic!("a git command in {err}"));
    assert!(hint.ends_with("fetch --unshallow"), "{hint}");
    assert!(std::process::Command::new("git")
        .args(hint.split(' '))
        .current_dir(&lab)
        .status()
        .unwrap()
        .success());
    let o = common::rtcdoc(
        &["build", ".", "-o", site3.to_str().unwrap(), "-f", "json"],
        &lab,
    );
    assert!(!String::from_utf8_lossy(&o.stderr).contains("shallow clone"));
    let json: Value =
        serde_json::from_slice(&std::fs::read(site3.join("catalog.json")).unwrap()).unwrap();
    assert_eq!(
        entry_count(&json, "Base"),
        4,
        "the whole history after the hint"
    );
}
