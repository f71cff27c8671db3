//! RT System profiles in the catalogue: each system with its slug and the links from its
//! instances to the component profiles of the catalogue and from its connector ends to their
//! ports (issue 16).
//!
//! An instance names its component by the `RTC:vendor:category:name:version` id of the
//! component's RTC.xml; it is matched by vendor, category and name (compared like facets: case
//! and white space do not matter), the version is only compared (a different one is *drift*).
//! Real files truncate or damage categories (`RTC:Vendor:Categ:Name:1.0`), so an instance whose
//! full key matches nothing is matched by vendor and name when exactly one component has them.
//! Links are kept by component slug and port name (not by vector index) in what is serialised,
//! so `catalog.json` stays readable when the component list changes.

use super::{facet_key, qualifier_slug, slugify, unique_slugs, Catalog, Component};
use super::{ComponentIx, Ix};
use crate::model::system::{PortEnd, RtSystem, SystemComponent};
use crate::model::{non_empty, PortDirection};
use crate::parse::SourceFormat;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// An RT System profile read from one file, ready for the catalogue.
#[derive(Debug, Clone)]
pub struct LoadedSystem {
    pub source: String,
    pub format: SourceFormat,
    pub system: Box<RtSystem>,
    /// Its history when it is known already (read back, or kept across a rebuild).
    pub history: Vec<super::history::Entry>,
}

impl From<System> for LoadedSystem {
    /// A system of a catalogue, to be attached again (its links are made anew, its history
    /// kept).
    fn from(s: System) -> LoadedSystem {
        LoadedSystem {
            source: s.source,
            format: s.format,
            system: s.profile,
            history: s.history,
        }
    }
}

/// One RT System profile of the catalogue and its resolved links.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct System {
    /// Path of the profile relative to the input directory, forward slashes.
    pub source: String,
    /// The `[[source]]` repository the profile was read from (none: the input directory).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub origin: Option<crate::model::Origin>,
    pub format: SourceFormat,
    /// File-name-safe, stable identifier of the system's page (`systems/<slug>.html`).
    pub slug: String,
    /// What tells this system apart from others of the same name (RTSystemEditor names most
    /// systems `RTSystem`): the folders (else the file name) where their paths differ.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub qualifier: Option<String>,
    /// One per instance (`system.components`), in the same order.
    pub instances: Vec<InstanceLink>,
    /// One per data port connector, in the same order.
    pub data_connectors: Vec<ConnectorLink>,
    /// One per service port connector, in the same order.
    pub service_connectors: Vec<ConnectorLink>,
    /// Its past versions, newest first, each with the changes `rtcdoc diff` finds between two
    /// versions of a system ([`super::history`]); empty when the history is off or no
    /// repository holds the file.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub history: Vec<super::history::Entry>,
    /// The system as read: every value of the file.
    pub profile: Box<RtSystem>,
}

/// How an instance was matched to a component profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum MatchKind {
    /// Vendor, category and name agree.
    Exact,
    /// Vendor and name agree, the category does not (a damaged or truncated id); the only
    /// component with that vendor and name.
    VendorName,
}

/// Where an instance's component is in the catalogue.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct InstanceLink {
    /// The component's handle; use [`Catalog::instance_component`].
    #[serde(skip)]
    pub component_index: Option<ComponentIx>,
    /// The component's id ([`crate::catalog::Component::id`]), when it is in the catalogue.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub component: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub matched_by: Option<MatchKind>,
    /// The catalogue component's version when the instance's id names another one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub version_drift: Option<String>,
    /// Anchor of the instance's row on the system page, unique within the page.
    pub anchor: String,
}

/// Which port of a component a connector end names.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", tag = "kind")]
pub enum PortLink {
    /// Index into the component's `data_ports`.
    Data {
        #[serde(skip)]
        index: usize,
        name: String,
    },
    /// Index into the component's `service_ports`.
    Service {
        #[serde(skip)]
        index: usize,
        name: String,
    },
}

/// One end of a connector, resolved.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct EndLink {
    /// Index into `system.components` of the instance the end names.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub instance: Option<usize>,
    /// The port of the instance's component profile (when that is in the catalogue and has it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub port: Option<PortLink>,
}

