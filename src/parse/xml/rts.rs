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
use crate::model::fields::Fields;
use crate::model::system::*;
use crate::model::{Extra, Extras, Located, Pos};
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

fn unknown_attr(m: &mut Mapper, a: &Attr, on: &str, extra: &mut Extras) {
    let what = format!("attribute `{}`{} on {on}", a.qname, ns_note(&a.ns));
    keep(m, a.pos, &what, attr_extra(a), extra);
}

fn unknown_elem(m: &mut Mapper, n: &Node, on: &str, extra: &mut Extras) {
    let what = format!("element `{}`{} in {on}", n.qname, ns_note(&n.ns));
    keep(m, n.pos, &what, node_extra(n), extra);
}

/// Something unknown (`what`): warned about and kept as extra `e`.
fn keep(m: &mut Mapper, pos: Pos, what: &str, e: Extra, extra: &mut Extras) {
    m.warn(pos, format!("unknown {what}; kept as an extra property"));
    extra.push(e);
}

/// A new node `T` at element `n` with the attributes the field table lists for `T` (any
/// namespace of the system profile); every other attribute is unknown on `on`.
fn attrs<T: Fields + Default>(m: &mut Mapper, n: &Node, on: &str, extra: &mut Extras) -> T {
    let mut t = T::default();
    *t.pos_mut() = n.pos;
    for a in &n.attrs {
        let def = akey(a).and_then(|k| T::NODE.xml(k));
        match def.and_then(|(d, _)| t.slot(d.field)) {
            Some(slot) => m.set(slot, a, on, extra),
            None => unknown_attr(m, a, on, extra),
        }
    }
    t
}

/// The child elements of `n` read into `t` by `child` (given each one's local name; false for
/// one it does not know, kept in `extra` and reported in `on`), then its stray text; `extra`
/// becomes `t`'s.
fn children<T: Located>(
    m: &mut Mapper,
    n: &Node,
    on: &str,
    mut t: T,
    mut extra: Extras,
    mut child: impl FnMut(&mut Mapper, &Node, &str, &mut T, &mut Extras) -> bool,
) -> T {
    for c in &n.children {
        if !ekey(c).is_some_and(|k| child(m, c, k, &mut t, &mut extra)) {
            unknown_elem(m, c, on, &mut extra);
        }
    }
    m.stray_text(n, on, &mut extra);
    *t.extra_mut() = extra;
    t
}

/// Element `n` as the node `T` of the field table (attributes only, no child elements defined).
fn leaf<T: Fields + Default>(m: &mut Mapper, n: &Node, on: &str) -> T {
    let mut extra = crate::model::Extras::new();
    let t = attrs(m, n, on, &mut extra);
    children(m, n, on, t, extra, |_, _, _, _, _| false)
}

/// Element `n` as the node `T` of the field table, each child element by `child`.
fn node<T: Fields + Default>(
    m: &mut Mapper,
    n: &Node,
    on: &str,
    child: impl FnMut(&mut Mapper, &Node, &str, &mut T, &mut Extras) -> bool,
) -> T {
    let mut extra = crate::model::Extras::new();
    let t = attrs(m, n, on, &mut extra);
    children(m, n, on, t, extra, child)
}

// --- mapping -----------------------------------------------------------------------------------

/// `rts:RtsProfile`.
fn map_system(m: &mut Mapper, n: &Node) -> RtSystem {
    let on = "RtsProfile";
    let mut s = node::<RtSystem>(m, n, on, |m, c, k, s, extra| {
        match k {
            "Components" => s.components.push(map_component(m, c)),
            "Groups" => s.groups.push(map_group(m, c)),
            "DataPortConnectors" => s.data_port_connectors.push(map_data_connector(m, c)),
            "ServicePortConnectors" => s.service_port_connectors.push(map_service_connector(m, c)),
            // RtsProfile_ext writes `VersionUpLogs`; rtsprofile (Python) reads `VersionUpLog`.
            "VersionUpLogs" | "VersionUpLog" => {
                let t = m.text_of(c, on, extra);
                if !t.trim().is_empty() {
                    s.version_up_logs.push(t);
                }
            }
            "Properties" => s.properties.push(map_property(m, c)),
            "Systems" => s.systems.push(leaf(m, c, "Systems")),
            // Each order at most once (the XSD's maxOccurs="1").
            k => match OrderKind::from_xml_name(k) {
                Some(kind) if s.orders.iter().any(|o| o.kind == kind) => {
                    m.repeated_elem(c, on, extra)
                }
                Some(kind) => s.orders.push(map_order(m, c, kind)),
                None => return false,
            },
        }
        true
    });
    s.id_parts = s.id.as_deref().and_then(SystemIdParts::parse);
    s.orders.sort_by_key(|o| o.kind);
    s
}

