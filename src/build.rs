//! The pipeline behind `rtcdoc build`: walk → parse (in parallel) → catalogue → render → swap.

use crate::catalog::{backups::Backup, Catalog, LoadedProfile};
use crate::diagnostic::Diagnostic;
use crate::output::{absolute, Sink, Staging, WriterThread};
use crate::parse::{self, Limits};
use crate::render::{Format, Prefixed, RenderContext, SiteOptions};
use crate::walk::{self, Skipped, WalkOptions};
use anyhow::{bail, Context, Result};
use rayon::prelude::*;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// How to find and read profiles.
#[derive(Debug, Clone, Default)]
pub struct LoadOptions {
    pub include: Vec<String>,
    pub exclude: Vec<String>,
    pub limits: Limits,
    /// Directories the walk must not enter (the output directory).
    pub skip_dirs: Vec<PathBuf>,
    /// Accept an input with no profile at all (`--allow-empty`); otherwise that is an error.
    pub allow_empty: bool,
    /// More directories of IDL files (`--idl-path`, `idl-path`), searched recursively, e.g. an
    /// OpenRTM installation's `rtm/idl`.
    pub idl_path: Vec<PathBuf>,
    /// `[[source]]` repositories pinned at their commits, read besides (or instead of) the
    /// input directory ([`crate::sources`]).
    pub sources: Vec<crate::sources::Pinned>,
    /// Read only the sources, not the input directory (sources configured, no `input`).
    pub sources_only: bool,
    /// Sources read at once (`--jobs`, `jobs`); `None`: the number of cores.
    pub jobs: Option<usize>,
    /// Commits read per profile for its history (`history`, `--history`; 0: no history, the
    /// default of these options, as `check` and `diff` need none). Only `build` reads it.
    pub history: usize,
    /// What reads the history ([`crate::history::attach`], set by `config::build_options`: the
    /// history compares versions with `diff`, a later layer than this one).
    pub history_reader: Option<HistoryReader>,
    /// Whether and where each component's implementation is read (`[implementation]` of
    /// `rtcdoc.toml`; its size limit is `limits.max_file_size`).
    pub implementation: crate::catalog::implementations::Settings,
    /// The stability marks of `rtcdoc.toml`'s `[stability]` ([`crate::catalog::stability`]).
    pub stability: crate::catalog::stability::Settings,
}

/// Fills in the components' history of a loaded catalogue (see [`LoadOptions::history`]).
pub type HistoryReader = fn(&mut Catalog, &crate::catalog::sources::Roots, &LoadOptions);

/// `--strict` and a profile has an error: nothing was written. Carries the findings so the
/// caller can print them (exit status 1, like `check`).
#[derive(Debug, thiserror::Error)]
#[error("{errors} error(s) in the profiles (--strict); nothing was written")]
pub struct StrictFailure {
    pub errors: usize,
    pub diagnostics: Vec<Diagnostic>,
}

/// The input holds nothing to document (and `--allow-empty` was not given): the message names
/// the directory and what was skipped, which `--verbose` lists.
#[derive(Debug, thiserror::Error)]
#[error("{message}")]
pub struct NothingToDocument {
    pub message: String,
    /// The input directory (the sources' files are named `<source>/<path>`).
    pub input: PathBuf,
    /// What the walk did not take.
    pub skipped: Vec<Skipped>,
    /// What the message says of RTCBuilder's backups found without their profile.
    pub backups: Option<String>,
}

/// The result of loading a directory.
pub struct Loaded {
    pub catalog: Catalog,
    /// Files looked at and not taken (for `--verbose`).
    pub skipped: Vec<Skipped>,
    /// Number of profile files found (loaded or not).
    pub files: usize,
    /// RT System profiles that could not be read (their errors are among the catalogue's
    /// diagnostics), by path relative to the input.
    pub failed_systems: Vec<String>,
    /// Where the catalogue's files are (the input directory, the sources' temporary folder,
    /// kept while the catalogue is in use).
    pub roots: crate::catalog::sources::Roots,
    /// The types and interfaces that IDL files below the input define and no page shows
    /// (no port uses them, nor a type a port uses): scoped names, in file order
    /// ([`Catalog::idl_on_no_page`]). `catalog.json` has them.
    pub idl_on_no_page: Vec<String>,
}

