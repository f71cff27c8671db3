//! RT System profiles of the two sides, and the connectors of theirs that a change breaks.
//!
//! The systems of a side are the `RtsProfile` files the walk found below it (the component
//! walk skips them as "not a component profile"; they are read here with
//! [`crate::parse::rts::parse`]). Systems themselves are not compared: a connector is reported
//! (DIFF14x) when one of its ends is a component that was removed, or a port of a matched
//! component that was removed or changed in a breaking way. NEW's systems are checked, and
//! OLD's systems that NEW does not have (by id, else by file), so a system kept only on the
//! old side is not forgotten; a system NEW updated is judged as NEW has it.

use super::{codes, Change, Key, Level, Namer};
use crate::diagnostic::Diagnostic;
use crate::model::non_empty;
use crate::model::system::{short_port_name, ComponentIdParts, PortEnd, RtSystem};
use std::collections::{BTreeMap, BTreeSet};

/// One system profile of a side.
#[derive(Debug, Clone)]
pub struct LoadedSystem {
    /// Relative to the side's input, like a component's `source`.
    pub source: String,
    pub system: RtSystem,
}

/// The system profiles of a side, and those that could not be read.
#[derive(Debug, Clone, Default)]
pub struct Systems {
    pub systems: Vec<LoadedSystem>,
    pub unreadable: Vec<Diagnostic>,
}

/// What the comparison broke, by component and port: filled while components are compared.
#[derive(Debug, Default)]
pub(super) struct Breaks {
    /// Removed components: key → label.
    removed: BTreeMap<Key, String>,
    /// (component key, port name) → the component's label, whether the port was removed, and
    /// the breaking changes of the port (``CODE `path` ``).
    ports: BTreeMap<(Key, String), (String, bool, Vec<String>)>,
}

impl Breaks {
    pub(super) fn note_removed(&mut self, key: &Key, label: &str) {
        self.removed.insert(key.clone(), label.to_string());
    }

    /// Takes the breaking changes of a matched component under `dataPorts/<port>` and
    /// `servicePorts/<port>`.
    pub(super) fn note_ports(&mut self, key: &Key, label: &str, changes: &[Change]) {
        for c in changes.iter().filter(|c| c.severity == Level::Breaking) {
            let mut parts = c.path.splitn(3, '/');
            let (Some(list), Some(port)) = (parts.next(), parts.next()) else {
                continue;
            };
            if !matches!(list, "dataPorts" | "servicePorts") {
                continue;
            }
            let removed = matches!(
                c.code,
                codes::DATA_PORT_REMOVED | codes::SERVICE_PORT_REMOVED
            );
            let entry = self
                .ports
                .entry((key.clone(), port.to_string()))
                .or_insert_with(|| (label.to_string(), false, Vec::new()));
            entry.1 |= removed;
            let reason = format!("{} `{}`", c.code, c.path);
            if !entry.2.contains(&reason) {
                entry.2.push(reason);
            }
        }
    }

