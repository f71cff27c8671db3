//! Two versions of one RT System profile compared: instances, connectors, configuration,
//! execution contexts, and every other value of the file (DIFF15x / DIFF25x / DIFF35x).
//!
//! [`compare_systems`] takes two systems and nothing else (no files, no catalogue), so that
//! `rtcdoc diff` calls it for each pair of systems of its two sides and a history of one system
//! can call it for each pair of its versions. Instances are matched by instance name,
//! configuration sets and execution contexts by id, configuration values and properties by
//! name, connectors by connector id and else by their two ends (instance and port, with or
//! without the `<instance>.` prefix). Positions are not compared, so a file that only changed
//! its attribute order or white space gives no change; host data (IORs, host names, endpoints,
//! naming paths: [`crate::catalog::systems::strip_host_data`]) is not compared either.

use super::end_text;
use crate::diff::{change, codes, labels, quoted, respelled_message, same_type, Change};
use crate::model::system::{
    short_port_name, ComponentIdParts, Connector, DataPortConnector, ExecutionContext, PortEnd,
    RtSystem, ServicePortConnector, SystemComponent, SystemConfigurationSet, SystemProperty,
};
use crate::model::{non_empty, Pos, Text};
use serde::Serialize;
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};

/// The changes from `old` to `new`, each under NEW's system id (see [`system_label`]); the
/// positions are those of the two systems' files (`line`/`column` in NEW, `oldLine`/`oldColumn`
/// for what exists only in OLD); `file` and `oldFile` are left for the caller to fill.
pub fn compare_systems(old: &RtSystem, new: &RtSystem) -> Vec<Change> {
    compare_systems_as(&system_label(new), old, new)
}

/// [`compare_systems`] with the changes under `label` (the `component` of each change).
pub fn compare_systems_as(label: &str, old: &RtSystem, new: &RtSystem) -> Vec<Change> {
    // Host data is not compared: it changes with every save, and it is not published (a
    // catalog.json side has none of it).
    let (old, new) = (&public(old), &public(new));
    let mut cx = Cx {
        label,
        sides: (old, new),
        out: Vec::new(),
    };
    cx.instances(old, new);
    cx.data_connectors(old, new);
    cx.service_connectors(old, new);
    let rest = |s: &RtSystem| {
        without(
            s,
            &[
                "components",
                "dataPortConnectors",
                "servicePortConnectors",
                "idParts",
                // Save stamps: RTSystemEditor rewrites them at every save.
                "creationDate",
                "updateDate",
            ],
        )
    };
    cx.other("", rest(old), rest(new), new.pos);
    crate::diff::sort(&mut cx.out);
    cx.out
}

/// A system's values without positions, derived values and host data, as text: equal for
/// copies of one system (which [`compare_systems`] finds no change between).
pub(super) fn fingerprint(s: &RtSystem) -> String {
    without(&public(s), &[]).to_string()
}

/// A copy of `s` without host data ([`crate::catalog::systems::strip_host_data`]).
fn public(s: &RtSystem) -> RtSystem {
    let mut s = s.clone();
    crate::catalog::systems::strip_host_data(&mut s);
    s
}

/// How changes name a system: its id as written, else `(no id)`.
pub fn system_label(s: &RtSystem) -> String {
    non_empty(&s.id).unwrap_or("(no id)").to_string()
}

/// Where a change is: in NEW, or (for what exists only there) in OLD.
#[derive(Clone, Copy)]
enum At {
    New(Pos),
    Old(Pos),
}

struct Cx<'a> {
    label: &'a str,
    /// The two systems, for what a connector's ports carry.
    sides: (&'a RtSystem, &'a RtSystem),
    out: Vec<Change>,
}

/// `, <type>` for a data connector that records its data type, to follow its ends in a message.
fn type_note(c: &DataPortConnector) -> String {
    non_empty(&c.data_type)
        .map(|t| format!(", {t}"))
        .unwrap_or_default()
}

/// The type system `s` records for the data port at connector end `e` (RTSystemEditor's
/// `dataport.data_type` on the instance's port), when it records one.
fn recorded_type<'s>(s: &'s RtSystem, e: Option<&PortEnd>) -> Option<&'s str> {
    let e = e?;
    let instance = non_empty(&e.instance_name)?;
    s.components
        .iter()
        .find(|c| non_empty(&c.instance_name) == Some(instance))?
        .recorded_data_type(crate::catalog::systems::end_port_name(e))
}

/// Whether connector `c` of system `s` carries the type both its ports carry, as `s` records
/// them; `None` when it records no type for a port.
fn carries_its_ports_type(s: &RtSystem, c: &DataPortConnector) -> Option<bool> {
    let ends = [
        recorded_type(s, c.source.as_ref())?,
        recorded_type(s, c.target.as_ref())?,
    ];
    let t = c.data_type.as_deref();
    Some(ends.iter().all(|p| same_type(t, Some(p))))
}

fn text(s: &Option<Text>) -> Option<String> {
    s.as_deref().map(str::to_string)
}

/// The code and message of a value written another way with the same meaning: `SYSTEM_OTHER`,
/// "{subject} is spelled differently (A → B) but {same}".
fn respelled(
    subject: &str,
    (a, b): (Option<&str>, Option<&str>),
    same: &str,
) -> (&'static str, String) {
    (
        codes::SYSTEM_OTHER,
        respelled_message(subject, &quoted(a), &quoted(b), same),
    )
}

