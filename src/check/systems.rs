//! The rules over RT System profiles (RTC6xx): connector ends against the ports of the
//! component profiles, connector types against port types, instances against the catalogue,
//! instance names, and configuration values against the components' declarations.

use super::registry as r;
use super::rules::{seen_before, Findings};
use crate::catalog::systems::{
    check_configuration, end_port_name, instance_lists_port, ConfigCheck, PortLink, System,
};
use crate::catalog::Catalog;
use crate::diagnostic::Diagnostic;
use crate::model::non_empty;
use crate::model::system::PortEnd;
use crate::quote::Code;
use std::collections::HashMap;

/// Every finding over every system of the catalogue.
pub fn run(cat: &Catalog) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for s in &cat.systems {
        let mut sink = Findings {
            file: &s.source,
            out: Vec::new(),
        };
        system(cat, s, &mut sink);
        out.extend(sink.out);
    }
    out
}

fn system(cat: &Catalog, s: &System, sink: &mut Findings<'_>) {
    duplicate_names(s, sink);
    instances(cat, s, sink);
    connector_ends(cat, s, sink);
    connector_types(cat, s, sink);
}

/// RTC605 and RTC609: an instance name, or a connector id, used twice.
fn duplicate_names(s: &System, sink: &mut Findings<'_>) {
    let p = &s.profile;
    // Instance names.
    let mut first: HashMap<&str, usize> = HashMap::new();
    for c in &p.components {
        let Some(n) = non_empty(&c.instance_name) else {
            continue;
        };
        let seen = first.entry(n).or_default();
        *seen += 1;
        if *seen == 2 {
            sink.emit(
                r::SYSTEM_DUPLICATE_INSTANCE,
                c.pos,
                format!("instance name `{n}` is used by more than one instance"),
            );
        }
    }
    // Connector ids.
    let mut ids: HashMap<&str, (&str, crate::model::Pos)> = HashMap::new();
    let connectors = p
        .data_port_connectors
        .iter()
        .map(|c| (&c.connector_id, &c.name, c.pos))
        .chain(
            p.service_port_connectors
                .iter()
                .map(|c| (&c.connector_id, &c.name, c.pos)),
        );
    for (id, name, pos) in connectors {
        let name = non_empty(name).unwrap_or("");
        // Twins often share their name too: the first one is named by its line.
        if let Some((id, (first, at))) = seen_before(&mut ids, id, (name, pos)) {
            sink.emit(
                r::SYSTEM_DUPLICATE_CONNECTOR_ID,
                pos,
                format!(
                    "connector `{name}` has the id `{id}` of connector `{first}` (line {})",
                    at.line
                ),
            );
        }
    }
}

/// RTC603, RTC604, RTC610 and the configuration (RTC606, RTC607): each instance against the
/// catalogue.
fn instances(cat: &Catalog, s: &System, sink: &mut Findings<'_>) {
    for (i, c) in s.profile.components.iter().enumerate() {
        let name = non_empty(&c.instance_name).unwrap_or("");
        let id = non_empty(&c.id).unwrap_or("");
        let Some(comp) = cat.instance_component(s, i) else {
            sink.emit(
                r::SYSTEM_COMPONENT_MISSING,
                c.pos,
                format!(
                    "instance `{name}`: no component profile of the input has the id `{id}` (vendor, category and name)"
                ),
            );
            if let Some(hint) = instance_named_id(cat, c) {
                if let Some(d) = sink.out.last_mut() {
                    d.hint = Some(hint);
                }
            }
            continue;
        };
        if let Some(theirs) = &s.instances[i].version_drift {
            let ours = c
                .id_parts
                .as_ref()
                .and_then(|x| non_empty(&x.version))
                .unwrap_or("");
            sink.emit(
                r::SYSTEM_VERSION_DRIFT,
                c.pos,
                format!(
                    "instance `{name}` names version {ours} of `{}`; the catalogue has {theirs} ({})",
                    comp.profile.name(),
                    comp.source
                ),
            );
        }
        deprecated_instance(comp, (name, c.pos), sink);
        configuration(comp, c, name, sink);
    }
}