    /// The DIFF14x changes of the connectors of both sides' systems.
    pub(super) fn connectors(
        &self,
        old: &[LoadedSystem],
        new: &[LoadedSystem],
        old_name: Namer,
        new_name: Namer,
        out: &mut Vec<Change>,
    ) {
        if self.removed.is_empty() && self.ports.is_empty() {
            return;
        }
        let ident = |s: &LoadedSystem| -> String {
            non_empty(&s.system.id)
                .map(str::to_string)
                .unwrap_or_else(|| format!("file:{}", s.source))
        };
        let new_ids: BTreeSet<String> = new.iter().map(ident).collect();
        let checked = new.iter().map(|s| (s, true)).chain(
            old.iter()
                .filter(|s| !new_ids.contains(&ident(s)))
                .map(|s| (s, false)),
        );
        for (s, in_new) in checked {
            let file = if in_new {
                new_name(&s.source)
            } else {
                old_name(&s.source)
            };
            let sys = &s.system;
            let sys_text = match non_empty(&sys.id) {
                Some(id) => format!("system `{id}` ({file})"),
                None => format!("system `{}` ({file})", sys.name()),
            };
            let data = sys.data_port_connectors.iter().map(|c| {
                (
                    non_empty(&c.name).or(non_empty(&c.connector_id)),
                    c.source.as_ref(),
                    c.target.as_ref(),
                    c.pos,
                    "data port connector",
                )
            });
            let service = sys.service_port_connectors.iter().map(|c| {
                (
                    non_empty(&c.name).or(non_empty(&c.connector_id)),
                    c.source.as_ref(),
                    c.target.as_ref(),
                    c.pos,
                    "service port connector",
                )
            });
            for (name, source, target, pos, kind) in data.chain(service) {
                let name = name.unwrap_or("(unnamed)");
                let ends = format!("`{}` → `{}`", end_text(source), end_text(target));
                for end in [source, target].into_iter().flatten() {
                    let Some((key, port)) = end_key(end) else {
                        continue;
                    };
                    let (code, component, why) = if let Some(label) = self.removed.get(&key) {
                        (
                            codes::CONNECTOR_COMPONENT_REMOVED,
                            label.clone(),
                            format!("connects component `{label}`, which was removed"),
                        )
                    } else if let Some((label, removed, reasons)) =
                        self.ports.get(&(key.clone(), port.clone()))
                    {
                        if *removed {
                            (
                                codes::CONNECTOR_PORT_REMOVED,
                                label.clone(),
                                format!("connects port `{port}`, which was removed"),
                            )
                        } else {
                            (
                                codes::CONNECTOR_PORT_CHANGED,
                                label.clone(),
                                format!(
                                    "connects port `{port}`, which changed incompatibly ({})",
                                    reasons.join(", ")
                                ),
                            )
                        }
                    } else {
                        continue;
                    };
                    let mut c = super::change(
                        code,
                        component,
                        format!("connectors/{}/{name}", sys.name()),
                        None,
                        None,
                        format!("{kind} `{name}` ({ends}) of {sys_text} {why}"),
                    );
                    if in_new {
                        c.file = Some(file.clone());
                        c.line = Some(pos.line).filter(|l| *l > 0);
                        c.column = Some(pos.column).filter(|_| pos.line > 0);
                    } else {
                        c.old_file = Some(file.clone());
                    }
                    out.push(c);
                }
            }
        }
    }
}

/// `instance.port` of a connector end, as the system names it.
fn end_text(end: Option<&PortEnd>) -> String {
    let Some(e) = end else {
        return "(none)".into();
    };
    let port = non_empty(&e.port_name).unwrap_or("?");
    match non_empty(&e.instance_name) {
        Some(i) if !port.starts_with(&format!("{i}.")) => format!("{i}.{port}"),
        _ => port.to_string(),
    }
}

/// The component key and the port name of a connector end.
fn end_key(end: &PortEnd) -> Option<(Key, String)> {
    let id = ComponentIdParts::parse(non_empty(&end.component_id)?)?;
    let part = |t: &Option<crate::model::Text>| non_empty(t).unwrap_or("").to_string();
    let key = Key(part(&id.vendor), part(&id.category), part(&id.name));
    let port = non_empty(&end.port_name)?;
    let port = short_port_name(port, non_empty(&end.instance_name)).to_string();
    Some((key, port))
}

/// DIFF002 for the system profiles a side could not read.
pub(super) fn unreadable(side: &str, diags: &[Diagnostic], name: Namer, out: &mut Vec<Change>) {
    for d in diags {
        let mut c = super::change(
            codes::UNREADABLE_PROFILE,
            String::new(),
            String::new(),
            None,
            None,
            format!(
                "{side}: RT System profile {} could not be read ({}[{}]: {}); its connectors are not checked",
                name(&d.file),
                d.severity,
                d.code,
                d.message
            ),
        );
        if side == "NEW" {
            c.file = Some(name(&d.file));
            c.line = d.pos.map(|p| p.line);
            c.column = d.pos.map(|p| p.column);
        } else {
            c.old_file = Some(name(&d.file));
        }
        out.push(c);
    }
}
