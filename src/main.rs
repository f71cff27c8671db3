//! The `rtcdoc` command line: thin — parse arguments, call the library, report.

use clap::{Args, Parser, Subcommand};
use codespan_reporting::term::termcolor::{ColorChoice, StandardStream};
use rtcdoc::build::{self, BuildOptions, LoadOptions};
use rtcdoc::diagnostic::Severity;
use rtcdoc::parse::Limits;
use rtcdoc::render::{Format, SiteOptions};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "rtcdoc",
    version,
    about = "Documentation for OpenRTM RT-Component profiles (RTC.xml / YAML)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Print every file looked at and skipped, and every warning.
    #[arg(short, long, global = true)]
    verbose: bool,
    /// Print only errors.
    #[arg(short, long, global = true, conflicts_with = "verbose")]
    quiet: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Render a directory of profiles as an HTML site, Markdown, Doxygen input or JSON.
    Build(BuildArgs),
    /// Validate profiles (for CI); exits 1 when a profile has an error.
    Check(CheckArgs),
}

#[derive(Args, Clone)]
struct InputArgs {
    /// Glob of input-relative paths to leave out (repeatable), e.g. `--exclude '**/backup/**'`.
    #[arg(long, value_name = "GLOB")]
    exclude: Vec<String>,
    /// Largest profile file accepted, in bytes.
    #[arg(long, value_name = "BYTES", default_value_t = Limits::default().max_file_size)]
    max_file_size: u64,
    /// Deepest element / collection nesting accepted.
    #[arg(long, value_name = "N", default_value_t = Limits::default().max_depth)]
    max_depth: usize,
}

impl InputArgs {
    fn load_options(&self) -> LoadOptions {
        LoadOptions {
            exclude: self.exclude.clone(),
            limits: Limits {
                max_file_size: self.max_file_size,
                max_depth: self.max_depth,
            },
            skip_dirs: vec![],
        }
    }
}

#[derive(Args)]
struct BuildArgs {
    /// Directory (or single file) of profiles.
    #[arg(default_value = ".")]
    input: PathBuf,
    /// Output directory; replaced on success.
    #[arg(short, long, default_value = "site")]
    output: PathBuf,
    /// Output format(s); several at once go to OUT/<format>/.
    #[arg(short, long, value_enum, value_delimiter = ',', default_value = "html")]
    format: Vec<Format>,
    /// Fail without writing anything when any profile has an error.
    #[arg(long)]
    strict: bool,
    /// Title of the catalogue.
    #[arg(long, default_value = "RT-Component catalogue")]
    title: String,
    /// URL the site is published at (for sitemap.xml).
    #[arg(long, value_name = "URL")]
    base_url: Option<String>,
    /// Theme directory overriding built-in templates and assets file by file.
    #[arg(long, value_name = "DIR")]
    theme: Option<PathBuf>,
    /// Language of generated labels (profile text is shown as written).
    #[arg(long, value_enum, default_value = "en")]
    language: rtcdoc::i18n::Lang,
    #[command(flatten)]
    input_args: InputArgs,
}

