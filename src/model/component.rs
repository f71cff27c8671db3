//! Typed model of an RTC Profile (spec v0.2, chapter 2; XSD chapter 6; YAML schema chapter 7).
//!
//! The model is plain data: no XML, no YAML, no I/O. Every value is kept as the profile wrote it
//! (strings stay strings, empty attributes stay `Some("")`), so the JSON output shows exactly what
//! the source said; typed views (`ActionKind`, `Direction`, `PortSide`, …) are offered as methods.
//! Values the spec does not define are kept in an `extra` list on the nearest node.

use super::fields::Field;
use super::Extras;
use serde::{Deserialize, Serialize};

/// A string value of a profile. Most values are short (names, types, numbers, `true`), and a
/// `CompactString` keeps up to 24 bytes inline, without a heap allocation: a 10,000-profile
/// catalogue holds millions of them.
pub type Text = compact_str::CompactString;

/// Reads a string of a small fixed vocabulary (a dialect name, a diagnostic code) into the
/// `&'static str` the model keeps, for `catalog.json` read back: each distinct value is
/// stored once for the rest of the process.
pub fn intern(s: String) -> &'static str {
    use std::collections::HashSet;
    use std::sync::{Mutex, OnceLock};
    static SEEN: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
    let mut seen = SEEN
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(|e| e.into_inner());
    if let Some(&known) = seen.get(s.as_str()) {
        return known;
    }
    let leaked: &'static str = Box::leak(s.into_boxed_str());
    seen.insert(leaked);
    leaked
}

/// A position in a source file: 1-based line and column (columns count characters).
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
pub struct Pos {
    pub line: u32,
    pub column: u32,
}

impl Pos {
    pub fn new(line: u32, column: u32) -> Self {
        Pos { line, column }
    }
    /// The line and column (1-based, columns in characters) of byte `offset` of `text`; an
    /// offset past the end or inside a character counts up to the last whole character before.
    pub fn at_offset(text: &str, offset: usize) -> Self {
        let mut end = offset.min(text.len());
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        let before = &text[..end];
        let line = before.matches('\n').count() + 1;
        let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        Pos::new(
            u32::try_from(line).unwrap_or(u32::MAX),
            u32::try_from(col).unwrap_or(u32::MAX),
        )
    }
    /// True when no position is known (line 0).
    pub fn is_unknown(&self) -> bool {
        self.line == 0
    }
}

impl std::fmt::Display for Pos {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// A value the spec does not define: an unknown attribute, element (with its whole subtree) or
/// YAML key. Kept so that nothing in a profile is lost, and shown as an extra property.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Extra {
    /// `attribute`, `element` or `key` (YAML).
    pub kind: ExtraKind,
    /// Name as written, with its prefix when it had one (`rtc:library`, `"rtcExt::foo"`).
    pub name: Text,
    /// Namespace URI for XML names that have one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub namespace: Option<Text>,
    /// The attribute value, the element's text, or the YAML scalar.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<Text>,
    /// Attributes and child elements of an unknown element; entries of a YAML map or sequence.
    #[serde(default, skip_serializing_if = "thin_vec::ThinVec::is_empty")]
    pub children: Extras,
    pub pos: Pos,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum ExtraKind {
    Attribute,
    Element,
    Key,
}

node! {
    /// `rtcExt:Properties` / `"rtcExt::properties"`: a free name/value pair.
    pub struct Property {
        pub name: Option<Text>,
        pub value: Option<Text>,
    }
}

node! {
    /// The whole profile (spec 2.2 `rtc_profile`).
    pub struct Profile {
        /// `RTC:<vendor>:<category>:<name>:<version>`.
        pub id: Option<Text>,
        /// Version of the profile format (`0.2`, `0.3`, `1.0`).
        pub version: Option<Text>,
        pub basic_info: BasicInfo,
        /// The 14 lifecycle actions, in spec order, as far as the profile lists them.
        pub actions: Vec<Action>,
        /// Position of the `Actions` element / key, when present.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub actions_pos: Option<Pos>,
        /// `ConfigurationSet`; `None` when the profile has none.
        pub configuration_set: Option<ConfigurationSet>,
        pub data_ports: Vec<DataPort>,
        pub service_ports: Vec<ServicePort>,
        /// System parameters (spec 5.4).
        pub parameters: Vec<Parameter>,
        pub language: Option<Language>,
        /// Values read under another writer's spelling (RTCBuilder 0.1, rtc-template) and mapped
        /// to the field they mean; the JSON shows what was written.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        pub written_as: Vec<WrittenAs>,
        /// Positions of the `id` and `version` attributes / keys.
        #[serde(skip)]
        pub attr_pos: AttrPos,
    }
}

/// A value a profile wrote under a spelling other than spec v0.2's, read as the field it means
/// (NOTES: "The oldest RTCBuilder format"): `rtcExt:varname` → `variableName`,
/// `rtc:subscriprionType` → `subscriptionType`, `<rtc:Cxx/>` → language `C++`, the dotted id,
/// activityType `EVENT_DRIVEN`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct WrittenAs {
    /// The model field the value was read into, on its node (`dataPort out.variableName`).
    pub field: Text,
    /// What the profile wrote: the attribute, key or element name, or the value.
    pub written_as: Text,
    /// The writer generation that uses this spelling.
    pub dialect: &'static str,
    pub pos: Pos,
}

