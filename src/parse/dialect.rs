//! What the readers share about the writers of profiles other than spec v0.2's RTCBuilder:
//! the first RTCBuilder format (`rtc:version="0.1"`, 2009; OpenRTM-aist still ships such
//! files as `examples/Templates/*.xml`), OpenRTM-aist-Python's rtc-template (YAML), and
//! wasanbon's empty attributes. See `spec/NOTES.md` and `book/src/formats.md`.
//!
//! Each older spelling is read as the field it means and recorded in
//! [`Profile::written_as`], so the JSON still says what the file wrote.

use crate::diagnostic::{codes, Diagnostic};
use crate::model::{IdParts, Pos, Profile, Text, WrittenAs};

pub use crate::model::fields::{RTCBUILDER_01, RTC_TEMPLATE};

/// The language a child element of `<rtc:Language>` names (RTCBuilder 0.1), or the key of
/// the YAML `language` map names (rtc-template: `java: {library: […]}`).
pub fn language_element(local: &str) -> Option<&'static str> {
    match local.to_ascii_lowercase().as_str() {
        "cxx" | "cpp" | "c++" => Some("C++"),
        "python" => Some("Python"),
        "java" => Some("Java"),
        _ => None,
    }
}

/// Empty unknown attributes or keys of one profile: kept as extras, reported once.
#[derive(Debug, Default)]
pub struct EmptyUnknowns {
    count: usize,
    /// Distinct names, in order of first appearance.
    names: Vec<Text>,
}

impl EmptyUnknowns {
    pub fn add(&mut self, name: &str) {
        self.count += 1;
        if !self.names.iter().any(|n| n == name) {
            self.names.push(name.into());
        }
    }

    /// The one summary note of a profile (`None` when there was nothing empty).
    pub fn note(&self, file: &str, pos: Pos, what: &str) -> Option<Diagnostic> {
        if self.count == 0 {
            return None;
        }
        const SHOWN: usize = 6;
        let mut list = self
            .names
            .iter()
            .take(SHOWN)
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", ");
        if self.names.len() > SHOWN {
            list.push_str(&format!(" and {} more", self.names.len() - SHOWN));
        }
        let plural = if self.count == 1 { "" } else { "s" };
        Some(
            Diagnostic::info(
                codes::EMPTY_UNKNOWN,
                file,
                format!(
                    "{} empty {what}{plural} the spec does not define ({list}); kept as extra properties",
                    self.count
                ),
            )
            .at(pos)
            .with_hint("nothing to do: they carry no value (wasanbon writes them); remove them to tidy the profile"),
        )
    }
}

/// Format-independent dialect notes, after either reader: the dotted id and activityType
/// `EVENT_DRIVEN` are kept as written, and noted as read.
pub fn annotate(p: &mut Profile) {
    if let Some(id) = p.id.as_deref() {
        if IdParts::parse(id, &p.basic_info).is_some_and(|i| i.dotted) {
            let pos = p.attr_pos.or("id", p.pos);
            p.written_as.push(WrittenAs {
                field: "id".into(),
                written_as: "RTC:<vendor>.<category>.<name>:<version>".into(),
                dialect: RTCBUILDER_01,
                pos,
            });
        }
    }
    if p.basic_info
        .activity_type
        .as_deref()
        .is_some_and(|a| a.trim() == "EVENT_DRIVEN")
    {
        let pos = p.basic_info.attr_pos.or("activityType", p.basic_info.pos);
        p.written_as.push(WrittenAs {
            field: "basicInfo.activityType".into(),
            written_as: "EVENT_DRIVEN".into(),
            dialect: RTCBUILDER_01,
            pos,
        });
    }
}
