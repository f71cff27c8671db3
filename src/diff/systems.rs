//! RT System profiles of the two sides: the systems themselves compared, and the connectors of
//! theirs that a component change breaks.
//!
//! The systems of a side are the `RtsProfile` files the walk found below it (the component
//! walk skips them as "not a component profile"; they are read here with
//! [`crate::parse::rts::parse`]).
//!
//! - [`compare_all`] pairs the systems of the two sides (by the vendor and name of their id,
//!   else by file) and compares each pair with [`compare_systems`] (DIFF15x / DIFF25x /
//!   DIFF35x, see `compare.rs`); a system on one side only is removed or added.
//! - [`Breaks::connectors`] reports a connector (DIFF14x) when one of its ends is a component
//!   that was removed, or a port of a matched component that was removed or changed in a
//!   breaking way. NEW's systems are checked, and OLD's systems that NEW does not have (by id,
//!   else by file), so a system kept only on the old side is not forgotten; a system NEW
//!   updated is judged as NEW has it.

use super::{codes, Change, Key, Level, Namer};
use crate::diagnostic::Diagnostic;
use crate::model::non_empty;
use crate::model::system::{short_port_name, ComponentIdParts, Connector, PortEnd, RtSystem};
use std::collections::{BTreeMap, BTreeSet};

mod compare;
pub use compare::{compare_systems, compare_systems_as, system_label};

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
            let data = sys
                .data_port_connectors
                .iter()
                .map(|c| (c as &dyn Connector, "data port connector"));
            let service = sys
                .service_port_connectors
                .iter()
                .map(|c| (c as &dyn Connector, "service port connector"));
            for (c, kind) in data.chain(service) {
                let name = non_empty(c.name()).or(non_empty(c.connector_id()));
                let name = name.unwrap_or("(unnamed)");
                let ((source, target), pos) = (c.ends(), c.pos());
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
    let words = ("RT System profile ", "its connectors are not checked");
    out.extend(
        diags
            .iter()
            .map(|d| super::unreadable(side, d, name, words)),
    );
}

/// How systems are matched: the vendor and name of the id (the version left out, like a
/// component's), else the id as written, else the file.
fn system_key(s: &LoadedSystem) -> String {
    let parts = s.system.id_parts.as_ref();
    let name = parts.and_then(|p| non_empty(&p.name));
    match (name, non_empty(&s.system.id)) {
        (Some(n), _) => format!(
            "id:{}:{}",
            parts.and_then(|p| non_empty(&p.vendor)).unwrap_or(""),
            n
        ),
        (None, Some(id)) => format!("id:{id}"),
        (None, None) => format!("file:{}", s.source),
    }
}

