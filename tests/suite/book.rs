//! The user guide: builds with the real mdbook without warnings, and documents every command and
//! rule the binary has.

use crate::common;
use common::OutputWithin;
use common::*;

#[test]
fn guide_builds_with_mdbook_without_warnings() {
    if std::process::Command::new("mdbook")
        .arg("--version")
        .output_within(common::COMMAND_LIMIT)
        .is_err()
    {
        crate::common::missing_tool("mdbook not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let out = std::process::Command::new("mdbook")
        .arg("build")
        .arg(root().join("book"))
        .arg("-d")
        .arg(dir.path())
        .output_within(common::COMMAND_LIMIT)
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
    // The English introduction links the Japanese guide, published beside it at `ja/`
    // (tests/suite/book_ja.rs checks that book itself).
    let ja = std::process::Command::new("mdbook")
        .arg("build")
        .arg(root().join("book/ja"))
        .arg("-d")
        .arg(dir.path().join("ja"))
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(
        ja.status.success(),
        "{}",
        String::from_utf8_lossy(&ja.stderr)
    );
    if let Some(tool) = shared_tool("linkcheck.py") {
        let r = std::process::Command::new("python3")
            .arg(tool)
            .arg(dir.path())
            .output_within(common::COMMAND_LIMIT)
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
        "rtcdoc diff",
        "rtcdoc serve",
        "rtcdoc graph",
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

/// Text between `<` and `>` outside code is an HTML tag to every CommonMark renderer: mdBook
/// 0.4 drops unknown ones silently ("the id is not RTC::::"), 0.5 warns. The guide writes such
/// text in code spans; this finds any that is not, whatever mdBook version is installed.
#[test]
fn guide_has_no_raw_angle_bracket_text() {
    // Tags the guide means as HTML.
    const HTML: &[&str] = &["br", "kbd", "img", "a", "details", "summary", "sup", "sub"];
    let mut bad = Vec::new();
    for entry in std::fs::read_dir(root().join("book/src")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("md") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let mut fenced = false;
        for (n, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
                continue;
            }
            if fenced || line.starts_with("    ") {
                continue;
            }
            for tag in raw_tags(line) {
                let name = tag.trim_start_matches('/');
                if !HTML.contains(&name.to_ascii_lowercase().as_str()) {
                    bad.push(format!("{}:{}: <{tag}>", path.display(), n + 1));
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "raw <…> text outside code:\n{}",
        bad.join("\n")
    );
}

/// Names of `<name …>` / `</name>` outside code spans and autolinks (`<https://…>`).
fn raw_tags(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_code = false;
    let b = line.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'`' => in_code = !in_code,
            b'\\' => i += 1,
            b'<' if !in_code => {
                let rest = &line[i + 1..];
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '/' || *c == '-')
                    .collect();
                let after = rest[name.len()..].chars().next();
                let autolink =
                    rest.starts_with("http") || rest.contains('@') && !rest.contains(' ');
                if !name.trim_start_matches('/').is_empty()
                    && matches!(after, Some('>' | ' ' | '/'))
                    && !autolink
                {
                    out.push(name);
                }
            }
            _ => {}
        }
        i += 1;
    }
    out
}

#[test]
fn raw_tag_finder_finds_what_mdbook_would_take_for_html() {
    assert_eq!(
        raw_tags("the id is not RTC:<vendor>:<name>"),
        ["vendor", "name"]
    );
    assert_eq!(
        raw_tags("`RTC:<vendor>` and <https://rustup.rs>"),
        Vec::<String>::new()
    );
    assert_eq!(raw_tags("a <br> b </t>"), ["br", "/t"]);
    assert_eq!(raw_tags("x < y and y > z, \\<v>"), Vec::<String>::new());
}

/// The long flags `rtcdoc SUBCOMMAND --help` lists.
fn help_flags(sub: &str) -> Vec<String> {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args([sub, "--help"])
        .output_within(common::COMMAND_LIMIT)
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    let mut flags: Vec<String> = text
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| w.starts_with("--") && w.len() > 2)
        .map(str::to_string)
        .filter(|f| f != "--help" && f != "--version")
        .collect();
    flags.sort();
    flags.dedup();
    flags
}

/// `--help`, the command-line page of the guide and the README name the same flags.
#[test]
fn help_guide_and_readme_name_the_same_flags() {
    let cli = std::fs::read_to_string(root().join("book/src/cli.md")).unwrap();
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    for sub in [
        "build", "check", "diff", "serve", "graph", "init", "extract",
    ] {
        let flags = help_flags(sub);
        assert!(!flags.is_empty(), "{sub}");
        for f in &flags {
            assert!(
                cli.contains(f.as_str()),
                "cli.md does not mention `{sub} {f}`"
            );
            if sub != "init" {
                assert!(
                    readme.contains(f.as_str()),
                    "README does not mention `{sub} {f}`"
                );
            }
        }
    }
    // serve takes no output options: the guide says so, and --help does not offer them.
    let serve = help_flags("serve");
    for f in ["--output", "--format", "--strict"] {
        assert!(!serve.iter().any(|s| s == f), "serve offers {f}");
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

/// The code table and each code's section of `book/src/diff.md` say what the change registry
/// says (`RTCDOC_BLESS=1` rewrites them from the registry); SUMMARY.md links the page.
#[test]
fn diff_guide_matches_the_code_registry() {
    let path = root().join("book/src/diff.md");
    let text = std::fs::read_to_string(&path).unwrap();
    let mut block = String::from(
        "<!-- codes:begin -->\n| Code | Severity | Name | Summary |\n|---|---|---|---|\n",
    );
    for c in rtcdoc::diff::CODES {
        block.push_str(&format!(
            "| [{code}](#{lower}) | {level} | `{name}` | {summary} |\n",
            code = c.code,
            lower = c.code.to_lowercase(),
            level = c.level,
            name = c.name,
            summary = c.summary
        ));
    }
    for c in rtcdoc::diff::CODES {
        block.push_str(&format!(
            "\n### {code}\n\n**{name}** — {level}. {summary}.\n\n{expl}\n",
            code = c.code,
            name = c.name,
            level = c.level,
            summary = c.summary,
            expl = c.explanation
        ));
    }
    block.push_str("<!-- codes:end -->");
    let start = text
        .find("<!-- codes:begin -->")
        .expect("codes:begin marker");
    let end =
        text.find("<!-- codes:end -->").expect("codes:end marker") + "<!-- codes:end -->".len();
    if std::env::var_os("RTCDOC_BLESS").is_some() {
        let new = format!("{}{block}{}", &text[..start], &text[end..]);
        std::fs::write(&path, new).unwrap();
    } else {
        assert_eq!(
            &text[start..end],
            block,
            "book/src/diff.md is out of date: run RTCDOC_BLESS=1 cargo test --test suite book::"
        );
    }
    let summary = std::fs::read_to_string(root().join("book/src/SUMMARY.md")).unwrap();
    assert!(summary.contains("(diff.md)"), "SUMMARY.md links diff.md");
}
