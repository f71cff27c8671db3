//! An in-memory site that can be updated when single profiles change (for `rtcdoc serve`).
//!
//! The workspace keeps the last good parse of every profile, the catalogue and the rendered
//! files. [`Workspace::update`] re-reads only the changed files, rebuilds the catalogue (cheap,
//! O(n)) and re-renders only the pages whose content can have changed: the changed component's
//! page, the pages of the data types and interfaces it used before or uses now, the pages of the
//! components connected through them, and the index pages. A profile that no longer parses
//! leaves the last good site in place and reports its diagnostics.

use crate::build::{add_check_diagnostics, load, BuildOptions};
use crate::catalog::{Catalog, Component, Ix, LoadedProfile, PageKind};
use crate::diagnostic::Diagnostic;
use crate::output::MemorySink;
use crate::parse;
use crate::render::html::HtmlRenderer;
use crate::render::RenderContext;
use crate::walk;
use anyhow::Result;
use std::collections::{BTreeMap, BTreeSet, HashMap};
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
    /// Where the catalogue's files are (with the sources' folder, kept alive).
    roots: crate::catalog::sources::Roots,
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

/// What a component shows on *other* pages (type and interface pages, peers' "connects to"
/// lists): its name, slug and anchors, and the name, type, IDL file and direction of every port
/// and interface. When this is unchanged, no other component's or type's page can change.
fn link_signature(c: &Component) -> String {
    let p = &c.profile;
    let mut s = format!("{}\u{0}{}\u{0}{:?}", p.name(), c.slug, c.anchors);
    for d in &p.data_ports {
        s.push_str(&format!(
            "\u{1}{:?}{:?}{:?}{:?}",
            d.name, d.type_, d.idl_file, d.port_type
        ));
    }
    for sp in &p.service_ports {
        s.push_str(&format!("\u{2}{:?}", sp.name));
        for i in &sp.interfaces {
            s.push_str(&format!(
                "\u{3}{:?}{:?}{:?}{:?}",
                i.name, i.type_, i.idl_file, i.direction
            ));
        }
    }
    s
}

/// Pages of the types and interfaces component `ci` of `cat` uses and of the components
/// connected to it through them.
fn peer_pages(cat: &Catalog, comp: &Component, set: &mut BTreeSet<String>) {
    let component_page = |id: &str| {
        cat.component_index(id)
            .map(|ci| cat.component_page(ci).path("html"))
    };
    for p in &comp.profile.data_ports {
        if let Some(ti) = p.type_.as_deref().and_then(|t| cat.data_type_index(t)) {
            set.insert(cat.data_type_page(ti).path("html"));
            let t = &cat[ti];
            for r in t.all_uses() {
                set.extend(component_page(&r.component));
            }
        }
    }
    for sp in &comp.profile.service_ports {
        for i in &sp.interfaces {
            if let Some(ii) = i.type_.as_deref().and_then(|t| cat.interface_index_of(t)) {
                set.insert(cat.interface_page(ii).path("html"));
                let t = &cat[ii];
                for r in t.all_uses() {
                    set.extend(component_page(&r.component));
                }
            }
        }
    }
}

/// A changed profile read again, with its reader warnings.
type Reread = (LoadedProfile, Vec<Diagnostic>);

/// What the old site looked like, taken before the old catalogue is consumed.
struct Before {
    slugs: Vec<(String, String)>,
    names: [BTreeMap<String, String>; 4],
    had_diagnostics: bool,
    /// Per changed source: its link signature and the peer pages on the old site.
    changed: BTreeMap<String, (String, BTreeSet<String>)>,
}

fn slug_maps(c: &Catalog) -> [BTreeMap<String, String>; 4] {
    let m =
        |v: Vec<(&String, &String)>| v.into_iter().map(|(a, b)| (a.clone(), b.clone())).collect();
    [
        m(c.data_types.iter().map(|t| (&t.name, &t.slug)).collect()),
        m(c.interfaces.iter().map(|t| (&t.name, &t.slug)).collect()),
        m(c.categories.iter().map(|t| (&t.name, &t.slug)).collect()),
        m(c.vendors.iter().map(|t| (&t.name, &t.slug)).collect()),
    ]
}

