//! `rtcdoc diff` through the binary on the fixture pairs of `tests/fixtures/diff/CODE/{old,new}`:
//! every IDL-level code (DIFF13x, DIFF140, DIFF23x, DIFF33x), every RT System connector code (DIFF14x)
//! and every code of the RT Systems compared (DIFF003, DIFF15x, DIFF25x, DIFF35x) with its
//! severity, path, component, file and the exit status; and the IDL and system cases around
//! them (spellings, a git revision, a system only OLD has, an unreadable system profile,
//! `--idl-path`, two system files, a reformatted system).

use crate::common;
use common::OutputWithin;
use common::{root, rtcdoc, write};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn fixture(code: &str) -> PathBuf {
    root().join("tests/fixtures/diff").join(code)
}

fn run(dir: &Path, args: &[&str]) -> (i32, Value) {
    let mut all = vec!["diff"];
    all.extend_from_slice(args);
    all.extend(["--format", "json"]);
    let out = rtcdoc(&all, dir);
    let json: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code().expect("exit code"), json)
}

fn changes(json: &Value) -> &Vec<Value> {
    json["changes"].as_array().expect("changes")
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
    path: &'static str,
    component: &'static str,
    /// Every code the pair gives, sorted.
    all: &'static [&'static str],
    /// The NEW file the change points at.
    file: &'static str,
    says: &'static str,
}

const NAV: &str = "RTC:Lab:Mobile:Nav:1.0.0";
const NAV_RTC: &str = "new/Nav/RTC.xml";
const SYSTEM: &str = "new/systems/NavSystem.xml";
const NAV_SYSTEM: &str = "RTSystem:Lab:NavSystem:1.0";

