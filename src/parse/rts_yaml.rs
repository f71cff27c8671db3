//! YAML reader for RT System profiles (root key `rtsProfile`, camelCase keys, `"rtsExt::…"`
//! for the extended profile, dates as maps: the form rtsprofile/rtshell read and write). A child
//! of the component YAML reader's module so that it runs on the very same value builder (alias
//! bomb and depth limits), line reader fast path, locator (positions) and extra/warning
//! helpers; only the mapping is its own.
//!
//! Extension keys are accepted with or without their `rtsExt::` prefix (the XML reader accepts
//! either namespace), so `"rtsExt::comment"` and `comment` both fill `comment`.

use super::{each_item, root_reader, untag_ref, Reader};
use crate::diagnostic::Diagnostic;
use crate::model::fields::Fields;
use crate::model::system::*;
use crate::model::{Extras, Pos};
use crate::parse::Limits;
use serde_norway::{Mapping, Value};

const ROOT: &str = "rtsProfile";

/// Reads an RT System profile from YAML bytes: (system, warnings) or the error that stops it.
pub(crate) fn parse(
    bytes: &[u8],
    file: &str,
    limits: &Limits,
) -> Result<(RtSystem, Vec<Diagnostic>), Diagnostic> {
    let (root, mut r) = root_reader(
        bytes,
        file,
        limits,
        ROOT,
        "RT System profile",
        "a YAML RT System profile starts with `rtsProfile:`",
    )?;
    let s = r.document(&root, ROOT, |r, v, pos, s: &mut RtSystem| {
        if let Some(m) = r.map(v, ROOT, pos, &mut s.extra) {
            // The root's unknown keys before `rtsProfile` stay first.
            let before = std::mem::replace(s, system(r, m, pos));
            s.extra.splice(0..0, before.extra);
        }
    });
    Ok((s, r.diags))
}

/// A key without its `rtsExt::` prefix.
fn bare(name: &str) -> &str {
    name.strip_prefix("rtsExt::").unwrap_or(name)
}

/// `"rtsExt::properties"`: `[{name, value}]`.
fn properties(
    r: &mut Reader,
    v: &Value,
    name: &str,
    pos: Pos,
    sink: &mut Extras,
) -> Vec<SystemProperty> {
    r.properties(v, name, pos, sink)
        .into_iter()
        .map(|p| SystemProperty::new(p.name, p.value, p.pos, p.extra))
        .collect()
}

/// `rtsProfile`.
fn system(r: &mut Reader, m: &Mapping, pos: Pos) -> RtSystem {
    let (mut s, _) = r.node(m, pos, |r, n, v, kp, s: &mut RtSystem| {
        let x = &mut s.extra;
        match bare(n) {
            "versionUpLogs" | "versionUpLog" => s.version_up_logs = r.texts(v, n, kp, x),
            "properties" | "property" => s.properties = properties(r, v, n, kp, x),
            "systems" => items(r, v, n, kp, x, &mut s.systems, |r, m, ip| {
                r.leaf(m, ip, "a sub-system")
            }),
            "components" => items(r, v, n, kp, x, &mut s.components, component),
            "groups" => items(r, v, n, kp, x, &mut s.groups, group),
            "dataPortConnectors" => {
                items(r, v, n, kp, x, &mut s.data_port_connectors, |r, m, ip| {
                    let ends = ["sourceDataPort", "targetDataPort"];
                    let mut d: DataPortConnector =
                        connector(r, m, ip, "a data port connector", ends);
                    d.data_type_scoped = d.data_type.as_deref().and_then(scoped_data_type);
                    d
                })
            }
            "servicePortConnectors" => items(
                r,
                v,
                n,
                kp,
                x,
                &mut s.service_port_connectors,
                |r, m, ip| {
                    let ends = ["sourceServicePort", "targetServicePort"];
                    connector(r, m, ip, "a service port connector", ends)
                },
            ),
            other => match OrderKind::from_yaml_name(other) {
                Some(kind) => {
                    if let Some(m) = r.map(v, n, kp, x) {
                        let o = order(r, m, kp, kind);
                        s.orders.push(o);
                    }
                }
                None => r.unknown(n, v, kp, ROOT, x),
            },
        }
    });
    s.id_parts = s.id.as_deref().and_then(SystemIdParts::parse);
    s.orders.sort_by_key(|o| o.kind);
    s
}

