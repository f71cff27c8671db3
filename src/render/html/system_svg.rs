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

use super::svg::{attr_num, esc_into, num};
use crate::layout::wiring::{layout_with, Edge, Effort, Node, NodeBox, Port, PortKind, Side};
use crate::render::wiring::{WireConnector, WireInstance};

/// Appends `x,y`.
fn point(s: &mut String, x: f32, y: f32) {
    num(s, x);
    s.push(',');
    num(s, y);
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

/// Appends ` href="…"`, or nothing for an empty link (a drawing on its own).
fn href_attr(s: &mut String, h: &str) {
    if !h.is_empty() {
        s.push_str(" href=\"");
        esc_to(s, h);
        s.push('"');
    }
}

/// Appends `t` escaped.
fn esc_to(s: &mut String, t: &str) {
    // Writing to a String cannot fail.
    let _ = esc_into(s, t);
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

/// Appends an orthogonal polyline as a path with rounded bends (radius up to 6, less where a
/// segment is short).
fn rounded_path(d: &mut String, pts: &[(f32, f32)]) {
    let Some(&(x0, y0)) = pts.first() else {
        return;
    };
    d.push('M');
    point(d, x0, y0);
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
            d.push_str(" L");
            point(d, x - ix * r, y - iy * r);
            d.push_str(" Q");
            point(d, x, y);
            d.push(' ');
            point(d, x + ox * r, y + oy * r);
        } else {
            d.push_str(" L");
            point(d, x, y);
        }
    }
}

/// The wiring diagram. `title` names the drawing for assistive technology.
pub fn system_diagram(title: &str, inst: &[WireInstance], conns: &[WireConnector]) -> String {
    system_diagram_with(title, inst, conns, Effort::Full, "")
}

/// [`system_diagram`] laid out with the given [`Effort`]; `class` (empty, or starting with a
/// space) is added to the drawing's classes.
pub fn system_diagram_with(
    title: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
    effort: Effort,
    class: &str,
) -> String {
    draw(title, inst, conns, (effort, class), (&[], None))
}

/// Line height and font size of the notes under a drawing.
const NOTE_LINE: f32 = 16.0;
const NOTE_PX: f32 = 12.0;

