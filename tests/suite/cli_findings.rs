//! What `build`, `check` and `serve` print and how they exit: findings like cargo, exit codes,
//! `--exclude DIR`, profile-named files that are not profiles, files named on the command line,
//! inputs with nothing to document, flags `serve` does not take.

use crate::common;
use common::OutputWithin;
use common::*;
use std::path::Path;

fn fixture(name: &str) -> String {
    std::fs::read_to_string(root().join("tests/fixtures/check").join(name)).expect("fixture")
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `in/` with one profile with a rule error (RTC303) and one with a warning (RTC203).
fn with_findings(d: &Path) {
    write(d, "in/bad/RTC.xml", &fixture("RTC303-bad.xml"));
    write(d, "in/warn/RTC.xml", &fixture("RTC203-bad.xml"));
    // Undocumented: documentation-coverage infos.
    write(
        d,
        "in/plain/RTC.xml",
        &xml_profile("Plain", &[("DataOutPort", "out", "RTC::TimedLong")]),
    );
}

#[test]
fn build_prints_rule_errors_and_warnings_like_cargo() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    with_findings(d);
    let out = rtcdoc(&["build", "in", "-o", "site", "--exclude", "nothing/**"], d);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let err = stderr(&out);
    // file:line:col: severity[CODE]: message, with the path as the user can open it.
    assert!(
        err.contains("in/bad/RTC.xml:10:95: error[RTC303]:"),
        "{err}"
    );
    assert!(err.contains("in/warn/RTC.xml:"), "{err}");
    assert!(err.contains(": warning[RTC203]:"), "{err}");
    assert!(err.contains("  = help: "), "{err}");
    // Errors come before warnings.
    assert!(err.find("error[RTC303]").unwrap() < err.find("warning[RTC203]").unwrap());
    // Infos only with --verbose.
    assert!(!err.contains(": info["), "{err}");
    // The hint repeats the input options of the build.
    assert!(
        err.contains("(details: rtcdoc check in --exclude 'nothing/**')"),
        "{err}"
    );
    let v = rtcdoc(&["build", "in", "-o", "site", "--verbose"], d);
    assert!(stderr(&v).contains(": info[RTC50"), "{}", stderr(&v));
    // --quiet: errors only.
    let q = rtcdoc(&["build", "in", "-o", "site", "--quiet"], d);
    let qe = stderr(&q);
    assert!(
        qe.contains("error[RTC303]") && !qe.contains("warning["),
        "{qe}"
    );
}

#[test]
fn build_caps_the_findings_it_prints() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for i in 0..60 {
        write(
            d,
            &format!("in/c{i:02}/RTC.xml"),
            &fixture("RTC303-bad.xml"),
        );
    }
    let out = rtcdoc(&["build", "in", "-o", "site", "--config", "none.toml"], d);
    let err = stderr(&out);
    // --config names a missing file: the build says so (exit 2) …
    assert_eq!(out.status.code(), Some(2), "{err}");
    let out = rtcdoc(&["build", "in", "-o", "site"], d);
    let err = stderr(&out);
    let printed = err.lines().filter(|l| l.contains("]: ")).count();
    assert_eq!(printed, 50, "{err}");
    // 60 RTC303 errors and 60 duplicate-id warnings: 70 more than printed.
    assert!(
        err.contains("… 70 more: run `rtcdoc check in` to see them all"),
        "{err}"
    );
    let v = rtcdoc(&["build", "in", "-o", "site", "--verbose"], d);
    assert!(!stderr(&v).contains("more: run"), "{}", stderr(&v));
}

#[test]
fn strict_build_exits_1_and_prints_the_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    with_findings(d);
    let out = rtcdoc(&["build", "in", "-o", "site", "--strict"], d);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.contains("in/bad/RTC.xml:10:95: error[RTC303]:"),
        "{err}"
    );
    assert!(err.contains("nothing was written"), "{err}");
    assert!(!d.join("site").exists());
    // Usage errors are 2.
    let u = rtcdoc(&["build", "in", "--format", "pdf"], d);
    assert_eq!(u.status.code(), Some(2));
}