/// [`WrittenAs`] as `catalog.json` has it.
#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct WrittenAsRead {
    field: Text,
    written_as: Text,
    dialect: String,
    pos: Pos,
}

impl<'de> Deserialize<'de> for WrittenAs {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let w = WrittenAsRead::deserialize(d)?;
        Ok(WrittenAs {
            field: w.field,
            written_as: w.written_as,
            dialect: intern(w.dialect),
            pos: w.pos,
        })
    }
}

/// Positions of a node's known attributes (XML) or keys (YAML), by field, for the rules:
/// RTCBuilder writes an element on one long line, so the element's start can be hundreds of
/// columns away from the attribute that is wrong. Not part of the JSON.
/// Each entry is a field's index in [`Field::ALL`] and its position: 12 bytes, not the 24 of a
/// `&str` and a position (at 10,000 profiles the positions are millions of entries).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct AttrPos(Vec<(u8, Pos)>);

impl AttrPos {
    /// Records the position of `field` (the first one wins, as for the value).
    pub fn note(&mut self, field: Field, pos: Pos) {
        let Ok(i) = u8::try_from(field as usize) else {
            return;
        };
        if !self.0.iter().any(|(f, _)| *f == i) {
            self.0.push((i, pos));
        }
    }
    /// The position of `field`, when it was written.
    pub fn field(&self, field: Field) -> Option<Pos> {
        let i = u8::try_from(field as usize).ok()?;
        self.0.iter().find(|(f, _)| *f == i).map(|(_, p)| *p)
    }
    /// The position of the field whose JSON name is `name` (the spec's name: `portType`), when
    /// it was written. The entries of one node have distinct names.
    pub fn get(&self, name: &str) -> Option<Pos> {
        // A name no field has (a field renamed in the table, not in a rule) is a bug.
        debug_assert!(
            Field::ALL.iter().any(|f| f.json() == name),
            "no field is called `{name}`"
        );
        self.0
            .iter()
            .find(|(f, _)| Field::from_index(*f).is_some_and(|f| f.json() == name))
            .map(|(_, p)| *p)
    }
    /// Gives back spare capacity (the readers push entry by entry).
    pub fn shrink_to_fit(&mut self) {
        self.0.shrink_to_fit();
    }
    /// Entries kept.
    pub fn len(&self) -> usize {
        self.0.len()
    }
    /// No entry kept.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// Entries the vector has room for (tests of [`AttrPos::shrink_to_fit`]).
    pub fn capacity(&self) -> usize {
        self.0.capacity()
    }
    /// The position of `field`, else `fallback` (the element or key of the node).
    pub fn or(&self, field: &str, fallback: Pos) -> Pos {
        self.get(field).unwrap_or(fallback)
    }
}

#[cfg(test)]
mod attr_pos_tests {
    use super::*;

    #[test]
    fn positions_of_offsets_count_characters() {
        let t = "ab\nカメラx";
        assert_eq!(Pos::at_offset(t, 0), Pos::new(1, 1));
        assert_eq!(Pos::at_offset(t, 3), Pos::new(2, 1));
        // `x` after three 3-byte characters is column 4.
        assert_eq!(Pos::at_offset(t, 12), Pos::new(2, 4));
        // Inside a character, or past the end: up to the last whole character.
        assert_eq!(Pos::at_offset(t, 4), Pos::new(2, 1));
        assert_eq!(Pos::at_offset(t, 99), Pos::new(2, 5));
    }

    #[test]
    fn every_field_has_a_position_by_its_name() {
        for &f in Field::ALL {
            let mut a = AttrPos::default();
            let p = Pos { line: 3, column: 7 };
            a.note(f, p);
            a.note(f, Pos::new(9, 9));
            assert_eq!(a.get(f.json()), Some(p), "{f:?}");
            assert_eq!(a.field(f), Some(p), "{f:?}");
            assert_eq!(a.len(), 1);
        }
        assert_eq!(AttrPos::default().get("name"), None);
    }
}

/// The parts of a component id (spec 2.3.1.1), in either form real profiles use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IdParts<'a> {
    pub vendor: &'a str,
    pub category: &'a str,
    pub name: &'a str,
    pub version: &'a str,
    /// `RTC:vendor.category.name:version`, the form of RTCBuilder's first profile format
    /// (`rtc:version="0.1"`, 2009) and of OpenRTM-aist-Python's rtc-template.
    pub dotted: bool,
}

