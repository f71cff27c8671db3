//! Profiles of other writers and generations, read as they mean (issue 14): RTCBuilder's first
//! format (`rtc:version="0.1"`), OpenRTM-aist-Python's rtc-template YAML, wasanbon's empty
//! attributes and RTCBuilder's placeholders. Each fixture asserts the model fields, the
//! absence of the spurious findings, XML/YAML agreement, and that nothing is lost.

use crate::common;
use common::OutputWithin;

use rtcdoc::build::{self, LoadOptions};
use rtcdoc::catalog::Component;
use rtcdoc::check::{self, Report};
use rtcdoc::diagnostic::Diagnostic;
use rtcdoc::i18n::Lang;
use rtcdoc::model::{IdParts, Profile};
use rtcdoc::render::facts;
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::root().join("tests/fixtures/dialects").join(name)
}

/// The component of one fixture file and every finding about it (reader and rules).
fn load(name: &str) -> (Component, Report) {
    let loaded = build::load(&fixture(name), &LoadOptions::default()).expect("load");
    let report = check::check(&loaded.catalog);
    let c = loaded
        .catalog
        .components
        .into_iter()
        .next()
        .expect("one component");
    (c, report)
}

fn codes(r: &Report) -> Vec<&str> {
    r.diagnostics.iter().map(|d| d.code).collect()
}

fn of<'a>(r: &'a Report, code: &str) -> Vec<&'a Diagnostic> {
    r.diagnostics.iter().filter(|d| d.code == code).collect()
}

/// What the 0.1 fixtures mean, whatever their format.
fn assert_rtcbuilder01(p: &Profile, r: &Report) {
    let id = IdParts::parse(p.id.as_deref().unwrap(), &p.basic_info).expect("id parts");
    assert!(id.dotted);
    assert_eq!(
        (id.vendor, id.category, id.name, id.version),
        ("Acme", "Software algorithm", "Planner", "1.2.0")
    );
    let d = &p.data_ports[0];
    assert_eq!(d.variable_name.as_deref(), Some("route"));
    assert_eq!(d.subscription_type.as_deref(), Some("New"));
    assert_eq!(d.position.as_deref(), Some("right"));
    assert_eq!(
        d.doc.as_ref().unwrap().semantics.as_deref(),
        Some("Ordered waypoints.")
    );
    let i = &p.service_ports[0].interfaces[0];
    assert_eq!(i.variable_name.as_deref(), Some("planner"));
    assert_eq!(p.service_ports[0].position.as_deref(), Some("top"));
    let l = p.language.as_ref().expect("language");
    assert_eq!(l.kind.as_deref(), Some("C++"));
    assert_eq!(l.targets.len(), 1);
    assert_eq!(l.targets[0].os.as_deref(), Some("Linux"));
    assert_eq!(l.targets[0].cpus, vec!["x86_64"]);
    // Kept as written, read as EVENTDRIVEN.
    assert_eq!(p.basic_info.activity_type.as_deref(), Some("EVENT_DRIVEN"));
    let fields: Vec<&str> = p.written_as.iter().map(|w| w.field.as_str()).collect();
    for f in [
        "id",
        "basicInfo.activityType",
        "dataPort Route.variableName",
        "dataPort Route.subscriptionType",
        "serviceInterface plannerServices.variableName",
        "language.kind",
    ] {
        assert!(fields.contains(&f), "{f} not in writtenAs: {fields:?}");
    }
    assert!(p.written_as.iter().all(|w| !w.pos.is_unknown()));
    // None of the spurious findings: unknown attribute, id format / mismatch, enumeration,
    // missing language kind.
    for code in [
        "RTC006", "RTC011", "RTC101", "RTC102", "RTC201", "RTC202", "RTC212",
    ] {
        assert!(of(r, code).is_empty(), "{code}: {:#?}", r.diagnostics);
    }
    // Only the genuine one: the service port has no description.
    assert_eq!(codes(r), vec!["RTC502"], "{:#?}", r.diagnostics);
}

