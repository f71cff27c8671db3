//! Typed model of an RT System profile (`RtsProfile`, written by RTSystemEditor; YAML form of
//! rtsprofile/rtshell). See `spec/NOTES.md`, "RT System profiles".
//!
//! Like [`crate::model`] for component profiles, the model is plain data: every value is kept as
//! the file wrote it (`Some("")` for an empty attribute), typed views are methods, and whatever
//! the schema does not define is kept in an `extra` list on the nearest node. On top of the
//! values as written, the reader adds a few derived fields that later stages need and real
//! files make hard to compute: the parts of damaged ids, port names without their
//! `Instance0.` prefix, the scoped name of a repository-id data type, pseudo configuration sets
//! and private host data.

use crate::model::{non_empty, parse_bool, Extras, Pos, Text};
use serde::{Deserialize, Serialize};

node! {
    /// The whole system (`rts:RtsProfile`).
    pub struct RtSystem {
        /// `RTSystem:<vendor>:<name>:<version>` as written.
        pub id: Option<Text>,
        /// The parts of `id`, when they can be told apart (also from damaged ids).
        pub id_parts: Option<SystemIdParts>,
        /// Version of the profile format (`0.2`).
        pub version: Option<Text>,
        #[serde(rename = "abstract")]
        pub abstract_: Option<Text>,
        /// As written (`xsd:dateTime`); YAML date maps are turned into the same ISO form.
        pub creation_date: Option<Text>,
        pub update_date: Option<Text>,
        /// `rtsExt:comment`.
        pub comment: Option<Text>,
        /// `rtsExt:VersionUpLogs`, in document order.
        pub version_up_logs: Vec<Text>,
        /// `rtsExt:Properties` of the system.
        pub properties: Vec<SystemProperty>,
        /// `rtsExt:Systems`: sub-systems by path.
        pub systems: Vec<SubSystem>,
        /// `rts:Components`, one per component instance, in document order.
        pub components: Vec<SystemComponent>,
        pub groups: Vec<Group>,
        pub data_port_connectors: Vec<DataPortConnector>,
        pub service_port_connectors: Vec<ServicePortConnector>,
        /// `StartUp`, `ShutDown`, `Activation`, …: in [`OrderKind`] order (then document order).
        pub orders: Vec<Order>,
    }
}

/// How an id was read.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum IdForm {
    /// The documented form (`RTSystem:v:n:ver`, `RTC:v:c:n:ver`).
    #[default]
    Standard,
    /// The old dotted component form `RTC:vendor.category.name:version` (RTCBuilder 0.1).
    Dotted,
    /// A damaged id (`RTSystem :Vendor.Name.1.0`, missing or extra parts) whose parts were
    /// recovered by a best guess.
    Repaired,
}

/// The parts of an `RTSystem:<vendor>:<name>:<version>` id.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct SystemIdParts {
    pub vendor: Option<Text>,
    pub name: Option<Text>,
    pub version: Option<Text>,
    pub form: IdForm,
}

impl SystemIdParts {
    /// Parses a system id, tolerating the damage real files show: white space before the `:`
    /// (`RTSystem :…`), dots for colons (`Vendor.Name.1.0`, whose trailing numeric segments are
    /// the version), too few or too many parts. `None` when the id does not start with
    /// `RTSystem` or has nothing after it.
    pub fn parse(id: &str) -> Option<SystemIdParts> {
        let t = id.trim();
        let head = t.get(..8)?;
        if !head.eq_ignore_ascii_case("RTSystem") {
            return None;
        }
        let after = &t[8..];
        let rest = after.trim_start().strip_prefix(':')?;
        let mut form = if after.starts_with(':') && head == "RTSystem" {
            IdForm::Standard
        } else {
            IdForm::Repaired
        };
        let parts: Vec<&str> = rest.split(':').collect();
        let (vendor, name, version) = match parts.as_slice() {
            [v, n, ver] => (Some(*v), Some(*n), Some(*ver)),
            [one] if one.trim().is_empty() => return None,
            [one] => {
                form = IdForm::Repaired;
                let segs: Vec<&str> = one.split('.').collect();
                // The version is the run of numeric segments at the end, leaving a name.
                let numeric = segs
                    .iter()
                    .rev()
                    .take_while(|s| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()))
                    .count()
                    .min(segs.len().saturating_sub(1));
                let (body, ver) = segs.split_at(segs.len() - numeric);
                let version = (!ver.is_empty()).then(|| ver.join("."));
                let (vendor, name) = match body {
                    [] => (None, None),
                    [n] => (None, Some(n.to_string())),
                    [v @ .., n] => (Some(v.join(".")), Some(n.to_string())),
                };
                return Some(SystemIdParts {
                    vendor: vendor.map(Text::from),
                    name: name.map(Text::from),
                    version: version.map(Text::from),
                    form,
                });
            }
            [a, b] => {
                form = IdForm::Repaired;
                if looks_like_version(b) {
                    (None, Some(*a), Some(*b))
                } else {
                    (Some(*a), Some(*b), None)
                }
            }
            [v @ .., n, ver] => {
                form = IdForm::Repaired;
                return Some(SystemIdParts {
                    vendor: Some(v.join(":").into()),
                    name: Some((*n).into()),
                    version: Some((*ver).into()),
                    form,
                });
            }
            [] => return None,
        };
        Some(SystemIdParts {
            vendor: vendor.map(Text::from),
            name: name.map(Text::from),
            version: version.map(Text::from),
            form,
        })
    }
}

