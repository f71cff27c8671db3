//! Helpers for the HTML site tests: building sites, a tiny tag scanner and a link checker.
#![allow(dead_code)]

use rtcdoc::build::{self, BuildOptions, LoadOptions};
use rtcdoc::render::{Format, SiteOptions};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Builds the HTML site of `input` into `out` with `site` options.
/// The stability marks of the input's own `rtcdoc.toml` are applied (the other settings are
/// the tests' to give).
pub fn build_site(input: &Path, out: &Path, site: SiteOptions) -> build::Loaded {
    let mut load = LoadOptions::default();
    if input.join(rtcdoc::config::FILE_NAME).is_file() {
        let file = rtcdoc::config::load(None, &[input]).expect("rtcdoc.toml");
        load.stability = file.config.stability_marks;
    }
    let (loaded, _report) = build::build(&BuildOptions {
        input: input.to_path_buf(),
        output: out.to_path_buf(),
        formats: vec![Format::Html],
        strict: false,
        load,
        site,
    })
    .expect("build succeeds");
    loaded
}

/// The crate's `examples/` catalogue.
pub fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples")
}

/// One start tag: lower-case name and attributes (values entity-decoded).
#[derive(Debug, Clone)]
pub struct Tag {
    pub name: String,
    pub attrs: Vec<(String, String)>,
}

impl Tag {
    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }
}

fn decode(s: &str) -> String {
    s.replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&#x27;", "'")
        .replace("&#x2f;", "/")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// Scans the start tags of an HTML document (comments skipped; raw text of `script` and
/// `style` elements skipped).
pub fn tags(html: &str) -> Vec<Tag> {
    let b = html.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(off) = html[i..].find('<') {
        i += off;
        if html[i..].starts_with("<!--") {
            i = html[i..].find("-->").map(|e| i + e + 3).unwrap_or(b.len());
            continue;
        }
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'/' || b[j] == b'!' || b[j] == b'?') {
            i = html[i..].find('>').map(|e| i + e + 1).unwrap_or(b.len());
            continue;
        }
        let start = j;
        while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'-' || b[j] == b':') {
            j += 1;
        }
        if j == start {
            i += 1;
            continue;
        }
        let name = html[start..j].to_ascii_lowercase();
        let mut attrs = Vec::new();
        loop {
            while j < b.len() && (b[j].is_ascii_whitespace() || b[j] == b'/') {
                j += 1;
            }
            if j >= b.len() || b[j] == b'>' {
                break;
            }
            let ks = j;
            while j < b.len() && !b[j].is_ascii_whitespace() && b[j] != b'=' && b[j] != b'>' {
                j += 1;
            }
            let key = html[ks..j].to_ascii_lowercase();
            let mut val = String::new();
            if j < b.len() && b[j] == b'=' {
                j += 1;
                if j < b.len() && (b[j] == b'"' || b[j] == b'\'') {
                    let q = b[j];
                    let vs = j + 1;
                    let ve = html[vs..]
                        .find(q as char)
                        .map(|e| vs + e)
                        .unwrap_or(b.len());
                    val = decode(&html[vs..ve]);
                    j = (ve + 1).min(b.len());
                } else {
                    let vs = j;
                    while j < b.len() && !b[j].is_ascii_whitespace() && b[j] != b'>' {
                        j += 1;
                    }
                    val = decode(&html[vs..j]);
                }
            }
            attrs.push((key, val));
        }
        i = (j + 1).min(b.len());
        if name == "script" || name == "style" {
            let close = format!("</{name}");
            i = html[i..].find(&close).map(|e| i + e).unwrap_or(b.len());
        }
        out.push(Tag { name, attrs });
    }
    out
}

/// Every `.html` file below `site`, relative path → contents.
pub fn pages(site: &Path) -> BTreeMap<String, String> {
    walkdir::WalkDir::new(site)
        .sort_by_file_name()
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file() && e.path().extension().is_some_and(|x| x == "html"))
        .map(|e| {
            let rel = e
                .path()
                .strip_prefix(site)
                .expect("inside")
                .to_string_lossy()
                .replace('\\', "/");
            (rel, std::fs::read_to_string(e.path()).expect("utf-8 page"))
        })
        .collect()
}

/// Resolves `href` found in page `from` (site-relative) to (site-relative path, fragment);
/// `None` for external links.
pub fn resolve(from: &str, href: &str) -> Option<(String, Option<String>)> {
    if href.starts_with("http:") || href.starts_with("https:") || href.starts_with("mailto:") {
        return None;
    }
    let (path, frag) = match href.split_once('#') {
        Some((p, f)) => (p, Some(f.to_string())),
        None => (href, None),
    };
    let path = path.split('?').next().unwrap_or("");
    let mut parts: Vec<&str> = from.split('/').collect();
    parts.pop();
    if path.is_empty() {
        return Some((from.to_string(), frag));
    }
    for seg in path.split('/') {
        match seg {
            ".." => {
                parts.pop();
            }
            "." | "" => {}
            s => parts.push(s),
        }
    }
    Some((parts.join("/"), frag))
}

/// Checks every internal `href`/`src` of every page: the file exists and the fragment names an
/// id in it. Returns the broken links as `page: href`.
pub fn broken_links(site: &Path) -> Vec<String> {
    let pages = pages(site);
    let ids: BTreeMap<&str, BTreeSet<String>> = pages
        .iter()
        .map(|(p, html)| {
            (
                p.as_str(),
                tags(html)
                    .into_iter()
                    .filter_map(|t| t.attr("id").map(str::to_string))
                    .collect(),
            )
        })
        .collect();
    let mut broken = Vec::new();
    for (page, html) in &pages {
        for t in tags(html) {
            for key in ["href", "src"] {
                let Some(v) = t.attr(key) else { continue };
                if v.trim().to_ascii_lowercase().starts_with("javascript:") {
                    broken.push(format!("{page}: {v}"));
                    continue;
                }
                let Some((target, frag)) = resolve(page, v) else {
                    continue;
                };
                if !site.join(&target).is_file() {
                    broken.push(format!("{page}: {v} (no file {target})"));
                    continue;
                }
                if let Some(f) = frag.filter(|f| !f.is_empty()) {
                    if !ids.get(target.as_str()).is_some_and(|s| s.contains(&f)) {
                        broken.push(format!("{page}: {v} (no id {f} in {target})"));
                    }
                }
            }
        }
    }
    broken
}

/// Whether `program` runs (`program --version` succeeds).
pub fn have(program: &str) -> bool {
    std::process::Command::new(program)
        .arg("--version")
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false)
}
