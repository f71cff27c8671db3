//! `rtcdoc build -f manual`: the example's PatrolRobot system as one self-contained HTML file
//! (every component it uses with its ports and parameters, the types they name; links only to
//! its own anchors; nothing fetched; the same bytes on a second build), and its PDF printed by
//! headless Chromium (pages, extractable text, the Japanese manual in a Noto Sans CJK font).

use crate::common::{self, missing_tool, read_page, root, OutputWithin, COMMAND_LIMIT};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The components PatrolRobot's instances are (examples/system/PatrolRobot.xml).
const COMPONENTS: [&str; 9] = [
    "UrgRangeSensor",
    "UsbCamera",
    "MapServer",
    "MobileBaseDriver",
    "Localization",
    "ObjectDetector",
    "Navigator",
    "SafetyMonitor",
    "PathPlanner",
];

/// Builds the examples with `-f manual` (and `args`) into `dir/name`: the manual's path.
fn build_manual(dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    let out = dir.join(name);
    let out_s = out.to_string_lossy().into_owned();
    let mut all = vec!["build", "examples", "-o", &out_s, "-f", "manual"];
    all.extend_from_slice(args);
    let o = common::rtcdoc(&all, &root());
    assert!(
        o.status.success(),
        "build failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    out.join("patrolrobot.html")
}

/// The values of attribute `attr` (`id`, `href`, `src`) in `html`.
fn attr_values<'a>(html: &'a str, attr: &str) -> Vec<&'a str> {
    let pat = format!(" {attr}=\"");
    html.match_indices(&pat)
        .filter_map(|(at, _)| {
            let start = at + pat.len();
            let len = html[start..].find('"')?;
            Some(&html[start..start + len])
        })
        .collect()
}

#[test]
fn the_manual_holds_the_system_its_components_and_their_types() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = build_manual(dir.path(), "out", &[]);
    let html = read_page(&path);
    assert!(html.contains("<h1>PatrolRobot</h1>"), "title page");
    assert!(
        html.contains("2024-05-20T16:30:00"),
        "the profile's update date"
    );
    for c in COMPONENTS {
        let id = format!("components-{}", c.to_lowercase());
        assert!(
            html.contains(&format!(
                "<article class=\"component chapter\" id=\"{id}\">"
            )),
            "a chapter for {c}"
        );
    }
    // Ports, parameters, actions of a component, each row under the chapter's prefix.
    for row in [
        "components-urgrangesensor--port-range",
        "components-urgrangesensor--conf-baudrate",
        "components-urgrangesensor--action-on_execute",
        "components-usbcamera--",
    ] {
        assert!(html.contains(&format!("id=\"{row}")), "row {row}");
    }
    assert!(
        html.contains("<code>port_name</code>"),
        "a configuration parameter"
    );
    // The types the ports name, and those their definitions name (BoundingBox is a field of
    // DetectedObject, held by TimedObjectList's sequence).
    for ty in [
        "types-rtc-rangedata",
        "types-detection-timedobjectlist",
        "types-detection-boundingbox",
        "interfaces-camera-cameracontrol",
    ] {
        assert!(
            html.contains(&format!("id=\"{ty}\"")),
            "appendix section {ty}"
        );
    }
    assert!(html.contains("id=\"interfaces-camera-cameracontrol--op-setExposure\""));
    // The system: wiring drawing inline, instances, connectors, the configuration it sets.
    assert!(html.contains("<svg") && html.contains("system-diagram"));
    assert!(html.contains("/dev/ttyACM1"), "configuration used");
    // Host data is left out as on the system page.
    assert!(!html.contains("patrol-pc.example"), "host name published");
    assert!(
        !html.contains("localhost:2809/UrgRangeSensor0.rtc"),
        "naming path published"
    );
}

#[test]
fn the_manual_links_only_inside_itself_and_fetches_nothing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = build_manual(dir.path(), "out", &[]);
    let html = std::fs::read_to_string(&path).expect("manual");
    let ids: BTreeSet<&str> = attr_values(&html, "id").into_iter().collect();
    let mut anchors = 0;
    for href in attr_values(&html, "href") {
        match href.strip_prefix('#') {
            Some(a) => {
                anchors += 1;
                assert!(
                    ids.contains(a),
                    "link to #{a}, which the manual does not define"
                );
            }
            // Links written in profile text (a reference, a mail address) are kept: a link,
            // not a request.
            None => assert!(
                href.starts_with("https://") || href.starts_with("mailto:"),
                "link out of the file: {href}"
            ),
        }
    }
    assert!(anchors > 100, "only {anchors} links inside the manual");
    assert!(attr_values(&html, "src").is_empty(), "a src attribute");
    for no in [
        "<link",
        "<script",
        "<img",
        "<iframe",
        "url(http",
        "@import",
        "@font-face",
    ] {
        assert!(!html.contains(no), "the manual holds {no}");
    }
    assert!(
        html.contains("default-src 'none'"),
        "its CSP forbids requests"
    );
    // The same bytes on a second build.
    let again = build_manual(dir.path(), "again", &[]);
    assert_eq!(
        std::fs::read(&path).expect("first"),
        std::fs::read(&again).expect("second"),
        "the manual differs between two builds"
    );
}

