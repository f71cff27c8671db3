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

/// Serializes the catalogue as pretty JSON.
pub fn to_json(catalog: &Catalog, title: &str) -> serde_json::Result<Vec<u8>> {
    let doc = Document {
        generator: format!("rtcdoc {}", env!("CARGO_PKG_VERSION")),
        format_version: FORMAT_VERSION,
        title,
        catalog,
    };
    let mut v = serde_json::to_vec_pretty(&doc)?;
    v.push(b'\n');
    Ok(v)
}

/// Writes `catalog.json`.
pub struct JsonRenderer;

impl Renderer for JsonRenderer {
    fn name(&self) -> &'static str {
        "json"
    }
    fn render(&self, ctx: &RenderContext<'_>, out: &dyn Sink) -> anyhow::Result<usize> {
        out.write("catalog.json", &to_json(ctx.catalog, &ctx.site.title)?)?;
        Ok(1)
    }
}