impl<'a> IdParts<'a> {
    /// Parses `RTC:vendor:category:name:version` or the dotted
    /// `RTC:vendor.category.name:version`. A dotted middle part is split with the help of
    /// `basic` (vendors such as `ysuga.net` contain dots): when BasicInfo's vendor, category and
    /// name joined by `.` give it, those are the parts; else the vendor runs to the first dot
    /// and the name from the last. `None` for anything else.
    pub fn parse(id: &'a str, basic: &BasicInfo) -> Option<IdParts<'a>> {
        let rest = id.trim().strip_prefix("RTC:")?;
        let parts: Vec<&str> = rest.split(':').collect();
        match parts.as_slice() {
            [vendor, category, name, version] => Some(IdParts {
                vendor,
                category,
                name,
                version,
                dotted: false,
            }),
            [middle, version] => {
                let (v, c, n) = (
                    basic.vendor.as_deref().unwrap_or(""),
                    basic.category.as_deref().unwrap_or(""),
                    basic.name.as_deref().unwrap_or(""),
                );
                let joined = !v.is_empty()
                    && !c.is_empty()
                    && !n.is_empty()
                    && middle.len() == v.len() + c.len() + n.len() + 2
                    && middle.starts_with(v)
                    && middle[v.len()..].starts_with('.')
                    && middle[v.len() + 1..].starts_with(c)
                    && middle[v.len() + 1 + c.len()..].starts_with('.')
                    && middle.ends_with(n);
                let (vendor, category, name) = if joined {
                    (
                        &middle[..v.len()],
                        &middle[v.len() + 1..v.len() + 1 + c.len()],
                        &middle[middle.len() - n.len()..],
                    )
                } else {
                    let first = middle.find('.')?;
                    let last = middle.rfind('.')?;
                    if first == last {
                        return None;
                    }
                    (
                        &middle[..first],
                        &middle[first + 1..last],
                        &middle[last + 1..],
                    )
                };
                Some(IdParts {
                    vendor,
                    category,
                    name,
                    version,
                    dotted: true,
                })
            }
            _ => None,
        }
    }
}

node! {
    /// Basic information (spec 2.3.2) with its Document (2.4.1) and Extended (2.5.1) parts.
    pub struct BasicInfo {
        pub name: Option<Text>,
        pub component_type: Option<Text>,
        pub activity_type: Option<Text>,
        pub component_kind: Option<Text>,
        pub rtc_type: Option<Text>,
        pub category: Option<Text>,
        pub description: Option<Text>,
        pub execution_rate: Option<Text>,
        pub execution_type: Option<Text>,
        pub max_instances: Option<Text>,
        pub vendor: Option<Text>,
        pub version: Option<Text>,
        #[serde(rename = "abstract")]
        pub abstract_: Option<Text>,
        pub hardware_profile: Option<Text>,
        /// As written in XML (`xsd:dateTime`); YAML date maps are turned into the same ISO form.
        pub creation_date: Option<Text>,
        pub update_date: Option<Text>,
        pub doc: Option<BasicDoc>,
        pub comment: Option<Text>,
        pub save_project: Option<Text>,
        pub version_up_logs: Vec<Text>,
        pub properties: Vec<Property>,
        /// Positions of the attributes / keys, for the rules.
        #[serde(skip)]
        pub attr_pos: AttrPos,
    }
}

node! {
    /// Document Profile of the component (spec 2.4.2).
    pub struct BasicDoc {
        pub description: Option<Text>,
        pub inout: Option<Text>,
        pub algorithm: Option<Text>,
        pub creator: Option<Text>,
        pub license: Option<Text>,
        pub reference: Option<Text>,
    }
}

/// The lifecycle callbacks (spec 2.3.3), in spec order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum ActionKind {
    OnInitialize,
    OnFinalize,
    OnStartup,
    OnShutdown,
    OnActivated,
    OnDeactivated,
    OnAborting,
    OnError,
    OnReset,
    OnExecute,
    OnStateUpdate,
    OnRateChanged,
    OnAction,
    OnModeChanged,
}

impl ActionKind {
    pub const ALL: [ActionKind; 14] = [
        ActionKind::OnInitialize,
        ActionKind::OnFinalize,
        ActionKind::OnStartup,
        ActionKind::OnShutdown,
        ActionKind::OnActivated,
        ActionKind::OnDeactivated,
        ActionKind::OnAborting,
        ActionKind::OnError,
        ActionKind::OnReset,
        ActionKind::OnExecute,
        ActionKind::OnStateUpdate,
        ActionKind::OnRateChanged,
        ActionKind::OnAction,
        ActionKind::OnModeChanged,
    ];

