//! Pass 3 of the XML reader: the element tree → [`Profile`]. Whatever the specification does not
//! define for a node is kept in that node's `extra` list and reported as a warning.

use super::*;
use crate::model::fields::Fields;
use crate::parse::Documented;
// ---------------------------------------------------------------------------------------------
// Pass 3: tree → model
// ---------------------------------------------------------------------------------------------

pub(super) struct Mapper<'f> {
    pub(super) file: &'f str,
    pub(super) diags: Vec<Diagnostic>,
    /// Empty unknown attributes (wasanbon writes many): summarised in one note.
    pub(super) empties: crate::parse::dialect::EmptyUnknowns,
    /// Values read under an older spelling, for [`Profile::written_as`].
    pub(super) written_as: Vec<WrittenAs>,
}

impl Mapper<'_> {
    pub(super) fn warn(&mut self, pos: Pos, msg: String) {
        self.diags
            .push(Diagnostic::warning(codes::UNKNOWN, self.file, msg).at(pos));
    }

    /// An attribute the spec does not define on `on`. An empty one (`rtcDoc:license=""` on a
    /// configuration doc, as wasanbon writes them by the dozen) says nothing: it is kept, and
    /// counted for the profile's one summary note instead of a warning of its own.
    pub(super) fn unknown_attr(&mut self, a: &Attr, on: &str, extra: &mut Extras) {
        if a.value.trim().is_empty() {
            self.empties.add(&a.qname);
            extra.push(attr_extra(a));
            return;
        }
        self.warn(
            a.pos,
            format!(
                "unknown attribute `{}`{} on {on}; kept as an extra property",
                a.qname,
                foreign(&a.ns)
            ),
        );
        extra.push(attr_extra(a));
    }

    /// An element the spec does not define inside `on` (kept with its whole subtree).
    pub(super) fn unknown_elem(&mut self, n: &Node, on: &str, extra: &mut Extras) {
        self.warn(
            n.pos,
            format!(
                "unknown element `{}`{} in {on}; kept as an extra property",
                n.qname,
                foreign(&n.ns)
            ),
        );
        extra.push(node_extra(n));
    }

    /// A second occurrence of an element or attribute allowed once.
    pub(super) fn repeated_elem(&mut self, n: &Node, on: &str, extra: &mut Extras) {
        self.warn(
            n.pos,
            format!(
                "repeated element `{}` in {on}; only the first is used, this one is kept as an extra property",
                n.qname
            ),
        );
        extra.push(node_extra(n));
    }

    /// Sets a known attribute's field; a duplicate (same local name in two namespaces) goes
    /// to `extra`.
    pub(super) fn set(&mut self, slot: &mut Option<Text>, a: &Attr, on: &str, extra: &mut Extras) {
        if slot.is_some() {
            self.warn(
                a.pos,
                format!(
                    "repeated attribute `{}` on {on}; the first is used, this one is kept as an extra property",
                    a.qname
                ),
            );
            extra.push(attr_extra(a));
        } else {
            *slot = Some((&*a.value).into());
        }
    }

    /// Non-whitespace text directly inside an element that holds no text.
    pub(super) fn stray_text(&mut self, n: &Node, on: &str, extra: &mut Extras) {
        if n.has_text() {
            let pos = n.text_pos.unwrap_or(n.pos);
            self.warn(
                pos,
                format!("unexpected text in {on}; kept as an extra property"),
            );
            extra.push(Extra {
                kind: ExtraKind::Element,
                name: "#text".into(),
                namespace: None,
                value: Some(n.text.as_str().into()),
                children: crate::model::Extras::new(),
                pos,
            });
        }
    }

    /// Text content of a text-only element (`VersionUpLogs`, `cpus`, `Literal`, …). Its
    /// attributes and child elements are unknown and go to `extra` of the owning node.
    pub(super) fn text_of(&mut self, n: &Node, on: &str, extra: &mut Extras) -> Text {
        if !n.attrs.is_empty() || !n.children.is_empty() {
            let what = format!("`{}` of {on}", n.qname);
            for a in &n.attrs {
                self.unknown_attr(a, &what, extra);
            }
            for c in &n.children {
                self.unknown_elem(c, &what, extra);
            }
        }
        n.text.as_str().into()
    }

    /// Reports every attribute of an element that has none defined.
    pub(super) fn no_attrs(&mut self, n: &Node, on: &str, extra: &mut Extras) {
        for a in &n.attrs {
            self.unknown_attr(a, on, extra);
        }
    }
}

