//! `rtcdoc check`: one failing fixture and its fixed twin per rule (code and line:col),
//! constraint evaluation for every operator, the CLI (exit codes, formats, --explain) and a run
//! over the shared corpus.

use crate::common;

use rtcdoc::build::{self, LoadOptions};
use rtcdoc::check::{self, Report};
use rtcdoc::constraint::{evaluate, like_matches, LikeChars, Verdict};
use rtcdoc::model::{Comparison, Condition, Constraint, ConstraintKind, Pos};
use rtcdoc::value::ValueType;
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    common::root().join("tests/fixtures/check").join(name)
}

/// The report of a fixture; a directory fixture's own `rtcdoc.toml` gives its stability marks.
fn report(path: &Path) -> Report {
    let mut opts = LoadOptions::default();
    if path.join(rtcdoc::config::FILE_NAME).is_file() {
        let file = rtcdoc::config::load(None, &[path]).expect("rtcdoc.toml");
        opts.stability = file.config.stability_marks;
    }
    let loaded = build::load(path, &opts).expect("load");
    check::check(&loaded.catalog)
}

/// (code, fixture, file within a directory fixture, line, column; line 0: no position). Positions point at the
/// attribute that is wrong (RTCBuilder writes each element on one long line), or at the element
/// when the attribute is missing.
const CASES: &[(&str, &str, u32, u32)] = &[
    ("RTC101", "", 3, 3),
    ("RTC102", "", 3, 124),
    ("RTC103", "", 3, 262),
    ("RTC104", "", 3, 289),
    ("RTC105", "", 3, 310),
    ("RTC106", "", 7, 5),
    ("RTC201", "", 2, 235),
    ("RTC202", "", 2, 235),
    ("RTC203", "", 3, 67),
    ("RTC204", "", 9, 75),
    ("RTC205", "", 10, 55),
    ("RTC206", "", 12, 66),
    ("RTC207", "", 13, 60),
    ("RTC208", "", 3, 179),
    ("RTC209", "", 3, 217),
    ("RTC210", "", 9, 138),
    ("RTC211", "", 9, 138),
    ("RTC212", "", 9, 138),
    ("RTC301", "", 10, 92),
    ("RTC302", "", 10, 76),
    ("RTC303", "", 10, 95),
    ("RTC304", "", 11, 7),
    ("RTC305", "", 11, 7),
    ("RTC306", "", 11, 7),
    ("RTC307", "", 14, 7),
    ("RTC401", "", 11, 5),
    ("RTC408", "", 5, 5),
    ("RTC501", "", 3, 3),
    ("RTC502", "", 9, 3),
    ("RTC503", "", 11, 5),
    ("RTC504", "", 10, 5),
    ("RTC505", "", 7, 5),
    ("RTC010", "A.xml", 2, 1),
    ("RTC402", "A.xml", 9, 3),
    ("RTC403", "A.xml", 9, 3),
    ("RTC404", "A.xml", 9, 3),
    ("RTC405", "A.xml", 9, 3),
    ("RTC406", "vendor/Lab.idl", 3, 3),
    // A deprecated interface of rtcdoc.toml's [stability], at the service interface using it.
    ("RTC407", "A.xml", 11, 5),
    ("RTC506", "idl/Lab.idl", 6, 12),
    ("RTC507", "idl/Lab.idl", 6, 5),
    ("RTC508", "idl/Lab.idl", 7, 12),
    ("RTC601", "System.xml", 8, 5),
    ("RTC602", "System.xml", 7, 3),
    ("RTC603", "System.xml", 3, 3),
    ("RTC604", "System.xml", 5, 3),
    ("RTC605", "System.xml", 5, 3),
    ("RTC606", "System.xml", 5, 7),
    ("RTC607", "System.xml", 5, 7),
    ("RTC608", "System.xml", 9, 5),
    ("RTC609", "System.xml", 14, 3),
    // An instance of a component deprecated in rtcdoc.toml, at the instance.
    ("RTC610", "System.xml", 3, 3),
    ("RTC701", "README.md", 2, 1),
    // A folder named README.md: a finding about the whole file, without a position.
    ("RTC702", "README.md", 0, 0),
    ("RTC703", "README.md", 5, 11),
    // The code beside the profile (RTCBuilder's C++ layout: src/Drift.cpp,
    // include/Drift/Drift.h): at the source line, or at the profile element when the code has
    // nothing there.
    ("RTC801", "RTC.xml", 19, 3),
    ("RTC802", "src/Drift.cpp", 36, 3),
    ("RTC803", "src/Drift.cpp", 34, 3),
    ("RTC804", "src/Drift.cpp", 34, 3),
    ("RTC805", "src/Drift.cpp", 34, 3),
    ("RTC806", "src/Drift.cpp", 38, 3),
    ("RTC807", "src/Drift.cpp", 49, 26),
    ("RTC808", "RTC.xml", 8, 5),
    ("RTC809", "src/Drift.cpp", 10, 26),
    ("RTC810", "src/Drift.cpp", 34, 3),
    ("RTC811", "include/Drift/Drift.h", 25, 281),
    // Code and no profile: documented from the code, at its spec array.
    ("RTC812", "src/Drift.cpp", 7, 26),
];