pub use crate::progress::{Progress, Quiet};

/// Finds and reads every profile below `input` (a directory or one file) and builds the
/// catalogue. A file that cannot be read is reported and left out; the others still load.
pub fn load(input: &Path, opts: &LoadOptions) -> Result<Loaded> {
    load_with(input, opts, &Quiet)
}

/// The `[[source]]` repositories' files (read into a temporary folder) added to the
/// candidates `found` and recorded in `roots`; the notes on what was not read.
fn add_sources(
    input: &Path,
    opts: &LoadOptions,
    walk_opts: &WalkOptions,
    found: &mut walk::Candidates,
    roots: &mut crate::catalog::sources::Roots,
    progress: &dyn Progress,
) -> Result<Vec<Diagnostic>> {
    if opts.sources.is_empty() {
        return Ok(Vec::new());
    }
    let mut m = crate::sources::materialize(
        &opts.sources,
        opts.limits.max_file_size,
        &opts.implementation.selection(),
        opts.jobs,
        progress,
    )?;
    let names: Vec<&str> = opts
        .sources
        .iter()
        .map(|p| p.source.name.as_str())
        .collect();
    if let Some((_, rel)) = found
        .files
        .iter()
        .chain(&found.idl)
        .find(|(_, rel)| rel.split('/').next().is_some_and(|f| names.contains(&f)))
    {
        // Not "exclude the folder": the source's files are named `<name>/…` too, and an
        // exclude pattern matching the folder leaves them out as well.
        let folder = rel.split('/').next().unwrap_or_default();
        bail!(
            "`{rel}` of the input directory `{}` is in a folder named like a source (`{folder}`): the source's files are named `{folder}/…` too; give that [[source]] another name (`name = \"{folder}-source\"`) or move the folder out of the input directory (an `exclude` pattern for it would leave out the source's files as well)",
            input.display(),
        );
    }
    let mut from_sources = walk::candidates(
        m.dir.path(),
        &WalkOptions {
            skip_dirs: Vec::new(),
            ..walk_opts.clone()
        },
    )?;
    found.files.append(&mut from_sources.files);
    found.idl.append(&mut from_sources.idl);
    found.idl.sort_by(|a, b| a.1.cmp(&b.1));
    found.code.append(&mut from_sources.code);
    found.skipped.append(&mut from_sources.skipped);
    found.readme_dirs.append(&mut from_sources.readme_dirs);
    roots.sources = opts.sources.iter().map(|p| p.info()).collect();
    let notes = std::mem::take(&mut m.notes);
    roots.sources_dir = Some(std::sync::Arc::new(m.dir));
    Ok(notes)
}

/// What the candidates read to, sorted: the profiles, RT Systems and RTCBuilder backups; the
/// files that are not profiles added to `skipped`.
struct Sorted {
    diagnostics: Vec<Diagnostic>,
    profiles: Vec<LoadedProfile>,
    /// Component profiles read or failed.
    files: usize,
    systems: Vec<crate::catalog::systems::LoadedSystem>,
    failed_systems: Vec<String>,
    backups: Vec<Backup>,
}

