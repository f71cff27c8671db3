//! The build pipeline end to end: walk, load, catalogue, JSON output and output safety.

use crate::common;
use common::OutputWithin;
use common::*;
use rtcdoc::build::{self, BuildOptions, LoadOptions};
use rtcdoc::render::{Format, SiteOptions};
use std::path::Path;

fn opts(input: &Path, output: &Path, format: Format) -> BuildOptions {
    BuildOptions {
        input: input.to_path_buf(),
        output: output.to_path_buf(),
        formats: vec![format],
        strict: false,
        load: LoadOptions::default(),
        site: SiteOptions::default(),
    }
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(path).expect("read json")).expect("valid json")
}

/// Two profiles (one under a backup name) among files the walk must skip: a non-profile
/// `.xml`, an RT System profile, a README, a hidden directory and `skip/` (to be excluded).
fn mixed_tree(d: &Path) {
    write(d, "b/RTC.xml", &xml_profile("B", &[]));
    write(d, "a/RTC.xml20230831164412.xml", &xml_profile("A", &[]));
    write(d, "a/notes.xml", "<root/>");
    write(
        d,
        "sys.xml",
        "<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\"/>",
    );
    write(d, "readme.md", "# hi");
    write(d, ".git/RTC.xml", &xml_profile("Hidden", &[]));
    write(d, "skip/me/RTC.xml", &xml_profile("Excluded", &[]));
}

#[test]
fn walk_finds_profiles_by_content_sorted_and_skips_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    mixed_tree(d);
    let res = rtcdoc::walk::walk(
        d,
        &rtcdoc::walk::WalkOptions {
            exclude: vec!["skip/**".into()],
            ..Default::default()
        },
    )
    .unwrap();
    let rels: Vec<&str> = res.sources.iter().map(|s| s.rel.as_str()).collect();
    assert_eq!(rels, ["a/RTC.xml20230831164412.xml", "b/RTC.xml"]);
    let skipped: Vec<&str> = res.skipped.iter().map(|s| s.rel.as_str()).collect();
    assert!(skipped.contains(&"a/notes.xml"));
    assert!(skipped.contains(&"sys.xml"));
    assert!(skipped.contains(&"readme.md"));
    // An exclude pattern that matches a directory leaves it out whole, reported once.
    assert!(skipped.contains(&"skip/me/"), "{skipped:?}");
    assert!(!skipped.iter().any(|s| s.starts_with("skip/me/R")));
}

#[test]
fn load_takes_and_skips_the_same_files_as_the_walk() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    mixed_tree(d);
    write(
        d,
        "c/RTC.yaml",
        "rtcProfile:\n  id: RTC:V:C:Y:1\n  basicInfo:\n    name: Y\n",
    );
    // A profile whose root element comes after a comment longer than the size limit: still
    // recognised (the head read to recognise profiles is 64 KiB), then refused as too large.
    let mut late = String::from("<?xml version=\"1.0\"?>\n");
    late.push_str(&format!("<!-- {} -->\n", "x".repeat(3000)));
    late.push_str(
        &xml_profile("Late", &[])["<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n".len()..],
    );
    write(d, "late/RTC.xml", &late);
    let walk_opts = rtcdoc::walk::WalkOptions {
        exclude: vec!["skip/**".into()],
        ..Default::default()
    };
    let walked = rtcdoc::walk::walk(d, &walk_opts).unwrap();
    let mut o = LoadOptions {
        exclude: walk_opts.exclude.clone(),
        ..Default::default()
    };
    o.limits.max_file_size = 2000;
    let loaded = build::load(d, &o).unwrap();

    let skipped = |v: &[rtcdoc::walk::Skipped]| -> Vec<(String, String)> {
        v.iter()
            .map(|s| (s.rel.clone(), s.reason.clone()))
            .collect()
    };
    // The walk (component profiles only) skips the RT System profile; the load reads it.
    let mut walk_skipped = skipped(&walked.skipped);
    walk_skipped.retain(|(rel, _)| rel != "sys.xml");
    assert_eq!(skipped(&loaded.skipped), walk_skipped);
    let systems: Vec<&str> = loaded
        .catalog
        .systems
        .iter()
        .map(|s| s.source.as_str())
        .collect();
    assert_eq!(systems, ["sys.xml"]);
    // The walk lists RTCBuilder's backup among the profiles; the load keeps it apart (its
    // RTC.xml is gone: RTC013).
    assert_eq!(loaded.files + 1, walked.sources.len());
    let backups: Vec<&str> = loaded
        .catalog
        .detached_backups
        .iter()
        .map(|b| b.source.as_str())
        .collect();
    assert_eq!(backups, ["a/RTC.xml20230831164412.xml"]);
    assert!(loaded
        .catalog
        .diagnostics
        .iter()
        .any(|d| d.code == "RTC013" && d.file == "a/RTC.xml20230831164412.xml"));
    let sources: Vec<&str> = loaded
        .catalog
        .components
        .iter()
        .map(|c| c.source.as_str())
        .collect();
    assert_eq!(sources, ["b/RTC.xml", "c/RTC.yaml"]);
    let too_large = loaded
        .catalog
        .diagnostics
        .iter()
        .find(|d| d.file == "late/RTC.xml")
        .expect("the late profile is reported");
    assert_eq!(too_large.code, "RTC002");
    assert!(
        too_large
            .message
            .contains("larger than the limit of 2000 bytes"),
        "{too_large}"
    );
}