pub(super) fn foreign(ns: &Ns) -> String {
    match ns {
        Ns::Other(uri) => format!(" (namespace {uri})"),
        _ => String::new(),
    }
}

pub(super) fn attr_extra(a: &Attr) -> Extra {
    Extra {
        kind: ExtraKind::Attribute,
        name: (&*a.qname).into(),
        namespace: a.ns.uri(),
        value: Some((&*a.value).into()),
        children: crate::model::Extras::new(),
        pos: a.pos,
    }
}

/// An unknown element with its whole subtree: attributes first, then child elements.
pub(super) fn node_extra(n: &Node) -> Extra {
    let mut children: Extras = n.attrs.iter().map(attr_extra).collect();
    children.extend(n.children.iter().map(node_extra));
    Extra {
        kind: ExtraKind::Element,
        name: (&*n.qname).into(),
        namespace: n.ns.uri(),
        value: n.has_text().then(|| n.text.as_str().into()),
        children,
        pos: n.pos,
    }
}

impl Mapper<'_> {
    /// Records that attribute `a` was read as `field` of `node` under an older spelling.
    pub(super) fn alias(&mut self, node: &str, field: &str, a: &Attr, dialect: &'static str) {
        self.written_as.push(WrittenAs {
            field: compact_str::format_compact!("{node}.{field}"),
            written_as: (&*a.qname).into(),
            dialect,
            pos: a.pos,
        });
    }
}

/// An attribute read under an older spelling: the field's JSON name, the attribute and the
/// writer of the spelling, for [`Profile::written_as`].
pub(super) type Alias<'n, 't> = (&'static str, &'n Attr<'t>, &'static str);

/// Reads the attributes of `n` that the field table lists for `T` into `t` (noting their
/// positions where `T` keeps them); every other attribute is unknown on `on`. Returns the
/// attributes read under an older spelling.
pub(super) fn scalar_attrs<'n, 't, T: Fields>(
    m: &mut Mapper,
    n: &'n Node<'t>,
    t: &mut T,
    on: &str,
    extra: &mut Extras,
) -> Vec<Alias<'n, 't>> {
    let mut aliases = Vec::new();
    for a in &n.attrs {
        if !scalar_attr(m, a, t, on, extra, &mut aliases) {
            m.unknown_attr(a, on, extra);
        }
    }
    aliases
}

/// Reads attribute `a` into `t` when the field table lists it for `T`; false otherwise.
pub(super) fn scalar_attr<'n, 't, T: Fields>(
    m: &mut Mapper,
    a: &'n Attr<'t>,
    t: &mut T,
    on: &str,
    extra: &mut Extras,
    aliases: &mut Vec<Alias<'n, 't>>,
) -> bool {
    let Some((def, spelling)) = a.key().and_then(|k| T::NODE.xml(k)) else {
        return false;
    };
    if let Some(p) = t.attr_pos() {
        p.note(def.field, a.pos);
    }
    if let Some(d) = spelling.dialect {
        aliases.push((def.json, a, d));
    }
    match t.slot(def.field) {
        Some(slot) => m.set(slot, a, on, extra),
        None => return false,
    }
    true
}

