//! The stability mark of each component, data type and interface ([`crate::model::stability`]):
//! read from each component's profile (`rtcdoc.stability` properties), then from
//! `rtcdoc.toml`'s `[stability]` table, which wins. A property whose status is no status, and
//! a `[stability]` key that names nothing of the catalogue, are RTC408 findings.

use super::{Catalog, DataTypeIx, InterfaceIx};
use crate::diagnostic::Diagnostic;
use crate::model::stability::{self, FromProperties, Stability};
use crate::model::Pos;

/// The code of a stability mark that cannot be applied (an unknown status in a profile, a
/// `[stability]` key naming nothing).
pub const MARK_INVALID: &str = "RTC408";

/// The message part of an unknown status: what it is not, the nearest status, the choices.
pub fn unknown_status(written: &str) -> String {
    let near = crate::suggest::typo(written, stability::STATUSES)
        .map(|n| format!(" (did you mean `{n}`?)"))
        .unwrap_or_default();
    format!(
        "`{written}` is no stability status{near}; write \"experimental\", \"stable\" or \"deprecated\""
    )
}

/// `[stability]` of `rtcdoc.toml`, checked (`crate::config`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    /// The file as shown in findings (`rtcdoc.toml`).
    pub file: String,
    /// The marks, in the file's order of keys.
    pub marks: Vec<Mark>,
}

/// One `[stability."KEY"]` table.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// A component id or name, or the scoped name of a data type or interface.
    pub key: String,
    /// Where the key is in the file.
    pub pos: Option<Pos>,
    pub stability: Stability,
}

/// What a key names.
#[derive(Debug, Default)]
struct Named {
    components: Vec<super::ComponentIx>,
    data_type: Option<DataTypeIx>,
    interface: Option<InterfaceIx>,
    /// An IDL definition that no port carries (no page: nothing to mark, but no mistake).
    idl_only: bool,
}

impl Catalog {
    /// Gives each entry its mark: the profile's properties first, then `settings` over them.
    pub fn attach_stability(&mut self, settings: &Settings) {
        for c in &mut self.components {
            match stability::from_properties(&c.profile.basic_info.properties) {
                FromProperties::None => {}
                FromProperties::Marked(s) => c.stability = Some(s),
                FromProperties::Unknown(p, written) => {
                    let message = unknown_status(written);
                    let d = Diagnostic::warning(
                        MARK_INVALID,
                        &c.source,
                        format!("property `{}`: {message}", stability::STATUS_KEY),
                    )
                    .at(p.pos)
                    .with_hint(
                        "write the status as experimental, stable or deprecated (the page shows no stability until then)",
                    );
                    self.diagnostics.push(d);
                }
            }
        }
        for m in &settings.marks {
            let named = self.named_by(&m.key);
            for &ci in &named.components {
                self.components[ci.get()].stability = Some(m.stability.clone());
            }
            if let Some(t) = named.data_type {
                self.data_types[t.get()].stability = Some(m.stability.clone());
            }
            if let Some(i) = named.interface {
                self.interfaces[i.get()].stability = Some(m.stability.clone());
            }
            let nothing = named.components.is_empty()
                && named.data_type.is_none()
                && named.interface.is_none()
                && !named.idl_only;
            if nothing {
                let d = self.unmatched(settings, m);
                self.diagnostics.push(d);
            }
        }
    }

    /// The entries `key` names: components by id (as documented or as written) or name, a data
    /// type or an interface by any spelling.
    fn named_by(&self, key: &str) -> Named {
        let key = key.trim();
        let components = super::Ix::enumerate(&self.components)
            .filter(|(_, c)| {
                c.id.as_str() == key
                    || c.profile.id.as_deref().map(str::trim) == Some(key)
                    || crate::model::non_empty(&c.profile.basic_info.name).map(str::trim)
                        == Some(key)
            })
            .map(|(ci, _)| ci)
            .collect();
        let data_type = self.data_type_index(key);
        let interface = self.interface_index_of(key);
        Named {
            components,
            data_type,
            interface,
            idl_only: self.idl.find(key).is_some(),
        }
    }

    /// The RTC408 finding of a key naming nothing, with the nearest name of the catalogue.
    fn unmatched(&self, settings: &Settings, m: &Mark) -> Diagnostic {
        let names = self
            .components
            .iter()
            .flat_map(|c| [c.id.as_str(), c.profile.name()])
            .chain(self.data_types.iter().map(|t| t.name.as_str()))
            .chain(self.interfaces.iter().map(|t| t.name.as_str()));
        let hint = match crate::suggest::typo(&m.key, names) {
            Some(near) => format!("did you mean `{near}`? A key names a component (its id or name), a data type or a service interface (its scoped name, `RTC::TimedLong`)"),
            None => "name a component (its id or name), a data type or a service interface (its scoped name, `RTC::TimedLong`) of the catalogue, or remove the table".to_string(),
        };
        let d = Diagnostic::warning(
            MARK_INVALID,
            &settings.file,
            format!(
                "[stability] `{}` names no component, data type or interface of the catalogue, so it marks nothing",
                m.key
            ),
        )
        .with_hint(hint);
        match m.pos {
            Some(p) => d.at(p),
            None => d,
        }
    }

    /// The page of what a replacement names, when it is in the catalogue: a component (id or
    /// name), else an interface, else a data type.
    pub fn replacement_page(&self, name: &str) -> Option<&super::Page> {
        let named = self.named_by(name);
        if let Some(&ci) = named.components.first() {
            return Some(self.component_page(ci));
        }
        if let Some(i) = named.interface {
            return Some(self.interface_page(i));
        }
        named.data_type.map(|t| self.data_type_page(t))
    }
}