/// The parts of a component id, `RTC:<vendor>:<category>:<name>:<version>` (the same string as
/// in the component's RTC.xml) or the old dotted `RTC:vendor.category.name:version`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct ComponentIdParts {
    pub vendor: Option<Text>,
    pub category: Option<Text>,
    pub name: Option<Text>,
    pub version: Option<Text>,
    pub form: IdForm,
}

impl ComponentIdParts {
    /// Parses a component id. The rule the `check` stage applies to component profiles
    /// (RTC201: five `:`-separated parts, the first `RTC`) gives [`IdForm::Standard`]; the
    /// dotted form of RTCBuilder 0.1 ([`IdForm::Dotted`]: the last dotted segment is the name,
    /// the one before it the category, the rest the vendor, which may hold dots itself) and ids
    /// with a missing category or extra `:` ([`IdForm::Repaired`]) are read too. `None` when
    /// the id does not start with `RTC:` or cannot be split.
    pub fn parse(id: &str) -> Option<ComponentIdParts> {
        let t = id.trim();
        let head = t.get(..3)?;
        if !head.eq_ignore_ascii_case("RTC") {
            return None;
        }
        let after = &t[3..];
        let rest = after.trim_start().strip_prefix(':')?;
        let repaired = !(head == "RTC" && after.starts_with(':'));
        let parts: Vec<&str> = rest.split(':').collect();
        let some = |s: &str| Some(Text::from(s));
        let standard = if repaired {
            IdForm::Repaired
        } else {
            IdForm::Standard
        };
        match parts.as_slice() {
            [v, c, n, ver] => Some(ComponentIdParts {
                vendor: some(v),
                category: some(c),
                name: some(n),
                version: some(ver),
                form: standard,
            }),
            [dotted, ver] => {
                let segs: Vec<&str> = dotted.split('.').collect();
                match segs.as_slice() {
                    [v @ .., c, n] if !v.is_empty() => Some(ComponentIdParts {
                        vendor: Some(v.join(".").into()),
                        category: some(c),
                        name: some(n),
                        version: some(ver),
                        form: if repaired {
                            IdForm::Repaired
                        } else {
                            IdForm::Dotted
                        },
                    }),
                    _ => None,
                }
            }
            [v, n, ver] => Some(ComponentIdParts {
                vendor: some(v),
                category: None,
                name: some(n),
                version: some(ver),
                form: IdForm::Repaired,
            }),
            [v @ .., c, n, ver] if v.len() > 1 => Some(ComponentIdParts {
                vendor: Some(v.join(":").into()),
                category: some(c),
                name: some(n),
                version: some(ver),
                form: IdForm::Repaired,
            }),
            _ => None,
        }
    }
}

fn looks_like_version(s: &str) -> bool {
    let s = s.trim();
    !s.is_empty()
        && s.bytes().all(|b| b.is_ascii_digit() || b == b'.')
        && s.bytes().any(|b| b.is_ascii_digit())
}

node! {
    /// `rtsExt:Properties` / `"rtsExt::properties"`: a free name/value pair, with the host-data flag.
    pub struct SystemProperty {
        pub name: Option<Text>,
        pub value: Option<Text>,
        /// Host names, IORs and CORBA endpoints of the machine the system was saved on: not
        /// published by default. See [`is_private_property`].
        pub private: bool,
    }
}

impl SystemProperty {
    /// A property with `private` computed from its name and value.
    pub fn new(name: Option<Text>, value: Option<Text>, pos: Pos, extra: Extras) -> Self {
        let private = is_private_property(name.as_deref(), value.as_deref());
        SystemProperty {
            name,
            value,
            private,
            pos,
            extra,
        }
    }
}

