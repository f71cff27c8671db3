//! A component folder's README (issue 17): which file is read, what the component page shows
//! (headings, table, images copied, links resolved or dropped, payloads removed), the findings
//! (generated, unreadable, images), the JSON, the Markdown and Doxygen outputs, bounds, `serve`'s
//! incremental rebuild and determinism. The fixture set is `tests/fixtures/readme`.

use crate::common;

use rtcdoc::build::{self, BuildOptions, LoadOptions};
use rtcdoc::diagnostic::Severity;
use rtcdoc::render::{Format, SiteOptions};
use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    common::root().join("tests/fixtures/readme")
}

fn build_into(input: &Path, out: &Path, formats: Vec<Format>, site: SiteOptions) {
    let opts = BuildOptions {
        input: input.to_path_buf(),
        output: out.to_path_buf(),
        formats,
        strict: false,
        load: LoadOptions::default(),
        site,
    };
    build::build(&opts).expect("build succeeds");
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// A kept link as the page writes it.
fn link(href: &str, text: &str) -> String {
    format!("<a href=\"{href}\" rel=\"noopener noreferrer\">{text}</a>")
}

/// Builds the fixture set in `formats` into a new temporary directory: (it, the output).
fn build_fixture(formats: Vec<Format>, site: SiteOptions) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    build_into(&fixture(), &out, formats, site);
    (dir, out)
}

/// The README section of a component page.
fn readme_section(html: &str) -> &str {
    let start = html
        .find("<section id=\"readme\"")
        .unwrap_or_else(|| panic!("no README section:\n{html}"));
    let end = start + html[start..].find("</section>").expect("section end");
    &html[start..end]
}

