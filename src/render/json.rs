//! JSON output: `catalog.json`, the normalized catalogue for other tools, and reading it back.
//!
//! Format 2 (documented in `book/src/json.md`) is the keyed catalogue: `{"generator",
//! "formatVersion": 2, "title", "components": {ID: …}, "dataTypes": {NAME: …}, "interfaces":
//! {NAME: …}, "categories": {NAME: …}, "vendors": {NAME: …}, "pages": [...], "diagnostics":
//! [...], "idl"?, "systems"?: {SOURCE: …}, "backups"?: [...]}` (`backups`: RTCBuilder
//! backups whose `RTC.xml` is no component; the others are in their component). Each component is the whole profile model plus `source`, `format`, `slug`
//! and `anchors`, keyed by its id ([`crate::catalog::Component::id`]); references between
//! entries are ids (`{"component": ID, "port": NAME}`), never positions, so two catalogues can
//! be compared entry by entry (`rtcdoc diff`) and [`read_catalog`] gives the same catalogue
//! back (a round trip writes the same bytes).

use super::{RenderContext, Renderer};
use crate::catalog::systems::System;
use crate::catalog::{Catalog, Component, DataType, Facet, InterfaceType, Output, PageKind};
use crate::diagnostic::Diagnostic;
use crate::idl::IdlSet;
use crate::output::Sink;
use serde::ser::SerializeMap;
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

/// Version of the `catalog.json` shape; bumped on incompatible changes. 1 (before 0.2) listed
/// entries in arrays and referred to them by position; 2 had no history pages of RT Systems
/// and IDL files in `pages` (kinds `systemHistory`, `idlHistory`).
pub const FORMAT_VERSION: u32 = 3;

/// An entry of a keyed object: what its key is, and taking it back when read.
trait KeyedEntry {
    /// What the entry is, in messages (`data type`).
    const WHAT: &'static str;
    fn key(&self) -> &str;
    /// Takes `key` back on reading: sets it where the entry does not hold it, else checks that
    /// the entry holds that very key (a mismatch means the file was edited).
    fn take_key(&mut self, key: String) -> Result<(), String> {
        if key == self.key() {
            Ok(())
        } else {
            Err(format!(
                "{} `{key}` holds the entry of `{}`: the file was edited; build it again",
                Self::WHAT,
                self.key()
            ))
        }
    }
}

impl KeyedEntry for Component {
    const WHAT: &'static str = "component";
    fn key(&self) -> &str {
        &self.id
    }
    /// The id is the key only: the entry does not repeat it.
    fn take_key(&mut self, key: String) -> Result<(), String> {
        self.id = key.into();
        Ok(())
    }
}
/// The entries keyed by a field they keep (`type => "what", field`).
macro_rules! keyed_by_field {
    ($($t:ty => $what:literal, $field:ident;)*) => {$(
        impl KeyedEntry for $t {
            const WHAT: &'static str = $what;
            fn key(&self) -> &str {
                &self.$field
            }
        }
    )*};
}
keyed_by_field! {
    DataType => "data type", name;
    InterfaceType => "interface", name;
    Facet => "facet", name;
    System => "system", source;
}

/// Entries as one JSON object keyed by each entry's key, in catalogue order: borrowed when
/// written, owned when read.
struct Keyed<'a, T: Clone>(Cow<'a, [T]>);

impl<T: Clone> Keyed<'_, T> {
    fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl<T: Clone> Default for Keyed<'_, T> {
    fn default() -> Self {
        Keyed(Cow::Owned(Vec::new()))
    }
}

impl<T: Clone + Serialize + KeyedEntry> Serialize for Keyed<'_, T> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for e in self.0.iter() {
            m.serialize_entry(e.key(), e)?;
        }
        m.end()
    }
}

impl<'de, T: Clone + Deserialize<'de> + KeyedEntry> Deserialize<'de> for Keyed<'_, T> {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Visit<T>(std::marker::PhantomData<T>);
        impl<'de, T: Deserialize<'de> + KeyedEntry> serde::de::Visitor<'de> for Visit<T> {
            type Value = Vec<T>;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("an object of entries keyed by id")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut m: A,
            ) -> Result<Self::Value, A::Error> {
                let mut out = Vec::with_capacity(m.size_hint().unwrap_or(0).min(4096));
                while let Some((key, mut entry)) = m.next_entry::<String, T>()? {
                    entry.take_key(key).map_err(serde::de::Error::custom)?;
                    out.push(entry);
                }
                Ok(out)
            }
        }
        d.deserialize_map(Visit(std::marker::PhantomData))
            .map(|v| Keyed(Cow::Owned(v)))
    }
}

