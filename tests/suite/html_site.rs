//! The HTML catalogue site: structure, cross-links, sanitisation, determinism, themes, validity.

use crate::common;
use crate::html_support;
use common::OutputWithin;

use html_support::*;
use rtcdoc::catalog::{Catalog, LoadedProfile};
use rtcdoc::model::{
    Action, ActionKind, BasicInfo, DataPort, Profile, ServiceInterface, ServicePort,
};
use rtcdoc::output::Staging;
use rtcdoc::parse::SourceFormat;
use rtcdoc::render::{html::HtmlRenderer, RenderContext, Renderer, SiteOptions};
use rtcdoc::types::canonical_type;
use std::collections::BTreeSet;
use std::path::Path;

// ---------- a small builder for catalogues made in Rust ----------

fn s(v: &str) -> Option<rtcdoc::model::Text> {
    Some(v.into())
}

fn component(name: &str, category: &str) -> Profile {
    Profile {
        id: s(&format!("RTC:Test:{category}:{name}:1.0")),
        version: s("0.2"),
        basic_info: BasicInfo {
            name: s(name),
            category: s(category),
            vendor: s("Test"),
            version: s("1.0"),
            description: s(&format!("{name} does things.\nSecond line.")),
            ..Default::default()
        },
        actions: vec![Action {
            kind: ActionKind::OnExecute,
            implemented: s("true"),
            doc: None,
            pos: Default::default(),
            extra: rtcdoc::model::Extras::new(),
        }],
        ..Default::default()
    }
}

fn data_port(dir: &str, name: &str, ty: &str) -> DataPort {
    DataPort {
        port_type: s(dir),
        name: s(name),
        type_: s(ty),
        ..Default::default()
    }
}

fn service_port(name: &str, ifaces: &[(&str, &str, &str)]) -> ServicePort {
    ServicePort {
        name: s(name),
        interfaces: ifaces
            .iter()
            .map(|(n, dir, ty)| ServiceInterface {
                name: s(n),
                direction: s(dir),
                type_: s(ty),
                ..Default::default()
            })
            .collect(),
        ..Default::default()
    }
}

fn render_catalog(profiles: Vec<Profile>, out: &Path, site: &SiteOptions) -> Catalog {
    let loaded = profiles
        .into_iter()
        .enumerate()
        .map(|(i, profile)| LoadedProfile {
            source: format!("c{i:03}/RTC.xml"),
            format: SourceFormat::Xml,
            profile: Box::new(profile),
        })
        .collect();
    let catalog = Catalog::build(loaded, vec![]);
    let staging = Staging::new(out).expect("staging");
    HtmlRenderer
        .render(
            &RenderContext {
                catalog: &catalog,
                site,
            },
            &staging,
        )
        .expect("render");
    staging.commit().expect("commit");
    catalog
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

fn title_of(html: &str) -> String {
    let a = html.find("<title>").expect("title") + 7;
    let b = html[a..].find("</title>").expect("end of title") + a;
    html[a..b].to_string()
}

/// The hrefs inside `<section id="ID">…</section>` of a page.
fn section_links(html: &str, id: &str) -> BTreeSet<String> {
    let open = format!("<section id=\"{id}\">");
    let Some(a) = html.find(&open) else {
        return BTreeSet::new();
    };
    let b = html[a..]
        .find("</section>")
        .map(|e| a + e)
        .unwrap_or(html.len());
    tags(&html[a..b])
        .into_iter()
        .filter(|t| t.name == "a")
        .filter_map(|t| t.attr("href").map(str::to_string))
        .filter(|h| h.contains('#'))
        .collect()
}

// ---------- the examples site ----------

#[test]
fn examples_site_has_every_page_and_no_broken_link() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&examples(), &out, SiteOptions::default());
    let cat = &loaded.catalog;
    assert!(cat.components.len() >= 9, "examples loaded");
    for f in [
        "index.html",
        "search.html",
        "search-index.js",
        "search.js",
        "filter.js",
        "style.css",
        "404.html",
        "types/index.html",
        "interfaces/index.html",
        "categories/index.html",
        "vendors/index.html",
    ] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    for c in &cat.components {
        let html = read(&out.join(format!("components/{}.html", c.slug)));
        assert!(
            title_of(&html).starts_with(c.profile.name()),
            "title of {}",
            c.slug
        );
        assert!(html.contains("<svg") && html.contains("«RTC»"), "diagram");
        assert!(html.contains("lifecycle-diagram"));
    }
    for t in &cat.data_types {
        let html = read(&out.join(format!("types/{}.html", t.slug)));
        assert!(title_of(&html).contains(&t.name), "type title {}", t.name);
    }
    for i in &cat.interfaces {
        let html = read(&out.join(format!("interfaces/{}.html", i.slug)));
        assert!(
            title_of(&html).contains(&i.name),
            "interface title {}",
            i.name
        );
    }
    let broken = broken_links(&out);
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
    if let Some(tool) = common::shared_tool("linkcheck.py") {
        let o = std::process::Command::new("python3")
            .arg(tool)
            .arg(&out)
            .output_within(common::COMMAND_LIMIT)
            .expect("python3");
        assert!(
            o.status.success(),
            "linkcheck.py: {}",
            String::from_utf8_lossy(&o.stdout)
        );
    } else {
        println!("skipped: ../shared/tools/linkcheck.py not present");
    }
    // A sitemap needs absolute URLs: without a base URL there is none.
    assert!(!out.join("sitemap.xml").exists());
}

