//! The built-in theme's component, data type and interface pages are written by Rust code
//! (`render/html/native/`) rather than by running `base.html` + `component.html` (`type.html`,
//! `interface.html`, with `macros.html`). These tests hold the two to the same bytes: a theme
//! directory holding unchanged copies of those templates makes rtcdoc run them, and the whole
//! site must come out identical to the default build — for the
//! examples, every fixture set (hostile text, odd dialects, diagnostics), both languages, a
//! title with markup, a catalogue whose shared type overflows the "connects to" lists and, when
//! present, the real-world corpus.

use crate::common;
use crate::html_support;

use html_support::*;
use rtcdoc::i18n::Lang;
use rtcdoc::render::SiteOptions;
use std::path::{Path, PathBuf};

/// A theme directory holding unchanged copies of the built-in `names`.
fn template_theme(dir: &Path, names: &[&str]) -> PathBuf {
    let theme = dir.join("theme");
    for n in names {
        let src = common::root().join("themes/default").join(n);
        common::write(
            &theme,
            n,
            &std::fs::read_to_string(&src).expect("built-in template"),
        );
    }
    theme
}

/// The templates the built-in writer stands for.
const NATIVE: [&str; 3] = ["component.html", "type.html", "interface.html"];

/// Builds `input` with the built-in theme and through the templates; asserts byte equality of
/// every file and returns how many component pages were compared.
fn same_both_ways(input: &Path, site: SiteOptions) -> usize {
    built_both_ways(input, site)
        .iter()
        .filter(|(path, _)| path.starts_with("components/"))
        .count()
}

/// [`same_both_ways`], returning the site's files (path, bytes).
fn built_both_ways(input: &Path, site: SiteOptions) -> Vec<(String, Vec<u8>)> {
    let dir = tempfile::tempdir().unwrap();
    let native = dir.path().join("native");
    let templated = dir.path().join("templated");
    build_site(input, &native, site.clone());
    build_site(
        input,
        &templated,
        SiteOptions {
            theme_dir: Some(template_theme(dir.path(), &NATIVE)),
            ..site
        },
    );
    let a = common::tree(&native);
    let b = common::tree(&templated);
    assert_eq!(
        a.iter().map(|(p, _)| p).collect::<Vec<_>>(),
        b.iter().map(|(p, _)| p).collect::<Vec<_>>(),
        "{}",
        input.display()
    );
    for ((path, x), (_, y)) in a.iter().zip(&b) {
        if x != y {
            let at = x.iter().zip(y).position(|(p, q)| p != q);
            let at = at.unwrap_or(x.len().min(y.len()));
            let around = |v: &[u8]| {
                String::from_utf8_lossy(&v[at.saturating_sub(200)..(at + 200).min(v.len())])
                    .into_owned()
            };
            panic!(
                "{}: {path} differs at byte {at}\nnative:    {:?}\ntemplated: {:?}",
                input.display(),
                around(x),
                around(y),
            );
        }
    }
    a
}

#[test]
fn examples_and_fixtures_match_the_templates() {
    let mut inputs = vec![examples()];
    let fixtures = common::root().join("tests/fixtures");
    let mut sets: Vec<PathBuf> = std::fs::read_dir(&fixtures)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        // IDL reader fixtures (tests/suite/idl_reader.rs) hold no profiles.
        .filter(|p| !p.ends_with("idl"))
        .collect();
    sets.sort();
    assert!(sets.len() >= 5, "fixture sets: {sets:?}");
    inputs.extend(sets);
    for input in &inputs {
        let pages = same_both_ways(input, SiteOptions::default());
        assert!(pages > 0, "{} has no component page", input.display());
    }
}

/// Type and interface pages with every part the templates can print: an IDL file section
/// (linked by `source-url`), struct fields, a union's cases and switch, typedefs, enum values,
/// an interface with bases (their operations and attributes inherited), attributes (read-only
/// too), operations with documented parameters,
/// `oneway` and `raises`, an interface required and not provided, a type contained in another.
#[test]
fn every_part_of_a_type_page_matches_the_templates() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    for idl in ["MyDataTypes.idl", "MyService.idl"] {
        let text =
            std::fs::read_to_string(common::root().join("tests/fixtures/idl").join(idl)).unwrap();
        common::write(&input, &format!("idl/{idl}"), &text);
    }
    let service = r#"  <rtc:ServicePorts xsi:type="rtcExt:serviceport_ext" rtcExt:position="TOP" rtc:name="Paths">
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:type="Demo::PathService" rtc:idlFile="MyService.idl" rtc:instanceName="paths" rtc:direction="Required" rtc:name="paths"/>
  </rtc:ServicePorts>
</rtc:RtcProfile>"#;
    let a = common::xml_profile(
        "A",
        &[
            ("DataOutPort", "foo", "RTC::TimedFoo"),
            ("DataOutPort", "time", "RTC::Time"),
            ("DataOutPort", "reading", "RTC::Reading"),
            ("DataOutPort", "colour", "RTC::Colour"),
            ("DataOutPort", "big", "RTC::Big"),
        ],
    )
    .replace("</rtc:RtcProfile>", service);
    common::write(&input, "a/RTC.xml", &a);
    common::write(
        &input,
        "b/RTC.xml",
        &common::xml_profile("B", &[("DataInPort", "foo", "RTC::TimedFoo")]),
    );
    let site = || SiteOptions {
        source_url: Some("https://example.org/repo/blob/main/{path}".into()),
        ..SiteOptions::default()
    };
    let all: String = built_both_ways(&input, site())
        .iter()
        .filter(|(path, _)| path.starts_with("types/") || path.starts_with("interfaces/"))
        .map(|(_, bytes)| String::from_utf8_lossy(bytes))
        .collect();
    for part in [
        "<section id=\"idl-file\">",
        "class=\"idl-fields\"",
        "class=\"idl-values\"",
        "class=\"idl-attributes\"",
        "class=\"idl-operation\"",
        "<ul class=\"idl-inherited\"><li><a href=\"../interfaces/demo-base.html#op-ping\">",
        "<ul class=\"idl-inherited\"><li><a href=\"../interfaces/demo-other.html#attr-label\"><code>label</code></a> (read-only): A label.</li>",
        "<dl class=\"params\"><dt>",
        " <code>raises (</code>",
        "<code>oneway </code>",
        "<section id=\"contained-in\">",
        "<section id=\"used-by-interfaces\">",
        "<section id=\"producers\">",
        "<section id=\"providers\">",
        "class=\"warning flag\"",
        "<table class=\"uses\">",
    ] {
        assert!(all.contains(part), "no compared page shows {part}");
    }
}

