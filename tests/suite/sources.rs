//! `[[source]]` repositories: fetched from repositories the tests create (`git init`, `file://`
//! URLs, no network), pinned in `rtcdoc.lock`, read from git objects.

use crate::common;
use common::OutputWithin;
use common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Runs git in `dir` (identity and branch fixed, no user or system configuration).
fn git(dir: &Path, args: &[&str]) -> String {
    let out = Command::new("git")
        .args(["-c", "user.name=t", "-c", "user.email=t@example.org"])
        .args([
            "-c",
            "init.defaultBranch=main",
            "-c",
            "commit.gpgsign=false",
        ])
        .args(args)
        .current_dir(dir)
        .env("GIT_CONFIG_NOSYSTEM", "1")
        .env("GIT_CONFIG_GLOBAL", "/dev/null")
        .output_within(common::COMMAND_LIMIT)
        .expect("git runs");
    assert!(
        out.status.success(),
        "git {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// A repository at `dir` with `files` committed (and tagged `tag`, if given); its HEAD commit.
fn commit(dir: &Path, files: &[(&str, String)], tag: Option<&str>) -> String {
    if !dir.join(".git").is_dir() {
        std::fs::create_dir_all(dir).unwrap();
        git(dir, &["init", "-q"]);
    }
    for (rel, text) in files {
        write(dir, rel, text);
    }
    git(dir, &["add", "-A"]);
    git(dir, &["commit", "-q", "-m", "change"]);
    if let Some(t) = tag {
        git(dir, &["tag", t]);
    }
    git(dir, &["rev-parse", "HEAD"])
}

fn url(p: &Path) -> String {
    format!("file://{}", p.display())
}

struct Project {
    _tmp: tempfile::TempDir,
    root: PathBuf,
    proj: PathBuf,
    cache: String,
}

impl Project {
    fn new() -> Project {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path().to_path_buf();
        let proj = root.join("proj");
        std::fs::create_dir_all(&proj).unwrap();
        let cache = root.join("cache").display().to_string();
        Project {
            _tmp: tmp,
            root,
            proj,
            cache,
        }
    }

    fn config(&self, text: &str) {
        write(&self.proj, "rtcdoc.toml", text);
    }

    /// `rtcdoc ARGS --cache-dir CACHE` in the project.
    fn run(&self, args: &[&str]) -> (i32, String) {
        let mut all: Vec<&str> = args.to_vec();
        all.extend(["--cache-dir", &self.cache]);
        let o = rtcdoc(&all, &self.proj);
        (
            o.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    }

    fn lock(&self) -> String {
        std::fs::read_to_string(self.proj.join("rtcdoc.lock")).unwrap_or_default()
    }

    fn catalog(&self) -> serde_json::Value {
        let p = self.proj.join("site/json/catalog.json");
        let p = if p.is_file() {
            p
        } else {
            self.proj.join("site/catalog.json")
        };
        serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap()
    }

    fn component_names(&self) -> Vec<String> {
        let c = self.catalog();
        let mut v: Vec<String> = c["components"]
            .as_object()
            .unwrap()
            .values()
            .map(|c| c["source"].as_str().unwrap().to_string())
            .collect();
        v.sort();
        v
    }
}

/// Two repositories (one with two components and a tag, one with one) and a local directory.
fn two_repos(p: &Project) -> (PathBuf, String, PathBuf, String) {
    let nav = p.root.join("nav");
    let v1 = commit(
        &nav,
        &[
            ("comps/Planner/RTC.xml", xml_profile("Planner", &[])),
            ("comps/Mover/RTC.xml", xml_profile("Mover", &[])),
            ("other/Ignored/RTC.xml", xml_profile("Ignored", &[])),
        ],
        Some("v1"),
    );
    let cam = p.root.join("cam");
    let c1 = commit(
        &cam,
        &[
            ("Camera/RTC.xml", xml_profile("Camera", &[])),
            (
                "Camera/README.md",
                "# Camera\n\nThe driver is [main.cpp](src/main.cpp).\n".to_string(),
            ),
        ],
        None,
    );
    (nav, v1, cam, c1)
}

#[test]
fn sources_are_pinned_in_the_lock_and_linked_at_their_commit() {
    let p = Project::new();
    let (nav, v1, _, c1) = two_repos(&p);
    write(&p.proj, "local/Local/RTC.xml", &xml_profile("Local", &[]));
    p.config(&format!(
        "input = \"local\"\n\n[[source]]\ngit = \"{}\"\nrev = \"v1\"\npath = \"comps\"\n\n[[source]]\ngit = \"../cam\"\nname = \"camera\"\nsource-url = \"https://git.example.org/cam/blob/{{commit}}/{{path}}\"\n",
        url(&nav)
    ));
    let (code, err) = p.run(&["build", "-f", "html,json"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("rtcdoc.lock: camera added at"), "{err}");
    // The lock: sorted by name, each with its URL as written, rev and commit.
    assert_eq!(
        p.lock()
            .lines()
            .filter(|l| !l.starts_with('#'))
            .collect::<Vec<_>>()
            .join("\n"),
        format!(
            "version = 1\n\n[[source]]\nname = \"camera\"\ngit = \"../cam\"\ncommit = \"{c1}\"\n\n[[source]]\nname = \"nav\"\ngit = \"{}\"\nrev = \"v1\"\ncommit = \"{v1}\"",
            url(&nav)
        )
    );
    // Sources and the local directory, mixed; `path` leaves the rest of the repository out.
    assert_eq!(
        p.component_names(),
        [
            "Local/RTC.xml",
            "camera/Camera/RTC.xml",
            "nav/comps/Mover/RTC.xml",
            "nav/comps/Planner/RTC.xml"
        ]
    );
    let cat = p.catalog();
    let planner = &cat["components"]["RTC:Test:Cat:Planner:1.0.0"];
    assert_eq!(planner["origin"]["source"], "nav");
    assert_eq!(planner["origin"]["commit"], v1.as_str());
    assert_eq!(planner["origin"]["path"], "comps/Planner/RTC.xml");
    assert!(cat["components"]["RTC:Test:Cat:Local:1.0.0"]
        .get("origin")
        .is_none());
    assert_eq!(cat["sources"][0]["name"], "nav");
    assert_eq!(
        cat["sources"][1]["sourceUrl"],
        "https://git.example.org/cam/blob/{commit}/{path}"
    );
    // The Source link of a component points into its own repository at the pinned commit.
    let page = common::read_page(&p.proj.join("site/html/components/camera.html"));
    assert!(
        page.contains(&format!(
            "<a href=\"https://git.example.org/cam/blob/{c1}/Camera/RTC.xml\"><code>camera/Camera/RTC.xml</code></a>"
        )),
        "{page}"
    );
    // Its README is read from the repository, its links go into the repository at the commit.
    assert!(
        page.contains(&format!(
            "<a href=\"https://git.example.org/cam/blob/{c1}/Camera/src/main.cpp\" rel=\"noopener noreferrer\">main.cpp</a>"
        )),
        "{page}"
    );
    // The index can be filtered by source; the search finds a source's components by its name.
    let index = common::read_page(&p.proj.join("site/html/index.html"));
    assert!(
        index.contains("<option value=\"nav\">nav</option>"),
        "{index}"
    );
    assert!(
        index.contains("data-category=\"cat\" data-source=\"camera\">"),
        "{index}"
    );
    // Three components from sources; the local one has none.
    assert_eq!(index.matches(" data-source=").count(), 3, "{index}");
    let search = common::search_index::read(&p.proj.join("site/html"));
    assert!(
        search
            .entries
            .iter()
            .any(|e| e.meta == "Cat · Test · camera"),
        "{:?}",
        search.entries
    );
    // catalog.json reads back (diff of the catalogue with itself: no change).
    let o = rtcdoc(
        &["diff", "site/json/catalog.json", "site/json/catalog.json"],
        &p.proj,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // A second build with the lock: nothing fetched or changed, the same bytes.
    let before = tree(&p.proj.join("site"));
    let (code, err) = p.run(&["build", "-f", "html,json", "--locked"]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("rtcdoc.lock:"), "{err}");
    assert_eq!(tree(&p.proj.join("site")), before);
    // Markdown links the Source the same way.
    let (code, err) = p.run(&["build", "-f", "markdown", "-o", "md"]);
    assert_eq!(code, 0, "{err}");
    let md = std::fs::read_to_string(p.proj.join("md/components/camera.md")).unwrap();
    assert!(
        md.contains(&format!(
            "[camera/Camera/RTC.xml](https://git.example.org/cam/blob/{c1}/Camera/RTC.xml)"
        )),
        "{md}"
    );
    // `check` reads the same sources, also with the directory named as `build DIR` takes it.
    for args in [&["check"][..], &["check", "."]] {
        let (code, err) = p.run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(err.contains("4 component profiles"), "{args:?}: {err}");
    }
}

#[test]
fn builds_keep_the_locked_commit_until_update_moves_it() {
    let p = Project::new();
    let repo = p.root.join("repo");
    let first = commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(p.lock().contains(&first));
    let second = commit(&repo, &[("B/RTC.xml", xml_profile("B", &[]))], None);
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(p.component_names(), ["repo/A/RTC.xml"]);
    // `update NAME` of a name that does not exist: the names are listed.
    let (code, err) = p.run(&["update", "nope"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("no source is named `nope`; the sources are: repo"),
        "{err}"
    );
    let (code, err) = p.run(&["update", "repo"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains(&format!("repo {} -> {}", &first[..12], &second[..12])),
        "{err}"
    );
    assert!(p.lock().contains(&second) && !p.lock().contains(&first));
    let (code, err) = p.run(&["update"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("rtcdoc.lock is up to date (1 source(s))"),
        "{err}"
    );
    let (code, err) = p.run(&["build", "-f", "json", "--locked"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(p.component_names(), ["repo/A/RTC.xml", "repo/B/RTC.xml"]);
}

/// `rev = "HEAD"` (what `git ls-remote` lists first) is the remote's default branch, as no
/// `rev` is: the checked-out branch of the repository, not another branch; `diff NAME@HEAD`
/// too.
#[test]
fn rev_head_is_the_default_branch() {
    let p = Project::new();
    let repo = p.root.join("repo");
    commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    git(&repo, &["checkout", "-q", "-b", "work"]);
    let work = commit(&repo, &[("B/RTC.xml", xml_profile("B", &[]))], None);
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\nrev = \"HEAD\"\n",
        url(&repo)
    ));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        p.lock().contains(&work) && p.lock().contains("rev = \"HEAD\""),
        "{}",
        p.lock()
    );
    assert_eq!(p.component_names(), ["repo/A/RTC.xml", "repo/B/RTC.xml"]);
    let (code, err) = p.run(&["diff", "repo", "repo@HEAD"]);
    assert_eq!(code, 0, "{err}");
}

/// The `git ls-remote` a bad `rev` suggests works from where rtcdoc was run, not only from the
/// folder of `rtcdoc.toml` (its `git` path is relative to that folder).
#[test]
fn the_suggested_ls_remote_works_from_the_current_directory() {
    let p = Project::new();
    commit(
        &p.proj.join("repo"),
        &[("A/RTC.xml", xml_profile("A", &[]))],
        None,
    );
    write(
        &p.proj,
        "cfg/rtcdoc.toml",
        "[[source]]\ngit = \"../repo\"\nrev = \"no-such\"\n",
    );
    let (code, err) = p.run(&["build", "--config", "cfg/rtcdoc.toml"]);
    assert_eq!(code, 2, "{err}");
    let command = err
        .split("list them with `")
        .nth(1)
        .and_then(|rest| rest.split('`').next())
        .unwrap_or_else(|| panic!("a git ls-remote to run: {err}"));
    assert!(command.starts_with("git ls-remote "), "{err}");
    let o = Command::new("sh")
        .args(["-c", command])
        .current_dir(&p.proj)
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(
        o.status.success() && String::from_utf8_lossy(&o.stdout).contains("refs/heads/main"),
        "{command}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The `rtcdoc update` that the --locked and --offline errors suggest carries the --config and
/// --cache-dir given: following it writes the lock the command reads and fills the cache it
/// reads, so the command then succeeds.
#[test]
fn the_suggested_update_carries_config_and_cache_dir() {
    let p = Project::new();
    commit(
        &p.proj.join("repo"),
        &[("A/RTC.xml", xml_profile("A", &[]))],
        None,
    );
    write(
        &p.proj,
        "cfg/rtcdoc.toml",
        "[[source]]\ngit = \"../repo\"\n",
    );
    let run = |args: &[&str]| {
        let mut all = args.to_vec();
        all.extend(["--config", "cfg/rtcdoc.toml", "--cache-dir", "../cache2"]);
        all.extend(["-f", "json"]);
        let o = rtcdoc(&all, &p.proj);
        (
            o.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    // Runs the `rtcdoc update …` the error names, as printed, from the same directory.
    let follow = |err: &str| {
        let command = err
            .split('`')
            .find(|c| c.starts_with("rtcdoc update"))
            .unwrap_or_else(|| panic!("an rtcdoc update to run: {err}"));
        assert_eq!(
            command, "rtcdoc update --config cfg/rtcdoc.toml --cache-dir ../cache2",
            "{err}"
        );
        let bin = env!("CARGO_BIN_EXE_rtcdoc");
        let o = Command::new("sh")
            .args(["-c", &command.replacen("rtcdoc", &format!("'{bin}'"), 1)])
            .current_dir(&p.proj)
            .output_within(common::COMMAND_LIMIT)
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    let (code, err) = run(&["build", "--locked"]);
    assert_eq!(code, 2, "{err}");
    follow(&err);
    assert!(p.proj.join("cfg/rtcdoc.lock").is_file());
    let (code, err) = run(&["build", "--locked"]);
    assert_eq!(code, 0, "{err}");

    std::fs::remove_dir_all(p.root.join("cache2")).unwrap();
    let (code, err) = run(&["build", "--offline"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--offline forbids fetching"), "{err}");
    follow(&err);
    let (code, err) = run(&["build", "--offline", "--locked"]);
    assert_eq!(code, 0, "{err}");
}

/// A folder of the input named like a source: the error says why an exclude pattern is no
/// way out (the source's files are named `<name>/…` too) and names a source name that works,
/// and the input is named as written (`.`, not `./.`).
#[test]
fn a_folder_named_like_a_source_names_a_way_out_that_works() {
    let p = Project::new();
    let repo = p.root.join("repo");
    commit(&repo, &[("B/RTC.xml", xml_profile("B", &[]))], None);
    write(&p.proj, "a/prof/RTC.xml", &xml_profile("Prof", &[]));
    let table = format!("[[source]]\ngit = \"{}\"\nname = \"a\"\n", url(&repo));
    p.config(&format!("input = \".\"\n{table}"));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains(
            "`a/prof/RTC.xml` of the input directory `.` is in a folder named like a source (`a`)"
        ),
        "{err}"
    );
    assert!(
        err.contains("an `exclude` pattern for it would leave out the source's files as well"),
        "{err}"
    );
    let name = err
        .split("name = \"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .unwrap_or_else(|| panic!("a name to give: {err}"));
    p.config(&format!(
        "input = \".\"\n{}",
        table.replace("name = \"a\"", &format!("name = \"{name}\""))
    ));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        p.component_names(),
        ["a-source/B/RTC.xml", "a/prof/RTC.xml"]
    );
    assert!(
        err.contains("(details: rtcdoc check . --cache-dir"),
        "{err}"
    );
}

#[test]
fn locked_fails_when_the_lock_is_missing_or_would_change() {
    let p = Project::new();
    let (nav, _, cam, _) = two_repos(&p);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&nav)));
    let (code, err) = p.run(&["build", "--locked"]);
    assert_eq!(code, 2);
    assert!(
        err.contains(&format!(
            "--locked: there is no `./rtcdoc.lock`; run `rtcdoc update --cache-dir {}`",
            p.cache
        )),
        "{err}"
    );
    assert!(!p.proj.join("site").exists() && !p.proj.join("rtcdoc.lock").exists());
    assert_eq!(p.run(&["update"]).0, 0);
    assert_eq!(p.run(&["build", "--locked"]).0, 0);
    let lock = p.lock();
    // Edited (a rev), added, removed: each refused, the lock left as it was.
    for config in [
        format!("[[source]]\ngit = \"{}\"\nrev = \"v1\"\n", url(&nav)),
        format!(
            "[[source]]\ngit = \"{}\"\n\n[[source]]\ngit = \"{}\"\n",
            url(&nav),
            url(&cam)
        ),
        format!("[[source]]\ngit = \"{}\"\n", url(&cam)),
    ] {
        p.config(&config);
        for cmd in ["build", "check"] {
            let (code, err) = p.run(&[cmd, "--locked"]);
            assert_eq!(code, 2, "{config}");
            assert!(
                err.contains("--locked: `./rtcdoc.lock` would have to change"),
                "{err}"
            );
            assert!(err.contains("rtcdoc update"), "{err}");
            assert_eq!(p.lock(), lock);
        }
    }
    // Removed only: the lock names a source the configuration has no more.
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\n\n[[source]]\ngit = \"{}\"\n",
        url(&nav),
        url(&cam)
    ));
    assert_eq!(p.run(&["update"]).0, 0);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&nav)));
    let (code, err) = p.run(&["build", "--locked"]);
    assert_eq!(code, 2);
    assert!(err.contains("(cam removed)"), "{err}");
}

#[test]
fn offline_uses_the_cache_only_and_says_what_is_missing() {
    let p = Project::new();
    let (nav, _, _, _) = two_repos(&p);
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\nrev = \"v1\"\n",
        url(&nav)
    ));
    let (code, err) = p.run(&["build", "--offline"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("source `nav` (`file://")
            && err.contains("is not in the cache")
            && err.contains("--offline forbids fetching; run once without --offline"),
        "{err}"
    );
    assert!(!p.proj.join("site").exists());
    assert_eq!(p.run(&["build"]).0, 0);
    // The repository gone: the cache still builds offline.
    std::fs::rename(&nav, p.root.join("elsewhere")).unwrap();
    let (code, err) = p.run(&["build", "--offline", "--locked"]);
    assert_eq!(code, 0, "{err}");
    // Without --offline, the fetch fails and says so.
    let (code, err) = p.run(&["build"]);
    assert_eq!(
        code, 0,
        "a locked commit in the cache needs no fetch: {err}"
    );
    std::fs::remove_file(p.proj.join("rtcdoc.lock")).unwrap();
    let (code, err) = p.run(&["build"]);
    assert_eq!(code, 2);
    assert!(err.contains("source `nav`: git cannot fetch"), "{err}");
}

/// A first fetch that fails leaves nothing in the cache, and its error does not offer
/// `--offline` (there is no cache to build from); `--offline` then says the source is not
/// cached. Git's message names the path as written (`./x`, not `././x`). A mirror that holds
/// nothing (an empty repository fetched) is not taken for a cached source either.
#[test]
fn a_failed_first_fetch_leaves_no_mirror_and_offers_no_offline_build() {
    let p = Project::new();
    p.config("[[source]]\ngit = \"./does-not-exist.git\"\nrev = \"main\"\n");
    let (code, err) = p.run(&["build"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("source `does-not-exist`: git cannot fetch `./does-not-exist.git`"),
        "{err}"
    );
    assert!(err.contains("'./does-not-exist.git'"), "{err}");
    assert!(!err.contains("--offline"), "{err}");
    let cached: Vec<_> = std::fs::read_dir(&p.cache)
        .map(|d| d.flatten().map(|e| e.file_name()).collect())
        .unwrap_or_default();
    assert!(cached.is_empty(), "{cached:?}");
    let (code, err) = p.run(&["build", "--offline"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("source `does-not-exist` (`./does-not-exist.git`) is not in the cache"),
        "{err}"
    );

    let empty = p.root.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    git(&empty, &["init", "-q"]);
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\nrev = \"main\"\n",
        url(&empty)
    ));
    let (code, err) = p.run(&["build"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("no branch, tag or commit `main`"), "{err}");
    let (code, err) = p.run(&["build", "--offline"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("is not in the cache"), "{err}");
}

/// The `rtcdoc check` that a build's summary suggests works when followed: it repeats
/// `--cache-dir`, `--offline` and `--locked`, so it reads the same cache without fetching.
#[test]
fn the_suggested_check_command_reads_the_same_cache() {
    let p = Project::new();
    let repo = p.root.join("bad");
    let profile =
        std::fs::read_to_string(root().join("tests/fixtures/check/RTC303-bad.xml")).unwrap();
    commit(&repo, &[("Bad/RTC.xml", profile)], None);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    assert_eq!(p.run(&["build", "-o", "site"]).0, 0);
    // The repository gone: only the cache has it.
    std::fs::rename(&repo, p.root.join("elsewhere")).unwrap();
    let (code, err) = p.run(&["build", "-o", "site", "--offline", "--locked"]);
    assert_eq!(code, 0, "{err}");
    let suggested = err
        .split("(details: ")
        .nth(1)
        .and_then(|rest| rest.split(')').next())
        .unwrap_or_else(|| panic!("no suggested command: {err}"));
    assert!(
        suggested.contains("--cache-dir")
            && suggested.contains("--offline")
            && suggested.contains("--locked"),
        "{suggested}"
    );
    let bin = env!("CARGO_BIN_EXE_rtcdoc");
    let command = suggested.replacen("rtcdoc", bin, 1);
    let out = Command::new("sh")
        .args(["-c", &command])
        .current_dir(&p.proj)
        .output_within(common::COMMAND_LIMIT)
        .expect("sh runs");
    let text =
        String::from_utf8_lossy(&out.stderr).into_owned() + &String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{command}: {text}");
    assert!(text.contains("error[RTC303]"), "{text}");
}

#[test]
fn options_and_command_transports_are_refused_before_git_runs() {
    let p = Project::new();
    let (nav, _, _, _) = two_repos(&p);
    let marker = p.root.join("pwned");
    let cases = [
        (
            format!("git = \"{}\"\nrev = \"-x\"", url(&nav)),
            "`rev = \"-x\"` starts with `-`",
        ),
        (
            format!(
                "git = \"{}\"\nrev = \"--upload-pack=touch {}\"",
                url(&nav),
                marker.display()
            ),
            "starts with `-`",
        ),
        (
            format!("git = \"ext::sh -c touch% {}\"", marker.display()),
            "uses the git transport `ext::`",
        ),
        (
            "git = \"fd::3\"".to_string(),
            "uses the git transport `fd::`",
        ),
        (
            format!("git = \"--upload-pack=touch {}\"", marker.display()),
            "starts with `-`: rtcdoc never passes options to git",
        ),
        (
            "git = \"http://example.org/r.git\"".to_string(),
            "the transport `http://` is not supported",
        ),
        (
            format!("git = \"{}\"\npath = \"../x\"", url(&nav)),
            "leaves the repository",
        ),
        (
            format!("git = \"{}\"\nbogus = 1", url(&nav)),
            "unknown field `bogus`",
        ),
    ];
    for (table, want) in cases {
        p.config(&format!("[[source]]\n{table}\n"));
        let (code, err) = p.run(&["build"]);
        assert_eq!(code, 2, "{table}");
        assert!(err.contains(want), "{table}: {err}");
        assert!(!marker.exists(), "{table} ran a command");
        assert!(!p.proj.join("site").exists() && !p.proj.join("rtcdoc.lock").exists());
    }
}

#[test]
fn bad_sources_name_the_source_and_leave_the_site_alone() {
    let p = Project::new();
    let (nav, _, _, _) = two_repos(&p);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&nav)));
    assert_eq!(p.run(&["build"]).0, 0);
    let site = tree(&p.proj.join("site"));
    let lock = p.lock();
    let not_a_repo = p.root.join("plain");
    std::fs::create_dir_all(&not_a_repo).unwrap();
    let cases = [
        (
            format!("git = \"{}\"\nrev = \"v9\"", url(&nav)),
            "source `nav`: no branch, tag or commit `v9` in `file://",
        ),
        (
            format!("git = \"{}\"", not_a_repo.display()),
            "source `plain`: git cannot fetch",
        ),
        (
            format!("git = \"{}\"", url(&p.root.join("missing"))),
            "source `missing`: git cannot fetch",
        ),
        (
            format!("git = \"{}\"\npath = \"nothing/here\"", url(&nav)),
            "source `nav`: no folder `nothing/here` at commit",
        ),
    ];
    for (table, want) in cases {
        p.config(&format!("[[source]]\n{table}\n"));
        let (code, err) = p.run(&["build"]);
        assert_eq!(code, 2, "{table}: {err}");
        assert!(err.contains(want), "{table}: {err}");
        assert_eq!(tree(&p.proj.join("site")), site, "{table}");
        assert_eq!(p.lock(), lock, "{table}");
    }
}

#[test]
fn a_lock_naming_a_commit_the_remote_lost_says_to_update() {
    let p = Project::new();
    let repo = p.root.join("repo");
    commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    assert_eq!(p.run(&["build"]).0, 0);
    // History rewritten and the old commit collected; a fresh cache (another machine).
    git(&repo, &["commit", "-q", "--amend", "-m", "rewritten"]);
    git(&repo, &["reflog", "expire", "--expire=now", "--all"]);
    git(&repo, &["gc", "-q", "--prune=now"]);
    let other = p.root.join("cache2").display().to_string();
    let o = rtcdoc(&["build", "--cache-dir", &other], &p.proj);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("source `repo`: `file://") && err.contains("no longer has the commit"),
        "{err}"
    );
    assert!(
        err.contains(&format!("run `rtcdoc update repo --cache-dir {other}`")),
        "{err}"
    );
    let o = rtcdoc(&["update", "--cache-dir", &other], &p.proj);
    assert!(o.status.success());
    let o = rtcdoc(&["build", "--cache-dir", &other], &p.proj);
    assert!(o.status.success());
}

#[test]
fn a_shallow_repository_without_the_commit_is_named() {
    let p = Project::new();
    let repo = p.root.join("repo");
    let first = commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    commit(&repo, &[("B/RTC.xml", xml_profile("B", &[]))], None);
    let shallow = p.root.join("shallow");
    git(
        &p.root,
        &["clone", "-q", "--depth", "1", &url(&repo), "shallow"],
    );
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\nrev = \"{first}\"\n",
        shallow.display()
    ));
    let (code, err) = p.run(&["build"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains(&format!("no branch, tag or commit `{first}`")),
        "{err}"
    );
    assert!(err.contains("shallow clone"), "{err}");
}

#[test]
fn symbolic_links_and_submodules_are_not_followed() {
    let p = Project::new();
    let outside = p.root.join("secret");
    write(&outside, "RTC.xml", &xml_profile("Secret", &[]));
    let repo = p.root.join("repo");
    std::fs::create_dir_all(repo.join("Linked")).unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(outside.join("RTC.xml"), repo.join("Linked/RTC.xml")).unwrap();
    // A link to a folder of profiles (named as folders are), and one to a file rtcdoc does not
    // read (not noted).
    #[cfg(unix)]
    std::os::unix::fs::symlink(&outside, repo.join("shared")).unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(outside.join("RTC.xml"), repo.join("notes.txt")).unwrap();
    let first = commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    // A submodule (a gitlink: a folder of another repository at a commit), named as folders
    // are, without an extension.
    git(
        &repo,
        &[
            "update-index",
            "--add",
            "--cacheinfo",
            &format!("160000,{first},vendor/sub"),
        ],
    );
    git(&repo, &["commit", "-q", "-m", "submodule"]);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    let (code, err) = p.run(&["build", "-f", "json", "-v"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(p.component_names(), ["repo/A/RTC.xml"]);
    assert!(
        err.contains(
            "repo/Linked/RTC.xml: info[RTC015]: a symbolic link in the repository; not followed"
        ),
        "{err}"
    );
    assert!(
        err.contains("repo/vendor/sub: info[RTC015]: a submodule; its files are not read"),
        "{err}"
    );
    assert!(
        err.contains("repo/shared: info[RTC015]: a symbolic link without an extension (it may stand for a folder); not followed, nothing behind it is read"),
        "{err}"
    );
    assert!(!err.contains("notes.txt"), "{err}");
}

#[test]
fn the_same_component_id_in_two_sources_names_both_and_keeps_both() {
    let p = Project::new();
    let a = p.root.join("a");
    let b = p.root.join("b");
    commit(&a, &[("X/RTC.xml", xml_profile("Same", &[]))], None);
    commit(&b, &[("Y/RTC.xml", xml_profile("Same", &[]))], None);
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\n\n[[source]]\ngit = \"{}\"\n",
        url(&a),
        url(&b)
    ));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(p.component_names(), ["a/X/RTC.xml", "b/Y/RTC.xml"]);
    assert!(
        err.contains("a/X/RTC.xml:2:1: warning[RTC014]: component id `RTC:Test:Cat:Same:1.0.0` of source `a` (`a/X/RTC.xml`) is also declared by source `b` (`b/Y/RTC.xml`)"),
        "{err}"
    );
    assert!(!err.contains("RTC010"), "{err}");
}

/// A component copied into many sources: each finding names three of the others and counts
/// the rest (it named every other, so the findings grew with the square of the copies).
#[test]
fn a_component_id_in_many_sources_names_a_few_of_the_others() {
    let p = Project::new();
    let mut config = String::new();
    for n in ["a", "b", "c", "d", "e", "f"] {
        let repo = p.root.join(n);
        commit(&repo, &[("X/RTC.xml", xml_profile("Same", &[]))], None);
        config.push_str(&format!("[[source]]\ngit = \"{}\"\n\n", url(&repo)));
    }
    p.config(&config);
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("a/X/RTC.xml:2:1: warning[RTC014]: component id `RTC:Test:Cat:Same:1.0.0` of source `a` (`a/X/RTC.xml`) is also declared by source `b` (`b/X/RTC.xml`), source `c` (`c/X/RTC.xml`), source `d` (`d/X/RTC.xml`) and 2 more"),
        "{err}"
    );
    assert!(
        err.contains("f/X/RTC.xml:2:1: warning[RTC014]: component id `RTC:Test:Cat:Same:1.0.0` of source `f` (`f/X/RTC.xml`) is also declared by source `a` (`a/X/RTC.xml`), source `b` (`b/X/RTC.xml`), source `c` (`c/X/RTC.xml`) and 2 more"),
        "{err}"
    );
    assert_eq!(err.matches("warning[RTC014]").count(), 6, "{err}");
}

