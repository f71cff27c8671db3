//! The two sides of `rtcdoc diff`: a directory (walked like `build`), one profile file, a
//! `catalog.json` written by `rtcdoc build --format json` (format 2, read back as the catalogue
//! it was written from), or `REV:PATH` — a path as it is in a git revision of the current repository, read with
//! `git ls-tree` and `git cat-file` into a temporary directory, without touching the work tree
//! or the index.

use crate::build::{self, LoadOptions};
use anyhow::{bail, Context, Result};

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Where a side comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Spec {
    /// A directory or a file on disk.
    Local(PathBuf),
    /// `REV:PATH` of the repository of the current directory.
    Git { rev: String, path: String },
    /// A `[[source]]` of rtcdoc.toml at a commit (`NAME` or `NAME@REV` on the command line).
    Source(Box<crate::sources::Pinned>),
}

impl Spec {
    /// What goes before a file of this side for a reader to open it: `REV:` for a revision
    /// (`REV:./` when its path is relative to the current folder, as `git show` reads it),
    /// nothing for a folder on disk.
    pub fn file_prefix(&self) -> String {
        match self {
            Spec::Git { rev, path } if path.starts_with("./") => format!("{rev}:./"),
            Spec::Git { rev, .. } => format!("{rev}:"),
            Spec::Local(_) | Spec::Source(_) => String::new(),
        }
    }

    /// Reads a command-line argument: an existing path is local (so `C:\dir` and files with a
    /// `:` in their name work), else `REV:PATH` when it has a `:`, else a local path (which
    /// does not exist: [`load`] says so).
    pub fn parse(arg: &str) -> Spec {
        if Path::new(arg).exists() {
            return Spec::Local(PathBuf::from(arg));
        }
        match arg.split_once(':') {
            Some((rev, path)) if !rev.is_empty() => Spec::Git {
                rev: rev.to_string(),
                // `REV:.` is this folder, as on the command line (git itself wants `REV:./`).
                path: match path.strip_suffix('.') {
                    Some("") => "./".to_string(),
                    Some(dir) if dir.ends_with('/') => dir.to_string(),
                    _ => path.to_string(),
                },
            },
            _ => Spec::Local(PathBuf::from(arg)),
        }
    }
}

/// A loaded side.
pub struct Side {
    pub loaded: build::Loaded,
    /// What the files of the catalogue are relative to, as the user names them: the input
    /// directory, the parent of an input file, or the path inside the repository.
    pub root: PathBuf,
    /// The temporary copy of a git revision (removed when the side is dropped).
    _temp: Option<tempfile::TempDir>,
}

impl Side {
    /// `file` (relative to the side's input) as the user can find it.
    pub fn display(&self, file: &str) -> String {
        let joined = self.root.join(file).to_string_lossy().replace('\\', "/");
        joined.strip_prefix("./").unwrap_or(&joined).to_string()
    }
}

impl Side {
    /// The RT System profiles of the side, as the load read them into the catalogue, and the
    /// load's errors of those it could not read.
    pub fn systems(&self) -> super::systems::Systems {
        super::systems::Systems {
            systems: self
                .loaded
                .catalog
                .systems
                .iter()
                .map(|s| super::systems::LoadedSystem {
                    source: s.source.clone(),
                    system: (*s.profile).clone(),
                })
                .collect(),
            unreadable: self
                .loaded
                .catalog
                .diagnostics
                .iter()
                .filter(|d| d.is_error() && self.loaded.failed_systems.contains(&d.file))
                .cloned()
                .collect(),
        }
    }
}

/// Whether `name` looks like a catalogue written by `rtcdoc build --format json`.
fn is_catalog_json(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"))
}