#[test]
fn type_pages_list_exactly_the_producers_and_consumers() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&examples(), &out, SiteOptions::default());
    let cat = &loaded.catalog;
    // Expected sets derived from the profiles directly (not from the catalogue indexes).
    for t in &cat.data_types {
        let mut producers = BTreeSet::new();
        let mut consumers = BTreeSet::new();
        for c in &cat.components {
            for (pi, p) in c.profile.data_ports.iter().enumerate() {
                let Some(ty) = p.type_.as_deref().filter(|x| !x.trim().is_empty()) else {
                    continue;
                };
                if canonical_type(ty) != t.name {
                    continue;
                }
                let href = format!("../components/{}.html#{}", c.slug, c.anchors.data_ports[pi]);
                match p.port_type.as_deref() {
                    Some("DataOutPort") => producers.insert(href),
                    Some("DataInPort") => consumers.insert(href),
                    _ => false,
                };
            }
        }
        let html = read(&out.join(format!("types/{}.html", t.slug)));
        assert_eq!(section_links(&html, "producers"), producers, "{}", t.name);
        assert_eq!(section_links(&html, "consumers"), consumers, "{}", t.name);
    }
    // A known fact of the example robot: the camera image flows to the filter and detector.
    let img = cat.data_type("CameraImage").expect("CameraImage is used");
    let html = read(&out.join(format!("types/{}.html", img.slug)));
    assert!(section_links(&html, "producers")
        .iter()
        .any(|h| h.starts_with("../components/usbcamera.html#")));
    assert!(section_links(&html, "consumers").len() >= 2);
}

#[test]
fn every_port_links_to_its_type_or_interface_page_and_peers() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&examples(), &out, SiteOptions::default());
    let cat = &loaded.catalog;
    for (ci, c) in rtcdoc::catalog::Ix::enumerate(&cat.components) {
        let html = read(&out.join(format!("components/{}.html", c.slug)));
        for (pi, p) in c.profile.data_ports.iter().enumerate() {
            let Some(t) = p.type_.as_deref().and_then(|t| cat.data_type(t)) else {
                continue;
            };
            let anchor = &c.anchors.data_ports[pi];
            let row_start = html
                .find(&format!("<tr id=\"{anchor}\">"))
                .unwrap_or_else(|| panic!("row {anchor} in {}", c.slug));
            let row = &html[row_start..row_start + html[row_start..].find("</tr>").unwrap()];
            assert!(
                row.contains(&format!("href=\"../types/{}.html\"", t.slug)),
                "{}.{anchor} links to its type",
                c.slug
            );
            // Peers are other components (a port never "connects to" its own component),
            // grouped by component: one link each, to its first port, at most
            // PEER_COMPONENTS_CAP components.
            let mut firsts = cat
                .data_port_peers(ci, pi)
                .refs
                .iter()
                .filter(|r| r.component != c.id)
                .collect::<Vec<_>>();
            firsts.dedup_by_key(|r| r.component.clone());
            for peer in firsts
                .into_iter()
                .take(rtcdoc::render::html::PEER_COMPONENTS_CAP)
            {
                let (pci, ppi) = cat.resolve_port(peer).unwrap();
                let pc = &cat[pci];
                let href = format!(
                    "../components/{}.html#{}",
                    pc.slug, pc.anchors.data_ports[ppi]
                );
                assert!(
                    row.contains(&href),
                    "{}.{anchor} connects to {href}",
                    c.slug
                );
            }
            // The diagram links the port to its row.
            assert!(html.contains(&format!("<a href=\"#{anchor}\"")));
        }
        for (si, sp) in c.profile.service_ports.iter().enumerate() {
            for (ii, i) in sp.interfaces.iter().enumerate() {
                let Some(t) = i.type_.as_deref().and_then(|t| cat.interface(t)) else {
                    continue;
                };
                let anchor = &c.anchors.interfaces[si][ii];
                let row_start = html.find(&format!("<tr id=\"{anchor}\">")).expect("row");
                let row = &html[row_start..row_start + html[row_start..].find("</tr>").unwrap()];
                assert!(row.contains(&format!("href=\"../interfaces/{}.html\"", t.slug)));
            }
        }
    }
}

