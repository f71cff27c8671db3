//! The history pages, through the binary: a component's whole history (`history/<slug>`), the
//! "since" notes of its ports, interfaces and parameters (and `since` in catalog.json), the
//! catalogue's What's new, and the Atom feed `feed.xml` (with `base-url` only), in every
//! output. The repository is `common::history_repo`'s: four commits of one profile.

use crate::common;
use common::history_repo::{self, history_repo, page};
use common::OutputWithin;
use common::{tree, write};
use std::path::{Path, PathBuf};

const SOURCE_URL: &str = "source-url = \"https://example.org/lab/blob/{commit}/{path}\"\n";

/// The repository in `dir/repo` with a `source-url`; `None` without git.
fn repo(dir: &Path) -> Option<PathBuf> {
    let repo = dir.join("repo");
    if !history_repo(&repo) {
        crate::common::missing_tool("git not available");
        return None;
    }
    write(&repo, "rtcdoc.toml", SOURCE_URL);
    Some(repo)
}

fn build(input: &Path, out: &Path, extra: &[&str]) {
    let mut args = vec!["-f", "html,markdown,doxygen,json"];
    args.extend_from_slice(extra);
    history_repo::build(input, out, &args);
}

/// The text from `from` to the next `to` (exclusive).
fn between<'a>(s: &'a str, from: &str, to: &str) -> &'a str {
    let s = &s[s.find(from).unwrap_or_else(|| panic!("no `{from}` in {s}"))..];
    &s[..s[from.len()..].find(to).map_or(s.len(), |i| i + from.len())]
}

/// The short commit ids of the repository, newest first.
fn commits(repo: &Path) -> Vec<String> {
    let o = std::process::Command::new("git")
        .args(["log", "--format=%h", "--abbrev=12"])
        .current_dir(repo)
        .output_within(common::COMMAND_LIMIT)
        .expect("git log");
    String::from_utf8_lossy(&o.stdout)
        .lines()
        .map(str::to_string)
        .collect()
}

