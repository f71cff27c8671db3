//! The `rtcdoc` command line: thin — parse arguments, load the configuration, call the
//! library, report.

use clap::{Args, CommandFactory, Parser, Subcommand};
use codespan_reporting::term::termcolor::{BufferedStandardStream, ColorChoice};
use rtcdoc::build::{self, Progress};
use rtcdoc::config::{self, Overrides};
use rtcdoc::diagnostic::Severity;
use rtcdoc::i18n::Lang;
use rtcdoc::quote::shell_word;
use rtcdoc::render::Format;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// mimalloc: the pipeline allocates many small strings in parallel, where it is markedly faster
/// than the system allocator.
#[cfg(not(any(feature = "alloc-stats", feature = "system-alloc")))]
#[global_allocator]
static GLOBAL: rtcdoc::allocator::Mi = rtcdoc::allocator::Mi;

/// mimalloc with byte counters (memory profiling, feature `alloc-stats`).
#[cfg(feature = "alloc-stats")]
#[global_allocator]
static GLOBAL: rtcdoc::alloc_stats::Counting = rtcdoc::alloc_stats::Counting;

#[derive(Parser)]
#[command(
    name = "rtcdoc",
    version,
    about = "Documentation for OpenRTM RT-Component profiles (RTC.xml / YAML)",
    long_about = "rtcdoc turns a directory of RTC Profiles (RTC.xml as written by RTCBuilder, or the YAML \
                  form) into an HTML site, Markdown, Doxygen input or JSON, with cross-links between \
                  components that share data types and service interfaces, and validates profiles for CI."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Print every file looked at and skipped, and every note.
    #[arg(short, long, global = true)]
    verbose: bool,
    /// Print only errors.
    #[arg(short, long, global = true, conflicts_with = "verbose")]
    quiet: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Render a directory of profiles as an HTML site, Markdown, Doxygen input or JSON; exits 1
    /// with --strict when a profile has an error.
    Build(BuildArgs),
    /// Validate profiles (for CI); exits 1 when a profile has an error.
    Check(CheckArgs),
    /// Compare two versions of a catalogue (directories, profile or IDL files, or REV:PATH of git) and
    /// classify every change as breaking, warning or info — also where a component's code starts
    /// or stops disagreeing with its profile; exits 1 when one reaches --fail-on.
    Diff(DiffArgs),
    /// Build into memory, serve on 127.0.0.1, rebuild on changes and live-reload browsers.
    Serve(ServeArgs),
    /// Write the wiring of an RT System, a component's neighbourhood or the catalogue's data
    /// flow as Graphviz DOT, Mermaid or SVG (to stdout or -o FILE).
    Graph(GraphArgs),
    /// Write an `rtcdoc.toml` with every setting commented out: at its default, or as an example
    /// where it has none.
    Init(InitArgs),
    /// Write the RTC.xml of a component that has code and no profile: read from its C++,
    /// Python or Java source (spec array, ports, service ports, parameters, callbacks).
    Extract(ExtractArgs),
    /// Move the `[[source]]` repositories of rtcdoc.toml (all, or those named) to the current
    /// commit of their `rev` and write rtcdoc.lock.
    Update(UpdateArgs),
    /// Print a shell completion script (bash, zsh, fish, elvish, powershell).
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// Print the man page (roff) on standard output.
    Man,
}

#[derive(Args, Clone, Default)]
struct InputArgs {
    /// Glob of input-relative paths to take (repeatable); default: every file.
    #[arg(long, value_name = "GLOB")]
    include: Vec<String>,
    /// Glob of input-relative paths to leave out (repeatable); a directory it matches is left
    /// out whole, e.g. `--exclude examples/Templates` or `--exclude '**/backup'`.
    #[arg(long, value_name = "GLOB")]
    exclude: Vec<String>,
    /// Largest profile file accepted, in bytes [default: 16 MiB].
    #[arg(long, value_name = "BYTES")]
    max_file_size: Option<u64>,
    /// Deepest element / collection nesting accepted [default: 64].
    #[arg(long, value_name = "N")]
    max_depth: Option<usize>,
    /// Configuration file [default: rtcdoc.toml in the input directory or the current directory].
    #[arg(long, value_name = "FILE")]
    config: Option<PathBuf>,
    /// Accept an input that holds nothing to document: no component profile, RT System
    /// profile or IDL file (otherwise an error, exit 2).
    #[arg(long)]
    allow_empty: bool,
    /// Directory of IDL files to read as well, searched recursively (repeatable), e.g. an
    /// OpenRTM installation's `rtm/idl`; every `*.idl` below the input is read anyway.
    #[arg(long, value_name = "DIR")]
    idl_path: Vec<PathBuf>,
}

/// How the `[[source]]` repositories of rtcdoc.toml are fetched: shared by `build`, `check`,
/// `diff`, `serve` and `update`.
#[derive(Args, Clone, Default)]
struct SourceArgs {
    /// Where the repositories are cached [default: rtcdoc/ in the user's cache directory,
    /// e.g. ~/.cache/rtcdoc].
    #[arg(long, value_name = "DIR")]
    cache_dir: Option<PathBuf>,
    /// Fail (exit 2) when rtcdoc.lock is missing or would have to change (a source added,
    /// removed or edited).
    #[arg(long)]
    locked: bool,
    /// Never fetch: use the cached repositories only.
    #[arg(long)]
    offline: bool,
    /// Fetch and read N [[source]] repositories at once [default: the number of cores].
    #[arg(short, long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    jobs: Option<u64>,
}

impl SourceArgs {
    fn mode(&self) -> rtcdoc::sources::Mode {
        rtcdoc::sources::Mode {
            cache_dir: self.cache_dir.clone(),
            locked: self.locked,
            offline: self.offline,
            // Filled by `config::pin_sources`, which knows the file read.
            config: None,
            jobs: self.jobs.and_then(|j| usize::try_from(j).ok()),
        }
    }
}

#[derive(Args)]
struct ExtractArgs {
    /// The component's folder (or the source file holding its spec array); every component
    /// implemented below a folder gets its profile.
    #[arg(default_value = ".")]
    path: PathBuf,
    /// Print the profile on standard output instead of writing it (one component only).
    #[arg(long, conflicts_with = "output")]
    stdout: bool,
    /// Write the profile to FILE instead of RTC.xml in the component folder (one component
    /// only).
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Overwrite profiles that exist already (their documentation is lost: the code has none).
    #[arg(long)]
    force: bool,
    /// Skip source files larger than this (bytes; default 16 MiB).
    #[arg(long, value_name = "BYTES")]
    max_file_size: Option<u64>,
}

#[derive(Args)]
struct UpdateArgs {
    /// The sources to move, by name [default: all].
    names: Vec<String>,
    /// Configuration file [default: rtcdoc.toml in the current directory].
    #[arg(long, value_name = "FILE")]
    config: Option<PathBuf>,
    /// Where the repositories are cached [default: rtcdoc/ in the user's cache directory].
    #[arg(long, value_name = "DIR")]
    cache_dir: Option<PathBuf>,
    /// Fetch N [[source]] repositories at once [default: the number of cores].
    #[arg(short, long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    jobs: Option<u64>,
}

/// What is read and how: the input's filters and limits, and how the `[[source]]` repositories
/// are fetched. Shared by `build`, `check`, `diff` and `serve`.
#[derive(Args, Clone, Default)]
struct ReadArgs {
    #[command(flatten)]
    input: InputArgs,
    #[command(flatten)]
    sources: SourceArgs,
}

/// What the pages look like: shared by `build` and `serve`.
#[derive(Args, Clone, Default)]
struct SiteArgs {
    /// Title of the catalogue.
    #[arg(long)]
    title: Option<String>,
    /// URL the site is published at (sitemap.xml and the history's Atom feed feed.xml are
    /// written only with it).
    #[arg(long, value_name = "URL")]
    base_url: Option<String>,
    /// Theme directory overriding built-in templates and assets file by file.
    #[arg(long, value_name = "DIR")]
    theme: Option<PathBuf>,
    /// Language of generated labels (profile text is shown as written; the messages of
    /// findings and changes stay English, each with its code).
    #[arg(long, value_enum)]
    language: Option<Lang>,
}

#[derive(Args)]
struct BuildArgs {
    /// Directory (or single file) of profiles [default: the config's `input`, else the config
    /// file's folder, else `.`].
    input: Option<PathBuf>,
    /// Output directory, replaced on success [default: the config's `output`, else `site`;
    /// relative to the config file's folder when there is a config file].
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Output format(s); several at once go to OUT/<format>/ [default: html].
    #[arg(short, long, value_enum, value_delimiter = ',')]
    format: Vec<Format>,
    /// Fail (exit 1) without writing anything when any profile has an error.
    #[arg(long, overrides_with = "no_strict")]
    strict: bool,
    /// Write the output even when a profile has an error (turns off `strict = true` of the
    /// config file).
    #[arg(long, overrides_with = "strict")]
    no_strict: bool,
    /// Commits read per file (component profile, RT System profile, IDL file) for its history
    /// (from git, and RTCBuilder's backups); 0 turns the history off [default: 100].
    #[arg(long, value_name = "N")]
    history: Option<usize>,
    #[command(flatten)]
    site: SiteArgs,
    #[command(flatten)]
    read: ReadArgs,
}

