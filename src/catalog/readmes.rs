//! Each component folder's README, attached to the components of that folder.

use super::Catalog;
use crate::diagnostic::Diagnostic;
use crate::readme::{read_folder, Readme};
use std::collections::BTreeMap;
use std::path::Path;

impl Catalog {
    /// Reads the README of every component folder (below the input at `root`), attaches it to
    /// the components of that folder and adds the findings (once per README). A README whose
    /// path `excluded` accepts (`--exclude`) is not read. With `only`, the folders the walk
    /// met an entry named like a README in, the other folders are not listed again.
    pub fn attach_readmes(
        &mut self,
        root: &super::sources::Roots,
        excluded: &(dyn Fn(&str) -> bool + Sync),
        only: Option<&std::collections::BTreeSet<String>>,
    ) {
        let mut folders: BTreeMap<String, Vec<usize>> = BTreeMap::new();
        for (ci, c) in self.components.iter().enumerate() {
            let dir = c.source.rsplit_once('/').map_or("", |(d, _)| d);
            if only.is_some_and(|o| !o.contains(dir)) {
                continue;
            }
            folders.entry(dir.to_string()).or_default().push(ci);
        }
        use rayon::prelude::*;
        let read: Vec<(Vec<usize>, Option<Readme>, Vec<Diagnostic>)> = folders
            .into_par_iter()
            .map(|(dir, members)| {
                let (readme, diags) = read_folder(root.dir_of(&dir), &dir, excluded);
                (members, readme, diags)
            })
            .collect();
        for (members, readme, diags) in read {
            if let Some(r) = readme {
                for &ci in &members {
                    self.components[ci].readme = Some(r.clone());
                }
            }
            self.diagnostics.extend(diags);
        }
        crate::diagnostic::sort(&mut self.diagnostics);
    }

    /// Every image file the READMEs show: (site path of the copy, file), each once, sorted by
    /// site path.
    pub fn readme_assets(&self) -> Vec<(&str, &Path)> {
        let mut all: BTreeMap<&str, &Path> = BTreeMap::new();
        for c in &self.components {
            for i in c.readme.iter().flat_map(|r| &r.images) {
                all.insert(&i.asset, &i.abs);
            }
        }
        all.into_iter().collect()
    }
}
