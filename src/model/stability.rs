//! Stability marks: a component, a service interface or a data type is `experimental`,
//! `stable` or `deprecated` (with the version it is so since, its replacement and a note).
//!
//! A mark comes from the component's profile (the BasicInfo properties [`STATUS_KEY`],
//! [`SINCE_KEY`], [`REPLACEMENT_KEY`], [`NOTE_KEY`]) or from `rtcdoc.toml`'s `[stability]`
//! table (by component id or name, or by a type's scoped name); the file wins over the
//! profile. The catalogue keeps the mark of each entry (`crate::catalog::stability`).

use super::Property;
use serde::{Deserialize, Serialize};

/// The property of a component's profile giving its status.
pub const STATUS_KEY: &str = "rtcdoc.stability";
/// The property giving the version since which the status holds.
pub const SINCE_KEY: &str = "rtcdoc.stability.since";
/// The property naming what to use instead (a component, an interface or a data type).
pub const REPLACEMENT_KEY: &str = "rtcdoc.stability.replacement";
/// The property with a free note.
pub const NOTE_KEY: &str = "rtcdoc.stability.note";

/// How far an item can be relied on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// May change in any release: `diff` reports its breaking changes as warnings.
    Experimental,
    /// Relied on: its breaking changes are breaking.
    Stable,
    /// To be replaced: `check` warns where it is used (RTC407).
    Deprecated,
}

/// The statuses as written, in order.
pub const STATUSES: [&str; 3] = ["experimental", "stable", "deprecated"];

impl Status {
    /// Reads a status as written (any case, trimmed); `None` for anything else.
    pub fn parse(written: &str) -> Option<Status> {
        match written.trim().to_ascii_lowercase().as_str() {
            "experimental" => Some(Status::Experimental),
            "stable" => Some(Status::Stable),
            "deprecated" => Some(Status::Deprecated),
            _ => None,
        }
    }

    /// The status as written in a profile or `rtcdoc.toml`.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Experimental => "experimental",
            Status::Stable => "stable",
            Status::Deprecated => "deprecated",
        }
    }
}

/// Where a mark was read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Origin {
    /// The component's own profile (its `rtcdoc.stability` properties).
    Profile,
    /// `rtcdoc.toml`'s `[stability]` table.
    Config,
}

/// The stability mark of one entry of the catalogue.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Stability {
    pub status: Status,
    /// The version since which it is so (`2.0`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub since: Option<String>,
    /// What to use instead: a component id or name, an interface or data type name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub replacement: Option<String>,
    /// A free note (why, until when).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// Where the mark was read.
    pub origin: Origin,
}

/// What the stability properties of a component's profile say: its mark, or the property whose
/// status is no status (with the status as written).
pub enum FromProperties<'a> {
    None,
    Marked(Stability),
    Unknown(&'a Property, &'a str),
}

/// The mark the BasicInfo properties `props` give (their first [`STATUS_KEY`]).
pub fn from_properties(props: &[Property]) -> FromProperties<'_> {
    let value = |key: &str| {
        super::property_value(props, key)
            .map(str::trim)
            .filter(|v| !v.is_empty())
            .map(str::to_string)
    };
    let Some(p) = props
        .iter()
        .find(|p| p.name.as_deref().map(str::trim) == Some(STATUS_KEY))
    else {
        return FromProperties::None;
    };
    let written = p.value.as_deref().unwrap_or("");
    match Status::parse(written) {
        Some(status) => FromProperties::Marked(Stability {
            status,
            since: value(SINCE_KEY),
            replacement: value(REPLACEMENT_KEY),
            note: value(NOTE_KEY),
            origin: Origin::Profile,
        }),
        None => FromProperties::Unknown(p, written),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn prop(name: &str, value: &str) -> Property {
        Property {
            name: Some(name.into()),
            value: Some(value.into()),
            ..Property::default()
        }
    }

    #[test]
    fn properties_give_a_mark_or_an_unknown_status() {
        let props = [
            prop(STATUS_KEY, " Deprecated "),
            prop(SINCE_KEY, "2.0"),
            prop(REPLACEMENT_KEY, "NewCamera"),
            prop(NOTE_KEY, ""),
        ];
        let FromProperties::Marked(s) = from_properties(&props) else {
            panic!("no mark")
        };
        assert_eq!(s.status, Status::Deprecated);
        assert_eq!(s.since.as_deref(), Some("2.0"));
        assert_eq!(s.replacement.as_deref(), Some("NewCamera"));
        assert_eq!(s.note, None);
        let props = [prop(STATUS_KEY, "deprecatd")];
        let FromProperties::Unknown(_, written) = from_properties(&props) else {
            panic!("not unknown")
        };
        assert_eq!(written, "deprecatd");
        assert!(matches!(
            from_properties(&[prop("FSM", "YES")]),
            FromProperties::None
        ));
    }
}
