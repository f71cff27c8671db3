//! The document models: plain data, `Serialize + Deserialize`, no I/O.
//!
//! - [`component`] — an RTC Profile (`RTC.xml` or YAML), re-exported here
//!   (`crate::model::Profile`), with the shared pieces every model uses ([`Pos`], [`Extra`],
//!   [`Text`], [`prose`]);
//! - [`system`] — an RT System profile (`RtsProfile`);
//! - [`fields`] — the field table: every scalar field of the component model with its XML,
//!   YAML and JSON names;
//! - [`idl`] — an IDL file's declarations (re-exported by [`crate::idl`], which reads them).
//!
//! Readers (`crate::parse`, `crate::idl`) fill them; the catalogue, checks, diff and renderers
//! read them.

/// Declares a node of a document model: the struct with the derives and serde attributes every
/// node has (each field defaulted when absent from `catalog.json`, JSON names in camelCase) and,
/// after the fields written, the two every node ends with: `pos`, where its element or key
/// starts, and `extra`, the values the schema does not define (left out of the JSON when empty),
/// both also reachable through [`Located`] for the readers.
macro_rules! node {
    ($(#[$meta:meta])* pub struct $name:ident { $($fields:tt)* }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(default, rename_all = "camelCase")]
        pub struct $name {
            $($fields)*
            pub pos: $crate::model::Pos,
            #[serde(skip_serializing_if = "thin_vec::ThinVec::is_empty")]
            pub extra: $crate::model::Extras,
        }

        impl $crate::model::Located for $name {
            fn pos_mut(&mut self) -> &mut $crate::model::Pos {
                &mut self.pos
            }
            fn extra_mut(&mut self) -> &mut $crate::model::Extras {
                &mut self.extra
            }
        }
    };
}

/// What every node of a document model has, for the readers that fill any node: where its
/// element or key starts, and the values the schema does not define.
pub trait Located {
    fn pos_mut(&mut self) -> &mut Pos;
    fn extra_mut(&mut self) -> &mut Extras;
}

/// The values of a node the schema does not define: almost always none, so a thin vector
/// (one pointer, no allocation when empty) rather than a `Vec`'s three words, on each of the
/// millions of nodes of a 10,000-profile catalogue.
pub type Extras = thin_vec::ThinVec<Extra>;

pub mod component;
pub mod fields;
pub mod idl;
pub mod stability;
pub mod system;

pub use component::*;

/// For `skip_serializing_if`: a flag the JSON leaves out while it is false.
pub(crate) fn is_false(b: &bool) -> bool {
    !*b
}

/// Where a document came from when it was read from a `[[source]]` repository of
/// `rtcdoc.toml` (not from the input directory): the source's name, the commit it is pinned
/// at and the file's path in that repository.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Origin {
    /// The source's `name`.
    pub source: String,
    /// The commit read (40 hex digits).
    pub commit: String,
    /// The file's path in the repository, `/`-separated.
    pub path: String,
}

/// A `[[source]]` repository as a catalogue records it.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct SourceInfo {
    pub name: String,
    /// The repository as `rtcdoc.toml` names it.
    pub git: String,
    /// The branch, tag or commit asked for; `None`: the remote's default branch.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rev: Option<String>,
    /// The commit `rev` was pinned to (`rtcdoc.lock`).
    pub commit: String,
    /// The sub-folder documented (`""`: the whole repository).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub path: String,
    /// The template of a file's URL in the repository (`{commit}`, `{path}`), when known.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source_url: Option<String>,
}

impl SourceInfo {
    /// The origin of a catalogue path (`<name>/<path in the repository>`) of this source.
    pub fn origin_of(&self, rel: &str) -> Option<Origin> {
        let path = rel.strip_prefix(self.name.as_str())?.strip_prefix('/')?;
        Some(Origin {
            source: self.name.clone(),
            commit: self.commit.clone(),
            path: path.to_string(),
        })
    }
}

#[cfg(test)]
mod extras_tests {
    use super::*;

    /// Every node carries its extras; the list is one pointer, with no allocation while empty,
    /// and it is written to JSON and read back like the `Vec` it replaced.
    #[test]
    fn extras_are_one_word_and_round_trip() {
        assert_eq!(std::mem::size_of::<Extras>(), std::mem::size_of::<usize>());
        let mut p = DataPort::default();
        assert!(p.extra.is_empty());
        let json = serde_json::to_string(&p).expect("json");
        assert!(!json.contains("extra"), "{json}");
        p.extra.push(Extra {
            kind: ExtraKind::Attribute,
            name: "rtcExt:foo".into(),
            namespace: None,
            value: Some("1".into()),
            children: Extras::new(),
            pos: Pos::new(3, 4),
        });
        let json = serde_json::to_string(&p).expect("json");
        assert!(
            json.contains(r#""extra":[{"kind":"attribute","name":"rtcExt:foo""#),
            "{json}"
        );
        let back: DataPort = serde_json::from_str(&json).expect("read back");
        assert_eq!(back, p);
    }
}