    /// XML element name (`OnInitialize`).
    pub fn xml_name(self) -> &'static str {
        match self {
            ActionKind::OnInitialize => "OnInitialize",
            ActionKind::OnFinalize => "OnFinalize",
            ActionKind::OnStartup => "OnStartup",
            ActionKind::OnShutdown => "OnShutdown",
            ActionKind::OnActivated => "OnActivated",
            ActionKind::OnDeactivated => "OnDeactivated",
            ActionKind::OnAborting => "OnAborting",
            ActionKind::OnError => "OnError",
            ActionKind::OnReset => "OnReset",
            ActionKind::OnExecute => "OnExecute",
            ActionKind::OnStateUpdate => "OnStateUpdate",
            ActionKind::OnRateChanged => "OnRateChanged",
            ActionKind::OnAction => "OnAction",
            ActionKind::OnModeChanged => "OnModeChanged",
        }
    }

    /// YAML key (`onInitialize`).
    pub fn yaml_name(self) -> &'static str {
        match self {
            ActionKind::OnInitialize => "onInitialize",
            ActionKind::OnFinalize => "onFinalize",
            ActionKind::OnStartup => "onStartup",
            ActionKind::OnShutdown => "onShutdown",
            ActionKind::OnActivated => "onActivated",
            ActionKind::OnDeactivated => "onDeactivated",
            ActionKind::OnAborting => "onAborting",
            ActionKind::OnError => "onError",
            ActionKind::OnReset => "onReset",
            ActionKind::OnExecute => "onExecute",
            ActionKind::OnStateUpdate => "onStateUpdate",
            ActionKind::OnRateChanged => "onRateChanged",
            ActionKind::OnAction => "onAction",
            ActionKind::OnModeChanged => "onModeChanged",
        }
    }

    /// The C++ callback name users know (`on_initialize`).
    pub fn callback_name(self) -> &'static str {
        match self {
            ActionKind::OnInitialize => "on_initialize",
            ActionKind::OnFinalize => "on_finalize",
            ActionKind::OnStartup => "on_startup",
            ActionKind::OnShutdown => "on_shutdown",
            ActionKind::OnActivated => "on_activated",
            ActionKind::OnDeactivated => "on_deactivated",
            ActionKind::OnAborting => "on_aborting",
            ActionKind::OnError => "on_error",
            ActionKind::OnReset => "on_reset",
            ActionKind::OnExecute => "on_execute",
            ActionKind::OnStateUpdate => "on_state_update",
            ActionKind::OnRateChanged => "on_rate_changed",
            ActionKind::OnAction => "on_action",
            ActionKind::OnModeChanged => "on_mode_changed",
        }
    }

    pub fn from_xml_name(name: &str) -> Option<ActionKind> {
        ActionKind::ALL.into_iter().find(|k| k.xml_name() == name)
    }

    pub fn from_yaml_name(name: &str) -> Option<ActionKind> {
        ActionKind::ALL.into_iter().find(|k| k.yaml_name() == name)
    }
}

/// One lifecycle action (spec 2.3.4 `action_status`, 2.4.3 doc).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Action {
    pub kind: ActionKind,
    /// `implemented` as written (`true` / `false`).
    pub implemented: Option<Text>,
    pub doc: Option<ActionDoc>,
    pub pos: Pos,
    #[serde(default, skip_serializing_if = "thin_vec::ThinVec::is_empty")]
    pub extra: Extras,
}

impl super::Located for Action {
    fn pos_mut(&mut self) -> &mut Pos {
        &mut self.pos
    }
    fn extra_mut(&mut self) -> &mut Extras {
        &mut self.extra
    }
}

impl Action {
    /// Whether the profile marks this callback as implemented (absent or invalid = false).
    pub fn is_implemented(&self) -> bool {
        parse_bool(self.implemented.as_deref()).unwrap_or(false)
    }
}

node! {
    pub struct ActionDoc {
        pub description: Option<Text>,
        pub pre_condition: Option<Text>,
        pub post_condition: Option<Text>,
    }
}

node! {
    /// `ConfigurationSet` (spec 2.3.5).
    pub struct ConfigurationSet {
        pub configurations: Vec<Configuration>,
    }
}

node! {
    /// One configuration parameter (spec 2.3.6, 2.4.4 doc, 2.5.2 ext).
    pub struct Configuration {
        pub name: Option<Text>,
        #[serde(rename = "type")]
        pub type_: Option<Text>,
        pub default_value: Option<Text>,
        pub unit: Option<Text>,
        pub constraint: Option<Constraint>,
        pub doc: Option<ConfigurationDoc>,
        pub comment: Option<Text>,
        pub variable_name: Option<Text>,
        pub properties: Vec<Property>,
        #[serde(skip)]
        pub attr_pos: AttrPos,
    }
}

impl Configuration {
    /// Value of the `__widget__` property (RTSystemEditor's editor widget: text, radio,
    /// slider.N, spin, checkbox, ordered_list).
    pub fn widget(&self) -> Option<&str> {
        property_value(&self.properties, "__widget__")
    }
    /// Value of the `__step__` property (step of a slider or spin widget).
    pub fn step(&self) -> Option<&str> {
        property_value(&self.properties, "__step__")
    }
}

node! {
    pub struct ConfigurationDoc {
        pub dataname: Option<Text>,
        pub default_value: Option<Text>,
        pub description: Option<Text>,
        pub unit: Option<Text>,
        pub range: Option<Text>,
        pub constraint: Option<Text>,
    }
}

node! {
    /// A data port (spec 2.3.7, 2.4.5 doc, 2.5.3 ext); also FSM `EventPort`s with their events.
    pub struct DataPort {
        /// `DataInPort`, `DataOutPort` or `EventPort` as written.
        pub port_type: Option<Text>,
        pub name: Option<Text>,
        #[serde(rename = "type")]
        pub type_: Option<Text>,
        pub idl_file: Option<Text>,
        pub interface_type: Option<Text>,
        pub dataflow_type: Option<Text>,
        pub subscription_type: Option<Text>,
        pub unit: Option<Text>,
        pub constraint: Option<Constraint>,
        pub doc: Option<DataPortDoc>,
        pub comment: Option<Text>,
        pub variable_name: Option<Text>,
        /// `rtcExt:position` as written (`LEFT`, `left`, …).
        pub position: Option<Text>,
        pub properties: Vec<Property>,
        /// FSM events carried by an `EventPort` (RTCBuilder 2.x).
        pub events: Vec<Event>,
        #[serde(skip)]
        pub attr_pos: AttrPos,
    }
}

