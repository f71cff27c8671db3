//! The wiring diagram of an RT System: each instance a box with its ports on the sides (data
//! in-ports on the left, out-ports on the right, service ports on the side facing their
//! partners), data connectors as lines from out-port to in-port, service connectors as dashed
//! lines, routed around the boxes with rounded bends. The geometry comes from
//! [`crate::layout::wiring`]; this module only draws it.
//!
//! Hooks for styles and tests (documented in `book/src/themes.md`): `svg.system-diagram`, each
//! instance a `g.instance` whose `rect.rtc-box` is its box, each connector a `path.connector`
//! with `data` or `service`. The drawing is a `role="group"` (not `role="img"`: it holds links),
//! each instance and port a link named by `aria-label` and a `<title>`.

use super::svg::esc;
use crate::layout::wiring::{layout_with, Edge, Effort, Node, Port, PortKind, Side};
use crate::render::wiring::{WireConnector, WireInstance};
use std::fmt::Write;

/// A coordinate of the drawing, written exactly as `f32`'s `Display` writes it. The layout's
/// coordinates are whole or half pixels, which are written here as an integer and `.5`
/// without `Display`'s general shortest-digits search (half of the drawing's time at 10,000
/// profiles went there); any other value is handed to `Display`.
#[derive(Clone, Copy)]
struct Num(f32);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = self.0;
        let twice = v * 2.0;
        // Below a million an f32 is exact to 1/16, so a whole or half value's shortest digits
        // are its integer part and `.5`; -0 is left to `Display` (it writes `-0`).
        if v.abs() < 1e6 && twice == twice.trunc() && !(v == 0.0 && v.is_sign_negative()) {
            let t = twice as i64;
            let m = t.unsigned_abs();
            let sign = if t < 0 { "-" } else { "" };
            if m % 2 == 0 {
                write!(f, "{sign}{}", m / 2)
            } else {
                write!(f, "{sign}{}.5", m / 2)
            }
        } else {
            std::fmt::Display::fmt(&v, f)
        }
    }
}

impl WireInstance {
    /// The layout's view of this instance.
    pub fn node(&self) -> Node {
        Node {
            name: self.name.clone(),
            component: self.component.clone(),
            ports: self
                .ports
                .iter()
                .map(|p| Port {
                    name: p.name.clone(),
                    kind: match p.class {
                        "in" => PortKind::In,
                        "out" => PortKind::Out,
                        "service" => PortKind::Service,
                        _ => PortKind::Other,
                    },
                })
                .collect(),
            location: self.location,
        }
    }
}

impl WireConnector {
    /// The layout's view of this connector.
    pub fn edge(&self) -> Edge {
        Edge {
            from: self.from,
            to: self.to,
            service: self.service,
        }
    }
}

/// The layout of a wiring.
#[cfg(test)]
pub fn wiring_layout(
    inst: &[WireInstance],
    conns: &[WireConnector],
) -> crate::layout::wiring::WiringLayout {
    let nodes: Vec<Node> = inst.iter().map(WireInstance::node).collect();
    let edges: Vec<Edge> = conns.iter().map(WireConnector::edge).collect();
    crate::layout::wiring::layout(&nodes, &edges)
}

/// ` href="…"`, or nothing for an empty link (a drawing on its own).
fn href_attr(h: &str) -> String {
    if h.is_empty() {
        String::new()
    } else {
        format!(" href=\"{}\"", esc(h))
    }
}