/// A side read from a `catalog.json` at `path` (`shown` as the user named it).
fn from_catalog_json(which: &str, shown: &str, path: &Path) -> Result<build::Loaded> {
    let bytes =
        std::fs::read(path).with_context(|| format!("{which} `{shown}`: cannot read it"))?;
    let read = crate::render::json::read_catalog(&bytes, shown)
        .with_context(|| format!("{which} `{shown}`"))?;
    let files = read.catalog.components.len();
    Ok(build::Loaded {
        catalog: read.catalog,
        skipped: Vec::new(),
        files,
        failed_systems: Vec::new(),
        roots: Default::default(),
        idl_on_no_page: Vec::new(),
    })
}

/// Loads one side (`which` is `OLD` or `NEW`, for messages).
pub fn load(which: &str, spec: &Spec, opts: &LoadOptions) -> Result<Side> {
    match spec {
        Spec::Local(p) => {
            if !p.exists() {
                let shown = p.display().to_string();
                if is_revision(&shown) {
                    bail!(
                        "{which} `{shown}` is a git revision, not a directory: name a folder in it, `{shown}:./` for this folder or `{shown}:components` (a path from the repository's top)"
                    );
                }
                bail!(
                    "{which} `{shown}` does not exist; give a directory, a profile or IDL file, or REV:PATH (a git revision and a path, e.g. origin/main:components)"
                );
            }
            if p.is_file() && is_catalog_json(p) {
                // Its files are relative to the input it was built from, which it does not
                // name: they are shown as the catalogue has them.
                return Ok(Side {
                    loaded: from_catalog_json(which, &p.display().to_string(), p)?,
                    root: PathBuf::new(),
                    _temp: None,
                });
            }
            let loaded =
                build::load(p, opts).with_context(|| format!("{which} `{}`", p.display()))?;
            let root = if p.is_file() {
                p.parent().map(Path::to_path_buf).unwrap_or_default()
            } else {
                p.clone()
            };
            Ok(Side {
                loaded,
                root,
                _temp: None,
            })
        }
        Spec::Source(pinned) => {
            let mut o = opts.clone();
            o.sources = vec![(**pinned).clone()];
            o.sources_only = true;
            let shown = format!("{}@{}", pinned.source.name, pinned.commit);
            let loaded =
                build::load(Path::new("."), &o).with_context(|| format!("{which} `{shown}`"))?;
            Ok(Side {
                loaded,
                root: PathBuf::new(),
                _temp: None,
            })
        }
        Spec::Git { rev, path } => {
            let object = format!("{rev}:{path}");
            let temp = tempfile::Builder::new()
                .prefix("rtcdoc-diff-")
                .tempdir()
                .context("cannot create a temporary directory for the git revision")?;
            let kind = git_checkout(which, &object, temp.path(), opts)?;
            let blob = match &kind {
                ObjectKind::Blob(name) => Some(name.clone()),
                ObjectKind::Tree => None,
            };
            let (input, root) = match kind {
                ObjectKind::Tree => (temp.path().to_path_buf(), PathBuf::from(path)),
                ObjectKind::Blob(name) => {
                    if is_catalog_json(Path::new(&name)) {
                        let loaded = from_catalog_json(which, &object, &temp.path().join(&name))?;
                        return Ok(Side {
                            loaded,
                            root: PathBuf::new(),
                            _temp: Some(temp),
                        });
                    }
                    (
                        temp.path().join(&name),
                        Path::new(path)
                            .parent()
                            .map(Path::to_path_buf)
                            .unwrap_or_default(),
                    )
                }
            };
            let loaded = build::load(&input, opts)
                .map_err(|e| {
                    // Named as the user wrote it: the temporary folder is gone when it is read.
                    match e.downcast::<build::NothingToDocument>() {
                        Ok(mut n) => {
                            // Only such files are taken out of the revision.
                            n.message = build::nothing_found(
                                &object,
                                &n.skipped,
                                n.backups.as_deref(),
                                "it holds no .xml, .yaml, .rtsys or .idl file",
                            );
                            // `--verbose` names the files skipped below it as `git show`
                            // opens them (`HEAD:./a.xml`).
                            n.input = PathBuf::from(if path.is_empty() {
                                format!("{rev}:./")
                            } else {
                                object.clone()
                            });
                            anyhow::Error::new(n)
                        }
                        Err(e) => as_typed(&e, temp.path(), &object, blob.as_deref()),
                    }
                })
                .with_context(|| format!("{which} `{object}`"))?;
            Ok(Side {
                loaded,
                root,
                _temp: Some(temp),
            })
        }
    }
}