/// Compares the systems of both sides: each pair with [`compare_systems`], a system of one side
/// only as removed (DIFF151) or added (DIFF351). Several systems with one id (RTSystemEditor's
/// `DefaultSystem`) are paired by identical file path, then by identical values (copies), and
/// when one is left on each side, those two; what is still left on both sides is DIFF003.
/// Systems left unpaired are then paired as renamed (DIFF257) by identical file path, or when
/// each side holds just one system. Returns the counts.
pub(super) fn compare_all(
    old: &[LoadedSystem],
    new: &[LoadedSystem],
    old_name: Namer,
    new_name: Namer,
    out: &mut Vec<Change>,
) -> super::Counts {
    let mut counts = super::Counts {
        old: old.len(),
        new: new.len(),
        ..Default::default()
    };
    let mut groups: BTreeMap<String, (Vec<usize>, Vec<usize>)> = BTreeMap::new();
    for (i, s) in old.iter().enumerate() {
        groups.entry(system_key(s)).or_default().0.push(i);
    }
    for (i, s) in new.iter().enumerate() {
        groups.entry(system_key(s)).or_default().1.push(i);
    }
    // Ids several systems of a side share: their systems are named with their file.
    let shared: std::collections::BTreeSet<&str> = groups
        .iter()
        .filter(|(_, (o, n))| o.len() > 1 || n.len() > 1)
        .map(|(k, _)| k.as_str())
        .collect();
    let label = |s: &LoadedSystem, file: &str| -> String {
        match (
            non_empty(&s.system.id),
            shared.contains(system_key(s).as_str()),
        ) {
            (Some(id), false) => id.to_string(),
            (Some(id), true) => format!("{id} ({file})"),
            (None, _) => format!("(no id: {file})"),
        }
    };
    let (mut pairs, mut removed, mut added) = (Vec::new(), Vec::new(), Vec::new());
    for (olds, news) in groups.values() {
        let (lo, ln) = pair_group(olds.clone(), news.clone(), old, new, &mut pairs);
        if !lo.is_empty() && !ln.is_empty() {
            let files = |v: &[usize], s: &[LoadedSystem], name: Namer| {
                v.iter().map(|&i| name(&s[i].source)).collect()
            };
            let id = non_empty(&new[ln[0]].system.id).unwrap_or("(no id)");
            out.push(super::ambiguous(
                codes::AMBIGUOUS_SYSTEM,
                id,
                [files(&lo, old, old_name), files(&ln, new, new_name)],
                format!(
                    "{} RT System profiles in OLD and {} in NEW have the id `{id}`; they cannot be paired and are not compared (give each system its own id)",
                    lo.len(),
                    ln.len()
                ),
            ));
        } else {
            removed.extend(lo);
            added.extend(ln);
        }
    }
    let renamed = pair_renamed(&mut removed, &mut added, old, new);
    for (o, n, was_renamed) in pairs
        .into_iter()
        .map(|(o, n)| (o, n, false))
        .chain(renamed.into_iter().map(|(o, n)| (o, n, true)))
    {
        counts.matched += 1;
        let (os, ns) = (&old[o], &new[n]);
        let (of, nf) = (old_name(&os.source), new_name(&ns.source));
        let mut found = compare_systems_as(&label(ns, &nf), &os.system, &ns.system);
        if was_renamed {
            // The new id is the rename's, not a change of its own.
            found.retain(|c| !(c.code == codes::SYSTEM_OTHER && c.path == "id"));
            found.push(renamed_change(os, ns, &label(ns, &nf), &of));
        }
        if !found.is_empty() {
            counts.changed += 1;
        }
        out.extend(found.into_iter().map(|mut c| {
            c.file = Some(nf.clone());
            c.old_file = Some(of.clone());
            c
        }));
    }
    for o in removed {
        counts.removed += 1;
        let s = &old[o];
        let file = old_name(&s.source);
        out.push(removed_system(s, label(s, &file), file));
    }
    for n in added {
        counts.added += 1;
        let s = &new[n];
        let file = new_name(&s.source);
        out.push(added_system(s, label(s, &file), file));
    }
    counts
}

/// SYSTEM_REMOVED of system `s` of OLD (`file`), named `label`.
fn removed_system(s: &LoadedSystem, label: String, file: String) -> Change {
    let at = Some(s.system.pos).filter(|p| p.line > 0);
    let mut c = super::change(
        codes::SYSTEM_REMOVED,
        label,
        String::new(),
        non_empty(&s.system.id).map(str::to_string),
        None,
        format!(
            "RT System `{}` ({file}, {} instance(s), {} connector(s)) was removed: it can no longer be restored",
            s.system.name(),
            s.system.components.len(),
            s.system.data_port_connectors.len() + s.system.service_port_connectors.len()
        ),
    );
    c.old_file = Some(file);
    c.old_line = at.map(|p| p.line);
    c.old_column = at.map(|p| p.column);
    c
}

/// SYSTEM_ADDED of system `s` of NEW (`file`), named `label`.
fn added_system(s: &LoadedSystem, label: String, file: String) -> Change {
    let mut c = super::change(
        codes::SYSTEM_ADDED,
        label,
        String::new(),
        None,
        non_empty(&s.system.id).map(str::to_string),
        format!(
            "RT System `{}` ({file}, {} instance(s)) was added",
            s.system.name(),
            s.system.components.len()
        ),
    );
    c.file = Some(file);
    c.line = Some(s.system.pos.line).filter(|l| *l > 0);
    c.column = Some(s.system.pos.column).filter(|_| s.system.pos.line > 0);
    c
}

