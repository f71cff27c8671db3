//! The wiring of an RT System as the diagrams draw it: instances with their ports and the
//! connectors between them, built once from the catalogue and drawn by each renderer — SVG
//! (`html::system_svg`, laid out by [`crate::layout::wiring`]), Graphviz DOT and Mermaid
//! (`rtcdoc graph`, the Markdown output's `diagrams = "mermaid"`).

use crate::catalog::systems::{
    end_port_name, instance_lists_port, InstancePortKind, PortLink, System,
};
use crate::catalog::Catalog;
use crate::i18n::Lang;
use crate::model::{non_empty, PortDirection, Text};
use std::fmt::Write as _;

fn txt(v: &Option<Text>) -> String {
    non_empty(v).unwrap_or("").to_string()
}

/// A port as drawn.
#[derive(Clone)]
pub struct WirePort {
    pub name: String,
    /// `in`, `out`, `service` or `other` (CSS class and side).
    pub class: &'static str,
    /// Where the port's link goes (the component page's port row, or the instance row).
    pub href: String,
    /// Accessible name of the link.
    pub label: String,
    /// A port the system file names but the component's profile (in the catalogue) does not
    /// have (RTC601): drawn in a style of its own.
    pub unknown: bool,
}

/// An instance as drawn.
#[derive(Clone)]
pub struct WireInstance {
    pub name: String,
    /// The component's name (second line), when known.
    pub component: String,
    pub href: String,
    pub label: String,
    pub ports: Vec<WirePort>,
    /// `rtsExt:Location` x/y, when given as integers.
    pub location: Option<(i64, i64)>,
    /// What the instance is in a composite component, which the drawings mark.
    pub role: Role,
}

/// The notes under a drawing on its own: the connectors it leaves out (warnings), and the
/// legend of its outlines (an explanation).
pub type DrawingNotes<'a> = (&'a [String], Option<&'a str>);

/// An instance's part in composite components: a composite (a `compositeType` other than
/// `None`, or participants) is drawn with a double outline, a member (a participant of
/// another instance) with a dashed one; the accessible name says which.
#[derive(Clone, Copy, Default, PartialEq, Eq, Debug)]
pub struct Role {
    pub composite: bool,
    pub member: bool,
}

impl Role {
    /// The SVG classes of the instance's group after `instance` (` composite`, ` member`).
    pub fn classes(self) -> &'static str {
        match (self.composite, self.member) {
            (false, false) => "",
            (true, false) => " composite",
            (false, true) => " member",
            (true, true) => " composite member",
        }
    }
}

/// A connector between two ports: (instance, port) indices into the drawn instances.
pub struct WireConnector {
    pub from: (usize, usize),
    pub to: (usize, usize),
    pub service: bool,
    /// What the connector is, for assistive technology and tooltips.
    pub label: String,
    /// The text written on the edge of an exported graph (DOT `label`, Mermaid's link text),
    /// where the ports alone do not say what the edge is; `None`: DOT shows none and Mermaid
    /// `out → in`.
    pub caption: Option<String>,
}

/// The wiring of a system as drawn: its instances, the connectors drawn between them, a
/// sentence for each connector that could not be drawn (an end naming no instance of the
/// system, RTC608, or no end at all), and, when the system has composite components, what
/// their outlines mean. Every drawing and caption shows both ([`SystemWiring::notes`]).
pub struct SystemWiring {
    pub instances: Vec<WireInstance>,
    pub connectors: Vec<WireConnector>,
    pub not_drawn: Vec<String>,
    /// What the SVG drawing's marks mean (outlines and port squares).
    pub legend: Option<String>,
    /// What the outlines mean, for DOT and Mermaid, which draw no port squares.
    pub outline_legend: Option<String>,
}

impl SystemWiring {
    /// The sentences under the drawing: the connectors not drawn, then the legend (`squares`:
    /// a drawing with port squares, the SVG; DOT and Mermaid have none).
    pub fn notes(&self, squares: bool) -> Vec<String> {
        let legend = if squares {
            &self.legend
        } else {
            &self.outline_legend
        };
        self.not_drawn.iter().chain(legend).cloned().collect()
    }
    /// The notes as a drawing on its own writes them: the connectors not drawn (warnings), and
    /// the legend (an explanation).
    pub fn drawing_notes(&self) -> DrawingNotes<'_> {
        (&self.not_drawn, self.legend.as_deref())
    }
}

