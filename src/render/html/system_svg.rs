//! The wiring diagram of an RT System: each instance a box with its ports on the sides (data
//! in-ports on the left, out-ports and service ports on the right, as the component diagram
//! draws a component), data connectors as lines from out-port to in-port, service connectors as
//! dashed lines from the required side to the provided side.
//!
//! Placed where RTSystemEditor drew the instances (`rtsExt:Location`) when every instance has a
//! location and the boxes, scaled to fit, do not overlap; otherwise by a layered layout (longest
//! path over the data connectors, left to right). The drawing is a `role="group"` (not
//! `role="img"`: it holds links), each instance and port a link named by `aria-label` and a
//! `<title>`.

use super::svg::esc;
use std::fmt::Write;

/// A port as drawn.
pub struct WirePort {
    pub name: String,
    /// `in`, `out`, `service` or `other` (CSS class and side).
    pub class: &'static str,
    /// Where the port's link goes (the component page's port row, or the instance row).
    pub href: String,
    /// Accessible name of the link.
    pub label: String,
}

/// An instance as drawn.
pub struct WireInstance {
    pub name: String,
    /// The component's name (second line), when known.
    pub component: String,
    pub href: String,
    pub label: String,
    pub ports: Vec<WirePort>,
    /// `rtsExt:Location` x/y, when given as integers.
    pub location: Option<(i64, i64)>,
}

/// A connector between two ports: (instance, port) indices into the drawn instances.
pub struct WireConnector {
    pub from: (usize, usize),
    pub to: (usize, usize),
    pub service: bool,
    pub label: String,
}

const ROW: f32 = 22.0;
const HEADER: f32 = 44.0;
const GAP_X: f32 = 140.0;
const GAP_Y: f32 = 40.0;
const MARGIN: f32 = 20.0;

fn text_width(s: &str, px: f32) -> f32 {
    s.chars()
        .map(|c| if (c as u32) >= 0x2E80 { px } else { px * 0.6 })
        .sum()
}

fn clip(s: &str, max: usize) -> String {
    if s.chars().count() <= max {
        s.to_string()
    } else {
        let mut c: String = s.chars().take(max - 1).collect();
        c.push('…');
        c
    }
}

struct BoxGeom {
    w: f32,
    h: f32,
    /// Ports on the left, on the right: indices into the instance's ports.
    left: Vec<usize>,
    right: Vec<usize>,
}

fn geometry(i: &WireInstance) -> BoxGeom {
    let mut left = Vec::new();
    let mut right = Vec::new();
    for (k, p) in i.ports.iter().enumerate() {
        if p.class == "in" {
            left.push(k);
        } else {
            right.push(k);
        }
    }
    let label_w = |v: &[usize]| {
        v.iter()
            .map(|&k| text_width(&clip(&i.ports[k].name, 28), 11.0))
            .fold(0.0, f32::max)
    };
    let w = [
        150.0,
        text_width(&clip(&i.name, 40), 13.0) + 24.0,
        text_width(&clip(&i.component, 40), 11.0) + 24.0,
        label_w(&left) + label_w(&right) + 40.0,
    ]
    .into_iter()
    .fold(0.0, f32::max)
    .ceil();
    let h = (HEADER + left.len().max(right.len()) as f32 * ROW + 8.0).ceil();
    BoxGeom { w, h, left, right }
}

/// Top-left corners from the instances' locations, scaled apart until no boxes overlap (at
/// most 4×); `None` when an instance has no location or they overlap even then.
fn from_locations(inst: &[WireInstance], geo: &[BoxGeom]) -> Option<Vec<(f32, f32)>> {
    let locs: Vec<(i64, i64)> = inst.iter().map(|i| i.location).collect::<Option<_>>()?;
    let minx = locs.iter().map(|l| l.0).min()? as f32;
    let miny = locs.iter().map(|l| l.1).min()? as f32;
    for step in 0..=12 {
        let f = 1.0 + step as f32 * 0.25;
        let pos: Vec<(f32, f32)> = locs
            .iter()
            .map(|&(x, y)| {
                (
                    MARGIN + 90.0 + (x as f32 - minx) * f,
                    MARGIN + (y as f32 - miny) * f,
                )
            })
            .collect();
        let overlap = (0..pos.len()).any(|a| {
            (a + 1..pos.len()).any(|b| {
                let (ax, ay) = pos[a];
                let (bx, by) = pos[b];
                ax < bx + geo[b].w + 20.0
                    && bx < ax + geo[a].w + 20.0
                    && ay < by + geo[b].h + 20.0
                    && by < ay + geo[a].h + 20.0
            })
        });
        if !overlap {
            return Some(pos);
        }
    }
    None
}

