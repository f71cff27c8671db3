//! `rtcdoc diff` through the binary: every change code from an old/new pair that differs in
//! one edit, the catalogue-level cases (removed, added, moved, swapped, ambiguous, unreadable),
//! a git revision of a temporary repository, every output format and every `--fail-on` level.

use crate::common;
use common::git;
use common::OutputWithin;
use common::{root, rtcdoc, write};
use serde_json::Value;
use std::path::Path;

/// A profile with something of every kind the diff compares.
const BASE: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcDoc="http://www.openrtp.org/namespaces/rtc_doc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:Lab:Mobile:Base:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="Base" rtc:vendor="Lab" rtc:category="Mobile" rtc:version="1.0.0" rtc:componentType="STATIC" rtc:activityType="PERIODIC" rtc:componentKind="DataFlowComponent" rtc:executionType="PeriodicExecutionContext" rtc:executionRate="100.0" rtc:maxInstances="4" rtc:description="Drives the base" rtc:creationDate="2024-01-01T00:00:00+09:00" rtc:updateDate="2024-01-01T00:00:00+09:00"/>
  <rtc:Actions>
    <rtc:OnInitialize xsi:type="rtcDoc:action_status_doc" rtc:implemented="true"/>
    <rtc:OnActivated xsi:type="rtcDoc:action_status_doc" rtc:implemented="true"/>
    <rtc:OnExecute xsi:type="rtcDoc:action_status_doc" rtc:implemented="true"/>
  </rtc:Actions>
  <rtc:ConfigurationSet>
    <rtc:Configuration xsi:type="rtcExt:configuration_ext" rtc:name="gain" rtc:type="double" rtc:defaultValue="5.0" rtc:unit="m">
      <rtc:Constraint>
        <rtc:ConstraintUnitType>
          <rtc:propertyIsBetween>
            <rtc:LowerBoundary>0</rtc:LowerBoundary>
            <rtc:UpperBoundary>10</rtc:UpperBoundary>
          </rtc:propertyIsBetween>
        </rtc:ConstraintUnitType>
      </rtc:Constraint>
      <rtcDoc:Doc rtcDoc:description="Gain of the loop"/>
    </rtc:Configuration>
    <rtc:Configuration xsi:type="rtcExt:configuration_ext" rtc:name="mode" rtc:type="string" rtc:defaultValue="fast">
      <rtc:Constraint>
        <rtc:ConstraintUnitType>
          <rtc:propertyIsLike>
            <rtc:Literal>f*</rtc:Literal>
          </rtc:propertyIsLike>
        </rtc:ConstraintUnitType>
      </rtc:Constraint>
    </rtc:Configuration>
  </rtc:ConfigurationSet>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataInPort" rtc:name="cmd" rtc:type="RTC::TimedVelocity2D" rtc:unit="m/s"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="odometry" rtc:type="RTC::TimedPose2D" rtc:dataflowType="push,pull" rtcExt:position="RIGHT"/>
  <rtc:ServicePorts xsi:type="rtcExt:serviceport_ext" rtc:name="Map">
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="map" rtc:type="Nav::MapService" rtc:direction="Provided" rtc:idlFile="Map.idl"/>
  </rtc:ServicePorts>
  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="C++"/>
</rtc:RtcProfile>
"#;

/// `BASE` with each `(from, to)` replaced once (the edit must apply).
fn edited(edits: &[(&str, &str)]) -> String {
    let mut s = BASE.to_string();
    for (from, to) in edits {
        assert!(s.contains(from), "edit `{from}` does not apply");
        s = s.replacen(from, to, 1);
    }
    s
}

/// A version bump, to keep DIFF208 out of the cases that are not about it.
const BUMP: [(&str, &str); 2] = [
    (":Base:1.0.0\"", ":Base:2.0.0\""),
    ("rtc:version=\"1.0.0\"", "rtc:version=\"2.0.0\""),
];

fn run_diff(dir: &Path, args: &[&str]) -> (i32, Value) {
    let mut all = vec!["diff", "old", "new", "--format", "json"];
    all.extend_from_slice(args);
    let out = rtcdoc(&all, dir);
    let code = out.status.code().expect("exit code");
    let json: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (code, json)
}

fn changes(json: &Value) -> Vec<&Value> {
    json["changes"]
        .as_array()
        .expect("changes")
        .iter()
        .collect()
}

fn codes_of(json: &Value) -> Vec<String> {
    let mut v: Vec<String> = changes(json)
        .iter()
        .map(|c| c["code"].as_str().unwrap_or("").to_string())
        .collect();
    v.sort();
    v
}

struct Case {
    code: &'static str,
    edits: Vec<(&'static str, &'static str)>,
    /// The version is raised with the edit (so no DIFF208).
    bump: bool,
    path: &'static str,
    /// Every code the edit must produce (the version bump's DIFF306 is added when `bump`).
    all: Vec<&'static str>,
    /// Text the change's message must contain.
    says: &'static str,
}

fn case(
    code: &'static str,
    edits: Vec<(&'static str, &'static str)>,
    path: &'static str,
    all: Vec<&'static str>,
    says: &'static str,
) -> Case {
    Case {
        code,
        edits,
        bump: true,
        path,
        all,
        says,
    }
}

