//! YAML reader for the YAML form of RTC Profiles (spec chapter 3.2, schema chapter 7).

use super::{Limits, Parsed};
use crate::diagnostic::{codes, Diagnostic};

/// True when the bytes look like an YAML document with a top-level `rtcProfile` key.
pub fn is_profile(bytes: &[u8]) -> bool {
    let _ = bytes;
    false
}

/// Reads an RTC Profile from YAML bytes.
pub fn parse(bytes: &[u8], file: &str, limits: &Limits) -> Result<Parsed, Diagnostic> {
    let _ = (bytes, limits);
    Err(Diagnostic::error(
        codes::MALFORMED,
        file,
        "YAML reader not implemented yet",
    ))
}
