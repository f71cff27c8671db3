//! Tests of the XML reader (`rtcdoc::parse::xml`): one test per dialect variation, one per
//! error kind (code + line:column), the real-world corpus, and property tests for robustness.

use rtcdoc::diagnostic::{codes, Diagnostic, Severity};
use rtcdoc::model::*;
use rtcdoc::parse::xml::{is_profile, parse};
use rtcdoc::parse::{Limits, Parsed};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn fixture_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/xml")
        .join(name)
}

fn fixture(name: &str) -> Vec<u8> {
    std::fs::read(fixture_path(name)).expect("fixture exists")
}

fn ok(name: &str) -> Parsed {
    match parse(&fixture(name), name, &Limits::default()) {
        Ok(p) => p,
        Err(d) => panic!("{name} should parse: {d}"),
    }
}

fn err_bytes(bytes: &[u8]) -> Diagnostic {
    match parse(bytes, "test.xml", &Limits::default()) {
        Ok(p) => panic!("should fail, got {:#?}", p.profile),
        Err(d) => d,
    }
}

fn err(name: &str) -> Diagnostic {
    err_bytes(&fixture(name))
}

fn assert_err(d: &Diagnostic, code: &str, line: u32, column: u32) {
    assert_eq!(d.code, code, "{d}");
    assert_eq!(d.severity, Severity::Error, "{d}");
    assert_eq!(d.pos, Some(Pos::new(line, column)), "{d}");
}

fn unit_condition(c: &Constraint) -> &Condition {
    match &c.kind {
        ConstraintKind::Unit { condition, .. } => condition,
        other => panic!("expected a unit, got {other:?}"),
    }
}

fn config_constraint(p: &Parsed) -> &Constraint {
    p.profile.configurations()[0]
        .constraint
        .as_ref()
        .expect("constraint")
}

/// A profile whose configuration holds `constraint`.
fn with_constraint(constraint: &str) -> Vec<u8> {
    format!(
        r#"<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc"><rtc:ConfigurationSet><rtc:Configuration rtc:name="c">{constraint}</rtc:Configuration></rtc:ConfigurationSet></rtc:RtcProfile>"#
    )
    .into_bytes()
}

// --- every field ---------------------------------------------------------------------------