const CASES: &[Case] = &[
    Case {
        code: "DIFF130",
        path: "dataPorts/odometry/type",
        component: NAV,
        all: &["DIFF130", "DIFF208"],
        file: NAV_RTC,
        says: "`IDL:Nav/TimedOdometry:1.0` to `IDL:Nav/TimedOdometry:1.1`",
    },
    Case {
        code: "DIFF131",
        path: "dataPorts/odometry/type/fields/speed",
        component: NAV,
        all: &["DIFF131", "DIFF208"],
        file: NAV_RTC,
        says: "member `speed` (double) was added to `Nav::TimedOdometry` as member 4 of 4",
    },
    Case {
        code: "DIFF132",
        path: "dataPorts/odometry/type/fields/history",
        component: NAV,
        all: &["DIFF132", "DIFF208"],
        file: NAV_RTC,
        says: "member `history` (sequence<Nav::Pose2D>) of `Nav::TimedOdometry` was removed",
    },
    Case {
        code: "DIFF133",
        path: "dataPorts/odometry/type/fields",
        component: NAV,
        all: &["DIFF133", "DIFF208"],
        file: NAV_RTC,
        says: "tm, pose, history → pose, tm, history",
    },
    Case {
        code: "DIFF134",
        path: "dataPorts/odometry/type/fields/pose.heading",
        component: NAV,
        // Once per port or interface, where the type is first met: odometry's pose (not
        // again in history[]), setOrigin's origin, plan's goal (not again in path[]).
        all: &["DIFF134", "DIFF134", "DIFF134", "DIFF208"],
        file: NAV_RTC,
        says: "member `heading` of `Nav::Pose2D` is now `float` instead of `double`",
    },
    Case {
        code: "DIFF135",
        path: "dataPorts/mode/type/fields/data/values/MANUAL",
        component: NAV,
        all: &["DIFF135", "DIFF135", "DIFF208"],
        file: NAV_RTC,
        says: "value `MANUAL` (number 1) was removed from enum `Nav::Mode`",
    },
    Case {
        code: "DIFF136",
        path: "dataPorts/shape/type/cases/box",
        component: NAV,
        all: &["DIFF136", "DIFF208"],
        file: NAV_RTC,
        says: "case `box` of union `Nav::Shape` is selected by 2 instead of 1",
    },
    Case {
        code: "DIFF137",
        path: "dataPorts/shape/type/cases/box",
        component: NAV,
        all: &["DIFF137", "DIFF208"],
        file: NAV_RTC,
        says: "typedef `Nav::Vector3` is now `sequence<double, 4>` instead of `sequence<double, 3>`",
    },
    Case {
        code: "DIFF138",
        path: "servicePorts/Map/interfaces/map/type/operations/setOrigin",
        component: NAV,
        all: &["DIFF138", "DIFF208"],
        file: NAV_RTC,
        says: "operation `setOrigin` was removed from interface `Nav::MapService`",
    },
    Case {
        code: "DIFF139",
        path: "servicePorts/Map/interfaces/map/type/operations/getMap",
        component: NAV,
        all: &["DIFF139", "DIFF208"],
        file: NAV_RTC,
        says: "it takes 2 parameter(s) instead of 1 (`in double resolution` added)",
    },
    Case {
        code: "DIFF231",
        path: "dataPorts/mode/type/fields/data/values/DOCKING",
        component: NAV,
        all: &["DIFF231"],
        file: NAV_RTC,
        says: "value `DOCKING` (number 3) was appended to enum `Nav::Mode`",
    },
    Case {
        code: "DIFF232",
        path: "servicePorts/Map/interfaces/map/type/operations/clear",
        component: NAV,
        all: &["DIFF232"],
        file: NAV_RTC,
        says: "operation `clear` was added to interface `Nav::MapService`",
    },
    Case {
        code: "DIFF331",
        path: "dataPorts/odometry/type",
        component: NAV,
        all: &["DIFF331"],
        file: NAV_RTC,
        says: "the doc comment of `Nav::TimedOdometry` changed",
    },
    Case {
        code: "DIFF332",
        path: "idl/Nav::TimedMode",
        component: "",
        all: &["DIFF332"],
        file: "",
        says: "`Nav::TimedMode` is defined in OLD's IDL only",
    },
    Case {
        code: "DIFF334",
        path: "idl/Nav::Battery",
        component: "new/idl/Nav.idl",
        all: &["DIFF334"],
        file: "new/idl/Nav.idl",
        says: "`Nav::Battery` is defined in `new/idl/Nav.idl`",
    },
    Case {
        code: "DIFF335",
        path: "idlFiles/BasicDataType.idl",
        component: "old/idl/BasicDataType.idl",
        all: &["DIFF335"],
        file: "",
        says: "`old/idl/BasicDataType.idl`, a copy of OpenRTM's own IDL, is no longer read: its 2 type(s) (`RTC::Time`, `RTC::TimedShort`) come from an OpenRTM installation; pass `--idl-path` with OpenRTM's IDL to compare them",
    },
    Case {
        code: "DIFF333",
        path: "servicePorts/Map/interfaces/planner/type/operations/cancel",
        component: NAV,
        all: &["DIFF333"],
        file: NAV_RTC,
        says: "operation `cancel` was removed from interface `Nav::Planner`",
    },
    Case {
        code: "DIFF140",
        path: "idl/Nav::Battery",
        component: "old/idl/Nav.idl",
        all: &["DIFF140"],
        file: "",
        says: "`Nav::Battery` is no longer defined (it was in `old/idl/Nav.idl`)",
    },
    Case {
        code: "DIFF141",
        path: "connectors/NavSystem/odometry_odom",
        component: "RTC:Lab:Mobile:Planner:1.0.0",
        // The data and the service connector.
        all: &["DIFF101", "DIFF141", "DIFF141"],
        file: SYSTEM,
        says: "data port connector `odometry_odom` (`Base0.odometry` → `Planner0.odom`) of system `RTSystem:Lab:NavSystem:1.0` (new/systems/NavSystem.xml) connects component `RTC:Lab:Mobile:Planner:1.0.0`, which was removed",
    },
    Case {
        code: "DIFF142",
        path: "connectors/NavSystem/odometry_odom",
        component: "RTC:Lab:Mobile:Base:2.0.0",
        all: &["DIFF102", "DIFF142", "DIFF306"],
        file: SYSTEM,
        says: "connects port `odometry`, which was removed",
    },
    Case {
        code: "DIFF143",
        path: "connectors/NavSystem/Map_Map",
        component: "RTC:Lab:Mobile:Base:2.0.0",
        all: &["DIFF104", "DIFF107", "DIFF143", "DIFF143", "DIFF306"],
        file: SYSTEM,
        says: "service port connector `Map_Map` (`Base0.Map` → `Planner0.Map`) of system `RTSystem:Lab:NavSystem:1.0` (new/systems/NavSystem.xml) connects port `Map`, which changed incompatibly (DIFF107 `servicePorts/Map/interfaces/map/type`)",
    },
    Case {
        code: "DIFF003",
        path: "",
        component: NAV_SYSTEM,
        all: &["DIFF003"],
        file: "new/field-2024/NavSystem.xml",
        says: "2 RT System profiles in OLD and 2 in NEW have the id `RTSystem:Lab:NavSystem:1.0`; they cannot be paired and are not compared",
    },
    Case {
        code: "DIFF151",
        path: "",
        component: NAV_SYSTEM,
        all: &["DIFF151"],
        file: "",
        says: "RT System `NavSystem` (old/systems/NavSystem.xml, 3 instance(s), 3 connector(s)) was removed",
    },
    Case {
        code: "DIFF152",
        path: "components/Logger0",
        component: NAV_SYSTEM,
        all: &["DIFF152", "DIFF154"],
        file: SYSTEM,
        says: "instance `Logger0` of component `RTC:Lab:Util:Logger:1.0.0` was removed: the instances connected to it (`Base0`) lose the data and services it exchanged with them",
    },
    Case {
        code: "DIFF153",
        path: "components/Logger0/id",
        component: NAV_SYSTEM,
        all: &["DIFF153"],
        file: SYSTEM,
        says: "instance `Logger0` now runs component `RTC:Lab:Util:Recorder:1.0.0` instead of `RTC:Lab:Util:Logger:1.0.0`",
    },
    Case {
        code: "DIFF154",
        path: "dataPortConnectors/odometry_log",
        component: NAV_SYSTEM,
        all: &["DIFF154"],
        file: SYSTEM,
        says: "data port connector `odometry_log` (`Base0.odometry` → `Logger0.in`, IDL:RTC/TimedPose2D:1.0) was removed: `Logger0.in` no longer receives data from `Base0.odometry`",
    },
    Case {
        code: "DIFF155",
        path: "dataPortConnectors/odometry_log",
        component: NAV_SYSTEM,
        all: &["DIFF155"],
        file: SYSTEM,
        says: "now connects `Base0.odometry` → `Planner0.goal` instead of `Base0.odometry` → `Logger0.in`: `Logger0.in` is no longer connected by it",
    },
    Case {
        code: "DIFF156",
        path: "dataPortConnectors/odometry_odom/dataType",
        component: NAV_SYSTEM,
        // The `dataport.data_type` property changed with the attribute: said once.
        all: &["DIFF156"],
        file: SYSTEM,
        says: "now carries `IDL:RTC/TimedPose3D:1.0` instead of `IDL:RTC/TimedPose2D:1.0`",
    },
    Case {
        code: "DIFF356",
        path: "dataPortConnectors/odometry_odom/dataType",
        component: NAV_SYSTEM,
        // The same change as DIFF156's, but the file records both ports as TimedPose3D: the
        // connector now carries their type, a repair.
        all: &["DIFF356"],
        file: SYSTEM,
        says: "now carries `IDL:RTC/TimedPose3D:1.0`, the type its ports carry, instead of `IDL:RTC/TimedPose2D:1.0`, which they did not: a repair",
    },
    Case {
        code: "DIFF251",
        path: "components/Base0/id",
        component: NAV_SYSTEM,
        all: &["DIFF251"],
        file: SYSTEM,
        says: "instance `Base0` now names version `2.0.0` of its component instead of `1.0.0`",
    },
    Case {
        code: "DIFF252",
        path: "components/Base0/activeConfigurationSet",
        component: NAV_SYSTEM,
        all: &["DIFF252"],
        file: SYSTEM,
        says: "instance `Base0` now runs with configuration set `slow` instead of `default`",
    },
    Case {
        code: "DIFF253",
        path: "components/Base0/executionContexts/0/rate",
        component: NAV_SYSTEM,
        all: &["DIFF253"],
        file: SYSTEM,
        says: "instance `Base0` now runs at 50 Hz instead of 100.0 Hz",
    },
    Case {
        code: "DIFF254",
        path: "components/Planner0/executionContexts/0/kind",
        component: NAV_SYSTEM,
        all: &["DIFF254"],
        file: SYSTEM,
        says: "execution context `0` of instance `Planner0` is now `EVENT_DRIVEN` instead of `PERIODIC`",
    },
    Case {
        code: "DIFF255",
        path: "dataPortConnectors/odometry_odom/interfaceType",
        component: NAV_SYSTEM,
        all: &["DIFF255"],
        file: SYSTEM,
        says: "the interface type of data port connector `odometry_odom` changed from `corba_cdr` to `shared_memory`",
    },
    Case {
        code: "DIFF256",
        path: "dataPortConnectors/odometry_odom/properties/dataport.publisher.push_policy",
        component: NAV_SYSTEM,
        // The subscription type (its property folded into it) and the push policy.
        all: &["DIFF256", "DIFF256"],
        file: SYSTEM,
        says: "property `dataport.publisher.push_policy` of connector `odometry_odom` changed from `all` to `skip`",
    },
    Case {
        code: "DIFF257",
        path: "",
        component: "RTSystem:Lab:NavigationSystem:1.0",
        // Compared as one system: its other change is found, its new id is no change of its own.
        all: &["DIFF252", "DIFF257"],
        file: SYSTEM,
        says: "RT System `NavSystem` (old/systems/NavSystem.xml) is now `NavigationSystem`: its id changed from `RTSystem:Lab:NavSystem:1.0` to `RTSystem:Lab:NavigationSystem:1.0`",
    },
    Case {
        code: "DIFF351",
        path: "",
        component: NAV_SYSTEM,
        all: &["DIFF351"],
        file: SYSTEM,
        says: "RT System `NavSystem` (new/systems/NavSystem.xml, 3 instance(s)) was added",
    },
    Case {
        code: "DIFF352",
        path: "components/Camera0",
        component: NAV_SYSTEM,
        all: &["DIFF352"],
        file: SYSTEM,
        says: "instance `Camera0` of component `RTC:Lab:Sensor:Camera:1.0.0` was added",
    },
    Case {
        code: "DIFF353",
        path: "dataPortConnectors/odometry_goal",
        component: NAV_SYSTEM,
        all: &["DIFF353"],
        file: SYSTEM,
        // With its data type, as a removed connector's message has it (DIFF154).
        says: "data port connector `odometry_goal` (`Base0.odometry` → `Planner0.goal`, IDL:RTC/TimedPose2D:1.0) was added",
    },
    Case {
        code: "DIFF354",
        path: "components/Base0/configurationSets/default/gain",
        component: NAV_SYSTEM,
        all: &["DIFF354"],
        file: SYSTEM,
        says: "`gain` in configuration set `default` (the active set) of instance `Base0` changed from `5.0` to `2.5`",
    },
    Case {
        code: "DIFF355",
        path: "components/Logger0/location/y",
        component: NAV_SYSTEM,
        all: &["DIFF355"],
        file: SYSTEM,
        says: "changed from `140` to `160`",
    },
];

