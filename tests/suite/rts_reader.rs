//! The RT System profile reader (`parse::rts`): every element of the model from hand-written
//! XML and YAML fixtures, the oddities of real files, unknown content kept, positions, hostile
//! input, XML and YAML giving the same model, and — when `../shared/corpus` is present — the 9
//! real RTSystemEditor files read with no lost value and no RTC006 warning.

use rtcdoc::diagnostic::{codes, Diagnostic, Severity};
use rtcdoc::model::system::*;
use rtcdoc::model::{Extra, ExtraKind, Pos};
use rtcdoc::parse::rts::{is_system, parse, ParsedSystem};
use rtcdoc::parse::{Limits, SourceFormat};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> Vec<u8> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/rts")
        .join(name);
    std::fs::read(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

fn format_of(name: &str) -> SourceFormat {
    if name.ends_with(".xml") {
        SourceFormat::Xml
    } else {
        SourceFormat::Yaml
    }
}

fn read(name: &str) -> ParsedSystem {
    let bytes = fixture(name);
    parse(format_of(name), &bytes, name, &Limits::default())
        .unwrap_or_else(|d| panic!("{name}: {d}"))
}

fn read_str(format: SourceFormat, text: &str) -> Result<ParsedSystem, Diagnostic> {
    parse(format, text.as_bytes(), "t", &Limits::default())
}

fn codes_of(d: &[Diagnostic]) -> Vec<&'static str> {
    d.iter().map(|d| d.code).collect()
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

fn corpus_files() -> Option<Vec<PathBuf>> {
    let dir = corpus_dir()?.join("rts-xml");
    let mut out: Vec<PathBuf> = walkdir::WalkDir::new(dir)
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file())
        .map(|e| e.into_path())
        .filter(|p| p.extension().is_some_and(|e| e == "xml"))
        .collect();
    out.sort();
    Some(out)
}

/// Every attribute value and non-blank text of an XML document, read with quick-xml directly
/// (independent of the reader under test); `xsi:*` and `xmlns*` attributes are plumbing.
fn xml_values(bytes: &[u8]) -> Vec<String> {
    use quick_xml::events::Event;
    let mut r = quick_xml::Reader::from_reader(bytes);
    let mut out = Vec::new();
    let mut buf = Vec::new();
    let mut text = String::new();
    let flush = |text: &mut String, out: &mut Vec<String>| {
        if !text.trim().is_empty() {
            out.push(std::mem::take(text));
        }
        text.clear();
    };
    loop {
        match r.read_event_into(&mut buf) {
            Ok(Event::Start(e)) | Ok(Event::Empty(e)) => {
                flush(&mut text, &mut out);
                for a in e.attributes().flatten() {
                    let k = String::from_utf8_lossy(a.key.as_ref()).to_string();
                    if k.starts_with("xsi:") || k.starts_with("xmlns") {
                        continue;
                    }
                    let v = a
                        .unescape_value()
                        .map(|v| v.to_string())
                        .unwrap_or_default();
                    if !v.trim().is_empty() {
                        out.push(v);
                    }
                }
            }
            Ok(Event::End(_)) => flush(&mut text, &mut out),
            Ok(Event::Text(t)) => text.push_str(&t.decode().unwrap_or_default()),
            Ok(Event::GeneralRef(g)) => text.push_str(match &*g {
                b"lt" => "<",
                b"gt" => ">",
                b"amp" => "&",
                b"quot" => "\"",
                _ => "'",
            }),
            Ok(Event::Eof) => break,
            Ok(_) => {}
            Err(e) => panic!("corpus file is not XML: {e}"),
        }
        buf.clear();
    }
    out
}

/// Every string in a JSON value, with how often it occurs.
fn json_strings(v: &serde_json::Value, out: &mut HashMap<String, usize>) {
    match v {
        serde_json::Value::String(s) => *out.entry(s.trim().to_string()).or_default() += 1,
        serde_json::Value::Array(a) => a.iter().for_each(|v| json_strings(v, out)),
        serde_json::Value::Object(o) => o.values().for_each(|v| json_strings(v, out)),
        _ => {}
    }
}

/// The values of a file the model's JSON does not hold as often as the file does: a value
/// written twice must be kept twice (the model adds derived strings, never fewer).
fn lost_values(values: &[String], model: &impl serde::Serialize) -> Vec<String> {
    let mut pool = HashMap::new();
    json_strings(&serde_json::to_value(model).unwrap(), &mut pool);
    let mut lost = Vec::new();
    for v in values {
        match pool.get_mut(v.trim()) {
            Some(n) if *n > 0 => *n -= 1,
            _ => lost.push(v.clone()),
        }
    }
    lost
}