#[test]
fn the_history_page_shows_every_version_and_change_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let Some(repo) = repo(dir.path()) else { return };
    let site = dir.path().join("site");
    build(&repo, &site, &[]);
    let ids = commits(&repo);
    assert_eq!(ids.len(), 4);

    let html = page(&site, "html/history/base.html");
    // Newest first: the rename, the reformatting folded, the release, the first version.
    let order: Vec<usize> = [
        format!("<section id=\"v-{}\"", ids[0]),
        "<p class=\"folded\">1 version without changes to the specification</p>".into(),
        format!("<section id=\"v-{}\"", ids[2]),
        format!("<section id=\"v-{}\"", ids[3]),
    ]
    .iter()
    .map(|s| {
        html.find(s.as_str())
            .unwrap_or_else(|| panic!("no {s} in {html}"))
    })
    .collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{order:?}");
    assert!(!html.contains(&format!("v-{}", ids[1])), "folded: {html}");
    let rename = between(
        &html,
        &format!("<section id=\"v-{}\"", ids[0]),
        "</section>",
    );
    // Every change with its code, severity, path and message (its code spans as code, as in
    // Markdown and Doxygen); DIFF208 among them.
    for s in [
        "<span class=\"sev breaking\">breaking</span></th><td class=\"nowrap\" data-label=\"Code\"><code>DIFF102</code></td><td data-label=\"Where\"><code>dataPorts/cmd</code></td><td data-label=\"Message\">data port <code>cmd</code> was removed</td>",
        "<code>DIFF208</code>",
        "<code>DIFF301</code></td><td data-label=\"Where\"><code>dataPorts/velocity</code>",
        "1 breaking, 1 warning, 1 info",
        "<dd>Rename cmd</dd>",
        "<dd>Tester</dd>",
        "<dd>2024-01-04T10:00:00+09:00</dd>",
    ] {
        assert!(rename.contains(s), "no {s} in {rename}");
    }
    // The commit links to its file at that commit, as on the component page.
    let link = format!(
        "<a href=\"https://example.org/lab/blob/{}",
        &ids[0][..12.min(ids[0].len())]
    );
    assert!(rename.contains(&link), "{rename}");
    let release = between(
        &html,
        &format!("<section id=\"v-{}\"", ids[2]),
        "</section>",
    );
    // The release is marked once: beside the heading, not also in it.
    let short = &ids[2][..12.min(ids[2].len())];
    assert!(
        release.contains(&format!(
            "<h2>1.1.0 · {short} <span class=\"release\">release</span></h2>"
        )),
        "{release}"
    );
    assert_eq!(release.matches("release").count(), 2, "{release}");
    // Profile and commit text is escaped.
    assert!(
        release.contains("Release 1.1.0 &lt;with status&gt;"),
        "{release}"
    );
    for code in ["DIFF301", "DIFF303", "DIFF306"] {
        assert!(release.contains(code), "{code}: {release}");
    }
    let first = between(
        &html,
        &format!("<section id=\"v-{}\"", ids[3]),
        "</section>",
    );
    assert!(first.contains("first version in the history"), "{first}");
    assert!(!first.contains("<table"), "{first}");

    // The component page's History section links to it.
    let comp = page(&site, "html/components/base.html");
    assert!(
        comp.contains(
            "<p><a href=\"../history/base.html\">The whole history, with every change</a></p>"
        ),
        "{comp}"
    );

    let md = page(&site, "markdown/history/base.md");
    assert!(md.starts_with("# History of Base\n"), "{md}");
    assert!(
        md.contains(&format!(
            "<a id=\"v-{}\"></a>\n\n## 1.1.0 · {}",
            ids[0], ids[0]
        )),
        "{md}"
    );
    assert!(
        md.contains("| breaking | DIFF102 | dataPorts/cmd | data port `cmd` was removed |"),
        "{md}"
    );
    assert!(
        md.contains("| warning | DIFF208 | basicInfo/version |"),
        "{md}"
    );
    // Breaking changes first, though their path sorts after the warning's.
    assert!(
        md.find("| breaking | DIFF102 |").expect("breaking row")
            < md.find("| warning | DIFF208 |").expect("warning row"),
        "{md}"
    );
    assert!(
        md.contains(&format!("## 1.1.0 · {short}\n\n| Field | Value |")),
        "{md}"
    );
    assert_eq!(
        md.matches("A release: the version string changed.").count(),
        1,
        "{md}"
    );
    assert!(!md.contains("(release)"), "{md}");
    let dox = page(&site, "doxygen/history/base.dox");
    assert!(dox.contains(&format!(" 1.1.0 · {short}\n")), "{dox}");
    assert_eq!(
        dox.matches("A release: the version string changed.")
            .count(),
        1,
        "{dox}"
    );
    assert!(!dox.contains("(release)"), "{dox}");
    assert!(
        md.contains("1 version without changes to the specification"),
        "{md}"
    );
    let summary = page(&site, "markdown/SUMMARY.md");
    assert!(
        summary
            .contains("- [What\\'s new](whats-new.md)\n    - [History of Base](history/base.md)"),
        "{summary}"
    );
    assert!(
        page(&site, "markdown/components/base.md").contains("](../history/base.md)"),
        "the Markdown component page links its history"
    );
    let dox = page(&site, "doxygen/history/base.dox");
    assert!(
        dox.contains("\\page rtc_hist_base History of Base"),
        "{dox}"
    );
    assert!(
        dox.contains(&format!("\\section rtc_hist_base__v_{} ", ids[0])),
        "{dox}"
    );
    assert!(dox.contains("DIFF208"), "{dox}");
    assert!(
        page(&site, "doxygen/components/base.dox").contains("\\ref rtc_hist_base"),
        "the Doxygen component page links its history"
    );
    assert!(
        page(&site, "doxygen/Doxyfile").contains("history/base.dox"),
        "the Doxyfile lists the page"
    );
}

