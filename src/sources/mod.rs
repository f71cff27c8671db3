//! `[[source]]` repositories of `rtcdoc.toml`: documented at a pinned commit.
//!
//! - **Configuration** ([`SourceConfig`]): `git` (https, ssh, `user@host:path`, `file://` or a
//!   local path), `rev`, `path`, `name`, `source-url`. Anything else is refused before git
//!   runs ([`check_url`], [`check_rev`]): a URL or rev starting with `-`, transport helpers
//!   (`ext::`, `fd::`, any `x::`), `http://`, `git://`.
//! - **Cache** ([`cache_dir`]): one bare mirror per URL, `<cache>/<name>-<hash>.git`, filled
//!   with `git fetch` (branches, tags and the remote's `HEAD`).
//! - **Lock** ([`lock`]): `rtcdoc.lock` beside `rtcdoc.toml`, every source's URL, rev and
//!   commit; [`prepare`] uses the locked commits, resolves the new or edited sources and writes
//!   the lock; `--locked` refuses to change it; `--offline` never fetches.
//! - **Reading** ([`materialize`]): one `git cat-file --batch` per source
//!   ([`objects::ObjectReader`]) walks the pinned commit's tree (bounded: files and depth) and
//!   reads the blobs rtcdoc can read (profiles, IDL, READMEs and their images, the code of the
//!   implementation check), written below a temporary folder as `<name>/<path in the
//!   repository>`. Git objects only: no checkout, so no hooks, filters or submodules run;
//!   symbolic links and submodules are reported, not followed; a file above the size limit is
//!   cut at the limit plus one byte, so that it is reported as too large like one on disk.
//! - **Kept answers** ([`memo`]): a commit never changes, so what is read of it is kept below
//!   its mirror (the files of a source per commit and settings, that the walk found the commit
//!   and `path`, a mirror's history answers) and a warm build whose lock pins the same commits
//!   runs no git at all.
//!
//! The `git` command is used (as `rtcdoc diff REV:PATH` does) rather than a Rust git library:
//! it is the reference implementation of every transport and of the user's credentials (ssh
//! agent, credential helpers, `insteadOf`), and it adds nothing to the build. It runs without
//! the system configuration, without hooks, without a terminal prompt and with only the
//! `file`, `https` and `ssh` protocols allowed (`GIT_ALLOW_PROTOCOL`).

pub mod code;
pub mod lock;
pub mod memo;
pub mod objects;

use crate::diagnostic::{codes, Diagnostic};
use crate::model::SourceInfo;
use anyhow::{bail, Context, Result};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// A `[[source]]` table of `rtcdoc.toml`, as written.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct SourceConfig {
    /// The repository: an https or ssh URL, `git@host:path`, a `file://` URL or a local path.
    pub git: String,
    /// A branch, tag or commit; default (or `HEAD`) the remote's default branch.
    pub rev: Option<String>,
    /// The sub-folder to document; default the whole repository.
    pub path: Option<String>,
    /// A label (the first folder of the source's files in the catalogue); default from the URL.
    pub name: Option<String>,
    /// The URL template of a file in the repository, with `{commit}` and `{path}`; derived for
    /// GitHub and GitLab https URLs.
    pub source_url: Option<String>,
}

/// A source, checked: what to fetch and what to call it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Source {
    pub name: String,
    /// As written in `rtcdoc.toml` (and in the lock).
    pub git: String,
    /// What git is given: a local path made absolute against the configuration's folder.
    pub url: String,
    pub rev: Option<String>,
    /// `/`-separated, without leading or trailing `/`; `""` is the whole repository.
    pub path: String,
    pub source_url: Option<String>,
}

/// A source pinned at a commit, its objects in the cache.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Pinned {
    pub source: Source,
    pub commit: String,
    /// The bare mirror holding the commit.
    pub mirror: PathBuf,
    /// The files of the commit below `path`, when pinning walked its tree already (then
    /// [`materialize`] does not walk it again).
    pub listing: Option<Vec<objects::TreeEntry>>,
}

impl Pinned {
    /// The record of the catalogue.
    pub fn info(&self) -> SourceInfo {
        SourceInfo {
            name: self.source.name.clone(),
            git: self.source.git.clone(),
            rev: self.source.rev.clone(),
            commit: self.commit.clone(),
            path: self.source.path.clone(),
            source_url: self
                .source
                .source_url
                .clone()
                .or_else(|| derived_source_url(&self.source.git)),
        }
    }
}

/// How sources are fetched: `--cache-dir`, `--locked`, `--offline`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Mode {
    pub cache_dir: Option<PathBuf>,
    pub locked: bool,
    pub offline: bool,
    /// The configuration file, when `rtcdoc update` would not find it by itself (it is not
    /// `rtcdoc.toml` in the current directory): named in the commands the errors suggest.
    pub config: Option<PathBuf>,
    /// Sources fetched and read at once (`--jobs`, `jobs`); `None`: the number of cores.
    pub jobs: Option<usize>,
}

impl Mode {
    /// `rtcdoc update [NAME]` with the `--config` and `--cache-dir` that make it act on the
    /// same configuration and cache as the command that suggests it.
    pub fn update_command(&self, name: Option<&str>) -> String {
        use crate::quote::shell_word;
        let mut cmd = "rtcdoc update".to_string();
        if let Some(n) = name {
            cmd.push(' ');
            cmd.push_str(&shell_word(n));
        }
        if let Some(c) = &self.config {
            cmd.push_str(" --config ");
            cmd.push_str(&shell_word(&c.to_string_lossy()));
        }
        if let Some(d) = &self.cache_dir {
            cmd.push_str(" --cache-dir ");
            cmd.push_str(&shell_word(&d.to_string_lossy()));
        }
        cmd
    }
}

/// The sources of a configuration, checked: names unique, URLs, revs and paths safe. `base`
/// is the configuration's folder (local paths are relative to it).
pub fn check_all(configs: &[SourceConfig], base: &Path) -> Result<Vec<Source>> {
    let mut out: Vec<Source> = Vec::with_capacity(configs.len());
    for (i, c) in configs.iter().enumerate() {
        let which = format!("[[source]] #{} (`{}`)", i + 1, c.git);
        let url = check_url(&c.git, base).with_context(|| which.clone())?;
        if let Some(rev) = &c.rev {
            check_rev(rev).with_context(|| which.clone())?;
        }
        let path = check_path(c.path.as_deref().unwrap_or("")).with_context(|| which.clone())?;
        let name = match &c.name {
            Some(n) => n.clone(),
            None => name_from_url(&c.git),
        };
        check_name(&name).with_context(|| which.clone())?;
        if let Some(other) = out.iter().find(|s| s.name == name) {
            bail!(
                "{which}: the name `{name}` is taken by the source `{}`; give one of them another `name = \"…\"`",
                other.git
            );
        }
        if let Some(t) = &c.source_url {
            if !(t.starts_with("https://") || t.starts_with("http://")) || !t.contains("{path}") {
                bail!("{which}: source-url `{t}` must be an http(s) URL with `{{path}}` (and usually `{{commit}}`)");
            }
        }
        out.push(Source {
            name,
            git: c.git.clone(),
            url,
            rev: c.rev.clone(),
            path,
            source_url: c.source_url.clone(),
        });
    }
    Ok(out)
}

