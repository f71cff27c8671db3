//! The history of every component profile: the commits that changed its file (a git work tree
//! as input, a `[[source]]` repository at its pinned commit) and RTCBuilder's backups beside
//! it, newest first, each version compared with the one before it by the diff engine
//! ([`crate::diff::compare_profiles`]). Each distinct blob is read (one `git cat-file --batch`
//! per repository) and parsed once, keyed by its object id.
//!
//! Git is run as [`crate::sources`] runs it: no system configuration, no hooks, no prompt, the
//! revision after `--end-of-options`, paths as literal pathspecs.

use crate::catalog::history::{Change, Entry};
use crate::catalog::sources::Roots;
use crate::catalog::{Catalog, Component};
use crate::model::{non_empty, Profile};
use crate::parse::{self, Limits};
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use std::io::{BufRead, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Commits read per profile when `history` is not set.
pub const DEFAULT_LIMIT: usize = 100;

/// A blob's bytes, or why git could not give them.
type Blob = Result<Vec<u8>, String>;

/// Where a version of a profile is.
#[derive(Debug, Clone)]
enum Where {
    /// A blob of the repository `repo` (an index into the repositories read).
    Blob { repo: usize, oid: String },
    /// A backup of the component (an index into its `backups`).
    Backup(usize),
    /// The file as the input holds it (the catalogue's profile).
    Current,
}

#[derive(Debug, Clone)]
struct Version {
    at: Where,
    entry: Entry,
    /// Sorts the versions of git and of the backups together: `yyyy-mm-dd hh:mm:ss`, local.
    key: String,
}

/// A repository histories are read from.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Repo {
    /// The work tree holding the input directory (git run in it, at `HEAD`).
    WorkTree(PathBuf),
    /// The bare mirror of a `[[source]]` (at the source's pinned commit).
    Mirror(PathBuf),
}

impl Repo {
    fn git(&self) -> Command {
        let mut c = match self {
            Repo::WorkTree(dir) => {
                let mut c = crate::sources::git_command(None);
                c.current_dir(dir);
                // The user's limit on finding the repository around the input is kept (the
                // sources' commands drop it: they name their repository).
                if let Some(v) = std::env::var_os("GIT_CEILING_DIRECTORIES") {
                    c.env("GIT_CEILING_DIRECTORIES", v);
                }
                c
            }
            Repo::Mirror(m) => crate::sources::git_command(Some(m)),
        };
        c.args(["-c", "log.showSignature=false", "--literal-pathspecs"]);
        c
    }
}

/// Whether `dir` is inside a git work tree (and git runs).
fn is_work_tree(dir: &Path) -> bool {
    let mut c = Repo::WorkTree(dir.to_path_buf()).git();
    c.args(["rev-parse", "--is-inside-work-tree"]);
    c.stderr(Stdio::null());
    matches!(c.output(), Ok(o) if o.status.success() && o.stdout.starts_with(b"true"))
}

