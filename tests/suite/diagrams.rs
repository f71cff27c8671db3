//! Diagrams a reader can trust (#26): the wiring layout's geometry on hand-made systems (no
//! browser), the exports run through the real tools (Graphviz `dot`, Mermaid's own parser),
//! and every diagram of the example and corpus sites measured in headless Chromium.

use crate::common;
use common::OutputWithin;

use rtcdoc::layout::wiring::{layout, problems, shared_tracks, Edge, Node, Port, PortKind};
use std::path::Path;

fn node(name: &str, ports: &[(&str, PortKind)], location: Option<(i64, i64)>) -> Node {
    Node {
        name: name.into(),
        component: format!("{name}Component"),
        ports: ports
            .iter()
            .map(|(n, k)| Port {
                name: n.to_string(),
                kind: *k,
            })
            .collect(),
        location,
    }
}

fn edge(from: (usize, usize), to: (usize, usize), service: bool) -> Edge {
    Edge { from, to, service }
}

#[test]
fn a_generated_40_instance_system_is_sound() {
    use PortKind::*;
    // Stages fed by earlier ones (some far back, some cycles), a service bus, isolated nodes.
    let n = 40;
    let nodes: Vec<Node> = (0..n)
        .map(|i| {
            node(
                &format!("Stage{i}"),
                &[("in", In), ("aux", In), ("out", Out), ("svc", Service)],
                None,
            )
        })
        .collect();
    let mut edges = Vec::new();
    for i in 1..n {
        edges.push(edge((i / 2, 2), (i, 0), false));
        if i % 7 == 0 {
            edges.push(edge((i, 2), (i / 3, 1), false)); // back edge
        }
        if i % 5 == 0 {
            edges.push(edge((i, 3), ((i + 3) % n, 3), true));
        }
    }
    let l = layout(&nodes, &edges);
    let p = problems(&l);
    assert!(p.is_empty(), "{p:#?}");
    assert!(l.routes.iter().all(Option::is_some));
    // Readable: text is not shrunk, the drawing grows instead.
    assert!(l.width > 600.0 && l.height > 300.0);
}

/// A generated system of `n` instances (two in-ports, two out-ports, a service port `srv` and
/// a client port `cli` each): each fed by earlier ones, and about `n / 7` service connectors
/// between instances far apart, the pairs drawn by a fixed pseudo-random sequence (`seed`).
fn generated_system(n: usize, seed: u64) -> (Vec<Node>, Vec<Edge>) {
    use PortKind::*;
    let mut state = seed;
    let mut next = |m: usize| {
        // A linear congruential generator (Knuth's MMIX constants): the same pairs every run.
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 33) as usize) % m
    };
    let nodes: Vec<Node> = (0..n)
        .map(|i| {
            node(
                &format!("Node{i}"),
                &[
                    ("in1", In),
                    ("in2", In),
                    ("out1", Out),
                    ("out2", Out),
                    ("srv", Service),
                    ("cli", Service),
                ],
                None,
            )
        })
        .collect();
    let mut edges = Vec::new();
    for i in 1..n {
        edges.push(edge((next(i), 2 + next(2)), (i, 0), false));
        if next(3) == 0 {
            edges.push(edge((next(i), 2 + next(2)), (i, 1), false));
        }
    }
    for _ in 0..n / 7 {
        let (a, b) = (next(n), next(n));
        if a != b {
            edges.push(edge((a, 5), (b, 4), true));
        }
    }
    (nodes, edges)
}

/// Every connector has its own track where it would overlap another (no two unrelated
/// connectors run along one line, so that one seems to branch into the other), in large
/// generated systems such as the 200-instance one where two service connectors shared a
/// horizontal run (a port of one at the height another passed the layer before).
#[test]
fn no_two_connectors_share_a_track_in_large_generated_systems() {
    for (n, seed) in [(200, 1), (200, 7), (120, 3), (60, 11)] {
        let (nodes, edges) = generated_system(n, seed);
        let l = layout(&nodes, &edges);
        let shared = shared_tracks(&l, &edges);
        assert!(shared.is_empty(), "{n} instances, seed {seed}: {shared:#?}");
        let p = problems(&l);
        assert!(p.is_empty(), "{n} instances, seed {seed}: {p:#?}");
    }
}

