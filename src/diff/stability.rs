//! Experimental items relax `diff`: a breaking change whose component, or the data type or
//! interface it is about, is marked experimental on the NEW side ([`crate::model::stability`])
//! is reported as a warning, with a note saying why.
//!
//! Applied once to the finished comparison, after the `[diff]` policy's severities (so a code
//! the policy makes breaking is relaxed too) and before the baseline ([`relax`]).

use super::{Change, Diff, Level, Standing};
use crate::catalog::{member_at, Catalog, ComponentIx};
use crate::model::stability::{Stability, Status};

/// Relaxes the breaking changes of experimental items of `new` to warnings: each keeps its
/// earlier severity as its standing's `default_severity`, names the item in `relaxed` and says
/// so at the end of its message. A component's DIFF208 (breaking changes under the same
/// version) whose breaking changes were all relaxed becomes information, saying so.
pub fn relax(diff: &mut Diff, new: &Catalog) {
    let labels: Vec<(ComponentIx, [String; 3])> = labels(new);
    let relaxed = relaxed_of(&diff.changes, &|c| {
        let ci = labels
            .iter()
            .find(|(_, l)| l.contains(&c.component))
            .map(|(ci, _)| *ci);
        let comp = ci.map(|ci| &new[ci]);
        experimental_item(new, comp.map(|c| (&*c.profile, c.stability.as_ref())), c)
    });
    if relaxed.is_empty() {
        return;
    }
    diff.gate.resize(diff.changes.len(), Standing::default());
    for (i, item) in relaxed {
        let c = &mut diff.changes[i];
        diff.gate[i].default_severity.get_or_insert(c.severity);
        relax_one(c, &item);
        diff.gate[i].relaxed = Some(item);
    }
}

/// [`relax`] for the changes between two versions of one component's history: `new` the
/// newer version's profile, `mark` its stability (the catalogue's mark for the profile as it
/// is, else the version's own `rtcdoc.stability` properties), `cat` the catalogue of the build
/// (its data types' and interfaces' marks).
pub fn relax_version(
    changes: &mut [Change],
    cat: &Catalog,
    new: &crate::model::Profile,
    mark: Option<&Stability>,
) {
    for (i, item) in relaxed_of(changes, &|c| experimental_item(cat, Some((new, mark)), c)) {
        relax_one(&mut changes[i], &item);
    }
}

/// The changes to relax, by index, with the item each is relaxed for: each breaking change
/// `item_of` names an experimental item for, then each breaking-without-version-bump
/// (DIFF208) whose component has breaking changes left none.
fn relaxed_of(
    changes: &[Change],
    item_of: &dyn Fn(&Change) -> Option<String>,
) -> Vec<(usize, String)> {
    let mut relaxed: Vec<(usize, String)> = changes
        .iter()
        .enumerate()
        .filter(|(_, c)| c.severity == Level::Breaking)
        .filter_map(|(i, c)| item_of(c).map(|item| (i, item)))
        .collect();
    let breaking_left = |component: &str| {
        changes.iter().enumerate().any(|(i, c)| {
            c.severity == Level::Breaking
                && c.component == component
                && !relaxed.iter().any(|(r, _)| *r == i)
        })
    };
    let bumps: Vec<(usize, String)> = changes
        .iter()
        .enumerate()
        .filter(|(_, c)| c.code == super::codes::BREAKING_WITHOUT_BUMP)
        .filter(|(i, _)| !relaxed.iter().any(|(r, _)| r == i))
        .filter(|(_, c)| !breaking_left(&c.component))
        .map(|(i, c)| {
            (
                i,
                format!(
                    "every breaking change of {}",
                    crate::quote::Code(&c.component)
                ),
            )
        })
        .collect();
    relaxed.extend(bumps);
    relaxed
}

/// Change `c` relaxed for `item`: a breaking change becomes a warning, a warning (DIFF208)
/// information.
fn relax_one(c: &mut Change, item: &str) {
    c.severity = if c.severity == Level::Breaking {
        Level::Warning
    } else {
        Level::Info
    };
    if c.code == super::codes::BREAKING_WITHOUT_BUMP {
        c.message
            .push_str(&format!(" (relaxed: experimental — {item} is relaxed)"));
    } else {
        c.message.push_str(&format!(
            " (relaxed: experimental — {item} is experimental)"
        ));
    }
}

/// Each component of `cat` with the labels a change may name it by (`diff`'s: the id, with the
/// language or the file when several profiles share it).
fn labels(cat: &Catalog) -> Vec<(ComponentIx, [String; 3])> {
    crate::catalog::Ix::enumerate(&cat.components)
        .map(|(ci, c)| {
            let id = super::ident(c);
            let lang = format!("{} ({})", id.id, id.language);
            let file = format!("{} ({})", id.id, c.source);
            (ci, [id.id, lang, file])
        })
        .collect()
}

fn name(n: &Option<crate::model::Text>) -> &str {
    n.as_deref().unwrap_or_default()
}

fn experimental(s: &Option<Stability>) -> bool {
    s.as_ref().is_some_and(|s| s.status == Status::Experimental)
}

/// The experimental item a change is about, quoted (`` component `X` ``), if any: its
/// component (`comp`: its profile and mark), else the data type of the data port or the
/// interface type of the service interface its path names, else the IDL type of an
/// `idl/NAME` path.
fn experimental_item(
    cat: &Catalog,
    comp: Option<(&crate::model::Profile, Option<&Stability>)>,
    c: &Change,
) -> Option<String> {
    use crate::quote::Code;
    let ty = |name: &str| -> Option<String> {
        if let Some(t) = cat.data_type(name).filter(|t| experimental(&t.stability)) {
            return Some(format!("data type {}", Code(&t.name)));
        }
        cat.interface(name)
            .filter(|t| experimental(&t.stability))
            .map(|t| format!("interface {}", Code(&t.name)))
    };
    if let Some(rest) = c.path.strip_prefix("idl/") {
        let name = rest.split('/').next().unwrap_or(rest);
        if let Some(item) = ty(name) {
            return Some(item);
        }
    }
    let (p, mark) = comp?;
    if mark.is_some_and(|s| s.status == Status::Experimental) {
        return Some(format!("component {}", Code(p.name())));
    }
    let parts: Vec<&str> = c.path.split('/').collect();
    let type_name = match parts.as_slice() {
        ["dataPorts", port, ..] => {
            let pi = member_at(p.data_ports.iter().map(|d| name(&d.name)), port)?;
            p.data_ports[pi].type_.as_deref()
        }
        ["servicePorts", port, "interfaces", iface, ..] => {
            let pi = member_at(p.service_ports.iter().map(|s| name(&s.name)), port)?;
            let sp = &p.service_ports[pi];
            let ii = member_at(sp.interfaces.iter().map(|i| name(&i.name)), iface)?;
            sp.interfaces[ii].type_.as_deref()
        }
        _ => None,
    }?;
    ty(type_name)
}