/// Sorts what each candidate of `files` read to (`outcomes`, in their order); `named`: one
/// file named on the command line (`input`), which must be something rtcdoc reads.
fn sort_outcomes(
    input: &Path,
    files: Vec<(PathBuf, String)>,
    outcomes: Vec<Outcome>,
    named: bool,
    skipped: &mut Vec<Skipped>,
) -> Result<Sorted> {
    let mut diagnostics = Vec::new();
    let mut profiles = Vec::with_capacity(outcomes.len());
    let mut count = 0;
    let mut systems = Vec::new();
    let mut failed_systems = Vec::new();
    let mut backups = Vec::new();
    for ((path, rel), outcome) in files.into_iter().zip(outcomes) {
        // RTCBuilder's backups are older versions of the profile beside them, not components:
        // kept apart, whatever they hold (a file named on the command line is read as is).
        let outcome = if !named && walk::is_backup(&path) {
            match outcome {
                Outcome::Loaded(p, _) => {
                    backups.push(Backup::read(rel, p.profile));
                    continue;
                }
                Outcome::Failed(d) => {
                    backups.push(Backup::unreadable(rel, d.message));
                    continue;
                }
                Outcome::NotProfile(what) => {
                    backups.push(Backup::unreadable(rel, what));
                    continue;
                }
                other => other,
            }
        } else {
            outcome
        };
        match outcome {
            Outcome::NotProfile(what) if named => {
                bail!(
                    "`{}` {what}; name an RTC component profile (RTC.xml or its YAML form), an RT System profile or an IDL file (`.idl`)",
                    input.display()
                )
            }
            Outcome::NotProfile(what) if walk::named_like_profile(&path) => {
                let name = path
                    .file_name()
                    .map(|n| n.to_string_lossy())
                    .unwrap_or_default();
                diagnostics.push(
                    Diagnostic::warning(
                        crate::diagnostic::codes::NOT_A_PROFILE,
                        &rel,
                        format!("{name} {what}; it is not documented"),
                    )
                    .with_hint("restore it (version control, RTCBuilder), or rename or exclude it"),
                );
                skipped.push(walk::Skipped {
                    rel,
                    reason: what,
                    kind: walk::SkipKind::NotAProfile,
                });
            }
            Outcome::NotProfile(what) => skipped.push(walk::Skipped {
                rel,
                reason: what,
                kind: walk::SkipKind::NotAProfile,
            }),
            Outcome::Loaded(p, d) => {
                count += 1;
                profiles.push(p);
                diagnostics.extend(d);
            }
            Outcome::Failed(d) => {
                count += 1;
                diagnostics.push(d);
            }
            Outcome::System(s, d) => {
                systems.push(s);
                diagnostics.extend(d);
            }
            Outcome::SystemFailed(d) => {
                failed_systems.push(rel);
                diagnostics.push(d);
            }
        }
    }
    Ok(Sorted {
        diagnostics,
        profiles,
        files: count,
        systems,
        failed_systems,
        backups,
    })
}