/// Pairs the systems of one key ([`system_key`]) into `pairs`: one on each side, else by
/// identical file path, then by identical values (copies), then the last one of each side.
/// Returns the systems left on each side.
fn pair_group(
    mut lo: Vec<usize>,
    mut ln: Vec<usize>,
    old: &[LoadedSystem],
    new: &[LoadedSystem],
    pairs: &mut Vec<(usize, usize)>,
) -> (Vec<usize>, Vec<usize>) {
    if lo.len() == 1 && ln.len() == 1 {
        pairs.push((lo[0], ln[0]));
        return (Vec::new(), Vec::new());
    }
    // Same file on both sides: the same system.
    pair_same_file(&mut lo, &mut ln, old, new, pairs);
    // Copies: a system equal to one of the other side (positions aside) is that one.
    if !lo.is_empty() && !ln.is_empty() {
        let mut by_print: BTreeMap<String, Vec<usize>> = BTreeMap::new();
        for &n in ln.iter().rev() {
            by_print
                .entry(compare::fingerprint(&new[n].system))
                .or_default()
                .push(n);
        }
        lo.retain(|&o| {
            match by_print
                .get_mut(&compare::fingerprint(&old[o].system))
                .and_then(Vec::pop)
            {
                Some(n) => {
                    ln.retain(|&x| x != n);
                    pairs.push((o, n));
                    false
                }
                None => true,
            }
        });
    }
    if lo.len() == 1 && ln.len() == 1 {
        pairs.push((lo[0], ln[0]));
        return (Vec::new(), Vec::new());
    }
    (lo, ln)
}

/// Of the systems no system of the other side shares an id with, the pairs that are one
/// system renamed: the same file on both sides, or the one system of each side. They are
/// taken out of `removed` and `added`.
fn pair_renamed(
    removed: &mut Vec<usize>,
    added: &mut Vec<usize>,
    old: &[LoadedSystem],
    new: &[LoadedSystem],
) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    if old.len() == 1 && new.len() == 1 && removed.len() == 1 && added.len() == 1 {
        pairs.push((removed[0], added[0]));
        removed.clear();
        added.clear();
        return pairs;
    }
    pair_same_file(removed, added, old, new, &mut pairs);
    pairs
}

/// Pairs the systems of `lo` and `ln` that are in the same file on both sides, taking them out.
fn pair_same_file(
    lo: &mut Vec<usize>,
    ln: &mut Vec<usize>,
    old: &[LoadedSystem],
    new: &[LoadedSystem],
    pairs: &mut Vec<(usize, usize)>,
) {
    lo.retain(
        |&o| match ln.iter().position(|&n| new[n].source == old[o].source) {
            Some(at) => {
                pairs.push((o, ln.remove(at)));
                false
            }
            None => true,
        },
    );
}

/// DIFF257: the system of `os` is `ns` under another id.
fn renamed_change(os: &LoadedSystem, ns: &LoadedSystem, label: &str, old_file: &str) -> Change {
    let (from, to) = (non_empty(&os.system.id), non_empty(&ns.system.id));
    let mut c = super::change(
        codes::SYSTEM_RENAMED,
        label.to_string(),
        String::new(),
        from.map(str::to_string),
        to.map(str::to_string),
        format!(
            "RT System `{}` ({old_file}) is now `{}`: its id changed from {} to {}; the instances, connectors and configuration are compared as one system",
            os.system.name(),
            ns.system.name(),
            from.map_or("none".to_string(), |i| format!("`{i}`")),
            to.map_or("none".to_string(), |i| format!("`{i}`")),
        ),
    );
    c.line = Some(ns.system.pos.line).filter(|l| *l > 0);
    c.column = Some(ns.system.pos.column).filter(|_| ns.system.pos.line > 0);
    c
}