/// The instances and connectors of system `s`. A port of a component in the catalogue links
/// to its row on the component's page through `link(page, anchor)` (the caller's
/// [`Catalog::href`] from where the drawing is shown); an instance links to its row (`#…`).
pub fn system_wiring(
    catalog: &Catalog,
    s: &System,
    lang: Lang,
    link: &dyn Fn(&crate::catalog::Page, &str) -> String,
) -> SystemWiring {
    let p = &s.profile;
    let mut wire: Vec<WireInstance> = Vec::with_capacity(p.components.len());
    for (i, c) in p.components.iter().enumerate() {
        let (iname, comp) = (txt(&c.instance_name), catalog.instance_component(s, i));
        let anchor = &s.instances[i].anchor;
        let ports = catalog
            .instance_ports(s, i)
            .into_iter()
            .map(|pt| {
                let class = match pt.kind {
                    InstancePortKind::Service => "service",
                    InstancePortKind::Data(Some(PortDirection::In)) => "in",
                    InstancePortKind::Data(Some(PortDirection::Out)) => "out",
                    InstancePortKind::Data(_) => "other",
                };
                let page = s.instances[i]
                    .component_index
                    .map(|ci| catalog.component_page(ci));
                let href = match (comp, page, &pt.link) {
                    (Some(k), Some(to), Some(PortLink::Data { index, .. })) => {
                        link(to, &k.anchors.data_ports[*index])
                    }
                    (Some(k), Some(to), Some(PortLink::Service { index, .. })) => {
                        link(to, &k.anchors.service_ports[*index])
                    }
                    _ => format!("#{anchor}"),
                };
                let kind = match class {
                    "in" => lang.t("sys_in_port"),
                    "out" => lang.t("sys_out_port"),
                    "service" => lang.t("sys_service_port"),
                    _ => lang.t("port"),
                };
                // A port its component's profile does not have, or, for a component not in
                // the catalogue, one the system file does not list for the instance (RTC601).
                let service = pt.kind == InstancePortKind::Service;
                let why = match comp {
                    Some(_) => pt.link.is_none().then_some("sys_port_not_in_profile"),
                    None => (instance_lists_port(c, service, &pt.name) == Some(false))
                        .then_some("sys_port_not_listed"),
                };
                let unknown = why.is_some();
                WirePort {
                    label: match why {
                        Some(key) => format!("{kind} {iname}.{} ({})", pt.name, lang.t(key)),
                        None => format!("{kind} {iname}.{}", pt.name),
                    },
                    name: pt.name,
                    class,
                    href,
                    unknown,
                }
            })
            .collect();
        let component = comp
            .map(|k| k.display_name().into_owned())
            .or_else(|| {
                c.id_parts
                    .as_ref()
                    .and_then(|x| non_empty(&x.name))
                    .map(str::to_string)
            })
            .unwrap_or_default();
        let (role, about) = composite_role(p, c, &iname, lang);
        wire.push(WireInstance {
            // The accessible name starts with the box's visible text (WCAG 2.5.3).
            label: if component.is_empty() {
                format!("{iname} ({about})")
            } else {
                format!("{iname} {component} ({about})")
            },
            role,
            component,
            name: iname,
            href: format!("#{anchor}"),
            ports,
            location: c.location.as_ref().and_then(|l| l.xy()),
        });
    }
    let (connectors, not_drawn) =
        system_connectors(s, &wire, &catalog.reversed_data_connectors(s), lang);
    SystemWiring {
        legend: legend(&wire, lang, true),
        outline_legend: legend(&wire, lang, false),
        instances: wire,
        connectors,
        not_drawn,
    }
}

