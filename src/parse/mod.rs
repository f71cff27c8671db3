//! Readers: bytes of one profile file → [`Profile`] plus diagnostics.
//!
//! One module per input format. Readers never perform I/O; positions are captured here so that
//! later stages can point at the source.

pub mod dialect;
pub mod rts;
mod shrink;
pub mod xml;
pub mod yaml;
mod yaml_fast;

/// Helpers shared by the readers' property tests.
#[cfg(test)]
mod test_support {
    /// Inserts `text` into `s` at `at` (taken modulo the length, moved back to a character
    /// boundary): a mutation of a generated document.
    pub fn insert(s: &mut String, at: usize, text: &str) {
        let mut at = at % (s.len() + 1);
        while !s.is_char_boundary(at) {
            at -= 1;
        }
        s.insert_str(at, text);
    }

    /// What both fast readers are held to: whenever `fast` reads `doc`, or `doc` with each of
    /// `edits` inserted ([`insert`]), `slow` reads the same.
    pub fn fast_agrees(
        doc: &str,
        edits: Vec<(usize, &str)>,
        fast: fn(&str) -> Option<String>,
        slow: fn(&str) -> String,
    ) -> Result<(), proptest::test_runner::TestCaseError> {
        let mut edited = doc.to_string();
        for (at, text) in edits {
            insert(&mut edited, at, text);
        }
        for doc in [doc, &edited] {
            if let Some(v) = fast(doc) {
                proptest::prop_assert_eq!(v, slow(doc), "{:?}", doc);
            }
        }
        Ok(())
    }
}

use crate::diagnostic::Diagnostic;
use crate::model::fields::Fields;
use crate::model::{
    Configuration, ConfigurationDoc, Constraint, DataPort, DataPortDoc, Extras, Profile, Property,
    ServiceInterface, ServiceInterfaceDoc, ServicePort, ServicePortDoc,
};

/// What a configuration, a data port, a service port and a service interface hold beside their
/// scalars, as both component readers fill it: properties, a doc node and (a configuration, a
/// data port) a constraint.
pub(crate) trait Documented: Fields + Default {
    type Doc: Fields + Default;
    /// The node's name in [`Profile::written_as`] (`dataPort`).
    const LABEL: &'static str;
    fn parts(&mut self) -> DocParts<'_, Self::Doc>;

    /// `"{LABEL} {name}"`: the node as [`crate::model::Profile::written_as`] names it.
    fn written_as_node(&self) -> String {
        let name = Self::NODE
            .json_field("name")
            .and_then(|f| self.value(f)?.as_deref());
        format!("{} {}", Self::LABEL, name.unwrap_or(""))
    }
}

/// The parts of a [`Documented`] node.
pub(crate) struct DocParts<'a, D> {
    pub properties: &'a mut Vec<Property>,
    pub doc: &'a mut Option<D>,
    /// `None` on a node that has no constraint.
    pub constraint: Option<&'a mut Option<Constraint>>,
    pub extra: &'a mut Extras,
}

/// `Node: Doc, "label"` (`, constraint` when the node has one): its [`Documented`] impl.
macro_rules! documented {
    (@constraint $node:ident) => { None };
    (@constraint $node:ident $field:ident) => { Some(&mut $node.$field) };
    ($($node:ident: $doc:ident, $label:literal $(, $constraint:ident)?;)*) => {$(
        impl Documented for $node {
            type Doc = $doc;
            const LABEL: &'static str = $label;
            fn parts(&mut self) -> DocParts<'_, $doc> {
                DocParts {
                    properties: &mut self.properties,
                    doc: &mut self.doc,
                    constraint: documented!(@constraint self $($constraint)?),
                    extra: &mut self.extra,
                }
            }
        }
    )*};
}

documented! {
    Configuration: ConfigurationDoc, "configuration", constraint;
    DataPort: DataPortDoc, "dataPort", constraint;
    ServicePort: ServicePortDoc, "servicePort";
    ServiceInterface: ServiceInterfaceDoc, "serviceInterface";
}

/// The XML and the YAML reader of one kind of profile ([`Limits::read`]), each given the bytes,
/// the file name used in diagnostics and the limits.
type Readers<T> = [fn(&[u8], &str, &Limits) -> Result<T, Diagnostic>; 2];

/// Limits that protect against hostile input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Largest file accepted, in bytes (default 16 MiB).
    pub max_file_size: u64,
    /// Deepest element / collection nesting accepted (default 64).
    pub max_depth: usize,
}

impl Limits {
    /// `bytes` read by the reader of `format` among `readers` (XML, YAML) once they pass
    /// [`Limits::check_size`]: how the component and the system profile readers ([`parse`],
    /// [`rts::parse`]) both start.
    fn read<T>(
        &self,
        format: SourceFormat,
        bytes: &[u8],
        file: &str,
        [xml, yaml]: Readers<T>,
    ) -> Result<T, Diagnostic> {
        self.check_size(bytes, file)?;
        match format {
            SourceFormat::Xml => xml(bytes, file, self),
            SourceFormat::Yaml => yaml(bytes, file, self),
        }
    }

    /// `RTC002` when `bytes` are more than [`Limits::max_file_size`]: every reader checks this
    /// before it decodes anything.
    pub fn check_size(&self, bytes: &[u8], file: &str) -> Result<(), Diagnostic> {
        if bytes.len() as u64 <= self.max_file_size {
            return Ok(());
        }
        Err(Diagnostic::error(
            crate::diagnostic::codes::TOO_LARGE,
            file,
            // Files are read to one byte past the limit: the size beyond it is not known.
            format!(
                "file is larger than the limit of {} bytes; it is not read",
                self.max_file_size
            ),
        )
        .with_hint(
            "if the file is genuine, raise `max-file-size` in rtcdoc.toml or pass --max-file-size BYTES",
        ))
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_file_size: 16 * 1024 * 1024,
            max_depth: 64,
        }
    }
}

/// The input format of a profile file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SourceFormat {
    Xml,
    Yaml,
}

/// A successfully read profile and the warnings met while reading it.
#[derive(Debug, Clone)]
pub struct Parsed {
    pub profile: Profile,
    /// Warnings (unknown values kept as extras, dialect notes). Never errors.
    pub diagnostics: Vec<Diagnostic>,
}

impl Parsed {
    /// A profile as a reader leaves it: the values it read under older spellings go into
    /// [`Profile::written_as`], and its empty unknown `what`s (`attribute`, `key`) into one
    /// summary note after its warnings.
    fn read(
        mut profile: Profile,
        written_as: Vec<crate::model::WrittenAs>,
        empties: &dialect::EmptyUnknowns,
        what: &str,
        file: &str,
        mut diagnostics: Vec<Diagnostic>,
    ) -> Parsed {
        profile.written_as = written_as;
        diagnostics.extend(empties.note(file, profile.pos, what));
        Parsed {
            profile,
            diagnostics,
        }
    }
}

/// Reads a profile in `format`. `file` is the name used in diagnostics.
pub fn parse(
    format: SourceFormat,
    bytes: &[u8],
    file: &str,
    limits: &Limits,
) -> Result<Parsed, Diagnostic> {
    let mut parsed = limits.read(format, bytes, file, [xml::parse, yaml::parse])?;
    // The model keeps actions in spec order whatever order the file used (RTCBuilder's YAML
    // sorts keys alphabetically).
    parsed.profile.actions.sort_by_key(|a| a.kind);
    dialect::annotate(&mut parsed.profile);
    shrink::profile(&mut parsed.profile);
    Ok(parsed)
}