/// Direction of a data port.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum PortDirection {
    In,
    Out,
    Event,
}

impl PortDirection {
    /// In, Out or Event, from a `portType` (case-insensitive); `None` for anything else.
    pub fn parse(port_type: &str) -> Option<PortDirection> {
        match port_type.trim().to_ascii_lowercase().as_str() {
            "datainport" | "inport" | "in" => Some(PortDirection::In),
            "dataoutport" | "outport" | "out" => Some(PortDirection::Out),
            "eventport" => Some(PortDirection::Event),
            _ => None,
        }
    }
}

impl DataPort {
    /// In, Out or Event, from `portType` (case-insensitive); `None` for anything else.
    pub fn direction(&self) -> Option<PortDirection> {
        PortDirection::parse(self.port_type.as_deref()?)
    }
    /// The edge the port is drawn on: `rtcExt:position` or, without it, in-ports left and
    /// out-ports right (spec chapter 4).
    pub fn side(&self) -> PortSide {
        PortSide::parse(self.position.as_deref()).unwrap_or(match self.direction() {
            Some(PortDirection::Out) => PortSide::Right,
            _ => PortSide::Left,
        })
    }
}

node! {
    /// An FSM event of an `EventPort`.
    pub struct Event {
        pub name: Option<Text>,
        #[serde(rename = "type")]
        pub type_: Option<Text>,
        pub source: Option<Text>,
        pub target: Option<Text>,
        pub condition: Option<Text>,
        pub doc: Option<DataPortDoc>,
    }
}

node! {
    /// Document Profile of a data port (spec 2.4.6). `occurrence` also accepts RTCBuilder's
    /// `occerrence` spelling.
    pub struct DataPortDoc {
        pub description: Option<Text>,
        #[serde(rename = "type")]
        pub type_: Option<Text>,
        pub number: Option<Text>,
        pub semantics: Option<Text>,
        pub unit: Option<Text>,
        pub occurrence: Option<Text>,
        pub operation: Option<Text>,
    }
}

/// The edge of the component box a port is drawn on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum PortSide {
    Left,
    Right,
    Top,
    Bottom,
}

impl PortSide {
    /// Parses `left/right/top/bottom` in any case.
    pub fn parse(s: Option<&str>) -> Option<PortSide> {
        match s?.trim().to_ascii_lowercase().as_str() {
            "left" => Some(PortSide::Left),
            "right" => Some(PortSide::Right),
            "top" => Some(PortSide::Top),
            "bottom" => Some(PortSide::Bottom),
            _ => None,
        }
    }
}

node! {
    /// A service port (spec 2.3.8, 2.4.7 doc, 2.5.4 ext).
    pub struct ServicePort {
        pub name: Option<Text>,
        pub interfaces: Vec<ServiceInterface>,
        pub trans_methods: Vec<TransMethod>,
        pub doc: Option<ServicePortDoc>,
        pub comment: Option<Text>,
        pub position: Option<Text>,
        pub properties: Vec<Property>,
        #[serde(skip)]
        pub attr_pos: AttrPos,
    }
}

impl ServicePort {
    /// Edge from `rtcExt:position`; left when absent.
    pub fn side(&self) -> PortSide {
        PortSide::parse(self.position.as_deref()).unwrap_or(PortSide::Left)
    }
}

node! {
    pub struct ServicePortDoc {
        pub description: Option<Text>,
        pub ifdescription: Option<Text>,
    }
}

node! {
    /// `TransMethods` (spec 2.3.10).
    pub struct TransMethod {
        pub kind: Option<Text>,
    }
}

node! {
    /// A service interface of a service port (spec 2.3.9, 2.4.8 doc, 2.5.5 ext).
    pub struct ServiceInterface {
        pub name: Option<Text>,
        #[serde(rename = "type")]
        pub type_: Option<Text>,
        /// `Provided` or `Required` as written.
        pub direction: Option<Text>,
        pub instance_name: Option<Text>,
        pub idl_file: Option<Text>,
        pub path: Option<Text>,
        pub doc: Option<ServiceInterfaceDoc>,
        pub comment: Option<Text>,
        pub variable_name: Option<Text>,
        pub properties: Vec<Property>,
        #[serde(skip)]
        pub attr_pos: AttrPos,
    }
}

/// Provided or required, for service interfaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Direction {
    Provided,
    Required,
}

impl Direction {
    /// `Provided` / `Required` in any case; `None` for anything else.
    pub fn parse(direction: &str) -> Option<Direction> {
        match direction.trim().to_ascii_lowercase().as_str() {
            "provided" => Some(Direction::Provided),
            "required" => Some(Direction::Required),
            _ => None,
        }
    }
}

impl ServiceInterface {
    /// `Provided` / `Required` in any case; `None` for anything else.
    pub fn direction_kind(&self) -> Option<Direction> {
        Direction::parse(self.direction.as_deref()?)
    }
}