#[test]
fn interface_pages_list_providers_and_flag_unprovided() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&examples(), &out, SiteOptions::default());
    let cat = &loaded.catalog;
    let index = read(&out.join("interfaces/index.html"));
    let mut flagged = 0;
    for i in &cat.interfaces {
        let html = read(&out.join(format!("interfaces/{}.html", i.slug)));
        assert_eq!(
            section_links(&html, "providers").len(),
            i.uses.providers.len()
        );
        assert_eq!(
            section_links(&html, "requirers").len(),
            i.uses.requirers.len()
        );
        assert_eq!(
            html.contains("class=\"warning flag\""),
            i.is_unprovided(),
            "{}",
            i.name
        );
        if i.is_unprovided() {
            flagged += 1;
        }
    }
    assert!(
        flagged >= 1,
        "the examples require an interface nobody provides"
    );
    assert_eq!(index.matches("class=\"unprovided\"").count(), flagged);
}

// ---------- catalogues built in Rust ----------

#[test]
fn big_components_grow_the_diagram_and_cap_peer_lists() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let mut big = component("Big", "Test");
    for i in 0..44 {
        let dir = if i % 2 == 0 {
            "DataInPort"
        } else {
            "DataOutPort"
        };
        big.data_ports
            .push(data_port(dir, &format!("port{i}"), "RTC::TimedLong"));
    }
    big.service_ports.push(service_port(
        "svc",
        &[
            ("need", "Required", "Nobody::Provides"),
            ("give", "Provided", "My::Service"),
        ],
    ));
    let mut profiles = vec![big];
    for i in 0..30 {
        let mut c = component(&format!("Sink{i:02}"), "Sinks");
        c.data_ports
            .push(data_port("DataInPort", "in", "TimedLong"));
        profiles.push(c);
    }
    let mut jp = component("地図サーバ", "ナビゲーション");
    jp.basic_info.description = s("占有格子地図を配信する");
    profiles.push(jp);
    let cat = render_catalog(profiles, &out, &SiteOptions::default());
    let big = &cat.components[0];
    let html = read(&out.join(format!("components/{}.html", big.slug)));
    // 22 in-ports on the left at 38 px each: the box is far taller than the minimum.
    let svg_start = html.find("<svg").unwrap();
    let h: f32 = html[svg_start..]
        .split("height=\"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .and_then(|v| v.parse().ok())
        .unwrap();
    assert!(h > 22.0 * 38.0, "diagram height {h}");
    for a in &big.anchors.data_ports {
        assert!(html.contains(&format!("<a href=\"#{a}\"")));
    }
    // An out port with 30 consumers lists the first 5 components and links to the type page
    // for the other 25.
    let row_start = html
        .find(&format!("<tr id=\"{}\">", big.anchors.data_ports[1]))
        .unwrap();
    let row = &html[row_start..row_start + html[row_start..].find("</tr>").unwrap()];
    assert_eq!(row.matches("<li><a href=\"../components/sink").count(), 5);
    assert!(row.contains("class=\"more\"") && row.contains("../types/rtc-timedlong.html"));
    assert!(row.contains(">+25 — "), "the count of the rest");
    let t = read(&out.join("types/rtc-timedlong.html"));
    assert_eq!(section_links(&t, "consumers").len(), 30 + 22);
    // The unprovided interface is flagged; the Japanese component got a safe slug and page.
    let nobody = cat.interface("Nobody::Provides").unwrap();
    assert!(read(&out.join(format!("interfaces/{}.html", nobody.slug))).contains("warning flag"));
    let jp = cat
        .components
        .iter()
        .find(|c| c.profile.name() == "地図サーバ")
        .unwrap();
    assert!(jp.slug.is_ascii());
    let jhtml = read(&out.join(format!("components/{}.html", jp.slug)));
    assert!(title_of(&jhtml).starts_with("地図サーバ"));
    // Line breaks of plain text survive.
    assert!(html.contains("Big does things.<br>"));
    let broken = broken_links(&out);
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}