/// Pairs the items of two lists by key: the n-th item of a key in OLD with the n-th of that key
/// in NEW. Items without a key, and those left over, are returned unpaired.
fn pair_by<T>(
    old: &[T],
    new: &[T],
    key: impl Fn(&T) -> Option<String>,
) -> (Vec<(usize, usize)>, Vec<usize>, Vec<usize>) {
    let mut pending: BTreeMap<String, std::collections::VecDeque<usize>> = BTreeMap::new();
    let mut unpaired_new = Vec::new();
    for (i, n) in new.iter().enumerate() {
        match key(n) {
            Some(k) => pending.entry(k).or_default().push_back(i),
            None => unpaired_new.push(i),
        }
    }
    let mut pairs = Vec::new();
    let mut unpaired_old = Vec::new();
    for (i, o) in old.iter().enumerate() {
        match key(o).and_then(|k| pending.get_mut(&k)?.pop_front()) {
            Some(n) => pairs.push((i, n)),
            None => unpaired_old.push(i),
        }
    }
    unpaired_new.extend(pending.into_values().flatten());
    unpaired_new.sort_unstable();
    (pairs, unpaired_old, unpaired_new)
}

/// `v` as JSON without the keys `drop` (and without positions, derived values and host data).
fn without<T: Serialize>(v: &T, drop: &[&str]) -> Value {
    let mut v = serde_json::to_value(v).unwrap_or(Value::Null);
    if let Some(m) = v.as_object_mut() {
        for k in drop {
            m.remove(*k);
        }
    }
    clean(v)
}

/// Positions, values the reader derives from others (`idParts`, `shortName`,
/// `dataTypeScoped`, `pseudo`) and private host data left out.
fn clean(v: Value) -> Value {
    match v {
        Value::Object(m) => Value::Object(
            m.into_iter()
                .filter(|(k, _)| {
                    !matches!(
                        k.as_str(),
                        "pos" | "idParts" | "shortName" | "dataTypeScoped" | "pseudo" | "private"
                    )
                })
                .map(|(k, v)| (k, clean(v)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(
            a.into_iter()
                .filter(|x| x.get("private") != Some(&Value::Bool(true)))
                .map(clean)
                .collect(),
        ),
        other => other,
    }
}

fn leaf_text(v: &Value) -> Option<String> {
    match v {
        Value::Null => None,
        Value::String(s) => Some(s.clone()),
        other => Some(other.to_string()),
    }
}

/// The key field of a list whose items are matched by it, when every item has it.
fn list_key(items: &[Value]) -> Option<&'static str> {
    ["name", "id", "instanceName", "kind"]
        .into_iter()
        .find(|k| {
            !items.is_empty()
                && items
                    .iter()
                    .all(|i| i.get(*k).and_then(Value::as_str).is_some())
        })
}

/// The names of a connector property's kind: the attribute it repeats, and its code.
fn property_class(name: &str) -> (Option<&'static str>, &'static str) {
    let n = name.trim().to_ascii_lowercase();
    match n.as_str() {
        "dataport.data_type" => (Some("dataType"), codes::SYSTEM_CONNECTOR_DATA_TYPE),
        "dataport.interface_type" => (Some("interfaceType"), codes::SYSTEM_CONNECTOR_TRANSPORT),
        "dataport.dataflow_type" => (Some("dataflowType"), codes::SYSTEM_CONNECTOR_TRANSPORT),
        "dataport.subscription_type" => (Some("subscriptionType"), codes::SYSTEM_CONNECTOR_POLICY),
        "dataport.push_rate" | "dataport.push_interval" => (None, codes::SYSTEM_CONNECTOR_POLICY),
        _ if n.starts_with("dataport.publisher.")
            || (n.starts_with("dataport.") && n.contains("buffer")) =>
        {
            (None, codes::SYSTEM_CONNECTOR_POLICY)
        }
        _ => (None, codes::SYSTEM_OTHER),
    }
}

/// The instance and the port's own name of a connector end.
fn end_key(end: Option<&PortEnd>) -> (String, String) {
    let Some(e) = end else {
        return (String::new(), String::new());
    };
    let instance = non_empty(&e.instance_name).unwrap_or("").to_string();
    let port = non_empty(&e.port_name).unwrap_or("");
    let port = short_port_name(port, Some(instance.as_str())).to_string();
    (instance, port)
}

/// The key that pairs connectors by their ends: the two ports in either order (OpenRTM
/// connects the same two ports whichever is listed first; a data connector's direction comes
/// from the ports' types).
fn ends_key(source: Option<&PortEnd>, target: Option<&PortEnd>) -> Option<String> {
    let (a, b) = (end_key(source), end_key(target));
    if a.1.is_empty() && b.1.is_empty() {
        return None;
    }
    let (a, b) = (format!("{}.{}", a.0, a.1), format!("{}.{}", b.0, b.1));
    Some(if a <= b {
        format!("{a} > {b}")
    } else {
        format!("{b} > {a}")
    })
}

/// How a matched connector's ends compare.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum EndsAre {
    Same,
    /// The same two ports, listed the other way round: the same connection.
    Swapped,
    /// Other ports (reported as DIFF155).
    Changed,
}

/// The component key (vendor, category, name; any case and spacing) and version of an id.
fn component_key(id: &str) -> Option<(String, String)> {
    let p = ComponentIdParts::parse(id)?;
    let norm = |t: &Option<Text>| -> String {
        t.as_deref()
            .unwrap_or("")
            .chars()
            .filter(|c| !c.is_whitespace())
            .flat_map(char::to_lowercase)
            .collect()
    };
    Some((
        format!(
            "{}:{}:{}",
            norm(&p.vendor),
            norm(&p.category),
            norm(&p.name)
        ),
        p.version.as_deref().unwrap_or("").trim().to_string(),
    ))
}

/// An execution context kind by meaning: `PERIODIC` = `Periodic` = `PeriodicExecutionContext`.
fn ec_kind(s: &str) -> String {
    let k: String = s
        .trim()
        .chars()
        .filter(|c| *c != '_' && !c.is_whitespace())
        .flat_map(char::to_lowercase)
        .collect();
    k.strip_suffix("executioncontext").unwrap_or(&k).to_string()
}

fn number(s: Option<&str>) -> Option<f64> {
    s?.trim().parse::<f64>().ok()
}

/// Connector labels: name, else connector id, else the two ends; `#n` for repeats.
fn connector_labels<'a>(items: impl Iterator<Item = (Option<&'a str>, String)>) -> Vec<String> {
    let names: Vec<String> = items
        .map(|(n, ends)| n.map(str::to_string).unwrap_or(ends))
        .collect();
    labels(names.iter().map(|s| Some(s.as_str())))
}