fn cases() -> Vec<Case> {
    let port_odometry = r#"  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="odometry" rtc:type="RTC::TimedPose2D" rtc:dataflowType="push,pull" rtcExt:position="RIGHT"/>
"#;
    let interface = r#"    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="map" rtc:type="Nav::MapService" rtc:direction="Provided" rtc:idlFile="Map.idl"/>
"#;
    let mode_config = BASE
        .find(r#"    <rtc:Configuration xsi:type="rtcExt:configuration_ext" rtc:name="mode""#)
        .map(|start| {
            let end = BASE[start..].find("</rtc:Configuration>\n").expect("end") + start;
            &BASE[start..end + "</rtc:Configuration>\n".len()]
        })
        .expect("mode configuration");
    vec![
        case(
            "DIFF102",
            vec![(port_odometry, "")],
            "dataPorts/odometry",
            vec!["DIFF102"],
            "data port `odometry` was removed",
        ),
        case(
            "DIFF103",
            vec![(
                r#"rtc:portType="DataOutPort" rtc:name="odometry""#,
                r#"rtc:portType="DataInPort" rtc:name="odometry""#,
            )],
            "dataPorts/odometry/portType",
            vec!["DIFF103"],
            "`DataOutPort` to `DataInPort`",
        ),
        case(
            "DIFF104",
            vec![("RTC::TimedPose2D", "RTC::TimedPose3D")],
            "dataPorts/odometry/type",
            vec!["DIFF104"],
            "now carries `RTC::TimedPose3D`",
        ),
        case(
            "DIFF105",
            vec![(
                &BASE[BASE.find("  <rtc:ServicePorts").expect("sp")
                    ..BASE.find("  <rtc:Language").expect("lang")],
                "",
            )],
            "servicePorts/Map",
            vec!["DIFF105"],
            "service port `Map` was removed",
        ),
        case(
            "DIFF106",
            vec![(interface, "")],
            "servicePorts/Map/interfaces/map",
            vec!["DIFF106"],
            "Provided interface `map` of service port `Map` was removed",
        ),
        case(
            "DIFF107",
            vec![("Nav::MapService", "Nav::MapService2")],
            "servicePorts/Map/interfaces/map/type",
            vec!["DIFF107"],
            "is now `Nav::MapService2`",
        ),
        case(
            "DIFF108",
            vec![(r#"rtc:direction="Provided""#, r#"rtc:direction="Required""#)],
            "servicePorts/Map/interfaces/map/direction",
            vec!["DIFF108"],
            "`Provided` to `Required`",
        ),
        case(
            "DIFF109",
            vec![(mode_config, "")],
            "configurations/mode",
            vec!["DIFF109"],
            "configuration parameter `mode` was removed",
        ),
        case(
            "DIFF110",
            vec![(
                r#"rtc:name="gain" rtc:type="double""#,
                r#"rtc:name="gain" rtc:type="int""#,
            )],
            "configurations/gain/type",
            vec!["DIFF110"],
            "is now `int` instead of `double`",
        ),
        case(
            "DIFF201",
            vec![(r#"rtc:defaultValue="5.0""#, r#"rtc:defaultValue="6.0""#)],
            "configurations/gain/defaultValue",
            vec!["DIFF201"],
            "from `5.0` to `6.0`",
        ),
        case(
            "DIFF202",
            vec![(
                "<rtc:UpperBoundary>10</rtc:UpperBoundary>",
                "<rtc:UpperBoundary>4</rtc:UpperBoundary>",
            )],
            "configurations/gain/constraint",
            vec!["DIFF202"],
            "the old default `5.0` no longer satisfies it",
        ),
        case(
            "DIFF203",
            vec![(
                "<rtc:Literal>f*</rtc:Literal>",
                "<rtc:Literal>s*</rtc:Literal>",
            )],
            "configurations/mode/constraint",
            vec!["DIFF203"],
            "the old default `fast` no longer satisfies it",
        ),
        case(
            "DIFF204",
            vec![(
                r#"rtc:executionType="PeriodicExecutionContext""#,
                r#"rtc:executionType="ExtTrigExecutionContext""#,
            )],
            "basicInfo/executionType",
            vec!["DIFF204"],
            "ExtTrigExecutionContext",
        ),
        case(
            "DIFF205",
            vec![(r#"rtc:executionRate="100.0""#, r#"rtc:executionRate="50""#)],
            "basicInfo/executionRate",
            vec!["DIFF205"],
            "execution rate `100.0` → `50`",
        ),
        case(
            "DIFF206",
            vec![(r#"rtc:maxInstances="4""#, r#"rtc:maxInstances="1""#)],
            "basicInfo/maxInstances",
            vec!["DIFF206"],
            "at most 1 instance(s) now (was 4)",
        ),
        case(
            "DIFF207",
            vec![(
                r#"<rtc:OnActivated xsi:type="rtcDoc:action_status_doc" rtc:implemented="true"/>"#,
                r#"<rtc:OnActivated xsi:type="rtcDoc:action_status_doc" rtc:implemented="false"/>"#,
            )],
            "actions/onActivated/implemented",
            vec!["DIFF207"],
            "action `onActivated` is no longer implemented",
        ),
        Case {
            bump: false,
            ..case(
                "DIFF208",
                vec![("RTC::TimedPose2D", "RTC::TimedPose3D")],
                "basicInfo/version",
                vec!["DIFF104", "DIFF208"],
                "keeps version 1.0.0",
            )
        },
        case(
            "DIFF209",
            vec![(
                r#"rtc:dataflowType="push,pull""#,
                r#"rtc:dataflowType="push""#,
            )],
            "dataPorts/odometry/dataflowType",
            vec!["DIFF209"],
            "no longer offers `pull`",
        ),
        case(
            "DIFF210",
            vec![(r#"rtc:unit="m">"#, r#"rtc:unit="mm">"#)],
            "configurations/gain/unit",
            vec!["DIFF210"],
            "from `m` to `mm`",
        ),
        // An empty value is said to be empty: `` would open a code span.
        case(
            "DIFF210",
            vec![(r#"rtc:unit="m">"#, r#"rtc:unit="">"#)],
            "configurations/gain/unit",
            vec!["DIFF210"],
            "from `m` to (empty)",
        ),
        case(
            "DIFF211",
            vec![(
                interface,
                r#"    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="map" rtc:type="Nav::MapService" rtc:direction="Provided" rtc:idlFile="Map.idl"/>
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="log" rtc:type="Nav::Logger" rtc:direction="Required"/>
"#,
            )],
            "servicePorts/Map/interfaces/log",
            vec!["DIFF211"],
            "Required interface `log` was added",
        ),
        case(
            "DIFF301",
            vec![(
                port_odometry,
                r#"  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="odometry" rtc:type="RTC::TimedPose2D" rtc:dataflowType="push,pull" rtcExt:position="RIGHT"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="battery" rtc:type="RTC::TimedDouble"/>
"#,
            )],
            "dataPorts/battery",
            vec!["DIFF301"],
            "data port `battery` (DataOutPort) was added",
        ),
        case(
            "DIFF302",
            vec![(
                interface,
                r#"    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="map" rtc:type="Nav::MapService" rtc:direction="Provided" rtc:idlFile="Map.idl"/>
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="status" rtc:type="Nav::Status" rtc:direction="Provided"/>
"#,
            )],
            "servicePorts/Map/interfaces/status",
            vec!["DIFF302"],
            "Provided interface `status` was added",
        ),
        case(
            "DIFF303",
            vec![(
                "  </rtc:ConfigurationSet>",
                r#"    <rtc:Configuration xsi:type="rtcExt:configuration_ext" rtc:name="debug" rtc:type="bool" rtc:defaultValue="false"/>
  </rtc:ConfigurationSet>"#,
            )],
            "configurations/debug",
            vec!["DIFF303"],
            "configuration parameter `debug` was added (default `false`)",
        ),
        case(
            "DIFF305",
            vec![(
                "<rtc:UpperBoundary>10</rtc:UpperBoundary>",
                "<rtc:UpperBoundary>20</rtc:UpperBoundary>",
            )],
            "configurations/gain/constraint",
            vec!["DIFF305"],
            "it accepts more values",
        ),
        case(
            "DIFF306",
            vec![],
            "basicInfo/version",
            vec![],
            "version `1.0.0` → `2.0.0`",
        ),
        case(
            "DIFF307",
            vec![("Gain of the loop", "Gain of the velocity loop")],
            "configurations/gain/doc/description",
            vec!["DIFF307"],
            "Gain of the velocity loop",
        ),
        case(
            "DIFF308",
            vec![(r#"rtcExt:position="RIGHT""#, r#"rtcExt:position="LEFT""#)],
            "dataPorts/odometry/position",
            vec!["DIFF308"],
            "from `RIGHT` to `LEFT`",
        ),
    ]
}

/// Codes exercised by the catalogue-level tests below rather than by one-edit cases.
const CATALOGUE_CODES: [&str; 4] = ["DIFF001", "DIFF002", "DIFF101", "DIFF304"];

#[test]
fn every_code_from_a_one_edit_pair() {
    let cases = cases();
    for c in rtcdoc::diff::CODES {
        assert!(
            cases.iter().any(|k| k.code == c.code)
                || CATALOGUE_CODES.contains(&c.code)
                // The drift codes have a fixture pair of code edits (tests/suite/diff_drift.rs).
                || crate::diff_drift::CODES.contains(&c.code)
                // The IDL and connector codes have fixture pairs (tests/suite/diff_fixtures.rs).
                || root().join("tests/fixtures/diff").join(c.code).is_dir(),
            "no test case for {}",
            c.code
        );
    }
    for k in &cases {
        let dir = tempfile::tempdir().expect("tempdir");
        write(dir.path(), "old/Base/RTC.xml", BASE);
        let mut edits = k.edits.clone();
        if k.bump {
            edits.extend(BUMP);
        }
        write(dir.path(), "new/Base/RTC.xml", &edited(&edits));
        let (exit, json) = run_diff(dir.path(), &[]);
        let mut expected: Vec<String> = k.all.iter().map(|s| s.to_string()).collect();
        if k.bump {
            expected.push("DIFF306".into());
        }
        expected.sort();
        assert_eq!(codes_of(&json), expected, "{}: {json:#}", k.code);
        let entry = rtcdoc::diff::codes::code(k.code).expect("registered");
        let found = changes(&json)
            .into_iter()
            .find(|c| c["code"] == k.code && c["path"] == k.path)
            .unwrap_or_else(|| panic!("{}: no change at {}: {json:#}", k.code, k.path));
        assert_eq!(found["severity"], entry.level.to_string(), "{}", k.code);
        assert_eq!(found["name"], entry.name, "{}", k.code);
        let version = if k.bump { "2.0.0" } else { "1.0.0" };
        assert_eq!(
            found["component"],
            format!("RTC:Lab:Mobile:Base:{version}"),
            "{}",
            k.code
        );
        assert!(
            found["message"].as_str().unwrap_or("").contains(k.says),
            "{}: {}",
            k.code,
            found["message"]
        );
        assert_eq!(found["file"], "new/Base/RTC.xml", "{}", k.code);
        // A removed item is located in OLD, where it exists; anything else in NEW.
        let line = if found["line"].is_null() {
            assert_eq!(found["oldFile"], "old/Base/RTC.xml", "{}", k.code);
            &found["oldLine"]
        } else {
            &found["line"]
        };
        assert!(line.as_u64().unwrap_or(0) > 0, "{}: a line", k.code);
        let breaking = expected.iter().any(|c| c.starts_with("DIFF1"));
        assert_eq!(exit, i32::from(breaking), "{}: exit status", k.code);
        assert_eq!(json["summary"]["failed"], breaking, "{}", k.code);
    }
}

/// A matched component is named by NEW's id.
#[test]
fn component_id_is_the_new_version() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    write(
        dir.path(),
        "new/RTC.xml",
        &edited(&[("RTC::TimedPose2D", "RTC::TimedPose3D")]),
    );
    let (_, json) = run_diff(dir.path(), &[]);
    assert!(changes(&json)
        .iter()
        .all(|c| c["component"] == "RTC:Lab:Mobile:Base:1.0.0"));
}

#[test]
fn equal_canonical_types_and_respelled_values_are_not_breaking() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    write(
        dir.path(),
        "new/RTC.xml",
        &edited(&[
            ("RTC::TimedPose2D", "IDL:RTC/TimedPose2D:1.0"),
            ("RTC::TimedVelocity2D", "TimedVelocity2D"),
            (r#"rtc:executionRate="100.0""#, r#"rtc:executionRate="100""#),
            (r#"rtc:direction="Provided""#, r#"rtc:direction="PROVIDED""#),
            (
                r#"rtc:name="mode" rtc:type="string""#,
                r#"rtc:name="mode" rtc:type="std::string""#,
            ),
        ]),
    );
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 0, "{json:#}");
    assert_eq!(codes_of(&json), vec!["DIFF308"; 5], "{json:#}");
    assert!(changes(&json).iter().all(|c| c["message"]
        .as_str()
        .unwrap_or("")
        .contains("spelled differently")));
}

#[test]
fn identical_sides_have_no_changes() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    write(dir.path(), "new/RTC.xml", BASE);
    let (exit, json) = run_diff(dir.path(), &["--fail-on", "info"]);
    assert_eq!(exit, 0);
    assert!(changes(&json).is_empty());
    assert_eq!(json["formatVersion"], 1);
    assert_eq!(json["summary"]["components"]["matched"], 1);
}

/// A profile of component `name` with one out-port of type `ty`, written by `lang`.
fn component(name: &str, ty: &str, lang: &str) -> String {
    BASE.replace(":Base:1.0.0", &format!(":{name}:1.0.0"))
        .replace(r#"rtc:name="Base""#, &format!(r#"rtc:name="{name}""#))
        .replace("RTC::TimedPose2D", ty)
        .replace(r#"rtc:kind="C++""#, &format!(r#"rtc:kind="{lang}""#))
}

#[test]
fn removed_and_added_components() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(
        dir.path(),
        "old/a/RTC.xml",
        &component("Alpha", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "old/b/RTC.xml",
        &component("Beta", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "new/b/RTC.xml",
        &component("Beta", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "new/c/RTC.xml",
        &component("Gamma", "RTC::TimedLong", "C++"),
    );
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 1);
    assert_eq!(codes_of(&json), ["DIFF101", "DIFF304"], "{json:#}");
    let removed = changes(&json)[0];
    assert_eq!(removed["component"], "RTC:Lab:Mobile:Alpha:1.0.0");
    assert_eq!(removed["severity"], "breaking");
    assert_eq!(removed["path"], "");
    assert_eq!(removed["oldFile"], "old/a/RTC.xml");
    assert_eq!(removed["file"], Value::Null);
    let added = changes(&json)[1];
    assert_eq!(added["component"], "RTC:Lab:Mobile:Gamma:1.0.0");
    assert_eq!(added["severity"], "info");
    assert_eq!(added["file"], "new/c/RTC.xml");
    let s = &json["summary"]["components"];
    assert_eq!((s["old"].as_u64(), s["new"].as_u64()), (Some(2), Some(2)));
    assert_eq!(
        (
            s["matched"].as_u64(),
            s["added"].as_u64(),
            s["removed"].as_u64()
        ),
        (Some(1), Some(1), Some(1))
    );
    // Adding a component only: informational, exit 0 by default, 1 with --fail-on info.
    std::fs::remove_dir_all(dir.path().join("old/a")).expect("rm");
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!((exit, codes_of(&json)), (0, vec!["DIFF304".to_string()]));
    let (exit, _) = run_diff(dir.path(), &["--fail-on", "info"]);
    assert_eq!(exit, 1);
}

#[test]
fn a_moved_file_and_swapped_folders_are_no_change() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (a, b) = (
        component("Alpha", "RTC::TimedLong", "C++"),
        component("Beta", "RTC::TimedDouble", "C++"),
    );
    write(dir.path(), "old/x/RTC.xml", &a);
    write(dir.path(), "old/y/RTC.xml", &b);
    // Swapped between the folders, and one moved deeper.
    write(dir.path(), "new/y/RTC.xml", &a);
    write(dir.path(), "new/deeper/x/Beta.xml", &b);
    let (exit, json) = run_diff(dir.path(), &["--fail-on", "info"]);
    assert_eq!(exit, 0, "{json:#}");
    assert!(changes(&json).is_empty(), "{json:#}");
    assert_eq!(json["summary"]["components"]["matched"], 2);
}

#[test]
fn the_dotted_id_form_names_the_same_component() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    write(
        dir.path(),
        "new/RTC.xml",
        &BASE.replace("RTC:Lab:Mobile:Base:1.0.0", "RTC:Lab.Mobile.Base:1.0.0"),
    );
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 0, "{json:#}");
    // The id is only respelled: one info on the id. Which spellings the file used
    // (`writtenAs`) is the reader's bookkeeping, not a second change.
    assert_eq!(codes_of(&json), ["DIFF308"], "{json:#}");
    assert_eq!(changes(&json)[0]["path"], "id");
}

#[test]
fn duplicate_ids_pair_by_language_else_are_ambiguous() {
    let dir = tempfile::tempdir().expect("tempdir");
    // One id, a C++ and a Python variant: moved and paired by language; the Python one changes.
    write(
        dir.path(),
        "old/cpp/RTC.xml",
        &component("Dup", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "old/py/RTC.xml",
        &component("Dup", "RTC::TimedLong", "Python"),
    );
    write(
        dir.path(),
        "new/a/RTC.xml",
        &component("Dup", "RTC::TimedDouble", "Python"),
    );
    write(
        dir.path(),
        "new/b/RTC.xml",
        &component("Dup", "RTC::TimedLong", "C++"),
    );
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 1);
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"], "{json:#}");
    assert_eq!(
        changes(&json)[0]["component"],
        "RTC:Lab:Mobile:Dup:1.0.0 (Python)"
    );
    assert_eq!(changes(&json)[0]["file"], "new/a/RTC.xml");

    // Copies in other folders: the copy equal to one of the other side is paired with it, and
    // the one left on each side with each other.
    let dir = tempfile::tempdir().expect("tempdir");
    let dup = |ty: &str| component("Dup", ty, "C++");
    write(dir.path(), "old/a/RTC.xml", &dup("RTC::TimedLong"));
    write(dir.path(), "old/b/RTC.xml", &dup("RTC::TimedDouble"));
    write(dir.path(), "new/c/RTC.xml", &dup("RTC::TimedShort"));
    write(dir.path(), "new/d/RTC.xml", &dup("RTC::TimedLong"));
    let (_, json) = run_diff(dir.path(), &[]);
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"], "{json:#}");
    let c = changes(&json)
        .into_iter()
        .find(|c| c["code"] == "DIFF104")
        .expect("DIFF104");
    assert_eq!(
        (c["old"].as_str(), c["new"].as_str()),
        (Some("RTC::TimedDouble"), Some("RTC::TimedShort"))
    );
    assert_eq!(
        (c["oldFile"].as_str(), c["file"].as_str()),
        (Some("old/b/RTC.xml"), Some("new/c/RTC.xml"))
    );

    // Two of one id and one language on each side, all different, in other folders:
    // ambiguous, not compared.
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/a/RTC.xml", &dup("RTC::TimedLong"));
    write(dir.path(), "old/b/RTC.xml", &dup("RTC::TimedDouble"));
    write(dir.path(), "new/c/RTC.xml", &dup("RTC::TimedShort"));
    write(dir.path(), "new/d/RTC.xml", &dup("RTC::TimedBoolean"));
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 0, "ambiguity is a warning: {json:#}");
    assert_eq!(codes_of(&json), ["DIFF001"], "{json:#}");
    let c = changes(&json)[0];
    assert_eq!(c["severity"], "warning");
    assert_eq!(c["old"], "old/a/RTC.xml, old/b/RTC.xml");
    assert_eq!(c["new"], "new/c/RTC.xml, new/d/RTC.xml");
    let (exit, _) = run_diff(dir.path(), &["--fail-on", "warning"]);
    assert_eq!(exit, 1);

    // The same two files on both sides: paired by path.
    let dir = tempfile::tempdir().expect("tempdir");
    for side in ["old", "new"] {
        write(
            dir.path(),
            &format!("{side}/a/RTC.xml"),
            &component("Dup", "RTC::TimedLong", "C++"),
        );
    }
    write(
        dir.path(),
        "old/b/RTC.xml",
        &component("Dup", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "new/b/RTC.xml",
        &component("Dup", "RTC::TimedShort", "C++"),
    );
    let (_, json) = run_diff(dir.path(), &[]);
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"], "{json:#}");
    assert_eq!(
        changes(&json)[0]["component"],
        "RTC:Lab:Mobile:Dup:1.0.0 (C++)"
    );
}

#[test]
fn an_unreadable_profile_is_reported_with_its_component_as_removed() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    write(dir.path(), "new/RTC.xml", &BASE[..BASE.len() / 2]);
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 1);
    assert_eq!(codes_of(&json), ["DIFF002", "DIFF101"], "{json:#}");
    let unreadable = changes(&json)
        .into_iter()
        .find(|c| c["code"] == "DIFF002")
        .expect("DIFF002");
    assert_eq!(unreadable["severity"], "warning");
    assert_eq!(unreadable["file"], "new/RTC.xml");
    assert!(unreadable["message"]
        .as_str()
        .unwrap_or("")
        .contains("counts as absent"));
}

#[test]
fn single_files_yaml_and_the_examples() {
    let dir = tempfile::tempdir().expect("tempdir");
    let examples = root().join("examples");
    for side in ["old", "new"] {
        for e in std::fs::read_dir(&examples).expect("examples").flatten() {
            if e.path().is_dir() {
                for f in std::fs::read_dir(e.path()).expect("component").flatten() {
                    let rel = format!(
                        "{side}/{}/{}",
                        e.file_name().to_string_lossy(),
                        f.file_name().to_string_lossy()
                    );
                    write(
                        dir.path(),
                        &rel,
                        &std::fs::read_to_string(f.path()).expect("read"),
                    );
                }
            }
        }
    }
    let yaml = dir.path().join("new/Localization/RTC.yaml");
    let text = std::fs::read_to_string(&yaml).expect("yaml");
    assert!(text.contains("name: num_particles"));
    std::fs::write(
        &yaml,
        text.replacen("defaultValue: \"500\"", "defaultValue: \"800\"", 1),
    )
    .expect("write");
    let (exit, json) = run_diff(dir.path(), &[]);
    assert_eq!(exit, 0, "{json:#}");
    assert_eq!(codes_of(&json), ["DIFF201"], "{json:#}");
    let c = changes(&json)[0];
    assert_eq!(
        c["component"],
        "RTC:ExampleRobotics:Navigation:Localization:1.1.0"
    );
    assert_eq!(c["path"], "configurations/num_particles/defaultValue");
    assert_eq!(
        (c["old"].as_str(), c["new"].as_str()),
        (Some("500"), Some("800"))
    );
    assert_eq!(json["summary"]["components"]["matched"], 11);

    // One file against one file.
    let out = rtcdoc(
        &[
            "diff",
            "old/Localization/RTC.yaml",
            "new/Localization/RTC.yaml",
            "--format",
            "json",
        ],
        dir.path(),
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(codes_of(&json), ["DIFF201"]);
    assert_eq!(changes(&json)[0]["file"], "new/Localization/RTC.yaml");
}

/// A git repository in `d` whose first commit holds [`BASE`] at `file`.
fn first_commit(d: &Path, file: &str) {
    assert!(git(d, &["init", "-q"]), "git is needed");
    assert!(git(d, &["config", "user.name", "Test"]));
    assert!(git(d, &["config", "user.email", "test@example.org"]));
    write(d, file, BASE);
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "first"]));
}

#[test]
fn a_git_revision_is_read_without_touching_the_work_tree() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    if !git(d, &["--version"]) {
        crate::common::missing_tool("git not available");
        return;
    }
    assert!(git(d, &["init", "-q"]));
    assert!(git(d, &["config", "user.name", "Test"]));
    assert!(git(d, &["config", "user.email", "test@example.org"]));
    write(d, "components/Base/RTC.xml", BASE);
    write(d, "components/Base/src/main.cpp", "int main() {}\n");
    write(
        d,
        "components/Other/RTC.xml",
        &component("Other", "RTC::TimedLong", "C++"),
    );
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "first"]));
    // The work tree moves on: a port changes type, a component is moved.
    write(
        d,
        "components/Base/RTC.xml",
        &edited(&[("RTC::TimedPose2D", "RTC::TimedPose3D")]),
    );
    std::fs::rename(d.join("components/Other"), d.join("components/Moved")).expect("mv");
    let before = common::tree(d);

    let out = rtcdoc(
        &["diff", "HEAD:components", "components", "--format", "json"],
        d,
    );
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"], "{json:#}");
    let c = changes(&json)
        .into_iter()
        .find(|c| c["code"] == "DIFF104")
        .expect("DIFF104");
    assert_eq!(c["path"], "dataPorts/odometry/type");
    assert_eq!(c["file"], "components/Base/RTC.xml");
    assert_eq!(c["oldFile"], "components/Base/RTC.xml");
    assert_eq!(json["old"], "HEAD:components");
    assert_eq!(common::tree(d), before, "the work tree is untouched");

    // The reverse direction, a file of a revision, and the whole tree.
    let out = rtcdoc(
        &["diff", "components", "HEAD:components", "--format", "json"],
        d,
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"]);
    let out = rtcdoc(
        &[
            "diff",
            "HEAD:components/Base/RTC.xml",
            "components/Base/RTC.xml",
            "--format",
            "json",
        ],
        d,
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"]);
    let out = rtcdoc(&["diff", "HEAD:", "HEAD:components", "--format", "json"], d);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );

    // A bad revision, a missing path: exit 2 with a message.
    let out = rtcdoc(&["diff", "no-such-branch:components", "components"], d);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("OLD `no-such-branch:components`: git cannot find it"),
        "{err}"
    );
    let out = rtcdoc(&["diff", "HEAD:nothing-here", "components"], d);
    assert_eq!(out.status.code(), Some(2));

    // `REV:.` is the current folder, as `REV:./` (git itself refuses `.`).
    let sub = d.join("components");
    let out = rtcdoc(&["diff", "HEAD:.", ".", "--format", "json"], &sub);
    let json: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|_| panic!("{}", String::from_utf8_lossy(&out.stderr)));
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"]);
    // A bare revision names no folder: the message says how, and that works.
    let out = rtcdoc(&["diff", "HEAD", "."], &sub);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    let shown = err
        .split("for this folder")
        .next()
        .and_then(|s| s.rsplit('`').nth(1))
        .unwrap_or_else(|| panic!("{err}"));
    assert_eq!(shown, "HEAD:./", "{err}");
    let out = rtcdoc(&["diff", shown, ".", "--format", "json"], &sub);
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(codes_of(&json), ["DIFF104", "DIFF208"]);

    // Outside a repository.
    let outside = tempfile::tempdir().expect("tempdir");
    write(outside.path(), "c/RTC.xml", BASE);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(["diff", "HEAD:c", "c"])
        .current_dir(outside.path())
        .env(
            "GIT_CEILING_DIRECTORIES",
            outside.path().parent().expect("parent"),
        )
        .output_within(common::COMMAND_LIMIT)
        .expect("run");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("not in a git repository"), "{err}");
}

#[test]
fn usage_and_input_errors_exit_2() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    let out = rtcdoc(&["diff", "old", "missing"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("NEW `missing` does not exist"));
    write(
        dir.path(),
        "site/catalog.json",
        "{\"generator\": \"rtcdoc 0.1.0\", \"formatVersion\": 1}",
    );
    let out = rtcdoc(&["diff", "site/catalog.json", "old"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("OLD `site/catalog.json`")
            && err.contains("catalog.json format 1 (written by rtcdoc 0.1.0)")
            && err.contains("build the catalogue again"),
        "{err}"
    );
    let out = rtcdoc(&["diff", "old"], dir.path());
    assert_eq!(out.status.code(), Some(2), "NEW is required");
    std::fs::create_dir_all(dir.path().join("empty")).expect("mkdir");
    let out = rtcdoc(&["diff", "old", "empty"], dir.path());
    assert_eq!(
        out.status.code(),
        Some(2),
        "an empty side needs --allow-empty"
    );
    let out = rtcdoc(
        &["diff", "old", "empty", "--allow-empty", "--format", "json"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(codes_of(&json), ["DIFF101"]);
}

#[test]
fn include_and_exclude_apply_to_both_sides() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/keep/RTC.xml", BASE);
    write(
        dir.path(),
        "old/backup/RTC.xml",
        &component("Old", "RTC::TimedLong", "C++"),
    );
    write(dir.path(), "new/keep/RTC.xml", BASE);
    let (exit, json) = run_diff(dir.path(), &["--exclude", "backup"]);
    assert_eq!((exit, changes(&json).len()), (0, 0), "{json:#}");
    let (exit, _) = run_diff(dir.path(), &[]);
    assert_eq!(
        exit, 1,
        "without --exclude the backup's component is removed"
    );
    let (exit, json) = run_diff(dir.path(), &["--include", "keep/**"]);
    assert_eq!((exit, changes(&json).len()), (0, 0), "{json:#}");
}

#[test]
fn fail_on_levels() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    // A warning (default changed) and an info (version bump), nothing breaking.
    let mut edits = vec![(r#"rtc:defaultValue="5.0""#, r#"rtc:defaultValue="6.0""#)];
    edits.extend(BUMP);
    write(dir.path(), "new/RTC.xml", &edited(&edits));
    for (level, exit) in [("breaking", 0), ("warning", 1), ("info", 1), ("never", 0)] {
        let (got, json) = run_diff(dir.path(), &["--fail-on", level]);
        assert_eq!(got, exit, "--fail-on {level}");
        assert_eq!(json["summary"]["failOn"], level);
    }
    // Only an info change.
    write(dir.path(), "new/RTC.xml", &edited(&BUMP));
    for (level, exit) in [("breaking", 0), ("warning", 0), ("info", 1), ("never", 0)] {
        assert_eq!(
            run_diff(dir.path(), &["--fail-on", level]).0,
            exit,
            "--fail-on {level}"
        );
    }
    // Breaking: fails unless never.
    write(
        dir.path(),
        "new/RTC.xml",
        &edited(&[("RTC::TimedPose2D", "RTC::TimedPose3D")]),
    );
    for (level, exit) in [("breaking", 1), ("warning", 1), ("info", 1), ("never", 0)] {
        assert_eq!(
            run_diff(dir.path(), &["--fail-on", level]).0,
            exit,
            "--fail-on {level}"
        );
    }
}

/// old/new with a breaking change, a warning and a documentation change.
fn mixed(dir: &Path) {
    write(dir, "old/RTC.xml", BASE);
    let mut edits = vec![
        ("RTC::TimedPose2D", "RTC::TimedPose3D"),
        (r#"rtc:defaultValue="5.0""#, r#"rtc:defaultValue="6.0""#),
        ("Gain of the loop", "Gain | of the loop"),
    ];
    edits.extend(BUMP);
    write(dir, "new/RTC.xml", &edited(&edits));
}

#[test]
fn human_output() {
    let dir = tempfile::tempdir().expect("tempdir");
    mixed(dir.path());
    let out = rtcdoc(&["diff", "old", "new"], dir.path());
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        !text.contains('\u{1b}'),
        "no colour when NO_COLOR is set / not a terminal"
    );
    assert!(text.starts_with("RTC:Lab:Mobile:Base:2.0.0\n"), "{text}");
    assert!(
        text.contains(
            "  breaking[DIFF104] dataPorts/odometry/type: data port `odometry` now carries"
        ),
        "{text}"
    );
    assert!(
        text.contains("      RTC::TimedPose2D → RTC::TimedPose3D\n"),
        "{text}"
    );
    assert!(text.contains("      --> new/RTC.xml:"), "{text}");
    // Breaking first, then warnings, then infos.
    let at = |s: &str| text.find(s).unwrap_or_else(|| panic!("{s} in {text}"));
    assert!(at("breaking[DIFF104]") < at("warning[DIFF201]"));
    assert!(at("warning[DIFF201]") < at("info[DIFF306]"));
    assert!(text.trim_end().ends_with(
        "rtcdoc diff: 1 breaking, 1 warning, 2 infos in 1 of 1 matched component(s); 0 added, 0 removed"
    ), "{text}");
    let quiet = rtcdoc(&["diff", "old", "new", "-q"], dir.path());
    let q = String::from_utf8_lossy(&quiet.stdout);
    assert!(
        q.contains("breaking[DIFF104]") && !q.contains("DIFF201") && !q.contains("rtcdoc diff:"),
        "{q}"
    );
}

#[test]
fn markdown_output() {
    let dir = tempfile::tempdir().expect("tempdir");
    mixed(dir.path());
    write(
        dir.path(),
        "old/Gone/RTC.xml",
        &component("Gone", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "old/Quiet/RTC.xml",
        &component("Quiet", "RTC::TimedLong", "C++"),
    );
    write(
        dir.path(),
        "new/Quiet/RTC.xml",
        &component("Quiet", "RTC::TimedLong", "C++").replace("Drives the base", "Drives it"),
    );
    let out = rtcdoc(&["diff", "old", "new", "--format", "markdown"], dir.path());
    assert_eq!(out.status.code(), Some(1));
    let md = String::from_utf8_lossy(&out.stdout);
    assert!(
        md.starts_with("## rtcdoc diff: 2 breaking, 1 warning, 3 infos\n"),
        "{md}"
    );
    assert!(
        md.contains("the check fails (`--fail-on breaking`)"),
        "{md}"
    );
    // Grouped by component, components with breaking changes first (by id), info-only last.
    let at = |s: &str| md.find(s).unwrap_or_else(|| panic!("{s} in {md}"));
    assert!(at("### `RTC:Lab:Mobile:Base:2.0.0`") < at("### `RTC:Lab:Mobile:Gone:1.0.0`"));
    assert!(at("### `RTC:Lab:Mobile:Gone:1.0.0`") < at("### `RTC:Lab:Mobile:Quiet:1.0.0`"));
    assert!(md.contains(
        "| 🔴 breaking | DIFF104 `data-port-type-changed` | `dataPorts/odometry/type` | `RTC::TimedPose2D` | `RTC::TimedPose3D` |"
    ), "{md}");
    // Infos are folded in a list, where a `|` in a value is no table's and is shown as
    // written.
    assert!(
        md.contains("<details><summary>2 informational change(s)</summary>"),
        "{md}"
    );
    assert!(md.contains("Gain | of the loop"), "{md}");
    assert!(!md.contains("Gain \\| of the loop"), "{md}");
    assert!(!md.contains("| Gain | of"), "{md}");
}

#[test]
fn github_annotations() {
    let dir = tempfile::tempdir().expect("tempdir");
    mixed(dir.path());
    write(
        dir.path(),
        "old/Gone/RTC.xml",
        &component("Gone", "RTC::TimedLong", "C++"),
    );
    let out = rtcdoc(&["diff", "old", "new", "--format", "github"], dir.path());
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = text.lines().collect();
    let port = lines
        .iter()
        .find(|l| l.contains("DIFF104"))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(port.starts_with("::error file=new/RTC.xml,line="), "{port}");
    assert!(
        port.contains(",title=DIFF104 data-port-type-changed::RTC:Lab:Mobile:Base:2.0.0 dataPorts/odometry/type: data port"),
        "{port}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("::warning file=new/RTC.xml,line=") && l.contains("DIFF201")),
        "{text}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("::notice ") && l.contains("DIFF307")),
        "{text}"
    );
    // A removed component has no file on the NEW side: an annotation without a file.
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("::error title=DIFF101 component-removed::")),
        "{text}"
    );
    assert!(text.trim_end().ends_with("0 added, 1 removed"), "{text}");
}

#[test]
fn explain_prints_every_code() {
    let dir = tempfile::tempdir().expect("tempdir");
    for c in rtcdoc::diff::CODES {
        let out = rtcdoc(&["diff", "--explain", c.code], dir.path());
        assert!(out.status.success(), "{}", c.code);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            text.starts_with(&format!("{} ({})", c.code, c.name)),
            "{text}"
        );
        assert!(text.contains(c.explanation) && text.contains(&c.level.to_string()));
    }
    let out = rtcdoc(&["diff", "--explain", "DIFF999"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("the codes are DIFF001, DIFF002"));
}

#[test]
fn output_is_deterministic() {
    let dir = tempfile::tempdir().expect("tempdir");
    mixed(dir.path());
    for (i, name) in ["Zeta", "Alpha", "Mu"].iter().enumerate() {
        write(
            dir.path(),
            &format!("old/{i}/RTC.xml"),
            &component(name, "RTC::TimedLong", "C++"),
        );
    }
    let first = rtcdoc(&["diff", "old", "new", "--format", "json"], dir.path()).stdout;
    for _ in 0..3 {
        assert_eq!(
            rtcdoc(&["diff", "old", "new", "--format", "json"], dir.path()).stdout,
            first
        );
    }
    let json: Value = serde_json::from_slice(&first).expect("json");
    let keys: Vec<(String, String)> = changes(&json)
        .iter()
        .map(|c| {
            (
                c["component"].as_str().unwrap_or("").into(),
                c["path"].as_str().unwrap_or("").into(),
            )
        })
        .collect();
    let mut sorted = keys.clone();
    sorted.sort();
    assert_eq!(keys, sorted, "sorted by component id, then path");
}

#[test]
fn profiles_without_any_id_are_matched_by_file_name() {
    let dir = tempfile::tempdir().expect("tempdir");
    let anonymous = BASE
        .replace(r#" rtc:id="RTC:Lab:Mobile:Base:1.0.0""#, "")
        .replace(
            r#"rtc:name="Base" rtc:vendor="Lab" rtc:category="Mobile" "#,
            "",
        );
    write(dir.path(), "old/x/Fragment.xml", &anonymous);
    write(dir.path(), "new/y/Fragment.xml", &anonymous);
    let (exit, json) = run_diff(dir.path(), &["--fail-on", "info"]);
    assert_eq!(exit, 0, "{json:#}");
    assert_eq!(json["summary"]["components"]["matched"], 1);
}

/// The published profiles against themselves, and against a copy with every file moved to
/// another folder: no change at all.
#[test]
fn the_corpus_moved_is_no_change() {
    let Some(corpus) = common::corpus() else {
        return;
    };
    let dir = tempfile::tempdir().expect("tempdir");
    let mut n = 0;
    for e in walkdir::WalkDir::new(&corpus)
        .sort_by_file_name()
        .into_iter()
        .flatten()
    {
        if e.file_type().is_file() {
            n += 1;
            let name = e.file_name().to_string_lossy().to_string();
            let target = dir.path().join(format!("moved/{n:04}/{name}"));
            std::fs::create_dir_all(target.parent().expect("parent")).expect("mkdir");
            std::fs::copy(e.path(), target).expect("copy");
        }
    }
    let corpus = corpus.to_string_lossy().to_string();
    let moved = dir.path().join("moved").to_string_lossy().to_string();
    for (old, new) in [(&corpus, &corpus), (&corpus, &moved)] {
        let out = rtcdoc(
            &["diff", old, new, "--format", "json", "--fail-on", "info"],
            dir.path(),
        );
        assert_eq!(
            out.status.code(),
            Some(0),
            "{old} → {new}: {}",
            String::from_utf8_lossy(&out.stdout)
        );
        let json: Value = serde_json::from_slice(&out.stdout).expect("json");
        let s = &json["summary"]["components"];
        assert!(s["matched"].as_u64().unwrap_or(0) > 100, "{s}");
        assert_eq!(s["matched"], s["old"]);
    }
}

#[test]
fn the_markdown_report_stays_below_the_comment_limit() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "new/RTC.xml", BASE);
    for i in 0..400 {
        write(
            dir.path(),
            &format!("old/{i}/RTC.xml"),
            &component(&format!("Component{i:03}"), "RTC::TimedLong", "C++"),
        );
    }
    let out = rtcdoc(&["diff", "old", "new", "--format", "markdown"], dir.path());
    assert_eq!(out.status.code(), Some(1));
    let md = String::from_utf8_lossy(&out.stdout);
    assert!(md.len() < 65_536, "{} bytes", md.len());
    assert!(
        md.starts_with("## rtcdoc diff: 400 breaking"),
        "{}",
        &md[..200]
    );
    assert!(
        md.contains("more component(s): run `rtcdoc diff` locally"),
        "the rest is counted"
    );
}

/// A catalog.json written by `rtcdoc build --format json` is a side like the profiles it was
/// built from: against them nothing changed; against a changed profile the change is found,
/// with the same code, path and exit status as from the directory.
#[test]
fn catalog_json_is_a_side() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    let out = rtcdoc(
        &["build", "old", "--format", "json", "-o", "site", "-q"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let same = rtcdoc(&["diff", "site/catalog.json", "old"], dir.path());
    assert_eq!(
        same.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&same.stderr)
    );
    let new = BASE.replace("RTC::TimedPose2D", "RTC::TimedPose3D");
    assert_ne!(new, BASE, "the fixture has a TimedPose2D port");
    write(dir.path(), "new/RTC.xml", &new);
    let from_dir = rtcdoc(&["diff", "old", "new", "--format", "json"], dir.path());
    let from_json = rtcdoc(
        &["diff", "site/catalog.json", "new", "--format", "json"],
        dir.path(),
    );
    assert_eq!(from_json.status.code(), Some(1));
    assert_eq!(from_json.status.code(), from_dir.status.code());
    let a: serde_json::Value = serde_json::from_slice(&from_dir.stdout).expect("json");
    let b: serde_json::Value = serde_json::from_slice(&from_json.stdout).expect("json");
    let key = |v: &serde_json::Value| -> Vec<(String, String, String)> {
        v["changes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| {
                (
                    c["code"].as_str().unwrap_or("").to_string(),
                    c["path"].as_str().unwrap_or("").to_string(),
                    c["severity"].as_str().unwrap_or("").to_string(),
                )
            })
            .collect()
    };
    assert!(!key(&a).is_empty());
    assert_eq!(key(&a), key(&b));
}

/// A revision is data, never an option of git: `rtcdoc diff -- '--output=/tmp/x:dir' dir` is
/// refused by rtcdoc itself, and git never sees it.
#[test]
fn a_revision_that_looks_like_an_option_is_refused() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    first_commit(d, "components/Base/RTC.xml");
    let target = d.join("written-by-git");
    let arg = format!("--output={}:components", target.display());
    let out = rtcdoc(&["diff", "--", &arg, "components"], d);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("starts with `-`"), "{err}");
    assert!(!target.exists());
    // An ordinary revision still works (passed after --end-of-options).
    let out = rtcdoc(&["diff", "HEAD:components", "components"], d);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The first change of `code` that `rtcdoc diff old new --format json` reports in `d`.
fn the_change(d: &std::path::Path, code: &str) -> Value {
    let out = rtcdoc(&["diff", "old", "new", "--format", "json"], d);
    let json: Value = serde_json::from_slice(&out.stdout).expect("json");
    changes(&json)
        .into_iter()
        .find(|c| c["code"] == code)
        .cloned()
        .unwrap_or_else(|| panic!("no {code}: {json:#}"))
}

/// A removed port is located where it exists: in OLD's file, at the port.
#[test]
fn a_removed_port_points_at_the_port_in_the_old_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let profile = |ports: &[(&str, &str, &str)]| common::xml_profile("Base", ports);
    write(
        d,
        "old/Base/RTC.xml",
        &profile(&[
            ("DataInPort", "cmd", "RTC::TimedLong"),
            ("DataOutPort", "odometry", "RTC::TimedPose2D"),
        ]),
    );
    write(
        d,
        "new/Base/RTC.xml",
        &profile(&[("DataInPort", "cmd", "RTC::TimedLong")]),
    );
    let c = the_change(d, "DIFF102");
    assert_eq!(c["oldFile"], "old/Base/RTC.xml");
    assert_eq!(
        (c["oldLine"].as_u64(), c["oldColumn"].as_u64()),
        (Some(8), Some(3)),
        "{c:#}"
    );
    assert!(c["line"].is_null(), "{c:#}");
    let out = rtcdoc(&["diff", "old", "new"], d);
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(text.contains("--> old/Base/RTC.xml:8:3"), "{text}");
}

/// A removed configuration parameter too: the human report points at it in OLD's file,
/// although the JSON also gives NEW's configuration set as `line` (an annotation of NEW's file
/// needs one there).
#[test]
fn a_removed_parameter_points_at_the_parameter_in_the_old_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let profile = |params: &str| {
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile rtc:version="0.2" rtc:id="RTC:V:C:T:1.0.0" xmlns:rtc="http://www.openrtp.org/namespaces/rtc">
  <rtc:BasicInfo rtc:name="T" rtc:vendor="V" rtc:category="C" rtc:version="1.0.0"/>
  <rtc:ConfigurationSet>
    <rtc:Configuration rtc:defaultValue="0" rtc:type="int" rtc:name="keep"/>{params}
  </rtc:ConfigurationSet>
</rtc:RtcProfile>
"#
        )
    };
    write(
        d,
        "old/T/RTC.xml",
        &profile("\n    <rtc:Configuration rtc:defaultValue=\"0\" rtc:type=\"short\" rtc:name=\"gone\"/>"),
    );
    write(d, "new/T/RTC.xml", &profile(""));
    let c = the_change(d, "DIFF109");
    assert_eq!(
        (
            c["oldLine"].as_u64(),
            c["oldColumn"].as_u64(),
            c["line"].as_u64()
        ),
        (Some(6), Some(5), Some(4)),
        "{c:#}"
    );
    let out = rtcdoc(&["diff", "old", "new"], d);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(text.contains("--> old/T/RTC.xml:6:5"), "{text}");
    assert!(!text.contains("--> new/T/RTC.xml:4"), "{text}");
}

/// Documentation left blank is documentation left out: RTCBuilder writes an empty
/// `rtcDoc:Doc` (every attribute `""`) where other versions of it write none, which is no
/// change; filling the description in still is one.
#[test]
fn blank_documentation_and_none_are_the_same() {
    let dir = tempfile::tempdir().expect("tempdir");
    let blank = edited(&[(
        r#"rtc:unit="m/s"/>"#,
        r#"rtc:unit="m/s"><rtcDoc:Doc rtcDoc:description="" rtcDoc:type="" rtcDoc:number="" rtcDoc:unit=" "/></rtc:DataPorts>"#,
    )]);
    write(dir.path(), "old/RTC.xml", BASE);
    write(dir.path(), "new/RTC.xml", &blank);
    let (exit, json) = run_diff(dir.path(), &["--fail-on", "info"]);
    assert_eq!(exit, 0, "{json:#}");
    assert!(changes(&json).is_empty(), "{json:#}");
    let filled = blank.replace(
        r#"rtcDoc:description="""#,
        r#"rtcDoc:description="Velocity command""#,
    );
    write(dir.path(), "new/RTC.xml", &filled);
    let (_, json) = run_diff(dir.path(), &[]);
    let found: Vec<(&str, &str)> = changes(&json)
        .iter()
        .map(|c| (c["code"].as_str().unwrap(), c["path"].as_str().unwrap()))
        .collect();
    assert_eq!(
        found,
        [("DIFF307", "dataPorts/cmd/doc/description")],
        "{json:#}"
    );
}

/// A `Language` element without targets adds a language kind, not an empty list of targets
/// (an empty list is no list).
#[test]
fn a_language_without_targets_adds_only_its_kind() {
    let dir = tempfile::tempdir().expect("tempdir");
    let lang = r#"  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="C++"/>
"#;
    assert!(BASE.contains(lang), "the fixture has a Language element");
    write(dir.path(), "old/RTC.xml", &BASE.replace(lang, ""));
    write(dir.path(), "new/RTC.xml", BASE);
    let (_, json) = run_diff(dir.path(), &["--fail-on", "never"]);
    let found: Vec<(&str, &str)> = changes(&json)
        .iter()
        .map(|c| (c["code"].as_str().unwrap(), c["path"].as_str().unwrap()))
        .collect();
    assert_eq!(found, [("DIFF308", "language/kind")], "{json:#}");
}

/// An RT System of two instances and one connector between their ports `p` (`kind`:
/// `Data` or `Service`; `id`: the connector id attribute or ""), its ends in the order given.
fn two_instance_system(kind: &str, id: &str, ends: [(&str, &str); 2]) -> String {
    let end = |side: &str, (inst, port): (&str, &str)| {
        format!(
            r#"    <rts:{side}{kind}Port rts:portName="{inst}.{port}" rts:instanceName="{inst}" rts:componentId="RTC:Me:Cat:{inst}:1.0"/>
"#
        )
    };
    let instance = |inst: &str| {
        format!(
            r#"  <rts:Components rts:instanceName="{inst}" rts:id="RTC:Me:Cat:{inst}:1.0" rts:compositeType="None" rts:isRequired="true">
    <rts:{kind}Ports rts:name="{inst}.p"/>
    <rts:{kind}Ports rts:name="{inst}.q"/>
  </rts:Components>
"#
        )
    };
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<rts:RtsProfile rts:version="0.2" rts:id="RTSystem:Me:Sys:1.0" xmlns:rts="http://www.openrtp.org/namespaces/rts">
{}{}{}  <rts:{kind}PortConnectors rts:name="conn" {id}>
{}{}  </rts:{kind}PortConnectors>
</rts:RtsProfile>
"#,
        instance("A0"),
        instance("B0"),
        instance("C0"),
        end("source", ends[0]),
        end("target", ends[1]),
    )
}

/// A connector between the same two ports with its ends listed the other way round is the same
/// connection (OpenRTM connects two ports whichever comes first): no change, with a connector
/// id or without (then it is paired by its ends); other ports are still DIFF155, naming the
/// port no longer connected.
#[test]
fn a_connector_with_its_ends_swapped_is_the_same_connection() {
    let dir = tempfile::tempdir().expect("tempdir");
    for kind in ["Data", "Service"] {
        for id in [r#"rts:connectorId="c1""#, ""] {
            let old = two_instance_system(kind, id, [("A0", "p"), ("B0", "p")]);
            let new = two_instance_system(kind, id, [("B0", "p"), ("A0", "p")]);
            write(dir.path(), "old/Sys.xml", &old);
            write(dir.path(), "new/Sys.xml", &new);
            let (exit, json) = run_diff(dir.path(), &["--fail-on", "info"]);
            assert!(changes(&json).is_empty(), "{kind} {id}: {json:#}");
            assert_eq!(exit, 0, "{kind} {id}");
        }
        let old = two_instance_system(kind, "rts:connectorId=\"c1\"", [("A0", "p"), ("B0", "p")]);
        let new = two_instance_system(kind, "rts:connectorId=\"c1\"", [("C0", "p"), ("A0", "p")]);
        write(dir.path(), "old/Sys.xml", &old);
        write(dir.path(), "new/Sys.xml", &new);
        let (_, json) = run_diff(dir.path(), &["--fail-on", "never"]);
        let found = changes(&json);
        assert_eq!(found.len(), 1, "{json:#}");
        assert_eq!(found[0]["code"], "DIFF155", "{json:#}");
        let message = found[0]["message"].as_str().unwrap_or_default();
        assert!(
            message.ends_with("instead of `A0.p` → `B0.p`: `B0.p` is no longer connected by it"),
            "{message}"
        );
    }
}

/// A catalog.json against the directory it was built from is no change, and says nothing
/// else either: a profile with a check rule's error was read (it is no "could not be read"
/// warning), and the host data the JSON leaves out is neither reported as added nor printed.
#[test]
fn catalog_json_against_its_own_input_reports_nothing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let bad_default = BASE.replace(r#"rtc:defaultValue="5.0""#, r#"rtc:defaultValue="5.0;x""#);
    assert_ne!(
        bad_default, BASE,
        "the fixture has a double parameter of 5.0"
    );
    write(dir.path(), "in/RTC.xml", &bad_default);
    write(
        dir.path(),
        "in/Demo.xml",
        &common::naming_path_system("Demo"),
    );
    let check = rtcdoc(&["check", "in", "--format", "json"], dir.path());
    assert!(
        String::from_utf8_lossy(&check.stdout).contains("RTC301"),
        "the profile has a check error"
    );
    let out = rtcdoc(
        &["build", "in", "--format", "json", "-o", "site", "-q"],
        dir.path(),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for args in [
        ["diff", "site/catalog.json", "in", "--fail-on", "info"],
        ["diff", "in", "site/catalog.json", "--fail-on", "info"],
    ] {
        let d = rtcdoc(&args, dir.path());
        let all = format!(
            "{}{}",
            String::from_utf8_lossy(&d.stdout),
            String::from_utf8_lossy(&d.stderr)
        );
        assert_eq!(d.status.code(), Some(0), "{args:?}: {all}");
        assert!(!all.contains("DIFF"), "{args:?}: {all}");
        for secret in ["150.29.145.246", "cam-pc", "view-pc"] {
            assert!(!all.contains(secret), "{args:?} printed {secret}: {all}");
        }
    }
}

/// A component's history pairs the versions of one file; when a version's id names another
/// component (here its category changed), the history says so with the code and severity
/// `rtcdoc diff` gives the same two versions: DIFF101, breaking.
#[test]
fn history_and_diff_agree_on_an_id_that_names_another_component() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    first_commit(d, "Base/RTC.xml");
    let moved = BASE
        .replace("RTC:Lab:Mobile:Base:1.0.0", "RTC:Lab:Vehicle:Base:1.0.0")
        .replace(r#"rtc:category="Mobile""#, r#"rtc:category="Vehicle""#);
    assert_ne!(moved, BASE);
    write(d, "Base/RTC.xml", &moved);
    assert!(git(d, &["commit", "-q", "-am", "category"]));
    let diff = rtcdoc(&["diff", "HEAD~1:", "HEAD:", "--format", "json"], d);
    let diff: serde_json::Value = serde_json::from_slice(&diff.stdout).expect("diff json");
    let codes = |changes: &serde_json::Value| -> Vec<(String, String)> {
        changes
            .as_array()
            .expect("changes")
            .iter()
            .filter(|c| c["severity"] == "breaking")
            .map(|c| {
                (
                    c["code"].as_str().unwrap_or("").into(),
                    c["severity"].as_str().unwrap_or("").into(),
                )
            })
            .collect()
    };
    assert_eq!(
        codes(&diff["changes"]),
        [("DIFF101".to_string(), "breaking".to_string())]
    );
    let out = rtcdoc(&["build", ".", "--format", "json", "-o", "site", "-q"], d);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cat: serde_json::Value =
        serde_json::from_slice(&std::fs::read(d.join("site/catalog.json")).expect("catalog"))
            .expect("catalog json");
    let history = &cat["components"]["RTC:Lab:Vehicle:Base:1.0.0"]["history"];
    let newest = &history[0];
    assert_eq!(newest["subject"], "category", "{history}");
    assert_eq!(
        codes(&newest["changes"]),
        codes(&diff["changes"]),
        "{history}"
    );
    let text = newest["changes"].to_string();
    assert!(!text.contains("names the same component"), "{text}");
}

/// A value holding a backtick is quoted with a longer fence (CommonMark), so that the message
/// shows it whole as code in every output instead of breaking at the backtick.
#[test]
fn a_value_with_a_backtick_is_quoted_whole() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    let new = BASE.replace(r#"rtc:defaultValue="5.0""#, r#"rtc:defaultValue="x`y""#);
    assert_ne!(new, BASE);
    write(dir.path(), "new/RTC.xml", &new);
    let o = rtcdoc(&["diff", "old", "new", "--format", "json"], dir.path());
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let change = json["changes"]
        .as_array()
        .expect("changes")
        .iter()
        .find(|c| c["path"] == "configurations/gain/defaultValue")
        .expect("the default's change");
    assert_eq!(change["new"], "x`y");
    let message = change["message"].as_str().unwrap_or_default();
    assert!(message.contains("to ``x`y``"), "{message}");
    let o = rtcdoc(&["diff", "old", "new", "--format", "markdown"], dir.path());
    let md = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(md.contains("| `5.0` | ``x`y`` |"), "{md}");
}

/// The Markdown report shows values as written: inside code spans nothing is escaped but the
/// table's `|`; outside them `<` cannot open a tag.
#[test]
fn markdown_shows_values_in_code_spans_as_written() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/RTC.xml", BASE);
    let new = BASE.replace(
        r#"rtc:defaultValue="5.0""#,
        r#"rtc:defaultValue="a\b&lt;c&gt;|d""#,
    );
    assert_ne!(new, BASE);
    write(dir.path(), "new/RTC.xml", &new);
    let o = rtcdoc(&["diff", "old", "new", "--format", "markdown"], dir.path());
    let md = String::from_utf8_lossy(&o.stdout).into_owned();
    let row = md
        .lines()
        .find(|l| l.contains("configurations/gain/defaultValue"))
        .unwrap_or_else(|| panic!("no row for the default: {md}"));
    assert!(row.contains(r"| `5.0` | `a\b<c>\|d` |"), "{row}");
    assert!(row.contains(r"to `a\b<c>\|d`"), "{row}");
    assert!(!row.contains("&lt;") && !row.contains(r"\\"), "{row}");
}

/// The human report names a file of a side read at a revision as `REV:path`, which `git show`
/// opens (here a type removed from an IDL file: its old line is in the old file, not in the
/// work tree's).
#[test]
fn a_location_at_a_revision_is_named_with_the_revision() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    first_commit(d, "Base/RTC.xml");
    let idl = "module Lab {\n  struct Kept { long a; };\n\n\n  struct Gone { long b; };\n};\n";
    write(d, "idl/Lab.idl", idl);
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "idl"]));
    write(
        d,
        "idl/Lab.idl",
        "module Lab {\n  struct Kept { long a; };\n};\n",
    );
    let out = rtcdoc(&["diff", "HEAD:.", "."], d);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(text.contains("DIFF140"), "{text}");
    let at = text
        .lines()
        .find_map(|l| l.trim().strip_prefix("--> HEAD:./idl/Lab.idl:"))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(at.starts_with("5:"), "{text}");
    // Followed: git shows the old file, whose line 5 is the removed type.
    let shown = std::process::Command::new("git")
        .args(["show", "HEAD:./idl/Lab.idl"])
        .current_dir(d)
        .output_within(common::COMMAND_LIMIT)
        .expect("git");
    let old = String::from_utf8_lossy(&shown.stdout);
    assert_eq!(
        old.lines().nth(4),
        Some("  struct Gone { long b; };"),
        "{old}"
    );
    // The other way round, the type is added on the NEW side, which is the revision.
    let out = rtcdoc(&["diff", ".", "HEAD:."], d);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(text.contains("--> HEAD:./idl/Lab.idl:5:"), "{text}");
}