/// Whether a property carries private host data: its name is `os.hostname`, `os.release` or
/// `os.version` (the saving machine's kernel release and build, e.g. `4.15.0-32-generic`,
/// `#35~16.04.1-Ubuntu SMP …`), `corba.endpoint`, `corba.endpoints`, or ends in `.host`, `hostname` or an `ior` segment (`IOR`,
/// `dataport.corba_cdr.inport_ior`; `behavior` is not one), or its value is an IOR string
/// (`IOR:` + hex digits), a `host:port` endpoint (also `giop:tcp:host:port`, `[::1]:2809`,
/// and lists of them) or a name-service path in a host's context (`lab-pc.host_cxt/Cam0.rtc`,
/// what OpenRTM's default `naming.names` format `%h.host_cxt/%n.rtc` gives). Names compare
/// case-insensitively.
pub fn is_private_property(name: Option<&str>, value: Option<&str>) -> bool {
    if let Some(n) = name {
        let n = n.trim().to_ascii_lowercase();
        let last = n.rsplit(['.', '_', ':']).next().unwrap_or(&n);
        if matches!(
            n.as_str(),
            "os.hostname"
                | "os.release"
                | "os.version"
                | "corba.endpoint"
                | "corba.endpoints"
                | "host"
        ) || n.ends_with(".host")
            || n.ends_with("hostname")
            || last == "ior"
        {
            return true;
        }
    }
    value.is_some_and(|v| {
        is_ior(v)
            || v.split([',', ' ', ';'])
                .any(|p| is_endpoint(p) || in_host_context(p))
    })
}

/// A name-service path with a context named after a host: `lab-pc.host_cxt/Cam0.rtc`
/// (`%h.host_cxt`, OpenRTM's default, before it is filled in, names no host).
fn in_host_context(path: &str) -> bool {
    path.split('/').any(|c| {
        let c = c.trim().to_ascii_lowercase();
        c.strip_suffix(".host_cxt")
            .is_some_and(|host| !host.is_empty() && host != "%h")
    })
}

/// `IOR:` followed by hex digits (a stringified CORBA object reference).
pub fn is_ior(v: &str) -> bool {
    let v = v.trim();
    v.get(..4).is_some_and(|h| h.eq_ignore_ascii_case("IOR:"))
        && v.len() > 4
        && v[4..].bytes().all(|b| b.is_ascii_hexdigit())
}

/// `host:port` (host with a letter, or a dotted IPv4 address; port 1–5 digits), optionally
/// after `giop:tcp:` / `giop:ssl:` / `iiop:`, or `[ipv6]:port`.
fn is_endpoint(v: &str) -> bool {
    let mut v = v.trim();
    for p in [
        "giop:tcp:",
        "giop:ssl:",
        "giop:unix:",
        "iiop:",
        "corbaloc:iiop:",
    ] {
        if let Some(rest) = v.strip_prefix(p) {
            v = rest;
        }
    }
    let Some((host, port)) = v.rsplit_once(':') else {
        return false;
    };
    if port.is_empty() || port.len() > 5 || !port.bytes().all(|b| b.is_ascii_digit()) {
        return false;
    }
    if let Some(inner) = host.strip_prefix('[').and_then(|h| h.strip_suffix(']')) {
        return !inner.is_empty()
            && inner
                .bytes()
                .all(|b| b.is_ascii_hexdigit() || b == b':' || b == b'.');
    }
    if host.is_empty()
        || !host
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'-' | b'_'))
    {
        return false;
    }
    let ipv4 = {
        let segs: Vec<&str> = host.split('.').collect();
        segs.len() == 4
            && segs
                .iter()
                .all(|s| !s.is_empty() && s.len() <= 3 && s.bytes().all(|b| b.is_ascii_digit()))
    };
    ipv4 || host.bytes().any(|b| b.is_ascii_alphabetic())
}

node! {
    /// `rtsExt:Systems`: a sub-system by path.
    pub struct SubSystem {
        pub path: Option<Text>,
    }
}

