//! The rules themselves: per component (schema level, spec semantics, values, doc coverage)
//! and over the catalogue. Each rule emits diagnostics with the code, default severity and hint
//! of its [`registry`](super::registry) entry.

use super::registry::{self as r, rule_exact};
use crate::catalog::{Catalog, Component, ComponentIx};
use crate::constraint::{self, Problem, Verdict};
use crate::diagnostic::{Diagnostic, Severity};
use crate::model::{is_placeholder, non_empty, parse_bool, IdParts, Pos, Profile};
use crate::quote::Code;
use crate::value::{self, ValueType};
use std::collections::{BTreeMap, HashMap};

/// Collects the diagnostics of one file.
pub(crate) struct Findings<'a> {
    pub file: &'a str,
    pub out: Vec<Diagnostic>,
}

impl Findings<'_> {
    /// Emits `code` at `pos` with the registry's severity and hint.
    pub fn emit(&mut self, code: &'static str, pos: Pos, message: impl Into<String>) {
        let (severity, hint) =
            rule_exact(code).map_or((Severity::Warning, ""), |r| (r.severity, r.hint));
        let mut d = Diagnostic::new(severity, code, self.file, message).at(pos);
        if !hint.is_empty() {
            d = d.with_hint(hint);
        }
        self.out.push(d);
    }
}

fn blank(s: &Option<crate::model::Text>) -> bool {
    non_empty(s).is_none()
}

/// Runs every per-component rule on `c`.
pub(crate) fn component(c: &Component) -> Vec<Diagnostic> {
    let mut s = Findings {
        file: &c.source,
        out: Vec::new(),
    };
    // A component documented from its code has no profile to check: it is named, with what
    // its code does not say.
    if let Some(r) = &c.recovered {
        s.out.push(super::drift::recovered(c, r));
        s.out.extend(super::drift::findings(c));
        return s.out;
    }
    let p = &c.profile;
    required(p, &mut s);
    enumerations(p, &mut s);
    numbers_dates_booleans(p, &mut s);
    identity(p, &mut s);
    names(p, &mut s);
    known_values(p, &mut s);
    configuration_values(p, &mut s);
    configuration_datanames(p, &mut s);
    placeholders(p, &mut s);
    documentation(p, &mut s);
    s.out.extend(super::drift::findings(c));
    s.out
}

/// RTC101: required attributes (XSD `use="required"`).
fn required(p: &Profile, s: &mut Findings) {
    required_basic(p, s);
    required_nodes(p, s);
}

/// A required value `what` that is blank: an empty attribute is pointed at, a missing one at
/// its element (`pos` is either). `what` is put in words only when something is missing.
fn miss(s: &mut Findings, what: &dyn std::fmt::Display, v: &Option<crate::model::Text>, pos: Pos) {
    if blank(v) {
        let how = if v.is_some() {
            "is empty"
        } else {
            "is missing"
        };
        s.emit(r::MISSING_REQUIRED, pos, format!("required {what} {how}"));
    }
}

/// RTC101 of the profile's own attributes, its BasicInfo and its actions.
fn required_basic(p: &Profile, s: &mut Findings) {
    miss(
        s,
        &"rtc_profile attribute `id`",
        &p.id,
        p.attr_pos.or("id", p.pos),
    );
    miss(
        s,
        &"rtc_profile attribute `version`",
        &p.version,
        p.attr_pos.or("version", p.pos),
    );
    let b = &p.basic_info;
    let bpos = if b.pos.is_unknown() { p.pos } else { b.pos };
    for (name, v) in [
        ("name", &b.name),
        ("componentType", &b.component_type),
        ("activityType", &b.activity_type),
        ("componentKind", &b.component_kind),
        ("category", &b.category),
        ("executionType", &b.execution_type),
        ("vendor", &b.vendor),
        ("version", &b.version),
        ("creationDate", &b.creation_date),
        ("updateDate", &b.update_date),
    ] {
        miss(
            s,
            &format_args!("BasicInfo attribute `{name}`"),
            v,
            b.attr_pos.or(name, bpos),
        );
    }
    if p.actions.is_empty() && p.actions_pos.is_none() {
        s.emit(
            r::MISSING_REQUIRED,
            p.pos,
            "required element `Actions` is missing",
        );
    }
    for a in &p.actions {
        if a.implemented.is_none() {
            s.emit(
                r::MISSING_REQUIRED,
                a.pos,
                format!(
                    "required attribute `implemented` of action {} is missing",
                    a.kind.xml_name()
                ),
            );
        }
    }
}

/// RTC101 of the configuration parameters, ports, interfaces, parameters and language.
fn required_nodes(p: &Profile, s: &mut Findings) {
    // A node's `name`, then its other required attributes, each labelled with that name.
    let node = |s: &mut Findings,
                (element, what): (&str, &str),
                name: &Option<crate::model::Text>,
                (attr_pos, pos): (&crate::model::AttrPos, Pos),
                attrs: &[(&str, &Option<crate::model::Text>)]| {
        miss(
            s,
            &format_args!("{element} attribute `name`"),
            name,
            attr_pos.or("name", pos),
        );
        let label = name.as_deref().unwrap_or("");
        for (attr, v) in attrs {
            miss(
                s,
                &format_args!("attribute `{attr}` of {what} `{label}`"),
                v,
                attr_pos.or(attr, pos),
            );
        }
    };
    for c in p.configurations() {
        let at = (&c.attr_pos, c.pos);
        node(
            s,
            ("Configuration", "configuration"),
            &c.name,
            at,
            &[("type", &c.type_)],
        );
        if c.default_value.is_none() {
            let label = c.name.as_deref().unwrap_or("");
            s.emit(
                r::MISSING_REQUIRED,
                c.pos,
                format!("required attribute `defaultValue` of configuration `{label}` is missing"),
            );
        }
    }
    for d in &p.data_ports {
        let attrs = [("portType", &d.port_type), ("type", &d.type_)];
        node(
            s,
            ("DataPort", "data port"),
            &d.name,
            (&d.attr_pos, d.pos),
            &attrs,
        );
    }
    for sp in &p.service_ports {
        node(
            s,
            ("ServicePort", ""),
            &sp.name,
            (&sp.attr_pos, sp.pos),
            &[],
        );
        for i in &sp.interfaces {
            let attrs = [("type", &i.type_), ("direction", &i.direction)];
            let at = (&i.attr_pos, i.pos);
            node(
                s,
                ("ServiceInterface", "service interface"),
                &i.name,
                at,
                &attrs,
            );
        }
    }
    for par in &p.parameters {
        miss(s, &"Parameter attribute `name`", &par.name, par.pos);
    }
    if let Some(l) = &p.language {
        miss(s, &"Language attribute `kind`", &l.kind, l.pos);
    }
}

