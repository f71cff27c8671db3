//! The model field table: every scalar field of every node of a component profile and of an
//! RT System profile, described once — its node, its Rust field, its JSON (serde) name, the XML attribute names and YAML keys
//! it is read from (with the older spellings and the writer that uses each), whether it is a
//! date and whether it is documentation only.
//!
//! The readers (`parse::xml::map`, `parse::yaml`, and for systems `parse::xml::rts`,
//! `parse::rts_yaml`), the attribute positions ([`AttrPos`]) and
//! `diff` read this table; none of them lists a field's names itself. A new scalar field is one
//! line here (plus the `Option<Text>` in `component.rs` and its view in `render/facts.rs`).
//!
//! Nodes are also linked to their children ([`CHILDREN`]): which JSON key holds which node, and
//! by which key the items of a list are matched. `diff` turns a JSON path into a typed
//! [`Place`] with it.

use super::component::*;
use super::system::{
    ConfigurationData, DataPortConnector, ExecutionContext, Group, Location, Order, OrderTarget,
    PortEnd, Preceding, RtSystem, ServicePortConnector, SubSystem, SystemComponent,
    SystemConfigurationSet, SystemPort, SystemProperty, TargetComponent, WaitTime,
};

/// The writer generation of the dotted id, `varname`, `subscriprionType`, the language
/// elements and `EVENT_DRIVEN`.
pub const RTCBUILDER_01: &str = "RTCBuilder 0.1";
/// OpenRTM-aist-Python's rtc-template and the old OpenRTP YAML samples: unprefixed `doc`,
/// `position`, `varname`, `versionUpLog` keys.
pub const RTC_TEMPLATE: &str = "rtc-template";

/// The prefix of the extended RT System profile's YAML keys, optional on every system key.
pub const RTS_EXT: &str = "rtsExt::";

/// One way a field is written: an XML attribute's local name or a YAML key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Spelling {
    pub name: &'static str,
    /// The writer of an older spelling, recorded in [`Profile::written_as`] when read; `None`
    /// for the spec's spelling and for misspellings accepted silently (`occerrence`).
    pub dialect: Option<&'static str>,
}

/// How the YAML reader reads a field's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A scalar, kept as written.
    Text,
    /// A scalar, or a chapter 7 date map turned into ISO 8601 (`creationDate`, `updateDate`).
    Date,
}

/// One line of the table.
#[derive(Debug)]
pub struct FieldDef {
    pub field: Field,
    pub node: Node,
    /// The Rust field of the node's struct.
    pub rust: &'static str,
    /// The serde name: the key in `catalog.json`, and the path segment of `diff`.
    pub json: &'static str,
    /// XML attribute local names (any RTC namespace), the spec's first.
    pub xml: &'static [Spelling],
    /// YAML keys, the spec's first.
    pub yaml: &'static [Spelling],
    pub kind: Kind,
    /// A change of it is a documentation change (`diff`).
    pub doc: bool,
}

/// A node of the model with the fields of the table.
pub trait Fields: super::Located {
    const NODE: Node;
    /// The field `f` of this node (`None` for a field of another node).
    fn slot(&mut self, f: Field) -> Option<&mut Option<Text>>;
    /// The value of field `f` of this node (`None` for a field of another node).
    fn value(&self, f: Field) -> Option<&Option<Text>>;
    /// The positions of its attributes / keys, on the nodes that keep them.
    fn attr_pos(&mut self) -> Option<&mut AttrPos> {
        None
    }
}

macro_rules! dialect {
    () => {
        None
    };
    ($d:ident) => {
        Some($d)
    };
}

/// `["name", "old" @ DIALECT]` → `&[Spelling]`; a constant's name stands for itself.
macro_rules! spellings {
    ([$($name:literal $(@ $d:ident)?),* $(,)?]) => {
        &[$(Spelling { name: $name, dialect: dialect!($($d)?) }),*]
    };
    ($list:ident) => {
        $list
    };
}

/// A row's spellings in one format (`xml` or `yaml`): the row's own list for that format, else
/// its `both` list, else its JSON name alone.
macro_rules! spelled {
    ($format:ident, $json:literal;) => {
        spellings!([$json])
    };
    (xml, $json:literal; xml $list:tt $($rest:tt)*) => {
        spellings!($list)
    };
    (yaml, $json:literal; yaml $list:tt $($rest:tt)*) => {
        spellings!($list)
    };
    ($format:ident, $json:literal; both $list:tt $($rest:tt)*) => {
        spellings!($list)
    };
    ($format:ident, $json:literal; $other:ident $list:tt $($rest:tt)*) => {
        spelled!($format, $json; $($rest)*)
    };
}

