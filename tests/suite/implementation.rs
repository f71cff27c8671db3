//! The implementation check: the code beside each profile (C++, Python, Java; generated and
//! hand-edited; names built at run time, macros, base classes; hostile files) compared with
//! the profile, in `check`, SARIF and `catalog.json`.

use crate::common;
use rtcdoc::build::{self, LoadOptions};
use rtcdoc::check;
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::root()
        .join("tests/fixtures/implementation")
        .join(name)
}

/// (code, file, message) of every finding of `dir`.
fn findings(dir: &std::path::Path) -> Vec<(String, String, String)> {
    let loaded = build::load(dir, &LoadOptions::default()).expect("load");
    check::check(&loaded.catalog)
        .diagnostics
        .into_iter()
        .map(|d| (d.code.to_string(), d.file, d.message))
        .collect()
}

fn codes(dir: &std::path::Path) -> Vec<String> {
    let mut c: Vec<String> = findings(dir).into_iter().map(|f| f.0).collect();
    c.sort();
    c
}

#[test]
fn generated_code_matches_its_profile() {
    for f in ["python-generated", "java-generated"] {
        assert_eq!(codes(&fixture(f)), Vec::<String>::new(), "{f}");
    }
}

#[test]
fn a_hand_edited_python_component_drifts() {
    let f = findings(&fixture("python-edited"));
    let mut c: Vec<&str> = f.iter().map(|f| f.0.as_str()).collect();
    c.sort();
    // The in-port renamed in the code only (ir_sensor → distance_sensor), SPORADIC in the spec
    // array, onActivated written where the profile says not implemented.
    assert_eq!(c, ["RTC801", "RTC802", "RTC807", "RTC809"], "{f:#?}");
    assert!(f.iter().any(|x| x.0 == "RTC802"
        && x.1.ends_with("SensorGUI.py")
        && x.2.contains("distance_sensor")));
    assert!(f
        .iter()
        .any(|x| x.0 == "RTC801" && x.1.ends_with("RTC.xml") && x.2.contains("ir_sensor")));
    assert!(f
        .iter()
        .any(|x| x.0 == "RTC809" && x.2.contains("SPORADIC")));
    // The commented-out `#def onFinalize` is no callback.
    assert!(!f.iter().any(|x| x.2.contains("onFinalize")));
}

#[test]
fn python_registrations_and_types_are_read() {
    let loaded = build::load(&fixture("python-generated"), &LoadOptions::default()).unwrap();
    let imp = loaded.catalog.components[0]
        .implementation
        .as_ref()
        .expect("implementation");
    assert_eq!(imp.files, ["SensorGUI.py"]);
    let ports: Vec<(&str, Option<&str>)> = imp
        .data_ports
        .iter()
        .map(|p| (p.name.as_str(), p.data_type.as_deref()))
        .collect();
    assert_eq!(
        ports,
        [
            ("ir_sensor", Some("RTC::TimedShortSeq")),
            ("cmd", Some("RTC::TimedString"))
        ]
    );
    assert_eq!(imp.parameters[0].default.as_deref(), Some("1.0"));
    let cbs: Vec<(&str, bool)> = imp
        .callbacks
        .iter()
        .map(|c| (c.name.as_str(), c.implemented))
        .collect();
    // onInitialize holds only registrations: the generated body.
    assert_eq!(cbs, [("onInitialize", false), ("onExecute", true)]);
    // The spec array agrees with the profile: the catalogue keeps none of it (the profile
    // says it); of a hand-edited one, the value that differs.
    assert!(imp.spec.is_empty(), "{:?}", imp.spec);
    let edited = build::load(&fixture("python-edited"), &LoadOptions::default()).unwrap();
    let spec = &edited.catalog.components[0]
        .implementation
        .as_ref()
        .expect("implementation")
        .spec;
    let kept: Vec<(&str, Option<&str>)> = spec
        .iter()
        .map(|s| (s.key.as_str(), s.value.as_deref()))
        .collect();
    assert_eq!(kept, [("activity_type", Some("SPORADIC"))]);
}

