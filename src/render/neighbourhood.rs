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

/// At most this many neighbour components are drawn, the closest (the most port pairs) first;
/// the others are counted in a "+N more" box and named in the list beside the drawing.
pub const NEIGHBOURS_DRAWN: usize = 8;

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

/// One edge of the drawing: every port pair between the component and one neighbour in one
/// direction, of one kind (data or service).
struct Bundle<'r, 'a> {
    nb: &'r NeighbourItem<'a>,
    upstream: bool,
    service: bool,
    pairs: usize,
    /// The component's ports and the neighbour's, each once, in the order met.
    mine: Vec<PortAt>,
    theirs: Vec<PortAt>,
    types: Vec<&'a str>,
}

/// An end of the component's box that edges meet: (upstream, service, towards the left
/// column). Data from the left meets the in-port end on the left side; data to the right
/// leaves the out-port end on the right; data from a neighbour on the right (one that is also
/// fed) meets an in-port end on the right side, so that the two edges between them run side
/// by side instead of around the drawing.
type End = (bool, bool, bool);

/// A port's class for its colour and side: data ports on their usual side (`in`, `out`), or
/// facing their partner (`in facing`, `out facing`: the layout puts a port of an unknown kind
/// on the side of its partners, the style colours it by its first class).
fn end_class((upstream, service, left): End, own: bool) -> &'static str {
    match (service, upstream == own, left || !upstream) {
        (true, _, _) => "service",
        (false, true, true) => "in",
        (false, true, false) => "in facing",
        (false, false, true) => "out",
        (false, false, false) => "out facing",
    }
}

/// The rows' port pairs bundled by (neighbour, direction, kind), in the order met.
fn bundles<'r, 'a>(rows: &'r [NeighbourRow<'a>]) -> Vec<Bundle<'r, 'a>> {
    let mut out: Vec<Bundle<'r, 'a>> = Vec::new();
    for row in rows {
        for (nb, ports) in row.neighbours.iter().zip(&row.ports_at) {
            let k = match out.iter().position(|b| {
                b.nb.component == nb.component
                    && b.upstream == row.upstream
                    && b.service == row.service
            }) {
                Some(k) => k,
                None => {
                    out.push(Bundle {
                        nb,
                        upstream: row.upstream,
                        service: row.service,
                        pairs: 0,
                        mine: Vec::new(),
                        theirs: Vec::new(),
                        types: Vec::new(),
                    });
                    out.len() - 1
                }
            };
            let b = &mut out[k];
            b.pairs += ports.len();
            if !b.mine.contains(&row.at) {
                b.mine.push(row.at);
            }
            for &at in ports {
                if !b.theirs.contains(&at) {
                    b.theirs.push(at);
                }
            }
            if !b.types.contains(&row.type_name) {
                b.types.push(row.type_name);
            }
        }
    }
    out
}

/// The neighbours to draw: the [`NEIGHBOURS_DRAWN`] with the most port pairs (the first met
/// among equals), in that order; and the others, in the order met.
fn closest(bundles: &[Bundle<'_, '_>]) -> (Vec<ComponentIx>, Vec<ComponentIx>) {
    let mut pairs: Vec<(ComponentIx, usize)> = Vec::new();
    for b in bundles {
        match pairs.iter_mut().find(|(c, _)| *c == b.nb.component) {
            Some((_, n)) => *n += b.pairs,
            None => pairs.push((b.nb.component, b.pairs)),
        }
    }
    let mut ranked = pairs.clone();
    // A stable sort: equals keep the order met.
    ranked.sort_by_key(|b| std::cmp::Reverse(b.1));
    ranked.truncate(NEIGHBOURS_DRAWN);
    let drawn: Vec<ComponentIx> = ranked.into_iter().map(|(c, _)| c).collect();
    let left_out = pairs
        .into_iter()
        .map(|(c, _)| c)
        .filter(|c| !drawn.contains(c))
        .collect();
    (drawn, left_out)
}

