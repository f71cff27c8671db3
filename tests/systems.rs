//! RT System profiles as documented pages (issue 16): loading into the catalogue, links from
//! instances to components and from connector ends to ports, the pages, the other outputs and
//! the check rules.

mod common;

use rtcdoc::build::{self, LoadOptions};
use rtcdoc::catalog::systems::{MatchKind, PortLink};
use rtcdoc::catalog::Catalog;
use std::path::PathBuf;

fn site_fixture() -> PathBuf {
    common::root().join("tests/fixtures/systems/site")
}

fn load(path: &std::path::Path) -> Catalog {
    build::load(path, &LoadOptions::default())
        .expect("load")
        .catalog
}

#[test]
fn systems_are_loaded_and_linked() {
    let cat = load(&site_fixture());
    assert_eq!(cat.components.len(), 2);
    assert_eq!(cat.systems.len(), 1, "the system is read, not skipped");
    let s = &cat.systems[0];
    assert_eq!(s.source, "system/PatrolSystem.xml");
    assert_eq!(s.slug, "patrolsystem");
    assert_eq!(s.profile.components.len(), 2);
    // Camera0 → Camera (same version), Planner0 → Planner (1.2.0 named, 1.1.0 in the catalogue).
    let cam = &s.instances[0];
    assert_eq!(cam.component.as_deref(), Some("camera"));
    assert_eq!(cam.matched_by, Some(MatchKind::Exact));
    assert_eq!(cam.version_drift, None);
    let pl = &s.instances[1];
    assert_eq!(pl.component.as_deref(), Some("planner"));
    assert_eq!(pl.version_drift.as_deref(), Some("1.1.0"));
    // Connector ends resolve to the ports of the profiles, `Camera0.image` and `image` alike.
    let d = &s.data_connectors[0];
    assert_eq!(d.source.instance, Some(0));
    assert!(matches!(&d.source.port, Some(PortLink::Data { name, .. }) if name == "image"));
    assert_eq!(d.target.instance, Some(1));
    assert!(matches!(&d.target.port, Some(PortLink::Data { name, .. }) if name == "image"));
    let sc = &s.service_connectors[0];
    assert!(matches!(&sc.source.port, Some(PortLink::Service { name, .. }) if name == "camera"));
    assert!(matches!(&sc.target.port, Some(PortLink::Service { name, .. }) if name == "control"));
    // No "not a component profile" warning for it any more.
    assert!(
        !cat.diagnostics.iter().any(|d| d.code == "RTC012"),
        "{:?}",
        cat.diagnostics
    );
    // Who uses what.
    let ci = cat.components.iter().position(|c| c.slug == "planner").unwrap();
    let using = cat.systems_using(ci);
    assert_eq!(using.len(), 1);
    assert_eq!(using[0].1, vec!["Planner0"]);
    assert_eq!(cat.connectors_carrying("RTC::CameraImage").len(), 1);
    assert_eq!(cat.connectors_carrying("IDL:RTC/CameraImage:1.0").len(), 1);
    assert!(cat.connectors_carrying("RTC::TimedLong").is_empty());
}

#[test]
fn a_system_alone_is_something_to_document() {
    let cat = load(&site_fixture().join("system/PatrolSystem.xml"));
    assert_eq!(cat.systems.len(), 1);
    assert!(cat.components.is_empty());
    assert!(cat.systems[0].instances.iter().all(|i| i.component.is_none()));
    // The ports still come from the system file and its connectors.
    let ports = cat.instance_ports(&cat.systems[0], 1);
    let names: Vec<&str> = ports.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["image", "path", "camera"]);
}
