//! What's new and the Atom feed hold every history, not only the components' (issue #55: a
//! catalogue's feed had one entry, without a system's breaking changes or any IDL version),
//! RT Systems and IDL files have history pages as components do, every text that sends the
//! reader to "the history page" links one that exists, and a History row spells out what
//! changed, not only counts.
//!
//! The input: a git work tree with one component (`Nav/RTC.xml`, a port renamed), an RT System
//! profile (`systems/NavSystem.xml`, an instance's component upgraded) and an IDL file
//! (`idl/Nav.idl`, fourteen versions: more than a History section shows, one version of six
//! changes, the newest of three warnings: the enum, the struct holding it, the interface).

use crate::common;
use common::history_repo::{build, commit, edit, init, page};
use common::{root, write};
use std::path::{Path, PathBuf};

const COMPONENT: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:Lab:Mobile:Nav:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="Nav" rtc:vendor="Lab" rtc:category="Mobile" rtc:version="1.0.0" rtc:componentType="STATIC" rtc:activityType="PERIODIC" rtc:componentKind="DataFlowComponent" rtc:executionType="PeriodicExecutionContext" rtc:executionRate="10.0"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataOutPort" rtc:name="odometry" rtc:type="Nav::TimedOdometry" rtc:idlFile="Nav.idl"/>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataInPort" rtc:name="mode" rtc:type="Nav::TimedMode" rtc:idlFile="Nav.idl"/>
  <rtc:ServicePorts xsi:type="rtcExt:serviceport_ext" rtc:name="Plan">
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="planner" rtc:type="Nav::Planner" rtc:direction="Required" rtc:idlFile="Nav.idl"/>
  </rtc:ServicePorts>
  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="C++"/>
</rtc:RtcProfile>
"#;

const IDL: &str = "module Nav\n{\n  struct Time\n  {\n    unsigned long sec;\n    unsigned long nsec;\n  };\n\n  struct TimedOdometry\n  {\n    Time tm;\n    double x;\n  };\n\n  enum Mode\n  {\n    STOPPED,\n    MANUAL\n  };\n\n  struct TimedMode\n  {\n    Time tm;\n    Mode data;\n  };\n\n  interface Planner\n  {\n    void cancel();\n  };\n};\n";

/// `idl` with a struct `name` added at the end of its module.
fn with_struct(idl: &str, name: &str) -> String {
    idl.replacen(
        "\n};\n",
        &format!("\n\n  struct {name}\n  {{\n    double v;\n  }};\n}};\n"),
        1,
    )
}

/// The commits of `d`, newest first (40 digits each).
fn commits(d: &Path) -> Vec<String> {
    let o = std::process::Command::new("git")
        .args(["log", "--format=%H"])
        .current_dir(d)
        .env("GIT_CONFIG_NOSYSTEM", "1")
        .env("HOME", d)
        .output()
        .expect("git log");
    String::from_utf8_lossy(&o.stdout)
        .lines()
        .map(str::to_string)
        .collect()
}

/// The work tree (see the module's comment) in `d`, dated 2024-01-01 … 16; its commits, newest
/// first, or `None` without git.
pub(crate) fn repository(d: &Path) -> Option<Vec<String>> {
    if !init(d) {
        return None;
    }
    let fixture = |rel: &str| {
        std::fs::read_to_string(root().join("tests/fixtures/diff/DIFF251").join(rel)).unwrap()
    };
    write(d, "Nav/RTC.xml", COMPONENT);
    write(d, "idl/Nav.idl", IDL);
    write(
        d,
        "systems/NavSystem.xml",
        &fixture("old/systems/NavSystem.xml"),
    );
    commit(d, 1, "First versions");
    let renamed = edit(COMPONENT, &[("rtc:name=\"mode\"", "rtc:name=\"mode_in\"")]);
    write(d, "Nav/RTC.xml", &renamed);
    commit(d, 2, "Rename mode");
    write(
        d,
        "systems/NavSystem.xml",
        &fixture("new/systems/NavSystem.xml"),
    );
    commit(d, 3, "Upgrade Base");
    // Eleven versions of one added type each (info).
    let mut idl = IDL.to_string();
    for k in 1..=11 {
        idl = with_struct(&idl, &format!("S{k}"));
        write(d, "idl/Nav.idl", &idl);
        commit(d, 3 + k, &format!("Add S{k}"));
    }
    // Six types in one version: one more than a History row spells out.
    for k in 1..=6 {
        idl = with_struct(&idl, &format!("E{k}"));
    }
    write(d, "idl/Nav.idl", &idl);
    commit(d, 15, "Add six types");
    // Two warnings: an enum value appended, an operation added.
    idl = edit(
        &idl,
        &[
            ("    MANUAL\n", "    MANUAL,\n    AUTO\n"),
            (
                "    void cancel();\n",
                "    void cancel();\n    void pause();\n",
            ),
        ],
    );
    write(d, "idl/Nav.idl", &idl);
    commit(d, 16, "Extend Mode and Planner");
    Some(commits(d))
}