/// RTC102: enumerations of the XSD.
fn enumerations(p: &Profile, s: &mut Findings) {
    let b = &p.basic_info;
    // `what` is formatted only for a finding (most values are valid).
    let exact = |s: &mut Findings,
                 what: &dyn std::fmt::Display,
                 v: &Option<crate::model::Text>,
                 allowed: &[&str],
                 pos: Pos| {
        if let Some(v) = non_empty(v) {
            if !allowed.contains(&v) {
                let hint = allowed
                    .iter()
                    .find(|a| a.eq_ignore_ascii_case(v))
                    .map(|a| format!(" (write {}: the value is case-sensitive)", Code(a)))
                    .unwrap_or_default();
                s.emit(
                    r::INVALID_ENUM,
                    pos,
                    format!(
                        "{what} {} is not one of {}{hint}",
                        Code(v),
                        allowed.join(", ")
                    ),
                );
            }
        }
    };
    exact(
        s,
        &"componentType",
        &b.component_type,
        &["STATIC", "UNIQUE", "COMMUTATIVE"],
        b.attr_pos.or("componentType", b.pos),
    );
    // `EVENT_DRIVEN` is how RTCBuilder 0.1 and rtc-template spell EVENTDRIVEN (noted in
    // `writtenAs`, not an error).
    if non_empty(&b.activity_type) != Some("EVENT_DRIVEN") {
        exact(
            s,
            &"activityType",
            &b.activity_type,
            &["PERIODIC", "SPORADIC", "EVENTDRIVEN"],
            b.attr_pos.or("activityType", b.pos),
        );
    }
    for d in &p.data_ports {
        exact(
            s,
            &format_args!(
                "portType of data port `{}`",
                d.name.as_deref().unwrap_or("")
            ),
            &d.port_type,
            &["DataInPort", "DataOutPort", "EventPort"],
            d.attr_pos.or("portType", d.pos),
        );
        position(
            s,
            &d.position,
            d.name.as_deref(),
            d.attr_pos.or("position", d.pos),
        );
    }
    for sp in &p.service_ports {
        position(
            s,
            &sp.position,
            sp.name.as_deref(),
            sp.attr_pos.or("position", sp.pos),
        );
        for i in &sp.interfaces {
            if let Some(v) = non_empty(&i.direction) {
                if i.direction_kind().is_none() {
                    s.emit(
                        r::INVALID_ENUM,
                        i.attr_pos.or("direction", i.pos),
                        format!(
                            "direction `{v}` of service interface `{}` is not Provided or Required",
                            i.name.as_deref().unwrap_or("")
                        ),
                    );
                }
            }
        }
    }
}

fn position(s: &mut Findings, v: &Option<crate::model::Text>, port: Option<&str>, pos: Pos) {
    if let Some(v) = non_empty(v) {
        if crate::model::PortSide::parse(Some(v)).is_none() {
            s.emit(
                r::INVALID_ENUM,
                pos,
                format!(
                    "position `{v}` of port `{}` is not left, right, top or bottom",
                    port.unwrap_or("")
                ),
            );
        }
    }
}

/// What to do about a rate of 0 on a periodic context (RTC103 as a warning).
const ZERO_RATE_HINT: &str = "if rtc.conf sets `exec_cxt.periodic.rate`, nothing to do; otherwise write the rate in Hz, e.g. executionRate=\"1000.0\"";

/// RTC103–RTC106: executionRate, maxInstances, dates, booleans.
fn numbers_dates_booleans(p: &Profile, s: &mut Findings) {
    let b = &p.basic_info;
    if let Some(rate) = b.execution_rate.as_deref().filter(|v| !v.trim().is_empty()) {
        let at = b.attr_pos.or("executionRate", b.pos);
        // An externally triggered or event-driven context does not run at a rate: 0 is
        // what profiles write there.
        let driven = b.execution_type.as_deref().is_some_and(|t| {
            let t = t.trim().to_ascii_lowercase();
            t.starts_with("exttrig") || t.starts_with("eventdriven")
        });
        match value::parse_float(rate) {
            Some(f) if f > 0.0 || (driven && f == 0.0) => {}
            Some(0.0) => {
                // A suite that sets the rate at run time writes 0: not an error that fails
                // `check` on every profile, a warning that says where the rate comes from.
                s.emit(
                    r::EXECUTION_RATE,
                    at,
                    format!(
                        "executionRate {} is 0: the periodic execution context's rate is then set at run time (rtc.conf `exec_cxt.periodic.rate`, else OpenRTM's default)",
                        Code(rate.trim())
                    ),
                );
                if let Some(d) = s.out.last_mut() {
                    d.severity = Severity::Warning;
                    d.hint = Some(ZERO_RATE_HINT.to_string());
                }
            }
            Some(_) => s.emit(
                r::EXECUTION_RATE,
                at,
                format!("executionRate {} is not greater than 0", Code(rate.trim())),
            ),
            None => s.emit(
                r::EXECUTION_RATE,
                at,
                format!("executionRate {} is not a number", Code(rate.trim())),
            ),
        }
    }
    if let Some(m) = b.max_instances.as_deref().filter(|v| !v.trim().is_empty()) {
        let t = m.trim();
        let at = b.attr_pos.or("maxInstances", b.pos);
        match t.strip_prefix('+').unwrap_or(t).parse::<i128>() {
            Ok(n) if n >= 0 => {}
            Ok(n) => s.emit(
                r::MAX_INSTANCES,
                at,
                format!("maxInstances `{n}` is negative"),
            ),
            Err(_) => s.emit(
                r::MAX_INSTANCES,
                at,
                format!("maxInstances {} is not an integer", Code(t)),
            ),
        }
    }
    for (name, v) in [
        ("creationDate", &b.creation_date),
        ("updateDate", &b.update_date),
    ] {
        if let Some(d) = non_empty(v) {
            if let Err(why) = check_date_time(d) {
                s.emit(
                    r::DATE_TIME,
                    b.attr_pos.or(name, b.pos),
                    format!("{name} {} is not a valid xsd:dateTime: {why}", Code(d)),
                );
            }
        }
    }
    let boolean = |s: &mut Findings,
                   what: &dyn std::fmt::Display,
                   v: &Option<crate::model::Text>,
                   pos: Pos| {
        if let Some(t) = v {
            if parse_bool(Some(t)).is_none() {
                s.emit(
                    r::BOOLEAN,
                    pos,
                    format!("{what} {} is not a boolean (true, false, 1, 0)", Code(t)),
                );
            }
        }
    };
    for a in &p.actions {
        boolean(
            s,
            &format_args!("implemented of action {}", a.kind.xml_name()),
            &a.implemented,
            a.pos,
        );
    }
    // saveProject is a project name (xsd:string, spec 2.5.1.2), not a boolean.
    // matchCase is checked with the constraints (RTC305 reports it as malformed).
}