macro_rules! table {
    ($(
        $node:ident $([$pos:ident])? {
            $( $var:ident : $acc:ident = $json:literal, $kind:ident, $doc:literal
               $(, $format:ident $list:tt)*; )*
        }
    )*) => {
        /// The nodes of a component profile and of an RT System profile.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Node { $($node,)* ConfigurationSet, Constraint, TextList }

        /// Every scalar field of every node.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Field { $($($var,)*)* }

        impl Field {
            /// Every field, in table order (`Field::ALL[f as usize] == f`).
            pub const ALL: &'static [Field] = &[$($(Field::$var,)*)*];
            /// The JSON name of each field, in table order.
            const JSON: &'static [&'static str] = &[$($($json,)*)*];
            /// The node the field belongs to.
            pub fn node(self) -> Node {
                match self { $($(Field::$var => Node::$node,)*)* }
            }
        }

        #[allow(non_upper_case_globals)]
        mod per_node {
            use super::*;
            $(pub static $node: &[FieldDef] = &[$(FieldDef {
                field: Field::$var,
                node: Node::$node,
                rust: stringify!($acc),
                json: $json,
                xml: spelled!(xml, $json; $($format $list)*),
                yaml: spelled!(yaml, $json; $($format $list)*),
                kind: Kind::$kind,
                doc: $doc,
            },)*];)*
        }

        impl Node {
            /// The fields of the node, in table order.
            pub fn fields(self) -> &'static [FieldDef] {
                match self {
                    $(Node::$node => per_node::$node,)*
                    Node::ConfigurationSet | Node::Constraint | Node::TextList => &[],
                }
            }
        }

        $(impl Fields for $node {
            const NODE: Node = Node::$node;
            fn slot(&mut self, f: Field) -> Option<&mut Option<Text>> {
                match f {
                    $(Field::$var => Some(&mut self.$acc),)*
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }
            fn value(&self, f: Field) -> Option<&Option<Text>> {
                match f {
                    $(Field::$var => Some(&self.$acc),)*
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }
            $(fn attr_pos(&mut self) -> Option<&mut AttrPos> {
                let _ = stringify!($pos);
                Some(&mut self.attr_pos)
            })?
        })*
    };
}

/// `variableName` as RTCBuilder writes it in XML (0.1: `varname`).
const VARIABLE_NAME_XML: &[Spelling] = spellings!(["variableName", "varname" @ RTCBUILDER_01]);
/// `variableName` in YAML (rtc-template: `varname`, `rtcExt::varname`).
const VARIABLE_NAME_YAML: &[Spelling] = spellings!([
    "rtcExt::variableName",
    "rtcExt::varname" @ RTC_TEMPLATE,
    "varname" @ RTC_TEMPLATE,
]);
/// `rtcExt:position` in YAML (rtc-template: `position`).
const POSITION_YAML: &[Spelling] = spellings!(["rtcExt::position", "position" @ RTC_TEMPLATE]);
/// `rtcExt:comment` in YAML.
const COMMENT_YAML: &[Spelling] = spellings!(["rtcExt::comment"]);

