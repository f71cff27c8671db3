//! The `rtcdoc` command line: thin — parse arguments, load the configuration, call the
//! library, report.

use clap::{Args, CommandFactory, Parser, Subcommand};
use rtcdoc::build::{self, LoadOptions, Progress};
use rtcdoc::config::{self, Overrides};
use rtcdoc::diagnostic::Severity;
use rtcdoc::i18n::Lang;
use rtcdoc::render::Format;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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
    /// Render a directory of profiles as an HTML site, Markdown, Doxygen input or JSON.
    Build(BuildArgs),
    /// Validate profiles (for CI); exits 1 when a profile has an error.
    Check(CheckArgs),
    /// Write an `rtcdoc.toml` with every setting commented out at its default.
    Init(InitArgs),
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
    /// Glob of input-relative paths to leave out (repeatable), e.g. `--exclude '**/backup/**'`.
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
}

#[derive(Args)]
struct BuildArgs {
    /// Directory (or single file) of profiles [default: the config's `input`, else `.`].
    input: Option<PathBuf>,
    /// Output directory, replaced on success [default: `site`].
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Output format(s); several at once go to OUT/<format>/ [default: html].
    #[arg(short, long, value_enum, value_delimiter = ',')]
    format: Vec<Format>,
    /// Fail without writing anything when any profile has an error.
    #[arg(long)]
    strict: bool,
    /// Title of the catalogue.
    #[arg(long)]
    title: Option<String>,
    /// URL the site is published at (for sitemap.xml).
    #[arg(long, value_name = "URL")]
    base_url: Option<String>,
    /// Theme directory overriding built-in templates and assets file by file.
    #[arg(long, value_name = "DIR")]
    theme: Option<PathBuf>,
    /// Language of generated labels (profile text is shown as written).
    #[arg(long, value_enum)]
    language: Option<Lang>,
    #[command(flatten)]
    input_args: InputArgs,
}

#[derive(Args)]
struct CheckArgs {
    /// Directories or files to check [default: `.`].
    paths: Vec<PathBuf>,
    #[command(flatten)]
    input_args: InputArgs,
}

#[derive(Args)]
struct InitArgs {
    /// Directory to write `rtcdoc.toml` into.
    #[arg(default_value = ".")]
    dir: PathBuf,
    /// Overwrite an existing `rtcdoc.toml`.
    #[arg(long)]
    force: bool,
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

/// A progress bar on standard error, drawn only when it is a terminal.
struct Bar(indicatif::ProgressBar);

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
            Bar(b)
        } else {
            Bar(indicatif::ProgressBar::hidden())
        }
    }
}

impl Progress for Bar {
    fn stage(&self, name: &str, total: usize) {
        self.0.set_message(name.to_string());
        self.0.set_length(total as u64);
        self.0.set_position(0);
    }
    fn advance(&self, n: usize) {
        self.0.inc(n as u64);
    }
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

fn overrides(args: &BuildArgs) -> Overrides {
    let i = &args.input_args;
    Overrides {
        input: args.input.clone(),
        output: args.output.clone(),
        formats: args.format.clone(),
        strict: args.strict,
        title: args.title.clone(),
        base_url: args.base_url.clone(),
        theme: args.theme.clone(),
        language: args.language,
        include: i.include.clone(),
        exclude: i.exclude.clone(),
        max_file_size: i.max_file_size,
        max_depth: i.max_depth,
    }
}

fn run(cli: &Cli) -> anyhow::Result<ExitCode> {
    match &cli.command {
        Command::Build(args) => {
            let file = load_config(args.input.as_deref(), args.input_args.config.as_deref())?;
            let opts = config::build_options(&file, &overrides(args));
            let bar = Bar::new(!cli.quiet);
            let result = build::build_with(&opts, &bar);
            bar.0.finish_and_clear();
            let (loaded, report) = result?;
            if cli.verbose {
                if let Some(p) = &file.path {
                    eprintln!("configuration: {}", p.display());
                }
                for s in &loaded.skipped {
                    eprintln!("skipped {}: {}", s.rel, s.reason);
                }
            }
            print_diagnostics(&loaded.catalog.diagnostics, cli.verbose, cli.quiet);
            if !cli.quiet {
                eprintln!(
                    "built {} profile(s) into {}: {} file(s), {} error(s), {} warning(s) in {:.2}s",
                    report.profiles,
                    opts.output.display(),
                    report.files_written,
                    report.errors,
                    report.warnings,
                    report.seconds
                );
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Check(args) => {
            let paths = if args.paths.is_empty() {
                vec![PathBuf::from(".")]
            } else {
                args.paths.clone()
            };
            let file = load_config(
                paths.first().map(PathBuf::as_path),
                args.input_args.config.as_deref(),
            )?;
            let mut opts = config::build_options(
                &file,
                &Overrides {
                    include: args.input_args.include.clone(),
                    exclude: args.input_args.exclude.clone(),
                    max_file_size: args.input_args.max_file_size,
                    max_depth: args.input_args.max_depth,
                    ..Default::default()
                },
            )
            .load;
            opts.skip_dirs.clear();
            let mut failed = false;
            for p in &paths {
                let loaded = build::load(p, &LoadOptions { ..opts.clone() })?;
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
        Command::Init(args) => {
            let path = args.dir.join(config::FILE_NAME);
            if path.exists() && !args.force {
                anyhow::bail!(
                    "`{}` already exists (use --force to overwrite it)",
                    path.display()
                );
            }
            std::fs::create_dir_all(&args.dir)?;
            std::fs::write(&path, config::template())?;
            if !cli.quiet {
                eprintln!("wrote {}", path.display());
            }
            Ok(ExitCode::SUCCESS)
        }
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
            clap_mangen::Man::new(Cli::command()).render(&mut std::io::stdout())?;
            Ok(ExitCode::SUCCESS)
        }
    }
}
