//! The Japanese user guide (`book/ja`) is kept in step with the English one (`book/`): the same
//! chapters, the same headings, the same code, and it builds with the real mdbook beside the
//! English book, without warnings or broken links.
//!
//! The rule for code blocks: every fenced code block of an English chapter appears in the
//! Japanese chapter in the same order, with the same info string and the same lines, except that
//! a comment — from a `#` at the start of a line or after a space to the end of the line — may be
//! translated. Headings: the same number of `#` headings, at the same levels, in the same order
//! (their text is translated; an explicit `{#id}` keeps the English anchor).

use crate::common;
use common::OutputWithin;
use common::*;
use std::path::Path;

/// The chapter files SUMMARY.md links, in order, each with its nesting depth.
fn summary_chapters(summary: &Path) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(summary).unwrap();
    text.lines()
        .filter_map(|line| {
            let depth = (line.len() - line.trim_start().len()) / 2;
            let start = line.find("](")? + 2;
            let end = start + line[start..].find(')')?;
            Some((depth, line[start..end].to_string()))
        })
        .collect()
}

/// A chapter's headings (their levels, in order) and fenced code blocks (info string and lines).
struct Shape {
    headings: Vec<usize>,
    blocks: Vec<(String, Vec<String>)>,
}

fn shape(text: &str) -> Shape {
    let mut headings = Vec::new();
    let mut blocks: Vec<(String, Vec<String>)> = Vec::new();
    let mut fence: Option<String> = None;
    for line in text.lines() {
        let trimmed = line.trim_start();
        if let Some(f) = &fence {
            if trimmed.starts_with(f.as_str()) && trimmed.trim_start_matches('`').trim().is_empty()
            {
                fence = None;
            } else {
                blocks.last_mut().unwrap().1.push(line.to_string());
            }
            continue;
        }
        if trimmed.starts_with("```") {
            let ticks: String = trimmed.chars().take_while(|c| *c == '`').collect();
            blocks.push((trimmed[ticks.len()..].trim().to_string(), Vec::new()));
            fence = Some(ticks);
            continue;
        }
        let level = line.chars().take_while(|c| *c == '#').count();
        if (1..=6).contains(&level) && line[level..].starts_with(' ') {
            headings.push(level);
        }
    }
    Shape { headings, blocks }
}

/// A code line without its comment (`#` at the start or after a space, to the end of the line)
/// and trailing spaces: what must be the same in both languages.
fn code_of(line: &str) -> &str {
    let cut = if line.trim_start().starts_with('#') {
        Some(line.len() - line.trim_start().len())
    } else {
        line.find(" #")
    };
    match cut {
        Some(i) => line[..i].trim_end(),
        None => line.trim_end(),
    }
}

/// What differs between the English and the Japanese chapter, if anything.
fn differences(en: &str, ja: &str) -> Vec<String> {
    let (en, ja) = (shape(en), shape(ja));
    let mut out = Vec::new();
    if en.headings != ja.headings {
        out.push(format!(
            "headings differ: English has levels {:?}, Japanese {:?}",
            en.headings, ja.headings
        ));
    }
    if en.blocks.len() != ja.blocks.len() {
        out.push(format!(
            "English has {} code blocks, Japanese {}",
            en.blocks.len(),
            ja.blocks.len()
        ));
    }
    for (n, ((ei, el), (ji, jl))) in en.blocks.iter().zip(&ja.blocks).enumerate() {
        if ei != ji {
            out.push(format!(
                "code block {}: ```{ei} in English, ```{ji} in Japanese",
                n + 1
            ));
        }
        let e: Vec<&str> = el.iter().map(|l| code_of(l)).collect();
        let j: Vec<&str> = jl.iter().map(|l| code_of(l)).collect();
        if e != j {
            let at = e
                .iter()
                .zip(&j)
                .position(|(a, b)| a != b)
                .unwrap_or(e.len().min(j.len()));
            out.push(format!(
                "code block {} differs at its line {}: English `{}`, Japanese `{}`",
                n + 1,
                at + 1,
                e.get(at).copied().unwrap_or("(none)"),
                j.get(at).copied().unwrap_or("(none)")
            ));
        }
    }
    out
}