// node [keeps positions] { Variant: rust_field = "json", Text|Date, documentation?
//                          [, xml [attribute names]] [, yaml [keys]] [, both [names]]; }
// A format without a list of its own reads the `both` list, or else the row's JSON name alone.
table! {
    Profile [pos] {
        ProfileId: id = "id", Text, false;
        ProfileVersion: version = "version", Text, false;
    }
    BasicInfo [pos] {
        BasicName: name = "name", Text, false;
        BasicComponentType: component_type = "componentType", Text, false;
        BasicActivityType: activity_type = "activityType", Text, false;
        BasicComponentKind: component_kind = "componentKind", Text, false;
        BasicRtcType: rtc_type = "rtcType", Text, false;
        BasicCategory: category = "category", Text, false;
        BasicDescription: description = "description", Text, true;
        BasicExecutionRate: execution_rate = "executionRate", Text, false;
        BasicExecutionType: execution_type = "executionType", Text, false;
        BasicMaxInstances: max_instances = "maxInstances", Text, false;
        BasicVendor: vendor = "vendor", Text, false;
        BasicVersion: version = "version", Text, false;
        BasicAbstract: abstract_ = "abstract", Text, true;
        BasicHardwareProfile: hardware_profile = "hardwareProfile", Text, true;
        BasicCreationDate: creation_date = "creationDate", Date, false;
        BasicUpdateDate: update_date = "updateDate", Date, false;
        BasicComment: comment = "comment", Text, true, yaml COMMENT_YAML;
        BasicSaveProject: save_project = "saveProject", Text, false, yaml ["rtcExt::saveProject"];
    }
    BasicDoc {
        BasicDocDescription: description = "description", Text, true;
        BasicDocInout: inout = "inout", Text, true;
        BasicDocAlgorithm: algorithm = "algorithm", Text, true;
        BasicDocCreator: creator = "creator", Text, true;
        BasicDocLicense: license = "license", Text, true;
        BasicDocReference: reference = "reference", Text, true;
    }
    Action {
        ActionImplemented: implemented = "implemented", Text, false;
    }
    ActionDoc {
        ActionDocDescription: description = "description", Text, true;
        ActionDocPreCondition: pre_condition = "preCondition", Text, true;
        ActionDocPostCondition: post_condition = "postCondition", Text, true;
    }
    Configuration [pos] {
        ConfigurationName: name = "name", Text, false;
        ConfigurationType: type_ = "type", Text, false;
        ConfigurationDefaultValue: default_value = "defaultValue", Text, false;
        ConfigurationUnit: unit = "unit", Text, false;
        ConfigurationComment: comment = "comment", Text, true, yaml COMMENT_YAML;
        ConfigurationVariableName: variable_name = "variableName",
            Text, false, xml VARIABLE_NAME_XML, yaml VARIABLE_NAME_YAML;
    }
    ConfigurationDoc {
        ConfigurationDocDataname: dataname = "dataname", Text, true;
        ConfigurationDocDefaultValue: default_value = "defaultValue", Text, true;
        ConfigurationDocDescription: description = "description", Text, true;
        ConfigurationDocUnit: unit = "unit", Text, true;
        ConfigurationDocRange: range = "range", Text, true;
        ConfigurationDocConstraint: constraint = "constraint", Text, true;
    }
    DataPort [pos] {
        DataPortPortType: port_type = "portType", Text, false;
        DataPortName: name = "name", Text, false;
        DataPortType: type_ = "type", Text, false;
        DataPortIdlFile: idl_file = "idlFile", Text, false;
        DataPortInterfaceType: interface_type = "interfaceType", Text, false;
        DataPortDataflowType: dataflow_type = "dataflowType", Text, false;
        // RTCBuilder 0.1 (2009) misspells it.
        DataPortSubscriptionType: subscription_type = "subscriptionType",
            Text, false, both ["subscriptionType", "subscriprionType" @ RTCBUILDER_01];
        DataPortUnit: unit = "unit", Text, false;
        DataPortComment: comment = "comment", Text, true, yaml COMMENT_YAML;
        DataPortVariableName: variable_name = "variableName",
            Text, false, xml VARIABLE_NAME_XML, yaml VARIABLE_NAME_YAML;
        DataPortPosition: position = "position", Text, false, yaml POSITION_YAML;
    }
    DataPortDoc {
        DataPortDocDescription: description = "description", Text, true;
        DataPortDocType: type_ = "type", Text, true;
        DataPortDocNumber: number = "number", Text, true;
        DataPortDocSemantics: semantics = "semantics", Text, true;
        DataPortDocUnit: unit = "unit", Text, true;
        // RTCBuilder writes `occerrence`: accepted silently as the same field.
        DataPortDocOccurrence: occurrence = "occurrence",
            Text, true, both ["occurrence", "occerrence"];
        DataPortDocOperation: operation = "operation", Text, true;
    }
    Event {
        EventName: name = "name", Text, false, yaml [];
        EventType: type_ = "type", Text, false, yaml [];
        EventSource: source = "source", Text, false, yaml [];
        EventTarget: target = "target", Text, false, yaml [];
        EventCondition: condition = "condition", Text, false, yaml [];
    }
    ServicePort [pos] {
        ServicePortName: name = "name", Text, false;
        ServicePortComment: comment = "comment", Text, true, yaml COMMENT_YAML;
        ServicePortPosition: position = "position", Text, false, yaml POSITION_YAML;
    }
    ServicePortDoc {
        ServicePortDocDescription: description = "description", Text, true;
        ServicePortDocIfdescription: ifdescription = "ifdescription", Text, true;
    }
    TransMethod {
        TransMethodKind: kind = "kind", Text, false;
    }
    ServiceInterface [pos] {
        InterfaceName: name = "name", Text, false;
        InterfaceType: type_ = "type", Text, false;
        InterfaceDirection: direction = "direction", Text, false;
        InterfaceInstanceName: instance_name = "instanceName", Text, false;
        InterfaceIdlFile: idl_file = "idlFile", Text, false;
        InterfacePath: path = "path", Text, false;
        InterfaceComment: comment = "comment", Text, true, yaml COMMENT_YAML;
        InterfaceVariableName: variable_name = "variableName",
            Text, false, xml VARIABLE_NAME_XML, yaml VARIABLE_NAME_YAML;
    }
    ServiceInterfaceDoc {
        InterfaceDocDescription: description = "description", Text, true;
        InterfaceDocArgument: doc_argument = "docArgument", Text, true;
        InterfaceDocReturn: doc_return = "docReturn", Text, true;
        InterfaceDocException: doc_exception = "docException", Text, true;
        InterfaceDocPreCondition: doc_pre_condition = "docPreCondition", Text, true;
        InterfaceDocPostCondition: doc_post_condition = "docPostCondition", Text, true;
    }
    Parameter {
        ParameterName: name = "name", Text, false;
        ParameterDefaultValue: default_value = "defaultValue", Text, false;
    }
    Property {
        PropertyName: name = "name", Text, false;
        PropertyValue: value = "value", Text, false;
    }
    Language {
        LanguageKind: kind = "kind", Text, false;
    }
    Target {
        TargetLangVersion: lang_version = "langVersion", Text, false;
        TargetOs: os = "os", Text, false;
        TargetOther: other = "other", Text, false;
        TargetCpuOther: cpu_other = "cpuOther", Text, false;
    }
    // The PIM calls the library's name `path`: accepted silently.
    Library {
        LibraryName: name = "name", Text, false, both ["name", "path"];
        LibraryVersion: version = "version", Text, false;
        LibraryOther: other = "other", Text, false;
    }
    // RT System profiles (`model/system.rs`): the XML attributes and YAML keys are the same
    // names, in either the `rts` or the `rtsExt` namespace (YAML: with or without `rtsExt::`).
    RtSystem {
        SystemId: id = "id", Text, false;
        SystemVersion: version = "version", Text, false;
        SystemAbstract: abstract_ = "abstract", Text, false;
        SystemCreationDate: creation_date = "creationDate", Date, false;
        SystemUpdateDate: update_date = "updateDate", Date, false;
        SystemComment: comment = "comment", Text, false;
    }
    SystemProperty {
        SystemPropertyName: name = "name", Text, false;
        SystemPropertyValue: value = "value", Text, false;
    }
    SubSystem {
        SubSystemPath: path = "path", Text, false;
    }
    SystemComponent {
        InstanceId: id = "id", Text, false;
        InstancePathUri: path_uri = "pathUri", Text, false;
        InstanceActiveConfigurationSet: active_configuration_set = "activeConfigurationSet",
            Text, false;
        InstanceName: instance_name = "instanceName", Text, false;
        InstanceCompositeType: composite_type = "compositeType", Text, false;
        InstanceIsRequired: is_required = "isRequired", Text, false;
        InstanceComment: comment = "comment", Text, false;
        InstanceVisible: visible = "visible", Text, false;
    }
    SystemPort {
        SystemPortName: name = "name", Text, false;
        SystemPortComment: comment = "comment", Text, false;
        SystemPortVisible: visible = "visible", Text, false;
    }
    SystemConfigurationSet {
        SystemConfigurationSetId: id = "id", Text, false;
    }
    ConfigurationData {
        ConfigurationDataName: name = "name", Text, false;
        ConfigurationDataData: data = "data", Text, false;
    }
    ExecutionContext {
        ExecutionContextId: id = "id", Text, false;
        ExecutionContextKind: kind = "kind", Text, false;
        ExecutionContextRate: rate = "rate", Text, false;
    }
    TargetComponent {
        TargetComponentId: component_id = "componentId", Text, false;
        TargetInstanceName: instance_name = "instanceName", Text, false;
        TargetId: id = "id", Text, false;
    }
    Location {
        LocationX: x = "x", Text, false;
        LocationY: y = "y", Text, false;
        LocationHeight: height = "height", Text, false;
        LocationWidth: width = "width", Text, false;
        LocationDirection: direction = "direction", Text, false;
    }
    // rtsprofile (Python) writes `groupID`, the schema `groupId`: either fills the id (a
    // second one is a repeated attribute in XML).
    Group {
        GroupId: group_id = "groupId", Text, false, both ["groupId", "groupID"];
    }
    PortEnd {
        PortEndComponentId: component_id = "componentId", Text, false;
        PortEndInstanceName: instance_name = "instanceName", Text, false;
        PortEndPortName: port_name = "portName", Text, false;
    }
    DataPortConnector {
        DataConnectorId: connector_id = "connectorId", Text, false;
        DataConnectorName: name = "name", Text, false;
        DataConnectorDataType: data_type = "dataType", Text, false;
        DataConnectorInterfaceType: interface_type = "interfaceType", Text, false;
        DataConnectorDataflowType: dataflow_type = "dataflowType", Text, false;
        DataConnectorSubscriptionType: subscription_type = "subscriptionType", Text, false;
        DataConnectorPushInterval: push_interval = "pushInterval", Text, false;
        DataConnectorComment: comment = "comment", Text, false;
        DataConnectorVisible: visible = "visible", Text, false;
    }
    ServicePortConnector {
        ServiceConnectorId: connector_id = "connectorId", Text, false;
        ServiceConnectorName: name = "name", Text, false;
        ServiceConnectorTransMethod: trans_method = "transMethod", Text, false;
        ServiceConnectorComment: comment = "comment", Text, false;
        ServiceConnectorVisible: visible = "visible", Text, false;
    }
    Order {}
    OrderTarget {
        OrderTargetSequence: sequence = "sequence", Text, false;
    }
    WaitTime {
        WaitTimeWaitTime: wait_time = "waitTime", Text, false;
    }
    Preceding {
        PrecedingTimeout: timeout = "timeout", Text, false;
        PrecedingSendingTiming: sending_timing = "sendingTiming", Text, false;
    }
}