#[test]
fn exclude_of_a_directory_leaves_out_its_whole_subtree() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/comp/RTC.xml", &xml_profile("Comp", &[]));
    write(
        d,
        "in/examples/Templates/a/RTC.xml",
        &xml_profile("TplA", &[]),
    );
    write(d, "in/examples/Templates/b.xml", &xml_profile("TplB", &[]));
    let out = rtcdoc(
        &[
            "build",
            "in",
            "-f",
            "json",
            "-o",
            "out",
            "--exclude",
            "examples/Templates",
            "--verbose",
        ],
        d,
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let json = std::fs::read_to_string(d.join("out/catalog.json")).unwrap();
    assert!(json.contains("\"Comp\"") && !json.contains("Tpl"), "{json}");
    let err = stderr(&out);
    assert!(
        err.contains(
            "skipped in/examples/Templates/: directory excluded by pattern `examples/Templates`"
        ),
        "{err}"
    );
    // check with the same pattern agrees.
    let c = rtcdoc(
        &[
            "check",
            "in",
            "--exclude",
            "examples/Templates",
            "--format",
            "json",
        ],
        d,
    );
    let v: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
    assert_eq!(v["coverage"]["components"].as_array().unwrap().len(), 1);
}

#[test]
fn profile_named_files_that_are_no_profiles_are_warned_about() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/ok/RTC.xml", &xml_profile("Ok", &[]));
    write(d, "in/empty/RTC.xml", "");
    std::fs::create_dir_all(d.join("in/bin")).unwrap();
    std::fs::write(d.join("in/bin/RTC.xml"), b"\x89PNG\r\n\x1a\n\0\0\0IHDR").unwrap();
    write(
        d,
        "in/cut/RTC.xml",
        "<?xml version=\"1.0\"?>\n<!-- RTCBuilder -->\n",
    );
    write(d, "in/yaml/RTC.yaml", "just: text\n");
    write(d, "in/old/RTC.xml20171205120156", "");
    write(
        d,
        "in/sys/RTC.xml",
        "<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\"/>",
    );
    // Not named like a profile: quietly skipped, as before.
    write(d, "in/ok/notes.xml", "<notes/>");
    let out = rtcdoc(&["build", "in", "-o", "site"], d);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    for (file, what) in [
        ("in/empty/RTC.xml", "RTC.xml is empty (a failed save?)"),
        ("in/bin/RTC.xml", "RTC.xml is binary data"),
        (
            "in/cut/RTC.xml",
            "RTC.xml ends before its root element (truncated?)",
        ),
        (
            "in/yaml/RTC.yaml",
            "RTC.yaml is neither XML nor YAML with a top-level `rtcProfile` (component) or `rtsProfile` (RT System) key",
        ),
    ] {
        assert!(
            err.contains(&format!("{file}: warning[RTC012]: {what}")),
            "{file}: {err}"
        );
    }
    assert!(!err.contains("notes.xml"), "{err}");
    // An RTCBuilder backup is a version of its folder's RTC.xml, not a profile of its own: this
    // one (empty, and its RTC.xml gone) is reported as a backup without its profile.
    assert!(
        err.contains("in/old/RTC.xml20171205120156: warning[RTC013]: 1 RTCBuilder backup(s) (RTC.xml20171205120156) but no old/RTC.xml beside them"),
        "{err}"
    );
    // An RT System profile is documented as a system, whatever its name.
    assert!(!err.contains("in/sys/RTC.xml"), "{err}");
    // check reports the same warnings.
    let c = rtcdoc(&["check", "in", "--format", "json"], d);
    assert_eq!(c.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
    assert_eq!(v["summary"]["byCode"]["RTC012"], 4, "{v}");
    assert_eq!(v["summary"]["byCode"]["RTC013"], 1, "{v}");
    // A backup without .xml that is a profile is read like one with it, and kept in the JSON
    // (its RTC.xml being gone, among the catalogue's backups).
    write(d, "in/old/RTC.xml20171205120156", &xml_profile("Old", &[]));
    let j = rtcdoc(&["build", "in", "-f", "json", "-o", "j"], d);
    assert!(j.status.success(), "{}", stderr(&j));
    let json = std::fs::read_to_string(d.join("j/catalog.json")).unwrap();
    assert!(
        json.contains("\"source\": \"old/RTC.xml20171205120156\""),
        "{json}"
    );
}