/// Fills in `history` of every component: up to `limit` commits of its file (0: none, and no
/// history at all), its backups, and the file as it is when that differs from the newest
/// commit. A repository that cannot be read leaves the components without git history; a
/// version that cannot be read stays in the history with the reason.
pub fn attach(catalog: &mut Catalog, roots: &Roots, opts: &crate::build::LoadOptions) {
    let (sources, limit, limits) = (&opts.sources, opts.history, &opts.limits);
    if limit == 0 {
        return;
    }
    let local = is_work_tree(&roots.local).then(|| Repo::WorkTree(roots.local.clone()));
    let mut repos: Vec<Repo> = Vec::new();
    // (repository, revision, pathspec) of each component, if its file is in one.
    let mut located: Vec<Option<(usize, String, String)>> = Vec::new();
    for c in &catalog.components {
        let (repo, rev, path) = match &c.origin {
            Some(o) => match sources.iter().find(|p| p.source.name == o.source) {
                Some(p) => (
                    Repo::Mirror(p.mirror.clone()),
                    o.commit.clone(),
                    o.path.clone(),
                ),
                None => {
                    located.push(None);
                    continue;
                }
            },
            None => match &local {
                Some(r) => (r.clone(), "HEAD".to_string(), c.source.clone()),
                None => {
                    located.push(None);
                    continue;
                }
            },
        };
        let at = match repos.iter().position(|r| *r == repo) {
            Some(i) => i,
            None => {
                repos.push(repo);
                repos.len() - 1
            }
        };
        located.push(Some((at, rev, path)));
    }
    // The commits of each file, newest first: from one log of the whole repository where it
    // has several of the files, else (or where `--follow` could find a rename) a log per file.
    let mut groups: BTreeMap<(usize, &str), Vec<&str>> = BTreeMap::new();
    for (repo, rev, path) in located.iter().flatten() {
        groups.entry((*repo, rev)).or_default().push(path);
    }
    let wholes: HashMap<(usize, &str), WholeLog> = groups
        .into_par_iter()
        .filter(|(_, paths)| paths.len() >= 2)
        .filter_map(|((repo, rev), paths)| {
            whole_log(&repos[repo], rev, &paths).map(|w| ((repo, rev), w))
        })
        .collect();
    let logs: Vec<Vec<Version>> = located
        .par_iter()
        .map(|l| match l {
            Some((repo, rev, path)) => wholes
                .get(&(*repo, rev.as_str()))
                .and_then(|w| w.log(*repo, path, limit))
                .unwrap_or_else(|| log(&repos[*repo], *repo, rev, path, limit)),
            None => Vec::new(),
        })
        .collect();
    // Each distinct blob read and parsed once.
    // (object id, a path it had: its extension names the format when the content does not).
    let mut wanted: Vec<BTreeMap<String, String>> = vec![BTreeMap::new(); repos.len()];
    for v in logs.iter().flatten() {
        if let Where::Blob { repo, oid } = &v.at {
            wanted[*repo]
                .entry(oid.clone())
                .or_insert_with(|| v.entry.file.clone());
        }
    }
    // A component whose file is its newest commit's blob byte for byte: that version is the
    // catalogue's profile (the same bytes parsed the same way), not parsed again. The blobs
    // are compared with the files as git gives them; only those some version needs are kept.
    let mut newest: Vec<HashMap<&str, Vec<usize>>> = vec![HashMap::new(); repos.len()];
    let mut older: Vec<std::collections::HashSet<&str>> = vec![Default::default(); repos.len()];
    for (ci, log) in logs.iter().enumerate() {
        for (i, v) in log.iter().enumerate() {
            if let Where::Blob { repo, oid } = &v.at {
                if i == 0 {
                    newest[*repo].entry(oid).or_default().push(ci);
                } else {
                    older[*repo].insert(oid);
                }
            }
        }
    }
    let mut current: Vec<Option<(usize, String)>> = vec![None; catalog.components.len()];
    let raw: Vec<HashMap<String, Blob>> = repos
        .iter()
        .zip(&wanted)
        .enumerate()
        .map(|(r, (repo, oids))| {
            let mut keep = |oid: &str, bytes: &[u8]| {
                let mut needed = older[r].contains(oid);
                for &ci in newest[r].get(oid).into_iter().flatten() {
                    let c = &catalog.components[ci];
                    let file = oids.get(oid).map_or("", String::as_str);
                    let same = blob_format(bytes, file) == Some(c.format)
                        && std::fs::read(roots.dir_of(&c.source).join(&c.source))
                            .is_ok_and(|f| f == bytes);
                    if same {
                        current[ci] = Some((r, oid.to_string()));
                    }
                    needed |= !same;
                }
                needed
            };
            read_blobs(repo, oids, &mut keep)
        })
        .collect();
    drop((newest, older));
    let parsed: Vec<HashMap<String, Result<Profile, String>>> = raw
        .into_iter()
        .zip(&wanted)
        .map(|(blobs, oids)| {
            blobs
                .into_par_iter()
                .map(|(oid, bytes)| {
                    let file = oids.get(&oid).map_or("", String::as_str);
                    let parsed = bytes.and_then(|b| parse_blob(&b, file, limits));
                    (oid, parsed)
                })
                .collect()
        })
        .collect();
    let idl = &catalog.idl;
    let histories: Vec<Vec<Entry>> = catalog
        .components
        .par_iter()
        .zip(logs)
        .zip(current)
        .map(|((c, commits), current)| history_of(c, commits, &parsed, current, idl))
        .collect();
    for (c, h) in catalog.components.iter_mut().zip(histories) {
        c.history = h;
    }
}

