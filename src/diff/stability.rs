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
/// so at the end of its message.
pub fn relax(diff: &mut Diff, new: &Catalog) {
    let labels: Vec<(ComponentIx, [String; 3])> = labels(new);
    let mut relaxed = Vec::new();
    for (i, c) in diff.changes.iter().enumerate() {
        if c.severity != Level::Breaking {
            continue;
        }
        if let Some(item) = experimental_item(new, &labels, c) {
            relaxed.push((i, item));
        }
    }
    if relaxed.is_empty() {
        return;
    }
    diff.gate.resize(diff.changes.len(), Standing::default());
    for (i, item) in relaxed {
        let c = &mut diff.changes[i];
        diff.gate[i].default_severity.get_or_insert(c.severity);
        c.severity = Level::Warning;
        c.message.push_str(&format!(
            " (relaxed: experimental — {item} is experimental)"
        ));
        diff.gate[i].relaxed = Some(item);
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
/// component, else the data type of the data port or the interface type of the service
/// interface its path names, else the IDL type of an `idl/NAME` path.
fn experimental_item(
    cat: &Catalog,
    labels: &[(ComponentIx, [String; 3])],
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
    let ci = labels
        .iter()
        .find(|(_, l)| l.contains(&c.component))
        .map(|(ci, _)| *ci)?;
    let comp = &cat[ci];
    if experimental(&comp.stability) {
        return Some(format!("component {}", Code(comp.profile.name())));
    }
    let parts: Vec<&str> = c.path.split('/').collect();
    let p = &comp.profile;
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
