//! The reach of a change: the other components of a catalogue that produce, consume, provide
//! or require what the change is to (a data port's type, a service interface's type, an IDL
//! definition). Read by `rtcdoc diff`'s impact (`crate::diff::impact`, on the catalogue of
//! each side) and by the history pages (on the catalogue of the build).
//!
//! A change is to a type when its path names one ([`subject_of`]):
//! - `dataPorts/P` removed (its old value is the type), `dataPorts/P/type` (the type it carried
//!   before: the components wired to that type are the ones it reaches), `dataPorts/P/portType`
//!   and `dataPorts/P/type/…` (inside the type, through the IDL: the port's type);
//! - `servicePorts/P/interfaces/I` removed, `…/I/type` (the interface before), `…/I/direction`
//!   and `…/I/type/…`: the interface's type; `servicePorts/P` (a service port removed): every
//!   interface type of the port the lookup knows;
//! - `idl/NAME[/…]`: the definition `NAME`, and with it the data types containing it and the
//!   interfaces using it (a change inside a nested struct reaches the ports of the struct
//!   holding it).

use super::{Catalog, Component, Role};
use serde::Serialize;
use std::collections::BTreeSet;

/// What a change is to.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum Subject {
    /// A data port's type, by name as the profile spells it.
    DataType(String),
    /// A service interface's type.
    Interface(String),
    /// An IDL definition, by scoped name: a data type, an interface or anything they hold.
    Definition(String),
}

impl Subject {
    /// The type's name, as the change or the profile spells it.
    pub fn name(&self) -> &str {
        match self {
            Subject::DataType(n) | Subject::Interface(n) | Subject::Definition(n) => n,
        }
    }
}

/// A component a change reaches, and how it uses what the change is to.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub struct Reached {
    /// [`Component::id`].
    pub component: String,
    /// `producer`, `consumer`, `provider`, `requirer` or `other`.
    pub role: &'static str,
}

impl Role {
    /// `producer`, `consumer`, `provider`, `requirer`, `other` (the JSON of a reach).
    pub fn name(self) -> &'static str {
        match self {
            Role::Producer => "producer",
            Role::Consumer => "consumer",
            Role::Provider => "provider",
            Role::Requirer => "requirer",
            Role::Other => "other",
        }
    }
}

/// The types of a component's element: `(port, Some(interface))` an interface's type,
/// `(port, None)` a data port's type, else every interface type of service port `port`.
pub type Lookup<'a> = &'a dyn Fn(&str, Option<&str>) -> Vec<Subject>;

/// What the change at `path` (with its `old` and `new` values) is to; `lookup` gives the types
/// of the component's ports. Empty for a change to anything else (an added port, a
/// description, a configuration parameter).
pub fn subject_of(
    path: &str,
    old: Option<&str>,
    new: Option<&str>,
    lookup: Lookup,
) -> Vec<Subject> {
    let p: Vec<&str> = path.split('/').collect();
    let removed = old.is_some() && new.is_none();
    let named = |s: Option<&str>, f: fn(String) -> Subject| -> Vec<Subject> {
        s.map(str::trim)
            .filter(|s| !s.is_empty())
            .map(|s| vec![f(s.to_string())])
            .unwrap_or_default()
    };
    match p.as_slice() {
        ["dataPorts", _] if removed => named(old, Subject::DataType),
        ["dataPorts", _, "type"] => named(old.or(new), Subject::DataType),
        ["dataPorts", port, "portType"] => lookup(port, None),
        ["dataPorts", port, "type", _, ..] => lookup(port, None),
        ["servicePorts", _, "interfaces", _] if removed => named(old, Subject::Interface),
        ["servicePorts", _, "interfaces", _, "type"] => named(old.or(new), Subject::Interface),
        ["servicePorts", port, "interfaces", i, "direction"] => lookup(port, Some(i)),
        ["servicePorts", port, "interfaces", i, "type", _, ..] => lookup(port, Some(i)),
        ["servicePorts", port] if old.is_none() && new.is_none() => {
            let mut all = lookup(port, Some(""));
            all.sort();
            all.dedup();
            all
        }
        ["idl", name, ..] if !name.is_empty() => vec![Subject::Definition(name.to_string())],
        _ => Vec::new(),
    }
}