#[test]
fn since_notes_name_the_version_that_added_each_element() {
    let dir = tempfile::tempdir().unwrap();
    let Some(repo) = repo(dir.path()) else { return };
    let site = dir.path().join("site");
    build(&repo, &site, &[]);
    let bytes = std::fs::read(site.join("json/catalog.json")).unwrap();
    let json: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
    let c = &json["components"]["RTC:Lab:Mobile:Base:1.1.0"];
    // The elements of the first version have none; the renamed port is dated by the rename,
    // by its day: the rename kept 1.1.0, which the release first came without it.
    assert_eq!(
        c["since"],
        serde_json::json!({
            "configurations/gain": "1.1.0",
            "dataPorts/status": "1.1.0",
            "dataPorts/velocity": "2024-01-04",
            "servicePorts/svc": "1.1.0",
            "servicePorts/svc/interfaces/map": "1.1.0",
        })
    );
    // catalog.json still reads back to the same bytes.
    let back = rtcdoc::render::json::read_catalog(&bytes, "catalog.json").expect("reads back");
    let mut again = Vec::new();
    rtcdoc::render::json::write_json_with(&back.catalog, &back.title, false, &mut again).unwrap();
    assert!(again == bytes, "catalog.json round trip differs");

    let html = page(&site, "html/components/base.html");
    let badge = "<span class=\"since\">since 1.1.0</span>";
    for name in ["status", "map", "gain"] {
        assert!(
            html.contains(&format!("<code>{name}</code> {badge}</th>")),
            "{name}: {html}"
        );
    }
    assert!(
        html.contains("<code>velocity</code> <span class=\"since\">since 2024-01-04</span></th>"),
        "{html}"
    );
    assert!(
        html.contains(&format!("<code>svc</code> {badge}")),
        "{html}"
    );
    assert!(html.contains("<code>max_speed</code></th>"), "{html}");
    assert_eq!(html.matches(badge).count(), 4, "{html}");
    let md = page(&site, "markdown/components/base.md");
    assert!(md.contains("status (since 1.1.0)"), "{md}");
    assert!(md.contains("gain (since 1.1.0)"), "{md}");
    assert!(md.contains("### svc (since 1.1.0)"), "{md}");
    assert!(!md.contains("max\\_speed (since") && !md.contains("max_speed (since"));
    let dox = page(&site, "doxygen/components/base.dox");
    assert!(dox.contains("map (since 1.1.0)"), "{dox}");

    // Japanese.
    let ja = dir.path().join("ja");
    build(&repo, &ja, &["--language", "ja"]);
    let html = page(&ja, "html/components/base.html");
    assert!(
        html.contains("<span class=\"since\">1.1.0 から</span>"),
        "{html}"
    );
}

#[test]
fn whats_new_lists_every_change_newest_first_with_a_filter() {
    let dir = tempfile::tempdir().unwrap();
    let Some(repo) = repo(dir.path()) else { return };
    let site = dir.path().join("site");
    build(&repo, &site, &[]);
    let ids = commits(&repo);
    let html = page(&site, "html/whats-new.html");
    // Two days with changes, newest first; the reformatting and the first version have none.
    let d4 = html
        .find("<section class=\"news-day\" id=\"d-2024-01-04\">")
        .expect("day 4");
    let d2 = html
        .find("<section class=\"news-day\" id=\"d-2024-01-02\">")
        .expect("day 2");
    assert!(d4 < d2);
    assert!(!html.contains("d-2024-01-03") && !html.contains("d-2024-01-01"));
    let rows: Vec<&str> = html.split("<tr data-sev=").skip(1).collect();
    assert_eq!(rows.len(), 3 + 4, "{html}");
    assert!(rows[..3].iter().all(|r| r.contains(&ids[0])), "{html}");
    let breaking = rows
        .iter()
        .find(|r| r.contains("DIFF102"))
        .expect("the rename");
    assert!(breaking.starts_with("\"breaking\" data-source=\"\" data-category=\"Mobile\">"));
    assert!(
        breaking.contains(&format!(
            "<a href=\"history/base.html#v-{}\">Base</a>",
            ids[0]
        )),
        "{breaking}"
    );
    // The filter (the page reads whole without it) and its script, which the CSP allows.
    for s in [
        "<form id=\"news-filter\" class=\"filter\">",
        "<option value=\"breaking\">breaking</option>",
        "<option value=\"Mobile\">Mobile</option>",
        "<script src=\"filter.js\" defer></script>",
    ] {
        assert!(html.contains(s), "no {s}");
    }
    assert!(
        !html.contains("f-nsource"),
        "no source filter without [[source]]"
    );
    assert!(page(&site, "html/filter.js").contains("news-filter"));
    // Every page's navigation links it.
    for p in [
        "html/index.html",
        "html/components/base.html",
        "html/history/base.html",
    ] {
        assert!(
            page(&site, p).contains("whats-new.html\">What&#39;s new</a></li>"),
            "{p}"
        );
    }

    let md = page(&site, "markdown/whats-new.md");
    let (m4, m2) = (
        md.find("## 2024-01-04").unwrap(),
        md.find("## 2024-01-02").unwrap(),
    );
    assert!(m4 < m2, "{md}");
    assert!(
        md.contains(&format!(
            "- [Base](history/base.md#v-{}) 1.1.0 · 2024-01-04T10:00:00+09:00 · [{}](https://example.org/lab/blob/",
            ids[0], ids[0]
        )),
        "{md}"
    );
    assert!(page(&site, "markdown/index.md").contains("[What\\'s new](whats-new.md)"));
    let dox = page(&site, "doxygen/whats-new.dox");
    assert!(dox.contains("\\page rtc_whats_new "), "{dox}");
    assert!(
        dox.contains(&format!("\\ref rtc_hist_base__v_{}", ids[0])),
        "{dox}"
    );
    assert!(page(&site, "doxygen/mainpage.dox").contains("\\subpage rtc_whats_new"));
}

