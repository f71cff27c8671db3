//! Headless Chromium against the generated site: search works offline from `file://` in English
//! and Japanese, and no payload of the hostile fixture ends up executable in the live DOM.
//! Skipped, with a visible message, when `/usr/bin/chromium` is not installed.

use crate::common;
use crate::html_support;
use common::OutputWithin;

use html_support::*;
use rtcdoc::render::SiteOptions;
use std::path::Path;

const CHROMIUM: &str = "/usr/bin/chromium";

fn chromium() -> bool {
    if Path::new(CHROMIUM).exists() {
        true
    } else {
        crate::common::missing_tool("chromium not installed");
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
        .output_within(common::COMMAND_LIMIT)
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
    // A full-width query (as a Japanese input method types it) is read in NFKC.
    let wide: String = "ｃａｍｅｒａ"
        .bytes()
        .map(|b| format!("%{b:02X}"))
        .collect();
    let dom = dump_dom(
        &format!("{}?q={wide}", file_url(&out.join("search.html"))),
        &prof,
    );
    let names = result_names(&dom);
    assert!(
        names.iter().any(|n| n == "UsbCamera"),
        "ｃａｍｅｒａ → {names:?}"
    );
    // A port name and a data type find their components.
    let dom = dump_dom(
        &format!("{}?q=TimedVelocity2D", file_url(&out.join("search.html"))),
        &prof,
    );
    assert!(!result_names(&dom).is_empty(), "type search");
}

/// RTCBuilder users often write their only Japanese summary in the abstract: the browser's
/// search finds a component by it as well as by its description.
#[test]
fn search_finds_a_japanese_summary_written_only_in_the_abstract() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(
        &common::root().join("tests/fixtures/prose"),
        &out,
        SiteOptions::default(),
    );
    // 四足歩行
    let dom = dump_dom(
        &format!(
            "{}?q=%E5%9B%9B%E8%B6%B3%E6%AD%A9%E8%A1%8C",
            file_url(&out.join("search.html"))
        ),
        &dir.path().join("chromium"),
    );
    let mut names = result_names(&dom);
    names.sort();
    assert_eq!(names, ["GaitPlanner", "Walker"], "四足歩行 → {names:?}");
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
                // The index's other files, which search.js loads (search/t0.js …).
                let index_file = src
                    .rsplit_once("search/")
                    .is_some_and(|(_, f)| f.ends_with(".js") && !f.contains('/'));
                assert!(
                    index_file
                        || ["search.js", "filter.js", "search-index.js"]
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

/// The audit harness of `tests/browser` (puppeteer-core driving this chromium, axe-core) on
/// `site`: one page of each kind, and `pages`. Needs node and its `npm ci` install (done by
/// `.ci/run`). `None`, with a "skipped" message, when either is missing.
fn audit(site: &Path, searches: &[&str], pages: &[&str]) -> Option<serde_json::Value> {
    audit_with(site, searches, pages, &[])
}

/// [`audit`] of `pages`, with What's new's `filters` (`SELECT_ID=VALUE`) tried one by one.
fn audit_filtering(site: &Path, pages: &[&str], filters: &[&str]) -> Option<serde_json::Value> {
    audit_with(site, &[], pages, filters)
}

fn audit_with(
    site: &Path,
    searches: &[&str],
    pages: &[&str],
    filters: &[&str],
) -> Option<serde_json::Value> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser");
    if !dir.join("node_modules/axe-core").is_dir()
        || !dir.join("node_modules/puppeteer-core").is_dir()
    {
        crate::common::missing_tool(
            "tests/browser/node_modules missing (run `npm ci` in tests/browser)",
        );
        return None;
    }
    let mut cmd = std::process::Command::new("node");
    cmd.arg(dir.join("audit.mjs")).arg(site);
    for s in searches {
        cmd.arg("--search").arg(s);
    }
    for p in pages {
        cmd.arg("--page").arg(p);
    }
    for f in filters {
        cmd.arg("--filter").arg(f);
    }
    let o = common::run_browser_harness(&mut cmd)?;
    assert!(
        o.status.success(),
        "audit.mjs failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    Some(serde_json::from_slice(&o.stdout).expect("audit.mjs prints one JSON object"))
}

/// Every page kind × {light, dark, 390 px, 800 px, 900 px dark}: no axe-core violation (WCAG
/// 2.0–2.2 A/AA and best practice), no column header with a word broken across lines, no name
/// in a table cell broken inside one of its words (it breaks at `::`, `_`, camelCase), at the
/// three narrow widths no page wider than the screen and no region that scrolls sideways (but a
/// diagram's), and no stacked row (card) that labels a cell twice;
/// each search's first result is the expected page, shows its kind, `?q=` follows the box and
/// Enter opens the first result.
fn assert_audit(report: &serde_json::Value, kinds: &[&str]) {
    let errors = report["errors"].as_array().expect("errors");
    assert!(errors.is_empty(), "script errors: {errors:?}");
    let pages = report["pages"].as_array().expect("pages");
    for kind in kinds {
        for mode in ["light", "dark", "phone", "tablet", "narrow"] {
            assert!(
                pages
                    .iter()
                    .any(|p| p["page"].as_str().is_some_and(|s| s.starts_with(kind))
                        && p["mode"] == mode),
                "no {kind} page audited in {mode}"
            );
        }
    }
    let mut problems = Vec::new();
    for p in pages {
        let (page, mode) = (&p["page"], &p["mode"]);
        for v in p["violations"].as_array().into_iter().flatten() {
            problems.push(format!(
                "{page} {mode}: {} ({} nodes) {}",
                v["id"], v["nodes"], v["sample"]
            ));
        }
        for c in p["clipped"].as_array().into_iter().flatten() {
            problems.push(format!("{page} {mode}: text past its cell: {c}"));
        }
        for w in p["broken"].as_array().into_iter().flatten() {
            problems.push(format!("{page} {mode}: column header word broken: {w}"));
        }
        for w in p["midword"].as_array().into_iter().flatten() {
            problems.push(format!("{page} {mode}: a name broken inside a word: {w}"));
        }
        for l in p["twice"].as_array().into_iter().flatten() {
            problems.push(format!("{page} {mode}: a card labels a cell {l} twice"));
        }
        let viewport = p["viewport"].as_u64().unwrap_or(0);
        if viewport < 1000 {
            let w = p["width"].as_u64().unwrap_or(u64::MAX);
            if w > viewport {
                problems.push(format!("{page}: {w} px wide at {viewport} px"));
            }
            // A diagram scrolls in its own box rather than shrink below legible text (#26).
            for s in p["scrollers"].as_array().into_iter().flatten() {
                if s["cls"] != "diagram-scroll" {
                    problems.push(format!("{page} {mode}: sideways-scrolling region {s}"));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    for s in report["searches"].as_array().into_iter().flatten() {
        let expect = s["expect"].as_str().unwrap_or("");
        let first = &s["results"][0];
        assert!(
            first["href"].as_str().is_some_and(|h| h.contains(expect)),
            "search {}: first result {first} is not {expect}",
            s["q"]
        );
        assert!(
            first["kind"].as_str().is_some_and(|k| !k.is_empty()),
            "kind shown: {s}"
        );
        assert_eq!(s["url_q"], s["q"], "?q= follows the box");
        assert!(
            s["opened"].as_str().is_some_and(|u| u.contains(expect)),
            "Enter opens the first result: {s}"
        );
    }
    if let Some(tables) = report.get("print").and_then(|p| p.as_array()) {
        assert!(!tables.is_empty(), "no table on the printed page");
        for t in tables {
            assert_eq!(t["display"], "table", "printed tables stay tables: {t}");
            assert_ne!(
                t["head"], "absolute",
                "printed column headers are shown: {t}"
            );
        }
    }
    if let Some(p) = report.get("popup") {
        assert_eq!(p["opened"], true, "the header search shows results: {p}");
        assert_eq!(p["focus_in_form"], false, "Tab went past the results: {p}");
        assert_eq!(
            p["closed"], true,
            "the popup closes when the focus leaves it: {p}"
        );
    }
    if let Some(f) = report
        .get("index_filter")
        .filter(|f| !f["nothing"].is_null())
    {
        let none = &f["nothing"];
        assert_eq!(none["shown"], 0, "{f}");
        assert_eq!(none["text"], none["none"], "no match is said: {f}");
        let some = &f["some"];
        let (shown, rows) = (&some["shown"], &some["rows"]);
        assert_eq!(
            some["text"],
            format!("{shown} of {rows} components shown"),
            "{f}"
        );
        // Full-width letters match as the search box's do (NFKC).
        assert_eq!(f["wide"]["shown"], some["shown"], "{f}");
    }
}

/// One page of every kind the site has (a page is audited when its path starts so).
const PAGE_KINDS: &[&str] = &[
    "index.html",
    "search.html",
    "no/such/deep/page.html",
    "diagnostics.html",
    "dataflow.html",
    "components/",
    "types/index.html",
    "types/",
    "interfaces/index.html",
    "interfaces/",
    "categories/index.html",
    "categories/",
    "vendors/index.html",
    "vendors/",
];

#[test]
fn every_page_kind_passes_axe_and_fits_a_phone_and_search_ranks_and_opens() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(&examples(), &out, SiteOptions::default());
    let searches = [
        // A Japanese word of a port description (車輪オドメトリ, the odometry port).
        "車輪=components/localization",
        // Name before type: the type page first, then the components using it.
        "TimedPose2D=types/rtc-timedpose2d",
        // An IDL field name finds its struct, an operation name its interface.
        "confidence=types/detection-detectedobject",
        "setExposure=interfaces/camera-cameracontrol",
    ];
    // The Navigator has a README (a table, an SVG image, fragment and component links).
    let readme_page = "components/navigator.html";
    let Some(report) = audit(&out, &searches, &[readme_page]) else {
        return;
    };
    assert_audit(&report, PAGE_KINDS);
    let audited = report["pages"].as_array().expect("pages");
    assert!(
        audited.iter().filter(|p| p["page"] == readme_page).count() == 5,
        "{readme_page} audited in every mode"
    );
}

/// The history pages (What's new with its filter, a component's whole history, the component
/// page with its "since" badges) of a site built from a git repository with a history.
#[test]
fn the_history_pages_pass_axe_and_fit_a_phone() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !common::history_repo::history_repo(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let out = dir.path().join("site");
    let o = common::rtcdoc(
        &["build", repo.to_str().unwrap(), "-o", out.to_str().unwrap()],
        &repo,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(broken_links(&out).is_empty(), "{:?}", broken_links(&out));
    let pages = [
        "whats-new.html",
        "history/base.html",
        "components/base.html",
    ];
    let Some(report) = audit_filtering(
        &out,
        &pages,
        &[
            "f-nsev=breaking",
            "f-nsev=info",
            "f-nsev=",
            "f-ncategory=Mobile",
        ],
    ) else {
        return;
    };
    assert_audit(&report, &pages);
    // The filter hides the rows it rules out, and a day left without rows (7 changes over two
    // days: the rename's breaking, warning and info; the release's four infos).
    let shown: Vec<(String, u64, u64)> = report["filters"]
        .as_array()
        .expect("filters")
        .iter()
        .map(|f| {
            (
                f["filter"].as_str().unwrap_or("").to_string(),
                f["rows"].as_u64().unwrap_or(0),
                f["days"].as_u64().unwrap_or(0),
            )
        })
        .collect();
    assert_eq!(
        shown,
        [
            ("f-nsev=breaking".to_string(), 1, 1),
            ("f-nsev=info".to_string(), 5, 2),
            ("f-nsev=".to_string(), 7, 2),
            ("f-ncategory=Mobile".to_string(), 7, 2),
        ]
    );
}

/// The history pages of an RT System and an IDL file, What's new with their rows, and the
/// History sections that spell out each version's changes (system page, type page) pass the
/// audit in every mode; no link of the site is broken.
#[test]
fn system_and_idl_history_pages_pass_axe_and_fit_a_phone() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if crate::history_feed::repository(&repo).is_none() {
        println!("skipped: git not available");
        return;
    }
    let out = dir.path().join("site");
    let o = common::rtcdoc(
        &["build", repo.to_str().unwrap(), "-o", out.to_str().unwrap()],
        &repo,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(broken_links(&out).is_empty(), "{:?}", broken_links(&out));
    let pages = [
        "whats-new.html",
        "idl-history/idl-nav-idl.html",
        "system-history/navsystem.html",
        "systems/navsystem.html",
        "types/nav-timedodometry.html",
    ];
    let Some(report) = audit_filtering(&out, &pages, &["f-nsev=warning", "f-nsev="]) else {
        return;
    };
    assert_audit(&report, &pages);
}

#[test]
fn the_corpus_site_passes_axe_and_fits_a_phone() {
    if !chromium() {
        return;
    }
    let Some(corpus) = common::corpus() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(&corpus, &out, SiteOptions::default());
    // 温度センサ occurs in one file of the corpus, in a data port's description only.
    let searches = [
        "温度センサ=components/accandmagnsensor",
        "TimedDoubleSeq=types/rtc-timeddoubleseq",
        "ManipulatorCommonInterface_Middle=interfaces/jara-arm-manipulatorcommoninterface-middle",
    ];
    // A page whose service ports connect to many long port names.
    let Some(report) = audit(&out, &searches, &["components/armcontroller.html"]) else {
        return;
    };
    assert_audit(&report, PAGE_KINDS);
    // The diagnostics page of the corpus stays small (it was 990 KB, a row per finding).
    let diag = std::fs::metadata(out.join("diagnostics.html"))
        .unwrap()
        .len();
    assert!(diag <= 300_000, "diagnostics.html is {diag} bytes");
}

/// Long port and interface names (`ManipulatorCommonInterface_Common.JARA_ARM_…`) wrap inside
/// their cells at every width, never past them.
#[test]
fn long_names_wrap_inside_their_cells() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(
        &common::root().join("tests/fixtures/long-names"),
        &out,
        SiteOptions::default(),
    );
    let Some(report) = audit(&out, &[], &["components/armcontroller.html"]) else {
        return;
    };
    assert_audit(&report, &[]);
}

/// A component page listing RTCBuilder backups, and a system page with an empty configuration
/// set, pass the audit in every mode.
#[test]
fn backups_and_empty_configuration_sets_pass_the_audit() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (fixture, page) in [
        ("backups", "components/pidcontroller.html"),
        ("rtsys", "systems/wiring.html"),
    ] {
        let out = dir.path().join(fixture);
        build_site(
            &common::root().join("tests/fixtures").join(fixture),
            &out,
            SiteOptions::default(),
        );
        let Some(report) = audit(&out, &[], &[page]) else {
            return;
        };
        assert_audit(&report, &[]);
    }
}

/// The Implementation section, with its table of differences and as the page of a component
/// recovered from its code, passes the audit in every mode (axe, light and dark, 1280 and
/// 390 px).
#[test]
fn implementation_sections_pass_the_audit() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (fixture, page) in [
        ("python-edited", "components/sensorgui.html"),
        ("recovered", "components/gripper.html"),
    ] {
        let out = dir.path().join(fixture);
        build_site(
            &common::root()
                .join("tests/fixtures/implementation")
                .join(fixture),
            &out,
            SiteOptions::default(),
        );
        assert!(out.join(page).is_file(), "{page}");
        let Some(report) = audit(&out, &[], &[page, "index.html"]) else {
            return;
        };
        assert_audit(&report, &[]);
    }
}

/// The result links (`href`s) of the search page's results.
fn result_links(dom: &str) -> Vec<String> {
    let Some(list) = dom.split("id=\"search-results\"").nth(1) else {
        return Vec::new();
    };
    list.split("href=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .map(str::to_string)
        .collect()
}

/// Port compatibility queries on the search page: `in:`, `out:`, `provides:`, `requires:`
/// and `feeds:` list ports linked to their rows; plain words filter them; an unknown type
/// finds nothing.
#[test]
fn search_finds_ports_by_type_and_by_what_feeds_an_in_port() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    build_site(&examples(), &out, SiteOptions::default());
    let prof = dir.path().join("chromium");
    let search = |q: &str| {
        let dom = dump_dom(
            &format!("{}?q={q}", file_url(&out.join("search.html"))),
            &prof,
        );
        (result_names(&dom), result_links(&dom))
    };
    let (names, links) = search("in:RTC::TimedLong");
    assert_eq!(names, ["SafetyMonitor.person_count"]);
    assert_eq!(links, ["components/safetymonitor.html#port-person-count"]);
    // The scoped name's last part, any case.
    let (names, links) = search("out:timedlong");
    assert_eq!(names, ["ObjectDetector.count", "UrgRangeSensor.status"]);
    assert_eq!(
        links,
        [
            "components/objectdetector.html#port-count",
            "components/urgrangesensor.html#port-status"
        ]
    );
    // What can feed SafetyMonitor's person_count: the producers of its type.
    let (names, _) = search("feeds:SafetyMonitor.person_count");
    assert_eq!(names, ["ObjectDetector.count", "UrgRangeSensor.status"]);
    // A repository id names the type too; a plain word keeps the components it finds.
    let (names, _) = search("out:IDL:RTC/TimedPose2D:1.0");
    assert_eq!(names.len(), 3, "{names:?}");
    let (names, _) = search("out:IDL:RTC/TimedPose2D:1.0%20navigator");
    assert_eq!(names, ["Navigator.goal"]);
    let (names, links) = search("requires:RTC::OGMapServer");
    assert_eq!(
        names,
        [
            "Localization.MapService.map_server",
            "PathPlanner.MapService.map_server"
        ]
    );
    assert_eq!(
        links[0],
        "components/localization.html#if-mapservice-map-server"
    );
    let (names, _) = search("provides:OGMapServer");
    assert_eq!(names, ["MapServer.MapService.map_server"]);
    // No such type: the no-result message, no result.
    let dom = dump_dom(
        &format!(
            "{}?q=in:RTC::NoSuchType",
            file_url(&out.join("search.html"))
        ),
        &prof,
    );
    assert!(result_names(&dom).is_empty());
    assert!(dom.contains("No results"), "no-result message");
}

/// While a query's token files are on their way (held back by the harness), the search page
/// answers from the names its first file holds: those results are marked partial (`N+ · q …`,
/// the list `aria-busy`), each is a result of the full answer, in the full answer's order, and
/// the full answer replaces them when the files come. `pose` is a camelCase part of a name
/// (`TimedPose2D`), `camera` a whole word of some names and a part of others (`UsbCamera`).
#[test]
fn search_answers_from_the_names_while_its_files_load() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser");
    if !dir.join("node_modules/puppeteer-core").is_dir() {
        crate::common::missing_tool(
            "tests/browser/node_modules missing (run `npm ci` in tests/browser)",
        );
        return;
    }
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("site");
    build_site(&examples(), &out, SiteOptions::default());
    let mut cmd = std::process::Command::new("node");
    cmd.arg(dir.join("search_partial.mjs"))
        .arg(&out)
        .args(["camera", "pose", "timedpose2d"]);
    let Some(o) = common::run_browser_harness(&mut cmd) else {
        return;
    };
    assert!(
        o.status.success(),
        "search_partial.mjs failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let report: serde_json::Value =
        serde_json::from_slice(&o.stdout).expect("search_partial.mjs prints one JSON array");
    let hrefs = |v: &serde_json::Value| -> Vec<String> {
        v["results"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(|h| h.as_str().map(str::to_string))
            .collect()
    };
    for r in report.as_array().expect("an array") {
        let q = r["q"].as_str().unwrap_or("");
        let (partial, full) = (&r["partial"], &r["final"]);
        assert!(r["held"].as_u64() > Some(0), "no file was held back: {r}");
        let (p, f) = (hrefs(partial), hrefs(full));
        assert!(!p.is_empty(), "{q}: no result from the names: {r}");
        assert_eq!(
            partial["status"],
            format!("{}+ · {q} …", p.len()),
            "partial marked: {r}"
        );
        assert_eq!(partial["busy"], true, "partial list aria-busy: {r}");
        assert_eq!(full["status"], format!("{} · {q}", f.len()), "{r}");
        assert_eq!(full["busy"], false, "{r}");
        // Each partial result is in the full answer, in the same order.
        let mut at = f.iter();
        for h in &p {
            assert!(
                at.any(|x| x == h),
                "{q}: partial result {h} not in the full answer in order: {r}"
            );
        }
        assert!(
            f.len() > p.len(),
            "{q}: the full answer adds the other matches: {r}"
        );
    }
    // The camelCase part finds the type by its name before any file came.
    let pose = &report[1];
    assert!(
        hrefs(&pose["partial"])
            .iter()
            .any(|h| h.contains("types/rtc-timedpose2d")),
        "{pose}"
    );
}

/// A catalogue whose ports fill many port files (each type is in the file its key names, and
/// `feeds:` reads the in-port's file first): `in:`, `out:` (by scoped name, by last part, by
/// repository id) and `feeds:` answer from whichever file holds the type. Component `C{i}` has
/// out-ports `o{j}` of type `Lab::Sensors::Reading{i}x{j}` and in-ports `i{j}` of
/// `Reading{i-1}x{j}`.
#[test]
fn port_queries_find_their_type_in_any_port_file() {
    if !chromium() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = many_ports_site(dir.path());
    let ty = many_ports_type;
    let idx = common::search_index::read(&out);
    let files = idx.first["p"].as_u64().unwrap();
    assert!(files >= 4, "{files} port files");
    let prof = dir.path().join("chromium");
    let search = |q: &str| {
        let dom = dump_dom(
            &format!("{}?q={q}", file_url(&out.join("search.html"))),
            &prof,
        );
        result_names(&dom)
    };
    // Types of four different port files.
    let mut used = std::collections::BTreeSet::new();
    let picked: Vec<(usize, usize)> = (0..239)
        .step_by(7)
        .map(|i| (i, i % 4))
        .filter(|&(i, j)| used.insert(port_file(&out, &ty(i, j))))
        .take(4)
        .collect();
    assert_eq!(picked.len(), 4, "{used:?}");
    for (i, j) in picked {
        assert_eq!(
            search(&format!("in:{}", ty(i, j))),
            [format!("C{}.i{j}", i + 1)]
        );
        assert_eq!(
            search(&format!("out:Reading{i}x{j}")),
            [format!("C{i}.o{j}")]
        );
        assert_eq!(
            search(&format!(
                "out:IDL:Lab/Sensors/LongEnoughTypeName/Reading{i}x{j}:1.0"
            )),
            Vec::<String>::new(),
            "no such repository id in the catalogue (no IDL): nothing"
        );
        assert_eq!(
            search(&format!("feeds:C{}.i{j}", i + 1)),
            [format!("C{i}.o{j}")]
        );
    }
}

/// The port file holding the type named `name` (the one whose types list it).
fn port_file(site: &Path, name: &str) -> String {
    let dir = site.join("search");
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let f = p.file_name().unwrap().to_string_lossy().into_owned();
        if f.starts_with('p')
            && std::fs::read_to_string(&p)
                .unwrap()
                .contains(&format!("\"{name}\""))
        {
            return f;
        }
    }
    panic!("{name} in no port file");
}

/// `bench/port_queries.mjs` on the example: every type and interface page's producers and
/// consumers (providers and requirers) are exactly what `out:`/`in:` (`provides:`/`requires:`)
/// of its scoped name find, and `feeds:` of its first consumer finds its producers. (The same
/// script checks a 10,000-profile site; see the guide's performance page.)
#[test]
fn port_queries_agree_with_every_type_page() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    if !dir
        .join("tests/browser/node_modules/puppeteer-core")
        .is_dir()
    {
        crate::common::missing_tool(
            "tests/browser/node_modules missing (run `npm ci` in tests/browser)",
        );
        return;
    }
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("site");
    build_site(&examples(), &out, SiteOptions::default());
    let mut cmd = std::process::Command::new("node");
    cmd.arg(dir.join("bench/port_queries.mjs"))
        .arg(&out)
        .arg("1000");
    let Some(o) = common::run_browser_harness(&mut cmd) else {
        return;
    };
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{said}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let checked: usize = said
        .split(" port queries compared")
        .next()
        .and_then(|s| s.rsplit('\n').next())
        .and_then(|n| n.trim().parse().ok())
        .unwrap_or(0);
    assert!(checked >= 20, "{said}");
    assert!(said.contains(", 0 mismatches"), "{said}");
}

/// The type of out-port `o{j}` of component `C{i}` in [`many_ports_site`].
fn many_ports_type(i: usize, j: usize) -> String {
    format!("Lab::Sensors::LongEnoughTypeName::Reading{i}x{j}")
}

/// A site of 240 components whose ports fill many port files: `C{i}` has out-ports `o{j}` of
/// type [`many_ports_type`]`(i, j)` and in-ports `i{j}` of `(i - 1, j)`. Built below `dir`.
fn many_ports_site(dir: &Path) -> std::path::PathBuf {
    let input = dir.join("in");
    let ty = many_ports_type;
    for i in 0..240 {
        let mut ports: Vec<(String, String, String)> = (0..4)
            .map(|j| ("DataOutPort".into(), format!("o{j}"), ty(i, j)))
            .collect();
        if i > 0 {
            ports.extend((0..4).map(|j| ("DataInPort".into(), format!("i{j}"), ty(i - 1, j))));
        }
        let ports: Vec<(&str, &str, &str)> = ports
            .iter()
            .map(|(a, b, c)| (a.as_str(), b.as_str(), c.as_str()))
            .collect();
        common::write(
            &input,
            &format!("C{i}/RTC.xml"),
            &common::xml_profile(&format!("C{i}"), &ports),
        );
    }
    let out = dir.join("site");
    build_site(&input, &out, SiteOptions::default());
    out
}

/// The search page loads the details (meta line, summary) of the results near the screen,
/// not of all 100 it lists: scrolling to the last one loads the rest.
#[test]
fn search_page_loads_details_near_the_screen() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser");
    if !dir.join("node_modules/puppeteer-core").is_dir() {
        crate::common::missing_tool(
            "tests/browser/node_modules missing (run `npm ci` in tests/browser)",
        );
        return;
    }
    let tmp = tempfile::tempdir().unwrap();
    let out = many_ports_site(tmp.path());
    let mut cmd = std::process::Command::new("node");
    cmd.arg(dir.join("search_partial.mjs")).arg(&out).arg("c");
    let Some(o) = common::run_browser_harness(&mut cmd) else {
        return;
    };
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let r = &report[0];
    let shown = r["final"]["results"].as_array().map_or(0, Vec::len);
    assert_eq!(shown, 100, "{r}");
    let (before, after) = (&r["final"], &r["scrolled"]);
    let filled = before["filled"].as_u64().unwrap();
    assert!(
        filled > 0 && filled < 60,
        "details near the screen only: {r}"
    );
    assert_eq!(
        after["filled"], 100,
        "every result filled in after scrolling: {r}"
    );
    assert!(
        after["details"].as_u64() > before["details"].as_u64(),
        "scrolling loaded more details files: {r}"
    );
    // A port query typed a key at a time asks for a port file only for a key the catalogue
    // has (`search/k0.js` lists them), not one per prefix of the type's name.
    let q = format!("in:{}", many_ports_type(57, 2));
    let mut cmd = std::process::Command::new("node");
    cmd.arg(dir.join("search_partial.mjs")).arg(&out).arg(&q);
    let Some(o) = common::run_browser_harness(&mut cmd) else {
        return;
    };
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let r = &report[0];
    assert_eq!(r["final"]["status"], format!("1 · {q}"), "{r}");
    let files: Vec<&str> = r["final"]["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|f| f.as_str())
        .collect();
    let port_files = files.iter().filter(|f| f.starts_with("search/p")).count();
    assert!(files.contains(&"search/k0.js"), "{files:?}");
    assert!(
        port_files <= 2,
        "{port_files} port files for one query typed: {files:?}"
    );
}