#[test]
fn corpus_systems_are_read_whole_without_unknown_warnings() {
    let Some(files) = corpus_files() else {
        println!("skipped: ../shared/corpus not present");
        return;
    };
    assert_eq!(files.len(), 9, "the corpus has 9 RT System profiles");
    let mut total_values = 0;
    for f in &files {
        let bytes = std::fs::read(f).unwrap();
        assert!(is_system(&bytes), "{}", f.display());
        let name = f.display().to_string();
        let started = std::time::Instant::now();
        let p = parse(SourceFormat::Xml, &bytes, &name, &Limits::default())
            .unwrap_or_else(|d| panic!("{d}"));
        let took = started.elapsed();
        assert!(took < std::time::Duration::from_secs(2), "{name}: {took:?}");
        let s = &p.system;
        println!(
            "{} ({} bytes, {took:?}): id {:?}, {} instances, {} data + {} service connectors, {} private properties, warnings {:?}",
            f.strip_prefix(corpus_dir().unwrap()).unwrap().display(),
            bytes.len(),
            s.id.as_deref().unwrap_or(""),
            s.components.len(),
            s.data_port_connectors.len(),
            s.service_port_connectors.len(),
            s.private_properties(),
            p.diagnostics.iter().map(|d| d.to_string()).collect::<Vec<_>>()
        );
        assert!(
            !p.diagnostics.iter().any(|d| d.code == codes::UNKNOWN),
            "{name}: RTC006 for schema content: {:?}",
            p.diagnostics
        );
        assert!(!s.components.is_empty(), "{name}");
        // Nothing lost: every value of the file is a string of the model's JSON.
        let values = xml_values(&bytes);
        total_values += values.len();
        let lost = lost_values(&values, s);
        assert!(lost.is_empty(), "{name}: lost {lost:?}");
        // Every instance's component id is parsed, and every connector end has a port name.
        for c in &s.components {
            assert!(c.id_parts.is_some(), "{name}: {:?}", c.id);
        }
        for d in &s.data_port_connectors {
            for e in [&d.source, &d.target] {
                let e = e.as_ref().expect("both ends");
                let short = e.short_name.as_deref().unwrap();
                assert!(!short.contains('.'), "{name}: {short}");
            }
        }
    }
    println!(
        "corpus rts-xml: {} files, {total_values} values, none lost",
        files.len()
    );
}

// --- every element ------------------------------------------------------------------------------

fn t(s: &Option<compact_str::CompactString>) -> &str {
    s.as_deref().unwrap_or("<none>")
}