/// The copied images below `dir` (`assets/readme/…`), sorted.
fn assets(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir.join("assets/readme"))
        .map(|r| {
            r.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

#[test]
fn the_component_page_shows_the_readme_sanitised_with_links_and_images_resolved() {
    let (_dir, out) = build_fixture(vec![Format::Html], SiteOptions::default());
    let page = read(&out.join("components/camera.html"));
    let s = readme_section(&page);

    // After the Document Profile section, with a TOC entry.
    assert!(
        page.contains("<li><a href=\"#readme\">README</a></li>"),
        "TOC"
    );
    assert!(page.find("id=\"document\"") < page.find("id=\"readme\""));
    assert!(page.find("id=\"readme\"") < page.find("id=\"diagram\""));
    // Headings shifted under the section's <h2>, with prefixed GitHub-style ids.
    assert!(s.contains("<h2>README</h2>"), "{s}");
    assert!(
        s.contains("<h3 id=\"readme-camera-component\">Camera component</h3>"),
        "{s}"
    );
    assert!(s.contains("<h4 id=\"readme-wiring-and-ports\">"), "{s}");
    // A fragment link goes to the heading; one to no heading keeps only its text.
    assert!(
        s.contains(&link("#readme-wiring-and-ports", "the wiring")),
        "{s}"
    );
    assert!(
        s.contains("or to nowhere.") && !s.contains("no-such-heading"),
        "{s}"
    );
    // The table, task list and footnote.
    assert!(
        s.contains("<table>") && s.contains("<td><code>image</code></td>"),
        "{s}"
    );
    assert!(
        s.contains("☑ captures") && s.contains("☐ records") && !s.contains("<input"),
        "{s}"
    );
    assert!(
        s.contains("href=\"#readme-fn-cal\"") && s.contains("id=\"readme-fn-cal\""),
        "{s}"
    );

    // The local image is copied once and shown lazily with its alt text.
    let copied = assets(&out);
    assert_eq!(copied.len(), 1, "{copied:?}");
    assert!(copied[0].starts_with("diagram-") && copied[0].ends_with(".svg"));
    assert_eq!(
        std::fs::read(out.join("assets/readme").join(&copied[0])).unwrap(),
        std::fs::read(fixture().join("cam/img/diagram.svg")).unwrap()
    );
    let img = format!(
        "<img src=\"../assets/readme/{}\" alt=\"Block diagram\" loading=\"lazy\">",
        copied[0]
    );
    assert!(s.contains(&img), "{s}");
    // The missing image: its alt text only. The remote one: a link, no request.
    assert!(
        s.contains("<p>Missing photo</p>") && !s.contains("missing.png"),
        "{s}"
    );
    assert!(
        s.contains(&link("https://example.org/logo.png", "Remote logo")),
        "{s}"
    );
    assert!(!s.contains("<img src=\"http"), "{s}");
    // Links: another component's profile → its page; outside the input and, without
    // source-url, other files → text only; https kept.
    assert!(
        s.contains(&link("../components/filter.html", "filter")),
        "{s}"
    );
    assert!(
        s.contains("the manual, the") && !s.contains("manual.md"),
        "{s}"
    );
    assert!(
        s.contains("password file") && !s.contains("passwd\""),
        "{s}"
    );
    assert!(
        s.contains(&link("https://example.org/camera", "the project")),
        "{s}"
    );

    // Hostile raw HTML and URLs.
    for bad in [
        "<script",
        "alert(\"readme\")",
        "onerror",
        "javascript:",
        "<img src=\"data:",
        "<iframe",
        "<style",
        "display: none",
        "id=\"overview\"",
        "<h1",
    ] {
        assert!(!s.contains(bad), "{bad} survived:\n{s}");
    }
    assert!(
        s.contains("js link") && s.contains("Raw heading"),
        "text kept: {s}"
    );
    // The raw <img> of the same local file uses the same copy, with an (empty) alt.
    assert_eq!(
        s.matches(&format!("../assets/readme/{}", copied[0]))
            .count(),
        2,
        "{s}"
    );
    assert!(!s.contains("<img src=\"img/"), "{s}");

    // Every profile of the folder shows it; a generated README and a README.txt do not.
    assert!(read(&out.join("components/camerasim.html"))
        .contains("<h3 id=\"readme-camera-component\">"));
    for other in ["filter", "other"] {
        let p = read(&out.join(format!("components/{other}.html")));
        assert!(!p.contains("id=\"readme\""), "{other} shows a README");
        assert!(!p.contains("href=\"#readme\""), "{other} lists a README");
    }
    // The page has one id of each value.
    let mut ids: Vec<&str> = page
        .split(" id=\"")
        .skip(1)
        .filter_map(|r| r.split('"').next())
        .collect();
    let n = ids.len();
    ids.sort();
    ids.dedup();
    assert_eq!(ids.len(), n, "duplicate ids");
}

#[test]
fn source_url_links_the_readmes_other_files_to_the_repository() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let site = SiteOptions {
        source_url: Some("https://example.org/repo/blob/main/{path}".into()),
        ..SiteOptions::default()
    };
    build_into(&fixture(), &out, vec![Format::Html], site);
    let s = read(&out.join("components/camera.html"));
    let s = readme_section(&s);
    assert!(
        s.contains(&link(
            "https://example.org/repo/blob/main/cam/docs/manual.md#setup",
            "manual"
        )),
        "{s}"
    );
    // A catalogued profile still goes to its page; outside the input still nothing.
    assert!(s.contains("href=\"../components/filter.html\""), "{s}");
    assert!(!s.contains("etc/passwd\""), "{s}");
}

#[test]
fn findings_say_which_readmes_and_images_are_not_shown() {
    let loaded = build::load(&fixture(), &LoadOptions::default()).expect("load");
    let d: Vec<_> = loaded
        .catalog
        .diagnostics
        .iter()
        .filter(|d| d.code.starts_with("RTC70"))
        .collect();
    assert_eq!(d.len(), 2, "{d:#?}");
    let generated = d.iter().find(|d| d.code == "RTC701").expect("RTC701");
    assert_eq!(generated.severity, Severity::Info);
    assert_eq!(generated.file, "filter/README.md");
    assert_eq!(generated.pos.map(|p| (p.line, p.column)), Some((2, 1)));
    let image = d.iter().find(|d| d.code == "RTC703").expect("RTC703");
    assert_eq!(image.severity, Severity::Warning);
    assert_eq!(image.file, "cam/README.md");
    assert_eq!(image.pos.map(|p| (p.line, p.column)), Some((14, 18)));
    assert!(image.message.contains("img/missing.png") && image.hint.is_some());
    // `check` shows them; the info only with --verbose.
    let o = common::rtcdoc(
        &["check", "--verbose", "tests/fixtures/readme"],
        &common::root(),
    );
    let text = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(text.contains("RTC701") && text.contains("RTC703"), "{text}");
}

#[test]
fn oversized_invalid_utf8_bom_and_linked_readmes() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    for name in ["big", "bad", "bom", "lower", "parent/child", "sjis", "euc"] {
        common::write(
            &input,
            &format!("{name}/RTC.xml"),
            &common::xml_profile(&name.replace('/', "_"), &[]),
        );
    }
    std::fs::write(input.join("big/README.md"), "x".repeat(1024 * 1024 + 1)).unwrap();
    std::fs::write(input.join("bad/README.md"), b"# Bad\n\nok \xff\xfe here\n").unwrap();
    std::fs::write(input.join("bom/README.md"), "\u{feff}# With BOM\n\nText.\n").unwrap();
    // Japanese READMEs of older repositories: Shift_JIS (Windows) and EUC-JP (Unix).
    let japanese = "# カメラ\n\n画像を取り込み、`RTC::CameraImage` で送ります。\n";
    let (sjis, _, _) = encoding_rs::SHIFT_JIS.encode(japanese);
    let (euc, _, _) = encoding_rs::EUC_JP.encode(japanese);
    assert!(std::str::from_utf8(&sjis).is_err() && std::str::from_utf8(&euc).is_err());
    std::fs::write(input.join("sjis/README.md"), &sjis).unwrap();
    std::fs::write(input.join("euc/README.md"), &euc).unwrap();
    // Any case; README.md before README.markdown.
    std::fs::write(input.join("lower/readme.markdown"), "# Second choice\n").unwrap();
    std::fs::write(input.join("lower/Readme.MD"), "# First choice\n").unwrap();
    // A README of a parent folder is the repository's, not the component's.
    std::fs::write(input.join("parent/README.md"), "# Repository\n").unwrap();
    #[cfg(unix)]
    {
        common::write(&input, "link/RTC.xml", &common::xml_profile("link", &[]));
        std::os::unix::fs::symlink(input.join("bom/README.md"), input.join("link/README.md"))
            .unwrap();
    }

    let loaded = build::load(&input, &LoadOptions::default()).expect("load");
    let cat = &loaded.catalog;
    let readme_of = |name: &str| {
        cat.components
            .iter()
            .find(|c| c.profile.name() == name)
            .and_then(|c| c.readme.as_ref())
    };
    assert!(readme_of("big").is_none() && readme_of("bad").is_none());
    assert_eq!(
        readme_of("bom").map(|r| r.text.as_str()),
        Some("# With BOM\n\nText.\n")
    );
    assert_eq!(
        readme_of("lower").map(|r| r.file.as_str()),
        Some("lower/Readme.MD")
    );
    assert!(readme_of("parent_child").is_none());
    for name in ["sjis", "euc"] {
        assert_eq!(
            readme_of(name).map(|r| r.text.as_str()),
            Some(japanese),
            "{name}"
        );
        assert!(
            !cat.diagnostics
                .iter()
                .any(|d| d.code == "RTC702" && d.file == format!("{name}/README.md")),
            "{name}"
        );
    }
    let warn = |file: &str| {
        cat.diagnostics
            .iter()
            .find(|d| d.code == "RTC702" && d.file == file)
            .unwrap_or_else(|| panic!("no RTC702 for {file}: {:#?}", cat.diagnostics))
    };
    assert!(warn("big/README.md").message.contains("larger than 1 MiB"));
    let bad = warn("bad/README.md");
    assert!(bad.message.contains("UTF-8"), "{}", bad.message);
    assert_eq!(bad.pos.map(|p| (p.line, p.column)), Some((3, 4)));
    #[cfg(unix)]
    {
        assert!(readme_of("link").is_none());
        assert!(warn("link/README.md").message.contains("symbolic link"));
    }
    // `--exclude` leaves a README out like any file.
    let opts = LoadOptions {
        exclude: vec!["bom/README.md".into()],
        ..LoadOptions::default()
    };
    let excluded = build::load(&input, &opts).expect("load");
    assert!(excluded
        .catalog
        .components
        .iter()
        .all(|c| c.readme.as_ref().is_none_or(|r| r.file != "bom/README.md")));
    // The site still builds, and shows what could be shown.
    let out = dir.path().join("site");
    build_into(&input, &out, vec![Format::Html], SiteOptions::default());
    assert!(
        read(&out.join("components/bom.html")).contains("<h3 id=\"readme-with-bom\">With BOM</h3>")
    );
    assert!(!read(&out.join("components/big.html")).contains("id=\"readme\""));
}