/// What git is given for `git` (a URL as is, a local path made absolute), or why it is refused.
pub fn check_url(git: &str, base: &Path) -> Result<String> {
    let g = git.trim();
    if g.is_empty() {
        bail!("`git` is empty; give the repository's URL or path");
    }
    if g != git || g.chars().any(char::is_control) {
        bail!("`git = {git:?}` has white space or control characters around or in it");
    }
    if g.starts_with('-') {
        bail!("`git = \"{g}\"` starts with `-`: rtcdoc never passes options to git; give a URL (https://, ssh://, git@host:path, file://) or a path");
    }
    if let Some((scheme, _)) = g.split_once("::") {
        bail!("`git = \"{g}\"` uses the git transport `{scheme}::`, which runs commands; rtcdoc reads https://, ssh://, git@host:path, file:// and local paths only");
    }
    if let Some((scheme, rest)) = g.split_once("://") {
        return match scheme.to_ascii_lowercase().as_str() {
            "https" | "ssh" if !rest.is_empty() => Ok(g.to_string()),
            "file" if !rest.is_empty() => Ok(g.to_string()),
            s => bail!("`git = \"{g}\"`: the transport `{s}://` is not supported; rtcdoc reads https://, ssh://, git@host:path, file:// and local paths only"),
        };
    }
    // scp-like `[user@]host:path` (not a Windows drive `C:\…`).
    if let Some((host, path)) = g.split_once(':') {
        let drive = host.len() == 1 && host.chars().all(|c| c.is_ascii_alphabetic());
        if !drive && !host.contains('/') && !host.contains('\\') {
            if host.is_empty() || path.is_empty() || host.ends_with('@') {
                bail!("`git = \"{g}\"` is neither a URL nor a path; write git@host:path, ssh://host/path, https://… or a path");
            }
            return Ok(g.to_string());
        }
    }
    let p = Path::new(g);
    let abs = if p.is_absolute() {
        p.to_path_buf()
    } else {
        base.join(p)
    };
    // `./x` beside a configuration in `.` is `./x`, not `././x` (as git would echo it).
    let tidy: PathBuf = abs.components().collect();
    Ok(tidy.to_string_lossy().into_owned())
}

/// A rev rtcdoc accepts: a branch, tag or commit name, never an option or a revision
/// expression.
pub fn check_rev(rev: &str) -> Result<()> {
    if rev.is_empty() {
        bail!("`rev` is empty; leave it out for the remote's default branch");
    }
    if rev.starts_with('-') {
        bail!("`rev = \"{rev}\"` starts with `-`: a branch, tag or commit never does, and rtcdoc does not pass options to git");
    }
    let bad = rev.chars().any(|c| {
        c.is_control() || c.is_whitespace() || matches!(c, '~' | '^' | ':' | '?' | '*' | '[' | '\\')
    });
    if bad
        || rev.contains("..")
        || rev.contains("@{")
        || rev.ends_with('/')
        || rev.ends_with(".lock")
    {
        bail!("`rev = \"{rev}\"` is not a branch, tag or commit name (no spaces, `~ ^ : ? * [ \\`, `..` or `@{{`); name a branch (`main`), a tag (`v1.2.0`) or a commit");
    }
    Ok(())
}

/// `path` checked and normalised: relative, inside the repository.
fn check_path(path: &str) -> Result<String> {
    let p = path.trim_matches('/');
    if path.starts_with('/') || path.contains('\\') {
        bail!("`path = \"{path}\"` must be relative to the repository's root, with `/`");
    }
    let mut parts = Vec::new();
    for seg in p.split('/') {
        match seg {
            "" | "." => {}
            ".." => bail!("`path = \"{path}\"` leaves the repository (`..`)"),
            s if s.chars().any(char::is_control) => {
                bail!("`path = {path:?}` has control characters")
            }
            s => parts.push(s),
        }
    }
    Ok(parts.join("/"))
}

/// A source's default name: the last segment of its URL or path, without `.git`.
pub fn name_from_url(git: &str) -> String {
    let trimmed = git.trim_end_matches(['/', '\\']);
    // `…/comp/.git` (a work tree's git directory) is named after `comp`, as `git clone` names it.
    let trimmed = trimmed
        .strip_suffix(".git")
        .filter(|t| t.ends_with(['/', '\\']))
        .map_or(trimmed, |t| t.trim_end_matches(['/', '\\']));
    let last = trimmed.rsplit(['/', '\\', ':']).next().unwrap_or(trimmed);
    let last = last.strip_suffix(".git").unwrap_or(last);
    let name: String = last
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '-'
            }
        })
        .collect();
    let name = name.trim_start_matches(['.', '-']).to_string();
    if name.is_empty() {
        "source".into()
    } else {
        name
    }
}

fn check_name(name: &str) -> Result<()> {
    let ok = !name.is_empty()
        && !name.starts_with(['.', '-'])
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'));
    if !ok {
        bail!("the source name `{name}` must be letters, digits, `-`, `_` or `.`, not starting with `.` or `-` (it is the first folder of the source's files); set `name = \"…\"`");
    }
    Ok(())
}

/// The file URL template of a GitHub or GitLab repository (https or `git@` form).
pub fn derived_source_url(git: &str) -> Option<String> {
    let g = git.trim().trim_end_matches('/');
    let g = g.strip_suffix(".git").unwrap_or(g);
    let (host, repo) = if let Some(rest) = g.strip_prefix("https://") {
        rest.split_once('/')?
    } else if let Some(rest) = g.strip_prefix("git@") {
        rest.split_once(':')?
    } else {
        return None;
    };
    let host = host.rsplit('@').next()?.to_ascii_lowercase();
    let ok = |s: &str| {
        !s.is_empty()
            && s.split('/').all(|p| {
                !p.is_empty()
                    && p != ".."
                    && p.chars()
                        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
            })
    };
    if !ok(repo) {
        return None;
    }
    match host.as_str() {
        "github.com" if repo.split('/').count() == 2 => Some(format!(
            "https://github.com/{repo}/blob/{{commit}}/{{path}}"
        )),
        "gitlab.com" if repo.split('/').count() >= 2 => Some(format!(
            "https://gitlab.com/{repo}/-/blob/{{commit}}/{{path}}"
        )),
        _ => None,
    }
}