impl Before {
    fn of(old: &Catalog, changed: &[String]) -> Before {
        let mut ch = BTreeMap::new();
        for src in changed {
            if let Some(c) = old.components.iter().find(|c| &c.source == src) {
                let mut set = BTreeSet::new();
                peer_pages(old, c, &mut set);
                ch.insert(src.clone(), (link_signature(c), set));
            }
        }
        Before {
            slugs: old
                .components
                .iter()
                .map(|x| (x.source.clone(), x.slug.clone()))
                .collect(),
            names: slug_maps(old),
            had_diagnostics: !old.diagnostics.is_empty(),
            changed: ch,
        }
    }
}

/// The pages that can differ between the old site and the site of `new` when only the profiles
/// in `changed` (sources) differ; `None` when everything must be rendered again (a component was
/// added, removed or renamed, a slug moved, or the diagnostics page appeared or vanished —
/// every page's navigation links to it).
fn affected(before: &Before, new: &Catalog, changed: &[String]) -> Option<BTreeSet<String>> {
    let slugs: Vec<(String, String)> = new
        .components
        .iter()
        .map(|x| (x.source.clone(), x.slug.clone()))
        .collect();
    if slugs != before.slugs || before.had_diagnostics == new.diagnostics.is_empty() {
        return None;
    }
    // A type, interface or facet that exists on both sides must keep its slug.
    for (old, new) in before.names.iter().zip(slug_maps(new).iter()) {
        if new.iter().any(|(n, s)| old.get(n).is_some_and(|o| o != s)) {
            return None;
        }
    }
    use crate::catalog::PageKind;
    let mut set: BTreeSet<String> = [
        PageKind::Index,
        PageKind::DataTypes,
        PageKind::Interfaces,
        PageKind::Diagnostics,
        PageKind::DataFlow,
    ]
    .into_iter()
    .map(|k| new.site_page(k).path("html"))
    .chain(["search-index.js", "sitemap.xml"].map(String::from))
    .chain(
        new.pages()
            .iter()
            .filter(|p| p.kind == PageKind::WhatsNew)
            .map(|p| p.path("html")),
    )
    .collect();
    for src in changed {
        let ci = new
            .components
            .iter()
            .position(|c| &c.source == src)
            .map(Ix::new)?;
        let comp = &new[ci];
        let (old_sig, old_peers) = before.changed.get(src)?;
        set.insert(new.component_page(ci).path("html"));
        if let Some(h) = new.history_page(ci) {
            set.insert(h.path("html"));
        }
        if *old_sig != link_signature(comp) {
            // Its ports or name changed: every page listing them, before and after.
            set.extend(old_peers.iter().cloned());
            peer_pages(new, comp, &mut set);
        }
    }
    Some(set)
}