#[test]
fn images_outside_the_input_of_other_types_or_too_large_are_text_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    common::write(&input, "c/RTC.xml", &common::xml_profile("c", &[]));
    std::fs::write(dir.path().join("secret.png"), b"\x89PNG").unwrap();
    common::write(&input, "c/notes.txt", "not an image");
    std::fs::write(input.join("c/huge.png"), vec![0u8; 5 * 1024 * 1024 + 1]).unwrap();
    std::fs::write(input.join("c/ok.png"), b"\x89PNG\r\n\x1a\n").unwrap();
    common::write(
        &input,
        "c/README.md",
        "![out](../../secret.png) ![txt](notes.txt) ![huge](huge.png) ![ok](ok.png) ![again](./ok.png)\n",
    );
    let loaded = build::load(&input, &LoadOptions::default()).expect("load");
    let msgs: Vec<&str> = loaded
        .catalog
        .diagnostics
        .iter()
        .filter(|d| d.code == "RTC703")
        .map(|d| d.message.as_str())
        .collect();
    assert_eq!(msgs.len(), 3, "{msgs:#?}");
    assert!(msgs.iter().any(|m| m.contains("outside the input")));
    assert!(msgs.iter().any(|m| m.contains("not of a type")));
    assert!(msgs.iter().any(|m| m.contains("larger than 5 MiB")));
    let out = dir.path().join("site");
    build_into(&input, &out, vec![Format::Html], SiteOptions::default());
    let page = read(&out.join("components/c.html"));
    let s = readme_section(&page);
    // The same file written two ways is copied once.
    assert_eq!(assets(&out).len(), 1);
    assert_eq!(s.matches("<img ").count(), 2, "{s}");
    assert!(s.contains("out txt huge"), "{s}");
}

