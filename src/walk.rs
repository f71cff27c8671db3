//! Directory walk: finds profile files anywhere below the input.
//!
//! A file is a profile by its content, not its name (RTCBuilder leaves backups such as
//! `RTC.xml20230831164412.xml`): `*.xml` whose root element is `RtcProfile`, and `*.yaml`/`*.yml`
//! with a top-level `rtcProfile` key. Everything else is skipped quietly (reported as
//! [`Skipped`] for `--verbose`). Symlinks are not followed, so cycles cannot loop; the output
//! directory is skipped when it lies inside the input; the order is sorted and stable.

use crate::parse::{self, SourceFormat};
use globset::{Glob, GlobSet, GlobSetBuilder};
use std::path::{Path, PathBuf};

/// A profile file found by the walk. Its bytes are read when it is parsed, so a large
/// catalogue is never held in memory as text all at once.
#[derive(Debug, Clone)]
pub struct Source {
    /// Absolute or input-relative path on disk.
    pub path: PathBuf,
    /// Path relative to the input directory, with forward slashes (used in output and JSON).
    pub rel: String,
    pub format: SourceFormat,
}

/// How much of a file the walk reads to recognise a profile.
const SNIFF_BYTES: u64 = 64 * 1024;

/// A file the walk looked at and did not take, with the reason.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Skipped {
    pub rel: String,
    pub reason: String,
}

/// Options of a walk.
#[derive(Debug, Clone, Default)]
pub struct WalkOptions {
    /// Glob patterns (matched against the input-relative path) to take; empty = every file.
    pub include: Vec<String>,
    /// Glob patterns (matched against the input-relative path) to leave out.
    pub exclude: Vec<String>,
    /// Directories never to enter (e.g. the output directory).
    pub skip_dirs: Vec<PathBuf>,
}

/// What a walk found.
#[derive(Debug, Default)]
pub struct WalkResult {
    pub sources: Vec<Source>,
    pub skipped: Vec<Skipped>,
    /// Files that looked like profiles but could not be read (I/O errors).
    pub errors: Vec<crate::diagnostic::Diagnostic>,
}

/// Errors that stop a walk before it starts.
#[derive(Debug, thiserror::Error)]
pub enum WalkError {
    #[error("input `{0}` does not exist")]
    Missing(PathBuf),
    #[error("invalid exclude pattern `{pattern}`: {message}")]
    BadGlob { pattern: String, message: String },
}

/// Guesses the format of a file from its extension and content; `None` when it is not an RTC
/// component profile.
pub fn detect(path: &Path, bytes: &[u8]) -> Option<SourceFormat> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase());
    match ext.as_deref() {
        Some("xml") if parse::xml::is_profile(bytes) => Some(SourceFormat::Xml),
        Some("yaml") | Some("yml") if parse::yaml::is_profile(bytes) => Some(SourceFormat::Yaml),
        _ => None,
    }
}

fn build_globs(patterns: &[String]) -> Result<GlobSet, WalkError> {
    let mut b = GlobSetBuilder::new();
    for p in patterns {
        let g = Glob::new(p).map_err(|e| WalkError::BadGlob {
            pattern: p.clone(),
            message: e.to_string(),
        })?;
        b.add(g);
    }
    b.build().map_err(|e| WalkError::BadGlob {
        pattern: patterns.join(", "),
        message: e.to_string(),
    })
}

/// `path` relative to `root`, with forward slashes (its file name when it is `root` itself).
pub(crate) fn rel_path(root: &Path, path: &Path) -> String {
    let rel = path.strip_prefix(root).unwrap_or(path);
    let s: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if s.is_empty() {
        path.file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default()
    } else {
        s.join("/")
    }
}

/// Walks `input` (a directory or a single file) and returns the profiles found, sorted by
/// their relative path.
pub fn walk(input: &Path, opts: &WalkOptions) -> Result<WalkResult, WalkError> {
    let Candidates {
        files: candidates,
        skipped,
    } = candidates(input, opts)?;
    let mut result = WalkResult {
        skipped,
        ..WalkResult::default()
    };
    // Recognising profiles reads the head of every candidate: done in parallel.
    use rayon::prelude::*;
    let sniffed: Vec<(PathBuf, String, std::io::Result<Option<SourceFormat>>)> = candidates
        .into_par_iter()
        .map(|(path, rel)| {
            let r = sniff(&path).map(|(_, _, format)| format);
            (path, rel, r)
        })
        .collect();
    for (path, rel, r) in sniffed {
        match r {
            Ok(Some(format)) => result.sources.push(Source { path, rel, format }),
            Ok(None) => result.skipped.push(not_a_profile(rel)),
            Err(e) => result
                .errors
                .push(crate::diagnostic::Diagnostic::io(&rel, &e)),
        }
    }
    result.sources.sort_by(|a, b| a.rel.cmp(&b.rel));
    Ok(result)
}

/// The files a walk considers: every `.xml`/`.yaml`/`.yml` file the patterns let through, in
/// walk order, before their content is looked at; and the files left out on the way.
pub(crate) struct Candidates {
    pub files: Vec<(PathBuf, String)>,
    pub skipped: Vec<Skipped>,
}