#[test]
fn rtcbuilder_0_1_xml_reads_as_it_means() {
    let (c, r) = load("rtcbuilder01.xml");
    assert_rtcbuilder01(&c.profile, &r);
    // The attribute as written is named in the JSON.
    let w = c
        .profile
        .written_as
        .iter()
        .find(|w| w.field == "dataPort Route.subscriptionType")
        .unwrap();
    assert_eq!(w.written_as, "rtc:subscriprionType");
    assert_eq!(w.dialect, "RTCBuilder 0.1");
    assert_eq!((w.pos.line, w.pos.column), (8, 98));
    let json = serde_json::to_value(&c).unwrap();
    assert_eq!(json["writtenAs"][0]["writtenAs"], "rtcExt:varname");
    // The variable name reaches the page.
    let f = facts::data_port(&c.profile.data_ports[0], Lang::En);
    assert!(f.iter().any(|f| f.value == "route"), "{f:?}");
}

#[test]
fn rtcbuilder_0_1_yaml_reads_as_the_xml() {
    let (y, ry) = load("rtcbuilder01.yaml");
    assert_rtcbuilder01(&y.profile, &ry);
    let (x, _) = load("rtcbuilder01.xml");
    // The two readers agree on every field of the model (positions and spellings aside).
    let strip = |c: &Component| {
        let mut v = serde_json::to_value(&*c.profile).unwrap();
        fn walk(v: &mut serde_json::Value) {
            match v {
                serde_json::Value::Object(m) => {
                    m.remove("pos");
                    m.remove("actionsPos");
                    m.remove("writtenAs");
                    m.values_mut().for_each(walk);
                }
                serde_json::Value::Array(a) => a.iter_mut().for_each(walk),
                _ => {}
            }
        }
        walk(&mut v);
        v
    };
    assert_eq!(strip(&x), strip(&y));
}

#[test]
fn rtc_template_yaml_reads_cleanly() {
    let (c, r) = load("rtc_template.yaml");
    assert!(r.diagnostics.is_empty(), "{:#?}", r.diagnostics);
    let p = &c.profile;
    let id = IdParts::parse(p.id.as_deref().unwrap(), &p.basic_info).unwrap();
    assert_eq!(
        (id.vendor, id.category, id.name, id.dotted),
        ("SampleVendor", "Sensor", "RangeReader", true)
    );
    assert_eq!(p.data_ports[0].variable_name.as_deref(), Some("m_range"));
    assert_eq!(p.data_ports[0].position.as_deref(), Some("RIGHT"));
    assert_eq!(
        p.service_ports[0].interfaces[0].variable_name.as_deref(),
        Some("m_ctrl")
    );
    assert_eq!(
        p.configurations()[0].variable_name.as_deref(),
        Some("m_port")
    );
    assert_eq!(
        p.basic_info.version_up_logs,
        vec!["2024/05/01 first version"]
    );
    let l = p.language.as_ref().unwrap();
    assert_eq!(l.kind.as_deref(), Some("Java"));
    assert_eq!(l.targets[0].libraries[0].name.as_deref(), Some("range.jar"));
    assert_eq!(r.coverage.percent, 100.0);
}

#[test]
fn wasanbon_empty_attributes_are_one_note_and_no_rows() {
    let (c, r) = load("wasanbon.xml");
    let notes = of(&r, "RTC011");
    assert_eq!(notes.len(), 1, "{:#?}", r.diagnostics);
    assert!(
        notes[0].message.starts_with("7 empty attributes"),
        "{}",
        notes[0].message
    );
    assert!(notes[0].message.contains("`rtcDoc:license`"));
    // A non-empty unknown attribute is still a warning of its own.
    let unknown = of(&r, "RTC006");
    assert_eq!(unknown.len(), 1, "{:#?}", r.diagnostics);
    assert!(unknown[0].message.contains("rtcDoc:hint"));
    assert_eq!(codes(&r).len(), 2, "{:#?}", r.diagnostics);
    // Kept (JSON) …
    let all = c.profile.all_extras();
    assert_eq!(all.len(), 8);
    assert!(all
        .iter()
        .any(|(path, e)| path == "configuration debug" && e.name == "rtcDoc:license"));
    // … but not shown as empty rows.
    let rows = facts::extras(&c.profile);
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert_eq!(rows[0].value, "verbose above 1");
}