impl Cx<'_> {
    fn push(
        &mut self,
        code: &'static str,
        path: String,
        (old, new): (Option<String>, Option<String>),
        message: String,
        at: At,
    ) {
        let mut c = change(code, self.label.to_string(), path, old, new, message);
        match at {
            At::New(p) if p.line > 0 => {
                c.line = Some(p.line);
                c.column = Some(p.column);
            }
            At::Old(p) if p.line > 0 => {
                c.old_line = Some(p.line);
                c.old_column = Some(p.column);
            }
            _ => {}
        }
        self.out.push(c);
    }

    /// `push` for a text value changed from `old` to `new`.
    fn changed(
        &mut self,
        code: &'static str,
        path: String,
        (old, new): (&Option<Text>, &Option<Text>),
        message: String,
        at: At,
    ) {
        self.push(code, path, (text(old), text(new)), message, at);
    }

    /// Every difference between two JSON values, as DIFF355 (or `code_of` a path's own code)
    /// under `path`.
    fn other(&mut self, path: &str, o: Value, n: Value, at: Pos) {
        let mut found = Vec::new();
        diff_values(path, &o, &n, &mut found);
        for (p, a, b) in found {
            let message = match (&a, &b) {
                // The change's path names the value: the message does not say it again.
                (None, Some(v)) => format!("was added ({})", quoted(Some(v))),
                (Some(v), None) => format!("was removed (was {})", quoted(Some(v))),
                _ => crate::word_diff::message(a.as_deref(), b.as_deref()).unwrap_or_else(|| {
                    format!(
                        "changed from {} to {}",
                        quoted(a.as_deref()),
                        quoted(b.as_deref())
                    )
                }),
            };
            self.push(codes::SYSTEM_OTHER, p, (a, b), message, At::New(at));
        }
    }

    fn instances(&mut self, old: &RtSystem, new: &RtSystem) {
        let ol = labels(old.components.iter().map(|c| c.instance_name.as_deref()));
        let nl = labels(new.components.iter().map(|c| c.instance_name.as_deref()));
        let (pairs, removed, added) = pair_by(&ol, &nl, |l: &String| Some(l.clone()));
        for (o, n) in pairs {
            self.instance(&nl[n], &old.components[o], &new.components[n]);
        }
        for o in removed {
            let c = &old.components[o];
            let peers = peers(old, c.instance_name.as_deref().unwrap_or(""));
            let whom = if peers.is_empty() {
                "no connector of the system reaches it, but the system no longer starts it"
                    .to_string()
            } else {
                format!(
                    "the instances connected to it ({}) lose the data and services it exchanged with them, and the system no longer starts it",
                    peers.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", ")
                )
            };
            self.push(
                codes::SYSTEM_INSTANCE_REMOVED,
                format!("components/{}", ol[o]),
                (text(&c.id), None),
                format!(
                    "instance `{}` of component {} was removed: {whom}",
                    ol[o],
                    quoted(non_empty(&c.id))
                ),
                At::Old(c.pos),
            );
        }
        for n in added {
            let c = &new.components[n];
            self.push(
                codes::SYSTEM_INSTANCE_ADDED,
                format!("components/{}", nl[n]),
                (None, text(&c.id)),
                format!(
                    "instance `{}` of component {} was added",
                    nl[n],
                    quoted(non_empty(&c.id))
                ),
                At::New(c.pos),
            );
        }
    }

    fn instance(&mut self, name: &str, o: &SystemComponent, n: &SystemComponent) {
        let base = format!("components/{name}");
        let at = At::New(n.pos);
        // The component it runs.
        let (oid, nid) = (non_empty(&o.id), non_empty(&n.id));
        if oid != nid {
            let (ok, nk) = (oid.and_then(component_key), nid.and_then(component_key));
            let (code, message) = match (&ok, &nk) {
                (Some(a), Some(b)) if a.0 == b.0 && a.1 != b.1 => (
                    codes::SYSTEM_INSTANCE_VERSION,
                    format!(
                        "instance `{name}` now names version `{}` of its component instead of `{}`",
                        b.1, a.1
                    ),
                ),
                (Some(a), Some(b)) if a == b => respelled(
                    &format!("the component id of instance `{name}`"),
                    (oid, nid),
                    "names the same component",
                ),
                _ => (
                    codes::SYSTEM_INSTANCE_COMPONENT,
                    format!(
                        "instance `{name}` now runs component {} instead of {}: its connectors and configuration were saved for the old component's ports and parameters",
                        quoted(nid),
                        quoted(oid)
                    ),
                ),
            };
            self.changed(code, format!("{base}/id"), (&o.id, &n.id), message, at);
        }
        // The active configuration set.
        let (oa, na) = (
            non_empty(&o.active_configuration_set),
            non_empty(&n.active_configuration_set),
        );
        if oa != na {
            self.changed(
                codes::SYSTEM_ACTIVE_CONFIGURATION,
                format!("{base}/activeConfigurationSet"),
                (&o.active_configuration_set, &n.active_configuration_set),
                format!(
                    "instance `{name}` now runs with configuration set {} instead of {}",
                    quoted(na),
                    quoted(oa)
                ),
                at,
            );
        } else if o.active_configuration_set != n.active_configuration_set {
            self.changed(
                codes::SYSTEM_OTHER,
                format!("{base}/activeConfigurationSet"),
                (&o.active_configuration_set, &n.active_configuration_set),
                format!("the active configuration set of `{name}` is spelled differently"),
                at,
            );
        }
        self.configuration(name, o, n);
        self.execution_contexts(name, &o.execution_contexts, &n.execution_contexts, n.pos);
        let rest = |c: &SystemComponent| {
            let mut v = without(
                c,
                &[
                    "id",
                    "instanceName",
                    "activeConfigurationSet",
                    "configurationSets",
                    "executionContexts",
                ],
            );
            // RTSystemEditor's own sets are compared as other values.
            let pseudo: Vec<&SystemConfigurationSet> =
                c.configuration_sets.iter().filter(|s| s.pseudo).collect();
            if let Some(m) = v.as_object_mut() {
                m.insert(
                    "configurationSets".into(),
                    clean(serde_json::to_value(pseudo).unwrap_or(Value::Null)),
                );
            }
            v
        };
        self.other(&base, rest(o), rest(n), n.pos);
    }

    fn configuration(&mut self, name: &str, o: &SystemComponent, n: &SystemComponent) {
        let (os, ns) = (real_sets(o), real_sets(n));
        let active = |c: &SystemComponent, set: &str| {
            if non_empty(&c.active_configuration_set) == Some(set) {
                " (the active set)"
            } else {
                ""
            }
        };
        let (pairs, removed, added) = pair_by(&os, &ns, |(l, _)| Some(l.clone()));
        let base = format!("components/{name}/configurationSets");
        for o_i in removed {
            let (l, s) = &os[o_i];
            self.push(
                codes::SYSTEM_CONFIGURATION,
                format!("{base}/{l}"),
                (Some(l.clone()), None),
                format!(
                    "configuration set `{l}`{} of instance `{name}` ({} value(s)) was removed",
                    active(o, l),
                    s.configuration_data.len()
                ),
                At::Old(s.pos),
            );
        }
        for n_i in added {
            let (l, s) = &ns[n_i];
            self.push(
                codes::SYSTEM_CONFIGURATION,
                format!("{base}/{l}"),
                (None, Some(l.clone())),
                format!(
                    "configuration set `{l}`{} of instance `{name}` ({} value(s)) was added",
                    active(n, l),
                    s.configuration_data.len()
                ),
                At::New(s.pos),
            );
        }
        for (oi, ni) in pairs {
            let ((l, a), (_, b)) = (&os[oi], &ns[ni]);
            let act = active(n, l);
            let ol = labels(a.configuration_data.iter().map(|d| d.name.as_deref()));
            let nl = labels(b.configuration_data.iter().map(|d| d.name.as_deref()));
            let (pairs, removed, added) = pair_by(&ol, &nl, |x: &String| Some(x.clone()));
            for i in removed {
                let d = &a.configuration_data[i];
                self.push(
                    codes::SYSTEM_CONFIGURATION,
                    format!("{base}/{l}/{}", ol[i]),
                    (text(&d.data), None),
                    format!(
                        "the value {} of `{}` in configuration set `{l}`{act} of instance `{name}` was removed (the component's default applies)",
                        quoted(d.data.as_deref()),
                        ol[i]
                    ),
                    At::Old(d.pos),
                );
            }
            for i in added {
                let d = &b.configuration_data[i];
                self.push(
                    codes::SYSTEM_CONFIGURATION,
                    format!("{base}/{l}/{}", nl[i]),
                    (None, text(&d.data)),
                    format!(
                        "`{}` is set to {} in configuration set `{l}`{act} of instance `{name}`",
                        nl[i],
                        quoted(d.data.as_deref())
                    ),
                    At::New(d.pos),
                );
            }
            for (i, j) in pairs {
                let (x, y) = (&a.configuration_data[i], &b.configuration_data[j]);
                let path = format!("{base}/{l}/{}", nl[j]);
                if x.data != y.data {
                    self.changed(
                        codes::SYSTEM_CONFIGURATION,
                        path.clone(),
                        (&x.data, &y.data),
                        format!(
                            "`{}` in configuration set `{l}`{act} of instance `{name}` changed from {} to {}",
                            nl[j],
                            quoted(x.data.as_deref()),
                            quoted(y.data.as_deref())
                        ),
                        At::New(y.pos),
                    );
                }
                self.other(
                    &path,
                    without(x, &["name", "data"]),
                    without(y, &["name", "data"]),
                    y.pos,
                );
            }
            self.other(
                &format!("{base}/{l}"),
                without(a, &["id", "configurationData"]),
                without(b, &["id", "configurationData"]),
                b.pos,
            );
        }
    }

    fn execution_contexts(
        &mut self,
        name: &str,
        old: &[ExecutionContext],
        new: &[ExecutionContext],
        instance_pos: Pos,
    ) {
        let ol = labels(old.iter().map(|e| e.id.as_deref()));
        let nl = labels(new.iter().map(|e| e.id.as_deref()));
        let (pairs, removed, added) = pair_by(&ol, &nl, |x: &String| Some(x.clone()));
        let base = format!("components/{name}/executionContexts");
        let describe = |e: &ExecutionContext| {
            format!(
                "{}{}",
                non_empty(&e.kind).unwrap_or("(no kind)"),
                non_empty(&e.rate)
                    .map(|r| format!(" at {r} Hz"))
                    .unwrap_or_default()
            )
        };
        for i in removed {
            let e = &old[i];
            self.push(
                codes::SYSTEM_EXECUTION_CONTEXT,
                format!("{base}/{}", ol[i]),
                (Some(describe(e)), None),
                format!(
                    "execution context `{}` ({}) of instance `{name}` was removed: the instance is no longer run by it",
                    ol[i],
                    describe(e)
                ),
                At::Old(e.pos),
            );
        }
        for j in added {
            let e = &new[j];
            let at = if e.pos.line > 0 { e.pos } else { instance_pos };
            self.push(
                codes::SYSTEM_EXECUTION_CONTEXT,
                format!("{base}/{}", nl[j]),
                (None, Some(describe(e))),
                format!(
                    "execution context `{}` ({}) of instance `{name}` was added",
                    nl[j],
                    describe(e)
                ),
                At::New(at),
            );
        }
        for (i, j) in pairs {
            let (a, b) = (&old[i], &new[j]);
            let path = format!("{base}/{}", nl[j]);
            let at = At::New(b.pos);
            if a.rate != b.rate {
                let (x, y) = (number(a.rate.as_deref()), number(b.rate.as_deref()));
                let same = matches!((x, y), (Some(x), Some(y)) if x == y);
                let (code, message) = if same {
                    respelled(
                        &format!("the rate of execution context `{}` of `{name}`", nl[j]),
                        (a.rate.as_deref(), b.rate.as_deref()),
                        "is the same rate",
                    )
                } else {
                    (
                        codes::SYSTEM_EXECUTION_RATE,
                        format!(
                            "instance `{name}` now runs at {} Hz instead of {} Hz (execution context `{}`): its consumers see data at another rate",
                            non_empty(&b.rate).unwrap_or("(no rate)"),
                            non_empty(&a.rate).unwrap_or("(no rate)"),
                            nl[j]
                        ),
                    )
                };
                self.changed(
                    code,
                    format!("{path}/rate"),
                    (&a.rate, &b.rate),
                    message,
                    at,
                );
            }
            if a.kind != b.kind {
                let same = ec_kind(a.kind.as_deref().unwrap_or(""))
                    == ec_kind(b.kind.as_deref().unwrap_or(""));
                let (code, message) = if same {
                    respelled(
                        &format!("the kind of execution context `{}` of `{name}`", nl[j]),
                        (a.kind.as_deref(), b.kind.as_deref()),
                        "means the same",
                    )
                } else {
                    (
                        codes::SYSTEM_EXECUTION_CONTEXT,
                        format!(
                            "execution context `{}` of instance `{name}` is now {} instead of {}",
                            nl[j],
                            quoted(b.kind.as_deref()),
                            quoted(a.kind.as_deref())
                        ),
                    )
                };
                self.changed(
                    code,
                    format!("{path}/kind"),
                    (&a.kind, &b.kind),
                    message,
                    at,
                );
            }
            self.other(
                &path,
                without(a, &["id", "rate", "kind"]),
                without(b, &["id", "rate", "kind"]),
                b.pos,
            );
        }
    }

    fn data_connectors(&mut self, old: &RtSystem, new: &RtSystem) {
        self.connectors(
            ("dataPortConnectors", "to"),
            (&old.data_port_connectors, &new.data_port_connectors),
            |label, c, (s, t)| {
                format!(
                    "data port connector `{label}` (`{s}` → `{t}`{}) was removed: `{t}` no longer receives data from `{s}`",
                    type_note(c)
                )
            },
            |label, c, (s, t)| {
                format!(
                    "data port connector `{label}` (`{s}` → `{t}`{}) was added",
                    type_note(c)
                )
            },
            |cx, label, a, b| cx.data_connector(label, a, b),
        );
    }

    /// Pairs the connectors of one list (`key`), reports each one removed and added (the
    /// messages made from its label and ends' text; `join` words its old or new value `A join
    /// B`) and compares each pair with `pair`.
    fn connectors<C: Connector>(
        &mut self,
        (key, join): (&str, &str),
        (o, n): (&[C], &[C]),
        removed: impl Fn(&str, &C, (&str, &str)) -> String,
        added: impl Fn(&str, &C, (&str, &str)) -> String,
        mut pair: impl FnMut(&mut Self, &str, &C, &C),
    ) {
        let ends = |c: &C| {
            let (s, t) = c.ends();
            (end_text(s), end_text(t))
        };
        let (ol, nl, matched) = paired_connectors(o, n);
        for m in matched {
            match m {
                (Some(i), None) => {
                    let (s, t) = ends(&o[i]);
                    self.push(
                        codes::SYSTEM_CONNECTOR_REMOVED,
                        format!("{key}/{}", ol[i]),
                        (Some(format!("{s} {join} {t}")), None),
                        removed(&ol[i], &o[i], (&s, &t)),
                        At::Old(o[i].pos()),
                    );
                }
                (None, Some(j)) => {
                    let (s, t) = ends(&n[j]);
                    self.push(
                        codes::SYSTEM_CONNECTOR_ADDED,
                        format!("{key}/{}", nl[j]),
                        (None, Some(format!("{s} {join} {t}"))),
                        added(&nl[j], &n[j], (&s, &t)),
                        At::New(n[j].pos()),
                    );
                }
                (Some(i), Some(j)) => pair(self, &nl[j], &o[i], &n[j]),
                (None, None) => {}
            }
        }
    }

    fn data_connector(&mut self, label: &str, a: &DataPortConnector, b: &DataPortConnector) {
        let base = format!("dataPortConnectors/{label}");
        let at = At::New(b.pos);
        let ends = self.ends("data port connector", &base, label, a, b);
        let mut reported: BTreeSet<&str> = BTreeSet::new();
        // The data type, by meaning.
        if a.data_type != b.data_type {
            let same = same_type(a.data_type.as_deref(), b.data_type.as_deref());
            let (code, message) = if same {
                respelled(
                    &format!("the data type of connector `{label}`"),
                    (a.data_type.as_deref(), b.data_type.as_deref()),
                    "names the same type",
                )
            } else {
                // To the type both ports carry, from one they did not: a repair.
                let repaired = carries_its_ports_type(self.sides.1, b) == Some(true)
                    && carries_its_ports_type(self.sides.0, a) == Some(false);
                let (code, new_note, old_note) = if repaired {
                    (
                        codes::SYSTEM_CONNECTOR_TYPE_REPAIRED,
                        ", the type its ports carry,",
                        ", which they did not: a repair",
                    )
                } else {
                    (
                        codes::SYSTEM_CONNECTOR_DATA_TYPE,
                        "",
                        ": the ports must carry the new type, or the connection is refused",
                    )
                };
                let message = format!(
                    "data port connector `{label}` (`{}` → `{}`) now carries {}{new_note} instead of {}{old_note}",
                    end_text(b.source.as_ref()),
                    end_text(b.target.as_ref()),
                    quoted(b.data_type.as_deref()),
                    quoted(a.data_type.as_deref())
                );
                (code, message)
            };
            reported.insert("dataType");
            self.changed(
                code,
                format!("{base}/dataType"),
                (&a.data_type, &b.data_type),
                message,
                at,
            );
        }
        for (field, x, y, code, what) in [
            (
                "interfaceType",
                &a.interface_type,
                &b.interface_type,
                codes::SYSTEM_CONNECTOR_TRANSPORT,
                "interface type",
            ),
            (
                "dataflowType",
                &a.dataflow_type,
                &b.dataflow_type,
                codes::SYSTEM_CONNECTOR_TRANSPORT,
                "dataflow type",
            ),
            (
                "subscriptionType",
                &a.subscription_type,
                &b.subscription_type,
                codes::SYSTEM_CONNECTOR_POLICY,
                "subscription type",
            ),
        ] {
            if x == y {
                continue;
            }
            let norm = |s: &Option<Text>| s.as_deref().map(|s| s.trim().to_ascii_lowercase());
            let code = if norm(x) == norm(y) {
                codes::SYSTEM_OTHER
            } else {
                reported.insert(field);
                code
            };
            self.changed(
                code,
                format!("{base}/{field}"),
                (x, y),
                format!(
                    "the {what} of data port connector `{label}` changed from {} to {}",
                    quoted(x.as_deref()),
                    quoted(y.as_deref())
                ),
                at,
            );
        }
        if a.push_interval != b.push_interval {
            let (x, y) = (
                number(a.push_interval.as_deref()),
                number(b.push_interval.as_deref()),
            );
            let code = if matches!((x, y), (Some(x), Some(y)) if x == y) {
                codes::SYSTEM_OTHER
            } else {
                codes::SYSTEM_CONNECTOR_POLICY
            };
            self.changed(
                code,
                format!("{base}/pushInterval"),
                (&a.push_interval, &b.push_interval),
                format!(
                    "the push interval of data port connector `{label}` changed from {} to {}",
                    quoted(a.push_interval.as_deref()),
                    quoted(b.push_interval.as_deref())
                ),
                at,
            );
        }
        self.connector_properties(&base, label, &a.properties, &b.properties, &reported, b.pos);
        let rest = |c: &DataPortConnector| {
            let mut v = without(
                c,
                &[
                    "dataType",
                    "interfaceType",
                    "dataflowType",
                    "subscriptionType",
                    "pushInterval",
                    "properties",
                ],
            );
            strip_ends(&mut v, ends);
            v
        };
        self.other(&base, rest(a), rest(b), b.pos);
    }

    fn service_connectors(&mut self, old: &RtSystem, new: &RtSystem) {
        self.connectors(
            ("servicePortConnectors", "and"),
            (&old.service_port_connectors, &new.service_port_connectors),
            |label, _, (s, t)| {
                format!(
                    "service port connector `{label}` (`{s}` — `{t}`) was removed: the interfaces these ports require from each other lose their provider, and calls through them fail"
                )
            },
            |label, _, (s, t)| format!("service port connector `{label}` (`{s}` — `{t}`) was added"),
            |cx, label, a, b| {
                let base = format!("servicePortConnectors/{label}");
                let changed = cx.ends("service port connector", &base, label, a, b);
                let rest = |c: &ServicePortConnector| {
                    let mut v = without(c, &[]);
                    strip_ends(&mut v, changed);
                    v
                };
                cx.other(&base, rest(a), rest(b), b.pos);
            },
        );
    }

    /// DIFF155 when a matched connector joins other ports; how its ends compare.
    fn ends<C: Connector>(&mut self, kind: &str, base: &str, label: &str, a: &C, b: &C) -> EndsAre {
        let ((os, ot), (ns, nt), at) = (a.ends(), b.ends(), b.pos());
        if end_key(os) == end_key(ns) && end_key(ot) == end_key(nt) {
            return EndsAre::Same;
        }
        if end_key(os) == end_key(nt) && end_key(ot) == end_key(ns) {
            return EndsAre::Swapped;
        }
        let (was, now) = (
            format!("{} to {}", end_text(os), end_text(ot)),
            format!("{} to {}", end_text(ns), end_text(nt)),
        );
        let mut left = Vec::new();
        if end_key(os) != end_key(ns) && end_key(os) != end_key(nt) {
            left.push(end_text(os));
        }
        if end_key(ot) != end_key(nt) && end_key(ot) != end_key(ns) {
            left.push(end_text(ot));
        }
        let left = match left.as_slice() {
            [one] => format!(": `{one}` is no longer connected by it"),
            [one, two] => format!(": `{one}` and `{two}` are no longer connected by it"),
            _ => String::new(),
        };
        self.push(
            codes::SYSTEM_CONNECTOR_ENDS,
            base.to_string(),
            (Some(was.clone()), Some(now.clone())),
            format!(
                "{kind} `{label}` now connects `{}` → `{}` instead of `{}` → `{}`{left}",
                end_text(ns),
                end_text(nt),
                end_text(os),
                end_text(ot),
            ),
            At::New(at),
        );
        EndsAre::Changed
    }

    fn connector_properties(
        &mut self,
        base: &str,
        label: &str,
        old: &[SystemProperty],
        new: &[SystemProperty],
        reported: &BTreeSet<&str>,
        at: Pos,
    ) {
        let public = |v: &[SystemProperty]| -> Vec<(String, SystemProperty)> {
            let kept: Vec<&SystemProperty> = v.iter().filter(|p| !p.private).collect();
            labels(kept.iter().map(|p| p.name.as_deref()))
                .into_iter()
                .zip(kept.into_iter().cloned())
                .collect()
        };
        let (o, n) = (public(old), public(new));
        let (pairs, removed, added) = pair_by(&o, &n, |(l, _)| Some(l.clone()));
        let mut items: Vec<(String, Option<&SystemProperty>, Option<&SystemProperty>)> = Vec::new();
        items.extend(
            pairs
                .into_iter()
                .map(|(i, j)| (n[j].0.clone(), Some(&o[i].1), Some(&n[j].1))),
        );
        items.extend(
            removed
                .into_iter()
                .map(|i| (o[i].0.clone(), Some(&o[i].1), None)),
        );
        items.extend(
            added
                .into_iter()
                .map(|j| (n[j].0.clone(), None, Some(&n[j].1))),
        );
        for (name, x, y) in items {
            let path = format!("{base}/properties/{name}");
            let (xv, yv) = (
                x.and_then(|p| text(&p.value)),
                y.and_then(|p| text(&p.value)),
            );
            if let (Some(x), Some(y)) = (x, y) {
                self.other(
                    &path,
                    without(x, &["name", "value"]),
                    without(y, &["name", "value"]),
                    y.pos,
                );
            }
            if x.is_some() && y.is_some() && xv == yv {
                continue;
            }
            let (attr, mut code) = property_class(&name);
            if attr.is_some_and(|a| reported.contains(a)) {
                // Said with the attribute it repeats.
                continue;
            }
            let same = match code {
                codes::SYSTEM_CONNECTOR_DATA_TYPE => same_type(xv.as_deref(), yv.as_deref()),
                codes::SYSTEM_CONNECTOR_TRANSPORT | codes::SYSTEM_CONNECTOR_POLICY => {
                    xv.as_deref().map(|s| s.trim().to_ascii_lowercase())
                        == yv.as_deref().map(|s| s.trim().to_ascii_lowercase())
                }
                _ => false,
            };
            if same {
                code = codes::SYSTEM_OTHER;
            }
            let message = match (&xv, &yv, x.is_some(), y.is_some()) {
                (_, _, false, true) => format!(
                    "property `{name}` of connector `{label}` was added ({})",
                    quoted(yv.as_deref())
                ),
                (_, _, true, false) => format!(
                    "property `{name}` of connector `{label}` was removed (was {})",
                    quoted(xv.as_deref())
                ),
                _ => format!(
                    "property `{name}` of connector `{label}` changed from {} to {}",
                    quoted(xv.as_deref()),
                    quoted(yv.as_deref())
                ),
            };
            let pos = y.map(|p| p.pos).filter(|p| p.line > 0).unwrap_or(at);
            self.push(code, path, (xv, yv), message, At::New(pos));
        }
    }
}