#[test]
fn xml_reads_every_element_of_the_model() {
    let p = read("full.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let s = &p.system;
    assert_eq!(t(&s.id), "RTSystem:Example Lab:PatrolSystem:2.1.0");
    let id = s.id_parts.as_ref().unwrap();
    assert_eq!(
        (t(&id.vendor), t(&id.name), t(&id.version), id.form),
        ("Example Lab", "PatrolSystem", "2.1.0", IdForm::Standard)
    );
    assert_eq!(s.name(), "PatrolSystem");
    assert_eq!(t(&s.version), "0.2");
    assert_eq!(t(&s.abstract_), "A patrol robot: camera, planner, base");
    assert_eq!(t(&s.creation_date), "2024-01-02T03:04:05");
    assert_eq!(t(&s.update_date), "2024-02-03T04:05:06");
    assert_eq!(t(&s.comment), "Hand-written test system");
    assert_eq!(
        s.version_up_logs,
        ["2.0: planner added", "2.1: push interval"]
    );
    assert_eq!(s.properties.len(), 2);
    assert!(!s.properties[0].private);
    assert!(s.properties[1].private, "naming.host is host data");
    assert_eq!(s.systems.len(), 1);
    assert_eq!(t(&s.systems[0].path), "sub/Arm.xml");

    // Instances.
    assert_eq!(s.components.len(), 2);
    let cam = s.component("Camera0").unwrap();
    assert_eq!(t(&cam.id), "RTC:Example Lab:Sensor:Camera:1.0.0");
    let cid = cam.id_parts.as_ref().unwrap();
    assert_eq!(
        (
            t(&cid.vendor),
            t(&cid.category),
            t(&cid.name),
            t(&cid.version)
        ),
        ("Example Lab", "Sensor", "Camera", "1.0.0")
    );
    assert_eq!(t(&cam.path_uri), "localhost:2809/Camera0.rtc");
    assert_eq!(t(&cam.active_configuration_set), "outdoor");
    assert_eq!(cam.required(), Some(true));
    assert_eq!(t(&cam.composite_type), "None");
    assert_eq!(t(&cam.comment), "front camera");
    assert_eq!(t(&cam.visible), "true");
    assert_eq!(cam.data_ports.len(), 1);
    let img = &cam.data_ports[0];
    assert_eq!(
        (t(&img.name), t(&img.short_name)),
        ("Camera0.image", "image")
    );
    assert_eq!((t(&img.comment), t(&img.visible)), ("frames", "true"));
    assert_eq!(t(&img.properties[0].value), "DataOutPort");
    assert_eq!(t(&cam.service_ports[0].short_name), "control");
    assert_eq!(t(&cam.service_ports[0].visible), "false");
    // Configuration sets, pseudo ones marked.
    let ids: Vec<(&str, bool)> = cam
        .configuration_sets
        .iter()
        .map(|c| (t(&c.id), c.pseudo))
        .collect();
    assert_eq!(
        ids,
        [
            ("outdoor", false),
            ("__widget__", true),
            ("__constraints__", true)
        ]
    );
    let active = cam.active_set().unwrap();
    let data: Vec<(&str, &str)> = active
        .configuration_data
        .iter()
        .map(|d| (t(&d.name), t(&d.data)))
        .collect();
    assert_eq!(data, [("exposure", "0.02"), ("gain", "3")]);
    assert_eq!(
        t(&cam.configuration_sets[2].configuration_data[0].data),
        "0<=x<=1"
    );
    // Execution contexts with participants and properties.
    let ec = &cam.execution_contexts[0];
    assert_eq!(
        (t(&ec.id), t(&ec.kind), t(&ec.rate)),
        ("0", "PERIODIC", "30.0")
    );
    assert_eq!(t(&ec.participants[0].instance_name), "Planner0");
    assert_eq!(t(&ec.properties[0].name), "sync_transition");
    // Location, lower-case direction accepted.
    let loc = cam.location.as_ref().unwrap();
    assert_eq!(
        (
            t(&loc.x),
            t(&loc.y),
            t(&loc.height),
            t(&loc.width),
            t(&loc.direction)
        ),
        ("40", "60", "80", "120", "down")
    );
    assert_eq!(loc.direction_kind(), Some(LocationDirection::Down));
    assert_eq!(loc.xy(), Some((40, 60)));
    // Host data flagged.
    let private: Vec<(&str, bool)> = cam
        .properties
        .iter()
        .map(|p| (t(&p.name), p.private))
        .collect();
    assert_eq!(
        private,
        [
            ("IOR", true),
            ("os.hostname", true),
            ("corba.endpoints", true),
            ("exec_cxt.periodic.rate", false)
        ]
    );
    assert_eq!(s.private_properties(), 4);

    let planner = s.component("Planner0").unwrap();
    assert_eq!(planner.required(), Some(false));
    assert_eq!(t(&planner.composite_type), "PeriodicECShared");
    let names: Vec<(&str, &str)> = planner
        .data_ports
        .iter()
        .map(|p| (t(&p.name), t(&p.short_name)))
        .collect();
    assert_eq!(names, [("image", "image"), ("path", "path")]);
    assert_eq!(t(&planner.execution_contexts[0].kind), "EVENT_DRIVEN");
    assert_eq!(planner.execution_contexts[0].rate, None);
    assert_eq!(planner.participants.len(), 1);
    assert_eq!(t(&planner.participants[0].instance_name), "Camera0");
    assert_eq!(
        planner.location.as_ref().unwrap().direction_kind(),
        Some(LocationDirection::Right)
    );

    // Groups.
    assert_eq!(t(&s.groups[0].group_id), "vision");
    assert_eq!(s.groups[0].members.len(), 2);

    // Data connector: repository-id type with its scoped name, both ends normalised.
    let d = &s.data_port_connectors[0];
    assert_eq!(t(&d.connector_id), "c1-image");
    assert_eq!(t(&d.name), "Camera0.image_Planner0.image");
    assert_eq!(t(&d.data_type), "IDL:RTC/CameraImage:1.0");
    assert_eq!(t(&d.data_type_scoped), "RTC::CameraImage");
    assert_eq!(
        (
            t(&d.interface_type),
            t(&d.dataflow_type),
            t(&d.subscription_type),
            t(&d.push_interval)
        ),
        ("corba_cdr", "push", "periodic", "0.5")
    );
    assert_eq!(
        (t(&d.comment), t(&d.visible)),
        ("frames to planner", "true")
    );
    let src = d.source.as_ref().unwrap();
    assert_eq!(
        (
            t(&src.component_id),
            t(&src.instance_name),
            t(&src.port_name),
            t(&src.short_name)
        ),
        (
            "RTC:Example Lab:Sensor:Camera:1.0.0",
            "Camera0",
            "Camera0.image",
            "image"
        )
    );
    assert_eq!(t(&src.properties[0].name), "COMPONENT_PATH_ID");
    let dst = d.target.as_ref().unwrap();
    assert_eq!((t(&dst.port_name), t(&dst.short_name)), ("image", "image"));
    assert_eq!(t(&d.properties[0].value), "new");

    // Service connector.
    let c = &s.service_port_connectors[0];
    assert_eq!(
        (t(&c.connector_id), t(&c.name), t(&c.trans_method)),
        ("c2-control", "Planner0.camera_Camera0.control", "corba")
    );
    assert_eq!(t(&c.source.as_ref().unwrap().short_name), "camera");
    assert_eq!(t(&c.target.as_ref().unwrap().short_name), "control");
    assert_eq!(t(&c.properties[0].value), "strict");

    // The seven orders, in their fixed order.
    let kinds: Vec<OrderKind> = s.orders.iter().map(|o| o.kind).collect();
    assert_eq!(kinds, OrderKind::ALL);
    let start = s.order(OrderKind::StartUp).unwrap();
    assert_eq!(start.targets.len(), 2);
    let first = &start.targets[0];
    assert_eq!(t(&first.sequence), "1");
    let tc = first.target_component.as_ref().unwrap();
    assert_eq!(
        (t(&tc.component_id), t(&tc.instance_name), t(&tc.id)),
        ("RTC:Example Lab:Sensor:Camera:1.0.0", "Camera0", "0")
    );
    assert_eq!(t(&first.wait_time.as_ref().unwrap().wait_time), "1000");
    assert!(first.preceding.is_none());
    assert_eq!(t(&first.properties[0].value), "camera first");
    let pre = start.targets[1].preceding.as_ref().unwrap();
    assert_eq!((t(&pre.timeout), t(&pre.sending_timing)), ("500", "SYNC"));
    assert_eq!(t(&pre.preceding_components[0].instance_name), "Camera0");
    let waits: Vec<&str> = s.orders[1..]
        .iter()
        .map(|o| t(&o.targets[0].wait_time.as_ref().unwrap().wait_time))
        .collect();
    assert_eq!(waits, ["200", "10", "20", "30", "40", "50"]);
}

/// The model as JSON without positions (YAML and XML positions differ by nature).
fn without_pos(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(o) => {
            o.remove("pos");
            o.values_mut().for_each(without_pos);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(without_pos),
        _ => {}
    }
}

#[test]
fn xml_and_yaml_give_the_same_model() {
    let x = read("full.xml");
    let y = read("full.yaml");
    assert!(y.diagnostics.is_empty(), "{:?}", y.diagnostics);
    let mut xj = serde_json::to_value(&x.system).unwrap();
    let mut yj = serde_json::to_value(&y.system).unwrap();
    without_pos(&mut xj);
    without_pos(&mut yj);
    if xj != yj {
        let xs = serde_json::to_string_pretty(&xj).unwrap();
        let ys = serde_json::to_string_pretty(&yj).unwrap();
        let first = xs
            .lines()
            .zip(ys.lines())
            .enumerate()
            .find(|(_, (a, b))| a != b);
        panic!("XML and YAML models differ; first difference: {first:?}");
    }
}

#[test]
fn model_round_trips_through_json() {
    for name in [
        "full.xml",
        "full.yaml",
        "oddities.xml",
        "unknown.xml",
        "unknown.yaml",
    ] {
        let s = read(name).system;
        let json = serde_json::to_string(&s).unwrap();
        let back: RtSystem = serde_json::from_str(&json).unwrap();
        assert_eq!(back, s, "{name}");
    }
}

#[test]
fn positions_point_at_the_nodes() {
    let s = read("full.xml").system;
    assert_eq!(s.pos, Pos::new(2, 1));
    assert_eq!(s.components[0].pos, Pos::new(3, 5));
    assert_eq!(s.components[0].data_ports[0].pos, Pos::new(4, 9));
    assert_eq!(
        s.components[0].data_ports[0].properties[0].pos,
        Pos::new(5, 13)
    );
    assert_eq!(
        s.components[0].configuration_sets[0].configuration_data[1].pos,
        Pos::new(10, 13)
    );
    assert_eq!(
        s.components[0].location.as_ref().unwrap().pos,
        Pos::new(22, 9)
    );
    assert_eq!(s.data_port_connectors[0].pos, Pos::new(45, 5));
    assert_eq!(
        s.data_port_connectors[0].target.as_ref().unwrap().pos,
        Pos::new(49, 9)
    );
    let y = read("full.yaml").system;
    assert_eq!(y.pos, Pos::new(2, 1));
    assert_eq!(y.components[0].pos, Pos::new(22, 5));
    assert_eq!(y.components[1].pos, Pos::new(80, 5));
    assert_eq!(y.data_port_connectors[0].pos, Pos::new(117, 5));
}

// --- real-world oddities ------------------------------------------------------------------------

#[test]
fn real_world_oddities_are_read_leniently() {
    let p = read("oddities.xml");
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let s = &p.system;
    // Damaged id: `RTSystem :Vendor.Name.1.0`.
    let id = s.id_parts.as_ref().unwrap();
    assert_eq!(
        (t(&id.vendor), t(&id.name), t(&id.version), id.form),
        ("Demo Works", "DefaultSystem01", "1.0", IdForm::Repaired)
    );
    assert_eq!(s.name(), "DefaultSystem01");
    // Missing dates stay missing; an empty attribute stays empty.
    assert_eq!(
        (s.creation_date.as_ref(), s.update_date.as_ref()),
        (None, None)
    );
    assert_eq!(s.abstract_.as_deref(), Some(""));
    // Truncated category, placeholder vendor, old dotted form.
    let kin = &s.components[0];
    assert_eq!(t(&kin.id_parts.as_ref().unwrap().category), "Experimenta");
    assert_eq!(
        t(&s.components[1].id_parts.as_ref().unwrap().vendor),
        "$VenderName"
    );
    let dotted = s.components[2].id_parts.as_ref().unwrap();
    assert_eq!(
        (
            t(&dotted.vendor),
            t(&dotted.category),
            t(&dotted.name),
            dotted.form
        ),
        (
            "AIST",
            "Software algorithm",
            "PathPlanner2D",
            IdForm::Dotted
        )
    );
    // `Instance.port` and bare `port`, in instances and connector ends.
    assert_eq!(t(&kin.data_ports[0].short_name), "velocity");
    assert_eq!(t(&s.components[1].data_ports[0].short_name), "out");
    let d = &s.data_port_connectors[0];
    assert_eq!(t(&d.source.as_ref().unwrap().short_name), "out");
    assert_eq!(t(&d.target.as_ref().unwrap().short_name), "velocity");
    assert_eq!(t(&d.data_type_scoped), "RTC::TimedVelocity2D");
    // A scoped name is already scoped; an end without instance name keeps its written name.
    let d2 = &s.data_port_connectors[1];
    assert_eq!(d2.data_type_scoped, None);
    assert!(d2.target.is_none());
    assert_eq!(t(&d2.source.as_ref().unwrap().short_name), "Joy0.out");
    // Pseudo sets, including `__type__`.
    let pseudo: Vec<bool> = kin.configuration_sets.iter().map(|c| c.pseudo).collect();
    assert_eq!(pseudo, [false, true, true]);
    // Directions in any case.
    assert_eq!(
        kin.location.as_ref().unwrap().direction_kind(),
        Some(LocationDirection::Down)
    );
    assert_eq!(
        s.components[1].location.as_ref().unwrap().direction_kind(),
        Some(LocationDirection::Left)
    );
    // Host data: IOR, an `…_ior` name (even empty), os.hostname, corba.endpoint; not `behavior`.
    let flags: Vec<(&str, bool)> = s
        .all_properties()
        .iter()
        .map(|p| (t(&p.name), p.private))
        .collect();
    assert_eq!(
        flags,
        [
            ("IOR", true),
            ("dataport.corba_cdr.inport_ior", true),
            ("behavior", false),
            ("os.hostname", true),
            ("corba.endpoint", true)
        ]
    );
    assert_eq!(s.private_properties(), 4);
}

#[test]
fn damaged_system_ids_in_the_root() {
    for (id, parts) in [
        ("RTSystem:1:3:2", ("1", "3", "2")),
        ("RTSystem :Vendor.Name.1.0", ("Vendor", "Name", "1.0")),
        ("RTSystem:Vendor:Name:1.0", ("Vendor", "Name", "1.0")),
    ] {
        let xml = format!(
            "<rts:RtsProfile xmlns:rts=\"{NS}\" rts:id=\"{id}\"/>",
            NS = rtcdoc::parse::rts::NS_RTS
        );
        let s = read_str(SourceFormat::Xml, &xml).unwrap().system;
        let p = s.id_parts.unwrap();
        assert_eq!((t(&p.vendor), t(&p.name), t(&p.version)), parts, "{id}");
        assert_eq!(s.id.as_deref(), Some(id), "the id is kept as written");
    }
    let s = read_str(
        SourceFormat::Xml,
        "<RtsProfile xmlns=\"http://www.openrtp.org/namespaces/rts\" id=\"SomethingElse\"/>",
    )
    .unwrap()
    .system;
    assert_eq!(s.id_parts, None);
    assert_eq!(s.name(), "SomethingElse");
}

// --- unknown content ----------------------------------------------------------------------------

fn extra<'a>(list: &'a [Extra], name: &str) -> &'a Extra {
    list.iter()
        .find(|e| e.name == name)
        .unwrap_or_else(|| panic!("no extra {name} in {list:?}"))
}

