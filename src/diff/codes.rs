//! The change registry: every code `rtcdoc diff` reports, with its severity, short name and the
//! reasoning behind the classification (`rtcdoc diff --explain CODE` prints an entry; the guide
//! `book/src/diff.md` lists them all, held to this table by a test).
//!
//! Numbering: DIFF0xx are about the comparison itself, DIFF1xx breaking, DIFF2xx warnings,
//! DIFF3xx information. Codes are never reused. The IDL-level codes (struct members, enum
//! values, unions, typedefs, operations) are DIFF13x / DIFF23x / DIFF33x, the RT System
//! connectors a component change breaks DIFF14x, the changes of the RT System profiles
//! themselves (instances, connectors, configuration, execution contexts) DIFF15x / DIFF25x /
//! DIFF35x, and the changes of where a component's code and its profile disagree (its drift,
//! [`crate::implementation::drift`]) DIFF26x / DIFF36x.

use serde::Serialize;

/// How much a change matters to the systems and components connected to a component.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// Existing connections, configurations or peers stop working.
    Breaking,
    /// Probably fine, but a user of the component has to look.
    Warning,
    /// Nothing connected to the component is affected.
    Info,
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Level::Breaking => "breaking",
            Level::Warning => "warning",
            Level::Info => "info",
        })
    }
}

/// One change code and its documentation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Code {
    /// Stable code, e.g. `DIFF104`.
    pub code: &'static str,
    pub level: Level,
    /// Short kebab-case name (`data-port-type-changed`).
    pub name: &'static str,
    /// One-line summary.
    pub summary: &'static str,
    /// Why the change is classified the way it is.
    pub explanation: &'static str,
}

pub const AMBIGUOUS_COMPONENT: &str = "DIFF001";
pub const UNREADABLE_PROFILE: &str = "DIFF002";
pub const AMBIGUOUS_SYSTEM: &str = "DIFF003";
pub const COMPONENT_REMOVED: &str = "DIFF101";
pub const DATA_PORT_REMOVED: &str = "DIFF102";
pub const DATA_PORT_DIRECTION: &str = "DIFF103";
pub const DATA_PORT_TYPE: &str = "DIFF104";
pub const SERVICE_PORT_REMOVED: &str = "DIFF105";
pub const INTERFACE_REMOVED: &str = "DIFF106";
pub const INTERFACE_TYPE: &str = "DIFF107";
pub const INTERFACE_DIRECTION: &str = "DIFF108";
pub const CONFIGURATION_REMOVED: &str = "DIFF109";
pub const CONFIGURATION_TYPE: &str = "DIFF110";
pub const IDL_REPOSITORY_ID: &str = "DIFF130";
pub const IDL_MEMBER_ADDED: &str = "DIFF131";
pub const IDL_MEMBER_REMOVED: &str = "DIFF132";
pub const IDL_MEMBERS_REORDERED: &str = "DIFF133";
pub const IDL_MEMBER_RETYPED: &str = "DIFF134";
pub const IDL_ENUM_VALUE_REMOVED: &str = "DIFF135";
pub const IDL_UNION_CHANGED: &str = "DIFF136";
pub const IDL_TYPEDEF_CHANGED: &str = "DIFF137";
pub const IDL_OPERATION_REMOVED: &str = "DIFF138";
pub const IDL_OPERATION_CHANGED: &str = "DIFF139";
pub const IDL_TYPE_REMOVED: &str = "DIFF140";
pub const CONNECTOR_COMPONENT_REMOVED: &str = "DIFF141";
pub const CONNECTOR_PORT_REMOVED: &str = "DIFF142";
pub const CONNECTOR_PORT_CHANGED: &str = "DIFF143";
pub const SYSTEM_REMOVED: &str = "DIFF151";
pub const SYSTEM_INSTANCE_REMOVED: &str = "DIFF152";
pub const SYSTEM_INSTANCE_COMPONENT: &str = "DIFF153";
pub const SYSTEM_CONNECTOR_REMOVED: &str = "DIFF154";
pub const SYSTEM_CONNECTOR_ENDS: &str = "DIFF155";
pub const SYSTEM_CONNECTOR_DATA_TYPE: &str = "DIFF156";
pub const DEFAULT_CHANGED: &str = "DIFF201";
pub const CONSTRAINT_NARROWED: &str = "DIFF202";
pub const CONSTRAINT_CHANGED: &str = "DIFF203";
pub const EXECUTION_TYPE: &str = "DIFF204";
pub const EXECUTION_RATE: &str = "DIFF205";
pub const MAX_INSTANCES_LOWERED: &str = "DIFF206";
pub const ACTION_NOT_IMPLEMENTED: &str = "DIFF207";
pub const BREAKING_WITHOUT_BUMP: &str = "DIFF208";
pub const TRANSPORT_NARROWED: &str = "DIFF209";
pub const UNIT_CHANGED: &str = "DIFF210";
pub const REQUIRED_INTERFACE_ADDED: &str = "DIFF211";
pub const IDL_ENUM_VALUE_APPENDED: &str = "DIFF231";
pub const IDL_OPERATION_ADDED: &str = "DIFF232";
pub const SYSTEM_INSTANCE_VERSION: &str = "DIFF251";
pub const SYSTEM_ACTIVE_CONFIGURATION: &str = "DIFF252";
pub const SYSTEM_EXECUTION_RATE: &str = "DIFF253";
pub const SYSTEM_EXECUTION_CONTEXT: &str = "DIFF254";
pub const SYSTEM_CONNECTOR_TRANSPORT: &str = "DIFF255";
pub const SYSTEM_CONNECTOR_POLICY: &str = "DIFF256";
pub const SYSTEM_RENAMED: &str = "DIFF257";
pub const DRIFT_INTRODUCED: &str = "DIFF261";
pub const PORT_ADDED: &str = "DIFF301";
pub const INTERFACE_ADDED: &str = "DIFF302";
pub const CONFIGURATION_ADDED: &str = "DIFF303";
pub const COMPONENT_ADDED: &str = "DIFF304";
pub const CONSTRAINT_WIDENED: &str = "DIFF305";
pub const VERSION_CHANGED: &str = "DIFF306";
pub const DOCUMENTATION_CHANGED: &str = "DIFF307";
pub const OTHER_CHANGED: &str = "DIFF308";
pub const IDL_DOCUMENTATION_CHANGED: &str = "DIFF331";
pub const IDL_TYPE_ON_ONE_SIDE: &str = "DIFF332";
pub const IDL_REQUIRED_OPERATION_REMOVED: &str = "DIFF333";
pub const IDL_TYPE_ADDED: &str = "DIFF334";
pub const OPENRTM_IDL_COPY: &str = "DIFF335";
pub const SYSTEM_ADDED: &str = "DIFF351";
pub const SYSTEM_INSTANCE_ADDED: &str = "DIFF352";
pub const SYSTEM_CONNECTOR_ADDED: &str = "DIFF353";
pub const SYSTEM_CONFIGURATION: &str = "DIFF354";
pub const SYSTEM_OTHER: &str = "DIFF355";
pub const SYSTEM_CONNECTOR_TYPE_REPAIRED: &str = "DIFF356";
pub const DRIFT_RESOLVED: &str = "DIFF361";
pub const IMPLEMENTATION_ADDED: &str = "DIFF362";
pub const IMPLEMENTATION_REMOVED: &str = "DIFF363";