#[cfg(unix)]
#[test]
fn walk_survives_symlink_cycles() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "x/RTC.xml", &xml_profile("X", &[]));
    std::os::unix::fs::symlink(d, d.join("x/loop")).unwrap();
    let res = rtcdoc::walk::walk(d, &Default::default()).unwrap();
    assert_eq!(res.sources.len(), 1);
    assert!(res.skipped.iter().any(|s| s.rel == "x/loop"));
}

#[test]
fn json_output_holds_components_sources_and_cross_links() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(
        &input,
        "cam/RTC.xml",
        &xml_profile("Cam", &[("DataOutPort", "image", "RTC::CameraImage")]),
    );
    write(
        &input,
        "view/RTC.xml",
        &xml_profile("Viewer", &[("DataInPort", "in", "CameraImage")]),
    );
    write(
        &input,
        "broken/RTC.xml",
        "<rtc:RtcProfile xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\"><oops>",
    );
    let out = dir.path().join("out");
    let (loaded, report) = build::build(&opts(&input, &out, Format::Json)).unwrap();
    assert_eq!(
        report.profiles, 2,
        "the broken file is reported, the others load"
    );
    assert_eq!(report.errors, 1);
    let err = loaded
        .catalog
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .unwrap();
    assert_eq!(err.file, "broken/RTC.xml");
    assert!(err.pos.is_some(), "errors carry a position");

    let v = json(&out.join("catalog.json"));
    assert_eq!(v["formatVersion"], 3);
    let keyed = v["components"].as_object().unwrap();
    let comps: Vec<&serde_json::Value> = keyed.values().collect();
    let sources: Vec<&str> = comps
        .iter()
        .map(|c| c["source"].as_str().unwrap())
        .collect();
    assert_eq!(sources, ["cam/RTC.xml", "view/RTC.xml"]);
    let ids: Vec<&String> = keyed.keys().collect();
    assert_eq!(comps[0]["basicInfo"]["name"], "Cam");
    assert_eq!(comps[0]["dataPorts"][0]["type"], "RTC::CameraImage");
    // Both spellings are one type, produced by Cam and consumed by Viewer.
    let types: Vec<&serde_json::Value> = v["dataTypes"].as_object().unwrap().values().collect();
    assert_eq!(types.len(), 1);
    assert_eq!(types[0]["name"], "RTC::CameraImage");
    assert_eq!(types[0]["producers"][0]["component"], ids[0].as_str());
    assert_eq!(types[0]["consumers"][0]["component"], ids[1].as_str());
    assert_eq!(
        types[0]["producers"][0]["port"],
        comps[0]["dataPorts"][0]["name"]
    );
    assert_eq!(v["diagnostics"][0]["file"], "broken/RTC.xml");
    assert!(out.join(".rtcdoc-output").exists());
}

#[test]
fn strict_mode_fails_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(&input, "ok/RTC.xml", &xml_profile("Ok", &[]));
    write(
        &input,
        "bad/RTC.xml",
        "<rtc:RtcProfile xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\">",
    );
    let out = dir.path().join("out");
    let mut o = opts(&input, &out, Format::Json);
    o.strict = true;
    let err = build::build(&o).err().expect("strict build fails");
    assert!(format!("{err:#}").contains("--strict"));
    assert!(!out.exists());
    let entries: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(entries.len(), 1, "no temporary directory is left behind");
}

