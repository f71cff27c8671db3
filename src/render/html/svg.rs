//! SVG diagrams built in Rust: the component diagram (spec chapter 4) and the lifecycle state
//! diagram. Every profile string that lands in the SVG goes through [`esc`]; colours come from
//! CSS classes in `style.css`, so the diagrams follow the light and dark themes.

use crate::model::PortSide;
use std::fmt::Write as _;

/// Whether [`esc_into`] replaces byte `c`: `& < > " '` and control characters but newline and
/// tab. Comparisons joined by `|`, so that [`crate::bytes::run_len`] tests sixteen bytes per
/// step.
#[inline(always)]
const fn needs_escape(c: u8) -> bool {
    (c == b'&')
        | (c == b'<')
        | (c == b'>')
        | (c == b'"')
        | (c == b'\'')
        | ((c < 0x20) & (c != b'\n') & (c != b'\t'))
}

/// [`needs_escape`] as a table, for the byte-by-byte part of the scan (one load per byte; most
/// escaped text is a short label).
const NEEDS_ESCAPE: [bool; 256] = {
    let mut t = [false; 256];
    let mut c = 0;
    while c < 256 {
        t[c] = needs_escape(c as u8);
        c += 1;
    }
    t
};

/// Escapes text for SVG/HTML text and attribute values.
pub fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    // Writing to a String cannot fail.
    let _ = esc_into(&mut out, s);
    out
}

/// Writes `s` escaped for HTML/SVG text and attribute values: `& < > " '` become references,
/// control characters other than newline and tab become spaces. Runs of ordinary text are
/// written in one piece.
/// `s` escaped, its code spans (`` `name` ``, as [`crate::render::text::code_spans`] finds
/// them) as `<code>`: a diff message, a finding or its hint as Markdown and Doxygen show it.
pub fn esc_code_into<W: std::fmt::Write + ?Sized>(out: &mut W, s: &str) -> std::fmt::Result {
    if !s.contains('`') {
        return esc_into(out, s);
    }
    let chars: Vec<char> = s.chars().collect();
    let mut at = 0;
    let mut piece = String::new();
    for span in crate::render::text::code_spans(&chars, true) {
        piece.clear();
        piece.extend(&chars[at..span.open]);
        esc_into(out, &piece)?;
        piece.clear();
        piece.extend(span.content(&chars));
        out.write_str("<code>")?;
        esc_into(out, &piece)?;
        out.write_str("</code>")?;
        at = span.close + 1;
    }
    piece.clear();
    piece.extend(&chars[at..]);
    esc_into(out, &piece)
}

/// `s` escaped as [`esc_into`] does, with `<wbr>` where a name may break between its words:
/// after a run of `:` `_` `.` `/` `-` `<` before a letter (`RTC::<wbr>TimedLong`,
/// `max_<wbr>speed`, `vector<<wbr>double>`), after a comma (`0.1,<wbr>0.2`), before a version after `:` (`Long:<wbr>1.0`), and before a capital that starts a word (`Timed<wbr>Double<wbr>Seq`,
/// `IOR<wbr>String`). A narrow column then breaks `RTC::TimedDoubleSeq` between words, never
/// inside one (the cell's `overflow-wrap: break-word` breaks a word only where nothing else
/// fits). Text, `title` and copied text are unchanged: `<wbr>` is no character.
pub fn esc_wbr_into<W: std::fmt::Write + ?Sized>(out: &mut W, s: &str) -> std::fmt::Result {
    let b = s.as_bytes();
    let sep = |c: u8| matches!(c, b':' | b'_' | b'.' | b'/' | b'-' | b'<');
    let mut start = 0;
    for i in 1..b.len() {
        let (p, c) = (b[i - 1], b[i]);
        let word_start = if c.is_ascii_uppercase() {
            p.is_ascii_lowercase()
                || p.is_ascii_digit()
                || (p.is_ascii_uppercase() && b.get(i + 1).is_some_and(u8::is_ascii_lowercase))
                || (sep(p) && i > 1)
        } else {
            (c.is_ascii_lowercase() && sep(p) && i > 1)
                || (p == b',' && c.is_ascii_alphanumeric())
                || (p == b':' && c.is_ascii_digit() && i > 1)
        };
        if word_start {
            // `i` is at an ASCII byte: both slices end on character boundaries.
            esc_into(out, &s[start..i])?;
            out.write_str("<wbr>")?;
            start = i;
        }
    }
    esc_into(out, &s[start..])
}