#[test]
fn a_file_named_on_the_command_line_is_read_whatever_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "backup/RTC.bak", &fixture("RTC303-bad.xml"));
    let out = rtcdoc(&["check", "backup/RTC.bak"], d);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("error[RTC303]"), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("backup/RTC.bak:10:95"),
        "{}",
        stderr(&out)
    );
    write(
        d,
        "sys/DefaultSystem.xml",
        "<?xml version=\"1.0\"?><rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\"/>",
    );
    // An RT System profile named on the command line is read as one.
    let sys = rtcdoc(&["check", "sys/DefaultSystem.xml"], d);
    assert_eq!(sys.status.code(), Some(0), "{}", stderr(&sys));
    write(d, "notes.txt", "hello");
    let txt = rtcdoc(&["check", "notes.txt"], d);
    assert_eq!(txt.status.code(), Some(2));
    assert!(
        stderr(&txt).contains("is neither XML nor YAML"),
        "{}",
        stderr(&txt)
    );
}

#[test]
fn nothing_to_document_is_an_error_unless_allowed() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/src/main.cpp", "int main() {}");
    write(d, "in/data/notes.xml", "<notes/>");
    for cmd in ["build", "check"] {
        let out = rtcdoc(&[cmd, "in"], d);
        assert_eq!(out.status.code(), Some(2), "{cmd}: {}", stderr(&out));
        let err = stderr(&out);
        assert!(err.contains("nothing to document"), "{err}");
        assert!(err.contains("`in`"), "{err}");
        assert!(
            err.contains("1 .xml/.yaml file(s) that are not component profiles, 1 other file(s)"),
            "{err}"
        );
        assert!(err.contains("--allow-empty"), "{err}");
        // `--verbose` lists them, as the message says.
        let out = rtcdoc(&[cmd, "in", "--verbose"], d);
        assert_eq!(out.status.code(), Some(2));
        let err = stderr(&out);
        assert!(
            err.contains("skipped in/data/notes.xml: is XML with the root element `notes`"),
            "{err}"
        );
        assert!(err.contains("skipped 1 other file(s)"), "{err}");
    }
    assert!(!d.join("site").exists());
    // An empty folder: nothing for `--verbose` to list, so the message does not offer it.
    std::fs::create_dir_all(d.join("empty")).unwrap();
    let err = stderr(&rtcdoc(&["check", "empty"], d));
    assert!(
        err.contains("in `empty` (it holds no files).") && !err.contains("--verbose"),
        "{err}"
    );
    let ok = rtcdoc(&["build", "in", "--allow-empty", "-o", "site"], d);
    assert!(ok.status.success(), "{}", stderr(&ok));
    assert!(d.join("site/index.html").is_file());
    assert!(rtcdoc(&["check", "in", "--allow-empty"], d)
        .status
        .success());
    // `diff` against a side left empty (its last profile deleted): the hint it gives works,
    // and every component of the other side is then removed.
    let camera = std::fs::read_to_string(common::root().join("examples/Joystick/RTC.xml")).unwrap();
    write(d, "old/Joystick/RTC.xml", &camera);
    let out = rtcdoc(&["diff", "old", "empty"], d);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("or pass --allow-empty to accept an empty input"),
        "{}",
        stderr(&out)
    );
    let out = rtcdoc(&["diff", "old", "empty", "--allow-empty"], d);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("breaking[DIFF101]"),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn sitemap_only_with_a_base_url() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/a/RTC.xml", &xml_profile("A", &[]));
    let out = rtcdoc(&["build", "in", "-o", "site"], d);
    assert!(out.status.success());
    assert!(!d.join("site/sitemap.xml").exists());
    assert!(
        stderr(&out).contains("note: no sitemap.xml"),
        "{}",
        stderr(&out)
    );
    let out = rtcdoc(
        &[
            "build",
            "in",
            "-o",
            "site",
            "--base-url",
            "https://x.example/c",
        ],
        d,
    );
    assert!(!stderr(&out).contains("sitemap"), "{}", stderr(&out));
    let sm = std::fs::read_to_string(d.join("site/sitemap.xml")).unwrap();
    assert!(sm.contains("<loc>https://x.example/c/components/"), "{sm}");
}

