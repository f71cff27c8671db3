//! Renderers: one module per output format behind the small [`Renderer`] trait.
//!
//! A renderer receives the finished [`Catalog`] and writes files through a [`Sink`]; it never
//! re-parses and never knows which input format a profile came from.

pub mod doxygen;
pub mod facts;
pub mod history_text;
pub mod html;
pub mod idl_view;
pub mod json;
pub mod markdown;
pub mod neighbourhood;
pub mod system_text;
pub mod text;
pub mod view;
pub mod wiring;

use crate::catalog::Catalog;
use crate::output::Sink;
use std::path::PathBuf;

/// What the outputs name as their generator: `rtcdoc <version>`.
pub fn generator() -> String {
    format!("rtcdoc {}", env!("CARGO_PKG_VERSION"))
}

/// A byte set for escapers' "can this text be copied as is" checks: the ASCII control
/// characters when `controls`, and `bytes`.
pub(crate) const fn byte_set(controls: bool, bytes: &[u8]) -> [bool; 256] {
    let mut t = [false; 256];
    let mut i = 0;
    while controls && i < 0x20 {
        t[i] = true;
        i += 1;
    }
    let mut k = 0;
    while k < bytes.len() {
        t[bytes[k] as usize] = true;
        k += 1;
    }
    t
}

/// How the Markdown output carries a system's wiring diagram: an SVG file beside the page
/// (`svg`, the default) or a Mermaid block in it (`mermaid`, drawn by GitHub, GitLab and
/// mdBook with its Mermaid preprocessor).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DiagramFormat {
    #[default]
    Svg,
    Mermaid,
}

/// Site-wide settings every renderer can use.
#[derive(Debug, Clone)]
pub struct SiteOptions {
    /// Title of the catalogue (index page, book title, Doxygen project name).
    pub title: String,
    /// Absolute URL the site is published at (sitemap, canonical links); optional.
    pub base_url: Option<String>,
    /// A theme directory whose files override the built-in theme file by file.
    pub theme_dir: Option<PathBuf>,
    /// Language of generated labels.
    pub language: crate::i18n::Lang,
    /// Publish the host data of RT System profiles (host names, IORs, CORBA endpoints, naming
    /// paths); hidden by default (`show-host-data` in rtcdoc.toml).
    pub show_host_data: bool,
    /// How the Markdown output draws system diagrams (`[markdown] diagrams`).
    pub markdown_diagrams: DiagramFormat,
    /// `source-url`: a URL template with `{path}` (the profile's input-relative path) that
    /// makes "Source" on component pages a link to the file in its repository.
    pub source_url: Option<String>,
}

impl Default for SiteOptions {
    fn default() -> Self {
        SiteOptions {
            title: "RT-Component catalogue".into(),
            base_url: None,
            theme_dir: None,
            language: crate::i18n::Lang::En,
            show_host_data: false,
            markdown_diagrams: DiagramFormat::Svg,
            source_url: None,
        }
    }
}

/// What a renderer sees.
pub struct RenderContext<'a> {
    pub catalog: &'a Catalog,
    pub site: &'a SiteOptions,
}

/// An output format.
pub trait Renderer: Sync {
    /// Short name (`html`, `markdown`, `doxygen`, `json`), also the sub-directory used when
    /// several formats are built at once.
    fn name(&self) -> &'static str;
    /// Writes the whole output; returns the number of files written.
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize>;
}

/// Output formats known to `rtcdoc build`.
#[derive(
    Debug,
    Clone,
    Copy,
    PartialEq,
    Eq,
    Hash,
    PartialOrd,
    Ord,
    clap::ValueEnum,
    serde::Serialize,
    serde::Deserialize,
)]
#[serde(rename_all = "lowercase")]
pub enum Format {
    Html,
    Markdown,
    Doxygen,
    Json,
    /// A system manual: one self-contained HTML file per RT System, to print.
    Manual,
}

impl Format {
    pub fn name(self) -> &'static str {
        match self {
            Format::Html => "html",
            Format::Markdown => "markdown",
            Format::Doxygen => "doxygen",
            Format::Json => "json",
            Format::Manual => "manual",
        }
    }

    /// The renderer for this format.
    pub fn renderer(self) -> Box<dyn Renderer> {
        match self {
            Format::Html => Box::new(html::HtmlRenderer),
            Format::Json => Box::new(json::JsonRenderer),
            Format::Markdown => Box::new(markdown::MarkdownRenderer),
            Format::Doxygen => Box::new(doxygen::DoxygenRenderer),
            Format::Manual => Box::new(html::ManualRenderer),
        }
    }
}

/// A sink that writes below a sub-directory of another sink.
pub struct Prefixed<'a> {
    pub inner: &'a dyn Sink,
    pub prefix: String,
}

impl Sink for Prefixed<'_> {
    fn write(&self, rel: &str, bytes: &[u8]) -> anyhow::Result<()> {
        self.inner.write(&format!("{}/{rel}", self.prefix), bytes)
    }
    fn write_with(
        &self,
        rel: &str,
        fill: &mut dyn FnMut(&mut dyn std::io::Write) -> anyhow::Result<()>,
    ) -> anyhow::Result<()> {
        self.inner
            .write_with(&format!("{}/{rel}", self.prefix), fill)
    }
}