node! {
    pub struct ServiceInterfaceDoc {
        pub description: Option<Text>,
        pub doc_argument: Option<Text>,
        pub doc_return: Option<Text>,
        pub doc_exception: Option<Text>,
        pub doc_pre_condition: Option<Text>,
        pub doc_post_condition: Option<Text>,
    }
}

node! {
    /// A system parameter (spec 2.3.11, 5.4).
    pub struct Parameter {
        pub name: Option<Text>,
        pub default_value: Option<Text>,
    }
}

node! {
    /// Implementation language (spec 2.3.12) with target environments (2.5.6).
    pub struct Language {
        pub kind: Option<Text>,
        pub targets: Vec<Target>,
    }
}

node! {
    /// A target environment (spec 2.5.7).
    pub struct Target {
        pub lang_version: Option<Text>,
        pub os: Option<Text>,
        pub os_versions: Vec<Text>,
        pub other: Option<Text>,
        pub cpus: Vec<Text>,
        pub cpu_other: Option<Text>,
        pub libraries: Vec<Library>,
    }
}

node! {
    /// A library of a target environment (spec 2.5.8). `name` also accepts the PIM's `path`.
    pub struct Library {
        pub name: Option<Text>,
        pub version: Option<Text>,
        pub other: Option<Text>,
    }
}

/// A constraint (spec 2.3.17): a unit, an ordered list, or a keyed hash of constraints.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Constraint {
    pub kind: ConstraintKind,
    pub pos: Pos,
    #[serde(default, skip_serializing_if = "thin_vec::ThinVec::is_empty")]
    pub extra: Extras,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", tag = "form")]
pub enum ConstraintKind {
    /// `ConstraintUnitType` (2.3.19): one condition, optionally keyed (inside a hash).
    Unit {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        key: Option<Text>,
        condition: Box<Condition>,
    },
    /// `ConstraintListType` (2.3.20): element i of a vector value must satisfy item i.
    List { items: Vec<Constraint> },
    /// `ConstraintHashType` (2.3.21): the value under each key must satisfy that item.
    Hash { items: Vec<Constraint> },
    /// A constraint element with no recognised content (kept so the position is known).
    Empty,
}

impl ConstraintKind {
    /// A unit constraint of `condition` (with its `key` inside a hash); `Empty` without one.
    pub fn unit(key: Option<Text>, condition: Option<Condition>) -> ConstraintKind {
        match condition {
            Some(c) => ConstraintKind::Unit {
                key,
                condition: Box::new(c),
            },
            None => ConstraintKind::Empty,
        }
    }
}

/// One condition of a constraint unit (spec 2.3.22–2.3.41).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", tag = "op")]
pub enum Condition {
    Not {
        operand: Constraint,
    },
    And {
        operands: Vec<Constraint>,
    },
    Or {
        operands: Vec<Constraint>,
    },
    /// `propertyIsNull`: the value must be empty.
    IsNull {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        text: Option<Text>,
    },
    /// `=`, `≠`, `<`, `>`, `≤`, `≥` against a literal.
    Compare {
        comparison: Comparison,
        literal: Option<Text>,
        /// `matchCase` as written; absent means case-sensitive (spec 8.1).
        match_case: Option<Text>,
    },
    /// `propertyIsLike`: a pattern with wild-card, single-character and escape characters.
    Like {
        literal: Option<Text>,
        wild_card: Option<Text>,
        single_char: Option<Text>,
        escape_char: Option<Text>,
    },
    /// `propertyIsBetween`: lower ≤ x ≤ upper (both inclusive).
    Between {
        lower: Option<Text>,
        upper: Option<Text>,
    },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Comparison {
    EqualTo,
    NotEqualTo,
    LessThan,
    GreaterThan,
    LessThanOrEqualTo,
    GreaterThanOrEqualTo,
}

impl Comparison {
    /// The mathematical symbol (`=`, `≠`, `<`, `>`, `≤`, `≥`).
    pub fn symbol(self) -> &'static str {
        match self {
            Comparison::EqualTo => "=",
            Comparison::NotEqualTo => "≠",
            Comparison::LessThan => "<",
            Comparison::GreaterThan => ">",
            Comparison::LessThanOrEqualTo => "≤",
            Comparison::GreaterThanOrEqualTo => "≥",
        }
    }
    /// Element / key local name without the `propertyIs` prefix (`EqualTo`).
    pub fn from_suffix(s: &str) -> Option<Comparison> {
        match s.to_ascii_lowercase().as_str() {
            "equalto" => Some(Comparison::EqualTo),
            "notequalto" => Some(Comparison::NotEqualTo),
            "lessthan" => Some(Comparison::LessThan),
            "greaterthan" => Some(Comparison::GreaterThan),
            "lessthanorequalto" => Some(Comparison::LessThanOrEqualTo),
            "greaterthanorequalto" => Some(Comparison::GreaterThanOrEqualTo),
            _ => None,
        }
    }
}

/// Whether `value` of `field` is a placeholder RTCBuilder pre-fills until the user edits the
/// field (NOTES: "RTCBuilder leaves placeholders"): vendor `VenderName` (sic), category
/// `Category`, name `ModuleName`, description `ModuleDescription`, and template variables such
/// as `$VenderName` in any field.
pub fn is_placeholder(field: &str, value: &str) -> bool {
    let v = value.trim();
    if let Some(var) = v.strip_prefix('$') {
        if !var.is_empty() && var.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
            return true;
        }
    }
    matches!(
        (field, v),
        ("vendor", "VenderName")
            | ("category", "Category")
            | ("name", "ModuleName")
            | ("description", "ModuleDescription")
    )
}

