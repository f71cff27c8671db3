//! The built-in theme's component pages are written by Rust code (`render/html/native.rs`)
//! rather than by running `base.html` + `component.html`. These tests hold the two to the same
//! bytes: a theme directory holding an unchanged copy of `component.html` makes rtcdoc run the
//! templates, and the whole site must come out identical to the default build — for the
//! examples, every fixture set (hostile text, odd dialects, diagnostics), both languages, a
//! title with markup, a catalogue whose shared type overflows the "connects to" lists and, when
//! present, the real-world corpus.

mod common;
mod html_support;

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

/// Builds `input` with the built-in theme and through the templates; asserts byte equality of
/// every file and returns how many component pages were compared.
fn same_both_ways(input: &Path, site: SiteOptions) -> usize {
    let dir = tempfile::tempdir().unwrap();
    let native = dir.path().join("native");
    let templated = dir.path().join("templated");
    build_site(input, &native, site.clone());
    build_site(
        input,
        &templated,
        SiteOptions {
            theme_dir: Some(template_theme(dir.path(), &["component.html"])),
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
    let mut pages = 0;
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
        pages += usize::from(path.starts_with("components/"));
    }
    pages
}

#[test]
fn examples_and_fixtures_match_the_templates() {
    let mut inputs = vec![examples()];
    let fixtures = common::root().join("tests/fixtures");
    let mut sets: Vec<PathBuf> = std::fs::read_dir(&fixtures)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        // IDL reader fixtures (tests/idl_reader.rs) hold no profiles.
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