/// Both ends of a connector, resolved.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct ConnectorLink {
    pub source: EndLink,
    pub target: EndLink,
}

/// A port of an instance as the diagram and the tables show it: from the component profile
/// when it is in the catalogue, else from the system file (its port lists and connector ends).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InstancePort {
    /// The port's own name (without `Instance0.`).
    pub name: String,
    pub kind: InstancePortKind,
    /// The port of the component profile.
    pub link: Option<PortLink>,
}

/// What an instance's port is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InstancePortKind {
    /// A data port: in or out (from the profile, else from the connectors that use it).
    Data(Option<PortDirection>),
    Service,
}

/// The key components are matched on: (vendor, category, name), compared as facets are.
fn key3(vendor: &str, category: &str, name: &str) -> (String, String, String) {
    (facet_key(vendor), facet_key(category), facet_key(name))
}

/// The name of a connector end's port without the instance prefix.
pub fn end_port_name(e: &PortEnd) -> &str {
    non_empty(&e.short_name)
        .or_else(|| non_empty(&e.port_name))
        .unwrap_or("")
}

/// For an instance whose component is not in the catalogue, whether the system file lists
/// `port` among the instance's ports of its kind (data or service), each compared by its last
/// `.` part as the catalogue finds ports; `None` when it lists no port of that kind (an
/// instance may list only its data ports). `rtcdoc check` reports a connector end at a port
/// not listed (RTC601), and the drawings mark that port.
pub fn instance_lists_port(c: &SystemComponent, service: bool, port: &str) -> Option<bool> {
    let ports = if service {
        &c.service_ports
    } else {
        &c.data_ports
    };
    let want = port_own_part(port.trim());
    (!ports.is_empty()).then(|| {
        ports
            .iter()
            .any(|p| port_own_part(p.own_name().trim()) == want)
    })
}

/// A port name's own part: the text after its last `.` (`Instance0.out` → `out`).
pub fn port_own_part(name: &str) -> &str {
    name.rsplit('.').next().unwrap_or(name)
}

/// The port of component `c` named `name` (its own name or `Instance.name`).
fn find_port(c: &Component, name: &str) -> Option<PortLink> {
    let candidates = [name, port_own_part(name)];
    let p = &c.profile;
    for n in candidates {
        let named = |name: Option<&str>| name.map(str::trim) == Some(n);
        let name = n.to_string();
        if let Some(index) = p.data_ports.iter().position(|p| named(p.name.as_deref())) {
            return Some(PortLink::Data { index, name });
        }
        if let Some(index) = p
            .service_ports
            .iter()
            .position(|p| named(p.name.as_deref()))
        {
            return Some(PortLink::Service { index, name });
        }
    }
    None
}