#[test]
fn without_a_history_there_are_no_history_pages() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(
        &input,
        "Base/RTC.xml",
        &common::history_repo::versions()[0].1,
    );
    let site = dir.path().join("site");
    build(&input, &site, &["--base-url", "https://example.org/docs"]);
    for p in [
        "html/whats-new.html",
        "html/history",
        "html/feed.xml",
        "markdown/whats-new.md",
        "doxygen/whats-new.dox",
    ] {
        assert!(!site.join(p).exists(), "{p}");
    }
    let html = page(&site, "html/components/base.html");
    assert!(!html.contains("whats-new") && !html.contains("feed.xml") && !html.contains("since"));
}

#[test]
fn the_atom_feed_is_valid_stable_and_only_with_a_base_url() {
    let dir = tempfile::tempdir().unwrap();
    let Some(repo) = repo(dir.path()) else { return };
    let ids = commits(&repo);
    let site = dir.path().join("site");
    build(&repo, &site, &["--base-url", "https://example.org/docs/"]);
    let feed = page(&site, "html/feed.xml");
    if common::tool_available("xmllint") {
        let o = std::process::Command::new("xmllint")
            .args(["--noout"])
            .arg(site.join("html/feed.xml"))
            .output_within(common::COMMAND_LIMIT)
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    } else {
        common::missing_tool("(xmllint part) xmllint not installed");
    }
    assert!(feed.starts_with(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<feed xmlns=\"http://www.w3.org/2005/Atom\""
    ));
    assert!(
        feed.contains("<id>https://example.org/docs/feed.xml</id>"),
        "{feed}"
    );
    // The newest commit's date, never the build time.
    assert!(
        feed.contains("</generator>\n  <entry>")
            && feed.contains("<updated>2024-01-04T10:00:00+09:00</updated>\n  <author>"),
        "{feed}"
    );
    // One entry per version with changes, newest first, each with its page anchor as id.
    let entries: Vec<&str> = feed.split("<entry>").skip(1).collect();
    assert_eq!(entries.len(), 2, "{feed}");
    let id = |i: usize| {
        format!(
            "<id>https://example.org/docs/history/base.html#v-{}</id>",
            ids[i]
        )
    };
    assert!(entries[0].contains(&id(0)), "{}", entries[0]);
    assert!(entries[0].contains("<title>Base 1.1.0: Rename cmd</title>"));
    assert!(entries[0].contains("<updated>2024-01-04T10:00:00+09:00</updated>"));
    assert!(entries[0].contains("[breaking] DIFF102 dataPorts/cmd: data port `cmd` was removed"));
    assert!(entries[1].contains(&id(2)), "{}", entries[1]);
    assert!(
        entries[1]
            .contains("<title>Base 1.1.0 (release): Release 1.1.0 &lt;with status&gt;</title>"),
        "{}",
        entries[1]
    );
    // Linked from every page's head.
    let link = "<link rel=\"alternate\" type=\"application/atom+xml\" href=\"../feed.xml\" title=\"Changes (Atom feed)\">";
    assert!(page(&site, "html/components/base.html").contains(link));
    assert!(page(&site, "html/history/base.html").contains(link));
    // Byte-identical on a second build.
    let again = dir.path().join("again");
    build(&repo, &again, &["--base-url", "https://example.org/docs/"]);
    assert!(tree(&site) == tree(&again), "two builds differ");
    // The native component page (since badges, the history link, the feed link, What's new in
    // the navigation) is byte for byte what the templates write.
    let theme = dir.path().join("theme");
    write(
        &theme,
        "component.html",
        &std::fs::read_to_string(common::root().join("themes/default/component.html")).unwrap(),
    );
    let templated = dir.path().join("templated");
    build(
        &repo,
        &templated,
        &[
            "--base-url",
            "https://example.org/docs/",
            "--theme",
            theme.to_str().unwrap(),
        ],
    );
    let native = page(&site, "html/components/base.html");
    assert!(native.contains("<span class=\"since\">") && native.contains(link));
    assert_eq!(native, page(&templated, "html/components/base.html"));
    // Without a base URL: no feed, no link.
    let plain = dir.path().join("plain");
    build(&repo, &plain, &[]);
    assert!(!plain.join("html/feed.xml").exists());
    assert!(!page(&plain, "html/components/base.html").contains("application/atom+xml"));
}