/// Validates an `xsd:dateTime`: `YYYY-MM-DDThh:mm:ss[.fff][Z|±hh:mm]`.
pub fn check_date_time(s: &str) -> Result<(), String> {
    let s = s.trim();
    let (date, time) = s
        .split_once('T')
        .ok_or("expected a `T` between date and time")?;
    let date = date.strip_prefix('-').unwrap_or(date);
    let dp: Vec<&str> = date.split('-').collect();
    let [y, mo, d] = dp.as_slice() else {
        return Err("the date is not YYYY-MM-DD".into());
    };
    let num = |t: &str, len: usize, what: &str| -> Result<u32, String> {
        if t.len() < len || !t.bytes().all(|b| b.is_ascii_digit()) {
            return Err(format!("the {what} `{t}` is not a {len}-digit number"));
        }
        t.parse::<u32>()
            .map_err(|_| format!("the {what} `{t}` is too large"))
    };
    let year = num(y, 4, "year")?;
    let month = num(mo, 2, "month")?;
    let day = num(d, 2, "day")?;
    if !(1..=12).contains(&month) {
        return Err(format!("month {month} does not exist"));
    }
    let leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    let days = match month {
        2 if leap => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        _ => 31,
    };
    if day == 0 || day > days {
        return Err(format!("day {day} does not exist in month {month}"));
    }
    // Split off the offset: `Z`, or the last `+`/`-`.
    let (clock, offset) = if let Some(c) = time.strip_suffix('Z') {
        (c, None)
    } else if let Some(i) = time.rfind(['+', '-']) {
        (&time[..i], Some(&time[i + 1..]))
    } else {
        (time, None)
    };
    let tp: Vec<&str> = clock.split(':').collect();
    let [h, mi, sec] = tp.as_slice() else {
        return Err("the time is not hh:mm:ss".into());
    };
    let hour = num(h, 2, "hour")?;
    let minute = num(mi, 2, "minute")?;
    let (whole, frac) = sec.split_once('.').unwrap_or((sec, "0"));
    let second = num(whole, 2, "second")?;
    if frac.is_empty() || !frac.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!("the fractional seconds `{frac}` are not digits"));
    }
    let midnight = hour == 24 && minute == 0 && second == 0;
    if (hour > 23 && !midnight) || minute > 59 || second > 59 {
        return Err(format!("{clock} is not a time of day"));
    }
    if let Some(o) = offset {
        let (oh, om) = o.split_once(':').ok_or("the offset is not ±hh:mm")?;
        let (oh, om) = (num(oh, 2, "offset hour")?, num(om, 2, "offset minute")?);
        if oh > 14 || om > 59 || (oh == 14 && om > 0) {
            return Err(format!("the offset {o} is out of range"));
        }
    }
    Ok(())
}

/// A version number: digits and dots, starting with a digit (`1.0.0`, `2`).
fn looks_like_version(s: &str) -> bool {
    s.starts_with(|c: char| c.is_ascii_digit()) && s.chars().all(|c| c.is_ascii_digit() || c == '.')
}

/// RTC201–RTC203: the id and the parts it is built from.
fn identity(p: &Profile, s: &mut Findings) {
    let b = &p.basic_info;
    let bpos = if b.pos.is_unknown() { p.pos } else { b.pos };
    for (name, v) in [("vendor", &b.vendor), ("version", &b.version)] {
        if let Some(t) = v.as_deref().filter(|t| !t.trim().is_empty()) {
            let mut bad = Vec::new();
            if t.chars().any(char::is_whitespace) {
                bad.push("whitespace");
            }
            if t.contains(':') {
                bad.push("`:`");
            }
            if !bad.is_empty() {
                // Words in the version and a version number as the vendor: the two swapped.
                let swapped = match (name, b.vendor.as_deref().map(str::trim)) {
                    ("version", Some(v))
                        if looks_like_version(v)
                            && !t.trim().starts_with(|c: char| c.is_ascii_digit()) =>
                    {
                        format!(
                        " (the vendor {} looks like a version: are vendor and version swapped?)",
                        Code(v)
                    )
                    }
                    _ => String::new(),
                };
                s.emit(
                    r::VENDOR_VERSION_CHARS,
                    b.attr_pos.or(name, bpos),
                    format!("{name} {} contains {}{swapped}", Code(t), bad.join(" and ")),
                );
            }
        }
    }
    let Some(id) = non_empty(&p.id) else { return };
    let id_pos = p.attr_pos.or("id", p.pos);
    // Both the colon form and RTCBuilder 0.1's dotted form name the parts.
    let Some(parts) = IdParts::parse(id, b) else {
        let colon: Vec<&str> = id.split(':').collect();
        let why = if colon.first() != Some(&"RTC") {
            "it does not start with `RTC:`".to_string()
        } else {
            format!("it has {} `:`-separated parts, not 5", colon.len())
        };
        s.emit(
            r::ID_FORMAT,
            id_pos,
            format!("id `{id}` is not RTC:<vendor>:<category>:<name>:<version>: {why}"),
        );
        return;
    };
    for (name, v, got) in [
        ("vendor", &b.vendor, parts.vendor),
        ("category", &b.category, parts.category),
        ("name", &b.name, parts.name),
        ("version", &b.version, parts.version),
    ] {
        let Some(expected) = v.as_deref() else {
            continue;
        };
        if got != expected {
            let squash = |t: &str| t.split_whitespace().collect::<String>();
            let note = if squash(got) == squash(expected) {
                " (they differ only in whitespace)"
            } else if got.eq_ignore_ascii_case(expected) {
                " (they differ only in case)"
            } else {
                ""
            };
            s.emit(
                r::ID_MISMATCH,
                id_pos,
                format!(
                    "the {name} part of the id is `{got}` but BasicInfo {name} is `{expected}`{note}"
                ),
            );
        }
    }
}