/// One item of `components`.
fn component(r: &mut Reader, m: &Mapping, pos: Pos) -> SystemComponent {
    // Ports are named `<instance>.port`, and the instance name may come after the ports.
    let mut ports: Vec<(bool, SystemPort)> = Vec::new();
    let (mut c, _) = r.node(m, pos, |r, n, v, kp, c: &mut SystemComponent| {
        let x = &mut c.extra;
        match bare(n) {
            "dataPorts" | "servicePorts" => {
                let data = bare(n) == "dataPorts";
                each_item(r, v, n, kp, x, |r, m, ip| {
                    ports.push((data, port(r, m, ip)));
                });
            }
            "configurationSets" => items(r, v, n, kp, x, &mut c.configuration_sets, config_set),
            "executionContexts" => {
                items(r, v, n, kp, x, &mut c.execution_contexts, execution_context)
            }
            "participants" => items(r, v, n, kp, x, &mut c.participants, participant),
            "location" => {
                if c.location.is_some() {
                    r.unknown(n, v, kp, "a component instance", x);
                } else if let Some(m) = r.map(v, n, kp, x) {
                    c.location = Some(r.leaf(m, kp, "a location"));
                }
            }
            "properties" | "property" => c.properties = properties(r, v, n, kp, x),
            _ => r.unknown(n, v, kp, "a component instance", x),
        }
    });
    c.id_parts = c.id.as_deref().and_then(ComponentIdParts::parse);
    for (data, mut p) in ports {
        p.short_name = p
            .name
            .as_deref()
            .map(|s| short_port_name(s, c.instance_name.as_deref()).into());
        if data {
            c.data_ports.push(p);
        } else {
            c.service_ports.push(p);
        }
    }
    c
}

/// The `"rtsExt::properties"` of a node whose other keys are all scalars (in the field table);
/// any other key is unknown in `place`.
fn with_properties<T: Fields + Default>(
    r: &mut Reader,
    m: &Mapping,
    pos: Pos,
    place: &str,
    properties_of: impl Fn(&mut T) -> &mut Vec<SystemProperty>,
) -> T {
    r.node(m, pos, |r, n, v, kp, t: &mut T| match bare(n) {
        "properties" | "property" => {
            let p = properties(r, v, n, kp, t.extra_mut());
            *properties_of(t) = p;
        }
        _ => r.unknown(n, v, kp, place, t.extra_mut()),
    })
    .0
}

/// An item of `dataPorts` / `servicePorts` (`short_name` is set by the caller).
fn port(r: &mut Reader, m: &Mapping, pos: Pos) -> SystemPort {
    with_properties(r, m, pos, "a port", |p: &mut SystemPort| &mut p.properties)
}

fn config_set(r: &mut Reader, m: &Mapping, pos: Pos) -> SystemConfigurationSet {
    let place = "a configuration set";
    let parts: ListParts<SystemConfigurationSet, _> = |s| (&mut s.configuration_data, &mut s.extra);
    let mut s = with_list(r, m, pos, place, "configurationData", parts, |r, m, ip| {
        r.leaf(m, ip, "configuration data")
    });
    s.pseudo = s.id.as_deref().is_some_and(is_pseudo_set);
    s
}

/// A list of a node and the node's extras.
type ListParts<T, I> = fn(&mut T) -> (&mut Vec<I>, &mut Extras);

/// Reads mapping `m` (at `pos`) as the system node `T` whose only key beside its scalars (in
/// the field table) is the list `key`: its items read by `read` into the list that `parts`
/// gives with the node's extras. Any other key is unknown in `place`.
fn with_list<T: Fields + Default, I>(
    r: &mut Reader,
    m: &Mapping,
    pos: Pos,
    place: &str,
    key: &str,
    parts: fn(&mut T) -> (&mut Vec<I>, &mut Extras),
    read: impl Fn(&mut Reader, &Mapping, Pos) -> I,
) -> T {
    r.node(m, pos, |r, n, v, kp, t: &mut T| {
        let (list, x) = parts(t);
        if bare(n) == key {
            items(r, v, n, kp, x, list, &read);
        } else {
            r.unknown(n, v, kp, place, x);
        }
    })
    .0
}

/// The mapping items of list `v` (key `n` at `kp`) read by `read` onto `list`; the other
/// items go to `sink`.
fn items<I>(
    r: &mut Reader,
    v: &Value,
    n: &str,
    kp: Pos,
    sink: &mut Extras,
    list: &mut Vec<I>,
    read: impl Fn(&mut Reader, &Mapping, Pos) -> I,
) {
    each_item(r, v, n, kp, sink, |r, m, ip| {
        let item = read(r, m, ip);
        list.push(item);
    });
}

fn execution_context(r: &mut Reader, m: &Mapping, pos: Pos) -> ExecutionContext {
    r.node(m, pos, |r, n, v, kp, e: &mut ExecutionContext| {
        let x = &mut e.extra;
        match bare(n) {
            "participants" => items(r, v, n, kp, x, &mut e.participants, |r, m, ip| {
                target(r, m, ip, "a participant")
            }),
            "properties" | "property" => e.properties = properties(r, v, n, kp, x),
            _ => r.unknown(n, v, kp, "an execution context", x),
        }
    })
    .0
}

/// A target component: `componentId`, `instanceName`, `id`, `"rtsExt::properties"`.
fn target(r: &mut Reader, m: &Mapping, pos: Pos, place: &str) -> TargetComponent {
    with_properties(r, m, pos, place, |t: &mut TargetComponent| {
        &mut t.properties
    })
}

