//! The history of every component profile: the commits that changed its file (a git work tree
//! as input, a `[[source]]` repository at its pinned commit) and RTCBuilder's backups beside
//! it, newest first, each version compared with the one before it by the diff engine
//! ([`crate::diff::compare_profiles`]). Each distinct blob is read (one `git cat-file --batch`
//! per repository, streamed) and parsed once, keyed by its object id; a component's newest blob
//! that is its file byte for byte is not parsed at all (the catalogue's profile stands for it).
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
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Commits read per profile when `history` is not set.
pub const DEFAULT_LIMIT: usize = 100;

/// A blob's bytes, or why git could not give them.
type Blob = Result<Vec<u8>, String>;

/// Whether a blob git gave is parsed and kept: (repository index, object id, a path it had,
/// bytes). A blob no version needs is dropped as it arrives.
type KeepFn<'a> = &'a mut dyn FnMut(usize, &str, &str, &[u8]) -> bool;

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
    /// The commit added the file at this path (git found no older path for it).
    added: bool,
}

/// A repository histories are read from.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Repo {
    /// The work tree holding the input directory (git run in it, at `HEAD`).
    WorkTree(PathBuf),
    /// The bare mirror of a `[[source]]` (at the source's pinned commit).
    Mirror(PathBuf),
}

/// What git answered: whether it succeeded, its output and its error output.
struct Answer {
    ok: bool,
    stdout: Vec<u8>,
    stderr: Vec<u8>,
}

impl Repo {
    /// `c` (a command of this repository) run, or, for a mirror, its answer kept in the cache
    /// ([`crate::sources::memo`]): the revisions asked about are the pinned commits and their
    /// ancestors, so the answer cannot change while git's configuration does not (it is part
    /// of the key). `None`: git does not run.
    fn answer(&self, mut c: Command) -> Option<Answer> {
        use crate::sources::memo;
        let kept = match self {
            Repo::Mirror(m) => memo::folder(m, "answers").map(|d| {
                let mut key = format!(
                    "answer {}\0{:016x}",
                    env!("CARGO_PKG_VERSION"),
                    memo::config_stamp(m)
                );
                // Without the mirror's path: the answers are kept in the mirror, and a cache
                // named another way (relative, through a link) is the same.
                let mut args = c.get_args();
                while let Some(a) = args.next() {
                    if a == "--git-dir" {
                        args.next();
                        continue;
                    }
                    key.push('\0');
                    key.push_str(&a.to_string_lossy());
                }
                (d, key)
            }),
            Repo::WorkTree(_) => None,
        };
        if let Some((d, key)) = &kept {
            if let Some(v) = memo::recall(d, key) {
                let mut rest = &v[..];
                if let (Some(&[ok]), Some(stdout), Some(stderr)) = (
                    memo::take_field(&mut rest),
                    memo::take_field(&mut rest),
                    memo::take_field(&mut rest),
                ) {
                    return Some(Answer {
                        ok: ok == 1,
                        stdout: stdout.to_vec(),
                        stderr: stderr.to_vec(),
                    });
                }
            }
        }
        let out = c.output().ok()?;
        let a = Answer {
            ok: out.status.success(),
            stdout: out.stdout,
            stderr: out.stderr,
        };
        // A git killed by a signal answered nothing that can be kept; nor did one that failed,
        // but for the parent of a commit (`C^`: a root commit's parent never appears) and for
        // `git config --get` (a setting not set; the configuration is in the key): a failure
        // for anything else may pass (the history then says that git could not give it).
        let expected = c
            .get_args()
            .any(|a| a == "config" || a.to_string_lossy().ends_with('^'));
        let keep = out.status.code().is_some() && (a.ok || expected);
        if let Some((d, key)) = kept.filter(|_| keep) {
            let mut v = Vec::with_capacity(a.stdout.len() + a.stderr.len() + 32);
            memo::put_field(&mut v, &[u8::from(a.ok)]);
            memo::put_field(&mut v, &a.stdout);
            memo::put_field(&mut v, &a.stderr);
            memo::remember(&d, &key, &v);
        }
        Some(a)
    }

    fn git(&self) -> Command {
        let mut c = match self {
            Repo::WorkTree(dir) => crate::sources::work_tree_git(dir),
            Repo::Mirror(m) => crate::sources::git_command(Some(m)),
        };
        c.args(["-c", "log.showSignature=false", "--literal-pathspecs"]);
        c
    }
}

/// Fills in `history` of every component: up to `limit` commits of its file (0: none, and no
/// history at all), its backups, and the file as it is when that differs from the newest
/// commit; then the history of every RT System profile the same way ([`attach_systems`]). A
/// repository that cannot be read leaves the documents without git history; a version that
/// cannot be read stays in the history with the reason.
pub fn attach(catalog: &mut Catalog, roots: &Roots, opts: &crate::build::LoadOptions) {
    if opts.history == 0 {
        return;
    }
    let mut repos = Repos::new(roots, &opts.sources);
    attach_components(catalog, &mut repos, roots, opts, &|_| true);
    attach_systems(catalog, &mut repos, opts.history, &opts.limits);
    attach_idl(catalog, &mut repos, roots, opts.history, &opts.limits);
    repos.finish(catalog);
}

/// [`attach`] for the components whose file (input path) is in `only`: the others keep the
/// history they have. `serve` calls it after an edit of profiles: one `git log` and one
/// `git cat-file` per edited file, not the whole catalogue's again.
pub fn attach_some(
    catalog: &mut Catalog,
    roots: &Roots,
    opts: &crate::build::LoadOptions,
    only: &std::collections::BTreeSet<String>,
) {
    if opts.history == 0 {
        return;
    }
    let mut repos = Repos::new(roots, &opts.sources);
    attach_components(catalog, &mut repos, roots, opts, &|c| {
        only.contains(&c.source)
    });
    repos.finish(catalog);
}