pub fn esc_into<W: std::fmt::Write + ?Sized>(out: &mut W, s: &str) -> std::fmt::Result {
    let b = s.as_bytes();
    let mut start = 0;
    loop {
        let i = start
            + crate::bytes::run_len(
                &b[start..],
                |c| !needs_escape(c),
                |c| !NEEDS_ESCAPE[usize::from(c)],
            );
        if i == b.len() {
            break;
        }
        let rep = match b[i] {
            b'&' => "&amp;",
            b'<' => "&lt;",
            b'>' => "&gt;",
            b'"' => "&quot;",
            b'\'' => "&#39;",
            _ => " ", // a control character other than newline and tab
        };
        // `i` is at an ASCII byte, so both slices end on character boundaries.
        out.write_str(&s[start..i])?;
        out.write_str(rep)?;
        start = i + 1;
    }
    out.write_str(&s[start..])
}

/// Appends a coordinate of the drawing exactly as `f32`'s `Display` writes it. The layout's
/// coordinates are whole or half pixels, which are written here as an integer and `.5`
/// without `Display`'s general shortest-digits search (half of the drawing's time at 10,000
/// profiles went there) and without the formatting machinery; any other value is handed to
/// `Display`.
pub(super) fn num(s: &mut String, v: f32) {
    let twice = v * 2.0;
    // Below a million an f32 is exact to 1/16, so a whole or half value's shortest digits
    // are its integer part and `.5`; -0 is left to `Display` (it writes `-0`).
    if v.abs() < 1e6 && twice == twice.trunc() && !(v == 0.0 && v.is_sign_negative()) {
        let t = twice as i64;
        if t < 0 {
            s.push('-');
        }
        let m = t.unsigned_abs();
        s.push_str(itoa::Buffer::new().format(m / 2));
        if m % 2 == 1 {
            s.push_str(".5");
        }
    } else {
        let _ = write!(s, "{v}");
    }
}

/// Appends ` name="value"` for a coordinate.
pub(super) fn attr_num(s: &mut String, name: &str, v: f32) {
    s.push(' ');
    s.push_str(name);
    s.push_str("=\"");
    num(s, v);
    s.push('"');
}

use crate::layout::text::{text_width, wrap, Font};

/// A data port as drawn on the component box.
pub struct DiagramDataPort {
    pub side: PortSide,
    pub name: String,
    /// Short type name shown under the port name.
    pub type_label: String,
    /// `in`, `out` or `event` (CSS class).
    pub class: &'static str,
    pub anchor: String,
}

/// A service interface of a service port, drawn as a lollipop (provided) or socket (required).
pub struct DiagramInterface {
    pub provided: bool,
    pub label: String,
    pub type_label: String,
    pub anchor: String,
}

/// A service port with its interfaces.
pub struct DiagramServicePort {
    pub side: PortSide,
    pub name: String,
    pub anchor: String,
    pub interfaces: Vec<DiagramInterface>,
}

enum Slot<'a> {
    Data(&'a DiagramDataPort),
    /// A service port spanning `span` slots; the interface (if any) drawn at this slot.
    Service {
        port: &'a DiagramServicePort,
        index: usize,
    },
}

const SLOT_V: f32 = 38.0; // least slot height on the left and right edges
const SLOT_H: f32 = 26.0; // slot width on the top and bottom edges
const HEADER: f32 = 50.0;
const STEM: f32 = 30.0; // distance from the edge to an interface symbol
/// Widest line of a label on the left or right before it wraps (names are never cut).
const MAX_LINE: f32 = 250.0;

fn slots_on<'a>(
    side: PortSide,
    data: &'a [DiagramDataPort],
    service: &'a [DiagramServicePort],
) -> Vec<Slot<'a>> {
    let mut v: Vec<Slot<'a>> = data
        .iter()
        .filter(|p| p.side == side)
        .map(Slot::Data)
        .collect();
    for p in service.iter().filter(|p| p.side == side) {
        for index in 0..p.interfaces.len().max(1) {
            v.push(Slot::Service { port: p, index });
        }
    }
    v
}