/// The repository and its site built in HTML, Markdown and Doxygen (with a base URL: the
/// feed); `None` without git.
fn site(dir: &Path) -> Option<(PathBuf, Vec<String>, PathBuf)> {
    let repo = dir.join("repo");
    let ids = repository(&repo)?;
    let site = dir.join("site");
    build(
        &repo,
        &site,
        &[
            "-f",
            "html,markdown,doxygen",
            "--base-url",
            "https://example.org/docs/",
        ],
    );
    Some((repo, ids, site))
}

/// The anchor of commit `id` on its history page.
fn anchor(id: &str) -> String {
    format!("v-{}", &id[..12])
}

#[test]
fn whats_new_and_the_feed_list_system_and_idl_versions_with_the_components() {
    let dir = tempfile::tempdir().unwrap();
    let Some((_repo, ids, site)) = site(dir.path()) else {
        println!("skipped: git not available");
        return;
    };
    // ids: newest first: [0] Extend Mode and Planner, [1] Add six types, [2..=12] Add S11 … S1,
    // [13] Upgrade Base, [14] Rename mode, [15] First versions.
    let (idl_page, system_page) = ("idl-history/idl-nav-idl", "system-history/navsystem");

    // What's new: the IDL file's, the system's and the component's changes, newest first.
    let news = page(&site, "html/whats-new.html");
    let at = |needle: &str| {
        news.find(needle)
            .unwrap_or_else(|| panic!("What's new has no `{needle}`:\n{news}"))
    };
    let newest = at(&format!(
        "<a href=\"{idl_page}.html#{}\">idl/Nav.idl (IDL file)</a></th>",
        anchor(&ids[0])
    ));
    let system = at(&format!(
        "<a href=\"{system_page}.html#{}\">NavSystem (RT System)</a></th>",
        anchor(&ids[13])
    ));
    let component = at(&format!(
        "<a href=\"history/nav.html#{}\">Nav</a></th>",
        anchor(&ids[14])
    ));
    assert!(newest < system && system < component, "not newest first");
    assert!(at("id=\"d-2024-01-16\"") < at("id=\"d-2024-01-03\""));
    // The system's change as the system page's history shows it, with its severity.
    let system_row = &news[system..];
    let system_row = &system_row[..system_row.find("</tr>").unwrap()];
    assert!(system_row.contains("<code>DIFF251</code>"), "{system_row}");
    assert!(
        system_row.contains("<span class=\"sev warning\">"),
        "{system_row}"
    );
    // An IDL change names its type, linked to the type's page.
    let planner = at("<code>idl/Nav::Planner/operations/pause</code></a>");
    assert!(
        news[..planner].ends_with(".html\">")
            && news[..planner].rfind("href=\"interfaces/").is_some(),
        "{}",
        &news[planner.saturating_sub(200)..planner + 60]
    );
    assert!(news.contains("<th scope=\"col\">Component, RT System or IDL file</th>"));

    // Markdown and Doxygen list them too.
    let md = page(&site, "markdown/whats-new.md");
    assert!(
        md.contains(&format!(
            "[idl/Nav.idl (IDL file)]({idl_page}.md#{})",
            anchor(&ids[0])
        )),
        "{md}"
    );
    assert!(
        md.contains(&format!(
            "[NavSystem (RT System)]({system_page}.md#{})",
            anchor(&ids[13])
        )),
        "{md}"
    );
    let dox = page(&site, "doxygen/whats-new.dox");
    assert!(dox.contains("rtc_idlhist_idl_nav_idl__v_"), "{dox}");
    assert!(dox.contains("rtc_syshist_navsystem__v_"), "{dox}");

    // The feed: an entry per version with changes, newest first, the IDL file's and the
    // system's among the component's.
    let feed = page(&site, "html/feed.xml");
    let entries: Vec<&str> = feed.split("<entry>").skip(1).collect();
    assert_eq!(entries.len(), 15, "{feed}");
    let id = |page: &str, i: usize| {
        format!(
            "<id>https://example.org/docs/{page}.html#{}</id>",
            anchor(&ids[i])
        )
    };
    assert!(entries[0].contains(&id(idl_page, 0)), "{}", entries[0]);
    assert!(
        entries[0].contains("<title>idl/Nav.idl (IDL file): Extend Mode and Planner</title>"),
        "{}",
        entries[0]
    );
    assert!(
        entries[0].contains("2 warnings\n[warning] DIFF231 idl/Nav::Mode"),
        "{}",
        entries[0]
    );
    assert!(entries[0].contains("[warning] DIFF232 idl/Nav::Planner/operations/pause"));
    assert!(
        entries[13].contains(&id(system_page, 13)),
        "{}",
        entries[13]
    );
    assert!(
        entries[13].contains("<title>NavSystem (RT System) 1.0: Upgrade Base</title>"),
        "{}",
        entries[13]
    );
    assert!(entries[13].contains("[warning] DIFF251"), "{}", entries[13]);
    assert!(
        entries[14].contains(&id("history/nav", 14)),
        "{}",
        entries[14]
    );
    let dates: Vec<&str> = entries
        .iter()
        .map(|e| &e[e.find("<updated>").unwrap() + 9..][..10])
        .collect();
    let mut sorted = dates.clone();
    sorted.sort_by(|a, b| b.cmp(a));
    assert_eq!(dates, sorted, "the feed is newest first");
}

