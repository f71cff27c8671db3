//! The command line around the core: init, configuration, completions, man page.

use crate::common;
use common::OutputWithin;
use common::*;
use std::path::Path;

#[test]
fn init_writes_a_commented_config_and_refuses_to_overwrite() {
    let dir = tempfile::tempdir().unwrap();
    let out = rtcdoc(&["init", "proj"], dir.path());
    assert!(out.status.success());
    let text = std::fs::read_to_string(dir.path().join("proj/rtcdoc.toml")).unwrap();
    assert!(text.contains("# title = "));
    assert!(text.contains("# max-file-size = "));
    let again = rtcdoc(&["init", "proj"], dir.path());
    assert_eq!(again.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&again.stderr).contains("already exists"));
    assert!(rtcdoc(&["init", "proj", "--force"], dir.path())
        .status
        .success());
}

/// `rtcdoc init --language ja` starts a Japanese project: Japanese comments, `language = "ja"`
/// set, the same keys as the English file; `--language en` is the English file, unchanged.
#[test]
fn init_language_ja_writes_japanese_comments_and_sets_the_language() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let empty = d.join("no-openrtm");
    for (args, name) in [
        (&["init", "en"][..], "en"),
        (&["init", "en-flag", "--language", "en"][..], "en-flag"),
        (&["init", "ja", "--language", "ja"][..], "ja"),
    ] {
        let out = init_with_prefixes(args, d, &empty);
        assert!(out.status.success(), "{args:?}: {out:?}");
        // Messages stay English.
        assert!(
            String::from_utf8_lossy(&out.stderr).starts_with("wrote "),
            "{name}"
        );
    }
    let read = |name: &str| std::fs::read_to_string(d.join(name).join("rtcdoc.toml")).unwrap();
    let (en, en_flag, ja) = (read("en"), read("en-flag"), read("ja"));
    assert_eq!(en, rtcdoc::config::template());
    assert_eq!(en_flag, en);
    assert!(ja.contains("# rtcdoc の設定ファイル。"), "{ja}");
    assert!(ja.lines().any(|l| l == "language = \"ja\""), "{ja}");
    assert!(!ja.contains("Title of the catalogue"), "{ja}");
    // Every key of the English file, commented or not, is in the Japanese one.
    let keys = |t: &str| -> Vec<String> {
        t.lines()
            .map(|l| l.strip_prefix("# ").unwrap_or(l))
            .filter_map(|l| l.split_once(" = ").map(|(k, _)| k.to_string()))
            .filter(|k| !k.contains(' '))
            .collect()
    };
    assert_eq!(keys(&ja), keys(&en));
    assert!(!keys(&en).is_empty());
    // It is a valid configuration: a build in the folder labels its pages in Japanese.
    write(&d.join("ja"), "Cam/RTC.xml", &xml_profile("Cam", &[]));
    let out = rtcdoc(&["build", "ja", "-o", "site", "-q"], d);
    assert!(out.status.success(), "{out:?}");
    let index = std::fs::read_to_string(d.join("site/index.html")).unwrap();
    assert!(index.contains("<html lang=\"ja\""), "{index}");
    // An unknown language is a usage error.
    let bad = rtcdoc(&["init", "fr", "--language", "fr"], d);
    assert_eq!(bad.status.code(), Some(2));
}

/// `rtcdoc init` with the OpenRTM search confined to `prefixes` (and no OpenRTM variables).
fn init_with_prefixes(args: &[&str], cwd: &Path, prefixes: &Path) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(args)
        .current_dir(cwd)
        .env("NO_COLOR", "1")
        .env(rtcdoc::init::PREFIXES_VAR, prefixes)
        .env_remove("RTM_ROOT")
        .env_remove("OPENRTM_DIR")
        .env_remove("OpenRTM_DIR")
        .output_within(common::COMMAND_LIMIT)
        .expect("run rtcdoc")
}