/// [`load`] with progress reports.
pub fn load_with(input: &Path, opts: &LoadOptions, progress: &dyn Progress) -> Result<Loaded> {
    progress.stage("finding profiles", 0);
    let walk_opts = WalkOptions {
        include: opts.include.clone(),
        exclude: opts.exclude.clone(),
        skip_dirs: opts.skip_dirs.clone(),
    };
    let mut found = if opts.sources_only {
        walk::Candidates::default()
    } else {
        walk::candidates(input, &walk_opts)?
    };
    let mut roots = crate::catalog::sources::Roots::local(&input_root(input));
    // The history asks git whether the input is in a work tree: asked now, so that git's
    // start-up overlaps the reading of the profiles.
    if opts.history > 0 && opts.history_reader.is_some() {
        roots.start_work_tree_probe();
    }
    let source_notes = add_sources(input, opts, &walk_opts, &mut found, &mut roots, progress)?;
    // Each candidate is read once: its head tells whether it is a profile (as `walk::walk`
    // decides), and a profile is parsed from the same bytes.
    progress.stage("reading profiles", found.files.len());
    // A file named on the command line is read as a profile whatever its name.
    let named = !opts.sources_only && input.is_file();
    // The IDL files are read beside the profiles (their reading is mostly serial).
    let (outcomes, idl) = rayon::join(
        || read_outcomes(&found.files, opts, named, progress),
        || read_idl(&found.idl, opts),
    );
    progress.stage("cross-referencing", 0);
    let mut skipped = found.skipped;
    let Sorted {
        mut diagnostics,
        mut profiles,
        files,
        systems,
        mut failed_systems,
        backups,
    } = sort_outcomes(input, found.files, outcomes, named, &mut skipped)?;
    let idl = idl?;
    let implementation = crate::catalog::implementations::Settings {
        max_file_size: opts.limits.max_file_size,
        // A profile named on the command line is checked alone, as written.
        enabled: opts.implementation.enabled && !named,
        ..opts.implementation.clone()
    };
    // Components with code and no profile, documented from their code.
    let (recovered_profiles, recovered, recover_diags) =
        crate::catalog::implementations::recover(&profiles, &found.code, &implementation);
    let recovered_any = !recovered_profiles.is_empty();
    profiles.extend(recovered_profiles);
    diagnostics.extend(recover_diags);
    if files == 0
        && !recovered_any
        && systems.is_empty()
        && failed_systems.is_empty()
        && found.idl.is_empty()
        && !opts.allow_empty
    {
        if opts.sources_only {
            let names: Vec<&str> = opts
                .sources
                .iter()
                .map(|p| p.source.name.as_str())
                .collect();
            return Err(NothingToDocument {
                message: format!(
                    "nothing to document: no RTC component profile, RT System profile or IDL file in the sources {} at their pinned commits; check each source's `path` and the --include/--exclude patterns, or pass --allow-empty",
                    names.join(", ")
                ),
                input: input.to_path_buf(),
                skipped,
                backups: None,
            }
            .into());
        }
        let backups = backups_part(&backups);
        return Err(NothingToDocument {
            message: nothing_found(
                &input.display().to_string(),
                &skipped,
                backups.as_deref(),
                "it holds no files",
            ),
            input: input.to_path_buf(),
            skipped,
            backups,
        }
        .into());
    }
    diagnostics.extend(idl.diagnostics.iter().cloned());
    diagnostics.extend(source_notes);
    // `Catalog::build` orders the profiles by path and the diagnostics by file and position.
    let docs = crate::catalog::Documents {
        profiles,
        diagnostics,
        idl,
        systems,
        backups,
        // A file named on the command line: the walk listed no folder.
        readme_dirs: (!named).then_some(found.readme_dirs),
        implementation,
        recovered,
        stability: opts.stability.clone(),
    };
    let catalog = Catalog::assemble(docs, &roots, &walk::exclude_matcher(&opts.exclude));
    failed_systems.sort();
    let input_idl: HashSet<&str> = found.idl.iter().map(|(_, rel)| rel.as_str()).collect();
    let idl_on_no_page = catalog.idl_on_no_page(&input_idl);
    Ok(Loaded {
        catalog,
        skipped,
        files,
        failed_systems,
        roots,
        idl_on_no_page,
    })
}

/// The directory profile paths are relative to: `input`, or the folder of a file named.
pub fn input_root(input: &Path) -> PathBuf {
    if input.is_file() {
        input
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
    } else {
        input.to_path_buf()
    }
}

/// Reads an RT System profile (its head showed an `RtsProfile` root): at most the size limit
/// plus one byte, so that an oversized file is reported, not read whole.
pub fn read_system(
    path: &Path,
    rel: &str,
    limits: &Limits,
) -> std::result::Result<(crate::catalog::systems::LoadedSystem, Vec<Diagnostic>), Diagnostic> {
    use std::io::Read;
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| {
            f.take(limits.max_file_size.saturating_add(1))
                .read_to_end(&mut bytes)
        })
        .map_err(|e| Diagnostic::io(rel, &e))?;
    let format = system_format(path, &bytes);
    let parsed = parse::rts::parse(format, &bytes, rel, limits)?;
    Ok((
        crate::catalog::systems::LoadedSystem {
            source: rel.to_string(),
            format,
            system: Box::new(parsed.system),
            history: Vec::new(),
        },
        parsed.diagnostics,
    ))
}

/// XML when the file starts like XML (after a byte order mark and white space), else YAML.
pub(crate) fn system_format(path: &Path, bytes: &[u8]) -> parse::SourceFormat {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let body = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let first = body.iter().find(|b| !b.is_ascii_whitespace());
    match ext.as_deref() {
        Some("yaml" | "yml") => parse::SourceFormat::Yaml,
        Some("xml") => parse::SourceFormat::Xml,
        _ if first == Some(&b'<')
            || bytes.starts_with(&[0xFF, 0xFE])
            || bytes.starts_with(&[0xFE, 0xFF]) =>
        {
            parse::SourceFormat::Xml
        }
        _ => parse::SourceFormat::Yaml,
    }
}