#[test]
fn systems_and_idl_files_have_history_pages_that_the_pages_link() {
    let dir = tempfile::tempdir().unwrap();
    let Some((repo, ids, site)) = site(dir.path()) else {
        println!("skipped: git not available");
        return;
    };
    // The IDL file's history page: every version, each change linked to its type's page.
    let h = page(&site, "html/idl-history/idl-nav-idl.html");
    assert!(h.contains("<h1>History of idl/Nav.idl</h1>"), "{h}");
    assert_eq!(h.matches("class=\"version\"").count(), 14, "{h}");
    for id in &ids[..13] {
        assert!(
            h.contains(&format!("<section id=\"{}\"", anchor(id))),
            "{id}"
        );
    }
    assert!(
        h.contains("Types defined in this file: <a href=\"../types/"),
        "{h}"
    );
    assert!(h.contains("<code>idl/Nav::E6</code>"), "{h}");
    assert!(h.contains("<a href=\"../interfaces/"), "{h}");
    // The system's.
    let s = page(&site, "html/system-history/navsystem.html");
    assert!(s.contains("<h1>History of NavSystem</h1>"), "{s}");
    assert!(
        s.contains("<a href=\"../systems/navsystem.html\">NavSystem</a>"),
        "{s}"
    );
    assert!(
        s.contains(&format!("<section id=\"{}\"", anchor(&ids[13]))),
        "{s}"
    );
    for rel in [
        "markdown/idl-history/idl-nav-idl.md",
        "markdown/system-history/navsystem.md",
        "doxygen/idl-history/idl-nav-idl.dox",
        "doxygen/system-history/navsystem.dox",
    ] {
        assert!(site.join(rel).is_file(), "no {rel}");
    }
    let summary = page(&site, "markdown/SUMMARY.md");
    assert!(
        summary.contains("(idl-history/idl-nav-idl.md)"),
        "{summary}"
    );

    // The type page's IDL file section: the latest ten versions, each row saying what changed
    // (the newest: two warnings, spelled out; six changes: five and a link to the rest), the
    // four older ones counted, the history page linked.
    let types = type_page(&site, "Nav::TimedOdometry");
    let section = &types[types.find("<section id=\"idl-file\">").unwrap()..];
    let section = &section[..section.find("</section>").unwrap()];
    let rows: Vec<&str> = section.split("<tr>").skip(2).collect();
    assert_eq!(rows.len(), 10, "{section}");
    assert!(
        rows[0].contains(
            "2 warnings<ul><li><span class=\"sev warning\">warning</span> <code>idl/Nav::Mode"
        ),
        "{}",
        rows[0]
    );
    assert!(
        rows[0].contains("<code>idl/Nav::Planner/operations/pause</code>: "),
        "{}",
        rows[0]
    );
    assert_eq!(rows[1].matches("<li>").count(), 6, "{}", rows[1]);
    assert!(
        rows[1].contains(&format!(
            "<li><a href=\"../idl-history/idl-nav-idl.html#{}\">1 more change on the history page</a></li>",
            anchor(&ids[1])
        )),
        "{}",
        rows[1]
    );
    assert!(
        section.contains("4 older versions are on the history page"),
        "{section}"
    );
    assert!(
        section.contains("<a href=\"../idl-history/idl-nav-idl.html\">The whole history"),
        "{section}"
    );
    // The system page links its history page.
    let sys = page(&site, "html/systems/navsystem.html");
    assert!(
        sys.contains("<a href=\"../system-history/navsystem.html\">The whole history"),
        "{sys}"
    );

    // Every promise of a history page, in every page of both outputs, is a link to a file
    // that is there.
    let mut promises = 0;
    for (dir, ext) in [("html", "html"), ("markdown", "md")] {
        promises += history_promises_are_links(&site.join(dir), ext);
    }
    assert!(promises >= 4, "{promises} texts name the history page");

    // The native type and component pages are byte for byte the templates'.
    let theme = dir.path().join("theme");
    for t in ["type.html", "interface.html", "component.html"] {
        let text = std::fs::read_to_string(root().join("themes/default").join(t)).unwrap();
        write(&theme, t, &text);
    }
    let templated = dir.path().join("templated");
    let theme = theme.to_str().unwrap().to_string();
    build(
        &repo,
        &templated,
        &[
            "-f",
            "html,markdown",
            "--base-url",
            "https://example.org/docs/",
            "--theme",
            &theme,
        ],
    );
    let rel = "html/components/nav.html";
    assert_eq!(page(&site, rel), page(&templated, rel), "{rel}");
    for e in std::fs::read_dir(site.join("html/types")).unwrap() {
        let rel = format!("html/types/{}", e.unwrap().file_name().to_string_lossy());
        assert!(page(&site, &rel) == page(&templated, &rel), "{rel} differs");
    }
}

