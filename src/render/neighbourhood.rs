//! What every output shows of a component's neighbourhood ([`Catalog::neighbourhood`]): the
//! list, grouped by port ([`rows`]), and the drawing as a wiring ([`wiring`]) that the HTML
//! page draws like a system diagram and `rtcdoc graph --component` writes as DOT, Mermaid or
//! SVG. Each format's code stays thin: it links and escapes, nothing more.

use crate::catalog::neighbourhood::{Neighbourhood, PortAt, PEER_COMPONENTS_CAP};
use crate::catalog::{Catalog, ComponentIx, Page, TypeIx};
use crate::i18n::Lang;
use crate::model::non_empty;
use crate::render::wiring::{Role, WireConnector, WireInstance, WirePort};

/// One neighbour component of a port, as listed.
pub struct NeighbourItem<'a> {
    /// The neighbouring component.
    pub component: ComponentIx,
    /// Its name as shown (with what tells same-named components apart).
    pub name: String,
    pub page: &'a Page,
    /// The anchor of its first matching port on its page.
    pub anchor: &'a str,
    /// Its matching ports' names (`port.interface` for a service interface, as the port tables write it).
    pub ports: Vec<String>,
}

/// One port of the component and its neighbours, as listed.
pub struct NeighbourRow<'a> {
    /// The port's name (`port.interface` for a service interface, as the port tables write it).
    pub port: String,
    /// The port's anchor on the component's page.
    pub anchor: &'a str,
    /// The data type or interface, and its page (which lists every neighbour).
    pub type_name: &'a str,
    pub type_page: &'a Page,
    pub neighbours: Vec<NeighbourItem<'a>>,
    /// Neighbour components counted but not named.
    pub more: usize,
    pub upstream: bool,
    pub service: bool,
    /// The neighbours' ports, as [`Catalog::neighbourhood`] found them (for the drawing).
    ports_at: Vec<Vec<PortAt>>,
    at: PortAt,
}

impl NeighbourRow<'_> {
    /// The relation's label key: `nb_fed_by`, `nb_feeds`, `nb_used_by` or `nb_uses`.
    pub fn relation(&self) -> &'static str {
        match (self.service, self.upstream) {
            (false, true) => "nb_fed_by",
            (false, false) => "nb_feeds",
            (true, true) => "nb_used_by",
            (true, false) => "nb_uses",
        }
    }

    /// Where the neighbours not named are all listed: `more_on_interface_page` or
    /// `more_on_type_page`.
    pub fn more_key(&self) -> &'static str {
        if self.service {
            "more_on_interface_page"
        } else {
            "more_on_type_page"
        }
    }
}

/// The name of a port of component `ci` as listed.
fn port_name(cat: &Catalog, ci: ComponentIx, at: PortAt) -> String {
    let p = &cat[ci].profile;
    match at {
        PortAt::Data(k) => non_empty(&p.data_ports[k].name).unwrap_or("").to_string(),
        PortAt::Interface(s, i) => {
            let sp = &p.service_ports[s];
            format!(
                "{}.{}",
                non_empty(&sp.name).unwrap_or(""),
                non_empty(&sp.interfaces[i].name).unwrap_or("")
            )
        }
    }
}

/// The anchor of a port of component `ci` on its page.
fn port_anchor(cat: &Catalog, ci: ComponentIx, at: PortAt) -> &str {
    let a = &cat[ci].anchors;
    match at {
        PortAt::Data(k) => &a.data_ports[k],
        PortAt::Interface(s, i) => &a.interfaces[s][i],
    }
}

/// The neighbourhood of component `ci`, at most [`PEER_COMPONENTS_CAP`] neighbours per port.
pub fn neighbourhood(cat: &Catalog, ci: ComponentIx) -> Neighbourhood {
    cat.neighbourhood(ci, PEER_COMPONENTS_CAP)
}

