//! XML reader for `RTC.xml` profiles (spec chapter 3.1, XSD chapter 6).
//!
//! Reading happens in three passes, each O(n) in the file size, one file each:
//!
//! 1. `decode.rs`: bytes → text. UTF-8 (with or without BOM) is the default; an encoding named
//!    in the XML declaration (Shift_JIS, EUC-JP, …) is decoded with `encoding_rs`. Invalid bytes
//!    are an error pointing at the first bad byte. Byte offsets → line:column live here too.
//! 2. `tree.rs` (`build_tree`; `fast.rs` is a prefilter for the common shape of file that builds
//!    the same tree, or gives up): text → a small element tree with namespaces resolved *by URI*
//!    and every element and attribute carrying its line:column. Hostile input (entity
//!    declarations, undefined entities, too deep nesting) is rejected while streaming.
//! 3. `map.rs` (`map_*` functions): tree → [`Profile`]. Whatever the spec does not define for a
//!    node is kept in that node's `extra` list and reported as a warning, so nothing in a
//!    profile is lost. `rts.rs` maps RT System profiles on the same decoder and tree.

use super::{Limits, Parsed};
use crate::diagnostic::{codes, Diagnostic};
use crate::model::*;
use quick_xml::events::Event as XmlEvent;
use quick_xml::name::ResolveResult;
use quick_xml::reader::{NsReader, Reader};
use std::borrow::Cow;

/// Namespace URI of the basic profile (XSD 6.1).
pub const NS_RTC: &str = "http://www.openrtp.org/namespaces/rtc";
/// Namespace URI of the document profile (XSD 6.2).
pub const NS_RTC_DOC: &str = "http://www.openrtp.org/namespaces/rtc_doc";
/// Namespace URI of the extended profile (XSD 6.3).
pub const NS_RTC_EXT: &str = "http://www.openrtp.org/namespaces/rtc_ext";
/// XML Schema instance namespace (`xsi:type`).
pub const NS_XSI: &str = "http://www.w3.org/2001/XMLSchema-instance";

/// Hard cap on nesting, whatever `Limits::max_depth` says: the mapping pass recurses over the
/// tree, and this keeps the stack bounded.
pub(super) const HARD_MAX_DEPTH: usize = 1024;

/// True when the bytes look like an XML document whose root element is `RtcProfile`.
///
/// Skips a BOM, the XML declaration, comments, processing instructions and a DOCTYPE, then
/// looks at the local name of the first element only; `RtsProfile` (system profiles) and
/// anything that is not XML give `false`.
pub fn is_profile(bytes: &[u8]) -> bool {
    matches!(root_element(bytes), Root::Element(name) if name == "RtcProfile")
}

/// What the head of an XML file shows about its root element.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Root {
    /// The local name of the first element (`RtcProfile`, `RtsProfile`, …).
    Element(String),
    /// Only a prolog (declaration, comments, white space): the file ends before its root.
    Truncated,
    /// Not XML: the first thing after the prolog is neither an element nor white space.
    NotXml,
}

/// The root element of an XML document, from its head (UTF-8, UTF-16 with BOM).
pub fn root_element(bytes: &[u8]) -> Root {
    // UTF-16 needs decoding before a byte-oriented look; only the head is needed.
    let utf16 = match bytes {
        [0xFF, 0xFE, ..] => Some(encoding_rs::UTF_16LE),
        [0xFE, 0xFF, ..] => Some(encoding_rs::UTF_16BE),
        _ => None,
    };
    if let Some(enc) = utf16 {
        let head = &bytes[2..bytes.len().min(64 * 1024)];
        let (text, _) = enc.decode_without_bom_handling(head);
        return first_element(text.as_bytes());
    }
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    first_element(bytes)
}