impl Field {
    /// The field's line of the table.
    pub fn def(self) -> &'static FieldDef {
        let fields = self.node().fields();
        // Every field is in its node's list (held by a test).
        fields
            .iter()
            .find(|d| d.field == self)
            .unwrap_or(&fields[0])
    }
    /// The serde (JSON) name.
    pub fn json(self) -> &'static str {
        Field::JSON[self as usize]
    }
    /// The field of index `i` (`Field::ALL[i]`).
    pub fn from_index(i: u8) -> Option<Field> {
        Field::ALL.get(usize::from(i)).copied()
    }
}

impl Node {
    /// The field read from XML attribute `local` on this node, and the spelling it had.
    pub fn xml(self, local: &str) -> Option<(&'static FieldDef, &'static Spelling)> {
        self.fields()
            .iter()
            .find_map(|d| d.xml.iter().find(|s| s.name == local).map(|s| (d, s)))
    }
    /// The field read from YAML key `key` on this node, and the spelling it had (on the nodes
    /// of an RT System, `key` may carry the `rtsExt::` prefix).
    pub fn yaml(self, key: &str) -> Option<(&'static FieldDef, &'static Spelling)> {
        let key = if self.is_system() {
            key.strip_prefix(RTS_EXT).unwrap_or(key)
        } else {
            key
        };
        self.fields()
            .iter()
            .find_map(|d| d.yaml.iter().find(|s| s.name == key).map(|s| (d, s)))
    }
    /// The field whose JSON name is `json` on this node.
    pub fn json_field(self, json: &str) -> Option<Field> {
        self.fields()
            .iter()
            .find(|d| d.json == json)
            .map(|d| d.field)
    }
    /// The child node under JSON key `json` of this node, with how its items are matched.
    pub fn child(self, json: &str) -> Option<&'static Child> {
        CHILDREN.iter().find(|c| c.parent == self && c.json == json)
    }
    /// The child nodes of this node.
    pub fn children(self) -> impl Iterator<Item = &'static Child> {
        CHILDREN.iter().filter(move |c| c.parent == self)
    }
    /// Whether the node is a node of an RT System profile.
    pub fn is_system(self) -> bool {
        matches!(
            self,
            Node::RtSystem
                | Node::SystemProperty
                | Node::SubSystem
                | Node::SystemComponent
                | Node::SystemPort
                | Node::SystemConfigurationSet
                | Node::ConfigurationData
                | Node::ExecutionContext
                | Node::TargetComponent
                | Node::Location
                | Node::Group
                | Node::PortEnd
                | Node::DataPortConnector
                | Node::ServicePortConnector
                | Node::Order
                | Node::OrderTarget
                | Node::WaitTime
                | Node::Preceding
        )
    }
    /// Whether the node is a documentation node (`rtcDoc:Doc`).
    pub fn is_doc(self) -> bool {
        matches!(
            self,
            Node::BasicDoc
                | Node::ActionDoc
                | Node::ConfigurationDoc
                | Node::DataPortDoc
                | Node::ServicePortDoc
                | Node::ServiceInterfaceDoc
        )
    }
}