#[test]
fn every_english_chapter_has_its_japanese_chapter_with_the_same_headings_and_code() {
    let en = summary_chapters(&root().join("book/src/SUMMARY.md"));
    let ja = summary_chapters(&root().join("book/ja/src/SUMMARY.md"));
    assert!(en.len() > 10, "{en:?}");
    assert_eq!(
        en, ja,
        "book/ja/src/SUMMARY.md must list the chapters of book/src/SUMMARY.md (same files, same order and nesting)"
    );
    let mut problems = Vec::new();
    for (_, file) in &en {
        let ja_path = root().join("book/ja/src").join(file);
        let Ok(ja_text) = std::fs::read_to_string(&ja_path) else {
            problems.push(format!("{file}: no Japanese chapter book/ja/src/{file}"));
            continue;
        };
        let en_text = std::fs::read_to_string(root().join("book/src").join(file)).unwrap();
        for d in differences(&en_text, &ja_text) {
            problems.push(format!("{file}: {d}"));
        }
    }
    assert!(
        problems.is_empty(),
        "the Japanese guide is out of step with the English one:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_comparison_finds_what_differs() {
    let en = "# A\n\n## B\n\n```sh\nrtcdoc build x -o site   # HTML\n# a comment\n```\n";
    // Translated text, headings and comments: in step.
    let ja =
        "# あ {#a}\n\n## い\n\n```sh\nrtcdoc build x -o site   # HTML (既定)\n# コメント\n```\n";
    assert!(differences(en, ja).is_empty(), "{:?}", differences(en, ja));
    // A heading level, a command and a missing block are found.
    let bad = "# あ\n\n### い\n\n```sh\nrtcdoc build x -o out   # HTML\n# コメント\n```\n";
    let d = differences(en, bad);
    assert!(d.iter().any(|m| m.contains("headings differ")), "{d:?}");
    assert!(
        d.iter().any(|m| m.contains("rtcdoc build x -o out")),
        "{d:?}"
    );
    assert!(differences(en, "# あ\n\n## い\n")
        .iter()
        .any(|m| m.contains("1 code blocks, Japanese 0")));
    // A `#` inside a value is not a comment.
    assert_eq!(code_of("url = \"a#b\"  # x"), "url = \"a#b\"");
}

/// The language switch is one script (and one style sheet) shared by both books.
#[test]
fn both_books_use_the_same_language_switch() {
    for f in ["lang-switch.js", "lang-switch.css"] {
        let en = std::fs::read(root().join("book").join(f)).unwrap();
        let ja = std::fs::read(root().join("book/ja").join(f)).unwrap();
        assert_eq!(en, ja, "book/{f} and book/ja/{f} differ");
        for toml in ["book/book.toml", "book/ja/book.toml"] {
            let t = std::fs::read_to_string(root().join(toml)).unwrap();
            assert!(t.contains(&format!("\"{f}\"")), "{toml} does not use {f}");
        }
    }
    let ja = std::fs::read_to_string(root().join("book/ja/book.toml")).unwrap();
    assert!(ja.contains("language = \"ja\""));
    let intro = std::fs::read_to_string(root().join("book/src/introduction.md")).unwrap();
    assert!(
        intro.contains("(ja/index.html)"),
        "the English introduction links the Japanese guide"
    );
}

/// Both books built as they are published — English at the root, Japanese in `ja/` — without
/// warnings, and with no broken link in either (the books link to each other).
#[test]
fn japanese_guide_builds_with_mdbook_beside_the_english_one() {
    if std::process::Command::new("mdbook")
        .arg("--version")
        .output_within(common::COMMAND_LIMIT)
        .is_err()
    {
        crate::common::missing_tool("mdbook not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (book, dest) in [
        ("book", dir.path().to_path_buf()),
        ("book/ja", dir.path().join("ja")),
    ] {
        let out = std::process::Command::new("mdbook")
            .arg("build")
            .arg(root().join(book))
            .arg("-d")
            .arg(&dest)
            .output_within(common::COMMAND_LIMIT)
            .unwrap();
        let log = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{book}: {log}");
        assert!(
            !log.contains("WARN") && !log.contains("ERROR"),
            "{book}: {log}"
        );
    }
    let ja = dir.path().join("ja");
    for (_, file) in summary_chapters(&root().join("book/ja/src/SUMMARY.md")) {
        let page = file.replace(".md", ".html");
        assert!(ja.join(&page).exists(), "ja/{page}");
        assert!(dir.path().join(&page).exists(), "{page}");
    }
    let index = std::fs::read_to_string(ja.join("index.html")).unwrap();
    assert!(
        index.contains("lang=\"ja\""),
        "the Japanese book is marked as Japanese"
    );
    assert!(index.contains("lang-switch"), "the language switch script");
    assert!(ja.join("images/component-page.png").exists());
    if let Some(tool) = shared_tool("linkcheck.py") {
        let r = std::process::Command::new("python3")
            .arg(tool)
            .arg(dir.path())
            .output_within(common::COMMAND_LIMIT)
            .unwrap();
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stdout));
    }
}