/// A page of the catalogue in `catalog.json`: where the HTML site has it.
#[derive(Debug, Serialize, Deserialize, PartialEq)]
#[serde(rename_all = "camelCase")]
struct PageEntry {
    path: String,
    kind: PageKind,
    id: String,
    title: String,
}

/// [`Catalog::pages`] as `catalog.json` lists them.
fn page_entries(catalog: &Catalog) -> Vec<PageEntry> {
    catalog
        .pages()
        .iter()
        .map(|p| PageEntry {
            path: p.path_in(Output::Html),
            kind: p.kind,
            id: p.id.clone(),
            title: p.title.clone(),
        })
        .collect()
}

/// `catalog.json`, the one definition of its shape: written from the catalogue (borrowed;
/// `components` left empty in the skeleton [`write_json`] fills in) and read back (owned).
#[derive(Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
struct Document<'a> {
    #[serde(default)]
    generator: String,
    format_version: u32,
    title: Cow<'a, str>,
    components: Keyed<'a, Component>,
    data_types: Keyed<'a, DataType>,
    interfaces: Keyed<'a, InterfaceType>,
    categories: Keyed<'a, Facet>,
    vendors: Keyed<'a, Facet>,
    pages: Vec<PageEntry>,
    diagnostics: Cow<'a, [Diagnostic]>,
    #[serde(default, skip_serializing_if = "IdlDoc::is_empty")]
    idl: IdlDoc<'a>,
    /// Each system with its resolved links; read back, the links are made again.
    #[serde(default, skip_serializing_if = "Keyed::is_empty")]
    systems: Keyed<'a, System>,
    /// RTCBuilder backups whose `RTC.xml` is no component of the catalogue (gone, excluded or
    /// unreadable): documents too, so they are kept.
    #[serde(default, skip_serializing_if = "<[_]>::is_empty")]
    backups: Cow<'a, [crate::catalog::backups::Backup]>,
    /// The `[[source]]` repositories read, each pinned at its commit (the entries read from
    /// one carry an `origin`).
    #[serde(default, skip_serializing_if = "<[_]>::is_empty")]
    sources: Cow<'a, [crate::model::SourceInfo]>,
}

/// The IDL files as `catalog.json` has them: each file's definitions and its history
/// ([`Catalog::idl_history`]).
#[derive(Default, Serialize, Deserialize)]
struct IdlDoc<'a> {
    files: Vec<IdlFileDoc<'a>>,
}

#[derive(Serialize, Deserialize)]
struct IdlFileDoc<'a> {
    #[serde(flatten)]
    file: Cow<'a, crate::idl::IdlFile>,
    #[serde(default, skip_serializing_if = "<[_]>::is_empty")]
    history: Cow<'a, [crate::catalog::history::Entry]>,
}

impl IdlDoc<'_> {
    fn is_empty(&self) -> bool {
        self.files.is_empty()
    }
}

fn idl_doc(catalog: &Catalog) -> IdlDoc<'_> {
    IdlDoc {
        files: catalog
            .idl
            .files
            .iter()
            .map(|file| IdlFileDoc {
                file: Cow::Borrowed(file),
                history: Cow::Borrowed(
                    catalog
                        .idl_history
                        .get(&file.path)
                        .map_or(&[], Vec::as_slice),
                ),
            })
            .collect(),
    }
}

fn document<'a>(
    catalog: &'a Catalog,
    title: &'a str,
    components: &'a [Component],
    systems: &'a [System],
) -> Document<'a> {
    Document {
        generator: super::generator(),
        format_version: FORMAT_VERSION,
        title: Cow::Borrowed(title),
        components: Keyed(Cow::Borrowed(components)),
        data_types: Keyed(Cow::Borrowed(&catalog.data_types)),
        interfaces: Keyed(Cow::Borrowed(&catalog.interfaces)),
        categories: Keyed(Cow::Borrowed(&catalog.categories)),
        vendors: Keyed(Cow::Borrowed(&catalog.vendors)),
        pages: page_entries(catalog),
        diagnostics: Cow::Borrowed(&catalog.diagnostics),
        idl: idl_doc(catalog),
        systems: Keyed(Cow::Borrowed(systems)),
        backups: Cow::Borrowed(&catalog.detached_backups),
        sources: Cow::Borrowed(&catalog.sources),
    }
}