#[test]
fn markdown_output_keeps_its_marker_out_of_the_book() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/a/RTC.xml", &xml_profile("A", &[]));
    let out = rtcdoc(&["build", "in", "-f", "markdown", "-o", "book/src"], d);
    assert!(out.status.success(), "{}", stderr(&out));
    // mdBook copies every non-Markdown file of src/ into the book: the marker is a .md file.
    assert!(d.join("book/src/.rtcdoc-output.md").is_file());
    assert!(!d.join("book/src/.rtcdoc-output").exists());
    // … and still lets the next build replace the output.
    let again = rtcdoc(&["build", "in", "-f", "markdown", "-o", "book/src"], d);
    assert!(again.status.success(), "{}", stderr(&again));
    if tool_available("mdbook") {
        write(d, "book/book.toml", "[book]\ntitle = \"t\"\n");
        let b = std::process::Command::new("mdbook")
            .arg("build")
            .current_dir(d.join("book"))
            .output_within(common::COMMAND_LIMIT)
            .unwrap();
        assert!(b.status.success(), "{}", String::from_utf8_lossy(&b.stderr));
        let leaked: Vec<_> = walkdir::WalkDir::new(d.join("book/book"))
            .into_iter()
            .flatten()
            .filter(|e| e.file_name().to_string_lossy().contains("rtcdoc-output"))
            .collect();
        assert!(leaked.is_empty(), "{leaked:?}");
    } else {
        crate::common::missing_tool("(mdbook part) mdbook not installed");
    }
}

#[test]
fn serve_refuses_flags_it_would_ignore_and_prints_the_first_findings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    with_findings(d);
    for flags in [&["-o", "x"][..], &["-f", "json"], &["--strict"]] {
        let mut args = vec!["serve", "in", "--port", "0"];
        args.extend_from_slice(flags);
        let out = rtcdoc(&args, d);
        assert_eq!(out.status.code(), Some(2), "{flags:?}");
        assert!(
            stderr(&out).contains("unexpected argument"),
            "{}",
            stderr(&out)
        );
    }
    // The first build's findings are printed before "serving at".
    let (mut child, rx, lines) = common::serve_until_ready(&["serve", "in", "--port", "0"], d);
    let text = lines.join("\n");
    assert!(
        text.contains("in/bad/RTC.xml:10:95: error[RTC303]"),
        "{text}"
    );
    assert!(text.contains("serving at http://127.0.0.1:"), "{text}");
    // A live rebuild's findings name the file as the first build's do (below `in/`). Edited until the watcher, armed in the background, sees it.
    let plain = d.join("in/plain/RTC.xml");
    let good = std::fs::read_to_string(&plain).unwrap();
    let mut after = Vec::new();
    'edits: for attempt in 0..20 {
        let broken = format!("{good}<after{attempt} the root>");
        std::fs::write(&plain, broken).unwrap();
        while let Ok(line) = rx.recv_timeout(std::time::Duration::from_millis(500)) {
            after.push(line);
            if after.iter().any(|l| l.contains("RTC001")) {
                break 'edits;
            }
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    let text = after.join("\n");
    let finding = after
        .iter()
        .find(|l| l.contains("RTC001"))
        .unwrap_or_else(|| panic!("no rebuild error: {text}"));
    assert!(
        finding.starts_with("in/plain/RTC.xml:9:1: error[RTC001]"),
        "{text}"
    );
}

/// Without a path, `check` reads what `build` reads: the configuration's `input`, else the
/// configuration file's folder.
#[test]
fn check_without_a_path_reads_the_configured_input() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "a/ok/RTC.xml", &xml_profile("Ok", &[]));
    write(d, "b/bad/RTC.xml", &fixture("RTC303-bad.xml"));
    write(d, "rtcdoc.toml", "input = \"a\"\n");
    let built = rtcdoc(&["build", "-o", "site"], d);
    assert_eq!(built.status.code(), Some(0), "{}", stderr(&built));
    let checked = rtcdoc(&["check"], d);
    assert_eq!(checked.status.code(), Some(0), "{}", stderr(&checked));
    assert!(!stderr(&checked).contains("RTC303"), "{}", stderr(&checked));
    // A configuration elsewhere with no `input`: its own folder.
    write(d, "b/rtcdoc.toml", "title = \"B\"\n");
    let other = rtcdoc(&["check", "--config", "b/rtcdoc.toml"], d);
    assert_eq!(other.status.code(), Some(1), "{}", stderr(&other));
    assert!(
        stderr(&other).contains("b/bad/RTC.xml"),
        "{}",
        stderr(&other)
    );
}

