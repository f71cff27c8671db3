//! The Markdown and Doxygen outputs, checked with the real tools: `doxygen` (warnings are
//! errors) and `mdbook` (no warning, no broken link in the built book). Tool-driven tests print
//! `skipped: <tool> not installed` and pass when the tool is missing; CI installs both.

use crate::common;
use common::books::{have, run_doxygen, run_mdbook};
use rtcdoc::build::{self, BuildOptions, LoadOptions};
use rtcdoc::catalog::Catalog;
use rtcdoc::i18n::Lang;
use rtcdoc::render::{doxygen, markdown, Format, SiteOptions};
use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn examples() -> PathBuf {
    root().join("examples")
}

fn hostile() -> PathBuf {
    root().join("tests/fixtures/hostile")
}

/// `../shared/corpus`, else `/work/shared/corpus`; prints a visible skip line when absent.
fn corpus() -> Option<PathBuf> {
    for p in [
        root().join("../shared/corpus"),
        PathBuf::from("/work/shared/corpus"),
    ] {
        if p.is_dir() {
            return Some(p);
        }
    }
    println!("skipped: ../shared/corpus not present");
    None
}

/// Runs `rtcdoc build` (the library) on `input`; returns the temp dir and the output path.
fn render(input: &Path, format: Format, lang: Lang) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out");
    let opts = BuildOptions {
        input: input.to_path_buf(),
        output: out.clone(),
        formats: vec![format],
        strict: false,
        load: LoadOptions::default(),
        site: SiteOptions {
            title: "Robot <catalogue> & \"friends\"".into(),
            language: lang,
            ..SiteOptions::default()
        },
    };
    build::build(&opts).expect("build succeeds");
    (dir, out)
}

fn catalog(input: &Path) -> Catalog {
    build::load(input, &LoadOptions::default())
        .expect("load")
        .catalog
}

/// The text of an HTML page: tags removed, entities decoded (enough for our assertions).
fn html_text(html: &str) -> String {
    let mut out = String::with_capacity(html.len());
    let mut in_tag = false;
    for ch in html.chars() {
        match ch {
            '<' => in_tag = true,
            '>' if in_tag => in_tag = false,
            c if !in_tag => out.push(c),
            _ => {}
        }
    }
    out.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&apos;", "'")
        .replace("&#160;", " ")
        .replace("&nbsp;", " ")
        .replace("&zwj;", "")
        .replace("&amp;", "&")
}

fn read_tree(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    walkdir::WalkDir::new(dir)
        .into_iter()
        .flatten()
        .filter(|e| e.file_type().is_file())
        .map(|e| {
            (
                e.path()
                    .strip_prefix(dir)
                    .expect("prefix")
                    .to_string_lossy()
                    .into_owned(),
                std::fs::read(e.path()).expect("read"),
            )
        })
        .collect()
}

/// Strings of `metachars.xml` that must come out literally.
const METACHARS: &[&str] = &[
    "in|out: a|b|c",
    "\\ref SomeClass \\param x \\return y @param foo @return bar @see baz",
    // `<br>` is RTCBuilder's line break in any text field (model::prose): the line breaks there.
    "<b>bold?</b> & <i>italic?</i>",
    "&amp; &lt;",
    "Hash/percent/dollar: # %d %s $PATH ${HOME} $$ \\$",
    "Backslashes: \\ \\\\ \\n \\t \\* \\_ \\`",
    "At-signs: @ @@ @{ @}",
    "<!-- comment --> <![CDATA[x]]>",
    "Braces: {{ }} {% raw %} [[link]]",
    // mdBook 0.5's smart punctuation would make dashes, an ellipsis and curly quotes of these.
    "Dashes -- and --- and dots... 'single' \"double\" it's",
    "# Not a heading",
    // A backtick span is code in every output, as on the HTML site (the text keeps `code`).
    "code *bold* _em_ **strong** __under__ ~~strike~~",
    "\\brief not a brief @brief neither",
    "MIT | *BSD* | _GPL_",
    "End | with | pipes |",
    "gain|max",
    "#count",
    "rate%",
    "Meta::If|Type",
    "m/s^2",
    "$ | %",
];

fn metachars_dir() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("tempdir");
    let input = dir.path().join("in");
    std::fs::create_dir_all(&input).expect("mkdir");
    std::fs::copy(hostile().join("metachars.xml"), input.join("metachars.xml"))
        .expect("copy fixture");
    (dir, input)
}

