//! Every page the catalogue lists ([`Catalog::pages`]) is written in every output that carries
//! its kind ([`Output::carries`]): an HTML file, a Markdown file, a Doxygen page. A page kind
//! that one renderer forgets fails here with the kind and the format named (#24: the Markdown
//! and Doxygen outputs had no vendor pages, and no test noticed).
//!
//! Inputs: the example catalogue, and `tests/fixtures/vendors`, whose vendors cut across its
//! categories (a vendor in two categories and two spellings, a category of two vendors, a vendor
//! named `Index`, a component without a vendor). The real `mdbook` and `doxygen` then build the
//! Markdown and Doxygen outputs without a warning or a broken link, every page among the
//! results.

use crate::common;

use common::books::{have, run_doxygen, run_mdbook};
use common::root;
use rtcdoc::build::{self, BuildOptions, LoadOptions};
use rtcdoc::catalog::pages::{MARKDOWN_README, MARKDOWN_SUMMARY};
use rtcdoc::catalog::{Catalog, Output, Page, PageKind};
use rtcdoc::render::{Format, SiteOptions};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn inputs() -> Vec<PathBuf> {
    vec![
        root().join("examples"),
        root().join("tests/fixtures/vendors"),
    ]
}

/// A git work tree with a component history (`common::history_repo`), and an RT System
/// profile and an IDL file changed in a later commit: the history pages (What's new, a
/// component's, a system's and an IDL file's history). `None` without git.
fn history_input(dir: &Path) -> Option<PathBuf> {
    use common::history_repo::commit;
    let repo = dir.join("repo");
    if !common::history_repo::history_repo(&repo) {
        return None;
    }
    let fixture = |rel: &str| std::fs::read_to_string(root().join("tests/fixtures/diff").join(rel));
    for (side, day) in [("old", 5), ("new", 6)] {
        let system = fixture(&format!("DIFF251/{side}/systems/NavSystem.xml")).expect("system");
        let idl = fixture(&format!("DIFF131/{side}/idl/Nav.idl")).expect("IDL file");
        common::write(&repo, "systems/NavSystem.xml", &system);
        common::write(&repo, "idl/Nav.idl", &idl);
        commit(&repo, day, &format!("System and IDL, {side}"));
    }
    Some(repo)
}

/// The inputs, with the history repository (in `dir`) when git runs.
fn all_inputs(dir: &Path) -> Vec<PathBuf> {
    let mut all = inputs();
    all.extend(history_input(dir));
    all
}

/// Builds `input` in HTML, Markdown and Doxygen (`out/<format>/`).
fn render(input: &Path) -> (tempfile::TempDir, PathBuf, Catalog) {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out");
    let opts = BuildOptions {
        input: input.to_path_buf(),
        output: out.clone(),
        formats: vec![Format::Html, Format::Markdown, Format::Doxygen],
        strict: false,
        // The history as `rtcdoc build` reads it, for the history repository only (the
        // fixtures' history would be this repository's, which differs between clones).
        load: LoadOptions {
            history: if input.starts_with(root()) { 0 } else { 100 },
            history_reader: Some(rtcdoc::history::attach),
            ..LoadOptions::default()
        },
        site: SiteOptions::default(),
    };
    // The catalogue the pages were rendered from (with its history pages).
    let catalog = build::build(&opts).expect("build succeeds").0.catalog;
    (dir, out, catalog)
}

/// The folder of output `o` below a several-format build.
fn folder(o: Output) -> &'static str {
    match o {
        Output::Html => "html",
        Output::Markdown => "markdown",
        Output::Doxygen => "doxygen",
        // Not in `Output::ALL`: its pages are sections of a system's file (tests/suite/manual.rs).
        Output::Manual => "manual",
    }
}

/// What is wrong with `page` in output `o` under `root` (`None` when it is there): the file
/// must exist, and a Doxygen file must declare the page under its label.
fn missing(root: &Path, o: Output, page: &Page) -> Option<String> {
    let path = page.path_in(o);
    let file = root.join(folder(o)).join(&path);
    let Ok(text) = std::fs::read_to_string(&file) else {
        return Some(format!(
            "{:?} page `{}` ({}) is not written in {}: no {path}",
            page.kind,
            page.id,
            page.stem,
            o.name()
        ));
    };
    if o == Output::Doxygen {
        let declared = match page.kind {
            PageKind::Index => text.contains("/// \\mainpage "),
            _ => text.contains(&format!("/// \\page {} ", page.doxygen_label())),
        };
        if !declared {
            return Some(format!(
                "{:?} page `{}`: {path} does not declare \\page {} in doxygen",
                page.kind,
                page.id,
                page.doxygen_label()
            ));
        }
    }
    None
}