#[test]
fn a_hand_edited_java_component_drifts() {
    let f = findings(&fixture("java-edited"));
    let c: Vec<&str> = f.iter().map(|f| f.0.as_str()).collect();
    assert_eq!(c.len(), 2, "{f:#?}");
    assert!(f
        .iter()
        .any(|x| x.0 == "RTC809" && x.1.ends_with("src/Counter.java") && x.2.contains("1.2.0")));
    assert!(f.iter().any(|x| x.0 == "RTC803"
        && x.1.ends_with("src/CounterImpl.java")
        && x.2.contains("`limit`")));
}

#[test]
fn what_cannot_be_read_statically_is_never_a_warning() {
    let f = findings(&fixture("cpp-dynamic"));
    assert!(f.iter().all(|x| x.0 == "RTC810"), "{f:#?}");
    let said: Vec<&str> = f.iter().map(|x| x.2.as_str()).collect();
    assert!(
        said.iter()
            .any(|m| m.contains("macro") && m.contains("ADD_JOINT_PORT")),
        "{said:#?}"
    );
    assert!(
        said.iter().any(|m| m.contains("std::to_string")),
        "{said:#?}"
    );
    assert!(
        said.iter()
            .any(|m| m.contains("`version`") && m.contains("ARM_PACKAGE_VERSION")),
        "{said:#?}"
    );
    let f = findings(&fixture("cpp-base-class"));
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].0, "RTC810");
    assert!(f[0].2.contains("LimbBase"), "{}", f[0].2);
}

#[test]
fn hostile_sources_are_bounded_named_and_never_abort_the_build() {
    let dir = tempfile::tempdir().unwrap();
    let src = fixture("hostile");
    for e in walkdir(&src) {
        let rel = e.strip_prefix(&src).unwrap();
        let to = dir.path().join(rel);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(&e, &to).unwrap();
    }
    // A 16 MiB source file (over the limit by one byte).
    let huge = dir.path().join("Huge");
    common::write(
        &huge,
        "RTC.xml",
        &common::xml_profile("Huge", &[("DataInPort", "in", "RTC::TimedLong")]),
    );
    let mut big = b"// ".to_vec();
    big.resize(16 * 1024 * 1024 + 1, b'x');
    std::fs::create_dir_all(huge.join("src")).unwrap();
    std::fs::write(huge.join("src/Huge.cpp"), big).unwrap();
    let f = findings(dir.path());
    let unreadable: Vec<&(String, String, String)> = f.iter().filter(|x| x.0 == "RTC811").collect();
    assert_eq!(unreadable.len(), 2, "{f:#?}");
    assert!(unreadable
        .iter()
        .any(|x| x.1 == "Deep/src/Deep.cpp" && x.2.contains("nested deeper")));
    assert!(unreadable
        .iter()
        .any(|x| x.1 == "Huge/src/Huge.cpp" && x.2.contains("larger than")));
    assert!(
        !f.iter().any(|x| x.0.starts_with("RTC80")),
        "no drift: {f:#?}"
    );
    let loaded = build::load(dir.path(), &LoadOptions::default()).unwrap();
    let by_name = |n: &str| {
        loaded
            .catalog
            .components
            .iter()
            .find(|c| c.profile.basic_info.name.as_deref() == Some(n))
            .unwrap()
    };
    // Shift_JIS and invalid UTF-8 are read: their registrations are there.
    for n in ["Sjis", "Bad"] {
        let imp = by_name(n)
            .implementation
            .as_ref()
            .unwrap_or_else(|| panic!("{n}"));
        assert_eq!(imp.data_ports[0].name, "in", "{n}");
    }
    // The build goes on and writes the site.
    let out = dir.path().join("site");
    let o = common::rtcdoc(&["build", ".", "-o", out.to_str().unwrap()], dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.join("index.html").is_file());
}

fn walkdir(d: &std::path::Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(d).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(walkdir(&p));
        } else {
            out.push(p);
        }
    }
    out
}

#[test]
fn sarif_names_the_profile_element_as_related_location() {
    let dir = common::root().join("tests/fixtures/check");
    let o = common::rtcdoc(&["check", "RTC803-bad", "--format", "sarif"], &dir);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let r = &v["runs"][0]["results"][0];
    assert_eq!(r["ruleId"], "RTC803");
    assert_eq!(
        r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
        "RTC803-bad/src/Drift.cpp"
    );
    let rel = &r["relatedLocations"][0]["physicalLocation"];
    assert_eq!(rel["artifactLocation"]["uri"], "RTC803-bad/RTC.xml");
    assert_eq!(rel["region"]["startLine"], 17);
    // The human output names both places too.
    let o = common::rtcdoc(&["check", "RTC803-bad"], &dir);
    let text = String::from_utf8_lossy(&o.stderr).to_string() + &String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("the profile says it here: RTC803-bad/RTC.xml:17:3"),
        "{text}"
    );
}

