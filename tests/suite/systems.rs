//! RT System profiles as documented pages (issue 16): loading into the catalogue, links from
//! instances to components and from connector ends to ports, the pages, the other outputs and
//! the check rules.

use crate::common;
use crate::html_support;
use common::OutputWithin;

use html_support::{broken_links, build_site, tags};
use rtcdoc::build::{self, LoadOptions};
use rtcdoc::catalog::systems::{MatchKind, PortLink};
use rtcdoc::catalog::Catalog;
use rtcdoc::render::SiteOptions;
use std::path::PathBuf;

fn read(p: &std::path::Path) -> String {
    common::read_page(p)
}

/// The part of `html` from the element with `id` to the end of its section.
fn section<'a>(html: &'a str, id: &str) -> &'a str {
    let start = html
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no section {id}"));
    let rest = &html[start..];
    &rest[..rest.find("</section>").unwrap_or(rest.len())]
}

fn site_fixture() -> PathBuf {
    common::root().join("tests/fixtures/systems/site")
}

/// The id of the component whose page slug is `slug`: instances name components by id.
fn id_of(cat: &Catalog, slug: &str) -> String {
    cat.components
        .iter()
        .find(|c| c.slug == slug)
        .map(|c| c.id.to_string())
        .unwrap_or_else(|| panic!("no component {slug}"))
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
    assert_eq!(cam.component, Some(id_of(&cat, "camera")));
    assert_eq!(cam.matched_by, Some(MatchKind::Exact));
    assert_eq!(cam.version_drift, None);
    let pl = &s.instances[1];
    assert_eq!(pl.component, Some(id_of(&cat, "planner")));
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
    let ci = cat
        .components
        .iter()
        .position(|c| c.slug == "planner")
        .unwrap();
    let using = cat.systems_using(rtcdoc::catalog::Ix::new(ci));
    assert_eq!(using.len(), 1);
    assert_eq!(using[0].1, vec!["Planner0"]);
    assert_eq!(cat.connectors_carrying("RTC::CameraImage").len(), 1);
    assert_eq!(cat.connectors_carrying("IDL:RTC/CameraImage:1.0").len(), 1);
    assert!(cat.connectors_carrying("RTC::TimedLong").is_empty());
}

/// RTSystemEditor names most systems `RTSystem`: systems of one name are told apart by the
/// folders where their paths differ, on their pages, in the index and in the Markdown.
#[test]
fn systems_of_one_name_are_told_apart_by_their_folders() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let system = read(&site_fixture().join("system/PatrolSystem.xml"));
    for d in ["ev3/demo", "mouse/demo"] {
        common::write(&input, &format!("{d}/PatrolSystem.xml"), &system);
    }
    // Solo has no service connector.
    let start = system.find("<rts:ServicePortConnectors").unwrap();
    let end = system.find("</rts:ServicePortConnectors>").unwrap() + 28;
    let solo = format!("{}{}", &system[..start], &system[end..]).replace("PatrolSystem", "Solo");
    common::write(&input, "other/Solo.xml", &solo);
    let camera = read(&site_fixture().join("components/Camera/RTC.xml"));
    common::write(&input, "components/Camera/RTC.xml", &camera);
    let out = dir.path().join("site");
    let loaded = build_site(&input, &out, SiteOptions::default());
    let names: Vec<String> = loaded
        .catalog
        .systems
        .iter()
        .map(|s| s.display_name().into_owned())
        .collect();
    assert_eq!(
        names,
        ["PatrolSystem (ev3)", "PatrolSystem (mouse)", "Solo"]
    );
    let index = read(&out.join("systems/index.html"));
    assert!(index.contains(">PatrolSystem (ev3)</a>"), "{index}");
    assert!(index.contains(">PatrolSystem (mouse)</a>"), "{index}");
    let page = read(&out.join(format!("systems/{}.html", loaded.catalog.systems[1].slug)));
    let title = &page[page.find("<title>").unwrap() + 7..];
    assert!(title.starts_with("PatrolSystem (mouse) "), "{title}");
    assert!(page.contains("</span> PatrolSystem (mouse)</h1>"), "{page}");
    // The component's "used in" list: the system's name (qualified) and then the instances,
    // so that the qualifier and the instance names are not two alike parentheses.
    let camera = read(&out.join("components/camera.html"));
    for want in [
        ">PatrolSystem (ev3): Camera0</a>",
        ">PatrolSystem (mouse): Camera0</a>",
        ">Solo: Camera0</a>",
    ] {
        assert!(camera.contains(want), "{want}\n{camera}");
    }
    let md: std::collections::BTreeMap<String, String> =
        rtcdoc::render::markdown::pages(&loaded.catalog, "Cat", rtcdoc::i18n::Lang::En)
            .into_iter()
            .collect();
    let camera = &md["components/camera.md"];
    assert!(
        camera.contains("[PatrolSystem (ev3): Camera0]("),
        "{camera}"
    );
    // A section without connectors says so as the HTML page does, not with an empty table.
    let solo = &md["systems/solo.md"];
    let section = solo.split("Service port connectors").nth(1).unwrap();
    let section = section.split("\n#").next().unwrap();
    assert!(section.contains("\n—\n"), "{solo}");
    assert!(!section.contains("| Connector |"), "{solo}");
}

#[test]
fn a_system_alone_is_something_to_document() {
    let cat = load(&site_fixture().join("system/PatrolSystem.xml"));
    assert_eq!(cat.systems.len(), 1);
    assert!(cat.components.is_empty());
    assert!(cat.systems[0]
        .instances
        .iter()
        .all(|i| i.component.is_none()));
    // The ports still come from the system file and its connectors.
    let ports = cat.instance_ports(&cat.systems[0], 1);
    let names: Vec<&str> = ports.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["image", "path", "camera"]);
    // Sides: `image` is a connector's target; `path` ends at no connector and has no side;
    // `camera` is a service port.
    let kinds: Vec<_> = ports.iter().map(|p| p.kind).collect();
    use rtcdoc::catalog::systems::InstancePortKind::{Data, Service};
    use rtcdoc::model::PortDirection::{In, Out};
    assert_eq!(kinds, [Data(Some(In)), Data(None), Service]);
    // RTSystemEditor's `port.port_type` property gives an unconnected port its side.
    let dir = tempfile::tempdir().unwrap();
    let text = read(&site_fixture().join("system/PatrolSystem.xml")).replace(
        r#"<rts:DataPorts rts:name="path"/>"#,
        r#"<rts:DataPorts rts:name="path"><rtsExt:Properties rtsExt:name="port.port_type" rtsExt:value="DataOutPort"/></rts:DataPorts>"#,
    );
    common::write(dir.path(), "PatrolSystem.xml", &text);
    let cat = load(&dir.path().join("PatrolSystem.xml"));
    let ports = cat.instance_ports(&cat.systems[0], 1);
    let kinds: Vec<_> = ports.iter().map(|p| p.kind).collect();
    assert_eq!(kinds, [Data(Some(In)), Data(Some(Out)), Service]);
    // … and the drawing puts it with the out-ports.
    let out = dir.path().join("site");
    build_site(dir.path(), &out, SiteOptions::default());
    let svg = read(&out.join("systems/patrolsystem.svg"));
    assert!(svg.contains("out-port Planner0.path"), "{svg}");
}

