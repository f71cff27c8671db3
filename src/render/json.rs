//! JSON output: `catalog.json`, the normalized catalogue for other tools.
//!
//! Shape (documented in `book/src/json.md`): `{"generator", "formatVersion", "components": [...],
//! "dataTypes": [...], "interfaces": [...], "categories": [...], "vendors": [...],
//! "diagnostics": [...]}`; each component is the whole profile model plus `source`, `format`,
//! `slug` and `anchors`; `systems` (when any) lists the RT System profiles with their links.

use super::{RenderContext, Renderer};
use crate::catalog::Catalog;
use crate::output::Sink;
use serde::Serialize;

/// Version of the `catalog.json` shape; bumped on incompatible changes.
pub const FORMAT_VERSION: u32 = 1;

/// The document as serde would write it from the catalogue's own `Serialize`. Used by the
/// tests as the reference for [`write_json`].
#[cfg(test)]
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Document<'a> {
    generator: String,
    format_version: u32,
    title: &'a str,
    #[serde(flatten)]
    catalog: &'a Catalog,
}

/// The document around the components: every field of [`Catalog`] in its order, with
/// `components` left empty (filled in by [`write_json`]). A test holds the result to the
/// catalogue's own serialization, so a field added to `Catalog` but not here fails it.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Skeleton<'a> {
    generator: String,
    format_version: u32,
    title: &'a str,
    components: [(); 0],
    data_types: &'a [crate::catalog::DataType],
    interfaces: &'a [crate::catalog::InterfaceType],
    categories: &'a [crate::catalog::Facet],
    vendors: &'a [crate::catalog::Facet],
    diagnostics: &'a [crate::diagnostic::Diagnostic],
    #[serde(skip_serializing_if = "crate::idl::IdlSet::is_empty")]
    idl: &'a crate::idl::IdlSet,
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    systems: &'a [crate::catalog::systems::System],
}

/// Where the components go in the pretty-printed skeleton (top-level keys are indented by two
/// spaces; a string value cannot hold a raw newline or quote, so only the key matches).
const COMPONENTS_KEY: &[u8] = b"\n  \"components\": []";

/// Serializes the catalogue as pretty JSON into `w`: the same bytes as
/// `serde_json::to_writer_pretty` of the whole document, but the components — nearly all of
/// it — are serialized in parallel, each into its own buffer, and written in order.
pub fn write_json(
    catalog: &Catalog,
    title: &str,
    w: &mut dyn std::io::Write,
) -> anyhow::Result<()> {
    write_json_with(catalog, title, true, w)
}

/// [`write_json`], with the host data of RT System profiles left out unless `show_host_data`
/// ([`crate::catalog::systems::System::without_host_data`]).
pub fn write_json_with(
    catalog: &Catalog,
    title: &str,
    show_host_data: bool,
    w: &mut dyn std::io::Write,
) -> anyhow::Result<()> {
    use rayon::prelude::*;
    let redacted: Vec<crate::catalog::systems::System>;
    let systems = if show_host_data {
        &catalog.systems[..]
    } else {
        redacted = catalog
            .systems
            .iter()
            .map(|s| s.without_host_data())
            .collect();
        &redacted[..]
    };
    let skeleton = serde_json::to_vec_pretty(&Skeleton {
        generator: super::generator(),
        format_version: FORMAT_VERSION,
        title,
        components: [],
        data_types: &catalog.data_types,
        interfaces: &catalog.interfaces,
        categories: &catalog.categories,
        vendors: &catalog.vendors,
        diagnostics: &catalog.diagnostics,
        idl: &catalog.idl,
        systems,
    })?;
    let at = skeleton
        .windows(COMPONENTS_KEY.len())
        .position(|win| win == COMPONENTS_KEY)
        .ok_or_else(|| anyhow::anyhow!("internal error: no components key in catalog.json"))?;
    let open = at + COMPONENTS_KEY.len() - 1; // the `]` of `[]`
    w.write_all(&skeleton[..open])?;
    if !catalog.components.is_empty() {
        // Chunks of components, so that a 10,000-component catalogue is never in memory as
        // JSON all at once.
        let mut separator: &[u8] = b"\n";
        for chunk in catalog.components.chunks(64) {
            let parts = chunk
                .par_iter()
                .map(|c| {
                    let mut buf = Vec::with_capacity(16 * 1024);
                    serde_json::to_writer_pretty(&mut buf, c)?;
                    Ok(indented(&buf))
                })
                .collect::<serde_json::Result<Vec<Vec<u8>>>>()?;
            for part in &parts {
                w.write_all(separator)?;
                w.write_all(part)?;
                separator = b",\n";
            }
        }
        w.write_all(b"\n  ")?;
    }
    w.write_all(&skeleton[open..])?;
    w.write_all(b"\n")?;
    Ok(())
}