impl Workspace {
    /// Loads and renders everything.
    pub fn open(opts: &BuildOptions) -> Result<Workspace> {
        let mut loaded = load(&opts.input, &opts.load)?;
        // The history, as `build` reads it.
        if let Some(read_history) = opts.load.history_reader.filter(|_| opts.load.history > 0) {
            read_history(&mut loaded.catalog, &loaded.roots, &opts.load);
            loaded.catalog.history_attached();
        }
        let input_root = crate::build::input_root(&opts.input);
        let mut warnings: BTreeMap<String, Vec<Diagnostic>> = BTreeMap::new();
        // Only the readers' diagnostics are kept per file: the catalogue adds its own
        // (duplicate ids) and the READMEs' again whenever it is rebuilt.
        for d in loaded.catalog.diagnostics.iter().filter(|d| {
            d.code != crate::diagnostic::codes::DUPLICATE_ID
                && d.code != crate::diagnostic::codes::ORPHAN_BACKUP
                && d.code != crate::diagnostic::codes::DUPLICATE_ACROSS_SOURCES
                && !crate::readme::CODES.contains(&d.code)
        }) {
            warnings.entry(d.file.clone()).or_default().push(d.clone());
        }
        let mut catalog = loaded.catalog;
        add_check_diagnostics(&mut catalog);
        let (files, _) = render(opts, &catalog, &|_| true)?;
        Ok(Workspace {
            opts: opts.clone(),
            input_root,
            roots: loaded.roots,
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
        // Paths outside the input (e.g. the theme) are not profiles of this workspace.
        abs.starts_with(&root)
            .then(|| crate::walk::rel_path(&root, &abs))
    }

    /// Applies changes to the given files (created, modified or deleted).
    pub fn update(
        &mut self,
        changed: &[PathBuf],
    ) -> std::result::Result<UpdateReport, UpdateError> {
        // Read the changed files first: an error leaves everything as it was.
        // An RT System profile added, changed or removed: everything is read again (systems
        // link to components and are listed on their pages; they are few).
        // A README or an image one shows: the same (READMEs are read for every folder).
        // An RTCBuilder backup: the same (a save in RTCBuilder writes one beside the profile).
        if changed.iter().any(|p| {
            self.is_system_file(p)
                    || self.is_readme_file(p)
                    || walk::is_backup(p)
                    // Source code: the implementations, and the components recovered from it.
                    || (self.opts.load.implementation.enabled
                        && crate::implementation::recover::is_code_file(p))
        }) {
            let opts = self.opts.clone();
            self.reload(&opts)
                .map_err(|e| UpdateError::Other(format!("{e:#}")))?;
            return Ok(UpdateReport {
                rendered: self.files.len(),
                full: true,
            });
        }
        let mut errors = Vec::new();
        let mut replaced: Vec<(String, Option<Reread>)> = Vec::new();
        let load = &self.opts.load;
        for path in changed {
            let Some(rel) = self.rel(path) else { continue };
            let bytes = if path.exists() {
                walk::read_at_most(path, load.limits.max_file_size.saturating_add(1)).ok()
            } else {
                None
            };
            let format = bytes.as_deref().and_then(|b| walk::detect(path, b));
            match (bytes, format) {
                (Some(bytes), Some(format)) => {
                    match parse::parse(format, &bytes, &rel, &load.limits) {
                        Ok(p) => replaced.push((
                            rel.clone(),
                            Some((
                                LoadedProfile {
                                    source: rel,
                                    format,
                                    profile: Box::new(p.profile),
                                },
                                p.diagnostics,
                            )),
                        )),
                        Err(d) => errors.push(d),
                    }
                }
                // Deleted, or no longer a profile.
                _ => {
                    if self.catalog.components.iter().any(|c| c.source == rel) {
                        replaced.push((rel, None));
                    }
                }
            }
        }
        if !errors.is_empty() {
            return Err(UpdateError::Profiles(errors));
        }
        if replaced.is_empty() {
            return Ok(UpdateReport::default());
        }
        let touched: Vec<String> = replaced.iter().map(|(r, _)| r.clone()).collect();
        let before = Before::of(&self.catalog, &touched);

        // Move the profiles out of the old catalogue (no copies), apply the changes, rebuild.
        let mut old = std::mem::replace(&mut self.catalog, Catalog::build(Vec::new(), Vec::new()));
        // Profiles changed, not IDL (a changed IDL file reloads everything: see `serve`).
        let idl = std::mem::take(&mut old.idl);
        let idl_history = std::mem::take(&mut old.idl_history);
        // The histories are kept: only the edited profiles' are read again (below).
        let mut histories: HashMap<String, Vec<crate::catalog::history::Entry>> = HashMap::new();
        let systems: Vec<crate::catalog::systems::LoadedSystem> = std::mem::take(&mut old.systems)
            .into_iter()
            .map(Into::into)
            .collect();
        let mut backups = std::mem::take(&mut old.detached_backups);
        let mut recovered = BTreeMap::new();
        let mut profiles: BTreeMap<String, LoadedProfile> = old
            .components
            .into_iter()
            .map(|mut c| {
                backups.append(&mut c.backups);
                if let (Some(r), Some(i)) = (c.recovered.take(), c.implementation.take()) {
                    recovered.insert(
                        c.source.clone(),
                        crate::catalog::implementations::Recovery {
                            implementation: i,
                            recovered: r,
                        },
                    );
                }
                histories.insert(c.source.clone(), std::mem::take(&mut c.history));
                (
                    c.source.clone(),
                    LoadedProfile {
                        source: c.source,
                        format: c.format,
                        profile: c.profile,
                    },
                )
            })
            .collect();
        for (rel, new) in replaced {
            match new {
                Some((p, diags)) => {
                    profiles.insert(rel.clone(), p);
                    self.warnings.insert(rel, diags);
                }
                None => {
                    profiles.remove(&rel);
                    self.warnings.remove(&rel);
                }
            }
        }
        let diags: Vec<Diagnostic> = self.warnings.values().flatten().cloned().collect();
        let docs = crate::catalog::Documents {
            profiles: profiles.into_values().collect(),
            diagnostics: diags,
            idl,
            systems,
            backups,
            // A README may have come since the walk: every component folder is looked in.
            readme_dirs: None,
            implementation: crate::catalog::implementations::Settings {
                max_file_size: self.opts.load.limits.max_file_size,
                ..self.opts.load.implementation.clone()
            },
            recovered,
            stability: self.opts.load.stability.clone(),
        };
        let mut catalog = Catalog::assemble(
            docs,
            &self.roots,
            &walk::exclude_matcher(&self.opts.load.exclude),
        );
        for c in &mut catalog.components {
            c.history = histories.remove(&c.source).unwrap_or_default();
        }
        catalog.idl_history = idl_history;
        if self.opts.load.history_reader.is_some() {
            let edited: BTreeSet<String> = touched.iter().cloned().collect();
            crate::history::attach_some(&mut catalog, &self.roots, &self.opts.load, &edited);
            catalog.history_attached();
        }
        add_check_diagnostics(&mut catalog);
        self.catalog = catalog;

        let plan = affected(&before, &self.catalog, &touched);
        let full = plan.is_none();
        // Re-rendered on every change: the diagnostics pages and the category, vendor and
        // system pages (and the files beside them), by the folders the page list puts them in.
        let folders: Vec<String> = self
            .catalog
            .pages()
            .iter()
            .filter(|pg| {
                matches!(
                    pg.kind,
                    PageKind::Diagnostics
                        | PageKind::Category
                        | PageKind::Vendor
                        | PageKind::System
                )
            })
            .map(|pg| match pg.kind {
                PageKind::Diagnostics => format!("{}/", pg.stem),
                _ => pg
                    .stem
                    .rsplit_once('/')
                    .map_or(String::new(), |(d, _)| format!("{d}/")),
            })
            .filter(|f| !f.is_empty())
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        let wanted = |p: &str| match &plan {
            None => true,
            Some(set) => set.contains(p) || folders.iter().any(|f| p.starts_with(f.as_str())),
        };
        let (written, all_paths) = render(&self.opts, &self.catalog, &wanted)
            .map_err(|e| UpdateError::Other(format!("{e:#}")))?;
        let rendered = written.len();
        let keep: BTreeSet<&String> = all_paths.iter().collect();
        self.files.retain(|k, _| keep.contains(k));
        self.files.extend(written);
        Ok(UpdateReport { rendered, full })
    }

    /// Whether `path` is (now) an RT System profile or was one of the catalogue's.
    fn is_system_file(&self, path: &Path) -> bool {
        let Some(rel) = self.rel(path) else {
            return false;
        };
        if self.catalog.systems.iter().any(|s| s.source == rel) {
            return true;
        }
        let is_candidate = path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| walk::is_document_extension(&e.to_ascii_lowercase()));
        is_candidate
            && walk::read_at_most(path, walk::SNIFF_BYTES)
                .map(|b| parse::rts::is_system(&b))
                .unwrap_or(false)
    }

    /// Whether `path` is named like a README, or is an image (a README may show it, or have
    /// been missing it).
    fn is_readme_file(&self, path: &Path) -> bool {
        let image = path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
            crate::readme::IMAGE_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str())
        });
        (image || crate::readme::is_readme_path(path)) && self.rel(path).is_some()
    }

    /// Re-reads everything (after a configuration or theme change).
    pub fn reload(&mut self, opts: &BuildOptions) -> Result<()> {
        *self = Workspace::open(opts)?;
        Ok(())
    }
}