#[test]
fn the_added_codes_of_the_catalogue_are_the_diff_engines() {
    use rtcdoc::diff::codes;
    let mut ours = rtcdoc::catalog::history::ADDED_CODES.to_vec();
    let mut theirs = vec![
        codes::PORT_ADDED,
        codes::INTERFACE_ADDED,
        codes::REQUIRED_INTERFACE_ADDED,
        codes::CONFIGURATION_ADDED,
    ];
    ours.sort();
    theirs.sort();
    assert_eq!(ours, theirs);
}

/// A backup's name gives its time in the saving machine's zone, without the zone: What's new
/// and the feed read it in the zone of the component's commits, so a backup saved at 12:43 in
/// Japan comes before a commit made at 18:18 +09:00 that day (read as UTC it came after).
#[test]
fn a_backup_orders_among_commits_in_their_time_zone() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !history_repo::init(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let v = history_repo::versions();
    // `Base/RTC.xml` committed at `time` on 2017-04-27, +09:00.
    let commit_at = |time: &str, subject: &str| {
        let date = format!("2017-04-27 {time} +0900");
        assert!(history_repo::git(&repo, &["add", "Base/RTC.xml"], &date));
        assert!(history_repo::git(
            &repo,
            &["commit", "-q", "-m", subject],
            &date
        ));
    };
    write(&repo, "Base/RTC.xml", &v[0].1);
    commit_at("08:00:00", "morning");
    // RTCBuilder saved version 2 at 12:43:18 local time (its backup), then version 4 was committed.
    write(&repo, "Base/RTC.xml20170427124318", &v[1].1);
    write(&repo, "Base/RTC.xml", &v[3].1);
    commit_at("18:18:45", "evening");
    let site = dir.path().join("site");
    history_repo::build(
        &repo,
        &site,
        &["-f", "markdown", "--base-url", "https://example.org/"],
    );
    let md = page(&site, "whats-new.md");
    let commit = md
        .find(" · 2017-04-27T18:18:45+09:00 · ")
        .unwrap_or_else(|| panic!("{md}"));
    let backup = md
        .find(" · 2017-04-27 12:43:18 · RTC.xml20170427124318 — ")
        .unwrap_or_else(|| panic!("{md}"));
    assert!(commit < backup, "the 18:18 commit first:\n{md}");
}

/// git writes a UTC author date with `Z` and any other with its offset: the pages show every
/// commit's date in one form, its own offset, UTC as `+00:00` (they mixed `Z` and `+09:00`).
#[test]
fn commit_dates_are_shown_in_one_form() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !history_repo::init(&repo) {
        crate::common::missing_tool("git not available");
        return;
    }
    let v = history_repo::versions();
    for (i, (text, date)) in [
        (&v[0].1, "2024-01-01T10:00:00+0900"),
        (&v[1].1, "2024-01-02T01:00:00+0000"),
        (&v[3].1, "2024-01-03T10:00:00+0900"),
    ]
    .into_iter()
    .enumerate()
    {
        write(&repo, "Base/RTC.xml", text);
        assert!(history_repo::git(&repo, &["add", "Base/RTC.xml"], date));
        let subject = format!("version {i}");
        assert!(history_repo::git(
            &repo,
            &["commit", "-q", "-m", &subject],
            date
        ));
    }
    let site = dir.path().join("site");
    build(&repo, &site, &[]);
    let html = page(&site, "html/history/base.html");
    let md = page(&site, "markdown/history/base.md");
    let news = page(&site, "markdown/whats-new.md");
    for (name, text) in [("html", &html), ("md", &md), ("whats-new", &news)] {
        assert!(text.contains("2024-01-03T10:00:00+09:00"), "{name}: {text}");
        assert!(text.contains("2024-01-02T01:00:00+00:00"), "{name}: {text}");
        assert!(!text.contains("2024-01-02T01:00:00Z"), "{name}: {text}");
    }
}