/// The type subjects of the element at `port` (and `interface`) of `profile` ([`Lookup`];
/// `Some("")` names every interface of the service port).
pub fn profile_lookup(
    profile: &crate::model::Profile,
    port: &str,
    interface: Option<&str>,
) -> Vec<Subject> {
    fn name(n: &Option<crate::model::Text>) -> &str {
        n.as_deref().unwrap_or_default()
    }
    let ty = |t: &Option<crate::model::Text>| {
        t.as_deref()
            .map(str::trim)
            .filter(|t| !t.is_empty())
            .map(str::to_string)
    };
    match interface {
        None => {
            let ports = &profile.data_ports;
            super::member_at(ports.iter().map(|d| name(&d.name)), port)
                .and_then(|i| ty(&ports[i].type_))
                .map(Subject::DataType)
                .into_iter()
                .collect()
        }
        Some(i) => {
            let sps = &profile.service_ports;
            let Some(sp) = super::member_at(sps.iter().map(|s| name(&s.name)), port) else {
                return Vec::new();
            };
            let ifaces = &sps[sp].interfaces;
            let at: Vec<usize> = if i.is_empty() {
                (0..ifaces.len()).collect()
            } else {
                super::member_at(ifaces.iter().map(|x| name(&x.name)), i)
                    .into_iter()
                    .collect()
            };
            at.into_iter()
                .filter_map(|k| ty(&ifaces[k].type_))
                .map(Subject::Interface)
                .collect()
        }
    }
}

impl Catalog {
    /// Whether the catalogue knows `subject` (has a data type or interface entry for it).
    pub fn knows(&self, subject: &Subject) -> bool {
        let n = subject.name();
        match subject {
            Subject::DataType(_) => self.data_type(n).is_some(),
            Subject::Interface(_) => self.interface(n).is_some(),
            Subject::Definition(_) => self.data_type(n).is_some() || self.interface(n).is_some(),
        }
    }

    /// The components that use `subjects`, each with its role, but those `except` names (the
    /// changed component); sorted by id, then role, each pair once.
    pub fn reach(&self, subjects: &[Subject], except: &dyn Fn(&Component) -> bool) -> Vec<Reached> {
        let (mut data, mut ifaces) = (BTreeSet::new(), BTreeSet::new());
        for s in subjects {
            let n = s.name();
            match s {
                Subject::DataType(_) => data.extend(self.data_type_index(n)),
                Subject::Interface(_) => ifaces.extend(self.interface_index_of(n)),
                Subject::Definition(_) => self.enclosing(n, &mut data, &mut ifaces),
            }
        }
        let mut out = BTreeSet::new();
        let mut add = |ci: Option<super::ComponentIx>, role: Role| {
            if let Some(c) = ci.map(|ci| &self[ci]) {
                if !except(c) {
                    out.insert(Reached {
                        component: c.id.as_str().to_string(),
                        role: role.name(),
                    });
                }
            }
        };
        for t in data {
            for (role, refs) in super::Uses::by_role(&self[t].uses) {
                refs.iter().for_each(|r| add(self.port_component(r), role));
            }
        }
        for t in ifaces {
            for (role, refs) in super::Uses::by_role(&self[t].uses) {
                refs.iter()
                    .for_each(|r| add(self.interface_component(r), role));
            }
        }
        out.into_iter().collect()
    }

    /// The data types and interfaces that hold definition `name`: itself, the data types
    /// containing it (transitively) and the interfaces whose operations or attributes use any
    /// of them.
    fn enclosing(
        &self,
        name: &str,
        data: &mut BTreeSet<super::DataTypeIx>,
        ifaces: &mut BTreeSet<super::InterfaceIx>,
    ) {
        let mut stack = vec![name.to_string()];
        let mut seen = BTreeSet::new();
        while let Some(n) = stack.pop() {
            if !seen.insert(n.clone()) {
                continue;
            }
            if let Some(ii) = self.interface_index_of(&n) {
                ifaces.insert(ii);
            }
            if let Some(ti) = self.data_type_index(&n) {
                data.insert(ti);
                let t = &self[ti];
                stack.extend(t.contained_in.iter().cloned());
                stack.extend(t.used_by.iter().map(|u| u.interface.clone()));
            }
        }
    }
}
