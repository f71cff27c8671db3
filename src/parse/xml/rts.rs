//! XML reader for RT System profiles (`rts:RtsProfile`, RTSystemEditor; `spec/NOTES.md`, "RT
//! System profiles"). A child of the component reader's module so that it runs on the very same
//! decoder (BOM, declared encodings), element tree (positions, entity refusal, depth limit) and
//! extra/warning helpers; only the mapping pass is its own.
//!
//! Names are resolved by namespace URI, not prefix: `rts` and `rtsExt` are accepted for every
//! known name (real files and writers mix them up), as are unprefixed names. `xsi:type` is
//! schema plumbing (dropped by the tree builder), so elements without it read the same.

use super::{attr_extra, build_any_tree, decode, node_extra, Attr, Mapper, Node, Ns};
use crate::diagnostic::{codes, Diagnostic};
use crate::model::system::*;
use crate::model::{Extra, Text};
use crate::parse::Limits;

/// Namespace URI of the basic system profile (`RtsProfile.xsd`).
pub const NS_RTS: &str = "http://www.openrtp.org/namespaces/rts";
/// Namespace URI of the extended system profile (`RtsProfile_ext.xsd`).
pub const NS_RTS_EXT: &str = "http://www.openrtp.org/namespaces/rts_ext";

/// True when a name in `ns` may be a known system-profile name.
fn is_rts(ns: &Ns) -> bool {
    match ns {
        Ns::Other(u) => u == NS_RTS || u == NS_RTS_EXT,
        Ns::None => true,
        _ => false,
    }
}

fn akey<'a>(a: &'a Attr) -> Option<&'a str> {
    is_rts(&a.ns).then_some(&*a.local)
}

fn ekey<'a>(n: &'a Node) -> Option<&'a str> {
    is_rts(&n.ns).then_some(&*n.local)
}

/// Reads an RT System profile from XML bytes: (system, warnings) or the error that stops it.
pub(crate) fn parse(
    bytes: &[u8],
    file: &str,
    limits: &Limits,
) -> Result<(RtSystem, Vec<Diagnostic>), Diagnostic> {
    let text = decode(bytes, file)?;
    let root = build_any_tree(&text, file, limits)?;
    if root.local != "RtsProfile" || !is_rts(&root.ns) {
        return Err(Diagnostic::error(
            codes::SHAPE,
            file,
            format!(
                "root element is `{}`, not `rts:RtsProfile`: not an RT System profile",
                root.qname
            ),
        )
        .at(root.pos)
        .with_hint("RT System profiles are written by RTSystemEditor (root `rts:RtsProfile`)"));
    }
    let mut m = Mapper {
        file,
        diags: Vec::new(),
        empties: Default::default(),
        written_as: Vec::new(),
    };
    let system = map_system(&mut m, &root);
    Ok((system, m.diags))
}

// --- reporting ---------------------------------------------------------------------------------

fn ns_note(ns: &Ns) -> String {
    match ns {
        Ns::Other(u) if u != NS_RTS && u != NS_RTS_EXT => format!(" (namespace {u})"),
        Ns::Other(_) | Ns::None => String::new(),
        other => other
            .uri()
            .map(|u| format!(" (namespace {u})"))
            .unwrap_or_default(),
    }
}

fn unknown_attr(m: &mut Mapper, a: &Attr, on: &str, extra: &mut Vec<Extra>) {
    m.warn(
        a.pos,
        format!(
            "unknown attribute `{}`{} on {on}; kept as an extra property",
            a.qname,
            ns_note(&a.ns)
        ),
    );
    extra.push(attr_extra(a));
}

fn unknown_elem(m: &mut Mapper, n: &Node, on: &str, extra: &mut Vec<Extra>) {
    m.warn(
        n.pos,
        format!(
            "unknown element `{}`{} in {on}; kept as an extra property",
            n.qname,
            ns_note(&n.ns)
        ),
    );
    extra.push(node_extra(n));
}