/// What reading one candidate file gave.
enum Outcome {
    NotProfile(String),
    System(crate::catalog::systems::LoadedSystem, Vec<Diagnostic>),
    Loaded(LoadedProfile, Vec<Diagnostic>),
    Failed(Diagnostic),
    SystemFailed(Diagnostic),
}

/// The most files a core reads without offering the rest to the other cores.
const READ_PIECE: usize = 8;

/// Reads and parses the candidate `files` in parallel, in their order (`named`: the file was
/// named on the command line, read as a profile whatever its name).
fn read_outcomes(
    files: &[(PathBuf, String)],
    opts: &LoadOptions,
    named: bool,
    progress: &dyn Progress,
) -> Vec<Outcome> {
    files
        .par_iter()
        // Small pieces, so that no core is left idle while the other reads a long run of
        // files alone (rayon's adaptive split leaves pieces of a quarter of the list on two
        // cores: the last one was read alone for 30 ms at 3,000 profiles).
        .with_max_len(READ_PIECE)
        .map(|(path, rel)| {
            let outcome = match walk::read_profile(path, opts.limits.max_file_size, named) {
                Ok(walk::ReadFile::Other(head)) if parse::rts::is_system(&head) => {
                    match read_system(path, rel, &opts.limits) {
                        Ok((s, d)) => Outcome::System(s, d),
                        Err(d) => Outcome::SystemFailed(d),
                    }
                }
                Ok(walk::ReadFile::Other(head)) => {
                    Outcome::NotProfile(walk::describe_non_profile(&head))
                }
                Ok(walk::ReadFile::Profile(format, bytes)) => {
                    match parse::parse(format, &bytes, rel, &opts.limits) {
                        Ok(parsed) => Outcome::Loaded(
                            LoadedProfile {
                                source: rel.clone(),
                                format,
                                profile: Box::new(parsed.profile),
                            },
                            parsed.diagnostics,
                        ),
                        Err(d) => Outcome::Failed(d),
                    }
                }
                Err(e) => Outcome::Failed(Diagnostic::io(rel, &e)),
            };
            progress.advance(1);
            outcome
        })
        .collect()
}

/// Reads the IDL files found below the input and on the IDL path (each file once, in order).
/// An unreadable file is a diagnostic of the set, like a syntax error.
/// Each file knows its tree (the input, a source by the first folder of its name, the IDL path):
/// an include is looked for in the including file's own tree and on the IDL path only.
fn read_idl(found: &[(PathBuf, String)], opts: &LoadOptions) -> Result<crate::idl::IdlSet> {
    use crate::idl::Tree;
    let tree_of = |rel: &str| {
        let first = rel.split('/').next().unwrap_or_default();
        match opts.sources.iter().find(|p| p.source.name == first) {
            Some(p) => Tree::Source(p.source.name.clone()),
            None => Tree::Input,
        }
    };
    let mut all: Vec<(PathBuf, String, Tree)> = found
        .iter()
        .map(|(path, rel)| (path.clone(), rel.clone(), tree_of(rel)))
        .collect();
    let mut search_path: Vec<String> = Vec::new();
    for dir in &opts.idl_path {
        let files = walk::idl_files(dir)
            .with_context(|| format!("--idl-path `{}`: not a directory", dir.display()))?;
        for (path, rel) in files {
            // Named `<folder>/…` (walk::idl_files): the folder is the search path's entry.
            let folder = rel.split('/').next().unwrap_or_default().to_string();
            if !search_path.contains(&folder) {
                search_path.push(folder);
            }
            all.push((path, rel, Tree::SearchPath));
        }
    }
    let read: Vec<std::result::Result<crate::idl::SourceFile, Diagnostic>> = all
        .par_iter()
        .map(|(path, rel, tree)| {
            use std::io::Read;
            let mut bytes = Vec::new();
            std::fs::File::open(path)
                .and_then(|f| {
                    f.take(opts.limits.max_file_size.saturating_add(1))
                        .read_to_end(&mut bytes)
                })
                .map(|_| crate::idl::SourceFile::new(rel.clone(), bytes).in_tree(tree.clone()))
                .map_err(|e| Diagnostic::io(rel, &e))
        })
        .collect();
    let mut sources = Vec::with_capacity(read.len());
    let mut failed = Vec::new();
    for r in read {
        match r {
            Ok(s) => sources.push(s),
            Err(d) => failed.push(d),
        }
    }
    let idl_opts = crate::idl::IdlOptions {
        max_file_size: opts.limits.max_file_size,
        max_depth: opts.limits.max_depth,
        search_path,
        ..Default::default()
    };
    let mut set = crate::idl::read(&sources, &idl_opts);
    set.diagnostics.extend(failed);
    Ok(set)
}