#[test]
fn minimal_profile_fills_every_field() {
    let p = ok("minimal.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let pr = &p.profile;
    assert_eq!(pr.id.as_deref(), Some("RTC:Acme:Test:Sample:1.0.0"));
    assert_eq!(pr.version.as_deref(), Some("0.2"));
    assert_eq!(pr.pos, Pos::new(2, 1));
    let b = &pr.basic_info;
    assert_eq!(b.name.as_deref(), Some("Sample"));
    assert_eq!(
        b.execution_type.as_deref(),
        Some("PeriodicExecutionContext")
    );
    assert_eq!(b.max_instances.as_deref(), Some("1"));
    assert_eq!(b.pos, Pos::new(3, 5));
    let doc = b.doc.as_ref().unwrap();
    assert_eq!(doc.description.as_deref(), Some("A <sample> & more!"));
    assert_eq!(doc.license.as_deref(), Some("MIT"));
    assert_eq!(b.properties[0].name.as_deref(), Some("FSM"));
    assert_eq!(pr.actions.len(), 2);
    assert_eq!(pr.actions[0].kind, ActionKind::OnInitialize);
    assert!(pr.actions[0].is_implemented());
    let ad = pr.actions[0].doc.as_ref().unwrap();
    assert_eq!(ad.pre_condition.as_deref(), Some("pre"));
    assert_eq!(ad.post_condition.as_deref(), Some("post"));
    assert_eq!(pr.actions[1].kind, ActionKind::OnExecute);
    assert!(pr.actions_pos.is_some());

    let c = &pr.configurations()[0];
    assert_eq!(c.name.as_deref(), Some("gain"));
    assert_eq!(c.variable_name.as_deref(), Some("gain"));
    assert_eq!(c.unit.as_deref(), Some(""));
    assert_eq!(c.widget(), Some("slider.1"));
    let cd = c.doc.as_ref().unwrap();
    assert_eq!(cd.constraint.as_deref(), Some("0<=x<=100"));
    assert_eq!(cd.range.as_deref(), Some("0-100"));
    assert_eq!(
        unit_condition(c.constraint.as_ref().unwrap()),
        &Condition::Between {
            lower: Some("0".into()),
            upper: Some("100".into())
        }
    );

    let d = &pr.data_ports[0];
    assert_eq!(d.direction(), Some(PortDirection::In));
    assert_eq!(d.type_.as_deref(), Some("RTC::TimedLong"));
    assert_eq!(d.position.as_deref(), Some("LEFT"));
    let dd = d.doc.as_ref().unwrap();
    assert_eq!(
        dd.occurrence.as_deref(),
        Some("periodic"),
        "occerrence accepted"
    );
    assert_eq!(dd.description.as_deref(), Some("input"));

    let s = &pr.service_ports[0];
    assert_eq!(s.name.as_deref(), Some("svc"));
    assert_eq!(s.position.as_deref(), Some("RIGHT"));
    assert_eq!(s.doc.as_ref().unwrap().ifdescription.as_deref(), Some("if"));
    let i = &s.interfaces[0];
    assert_eq!(i.direction_kind(), Some(Direction::Provided));
    assert_eq!(i.instance_name.as_deref(), Some("inst"));
    assert_eq!(i.path.as_deref(), Some("/idl"));
    assert_eq!(i.variable_name.as_deref(), Some("v"));
    let idoc = i.doc.as_ref().unwrap();
    assert_eq!(idoc.doc_argument.as_deref(), Some("e"));
    assert_eq!(idoc.doc_post_condition.as_deref(), Some("a"));
    assert_eq!(s.trans_methods[0].kind.as_deref(), Some("CORBA"));

    assert_eq!(pr.parameters[0].name.as_deref(), Some("p1"));
    assert_eq!(pr.parameters[0].default_value.as_deref(), Some("v1"));
    let l = pr.language.as_ref().unwrap();
    assert_eq!(l.kind.as_deref(), Some("C++"));
    let t = &l.targets[0];
    assert_eq!(t.os.as_deref(), Some("Linux"));
    assert_eq!(t.cpu_other.as_deref(), Some(""));
    assert_eq!(t.os_versions, vec!["Ubuntu 22.04"]);
    assert_eq!(t.cpus, vec!["x86_64"]);
    assert_eq!(t.libraries[0].name.as_deref(), Some("libfoo"));
    assert_eq!(t.libraries[0].version.as_deref(), Some("1.2"));
    assert!(pr.all_extras().is_empty());
}

#[test]
fn is_profile_detects_root() {
    assert!(is_profile(&fixture("minimal.xml")));
    assert!(is_profile(&fixture("other_prefixes.xml")));
    assert!(!is_profile(&fixture("system_profile.xml")));
    assert!(!is_profile(b"not xml"));
    assert!(!is_profile(b""));
    let mut bom = b"\xEF\xBB\xBF<!-- c --><?pi x?><!DOCTYPE x>".to_vec();
    bom.extend_from_slice(b"<a:RtcProfile xmlns:a='u'/>");
    assert!(is_profile(&bom));
}

// --- dialect variations ----------------------------------------------------------------------

#[test]
fn constraint_element_case_and_default_namespace() {
    let p = ok("constraint_case.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    assert_eq!(
        unit_condition(config_constraint(&p)),
        &Condition::Compare {
            comparison: Comparison::EqualTo,
            literal: Some("100".into()),
            match_case: None
        }
    );
}

#[test]
fn like_accepts_wild_char() {
    let p = ok("like_wildchar.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    assert_eq!(
        unit_condition(config_constraint(&p)),
        &Condition::Like {
            literal: Some("a*".into()),
            wild_card: Some("*".into()),
            single_char: Some("?".into()),
            escape_char: Some("\\".into())
        }
    );
}

#[test]
fn like_accepts_wild_card() {
    let p = ok("like_wildcard.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    match unit_condition(config_constraint(&p)) {
        Condition::Like { wild_card, .. } => assert_eq!(wild_card.as_deref(), Some("%")),
        other => panic!("{other:?}"),
    }
}

#[test]
fn or_with_three_operands_and_missing_match_case() {
    let p = ok("or_three.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let Condition::Or { operands } = unit_condition(config_constraint(&p)) else {
        panic!("or expected")
    };
    assert_eq!(operands.len(), 3);
    match unit_condition(&operands[2]) {
        Condition::Compare {
            literal,
            match_case,
            ..
        } => {
            assert_eq!(literal.as_deref(), Some("JPEG"));
            assert_eq!(match_case, &None, "missing matchCase stays None");
        }
        other => panic!("{other:?}"),
    }
    match unit_condition(&operands[0]) {
        Condition::Compare { match_case, .. } => assert_eq!(match_case.as_deref(), Some("false")),
        other => panic!("{other:?}"),
    }
}

#[test]
fn and_with_three_operands_and_not() {
    let p = ok("and_three_not.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let Condition::And { operands } = unit_condition(config_constraint(&p)) else {
        panic!("and expected")
    };
    assert_eq!(operands.len(), 3);
    assert!(matches!(
        unit_condition(&operands[0]),
        Condition::Compare {
            comparison: Comparison::GreaterThanOrEqualTo,
            ..
        }
    ));
    let Condition::Not { operand } = unit_condition(&operands[2]) else {
        panic!("not expected")
    };
    assert!(matches!(
        unit_condition(operand),
        Condition::Compare {
            comparison: Comparison::EqualTo,
            ..
        }
    ));
}

#[test]
fn hash_list_null_and_empty_constraint() {
    let p = ok("hash_list_null.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let ConstraintKind::Hash { items } = &config_constraint(&p).kind else {
        panic!("hash expected")
    };
    assert_eq!(items.len(), 3);
    match &items[0].kind {
        ConstraintKind::Unit { key, condition } => {
            assert_eq!(key.as_deref(), Some("x"));
            assert_eq!(**condition, Condition::IsNull { text: None });
        }
        other => panic!("{other:?}"),
    }
    let ConstraintKind::List { items: list } = &items[1].kind else {
        panic!("list expected")
    };
    assert_eq!(unit_condition(&list[0]), &Condition::IsNull { text: None });
    assert_eq!(items[2].kind, ConstraintKind::Empty);
}

#[test]
fn version_up_log_both_spellings_empty_dropped() {
    let p = ok("version_up_logs.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    assert_eq!(
        p.profile.basic_info.version_up_logs,
        vec!["2020/01/01 first", "2020/02/01 second"]
    );
}

#[test]
fn library_name_or_path() {
    let p = ok("library_name_path.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let libs = &p.profile.language.as_ref().unwrap().targets[0].libraries;
    assert_eq!(libs[0].name.as_deref(), Some("byname"));
    assert_eq!(libs[1].name.as_deref(), Some("C:\\lib\\bypath.dll"));
}

#[test]
fn position_any_case_any_rtc_namespace_or_unqualified() {
    let p = ok("position_variants.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let d = &p.profile.data_ports;
    assert_eq!(d[0].position.as_deref(), Some("left"));
    assert_eq!(d[0].side(), PortSide::Left);
    assert_eq!(d[1].position.as_deref(), Some("BOTTOM"));
    assert_eq!(d[1].side(), PortSide::Bottom);
    assert_eq!(p.profile.service_ports[0].position.as_deref(), Some("Top"));
}

#[test]
fn empty_attributes_kept_and_dates_as_written() {
    let p = ok("empty_attrs_dates.xml");
    let b = &p.profile.basic_info;
    assert_eq!(b.name.as_deref(), Some(""));
    assert_eq!(b.description.as_deref(), Some(""));
    assert_eq!(
        b.creation_date.as_deref(),
        Some("2014-02-04T17:15:06+09:00")
    );
    assert_eq!(b.update_date.as_deref(), Some("2019-12-19T22:51:23.000"));
    let d = &p.profile.data_ports[0];
    assert_eq!(d.type_.as_deref(), Some(""));
    assert_eq!(d.interface_type.as_deref(), Some(""));
    assert_eq!(d.dataflow_type.as_deref(), Some(""));
    assert_eq!(d.subscription_type.as_deref(), Some(""));
    assert_eq!(d.unit.as_deref(), Some(""));
    assert_eq!(d.idl_file, None);
}

#[test]
fn other_prefixes_and_default_namespace() {
    let p = ok("other_prefixes.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let pr = &p.profile;
    assert_eq!(pr.id.as_deref(), Some("RTC:A:B:C:1"));
    assert_eq!(pr.basic_info.name.as_deref(), Some("Prefixed"));
    assert_eq!(pr.basic_info.comment.as_deref(), Some("note"));
    assert_eq!(
        pr.basic_info.doc.as_ref().unwrap().license.as_deref(),
        Some("BSD")
    );
    assert_eq!(pr.data_ports[0].position.as_deref(), Some("RIGHT"));
    assert_eq!(
        pr.data_ports[0].doc.as_ref().unwrap().occurrence.as_deref(),
        Some("on change")
    );
}

#[test]
fn event_port_with_events() {
    let p = ok("event_port.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    assert!(p.profile.is_fsm());
    let d = &p.profile.data_ports[0];
    assert_eq!(d.direction(), Some(PortDirection::Event));
    assert_eq!(d.events.len(), 2);
    let e = &d.events[0];
    assert_eq!(e.name.as_deref(), Some("go"));
    assert_eq!(e.type_.as_deref(), Some("TimedLong"));
    assert_eq!(e.source.as_deref(), Some("S1"));
    assert_eq!(e.target.as_deref(), Some("S2"));
    assert_eq!(e.condition.as_deref(), Some("x > 1"));
    let doc = e.doc.as_ref().unwrap();
    assert_eq!(doc.description.as_deref(), Some("go to S2"));
    assert_eq!(doc.occurrence.as_deref(), Some("once"));
    assert_eq!(d.events[1].source.as_deref(), Some("Init"));
    assert_eq!(d.events[1].pos, Pos::new(10, 9));
}

#[test]
fn unknown_attribute_and_element_kept_with_warning() {
    let p = ok("unknown_attr_elem.xml");
    let d = &p.profile.data_ports[0];
    // Unknown attribute on the port.
    let a = &d.extra[0];
    assert_eq!(a.kind, ExtraKind::Attribute);
    assert_eq!(a.name, "rtc:varnome");
    assert_eq!(a.namespace.as_deref(), Some(rtcdoc::parse::xml::NS_RTC));
    assert_eq!(a.value.as_deref(), Some("in1"));
    assert_eq!(a.pos, Pos::new(3, 86));
    // Unknown attribute on the doc goes to the doc.
    let doc = d.doc.as_ref().unwrap();
    assert_eq!(doc.extra[0].name, "rtcDoc:license");
    // Unknown element with its whole subtree.
    let e = &d.extra[1];
    assert_eq!(e.kind, ExtraKind::Element);
    assert_eq!(e.name, "rtc:Hint");
    assert_eq!(e.pos, Pos::new(5, 9));
    assert_eq!(e.value.as_deref(), Some("use  care"));
    assert_eq!(e.children[0].name, "rtc:level");
    assert_eq!(e.children[0].value.as_deref(), Some("2"));
    assert_eq!(e.children[1].name, "b");
    assert_eq!(e.children[1].value.as_deref(), Some("with"));

    assert_eq!(p.diagnostics.len(), 3, "{:?}", p.diagnostics);
    assert!(p
        .diagnostics
        .iter()
        .all(|d| d.severity == Severity::Warning));
    assert!(p.diagnostics.iter().all(|d| d.code == codes::UNKNOWN));
    assert_eq!(
        p.diagnostics[1].message,
        "unknown attribute `rtcDoc:license` on data port doc; kept as an extra property"
    );
    assert_eq!(p.diagnostics[1].pos, Some(Pos::new(4, 44)));
    assert_eq!(p.diagnostics[0].pos, Some(Pos::new(3, 86)));
    assert_eq!(p.diagnostics[2].pos, Some(Pos::new(5, 9)));
}

#[test]
fn foreign_namespace_kept() {
    let p = ok("foreign_namespace.xml");
    let b = &p.profile.basic_info;
    assert_eq!(b.name.as_deref(), Some("F"));
    assert_eq!(b.extra.len(), 2);
    assert_eq!(b.extra[0].name, "sem:tag");
    assert_eq!(
        b.extra[0].namespace.as_deref(),
        Some("http://openhri.net/RTCSemantics")
    );
    let e = &b.extra[1];
    assert_eq!(e.name, "sem:Semantics");
    assert_eq!(e.value.as_deref(), Some("text"));
    assert_eq!(e.children[0].name, "sem:kind");
    assert_eq!(p.diagnostics.len(), 2);
    assert!(p.diagnostics[1]
        .message
        .contains("(namespace http://openhri.net/RTCSemantics)"));
}

#[test]
fn missing_required_elements_are_not_errors() {
    let p = parse(
        br#"<RtcProfile xmlns="http://www.openrtp.org/namespaces/rtc"/>"#,
        "t",
        &Limits::default(),
    )
    .unwrap();
    assert_eq!(p.profile.basic_info.name, None);
    assert!(p.profile.actions.is_empty());
    assert!(p.diagnostics.is_empty());
}

#[test]
fn crlf_text_normalised_and_cdata() {
    let p = parse(
        &with_constraint(
            "<rtc:Constraint><rtc:ConstraintUnitType><rtc:propertyIsEqualTo><rtc:Literal>a\r\nb<![CDATA[<c>]]>&#13;</rtc:Literal></rtc:propertyIsEqualTo></rtc:ConstraintUnitType></rtc:Constraint>",
        ),
        "t",
        &Limits::default(),
    )
    .unwrap();
    match unit_condition(config_constraint(&p)) {
        Condition::Compare { literal, .. } => assert_eq!(literal.as_deref(), Some("a\nb<c>\r")),
        other => panic!("{other:?}"),
    }
}

// --- errors ------------------------------------------------------------------------------------

#[test]
fn error_unclosed_element_truncated_file() {
    let d = err("malformed_unclosed.xml");
    assert_err(&d, codes::MALFORMED, 3, 5);
    assert!(
        d.message.contains("unclosed element `rtc:BasicInfo`"),
        "{d}"
    );
}

#[test]
fn error_unclosed_tag() {
    let d = err_bytes(b"<rtc:RtcProfile xmlns:rtc='x'>\n  <rtc:BasicInfo rtc:name='a'");
    assert_eq!(d.code, codes::MALFORMED);
    assert_eq!(d.pos, Some(Pos::new(2, 3)), "{d}");
    assert!(d.message.contains("unclosed tag"), "{d}");
}

#[test]
fn error_mismatched_end_tag() {
    let d = err("malformed_mismatched.xml");
    assert_err(&d, codes::MALFORMED, 4, 5);
    assert!(d.message.contains("mismatched end tag"), "{d}");
    assert!(d.message.contains("`</rtc:BasicInfo>`"), "{d}");
}

#[test]
fn error_garbage() {
    let d = err("malformed_garbage.xml");
    assert_err(&d, codes::MALFORMED, 5, 1);
    assert!(d.message.contains("text outside the root element"), "{d}");
    let d = err_bytes(b"\n  \x01 garbage <<< >>>");
    assert_err(&d, codes::MALFORMED, 2, 3);
    let d = err_bytes(b"<a><<<b>>></a>");
    assert_err(&d, codes::MALFORMED, 1, 4);
    let d = err_bytes(b"");
    assert_eq!(d.code, codes::MALFORMED);
}

#[test]
fn error_root_not_profile() {
    let d = err("system_profile.xml");
    assert_err(&d, codes::SHAPE, 3, 1);
}

#[test]
fn error_entity_declaration_billion_laughs() {
    let t = Instant::now();
    let d = err("billion_laughs.xml");
    assert_err(&d, codes::ENTITY, 2, 1);
    assert!(d.message.contains("entity declarations are not allowed"));
    assert!(t.elapsed() < Duration::from_secs(1));
}

#[test]
fn error_undefined_entity() {
    let d = err("undefined_entity.xml");
    assert_err(&d, codes::ENTITY, 3, 50);
    assert!(d.message.contains("&nbsp;"), "{d}");
    // In text too.
    let d = err_bytes(b"<a>\n x &foo; y</a>");
    assert_err(&d, codes::ENTITY, 2, 4);
}

#[test]
fn error_too_deep_fast() {
    let n = 1_000_000;
    let mut s = String::with_capacity(n * 7 + 100);
    s.push_str("<RtcProfile xmlns=\"http://www.openrtp.org/namespaces/rtc\">\n");
    for _ in 0..n {
        s.push_str("<a>");
    }
    let t = Instant::now();
    let d = err_bytes(s.as_bytes());
    assert!(t.elapsed() < Duration::from_secs(1), "{:?}", t.elapsed());
    // Root is depth 1; the 64th `<a>` would be depth 65.
    assert_err(&d, codes::TOO_DEEP, 2, 63 * 3 + 1);
    let limits = Limits {
        max_depth: 3,
        ..Limits::default()
    };
    let e = parse(b"<a><b><c><d/></c></b></a>", "t", &limits).unwrap_err();
    assert_err(&e, codes::TOO_DEEP, 1, 10);
}

#[test]
fn many_attributes_stay_linear() {
    // quick-xml's duplicate check compares each attribute with all earlier ones; 100,000
    // attributes on one tag took minutes. The duplicate at the end is still found.
    let n = 100_000;
    let mut s = String::from(
        "<rtc:RtcProfile xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\">\n<rtc:BasicInfo",
    );
    for i in 0..n {
        s.push_str(&format!(" a{i}=\"x\""));
    }
    s.push_str(" a7=\"again\"/></rtc:RtcProfile>\n");
    let t = Instant::now();
    let d = err_bytes(s.as_bytes());
    assert!(t.elapsed() < Duration::from_secs(10), "{:?}", t.elapsed());
    assert_err(&d, codes::MALFORMED, 2, 1);
    assert!(d.message.contains("written twice"), "{}", d.message);
}

#[test]
fn error_invalid_utf8() {
    let mut b =
        b"<?xml version=\"1.0\"?>\n<rtc:RtcProfile xmlns:rtc=\"x\">\n  <a>h\xC3\xA9".to_vec();
    b.extend_from_slice(b"\xFF</a></rtc:RtcProfile>");
    let d = err_bytes(&b);
    assert_err(&d, codes::ENCODING, 3, 8);
}

#[test]
fn error_unknown_encoding_label() {
    let d = err_bytes(b"<?xml version=\"1.0\" encoding=\"klingon\"?><a/>");
    assert_err(&d, codes::ENCODING, 1, 31);
    assert!(d.message.contains("unknown encoding `klingon`"), "{d}");
}

fn japanese_profile(label: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"{label}\"?>\n<rtc:RtcProfile xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\" xmlns:rtcDoc=\"http://www.openrtp.org/namespaces/rtc_doc\">\n<rtc:BasicInfo rtc:name=\"カメラ\"><rtcDoc:Doc rtcDoc:description=\"日本語の説明\"/></rtc:BasicInfo></rtc:RtcProfile>"
    )
}

#[test]
fn shift_jis_decoded() {
    let text = japanese_profile("Shift_JIS");
    let (bytes, _, bad) = encoding_rs::SHIFT_JIS.encode(&text);
    assert!(!bad);
    assert!(std::str::from_utf8(&bytes).is_err(), "really not UTF-8");
    let p = parse(&bytes, "sjis.xml", &Limits::default()).unwrap();
    assert_eq!(p.profile.basic_info.name.as_deref(), Some("カメラ"));
    assert_eq!(
        p.profile.basic_info.doc.unwrap().description.as_deref(),
        Some("日本語の説明")
    );
    assert!(is_profile(&bytes));
}

#[test]
fn euc_jp_decoded() {
    let text = japanese_profile("EUC-JP");
    let (bytes, _, bad) = encoding_rs::EUC_JP.encode(&text);
    assert!(!bad);
    let p = parse(&bytes, "euc.xml", &Limits::default()).unwrap();
    assert_eq!(p.profile.basic_info.name.as_deref(), Some("カメラ"));
    // Column counts characters of the decoded text.
    assert_eq!(p.profile.basic_info.doc.unwrap().pos, Pos::new(3, 31));
}

#[test]
fn bad_shift_jis_byte_reports_position() {
    let mut bytes = encoding_rs::SHIFT_JIS
        .encode("<?xml version=\"1.0\" encoding=\"Shift_JIS\"?>\n<a>日本")
        .0
        .into_owned();
    bytes.extend_from_slice(b"\x81\x20</a>");
    let d = err_bytes(&bytes);
    assert_err(&d, codes::ENCODING, 2, 6);
}

#[test]
fn bom_accepted() {
    let mut b = b"\xEF\xBB\xBF".to_vec();
    b.extend_from_slice(&fixture("minimal.xml"));
    let p = parse(&b, "bom.xml", &Limits::default()).unwrap();
    assert_eq!(p.profile.basic_info.name.as_deref(), Some("Sample"));
    assert_eq!(p.profile.pos, Pos::new(2, 1));
    assert!(is_profile(&b));
    // UTF-16 with BOM too.
    let text = String::from_utf8(fixture("minimal.xml")).unwrap();
    let mut u16 = vec![0xFF, 0xFE];
    for unit in text.encode_utf16() {
        u16.extend_from_slice(&unit.to_le_bytes());
    }
    let p = parse(&u16, "utf16.xml", &Limits::default()).unwrap();
    assert_eq!(p.profile.basic_info.name.as_deref(), Some("Sample"));
    assert!(is_profile(&u16));
}

// --- corpus ------------------------------------------------------------------------------------

fn corpus_dir() -> Option<PathBuf> {
    [
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus"),
        PathBuf::from("/work/shared/corpus"),
    ]
    .into_iter()
    .find(|p| p.is_dir())
}

fn xml_files(dir: &Path) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = walkdir::WalkDir::new(dir)
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file())
        .map(|e| e.into_path())
        .filter(|p| {
            p.extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
        })
        .collect();
    out.sort();
    out
}

/// The message with backticked names kept but positions dropped: the "kind" of a warning.
fn message_kind(d: &Diagnostic) -> String {
    d.message.clone()
}

#[test]
fn corpus_rtc_xml_parses_without_errors() {
    let Some(dir) = corpus_dir() else {
        println!("skipped: ../shared/corpus not present");
        return;
    };
    let files = xml_files(&dir.join("rtc-xml"));
    let (mut parsed, mut skipped, mut warnings) = (0, 0, 0);
    let mut kinds: BTreeMap<String, usize> = BTreeMap::new();
    let mut errors = Vec::new();
    for f in &files {
        let bytes = std::fs::read(f).unwrap();
        if !is_profile(&bytes) {
            skipped += 1;
            continue;
        }
        let t = Instant::now();
        match parse(&bytes, &f.display().to_string(), &Limits::default()) {
            Ok(p) => {
                parsed += 1;
                for d in &p.diagnostics {
                    // Warnings, and the one summary note of empty unknown attributes.
                    if d.code == codes::EMPTY_UNKNOWN {
                        assert_eq!(d.severity, Severity::Info);
                        continue;
                    }
                    assert_eq!(d.severity, Severity::Warning);
                    warnings += 1;
                    *kinds.entry(message_kind(d)).or_default() += 1;
                }
            }
            Err(d) => errors.push(d.to_string()),
        }
        assert!(t.elapsed() < Duration::from_secs(2));
    }
    println!(
        "corpus rtc-xml: {} files, {parsed} parsed, {skipped} not profiles, {} errors, {warnings} warnings",
        files.len(),
        errors.len()
    );
    for (k, n) in &kinds {
        println!("  {n:5}  {k}");
    }
    assert!(errors.is_empty(), "{errors:#?}");
    assert!(parsed > 100);
}

#[test]
fn corpus_rts_xml_are_not_profiles() {
    let Some(dir) = corpus_dir() else {
        println!("skipped: ../shared/corpus not present");
        return;
    };
    let files = xml_files(&dir.join("rts-xml"));
    for f in &files {
        let bytes = std::fs::read(f).unwrap();
        assert!(!is_profile(&bytes), "{}", f.display());
    }
    println!("corpus rts-xml: {} files, none is a profile", files.len());
}

// --- robustness ----------------------------------------------------------------------------------

mod robustness {
    use super::*;
    use proptest::prelude::*;

    fn timed(bytes: &[u8]) {
        let t = Instant::now();
        let _ = is_profile(bytes);
        let _ = parse(bytes, "fuzz.xml", &Limits::default());
        assert!(
            t.elapsed() < Duration::from_secs(1),
            "took {:?}",
            t.elapsed()
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

        #[test]
        fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..2048)) {
            timed(&bytes);
        }

        #[test]
        fn mutated_profile_never_panics(
            edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..16)
        ) {
            let mut bytes = fixture("minimal.xml");
            for (at, byte, op) in edits {
                if bytes.is_empty() { break; }
                let i = at.index(bytes.len());
                match op {
                    0 => bytes[i] = byte,
                    1 => { bytes.remove(i); }
                    _ => bytes.insert(i, byte),
                }
            }
            timed(&bytes);
        }

        #[test]
        fn truncated_profile_never_panics(cut in 0usize..5000) {
            let bytes = fixture("minimal.xml");
            let cut = cut.min(bytes.len());
            timed(&bytes[..cut]);
        }
    }
}