/// How a node holds a child node in the JSON.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Holds {
    /// One record (`basicInfo`, `doc`).
    One,
    /// A list whose items are matched by the JSON key given (`dataPorts` by `name`).
    Keyed(&'static str),
    /// A value compared whole (a list of unnamed items, a constraint, a list of texts).
    Whole,
}

/// A child node of a node, by the JSON key that holds it.
#[derive(Debug)]
pub struct Child {
    pub parent: Node,
    pub json: &'static str,
    pub node: Node,
    pub holds: Holds,
    /// A change of it is a documentation change.
    pub doc: bool,
}

macro_rules! children {
    ($($parent:ident . $json:literal => $node:ident $holds:ident $(($key:literal))? $(, $doc:literal)?;)*) => {
        /// The child nodes of each node, by JSON key.
        pub static CHILDREN: &[Child] = &[$(Child {
            parent: Node::$parent,
            json: $json,
            node: Node::$node,
            holds: Holds::$holds $(($key))?,
            doc: false $(|| $doc)?,
        },)*];
    };
}

children! {
    Profile."basicInfo" => BasicInfo One;
    Profile."actions" => Action Keyed("kind");
    Profile."configurationSet" => ConfigurationSet One;
    Profile."dataPorts" => DataPort Keyed("name");
    Profile."servicePorts" => ServicePort Keyed("name");
    Profile."parameters" => Parameter Keyed("name");
    Profile."language" => Language One;
    BasicInfo."doc" => BasicDoc One;
    BasicInfo."properties" => Property Keyed("name");
    BasicInfo."versionUpLogs" => TextList Whole, true;
    Action."doc" => ActionDoc One;
    ConfigurationSet."configurations" => Configuration Keyed("name");
    Configuration."doc" => ConfigurationDoc One;
    Configuration."properties" => Property Keyed("name");
    Configuration."constraint" => Constraint Whole;
    DataPort."doc" => DataPortDoc One;
    DataPort."properties" => Property Keyed("name");
    DataPort."constraint" => Constraint Whole;
    DataPort."events" => Event Keyed("name");
    Event."doc" => DataPortDoc One;
    ServicePort."doc" => ServicePortDoc One;
    ServicePort."properties" => Property Keyed("name");
    ServicePort."interfaces" => ServiceInterface Keyed("name");
    ServicePort."transMethods" => TransMethod Whole;
    ServiceInterface."doc" => ServiceInterfaceDoc One;
    ServiceInterface."properties" => Property Keyed("name");
    Language."targets" => Target Whole;
    Target."libraries" => Library Keyed("name");
}