fn assert_metachars_intact(page: &Path) {
    let html = std::fs::read_to_string(page).expect("page");
    let text = html_text(&html);
    for s in METACHARS {
        assert!(text.contains(s), "{} lacks {s:?}", page.display());
    }
    // … and shown as code.
    assert!(
        html.contains(">code</code>") || html.contains(">code</tt>"),
        "{}: `code` is not code",
        page.display()
    );
}

// ---------------------------------------------------------------------------------------------
// Doxygen

#[test]
fn doxygen_builds_the_examples_without_warnings() {
    if !have("doxygen") {
        return;
    }
    let cat = catalog(&examples());
    assert!(cat.components.len() >= 5, "examples load");
    let (_t, out) = render(&examples(), Format::Doxygen, Lang::En);
    run_doxygen(&out);
    let html = out.join("html");
    for c in &cat.components {
        let f = html.join(format!("rtc_comp_{}.html", doxygen::label(&c.slug)));
        assert!(f.is_file(), "missing {}", f.display());
    }
    for t in &cat.data_types {
        assert!(html
            .join(format!("rtc_type_{}.html", doxygen::label(&t.slug)))
            .is_file());
    }
    for t in &cat.interfaces {
        assert!(html
            .join(format!("rtc_if_{}.html", doxygen::label(&t.slug)))
            .is_file());
    }
    assert!(html.join("index.html").is_file());
    assert!(html.join("rtc_types.html").is_file());
    assert!(out.join("latex/refman.tex").is_file());
    let tag = std::fs::read_to_string(out.join("rtcdoc.tag")).expect("tag file");
    assert!(
        tag.contains("<name>rtc_comp_"),
        "tag file lists component pages"
    );
    assert!(tag.contains("rtc_types"));
    assert!(out.join("man").is_dir());
    // A port row links to its type page and carries its anchor.
    let nav = std::fs::read_to_string(html.join("rtc_comp_navigator.html")).unwrap_or_default();
    assert!(
        nav.is_empty() || nav.contains("rtc_type_"),
        "navigator links types"
    );
}

/// The README fixture (hostile raw HTML, Doxygen metacharacters) keeps Doxygen at 0 warnings.
#[test]
fn doxygen_builds_the_readme_fixture_without_warnings() {
    if !have("doxygen") {
        return;
    }
    let input = root().join("tests/fixtures/readme");
    let (_t, out) = render(&input, Format::Doxygen, Lang::En);
    run_doxygen(&out);
    let page = std::fs::read_to_string(out.join("html/rtc_comp_camera.html")).expect("page");
    assert!(page.contains("Camera component"), "README shown");
    assert!(!page.contains("<script>alert"), "no script");
}

#[test]
fn doxygen_builds_the_examples_in_japanese() {
    if !have("doxygen") {
        return;
    }
    let (_t, out) = render(&examples(), Format::Doxygen, Lang::Ja);
    let doxyfile = std::fs::read_to_string(out.join("Doxyfile")).expect("Doxyfile");
    assert!(doxyfile.contains("OUTPUT_LANGUAGE        = Japanese"));
    run_doxygen(&out);
    let cat = catalog(&examples());
    let page = out.join(format!(
        "html/rtc_comp_{}.html",
        doxygen::label(&cat.components[0].slug)
    ));
    let text = html_text(&std::fs::read_to_string(page).expect("page"));
    assert!(text.contains("ライフサイクル"), "Japanese headings");
    assert!(out.join("latex/refman.tex").is_file());
}

#[test]
fn doxygen_builds_the_corpus_without_warnings() {
    let Some(corpus) = corpus() else { return };
    if !have("doxygen") {
        return;
    }
    let cat = catalog(&corpus);
    let (_t, out) = render(&corpus, Format::Doxygen, Lang::En);
    run_doxygen(&out);
    for c in &cat.components {
        let f = out.join(format!("html/rtc_comp_{}.html", doxygen::label(&c.slug)));
        assert!(f.is_file(), "missing {}", f.display());
    }
    assert!(out.join("latex/refman.tex").is_file());
    println!(
        "doxygen: {} components, {} types, {} interfaces, 0 warnings",
        cat.components.len(),
        cat.data_types.len(),
        cat.interfaces.len()
    );
}

#[test]
fn doxygen_keeps_metacharacters_literal() {
    if !have("doxygen") {
        return;
    }
    let (_d, input) = metachars_dir();
    let (_t, out) = render(&input, Format::Doxygen, Lang::En);
    run_doxygen(&out);
    assert_metachars_intact(&out.join("html/rtc_comp_metachars.html"));
}