impl Catalog {
    /// Takes in the RT System profiles read for this catalogue: each gets a slug and its links
    /// to the components and ports of the catalogue. Their pages join the page list when it is
    /// made ([`Catalog::assemble`], [`Catalog::bound`]).
    pub fn attach_systems(&mut self, mut loaded: Vec<LoadedSystem>) {
        loaded.sort_by(|a, b| a.source.cmp(&b.source));
        let mut exact: ByKey = HashMap::new();
        let mut by_vendor_name: ByVendorName = HashMap::new();
        // The components are keyed only when there are systems to match.
        let components = if loaded.is_empty() {
            &[][..]
        } else {
            &self.components[..]
        };
        for (i, c) in Ix::enumerate(components) {
            let b = &c.profile.basic_info;
            let v = non_empty(&b.vendor).unwrap_or("");
            let cat = non_empty(&b.category).unwrap_or("");
            let n = non_empty(&b.name).unwrap_or("");
            let own = key3(v, cat, n);
            // The instance's id is the `rtc:id` of the component's RTC.xml, which may say
            // another vendor or category than BasicInfo (RTC202): match that too.
            if let Some(p) = c
                .profile
                .id
                .as_deref()
                .and_then(|id| crate::model::IdParts::parse(id, b))
            {
                let k = key3(p.vendor, p.category, p.name);
                if k != own {
                    exact.entry(k).or_default().push(i);
                }
            }
            exact.entry(own).or_default().push(i);
            by_vendor_name
                .entry((facet_key(v), facet_key(n)))
                .or_default()
                .push(i);
        }
        let names: Vec<(String, String)> = loaded
            .iter()
            .map(|l| (l.system.name().to_string(), l.source.clone()))
            .collect();
        let qualifiers = name_qualifiers(&names);
        let slugs = system_slugs(&names, &qualifiers);
        let mut systems = Vec::with_capacity(loaded.len());
        for ((l, slug), qualifier) in loaded.into_iter().zip(slugs).zip(qualifiers) {
            let sys = &l.system;
            let instances: Vec<InstanceLink> = {
                let mut seen: HashMap<String, usize> = HashMap::new();
                sys.components
                    .iter()
                    .map(|inst| {
                        let mut link =
                            self.match_instance(inst, &l.source, (&exact, &by_vendor_name));
                        let base = format!(
                            "inst-{}",
                            slugify(non_empty(&inst.instance_name).unwrap_or("instance"))
                        );
                        let n = seen.entry(base.clone()).or_default();
                        *n += 1;
                        link.anchor = if *n > 1 { format!("{base}-{n}") } else { base };
                        link
                    })
                    .collect()
            };
            let end = |e: &Option<PortEnd>| -> EndLink {
                let Some(e) = e else {
                    return EndLink::default();
                };
                let instance = non_empty(&e.instance_name).and_then(|n| {
                    sys.components
                        .iter()
                        .position(|c| c.instance_name.as_deref() == Some(n))
                });
                let port = instance
                    .and_then(|i| instances[i].component_index)
                    .and_then(|ci| find_port(&self[ci], end_port_name(e)));
                EndLink { instance, port }
            };
            let link = |source, target| ConnectorLink {
                source: end(source),
                target: end(target),
            };
            let data_connectors = sys
                .data_port_connectors
                .iter()
                .map(|c| link(&c.source, &c.target))
                .collect();
            let service_connectors = sys
                .service_port_connectors
                .iter()
                .map(|c| link(&c.source, &c.target))
                .collect();
            systems.push(System {
                source: l.source,
                origin: None,
                format: l.format,
                slug,
                qualifier,
                instances,
                data_connectors,
                service_connectors,
                history: l.history,
                profile: l.system,
            });
        }
        self.systems = systems;
    }

    fn match_instance(
        &self,
        inst: &SystemComponent,
        system_source: &str,
        (exact, by_vendor_name): (&ByKey, &ByVendorName),
    ) -> InstanceLink {
        let Some(parts) = &inst.id_parts else {
            return InstanceLink::default();
        };
        let v = non_empty(&parts.vendor).unwrap_or("");
        let cat = non_empty(&parts.category).unwrap_or("");
        let n = non_empty(&parts.name).unwrap_or("");
        let version = non_empty(&parts.version).unwrap_or("").trim();
        let (found, kind) = match exact.get(&key3(v, cat, n)) {
            Some(list) => (Some(list), MatchKind::Exact),
            None => match by_vendor_name.get(&(facet_key(v), facet_key(n))) {
                Some(list) if list.len() == 1 => (Some(list), MatchKind::VendorName),
                _ => (None, MatchKind::Exact),
            },
        };
        let Some(list) = found else {
            return InstanceLink::default();
        };
        // Several profiles of one id (the C++ and Python variants, copies in other
        // repositories): of those of the same version (else of all), the nearest to the system
        // file (the most folders in common), the first by path among equally near ones.
        let version_of = |ci: ComponentIx| {
            non_empty(&self[ci].profile.basic_info.version)
                .unwrap_or("")
                .trim()
                .to_string()
        };
        let same: Vec<ComponentIx> = list
            .iter()
            .copied()
            .filter(|&ci| version_of(ci) == version)
            .collect();
        let candidates = if same.is_empty() { list } else { &same };
        let nearness = |ci: ComponentIx| shared_folders(&self[ci].source, system_source);
        let ci = candidates
            .iter()
            .copied()
            .rev()
            .max_by_key(|&ci| nearness(ci))
            .unwrap_or(list[0]);
        let theirs = version_of(ci);
        InstanceLink {
            component_index: Some(ci),
            component: Some(self[ci].id.to_string()),
            matched_by: Some(kind),
            version_drift: (!version.is_empty() && theirs != version).then_some(theirs),
            anchor: String::new(),
        }
    }