/// The default cache: `$XDG_CACHE_HOME/rtcdoc`, `~/.cache/rtcdoc` (Linux), `~/Library/Caches/
/// rtcdoc` (macOS), `%LOCALAPPDATA%\rtcdoc\cache` (Windows).
pub fn default_cache_dir() -> Result<PathBuf> {
    let env = |k: &str| {
        std::env::var_os(k)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    let dir = if cfg!(windows) {
        env("LOCALAPPDATA").map(|d| d.join("rtcdoc").join("cache"))
    } else if cfg!(target_os = "macos") {
        env("HOME").map(|h| h.join("Library/Caches/rtcdoc"))
    } else {
        env("XDG_CACHE_HOME")
            .map(|d| d.join("rtcdoc"))
            .or_else(|| env("HOME").map(|h| h.join(".cache/rtcdoc")))
    };
    dir.context("no cache directory: HOME (or XDG_CACHE_HOME, LOCALAPPDATA) is not set; pass --cache-dir DIR")
}

/// The cache directory of `mode`.
pub fn cache_dir(mode: &Mode) -> Result<PathBuf> {
    match &mode.cache_dir {
        Some(d) => Ok(d.clone()),
        None => default_cache_dir(),
    }
}

/// The bare mirror of a source below `cache`.
pub fn mirror_path(cache: &Path, s: &Source) -> PathBuf {
    cache.join(format!(
        "{}-{:016x}.git",
        name_from_url(&s.git),
        crate::slug::fnv1a(s.url.as_bytes())
    ))
}

/// `git` run in the input directory `dir` (its history): [`git_command`], except that the
/// user's limit on finding the repository around it (`GIT_CEILING_DIRECTORIES`) is kept (the
/// sources' commands drop it: they name their repository).
pub(crate) fn work_tree_git(dir: &Path) -> Command {
    let mut c = git_command(None);
    c.current_dir(dir);
    if let Some(v) = std::env::var_os("GIT_CEILING_DIRECTORIES") {
        c.env("GIT_CEILING_DIRECTORIES", v);
    }
    c
}

/// Whether the input directory is inside a git work tree (and git runs), with a note when git
/// refuses the repository (owned by another user) or it is a shallow clone: its histories are
/// cut short.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct WorkTree {
    pub inside: bool,
    pub note: Option<String>,
}

/// The `git rev-parse` that answers [`WorkTree`] for a directory, started and not yet waited
/// for: a build starts it before reading the profiles, so that git's start-up overlaps them.
#[derive(Debug)]
pub struct WorkTreeProbe(Option<std::process::Child>);