#[test]
fn json_keeps_the_readme_path_and_raw_text_and_reads_back() {
    let (_dir, out) = build_fixture(vec![Format::Json], SiteOptions::default());
    let bytes = std::fs::read(out.join("catalog.json")).unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
    let comps = doc["components"].as_object().unwrap();
    let cam = &comps["RTC:Test:Vision:Camera:1.0.0"]["readme"];
    assert_eq!(cam["file"], "cam/README.md");
    assert_eq!(
        cam["text"].as_str().unwrap(),
        read(&fixture().join("cam/README.md"))
    );
    assert_eq!(
        cam.as_object().unwrap().len(),
        2,
        "only file and text: {cam}"
    );
    assert!(comps["RTC:Test:Vision:Filter:1.0.0"]
        .get("readme")
        .is_none());
    let back = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").expect("reads back");
    let c = back
        .catalog
        .components
        .iter()
        .find(|c| c.profile.name() == "Camera")
        .unwrap();
    assert_eq!(
        c.readme.as_ref().map(|r| r.file.as_str()),
        Some("cam/README.md")
    );
}

#[test]
fn markdown_embeds_the_readme_as_one_html_block_with_its_images() {
    let (_dir, out) = build_fixture(vec![Format::Markdown], SiteOptions::default());
    let page = read(&out.join("components/camera.md"));
    let at = page.find("<div class=\"readme\">").expect("README block");
    assert!(page[..at].contains("## README"), "{page}");
    // The README is the page's last section.
    let block = page[at..].trim_end();
    assert!(block.ends_with("</div>"), "{block}");
    // One HTML block: no blank line inside; no mdBook directive; links to Markdown pages.
    assert!(!block.contains("\n\n"), "{block}");
    assert!(
        !block.contains("{{") && block.contains("&#123;&#123;#include"),
        "{block}"
    );
    assert!(
        block.contains("href=\"../components/filter.md\""),
        "{block}"
    );
    assert!(
        !block.contains("<script") && !block.contains("onerror"),
        "{block}"
    );
    // A blank line of preformatted text is a character reference, not a break of the block.
    assert!(
        block.contains("rtc.conf&#10;\n# then activate it"),
        "{block}"
    );
    let copied = assets(&out);
    assert_eq!(copied.len(), 1);
    assert!(block.contains(&format!("src=\"../assets/readme/{}\"", copied[0])));
}

