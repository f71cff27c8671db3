//! Each component's implementation, read from the source files beside its profile
//! ([`crate::implementation`]) and compared with it.

use super::Catalog;
use crate::implementation::{self, drift};
use rayon::prelude::*;

/// How implementations are read: `rtcdoc.toml`'s `[implementation]`.
#[derive(Debug, Clone)]
pub struct Settings {
    /// Read and compare implementations at all (`check = false` turns it off).
    pub enabled: bool,
    /// The largest source file read (the profiles' limit).
    pub max_file_size: u64,
    /// Files named per component (`[[implementation.component]]`): (component name or id glob,
    /// files relative to the profile's folder).
    pub files: Vec<(globset::GlobMatcher, Vec<String>)>,
}

impl Settings {
    /// The code a git revision's reading copies for these settings.
    pub fn selection(&self) -> crate::sources::code::Selection {
        crate::sources::code::Selection {
            enabled: self.enabled,
            named: self
                .files
                .iter()
                .flat_map(|(_, f)| f.iter().cloned())
                .collect(),
        }
    }
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            enabled: true,
            max_file_size: crate::parse::Limits::default().max_file_size,
            files: Vec::new(),
        }
    }
}

/// A component documented from its code alone: its implementation and what the code does
/// not say (the profile made from them is the component's).
#[derive(Debug, Clone)]
pub struct Recovery {
    pub implementation: Box<implementation::Implementation>,
    pub recovered: Box<implementation::recover::Recovered>,
}

/// The components of `code` (the source files of the walk) that no profile of `profiles`
/// documents, as profiles to load and their recoveries by source; the reading's findings.
pub fn recover(
    profiles: &[super::LoadedProfile],
    code: &[(std::path::PathBuf, String)],
    settings: &Settings,
) -> (
    Vec<super::LoadedProfile>,
    std::collections::BTreeMap<String, Recovery>,
    Vec<crate::diagnostic::Diagnostic>,
) {
    use implementation::recover::{find_all, profile_folders};
    let mut loaded = Vec::new();
    let mut by_source = std::collections::BTreeMap::new();
    if !settings.enabled || code.is_empty() {
        return (loaded, by_source, Vec::new());
    }
    let folders: std::collections::HashSet<String> = profiles
        .iter()
        .flat_map(|p| profile_folders(&p.source).map(str::to_string))
        .collect();
    let (found, diags) = find_all(code, &folders, settings.max_file_size);
    for f in found {
        loaded.push(super::LoadedProfile {
            source: f.source.clone(),
            format: crate::parse::SourceFormat::Xml,
            profile: Box::new(f.profile),
        });
        by_source.insert(
            f.source,
            Recovery {
                implementation: Box::new(f.implementation),
                recovered: Box::new(f.recovered),
            },
        );
    }
    (loaded, by_source, diags)
}

impl Catalog {
    /// Marks the components documented from their code alone ([`recover`]) and gives them
    /// the implementation they were read from.
    pub fn attach_recovered(
        &mut self,
        mut recovered: std::collections::BTreeMap<String, Recovery>,
    ) {
        if recovered.is_empty() {
            return;
        }
        for c in &mut self.components {
            if let Some(r) = recovered.remove(&c.source) {
                c.implementation = Some(r.implementation);
                c.recovered = Some(r.recovered);
            }
        }
    }

    /// Finds, reads and compares every component's implementation (in parallel, a component
    /// a task); the reading's findings join the catalogue's diagnostics.
    pub fn attach_implementations(
        &mut self,
        root: &super::sources::Roots,
        excluded: &(dyn Fn(&str) -> bool + Sync),
        settings: &Settings,
    ) {
        if !settings.enabled {
            return;
        }
        let read: Vec<_> = self
            .components
            .par_iter()
            .map(|c| {
                // A component recovered from its code has its code already (attach_recovered).
                if c.recovered.is_some() {
                    return None;
                }
                let dir = c.source.rsplit_once('/').map_or("", |(d, _)| d);
                let name = c.profile.basic_info.name.as_deref().unwrap_or("").trim();
                let id = c.id.as_str();
                let extra: &[String] = settings
                    .files
                    .iter()
                    .find(|(g, _)| g.is_match(name) || g.is_match(id))
                    .map_or(&[], |(_, f)| f.as_slice());
                let langs = implementation::languages(
                    c.profile.language.as_ref().and_then(|l| l.kind.as_deref()),
                );
                let abs = root.dir_of(&c.source).join(dir);
                let Some((lang, files)) = implementation::find(&abs, dir, name, &langs, extra)
                else {
                    return Some((None, Vec::new()));
                };
                let files: Vec<_> = files
                    .into_iter()
                    .filter(|(_, rel)| !excluded(rel))
                    .collect();
                if files.is_empty() {
                    return Some((None, Vec::new()));
                }
                let (imp, diags) = implementation::read(lang, &files, settings.max_file_size);
                let imp = imp.map(|mut i| {
                    i.drift = drift::compare(&c.profile, &i);
                    i.drift.shrink_to_fit();
                    i.keep_spec_the_profile_lacks();
                    Box::new(i)
                });
                Some((imp, diags))
            })
            .collect();
        for (c, read) in self.components.iter_mut().zip(read) {
            if let Some((imp, diags)) = read {
                c.implementation = imp;
                self.diagnostics.extend(diags);
            }
        }
        crate::diagnostic::sort(&mut self.diagnostics);
    }
}