/// Fills in `history` of the components `wanted` says.
fn attach_components(
    catalog: &mut Catalog,
    repos: &mut Repos<'_>,
    roots: &Roots,
    opts: &crate::build::LoadOptions,
    wanted: &(dyn Fn(&Component) -> bool + Sync),
) {
    let (limit, limits) = (opts.history, &opts.limits);
    let located: Vec<Option<Located>> = catalog
        .components
        .iter()
        .map(|c| {
            wanted(c)
                .then(|| repos.locate(c.origin.as_ref(), &c.source))
                .flatten()
        })
        .collect();
    let parse = |bytes: &[u8], file: &str| parse_blob(bytes, file, limits);
    let mut logs = read_logs(repos, &located, limit);
    // A profile git's `--follow` lost at an older path: found again by its component id.
    let list = &repos.list;
    logs.par_iter_mut()
        .zip(&located)
        .zip(&catalog.components)
        .for_each(|((versions, l), c)| {
            if let Some((repo, rev, _)) = l {
                follow_by_id(
                    &list[*repo],
                    *repo,
                    rev,
                    versions,
                    limit,
                    &c.profile,
                    &parse,
                );
            }
        });
    // A component whose file is its newest commit's blob byte for byte (read in the same
    // format): that version is the catalogue's profile, not parsed again. Each blob is compared
    // with the files as git gives it, and kept only when some version needs it parsed.
    let mut current: Vec<Option<(usize, String)>> = vec![None; catalog.components.len()];
    let parsed = {
        let mut newest: Vec<HashMap<&str, Vec<usize>>> = vec![HashMap::new(); list.len()];
        let mut older: Vec<std::collections::HashSet<&str>> = vec![Default::default(); list.len()];
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
        let components = &catalog.components;
        let mut keep = |r: usize, oid: &str, file: &str, bytes: &[u8]| {
            let mut needed = older[r].contains(oid);
            for &ci in newest[r].get(oid).into_iter().flatten() {
                let c = &components[ci];
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
        read_parsed(list, &logs, &parse, &mut keep)
    };
    let (idl, cat) = (&catalog.idl, &*catalog);
    let histories: Vec<Option<Vec<Entry>>> = catalog
        .components
        .par_iter()
        .zip(logs)
        .zip(current)
        .map(|((c, commits), current)| {
            wanted(c).then(|| history_of(c, commits, &parsed, current, (idl, cat)))
        })
        .collect();
    for (c, h) in catalog.components.iter_mut().zip(histories) {
        if let Some(h) = h {
            c.history = h;
        }
    }
    let undated: Vec<&str> = catalog
        .components
        .iter()
        .filter(|c| wanted(c))
        .flat_map(|c| &c.backups)
        .filter(|b| b.saved.is_none())
        .map(|b| b.source.as_str())
        .collect();
    if let Some(note) = undated_backups_note(&undated) {
        catalog.history_notes.push(note);
    }
}

/// The note on backups whose names hold no valid save date and time
/// ([`crate::catalog::backups::saved_at`]): they cannot be placed among the versions, so the
/// history leaves them out (they are still listed on the component's page).
fn undated_backups_note(files: &[&str]) -> Option<String> {
    let first = files.first()?;
    let (what, it, each) = match files.len() {
        1 => (format!("the backup `{first}` has"), "it is", "it"),
        n => (
            format!("{n} backups (the first, `{first}`) have"),
            "they are",
            "each",
        ),
    };
    Some(format!(
        "{what} no valid save date and time in the name (`RTC.xml` then yyyymmddhhmmss), so {it} left out of the history (a version without a date has no place in it); rename {each} by the time it was saved (`RTC.xml20240131235900`), or delete it"
    ))
}

/// The repositories histories are read from, each once.
struct Repos<'a> {
    list: Vec<Repo>,
    /// The work tree around the input directory, if it is in one.
    local: Option<Repo>,
    sources: &'a [crate::sources::Pinned],
    /// The input directory: a folder below it holding a `.git` of its own (a clone of a
    /// component's repository among others) is the work tree of the files below it.
    root: PathBuf,
    /// The nearest folder below the input with a `.git`, by folder of a file (`None`: none).
    nested: HashMap<String, Option<String>>,
    /// The shallow clones among them (`.git/shallow`): their histories are cut short.
    shallow: std::collections::BTreeSet<String>,
    /// Why the work tree's histories are cut short (a shallow clone) or missing (a repository
    /// git refuses), for [`Catalog::history_notes`].
    note: Option<String>,
    /// The files whose log git could not give: the command that shows git's whole message
    /// (and where to run it), and git's first line, by file.
    failed: std::sync::Mutex<BTreeMap<String, (String, String)>>,
}

/// Where a document's file is: (repository index, revision, path in the repository).
type Located = (usize, String, String);

impl<'a> Repos<'a> {
    fn new(roots: &Roots, sources: &'a [crate::sources::Pinned]) -> Self {
        let crate::sources::WorkTree { inside, note } = roots.work_tree();
        Repos {
            list: Vec::new(),
            local: inside.then(|| Repo::WorkTree(roots.local.clone())),
            sources,
            root: roots.local.clone(),
            nested: HashMap::new(),
            shallow: Default::default(),
            note,
            failed: Default::default(),
        }
    }

    /// Git could not give the log of `path` at `rev` of `repo`: `error`.
    fn failed(&self, repo: &Repo, rev: &str, path: &str, error: String) {
        let command = match repo {
            Repo::WorkTree(d) if *d == self.root => {
                format!("`git log --follow -- {path}` in the input directory")
            }
            Repo::WorkTree(d) => format!("`git log --follow -- {path}` in `{}`", d.display()),
            Repo::Mirror(m) => format!(
                "`git --git-dir {} log --follow {rev} -- {path}`",
                m.display()
            ),
        };
        self.failed
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(path.to_string(), (command, error));
    }

    /// Hands the notes to the catalogue: one for all the files whose log git could not give.
    fn finish(self, catalog: &mut Catalog) {
        let mut notes: std::collections::BTreeSet<String> = self.note.into_iter().collect();
        if let Some(first) = self.shallow.iter().next() {
            let at = self.root.join(first);
            let at = at.display();
            notes.insert(match self.shallow.len() {
                1 => format!("the clone `{first}` is a shallow clone: its histories start at its oldest commit, not where the file began; fetch its whole history (`git -C {at} fetch --unshallow`)"),
                n => format!("{n} clones (the first, `{first}`) are shallow clones: their histories start at their oldest commit, not where the file began; fetch the whole history of each (`git -C {at} fetch --unshallow`)"),
            });
        }
        let failed = self.failed.into_inner().unwrap_or_else(|e| e.into_inner());
        if let Some((path, (command, error))) = failed.iter().next() {
            notes.insert(match failed.len() {
                1 => format!(
                    "git could not give the history of `{path}` ({error}); it shows only its working copy and backups: {command} says more"
                ),
                n => format!(
                    "git could not give the history of {n} files (the first, `{path}`: {error}); they show only their working copy and backups: {command} says more"
                ),
            });
        }
        notes.extend(std::mem::take(&mut catalog.history_notes));
        catalog.history_notes = notes.into_iter().collect();
    }

    /// The nearest folder of `source` (a path in the input directory) below the input that
    /// holds a `.git` (a folder, or the file of a linked work tree; never a symbolic link), and
    /// `source`'s path from it: a folder of clones keeps each clone's history, whether or not
    /// the input is itself in a work tree.
    fn nested_repo(&mut self, source: &str) -> Option<(String, String)> {
        let parts: Vec<&str> = source.split('/').collect();
        for i in (1..parts.len()).rev() {
            let folder = parts[..i].join("/");
            let (root, shallow) = (&self.root, &mut self.shallow);
            let found = self
                .nested
                .entry(folder.clone())
                .or_insert_with(|| {
                    let dot = root.join(&folder).join(".git");
                    let meta = std::fs::symlink_metadata(&dot).ok()?;
                    if meta.is_dir() && dot.join("shallow").is_file() {
                        shallow.insert(folder.clone());
                    }
                    (meta.is_dir() || meta.is_file()).then(|| folder.clone())
                })
                .clone();
            if let Some(dir) = found {
                return Some((dir, parts[i..].join("/")));
            }
        }
        None
    }

    /// The repository, revision and path of a document read from `origin` (a `[[source]]`) or
    /// from `source` of the input directory; `None` when no repository holds it.
    fn locate(&mut self, origin: Option<&crate::model::Origin>, source: &str) -> Option<Located> {
        let (repo, rev, path) = match origin {
            Some(o) => {
                let p = self.sources.iter().find(|p| p.source.name == o.source)?;
                (
                    Repo::Mirror(p.mirror.clone()),
                    o.commit.clone(),
                    o.path.clone(),
                )
            }
            None => match self.nested_repo(source) {
                Some((dir, path)) => (Repo::WorkTree(self.root.join(dir)), "HEAD".into(), path),
                None => (self.local.clone()?, "HEAD".to_string(), source.to_string()),
            },
        };
        let at = match self.list.iter().position(|r| *r == repo) {
            Some(i) => i,
            None => {
                self.list.push(repo);
                self.list.len() - 1
            }
        };
        Some((at, rev, path))
    }
}

/// Parses a version's bytes (with a path the blob had) into its document, or says why not.
type ParseFn<'a, D> = &'a (dyn Fn(&[u8], &str) -> Result<D, String> + Sync);

/// Compares two versions (each with its file) into the changes of the newer.
type CompareFn<'a, D> = &'a dyn Fn((&D, &str), (&D, &str)) -> Vec<Change>;

/// A version's document by blob, per repository, parsed once.
type Parsed<D> = Vec<HashMap<String, Result<D, String>>>;

/// The commits of each located file (newest first, up to `limit`) and every distinct blob of
/// them read (one `git cat-file --batch` per repository) and parsed once by `parse` (bytes, a
/// path the blob had: its extension names the format when the content does not).
fn read_versions<D: Send>(
    repos: &Repos<'_>,
    located: &[Option<Located>],
    limit: usize,
    parse: ParseFn<'_, D>,
) -> (Vec<Vec<Version>>, Parsed<D>) {
    let logs = read_logs(repos, located, limit);
    let parsed = read_parsed(&repos.list, &logs, parse, &mut |_, _, _, _| true);
    (logs, parsed)
}

/// The commits of each located file, newest first, up to `limit`.
///
/// From one log of the whole repository where it has several of the files ([`WholeLog`]),
/// else (or where `--follow` could find a rename or copy) a `git log --follow` per file.
fn read_logs(all: &Repos<'_>, located: &[Option<Located>], limit: usize) -> Vec<Vec<Version>> {
    let repos = &all.list;
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
    located
        .par_iter()
        .map(|l| match l {
            Some((repo, rev, path)) => wholes
                .get(&(*repo, rev.as_str()))
                .and_then(|w| w.log(*repo, path, limit))
                .unwrap_or_else(|| {
                    log(&repos[*repo], *repo, rev, path, limit).unwrap_or_else(|e| {
                        all.failed(&repos[*repo], rev, path, e);
                        Vec::new()
                    })
                }),
            None => Vec::new(),
        })
        .collect()
}

/// Every distinct blob of `logs` read (one `git cat-file --batch` per repository) and, when
/// `keep` wants it, parsed once by `parse`.
fn read_parsed<D: Send>(
    repos: &[Repo],
    logs: &[Vec<Version>],
    parse: ParseFn<'_, D>,
    keep: KeepFn<'_>,
) -> Parsed<D> {
    let mut wanted: Vec<BTreeMap<String, String>> = vec![BTreeMap::new(); repos.len()];
    for v in logs.iter().flatten() {
        if let Where::Blob { repo, oid } = &v.at {
            wanted[*repo]
                .entry(oid.clone())
                .or_insert_with(|| v.entry.file.clone());
        }
    }
    repos
        .iter()
        .zip(wanted)
        .enumerate()
        .map(|(at, (repo, oids))| read_blobs(repo, at, &oids, parse, keep))
        .collect()
}

/// Most deleted profile files looked at for a lost history at one commit.
const MAX_CANDIDATES: usize = 200;

/// Commits before the one that added a file looked at for a profile of the same component
/// deleted there (a folder renamed in two commits: the old file deleted, then the new one
/// added).
pub const MAX_GAP: usize = 20;

/// Continues `versions` (newest first, up to `limit`) where git's `--follow` stops at a commit
/// that added the file: when the commit before it held, at a path no longer at `rev`, exactly
/// one profile of the same component (vendor, category and name of its id, and language when
/// both say), the history goes on with that file's commits up to there; else, when one of the
/// [`MAX_GAP`] commits before deleted profiles and the newest of them to delete one of the same
/// component deleted exactly one, with that file's commits up to its deletion; and so on.
fn follow_by_id(
    repo: &Repo,
    at: usize,
    rev: &str,
    versions: &mut Vec<Version>,
    limit: usize,
    profile: &Profile,
    parse: ParseFn<'_, Profile>,
) {
    let mut now: Option<std::collections::HashSet<String>> = None;
    let mut seen: std::collections::HashSet<String> = std::collections::HashSet::new();
    while versions.len() < limit {
        let Some(oldest) = versions.last().filter(|v| v.added) else {
            return;
        };
        let Some(commit) = oldest.entry.commit.clone() else {
            return;
        };
        seen.insert(oldest.entry.file.clone());
        let parent = format!("{commit}^");
        let Some(before) = ls_tree(repo, &parent) else {
            return; // the first commit
        };
        let now = match &mut now {
            Some(n) => n,
            None => now.insert(
                ls_tree(repo, rev)
                    .unwrap_or_default()
                    .into_iter()
                    .map(|(_, p)| p)
                    .collect(),
            ),
        };
        let lost = |p: &str| {
            !now.contains(p)
                && !seen.contains(p)
                && p.rsplit_once('.').is_some_and(|(_, e)| {
                    crate::walk::is_document_extension(&e.to_ascii_lowercase())
                })
        };
        let candidates: Vec<(String, String)> = before
            .into_iter()
            .filter(|(_, p)| lost(p))
            .take(MAX_CANDIDATES)
            .collect();
        // The file as that commit added it, too: the id may have changed since (a new vendor
        // or category after the copy), and the deleted original has the id of then.
        // Read only when some deleted profile is looked at.
        let then = std::cell::OnceCell::new();
        let then = || {
            then.get_or_init(|| match &oldest.at {
                Where::Blob { oid, .. } => {
                    let mut blob = None;
                    let _ = cat_file(repo, std::slice::from_ref(oid), &mut |_, b| blob = Some(b));
                    blob.and_then(|b| b.ok())
                        .and_then(|bytes| parse(&bytes, &oldest.entry.file).ok())
                }
                _ => None,
            })
        };
        let same = |candidates: &[(String, String)]| -> Option<Vec<String>> {
            let oids: Vec<String> = candidates.iter().map(|(o, _)| o.clone()).collect();
            let mut blobs: Vec<Blob> = Vec::with_capacity(oids.len());
            cat_file(repo, &oids, &mut |_, b| blobs.push(b)).ok()?;
            Some(
                candidates
                    .iter()
                    .zip(&blobs)
                    .filter(|((_, path), bytes)| {
                        bytes
                            .as_ref()
                            .ok()
                            .and_then(|b| parse(b, path).ok())
                            .is_some_and(|p| {
                                crate::diff::same_component(&p, profile)
                                    || then()
                                        .as_ref()
                                        .is_some_and(|t| crate::diff::same_component(&p, t))
                            })
                    })
                    .map(|((_, path), _)| path.clone())
                    .collect(),
            )
        };
        let found = if candidates.is_empty() {
            Vec::new()
        } else {
            match same(&candidates) {
                Some(found) => found,
                None => return,
            }
        };
        let (old_path, from) = match &found[..] {
            [one] => (one.clone(), parent),
            [] => {
                // Deleted before the commit that added the file: the newest commit of the gap
                // deleting a profile of the same component.
                let mut hit = None;
                for (deleting, deleted) in deletions(repo, &parent, MAX_GAP) {
                    let deleted: Vec<(String, String)> = deleted
                        .into_iter()
                        .filter(|(_, p)| lost(p))
                        .take(MAX_CANDIDATES)
                        .collect();
                    if deleted.is_empty() {
                        continue;
                    }
                    match same(&deleted).as_deref() {
                        Some([]) => continue,
                        Some([one]) => hit = Some((one.clone(), format!("{deleting}^"))),
                        _ => {}
                    }
                    break;
                }
                match hit {
                    Some(hit) => hit,
                    None => return,
                }
            }
            _ => return,
        };
        let more = log(
            repo,
            at,
            &from,
            &pathspec(repo, &old_path),
            limit - versions.len(),
        )
        .unwrap_or_default();
        if more.is_empty() {
            return;
        }
        versions.extend(more);
    }
}

/// One entry of a commit's `git log --raw -z` output: `:mode mode old new status`, then the
/// path.
struct RawEntry<'a> {
    old: &'a str,
    new: &'a str,
    status: &'a str,
    path: &'a str,
}