/// [`system_diagram_with`], with `notes` (what the drawing leaves out, then the legend of its
/// composite outlines) as lines of text under it.
fn draw(
    title: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
    (effort, class): (Effort, &str),
    (not_drawn, legend): crate::render::wiring::DrawingNotes<'_>,
) -> String {
    let notes: Vec<&str> = not_drawn.iter().map(String::as_str).chain(legend).collect();
    let nodes: Vec<Node> = inst.iter().map(WireInstance::node).collect();
    let edges: Vec<Edge> = conns.iter().map(WireConnector::edge).collect();
    let mut l = layout_with(&nodes, &edges, effort);
    let notes_top = l.height;
    if !notes.is_empty() {
        let widest = notes
            .iter()
            .map(|n| crate::layout::text::text_width(n, NOTE_PX))
            .fold(0.0f32, f32::max);
        l.width = l.width.max(widest + 24.0);
        l.height += 8.0 + NOTE_LINE * notes.len() as f32;
    }
    // About what the drawing takes (a box with its ports ~700 bytes, a connector with its
    // route and title ~400), so that it is rarely copied to grow.
    let mut s = String::with_capacity(2048 + inst.len() * 768 + conns.len() * 448);
    s.push_str(r#"<svg xmlns="http://www.w3.org/2000/svg" class="diagram system-diagram"#);
    s.push_str(class);
    s.push_str(r#"" viewBox="0 0 "#);
    num(&mut s, l.width);
    s.push(' ');
    num(&mut s, l.height);
    s.push('"');
    attr_num(&mut s, "width", l.width);
    attr_num(&mut s, "height", l.height);
    s.push_str(r#" role="group" aria-label=""#);
    esc_to(&mut s, title);
    s.push_str(r#""><title>"#);
    esc_to(&mut s, title);
    s.push_str("</title>");
    // Connectors first, under the boxes.
    s.push_str(r#"<g class="connectors">"#);
    for (c, route) in conns.iter().zip(&l.routes) {
        let Some(route) = route else { continue };
        s.push_str(if c.service {
            r#"<path class="connector service" d=""#
        } else {
            r#"<path class="connector data" d=""#
        });
        rounded_path(&mut s, route);
        s.push_str(r#""><title>"#);
        esc_to(&mut s, &c.label);
        s.push_str("</title></path>");
    }
    s.push_str("</g>");
    for (it, b) in inst.iter().zip(&l.nodes) {
        instance(&mut s, it, b);
    }
    // The legend of composite outlines, last, is an explanation, not a warning.
    for (k, n) in notes.iter().enumerate() {
        s.push_str(if k >= not_drawn.len() {
            r#"<text class="legend" x="8""#
        } else {
            r#"<text class="not-drawn" x="8""#
        });
        attr_num(&mut s, "y", notes_top + NOTE_LINE * (k as f32 + 1.0));
        s.push('>');
        esc_to(&mut s, n);
        s.push_str("</text>");
    }
    s.push_str("</svg>");
    s
}

/// Appends one instance: its box with title and component name, and its ports.
fn instance(s: &mut String, it: &WireInstance, b: &NodeBox) {
    let cx = b.x + b.w / 2.0;
    s.push_str(r#"<g class="instance"#);
    s.push_str(it.role.classes());
    s.push_str(r#""><a"#);
    href_attr(s, &it.href);
    s.push_str(r#" aria-label=""#);
    esc_to(s, &it.label);
    s.push_str(r#""><title>"#);
    esc_to(s, &it.label);
    s.push_str(r#"</title><rect class="rtc-box""#);
    attr_num(s, "x", b.x);
    attr_num(s, "y", b.y);
    attr_num(s, "width", b.w);
    attr_num(s, "height", b.h);
    s.push_str(r#" rx="4"/>"#);
    if it.role.composite {
        // A composite's second outline, inside the first.
        s.push_str(r#"<rect class="rtc-box-inner""#);
        attr_num(s, "x", b.x + 3.0);
        attr_num(s, "y", b.y + 3.0);
        attr_num(s, "width", b.w - 6.0);
        attr_num(s, "height", b.h - 6.0);
        s.push_str(r#" rx="2"/>"#);
    }
    s.push_str(r#"<text class="rtc-name""#);
    attr_num(s, "x", cx);
    attr_num(s, "y", b.title.y);
    s.push_str(r#" text-anchor="middle">"#);
    for (k, line) in b.title.lines.iter().enumerate() {
        if k == 0 {
            esc_to(s, line);
        } else {
            s.push_str("<tspan");
            attr_num(s, "x", cx);
            attr_num(s, "dy", b.title.leading);
            s.push('>');
            esc_to(s, line);
            s.push_str("</tspan>");
        }
    }
    // The component's name is a further line of the same text, after a space: the link's
    // visible text reads "instance component", as its accessible name begins.
    let mut prev_y = b.title.last_baseline();
    for (k, line) in b.subtitle.lines.iter().enumerate() {
        let ty = b.subtitle.baseline(k);
        s.push_str(r#"<tspan class="stereotype""#);
        attr_num(s, "x", cx);
        attr_num(s, "dy", ty - prev_y);
        s.push('>');
        if k == 0 {
            s.push(' ');
        }
        esc_to(s, line);
        s.push_str("</tspan>");
        prev_y = ty;
    }
    s.push_str("</text></a>");
    for (p, pl) in it.ports.iter().zip(&b.ports) {
        s.push_str("<a");
        href_attr(s, &p.href);
        s.push_str(r#" class="port "#);
        s.push_str(p.class);
        if p.unknown {
            s.push_str(" unknown");
        }
        s.push_str(r#"" aria-label=""#);
        esc_to(s, &p.label);
        s.push_str(r#""><title>"#);
        esc_to(s, &p.label);
        s.push_str("</title>");
        if p.class == "service" {
            s.push_str(r#"<circle class="port-square""#);
            attr_num(s, "cx", pl.x);
            attr_num(s, "cy", pl.y);
            s.push_str(r#" r="6"/>"#);
        } else {
            s.push_str(r#"<rect class="port-square""#);
            attr_num(s, "x", pl.x - 6.0);
            attr_num(s, "y", pl.y - 6.0);
            s.push_str(r#" width="12" height="12"/>"#);
        }
        // A nameless port (a "+N more" box's) has no text to draw.
        if pl.lines.iter().all(|l| l.is_empty()) {
            s.push_str("</a>");
            continue;
        }
        s.push_str(r#"<text class="port-name""#);
        attr_num(s, "x", pl.text_x);
        attr_num(s, "y", pl.text_y);
        s.push_str(match pl.side {
            Side::Left => r#" text-anchor="start">"#,
            Side::Right => r#" text-anchor="end">"#,
        });
        for (k, line) in pl.lines.iter().enumerate() {
            if k == 0 {
                esc_to(s, line);
            } else {
                s.push_str("<tspan");
                attr_num(s, "x", pl.text_x);
                s.push_str(r#" dy="13">"#);
                esc_to(s, line);
                s.push_str("</tspan>");
            }
        }
        s.push_str("</text></a>");
    }
    s.push_str("</g>");
}

/// Colours of a drawing opened on its own (no site style sheet): the light theme's.
const STANDALONE_STYLE: &str = "<style>text{font-family:system-ui,sans-serif;font-size:12px;fill:#1f2328}.rtc-box{fill:#f3f6fb;stroke:#33415c;stroke-width:1.6}.rtc-name{font-size:15px;font-weight:700}.stereotype{fill:#5b6472;font-size:12px;font-weight:400}.port-name{font-size:11px}.port-square{stroke:#33415c;stroke-width:1.2;fill:#fff}a.in .port-square{fill:#1f7a4d}a.out .port-square{fill:#b8561c}a.service .port-square{fill:#5b6472}.connector{fill:none;stroke:#33415c;stroke-width:1.6}.connector.service{stroke-dasharray:6 4}a.unknown .port-square{fill:#fff;stroke-dasharray:2 2}a.unknown .port-name{font-style:italic}.rtc-box-inner{fill:none;stroke:#33415c;stroke-width:1}.member>a>.rtc-box{stroke-dasharray:6 3}.not-drawn{fill:#a4262c}.legend{fill:#5b6472}</style>";

/// The wiring diagram as a file of its own (`rtcdoc graph --format svg`): the same drawing
/// with its colours in a `<style>` element, and `notes` (what it leaves out: the connectors
/// not drawn, and why; then what the outlines of composites mean) as lines of text under it.
pub fn standalone_system_diagram(
    title: &str,
    inst: &[WireInstance],
    conns: &[WireConnector],
    notes: crate::render::wiring::DrawingNotes<'_>,
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
    let svg = draw(title, &bare, conns, (Effort::Full, ""), notes);
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
                    unknown: false,
                })
                .collect(),
            location: loc,
            role: Default::default(),
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
            let mut s = String::new();
            num(&mut s, v);
            assert_eq!(s, v.to_string(), "{v:?}");
        }
    }

    #[test]
    fn layered_layout_puts_targets_right_of_sources_and_survives_cycles() {
        let v = vec![
            inst("a", &[("o", "out"), ("i", "in")], None),
            inst("b", &[("i", "in"), ("o", "out")], None),
        ];
        let data = |from, to, label: &str| WireConnector {
            from,
            to,
            service: false,
            label: label.into(),
            caption: None,
        };
        let c = vec![
            data((0, 0), (1, 0), "a.o → b.i"),
            data((1, 1), (0, 1), "b.o → a.i"),
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