/// RTC606 and RTC607: the configuration sets instance `name` (`c`, of component `comp`) has.
fn configuration(
    comp: &crate::catalog::Component,
    c: &crate::model::system::SystemComponent,
    name: &str,
    sink: &mut Findings<'_>,
) {
    for set in c.configuration_sets.iter().filter(|x| !x.pseudo) {
        let set_id = non_empty(&set.id).unwrap_or("");
        for d in &set.configuration_data {
            let n = non_empty(&d.name).unwrap_or("");
            let v = d.data.as_deref().unwrap_or("");
            match check_configuration(comp, n, v) {
                ConfigCheck::Ok => {}
                ConfigCheck::Undeclared => sink.emit(
                    r::SYSTEM_CONFIG_UNDECLARED,
                    d.pos,
                    format!(
                        "instance `{name}`, set `{set_id}`: `{}` declares no parameter `{n}`",
                        comp.profile.name()
                    ),
                ),
                ConfigCheck::BadType(why) | ConfigCheck::Violated(why) => sink.emit(
                    r::SYSTEM_CONFIG_INVALID,
                    d.pos,
                    format!(
                        "instance `{name}`, set `{set_id}`: `{n}` = {} is {why}",
                        Code(v)
                    ),
                ),
            }
        }
    }
}

/// The findings of each connector's ends ([`end`]).
fn connector_ends(cat: &Catalog, s: &System, sink: &mut Findings<'_>) {
    let p = &s.profile;
    let ends = p
        .data_port_connectors
        .iter()
        .zip(&s.data_connectors)
        .map(|(c, l)| (&c.source, &c.target, l, false))
        .chain(
            p.service_port_connectors
                .iter()
                .zip(&s.service_connectors)
                .map(|(c, l)| (&c.source, &c.target, l, true)),
        );
    for (src, dst, l, service) in ends {
        for (e, el) in [(src, &l.source), (dst, &l.target)] {
            let Some(e) = e else { continue };
            end(cat, s, (e, service), el, sink);
        }
    }
}

/// RTC602: connector types against port types, each spelling read as the IDL defines it (a
/// repository id with a `#pragma prefix` names the type defined under it).
fn connector_types(cat: &Catalog, s: &System, sink: &mut Findings<'_>) {
    let p = &s.profile;
    let canonical = |t: &str| cat.idl.canonical_name(t);
    for (c, l) in p.data_port_connectors.iter().zip(&s.data_connectors) {
        let port_type = |el: &crate::catalog::systems::EndLink| -> Option<(String, String)> {
            let comp = cat.instance_component(s, el.instance?)?;
            let Some(PortLink::Data { index, name }) = &el.port else {
                return None;
            };
            let t = non_empty(&comp.profile.data_ports[*index].type_)?;
            Some((canonical(t), format!("{}.{name}", comp.profile.name())))
        };
        // A component not in the catalogue: the type the system file records for the port
        // (RTSystemEditor's `dataport.data_type`).
        let recorded = |e: &Option<PortEnd>, el: &crate::catalog::systems::EndLink| {
            let inst = p.components.get(el.instance?)?;
            let name = end_port_name(e.as_ref()?);
            let t = inst.recorded_data_type(name)?;
            let who = non_empty(&inst.instance_name).unwrap_or("");
            Some((
                canonical(t),
                format!("{who}.{name} (as the system file records it)"),
            ))
        };
        let a = port_type(&l.source).or_else(|| recorded(&c.source, &l.source));
        let b = port_type(&l.target).or_else(|| recorded(&c.target, &l.target));
        let cname = non_empty(&c.name).unwrap_or("");
        if let Some(t) = non_empty(&c.data_type) {
            let want = canonical(t);
            // One finding a connector, naming each end that differs.
            let ends: Vec<String> = [&a, &b]
                .into_iter()
                .flatten()
                .filter(|(pt, _)| *pt != want)
                .map(|(pt, port)| format!("port {port} carries `{pt}`"))
                .collect();
            if !ends.is_empty() {
                sink.emit(
                    r::SYSTEM_TYPE_MISMATCH,
                    c.pos,
                    format!(
                        "connector `{cname}` carries `{t}`, but {}",
                        ends.join(" and ")
                    ),
                );
            }
        } else if let (Some((ta, pa)), Some((tb, pb))) = (&a, &b) {
            if ta != tb {
                sink.emit(
                    r::SYSTEM_TYPE_MISMATCH,
                    c.pos,
                    format!("connector `{cname}` joins {pa} (`{ta}`) to {pb} (`{tb}`)"),
                );
            }
        }
    }
}