/// The entries of one commit's `--raw -z` text (what follows its header); `None` when one is
/// malformed (fewer fields, or no path).
fn raw_entries(raw: &str) -> Option<Vec<RawEntry<'_>>> {
    let mut out = Vec::new();
    let mut parts = raw.trim_start_matches('\n').split('\0');
    while let Some(meta) = parts.next().filter(|m| m.starts_with(':')) {
        let mut fields = meta.split(' ').skip(2);
        let (Some(old), Some(new), Some(status)) = (fields.next(), fields.next(), fields.next())
        else {
            return None;
        };
        out.push(RawEntry {
            old,
            new,
            status,
            path: parts.next()?,
        });
    }
    Some(out)
}

/// `git log` of every file each commit touched, as [`raw_entries`] reads it: no renames, whole
/// ids, `--raw -z`, no colour, no external diff (the format and range are the caller's).
fn raw_log(repo: &Repo) -> Command {
    let mut c = repo.git();
    c.args([
        "log",
        "--no-renames",
        "--no-abbrev",
        "--raw",
        "-z",
        "--no-color",
        "--no-ext-diff",
    ]);
    c
}

/// The files deleted by each of the `count` commits up to `rev` (newest first): (commit, the
/// deleted blobs with their paths from the top of the repository); empty when git cannot say.
fn deletions(repo: &Repo, rev: &str, count: usize) -> Vec<(String, Vec<(String, String)>)> {
    if rev.starts_with('-') {
        return Vec::new();
    }
    let mut c = raw_log(repo);
    c.arg("--format=%x1e%H")
        .arg(format!("--max-count={count}"))
        .args(["--end-of-options", rev, "--"])
        .stderr(Stdio::null());
    let Some(out) = repo.answer(c).filter(|o| o.ok) else {
        return Vec::new();
    };
    let text = String::from_utf8_lossy(&out.stdout);
    let mut found = Vec::new();
    for record in text.split('\u{1e}').filter(|r| !r.is_empty()) {
        let (commit, raw) = record.split_once('\0').unwrap_or((record, ""));
        let deleted = raw_entries(raw)
            .unwrap_or_default()
            .into_iter()
            .filter(|e| e.status.starts_with('D'))
            .map(|e| (e.old.to_string(), e.path.to_string()))
            .collect();
        found.push((commit.trim().to_string(), deleted));
    }
    found
}