/// RTC204–RTC207: names without whitespace, unique where they must be.
fn names<'a>(p: &'a Profile, s: &mut Findings) {
    let ws = |s: &mut Findings, what: &str, v: &Option<crate::model::Text>, pos: Pos| {
        if let Some(n) = v.as_deref().filter(|n| !n.trim().is_empty()) {
            if n.chars().any(char::is_whitespace) {
                s.emit(
                    r::NAME_WHITESPACE,
                    pos,
                    format!("{what} name `{n}` contains whitespace"),
                );
            }
        }
    };
    // Ports: data and service ports share one namespace.
    let mut ports: HashMap<&str, (Pos, &str)> = HashMap::new();
    let mut port =
        |s: &mut Findings, kind: &'static str, v: &'a Option<crate::model::Text>, pos: Pos| {
            if let Some((n, (first, first_kind))) = seen_before(&mut ports, v, (pos, kind)) {
                s.emit(
                    r::DUPLICATE_PORT,
                    pos,
                    format!(
                        "{kind} `{n}` has the same name as the {first_kind} at line {}",
                        first.line
                    ),
                );
            }
        };
    for d in &p.data_ports {
        let at = d.attr_pos.or("name", d.pos);
        ws(s, "data port", &d.name, at);
        port(s, "data port", &d.name, at);
    }
    for sp in &p.service_ports {
        let at = sp.attr_pos.or("name", sp.pos);
        ws(s, "service port", &sp.name, at);
        port(s, "service port", &sp.name, at);
        let mut seen: HashMap<&str, Pos> = HashMap::new();
        for i in &sp.interfaces {
            ws(
                s,
                "service interface",
                &i.name,
                i.attr_pos.or("name", i.pos),
            );
            if let Some((n, first)) = seen_before(&mut seen, &i.name, i.pos) {
                s.emit(
                    r::DUPLICATE_INTERFACE,
                    i.attr_pos.or("name", i.pos),
                    format!(
                        "service port `{}` has two interfaces named `{n}` (the first at line {})",
                        sp.name.as_deref().unwrap_or(""),
                        first.line
                    ),
                );
            }
        }
    }
    // Configuration parameters, then parameters: each list its own namespace.
    let configurations = p.configurations().iter().map(|c| {
        (
            "configuration",
            &c.name,
            c.pos,
            c.attr_pos.or("name", c.pos),
        )
    });
    let parameters = p
        .parameters
        .iter()
        .map(|par| ("parameter", &par.name, par.pos, par.pos));
    // What it is, its name, where it is and where its name is.
    type Named<'p> = (&'p str, &'p Option<crate::model::Text>, Pos, Pos);
    let lists: [Vec<Named>; 2] = [configurations.collect(), parameters.collect()];
    for list in lists {
        let mut seen: HashMap<&str, Pos> = HashMap::new();
        for (what, name, pos, at) in list {
            ws(s, what, name, at);
            if let Some((n, first)) = seen_before(&mut seen, name, pos) {
                s.emit(
                    r::DUPLICATE_PARAMETER,
                    at,
                    format!(
                        "{what} `{n}` is declared twice (the first at line {})",
                        first.line
                    ),
                );
            }
        }
    }
}

/// A name met before in its list, with what it was first met with (where, usually); else
/// `None`, and the name is remembered with `first` (an empty name is never remembered).
pub(super) fn seen_before<'a, T: Copy>(
    seen: &mut HashMap<&'a str, T>,
    name: &'a Option<crate::model::Text>,
    first: T,
) -> Option<(&'a str, T)> {
    let n = non_empty(name)?;
    match seen.get(n) {
        Some(before) => Some((n, *before)),
        None => {
            seen.insert(n, first);
            None
        }
    }
}

const COMPONENT_KINDS: &[&str] = &[
    "dataflowcomponent",
    "finitestatemachinecomponent",
    "dataflowfinitestatemachinecomponent",
    "finitestatemachinemultimodecomponent",
    "dataflowmultimodecomponent",
    "dataflowfinitestatemachinemultimodecomponent",
    "multimodecomponent",
    // DDC4RTC short forms.
    "dataflow",
    "finitestatemachine",
    "multimode",
    "dataflowfinitestatemachine",
    "finitestatemachinemultimode",
    "dataflowmultimode",
    "dataflowfinitestatemachinemultimode",
    "fsm",
];

const EXECUTION_TYPES: &[&str] = &[
    "periodic",
    "eventdriven",
    "other",
    "periodicexecutioncontext",
    "exttrigexecutioncontext",
    "eventdrivenexecutioncontext",
    "openhrpexecutioncontext",
    "simulatorexecutioncontext",
    "rtpreemptec",
    "multilayercompositeec",
    "periodicecsharedcomposite",
    "artexecutioncontext",
    "openhrp",
];

const INTERFACE_TYPES: &[&str] = &[
    "corba_cdr",
    "data_service",
    "shared_memory",
    "direct",
    "corbaport",
];
const DATAFLOW_TYPES: &[&str] = &["push", "pull"];
const SUBSCRIPTION_TYPES: &[&str] = &["flush", "new", "periodic"];
/// An in-port's: OpenRTM's `InPortBase` reports `Any` (it has no publisher and takes a
/// connection of every kind), and RTSystemEditor saves what the port reports.
const IN_PORT_SUBSCRIPTION_TYPES: &[&str] = &["flush", "new", "periodic", "any"];

/// The items of a comma-separated value that are not in `known` (compared without case and
/// without a `_`/space difference).
fn unknown_items<'a>(v: &'a str, known: &[&str]) -> Vec<&'a str> {
    v.split(',')
        .map(str::trim)
        .filter(|i| !i.is_empty())
        .filter(|i| {
            let k = i.to_ascii_lowercase().replace(' ', "");
            !known.contains(&k.as_str())
        })
        .collect()
}