/// What [`NothingToDocument`] says of RTCBuilder's backups found without their `RTC.xml`.
fn backups_part(backups: &[Backup]) -> Option<String> {
    let newest = backups.iter().max_by(|a, b| a.source.cmp(&b.source))?;
    Some(format!(
        "{} RTCBuilder backup(s) without their RTC.xml (to document the newest, copy `{}` to `{}`)",
        backups.len(),
        newest.source,
        newest.profile_path()
    ))
}

/// The message of [`NothingToDocument`]: where (`shown`, as the user named it), what the walk
/// left out by kind (`--verbose` lists those files) and the backups without their profile;
/// `empty` when it left out nothing (`it holds no files`).
pub fn nothing_found(
    shown: &str,
    skipped: &[walk::Skipped],
    backups: Option<&str>,
    empty: &str,
) -> String {
    use walk::SkipKind;
    let count = |k: SkipKind| skipped.iter().filter(|s| s.kind == k).count();
    let mut parts = Vec::new();
    for (kind, what) in [
        (
            SkipKind::NotAProfile,
            ".xml/.yaml file(s) that are not component profiles",
        ),
        (SkipKind::Excluded, "excluded by --exclude"),
        (SkipKind::NotIncluded, "not matched by --include"),
        (SkipKind::OtherFile, "other file(s)"),
        (SkipKind::Symlink, "symbolic link(s)"),
        (SkipKind::Unreadable, "unreadable"),
    ] {
        let n = count(kind);
        if n > 0 {
            parts.push(format!("{n} {what}"));
        }
    }
    parts.extend(backups.map(str::to_string));
    let looked = if parts.is_empty() {
        empty.to_string()
    } else {
        format!("skipped {}; `--verbose` lists them", parts.join(", "))
    };
    format!(
        "nothing to document: no RTC component profile (RTC.xml, or YAML with `rtcProfile`), RT System profile (RtsProfile XML, .rtsys, or YAML with `rtsProfile`) or IDL file in `{shown}` ({looked}). \
         Check the path and the --include/--exclude patterns, or pass --allow-empty to accept an \
         empty input"
    )
}

/// Runs the `rtcdoc check` rules ([`crate::check::run`]) and adds their diagnostics to the
/// catalogue's, keeping them sorted by file and position.
pub fn add_check_diagnostics(catalog: &mut Catalog) {
    let found = crate::check::run(catalog);
    catalog.diagnostics.extend(found);
    crate::diagnostic::sort(&mut catalog.diagnostics);
}

/// Everything `rtcdoc build` needs.
#[derive(Debug, Clone)]
pub struct BuildOptions {
    pub input: PathBuf,
    pub output: PathBuf,
    pub formats: Vec<Format>,
    /// Fail (and write nothing) when any profile has an error.
    pub strict: bool,
    pub load: LoadOptions,
    pub site: SiteOptions,
}

/// What a build did.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct BuildReport {
    pub profiles: usize,
    pub files_found: usize,
    pub files_written: usize,
    pub errors: usize,
    pub warnings: usize,
    pub seconds: f64,
}