/// Layers by longest path over the data connectors (a cycle is cut where a search meets an
/// instance already on its path); each layer a column, instances stacked in input order.
fn layered(inst: &[WireInstance], geo: &[BoxGeom], conns: &[WireConnector]) -> Vec<(f32, f32)> {
    let n = inst.len();
    let mut succ: Vec<Vec<usize>> = vec![Vec::new(); n];
    for c in conns.iter().filter(|c| !c.service) {
        if c.from.0 != c.to.0 && c.from.0 < n && c.to.0 < n {
            succ[c.from.0].push(c.to.0);
        }
    }
    // Depth-first order, then longest path on the acyclic part.
    let mut layer = vec![0usize; n];
    let mut state = vec![0u8; n]; // 0 new, 1 on the path, 2 done
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
    let rank: Vec<usize> = {
        let mut r = vec![0; n];
        for (k, &v) in order.iter().enumerate() {
            r[v] = k;
        }
        r
    };
    for &v in &order {
        for &w in &succ[v] {
            if rank[w] > rank[v] {
                layer[w] = layer[w].max(layer[v] + 1);
            }
        }
    }
    let layers = layer.iter().copied().max().map_or(0, |m| m + 1);
    let mut col_w = vec![0.0f32; layers];
    for (v, &l) in layer.iter().enumerate() {
        col_w[l] = col_w[l].max(geo[v].w);
    }
    let mut col_x = Vec::with_capacity(layers);
    let mut x = MARGIN + 90.0;
    for w in &col_w {
        col_x.push(x);
        x += w + GAP_X + 90.0;
    }
    let mut col_y = vec![MARGIN; layers];
    let mut pos = vec![(0.0, 0.0); n];
    for v in 0..n {
        let l = layer[v];
        pos[v] = (col_x[l], col_y[l]);
        col_y[l] += geo[v].h + GAP_Y;
    }
    pos
}