/// Instance `c`'s part in composite components of system profile `p` and the words its
/// accessible name gets for it (`Instance, Composite type: PeriodicECShared, Members: A0, B0`
/// or `Instance, member of: CompositeRTC`).
fn composite_role(
    p: &crate::model::system::RtSystem,
    c: &crate::model::system::SystemComponent,
    iname: &str,
    lang: Lang,
) -> (Role, String) {
    // A composite names its type and members; a member the composites it belongs to (a
    // composite without a name still makes its members members).
    let members = c.member_names();
    let kind = non_empty(&c.composite_type).filter(|t| *t != "None");
    let mut member = false;
    let mut member_of: Vec<&str> = Vec::new();
    for k in p.composites_of(iname) {
        member = true;
        if let Some(n) = non_empty(&k.instance_name).filter(|n| !member_of.contains(n)) {
            member_of.push(n);
        }
    }
    let role = Role {
        composite: kind.is_some() || !c.participants.is_empty(),
        member,
    };
    let mut about = lang.t("instance").to_string();
    if let Some(kind) = kind {
        about.push_str(&format!(", {}: {kind}", lang.t("sys_composite")));
    }
    if !members.is_empty() {
        about.push_str(&format!(
            ", {}: {}",
            lang.t("sys_members"),
            members.join(", ")
        ));
    }
    if !member_of.is_empty() {
        let of = lang.t("sys_member_of").trim_end_matches(':');
        about.push_str(&format!(", {of}: {}", member_of.join(", ")));
    }
    (role, about)
}

/// What the drawing's marks mean, each naming its instances: the outlines of composite
/// components and their members, and the hollow (kind unknown) and dotted (not in the
/// component's profile, RTC601) port squares, those only when the drawing has `squares` (the
/// SVG) (`Double outline: composite component (Planner0); dashed outline: member of a composite
/// (Camera0)`); `None` when the drawing has none.
fn legend(wire: &[WireInstance], lang: Lang, squares: bool) -> Option<String> {
    let part = |key: &str, pick: &dyn Fn(&WireInstance) -> bool| {
        if !wire.iter().any(pick) {
            return None;
        }
        // The named ones, each once (an instance may have no name, or share one).
        let mut names: Vec<&str> = Vec::new();
        for w in wire.iter().filter(|w| pick(w) && !w.name.is_empty()) {
            if !names.contains(&w.name.as_str()) {
                names.push(&w.name);
            }
        }
        // At most five named, so that the sentence stays a line under a large system.
        const NAMED: usize = 5;
        let mut shown: Vec<String> = names.iter().take(NAMED).map(|n| n.to_string()).collect();
        if names.len() > NAMED {
            shown.push(format!("+{} {}", names.len() - NAMED, lang.t("nb_more")));
        }
        Some(if shown.is_empty() {
            lang.t(key).to_string()
        } else {
            format!("{} ({})", lang.t(key), shown.join(", "))
        })
    };
    let port = |w: &WireInstance, unknown: bool| {
        w.ports
            .iter()
            .any(|p| p.unknown == unknown && (unknown || p.class == "other"))
    };
    let parts: Vec<String> = [
        part("sys_legend_composite", &|w| w.role.composite),
        part("sys_legend_member", &|w| w.role.member),
        part("sys_legend_other_port", &|w| squares && port(w, false)),
        part("sys_legend_unknown_port", &|w| squares && port(w, true)),
    ]
    .into_iter()
    .flatten()
    .collect();
    // A sentence: its first letter a capital, whichever part comes first.
    let text = parts.join("; ");
    let mut chars = text.chars();
    let first = chars.next()?;
    Some(first.to_uppercase().chain(chars).collect())
}

/// A connector as a note names it: its name and its id in brackets (`out_in [c3]`: names
/// repeat), either alone, or `—`.
fn connector_name(name: &Option<Text>, id: &Option<Text>) -> String {
    match (non_empty(name), non_empty(id)) {
        (Some(n), Some(i)) if n != i => format!("{n} [{i}]"),
        (Some(n), _) => n.to_string(),
        (None, Some(i)) => i.to_string(),
        (None, None) => "—".to_string(),
    }
}

/// Why a connector named `name`, from end `se` to end `te`, is not drawn, as a sentence
/// (`Not drawn: c3 (Src0.out → Ghost0.in): the system has no instance Ghost0`): its ends as the
/// file names them and what is missing.
fn not_drawn_note(
    lang: Lang,
    name: &str,
    (se, te): (
        &Option<crate::model::system::PortEnd>,
        &Option<crate::model::system::PortEnd>,
    ),
    (a, b): (Option<usize>, Option<usize>),
) -> String {
    let end = |e: &Option<crate::model::system::PortEnd>| {
        e.as_ref()
            .map(|e| format!("{}.{}", txt(&e.instance_name), end_port_name(e)))
            .unwrap_or_else(|| "?".to_string())
    };
    let missing: Vec<String> = [(se, a), (te, b)]
        .into_iter()
        .filter(|(_, i)| i.is_none())
        .map(|(e, _)| match e {
            Some(e) => format!("{} {}", lang.t("sys_no_instance"), txt(&e.instance_name)),
            None => lang.t("sys_no_end").to_string(),
        })
        .collect();
    let reason = if missing.is_empty() {
        lang.t("sys_no_port").to_string()
    } else {
        missing.join("; ")
    };
    format!(
        "{}: {name} ({} → {}): {reason}",
        lang.t("sys_not_drawn"),
        end(se),
        end(te)
    )
}