use Level::{Breaking, Info, Warning};

/// Every code, in order.
pub static CODES: &[Code] = &[
    Code {
        code: AMBIGUOUS_COMPONENT,
        level: Warning,
        name: "ambiguous-component",
        summary: "several profiles on a side share one component id and cannot be paired",
        explanation: "Components are matched by vendor, category and name (spec 2.3.1.1: the id names a component uniquely). When one side holds several profiles with that id (rtcdoc check reports them as RTC010), they are paired by implementation language, then by identical file path. Profiles still left on both sides cannot be told apart, so they are not compared at all: this warning names their files instead of guessing a pairing that would report invented changes.",
    },
    Code {
        code: UNREADABLE_PROFILE,
        level: Warning,
        name: "unreadable-profile",
        summary: "a profile file of one side could not be read",
        explanation: "A file that is not well-formed (or too large, or unreadable) contributes no component, so its component may show up as removed or added. The warning says so, so that a broken file is not mistaken for a deliberate removal; `rtcdoc check` gives the details.",
    },
    Code {
        code: AMBIGUOUS_SYSTEM,
        level: Warning,
        name: "ambiguous-system",
        summary: "several RT System profiles on a side share one system id and cannot be paired",
        explanation: "Systems are matched by the vendor and name of their id (`RTSystem:vendor:name:version`, the version left out), else by file. RTSystemEditor saves every new system as `DefaultSystem` unless renamed, so unrelated systems often share an id; those are paired by identical file path, then by identical values (copies), and when one is left on each side, those two. Systems still left on both sides cannot be told apart, so they are not compared: this warning names their files instead of guessing a pairing that would report invented changes. Give each system its own id (RTSystemEditor: Save As, or the `id` of the profile).",
    },
    Code {
        code: COMPONENT_REMOVED,
        level: Breaking,
        name: "component-removed",
        summary: "a component of OLD is not in NEW",
        explanation: "RT System profiles, launch scripts and other components name the component by its id; none of them can find it any more (spec 10.6: a replacement must keep what it replaces). A file that only moved is no change: components are matched by id, not by path. In a component's history, whose versions are paired by their file, a version whose id names another component (its vendor, category or name changed) is reported with this code too.",
    },
    Code {
        code: DATA_PORT_REMOVED,
        level: Breaking,
        name: "data-port-removed",
        summary: "a data port was removed",
        explanation: "Connectors of RT System profiles name ports by `<instance>.<port>`; a connector to a port that no longer exists fails to connect, and the peer loses its data.",
    },
    Code {
        code: DATA_PORT_DIRECTION,
        level: Breaking,
        name: "data-port-direction-changed",
        summary: "a data port changed its kind (DataInPort, DataOutPort, EventPort)",
        explanation: "A connector joins an out-port to an in-port; flipping the direction turns every existing connection into an out-out or in-in pair, which OpenRTM refuses. Only the meaning of portType counts: `DataInPort` written `datainport` is no change.",
    },
    Code {
        code: DATA_PORT_TYPE,
        level: Breaking,
        name: "data-port-type-changed",
        summary: "a data port carries another data type",
        explanation: "Connectors require equal data types on both ends, and data are marshalled with CDR, which is positional: a peer built for the old type cannot read the new one. Spellings of one type (`RTC::TimedLong`, `TimedLong`, `IDL:RTC/TimedLong:1.0`) are compared in canonical form and are no change (reported as other-changed when only the spelling differs).",
    },
    Code {
        code: SERVICE_PORT_REMOVED,
        level: Breaking,
        name: "service-port-removed",
        summary: "a service port was removed",
        explanation: "Service-port connectors name the port; its provided interfaces disappear for every requirer, and its required interfaces are no longer served to the component.",
    },
    Code {
        code: INTERFACE_REMOVED,
        level: Breaking,
        name: "interface-removed",
        summary: "a service interface was removed from a service port that remains",
        explanation: "A removed provided interface leaves the components that require it without a provider; a removed required interface changes what the port connects to. Interfaces are matched by port and interface name.",
    },
    Code {
        code: INTERFACE_TYPE,
        level: Breaking,
        name: "interface-type-changed",
        summary: "a service interface has another IDL interface type",
        explanation: "Requirers and providers are connected by interface type; a consumer narrows the object reference to the type it was built for, which fails for another interface. Spellings of one type are compared in canonical form.",
    },
    Code {
        code: INTERFACE_DIRECTION,
        level: Breaking,
        name: "interface-direction-changed",
        summary: "a service interface switched between Provided and Required",
        explanation: "A provided interface is served to peers, a required one consumed from them: a switch turns every existing provider/requirer pair into two providers or two requirers.",
    },
    Code {
        code: CONFIGURATION_REMOVED,
        level: Breaking,
        name: "configuration-removed",
        summary: "a configuration parameter was removed",
        explanation: "Configuration sets saved in RT System profiles and rtc.conf files set parameters by name; a removed parameter is silently ignored, so the behaviour it tuned is lost.",
    },
    Code {
        code: CONFIGURATION_TYPE,
        level: Breaking,
        name: "configuration-type-changed",
        summary: "a configuration parameter has another value type",
        explanation: "Saved values of the old type may not parse for the new one (`1.5` for an `int`), and the component then keeps its default. Spellings of one type (`int` and `long`, `std::string` and `string`, `vector<double>` and `std::vector<double>`) are compared by the type they mean.",
    },
    Code {
        code: IDL_REPOSITORY_ID,
        level: Breaking,
        name: "idl-repository-id-changed",
        summary: "the repository id of a port's data type or of an interface changed",
        explanation: "OpenRTM connects two data ports only when their `dataport.data_type` — the repository id, `IDL:RTC/TimedLong:1.0` — is equal, and a consumer narrows an object reference to the repository id it was built for. A new `#pragma prefix`, `#pragma version` or `#pragma ID` (or `typeid`/`typeprefix`) makes peers built from the old IDL refuse the connection even when the members are the same. Only the type a port or interface names counts: nested types travel inside it without their id.",
    },
    Code {
        code: IDL_MEMBER_ADDED,
        level: Breaking,
        name: "idl-member-added",
        summary: "a struct (or exception) carried by a port gained a member",
        explanation: "Data travel as CDR, which is positional and carries no member names or count: a peer built from the old IDL reads the new layout wrongly or fails on the extra bytes. Unlike protobuf there are no optional fields, so even a member appended at the end breaks every existing peer. The path names the member through the nested structs (`dataPorts/odometry/type/fields/pose.heading`), and `[]` marks the element of a sequence or array.",
    },
    Code {
        code: IDL_MEMBER_REMOVED,
        level: Breaking,
        name: "idl-member-removed",
        summary: "a struct (or exception) carried by a port lost a member",
        explanation: "CDR is positional: without the member every later one is read from the wrong offset by a peer built from the old IDL, and code using the member no longer compiles. A renamed member is reported as removed and added (source code names it).",
    },
    Code {
        code: IDL_MEMBERS_REORDERED,
        level: Breaking,
        name: "idl-members-reordered",
        summary: "the members of a struct (or exception) carried by a port changed their order",
        explanation: "CDR writes members in declaration order, so a peer built from the old IDL assigns the values to the wrong members (two `double`s swapped still 'work', silently wrong). Reported once per struct, with both orders.",
    },
    Code {
        code: IDL_MEMBER_RETYPED,
        level: Breaking,
        name: "idl-member-retyped",
        summary: "a member of a struct (or exception) carried by a port has another type or array size",
        explanation: "The member takes another number of bytes or another encoding on the wire (`float` to `double`, `long` to `long long`, a bound or array size changed, another struct). Types are compared after following typedefs, so `typedef double Real; Real x` → `double x` is the same type (reported as DIFF308).",
    },
    Code {
        code: IDL_ENUM_VALUE_REMOVED,
        level: Breaking,
        name: "idl-enum-value-removed",
        summary: "an enum value was removed, moved or had a value inserted before it",
        explanation: "CDR sends an enum as the ordinal of its value: a removed value is an ordinal peers still send, and a moved or inserted value renumbers the ones after it, so old and new peers mean different values by the same number. Only values appended at the end keep every number (DIFF231).",
    },
    Code {
        code: IDL_UNION_CHANGED,
        level: Breaking,
        name: "idl-union-changed",
        summary: "a union carried by a port changed its discriminator, a case label or a case member",
        explanation: "A union is sent as the discriminator and then the member its label selects: another discriminator type, a label that selects another member, a case added or removed, or a case member of another type, makes old and new peers decode different members. The order of the cases does not matter.",
    },
    Code {
        code: IDL_TYPEDEF_CHANGED,
        level: Breaking,
        name: "idl-typedef-changed",
        summary: "a typedef carried by a port names another type, or a type changed its kind",
        explanation: "`typedef sequence<double, 3> Vector3` that becomes `sequence<double, 4>`, or a typedef that becomes a struct, changes what is on the wire under the same name. Typedefs to the same type (after following typedefs) are no change.",
    },
    Code {
        code: IDL_OPERATION_REMOVED,
        level: Breaking,
        name: "idl-operation-removed",
        summary: "an operation or attribute was removed from a provided interface",
        explanation: "Components requiring the interface call the operation (an attribute is its `_get_`/`_set_` operations) and get `BAD_OPERATION` from the new provider. Operations inherited from base interfaces count as the interface's own. For a required interface the component merely stops calling it (DIFF333).",
    },
    Code {
        code: IDL_OPERATION_CHANGED,
        level: Breaking,
        name: "idl-operation-changed",
        summary: "an operation's signature (parameters, directions, result, raises, oneway) or an attribute's type changed",
        explanation: "GIOP marshals the parameters of a call positionally by the caller's IDL: another parameter type, count or direction (`in`, `out`, `inout`), result type, `oneway` or exception list, or an attribute's type or `readonly`, makes calls between peers built from the old and the new IDL fail or carry wrong values — for the requirers of a provided interface, and for the component itself calling a required one. Parameter names alone are no change on the wire (DIFF308); struct parameters that changed inside are reported with the struct codes.",
    },
    Code {
        code: IDL_TYPE_REMOVED,
        level: Breaking,
        name: "idl-type-removed",
        summary: "a type the IDL files defined is no longer defined",
        explanation: "A struct, union, enum, typedef, interface, exception or constant one side's IDL files define is defined by none of the other's (by scoped name: a type moved to another module counts as removed and added). Ports, peers and generated code naming it no longer build, and a data port carrying it cannot be connected to an old peer. `rtcdoc diff` reports it when both sides have IDL and no port carries the type (a type a port carries is DIFF332), also when the sides hold IDL alone; the history of an IDL file reports it for every type the file stopped defining.",
    },
    Code {
        code: CONNECTOR_COMPONENT_REMOVED,
        level: Breaking,
        name: "connector-component-removed",
        summary: "a connector of an RT System profile connects a component that was removed",
        explanation: "An RT System profile (RTSystemEditor, rtshell) restores its connectors by component id and port name; the component is no longer in NEW, so the connector cannot be made. The change names the system (its id and file) and the connector (its name or id, source → target). Systems are read from both sides (NEW's, and OLD's that NEW does not have by id).",
    },
    Code {
        code: CONNECTOR_PORT_REMOVED,
        level: Breaking,
        name: "connector-port-removed",
        summary: "a connector of an RT System profile connects a port that was removed",
        explanation: "The system names the port as `<instance>.<port>`; a removed data or service port makes the connector fail when the system is restored (`rtresurrect`, RTSystemEditor's Restore), and the peer loses its data or service.",
    },
    Code {
        code: CONNECTOR_PORT_CHANGED,
        level: Breaking,
        name: "connector-port-changed",
        summary: "a connector of an RT System profile connects a port whose type or direction changed incompatibly",
        explanation: "The connector still finds the port, but its data type, kind, interfaces or their IDL changed in a breaking way (DIFF103, DIFF104, DIFF106–DIFF108, DIFF13x on the port): OpenRTM refuses the connection (another `data_type`, two out-ports) or the peers exchange data they decode differently. The message lists the changes of the port.",
    },
    Code {
        code: SYSTEM_REMOVED,
        level: Breaking,
        name: "system-removed",
        summary: "an RT System profile of OLD is not in NEW",
        explanation: "Whoever deploys the system (RTSystemEditor's Open and Restore, `rtresurrect`, `rtstart`, a launch script naming the file) can no longer restore its connections, configuration and start order. Systems are matched by id (vendor and name), else by file: a file that only moved is no change.",
    },
    Code {
        code: SYSTEM_INSTANCE_REMOVED,
        level: Breaking,
        name: "system-instance-removed",
        summary: "a component instance was removed from an RT System",
        explanation: "The system no longer starts, connects or configures the instance: the instances whose in-ports it fed stop receiving data, those whose required interfaces it provided lose their provider, and start-up orders that named it skip it. Instances are matched by instance name. (Its connectors, when NEW dropped them too, are reported as DIFF154.)",
    },
    Code {
        code: SYSTEM_INSTANCE_COMPONENT,
        level: Breaking,
        name: "system-instance-component-changed",
        summary: "an instance of an RT System now names another component",
        explanation: "The instance keeps its name, but its `id` names another component (another vendor, category or name): the connectors and configuration sets saved for the instance were made for the old component's ports and parameters, so restoring the system connects ports that may not exist or carry other data, and sets parameters the new component does not declare. Another version of the same component is DIFF251; the id written in the other form (dotted or colon) is DIFF355.",
    },
    Code {
        code: SYSTEM_CONNECTOR_REMOVED,
        level: Breaking,
        name: "system-connector-removed",
        summary: "a data or service port connector was removed from an RT System",
        explanation: "For a data connector, the consumer (the target in-port) stops receiving the data the producer sends; for a service connector, the port requiring an interface loses its provider and its calls fail. Connectors are matched by connector id, else by their two ends (instance and port, with or without the `<instance>.` prefix), so a connector that was deleted and drawn again between the same ports is no removal.",
    },
    Code {
        code: SYSTEM_CONNECTOR_ENDS,
        level: Breaking,
        name: "system-connector-ends-changed",
        summary: "a connector of an RT System now joins other ports",
        explanation: "The connector (matched by its id) now starts or ends at another instance or port: the port it left stops receiving (or providing), and the port it reaches gets data or calls it did not get before. The message names both ends before and after, and the ports no longer connected. The same two ports listed the other way round (source and target swapped) are no change: OpenRTM connects two ports whichever comes first, and a data connector's direction comes from the ports' types.",
    },
    Code {
        code: SYSTEM_CONNECTOR_DATA_TYPE,
        level: Breaking,
        name: "system-connector-data-type-changed",
        summary: "a data connector of an RT System carries another data type",
        explanation: "OpenRTM connects two data ports only when the connector's `dataport.data_type` equals the types of both ports: a connector saved with another type is refused when the system is restored, or joins peers built for different types (CDR is positional, so they decode each other's data wrongly). Spellings of one type (`RTC::TimedLong`, `IDL:RTC/TimedLong:1.0`) are compared in canonical form and are DIFF355 when only the spelling changed. The `dataport.data_type` property is folded into the attribute when both changed. A change to the type both ports carry as the file records them, from one they did not carry, is a repair (DIFF356).",
    },
    Code {
        code: DEFAULT_CHANGED,
        level: Warning,
        name: "configuration-default-changed",
        summary: "a configuration parameter has another default value",
        explanation: "Systems that never set the parameter behave differently after the update; nothing fails to connect, so it is a warning, not breaking.",
    },
    Code {
        code: CONSTRAINT_NARROWED,
        level: Warning,
        name: "constraint-narrowed",
        summary: "a configuration constraint accepts fewer values than before",
        explanation: "Saved configuration values that the old constraint accepted may be refused now. The message says whether the old default still satisfies the new constraint. Narrowing is decided on a sound approximation: a constraint added where there was none; numeric comparisons and `between` as unions of intervals (new ⊂ old); `=` alternatives as sets of literals; hash and list constraints item by item (a new key or item narrows, a dropped one widens). Anything else that changed is DIFF203.",
    },
    Code {
        code: CONSTRAINT_CHANGED,
        level: Warning,
        name: "constraint-changed",
        summary: "a configuration constraint changed in a way that is neither clearly narrower nor wider",
        explanation: "Two constraints rtcdoc cannot order (a `like` pattern, `not`, a mix of shapes, intervals that overlap without containment) may refuse values the old one accepted, so the change is treated like a narrowing. The message says whether the old default satisfies the new constraint.",
    },
    Code {
        code: EXECUTION_TYPE,
        level: Warning,
        name: "execution-type-changed",
        summary: "the execution context type changed",
        explanation: "A periodic component that becomes event-driven (or the reverse) is scheduled differently: systems that relied on its timing, or attached it to an execution context of the old type, behave differently.",
    },
    Code {
        code: EXECUTION_RATE,
        level: Warning,
        name: "execution-rate-changed",
        summary: "the execution rate changed",
        explanation: "Peers that depend on the output frequency (controllers, filters) see data at another rate. Rates are compared as numbers: `50` and `50.0` are equal.",
    },
    Code {
        code: MAX_INSTANCES_LOWERED,
        level: Warning,
        name: "max-instances-lowered",
        summary: "fewer instances of the component may run",
        explanation: "A system that starts more instances than the new maximum fails to create the extra ones. An absent or empty maxInstances counts as unlimited; a value that is not a number is treated as lowered (it cannot be compared).",
    },
    Code {
        code: ACTION_NOT_IMPLEMENTED,
        level: Warning,
        name: "action-no-longer-implemented",
        summary: "a lifecycle action is no longer implemented",
        explanation: "The behaviour the callback had (on_activated opening a device, on_reset clearing a fault) is gone; connections still work, so it is a warning.",
    },
    Code {
        code: BREAKING_WITHOUT_BUMP,
        level: Warning,
        name: "breaking-without-version-bump",
        summary: "a component has breaking changes but kept its version",
        explanation: "The version in the id (`RTC:vendor:category:name:version`) and in BasicInfo is what repositories and users compare; a breaking change under the same version makes two incompatible components indistinguishable.",
    },
    Code {
        code: TRANSPORT_NARROWED,
        level: Warning,
        name: "transport-narrowed",
        summary: "a data port supports fewer interface, dataflow or subscription types",
        explanation: "interfaceType, dataflowType and subscriptionType list what a data port offers (`corba_cdr`, `push,pull`, `flush,new,periodic`); a connector asking for a value that was dropped no longer connects. They are compared as comma-separated sets (any case); an empty value means unrestricted. Not breaking: the connector profiles of most systems use the defaults.",
    },
    Code {
        code: UNIT_CHANGED,
        level: Warning,
        name: "unit-changed",
        summary: "the unit of a configuration parameter or data port changed",
        explanation: "The same number now means something else (`m` to `mm`): saved values and peers that computed with the old unit are off by a factor.",
    },
    Code {
        code: REQUIRED_INTERFACE_ADDED,
        level: Warning,
        name: "required-interface-added",
        summary: "a service port requires a new interface",
        explanation: "The component now depends on a provider that existing systems do not connect to it.",
    },
    Code {
        code: IDL_ENUM_VALUE_APPENDED,
        level: Warning,
        name: "idl-enum-value-appended",
        summary: "an enum carried by a port gained a value at its end",
        explanation: "Every old value keeps its number, so old peers still read what they knew; but a peer built from the old IDL receives a number it has no value for when the new one is sent, and its behaviour for it is undefined. Not breaking, but the consumers have to look.",
    },
    Code {
        code: IDL_OPERATION_ADDED,
        level: Warning,
        name: "idl-operation-added",
        summary: "an operation or attribute was added to a service interface",
        explanation: "Added to a provided interface, old requirers are unaffected, but two providers under one repository id now differ, and requirers built from the new IDL get `BAD_OPERATION` from old providers. Added to a required interface, the component may call an operation that existing providers do not implement.",
    },
    Code {
        code: SYSTEM_INSTANCE_VERSION,
        level: Warning,
        name: "system-instance-version-changed",
        summary: "an instance of an RT System names another version of its component",
        explanation: "The instance still names the same component (vendor, category and name), but another version: the system was saved against the new version, so hosts still running the old one restore it with the ports and parameters of the old version (`rtcdoc check` reports the mismatch with the catalogue as RTC604). Not breaking by itself; the component's own diff says what the versions differ in.",
    },
    Code {
        code: SYSTEM_ACTIVE_CONFIGURATION,
        level: Warning,
        name: "system-active-configuration-changed",
        summary: "an instance of an RT System activates another configuration set",
        explanation: "The instance now runs with the values of another set (`activeConfigurationSet`): everything it tunes (gains, limits, device names) may take other values, so its peers see other behaviour, though every connection still works.",
    },
    Code {
        code: SYSTEM_EXECUTION_RATE,
        level: Warning,
        name: "system-execution-rate-changed",
        summary: "an execution context of an RT System instance runs at another rate",
        explanation: "The instance executes at another frequency: its consumers see data at another rate, and controllers and filters tuned to the old period behave differently. Rates are compared as numbers (`1000` and `1000.0` are equal).",
    },
    Code {
        code: SYSTEM_EXECUTION_CONTEXT,
        level: Warning,
        name: "system-execution-context-changed",
        summary: "an execution context of an RT System instance changed its kind, or was added or removed",
        explanation: "A periodic context that becomes event-driven (or the reverse), or a context added or removed, changes when and how often the instance runs, and which instances share a thread. Kinds are compared by meaning: `PERIODIC`, `Periodic` and `PeriodicExecutionContext` are the same. Execution contexts are matched by id.",
    },
    Code {
        code: SYSTEM_CONNECTOR_TRANSPORT,
        level: Warning,
        name: "system-connector-transport-changed",
        summary: "a data connector of an RT System uses another interface type or dataflow type",
        explanation: "The connector asks for another transport (`corba_cdr`, `shared_memory`, `direct`, …) or dataflow (`push`, `pull`): it connects only when both ports offer it, and a consumer that pulled now receives pushes (or must pull). Compared in any case; the `dataport.interface_type` and `dataport.dataflow_type` properties are folded into the attributes when both changed.",
    },
    Code {
        code: SYSTEM_CONNECTOR_POLICY,
        level: Warning,
        name: "system-connector-policy-changed",
        summary: "a data connector of an RT System delivers data under another policy",
        explanation: "The subscription type (`flush`, `new`, `periodic`), push interval, push policy (`all`, `fifo`, `skip`, `new`), skip count or buffer settings of the connector changed: every connection still works, but the consumer may receive fewer, later or other samples (a `new` subscription drops samples the consumer is too slow for). The connector's `dataport.subscription_type`, `dataport.publisher.*`, `dataport.push_rate` and `dataport.*buffer*` properties count too.",
    },
    Code {
        code: SYSTEM_RENAMED,
        level: Warning,
        name: "system-renamed",
        summary: "an RT System profile names its system differently (another vendor or name in its id)",
        explanation: "A system is matched by the vendor and name of its id. When no system of the other side has the id, a system of the same file (or the one system of each side) is taken as the same system renamed: its instances, connectors and configuration are then compared as usual. The file still restores the system; what names the system by its id (scripts, a name service context, documentation) must follow.",
    },
    Code {
        code: DRIFT_INTRODUCED,
        level: Warning,
        name: "drift-introduced",
        summary: "the code and the profile of a component disagree in NEW where they did not in OLD",
        explanation: "A component's implementation (the C++, Python or Java code beside its profile) is compared with the profile on both sides, as `rtcdoc check` compares them (RTC801-RTC809: a port or parameter on one side only, another type, direction or default, a callback marked otherwise, a spec array value). A finding of NEW that OLD does not have is reported here, so that a pull request that edits only the code, or only the profile, and leaves the two disagreeing is caught: the documentation, and the systems built from the profile, no longer describe what the component does. A finding is identified by its component, its RTC80x kind and the element (`dataPorts/in`, `configurationSet/gain/defaultValue`), not by its line, so an edit that only moves code reports nothing; a finding that persists with other values is the same finding. The message says what the profile says and what the code says, and where in NEW's code. Not breaking by itself, since nothing connected to the component changed; make the profile and the code agree again (`rtcdoc check` gives a hint for each kind). The code of a component that OLD has none of (added, or newly readable) is compared too: its findings are reported here, beside DIFF362.",
    },
    Code {
        code: PORT_ADDED,
        level: Info,
        name: "port-added",
        summary: "a data port or service port was added",
        explanation: "Existing connections are untouched; the new port is simply unconnected.",
    },
    Code {
        code: INTERFACE_ADDED,
        level: Info,
        name: "interface-added",
        summary: "a provided service interface was added to an existing service port",
        explanation: "Peers that do not know the interface ignore it.",
    },
    Code {
        code: CONFIGURATION_ADDED,
        level: Info,
        name: "configuration-added",
        summary: "a configuration parameter was added",
        explanation: "Systems that do not set it get its default.",
    },
    Code {
        code: COMPONENT_ADDED,
        level: Info,
        name: "component-added",
        summary: "a component of NEW is not in OLD",
        explanation: "Nothing used it before, so nothing can break.",
    },
    Code {
        code: CONSTRAINT_WIDENED,
        level: Info,
        name: "constraint-widened",
        summary: "a configuration constraint accepts more values than before (or was removed)",
        explanation: "Every value that was valid stays valid. Decided with the same approximation as DIFF202.",
    },
    Code {
        code: VERSION_CHANGED,
        level: Info,
        name: "version-changed",
        summary: "the component version changed",
        explanation: "A version bump alone changes nothing a peer depends on.",
    },
    Code {
        code: DOCUMENTATION_CHANGED,
        level: Info,
        name: "documentation-changed",
        summary: "a description, doc field or comment changed",
        explanation: "Documentation (the rtcDoc fields, descriptions, comments, abstract, hardware profile, version-up logs) does not affect behaviour. A doc field left blank (`\"\"`, as RTCBuilder writes what it leaves empty) and one left out are the same: no change.",
    },
    Code {
        code: OTHER_CHANGED,
        level: Info,
        name: "other-changed",
        summary: "any other value of the profile changed",
        explanation: "Every value of a profile is compared, so that no change goes unreported; values without a classification of their own (positions on the component box, variable names, properties, values rtcdoc does not know, a type spelled differently) are reported here. So is an id that RTCBuilder's placeholders (vendor `VenderName`, category `Category`, name `ModuleName`) gave the component before its wizard was filled in, when a history compares it with the named one: the component named for the first time, not one removed. The save stamps `creationDate` and `updateDate` (RTCBuilder rewrites `updateDate` at every save) are not compared.",
    },
    Code {
        code: IDL_DOCUMENTATION_CHANGED,
        level: Info,
        name: "idl-documentation-changed",
        summary: "the doc comment of an IDL type, member, value, operation or parameter changed",
        explanation: "Doc comments (`/** … */`, `///`, `///<`) are not part of the wire format or the generated code's interface.",
    },
    Code {
        code: IDL_TYPE_ON_ONE_SIDE,
        level: Info,
        name: "idl-type-on-one-side",
        summary: "a data or interface type used on both sides is defined in one side's IDL only",
        explanation: "Without both definitions the type cannot be compared, so a change inside it would go unseen: add the IDL file to the side that lacks it (below the input, or with `--idl-path`, which applies to both sides). Reported once per type, naming the components whose ports carry it, not once per port.",
    },
    Code {
        code: IDL_REQUIRED_OPERATION_REMOVED,
        level: Info,
        name: "idl-required-operation-removed",
        summary: "an operation or attribute was removed from an interface the component requires",
        explanation: "The component calls less than before; the providers it connects to still implement the operation, so nothing fails. (Removed from a provided interface it is DIFF138.)",
    },
    Code {
        code: IDL_TYPE_ADDED,
        level: Info,
        name: "idl-type-added",
        summary: "the IDL files define a new type",
        explanation: "A struct, union, enum, typedef, interface, exception or constant is defined on the new side only (by scoped name). Nothing that worked before depends on it. `rtcdoc diff` reports it when both sides have IDL and no port carries the type (a type a port carries is DIFF332), also when the sides hold IDL alone; the history of an IDL file reports it for every type the file begins to define.",
    },
    Code {
        code: OPENRTM_IDL_COPY,
        level: Info,
        name: "openrtm-idl-copy",
        summary: "a copy of one of OpenRTM's own IDL files is read on one side only",
        explanation: "Projects often keep a copy of OpenRTM's IDL (`BasicDataType.idl`, `ExtendedDataTypes.idl`, `InterfaceDataTypes.idl`, …) beside their own. When one side has such a copy and the other does not, the types only it defines are not gone from the components' world: an OpenRTM installation defines them. Reported once per file, naming its types, instead of each type as removed (DIFF140) or added (DIFF334). To compare the types themselves, give both sides OpenRTM's IDL with `--idl-path`.",
    },
    Code {
        code: SYSTEM_ADDED,
        level: Info,
        name: "system-added",
        summary: "an RT System profile of NEW is not in OLD",
        explanation: "Nothing deployed it before, so nothing can break.",
    },
    Code {
        code: SYSTEM_INSTANCE_ADDED,
        level: Info,
        name: "system-instance-added",
        summary: "a component instance was added to an RT System",
        explanation: "The existing instances and their connections are untouched; the new instance is started and connected as the system says (its connectors are DIFF353).",
    },
    Code {
        code: SYSTEM_CONNECTOR_ADDED,
        level: Info,
        name: "system-connector-added",
        summary: "a data or service port connector was added to an RT System",
        explanation: "Existing connections are untouched; a port may now receive data or a provider it did not have, which is what the author intended.",
    },
    Code {
        code: SYSTEM_CONFIGURATION,
        level: Info,
        name: "system-configuration-changed",
        summary: "a configuration value of an RT System instance changed, or a value or set was added or removed",
        explanation: "Configuration values tune an instance without changing what it connects to; the message says whether the value is in the active set (the one the instance runs with). Which set is active is DIFF252. RTSystemEditor's own sets (`__widget__`, `__constraints__`) are DIFF355.",
    },
    Code {
        code: SYSTEM_OTHER,
        level: Info,
        name: "system-other-changed",
        summary: "any other value of an RT System profile changed",
        explanation: "Every value of a system profile is compared, so that no change goes unreported; values without a classification of their own (the system's version, comments, the boxes' positions in RTSystemEditor, start-up orders, groups, properties, values rtcdoc does not know, a type spelled differently) are reported here. Host data (IORs, host names, CORBA endpoints, naming paths such as `pc1:2809/Cam0.rtc` or `pc1/Cam0.rtc`, which change with every save and are not published) is not compared, nor are the save stamps `creationDate` and `updateDate`, which RTSystemEditor rewrites at every save.",
    },
    Code {
        code: SYSTEM_CONNECTOR_TYPE_REPAIRED,
        level: Info,
        name: "system-connector-data-type-repaired",
        summary: "a data connector of an RT System now carries the type its ports carry",
        explanation: "The connector's data type changed to the type that both its ports carry, as the system file records them (RTSystemEditor's `dataport.data_type` on each instance's port), where before it carried a type they did not: the connection that was refused when the system was restored now succeeds. Any other change of a connector's type is DIFF156; when the file records no type for a port, a change cannot be told to be a repair and is DIFF156 too.",
    },
    Code {
        code: DRIFT_RESOLVED,
        level: Info,
        name: "drift-resolved",
        summary: "the code and the profile of a component no longer disagree where they did in OLD",
        explanation: "A finding of OLD's implementation check (RTC801-RTC809, identified by its component, kind and element, as for DIFF261) that NEW does not have: the code or the profile was changed so that the two agree. When NEW's code registers ports or parameters of that kind through a name or macro rtcdoc cannot read (RTC810), or none at all, a finding that the profile or the code has such an element the other lacks is no longer made, so its disappearance is no proof of agreement: the message says so (`no longer found, but not verified either`). The component's code removed altogether is DIFF363, not a resolution.",
    },
    Code {
        code: IMPLEMENTATION_ADDED,
        level: Info,
        name: "implementation-added",
        summary: "NEW reads code for a component whose code OLD does not have",
        explanation: "Source files of the component are found beside its profile in NEW and not in OLD (the code was added, or could not be read before: too large, unreadable, excluded). Having code is no drift and affects nothing connected to the component; where the new code disagrees with the profile, each finding is reported as DIFF261. The message names the language and the files read.",
    },
    Code {
        code: IMPLEMENTATION_REMOVED,
        level: Info,
        name: "implementation-removed",
        summary: "OLD reads code for a component whose code NEW does not have",
        explanation: "The source files found beside the profile in OLD are gone in NEW (removed, moved away from RTCBuilder's layout, excluded, or no longer readable). The disagreements OLD's code had with the profile are not resolved, only no longer compared: they are counted in the message instead of reported one by one as DIFF361. If the code moved, name its files in rtcdoc.toml ([[implementation.component]] with its name and files).",
    },
];

/// The registry entry of `code` or of its name (`data-port-type-changed`), in any case.
pub fn code(code: &str) -> Option<&'static Code> {
    crate::diagnostic::registry_entry(CODES, code, |c| (c.code, c.name))
}

/// `--explain` text for a code.
pub fn explain(c: &Code) -> String {
    let severity = format!("Severity: {}", c.level);
    crate::diagnostic::explanation(c.code, c.name, c.summary, &[&severity, c.explanation])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_unique_and_numbered_by_severity() {
        let mut seen = std::collections::HashSet::new();
        for c in CODES {
            assert!(seen.insert(c.code), "duplicate {}", c.code);
            assert!(
                c.code.len() == 7 && c.code.starts_with("DIFF"),
                "{}",
                c.code
            );
            let expected = match &c.code[4..5] {
                "1" => Some(Level::Breaking),
                "2" => Some(Level::Warning),
                "3" => Some(Level::Info),
                _ => None,
            };
            if let Some(l) = expected {
                assert_eq!(c.level, l, "{}", c.code);
            }
        }
        assert_eq!(
            code("diff104").map(|c| c.name),
            Some("data-port-type-changed")
        );
    }
}