/// RTC208–RTC212: componentKind, executionType and the data-port transport attributes.
fn known_values(p: &Profile, s: &mut Findings) {
    let b = &p.basic_info;
    let check = |s: &mut Findings,
                 code,
                 what: &dyn std::fmt::Display,
                 v: &Option<crate::model::Text>,
                 known: &[&str],
                 pos| {
        let Some(t) = non_empty(v) else { return };
        let bad = unknown_items(t, known);
        if !bad.is_empty() {
            s.emit(
                code,
                pos,
                format!(
                    "{what} {} is not a known value{}",
                    bad.iter()
                        .map(|b| Code(b).to_string())
                        .collect::<Vec<_>>()
                        .join(", "),
                    if bad.len() == 1 && bad[0] == t {
                        String::new()
                    } else {
                        format!(" (in {})", Code(t))
                    }
                ),
            );
        }
    };
    check(
        s,
        r::COMPONENT_KIND,
        &"componentKind",
        &b.component_kind,
        COMPONENT_KINDS,
        b.attr_pos.or("componentKind", b.pos),
    );
    check(
        s,
        r::EXECUTION_TYPE,
        &"executionType",
        &b.execution_type,
        EXECUTION_TYPES,
        b.attr_pos.or("executionType", b.pos),
    );
    for d in &p.data_ports {
        let n = d.name.as_deref().unwrap_or("");
        check(
            s,
            r::INTERFACE_TYPE,
            &format_args!("interfaceType of data port `{n}`:"),
            &d.interface_type,
            INTERFACE_TYPES,
            d.attr_pos.or("interfaceType", d.pos),
        );
        check(
            s,
            r::DATAFLOW_TYPE,
            &format_args!("dataflowType of data port `{n}`:"),
            &d.dataflow_type,
            DATAFLOW_TYPES,
            d.attr_pos.or("dataflowType", d.pos),
        );
        let in_port = matches!(
            d.direction(),
            Some(crate::model::PortDirection::In | crate::model::PortDirection::Event)
        );
        let at = d.attr_pos.or("subscriptionType", d.pos);
        if !in_port && non_empty(&d.subscription_type).is_some_and(is_any) {
            // `Any` is an in-port's word; an out-port's publisher is flush, new or periodic.
            s.emit(
                r::SUBSCRIPTION_TYPE,
                at,
                format!("subscriptionType of data port `{n}` is `Any`, which OpenRTM in-ports report; an out-port publishes flush, new or periodic: name those it supports (New,Periodic) or leave it empty"),
            );
            continue;
        }
        check(
            s,
            r::SUBSCRIPTION_TYPE,
            &format_args!("subscriptionType of data port `{n}`:"),
            &d.subscription_type,
            if in_port {
                IN_PORT_SUBSCRIPTION_TYPES
            } else {
                SUBSCRIPTION_TYPES
            },
            at,
        );
    }
}

/// `Any` (any case), alone.
fn is_any(v: &str) -> bool {
    v.trim().eq_ignore_ascii_case("any")
}

/// RTC307: a configuration whose documentation names another parameter of the component as
/// the data it describes: a copy-paste slip (real profiles document `dir_lf0` under `dir_rf1`).
/// A data name that is a human label (`wheel base`, `画像幅`) is what RTCBuilder's form asks
/// for and is not reported.
fn configuration_datanames(p: &Profile, s: &mut Findings) {
    let names: std::collections::HashSet<&str> = p
        .configurations()
        .iter()
        .filter_map(|c| non_empty(&c.name))
        .collect();
    for c in p.configurations() {
        let (Some(name), Some(doc)) = (non_empty(&c.name), &c.doc) else {
            continue;
        };
        let Some(documented) = non_empty(&doc.dataname) else {
            continue;
        };
        if documented != name && names.contains(documented) {
            s.emit(
                r::DATANAME_MISMATCH,
                if doc.pos.is_unknown() { c.pos } else { doc.pos },
                format!(
                    "the documentation of configuration `{name}` names the parameter `{documented}` (rtcDoc:dataname): it was probably copied from `{documented}`: check that its text describes `{name}`"
                ),
            );
        }
    }
}

/// RTC301–RTC305: configuration default values against their types and constraints.
fn configuration_values(p: &Profile, s: &mut Findings) {
    for c in p.configurations() {
        let name = c.name.as_deref().unwrap_or("");
        let ty = match non_empty(&c.type_) {
            Some(t) => {
                let ty = ValueType::parse(t);
                if ty == ValueType::Unknown {
                    s.emit(
                        r::UNKNOWN_TYPE,
                        c.attr_pos.or("type", c.pos),
                        format!("configuration `{name}` has type `{t}`, which rtcdoc cannot check"),
                    );
                }
                ty
            }
            None => ValueType::Unknown,
        };
        let mut default_ok = true;
        if let Some(v) = &c.default_value {
            if let Err(why) = value::check_value(ty, v) {
                default_ok = false;
                s.emit(
                    r::DEFAULT_TYPE,
                    c.attr_pos.or("defaultValue", c.pos),
                    format!(
                        "default value {} of configuration `{name}` is not a valid {}: {why}",
                        Code(v),
                        c.type_.as_deref().unwrap_or("").trim()
                    ),
                );
            }
        }
        let Some(k) = &c.constraint else { continue };
        // RTCBuilder's `conf_constraint` constrains nothing (RTC306 reports it).
        if k.placeholder().is_some() {
            continue;
        }
        let problems = constraint::problems(k, ty);
        for pr in &problems {
            match pr {
                Problem::Literal { pos, message } => s.emit(
                    r::CONSTRAINT_LITERAL,
                    *pos,
                    format!("in the constraint of configuration `{name}`: {message}"),
                ),
                Problem::Structure { pos, message } => s.emit(
                    r::CONSTRAINT_MALFORMED,
                    *pos,
                    format!("in the constraint of configuration `{name}`: {message}"),
                ),
            }
        }
        let Some(v) = &c.default_value else { continue };
        if !default_ok || !problems.is_empty() {
            continue;
        }
        match constraint::evaluate(k, v, constraint::widget_type(c.widget(), ty)) {
            Verdict::Satisfied => {}
            Verdict::Violated(why) => s.emit(
                r::CONSTRAINT_VIOLATED,
                c.attr_pos.or("defaultValue", c.pos),
                format!(
                    "default value {} of configuration `{name}` does not satisfy its constraint {}: {why}",
                    Code(v),
                    Code(&constraint::describe(k))
                ),
            ),
            Verdict::Unevaluable(why) => s.emit(
                r::CONSTRAINT_MALFORMED,
                k.pos,
                format!(
                    "the constraint of configuration `{name}` cannot be evaluated for {}: {why}",
                    Code(v)
                ),
            ),
        }
    }
    for d in &p.data_ports {
        if let Some(k) = d.constraint.as_ref().filter(|k| k.placeholder().is_none()) {
            for pr in constraint::problems(k, ValueType::Unknown) {
                if let Problem::Structure { pos, message } = pr {
                    s.emit(
                        r::CONSTRAINT_MALFORMED,
                        pos,
                        format!(
                            "in the constraint of data port `{}`: {message}",
                            d.name.as_deref().unwrap_or("")
                        ),
                    );
                }
            }
        }
    }
}