/// The [`Skipped`] entry of a candidate whose content is not a profile.
pub(crate) fn not_a_profile(rel: String) -> Skipped {
    Skipped {
        rel,
        reason: "not an RTC component profile (root is not RtcProfile / rtcProfile)".into(),
    }
}

/// Opens a candidate and reads its head: the open file (positioned after the head), the head
/// and the format when the head shows a profile.
fn sniff(path: &Path) -> std::io::Result<(std::fs::File, Vec<u8>, Option<SourceFormat>)> {
    use std::io::Read;
    let mut f = std::fs::File::open(path)?;
    let mut head = Vec::new();
    (&mut f)
        .take(SNIFF_BYTES.saturating_add(1))
        .read_to_end(&mut head)?;
    let format = detect(path, &head);
    Ok((f, head, format))
}

/// Reads a candidate file once: its head, to recognise a profile exactly as [`walk`] does, and
/// when it is one, the rest — at most `limit + 1` bytes in all, so that an oversized file is
/// detected without reading it whole. `None` when the file is not a profile.
pub(crate) fn read_profile(
    path: &Path,
    limit: u64,
) -> std::io::Result<Option<(SourceFormat, Vec<u8>)>> {
    use std::io::Read;
    let (f, mut buf, format) = sniff(path)?;
    let Some(format) = format else {
        return Ok(None);
    };
    let cap = limit.saturating_add(1);
    let have = buf.len() as u64;
    if have > cap {
        buf.truncate(usize::try_from(cap).unwrap_or(usize::MAX));
    } else {
        f.take(cap - have).read_to_end(&mut buf)?;
    }
    Ok(Some((format, buf)))
}

/// The traversal part of [`walk`]: which files are candidates, without reading any.
pub(crate) fn candidates(input: &Path, opts: &WalkOptions) -> Result<Candidates, WalkError> {
    if !input.exists() {
        return Err(WalkError::Missing(input.to_path_buf()));
    }
    let globs = build_globs(&opts.exclude)?;
    let includes = build_globs(&opts.include)?;
    let skip_dirs: Vec<PathBuf> = opts
        .skip_dirs
        .iter()
        .filter_map(|d| d.canonicalize().ok())
        .collect();
    // Canonicalizing every directory of a large tree costs a path resolution each; on Unix
    // only a directory with the inode number of a skipped one needs it.
    #[cfg(unix)]
    let skip_inodes: Vec<u64> = {
        use std::os::unix::fs::MetadataExt;
        skip_dirs
            .iter()
            .filter_map(|d| std::fs::metadata(d).ok().map(|m| m.ino()))
            .collect()
    };
    let may_be_skipped = |e: &walkdir::DirEntry| -> bool {
        if skip_dirs.is_empty() {
            return false;
        }
        #[cfg(unix)]
        {
            use walkdir::DirEntryExt;
            skip_inodes.contains(&e.ino())
        }
        #[cfg(not(unix))]
        {
            let _ = e;
            true
        }
    };
    let mut result = WalkResult::default();
    let mut candidates: Vec<(PathBuf, String)> = Vec::new();
    let root = if input.is_file() {
        input.parent().unwrap_or(Path::new(".")).to_path_buf()
    } else {
        input.to_path_buf()
    };
    let walker = walkdir::WalkDir::new(input)
        .follow_links(false)
        .sort_by_file_name()
        .into_iter()
        .filter_entry(|e| {
            if e.depth() > 0 && e.file_type().is_dir() {
                if may_be_skipped(e) {
                    if let Ok(c) = e.path().canonicalize() {
                        if skip_dirs.contains(&c) {
                            return false;
                        }
                    }
                }
                // Hidden directories (.git, .svn, .cache) hold no profiles of interest.
                if e.file_name().to_string_lossy().starts_with('.') {
                    return false;
                }
            }
            true
        });
    for entry in walker {
        let entry = match entry {
            Ok(e) => e,
            Err(e) => {
                let rel = e
                    .path()
                    .map(|p| rel_path(&root, p))
                    .unwrap_or_else(|| input.display().to_string());
                result.skipped.push(Skipped {
                    rel,
                    reason: format!("cannot be read: {e}"),
                });
                continue;
            }
        };
        if !entry.file_type().is_file() {
            if entry.file_type().is_symlink() {
                result.skipped.push(Skipped {
                    rel: rel_path(&root, entry.path()),
                    reason: "symbolic link (not followed)".into(),
                });
            }
            continue;
        }
        let path = entry.path();
        let rel = rel_path(&root, path);
        if globs.is_match(&rel) {
            result.skipped.push(Skipped {
                rel,
                reason: "excluded by pattern".into(),
            });
            continue;
        }
        if !opts.include.is_empty() && !includes.is_match(&rel) {
            result.skipped.push(Skipped {
                rel,
                reason: "not matched by an include pattern".into(),
            });
            continue;
        }
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase());
        if !matches!(ext.as_deref(), Some("xml" | "yaml" | "yml")) {
            result.skipped.push(Skipped {
                rel,
                reason: "not an .xml/.yaml/.yml file".into(),
            });
            continue;
        }
        candidates.push((path.to_path_buf(), rel));
    }
    Ok(Candidates {
        files: candidates,
        skipped: result.skipped,
    })
}