/// The configuration sets of an instance that are not RTSystemEditor's own, with their labels.
fn real_sets(c: &SystemComponent) -> Vec<(String, &SystemConfigurationSet)> {
    let real: Vec<&SystemConfigurationSet> =
        c.configuration_sets.iter().filter(|s| !s.pseudo).collect();
    labels(real.iter().map(|s| s.id.as_deref()))
        .into_iter()
        .zip(real)
        .collect()
}

/// Removes the instance names (and, when they changed, the ports) from the `source` and
/// `target` ends of a connector's JSON.
fn strip_ends(v: &mut Value, ends: EndsAre) {
    // The same two ports listed the other way round are compared in one order.
    if ends == EndsAre::Swapped {
        if let Some(m) = v.as_object_mut() {
            let key = |e: Option<&Value>| {
                ["instanceName", "portName"].map(|k| {
                    e.and_then(|e| e.get(k))
                        .and_then(Value::as_str)
                        .unwrap_or("")
                        .to_string()
                })
            };
            if key(m.get("source")) > key(m.get("target")) {
                let (s, t) = (m.remove("source"), m.remove("target"));
                if let Some(t) = t {
                    m.insert("source".into(), t);
                }
                if let Some(s) = s {
                    m.insert("target".into(), s);
                }
            }
        }
    }
    // Ends reported as changed are not reported again among the rest.
    let keys: &[&str] = if ends == EndsAre::Changed {
        &["instanceName", "portName", "componentId"]
    } else {
        &["instanceName"]
    };
    for end in ["source", "target"] {
        if let Some(m) = v.get_mut(end).and_then(Value::as_object_mut) {
            for k in keys {
                m.remove(*k);
            }
        }
    }
}