/// `rtsExt:Properties(name, value)`.
fn map_property(m: &mut Mapper, n: &Node) -> SystemProperty {
    let p: SystemProperty = leaf(m, n, "property");
    SystemProperty::new(p.name, p.value, p.pos, p.extra)
}

/// `rtsExt:Properties` children: the one element every system node but a few may hold.
fn property(m: &mut Mapper, c: &Node, k: &str, properties: &mut Vec<SystemProperty>) -> bool {
    if k != "Properties" {
        return false;
    }
    properties.push(map_property(m, c));
    true
}

/// `rts:Components`: one component instance.
fn map_component(m: &mut Mapper, n: &Node) -> SystemComponent {
    let mut extra = crate::model::Extras::new();
    let mut c: SystemComponent = attrs(m, n, "component instance", &mut extra);
    c.id_parts = c.id.as_deref().and_then(ComponentIdParts::parse);
    let on = format!(
        "component instance `{}`",
        c.instance_name.as_deref().unwrap_or("")
    );
    let instance = c.instance_name.clone();
    let instance = instance.as_deref();
    children(m, n, &on, c, extra, |m, ch, k, c, extra| {
        match k {
            "DataPorts" => c.data_ports.push(map_port(m, ch, "data port", instance)),
            "ServicePorts" => c
                .service_ports
                .push(map_port(m, ch, "service port", instance)),
            "ConfigurationSets" => c.configuration_sets.push(map_config_set(m, ch)),
            "ExecutionContexts" => c.execution_contexts.push(map_ec(m, ch)),
            "Participants" => c.participants.push(map_participant(m, ch)),
            "Location" if c.location.is_none() => c.location = Some(leaf(m, ch, "location")),
            "Location" => m.repeated_elem(ch, &on, extra),
            _ => return property(m, ch, k, &mut c.properties),
        }
        true
    })
}

/// `rts:DataPorts` / `rts:ServicePorts` of an instance.
fn map_port(m: &mut Mapper, n: &Node, on: &str, instance: Option<&str>) -> SystemPort {
    let mut extra = crate::model::Extras::new();
    let mut p: SystemPort = attrs(m, n, on, &mut extra);
    p.short_name = p
        .name
        .as_deref()
        .map(|s| short_port_name(s, instance).into());
    children(m, n, on, p, extra, |m, c, k, p, _| {
        property(m, c, k, &mut p.properties)
    })
}

/// `rts:ConfigurationSets` → `rts:ConfigurationData`.
fn map_config_set(m: &mut Mapper, n: &Node) -> SystemConfigurationSet {
    let mut s = node::<SystemConfigurationSet>(m, n, "configuration set", |m, c, k, s, _| {
        let data = k == "ConfigurationData";
        if data {
            s.configuration_data.push(leaf(m, c, "configuration data"));
        }
        data
    });
    s.pseudo = s.id.as_deref().is_some_and(is_pseudo_set);
    s
}

/// `rts:ExecutionContexts(id, kind, rate)` → `Participants`, `rtsExt:Properties`.
fn map_ec(m: &mut Mapper, n: &Node) -> ExecutionContext {
    node::<ExecutionContext>(m, n, "execution context", |m, c, k, e, _| match k {
        "Participants" => {
            e.participants.push(map_target(m, c, "participant"));
            true
        }
        _ => property(m, c, k, &mut e.properties),
    })
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
    node::<TargetComponent>(m, n, on, |m, c, k, t, _| {
        property(m, c, k, &mut t.properties)
    })
}

/// `rts:Groups(groupId)` → `Members`.
fn map_group(m: &mut Mapper, n: &Node) -> Group {
    node::<Group>(m, n, "group", |m, c, k, g, _| {
        let member = k == "Members";
        if member {
            g.members.push(map_target(m, c, "group member"));
        }
        member
    })
}

