//! XML reader for `RTC.xml` profiles (spec chapter 3.1, XSD chapter 6).

use super::{Limits, Parsed};
use crate::diagnostic::{codes, Diagnostic};

/// True when the bytes look like an XML document whose root element is `RtcProfile`.
pub fn is_profile(bytes: &[u8]) -> bool {
    let _ = bytes;
    false
}

/// Reads an RTC Profile from XML bytes.
pub fn parse(bytes: &[u8], file: &str, limits: &Limits) -> Result<Parsed, Diagnostic> {
    let _ = (bytes, limits);
    Err(Diagnostic::error(
        codes::MALFORMED,
        file,
        "XML reader not implemented yet",
    ))
}