#[test]
fn every_idl_and_connector_code_from_its_fixture_pair() {
    for c in rtcdoc::diff::CODES {
        let idl_or_connector = [
            "DIFF003", "DIFF13", "DIFF14", "DIFF15", "DIFF23", "DIFF25", "DIFF33", "DIFF35",
        ]
        .iter()
        .any(|p| c.code.starts_with(p));
        assert_eq!(
            fixture(c.code).is_dir(),
            idl_or_connector,
            "{}: a fixture pair exactly for the IDL and connector codes",
            c.code
        );
        if idl_or_connector {
            assert!(
                CASES.iter().any(|k| k.code == c.code),
                "no case for {}",
                c.code
            );
        }
    }
    for k in CASES {
        let (exit, json) = run(&fixture(k.code), &["old", "new"]);
        assert_eq!(codes_of(&json), k.all, "{}: {json:#}", k.code);
        let entry = rtcdoc::diff::codes::code(k.code).expect("registered");
        let found = changes(&json)
            .iter()
            .find(|c| c["code"] == k.code && c["path"] == k.path)
            .unwrap_or_else(|| panic!("{}: no change at {}: {json:#}", k.code, k.path));
        assert_eq!(found["severity"], entry.level.to_string(), "{}", k.code);
        assert_eq!(found["name"], entry.name, "{}", k.code);
        assert_eq!(found["component"], k.component, "{}", k.code);
        let message = found["message"].as_str().unwrap_or("");
        assert!(message.contains(k.says), "{}: {message}", k.code);
        if k.file.is_empty() {
            assert!(found["file"].is_null(), "{}", k.code);
        } else {
            assert_eq!(found["file"], k.file, "{}", k.code);
        }
        // Located in NEW, or (what exists only there) in OLD; DIFF003 names files only, and
        // DIFF332 no file.
        let line = if found["line"].is_null() {
            &found["oldLine"]
        } else {
            &found["line"]
        };
        assert!(
            line.as_u64().unwrap_or(0) > 0 || ["DIFF003", "DIFF332"].contains(&k.code),
            "{}: a line: {found:#}",
            k.code
        );
        let breaking = k.all.iter().any(|c| c.starts_with("DIFF1"));
        assert_eq!(exit, i32::from(breaking), "{}: exit status", k.code);
        assert_eq!(json["summary"]["failed"], breaking, "{}", k.code);
        // `--fail-on info` fails on every pair (each has a change).
        let (exit, _) = run(&fixture(k.code), &["old", "new", "--fail-on", "info"]);
        assert_eq!(exit, 1, "{}", k.code);
    }
}

