//! An in-memory site that can be updated when single profiles change (for `rtcdoc serve`).
//!
//! The workspace keeps the last good parse of every profile, the catalogue and the rendered
//! files. [`Workspace::update`] re-reads only the changed files, rebuilds the catalogue (cheap,
//! O(n)) and re-renders only the pages whose content can have changed: the changed component's
//! page, the pages of the data types and interfaces it used before or uses now, the pages of the
//! components connected through them, and the index pages. A profile that no longer parses
//! leaves the last good site in place and reports its diagnostics.

use crate::build::{add_check_diagnostics, load, BuildOptions};
use crate::catalog::{Catalog, LoadedProfile};
use crate::diagnostic::Diagnostic;
use crate::output::MemorySink;
use crate::parse;
use crate::render::html::HtmlRenderer;
use crate::render::RenderContext;
use crate::walk;
use anyhow::Result;
use std::collections::{BTreeMap, BTreeSet};
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

/// Rendered files by site-relative path.
pub type Files = BTreeMap<String, Vec<u8>>;

/// Renders the files `wanted` accepts; returns them and the paths of the whole site.
fn render(
    opts: &BuildOptions,
    catalog: &Catalog,
    wanted: &(dyn Fn(&str) -> bool + Sync),
) -> Result<(Files, Vec<String>)> {
    let sink = MemorySink::new();
    let ctx = RenderContext {
        catalog,
        site: &opts.site,
    };
    let r = HtmlRenderer.render_some(&ctx, &sink, wanted)?;
    Ok((sink.into_files(), r.all_paths))
}

/// The pages that can differ between the sites of `old` and `new` when only the profiles in
/// `changed` (sources) differ; `None` when everything must be rendered again (a component was
/// added, removed or renamed, a slug moved, or the diagnostics page appeared or vanished —
/// every page's navigation links to it).
fn affected(old: &Catalog, new: &Catalog, changed: &[String]) -> Option<BTreeSet<String>> {
    let slugs = |c: &Catalog| -> Vec<(String, String)> {
        c.components
            .iter()
            .map(|x| (x.source.clone(), x.slug.clone()))
            .collect()
    };
    if slugs(old) != slugs(new) || old.diagnostics.is_empty() != new.diagnostics.is_empty() {
        return None;
    }
    // A type, interface or facet that exists on both sides must keep its slug.
    let moved = |a: Vec<(&String, &String)>, b: Vec<(&String, &String)>| {
        let a: BTreeMap<_, _> = a.into_iter().collect();
        b.into_iter()
            .any(|(n, s)| a.get(n).is_some_and(|o| *o != s))
    };
    if moved(
        old.data_types.iter().map(|t| (&t.name, &t.slug)).collect(),
        new.data_types.iter().map(|t| (&t.name, &t.slug)).collect(),
    ) || moved(
        old.interfaces.iter().map(|t| (&t.name, &t.slug)).collect(),
        new.interfaces.iter().map(|t| (&t.name, &t.slug)).collect(),
    ) || moved(
        old.categories.iter().map(|t| (&t.name, &t.slug)).collect(),
        new.categories.iter().map(|t| (&t.name, &t.slug)).collect(),
    ) || moved(
        old.vendors.iter().map(|t| (&t.name, &t.slug)).collect(),
        new.vendors.iter().map(|t| (&t.name, &t.slug)).collect(),
    ) {
        return None;
    }
    let mut set: BTreeSet<String> = [
        "index.html",
        "types/index.html",
        "interfaces/index.html",
        "search-index.js",
        "sitemap.xml",
        "diagnostics.html",
    ]
    .into_iter()
    .map(String::from)
    .collect();
    for src in changed {
        let ci = new.components.iter().position(|c| &c.source == src)?;
        for cat in [old, new] {
            let comp = &cat.components[ci];
            set.insert(format!("components/{}.html", comp.slug));
            // Every page that lists a port of this component: its types' and interfaces'
            // pages and the pages of the components connected through them.
            for p in &comp.profile.data_ports {
                for side in [old, new] {
                    if let Some(t) = p.type_.as_deref().and_then(|t| side.data_type(t)) {
                        set.insert(format!("types/{}.html", t.slug));
                        for r in t.producers.iter().chain(&t.consumers).chain(&t.others) {
                            set.insert(format!(
                                "components/{}.html",
                                side.components[r.component].slug
                            ));
                        }
                    }
                }
            }
            for sp in &comp.profile.service_ports {
                for i in &sp.interfaces {
                    for side in [old, new] {
                        if let Some(t) = i.type_.as_deref().and_then(|t| side.interface(t)) {
                            set.insert(format!("interfaces/{}.html", t.slug));
                            for r in t.providers.iter().chain(&t.requirers).chain(&t.others) {
                                set.insert(format!(
                                    "components/{}.html",
                                    side.components[r.component].slug
                                ));
                            }
                        }
                    }
                }
            }
        }
    }
    Some(set)
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
        // Only the readers' diagnostics are kept per file: the catalogue adds its own
        // (duplicate ids) again whenever it is rebuilt.
        for d in loaded
            .catalog
            .diagnostics
            .iter()
            .filter(|d| d.code != crate::diagnostic::codes::DUPLICATE_ID)
        {
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
        let mut catalog = loaded.catalog;
        add_check_diagnostics(&mut catalog);
        let (files, _) = render(opts, &catalog, &|_| true)?;
        Ok(Workspace {
            opts: opts.clone(),
            input_root,
            profiles,
            catalog,
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
        // Lexical: the file may be gone (deleted with its directory).
        let root = crate::output::absolute(&self.input_root).ok()?;
        let abs = crate::output::absolute(path).ok()?;
        let rel = abs.strip_prefix(&root).ok()?;
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
        let mut catalog = Catalog::build(new_profiles.values().cloned().collect(), diags);
        add_check_diagnostics(&mut catalog);
        let plan = affected(&self.catalog, &catalog, &touched);
        let full = plan.is_none();
        let wanted = |p: &str| match &plan {
            None => true,
            Some(set) => {
                set.contains(p) || p.starts_with("categories/") || p.starts_with("vendors/")
            }
        };
        let (written, all_paths) = render(&self.opts, &catalog, &wanted)
            .map_err(|e| UpdateError::Other(format!("{e:#}")))?;
        let rendered = written.len();
        let keep: BTreeSet<&String> = all_paths.iter().collect();
        self.files.retain(|k, _| keep.contains(k));
        self.files.extend(written);
        self.profiles = new_profiles;
        self.warnings = new_warnings;
        self.catalog = catalog;
        Ok(UpdateReport { rendered, full })
    }

    /// Re-reads everything (after a configuration or theme change).
    pub fn reload(&mut self, opts: &BuildOptions) -> Result<()> {
        *self = Workspace::open(opts)?;
        Ok(())
    }
}