#[test]
fn every_rule_has_a_failing_fixture_and_a_fixed_twin() {
    for &(code, file, line, column) in CASES {
        let (bad, good) = if file.is_empty() {
            (
                fixture(&format!("{code}-bad.xml")),
                fixture(&format!("{code}-good.xml")),
            )
        } else {
            (
                fixture(&format!("{code}-bad")),
                fixture(&format!("{code}-good")),
            )
        };
        let r = report(&bad);
        let hit = r.diagnostics.iter().find(|d| d.code == code);
        let d = hit.unwrap_or_else(|| panic!("{code}: not reported: {:#?}", r.diagnostics));
        if line == 0 {
            assert_eq!(d.pos, None, "{code}: {}", d.message);
        } else {
            let p = d.pos.unwrap_or_else(|| panic!("{code}: no position"));
            assert_eq!((p.line, p.column), (line, column), "{code}: {}", d.message);
        }
        if !file.is_empty() {
            assert!(d.file.ends_with(file), "{code}: {}", d.file);
        }
        assert!(d.hint.is_some(), "{code} has no hint");
        // The failing fixture shows exactly this one problem.
        assert!(
            r.diagnostics.iter().all(|d| d.code == code),
            "{code}: other findings: {:#?}",
            r.diagnostics
        );
        let r = report(&good);
        assert!(
            r.diagnostics.is_empty(),
            "{code}: the fixed twin is not clean: {:#?}",
            r.diagnostics
        );
    }
}

#[test]
fn every_registered_rule_is_covered_or_a_loader_code() {
    for r in check::RULES {
        let covered = CASES.iter().any(|c| c.0 == r.code) || r.code < "RTC100";
        assert!(covered, "{} has no fixture", r.code);
    }
}

#[test]
fn bundled_examples_satisfy_their_constraints() {
    let r = report(&common::root().join("examples"));
    let codes: Vec<&str> = r.diagnostics.iter().map(|d| d.code).collect();
    for bad in ["RTC301", "RTC303", "RTC304", "RTC305"] {
        assert!(
            !codes.contains(&bad),
            "{bad} in examples: {:#?}",
            r.diagnostics
        );
    }
    assert_eq!(r.summary.errors, 0, "{:#?}", r.diagnostics);
    assert!(r.coverage.total > 0 && r.coverage.percent <= 100.0);
}

// ---- constraint evaluation -------------------------------------------------------------

fn unit(cond: Condition) -> Constraint {
    Constraint {
        kind: ConstraintKind::Unit {
            key: None,
            condition: Box::new(cond),
        },
        pos: Pos::default(),
        extra: rtcdoc::model::Extras::new(),
    }
}
fn keyed(key: &str, c: Constraint) -> Constraint {
    let ConstraintKind::Unit { condition, .. } = c.kind else {
        panic!("unit expected")
    };
    Constraint {
        kind: ConstraintKind::Unit {
            key: Some(key.into()),
            condition,
        },
        pos: Pos::default(),
        extra: rtcdoc::model::Extras::new(),
    }
}
fn cmp_case(c: Comparison, lit: &str, match_case: Option<&str>) -> Constraint {
    unit(Condition::Compare {
        comparison: c,
        literal: Some(lit.into()),
        match_case: match_case.map(Into::into),
    })
}
fn cmp(c: Comparison, lit: &str) -> Constraint {
    cmp_case(c, lit, None)
}
fn between(lo: &str, hi: &str) -> Constraint {
    unit(Condition::Between {
        lower: Some(lo.into()),
        upper: Some(hi.into()),
    })
}
fn like(lit: &str, w: Option<&str>, s: Option<&str>, e: Option<&str>) -> Constraint {
    unit(Condition::Like {
        literal: Some(lit.into()),
        wild_card: w.map(Into::into),
        single_char: s.map(Into::into),
        escape_char: e.map(Into::into),
    })
}
fn not(c: Constraint) -> Constraint {
    unit(Condition::Not { operand: c })
}
fn and(v: Vec<Constraint>) -> Constraint {
    unit(Condition::And { operands: v })
}
fn or(v: Vec<Constraint>) -> Constraint {
    unit(Condition::Or { operands: v })
}
fn null() -> Constraint {
    unit(Condition::IsNull { text: None })
}
fn list(items: Vec<Constraint>) -> Constraint {
    Constraint {
        kind: ConstraintKind::List { items },
        pos: Pos::default(),
        extra: rtcdoc::model::Extras::new(),
    }
}
fn hash(items: Vec<Constraint>) -> Constraint {
    Constraint {
        kind: ConstraintKind::Hash { items },
        pos: Pos::default(),
        extra: rtcdoc::model::Extras::new(),
    }
}
fn ok(c: &Constraint, v: &str, ty: &str) -> bool {
    match evaluate(c, v, ValueType::parse(ty)) {
        Verdict::Satisfied => true,
        Verdict::Violated(_) => false,
        Verdict::Unevaluable(w) => panic!("unevaluable: {w}"),
    }
}

