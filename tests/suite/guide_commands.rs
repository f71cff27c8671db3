//! The guide is true: every `rtcdoc` command its code blocks show runs as written (in a
//! workspace holding the paths the guide names, each a copy of the example catalogue), and the
//! claims of the quick start hold for the example.

use crate::common;
use common::*;
use std::path::Path;

/// The shell words of a command line (single and double quotes; no expansion).
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quote: Option<char> = None;
    let mut any = false;
    for ch in line.chars() {
        match (quote, ch) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => cur.push(c),
            (None, '\'' | '"') => {
                quote = Some(ch);
                any = true;
            }
            (None, c) if c.is_whitespace() => {
                if any || !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
                any = false;
            }
            (None, c) => cur.push(c),
        }
    }
    if any || !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// A command of the guide: (page, line, words).
type Command = (String, String, Vec<String>);

/// Every `rtcdoc …` command of the guide's code blocks that can run here, by code block (a
/// block's commands run in order in one workspace, as a reader types them). A redirection, pipe
/// or `||` ends the command; comments are dropped. Lines with placeholders (`DIR`, `OLD`, `…`,
/// `$VARIABLE`) and `serve` (which runs until stopped) are left out.
fn blocks() -> Vec<Vec<Command>> {
    let mut out: Vec<Vec<Command>> = Vec::new();
    let mut pages: Vec<_> = std::fs::read_dir(root().join("book/src"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    for page in pages {
        let text = std::fs::read_to_string(&page).unwrap();
        let name = page.file_name().unwrap().to_string_lossy().into_owned();
        let mut in_block = false;
        for line in text.lines() {
            if line.trim_start().starts_with("```") {
                in_block = !in_block;
                if in_block {
                    out.push(Vec::new());
                }
                continue;
            }
            if !in_block {
                continue;
            }
            let mut l = line.trim();
            for prefix in ["$ ", "- run: ", "run: ", "- "] {
                l = l.strip_prefix(prefix).unwrap_or(l);
            }
            let l = l
                .strip_prefix("cargo run --release -- ")
                .map(|rest| format!("rtcdoc {rest}"))
                .unwrap_or_else(|| l.to_string());
            if !l.starts_with("rtcdoc ") {
                continue;
            }
            let cut = [" >", " |", " &&", "  #", " # "]
                .iter()
                .filter_map(|s| l.find(s))
                .min()
                .unwrap_or(l.len());
            let cmd = l[..cut].trim();
            let w = words(cmd);
            let placeholder = w.iter().skip(1).any(|a| {
                a.contains('…')
                    || a.contains('$')
                    || a.contains('[')
                    || (a.len() > 1
                        && a.chars()
                            .all(|c| c.is_ascii_uppercase() || c == ':' || c == '_'))
            });
            if placeholder || w.get(1).map(String::as_str) == Some("serve") {
                continue;
            }
            if let Some(block) = out.last_mut() {
                block.push((name.clone(), line.to_string(), w[1..].to_vec()));
            }
        }
    }
    out.retain(|b| !b.is_empty());
    out
}

/// The workspace as a git repository whose one commit holds it, tagged `v1.0.0` and known as
/// `origin/main` too: the revisions the guide's `--since` commands name.
fn commit_workspace(ws: &Path) {
    for args in [
        &["init", "-q"][..],
        &["config", "user.name", "Guide"],
        &["config", "user.email", "guide@example.org"],
        &["add", "-A"],
        &["commit", "-q", "-m", "guide"],
        &["tag", "v1.0.0"],
        &["update-ref", "refs/remotes/origin/main", "HEAD"],
    ] {
        assert!(git(ws, args), "git {args:?}");
    }
}

fn copy_examples(to: &Path) {
    for (rel, bytes) in tree(&root().join("examples")) {
        let p = to.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
}

#[test]
fn every_command_of_the_guide_runs_as_written() {
    let blocks = blocks();
    let count: usize = blocks.iter().map(Vec::len).sum();
    assert!(count >= 15, "{blocks:#?}");
    // The gate of ci.md and diff.md: `--since`, the baseline written, then read.
    let since = blocks
        .iter()
        .flatten()
        .filter(|(page, _, w)| page == "ci.md" && w.iter().any(|a| a == "--since"))
        .count();
    assert!(since >= 4, "ci.md's gate is run: {blocks:#?}");
    let mut failed = Vec::new();
    for block in &blocks {
        let dir = tempfile::tempdir().unwrap();
        let ws = dir.path();
        // The paths the guide's commands name hold the example catalogue.
        for d in [
            "examples",
            "components",
            "path/to/components",
            "robots",
            "profiles",
        ] {
            copy_examples(&ws.join(d));
        }
        if block
            .iter()
            .any(|(_, _, w)| w.iter().any(|a| a == "--since"))
        {
            if !git(ws, &["--version"]) {
                common::missing_tool("git not available");
                continue;
            }
            commit_workspace(ws);
        }
        for (page, line, args) in block {
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            let o = rtcdoc(&args, ws);
            let err = String::from_utf8_lossy(&o.stderr);
            let ok = match args[0] {
                // check and diff exit 1 for findings and changes, which is what they are for.
                "check" | "diff" => matches!(o.status.code(), Some(0 | 1)),
                _ => o.status.success(),
            };
            if !ok || err.contains("unexpected argument") {
                failed.push(format!("{page}: `{}` → {:?}\n{err}", line.trim(), o.status));
            }
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// The quick start's claims about the example catalogue.
#[test]
fn the_quick_start_is_true_of_the_example() {
    let dir = tempfile::tempdir().unwrap();
    let o = rtcdoc(
        &[
            "build",
            root().join("examples").to_str().unwrap(),
            "-o",
            "site",
        ],
        dir.path(),
    );
    assert!(o.status.success());
    let site = dir.path().join("site");
    let quick = std::fs::read_to_string(root().join("book/src/quickstart.md")).unwrap();
    // "eleven components", "nine in XML and two in YAML".
    assert!(quick.contains("eleven components") && quick.contains("nine in XML and two in YAML"));
    let components = std::fs::read_dir(site.join("components"))
        .unwrap()
        .filter(|e| e.as_ref().unwrap().file_name() != "index.html")
        .count();
    assert_eq!(components, 11);
    let json = dir.path().join("json");
    let o = rtcdoc(
        &[
            "build",
            root().join("examples").to_str().unwrap(),
            "-f",
            "json",
            "-o",
            json.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert!(o.status.success());
    let cat: serde_json::Value =
        serde_json::from_slice(&std::fs::read(json.join("catalog.json")).unwrap()).unwrap();
    let formats: Vec<&str> = cat["components"]
        .as_object()
        .unwrap()
        .values()
        .map(|c| c["format"].as_str().unwrap())
        .collect();
    assert_eq!(formats.iter().filter(|f| **f == "xml").count(), 9);
    assert_eq!(formats.iter().filter(|f| **f == "yaml").count(), 2);
    // "RT System profiles … get a page each".
    assert!(quick.contains("get a page each"));
    assert!(std::fs::read_dir(site.join("systems")).unwrap().count() >= 2);
    // The searches it suggests find something: `laser`, `TimedPose2D`, `カメラ`.
    let index = common::search_index::read(&site).text().to_lowercase();
    for q in ["laser", "timedpose2d", "カメ"] {
        assert!(quick.to_lowercase().contains(q) || q == "カメ");
        assert!(index.contains(q), "{q} is not in the search index");
    }
}