/// Page titles show names as written: in the page heading always; in the HTML `<title>` (where
/// Doxygen copies most escapes verbatim) for everything but `\`, `@`, `%`, `#`, `::` before a
/// name, `$Word:` (an RCS keyword) and a leading `-` (a list), which Doxygen would read and so
/// stay escaped there.
#[test]
fn doxygen_titles_show_names_as_written() {
    if !have("doxygen") {
        return;
    }
    let d = tempfile::tempdir().expect("tempdir");
    let input = d.path().join("in");
    let vendor = "R&D <Lab> 100% #1 $x \"q\" a--b RTC::X 計測";
    let category = "- #team %d ::c @v \\n $Date: 1 $ #~Foo";
    let xml = common::xml_profile("Titles", &[])
        .replace(
            "rtc:vendor=\"Test\"",
            "rtc:vendor=\"R&amp;D &lt;Lab&gt; 100% #1 $x &quot;q&quot; a--b RTC::X 計測\"",
        )
        .replace(
            "rtc:category=\"Cat\"",
            &format!("rtc:category=\"{category}\""),
        );
    common::write(&input, "RTC.xml", &xml);
    let (_t, out) = render(&input, Format::Doxygen, Lang::En);
    run_doxygen(&out);
    let (mut titles, mut headings) = (Vec::new(), Vec::new());
    let between = |s: &str, open: &str, close: &str| {
        let (_, rest) = s.split_once(open)?;
        Some(html_text(rest.split_once(close)?.0).trim().to_string())
    };
    for (path, bytes) in read_tree(&out.join("html")) {
        let s = String::from_utf8_lossy(&bytes);
        if path.ends_with(".html") {
            titles.extend(between(&s, "<title>", "</title>"));
            headings.extend(between(&s, "<div class=\"title\">", "</div>"));
        }
    }
    let site = "Robot <catalogue> & \"friends\"";
    let title = format!("{site}: {vendor}");
    assert!(
        titles.contains(&title),
        "no <title> {title:?} in {titles:#?}"
    );
    for name in [vendor, category, site] {
        assert!(
            headings.iter().any(|h| h == name),
            "no heading {name:?} in {headings:#?}"
        );
    }
}

/// Vendors and categories are free text: a double space (`Kyohei Iwane  Osaka.Univ`, as a
/// real lab's code wrote it), trailing and full-width spaces, a tab, Japanese, names that
/// differ only in punctuation (one slug base), RTCBuilder's placeholder. Each facet gets a
/// Doxygen page of its own, the pages link it by the label it declares, and Doxygen says
/// nothing.
#[test]
fn doxygen_has_a_page_for_every_free_text_facet() {
    if !have("doxygen") {
        return;
    }
    let d = tempfile::tempdir().expect("tempdir");
    let input = d.path().join("in");
    let vendors = [
        "Kyohei Iwane  Osaka.Univ",
        "Trailing ",
        "産総研　知能",
        "Tab&#9;Here",
        "A.B",
        "A B",
        "VenderName",
        "__init__",
        "ｒｔｍ",
    ];
    for (i, v) in vendors.iter().enumerate() {
        let xml = common::xml_profile(&format!("C{i}"), &[])
            .replace("rtc:vendor=\"Test\"", &format!("rtc:vendor=\"{v}\""))
            .replace("rtc:category=\"Cat\"", &format!("rtc:category=\"{v} cat\""))
            .replace("RTC:Test:Cat:", &format!("RTC:V{i}:Cat{i}:"));
        common::write(&input, &format!("c{i}/RTC.xml"), &xml);
    }
    let cat = catalog(&input);
    // `VenderName` is no vendor: its component is under "(no vendor)", a facet too.
    assert_eq!(cat.vendors.len(), vendors.len(), "{:?}", cat.vendors);
    let (_t, out) = render(&input, Format::Doxygen, Lang::En);
    run_doxygen(&out);
    let html = out.join("html");
    let mut labels = HashSet::new();
    for (fi, f) in cat.vendors.iter().enumerate() {
        let label = cat.vendor_page(fi).doxygen_label();
        assert!(
            label
                .bytes()
                .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_'),
            "{label}"
        );
        assert!(labels.insert(label.clone()), "{label} twice");
        let page = std::fs::read_to_string(html.join(format!("{label}.html")))
            .unwrap_or_else(|e| panic!("no Doxygen page for vendor {:?} ({label}): {e}", f.name));
        for c in &f.components {
            let comp = cat.component(c).expect("member");
            assert!(
                page.contains(&format!("rtc_comp_{}.html", doxygen::label(&comp.slug))),
                "{label} lists {}",
                comp.slug
            );
            // The component page links the vendor page by the same label.
            let cp = std::fs::read_to_string(
                html.join(format!("rtc_comp_{}.html", doxygen::label(&comp.slug))),
            )
            .expect("component page");
            if !f.name.is_empty() {
                assert!(cp.contains(&format!("href=\"{label}.html\"")), "{label}");
            }
        }
    }
    for fi in 0..cat.categories.len() {
        let label = cat.category_page(fi).doxygen_label();
        assert!(html.join(format!("{label}.html")).is_file(), "{label}");
        assert!(labels.insert(label.clone()), "{label} twice");
    }
}