/// The neighbourhood `n` of component `ci` as a list grouped by port, in port order.
pub fn rows<'a>(cat: &'a Catalog, ci: ComponentIx, n: &Neighbourhood) -> Vec<NeighbourRow<'a>> {
    n.ports
        .iter()
        .map(|pn| {
            let service = pn.is_service();
            let type_name = match pn.type_ {
                TypeIx::Interface(i) => cat[i].name.as_str(),
                TypeIx::Data(i) => cat[i].name.as_str(),
            };
            let type_page = cat.type_page(pn.type_);
            NeighbourRow {
                port: port_name(cat, ci, pn.port),
                anchor: port_anchor(cat, ci, pn.port),
                type_name,
                type_page,
                neighbours: pn
                    .shown
                    .iter()
                    .map(|nb| NeighbourItem {
                        component: nb.component,
                        name: cat[nb.component].display_name().into_owned(),
                        page: cat.component_page(nb.component),
                        anchor: nb
                            .ports
                            .first()
                            .map_or("", |&at| port_anchor(cat, nb.component, at)),
                        ports: nb
                            .ports
                            .iter()
                            .map(|&at| port_name(cat, nb.component, at))
                            .collect(),
                    })
                    .collect(),
                more: pn.more(),
                upstream: pn.upstream,
                service,
                ports_at: pn.shown.iter().map(|nb| nb.ports.clone()).collect(),
                at: pn.port,
            }
        })
        .collect()
}

/// The text of a row's "+N more" entry: `+12 — see all on the type page`.
pub fn more_text(row: &NeighbourRow<'_>, lang: Lang) -> String {
    format!("+{} — {}", row.more, lang.t(row.more_key()))
}

/// The drawn name of a port: a data port's name, a service port's name (its interfaces meet
/// on it, as in a system diagram).
fn drawn_port(cat: &Catalog, ci: ComponentIx, at: PortAt) -> (String, &'static str, &str) {
    let p = &cat[ci].profile;
    let a = &cat[ci].anchors;
    match at {
        PortAt::Data(k) => {
            let port = &p.data_ports[k];
            let class = match port.direction() {
                Some(crate::model::PortDirection::In) => "in",
                Some(crate::model::PortDirection::Out) => "out",
                _ => "other",
            };
            (
                non_empty(&port.name).unwrap_or("").to_string(),
                class,
                &a.data_ports[k],
            )
        }
        PortAt::Interface(s, _) => (
            non_empty(&p.service_ports[s].name)
                .unwrap_or("")
                .to_string(),
            "service",
            &a.service_ports[s],
        ),
    }
}

/// The port `name` of `inst` (added when new).
fn port_of(
    inst: &mut WireInstance,
    name: String,
    class: &'static str,
    href: String,
    label: String,
) -> usize {
    if let Some(k) = inst
        .ports
        .iter()
        .position(|p| p.name == name && p.class == class)
    {
        return k;
    }
    inst.ports.push(WirePort {
        name,
        class,
        href,
        label,
        unknown: false,
    });
    inst.ports.len() - 1
}