node! {
    /// One component instance of the system (`rts:Components`).
    pub struct SystemComponent {
        /// The component's `RTC:…` id, as written (the same string as in its RTC.xml).
        pub id: Option<Text>,
        pub id_parts: Option<ComponentIdParts>,
        pub instance_name: Option<Text>,
        /// Naming path (`localhost:2809/X0.rtc`) or file URI.
        pub path_uri: Option<Text>,
        pub active_configuration_set: Option<Text>,
        /// `true` / `false` as written.
        pub is_required: Option<Text>,
        /// `None`, `PeriodicECShared`, `PeriodicStateShared`, `Grouping`, `FsmECShared`,
        /// `FsmStateShared` as written.
        pub composite_type: Option<Text>,
        pub comment: Option<Text>,
        /// `rtsExt:visible` as written.
        pub visible: Option<Text>,
        pub data_ports: Vec<SystemPort>,
        pub service_ports: Vec<SystemPort>,
        pub configuration_sets: Vec<SystemConfigurationSet>,
        pub execution_contexts: Vec<ExecutionContext>,
        /// Members of a composite component.
        pub participants: Vec<TargetComponent>,
        pub location: Option<Location>,
        pub properties: Vec<SystemProperty>,
    }
}

impl SystemComponent {
    /// The type the system file records for this instance's data port `port` (its own name):
    /// RTSystemEditor's `dataport.data_type` on the port.
    pub fn recorded_data_type(&self, port: &str) -> Option<&str> {
        self.data_ports
            .iter()
            .find(|p| p.own_name() == port)?
            .property("dataport.data_type")
    }
    /// The instance names of its participants (its members, as a composite), each once, in
    /// file order.
    pub fn member_names(&self) -> Vec<&str> {
        let mut names: Vec<&str> = Vec::new();
        for n in self
            .participants
            .iter()
            .filter_map(|t| non_empty(&t.instance_name))
        {
            if !names.contains(&n) {
                names.push(n);
            }
        }
        names
    }
    /// `isRequired` as a boolean (absent or invalid: `None`).
    pub fn required(&self) -> Option<bool> {
        parse_bool(self.is_required.as_deref())
    }
    /// The configuration set with id `id`.
    pub fn configuration_set(&self, id: &str) -> Option<&SystemConfigurationSet> {
        self.configuration_sets
            .iter()
            .find(|c| c.id.as_deref() == Some(id))
    }
    /// The active configuration set, when named and present.
    pub fn active_set(&self) -> Option<&SystemConfigurationSet> {
        self.configuration_set(non_empty(&self.active_configuration_set)?)
    }
}

node! {
    /// A data or service port of an instance (`rts:DataPorts` / `rts:ServicePorts`).
    pub struct SystemPort {
        /// As written: `Instance0.port` (RTSystemEditor) or `port` (other writers).
        pub name: Option<Text>,
        /// The port's own name, without the `<instanceName>.` prefix.
        pub short_name: Option<Text>,
        pub comment: Option<Text>,
        pub visible: Option<Text>,
        pub properties: Vec<SystemProperty>,
    }
}

impl SystemPort {
    /// The port's own name: without the `<instance>.` prefix, else as written.
    pub fn own_name(&self) -> &str {
        non_empty(&self.short_name)
            .or_else(|| non_empty(&self.name))
            .unwrap_or("")
    }

    /// The value of the port's property `key` (RTSystemEditor records `port.port_type`,
    /// `dataport.data_type` and others), trimmed; `None` when absent or empty.
    pub fn property(&self, key: &str) -> Option<&str> {
        self.properties
            .iter()
            .find(|q| non_empty(&q.name).map(str::trim) == Some(key))
            .and_then(|q| non_empty(&q.value))
            .map(str::trim)
    }
}

/// A port name without its `<instance>.` prefix (RTSystemEditor writes `Instance0.port`); other
/// names are returned as they are.
pub fn short_port_name<'a>(name: &'a str, instance: Option<&str>) -> &'a str {
    match instance.filter(|i| !i.is_empty()) {
        Some(i) => name
            .strip_prefix(i)
            .and_then(|r| r.strip_prefix('.'))
            .filter(|r| !r.is_empty())
            .unwrap_or(name),
        None => name,
    }
}

node! {
    /// `rts:ConfigurationSets`: the configuration of an instance, or a pseudo set.
    pub struct SystemConfigurationSet {
        pub id: Option<Text>,
        /// A set RTSystemEditor keeps for its own use, not a configuration: `__widget__` (editor
        /// widgets), `__constraints__` (value constraints), `__type__` (parameter types) — any id
        /// of the form `__name__`.
        pub pseudo: bool,
        pub configuration_data: Vec<ConfigurationData>,
    }
}

/// Whether a configuration set id names a pseudo set (`__widget__`, `__constraints__`, …).
pub fn is_pseudo_set(id: &str) -> bool {
    let id = id.trim();
    id.len() > 4 && id.starts_with("__") && id.ends_with("__")
}