#[test]
fn comparisons_numeric_and_string() {
    use Comparison::*;
    assert!(ok(&cmp(EqualTo, "100"), "100.0", "double"));
    assert!(!ok(&cmp(EqualTo, "100"), "100.0", "string"));
    assert!(ok(&cmp(NotEqualTo, "100"), "99", "int"));
    assert!(!ok(&cmp(NotEqualTo, "100"), "100", "int"));
    assert!(ok(&cmp(LessThan, "100"), "99", "int"));
    assert!(!ok(&cmp(LessThan, "100"), "100", "int"));
    // 9 < 10 numerically, but "9" > "10" as strings.
    assert!(ok(&cmp(LessThan, "10"), "9", "short"));
    assert!(!ok(&cmp(LessThan, "10"), "9", "string"));
    assert!(ok(&cmp(GreaterThan, "-1.5"), "-1", "float"));
    assert!(ok(&cmp(LessThanOrEqualTo, "100"), "100", "long"));
    assert!(!ok(&cmp(LessThanOrEqualTo, "100"), "100.5", "double"));
    assert!(ok(&cmp(GreaterThanOrEqualTo, "0"), "0", "unsigned int"));
    assert!(ok(&cmp(LessThan, "b"), "a", "string"));
    // Unknown types compare numerically when both sides are numbers.
    assert!(ok(&cmp(LessThan, "10"), "9", "MyType"));
    // Booleans compare by value.
    assert!(ok(&cmp(EqualTo, "true"), "1", "bool"));
    assert!(!ok(&cmp(EqualTo, "false"), "yes", "boolean"));
}

#[test]
fn match_case() {
    use Comparison::*;
    assert!(
        !ok(&cmp(EqualTo, "test"), "TEST", "string"),
        "absent = sensitive"
    );
    assert!(!ok(
        &cmp_case(EqualTo, "test", Some("true")),
        "TEST",
        "string"
    ));
    assert!(ok(
        &cmp_case(EqualTo, "test", Some("false")),
        "TEST",
        "string"
    ));
    assert!(ok(
        &cmp_case(NotEqualTo, "test", Some("true")),
        "Test",
        "string"
    ));
    assert!(!ok(
        &cmp_case(NotEqualTo, "test", Some("false")),
        "Test",
        "string"
    ));
}

#[test]
fn between_edges_inclusive() {
    let b = between("100", "200");
    assert!(ok(&b, "100", "int"));
    assert!(ok(&b, "200", "int"));
    assert!(ok(&b, "150", "int"));
    assert!(!ok(&b, "99", "int"));
    assert!(!ok(&b, "200.0001", "double"));
    assert!(ok(&between("b", "d"), "c", "string"));
    assert!(!ok(&between("b", "d"), "e", "string"));
}

#[test]
fn null_and_not() {
    assert!(ok(&null(), "", "string"));
    assert!(ok(&null(), "  ", "string"));
    assert!(!ok(&null(), "x", "string"));
    assert!(ok(&not(null()), "x", "string"));
    assert!(!ok(&not(null()), "", "string"));
    assert!(
        !ok(&not(null()), "", "vector<int>"),
        "null applies to the whole vector"
    );
    assert!(ok(&not(not(cmp(Comparison::EqualTo, "1"))), "1", "int"));
}

#[test]
fn and_or_nesting() {
    use Comparison::*;
    let range = and(vec![cmp(GreaterThanOrEqualTo, "0"), cmp(LessThan, "10")]);
    assert!(ok(&range, "0", "int"));
    assert!(!ok(&range, "10", "int"));
    let outside = or(vec![
        cmp(LessThanOrEqualTo, "100"),
        cmp(GreaterThanOrEqualTo, "200"),
    ]);
    assert!(ok(&outside, "100", "int"));
    assert!(ok(&outside, "250", "int"));
    assert!(!ok(&outside, "150", "int"));
    let colours = or(vec![
        cmp(EqualTo, "red"),
        cmp(EqualTo, "blue"),
        cmp(EqualTo, "green"),
    ]);
    assert!(ok(&colours, "blue", "string"));
    assert!(!ok(&colours, "white", "string"));
    // not (x in 5..=10 or x = 42) and x > 0, three operands under and.
    let nested = and(vec![
        not(or(vec![between("5", "10"), cmp(EqualTo, "42")])),
        cmp(GreaterThan, "0"),
        not(null()),
    ]);
    assert!(ok(&nested, "3", "int"));
    assert!(!ok(&nested, "7", "int"));
    assert!(!ok(&nested, "42", "int"));
    assert!(!ok(&nested, "-1", "int"));
}