/// `sourceDataPort`, `targetServicePort`, …: `componentId`, `instanceName`, `portName`.
fn map_end(m: &mut Mapper, n: &Node, on: &str) -> PortEnd {
    let mut e = node::<PortEnd>(m, n, on, |m, c, k, e, _| {
        property(m, c, k, &mut e.properties)
    });
    e.short_name = e
        .port_name
        .as_deref()
        .map(|p| short_port_name(p, e.instance_name.as_deref()).into());
    e
}

/// Sets a connector end; a second one is kept as an extra.
fn set_end(m: &mut Mapper, slot: &mut Option<PortEnd>, c: &Node, on: &str, extra: &mut Extras) {
    if slot.is_some() {
        m.repeated_elem(c, on, extra);
    } else {
        *slot = Some(map_end(m, c, &format!("`{}` of {on}", c.local)));
    }
}

/// `rts:DataPortConnectors`.
fn map_data_connector(m: &mut Mapper, n: &Node) -> DataPortConnector {
    let ends = ["sourceDataPort", "targetDataPort"];
    let mut d: DataPortConnector = map_connector(m, n, "data port connector", ends);
    d.data_type_scoped = d.data_type.as_deref().and_then(scoped_data_type);
    d
}

/// `rts:ServicePortConnectors`.
fn map_service_connector(m: &mut Mapper, n: &Node) -> ServicePortConnector {
    let ends = ["sourceServicePort", "targetServicePort"];
    map_connector(m, n, "service port connector", ends)
}

/// A connector (`what`, named by its `name` in the messages about its children): its
/// attributes by the field table, its two ends (elements `ends`, source first) and properties.
fn map_connector<T: Fields + Default + Connector>(
    m: &mut Mapper,
    n: &Node,
    what: &str,
    ends: [&str; 2],
) -> T {
    let mut extra = crate::model::Extras::new();
    let t: T = attrs(m, n, what, &mut extra);
    let name = T::NODE
        .json_field("name")
        .and_then(|f| t.value(f)?.as_deref());
    let on = format!("{what} `{}`", name.unwrap_or(""));
    children(m, n, &on, t, extra, |m, c, k, t, extra| {
        let parts = t.parts_mut();
        let end = match k {
            _ if k == ends[0] => parts.source,
            _ if k == ends[1] => parts.target,
            _ => return property(m, c, k, parts.properties),
        };
        set_end(m, end, c, &on, extra);
        true
    })
}

/// `rts:StartUp`, `rts:ShutDown`, …: `targets` in sequence.
fn map_order(m: &mut Mapper, n: &Node, kind: OrderKind) -> Order {
    let on = kind.xml_name();
    let mut o = node::<Order>(m, n, on, |m, c, k, o, _| {
        let target = k == "targets";
        if target {
            o.targets.push(map_order_target(m, c, on));
        }
        target
    });
    o.kind = kind;
    o
}

/// `rts:targets(sequence)` (`rtsExt:condition_ext`): `TargetComponent`, then `WaitTime` or
/// `Preceding`, and `rtsExt:Properties`.
fn map_order_target(m: &mut Mapper, n: &Node, order: &str) -> OrderTarget {
    let on = format!("target of {order}");
    node::<OrderTarget>(m, n, &on, |m, c, k, t, extra| {
        match k {
            "TargetComponent" if t.target_component.is_none() => {
                t.target_component = Some(map_target(m, c, "target component"))
            }
            "WaitTime" if t.wait_time.is_none() => t.wait_time = Some(leaf(m, c, "wait time")),
            "Preceding" if t.preceding.is_none() => t.preceding = Some(map_preceding(m, c)),
            "TargetComponent" | "WaitTime" | "Preceding" => m.repeated_elem(c, &on, extra),
            _ => return property(m, c, k, &mut t.properties),
        }
        true
    })
}

/// `rts:Preceding(timeout, sendingTiming)` → `PrecedingComponents`.
fn map_preceding(m: &mut Mapper, n: &Node) -> Preceding {
    node::<Preceding>(m, n, "preceding condition", |m, c, k, p, _| {
        let preceding = k == "PrecedingComponents";
        if preceding {
            p.preceding_components
                .push(map_target(m, c, "preceding component"));
        }
        preceding
    })
}