#[test]
fn unknown_xml_content_is_kept_on_the_nearest_node_and_warned() {
    let p = read("unknown.xml");
    let s = &p.system;
    let root_attr = extra(&s.extra, "my:tool");
    assert_eq!(root_attr.kind, ExtraKind::Attribute);
    assert_eq!(root_attr.namespace.as_deref(), Some("urn:example:tool"));
    assert_eq!(root_attr.value.as_deref(), Some("editor 3"));
    assert_eq!(
        extra(&s.extra, "rts:Wiring").children[0].value.as_deref(),
        Some("auto")
    );
    assert!(extra(&s.extra, "#text")
        .value
        .as_deref()
        .unwrap()
        .contains("stray words"));
    let c = &s.components[0];
    assert_eq!(extra(&c.extra, "rts:colour").value.as_deref(), Some("red"));
    let note = extra(&c.extra, "my:Note");
    assert_eq!(note.kind, ExtraKind::Element);
    assert_eq!(note.value.as_deref(), Some("check the wiring"));
    assert_eq!(note.children.len(), 2, "attribute and child element");
    assert_eq!(note.pos, Pos::new(4, 9));
    assert_eq!(
        extra(&c.data_ports[0].extra, "rts:kind").value.as_deref(),
        Some("in")
    );
    let loc = c.location.as_ref().unwrap();
    assert_eq!(extra(&loc.extra, "rtsExt:z").value.as_deref(), Some("9"));
    assert_eq!(t(&loc.x), "1", "the first Location is used");
    assert_eq!(
        extra(&c.extra, "rtsExt:Location").children[0]
            .value
            .as_deref(),
        Some("5")
    );
    let d = &s.data_port_connectors[0];
    assert_eq!(
        extra(&d.extra, "rts:bufferLength").value.as_deref(),
        Some("8")
    );
    assert_eq!(
        extra(&d.source.as_ref().unwrap().extra, "rts:side")
            .value
            .as_deref(),
        Some("left")
    );
    assert_eq!(t(&d.source.as_ref().unwrap().short_name), "out");
    assert_eq!(extra(&d.extra, "rts:sourceDataPort").pos, Pos::new(11, 9));
    let o = &s.orders[0];
    assert_eq!(extra(&o.extra, "rts:mode").value.as_deref(), Some("fast"));
    assert_eq!(
        extra(&o.targets[0].extra, "rts:priority").value.as_deref(),
        Some("high")
    );
    assert_eq!(
        extra(&o.targets[0].extra, "rts:Delay").children[0]
            .value
            .as_deref(),
        Some("5")
    );

    // One warning per unknown thing, each with its position and what was done.
    let warnings: Vec<String> = p.diagnostics.iter().map(|d| d.to_string()).collect();
    assert!(p
        .diagnostics
        .iter()
        .all(|d| d.severity == Severity::Warning && d.code == codes::UNKNOWN));
    assert_eq!(warnings.len(), 14, "{warnings:#?}");
    assert!(warnings
        .iter()
        .all(|w| w.contains("kept as an extra property")));
    assert!(warnings.contains(
        &"unknown.xml:2:196: warning[RTC006]: unknown attribute `my:tool` (namespace urn:example:tool) on RtsProfile; kept as an extra property".to_string()
    ), "{warnings:#?}");
    assert!(warnings.iter().any(|w| w.starts_with("unknown.xml:3:66: ")
        && w.contains("unknown attribute `rts:colour` on component instance")));
    assert!(warnings
        .iter()
        .any(|w| w.starts_with("unknown.xml:7:9: ")
            && w.contains("repeated element `rtsExt:Location`")));
}