/// The JSON key of a list whose items are matched by a key, and that key (`dataPorts` →
/// `name`), for any node.
pub fn item_key(list: &str) -> Option<&'static str> {
    CHILDREN.iter().find_map(|c| match c.holds {
        Holds::Keyed(k) if c.json == list => Some(k),
        _ => None,
    })
}

/// Whether the value under JSON key `key` is compared whole (a constraint, a list of unnamed
/// items or of texts), whatever node holds it.
pub fn compared_whole(key: &str) -> bool {
    CHILDREN
        .iter()
        .any(|c| c.json == key && c.holds == Holds::Whole)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    #[test]
    fn the_table_is_in_field_order_and_every_field_has_its_line() {
        for (i, &f) in Field::ALL.iter().enumerate() {
            assert_eq!(f as usize, i);
            assert_eq!(Field::from_index(u8::try_from(i).expect("u8")), Some(f));
            let d = f.def();
            assert_eq!((d.field, d.node), (f, f.node()), "{f:?}");
            assert_eq!(d.json, f.json(), "{f:?}");
        }
        assert!(Field::ALL.len() <= usize::from(u8::MAX));
    }

    #[test]
    fn names_and_spellings_are_unique_on_each_node() {
        for &f in Field::ALL {
            let d = f.def();
            let node = f.node();
            assert_eq!(node.json_field(d.json), Some(f), "{f:?} json");
            for s in d.xml {
                assert_eq!(node.xml(s.name).map(|(x, _)| x.field), Some(f), "{f:?} xml");
            }
            for s in d.yaml {
                assert_eq!(
                    node.yaml(s.name).map(|(x, _)| x.field),
                    Some(f),
                    "{f:?} yaml"
                );
            }
            // The spec's spelling comes first and is not an older writer's.
            for list in [d.xml, d.yaml] {
                assert!(list.first().is_none_or(|s| s.dialect.is_none()), "{f:?}");
            }
        }
    }

    #[test]
    fn system_keys_take_the_rts_ext_prefix_and_component_keys_do_not() {
        let field = |node: Node, key| node.yaml(key).map(|(d, _)| d.field);
        let comment = Some(Field::InstanceComment);
        assert_eq!(field(Node::SystemComponent, "comment"), comment);
        assert_eq!(field(Node::SystemComponent, "rtsExt::comment"), comment);
        assert_eq!(field(Node::SystemComponent, "rtcExt::comment"), None);
        assert_eq!(field(Node::BasicInfo, "rtsExt::comment"), None);
        assert!(Node::Order.is_system() && !Node::Profile.is_system());
    }

    /// The node of `f` with only `f` set, as JSON.
    fn json_with(f: Field) -> Value {
        fn set<T: Fields + serde::Serialize>(mut t: T, f: Field) -> Value {
            *t.slot(f).expect("a field of the node") = Some("set-by-test".into());
            serde_json::to_value(&t).expect("json")
        }
        match f.node() {
            Node::Profile => set(Profile::default(), f),
            Node::BasicInfo => set(BasicInfo::default(), f),
            Node::BasicDoc => set(BasicDoc::default(), f),
            Node::Action => set(
                Action {
                    kind: ActionKind::OnExecute,
                    implemented: None,
                    doc: None,
                    pos: Pos::default(),
                    extra: crate::model::Extras::new(),
                },
                f,
            ),
            Node::ActionDoc => set(ActionDoc::default(), f),
            Node::Configuration => set(Configuration::default(), f),
            Node::ConfigurationDoc => set(ConfigurationDoc::default(), f),
            Node::DataPort => set(DataPort::default(), f),
            Node::DataPortDoc => set(DataPortDoc::default(), f),
            Node::Event => set(Event::default(), f),
            Node::ServicePort => set(ServicePort::default(), f),
            Node::ServicePortDoc => set(ServicePortDoc::default(), f),
            Node::TransMethod => set(TransMethod::default(), f),
            Node::ServiceInterface => set(ServiceInterface::default(), f),
            Node::ServiceInterfaceDoc => set(ServiceInterfaceDoc::default(), f),
            Node::Parameter => set(Parameter::default(), f),
            Node::Property => set(Property::default(), f),
            Node::Language => set(Language::default(), f),
            Node::Target => set(Target::default(), f),
            Node::Library => set(Library::default(), f),
            Node::RtSystem => set(RtSystem::default(), f),
            Node::SystemProperty => set(SystemProperty::default(), f),
            Node::SubSystem => set(SubSystem::default(), f),
            Node::SystemComponent => set(SystemComponent::default(), f),
            Node::SystemPort => set(SystemPort::default(), f),
            Node::SystemConfigurationSet => set(SystemConfigurationSet::default(), f),
            Node::ConfigurationData => set(ConfigurationData::default(), f),
            Node::ExecutionContext => set(ExecutionContext::default(), f),
            Node::TargetComponent => set(TargetComponent::default(), f),
            Node::Location => set(Location::default(), f),
            Node::Group => set(Group::default(), f),
            Node::PortEnd => set(PortEnd::default(), f),
            Node::DataPortConnector => set(DataPortConnector::default(), f),
            Node::ServicePortConnector => set(ServicePortConnector::default(), f),
            Node::OrderTarget => set(OrderTarget::default(), f),
            Node::WaitTime => set(WaitTime::default(), f),
            Node::Preceding => set(Preceding::default(), f),
            Node::ConfigurationSet | Node::Constraint | Node::TextList | Node::Order => {
                panic!("{f:?} on a node without fields")
            }
        }
    }

    /// Renaming a serde field without its line here fails this test: `diff` and the positions
    /// find fields by the table's JSON name.
    #[test]
    fn every_json_name_is_the_serde_name() {
        for &f in Field::ALL {
            let v = json_with(f);
            let set: Vec<&String> = v
                .as_object()
                .expect("an object")
                .iter()
                .filter(|(_, x)| x.as_str() == Some("set-by-test"))
                .map(|(k, _)| k)
                .collect();
            assert_eq!(set, [f.json()], "{f:?}");
        }
    }

    /// A profile with one of every node.
    fn full_profile() -> Profile {
        let constraint = || Constraint {
            kind: ConstraintKind::Empty,
            pos: Pos::default(),
            extra: crate::model::Extras::new(),
        };
        let property = || Property {
            name: Some("p".into()),
            ..Default::default()
        };
        Profile {
            basic_info: BasicInfo {
                doc: Some(BasicDoc::default()),
                version_up_logs: vec!["log".into()],
                properties: vec![property()],
                ..Default::default()
            },
            actions: vec![Action {
                kind: ActionKind::OnExecute,
                implemented: None,
                doc: Some(ActionDoc::default()),
                pos: Pos::default(),
                extra: crate::model::Extras::new(),
            }],
            configuration_set: Some(ConfigurationSet {
                configurations: vec![Configuration {
                    name: Some("c".into()),
                    doc: Some(ConfigurationDoc::default()),
                    constraint: Some(constraint()),
                    properties: vec![property()],
                    ..Default::default()
                }],
                ..Default::default()
            }),
            data_ports: vec![DataPort {
                name: Some("d".into()),
                doc: Some(DataPortDoc::default()),
                constraint: Some(constraint()),
                properties: vec![property()],
                events: vec![Event {
                    name: Some("e".into()),
                    doc: Some(DataPortDoc::default()),
                    ..Default::default()
                }],
                ..Default::default()
            }],
            service_ports: vec![ServicePort {
                name: Some("s".into()),
                doc: Some(ServicePortDoc::default()),
                properties: vec![property()],
                trans_methods: vec![TransMethod::default()],
                interfaces: vec![ServiceInterface {
                    name: Some("i".into()),
                    doc: Some(ServiceInterfaceDoc::default()),
                    properties: vec![property()],
                    ..Default::default()
                }],
                ..Default::default()
            }],
            parameters: vec![Parameter {
                name: Some("x".into()),
                ..Default::default()
            }],
            language: Some(Language {
                targets: vec![Target {
                    libraries: vec![Library {
                        name: Some("l".into()),
                        ..Default::default()
                    }],
                    ..Default::default()
                }],
                ..Default::default()
            }),
            ..Default::default()
        }
    }

    /// Every child of the table is under its JSON key in the serialised model, and the items
    /// of a keyed list carry their key.
    #[test]
    fn every_child_is_under_its_serde_name() {
        fn check(node: Node, v: &Value, seen: &mut Vec<(Node, &'static str)>) {
            for c in node.children() {
                let x = v
                    .get(c.json)
                    .unwrap_or_else(|| panic!("{node:?} has no `{}` in {v}", c.json));
                seen.push((node, c.json));
                match c.holds {
                    Holds::One => check(c.node, x, seen),
                    Holds::Keyed(key) => {
                        let item = &x.as_array().expect("a list")[0];
                        assert!(item.get(key).is_some(), "{node:?}.{} items: {key}", c.json);
                        check(c.node, item, seen);
                    }
                    Holds::Whole => {
                        assert!(!x.is_null(), "{node:?}.{}", c.json);
                        let first = x.as_array().and_then(|a| a.first());
                        if let Some(item) = first.filter(|i| i.is_object()) {
                            check(c.node, item, seen);
                        }
                    }
                }
            }
        }
        let v = serde_json::to_value(full_profile()).expect("json");
        let mut seen = Vec::new();
        check(Node::Profile, &v, &mut seen);
        for c in CHILDREN {
            assert!(
                seen.contains(&(c.parent, c.json)),
                "{:?}.{} not reached",
                c.parent,
                c.json
            );
        }
    }
}