/// Reads the attributes of `n` into the `slots` named by local name, and reports the others.
fn attrs(
    m: &mut Mapper,
    n: &Node,
    on: &str,
    extra: &mut Vec<Extra>,
    slots: &mut [(&str, &mut Option<Text>)],
) {
    for a in &n.attrs {
        let key = akey(a);
        match slots.iter_mut().find(|(name, _)| Some(*name) == key) {
            Some((_, slot)) => m.set(slot, a, on, extra),
            None => unknown_attr(m, a, on, extra),
        }
    }
}

// --- mapping -----------------------------------------------------------------------------------

/// `rts:RtsProfile`.
fn map_system(m: &mut Mapper, n: &Node) -> RtSystem {
    let on = "RtsProfile";
    let mut s = RtSystem {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("id", &mut s.id),
            ("version", &mut s.version),
            ("abstract", &mut s.abstract_),
            ("creationDate", &mut s.creation_date),
            ("updateDate", &mut s.update_date),
            ("comment", &mut s.comment),
        ],
    );
    s.id_parts = s.id.as_deref().and_then(SystemIdParts::parse);
    for c in &n.children {
        match ekey(c) {
            Some("Components") => s.components.push(map_component(m, c)),
            Some("Groups") => s.groups.push(map_group(m, c)),
            Some("DataPortConnectors") => s.data_port_connectors.push(map_data_connector(m, c)),
            Some("ServicePortConnectors") => {
                s.service_port_connectors.push(map_service_connector(m, c))
            }
            // RtsProfile_ext writes `VersionUpLogs`; rtsprofile (Python) reads `VersionUpLog`.
            Some("VersionUpLogs" | "VersionUpLog") => {
                let t = m.text_of(c, on, &mut extra);
                if !t.trim().is_empty() {
                    s.version_up_logs.push(t);
                }
            }
            Some("Properties") => s.properties.push(map_property(m, c)),
            Some("Systems") => s.systems.push(map_subsystem(m, c)),
            // Each order at most once (the XSD's maxOccurs="1").
            Some(k) => match OrderKind::from_xml_name(k) {
                Some(kind) if s.orders.iter().any(|o| o.kind == kind) => {
                    m.repeated_elem(c, on, &mut extra)
                }
                Some(kind) => s.orders.push(map_order(m, c, kind)),
                None => unknown_elem(m, c, on, &mut extra),
            },
            None => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    s.orders.sort_by_key(|o| o.kind);
    s.extra = extra;
    s
}

/// `rtsExt:Properties(name, value)`.
fn map_property(m: &mut Mapper, n: &Node) -> SystemProperty {
    let on = "property";
    let (mut name, mut value) = (None, None);
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [("name", &mut name), ("value", &mut value)],
    );
    leaf(m, n, on, &mut extra);
    SystemProperty::new(name, value, n.pos, extra)
}

/// The children and text of an element that has none defined.
fn leaf(m: &mut Mapper, n: &Node, on: &str, extra: &mut Vec<Extra>) {
    for c in &n.children {
        unknown_elem(m, c, on, extra);
    }
    m.stray_text(n, on, extra);
}