#[test]
fn unknown_yaml_keys_are_kept_and_warned() {
    let p = read("unknown.yaml");
    let s = &p.system;
    assert_eq!(extra(&s.extra, "tool").value.as_deref(), Some("editor 3"));
    assert_eq!(extra(&s.extra, "extraRoot").pos, Pos::new(25, 1));
    let c = &s.components[0];
    assert_eq!(extra(&c.extra, "colour").value.as_deref(), Some("red"));
    assert_eq!(
        extra(&c.location.as_ref().unwrap().extra, "z")
            .value
            .as_deref(),
        Some("9")
    );
    let d = &s.data_port_connectors[0];
    assert_eq!(extra(&d.extra, "bufferLength").value.as_deref(), Some("8"));
    assert_eq!(
        extra(&d.source.as_ref().unwrap().extra, "side").pos,
        Pos::new(17, 9)
    );
    let o = &s.orders[0];
    assert_eq!(extra(&o.extra, "mode").value.as_deref(), Some("fast"));
    assert_eq!(
        extra(&o.targets[0].extra, "delay").children[0]
            .value
            .as_deref(),
        Some("5")
    );
    assert_eq!(
        codes_of(&p.diagnostics),
        vec![codes::UNKNOWN; 8],
        "{:?}",
        p.diagnostics
    );
}