impl WorkTreeProbe {
    /// Starts `git rev-parse` in `dir` (a probe that answers "not a work tree" when git does
    /// not start).
    pub fn start(dir: &Path) -> WorkTreeProbe {
        let mut c = work_tree_git(dir);
        c.args([
            "rev-parse",
            "--is-inside-work-tree",
            "--is-shallow-repository",
            "--show-toplevel",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
        WorkTreeProbe(c.spawn().ok())
    }

    /// Waits for git's answer.
    pub fn wait(mut self) -> WorkTree {
        let Some(Ok(o)) = self.0.take().map(|c| c.wait_with_output()) else {
            return WorkTree::default();
        };
        let err = String::from_utf8_lossy(&o.stderr);
        if !o.status.success() {
            let note = refused_repository(&err).map(|top| {
                format!(
                    "git refuses the repository at `{top}` (it belongs to another user), so no component has a git history; {}",
                    safe_directory_hint(top)
                )
            });
            return WorkTree {
                inside: false,
                note,
            };
        }
        let out = String::from_utf8_lossy(&o.stdout);
        let mut lines = out.lines();
        let inside = lines.next() == Some("true");
        let shallow = lines.next() == Some("true");
        let top = lines.next().unwrap_or_default();
        let note = (inside && shallow).then(|| {
            format!(
                "the repository at `{top}` is a shallow clone: each history starts at its oldest commit, not where the file began; fetch the whole history (`git fetch --unshallow`, or `fetch-depth: 0` for actions/checkout)"
            )
        });
        WorkTree { inside, note }
    }
}

impl Drop for WorkTreeProbe {
    /// A probe nobody waited for (the build failed first): git is stopped and reaped.
    fn drop(&mut self) {
        if let Some(mut c) = self.0.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

/// The repository git refuses because another user owns it, from git's error output
/// ("detected dubious ownership in repository at 'DIR'" … `safe.directory`): `DIR`.
pub(crate) fn refused_repository(stderr: &str) -> Option<&str> {
    if !stderr.contains("safe.directory") {
        return None;
    }
    stderr.split('\'').nth(1)
}

/// What to do about a repository git refuses ([`refused_repository`]).
pub(crate) fn safe_directory_hint(dir: &str) -> String {
    format!("if you trust it, run `git config --global --add safe.directory {dir}`")
}

/// `git` with the safe environment: no system configuration, no prompt, no hooks, only the
/// `file`, `https` and `ssh` protocols, nothing of a repository around the current directory.
pub(crate) fn git_command(git_dir: Option<&Path>) -> Command {
    let mut c = Command::new("git");
    for k in [
        "GIT_DIR",
        "GIT_WORK_TREE",
        "GIT_INDEX_FILE",
        "GIT_OBJECT_DIRECTORY",
        "GIT_ALTERNATE_OBJECT_DIRECTORIES",
        "GIT_NAMESPACE",
        "GIT_CEILING_DIRECTORIES",
    ] {
        c.env_remove(k);
    }
    c.env("GIT_CONFIG_NOSYSTEM", "1")
        .env("GIT_TERMINAL_PROMPT", "0")
        .env("GIT_ALLOW_PROTOCOL", "file:https:ssh")
        .env("GIT_PROTOCOL_FROM_USER", "0")
        .stdin(Stdio::null());
    if std::env::var_os("GIT_SSH_COMMAND").is_none() && std::env::var_os("GIT_SSH").is_none() {
        c.env("GIT_SSH_COMMAND", "ssh -o BatchMode=yes");
    }
    c.args([
        "-c",
        "core.hooksPath=/dev/null",
        "-c",
        "core.fsmonitor=false",
        "-c",
        "protocol.ext.allow=never",
        "-c",
        "protocol.fd.allow=never",
        "-c",
        "submodule.recurse=false",
        "-c",
        "fetch.recurseSubmodules=false",
    ]);
    if let Some(d) = git_dir {
        c.arg("--git-dir").arg(d);
    }
    c
}

fn run(mut c: Command) -> Result<std::process::Output> {
    c.output()
        .context("cannot run `git` ([[source]] repositories need git on the PATH)")
}

/// Runs `c`; its output when git succeeded, else the error `fail` words around git's first
/// error line.
fn run_ok(c: Command, fail: impl FnOnce(String) -> String) -> Result<std::process::Output> {
    let out = run(c)?;
    if !out.status.success() {
        bail!("{}", fail(first_error_line(&out)));
    }
    Ok(out)
}

/// Git's first `fatal:`/`error:` line of `out`, else its first line.
pub(crate) fn first_error_line(out: &std::process::Output) -> String {
    first_error_line_of(&out.stderr)
}

/// Git's first `fatal:`/`error:` line of its error output `stderr`, else its first line.
pub(crate) fn first_error_line_of(stderr: &[u8]) -> String {
    let text = String::from_utf8_lossy(stderr);
    text.lines()
        .map(str::trim)
        .find(|l| l.starts_with("fatal:") || l.starts_with("error:"))
        .or_else(|| text.lines().map(str::trim).find(|l| !l.is_empty()))
        .unwrap_or("no message")
        .to_string()
}

/// The commit `what` names in `mirror`, if any (`what` never starts with `-`).
fn rev_parse(mirror: &Path, what: &str) -> Result<Option<String>> {
    let mut c = git_command(Some(mirror));
    c.args(["rev-parse", "--verify", "--quiet", "--end-of-options"])
        .arg(format!("{what}^{{commit}}"));
    let out = run(c)?;
    Ok(out
        .status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
        .filter(|s| s.len() == 40 && s.bytes().all(|b| b.is_ascii_hexdigit())))
}

/// The error for a source whose `path` is no folder at `commit`.
fn no_folder(s: &Source, commit: &str) -> anyhow::Error {
    anyhow::anyhow!(
        "source `{}`: no folder `{}` at commit {commit} of `{}`; fix `path` in rtcdoc.toml (relative to the repository's root)",
        s.name,
        s.path,
        s.git
    )
}

/// Whether `rev` means the remote's default branch: none given, or `HEAD` (as `git ls-remote`
/// lists it first).
fn default_branch(rev: Option<&str>) -> bool {
    rev.is_none_or(|r| r == "HEAD")
}

/// The commit `rev` names in the mirror `reader` reads: a branch, else a tag, else a commit
/// (full or abbreviated hex); `None` or `HEAD`: the remote's default branch.
fn resolve(reader: &mut objects::ObjectReader, rev: Option<&str>) -> Result<Option<String>> {
    let Some(rev) = rev.filter(|r| !default_branch(Some(r))) else {
        return reader.commit_of(DEFAULT_REF);
    };
    for r in [format!("refs/heads/{rev}"), format!("refs/tags/{rev}")] {
        if let Some(c) = reader.commit_of(&r)? {
            return Ok(Some(c));
        }
    }
    if rev.len() >= 7 && rev.bytes().all(|b| b.is_ascii_hexdigit()) {
        return reader.commit_of(rev);
    }
    Ok(None)
}

/// The `git ls-remote` that lists a source's branches and tags, run from the current
/// directory: a local path as git is given it (made relative to where rtcdoc runs, not to
/// `rtcdoc.toml`).
fn ls_remote(s: &Source) -> String {
    format!("git ls-remote {}", crate::quote::shell_word(&s.url))
}

/// Where the remote's default branch is kept in a mirror.
const DEFAULT_REF: &str = "refs/rtcdoc/default";

fn is_mirror(mirror: &Path) -> bool {
    mirror.join("HEAD").is_file() && mirror.join("objects").is_dir()
}

/// Whether a mirror was ever fetched into: it holds a ref. A mirror left empty by a failed
/// first fetch (as older rtcdoc left them) counts as not cached.
fn fetched(mirror: &Path) -> bool {
    if !is_mirror(mirror) {
        return false;
    }
    let mut c = git_command(Some(mirror));
    c.args(["for-each-ref", "--count=1", "--format=x"]);
    run(c).is_ok_and(|o| o.status.success() && !o.stdout.is_empty())
}

/// Fetches a source's branches, tags and default branch into its mirror (created if needed);
/// `commit`, when given and still missing, is asked for by name. A first fetch that fails
/// leaves no mirror behind.
fn fetch(s: &Source, mirror: &Path, commit: Option<&str>) -> Result<()> {
    let cached = fetched(mirror);
    if !is_mirror(mirror) {
        if let Some(parent) = mirror.parent() {
            std::fs::create_dir_all(parent).with_context(|| {
                format!("cannot create the cache directory `{}`", parent.display())
            })?;
        }
        let mut c = git_command(None);
        c.args(["init", "--bare", "--quiet"]).arg(mirror);
        run_ok(c, |why| {
            format!(
                "cannot create the cache of source `{}` in `{}`: {why}",
                s.name,
                mirror.display()
            )
        })?;
    }
    let mut specs = vec![
        "+refs/heads/*:refs/heads/*".to_string(),
        "+refs/tags/*:refs/tags/*".to_string(),
    ];
    if default_branch(s.rev.as_deref()) {
        specs.push(format!("+HEAD:{DEFAULT_REF}"));
    }
    let mut c = git_command(Some(mirror));
    c.args([
        "fetch",
        "--quiet",
        "--prune",
        // A shallow clone's refs are taken (the mirror becomes shallow; a commit it lacks is
        // reported with a note saying why) rather than silently rejected.
        "--update-shallow",
        "--no-tags",
        "--no-write-fetch-head",
        "--end-of-options",
    ])
    .arg(&s.url)
    .args(&specs);
    let fetched = run_ok(c, |why| {
        format!(
            "source `{}`: git cannot fetch `{}` ({why}); check the URL or path and your access to it (ssh key, token){}",
            s.name,
            s.git,
            if cached {
                ", or build with --offline from the cache"
            } else {
                ""
            }
        )
    });
    if let Err(e) = fetched {
        if !cached && is_mirror(mirror) {
            // Nothing was ever fetched into it: no mirror stays that `--offline` would take
            // for a cached one.
            let _ = std::fs::remove_dir_all(mirror);
        }
        return Err(e);
    }
    if let Some(commit) = commit {
        if rev_parse(mirror, commit)?.is_none() {
            // Not on a branch or tag any more: ask for it by name (servers allow it when it
            // is reachable; otherwise the caller reports it missing).
            let mut c = git_command(Some(mirror));
            c.args([
                "fetch",
                "--quiet",
                "--no-tags",
                "--no-write-fetch-head",
                "--end-of-options",
            ])
            .arg(&s.url)
            .arg(commit);
            let _ = run(c)?;
        }
    }
    Ok(())
}

/// A hint for a missing commit or rev: a shallow mirror (fetched from a shallow clone) lacks
/// history.
fn shallow_note(mirror: &Path) -> &'static str {
    if mirror.join("shallow").is_file() {
        " (the repository fetched from is a shallow clone without that history: fetch it whole with `git fetch --unshallow` there, or use the full repository's URL)"
    } else {
        ""
    }
}

/// Pins every source: locked commits where the lock has the source unchanged, the current
/// commit of `rev` for the others (and every source named in `update`, all when it is
/// `Some(&[])`); fetches what the cache lacks (never with `--offline`) and writes the lock when
/// it changed (refused with `--locked`). `lock_path` is `rtcdoc.lock` beside the configuration.
/// The sources are pinned on `mode.jobs` threads (sources sharing a mirror one after another);
/// the results and the first error are those of the configuration's order.
pub fn prepare(
    sources: &[Source],
    lock_path: &Path,
    mode: &Mode,
    update: Option<&[String]>,
    progress: &dyn crate::progress::Progress,
) -> Result<(Vec<Pinned>, lock::Changes)> {
    let old = lock::read(lock_path, &mode.update_command(None))?;
    check_update_names(sources, update)?;
    let wanted_update = |s: &Source| match update {
        None => false,
        Some([]) => true,
        Some(names) => names.contains(&s.name),
    };
    let mut locked = Vec::with_capacity(sources.len());
    for s in sources {
        let l = old
            .as_ref()
            .and_then(|l| l.find(&s.name))
            .filter(|e| e.git == s.git && e.rev == s.rev)
            .map(|e| e.commit.clone());
        if mode.locked {
            if old.is_none() {
                bail!(
                    "--locked: there is no `{}`; run `{}` (or a build without --locked) to write it, and commit it",
                    lock_path.display(),
                    mode.update_command(None)
                );
            }
            if l.is_none() || update.is_some() {
                bail!(
                    "--locked: `{}` would have to change: the source `{}` is new or its `git` or `rev` was edited; run `{}` and commit the lock",
                    lock_path.display(),
                    s.name,
                    mode.update_command(Some(&s.name))
                );
            }
        }
        locked.push(l.filter(|_| !wanted_update(s)));
    }
    let cache = cache_dir(mode)?;
    progress.stage("fetching sources", sources.len());
    let results = in_parallel(sources, &cache, mode.jobs, |i, s, mirror| {
        let r = pin_one(s, locked[i].clone(), mirror, mode, lock_path);
        progress.advance(1);
        r
    })?;
    let mut pinned = Vec::with_capacity(sources.len());
    let mut new_lock = lock::Lock::default();
    for r in results {
        let p = r?;
        new_lock.sources.push(lock::Entry {
            name: p.source.name.clone(),
            git: p.source.git.clone(),
            rev: p.source.rev.clone(),
            commit: p.commit.clone(),
        });
        pinned.push(p);
    }
    new_lock.sort();
    let changes = lock::changes(old.as_ref(), &new_lock);
    if old.as_ref() != Some(&new_lock) {
        if mode.locked {
            bail!(
                "--locked: `{}` would have to change ({}); run `{}` and commit the lock",
                lock_path.display(),
                changes.describe(),
                mode.update_command(None)
            );
        }
        lock::write(lock_path, &new_lock)?;
    }
    Ok((pinned, changes))
}

/// Every name of `update` is a source's.
fn check_update_names(sources: &[Source], update: Option<&[String]>) -> Result<()> {
    for n in update.unwrap_or_default() {
        if !sources.iter().any(|s| &s.name == n) {
            let all: Vec<&str> = sources.iter().map(|s| s.name.as_str()).collect();
            bail!(
                "no source is named `{n}`; the sources are: {}",
                if all.is_empty() {
                    "(none)".to_string()
                } else {
                    all.join(", ")
                }
            );
        }
    }
    Ok(())
}

/// The number of threads `jobs` asks for: the number of cores when `None`.
pub fn threads(jobs: Option<usize>) -> usize {
    jobs.filter(|&j| j > 0).unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    })
}

/// `f(index, source, mirror)` of every source on `jobs` threads, the sources that share a
/// mirror one after another on one thread (git does not share a repository being fetched
/// into); the results in the order of `sources`.
fn in_parallel<T: Send>(
    sources: &[Source],
    cache: &Path,
    jobs: Option<usize>,
    f: impl Fn(usize, &Source, PathBuf) -> T + Sync,
) -> Result<Vec<T>> {
    use rayon::prelude::*;
    let mut groups: Vec<(PathBuf, Vec<usize>)> = Vec::new();
    for (i, s) in sources.iter().enumerate() {
        let m = mirror_path(cache, s);
        match groups.iter_mut().find(|(g, _)| *g == m) {
            Some((_, members)) => members.push(i),
            None => groups.push((m, vec![i])),
        }
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads(jobs))
        .build()
        .context("cannot start the threads that fetch the sources; try --jobs 1")?;
    let done: Vec<Vec<(usize, T)>> = pool.install(|| {
        groups
            .par_iter()
            .map(|(m, members)| {
                members
                    .iter()
                    .map(|&i| (i, f(i, &sources[i], m.clone())))
                    .collect()
            })
            .collect()
    });
    let mut all: Vec<(usize, T)> = done.into_iter().flatten().collect();
    all.sort_by_key(|(i, _)| *i);
    Ok(all.into_iter().map(|(_, t)| t).collect())
}

/// One source pinned: at its `locked` commit (fetched if the cache lacks it), else at the
/// current commit of its `rev`; its files listed (the walk of its tree answers whether the
/// commit is cached and whether `path` is a folder of it, without another git process).
fn pin_one(
    s: &Source,
    locked: Option<String>,
    mirror: PathBuf,
    mode: &Mode,
    lock_path: &Path,
) -> Result<Pinned> {
    let (commit, listing) = match locked {
        // Walked before: the commit is in the mirror and `path` a folder of it (neither can
        // change), and its files are read from the cache or by `materialize`.
        Some(commit) if pinned_before(&mirror, &commit, &s.path) => {
            return Ok(Pinned {
                source: s.clone(),
                commit,
                mirror,
                listing: None,
            });
        }
        Some(commit) => match walk(s, &mirror, &commit)? {
            Some(l) => (commit, Some(l)),
            None => {
                fetch_locked(s, &commit, &mirror, mode, lock_path)?;
                (commit, None)
            }
        },
        None => {
            refresh(
                s,
                &mirror,
                mode,
                &format!(" (or `{}`)", mode.update_command(None)),
            )?;
            // One reader resolves the rev and walks its tree.
            let mut reader = objects::ObjectReader::open(Some(&mirror))?;
            let commit = resolve_or_fail(s, &mirror, mode, &mut reader)?;
            let listing = reader
                .walk(&commit, &s.path)
                .with_context(|| format!("source `{}` at commit {commit}", s.name))?
                .ok_or_else(|| no_folder(s, &commit))?;
            (commit, Some(listing))
        }
    };
    // A `path` the commit lacks fails here, before the lock is written.
    let listing = match listing {
        Some(l) => l,
        None => walk(s, &mirror, &commit)?.ok_or_else(|| no_folder(s, &commit))?,
    };
    if let Some(d) = memo::folder(&mirror, "pinned") {
        memo::remember(&d, &pinned_key(&commit, &s.path), b"");
    }
    Ok(Pinned {
        source: s.clone(),
        commit,
        mirror,
        listing: Some(listing),
    })
}

/// The key of the record that `commit` is in a mirror with the folder `path`.
fn pinned_key(commit: &str, path: &str) -> String {
    format!("pinned\0{commit}\0{path}")
}

/// Whether a walk found `commit` in `mirror` with the folder `path` before (no git runs).
fn pinned_before(mirror: &Path, commit: &str, path: &str) -> bool {
    memo::folder(mirror, "pinned").is_some_and(|d| memo::has(&d, &pinned_key(commit, path)))
}

/// The files of `commit` below the source's `path`, walked in `mirror` with one
/// [`objects::ObjectReader`]; `None` when the mirror lacks the commit or `path` is no folder
/// of it; an error when the tree is past the walk's bounds.
fn walk(s: &Source, mirror: &Path, commit: &str) -> Result<Option<Vec<objects::TreeEntry>>> {
    if !is_mirror(mirror) {
        return Ok(None);
    }
    objects::ObjectReader::open(Some(mirror))?
        .walk(commit, &s.path)
        .with_context(|| format!("source `{}` at commit {commit}", s.name))
}

/// The locked commit of a source the cache lacks, fetched (refused with `--offline`).
fn fetch_locked(
    s: &Source,
    commit: &str,
    mirror: &Path,
    mode: &Mode,
    lock_path: &Path,
) -> Result<()> {
    if rev_parse(mirror, commit)?.is_some() {
        return Ok(());
    }
    if mode.offline {
        bail!(
            "source `{}`: the locked commit {commit} is not in the cache (`{}`) and --offline forbids fetching; run once without --offline (or `{}`) to fill the cache",
            s.name,
            mirror.display(),
            mode.update_command(None)
        );
    }
    fetch(s, mirror, Some(commit))?;
    if rev_parse(mirror, commit)?.is_none() {
        bail!(
            "source `{}`: `{}` no longer has the commit {commit} that `{}` names{}; run `{}` to move to the current `{}`",
            s.name,
            s.git,
            lock_path.display(),
            shallow_note(mirror),
            mode.update_command(Some(&s.name)),
            s.rev.as_deref().unwrap_or("default branch")
        );
    }
    Ok(())
}

/// The commit of a source's `rev` in its (refreshed) mirror, or why there is none.
fn resolve_or_fail(
    s: &Source,
    mirror: &Path,
    mode: &Mode,
    reader: &mut objects::ObjectReader,
) -> Result<String> {
    if let Some(c) = resolve(reader, s.rev.as_deref())? {
        return Ok(c);
    }
    match s.rev.as_ref().filter(|r| !default_branch(Some(r))) {
        Some(rev) => bail!(
            "source `{}`: no branch, tag or commit `{rev}` in `{}`{}{}; list them with `{}` and fix `rev` in rtcdoc.toml",
            s.name,
            s.git,
            shallow_note(mirror),
            if mode.offline { " (as cached: run without --offline to fetch)" } else { "" },
            ls_remote(s)
        ),
        None => bail!(
            "source `{}`: `{}` has no default branch (an empty repository?); push a commit or set `rev`",
            s.name,
            s.git
        ),
    }
}

/// Fetches a source into its mirror; with `--offline`, only checks that the mirror is cached
/// (`fill`: what else, after "run once without --offline", fills the cache).
fn refresh(s: &Source, mirror: &Path, mode: &Mode, fill: &str) -> Result<()> {
    if !mode.offline {
        return fetch(s, mirror, None);
    }
    if !fetched(mirror) {
        bail!(
            "source `{}` (`{}`) is not in the cache (`{}`) and --offline forbids fetching; run once without --offline{fill} to fill the cache",
            s.name,
            s.git,
            mirror.display()
        );
    }
    Ok(())
}

/// One source at `rev` (a branch, tag or commit), whatever the lock says: for `rtcdoc diff
/// NAME@REV`. Fetched unless `--offline`; the lock is neither read nor written.
pub fn pin_rev(s: &Source, rev: &str, mode: &Mode) -> Result<Pinned> {
    check_rev(rev).with_context(|| format!("`{}@{rev}`", s.name))?;
    let mut s = s.clone();
    s.rev = Some(rev.to_string());
    let mirror = mirror_path(&cache_dir(mode)?, &s);
    refresh(&s, &mirror, mode, "")?;
    let mut reader = objects::ObjectReader::open(Some(&mirror))?;
    let Some(commit) = resolve(&mut reader, Some(rev))? else {
        bail!(
            "source `{}`: no branch, tag or commit `{rev}` in `{}`{}; list them with `{}`",
            s.name,
            s.git,
            shallow_note(&mirror),
            ls_remote(&s)
        );
    };
    Ok(Pinned {
        source: s,
        commit,
        mirror,
        listing: None,
    })
}

/// The files of the pinned sources, below a temporary folder.
pub struct Materialized {
    pub dir: tempfile::TempDir,
    /// Symbolic links and submodules not followed (RTC015).
    pub notes: Vec<Diagnostic>,
}

/// Whether rtcdoc may read a repository file: a specification file, a README, an image.
fn wanted(rel: &str) -> bool {
    let p = Path::new(rel);
    let ext = p
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    crate::walk::is_specification_file(p)
        || crate::readme::is_readme_path(p)
        || crate::readme::IMAGE_EXTENSIONS.contains(&ext.as_deref().unwrap_or(""))
}

/// Whether the last segment of `rel` has no extension, as folders are named (`idl`, `Linked`,
/// `.github` too): a symbolic link of such a name may stand for a folder of profiles.
fn folder_shaped(rel: &str) -> bool {
    let last = rel.rsplit('/').next().unwrap_or(rel);
    !last.trim_start_matches('.').contains('.')
}

/// A repository path safe to write below the temporary folder.
fn safe(rel: &str) -> bool {
    !rel.is_empty()
        && rel.split('/').all(|seg| {
            !seg.is_empty()
                && seg != "."
                && seg != ".."
                && !seg.contains('\\')
                && !seg.contains('\0')
        })
}

/// Writes the readable files of every pinned source (at its commit, below its `path`) into a
/// new temporary folder as `<name>/<path in the repository>`. `max_file_size` bounds what is
/// kept of each file (one byte more, so that the readers report it as too large).
pub fn materialize(
    pinned: &[Pinned],
    max_file_size: u64,
    implementation: &code::Selection,
    jobs: Option<usize>,
    progress: &dyn crate::progress::Progress,
) -> Result<Materialized> {
    use rayon::prelude::*;
    let dir = tempfile::Builder::new()
        .prefix("rtcdoc-sources-")
        .tempdir()
        .context("cannot create a temporary directory for the sources")?;
    progress.stage("reading sources", pinned.len());
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads(jobs))
        .build()
        .context("cannot start the threads that read the sources; try --jobs 1")?;
    // Each source below a folder of its own (the names are unique): in parallel, the notes and
    // the first error in the sources' order.
    let each: Vec<Result<Vec<Diagnostic>>> = pool.install(|| {
        pinned
            .par_iter()
            .map(|p| {
                let r = materialize_one(p, dir.path(), max_file_size, implementation);
                progress.advance(1);
                r
            })
            .collect()
    });
    let mut notes = Vec::new();
    for r in each {
        notes.extend(r?);
    }
    Ok(Materialized { dir, notes })
}