#[test]
fn like_patterns() {
    let d = LikeChars::from_attrs(&None, &None, &None);
    assert!(like_matches("camera0", "camera?", d));
    assert!(!like_matches("camera10", "camera?", d));
    assert!(like_matches("camera10", "camera*", d));
    assert!(like_matches("", "*", d));
    assert!(like_matches("abcabd", "*abd", d));
    assert!(!like_matches("abc", "a*d", d));
    // Escapes: a literal star and question mark.
    assert!(like_matches("a*b", "a\\*b", d));
    assert!(!like_matches("axb", "a\\*b", d));
    assert!(like_matches("why?", "why\\?", d));
    // Custom characters, as in spec 8.1 (`singleChar=". "`, `escapeChar="\$"`).
    let c = LikeChars::from_attrs(&Some("%".into()), &Some(". ".into()), &Some("!".into()));
    assert!(like_matches("abcd : efg : anything", ".... : ... : %", c));
    assert!(!like_matches("abc : efg : x", ".... : ... : %", c));
    assert!(like_matches("50%", "50!%", c));
    assert!(like_matches("a.b", "a!.b", c));
    assert!(!like_matches("axb", "a!.b", c));
    // Regex metacharacters are plain text.
    assert!(like_matches("(a+)$", "(a+)$", d));
    assert!(!like_matches("aa", "(a+)", d));
    // Pathological pattern: quick, no exponential backtracking.
    let text = "a".repeat(2000);
    let pat = format!("{}b", "*a".repeat(50));
    assert!(!like_matches(&text, &pat, d));
    // Evaluated as a constraint.
    assert!(ok(&like("cam*", None, None, None), "camera", "string"));
    assert!(!ok(&like("cam*", None, None, None), "Camera", "string"));
}

#[test]
fn list_and_hash_over_vectors() {
    use Comparison::*;
    let l = list(vec![between("0", "10"), cmp(GreaterThan, "100")]);
    assert!(ok(&l, "5, 200", "vector<int>"));
    assert!(
        ok(&l, "5,200,7", "std::vector<int>"),
        "extra elements are free"
    );
    assert!(!ok(&l, "11,200", "vector<int>"));
    assert!(!ok(&l, "5,50", "vector<int>"));
    assert!(!ok(&l, "5", "vector<int>"), "missing element");
    // A unit over a vector applies to every element.
    assert!(ok(&between("0", "1"), "0.1,0.5,1", "vector<double>"));
    assert!(!ok(&between("0", "1"), "0.1,1.5", "vector<double>"));
    assert!(ok(&between("0", "1"), "", "vector<double>"), "empty vector");
    // An enumeration over a vector: each element is one of the values.
    let one_of = or(vec![cmp(EqualTo, "raw"), cmp(EqualTo, "jpeg")]);
    assert!(ok(&one_of, "raw,jpeg", "vector<string>"));
    assert!(!ok(&one_of, "raw,png", "vector<string>"));
    let h = hash(vec![
        keyed("x", cmp(GreaterThanOrEqualTo, "0")),
        keyed("width", between("1", "1280")),
    ]);
    assert!(
        ok(&h, "x:0,y:5,width:640", "string"),
        "numbers inside a string"
    );
    assert!(!ok(&h, "x:-1,width:640", "string"));
    assert!(!ok(&h, "x:1", "string"), "missing key");
    assert!(!ok(&h, "x:1,width:2000", "vector<int>"));
    // Hash over a plain value: keyed alternatives.
    let alt = hash(vec![
        keyed("twochar", cmp(EqualTo, "2")),
        keyed("threechar", cmp(EqualTo, "3")),
    ]);
    assert!(ok(&alt, "2", "int"));
    assert!(!ok(&alt, "4", "int"));
    // A mix of pairs and plain items cannot be evaluated.
    assert!(matches!(
        evaluate(&h, "x:1,7", ValueType::parse("string")),
        Verdict::Unevaluable(_)
    ));
}

#[test]
fn evaluation_never_panics_on_odd_input() {
    let odd = [
        "",
        ",",
        ":",
        ",,,:,:",
        "\u{0}",
        "ｘ：１",
        "1e999",
        "-",
        "NaN",
    ];
    let cs = [
        cmp(Comparison::LessThan, ""),
        between("x", "1"),
        like("", Some(""), Some(""), Some("")),
        like("\\", None, None, None),
        list(vec![]),
        hash(vec![cmp(Comparison::EqualTo, "1")]),
        and(vec![]),
        or(vec![]),
        Constraint {
            kind: ConstraintKind::Empty,
            pos: Pos::default(),
            extra: rtcdoc::model::Extras::new(),
        },
    ];
    for c in &cs {
        for v in odd {
            for ty in [
                "int",
                "double",
                "bool",
                "char",
                "string",
                "vector<int>",
                "X",
            ] {
                let _ = evaluate(c, v, ValueType::parse(ty));
                let _ = rtcdoc::constraint::problems(c, ValueType::parse(ty));
            }
        }
    }
    // Deep nesting is bounded.
    let mut deep = null();
    for _ in 0..2000 {
        deep = not(deep);
    }
    let _ = evaluate(&deep, "x", ValueType::parse("string"));
    std::mem::forget(deep); // dropping 2000 nested boxes recursively is fine, but not needed
}