// --- detection and hostile input ----------------------------------------------------------------

#[test]
fn systems_are_detected_by_their_root() {
    assert!(is_system(&fixture("full.xml")));
    assert!(is_system(&fixture("full.yaml")));
    assert!(is_system(
        b"\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!-- c --><rts:RtsProfile/>"
    ));
    assert!(is_system(b"\"rtsProfile\":\n  id: x\n"));
    assert!(!is_system(b"<rtc:RtcProfile xmlns:rtc=\"x\"/>"));
    assert!(!is_system(b"rtcProfile:\n  id: x\n"));
    assert!(!is_system(b"\x00\x01binary"));
    assert!(!is_system(b""));
    // And a system profile is no component profile.
    assert!(!rtcdoc::parse::xml::is_profile(&fixture("full.xml")));
    assert!(!rtcdoc::parse::yaml::is_profile(&fixture("full.yaml")));
}

fn err(format: SourceFormat, bytes: &[u8], limits: &Limits) -> Diagnostic {
    match parse(format, bytes, "bad", limits) {
        Ok(p) => panic!("accepted: {:?}", p.system),
        Err(d) => d,
    }
}

#[test]
fn hostile_and_broken_input_is_refused_with_a_position() {
    let l = Limits::default();
    let ns = "xmlns:rts=\"http://www.openrtp.org/namespaces/rts\"";
    // Entities: declarations and undefined references.
    let d = err(
        SourceFormat::Xml,
        format!("<!DOCTYPE r [<!ENTITY a \"aaaa\">]><rts:RtsProfile {ns} rts:id=\"&a;\"/>")
            .as_bytes(),
        &l,
    );
    assert_eq!(d.code, codes::ENTITY);
    assert!(d.pos.is_some() && d.hint.is_some());
    let d = err(
        SourceFormat::Xml,
        format!("<rts:RtsProfile {ns} rts:id=\"&xxe;\"/>").as_bytes(),
        &l,
    );
    assert_eq!(d.code, codes::ENTITY);
    // Depth.
    let small = Limits {
        max_depth: 8,
        ..Limits::default()
    };
    let deep = format!("<rts:RtsProfile {ns}>{}", "<a>".repeat(20));
    let d = err(SourceFormat::Xml, deep.as_bytes(), &small);
    assert_eq!(d.code, codes::TOO_DEEP);
    // The root and 7 `<a>` fill the 8 levels; the 8th `<a>` is refused where it starts.
    assert_eq!(d.pos, Some(Pos::new(1, 67 + 7 * 3)));
    let deep_yaml = format!("rtsProfile: {}{}", "[".repeat(20), "]".repeat(20));
    assert_eq!(
        err(SourceFormat::Yaml, deep_yaml.as_bytes(), &small).code,
        codes::TOO_DEEP
    );
    // Size.
    let tiny = Limits {
        max_file_size: 10,
        ..Limits::default()
    };
    let d = err(SourceFormat::Xml, &fixture("full.xml"), &tiny);
    assert_eq!(d.code, codes::TOO_LARGE);
    assert!(d.hint.unwrap().contains("`max-file-size` in rtcdoc.toml"));
    // Alias bomb.
    let mut bomb = String::from("a: &a [x, x, x, x, x, x, x, x, x, x]\n");
    for i in 1..9 {
        bomb.push_str(&format!(
            "{n}: &{n} [*{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}]\n",
            n = (b'a' + i) as char,
            p = (b'a' + i - 1) as char
        ));
    }
    bomb.push_str("rtsProfile:\n  id: *i\n");
    let d = err(SourceFormat::Yaml, bomb.as_bytes(), &l);
    assert!(d.code == codes::YAML_STRUCTURE, "{d}");
    // Malformed, truncated, wrong root, not a system.
    let d = err(
        SourceFormat::Xml,
        format!("<rts:RtsProfile {ns}><rts:Components>").as_bytes(),
        &l,
    );
    assert_eq!(d.code, codes::MALFORMED);
    assert!(d.message.contains("truncated"), "{d}");
    let d = err(
        SourceFormat::Xml,
        b"<rtc:RtcProfile xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\"/>",
        &l,
    );
    assert_eq!(d.code, codes::SHAPE);
    assert!(d.message.contains("not an RT System profile"), "{d}");
    let d = err(SourceFormat::Yaml, b"rtcProfile:\n  id: x\n", &l);
    assert_eq!(d.code, codes::SHAPE);
    let d = err(SourceFormat::Yaml, b"rtsProfile: [\n", &l);
    assert_eq!(d.code, codes::MALFORMED);
    assert!(d.pos.is_some());
    // Encodings: a declared one is decoded, bad bytes are refused with where they are.
    let (sjis, _, _) = encoding_rs::SHIFT_JIS.encode("ロボット");
    let mut doc = format!(
        "<?xml version=\"1.0\" encoding=\"Shift_JIS\"?>\n<rts:RtsProfile {ns} xmlns:rtsExt=\"http://www.openrtp.org/namespaces/rts_ext\" rtsExt:comment=\""
    )
    .into_bytes();
    doc.extend_from_slice(&sjis);
    doc.extend_from_slice(b"\"/>");
    let s = parse(SourceFormat::Xml, &doc, "sjis", &l).unwrap().system;
    assert_eq!(s.comment.as_deref(), Some("ロボット"));
    let d = err(
        SourceFormat::Xml,
        format!("<rts:RtsProfile {ns} rts:id=\"\u{e9}")
            .as_bytes()
            .iter()
            .copied()
            .chain(*b"\xff\"/>")
            .collect::<Vec<u8>>()
            .as_slice(),
        &l,
    );
    assert_eq!(d.code, codes::ENCODING);
    let d = err(SourceFormat::Yaml, b"rtsProfile:\n  id: \xff\n", &l);
    assert_eq!(d.code, codes::ENCODING);
    assert_eq!(d.pos, Some(Pos::new(2, 7)));
}