#[test]
fn diff_compares_a_source_at_two_revs() {
    let p = Project::new();
    let repo = p.root.join("repo");
    commit(
        &repo,
        &[(
            "A/RTC.xml",
            xml_profile("A", &[("DataOutPort", "out", "RTC::TimedLong")]),
        )],
        Some("v1"),
    );
    commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    let o = rtcdoc(
        &["diff", "repo@v1", "repo@main", "--cache-dir", &p.cache],
        &p.proj,
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(out.contains("breaking[DIFF102] dataPorts/out"), "{out}");
    assert!(out.contains("--> repo/A/RTC.xml:"), "{out}");
    // The locked commit (written by this first use) against itself: no change.
    let o = rtcdoc(
        &["diff", "repo", "repo@main", "--cache-dir", &p.cache],
        &p.proj,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = rtcdoc(
        &["diff", "repo@v7", "repo", "--cache-dir", &p.cache],
        &p.proj,
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        err.contains("source `repo`: no branch, tag or commit `v7`"),
        "{err}"
    );
}

/// What's new names each change's `[[source]]` and offers the sources as a filter; the search
/// index and the component pages say the same source.
#[test]
fn whats_new_filters_by_source() {
    let p = Project::new();
    let nav = p.root.join("nav");
    commit(
        &nav,
        &[("Planner/RTC.xml", xml_profile("Planner", &[]))],
        None,
    );
    commit(
        &nav,
        &[(
            "Planner/RTC.xml",
            xml_profile("Planner", &[("DataInPort", "goal", "RTC::TimedPose2D")]),
        )],
        None,
    );
    let cam = p.root.join("cam");
    commit(
        &cam,
        &[("Camera/RTC.xml", xml_profile("Camera", &[]))],
        None,
    );
    commit(
        &cam,
        &[(
            "Camera/RTC.xml",
            xml_profile("Camera", &[("DataOutPort", "image", "RTC::CameraImage")]),
        )],
        None,
    );
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\nname = \"nav\"\n\n[[source]]\ngit = \"{}\"\nname = \"camera\"\n",
        url(&nav),
        url(&cam)
    ));
    let (code, err) = p.run(&["build", "-f", "html"]);
    assert_eq!(code, 0, "{err}");
    let page = common::read_page(&p.proj.join("site/whats-new.html"));
    // The filter lists both sources, and each change's row carries its own.
    assert!(page.contains("<select id=\"f-nsource\">"), "{page}");
    for s in ["nav", "camera"] {
        assert!(
            page.contains(&format!("<option value=\"{s}\">{s}</option>")),
            "{page}"
        );
    }
    let row = |port: &str| -> String {
        let at = page.find(&format!("dataPorts/{port}")).expect(port);
        let start = page[..at].rfind("<tr ").unwrap();
        page[start..at].to_string()
    };
    assert!(
        row("goal").contains("data-source=\"nav\""),
        "{}",
        row("goal")
    );
    assert!(
        row("image").contains("data-source=\"camera\""),
        "{}",
        row("image")
    );
}