/// The connectors of system `s` between its drawn instances `wire`: data connectors from the
/// out-port to the in-port (`reversed`: those saved in-port first,
/// [`Catalog::reversed_data_connectors`]), service connectors undirected.
fn system_connectors(
    s: &System,
    wire: &[WireInstance],
    reversed: &[bool],
    lang: Lang,
) -> (Vec<WireConnector>, Vec<String>) {
    let p = &s.profile;
    let port_at = |i: usize, name: &str| wire.get(i)?.ports.iter().position(|q| q.name == name);
    let mut conns: Vec<WireConnector> = Vec::new();
    let mut not_drawn: Vec<String> = Vec::new();
    // Both kinds of connector: the ends' instances (resolved by the catalogue) and ports.
    let ends = p
        .data_port_connectors
        .iter()
        .zip(&s.data_connectors)
        .enumerate()
        .map(|(k, (c, l))| {
            let turned = reversed.get(k).copied().unwrap_or(false);
            let name = connector_name(&c.name, &c.connector_id);
            let data_type = Some(non_empty(&c.data_type));
            (l, name, (&c.source, &c.target), data_type, turned)
        })
        .chain(
            p.service_port_connectors
                .iter()
                .zip(&s.service_connectors)
                .map(|(c, l)| {
                    let name = connector_name(&c.name, &c.connector_id);
                    (l, name, (&c.source, &c.target), None, false)
                }),
        );
    for (l, name, ends, data_type, turned) in ends {
        let (a, b) = (l.source.instance, l.target.instance);
        let drawn = match (a, b, ends.0, ends.1) {
            (Some(a), Some(b), Some(se), Some(te)) => {
                match (port_at(a, end_port_name(se)), port_at(b, end_port_name(te))) {
                    (Some(pa), Some(pb)) => Some((a, b, se, te, pa, pb)),
                    _ => None,
                }
            }
            _ => None,
        };
        let Some((a, b, se, te, pa, pb)) = drawn else {
            not_drawn.push(not_drawn_note(lang, &name, ends, (a, b)));
            continue;
        };
        let (mut source, mut target) = (
            format!("{}.{}", txt(&se.instance_name), end_port_name(se)),
            format!("{}.{}", txt(&te.instance_name), end_port_name(te)),
        );
        let (mut from, mut to) = ((a, pa), (b, pb));
        // Data flows from the out-port to the in-port whichever end the file names first
        // (RTSystemEditor saves the end the user dragged from as the source).
        if turned {
            std::mem::swap(&mut from, &mut to);
            std::mem::swap(&mut source, &mut target);
        }
        conns.push(WireConnector {
            from,
            to,
            service: data_type.is_none(),
            // A data connector without a data type says nothing about it (no empty `()`).
            label: match data_type {
                Some(Some(t)) => format!("{source} → {target} ({t})"),
                Some(None) => format!("{source} → {target}"),
                None => format!("{source} — {target}"),
            },
            caption: None,
        });
    }
    (conns, not_drawn)
}

/// `s` with each character of `table` replaced by its text, and control characters by a space.
fn escape_with(s: &str, table: &[(char, &str)]) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match table.iter().find(|(k, _)| *k == c) {
            Some((_, e)) => o.push_str(e),
            None if c.is_control() => o.push(' '),
            None => o.push(c),
        }
    }
    o
}

/// Escapes text for a Graphviz HTML-like label.
fn dot_html(s: &str) -> String {
    escape_with(
        s,
        &[
            ('&', "&amp;"),
            ('<', "&lt;"),
            ('>', "&gt;"),
            ('"', "&quot;"),
        ],
    )
}

/// Escapes text for a quoted Graphviz string.
fn dot_str(s: &str) -> String {
    escape_with(s, &[('"', "\\\""), ('\\', "\\\\")])
}