/// An item of a composite's `participants`: `{participant: target}` (also a bare target).
fn participant(r: &mut Reader, m: &Mapping, pos: Pos) -> TargetComponent {
    if !m.contains_key("participant") {
        return target(r, m, pos, "a participant");
    }
    let mut found: Option<TargetComponent> = None;
    let mut extra = crate::model::Extras::new();
    for (k, v) in m {
        let (n, kp) = r.key(k);
        match (&*n, untag_ref(v)) {
            ("participant", Value::Mapping(pm)) if found.is_none() => {
                found = Some(target(r, pm, kp, "a participant"))
            }
            _ => r.unknown(&n, v, kp, "a participant", &mut extra),
        }
    }
    let mut t = found.unwrap_or(TargetComponent {
        pos,
        ..Default::default()
    });
    t.extra.extend(extra);
    t
}

fn group(r: &mut Reader, m: &Mapping, pos: Pos) -> Group {
    let parts: ListParts<Group, _> = |g| (&mut g.members, &mut g.extra);
    with_list(r, m, pos, "a group", "members", parts, |r, m, ip| {
        target(r, m, ip, "a group member")
    })
}

/// A connector end: `componentId`, `instanceName`, `portName`, `"rtsExt::properties"`.
fn end(r: &mut Reader, v: &Value, name: &str, pos: Pos, sink: &mut Extras) -> Option<PortEnd> {
    let m = r.map(v, name, pos, sink)?;
    let mut e = with_properties(r, m, pos, "a connector end", |e: &mut PortEnd| {
        &mut e.properties
    });
    e.short_name = e
        .port_name
        .as_deref()
        .map(|p| short_port_name(p, e.instance_name.as_deref()).into());
    Some(e)
}

/// A connector (`place`): its scalars by the field table, its two ends (keys `ends`, source
/// first) and properties.
fn connector<T: Fields + Default + Connector>(
    r: &mut Reader,
    m: &Mapping,
    pos: Pos,
    place: &str,
    ends: [&str; 2],
) -> T {
    r.node(m, pos, |r, n, v, kp, t: &mut T| {
        let p = t.parts_mut();
        match bare(n) {
            k if k == ends[0] => *p.source = end(r, v, n, kp, p.extra),
            k if k == ends[1] => *p.target = end(r, v, n, kp, p.extra),
            "properties" | "property" => *p.properties = properties(r, v, n, kp, p.extra),
            _ => r.unknown(n, v, kp, place, p.extra),
        }
    })
    .0
}

/// `startUp`, `shutDown`, …: `{targets: [...]}`.
fn order(r: &mut Reader, m: &Mapping, pos: Pos, kind: OrderKind) -> Order {
    let parts: ListParts<Order, _> = |o| (&mut o.targets, &mut o.extra);
    let mut o = with_list(r, m, pos, kind.yaml_name(), "targets", parts, order_target);
    o.kind = kind;
    o
}

/// A target: `sequence`, `targetComponent`, `condition: {waitTime: {waitTime}}` or
/// `condition: {preceding: {timeout, sendingTiming, precedingComponents}}`.
fn order_target(r: &mut Reader, m: &Mapping, pos: Pos) -> OrderTarget {
    r.node(m, pos, |r, n, v, kp, t: &mut OrderTarget| {
        let x = &mut t.extra;
        match bare(n) {
            "targetComponent" => {
                if let Some(m) = r.map(v, n, kp, x) {
                    t.target_component = Some(target(r, m, kp, "a target component"));
                }
            }
            "condition" => {
                if let Some(cm) = r.map(v, n, kp, x) {
                    condition(r, cm, t);
                }
            }
            "properties" | "property" => t.properties = properties(r, v, n, kp, x),
            _ => r.unknown(n, v, kp, "an order target", x),
        }
    })
    .0
}

/// The `condition` of an order target, read into `t`: `waitTime: {waitTime: N}` (rtsprofile; a
/// bare `waitTime: N` is accepted too) or `preceding: {…}`.
fn condition(r: &mut Reader, cm: &Mapping, t: &mut OrderTarget) {
    for (k, v) in cm {
        let (cn, ckp) = r.key(k);
        match (bare(&cn), untag_ref(v)) {
            ("waitTime", Value::Mapping(m)) if t.wait_time.is_none() => {
                t.wait_time = Some(r.leaf(m, ckp, "a wait time"))
            }
            ("waitTime", Value::Null) if t.wait_time.is_none() => {}
            ("waitTime", _) if t.wait_time.is_none() => {
                let wait_time = r.text(v, &cn, ckp, &mut t.extra);
                t.wait_time = Some(WaitTime {
                    wait_time,
                    pos: ckp,
                    ..Default::default()
                })
            }
            ("preceding", _) if t.preceding.is_none() => {
                if let Some(pm) = r.map(v, &cn, ckp, &mut t.extra) {
                    t.preceding = Some(preceding(r, pm, ckp));
                }
            }
            _ => r.unknown(&cn, v, ckp, "a condition", &mut t.extra),
        }
    }
}

fn preceding(r: &mut Reader, m: &Mapping, pos: Pos) -> Preceding {
    let parts: ListParts<Preceding, _> = |p| (&mut p.preceding_components, &mut p.extra);
    with_list(
        r,
        m,
        pos,
        "a preceding condition",
        "precedingComponents",
        parts,
        |r, m, ip| target(r, m, ip, "a preceding component"),
    )
}