#[test]
fn rtcbuilder_placeholders_are_no_lead_and_no_group() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    // As RTCBuilder leaves a profile nobody filled in, beside a documented one.
    let mut ph = component("Wizard", "Category");
    ph.basic_info.description = s("ModuleDescription");
    ph.basic_info.vendor = s("VenderName");
    let cat = render_catalog(
        vec![ph, component("Cam", "Sensor")],
        &out,
        &SiteOptions::default(),
    );
    // The placeholder category is the uncategorised group, the vendor no vendor.
    let names: Vec<&str> = cat.categories.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["", "Sensor"]);
    let vendors: Vec<&str> = cat.vendors.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(vendors, ["", "Test"]);
    let w = cat
        .components
        .iter()
        .find(|c| c.profile.name() == "Wizard")
        .unwrap();
    let html = read(&out.join(format!("components/{}.html", w.slug)));
    // No lead text …
    assert!(!html.contains("class=\"summary\""), "no lead");
    // … but nothing lost: the basic facts keep every value, said to be the placeholder.
    for v in ["ModuleDescription", "Category", "VenderName"] {
        assert!(
            html.contains(&format!(
                "{v} (RTCBuilder&#39;s placeholder, not filled in)"
            )) || html.contains(&format!("{v} (RTCBuilder's placeholder, not filled in)")),
            "{v} in the basic facts"
        );
    }
    // The index lists the component without the placeholder as its description.
    let index = read(&out.join("index.html"));
    assert!(index.contains("Wizard") && !index.contains("ModuleDescription"));
    let groups = read(&out.join("categories/index.html"));
    assert!(groups.contains("(no category)") && !groups.contains(">Category<"));
}

#[test]
fn category_groups_sort_case_insensitively() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let profiles = ["Zeta", "camera", "Arm", "actuator", "Base"]
        .iter()
        .enumerate()
        .map(|(i, c)| component(&format!("C{i}"), c))
        .collect();
    let cat = render_catalog(profiles, &out, &SiteOptions::default());
    let names: Vec<&str> = cat.categories.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["actuator", "Arm", "Base", "camera", "Zeta"]);
    // The front page's group headings in that order.
    let index = read(&out.join("index.html"));
    let at = |name: &str| {
        index
            .find(&format!(
                ".html\">{name}</a> <span class=\"count\">1</span></h2>"
            ))
            .unwrap_or_else(|| panic!("{name} on the front page: {index}"))
    };
    let order: Vec<usize> = names.iter().map(|n| at(n)).collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{order:?}");
}

#[test]
fn labels_follow_the_site_language() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let mut c = component("Cam", "Sensor");
    c.data_ports
        .push(data_port("DataOutPort", "img", "RTC::CameraImage"));
    let site = SiteOptions {
        language: rtcdoc::i18n::Lang::Ja,
        ..Default::default()
    };
    render_catalog(vec![c], &out, &site);
    let html = read(&out.join("components/cam.html"));
    assert!(html.contains("<html lang=\"ja\">"));
    assert!(html.contains("データポート"));
}

// ---------- hostile input ----------

#[test]
fn no_payload_of_the_xss_fixture_survives() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::hostile_input(dir.path());
    let out = dir.path().join("site");
    let loaded = build_site(&input, &out, SiteOptions::default());
    assert_eq!(loaded.catalog.components.len(), 2, "both fixtures load");
    let mut checked = 0;
    let mut indexed = false;
    for (rel, bytes) in common::tree(&out) {
        let text = String::from_utf8_lossy(&bytes);
        if rel.ends_with(".js") {
            if rel == "search-index.js" || rel.starts_with("search/") {
                assert!(
                    !text.contains('<') && !text.contains('>'),
                    "{rel}: the index is JSON-escaped"
                );
                indexed |= text.contains("XSS");
            }
            continue;
        }
        if !rel.ends_with(".html") && !rel.ends_with(".xml") {
            continue;
        }
        for t in tags(&text) {
            match t.name.as_str() {
                "script" => {
                    let src = t.attr("src").unwrap_or("");
                    assert!(
                        ["search.js", "filter.js", "search-index.js"]
                            .iter()
                            .any(|ok| src.ends_with(ok)),
                        "{rel}: foreign script {t:?}"
                    );
                }
                "iframe" | "object" | "embed" | "style" | "base" | "form"
                    if t.name != "form" || t.attr("role") != Some("search") =>
                {
                    if t.name == "form"
                        && matches!(t.attr("id"), Some("catalog-filter" | "diag-filter"))
                    {
                        continue;
                    }
                    panic!("{rel}: forbidden element {t:?}");
                }
                "svg" => assert!(
                    t.attr("class").is_some_and(|c| c.contains("diagram")),
                    "{rel}: svg from profile text {t:?}"
                ),
                "img" => panic!("{rel}: image from profile text {t:?}"),
                _ => {}
            }
            for (k, v) in &t.attrs {
                assert!(!k.starts_with("on"), "{rel}: event handler {t:?}");
                assert!(k != "style", "{rel}: style attribute {t:?}");
                let v = v.trim().to_ascii_lowercase();
                // The description of a page is text (a vendor named `javascript:…`), no URL.
                let text_only = t.name == "meta" && t.attr("name") == Some("description");
                assert!(
                    text_only
                        || !(v.starts_with("javascript:")
                            || v.starts_with("data:")
                            || v.starts_with("vbscript:")),
                    "{rel}: script URL {t:?}"
                );
            }
        }
        // Raw markup of the payloads never appears unescaped.
        assert!(!text.contains("<script>alert"), "{rel}");
        assert!(!text.contains("<iframe"), "{rel}");
        assert!(!text.contains("<img"), "{rel}");
        checked += 1;
    }
    assert!(checked > 10);
    assert!(indexed, "payload text is indexed (inert)");
    // Escaped, the payload text is still shown (nothing is silently dropped from names).
    let c = &loaded.catalog.components[0];
    let html = read(&out.join(format!("components/{}.html", c.slug)));
    assert!(html.contains("&lt;"), "names are escaped, not removed");
    // A path-like name got a safe slug.
    for c in &loaded.catalog.components {
        assert!(!c.slug.contains('/') && !c.slug.contains(".."));
    }
}

