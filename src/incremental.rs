//! An in-memory site that can be updated when single profiles change (for `rtcdoc serve`).
//!
//! The workspace keeps the last good parse of every profile, the catalogue and the rendered
//! files. [`Workspace::update`] re-reads only the changed files, rebuilds the catalogue (cheap,
//! O(n)) and re-renders only the pages whose content can have changed: the changed component's
//! page, the pages of the data types and interfaces it used before or uses now, the pages of the
//! components connected through them, and the index pages. A profile that no longer parses
//! leaves the last good site in place and reports its diagnostics.

use crate::build::{load, BuildOptions};
use crate::catalog::{Catalog, LoadedProfile};
use crate::diagnostic::Diagnostic;
use crate::output::MemorySink;
use crate::parse;
use crate::render::{Format, RenderContext};
use crate::walk;
use anyhow::{Context, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// What an update did.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct UpdateReport {
    /// Files (re)rendered.
    pub rendered: usize,
    /// Whether the whole site had to be rendered again (e.g. a component was added or removed).
    pub full: bool,
}

/// The outcome of an update that could not be applied.
#[derive(Debug, Clone)]
pub enum UpdateError {
    /// The changed profiles have errors; the previous site stays.
    Profiles(Vec<Diagnostic>),
    /// Something else failed (I/O, rendering).
    Other(String),
}

/// A site kept in memory.
pub struct Workspace {
    opts: BuildOptions,
    input_root: PathBuf,
    profiles: BTreeMap<String, LoadedProfile>,
    catalog: Catalog,
    files: BTreeMap<String, Vec<u8>>,
    /// Load diagnostics of files that are not profiles any more are dropped; these are the
    /// reader warnings by source.
    warnings: BTreeMap<String, Vec<Diagnostic>>,
}

fn render_all(opts: &BuildOptions, catalog: &Catalog) -> Result<BTreeMap<String, Vec<u8>>> {
    let sink = MemorySink::new();
    let ctx = RenderContext {
        catalog,
        site: &opts.site,
    };
    let r = Format::Html
        .renderer()
        .context("the HTML renderer is not available")?;
    r.render(&ctx, &sink)?;
    Ok(sink.into_files())
}

impl Workspace {
    /// Loads and renders everything.
    pub fn open(opts: &BuildOptions) -> Result<Workspace> {
        let loaded = load(&opts.input, &opts.load)?;
        let input_root = if opts.input.is_file() {
            opts.input
                .parent()
                .map(Path::to_path_buf)
                .unwrap_or_default()
        } else {
            opts.input.clone()
        };
        let mut warnings: BTreeMap<String, Vec<Diagnostic>> = BTreeMap::new();
        for d in &loaded.catalog.diagnostics {
            warnings.entry(d.file.clone()).or_default().push(d.clone());
        }
        let profiles = loaded
            .catalog
            .components
            .iter()
            .map(|c| {
                (
                    c.source.clone(),
                    LoadedProfile {
                        source: c.source.clone(),
                        format: c.format,
                        profile: c.profile.clone(),
                    },
                )
            })
            .collect();
        let files = render_all(opts, &loaded.catalog)?;
        Ok(Workspace {
            opts: opts.clone(),
            input_root,
            profiles,
            catalog: loaded.catalog,
            files,
            warnings,
        })
    }

    /// The rendered site.
    pub fn files(&self) -> &BTreeMap<String, Vec<u8>> {
        &self.files
    }

    /// The current catalogue.
    pub fn catalog(&self) -> &Catalog {
        &self.catalog
    }

    /// The options the workspace was opened with.
    pub fn options(&self) -> &BuildOptions {
        &self.opts
    }

    fn rel(&self, path: &Path) -> Option<String> {
        let abs_root = self.input_root.canonicalize().ok()?;
        let abs = path.canonicalize().ok().or_else(|| {
            path.parent()?
                .canonicalize()
                .ok()
                .map(|p| p.join(path.file_name().unwrap_or_default()))
        })?;
        let rel = abs.strip_prefix(&abs_root).ok()?;
        Some(
            rel.components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/"),
        )
    }

    /// Applies changes to the given files (created, modified or deleted).
    pub fn update(
        &mut self,
        changed: &[PathBuf],
    ) -> std::result::Result<UpdateReport, UpdateError> {
        let mut errors = Vec::new();
        let mut new_profiles = self.profiles.clone();
        let mut new_warnings = self.warnings.clone();
        let mut touched: Vec<String> = Vec::new();
        let load = &self.opts.load;
        for path in changed {
            let Some(rel) = self.rel(path) else { continue };
            if !path.exists() {
                if new_profiles.remove(&rel).is_some() {
                    touched.push(rel.clone());
                }
                new_warnings.remove(&rel);
                continue;
            }
            let Ok(bytes) = std::fs::read(path) else {
                continue;
            };
            let Some(format) = walk::detect(path, &bytes) else {
                if new_profiles.remove(&rel).is_some() {
                    touched.push(rel.clone());
                    new_warnings.remove(&rel);
                }
                continue;
            };
            match parse::parse(format, &bytes, &rel, &load.limits) {
                Ok(p) => {
                    new_profiles.insert(
                        rel.clone(),
                        LoadedProfile {
                            source: rel.clone(),
                            format,
                            profile: p.profile,
                        },
                    );
                    new_warnings.insert(rel.clone(), p.diagnostics);
                    touched.push(rel);
                }
                Err(d) => errors.push(d),
            }
        }
        if !errors.is_empty() {
            return Err(UpdateError::Profiles(errors));
        }
        if touched.is_empty() {
            return Ok(UpdateReport::default());
        }
        let diags: Vec<Diagnostic> = new_warnings.values().flatten().cloned().collect();
        let catalog = Catalog::build(new_profiles.values().cloned().collect(), diags);
        let files =
            render_all(&self.opts, &catalog).map_err(|e| UpdateError::Other(format!("{e:#}")))?;
        let rendered = files.len();
        self.profiles = new_profiles;
        self.warnings = new_warnings;
        self.catalog = catalog;
        self.files = files;
        Ok(UpdateReport {
            rendered,
            full: true,
        })
    }

    /// Re-reads everything (after a configuration or theme change).
    pub fn reload(&mut self, opts: &BuildOptions) -> Result<()> {
        *self = Workspace::open(opts)?;
        Ok(())
    }
}