/// The version of what [`materialize_one`] keeps of a source in the cache.
const FILES_FORMAT: u32 = 1;

/// The key of a source's files kept in the cache: its commit and everything else that changes
/// what is read of it (its name and `path`, the size limit, the code selection, rtcdoc's
/// version).
fn files_key(p: &Pinned, max_file_size: u64, implementation: &code::Selection) -> String {
    format!(
        "files {FILES_FORMAT} {}\0{}\0{}\0{}\0{max_file_size}\0{}\0{}",
        env!("CARGO_PKG_VERSION"),
        p.commit,
        p.source.name,
        p.source.path,
        implementation.enabled,
        implementation.named.join("\0")
    )
}

/// The files of one pinned source written below `dir/<name>`; the notes on what was not read.
/// Taken from the cache when an earlier build read them at this commit with these settings (no
/// git runs); else one [`objects::ObjectReader`] of its mirror walks the tree (unless pinning
/// did) and reads the files and the source code, and they are kept in the cache.
fn materialize_one(
    p: &Pinned,
    dir: &Path,
    max_file_size: u64,
    implementation: &code::Selection,
) -> Result<Vec<Diagnostic>> {
    let s = &p.source;
    let root = dir.join(&s.name);
    std::fs::create_dir_all(&root)?;
    let kept = memo::folder(&p.mirror, "files");
    let key = files_key(p, max_file_size, implementation);
    if let Some(notes) = kept.as_deref().and_then(|d| memo::recall(d, &key)) {
        if let Some(notes) = unpack(&notes, &root)? {
            return Ok(notes);
        }
    }
    let mut reader = objects::ObjectReader::open(Some(&p.mirror))?;
    let walked;
    let listing = match &p.listing {
        Some(l) => l,
        None => {
            walked = reader
                .walk(&p.commit, &s.path)
                .with_context(|| format!("source `{}` at commit {}", s.name, p.commit))?
                .ok_or_else(|| {
                    anyhow::anyhow!(
                        "source `{}`: the cache lacks commit {} or its folder `{}`; delete the cache `{}` and build again",
                        s.name,
                        p.commit,
                        s.path,
                        p.mirror.display()
                    )
                })?;
            &walked
        }
    };
    let (blobs, code, notes) = select(s, listing, implementation);
    let mut sink = Keeping {
        dir: Dir(&root),
        memo: kept.as_deref().and_then(|d| memo::Writer::new(d, &key)),
    };
    write_blobs(&mut reader, &blobs, &mut sink, max_file_size)
        .with_context(|| format!("source `{}`: cannot read its files from the cache", s.name))?;
    let profiles: Vec<(String, String)> = blobs
        .iter()
        .filter(|(_, rel)| crate::walk::is_specification_file(Path::new(rel)))
        .cloned()
        .collect();
    code::write(
        &mut reader,
        &profiles,
        code,
        &mut sink,
        implementation,
        max_file_size,
    )
    .with_context(|| {
        format!(
            "source `{}`: cannot read its source code from the cache",
            s.name
        )
    })?;
    if let Some(mut m) = sink.memo {
        for n in &notes {
            m.write(b"N");
            for f in [&n.file, &n.message, n.hint.as_deref().unwrap_or_default()] {
                m.write(&(f.len() as u64).to_le_bytes());
                m.write(f.as_bytes());
            }
        }
        m.finish();
    }
    Ok(notes)
}