#[test]
fn output_is_deterministic() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    for i in 0..20 {
        write(
            &input,
            &format!("c{i}/RTC.xml"),
            &xml_profile(
                &format!("C{}", i % 7),
                &[
                    ("DataOutPort", "o", "RTC::TimedLong"),
                    ("DataInPort", "i", "TimedLong"),
                ],
            ),
        );
    }
    let a = dir.path().join("a");
    let b = dir.path().join("b");
    build::build(&opts(&input, &a, Format::Json)).unwrap();
    build::build(&opts(&input, &b, Format::Json)).unwrap();
    assert_eq!(tree(&a), tree(&b));
}

#[test]
fn refuses_dangerous_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(&input, "a/RTC.xml", &xml_profile("A", &[]));
    // The input itself, and a parent of the input.
    assert!(build::build(&opts(&input, &input, Format::Json)).is_err());
    assert!(build::build(&opts(&input, dir.path(), Format::Json)).is_err());
    // A directory holding profiles.
    let other = dir.path().join("other");
    write(&other, "RTC.xml", &xml_profile("B", &[]));
    assert!(build::build(&opts(&input, &other, Format::Json)).is_err());
    assert!(other.join("RTC.xml").exists());
    // A foreign non-empty directory.
    let foreign = dir.path().join("foreign");
    write(&foreign, "precious.txt", "keep me");
    assert!(build::build(&opts(&input, &foreign, Format::Json)).is_err());
    assert!(foreign.join("precious.txt").exists());
    // An output inside the input is skipped by the walk and can be rebuilt.
    let inner = input.join("site");
    build::build(&opts(&input, &inner, Format::Json)).unwrap();
    let (_, report) = build::build(&opts(&input, &inner, Format::Json)).unwrap();
    assert_eq!(report.profiles, 1);
}

#[test]
fn duplicate_ids_are_kept_apart_and_warned() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(&input, "a/RTC.xml", &xml_profile("Same", &[]));
    write(&input, "b/RTC.xml", &xml_profile("Same", &[]));
    let loaded = build::load(&input, &LoadOptions::default()).unwrap();
    let c = &loaded.catalog;
    assert_eq!(c.components.len(), 2);
    assert_ne!(c.components[0].slug, c.components[1].slug);
    let dups: Vec<_> = c
        .diagnostics
        .iter()
        .filter(|d| d.code == "RTC010")
        .collect();
    assert_eq!(dups.len(), 2);
}

#[test]
fn cli_builds_json_and_reports() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "in/a/RTC.xml", &xml_profile("A", &[]));
    let out = rtcdoc(
        &["build", "in", "--format", "json", "-o", "out"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.path().join("out/catalog.json").exists());
    let missing = rtcdoc(&["build", "nope", "-o", "out2"], dir.path());
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("does not exist"));
}

