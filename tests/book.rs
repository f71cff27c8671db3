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

/// The rule table and each rule's section of `book/src/check.md` say what the registry says
/// (`RTCDOC_BLESS=1` rewrites them from the registry).
#[test]
fn check_guide_matches_the_rule_registry() {
    let path = root().join("book/src/check.md");
    let mut text = std::fs::read_to_string(&path).unwrap();
    let cap = |s: &str| {
        let mut c = s.chars();
        c.next()
            .map(|f| f.to_uppercase().collect::<String>() + c.as_str())
            .unwrap_or_default()
    };
    let mut missing = Vec::new();
    for r in rtcdoc::check::RULES {
        let sev = r.severity.to_string();
        let row = format!(
            "| [{code}](#{lower}) | {sev} | `{name}` | {summary} |",
            code = r.code,
            lower = r.code.to_lowercase(),
            name = r.name,
            summary = r.summary
        );
        let section = format!(
            "### {code}\n\n**{name}** — {sev}. {summary}.\n\n{expl}\n\n*Spec:* {spec}\n\n*Fix:* {hint}.\n",
            code = r.code,
            name = r.name,
            summary = cap(r.summary),
            expl = r.explanation,
            spec = r.spec,
            hint = r.hint
        );
        for (what, want, start) in [
            ("row", row, format!("| [{}](#", r.code)),
            ("section", section, format!("### {}\n", r.code)),
        ] {
            if text.contains(&want) {
                continue;
            }
            if std::env::var_os("RTCDOC_BLESS").is_some() {
                if let Some(at) = text.find(&start) {
                    // Replace up to the end of the row / the `*Fix:*` line.
                    let end_marker = if what == "row" { "\n" } else { "*Fix:*" };
                    let from = at + text[at..].find(end_marker).unwrap_or(0);
                    let end = from + text[from..].find('\n').map_or(0, |i| i + 1);
                    text.replace_range(at..end, &want);
                    if what == "row" {
                        text.insert(at + want.len(), '\n');
                    }
                    continue;
                }
            }
            missing.push(format!("{} {what}:\n{want}", r.code));
        }
    }
    if std::env::var_os("RTCDOC_BLESS").is_some() {
        std::fs::write(&path, &text).unwrap();
    }
    assert!(
        missing.is_empty(),
        "check.md is out of date:\n{}",
        missing.join("\n")
    );
}