#[derive(Args)]
struct CheckArgs {
    /// Directories or files to check [default: the config's `input`, else the config file's
    /// folder, else `.`].
    paths: Vec<PathBuf>,
    /// Output format: human (rustc-like, on stderr), json or sarif (on stdout).
    #[arg(short, long, value_enum, default_value = "human")]
    format: CheckFormat,
    /// Treat a class of findings as errors for the exit status (`--deny warnings`).
    #[arg(long, value_enum, value_name = "WHAT")]
    deny: Vec<Deny>,
    /// Print the rationale and spec section of a rule, by code or name (`--explain RTC303`,
    /// `--explain duplicate-parameter`), and exit.
    #[arg(long, value_name = "CODE")]
    explain: Option<String>,
    #[command(flatten)]
    read: ReadArgs,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum CheckFormat {
    Human,
    Json,
    Sarif,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Deny {
    /// Warnings make the check fail (exit 1).
    Warnings,
}

#[derive(Args)]
struct DiffArgs {
    /// The old side: a directory, a profile file, an IDL file (`.idl`), a catalog.json written by
    /// `rtcdoc build --format json`, or REV:PATH (a git revision and a path in the current
    /// repository, e.g. `origin/main:components` or `HEAD~1:idl/Lab.idl`).
    #[arg(required_unless_present_any = ["explain", "since"])]
    old: Option<String>,
    /// The new side, like OLD (with --since, the one path given is NEW).
    #[arg(required_unless_present_any = ["explain", "since"])]
    new: Option<String>,
    /// Compare with the git revision REV (a tag, branch or commit, e.g. `v1.0.0`): OLD is
    /// `REV:` with NEW's path, and NEW is the one path given [default: the config's `input`,
    /// else the config file's folder, else `.`].
    #[arg(long, value_name = "REV")]
    since: Option<String>,
    /// Accept the changes the baseline FILE names (each entry with its reason; see
    /// --write-baseline): they are listed as accepted and do not fail; its entries whose change
    /// is gone are reported as stale.
    #[arg(long, value_name = "FILE")]
    baseline: Option<PathBuf>,
    /// Write every change that reaches --fail-on (breaking with `never`) to FILE as a baseline,
    /// keeping the reasons FILE (or --baseline) already gives, and accept them; each new entry's
    /// reason is a "TODO:" to replace before --baseline takes the file.
    #[arg(long, value_name = "FILE")]
    write_baseline: Option<PathBuf>,
    /// Output format: human (coloured), json, markdown (a pull-request comment) or github
    /// (workflow annotations); all on stdout.
    #[arg(short, long, value_enum, default_value = "human")]
    format: rtcdoc::diff::report::OutputFormat,
    /// The least severe change that makes the exit status 1.
    #[arg(long, value_enum, value_name = "LEVEL", default_value = "breaking")]
    fail_on: rtcdoc::diff::report::FailOn,
    /// Print the classification and reasoning of a change, by code or name (`--explain DIFF104`,
    /// `--explain data-port-type-changed`), and exit.
    #[arg(long, value_name = "CODE")]
    explain: Option<String>,
    #[command(flatten)]
    read: ReadArgs,
}

/// `serve` renders HTML into memory: it takes no output directory, format or `--strict`.
#[derive(Args)]
struct ServeArgs {
    /// Directory of profiles [default: the config's `input`, else the config file's folder,
    /// else `.`].
    input: Option<PathBuf>,
    #[command(flatten)]
    site: SiteArgs,
    #[command(flatten)]
    read: ReadArgs,
    /// Port on 127.0.0.1 [default: 3000; 0 picks a free one].
    #[arg(short, long)]
    port: Option<u16>,
    /// Open the site in the default browser.
    #[arg(long, overrides_with = "no_open")]
    open: bool,
    /// Don't open a browser (turns off `open = true` of the config file's `[serve]`).
    #[arg(long, overrides_with = "open")]
    no_open: bool,
}

#[derive(Args)]
struct GraphArgs {
    /// Directory or file holding the system profile (and the component profiles its instances
    /// use) [default: the config's `input`, else the config file's folder, else `.`].
    input: Option<PathBuf>,
    /// The system to draw, by name (also as the pages show it, `RTSystem (ev3)`), page slug or
    /// file path (relative to the input, or to the current directory); needed when the input
    /// holds several.
    #[arg(long, value_name = "NAME", conflicts_with_all = ["dataflow", "component"])]
    system: Option<String>,
    /// Instead of a system: the neighbourhood of one component, by name, id or page slug (the
    /// components that can feed each of its ports and those it can feed, one hop, at most 5
    /// per port and the rest counted in a "+N more" box).
    #[arg(long, value_name = "NAME|ID", conflicts_with = "dataflow")]
    component: Option<String>,
    /// Instead of a system: the catalogue's data flow between its categories or vendors (which
    /// groups can feed which, each flow with its port pairs), every group and flow.
    #[arg(long, value_enum, value_name = "GROUPING")]
    dataflow: Option<DataflowGrouping>,
    /// Output format: dot (Graphviz), mermaid (`flowchart LR`) or svg (the site's drawing).
    #[arg(short, long, value_enum, default_value = "dot")]
    format: GraphFormat,
    /// Write to FILE instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    #[command(flatten)]
    input_args: InputArgs,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum DataflowGrouping {
    Category,
    Vendor,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum GraphFormat {
    Dot,
    Mermaid,
    Svg,
}

#[derive(Args)]
struct InitArgs {
    /// Directory to write `rtcdoc.toml` into.
    #[arg(default_value = ".")]
    dir: PathBuf,
    /// Overwrite an existing `rtcdoc.toml`.
    #[arg(long)]
    force: bool,
    /// Language of the file's comments; `ja` also sets `language = "ja"` (generated labels in
    /// Japanese) [default: en].
    #[arg(long, value_enum)]
    language: Option<Lang>,
}

/// mimalloc v3 keeps freed pages for a second (`purge_delay` 1000 ms) before it gives them
/// back to the system. A build frees the reading stage's transient parse trees within
/// milliseconds, and the rendering stage then takes fresh pages: at a tenth of a second the
/// peak RSS of a 10,000-profile build is 4-12 MB lower on a quiet machine, with the same system
/// time (shorter delays purge too often; book/src/performance.md). `MIMALLOC_PURGE_DELAY` in the
/// environment still decides when it is set.
#[cfg(not(feature = "system-alloc"))]
fn tune_allocator() {
    /// `mi_option_purge_delay` in mimalloc.h (the same in its v2 and v3).
    const PURGE_DELAY: libmimalloc_sys::mi_option_t = 15;
    // SAFETY: two integers; called first in `main`, before any other thread exists (mimalloc's
    // option setters are not thread-safe).
    unsafe { libmimalloc_sys::mi_option_set_default(PURGE_DELAY, 100) };
}

#[cfg(feature = "system-alloc")]
fn tune_allocator() {}

fn main() -> ExitCode {
    tune_allocator();
    let cli = Cli::parse();
    match run(&cli) {
        Ok(code) => code,
        Err(e) => {
            // `--verbose` lists what the walk skipped, as the message says it does.
            if let Some(n) = e
                .downcast_ref::<build::NothingToDocument>()
                .filter(|_| cli.verbose)
            {
                print_skipped(&n.skipped, &input_root(&n.input), &Default::default());
            }
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// A progress bar on standard error, drawn only when it is a terminal. With the environment
/// variable `RTCDOC_TIMING` set, the time of every stage and the peak RSS so far are printed as
/// well (for profiling).
struct Bar(indicatif::ProgressBar, Option<std::sync::Mutex<StageClock>>);

/// The stage being timed (`RTCDOC_TIMING`): its name, when it started, and the process's CPU
/// time then.
struct StageClock(String, std::time::Instant, Option<u64>);

impl Bar {
    fn new(enabled: bool) -> Bar {
        if enabled && std::io::stderr().is_terminal() {
            let b = indicatif::ProgressBar::new(0);
            b.set_style(
                indicatif::ProgressStyle::with_template(
                    "{spinner} {msg:20} [{bar:30}] {pos}/{len}",
                )
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
                .progress_chars("=> "),
            );
            Bar(b, timing())
        } else {
            Bar(indicatif::ProgressBar::hidden(), timing())
        }
    }
}

/// The process's peak resident set size (`VmHWM` of `/proc/self/status`, Linux only).
fn peak_rss() -> Option<String> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let kb: u64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))?
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(format!("{} MB", kb / 1024))
}

/// The CPU time (user and system, all threads) the process has used so far, in milliseconds
/// (`/proc/self/stat`, Linux only; the kernel counts it in ticks of 10 ms).
fn cpu_ms() -> Option<u64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The fields after the command name (which may hold spaces), from field 3 (`state`) on.
    let rest = &stat[stat.rfind(')')? + 2..];
    let mut f = rest.split(' ').skip(11);
    let utime: u64 = f.next()?.parse().ok()?;
    let stime: u64 = f.next()?.parse().ok()?;
    Some((utime + stime) * 10)
}

/// The live heap and the stage's peak heap (feature `alloc-stats`); nothing otherwise.
#[cfg(feature = "alloc-stats")]
fn heap_stats() -> String {
    use rtcdoc::alloc_stats;
    let mb = |b: usize| b as f64 / (1024.0 * 1024.0);
    let s = format!(
        "  heap: {:.1} MB live, stage peak {:.1} MB",
        mb(alloc_stats::live()),
        mb(alloc_stats::peak())
    );
    alloc_stats::reset_peak();
    s
}

#[cfg(not(feature = "alloc-stats"))]
fn heap_stats() -> &'static str {
    ""
}

fn timing() -> Option<std::sync::Mutex<StageClock>> {
    std::env::var_os("RTCDOC_TIMING").map(|_| {
        std::sync::Mutex::new(StageClock(
            String::new(),
            std::time::Instant::now(),
            cpu_ms(),
        ))
    })
}

impl Progress for Bar {
    fn stage(&self, name: &str, total: usize) {
        if let Some(t) = &self.1 {
            let mut t = t.lock().unwrap_or_else(|e| e.into_inner());
            let cpu = cpu_ms();
            if !t.0.is_empty() {
                let wall = t.1.elapsed().as_secs_f64() * 1000.0;
                let used = match (t.2, cpu) {
                    (Some(a), Some(b)) => format!("  cpu {:>5} ms", b.saturating_sub(a)),
                    _ => String::new(),
                };
                eprintln!(
                    "timing: {:<20} {:>8.1} ms{used}  (peak RSS so far: {}){}",
                    t.0,
                    wall,
                    peak_rss().unwrap_or_else(|| "?".into()),
                    heap_stats()
                );
            }
            *t = StageClock(name.to_string(), std::time::Instant::now(), cpu);
        }
        self.0.set_message(name.to_string());
        self.0.set_length(total as u64);
        self.0.set_position(0);
    }
    fn advance(&self, n: usize) {
        self.0.inc(n as u64);
    }
}

/// The names of the `[[source]]` repositories read: their files are shown as the catalogue has
/// them (`<name>/<path>`), not below the input directory.
static SOURCE_NAMES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();

/// Pins the `[[source]]` repositories of the configuration into `load` (fetching as needed,
/// writing rtcdoc.lock when it changed, which is reported unless `quiet`).
fn pin(
    file: &config::Loaded,
    s: &SourceArgs,
    load: &mut build::LoadOptions,
    quiet: bool,
) -> anyhow::Result<()> {
    let (pinned, changes) = pin_with_bar(file, &s.mode(), None, quiet)?;
    load.jobs = s.mode().jobs.or(file.config.jobs);
    if !changes.is_empty() && !quiet {
        eprintln!("rtcdoc.lock: {}", changes.describe());
    }
    let _ = SOURCE_NAMES.set(pinned.iter().map(|p| p.source.name.clone()).collect());
    load.sources = pinned;
    Ok(())
}

/// [`config::pin_sources`] with a progress line "fetching sources k/N" on a terminal (none
/// when `quiet`).
fn pin_with_bar(
    file: &config::Loaded,
    mode: &rtcdoc::sources::Mode,
    update: Option<&[String]>,
    quiet: bool,
) -> anyhow::Result<(Vec<rtcdoc::sources::Pinned>, rtcdoc::sources::lock::Changes)> {
    let bar = Bar::new(!quiet);
    let pinned = config::pin_sources(file, mode, update, &bar);
    bar.0.finish_and_clear();
    pinned
}

/// [`load_config`] for a command: with `--verbose`, the file used is named.
fn config_for(cli: &Cli, input: Option<&Path>, i: &InputArgs) -> anyhow::Result<config::Loaded> {
    let file = load_config(input, i.config.as_deref())?;
    if let (true, Some(p)) = (cli.verbose, &file.path) {
        eprintln!("configuration: {}", p.display());
    }
    Ok(file)
}

fn load_config(input: Option<&Path>, explicit: Option<&Path>) -> anyhow::Result<config::Loaded> {
    let cwd = PathBuf::from(".");
    let mut search: Vec<&Path> = Vec::new();
    if let Some(i) = input {
        search.push(i);
    }
    search.push(&cwd);
    config::load(explicit, &search)
}

fn overrides(
    input: &Option<PathBuf>,
    site: &SiteArgs,
    i: &InputArgs,
    build: Option<&BuildArgs>,
) -> Overrides {
    // A list flag not given sets nothing (the file's list applies).
    fn given<T: Clone>(list: &[T]) -> Option<Vec<T>> {
        (!list.is_empty()).then(|| list.to_vec())
    }
    Overrides {
        settings: config::Config {
            input: input.clone(),
            output: build.and_then(|b| b.output.clone()),
            formats: build.and_then(|b| given(&b.format)),
            strict: build.and_then(|b| match (b.strict, b.no_strict) {
                (true, _) => Some(true),
                (_, true) => Some(false),
                _ => None,
            }),
            title: site.title.clone(),
            base_url: site.base_url.clone(),
            theme: site.theme.clone(),
            language: site.language,
            include: given(&i.include),
            exclude: given(&i.exclude),
            max_file_size: i.max_file_size,
            max_depth: i.max_depth,
            idl_path: given(&i.idl_path),
            history: build.and_then(|b| b.history),
            ..Default::default()
        },
        allow_empty: i.allow_empty,
    }
}

/// The load options of `check` and `diff`: the configuration file, then the input flags (no
/// output directory to skip).
fn load_options(file: &config::Loaded, i: &InputArgs) -> build::LoadOptions {
    let mut opts =
        config::build_options(file, &overrides(&None, &SiteArgs::default(), i, None)).load;
    opts.skip_dirs.clear();
    opts.history = 0;
    opts
}

fn build_overrides(args: &BuildArgs) -> Overrides {
    overrides(&args.input, &args.site, &args.read.input, Some(args))
}

/// How many errors and warnings `build` and `serve` print before pointing at `rtcdoc check`.
const PRINT_CAP: usize = 50;

/// Notes on history rtcdoc could not read whole (a shallow clone, a repository git refuses,
/// logs git could not give), each with what to do.
fn print_history_notes(notes: &[String]) {
    for note in notes {
        eprintln!("warning: history: {note}");
    }
}

/// Prints what the rules found, like cargo: errors, then warnings (unless `quiet`), then infos
/// (only with `verbose`), each as `file:line:col: severity[CODE]: message` with files named as
/// the user can open them. Without `verbose` at most [`PRINT_CAP`] are printed; the rest are
/// counted, with the command that lists them all.
fn print_findings(
    diags: &[rtcdoc::diagnostic::Diagnostic],
    root: &Path,
    verbose: bool,
    quiet: bool,
    check_cmd: &str,
) {
    let mut shown: Vec<&rtcdoc::diagnostic::Diagnostic> = Vec::new();
    for sev in [Severity::Error, Severity::Warning, Severity::Info] {
        let wanted = match sev {
            Severity::Error => true,
            Severity::Warning => !quiet,
            Severity::Info => verbose,
        };
        if wanted {
            shown.extend(diags.iter().filter(|d| d.severity == sev));
        }
    }
    let cap = if verbose { usize::MAX } else { PRINT_CAP };
    for d in shown.iter().take(cap) {
        eprintln!("{}", d.cli_text(&display_path(root, &d.file)));
    }
    if shown.len() > cap {
        eprintln!(
            "… {} more: run `{check_cmd}` to see them all",
            shown.len() - cap
        );
    }
}

/// `rtcdoc check` with the input and source options a build used, so that it reports the same
/// findings (and reads the `[[source]]` repositories from the same cache, without fetching when
/// the build did not).
fn check_command(input: &Path, read: &ReadArgs) -> String {
    let i = &read.input;
    let mut cmd = format!("rtcdoc check {}", shell_word(&input.to_string_lossy()));
    if let Some(c) = &i.config {
        cmd.push_str(&format!(" --config {}", shell_word(&c.to_string_lossy())));
    }
    for (flag, values) in [("--include", &i.include), ("--exclude", &i.exclude)] {
        for v in values {
            cmd.push_str(&format!(" {flag} {}", shell_word(v)));
        }
    }
    if let Some(n) = i.max_file_size {
        cmd.push_str(&format!(" --max-file-size {n}"));
    }
    if let Some(n) = i.max_depth {
        cmd.push_str(&format!(" --max-depth {n}"));
    }
    if i.allow_empty {
        cmd.push_str(" --allow-empty");
    }
    for d in &i.idl_path {
        cmd.push_str(&format!(" --idl-path {}", shell_word(&d.to_string_lossy())));
    }
    let s = &read.sources;
    if let Some(d) = &s.cache_dir {
        cmd.push_str(&format!(
            " --cache-dir {}",
            shell_word(&d.to_string_lossy())
        ));
    }
    for (flag, on) in [("--locked", s.locked), ("--offline", s.offline)] {
        if on {
            cmd.push(' ');
            cmd.push_str(flag);
        }
    }
    cmd
}

/// `rtcdoc check` of a configuration with sources only (no input directory).
fn check_command_sources(file: &config::Loaded, read: &ReadArgs) -> String {
    let mut cmd = check_command(Path::new("."), read);
    if read.input.config.is_none() {
        if let Some(p) = &file.path {
            cmd = format!("{} --config {}", cmd, shell_word(&p.to_string_lossy()));
        }
    }
    cmd.replacen("rtcdoc check . ", "rtcdoc check ", 1)
        .replacen("rtcdoc check .", "rtcdoc check", 1)
}

/// The READMEs of the components and the images they show (paths relative to the input).
fn shown_files(cat: &rtcdoc::catalog::Catalog) -> std::collections::HashSet<&str> {
    cat.components
        .iter()
        .filter_map(|c| c.readme.as_ref())
        .flat_map(|r| {
            std::iter::once(r.file.as_str()).chain(r.images.iter().map(|i| i.path.as_str()))
        })
        .collect()
}

/// `--verbose`: every file that could have been a profile and was not taken, with the reason;
/// the other files (sources, images, …) as one count by extension. The READMEs and images the
/// component pages show (`shown`) are not skipped.
fn print_skipped(
    skipped: &[rtcdoc::walk::Skipped],
    root: &Path,
    shown: &std::collections::HashSet<&str>,
) {
    use rtcdoc::walk::SkipKind;
    let mut others: std::collections::BTreeMap<String, usize> = Default::default();
    for s in skipped {
        if shown.contains(s.rel.as_str()) {
            continue;
        }
        if s.kind == SkipKind::OtherFile {
            let ext = Path::new(&s.rel)
                .extension()
                .map(|e| format!(".{}", e.to_string_lossy().to_ascii_lowercase()))
                .unwrap_or_else(|| "no extension".into());
            *others.entry(ext).or_default() += 1;
        } else {
            eprintln!("skipped {}: {}", display_path(root, &s.rel), s.reason);
        }
    }
    if !others.is_empty() {
        let total: usize = others.values().sum();
        let mut by: Vec<(String, usize)> = others.into_iter().collect();
        by.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        // The most frequent kinds; a long tail of one-off names says nothing.
        const KINDS: usize = 12;
        let mut list: Vec<String> = by
            .iter()
            .take(KINDS)
            .map(|(e, n)| format!("{n} {e}"))
            .collect();
        if by.len() > KINDS {
            let rest: usize = by[KINDS..].iter().map(|(_, n)| n).sum();
            list.push(format!("{rest} of {} other kinds", by.len() - KINDS));
        }
        eprintln!(
            "skipped {total} other file(s), not .xml/.yaml/.yml/.rtsys: {}",
            list.join(", ")
        );
    }
}

fn run(cli: &Cli) -> anyhow::Result<ExitCode> {
    match &cli.command {
        Command::Build(args) => build_command(cli, args),
        Command::Check(args) => check(cli, args),
        Command::Diff(args) => diff(cli, args),
        Command::Serve(args) => serve_command(cli, args),
        Command::Init(args) => init_command(cli, args),
        Command::Completions { shell } => {
            clap_complete::generate(
                *shell,
                &mut Cli::command(),
                "rtcdoc",
                &mut std::io::stdout(),
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Man => {
            man_page(&mut std::io::stdout().lock())?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Graph(args) => graph(cli, args),
        Command::Extract(args) => extract(cli, args),
        Command::Update(args) => update_command(cli, args),
    }
}

/// `rtcdoc build`: the catalogue read, checked and rendered, then the findings and a summary.
fn build_command(cli: &Cli, args: &BuildArgs) -> anyhow::Result<ExitCode> {
    let file = config_for(cli, args.input.as_deref(), &args.read.input)?;
    let mut opts = config::build_options(&file, &build_overrides(args));
    pin(&file, &args.read.sources, &mut opts.load, cli.quiet)?;
    let root = input_root(&opts.input);
    let check_cmd = if opts.load.sources_only {
        check_command_sources(&file, &args.read)
    } else {
        check_command(&opts.input, &args.read)
    };
    let bar = Bar::new(!cli.quiet);
    let result = build::build_with(&opts, &bar);
    bar.0.finish_and_clear();
    let (loaded, report) = match result {
        Ok(r) => r,
        Err(e) => {
            if let Some(f) = e.downcast_ref::<build::StrictFailure>() {
                print_findings(&f.diagnostics, &root, cli.verbose, cli.quiet, &check_cmd);
                eprintln!("error: {e}");
                return Ok(ExitCode::from(1));
            }
            return Err(e);
        }
    };
    if cli.verbose {
        print_skipped(&loaded.skipped, &root, &shown_files(&loaded.catalog));
    }
    print_findings(
        &loaded.catalog.diagnostics,
        &root,
        cli.verbose,
        cli.quiet,
        &check_cmd,
    );
    if !cli.quiet {
        print_history_notes(&loaded.catalog.history_notes);
        let html = opts.formats.is_empty() || opts.formats.contains(&Format::Html);
        if html && opts.site.base_url.is_none() {
            eprintln!("note: no sitemap.xml: it needs absolute URLs; pass --base-url URL (or set base-url in rtcdoc.toml)");
        }
        if let Some(note) = loaded.catalog.backup_note() {
            eprintln!("note: {note}");
        }
        if let Some(note) =
            rtcdoc::check::undefined_types_note(&loaded.catalog, file.path.as_deref())
        {
            eprintln!("note: {note}");
        }
        if let Some(note) = rtcdoc::check::idl_on_no_page_note(&loaded.idl_on_no_page) {
            eprintln!("note: {note}");
        }
        eprintln!(
            "{} (details: {check_cmd})",
            rtcdoc::check::Summary::of(&loaded.catalog.diagnostics).one_line(),
        );
        eprintln!(
            "built {} into {}: {} file(s), {} error(s), {} warning(s) in {:.2}s",
            loaded.catalog.documented(),
            opts.output.display(),
            report.files_written,
            report.errors,
            report.warnings,
            report.seconds
        );
    }
    // The process ends next: freeing a large catalogue one allocation at a time only
    // delays the exit (about 40 ms for 10,000 profiles); the OS takes the memory back.
    std::mem::forget(loaded);
    Ok(ExitCode::SUCCESS)
}

/// `rtcdoc serve`: the site served with live reload until Ctrl-C.
fn serve_command(cli: &Cli, args: &ServeArgs) -> anyhow::Result<ExitCode> {
    let file = config_for(cli, args.input.as_deref(), &args.read.input)?;
    let cli_over = overrides(&args.input, &args.site, &args.read.input, None);
    let mut build = config::build_options(&file, &cli_over);
    build.formats = vec![Format::Html];
    pin(&file, &args.read.sources, &mut build.load, cli.quiet)?;
    let serve_cfg = file.config.serve.clone().unwrap_or_default();
    let mut watch = Vec::new();
    if let Some(t) = &build.site.theme_dir {
        watch.push(t.clone());
    }
    if let Some(p) = &file.path {
        watch.push(p.clone());
    }
    let quiet = cli.quiet;
    let root = input_root(&build.input);
    let check_cmd = check_command(&build.input, &args.read);
    let (input, explicit) = (args.input.clone(), args.read.input.config.clone());
    let source_args = args.read.sources.clone();
    let reconfigure: rtcdoc::serve::Reconfigure = std::sync::Arc::new(move || {
        let file = load_config(input.as_deref(), explicit.as_deref())?;
        let mut b = config::build_options(&file, &cli_over);
        b.formats = vec![Format::Html];
        pin(&file, &source_args, &mut b.load, quiet)?;
        Ok(b)
    });
    let handle = rtcdoc::serve::start(
        rtcdoc::serve::ServeOptions {
            build,
            port: args.port.or(serve_cfg.port).unwrap_or(3000),
            watch,
            reconfigure: Some(reconfigure),
            file_name: Some({
                let root = root.clone();
                std::sync::Arc::new(move |f: &str| display_path(&root, f))
            }),
        },
        std::sync::Arc::new(move |line: &str| {
            if !quiet || line.starts_with("error") {
                eprintln!("{line}");
            }
        }),
    )?;
    print_findings(
        handle.first_diagnostics(),
        &root,
        cli.verbose,
        cli.quiet,
        &check_cmd,
    );
    if !cli.quiet {
        print_history_notes(handle.first_history_notes());
    }
    eprintln!("serving at {} (Ctrl-C to stop)", handle.url());
    if args.open || (!args.no_open && serve_cfg.open.unwrap_or(false)) {
        rtcdoc::serve::open_browser(&handle.url());
    }
    handle.wait();
    Ok(ExitCode::SUCCESS)
}

/// `rtcdoc init`: a commented rtcdoc.toml, with an OpenRTM installation's IDL when one is found.
fn init_command(cli: &Cli, args: &InitArgs) -> anyhow::Result<ExitCode> {
    let path = args.dir.join(config::FILE_NAME);
    if path.exists() && !args.force {
        anyhow::bail!(
            "`{}` already exists (use --force to overwrite it)",
            path.display()
        );
    }
    std::fs::create_dir_all(&args.dir)?;
    // An OpenRTM installation's IDL, suggested (commented out) in the file.
    let idl = rtcdoc::init::detect(&|k| std::env::var_os(k));
    let lang = args.language.unwrap_or_default();
    std::fs::write(&path, config::template_in(lang, idl.as_ref()))?;
    if !cli.quiet {
        eprintln!("wrote {}", path.display());
        match &idl {
            Some(found) => eprintln!(
                "found OpenRTM's IDL in {} ({}); uncomment `idl-path` in {} to use it",
                found.dir.display(),
                found.via,
                config::FILE_NAME
            ),
            // Said, so that the hint that sent the user here ends somewhere.
            None => eprintln!(
                "found no OpenRTM installation's IDL (looked at $RTM_ROOT, $OPENRTM_DIR and the usual install prefixes, or those in ${}); if you have one elsewhere, set `idl-path` in {} to its rtm/idl directory",
                rtcdoc::init::PREFIXES_VAR,
                config::FILE_NAME
            ),
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `rtcdoc update`: the `[[source]]` repositories moved to their branches' newest commits in rtcdoc.lock.
fn update_command(cli: &Cli, args: &UpdateArgs) -> anyhow::Result<ExitCode> {
    let file = load_config(None, args.config.as_deref())?;
    let mode = rtcdoc::sources::Mode {
        cache_dir: args.cache_dir.clone(),
        jobs: args.jobs.and_then(|j| usize::try_from(j).ok()),
        ..Default::default()
    };
    let (pinned, changes) = pin_with_bar(&file, &mode, Some(&args.names), cli.quiet)?;
    if !cli.quiet {
        if changes.is_empty() {
            eprintln!("rtcdoc.lock is up to date ({} source(s))", pinned.len());
        } else {
            eprintln!("rtcdoc.lock: {}", changes.describe());
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// The man page: name, synopsis, description and global options, then every command with its
/// synopsis, description and options (one page, as `rtcdoc man` promises; no `rtcdoc-build(1)`
/// pages exist to point at), and the exit status.
fn man_page(out: &mut dyn std::io::Write) -> std::io::Result<()> {
    use clap_mangen::Man;
    let cmd = Cli::command();
    let man = Man::new(cmd.clone());
    man.render_title(out)?;
    man.render_name_section(out)?;
    man.render_synopsis_section(out)?;
    man.render_description_section(out)?;
    man.render_options_section(out)?;
    writeln!(out, ".SH COMMANDS")?;
    for sub in cmd.get_subcommands().filter(|s| s.get_name() != "help") {
        let name = format!("rtcdoc {}", sub.get_name());
        let sub_man = Man::new(sub.clone().bin_name(name.clone()));
        let mut buf = Vec::new();
        sub_man.render_synopsis_section(&mut buf)?;
        sub_man.render_description_section(&mut buf)?;
        sub_man.render_options_section(&mut buf)?;
        // The command's sections become paragraphs of one subsection.
        let text = String::from_utf8_lossy(&buf)
            .replace(".SH SYNOPSIS\n", &format!(".SS \"{name}\"\n"))
            .replace(".SH DESCRIPTION\n", ".PP\n")
            .replace(".SH OPTIONS\n", ".PP\nOptions:\n");
        out.write_all(text.as_bytes())?;
    }
    writeln!(out, ".SH \"EXIT STATUS\"")?;
    for (code, meaning) in [
        ("0", "success"),
        (
            "1",
            "a profile has an error (check, build --strict), or a change reached --fail-on (diff)",
        ),
        (
            "2",
            "the command could not run: bad usage, an unreadable input or configuration",
        ),
    ] {
        writeln!(out, ".TP\n{code}\n{meaning}")?;
    }
    man.render_version_section(out)
}

/// The RT System `graph` draws: the one `--system` names (its name, name as the pages show
/// it, slug or file), or the only one; else an error that lists them, or says what `graph`
/// draws without one.
fn choose_system<'a>(
    catalog: &'a rtcdoc::catalog::Catalog,
    args: &GraphArgs,
    input: &Path,
) -> anyhow::Result<&'a rtcdoc::catalog::systems::System> {
    let systems = &catalog.systems;
    // A file path as the shell completes it (from the current directory, not the input).
    let want_file = args
        .system
        .as_deref()
        .and_then(|w| std::fs::canonicalize(w).ok());
    let chosen: Vec<&rtcdoc::catalog::systems::System> = match &args.system {
        Some(want) => systems
            .iter()
            .filter(|s| {
                s.profile.name() == want
                    || s.display_name() == want.as_str()
                    || &s.slug == want
                    || &s.source == want
                    || want_file.is_some()
                        && std::fs::canonicalize(input.join(&s.source)).ok() == want_file
            })
            .collect(),
        None => systems.iter().collect(),
    };
    let listed = |list: &[&rtcdoc::catalog::systems::System]| {
        list.iter()
            .map(|s| format!("{} — {}", s.display_name(), s.source))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let names = || listed(&systems.iter().collect::<Vec<_>>());
    Ok(match chosen.as_slice() {
        [one] => *one,
        [] if systems.is_empty() => {
            // What graph can draw from components alone, with a name that works.
            let example = catalog
                .components
                .first()
                .map(|c| shell_word(&c.display_name()))
                .unwrap_or_else(|| "NAME".into());
            anyhow::bail!(
                "no RT System profile in {}; graph draws a component's neighbourhood (--component={example}) or the data flow between categories (--dataflow category) without one",
                input.display()
            )
        }
        [] => anyhow::bail!(
            "no system named {:?} in {}; the systems are: {}",
            args.system.as_deref().unwrap_or(""),
            input.display(),
            names()
        ),
        many => match &args.system {
            // Several systems of that name: only a file path tells them apart.
            Some(want) => anyhow::bail!(
                "{} systems in {} are named {want:?}; choose one by its name as the pages show it or by its file, with --system: {}",
                many.len(),
                input.display(),
                listed(many)
            ),
            None => anyhow::bail!(
                "{} holds {} systems; choose one with --system NAME (its name as the pages show it, or its file path): {}",
                input.display(),
                many.len(),
                listed(many)
            ),
        },
    })
}

/// `rtcdoc graph`: the wiring of one system of the input as DOT, Mermaid or SVG.
fn graph(cli: &Cli, args: &GraphArgs) -> anyhow::Result<ExitCode> {
    let file = config_for(cli, args.input.as_deref(), &args.input_args)?;
    let input = args
        .input
        .clone()
        .unwrap_or_else(|| config::default_input(&file));
    let mut opts = load_options(&file, &args.input_args);
    if args.input.is_none() {
        pin(&file, &SourceArgs::default(), &mut opts, true)?;
    } else {
        opts.sources_only = false;
    }
    let loaded = build::load(&input, &opts)?;
    let lang = file.config.language.unwrap_or_default();
    if let Some(grouping) = args.dataflow {
        use rtcdoc::catalog::dataflow::Grouping;
        let (grouping, key) = match grouping {
            DataflowGrouping::Category => (Grouping::Category, "dataflow_by_category"),
            DataflowGrouping::Vendor => (Grouping::Vendor, "dataflow_by_vendor"),
        };
        let rows = rtcdoc::render::facts::dataflow_rows(&loaded.catalog, grouping, lang);
        // Every group and flow (an export is for post-processing), no links.
        let (inst, conns, _, _) =
            rtcdoc::render::wiring::dataflow_wiring(&rows, lang, &|_| String::new(), None);
        let name = format!("{} — {}", lang.t("dataflow"), lang.t(key));
        if inst.is_empty() && !cli.quiet {
            // An empty graph is written (a script expects one), with the reason on stderr.
            eprintln!("note: {}", lang.t("dataflow_none"));
        }
        return write_graph(args, &name, &name, (&inst, &conns, (&[], None)));
    }
    if let Some(want) = &args.component {
        let cat = &loaded.catalog;
        let ci = find_component(cat, want, &input)?;
        use rtcdoc::render::neighbourhood as nb;
        let n = nb::neighbourhood(cat, ci);
        let rows = nb::rows(cat, ci, &n);
        // No links: the pages they would point to are not beside the export.
        let (inst, conns) = nb::wiring(cat, ci, &rows, lang, &|_, _| String::new());
        let name = cat[ci].display_name();
        let title = format!("{} {name}", lang.t("neighbourhood_of"));
        return write_graph(args, &title, &title, (&inst, &conns, (&[], None)));
    }
    let s = choose_system(&loaded.catalog, args, &input)?;
    // Links as from the site's root (the drawing stands on its own).
    let cat = &loaded.catalog;
    let w = rtcdoc::render::wiring::system_wiring(cat, s, lang, &|to, a| {
        cat.href_from_root(to, Some(a), rtcdoc::catalog::Output::Html)
    });
    let name = s.profile.name();
    // A connector left out of the drawing is named on stderr too (and in the drawing).
    for n in &w.not_drawn {
        eprintln!("note: {n}");
    }
    write_graph(
        args,
        name,
        &format!("{} {name}", lang.t("sys_wiring")),
        (
            &w.instances,
            &w.connectors,
            // DOT and Mermaid draw no port squares: their legend says what the outlines mean.
            match args.format {
                GraphFormat::Svg => w.drawing_notes(),
                _ => (&w.not_drawn, w.outline_legend.as_deref()),
            },
        ),
    )
}

/// The component `want` names (its name, id or page slug; exactly one), or an error naming
/// the closest names of the catalogue.
fn find_component(
    cat: &rtcdoc::catalog::Catalog,
    want: &str,
    input: &std::path::Path,
) -> anyhow::Result<rtcdoc::catalog::ComponentIx> {
    let found: Vec<rtcdoc::catalog::ComponentIx> = rtcdoc::catalog::Ix::enumerate(&cat.components)
        .filter(|(_, c)| {
            // The id as written, also when several profiles share it (their entry ids carry
            // `@source`).
            let written =
                c.id.strip_suffix(c.source.as_str())
                    .and_then(|id| id.strip_suffix('@'))
                    .unwrap_or(&c.id);
            c.profile.name() == want
                || &*c.id == want
                || written == want
                || c.slug == want
                || c.display_name() == want
        })
        .map(|(ci, _)| ci)
        .collect();
    match found.as_slice() {
        [one] => Ok(*one),
        [] if cat.components.is_empty() => {
            anyhow::bail!("no component profile in {}", input.display())
        }
        [] => {
            // Only names like the one given (`rtcdoc::suggest`): the five least far of
            // unrelated names would send the reader after the wrong component.
            let names: Vec<std::borrow::Cow<'_, str>> =
                cat.components.iter().map(|c| c.display_name()).collect();
            let near = rtcdoc::suggest::nearest(want, names.iter().map(|n| n.as_ref()), 5);
            if near.is_empty() {
                anyhow::bail!(
                    "no component named {want:?} in {}, nor one of a similar name; give the name, id or page slug of one of its {} components (the index page of `rtcdoc build` lists them)",
                    input.display(),
                    cat.components.len()
                )
            }
            anyhow::bail!(
                "no component named {want:?} in {}; did you mean: {}? (give a name, an id or a page slug)",
                input.display(),
                near.join(", ")
            )
        }
        many => anyhow::bail!(
            "{} components match {want:?}; choose one by id: {}",
            many.len(),
            many.iter()
                .map(|&ci| format!("{} ({})", cat[ci].display_name(), cat[ci].id))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Writes a graph (a system's wiring, the data flow, a neighbourhood) in the chosen format:
/// its instances, its connectors and the connectors it leaves out (sentences that say why).
fn write_graph(
    args: &GraphArgs,
    name: &str,
    title: &str,
    (inst, conns, notes): (
        &[rtcdoc::render::wiring::WireInstance],
        &[rtcdoc::render::wiring::WireConnector],
        rtcdoc::render::wiring::DrawingNotes<'_>,
    ),
) -> anyhow::Result<ExitCode> {
    use rtcdoc::render::{html, wiring};
    let all: Vec<String> = notes
        .0
        .iter()
        .cloned()
        .chain(notes.1.map(str::to_string))
        .collect();
    let text = match args.format {
        GraphFormat::Dot => wiring::to_dot(name, inst, conns, &all),
        GraphFormat::Mermaid => wiring::to_mermaid(name, inst, conns, &all),
        GraphFormat::Svg => html::standalone_system_diagram(title, inst, conns, notes),
    };
    match &args.output {
        Some(path) => std::fs::write(path, text.as_bytes())
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?,
        None => print_stdout(text.trim_end())?,
    }
    Ok(ExitCode::SUCCESS)
}

/// Where the files of an input live: the input directory, or the parent of an input file
/// (diagnostics name files relative to it, like the walk does).
fn input_root(input: &std::path::Path) -> PathBuf {
    if input.is_file() {
        input
            .parent()
            .map(std::path::Path::to_path_buf)
            .unwrap_or_default()
    } else {
        input.to_path_buf()
    }
}

/// How much `check`'s human report says: `-q`, `-v`, or the default.
fn verbosity(cli: &Cli) -> rtcdoc::check::report::Verbosity {
    use rtcdoc::check::report::Verbosity;
    if cli.quiet {
        Verbosity::Quiet
    } else if cli.verbose {
        Verbosity::Verbose
    } else {
        Verbosity::Normal
    }
}

/// `check`'s human report on stderr: each finding with its snippet (a source's file read from
/// `source_dirs`), then the one-line summary with the documentation coverage.
fn write_check_human(
    cli: &Cli,
    report: &rtcdoc::check::Report,
    counts: (usize, usize, usize),
    source_dirs: &[std::sync::Arc<tempfile::TempDir>],
) -> anyhow::Result<()> {
    use rtcdoc::check::report;
    use std::io::IsTerminal;
    // Buffered: codespan writes a snippet in many small pieces.
    let choice = colour_choice(std::io::stderr().is_terminal());
    let mut stream = BufferedStandardStream::stderr(choice);
    let verbosity = verbosity(cli);
    report::write_human(&mut stream, &report.diagnostics, verbosity, &mut |f| {
        let first = f.split('/').next().unwrap_or_default();
        let bytes = if SOURCE_NAMES
            .get()
            .is_some_and(|n| n.iter().any(|n| n == first))
        {
            source_dirs
                .iter()
                .find_map(|d| std::fs::read(d.path().join(f)).ok())?
        } else {
            std::fs::read(f).ok()?
        };
        String::from_utf8(bytes).ok()
    })?;
    std::io::Write::flush(&mut stream)?;
    if !cli.quiet {
        let s = &report.summary;
        let hidden = if verbosity == report::Verbosity::Verbose || s.infos == 0 {
            String::new()
        } else {
            " (infos shown with --verbose)".to_string()
        };
        // The IDL members' share, when IDL definitions were counted (RTC506–RTC508).
        let idl = match report.coverage.idl_counts() {
            (_, 0) => String::new(),
            (d, t) => format!("; IDL {d}/{t}"),
        };
        let documented = rtcdoc::catalog::documented(counts.0, counts.1, counts.2);
        let coverage = if report.coverage.total == 0 {
            String::new()
        } else {
            format!(
                ", documentation coverage {:.1}% ({}/{}{idl})",
                report.coverage.percent, report.coverage.documented, report.coverage.total
            )
        };
        eprintln!("{}{hidden}; {documented}{coverage}", s.one_line());
    }
    Ok(())
}

/// `rtcdoc check --explain CODE`: the rule's text, or what to run for a code of `diff`.
fn explain_rule(code: &str) -> ExitCode {
    use rtcdoc::check;
    match check::rule(code) {
        Some(r) => {
            print!("{}", check::explain(r));
            ExitCode::SUCCESS
        }
        None if rtcdoc::diff::codes::code(code).is_some() => {
            eprintln!(
                "error: `{code}` is a code of rtcdoc diff: run `rtcdoc diff --explain {code}`"
            );
            ExitCode::from(2)
        }
        None => {
            let codes: Vec<&str> = check::RULES.iter().map(|r| r.code).collect();
            eprintln!(
                "error: no rule has the code or name `{code}`; the codes are {}",
                codes.join(", ")
            );
            ExitCode::from(2)
        }
    }
}

/// What `check` found in one path.
struct Checked {
    /// The findings, files named as the user can open them.
    report: rtcdoc::check::Report,
    /// The components, RT Systems and IDL files read.
    counts: (usize, usize, usize),
    /// The folder of its sources' files (for the snippets of the human report).
    sources_dir: Option<std::sync::Arc<tempfile::TempDir>>,
}

/// `check` of one path.
fn check_path(
    cli: &Cli,
    args: &CheckArgs,
    file: &config::Loaded,
    opts: &build::LoadOptions,
    p: &Path,
) -> anyhow::Result<Checked> {
    use rtcdoc::check;
    let loaded = build::load(p, opts)?;
    if let (Some(note), false) = (loaded.catalog.backup_note(), cli.quiet) {
        eprintln!("note: {note}");
    }
    let human = matches!(args.format, CheckFormat::Human);
    if let (Some(note), true) = (
        rtcdoc::check::undefined_types_note(&loaded.catalog, file.path.as_deref()),
        human && !cli.quiet,
    ) {
        eprintln!("note: {note}");
    }
    if let (Some(note), true) = (
        rtcdoc::check::idl_on_no_page_note(&loaded.idl_on_no_page),
        human && !cli.quiet,
    ) {
        eprintln!("note: {note}");
    }
    let mut r = check::check(&loaded.catalog);
    // Name files as the user can open them: relative to the current directory.
    let root = input_root(p);
    for d in &mut r.diagnostics {
        // The folder `rtcdoc extract` is to be run on, as the user names it.
        if d.code == rtcdoc::implementation::codes::RECOVERED {
            let folder = rtcdoc::implementation::recover::component_folder(&d.file);
            d.hint = Some(rtcdoc::implementation::recover::extract_hint(
                &display_path(&root, folder),
            ));
        }
        d.file = display_path(&root, &d.file);
        if let Some(rel) = &mut d.related {
            rel.file = display_path(&root, &rel.file);
        }
    }
    for c in &mut r.coverage.components {
        c.source = display_path(&root, &c.source);
    }
    for c in &mut r.coverage.idl {
        c.file = display_path(&root, &c.file);
    }
    if cli.verbose {
        print_skipped(&loaded.skipped, &root, &shown_files(&loaded.catalog));
    }
    let counts = (
        loaded.catalog.components.len(),
        loaded.catalog.systems.len(),
        loaded.catalog.idl.files.len(),
    );
    let dir = loaded.roots.sources_dir.clone();
    // Not freed one allocation at a time: the process ends soon (see `Command::Build`).
    std::mem::forget(loaded);
    Ok(Checked {
        report: r,
        counts,
        sources_dir: dir,
    })
}

/// `rtcdoc check`: exit 0 when clean, 1 on errors (or warnings with `--deny warnings`), 2 on
/// usage or I/O problems.
fn check(cli: &Cli, args: &CheckArgs) -> anyhow::Result<ExitCode> {
    use rtcdoc::check::{self, report};
    if let Some(code) = &args.explain {
        return Ok(explain_rule(code));
    }
    // Same input options as `build`: rtcdoc.toml, then the command line.
    let file = config_for(
        cli,
        args.paths.first().map(PathBuf::as_path),
        &args.read.input,
    )?;
    let mut opts = load_options(&file, &args.read.input);
    // No path: the configuration's input (its `input`, its folder, or its sources only), and
    // one directory: it and the sources added to it — both as `build` reads them.
    if args.paths.is_empty() || (args.paths.len() == 1 && args.paths[0].is_dir()) {
        pin(&file, &args.read.sources, &mut opts, cli.quiet)?;
    }
    let paths = if args.paths.is_empty() {
        vec![config::default_input(&file)]
    } else {
        opts.sources_only = false;
        args.paths.clone()
    };
    let mut reports = Vec::new();
    let mut counts = (0, 0, 0);
    // The sources' files, kept for the snippets of the human report.
    let mut source_dirs = Vec::new();
    for p in &paths {
        let c = check_path(cli, args, &file, &opts, p)?;
        source_dirs.extend(c.sources_dir);
        counts.0 += c.counts.0;
        counts.1 += c.counts.1;
        counts.2 += c.counts.2;
        reports.push(c.report);
    }
    let report = check::Report::merge(reports);
    let deny_warnings = args.deny.contains(&Deny::Warnings);
    match args.format {
        CheckFormat::Json => {
            print_stdout(&serde_json::to_string_pretty(&report::to_json(&report))?)?
        }
        CheckFormat::Sarif => {
            print_stdout(&serde_json::to_string_pretty(&report::to_sarif(&report))?)?
        }
        CheckFormat::Human => {
            write_check_human(cli, &report, counts, &source_dirs)?;
        }
    }
    Ok(if report.failed(deny_warnings) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// `rtcdoc diff`: exit 0 when no change reaches `--fail-on`, 1 when one does, 2 on usage or I/O
/// problems (an unreadable side, not a git repository, a bad revision).
fn diff(cli: &Cli, args: &DiffArgs) -> anyhow::Result<ExitCode> {
    use rtcdoc::diff::{self, report, side};
    if let Some(code) = &args.explain {
        return Ok(match diff::codes::code(code) {
            Some(c) => {
                print!("{}", diff::codes::explain(c));
                ExitCode::SUCCESS
            }
            None if rtcdoc::check::rule(code).is_some() => {
                eprintln!("error: `{code}` is a code of rtcdoc check: run `rtcdoc check --explain {code}`");
                ExitCode::from(2)
            }
            None => {
                let codes: Vec<&str> = diff::CODES.iter().map(|c| c.code).collect();
                eprintln!(
                    "error: no change has the code or name `{code}`; the codes are {}",
                    codes.join(", ")
                );
                ExitCode::from(2)
            }
        });
    }
    let (old_arg, new_arg, file) = diff_sides(cli, args)?;
    let (old_arg, new_arg) = (&old_arg, &new_arg);
    let (old_spec, new_spec) = (side::Spec::parse(old_arg), side::Spec::parse(new_arg));
    let mut opts = load_options(&file, &args.read.input);
    opts.sources_only = false;
    // `NAME` or `NAME@REV` of a `[[source]]` (not a path on disk): that source alone, at its
    // locked commit or at REV.
    let (old_spec, new_spec) = (
        source_spec(&file, old_arg, old_spec, &args.read.sources)?,
        source_spec(&file, new_arg, new_spec, &args.read.sources)?,
    );
    let old = side::load("OLD", &old_spec, &opts)?;
    let new = side::load("NEW", &new_spec, &opts)?;
    let mut result = diff::diff_with_systems(
        &old.loaded.catalog,
        &new.loaded.catalog,
        &|f| old.display(f),
        &|f| new.display(f),
        (&old.systems(), &new.systems()),
    );
    let fail_on = args.fail_on.level();
    gate(&file, args, (fail_on, cli.quiet), (&old, &new), &mut result)?;
    match args.format {
        report::OutputFormat::Json => print_stdout(&serde_json::to_string_pretty(
            &report::to_json(&result, old_arg, new_arg, fail_on),
        )?)?,
        report::OutputFormat::Markdown => {
            print_stdout(report::to_markdown(&result, old_arg, new_arg, fail_on).trim_end())?
        }
        report::OutputFormat::Github => print_stdout(report::to_github(&result).trim_end())?,
        report::OutputFormat::Human => {
            let choice = colour_choice(std::io::stdout().is_terminal());
            let mut stream = BufferedStandardStream::stdout(choice);
            let verbosity = if cli.quiet {
                report::Verbosity::Quiet
            } else if cli.verbose {
                report::Verbosity::Verbose
            } else {
                report::Verbosity::Normal
            };
            let revs = [&old_spec, &new_spec].map(side::Spec::file_prefix);
            match report::write_human(&mut stream, &result, verbosity, [&revs[0], &revs[1]])
                .and_then(|_| std::io::Write::flush(&mut stream))
            {
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {}
                r => r?,
            }
        }
    }
    Ok(if result.summary().fails(fail_on) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// The sides of `rtcdoc diff` as given (OLD and NEW, or `--since REV` and NEW) and the
/// configuration: rtcdoc.toml of NEW when it is a directory on disk, else of the current
/// directory. With `--since REV`, OLD is `REV:./NEW` (NEW relative to the current directory),
/// NEW the one path given, else the configuration's input.
fn diff_sides(cli: &Cli, args: &DiffArgs) -> anyhow::Result<(String, String, config::Loaded)> {
    use rtcdoc::diff::side::Spec;
    let config_of = |new: &str| {
        let spec = Spec::parse(new);
        let dir = match &spec {
            Spec::Local(p) => Some(p.as_path()),
            Spec::Git { .. } | Spec::Source(_) => None,
        };
        config_for(cli, dir, &args.read.input)
    };
    let Some(rev) = &args.since else {
        let (Some(old), Some(new)) = (&args.old, &args.new) else {
            anyhow::bail!("give OLD and NEW (or --since REV, or --explain CODE)");
        };
        return Ok((old.clone(), new.clone(), config_of(new)?));
    };
    if rev.starts_with('-') {
        anyhow::bail!(
            "--since `{rev}` starts with `-`: a git revision never does, and rtcdoc does not pass options to git; name a tag, branch or commit (`--since v1.0.0`)"
        );
    }
    if rev.trim().is_empty() || rev.contains(':') {
        anyhow::bail!(
            "--since takes a revision alone (a tag, branch or commit: `--since v1.0.0`, `--since origin/main`), not REV:PATH: the path is NEW's; to compare other paths, give OLD and NEW"
        );
    }
    if args.new.is_some() {
        anyhow::bail!(
            "--since REV is OLD: give only NEW (`rtcdoc diff --since {rev} components`), or OLD and NEW without --since"
        );
    }
    let (new, file) = match &args.old {
        Some(new) => (new.clone(), config_of(new)?),
        None => {
            let file = config_for(cli, None, &args.read.input)?;
            let input = config::default_input(&file);
            (input.to_string_lossy().into_owned(), file)
        }
    };
    let path = Path::new(&new);
    if !path.exists() {
        anyhow::bail!(
            "NEW `{new}` does not exist: with --since REV, NEW is a directory or profile file of the working tree, compared with the same path at REV"
        );
    }
    let relative = if path.is_absolute() {
        let cwd = std::env::current_dir()?;
        path.strip_prefix(&cwd)
            .map_err(|_| {
                anyhow::anyhow!(
                    "NEW `{new}` is outside the current directory: with --since REV, run rtcdoc diff inside the repository, or give OLD as REV:PATH"
                )
            })?
            .to_path_buf()
    } else {
        path.to_path_buf()
    };
    let parts: Vec<String> = relative
        .components()
        .filter(|c| !matches!(c, std::path::Component::CurDir))
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    Ok((format!("{rev}:./{}", parts.join("/")), new, file))
}

/// Applies the `[diff]` policy of the configuration and the baseline (`--baseline`, or the
/// one `--write-baseline` writes) to a finished comparison.
fn gate(
    file: &config::Loaded,
    args: &DiffArgs,
    (fail_on, quiet): (Option<rtcdoc::diff::Level>, bool),
    (old, new): (&rtcdoc::diff::side::Side, &rtcdoc::diff::side::Side),
    result: &mut rtcdoc::diff::Diff,
) -> anyhow::Result<()> {
    use anyhow::Context;
    use rtcdoc::diff::{baseline, policy};
    if let Some(d) = &file.config.diff {
        let shown = file
            .path
            .as_deref()
            .unwrap_or(Path::new(config::FILE_NAME))
            .display()
            .to_string();
        let p = policy::Policy::new(d, &|_| shown.clone())?;
        // The globs of `ignore-only` are written relative to the input, as `exclude`'s are.
        let relative = |side: &rtcdoc::diff::side::Side, shown: &str| {
            let root = side.root.to_string_lossy().replace('\\', "/");
            let root = root.trim_start_matches("./").trim_end_matches('/');
            if root.is_empty() || root == "." {
                shown.to_string()
            } else {
                shown
                    .strip_prefix(root)
                    .and_then(|r| r.strip_prefix('/'))
                    .unwrap_or(shown)
                    .to_string()
            }
        };
        p.apply(result, &|c| {
            let mut files = Vec::new();
            files.extend(c.file.as_deref().map(|f| relative(new, f)));
            files.extend(c.old_file.as_deref().map(|f| relative(old, f)));
            files
        });
    }
    // After the policy's severities, before the baseline: a breaking change of an item
    // experimental on the NEW side is a warning.
    rtcdoc::diff::stability::relax(result, &new.loaded.catalog);
    let shown = |p: &Path| p.display().to_string();
    if let Some(out) = &args.write_baseline {
        // The reasons already reviewed are kept: those of --baseline first, then those of the
        // file being rewritten (a re-run after `git pull` or on a new base keeps them both).
        let mut keep = Vec::new();
        if let Some(b) = &args.baseline {
            keep.push(baseline::read(b, &shown(b), false)?);
        }
        if out.exists() && args.baseline.as_deref() != Some(out.as_path()) {
            keep.push(baseline::read(out, &shown(out), false).with_context(|| {
                format!(
                    "--write-baseline `{}` exists and is not a baseline: nothing was written; name another file, or remove it",
                    out.display()
                )
            })?);
        }
        let level = fail_on.unwrap_or(rtcdoc::diff::Level::Breaking);
        let (text, entries, kept) = baseline::write(result, level, &keep);
        std::fs::write(out, &text)
            .with_context(|| format!("cannot write the baseline `{}`", out.display()))?;
        if !quiet {
            eprintln!(
                "note: wrote {entries} baseline entr{} to {} ({kept} with the reason it had); write in each `reason` still starting with \"TODO:\" why the change is accepted, then run with --baseline {}",
                if entries == 1 { "y" } else { "ies" },
                out.display(),
                out.display()
            );
        }
        baseline::apply(result, &baseline::parse(&text, &shown(out), false)?);
    } else if let Some(b) = &args.baseline {
        baseline::apply(result, &baseline::read(b, &shown(b), true)?);
    }
    Ok(())
}

/// A side of `rtcdoc diff` named `NAME` or `NAME@REV` of a `[[source]]` of the configuration
/// (when no such path exists): that source pinned at its locked commit, or at REV.
fn source_spec(
    file: &config::Loaded,
    arg: &str,
    spec: rtcdoc::diff::side::Spec,
    s: &SourceArgs,
) -> anyhow::Result<rtcdoc::diff::side::Spec> {
    use rtcdoc::diff::side::Spec;
    let configs = file.config.source.as_deref().unwrap_or_default();
    if !matches!(&spec, Spec::Local(p) if !p.exists()) || configs.is_empty() {
        return Ok(spec);
    }
    let (name, rev) = match arg.split_once('@') {
        Some((n, r)) => (n, Some(r)),
        None => (arg, None),
    };
    let base = file.dir.clone().unwrap_or_else(|| PathBuf::from("."));
    let sources = rtcdoc::sources::check_all(configs, &base)?;
    let Some(source) = sources.iter().find(|x| x.name == name) else {
        return Ok(spec);
    };
    let pinned = match rev {
        Some(rev) => rtcdoc::sources::pin_rev(source, rev, &s.mode())?,
        None => {
            let (all, _) = config::pin_sources(file, &s.mode(), None, &rtcdoc::build::Quiet)?;
            all.into_iter()
                .find(|p| p.source.name == name)
                .ok_or_else(|| anyhow::anyhow!("source `{name}` was not pinned"))?
        }
    };
    let _ = SOURCE_NAMES.set(sources.iter().map(|x| x.name.clone()).collect());
    Ok(Spec::Source(Box::new(pinned)))
}

/// `rtcdoc extract`: the profile of each component implemented below the path, written
/// beside its code (all checked first: nothing is written when one cannot be).
fn extract(cli: &Cli, args: &ExtractArgs) -> anyhow::Result<ExitCode> {
    use rtcdoc::implementation::recover;
    if !args.path.exists() {
        anyhow::bail!("`{}` does not exist", args.path.display());
    }
    let max = args
        .max_file_size
        .unwrap_or(rtcdoc::parse::Limits::default().max_file_size);
    let mut found = recover::extract(&args.path, max)?;
    // A component a profile documents already is `check`'s to compare, unless --force (or
    // only printed).
    let documented: Vec<String> = found
        .iter()
        .filter(|e| e.documented && !args.force && !args.stdout)
        .map(|e| e.found.source.clone())
        .collect();
    if !documented.is_empty() {
        found.retain(|e| !e.documented);
        if found.is_empty() {
            anyhow::bail!(
                "every component in `{}` has a profile already ({}); nothing was written: `rtcdoc check` compares a profile with its code, `--stdout` prints the profile the code describes, and --force overwrites the profile (what only it says is lost)",
                args.path.display(),
                documented.join(", ")
            );
        }
        if !cli.quiet && !found.is_empty() {
            eprintln!(
                "note: left out {} component(s) a profile documents already ({}); --force writes them too",
                documented.len(),
                documented.join(", ")
            );
        }
    }
    if found.is_empty() {
        anyhow::bail!(
            "no component implementation in `{}`: no C++, Python or Java file holds a spec array (`<name>_spec[]` with \"implementation_id\"); name the component's folder",
            args.path.display()
        );
    }
    if (args.stdout || args.output.is_some()) && found.len() > 1 {
        let names: Vec<String> = found.iter().map(|e| e.found.source.clone()).collect();
        anyhow::bail!(
            "`{}` holds {} components ({}); name one of their files or folders to use {}",
            args.path.display(),
            found.len(),
            names.join(", "),
            if args.stdout { "--stdout" } else { "--output" }
        );
    }
    if args.stdout {
        print_stdout(found[0].xml.trim_end())?;
        return Ok(ExitCode::SUCCESS);
    }
    let targets: Vec<PathBuf> = found
        .iter()
        .map(|e| args.output.clone().unwrap_or_else(|| e.target.clone()))
        .collect();
    if !args.force {
        if let Some(t) = targets.iter().find(|t| t.exists()) {
            anyhow::bail!(
                "`{}` exists already; nothing was written (pass --force to overwrite it, and lose what only the profile says, or --stdout to compare)",
                t.display()
            );
        }
    }
    for (e, target) in found.iter().zip(&targets) {
        if let Some(dir) = target.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(target, &e.xml)
            .map_err(|err| anyhow::anyhow!("cannot write `{}`: {err}", target.display()))?;
        if !cli.quiet {
            let p = &e.found.profile;
            let unread: Vec<String> = e
                .found
                .recovered
                .unread
                .iter()
                .map(|u| format!("{} ({})", u.field, u.written))
                .collect();
            eprintln!(
                "wrote {}: {} ({}; {} data port(s), {} service port(s), {} parameter(s)){}",
                target.display(),
                p.name(),
                e.found.implementation.language.name(),
                p.data_ports.len(),
                p.service_ports.len(),
                p.configurations().len(),
                if unread.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; not read from the code, left empty: {}",
                        unread.join(", ")
                    )
                }
            );
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `root/rel` with forward slashes and without a leading `./`.
fn display_path(root: &std::path::Path, rel: &str) -> String {
    let first = rel.split('/').next().unwrap_or_default();
    if SOURCE_NAMES
        .get()
        .is_some_and(|n| n.iter().any(|n| n == first))
    {
        return rel.to_string();
    }
    let joined = root.join(rel).to_string_lossy().replace('\\', "/");
    joined.strip_prefix("./").unwrap_or(&joined).to_string()
}

/// Colour on a terminal stream unless `NO_COLOR` is set (and not empty).
fn colour_choice(is_terminal: bool) -> ColorChoice {
    let colour = std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()) && is_terminal;
    if colour {
        ColorChoice::Auto
    } else {
        ColorChoice::Never
    }
}

/// Prints a document on stdout; a closed pipe (`| head`) is not an error.
fn print_stdout(text: &str) -> std::io::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match writeln!(out, "{text}").and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        r => r,
    }
}