/// A source's files kept in the cache ([`materialize_one`]) written below `root`: their notes,
/// or `None` when the entry does not read as one (it is then read from git again).
fn unpack(kept: &[u8], root: &Path) -> Result<Option<Vec<Diagnostic>>> {
    let mut files = Vec::new();
    let mut notes = Vec::new();
    let mut rest = kept;
    while let Some((&tag, after)) = rest.split_first() {
        rest = after;
        let mut field = || memo::take_field(&mut rest);
        match tag {
            b'F' => {
                let (Some(rel), Some(bytes)) = (field(), field()) else {
                    return Ok(None);
                };
                match std::str::from_utf8(rel) {
                    Ok(rel) if safe(rel) => files.push((rel, bytes)),
                    _ => return Ok(None),
                }
            }
            b'N' => {
                let (Some(file), Some(message), Some(hint)) = (field(), field(), field()) else {
                    return Ok(None);
                };
                let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
                let mut d = Diagnostic::info(codes::SOURCE_SKIPPED, &text(file), text(message));
                if !hint.is_empty() {
                    d = d.with_hint(text(hint));
                }
                notes.push(d);
            }
            _ => return Ok(None),
        }
    }
    let mut dir = Dir(root);
    for (rel, bytes) in files {
        dir.put(rel, bytes)?;
    }
    Ok(Some(notes))
}