/// A component's pretty JSON as an element of a top-level array: every line four spaces
/// deeper (JSON text has raw line breaks only between tokens).
fn indented(json: &[u8]) -> Vec<u8> {
    const INDENT: &[u8] = b"    ";
    let mut out = Vec::with_capacity(json.len() + json.len() / 8);
    out.extend_from_slice(INDENT);
    let mut start = 0;
    for nl in memchr::memchr_iter(b'\n', json) {
        out.extend_from_slice(&json[start..=nl]);
        out.extend_from_slice(INDENT);
        start = nl + 1;
    }
    out.extend_from_slice(&json[start..]);
    out
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
            write_json_with(ctx.catalog, &ctx.site.title, ctx.site.show_host_data, w)
        })?;
        Ok(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::{load, LoadOptions};
    use crate::catalog::LoadedProfile;

    fn reference(catalog: &Catalog, title: &str) -> Vec<u8> {
        let mut out = serde_json::to_vec_pretty(&Document {
            generator: super::super::generator(),
            format_version: FORMAT_VERSION,
            title,
            catalog,
        })
        .unwrap();
        out.push(b'\n');
        out
    }

    fn written(catalog: &Catalog, title: &str) -> Vec<u8> {
        let mut out = Vec::new();
        write_json(catalog, title, &mut out).unwrap();
        out
    }

    /// The parallel writer gives exactly what serde writes for the whole catalogue: for the
    /// examples, every fixture set (diagnostics, hostile text), the corpus when present, an
    /// empty catalogue and a title that looks like the components key.
    #[test]
    fn same_bytes_as_serializing_the_whole_catalogue() {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let mut inputs = vec![root.join("examples"), root.join("../shared/corpus")];
        for e in std::fs::read_dir(root.join("tests/fixtures")).unwrap() {
            inputs.push(e.unwrap().path());
        }
        let mut compared = 0;
        for input in inputs.iter().filter(|p| p.is_dir()) {
            let opts = LoadOptions {
                allow_empty: true,
                ..Default::default()
            };
            let catalog = load(input, &opts).unwrap().catalog;
            for title in ["Catalogue", "\n  \"components\": []"] {
                let (a, b) = (written(&catalog, title), reference(&catalog, title));
                assert!(a == b, "{} differs", input.display());
            }
            compared += catalog.components.len();
        }
        assert!(compared > 20, "{compared}");
        // More components than several parallel chunks.
        let examples = load(&root.join("examples"), &LoadOptions::default()).unwrap();
        let many: Vec<LoadedProfile> = (0..30)
            .flat_map(|k| {
                examples
                    .catalog
                    .components
                    .iter()
                    .map(move |c| LoadedProfile {
                        source: format!("{k}/{}", c.source),
                        format: c.format,
                        profile: c.profile.clone(),
                    })
            })
            .collect();
        let big = Catalog::build(many, vec![]);
        assert!(big.components.len() > 300);
        assert!(written(&big, "t") == reference(&big, "t"));
        let empty = Catalog::build(vec![], vec![]);
        assert_eq!(written(&empty, "t"), reference(&empty, "t"));
    }
}
