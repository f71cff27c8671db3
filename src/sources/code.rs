//! The source files of a git revision the implementation check reads
//! ([`crate::implementation`]), for `[[source]]` repositories and `diff REV:PATH` sides alike:
//! those beside the profiles (as `implementation::find` looks for them), and the files holding
//! a spec array anywhere with the headers of their folder (components that have code and no
//! profile, [`crate::implementation::recover`]). They are written cut at the size limit.

use anyhow::Result;
use std::path::Path;

/// Which code to read: whether the implementation check is on, and the files
/// `[[implementation.component]]` names (relative to a profile's folder).
#[derive(Debug, Clone, Default)]
pub struct Selection {
    pub enabled: bool,
    pub named: Vec<String>,
}

/// How deep below a profile's folder the implementation check looks for the files named after
/// the component, and how many entries it looks at (`implementation::find`).
const SOURCE_DEPTH: usize = 5;
const SOURCES_PER_FOLDER: usize = 2_000;

/// A file the implementation check reads by its extension (C++, Python, Java), at a safe
/// path outside hidden folders (the check's walk does not enter them).
pub(crate) fn is_source_file(rel: &str) -> bool {
    let p = Path::new(rel);
    crate::implementation::language_of(p).is_some()
        && p.components().all(
        |c| matches!(c, std::path::Component::Normal(n) if !n.to_string_lossy().starts_with('.')),
    )
}

/// Of the source files `(sha, path)` of a revision, those the implementation check could read
/// for the profiles among `profiles` (the profile-like files copied): below a profile's folder,
/// at most [`SOURCE_DEPTH`] levels down (RTCBuilder's layout is 1–3), the shallowest
/// [`SOURCES_PER_FOLDER`] of each folder; and the files `[[implementation.component]]` names,
/// at any depth. Their size is bounded when they are written.
pub(crate) fn implementation_files(
    profiles: &[(String, String)],
    sources: &[(String, String)],
    settings: &Selection,
) -> Vec<(String, String)> {
    use std::collections::{BTreeMap, BTreeSet};
    let folder = |rel: &str| rel.rsplit_once('/').map_or("", |(d, _)| d).to_string();
    let dirs: BTreeSet<String> = profiles
        .iter()
        .filter(|(_, rel)| {
            let ext = Path::new(rel)
                .extension()
                .and_then(|e| e.to_str())
                .map(str::to_ascii_lowercase);
            !matches!(ext.as_deref(), Some("idl"))
        })
        .map(|(_, rel)| folder(rel))
        .collect();
    let named: BTreeSet<&str> = settings.named.iter().map(String::as_str).collect();
    // Per profile folder, its candidates by depth below it.
    let mut per_dir: BTreeMap<&str, Vec<(usize, usize)>> = BTreeMap::new();
    let mut keep = vec![false; sources.len()];
    for (i, (_, rel)) in sources.iter().enumerate() {
        for dir in &dirs {
            let below = if dir.is_empty() {
                Some(rel.as_str())
            } else {
                rel.strip_prefix(dir.as_str())
                    .and_then(|r| r.strip_prefix('/'))
            };
            let Some(below) = below else { continue };
            if named.contains(below) {
                keep[i] = true;
            }
            let depth = below.split('/').count();
            if depth <= SOURCE_DEPTH {
                per_dir.entry(dir).or_default().push((depth, i));
            }
        }
    }
    for v in per_dir.values_mut() {
        v.sort_by(|a, b| (a.0, &sources[a.1].1).cmp(&(b.0, &sources[b.1].1)));
        for &(_, i) in v.iter().take(SOURCES_PER_FOLDER) {
            keep[i] = true;
        }
    }
    sources
        .iter()
        .zip(keep)
        .filter(|(_, k)| *k)
        .map(|(s, _)| s.clone())
        .collect()
}

/// Writes below `dest` the files of `code` (`(sha, path)`: the revision's source files) that
/// the implementation check reads for the `profiles` written there (`(sha, path)` too): those
/// [`implementation_files`] selects, and the files holding a spec array
/// (`implementation_id`) with the headers of their component folder. Each is cut at `max`
/// (one byte more, so that the check reports a larger file as not read, RTC811, as on disk).
pub(crate) fn write(
    reader: &mut super::objects::ObjectReader,
    profiles: &[(String, String)],
    code: Vec<(String, String)>,
    dest: &mut dyn super::Sink,
    settings: &Selection,
    max: u64,
) -> Result<()> {
    if !settings.enabled || code.is_empty() {
        return Ok(());
    }
    use crate::implementation::recover::component_folder;
    let beside = implementation_files(profiles, &code, settings);
    let taken: std::collections::HashSet<&str> = beside.iter().map(|(_, r)| r.as_str()).collect();
    // The files that may hold a spec array (not headers), written only when they do.
    let (spec_like, headers): (Vec<_>, Vec<_>) = code
        .iter()
        .filter(|(_, r)| !taken.contains(r.as_str()))
        .cloned()
        .partition(|(_, r)| crate::walk::is_code_file(Path::new(r)));
    super::write_blobs(reader, &beside, dest, max)?;
    let with_spec = super::write_blobs_where(reader, &spec_like, dest, max, &|body| {
        memchr::memmem::find(body, b"implementation_id").is_some()
    })?;
    let folders: std::collections::HashSet<&str> =
        with_spec.iter().map(|r| component_folder(r)).collect();
    // The headers below each such folder, as `implementation::find` looks for them.
    let mut companions: Vec<(usize, (String, String))> = headers
        .into_iter()
        .filter_map(|h| {
            let depth = folders
                .iter()
                .filter_map(|f| {
                    let below = if f.is_empty() {
                        Some(h.1.as_str())
                    } else {
                        h.1.strip_prefix(f).and_then(|r| r.strip_prefix('/'))
                    }?;
                    Some(below.split('/').count())
                })
                .min()?;
            (depth <= SOURCE_DEPTH).then_some((depth, h))
        })
        .collect();
    companions.sort_by(|a, b| (a.0, &a.1 .1).cmp(&(b.0, &b.1 .1)));
    let companions: Vec<(String, String)> = companions
        .into_iter()
        .take(SOURCES_PER_FOLDER)
        .map(|(_, h)| h)
        .collect();
    super::write_blobs(reader, &companions, dest, max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn source_files_beside_profiles_are_copied() {
        let sha = |rel: &str| (format!("sha-{rel}"), rel.to_string());
        let profiles = [sha("comp/A/RTC.xml"), sha("idl/Nav.idl")];
        let sources = [
            "comp/A/src/A.cpp",
            "comp/A/include/A/A.h",
            "comp/A/a/b/c/d/e/too_deep.cpp",
            "comp/A/a/b/c/d/five.py",
            "comp/B/src/B.cpp",
            "idl/gen/Nav.cpp",
            "comp/A/x/y/z/w/v/Named.java",
        ]
        .map(sha)
        .to_vec();
        let settings = Selection {
            enabled: true,
            named: vec!["x/y/z/w/v/Named.java".into()],
        };
        let kept: Vec<String> = implementation_files(&profiles, &sources, &settings)
            .into_iter()
            .map(|(_, rel)| rel)
            .collect();
        assert_eq!(
            kept,
            [
                "comp/A/src/A.cpp",
                "comp/A/include/A/A.h",
                "comp/A/a/b/c/d/five.py",
                "comp/A/x/y/z/w/v/Named.java",
            ]
        );
        assert!(is_source_file("a/B.HPP") && is_source_file("B.py"));
        assert!(!is_source_file("a/.hidden/B.cpp") && !is_source_file("a/B.txt"));
    }
}