#[test]
fn placeholders_are_found_in_xml_and_yaml_alike() {
    for name in ["placeholders.xml", "placeholders.yaml"] {
        let (c, r) = load(name);
        let found: Vec<&str> = of(&r, "RTC306")
            .iter()
            .map(|d| d.message.as_str())
            .collect();
        assert_eq!(found.len(), 6, "{name}: {found:#?}");
        for what in [
            "name `ModuleName`",
            "vendor `VenderName`",
            "category `Category`",
            "description `ModuleDescription`",
            "configuration `file` is RTCBuilder's placeholder `conf_constraint`",
            "data port `in` is RTCBuilder's placeholder `dp_constraint`",
        ] {
            assert!(found.iter().any(|m| m.contains(what)), "{name}: {what}");
        }
        // The placeholder constraint is not evaluated against `beep.wav`, and a placeholder
        // description does not document the component.
        assert!(of(&r, "RTC303").is_empty() && of(&r, "RTC304").is_empty());
        assert_eq!(of(&r, "RTC501").len(), 1, "{name}");
        // Neither constraint is rendered ("x = dp_constraint").
        let p = &c.profile;
        let port = facts::data_port(&p.data_ports[0], Lang::En);
        assert!(
            port.iter().all(|f| !f.value.contains("dp_constraint")),
            "{port:?}"
        );
        assert_eq!(
            facts::configuration_constraint(&p.configurations()[0], rtcdoc::i18n::Lang::En),
            None
        );
        // … but kept.
        assert!(p.data_ports[0].constraint.is_some());
    }
}

#[test]
fn dotted_ids_split_with_basic_info() {
    let mut p = Profile::default();
    // A vendor with a dot: BasicInfo tells where the parts end.
    p.basic_info.vendor = Some("ysuga.net".into());
    p.basic_info.category = Some("Sensor".into());
    p.basic_info.name = Some("Cam".into());
    let id = IdParts::parse("RTC:ysuga.net.Sensor.Cam:1.0", &p.basic_info).unwrap();
    assert_eq!(
        (id.vendor, id.category, id.name),
        ("ysuga.net", "Sensor", "Cam")
    );
    // Without BasicInfo: the vendor to the first dot, the name from the last.
    let none = Profile::default();
    let id = IdParts::parse("RTC:a.b c.d.e:2", &none.basic_info).unwrap();
    assert_eq!(
        (id.vendor, id.category, id.name, id.version),
        ("a", "b c.d", "e", "2")
    );
    assert!(IdParts::parse("RTC:a.b:1", &none.basic_info).is_none());
    assert!(IdParts::parse("RTC:a:b:c", &none.basic_info).is_none());
    let colon = IdParts::parse("RTC:v:c:n:1", &none.basic_info).unwrap();
    assert!(!colon.dotted);
}

