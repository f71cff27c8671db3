//! The user guide: builds with the real mdbook without warnings, and documents every command and
//! rule the binary has.

mod common;
use common::*;

#[test]
fn guide_builds_with_mdbook_without_warnings() {
    if std::process::Command::new("mdbook")
        .arg("--version")
        .output()
        .is_err()
    {
        println!("skipped: mdbook not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = std::process::Command::new("mdbook")
        .arg("build")
        .arg(root().join("book"))
        .arg("-d")
        .arg(dir.path())
        .output()
        .unwrap();
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{log}");
    assert!(!log.contains("WARN") && !log.contains("ERROR"), "{log}");
    for page in [
        "index.html",
        "cli.html",
        "configuration.html",
        "themes.html",
        "formats.html",
        "json.html",
        "check.html",
        "ci.html",
        "serve.html",
        "faq.html",
        "performance.html",
    ] {
        assert!(dir.path().join(page).exists(), "{page}");
    }
    assert!(dir.path().join("images/component-page.png").exists());
    if let Some(tool) = shared_tool("linkcheck.py") {
        let r = std::process::Command::new("python3")
            .arg(tool)
            .arg(dir.path())
            .output()
            .unwrap();
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stdout));
    }
}

#[test]
fn guide_documents_every_command_and_rule() {
    let cli = std::fs::read_to_string(root().join("book/src/cli.md")).unwrap();
    for cmd in [
        "rtcdoc build",
        "rtcdoc check",
        "rtcdoc serve",
        "rtcdoc init",
        "rtcdoc completions",
        "rtcdoc man",
    ] {
        assert!(cli.contains(cmd), "cli.md lacks {cmd}");
    }
    let check = std::fs::read_to_string(root().join("book/src/check.md")).unwrap();
    for rule in rtcdoc::check::RULES {
        assert!(check.contains(rule.code), "check.md lacks {}", rule.code);
    }
    let config = std::fs::read_to_string(root().join("book/src/configuration.md")).unwrap();
    for line in rtcdoc::config::template().lines() {
        if let Some(key) = line
            .strip_prefix("# ")
            .and_then(|l| l.split_once(" = "))
            .map(|(k, _)| k)
        {
            if !key.contains(' ') {
                assert!(config.contains(key), "configuration.md lacks {key}");
            }
        }
    }
}