/// The commits that changed `path` up to `rev`, following renames.
fn log(repo: &Repo, at: usize, rev: &str, path: &str, limit: usize) -> Vec<Version> {
    if rev.starts_with('-') || path.is_empty() {
        return Vec::new();
    }
    let mut c = repo.git();
    c.args([
        "log",
        "--follow",
        "--no-abbrev",
        "--raw",
        "-z",
        "--no-color",
        "--no-ext-diff",
        "--format=%x1e%H%x1f%aI%x1f%an%x1f%s",
    ])
    .arg(format!("--max-count={limit}"))
    .args(["--end-of-options", rev, "--", path]);
    c.stderr(Stdio::null());
    let Ok(out) = c.output() else {
        return Vec::new();
    };
    if !out.status.success() {
        return Vec::new();
    }
    parse_log(&String::from_utf8_lossy(&out.stdout), at)
}

/// A commit as `git log` describes it: id, author date, author, subject.
type Header<'a> = (&'a str, &'a str, &'a str, &'a str);

/// A version of a file at a commit: its blob `new` and its path then.
fn version(repo: usize, (commit, date, author, subject): Header, new: &str, file: &str) -> Version {
    Version {
        at: Where::Blob {
            repo,
            oid: new.to_string(),
        },
        key: date.get(..19).unwrap_or(date).replace('T', " "),
        entry: Entry {
            commit: Some(commit.to_string()),
            file: file.to_string(),
            date: Some(date.to_string()),
            author: Some(author.to_string()),
            subject: Some(subject.to_string()),
            ..Entry::default()
        },
    }
}

/// The history of a repository at a revision for many of its files at once: one `git log`
/// of every commit with every file it changed, instead of a `git log --follow` per file
/// (10,000 profiles: 10,000 git processes, each walking the whole history). It gives what
/// `git log --follow` gives where `--follow` has nothing to find: the history is linear (no
/// merge to simplify), and the file is added, within the commits asked for, only by a root
/// commit (at any other commit adding it, `--follow` looks for a file it was renamed or
/// copied from, among all the files of the commit before); any other file falls back to its
/// own `git log --follow`.
struct WholeLog {
    /// The commits, newest first, and whether each is a root commit (without parents).
    commits: Vec<(String, String, String, String, bool)>,
    /// Per file asked for (its path in the repository): (commit index, new blob, added).
    files: HashMap<String, Vec<(usize, String, bool)>>,
    /// The files asked for whose path is also a folder in some commit (pathspecs match both).
    folders: std::collections::HashSet<String>,
    /// The input directory's path in the repository (`git rev-parse --show-prefix`).
    prefix: String,
}