#[test]
fn deny_warnings_fails_on_drift_and_passes_on_matching_code() {
    let dir = common::root().join("tests/fixtures/check");
    let o = common::rtcdoc(&["check", "RTC806-bad", "--deny", "warnings"], &dir);
    assert_eq!(o.status.code(), Some(1));
    let o = common::rtcdoc(&["check", "RTC806-good", "--deny", "warnings"], &dir);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // "Could not verify" is an info: it does not fail the gate.
    let o = common::rtcdoc(&["check", "RTC810-bad", "--deny", "warnings"], &dir);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn the_configuration_turns_the_check_off_or_names_the_files() {
    let dir = tempfile::tempdir().unwrap();
    let src = common::root().join("tests/fixtures/check/RTC806-bad");
    for rel in ["RTC.xml", "src/Drift.cpp", "include/Drift/Drift.h"] {
        common::write(
            dir.path(),
            rel,
            &std::fs::read_to_string(src.join(rel)).unwrap(),
        );
    }
    let has = |args: &[&str]| {
        let o = common::rtcdoc(args, dir.path());
        String::from_utf8_lossy(&o.stdout).contains("RTC806")
    };
    assert!(has(&["check", ".", "--format", "json"]));
    common::write(
        dir.path(),
        "rtcdoc.toml",
        "[implementation]\ncheck = false\n",
    );
    assert!(!has(&["check", ".", "--format", "json"]));
    // The files moved and named: found again.
    std::fs::rename(dir.path().join("src"), dir.path().join("code")).unwrap();
    common::write(
        dir.path(),
        "rtcdoc.toml",
        "[implementation]\ncheck = true\n",
    );
    assert!(
        !has(&["check", ".", "--format", "json"]),
        "not in RTCBuilder's layout any more"
    );
    common::write(
        dir.path(),
        "rtcdoc.toml",
        "[[implementation.component]]\nname = \"Dr*\"\nfiles = [\"code/Drift.cpp\", \"include/Drift/Drift.h\"]\n",
    );
    assert!(has(&["check", ".", "--format", "json"]));
    // A file outside the folder is refused when the configuration is read.
    common::write(
        dir.path(),
        "rtcdoc.toml",
        "[[implementation.component]]\nname = \"Drift\"\nfiles = [\"../x.cpp\"]\n",
    );
    let o = common::rtcdoc(&["check", "."], dir.path());
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("outside the component's folder"));
}

#[test]
fn catalog_json_carries_the_implementation_and_reads_it_back() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = common::rtcdoc(
        &[
            "build",
            fixture("python-edited").to_str().unwrap(),
            "-f",
            "json",
            "-o",
            out.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let bytes = std::fs::read(out.join("catalog.json")).unwrap();
    let v: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
    let c = v["components"]
        .as_object()
        .unwrap()
        .values()
        .next()
        .unwrap();
    let imp = &c["implementation"];
    assert_eq!(imp["language"], "Python");
    assert_eq!(imp["dataPorts"][0]["name"], "distance_sensor");
    let kinds: Vec<&str> = imp["drift"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["kind"].as_str().unwrap())
        .collect();
    assert!(
        kinds.contains(&"onlyInCode") && kinds.contains(&"callbackUnmarked"),
        "{kinds:?}"
    );
    let back = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").expect("reads back");
    let mut again = Vec::new();
    rtcdoc::render::json::write_json_with(&back.catalog, &back.title, false, &mut again).unwrap();
    assert!(again == bytes, "catalog.json round trip differs");
}

/// `rtcdoc ARGS` in `cwd` at a fixed extraction time (the profile's dates).
fn rtcdoc_at(args: &[&str], cwd: &std::path::Path) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(args)
        .current_dir(cwd)
        .env("NO_COLOR", "1")
        .env("SOURCE_DATE_EPOCH", "1704067200")
        .output()
        .expect("run rtcdoc")
}