    /// The component profile of instance `i` of `sys`, when it is in the catalogue.
    pub fn instance_component(&self, sys: &System, i: usize) -> Option<&Component> {
        sys.instances.get(i)?.component_index.map(|ci| &self[ci])
    }

    /// The systems with an instance of component `ci`, with the instance names, in system order.
    pub fn systems_using(&self, ci: ComponentIx) -> Vec<(&System, Vec<&str>)> {
        self.systems
            .iter()
            .filter_map(|s| {
                let names: Vec<&str> = s
                    .instances
                    .iter()
                    .zip(&s.profile.components)
                    .filter(|(l, _)| l.component_index == Some(ci))
                    .map(|(_, c)| non_empty(&c.instance_name).unwrap_or(""))
                    .collect();
                (!names.is_empty()).then_some((s, names))
            })
            .collect()
    }

    /// The data connectors carrying type `name` (any spelling): (system, connector index).
    pub fn connectors_carrying(&self, name: &str) -> Vec<(&System, usize)> {
        let want = self.idl.canonical_name(name);
        let mut out = Vec::new();
        for s in &self.systems {
            for (k, c) in s.profile.data_port_connectors.iter().enumerate() {
                if let Some(t) = non_empty(&c.data_type) {
                    if self.idl.canonical_name(t) == want {
                        out.push((s, k));
                    }
                }
            }
        }
        out
    }

    /// For each data connector of `sys`, whether the file saved it in-port first: its source
    /// end an in-port and its target end an out-port ([`Catalog::instance_ports`]), as
    /// RTSystemEditor saves the end the user dragged from as the source. Diagrams and tables
    /// show such a connector from its out-port to its in-port, the way data flows.
    pub fn reversed_data_connectors(&self, sys: &System) -> Vec<bool> {
        let mut ports: HashMap<usize, Vec<InstancePort>> = HashMap::new();
        let mut direction = |i: Option<usize>, e: &Option<PortEnd>| -> Option<PortDirection> {
            let (i, e) = (i?, e.as_ref()?);
            let name = end_port_name(e);
            ports
                .entry(i)
                .or_insert_with(|| self.instance_ports(sys, i))
                .iter()
                .find_map(|p| match p.kind {
                    InstancePortKind::Data(d) if p.name == name => Some(d),
                    _ => None,
                })?
        };
        sys.profile
            .data_port_connectors
            .iter()
            .zip(&sys.data_connectors)
            .map(|(c, l)| {
                direction(l.source.instance, &c.source) == Some(PortDirection::In)
                    && direction(l.target.instance, &c.target) == Some(PortDirection::Out)
            })
            .collect()
    }

    /// The ports of instance `i` of `sys`: the component profile's (data ports, then service
    /// ports) when it is in the catalogue, then any other port the system file names for the
    /// instance (its port lists, its connector ends), in the order first met.
    pub fn instance_ports(&self, sys: &System, i: usize) -> Vec<InstancePort> {
        let mut out: Vec<InstancePort> = Vec::new();
        if let Some(c) = self.instance_component(sys, i) {
            let name =
                |n: &Option<crate::model::Text>| non_empty(n).unwrap_or("").trim().to_string();
            let data = c.profile.data_ports.iter().enumerate().map(|(index, p)| {
                let link = PortLink::Data {
                    index,
                    name: name(&p.name),
                };
                (link, InstancePortKind::Data(p.direction()))
            });
            let service = c
                .profile
                .service_ports
                .iter()
                .enumerate()
                .map(|(index, p)| {
                    let link = PortLink::Service {
                        index,
                        name: name(&p.name),
                    };
                    (link, InstancePortKind::Service)
                });
            for (link, kind) in data.chain(service) {
                let (PortLink::Data { name, .. } | PortLink::Service { name, .. }) = &link;
                out.push(InstancePort {
                    name: name.clone(),
                    kind,
                    link: Some(link),
                });
            }
        }
        let inst = &sys.profile.components[i];
        let mut add = |name: &str, kind: InstancePortKind| {
            if name.is_empty() {
                return;
            }
            match out.iter_mut().find(|p| p.name == name) {
                Some(p) => {
                    // A data port's direction, when the profile and the port lists left it open.
                    if p.kind == InstancePortKind::Data(None) {
                        if let InstancePortKind::Data(d) = kind {
                            p.kind = InstancePortKind::Data(d);
                        }
                    }
                }
                None => out.push(InstancePort {
                    name: name.to_string(),
                    kind,
                    link: None,
                }),
            }
        };
        // RTSystemEditor records each port's kind as the property `port.port_type`
        // (`DataInPort`, `DataOutPort`, `CorbaPort`): a port that no connector ends at still
        // gets its side when the component is not in the catalogue.
        for p in &inst.data_ports {
            let kind = p.property("port.port_type").and_then(PortDirection::parse);
            add(p.own_name(), InstancePortKind::Data(kind));
        }
        for p in &inst.service_ports {
            add(p.own_name(), InstancePortKind::Service);
        }
        for (k, c) in sys.profile.data_port_connectors.iter().enumerate() {
            let l = &sys.data_connectors[k];
            if l.source.instance == Some(i) {
                if let Some(e) = &c.source {
                    add(
                        end_port_name(e),
                        InstancePortKind::Data(Some(PortDirection::Out)),
                    );
                }
            }
            if l.target.instance == Some(i) {
                if let Some(e) = &c.target {
                    add(
                        end_port_name(e),
                        InstancePortKind::Data(Some(PortDirection::In)),
                    );
                }
            }
        }
        for (k, c) in sys.profile.service_port_connectors.iter().enumerate() {
            let l = &sys.service_connectors[k];
            for (e, el) in [(&c.source, &l.source), (&c.target, &l.target)] {
                if el.instance == Some(i) {
                    if let Some(e) = e {
                        add(end_port_name(e), InstancePortKind::Service);
                    }
                }
            }
        }
        out
    }
}

