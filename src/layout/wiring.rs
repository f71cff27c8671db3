//! Layout of an RT System's wiring diagram: instances as boxes with their ports on the sides,
//! connectors routed orthogonally between them. Geometry only; the HTML renderer draws it as
//! SVG (`render::html::system_svg`), the exports write the same graph as DOT and Mermaid.
//!
//! A layered layout in the direction data flows (Sugiyama's scheme, as Graphviz `dot` and ELK
//! Layered do), written here rather than taken from a crate because what matters is the port
//! handling and the routing, which the layout crates do not offer (`layout-rs` routes splines
//! without ports, `rust-sugiyama` stops at coordinates):
//!
//! 1. **Layers.** Longest path over the data connectors (a cycle is cut where a depth-first
//!    search meets an instance already on its path), sources pulled right next to their first
//!    consumer; instances with only service connectors go right of their partners. When
//!    RTSystemEditor saved a position for every instance (`rtsExt:Location`, all distinct),
//!    its columns and vertical order are kept instead (the author's mental map).
//! 2. **Port sides.** Data in-ports on the left, out-ports on the right; a service port on the
//!    side that faces most of its partners (right when they share the column).
//! 3. **Channels and dummies.** Between two layers runs a vertical channel; a connector leaves
//!    its port into the channel beside it, and where it must pass a layer it gets a dummy slot
//!    there (a gap between boxes), so no connector ever crosses a box.
//! 4. **Order.** Barycentre sweeps over the layers with port positions, keeping the order with
//!    the fewest crossings; then the ports of each side sorted by where their partners are.
//! 5. **Coordinates.** Each layer's items placed as near as their order allows to the height of
//!    the ports they connect to (isotonic regression by pooling adjacent violators, a few sweeps
//!    both ways), so most connectors run straight.
//! 6. **Routing.** In each channel every vertical segment gets a track; segments are ordered so
//!    that two connectors that need not cross do not (a connector going down from higher up
//!    runs further right), and overlapping ones never share a track.
//!
//! Boxes are sized to their names, wrapped on several lines when very long, never cut.

use super::text::{bold_width, text_width, wrap_measured, Font};

/// What a port is, for its side and symbol.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PortKind {
    In,
    Out,
    Service,
    Other,
}

/// A port of an instance.
#[derive(Debug, Clone)]
pub struct Port {
    pub name: String,
    pub kind: PortKind,
}

/// An instance of the system.
#[derive(Debug, Clone)]
pub struct Node {
    pub name: String,
    /// The component's name, shown under the instance name (may be empty).
    pub component: String,
    pub ports: Vec<Port>,
    /// `rtsExt:Location` x/y.
    pub location: Option<(i64, i64)>,
}

/// A connector from (instance, port) to (instance, port).
#[derive(Debug, Clone, Copy)]
pub struct Edge {
    pub from: (usize, usize),
    pub to: (usize, usize),
    pub service: bool,
}

/// Side of a box a port is drawn on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    Left,
    Right,
}

/// A port as placed.
#[derive(Debug, Clone)]
pub struct PortPlace {
    pub side: Side,
    /// Where connectors meet the port (on the box edge).
    pub x: f32,
    pub y: f32,
    /// The name, on one line or wrapped on several.
    pub lines: Vec<String>,
    /// Where the name's text starts (`text-anchor` start on the left, end on the right).
    pub text_x: f32,
    /// Baseline of the first line.
    pub text_y: f32,
}

/// Lines of text set one under the other.
#[derive(Debug, Clone)]
pub struct TextLines {
    pub lines: Vec<String>,
    /// Baseline of the first line.
    pub y: f32,
    /// From one baseline to the next.
    pub leading: f32,
}

impl TextLines {
    /// Baseline of line `k`.
    pub fn baseline(&self, k: usize) -> f32 {
        self.y + self.leading * k as f32
    }

    /// Baseline of the last line (of the first when there are none).
    pub fn last_baseline(&self) -> f32 {
        self.baseline(self.lines.len().saturating_sub(1))
    }
}

/// An instance as placed.
#[derive(Debug, Clone)]
pub struct NodeBox {
    pub x: f32,
    pub y: f32,
    pub w: f32,
    pub h: f32,
    /// The instance name, centred.
    pub title: TextLines,
    /// The component name, under the title.
    pub subtitle: TextLines,
    /// Indexed like the node's ports.
    pub ports: Vec<PortPlace>,
}

/// The laid-out diagram.
#[derive(Debug, Clone)]
pub struct WiringLayout {
    pub width: f32,
    pub height: f32,
    pub nodes: Vec<NodeBox>,
    /// Per edge: the polyline from the source port to the target port (orthogonal), or `None`
    /// when the edge names a missing instance or port.
    pub routes: Vec<Option<Vec<(f32, f32)>>>,
    /// True when the boxes keep RTSystemEditor's arrangement.
    pub from_locations: bool,
}

/// Font sizes and line heights, as `style.css` sets them for `svg.system-diagram`.
pub const TITLE_PX: f32 = 15.0;
pub const SUBTITLE_PX: f32 = 12.0;
pub const PORT_PX: f32 = 11.0;
const TITLE_LINE: f32 = 18.0;
const SUBTITLE_LINE: f32 = 15.0;
const PORT_LINE: f32 = 13.0;
const ROW_MIN: f32 = 22.0;
/// Widest line of an instance name, and of a port name, before it wraps.
const TITLE_MAX: f32 = 260.0;
const PORT_MAX: f32 = 170.0;
/// Inset of port names from the box edge (the port square reaches 6 px inside).
const PORT_INSET: f32 = 12.0;
const MARGIN: f32 = 14.0;
const GAP_NODES: f32 = 28.0;
const GAP_DUMMY: f32 = 12.0;
const TRACK: f32 = 10.0;
const CHANNEL_PAD: f32 = 18.0;
const CHANNEL_MIN: f32 = 48.0;
/// RTSystemEditor positions: instances closer than this in x share a column; y is scaled.
const LOC_COLUMN: i64 = 110;
const LOC_Y_SCALE: f32 = 1.5;
/// Pull of a saved position against that of the connectors (weight 1 each): strong enough to
/// keep the arrangement, weak enough to straighten a connector a few pixels off.
const LOC_WEIGHT: f32 = 3.0;

fn port_w(s: &str) -> f32 {
    text_width(s, PORT_PX)
}
fn title_w(s: &str) -> f32 {
    bold_width(s, TITLE_PX)
}
fn subtitle_w(s: &str) -> f32 {
    text_width(s, SUBTITLE_PX)
}

fn max_w(lines: &[String], f: &dyn Fn(&str) -> f32) -> f32 {
    lines.iter().map(|l| f(l)).fold(0.0, f32::max)
}

/// An item of a layer: an instance, or a dummy slot where connector `edge` passes the layer.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Item {
    Node(usize),
    Dummy,
}

/// A stop on a connector's way: a port of an instance or a dummy item.
#[derive(Debug, Clone, Copy)]
enum Stop {
    Port { node: usize, port: usize },
    Dummy(usize),
}