/// The kinds the text outputs leave out, by design (the search page, the not-found page) or
/// still (#24: the diagnostics page; the categories index, whose category pages hang from the
/// front page). Adding one here is a decision, not a fix.
const NOT_IN_TEXT: [PageKind; 4] = [
    PageKind::Search,
    PageKind::NotFound,
    PageKind::Diagnostics,
    PageKind::Categories,
];

#[test]
fn every_page_is_written_in_every_output_that_carries_its_kind() {
    let mut kinds_seen = BTreeSet::new();
    let tmp = tempfile::tempdir().expect("tempdir");
    let all = all_inputs(tmp.path());
    let with_history = all.len() > inputs().len();
    for input in all {
        let (_t, out, cat) = render(&input);
        let mut problems = Vec::new();
        for page in cat.pages() {
            kinds_seen.insert(format!("{:?}", page.kind));
            for o in Output::ALL {
                if o.carries(page.kind) {
                    problems.extend(missing(&out, o, page));
                }
            }
        }
        assert!(
            problems.is_empty(),
            "{}: pages missing:\n{}",
            input.display(),
            problems.join("\n")
        );
        // The vendor fixture's point: vendors that are not the categories.
        let vendors: Vec<&str> = cat.vendors.iter().map(|f| f.name.as_str()).collect();
        let categories: Vec<&str> = cat.categories.iter().map(|f| f.name.as_str()).collect();
        assert_ne!(vendors, categories);
    }
    // Every kind of page was looked at (the example has a system; nothing is vacuous).
    for kind in [
        "Index",
        "Search",
        "Diagnostics",
        "NotFound",
        "Component",
        "DataTypes",
        "DataType",
        "Interfaces",
        "Interface",
        "Categories",
        "Category",
        "Vendors",
        "Vendor",
        "Systems",
        "System",
        "DataFlow",
        "WhatsNew",
        "ComponentHistory",
        "SystemHistory",
        "IdlHistory",
    ] {
        if !with_history && (kind == "WhatsNew" || kind.ends_with("History")) {
            crate::common::missing_tool(&format!("{kind}: git not available"));
            continue;
        }
        assert!(kinds_seen.contains(kind), "no {kind} page in the inputs");
    }
}

#[test]
fn the_text_outputs_leave_out_only_the_listed_kinds() {
    let cat = render(&inputs()[0]).2;
    let kinds: BTreeSet<String> = cat
        .pages()
        .iter()
        .map(|p| format!("{:?}", p.kind))
        .collect();
    for o in [Output::Markdown, Output::Doxygen] {
        let left_out: BTreeSet<String> = cat
            .pages()
            .iter()
            .filter(|p| !o.carries(p.kind))
            .map(|p| format!("{:?}", p.kind))
            .collect();
        let listed: BTreeSet<String> = NOT_IN_TEXT.iter().map(|k| format!("{k:?}")).collect();
        assert_eq!(left_out, listed, "page kinds {} leaves out", o.name());
    }
    assert!(Output::ALL.len() == 3 && kinds.len() == 16);
    for page in cat.pages() {
        assert!(Output::Html.carries(page.kind), "html writes every page");
    }
}

/// Nothing is written that the catalogue does not list: every Markdown and Doxygen file is a
/// page of [`Catalog::pages`] (or mdBook's `SUMMARY.md`, the GitHub `README.md`, the Doxyfile
/// and the assets beside the pages).
#[test]
fn the_text_outputs_write_no_page_the_catalogue_does_not_list() {
    let tmp = tempfile::tempdir().expect("tempdir");
    for input in all_inputs(tmp.path()) {
        let (_t, out, cat) = render(&input);
        for o in [Output::Markdown, Output::Doxygen] {
            let listed: BTreeSet<String> = cat
                .pages()
                .iter()
                .filter(|p| o.carries(p.kind))
                .map(|p| p.path_in(o))
                .collect();
            let ext = if o == Output::Markdown { ".md" } else { ".dox" };
            let dir = out.join(folder(o));
            for e in walkdir::WalkDir::new(&dir).into_iter().flatten() {
                let rel = e
                    .path()
                    .strip_prefix(&dir)
                    .expect("below")
                    .to_string_lossy()
                    .replace('\\', "/");
                if !rel.ends_with(ext) || rel == MARKDOWN_SUMMARY || rel == MARKDOWN_README {
                    continue;
                }
                assert!(
                    listed.contains(&rel),
                    "{}: {} writes {rel}, which is no page of the catalogue",
                    input.display(),
                    o.name()
                );
            }
        }
    }
}

