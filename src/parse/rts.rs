//! Readers of RT System profiles: bytes of one `RtsProfile` file (XML from RTSystemEditor, or
//! the YAML form of rtsprofile/rtshell) → [`RtSystem`] plus diagnostics. The counterpart of
//! [`crate::parse::parse`] for component profiles, on the same decoding, tree and limits.

use super::{Limits, SourceFormat};
use crate::diagnostic::Diagnostic;
use crate::model::system::RtSystem;

pub use super::xml::rts::{NS_RTS, NS_RTS_EXT};

/// A successfully read system profile and the warnings met while reading it.
#[derive(Debug, Clone)]
pub struct ParsedSystem {
    pub system: RtSystem,
    /// Warnings (unknown values kept as extras). Never errors.
    pub diagnostics: Vec<Diagnostic>,
}

/// Reads an RT System profile in `format`. `file` is the name used in diagnostics.
///
/// Errors (never panics) as the component readers do: `RTC002` too large, `RTC001` malformed,
/// `RTC003` too deep, `RTC004` entities, `RTC005` encoding, `RTC008` alias bomb, `RTC009` when
/// the root is not `RtsProfile` / `rtsProfile`. Unknown content is kept in `extra` with an
/// `RTC006` warning.
pub fn parse(
    format: SourceFormat,
    bytes: &[u8],
    file: &str,
    limits: &Limits,
) -> Result<ParsedSystem, Diagnostic> {
    let readers = [super::xml::rts::parse, super::yaml::rts::parse];
    let (system, diagnostics) = limits.read(format, bytes, file, readers)?;
    Ok(ParsedSystem {
        system,
        diagnostics,
    })
}

/// True when the bytes look like an RT System profile: an XML document whose root element is
/// `RtsProfile`, or a YAML document with a top-level `rtsProfile` key. Only the head of the file
/// is looked at.
pub fn is_system(bytes: &[u8]) -> bool {
    matches!(super::xml::root_element(bytes), super::xml::Root::Element(n) if n == "RtsProfile")
        || super::yaml::has_root_key(bytes, "rtsProfile")
}
