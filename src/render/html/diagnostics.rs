//! The diagnostics page: counts at the top, errors and warnings grouped by file (errors
//! first, each file linking its component page), infos summarised by code. On the real-world
//! corpus (1,800 findings, 1,500 of them infos) a row per finding made a 990 KB table; the
//! full list stays what `rtcdoc check` prints. A large catalogue's files are split into pages
//! of [`FILES_PER_PAGE`] files (`diagnostics.html`, then `diagnostics/2.html`, …, files with
//! errors first), so that no page grows with the catalogue: 10,000 profiles with warnings
//! made an 11 MB page.

use crate::catalog::{Catalog, Ix};
use crate::diagnostic::{Diagnostic, Severity};
use serde::Serialize;
use std::collections::{BTreeMap, HashMap};

/// One error or warning.
#[derive(Serialize)]
pub(super) struct Finding<'a> {
    severity: String,
    code: &'a str,
    /// `line:col`, empty when the finding has no position.
    at: String,
    message: &'a str,
    hint: &'a str,
}

/// The errors and warnings of one file.
#[derive(Serialize)]
pub(super) struct FileGroup<'a> {
    file: &'a str,
    /// The component page of the file (relative to the site root), when it has one.
    href: Option<String>,
    errors: usize,
    warnings: usize,
    findings: Vec<Finding<'a>>,
}

/// The infos of one code.
#[derive(Serialize)]
pub(super) struct InfoCode<'a> {
    code: &'a str,
    count: usize,
    files: usize,
    /// The message of the first one (the messages of a code differ in names only).
    example: &'a str,
}

/// Files (with their errors and warnings) per diagnostics page.
pub(super) const FILES_PER_PAGE: usize = 200;

/// The path of diagnostics page `n` (1-based) below the site root, the first being `first`
/// (`diagnostics.html`; then `diagnostics/2.html`, …).
fn page_path(first: &str, n: usize) -> String {
    if n <= 1 {
        first.to_string()
    } else {
        format!("{}/{n}.html", first.trim_end_matches(".html"))
    }
}

/// A link to one page of the diagnostics.
#[derive(Serialize, Clone)]
pub(super) struct PageLink {
    number: usize,
    href: String,
    current: bool,
}

/// What the diagnostics template shows (one page of it).
#[derive(Serialize)]
pub(super) struct DiagnosticsView<'a> {
    errors: usize,
    warnings: usize,
    infos: usize,
    /// Codes of errors and warnings, sorted (the code filter).
    codes: Vec<&'a str>,
    /// Files in all (on every page).
    file_count: usize,
    files: Vec<FileGroup<'a>>,
    /// The infos, on the first page.
    info_codes: Vec<InfoCode<'a>>,
    /// Every page, when there are several.
    pages: Vec<PageLink>,
    /// This page's number (1-based) and the first page's path from here.
    pub(super) page: usize,
    overview: String,
}

fn rank(s: Severity) -> u8 {
    match s {
        Severity::Error => 0,
        Severity::Warning => 1,
        Severity::Info => 2,
    }
}

/// The pages of `catalog.diagnostics`: (path, root, view), the first at `diagnostics.html`.
pub(super) fn views<'a>(
    catalog: &'a Catalog,
    first: &str,
) -> Vec<(String, &'static str, DiagnosticsView<'a>)> {
    let all = view(catalog);
    let count = all.files.len().div_ceil(FILES_PER_PAGE).max(1);
    let links = |current: usize, root: &str| -> Vec<PageLink> {
        if count == 1 {
            return Vec::new();
        }
        (1..=count)
            .map(|n| PageLink {
                number: n,
                href: format!("{root}{}", page_path(first, n)),
                current: n == current,
            })
            .collect()
    };
    let DiagnosticsView {
        errors,
        warnings,
        infos,
        codes,
        file_count,
        files,
        info_codes,
        ..
    } = all;
    let mut files = files.into_iter();
    let mut info_codes = Some(info_codes);
    (1..=count)
        .map(|n| {
            let root = if n == 1 { "" } else { "../" };
            let mut chunk: Vec<FileGroup<'_>> = files.by_ref().take(FILES_PER_PAGE).collect();
            for f in &mut chunk {
                if let Some(h) = &mut f.href {
                    h.insert_str(0, root);
                }
            }
            let view = DiagnosticsView {
                errors,
                warnings,
                infos,
                codes: codes.clone(),
                file_count,
                files: chunk,
                info_codes: info_codes.take().unwrap_or_default(),
                pages: links(n, root),
                page: n,
                overview: if n == 1 {
                    String::new()
                } else {
                    format!("{root}{}", page_path(first, 1))
                },
            };
            (page_path(first, n), root, view)
        })
        .collect()
}

/// The view of `catalog.diagnostics` on one page: files with errors first (most errors first,
/// then by path), within a file errors before warnings in position order.
fn view(catalog: &Catalog) -> DiagnosticsView<'_> {
    let pages: HashMap<&str, String> = Ix::enumerate(&catalog.components)
        .map(|(ci, c)| (c.source.as_str(), catalog.component_page(ci).path("html")))
        .collect();
    let count = |s: Severity| {
        catalog
            .diagnostics
            .iter()
            .filter(|d| d.severity == s)
            .count()
    };
    let mut by_file: BTreeMap<&str, Vec<&Diagnostic>> = BTreeMap::new();
    let mut infos: BTreeMap<&str, (usize, Vec<&str>, &str)> = BTreeMap::new();
    for d in &catalog.diagnostics {
        if d.severity == Severity::Info {
            let e = infos.entry(d.code).or_insert((0, Vec::new(), &d.message));
            e.0 += 1;
            e.1.push(&d.file);
        } else {
            by_file.entry(&d.file).or_default().push(d);
        }
    }
    let mut files: Vec<FileGroup<'_>> = by_file
        .into_iter()
        .map(|(file, mut list)| {
            list.sort_by_key(|d| (rank(d.severity), d.pos.map(|p| (p.line, p.column))));
            FileGroup {
                file,
                href: pages.get(file).cloned(),
                errors: list
                    .iter()
                    .filter(|d| d.severity == Severity::Error)
                    .count(),
                warnings: list
                    .iter()
                    .filter(|d| d.severity == Severity::Warning)
                    .count(),
                findings: list
                    .into_iter()
                    .map(|d| Finding {
                        severity: d.severity.to_string(),
                        code: d.code,
                        at: d
                            .pos
                            .map(|p| format!("{}:{}", p.line, p.column))
                            .unwrap_or_default(),
                        message: &d.message,
                        hint: d.hint.as_deref().unwrap_or(""),
                    })
                    .collect(),
            }
        })
        .collect();
    files.sort_by(|a, b| b.errors.cmp(&a.errors).then(a.file.cmp(b.file)));
    let mut codes: Vec<&str> = catalog
        .diagnostics
        .iter()
        .filter(|d| d.severity != Severity::Info)
        .map(|d| d.code)
        .collect();
    codes.sort_unstable();
    codes.dedup();
    let info_codes = infos
        .into_iter()
        .map(|(code, (count, mut fs, example))| {
            fs.sort_unstable();
            fs.dedup();
            InfoCode {
                code,
                count,
                files: fs.len(),
                example,
            }
        })
        .collect();
    DiagnosticsView {
        errors: count(Severity::Error),
        warnings: count(Severity::Warning),
        infos: count(Severity::Info),
        codes,
        file_count: files.len(),
        files,
        info_codes,
        pages: Vec::new(),
        page: 1,
        overview: String::new(),
    }
}