#[test]
fn mutated_fixtures_never_panic() {
    // Truncations and byte flips of both fixtures: each is read or refused, never a panic.
    for name in ["full.xml", "full.yaml"] {
        let bytes = fixture(name);
        let f = format_of(name);
        for cut in (0..bytes.len()).step_by(97) {
            let _ = parse(f, &bytes[..cut], name, &Limits::default());
            let mut flipped = bytes.clone();
            flipped[cut] ^= 0x5a;
            let _ = parse(f, &flipped, name, &Limits::default());
        }
    }
}

#[test]
fn own_fixtures_lose_nothing_either() {
    // XML: every attribute value and text (unknown ones included) is in the model's JSON.
    for name in ["full.xml", "oddities.xml", "unknown.xml"] {
        let lost = lost_values(&xml_values(&fixture(name)), &read(name).system);
        assert!(lost.is_empty(), "{name}: lost {lost:?}");
    }
    // YAML: every scalar (date maps become one ISO date) and every unknown key.
    fn scalars(v: &serde_norway::Value, out: &mut Vec<String>) {
        use serde_norway::Value as V;
        match v {
            V::String(s) => out.push(s.clone()),
            V::Number(n) => out.push(n.to_string()),
            V::Bool(b) => out.push(b.to_string()),
            V::Sequence(s) => s.iter().for_each(|v| scalars(v, out)),
            V::Mapping(m) => {
                for (k, v) in m {
                    let date = matches!(k.as_str(), Some("creationDate" | "updateDate"));
                    if !(date && v.is_mapping()) {
                        scalars(v, out);
                    }
                }
            }
            _ => {}
        }
    }
    for name in ["full.yaml", "unknown.yaml"] {
        let value: serde_norway::Value = serde_norway::from_slice(&fixture(name)).unwrap();
        let mut values = Vec::new();
        scalars(&value, &mut values);
        let lost = lost_values(&values, &read(name).system);
        assert!(lost.is_empty(), "{name}: lost {lost:?}");
    }
}