#[test]
fn the_same_idl_on_both_sides_is_no_change() {
    for code in ["DIFF131", "DIFF141"] {
        let (exit, json) = run(&fixture(code), &["old", "old"]);
        assert_eq!(exit, 0);
        assert!(changes(&json).is_empty(), "{json:#}");
    }
}

/// Each side reads its own IDL: the pair differs only in the IDL, and without it there is no
/// change at all.
#[test]
fn without_idl_files_the_pair_is_no_change() {
    let (exit, json) = run(
        &fixture("DIFF134"),
        &["old", "new", "--exclude", "**/*.idl"],
    );
    assert_eq!(exit, 0);
    assert!(changes(&json).is_empty(), "{json:#}");
}

const NAV_PROFILE: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:Lab:Mobile:Nav:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="Nav" rtc:vendor="Lab" rtc:category="Mobile" rtc:version="1.0.0"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="pose" rtc:type="Nav::Pose"/>
</rtc:RtcProfile>
"#;

/// A typedef followed to the same type is a respelling (DIFF308), not a retyped member; a
/// renamed typedef target that means another type is.
#[test]
fn typedefs_are_followed_before_types_are_compared() {
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/Nav/RTC.xml", NAV_PROFILE);
    write(dir.path(), "new/Nav/RTC.xml", NAV_PROFILE);
    write(
        dir.path(),
        "old/Nav.idl",
        "module Nav { typedef double Real; struct Pose { double x; Real y; float z; }; };\n",
    );
    write(
        dir.path(),
        "new/Nav.idl",
        "module Nav { typedef double Real; struct Pose { Real x; double y; Real z; }; };\n",
    );
    let (exit, json) = run(dir.path(), &["old", "new"]);
    let found: std::collections::BTreeSet<(String, String)> = changes(&json)
        .iter()
        .map(|c| {
            (
                c["code"].as_str().unwrap_or("").to_string(),
                c["path"].as_str().unwrap_or("").to_string(),
            )
        })
        .collect();
    let expected: std::collections::BTreeSet<(String, String)> = [
        ("DIFF308", "dataPorts/pose/type/fields/x"),
        ("DIFF308", "dataPorts/pose/type/fields/y"),
        ("DIFF134", "dataPorts/pose/type/fields/z"),
        ("DIFF208", "basicInfo/version"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    assert_eq!(found, expected, "{json:#}");
    let codes = codes_of(&json);
    assert_eq!(
        codes,
        ["DIFF134", "DIFF208", "DIFF308", "DIFF308"],
        "{json:#}"
    );
    let z = changes(&json)
        .iter()
        .find(|c| c["code"] == "DIFF134")
        .expect("z");
    assert_eq!(z["path"], "dataPorts/pose/type/fields/z");
    assert_eq!(
        (z["old"].as_str(), z["new"].as_str()),
        (Some("float"), Some("Nav::Real"))
    );
    assert_eq!(exit, 1);
}

fn git(dir: &Path, args: &[&str]) -> bool {
    std::process::Command::new("git")
        .args(args)
        .current_dir(dir)
        .env("GIT_AUTHOR_NAME", "t")
        .env("GIT_AUTHOR_EMAIL", "t@example.com")
        .env("GIT_COMMITTER_NAME", "t")
        .env("GIT_COMMITTER_EMAIL", "t@example.com")
        .output_within(common::COMMAND_LIMIT)
        .map(|o| o.status.success())
        .unwrap_or(false)
}

fn copy_tree(from: &Path, to: &Path) {
    for entry in std::fs::read_dir(from).expect("read_dir") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            std::fs::create_dir_all(&target).expect("mkdir");
            copy_tree(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).expect("copy");
        }
    }
}