/// Refuses outputs that would destroy input: the input itself, a parent of it, or a directory
/// that already holds profiles.
fn check_output_location(input: &Path, output: &Path) -> Result<()> {
    let input_abs = absolute(input)?;
    let input_dir = if input_abs.is_file() {
        input_abs
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or(input_abs.clone())
    } else {
        input_abs.clone()
    };
    let out_abs = absolute(output)?;
    if out_abs == input_dir {
        bail!(
            "the output directory `{}` is the input directory; choose another one (e.g. `-o site`)",
            output.display()
        );
    }
    if input_dir.starts_with(&out_abs) {
        bail!(
            "the output directory `{}` contains the input `{}`; replacing it would delete your profiles",
            output.display(),
            input.display()
        );
    }
    if out_abs.is_dir() {
        let found = walk::walk(&out_abs, &WalkOptions::default())?;
        if let Some(s) = found.sources.first() {
            bail!(
                "the output directory `{}` contains a profile (`{}`); refusing to replace it",
                output.display(),
                s.rel
            );
        }
    }
    Ok(())
}

/// Runs a whole build and returns the loaded catalogue with the report. Nothing is written when
/// a renderer fails or, with `strict`, when any profile has an error.
pub fn build(opts: &BuildOptions) -> Result<(Loaded, BuildReport)> {
    build_with(opts, &Quiet)
}

/// [`build`] with progress reports.
pub fn build_with(opts: &BuildOptions, progress: &dyn Progress) -> Result<(Loaded, BuildReport)> {
    let start = Instant::now();
    // With sources only, `input` is the configuration's folder: it is protected the same way.
    check_output_location(&opts.input, &opts.output)?;
    let mut load_opts = opts.load.clone();
    load_opts.skip_dirs.push(opts.output.clone());
    let mut loaded = load_with(&opts.input, &load_opts, progress)?;
    if let Some(read_history) = load_opts.history_reader.filter(|_| load_opts.history > 0) {
        progress.stage("reading the history", 0);
        read_history(&mut loaded.catalog, &loaded.roots, &load_opts);
        loaded.catalog.history_attached();
    }
    // The `rtcdoc check` rules run on every build; their findings join the catalogue's
    // diagnostics so they appear in the JSON output and the diagnostics page.
    progress.stage("checking", 0);
    add_check_diagnostics(&mut loaded.catalog);
    let (errors, warnings, _) = loaded.catalog.counts();
    if opts.strict && errors > 0 {
        return Err(StrictFailure {
            errors,
            diagnostics: loaded.catalog.diagnostics.clone(),
        }
        .into());
    }
    let mut formats = opts.formats.clone();
    formats.sort();
    formats.dedup();
    if formats.is_empty() {
        formats.push(Format::Html);
    }
    let marker = if formats == [Format::Markdown] {
        crate::output::MARKER_MD
    } else {
        crate::output::MARKER
    };
    let staging = Staging::with_marker(&opts.output, marker)?;
    let ctx = RenderContext {
        catalog: &loaded.catalog,
        site: &opts.site,
    };
    let mut files = 0;
    progress.stage("rendering", formats.len());
    std::thread::scope(|scope| -> Result<()> {
        let writer = WriterThread::start(scope, &staging);
        for f in &formats {
            let renderer = f.renderer();
            let written = if formats.len() == 1 {
                renderer.render(&ctx, &writer)?
            } else {
                let sub = Prefixed {
                    inner: &writer as &dyn Sink,
                    prefix: f.name().to_string(),
                };
                renderer.render(&ctx, &sub)?
            };
            files += written;
            progress.advance(1);
        }
        writer.finish()?;
        Ok(())
    })?;
    progress.stage("swapping in", 0);
    staging.commit()?;
    progress.stage("done", 0);
    let report = BuildReport {
        profiles: loaded.catalog.components.len(),
        files_found: loaded.files,
        files_written: files,
        errors,
        warnings,
        seconds: start.elapsed().as_secs_f64(),
    };
    Ok((loaded, report))
}
