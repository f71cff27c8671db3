//! No page path is spelled outside the page module: every link and output path comes from the
//! catalogue's page list (`catalog.rs`, `catalog/pages.rs`: `Page::path_in`, `Catalog::href`).
//! The one exception is the native HTML writer's navigation bar, which mirrors the theme's
//! `base.html` byte for byte (`tests/suite/html_native.rs`), where theme authors write the links.

use std::path::Path;

fn walk(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).expect("readable") {
        let p = e.expect("entry").path();
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn no_page_path_is_spelled_outside_the_page_module() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    walk(&src, &mut files);
    // Page folders and the fragments of a page path with an anchor.
    let spellings = [
        "\"components/",
        "\"types/",
        "\"interfaces/",
        "\"categories/",
        "\"vendors/",
        "\"systems/",
        "\"diagnostics/",
        "\"history/",
        "\"whats-new",
        "}components/",
        "}types/",
        ".html#",
        ".md#",
    ];
    let mut found = Vec::new();
    for f in files {
        let rel = f
            .strip_prefix(&src)
            .expect("below src")
            .to_string_lossy()
            .replace('\\', "/");
        // The page module; diff's paths are JSON paths ("components/<id>/…"), not pages.
        if rel == "catalog.rs"
            || rel.starts_with("catalog/")
            || rel.starts_with("diff/")
            || rel == "render/html/native/mod.rs"
        {
            continue;
        }
        let text = std::fs::read_to_string(&f).expect("readable");
        let code = text.split("#[cfg(test)]").next().unwrap_or(&text);
        for (n, line) in code.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            if let Some(s) = spellings.iter().find(|s| line.contains(*s)) {
                found.push(format!("src/{rel}:{}: {s}: {}", n + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "page paths spelled by hand:\n{}",
        found.join("\n")
    );
}