#[test]
fn a_service_connector_between_two_right_hand_ports_goes_around() {
    use PortKind::*;
    // a and b in one column (no data between them), both with their service port on the right.
    let nodes = vec![
        node("src", &[("out", Out)], None),
        node("a", &[("in", In), ("svc", Service)], None),
        node("b", &[("in", In), ("svc", Service)], None),
    ];
    let edges = vec![
        edge((0, 0), (1, 0), false),
        edge((0, 0), (2, 0), false),
        edge((1, 1), (2, 1), true),
    ];
    let l = layout(&nodes, &edges);
    assert!(problems(&l).is_empty(), "{:?}", problems(&l));
    assert_eq!(l.nodes[1].x, l.nodes[2].x, "same column");
    let r = l.routes[2].as_ref().expect("routed");
    // Out to the right and back: every point at or right of the boxes' right edge.
    let right = l.nodes[1].x + l.nodes[1].w;
    assert!(r.iter().all(|p| p.0 >= right - 0.01), "{r:?}");
}

#[test]
fn very_long_names_are_whole_and_inside_their_box() {
    use PortKind::*;
    let long = "ManipulatorCommonInterface_Middle.ManipulatorCommonInterface_Middle";
    let nodes = vec![
        node(
            "ManipulatorControllerWithAnUnusuallyLongInstanceName0",
            &[
                (long, Service),
                ("jointPositionsMeasuredByTheEncodersInRadians", Out),
            ],
            None,
        ),
        node("画像ビューア0", &[("入力画像", In)], None),
    ];
    let edges = vec![edge((0, 1), (1, 0), false)];
    let l = layout(&nodes, &edges);
    assert!(problems(&l).is_empty(), "{:?}", problems(&l));
    let b = &l.nodes[0];
    assert!(b.title.lines.len() >= 2, "wrapped: {:?}", b.title);
    assert_eq!(b.title.lines.concat(), nodes[0].name);
    assert_eq!(b.ports[0].lines.concat(), long);
    assert!(b.ports[0].lines.len() >= 2);
    assert!(!format!("{l:?}").contains('…'));
}

#[test]
fn saved_locations_keep_the_arrangement_and_connectors_go_around() {
    use PortKind::*;
    // The consumer saved left of its producer: the connector must pass around both boxes.
    let nodes = vec![
        node("consumer", &[("in", In)], Some((0, 0))),
        node("producer", &[("out", Out)], Some((400, 0))),
        node("below", &[("in", In), ("out", Out)], Some((0, 300))),
    ];
    let edges = vec![
        edge((1, 0), (0, 0), false),
        edge((1, 0), (2, 0), false),
        edge((2, 1), (0, 0), false),
    ];
    let l = layout(&nodes, &edges);
    assert!(l.from_locations);
    assert!(problems(&l).is_empty(), "{:?}", problems(&l));
    assert!(l.nodes[0].x < l.nodes[1].x, "consumer stays left");
    assert!(l.nodes[2].y > l.nodes[0].y, "below stays below");
}

#[test]
fn the_layout_is_deterministic() {
    use PortKind::*;
    let nodes: Vec<Node> = (0..12)
        .map(|i| node(&format!("n{i}"), &[("in", In), ("out", Out)], None))
        .collect();
    let edges: Vec<Edge> = (1..12)
        .map(|i| edge(((i * 5) % 12, 1), (i, 0), false))
        .collect();
    assert_eq!(
        format!("{:?}", layout(&nodes, &edges)),
        format!("{:?}", layout(&nodes, &edges))
    );
}

/// The system inputs the export tests run on: the fixture, the example, the corpus systems.
fn system_inputs() -> Vec<(std::path::PathBuf, Option<String>)> {
    let root = common::root();
    let mut v = vec![
        (root.join("tests/fixtures/diagrams"), None),
        (root.join("examples"), None),
        // A composite component and its member (double and dashed outlines).
        (root.join("tests/fixtures/systems/site"), None),
    ];
    if let Some(c) = common::corpus() {
        let dir = c.join("rts-xml");
        let loaded = rtcdoc::build::load(
            &dir,
            &rtcdoc::build::LoadOptions {
                allow_empty: true,
                ..Default::default()
            },
        )
        .expect("load corpus systems");
        for s in &loaded.catalog.systems {
            v.push((dir.clone(), Some(s.source.clone())));
        }
    }
    v
}