/// mdBook builds every Markdown page (a page missing from `SUMMARY.md` is not built) without a
/// warning or a broken link.
#[test]
fn mdbook_builds_every_page() {
    if !have("mdbook") {
        return;
    }
    let tmp = tempfile::tempdir().expect("tempdir");
    for input in all_inputs(tmp.path()) {
        let (_t, out, cat) = render(&input);
        let (_b, book) = run_mdbook(&out.join("markdown"));
        for page in cat
            .pages()
            .iter()
            .filter(|p| Output::Markdown.carries(p.kind))
        {
            let md = page.path_in(Output::Markdown);
            let html = format!("{}.html", md.trim_end_matches(".md"));
            assert!(
                book.join(&html).is_file(),
                "{}: mdbook did not build {:?} page {md}",
                input.display(),
                page.kind
            );
        }
    }
}

/// Doxygen builds every page (warnings are errors) and writes each as `<label>.html`.
#[test]
fn doxygen_builds_every_page() {
    if !have("doxygen") {
        return;
    }
    let tmp = tempfile::tempdir().expect("tempdir");
    for input in all_inputs(tmp.path()) {
        let (_t, out, cat) = render(&input);
        let dir = out.join("doxygen");
        run_doxygen(&dir);
        for page in cat
            .pages()
            .iter()
            .filter(|p| Output::Doxygen.carries(p.kind))
        {
            let html = match page.kind {
                PageKind::Index => "index.html".to_string(),
                _ => format!("{}.html", page.doxygen_label()),
            };
            assert!(
                dir.join("html").join(&html).is_file(),
                "{}: doxygen did not write {:?} page {html}",
                input.display(),
                page.kind
            );
        }
    }
}

/// A component page's Vendor links its vendor's page in both text outputs; the vendor pages
/// list their components, the way category pages do.
#[test]
fn vendor_pages_list_their_components_and_components_link_them() {
    let (_t, out, cat) = render(&inputs()[1]);
    let of = cat.vendor_of_each();
    for (ci, c) in rtcdoc::catalog::Ix::enumerate(&cat.components) {
        let comp = cat.component_page(ci);
        let vendor = cat.vendor_page(of[ci]);
        let md = std::fs::read_to_string(out.join("markdown").join(comp.path_in(Output::Markdown)))
            .expect("component page");
        let dox = std::fs::read_to_string(out.join("doxygen").join(comp.path_in(Output::Doxygen)))
            .expect("component page");
        if c.profile.basic_info.vendor.is_some() {
            let to = cat.href(comp, vendor, None, Output::Markdown);
            assert!(md.contains(&format!("]({to})")), "{}: {to}", c.slug);
            let to = cat.href(comp, vendor, None, Output::Doxygen);
            assert!(dox.contains(&format!("\\ref {to} ")), "{}: {to}", c.slug);
        }
        let vmd =
            std::fs::read_to_string(out.join("markdown").join(vendor.path_in(Output::Markdown)))
                .expect("vendor page");
        let to = cat.href(vendor, comp, None, Output::Markdown);
        assert!(vmd.contains(&format!("]({to})")), "vendor page lists {to}");
        let vdox =
            std::fs::read_to_string(out.join("doxygen").join(vendor.path_in(Output::Doxygen)))
                .expect("vendor page");
        let to = cat.href(vendor, comp, None, Output::Doxygen);
        assert!(
            vdox.contains(&format!("\\ref {to}<")),
            "vendor page lists {to}"
        );
    }
    // `Index` is a vendor, not the vendor index.
    let index = cat
        .vendors
        .iter()
        .position(|f| f.name == "Index")
        .expect("vendor Index");
    assert_ne!(
        cat.vendor_page(index).path_in(Output::Markdown),
        cat.site_page(PageKind::Vendors).path_in(Output::Markdown)
    );
    let summary = std::fs::read_to_string(out.join("markdown/SUMMARY.md")).expect("summary");
    assert!(summary.contains("- [Vendors](vendors.md)\n    - [(no vendor)](vendors/"));
}