// ---------- determinism, themes, validity ----------

#[test]
fn builds_are_byte_identical() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a");
    let b = dir.path().join("b");
    build_site(&examples(), &a, SiteOptions::default());
    build_site(&examples(), &b, SiteOptions::default());
    let ta = common::tree(&a);
    let tb = common::tree(&b);
    assert_eq!(
        ta.iter().map(|(p, _)| p).collect::<Vec<_>>(),
        tb.iter().map(|(p, _)| p).collect::<Vec<_>>()
    );
    for ((pa, ba), (_, bb)) in ta.iter().zip(&tb) {
        assert!(ba == bb, "{pa} differs between two builds");
    }
}

#[test]
fn a_theme_dir_overrides_single_files() {
    let dir = tempfile::tempdir().unwrap();
    let theme = dir.path().join("theme");
    common::write(
        &theme,
        "style.css",
        "/* my lab's style */\nbody { color: teal; }\n",
    );
    common::write(
        &theme,
        "404.html",
        "{% extends \"base.html\" %}{% block main %}<h1>Lost in the lab</h1>{% endblock %}",
    );
    let out = dir.path().join("site");
    build_site(
        &examples(),
        &out,
        SiteOptions {
            theme_dir: Some(theme),
            base_url: Some("https://robots.example.org/catalog/".into()),
            ..Default::default()
        },
    );
    assert!(read(&out.join("style.css")).contains("my lab's style"));
    let nf = read(&out.join("404.html"));
    assert!(nf.contains("Lost in the lab"));
    assert!(nf.contains("href=\"https://robots.example.org/catalog/style.css\""));
    // Files not overridden come from the built-in theme.
    assert!(read(&out.join("search.js")).contains("RTCDOC_INDEX"));
    assert!(read(&out.join("index.html")).contains("catalog-filter"));
    assert!(read(&out.join("sitemap.xml"))
        .contains("<loc>https://robots.example.org/catalog/index.html</loc>"));
}

#[test]
fn tidy_reports_no_errors() {
    if !have("tidy") {
        crate::common::missing_tool("tidy not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(&examples(), &out, SiteOptions::default());
    let mut errors = Vec::new();
    for rel in pages(&out).keys() {
        let o = std::process::Command::new("tidy")
            .args(["-q", "-e"])
            .arg(out.join(rel))
            .output_within(common::COMMAND_LIMIT)
            .expect("tidy");
        let report = String::from_utf8_lossy(&o.stderr);
        for line in report.lines().filter(|l| l.contains("Error:")) {
            errors.push(format!("{rel}: {line}"));
        }
        assert_ne!(o.status.code(), Some(2), "{rel}: {report}");
    }
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}

#[test]
fn search_index_is_compact() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&examples(), &out, SiteOptions::default());
    let idx = common::search_index::read(&out);
    let n = loaded.catalog.components.len() as f64;
    let size = |f: &dyn Fn(&str) -> bool| -> usize {
        idx.files
            .iter()
            .filter(|(p, _)| f(p))
            .map(|(_, t)| t.len())
            .sum()
    };
    let all = size(&|_| true);
    let first = size(&|p| p == "search-index.js");
    println!(
        "search index: {all} bytes in {} files, {:.0} bytes per component; the first file {first}",
        idx.files.len(),
        all as f64 / n
    );
    // As one file (with the port part) 1,664 bytes per component. Split, the token files hold
    // each token once with its postings, which costs more than a token per entry only when
    // few entries share tokens, as in these eleven (10,000 profiles: 13.52 MB before, 8.99 MB
    // split). A query loads the first file and the few others it needs.
    let per = all as f64 / n;
    assert!(per <= 1900.0, "{per} bytes per component");
    let per_first = first as f64 / n;
    assert!(per_first <= 160.0, "{per_first} bytes per component");
    let groups = |name: &str| -> Vec<Vec<String>> { idx.entry(name).groups.to_vec() };
    // Name, identifiers, prose: the name keeps all its tokens.
    assert!(groups("UsbCamera")[0].contains(&"usbcamera".to_string()));
    // Every document kind: types carry their IDL field names, interfaces their operations.
    let ty = groups("Detection::DetectedObject");
    assert!(ty[1].contains(&"confidence".to_string()), "{ty:?}");
    let iface = groups("Camera::CameraControl");
    assert!(
        iface[1].iter().any(|t| t.starts_with("setexposure")),
        "{iface:?}"
    );
    assert_eq!(idx.first["kinds"]["t"], "Data type");
    // A port description is indexed (Japanese as bigrams).
    assert!(groups("Localization")[2].contains(&"車輪".to_string()));
}