#[test]
fn doxygen_never_emits_profile_markup() {
    if !have("doxygen") {
        return;
    }
    let (_t, out) = render(&hostile(), Format::Doxygen, Lang::En);
    run_doxygen(&out);
    for (path, bytes) in read_tree(&out.join("html")) {
        if !path.ends_with(".html") {
            continue;
        }
        let s = String::from_utf8_lossy(&bytes);
        for bad in [
            "<script>alert",
            "<img src=x",
            "<svg onload",
            "href=\"javascript:",
        ] {
            assert!(!s.contains(bad), "{path} contains {bad}");
        }
    }
}

/// Labels are unique and plain; every page is the target of exactly one `\subpage`; every
/// `\ref` resolves.
#[test]
fn doxygen_labels_are_unique_and_every_page_has_one_subpage() {
    let mut inputs = vec![examples(), hostile()];
    inputs.extend(corpus());
    for input in inputs {
        let cat = catalog(&input);
        let pages = doxygen::pages(&cat, "T", Lang::En);
        let mut labels: Vec<String> = vec!["index".into()];
        let mut pages_: Vec<String> = Vec::new();
        let mut subpages: HashMap<String, usize> = HashMap::new();
        let mut refs: Vec<String> = Vec::new();
        for (path, text) in &pages {
            if !path.ends_with(".dox") {
                continue;
            }
            let words: Vec<&str> = text.split([' ', '\n', '>', '<']).collect();
            for w in words.windows(2) {
                match w[0] {
                    "\\page" => {
                        labels.push(w[1].into());
                        pages_.push(w[1].into());
                    }
                    "\\section" | "\\subsection" | "\\anchor" => labels.push(w[1].into()),
                    "\\subpage" => *subpages.entry(w[1].into()).or_default() += 1,
                    "\\ref" => refs.push(w[1].into()),
                    _ => {}
                }
            }
        }
        let set: HashSet<&String> = labels.iter().collect();
        assert_eq!(set.len(), labels.len(), "labels are unique in {input:?}");
        for l in &labels {
            assert!(
                l.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'),
                "label {l}"
            );
        }
        for p in &pages_ {
            assert!(p.starts_with("rtc_"), "prefixed: {p}");
            assert_eq!(
                subpages.get(p),
                Some(&1),
                "page {p} has exactly one \\subpage"
            );
        }
        assert_eq!(
            subpages.len(),
            pages_.len(),
            "no \\subpage to a missing page"
        );
        for r in &refs {
            assert!(set.contains(r), "\\ref {r} resolves");
        }
        assert_eq!(
            pages_.len(),
            cat.components.len()
                + cat.data_types.len()
                + cat.interfaces.len()
                + cat.categories.len()
                // The vendors index and a page per vendor.
                + 1
                + cat.vendors.len()
                + 2
                // The data-flow page.
                + 1
                // The systems index and a page per RT System.
                + if cat.systems.is_empty() { 0 } else { 1 + cat.systems.len() }
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Markdown / mdBook

#[test]
fn mdbook_builds_the_examples_without_warnings_or_broken_links() {
    if !have("mdbook") {
        return;
    }
    let cat = catalog(&examples());
    let (_t, out) = render(&examples(), Format::Markdown, Lang::En);
    let (_b, book) = run_mdbook(&out);
    for c in &cat.components {
        assert!(book.join(format!("components/{}.html", c.slug)).is_file());
    }
    for t in &cat.data_types {
        assert!(book.join(format!("types/{}.html", t.slug)).is_file());
    }
    for t in &cat.interfaces {
        assert!(book.join(format!("interfaces/{}.html", t.slug)).is_file());
    }
}

/// A component folder's README (hostile raw HTML, a table, images, links to another component,
/// a `{{#include}}` line) builds into the book: no warning, no broken link, its image copied, the
/// link to the other component a link to its chapter.
#[test]
fn mdbook_builds_the_readme_fixture() {
    if !have("mdbook") {
        return;
    }
    let input = root().join("tests/fixtures/readme");
    let (_t, out) = render(&input, Format::Markdown, Lang::En);
    let (_b, book) = run_mdbook(&out);
    let page = std::fs::read_to_string(book.join("components/camera.html")).expect("page");
    assert!(
        page.contains("<h3 id=\"readme-camera-component\">"),
        "README shown"
    );
    assert!(page.contains("../assets/readme/diagram-"), "image shown");
    assert!(book.join("assets/readme").is_dir(), "image copied");
    assert!(!page.contains("root:x:0"), "no file included");
    assert!(!page.contains("<script>alert"), "no script");
}

#[test]
fn mdbook_builds_the_corpus_without_warnings_or_broken_links() {
    let Some(corpus) = corpus() else { return };
    if !have("mdbook") {
        return;
    }
    let (_t, out) = render(&corpus, Format::Markdown, Lang::En);
    run_mdbook(&out);
}

#[test]
fn mdbook_keeps_metacharacters_literal() {
    if !have("mdbook") {
        return;
    }
    let (_d, input) = metachars_dir();
    let (_t, out) = render(&input, Format::Markdown, Lang::En);
    let (_b, book) = run_mdbook(&out);
    assert_metachars_intact(&book.join("components/metachars.html"));
}

#[test]
fn markdown_never_emits_profile_markup() {
    let cat = catalog(&hostile());
    for (path, text) in markdown::pages(&cat, "T", Lang::En) {
        // An escaped `\]` cannot close a link text.
        let text = text.replace("\\]", "");
        for bad in [
            "<script",
            "<img",
            "<svg",
            "<iframe",
            "](javascript:",
            "{{#",
            "<!--",
        ] {
            assert!(!text.contains(bad), "{path} contains {bad}");
        }
        // Every table row has as many unescaped pipes as its header.
        let mut cols = 0;
        for line in text.lines() {
            if !line.starts_with('|') {
                cols = 0;
                continue;
            }
            let n = line
                .replace("\\\\", "")
                .replace("\\|", "")
                .matches('|')
                .count();
            if cols == 0 {
                cols = n;
            }
            assert_eq!(n, cols, "{path}: row breaks its table: {line}");
        }
    }
    if have("mdbook") {
        let (_t, out) = render(&hostile(), Format::Markdown, Lang::En);
        let (_b, book) = run_mdbook(&out);
        for (path, bytes) in read_tree(&book) {
            if path.ends_with(".html") || path.ends_with("toc.js") {
                let s = String::from_utf8_lossy(&bytes);
                for bad in [
                    "<script>alert",
                    "<img src=x",
                    "<svg onload",
                    "href=\"javascript:",
                ] {
                    assert!(!s.contains(bad), "{path} contains {bad}");
                }
            }
        }
    }
}

#[test]
fn markdown_summary_lists_every_page_once() {
    let cat = catalog(&examples());
    let pages = markdown::pages(&cat, "T", Lang::En);
    let summary = &pages
        .iter()
        .find(|(p, _)| p == "SUMMARY.md")
        .expect("SUMMARY.md")
        .1;
    let mut linked: HashMap<&str, usize> = HashMap::new();
    for part in summary.split("](").skip(1) {
        let target = part.split(')').next().unwrap_or("");
        *linked.entry(target).or_default() += 1;
    }
    // Pages, not the assets beside them (a system's wiring diagram, `systems/<slug>.svg`).
    let md: Vec<&String> = pages
        .iter()
        .map(|(p, _)| p)
        .filter(|p| p.ends_with(".md"))
        .collect();
    assert!(pages.iter().any(|(p, _)| p.ends_with(".svg")));
    for p in &md {
        if *p == "SUMMARY.md" || *p == "README.md" {
            continue;
        }
        assert_eq!(linked.get(p.as_str()), Some(&1), "{p} in SUMMARY once");
    }
    assert_eq!(linked.len(), md.len() - 2);
}

#[test]
fn markdown_component_pages_show_every_section() {
    let cat = catalog(&examples());
    let pages: HashMap<String, String> = markdown::pages(&cat, "T", Lang::En).into_iter().collect();
    for c in &cat.components {
        let page = &pages[&format!("components/{}.md", c.slug)];
        for k in rtcdoc::model::ActionKind::ALL {
            assert!(page.contains(k.callback_name()), "{} lists {:?}", c.slug, k);
        }
        for a in c
            .anchors
            .data_ports
            .iter()
            .chain(&c.anchors.configurations)
            .chain(c.anchors.interfaces.iter().flatten())
        {
            assert!(page.contains(&format!("<a id=\"{a}\"></a>")), "anchor {a}");
        }
        for conf in c.profile.configurations() {
            if let Some(k) = &conf.constraint {
                let d = rtcdoc::constraint::describe(k);
                assert!(page.contains(&markdown::inline(&d)), "constraint {d}");
            }
        }
        for p in &c.profile.data_ports {
            if let Some(n) = rtcdoc::model::non_empty(&p.name) {
                assert!(page.contains(&markdown::inline(n)), "port {n}");
            }
        }
    }
    let ja: HashMap<String, String> = markdown::pages(&cat, "T", Lang::Ja).into_iter().collect();
    assert!(ja["index.md"].contains("コンポーネント"));
}

// ---------------------------------------------------------------------------------------------
// Both

#[test]
fn renders_are_deterministic() {
    for f in [Format::Markdown, Format::Doxygen] {
        let (_a, one) = render(&examples(), f, Lang::En);
        let (_b, two) = render(&examples(), f, Lang::En);
        assert_eq!(read_tree(&one), read_tree(&two), "{f:?} output is stable");
    }
}

#[test]
fn doxygen_tag_file_lets_another_manual_link_entries() {
    if !have("doxygen") {
        return;
    }
    let (t, out) = render(&examples(), Format::Doxygen, Lang::En);
    run_doxygen(&out);
    let other = t.path().join("other");
    std::fs::create_dir_all(&other).expect("mkdir");
    std::fs::write(
        other.join("m.dox"),
        "/// \\mainpage Other manual\n/// See \\ref rtc_comp_objectdetector and \
         \\ref rtc_comp_usbcamera__port_image \"UsbCamera.image\" of type \
         \\ref rtc_type_rtc_cameraimage.\n",
    )
    .expect("write");
    std::fs::write(
        other.join("Doxyfile"),
        "INPUT = m.dox\nTAGFILES = ../out/rtcdoc.tag=../../out/html\nGENERATE_LATEX = NO\n\
         HAVE_DOT = NO\nQUIET = YES\nWARN_AS_ERROR = FAIL_ON_WARNINGS\n",
    )
    .expect("write");
    run_doxygen(&other);
    let index = std::fs::read_to_string(other.join("html/index.html")).expect("index");
    assert!(index.contains("href=\"../../out/html/rtc_comp_objectdetector.html\""));
    assert!(index.contains("rtc_comp_usbcamera.html#rtc_comp_usbcamera__port_image"));
}

/// A catalogue of RT Systems only: the empty indexes (vendors, categories, data types,
/// interfaces) say so in every format, and Doxygen, whose Doxyfile fails on a warning, has none
/// (an empty `<ul>` was "error: empty list!").
#[test]
fn empty_indexes_say_none_in_every_format() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    std::fs::create_dir_all(&input).unwrap();
    std::fs::copy(
        root().join("tests/fixtures/rts/full.xml"),
        input.join("system.xml"),
    )
    .unwrap();
    let none = "None: the catalogue documents no component profile.";
    let (_m, md) = render(&input, Format::Markdown, Lang::En);
    let vendors = std::fs::read_to_string(md.join("vendors.md")).unwrap();
    assert!(vendors.contains(none), "{vendors}");
    let types = std::fs::read_to_string(md.join("types.md")).unwrap();
    assert!(
        types.contains("None: no data port of the catalogue names a data type.")
            && !types.contains('|'),
        "{types}"
    );
    let (_h, html) = render(&input, Format::Html, Lang::En);
    for page in ["vendors/index.html", "categories/index.html"] {
        let text = std::fs::read_to_string(html.join(page)).unwrap();
        assert!(
            text.contains(none) && !text.contains("<ul class=\"facets\">"),
            "{text}"
        );
    }
    let text = std::fs::read_to_string(html.join("interfaces/index.html")).unwrap();
    assert!(!text.contains("<table>"), "{text}");
    let (_d, dox) = render(&input, Format::Doxygen, Lang::En);
    let vendors = std::fs::read_to_string(dox.join("vendors.dox")).unwrap();
    assert!(
        vendors.contains(none) && !vendors.contains("<ul>"),
        "{vendors}"
    );
    if have("doxygen") {
        run_doxygen(&dox);
    }
}