#[test]
fn doxygen_shows_the_readme_source_as_plain_paragraphs() {
    let (_dir, out) = build_fixture(vec![Format::Doxygen], SiteOptions::default());
    let page = read(&out.join("components/camera.dox"));
    assert!(
        page.contains("\\section rtc_comp_camera__sec_readme README"),
        "{page}"
    );
    assert!(page.contains("<p>\\# Camera component</p>"), "{page}");
    // Profile-text escaping: no raw HTML tag, no Doxygen command from the README.
    assert!(page.contains("\\<script\\>"), "{page}");
    assert!(!read(&out.join("components/filter.dox")).contains("sec_readme"));
}

#[test]
fn builds_with_readmes_are_byte_identical() {
    let dir = tempfile::tempdir().unwrap();
    let formats = vec![
        Format::Html,
        Format::Markdown,
        Format::Doxygen,
        Format::Json,
    ];
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    build_into(&fixture(), &a, formats.clone(), SiteOptions::default());
    build_into(&fixture(), &b, formats, SiteOptions::default());
    let files = |root: &Path| -> Vec<(String, Vec<u8>)> {
        let mut v = Vec::new();
        let mut stack = vec![root.to_path_buf()];
        while let Some(d) = stack.pop() {
            for e in std::fs::read_dir(&d).unwrap() {
                let p = e.unwrap().path();
                if p.is_dir() {
                    stack.push(p);
                } else {
                    let rel = p.strip_prefix(root).unwrap().to_string_lossy().into_owned();
                    v.push((rel, std::fs::read(&p).unwrap()));
                }
            }
        }
        v.sort();
        v
    };
    let (fa, fb) = (files(&a), files(&b));
    assert!(fa.iter().any(|(p, _)| p.contains("assets/readme/")));
    assert_eq!(fa, fb);
}