/// The message of `e` (its causes included) with the paths of the temporary copy of a
/// revision (`/tmp/rtcdoc-diff-…/a.xml`) named as the user wrote the side (`REV:path/a.xml`),
/// `name` being the file a blob was written as: the folder is gone when the message is read,
/// and its name means nothing to the user.
fn as_typed(e: &anyhow::Error, temp: &Path, object: &str, name: Option<&str>) -> anyhow::Error {
    let mut text = format!("{e:#}");
    let dir = temp.to_string_lossy();
    if let Some(name) = name {
        text = text.replace(&temp.join(name).to_string_lossy().to_string(), object);
    }
    let inside = if object.ends_with(['/', ':']) {
        object.to_string()
    } else {
        format!("{object}/")
    };
    text = text.replace(&format!("{dir}/"), &inside);
    anyhow::anyhow!(text.replace(dir.as_ref(), object))
}

enum ObjectKind {
    Tree,
    /// A single file, written as `dest/<name>`.
    Blob(String),
}

fn git(args: &[&str]) -> Result<std::process::Output> {
    Command::new("git")
        .args(args)
        .stdin(Stdio::null())
        .output()
        .context("cannot run `git` (REV:PATH needs git on the PATH)")
}

/// Whether `name` is a commit of the repository around the current directory.
fn is_revision(name: &str) -> bool {
    !name.starts_with('-')
        && git(&[
            "rev-parse",
            "--verify",
            "--quiet",
            "--end-of-options",
            &format!("{name}^{{commit}}"),
        ])
        .is_ok_and(|o| o.status.success())
}

fn stderr_line(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr)
        .lines()
        .next()
        .unwrap_or("")
        .trim()
        .to_string()
}