/// The wiring diagram. `title` names the drawing for assistive technology.
pub fn system_diagram(title: &str, inst: &[WireInstance], conns: &[WireConnector]) -> String {
    let geo: Vec<BoxGeom> = inst.iter().map(geometry).collect();
    let pos = from_locations(inst, &geo).unwrap_or_else(|| layered(inst, &geo, conns));
    // Port anchor points.
    let point = |i: usize, k: usize| -> (f32, f32) {
        let g = &geo[i];
        let (x, y) = pos[i];
        if let Some(r) = g.left.iter().position(|&p| p == k) {
            (x, y + HEADER + r as f32 * ROW + ROW / 2.0)
        } else {
            let r = g.right.iter().position(|&p| p == k).unwrap_or(0);
            (x + g.w, y + HEADER + r as f32 * ROW + ROW / 2.0)
        }
    };
    let width = (0..inst.len())
        .map(|i| pos[i].0 + geo[i].w + 110.0)
        .fold(300.0, f32::max)
        .ceil();
    let height = (0..inst.len())
        .map(|i| pos[i].1 + geo[i].h + MARGIN)
        .fold(100.0, f32::max)
        .ceil();
    let mut s = String::with_capacity(4096 + inst.len() * 1024);
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" class="diagram system-diagram" viewBox="0 0 {width} {height}" width="{width}" height="{height}" role="group" aria-label="{t}"><title>{t}</title>"#,
        t = esc(title)
    );
    // Connectors first, under the boxes.
    s.push_str(r#"<g class="connectors">"#);
    for c in conns {
        let (Some(a), Some(b)) = (inst.get(c.from.0), inst.get(c.to.0)) else {
            continue;
        };
        if c.from.1 >= a.ports.len() || c.to.1 >= b.ports.len() {
            continue;
        }
        let (x1, y1) = point(c.from.0, c.from.1);
        let (x2, y2) = point(c.to.0, c.to.1);
        let out1 = if x1 >= pos[c.from.0].0 + geo[c.from.0].w - 0.5 {
            1.0
        } else {
            -1.0
        };
        let out2 = if x2 <= pos[c.to.0].0 + 0.5 { -1.0 } else { 1.0 };
        let bend = ((x2 - x1).abs() / 2.0).max(60.0);
        let _ = write!(
            s,
            r#"<path class="connector{}" d="M{x1},{y1} C{},{y1} {},{y2} {x2},{y2}"><title>{}</title></path>"#,
            if c.service { " service" } else { " data" },
            x1 + out1 * bend,
            x2 + out2 * bend,
            esc(&c.label)
        );
    }
    s.push_str("</g>");
    for (i, it) in inst.iter().enumerate() {
        let g = &geo[i];
        let (x, y) = pos[i];
        let _ = write!(
            s,
            r#"<g class="instance"><a href="{}" aria-label="{l}"><title>{l}</title><rect class="rtc-box" x="{x}" y="{y}" width="{}" height="{}" rx="4"/><text class="rtc-name" x="{}" y="{}" text-anchor="middle">{}"#,
            esc(&it.href),
            g.w,
            g.h,
            x + g.w / 2.0,
            y + 18.0,
            esc(&clip(&it.name, 40)),
            l = esc(&it.label),
        );
        // The component's name is a second line of the same text, after a space: the link's
        // visible text reads "instance component", as its accessible name begins.
        if !it.component.is_empty() {
            let _ = write!(
                s,
                r#"<tspan class="stereotype" x="{}" dy="16"> {}</tspan>"#,
                x + g.w / 2.0,
                esc(&clip(&it.component, 40))
            );
        }
        s.push_str("</text></a>");
        for (side, list) in [(false, &g.left), (true, &g.right)] {
            for &k in list.iter() {
                let p = &it.ports[k];
                let (px, py) = point(i, k);
                let _ = write!(
                    s,
                    r#"<a href="{}" class="port {}" aria-label="{l}"><title>{l}</title>"#,
                    esc(&p.href),
                    p.class,
                    l = esc(&p.label)
                );
                if p.class == "service" {
                    let _ = write!(
                        s,
                        r#"<circle class="port-square" cx="{px}" cy="{py}" r="6"/>"#
                    );
                } else {
                    let _ = write!(
                        s,
                        r#"<rect class="port-square" x="{}" y="{}" width="12" height="12"/>"#,
                        px - 6.0,
                        py - 6.0
                    );
                }
                let (tx, anchor) = if side {
                    (px - 10.0, "end")
                } else {
                    (px + 10.0, "start")
                };
                let _ = write!(
                    s,
                    r#"<text class="port-name" x="{tx}" y="{}" text-anchor="{anchor}">{}</text></a>"#,
                    py + 4.0,
                    esc(&clip(&p.name, 28))
                );
            }
        }
        s.push_str("</g>");
    }
    s.push_str("</svg>");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inst(name: &str, ports: &[(&str, &'static str)], loc: Option<(i64, i64)>) -> WireInstance {
        WireInstance {
            name: name.into(),
            component: String::new(),
            href: format!("#{name}"),
            label: format!("instance {name}"),
            ports: ports
                .iter()
                .map(|(n, c)| WirePort {
                    name: n.to_string(),
                    class: c,
                    href: format!("#{name}-{n}"),
                    label: format!("port {name}.{n}"),
                })
                .collect(),
            location: loc,
        }
    }

    #[test]
    fn layered_layout_puts_targets_right_of_sources_and_survives_cycles() {
        let v = vec![
            inst("a", &[("o", "out"), ("i", "in")], None),
            inst("b", &[("i", "in"), ("o", "out")], None),
        ];
        let c = vec![
            WireConnector {
                from: (0, 0),
                to: (1, 0),
                service: false,
                label: "a.o → b.i".into(),
            },
            WireConnector {
                from: (1, 1),
                to: (0, 1),
                service: false,
                label: "b.o → a.i".into(),
            },
        ];
        let geo: Vec<BoxGeom> = v.iter().map(geometry).collect();
        let pos = layered(&v, &geo, &c);
        assert!(pos[1].0 > pos[0].0, "{pos:?}");
        let svg = system_diagram("sys", &v, &c);
        assert!(svg.contains(r#"role="group""#) && !svg.contains("role=\"img\""));
        assert_eq!(svg.matches("<path class=\"connector data\"").count(), 2);
        assert!(svg.contains(r##"<a href="#a" aria-label="instance a">"##));
        assert!(svg.contains(r##"aria-label="port b.i""##));
    }

    #[test]
    fn locations_are_used_and_scaled_apart() {
        let v = vec![inst("a", &[], Some((0, 0))), inst("b", &[], Some((100, 0)))];
        let geo: Vec<BoxGeom> = v.iter().map(geometry).collect();
        let pos = from_locations(&v, &geo).expect("fits");
        assert!(pos[1].0 - pos[0].0 >= geo[0].w, "{pos:?}");
        // Two instances at the same place cannot be scaled apart: laid out instead.
        let same = vec![inst("a", &[], Some((5, 5))), inst("b", &[], Some((5, 5)))];
        let geo: Vec<BoxGeom> = same.iter().map(geometry).collect();
        assert!(from_locations(&same, &geo).is_none());
    }
}
