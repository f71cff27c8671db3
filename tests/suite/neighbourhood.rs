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
    let page = std::fs::read_to_string(site.join("components/hub.html")).unwrap();
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
    let lonely = std::fs::read_to_string(site.join("components/lonely.html")).unwrap();
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
        let text = std::fs::read_to_string(out.join(file)).unwrap();
        assert!(text.contains("Neighbourhood"), "{text}");
        assert!(text.contains(more), "{format}: {text}");
        assert!(text.contains("fed by") && text.contains("feeds"), "{text}");
        let lonely = std::fs::read_to_string(out.join(file.replace("hub", "lonely"))).unwrap();
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