#[test]
fn system_page_shows_every_instance_and_connector_with_named_links() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&site_fixture(), &out, SiteOptions::default());
    assert_eq!(loaded.catalog.systems.len(), 1);
    let index = read(&out.join("systems/index.html"));
    assert!(
        index.contains(r#"href="patrolsystem.html">PatrolSystem</a>"#),
        "{index}"
    );
    let html = read(&out.join("systems/patrolsystem.html"));
    let title = &html[html.find("<title>").unwrap() + 7..];
    assert!(title.starts_with("PatrolSystem "), "{title}");
    // On a phone the tables are cards: every value cell names its column.
    let cells = html.matches("<td").count();
    assert!(cells > 20, "{cells}");
    assert_eq!(html.matches(" data-label=\"").count(), cells, "{html}");
    // Every instance, linked to its component; drift flagged.
    let inst = section(&html, "instances");
    for (row, comp) in [
        ("inst-camera0", "../components/camera.html"),
        ("inst-planner0", "../components/planner.html"),
    ] {
        assert!(inst.contains(&format!(r#"<tr id="{row}">"#)), "{row}");
        assert!(inst.contains(&format!(r#"href="{comp}""#)), "{comp}");
    }
    assert!(
        inst.contains("version drift: the catalogue has 1.1.0"),
        "{inst}"
    );
    // Every connector, ends linked to the ports of the component pages, the type to its page.
    let data = section(&html, "data-connectors");
    assert!(
        data.contains(r#"<a href="../components/camera.html#port-image"><code>image</code></a>"#),
        "{data}"
    );
    assert!(
        data.contains(r#"<a href="../components/planner.html#port-image"><code>image</code></a>"#),
        "{data}"
    );
    assert!(
        data.contains(r#"href="../types/rtc-cameraimage.html""#),
        "{data}"
    );
    assert!(data.contains("periodic") && data.contains("0.5") && data.contains("corba_cdr"));
    let svc = section(&html, "service-connectors");
    assert!(
        svc.contains("#sport-camera") && svc.contains("#sport-control"),
        "{svc}"
    );
    assert!(
        svc.contains(r#"href="../interfaces/cameracontrol.html""#),
        "{svc}"
    );
    // The diagram: a group (not an image) with a named link per instance and per port.
    let svg = &html[html.find("<svg").unwrap()..html.find("</svg>").unwrap()];
    assert!(svg.contains(r#"role="group""#) && !svg.contains(r#"role="img""#));
    let links: Vec<_> = tags(svg).into_iter().filter(|t| t.name == "a").collect();
    let labels: Vec<&str> = links.iter().filter_map(|t| t.attr("aria-label")).collect();
    assert_eq!(links.len(), labels.len(), "every link is named");
    for l in [
        "Camera0 Camera (Instance, member of: Planner0)",
        "Planner0 Planner (Instance, Composite type: PeriodicECShared, Members: Camera0)",
        "out-port Camera0.image",
        "in-port Planner0.image",
        "out-port Planner0.path",
        "service port Planner0.camera",
        "service port Camera0.control",
    ] {
        assert!(labels.contains(&l), "{l} in {labels:?}");
    }
    assert_eq!(svg.matches("class=\"connector data\"").count(), 1);
    assert_eq!(svg.matches("class=\"connector service\"").count(), 1);
    assert!(html.contains("<figcaption>Wiring of PatrolSystem: 2 instances, 1 data connector, 1 service connector. Double outline: composite component (Planner0); dashed outline: member of a composite (Camera0). <a href=\"patrolsystem.svg\">Open the drawing on its own</a></figcaption>"), "{html}");
    // Configuration used next to the defaults: differences marked, values checked.
    let conf = section(&html, "configuration");
    assert!(
        conf.contains("<mark>0.02</mark></td><td data-label=\"Component default\">0.01</td>"),
        "{conf}"
    );
    assert!(
        conf.contains("<mark>0.5</mark></td><td data-label=\"Component default\">0.3</td>"),
        "{conf}"
    );
    // RTSystemEditor's editor data (`__widget__`, …) has no component default or description
    // to show: its tables have name and value only.
    let widget = conf
        .split("<caption><code>__widget__</code>")
        .nth(1)
        .and_then(|t| t.split("</table>").next())
        .unwrap_or_else(|| panic!("no __widget__ table: {conf}"));
    assert!(!widget.contains("Component default"), "{widget}");
    assert!(
        widget.contains("<th scope=\"col\">Value</th></tr>"),
        "{widget}"
    );
    // Editor data starts collapsed (it doubled a real system page's length); the sets that
    // configure the instances stay open.
    assert!(
        conf.contains("<details class=\"sys-config-pseudo\">\n<summary><code>__widget__</code> (editor data) <span class=\"count\">"),
        "{conf}"
    );
    assert!(!conf.contains("<details open"), "{conf}");
    let before_default = conf
        .split("<caption><code>default</code>")
        .next()
        .unwrap_or("");
    assert_eq!(
        before_default.matches("<details").count(),
        before_default.matches("</details>").count(),
        "the default set is in no <details>: {conf}"
    );
    // Orders and groups.
    assert!(section(&html, "orders").contains("after Camera0 (timeout 500 ms, SYNC)"));
    assert!(section(&html, "groups").contains("Camera0, Planner0"));
    // The component pages list the system; the type page lists the connector.
    let planner = read(&out.join("components/planner.html"));
    let used = section(&planner, "systems");
    assert!(
        used.contains(r#"<a href="../systems/patrolsystem.html">PatrolSystem: Planner0</a>"#),
        "{used}"
    );
    let ty = read(&out.join("types/rtc-cameraimage.html"));
    assert!(
        section(&ty, "system-connectors").contains("PatrolSystem: Camera0.image → Planner0.image")
    );
    // Navigation and search.
    assert!(read(&out.join("index.html")).contains(r#"<a href="systems/index.html">Systems</a>"#));
    assert!(planner.contains(r#"<a href="../systems/index.html">Systems</a>"#));
    let search = common::search_index::read(&out);
    assert!(search
        .entries
        .iter()
        .any(|e| e.href == "systems/patrolsystem.html" && e.kind == "s"));
    let broken = broken_links(&out);
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn host_data_is_hidden_unless_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    let hidden = dir.path().join("hidden");
    build_site(&site_fixture(), &hidden, SiteOptions::default());
    let html = read(&hidden.join("systems/patrolsystem.html"));
    for secret in [
        "robot-pc.local",
        "192.168.10.5:2810",
        "IOR:010000001a",
        "nameserver.example",
        "localhost:2809/Camera0.rtc",
        "robot-pc.host_cxt",
    ] {
        assert!(!html.contains(secret), "{secret} published");
    }
    assert!(
        html.contains("8 host values hidden"),
        "the page says what it left out"
    );
    assert!(html.contains("lab B"), "other properties stay");
    let shown = dir.path().join("shown");
    build_site(
        &site_fixture(),
        &shown,
        SiteOptions {
            show_host_data: true,
            ..Default::default()
        },
    );
    let html = read(&shown.join("systems/patrolsystem.html"));
    for secret in [
        "robot-pc.local",
        "192.168.10.5:2810",
        "IOR:010000001a",
        "nameserver.example",
        "localhost:2809/Camera0.rtc",
        "robot-pc.host_cxt",
    ] {
        assert!(html.contains(secret), "{secret} shown with show-host-data");
    }
    assert!(!html.contains("host values hidden"));
}

#[test]
fn show_host_data_is_a_configuration_key() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = d.join("in");
    std::fs::create_dir_all(&input).unwrap();
    std::fs::copy(
        site_fixture().join("system/PatrolSystem.xml"),
        input.join("PatrolSystem.xml"),
    )
    .unwrap();
    std::fs::write(input.join("rtcdoc.toml"), "show-host-data = true\n").unwrap();
    let out = common::rtcdoc(&["build", "in", "-o", "site"], d);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(read(&d.join("site/systems/patrolsystem.html")).contains("robot-pc.local"));
}

#[test]
fn a_diagram_of_many_instances_without_locations_is_laid_out_in_layers() {
    // A chain of 24 instances: each box left of the next, none overlapping.
    let mut comps = String::new();
    let mut conns = String::new();
    for i in 0..24 {
        comps.push_str(&format!(
            r#"<rts:Components rts:id="RTC:L:C:Stage:1.0" rts:instanceName="S{i}" rts:pathUri="" rts:activeConfigurationSet="default" rts:isRequired="true" rts:compositeType="None"><rts:DataPorts rts:name="S{i}.in"/><rts:DataPorts rts:name="S{i}.out"/></rts:Components>"#
        ));
        if i > 0 {
            conns.push_str(&format!(
                r#"<rts:DataPortConnectors rts:connectorId="c{i}" rts:name="c{i}" rts:dataType="IDL:RTC/TimedLong:1.0" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush"><rts:sourceDataPort rts:componentId="RTC:L:C:Stage:1.0" rts:instanceName="S{p}" rts:portName="S{p}.out"/><rts:targetDataPort rts:componentId="RTC:L:C:Stage:1.0" rts:instanceName="S{i}" rts:portName="S{i}.in"/></rts:DataPortConnectors>"#,
                p = i - 1
            ));
        }
    }
    let xml = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?><rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" rts:id="RTSystem:L:Chain:1.0" rts:version="0.2" rts:creationDate="2024-01-01T00:00:00" rts:updateDate="2024-01-01T00:00:00">{comps}{conns}</rts:RtsProfile>"#
    );
    let dir = tempfile::tempdir().unwrap();
    common::write(dir.path(), "in/Chain.xml", &xml);
    let out = dir.path().join("site");
    build_site(&dir.path().join("in"), &out, SiteOptions::default());
    let html = read(&out.join("systems/chain.html"));
    let svg = &html[html.find("<svg").unwrap()..html.find("</svg>").unwrap()];
    let boxes: Vec<f32> = tags(svg)
        .into_iter()
        .filter(|t| t.name == "rect" && t.attr("class") == Some("rtc-box"))
        .map(|t| t.attr("x").unwrap().parse().unwrap())
        .collect();
    assert_eq!(boxes.len(), 24);
    assert!(boxes.windows(2).all(|w| w[1] > w[0] + 150.0), "{boxes:?}");
    assert_eq!(svg.matches("class=\"connector data\"").count(), 23);
    // Ports named by the system file, directions from the connectors.
    assert!(svg.contains(r#"aria-label="out-port S0.out""#));
    assert!(svg.contains(r#"aria-label="in-port S23.in""#));
}

#[test]
fn markdown_doxygen_and_json_carry_systems() {
    use rtcdoc::render::{doxygen, markdown};
    let cat = load(&site_fixture());
    let lang = rtcdoc::i18n::Lang::En;
    // Markdown: an index, a page per system in SUMMARY, links both ways.
    let md: std::collections::BTreeMap<String, String> =
        markdown::pages(&cat, "Cat", lang).into_iter().collect();
    let page = &md["systems/patrolsystem.md"];
    for want in [
        "[Camera](../components/camera.md)",
        "version drift: the catalogue has 1.1.0",
        // The same columns as the HTML page: id, ends linked to the ports, comment.
        "| Camera0.image\\_Planner0.image | c1-image | Camera0.[image](../components/camera.md#port-image) | Planner0.[image](../components/planner.md#port-image) | [IDL:RTC/CameraImage:1.0](../types/rtc-cameraimage.md) | corba\\_cdr | push | periodic | 0.5 | frames to planner |",
        "| Planner0.camera\\_Camera0.control | c2-control | Planner0.[camera](../components/planner.md#sport-camera) | Camera0.[control](../components/camera.md#sport-control) | [CameraControl](../interfaces/cameracontrol.md) | corba | camera control |",
        "8 host values hidden",
    ] {
        assert!(page.contains(want), "{want} in\n{page}");
    }
    assert!(!page.contains("robot-pc.local"));
    assert!(
        page.contains("| Connector | Connector id | Source | Target |"),
        "{page}"
    );
    assert!(md["SUMMARY.md"]
        .contains("- [Systems](systems.md)\n    - [PatrolSystem](systems/patrolsystem.md)"));
    assert!(md["systems.md"].contains("[PatrolSystem](systems/patrolsystem.md)"));
    assert!(md["components/planner.md"]
        .contains("[PatrolSystem: Planner0](../systems/patrolsystem.md)"));
    assert!(md["types/rtc-cameraimage.md"]
        .contains("[PatrolSystem: Camera0.image → Planner0.image](../systems/patrolsystem.md#data-connectors)"));
    // Doxygen: pages and references, listed in the Doxyfile.
    let dox: std::collections::BTreeMap<String, String> =
        doxygen::pages(&cat, "Cat", lang).into_iter().collect();
    let page = &dox["systems/patrolsystem.dox"];
    assert!(
        page.starts_with("/// \\page rtc_sys_patrolsystem PatrolSystem"),
        "{page}"
    );
    assert!(page.contains("\\ref rtc_comp_camera \"Camera\""), "{page}");
    assert!(dox["systems.dox"].contains("\\subpage rtc_sys_patrolsystem"));
    assert!(dox["mainpage.dox"].contains("\\subpage rtc_systems (1)"));
    assert!(dox["components/camera.dox"]
        .contains("\\ref rtc_sys_patrolsystem \"PatrolSystem: Camera0\""));
    assert!(dox["Doxyfile"].contains("systems/patrolsystem.dox"));
    // JSON: systems with their links; host data left out by default.
    let dir = tempfile::tempdir().unwrap();
    for (show, name) in [(false, "hidden"), (true, "shown")] {
        let out = dir.path().join(name);
        build::build(&build::BuildOptions {
            input: site_fixture(),
            output: out.clone(),
            formats: vec![rtcdoc::render::Format::Json],
            strict: false,
            load: LoadOptions::default(),
            site: SiteOptions {
                show_host_data: show,
                ..Default::default()
            },
        })
        .expect("build");
        let text = read(&out.join("catalog.json"));
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let s = &v["systems"]["system/PatrolSystem.xml"];
        assert_eq!(s["slug"], "patrolsystem");
        let planner = s["instances"][1]["component"].as_str().unwrap();
        assert_eq!(v["components"][planner]["slug"], "planner");
        assert_eq!(s["instances"][1]["versionDrift"], "1.1.0");
        assert_eq!(s["instances"][0]["matchedBy"], "exact");
        assert_eq!(s["dataConnectors"][0]["source"]["instance"], 0);
        assert_eq!(s["dataConnectors"][0]["target"]["port"]["name"], "image");
        assert_eq!(
            s["serviceConnectors"][0]["target"]["port"]["kind"],
            "service"
        );
        assert_eq!(s["profile"]["components"].as_array().unwrap().len(), 2);
        assert_eq!(text.contains("robot-pc.local"), show, "{name}");
        assert_eq!(text.contains("localhost:2809/Camera0.rtc"), show, "{name}");
        // Other properties are kept either way.
        assert!(text.contains("\"lab B\""));
    }
}

#[test]
fn doxygen_runs_on_a_system_without_warnings() {
    if !html_support::have("doxygen") {
        crate::common::missing_tool("doxygen is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("dox");
    let o = common::rtcdoc(
        &[
            "build",
            site_fixture().to_str().unwrap(),
            "-f",
            "doxygen",
            "-o",
            out.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let d = std::process::Command::new("doxygen")
        .arg("Doxyfile")
        .current_dir(&out)
        .output_within(common::COMMAND_LIMIT)
        .expect("doxygen");
    let err = String::from_utf8_lossy(&d.stderr);
    assert!(
        d.status.success() && err.trim().is_empty(),
        "doxygen said:\n{err}"
    );
    assert!(out.join("html/rtc_sys_patrolsystem.html").is_file());
    // The wiring drawing, shown on the system's page.
    assert!(out.join("html/patrolsystem.svg").is_file());
    let page = read(&out.join("html/rtc_sys_patrolsystem.html"));
    assert!(page.contains(r#"data="patrolsystem.svg""#), "{page}");
}

#[test]
fn serve_picks_up_a_changed_system_and_keeps_systems_on_component_changes() {
    use rtcdoc::incremental::Workspace;
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    for rel in [
        "components/Camera/RTC.xml",
        "components/Planner/RTC.xml",
        "system/PatrolSystem.xml",
    ] {
        let to = input.join(rel);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(site_fixture().join(rel), &to).unwrap();
    }
    let opts = build::BuildOptions {
        input: input.clone(),
        output: dir.path().join("site"),
        formats: vec![rtcdoc::render::Format::Html],
        strict: false,
        load: LoadOptions::default(),
        site: SiteOptions::default(),
    };
    let mut ws = Workspace::open(&opts).expect("open");
    let page = |ws: &Workspace| {
        String::from_utf8(ws.files()["systems/patrolsystem.html"].clone()).unwrap()
    };
    assert!(page(&ws).contains("Hand-written test system"));
    // The system changes: its page follows.
    let sys = input.join("system/PatrolSystem.xml");
    let text = read(&sys).replace("Hand-written test system", "Edited while serving");
    std::fs::write(&sys, text).unwrap();
    let r = ws.update(std::slice::from_ref(&sys)).expect("update");
    assert!(r.full);
    assert!(page(&ws).contains("Edited while serving"));
    // A component changes (its version now matches): the system stays and loses its drift.
    let planner = input.join("components/Planner/RTC.xml");
    let text = read(&planner).replace("1.1.0", "1.2.0");
    std::fs::write(&planner, text).unwrap();
    ws.update(std::slice::from_ref(&planner)).expect("update");
    assert_eq!(ws.catalog().systems.len(), 1);
    assert!(
        !page(&ws).contains("version drift"),
        "re-rendered with the new component"
    );
}

/// Every RT System profile of the shared corpus (when present) has a page with every instance,
/// every connector and a diagram; no link of the site is broken. Prints the counts.
#[test]
fn every_corpus_system_has_a_complete_page() {
    let Some(corpus) = common::corpus() else {
        println!("skipped: ../shared/corpus not present");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&corpus, &out, SiteOptions::default());
    let cat = &loaded.catalog;
    assert_eq!(cat.systems.len(), 9);
    let (mut instances, mut matched, mut connectors) = (0, 0, 0);
    for s in &cat.systems {
        let html = read(&out.join(format!("systems/{}.html", s.slug)));
        assert!(
            html.contains("class=\"diagram system-diagram\""),
            "{}",
            s.source
        );
        for l in &s.instances {
            assert!(
                html.contains(&format!("<tr id=\"{}\">", l.anchor)),
                "{}",
                s.source
            );
        }
        let data = section(&html, "data-connectors");
        assert_eq!(
            data.matches("<tr><th scope=\"row\">").count(),
            s.profile.data_port_connectors.len(),
            "{}",
            s.source
        );
        let svc = section(&html, "service-connectors");
        assert_eq!(
            svc.matches("<tr><th scope=\"row\">").count(),
            s.profile.service_port_connectors.len(),
            "{}",
            s.source
        );
        instances += s.instances.len();
        matched += s.instances.iter().filter(|l| l.component.is_some()).count();
        connectors +=
            s.profile.data_port_connectors.len() + s.profile.service_port_connectors.len();
    }
    println!("corpus: {} systems, {instances} instances ({matched} matched to catalogue components), {connectors} connectors", cat.systems.len());
    assert_eq!((instances, connectors), (29, 35));
    let broken = broken_links(&out);
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn the_yaml_form_is_read_and_linked_like_the_xml_form() {
    let cat = load(&common::root().join("tests/fixtures/rts"));
    let by_source = |s: &str| cat.systems.iter().find(|x| x.source == s).unwrap();
    let (x, y) = (by_source("full.xml"), by_source("full.yaml"));
    assert_eq!(y.format, rtcdoc::parse::SourceFormat::Yaml);
    let links = |s: &rtcdoc::catalog::systems::System| -> Vec<Option<String>> {
        s.instances.iter().map(|i| i.component.clone()).collect()
    };
    assert_eq!(links(x), links(y));
    assert_eq!(links(x), [Some(id_of(&cat, "camera")), None]);
    assert_eq!(
        x.data_connectors[0].source.port,
        y.data_connectors[0].source.port
    );
    // Same name, two files: two pages with their own slugs.
    assert_ne!(x.slug, y.slug);
}

/// RTSystemEditor's save dialog offers the extension `.rtsys`: such a file is a system like any
/// other (found by its content), counted in the summaries; an empty configuration set says
/// "none" instead of an empty table.
#[test]
fn an_rtsys_file_is_a_system_and_an_empty_configuration_set_says_none() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::root().join("tests/fixtures/rtsys");
    let o = common::rtcdoc(
        &[
            "build",
            input.to_str().unwrap(),
            "-o",
            "site",
            "-f",
            "html,markdown,doxygen",
        ],
        dir.path(),
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("built 1 component profile and 1 RT System into"),
        "{err}"
    );
    let html = read(&dir.path().join("site/html/systems/wiring.html"));
    assert!(
        html.contains("<p class=\"sys-config-empty\"><code>default</code> (Active configuration set): none</p>"),
        "{html}"
    );
    assert!(!html.contains("<table class=\"sys-config\">"), "{html}");
    let index = read(&dir.path().join("site/html/index.html"));
    assert!(
        index.contains("<a href=\"systems/index.html\"><strong>1</strong> Systems</a>"),
        "{index}"
    );
    let md = read(&dir.path().join("site/markdown/systems/wiring.md"));
    assert!(md.contains("| Motor0 | default |   | none |"), "{md}");
    let o = common::rtcdoc(&["check", input.to_str().unwrap()], dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("; 1 component profile and 1 RT System, documentation coverage"),
        "{err}"
    );
    // A system alone: no coverage of nothing.
    let alone = dir.path().join("alone");
    std::fs::create_dir_all(&alone).unwrap();
    std::fs::copy(input.join("Wiring.rtsys"), alone.join("Wiring.rtsys")).unwrap();
    let o = common::rtcdoc(&["check", "alone"], dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("; 1 RT System\n"), "{err}");
    assert!(!err.contains("coverage"), "{err}");
    let o = common::rtcdoc(&["build", "alone", "-o", "alone-site"], dir.path());
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("built 1 RT System into"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The wiring drawing opens on its own: the site writes it beside the system page, as a
/// well-formed SVG without links, and the page's caption links it.
#[test]
fn the_wiring_drawing_opens_on_its_own() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(
        &common::root().join("examples"),
        &out,
        SiteOptions::default(),
    );
    let page = read(&out.join("systems/patrolrobot.html"));
    assert!(
        page.contains("<a href=\"patrolrobot.svg\">Open the drawing on its own</a></figcaption>"),
        "{page}"
    );
    let svg = read(&out.join("systems/patrolrobot.svg"));
    assert!(
        svg.contains("<svg xmlns=\"http://www.w3.org/2000/svg\""),
        "{svg}"
    );
    assert!(svg.contains("class=\"connector"), "{svg}");
    assert!(
        !svg.contains("href="),
        "no links: the pages are not beside a saved file"
    );
    let mut reader = quick_xml::Reader::from_str(&svg);
    loop {
        match reader.read_event() {
            Ok(quick_xml::events::Event::Eof) => break,
            Ok(_) => {}
            Err(e) => panic!("not well-formed at {}: {e}", reader.buffer_position()),
        }
    }
}

/// Naming paths are host data whether or not they give the name server's port: no output
/// publishes them by default, and text that only looks like a path stays.
#[test]
fn naming_paths_without_a_port_are_host_data() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "in/Demo.xml", &common::naming_path_system("Demo"));
    let out = common::rtcdoc(
        &[
            "build",
            "in",
            "-f",
            "html,markdown,doxygen,json",
            "-o",
            "site",
            "-q",
        ],
        d,
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut seen = 0;
    for f in walkdir::WalkDir::new(d.join("site"))
        .into_iter()
        .filter_map(Result::ok)
    {
        if !f.file_type().is_file() {
            continue;
        }
        let text = String::from_utf8_lossy(&std::fs::read(f.path()).unwrap()).into_owned();
        for secret in ["150.29.145.246", "cam-pc", "view-pc"] {
            assert!(
                !text.contains(secret),
                "{} publishes {secret}",
                f.path().display()
            );
        }
        if text.contains("in/out") {
            seen += 1;
        }
    }
    assert_eq!(
        seen, 4,
        "every output keeps the value that only looks like a path"
    );
    let html = read(&d.join("site/html/systems/demo.html"));
    assert!(html.contains("N/A"), "text that is no path stays");
    assert!(
        html.contains("4 host values hidden"),
        "two pathUri and two paths"
    );
}

/// Systems of one name: `graph` lists only those, by file, and the file it lists (or its path
/// from the current directory) selects one;
/// profiles sharing an id: `graph --component ID` says so, and an id it lists selects one.
#[test]
fn graph_names_what_tells_systems_and_components_of_one_name_apart() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "in/a/Demo.xml", &common::naming_path_system("Demo"));
    common::write(d, "in/b/Demo.xml", &common::naming_path_system("Demo"));
    common::write(d, "in/Other.xml", &common::naming_path_system("Other"));
    let run = |args: &[&str]| common::rtcdoc(args, d);
    let o = run(&["graph", "in", "--system", "Demo"]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(
        e.contains("2 systems in in are named \"Demo\"; choose one by its name as the pages show it or by its file, with --system: Demo (a) — a/Demo.xml, Demo (b) — b/Demo.xml"),
        "{e}"
    );
    assert!(!e.contains("Other"), "only the systems of that name: {e}");
    // Either of the two the list gives selects one, and the same one; so does the file's
    // path from the current directory (as the shell completes it).
    let mut drawn = Vec::new();
    for want in [
        "b/Demo.xml",
        "Demo (b)",
        "in/b/Demo.xml",
        "./in/b/../b/Demo.xml",
    ] {
        let o = run(&["graph", "in", "--system", want]);
        assert!(
            o.status.success(),
            "the hint works: {want}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        drawn.push(o.stdout);
    }
    assert!(drawn.iter().all(|d| *d == drawn[0]));
    let o = run(&["graph", "in"]);
    let e = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(
        e.contains("in holds 3 systems") && e.contains("Other — Other.xml"),
        "{e}"
    );

    let profile = |lang: &str| {
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile rtc:version="0.2" rtc:id="RTC:Lab:Sensor:Cam:1.0.0" xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <rtc:BasicInfo rtc:name="Cam" rtc:vendor="Lab" rtc:category="Sensor" rtc:version="1.0.0"/>
  <rtc:DataPorts rtc:name="out" rtc:portType="DataOutPort" rtc:type="RTC::TimedLong"/>
  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="{lang}"/>
</rtc:RtcProfile>
"#
        )
    };
    common::write(d, "in/cpp/RTC.xml", &profile("C++"));
    common::write(d, "in/py/RTC.xml", &profile("Python"));
    let o = run(&["graph", "in", "--component", "RTC:Lab:Sensor:Cam:1.0.0"]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(
        e.contains("2 components match \"RTC:Lab:Sensor:Cam:1.0.0\""),
        "{e}"
    );
    let listed = e
        .split('(')
        .find_map(|s| {
            s.strip_prefix("RTC:Lab:Sensor:Cam:1.0.0@")
                .map(|rest| rest.split(')').next().unwrap_or(""))
        })
        .expect("an id with its file");
    let id = format!("RTC:Lab:Sensor:Cam:1.0.0@{listed}");
    let o = run(&["graph", "in", "--component", &id]);
    assert!(
        o.status.success(),
        "the listed id works: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// A data connector saved without its data type: its tooltip and title name the two ports
/// only, with no empty `()` after them.
#[test]
fn a_connector_without_a_data_type_is_labelled_by_its_ends() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let with = common::naming_path_system("Demo");
    let without = with.replace(r#" rts:dataType="IDL:RTC/CameraImage:1.0""#, "");
    assert_ne!(with, without, "the fixture's connector has a data type");
    common::write(d, "with/Demo.xml", &with);
    common::write(d, "without/Demo.xml", &without);
    let dot = |input: &str| {
        let o = common::rtcdoc(&["graph", input, "-f", "dot"], d);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8(o.stdout).unwrap()
    };
    assert!(
        dot("with").contains(r#"tooltip="Cam0.out → View0.in (IDL:RTC/CameraImage:1.0)""#),
        "{}",
        dot("with")
    );
    let bare = dot("without");
    assert!(bare.contains(r#"tooltip="Cam0.out → View0.in""#), "{bare}");
    assert!(!bare.contains("()"), "{bare}");
}

/// A connector whose components are not in the catalogue is checked against the data types the
/// system file itself records for its ports (RTSystemEditor's `dataport.data_type`).
#[test]
fn a_connector_type_is_checked_against_the_types_the_system_records() {
    let text = read(&site_fixture().join("system/PatrolSystem.xml"));
    let recorded = |ty: &str| {
        text.replace(
            r#"<rtsExt:Properties rtsExt:name="port.port_type" rtsExt:value="DataOutPort"/>"#,
            &format!(
                r#"<rtsExt:Properties rtsExt:name="port.port_type" rtsExt:value="DataOutPort"/><rtsExt:Properties rtsExt:name="dataport.data_type" rtsExt:value="{ty}"/>"#
            ),
        )
    };
    let mismatches = |xml: &str| -> Vec<String> {
        let dir = tempfile::tempdir().unwrap();
        common::write(dir.path(), "in/PatrolSystem.xml", xml);
        let o = common::rtcdoc(&["check", "in", "--format", "json"], dir.path());
        let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
        json["diagnostics"]
            .as_array()
            .expect("diagnostics")
            .iter()
            .filter(|d| d["code"] == "RTC602")
            .map(|d| d["message"].as_str().unwrap_or_default().to_string())
            .collect()
    };
    let bad = recorded("IDL:RTC/TimedLong:1.0");
    assert_ne!(bad, text);
    assert_eq!(
        mismatches(&bad),
        ["connector `Camera0.image_Planner0.image` carries `IDL:RTC/CameraImage:1.0`, but port Camera0.image (as the system file records it) carries `RTC::TimedLong`"]
    );
    assert!(mismatches(&recorded("IDL:RTC/CameraImage:1.0")).is_empty());
    assert!(mismatches(&text).is_empty());
    // Both ends differ: one finding naming both.
    let both = bad.replace(
        r#"<rts:DataPorts rts:name="image"/>"#,
        r#"<rts:DataPorts rts:name="image"><rtsExt:Properties rtsExt:name="dataport.data_type" rtsExt:value="IDL:RTC/TimedLong:1.0"/></rts:DataPorts>"#,
    );
    assert_ne!(both, bad);
    assert_eq!(
        mismatches(&both),
        ["connector `Camera0.image_Planner0.image` carries `IDL:RTC/CameraImage:1.0`, but port Camera0.image (as the system file records it) carries `RTC::TimedLong` and port Planner0.image (as the system file records it) carries `RTC::TimedLong`"]
    );
}

/// Several profiles with the id an instance names (a component kept in two repositories, or
/// its C++ and Python variants): the instance is linked to the one nearest to the system file,
/// not to the first by path.
#[test]
fn an_instance_links_to_the_nearest_profile_of_its_id() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let cam = common::xml_profile("Cam", &[("DataOutPort", "out", "RTC::CameraImage")])
        .replace("RTC:Test:Cat:Cam:1.0.0", "RTC:Lab:Sensor:Cam:1.0.0")
        .replace(
            r#"rtc:vendor="Test" rtc:category="Cat""#,
            r#"rtc:vendor="Lab" rtc:category="Sensor""#,
        );
    common::write(d, "in/a_lab/Cam/RTC.xml", &cam);
    common::write(d, "in/b_lab/Cam/RTC.xml", &cam);
    common::write(
        d,
        "in/b_lab/systems/Demo.xml",
        &common::naming_path_system("Demo"),
    );
    let cat = load(&d.join("in"));
    let s = &cat.systems[0];
    let linked = cat.instance_component(s, 0).expect("Cam0 is linked");
    assert_eq!(linked.source, "b_lab/Cam/RTC.xml");
    // Moved beside the other copy, the system links to that one.
    std::fs::rename(d.join("in/b_lab/systems"), d.join("in/a_lab/systems")).expect("move");
    let cat = load(&d.join("in"));
    let linked = cat
        .instance_component(&cat.systems[0], 0)
        .expect("Cam0 is linked");
    assert_eq!(linked.source, "a_lab/Cam/RTC.xml");
}

/// A system profile that cannot be read (Shift_JIS bytes under a UTF-8 declaration) is its
/// error, even when it is the only file: not "nothing to document".
#[test]
fn an_unreadable_system_alone_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut bytes = b"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\" rts:id=\"RTSystem:V:S:1.0\" rts:comment=\"".to_vec();
    // 「画像」 in Shift_JIS.
    bytes.extend_from_slice(&[0x89, 0xe6, 0x91, 0x9c]);
    bytes.extend_from_slice(b"\"/>\n");
    std::fs::create_dir_all(d.join("in")).unwrap();
    std::fs::write(d.join("in/System.xml"), &bytes).unwrap();
    for input in ["in", "in/System.xml"] {
        let out = common::rtcdoc(&["check", input], d);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{input}: {err}");
        assert!(err.contains("error[RTC005]"), "{input}: {err}");
        assert!(err.contains("in/System.xml"), "{input}: {err}");
        assert!(!err.contains("nothing to document"), "{input}: {err}");
    }
}

/// `d/in` holding two components: `Src` (out-port `out`) and `Dst` (in-port `in`).
fn src_and_dst(d: &std::path::Path) -> PathBuf {
    let input = d.join("in");
    common::write(
        &input,
        "comps/Src/RTC.xml",
        &common::xml_profile("Src", &[("DataOutPort", "out", "RTC::TimedDouble")]),
    );
    common::write(
        &input,
        "comps/Dst/RTC.xml",
        &common::xml_profile("Dst", &[("DataInPort", "in", "RTC::TimedDouble")]),
    );
    input
}

/// An RT System instance `name` of component `comp` (vendor `Test`, category `Cat`) with data
/// port `port`.
fn instance_xml(name: &str, comp: &str, port: &str) -> String {
    format!(
        r#"<rts:Components rts:id="RTC:Test:Cat:{comp}:1.0.0" rts:instanceName="{name}" rts:pathUri="" rts:activeConfigurationSet="default" rts:isRequired="true" rts:compositeType="None"><rts:DataPorts rts:name="{name}.{port}"/></rts:Components>"#
    )
}

/// Two components, `Src` (out-port `out`) and `Dst` (in-port `in`), and a system `Rev` whose
/// one data connector `c1` is saved in-port first, as RTSystemEditor saves a connector dragged
/// from its in-port: source `Dst0.in`, target `Src0.out`.
fn reversed_connector_input(d: &std::path::Path) -> PathBuf {
    let input = src_and_dst(d);
    let inst = instance_xml;
    let xml = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?><rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" rts:id="RTSystem:Test:Rev:1.0" rts:version="0.2">{}{}<rts:DataPortConnectors rts:connectorId="c1" rts:name="in_out" rts:dataType="IDL:RTC/TimedDouble:1.0" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush"><rts:sourceDataPort rts:componentId="RTC:Test:Cat:Dst:1.0.0" rts:instanceName="Dst0" rts:portName="Dst0.in"/><rts:targetDataPort rts:componentId="RTC:Test:Cat:Src:1.0.0" rts:instanceName="Src0" rts:portName="Src0.out"/></rts:DataPortConnectors></rts:RtsProfile>"#,
        inst("Src0", "Src", "out"),
        inst("Dst0", "Dst", "in"),
    );
    common::write(&input, "system/Rev.xml", &xml);
    input
}

/// A data connector saved in-port first is listed the way data flows, as the diagrams draw it
/// (source the out-port, target the in-port), with a note of how the file saved it; the type
/// page's list of connectors says so too.
#[test]
fn a_connector_saved_in_port_first_is_listed_the_way_data_flows() {
    use rtcdoc::render::markdown;
    let dir = tempfile::tempdir().unwrap();
    let input = reversed_connector_input(dir.path());
    let out = dir.path().join("site");
    build_site(&input, &out, SiteOptions::default());
    let html = read(&out.join("systems/rev.html"));
    let data = section(&html, "data-connectors");
    let cells: Vec<&str> = data.split("<td data-label=").collect();
    assert!(
        cells[1].starts_with(r#""Source">"#)
            && cells[1].contains("Src0</a>.")
            && cells[1].contains("<code>out</code>"),
        "{data}"
    );
    assert!(
        cells[2].starts_with(r#""Target">"#)
            && cells[2].contains("Dst0</a>.")
            && cells[2].contains("<code>in</code>"),
        "{data}"
    );
    assert!(
        data.contains("saved in the file as: Dst0.in → Src0.out"),
        "{data}"
    );
    let cat = load(&input);
    let md: std::collections::BTreeMap<String, String> =
        markdown::pages(&cat, "Cat", rtcdoc::i18n::Lang::En)
            .into_iter()
            .collect();
    let page = &md["systems/rev.md"];
    assert!(
        page.contains("| in\\_out (saved in the file as: Dst0.in → Src0.out) | c1 | Src0.[out](../components/src.md#port-out) | Dst0.[in](../components/dst.md#port-in) |"),
        "{page}"
    );
    let ty = md
        .iter()
        .find(|(k, v)| k.starts_with("types/") && v.contains("Rev: "))
        .map(|(_, v)| v)
        .expect("a type page lists the connector");
    assert!(ty.contains("Rev: Src0.out → Dst0.in"), "{ty}");
    // The diagram agrees.
    let o = common::rtcdoc(&["graph", "in", "-f", "mermaid"], dir.path());
    let mermaid = String::from_utf8_lossy(&o.stdout);
    assert!(mermaid.contains("\"out → in\""), "{mermaid}");
}

/// A system of `Src0` (`Src`: out-port `out`) and `Dst0` (`Dst`: in-port `in`) with three
/// data connectors: `c1` Src0.out → Dst0.in, `c2` from `Src0.nosuchport` (a port `Src` does not
/// have, RTC601) and `c3` to `Ghost0.in` (no such instance, RTC608).
fn dangling_connector_input(d: &std::path::Path) -> PathBuf {
    let input = src_and_dst(d);
    let inst = instance_xml;
    let conn = |id: &str, (si, sp): (&str, &str), (ti, tp): (&str, &str)| {
        format!(
            r#"<rts:DataPortConnectors rts:connectorId="{id}" rts:name="{sp}_{tp}" rts:dataType="IDL:RTC/TimedDouble:1.0" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush"><rts:sourceDataPort rts:componentId="RTC:Test:Cat:Src:1.0.0" rts:instanceName="{si}" rts:portName="{si}.{sp}"/><rts:targetDataPort rts:componentId="RTC:Test:Cat:Dst:1.0.0" rts:instanceName="{ti}" rts:portName="{ti}.{tp}"/></rts:DataPortConnectors>"#
        )
    };
    let xml = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?><rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" rts:id="RTSystem:Test:Hostile:1.0" rts:version="0.2">{}{}{}{}{}</rts:RtsProfile>"#,
        inst("Src0", "Src", "out"),
        inst("Dst0", "Dst", "in"),
        conn("c1", ("Src0", "out"), ("Dst0", "in")),
        conn("c2", ("Src0", "nosuchport"), ("Dst0", "in")),
        conn("c3", ("Src0", "out"), ("Ghost0", "in")),
    );
    common::write(&input, "system/Hostile.xml", &xml);
    input
}

/// A connector that cannot be drawn (its end names no instance of the system) is named, with
/// the reason, by every drawing and caption instead of vanishing; a port the component's profile
/// does not have is drawn in a style of its own.
#[test]
fn a_connector_left_out_of_the_drawing_is_named_with_its_reason() {
    use rtcdoc::render::markdown;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = dangling_connector_input(d);
    let note = "Not drawn: out_in [c3] (Src0.out → Ghost0.in): the system has no instance Ghost0";
    let graph = |format: &str| {
        let o = common::rtcdoc(&["graph", "in", "-f", format], d);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(String::from_utf8_lossy(&o.stderr).contains(note));
        String::from_utf8(o.stdout).unwrap()
    };
    let dot = graph("dot");
    // DOT draws no port squares: no legend of them (the SVG has it, below).
    let legend =
        "Dotted square: a port not in its component's profile (or its instance's port list) (Src0)";
    assert!(dot.contains(&format!("label=\"{note}\\l\"")), "{dot}");
    assert_eq!(dot.matches(" -> ").count(), 2, "{dot}");
    assert!(dot.contains("<i>nosuchport</i> ?"), "{dot}");
    let mermaid = graph("mermaid");
    assert!(mermaid.contains(&format!("%% {note}")), "{mermaid}");
    let svg = graph("svg");
    assert!(
        svg.contains("<text class=\"not-drawn\" x=\"8\"") && svg.contains(note),
        "{svg}"
    );
    assert!(svg.contains(r#"class="port out unknown" aria-label="out-port Src0.nosuchport (not in the component&#39;s profile)""#), "{svg}");
    assert!(
        svg.contains(r#"<text class="legend" x="8" y="#)
            && svg.contains(&legend.replace('\'', "&#39;")),
        "{svg}"
    );
    assert!(
        svg.contains(r#"class="port out" aria-label="out-port Src0.out""#),
        "{svg}"
    );
    // The page's caption counts the file's connectors and names the one left out.
    let out = d.join("site");
    build_site(&input, &out, SiteOptions::default());
    let html = read(&out.join("systems/hostile.html"));
    let caption = &html[html.find("<figcaption>").unwrap()..html.find("</figcaption>").unwrap()];
    assert!(caption.contains("3 data connectors"), "{caption}");
    assert!(caption.contains(&format!("{note}.")), "{caption}");
    let md: std::collections::BTreeMap<String, String> = markdown::pages(
        &rtcdoc::build::load(&input, &LoadOptions::default())
            .unwrap()
            .catalog,
        "Cat",
        rtcdoc::i18n::Lang::En,
    )
    .into_iter()
    .collect();
    let page = &md["systems/hostile.md"];
    assert!(page.contains("Not drawn: out\\_in \\[c3\\]"), "{page}");
}

/// The wiring diagram comes right after the summary in every output, as on the HTML page:
/// Markdown (an SVG beside the page, or a Mermaid block) and Doxygen (the SVG beside the page,
/// `\image html`), before the instances and long before every value of the file.
#[test]
fn the_wiring_diagram_follows_the_summary_in_every_output() {
    use rtcdoc::render::{doxygen, markdown};
    let cat = load(&site_fixture());
    let lang = rtcdoc::i18n::Lang::En;
    let order = |page: &str, marks: &[&str]| {
        let at: Vec<usize> = marks
            .iter()
            .map(|m| {
                page.find(m)
                    .unwrap_or_else(|| panic!("no {m:?} in\n{page}"))
            })
            .collect();
        assert!(
            at.windows(2).all(|w| w[0] < w[1]),
            "{marks:?} out of order in\n{page}"
        );
    };
    let md: std::collections::BTreeMap<String, String> =
        markdown::pages(&cat, "Cat", lang).into_iter().collect();
    order(
        &md["systems/patrolsystem.md"],
        &[
            "| System id |",
            "## Wiring of PatrolSystem",
            "![Wiring of PatrolSystem](patrolsystem.svg)",
            "## Instances",
            "## Every value of the file",
        ],
    );
    assert!(md["systems/patrolsystem.svg"].contains("<svg"));
    let dox: std::collections::BTreeMap<String, String> =
        doxygen::pages(&cat, "Cat", lang).into_iter().collect();
    order(
        &dox["systems/patrolsystem.dox"],
        &[
            "<td>System id</td>",
            "\\section rtc_sys_patrolsystem__sec_wiring Wiring of PatrolSystem",
            "/// \\image html patrolsystem.svg\n",
            "\\section rtc_sys_patrolsystem__instances Instances",
            "Every value of the file",
        ],
    );
    assert!(dox["systems/patrolsystem.svg"].contains("<svg"));
    assert!(dox["Doxyfile"].contains("IMAGE_PATH             = systems\n"));
    assert!(
        !dox["Doxyfile"].contains("patrolsystem.svg"),
        "an image, not an input"
    );
    // Mermaid, where the configuration asks for it: the same place.
    let dir = tempfile::tempdir().unwrap();
    common::write(
        dir.path(),
        "rtcdoc.toml",
        "[markdown]\ndiagrams = \"mermaid\"\n",
    );
    let out = dir.path().join("md");
    let o = common::rtcdoc(
        &[
            "build",
            site_fixture().to_str().unwrap(),
            "-f",
            "markdown",
            "-o",
            out.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    order(
        &read(&out.join("systems/patrolsystem.md")),
        &[
            "| System id |",
            "```mermaid",
            "## Instances",
            "## Every value of the file",
        ],
    );
}

/// A composite instance (RTSystemEditor's `PeriodicECShared` with participants) shows its
/// members, each linked to its row, and each member the composite it belongs to, on the HTML
/// page and in the Markdown one.
#[test]
fn a_composite_instance_lists_its_members() {
    use rtcdoc::render::markdown;
    let dir = tempfile::tempdir().unwrap();
    let inst = |name: &str, composite: &str, inner: &str| {
        format!(
            r#"<rts:Components rts:id="RTC:Lab:Test:{name}:1.0.0" rts:instanceName="{name}" rts:pathUri="" rts:activeConfigurationSet="default" rts:isRequired="true" rts:compositeType="{composite}">{inner}</rts:Components>"#
        )
    };
    let member = |name: &str| {
        format!(
            r#"<rts:Participants><rts:Participant rts:instanceName="{name}" rts:componentId="RTC:Lab:Test:{name}:1.0.0"/></rts:Participants>"#
        )
    };
    let xml = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?><rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" rts:id="RTSystem:Lab:Comp:1.0" rts:version="0.2">{}{}{}{}</rts:RtsProfile>"#,
        inst("A0", "None", ""),
        inst("B0", "None", ""),
        inst("C0", "None", ""),
        inst(
            "CompositeRTC",
            "PeriodicECShared",
            &format!("{}{}", member("A0"), member("B0"))
        ),
    );
    common::write(dir.path(), "in/Comp.xml", &xml);
    let out = dir.path().join("site");
    build_site(&dir.path().join("in"), &out, SiteOptions::default());
    let html = read(&out.join("systems/comp.html"));
    let inst = section(&html, "instances");
    assert!(
        inst.contains(
            r##"PeriodicECShared<br>Members: <a href="#inst-a0">A0</a>, <a href="#inst-b0">B0</a>"##
        ),
        "{inst}"
    );
    assert_eq!(
        inst.matches(r##"<br>member of <a href="#inst-compositertc">CompositeRTC</a>"##)
            .count(),
        2,
        "{inst}"
    );
    let cat = load(&dir.path().join("in"));
    let md: std::collections::BTreeMap<String, String> =
        markdown::pages(&cat, "Cat", rtcdoc::i18n::Lang::En)
            .into_iter()
            .collect();
    let page = &md["systems/comp.md"];
    assert!(
        page.contains("| PeriodicECShared; Members: A0, B0 |"),
        "{page}"
    );
    assert!(page.contains("| None; member of CompositeRTC |"), "{page}");
    assert!(!page.contains("C0 | None; member"), "{page}");
    // The wiring diagram: the composite with a double outline, its members dashed, C0 plain;
    // each box's name says what it is, and the caption what the outlines mean.
    let svg = section(&html, "diagram");
    let legend = "Double outline: composite component (CompositeRTC); dashed outline: member of a composite (A0, B0)";
    assert!(svg.contains(legend), "{svg}");
    assert!(svg.contains(r##"<g class="instance composite"><a href="#inst-compositertc" aria-label="CompositeRTC CompositeRTC (Instance, Composite type: PeriodicECShared, Members: A0, B0)">"##), "{svg}");
    assert_eq!(
        svg.matches(r#"<rect class="rtc-box-inner""#).count(),
        1,
        "{svg}"
    );
    assert!(svg.contains(r##"<g class="instance member"><a href="#inst-a0" aria-label="A0 A0 (Instance, member of: CompositeRTC)">"##), "{svg}");
    assert_eq!(
        svg.matches(r#"<g class="instance member">"#).count(),
        2,
        "{svg}"
    );
    assert!(
        svg.contains(r##"<g class="instance"><a href="#inst-c0""##),
        "{svg}"
    );
    assert!(page.contains(&format!("{legend}.")), "{page}");
    let alone = read(&out.join("systems/comp.svg"));
    assert!(
        alone.contains(r#"<text class="legend" x="8""#) && alone.contains(legend),
        "{alone}"
    );
    let mmd = common::rtcdoc(&["graph", "in/Comp.xml", "-f", "mermaid"], dir.path());
    let mmd = String::from_utf8_lossy(&mmd.stdout);
    assert!(
        mmd.contains("  n3[[\"CompositeRTC<br/><small>CompositeRTC</small>\"]]\n"),
        "{mmd}"
    );
    assert!(
        mmd.contains("  classDef member stroke-dasharray:6 3\n  class n0,n1 member\n"),
        "{mmd}"
    );
    let dot = common::rtcdoc(&["graph", "in/Comp.xml", "-f", "dot"], dir.path());
    let (dot, note) = (
        String::from_utf8_lossy(&dot.stdout),
        String::from_utf8_lossy(&dot.stderr),
    );
    assert!(dot.contains(r#"n0 [label=<<table border="1" cellborder="0" cellspacing="0" cellpadding="3" style="dashed">"#), "{dot}");
    assert!(dot.contains(r#"n3 [label=<<table border="1" cellborder="0" cellspacing="2" cellpadding="0"><tr><td border="1"><table border="0""#), "{dot}");
    assert!(dot.contains(legend), "{dot}");
    // The legend is no note on stderr (those name connectors left out).
    assert!(!note.contains("outline"), "{note}");
}

/// An unnamed composite (a `Grouping`) with a connector that cannot be drawn: the drawing on
/// its own keeps the connector's note a warning and the legend an explanation, the legend
/// names each instance once and none by an empty name, and DOT gives Graphviz a label it
/// reads.
#[test]
fn an_unnamed_composite_and_a_connector_not_drawn() {
    let dir = tempfile::tempdir().unwrap();
    let comp = |name: &str, kind: &str, inner: &str| {
        format!(
            r#"<rts:Components rts:id="RTC:Lab:Test:C:1.0.0" rts:instanceName="{name}" rts:pathUri="" rts:activeConfigurationSet="default" rts:isRequired="true" rts:compositeType="{kind}"><rts:DataPorts rts:name="{name}.out"/>{inner}</rts:Components>"#
        )
    };
    let part = r#"<rts:Participants><rts:Participant rts:instanceName="M0" rts:componentId="RTC:Lab:Test:C:1.0.0"/></rts:Participants><rts:Participants><rts:Participant rts:instanceName="M0" rts:componentId="RTC:Lab:Test:C:1.0.0"/></rts:Participants>"#;
    let conn = r#"<rts:DataPortConnectors rts:connectorId="c1" rts:name="c1" rts:dataType="IDL:RTC/TimedLong:1.0" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush"><rts:sourceDataPort rts:portName="M0.out" rts:instanceName="M0" rts:componentId="RTC:Lab:Test:C:1.0.0"/><rts:targetDataPort rts:portName="Nobody.in" rts:instanceName="Nobody" rts:componentId="RTC:Lab:Test:C:1.0.0"/></rts:DataPortConnectors>"#;
    let xml = rts_system(
        "Un",
        &[&comp("M0", "None", ""), &comp("", "Grouping", part), conn],
    );
    common::write(dir.path(), "in/Un.xml", &xml);
    let svg = common::rtcdoc(&["graph", "in/Un.xml", "-f", "svg"], dir.path());
    let svg = String::from_utf8_lossy(&svg.stdout);
    let text = |class: &str| -> Vec<&str> {
        svg.split(&format!(r#"<text class="{class}" x="8""#))
            .skip(1)
            .map(|t| &t[t.find('>').unwrap() + 1..t.find("</text>").unwrap()])
            .collect()
    };
    assert_eq!(text("not-drawn").len(), 1, "{svg}");
    assert!(text("not-drawn")[0].starts_with("Not drawn: c1"), "{svg}");
    assert_eq!(
        text("legend"),
        ["Double outline: composite component; dashed outline: member of a composite (M0); hollow square: a port of unknown kind"],
        "{svg}"
    );
    let dot = common::rtcdoc(&["graph", "in/Un.xml", "-f", "dot"], dir.path());
    let dot = String::from_utf8_lossy(&dot.stdout).into_owned();
    assert!(dot.contains("<b> </b>"), "{dot}");
    if common::tool_available("dot") {
        let out = std::process::Command::new("dot")
            .args(["-Tsvg", "-o", "/dev/null"])
            .stdin(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .and_then(|mut c| {
                use std::io::Write as _;
                c.stdin.take().expect("stdin").write_all(dot.as_bytes())?;
                c.wait_with_output()
            })
            .expect("run dot");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// An instance whose id names the instance, as Choreonoid saves it
/// (`RTC:Test:Cat:Ctl0:1.0.0` for instance `Ctl0` of component `Ctl`): RTC603 points at the
/// component the input has, and writing the id it names links the instance.
#[test]
fn an_id_naming_the_instance_points_at_the_component() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(d, "in/Ctl/RTC.xml", &common::xml_profile("Ctl", &[]));
    // The RTC603 findings of the system whose instance `Ctl0` names `id_name` in its id.
    let rtc603 = |id_name: &str| {
        let system = rts_system("Cho", &[&instance_xml("Ctl0", id_name, "out")]);
        common::write(d, "in/sys/Cho.xml", &system);
        common::findings(d, "in", &["RTC603"])
    };
    let hint = |found: &[serde_json::Value]| found[0]["hint"].as_str().unwrap_or("").to_string();
    let found = rtc603("Ctl0");
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(
        hint(&found),
        "the id names `Ctl0`, an instance's name (as Choreonoid saves it); the input has the component `Ctl` (Ctl/RTC.xml, id `RTC:Test:Cat:Ctl:1.0.0`): write that id in the system file",
        "{found:?}"
    );
    // Followed: no finding.
    assert_eq!(rtc603("Ctl"), Vec::<serde_json::Value>::new());
    // Two profiles of that id (C++ and Python copies): the hint still names the id as written,
    // which links the instance.
    common::write(d, "in/Ctl2/RTC.xml", &common::xml_profile("Ctl", &[]));
    let found = rtc603("Ctl0");
    assert!(
        hint(&found).contains("id `RTC:Test:Cat:Ctl:1.0.0`)"),
        "{found:?}"
    );
    assert_eq!(rtc603("Ctl"), Vec::<serde_json::Value>::new());
    // A name that only ends in a digit, without such a component, keeps the general hint.
    let found = rtc603("Other2");
    assert!(
        hint(&found).starts_with("add the component's RTC.xml"),
        "{found:?}"
    );
}

/// A connector end naming a port its instance does not list, when the component is not in the
/// catalogue: the system file's own port list is the reference (RTC601), as for a misspelt
/// `Comp3_inort2` beside the listed `Comp3_inport2`; an instance that lists no ports says
/// nothing of its connectors.
#[test]
fn a_connector_end_not_among_the_instances_listed_ports_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let conn = |to: &str| {
        format!(
            r#"<rts:DataPortConnectors rts:connectorId="c1" rts:name="c1"><rts:sourceDataPort rts:portName="A0.out" rts:instanceName="A0" rts:componentId="RTC:Test:Cat:A:1.0.0"/><rts:targetDataPort rts:portName="B0.{to}" rts:instanceName="B0" rts:componentId="RTC:Test:Cat:B:1.0.0"/></rts:DataPortConnectors>"#
        )
    };
    let system = |to: &str| {
        rts_system(
            "P",
            &[
                &instance_xml("A0", "A", "out"),
                &instance_xml("B0", "B", "inport2"),
                &conn(to),
            ],
        )
    };
    common::write(d, "in/P.xml", &system("inort2"));
    let found = common::findings(d, "in", &["RTC601"]);
    let messages: Vec<&str> = found.iter().filter_map(|f| f["message"].as_str()).collect();
    assert_eq!(
        messages,
        ["connector end `B0.inort2`: instance `B0` lists no port `inort2` in the system file (it lists `inport2`)"]
    );
    // The drawing marks that port as it marks one a profile lacks: dotted, named in the
    // legend, and said in its label; the listed port is drawn as any other.
    let out = d.join("site");
    build_site(&d.join("in"), &out, SiteOptions::default());
    let svg = read(&out.join("systems/p.svg"));
    assert!(
        svg.contains(r#"class="port in unknown" aria-label="in-port B0.inort2 (not among the instance&#39;s ports in the system file)""#),
        "{svg}"
    );
    assert!(svg.contains(r#"aria-label="Port B0.inport2""#), "{svg}");
    assert!(
        svg.contains("dotted square: a port not in its component&#39;s profile (or its instance&#39;s port list) (B0)"),
        "{svg}"
    );
    common::write(d, "in/P.xml", &system("inport2"));
    assert!(common::findings(d, "in", &["RTC601"]).is_empty());
    // The instance lists its data ports only: a service connector's end is not judged by
    // them; a port listed under another instance's prefix matches by its last part.
    let service = r#"<rts:ServicePortConnectors rts:connectorId="s1" rts:name="s1"><rts:sourceServicePort rts:portName="A0.svc" rts:instanceName="A0" rts:componentId="RTC:Test:Cat:A:1.0.0"/><rts:targetServicePort rts:portName="B0.svc" rts:instanceName="B0" rts:componentId="RTC:Test:Cat:B:1.0.0"/></rts:ServicePortConnectors>"#;
    let renamed = system("inport2")
        .replace(r#"rts:name="B0.inport2""#, r#"rts:name="Old0.inport2""#)
        .replace("</rts:RtsProfile>", &format!("{service}</rts:RtsProfile>"));
    common::write(d, "in/P.xml", &renamed);
    assert_eq!(
        common::findings(d, "in", &["RTC601"]),
        Vec::<serde_json::Value>::new()
    );
    // No ports listed: nothing to compare with.
    common::write(
        d,
        "in/P.xml",
        &system("inort2").replace(r#"<rts:DataPorts rts:name="B0.inport2"/>"#, ""),
    );
    assert!(common::findings(d, "in", &["RTC601"]).is_empty());
}

/// The legend names at most five instances a mark, then how many more: under a large system
/// it stays one line (the drawing on its own is as wide as its widest note).
#[test]
fn the_legend_names_five_instances_and_counts_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let instances: String = (0..7)
        .map(|i| instance_xml(&format!("I{i}"), "Gone", "p"))
        .collect();
    common::write(d, "in/Big.xml", &rts_system("Big", &[&instances]));
    let o = common::rtcdoc(&["graph", "in", "-f", "svg"], d);
    let svg = String::from_utf8_lossy(&o.stdout);
    assert!(
        svg.contains(r#"<text class="legend" x="8" y="#)
            && svg.contains(
                ">Hollow square: a port of unknown kind (I0, I1, I2, I3, I4, +2 more)</text>"
            ),
        "{svg}"
    );
}

/// A connector typed by a repository id under a `#pragma prefix`
/// (`IDL:example.com/Lab/Pose:1.0`) carries the type its ports name `Lab::Pose`: no false
/// RTC602, and the type's page lists the connector.
#[test]
fn a_prefixed_repository_id_on_a_connector_is_the_type_it_names() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(
        d,
        "in/idl/Lab.idl",
        "#pragma prefix \"example.com\"\nmodule Lab { struct Pose { long x; }; };\n",
    );
    common::write(
        d,
        "in/Src/RTC.xml",
        &common::xml_profile("Src", &[("DataOutPort", "out", "Lab::Pose")]),
    );
    common::write(
        d,
        "in/Dst/RTC.xml",
        &common::xml_profile("Dst", &[("DataInPort", "in", "Lab::Pose")]),
    );
    let system = |ty: &str| {
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?><rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" rts:id="RTSystem:Lab:Pre:1.0" rts:version="0.2">{}{}<rts:DataPortConnectors rts:connectorId="c1" rts:name="pose" rts:dataType="{ty}" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush"><rts:sourceDataPort rts:portName="Src0.out" rts:instanceName="Src0" rts:componentId="RTC:Test:Cat:Src:1.0.0"/><rts:targetDataPort rts:portName="Dst0.in" rts:instanceName="Dst0" rts:componentId="RTC:Test:Cat:Dst:1.0.0"/></rts:DataPortConnectors></rts:RtsProfile>"#,
            instance_xml("Src0", "Src", "out"),
            instance_xml("Dst0", "Dst", "in")
        )
    };
    common::write(d, "in/sys/Pre.xml", &system("IDL:example.com/Lab/Pose:1.0"));
    assert_eq!(
        common::findings(d, "in", &["RTC602"]),
        Vec::<serde_json::Value>::new()
    );
    let cat = load(&d.join("in"));
    assert_eq!(cat.connectors_carrying("Lab::Pose").len(), 1);
    // Another type is still one.
    common::write(d, "in/sys/Pre.xml", &system("IDL:RTC/TimedLong:1.0"));
    assert_eq!(common::findings(d, "in", &["RTC602"]).len(), 1);
}

/// Systems sharing a name (RTSystemEditor's `DefaultSystem01`) get their qualifier in the page
/// slug, as in their titles: `defaultsystem01-kobuki` for `DefaultSystem01 (kobuki)`, not a
/// hash of the file.
#[test]
fn systems_sharing_a_name_have_readable_slugs() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for folder in ["kobuki", "nao"] {
        common::write(
            d,
            &format!("in/{folder}/System.xml"),
            &common::naming_path_system("DefaultSystem01"),
        );
    }
    common::write(d, "in/other/Solo.xml", &common::naming_path_system("Solo"));
    let cat = load(&d.join("in"));
    let got: Vec<(String, String)> = cat
        .systems
        .iter()
        .map(|s| (s.slug.clone(), s.display_name().into_owned()))
        .collect();
    assert_eq!(
        got,
        [
            (
                "defaultsystem01-kobuki".to_string(),
                "DefaultSystem01 (kobuki)".to_string()
            ),
            (
                "defaultsystem01-nao".to_string(),
                "DefaultSystem01 (nao)".to_string()
            ),
            ("solo".to_string(), "Solo".to_string()),
        ]
    );
    // A qualified slug equal to another system's own slug: the plain one keeps it, every page
    // gets its own file.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (folder, name) in [("a", "Demo X"), ("x", "Demo"), ("x-2", "Demo")] {
        common::write(
            d,
            &format!("in/{folder}/S.xml"),
            &common::naming_path_system(name),
        );
    }
    let cat = load(&d.join("in"));
    let mut slugs: Vec<&str> = cat.systems.iter().map(|s| s.slug.as_str()).collect();
    assert_eq!(slugs[0], "demo-x", "{slugs:?}");
    slugs.sort();
    slugs.dedup();
    assert_eq!(slugs.len(), 3, "{slugs:?}");
}

/// An RT System profile `RTSystem:Lab:<name>:1.0` holding `parts` (its components and
/// connectors as XML), as RTSystemEditor writes one.
fn rts_system(name: &str, parts: &[&str]) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?><rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" rts:id="RTSystem:Lab:{name}:1.0" rts:version="0.2">{}</rts:RtsProfile>"#,
        parts.concat()
    )
}

/// Whether an instance is required reads as yes or no in the page's language, as the
/// lifecycle table says whether an action is implemented; a value that is no boolean is shown
/// as written.
#[test]
fn required_instances_read_as_yes_or_no() {
    let dir = tempfile::tempdir().unwrap();
    let instance = |name: &str, required: &str| {
        format!(
            r#"<rts:Components rts:id="RTC:Lab:C:{name}:1.0" rts:instanceName="{name}0" rts:pathUri="" rts:activeConfigurationSet="default" rts:isRequired="{required}" rts:compositeType="None"/>"#
        )
    };
    let (a, b, c) = (
        instance("A", "true"),
        instance("B", "false"),
        instance("C", "maybe"),
    );
    common::write(dir.path(), "in/Req.xml", &rts_system("Req", &[&a, &b, &c]));
    for (language, label, yes, no) in [
        (rtcdoc::i18n::Lang::En, "Required", "yes", "no"),
        (rtcdoc::i18n::Lang::Ja, "必須", "はい", "いいえ"),
    ] {
        let out = dir.path().join(format!("{language:?}"));
        build_site(
            &dir.path().join("in"),
            &out,
            SiteOptions {
                language,
                ..Default::default()
            },
        );
        let html = read(&out.join("systems/req.html"));
        let cells: Vec<&str> = html
            .split(&format!(r#"<td class="nowrap" data-label="{label}">"#))
            .skip(1)
            .map(|rest| rest.split("</td>").next().unwrap_or(""))
            .collect();
        assert_eq!(cells, [yes, no, "maybe"], "{html}");
    }
}

/// A Comment column empty in every row of a system page's table is left out, in HTML and
/// Markdown alike; one comment brings it back, with the rows that have none left blank.
#[test]
fn empty_comment_columns_are_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (a, b) = (
        instance_xml("A0", "A", "out"),
        instance_xml("B0", "B", "in"),
    );
    let conn = r#"<rts:DataPortConnectors rts:connectorId="c1" rts:name="c1"><rts:sourceDataPort rts:portName="A0.out" rts:instanceName="A0"/><rts:targetDataPort rts:portName="B0.in" rts:instanceName="B0"/></rts:DataPortConnectors>"#;
    let build = |xml: &str| {
        common::write(d, "in/S.xml", xml);
        let o = common::rtcdoc(
            &["build", "in", "-o", "out", "-f", "html,markdown", "-q"],
            d,
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        (
            read(&d.join("out/html/systems/s.html")),
            read(&d.join("out/markdown/systems/s.md")),
        )
    };
    let (html, md) = build(&rts_system("S", &[&a, &b, conn]));
    assert!(!html.contains(r#"data-label="Comment""#), "{html}");
    assert!(!html.contains(r#"<th scope="col">Comment</th>"#), "{html}");
    assert!(!md.contains("| Comment |"), "{md}");
    let commented = a.replace(
        r#"rts:compositeType="None">"#,
        r#"rts:compositeType="None" rtsExt:comment="front camera" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext">"#,
    );
    let (html, md) = build(&rts_system("S", &[&commented, &b, conn]));
    // The instances table has the column (B0's cell blank); the connector tables still do not.
    assert_eq!(
        html.matches(r#"<th scope="col">Comment</th>"#).count(),
        1,
        "{html}"
    );
    assert!(
        html.contains(r#"<td data-label="Comment">front camera</td>"#),
        "{html}"
    );
    assert!(html.contains(r#"<td data-label="Comment"></td>"#), "{html}");
    assert_eq!(md.matches("| Comment |").count(), 1, "{md}");
}

/// In a YAML system whose list items start with a `-` alone on its line (as rtshell and
/// rtsprofile write them), each instance is placed at its own `-`, not at the end of the item
/// before it.
#[test]
fn yaml_items_after_a_lone_dash_are_placed_at_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let item = |name: &str| {
        format!(
            "    -\n      id: \"RTC:Lab:C:{name}:1.0\"\n      instanceName: \"{name}0\"\n      isRequired: true\n"
        )
    };
    let yaml = format!(
        "rtsProfile:\n  id: \"RTSystem:Lab:S:1.0\"\n  version: \"0.2\"\n  components:\n{}{}",
        item("Ghost"),
        item("Other")
    );
    common::write(d, "in/sys.yaml", &yaml);
    let found = common::findings(d, "in", &["RTC603"]);
    let at: Vec<(u64, u64)> = found
        .iter()
        .map(|f| {
            (
                f["line"].as_u64().unwrap_or(0),
                f["column"].as_u64().unwrap_or(0),
            )
        })
        .collect();
    assert_eq!(at, [(5, 5), (9, 5)], "{found:?}");
    // Flow style on one line: each item at its own `{`, its keys read.
    let flow = "rtsProfile:\n  id: \"RTSystem:Lab:S:1.0\"\n  components: [{id: \"RTC:Lab:C:Ghost:1.0\", instanceName: \"Ghost0\", isRequired: true}, {id: \"RTC:Lab:C:Other:1.0\", instanceName: \"Other0\", isRequired: false}]\n  dataPortConnectors: []\n";
    common::write(d, "in/sys.yaml", flow);
    let found = common::findings(d, "in", &["RTC603"]);
    let at: Vec<(u64, u64, bool)> = found
        .iter()
        .map(|f| {
            let m = f["message"].as_str().unwrap_or("");
            (
                f["line"].as_u64().unwrap_or(0),
                f["column"].as_u64().unwrap_or(0),
                m.contains("Other0") || m.contains("Ghost0"),
            )
        })
        .collect();
    assert_eq!(at, [(3, 16, true), (3, 87, true)], "{found:?}");
}