node! {
    /// `rts:ConfigurationData`: one parameter value.
    pub struct ConfigurationData {
        pub name: Option<Text>,
        pub data: Option<Text>,
    }
}

node! {
    /// `rts:ExecutionContexts`.
    pub struct ExecutionContext {
        pub id: Option<Text>,
        /// `PERIODIC`, `EVENT_DRIVEN`, `PeriodicExecutionContext`, … as written.
        pub kind: Option<Text>,
        /// Hz, as written (`1000.0`).
        pub rate: Option<Text>,
        pub participants: Vec<TargetComponent>,
        pub properties: Vec<SystemProperty>,
    }
}

node! {
    /// A reference to a component instance (and optionally one of its execution contexts): EC
    /// participants, composite participants, group members, order targets, preceding components.
    pub struct TargetComponent {
        pub component_id: Option<Text>,
        pub instance_name: Option<Text>,
        /// The execution context id (order targets, preceding components).
        pub id: Option<Text>,
        pub properties: Vec<SystemProperty>,
    }
}

node! {
    /// `rtsExt:Location`: where RTSystemEditor drew the instance.
    pub struct Location {
        pub x: Option<Text>,
        pub y: Option<Text>,
        pub height: Option<Text>,
        pub width: Option<Text>,
        /// `DOWN`, `RIGHT`, `UP`, `LEFT` as written (real files also write `down`).
        pub direction: Option<Text>,
    }
}

/// The direction an instance's ports face (RTSystemEditor's rotation of the box).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum LocationDirection {
    Down,
    Right,
    Up,
    Left,
}

impl LocationDirection {
    /// `DOWN|RIGHT|UP|LEFT` in any case.
    pub fn parse(s: &str) -> Option<LocationDirection> {
        match s.trim().to_ascii_uppercase().as_str() {
            "DOWN" => Some(LocationDirection::Down),
            "RIGHT" => Some(LocationDirection::Right),
            "UP" => Some(LocationDirection::Up),
            "LEFT" => Some(LocationDirection::Left),
            _ => None,
        }
    }
}

impl Location {
    pub fn direction_kind(&self) -> Option<LocationDirection> {
        LocationDirection::parse(self.direction.as_deref()?)
    }
    /// `x`, `y` as integers, when both are.
    pub fn xy(&self) -> Option<(i64, i64)> {
        let int = |s: &Option<Text>| s.as_deref()?.trim().parse::<i64>().ok();
        Some((int(&self.x)?, int(&self.y)?))
    }
}

node! {
    /// `rts:Groups`.
    pub struct Group {
        pub group_id: Option<Text>,
        pub members: Vec<TargetComponent>,
    }
}

node! {
    /// One end of a connector (`sourceDataPort`, `targetServicePort`, …).
    pub struct PortEnd {
        pub component_id: Option<Text>,
        pub instance_name: Option<Text>,
        /// As written (`Instance0.port` or `port`).
        pub port_name: Option<Text>,
        /// The port's own name, without the `<instanceName>.` prefix.
        pub short_name: Option<Text>,
        pub properties: Vec<SystemProperty>,
    }
}

node! {
    /// `rts:DataPortConnectors`.
    pub struct DataPortConnector {
        pub connector_id: Option<Text>,
        pub name: Option<Text>,
        /// As written: `RTC::TimedLong`, or a repository id `IDL:RTC/TimedLong:1.0`.
        pub data_type: Option<Text>,
        /// The scoped IDL name (`RTC::TimedLong`) when `data_type` is a repository id.
        pub data_type_scoped: Option<Text>,
        pub interface_type: Option<Text>,
        pub dataflow_type: Option<Text>,
        pub subscription_type: Option<Text>,
        pub push_interval: Option<Text>,
        pub comment: Option<Text>,
        pub visible: Option<Text>,
        pub source: Option<PortEnd>,
        pub target: Option<PortEnd>,
        pub properties: Vec<SystemProperty>,
    }
}

/// The scoped name of a repository-id data type (`IDL:RTC/TimedPose2D:1.0` → `RTC::TimedPose2D`);
/// `None` for anything else.
pub fn scoped_data_type(data_type: &str) -> Option<Text> {
    data_type
        .trim()
        .starts_with("IDL:")
        .then(|| crate::types::canonical_type(data_type).into())
}

node! {
    /// `rts:ServicePortConnectors`.
    pub struct ServicePortConnector {
        pub connector_id: Option<Text>,
        pub name: Option<Text>,
        pub trans_method: Option<Text>,
        pub comment: Option<Text>,
        pub visible: Option<Text>,
        pub source: Option<PortEnd>,
        pub target: Option<PortEnd>,
        pub properties: Vec<SystemProperty>,
    }
}