/// Where the components go in the pretty-printed skeleton (top-level keys are indented by two
/// spaces; a string value cannot hold a raw newline or quote, so only the key matches).
const COMPONENTS_KEY: &[u8] = b"\n  \"components\": {}";

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
    let redacted: Vec<System>;
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
    // The document without its components is written as serde_json makes it (not held whole:
    // at 10,000 components its diagnostics and type uses are tens of megabytes); the components
    // go where its empty `components` object opens.
    let mut splice = Splice {
        out: w,
        head: Vec::new(),
        spliced: false,
        catalog,
    };
    serde_json::to_writer_pretty(&mut splice, &document(catalog, title, &[], systems))?;
    if !splice.spliced {
        anyhow::bail!("internal error: no components key in catalog.json");
    }
    w.write_all(b"\n")?;
    Ok(())
}

/// The components of `catalog.json`, each the value of its id's entry as the pretty printer
/// writes it four spaces deep, from the line break after the object's `{` to the one before its
/// `}`. Chunks of components are serialized in parallel, so that a 10,000-component catalogue
/// is never in memory as JSON all at once.
fn write_components(catalog: &Catalog, w: &mut dyn std::io::Write) -> anyhow::Result<()> {
    use rayon::prelude::*;
    if catalog.components.is_empty() {
        return Ok(());
    }
    let mut separator: &[u8] = b"\n";
    for chunk in catalog.components.chunks(64) {
        let parts = chunk
            .par_iter()
            .map(|c| {
                let mut buf = Vec::with_capacity(16 * 1024);
                buf.extend_from_slice(b"    ");
                serde_json::to_writer(&mut buf, &*c.id)?;
                buf.extend_from_slice(b": ");
                let mut value = Vec::with_capacity(16 * 1024);
                serde_json::to_writer_pretty(&mut value, c)?;
                indent_into(&mut buf, &value);
                Ok(buf)
            })
            .collect::<serde_json::Result<Vec<Vec<u8>>>>()?;
        for part in &parts {
            w.write_all(separator)?;
            w.write_all(part)?;
            separator = b",\n";
        }
    }
    w.write_all(b"\n  ")?;
    Ok(())
}

/// A writer that passes the pretty-printed document through to `out`, holding back only its
/// head until [`COMPONENTS_KEY`] has passed, and writes the components of `catalog` between
/// that key's `{` and `}` ([`write_components`]).
struct Splice<'w, 'c> {
    out: &'w mut dyn std::io::Write,
    /// What came before the key was found (the generator, format version and title).
    head: Vec<u8>,
    spliced: bool,
    catalog: &'c Catalog,
}

impl std::io::Write for Splice<'_, '_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.spliced {
            return self.out.write(buf);
        }
        self.head.extend_from_slice(buf);
        if let Some(at) = memchr::memmem::find(&self.head, COMPONENTS_KEY) {
            let open = at + COMPONENTS_KEY.len() - 1; // the `}` of `{}`
            self.out.write_all(&self.head[..open])?;
            write_components(self.catalog, &mut *self.out).map_err(std::io::Error::other)?;
            self.out.write_all(&self.head[open..])?;
            self.head = Vec::new();
            self.spliced = true;
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.out.flush()
    }
}