struct Graph<'a> {
    nodes: &'a [Node],
    /// Layer of each node.
    layer: Vec<usize>,
    layers: usize,
    side: Vec<Vec<Side>>,
    /// Items: kind and layer.
    items: Vec<(Item, usize)>,
    /// Item index of each node.
    node_item: Vec<usize>,
    /// Per valid edge: its stops, source first.
    stops: Vec<Option<Vec<Stop>>>,
    /// Order of items in each layer.
    order: Vec<Vec<usize>>,
    /// Port order on each side of each node: port indices, top to bottom.
    port_order: Vec<[Vec<usize>; 2]>,
}

fn side_ix(s: Side) -> usize {
    match s {
        Side::Left => 0,
        Side::Right => 1,
    }
}

fn valid(nodes: &[Node], e: &Edge) -> bool {
    nodes
        .get(e.from.0)
        .is_some_and(|n| e.from.1 < n.ports.len())
        && nodes.get(e.to.0).is_some_and(|n| e.to.1 < n.ports.len())
}

/// Positions from RTSystemEditor are usable when every instance has one and no two coincide.
fn usable_locations(nodes: &[Node]) -> Option<Vec<(i64, i64)>> {
    let locs: Vec<(i64, i64)> = nodes.iter().map(|n| n.location).collect::<Option<_>>()?;
    let mut sorted = locs.clone();
    sorted.sort_unstable();
    sorted.dedup();
    (sorted.len() == locs.len() && !locs.is_empty()).then_some(locs)
}

/// Columns from positions: sorted by x, a new column where an instance starts further right
/// than [`LOC_COLUMN`] from the first of the current column.
fn location_layers(locs: &[(i64, i64)]) -> Vec<usize> {
    let mut by_x: Vec<usize> = (0..locs.len()).collect();
    by_x.sort_by_key(|&i| (locs[i].0, locs[i].1, i));
    let mut layer = vec![0; locs.len()];
    let mut col = 0;
    let mut start = by_x.first().map_or(0, |&i| locs[i].0);
    for &i in &by_x {
        if locs[i].0 - start > LOC_COLUMN {
            col += 1;
            start = locs[i].0;
        }
        layer[i] = col;
    }
    layer
}

