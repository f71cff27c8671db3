//! The drift of a matched pair: where a component's code and its profile disagree
//! ([`crate::implementation::drift`]) on one side and not on the other. A finding is identified
//! by its component (the pair), its kind (RTC801–RTC809) and its element (`dataPorts/in`), never
//! by its line: an edit that only moves code changes nothing. A finding of NEW that OLD lacks is
//! introduced (DIFF261, a warning), one of OLD that NEW lacks resolved (DIFF361). Code read on
//! one side only is DIFF362 / DIFF363 (info): having code is no drift, but the findings of code
//! that NEW adds are new disagreements, so they are DIFF261 too; those of code that NEW removes
//! are not resolved, only no longer compared, so they are counted, not listed.

use super::{change, codes, Change, Namer};
use crate::catalog::Component;
use crate::implementation::drift::{Drift, DriftKind};
use crate::implementation::{At, Implementation, Unread};
use crate::model::Pos;
use crate::quote::Code;
use std::collections::BTreeMap;

/// The identity of a finding within its component: its kind and its element.
type Identity<'a> = (DriftKind, &'a str);

/// The findings of one identity on each side (OLD, NEW).
type Findings<'a> = (Vec<&'a Drift>, Vec<&'a Drift>);

/// One side of the pair: the component and how its files are named.
pub(super) type Side<'a> = (&'a Component, Namer<'a>);

/// The drift changes of the matched pair `old` → `new`, under `component`.
pub(super) fn compare(component: &str, old: Side, new: Side, out: &mut Vec<Change>) {
    match (
        old.0.implementation.as_deref(),
        new.0.implementation.as_deref(),
    ) {
        (None, None) => {}
        (Some(oi), None) => out.push(removed(component, oi, old, new)),
        (None, Some(ni)) => {
            out.push(added(component, ni, old, new));
            for d in &ni.drift {
                out.push(introduced(component, d, old, new));
            }
        }
        (Some(oi), Some(ni)) => {
            // The findings of each identity, in the order each side made them: the first of
            // OLD is the first of NEW, and what one side has more of is introduced or resolved.
            let mut by_id: BTreeMap<Identity, Findings> = BTreeMap::new();
            for d in &oi.drift {
                by_id.entry((d.kind, &d.element)).or_default().0.push(d);
            }
            for d in &ni.drift {
                by_id.entry((d.kind, &d.element)).or_default().1.push(d);
            }
            for (o, n) in by_id.values() {
                for d in n.iter().skip(o.len()) {
                    out.push(introduced(component, d, old, new));
                }
                for d in o.iter().skip(n.len()) {
                    out.push(resolved(component, d, ni, old, new));
                }
            }
        }
    }
}

/// What a kind of finding is about, in a few words.
fn about(kind: DriftKind) -> &'static str {
    match kind {
        DriftKind::OnlyInProfile => "declared in the profile, not registered by the code",
        DriftKind::OnlyInCode => "registered by the code, not declared in the profile",
        DriftKind::NameCase => "names that differ only in case",
        DriftKind::DataType => "another type",
        DriftKind::Direction => "another direction",
        DriftKind::Default => "another default",
        DriftKind::CallbackUnmarked => "a callback implemented but marked not implemented",
        DriftKind::CallbackMissing => "a callback marked implemented but not defined",
        DriftKind::SpecValue => "a value of the spec array",
    }
}

/// `the profile says X / the code says Y` (`nothing` for a side without the element), in the
/// tense given.
fn both_sides(d: &Drift, says: &str) -> String {
    let v = |s: &Option<String>| {
        s.as_deref()
            .map_or("nothing".to_string(), |s| Code(s).to_string())
    };
    format!(
        "the profile {says} {} / the code {says} {}",
        v(&d.profile),
        v(&d.code)
    )
}

/// The `old`/`new` value of a change: `profile: X / code: Y` (`—` for nothing).
fn value(d: &Drift) -> String {
    let v = |s: &Option<String>| s.clone().unwrap_or_else(|| "—".into());
    format!("profile: {} / code: {}", v(&d.profile), v(&d.code))
}

/// Where a finding is on a side: its place in the code, else the profile element (the
/// component's file; its position when known).
fn place(d: &Drift, c: &Component, name: Namer) -> (String, Option<Pos>, bool) {
    match &d.at {
        Some(At { file, pos }) => (name(file), Some(*pos).filter(|p| !p.is_unknown()), true),
        None => (
            name(&c.source),
            d.profile_pos.filter(|p| !p.is_unknown()),
            false,
        ),
    }
}

fn shown(file: &str, pos: Option<Pos>) -> String {
    match pos {
        Some(p) => format!("{file}:{}", p.line),
        None => file.to_string(),
    }
}