/// A `path` the source's commit does not have is exit 2 before anything is written: `build`,
/// `check` and `update` leave the lock as it was.
#[test]
fn a_source_path_the_commit_lacks_writes_no_lock() {
    let p = Project::new();
    let repo = p.root.join("repo");
    commit(&repo, &[("A/RTC.xml", xml_profile("A", &[]))], None);
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    let good = p.lock();
    p.config(&format!(
        "[[source]]\ngit = \"{0}\"\n\n[[source]]\nname = \"bad\"\ngit = \"{0}\"\npath = \"NoSuchDir\"\n",
        url(&repo)
    ));
    for args in [&["build", "-f", "json"][..], &["check"], &["update"]] {
        let (code, err) = p.run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains("no folder `NoSuchDir`"), "{args:?}: {err}");
        assert_eq!(p.lock(), good, "{args:?} wrote the lock");
    }
}

/// A quoted include is looked for in the including file's folder and its own source, then on
/// the IDL path, as the source's own build (a C preprocessor with `-I` folders) looks for it:
/// another source's copy of `BasicDataType.idl` is not on that path. It satisfied the include
/// silently; now the include is not resolved and the warning names both files.
#[test]
fn an_include_is_not_satisfied_by_another_sources_copy() {
    let p = Project::new();
    let basic = "#ifndef BASIC_IDL\n#define BASIC_IDL\nmodule RTC { struct Time { long sec; }; };\n#endif\n";
    let lab_a = p.root.join("labA");
    commit(
        &lab_a,
        &[
            ("Cam/RTC.xml", xml_profile("Cam", &[])),
            (
                "Cam/idl/Cam.idl",
                "#include \"BasicDataType.idl\"\nmodule Cam { struct Frame { RTC::Time tm; }; };\n"
                    .to_string(),
            ),
        ],
        None,
    );
    let lab_b = p.root.join("labB");
    commit(
        &lab_b,
        &[
            ("Arm/RTC.xml", xml_profile("Arm", &[])),
            ("Arm/idl/BasicDataType.idl", basic.to_string()),
        ],
        None,
    );
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\n\n[[source]]\ngit = \"{}\"\n",
        url(&lab_a),
        url(&lab_b)
    ));
    let includes = |extra: &[&str]| -> Vec<serde_json::Value> {
        let mut args = vec!["check", "--format", "json", "--cache-dir", &p.cache];
        args.extend(extra);
        let o = rtcdoc(&args, &p.proj);
        let json: serde_json::Value = serde_json::from_slice(&o.stdout)
            .unwrap_or_else(|_| panic!("{}", String::from_utf8_lossy(&o.stderr)));
        json["diagnostics"]
            .as_array()
            .expect("diagnostics")
            .iter()
            .filter(|d| d["code"] == "RTC022")
            .cloned()
            .collect()
    };
    let found = includes(&[]);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!(found[0]["file"], "labA/Cam/idl/Cam.idl");
    assert_eq!(found[0]["severity"], "warning");
    let message = found[0]["message"].as_str().unwrap_or_default();
    assert!(
        message.contains("not found in the source `labA` or on the IDL path; the source `labB` has `labB/Arm/idl/BasicDataType.idl`, which is not used"),
        "{message}"
    );
    // OpenRTM's IDL on the IDL path satisfies it, for every source.
    write(&p.root, "openrtm/idl/BasicDataType.idl", basic);
    let idl_path = p.root.join("openrtm/idl").display().to_string();
    let found = includes(&["--idl-path", &idl_path]);
    assert!(found.is_empty(), "{found:#?}");
}