/// The label of a slot: the name (port, or `port.interface`) and the type, unwrapped.
fn slot_text(s: &Slot<'_>) -> (String, String) {
    match s {
        Slot::Data(p) => (p.name.clone(), p.type_label.clone()),
        Slot::Service { port, index } => match port.interfaces.get(*index) {
            Some(i) => (format!("{}.{}", port.name, i.label), i.type_label.clone()),
            None => (port.name.clone(), String::new()),
        },
    }
}

/// The label's lines as drawn on `side`: on the left and right the name and the type, each
/// wrapped at [`MAX_LINE`] (`true` marks a type line); on the top and bottom one rotated
/// line `name : Type`.
fn slot_lines(side: PortSide, s: &Slot<'_>) -> Vec<(String, bool)> {
    let (a, b) = slot_text(s);
    match side {
        PortSide::Top | PortSide::Bottom => {
            if b.is_empty() {
                vec![(a, false)]
            } else {
                vec![(format!("{a} : {b}"), false)]
            }
        }
        _ => {
            let mut v: Vec<(String, bool)> = wrap(&a, MAX_LINE, Font::regular(12.0))
                .into_iter()
                .map(|l| (l, false))
                .collect();
            if !b.is_empty() {
                v.extend(
                    wrap(&b, MAX_LINE, Font::regular(11.0))
                        .into_iter()
                        .map(|l| (l, true)),
                );
            }
            v
        }
    }
}

fn slot_label_width(side: PortSide, s: &Slot<'_>) -> f32 {
    slot_lines(side, s)
        .iter()
        .map(|(l, ty)| text_width(l, if *ty { 11.0 } else { 12.0 }))
        .fold(0.0, f32::max)
}