fn introduced(component: &str, d: &Drift, (oc, old_name): Side, (nc, new_name): Side) -> Change {
    let (file, pos, in_code) = place(d, nc, new_name);
    let at = shown(&file, pos);
    let where_ = if in_code {
        format!("in NEW's code at {}", Code(&at))
    } else {
        format!(
            "NEW's code has nothing there (the profile at {})",
            Code(&at)
        )
    };
    Change {
        file: Some(file),
        line: pos.map(|p| p.line),
        column: pos.map(|p| p.column),
        old_file: Some(old_name(&oc.source)),
        ..change(
            codes::DRIFT_INTRODUCED,
            component.to_string(),
            d.element.clone(),
            None,
            Some(value(d)),
            format!(
                "the code and the profile now disagree on {} ({}, {}): {}; {where_}",
                Code(&d.element),
                d.kind.code(),
                about(d.kind),
                both_sides(d, "says"),
            ),
        )
    }
}

/// Why a finding that NEW no longer makes is not verified either, when it is about a port or
/// parameter that NEW's code may register unseen: a finding that the code lacks an element is
/// only made once all its registrations of that kind were read, and one that the code has an
/// element goes away when the code registers it through a name that cannot be read (RTC810).
fn unverified_in_new(d: &Drift, new_imp: &Implementation) -> Option<String> {
    let mut parts = d.element.split('/');
    let (list, _, rest) = (parts.next(), parts.next(), parts.next());
    let (kind, what) = match (list, rest) {
        (Some("dataPorts"), None) => (Unread::DataPort, "data ports"),
        (Some("servicePorts"), None) => (Unread::ServicePort, "service ports"),
        (Some("configurationSet"), None) => (Unread::Parameter, "configuration parameters"),
        _ => return None,
    };
    let unread = new_imp
        .unverified
        .iter()
        .any(|u| u.of == kind || u.of == Unread::Any);
    match d.kind {
        DriftKind::OnlyInProfile if !new_imp.reads_all(kind) => Some(format!(
            "NEW's code registers no {what}, or some through a name or macro that cannot be read (RTC810), so what it lacks is not reported"
        )),
        DriftKind::OnlyInCode if unread => Some(format!(
            "NEW's code registers some {what} through a name or macro that cannot be read (RTC810), so what it registers is not all known"
        )),
        _ => None,
    }
}

fn resolved(
    component: &str,
    d: &Drift,
    new_imp: &Implementation,
    (oc, old_name): Side,
    (nc, new_name): Side,
) -> Change {
    let (old_file, old_pos, _) = place(d, oc, old_name);
    let was = format!(
        "in OLD {}, at {}",
        both_sides(d, "said"),
        Code(&shown(&old_file, old_pos))
    );
    let head = format!(
        "{} ({}, {})",
        Code(&d.element),
        d.kind.code(),
        about(d.kind)
    );
    let message = match unverified_in_new(d, new_imp) {
        Some(why) => format!("{head} is no longer found, but not verified either: {why}; {was}"),
        None => format!("the code and the profile agree again on {head}; {was}"),
    };
    Change {
        file: Some(new_name(&nc.source)),
        old_file: Some(old_file),
        old_line: old_pos.map(|p| p.line),
        old_column: old_pos.map(|p| p.column),
        ..change(
            codes::DRIFT_RESOLVED,
            component.to_string(),
            d.element.clone(),
            Some(value(d)),
            None,
            message,
        )
    }
}

/// `Python: a.py, b.py`.
fn files_of(imp: &Implementation, name: Namer) -> String {
    let files: Vec<String> = imp.files.iter().map(|f| name(f)).collect();
    format!("{}: {}", imp.language.name(), files.join(", "))
}

fn counted(n: usize) -> String {
    crate::diagnostic::counted(n, "drift finding")
}

fn added(
    component: &str,
    imp: &Implementation,
    (oc, old_name): Side,
    (_, new_name): Side,
) -> Change {
    let first = imp.files.first().map(|f| new_name(f));
    let then = if imp.drift.is_empty() {
        "it agrees with the profile".to_string()
    } else {
        format!(
            "{} in it, each reported as {}",
            counted(imp.drift.len()),
            codes::DRIFT_INTRODUCED
        )
    };
    Change {
        file: first,
        old_file: Some(old_name(&oc.source)),
        ..change(
            codes::IMPLEMENTATION_ADDED,
            component.to_string(),
            String::new(),
            None,
            Some(files_of(imp, new_name)),
            format!(
                "NEW has code for the component that OLD has not ({}); {then}",
                files_of(imp, new_name)
            ),
        )
    }
}

fn removed(
    component: &str,
    imp: &Implementation,
    (_, old_name): Side,
    (nc, new_name): Side,
) -> Change {
    let then = if imp.drift.is_empty() {
        "it agreed with the profile".to_string()
    } else {
        format!(
            "its {} are not resolved, only no longer compared",
            counted(imp.drift.len())
        )
    };
    Change {
        file: Some(new_name(&nc.source)),
        old_file: imp.files.first().map(|f| old_name(f)),
        ..change(
            codes::IMPLEMENTATION_REMOVED,
            component.to_string(),
            String::new(),
            Some(files_of(imp, old_name)),
            None,
            format!(
                "OLD has code for the component that NEW has not ({}); {then}",
                files_of(imp, old_name)
            ),
        )
    }
}