/// The findings of connector end `e` (of a service connector when `service`).
fn end(
    cat: &Catalog,
    s: &System,
    (e, service): (&PortEnd, bool),
    el: &crate::catalog::systems::EndLink,
    sink: &mut Findings<'_>,
) {
    let inst = non_empty(&e.instance_name).unwrap_or("");
    let port = end_port_name(e);
    let Some(i) = el.instance else {
        sink.emit(
            r::SYSTEM_UNKNOWN_INSTANCE,
            e.pos,
            format!("connector end `{inst}.{port}`: the system has no instance `{inst}`"),
        );
        return;
    };
    match (cat.instance_component(s, i), &el.port) {
        (Some(comp), None) => sink.emit(
            r::SYSTEM_UNKNOWN_PORT,
            e.pos,
            format!(
                "connector end `{inst}.{port}`: component `{}` ({}) has no port `{port}`",
                comp.profile.name(),
                comp.source
            ),
        ),
        // A component not in the catalogue: the ports the system file lists for the instance.
        (None, _) => {
            let Some(c) = s.profile.components.get(i) else {
                return;
            };
            if instance_lists_port(c, service, port) == Some(false) {
                let ports = if service {
                    &c.service_ports
                } else {
                    &c.data_ports
                };
                let listed: Vec<&str> = ports.iter().map(|p| p.own_name().trim()).collect();
                sink.emit(
                    r::SYSTEM_UNKNOWN_PORT,
                    e.pos,
                    format!(
                        "connector end `{inst}.{port}`: instance `{inst}` lists no port `{port}` in the system file (it lists {})",
                        listed.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
                    ),
                );
            }
        }
        _ => {}
    }
}

/// A hint for an instance whose id names the instance instead of its component, as Choreonoid
/// saves it (`RTC:AIST:Controller:RobotController0:1.0.0` for an instance `RobotController0`):
/// the component of that vendor and category whose name is the id's name without its trailing
/// number, when the input has one.
/// RTC610: an instance (`name` at `pos`) of component `comp` that is deprecated, naming its
/// replacement.
fn deprecated_instance(
    comp: &crate::catalog::Component,
    (name, pos): (&str, crate::model::Pos),
    sink: &mut Findings<'_>,
) {
    use crate::model::stability::Status;
    let Some(s) = comp
        .stability
        .as_ref()
        .filter(|s| s.status == Status::Deprecated)
    else {
        return;
    };
    sink.emit(
        r::SYSTEM_USES_DEPRECATED,
        pos,
        format!(
            "instance `{name}` is of `{}`, {}",
            comp.profile.name(),
            super::rules::deprecated_text(s)
        ),
    );
    if let (Some(r), Some(d)) = (&s.replacement, sink.out.last_mut()) {
        d.hint = Some(format!(
            "replace instance `{name}` by one of {} (the replacement the stability mark names; in RTSystemEditor, then save the system again), or keep it knowingly until it is removed",
            crate::quote::Code(r)
        ));
    }
}

fn instance_named_id(cat: &Catalog, c: &crate::model::system::SystemComponent) -> Option<String> {
    use crate::catalog::facet_key;
    let parts = c.id_parts.as_ref()?;
    let named = non_empty(&parts.name)?;
    let stem = named.trim_end_matches(|ch: char| ch.is_ascii_digit());
    if stem.is_empty() || stem == named {
        return None;
    }
    let (vendor, category) = (
        facet_key(non_empty(&parts.vendor).unwrap_or("")),
        facet_key(non_empty(&parts.category).unwrap_or("")),
    );
    let k = cat.components.iter().find(|k| {
        facet_key(k.profile.name()) == facet_key(stem)
            && facet_key(non_empty(&k.profile.basic_info.vendor).unwrap_or("")) == vendor
            && facet_key(non_empty(&k.profile.basic_info.category).unwrap_or("")) == category
    })?;
    // The id as the profile writes it (the catalogue's entry id may carry `@source`).
    let written = k.id.split('@').next().unwrap_or_default();
    Some(format!(
        "the id names `{named}`, an instance's name (as Choreonoid saves it); the input has the component `{}` ({}, id `{written}`): write that id in the system file",
        k.profile.name(),
        k.source
    ))
}