/// The wiring as a Graphviz DOT digraph (data flowing left to right): each instance a table
/// with its name, its component and its ports (in-ports in the left column, the others in the
/// right one, each a DOT port `pK`); data connectors as arrows between ports, service
/// connectors dashed without arrowheads. `rtstodot` parity: `dot -Tsvg` draws it. A port not in
/// its component's profile is in italics with a `?`; `not_drawn` (the connectors left out, and
/// why) is the graph's label, below the drawing.
pub fn to_dot(
    name: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
    not_drawn: &[String],
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "digraph \"{}\" {{", dot_str(name));
    s.push_str("  rankdir=LR;\n  node [shape=plaintext, fontname=\"sans-serif\", fontsize=11];\n  edge [fontname=\"sans-serif\", fontsize=9];\n");
    if !not_drawn.is_empty() {
        // Each line left-justified (`\l`), under the drawing.
        let lines: String = not_drawn
            .iter()
            .map(|n| format!("{}\\l", dot_str(n)))
            .collect();
        let _ = writeln!(
            s,
            "  graph [fontname=\"sans-serif\", fontsize=10, labelloc=b, labeljust=l, label=\"{lines}\"];"
        );
    }
    for (i, it) in inst.iter().enumerate() {
        dot_node(&mut s, i, it);
    }
    for c in conns {
        let (Some(a), Some(b)) = (inst.get(c.from.0), inst.get(c.to.0)) else {
            continue;
        };
        if c.from.1 >= a.ports.len() || c.to.1 >= b.ports.len() {
            continue;
        }
        let side = |class: &str| if class == "in" { "w" } else { "e" };
        let _ = writeln!(
            s,
            "  n{}:p{}:{} -> n{}:p{}:{} [{}tooltip=\"{}\"{}];",
            c.from.0,
            c.from.1,
            side(a.ports[c.from.1].class),
            c.to.0,
            c.to.1,
            side(b.ports[c.to.1].class),
            c.caption
                .as_deref()
                .map(|t| format!("label=\"{}\", ", dot_str(t)))
                .unwrap_or_default(),
            dot_str(&c.label),
            if c.service {
                ", style=dashed, dir=none"
            } else {
                ""
            }
        );
    }
    s.push_str("}\n");
    s
}

/// Node `n<i>` of the DOT graph: instance `it` as an HTML-like table, its name and component
/// on top, in-ports left and other ports right (each a `port` of the table); a composite inside
/// a second outline, a member dashed.
fn dot_node(s: &mut String, i: usize, it: &WireInstance) {
    let left: Vec<usize> = (0..it.ports.len())
        .filter(|&k| it.ports[k].class == "in")
        .collect();
    let right: Vec<usize> = (0..it.ports.len())
        .filter(|&k| it.ports[k].class != "in")
        .collect();
    // A composite: its table inside a second outline; a member: a dashed outline.
    let dashed = if it.role.member {
        " style=\"dashed\""
    } else {
        ""
    };
    let _ = write!(s, "  n{i} [label=<");
    if it.role.composite {
        let _ = write!(
            s,
            "<table border=\"1\" cellborder=\"0\" cellspacing=\"2\" cellpadding=\"0\"{dashed}><tr><td border=\"1\">"
        );
    }
    let _ = write!(
        s,
        "<table border=\"{}\" cellborder=\"0\" cellspacing=\"0\" cellpadding=\"3\"{}><tr><td colspan=\"2\"><b>{}</b>",
        if it.role.composite { "0" } else { "1" },
        if it.role.composite { "" } else { dashed },
        // An empty `<b></b>` is a syntax error to Graphviz.
        if it.name.is_empty() {
            " ".to_string()
        } else {
            dot_html(&it.name)
        }
    );
    if !it.component.is_empty() {
        let _ = write!(
            s,
            "<br/><font point-size=\"9\">{}</font>",
            dot_html(&it.component)
        );
    }
    s.push_str("</td></tr>");
    for r in 0..left.len().max(right.len()) {
        s.push_str("<tr>");
        for (list, align) in [(&left, "left"), (&right, "right")] {
            match list.get(r) {
                Some(&k) => {
                    let p = &it.ports[k];
                    let mark = match p.class {
                        "in" => "▶ ",
                        "service" => "◯ ",
                        _ => "",
                    };
                    let name = if p.unknown {
                        format!("<i>{}</i> ?", dot_html(&p.name))
                    } else {
                        dot_html(&p.name)
                    };
                    let _ = write!(
                        s,
                        "<td port=\"p{k}\" align=\"{align}\">{}{}{}</td>",
                        if align == "left" { mark } else { "" },
                        name,
                        if align == "right" && p.class == "out" {
                            " ▶"
                        } else if align == "right" && p.class == "service" {
                            " ◯"
                        } else {
                            ""
                        }
                    );
                }
                None => s.push_str("<td></td>"),
            }
        }
        s.push_str("</tr>");
    }
    s.push_str("</table>");
    if it.role.composite {
        s.push_str("</td></tr></table>");
    }
    s.push_str(">];\n");
}