#[test]
fn corpus_json_loses_nothing() {
    let Some(corpus) = corpus() else { return };
    let Some(tool) = shared_tool("nothing_lost.py") else {
        println!("skipped: nothing_lost.py not present");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let input = corpus.join("rtc-xml");
    let out = dir.path().join("out");
    let (loaded, _) = build::build(&opts(&input, &out, Format::Json)).unwrap();
    let errors: Vec<String> = loaded
        .catalog
        .diagnostics
        .iter()
        // Reader errors only: the `rtcdoc check` rules (RTC1xx…) rightly find real problems
        // in real profiles (see tests/suite/check_rules.rs).
        .filter(|d| d.is_error() && d.code < "RTC100")
        .map(|d| d.to_string())
        .collect();
    assert!(errors.is_empty(), "corpus errors: {errors:#?}");
    let run = std::process::Command::new("python3")
        .arg(&tool)
        .arg(&input)
        .arg(out.join("catalog.json"))
        .output_within(common::COMMAND_LIMIT)
        .expect("python3");
    let stdout = String::from_utf8_lossy(&run.stdout);
    println!("{stdout}");
    assert!(run.status.success(), "nothing_lost.py failed:\n{stdout}");
    assert!(stdout.contains("lost: 0, profiles without component: 0"));
}

#[test]
fn whole_corpus_loads_without_errors() {
    let Some(corpus) = corpus() else { return };
    let loaded = build::load(&corpus, &LoadOptions::default()).unwrap();
    let errors: Vec<String> = loaded
        .catalog
        .diagnostics
        .iter()
        // Reader errors only: the `rtcdoc check` rules (RTC1xx…) rightly find real problems
        // in real profiles (see tests/suite/check_rules.rs).
        .filter(|d| d.is_error() && d.code < "RTC100")
        .map(|d| d.to_string())
        .collect();
    assert!(errors.is_empty(), "corpus errors: {errors:#?}");
    let xml = loaded
        .catalog
        .components
        .iter()
        .filter(|c| c.source.starts_with("rtc-xml/"))
        .count();
    let yaml = loaded
        .catalog
        .components
        .iter()
        .filter(|c| c.source.starts_with("rtc-yaml/"))
        .count();
    let rts = loaded
        .catalog
        .components
        .iter()
        .filter(|c| c.source.starts_with("rts-xml/"))
        .count();
    println!(
        "corpus: {xml} XML and {yaml} YAML profiles, {} files skipped",
        loaded.skipped.len()
    );
    // One file of the corpus is an RTCBuilder backup without its RTC.xml: not a component.
    assert_eq!(xml, 138);
    assert_eq!(loaded.catalog.detached_backups.len(), 1);
    assert_eq!(yaml, 14);
    assert_eq!(rts, 0, "RT System profiles are not component profiles");
    assert_eq!(
        loaded.catalog.systems.len(),
        9,
        "RT System profiles are systems"
    );
    let mut by_code = std::collections::BTreeMap::new();
    for d in &loaded.catalog.diagnostics {
        *by_code.entry(d.code).or_insert(0) += 1;
    }
    println!("diagnostics by code: {by_code:?}");
}

#[test]
fn oversized_files_are_refused_quickly_with_the_file_named() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let mut big = xml_profile("Big", &[]);
    big.push_str(&format!("<!-- {} -->\n", "x".repeat(2_000_000)));
    write(&input, "big/RTC.xml", &big);
    write(&input, "ok/RTC.xml", &xml_profile("Ok", &[]));
    let mut o = LoadOptions::default();
    o.limits.max_file_size = 1_000_000;
    let start = std::time::Instant::now();
    let loaded = build::load(&input, &o).unwrap();
    assert!(start.elapsed().as_secs_f64() < 1.0);
    assert_eq!(loaded.catalog.components.len(), 1);
    let d = loaded
        .catalog
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .unwrap();
    assert_eq!((d.code, d.file.as_str()), ("RTC002", "big/RTC.xml"));
    assert!(d.to_string().contains("larger than the limit"));
}

/// Catalog::pages is the site: every page it lists is written at its path, under its own
/// title, no two share a path, and each output writes the same entry pages with its own
/// extension.
#[test]
fn every_listed_page_is_written_at_its_path() {
    use rtcdoc::catalog::{Output, PageKind};
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = tempfile::tempdir().unwrap();
    let mut o = opts(
        &root.join("examples"),
        &dir.path().join("site"),
        Format::Html,
    );
    o.formats = vec![Format::Html, Format::Markdown, Format::Doxygen];
    let (loaded, _) = build::build(&o).unwrap();
    let pages = loaded.catalog.pages();
    assert!(
        pages.iter().any(|p| p.kind == PageKind::System),
        "the examples have a system"
    );
    let mut seen = std::collections::HashSet::new();
    for p in pages {
        assert!(seen.insert(p.path("html")), "two pages at {}", p.stem);
        if p.kind == PageKind::Diagnostics && loaded.catalog.diagnostics.is_empty() {
            continue;
        }
        let html = std::fs::read_to_string(dir.path().join("site/html").join(p.path("html")))
            .unwrap_or_else(|e| panic!("{}: {e}", p.path("html")));
        if !p.title.is_empty() {
            let title = html
                .split("<title>")
                .nth(1)
                .and_then(|t| t.split("</title>").next());
            let escaped = p.title.replace('&', "&amp;").replace('<', "&lt;");
            assert!(
                title.is_some_and(|t| t.starts_with(&escaped)),
                "{}: title {title:?} does not start with {}",
                p.stem,
                p.title
            );
        }
        if matches!(
            p.kind,
            PageKind::Component | PageKind::DataType | PageKind::Interface | PageKind::System
        ) {
            for (out, dir_name) in [(Output::Markdown, "markdown"), (Output::Doxygen, "doxygen")] {
                let path = dir.path().join("site").join(dir_name).join(p.path_in(out));
                assert!(path.exists(), "{} missing", path.display());
            }
        }
    }
}