/// Every value of the XML fixtures is in the JSON (the shared nothing_lost.py), and every
/// non-empty scalar of the YAML fixtures too.
#[test]
fn dialect_fixtures_lose_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::root().join("tests/fixtures/dialects");
    let out = dir.path().join("out");
    let opts = rtcdoc::build::BuildOptions {
        input: input.clone(),
        output: out.clone(),
        formats: vec![rtcdoc::render::Format::Json],
        strict: false,
        load: LoadOptions::default(),
        site: Default::default(),
    };
    let (loaded, _) = build::build(&opts).unwrap();
    let catalog: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("catalog.json")).unwrap()).unwrap();
    if let Some(tool) = common::shared_tool("nothing_lost.py") {
        let run = std::process::Command::new("python3")
            .arg(&tool)
            .arg(&input)
            .arg(out.join("catalog.json"))
            .output_within(common::COMMAND_LIMIT)
            .expect("python3");
        let stdout = String::from_utf8_lossy(&run.stdout);
        assert!(run.status.success(), "nothing_lost.py failed:\n{stdout}");
        assert!(
            stdout.contains("lost: 0, profiles without component: 0"),
            "{stdout}"
        );
    } else {
        println!("skipped (XML part): nothing_lost.py not present");
    }
    fn scalars(v: &serde_json::Value, out: &mut Vec<String>) {
        match v {
            serde_json::Value::Object(m) => m.values().for_each(|v| scalars(v, out)),
            serde_json::Value::Array(a) => a.iter().for_each(|v| scalars(v, out)),
            serde_json::Value::String(s) => out.push(s.trim().to_string()),
            serde_json::Value::Number(n) => out.push(n.to_string()),
            serde_json::Value::Bool(b) => out.push(b.to_string()),
            serde_json::Value::Null => {}
        }
    }
    fn yaml_scalars(key: &str, v: &serde_norway::Value, out: &mut Vec<(String, String)>) {
        match v {
            serde_norway::Value::Mapping(m) => {
                for (k, v) in m {
                    let k = k.as_str().unwrap_or("").to_string();
                    // Date maps become one ISO string.
                    if k != "creationDate" && k != "updateDate" {
                        yaml_scalars(&k, v, out);
                    }
                }
            }
            serde_norway::Value::Sequence(s) => s.iter().for_each(|v| yaml_scalars(key, v, out)),
            serde_norway::Value::String(s) if !s.trim().is_empty() => {
                out.push((key.to_string(), s.trim().to_string()))
            }
            serde_norway::Value::Number(n) => out.push((key.to_string(), n.to_string())),
            serde_norway::Value::Bool(b) => out.push((key.to_string(), b.to_string())),
            _ => {}
        }
    }
    let comps: Vec<&serde_json::Value> = catalog["components"]
        .as_object()
        .unwrap()
        .values()
        .collect();
    let mut checked = 0;
    for c in &loaded.catalog.components {
        if !c.source.ends_with(".yaml") {
            continue;
        }
        let json = comps
            .iter()
            .find(|j| j["source"] == c.source.as_str())
            .unwrap();
        let mut pool = Vec::new();
        scalars(json, &mut pool);
        let src: serde_norway::Value =
            serde_norway::from_slice(&std::fs::read(input.join(&c.source)).unwrap()).unwrap();
        let mut vals = Vec::new();
        yaml_scalars("", &src, &mut vals);
        for (k, v) in vals {
            checked += 1;
            let num = |s: &str| s.parse::<f64>().ok();
            let hit = pool.contains(&v)
                || num(&v).is_some_and(|n| pool.iter().any(|p| num(p) == Some(n)));
            assert!(hit, "{}: {k} = {v:?} lost", c.source);
        }
    }
    assert!(checked > 100, "{checked}");
}

/// The dotted and the colon form of one id name the same component (RTC010).
#[test]
fn dotted_and_colon_ids_are_one_id() {
    let dir = tempfile::tempdir().unwrap();
    let old = std::fs::read_to_string(fixture("rtcbuilder01.xml")).unwrap();
    std::fs::create_dir_all(dir.path().join("a")).unwrap();
    std::fs::create_dir_all(dir.path().join("b")).unwrap();
    std::fs::write(dir.path().join("a/RTC.xml"), &old).unwrap();
    let colon = old.replace(
        "RTC:Acme.Software algorithm.Planner:1.2.0",
        "RTC:Acme:Software algorithm:Planner:1.2.0",
    );
    assert_ne!(colon, old);
    std::fs::write(dir.path().join("b/RTC.xml"), colon).unwrap();
    let loaded = build::load(dir.path(), &LoadOptions::default()).unwrap();
    let r = check::check(&loaded.catalog);
    assert_eq!(of(&r, "RTC010").len(), 2, "{:#?}", r.diagnostics);
    // Same name, same language: told apart by folder, with readable slugs.
    let slugs: Vec<&str> = loaded
        .catalog
        .components
        .iter()
        .map(|c| c.slug.as_str())
        .collect();
    assert_eq!(slugs, vec!["planner-a", "planner-b"]);
    assert_eq!(loaded.catalog.components[0].display_name(), "Planner (a)");
}