#[test]
fn japanese_labels_and_a_marked_up_title_match_the_templates() {
    let pages = same_both_ways(
        &examples(),
        SiteOptions {
            language: Lang::Ja,
            title: "<b>Lab's \"robots\" & co</b>".into(),
            ..SiteOptions::default()
        },
    );
    assert_eq!(pages, 11);
}

#[test]
fn overflowing_peer_lists_and_odd_names_match_the_templates() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    // One producer and 25 consumers of one type: the producer's row lists 20 peers and links
    // to the type page for the rest; names with markup characters are escaped the same way.
    common::write(
        &input,
        "src/RTC.xml",
        &common::xml_profile("Source", &[("DataOutPort", "out", "RTC::TimedLong")]),
    );
    for i in 0..25 {
        common::write(
            &input,
            &format!("sink{i:02}/RTC.xml"),
            &common::xml_profile(
                &format!("Sink{i:02}"),
                &[
                    ("DataInPort", "in", "RTC::TimedLong"),
                    ("DataInPort", "q&amp;a", "My::&lt;Odd&gt;"),
                    ("Weird", "x", ""),
                ],
            ),
        );
    }
    assert_eq!(same_both_ways(&input, SiteOptions::default()), 26);
}

#[test]
fn corpus_matches_the_templates() {
    let Some(corpus) = common::corpus() else {
        return;
    };
    assert!(same_both_ways(&corpus, SiteOptions::default()) > 100);
}

/// A theme that overrides `macros.html` gets its macros on the type, interface and component
/// pages (none of them is written by the Rust writer then).
#[test]
fn overridden_macros_are_used() {
    let dir = tempfile::tempdir().unwrap();
    let theme = dir.path().join("theme");
    let macros = std::fs::read_to_string(common::root().join("themes/default/macros.html"))
        .unwrap()
        .replace("<table class=\"uses\">", "<table class=\"uses mine\">")
        .replace(
            "<table class=\"history-table\">",
            "<table class=\"history-table mine\">",
        );
    common::write(&theme, "macros.html", &macros);
    let site = |theme_dir: Option<PathBuf>| SiteOptions {
        theme_dir,
        ..SiteOptions::default()
    };
    let out = dir.path().join("site");
    build_site(&examples(), &out, site(Some(theme.clone())));
    let types = common::tree(&out.join("types"));
    assert!(types.len() > 3);
    assert!(types
        .iter()
        .any(|(_, b)| String::from_utf8_lossy(b).contains("uses mine")));
    // RTCBuilder's dated backups give the components a history section (read by the CLI).
    let backups = common::root().join("tests/fixtures/backups");
    let pages = |name: &str, theme_args: &[&str]| {
        let out = dir.path().join(name);
        let mut args = vec![
            "build",
            backups.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "-q",
        ];
        args.extend(theme_args);
        let run = common::rtcdoc(&args, dir.path());
        assert!(run.status.success(), "{run:?}");
        common::tree(&out.join("components"))
    };
    let themed = pages("backups", &["--theme", theme.to_str().unwrap()]);
    assert!(themed.iter().any(|(_, b)| {
        let page = String::from_utf8_lossy(b);
        page.contains("<section id=\"change-history\">") && page.contains("history-table mine")
    }));
    let plain = pages("plain", &[]);
    assert!(plain
        .iter()
        .any(|(_, b)| String::from_utf8_lossy(b).contains("<section id=\"change-history\">")));
    assert!(plain
        .iter()
        .all(|(_, b)| !String::from_utf8_lossy(b).contains("mine")));
}

/// A theme that overrides either template gets its own markup on every component page (the
/// Rust writer is used only for the built-in pair).
#[test]
fn overridden_component_or_base_templates_are_used() {
    let dir = tempfile::tempdir().unwrap();
    for (name, content) in [
        (
            "component.html",
            "{% extends \"base.html\" %}{% block main %}<p class=\"mine\">{{ name }}</p>{% endblock %}",
        ),
        (
            "base.html",
            "<!DOCTYPE html><html><body class=\"mine\">{% block main %}{% endblock %}</body></html>",
        ),
    ] {
        let theme = dir.path().join(format!("theme-{name}"));
        common::write(&theme, name, content);
        let out = dir.path().join(format!("site-{name}"));
        build_site(
            &examples(),
            &out,
            SiteOptions {
                theme_dir: Some(theme),
                ..SiteOptions::default()
            },
        );
        let pages: Vec<_> = std::fs::read_dir(out.join("components"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        assert_eq!(pages.len(), 11);
        for p in pages {
            let html = std::fs::read_to_string(&p).unwrap();
            assert!(
                html.contains("class=\"mine\""),
                "{name}: {} ignores the theme",
                p.display()
            );
        }
    }
}