/// Reads the whole log of `rev` for the files `paths`, or `None` when it would not be the
/// `--follow` log of each (merges, paths relative to the input) or git fails.
fn whole_log(repo: &Repo, rev: &str, paths: &[&str]) -> Option<WholeLog> {
    if rev.starts_with('-') {
        return None;
    }
    let git = |args: &[&str]| -> Option<Vec<u8>> {
        let mut c = repo.git();
        c.args(args).stderr(Stdio::null());
        c.output().ok().map(|o| o.stdout)
    };
    // Relative paths would hide the files outside the input directory: a log per file then.
    let config = git(&["config", "--get", "diff.relative"])?;
    let config = String::from_utf8_lossy(&config).to_ascii_lowercase();
    if !matches!(config.trim(), "" | "false" | "no" | "off" | "0") {
        return None;
    }
    let prefix = match repo {
        Repo::WorkTree(_) => String::from_utf8(git(&["rev-parse", "--show-prefix"])?)
            .ok()?
            .trim_end_matches('\n')
            .to_string(),
        Repo::Mirror(_) => String::new(),
    };
    let mut c = repo.git();
    c.args([
        "log",
        "--no-renames",
        "--no-abbrev",
        "--raw",
        "-z",
        "--no-color",
        "--no-ext-diff",
        "--format=%x1e%H%x1f%P%x1f%aI%x1f%an%x1f%s",
        "--end-of-options",
        rev,
        "--",
    ])
    .stderr(Stdio::null());
    let out = c.output().ok()?;
    if !out.status.success() {
        return None;
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let wanted: std::collections::HashSet<String> =
        paths.iter().map(|p| format!("{prefix}{p}")).collect();
    let mut w = WholeLog {
        commits: Vec::new(),
        files: HashMap::new(),
        folders: Default::default(),
        prefix,
    };
    for record in text.split('\u{1e}').filter(|r| !r.is_empty()) {
        let (header, raw) = record.split_once('\0').unwrap_or((record, ""));
        let mut h = header.split('\u{1f}');
        let (Some(commit), Some(parents), Some(date), Some(author), Some(subject)) =
            (h.next(), h.next(), h.next(), h.next(), h.next())
        else {
            return None;
        };
        if parents.contains(' ') {
            return None; // a merge: per-file history simplification differs
        }
        let at = w.commits.len();
        let mut parts = raw.trim_start_matches('\n').split('\0');
        while let Some(meta) = parts.next().filter(|m| m.starts_with(':')) {
            let fields: Vec<&str> = meta.split(' ').collect();
            let (Some(new), Some(status)) = (fields.get(3), fields.get(4)) else {
                return None;
            };
            let path = parts.next()?;
            if !(status.starts_with('A')
                || status.starts_with('M')
                || status.starts_with('D')
                || status.starts_with('T'))
            {
                return None;
            }
            if wanted.contains(path) {
                w.files.entry(path.to_string()).or_default().push((
                    at,
                    new.to_string(),
                    status.starts_with('A'),
                ));
            }
            for (i, _) in path.match_indices('/') {
                if wanted.contains(&path[..i]) {
                    w.folders.insert(path[..i].to_string());
                }
            }
        }
        w.commits.push((
            commit.to_string(),
            date.to_string(),
            author.to_string(),
            subject.to_string(),
            parents.is_empty(),
        ));
    }
    Some(w)
}

impl WholeLog {
    /// The commits that changed `path` (relative to the input), as [`log`] gives them, or
    /// `None` when its own `git log --follow` is needed.
    fn log(&self, repo: usize, path: &str, limit: usize) -> Option<Vec<Version>> {
        if path.is_empty() {
            return Some(Vec::new());
        }
        let full = format!("{}{path}", self.prefix);
        if self.folders.contains(&full) {
            return None;
        }
        let mut out = Vec::new();
        for (at, new, added) in self.files.get(&full).into_iter().flatten().take(limit) {
            let (commit, date, author, subject, root) = &self.commits[*at];
            if *added && !*root {
                return None; // `--follow` looks for a rename or copy here
            }
            if new.bytes().all(|b| b == b'0') {
                continue; // deleted here
            }
            out.push(version(repo, (commit, date, author, subject), new, &full));
        }
        Some(out)
    }
}

/// Reads `git log --raw -z` output (records begun by U+001E, header fields split by U+001F).
fn parse_log(text: &str, repo: usize) -> Vec<Version> {
    let mut out = Vec::new();
    for record in text.split('\u{1e}').filter(|r| !r.is_empty()) {
        let (header, raw) = record.split_once('\0').unwrap_or((record, ""));
        let mut h = header.split('\u{1f}');
        let (Some(commit), Some(date), Some(author), Some(subject)) =
            (h.next(), h.next(), h.next(), h.next())
        else {
            continue;
        };
        // `:mode mode old new STATUS\0path\0[path\0]`; a merge has no raw line.
        let mut parts = raw.trim_start_matches('\n').split('\0');
        let Some(meta) = parts.next().filter(|m| m.starts_with(':')) else {
            continue;
        };
        let fields: Vec<&str> = meta.split(' ').collect();
        let (Some(new), Some(status)) = (fields.get(3), fields.get(4)) else {
            continue;
        };
        if new.bytes().all(|b| b == b'0') {
            continue; // deleted here
        }
        let first = parts.next().unwrap_or("");
        let file = if status.starts_with('R') || status.starts_with('C') {
            parts.next().unwrap_or(first)
        } else {
            first
        };
        out.push(version(repo, (commit, date, author, subject), new, file));
    }
    out
}

/// Reads the blobs `oids` of `repo` (one `git cat-file --batch`), keeping those `keep`
/// wants; a blob git cannot give is kept with the reason.
fn read_blobs(
    repo: &Repo,
    oids: &BTreeMap<String, String>,
    keep: &mut dyn FnMut(&str, &[u8]) -> bool,
) -> HashMap<String, Blob> {
    let ids: Vec<String> = oids.keys().cloned().collect();
    let mut out = HashMap::new();
    if ids.is_empty() {
        return out;
    }
    let mut visit = |oid: &str, blob: Blob| {
        if blob.as_ref().map_or(true, |b| keep(oid, b)) {
            out.insert(oid.to_string(), blob);
        }
    };
    if let Err(e) = cat_file(repo, &ids, &mut visit) {
        for o in &ids {
            visit(o, Err(e.clone()));
        }
    }
    out
}

/// Parses one version of a profile; `file` is its path then. A version whose content does not
/// look like a profile is still parsed by its extension, for the parser's error and position.
fn parse_blob(bytes: &[u8], file: &str, limits: &Limits) -> Result<Profile, String> {
    let format = blob_format(bytes, file).ok_or_else(|| {
        format!(
            "this version {} (not read as a component profile)",
            crate::walk::describe_non_profile(bytes)
        )
    })?;
    parse::parse(format, bytes, file, limits)
        .map(|p| p.profile)
        .map_err(|d| match d.pos {
            Some(p) => format!("line {}, column {}: {}", p.line, p.column, d.message),
            None => d.message,
        })
}

/// The format a version is read in: by its content, else by its file's extension.
fn blob_format(bytes: &[u8], file: &str) -> Option<parse::SourceFormat> {
    let by_name = match file
        .rsplit('.')
        .next()
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("xml") => Some(parse::SourceFormat::Xml),
        Some("yaml" | "yml") => Some(parse::SourceFormat::Yaml),
        _ => None,
    };
    crate::walk::detect_named(bytes).or(by_name)
}