#[test]
fn init_suggests_a_detected_openrtm_idl_directory_commented_out() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A fake installation: <prefix>/include/openrtm-2.0/rtm/idl with one IDL file.
    let prefix = d.join("fake-usr");
    write(
        &prefix,
        "include/openrtm-2.0/rtm/idl/BasicDataType.idl",
        "module RTC {\n  /// A time-stamped integer.\n  struct TimedLong { /** Value */ long data; };\n};\n",
    );
    let idl_dir = prefix.join("include/openrtm-2.0/rtm/idl");
    write(
        d,
        "proj/c/RTC.xml",
        &xml_profile("C", &[("DataOutPort", "out", "RTC::TimedLong")]),
    );
    let out = init_with_prefixes(&["init", "proj"], d, &prefix);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("found OpenRTM's IDL in"), "{stderr}");
    let text = std::fs::read_to_string(d.join("proj/rtcdoc.toml")).unwrap();
    let line = format!("# idl-path = [\"{}\"]", idl_dir.display());
    assert!(text.contains(&line), "{text}");
    assert!(
        text.contains("found OpenRTM's IDL through the prefix"),
        "{text}"
    );
    // Commented out: a build does not read it ...
    let out = rtcdoc(&["build", "proj", "-f", "json", "-o", "site1", "-q"], d);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json = std::fs::read_to_string(d.join("site1/catalog.json")).unwrap();
    assert!(!json.contains("BasicDataType.idl"));
    // ... and uncommented, the path as written reads the installation's IDL.
    std::fs::write(d.join("proj/rtcdoc.toml"), text.replace(&line, &line[2..])).unwrap();
    let out = rtcdoc(&["build", "proj", "-f", "json", "-o", "site2", "-q"], d);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json = std::fs::read_to_string(d.join("site2/catalog.json")).unwrap();
    assert!(json.contains("BasicDataType.idl"), "{json}");

    // Nothing installed below the prefixes: the usual template, without the sentence; init
    // says it found nothing, and where the directory goes.
    let empty = d.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let out = init_with_prefixes(&["init", "other"], d, &empty);
    let none = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{none}");
    assert!(
        none.contains("found no OpenRTM installation's IDL")
            && none.contains("set `idl-path` in rtcdoc.toml to its rtm/idl directory"),
        "{none}"
    );
    assert!(!none.contains("found OpenRTM's IDL"), "{none}");
    let text = std::fs::read_to_string(d.join("other/rtcdoc.toml")).unwrap();
    assert_eq!(text, rtcdoc::config::template());
}

#[test]
fn config_file_is_used_and_flags_override_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "cat/a/RTC.xml", &xml_profile("A", &[]));
    write(
        d,
        "cat/rtcdoc.toml",
        "formats = [\"json\"]\noutput = \"public\"\ntitle = \"Lab catalogue\"\n",
    );
    let out = rtcdoc(&["build", "cat"], d);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json = std::fs::read_to_string(d.join("cat/public/catalog.json")).unwrap();
    assert!(json.contains("\"title\": \"Lab catalogue\""));
    // A flag wins over the file.
    let out = rtcdoc(&["build", "cat", "--title", "From flag", "-o", "other"], d);
    assert!(out.status.success());
    let json = std::fs::read_to_string(d.join("other/catalog.json")).unwrap();
    assert!(json.contains("\"title\": \"From flag\""));
}

#[test]
fn unknown_config_keys_fail_with_their_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "cat/a/RTC.xml", &xml_profile("A", &[]));
    write(d, "cat/rtcdoc.toml", "title = \"x\"\nouptut = \"y\"\n");
    let out = rtcdoc(&["build", "cat"], d);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("rtcdoc.toml:2:1"), "{err}");
    assert!(err.contains("ouptut"), "{err}");
}

#[test]
fn completions_and_man_page() {
    let dir = tempfile::tempdir().unwrap();
    for shell in ["bash", "zsh", "fish"] {
        let out = rtcdoc(&["completions", shell], dir.path());
        assert!(out.status.success());
        assert!(String::from_utf8_lossy(&out.stdout).contains("rtcdoc"));
    }
    let man = rtcdoc(&["man"], dir.path());
    assert!(man.status.success());
    let text = String::from_utf8_lossy(&man.stdout);
    assert!(text.contains(".TH rtcdoc 1"));
    // One page: every command with its own options, no pointers to pages that don't exist.
    for command in [
        "build",
        "check",
        "diff",
        "serve",
        "graph",
        "init",
        "update",
        "completions",
        "man",
    ] {
        assert!(
            text.contains(&format!(".SS \"rtcdoc {command}\"")),
            "{command}"
        );
    }
    for option in [
        "\\-\\-no\\-strict",
        "\\-\\-fail\\-on",
        "\\-\\-dataflow",
        "\\-\\-no\\-open",
    ] {
        assert!(text.contains(option), "{option}");
    }
    assert!(!text.contains("rtcdoc\\-build(1)"), "{text}");
    assert!(text.contains(".SH \"EXIT STATUS\""));
}