/// A profile as loaded from `source`, with name, category and implementation language.
fn loaded_profile(
    name: &str,
    category: &str,
    lang: &str,
    source: &str,
) -> rtcdoc::catalog::LoadedProfile {
    let mut p = Profile::default();
    p.basic_info.name = Some(name.into());
    p.basic_info.category = Some(category.into());
    p.language = Some(rtcdoc::model::Language {
        kind: Some(lang.into()),
        ..Default::default()
    });
    rtcdoc::catalog::LoadedProfile {
        source: source.into(),
        format: rtcdoc::parse::SourceFormat::Xml,
        profile: Box::new(p),
    }
}

/// Categories differing only in case or spacing (`_` and `-` count as spaces) are one facet; the C++ and Python variants
/// of one component get their language as slug and qualifier.
#[test]
fn facets_fold_spellings_and_variants_get_language_slugs() {
    use rtcdoc::catalog::Catalog;
    let comp = loaded_profile;
    let cat = Catalog::build(
        vec![
            comp("RobotController", "Hardware Interface", "C++", "a/RTC.xml"),
            comp(
                "RobotController",
                "Hardware interface",
                "Python",
                "b/RTC.xml",
            ),
            comp("Other", "Hardware interface", "C++", "c/RTC.xml"),
            comp("Third", "Hardware_interface", "C++", "d/RTC.xml"),
        ],
        vec![],
    );
    assert_eq!(cat.categories.len(), 1);
    let f = &cat.categories[0];
    assert_eq!(f.name, "Hardware interface");
    assert_eq!(f.variants, vec!["Hardware Interface", "Hardware_interface"]);
    assert_eq!(f.slug, "hardware-interface");
    assert_eq!(
        cat.members(f).map(|ci| ci.get()).collect::<Vec<_>>(),
        vec![0, 1, 2, 3]
    );
    let slugs: Vec<&str> = cat.components.iter().map(|c| c.slug.as_str()).collect();
    assert_eq!(
        slugs,
        vec![
            "robotcontroller-cpp",
            "robotcontroller-python",
            "other",
            "third"
        ]
    );
    assert_eq!(cat.components[1].display_name(), "RobotController (Python)");
    assert_eq!(cat.components[2].qualifier, None);
}

/// A group of one name where one profile is told apart by its language and the others (of
/// one language) by place reads one way: the others say their language too.
#[test]
fn a_group_told_apart_by_language_and_place_names_the_language_throughout() {
    use rtcdoc::catalog::Catalog;
    let comp = |lang: &str, source: &str| loaded_profile("MyFirst", "Cat", lang, source);
    let cat = Catalog::build(
        vec![
            comp("C++", "Components/MyFirst/RTC.xml"),
            comp("C++", "projects/test/MyFirst/RTC.xml"),
            comp("Python", "py/MyFirst/RTC.xml"),
        ],
        vec![],
    );
    let names: Vec<String> = cat
        .components
        .iter()
        .map(|c| c.display_name().into_owned())
        .collect();
    assert_eq!(
        names,
        [
            "MyFirst (C++, Components)",
            "MyFirst (C++, projects)",
            "MyFirst (Python)"
        ]
    );
    let slugs: Vec<&str> = cat.components.iter().map(|c| c.slug.as_str()).collect();
    assert_eq!(
        slugs,
        [
            "myfirst-cpp-components",
            "myfirst-cpp-projects",
            "myfirst-python"
        ]
    );
}

/// The same profile in the current spellings: `rtcdoc diff` finds no change (the older
/// spellings are read into the fields they mean; which ones a file used is no value of it).
#[test]
fn a_file_resaved_in_the_current_spellings_is_no_change() {
    let old = std::fs::read_to_string(fixture("rtcbuilder01.xml")).unwrap();
    let new = old
        .replace("rtcExt:varname=", "rtcExt:variableName=")
        .replace("rtc:subscriprionType=", "rtc:subscriptionType=");
    assert_ne!(old, new, "the fixture uses both older spellings");
    let dir = tempfile::tempdir().unwrap();
    common::write(dir.path(), "old/RTC.xml", &old);
    common::write(dir.path(), "new/RTC.xml", &new);
    let o = common::rtcdoc(&["diff", "old", "new", "--fail-on", "info"], dir.path());
    let out = String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("0 breaking, 0 warnings, 0 infos"), "{out}");
}