/// The files of `rev` (object id, path from the top of the repository), or `None` when git
/// cannot list them (no such commit).
fn ls_tree(repo: &Repo, rev: &str) -> Option<Vec<(String, String)>> {
    if rev.starts_with('-') {
        return None;
    }
    let mut c = repo.git();
    c.args([
        "ls-tree",
        "-r",
        "-z",
        "--full-tree",
        "--end-of-options",
        rev,
    ]);
    c.stderr(Stdio::null());
    let out = repo.answer(c).filter(|o| o.ok)?;
    let text = String::from_utf8_lossy(&out.stdout);
    Some(
        text.split('\0')
            .filter_map(|line| {
                let (meta, path) = line.split_once('\t')?;
                let mut f = meta.split(' ');
                let (_, kind, oid) = (f.next()?, f.next()?, f.next()?);
                (kind == "blob").then(|| (oid.to_string(), path.to_string()))
            })
            .collect(),
    )
}

/// A path from the top of the repository as a pathspec of `repo`'s commands (a work tree's run
/// in the input directory, which may be a folder of it).
fn pathspec(repo: &Repo, top: &str) -> String {
    let Repo::WorkTree(_) = repo else {
        return top.to_string();
    };
    let mut c = repo.git();
    c.args(["rev-parse", "--show-prefix"]);
    c.stderr(Stdio::null());
    let prefix = c
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default();
    match top.strip_prefix(&prefix) {
        Some(rest) => rest.to_string(),
        None => format!("{}{top}", "../".repeat(prefix.matches('/').count())),
    }
}