/// A box of the drawing besides the component's.
enum Item<'b, 'r, 'a> {
    /// A neighbour drawn, with its bundles.
    Neighbour(Vec<&'b Bundle<'r, 'a>>),
    /// A "+N more" box: the end it joins, how many, and the type and its page whose list is
    /// capped, or none (neighbours the list names and the drawing leaves out).
    More(End, usize, Option<(&'a str, &'a Page)>),
}

impl Item<'_, '_, '_> {
    fn on_left(&self) -> bool {
        match self {
            Item::Neighbour(bs) => bs.iter().all(|b| b.upstream),
            Item::More(end, _, _) => end.2,
        }
    }
}

/// The boxes to draw: the closest neighbours (those joined by data one way first, then those
/// both feeding the component and fed by it, then those joined by services), then the
/// "+N more" boxes: one per side for
/// the neighbours the list names and the drawing leaves out, and one per type, direction and
/// kind whose list is capped.
fn items<'b, 'r, 'a>(
    rows: &[NeighbourRow<'a>],
    all: &'b [Bundle<'r, 'a>],
) -> (Vec<Item<'b, 'r, 'a>>, Vec<(End, Vec<PortAt>)>) {
    let (drawn, left_out) = closest(all);
    let of = |c: &ComponentIx| -> Vec<&'b Bundle<'r, 'a>> {
        all.iter().filter(|b| b.nb.component == *c).collect()
    };
    let mut items: Vec<Item<'b, 'r, 'a>> = drawn.iter().map(|c| Item::Neighbour(of(c))).collect();
    // Stable: the closest first within each kind. In the order of the component's ends on
    // that side (data one way, data both ways, services), so that their edges need not cross.
    items.sort_by_key(|it| match it {
        Item::Neighbour(bs) if bs.iter().all(|b| b.service) => 2,
        Item::Neighbour(bs) => {
            usize::from(bs.iter().any(|b| b.upstream) && bs.iter().any(|b| !b.upstream))
        }
        Item::More(..) => 3,
    });
    // Every end the boxes meet, with the component's ports gathered there.
    let mut ends: Vec<(End, Vec<PortAt>)> = Vec::new();
    let mut meet = |end: End, ports: &[PortAt]| {
        let k = match ends.iter().position(|(e, _)| *e == end) {
            Some(k) => k,
            None => {
                ends.push((end, Vec::new()));
                ends.len() - 1
            }
        };
        for p in ports {
            if !ends[k].1.contains(p) {
                ends[k].1.push(*p);
            }
        }
    };
    for it in &items {
        if let Item::Neighbour(bs) = it {
            let left = it.on_left();
            for b in bs {
                meet((b.upstream, b.service, left), &b.mine);
            }
        }
    }
    let mut more = Vec::new();
    for side_left in [true, false] {
        let out: Vec<Vec<&Bundle<'r, 'a>>> = left_out
            .iter()
            .map(of)
            .filter(|bs| bs.iter().all(|b| b.upstream) == side_left)
            .collect();
        let Some(first) = out.first().map(|bs| bs[0]) else {
            continue;
        };
        let end = (first.upstream, first.service, side_left);
        meet(end, &first.mine);
        more.push(Item::More(end, out.len(), None));
    }
    for r in rows.iter().filter(|r| r.more > 0) {
        let end = (r.upstream, r.service, r.upstream);
        let same = |it: &Item<'_, '_, '_>| matches!(it, Item::More(e, _, Some((t, _))) if *e == end && *t == r.type_name);
        if !more.iter().any(same) {
            meet(end, &[r.at]);
            more.push(Item::More(end, r.more, Some((r.type_name, r.type_page))));
        }
    }
    ends.sort_by_key(|(e, _)| (e.1, !e.0, !e.2));
    items.extend(more);
    (items, ends)
}