/// -1, 0 or 1 (`f32::signum` gives 1 for 0).
fn sign(v: f32) -> f32 {
    if v > 0.0 {
        1.0
    } else if v < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// An orthogonal polyline as a path with rounded bends (radius up to 6, less where a segment
/// is short).
fn rounded_path(pts: &[(f32, f32)]) -> String {
    let mut d = String::new();
    let Some(&(x0, y0)) = pts.first() else {
        return d;
    };
    let _ = write!(d, "M{},{}", Num(x0), Num(y0));
    for k in 1..pts.len() {
        let (x, y) = pts[k];
        if k + 1 < pts.len() {
            let (px, py) = pts[k - 1];
            let (nx, ny) = pts[k + 1];
            let len_in = (x - px).abs() + (y - py).abs();
            let len_out = (nx - x).abs() + (ny - y).abs();
            let r = 6.0f32.min(len_in / 2.0).min(len_out / 2.0);
            let (ix, iy) = (sign(x - px), sign(y - py));
            let (ox, oy) = (sign(nx - x), sign(ny - y));
            let _ = write!(
                d,
                " L{},{} Q{},{} {},{}",
                Num(x - ix * r),
                Num(y - iy * r),
                Num(x),
                Num(y),
                Num(x + ox * r),
                Num(y + oy * r)
            );
        } else {
            let _ = write!(d, " L{},{}", Num(x), Num(y));
        }
    }
    d
}

/// The wiring diagram. `title` names the drawing for assistive technology.
pub fn system_diagram(title: &str, inst: &[WireInstance], conns: &[WireConnector]) -> String {
    system_diagram_with(title, inst, conns, Effort::Full)
}

/// [`system_diagram`] laid out with the given [`Effort`].
pub fn system_diagram_with(
    title: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
    effort: Effort,
) -> String {
    let nodes: Vec<Node> = inst.iter().map(WireInstance::node).collect();
    let edges: Vec<Edge> = conns.iter().map(WireConnector::edge).collect();
    let l = layout_with(&nodes, &edges, effort);
    let (width, height) = (Num(l.width), Num(l.height));
    let mut s = String::with_capacity(4096 + inst.len() * 1024);
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" class="diagram system-diagram" viewBox="0 0 {width} {height}" width="{width}" height="{height}" role="group" aria-label="{t}"><title>{t}</title>"#,
        t = esc(title)
    );
    // Connectors first, under the boxes.
    s.push_str(r#"<g class="connectors">"#);
    for (c, route) in conns.iter().zip(&l.routes) {
        let Some(route) = route else { continue };
        let _ = write!(
            s,
            r#"<path class="connector{}" d="{}"><title>{}</title></path>"#,
            if c.service { " service" } else { " data" },
            rounded_path(route),
            esc(&c.label)
        );
    }
    s.push_str("</g>");
    for (it, b) in inst.iter().zip(&l.nodes) {
        let (x, y) = (Num(b.x), Num(b.y));
        let cx = Num(b.x + b.w / 2.0);
        let _ = write!(
            s,
            r#"<g class="instance"><a{} aria-label="{l}"><title>{l}</title><rect class="rtc-box" x="{x}" y="{y}" width="{}" height="{}" rx="4"/><text class="rtc-name" x="{cx}" y="{}" text-anchor="middle">"#,
            href_attr(&it.href),
            Num(b.w),
            Num(b.h),
            Num(b.title_y),
            l = esc(&it.label),
        );
        for (k, line) in b.title.iter().enumerate() {
            if k == 0 {
                s.push_str(&esc(line));
            } else {
                let _ = write!(s, r#"<tspan x="{cx}" dy="18">{}</tspan>"#, esc(line));
            }
        }
        // The component's name is a further line of the same text, after a space: the link's
        // visible text reads "instance component", as its accessible name begins.
        let mut prev_y = b.title_y + 18.0 * (b.title.len() as f32 - 1.0);
        for (k, line) in b.subtitle.iter().enumerate() {
            let ty = b.subtitle_y + 15.0 * k as f32;
            let _ = write!(
                s,
                r#"<tspan class="stereotype" x="{cx}" dy="{}">{}{}</tspan>"#,
                Num(ty - prev_y),
                if k == 0 { " " } else { "" },
                esc(line)
            );
            prev_y = ty;
        }
        s.push_str("</text></a>");
        for (p, pl) in it.ports.iter().zip(&b.ports) {
            let (px, py) = (Num(pl.x), Num(pl.y));
            let _ = write!(
                s,
                r#"<a{} class="port {}" aria-label="{l}"><title>{l}</title>"#,
                href_attr(&p.href),
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
                    Num(pl.x - 6.0),
                    Num(pl.y - 6.0)
                );
            }
            let anchor = match pl.side {
                Side::Left => "start",
                Side::Right => "end",
            };
            let _ = write!(
                s,
                r#"<text class="port-name" x="{}" y="{}" text-anchor="{anchor}">"#,
                Num(pl.text_x),
                Num(pl.text_y)
            );
            for (k, line) in pl.lines.iter().enumerate() {
                if k == 0 {
                    s.push_str(&esc(line));
                } else {
                    let _ = write!(
                        s,
                        r#"<tspan x="{}" dy="13">{}</tspan>"#,
                        Num(pl.text_x),
                        esc(line)
                    );
                }
            }
            s.push_str("</text></a>");
        }
        s.push_str("</g>");
    }
    s.push_str("</svg>");
    s
}

/// Colours of a drawing opened on its own (no site style sheet): the light theme's.
const STANDALONE_STYLE: &str = "<style>text{font-family:system-ui,sans-serif;font-size:12px;fill:#1f2328}.rtc-box{fill:#f3f6fb;stroke:#33415c;stroke-width:1.6}.rtc-name{font-size:15px;font-weight:700}.stereotype{fill:#5b6472;font-size:12px;font-weight:400}.port-name{font-size:11px}.port-square{stroke:#33415c;stroke-width:1.2;fill:#fff}a.in .port-square{fill:#1f7a4d}a.out .port-square{fill:#b8561c}a.service .port-square{fill:#5b6472}.connector{fill:none;stroke:#33415c;stroke-width:1.6}.connector.service{stroke-dasharray:6 4}</style>";

/// The wiring diagram as a file of its own (`rtcdoc graph --format svg`): the same drawing
/// with its colours in a `<style>` element.
pub fn standalone_system_diagram(
    title: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
) -> String {
    // No links: the pages they would point to are not beside the file.
    let bare: Vec<WireInstance> = inst
        .iter()
        .map(|i| {
            let mut i = i.clone();
            i.href.clear();
            for p in &mut i.ports {
                p.href.clear();
            }
            i
        })
        .collect();
    let svg = system_diagram(title, &bare, conns);
    match svg.find("</title>") {
        Some(i) => {
            let at = i + "</title>".len();
            format!(
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n{}{STANDALONE_STYLE}{}\n",
                &svg[..at],
                &svg[at..]
            )
        }
        None => svg,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::wiring::WirePort;

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
    fn coordinates_are_written_as_display_writes_them() {
        let mut values = vec![
            0.0f32,
            -0.0,
            0.5,
            -0.5,
            1.5,
            -1.5,
            0.25,
            -0.75,
            0.1,
            1.0 / 3.0,
        ];
        values.extend([
            999_999.5,
            1e6,
            1e6 + 0.5,
            -1e6,
            3e9,
            1e-7,
            f32::MAX,
            f32::MIN,
        ]);
        values.extend([f32::NAN, f32::INFINITY, f32::NEG_INFINITY]);
        values.extend((-4000..4000).map(|i| i as f32 / 4.0));
        values.extend((0..2000).map(|i| i as f32 * 0.1 + 7.0));
        for v in values {
            assert_eq!(Num(v).to_string(), v.to_string(), "{v:?}");
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
        let l = wiring_layout(&v, &c);
        assert!(l.nodes[1].x > l.nodes[0].x, "{l:?}");
        let p = crate::layout::wiring::problems(&l);
        assert!(p.is_empty(), "{p:?}");
        let svg = system_diagram("sys", &v, &c);
        assert!(svg.contains(r#"role="group""#) && !svg.contains("role=\"img\""));
        assert_eq!(svg.matches("<path class=\"connector data\"").count(), 2);
        assert!(svg.contains(r##"<a href="#a" aria-label="instance a">"##));
        assert!(svg.contains(r##"aria-label="port b.i""##));
    }

    #[test]
    fn locations_keep_the_arrangement_unless_they_coincide() {
        // b saved left of a: kept left of it.
        let v = vec![inst("a", &[], Some((300, 0))), inst("b", &[], Some((0, 0)))];
        let l = wiring_layout(&v, &[]);
        assert!(l.from_locations && l.nodes[1].x < l.nodes[0].x, "{l:?}");
        // Two instances at the same place: laid out instead.
        let same = vec![inst("a", &[], Some((5, 5))), inst("b", &[], Some((5, 5)))];
        assert!(!wiring_layout(&same, &[]).from_locations);
    }
}