/// A text that documents something: non-empty and not a placeholder of `field`.
pub fn documented<'a>(field: &str, s: &'a Option<Text>) -> Option<&'a str> {
    non_empty(s).filter(|v| !is_placeholder(field, v))
}

impl Constraint {
    /// The placeholder RTCBuilder writes for a constraint nobody filled in: a unit
    /// `propertyIsEqualTo` whose literal is `conf_constraint` (configurations) or
    /// `dp_constraint` (data ports). Such a constraint constrains nothing.
    pub fn placeholder(&self) -> Option<&str> {
        let ConstraintKind::Unit { condition, .. } = &self.kind else {
            return None;
        };
        match condition.as_ref() {
            Condition::Compare {
                comparison: Comparison::EqualTo,
                literal: Some(l),
                ..
            } => {
                let l = l.trim();
                matches!(l, "conf_constraint" | "dp_constraint").then_some(l)
            }
            _ => None,
        }
    }
}

/// Parses an `xsd:boolean` (`true`, `false`, `1`, `0`; surrounding space allowed).
pub fn parse_bool(s: Option<&str>) -> Option<bool> {
    match s?.trim() {
        "true" | "1" | "True" | "TRUE" => Some(true),
        "false" | "0" | "False" | "FALSE" => Some(false),
        _ => None,
    }
}

/// Value of the first property called `name`.
pub fn property_value<'a>(props: &'a [Property], name: &str) -> Option<&'a str> {
    props
        .iter()
        .find(|p| p.name.as_deref() == Some(name))
        .and_then(|p| p.value.as_deref())
}

/// Profile prose as it means: RTCBuilder stores a line break inside a text field as the tag
/// `<br/>` (escaped in the XML as `&lt;br/&gt;`; `<br>`, `<BR>` and `<br />` occur too, and
/// the doubly escaped `&lt;br/&gt;` after a round trip through another tool). Each becomes a
/// line break; everything else is unchanged. Every output renders prose through this one
/// function (HTML, Markdown, Doxygen, the search index); the JSON keeps the value as written.
pub fn prose(s: &str) -> std::borrow::Cow<'_, str> {
    if memchr::memchr2(b'<', b'&', s.as_bytes()).is_none() {
        return std::borrow::Cow::Borrowed(s);
    }
    // The length of a line-break tag at the start of `rest`, if one starts there.
    fn tag_len(rest: &str) -> Option<usize> {
        let (open, close) = if rest.starts_with('<') {
            ("<", ">")
        } else if rest.starts_with("&lt;") {
            ("&lt;", "&gt;")
        } else {
            return None;
        };
        let after = &rest[open.len()..];
        if !after.get(..2)?.eq_ignore_ascii_case("br") {
            return None;
        }
        let tail = &after[2..];
        let trimmed = tail.trim_start_matches([' ', '\t']);
        let trimmed = trimmed.strip_prefix('/').unwrap_or(trimmed);
        let end = trimmed.strip_prefix(close)?;
        Some(rest.len() - end.len())
    }
    let mut out = String::with_capacity(s.len());
    let mut last = 0;
    let mut i = 0;
    let b = s.as_bytes();
    let mut changed = false;
    while i < b.len() {
        if b[i] == b'<' || b[i] == b'&' {
            if let Some(n) = tag_len(&s[i..]) {
                out.push_str(&s[last..i]);
                out.push('\n');
                i += n;
                last = i;
                changed = true;
                continue;
            }
        }
        i += 1;
    }
    if !changed {
        return std::borrow::Cow::Borrowed(s);
    }
    out.push_str(&s[last..]);
    std::borrow::Cow::Owned(out)
}

/// A non-empty, trimmed view of an optional string: empty attributes count as absent when
/// rendering (NOTES: "treat empty as absent when rendering, but keep it in JSON as given").
pub fn non_empty(s: &Option<Text>) -> Option<&str> {
    s.as_deref().map(str::trim).filter(|s| !s.is_empty())
}

impl Profile {
    /// The component name, or a placeholder for a profile without one.
    pub fn name(&self) -> &str {
        non_empty(&self.basic_info.name).unwrap_or("(unnamed component)")
    }

    /// The implementation language the profile declares (`rtc:Language` `kind`: `C++`,
    /// `Python`), trimmed; `None` when it names none.
    pub fn language_kind(&self) -> Option<&str> {
        self.language.as_ref().and_then(|l| non_empty(&l.kind))
    }

    /// The action of `kind`, when the profile lists it.
    pub fn action(&self, kind: ActionKind) -> Option<&Action> {
        self.actions.iter().find(|a| a.kind == kind)
    }

    /// The type fields of the data ports, then of the service interfaces (port by port), in
    /// document order.
    pub fn port_types(&self) -> impl Iterator<Item = &Option<Text>> {
        self.data_ports
            .iter()
            .map(|d| &d.type_)
            .chain(self.service_interfaces().map(|(_, _, i)| &i.type_))
    }

