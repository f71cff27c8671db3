//! JSON output: `catalog.json`, the normalized catalogue for other tools.
//!
//! Shape (documented in `book/src/json.md`): `{"generator", "formatVersion", "components": [...],
//! "dataTypes": [...], "interfaces": [...], "categories": [...], "vendors": [...],
//! "diagnostics": [...]}`; each component is the whole profile model plus `source`, `format`,
//! `slug` and `anchors`.

use super::{RenderContext, Renderer};
use crate::catalog::Catalog;
use crate::output::Sink;
use serde::Serialize;

/// Version of the `catalog.json` shape; bumped on incompatible changes.
pub const FORMAT_VERSION: u32 = 1;

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Document<'a> {
    generator: String,
    format_version: u32,
    title: &'a str,
    #[serde(flatten)]
    catalog: &'a Catalog,
}

/// Serializes the catalogue as pretty JSON into `w`.
pub fn write_json(
    catalog: &Catalog,
    title: &str,
    w: &mut dyn std::io::Write,
) -> anyhow::Result<()> {
    let doc = Document {
        generator: format!("rtcdoc {}", env!("CARGO_PKG_VERSION")),
        format_version: FORMAT_VERSION,
        title,
        catalog,
    };
    serde_json::to_writer_pretty(&mut *w, &doc)?;
    w.write_all(b"\n")?;
    Ok(())
}

/// Writes `catalog.json`.
pub struct JsonRenderer;

impl Renderer for JsonRenderer {
    fn name(&self) -> &'static str {
        "json"
    }
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize> {
        // Streamed: at 10,000 components the document is hundreds of megabytes.
        out.write_with("catalog.json", &mut |w| {
            write_json(ctx.catalog, &ctx.site.title, w)
        })?;
        Ok(1)
    }
}