/// Prints `html` to a PDF with headless Chromium: its path, or `None` when chromium is missing.
fn print_pdf(html: &Path) -> Option<PathBuf> {
    let chromium = Path::new("/usr/bin/chromium");
    if !chromium.exists() {
        missing_tool("chromium missing");
        return None;
    }
    let pdf = html.with_extension("pdf");
    let profile = html.with_extension("profile");
    let o = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--no-pdf-header-footer",
            &format!("--user-data-dir={}", profile.display()),
            &format!("--print-to-pdf={}", pdf.display()),
            &format!("file://{}", html.display()),
        ])
        .output_within(COMMAND_LIMIT)
        .expect("run chromium");
    assert!(
        pdf.is_file(),
        "chromium wrote no PDF: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    Some(pdf)
}

/// What poppler's `tool` prints for `pdf` (pdftotext: its text), or `None` when
/// poppler-utils is missing.
fn poppler(tool: &str, pdf: &Path) -> Option<String> {
    let mut cmd = Command::new(tool);
    cmd.arg(pdf);
    if tool == "pdftotext" {
        cmd.arg("-");
    }
    match cmd.output() {
        Ok(o) => {
            assert!(
                o.status.success(),
                "{tool}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
            Some(String::from_utf8_lossy(&o.stdout).into_owned())
        }
        Err(_) => {
            missing_tool(&format!("{tool} missing (apt-get install poppler-utils)"));
            None
        }
    }
}

#[test]
fn the_manual_prints_to_a_pdf_of_many_pages_with_its_text() {
    let dir = tempfile::tempdir().expect("tempdir");
    let html = build_manual(dir.path(), "out", &[]);
    let Some(pdf) = print_pdf(&html) else { return };
    let Some(info) = poppler("pdfinfo", &pdf) else {
        return;
    };
    let pages: usize = info
        .lines()
        .find_map(|l| l.strip_prefix("Pages:"))
        .and_then(|n| n.trim().parse().ok())
        .expect("pdfinfo prints the pages");
    // A title page, the contents, the system, a chapter per component (each on a new page).
    assert!(pages > 2 + COMPONENTS.len(), "only {pages} pages");
    let Some(text) = poppler("pdftotext", &pdf) else {
        return;
    };
    for c in COMPONENTS {
        assert!(text.contains(c), "the PDF's text lacks {c}");
    }
    // The title page's kind is set in capitals by the style sheet.
    assert!(text.to_lowercase().contains("system manual") && text.contains("PatrolRobot"));
}

#[test]
fn the_japanese_manual_prints_in_a_noto_sans_cjk_font() {
    let dir = tempfile::tempdir().expect("tempdir");
    let html = build_manual(dir.path(), "ja", &["--language", "ja"]);
    assert!(read_page(&html).contains("<html lang=\"ja\">"));
    let Some(pdf) = print_pdf(&html) else { return };
    let Some(text) = poppler("pdftotext", &pdf) else {
        return;
    };
    assert!(
        text.contains("システムマニュアル"),
        "no Japanese text in the PDF"
    );
    assert!(text.contains("インスタンス"));
    let Some(fonts) = poppler("pdffonts", &pdf) else {
        return;
    };
    assert!(
        fonts.lines().skip(2).any(|l| l.contains(" yes ")),
        "pdffonts lists no embedded font:\n{fonts}"
    );
    // Chromium embeds the CJK faces (OpenType collections) as Type 3 fonts, which pdffonts
    // lists without a name; their descriptors name the face.
    let bytes = std::fs::read(&pdf).expect("pdf");
    let named = |face: &[u8]| bytes.windows(face.len()).any(|w| w == face);
    assert!(
        named(b"+NotoSansCJKjp") || fonts.contains("NotoSansCJK"),
        "the PDF embeds no Noto Sans CJK JP face:\n{fonts}"
    );
}

/// A deprecated component's chapter says so under its title, its replacement linked inside the
/// file; a type without its IDL definition says so without advice meant for the tool's user.
#[test]
fn the_manual_shows_stability_and_says_plainly_what_it_lacks() {
    let dir = tempfile::tempdir().expect("tempdir");
    let input = dir.path().join("in");
    for (rel, bytes) in common::tree(&root().join("examples")) {
        let to = input.join(&rel);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::write(to, bytes).unwrap();
    }
    common::write(
        &input,
        "rtcdoc.toml",
        "[stability.\"RTC:ExampleRobotics:Sensor:UrgRangeSensor:2.1.0\"]\nstatus = \"deprecated\"\nsince = \"2.1\"\nreplacement = \"SafetyMonitor\"\n",
    );
    let out = dir.path().join("out");
    let o = common::rtcdoc(
        &["build", "in", "-o", out.to_str().unwrap(), "-f", "manual"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = read_page(&out.join("patrolrobot.html"));
    let chapter = &html[html
        .find("<h1><span class=\"kind\">Component</span> UrgRangeSensor</h1>")
        .expect("the chapter")..];
    assert!(
        chapter.starts_with("<h1><span class=\"kind\">Component</span> UrgRangeSensor</h1>\n<p class=\"stability deprecated\" role=\"note\"><strong>Deprecated since 2.1</strong> — use <a href=\"#components-safetymonitor\"><code>SafetyMonitor</code></a></p>"),
        "{}",
        &chapter[..400.min(chapter.len())]
    );
    let ids = attr_values(&html, "id");
    assert!(ids.contains(&"components-safetymonitor"));
    assert!(html.contains("<p class=\"no-definition\">Its IDL definition was not available when this manual was made.</p>"));
    assert!(!html.contains("--idl-path") && !html.contains("rtcdoc init"));
}