/// The neighbourhood of component `ci` (its [`rows`]) as a wiring to draw or export: the
/// component first, then one box per neighbour component (a component met on several ports is
/// one box) and one "+N more" box per capped port, linked to the type or interface page.
/// Data connectors run from out-port to in-port, labelled `A.out → B.in (type)`; service
/// connectors join the service ports. `href(page, anchor)` makes a link (empty: none).
pub fn wiring(
    cat: &Catalog,
    ci: ComponentIx,
    rows: &[NeighbourRow<'_>],
    lang: Lang,
    href: &dyn Fn(&Page, Option<&str>) -> String,
) -> (Vec<WireInstance>, Vec<WireConnector>) {
    let me = cat[ci].display_name().into_owned();
    let mut inst = vec![WireInstance {
        label: me.clone(),
        name: me.clone(),
        component: String::new(),
        href: href(cat.component_page(ci), None),
        ports: Vec::new(),
        location: None,
        role: Role::default(),
    }];
    let mut conns: Vec<WireConnector> = Vec::new();
    let kind = |class: &str| match class {
        "in" => lang.t("sys_in_port"),
        "out" => lang.t("sys_out_port"),
        "service" => lang.t("sys_service_port"),
        _ => lang.t("port"),
    };
    let mut box_of: Vec<(ComponentIx, usize)> = Vec::new();
    for row in rows {
        let (mine, class, anchor) = drawn_port(cat, ci, row.at);
        let label = [kind(class), " ", &me, ".", &mine].concat();
        let link = href(cat.component_page(ci), Some(anchor));
        let mp = port_of(&mut inst[0], mine.clone(), class, link, label);
        let connect =
            |inst: &[WireInstance], b: usize, bp: usize, conns: &mut Vec<WireConnector>| {
                let theirs = (b, bp);
                let (from, to) = if row.upstream {
                    (theirs, (0, mp))
                } else {
                    ((0, mp), theirs)
                };
                if conns.iter().any(|c| c.from == from && c.to == to) {
                    return;
                }
                conns.push(connector(inst, from, to, row));
            };
        for (nb, ports) in row.neighbours.iter().zip(&row.ports_at) {
            let b = match box_of.iter().find(|(k, _)| *k == nb.component) {
                Some(&(_, b)) => b,
                None => {
                    inst.push(WireInstance {
                        label: nb.name.clone(),
                        name: nb.name.clone(),
                        component: String::new(),
                        href: href(nb.page, None),
                        ports: Vec::new(),
                        location: None,
                        role: Role::default(),
                    });
                    box_of.push((nb.component, inst.len() - 1));
                    inst.len() - 1
                }
            };
            for &at in ports {
                let (theirs, class, anchor) = drawn_port(cat, nb.component, at);
                let label = [kind(class), " ", &nb.name, ".", &theirs].concat();
                let link = href(nb.page, Some(anchor));
                let bp = port_of(&mut inst[b], theirs, class, link, label);
                connect(&inst, b, bp, &mut conns);
            }
        }
        if row.more > 0 {
            let name = format!("+{} {}", row.more, lang.t("nb_more"));
            let class = match (row.service, row.upstream) {
                (true, _) => "service",
                (false, true) => "out",
                (false, false) => "in",
            };
            inst.push(WireInstance {
                // The accessible name starts with the box's visible text (WCAG 2.5.3).
                label: format!("{name} {} — {}", row.type_name, lang.t(row.more_key())),
                component: row.type_name.to_string(),
                href: href(row.type_page, None),
                ports: vec![WirePort {
                    name: String::new(),
                    class,
                    href: String::new(),
                    label: format!("{name} ({})", row.type_name),
                    unknown: false,
                }],
                name,
                location: None,
                role: Role::default(),
            });
            let b = inst.len() - 1;
            connect(&inst, b, 0, &mut conns);
        }
    }
    place_in_columns(&mut inst, &conns);
    (inst, conns)
}

/// The connector from port `from` to port `to` (box, port) of `row`: labelled
/// `A.out → B.in (type)` (`—` between service ports), its exported edge `out → in (type)`.
fn connector(
    inst: &[WireInstance],
    from: (usize, usize),
    to: (usize, usize),
    row: &NeighbourRow<'_>,
) -> WireConnector {
    let (f, t) = (&inst[from.0], &inst[to.0]);
    let (a, b) = (&f.ports[from.1].name, &t.ports[to.1].name);
    let between = if row.service { " — " } else { " → " };
    let of = [" (", row.type_name, ")"].concat();
    // The "+N more" box has one nameless port: its end is the box's name alone.
    let end = |name: &str, port: &str| match port {
        "" => name.to_string(),
        _ => [name, ".", port].concat(),
    };
    let short = |name: &str, port: &str| (if port.is_empty() { name } else { port }).to_string();
    WireConnector {
        from,
        to,
        service: row.service,
        label: [end(&f.name, a), between.into(), end(&t.name, b), of.clone()].concat(),
        caption: Some([short(&f.name, a), between.into(), short(&t.name, b), of].concat()),
    }
}

/// Fixes the arrangement the layout keeps (as it keeps RTSystemEditor's saved positions): the
/// component in the middle column, a neighbour on the left when its first connector feeds the
/// component and on the right otherwise, each column in the order met. Cheaper than the layered
/// layout's ordering sweeps (every component page draws one) and the same picture every time.
fn place_in_columns(inst: &mut [WireInstance], conns: &[WireConnector]) {
    let mut rows = [0i64; 3];
    for (i, it) in inst.iter_mut().enumerate() {
        let col: usize = if i == 0 {
            1
        } else {
            match conns.iter().find(|c| c.from.0 == i || c.to.0 == i) {
                // Feeds the component (data), or uses its provided interface.
                Some(c) if c.from.0 == i => 0,
                _ => 2,
            }
        };
        it.location = Some((col as i64 * 1000, rows[col] * 40));
        rows[col] += 1;
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_intro_states_the_cap_in_use() {
        for lang in [crate::i18n::Lang::En, crate::i18n::Lang::Ja] {
            let cap = super::PEER_COMPONENTS_CAP.to_string();
            assert!(lang.t("neighbourhood_intro").contains(&cap));
        }
    }
}