/// What a configuration value of an instance is against its component's declaration.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ConfigCheck {
    /// Of the declared type and within the constraint (or nothing to check it against).
    Ok,
    /// The component declares no parameter of this name.
    Undeclared,
    /// Not a value of the declared type; the text says why.
    BadType(String),
    /// Outside the declared constraint; the text names the constraint and what failed.
    Violated(String),
}

/// Checks `value`, given to parameter `name` of component `c` by a system, against the
/// parameter's declared type and constraint (as `check` does for default values).
pub fn check_configuration(c: &Component, name: &str, value: &str) -> ConfigCheck {
    use crate::constraint::{self, Verdict};
    use crate::value::{self, ValueType};
    let Some(conf) = c
        .profile
        .configurations()
        .iter()
        .find(|k| k.name.as_deref().map(str::trim) == Some(name.trim()))
    else {
        return ConfigCheck::Undeclared;
    };
    let ty = non_empty(&conf.type_).map_or(ValueType::Unknown, ValueType::parse);
    if let Err(why) = value::check_value(ty, value) {
        return ConfigCheck::BadType(format!(
            "not a valid {}: {why}",
            conf.type_.as_deref().unwrap_or("").trim()
        ));
    }
    let Some(k) = conf
        .constraint
        .as_ref()
        .filter(|k| k.placeholder().is_none())
    else {
        return ConfigCheck::Ok;
    };
    if !constraint::problems(k, ty).is_empty() {
        return ConfigCheck::Ok;
    }
    match constraint::evaluate(k, value, constraint::widget_type(conf.widget(), ty)) {
        Verdict::Violated(why) => ConfigCheck::Violated(format!(
            "outside the constraint `{}`: {why}",
            constraint::describe(k)
        )),
        _ => ConfigCheck::Ok,
    }
}

/// Every value of the system as (path, value) rows (keys sorted within a node, lists in document
/// order): the full record that the pages summarise. Reader bookkeeping (positions, derived fields) is left out; so are
/// host data (private properties, naming paths) unless `show_host`.
pub fn all_values(p: &RtSystem, show_host: bool) -> Vec<(String, String)> {
    fn walk(v: &serde_json::Value, path: &str, show_host: bool, out: &mut Vec<(String, String)>) {
        use serde_json::Value as J;
        match v {
            J::Object(m) => {
                // Host data was stripped ([`strip_host_data`]): a property it emptied is
                // left out whole.
                if !show_host && m.get("private") == Some(&J::Bool(true)) {
                    return;
                }
                for (k, x) in m {
                    if matches!(
                        k.as_str(),
                        "pos" | "idParts" | "shortName" | "dataTypeScoped" | "pseudo" | "private"
                    ) {
                        continue;
                    }
                    let p = if path.is_empty() {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    walk(x, &p, show_host, out);
                }
            }
            J::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    walk(x, &format!("{path}[{i}]"), show_host, out);
                }
            }
            J::Null => {}
            J::String(s) => out.push((path.to_string(), s.clone())),
            other => out.push((path.to_string(), other.to_string())),
        }
    }
    let mut out = Vec::new();
    let value = if show_host {
        serde_json::to_value(p)
    } else {
        let mut public = p.clone();
        strip_host_data(&mut public);
        serde_json::to_value(&public)
    };
    if let Ok(v) = value {
        walk(&v, "", show_host, &mut out);
    }
    out
}