/// `rtsExt:Systems(path)`.
fn map_subsystem(m: &mut Mapper, n: &Node) -> SubSystem {
    let on = "Systems";
    let mut s = SubSystem {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    let mut path = None;
    attrs(m, n, on, &mut extra, &mut [("path", &mut path)]);
    s.path = path;
    leaf(m, n, on, &mut extra);
    s.extra = extra;
    s
}

/// `rts:Components`: one component instance.
fn map_component(m: &mut Mapper, n: &Node) -> SystemComponent {
    let mut c = SystemComponent {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        "component instance",
        &mut extra,
        &mut [
            ("id", &mut c.id),
            ("pathUri", &mut c.path_uri),
            ("activeConfigurationSet", &mut c.active_configuration_set),
            ("instanceName", &mut c.instance_name),
            ("compositeType", &mut c.composite_type),
            ("isRequired", &mut c.is_required),
            ("comment", &mut c.comment),
            ("visible", &mut c.visible),
        ],
    );
    c.id_parts = c.id.as_deref().and_then(ComponentIdParts::parse);
    let on = format!(
        "component instance `{}`",
        c.instance_name.as_deref().unwrap_or("")
    );
    let instance = c.instance_name.clone();
    for ch in &n.children {
        match ekey(ch) {
            Some("DataPorts") => {
                c.data_ports
                    .push(map_port(m, ch, "data port", instance.as_deref()))
            }
            Some("ServicePorts") => {
                c.service_ports
                    .push(map_port(m, ch, "service port", instance.as_deref()))
            }
            Some("ConfigurationSets") => c.configuration_sets.push(map_config_set(m, ch)),
            Some("ExecutionContexts") => c.execution_contexts.push(map_ec(m, ch)),
            Some("Participants") => c.participants.push(map_participant(m, ch)),
            Some("Location") if c.location.is_none() => c.location = Some(map_location(m, ch)),
            Some("Location") => m.repeated_elem(ch, &on, &mut extra),
            Some("Properties") => c.properties.push(map_property(m, ch)),
            _ => unknown_elem(m, ch, &on, &mut extra),
        }
    }
    m.stray_text(n, &on, &mut extra);
    c.extra = extra;
    c
}

/// `rts:DataPorts` / `rts:ServicePorts` of an instance.
fn map_port(m: &mut Mapper, n: &Node, on: &str, instance: Option<&str>) -> SystemPort {
    let mut p = SystemPort {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("name", &mut p.name),
            ("comment", &mut p.comment),
            ("visible", &mut p.visible),
        ],
    );
    p.short_name = p
        .name
        .as_deref()
        .map(|s| short_port_name(s, instance).into());
    for c in &n.children {
        match ekey(c) {
            Some("Properties") => p.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    p.extra = extra;
    p
}

/// `rts:ConfigurationSets` → `rts:ConfigurationData`.
fn map_config_set(m: &mut Mapper, n: &Node) -> SystemConfigurationSet {
    let on = "configuration set";
    let mut s = SystemConfigurationSet {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    let mut id = None;
    attrs(m, n, on, &mut extra, &mut [("id", &mut id)]);
    s.pseudo = id.as_deref().is_some_and(is_pseudo_set);
    s.id = id;
    for c in &n.children {
        match ekey(c) {
            Some("ConfigurationData") => {
                let don = "configuration data";
                let (mut name, mut data) = (None, None);
                let mut dx = Vec::new();
                attrs(
                    m,
                    c,
                    don,
                    &mut dx,
                    &mut [("name", &mut name), ("data", &mut data)],
                );
                leaf(m, c, don, &mut dx);
                s.configuration_data.push(ConfigurationData {
                    name,
                    data,
                    pos: c.pos,
                    extra: dx,
                });
            }
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    s.extra = extra;
    s
}

/// `rts:ExecutionContexts(id, kind, rate)` → `Participants`, `rtsExt:Properties`.
fn map_ec(m: &mut Mapper, n: &Node) -> ExecutionContext {
    let on = "execution context";
    let mut e = ExecutionContext {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("id", &mut e.id),
            ("kind", &mut e.kind),
            ("rate", &mut e.rate),
        ],
    );
    for c in &n.children {
        match ekey(c) {
            Some("Participants") => e.participants.push(map_target(m, c, "participant")),
            Some("Properties") => e.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    e.extra = extra;
    e
}

/// `rts:Participants` of a composite instance: a `Participant` child holding the target (the
/// attributes on `Participants` itself are read too, as for execution-context participants).
fn map_participant(m: &mut Mapper, n: &Node) -> TargetComponent {
    let on = "participant";
    let mut inner = n.children.iter().filter(|c| ekey(c) == Some("Participant"));
    let Some(first) = inner.next() else {
        return map_target(m, n, on);
    };
    let mut t = map_target(m, first, on);
    let mut extra = std::mem::take(&mut t.extra);
    for a in &n.attrs {
        unknown_attr(m, a, "Participants", &mut extra);
    }
    for c in &n.children {
        if std::ptr::eq(c, first) {
            continue;
        }
        match ekey(c) {
            Some("Participant") => m.repeated_elem(c, "Participants", &mut extra),
            _ => unknown_elem(m, c, "Participants", &mut extra),
        }
    }
    m.stray_text(n, "Participants", &mut extra);
    t.extra = extra;
    t
}

/// A target component (`componentId`, `instanceName`, `id`) with its `rtsExt:Properties`.
fn map_target(m: &mut Mapper, n: &Node, on: &str) -> TargetComponent {
    let mut t = TargetComponent {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("componentId", &mut t.component_id),
            ("instanceName", &mut t.instance_name),
            ("id", &mut t.id),
        ],
    );
    for c in &n.children {
        match ekey(c) {
            Some("Properties") => t.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    t.extra = extra;
    t
}

/// `rtsExt:Location(x, y, height, width, direction)`.
fn map_location(m: &mut Mapper, n: &Node) -> Location {
    let on = "location";
    let mut l = Location {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("x", &mut l.x),
            ("y", &mut l.y),
            ("height", &mut l.height),
            ("width", &mut l.width),
            ("direction", &mut l.direction),
        ],
    );
    leaf(m, n, on, &mut extra);
    l.extra = extra;
    l
}

/// `rts:Groups(groupId)` → `Members`.
fn map_group(m: &mut Mapper, n: &Node) -> Group {
    let on = "group";
    let mut g = Group {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    // rtsprofile (Python) writes `groupID`, the schema `groupId`: either fills the id, a
    // second one is kept as a repeated attribute.
    for a in &n.attrs {
        match akey(a) {
            Some("groupId" | "groupID") => m.set(&mut g.group_id, a, on, &mut extra),
            _ => unknown_attr(m, a, on, &mut extra),
        }
    }
    for c in &n.children {
        match ekey(c) {
            Some("Members") => g.members.push(map_target(m, c, "group member")),
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    g.extra = extra;
    g
}

/// `sourceDataPort`, `targetServicePort`, …: `componentId`, `instanceName`, `portName`.
fn map_end(m: &mut Mapper, n: &Node, on: &str) -> PortEnd {
    let mut e = PortEnd {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("componentId", &mut e.component_id),
            ("instanceName", &mut e.instance_name),
            ("portName", &mut e.port_name),
        ],
    );
    e.short_name = e
        .port_name
        .as_deref()
        .map(|p| short_port_name(p, e.instance_name.as_deref()).into());
    for c in &n.children {
        match ekey(c) {
            Some("Properties") => e.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    e.extra = extra;
    e
}

/// Sets a connector end; a second one is kept as an extra.
fn set_end(m: &mut Mapper, slot: &mut Option<PortEnd>, c: &Node, on: &str, extra: &mut Vec<Extra>) {
    if slot.is_some() {
        m.repeated_elem(c, on, extra);
    } else {
        *slot = Some(map_end(m, c, &format!("`{}` of {on}", c.local)));
    }
}

/// `rts:DataPortConnectors`.
fn map_data_connector(m: &mut Mapper, n: &Node) -> DataPortConnector {
    let on = "data port connector";
    let mut d = DataPortConnector {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("connectorId", &mut d.connector_id),
            ("name", &mut d.name),
            ("dataType", &mut d.data_type),
            ("interfaceType", &mut d.interface_type),
            ("dataflowType", &mut d.dataflow_type),
            ("subscriptionType", &mut d.subscription_type),
            ("pushInterval", &mut d.push_interval),
            ("comment", &mut d.comment),
            ("visible", &mut d.visible),
        ],
    );
    d.data_type_scoped = d.data_type.as_deref().and_then(scoped_data_type);
    let on = format!("data port connector `{}`", d.name.as_deref().unwrap_or(""));
    for c in &n.children {
        match ekey(c) {
            Some("sourceDataPort") => set_end(m, &mut d.source, c, &on, &mut extra),
            Some("targetDataPort") => set_end(m, &mut d.target, c, &on, &mut extra),
            Some("Properties") => d.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, &on, &mut extra),
        }
    }
    m.stray_text(n, &on, &mut extra);
    d.extra = extra;
    d
}

/// `rts:ServicePortConnectors`.
fn map_service_connector(m: &mut Mapper, n: &Node) -> ServicePortConnector {
    let on = "service port connector";
    let mut s = ServicePortConnector {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("connectorId", &mut s.connector_id),
            ("name", &mut s.name),
            ("transMethod", &mut s.trans_method),
            ("comment", &mut s.comment),
            ("visible", &mut s.visible),
        ],
    );
    let on = format!(
        "service port connector `{}`",
        s.name.as_deref().unwrap_or("")
    );
    for c in &n.children {
        match ekey(c) {
            Some("sourceServicePort") => set_end(m, &mut s.source, c, &on, &mut extra),
            Some("targetServicePort") => set_end(m, &mut s.target, c, &on, &mut extra),
            Some("Properties") => s.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, &on, &mut extra),
        }
    }
    m.stray_text(n, &on, &mut extra);
    s.extra = extra;
    s
}

/// `rts:StartUp`, `rts:ShutDown`, …: `targets` in sequence.
fn map_order(m: &mut Mapper, n: &Node, kind: OrderKind) -> Order {
    let on = kind.xml_name();
    let mut o = Order {
        kind,
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    for a in &n.attrs {
        unknown_attr(m, a, on, &mut extra);
    }
    for c in &n.children {
        match ekey(c) {
            Some("targets") => o.targets.push(map_order_target(m, c, on)),
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    o.extra = extra;
    o
}

/// `rts:targets(sequence)` (`rtsExt:condition_ext`): `TargetComponent`, then `WaitTime` or
/// `Preceding`, and `rtsExt:Properties`.
fn map_order_target(m: &mut Mapper, n: &Node, order: &str) -> OrderTarget {
    let on = format!("target of {order}");
    let mut t = OrderTarget {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    let mut seq = None;
    attrs(m, n, &on, &mut extra, &mut [("sequence", &mut seq)]);
    t.sequence = seq;
    for c in &n.children {
        match ekey(c) {
            Some("TargetComponent") if t.target_component.is_none() => {
                t.target_component = Some(map_target(m, c, "target component"))
            }
            Some("WaitTime") if t.wait_time.is_none() => {
                let won = "wait time";
                let mut w = WaitTime {
                    pos: c.pos,
                    ..Default::default()
                };
                let mut wx = Vec::new();
                let mut wt = None;
                attrs(m, c, won, &mut wx, &mut [("waitTime", &mut wt)]);
                w.wait_time = wt;
                leaf(m, c, won, &mut wx);
                w.extra = wx;
                t.wait_time = Some(w);
            }
            Some("Preceding") if t.preceding.is_none() => t.preceding = Some(map_preceding(m, c)),
            Some("TargetComponent" | "WaitTime" | "Preceding") => {
                m.repeated_elem(c, &on, &mut extra)
            }
            Some("Properties") => t.properties.push(map_property(m, c)),
            _ => unknown_elem(m, c, &on, &mut extra),
        }
    }
    m.stray_text(n, &on, &mut extra);
    t.extra = extra;
    t
}

/// `rts:Preceding(timeout, sendingTiming)` → `PrecedingComponents`.
fn map_preceding(m: &mut Mapper, n: &Node) -> Preceding {
    let on = "preceding condition";
    let mut p = Preceding {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = Vec::new();
    attrs(
        m,
        n,
        on,
        &mut extra,
        &mut [
            ("timeout", &mut p.timeout),
            ("sendingTiming", &mut p.sending_timing),
        ],
    );
    for c in &n.children {
        match ekey(c) {
            Some("PrecedingComponents") => {
                p.preceding_components
                    .push(map_target(m, c, "preceding component"))
            }
            _ => unknown_elem(m, c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    p.extra = extra;
    p
}