/// No renderer of the text outputs spells a page path or a Doxygen label: they come from the
/// catalogue's pages ([`Catalog::href`], [`Page::path_in`], [`Page::anchor_in`]). Comments and
/// unit tests may; code may not.
#[test]
fn text_renderers_format_no_page_path() {
    const SPELLINGS: [&str; 14] = [
        "\"categories/",
        "\"vendors/",
        "\"components/",
        "\"types/",
        "\"interfaces/",
        "\"systems/",
        "\"../",
        "{root}",
        ".md\"",
        ".dox\"",
        ".html\"",
        "rtc_",
        "\\\\ref index",
        "\"index\"",
    ];
    let mut found = Vec::new();
    for file in ["src/render/markdown.rs", "src/render/doxygen.rs"] {
        let text = std::fs::read_to_string(root().join(file)).expect("source");
        let code = text.split("#[cfg(test)]").next().unwrap_or("");
        for (n, line) in code.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            for s in SPELLINGS {
                if line.contains(s) {
                    found.push(format!("{file}:{}: {s} in `{}`", n + 1, line.trim()));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "page paths formatted by hand (use Catalog::href / Page::path_in):\n{}",
        found.join("\n")
    );
}

/// The example built in HTML, Markdown and Doxygen, and a reader of its files (`html/…`).
fn examples_in_every_format() -> (tempfile::TempDir, impl Fn(&str) -> String) {
    let dir = tempfile::tempdir().unwrap();
    let o = common::rtcdoc(
        &[
            "build",
            common::root().join("examples").to_str().unwrap(),
            "-o",
            "out",
            "-f",
            "html,markdown,doxygen",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = dir.path().join("out");
    (dir, move |p: &str| {
        std::fs::read_to_string(out.join(p)).unwrap()
    })
}

/// "Connects to" says the same in every output: the ports of *other* components, grouped by
/// component (a filter whose in- and out-port carry the same type is not its own peer).
#[test]
fn connects_to_is_the_same_in_every_output() {
    let (_dir, read) = examples_in_every_format();
    let html = read("html/components/imagefilter.html");
    let md = read("markdown/components/imagefilter.md");
    let dox = read("doxygen/components/imagefilter.dox");
    assert!(html.contains(">UsbCamera · image</a>"), "{html}");
    assert!(
        md.contains("[UsbCamera · image](../components/usbcamera.md#port-image)"),
        "{md}"
    );
    assert!(dox.contains("\"UsbCamera · image\""), "{dox}");
    for (name, text) in [("html", &html), ("markdown", &md), ("doxygen", &dox)] {
        assert!(
            !text.contains("ImageFilter · dst"),
            "{name} lists the component's own port"
        );
        assert!(
            !text.contains("ImageFilter / dst"),
            "{name} lists the component's own port"
        );
    }
}

/// The data-flow page in every output: which categories and vendors can feed which, with the
/// port pairs counted as the catalogue has them.
#[test]
fn the_data_flow_page_counts_port_pairs_between_groups() {
    let (_dir, read) = examples_in_every_format();
    let (html, md, dox) = (
        read("html/dataflow.html"),
        read("markdown/dataflow.md"),
        read("doxygen/dataflow.dox"),
    );
    // UsbCamera (Sensor) → ImageFilter and ObjectDetector (ImageProcessing): 2 CameraImage pairs.
    assert!(
        html.contains("<tr><th scope=\"row\"><a href=\"categories/sensor.html\">Sensor</a></th><td data-label=\"To\"><a href=\"categories/imageprocessing.html\">ImageProcessing</a></td><td class=\"num\" data-label=\"Port pairs\">2</td>"),
        "{html}"
    );
    assert!(
        md.contains("| [Sensor](categories/sensor.md) | [ImageProcessing](categories/imageprocessing.md) | 2 | [RTC::CameraImage](types/rtc-cameraimage.md) |"),
        "{md}"
    );
    assert!(dox.contains("\\page rtc_dataflow "), "{dox}");
    assert!(dox.contains("\\ref rtc_cat_sensor \"Sensor\""), "{dox}");
    // The drawing: one box per group, connectors between groups, links to the group pages.
    let svg = html.split("<svg").nth(1).expect("a drawing");
    assert!(svg.contains("href=\"categories/sensor.html\""), "{svg}");
    assert!(
        svg.matches("class=\"connector data\"").count() >= 8,
        "{svg}"
    );
    // Each group's ports are named in the page's language.
    assert!(svg.contains("aria-label=\"Sensor out-port\""), "{svg}");
    let dir = tempfile::tempdir().unwrap();
    let o = common::rtcdoc(
        &[
            "build",
            common::root().join("examples").to_str().unwrap(),
            "-o",
            "ja",
            "-f",
            "html",
            "--language",
            "ja",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let ja = std::fs::read_to_string(dir.path().join("ja/dataflow.html")).unwrap();
    assert!(ja.contains("aria-label=\"Sensor 出力ポート\""), "{ja}");
    assert!(!ja.contains("Sensor out"), "{ja}");
    // Linked from every page's navigation and the Markdown front page and summary.
    assert!(read("html/index.html").contains("<a href=\"dataflow.html\">Data flow</a>"));
    assert!(read("markdown/SUMMARY.md").contains("[Data flow](dataflow.md)"));
}