pub(super) fn first_element(bytes: &[u8]) -> Root {
    let mut reader = Reader::from_reader(bytes);
    // A prolog longer than this many events is not something we want to scan.
    for _ in 0..10_000 {
        match reader.read_event() {
            Ok(XmlEvent::Start(e)) | Ok(XmlEvent::Empty(e)) => {
                return Root::Element(
                    String::from_utf8_lossy(e.local_name().as_ref()).into_owned(),
                );
            }
            Ok(XmlEvent::Decl(_))
            | Ok(XmlEvent::Comment(_))
            | Ok(XmlEvent::PI(_))
            | Ok(XmlEvent::DocType(_)) => {}
            Ok(XmlEvent::Text(t)) if t.iter().all(u8::is_ascii_whitespace) => {}
            Ok(XmlEvent::Eof) => return Root::Truncated,
            _ => return Root::NotXml,
        }
    }
    Root::NotXml
}

/// Reads an RTC Profile from XML bytes.
///
/// Errors (never panics) on input that is not well-formed XML, uses a bad encoding, declares
/// entities, references undefined entities, nests deeper than `limits.max_depth`, or whose root
/// element is not `RtcProfile`. Missing elements are not errors: the model has defaults and the
/// `check` stage reports them. Unknown content becomes `extra` entries plus warnings.
pub fn parse(bytes: &[u8], file: &str, limits: &Limits) -> Result<Parsed, Diagnostic> {
    let text = decode(bytes, file)?;
    let root = match fast::build(&text, file, limits.max_depth.min(HARD_MAX_DEPTH)) {
        Some(root) => root,
        None => build_tree(&text, file, limits)?,
    };
    let mut m = Mapper {
        file,
        diags: Vec::new(),
        empties: crate::parse::dialect::EmptyUnknowns::default(),
        written_as: Vec::new(),
    };
    let profile = map_profile(&mut m, &root);
    Ok(Parsed::read(
        profile,
        m.written_as,
        &m.empties,
        "attribute",
        file,
        m.diags,
    ))
}

mod decode;
mod fast;
mod map;
mod tree;
use decode::*;
use map::*;
use tree::*;

/// The mapping of RT System profiles (`RtsProfile`), on this module's decoder and tree.
pub(super) mod rts;

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The streaming cursor gives the positions the index gives, for offsets asked in any
        /// order (mostly increasing, as in the reader, with jumps back and far ahead).
        #[test]
        fn pos_cursor_agrees_with_line_index(
            parts in proptest::collection::vec(
                proptest::sample::select(&["a", "é", "日", "\n", "\r\n", "\r", "  ", "<x>"][..]),
                0..200,
            ),
            offsets in proptest::collection::vec(0usize..1200, 1..60),
            sorted in proptest::bool::ANY,
        ) {
            let text: String = parts.concat();
            let mut offsets = offsets;
            if sorted {
                offsets.sort_unstable();
            }
            let index = LineIndex::new(&text);
            let mut cursor = PosCursor::new(&text);
            for o in offsets {
                proptest::prop_assert_eq!(cursor.pos(o), index.pos(o), "offset {} of {:?}", o, text);
            }
        }
    }

    #[test]
    fn line_index_counts_chars_and_cr() {
        let t = "ab\r\ncé\rx";
        let i = LineIndex::new(t);
        assert_eq!(i.pos(0), Pos::new(1, 1));
        assert_eq!(i.pos(4), Pos::new(2, 1));
        assert_eq!(i.pos(7), Pos::new(2, 3));
        assert_eq!(i.pos(8), Pos::new(3, 1));
    }

    #[test]
    fn attr_unescape_normalises() {
        assert_eq!(
            unescape_attr("a\r\nb\tc&#10;&lt;".into()).unwrap(),
            "a b c\n<"
        );
        assert!(matches!(
            unescape_attr("plain".into()),
            Ok(Cow::Borrowed("plain"))
        ));
        assert!(unescape_attr("&foo;".into()).is_err());
    }

    #[test]
    fn declared_encoding_found() {
        let (l, at) = declared_encoding(b"<?xml version='1.0' encoding = \"Shift_JIS\"?>").unwrap();
        assert_eq!(l, "Shift_JIS");
        assert_eq!(at, 32);
    }
}