/// Layers by longest path over the data connectors (cycles cut by a depth-first search),
/// sources moved next to their nearest consumer, service-only instances right of partners.
fn flow_layers(nodes: &[Node], edges: &[Edge]) -> Vec<usize> {
    let n = nodes.len();
    let mut succ: Vec<Vec<usize>> = vec![Vec::new(); n];
    for e in edges.iter().filter(|e| !e.service && valid(nodes, e)) {
        if e.from.0 != e.to.0 && !succ[e.from.0].contains(&e.to.0) {
            succ[e.from.0].push(e.to.0);
        }
    }
    let mut state = vec![0u8; n];
    let mut order = Vec::with_capacity(n);
    for start in 0..n {
        if state[start] != 0 {
            continue;
        }
        let mut stack = vec![(start, 0usize)];
        state[start] = 1;
        while let Some(&mut (v, ref mut next)) = stack.last_mut() {
            if *next < succ[v].len() {
                let w = succ[v][*next];
                *next += 1;
                if state[w] == 0 {
                    state[w] = 1;
                    stack.push((w, 0));
                }
            } else {
                state[v] = 2;
                order.push(v);
                stack.pop();
            }
        }
    }
    order.reverse();
    let mut rank = vec![0; n];
    for (k, &v) in order.iter().enumerate() {
        rank[v] = k;
    }
    // Forward edges only (the acyclic part).
    let fwd: Vec<Vec<usize>> = (0..n)
        .map(|v| {
            succ[v]
                .iter()
                .copied()
                .filter(|&w| rank[w] > rank[v])
                .collect()
        })
        .collect();
    let mut has_pred = vec![false; n];
    for &w in fwd.iter().flatten() {
        has_pred[w] = true;
    }
    let mut layer = vec![0usize; n];
    for &v in &order {
        for &w in &fwd[v] {
            layer[w] = layer[w].max(layer[v] + 1);
        }
    }
    // A source feeding only later layers moves right, next to its nearest consumer.
    for &v in order.iter().rev() {
        if !has_pred[v] {
            if let Some(m) = fwd[v].iter().map(|&w| layer[w]).min() {
                layer[v] = layer[v].max(m.saturating_sub(1));
            }
        }
    }
    // Instances without data connectors: right of their service partners.
    let mut anchored: Vec<bool> = (0..n)
        .map(|v| !succ[v].is_empty() || has_pred[v] || succ.iter().any(|s| s.contains(&v)))
        .collect();
    for _ in 0..n {
        let mut changed = false;
        for v in 0..n {
            if anchored[v] {
                continue;
            }
            let partners = edges
                .iter()
                .filter(|e| e.service && valid(nodes, e))
                .filter_map(|e| {
                    if e.from.0 == v {
                        Some(e.to.0)
                    } else if e.to.0 == v {
                        Some(e.from.0)
                    } else {
                        None
                    }
                })
                .filter(|&w| w != v && anchored[w]);
            if let Some(m) = partners.map(|w| layer[w]).max() {
                layer[v] = m + 1;
                anchored[v] = true;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    layer
}

/// Renumbers layers so that none is empty.
fn compact(layer: &mut [usize]) -> usize {
    let mut used: Vec<usize> = layer.to_vec();
    used.sort_unstable();
    used.dedup();
    for l in layer.iter_mut() {
        *l = used.binary_search(l).unwrap_or(0);
    }
    used.len()
}

/// Lays the wiring out.
pub fn layout(nodes: &[Node], edges: &[Edge]) -> WiringLayout {
    layout_with(nodes, edges, Effort::Full)
}

/// How hard the ordering works on a drawing with saved positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Effort {
    /// Connectors that pass a column are moved to where they cross fewest others (sifting).
    Full,
    /// Saved positions as they are, no sifting: for the many small drawings of a catalogue
    /// (every component page's neighbourhood), where sifting would cost more than the page.
    Quick,
}

/// [`layout`] with a given [`Effort`].
pub fn layout_with(nodes: &[Node], edges: &[Edge], effort: Effort) -> WiringLayout {
    let locs = usable_locations(nodes);
    let mut layer = match &locs {
        Some(l) => location_layers(l),
        None => flow_layers(nodes, edges),
    };
    let layers = if nodes.is_empty() {
        0
    } else {
        compact(&mut layer)
    };

    // Port sides.
    let side: Vec<Vec<Side>> = nodes
        .iter()
        .enumerate()
        .map(|(v, n)| {
            n.ports
                .iter()
                .enumerate()
                .map(|(k, p)| match p.kind {
                    PortKind::In => Side::Left,
                    PortKind::Out => Side::Right,
                    PortKind::Service | PortKind::Other => {
                        let mut vote = 0i64;
                        for e in edges.iter().filter(|e| valid(nodes, e)) {
                            let partner = if e.from == (v, k) {
                                e.to.0
                            } else if e.to == (v, k) {
                                e.from.0
                            } else {
                                continue;
                            };
                            vote += (layer[partner] as i64 - layer[v] as i64).signum();
                        }
                        if vote < 0 {
                            Side::Left
                        } else {
                            Side::Right
                        }
                    }
                })
                .collect()
        })
        .collect();

    let mut g = Graph {
        nodes,
        layer,
        layers,
        side,
        items: Vec::with_capacity(nodes.len() + edges.len()),
        node_item: Vec::with_capacity(nodes.len()),
        stops: Vec::with_capacity(edges.len()),
        order: vec![Vec::new(); layers],
        port_order: Vec::new(),
    };
    for v in 0..nodes.len() {
        g.node_item.push(g.items.len());
        g.items.push((Item::Node(v), g.layer[v]));
    }
    // Stops and dummies.
    for e in edges {
        if !valid(nodes, e) {
            g.stops.push(None);
            continue;
        }
        let ch = |(v, k): (usize, usize)| g.layer[v] + usize::from(g.side[v][k] == Side::Right);
        let (cs, ct) = (ch(e.from), ch(e.to));
        // A dummy in each layer between the two ends, from the source's side.
        let dummies = cs.abs_diff(ct);
        let mut stops = Vec::with_capacity(dummies + 2);
        stops.push(Stop::Port {
            node: e.from.0,
            port: e.from.1,
        });
        for k in 0..dummies {
            let l = if cs < ct { cs + k } else { cs - 1 - k };
            stops.push(Stop::Dummy(g.items.len()));
            g.items.push((Item::Dummy, l));
        }
        stops.push(Stop::Port {
            node: e.to.0,
            port: e.to.1,
        });
        g.stops.push(Some(stops));
    }
    // Port order: declared order on each side, to begin with.
    g.port_order = (0..nodes.len())
        .map(|v| {
            let n = g.side[v].len();
            let mut s: [Vec<usize>; 2] = [Vec::with_capacity(n), Vec::with_capacity(n)];
            for (k, &sd) in g.side[v].iter().enumerate() {
                s[side_ix(sd)].push(k);
            }
            s
        })
        .collect();

    // Initial order: by position (locations) or by input order.
    let mut in_layer = vec![0usize; layers];
    for &(_, l) in &g.items {
        in_layer[l] += 1;
    }
    for (order, &n) in g.order.iter_mut().zip(&in_layer) {
        order.reserve_exact(n);
    }
    for (it, &(_, l)) in g.items.iter().enumerate() {
        g.order[l].push(it);
    }
    match &locs {
        Some(l) => order_by_locations(&mut g, l, effort),
        None => order_by_barycentres(&mut g),
    }

    // Geometry of the boxes.
    let mut boxes: Vec<NodeBox> = nodes
        .iter()
        .enumerate()
        .map(|(v, n)| node_box(n, &g.side[v], &g.port_order[v]))
        .collect();

    // Vertical placement.
    let tops = place_vertically(&g, &boxes, locs.as_deref());
    // Channels and tracks, then x.
    let item_y = |it: usize| tops[it];
    let mut col_w = vec![0.0f32; layers];
    for (v, b) in boxes.iter().enumerate() {
        col_w[g.layer[v]] = col_w[g.layer[v]].max(b.w);
    }
    // Vertical segments per channel: (edge, stop index j, y_a, y_b).
    let stop_y = |s: &Stop, boxes: &[NodeBox]| -> f32 {
        match *s {
            Stop::Port { node, port } => tops[g.node_item[node]] + boxes[node].ports[port].y,
            Stop::Dummy(it) => item_y(it),
        }
    };
    let stop_layer = |s: &Stop| match *s {
        Stop::Port { node, .. } => g.layer[node],
        Stop::Dummy(it) => g.items[it].1,
    };
    let mut segs: Vec<Vec<Seg>> = (0..=layers).map(|_| Vec::new()).collect();
    for (e, st) in g.stops.iter().enumerate() {
        let Some(st) = st else { continue };
        for j in 0..st.len() - 1 {
            let (a, b) = (&st[j], &st[j + 1]);
            let c = channel_of(a, b, &g);
            let (ya, yb) = (stop_y(a, &boxes), stop_y(b, &boxes));
            if (ya - yb).abs() < 0.5 {
                continue;
            }
            let (la, lb) = (stop_layer(a), stop_layer(b));
            let left_bank = |l: usize| l + 1 == c;
            let (class, key) = match (left_bank(la), left_bank(lb)) {
                (true, true) => (0, (ya - yb).abs()),
                (false, false) => (3, -(ya - yb).abs()),
                (true, false) | (false, true) => {
                    let (yl, yr) = if left_bank(la) { (ya, yb) } else { (yb, ya) };
                    if yr > yl {
                        (1, -yl)
                    } else {
                        (2, yl)
                    }
                }
            };
            segs[c].push(Seg {
                edge: e,
                j,
                lo: ya.min(yb),
                hi: ya.max(yb),
                class,
                key,
                ends: [(left_bank(la), ya), (left_bank(lb), yb)],
            });
        }
    }
    // Tracks: in the preferred left-to-right order, each right of every earlier one it
    // overlaps.
    let mut track: Vec<Vec<(usize, usize, usize)>> = vec![Vec::new(); layers + 1];
    let mut tracks_in = vec![0usize; layers + 1];
    let mut placed: Vec<(f32, f32, usize)> = Vec::new();
    for c in 0..=layers {
        let list = &mut segs[c];
        list.sort_by(|a, b| {
            (a.class, a.key, a.edge, a.j)
                .partial_cmp(&(b.class, b.key, b.edge, b.j))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        placed.clear();
        track[c].reserve_exact(list.len());
        for s in track_order(list).into_iter().map(|k| &list[k]) {
            let t = placed
                .iter()
                .filter(|p| p.0 < s.hi + 6.0 && s.lo < p.1 + 6.0)
                .map(|p| p.2 + 1)
                .max()
                .unwrap_or(0);
            placed.push((s.lo, s.hi, t));
            track[c].push((s.edge, s.j, t));
            tracks_in[c] = tracks_in[c].max(t + 1);
        }
    }
    let ch_w: Vec<f32> = (0..=layers)
        .map(|c| {
            let t = tracks_in[c] as f32;
            let need = if t > 0.0 {
                2.0 * CHANNEL_PAD + (t - 1.0) * TRACK
            } else {
                0.0
            };
            if c == 0 || c == layers {
                need
            } else {
                need.max(CHANNEL_MIN)
            }
        })
        .collect();
    let mut ch_x = Vec::with_capacity(layers + 1);
    let mut col_x = Vec::with_capacity(layers);
    let mut x = MARGIN;
    for c in 0..=layers {
        ch_x.push(x);
        x += ch_w[c];
        if c < layers {
            col_x.push(x);
            x += col_w[c];
        }
    }
    let width = (x + MARGIN).ceil();
    let track_x = |c: usize, t: usize| -> f32 {
        let n = tracks_in[c] as f32;
        let used = (n - 1.0).max(0.0) * TRACK;
        ch_x[c] + (ch_w[c] - used) / 2.0 + t as f32 * TRACK
    };
    // Boxes to absolute coordinates.
    for (v, b) in boxes.iter_mut().enumerate() {
        let l = g.layer[v];
        let dx = (col_x[l] + (col_w[l] - b.w) / 2.0).round();
        let dy = tops[g.node_item[v]];
        b.x += dx;
        b.y += dy;
        b.title.y += dy;
        b.subtitle.y += dy;
        for p in &mut b.ports {
            p.x += dx;
            p.text_x += dx;
            p.y += dy;
            p.text_y += dy;
        }
    }
    let height = (boxes
        .iter()
        .map(|b| b.y + b.h)
        .chain(tops.iter().copied())
        .fold(0.0, f32::max)
        + MARGIN)
        .ceil();
    // Routes.
    let mut routes: Vec<Option<Vec<(f32, f32)>>> = Vec::with_capacity(edges.len());
    for (e, st) in g.stops.iter().enumerate() {
        let Some(st) = st else {
            routes.push(None);
            continue;
        };
        let at = |s: &Stop| -> f32 {
            match *s {
                Stop::Port { node, port } => boxes[node].ports[port].y,
                Stop::Dummy(it) => item_y(it),
            }
        };
        let mut pts: Vec<(f32, f32)> = Vec::with_capacity(2 * st.len());
        if let Stop::Port { node, port } = st[0] {
            let p = &boxes[node].ports[port];
            pts.push((p.x, p.y));
        }
        for j in 0..st.len() - 1 {
            let c = channel_of(&st[j], &st[j + 1], &g);
            if let Some(&(_, _, t)) = track[c].iter().find(|x| x.0 == e && x.1 == j) {
                let tx = track_x(c, t);
                pts.push((tx, at(&st[j])));
                pts.push((tx, at(&st[j + 1])));
            }
        }
        if let Some(Stop::Port { node, port }) = st.last() {
            let p = &boxes[*node].ports[*port];
            pts.push((p.x, p.y));
        }
        routes.push(Some(simplify(pts)));
    }
    WiringLayout {
        width: width.max(100.0),
        height: height.max(60.0),
        nodes: boxes,
        routes,
        from_locations: locs.is_some(),
    }
}

/// A vertical segment of a connector in a channel: from the connector's stop `j` to stop
/// `j + 1`, between `lo` and `hi`.
struct Seg {
    edge: usize,
    j: usize,
    lo: f32,
    hi: f32,
    /// 0 U-turn on the left bank, 1 crossing downwards, 2 upwards, 3 U-turn on the right.
    class: u8,
    key: f32,
    /// Its two ends: (on the left bank, y). The connector runs level from each end's bank to
    /// the segment's track.
    ends: [(bool, f32); 2],
}

/// The order in which the segments `list` (sorted as preferred) get their tracks, each right
/// of every earlier one it overlaps: the preferred order, except that a segment with an end
/// on the left bank at the height of another's end on the right bank goes before it (left of
/// it). Else their level runs, one from the left bank to its track and one from the right
/// bank to its own, would overlap on one line, and one connector would seem to branch into
/// the other. (A cycle of such constraints, two connectors meeting at two heights the other
/// way round each, keeps the preferred order.)
fn track_order(list: &[Seg]) -> Vec<usize> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    const LEVEL: f32 = 2.0;
    // Right-bank ends by height: (y, segment).
    let mut right: Vec<(f32, usize)> = list
        .iter()
        .enumerate()
        .flat_map(|(k, s)| s.ends.iter().filter(|e| !e.0).map(move |e| (e.1, k)))
        .collect();
    right.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    let mut after: Vec<Vec<usize>> = vec![Vec::new(); list.len()];
    let mut before = vec![0usize; list.len()];
    for (k, s) in list.iter().enumerate() {
        for &(_, y) in s.ends.iter().filter(|e| e.0) {
            let from = right.partition_point(|r| r.0 < y - LEVEL);
            for &(ry, m) in &right[from..] {
                if ry > y + LEVEL {
                    break;
                }
                if list[m].edge != s.edge && !after[k].contains(&m) {
                    after[k].push(m);
                    before[m] += 1;
                }
            }
        }
    }
    // Kahn's algorithm, the preferred (smallest) index first among those free to go.
    let mut free: BinaryHeap<Reverse<usize>> = (0..list.len())
        .filter(|&k| before[k] == 0)
        .map(Reverse)
        .collect();
    let mut done = vec![false; list.len()];
    let mut order = Vec::with_capacity(list.len());
    while order.len() < list.len() {
        let k = match free.pop() {
            Some(Reverse(k)) if done[k] => continue,
            Some(Reverse(k)) => k,
            // A cycle: the first segment left goes, whatever waits for it.
            None => match (0..list.len()).find(|&k| !done[k]) {
                Some(k) => k,
                None => break,
            },
        };
        done[k] = true;
        order.push(k);
        for &m in &after[k] {
            before[m] = before[m].saturating_sub(1);
            if before[m] == 0 && !done[m] {
                free.push(Reverse(m));
            }
        }
    }
    order
}

/// Drops repeated points and middle points of straight runs.
fn simplify(pts: Vec<(f32, f32)>) -> Vec<(f32, f32)> {
    let mut out: Vec<(f32, f32)> = Vec::with_capacity(pts.len());
    for p in pts {
        if out
            .last()
            .is_some_and(|q| (q.0 - p.0).abs() < 0.01 && (q.1 - p.1).abs() < 0.01)
        {
            continue;
        }
        if out.len() >= 2 {
            let a = out[out.len() - 2];
            let b = out[out.len() - 1];
            let straight = ((a.0 - b.0).abs() < 0.01 && (b.0 - p.0).abs() < 0.01)
                || ((a.1 - b.1).abs() < 0.01 && (b.1 - p.1).abs() < 0.01);
            if straight {
                out.pop();
            }
        }
        out.push(p);
    }
    out
}

/// The channel between two consecutive stops of a connector.
fn channel_of(a: &Stop, b: &Stop, g: &Graph<'_>) -> usize {
    let bank = |s: &Stop, other: &Stop| -> usize {
        match *s {
            Stop::Port { node, port } => {
                g.layer[node] + usize::from(g.side[node][port] == Side::Right)
            }
            Stop::Dummy(it) => {
                // A dummy meets the channel on the side of the other stop.
                let l = g.items[it].1;
                let ol = match *other {
                    Stop::Port { node, port } => {
                        let c = g.layer[node] + usize::from(g.side[node][port] == Side::Right);
                        return if c <= l { l } else { l + 1 };
                    }
                    Stop::Dummy(o) => g.items[o].1,
                };
                if ol < l {
                    l
                } else {
                    l + 1
                }
            }
        }
    };
    match (a, b) {
        (Stop::Port { .. }, _) => bank(a, b),
        (_, Stop::Port { .. }) => bank(b, a),
        _ => bank(a, b),
    }
}

/// Box geometry relative to its top-left corner.
fn node_box(n: &Node, side: &[Side], port_order: &[Vec<usize>; 2]) -> NodeBox {
    let (title, title_w) = wrap_measured(&n.name, TITLE_MAX, Font::bold(TITLE_PX));
    let (subtitle, subtitle_w) = if n.component.is_empty() {
        (Vec::new(), 0.0)
    } else {
        wrap_measured(&n.component, TITLE_MAX, Font::regular(SUBTITLE_PX))
    };
    // Each port's lines and the width of the widest.
    let (mut port_lines, port_ws): (Vec<Vec<String>>, Vec<f32>) = n
        .ports
        .iter()
        .map(|p| wrap_measured(&p.name, PORT_MAX, Font::regular(PORT_PX)))
        .unzip();
    let side_w = |s: usize| {
        port_order[s]
            .iter()
            .map(|&k| port_ws[k])
            .fold(0.0, f32::max)
    };
    let (lw, rw) = (side_w(0), side_w(1));
    let ports_w = PORT_INSET + lw + if lw > 0.0 && rw > 0.0 { 20.0 } else { 0.0 } + rw + PORT_INSET;
    let w = [120.0, title_w + 24.0, subtitle_w + 24.0, ports_w]
        .into_iter()
        .fold(0.0, f32::max)
        .ceil();
    let header =
        6.0 + TITLE_LINE * title.len() as f32 + SUBTITLE_LINE * subtitle.len() as f32 + 4.0;
    let subtitle = TextLines {
        y: 6.0 + TITLE_LINE * title.len() as f32 + 12.0,
        lines: subtitle,
        leading: SUBTITLE_LINE,
    };
    let title = TextLines {
        lines: title,
        y: 6.0 + 14.0,
        leading: TITLE_LINE,
    };
    let mut ports: Vec<PortPlace> = n
        .ports
        .iter()
        .map(|_| PortPlace {
            side: Side::Right,
            x: 0.0,
            y: 0.0,
            lines: Vec::new(),
            text_x: 0.0,
            text_y: 0.0,
        })
        .collect();
    let mut bottom = header;
    for (s, list) in port_order.iter().enumerate() {
        let mut y = header;
        for &k in list {
            // The sides share no port: each port's lines are taken once.
            let lines = std::mem::take(&mut port_lines[k]);
            let row = (PORT_LINE * lines.len() as f32 + 9.0).max(ROW_MIN);
            let cy = (y + row / 2.0).round();
            let (x, text_x) = if s == 0 {
                (0.0, PORT_INSET)
            } else {
                (w, w - PORT_INSET)
            };
            ports[k] = PortPlace {
                side: side[k],
                x,
                y: cy,
                text_y: cy - PORT_LINE * lines.len() as f32 / 2.0 + 10.0,
                lines,
                text_x,
            };
            y += row;
        }
        bottom = f32::max(bottom, y);
    }
    let h = (bottom + 6.0).ceil();
    NodeBox {
        x: 0.0,
        y: 0.0,
        w,
        h,
        title,
        subtitle,
        ports,
    }
}

/// Position of a stop for ordering: its item's index in its layer plus the port's place on
/// the box side (0..1).
fn stop_pos(g: &Graph<'_>, idx: &[f32], s: &Stop) -> f32 {
    match *s {
        Stop::Port { node, port } => {
            let sd = side_ix(g.side[node][port]);
            let list = &g.port_order[node][sd];
            let r = list.iter().position(|&k| k == port).unwrap_or(0);
            idx[g.node_item[node]] + (r as f32 + 0.5) / (list.len().max(1) as f32) - 0.5
        }
        Stop::Dummy(it) => idx[it],
    }
}

fn stop_item(g: &Graph<'_>, s: &Stop) -> usize {
    match *s {
        Stop::Port { node, .. } => g.node_item[node],
        Stop::Dummy(it) => it,
    }
}

/// Links between consecutive stops: (stop a, stop b), for every connector.
fn links<'g>(g: &'g Graph<'_>) -> impl Iterator<Item = (&'g Stop, &'g Stop)> + 'g {
    g.stops
        .iter()
        .flatten()
        .flat_map(|st| st.windows(2).map(|w| (&w[0], &w[1])))
}

fn index_of(g: &Graph<'_>) -> Vec<f32> {
    let mut idx = Vec::new();
    index_into(g, &mut idx);
    idx
}

/// Each item's index in its layer, into `idx`.
fn index_into(g: &Graph<'_>, idx: &mut Vec<f32>) {
    idx.clear();
    idx.resize(g.items.len(), 0.0);
    for l in &g.order {
        for (k, &it) in l.iter().enumerate() {
            idx[it] = k as f32;
        }
    }
}

/// Crossings the ordering implies, channel by channel: two links between the same two layers
/// whose ends are in opposite orders, a link whose end lies inside a U-turn (a link between
/// two items of one layer, drawn on that layer's side of the channel), and two U-turns on the
/// same side whose spans interleave.
fn crossings(g: &Graph<'_>) -> usize {
    Counter::default().count(g)
}

/// The lists [`crossings`] fills, kept from count to count: sifting counts the crossings of
/// every place of every item.
#[derive(Default)]
struct Counter {
    idx: Vec<f32>,
    /// Per channel: the links across it, by their ends' positions (left, right).
    across: Vec<Vec<(f32, f32)>>,
    /// Per channel: the U-turns in it (left bank?, lo, hi).
    uturn: Vec<Vec<(bool, f32, f32)>>,
}

impl Counter {
    /// [`crossings`] of the graph's present order.
    fn count(&mut self, g: &Graph<'_>) -> usize {
        let chans = g.layers + 1;
        let Counter { idx, across, uturn } = self;
        index_into(g, idx);
        across.resize_with(chans, Vec::new);
        across.iter_mut().for_each(Vec::clear);
        uturn.resize_with(chans, Vec::new);
        uturn.iter_mut().for_each(Vec::clear);
        for (a, b) in links(g) {
            let c = channel_of(a, b, g);
            let (la, lb) = (g.items[stop_item(g, a)].1, g.items[stop_item(g, b)].1);
            let (pa, pb) = (stop_pos(g, idx, a), stop_pos(g, idx, b));
            if la == lb {
                uturn[c].push((la + 1 == c, pa.min(pb), pa.max(pb)));
            } else {
                across[c].push(if la < lb { (pa, pb) } else { (pb, pa) });
            }
        }
        let mut n = 0;
        for c in 0..chans {
            let v = &across[c];
            let u = &uturn[c];
            for i in 0..v.len() {
                for j in i + 1..v.len() {
                    if (v[i].0 - v[j].0) * (v[i].1 - v[j].1) < 0.0 {
                        n += 1;
                    }
                }
                for &(left, lo, hi) in u {
                    let p = if left { v[i].0 } else { v[i].1 };
                    if p > lo + 1e-3 && p < hi - 1e-3 {
                        n += 1;
                    }
                }
            }
            for i in 0..u.len() {
                for j in i + 1..u.len() {
                    let (a, b) = (u[i], u[j]);
                    if a.0 == b.0
                        && ((a.1 < b.1 && b.1 < a.2 && a.2 < b.2)
                            || (b.1 < a.1 && a.1 < b.2 && b.2 < a.2))
                    {
                        n += 1;
                    }
                }
            }
        }
        n
    }
}

/// Sifting: each movable item tried at every place of its layer, kept where the implied
/// crossings are fewest (two passes; skipped for very large systems, where barycentres must
/// do). In `only_dummies` mode (saved positions) the instances keep their order.
fn sift(g: &mut Graph<'_>, only_dummies: bool) {
    let links_n = links(g).count();
    if links_n > 400 {
        return;
    }
    let mut counter = Counter::default();
    let mut best = counter.count(g);
    for _ in 0..2 {
        for it in 0..g.items.len() {
            if only_dummies && g.items[it].0 != Item::Dummy {
                continue;
            }
            if best == 0 {
                return;
            }
            let l = g.items[it].1;
            let Some(cur) = g.order[l].iter().position(|&x| x == it) else {
                continue;
            };
            g.order[l].remove(cur);
            let mut best_at = cur;
            for at in 0..=g.order[l].len() {
                g.order[l].insert(at, it);
                let n = counter.count(g);
                g.order[l].remove(at);
                if n < best {
                    best = n;
                    best_at = at;
                }
            }
            g.order[l].insert(best_at, it);
        }
        sort_ports(g);
        best = counter.count(g);
    }
}

/// Sorts the ports of each side by the mean position of the stops they connect to, layer by
/// layer from the left, each layer against the orders already chosen (sorting both ends of a
/// connector at once against each other's old order would swap both).
fn sort_ports(g: &mut Graph<'_>) {
    let idx = index_of(g);
    let all: Vec<(Stop, Stop)> = links(g).map(|(a, b)| (*a, *b)).collect();
    let mut key: Vec<Vec<(f32, usize)>> = g
        .nodes
        .iter()
        .map(|n| vec![(0.0, 0); n.ports.len()])
        .collect();
    for l in 0..g.layers {
        for k in key.iter_mut().flatten() {
            *k = (0.0, 0);
        }
        for (a, b) in &all {
            for (s, o) in [(a, b), (b, a)] {
                let Stop::Port { node, port } = *s else {
                    continue;
                };
                if g.layer[node] != l {
                    continue;
                }
                let other_layer = g.items[stop_item(g, o)].1;
                // Neighbours in another layer by their position; in the same layer (a U-turn)
                // above or below this box.
                let p = if other_layer == l {
                    if idx[stop_item(g, o)] < idx[g.node_item[node]] {
                        -1000.0
                    } else {
                        1000.0
                    }
                } else {
                    stop_pos(g, &idx, o)
                };
                key[node][port].0 += p;
                key[node][port].1 += 1;
            }
        }
        for (v, sides) in g.port_order.iter_mut().enumerate() {
            if g.layer[v] != l {
                continue;
            }
            for list in sides.iter_mut() {
                // Connected ports by their partners; unconnected ones after them, as declared.
                let mean = |k: usize| {
                    let (s, n) = key[v][k];
                    if n > 0 {
                        s / n as f32
                    } else {
                        f32::INFINITY
                    }
                };
                list.sort_by(|&a, &b| {
                    mean(a)
                        .partial_cmp(&mean(b))
                        .unwrap_or(std::cmp::Ordering::Equal)
                        .then(a.cmp(&b))
                });
            }
        }
    }
}

/// Barycentre sweeps, keeping the order with the fewest crossings.
fn order_by_barycentres(g: &mut Graph<'_>) {
    let mut best = g.order.clone();
    let mut best_ports = g.port_order.clone();
    let mut counter = Counter::default();
    let mut best_n = counter.count(g);
    // Once an order without crossings is found no later round can be kept (each must be
    // strictly better), so the rounds stop there: the same order is kept either way.
    for round in 0..12 {
        if best_n == 0 {
            break;
        }
        let down = round % 2 == 0;
        let seq: Vec<usize> = if down {
            (1..g.layers).collect()
        } else {
            (0..g.layers.saturating_sub(1)).rev().collect()
        };
        for l in seq {
            let from = if down { l - 1 } else { l + 1 };
            let idx = index_of(g);
            let mut sum = vec![(0.0f32, 0usize); g.items.len()];
            for (a, b) in links(g) {
                for (s, o) in [(a, b), (b, a)] {
                    let (si, oi) = (stop_item(g, s), stop_item(g, o));
                    if g.items[si].1 == l && g.items[oi].1 == from {
                        sum[si].0 += stop_pos(g, &idx, o);
                        sum[si].1 += 1;
                    }
                }
            }
            let mut list = g.order[l].clone();
            let key = |it: usize| {
                if sum[it].1 > 0 {
                    sum[it].0 / sum[it].1 as f32
                } else {
                    idx[it]
                }
            };
            list.sort_by(|&a, &b| {
                key(a)
                    .partial_cmp(&key(b))
                    .unwrap_or(std::cmp::Ordering::Equal)
                    .then(
                        idx[a]
                            .partial_cmp(&idx[b])
                            .unwrap_or(std::cmp::Ordering::Equal),
                    )
            });
            g.order[l] = list;
        }
        if round >= 4 {
            sort_ports(g);
        }
        let n = counter.count(g);
        if n < best_n {
            best_n = n;
            best = g.order.clone();
            best_ports = g.port_order.clone();
        }
    }
    g.order = best;
    g.port_order = best_ports;
    sort_ports(g);
    if counter.count(g) > best_n {
        g.port_order = best_ports_fallback(g, best_n);
    }
    sift(g, false);
}

/// The port order sort_ports chose made things worse: keep the declared order instead when
/// that is no worse.
fn best_ports_fallback(g: &mut Graph<'_>, best_n: usize) -> Vec<[Vec<usize>; 2]> {
    let sorted = g.port_order.clone();
    let declared: Vec<[Vec<usize>; 2]> = (0..g.nodes.len())
        .map(|v| {
            let mut s: [Vec<usize>; 2] = [Vec::new(), Vec::new()];
            for (k, &sd) in g.side[v].iter().enumerate() {
                s[side_ix(sd)].push(k);
            }
            s
        })
        .collect();
    g.port_order = declared.clone();
    if crossings(g) <= best_n {
        declared
    } else {
        sorted
    }
}

/// Orders each layer by the saved y of its instances; dummies go where their neighbours are.
fn order_by_locations(g: &mut Graph<'_>, locs: &[(i64, i64)], effort: Effort) {
    let mut y = vec![0.0f32; g.items.len()];
    for (v, &(_, ly)) in locs.iter().enumerate() {
        y[g.node_item[v]] = ly as f32;
    }
    // Dummies: average of their neighbours' heights, a few rounds to settle chains.
    for _ in 0..4 {
        let mut sum = vec![(0.0f32, 0usize); g.items.len()];
        for (a, b) in links(g) {
            for (s, o) in [(a, b), (b, a)] {
                if let Stop::Dummy(it) = *s {
                    sum[it].0 += y[stop_item(g, o)];
                    sum[it].1 += 1;
                }
            }
        }
        for (it, &(kind, _)) in g.items.iter().enumerate() {
            if kind == Item::Dummy && sum[it].1 > 0 {
                y[it] = sum[it].0 / sum[it].1 as f32;
            }
        }
    }
    for l in 0..g.layers {
        g.order[l].sort_by(|&a, &b| {
            y[a].partial_cmp(&y[b])
                .unwrap_or(std::cmp::Ordering::Equal)
                .then(a.cmp(&b))
        });
    }
    sort_ports(g);
    if effort == Effort::Full {
        sift(g, true);
    }
}

/// Tops of all items (dummies: the height their connector passes at).
fn place_vertically(g: &Graph<'_>, boxes: &[NodeBox], locs: Option<&[(i64, i64)]>) -> Vec<f32> {
    let height = |it: usize| match g.items[it].0 {
        Item::Node(v) => boxes[v].h,
        Item::Dummy => 0.0,
    };
    let gap = |a: usize, b: usize| match (g.items[a].0, g.items[b].0) {
        (Item::Node(_), Item::Node(_)) => GAP_NODES,
        _ => GAP_DUMMY,
    };
    let offset_of = |s: &Stop| match *s {
        Stop::Port { node, port } => boxes[node].ports[port].y,
        Stop::Dummy(_) => 0.0,
    };
    let mut top = vec![0.0f32; g.items.len()];
    // Stacked to begin with.
    for l in &g.order {
        let mut y = 0.0;
        for (k, &it) in l.iter().enumerate() {
            if k > 0 {
                y += gap(l[k - 1], it);
            }
            top[it] = y;
            y += height(it);
        }
    }
    let fixed: Vec<Option<f32>> = (0..g.items.len())
        .map(|it| match (g.items[it].0, locs) {
            (Item::Node(v), Some(l)) => Some(l[v].1 as f32 * LOC_Y_SCALE),
            _ => None,
        })
        .collect();
    // What pulls each item: the other end of each link it is on, in the order of the links
    // (the sums below add up in that order). Pulls are met per layer.
    struct Pull {
        item: usize,
        other: usize,
        offset: f32,
        other_offset: f32,
        weight: f32,
    }
    let mut per_layer = vec![0usize; g.layers];
    for (a, b) in links(g) {
        for s in [a, b] {
            per_layer[g.items[stop_item(g, s)].1] += 1;
        }
    }
    let mut pulls: Vec<Vec<Pull>> = per_layer.iter().map(|&n| Vec::with_capacity(n)).collect();
    for (a, b) in links(g) {
        for (s, o) in [(a, b), (b, a)] {
            let (si, oi) = (stop_item(g, s), stop_item(g, o));
            if si == oi {
                continue;
            }
            pulls[g.items[si].1].push(Pull {
                item: si,
                other: oi,
                offset: offset_of(s),
                other_offset: offset_of(o),
                weight: match (s, o) {
                    (Stop::Dummy(_), Stop::Dummy(_)) => 4.0,
                    (Stop::Dummy(_), _) | (_, Stop::Dummy(_)) => 2.0,
                    _ => 1.0,
                },
            });
        }
    }
    let mut want = vec![(0.0f32, 0.0f32); g.items.len()];
    // The lists of one layer, reused from layer to layer and round to round.
    let widest = g.order.iter().map(Vec::len).max().unwrap_or(0);
    let mut target = Vec::with_capacity(widest);
    let mut weight = Vec::with_capacity(widest);
    let mut off = Vec::with_capacity(widest);
    let mut pooled = Pooled::with_capacity(widest);
    for round in 0..16 {
        // A round that moves nothing leaves every later round nothing to move (each layer's
        // tops depend only on the tops): stop there, with the very same result.
        let mut moved = false;
        for step in 0..g.layers {
            // Down the layers in even rounds, up in odd ones.
            let l = if round % 2 == 0 {
                step
            } else {
                g.layers - 1 - step
            };
            // Desired tops.
            for &it in &g.order[l] {
                want[it] = (0.0, 0.0);
            }
            for p in &pulls[l] {
                let oy = top[p.other] + p.other_offset;
                want[p.item].0 += p.weight * (oy - p.offset);
                want[p.item].1 += p.weight;
            }
            let list = &g.order[l];
            target.clear();
            weight.clear();
            off.clear();
            let mut acc = 0.0;
            for (k, &it) in list.iter().enumerate() {
                if k > 0 {
                    acc += height(list[k - 1]) + gap(list[k - 1], it);
                }
                off.push(acc);
                let (t, w) = match fixed[it] {
                    Some(f) => (f, LOC_WEIGHT),
                    None if want[it].1 > 0.0 => (want[it].0 / want[it].1, want[it].1),
                    None => (top[it], 0.05),
                };
                target.push(t - acc);
                weight.push(w);
            }
            let z = pooled.isotonic(&target, &weight);
            for (k, &it) in list.iter().enumerate() {
                let y = z[k] + off[k];
                moved |= y.to_bits() != top[it].to_bits();
                top[it] = y;
            }
        }
        if !moved {
            break;
        }
    }
    // Everything below the margin, on whole pixels.
    let min = top.iter().copied().fold(f32::INFINITY, f32::min);
    let shift = if min.is_finite() { MARGIN - min } else { 0.0 };
    // Rounding may bring two items closer than their gap: round the running sum instead.
    let mut out = vec![0.0f32; g.items.len()];
    for l in &g.order {
        let mut prev: Option<(usize, f32)> = None;
        for &it in l {
            let mut y = (top[it] + shift).round();
            if let Some((p, py)) = prev {
                y = y.max(py + height(p) + gap(p, it));
            }
            out[it] = y;
            prev = Some((it, y));
        }
    }
    // Straighten small jogs: an item a few pixels off a neighbour it links to moves level
    // with it when its layer leaves room.
    for _ in 0..3 {
        for (a, b) in links(g) {
            for (s, o) in [(a, b), (b, a)] {
                let (si, oi) = (stop_item(g, s), stop_item(g, o));
                if si == oi || g.items[si].1 == g.items[oi].1 {
                    continue;
                }
                let dy = out[oi] + offset_of(o) - (out[si] + offset_of(s));
                if dy == 0.0 || dy.abs() > 10.0 {
                    continue;
                }
                let l = &g.order[g.items[si].1];
                let Some(k) = l.iter().position(|&x| x == si) else {
                    continue;
                };
                let y = out[si] + dy;
                let above_ok = k == 0 || out[l[k - 1]] + height(l[k - 1]) + gap(l[k - 1], si) <= y;
                let below_ok =
                    k + 1 == l.len() || y + height(si) + gap(si, l[k + 1]) <= out[l[k + 1]];
                if above_ok && below_ok && y >= MARGIN {
                    out[si] = y;
                }
            }
        }
    }
    out
}

/// Weighted isotonic regression (non-decreasing) by pooling adjacent violators, with its
/// lists kept from call to call.
struct Pooled {
    /// Blocks: (value, weight, count).
    blocks: Vec<(f32, f32, usize)>,
    out: Vec<f32>,
}

impl Pooled {
    fn with_capacity(n: usize) -> Pooled {
        Pooled {
            blocks: Vec::with_capacity(n),
            out: Vec::with_capacity(n),
        }
    }

    /// The non-decreasing values nearest `target` under `weight`.
    fn isotonic(&mut self, target: &[f32], weight: &[f32]) -> &[f32] {
        let blocks = &mut self.blocks;
        blocks.clear();
        for (&t, &w) in target.iter().zip(weight) {
            blocks.push((t, w, 1));
            while blocks.len() >= 2 {
                let b = blocks[blocks.len() - 1];
                let a = blocks[blocks.len() - 2];
                if a.0 <= b.0 {
                    break;
                }
                let w = a.1 + b.1;
                let v = if w > 0.0 {
                    (a.0 * a.1 + b.0 * b.1) / w
                } else {
                    (a.0 + b.0) / 2.0
                };
                blocks.pop();
                blocks.pop();
                blocks.push((v, w, a.2 + b.2));
            }
        }
        self.out.clear();
        for &(v, _, n) in blocks.iter() {
            self.out.extend(std::iter::repeat_n(v, n));
        }
        &self.out
    }
}

/// Geometry problems of a layout, described (an empty list when it is sound): a connector
/// segment through a box other than at its own port, a name wider or taller than its box by
/// the width estimate, anything outside the drawing, or a connector not orthogonal.
pub fn problems(l: &WiringLayout) -> Vec<String> {
    let mut out = Vec::new();
    let inside_drawing = |x: f32, y: f32| x >= 0.0 && y >= 0.0 && x <= l.width && y <= l.height;
    for (i, b) in l.nodes.iter().enumerate() {
        // The box with its port squares (6 px each side of the edge).
        if !inside_drawing(b.x - 7.0, b.y) || !inside_drawing(b.x + b.w + 7.0, b.y + b.h) {
            out.push(format!("box {i} outside the drawing"));
        }
        for t in &b.title.lines {
            if title_w(t) > b.w - 4.0 {
                out.push(format!("title {t:?} wider than its box"));
            }
        }
        for t in &b.subtitle.lines {
            if subtitle_w(t) > b.w - 4.0 {
                out.push(format!("component name {t:?} wider than its box"));
            }
        }
        let title_bottom = if b.subtitle.lines.is_empty() {
            b.title.last_baseline()
        } else {
            b.subtitle.last_baseline()
        } + 4.0;
        if title_bottom > b.y + b.h {
            out.push(format!("title of box {i} below the box"));
        }
        // Port names: inside the box, left and right names apart.
        let mut left_end = b.x;
        let mut right_start = b.x + b.w;
        for p in &b.ports {
            let w = max_w(&p.lines, &port_w);
            let (x0, x1) = match p.side {
                Side::Left => (p.text_x, p.text_x + w),
                Side::Right => (p.text_x - w, p.text_x),
            };
            if x0 < b.x + 7.0 || x1 > b.x + b.w - 7.0 {
                out.push(format!("port name {:?} outside its box", p.lines.concat()));
            }
            let top = p.text_y - 10.0;
            let bottom = p.text_y + PORT_LINE * (p.lines.len() as f32 - 1.0) + 3.0;
            if top < b.y || bottom > b.y + b.h || top < title_bottom - 2.0 {
                out.push(format!(
                    "port name {:?} above or below its box",
                    p.lines.concat()
                ));
            }
            match p.side {
                Side::Left => left_end = left_end.max(x1),
                Side::Right => right_start = right_start.min(x0),
            }
        }
        if left_end > right_start {
            out.push(format!("port names of box {i} overlap"));
        }
    }
    for (e, r) in l.routes.iter().enumerate() {
        let Some(r) = r else { continue };
        for w in r.windows(2) {
            let (a, b) = (w[0], w[1]);
            if !inside_drawing(a.0, a.1) || !inside_drawing(b.0, b.1) {
                out.push(format!("connector {e} leaves the drawing"));
            }
            if (a.0 - b.0).abs() > 0.01 && (a.1 - b.1).abs() > 0.01 {
                out.push(format!("connector {e} has a slanted segment"));
            }
            for (i, bx) in l.nodes.iter().enumerate() {
                if segment_enters(a, b, bx) {
                    out.push(format!("connector {e} runs through box {i}"));
                }
            }
        }
    }
    out
}

/// Connectors that share a stretch of track (an empty list when none do): two segments of
/// different connectors on one line overlapping by more than 2 px, which would make one seem to
/// branch into the other. Connectors that share a port (fan-out from one out-port) may share
/// the way out of it.
pub fn shared_tracks(l: &WiringLayout, edges: &[Edge]) -> Vec<String> {
    // Every segment: (horizontal, the line's coordinate, from, to along it, connector).
    let mut segs: Vec<(bool, f32, f32, f32, usize)> = Vec::new();
    for (e, r) in l.routes.iter().enumerate() {
        let Some(r) = r else { continue };
        for w in r.windows(2) {
            let ((ax, ay), (bx, by)) = (w[0], w[1]);
            if (ay - by).abs() < 0.01 {
                segs.push((true, ay, ax.min(bx), ax.max(bx), e));
            } else if (ax - bx).abs() < 0.01 {
                segs.push((false, ax, ay.min(by), ay.max(by), e));
            }
        }
    }
    segs.sort_by(|a, b| {
        (a.0, a.1, a.2)
            .partial_cmp(&(b.0, b.1, b.2))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let related = |a: usize, b: usize| {
        let (ea, eb) = (&edges[a], &edges[b]);
        a == b
            || [ea.from, ea.to]
                .iter()
                .any(|p| *p == eb.from || *p == eb.to)
    };
    let mut out = Vec::new();
    for (i, a) in segs.iter().enumerate() {
        for b in &segs[i + 1..] {
            if b.0 != a.0 || (b.1 - a.1).abs() > 0.01 || b.2 >= a.3 {
                break;
            }
            if a.3.min(b.3) - b.2 > 2.0 && !related(a.4, b.4) {
                let axis = if a.0 { "y" } else { "x" };
                out.push(format!(
                    "connectors {} and {} share {axis}={} from {} to {}",
                    a.4,
                    b.4,
                    a.1,
                    b.2,
                    a.3.min(b.3)
                ));
            }
        }
    }
    out
}

/// Whether the axis-parallel segment a–b passes through the inside of box `b` (touching its
/// edge, as a connector does at its port, is not entering).
pub fn segment_enters(a: (f32, f32), b: (f32, f32), bx: &NodeBox) -> bool {
    let (x0, x1) = (a.0.min(b.0), a.0.max(b.0));
    let (y0, y1) = (a.1.min(b.1), a.1.max(b.1));
    let e = 0.5;
    x1 > bx.x + e && x0 < bx.x + bx.w - e && y1 > bx.y + e && y0 < bx.y + bx.h - e
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(name: &str, ports: &[(&str, PortKind)]) -> Node {
        Node {
            name: name.into(),
            component: String::new(),
            ports: ports
                .iter()
                .map(|(n, k)| Port {
                    name: n.to_string(),
                    kind: *k,
                })
                .collect(),
            location: None,
        }
    }

    #[test]
    fn a_chain_runs_left_to_right_straight() {
        use PortKind::*;
        let n = vec![
            node("a", &[("out", Out)]),
            node("b", &[("in", In), ("out", Out)]),
            node("c", &[("in", In)]),
        ];
        let e = vec![
            Edge {
                from: (0, 0),
                to: (1, 0),
                service: false,
            },
            Edge {
                from: (1, 1),
                to: (2, 0),
                service: false,
            },
        ];
        let l = layout(&n, &e);
        assert!(problems(&l).is_empty(), "{:?}", problems(&l));
        assert!(l.nodes[0].x < l.nodes[1].x && l.nodes[1].x < l.nodes[2].x);
        // The first connector is one straight segment.
        assert_eq!(
            l.routes[0].as_ref().map(Vec::len),
            Some(2),
            "{:?}",
            l.routes
        );
    }

    #[test]
    fn isotonic_pools_violators() {
        let mut pooled = Pooled::with_capacity(0);
        assert_eq!(
            pooled.isotonic(&[1.0, 3.0, 2.0], &[1.0, 1.0, 1.0]),
            [1.0, 2.5, 2.5]
        );
        // The lists kept from the call before leave nothing behind.
        assert_eq!(pooled.isotonic(&[4.0], &[1.0]), [4.0]);
    }
}
