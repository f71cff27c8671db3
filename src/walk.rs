//! Directory walk: finds profile files anywhere below the input.
//!
//! A file is a profile by its content, not its name (RTCBuilder leaves backups such as
//! `RTC.xml20230831164412.xml`): `*.xml` whose root element is `RtcProfile`, and `*.yaml`/`*.yml`
//! with a top-level `rtcProfile` key. Everything else is skipped quietly (reported as
//! [`Skipped`] for `--verbose`). Symlinks are not followed, so cycles cannot loop; the output
//! directory is skipped when it lies inside the input; the order is sorted and stable.

use crate::parse::{self, SourceFormat};
use globset::{GlobSet, GlobSetBuilder};
use std::collections::BTreeSet;
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
pub(crate) const SNIFF_BYTES: u64 = 64 * 1024;

/// A file the walk looked at and did not take, with the reason.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Skipped {
    pub rel: String,
    pub reason: String,
    pub kind: SkipKind,
}

/// Why a file (or directory) was not taken: `--verbose` lists every kind but
/// [`SkipKind::OtherFile`], which it counts by extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum SkipKind {
    /// An `.xml`/`.yaml`/`.yml` file whose content is not an RTC component profile.
    NotAProfile,
    /// Left out by an `--exclude` pattern (a file, or a directory and everything below it).
    Excluded,
    /// Not matched by an `--include` pattern.
    NotIncluded,
    /// A symbolic link (not followed).
    Symlink,
    /// The file or directory could not be read.
    Unreadable,
    /// A file no profile can be in (`.cpp`, `.png`, …).
    OtherFile,
}

/// Whether `path`'s file name is one profile writers give a component profile: `RTC.xml`,
/// `RTC.yaml`, `RTC.yml`, `*.rtc.xml`, and RTCBuilder's backups `RTC.xml<timestamp>` (with or
/// without a further `.xml`). Such a file that is not a readable profile is worth a warning.
pub fn named_like_profile(path: &Path) -> bool {
    let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
        return false;
    };
    if matches!(name, "RTC.xml" | "RTC.yaml" | "RTC.yml") || name.ends_with(".rtc.xml") {
        return true;
    }
    is_backup_name(name)
}

/// Whether a file name is one of RTCBuilder's backups: `RTC.xml` followed by a timestamp of
/// digits, optionally ending in `.xml` (`RTC.xml20230831164412.xml` occurs too).
pub fn is_backup_name(name: &str) -> bool {
    backup_timestamp(name).is_some()
}

/// The digits after `RTC.xml` in a backup's name.
pub fn backup_timestamp(name: &str) -> Option<&str> {
    let rest = name.strip_prefix("RTC.xml")?;
    let digits = rest.strip_suffix(".xml").unwrap_or(rest);
    ((8..=17).contains(&digits.len()) && digits.bytes().all(|b| b.is_ascii_digit()))
        .then_some(digits)
}

/// Whether a (lower-case) extension is one a document may have: `.xml`, `.yaml`, `.yml`, and
/// `.rtsys` (RTSystemEditor's own save dialog offers it for RT System profiles). What the file
/// is, is decided by its content.
pub fn is_document_extension(ext: &str) -> bool {
    matches!(ext, "xml" | "yaml" | "yml" | "rtsys")
}

/// Whether a file is named as IDL (`.idl`, any case).
pub fn is_idl_path(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("idl"))
}

/// Whether a file is one the catalogue may read as a specification: a profile-like file (by
/// extension or by name, RTCBuilder's backups included) or an IDL file. What it is, is decided
/// by its content.
pub fn is_specification_file(path: &Path) -> bool {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    ext.as_deref()
        .is_some_and(|e| e == "idl" || is_document_extension(e))
        || named_like_profile(path)
}

/// Whether `path` is one of RTCBuilder's backups (`RTC.xml<timestamp>`): an older version of
/// the `RTC.xml` beside it, never a component of its own ([`crate::catalog::backups`]).
pub fn is_backup(path: &Path) -> bool {
    path.file_name()
        .and_then(|n| n.to_str())
        .is_some_and(is_backup_name)
}