/// The HTML page of data type `name` below `site`.
fn type_page(site: &Path, name: &str) -> String {
    for e in std::fs::read_dir(site.join("html/types")).unwrap() {
        let text = common::read_page(&e.unwrap().path());
        if text.contains(&format!("<code>{name}</code></h1>")) {
            return text;
        }
    }
    panic!("no page of {name}");
}

/// Checks that every text below `dir` (files ending `.ext`) that sends the reader to "the
/// history page" has, in its section, a link to a history page that exists; how many there
/// are.
fn history_promises_are_links(dir: &Path, ext: &str) -> usize {
    let mut n = 0;
    for e in walkdir::WalkDir::new(dir).into_iter().flatten() {
        let path = e.path();
        if path.extension().and_then(|x| x.to_str()) != Some(ext) {
            continue;
        }
        let text = common::read_page(path);
        let (open, close) = match ext {
            "html" => ("<section", "</section>"),
            _ => ("\n## ", "\n## "),
        };
        for (at, _) in text.match_indices("on the history page") {
            n += 1;
            let start = text[..at].rfind(open).unwrap_or(0);
            let end = text[at..].find(close).map_or(text.len(), |e| at + e);
            let section = &text[start..end];
            let links = links_in(section, ext);
            let ok = links.iter().any(|l| {
                let file = l.split('#').next().unwrap_or(l);
                file.contains("history/") && path.parent().unwrap().join(file).is_file()
            });
            assert!(
                ok,
                "{}: `on the history page` without a link to one that exists:\n{section}",
                path.display()
            );
        }
    }
    n
}

/// The link targets of an HTML (`href="…"`) or Markdown (`](…)`) text.
fn links_in(text: &str, ext: &str) -> Vec<String> {
    let open = if ext == "html" { "href=\"" } else { "](" };
    let close = if ext == "html" { '"' } else { ')' };
    text.match_indices(open)
        .filter_map(|(i, _)| {
            let rest = &text[i + open.len()..];
            rest.find(close).map(|j| rest[..j].to_string())
        })
        .collect()
}