/// A folder that the files go to, and the cache entry they are kept in too.
struct Keeping<'a> {
    dir: Dir<'a>,
    memo: Option<memo::Writer>,
}

impl Sink for Keeping<'_> {
    fn put(&mut self, rel: &str, bytes: &[u8]) -> Result<()> {
        self.dir.put(rel, bytes)?;
        if let Some(m) = &mut self.memo {
            m.write(b"F");
            for f in [rel.as_bytes(), bytes] {
                m.write(&(f.len() as u64).to_le_bytes());
                m.write(f);
            }
        }
        Ok(())
    }
}

/// What to read of a source's files: the blobs rtcdoc reads `(oid, path)`, the source code for
/// the implementation check, and the notes on the links and submodules not followed.
#[allow(clippy::type_complexity)]
fn select(
    s: &Source,
    listing: &[objects::TreeEntry],
    implementation: &code::Selection,
) -> (
    Vec<(String, String)>,
    Vec<(String, String)>,
    Vec<Diagnostic>,
) {
    let (mut blobs, mut code, mut notes) = (Vec::new(), Vec::new(), Vec::new());
    for e in listing {
        let rel = e.path.as_str();
        let (mode, ty) = (e.mode.as_str(), e.kind);
        let shown = format!("{}/{rel}", s.name);
        if !safe(rel) {
            continue;
        }
        // A submodule is noted whatever its name (a folder of another repository); a link
        // when rtcdoc would read a file of its name or when its name has no extension (it
        // may stand for a folder of profiles); a file only when rtcdoc reads its name.
        match (mode, ty) {
            ("120000", _) if !wanted(rel) && folder_shaped(rel) => notes.push(
                Diagnostic::info(
                    codes::SOURCE_SKIPPED,
                    &shown,
                    "a symbolic link without an extension (it may stand for a folder); not followed, nothing behind it is read (as in a directory)",
                )
                .with_hint("commit the folder itself instead of a link, or add the repository it belongs to as a [[source]] of its own"),
            ),
            // Source code, for the implementation check (`code::write` picks it).
            ("100644" | "100755", "blob")
                if !wanted(rel) && implementation.enabled && code::is_source_file(rel) =>
            {
                code.push((e.oid.clone(), rel.to_string()));
            }
            _ if ty != "commit" && !wanted(rel) => {}
            ("100644" | "100755", "blob") => blobs.push((e.oid.clone(), rel.to_string())),
            ("120000", _) => notes.push(
                Diagnostic::info(
                    codes::SOURCE_SKIPPED,
                    &shown,
                    "a symbolic link in the repository; not followed (as in a directory)",
                )
                .with_hint("commit the file itself instead of a link"),
            ),
            (_, "commit") => notes.push(
                Diagnostic::info(
                    codes::SOURCE_SKIPPED,
                    &shown,
                    "a submodule; its files are not read",
                )
                .with_hint("add the submodule's repository as a [[source]] of its own"),
            ),
            _ => {}
        }
    }
    (blobs, code, notes)
}

