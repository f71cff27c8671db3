//! Headless Chromium against the generated site: search works offline from `file://` in English
//! and Japanese, and no payload of the hostile fixture ends up executable in the live DOM.
//! Skipped, with a visible message, when `/usr/bin/chromium` is not installed.

mod common;
mod html_support;

use html_support::*;
use rtcdoc::render::SiteOptions;
use std::path::Path;

const CHROMIUM: &str = "/usr/bin/chromium";

fn chromium() -> bool {
    if Path::new(CHROMIUM).exists() {
        true
    } else {
        println!("skipped: chromium not installed");
        false
    }
}

/// The DOM of `url` after its scripts ran (virtual time lets deferred scripts finish).
fn dump_dom(url: &str, profile_dir: &Path) -> String {
    let o = std::process::Command::new(CHROMIUM)
        .args([
            "--headless=new",
            "--disable-gpu",
            "--no-sandbox",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--virtual-time-budget=5000",
        ])
        .arg(format!("--user-data-dir={}", profile_dir.display()))
        .arg("--dump-dom")
        .arg(url)
        .output()
        .expect("run chromium");
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn file_url(p: &Path) -> String {
    format!("file://{}", p.display())
}

fn result_names(dom: &str) -> Vec<String> {
    dom.split("class=\"r-name\">")
        .skip(1)
        .filter_map(|s| s.split('<').next())
        .map(str::to_string)
        .collect()
}

#[test]
fn search_finds_english_and_japanese_words_from_file_urls() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(&examples(), &out, SiteOptions::default());
    let prof = dir.path().join("chromium");
    // The search page runs `?q=` on load.
    let dom = dump_dom(
        &format!("{}?q=camera", file_url(&out.join("search.html"))),
        &prof,
    );
    let names = result_names(&dom);
    assert!(names.iter().any(|n| n == "UsbCamera"), "camera → {names:?}");
    // The search box of the index page shows live results too; Japanese via bigrams.
    let dom = dump_dom(
        &format!("{}?q=%E7%94%BB%E5%83%8F", file_url(&out.join("index.html"))),
        &prof,
    );
    let names = result_names(&dom);
    assert!(names.iter().any(|n| n == "UsbCamera"), "画像 → {names:?}");
    // A port name and a data type find their components.
    let dom = dump_dom(
        &format!("{}?q=TimedVelocity2D", file_url(&out.join("search.html"))),
        &prof,
    );
    assert!(!result_names(&dom).is_empty(), "type search");
}

#[test]
fn no_payload_of_the_xss_fixture_is_live_in_the_browser() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let input = common::hostile_input(dir.path());
    let out = dir.path().join("site");
    let loaded = build_site(&input, &out, SiteOptions::default());
    let prof = dir.path().join("chromium");
    let mut urls: Vec<String> = loaded
        .catalog
        .components
        .iter()
        .map(|c| file_url(&out.join(format!("components/{}.html", c.slug))))
        .collect();
    urls.push(file_url(&out.join("index.html")));
    // Search results are built from the index with textContent: search for the payloads.
    urls.push(format!("{}?q=alert", file_url(&out.join("search.html"))));
    urls.push(format!("{}?q=script", file_url(&out.join("index.html"))));
    for url in urls {
        let dom = dump_dom(&url, &prof);
        assert!(dom.contains("</html>"), "{url}: page rendered");
        for t in tags(&dom) {
            for (k, v) in &t.attrs {
                assert!(!k.starts_with("on"), "{url}: live event handler {t:?}");
                let v = v.trim().to_ascii_lowercase();
                assert!(!v.starts_with("javascript:"), "{url}: script URL {t:?}");
            }
            if t.name == "script" {
                let src = t.attr("src").unwrap_or("");
                assert!(
                    ["search.js", "filter.js", "search-index.js"]
                        .iter()
                        .any(|ok| src.ends_with(ok)),
                    "{url}: foreign script {t:?}"
                );
            }
            assert!(
                !matches!(t.name.as_str(), "iframe" | "img" | "object" | "embed"),
                "{url}: {t:?}"
            );
        }
    }
}