/// A data port row says each fact once: the unit is in its column (not again under
/// Description), a port without a unit of its own shows its documented unit there, and a
/// documented type or unit equal to the port's is not repeated; one that differs is kept
/// (nothing lost). `source-url` links "Source" to the file.
#[test]
fn port_rows_say_each_fact_once_and_source_links_to_the_repository() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let mut c = component("Odometry", "Sensor");
    let mut same = data_port("DataOutPort", "pose", "RTC::TimedPose2D");
    same.unit = s("m");
    same.doc = Some(rtcdoc::model::DataPortDoc {
        type_: s("TimedPose2D"),
        unit: s("m"),
        ..Default::default()
    });
    let mut documented = data_port("DataOutPort", "speed", "RTC::TimedDouble");
    documented.doc = Some(rtcdoc::model::DataPortDoc {
        unit: s("m/s"),
        ..Default::default()
    });
    let mut differs = data_port("DataOutPort", "heading", "RTC::TimedDouble");
    differs.unit = s("rad");
    differs.doc = Some(rtcdoc::model::DataPortDoc {
        type_: s("RTC::TimedFloat"),
        unit: s("deg"),
        ..Default::default()
    });
    c.data_ports = vec![same, documented, differs];
    let site = SiteOptions {
        source_url: Some("https://github.com/lab/robots/blob/main/{path}".into()),
        ..Default::default()
    };
    let cat = render_catalog(vec![c], &out, &site);
    let html = read(&out.join(format!("components/{}.html", cat.components[0].slug)));
    let row = |anchor: &str| {
        let start = html.find(&format!("<tr id=\"{anchor}\">")).unwrap();
        html[start..start + html[start..].find("</tr>").unwrap()].to_string()
    };
    let pose = row(&cat.components[0].anchors.data_ports[0]);
    assert!(pose.contains("<td data-label=\"Unit\">m</td>"), "{pose}");
    assert!(!pose.contains("<dt>Unit</dt>"), "unit twice: {pose}");
    assert!(!pose.contains("Documented type"), "type twice: {pose}");
    assert!(!pose.contains("Documented unit"), "unit twice: {pose}");
    let speed = row(&cat.components[0].anchors.data_ports[1]);
    assert!(
        speed.contains("<td data-label=\"Unit\">m/s</td>"),
        "{speed}"
    );
    assert!(!speed.contains("Documented unit"), "unit twice: {speed}");
    let heading = row(&cat.components[0].anchors.data_ports[2]);
    assert!(
        heading.contains("<td data-label=\"Unit\">rad</td>"),
        "{heading}"
    );
    assert!(
        heading.contains("<dt>Documented unit</dt><dd><p>deg</p>"),
        "{heading}"
    );
    assert!(
        heading.contains("<dt>Documented type</dt><dd><p>RTC::TimedFloat</p>"),
        "{heading}"
    );
    assert!(html.contains(
        "<dt>Source</dt><dd><a href=\"https://github.com/lab/robots/blob/main/c000/RTC.xml\"><code>c000/RTC.xml</code></a></dd>"
    ));
}