/// `REV:PATH` copies the IDL files and the system profiles of the revision too.
#[test]
fn a_git_revision_brings_its_idl_and_systems() {
    let dir = tempfile::tempdir().expect("tempdir");
    if !git(dir.path(), &["init", "-q"]) {
        crate::common::missing_tool("git is not available");
        return;
    }
    let work = dir.path().join("components");
    for (code, expect) in [("DIFF131", "DIFF131"), ("DIFF142", "DIFF142")] {
        let _ = std::fs::remove_dir_all(&work);
        std::fs::create_dir_all(&work).expect("mkdir");
        copy_tree(&fixture(code).join("old"), &work);
        assert!(git(dir.path(), &["add", "-A"]));
        assert!(git(dir.path(), &["commit", "-q", "-m", code]));
        std::fs::remove_dir_all(&work).expect("rm");
        std::fs::create_dir_all(&work).expect("mkdir");
        copy_tree(&fixture(code).join("new"), &work);
        let (exit, json) = run(dir.path(), &["HEAD:components", "components"]);
        assert_eq!(exit, 1, "{code}: {json:#}");
        assert!(
            codes_of(&json).contains(&expect.to_string()),
            "{code}: {json:#}"
        );
    }
}

/// A system only OLD has is still checked (its file is OLD's); NEW's version of a system wins
/// over OLD's.
#[test]
fn systems_of_old_only_are_checked_and_new_ones_win() {
    let dir = tempfile::tempdir().expect("tempdir");
    copy_tree(&fixture("DIFF142"), dir.path());
    std::fs::remove_dir_all(dir.path().join("new/systems")).expect("rm");
    let (exit, json) = run(dir.path(), &["old", "new"]);
    assert_eq!(exit, 1);
    let c = changes(&json)
        .iter()
        .find(|c| c["code"] == "DIFF142")
        .unwrap_or_else(|| panic!("{json:#}"));
    assert!(c["file"].is_null(), "{c:#}");
    assert_eq!(c["oldFile"], "old/systems/NavSystem.xml");
    // NEW's system without the connector: nothing to report.
    let system = std::fs::read_to_string(fixture("DIFF142").join("new/systems/NavSystem.xml"))
        .expect("system");
    let start = system
        .find("    <rts:DataPortConnectors")
        .expect("connector");
    let end = system.find("</rts:DataPortConnectors>\n").expect("end") + 26;
    write(
        dir.path(),
        "new/systems/NavSystem.xml",
        &format!("{}{}", &system[..start], &system[end..]),
    );
    // The system itself lost the connector (DIFF154); none of NEW's connectors is broken.
    let (_, json) = run(dir.path(), &["old", "new"]);
    assert_eq!(
        codes_of(&json),
        ["DIFF102", "DIFF154", "DIFF306"],
        "{json:#}"
    );
}

#[test]
fn an_unreadable_system_profile_is_a_warning() {
    let dir = tempfile::tempdir().expect("tempdir");
    copy_tree(&fixture("DIFF142"), dir.path());
    write(
        dir.path(),
        "new/systems/NavSystem.xml",
        "<?xml version=\"1.0\"?>\n<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\">\n  <rts:DataPortConnectors>\n",
    );
    let (_, json) = run(dir.path(), &["old", "new"]);
    let c = changes(&json)
        .iter()
        .find(|c| c["code"] == "DIFF002")
        .unwrap_or_else(|| panic!("{json:#}"));
    assert!(
        c["message"]
            .as_str()
            .unwrap_or("")
            .contains("RT System profile new/systems/NavSystem.xml could not be read"),
        "{c:#}"
    );
    assert_eq!(c["file"], "new/systems/NavSystem.xml");
    // NEW's broken system does not hide OLD's: OLD's is checked (NEW has no system by that id).
    assert!(codes_of(&json).contains(&"DIFF142".to_string()), "{json:#}");
}

/// `--idl-path` applies to both sides: a side without IDL of its own finds the types there
/// (the files below an input come first, so the other side keeps its own definitions).
#[test]
fn idl_path_applies_to_both_sides() {
    for (without, path_from) in [("new", "new"), ("old", "old")] {
        let dir = tempfile::tempdir().expect("tempdir");
        copy_tree(&fixture("DIFF131"), dir.path());
        std::fs::rename(
            dir.path().join(path_from).join("idl"),
            dir.path().join("shared-idl"),
        )
        .expect("mv");
        assert!(!dir.path().join(without).join("idl").exists());
        let (exit, json) = run(dir.path(), &["old", "new", "--idl-path", "shared-idl"]);
        assert_eq!(exit, 1, "{without}: {json:#}");
        assert_eq!(
            codes_of(&json),
            ["DIFF131", "DIFF208"],
            "{without}: {json:#}"
        );
        // Without it, that side has no IDL: the types are one-sided.
        let (exit, json) = run(dir.path(), &["old", "new"]);
        assert_eq!(exit, 0, "{without}: {json:#}");
        assert!(codes_of(&json).iter().all(|c| c == "DIFF332"), "{json:#}");
    }
}

/// An IDL file with a syntax error is a DIFF002 about its types, not about a component.
#[test]
fn an_idl_syntax_error_is_a_warning_about_its_types() {
    let dir = tempfile::tempdir().expect("tempdir");
    copy_tree(&fixture("DIFF131"), dir.path());
    write(
        dir.path(),
        "new/idl/Broken.idl",
        "module Nav { struct X { long a } };\n",
    );
    let (exit, json) = run(dir.path(), &["old", "new"]);
    assert_eq!(exit, 1);
    let c = changes(&json)
        .iter()
        .find(|c| c["code"] == "DIFF002")
        .unwrap_or_else(|| panic!("{json:#}"));
    let message = c["message"].as_str().unwrap_or("");
    assert!(
        message.contains("new/idl/Broken.idl could not be read")
            && message.ends_with("types it defines may be missing from the comparison"),
        "{message}"
    );
    assert_eq!(c["file"], "new/idl/Broken.idl");
    // The other file is still compared.
    assert!(codes_of(&json).contains(&"DIFF131".to_string()));
}