/// Appends a component's pretty JSON as the value of a top-level object entry: every line
/// after the first four spaces deeper (JSON text has raw line breaks only between tokens).
fn indent_into(out: &mut Vec<u8>, json: &[u8]) {
    const INDENT: &[u8] = b"    ";
    let mut start = 0;
    for nl in memchr::memchr_iter(b'\n', json) {
        out.extend_from_slice(&json[start..=nl]);
        out.extend_from_slice(INDENT);
        start = nl + 1;
    }
    out.extend_from_slice(&json[start..]);
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

/// serde_json's message without the position it appends (the caller puts it in front).
fn json_error(e: &serde_json::Error) -> String {
    let text = e.to_string();
    match text.rfind(" at line ") {
        Some(at) => text[..at].to_string(),
        None => text,
    }
}

/// A catalogue read back from `catalog.json`, with the title it was written with.
pub struct ReadCatalog {
    pub catalog: Catalog,
    pub title: String,
}

/// Reads a `catalog.json` written by rtcdoc (format 2). `name` is the file as shown in errors.
/// A document of another format version, or one whose entries disagree with their keys or
/// pages, is an error saying so.
pub fn read_catalog(bytes: &[u8], name: &str) -> anyhow::Result<ReadCatalog> {
    #[derive(Deserialize)]
    #[serde(rename_all = "camelCase")]
    struct Probe {
        format_version: Option<u32>,
        generator: Option<String>,
    }
    let probe: Probe = serde_json::from_slice(bytes).map_err(|e| {
        anyhow::anyhow!(
            "{name}:{}:{}: not a catalog.json written by rtcdoc: {}",
            e.line(),
            e.column(),
            json_error(&e)
        )
    })?;
    match probe.format_version {
        Some(FORMAT_VERSION) => {}
        Some(v) => anyhow::bail!(
            "{name}: catalog.json format {v} (written by {}); this rtcdoc reads format {FORMAT_VERSION}: build the catalogue again with this rtcdoc",
            probe.generator.as_deref().unwrap_or("an unknown generator")
        ),
        None => anyhow::bail!("{name}: no `formatVersion`: not a catalog.json written by rtcdoc"),
    }
    let doc: Document = serde_json::from_slice(bytes)
        .map_err(|e| anyhow::anyhow!("{name}:{}:{}: {}", e.line(), e.column(), json_error(&e)))?;
    let mut idl_files = Vec::with_capacity(doc.idl.files.len());
    let mut idl_history = std::collections::BTreeMap::new();
    for f in doc.idl.files {
        let file = f.file.into_owned();
        if !f.history.is_empty() {
            idl_history.insert(file.path.clone(), f.history.into_owned());
        }
        idl_files.push(file);
    }
    let mut entries = Catalog::default();
    entries.components = doc.components.0.into_owned();
    entries.data_types = doc.data_types.0.into_owned();
    entries.interfaces = doc.interfaces.0.into_owned();
    entries.categories = doc.categories.0.into_owned();
    entries.vendors = doc.vendors.0.into_owned();
    entries.diagnostics = doc.diagnostics.into_owned();
    entries.idl = IdlSet::from_files(idl_files);
    let mut entries = entries.with_lookups();
    // The systems' links are made again; their histories are kept as read. Binding makes the
    // page list, system pages included.
    entries.attach_systems(
        doc.systems
            .0
            .into_owned()
            .into_iter()
            .map(Into::into)
            .collect(),
    );
    let mut catalog = entries
        .bound()
        .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
    catalog.idl_history = idl_history;
    // The IDL files' history pages come with their histories.
    catalog.index_history_pages();
    catalog.detached_backups = doc.backups.into_owned();
    catalog.set_origins(doc.sources.into_owned());
    if page_entries(&catalog) != doc.pages {
        anyhow::bail!("{name}: the `pages` list does not match the entries' slugs: the file was edited; build it again");
    }
    Ok(ReadCatalog {
        catalog,
        title: doc.title.into_owned(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::{load, LoadOptions};
    use crate::catalog::LoadedProfile;

    fn reference(catalog: &Catalog, title: &str) -> Vec<u8> {
        let mut out = serde_json::to_vec_pretty(&document(
            catalog,
            title,
            &catalog.components,
            &catalog.systems,
        ))
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
            for title in ["Catalogue", "\n  \"components\": {}"] {
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

    /// Inputs with profiles, IDL and diagnostics: the examples, every fixture folder, the
    /// corpus when present.
    fn inputs() -> Vec<std::path::PathBuf> {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let mut inputs = vec![root.join("examples"), root.join("../shared/corpus")];
        for e in std::fs::read_dir(root.join("tests/fixtures")).unwrap() {
            inputs.push(e.unwrap().path());
        }
        inputs.retain(|p| p.is_dir());
        inputs
    }

    /// catalog.json read back is the same catalogue: written again, it is the same bytes; the
    /// references resolve to the same ports; the pages are the same.
    #[test]
    fn round_trip_gives_the_same_document() {
        let mut read = 0;
        for input in inputs() {
            let opts = LoadOptions {
                allow_empty: true,
                ..Default::default()
            };
            let catalog = load(&input, &opts).unwrap().catalog;
            let first = written(&catalog, "Round trip");
            let back = read_catalog(&first, "catalog.json")
                .unwrap_or_else(|e| panic!("{}: {e:#}", input.display()));
            assert_eq!(back.title, "Round trip");
            let second = written(&back.catalog, &back.title);
            assert!(
                first == second,
                "{} differs after a round trip",
                input.display()
            );
            assert_eq!(back.catalog.pages(), catalog.pages());
            for t in &catalog.data_types {
                for r in t.uses.producers.iter().chain(&t.uses.consumers) {
                    assert_eq!(back.catalog.resolve_port(r), catalog.resolve_port(r));
                }
            }
            assert_eq!(back.catalog.idl.files.len(), catalog.idl.files.len());
            read += catalog.components.len();
        }
        assert!(read > 20, "{read}");
    }

    /// References are ids: a port is its component's id and its name.
    #[test]
    fn references_are_ids_not_positions() {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let catalog = load(&root.join("examples"), &LoadOptions::default())
            .unwrap()
            .catalog;
        let json: serde_json::Value = serde_json::from_slice(&written(&catalog, "t")).unwrap();
        assert_eq!(json["formatVersion"], 3);
        let types = json["dataTypes"].as_object().unwrap();
        let (name, t) = types
            .iter()
            .find(|(_, t)| t["producers"].as_array().is_some_and(|p| !p.is_empty()))
            .unwrap();
        assert_eq!(t["name"], name.as_str());
        let r = &t["producers"][0];
        let id = r["component"].as_str().unwrap();
        assert!(id.starts_with("RTC:"), "{id}");
        let component = &json["components"][id];
        let ports = component["dataPorts"].as_array().unwrap();
        assert!(ports.iter().any(|p| p["name"] == r["port"]), "{r}");
        let pages = json["pages"].as_array().unwrap();
        assert!(pages
            .iter()
            .any(|p| p["kind"] == "component" && p["id"] == id));
    }

    /// Other versions and edited files are refused with a message saying what to do.
    #[test]
    fn other_versions_and_edited_files_are_refused() {
        let v1 = br#"{"generator": "rtcdoc 0.1.0", "formatVersion": 1, "components": []}"#;
        let e = read_catalog(v1, "old.json").err().unwrap().to_string();
        assert!(
            e.contains("format 1") && e.contains("build the catalogue again"),
            "{e}"
        );
        let e = read_catalog(b"[1, 2]", "x.json").err().unwrap().to_string();
        assert!(
            e.starts_with("x.json:1:5: not a catalog.json") && !e.contains(" at line"),
            "{e}"
        );
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let catalog = load(&root.join("examples"), &LoadOptions::default())
            .unwrap()
            .catalog;
        let text = String::from_utf8(written(&catalog, "t")).unwrap();
        let r = catalog
            .data_types
            .iter()
            .find_map(|t| t.uses.producers.first())
            .unwrap();
        let edited_error = |from: &str, to: &str| {
            let edited = text.replacen(from, to, 1);
            assert_ne!(edited, text);
            let e = read_catalog(edited.as_bytes(), "e.json").err().unwrap();
            (edited, e.to_string())
        };
        let port = format!("\"port\": \"{}\"", r.port);
        let (_, e) = edited_error(&port, "\"port\": \"no-such-port\"");
        assert!(
            e.contains("no-such-port") && e.contains("does not have"),
            "{e}"
        );
        // A key that is not its entry's: refused where it is, with what to do.
        let t = &catalog.data_types[0].name;
        let (edited, e) = edited_error(&format!("\n    \"{t}\": {{"), "\n    \"Edited::Name\": {");
        // serde reports the position where the entry ends.
        let key_line = edited[..edited.find("Edited::Name").unwrap()]
            .lines()
            .count();
        let at: usize = e
            .strip_prefix("e.json:")
            .and_then(|r| r.split(':').next())
            .and_then(|n| n.parse().ok())
            .unwrap_or(0);
        assert!(
            at >= key_line
                && e.contains(&format!(
                    "data type `Edited::Name` holds the entry of `{t}`: the file was edited; build it again"
                )),
            "{e}"
        );
    }
}