/// Where the files read out of git go: a folder, or a folder and a cache entry.
pub(crate) trait Sink {
    /// Keeps the file `rel` (a safe relative path) with `bytes`.
    fn put(&mut self, rel: &str, bytes: &[u8]) -> Result<()>;
}

/// The files written below a folder.
pub(crate) struct Dir<'a>(pub &'a Path);

impl Sink for Dir<'_> {
    fn put(&mut self, rel: &str, bytes: &[u8]) -> Result<()> {
        let path = self.0.join(rel);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::write(&path, bytes)?;
        Ok(())
    }
}

/// Writes the blobs `(oid, path)` that `reader` reads into `sink`, each cut at `max + 1` bytes
/// (the walk then reports a file over its limit as too large). Used for sources and for
/// `diff REV:PATH`.
pub(crate) fn write_blobs(
    reader: &mut objects::ObjectReader,
    files: &[(String, String)],
    sink: &mut dyn Sink,
    max: u64,
) -> Result<()> {
    write_blobs_where(reader, files, sink, max, &|_| true).map(|_| ())
}

/// [`write_blobs`], of the blobs whose (cut) content `accept` takes; the paths written.
pub(crate) fn write_blobs_where(
    reader: &mut objects::ObjectReader,
    files: &[(String, String)],
    sink: &mut dyn Sink,
    max: u64,
    accept: &dyn Fn(&[u8]) -> bool,
) -> Result<Vec<String>> {
    let mut written = Vec::new();
    let names: Vec<&str> = files.iter().map(|(oid, _)| oid.as_str()).collect();
    reader.read_each(&names, max, &mut |i, o| {
        let rel = &files[i].1;
        let Some(o) = o.filter(|o| o.kind == "blob") else {
            bail!("git cat-file has no blob {} for {rel}", files[i].0);
        };
        if accept(&o.data) {
            sink.put(rel, &o.data)?;
            written.push(rel.clone());
        }
        Ok(())
    })?;
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls() {
        let base = Path::new("/proj");
        for ok in [
            "https://github.com/o/r.git",
            "ssh://git@host/r.git",
            "git@github.com:o/r.git",
            "file:///srv/r.git",
        ] {
            assert_eq!(check_url(ok, base).unwrap(), ok);
        }
        assert_eq!(check_url("../r", base).unwrap(), "/proj/../r");
        for bad in [
            "-uhack",
            "ext::sh -c touch% /tmp/x",
            "fd::3",
            "http://x/r",
            "git://x/r",
            "",
            " x",
        ] {
            assert!(check_url(bad, base).is_err(), "{bad}");
        }
    }

    #[test]
    fn revs_paths_and_names() {
        for ok in ["main", "v1.2.0", "release/1.x", "0123456789abcdef"] {
            check_rev(ok).unwrap();
        }
        for bad in [
            "-x",
            "--upload-pack=x",
            "a..b",
            "HEAD~1",
            "a b",
            "x^{tree}",
            "@{-1}",
        ] {
            assert!(check_rev(bad).is_err(), "{bad}");
        }
        assert!(check_path("/a").is_err());
        assert_eq!(check_path("a/./b/").unwrap(), "a/b");
        assert!(check_path("a/../../b").is_err());
        for (url, name) in [
            ("https://github.com/o/Camera.git", "Camera"),
            ("git@host:o/nav-stack", "nav-stack"),
            ("/srv/repos/arm/", "arm"),
            ("../comp/.git", "comp"),
            ("C:\\work\\comp\\.git\\", "comp"),
            ("/srv/.git", "srv"),
        ] {
            assert_eq!(name_from_url(url), name, "{url}");
        }
    }

    #[test]
    fn derived_templates() {
        for (git, want) in [
            (
                "https://github.com/o/r.git",
                Some("https://github.com/o/r/blob/{commit}/{path}"),
            ),
            (
                "git@gitlab.com:g/sub/r.git",
                Some("https://gitlab.com/g/sub/r/-/blob/{commit}/{path}"),
            ),
            ("file:///srv/r", None),
            ("https://example.org/r.git", None),
        ] {
            assert_eq!(derived_source_url(git).as_deref(), want, "{git}");
        }
    }
}