/// A revision that holds no specification: the error names it as written (not the temporary
/// folder it was read into, which is gone by then), says what was looked for, and its hint,
/// `--allow-empty`, works: the component of the other side is reported removed. `--verbose`
/// names the files it skipped in the revision as `git show` opens them.
#[test]
fn a_revision_without_a_profile_is_named_and_allow_empty_compares_it() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    first_commit(d, "RTC.xml");
    write(d, "README.md", "# Base\n");
    std::fs::remove_file(d.join("RTC.xml")).unwrap();
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "only the README"]));
    let out = rtcdoc(&["diff", "HEAD~1:./", "HEAD:./"], d);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("NEW `HEAD:./`: nothing to document")
            && err.contains("IDL file in `HEAD:./` (it holds no .xml, .yaml, .rtsys or .idl file)")
            && !err.contains("rtcdoc-diff-"),
        "{err}"
    );
    let out = rtcdoc(&["diff", "HEAD~1:./", "HEAD:./", "--allow-empty"], d);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("breaking[DIFF101]: component `Base` was removed"),
        "{text}"
    );
    // A file it holds that is no profile: `--verbose` names it as `git show` opens it.
    write(d, "notes.xml", "<notes/>\n");
    assert!(git(d, &["add", "-A"]));
    assert!(git(d, &["commit", "-q", "-m", "notes"]));
    let out = rtcdoc(&["--verbose", "diff", "HEAD~2:./", "HEAD:./"], d);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("skipped HEAD:./notes.xml: is XML with the root element `notes`"),
        "{err}"
    );
}