/// The code of a `[[source]]` repository is read at its pinned commit as on disk: the
/// implementation beside a profile (its drift found), and a component with code and no
/// profile (recovered).
#[test]
fn a_sources_code_is_read_at_its_commit() {
    let p = Project::new();
    let repo = p.root.join("lab");
    let fixtures = root().join("tests/fixtures/implementation");
    let read = |rel: &str| std::fs::read_to_string(fixtures.join(rel)).unwrap();
    commit(
        &repo,
        &[
            ("Sensor/RTC.xml", read("python-edited/RTC.xml")),
            ("Sensor/SensorGUI.py", read("python-edited/SensorGUI.py")),
            (
                "Gripper/src/Gripper.cpp",
                read("recovered/Gripper/src/Gripper.cpp"),
            ),
            (
                "Gripper/include/Gripper/Gripper.h",
                read("recovered/Gripper/include/Gripper/Gripper.h"),
            ),
            ("tools/plot.py", "print('not a component')\n".to_string()),
        ],
        None,
    );
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    let (code, err) = p.run(&["build", "-f", "json"]);
    assert_eq!(code, 0, "{err}");
    let c = p.catalog();
    let comps = c["components"].as_object().unwrap();
    let sensor = comps
        .values()
        .find(|c| c["source"] == "lab/Sensor/RTC.xml")
        .expect("the profile");
    assert_eq!(
        sensor["implementation"]["files"],
        serde_json::json!(["lab/Sensor/SensorGUI.py"])
    );
    assert!(!sensor["implementation"]["drift"]
        .as_array()
        .unwrap()
        .is_empty());
    let gripper = comps
        .values()
        .find(|c| c["source"] == "lab/Gripper/src/Gripper.cpp")
        .expect("the component recovered from its code");
    assert_eq!(
        gripper["recovered"]["unread"][0]["written"],
        "GRIPPER_VERSION"
    );
    // The header was read with it: the ports have their types.
    assert_eq!(gripper["dataPorts"][0]["type"], "RTC::TimedLong");
    let (_, err) = p.run(&["check", "--format", "human"]);
    assert!(err.contains("RTC801") && err.contains("RTC802"), "{err}");
}

