//! The `[[source]]` repositories of a catalogue: where each document's files are on disk
//! ([`Roots`]), and which source, commit and repository path each document comes from
//! ([`Catalog::attach_sources`]).

use super::Catalog;
use crate::diagnostic::{codes, Diagnostic};
use crate::model::SourceInfo;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Where the files of a catalogue are: the input directory, and the temporary folder holding
/// the files read from the `[[source]]` repositories (`<dir>/<name>/<path in the repository>`).
#[derive(Debug, Clone, Default)]
pub struct Roots {
    /// The input directory (or the folder of an input file).
    pub local: PathBuf,
    /// The folder of the sources' files, kept as long as a catalogue may read from it (README
    /// images are copied when the site is rendered).
    pub sources_dir: Option<Arc<tempfile::TempDir>>,
    /// The sources read, by name.
    pub sources: Vec<SourceInfo>,
    /// Whether `local` is in a git work tree, asked when the build started
    /// ([`Roots::work_tree`] takes the answer once).
    pub work_tree_probe: Arc<std::sync::Mutex<Option<crate::sources::WorkTreeProbe>>>,
}

impl Roots {
    /// Only an input directory.
    pub fn local(dir: &Path) -> Roots {
        Roots {
            local: dir.to_path_buf(),
            ..Roots::default()
        }
    }

    /// Starts asking git whether `local` is in a work tree, for [`Roots::work_tree`] to take
    /// the answer later (git's start-up then overlaps other work).
    pub fn start_work_tree_probe(&mut self) {
        self.work_tree_probe = Arc::new(std::sync::Mutex::new(Some(
            crate::sources::WorkTreeProbe::start(&self.local),
        )));
    }

    /// Whether `local` is in a git work tree: the answer of the probe the build started, the
    /// first time; asked again afterwards (`serve` reads histories again after edits, and the
    /// folder may have become a repository meanwhile).
    pub fn work_tree(&self) -> crate::sources::WorkTree {
        let probe = self
            .work_tree_probe
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .take();
        probe
            .unwrap_or_else(|| crate::sources::WorkTreeProbe::start(&self.local))
            .wait()
    }

    /// The source a catalogue path (`<name>/…`) belongs to.
    pub fn source_of(&self, rel: &str) -> Option<&SourceInfo> {
        let first = rel.split('/').next()?;
        self.sources.iter().find(|s| s.name == first)
    }

    /// The directory `rel` (a catalogue path) is relative to.
    pub fn dir_of(&self, rel: &str) -> &Path {
        match (&self.sources_dir, self.source_of(rel)) {
            (Some(d), Some(_)) => d.path(),
            _ => &self.local,
        }
    }
}

impl Catalog {
    /// Records the sources and gives every component, system and IDL file read from one its
    /// [`crate::model::Origin`]. A component id declared in two sources (or in a source and the
    /// input directory) is reported as RTC014 on each profile, naming the others, instead of
    /// RTC010; both stay in the catalogue.
    pub fn attach_sources(&mut self, sources: Vec<SourceInfo>) {
        if sources.is_empty() {
            return;
        }
        self.set_origins(sources);
        self.cross_source_duplicates();
    }

    /// Records the sources and the origin of every document read from one (as
    /// [`Catalog::attach_sources`], without its findings: `catalog.json` read back has them).
    pub fn set_origins(&mut self, sources: Vec<SourceInfo>) {
        let origin = |rel: &str| {
            let first = rel.split('/').next()?;
            sources.iter().find(|s| s.name == first)?.origin_of(rel)
        };
        for c in &mut self.components {
            c.origin = origin(&c.source);
        }
        for s in &mut self.systems {
            s.origin = origin(&s.source);
        }
        for f in &mut self.idl.files {
            f.origin = origin(&f.path);
        }
        self.sources = sources;
    }

    /// RTC014: the same component id in two sources.
    fn cross_source_duplicates(&mut self) {
        let mut by_id: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
        for (i, c) in self.components.iter().enumerate() {
            let id = c.id.as_ref();
            // `@source` tells duplicates apart in the id; the id they share is before it.
            let shared = id
                .strip_suffix(c.source.as_str())
                .and_then(|a| a.strip_suffix('@'))
                .unwrap_or(id);
            by_id.entry(shared).or_default().push(i);
        }
        let label = |c: &super::Component| match &c.origin {
            Some(o) => format!("source `{}` (`{}`)", o.source, c.source),
            None => format!("the input directory (`{}`)", c.source),
        };
        let mut found: Vec<Diagnostic> = Vec::new();
        let mut recoded: Vec<&str> = Vec::new();
        for (id, idx) in &by_id {
            let mut from: Vec<Option<&str>> = idx
                .iter()
                .map(|&i| {
                    self.components[i]
                        .origin
                        .as_ref()
                        .map(|o| o.source.as_str())
                })
                .collect();
            from.sort();
            from.dedup();
            if idx.len() < 2 || from.len() < 2 {
                continue;
            }
            for &i in idx {
                let c = &self.components[i];
                // A few of the others, not all: a component copied into hundreds of sources
                // would make hundreds of messages each naming hundreds.
                let others: Vec<String> = idx
                    .iter()
                    .filter(|&&j| j != i)
                    .take(crate::diagnostic::A_FEW)
                    .map(|&j| label(&self.components[j]))
                    .collect();
                recoded.push(&c.source);
                found.push(
                    Diagnostic::warning(
                        codes::DUPLICATE_ACROSS_SOURCES,
                        &c.source,
                        format!(
                            "component id `{id}` of {} is also declared by {}",
                            label(c),
                            crate::diagnostic::a_few_of(&others, idx.len() - 1)
                        ),
                    )
                    .at(c.profile.pos)
                    .with_hint("if they are the same component, document it from one source only (its `path`, or --exclude); else give each its own id"),
                );
            }
        }
        if found.is_empty() {
            return;
        }
        let recoded: std::collections::HashSet<String> =
            recoded.into_iter().map(str::to_string).collect();
        self.diagnostics
            .retain(|d| !(d.code == codes::DUPLICATE_ID && recoded.contains(&d.file)));
        self.diagnostics.extend(found);
        crate::diagnostic::sort(&mut self.diagnostics);
    }
}