/// A system in the YAML form of rtsprofile/rtshell is read like the XML one.
#[test]
fn a_yaml_system_profile_is_checked_too() {
    let dir = tempfile::tempdir().expect("tempdir");
    copy_tree(&fixture("DIFF142"), dir.path());
    std::fs::remove_file(dir.path().join("new/systems/NavSystem.xml")).expect("rm");
    std::fs::remove_file(dir.path().join("old/systems/NavSystem.xml")).expect("rm");
    write(
        dir.path(),
        "new/systems/nav.yaml",
        r#"rtsProfile:
  id: "RTSystem:Lab:NavYaml:1.0"
  version: 0.2
  dataPortConnectors:
    - connectorId: y1
      name: odo
      dataType: "IDL:RTC/TimedPose2D:1.0"
      sourceDataPort:
        componentId: "RTC:Lab:Mobile:Base:1.0.0"
        instanceName: Base0
        portName: Base0.odometry
      targetDataPort:
        componentId: "RTC:Lab:Mobile:Planner:1.0.0"
        instanceName: Planner0
        portName: Planner0.odom
"#,
    );
    let (exit, json) = run(dir.path(), &["old", "new"]);
    assert_eq!(exit, 1);
    let c = changes(&json)
        .iter()
        .find(|c| c["code"] == "DIFF142")
        .unwrap_or_else(|| panic!("{json:#}"));
    assert_eq!(c["path"], "connectors/NavYaml/odo");
    assert_eq!(c["file"], "new/systems/nav.yaml");
    assert!(c["line"].as_u64().unwrap_or(0) > 0, "{c:#}");
}