/// A description holding RTCBuilder's `<br/>` breaks the line there in a change's message, as
/// the component page does (issue #55: it showed raw), in every output, without stray
/// backticks; the JSON keeps the value as written.
#[test]
fn a_line_break_tag_in_a_changed_text_breaks_the_line() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    let v1 = history_repo::versions().remove(0).1;
    let v2 = history_repo::edit(
        &v1,
        &[(
            r#"rtc:name="Base""#,
            r#"rtc:name="Base" rtc:description="line one&lt;br/&gt;line two""#,
        )],
    );
    if !history_repo::commit_versions(&repo, vec![("one", v1), ("two", v2)]) {
        crate::common::missing_tool("git not available");
        return;
    }
    let site = dir.path().join("site");
    build(&repo, &site, &[]);
    let md = page(&site, "markdown/history/base.md");
    assert!(md.contains("&#123;+line one<br>line two+&#125;"), "{md}");
    assert!(!md.contains("\\`"), "{md}");
    assert!(!md.contains("br/"), "{md}");
    let dox = page(&site, "doxygen/history/base.dox");
    assert!(dox.contains("{+line one<br>line two+}"), "{dox}");
    let html = page(&site, "html/history/base.html");
    assert!(html.contains("<ins>line one<br>line two</ins>"), "{html}");
    assert!(!html.contains("&lt;br"), "{html}");
    let json: serde_json::Value = serde_json::from_str(&page(&site, "json/catalog.json")).unwrap();
    let change = &json["components"]["RTC:Lab:Mobile:Base:1.0.0"]["history"][0]["changes"][0];
    assert_eq!(change["new"], "line one<br/>line two", "{change:#}");
}

/// A profile kept outside git beside its RTCBuilder backups: the file itself is the newest
/// version. What's new lists it first (under "Current files", dated by its `updateDate`, whose
/// milliseconds RTCBuilder writes), its history calls it the current file (there is no commit
/// it could be "not committed" to), and the feed has it first.
#[test]
fn a_profile_outside_git_is_the_newest_version_everywhere() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let v = history_repo::versions();
    let dated = |p: &str, date: &str| {
        history_repo::edit(
            p,
            &[(
                r#"rtc:executionRate="100.0""#,
                &format!(r#"rtc:executionRate="100.0" rtc:updateDate="{date}""#),
            )],
        )
    };
    write(
        &input,
        "Base/RTC.xml",
        &dated(&v[3].1, "2017-04-28T09:30:00.159+09:00"),
    );
    write(
        &input,
        "Base/RTC.xml20170427124318",
        &dated(&v[1].1, "2017-04-27T12:43:18.000+09:00"),
    );
    write(
        &input,
        "Base/RTC.xml20170426080000",
        &dated(&v[0].1, "2017-04-26T08:00:00.000+09:00"),
    );
    let site = dir.path().join("site");
    history_repo::build(
        &input,
        &site,
        &["-f", "html,markdown", "--base-url", "https://example.org/"],
    );
    let md = page(&site, "markdown/whats-new.md");
    let current = md
        .find("## Current files")
        .unwrap_or_else(|| panic!("{md}"));
    let day = md.find("## 2017-04-27").unwrap_or_else(|| panic!("{md}"));
    assert!(current < day, "the file itself first:\n{md}");
    assert!(
        md.contains(" 1.1.0 · 2017-04-28T09:30:00+09:00 · Base/RTC.xml — "),
        "{md}"
    );
    assert!(!md.contains("## Without a date"), "{md}");
    let history = page(&site, "markdown/history/base.md");
    assert!(
        history.contains("current file") && !history.contains("not committed"),
        "{history}"
    );
    // Its row is dated as What's new dates it, on the history page and the component page.
    let current_row = |text: &str| {
        text.lines()
            .find(|l| l.contains("current file") && l.contains('|'))
            .unwrap_or_else(|| panic!("{text}"))
            .to_string()
    };
    assert!(
        history.contains("| Date | 2017-04-28T09:30:00+09:00 |\n| Commit | current file |"),
        "{history}"
    );
    let component = page(&site, "markdown/components/base.md");
    assert!(
        current_row(&component).contains("2017-04-28T09:30:00+09:00"),
        "{component}"
    );
    let feed = page(&site, "html/feed.xml");
    let first = between(&feed, "<entry>", "</entry>");
    assert!(
        first.contains("<updated>2017-04-28T09:30:00+09:00</updated>")
            && first.contains("velocity"),
        "{feed}"
    );
}