/// Reads element `n` as the node `T` of the field table: its position, its attributes by the
/// table, each child element by `child` (given the node and its extras, where unknown elements
/// go too) and stray text. Returns the node and the attributes read under an older spelling.
pub(super) fn map_node<'n, 't, T: Fields + Default>(
    m: &mut Mapper,
    n: &'n Node<'t>,
    on: &str,
    mut child: impl FnMut(&mut Mapper, &'n Node<'t>, &mut T, &mut Extras),
) -> (T, Vec<Alias<'n, 't>>) {
    let mut t = T::default();
    *t.pos_mut() = n.pos;
    let mut extra = crate::model::Extras::new();
    let aliases = scalar_attrs(m, n, &mut t, on, &mut extra);
    for c in &n.children {
        child(m, c, &mut t, &mut extra);
    }
    m.stray_text(n, on, &mut extra);
    *t.extra_mut() = extra;
    (t, aliases)
}

/// [`map_node`] for a node with no child elements defined.
pub(super) fn map_leaf<T: Fields + Default>(m: &mut Mapper, n: &Node, on: &str) -> T {
    map_node(m, n, on, |m, c, _, extra| m.unknown_elem(c, on, extra)).0
}

impl Mapper<'_> {
    /// Records the attributes of a node read under an older spelling (after its children, as
    /// [`Profile::written_as`] lists them); the node's name (`kind name`) is made only when
    /// there are any (almost never).
    pub(super) fn aliases(&mut self, node: impl FnOnce() -> String, aliases: Vec<Alias>) {
        if aliases.is_empty() {
            return;
        }
        let node = node();
        for (field, a, dialect) in aliases {
            self.alias(&node, field, a, dialect);
        }
    }

    /// Child `n` of `on` as its `Doc` element (named `doc_on`, `{on} doc`, in messages: given,
    /// not formatted for every node), the first only ([`Mapper::once`]).
    pub(super) fn doc<T: Fields + Default>(
        &mut self,
        slot: &mut Option<T>,
        n: &Node,
        [on, doc_on]: [&str; 2],
        extra: &mut Extras,
    ) {
        self.once(slot, n, on, extra, |m, n| map_leaf(m, n, doc_on));
    }

    /// Child `n` of `on` as the one element `slot` holds: mapped by `map` the first time, a
    /// repeated element (kept in `extra`) after.
    pub(super) fn once<T>(
        &mut self,
        slot: &mut Option<T>,
        n: &Node,
        on: &str,
        extra: &mut Extras,
        map: impl FnOnce(&mut Self, &Node) -> T,
    ) {
        if slot.is_none() {
            *slot = Some(map(self, n));
        } else {
            self.repeated_elem(n, on, extra);
        }
    }
}

/// Non-empty text of a text element (whitespace-only counts as empty).
pub(super) fn non_blank(s: &str) -> Option<Text> {
    (!s.trim().is_empty()).then(|| s.into())
}

/// spec 2.2 `rtc_profile`, XSD 6.1 `RtcProfile`.
pub(super) fn map_profile(m: &mut Mapper, n: &Node) -> Profile {
    let on = "profile";
    let mut seen_basic = false;
    let (p, _) = map_node(m, n, on, |m, c, p: &mut Profile, extra| match c.key() {
        Some("BasicInfo") if !seen_basic => {
            seen_basic = true;
            p.basic_info = map_basic_info(m, c);
        }
        Some("Actions") if p.actions_pos.is_none() => {
            p.actions_pos = Some(c.pos);
            map_actions(m, c, &mut p.actions, extra);
        }
        Some("ConfigurationSet") if p.configuration_set.is_none() => {
            p.configuration_set = Some(map_configuration_set(m, c));
        }
        Some("DataPorts") => p.data_ports.push(map_data_port(m, c)),
        Some("ServicePorts") => p.service_ports.push(map_service_port(m, c)),
        Some("Parameters") => p.parameters.push(map_parameter(m, c)),
        Some("Language") if p.language.is_none() => p.language = Some(map_language(m, c)),
        Some("BasicInfo" | "Actions" | "ConfigurationSet" | "Language") => {
            m.repeated_elem(c, on, extra)
        }
        _ => m.unknown_elem(c, on, extra),
    });
    p
}