/// The component's box: one port per end its edges meet ([`End`]), named by its own port when
/// the end gathers one and by their number otherwise (`3 ports`); for each end, its single
/// port's name (`None` for several), which the connectors' labels name.
fn own_box(
    cat: &Catalog,
    ci: ComponentIx,
    ends: &[(End, Vec<PortAt>)],
    lang: Lang,
    href: &dyn Fn(&Page, Option<&str>) -> String,
) -> (WireInstance, Vec<(End, usize, Option<String>)>) {
    let me = cat[ci].display_name().into_owned();
    let page = cat.component_page(ci);
    let mut inst = WireInstance {
        label: me.clone(),
        name: me.clone(),
        component: String::new(),
        href: href(page, None),
        ports: Vec::new(),
        location: None,
        role: Role::default(),
    };
    let mut out = Vec::new();
    for (end, ports) in ends {
        let mut names: Vec<(String, &'static str, &str)> = Vec::new();
        for &at in ports {
            let d = drawn_port(cat, ci, at);
            if !names.iter().any(|n| n.0 == d.0) {
                names.push(d);
            }
        }
        let Some(first) = names.first() else {
            continue;
        };
        let class = end_class(*end, true);
        let kind = lang.t(match (end.1, end.0) {
            (true, _) => "sys_service_port",
            (false, true) => "sys_in_port",
            (false, false) => "sys_out_port",
        });
        let list: Vec<&str> = names.iter().map(|n| n.0.as_str()).collect();
        let (name, link, single) = if names.len() == 1 {
            let link = href(page, Some(first.2));
            (first.0.clone(), link, Some(first.0.clone()))
        } else {
            let section = if end.1 { "service-ports" } else { "data-ports" };
            let count = lang.count(names.len() as u64, "nb_port_count");
            (count, href(page, Some(section)), None)
        };
        // The accessible name holds the visible text (`3 ports`), then the ports (WCAG 2.5.3).
        let label = if single.is_some() {
            format!("{kind} {me}: {name}")
        } else {
            format!("{kind} {me}: {name} ({})", list.join(", "))
        };
        inst.ports.push(WirePort {
            name,
            class,
            href: link,
            label,
            unknown: false,
        });
        out.push((*end, inst.ports.len() - 1, single));
    }
    (inst, out)
}

/// The neighbourhood of component `ci` (its [`rows`]) as a wiring to draw or export: the
/// component first, with one port per [`End`]; then the [`NEIGHBOURS_DRAWN`] closest
/// neighbours, each one box with one edge per direction and kind that bundles all their port
/// pairs, labelled with their number (`12 port pairs`) or, for a single pair, with the two
/// ports; a "+N more" box for the neighbours the list names and the drawing leaves out; and a
/// "+N more" box per type and direction whose list is capped, linked to the type or interface
/// page. A neighbour that only feeds the component (or uses its provided interface) is on the
/// left; the others, also those that both feed it and are fed by it, on the right.
/// `href(page, anchor)` makes a link (empty: none).
pub fn wiring(
    cat: &Catalog,
    ci: ComponentIx,
    rows: &[NeighbourRow<'_>],
    lang: Lang,
    href: &dyn Fn(&Page, Option<&str>) -> String,
) -> (Vec<WireInstance>, Vec<WireConnector>) {
    let all = bundles(rows);
    let (items, ends) = items(rows, &all);
    let (me_box, ends) = own_box(cat, ci, &ends, lang, href);
    let me = me_box.name.clone();
    let end_of = |e: End| ends.iter().find(|(k, _, _)| *k == e);
    let mut inst = vec![me_box];
    let mut conns: Vec<WireConnector> = Vec::new();
    let mut left = vec![false];
    for it in &items {
        let on_left = it.on_left();
        let at = inst.len();
        let mut b = match it {
            Item::Neighbour(bs) => WireInstance {
                label: bs[0].nb.name.clone(),
                name: bs[0].nb.name.clone(),
                component: String::new(),
                href: href(bs[0].nb.page, None),
                ports: Vec::new(),
                location: None,
                role: Role::default(),
            },
            Item::More(end, n, typed) => {
                more_box(cat.component_page(ci), (*end, *n, *typed), lang, href)
            }
        };
        let ends_here: Vec<(End, Option<&Bundle<'_, '_>>)> = match it {
            Item::Neighbour(bs) => bs
                .iter()
                .map(|x| ((x.upstream, x.service, on_left), Some(*x)))
                .collect(),
            Item::More(end, _, _) => vec![(*end, None)],
        };
        for (end, bundle) in ends_here {
            let Some((_, mp, single)) = end_of(end) else {
                continue;
            };
            let conn = match bundle {
                Some(x) => {
                    b.ports.push(bundle_port(cat, x, end, lang, href));
                    bundle_connector(cat, x, (&me, single.as_deref()), lang)
                }
                None => more_connector(&b, end, (&me, single.as_deref())),
            };
            let theirs = (at, b.ports.len() - 1);
            let (from, to) = if end.0 {
                (theirs, (0, *mp))
            } else {
                ((0, *mp), theirs)
            };
            conns.push(WireConnector { from, to, ..conn });
        }
        left.push(on_left);
        inst.push(b);
    }
    place_in_columns(&mut inst, &left);
    (inst, conns)
}

/// A neighbour's port for one bundle: its own port's name for a single pair, the number of
/// pairs otherwise; linked to its first port.
fn bundle_port(
    cat: &Catalog,
    b: &Bundle<'_, '_>,
    end: End,
    lang: Lang,
    href: &dyn Fn(&Page, Option<&str>) -> String,
) -> WirePort {
    let (first, _, anchor) = drawn_port(cat, b.nb.component, b.theirs[0]);
    let names: Vec<String> = b
        .theirs
        .iter()
        .map(|&at| drawn_port(cat, b.nb.component, at).0)
        .collect();
    let name = if b.pairs == 1 {
        first
    } else {
        lang.count(b.pairs as u64, "dataflow_pair_count")
    };
    WirePort {
        label: format!("{} {}: {}", b.nb.name, name, names.join(", ")),
        name,
        class: end_class(end, false),
        href: href(b.nb.page, Some(anchor)),
        unknown: false,
    }
}

/// The connector of a bundle (its ends are set by the caller): `A.out → B.in (type)` for a
/// single pair (`—` between service ports), `A → B: 12 port pairs (types)` otherwise; `mine`
/// is the component's name and its port at that end when the end gathers one.
fn bundle_connector(
    cat: &Catalog,
    b: &Bundle<'_, '_>,
    (me, mine): (&str, Option<&str>),
    lang: Lang,
) -> WireConnector {
    let between = if b.service { " — " } else { " → " };
    let of = [" (", &b.types.join(", "), ")"].concat();
    let (label, caption) = if b.pairs == 1 {
        let theirs = drawn_port(cat, b.nb.component, b.theirs[0]).0;
        let mine = mine.unwrap_or("");
        let (f, fp, t, tp) = if b.upstream {
            (b.nb.name.as_str(), theirs.as_str(), me, mine)
        } else {
            (me, mine, b.nb.name.as_str(), theirs.as_str())
        };
        (
            [f, ".", fp, between, t, ".", tp, &of].concat(),
            [fp, between, tp, &of].concat(),
        )
    } else {
        let (f, t) = if b.upstream {
            (b.nb.name.as_str(), me)
        } else {
            (me, b.nb.name.as_str())
        };
        let count = lang.count(b.pairs as u64, "dataflow_pair_count");
        (
            [f, between, t, ": ", &count, &of].concat(),
            [count, of].concat(),
        )
    };
    WireConnector {
        from: (0, 0),
        to: (0, 0),
        service: b.service,
        label,
        caption: Some(caption),
    }
}

/// A "+N more" box: `n` neighbours of a capped list of `typed` (linked to its page), or, when
/// `typed` is none, named in the list and left out of the drawing (linked to the list on the
/// component's page `own`); its one nameless port meets `end`.
fn more_box(
    own: &Page,
    (end, n, typed): (End, usize, Option<(&str, &Page)>),
    lang: Lang,
    href: &dyn Fn(&Page, Option<&str>) -> String,
) -> WireInstance {
    let name = format!("+{n} {}", lang.t("nb_more"));
    // The accessible name starts with the box's visible text (WCAG 2.5.3).
    let (subtitle, label, port_label, link) = match typed {
        Some((t, page)) => {
            let k = if end.1 {
                "more_on_interface_page"
            } else {
                "more_on_type_page"
            };
            (
                t.to_string(),
                format!("{name} {t} — {}", lang.t(k)),
                format!("{name} ({t})"),
                href(page, None),
            )
        }
        None => {
            let listed = lang.t("nb_more_listed");
            (
                listed.to_string(),
                format!("{name} {listed}"),
                name.clone(),
                href(own, Some("neighbourhood")),
            )
        }
    };
    WireInstance {
        label,
        component: subtitle,
        href: link,
        ports: vec![WirePort {
            name: String::new(),
            class: end_class(end, false),
            href: String::new(),
            label: port_label,
            unknown: false,
        }],
        name,
        location: None,
        role: Role::default(),
    }
}

/// The connector of a "+N more" box `b` at `end` (its ends are set by the caller): it names
/// the box alone, without a port after it, and the type of a capped list
/// (`+3 more → Hub.in (RTC::TimedLong)`).
fn more_connector(b: &WireInstance, end: End, (me, mine): (&str, Option<&str>)) -> WireConnector {
    let between = if end.1 { " — " } else { " → " };
    let full = match mine {
        Some(p) => [me, ".", p].concat(),
        None => me.to_string(),
    };
    let short = mine.unwrap_or(me);
    // A capped list's box names its type on its port; the list's box does not.
    let of = if b.ports.first().is_some_and(|p| p.label != b.name) {
        format!(" ({})", b.component)
    } else {
        String::new()
    };
    let name = b.name.as_str();
    let (label, caption) = if end.0 {
        (
            [name, between, &full, &of].concat(),
            [name, between, short, &of].concat(),
        )
    } else {
        (
            [&full, between, name, &of].concat(),
            [short, between, name, &of].concat(),
        )
    };
    WireConnector {
        from: (0, 0),
        to: (0, 0),
        service: end.1,
        label,
        caption: Some(caption),
    }
}

/// Fixes the arrangement the layout keeps (as it keeps RTSystemEditor's saved positions): the
/// component in the middle column, a box on the left when `left` says so (a neighbour that
/// only feeds the component or uses its provided interface) and on the right otherwise, each
/// column in the order given (the closest neighbours first, the "+N more" boxes last).
/// Cheaper than the layered layout's ordering sweeps (every component page draws one) and the
/// same picture every time.
fn place_in_columns(inst: &mut [WireInstance], left: &[bool]) {
    let column = |i: usize| match (i, left.get(i)) {
        (0, _) => 1usize,
        (_, Some(true)) => 0,
        _ => 2,
    };
    let mut rows = [0i64; 3];
    for (i, it) in inst.iter_mut().enumerate() {
        let col = column(i);
        it.location = Some((col as i64 * 1000, rows[col] * 40));
        rows[col] += 1;
    }
    // The component level with the middle of the taller side column, not above it.
    let tallest = rows[0].max(rows[2]);
    if let Some(me) = inst.first_mut() {
        me.location = Some((1000, (tallest - 1).max(0) * 20));
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_drawing_s_explanation_states_its_cap() {
        for lang in [crate::i18n::Lang::En, crate::i18n::Lang::Ja] {
            let cap = super::NEIGHBOURS_DRAWN.to_string();
            assert!(lang.t("neighbourhood_drawing").contains(&cap));
        }
    }

    #[test]
    fn the_intro_states_the_cap_in_use() {
        for lang in [crate::i18n::Lang::En, crate::i18n::Lang::Ja] {
            let cap = super::PEER_COMPONENTS_CAP.to_string();
            assert!(lang.t("neighbourhood_intro").contains(&cap));
        }
    }
}
