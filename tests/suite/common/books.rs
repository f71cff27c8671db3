//! Running the real tools on the Markdown and Doxygen outputs: `doxygen` (warnings are errors)
//! and `mdbook` (no warning, no broken link in the built book). A test whose tool is missing
//! prints `skipped: <tool> not installed` and passes, except under CI, where it fails
//! (`missing_tool`); CI installs both.
use super::OutputWithin;

use super::root;
use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Whether `tool` runs; otherwise `missing_tool` (skipped, or a failure under CI).
pub fn have(tool: &str) -> bool {
    let ok = Command::new(tool)
        .arg("--version")
        .output_within(super::COMMAND_LIMIT)
        .map(|o| o.status.success())
        .unwrap_or(false);
    if !ok {
        super::missing_tool(&format!("{tool} not installed"));
    }
    ok
}

/// Runs doxygen in `dir`; asserts exit 0 and no warning on stderr.
pub fn run_doxygen(dir: &Path) {
    let o = Command::new("doxygen")
        .current_dir(dir)
        .output_within(super::COMMAND_LIMIT)
        .expect("run doxygen");
    let stderr = String::from_utf8_lossy(&o.stderr);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "doxygen failed: {stderr}\n{stdout}");
    assert!(
        !stderr.to_ascii_lowercase().contains("warning"),
        "doxygen warnings:\n{stderr}"
    );
    assert!(stderr.trim().is_empty(), "doxygen said:\n{stderr}");
}

/// Builds an mdBook over `src`; asserts no WARN/ERROR and no broken link. Returns the book dir.
pub fn run_mdbook(src: &Path) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("tempdir");
    let book = dir.path().join("book");
    std::fs::write(
        dir.path().join("book.toml"),
        format!(
            "[book]\ntitle = \"catalogue\"\nsrc = {:?}\n[build]\nbuild-dir = \"book\"\ncreate-missing = false\n",
            src.to_string_lossy()
        ),
    )
    .expect("write book.toml");
    let o = Command::new("mdbook")
        .arg("build")
        .current_dir(dir.path())
        .output_within(super::COMMAND_LIMIT)
        .expect("run mdbook");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "mdbook failed:\n{stderr}");
    assert!(
        !stderr.contains("WARN") && !stderr.contains("ERROR"),
        "mdbook warnings:\n{stderr}"
    );
    let broken = broken_links(&book);
    assert!(broken.is_empty(), "broken links: {broken:#?}");
    if let Some(tool) = Some(root().join("../shared/tools/linkcheck.py")).filter(|p| p.is_file()) {
        if let Ok(o) = Command::new("python3")
            .arg(&tool)
            .arg(&book)
            .output_within(super::COMMAND_LIMIT)
        {
            assert!(
                o.status.success(),
                "linkcheck.py: {}",
                String::from_utf8_lossy(&o.stdout)
            );
        }
    }
    (dir, book)
}

/// Values of `attr="…"` inside tags (text is escaped, so a real tag starts with `<`).
fn attr_values<'a>(html: &'a str, attr: &str) -> Vec<&'a str> {
    let pat = format!("{attr}=\"");
    let mut out = Vec::new();
    for piece in html.split('<').skip(1) {
        let tag = piece.split('>').next().unwrap_or("");
        let mut rest = tag;
        while let Some(i) = rest.find(&pat) {
            // Only whole attribute names: preceded by white space.
            let ok = i > 0 && rest.as_bytes()[i - 1].is_ascii_whitespace();
            rest = &rest[i + pat.len()..];
            if let Some(end) = rest.find('"') {
                if ok {
                    out.push(&rest[..end]);
                }
                rest = &rest[end..];
            }
        }
    }
    out
}

/// Every relative href/src of every page in `site` must name an existing file, and a fragment
/// must match an `id`/`name` in the target page.
pub fn broken_links(site: &Path) -> Vec<String> {
    let mut pages: HashMap<PathBuf, String> = HashMap::new();
    for e in walkdir::WalkDir::new(site).into_iter().flatten() {
        if e.path().extension().is_some_and(|x| x == "html") {
            let text = std::fs::read_to_string(e.path()).unwrap_or_default();
            pages.insert(e.path().to_path_buf(), text);
        }
    }
    let ids: HashMap<&PathBuf, HashSet<&str>> = pages
        .iter()
        .map(|(p, t)| {
            let mut s: HashSet<&str> = attr_values(t, "id").into_iter().collect();
            s.extend(attr_values(t, "name"));
            (p, s)
        })
        .collect();
    let mut broken = Vec::new();
    for (page, text) in &pages {
        for link in attr_values(text, "href")
            .into_iter()
            .chain(attr_values(text, "src"))
        {
            if link.is_empty() || link.contains("://") || link.starts_with("mailto:") {
                continue;
            }
            let (path, frag) = link.split_once('#').unwrap_or((link, ""));
            let path = path.split('?').next().unwrap_or("");
            let target = if path.is_empty() {
                page.clone()
            } else {
                normalize(&page.parent().expect("parent").join(path))
            };
            if !target.exists() {
                broken.push(format!("{}: {link}", page.display()));
                continue;
            }
            if !frag.is_empty() {
                if let Some(set) = ids.get(&target) {
                    if !set.contains(frag) {
                        broken.push(format!("{}: {link} (no such anchor)", page.display()));
                    }
                }
            }
        }
    }
    broken.sort();
    broken
}

fn normalize(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            std::path::Component::ParentDir => {
                out.pop();
            }
            std::path::Component::CurDir => {}
            c => out.push(c),
        }
    }
    out
}