/// Document coverage of one component: (documented, total) items, emitting RTC501–RTC505 for
/// the undocumented ones when `s` is given.
pub(crate) fn doc_items(p: &Profile, mut s: Option<&mut Findings>) -> (usize, usize) {
    use crate::model::Text;
    let b = &p.basic_info;
    // BasicInfo's description (2.3.2) documents the component as well as the Document
    // Profile's (2.4.1): the page shows either. A placeholder (`ModuleDescription`) does not.
    let described = [Some(&b.description), b.doc.as_ref().map(|d| &d.description)]
        .into_iter()
        .flatten()
        .find(|d| crate::model::documented("description", d).is_some());
    // Every item counted: its description, code, position and what it is (`what name`, the
    // name in backticks when `quoted`), put in words only for an item without a description.
    struct Item<'a> {
        desc: Option<&'a Option<Text>>,
        code: &'static str,
        pos: Pos,
        what: &'static str,
        name: &'a str,
        quoted: bool,
    }
    let mut items: Vec<Item<'_>> = vec![Item {
        desc: described,
        code: r::DOC_COMPONENT,
        pos: if b.pos.is_unknown() { p.pos } else { b.pos },
        what: "component",
        name: p.name(),
        quoted: true,
    }];
    for a in p.actions.iter().filter(|a| a.is_implemented()) {
        items.push(Item {
            desc: a.doc.as_ref().map(|d| &d.description),
            code: r::DOC_ACTION,
            pos: a.pos,
            what: "implemented action",
            name: a.kind.xml_name(),
            quoted: false,
        });
    }
    /// A named item (`data port `x``).
    fn named<'a>(
        what: &'static str,
        name: &'a Option<Text>,
        desc: Option<&'a Option<Text>>,
        code: &'static str,
        pos: Pos,
    ) -> Item<'a> {
        Item {
            desc,
            code,
            pos,
            what,
            name: name.as_deref().unwrap_or(""),
            quoted: true,
        }
    }
    for d in &p.data_ports {
        let desc = d.doc.as_ref().map(|d| &d.description);
        items.push(named("data port", &d.name, desc, r::DOC_PORT, d.pos));
    }
    for sp in &p.service_ports {
        let desc = sp.doc.as_ref().map(|d| &d.description);
        items.push(named("service port", &sp.name, desc, r::DOC_PORT, sp.pos));
        for i in &sp.interfaces {
            let desc = i.doc.as_ref().map(|d| &d.description);
            items.push(named(
                "service interface",
                &i.name,
                desc,
                r::DOC_INTERFACE,
                i.pos,
            ));
        }
    }
    for c in p.configurations() {
        let desc = c.doc.as_ref().map(|d| &d.description);
        items.push(named(
            "configuration",
            &c.name,
            desc,
            r::DOC_CONFIGURATION,
            c.pos,
        ));
    }
    let total = items.len();
    let mut documented = 0;
    for it in items {
        if it.desc.is_some_and(|d| !blank(d)) {
            documented += 1;
        } else if let Some(s) = s.as_deref_mut() {
            let message = if it.quoted {
                format!("{} `{}` has no description", it.what, it.name)
            } else {
                format!("{} {} has no description", it.what, it.name)
            };
            s.emit(it.code, it.pos, message);
        }
    }
    (documented, total)
}

/// RTC306: placeholders RTCBuilder pre-fills and nobody edited.
fn placeholders(p: &Profile, s: &mut Findings) {
    let b = &p.basic_info;
    for (field, v) in [
        ("vendor", &b.vendor),
        ("category", &b.category),
        ("name", &b.name),
        ("description", &b.description),
    ] {
        if let Some(t) = non_empty(v).filter(|t| is_placeholder(field, t)) {
            s.emit(
                r::PLACEHOLDER,
                b.attr_pos.or(field, b.pos),
                format!(
                    "BasicInfo {field} {} is RTCBuilder's placeholder, never filled in",
                    Code(t)
                ),
            );
        }
    }
    if let Some(t) = b
        .doc
        .as_ref()
        .and_then(|d| non_empty(&d.description))
        .filter(|t| is_placeholder("description", t))
    {
        s.emit(
            r::PLACEHOLDER,
            b.doc.as_ref().map_or(b.pos, |d| d.pos),
            format!(
                "the component description {} is RTCBuilder's placeholder, never filled in",
                Code(t)
            ),
        );
    }
    let constrained = p
        .configurations()
        .iter()
        .map(|c| ("configuration", &c.name, &c.constraint))
        .chain(
            p.data_ports
                .iter()
                .map(|d| ("data port", &d.name, &d.constraint)),
        );
    for (what, name, constraint) in constrained {
        let Some(k) = constraint.as_ref() else {
            continue;
        };
        if let Some(l) = k.placeholder() {
            s.emit(
                r::PLACEHOLDER,
                k.pos,
                format!(
                    "the constraint of {what} `{}` is RTCBuilder's placeholder {}; it constrains nothing",
                    name.as_deref().unwrap_or(""),
                    Code(l)
                ),
            );
        }
    }
}