/// RTSystemEditor's copies leave several connectors with one connector id: the ends tell them
/// apart, so removing one of them is that connector removed, not another one changed.
#[test]
fn connectors_sharing_an_id_are_told_apart_by_their_ends() {
    let original = std::fs::read_to_string(nav_system()).expect("system");
    let old = original.replace(r#"rts:connectorId="c3""#, r#"rts:connectorId="c1""#);
    assert_ne!(old, original);
    let start = old
        .find(r#"rts:name="odometry_odom""#)
        .expect("odometry_odom");
    let start = old[..start]
        .rfind("<rts:DataPortConnectors")
        .expect("its element");
    let end = start
        + old[start..]
            .find("</rts:DataPortConnectors>")
            .expect("its end")
        + "</rts:DataPortConnectors>".len();
    let new = format!("{}{}", &old[..start], &old[end..]);
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/NavSystem.xml", &old);
    write(dir.path(), "new/NavSystem.xml", &new);
    let (exit, json) = run(dir.path(), &["old/NavSystem.xml", "new/NavSystem.xml"]);
    assert_eq!(exit, 1, "{json:#}");
    assert_eq!(codes_of(&json), ["DIFF154"], "{json:#}");
    assert_eq!(
        changes(&json)[0]["path"],
        "dataPortConnectors/odometry_odom",
        "{json:#}"
    );
}

/// The old NavSystem of the DIFF15x/25x/35x pairs.
fn nav_system() -> PathBuf {
    fixture("DIFF154").join("old/systems/NavSystem.xml")
}

/// A system compared with itself, with a copy in another folder, and with itself reformatted
/// (attributes in another order, one a line, tabs) gives no change.
#[test]
fn identical_and_reformatted_systems_are_no_change() {
    let reformatted = root().join("tests/fixtures/diff/reformatted/NavSystem.xml");
    let original = std::fs::read_to_string(nav_system()).expect("system");
    let other = std::fs::read_to_string(&reformatted).expect("reformatted");
    assert_ne!(original, other, "the reformatted file differs as text");
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/NavSystem.xml", &original);
    write(dir.path(), "new/moved/NavSystem.xml", &other);
    for (a, b) in [
        (nav_system(), nav_system()),
        (nav_system(), reformatted.clone()),
        (reformatted.clone(), nav_system()),
        (dir.path().join("old"), dir.path().join("new")),
    ] {
        let (exit, json) = run(
            dir.path(),
            &[
                &a.to_string_lossy(),
                &b.to_string_lossy(),
                "--fail-on",
                "info",
            ],
        );
        assert_eq!(exit, 0, "{a:?} {b:?}: {json:#}");
        assert!(changes(&json).is_empty(), "{a:?} {b:?}: {json:#}");
        assert_eq!(json["summary"]["systems"]["matched"], 1, "{json:#}");
        assert_eq!(json["summary"]["systems"]["changed"], 0, "{json:#}");
    }
}

/// Two system files are compared (the issue: they reported "0 of 0 matched components", exit 0),
/// in every output format, with the exit status of `--fail-on`.
#[test]
fn two_system_files_in_every_format() {
    let dir = fixture("DIFF152");
    let (old, new) = ("old/systems/NavSystem.xml", "new/systems/NavSystem.xml");
    let (exit, json) = run(&dir, &[old, new]);
    assert_eq!(exit, 1, "{json:#}");
    assert_eq!(codes_of(&json), ["DIFF152", "DIFF154"]);
    let c = &changes(&json)[0];
    assert_eq!(c["file"], "new/systems/NavSystem.xml");
    assert_eq!(c["oldFile"], "old/systems/NavSystem.xml");
    assert_eq!(c["oldLine"], 28, "{c:#}");
    assert_eq!(
        json["summary"]["systems"],
        serde_json::json!({"old": 1, "new": 1, "matched": 1, "changed": 1, "added": 0, "removed": 0})
    );
    let (exit, _) = run(&dir, &[old, new, "--fail-on", "never"]);
    assert_eq!(exit, 0);
    let text = |format: &str| {
        let out = rtcdoc(&["diff", old, new, "--format", format], &dir);
        assert_eq!(out.status.code(), Some(1), "{format}");
        String::from_utf8_lossy(&out.stdout).to_string()
    };
    let human = text("human");
    assert!(human.starts_with("RTSystem:Lab:NavSystem:1.0\n  breaking[DIFF152] components/Logger0: instance `Logger0`"), "{human}");
    assert!(
        human.contains("--> old/systems/NavSystem.xml:28:5"),
        "{human}"
    );
    assert!(
        human.trim_end().ends_with("2 breaking, 0 warnings, 0 infos in 0 of 0 matched component(s); 0 added, 0 removed; 1 of 1 matched system(s) changed, 0 added, 0 removed"),
        "{human}"
    );
    let markdown = text("markdown");
    assert!(
        markdown.contains("### `RTSystem:Lab:NavSystem:1.0`"),
        "{markdown}"
    );
    assert!(markdown.contains("| 🔴 breaking | DIFF154 `system-connector-removed` | `dataPortConnectors/odometry_log` |"), "{markdown}");
    let github = text("github");
    assert!(
        github.contains("::error file=new/systems/NavSystem.xml,title=DIFF152 system-instance-removed::RTSystem:Lab:NavSystem:1.0 components/Logger0: instance `Logger0`"),
        "{github}"
    );
}

/// A warning and an info from the systems: `--fail-on` decides the exit status as for components.
#[test]
fn system_warnings_and_infos_follow_fail_on() {
    for (code, level) in [("DIFF253", "warning"), ("DIFF354", "info")] {
        for (fail_on, fails) in [
            ("breaking", false),
            ("warning", level == "warning"),
            ("info", true),
        ] {
            let (exit, json) = run(&fixture(code), &["old", "new", "--fail-on", fail_on]);
            assert_eq!(
                exit,
                i32::from(fails),
                "{code} --fail-on {fail_on}: {json:#}"
            );
            assert_eq!(json["summary"][level], 1, "{code}");
        }
    }
}

/// A service connector removed, a connector matched by its ends when its id changed, a data
/// type and an execution context respelled, and an instance's component version: each said as
/// what it is.
#[test]
fn connectors_match_by_ends_and_respellings_are_info() {
    let base = std::fs::read_to_string(nav_system()).expect("system");
    let edit = |pairs: &[(&str, &str)]| {
        let mut s = base.clone();
        for (a, b) in pairs {
            assert!(s.contains(a), "{a}");
            s = s.replacen(a, b, 1);
        }
        s
    };
    let dir = tempfile::tempdir().expect("tempdir");
    write(dir.path(), "old/NavSystem.xml", &base);
    write(
        dir.path(),
        "new/NavSystem.xml",
        &edit(&[
            // Drawn again between the same ports: a new id, the same connector.
            ("rts:connectorId=\"c3\"", "rts:connectorId=\"c9\""),
            // `RTC::TimedPose2D` is `IDL:RTC/TimedPose2D:1.0`.
            (
                "rts:dataType=\"IDL:RTC/TimedPose2D:1.0\" rts:name=\"odometry_log\"",
                "rts:dataType=\"RTC::TimedPose2D\" rts:name=\"odometry_log\"",
            ),
            (
                "rts:kind=\"PERIODIC\" rts:rate=\"1.0\"",
                "rts:kind=\"PeriodicExecutionContext\" rts:rate=\"1\"",
            ),
            (
                "rts:portName=\"Planner0.Map\"",
                "rts:portName=\"Planner0.Nav\"",
            ),
        ]),
    );
    let (exit, json) = run(dir.path(), &["old", "new"]);
    let found: Vec<(String, String)> = changes(&json)
        .iter()
        .map(|c| {
            (
                c["code"].as_str().unwrap_or("").to_string(),
                c["path"].as_str().unwrap_or("").to_string(),
            )
        })
        .collect();
    let expected: Vec<(String, String)> = [
        ("DIFF355", "components/Logger0/executionContexts/0/kind"),
        ("DIFF355", "components/Logger0/executionContexts/0/rate"),
        ("DIFF355", "dataPortConnectors/odometry_log/connectorId"),
        ("DIFF355", "dataPortConnectors/odometry_log/dataType"),
        ("DIFF155", "servicePortConnectors/Map_Map"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    assert_eq!(found, expected, "{json:#}");
    assert_eq!(exit, 1);
    // The service connector removed: its requirers lose their provider.
    let without = {
        let start = base
            .find("    <rts:ServicePortConnectors")
            .expect("service connector");
        let end = base.find("</rts:ServicePortConnectors>\n").expect("end") + 29;
        format!("{}{}", &base[..start], &base[end..])
    };
    write(dir.path(), "new/NavSystem.xml", &without);
    let (exit, json) = run(dir.path(), &["old", "new"]);
    assert_eq!(exit, 1);
    assert_eq!(codes_of(&json), ["DIFF154"], "{json:#}");
    let c = &changes(&json)[0];
    assert_eq!(c["path"], "servicePortConnectors/Map_Map");
    assert!(
        c["message"].as_str().unwrap_or("").contains("(`Base0.Map` — `Planner0.Map`) was removed: the interfaces these ports require from each other lose their provider"),
        "{c:#}"
    );
}

/// `REV:PATH` sides bring their systems, which are compared too.
#[test]
fn a_git_revision_compares_its_systems() {
    let dir = tempfile::tempdir().expect("tempdir");
    if !git(dir.path(), &["init", "-q"]) {
        crate::common::missing_tool("git is not available");
        return;
    }
    let work = dir.path().join("robot");
    std::fs::create_dir_all(&work).expect("mkdir");
    copy_tree(&fixture("DIFF253").join("old"), &work);
    assert!(git(dir.path(), &["add", "-A"]));
    assert!(git(dir.path(), &["commit", "-q", "-m", "old"]));
    copy_tree(&fixture("DIFF253").join("new"), &work);
    let (exit, json) = run(dir.path(), &["HEAD:robot", "robot", "--fail-on", "warning"]);
    assert_eq!(exit, 1, "{json:#}");
    assert_eq!(codes_of(&json), ["DIFF253"], "{json:#}");
    let c = &changes(&json)[0];
    assert_eq!(c["file"], "robot/systems/NavSystem.xml");
    assert_eq!(c["oldFile"], "robot/systems/NavSystem.xml");
    // Both revisions the same: nothing.
    let (exit, json) = run(
        dir.path(),
        &["HEAD:robot", "HEAD:robot", "--fail-on", "info"],
    );
    assert_eq!(exit, 0, "{json:#}");
}

/// The library function a history of one system calls per pair of versions.
#[test]
fn compare_systems_is_callable_per_pair_of_versions() {
    let read = |p: &Path| {
        let bytes = std::fs::read(p).expect("read");
        rtcdoc::parse::rts::parse(
            rtcdoc::parse::SourceFormat::Xml,
            &bytes,
            &p.to_string_lossy(),
            &rtcdoc::parse::Limits::default(),
        )
        .expect("parses")
        .system
    };
    let old = read(&fixture("DIFF253").join("old/systems/NavSystem.xml"));
    let new = read(&fixture("DIFF253").join("new/systems/NavSystem.xml"));
    assert!(rtcdoc::diff::systems::compare_systems(&old, &old).is_empty());
    let found = rtcdoc::diff::systems::compare_systems(&old, &new);
    assert_eq!(found.len(), 1);
    assert_eq!(found[0].code, "DIFF253");
    assert_eq!(found[0].component, "RTSystem:Lab:NavSystem:1.0");
    assert!(found[0].file.is_none() && found[0].line.is_some());
}

/// A copy of OpenRTM's IDL read on the NEW side only is one DIFF335 too ("now read"), not
/// one DIFF334 per type; with the copy on both sides there is nothing to report.
#[test]
fn a_copy_of_openrtm_s_idl_added_is_one_info() {
    let dir = fixture("DIFF335");
    let (exit, json) = run(&dir, &["new", "old"]);
    assert_eq!(exit, 0, "{json:#}");
    assert_eq!(codes_of(&json), ["DIFF335"], "{json:#}");
    let c = &changes(&json)[0];
    assert_eq!(c["file"], "old/idl/BasicDataType.idl", "{c:#}");
    assert!(c["line"].as_u64().unwrap_or(0) > 0, "{c:#}");
    let message = c["message"].as_str().unwrap_or_default();
    assert!(message.contains("is now read: its 2 type(s)"), "{message}");
    let (exit, json) = run(&dir, &["old", "old", "--fail-on", "info"]);
    assert_eq!(exit, 0, "{json:#}");
}

/// Two system files named on the command line hold one system each: a new id is that system
/// renamed (DIFF257, its contents compared), not one system removed and another added.
#[test]
fn the_one_system_of_each_side_renamed_is_compared() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let pair = fixture("DIFF257");
    for (from, to) in [
        ("old/systems/NavSystem.xml", "NavSystem.xml"),
        ("new/systems/NavSystem.xml", "NavSystem-renamed.xml"),
    ] {
        std::fs::copy(pair.join(from), d.join(to)).unwrap();
    }
    let (exit, json) = run(d, &["NavSystem.xml", "NavSystem-renamed.xml"]);
    assert_eq!(codes_of(&json), ["DIFF252", "DIFF257"], "{json:#}");
    assert_eq!(exit, 0, "warnings do not fail by default");
    // A removed system beside another one (no one-to-one) stays removed.
    let (_, json) = run(&fixture("DIFF151"), &["old", "new"]);
    assert_eq!(codes_of(&json), ["DIFF151"], "{json:#}");
}

/// A component renamed in its file (compared with its old self, DIFF101 on its id): the systems
/// that still name the old id lose it as if it was removed (DIFF141).
#[test]
fn a_renamed_component_is_gone_for_the_systems_that_name_its_old_id() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let from = fixture("DIFF141").join("old");
    copy_tree(&from, &d.join("old"));
    copy_tree(&from, &d.join("new"));
    let planner = d.join("new/Planner/RTC.xml");
    let text = std::fs::read_to_string(&planner).unwrap();
    assert!(text.contains(":Planner:1.0.0"), "{text}");
    std::fs::write(&planner, text.replace(":Planner:1.0.0", ":Router:1.0.0")).unwrap();
    let (code, json) = run(d, &["old", "new"]);
    assert_eq!(code, 1, "{json}");
    let codes = codes_of(&json);
    assert!(codes.contains(&"DIFF101".to_string()), "{codes:?}");
    assert_eq!(
        codes.iter().filter(|c| *c == "DIFF141").count(),
        2,
        "the data and the service connector: {codes:?}"
    );
    assert_eq!(json["summary"]["components"]["removed"], 0, "{json}");
}