/// Escapes text for a quoted Mermaid label: Mermaid's entity codes for the characters that
/// would end the label or be read as markup.
fn mermaid_str(s: &str) -> String {
    escape_with(
        s,
        &[
            ('#', "#35;"),
            ('"', "#quot;"),
            ('<', "#lt;"),
            ('>', "#gt;"),
            ('&', "#amp;"),
        ],
    )
}

/// The wiring as a Mermaid flowchart (`flowchart LR`): each instance a node named by the
/// instance and its component, each data connector an arrow labelled `out → in`, each service
/// connector a dotted line labelled with its two ports (or either with its caption). Mermaid
/// has no ports: the labels carry them. `not_drawn` (the connectors left out, and why) are
/// comments: Mermaid has no caption; the page that shows the block says them.
pub fn to_mermaid(
    name: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
    not_drawn: &[String],
) -> String {
    let mut s = String::from("flowchart LR\n");
    let _ = writeln!(s, "  %% {}", name.replace(['\n', '\r'], " "));
    for n in not_drawn {
        let _ = writeln!(s, "  %% {}", n.replace(['\n', '\r'], " "));
    }
    for (i, it) in inst.iter().enumerate() {
        let label = if it.component.is_empty() {
            mermaid_str(&it.name)
        } else {
            format!(
                "{}<br/><small>{}</small>",
                mermaid_str(&it.name),
                mermaid_str(&it.component)
            )
        };
        // A composite a subroutine node (double lines at its sides).
        let (open, close) = if it.role.composite {
            ("[[", "]]")
        } else {
            ("[", "]")
        };
        let _ = writeln!(s, "  n{i}{open}\"{label}\"{close}");
    }
    // A member's node a dashed outline.
    let members: Vec<String> = (0..inst.len())
        .filter(|&i| inst[i].role.member)
        .map(|i| format!("n{i}"))
        .collect();
    if !members.is_empty() {
        let _ = writeln!(s, "  classDef member stroke-dasharray:6 3");
        let _ = writeln!(s, "  class {} member", members.join(","));
    }
    for c in conns {
        let (Some(a), Some(b)) = (inst.get(c.from.0), inst.get(c.to.0)) else {
            continue;
        };
        let (Some(pa), Some(pb)) = (a.ports.get(c.from.1), b.ports.get(c.to.1)) else {
            continue;
        };
        // A service connector a dotted line, a data connector an arrow.
        let (open, between, close) = if c.service {
            ("-.", "—", ".-")
        } else {
            ("--", "→", "-->")
        };
        let text = match &c.caption {
            Some(t) => mermaid_str(t),
            None => format!(
                "{} {between} {}",
                mermaid_str(&pa.name),
                mermaid_str(&pb.name)
            ),
        };
        let _ = writeln!(s, "  n{} {open} \"{text}\" {close} n{}", c.from.0, c.to.0);
    }
    s
}