/// `strict = true` of the file is turned off by `--no-strict`; of two flags the last wins.
#[test]
fn no_strict_overrides_the_configuration() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    with_findings(d);
    write(d, "in/rtcdoc.toml", "strict = true\n");
    let strict = rtcdoc(&["build", "in", "-o", "site"], d);
    assert_eq!(strict.status.code(), Some(1), "{}", stderr(&strict));
    assert!(!d.join("site").exists());
    let relaxed = rtcdoc(&["build", "in", "-o", "site", "--no-strict"], d);
    assert_eq!(relaxed.status.code(), Some(0), "{}", stderr(&relaxed));
    assert!(d.join("site/index.html").exists());
    let last = rtcdoc(&["build", "in", "-o", "site", "--no-strict", "--strict"], d);
    assert_eq!(last.status.code(), Some(1), "{}", stderr(&last));
}

/// `--allow-empty` is honoured by `graph` and kept in the `check` command `build` suggests,
/// which then works as printed.
#[test]
fn allow_empty_is_honoured_and_kept_in_the_suggested_check() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir_all(d.join("empty")).unwrap();
    let refused = rtcdoc(&["graph", "empty", "--dataflow", "category"], d);
    assert_eq!(refused.status.code(), Some(2), "{}", stderr(&refused));
    assert!(
        stderr(&refused).contains("--allow-empty"),
        "{}",
        stderr(&refused)
    );
    let empty = rtcdoc(
        &["graph", "empty", "--dataflow", "category", "--allow-empty"],
        d,
    );
    assert_eq!(empty.status.code(), Some(0), "{}", stderr(&empty));
    let built = rtcdoc(&["build", "empty", "-o", "site", "--allow-empty"], d);
    assert_eq!(built.status.code(), Some(0), "{}", stderr(&built));
    let err = stderr(&built);
    let suggested = err
        .split("rtcdoc check ")
        .nth(1)
        .and_then(|rest| rest.split(')').next())
        .unwrap_or_else(|| panic!("no check command suggested:\n{err}"));
    let args: Vec<&str> = std::iter::once("check")
        .chain(suggested.split_whitespace())
        .collect();
    assert!(args.contains(&"--allow-empty"), "{args:?}");
    let checked = rtcdoc(&args, d);
    assert_eq!(checked.status.code(), Some(0), "{}", stderr(&checked));
}

/// `[serve] open = true` opens a browser (the platform's opener, here a stand-in that notes
/// the URL); `--no-open` turns it off.
#[cfg(target_os = "linux")]
#[test]
fn no_open_overrides_the_configuration() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/a/RTC.xml", &xml_profile("A", &[]));
    write(d, "in/rtcdoc.toml", "[serve]\nopen = true\n");
    let opened = d.join("opened.txt");
    let opener = d.join("bin/xdg-open");
    write(
        d,
        "bin/xdg-open",
        &format!("#!/bin/sh\necho \"$1\" >> '{}'\n", opened.display()),
    );
    std::fs::set_permissions(&opener, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = std::env::join_paths(std::iter::once(d.join("bin")).chain(std::env::split_paths(
        &std::env::var_os("PATH").unwrap_or_default(),
    )))
    .unwrap();
    let env = [("PATH", path)];
    for (flags, opens) in [(&["--no-open"][..], false), (&[][..], true)] {
        let mut args = vec!["serve", "in", "--port", "0"];
        args.extend_from_slice(flags);
        let (mut child, _rx, _lines) = common::serve_until_ready_with(&args, d, &env);
        // The opener is started right after "serving at"; give it time to write.
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(10);
        while opens && !opened.exists() && std::time::Instant::now() < deadline {
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        if !opens {
            std::thread::sleep(std::time::Duration::from_millis(500));
        }
        let _ = child.kill();
        let _ = child.wait();
        assert_eq!(opened.exists(), opens, "{flags:?}");
        if opens {
            let url = std::fs::read_to_string(&opened).unwrap();
            assert!(url.starts_with("http://127.0.0.1:"), "{url}");
        }
    }
}
