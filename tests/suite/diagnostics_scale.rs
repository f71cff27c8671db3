//! The diagnostics page at catalogue scale: 10,000 profiles with a warning each made an 11 MB
//! `diagnostics.html`. Files are split into pages (errors first), each well under 1 MB, and
//! every finding is still on one of them.

use crate::common;
use crate::html_support;
use common::*;
use html_support::{broken_links, build_site};
use rtcdoc::render::SiteOptions;

#[test]
fn ten_thousand_profiles_with_findings_make_small_diagnostics_pages() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    // RTC203 (vendor with whitespace) and RTC202 in every profile: two warnings each.
    let warned =
        std::fs::read_to_string(root().join("tests/fixtures/check/RTC203-bad.xml")).unwrap();
    for i in 0..10_000 {
        write(
            &input,
            &format!("g{}/C{i}/RTC.xml", i / 100),
            &warned
                .replace("rtc:name=\"Comp\"", &format!("rtc:name=\"C{i}\""))
                .replace(":Comp:", &format!(":C{i}:")),
        );
    }
    // One profile with an error, at the end of the walk: it still comes first.
    write(
        &input,
        "zz/Broken/RTC.xml",
        &std::fs::read_to_string(root().join("tests/fixtures/check/RTC301-bad.xml")).unwrap(),
    );
    let out = dir.path().join("site");
    let loaded = build_site(&input, &out, SiteOptions::default());
    let warnings = loaded
        .catalog
        .diagnostics
        .iter()
        .filter(|d| d.severity == rtcdoc::diagnostic::Severity::Warning)
        .count();
    assert!(warnings >= 10_000, "{warnings}");

    let bytes = std::fs::metadata(out.join("diagnostics.html"))
        .unwrap()
        .len();
    assert!(bytes < 1_000_000, "diagnostics.html is {bytes} bytes");
    let first = common::read_page(&out.join("diagnostics.html"));
    // Errors first: the broken profile's section is the first one on the first page.
    let first_section = first.split("<section class=\"diag-file\">").nth(1).unwrap();
    assert!(
        first_section.contains("zz/Broken/RTC.xml"),
        "{first_section}"
    );
    assert!(first.contains("<nav class=\"pages\""));
    let mut findings = first.matches("<li data-sev=\"warning\"").count();
    let mut pages = 1;
    for entry in std::fs::read_dir(out.join("diagnostics")).unwrap() {
        let page = std::fs::read_to_string(entry.unwrap().path()).unwrap();
        assert!(
            page.len() < 1_000_000,
            "a diagnostics page is {} bytes",
            page.len()
        );
        assert!(page.contains("<script src=\"../filter.js\" defer>"));
        findings += page.matches("<li data-sev=\"warning\"").count();
        pages += 1;
    }
    assert_eq!(findings, warnings, "every warning is on a page");
    assert_eq!(pages, 10_001_usize.div_ceil(200));
    assert!(out.join("diagnostics/2.html").exists());
    let broken: Vec<String> = broken_links(&out)
        .into_iter()
        .filter(|l| l.contains("diagnostics"))
        .collect();
    assert!(broken.is_empty(), "{broken:?}");
}