/// A naming path with the host in it: `localhost:2809/Camera0.rtc`, `lab-pc/Camera0.rtc` (the
/// name server's default port left out, as RTSystemEditor writes `COMPONENT_PATH_ID`),
/// `150.29.145.246/ctx.host_cxt/Camera0.rtc`, also after `rtcname://` or `rtcloc://`; the
/// `COMPONENT_PATH_ID` of connector ends, `pathUri`. Host data, like the endpoints the reader
/// flags as private. Without a port, the last segment must be a component (`….rtc`), so that
/// text such as `N/A` or `in/out` is not taken for a host.
pub fn is_naming_path(v: &str) -> bool {
    let v = v.trim();
    let v = ["rtcname://", "rtcloc://"]
        .iter()
        .find_map(|scheme| v.strip_prefix(scheme))
        .unwrap_or(v);
    let Some((host, path)) = v.split_once('/') else {
        return false;
    };
    crate::model::system::is_private_property(None, Some(host))
        || (is_host_name(host)
            && path
                .rsplit('/')
                .next()
                .is_some_and(|leaf| leaf.len() > 4 && leaf.ends_with(".rtc")))
}

/// A host name or IPv4 address as naming paths hold it: letters, digits, `-` and `.`,
/// starting with a letter or digit.
fn is_host_name(h: &str) -> bool {
    h.bytes().next().is_some_and(|b| b.is_ascii_alphanumeric())
        && h.len() <= 253
        && h.bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'.')
}

/// A property that is host data: flagged private by the reader (IORs, host names,
/// endpoints) or holding a naming path.
fn is_host_value(q: &crate::model::system::SystemProperty) -> bool {
    q.private || q.value.as_deref().is_some_and(is_naming_path)
}

/// How many host values the pages and the JSON leave out of `p` unless asked to show them:
/// private properties, properties whose value is a naming path, and instances' `pathUri`.
pub fn host_values(p: &RtSystem) -> usize {
    p.all_properties()
        .iter()
        .filter(|q| is_host_value(q))
        .count()
        + p.components
            .iter()
            .filter(|c| non_empty(&c.path_uri).is_some())
            .count()
}

/// Calls `f` on every property anywhere in `p` (the nodes of [`RtSystem::all_properties`]).
fn for_each_property_mut(
    p: &mut RtSystem,
    f: &mut dyn FnMut(&mut crate::model::system::SystemProperty),
) {
    use crate::model::system::TargetComponent;
    fn target(
        t: &mut TargetComponent,
        f: &mut dyn FnMut(&mut crate::model::system::SystemProperty),
    ) {
        t.properties.iter_mut().for_each(&mut *f);
    }
    fn end(e: &mut Option<PortEnd>, f: &mut dyn FnMut(&mut crate::model::system::SystemProperty)) {
        if let Some(e) = e {
            e.properties.iter_mut().for_each(&mut *f);
        }
    }
    p.properties.iter_mut().for_each(&mut *f);
    for c in &mut p.components {
        c.properties.iter_mut().for_each(&mut *f);
        for port in c.data_ports.iter_mut().chain(c.service_ports.iter_mut()) {
            port.properties.iter_mut().for_each(&mut *f);
        }
        for ec in &mut c.execution_contexts {
            ec.properties.iter_mut().for_each(&mut *f);
            ec.participants.iter_mut().for_each(|t| target(t, f));
        }
        c.participants.iter_mut().for_each(|t| target(t, f));
    }
    for g in &mut p.groups {
        g.members.iter_mut().for_each(|t| target(t, f));
    }
    for d in &mut p.data_port_connectors {
        d.properties.iter_mut().for_each(&mut *f);
        end(&mut d.source, f);
        end(&mut d.target, f);
    }
    for s in &mut p.service_port_connectors {
        s.properties.iter_mut().for_each(&mut *f);
        end(&mut s.source, f);
        end(&mut s.target, f);
    }
    for o in &mut p.orders {
        for t in &mut o.targets {
            t.properties.iter_mut().for_each(&mut *f);
            if let Some(tc) = &mut t.target_component {
                target(tc, f);
            }
            if let Some(pr) = &mut t.preceding {
                pr.preceding_components
                    .iter_mut()
                    .for_each(|t| target(t, f));
            }
        }
    }
}