/// What both kinds of connector hold beside their scalars, for the readers (which read them
/// alike).
pub struct ConnectorParts<'a> {
    pub source: &'a mut Option<PortEnd>,
    pub target: &'a mut Option<PortEnd>,
    pub properties: &'a mut Vec<SystemProperty>,
    pub extra: &'a mut Extras,
}

/// A data port connector or a service port connector: what the readers fill and what the
/// comparison of two systems reads, alike for both kinds.
pub trait Connector {
    fn parts_mut(&mut self) -> ConnectorParts<'_>;
    fn name(&self) -> &Option<Text>;
    fn connector_id(&self) -> &Option<Text>;
    fn ends(&self) -> (Option<&PortEnd>, Option<&PortEnd>);
    fn pos(&self) -> Pos;
}

macro_rules! connector {
    ($($t:ty),*) => {$(
        impl Connector for $t {
            fn parts_mut(&mut self) -> ConnectorParts<'_> {
                ConnectorParts {
                    source: &mut self.source,
                    target: &mut self.target,
                    properties: &mut self.properties,
                    extra: &mut self.extra,
                }
            }
            fn name(&self) -> &Option<Text> {
                &self.name
            }
            fn connector_id(&self) -> &Option<Text> {
                &self.connector_id
            }
            fn ends(&self) -> (Option<&PortEnd>, Option<&PortEnd>) {
                (self.source.as_ref(), self.target.as_ref())
            }
            fn pos(&self) -> Pos {
                self.pos
            }
        }
    )*};
}
connector!(DataPortConnector, ServicePortConnector);

/// Which order a [`Order`] is (root elements `StartUp` … `Finalizing`).
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
#[serde(rename_all = "camelCase")]
pub enum OrderKind {
    #[default]
    StartUp,
    ShutDown,
    Activation,
    Deactivation,
    Resetting,
    Initializing,
    Finalizing,
}

impl OrderKind {
    pub const ALL: [OrderKind; 7] = [
        OrderKind::StartUp,
        OrderKind::ShutDown,
        OrderKind::Activation,
        OrderKind::Deactivation,
        OrderKind::Resetting,
        OrderKind::Initializing,
        OrderKind::Finalizing,
    ];
    /// XML element name (`StartUp`).
    pub fn xml_name(self) -> &'static str {
        match self {
            OrderKind::StartUp => "StartUp",
            OrderKind::ShutDown => "ShutDown",
            OrderKind::Activation => "Activation",
            OrderKind::Deactivation => "Deactivation",
            OrderKind::Resetting => "Resetting",
            OrderKind::Initializing => "Initializing",
            OrderKind::Finalizing => "Finalizing",
        }
    }
    /// YAML key (`startUp`).
    pub fn yaml_name(self) -> &'static str {
        match self {
            OrderKind::StartUp => "startUp",
            OrderKind::ShutDown => "shutDown",
            OrderKind::Activation => "activation",
            OrderKind::Deactivation => "deactivation",
            OrderKind::Resetting => "resetting",
            OrderKind::Initializing => "initializing",
            OrderKind::Finalizing => "finalizing",
        }
    }
    pub fn from_xml_name(s: &str) -> Option<OrderKind> {
        OrderKind::ALL.into_iter().find(|k| k.xml_name() == s)
    }
    pub fn from_yaml_name(s: &str) -> Option<OrderKind> {
        OrderKind::ALL.into_iter().find(|k| k.yaml_name() == s)
    }
}

node! {
    /// A start-up / shut-down / activation / … order: the targets in sequence.
    pub struct Order {
        pub kind: OrderKind,
        pub targets: Vec<OrderTarget>,
    }
}

node! {
    /// One target of an order (`rts:targets`, `condition_ext`): a component's execution context and
    /// the condition under which it is sent the order.
    pub struct OrderTarget {
        pub sequence: Option<Text>,
        pub target_component: Option<TargetComponent>,
        pub wait_time: Option<WaitTime>,
        pub preceding: Option<Preceding>,
        pub properties: Vec<SystemProperty>,
    }
}

node! {
    /// `rts:WaitTime`: wait this long (ms) before sending.
    pub struct WaitTime {
        pub wait_time: Option<Text>,
    }
}

node! {
    /// `rts:Preceding`: send after these components (within `timeout` ms; `SYNC` / `ASYNC`).
    pub struct Preceding {
        pub timeout: Option<Text>,
        pub sending_timing: Option<Text>,
        pub preceding_components: Vec<TargetComponent>,
    }
}