#[test]
fn stray_text_kept_as_extra() {
    let p = parse(
        b"<rtc:RtcProfile xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\">\n<rtc:BasicInfo rtc:name=\"a\">  hello  </rtc:BasicInfo></rtc:RtcProfile>",
        "t",
        &Limits::default(),
    )
    .unwrap();
    let e = &p.profile.basic_info.extra[0];
    assert_eq!(e.name, "#text");
    assert_eq!(e.value.as_deref(), Some("  hello  "));
    assert_eq!(e.pos, Pos::new(2, 31));
    assert_eq!(p.diagnostics[0].code, codes::UNKNOWN);
    assert_eq!(p.diagnostics[0].pos, Some(Pos::new(2, 31)));
}

/// Each node and its doc are named in messages: the action's from a table made once, the
/// others given with the node (none is formatted per node any more).
#[test]
fn unknown_attributes_name_their_node_and_its_doc() {
    let xml = br#"<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcDoc="http://www.openrtp.org/namespaces/rtc_doc">
<rtc:Actions><rtc:OnExecute rtc:implemented="true" rtc:x="1"><rtc:Doc rtcDoc:y="2"/></rtc:OnExecute></rtc:Actions>
<rtc:ConfigurationSet><rtc:Configuration rtc:name="c"><rtc:Doc rtcDoc:z="3"/></rtc:Configuration></rtc:ConfigurationSet>
<rtc:ServicePorts rtc:name="s"><rtc:Doc rtcDoc:w="4"/><rtc:ServiceInterface rtc:name="i"><rtc:Doc rtcDoc:v="5"/></rtc:ServiceInterface></rtc:ServicePorts>
</rtc:RtcProfile>"#;
    let p = match parse(xml, "names.xml", &Limits::default()) {
        Ok(p) => p,
        Err(d) => panic!("should parse: {d}"),
    };
    let messages: Vec<&str> = p.diagnostics.iter().map(|d| d.message.as_str()).collect();
    for (attr, on) in [
        ("rtc:x", "action OnExecute"),
        ("rtcDoc:y", "action OnExecute doc"),
        ("rtcDoc:z", "configuration doc"),
        ("rtcDoc:w", "service port doc"),
        ("rtcDoc:v", "service interface doc"),
    ] {
        let want = format!("unknown attribute `{attr}` on {on}; kept as an extra property");
        assert!(
            messages.contains(&want.as_str()),
            "{want} not in {messages:#?}"
        );
    }
}