/// What a file that is not an RTC component profile is, for a message ("is empty: a failed
/// save?", "is an RT System profile").
pub fn describe_non_profile(bytes: &[u8]) -> String {
    let body = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    if body.iter().all(u8::is_ascii_whitespace) {
        return "is empty (a failed save?)".into();
    }
    let utf16 = bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF]);
    let head = &body[..body.len().min(4096)];
    if !utf16 && head.contains(&0) {
        return "is binary data, not a text profile".into();
    }
    let first = head.iter().find(|b| !b.is_ascii_whitespace()).copied();
    if utf16 || first == Some(b'<') {
        return match parse::xml::root_element(bytes) {
            parse::xml::Root::Element(name) if name == "RtsProfile" => {
                "is an RT System profile (RtsProfile), not a component profile".into()
            }
            parse::xml::Root::Element(name) => {
                format!("is XML with the root element `{name}`, not `RtcProfile`")
            }
            parse::xml::Root::Truncated => "ends before its root element (truncated?)".into(),
            parse::xml::Root::NotXml => "is not well-formed XML before its root element".into(),
        };
    }
    if parse::yaml::has_root_key(bytes, "rtsProfile") {
        return "is an RT System profile (YAML rtsProfile), not a component profile".into();
    }
    "is neither XML nor YAML with a top-level `rtcProfile` (component) or `rtsProfile` (RT System) key".into()
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
    #[error("invalid {kind} pattern `{pattern}`: {message}")]
    BadGlob {
        kind: &'static str,
        pattern: String,
        message: String,
    },
}

/// Source files that may hold a component's implementation (by extension).
pub fn is_code_file(path: &Path) -> bool {
    matches!(
        path.extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref(),
        Some("cpp" | "cc" | "cxx" | "py" | "java")
    )
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
        _ if is_backup(path) && parse::xml::is_profile(bytes) => Some(SourceFormat::Xml),
        _ => None,
    }
}

/// The `kind` (`include` or `exclude`) patterns as one set ([`glob_set`]).
fn build_globs(kind: &'static str, patterns: &[String]) -> Result<GlobSet, WalkError> {
    glob_set(patterns).map_err(|(pattern, e)| WalkError::BadGlob {
        kind,
        pattern,
        message: e.to_string(),
    })
}

/// Globs over input-relative paths as one set: `*` and `?` stay within one folder, `**` crosses
/// folders, and a pattern without `/` matches a name in any folder (`*.yml`, as in
/// `.gitignore`). An invalid pattern is returned with its error (all of them when the set
/// cannot be built).
pub(crate) fn glob_set(patterns: &[String]) -> Result<GlobSet, (String, globset::Error)> {
    let mut b = GlobSetBuilder::new();
    for p in patterns {
        let anywhere;
        let pattern = if p.contains('/') {
            p.as_str()
        } else {
            anywhere = format!("**/{p}");
            anywhere.as_str()
        };
        let g = globset::GlobBuilder::new(pattern)
            .literal_separator(true)
            .build()
            .map_err(|e| (p.clone(), e))?;
        b.add(g);
    }
    b.build().map_err(|e| (patterns.join(", "), e))
}