fn documentation(p: &Profile, s: &mut Findings) {
    doc_items(p, Some(s));
}

/// The file name of an IDL path, for comparison (`C:\…\BasicDataType.idl` → `basicdatatype.idl`).
fn idl_file_name(path: &str) -> String {
    shown_file_name(path).to_ascii_lowercase()
}

/// The file name of an IDL path as written (`C:\…\BasicDataType.idl` → `BasicDataType.idl`).
fn shown_file_name(path: &str) -> &str {
    crate::idl::pp::file_name(path.trim())
}

/// RTC403–RTC406: port types against the IDL read.
fn idl_rules(cat: &Catalog, out: &mut Vec<Diagnostic>) {
    port_types_in_idl(cat, out);
    differing_definitions(cat, out);
}

/// RTC402–RTC405: each port's type against the IDL read (defined, in the file its `idlFile`
/// names).
fn port_types_in_idl(cat: &Catalog, out: &mut Vec<Diagnostic>) {
    let have_idl = !cat.idl.is_empty();
    let idl_names: std::collections::HashSet<String> = cat
        .idl
        .files
        .iter()
        .map(|f| idl_file_name(&f.path))
        .collect();
    // (type name, idlFile, source file, position, port name) of every port, in catalogue order.
    let mut uses: Vec<(String, Option<String>, &str, Pos, String)> = Vec::new();
    type Text = crate::model::Text;
    let mut add = |ty: &str, (idl_file, port): (&Option<Text>, &Option<Text>), file, pos| {
        let idl_file = non_empty(idl_file).map(str::to_string);
        let port = port.as_deref().unwrap_or("").to_string();
        uses.push((ty.to_string(), idl_file, file, pos, port));
    };
    for t in &cat.data_types {
        for pr in t.all_uses() {
            if let Some((c, p)) = cat.port_of(pr) {
                add(&t.name, (&p.idl_file, &p.name), &c.source, p.pos);
            }
        }
    }
    for t in &cat.interfaces {
        for r in t.all_uses() {
            if let Some((c, _, i)) = cat.interface_of(r) {
                add(&t.name, (&i.idl_file, &i.name), &c.source, i.pos);
            }
        }
    }
    let mut reported: std::collections::HashSet<&str> = Default::default();
    // Made once, when some type is missing.
    let near_names = std::cell::OnceCell::new();
    for (name, idl_file, file, pos, port) in &uses {
        let mut s = Findings {
            file,
            out: Vec::new(),
        };
        let found = cat.idl.find_all(name);
        if found.is_empty() {
            if have_idl && reported.insert(name.as_str()) {
                s.emit(
                    r::TYPE_NOT_IN_IDL,
                    *pos,
                    format!("type `{name}` of `{port}` is defined in no IDL file read"),
                );
                // A type of that name in another module, or of a near name, is the first
                // thing to try.
                let near = near_names.get_or_init(|| cat.idl.near_names()).of(name, 3);
                if let (Some(d), false) = (s.out.last_mut(), near.is_empty()) {
                    let listed: Vec<String> = near.iter().map(|n| format!("`{n}`")).collect();
                    d.hint = Some(format!(
                        "did you mean {}? (defined in the IDL read); else {}",
                        listed.join(" or "),
                        d.hint.as_deref().unwrap_or("")
                    ));
                }
                // A warning when the IDL read declares the type's module (the type is missing
                // from its own files); an info when its module is elsewhere (its IDL, often
                // OpenRTM's own, was not given) or the type is one of OpenRTM's own (a
                // project's IDL may add to the `RTC` module without copying OpenRTM's).
                let module = name.rsplit_once("::").map(|(m, _)| m);
                if crate::types::is_openrtm_type(name)
                    || module.is_none_or(|m| cat.idl.find(m).is_none())
                {
                    for d in &mut s.out {
                        d.severity = Severity::Info;
                    }
                }
            }
        } else if let Some(f) = idl_file.as_deref() {
            let wanted = idl_file_name(f);
            if !idl_names.contains(&wanted) {
                // The type was read from another file: name it, as the first thing to try.
                let (defined_in, named) =
                    (shown_file_name(&found[0].file.path), shown_file_name(f));
                s.emit(
                    r::IDL_FILE_NOT_FOUND,
                    *pos,
                    format!(
                        "idlFile `{}` of `{port}` names no IDL file that was read; `{name}` is defined in `{defined_in}`",
                        f.trim()
                    ),
                );
                if let Some(d) = s.out.last_mut() {
                    d.hint = Some(format!(
                        "make `idlFile` name `{defined_in}` (the file that defines `{name}`), or add `{named}` below the input or pass `--idl-path DIR`"
                    ));
                }
            } else if !found.iter().any(|i| idl_file_name(&i.file.path) == wanted) {
                s.emit(
                    r::IDL_FILE_MISMATCH,
                    *pos,
                    format!(
                        "type `{name}` of `{port}` is defined in `{}`, not in its idlFile `{}`",
                        found[0].file.path,
                        f.trim()
                    ),
                );
            }
        }
        out.extend(s.out);
    }
}

/// RTC406: different definitions of one type (vendored copies that drifted apart).
fn differing_definitions(cat: &Catalog, out: &mut Vec<Diagnostic>) {
    let strip = |d: &crate::idl::IdlDefinition| -> serde_json::Value {
        fn clean(v: &mut serde_json::Value) {
            match v {
                serde_json::Value::Object(m) => {
                    m.remove("pos");
                    m.remove("file");
                    m.remove("doc");
                    m.values_mut().for_each(clean);
                }
                serde_json::Value::Array(a) => a.iter_mut().for_each(clean),
                _ => {}
            }
        }
        let mut v = serde_json::to_value(d).unwrap_or_default();
        clean(&mut v);
        v
    };
    let names = cat
        .data_types
        .iter()
        .map(|t| &t.name)
        .chain(cat.interfaces.iter().map(|t| &t.name));
    for name in names {
        let all: Vec<_> = cat
            .idl
            .find_all(name)
            .into_iter()
            .filter(|i| !matches!(i.definition, crate::idl::IdlDefinition::Forward(_)))
            .collect();
        // One definition (the usual case) has nothing to differ from.
        let Some(first) = all.first().filter(|_| all.len() > 1) else {
            continue;
        };
        let reference = strip(first.definition);
        if let Some(other) = all
            .iter()
            .skip(1)
            .find(|i| strip(i.definition) != reference)
        {
            let mut s = Findings {
                file: &other.file.path,
                out: Vec::new(),
            };
            s.emit(
                r::IDL_DEFINITIONS_DIFFER,
                other.definition.pos(),
                format!(
                    "`{name}` is defined differently here and in `{}:{}`",
                    first.file.path,
                    first.definition.pos().line
                ),
            );
            out.extend(s.out);
        }
    }
}

