//! History beyond components (issue 25): each RT System profile's commits compared with the
//! system diff engine, each IDL file's commits compared type by type, a profile followed to an
//! older path by its component id when git's `--follow` loses it, and the Source links of
//! system and IDL pages.

mod common;
use common::{root, rtcdoc, write};
use serde_json::Value;
use std::path::Path;

fn git(dir: &Path, args: &[&str], date: &str) -> bool {
    std::process::Command::new("git")
        .args(args)
        .current_dir(dir)
        .env("GIT_CONFIG_NOSYSTEM", "1")
        .env("HOME", dir)
        .env("GIT_AUTHOR_DATE", date)
        .env("GIT_COMMITTER_DATE", date)
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false)
}

/// A fresh repository in `d`, or `false` when git does not run.
fn init(d: &Path) -> bool {
    std::fs::create_dir_all(d).unwrap();
    if !git(d, &["--version"], "") {
        return false;
    }
    assert!(git(d, &["init", "-q"], ""));
    assert!(git(d, &["config", "user.name", "Tester"], ""));
    assert!(git(d, &["config", "user.email", "t@example.org"], ""));
    true
}

/// Commits everything on day `day` of January 2024.
fn commit(d: &Path, day: u32, subject: &str) {
    let date = format!("2024-01-{day:02} 10:00:00 +0900");
    assert!(git(d, &["add", "-A"], &date));
    assert!(git(d, &["commit", "-q", "-m", subject], &date));
}

fn fixture(rel: &str) -> String {
    std::fs::read_to_string(root().join("tests/fixtures").join(rel)).unwrap()
}

fn with(text: &str, edits: &[(&str, &str)]) -> String {
    let mut s = text.to_string();
    for (from, to) in edits {
        assert!(s.contains(from), "edit `{from}` does not apply");
        s = s.replacen(from, to, 1);
    }
    s
}

fn build(input: &Path, out: &Path, extra: &[&str]) {
    let mut args = vec![
        "build",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = rtcdoc(&args, input);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

fn page(dir: &Path, rel: &str) -> String {
    std::fs::read_to_string(dir.join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn codes(entry: &Value) -> Vec<&str> {
    entry["changes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["code"].as_str().unwrap())
        .collect()
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
        commit(d, day as u32 + 1, subject);
    }
    true
}

#[test]
fn a_system_has_its_history_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !system_repository(&repo) {
        println!("skipped: git not available");
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
        println!("skipped: git not available");
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
}