#[derive(Args)]
struct CheckArgs {
    /// Directories or files to check.
    #[arg(default_value = ".")]
    paths: Vec<PathBuf>,
    /// Output format: human (rustc-like, on stderr), json or sarif (on stdout).
    #[arg(long, value_enum, default_value = "human")]
    format: CheckFormat,
    /// Treat a class of findings as errors for the exit status (`--deny warnings`).
    #[arg(long, value_enum, value_name = "WHAT")]
    deny: Vec<Deny>,
    /// Print the rationale and spec section of a rule code (e.g. `--explain RTC303`) and exit.
    #[arg(long, value_name = "CODE")]
    explain: Option<String>,
    #[command(flatten)]
    input_args: InputArgs,
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(&cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn print_diagnostics(diags: &[rtcdoc::diagnostic::Diagnostic], verbose: bool, quiet: bool) {
    for d in diags {
        let show = match d.severity {
            Severity::Error => true,
            Severity::Warning => !quiet,
            Severity::Info => verbose,
        };
        if show {
            eprintln!("{d}");
            if let Some(h) = &d.hint {
                eprintln!("  = help: {h}");
            }
        }
    }
}

fn run(cli: &Cli) -> anyhow::Result<ExitCode> {
    match &cli.command {
        Command::Build(args) => {
            let opts = BuildOptions {
                input: args.input.clone(),
                output: args.output.clone(),
                formats: args.format.clone(),
                strict: args.strict,
                load: args.input_args.load_options(),
                site: SiteOptions {
                    title: args.title.clone(),
                    base_url: args.base_url.clone(),
                    theme_dir: args.theme.clone(),
                    language: args.language,
                },
            };
            let (loaded, report) = build::build(&opts)?;
            if cli.verbose {
                for s in &loaded.skipped {
                    eprintln!("skipped {}: {}", s.rel, s.reason);
                }
            }
            // Loader diagnostics as before; the check rules' findings are summed up in one
            // line (all of them with --verbose, and in the JSON output / diagnostics page).
            let (loader, rules): (Vec<_>, Vec<_>) = loaded
                .catalog
                .diagnostics
                .iter()
                .cloned()
                .partition(|d| d.code < "RTC100");
            print_diagnostics(&loader, cli.verbose, cli.quiet);
            if cli.verbose {
                print_diagnostics(&rules, true, false);
            }
            if !cli.quiet {
                eprintln!(
                    "{} (details: rtcdoc check {})",
                    rtcdoc::check::Summary::of(&loaded.catalog.diagnostics).one_line(),
                    args.input.display()
                );
                eprintln!(
                    "built {} profile(s) into {} ({} file(s)), {} error(s), {} warning(s) in {:.2}s",
                    report.profiles,
                    args.output.display(),
                    report.files_written,
                    report.errors,
                    report.warnings,
                    report.seconds
                );
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Check(args) => check(cli, args),
    }
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

/// `rtcdoc check`: exit 0 when clean, 1 on errors (or warnings with `--deny warnings`), 2 on
/// usage or I/O problems.
fn check(cli: &Cli, args: &CheckArgs) -> anyhow::Result<ExitCode> {
    use rtcdoc::check::{self, report};
    if let Some(code) = &args.explain {
        return Ok(match check::rule(code) {
            Some(r) => {
                print!("{}", check::explain(r));
                ExitCode::SUCCESS
            }
            None => {
                eprintln!("error: no rule has the code `{code}` (codes: RTC001–RTC010, RTC101…RTC505; see `rtcdoc check --help`)");
                ExitCode::from(2)
            }
        });
    }
    let mut reports = Vec::new();
    for p in &args.paths {
        let loaded = build::load(p, &args.input_args.load_options())?;
        let mut r = check::check(&loaded.catalog);
        // Name files as the user can open them: relative to the current directory.
        let root = input_root(p);
        for d in &mut r.diagnostics {
            d.file = display_path(&root, &d.file);
        }
        for c in &mut r.coverage.components {
            c.source = display_path(&root, &c.source);
        }
        if cli.verbose {
            for s in &loaded.skipped {
                eprintln!("skipped {}: {}", display_path(&root, &s.rel), s.reason);
            }
        }
        reports.push(r);
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
            use std::io::IsTerminal;
            let colour = std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
                && std::io::stderr().is_terminal();
            let choice = if colour {
                ColorChoice::Auto
            } else {
                ColorChoice::Never
            };
            let stream = StandardStream::stderr(choice);
            let verbosity = if cli.quiet {
                report::Verbosity::Quiet
            } else if cli.verbose {
                report::Verbosity::Verbose
            } else {
                report::Verbosity::Normal
            };
            let mut lock = stream.lock();
            report::write_human(&mut lock, &report.diagnostics, verbosity, &mut |f| {
                let bytes = std::fs::read(f).ok()?;
                String::from_utf8(bytes).ok()
            })?;
            drop(lock);
            if !cli.quiet {
                let s = &report.summary;
                let hidden = if verbosity == report::Verbosity::Verbose || s.infos == 0 {
                    String::new()
                } else {
                    " (infos shown with --verbose)".to_string()
                };
                eprintln!(
                    "{}{hidden}; {} profile(s), documentation coverage {:.1}% ({}/{})",
                    s.one_line(),
                    report.coverage.components.len(),
                    report.coverage.percent,
                    report.coverage.documented,
                    report.coverage.total
                );
            }
        }
    }
    Ok(if report.failed(deny_warnings) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// `root/rel` with forward slashes and without a leading `./`.
fn display_path(root: &std::path::Path, rel: &str) -> String {
    let joined = root.join(rel).to_string_lossy().replace('\\', "/");
    joined.strip_prefix("./").unwrap_or(&joined).to_string()
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
