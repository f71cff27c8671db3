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
use crate::model::system::*;
use crate::model::{Extra, Pos};
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
    let mut s = RtSystem::default();
    for (k, v) in &root {
        let (name, pos) = r.key(k);
        if name == ROOT {
            s.pos = pos;
            system(&mut r, v, pos, &mut s);
        } else {
            r.unknown(&name, v, pos, "the document root", &mut s.extra);
        }
    }
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
    sink: &mut Vec<Extra>,
) -> Vec<SystemProperty> {
    r.properties(v, name, pos, sink)
        .into_iter()
        .map(|p| SystemProperty::new(p.name, p.value, p.pos, p.extra))
        .collect()
}

/// `rtsProfile`.
fn system(r: &mut Reader, v: &Value, pos: Pos, s: &mut RtSystem) {
    let Some(m) = r.map(v, ROOT, pos, &mut s.extra) else {
        return;
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut s.extra;
        match bare(&n) {
            "id" => s.id = r.text(v, &n, kp, x),
            "version" => s.version = r.text(v, &n, kp, x),
            "abstract" => s.abstract_ = r.text(v, &n, kp, x),
            "creationDate" => s.creation_date = r.date(v, &n, kp, x),
            "updateDate" => s.update_date = r.date(v, &n, kp, x),
            "comment" => s.comment = r.text(v, &n, kp, x),
            "versionUpLogs" | "versionUpLog" => s.version_up_logs = r.texts(v, &n, kp, x),
            "properties" | "property" => s.properties = properties(r, v, &n, kp, x),
            "systems" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let mut sub = SubSystem {
                        pos: ip,
                        ..Default::default()
                    };
                    for (k, v) in m {
                        let (n, kp) = r.key(k);
                        match bare(&n) {
                            "path" => sub.path = r.text(v, &n, kp, &mut sub.extra),
                            _ => r.unknown(&n, v, kp, "a sub-system", &mut sub.extra),
                        }
                    }
                    s.systems.push(sub);
                });
            }
            "components" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let c = component(r, m, ip);
                    s.components.push(c);
                });
            }
            "groups" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let g = group(r, m, ip);
                    s.groups.push(g);
                });
            }
            "dataPortConnectors" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let d = data_connector(r, m, ip);
                    s.data_port_connectors.push(d);
                });
            }
            "servicePortConnectors" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let c = service_connector(r, m, ip);
                    s.service_port_connectors.push(c);
                });
            }
            other => match OrderKind::from_yaml_name(other) {
                Some(kind) => {
                    if let Some(m) = r.map(v, &n, kp, x) {
                        let o = order(r, m, kp, kind);
                        s.orders.push(o);
                    }
                }
                None => r.unknown(&n, v, kp, ROOT, x),
            },
        }
    }
    s.id_parts = s.id.as_deref().and_then(SystemIdParts::parse);
    s.orders.sort_by_key(|o| o.kind);
}

/// One item of `components`.
fn component(r: &mut Reader, m: &Mapping, pos: Pos) -> SystemComponent {
    let mut c = SystemComponent {
        pos,
        ..Default::default()
    };
    // Ports are named `<instance>.port`, and the instance name may come after the ports.
    let mut ports: Vec<(bool, SystemPort)> = Vec::new();
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut c.extra;
        match bare(&n) {
            "id" => c.id = r.text(v, &n, kp, x),
            "pathUri" => c.path_uri = r.text(v, &n, kp, x),
            "activeConfigurationSet" => c.active_configuration_set = r.text(v, &n, kp, x),
            "instanceName" => c.instance_name = r.text(v, &n, kp, x),
            "compositeType" => c.composite_type = r.text(v, &n, kp, x),
            "isRequired" => c.is_required = r.text(v, &n, kp, x),
            "comment" => c.comment = r.text(v, &n, kp, x),
            "visible" => c.visible = r.text(v, &n, kp, x),
            "dataPorts" | "servicePorts" => {
                let data = bare(&n) == "dataPorts";
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    ports.push((data, port(r, m, ip)));
                });
            }
            "configurationSets" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let cs = config_set(r, m, ip);
                    c.configuration_sets.push(cs);
                });
            }
            "executionContexts" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let e = execution_context(r, m, ip);
                    c.execution_contexts.push(e);
                });
            }
            "participants" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let t = participant(r, m, ip);
                    c.participants.push(t);
                });
            }
            "location" => {
                if c.location.is_some() {
                    r.unknown(&n, v, kp, "a component instance", x);
                } else if let Some(m) = r.map(v, &n, kp, x) {
                    c.location = Some(location(r, m, kp));
                }
            }
            "properties" | "property" => c.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "a component instance", x),
        }
    }
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

/// An item of `dataPorts` / `servicePorts` (`short_name` is set by the caller).
fn port(r: &mut Reader, m: &Mapping, pos: Pos) -> SystemPort {
    let mut p = SystemPort {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut p.extra;
        match bare(&n) {
            "name" => p.name = r.text(v, &n, kp, x),
            "comment" => p.comment = r.text(v, &n, kp, x),
            "visible" => p.visible = r.text(v, &n, kp, x),
            "properties" | "property" => p.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "a port", x),
        }
    }
    p
}