/// The labels of the old and the new connectors (name, else id, else `source > target`) and
/// their pairs ([`match_connectors`]: by id, then by ends).
fn paired_connectors<C: Connector>(old: &[C], new: &[C]) -> (Vec<String>, Vec<String>, Pairs) {
    let label = |v: &[C]| {
        connector_labels(v.iter().map(|c| {
            let (s, t) = c.ends();
            let name = non_empty(c.name()).or(non_empty(c.connector_id()));
            (name, format!("{} > {}", end_text(s), end_text(t)))
        }))
    };
    let matched = match_connectors(
        old,
        new,
        |c| non_empty(c.connector_id()).map(str::to_string),
        |c| {
            let (s, t) = c.ends();
            ends_key(s, t)
        },
    );
    (label(old), label(new), matched)
}

/// Indices of paired items: both, or only the old (removed) or only the new (added) one.
type Pairs = Vec<(Option<usize>, Option<usize>)>;

/// A key that pairs connectors (`None`: the connector has none).
type Key<'k, T> = dyn Fn(&T) -> Option<String> + 'k;

/// Connectors paired by connector id and ends together, then the rest by connector id, then
/// by their ends (RTSystemEditor's copies leave several connectors with one id: the ends tell
/// them apart); in OLD's order, then the added ones in NEW's order.
fn match_connectors<T>(
    old: &[T],
    new: &[T],
    id: impl Fn(&T) -> Option<String>,
    ends: impl Fn(&T) -> Option<String>,
) -> Pairs {
    let both = |c: &T| Some(format!("{}\u{0}{}", id(c)?, ends(c)?));
    let keys: [&Key<'_, T>; 3] = [&both, &id, &ends];
    let mut pairs = Vec::new();
    let (mut ro, mut rn): (Vec<usize>, Vec<usize>) =
        ((0..old.len()).collect(), (0..new.len()).collect());
    for key in keys {
        let old_left: Vec<&T> = ro.iter().map(|&i| &old[i]).collect();
        let new_left: Vec<&T> = rn.iter().map(|&j| &new[j]).collect();
        let (p, ro2, rn2) = pair_by(&old_left, &new_left, |c: &&T| key(c));
        pairs.extend(p.into_iter().map(|(i, j)| (ro[i], rn[j])));
        ro = ro2.into_iter().map(|i| ro[i]).collect();
        rn = rn2.into_iter().map(|j| rn[j]).collect();
    }
    pairs.sort_unstable();
    let mut out: Vec<(Option<usize>, Option<usize>)> =
        pairs.into_iter().map(|(i, j)| (Some(i), Some(j))).collect();
    out.extend(ro.into_iter().map(|i| (Some(i), None)));
    out.extend(rn.into_iter().map(|j| (None, Some(j))));
    out
}

/// The instances connected to `instance` by a connector of `s`, sorted.
fn peers(s: &RtSystem, instance: &str) -> Vec<String> {
    let mut out = BTreeSet::new();
    let ends = s
        .data_port_connectors
        .iter()
        .map(|c| (c.source.as_ref(), c.target.as_ref()))
        .chain(
            s.service_port_connectors
                .iter()
                .map(|c| (c.source.as_ref(), c.target.as_ref())),
        );
    for (a, b) in ends {
        let (x, y) = (end_key(a).0, end_key(b).0);
        if x == instance && !y.is_empty() && y != instance {
            out.insert(y);
        } else if y == instance && !x.is_empty() && x != instance {
            out.insert(x);
        }
    }
    out.into_iter().collect()
}

/// Every leaf that differs between `o` and `n`, as (path, old, new).
fn diff_values(
    path: &str,
    o: &Value,
    n: &Value,
    out: &mut Vec<(String, Option<String>, Option<String>)>,
) {
    if o == n {
        return;
    }
    let join = |k: &str| {
        if path.is_empty() {
            k.to_string()
        } else {
            format!("{path}/{k}")
        }
    };
    match (o, n) {
        (Value::Object(a), Value::Object(b)) => {
            let keys: BTreeSet<&String> = a.keys().chain(b.keys()).collect();
            for k in keys {
                let (x, y) = (
                    a.get(k).unwrap_or(&Value::Null),
                    b.get(k).unwrap_or(&Value::Null),
                );
                diff_values(&join(k), x, y, out);
            }
        }
        (Value::Array(a), Value::Array(b)) => {
            let key = list_key(a).filter(|k| list_key(b) == Some(k) || b.is_empty());
            let key = key.or_else(|| list_key(b).filter(|_| a.is_empty()));
            if let Some(k) = key {
                let names =
                    |v: &Vec<Value>| labels(v.iter().map(|i| i.get(k).and_then(Value::as_str)));
                let (ol, nl) = (names(a), names(b));
                let om: BTreeMap<&String, &Value> = ol.iter().zip(a).collect();
                let nm: BTreeMap<&String, &Value> = nl.iter().zip(b).collect();
                let labels: BTreeSet<&String> = ol.iter().chain(&nl).collect();
                for l in labels {
                    match (om.get(l), nm.get(l)) {
                        (Some(x), Some(y)) => diff_values(&join(l), x, y, out),
                        (x, y) => out.push((
                            join(l),
                            x.and_then(|v| leaf_text(v)),
                            y.and_then(|v| leaf_text(v)),
                        )),
                    }
                }
            } else if a.len() == b.len() {
                for (i, (x, y)) in a.iter().zip(b).enumerate() {
                    diff_values(&join(&(i + 1).to_string()), x, y, out);
                }
            } else {
                out.push((path.to_string(), leaf_text(o), leaf_text(n)));
            }
        }
        _ => out.push((path.to_string(), leaf_text(o), leaf_text(n))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_and_keys() {
        assert_eq!(ec_kind("PERIODIC"), ec_kind("PeriodicExecutionContext"));
        assert_eq!(
            ec_kind("EVENT_DRIVEN"),
            ec_kind("EventDrivenExecutionContext")
        );
        assert_ne!(ec_kind("PERIODIC"), ec_kind("EVENT_DRIVEN"));
        assert_eq!(
            component_key("RTC:Lab:Mobile:Base:1.0"),
            component_key("RTC:lab:Mobile : Base:1.0")
        );
        assert_eq!(
            property_class("dataport.publisher.push_policy").1,
            codes::SYSTEM_CONNECTOR_POLICY
        );
        assert_eq!(
            property_class("dataport.buffer.length").1,
            codes::SYSTEM_CONNECTOR_POLICY
        );
        assert_eq!(property_class("POSITION").1, codes::SYSTEM_OTHER);
    }

    #[test]
    fn identical_systems_have_no_change_and_pairing_is_by_key() {
        let s = RtSystem::default();
        assert!(compare_systems(&s, &s).is_empty());
        let (p, ro, rn) = pair_by(&["a", "b", "a"], &["a", "c", "a"], |x| Some(x.to_string()));
        assert_eq!(p, vec![(0, 0), (2, 2)]);
        assert_eq!((ro, rn), (vec![1], vec![1]));
    }
}