// ---- CLI -------------------------------------------------------------------------------

fn run(args: &[&str]) -> std::process::Output {
    common::rtcdoc(args, &common::root())
}

#[test]
fn cli_exit_codes() {
    let good = "tests/fixtures/check/RTC303-good.xml";
    let bad = "tests/fixtures/check/RTC303-bad.xml";
    let warn = "tests/fixtures/check/RTC203-bad.xml";
    assert_eq!(run(&["check", good]).status.code(), Some(0));
    let out = run(&["check", bad]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("error[RTC303]"), "{err}");
    assert!(
        err.contains("tests/fixtures/check/RTC303-bad.xml:10:95"),
        "{err}"
    );
    assert!(err.contains("^"), "caret under the source line: {err}");
    assert!(err.contains("help:"), "{err}");
    assert!(!err.contains("\u{1b}["), "NO_COLOR honoured: {err}");
    assert_eq!(run(&["check", warn]).status.code(), Some(0));
    assert_eq!(
        run(&["check", "--deny", "warnings", warn]).status.code(),
        Some(1)
    );
    assert_eq!(run(&["check", "does/not/exist"]).status.code(), Some(2));
    assert_eq!(
        run(&["check", "--format", "yaml", good]).status.code(),
        Some(2)
    );
    assert_eq!(
        run(&["check", "--explain", "RTC999"]).status.code(),
        Some(2)
    );
}

/// `--explain` takes a rule's name as well as its code, and a code of the other command says
/// which command explains it; that command does.
#[test]
fn explain_takes_names_and_points_to_the_other_command() {
    let text = |o: std::process::Output| {
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stdout).to_string(),
            String::from_utf8_lossy(&o.stderr).to_string(),
        )
    };
    let (code, out, _) = text(run(&["check", "--explain", "duplicate-parameter"]));
    assert_eq!(code, Some(0));
    assert!(out.starts_with("RTC207 (duplicate-parameter)"), "{out}");
    let (code, out, _) = text(run(&["diff", "--explain", "data-port-type-changed"]));
    assert_eq!(code, Some(0));
    assert!(out.starts_with("DIFF104 (data-port-type-changed)"), "{out}");
    for (cmd, code_, other, first) in [
        ("check", "DIFF101", "diff", "DIFF101 ("),
        ("diff", "RTC101", "check", "RTC101 ("),
    ] {
        let (code, _, err) = text(run(&[cmd, "--explain", code_]));
        assert_eq!(code, Some(2));
        let hint = format!("run `rtcdoc {other} --explain {code_}`");
        assert!(err.contains(&hint), "{err}");
        let (code, out, _) = text(run(&[other, "--explain", code_]));
        assert_eq!(code, Some(0));
        assert!(out.starts_with(first), "{out}");
    }
}