/// A component under a new id that no component of the other side has: paired with the one
/// component of the other side (two files compared) or with the one in the same file, and
/// compared field by field (DIFF101 on its id, the other changes beside it), as its history
/// compares two versions of its file; not removed and another added.
#[test]
fn a_component_under_a_new_id_is_compared_with_its_old_self() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let renamed = edited(&[
        (":Base:1.0.0\"", ":Drive:1.0.0\""),
        ("rtc:name=\"Base\"", "rtc:name=\"Drive\""),
        ("rtc:unit=\"m/s\"", "rtc:unit=\"mm/s\""),
    ]);
    // Two files, one component each (an RTCBuilder backup against the profile).
    write(d, "one/RTC.xml20150113093039", BASE);
    write(d, "one/RTC.xml", &renamed);
    let out = rtcdoc(
        &[
            "diff",
            "one/RTC.xml20150113093039",
            "one/RTC.xml",
            "--format",
            "json",
        ],
        d,
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let codes: Vec<(&str, &str)> = json["changes"]
        .as_array()
        .expect("changes")
        .iter()
        .map(|c| {
            (
                c["code"].as_str().unwrap_or(""),
                c["path"].as_str().unwrap_or(""),
            )
        })
        .collect();
    assert!(codes.contains(&("DIFF101", "id")), "{codes:?}");
    assert!(
        codes.contains(&("DIFF210", "dataPorts/cmd/unit")),
        "{codes:?}"
    );
    assert!(
        !codes.iter().any(|(c, _)| *c == "DIFF304"),
        "no component added: {codes:?}"
    );
    // Two catalogues: the renamed one pairs with the one in its file; the other by its id.
    write(d, "old/Base/RTC.xml", BASE);
    write(d, "new/Base/RTC.xml", &renamed);
    let other = BASE
        .replace(":Base:", ":Arm:")
        .replace("rtc:name=\"Base\"", "rtc:name=\"Arm\"");
    write(d, "old/Arm/RTC.xml", &other);
    write(d, "new/Arm/RTC.xml", &other);
    let (_, json) = run_diff(d, &[]);
    let counts = &json["summary"]["components"];
    assert_eq!(
        (
            &counts["matched"],
            &counts["changed"],
            &counts["added"],
            &counts["removed"]
        ),
        (
            &Value::from(2),
            &Value::from(1),
            &Value::from(0),
            &Value::from(0)
        ),
        "{json}"
    );
}