/// Every file below `dir`, by its path relative to `dir`.
fn tree(dir: &Path) -> std::collections::BTreeMap<String, Vec<u8>> {
    let mut out = std::collections::BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().display().to_string();
                out.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    out
}

#[test]
fn jobs_change_nothing_of_the_output_or_the_lock() {
    let p = Project::new();
    let mut config = String::new();
    for i in 0..6 {
        let r = p.root.join(format!("r{i}"));
        commit(
            &r,
            &[
                (&format!("C{i}/RTC.xml"), xml_profile(&format!("C{i}"), &[])),
                ("Extra/RTC.xml", xml_profile(&format!("Extra{i}"), &[])),
            ],
            None,
        );
        config.push_str(&format!("[[source]]\ngit = \"{}\"\n\n", url(&r)));
    }
    // Two sources of one repository share its mirror (fetched one after the other).
    let r0 = url(&p.root.join("r0"));
    config.push_str(&format!(
        "[[source]]\ngit = \"{r0}\"\nname = \"again\"\npath = \"Extra\"\n"
    ));
    p.config(&config);
    let mut sites = Vec::new();
    for jobs in ["1", "4"] {
        let _ = std::fs::remove_dir_all(&p.cache);
        let _ = std::fs::remove_file(p.proj.join("rtcdoc.lock"));
        let site = format!("site{jobs}");
        let (code, err) = p.run(&["build", "-q", "-j", jobs, "-o", &site]);
        assert_eq!(code, 0, "{err}");
        let lock = p.lock();
        assert_eq!(lock.matches("\n[[source]]\n").count(), 7, "{lock}");
        // Warm: the same from the cache and the lock.
        let (code, err) = p.run(&["build", "-q", "--jobs", jobs, "-o", &site]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(p.lock(), lock);
        sites.push((lock, tree(&p.proj.join(&site))));
    }
    assert!(sites[0].1.len() > 5, "{:?}", sites[0].1.keys());
    assert_eq!(sites[0].0, sites[1].0, "the lock depends on --jobs");
    assert_eq!(
        sites[0].1.keys().collect::<Vec<_>>(),
        sites[1].1.keys().collect::<Vec<_>>()
    );
    for (k, v) in &sites[0].1 {
        assert!(sites[1].1[k] == *v, "{k} differs between -j1 and -j4");
    }
    let (code, err) = p.run(&["build", "-q", "-j", "0"]);
    assert_eq!(code, 2, "{err}");
}

/// `rtcdoc ARGS --cache-dir CACHE` in the project, with `PATH` starting with `bin` (a `git`
/// there stands for the real one).
#[cfg(unix)]
fn run_with_path(p: &Project, bin: &Path, args: &[&str]) -> (i32, String) {
    run_with_path_and_cache(p, bin, args, &p.cache)
}

/// [`run_with_path`] with `--cache-dir cache` (relative to the project, say).
#[cfg(unix)]
fn run_with_path_and_cache(p: &Project, bin: &Path, args: &[&str], cache: &str) -> (i32, String) {
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--cache-dir", cache]);
    let o = Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(&all)
        .current_dir(&p.proj)
        .env("NO_COLOR", "1")
        .env("GIT_CEILING_DIRECTORIES", &p.root)
        .env("PATH", path)
        .output_within(common::COMMAND_LIMIT)
        .expect("run rtcdoc");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// A folder with a `git` that records its arguments in `log` and then runs the real git.
#[cfg(unix)]
fn counting_git(root: &Path, log: &Path) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let real = String::from_utf8(
        Command::new("sh")
            .args(["-c", "command -v git"])
            .output()
            .unwrap()
            .stdout,
    )
    .unwrap();
    let bin = root.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let script = bin.join("git");
    std::fs::write(
        &script,
        format!(
            "#!/bin/sh\necho \"$*\" >> '{}'\nexec '{}' \"$@\"\n",
            log.display(),
            real.trim()
        ),
    )
    .unwrap();
    std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    bin
}

/// The git commands of `log` (one a line) that read a mirror of the cache.
#[cfg(unix)]
fn cache_commands(p: &Project, log: &Path) -> Vec<String> {
    std::fs::read_to_string(log)
        .unwrap_or_default()
        .lines()
        .filter(|l| l.contains(&p.cache))
        .map(str::to_string)
        .collect()
}

#[test]
#[cfg(unix)]
fn a_warm_build_runs_no_git_on_the_cache_and_a_damaged_entry_is_read_again() {
    let p = Project::new();
    let (nav, _, cam, _) = two_repos(&p);
    // A second commit of a profile: a history of two versions.
    commit(
        &cam,
        &[(
            "Camera/RTC.xml",
            xml_profile("Camera", &[("DataInPort", "in", "RTC::TimedLong")]),
        )],
        None,
    );
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\npath = \"comps\"\n\n[[source]]\ngit = \"{}\"\n",
        url(&nav),
        url(&cam)
    ));
    let log = p.root.join("git.log");
    let bin = counting_git(&p.root, &log);
    let (code, err) = run_with_path(&p, &bin, &["build", "-q", "-o", "cold"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        !cache_commands(&p, &log).is_empty(),
        "the cold build reads the mirrors"
    );
    let cold = tree(&p.proj.join("cold"));
    let _ = std::fs::remove_file(&log);
    let (code, err) = run_with_path(&p, &bin, &["build", "-q", "-o", "warm"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(cache_commands(&p, &log), Vec::<String>::new());
    assert!(cold == tree(&p.proj.join("warm")), "the warm site differs");
    // Every kept answer damaged (cut, or a byte flipped): not trusted, read from git again,
    // the same site, and kept whole again.
    let mut damaged = 0;
    for m in std::fs::read_dir(&p.cache).unwrap() {
        let kept = m.unwrap().path().join("rtcdoc");
        for kind in ["files", "answers", "blobs", "pinned"] {
            for f in std::fs::read_dir(kept.join(kind)).into_iter().flatten() {
                let f = f.unwrap().path();
                let mut bytes = std::fs::read(&f).unwrap();
                if damaged % 2 == 0 {
                    bytes.truncate(bytes.len() / 2);
                } else if let Some(b) = bytes.get_mut(20) {
                    *b ^= 0x20;
                }
                std::fs::write(&f, bytes).unwrap();
                damaged += 1;
            }
        }
    }
    assert!(damaged >= 4, "{damaged} entries");
    let _ = std::fs::remove_file(&log);
    let (code, err) = run_with_path(&p, &bin, &["build", "-q", "-o", "again"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        !cache_commands(&p, &log).is_empty(),
        "damaged entries are read again"
    );
    assert!(
        cold == tree(&p.proj.join("again")),
        "a damaged entry changed the site"
    );
    let _ = std::fs::remove_file(&log);
    let (code, err) = run_with_path(&p, &bin, &["build", "-q", "-o", "warm2"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(cache_commands(&p, &log), Vec::<String>::new());
    // The same cache named another way (relative to the project): the same answers.
    let (code, err) = run_with_path_and_cache(&p, &bin, &["build", "-q", "-o", "rel"], "../cache");
    assert_eq!(code, 0, "{err}");
    let lines = std::fs::read_to_string(&log).unwrap_or_default();
    assert!(!lines.contains("--git-dir"), "{lines}");
    // A setting that changes what is read (the size limit) is read from git again.
    let (code, err) = run_with_path(
        &p,
        &bin,
        &["build", "-q", "-o", "small", "--max-file-size", "100"],
    );
    assert_ne!(
        cache_commands(&p, &log),
        Vec::<String>::new(),
        "{code} {err}"
    );
    // No git at all on the PATH: the warm build needs none.
    let empty = p.root.join("nogit");
    std::fs::create_dir_all(&empty).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args([
            "build",
            "-q",
            "-o",
            "nogit",
            "--offline",
            "--cache-dir",
            &p.cache,
        ])
        .current_dir(&p.proj)
        .env("NO_COLOR", "1")
        .env("PATH", &empty)
        .output_within(common::COMMAND_LIMIT)
        .expect("run rtcdoc");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        cold == tree(&p.proj.join("nogit")),
        "the site without git differs"
    );
}

#[test]
fn a_tree_deeper_than_the_walk_reads_is_named() {
    let p = Project::new();
    let repo = p.root.join("deep");
    let deep = vec!["d"; 258].join("/");
    commit(
        &repo,
        &[
            ("A/RTC.xml", xml_profile("A", &[])),
            (&format!("{deep}/RTC.xml"), xml_profile("Deep", &[])),
        ],
        None,
    );
    p.config(&format!("[[source]]\ngit = \"{}\"\n", url(&repo)));
    let (code, err) = p.run(&["build", "-q"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("source `deep`"), "{err}");
    assert!(err.contains("deeper than 256 levels"), "{err}");
    assert!(!p.proj.join("rtcdoc.lock").exists(), "a lock was written");
    // Its folder of profiles as `path`: read.
    p.config(&format!(
        "[[source]]\ngit = \"{}\"\npath = \"A\"\n",
        url(&repo)
    ));
    let (code, err) = p.run(&["build", "-q"]);
    assert_eq!(code, 0, "{err}");
}