/// Whether an input-relative path is left out by the `--exclude` patterns `patterns` (for files
/// the walk does not list itself, such as a component folder's README). A bad pattern, which
/// the walk reports, matches nothing here.
pub fn exclude_matcher(patterns: &[String]) -> impl Fn(&str) -> bool + Sync {
    let set = build_globs("exclude", patterns).unwrap_or_else(|_| GlobSet::empty());
    move |rel: &str| set.is_match(rel)
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
        ..
    } = candidates(input, opts)?;
    let mut result = WalkResult {
        skipped,
        ..WalkResult::default()
    };
    // Recognising profiles reads the head of every candidate: done in parallel.
    use rayon::prelude::*;
    let sniffed: Vec<(PathBuf, String, std::io::Result<Recognised>)> = candidates
        .into_par_iter()
        .map(|(path, rel)| {
            let r = sniff(&path).map(|s| s.format.ok_or_else(|| describe_non_profile(&s.head)));
            (path, rel, r)
        })
        .collect();
    for (path, rel, r) in sniffed {
        match r {
            Ok(Ok(format)) => result.sources.push(Source { path, rel, format }),
            Ok(Err(reason)) => result.skipped.push(Skipped {
                rel,
                reason,
                kind: SkipKind::NotAProfile,
            }),
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
#[derive(Default)]
pub struct Candidates {
    pub files: Vec<(PathBuf, String)>,
    /// `*.idl` files (data types and service interfaces), read by [`crate::idl`].
    pub idl: Vec<(PathBuf, String)>,
    /// Source files (`.cpp`, `.py`, `.java` …) no exclude pattern matches: where a component
    /// with code and no profile is found ([`crate::implementation::recover`]). They are also
    /// in `skipped`, as other files: no profile is read from them.
    pub code: Vec<(PathBuf, String)>,
    pub skipped: Vec<Skipped>,
    /// The folders (relative, `""` for the top) the walk met an entry named like a README in
    /// (of any kind: [`crate::readme::read_folder`] decides what it is), so that no other
    /// folder has to be listed again to look for one.
    pub readme_dirs: BTreeSet<String>,
}

impl Candidates {
    fn append(&mut self, mut other: Candidates) {
        self.files.append(&mut other.files);
        self.idl.append(&mut other.idl);
        self.code.append(&mut other.code);
        self.skipped.append(&mut other.skipped);
        self.readme_dirs.append(&mut other.readme_dirs);
    }
}

/// The format of a file named on the command line, by content alone (whatever its name): XML
/// when it starts like XML, else YAML; `None` when neither reads as a component profile.
pub fn detect_named(bytes: &[u8]) -> Option<SourceFormat> {
    if parse::xml::is_profile(bytes) {
        Some(SourceFormat::Xml)
    } else if parse::yaml::is_profile(bytes) {
        Some(SourceFormat::Yaml)
    } else {
        None
    }
}

/// A candidate opened by [`sniff`]: the file (positioned after its head), its length when it
/// was opened, the head, and the format when the head shows a profile.
struct Sniffed {
    file: std::fs::File,
    len: u64,
    head: Vec<u8>,
    format: Option<SourceFormat>,
}

/// Opens a candidate and reads its head. The buffer is sized from the file's length, so that a
/// head is read in one call (`read_to_end` into an empty buffer reads in steps that double
/// from 32 bytes: ten calls for a 30 KB profile); a length that changed by the time of reading
/// only costs more calls.
fn sniff(path: &Path) -> std::io::Result<Sniffed> {
    use std::io::Read;
    let mut file = std::fs::File::open(path)?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut head = Vec::with_capacity(capacity(len.min(SNIFF_BYTES)));
    (&mut file)
        .take(SNIFF_BYTES.saturating_add(1))
        .read_to_end(&mut head)?;
    let format = detect(path, &head);
    Ok(Sniffed {
        file,
        len,
        head,
        format,
    })
}

/// Room for `n` bytes and the read that finds the end of the file.
fn capacity(n: u64) -> usize {
    usize::try_from(n.saturating_add(1)).unwrap_or(usize::MAX)
}

/// What the head of a candidate shows: its format, or what it is instead (for a message).
type Recognised = Result<SourceFormat, String>;

/// A candidate read by [`read_profile`].
pub(crate) enum ReadFile {
    /// A profile of this format: its bytes (at most the size limit + 1).
    Profile(SourceFormat, Vec<u8>),
    /// Not a profile: the head that was read.
    Other(Vec<u8>),
}

/// Reads a candidate file once: its head, to recognise a profile exactly as [`walk`] does (or,
/// for a file named on the command line, by content alone), and when it is one, the rest — at
/// most `limit + 1` bytes in all, so that an oversized file is detected without reading it
/// whole. `Err(head)` when the file is not a profile.
pub(crate) fn read_profile(path: &Path, limit: u64, named: bool) -> std::io::Result<ReadFile> {
    use std::io::Read;
    let Sniffed {
        file,
        len,
        head: mut buf,
        format,
    } = sniff(path)?;
    let format = if named { detect_named(&buf) } else { format };
    let Some(format) = format else {
        return Ok(ReadFile::Other(buf));
    };
    let cap = limit.saturating_add(1);
    let have = buf.len() as u64;
    if have > cap {
        buf.truncate(usize::try_from(cap).unwrap_or(usize::MAX));
    } else {
        buf.reserve(capacity(len.min(cap).saturating_sub(have)));
        file.take(cap - have).read_to_end(&mut buf)?;
    }
    Ok(ReadFile::Profile(format, buf))
}

/// At most `cap` bytes of the file at `path`: what a watcher rereads is bounded like what a
/// walk reads (a file past the size limit is then reported, not read whole).
pub fn read_at_most(path: &Path, cap: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let file = std::fs::File::open(path)?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut buf = Vec::with_capacity(capacity(len.min(cap)));
    file.take(cap).read_to_end(&mut buf)?;
    Ok(buf)
}

/// The traversal part of [`walk`]: which files are candidates, without reading any. The
/// entries of the input directory are walked in parallel, each subtree in order, so the result
/// is the same as one sorted walk of the whole tree ([`Walker::subtree`] of the input).
pub fn candidates(input: &Path, opts: &WalkOptions) -> Result<Candidates, WalkError> {
    if !input.exists() {
        return Err(WalkError::Missing(input.to_path_buf()));
    }
    let w = Walker::new(input, opts)?;
    Ok(if input.is_dir() {
        w.parallel()
    } else {
        w.subtree(input)
    })
}

/// The settings of one walk.
struct Walker<'a> {
    input: &'a Path,
    /// What relative paths are relative to.
    root: PathBuf,
    excludes: GlobSet,
    /// The exclude patterns as written, in `excludes`' order (to name the one that matched).
    exclude_patterns: Vec<String>,
    includes: Option<GlobSet>,
    skip_dirs: Vec<PathBuf>,
    /// Inode numbers of `skip_dirs`: canonicalizing every directory of a large tree costs a
    /// path resolution each; on Unix only a directory with the inode number of a skipped one
    /// needs it.
    #[cfg(unix)]
    skip_inodes: Vec<u64>,
}

impl<'a> Walker<'a> {
    fn new(input: &'a Path, opts: &WalkOptions) -> Result<Walker<'a>, WalkError> {
        let skip_dirs: Vec<PathBuf> = opts
            .skip_dirs
            .iter()
            .filter_map(|d| d.canonicalize().ok())
            .collect();
        #[cfg(unix)]
        let skip_inodes = {
            use std::os::unix::fs::MetadataExt;
            skip_dirs
                .iter()
                .filter_map(|d| std::fs::metadata(d).ok().map(|m| m.ino()))
                .collect()
        };
        Ok(Walker {
            input,
            root: if input.is_file() {
                input.parent().unwrap_or(Path::new(".")).to_path_buf()
            } else {
                input.to_path_buf()
            },
            excludes: build_globs("exclude", &opts.exclude)?,
            exclude_patterns: opts.exclude.clone(),
            includes: if opts.include.is_empty() {
                None
            } else {
                Some(build_globs("include", &opts.include)?)
            },
            skip_dirs,
            #[cfg(unix)]
            skip_inodes,
        })
    }

    fn walkdir(start: &Path) -> walkdir::WalkDir {
        walkdir::WalkDir::new(start)
            .follow_links(false)
            .sort_by_file_name()
    }

    /// Whether the walk enters or takes `e` (every entry below the input): not a skipped
    /// directory (the output) and not a hidden directory.
    fn keep(&self, e: &walkdir::DirEntry) -> bool {
        if !e.file_type().is_dir() {
            return true;
        }
        if self.may_be_skipped(e) {
            if let Ok(c) = e.path().canonicalize() {
                if self.skip_dirs.contains(&c) {
                    return false;
                }
            }
        }
        // Hidden directories (.git, .svn, .cache) hold no profiles of interest.
        !e.file_name().to_string_lossy().starts_with('.')
    }

    fn may_be_skipped(&self, e: &walkdir::DirEntry) -> bool {
        if self.skip_dirs.is_empty() {
            return false;
        }
        #[cfg(unix)]
        {
            use walkdir::DirEntryExt;
            self.skip_inodes.contains(&e.ino())
        }
        #[cfg(not(unix))]
        {
            let _ = e;
            true
        }
    }

    /// The first exclude pattern that matches the input-relative path `rel`.
    fn excluded(&self, rel: &str) -> Option<&str> {
        self.excludes
            .matches(rel)
            .first()
            .and_then(|&i| self.exclude_patterns.get(i))
            .map(String::as_str)
    }

    /// Whether the walk enters the directory `e` (below the input): not a hidden or skipped
    /// one ([`Walker::keep`]), and not one an exclude pattern matches — `--exclude
    /// examples/Templates` leaves out everything below it, which is reported once.
    fn enter(&self, e: &walkdir::DirEntry, out: &mut Candidates) -> bool {
        self.note_readme(e, out);
        if !self.keep(e) {
            return false;
        }
        let rel = rel_path(&self.root, e.path());
        if let Some(pattern) = self.excluded(&rel) {
            out.skipped.push(Skipped {
                rel: format!("{rel}/"),
                reason: format!(
                    "directory excluded by pattern `{pattern}` (nothing below it is read)"
                ),
                kind: SkipKind::Excluded,
            });
            return false;
        }
        true
    }

    /// A sorted walk of `start` (the input, or a directory directly in it, already entered).
    fn subtree(&self, start: &Path) -> Candidates {
        let mut out = Candidates::default();
        let mut it = Self::walkdir(start).into_iter();
        while let Some(entry) = it.next() {
            if let Ok(e) = &entry {
                if e.depth() > 0 && e.file_type().is_dir() {
                    if !self.enter(e, &mut out) {
                        it.skip_current_dir();
                    }
                    continue;
                }
            }
            self.visit(entry, &mut out);
        }
        out
    }

    /// The input directory's entries in order, each directory among them walked on its own
    /// and in parallel.
    fn parallel(&self) -> Candidates {
        use rayon::prelude::*;
        let top: Vec<_> = Self::walkdir(self.input)
            .max_depth(1)
            .into_iter()
            .filter_entry(|e| e.depth() == 0 || self.keep(e))
            .collect();
        let parts: Vec<Candidates> = top
            .into_par_iter()
            .map(|entry| match entry {
                Ok(e) if e.depth() == 1 && e.file_type().is_dir() => {
                    let mut out = Candidates::default();
                    if self.enter(&e, &mut out) {
                        self.subtree(e.path())
                    } else {
                        out
                    }
                }
                other => {
                    let mut out = Candidates::default();
                    self.visit(other, &mut out);
                    out
                }
            })
            .collect();
        let mut all = Candidates::default();
        for p in parts {
            all.append(p);
        }
        all
    }

    /// Notes the folder of an entry named like a README, whatever kind of entry it is (a
    /// folder noted in vain only costs looking in it).
    fn note_readme(&self, e: &walkdir::DirEntry, out: &mut Candidates) {
        if crate::readme::readme_rank(&e.file_name().to_string_lossy()).is_some() {
            let rel = rel_path(&self.root, e.path());
            let dir = rel.rsplit_once('/').map_or("", |(d, _)| d);
            out.readme_dirs.insert(dir.to_string());
        }
    }

    /// Files: a candidate, or skipped with the reason; directories: nothing (symbolic links
    /// are reported).
    fn visit(&self, entry: walkdir::Result<walkdir::DirEntry>, out: &mut Candidates) {
        let entry = match entry {
            Ok(e) => e,
            Err(e) => {
                let rel = e
                    .path()
                    .map(|p| rel_path(&self.root, p))
                    .unwrap_or_else(|| self.input.display().to_string());
                out.skipped.push(Skipped {
                    rel,
                    reason: format!("cannot be read: {e}"),
                    kind: SkipKind::Unreadable,
                });
                return;
            }
        };
        self.note_readme(&entry, out);
        if !entry.file_type().is_file() {
            if entry.file_type().is_symlink() {
                out.skipped.push(Skipped {
                    rel: rel_path(&self.root, entry.path()),
                    reason: "symbolic link (not followed)".into(),
                    kind: SkipKind::Symlink,
                });
            }
            return;
        }
        let path = entry.path();
        let rel = rel_path(&self.root, path);
        // A file named on the command line is read whatever its name and the patterns: an
        // `.idl` file as IDL (`rtcdoc diff A.idl B.idl`), any other as a profile.
        if entry.depth() == 0 && self.input.is_file() {
            if is_idl_path(path) {
                out.idl.push((path.to_path_buf(), rel));
            } else {
                out.files.push((path.to_path_buf(), rel));
            }
            return;
        }
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase());
        let idl = ext.as_deref() == Some("idl");
        let candidate =
            idl || ext.as_deref().is_some_and(is_document_extension) || named_like_profile(path);
        if !candidate {
            if is_code_file(path) && self.excluded(&rel).is_none() {
                out.code.push((path.to_path_buf(), rel.clone()));
            }
            out.skipped.push(Skipped {
                rel,
                reason: "not an .xml/.yaml/.yml/.rtsys file".into(),
                kind: SkipKind::OtherFile,
            });
            return;
        }
        if let Some(pattern) = self.excluded(&rel) {
            out.skipped.push(Skipped {
                rel,
                reason: format!("excluded by pattern `{pattern}`"),
                kind: SkipKind::Excluded,
            });
            return;
        }
        if let Some(inc) = &self.includes {
            if !inc.is_match(&rel) {
                out.skipped.push(Skipped {
                    rel,
                    reason: "not matched by an include pattern".into(),
                    kind: SkipKind::NotIncluded,
                });
                return;
            }
        }
        if idl {
            out.idl.push((path.to_path_buf(), rel));
        } else {
            out.files.push((path.to_path_buf(), rel));
        }
    }
}

/// Every `*.idl` file below `dir` (an `--idl-path` directory), sorted, with its path shown as
/// `NAME/…` where NAME is the directory's own name — never the absolute path of this machine.
pub fn idl_files(dir: &Path) -> Result<Vec<(PathBuf, String)>, WalkError> {
    if !dir.is_dir() {
        return Err(WalkError::Missing(dir.to_path_buf()));
    }
    let opts = WalkOptions::default();
    let w = Walker::new(dir, &opts)?;
    let found = w.subtree(dir);
    let name = dir
        .canonicalize()
        .ok()
        .and_then(|d| d.file_name().map(|n| n.to_string_lossy().into_owned()))
        .unwrap_or_else(|| "idl-path".into());
    Ok(found
        .idl
        .into_iter()
        .map(|(p, rel)| (p, format!("{name}/{rel}")))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(dir: &Path, rel: &str) {
        let p = dir.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, "<rtc:RtcProfile/>").unwrap();
    }

    /// A temporary folder with a profile at each of `rels` (folders made as needed).
    fn tree(rels: &[&str]) -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        for rel in rels {
            write(dir.path(), rel);
        }
        dir
    }

    /// (files, skipped) as comparable lists.
    fn flat(c: Candidates) -> (Vec<(PathBuf, String)>, Vec<Skipped>) {
        (c.files, c.skipped)
    }

    /// Every folder in which a README would be found ([`crate::readme::find`]) is among the
    /// folders the walk noted: a README of any kind (file, folder, link), any spelling, at the
    /// top or deep, beside excluded and hidden entries.
    #[test]
    fn the_walk_notes_every_folder_with_a_readme() {
        let dir = tree(&[
            "RTC.xml",
            "README.md",
            "a/RTC.xml",
            "a/README.md",
            "b/RTC.xml",
            "b/readme.MARKDOWN",
            "c/RTC.xml",
            "c/notes.md",
            "d/RTC.xml",
            "f/g/RTC.xml",
            "f/g/ReadMe.md",
            "x/RTC.xml",
            "x/README.md",
        ]);
        let d = dir.path();
        std::fs::create_dir_all(d.join("d/README.md")).unwrap();
        std::fs::create_dir_all(d.join("e")).unwrap();
        write(d, "e/RTC.xml");
        #[cfg(unix)]
        std::os::unix::fs::symlink(d.join("a/README.md"), d.join("e/README.md")).unwrap();
        let opts = WalkOptions {
            exclude: vec!["x/README.md".into()],
            ..WalkOptions::default()
        };
        let c = candidates(d, &opts).unwrap();
        let mut folders = vec![String::new()];
        for (_, rel) in &c.files {
            if let Some((dir, _)) = rel.rsplit_once('/') {
                folders.push(dir.to_string());
            }
        }
        let mut with_readme = 0;
        for f in &folders {
            if crate::readme::find(&d.join(f)).is_some() {
                with_readme += 1;
                assert!(
                    c.readme_dirs.contains(f),
                    "{f:?} not noted: {:?}",
                    c.readme_dirs
                );
            }
        }
        assert!(with_readme >= 6, "{with_readme}");
        assert!(!c.readme_dirs.contains("c"), "{:?}", c.readme_dirs);
    }

    /// A profile is read whole whatever its size around the head's, an oversized one up to the
    /// limit and one byte, and a file that is not a profile only as far as its head.
    #[test]
    fn profiles_are_read_whole_or_to_the_limit() {
        let dir = tempfile::tempdir().unwrap();
        let head = SNIFF_BYTES as usize;
        for size in [0, 20, head - 1, head, head + 1, 3 * head + 17] {
            let mut text = b"<?xml version=\"1.0\"?>\n<rtc:RtcProfile>".to_vec();
            text.resize(size.max(text.len()), b' ');
            let path = dir.path().join(format!("RTC{size}.xml"));
            std::fs::write(&path, &text).unwrap();
            match read_profile(&path, 1 << 30, false).unwrap() {
                ReadFile::Profile(SourceFormat::Xml, bytes) => assert!(bytes == text, "{size}"),
                _ => panic!("{size}: not read as a profile"),
            }
            match read_profile(&path, 100, false).unwrap() {
                ReadFile::Profile(_, bytes) => assert_eq!(bytes.len(), text.len().min(101)),
                _ => panic!("{size}: not read as a profile"),
            }
        }
        let other = dir.path().join("notes.xml");
        std::fs::write(&other, vec![b'x'; 3 * head]).unwrap();
        match read_profile(&other, 1 << 30, false).unwrap() {
            ReadFile::Other(bytes) => assert_eq!(bytes.len(), head + 1),
            ReadFile::Profile(..) => panic!("read as a profile"),
        }
    }

    /// The parallel walk gives what one sorted walk of the whole tree gives: same files, same
    /// skipped entries, same order — with hidden and skipped directories and symbolic links at
    /// the top and deeper, root files among directories, and patterns.
    #[test]
    fn parallel_walk_equals_one_sorted_walk() {
        let dir = tree(&[
            "a.xml",
            "m.yaml",
            "z.txt",
            "b/RTC.xml",
            "b/c/RTC.yml",
            "b/c/notes.md",
            "b/.hidden/RTC.xml",
            ".git/RTC.xml",
            "out/index.xml",
            "deep/x/out2/RTC.xml",
            "deep/x/RTC.XML",
            "skip/me/RTC.xml",
            "n/keep.xml",
        ]);
        let d = dir.path();
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(d.join("b"), d.join("link-dir")).unwrap();
            std::os::unix::fs::symlink(d.join("a.xml"), d.join("b/link.xml")).unwrap();
            std::os::unix::fs::symlink(d, d.join("deep/x/cycle")).unwrap();
        }
        let cases = [
            WalkOptions::default(),
            WalkOptions {
                exclude: vec!["skip/**".into(), "*.yml".into()],
                skip_dirs: vec![d.join("out"), d.join("deep/x/out2")],
                ..Default::default()
            },
            WalkOptions {
                include: vec!["b/**".into(), "n/*".into()],
                ..Default::default()
            },
        ];
        for opts in &cases {
            let w = Walker::new(d, opts).unwrap();
            let one = flat(w.subtree(d));
            let par = flat(candidates(d, opts).unwrap());
            assert_eq!(par, one, "{opts:?}");
            assert!(!one.0.is_empty() && !one.1.is_empty(), "{opts:?}");
        }
        // The skipped directories and hidden ones are not entered; links are reported.
        let (files, skipped) = flat(candidates(d, &cases[1]).unwrap());
        let rels: Vec<&str> = files.iter().map(|(_, r)| r.as_str()).collect();
        assert_eq!(
            rels,
            [
                "a.xml",
                "b/RTC.xml",
                "deep/x/RTC.XML",
                "m.yaml",
                "n/keep.xml"
            ]
        );
        #[cfg(unix)]
        for link in ["link-dir", "b/link.xml", "deep/x/cycle"] {
            assert!(skipped.iter().any(|s| s.rel == link), "{link}: {skipped:?}");
        }
        // A single file is walked as itself.
        let one = flat(candidates(&d.join("b/RTC.xml"), &WalkOptions::default()).unwrap());
        assert_eq!(one.0.len(), 1);
    }
}