    /// Every interface of every service port, in document order, with the position of its
    /// port and its position in the port.
    pub fn service_interfaces(&self) -> impl Iterator<Item = (usize, usize, &ServiceInterface)> {
        self.service_ports.iter().enumerate().flat_map(|(pi, p)| {
            p.interfaces
                .iter()
                .enumerate()
                .map(move |(ii, i)| (pi, ii, i))
        })
    }

    /// Configuration parameters (empty when there is no configuration set).
    pub fn configurations(&self) -> &[Configuration] {
        self.configuration_set
            .as_ref()
            .map(|c| c.configurations.as_slice())
            .unwrap_or(&[])
    }

    /// Whether the profile marks itself as a finite-state-machine component (`FSM` property or
    /// an `EventPort`).
    pub fn is_fsm(&self) -> bool {
        property_value(&self.basic_info.properties, "FSM")
            .map(|v| v.eq_ignore_ascii_case("yes") || v.eq_ignore_ascii_case("true"))
            .unwrap_or(false)
            || self
                .data_ports
                .iter()
                .any(|p| p.direction() == Some(PortDirection::Event))
    }

    /// Every `extra` entry anywhere in the profile, with a dotted path to its node, for
    /// warnings and for the "extra properties" section of rendered pages.
    pub fn all_extras(&self) -> Vec<(String, &Extra)> {
        let mut out = Vec::new();
        collect_extras(self, &mut out);
        out
    }
}

fn collect_extras<'a>(p: &'a Profile, out: &mut Vec<(String, &'a Extra)>) {
    fn add<'a>(out: &mut Vec<(String, &'a Extra)>, path: &str, extras: &'a [Extra]) {
        out.extend(extras.iter().map(|e| (path.to_string(), e)));
    }
    fn constraint<'a>(out: &mut Vec<(String, &'a Extra)>, path: &str, c: &'a Constraint) {
        add(out, path, &c.extra);
        match &c.kind {
            ConstraintKind::Unit { condition, .. } => match condition.as_ref() {
                Condition::Not { operand } => constraint(out, path, operand),
                Condition::And { operands } | Condition::Or { operands } => {
                    operands.iter().for_each(|o| constraint(out, path, o))
                }
                _ => {}
            },
            ConstraintKind::List { items } | ConstraintKind::Hash { items } => {
                items.iter().for_each(|o| constraint(out, path, o))
            }
            ConstraintKind::Empty => {}
        }
    }
    fn props<'a>(out: &mut Vec<(String, &'a Extra)>, path: &str, ps: &'a [Property]) {
        ps.iter().for_each(|p| add(out, path, &p.extra));
    }
    add(out, "profile", &p.extra);
    let b = &p.basic_info;
    add(out, "basicInfo", &b.extra);
    if let Some(d) = &b.doc {
        add(out, "basicInfo.doc", &d.extra);
    }
    props(out, "basicInfo.properties", &b.properties);
    for a in &p.actions {
        let path = format!("actions.{}", a.kind.yaml_name());
        add(out, &path, &a.extra);
        if let Some(d) = &a.doc {
            add(out, &path, &d.extra);
        }
    }
    if let Some(cs) = &p.configuration_set {
        add(out, "configurationSet", &cs.extra);
        for c in &cs.configurations {
            let path = format!("configuration {}", c.name.as_deref().unwrap_or(""));
            add(out, &path, &c.extra);
            if let Some(d) = &c.doc {
                add(out, &path, &d.extra);
            }
            if let Some(k) = &c.constraint {
                constraint(out, &path, k);
            }
            props(out, &path, &c.properties);
        }
    }
    for d in &p.data_ports {
        let path = format!("dataPort {}", d.name.as_deref().unwrap_or(""));
        add(out, &path, &d.extra);
        if let Some(doc) = &d.doc {
            add(out, &path, &doc.extra);
        }
        if let Some(k) = &d.constraint {
            constraint(out, &path, k);
        }
        props(out, &path, &d.properties);
        for e in &d.events {
            add(out, &path, &e.extra);
            if let Some(doc) = &e.doc {
                add(out, &path, &doc.extra);
            }
        }
    }
    for s in &p.service_ports {
        let path = format!("servicePort {}", s.name.as_deref().unwrap_or(""));
        add(out, &path, &s.extra);
        if let Some(doc) = &s.doc {
            add(out, &path, &doc.extra);
        }
        props(out, &path, &s.properties);
        s.trans_methods
            .iter()
            .for_each(|t| add(out, &path, &t.extra));
        for i in &s.interfaces {
            let ipath = format!("{path} / interface {}", i.name.as_deref().unwrap_or(""));
            add(out, &ipath, &i.extra);
            if let Some(doc) = &i.doc {
                add(out, &ipath, &doc.extra);
            }
            props(out, &ipath, &i.properties);
        }
    }
    for par in &p.parameters {
        add(out, "parameters", &par.extra);
    }
    if let Some(l) = &p.language {
        add(out, "language", &l.extra);
        for t in &l.targets {
            add(out, "language.targets", &t.extra);
            t.libraries
                .iter()
                .for_each(|lib| add(out, "language.targets.libraries", &lib.extra));
        }
    }
}