#[test]
fn serve_rebuilds_the_component_page_when_its_readme_changes() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    common::write(&input, "c/RTC.xml", &common::xml_profile("c", &[]));
    common::write(&input, "c/README.md", "# First\n");
    let opts = BuildOptions {
        input: input.clone(),
        output: dir.path().join("unused"),
        formats: vec![Format::Html],
        strict: false,
        load: LoadOptions::default(),
        site: SiteOptions::default(),
    };
    let mut ws = rtcdoc::incremental::Workspace::open(&opts).expect("open");
    let page = |ws: &rtcdoc::incremental::Workspace| {
        String::from_utf8(ws.files()["components/c.html"].clone()).unwrap()
    };
    assert!(page(&ws).contains("<h3 id=\"readme-first\">First</h3>"));
    common::write(&input, "c/README.md", "# Second\n\n![pic](pic.svg)\n");
    ws.update(&[input.join("c/README.md")]).expect("update");
    assert!(page(&ws).contains("<h3 id=\"readme-second\">Second</h3>"));
    assert!(ws.catalog().diagnostics.iter().any(|d| d.code == "RTC703"));
    // The image appears: it is copied, and the finding goes away.
    common::write(
        &input,
        "c/pic.svg",
        "<svg xmlns=\"http://www.w3.org/2000/svg\"/>",
    );
    ws.update(&[input.join("c/pic.svg")]).expect("update");
    assert!(
        page(&ws).contains("<img src=\"../assets/readme/pic-"),
        "{}",
        page(&ws)
    );
    assert!(ws
        .files()
        .keys()
        .any(|k| k.starts_with("assets/readme/pic-")));
    assert!(!ws.catalog().diagnostics.iter().any(|d| d.code == "RTC703"));
    // A profile edit keeps the README (and its findings are not doubled).
    common::write(
        &input,
        "c/RTC.xml",
        &common::xml_profile("c", &[("DataInPort", "in", "RTC::TimedLong")]),
    );
    ws.update(&[input.join("c/RTC.xml")]).expect("update");
    assert!(page(&ws).contains("<h3 id=\"readme-second\">Second</h3>"));
    // Removed: the section goes.
    std::fs::remove_file(input.join("c/README.md")).unwrap();
    ws.update(&[input.join("c/README.md")]).expect("update");
    assert!(!page(&ws).contains("id=\"readme\""));
}

/// RTCBuilder 2.x writes a README.md from its template (often with a BOM): recognised by its
/// structure. Left as generated, it repeats the page (RTC701); filled in by the author, its
/// author's sections are shown and the generated tables are not.
#[test]
fn rtcbuilder2_readmes_are_recognised_by_their_structure() {
    let input = common::root().join("tests/fixtures/readme-rtcbuilder2");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_into(&input, &out, vec![Format::Html], SiteOptions::default());
    let blank = read(&out.join("components/blank.html"));
    assert!(!blank.contains("id=\"readme\""), "{blank}");
    // A configuration parameter's section (`#### speed` under the last generated heading) is
    // generated too: it was taken for the author's text and shown as the README.
    let configured = read(&out.join("components/configured.html"));
    assert!(!configured.contains("id=\"readme\""), "{configured}");
    let filled = read(&out.join("components/filled.html"));
    let section = readme_section(&filled);
    assert!(
        section.contains("<h3 id=\"readme-usage\">Usage</h3>"),
        "{section}"
    );
    assert!(section.contains("OpenRTM-aist 1.2 or newer."), "{section}");
    for generated in [
        "Module Name",
        "Basic Information",
        "Activity definition",
        "Overview",
        "Demo",
    ] {
        assert!(!section.contains(generated), "{generated} shown: {section}");
    }
    let o = common::rtcdoc(&["check", input.to_str().unwrap(), "--verbose"], dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains(
            "info[RTC701]: the README was generated from the profile (RTCBuilder 2.x's template"
        ),
        "{err}"
    );
    assert!(err.contains("Blank/README.md:19:1"), "{err}");
    assert!(err.contains("Configured/README.md:19:1"), "{err}");
    assert!(!err.contains("Filled/README.md"), "{err}");
    // Not a template: a hand-written README with a `Basic Information` heading but no table.
    let own = dir.path().join("own");
    common::write(&own, "c/RTC.xml", &common::xml_profile("c", &[]));
    common::write(
        &own,
        "c/README.md",
        "# c\n\n## Overview\n\nText.\n\n## Description\n\nMore.\n\n### Basic Information\n\nIt runs.\n\n### Algorithm etc\n\nKalman.\n",
    );
    let site = dir.path().join("own-site");
    build_into(&own, &site, vec![Format::Html], SiteOptions::default());
    assert!(readme_section(&read(&site.join("components/c.html"))).contains("Kalman."));
}
