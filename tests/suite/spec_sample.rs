//! The spec's 9.2 sample, written once as XML and once as YAML, reads to the same model.

use crate::common;
use rtcdoc::model::{Extra, Profile};
use rtcdoc::parse::{self, Limits, SourceFormat};

fn read(rel: &str, format: SourceFormat) -> Profile {
    let path = common::root().join("tests/fixtures/spec-9.2").join(rel);
    let bytes = std::fs::read(&path).unwrap();
    let parsed = parse::parse(format, &bytes, rel, &Limits::default()).unwrap();
    assert!(
        parsed.diagnostics.is_empty(),
        "{rel}: {:#?}",
        parsed.diagnostics
    );
    parsed.profile
}

/// Positions differ between the two files by nature; everything else must agree.
fn without_positions(p: &Profile) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                m.remove("pos");
                m.remove("actionsPos");
                m.values_mut().for_each(strip);
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v = serde_json::to_value(p).unwrap();
    strip(&mut v);
    v
}

#[test]
fn xml_and_yaml_forms_of_the_spec_sample_are_equal() {
    let x = read("RTC.xml", SourceFormat::Xml);
    let y = read("RTC.yaml", SourceFormat::Yaml);
    let (xv, yv) = (without_positions(&x), without_positions(&y));
    if xv != yv {
        // Point at the first difference rather than dumping two whole models.
        let xs = serde_json::to_string_pretty(&xv).unwrap();
        let ys = serde_json::to_string_pretty(&yv).unwrap();
        let line = xs
            .lines()
            .zip(ys.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(0);
        let ctx = |s: &str| {
            s.lines()
                .skip(line.saturating_sub(8))
                .take(12)
                .collect::<Vec<_>>()
                .join("\n")
        };
        panic!(
            "models differ near line {line}:\nXML:\n{}\nYAML:\n{}",
            ctx(&xs),
            ctx(&ys)
        );
    }
    // And the sample really is the rich one: all 14 actions, ports, constraints, docs.
    assert_eq!(x.actions.len(), 14);
    assert!(!x.data_ports.is_empty() && !x.service_ports.is_empty());
    assert!(x.configurations().iter().any(|c| c.constraint.is_some()));
    let no_extras: Vec<(String, &Extra)> = x.all_extras();
    assert!(no_extras.is_empty());
}