/// The catalogue's data flow between groups (`rows`, heaviest first) as instances and
/// connectors to draw or export: with `caps` (groups, flows), the groups with the most port
/// pairs between groups and the heaviest flows between those, and how many groups and
/// flows that leaves out; without (the export), every group and every flow, a flow within one
/// group too (from the group's out-port to its own in-port). Each group has an out-port and an
/// in-port as needed, one connector per flow.
pub fn dataflow_wiring(
    rows: &[crate::render::facts::FlowRow<'_>],
    lang: Lang,
    href: &dyn Fn(&crate::catalog::Page) -> String,
    caps: Option<(usize, usize)>,
) -> (Vec<WireInstance>, Vec<WireConnector>, usize, usize) {
    use crate::render::facts::FlowRow;
    use std::collections::BTreeMap;
    let (max_groups, max_flows) = caps.unwrap_or((usize::MAX, usize::MAX));
    // The drawing on the page shows the flows between groups (its table lists them all).
    let between: Vec<&FlowRow<'_>> = rows
        .iter()
        .filter(|r| caps.is_none() || r.from.1 != r.to.1)
        .collect();
    let mut weight: BTreeMap<&str, (u64, &str)> = BTreeMap::new();
    for r in &between {
        let ends = if r.from.1 == r.to.1 { 1 } else { 2 };
        for (name, page) in [&r.from, &r.to].into_iter().take(ends) {
            weight.entry(page.stem.as_str()).or_insert((0, name)).0 += r.pairs;
        }
    }
    let mut groups: Vec<(&str, u64, &str)> =
        weight.iter().map(|(s, (w, n))| (*s, *w, *n)).collect();
    groups.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
    let not_drawn = groups.len().saturating_sub(max_groups);
    groups.truncate(max_groups);
    groups.sort_by(|a, b| a.0.cmp(b.0));
    let index: BTreeMap<&str, usize> = groups.iter().enumerate().map(|(i, g)| (g.0, i)).collect();
    let mut inst: Vec<WireInstance> = groups
        .iter()
        .map(|(stem, _, name)| {
            let page = rows
                .iter()
                .flat_map(|r| [r.from.1, r.to.1])
                .find(|p| p.stem == *stem);
            WireInstance {
                name: name.to_string(),
                component: String::new(),
                href: page.map(href).unwrap_or_default(),
                label: name.to_string(),
                ports: Vec::new(),
                location: None,
                role: Role::default(),
            }
        })
        .collect();
    // Ports: "out" for a group that feeds another, "in" for one that is fed.
    let port = |inst: &mut Vec<WireInstance>, i: usize, class: &'static str| -> usize {
        if let Some(p) = inst[i].ports.iter().position(|p| p.class == class) {
            return p;
        }
        let kind = lang.t(if class == "in" {
            "sys_in_port"
        } else {
            "sys_out_port"
        });
        let label = format!("{} {kind}", inst[i].name);
        inst[i].ports.push(WirePort {
            name: class.to_string(),
            class,
            href: String::new(),
            label,
            unknown: false,
        });
        inst[i].ports.len() - 1
    };
    let mut conns = Vec::new();
    // `rows` come heaviest first: the flows between drawn groups, up to the cap.
    let drawn: Vec<(&FlowRow<'_>, usize, usize)> = between
        .iter()
        .filter_map(|r| {
            Some((
                *r,
                *index.get(r.from.1.stem.as_str())?,
                *index.get(r.to.1.stem.as_str())?,
            ))
        })
        .collect();
    let flows_not_drawn = between.len() - drawn.len().min(max_flows);
    for (r, a, b) in drawn.into_iter().take(max_flows) {
        let (pa, pb) = (port(&mut inst, a, "out"), port(&mut inst, b, "in"));
        let types: Vec<&str> = r.types.iter().map(|(n, _)| *n).collect();
        // `3 port pairs (RTC::TimedLong, +2)`: what the edge carries.
        let caption = format!(
            "{} ({}{})",
            lang.count(r.pairs, "dataflow_pair_count"),
            types.join(", "),
            if r.more_types > 0 {
                format!(", +{}", r.more_types)
            } else {
                String::new()
            }
        );
        conns.push(WireConnector {
            from: (a, pa),
            to: (b, pb),
            service: false,
            label: format!("{} → {}: {caption}", r.from.0, r.to.0),
            caption: Some(caption),
        });
    }
    // A group whose flows were all left out is not drawn either.
    let used: Vec<bool> = (0..inst.len())
        .map(|i| conns.iter().any(|c| c.from.0 == i || c.to.0 == i))
        .collect();
    let mut renumber = vec![0; inst.len()];
    let mut kept = Vec::new();
    for (i, g) in inst.into_iter().enumerate() {
        if used[i] {
            renumber[i] = kept.len();
            kept.push(g);
        }
    }
    let not_drawn = not_drawn + used.iter().filter(|u| !**u).count();
    for c in &mut conns {
        c.from.0 = renumber[c.from.0];
        c.to.0 = renumber[c.to.0];
    }
    (kept, conns, not_drawn, flows_not_drawn)
}