#[test]
fn quiet_and_verbose() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/a/RTC.xml", &xml_profile("A", &[]));
    write(d, "in/notes.txt", "hello");
    // The component's README (shown on its page) is not a skipped file.
    write(d, "in/a/README.md", "# A\n\nThe A component.\n");
    let v = rtcdoc(&["build", "in", "-f", "json", "-o", "o1", "--verbose"], d);
    let err = String::from_utf8_lossy(&v.stderr);
    // Files that cannot be profiles are counted by kind, not listed one by one.
    assert!(!err.contains("skipped notes.txt"), "{err}");
    assert!(
        err.contains("skipped 1 other file(s), not .xml/.yaml/.yml/.rtsys: 1 .txt"),
        "{err}"
    );
    assert!(err.contains("built 1 component profile into"));
    let q = rtcdoc(&["build", "in", "-f", "json", "-o", "o2", "--quiet"], d);
    assert!(q.status.success());
    assert!(
        q.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&q.stderr)
    );
    // Every command that reads a configuration names it with --verbose.
    write(d, "in/rtcdoc.toml", "title = \"T\"\n");
    write(d, "new/a/RTC.xml", &xml_profile("A", &[]));
    for args in [
        &["build", "in", "-o", "o3"][..],
        &["check", "in"],
        &["diff", "new", "in"],
        &["graph", "in", "--dataflow", "category"],
    ] {
        let v = rtcdoc(&[&["-v"][..], args].concat(), d);
        let err = String::from_utf8_lossy(&v.stderr);
        assert!(
            err.contains("configuration: in/rtcdoc.toml"),
            "{args:?}: {err}"
        );
    }
    // --quiet silences notes: an empty data-flow graph is written without its note.
    let q = rtcdoc(&["-q", "graph", "in", "--dataflow", "category"], d);
    assert!(q.status.success());
    assert!(
        q.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&q.stderr)
    );
    let loud = rtcdoc(&["graph", "in", "--dataflow", "category"], d);
    assert!(String::from_utf8_lossy(&loud.stderr).contains("note:"));
}

/// `*` in `--include`/`--exclude` stays within one folder and `**` crosses folders, as the
/// guide says; a bad pattern is named with the option it came from.
#[test]
fn a_glob_star_stays_within_one_folder() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in/old/RTC.xml", &xml_profile("Top", &[]));
    write(d, "in/old/sub/RTC.xml", &xml_profile("Deep", &[]));
    let names = |args: &[&str]| -> Vec<String> {
        let mut all = vec!["build", "in", "-f", "json", "-o", "out", "-q"];
        all.extend_from_slice(args);
        let o = rtcdoc(&all, d);
        assert!(
            o.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let cat: serde_json::Value =
            serde_json::from_slice(&std::fs::read(d.join("out/catalog.json")).unwrap()).unwrap();
        let mut n: Vec<String> = cat["components"]
            .as_object()
            .unwrap()
            .values()
            .map(|c| c["source"].as_str().unwrap().to_string())
            .collect();
        n.sort();
        n
    };
    assert_eq!(names(&["--exclude", "old/*.xml"]), ["old/sub/RTC.xml"]);
    assert_eq!(
        names(&["--exclude", "old/**/*.xml", "--allow-empty"]),
        Vec::<String>::new()
    );
    assert_eq!(names(&["--include", "*/RTC.xml"]), ["old/RTC.xml"]);
    assert_eq!(
        names(&["--include", "**/RTC.xml"]),
        ["old/RTC.xml", "old/sub/RTC.xml"]
    );
    for option in ["--include", "--exclude"] {
        let o = rtcdoc(&["check", "in", option, "["], d);
        assert_eq!(o.status.code(), Some(2));
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(
            e.contains(&format!("invalid {} pattern `[`", &option[2..])),
            "{option}: {e}"
        );
    }
}

/// The tests' deadline on the commands they run works: a command that does not end within its
/// limit is killed and fails its test, naming the command, instead of stalling `cargo test`.
#[test]
#[should_panic(expected = "did not end within 1 s and was killed")]
fn a_command_that_hangs_fails_its_test() {
    let _ = std::process::Command::new("sleep")
        .arg("30")
        .output_within(std::time::Duration::from_secs(1));
}

/// `-f` names the output format of every command that has one, as `build -f json` does: a
/// newcomer's `rtcdoc check -f json` and `rtcdoc diff A B -f json` were refused before.
#[test]
fn f_is_the_format_of_check_and_diff_too() {
    let examples = root().join("examples");
    let out = rtcdoc(&["check", "examples", "-f", "json"], &root());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    assert!(json["diagnostics"].is_array(), "{json}");
    let e = examples.to_str().unwrap();
    let out = rtcdoc(&["diff", e, e, "-f", "json"], &root());
    assert_eq!(out.status.code(), Some(0));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["summary"]["breaking"], 0, "{json}");
}