/// Drops the host data of `p`: the values of private properties and of naming-path
/// properties (`value` absent; the name stays and `private` is set, so a reader sees that
/// something was there), and instances' `pathUri`.
pub fn strip_host_data(p: &mut RtSystem) {
    for_each_property_mut(p, &mut |q| {
        if is_host_value(q) {
            q.private = true;
            q.value = None;
        }
    });
    for c in &mut p.components {
        c.path_uri = None;
    }
}

/// The page slugs of systems `names` (name, source): a name used once keeps its plain slug; a
/// system that shares its name with others gets its qualifier in the slug as in its title
/// (`defaultsystem01-kobuki` for `DefaultSystem01 (kobuki)`), as a component does; a slug that
/// still collides (names differing in case only, an overlong one) falls back to a hash of the
/// file, and a number when even that does ([`super::claim_slugs`]: the plain slugs first).
fn system_slugs(names: &[(String, String)], qualifiers: &[Option<String>]) -> Vec<String> {
    let hashed = unique_slugs(names);
    let bases = names
        .iter()
        .zip(qualifiers)
        .zip(hashed)
        .map(|(((name, _), q), h)| match q {
            Some(q) => {
                let s = format!("{}-{}", slugify(name), qualifier_slug(q));
                if s.len() > 96 {
                    h
                } else {
                    s
                }
            }
            None => h,
        });
    let bases: Vec<String> = bases.collect();
    super::claim_slugs(&bases, |i| qualifiers[i].is_none())
}

/// For each (name, source): what tells it apart from the others of its name, if any
/// ([`crate::catalog::folder_qualifiers`] of their paths).
fn name_qualifiers(names: &[(String, String)]) -> Vec<Option<String>> {
    let mut by_name: HashMap<&str, Vec<usize>> = HashMap::new();
    for (i, (name, _)) in names.iter().enumerate() {
        by_name.entry(name.as_str()).or_default().push(i);
    }
    let mut out = vec![None; names.len()];
    for members in by_name.values().filter(|m| m.len() > 1) {
        let sources: Vec<&str> = members.iter().map(|&i| names[i].1.as_str()).collect();
        for (&i, q) in members
            .iter()
            .zip(crate::catalog::folder_qualifiers(&sources))
        {
            out[i] = Some(q);
        }
    }
    out
}

impl System {
    /// The name, with the qualifier when others share it: `RTSystem (demoEV3)`.
    pub fn display_name(&self) -> std::borrow::Cow<'_, str> {
        match &self.qualifier {
            Some(q) => format!("{} ({q})", self.profile.name()).into(),
            None => self.profile.name().into(),
        }
    }

    /// A copy without host data ([`strip_host_data`]), for published output.
    pub fn without_host_data(&self) -> System {
        let mut s = self.clone();
        strip_host_data(&mut s.profile);
        s
    }
}

/// The components by their (vendor, category, name) key.
type ByKey = HashMap<(String, String, String), Vec<ComponentIx>>;
/// The components by their (vendor, name) key.
type ByVendorName = HashMap<(String, String), Vec<ComponentIx>>;

/// How many leading folders the paths `a` and `b` have in common (`a/b/x.xml` and
/// `a/b/c/y.xml`: 2).
fn shared_folders(a: &str, b: &str) -> usize {
    // Catalogue paths are written with `/`.
    fn folders(p: &str) -> std::str::Split<'_, char> {
        p.rsplit_once('/').map_or("", |(d, _)| d).split('/')
    }
    folders(a)
        .zip(folders(b))
        .take_while(|(x, y)| x == y)
        .count()
}