/// spec 2.3.2 basic info, 2.4.1 doc, 2.5.1 ext.
pub(super) fn map_basic_info(m: &mut Mapper, n: &Node) -> BasicInfo {
    let on = "basic info";
    let (b, _) = map_node(m, n, on, |m, c, b: &mut BasicInfo, extra| match c.key() {
        Some("Doc") => m.doc(&mut b.doc, c, [on, "basic info doc"], extra),
        // XSD 6.3 `VersionUpLogs`; the 9.2 sample writes `VersionUpLog`. Empty ones are
        // common in real files and say nothing.
        Some("VersionUpLogs" | "VersionUpLog") => {
            if let Some(t) = non_blank(&m.text_of(c, on, extra)) {
                b.version_up_logs.push(t);
            }
        }
        Some("Properties") => b.properties.push(map_leaf(m, c, "property")),
        _ => m.unknown_elem(c, on, extra),
    });
    b
}

/// spec 2.3.3 actions: the 14 callbacks, kept in document order. Unknown content of the
/// `Actions` element itself goes to the profile's extras.
pub(super) fn map_actions(m: &mut Mapper, n: &Node, actions: &mut Vec<Action>, extra: &mut Extras) {
    let on = "actions";
    m.no_attrs(n, on, extra);
    for c in &n.children {
        let kind = c.key().and_then(ActionKind::from_xml_name);
        match kind {
            Some(k) if actions.iter().all(|a| a.kind != k) => actions.push(map_action(m, c, k)),
            Some(_) => m.repeated_elem(c, on, extra),
            None => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
}

/// `action OnInitialize` and `action OnInitialize doc`: an action's names in messages, made
/// once (they were formatted for every action of every profile).
fn action_names(kind: ActionKind) -> [&'static str; 2] {
    static NAMES: std::sync::LazyLock<Vec<(ActionKind, [String; 2])>> =
        std::sync::LazyLock::new(|| {
            ActionKind::ALL
                .iter()
                .map(|k| {
                    let on = format!("action {}", k.xml_name());
                    let doc = format!("{on} doc");
                    (*k, [on, doc])
                })
                .collect()
        });
    let names = NAMES.iter().find(|(k, _)| *k == kind);
    names.map_or(["action", "action doc"], |(_, [on, doc])| {
        [on.as_str(), doc.as_str()]
    })
}

/// spec 2.3.4 `action_status`, 2.4.3 `doc_action`.
pub(super) fn map_action(m: &mut Mapper, n: &Node, kind: ActionKind) -> Action {
    let [on, doc_on] = action_names(kind);
    let mut act = Action {
        kind,
        implemented: None,
        doc: None,
        pos: n.pos,
        extra: crate::model::Extras::new(),
    };
    let mut extra = crate::model::Extras::new();
    scalar_attrs(m, n, &mut act, on, &mut extra);
    for c in &n.children {
        match c.key() {
            Some("Doc") => m.doc(&mut act.doc, c, [on, doc_on], &mut extra),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    act.extra = extra;
    act
}

/// spec 2.3.5 `configuration_set`.
pub(super) fn map_configuration_set(m: &mut Mapper, n: &Node) -> ConfigurationSet {
    let on = "configuration set";
    let mut cs = ConfigurationSet {
        pos: n.pos,
        ..Default::default()
    };
    let mut extra = crate::model::Extras::new();
    m.no_attrs(n, on, &mut extra);
    for c in &n.children {
        match c.key() {
            Some("Configuration") => cs.configurations.push(map_configuration(m, c)),
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    cs.extra = extra;
    cs
}

/// Node `n` as the [`Documented`] node `T` (named `on` in messages, its doc `doc_on`): its
/// scalars by the field table, the children all of them have (`Doc`, `Properties`, and
/// `Constraint` where `T` has one), any other child by `other` (false: unknown).
fn map_documented<'n, 't, T: Documented>(
    m: &mut Mapper,
    n: &'n Node<'t>,
    [on, doc_on]: [&str; 2],
    mut other: impl FnMut(&mut Mapper, &'n Node<'t>, &mut T) -> bool,
) -> T {
    let (t, aliases) = map_node(m, n, on, |m, c, t: &mut T, extra| {
        if other(m, c, t) {
            return;
        }
        let parts = t.parts();
        match (c.key(), parts.constraint) {
            (Some("Doc"), _) => m.doc(parts.doc, c, [on, doc_on], extra),
            (Some("Properties"), _) => parts.properties.push(map_leaf(m, c, "property")),
            (Some("Constraint"), Some(slot)) => m.once(slot, c, on, extra, map_constraint),
            _ => m.unknown_elem(c, on, extra),
        }
    });
    m.aliases(|| t.written_as_node(), aliases);
    t
}

/// spec 2.3.6 `configuration`, 2.4.4 doc, 2.5.2 ext.
pub(super) fn map_configuration(m: &mut Mapper, n: &Node) -> Configuration {
    let on = ["configuration", "configuration doc"];
    map_documented(m, n, on, |_, _, _| false)
}

/// spec 2.3.7 `dataport`, 2.4.5 doc, 2.5.3 ext; FSM `EventPort`s carry `Event` children.
pub(super) fn map_data_port(m: &mut Mapper, n: &Node) -> DataPort {
    map_documented(
        m,
        n,
        ["data port", "data port doc"],
        |m, c, d: &mut DataPort| {
            let event = c.key() == Some("Event");
            if event {
                d.events.push(map_event(m, c));
            }
            event
        },
    )
}

/// An FSM event of an `EventPort` (RTCBuilder 2.x; not in spec v0.2); its doc is a data port
/// doc (`rtcDoc:event_doc`).
pub(super) fn map_event(m: &mut Mapper, n: &Node) -> Event {
    let on = "event";
    let (e, _) = map_node(m, n, on, |m, c, e: &mut Event, extra| match c.key() {
        Some("Doc") => m.doc(&mut e.doc, c, [on, "event doc"], extra),
        _ => m.unknown_elem(c, on, extra),
    });
    e
}

/// spec 2.3.8 `serviceport`, 2.4.7 doc, 2.5.4 ext, 2.3.10 `transmission_method`.
pub(super) fn map_service_port(m: &mut Mapper, n: &Node) -> ServicePort {
    let on = ["service port", "service port doc"];
    map_documented(m, n, on, |m, c, s: &mut ServicePort| {
        match c.key() {
            Some("ServiceInterface") => s.interfaces.push(map_service_interface(m, c)),
            Some("TransMethods") => s.trans_methods.push(map_leaf(m, c, "transmission method")),
            _ => return false,
        }
        true
    })
}

/// spec 2.3.9 `serviceinterface`, 2.4.8 doc, 2.5.5 ext.
pub(super) fn map_service_interface(m: &mut Mapper, n: &Node) -> ServiceInterface {
    let on = ["service interface", "service interface doc"];
    map_documented(m, n, on, |_, _, _| false)
}

/// spec 2.3.11 `parameter`.
pub(super) fn map_parameter(m: &mut Mapper, n: &Node) -> Parameter {
    map_leaf(m, n, "parameter")
}

/// spec 2.3.12 `language`, 2.5.6 `language_ext`.
pub(super) fn map_language(m: &mut Mapper, n: &Node) -> Language {
    let on = "language";
    let (l, _) = map_node(m, n, on, |m, c, l: &mut Language, extra| match c.key() {
        Some("targets") => l.targets.push(map_target(m, c)),
        Some(k) if crate::parse::dialect::language_element(k).is_some() => {
            map_language_element(m, c, l)
        }
        _ => m.unknown_elem(c, on, extra),
    });
    l
}

/// RTCBuilder 0.1's `<rtc:Language>` names the language by a child element (`<rtc:Cxx
/// rtc:arch="" rtc:os="etc"/>`, `<rtc:Python/>`, `<rtc:Java/>`) instead of `rtc:kind`: that
/// is the kind, and the child's attributes describe the target (`os`, `arch` → cpus,
/// `osVersion`, `langVersion`, `library` children).
pub(super) fn map_language_element(m: &mut Mapper, c: &Node, l: &mut Language) {
    let Some(kind) = c.key().and_then(crate::parse::dialect::language_element) else {
        return;
    };
    let on = format!("language `{}`", c.qname);
    if l.kind.is_none() {
        l.kind = Some(kind.into());
        m.written_as.push(WrittenAs {
            field: "language.kind".into(),
            written_as: (&*c.qname).into(),
            dialect: crate::parse::dialect::RTCBUILDER_01,
            pos: c.pos,
        });
    }
    let mut t = Target {
        pos: c.pos,
        ..Default::default()
    };
    let mut extra = crate::model::Extras::new();
    for a in &c.attrs {
        if scalar_attr(m, a, &mut t, &on, &mut extra, &mut Vec::new()) {
            continue;
        }
        match a.key() {
            Some("arch" | "cpu") => {
                if let Some(v) = non_blank(&a.value) {
                    t.cpus.push(v);
                }
            }
            Some("osVersion" | "osVersions") => {
                if let Some(v) = non_blank(&a.value) {
                    t.os_versions.push(v);
                }
            }
            _ => m.unknown_attr(a, &on, &mut extra),
        }
    }
    for lc in &c.children {
        match lc.key() {
            Some("library" | "libraries") if lc.attrs.is_empty() => {
                let name = m.text_of(lc, &on, &mut extra);
                if let Some(name) = non_blank(&name) {
                    t.libraries.push(Library {
                        name: Some(name),
                        pos: lc.pos,
                        ..Default::default()
                    });
                }
            }
            Some("library" | "libraries") => t.libraries.push(map_library(m, lc)),
            _ => m.unknown_elem(lc, &on, &mut extra),
        }
    }
    m.stray_text(c, &on, &mut extra);
    t.extra = extra;
    // An empty `<rtc:Cxx/>` names the language and nothing more.
    if t != (Target {
        pos: c.pos,
        ..Default::default()
    }) {
        l.targets.push(t);
    }
}

/// spec 2.5.7 `target_environment`.
pub(super) fn map_target(m: &mut Mapper, n: &Node) -> Target {
    let on = "target environment";
    let (t, _) = map_node(m, n, on, |m, c, t: &mut Target, extra| {
        let list = match c.key() {
            Some("osVersions") => &mut t.os_versions,
            Some("cpus") => &mut t.cpus,
            Some("libraries") => return t.libraries.push(map_library(m, c)),
            _ => return m.unknown_elem(c, on, extra),
        };
        if let Some(v) = non_blank(&m.text_of(c, on, extra)) {
            list.push(v);
        }
    });
    t
}

/// spec 2.5.8 `library`: XSD attribute `name`, PIM `path` (accepted silently).
pub(super) fn map_library(m: &mut Mapper, n: &Node) -> Library {
    map_leaf(m, n, "library")
}

// --- constraints (spec 2.3.17–2.3.41, XSD 6.1 `constraint_type`, samples 8.1) ------------------

/// `Constraint` → unit | list | hash. Element names are matched case-insensitively: the 8.1
/// samples write `PropertyIsEqualTo`, the XSD `propertyIsEqualTo`.
pub(super) fn map_constraint(m: &mut Mapper, n: &Node) -> Constraint {
    let on = "constraint";
    let mut extra = crate::model::Extras::new();
    m.no_attrs(n, on, &mut extra);
    let mut kind: Option<ConstraintKind> = None;
    for c in &n.children {
        let k = c.key_lower();
        match k.as_deref() {
            Some("constraintunittype" | "constraintlisttype" | "constrainthashtype")
                if kind.is_some() =>
            {
                m.repeated_elem(c, on, &mut extra)
            }
            Some("constraintunittype") => kind = Some(map_unit(m, c, &mut extra)),
            Some("constraintlisttype") => {
                kind = Some(ConstraintKind::List {
                    items: constraint_children(m, c, "constraint list", &mut extra),
                })
            }
            Some("constrainthashtype") => {
                kind = Some(ConstraintKind::Hash {
                    items: constraint_children(m, c, "constraint hash", &mut extra),
                })
            }
            _ => m.unknown_elem(c, on, &mut extra),
        }
    }
    m.stray_text(n, on, &mut extra);
    Constraint {
        kind: kind.unwrap_or(ConstraintKind::Empty),
        pos: n.pos,
        extra,
    }
}

/// The `Constraint` children of a list, hash, `And` or `Or`; anything else goes to `extra`.
pub(super) fn constraint_children(
    m: &mut Mapper,
    n: &Node,
    on: &str,
    extra: &mut Extras,
) -> Vec<Constraint> {
    m.no_attrs(n, on, extra);
    let mut items = Vec::new();
    for c in &n.children {
        match c.key_lower().as_deref() {
            Some("constraint") => items.push(map_constraint(m, c)),
            _ => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    items
}

/// spec 2.3.19 `ConstraintUnitType`: an optional `key` and one condition.
pub(super) fn map_unit(m: &mut Mapper, n: &Node, extra: &mut Extras) -> ConstraintKind {
    let on = "constraint unit";
    let mut key = None;
    let mut key_attr = None;
    for a in &n.attrs {
        match a.key() {
            Some("key") if key.is_none() => {
                key = Some((&*a.value).into());
                key_attr = Some(a);
            }
            _ => m.unknown_attr(a, on, extra),
        }
    }
    let mut condition: Option<Condition> = None;
    for c in &n.children {
        let k = c.key_lower();
        let cond = match k.as_deref() {
            Some(k) => map_condition(m, c, k, extra),
            None => None,
        };
        match cond {
            Some(_) if condition.is_some() => m.repeated_elem(c, on, extra),
            Some(cond) => condition = Some(cond),
            None => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    if let (None, Some(a)) = (&condition, key_attr) {
        m.warn(
            a.pos,
            format!(
                "constraint unit with key `{}` has no condition; the key is kept as an extra property",
                a.value
            ),
        );
        extra.push(attr_extra(a));
    }
    ConstraintKind::unit(key, condition)
}

/// One condition element (lower-cased local name `k`); `None` when `k` is not a condition.
pub(super) fn map_condition(
    m: &mut Mapper,
    n: &Node,
    k: &str,
    extra: &mut Extras,
) -> Option<Condition> {
    let on = format!("`{}`", n.qname);
    let cond = match k {
        // spec 2.3.23 Not: exactly one operand.
        "not" => map_not(m, n, &on, extra),
        // spec 2.3.24/25 And/Or: the XSD says two operands, samples and real files use more.
        "and" => Condition::And {
            operands: constraint_children(m, n, &on, extra),
        },
        "or" => Condition::Or {
            operands: constraint_children(m, n, &on, extra),
        },
        // spec 2.3.26 propertyIsNull (XSD: `propertyIsNullType` wrapping `propertyIsNull`).
        "propertyisnull" => {
            m.no_attrs(n, &on, extra);
            for c in &n.children {
                m.unknown_elem(c, &on, extra);
            }
            Condition::IsNull {
                text: non_blank(&n.text),
            }
        }
        "propertyisnulltype" => {
            m.no_attrs(n, &on, extra);
            let mut text = None;
            for c in &n.children {
                match c.key_lower().as_deref() {
                    Some("propertyisnull") if text.is_none() => {
                        text = Some(non_blank(&m.text_of(c, &on, extra)))
                    }
                    _ => m.unknown_elem(c, &on, extra),
                }
            }
            m.stray_text(n, &on, extra);
            Condition::IsNull {
                text: text.flatten(),
            }
        }
        // spec 2.3.38 propertyIsLike: wildCard (XSD) / wildChar (PIM) / wildcard (YAML).
        "propertyislike" => map_like(m, n, &on, extra),
        // spec 2.3.40 propertyIsBetween: both boundaries inclusive.
        "propertyisbetween" => map_between(m, n, &on, extra),
        // spec 2.3.27–2.3.37 comparisons: `Literal` + `matchCase` (often absent).
        _ => {
            let comparison = k
                .strip_prefix("propertyis")
                .and_then(Comparison::from_suffix)?;
            let mut match_case = None;
            for a in &n.attrs {
                match a.key().map(str::to_ascii_lowercase).as_deref() {
                    Some("matchcase") => m.set(&mut match_case, a, &on, extra),
                    _ => m.unknown_attr(a, &on, extra),
                }
            }
            Condition::Compare {
                comparison,
                literal: literal_child(m, n, &on, extra),
                match_case,
            }
        }
    };
    Some(cond)
}

/// spec 2.3.23 Not: exactly one operand; the others are kept as extra properties.
fn map_not(m: &mut Mapper, n: &Node, on: &str, extra: &mut Extras) -> Condition {
    let mut ops = constraint_children(m, n, on, extra).into_iter();
    let operand = ops.next().unwrap_or(Constraint {
        kind: ConstraintKind::Empty,
        pos: n.pos,
        extra: crate::model::Extras::new(),
    });
    for more in ops {
        m.warn(
            more.pos,
            format!(
                "`{}` takes one constraint; this extra one is kept as an extra property",
                n.qname
            ),
        );
        extra.push(Extra {
            kind: ExtraKind::Element,
            name: "Constraint".into(),
            namespace: None,
            value: None,
            children: crate::model::Extras::new(),
            pos: more.pos,
        });
    }
    Condition::Not { operand }
}

/// spec 2.3.38 propertyIsLike: wildCard (XSD) / wildChar (PIM) / wildcard (YAML).
fn map_like(m: &mut Mapper, n: &Node, on: &str, extra: &mut Extras) -> Condition {
    let (mut wild_card, mut single_char, mut escape_char) = (None, None, None);
    for a in &n.attrs {
        let slot = match a.key().map(str::to_ascii_lowercase).as_deref() {
            Some("wildcard" | "wildchar") => &mut wild_card,
            Some("singlechar") => &mut single_char,
            Some("escapechar") => &mut escape_char,
            _ => {
                m.unknown_attr(a, on, extra);
                continue;
            }
        };
        m.set(slot, a, on, extra);
    }
    Condition::Like {
        literal: literal_child(m, n, on, extra),
        wild_card,
        single_char,
        escape_char,
    }
}

/// spec 2.3.40 propertyIsBetween: both boundaries inclusive.
fn map_between(m: &mut Mapper, n: &Node, on: &str, extra: &mut Extras) -> Condition {
    m.no_attrs(n, on, extra);
    let (mut lower, mut upper) = (None, None);
    for c in &n.children {
        match c.key_lower().as_deref() {
            Some("lowerboundary") if lower.is_none() => lower = Some(m.text_of(c, on, extra)),
            Some("upperboundary") if upper.is_none() => upper = Some(m.text_of(c, on, extra)),
            _ => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    Condition::Between { lower, upper }
}

/// The text of the `Literal` child; other children and stray text go to `extra`.
pub(super) fn literal_child(
    m: &mut Mapper,
    n: &Node,
    on: &str,
    extra: &mut Extras,
) -> Option<Text> {
    let mut literal = None;
    for c in &n.children {
        match c.key_lower().as_deref() {
            Some("literal") if literal.is_none() => literal = Some(m.text_of(c, on, extra)),
            _ => m.unknown_elem(c, on, extra),
        }
    }
    m.stray_text(n, on, extra);
    literal
}