fn config_set(r: &mut Reader, m: &Mapping, pos: Pos) -> SystemConfigurationSet {
    let mut s = SystemConfigurationSet {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut s.extra;
        match bare(&n) {
            "id" => s.id = r.text(v, &n, kp, x),
            "configurationData" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let mut d = ConfigurationData {
                        pos: ip,
                        ..Default::default()
                    };
                    for (k, v) in m {
                        let (n, kp) = r.key(k);
                        let dx = &mut d.extra;
                        match bare(&n) {
                            "name" => d.name = r.text(v, &n, kp, dx),
                            "data" => d.data = r.text(v, &n, kp, dx),
                            _ => r.unknown(&n, v, kp, "configuration data", dx),
                        }
                    }
                    s.configuration_data.push(d);
                });
            }
            _ => r.unknown(&n, v, kp, "a configuration set", x),
        }
    }
    s.pseudo = s.id.as_deref().is_some_and(is_pseudo_set);
    s
}

fn execution_context(r: &mut Reader, m: &Mapping, pos: Pos) -> ExecutionContext {
    let mut e = ExecutionContext {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut e.extra;
        match bare(&n) {
            "id" => e.id = r.text(v, &n, kp, x),
            "kind" => e.kind = r.text(v, &n, kp, x),
            "rate" => e.rate = r.text(v, &n, kp, x),
            "participants" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let t = target(r, m, ip, "a participant");
                    e.participants.push(t);
                });
            }
            "properties" | "property" => e.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "an execution context", x),
        }
    }
    e
}

/// A target component: `componentId`, `instanceName`, `id`, `"rtsExt::properties"`.
fn target(r: &mut Reader, m: &Mapping, pos: Pos, place: &str) -> TargetComponent {
    let mut t = TargetComponent {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut t.extra;
        match bare(&n) {
            "componentId" => t.component_id = r.text(v, &n, kp, x),
            "instanceName" => t.instance_name = r.text(v, &n, kp, x),
            "id" => t.id = r.text(v, &n, kp, x),
            "properties" | "property" => t.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, place, x),
        }
    }
    t
}

/// An item of a composite's `participants`: `{participant: target}` (also a bare target).
fn participant(r: &mut Reader, m: &Mapping, pos: Pos) -> TargetComponent {
    if !m.contains_key("participant") {
        return target(r, m, pos, "a participant");
    }
    let mut found: Option<TargetComponent> = None;
    let mut extra = Vec::new();
    for (k, v) in m {
        let (n, kp) = r.key(k);
        match (n.as_str(), untag_ref(v)) {
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

fn location(r: &mut Reader, m: &Mapping, pos: Pos) -> Location {
    let mut l = Location {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut l.extra;
        match bare(&n) {
            "x" => l.x = r.text(v, &n, kp, x),
            "y" => l.y = r.text(v, &n, kp, x),
            "height" => l.height = r.text(v, &n, kp, x),
            "width" => l.width = r.text(v, &n, kp, x),
            "direction" => l.direction = r.text(v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "a location", x),
        }
    }
    l
}

fn group(r: &mut Reader, m: &Mapping, pos: Pos) -> Group {
    let mut g = Group {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut g.extra;
        match bare(&n) {
            "groupId" | "groupID" => g.group_id = r.text(v, &n, kp, x),
            "members" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let t = target(r, m, ip, "a group member");
                    g.members.push(t);
                });
            }
            _ => r.unknown(&n, v, kp, "a group", x),
        }
    }
    g
}

/// A connector end: `componentId`, `instanceName`, `portName`, `"rtsExt::properties"`.
fn end(r: &mut Reader, v: &Value, name: &str, pos: Pos, sink: &mut Vec<Extra>) -> Option<PortEnd> {
    let m = r.map(v, name, pos, sink)?;
    let mut e = PortEnd {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut e.extra;
        match bare(&n) {
            "componentId" => e.component_id = r.text(v, &n, kp, x),
            "instanceName" => e.instance_name = r.text(v, &n, kp, x),
            "portName" => e.port_name = r.text(v, &n, kp, x),
            "properties" | "property" => e.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "a connector end", x),
        }
    }
    e.short_name = e
        .port_name
        .as_deref()
        .map(|p| short_port_name(p, e.instance_name.as_deref()).into());
    Some(e)
}