/// Slot height on a side: room for the most lines any of its labels has.
fn slot_height(side: PortSide, list: &[Slot<'_>]) -> f32 {
    match side {
        PortSide::Top | PortSide::Bottom => SLOT_H,
        _ => list
            .iter()
            .map(|s| 13.0 * slot_lines(side, s).len() as f32 + 12.0)
            .fold(SLOT_V, f32::max),
    }
}

/// Renders the component diagram: the `<<RTC>>` box, data ports as squares on their edge and
/// service interfaces as lollipops (provided) or sockets (required). Each port links to the
/// table row with its anchor. The box grows with the number of ports.
pub fn component_diagram(
    name: &str,
    title: &str,
    data: &[DiagramDataPort],
    service: &[DiagramServicePort],
) -> String {
    let sides = [
        PortSide::Left,
        PortSide::Right,
        PortSide::Top,
        PortSide::Bottom,
    ];
    let slots: Vec<Vec<Slot<'_>>> = sides.iter().map(|&s| slots_on(s, data, service)).collect();
    let label_w: Vec<f32> = slots
        .iter()
        .zip(sides)
        .map(|(v, side)| {
            v.iter()
                .map(|s| slot_label_width(side, s))
                .fold(0.0, f32::max)
        })
        .collect();
    let has_service = |i: usize| slots[i].iter().any(|s| matches!(s, Slot::Service { .. }));
    let margin = |i: usize| {
        if slots[i].is_empty() {
            16.0
        } else {
            label_w[i] + 24.0 + if has_service(i) { STEM + 10.0 } else { 0.0 }
        }
    };
    let (ml, mr, mt, mb) = (margin(0), margin(1), margin(2), margin(3));
    let name_c = name.to_string();
    let slot_v: Vec<f32> = sides
        .iter()
        .zip(&slots)
        .map(|(side, l)| slot_height(*side, l))
        .collect();
    let box_w = [
        200.0,
        text_width(&name_c, 15.0) + 40.0,
        slots[2].len() as f32 * SLOT_H + 40.0,
        slots[3].len() as f32 * SLOT_H + 40.0,
    ]
    .into_iter()
    .fold(0.0, f32::max)
    .ceil();
    let box_h = [
        110.0,
        HEADER + slots[0].len() as f32 * slot_v[0] + 10.0,
        HEADER + slots[1].len() as f32 * slot_v[1] + 10.0,
    ]
    .into_iter()
    .fold(0.0, f32::max)
    .ceil();
    let bx = ml.ceil();
    let by = mt.ceil();
    let width = (bx + box_w + mr).ceil();
    let height = (by + box_h + mb).ceil();

    let mut s = String::with_capacity(4096);
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" class="diagram component-diagram" viewBox="0 0 {width} {height}" width="{width}" height="{height}" role="group" aria-label="{}"><title>{}</title>"#,
        esc(title),
        esc(title)
    );
    let _ = write!(
        s,
        r#"<rect class="rtc-box" x="{bx}" y="{by}" width="{box_w}" height="{box_h}" rx="4"/><text class="stereotype" x="{}" y="{}" text-anchor="middle">«RTC»</text><text class="rtc-name" x="{}" y="{}" text-anchor="middle">{}</text>"#,
        bx + box_w / 2.0,
        by + 20.0,
        bx + box_w / 2.0,
        by + 40.0,
        esc(&name_c)
    );

    for (si, side) in sides.iter().enumerate() {
        let list = &slots[si];
        // Service ports are drawn as one rectangle spanning their slots.
        let mut i = 0;
        while i < list.len() {
            let (ex, ey) = edge_point(*side, slot_v[si], i, bx, by, box_w, box_h);
            match &list[i] {
                Slot::Data(p) => {
                    s.push_str(r##"<a href="#"##);
                    let _ = esc_into(&mut s, &p.anchor);
                    s.push_str(r#"" class="port "#);
                    s.push_str(p.class);
                    s.push_str(r#""><rect class="port-square""#);
                    attr_num(&mut s, "x", ex - 6.0);
                    attr_num(&mut s, "y", ey - 6.0);
                    s.push_str(r#" width="12" height="12"/>"#);
                    let lines = slot_lines(*side, &list[i]);
                    label(&mut s, *side, ex, ey, 14.0, &lines);
                    s.push_str("</a>");
                    i += 1;
                }
                Slot::Service { port, .. } => {
                    let span = service_port(
                        &mut s,
                        *side,
                        slot_v[si],
                        list,
                        i,
                        port,
                        (bx, by, box_w, box_h),
                    );
                    i += span;
                }
            }
        }
    }
    s.push_str("</svg>");
    s
}

/// Draws service port `port` on `side` at the first of `list`'s slots (one per interface):
/// one rectangle spanning them, each interface's symbol and label; returns the slots used.
fn service_port(
    s: &mut String,
    side: PortSide,
    step: f32,
    list: &[Slot<'_>],
    at: usize,
    port: &DiagramServicePort,
    (bx, by, box_w, box_h): (f32, f32, f32, f32),
) -> usize {
    let (ex, ey) = edge_point(side, step, at, bx, by, box_w, box_h);
    let span = port.interfaces.len().max(1);
    let (fx, fy) = edge_point(side, step, at + span - 1, bx, by, box_w, box_h);
    let (rx, ry, rw, rh) = match side {
        PortSide::Left | PortSide::Right => (ex - 6.0, ey - 6.0, 12.0, fy - ey + 12.0),
        _ => (ex - 6.0, ey - 6.0, fx - ex + 12.0, 12.0),
    };
    let _ = write!(
        s,
        r##"<a href="#{}" class="port service" aria-label="{}"><rect class="port-square" x="{rx}" y="{ry}" width="{rw}" height="{rh}"/></a>"##,
        esc(&port.anchor),
        esc(&port.name)
    );
    for k in 0..span {
        let (px, py) = edge_point(side, step, at + k, bx, by, box_w, box_h);
        let lines = slot_lines(side, &list[at + k]);
        match port.interfaces.get(k) {
            Some(iface) => {
                let _ = write!(
                    s,
                    r##"<a href="#{}" class="iface {}">"##,
                    esc(&iface.anchor),
                    if iface.provided {
                        "provided"
                    } else {
                        "required"
                    }
                );
                symbol(s, side, px, py, iface.provided);
                label(s, side, px, py, STEM + 14.0, &lines);
                s.push_str("</a>");
            }
            None => {
                let _ = write!(
                    s,
                    r##"<a href="#{}" class="port service">"##,
                    esc(&port.anchor)
                );
                label(s, side, px, py, 14.0, &lines);
                s.push_str("</a>");
            }
        }
    }
    span
}

/// Centre of slot `i` on `side`'s edge.
fn edge_point(
    side: PortSide,
    sv: f32,
    i: usize,
    bx: f32,
    by: f32,
    box_w: f32,
    box_h: f32,
) -> (f32, f32) {
    // The port sits at the first line of its label (as with one-line labels in a 38 px slot).
    let along_v = by + HEADER + sv * i as f32 + SLOT_V / 2.0 - 4.0;
    let along_h = bx + 20.0 + SLOT_H * i as f32 + SLOT_H / 2.0;
    match side {
        PortSide::Left => (bx, along_v),
        PortSide::Right => (bx + box_w, along_v),
        PortSide::Top => (along_h, by),
        PortSide::Bottom => (along_h, by + box_h),
    }
}

/// Lollipop (provided) or socket (required) on the outside of the edge at (x, y).
fn symbol(s: &mut String, side: PortSide, x: f32, y: f32, provided: bool) {
    let (nx, ny): (f32, f32) = match side {
        PortSide::Left => (-1.0, 0.0),
        PortSide::Right => (1.0, 0.0),
        PortSide::Top => (0.0, -1.0),
        PortSide::Bottom => (0.0, 1.0),
    };
    let (cx, cy) = (x + nx * STEM, y + ny * STEM);
    let r = 7.0;
    let (sx, sy) = (x + nx * 6.0, y + ny * 6.0);
    let (tx, ty) = (cx - nx * r, cy - ny * r);
    let _ = write!(
        s,
        r#"<line class="stem" x1="{sx}" y1="{sy}" x2="{tx}" y2="{ty}"/>"#
    );
    if provided {
        let _ = write!(s, r#"<circle class="ball" cx="{cx}" cy="{cy}" r="{r}"/>"#);
    } else {
        // A half circle whose back touches the stem and whose opening faces outward.
        let (px, py) = (-ny, nx);
        let (x1, y1) = (cx + px * r, cy + py * r);
        let (x2, y2) = (cx - px * r, cy - py * r);
        let _ = write!(
            s,
            r#"<path class="socket" d="M{x1} {y1} A{r} {r} 0 0 0 {x2} {y2}"/>"#
        );
    }
}

/// Label outside the edge, `gap` pixels away from it: on the left and right the name's lines
/// then the type's (`port-type`), one under the other; top and bottom labels are one line
/// rotated to read upwards so many ports still fit.
fn label(s: &mut String, side: PortSide, x: f32, y: f32, gap: f32, lines: &[(String, bool)]) {
    match side {
        PortSide::Left | PortSide::Right => {
            let (tx, anchor) = if side == PortSide::Left {
                (x - gap, "end")
            } else {
                (x + gap, "start")
            };
            for (k, (line, ty)) in lines.iter().enumerate() {
                s.push_str(r#"<text class=""#);
                s.push_str(if *ty { "port-type" } else { "port-name" });
                s.push('"');
                attr_num(s, "x", tx);
                attr_num(s, "y", y + 1.0 + 13.0 * k as f32);
                s.push_str(r#" text-anchor=""#);
                s.push_str(anchor);
                s.push_str(r#"">"#);
                let _ = esc_into(s, line);
                s.push_str("</text>");
            }
        }
        PortSide::Top | PortSide::Bottom => {
            let text = lines.first().map(|l| l.0.as_str()).unwrap_or("");
            let (ty, anchor) = if side == PortSide::Top {
                (y - gap, "start")
            } else {
                (y + gap, "end")
            };
            s.push_str(r#"<text class="port-name""#);
            attr_num(s, "x", x + 4.0);
            attr_num(s, "y", ty);
            s.push_str(r#" text-anchor=""#);
            s.push_str(anchor);
            s.push_str(r#"" transform="rotate(-90 "#);
            num(s, x + 4.0);
            s.push(' ');
            num(s, ty);
            s.push_str(r#")">"#);
            let _ = esc_into(s, text);
            s.push_str("</text>");
        }
    }
}

/// A callback label of the lifecycle diagram: x, y, text anchor, callback name.
type CallbackLabel = (u32, u32, &'static str, &'static str);

/// The transitions of the lifecycle diagram in drawing order: the arrow's path and the
/// callbacks written beside it.
const LIFECYCLE_TRANSITIONS: &[(&str, &[CallbackLabel])] = &[
    // Created → Inactive.
    (
        "M180 152 L318 152",
        &[(249, 144, "middle", "on_initialize")],
    ),
    // Inactive ⇄ Active.
    ("M450 142 L598 142", &[(524, 134, "middle", "on_activated")]),
    (
        "M600 164 L452 164",
        &[(524, 182, "middle", "on_deactivated")],
    ),
    // Active loop: periodic callbacks.
    (
        "M640 130 C640 80 700 80 700 128",
        &[
            (665, 76, "middle", "on_execute"),
            (665, 60, "middle", "on_state_update"),
        ],
    ),
    // Active → Error.
    ("M690 174 L690 298", &[(696, 240, "start", "on_aborting")]),
    // Error loop.
    (
        "M640 344 C640 390 700 390 700 346",
        &[(665, 396, "middle", "on_error")],
    ),
    // Error → Inactive.
    (
        "M600 310 C520 280 440 240 420 176",
        &[(500, 262, "middle", "on_reset")],
    ),
    // Inactive → Finalized.
    ("M385 174 L385 298", &[(379, 240, "end", "on_finalize")]),
];

/// The execution-context event callbacks of the lifecycle diagram (not tied to a transition).
const LIFECYCLE_EC_EVENTS: &[CallbackLabel] = &[
    (20, 42, "start", "on_startup"),
    (140, 42, "start", "on_shutdown"),
    (270, 42, "start", "on_rate_changed"),
];

/// The FSM callbacks of the lifecycle diagram.
const LIFECYCLE_FSM: &[CallbackLabel] = &[
    (20, 258, "start", "on_action"),
    (20, 276, "start", "on_mode_changed"),
];

/// Callback labels and states of the lifecycle diagram, in the page language.
pub struct LifecycleLabels<'a> {
    pub title: &'a str,
    pub created: &'a str,
    pub inactive: &'a str,
    pub active: &'a str,
    pub error: &'a str,
    pub finalized: &'a str,
    pub ec_events: &'a str,
    pub fsm: &'a str,
    pub implemented: &'a str,
    pub not_implemented: &'a str,
}

/// The lifecycle state diagram of one language, made once per build: its text with, in
/// place of each callback label, the label in both forms (implemented or not), so that a page's
/// diagram is a run of copies ([`LifecycleDiagram::render`]).
pub struct LifecycleDiagram {
    /// Text, then the callback named (if any) in its two forms, in drawing order.
    parts: Vec<(String, Option<LifecycleCallback>)>,
}

/// A callback label of [`LifecycleDiagram`] in both forms.
struct LifecycleCallback {
    name: &'static str,
    implemented: String,
    not_implemented: String,
}

impl LifecycleDiagram {
    /// The diagram (Created, Inactive, Active, Error, Finalized, with the callbacks on their
    /// transitions) with the labels `l`.
    pub fn new(l: &LifecycleLabels<'_>) -> LifecycleDiagram {
        let mut parts: Vec<(String, Option<LifecycleCallback>)> = Vec::new();
        let mut s = String::with_capacity(1024);
        let _ = write!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" class="diagram lifecycle-diagram" viewBox="0 0 800 410" width="800" height="410" role="img" aria-label="{}"><title>{}</title>"#,
            esc(l.title),
            esc(l.title)
        );
        s.push_str(r#"<defs><marker id="lc-arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse"><path class="arrowhead" d="M0 0 L10 5 L0 10 z"/></marker></defs>"#);
        let label = |on: bool, x: u32, y: u32, anchor: &str, name: &str| {
            format!(
                r#"<text class="cb{}" x="{x}" y="{y}" text-anchor="{anchor}">{}{}</text>"#,
                if on { " impl" } else { "" },
                if on { "✔ " } else { "" },
                esc(name)
            )
        };
        let mut cb = |s: &mut String, x: u32, y: u32, anchor: &str, name: &'static str| {
            let callback = LifecycleCallback {
                name,
                implemented: label(true, x, y, anchor, name),
                not_implemented: label(false, x, y, anchor, name),
            };
            parts.push((std::mem::take(s), Some(callback)));
        };
        let state = |s: &mut String, x: u32, y: u32, name: &str, class: &str| {
            let _ = write!(
                s,
                r#"<rect class="state {class}" x="{x}" y="{y}" width="130" height="44" rx="14"/><text class="state-name" x="{}" y="{}" text-anchor="middle">{}</text>"#,
                x + 65,
                y + 27,
                esc(name)
            );
        };
        let arrow = |s: &mut String, d: &str| {
            let _ = write!(
                s,
                r#"<path class="transition" d="{d}" marker-end="url(#lc-arrow)"/>"#
            );
        };
        // Initial pseudo-state and the states.
        s.push_str(r#"<circle class="initial" cx="20" cy="152" r="7"/>"#);
        arrow(&mut s, "M27 152 L48 152");
        for (x, y, name, class) in [
            (50, 130, l.created, "created"),
            (320, 130, l.inactive, "inactive"),
            (600, 130, l.active, "active"),
            (600, 300, l.error, "error"),
            (320, 300, l.finalized, "finalized"),
        ] {
            state(&mut s, x, y, name, class);
        }
        for (path, callbacks) in LIFECYCLE_TRANSITIONS {
            arrow(&mut s, path);
            for &(x, y, anchor, name) in *callbacks {
                cb(&mut s, x, y, anchor, name);
            }
        }
        // Execution-context events and FSM callbacks, not tied to one transition.
        for (title, y, callbacks) in [
            (l.ec_events, 24, LIFECYCLE_EC_EVENTS),
            (l.fsm, 240, LIFECYCLE_FSM),
        ] {
            let _ = write!(
                s,
                r#"<text class="note-title" x="20" y="{y}">{}</text>"#,
                esc(title)
            );
            for &(x, y, anchor, name) in callbacks {
                cb(&mut s, x, y, anchor, name);
            }
        }
        // Legend.
        let _ = write!(
            s,
            r#"<text class="cb impl" x="20" y="360">✔ {}</text><text class="cb" x="20" y="378">{}</text>"#,
            esc(l.implemented),
            esc(l.not_implemented)
        );
        s.push_str("</svg>");
        parts.push((s, None));
        LifecycleDiagram { parts }
    }

    /// The diagram of a component: `implemented(callback_name)` says which callbacks to
    /// highlight.
    pub fn render(&self, implemented: &dyn Fn(&str) -> bool) -> String {
        let len = self
            .parts
            .iter()
            .map(|(text, cb)| text.len() + cb.as_ref().map_or(0, |c| c.implemented.len()))
            .sum();
        let mut s = String::with_capacity(len);
        for (text, cb) in &self.parts {
            s.push_str(text);
            if let Some(c) = cb {
                s.push_str(if implemented(c.name) {
                    &c.implemented
                } else {
                    &c.not_implemented
                });
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// A coordinate is written exactly as `Display` writes it: whole and half values by
        /// the short path (both signs, around the million where it stops), anything else by
        /// `Display` itself.
        #[test]
        fn num_writes_what_display_writes(
            halves in -2_100_000i32..2_100_000,
            any in proptest::num::f32::ANY,
        ) {
            for v in [halves as f32 / 2.0, any, -0.0, 0.0, 0.25, 999_999.5, 1e6] {
                let mut s = String::new();
                num(&mut s, v);
                proptest::prop_assert_eq!(s, format!("{v}"));
            }
        }
    }

    #[test]
    fn escaping() {
        assert_eq!(esc("plain 画像"), "plain 画像");
        assert_eq!(
            esc("<a href=\"x\">'&'</a>\u{1}\n\t"),
            "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt; \n\t"
        );
        assert_eq!(esc("画<像"), "画&lt;像");
    }

    #[test]
    fn names_break_between_their_words() {
        let w = |s: &str| {
            let mut out = String::new();
            esc_wbr_into(&mut out, s).unwrap();
            out
        };
        assert_eq!(
            w("RTC::TimedDoubleSeq"),
            "RTC::<wbr>Timed<wbr>Double<wbr>Seq"
        );
        assert_eq!(w("IORString"), "IOR<wbr>String");
        assert_eq!(w("max_speed"), "max_<wbr>speed");
        assert_eq!(
            w("Img::CameraCaptureService"),
            "Img::<wbr>Camera<wbr>Capture<wbr>Service"
        );
        assert_eq!(
            w("IDL:RTC/TimedLong:1.0"),
            "IDL:<wbr>RTC/<wbr>Timed<wbr>Long:<wbr>1.0"
        );
        // Numbers, all-capital and one-word names, and text that is not Latin stay whole.
        assert_eq!(w("0.5"), "0.5");
        assert_eq!(w("0.1,0.2"), "0.1,<wbr>0.2");
        assert_eq!(w("vector<double>"), "vector&lt;<wbr>double&gt;");
        assert_eq!(w("RTC"), "RTC");
        assert_eq!(w("velocity"), "velocity");
        assert_eq!(w("画像_入力"), "画像_入力");
        assert_eq!(w("<b>&"), "&lt;b&gt;&amp;");
        assert_eq!(w("_x"), "_x");
    }

    #[test]
    fn code_spans_are_code_and_the_rest_is_escaped() {
        let code = |s: &str| {
            let mut out = String::new();
            esc_code_into(&mut out, s).unwrap();
            out
        };
        assert_eq!(
            code("port `a<b>` of `画像` & more"),
            "port <code>a&lt;b&gt;</code> of <code>画像</code> &amp; more"
        );
        // A lone or empty pair of backticks is text, as in Markdown and Doxygen.
        assert_eq!(code("a ` b"), "a ` b");
        assert_eq!(code("a `  ` b"), "a `  ` b");
        assert_eq!(code("no spans <here>"), esc("no spans <here>"));
        // Longer fences hold backticks (CommonMark); a run of another length does not close.
        assert_eq!(code("a ``x`y`` b"), "a <code>x`y</code> b");
        assert_eq!(code("`` `x` ``"), "<code>`x`</code>");
        assert_eq!(code("`a``b`"), "<code>a``b</code>");
        assert_eq!(code("``a` b"), "``a` b");
    }

    proptest::proptest! {
        /// A value written as one code span ([`crate::render::text::code_span`]) reads back
        /// whole, as one `<code>`, whatever backticks and spaces it holds.
        #[test]
        fn a_value_as_a_code_span_reads_back_whole(s in "[`a <|]{0,12}") {
            proptest::prop_assume!(s.chars().any(|c| !c.is_whitespace()));
            let mut out = String::new();
            esc_code_into(&mut out, &crate::render::text::code_span(&s)).unwrap();
            proptest::prop_assert_eq!(out, format!("<code>{}</code>", esc(&s)));
        }
    }

    /// Character by character, as the escaper is specified.
    fn reference(s: &str) -> String {
        s.chars()
            .map(|c| match c {
                '&' => "&amp;".to_string(),
                '<' => "&lt;".to_string(),
                '>' => "&gt;".to_string(),
                '"' => "&quot;".to_string(),
                '\'' => "&#39;".to_string(),
                '\n' | '\t' => c.to_string(),
                c if u32::from(c) < 0x20 => " ".to_string(),
                c => c.to_string(),
            })
            .collect()
    }

    /// The block-wise escaper writes exactly what the character-wise reference does, for
    /// text of any length around the block size with the special bytes anywhere in it.
    #[test]
    fn escaping_matches_the_reference() {
        const PARTS: &[&str] = &[
            "a",
            "plain text ",
            "画像",
            "&",
            "<",
            ">",
            "\"",
            "'",
            "\n",
            "\t",
            "\r",
            "\u{0}",
            "\u{1f}",
            " ",
            "\u{7f}",
            "é",
            "0123456789abcdef",
            "\u{1F600}",
        ];
        crate::test_text::agrees((PARTS, 40, Some(2048)), &[], esc, reference);
    }

    #[test]
    fn diagram_escapes_names_and_grows() {
        let ports: Vec<DiagramDataPort> = (0..45)
            .map(|i| DiagramDataPort {
                side: if i % 2 == 0 {
                    PortSide::Left
                } else {
                    PortSide::Right
                },
                name: format!("<in{i}>"),
                type_label: "T\"x".into(),
                class: "in",
                anchor: format!("port-in{i}"),
            })
            .collect();
        let svg = component_diagram("<b>x</b>", "t", &ports, &[]);
        assert!(!svg.contains("<b>"));
        assert!(svg.contains("&lt;in44&gt;"));
        assert!(svg.contains("href=\"#port-in44\""));
        // 23 slots on the left at 38 px each need a tall box.
        assert!(svg.contains("height=\"") && svg.len() > 5000);
    }
}