impl RtSystem {
    /// The components (composites) whose participants include the instance named `name`; none
    /// for an empty name.
    pub fn composites_of<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a SystemComponent> {
        self.components.iter().filter(move |k| {
            !name.is_empty()
                && k.participants
                    .iter()
                    .any(|t| non_empty(&t.instance_name) == Some(name))
        })
    }
    /// The system name from the id, or a placeholder.
    pub fn name(&self) -> &str {
        self.id_parts
            .as_ref()
            .and_then(|p| non_empty(&p.name))
            .or_else(|| non_empty(&self.id))
            .unwrap_or("(unnamed system)")
    }

    /// The instance called `instance_name`.
    pub fn component(&self, instance_name: &str) -> Option<&SystemComponent> {
        self.components
            .iter()
            .find(|c| c.instance_name.as_deref() == Some(instance_name))
    }

    /// The order of `kind`, when the system has one.
    pub fn order(&self, kind: OrderKind) -> Option<&Order> {
        self.orders.iter().find(|o| o.kind == kind)
    }

    /// Every property anywhere in the system, in document order of the nodes.
    pub fn all_properties(&self) -> Vec<&SystemProperty> {
        fn target<'a>(out: &mut Vec<&'a SystemProperty>, t: &'a TargetComponent) {
            out.extend(&t.properties);
        }
        fn end<'a>(out: &mut Vec<&'a SystemProperty>, e: &'a Option<PortEnd>) {
            if let Some(e) = e {
                out.extend(&e.properties);
            }
        }
        let mut out: Vec<&SystemProperty> = self.properties.iter().collect();
        for c in &self.components {
            out.extend(&c.properties);
            for p in c.data_ports.iter().chain(&c.service_ports) {
                out.extend(&p.properties);
            }
            for ec in &c.execution_contexts {
                out.extend(&ec.properties);
                ec.participants.iter().for_each(|t| target(&mut out, t));
            }
            c.participants.iter().for_each(|t| target(&mut out, t));
        }
        for g in &self.groups {
            g.members.iter().for_each(|t| target(&mut out, t));
        }
        for d in &self.data_port_connectors {
            out.extend(&d.properties);
            end(&mut out, &d.source);
            end(&mut out, &d.target);
        }
        for s in &self.service_port_connectors {
            out.extend(&s.properties);
            end(&mut out, &s.source);
            end(&mut out, &s.target);
        }
        for o in &self.orders {
            for t in &o.targets {
                out.extend(&t.properties);
                if let Some(tc) = &t.target_component {
                    target(&mut out, tc);
                }
                if let Some(p) = &t.preceding {
                    p.preceding_components
                        .iter()
                        .for_each(|t| target(&mut out, t));
                }
            }
        }
        out
    }

    /// How many properties carry private host data (pages hide them by default and say so).
    pub fn private_properties(&self) -> usize {
        self.all_properties().iter().filter(|p| p.private).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type Parts = (Option<String>, Option<String>, Option<String>, IdForm);

    fn sys(id: &str) -> Option<Parts> {
        SystemIdParts::parse(id).map(|p| {
            (
                p.vendor.map(|s| s.to_string()),
                p.name.map(|s| s.to_string()),
                p.version.map(|s| s.to_string()),
                p.form,
            )
        })
    }
    fn s(x: &str) -> Option<String> {
        Some(x.to_string())
    }

    #[test]
    fn system_ids() {
        assert_eq!(
            sys("RTSystem:jp.go.aist:SampleRTS:1.0.0"),
            Some((
                s("jp.go.aist"),
                s("SampleRTS"),
                s("1.0.0"),
                IdForm::Standard
            ))
        );
        assert_eq!(
            sys("RTSystem :Sugar Sweet Robotics.DefaultSystem01.1.0"),
            Some((
                s("Sugar Sweet Robotics"),
                s("DefaultSystem01"),
                s("1.0"),
                IdForm::Repaired
            ))
        );
        assert_eq!(
            sys("RTSystem:1:3:2"),
            Some((s("1"), s("3"), s("2"), IdForm::Standard))
        );
        assert_eq!(
            sys("RTSystem:a:b:c:1.0"),
            Some((s("a:b"), s("c"), s("1.0"), IdForm::Repaired))
        );
        assert_eq!(
            sys("RTSystem:Name:1.0"),
            Some((None, s("Name"), s("1.0"), IdForm::Repaired))
        );
        assert_eq!(sys("RTSystem:"), None);
        assert_eq!(sys("RTC:a:b:c:d"), None);
        assert_eq!(sys(""), None);
        assert_eq!(sys("RTSyst"), None);
    }

    #[test]
    fn component_ids() {
        let p = ComponentIdParts::parse("RTC:Sugar Sweet Robotics:Experimenta:Kin:1.0.0").unwrap();
        assert_eq!(p.vendor.as_deref(), Some("Sugar Sweet Robotics"));
        assert_eq!(p.category.as_deref(), Some("Experimenta"));
        assert_eq!(p.name.as_deref(), Some("Kin"));
        assert_eq!(p.version.as_deref(), Some("1.0.0"));
        assert_eq!(p.form, IdForm::Standard);
        let d =
            ComponentIdParts::parse("RTC:jp.AIST.Software algorithm.PathPlanner2D:1.0.0").unwrap();
        assert_eq!(d.vendor.as_deref(), Some("jp.AIST"));
        assert_eq!(d.category.as_deref(), Some("Software algorithm"));
        assert_eq!(d.name.as_deref(), Some("PathPlanner2D"));
        assert_eq!(d.form, IdForm::Dotted);
        let r = ComponentIdParts::parse("RTC:v:n:1").unwrap();
        assert_eq!((r.category, r.form), (None, IdForm::Repaired));
        assert!(ComponentIdParts::parse("RTC:only").is_none());
        assert!(ComponentIdParts::parse("RTSystem:a:b:c").is_none());
        assert!(ComponentIdParts::parse("").is_none());
    }

    #[test]
    fn private_properties() {
        let p = |n: &str, v: &str| is_private_property(Some(n), Some(v));
        // The saving machine's name and kernel; the platform alone names no machine.
        for (name, value, private) in [
            ("os.hostname", "x", true),
            ("os.release", "4.15.0-32-generic", true),
            (
                "OS.Version",
                "#35~16.04.1-Ubuntu SMP Fri Aug 10 21:54:34 UTC 2018",
                true,
            ),
            ("os.name", "Linux", false),
            ("os.arch", "x86_64", false),
        ] {
            assert_eq!(p(name, value), private, "{name}");
        }
        assert!(p("corba.endpoint", ""));
        assert!(p("corba.endpoints", ""));
        assert!(p("naming.host", "x"));
        assert!(p("manager.hostname", "x"));
        assert!(p("IOR", ""));
        assert!(p("dataport.corba_cdr.inport_ior", ""));
        assert!(p("x", "IOR:0100abcdef"));
        assert!(p("x", "192.168.0.3:2809"));
        assert!(p("x", "giop:tcp:robot.local:2810"));
        assert!(p("x", "a, myhost:2809"));
        assert!(p("x", "[::1]:2809"));
        assert!(p("naming.names", "secret-lab-pc.host_cxt/Cam0.rtc"));
        assert!(p(
            "naming.names",
            "a.rtc, /robots/WIN-LDAKBFMO7VE.Host_Cxt/Mapper0.rtc"
        ));
        assert!(!p("naming.names", "%h.host_cxt/%n.rtc"));
        assert!(!p("naming.names", "robots/Cam0.rtc"));
        assert!(!p("behavior", "x"));
        assert!(!p("x", "12:30"));
        assert!(!p("x", "IOR:xyz"));
        assert!(!p("x", "localhost:2809/X0.rtc"));
        assert!(!p("dataport.data_type", "IDL:RTC/TimedLong:1.0"));
        assert!(!p("POSITION", "{1:(82,19),2:(87,19)}"));
    }

    #[test]
    fn short_names_and_pseudo_sets() {
        assert_eq!(short_port_name("Inst0.port", Some("Inst0")), "port");
        assert_eq!(short_port_name("port", Some("Inst0")), "port");
        assert_eq!(short_port_name("Other.port", Some("Inst0")), "Other.port");
        assert_eq!(short_port_name("Inst0.", Some("Inst0")), "Inst0.");
        assert_eq!(short_port_name("a.b", None), "a.b");
        assert!(is_pseudo_set("__widget__"));
        assert!(is_pseudo_set("__constraints__"));
        assert!(!is_pseudo_set("default"));
        assert!(!is_pseudo_set("____"));
        assert_eq!(
            scoped_data_type("IDL:RTC/TimedPose2D:1.0").as_deref(),
            Some("RTC::TimedPose2D")
        );
        assert_eq!(scoped_data_type("RTC::TimedLong"), None);
        assert_eq!(
            LocationDirection::parse("down"),
            Some(LocationDirection::Down)
        );
    }
}