#[test]
fn cli_json_schema() {
    let out = run(&[
        "check",
        "--format",
        "json",
        "tests/fixtures/check/RTC303-bad.xml",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["version"], 1);
    let d = &v["diagnostics"][0];
    for key in [
        "code", "severity", "message", "file", "line", "column", "hint",
    ] {
        assert!(d.get(key).is_some(), "missing {key}");
    }
    assert_eq!(d["code"], "RTC303");
    assert_eq!(d["severity"], "error");
    assert_eq!(d["line"], 10);
    // The `rtc:defaultValue` attribute, not the start of its element.
    assert_eq!(d["column"], 95);
    assert_eq!(d["file"], "tests/fixtures/check/RTC303-bad.xml");
    let s = &v["summary"];
    assert_eq!(s["errors"], 1);
    assert_eq!(s["warnings"], 0);
    assert_eq!(s["infos"], 0);
    assert_eq!(s["byCode"]["RTC303"], 1);
    let c = &v["coverage"];
    assert!(c["percent"].is_number() && c["components"].is_array());
}

#[test]
fn cli_sarif() {
    let out = run(&[
        "check",
        "--format",
        "sarif",
        "tests/fixtures/check/RTC203-bad.xml",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("sarif json");
    assert_eq!(v["version"], "2.1.0");
    assert!(v["$schema"].as_str().is_some_and(|s| s.contains("sarif")));
    let run0 = &v["runs"][0];
    assert_eq!(run0["tool"]["driver"]["name"], "rtcdoc");
    // Columns are characters, as in the human output; SARIF assumes UTF-16 units unless told.
    assert_eq!(run0["columnKind"], "unicodeCodePoints");
    let rules = run0["tool"]["driver"]["rules"].as_array().expect("rules");
    assert!(rules.iter().any(|r| r["id"] == "RTC203"));
    assert!(rules
        .iter()
        .all(|r| r["shortDescription"]["text"].is_string() && r.get("helpUri").is_none()));
    let res = &run0["results"][0];
    assert_eq!(res["ruleId"], "RTC203");
    assert_eq!(res["level"], "warning");
    assert!(res["message"]["text"].is_string());
    let loc = &res["locations"][0]["physicalLocation"];
    assert_eq!(
        loc["artifactLocation"]["uri"],
        "tests/fixtures/check/RTC203-bad.xml"
    );
    assert_eq!(loc["region"]["startLine"], 3);
    assert_eq!(loc["region"]["startColumn"], 67);
}

#[test]
fn cli_explain() {
    for code in ["RTC001", "RTC010", "RTC303", "rtc501"] {
        let out = run(&["check", "--explain", code]);
        assert_eq!(out.status.code(), Some(0), "{code}");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("Spec:"), "{text}");
        assert!(text.to_uppercase().contains(&code.to_uppercase()));
    }
}

#[test]
fn build_prints_a_check_summary_and_keeps_rendering() {
    let tmp = tempfile::tempdir().expect("tmp");
    let out_dir = tmp.path().join("site");
    let out = run(&[
        "build",
        "tests/fixtures/check/RTC303-bad.xml",
        "-o",
        out_dir.to_str().expect("utf8"),
        "-f",
        "json",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("check: 1 error, 0 warnings, 0 infos"), "{err}");
    let json = std::fs::read_to_string(out_dir.join("catalog.json")).expect("catalog.json");
    assert!(
        json.contains("RTC303"),
        "rule diagnostics in the JSON output"
    );
}

// ---- corpus ----------------------------------------------------------------------------

#[test]
fn corpus_counts_by_code() {
    let dir = common::root().join("../shared/corpus");
    let dir = if dir.is_dir() {
        dir
    } else if Path::new("/work/shared/corpus").is_dir() {
        PathBuf::from("/work/shared/corpus")
    } else {
        println!("skipped: ../shared/corpus not present");
        return;
    };
    let r = report(&dir);
    println!(
        "corpus: {} profiles, {} errors, {} warnings, {} infos, doc coverage {:.1}%",
        r.coverage.components.len(),
        r.summary.errors,
        r.summary.warnings,
        r.summary.infos,
        r.coverage.percent
    );
    for (code, n) in &r.summary.by_code {
        println!("  {code}: {n}");
    }
    assert!(!r.coverage.components.is_empty());
}

/// On the real corpus: RTC501 fires only where neither BasicInfo nor the Document Profile
/// describes the component, and no dialect spelling (RTCBuilder 0.1, rtc-template) is reported
/// as unknown.
#[test]
fn corpus_component_descriptions_and_dialects() {
    let dir = common::root().join("../shared/corpus");
    if !dir.is_dir() {
        println!("skipped: ../shared/corpus not present");
        return;
    }
    let loaded = build::load(&dir, &LoadOptions::default()).expect("load");
    let r = check::check(&loaded.catalog);
    let (mut described, mut undescribed_reported) = (0, 0);
    for c in &loaded.catalog.components {
        let basic = rtcdoc::model::documented("description", &c.profile.basic_info.description);
        let fired = r
            .diagnostics
            .iter()
            .any(|d| d.code == "RTC501" && d.file == c.source);
        if basic.is_some() {
            described += 1;
            assert!(!fired, "RTC501 on {} which has a description", c.source);
        } else if fired {
            undescribed_reported += 1;
        }
    }
    assert!(described > 100, "{described}");
    // The rule still fires, on the same file names: the comparison above can fail.
    assert!(undescribed_reported > 10, "{undescribed_reported}");
    for d in &r.diagnostics {
        if d.code == "RTC006" {
            for name in [
                "varname",
                "subscriprionType",
                "`doc`",
                "`position`",
                "`java`",
            ] {
                assert!(!d.message.contains(name), "{}: {}", d.file, d.message);
            }
            assert!(!d.message.contains("``"), "{}", d.message);
        }
        assert_ne!(d.code, "RTC201", "{}: {}", d.file, d.message);
    }
}

/// An enumeration (an Or of equalities) that a value fails says so once, with the allowed
/// values, instead of one "is not =" per value.
#[test]
fn a_failed_enumeration_names_the_allowed_values_once() {
    use Comparison::*;
    let e = or(vec![
        cmp(EqualTo, "RGB"),
        cmp(EqualTo, "GRAY"),
        cmp(EqualTo, "JPEG"),
    ]);
    match evaluate(&e, "PNG", ValueType::parse("string")) {
        Verdict::Violated(w) => assert_eq!(w, "`PNG` is not one of: RGB, GRAY, JPEG"),
        other => panic!("{other:?}"),
    }
    // Other alternatives keep their reasons.
    let mixed = or(vec![cmp(LessThan, "0"), cmp(GreaterThan, "10")]);
    match evaluate(&mixed, "5", ValueType::parse("long")) {
        Verdict::Violated(w) => assert!(w.contains("; and "), "{w}"),
        other => panic!("{other:?}"),
    }
}

/// executionRate 0 is what profiles write for a context that runs at no rate (externally
/// triggered, event-driven): accepted there. On a periodic context it is what a suite writes
/// when rtc.conf sets the rate at run time (`exec_cxt.periodic.rate`): a warning that says so,
/// not an error that fails `check`. A negative rate or one that is not a number is an error.
#[test]
fn a_rate_of_zero_is_accepted_where_no_rate_drives_the_context() {
    use rtcdoc::diagnostic::Severity::{Error, Warning};
    let bad = std::fs::read_to_string(fixture("RTC103-bad.xml")).expect("fixture");
    let written = r#"rtc:executionType="PeriodicExecutionContext" rtc:executionRate="-10.0""#;
    assert!(bad.contains(written));
    let dir = tempfile::tempdir().expect("tempdir");
    for (execution_type, rate, found) in [
        ("PeriodicExecutionContext", "-10.0", Some(Error)),
        ("PeriodicExecutionContext", "0", Some(Warning)),
        ("PeriodicExecutionContext", "0.0", Some(Warning)),
        ("PeriodicExecutionContext", "-0.0", Some(Warning)),
        ("PeriodicExecutionContext", "fast", Some(Error)),
        ("ExtTrigExecutionContext", "0.0", None),
        ("EventDrivenExecutionContext", "0", None),
        ("ExtTrigExecutionContext", "-1", Some(Error)),
        ("ExtTrigExecutionContext", "fast", Some(Error)),
        ("ExtTrigExecutionContext", "100.0", None),
    ] {
        let text = bad.replace(
            written,
            &format!(r#"rtc:executionType="{execution_type}" rtc:executionRate="{rate}""#),
        );
        let file = dir.path().join(format!("{execution_type}-{rate}.xml"));
        std::fs::write(&file, text).expect("write");
        let r = report(&file);
        let d = r.diagnostics.iter().find(|d| d.code == "RTC103");
        assert_eq!(d.map(|d| d.severity), found, "{execution_type} at {rate}");
        if found == Some(Warning) {
            let d = d.expect("RTC103");
            assert!(
                d.message.contains("set at run time")
                    && d.message.contains("exec_cxt.periodic.rate"),
                "{}",
                d.message
            );
            // A warning does not fail `check` (without --deny warnings).
            assert!(!r.failed(false), "{execution_type} at {rate}");
        }
    }
}

/// `Any` is what OpenRTM's in-ports report and RTSystemEditor saves: accepted on an in-port
/// (and an FSM event port); on an out-port, whose publisher is flush, new or periodic, it is
/// still RTC212, as is an unknown value on an in-port.
#[test]
fn subscription_type_any_is_an_in_port_value() {
    let bad = std::fs::read_to_string(fixture("RTC212-bad.xml")).expect("fixture");
    let written = r#"rtc:portType="DataInPort" rtc:name="in" rtc:type="RTC::TimedLong" rtcExt:position="LEFT" rtc:subscriptionType="often""#;
    assert!(bad.contains(written));
    let dir = tempfile::tempdir().expect("tempdir");
    for (port_type, subscription, flagged) in [
        ("DataInPort", "Any", false),
        ("DataInPort", "any", false),
        ("EventPort", "Any", false),
        ("DataInPort", "New,Any", false),
        ("DataInPort", "often", true),
        ("DataOutPort", "Any", true),
        ("DataOutPort", "New,Periodic", false),
    ] {
        let text = bad.replace(
            written,
            &written
                .replace("DataInPort", port_type)
                .replace("often", subscription),
        );
        let file = dir.path().join(format!("{port_type}-{subscription}.xml"));
        std::fs::write(&file, text).expect("write");
        let r = report(&file);
        let found: Vec<&str> = r
            .diagnostics
            .iter()
            .filter(|d| d.code == "RTC212")
            .map(|d| d.message.as_str())
            .collect();
        assert_eq!(
            !found.is_empty(),
            flagged,
            "{port_type} {subscription}: {found:?}"
        );
        if port_type == "DataOutPort" && flagged {
            assert!(
                found[0].contains("which OpenRTM in-ports report"),
                "{found:?}"
            );
        }
    }
}

/// A value that holds backticks is quoted whole: the finding's code spans (read as CommonMark
/// reads them, as every output does) are the value, and the HTML report shows it as one piece
/// of code (it showed `1`, then `5` as text, then code running on into the message).
#[test]
fn a_value_with_backticks_is_quoted_whole() {
    let dir = tempfile::tempdir().unwrap();
    let profile =
        std::fs::read_to_string(common::root().join("tests/fixtures/check/RTC303-bad.xml"))
            .unwrap()
            .replace(r#"rtc:defaultValue="150""#, r#"rtc:defaultValue="1`5``0""#);
    common::write(dir.path(), "in/A.xml", &profile);
    let message = common::findings(dir.path(), "in", &["RTC301"])[0]["message"]
        .as_str()
        .expect("RTC301")
        .to_string();
    let chars: Vec<char> = message.chars().collect();
    let spans: Vec<String> = rtcdoc::render::text::code_spans(&chars, true)
        .iter()
        .map(|s| s.content(&chars).iter().collect())
        .collect();
    assert_eq!(spans, ["1`5``0", "speed", "1`5``0"], "{message}");
    let o = common::rtcdoc(&["build", "in", "-o", "site", "-q"], dir.path());
    assert!(o.status.success() || o.status.code() == Some(1), "{o:?}");
    let page = std::fs::read_to_string(dir.path().join("site/diagnostics.html")).unwrap();
    assert!(
        page.contains("default value <code>1`5``0</code> of configuration <code>speed</code>"),
        "{page}"
    );
}

/// The C++ and Python implementations of one component share its id (RTCBuilder generates
/// both from one specification): no RTC010 between them. Two profiles of one language still
/// clash, and only they are named.
#[test]
fn implementations_in_two_languages_share_an_id_without_rtc010() {
    let dir = tempfile::tempdir().unwrap();
    let a = std::fs::read_to_string(common::root().join("tests/fixtures/check/RTC010-bad/A.xml"))
        .unwrap();
    let with_lang = |kind: &str| {
        a.replace(
            "</rtc:RtcProfile>",
            &format!("  <rtc:Language xsi:type=\"rtcExt:language_ext\" rtc:kind=\"{kind}\"/>\n</rtc:RtcProfile>"),
        )
    };
    common::write(dir.path(), "in/cpp/RTC.xml", &with_lang("C++"));
    common::write(dir.path(), "in/py/RTC.xml", &with_lang("Python"));
    let rtc010 = |d: &Path| -> Vec<(String, String)> {
        common::findings(d, "in", &["RTC010"])
            .iter()
            .map(|f| {
                let s = |k: &str| f[k].as_str().unwrap_or_default().to_string();
                (s("file"), s("message"))
            })
            .collect()
    };
    assert_eq!(rtc010(dir.path()), Vec::new());
    common::write(dir.path(), "in/py-copy/RTC.xml", &with_lang("Python"));
    let found = rtc010(dir.path());
    let files: Vec<&str> = found.iter().map(|(f, _)| f.as_str()).collect();
    assert_eq!(files, ["in/py-copy/RTC.xml", "in/py/RTC.xml"], "{found:?}");
    assert!(
        found.iter().all(|(_, m)| !m.contains("cpp/RTC.xml")),
        "{found:?}"
    );
}

/// RTC203 on a version of words beside a vendor that is a version number: the message asks
/// whether the two are swapped (as in a 2015 SFML joystick profile), instead of only saying to
/// remove the spaces; a vendor with spaces alone gets no such question.
#[test]
fn vendor_and_version_swapped_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let joystick =
        std::fs::read_to_string(common::root().join("examples/Joystick/RTC.xml")).unwrap();
    let swapped = joystick
        .replace(
            r#"rtc:version="1.0.0""#,
            r#"rtc:version="Joystick Component""#,
        )
        .replace(r#"rtc:vendor="ExampleRobotics""#, r#"rtc:vendor="1.0.0""#);
    common::write(d, "in/RTC.xml", &swapped);
    let found = common::findings(d, "in", &["RTC203"]);
    let messages: Vec<&str> = found.iter().filter_map(|f| f["message"].as_str()).collect();
    assert_eq!(
        messages,
        ["version `Joystick Component` contains whitespace (the vendor `1.0.0` looks like a version: are vendor and version swapped?)"]
    );
    let spaced = joystick.replace(
        r#"rtc:vendor="ExampleRobotics""#,
        r#"rtc:vendor="Example Robotics""#,
    );
    common::write(d, "in/RTC.xml", &spaced);
    let found = common::findings(d, "in", &["RTC203"]);
    let messages: Vec<&str> = found.iter().filter_map(|f| f["message"].as_str()).collect();
    assert_eq!(messages, ["vendor `Example Robotics` contains whitespace"]);
    // A version with a space that is still a version number is not taken for a swap.
    let spaced_version = joystick
        .replace(r#"rtc:version="1.0.0""#, r#"rtc:version="1.0 rc1""#)
        .replace(r#"rtc:vendor="ExampleRobotics""#, r#"rtc:vendor="2""#);
    common::write(d, "in/RTC.xml", &spaced_version);
    let found = common::findings(d, "in", &["RTC203"]);
    let messages: Vec<&str> = found.iter().filter_map(|f| f["message"].as_str()).collect();
    assert_eq!(messages, ["version `1.0 rc1` contains whitespace"]);
}