#[test]
fn the_fixture_component_has_the_instance_id() {
    // tests/fixtures/rts/components/Camera/RTC.xml is the component of `Camera0`: the same
    // id string, and the same parts by the system reader's id rule.
    let bytes = fixture("components/Camera/RTC.xml");
    let profile = rtcdoc::parse::parse(SourceFormat::Xml, &bytes, "RTC.xml", &Limits::default())
        .unwrap()
        .profile;
    let s = read("full.xml").system;
    let cam = s.component("Camera0").unwrap();
    assert_eq!(profile.id, cam.id);
    let parts = ComponentIdParts::parse(profile.id.as_deref().unwrap()).unwrap();
    assert_eq!(Some(parts), cam.id_parts);
    let b = &profile.basic_info;
    let p = cam.id_parts.as_ref().unwrap();
    assert_eq!(
        (&b.vendor, &b.category, &b.name),
        (&p.vendor, &p.category, &p.name)
    );
}

#[test]
fn yaml_oddities() {
    // Dates written as strings, a bare participant, a bare wait time, `rtsExt::` left off,
    // a lower-case direction, an `Instance.port` name before the instance name.
    let y = "rtsProfile:\n  id: 'RTSystem :V.S.1.0'\n  creationDate: '2020-01-02T03:04:05'\n  comment: no prefix\n  components:\n    - dataPorts:\n        - name: I0.out\n      instanceName: I0\n      participants:\n        - componentId: RTC:V:C:P:1\n          instanceName: P0\n      location:\n        direction: up\n  startUp:\n    targets:\n      - sequence: 1\n        condition:\n          waitTime: 250\n";
    let p = read_str(SourceFormat::Yaml, y).unwrap();
    assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
    let s = p.system;
    assert_eq!(t(&s.creation_date), "2020-01-02T03:04:05");
    assert_eq!(t(&s.comment), "no prefix");
    assert_eq!(t(&s.id_parts.as_ref().unwrap().name), "S");
    let c = &s.components[0];
    assert_eq!(t(&c.data_ports[0].short_name), "out");
    assert_eq!(t(&c.participants[0].instance_name), "P0");
    assert_eq!(
        c.location.as_ref().unwrap().direction_kind(),
        Some(LocationDirection::Up)
    );
    let w = s.orders[0].targets[0].wait_time.as_ref().unwrap();
    assert_eq!(t(&w.wait_time), "250");
    // A wrong shape is kept and reported as such (RTC009), not dropped.
    let p = read_str(SourceFormat::Yaml, "rtsProfile:\n  components: 3\n").unwrap();
    assert_eq!(codes_of(&p.diagnostics), [codes::SHAPE]);
    assert_eq!(p.system.extra[0].value.as_deref(), Some("3"));
}

#[test]
fn group_id_spellings_and_repeated_orders() {
    let ns = "xmlns:rts=\"http://www.openrtp.org/namespaces/rts\"";
    // rtsprofile (Python) writes `groupID`; both spellings on one element keep the second.
    let x = format!(
        "<rts:RtsProfile {ns}>\n<rts:Groups rts:groupID=\"g1\"/>\n<rts:Groups rts:groupId=\"g2\" rts:groupID=\"g3\"/>\n<rts:StartUp/>\n<rts:StartUp/>\n</rts:RtsProfile>"
    );
    let p = read_str(SourceFormat::Xml, &x).unwrap();
    let s = &p.system;
    assert_eq!(t(&s.groups[0].group_id), "g1");
    assert_eq!(t(&s.groups[1].group_id), "g2");
    assert_eq!(s.groups[1].extra[0].value.as_deref(), Some("g3"));
    assert_eq!(s.orders.len(), 1, "StartUp is allowed once");
    assert_eq!(s.extra[0].name, "rts:StartUp");
    assert_eq!(s.extra[0].pos, Pos::new(5, 1));
    let msgs: Vec<&str> = p.diagnostics.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(msgs.len(), 2, "{msgs:?}");
    assert!(msgs[0].starts_with("repeated attribute `rts:groupID`"));
    assert!(msgs[1].starts_with("repeated element `rts:StartUp`"));
}