/// The commits that changed `path` up to `rev`, following renames, or git's first line of
/// error.
fn log(
    repo: &Repo,
    at: usize,
    rev: &str,
    path: &str,
    limit: usize,
) -> Result<Vec<Version>, String> {
    if rev.starts_with('-') || path.is_empty() {
        return Ok(Vec::new());
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
    let out = repo.answer(c).ok_or("git does not run")?;
    if !out.ok {
        return Err(crate::sources::first_error_line_of(&out.stderr));
    }
    Ok(parse_log(&String::from_utf8_lossy(&out.stdout), at))
}

/// A commit as `git log` describes it: id, author date, author, subject.
type Header<'a> = (&'a str, &'a str, &'a str, &'a str);

/// A version of a file at a commit: its blob `new` and its path then.
fn version(
    repo: usize,
    (commit, date, author, subject): Header,
    new: &str,
    file: &str,
    added: bool,
) -> Version {
    Version {
        added,
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
        repo.answer(c).map(|o| o.stdout)
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
    let mut c = raw_log(repo);
    c.args([
        "--format=%x1e%H%x1f%P%x1f%aI%x1f%an%x1f%s",
        "--end-of-options",
        rev,
        "--",
    ])
    .stderr(Stdio::null());
    let out = repo.answer(c)?;
    if !out.ok {
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
        for RawEntry {
            new, status, path, ..
        } in raw_entries(raw)?
        {
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
            // Added only by a root commit here: nothing before it to follow the file to by its
            // component id ([`follow_by_id`] would run a `git ls-tree` per file to find that).
            out.push(version(
                repo,
                (commit, date, author, subject),
                new,
                &full,
                false,
            ));
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
        // A copy (`--follow` finds copies too) starts a history of its own: its original is
        // still there, with its own history. (A copy whose original was deleted later goes on
        // at the original's path by its component id: [`follow_by_id`].)
        let copy = status.starts_with('C');
        out.push(version(
            repo,
            (commit, date, author, subject),
            new,
            file,
            copy || status.starts_with('A'),
        ));
        if copy {
            break;
        }
    }
    out
}

/// Reads the blobs `oids` of `repo` (the repository `at`; one `git cat-file --batch`), each
/// with the path it had, and parses those `keep` wants; a blob git cannot give is kept with
/// the reason.
fn read_blobs<D: Send>(
    repo: &Repo,
    at: usize,
    oids: &BTreeMap<String, String>,
    parse: ParseFn<'_, D>,
    keep: KeepFn<'_>,
) -> HashMap<String, Result<D, String>> {
    let ids: Vec<String> = oids.keys().cloned().collect();
    let mut raw: Vec<(String, Blob)> = Vec::new();
    if !ids.is_empty() {
        let mut visit = |oid: &str, blob: Blob| {
            let file = oids.get(oid).map_or("", String::as_str);
            if blob.as_ref().map_or(true, |b| keep(at, oid, file, b)) {
                raw.push((oid.to_string(), blob));
            }
        };
        if let Err(e) = cat_file(repo, &ids, &mut visit) {
            for o in &ids {
                visit(o, Err(e.clone()));
            }
        }
    }
    raw.into_par_iter()
        .map(|(oid, bytes)| {
            let file = oids.get(&oid).map_or("", String::as_str);
            let parsed = bytes.and_then(|b| parse(&b, file));
            (oid, parsed)
        })
        .collect()
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

/// The format a version of a profile is read in: by its content, else by its file's extension.
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
/// in order as it arrives (the blobs a caller does not keep are never all in memory at once).
/// An error: git could not be run.
fn cat_file(repo: &Repo, oids: &[String], visit: &mut dyn FnMut(&str, Blob)) -> Result<(), String> {
    use crate::sources::memo;
    let kept = match repo {
        Repo::Mirror(m) => memo::folder(m, "blobs"),
        Repo::WorkTree(_) => None,
    };
    let key = |oid: &str| format!("blob\0{oid}");
    let mut reader: Option<crate::sources::objects::ObjectReader> = None;
    let mut at = 0;
    while at < oids.len() {
        // A run of blobs kept in the cache (a mirror's), then a run of the others from git.
        if let Some(d) = &kept {
            if let Some(bytes) = memo::recall(d, &key(&oids[at])) {
                visit(&oids[at], Ok(bytes));
                at += 1;
                continue;
            }
        }
        let end = match &kept {
            Some(d) => (at + 1..oids.len())
                .find(|&i| memo::has(d, &key(&oids[i])))
                .unwrap_or(oids.len()),
            None => oids.len(),
        };
        let r = match &mut reader {
            Some(r) => r,
            None => reader.insert(
                crate::sources::objects::ObjectReader::spawn(repo.git())
                    .map_err(|e| format!("cannot run git: {e:#}"))?,
            ),
        };
        let names: Vec<&str> = oids[at..end].iter().map(String::as_str).collect();
        let mut done = at;
        let read = r.read_each(&names, u64::MAX, &mut |i, o| {
            let oid = &oids[at + i];
            done = at + i + 1;
            let blob = match o {
                Some(o) if o.kind == "blob" => Ok(o.data),
                Some(o) => Err(format!(
                    "git cannot read the object ({} {})",
                    o.kind, o.size
                )),
                None => Err("git cannot read the object (missing)".to_string()),
            };
            if let (Some(d), Ok(bytes)) = (&kept, &blob) {
                if bytes.len() <= MAX_KEPT_BLOB {
                    memo::remember(d, &key(oid), bytes);
                }
            }
            visit(oid, blob);
            Ok(())
        });
        if let Err(e) = read {
            for oid in &oids[done..] {
                visit(oid, Err(format!("git gave no answer for it ({e:#})")));
            }
            return Ok(());
        }
        at = end;
    }
    Ok(())
}

/// Largest blob of a mirror kept in the cache for its history (a larger one is read from git
/// each build).
const MAX_KEPT_BLOB: usize = 16 << 20;

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

/// A component's history; `current`: the blob (repository, object id) that is the file byte
/// for byte, whose version is the catalogue's profile.
fn history_of(
    c: &Component,
    commits: Vec<Version>,
    parsed: &Parsed<Profile>,
    current: Option<(usize, String)>,
    (idl, cat): (&crate::idl::IdlSet, &Catalog),
) -> Vec<Entry> {
    // Backups, newest first, merged into the commits by date; one whose name holds no date
    // has no place among them and is left out ([`undated_backups_note`] says so).
    let mut backups: Vec<Version> = c
        .backups
        .iter()
        .enumerate()
        .filter(|(_, b)| b.saved.is_some())
        .map(|(i, b)| Version {
            added: false,
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
    let profile_of = |w: &Where| -> Result<&Profile, String> {
        match w {
            Where::Blob { repo, oid }
                if current.as_ref().is_some_and(|(r, o)| r == repo && o == oid) =>
            {
                Ok(&c.profile)
            }
            Where::Blob { repo, oid } => blob(parsed, *repo, oid),
            Where::Backup(i) => match &c.backups[*i].content {
                crate::catalog::backups::BackupContent::Profile(p) => Ok(p),
                crate::catalog::backups::BackupContent::Error(e) => Err(e.clone()),
            },
            Where::Current => Ok(&c.profile),
        }
    };
    entries(
        versions,
        (&*c.profile, &c.source),
        &profile_of,
        &|old, new| {
            let mut changes = crate::diff::compare_profiles(old, new, idl);
            relax_experimental(&mut changes, (c, new.0), cat);
            changes.iter().map(to_entry_change).collect()
        },
        &version_of,
    )
}

/// Relaxes the breaking changes of a version of component `c` (`new`: that version's profile)
/// as `rtcdoc diff` does ([`crate::diff::stability`]): experimental by the catalogue's mark
/// for the profile as it is, by the version's own `rtcdoc.stability` properties for an older
/// one; the data types' and interfaces' marks are the catalogue's.
fn relax_experimental(
    changes: &mut [crate::diff::Change],
    (c, new): (&Component, &Profile),
    cat: &Catalog,
) {
    use crate::model::stability::{from_properties, FromProperties};
    if changes.is_empty() {
        return;
    }
    let own;
    let mark = if std::ptr::eq(new, &*c.profile) {
        c.stability.as_ref()
    } else {
        own = match from_properties(&new.basic_info.properties) {
            FromProperties::Marked(s) => Some(s),
            _ => None,
        };
        own.as_ref()
    };
    crate::diff::stability::relax_version(changes, cat, new, mark);
}

/// The parsed document of blob `oid` of repository `repo`.
fn blob<'p, D>(parsed: &'p Parsed<D>, repo: usize, oid: &str) -> Result<&'p D, String> {
    match parsed[repo].get(oid) {
        Some(Ok(d)) => Ok(d),
        Some(Err(e)) => Err(e.clone()),
        None => Err("git did not read it".to_string()),
    }
}

/// A document's history from its versions (newest first): the file as it is (`current`, with
/// its path) first when it differs from the newest commit in what `compare` sees (uncommitted
/// edits), or when no commit records the history (the newest commit's document being `current`
/// itself, it does not differ: no diff); then each version with the changes from the readable
/// version before it. `doc_of` gives a version's document (or why it cannot);
/// `version_of` its version string (a new one is a release).
fn entries<'d, D>(
    mut versions: Vec<Version>,
    current: (&'d D, &str),
    doc_of: &dyn Fn(&Where) -> Result<&'d D, String>,
    compare: CompareFn<'_, D>,
    version_of: &dyn Fn(&D) -> Option<String>,
) -> Vec<Entry> {
    if versions.is_empty() {
        return Vec::new();
    }
    let newest_commit = versions.iter().find(|v| v.entry.commit.is_some());
    let current_differs = match newest_commit {
        None => true,
        Some(v) => match doc_of(&v.at) {
            Ok(d) if std::ptr::eq(d, current.0) => false,
            Ok(d) => !compare((d, &v.entry.file), current).is_empty(),
            Err(_) => true,
        },
    };
    if current_differs {
        versions.insert(
            0,
            Version {
                added: false,
                at: Where::Current,
                key: String::new(),
                entry: Entry {
                    file: current.1.to_string(),
                    ..Entry::default()
                },
            },
        );
    }
    let docs: Vec<Result<&D, String>> = versions.iter().map(|v| doc_of(&v.at)).collect();
    let mut entries = Vec::with_capacity(versions.len());
    for (i, v) in versions.iter().enumerate() {
        let mut e = v.entry.clone();
        // A commit's file at another path than the commit before: moved (folder renamed).
        if let Where::Blob { .. } = v.at {
            e.moved_from = versions[i + 1..]
                .iter()
                .find(|w| matches!(w.at, Where::Blob { .. }))
                .map(|w| &w.entry.file)
                .filter(|f| **f != v.entry.file)
                .cloned();
        }
        match &docs[i] {
            Err(why) => e.error = Some(why.clone()),
            Ok(d) => {
                e.version = version_of(d);
                let before = (i + 1..versions.len()).find(|&j| docs[j].is_ok());
                match before {
                    None => e.first = true,
                    Some(j) => {
                        let old = docs[j].as_ref().expect("found ok");
                        let same_blob = matches!((&v.at, &versions[j].at),
                            (Where::Blob { oid: a, repo: ra }, Where::Blob { oid: b, repo: rb }) if a == b && ra == rb);
                        if !same_blob {
                            e.changes = compare((old, &versions[j].entry.file), (d, &v.entry.file));
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

/// The changes between two versions of a file, as entries naming both versions' files.
fn in_files(changes: &[crate::diff::Change], (old_file, new_file): (&str, &str)) -> Vec<Change> {
    changes
        .iter()
        .map(|c| Change {
            file: Some(new_file.to_string()),
            old_file: Some(old_file.to_string()),
            ..to_entry_change(c)
        })
        .collect()
}

/// Fills in `history` of every RT System profile: the commits of its file, each version
/// compared with the one before by the system diff engine ([`crate::diff::systems::compare_systems`],
/// DIFF15x/25x/35x), and the file as it is when that differs from the newest commit.
fn attach_systems(catalog: &mut Catalog, repos: &mut Repos<'_>, limit: usize, limits: &Limits) {
    if catalog.systems.is_empty() {
        return;
    }
    let located: Vec<Option<Located>> = catalog
        .systems
        .iter()
        .map(|s| repos.locate(s.origin.as_ref(), &s.source))
        .collect();
    let (logs, parsed) = read_versions(repos, &located, limit, &|bytes, file| {
        parse_system_blob(bytes, file, limits)
    });
    let histories: Vec<Vec<Entry>> = catalog
        .systems
        .par_iter()
        .zip(logs)
        .map(|(s, commits)| {
            entries(
                commits,
                (&*s.profile, &s.source),
                &|w| match w {
                    Where::Blob { repo, oid } => blob(&parsed, *repo, oid),
                    Where::Current => Ok(&*s.profile),
                    Where::Backup(_) => Err("a system has no backups".to_string()),
                },
                &|(old, old_file), (new, new_file)| {
                    let changes = crate::diff::systems::compare_systems(old, new);
                    in_files(&changes, (old_file, new_file))
                },
                &system_version,
            )
        })
        .collect();
    for (s, h) in catalog.systems.iter_mut().zip(histories) {
        s.history = h;
    }
}

/// Parses one version of an RT System profile; `file` is its path then.
fn parse_system_blob(
    bytes: &[u8],
    file: &str,
    limits: &Limits,
) -> Result<crate::model::system::RtSystem, String> {
    let format = crate::build::system_format(Path::new(file), bytes);
    parse::rts::parse(format, bytes, file, limits)
        .map(|p| p.system)
        .map_err(|d| match d.pos {
            Some(p) => format!("line {}, column {}: {}", p.line, p.column, d.message),
            None => d.message,
        })
}

/// The version string of an RT System profile: its id's version part.
fn system_version(s: &crate::model::system::RtSystem) -> Option<String> {
    s.id_parts
        .as_ref()
        .and_then(|p| non_empty(&p.version))
        .map(str::to_string)
}

/// Fills in the history of every IDL file the catalogue read ([`Catalog::idl_history`]): the
/// commits of the file, each version read on its own and compared with the one before type by
/// type ([`crate::diff::compare_idl_files`]), and the file as it is on disk when that differs
/// from the newest commit (a file of the input's work tree). A file outside every repository
/// (`--idl-path` elsewhere) has none.
fn attach_idl(
    catalog: &mut Catalog,
    repos: &mut Repos<'_>,
    roots: &Roots,
    limit: usize,
    limits: &Limits,
) {
    if catalog.idl.files.is_empty() {
        return;
    }
    let located: Vec<Option<Located>> = catalog
        .idl
        .files
        .iter()
        .map(|f| repos.locate(f.origin.as_ref(), &f.path))
        .collect();
    let parse = |bytes: &[u8], file: &str| parse_idl_blob(bytes, file, limits);
    let (logs, parsed) = read_versions(repos, &located, limit, &parse);
    // The file as it is: only a file of the input directory can differ from its newest commit
    // (a source's is read at its pinned commit).
    let current: Vec<Option<Result<crate::idl::IdlSet, String>>> = catalog
        .idl
        .files
        .par_iter()
        .zip(&logs)
        .map(|(f, commits)| {
            (f.origin.is_none() && !commits.is_empty()).then(|| {
                std::fs::read(roots.local.join(&f.path))
                    .map_err(|e| e.to_string())
                    .and_then(|b| parse(&b, &f.path))
            })
        })
        .collect();
    let histories: Vec<(String, Vec<Entry>)> = catalog
        .idl
        .files
        .par_iter()
        .zip(logs)
        .zip(&current)
        .map(|((f, commits), now)| {
            let doc_of = |w: &Where| match w {
                Where::Blob { repo, oid } => blob(&parsed, *repo, oid),
                _ => Err("an IDL file has no backups".to_string()),
            };
            // Without a readable file on disk, the newest commit stands for it.
            let now = match now {
                Some(Ok(set)) => Some(set),
                _ => commits.first().and_then(|v| doc_of(&v.at).ok()),
            };
            let h = match now {
                None => Vec::new(),
                Some(now) => entries(
                    commits,
                    (now, &f.path),
                    &doc_of,
                    &|(old, old_file), (new, new_file)| {
                        let changes = crate::diff::compare_idl_files(old, new, &f.path);
                        in_files(&changes, (old_file, new_file))
                    },
                    &|_| None,
                ),
            };
            (f.path.clone(), h)
        })
        .collect();
    catalog.idl_history = histories
        .into_iter()
        .filter(|(_, h)| !h.is_empty())
        .collect();
}

/// Reads one version of an IDL file on its own (its includes are not at hand: a type of
/// another file stays as written); an error of the reader makes the version unreadable.
fn parse_idl_blob(bytes: &[u8], file: &str, limits: &Limits) -> Result<crate::idl::IdlSet, String> {
    let opts = crate::idl::IdlOptions {
        max_file_size: limits.max_file_size,
        max_depth: limits.max_depth,
        ..Default::default()
    };
    let set = crate::idl::read(&[crate::idl::SourceFile::new(file, bytes)], &opts);
    match set
        .diagnostics
        .iter()
        .find(|d| d.severity == crate::diagnostic::Severity::Error)
    {
        Some(d) => Err(match d.pos {
            Some(p) => format!("line {}, column {}: {}", p.line, p.column, d.message),
            None => d.message.clone(),
        }),
        None => Ok(set),
    }
}