/// Writes the profile-like files of `object` (`REV:PATH`) below `dest`, and the source files
/// beside them that the implementation check may read ([`crate::sources::code::write`]). The object is
/// data, never an option: it is refused when it starts with `-`, and passed after
/// `--end-of-options` to every git command.
fn git_checkout(which: &str, object: &str, dest: &Path, opts: &LoadOptions) -> Result<ObjectKind> {
    if object.starts_with('-') {
        bail!(
            "{which} `{object}` starts with `-`: a git revision never does, and rtcdoc does not pass options to git; name the revision (`HEAD~1:profiles`) or a directory"
        );
    }
    let inside = git(&["rev-parse", "--is-inside-work-tree"])?;
    if let Some(top) = crate::sources::refused_repository(&String::from_utf8_lossy(&inside.stderr))
    {
        bail!(
            "{which} `{object}` names a git revision, but git refuses the repository at `{top}` (it belongs to another user); {}, or give a directory",
            crate::sources::safe_directory_hint(top)
        );
    }
    if !inside.status.success() {
        bail!(
            "{which} `{object}` names a git revision, but the current directory is not in a git repository ({}); run rtcdoc diff inside the repository, or give a directory",
            stderr_line(&inside)
        );
    }
    let kind = git(&["cat-file", "-t", "--end-of-options", object])?;
    if !kind.status.success() {
        bail!(
            "{which} `{object}`: git cannot find it ({}); check the revision (`git log`, fetch it with `git fetch`, in CI check out with fetch-depth: 0) and the path (relative to the repository root, or ./ for the current directory)",
            stderr_line(&kind)
        );
    }
    match String::from_utf8_lossy(&kind.stdout).trim() {
        "blob" => {
            let name = object
                .rsplit(['/', ':'])
                .next()
                .filter(|n| !n.is_empty())
                .unwrap_or("RTC.xml")
                .to_string();
            let out = git(&["cat-file", "blob", "--end-of-options", object])?;
            if !out.status.success() {
                bail!("{which} `{object}`: {}", stderr_line(&out));
            }
            std::fs::write(dest.join(&name), &out.stdout).with_context(|| {
                format!("{which} `{object}`: cannot copy it out of git into a temporary folder")
            })?;
            Ok(ObjectKind::Blob(name))
        }
        "tree" => {
            let list = git(&[
                "ls-tree",
                "-r",
                "-z",
                "--full-tree",
                "--end-of-options",
                object,
            ])?;
            if !list.status.success() {
                bail!("{which} `{object}`: {}", stderr_line(&list));
            }
            let mut files = Vec::new();
            let mut sources = Vec::new();
            for entry in list.stdout.split(|b| *b == 0).filter(|e| !e.is_empty()) {
                let entry = String::from_utf8_lossy(entry);
                let Some((meta, rel)) = entry.split_once('\t') else {
                    continue;
                };
                let mut meta = meta.split(' ');
                let (mode, ty, sha) = (meta.next(), meta.next(), meta.next());
                // Regular files only: symbolic links (120000) and submodules are not followed,
                // as the walk does not follow them on disk.
                if ty != Some("blob") || !matches!(mode, Some("100644" | "100755")) {
                    continue;
                }
                let Some(sha) = sha else { continue };
                if wanted(rel) {
                    files.push((sha.to_string(), rel.to_string()));
                } else if opts.implementation.enabled && crate::sources::code::is_source_file(rel) {
                    sources.push((sha.to_string(), rel.to_string()));
                }
            }
            let copied = || format!("{which} `{object}`: cannot copy its files out of git");
            let mut reader = crate::sources::objects::ObjectReader::open(None)?;
            let mut sink = crate::sources::Dir(dest);
            crate::sources::write_blobs(&mut reader, &files, &mut sink, u64::MAX)
                .with_context(copied)?;
            crate::sources::code::write(
                &mut reader,
                &files,
                sources,
                &mut sink,
                &opts.implementation.selection(),
                opts.limits.max_file_size,
            )
            .with_context(copied)?;
            Ok(ObjectKind::Tree)
        }
        other => bail!("{which} `{object}` is a git {other}, not a directory or a file"),
    }
}

/// The files the walk could take as profiles (component or system): `.xml`, `.yaml`, `.yml`
/// and RTCBuilder's backup names; and `.idl` files, for the IDL-level comparison. The others
/// (sources, images) are not copied out of the repository.
fn wanted(rel: &str) -> bool {
    let p = Path::new(rel);
    p.components()
        .all(|c| matches!(c, std::path::Component::Normal(_)))
        && crate::walk::is_specification_file(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn specs() {
        assert_eq!(
            Spec::parse("origin/main:components"),
            Spec::Git {
                rev: "origin/main".into(),
                path: "components".into()
            }
        );
        assert_eq!(
            Spec::parse("HEAD:"),
            Spec::Git {
                rev: "HEAD".into(),
                path: "".into()
            }
        );
        for (dot, path) in [("HEAD~1:.", "./"), ("v1:comp/.", "comp/"), ("v1:a.", "a.")] {
            assert_eq!(
                Spec::parse(dot),
                Spec::Git {
                    rev: dot.split(':').next().unwrap().into(),
                    path: path.into()
                }
            );
        }
        assert_eq!(
            Spec::parse("no/such/dir"),
            Spec::Local("no/such/dir".into())
        );
        assert_eq!(Spec::parse("src"), Spec::Local("src".into()));
    }

    #[test]
    fn only_profile_like_safe_paths_are_copied() {
        assert!(wanted("a/RTC.xml"));
        assert!(wanted("a/b.YAML"));
        assert!(wanted("a/RTC.xml20230831164412"));
        assert!(wanted("idl/Nav.idl"));
        assert!(!wanted("a/main.cpp"));
        assert!(!wanted("../x.xml"));
    }
}
