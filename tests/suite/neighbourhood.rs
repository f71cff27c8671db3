//! A component's neighbourhood (#26) on its pages and from `rtcdoc graph --component`: the
//! components that can feed each port and those it feeds, capped per port with the exact
//! number left out and a link to the type page — never dropped silently.

use crate::common;

use std::path::{Path, PathBuf};

/// A catalogue around `Hub` (`tests/fixtures/neighbourhood`): 8 sources of its in-port (5
/// named, +3), 2 sinks of its out-port (one of them, `Both`, also a source: one box, two
/// ports), a map server for its required interface, and `Lonely`, whom nobody connects to.
pub fn hub_input(_dir: &Path) -> PathBuf {
    common::root().join("tests/fixtures/neighbourhood")
}

fn run(args: &[&str]) -> std::process::Output {
    common::rtcdoc(args, &common::root())
}

#[test]
fn html_page_draws_and_lists_the_neighbourhood_with_caps_stated() {
    let dir = tempfile::tempdir().unwrap();
    let input = hub_input(dir.path());
    let site = dir.path().join("site");
    let o = run(&[
        "build",
        &input.display().to_string(),
        "-o",
        &site.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = common::read_page(&site.join("components/hub.html"));
    let s = page
        .find("<section id=\"neighbourhood\">")
        .expect("section");
    let sec = &page[s..s + page[s..].find("</section>").unwrap()];
    assert!(page.contains("<li><a href=\"#neighbourhood\">Neighbourhood</a></li>"));
    // The drawing: system-diagram conventions, inside the scrolling wrapper.
    assert!(sec.contains("<div class=\"diagram-scroll\"><svg"), "{sec}");
    assert!(sec.contains("class=\"diagram system-diagram neighbourhood-diagram\""));
    // One box per neighbour component named, plus Hub and the "+3 more" box.
    let boxes = sec.matches("<g class=\"instance\">").count();
    let list = &sec[sec.find("<ul class=\"neighbourhood\">").expect("list")..];
    // The list: by port, capped with the exact rest linked to the type page.
    assert_eq!(list.matches("<li><a href=\"#").count(), 3, "{list}");
    assert!(
        list.contains("fed by:") && list.contains("feeds:") && list.contains("uses:"),
        "{list}"
    );
    // A service interface is `port.interface`, as the port tables and peers write it.
    assert!(list.contains("<code>map.map</code>"), "{list}");
    assert!(list.contains(" · maps.map</a>"), "{list}");
    assert!(
        list.contains("<li class=\"more\"><a href=\"../types/rtc-timedlong.html\">+3 — see all on the type page</a></li>"),
        "{list}"
    );
    assert!(
        sec.contains(">+3 more<"),
        "the drawing says what it caps: {sec}"
    );
    // Its connector names the box alone, without a port after it.
    assert!(
        sec.contains("<title>+3 more → Hub.in (RTC::TimedLong)</title>"),
        "{sec}"
    );
    assert!(!sec.contains("more. "), "{sec}");
    // Named neighbours: 5 on `in`, 2 on `out` (Both, Sink), the map server; Both is on both
    // ports but one box.
    assert_eq!(list.matches("../components/").count(), 8, "{list}");
    assert_eq!(sec.matches("<path class=\"connector service\"").count(), 1);
    let named: std::collections::BTreeSet<&str> = list
        .split("../components/")
        .skip(1)
        .map(|x| &x[..x.find('#').unwrap()])
        .collect();
    assert_eq!(boxes, 1 + named.len() + 1, "{sec}");
    assert!(!list.contains("hub.html"), "never its own neighbour");
    // Nobody connects to Lonely: no drawing, a sentence.
    let lonely = common::read_page(&site.join("components/lonely.html"));
    let s = lonely.find("<section id=\"neighbourhood\">").unwrap();
    let sec = &lonely[s..s + lonely[s..].find("</section>").unwrap()];
    assert!(!sec.contains("<svg"));
    assert!(sec.contains("No other component in this catalogue connects to it."));
}

#[test]
fn markdown_and_doxygen_have_the_same_table_and_japanese_labels() {
    let dir = tempfile::tempdir().unwrap();
    let input = hub_input(dir.path());
    for (format, file, more) in [
        (
            "markdown",
            "components/hub.md",
            "[\\+3 — see all on the type page](../types/rtc-timedlong.md)",
        ),
        (
            "doxygen",
            "components/hub.dox",
            "\\ref rtc_type_rtc_timedlong \"+3 — see all on the type page\"",
        ),
    ] {
        let out = dir.path().join(format);
        let o = run(&[
            "build",
            &input.display().to_string(),
            "-f",
            format,
            "-o",
            &out.display().to_string(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let text = common::read_page(&out.join(file));
        assert!(text.contains("Neighbourhood"), "{text}");
        assert!(text.contains(more), "{format}: {text}");
        assert!(text.contains("fed by") && text.contains("feeds"), "{text}");
        let lonely = common::read_page(&out.join(file.replace("hub", "lonely")));
        assert!(lonely.contains("No other component in this catalogue connects to it."));
    }
    let cfg = dir.path().join("rtcdoc.toml");
    std::fs::write(&cfg, "language = \"ja\"\n").unwrap();
    let out = dir.path().join("ja");
    let o = run(&[
        "build",
        &input.display().to_string(),
        "-f",
        "markdown",
        "-o",
        &out.display().to_string(),
        "--config",
        &cfg.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(out.join("components/hub.md")).unwrap();
    assert!(
        text.contains("接続できるコンポーネント") && text.contains("入力元"),
        "{text}"
    );
}

#[test]
fn graph_component_writes_the_neighbourhood_and_names_close_matches() {
    let dir = tempfile::tempdir().unwrap();
    let input = hub_input(dir.path());
    let input = input.display().to_string();
    let o = run(&["graph", &input, "--component", "Hub", "-f", "mermaid"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m = String::from_utf8(o.stdout).unwrap();
    assert!(m.starts_with("flowchart LR\n"), "{m}");
    assert!(
        m.contains("[\"+3 more<br/><small>RTC::TimedLong</small>\"]"),
        "{m}"
    );
    // Edges labelled with the ports and the type (the guide); the "+3 more" box by its name.
    assert!(m.contains("\"value → in (RTC::TimedLong)\" --> n0"), "{m}");
    assert!(m.contains("\"+3 more → in (RTC::TimedLong)\""), "{m}");
    // By id too; DOT, its edges labelled alike.
    let o = run(&["graph", &input, "--component", "RTC:Test:Cat:Hub:1.0.0"]);
    assert!(o.status.success());
    let d = String::from_utf8(o.stdout).unwrap();
    assert!(d.starts_with("digraph \"Neighbourhood of Hub\""), "{d}");
    assert!(
        d.contains("[label=\"value → in (RTC::TimedLong)\", tooltip="),
        "{d}"
    );
    // A name that is no component: exit 2 and the similar names, only those.
    let o = run(&["graph", &input, "--component", "hubb"]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("no component named \"hubb\"") && e.contains("did you mean: Hub?"),
        "{e}"
    );
    // A name like none of them names none (not the least far of unrelated names).
    let o = run(&["graph", &input, "--component", "NoSuch"]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("no component named \"NoSuch\"") && e.contains("nor one of a similar name"),
        "{e}"
    );
    assert!(!e.contains("did you mean") && !e.contains("Hub"), "{e}");
    // Same input, same bytes.
    let svg = |f: &str| {
        let p = dir.path().join(f);
        let o = run(&[
            "graph",
            &input,
            "--component",
            "Hub",
            "-f",
            "svg",
            "-o",
            &p.display().to_string(),
        ]);
        assert!(o.status.success());
        std::fs::read(p).unwrap()
    };
    assert_eq!(svg("a.svg"), svg("b.svg"));
}

/// The neighbourhood of component `ci`, as drawn: the wiring and its layout (the one the
/// component page draws).
fn drawn(
    cat: &rtcdoc::catalog::Catalog,
    ci: rtcdoc::catalog::ComponentIx,
) -> (
    Vec<rtcdoc::render::wiring::WireInstance>,
    Vec<rtcdoc::render::wiring::WireConnector>,
    rtcdoc::layout::wiring::WiringLayout,
) {
    use rtcdoc::render::neighbourhood as nb;
    let rows = nb::rows(cat, ci, &nb::neighbourhood(cat, ci));
    let (inst, conns) = nb::wiring(cat, ci, &rows, rtcdoc::i18n::Lang::En, &|_, _| {
        String::new()
    });
    let nodes: Vec<_> = inst.iter().map(|i| i.node()).collect();
    let edges: Vec<_> = conns.iter().map(|c| c.edge()).collect();
    let l =
        rtcdoc::layout::wiring::layout_with(&nodes, &edges, rtcdoc::layout::wiring::Effort::Quick);
    (inst, conns, l)
}

/// The geometry audit the wiring diagrams pass (`tests/suite/diagrams.rs`), for a
/// neighbourhood drawing: no connector through a box, no name outside its box, no two
/// connectors on one track, no two boxes overlapping, and narrow enough for a 1280 px window.
fn audit(
    what: &str,
    l: &rtcdoc::layout::wiring::WiringLayout,
    conns: &[rtcdoc::layout::wiring::Edge],
) {
    let p = rtcdoc::layout::wiring::problems(l);
    assert!(p.is_empty(), "{what}: {p:#?}");
    let shared = rtcdoc::layout::wiring::shared_tracks(l, conns);
    assert!(shared.is_empty(), "{what}: {shared:#?}");
    for (i, a) in l.nodes.iter().enumerate() {
        for b in &l.nodes[i + 1..] {
            let apart =
                a.x + a.w <= b.x || b.x + b.w <= a.x || a.y + a.h <= b.y || b.y + b.h <= a.y;
            assert!(apart, "{what}: boxes overlap: {a:?} {b:?}");
        }
    }
    assert!(l.width <= 1200.0, "{what}: {} px wide", l.width);
}

/// Issue #55: a component whose six ports carry the generic `RTC::TimedDoubleSeq`, shared with
/// twelve components (`tests/fixtures/neighbourhood-generic`), is drawn with one edge per
/// neighbour and direction, labelled with its number of port pairs; the components that both
/// feed it and are fed by it on the right, beside it; the eight closest drawn and "+1 more"
/// for the ninth the list names; the capped lists' "+3 more" boxes; narrow, the component
/// level with the middle of its neighbours, and every port pair still in the list.
#[test]
fn a_generic_type_draws_one_edge_per_neighbour_and_direction() {
    let input = common::root().join("tests/fixtures/neighbourhood-generic");
    let loaded = rtcdoc::build::load(&input, &rtcdoc::build::LoadOptions::default()).unwrap();
    let cat = &loaded.catalog;
    let ci = rtcdoc::catalog::Ix::enumerate(&cat.components)
        .find(|(_, c)| c.profile.name() == "Filter")
        .expect("component")
        .0;
    let (inst, conns, l) = drawn(cat, ci);
    let edges: Vec<_> = conns.iter().map(|c| c.edge()).collect();
    audit("Filter", &l, &edges);
    let names: Vec<&str> = inst.iter().map(|i| i.name.as_str()).collect();
    // F1–F4, S1–S3 and B1 (the closest eight), "+1 more" (S4), two "+3 more" (X1–X3).
    assert_eq!(
        names,
        [
            "Filter", "F1", "F2", "F3", "F4", "S1", "S2", "S3", "B1", "+1 more", "+3 more",
            "+3 more"
        ]
    );
    // One edge per neighbour and direction: B1 has two, every other box one.
    assert_eq!(
        conns.len(),
        12,
        "{:?}",
        conns.iter().map(|c| &c.label).collect::<Vec<_>>()
    );
    let label = |l: &str| conns.iter().any(|c| c.label == l);
    assert!(label("F1 → Filter: 6 port pairs (RTC::TimedDoubleSeq)"));
    assert!(label("B1 → Filter: 3 port pairs (RTC::TimedDoubleSeq)"));
    assert!(label("Filter → B1: 3 port pairs (RTC::TimedDoubleSeq)"));
    assert!(label("+3 more → Filter (RTC::TimedDoubleSeq)"));
    assert!(label("Filter → +1 more"));
    let caption = conns.iter().find(|c| c.label.starts_with("F1 ")).unwrap();
    assert_eq!(
        caption.caption.as_deref(),
        Some("6 port pairs (RTC::TimedDoubleSeq)")
    );
    // The component's ends name their number of ports; F1's its number of pairs.
    assert!(inst[0]
        .ports
        .iter()
        .any(|p| p.name == "3 ports" && p.class == "in"));
    assert!(inst[1].ports.iter().all(|p| p.name == "6 port pairs"));
    // B1, fed and feeding, is right of the component, both its ports facing it; the feeders
    // left of it; the component level with the middle of the drawing.
    let (me, b1, f1) = (&l.nodes[0], &l.nodes[8], &l.nodes[1]);
    assert!(b1.x > me.x + me.w && f1.x + f1.w < me.x, "{l:?}");
    assert!(b1
        .ports
        .iter()
        .all(|p| p.side == rtcdoc::layout::wiring::Side::Left));
    let centre = me.y + me.h / 2.0;
    assert!(
        centre > l.height / 3.0 && centre < 2.0 * l.height / 3.0,
        "component at {centre} of {}",
        l.height
    );
    // On the page: the drawing and the list, which still names S4 and every port pair.
    let dir = tempfile::tempdir().unwrap();
    let site = dir.path().join("site");
    let o = run(&[
        "build",
        &input.display().to_string(),
        "-o",
        &site.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = common::read_page(&site.join("components/filter.html"));
    let s = page.find("<section id=\"neighbourhood\">").unwrap();
    let sec = &page[s..s + page[s..].find("</section>").unwrap()];
    assert_eq!(sec.matches("<path class=\"connector").count(), 12, "{sec}");
    assert!(sec.contains("> see the list below</tspan>"), "{sec}");
    let list = &sec[sec.find("<ul class=\"neighbourhood\">").unwrap()..];
    assert!(list.contains("../components/s4.html#port-a"), "{list}");
    assert!(list.contains(">F1 · a, b</a>"), "F1's two ports: {list}");
    assert_eq!(
        list.matches("<li><a href=\"#").count(),
        6,
        "one line per port: {list}"
    );
}

/// Every neighbourhood drawing of the examples and the neighbourhood fixtures (and the corpus,
/// when present) passes the geometry audit.
#[test]
fn every_neighbourhood_drawing_passes_the_geometry_audit() {
    let mut inputs = vec![
        common::root().join("examples"),
        common::root().join("tests/fixtures/neighbourhood"),
        common::root().join("tests/fixtures/neighbourhood-generic"),
    ];
    if let Some(c) = common::corpus() {
        inputs.push(c.join("rtc-xml"));
    }
    let (mut audited, mut widest) = (0, 0.0f32);
    for input in &inputs {
        let loaded = rtcdoc::build::load(input, &rtcdoc::build::LoadOptions::default()).unwrap();
        let cat = &loaded.catalog;
        for (ci, c) in rtcdoc::catalog::Ix::enumerate(&cat.components) {
            let name = c.profile.name();
            let (inst, conns, l) = drawn(cat, ci);
            if inst.len() < 2 {
                continue;
            }
            let edges: Vec<_> = conns.iter().map(|c| c.edge()).collect();
            audit(&format!("{} {name}", input.display()), &l, &edges);
            widest = widest.max(l.width);
            // At most the closest eight, two "+N more" for the list and one per capped list.
            assert!(
                inst.len() <= 1 + 8 + 2 + 4 * 2,
                "{name}: {} boxes",
                inst.len()
            );
            audited += 1;
        }
    }
    println!("{audited} neighbourhood drawings audited, the widest {widest} px");
    assert!(audited > 10, "{audited} drawings audited");
}