/// Reads the blobs `oids` of `repo` with one `git cat-file --batch`, handing each to `visit`
/// as it arrives (so that the blobs not kept are never all in memory at once).
fn cat_file(repo: &Repo, oids: &[String], visit: &mut dyn FnMut(&str, Blob)) -> Result<(), String> {
    let mut c = repo.git();
    c.args(["cat-file", "--batch"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null());
    let mut child = c.spawn().map_err(|e| format!("cannot run git: {e}"))?;
    let mut stdin = child.stdin.take().ok_or("no pipe to git")?;
    let stdout = child.stdout.take().ok_or("no pipe from git")?;
    let input: String = oids.iter().map(|o| format!("{o}\n")).collect();
    // Written from a thread: git answers while it reads.
    let writer = std::thread::spawn(move || {
        let _ = stdin.write_all(input.as_bytes());
    });
    let mut out = std::io::BufReader::with_capacity(1 << 16, stdout);
    let mut head = Vec::new();
    for oid in oids {
        head.clear();
        if !matches!(out.read_until(b'\n', &mut head), Ok(n) if n > 0 && head.ends_with(b"\n")) {
            visit(oid, Err("git gave no answer for it".to_string()));
            continue;
        }
        let head = String::from_utf8_lossy(&head[..head.len() - 1]).to_string();
        let f: Vec<&str> = head.split(' ').collect();
        let blob = match (f.get(1), f.get(2).and_then(|n| n.parse::<usize>().ok())) {
            (Some(&"blob"), Some(n)) => {
                let mut bytes = vec![0; n + 1];
                out.read_exact(&mut bytes).ok().map(|()| {
                    bytes.truncate(n);
                    bytes
                })
            }
            _ => None,
        };
        visit(
            oid,
            blob.ok_or_else(|| format!("git cannot read the object ({head})")),
        );
    }
    drop(out);
    let _ = writer.join();
    let _ = child.wait();
    Ok(())
}

/// The version string of a profile: BasicInfo's, else the id's last part.
fn version_of(p: &Profile) -> Option<String> {
    non_empty(&p.basic_info.version)
        .map(str::to_string)
        .or_else(|| {
            non_empty(&p.id)
                .and_then(|id| id.rsplit([':', '.']).next())
                .filter(|v| !v.is_empty())
                .map(str::to_string)
        })
}

fn history_of(
    c: &Component,
    commits: Vec<Version>,
    parsed: &[HashMap<String, Result<Profile, String>>],
    current: Option<(usize, String)>,
    idl: &crate::idl::IdlSet,
) -> Vec<Entry> {
    let is_current = |at: &Where| match (at, &current) {
        (Where::Blob { repo, oid }, Some((r, o))) => repo == r && oid == o,
        _ => false,
    };
    // Backups, newest first, merged into the commits by date.
    let mut backups: Vec<Version> = c
        .backups
        .iter()
        .enumerate()
        .map(|(i, b)| Version {
            at: Where::Backup(i),
            key: b.saved.clone().unwrap_or_default(),
            entry: Entry {
                backup: Some(b.source.clone()),
                file: b.source.clone(),
                date: b.saved.clone(),
                ..Entry::default()
            },
        })
        .collect();
    backups.sort_by(|a, b| b.key.cmp(&a.key).then(b.entry.file.cmp(&a.entry.file)));
    let mut versions: Vec<Version> = Vec::with_capacity(commits.len() + backups.len() + 1);
    let mut bs = backups.into_iter().peekable();
    for v in commits {
        while let Some(b) = bs.next_if(|b| b.key > v.key) {
            versions.push(b);
        }
        versions.push(v);
    }
    versions.extend(bs);
    if versions.is_empty() {
        return Vec::new();
    }
    let profile_of = |v: &Version| -> Result<&Profile, String> {
        match &v.at {
            Where::Blob { .. } if is_current(&v.at) => Ok(&c.profile),
            Where::Blob { repo, oid } => match parsed[*repo].get(oid) {
                Some(Ok(p)) => Ok(p),
                Some(Err(e)) => Err(e.clone()),
                None => Err("git did not read it".to_string()),
            },
            Where::Backup(i) => match &c.backups[*i] {
                b if b.profile.is_some() => Ok(b.profile.as_deref().expect("checked")),
                b => Err(b
                    .error
                    .clone()
                    .unwrap_or_else(|| "the backup could not be read".to_string())),
            },
            Where::Current => Ok(&c.profile),
        }
    };
    // The file as it is: a version of its own when it differs from the newest commit in the
    // specification (uncommitted edits), or when only backups record the history.
    let newest_commit = versions.iter().find(|v| v.entry.commit.is_some());
    let current_differs = match newest_commit {
        None => true,
        Some(v) if is_current(&v.at) => false,
        Some(v) => match profile_of(v) {
            Ok(p) => {
                !crate::diff::compare_profiles((p, &v.entry.file), (&c.profile, &c.source), idl)
                    .is_empty()
            }
            Err(_) => true,
        },
    };
    if current_differs {
        versions.insert(
            0,
            Version {
                at: Where::Current,
                key: String::new(),
                entry: Entry {
                    file: c.source.clone(),
                    ..Entry::default()
                },
            },
        );
    }
    let profiles: Vec<Result<&Profile, String>> = versions.iter().map(profile_of).collect();
    let mut entries = Vec::with_capacity(versions.len());
    for (i, v) in versions.iter().enumerate() {
        let mut e = v.entry.clone();
        match &profiles[i] {
            Err(why) => e.error = Some(why.clone()),
            Ok(p) => {
                e.version = version_of(p);
                let before = (i + 1..versions.len()).find(|&j| profiles[j].is_ok());
                match before {
                    None => e.first = true,
                    Some(j) => {
                        let old = profiles[j].as_ref().expect("found ok");
                        let same_blob = matches!((&v.at, &versions[j].at),
                            (Where::Blob { oid: a, repo: ra }, Where::Blob { oid: b, repo: rb }) if a == b && ra == rb);
                        if !same_blob {
                            e.changes = crate::diff::compare_profiles(
                                (old, &versions[j].entry.file),
                                (p, &v.entry.file),
                                idl,
                            )
                            .iter()
                            .map(to_entry_change)
                            .collect();
                        }
                        e.release = version_of(old) != e.version;
                    }
                }
            }
        }
        entries.push(e);
    }
    entries
}

/// A diff change as the catalogue keeps it: the same JSON object.
fn to_entry_change(c: &crate::diff::Change) -> Change {
    Change {
        severity: c.severity.to_string(),
        code: c.code.to_string(),
        name: c.name.to_string(),
        component: c.component.clone(),
        path: c.path.clone(),
        old: c.old.clone(),
        new: c.new.clone(),
        message: c.message.clone(),
        file: c.file.clone(),
        line: c.line,
        column: c.column,
        old_file: c.old_file.clone(),
        old_line: c.old_line,
        old_column: c.old_column,
    }
}