fn copy_fixture(name: &str, to: &std::path::Path) {
    let from = fixture(name);
    for f in walkdir(&from) {
        let rel = f.strip_prefix(&from).unwrap();
        let target = to.join(rel);
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        std::fs::copy(&f, &target).unwrap();
    }
}

#[test]
fn components_with_code_and_no_profile_are_documented_from_their_code() {
    let loaded = build::load(&fixture("recovered"), &LoadOptions::default()).expect("load");
    let cat = &loaded.catalog;
    let by_name = |n: &str| {
        cat.components
            .iter()
            .find(|c| c.profile.name() == n)
            .unwrap_or_else(|| panic!("{n} not documented"))
    };
    // Code only: recovered, from the file holding the spec array; the test copy is not.
    let g = by_name("Gripper");
    assert_eq!(g.source, "Gripper/src/Gripper.cpp");
    let r = g.recovered.as_ref().expect("marked as recovered");
    let unread: Vec<(&str, &str)> = r
        .unread
        .iter()
        .map(|u| (u.field.as_str(), u.written.as_str()))
        .collect();
    assert_eq!(unread, [("basicInfo/version", "GRIPPER_VERSION")]);
    assert!(
        g.profile.basic_info.version.is_none(),
        "a macro is never guessed"
    );
    let ports: Vec<(&str, &str, &str)> = g
        .profile
        .data_ports
        .iter()
        .map(|p| {
            (
                p.name.as_deref().unwrap(),
                p.port_type.as_deref().unwrap(),
                p.type_.as_deref().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        ports,
        [
            ("command", "DataInPort", "RTC::TimedLong"),
            ("width", "DataOutPort", "RTC::TimedDouble")
        ]
    );
    let sp = &g.profile.service_ports[0];
    assert_eq!(sp.name.as_deref(), Some("GripperService"));
    assert_eq!(
        sp.interfaces[0].type_.as_deref(),
        Some("Hand::GripperService")
    );
    assert_eq!(sp.interfaces[0].direction.as_deref(), Some("Provided"));
    let confs: Vec<(&str, &str, &str, Option<&str>)> = g
        .profile
        .configurations()
        .iter()
        .map(|c| {
            (
                c.name.as_deref().unwrap(),
                c.type_.as_deref().unwrap(),
                c.default_value.as_deref().unwrap(),
                c.widget(),
            )
        })
        .collect();
    assert_eq!(
        confs,
        [
            ("force", "int", "20", Some("slider.1")),
            ("mode", "string", "soft", Some("radio"))
        ]
    );
    let implemented: Vec<&str> = g
        .profile
        .actions
        .iter()
        .filter(|a| a.is_implemented())
        .map(|a| a.kind.xml_name())
        .collect();
    // onDeactivated is the generated stub.
    assert_eq!(implemented, ["OnInitialize", "OnActivated", "OnExecute"]);
    assert!(by_name("Counter").recovered.is_some());
    assert_eq!(
        by_name("Counter")
            .profile
            .basic_info
            .component_type
            .as_deref(),
        Some("STATIC"),
        "STATIC in activity_type is the component type"
    );
    // A folder with a profile is the profile's; a test copy is no component.
    assert!(by_name("Documented").recovered.is_none());
    // So is the code below a profile in a folder named src (Nested/src/RTC.xml and
    // Nested/src/src/Nested.cpp, as a real repository keeps its RTCBuilder project).
    assert_eq!(
        cat.components
            .iter()
            .filter(|c| c.profile.basic_info.name.as_deref() == Some("Nested"))
            .count(),
        1
    );
    assert!(by_name("Nested").recovered.is_none());
    assert!(!cat
        .components
        .iter()
        .any(|c| c.profile.name() == "GripperTest"));
    // A framework's default profile (an empty implementation_id) is no component.
    assert!(!cat
        .components
        .iter()
        .any(|c| c.source.starts_with("framework/")));
    // check: one info per recovered component, no profile rule run on them, no warning.
    let f = findings(&fixture("recovered"));
    let recovered: Vec<&str> = f
        .iter()
        .filter(|x| x.0 == "RTC812")
        .map(|x| x.1.as_str())
        .collect();
    assert_eq!(
        recovered,
        [
            "Counter/Counter.py",
            "Gripper/src/Gripper.cpp",
            "lib/LeftArm.cpp",
            "lib/RightArm.cpp"
        ]
    );
    assert!(f
        .iter()
        .any(|x| x.0 == "RTC812" && x.2.contains("GRIPPER_VERSION")));
    let loud: Vec<_> = f
        .iter()
        .filter(|x| !x.0.starts_with("RTC5") && x.0 != "RTC812" && x.0 != "RTC810")
        .collect();
    assert!(loud.is_empty(), "{loud:#?}");
}

#[test]
fn a_recovered_component_is_marked_on_its_page_and_in_the_json() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = common::rtcdoc(
        &[
            "build",
            fixture("recovered").to_str().unwrap(),
            "-f",
            "html,markdown,json",
            "-o",
            out.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = std::fs::read_to_string(out.join("html/components/gripper.html")).unwrap();
    assert!(html.contains("<p class=\"note\"><a href=\"#implementation\">No profile: documented from the source code</a></p>"));
    assert!(html.contains("C++ · recovered from the source"));
    assert!(
        html.contains("<li>basicInfo/version: GRIPPER_VERSION (Gripper/src/Gripper.cpp:10)</li>")
    );
    let md = std::fs::read_to_string(out.join("markdown/components/gripper.md")).unwrap();
    assert!(
        md.contains("**No profile: documented from the source code**"),
        "{md}"
    );
    let index = std::fs::read_to_string(out.join("html/index.html")).unwrap();
    assert!(index.contains("data-impl=\"recovered\""));
    let bytes = std::fs::read(out.join("json/catalog.json")).unwrap();
    let v: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
    let g = v["components"]
        .as_object()
        .unwrap()
        .values()
        .find(|c| c["basicInfo"]["name"] == "Gripper")
        .unwrap();
    assert_eq!(g["recovered"]["unread"][0]["written"], "GRIPPER_VERSION");
    let back = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").expect("reads back");
    let mut again = Vec::new();
    rtcdoc::render::json::write_json_with(&back.catalog, &back.title, false, &mut again).unwrap();
    assert!(again == bytes, "catalog.json round trip differs");
}

#[test]
fn extract_writes_the_profile_the_code_describes_and_check_finds_no_drift() {
    let dir = tempfile::tempdir().unwrap();
    let work = dir.path().join("w");
    copy_fixture("recovered", &work);
    let o = rtcdoc_at(&["extract", "."], &work);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    // The folder of one component gets RTC.xml; a folder of two, one file each; the one a
    // profile documents already is left alone.
    for f in [
        "Gripper/RTC.xml",
        "Counter/RTC.xml",
        "lib/LeftArm.xml",
        "lib/RightArm.xml",
    ] {
        assert!(work.join(f).is_file(), "{f} not written: {err}");
    }
    assert!(
        err.contains(
            "left out 2 component(s) a profile documents already (Documented/Documented.py, Nested/src/src/Nested.cpp)"
        ),
        "{err}"
    );
    assert!(
        err.contains("not read from the code, left empty: basicInfo/version (GRIPPER_VERSION)"),
        "{err}"
    );
    let xml = std::fs::read_to_string(work.join("Gripper/RTC.xml")).unwrap();
    assert!(xml.contains("<!-- basicInfo/version is not read from the code (GRIPPER_VERSION at src/Gripper.cpp:10): set it. -->"), "{xml}");
    assert!(xml.contains("rtc:creationDate=\"2024-01-01T00:00:00+00:00\""));
    // Read back: the profile is the component's, and its code matches it.
    let p = rtcdoc::parse::parse(
        rtcdoc::parse::SourceFormat::Xml,
        xml.as_bytes(),
        "RTC.xml",
        &Default::default(),
    )
    .expect("reads back");
    assert_eq!(p.profile.name(), "Gripper");
    assert_eq!(p.profile.data_ports.len(), 2);
    assert_eq!(p.profile.configurations()[0].widget(), Some("slider.1"));
    let loaded = build::load(&work, &LoadOptions::default()).expect("load");
    assert!(loaded
        .catalog
        .components
        .iter()
        .all(|c| c.recovered.is_none()));
    for c in &loaded.catalog.components {
        let imp = c
            .implementation
            .as_ref()
            .unwrap_or_else(|| panic!("{}: no code read", c.source));
        assert!(imp.drift.is_empty(), "{}: {:#?}", c.source, imp.drift);
    }
    let f = findings(&work);
    let drift_or_errors: Vec<_> = f
        .iter()
        .filter(|x| {
            x.0.starts_with("RTC80")
                || x.0 == "RTC812"
                || (x.0 == "RTC101" && !x.2.contains("`version`"))
        })
        .collect();
    assert!(drift_or_errors.is_empty(), "{drift_or_errors:#?}");
    // Again: nothing is overwritten without --force, and nothing written at all.
    let before = std::fs::read(work.join("Counter/RTC.xml")).unwrap();
    std::fs::remove_file(work.join("lib/LeftArm.xml")).unwrap();
    let o = rtcdoc_at(&["extract", "lib"], &work);
    assert!(!o.status.success());
    assert!(
        String::from_utf8_lossy(&o.stderr)
            .contains("every component in `lib` has a profile already")
            || String::from_utf8_lossy(&o.stderr).contains("exists already"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // --stdout prints what it would write, byte for byte; --force rewrites.
    let o = rtcdoc_at(&["extract", "Counter", "--stdout"], &work);
    assert!(o.status.success());
    assert!(o.stdout == before, "the same input gives the same profile");
    let o = rtcdoc_at(&["extract", "Counter", "--force"], &work);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::read(work.join("Counter/RTC.xml")).unwrap() == before);
    // Several components and one output: refused, naming them.
    let o = rtcdoc_at(&["extract", "lib", "--stdout"], &work);
    assert!(!o.status.success());
    assert!(
        String::from_utf8_lossy(&o.stderr)
            .contains("holds 2 components (lib/LeftArm.cpp, lib/RightArm.cpp)")
            || String::from_utf8_lossy(&o.stderr)
                .contains("holds 2 components (LeftArm.cpp, RightArm.cpp)"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // No component: a clear error.
    let o = rtcdoc_at(&["extract", "Gripper/include"], &work);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("no component implementation in"));
}

/// The implementation read for the component of fixture `false-alarms/<name>`.
fn implementation_of(name: &str) -> rtcdoc::implementation::Implementation {
    let loaded =
        build::load(&fixture("false-alarms").join(name), &LoadOptions::default()).expect("load");
    *loaded.catalog.components[0]
        .implementation
        .clone()
        .expect("implementation")
}

/// Hand-edited code that real repositories hold, where the code and the profile agree: no
/// finding at all, or only "could not verify".
#[test]
fn agreeing_hand_edited_code_gives_no_false_alarm() {
    let drift = |name: &str| {
        findings(&fixture("false-alarms").join(name))
            .into_iter()
            .filter(|f| f.0.starts_with("RTC8"))
            .collect::<Vec<_>>()
    };
    for name in ["Mixer", "SheetView", "Vector", "Timer", "Relay"] {
        assert_eq!(drift(name), Vec::new(), "{name}");
    }
    // A base class of an installed package: what it registers and defines is not verified
    // (no "only in profile" for the in-port, no RTC808 for onFinalize).
    let f = drift("Gauge");
    assert_eq!(f.len(), 1, "{f:#?}");
    assert_eq!(f[0].0, "RTC810");
    assert!(f[0].2.contains("gaugekit.GaugeBase"), "{}", f[0].2);
}

#[test]
fn a_data_port_is_named_by_its_constructor_and_registered_once() {
    // `m_levelIn("level", m_level)` and `addInPort("levelIn", m_levelIn)`: OpenRTM's
    // PortBase runs the port under its constructor's name; `mixed` is added in two branches.
    let imp = implementation_of("Mixer");
    let ports: Vec<(&str, &str)> = imp
        .data_ports
        .iter()
        .map(|p| (p.name.as_str(), p.direction.profile_word()))
        .collect();
    assert_eq!(ports, [("level", "DataInPort"), ("mixed", "DataOutPort")]);
    // A multi-word type keeps its space; an export macro is no class name.
    assert_eq!(imp.parameters[0].type_.as_deref(), Some("unsigned long"));
    assert_eq!(imp.class.as_ref().map(|c| c.name.as_str()), Some("Mixer"));
    // The generated onStateUpdate stub is not "implemented".
    let su = imp.callbacks.iter().find(|c| c.name == "onStateUpdate");
    assert_eq!(su.map(|c| c.implemented), Some(false));
}

#[test]
fn a_python_base_class_in_a_sibling_module_is_read() {
    let imp = implementation_of("SheetView");
    assert_eq!(imp.files, ["SheetView.py", "SheetCore.py"]);
    // The component's class, not the listener defined before it.
    assert_eq!(
        imp.class.as_ref().map(|c| c.name.as_str()),
        Some("SheetView")
    );
    let mut ports: Vec<&str> = imp.data_ports.iter().map(|p| p.name.as_str()).collect();
    ports.sort();
    assert_eq!(ports, ["cells", "selected"]);
    assert!(imp.callbacks.iter().any(|c| c.name == "onActivated"));
}

#[test]
fn a_java_component_is_its_impl_class_and_a_library_header_is_not_read() {
    let imp = implementation_of("Timer");
    assert_eq!(
        imp.class.as_ref().map(|c| c.name.as_str()),
        Some("TimerImpl")
    );
    assert!(imp.unverified.is_empty(), "{:#?}", imp.unverified);
    // `third_party/VECTOR.h` matches `Vector.h` only by case; `code/Vector.cpp` exactly.
    let imp = implementation_of("Vector");
    assert_eq!(imp.files, ["code/Vector.cpp"]);
    assert_eq!(imp.class.as_ref().map(|c| c.name.as_str()), Some("Vector"));
}

#[test]
fn the_profile_marks_of_fsm_and_mode_callbacks_say_nothing_of_a_data_flow_component() {
    // Mixer's profile marks onAction and onModeChanged implemented, as RTCBuilder's "all"
    // does; it generates neither for a DataFlowComponent.
    let f = findings(&fixture("false-alarms/Mixer"));
    assert!(!f.iter().any(|x| x.0 == "RTC808"), "{f:#?}");
}

#[test]
fn every_declarator_of_a_declaration_has_its_type() {
    // `int m_retries, m_gain;`, `double m_offset = 0.0, *m_scratch, m_ratio;`,
    // `OutPort<TimedDouble> m_forwardOut, m_mirrorOut;`; `std::map<int, double>` declares
    // no `int`.
    let imp = implementation_of("Relay");
    let params: Vec<(&str, Option<&str>)> = imp
        .parameters
        .iter()
        .map(|p| (p.name.as_str(), p.type_.as_deref()))
        .collect();
    assert_eq!(
        params,
        [
            ("gain", Some("int")),
            ("ratio", Some("double")),
            ("mode", Some("std::string"))
        ]
    );
    let ports: Vec<(&str, &str, Option<&str>)> = imp
        .data_ports
        .iter()
        .map(|p| {
            (
                p.name.as_str(),
                p.direction.profile_word(),
                p.data_type.as_deref(),
            )
        })
        .collect();
    assert_eq!(
        ports,
        [
            ("speed", "DataInPort", Some("RTC::TimedDouble")),
            ("forward", "DataOutPort", Some("RTC::TimedDouble")),
            ("mirror", "DataOutPort", Some("RTC::TimedDouble")),
        ]
    );
}

#[test]
fn a_name_the_profile_declares_twice_is_no_drift() {
    // Relay's profile declares `ratio` twice; the code binds it once. The profile check
    // reports the duplicate; the code lacks nothing.
    let f = findings(&fixture("false-alarms/Relay"));
    let codes: Vec<&str> = f.iter().map(|x| x.0.as_str()).collect();
    assert!(codes.contains(&"RTC207"), "{f:#?}");
    assert!(!codes.contains(&"RTC801"), "{f:#?}");
}

#[test]
fn a_profile_default_in_quotes_is_the_code_literal_without_them() {
    // Relay's profile gives `mode` the default `"fast"`; RTCBuilder pastes it into the
    // literal, whose quotes they are: `"fast"` in the spec array and bindParameter agree.
    let f = findings(&fixture("false-alarms/Relay"));
    assert!(!f.iter().any(|x| x.0 == "RTC806"), "{f:#?}");
    // Any other difference is still one.
    let dir = tempfile::tempdir().expect("tempdir");
    copy_fixture("false-alarms/Relay", dir.path());
    let xml = dir.path().join("RTC.xml");
    let text = std::fs::read_to_string(&xml).expect("read");
    std::fs::write(&xml, text.replace("&quot;fast&quot;", "&quot;slow&quot;")).expect("write");
    let f = findings(dir.path());
    assert_eq!(f.iter().filter(|x| x.0 == "RTC806").count(), 2, "{f:#?}");
}
