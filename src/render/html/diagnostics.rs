//! The diagnostics page: counts at the top, errors and warnings grouped by file (errors
//! first, each file linking its component page), infos summarised by code. On the real-world
//! corpus (1,800 findings, 1,500 of them infos) a row per finding made a 990 KB table; the
//! full list stays what `rtcdoc check` prints.

use crate::catalog::Catalog;
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

/// What the diagnostics template shows.
#[derive(Serialize)]
pub(super) struct DiagnosticsView<'a> {
    errors: usize,
    warnings: usize,
    infos: usize,
    /// Codes of errors and warnings, sorted (the code filter).
    codes: Vec<&'a str>,
    files: Vec<FileGroup<'a>>,
    info_codes: Vec<InfoCode<'a>>,
}

fn rank(s: Severity) -> u8 {
    match s {
        Severity::Error => 0,
        Severity::Warning => 1,
        Severity::Info => 2,
    }
}

/// The view of `catalog.diagnostics`: files with errors first (most errors first, then by
/// path), within a file errors before warnings in position order.
pub(super) fn view(catalog: &Catalog) -> DiagnosticsView<'_> {
    let pages: HashMap<&str, String> = catalog
        .components
        .iter()
        .enumerate()
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
        files,
        info_codes,
    }
}