fn data_connector(r: &mut Reader, m: &Mapping, pos: Pos) -> DataPortConnector {
    let mut d = DataPortConnector {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut d.extra;
        match bare(&n) {
            "connectorId" => d.connector_id = r.text(v, &n, kp, x),
            "name" => d.name = r.text(v, &n, kp, x),
            "dataType" => d.data_type = r.text(v, &n, kp, x),
            "interfaceType" => d.interface_type = r.text(v, &n, kp, x),
            "dataflowType" => d.dataflow_type = r.text(v, &n, kp, x),
            "subscriptionType" => d.subscription_type = r.text(v, &n, kp, x),
            "pushInterval" => d.push_interval = r.text(v, &n, kp, x),
            "comment" => d.comment = r.text(v, &n, kp, x),
            "visible" => d.visible = r.text(v, &n, kp, x),
            "sourceDataPort" => d.source = end(r, v, &n, kp, x),
            "targetDataPort" => d.target = end(r, v, &n, kp, x),
            "properties" | "property" => d.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "a data port connector", x),
        }
    }
    d.data_type_scoped = d.data_type.as_deref().and_then(scoped_data_type);
    d
}

fn service_connector(r: &mut Reader, m: &Mapping, pos: Pos) -> ServicePortConnector {
    let mut s = ServicePortConnector {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut s.extra;
        match bare(&n) {
            "connectorId" => s.connector_id = r.text(v, &n, kp, x),
            "name" => s.name = r.text(v, &n, kp, x),
            "transMethod" => s.trans_method = r.text(v, &n, kp, x),
            "comment" => s.comment = r.text(v, &n, kp, x),
            "visible" => s.visible = r.text(v, &n, kp, x),
            "sourceServicePort" => s.source = end(r, v, &n, kp, x),
            "targetServicePort" => s.target = end(r, v, &n, kp, x),
            "properties" | "property" => s.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "a service port connector", x),
        }
    }
    s
}

/// `startUp`, `shutDown`, …: `{targets: [...]}`.
fn order(r: &mut Reader, m: &Mapping, pos: Pos, kind: OrderKind) -> Order {
    let mut o = Order {
        kind,
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut o.extra;
        match bare(&n) {
            "targets" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let t = order_target(r, m, ip);
                    o.targets.push(t);
                });
            }
            _ => r.unknown(&n, v, kp, kind.yaml_name(), x),
        }
    }
    o
}

/// A target: `sequence`, `targetComponent`, `condition: {waitTime: {waitTime}}` or
/// `condition: {preceding: {timeout, sendingTiming, precedingComponents}}`.
fn order_target(r: &mut Reader, m: &Mapping, pos: Pos) -> OrderTarget {
    let mut t = OrderTarget {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut t.extra;
        match bare(&n) {
            "sequence" => t.sequence = r.text(v, &n, kp, x),
            "targetComponent" => {
                if let Some(m) = r.map(v, &n, kp, x) {
                    t.target_component = Some(target(r, m, kp, "a target component"));
                }
            }
            "condition" => {
                let Some(cm) = r.map(v, &n, kp, x) else {
                    continue;
                };
                for (k, v) in cm {
                    let (cn, ckp) = r.key(k);
                    match bare(&cn) {
                        "waitTime" if t.wait_time.is_none() => {
                            t.wait_time = wait_time(r, v, &cn, ckp, &mut t.extra)
                        }
                        "preceding" if t.preceding.is_none() => {
                            if let Some(pm) = r.map(v, &cn, ckp, &mut t.extra) {
                                t.preceding = Some(preceding(r, pm, ckp));
                            }
                        }
                        _ => r.unknown(&cn, v, ckp, "a condition", &mut t.extra),
                    }
                }
            }
            "properties" | "property" => t.properties = properties(r, v, &n, kp, x),
            _ => r.unknown(&n, v, kp, "an order target", x),
        }
    }
    t
}

/// `waitTime: {waitTime: N}` (rtsprofile); a bare `waitTime: N` is accepted too.
fn wait_time(
    r: &mut Reader,
    v: &Value,
    name: &str,
    pos: Pos,
    sink: &mut Vec<Extra>,
) -> Option<WaitTime> {
    let mut w = WaitTime {
        pos,
        ..Default::default()
    };
    match untag_ref(v) {
        Value::Mapping(m) => {
            for (k, v) in m {
                let (n, kp) = r.key(k);
                match bare(&n) {
                    "waitTime" => w.wait_time = r.text(v, &n, kp, &mut w.extra),
                    _ => r.unknown(&n, v, kp, "a wait time", &mut w.extra),
                }
            }
        }
        Value::Null => return None,
        _ => w.wait_time = r.text(v, name, pos, sink),
    }
    Some(w)
}

fn preceding(r: &mut Reader, m: &Mapping, pos: Pos) -> Preceding {
    let mut p = Preceding {
        pos,
        ..Default::default()
    };
    for (k, v) in m {
        let (n, kp) = r.key(k);
        let x = &mut p.extra;
        match bare(&n) {
            "timeout" => p.timeout = r.text(v, &n, kp, x),
            "sendingTiming" => p.sending_timing = r.text(v, &n, kp, x),
            "precedingComponents" => {
                each_item(r, v, &n, kp, x, |r, m, ip| {
                    let c = target(r, m, ip, "a preceding component");
                    p.preceding_components.push(c);
                });
            }
            _ => r.unknown(&n, v, kp, "a preceding condition", x),
        }
    }
    p
}