fn graph(input: &Path, system: &Option<String>, format: &str, out: &Path) {
    let select: Vec<&str> = match system {
        Some(s) => vec!["--system", s],
        None => Vec::new(),
    };
    graph_with(input, &select, format, out);
}

/// `rtcdoc graph INPUT SELECT… -f FORMAT -o OUT`, which must succeed.
fn graph_with(input: &Path, select: &[&str], format: &str, out: &Path) {
    let (input, out) = (input.display().to_string(), out.display().to_string());
    let mut args = vec!["graph", &input, "-f", format, "-o", &out];
    args.extend_from_slice(select);
    let o = common::rtcdoc(&args, &common::root());
    assert!(
        o.status.success(),
        "rtcdoc {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// `rtcdoc graph --dataflow category|vendor -f FORMAT` of the example and, when present, the
/// corpus: the files written.
fn dataflow_exports(format: &str, dir: &Path) -> Vec<std::path::PathBuf> {
    let mut inputs = vec![common::root().join("examples")];
    inputs.extend(common::corpus());
    let mut out = Vec::new();
    for (k, input) in inputs.iter().enumerate() {
        for grouping in ["category", "vendor"] {
            let f = dir.join(format!("dataflow-{k}-{grouping}.{format}"));
            graph_with(input, &["--dataflow", grouping], format, &f);
            out.push(f);
        }
    }
    out
}

/// `rtcdoc graph --component NAME -f FORMAT` of every component of the example, of the
/// neighbourhood fixture (capped ports) and of the first corpus components: the files written.
fn neighbourhood_exports(format: &str, dir: &Path) -> Vec<std::path::PathBuf> {
    let mut inputs = vec![
        common::root().join("examples"),
        common::root().join("tests/fixtures/neighbourhood"),
    ];
    inputs.extend(common::corpus().map(|c| c.join("rtc-xml")));
    let mut out = Vec::new();
    for (k, input) in inputs.iter().enumerate() {
        let loaded = rtcdoc::build::load(input, &rtcdoc::build::LoadOptions::default())
            .expect("load components");
        for (ci, c) in loaded.catalog.components.iter().enumerate().take(40) {
            let f = dir.join(format!("nb-{k}-{ci}.{format}"));
            graph_with(input, &["--component", &c.id], format, &f);
            out.push(f);
        }
    }
    out
}

#[test]
fn graphviz_dot_accepts_every_dot_export() {
    if !common::tool_available("dot") && !Path::new("/usr/bin/dot").exists() {
        crate::common::missing_tool("Graphviz dot not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let mut n = 0;
    for (k, (input, system)) in system_inputs().iter().enumerate() {
        let f = dir.path().join(format!("{k}.dot"));
        graph(input, system, "dot", &f);
        let o = std::process::Command::new("dot")
            .arg("-Tsvg")
            .arg(&f)
            .output_within(common::COMMAND_LIMIT)
            .expect("run dot");
        assert!(
            o.status.success() && o.stdout.starts_with(b"<?xml"),
            "dot rejects {input:?} {system:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        n += 1;
    }
    for f in dataflow_exports("dot", dir.path()) {
        let text = std::fs::read_to_string(&f).unwrap();
        assert!(text.contains("port pairs"), "{text}");
        let o = std::process::Command::new("dot")
            .arg("-Tsvg")
            .arg(&f)
            .output_within(common::COMMAND_LIMIT)
            .expect("run dot");
        assert!(
            o.status.success() && o.stdout.starts_with(b"<?xml"),
            "dot rejects {f:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        // The edges' labels are on the drawing, not only in tooltips.
        let svg = String::from_utf8_lossy(&o.stdout);
        assert!(
            svg.contains("<text") && svg.contains("port pairs (") && svg.contains("</text>"),
            "{svg}"
        );
        n += 1;
    }
    for f in neighbourhood_exports("dot", dir.path()) {
        let o = std::process::Command::new("dot")
            .arg("-Tsvg")
            .arg(&f)
            .output_within(common::COMMAND_LIMIT)
            .expect("run dot");
        assert!(
            o.status.success() && o.stdout.starts_with(b"<?xml"),
            "dot rejects {f:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        n += 1;
    }
    println!("dot accepted {n} DOT exports");
    assert!(n >= 2);
}

/// Runs tests/browser/mermaid-parse.mjs on `files`; `None` (with a visible "skipped") when
/// node, its npm install or chromium is missing.
fn mermaid_parse(files: &[std::path::PathBuf]) -> Option<serde_json::Value> {
    let dir = common::root().join("tests/browser");
    if !dir.join("node_modules/mermaid").is_dir() || !Path::new("/usr/bin/chromium").exists() {
        crate::common::missing_tool(
            "tests/browser/node_modules/mermaid or chromium missing (npm ci)",
        );
        return None;
    }
    let o = common::run_browser_harness(
        std::process::Command::new("node")
            .arg(dir.join("mermaid-parse.mjs"))
            .args(files),
    )?;
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    Some(serde_json::from_slice(&o.stdout).expect("json"))
}

#[test]
fn mermaids_parser_accepts_every_mermaid_export_and_markdown_block() {
    let dir = tempfile::tempdir().unwrap();
    let mut files = Vec::new();
    for (k, (input, system)) in system_inputs().iter().enumerate() {
        let f = dir.path().join(format!("{k}.mmd"));
        graph(input, system, "mermaid", &f);
        files.push(f);
    }
    files.extend(dataflow_exports("mermaid", dir.path()));
    files.extend(neighbourhood_exports("mermaid", dir.path()));
    // The Markdown output with `[markdown] diagrams = "mermaid"`.
    let cfg = dir.path().join("rtcdoc.toml");
    std::fs::write(&cfg, "[markdown]\ndiagrams = \"mermaid\"\n").unwrap();
    let md = dir.path().join("md");
    let o = common::rtcdoc(
        &[
            "build",
            "examples",
            "-f",
            "markdown",
            "-o",
            &md.display().to_string(),
            "--config",
            &cfg.display().to_string(),
        ],
        &common::root(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = md.join("systems/patrolrobot.md");
    let text = std::fs::read_to_string(&page).unwrap();
    assert!(text.contains("```mermaid\nflowchart LR\n"), "{text}");
    assert!(!md.join("systems/patrolrobot.svg").exists());
    files.push(page);
    let Some(r) = mermaid_parse(&files) else {
        return;
    };
    let results = r["results"].as_array().expect("results");
    assert_eq!(results.len(), files.len(), "{r}");
    for x in results {
        assert_eq!(x["ok"], true, "{x}");
    }
    println!("mermaid parsed {} blocks", results.len());
}

#[test]
fn markdown_writes_the_wiring_as_svg_by_default() {
    let dir = tempfile::tempdir().unwrap();
    let md = dir.path().join("md");
    let o = common::rtcdoc(
        &[
            "build",
            "examples",
            "-f",
            "markdown",
            "-o",
            &md.display().to_string(),
        ],
        &common::root(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(md.join("systems/patrolrobot.md")).unwrap();
    assert!(text.contains("](patrolrobot.svg)"), "{text}");
    let svg = std::fs::read_to_string(md.join("systems/patrolrobot.svg")).unwrap();
    assert!(svg.contains("class=\"diagram system-diagram\"") && svg.contains("<style>"));
}

/// Every system and component diagram of a site, measured in headless Chromium.
fn audit_site(site: &Path) -> Option<serde_json::Value> {
    let dir = common::root().join("tests/browser");
    if !dir.join("node_modules/puppeteer-core").is_dir() || !Path::new("/usr/bin/chromium").exists()
    {
        crate::common::missing_tool("tests/browser/node_modules or chromium missing (npm ci)");
        return None;
    }
    let o = common::run_browser_harness(
        std::process::Command::new("node")
            .arg(dir.join("diagrams.mjs"))
            .arg(site),
    )?;
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    Some(serde_json::from_slice(&o.stdout).expect("json"))
}

#[test]
fn rendered_diagrams_have_no_connector_through_a_box_and_every_name_whole() {
    let dir = tempfile::tempdir().unwrap();
    let mut inputs = vec![
        common::root().join("examples"),
        common::root().join("tests/fixtures/diagrams"),
        common::root().join("tests/fixtures/neighbourhood"),
        common::root().join("tests/fixtures/neighbourhood-generic"),
    ];
    if let Some(c) = common::corpus() {
        inputs.push(c.join("rts-xml"));
    }
    let (mut measured, mut neighbourhoods) = (0, 0);
    for (k, input) in inputs.iter().enumerate() {
        let site = dir.path().join(format!("site{k}"));
        let o = common::rtcdoc(
            &[
                "build",
                &input.display().to_string(),
                "-o",
                &site.display().to_string(),
                "--allow-empty",
            ],
            &common::root(),
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let Some(r) = audit_site(&site) else {
            return;
        };
        assert!(r["errors"].as_array().is_some_and(Vec::is_empty), "{r}");
        for d in r["diagrams"].as_array().expect("diagrams") {
            for key in ["through", "outsideBox", "cut", "outsideDrawing"] {
                assert_eq!(d[key], 0, "{} {key}: {}", d["page"], d["details"]);
            }
            if d["kind"] == "neighbourhood" {
                // Whole in a 1280 px window (one edge per neighbour and direction, #55).
                assert!(d["widthPx"].as_u64().is_some_and(|w| w <= 1200), "{d}");
            }
            measured += 1;
            neighbourhoods += usize::from(d["kind"] == "neighbourhood");
        }
    }
    println!("measured {measured} diagrams, {neighbourhoods} neighbourhoods");
    assert!(measured > 3);
    assert!(
        neighbourhoods > 3,
        "the neighbourhood drawings are measured too"
    );
}

/// The export holds every flow, one within a group too: two components of one category, one
/// feeding the other, are that category's edge to itself (the page's drawing shows the flows
/// between groups; its table lists that one).
#[test]
fn the_dataflow_export_holds_the_flows_within_a_group() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let profile = |name: &str, category: &str, dir: &str| {
        common::xml_profile(name, &[(dir, "p", "RTC::TimedLong")]).replace(
            "rtc:category=\"Cat\"",
            &format!("rtc:category=\"{category}\""),
        )
    };
    common::write(
        &input,
        "Src/RTC.xml",
        &profile("Src", "Sensor", "DataOutPort"),
    );
    common::write(
        &input,
        "Dst/RTC.xml",
        &profile("Dst", "Sensor", "DataInPort"),
    );
    let export = |format: &str| {
        let f = dir.path().join(format!("flow.{format}"));
        graph_with(&input, &["--dataflow", "category"], format, &f);
        std::fs::read_to_string(f).unwrap()
    };
    let dot = export("dot");
    assert!(dot.contains("n0:p0:e -> n0:p1:w"), "{dot}");
    // The edge says what it carries where it is drawn (the guide: labelled with the number
    // of port pairs and the types); the tooltip also names the groups.
    assert!(
        dot.contains(r#"n0:p0:e -> n0:p1:w [label="1 port pair (RTC::TimedLong)", tooltip="Sensor → Sensor: 1 port pair (RTC::TimedLong)"];"#),
        "{dot}"
    );
    let mermaid = export("mermaid");
    assert!(
        mermaid.contains("n0 -- \"1 port pair (RTC::TimedLong)\" --> n0"),
        "{mermaid}"
    );

    assert!(export("svg").contains(">Sensor<"));
    // A second group: both flows.
    common::write(
        &input,
        "Act/RTC.xml",
        &profile("Act", "Actuator", "DataInPort"),
    );
    let dot = export("dot");
    assert_eq!(dot.matches(" -> ").count(), 2, "{dot}");
    assert!(dot.contains("Sensor → Actuator: 1 port pair"), "{dot}");
}

/// A catalogue without data flows exports an empty graph and says why on stderr (the page
/// says the same), rather than an empty graph alone.
#[test]
fn an_empty_dataflow_export_says_why() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    common::write(
        &input,
        "Src/RTC.xml",
        &common::xml_profile("Src", &[("DataOutPort", "p", "RTC::TimedLong")]),
    );
    common::write(
        &input,
        "Dst/RTC.xml",
        &common::xml_profile("Dst", &[("DataInPort", "p", "RTC::TimedDouble")]),
    );
    let o = common::rtcdoc(
        &["graph", "in", "--dataflow", "category", "-f", "dot"],
        dir.path(),
    );
    assert!(o.status.success());
    let (out, err) = (
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr),
    );
    assert!(out.starts_with("digraph") && !out.contains("->"), "{out}");
    assert!(err.contains("note: No data flows"), "{err}");
}

/// A data connector saved with its in-port as the source (RTSystemEditor saves the end the user
/// dragged from first) is drawn from the out-port to the in-port, as every other: in the DOT
/// and Mermaid exports and on the system page, where the producer stands left of the consumer.
#[test]
fn a_connector_saved_from_its_in_port_flows_from_the_out_port() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let ty = "RTC::TimedBooleanSeq";
    common::write(
        d,
        "in/Sensor/RTC.xml",
        &common::xml_profile("Sensor", &[("DataOutPort", "bumper", ty)]),
    );
    common::write(
        d,
        "in/Ctrl/RTC.xml",
        &common::xml_profile("Ctrl", &[("DataInPort", "bumper", ty)]),
    );
    let instance = |name: &str, comp: &str| {
        format!(
            r#"  <rts:Components rts:isRequired="false" rts:compositeType="None" rts:activeConfigurationSet="default" rts:instanceName="{name}" rts:pathUri="localhost/{name}.rtc" rts:id="RTC:Test:Cat:{comp}:1.0.0">
    <rts:DataPorts rts:name="{name}.bumper"/>
    <rts:ConfigurationSets rts:id="default"/>
  </rts:Components>
"#
        )
    };
    let end = |tag: &str, name: &str, comp: &str| {
        format!(
            r#"    <rts:{tag} rts:portName="{name}.bumper" rts:instanceName="{name}" rts:componentId="RTC:Test:Cat:{comp}:1.0.0"/>
"#
        )
    };
    common::write(
        d,
        "in/System.xml",
        &format!(
            r#"<?xml version="1.0"?>
<rts:RtsProfile rts:version="0.2" rts:id="RTSystem:Test:Demo:1.0.0" xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
{}{}  <rts:DataPortConnectors rts:connectorId="c1" rts:name="Ctrl0.bumper_Sensor0.bumper" rts:dataType="IDL:RTC/TimedBooleanSeq:1.0" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush">
{}{}  </rts:DataPortConnectors>
</rts:RtsProfile>
"#,
            instance("Sensor0", "Sensor"),
            instance("Ctrl0", "Ctrl"),
            end("sourceDataPort", "Ctrl0", "Ctrl"),
            end("targetDataPort", "Sensor0", "Sensor"),
        ),
    );
    let stdout = |args: &[&str]| {
        let o = common::rtcdoc(args, d);
        assert!(o.status.success(), "{o:?}");
        String::from_utf8(o.stdout).unwrap()
    };
    // Sensor0 is n0, Ctrl0 n1 (the file's order).
    let dot = stdout(&["graph", "in"]);
    let arrow = dot
        .lines()
        .find(|l| l.contains(" -> "))
        .unwrap_or_else(|| panic!("{dot}"));
    assert!(
        arrow.trim_start().starts_with("n0:")
            && arrow.contains("-> n1:")
            && arrow.contains("Sensor0.bumper → Ctrl0.bumper"),
        "{arrow}"
    );
    let mermaid = stdout(&["graph", "in", "-f", "mermaid"]);
    assert!(
        mermaid.contains("n0 -- \"bumper → bumper\" --> n1"),
        "{mermaid}"
    );
    stdout(&["build", "in", "-o", "site", "-q"]);
    let page = std::fs::read_to_string(d.join("site/systems/demo.html")).unwrap();
    let box_x = |name: &str| -> f32 {
        let at = page
            .find(&format!("aria-label=\"{name} "))
            .unwrap_or_else(|| panic!("{name}: {page}"));
        let rest = &page[at..];
        let x = rest.split("class=\"rtc-box\" x=\"").nth(1).expect("box");
        x[..x.find('"').unwrap()].parse().unwrap()
    };
    assert!(box_x("Sensor0") < box_x("Ctrl0"), "{page}");
}

/// `rtcdoc graph` on an input without RT System profiles says what it can draw instead, with
/// a component of the input; the command it names works.
#[test]
fn graph_without_a_system_names_what_it_can_draw() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(
        d,
        "in/Cam/RTC.xml",
        &common::xml_profile("Cam", &[("DataOutPort", "out", "RTC::TimedLong")]),
    );
    let o = common::rtcdoc(&["graph", "in"], d);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("no RT System profile in in; graph draws a component's neighbourhood (--component=Cam) or the data flow between categories (--dataflow category) without one"), "{err}");
    for args in [
        &["graph", "in", "--component=Cam"][..],
        &["graph", "in", "--dataflow", "category"],
    ] {
        let o = common::rtcdoc(args, d);
        assert!(
            o.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert!(
            String::from_utf8_lossy(&o.stdout).starts_with("digraph"),
            "{args:?}"
        );
    }
}