/// A component page leaves out a table column that is empty in every row (no Unit column
/// without units, no Description column for a lifecycle nobody described), shows the editor
/// widget once (in its column, with its meaning and step; not again under Description), a
/// documented default equal to the default once, and each target environment in a block of its
/// own. The Markdown page leaves out the same empty columns.
#[test]
fn component_tables_have_no_empty_column_and_say_the_widget_once() {
    use rtcdoc::model::{
        Configuration, ConfigurationDoc, ConfigurationSet, Language, Property, Target,
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let mut c = component("Arm", "Manipulator");
    c.data_ports = vec![data_port("DataInPort", "joints", "RTC::TimedDoubleSeq")];
    let widget = |w: &str| Property {
        name: s("__widget__"),
        value: s(w),
        ..Default::default()
    };
    c.configuration_set = Some(ConfigurationSet {
        configurations: vec![
            Configuration {
                name: s("gain"),
                type_: s("double"),
                default_value: s("0.5"),
                doc: Some(ConfigurationDoc {
                    default_value: s("0.5"),
                    description: s("Gain of the controller."),
                    ..Default::default()
                }),
                properties: vec![
                    widget("slider"),
                    Property {
                        name: s("__step__"),
                        value: s("0.1"),
                        ..Default::default()
                    },
                ],
                ..Default::default()
            },
            Configuration {
                name: s("port"),
                type_: s("string"),
                default_value: s("COM1"),
                properties: vec![widget("text")],
                ..Default::default()
            },
        ],
        ..Default::default()
    });
    c.language = Some(Language {
        kind: s("C++"),
        targets: vec![
            Target {
                os: s("Linux"),
                os_versions: vec!["Ubuntu 22.04".into()],
                ..Default::default()
            },
            Target {
                os: s("Windows"),
                cpus: vec!["x86_64".into()],
                ..Default::default()
            },
        ],
        ..Default::default()
    });
    let cat = render_catalog(vec![c], &out, &SiteOptions::default());
    let html = read(&out.join(format!("components/{}.html", cat.components[0].slug)));
    let table = |id: &str| {
        let start = html.find(&format!("<section id=\"{id}\"")).unwrap();
        html[start..start + html[start..].find("</section>").unwrap()].to_string()
    };
    let heads = |t: &str| -> Vec<String> {
        t.split("<th scope=\"col\">")
            .skip(1)
            .map(|h| h[..h.find("</th>").unwrap()].to_string())
            .collect()
    };
    let ports = table("data-ports");
    assert_eq!(heads(&ports), ["Direction", "Name", "Type"], "{ports}");
    let conf = table("configuration");
    assert_eq!(
        heads(&conf),
        ["Name", "Type", "Default", "Widget", "Description"],
        "{conf}"
    );
    assert!(
        conf.contains("<td data-label=\"Widget\">slider (slider), Step 0.1</td>"),
        "{conf}"
    );
    assert!(
        conf.contains("<td data-label=\"Widget\">text (text box)</td>"),
        "{conf}"
    );
    assert!(!conf.contains("<dt>Widget</dt>"), "widget twice: {conf}");
    assert!(!conf.contains("<dt>Step</dt>"), "step twice: {conf}");
    assert!(
        !conf.contains("Documented default"),
        "default twice: {conf}"
    );
    assert!(conf.contains("Gain of the controller."), "{conf}");
    let life = table("lifecycle");
    assert_eq!(heads(&life), ["Callback", "Implemented"], "{life}");
    let lang = table("language");
    assert_eq!(lang.matches("<div class=\"target\">").count(), 2, "{lang}");
    assert!(lang.contains("<h4>Target environment 1</h4>"), "{lang}");
    assert!(lang.contains("<h4>Target environment 2</h4>"), "{lang}");
    let second = &lang[lang.find("Target environment 2").unwrap()..];
    assert!(
        second.contains("x86_64") && !second.contains("Ubuntu"),
        "{lang}"
    );

    // The Markdown page: the same view, so the same columns (the widget in its own column,
    // said once) and the same ones left out.
    let md_out = dir.path().join("md");
    let staging = Staging::new(&md_out).expect("staging");
    rtcdoc::render::markdown::MarkdownRenderer
        .render(
            &RenderContext {
                catalog: &cat,
                site: &SiteOptions::default(),
            },
            &staging,
        )
        .expect("render");
    staging.commit().expect("commit");
    let md = read(&md_out.join(format!("components/{}.md", cat.components[0].slug)));
    assert!(
        md.contains("| Name | Direction | Data type |\n"),
        "data port columns: {md}"
    );
    assert!(
        md.contains("| Name | Type | Default | Widget | Description |\n"),
        "configuration columns: {md}"
    );
    assert!(md.contains("| slider (slider), Step 0.1 |"), "{md}");
    assert!(!md.contains("**Widget**"), "widget twice: {md}");
    assert!(
        md.contains("| Callback | Implemented |\n"),
        "lifecycle: {md}"
    );
}

/// The diagnostics page names severities in the site's language, in its badges and in its
/// filter, as the other pages do; the filter's values stay the codes' severities.
#[test]
fn the_diagnostics_page_names_severities_in_the_sites_language() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::root().join("examples");
    let input = input.display().to_string();
    for (lang, warning, error) in [("en", "warning", "error"), ("ja", "警告", "エラー")] {
        let out = dir.path().join(lang);
        let o = common::rtcdoc(
            &[
                "build",
                &input,
                "--language",
                lang,
                "-o",
                &out.display().to_string(),
                "-q",
            ],
            dir.path(),
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let page = std::fs::read_to_string(out.join("diagnostics.html")).unwrap();
        assert!(
            page.contains(&format!(r#"<span class="sev warning">{warning}</span>"#)),
            "{lang}"
        );
        assert!(
            page.contains(&format!(r#"<option value="warning">{warning}</option>"#))
                && page.contains(&format!(r#"<option value="error">{error}</option>"#)),
            "{lang}"
        );
        // The messages' and hints' code spans are code, as in Markdown and Doxygen.
        assert!(
            page.contains(" vendor <code>Example Robotics</code> contains whitespace")
                && page.contains(
                    "(spaces: <code>AIST Lab</code> → <code>AISTLab</code>; a <code>:</code>)"
                )
                && !page.contains("`Example Robotics`"),
            "{lang}"
        );
    }
}

/// The index's `ports` part: one entry per catalogue type with ports, holding that type's
/// producers and consumers as the catalogue computed them (the type pages' rule), each port
/// by its component entry and its anchor on the component page.
#[test]
fn search_index_holds_the_ports_by_catalogue_type() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let loaded = build_site(&examples(), &out, SiteOptions::default());
    let idx = common::search_index::read(&out);
    let entries = &idx.entries;
    let ports = &idx.ports;
    let find = |list: &str, name: &str| -> serde_json::Value {
        ports[list]
            .as_array()
            .unwrap()
            .iter()
            .find(|t| t[0] == name)
            .unwrap_or_else(|| panic!("{name} in ports.{list}"))
            .clone()
    };
    // `Component.port` of each port of a list, checking its anchor is on the component page.
    // An interface's name is `port.interface`.
    let e_is_interface = |p: &serde_json::Value| p[1].as_str().unwrap().contains('.');
    let names = |l: &serde_json::Value| -> Vec<String> {
        l.as_array()
            .unwrap()
            .iter()
            .map(|p| {
                let e = &entries[p[0].as_u64().unwrap() as usize];
                assert_eq!(e.kind, "c", "{p}: a component entry");
                let page = common::read_page(&out.join(&e.href));
                // The anchor search.js makes when the index leaves it out.
                let made = format!(
                    "{}{}",
                    if e_is_interface(p) { "if-" } else { "port-" },
                    p[1].as_str()
                        .unwrap()
                        .to_lowercase()
                        .replace(['_', '.'], "-")
                );
                let anchor = format!(
                    "id=\"{}\"",
                    p.get(2).and_then(|a| a.as_str()).unwrap_or(&made)
                );
                assert!(page.contains(&anchor), "{anchor} on {}", e.href);
                format!("{}.{}", e.name, p[1].as_str().unwrap())
            })
            .collect()
    };
    let long = find("d", "RTC::TimedLong");
    assert_eq!(
        long[1],
        serde_json::json!(["TimedLong"]),
        "the name is not repeated"
    );
    assert_eq!(names(&long[3]), ["SafetyMonitor.person_count"]);
    assert_eq!(
        names(&long[2]),
        ["ObjectDetector.count", "UrgRangeSensor.status"]
    );
    // A repository id met in a profile, and one the IDL gives, are spellings of the entry.
    let pose = find("d", "RTC::TimedPose2D");
    assert!(pose[1]
        .as_array()
        .unwrap()
        .iter()
        .any(|s| s == "IDL:RTC/TimedPose2D:1.0"));
    let objects = find("d", "Detection::TimedObjectList");
    let ids = objects[1].as_array().unwrap();
    assert!(
        ids.iter().any(|s| s == "IDL:Detection/TimedObjectList:1.0"),
        "{ids:?}"
    );
    let map = find("i", "RTC::OGMapServer");
    assert_eq!(names(&map[2]), ["MapServer.MapService.map_server"]);
    assert_eq!(
        names(&map[3]),
        [
            "Localization.MapService.map_server",
            "PathPlanner.MapService.map_server"
        ]
    );
    // Every type with a port, with as many producers and consumers as its page lists.
    let cat = &loaded.catalog;
    let with_ports = cat
        .data_types
        .iter()
        .filter(|t| !t.uses.producers.is_empty() || !t.uses.consumers.is_empty());
    assert_eq!(
        with_ports.clone().count(),
        ports["d"].as_array().unwrap().len()
    );
    for t in with_ports {
        let e = find("d", &t.name);
        assert_eq!(
            e[2].as_array().unwrap().len(),
            t.uses.producers.len(),
            "{}",
            t.name
        );
        assert_eq!(
            e[3].as_array().unwrap().len(),
            t.uses.consumers.len(),
            "{}",
            t.name
        );
    }
    // The port kinds' labels are the first file's, beside the entry kinds'.
    assert_eq!(idx.first["kinds"]["in"], "In");
}