/// What a deprecation mark says, for a finding: "deprecated since 2.0; use `X` instead (note)".
pub(crate) fn deprecated_text(s: &crate::model::stability::Stability) -> String {
    let since = s
        .since
        .as_deref()
        .map(|v| format!(" since {v}"))
        .unwrap_or_default();
    let instead = match &s.replacement {
        Some(r) => format!("; use {} instead", Code(r)),
        None => String::new(),
    };
    let note = s
        .note
        .as_deref()
        .map(|n| format!(" ({n})"))
        .unwrap_or_default();
    format!("deprecated{since}{instead}{note}")
}

/// RTC407: each data port carrying a deprecated data type and each service interface of a
/// deprecated interface type, naming the replacement.
fn deprecated_uses(cat: &Catalog, out: &mut Vec<Diagnostic>) {
    use crate::model::stability::{Stability, Status};
    let deprecated = |s: &Option<Stability>| {
        s.as_ref()
            .filter(|s| s.status == Status::Deprecated)
            .cloned()
    };
    let finding = |c: &Component, pos: Pos, what: String, ty: &str, s: &Stability| {
        let hint = match &s.replacement {
            Some(r) => format!(
                "change the type to {} (the replacement the stability mark names), or keep it knowingly until it is removed",
                Code(r)
            ),
            None => "the stability mark names no replacement: ask the type's owners what replaces it (and add `replacement` to the mark)".to_string(),
        };
        Diagnostic::warning(
            r::USES_DEPRECATED,
            &c.source,
            format!("{what} uses {}, {}", Code(ty), deprecated_text(s)),
        )
        .at(pos)
        .with_hint(hint)
    };
    for t in &cat.data_types {
        let Some(s) = deprecated(&t.stability) else {
            continue;
        };
        for pr in t.all_uses() {
            if let Some((c, p)) = cat.port_of(pr) {
                let what = format!("data port {}", Code(p.name.as_deref().unwrap_or("")));
                out.push(finding(c, p.pos, what, &t.name, &s));
            }
        }
    }
    for t in &cat.interfaces {
        let Some(s) = deprecated(&t.stability) else {
            continue;
        };
        for ir in t.all_uses() {
            if let Some((c, sp, i)) = cat.interface_of(ir) {
                let what = format!(
                    "service interface {} of port {}",
                    Code(i.name.as_deref().unwrap_or("")),
                    Code(sp.name.as_deref().unwrap_or(""))
                );
                out.push(finding(c, i.pos, what, &t.name, &s));
            }
        }
    }
}

/// RTC401–RTC407: rules over the whole catalogue.
pub(crate) fn catalogue(cat: &Catalog) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    idl_rules(cat, &mut out);
    deprecated_uses(cat, &mut out);
    for t in cat.interfaces.iter().filter(|t| t.is_unprovided()) {
        for req in &t.uses.requirers {
            let Some((c, _, i)) = cat.interface_of(req) else {
                continue;
            };
            let mut s = Findings {
                file: &c.source,
                out: Vec::new(),
            };
            s.emit(
                r::UNPROVIDED_INTERFACE,
                i.pos,
                format!(
                    "required interface `{}` (type `{}`) is provided by no component in the catalogue",
                    i.name.as_deref().unwrap_or(""),
                    t.name
                ),
            );
            out.extend(s.out);
        }
    }
    for t in &cat.data_types {
        // file name → ports using it
        let mut by_file: BTreeMap<String, Vec<(ComponentIx, usize)>> = BTreeMap::new();
        for pr in t.all_uses() {
            let Some((ci, pi)) = cat.resolve_port(pr) else {
                continue;
            };
            let port = &cat[ci].profile.data_ports[pi];
            if let Some(f) = non_empty(&port.idl_file) {
                by_file.entry(idl_file_name(f)).or_default().push((ci, pi));
            }
        }
        if by_file.len() < 2 {
            continue;
        }
        for (file, ports) in &by_file {
            let others: Vec<&str> = by_file
                .keys()
                .filter(|k| *k != file)
                .map(String::as_str)
                .collect();
            for &(ci, pi) in ports {
                let c = &cat[ci];
                let port = &c.profile.data_ports[pi];
                let mut s = Findings {
                    file: &c.source,
                    out: Vec::new(),
                };
                s.emit(
                    r::IDL_CONFLICT,
                    port.pos,
                    format!(
                        "data type `{}` of port `{}` comes from `{}` here, but from `{}` elsewhere in the catalogue",
                        t.name,
                        port.name.as_deref().unwrap_or(""),
                        port.idl_file.as_deref().unwrap_or("").trim(),
                        others.join("`, `")
                    ),
                );
                out.extend(s.out);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn date_times() {
        for ok in [
            "2014-02-04T17:15:06+09:00",
            "2014-02-04T17:15:06",
            "2014-02-04T17:15:06.123+09:00",
            "2014-02-04T17:15:06Z",
            "2024-02-29T00:00:00",
        ] {
            assert!(check_date_time(ok).is_ok(), "{ok}");
        }
        for bad in [
            "2014-02-04",
            "2023-02-29T00:00:00",
            "2014-13-04T17:15:06",
            "2014-02-04T25:15:06",
            "2014/02/04T17:15:06",
            "2014-02-04T17:15:06+9",
            "yesterday",
            "2014-02-04T17:15:06.+09:00",
        ] {
            assert!(check_date_time(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn idl_names() {
        assert_eq!(
            idl_file_name(r"C:\Program Files\OpenRTM-aist\1.1.2\rtm\idl\BasicDataType.idl"),
            "basicdatatype.idl"
        );
        assert_eq!(
            idl_file_name("/usr/include/idl/BasicDataType.idl"),
            "basicdatatype.idl"
        );
    }
}
