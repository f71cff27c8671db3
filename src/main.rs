//! The `rtcdoc` command line: thin — parse arguments, call the library, report.

use clap::{Args, Parser, Subcommand};
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
    #[command(flatten)]
    input_args: InputArgs,
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
            print_diagnostics(&loaded.catalog.diagnostics, cli.verbose, cli.quiet);
            if !cli.quiet {
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
        Command::Check(args) => {
            let mut failed = false;
            for p in &args.paths {
                let loaded = build::load(p, &args.input_args.load_options())?;
                print_diagnostics(&loaded.catalog.diagnostics, cli.verbose, cli.quiet);
                let (e, w, _) = loaded.catalog.counts();
                if !cli.quiet {
                    eprintln!(
                        "checked {} profile(s): {e} error(s), {w} warning(s)",
                        loaded.catalog.components.len()
                    );
                }
                failed |= e > 0;
            }
            Ok(if failed {
                ExitCode::from(1)
            } else {
                ExitCode::SUCCESS
            })
        }
    }
}
