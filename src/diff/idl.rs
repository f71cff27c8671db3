//! IDL-level comparison: for a data type carried by a port on both sides, or an interface type
//! used on both sides, the definitions found in each side's IDL ([`IdlSet`], read as `build`
//! reads it) are compared — nested structs, unions, enums and typedefs followed transitively,
//! interfaces with the operations and attributes they inherit.
//!
//! A type is compared once ([`IdlDiff::outcome`], cached by canonical name); its findings carry
//! paths relative to the type (`fields/pose.heading`, `values/STOPPED`,
//! `operations/getMap/params/id`), which the caller prefixes with the port's path and turns into
//! [`Change`]s per port, so each change names the component whose port carries the type.

use super::codes;
use super::Change;
use crate::idl::{
    IdlAttribute, IdlBound, IdlDefinition, IdlField, IdlInterface, IdlItem, IdlOperation,
    IdlParamDirection, IdlSet, IdlType,
};
use crate::types::canonical_type;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::rc::Rc;

/// What a finding is, before the use of the type (data port, provided or required interface)
/// gives it a code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    RepositoryId,
    MemberAdded,
    MemberRemoved,
    Reordered,
    MemberRetyped,
    EnumRemoved,
    EnumAppended,
    Union,
    Typedef,
    /// An operation or attribute of the interface itself (not of a type nested in it).
    OperationRemoved,
    OperationChanged,
    OperationAdded,
    Documentation,
    Other,
}

/// One difference inside a type.
#[derive(Debug, Clone)]
pub(super) struct Finding {
    pub kind: Kind,
    /// Relative to the type; empty for the type itself.
    pub path: String,
    pub old: Option<String>,
    pub new: Option<String>,
    pub message: String,
    /// Where in the IDL files the finding is, when known.
    pub loc: Option<Loc>,
}

/// Where a finding is in the IDL files: the file (as the set names it) and the position, in
/// NEW, or in OLD for an item only OLD has (a removed member).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Loc {
    pub file: String,
    pub pos: crate::model::Pos,
    pub in_old: bool,
}

/// The comparison of one type.
#[derive(Debug, Default)]
pub(super) struct Outcome {
    pub findings: Vec<Finding>,
    /// Types met on the way that only one side defines: (scoped name, defined in NEW).
    pub one_side: Vec<(String, bool)>,
    /// Every definition compared on the way (the type itself and those it holds), by scoped
    /// name: their changes are reported with this type's.
    pub visited: BTreeSet<String>,
}

/// Every comparison of one diff: both IDL sets, the cache and the one-sided types.
pub(super) struct IdlDiff<'a> {
    old: &'a IdlSet,
    new: &'a IdlSet,
    cache: HashMap<String, Rc<Outcome>>,
    /// Scoped name → (defined in NEW, components whose ports carry it).
    one_side: BTreeMap<String, (bool, BTreeSet<String>)>,
    /// Every definition the ports' types led to ([`Outcome::visited`]): their changes are
    /// reported with the ports, and not again on their own ([`unused_types`]).
    visited: BTreeSet<String>,
    /// The types the ports carry whose comparison found a change.
    changed: BTreeSet<String>,
}

/// Nested definitions compared for one type at most (a guard against exponential fan-out of
/// types that hold the same struct many times over).
const BUDGET: usize = 20_000;

/// Definitions nested one in another that are followed at most (a chain of structs each holding
/// the one before would otherwise recurse once per link, past the stack).
const NESTING: usize = 128;

impl<'a> IdlDiff<'a> {
    pub fn new(old: &'a IdlSet, new: &'a IdlSet) -> Self {
        IdlDiff {
            old,
            new,
            cache: HashMap::new(),
            one_side: BTreeMap::new(),
            visited: BTreeSet::new(),
            changed: BTreeSet::new(),
        }
    }

    /// Neither side has IDL: nothing to compare.
    pub fn is_idle(&self) -> bool {
        self.old.is_empty() && self.new.is_empty()
    }

    /// The comparison of the type a port or interface names (any spelling), used by the
    /// component labelled `component`.
    pub fn outcome(&mut self, name: &str, component: &str) -> Rc<Outcome> {
        let key = canonical_type(name);
        let outcome = match self.cache.get(&key) {
            Some(o) => o.clone(),
            None => {
                let o = Rc::new(compare_type(self.old, self.new, &key));
                // Once per type (the cache): no pass over the visited set per port.
                self.visited.extend(o.visited.iter().cloned());
                if !o.findings.is_empty() {
                    self.changed.insert(key.clone());
                }
                self.cache.insert(key, o.clone());
                o
            }
        };
        for (name, in_new) in &outcome.one_side {
            self.one_side
                .entry(name.clone())
                .or_insert_with(|| (*in_new, BTreeSet::new()))
                .1
                .insert(component.to_string());
        }
        outcome
    }

    /// DIFF332 for every type found on one side only, once each; what the ports' types led
    /// to, for [`unused_types`].
    pub fn finish(self, out: &mut Vec<Change>) -> Compared {
        for (name, (in_new, users)) in self.one_side {
            let (has, lacks) = if in_new {
                ("NEW", "OLD")
            } else {
                ("OLD", "NEW")
            };
            let users: Vec<String> = users.iter().map(|u| format!("`{u}`")).collect();
            out.push(super::change(
                codes::IDL_TYPE_ON_ONE_SIDE,
                String::new(),
                format!("idl/{name}"),
                (!in_new).then(|| name.clone()),
                in_new.then(|| name.clone()),
                format!(
                    "`{name}` is defined in {has}'s IDL only, so changes inside it are not seen (add its IDL file to {lacks}, or pass --idl-path); used by ports of {}",
                    users.join(", ")
                ),
            ));
        }
        Compared {
            visited: self.visited,
            changed: self.changed,
        }
    }
}

/// What the comparison of the ports' types covered ([`IdlDiff::finish`]).
#[derive(Debug, Default)]
pub(super) struct Compared {
    /// Every definition compared through a port, nested ones included.
    visited: BTreeSet<String>,
    /// The types carried by ports whose comparison found a change.
    changed: BTreeSet<String>,
}

/// A definition that can be compared (forward declarations and skipped ones cannot).
fn find<'s>(set: &'s IdlSet, name: &str) -> Option<IdlItem<'s>> {
    set.find(name).filter(|i| {
        !matches!(
            i.definition,
            IdlDefinition::Forward(_) | IdlDefinition::Skipped(_)
        )
    })
}

fn compare_type(old: &IdlSet, new: &IdlSet, name: &str) -> Outcome {
    compare_type_past(old, new, name, &BTreeSet::new())
}

/// [`compare_type`], with the definitions of `reported` (compared already, their changes
/// reported where they were met: through a port) not compared again inside `name`.
fn compare_type_past(
    old: &IdlSet,
    new: &IdlSet,
    name: &str,
    reported: &BTreeSet<String>,
) -> Outcome {
    let mut cmp = Cmp {
        old,
        new,
        out: Outcome::default(),
        stack: Vec::new(),
        budget: BUDGET,
        reported,
    };
    match (find(old, name), find(new, name)) {
        (Some(o), Some(n)) => cmp.def(&P::root(), o, n, true),
        (Some(o), None) => cmp.one_sided(o.definition.scoped_name(), false),
        (None, Some(n)) => cmp.one_sided(n.definition.scoped_name(), true),
        (None, None) => {}
    }
    cmp.out
}

/// A path inside a type: `fields/a.b[].c`, `values/X`, `operations/op/params/p.x`.
#[derive(Debug, Clone)]
struct P {
    base: String,
    /// Inside a member: nested members are joined with `.`.
    in_member: bool,
}

fn join(a: &str, b: &str) -> String {
    if a.is_empty() {
        b.to_string()
    } else {
        format!("{a}/{b}")
    }
}

impl P {
    fn root() -> P {
        P {
            base: String::new(),
            in_member: false,
        }
    }
    fn member(&self, name: &str) -> P {
        let base = if self.in_member {
            format!("{}.{name}", self.base)
        } else {
            join(&self.base, &format!("fields/{name}"))
        };
        P {
            base,
            in_member: true,
        }
    }
    fn element(&self) -> P {
        if self.in_member {
            P {
                base: format!("{}[]", self.base),
                in_member: true,
            }
        } else {
            self.clone()
        }
    }
    fn seg(&self, s: &str) -> P {
        P {
            base: join(&self.base, s),
            in_member: false,
        }
    }
    /// A named slot whose own members are dotted (a union case, a parameter, an attribute).
    fn slot(&self, s: &str) -> P {
        P {
            base: join(&self.base, s),
            in_member: true,
        }
    }
}

fn bound(b: &IdlBound) -> String {
    b.value
        .map_or_else(|| b.expr.trim().to_string(), |v| v.to_string())
}

fn dims(a: &[IdlBound]) -> String {
    a.iter().map(|b| format!("[{}]", bound(b))).collect()
}

fn named_of(name: &str, resolved: &Option<String>) -> String {
    resolved
        .clone()
        .unwrap_or_else(|| name.trim().trim_start_matches("::").to_string())
}

/// The type as written, with names resolved (`Time` inside `module RTC` is `RTC::Time`).
fn written(t: &IdlType) -> String {
    match t {
        IdlType::Named { name, resolved } => named_of(name, resolved),
        IdlType::Sequence { element, bound: b } => match b {
            Some(b) => format!("sequence<{}, {}>", written(element), bound(b)),
            None => format!("sequence<{}>", written(element)),
        },
        IdlType::String { wide, bound: b } => {
            let w = if *wide { "wstring" } else { "string" };
            match b {
                Some(b) => format!("{w}<{}>", bound(b)),
                None => w.to_string(),
            }
        }
        IdlType::Fixed { digits, scale } => match (digits, scale) {
            (Some(d), Some(s)) => format!("fixed<{}, {}>", bound(d), bound(s)),
            _ => "fixed".to_string(),
        },
        other => other.to_idl(),
    }
}

/// The type with typedefs followed to what they name (for deciding whether two spellings are
/// the same type on the wire).
fn expanded(set: &IdlSet, t: &IdlType, depth: usize) -> String {
    if depth > 32 {
        return written(t);
    }
    match t {
        IdlType::Named { name, resolved } => {
            let n = named_of(name, resolved);
            match find(set, &n).map(|i| i.definition) {
                Some(IdlDefinition::Typedef(td)) => {
                    format!("{}{}", expanded(set, &td.ty, depth + 1), dims(&td.array))
                }
                Some(d) => d.scoped_name().to_string(),
                None => n,
            }
        }
        IdlType::Sequence { element, bound: b } => match b {
            Some(b) => format!(
                "sequence<{}, {}>",
                expanded(set, element, depth + 1),
                bound(b)
            ),
            None => format!("sequence<{}>", expanded(set, element, depth + 1)),
        },
        other => written(other),
    }
}

fn doc_text(d: Option<&crate::idl::IdlDoc>) -> Option<&str> {
    d.map(|d| d.text.trim()).filter(|t| !t.is_empty())
}

/// Where an item of `item`'s file is: shown in a message as ` (file:line)`, kept as the
/// finding's [`Loc`].
struct At(Loc);

impl std::fmt::Display for At {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Loc { file, pos, .. } = &self.0;
        if pos.line > 0 {
            write!(f, " ({file}:{})", pos.line)
        } else {
            write!(f, " ({file})")
        }
    }
}

impl At {
    fn loc(&self) -> Option<Loc> {
        Some(self.0.clone())
    }
}

/// An item of NEW's `item` at `pos`.
fn at(item: &IdlItem, pos: crate::model::Pos) -> At {
    At(Loc {
        file: item.file.path.clone(),
        pos,
        in_old: false,
    })
}

/// An item only OLD's `item` has, at `pos`.
fn at_old(item: &IdlItem, pos: crate::model::Pos) -> At {
    At(Loc {
        in_old: true,
        ..at(item, pos).0
    })
}

/// What a member, case or attribute holds: its type, array bounds and doc comment.
type Held<'s, 'a> = (&'s IdlType, &'a [IdlBound], Option<&'a crate::idl::IdlDoc>);

struct Cmp<'s> {
    old: &'s IdlSet,
    new: &'s IdlSet,
    out: Outcome,
    /// Scoped names being compared (a recursive type is not entered twice).
    stack: Vec<String>,
    budget: usize,
    /// Definitions whose changes are reported elsewhere (through a port, or on their own):
    /// not compared inside this type.
    reported: &'s BTreeSet<String>,
}

impl<'s> Cmp<'s> {
    fn push(
        &mut self,
        kind: Kind,
        p: &str,
        (old, new): (Option<String>, Option<String>),
        msg: String,
        loc: Option<Loc>,
    ) {
        self.out.findings.push(Finding {
            kind,
            path: p.to_string(),
            old,
            new,
            message: msg,
            loc,
        });
    }

    /// Where an operation or attribute at `pos` is: in the file of `from`, the interface that
    /// declares it (a base may be in another file), of NEW when `in_new`, else of OLD;
    /// `fallback`'s file when `from` is not found.
    fn declared(&self, in_new: bool, from: &str, pos: crate::model::Pos, fallback: &IdlItem) -> At {
        let set = if in_new { self.new } else { self.old };
        let file = find(set, from).map_or(fallback.file, |i| i.file);
        At(Loc {
            file: file.path.clone(),
            pos,
            in_old: !in_new,
        })
    }

    fn one_sided(&mut self, name: &str, in_new: bool) {
        let name = name.to_string();
        if !self.out.one_side.iter().any(|(n, _)| *n == name) {
            self.out.one_side.push((name, in_new));
        }
    }

    fn doc(
        &mut self,
        p: &P,
        what: &str,
        o: Option<&crate::idl::IdlDoc>,
        n: Option<&crate::idl::IdlDoc>,
        loc: Option<Loc>,
    ) {
        let (a, b) = (doc_text(o), doc_text(n));
        if a != b {
            self.push(
                Kind::Documentation,
                &p.base,
                (a.map(str::to_string), b.map(str::to_string)),
                format!("the doc comment of {what} changed"),
                loc,
            );
        }
    }

    /// Whether the comparison stops at `name` (item `n`): past the budget of nested types or
    /// the nesting limit, said once for the whole comparison.
    fn stopped(&mut self, p: &P, name: &str, n: &IdlItem<'s>) -> bool {
        let stop = if self.budget == 0 {
            Some(format!("more than {BUDGET} nested types"))
        } else if self.stack.len() >= NESTING {
            Some(format!("nested more than {NESTING} definitions deep"))
        } else {
            None
        };
        let Some(why) = stop else {
            return false;
        };
        if !self
            .out
            .findings
            .iter()
            .any(|f| f.kind == Kind::Other && f.message.starts_with("comparison stopped"))
        {
            self.push(
                Kind::Other,
                &p.base,
                (None, None),
                format!("comparison stopped at `{name}`: {why}"),
                at(n, n.definition.pos()).loc(),
            );
        }
        true
    }

    /// Compares two definitions of one name. `top`: the type a port or interface names.
    fn def(&mut self, p: &P, o: IdlItem<'s>, n: IdlItem<'s>, top: bool) {
        let (od, nd) = (o.definition, n.definition);
        let name = nd.scoped_name().to_string();
        // A definition met again inside the same type (an enum every operation returns, a
        // struct two members hold) was compared where it was first met: its changes are
        // reported once, there, not once per use.
        let seen = |n: &String| self.out.visited.contains(n) || self.reported.contains(n);
        if self.stack.contains(&name) || (!top && seen(&name)) {
            return;
        }
        if self.stopped(p, &name, &n) {
            return;
        }
        self.budget -= 1;
        self.out.visited.insert(name.clone());
        let here = at(&n, nd.pos());
        if top && od.repository_id() != nd.repository_id() {
            self.push(
                Kind::RepositoryId,
                &p.base,
                (
                    Some(od.repository_id().to_string()),
                    Some(nd.repository_id().to_string()),
                ),
                format!(
                    "the repository id of `{name}` changed from `{}` to `{}`{here}",
                    od.repository_id(),
                    nd.repository_id(),
                ),
                here.loc(),
            );
        }
        if od.kind_word() != nd.kind_word() {
            self.push(
                Kind::Typedef,
                &p.base,
                (
                    Some(format!("{} {name}", od.kind_word())),
                    Some(format!("{} {name}", nd.kind_word())),
                ),
                format!(
                    "`{name}` was a {} and is now a {}{here}",
                    od.kind_word(),
                    nd.kind_word(),
                ),
                here.loc(),
            );
            return;
        }
        self.stack.push(name.clone());
        self.doc(p, &format!("`{name}`"), od.doc(), nd.doc(), here.loc());
        match (od, nd) {
            (IdlDefinition::Struct(a), IdlDefinition::Struct(b)) => {
                self.members(p, &a.fields, &b.fields, &name, (&o, &n))
            }
            (IdlDefinition::Exception(a), IdlDefinition::Exception(b)) => {
                self.members(p, &a.fields, &b.fields, &name, (&o, &n))
            }
            (IdlDefinition::Enum(a), IdlDefinition::Enum(b)) => {
                let ov: Vec<&str> = a.values.iter().map(|v| v.name.as_str()).collect();
                let nv: Vec<&str> = b.values.iter().map(|v| v.name.as_str()).collect();
                self.enums(p, &ov, &nv, &name, &n);
                for v in &b.values {
                    if let Some(ov) = a.values.iter().find(|x| x.name == v.name) {
                        self.doc(
                            &p.seg(&format!("values/{}", v.name)),
                            &format!("value `{}` of `{name}`", v.name),
                            ov.doc.as_deref(),
                            v.doc.as_deref(),
                            here.loc(),
                        );
                    }
                }
            }
            (IdlDefinition::Union(a), IdlDefinition::Union(b)) => {
                self.union(p, (a, b), &name, (&o, &n))
            }
            (IdlDefinition::Typedef(a), IdlDefinition::Typedef(b)) => self.slot(
                p,
                (&a.ty, &a.array),
                (&b.ty, &b.array),
                Kind::Typedef,
                &format!("typedef `{name}`"),
                &at(&n, nd.pos()),
            ),
            (IdlDefinition::Interface(a), IdlDefinition::Interface(b)) if top => {
                self.interface(p, a, b, &name, &n)
            }
            (IdlDefinition::Const(a), IdlDefinition::Const(b))
                if written(&a.ty) != written(&b.ty) || a.value != b.value || a.expr != b.expr =>
            {
                self.push(
                    Kind::Other,
                    &p.base,
                    (Some(a.expr.clone()), Some(b.expr.clone())),
                    format!("constant `{name}` changed{here}"),
                    here.loc(),
                );
            }
            _ => {}
        }
        self.stack.pop();
    }

    /// The changes of union `name` (`a` of item `o` before, `b` of `n` after): its
    /// discriminator, and each case removed, added, selected otherwise or holding another type.
    fn union(
        &mut self,
        p: &P,
        (a, b): (&'s crate::idl::IdlUnion, &'s crate::idl::IdlUnion),
        name: &str,
        (o, n): (&IdlItem<'s>, &IdlItem<'s>),
    ) {
        let nd = n.definition;
        self.slot(
            &p.seg("switch"),
            (&a.switch_type, &[]),
            (&b.switch_type, &[]),
            Kind::Union,
            &format!("the discriminator of union `{name}`"),
            &at(n, nd.pos()),
        );
        let case_name = |c: &crate::idl::IdlUnionCase| c.field.name.clone();
        for c in &a.cases {
            if !b.cases.iter().any(|x| case_name(x) == case_name(c)) {
                self.push(
                    Kind::Union,
                    &p.slot(&format!("cases/{}", c.field.name)).base,
                    (Some(case_text(c)), None),
                    format!("case `{}` of union `{name}` was removed", c.field.name),
                    at_old(o, c.field.pos).loc(),
                );
            }
        }
        for c in &b.cases {
            let cp = p.slot(&format!("cases/{}", c.field.name));
            let Some(oc) = a.cases.iter().find(|x| case_name(x) == case_name(c)) else {
                self.push(
                    Kind::Union,
                    &cp.base,
                    (None, Some(case_text(c))),
                    format!(
                        "case `{}` was added to union `{name}`{}",
                        c.field.name,
                        at(n, c.field.pos)
                    ),
                    at(n, c.field.pos).loc(),
                );
                continue;
            };
            let labels = |c: &crate::idl::IdlUnionCase| {
                let mut l: Vec<String> = c
                    .labels
                    .iter()
                    .map(|s| s.split_whitespace().collect())
                    .collect();
                if c.is_default {
                    l.push("default".into());
                }
                l.sort();
                l.dedup();
                l
            };
            if labels(oc) != labels(c) {
                self.push(
                    Kind::Union,
                    &cp.base,
                    (Some(labels(oc).join(", ")), Some(labels(c).join(", "))),
                    format!(
                        "case `{}` of union `{name}` is selected by {} instead of {}{}",
                        c.field.name,
                        labels(c).join(", "),
                        labels(oc).join(", "),
                        at(n, c.field.pos)
                    ),
                    at(n, c.field.pos).loc(),
                );
            }
            let (of, nf) = (&oc.field, &c.field);
            self.held(
                &cp,
                (&of.ty, &of.array, of.doc.as_deref()),
                (&nf.ty, &nf.array, nf.doc.as_deref()),
                Kind::Union,
                (
                    &format!("case `{}` of union `{name}`", nf.name),
                    &format!("case `{}` of `{name}`", nf.name),
                ),
                &at(n, nf.pos),
            );
        }
    }

    fn members(
        &mut self,
        p: &P,
        of: &'s [IdlField],
        nf: &'s [IdlField],
        owner: &str,
        (o, n): (&IdlItem<'s>, &IdlItem<'s>),
    ) {
        let ty = |f: &IdlField| format!("{}{}", written(&f.ty), dims(&f.array));
        let on: Vec<&str> = of.iter().map(|f| f.name.as_str()).collect();
        let nn: Vec<&str> = nf.iter().map(|f| f.name.as_str()).collect();
        for f in of.iter().filter(|f| !nn.contains(&f.name.as_str())) {
            self.push(
                Kind::MemberRemoved,
                &p.member(&f.name).base,
                (Some(format!("{} {}", ty(f), f.name)), None),
                format!(
                    "member `{}` ({}) of `{owner}` was removed{}",
                    f.name,
                    ty(f),
                    at_old(o, f.pos)
                ),
                at_old(o, f.pos).loc(),
            );
        }
        for (i, f) in nf.iter().enumerate() {
            if !on.contains(&f.name.as_str()) {
                self.push(
                    Kind::MemberAdded,
                    &p.member(&f.name).base,
                    (None, Some(format!("{} {}", ty(f), f.name))),
                    format!(
                        "member `{}` ({}) was added to `{owner}` as member {} of {}{}",
                        f.name,
                        ty(f),
                        i + 1,
                        nf.len(),
                        at(n, f.pos)
                    ),
                    at(n, f.pos).loc(),
                );
            }
        }
        let co: Vec<&str> = on.iter().copied().filter(|x| nn.contains(x)).collect();
        let cn: Vec<&str> = nn.iter().copied().filter(|x| on.contains(x)).collect();
        if co != cn {
            let here = if p.base.is_empty() {
                "fields".to_string()
            } else {
                p.base.clone()
            };
            self.push(
                Kind::Reordered,
                &here,
                (Some(co.join(", ")), Some(cn.join(", "))),
                format!(
                    "the members of `{owner}` changed their order: {} → {}{}",
                    co.join(", "),
                    cn.join(", "),
                    at(n, n.definition.pos())
                ),
                at(n, n.definition.pos()).loc(),
            );
        }
        for f in nf {
            let Some(of) = of.iter().find(|x| x.name == f.name) else {
                continue;
            };
            let what = format!("member `{}` of `{owner}`", f.name);
            self.held(
                &p.member(&f.name),
                (&of.ty, &of.array, of.doc.as_deref()),
                (&f.ty, &f.array, f.doc.as_deref()),
                Kind::MemberRetyped,
                (&what, &what),
                &at(n, f.pos),
            );
        }
    }

    fn enums(&mut self, p: &P, ov: &[&str], nv: &[&str], owner: &str, n: &IdlItem) {
        for (i, v) in ov.iter().enumerate() {
            if !nv.contains(v) {
                self.push(
                    Kind::EnumRemoved,
                    &p.seg(&format!("values/{v}")).base,
                    (Some(v.to_string()), None),
                    format!("value `{v}` (number {i}) was removed from enum `{owner}`"),
                    at(n, n.definition.pos()).loc(),
                );
            }
        }
        let mut renumbered = Vec::new();
        for (i, v) in nv.iter().enumerate() {
            match ov.iter().position(|x| x == v) {
                Some(j) if j != i => renumbered.push(format!("`{v}` {j} → {i}")),
                None if i < ov.len() => {
                    renumbered.push(format!("`{v}` inserted as {i} (was `{}`)", ov[i]))
                }
                _ => {}
            }
        }
        if !renumbered.is_empty() {
            self.push(
                Kind::EnumRemoved,
                &p.seg("values").base,
                (Some(ov.join(", ")), Some(nv.join(", "))),
                format!(
                    "values of enum `{owner}` changed their numbers: {}{}",
                    renumbered.join(", "),
                    at(n, n.definition.pos())
                ),
                at(n, n.definition.pos()).loc(),
            );
        }
        for (i, v) in nv.iter().enumerate().skip(ov.len()) {
            if !ov.contains(v) {
                self.push(Kind::EnumAppended, &p.seg(&format!("values/{v}")).base, (None, Some(v.to_string())), format!(
                        "value `{v}` (number {i}) was appended to enum `{owner}`: peers built from the old IDL do not know it{}",
                        at(n, n.definition.pos())
                    ), at(n, n.definition.pos()).loc());
            }
        }
    }

    /// Compares what a member, case, typedef, parameter or result holds. Another type on the
    /// wire is `kind`; the same type written differently is `Other`; the same named type is
    /// compared inside.
    fn slot(
        &mut self,
        p: &P,
        (ot, oa): (&'s IdlType, &[IdlBound]),
        (nt, na): (&'s IdlType, &[IdlBound]),
        kind: Kind,
        what: &str,
        loc: &At,
    ) {
        let wo = format!("{}{}", written(ot), dims(oa));
        let wn = format!("{}{}", written(nt), dims(na));
        // The same type written the same way: what changed is inside it (a typedef's target
        // is reported by the typedef, a struct's members by the struct).
        if wo != wn {
            let eo = format!("{}{}", expanded(self.old, ot, 0), dims(oa));
            let en = format!("{}{}", expanded(self.new, nt, 0), dims(na));
            if eo != en {
                self.push(
                    kind,
                    &p.base,
                    (Some(wo.clone()), Some(wn.clone())),
                    format!("{what} is now `{wn}` instead of `{wo}`{loc}"),
                    loc.loc(),
                );
                return;
            }
            self.push(
                Kind::Other,
                &p.base,
                (Some(wo.clone()), Some(wn.clone())),
                format!("{what} is written `{wn}` instead of `{wo}`, the same type (`{en}`){loc}"),
                loc.loc(),
            );
        }
        // An array's members are its elements' (`m[]` like a sequence).
        let p = if na.is_empty() {
            p.clone()
        } else {
            p.element()
        };
        self.descend(&p, ot, nt, 0);
    }

    /// A member, union case or attribute on both sides: what it holds (`slot`, named `what`)
    /// and its doc comment (named `doc_what`).
    fn held(
        &mut self,
        p: &P,
        (ot, oa, od): Held<'s, '_>,
        (nt, na, nd): Held<'s, '_>,
        kind: Kind,
        (what, doc_what): (&str, &str),
        loc: &At,
    ) {
        self.slot(p, (ot, oa), (nt, na), kind, what, loc);
        self.doc(p, doc_what, od, nd, loc.loc());
    }

    /// Follows two types of the same shape into the named definitions they hold.
    fn descend(&mut self, p: &P, ot: &'s IdlType, nt: &'s IdlType, depth: usize) {
        if depth > 32 {
            return;
        }
        let typedef = |set: &'s IdlSet, t: &IdlType| -> Option<&'s IdlType> {
            let IdlType::Named { name, resolved } = t else {
                return None;
            };
            match find(set, &named_of(name, resolved))?.definition {
                IdlDefinition::Typedef(td) => Some(&td.ty),
                _ => None,
            }
        };
        match (ot, nt) {
            (IdlType::Sequence { element: a, .. }, IdlType::Sequence { element: b, .. }) => {
                self.descend(&p.element(), a, b, depth + 1)
            }
            (
                IdlType::Named {
                    name: an,
                    resolved: ar,
                },
                IdlType::Named {
                    name: bn,
                    resolved: br,
                },
            ) if named_of(an, ar) == named_of(bn, br) => {
                let name = named_of(bn, br);
                match (find(self.old, &name), find(self.new, &name)) {
                    (Some(o), Some(n)) => {
                        // An interface held by a member is an object reference: compared by
                        // name only.
                        if !matches!(n.definition, IdlDefinition::Interface(_)) {
                            self.def(p, o, n, false)
                        }
                    }
                    (Some(o), None) => self.one_sided(o.definition.scoped_name(), false),
                    (None, Some(n)) => self.one_sided(n.definition.scoped_name(), true),
                    (None, None) => {}
                }
            }
            (IdlType::Named { .. }, _) => {
                if let Some(t) = typedef(self.old, ot) {
                    self.descend(p, t, nt, depth + 1)
                }
            }
            (_, IdlType::Named { .. }) => {
                if let Some(t) = typedef(self.new, nt) {
                    self.descend(p, ot, t, depth + 1)
                }
            }
            _ => {}
        }
    }

    fn interface(
        &mut self,
        p: &P,
        a: &'s IdlInterface,
        b: &'s IdlInterface,
        name: &str,
        n: &IdlItem,
    ) {
        let bases = |i: &IdlInterface| -> Vec<String> { i.bases.iter().map(written).collect() };
        let here = at(n, n.definition.pos());
        if bases(a) != bases(b) {
            self.push(Kind::Other, &p.seg("bases").base, (Some(bases(a).join(", ")), Some(bases(b).join(", "))), format!(
                    "interface `{name}` inherits from {} instead of {} (the operations are compared with the inherited ones)",
                    list_or_none(&bases(b)),
                    list_or_none(&bases(a))
                ), here.loc());
        }
        let (oo, oa) = flatten(self.old, a);
        let (no, na) = flatten(self.new, b);
        for (op, from) in &oo {
            if !no.iter().any(|(x, _)| x.name == op.name) {
                self.push(
                    Kind::OperationRemoved,
                    &p.seg(&format!("operations/{}", op.name)).base,
                    (Some(signature(op)), None),
                    format!(
                        "operation `{}`{} was removed from interface `{name}`",
                        op.name,
                        inherited(from, name)
                    ),
                    self.declared(false, from, op.pos, n).loc(),
                );
            }
        }
        for (op, from) in &no {
            let opath = p.seg(&format!("operations/{}", op.name));
            let op_at = self.declared(true, from, op.pos, n);
            let Some((old_op, _)) = oo.iter().find(|(x, _)| x.name == op.name) else {
                self.push(
                    Kind::OperationAdded,
                    &opath.base,
                    (None, Some(signature(op))),
                    format!(
                        "operation `{}`{} was added to interface `{name}`{}",
                        op.name,
                        inherited(from, name),
                        op_at
                    ),
                    op_at.loc(),
                );
                continue;
            };
            self.operation(&opath, old_op, op, name, &op_at);
        }
        for (at_, from) in &oa {
            if !na.iter().any(|(x, _)| x.name == at_.name) {
                self.push(Kind::OperationRemoved, &p.seg(&format!("attributes/{}", at_.name)).base, (Some(attribute_text(at_)), None), format!(
                        "attribute `{}` (its _get_/_set_ operations) was removed from interface `{name}`",
                        at_.name
                    ), self.declared(false, from, at_.pos, n).loc());
            }
        }
        for (nat, from) in &na {
            let ap = p.slot(&format!("attributes/{}", nat.name));
            let nat_at = self.declared(true, from, nat.pos, n);
            let Some((oat, _)) = oa.iter().find(|(x, _)| x.name == nat.name) else {
                self.push(
                    Kind::OperationAdded,
                    &ap.base,
                    (None, Some(attribute_text(nat))),
                    format!(
                        "attribute `{}` was added to interface `{name}`{}",
                        nat.name, nat_at
                    ),
                    nat_at.loc(),
                );
                continue;
            };
            if expanded(self.old, &oat.ty, 0) != expanded(self.new, &nat.ty, 0)
                || oat.readonly != nat.readonly
            {
                self.push(
                    Kind::OperationChanged,
                    &ap.base,
                    (Some(attribute_text(oat)), Some(attribute_text(nat))),
                    format!(
                        "attribute `{}` of interface `{name}` is now `{}` instead of `{}`{}",
                        nat.name,
                        attribute_text(nat),
                        attribute_text(oat),
                        nat_at
                    ),
                    nat_at.loc(),
                );
            } else {
                let what = format!("attribute `{}` of `{name}`", nat.name);
                self.held(
                    &ap,
                    (&oat.ty, &[], oat.doc.as_deref()),
                    (&nat.ty, &[], nat.doc.as_deref()),
                    Kind::OperationChanged,
                    (&what, &what),
                    &nat_at,
                );
            }
        }
    }

    fn operation(
        &mut self,
        opath: &P,
        a: &'s IdlOperation,
        b: &'s IdlOperation,
        iface: &str,
        here: &At,
    ) {
        let mut what = Vec::new();
        if a.oneway != b.oneway {
            what.push(if b.oneway {
                "it is now oneway".to_string()
            } else {
                "it is no longer oneway".to_string()
            });
        }
        let ret = |set: &IdlSet, o: &IdlOperation| {
            o.return_type
                .as_ref()
                .map_or("void".to_string(), |t| expanded(set, t, 0))
        };
        if ret(self.old, a) != ret(self.new, b) {
            what.push(format!(
                "it returns `{}` instead of `{}`",
                ret(self.new, b),
                ret(self.old, a)
            ));
        }
        if a.params.len() != b.params.len() {
            let text = |p: &crate::idl::IdlParam| {
                format!("`{} {} {}`", dir(p.direction), written(&p.ty), p.name)
            };
            let mut detail: Vec<String> = Vec::new();
            for x in b
                .params
                .iter()
                .filter(|x| !a.params.iter().any(|y| y.name == x.name))
            {
                detail.push(format!("{} added", text(x)));
            }
            for x in a
                .params
                .iter()
                .filter(|x| !b.params.iter().any(|y| y.name == x.name))
            {
                detail.push(format!("{} removed", text(x)));
            }
            what.push(format!(
                "it takes {} parameter(s) instead of {}{}",
                b.params.len(),
                a.params.len(),
                if detail.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", detail.join(", "))
                }
            ));
        } else {
            for (i, (x, y)) in a.params.iter().zip(&b.params).enumerate() {
                if x.direction != y.direction {
                    what.push(format!(
                        "parameter {} `{}` is `{}` instead of `{}`",
                        i + 1,
                        y.name,
                        dir(y.direction),
                        dir(x.direction)
                    ));
                }
                let (tx, ty) = (expanded(self.old, &x.ty, 0), expanded(self.new, &y.ty, 0));
                if tx != ty {
                    what.push(format!(
                        "parameter {} `{}` is `{}` instead of `{}`",
                        i + 1,
                        y.name,
                        written(&y.ty),
                        written(&x.ty)
                    ));
                }
            }
        }
        let raises =
            |o: &IdlOperation| -> BTreeSet<String> { o.raises.iter().map(written).collect() };
        if raises(a) != raises(b) {
            what.push(format!(
                "it raises {} instead of {}",
                list_or_none(&raises(b).into_iter().collect::<Vec<_>>()),
                list_or_none(&raises(a).into_iter().collect::<Vec<_>>())
            ));
        }
        // A change on the wire, else only another way of writing the same signature.
        let (sa, sb) = (signature(a), signature(b));
        let on_wire = !what.is_empty();
        if on_wire || sa != sb {
            let (kind, message) = if on_wire {
                (
                    Kind::OperationChanged,
                    format!(
                        "the signature of operation `{}` of interface `{iface}` changed: {}{}",
                        b.name,
                        what.join("; "),
                        here
                    ),
                )
            } else {
                (
                    Kind::Other,
                    format!(
                        "operation `{}` of `{iface}` is written differently (parameter names, context or type spellings), with the same signature on the wire",
                        b.name
                    ),
                )
            };
            self.push(kind, &opath.base, (Some(sa), Some(sb)), message, here.loc());
        }
        if on_wire {
            return;
        }
        self.doc(
            opath,
            &format!("operation `{}` of `{iface}`", b.name),
            a.doc.as_deref(),
            b.doc.as_deref(),
            here.loc(),
        );
        for (x, y) in a.params.iter().zip(&b.params) {
            let pp = opath.slot(&format!("params/{}", y.name));
            self.descend(&pp, &x.ty, &y.ty, 0);
            self.doc(
                &pp,
                &format!("parameter `{}` of `{}`", y.name, b.name),
                x.doc.as_deref(),
                y.doc.as_deref(),
                here.loc(),
            );
        }
        if let (Some(x), Some(y)) = (&a.return_type, &b.return_type) {
            self.descend(&opath.slot("result"), x, y, 0);
        }
        for e in &b.raises {
            if let Some(x) = a.raises.iter().find(|x| written(x) == written(e)) {
                self.descend(&opath.seg(&format!("raises/{}", written(e))), x, e, 0);
            }
        }
    }
}

fn list_or_none(v: &[String]) -> String {
    if v.is_empty() {
        "nothing".to_string()
    } else {
        v.iter()
            .map(|s| format!("`{s}`"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

fn inherited(from: &str, iface: &str) -> String {
    if from == iface {
        String::new()
    } else {
        format!(" (inherited from `{from}`)")
    }
}

fn dir(d: IdlParamDirection) -> &'static str {
    match d {
        IdlParamDirection::In => "in",
        IdlParamDirection::Out => "out",
        IdlParamDirection::Inout => "inout",
    }
}

fn case_text(c: &crate::idl::IdlUnionCase) -> String {
    let mut labels: Vec<String> = c.labels.iter().map(|l| format!("case {l}")).collect();
    if c.is_default {
        labels.push("default".into());
    }
    format!(
        "{}: {}{} {}",
        labels.join(" "),
        written(&c.field.ty),
        dims(&c.field.array),
        c.field.name
    )
}

/// `oneway void name(in T a, out U b) raises (E)` (types with resolved names).
fn signature(o: &IdlOperation) -> String {
    let params: Vec<String> = o
        .params
        .iter()
        .map(|p| format!("{} {} {}", dir(p.direction), written(&p.ty), p.name))
        .collect();
    let mut s = format!(
        "{}{} {}({})",
        if o.oneway { "oneway " } else { "" },
        o.return_type.as_ref().map_or("void".into(), written),
        o.name,
        params.join(", ")
    );
    if !o.raises.is_empty() {
        let r: Vec<String> = o.raises.iter().map(written).collect();
        s.push_str(&format!(" raises ({})", r.join(", ")));
    }
    if !o.context.is_empty() {
        s.push_str(&format!(" context ({})", o.context.join(", ")));
    }
    s
}

fn attribute_text(a: &IdlAttribute) -> String {
    format!(
        "{}attribute {} {}",
        if a.readonly { "readonly " } else { "" },
        written(&a.ty),
        a.name
    )
}

type Flat<'s> = (
    Vec<(&'s IdlOperation, String)>,
    Vec<(&'s IdlAttribute, String)>,
);

/// The operations and attributes of an interface with those of its bases (transitively, each
/// base once), each with the interface that declares it; the first of one name wins.
fn flatten<'s>(set: &'s IdlSet, i: &'s IdlInterface) -> Flat<'s> {
    fn walk<'s>(
        set: &'s IdlSet,
        i: &'s IdlInterface,
        seen: &mut BTreeSet<String>,
        out: &mut Flat<'s>,
    ) {
        if !seen.insert(i.scoped_name.clone()) || seen.len() > 256 {
            return;
        }
        for o in &i.operations {
            if !out.0.iter().any(|(x, _)| x.name == o.name) {
                out.0.push((o, i.scoped_name.clone()));
            }
        }
        for a in &i.attributes {
            if !out.1.iter().any(|(x, _)| x.name == a.name) {
                out.1.push((a, i.scoped_name.clone()));
            }
        }
        for b in &i.bases {
            if let Some(IdlDefinition::Interface(bi)) = find(set, &written(b)).map(|x| x.definition)
            {
                walk(set, bi, seen, out);
            }
        }
    }
    let mut out = (Vec::new(), Vec::new());
    walk(set, i, &mut BTreeSet::new(), &mut out);
    out
}

/// The code of a finding, given where the type is used: `required` for an interface the
/// component requires (an operation it no longer calls is information, not a break).
pub(super) fn code_of(kind: Kind, required: bool) -> &'static str {
    match kind {
        Kind::RepositoryId => codes::IDL_REPOSITORY_ID,
        Kind::MemberAdded => codes::IDL_MEMBER_ADDED,
        Kind::MemberRemoved => codes::IDL_MEMBER_REMOVED,
        Kind::Reordered => codes::IDL_MEMBERS_REORDERED,
        Kind::MemberRetyped => codes::IDL_MEMBER_RETYPED,
        Kind::EnumRemoved => codes::IDL_ENUM_VALUE_REMOVED,
        Kind::EnumAppended => codes::IDL_ENUM_VALUE_APPENDED,
        Kind::Union => codes::IDL_UNION_CHANGED,
        Kind::Typedef => codes::IDL_TYPEDEF_CHANGED,
        Kind::OperationRemoved if required => codes::IDL_REQUIRED_OPERATION_REMOVED,
        Kind::OperationRemoved => codes::IDL_OPERATION_REMOVED,
        Kind::OperationChanged => codes::IDL_OPERATION_CHANGED,
        Kind::OperationAdded => codes::IDL_OPERATION_ADDED,
        Kind::Documentation => codes::IDL_DOCUMENTATION_CHANGED,
        Kind::Other => codes::OTHER_CHANGED,
    }
}

/// `port/type` followed by a finding's path inside the type.
fn sub(path: &str, inside: &str) -> String {
    if inside.is_empty() {
        path.to_string()
    } else {
        format!("{path}/{inside}")
    }
}

/// The IDL-level changes of one matched component: for each data port and service interface
/// present on both sides with the same (canonical) type, the findings of that type, under the
/// port's path.
pub(super) fn component(
    idl: &mut IdlDiff,
    ctx: &super::Ctx,
    old: &crate::model::Profile,
    new: &crate::model::Profile,
    out: &mut Vec<Change>,
) {
    use crate::model::non_empty;
    if idl.is_idle() {
        return;
    }
    let same = |a: Option<&str>, b: Option<&str>| -> Option<String> {
        let (a, b) = (a?, b?);
        (canonical_type(a) == canonical_type(b)).then(|| b.to_string())
    };
    let pos = |p: crate::model::Pos| Some(p).filter(|p| !p.is_unknown());
    let (o, n) = (&old.data_ports, &new.data_ports);
    for (label, op, np) in super::same_label(o, n, |p| p.name.as_deref()) {
        let Some(ty) = same(non_empty(&op.type_), non_empty(&np.type_)) else {
            continue;
        };
        let outcome = idl.outcome(&ty, ctx.component);
        for f in &outcome.findings {
            let path = format!("dataPorts/{label}/type");
            ctx.push(
                out,
                code_of(f.kind, false),
                &[sub(&path, &f.path)],
                pos(np.pos),
                (f.old.clone(), f.new.clone()),
                format!("data port `{label}` (`{ty}`): {}", f.message),
            );
        }
    }
    let (o, n) = (&old.service_ports, &new.service_ports);
    for (plabel, op, np) in super::same_label(o, n, |p| p.name.as_deref()) {
        let (o, n) = (&op.interfaces, &np.interfaces);
        for (ilabel, oi, ni) in super::same_label(o, n, |i| i.name.as_deref()) {
            let Some(ty) = same(non_empty(&oi.type_), non_empty(&ni.type_)) else {
                continue;
            };
            // A direction change is DIFF108 already; the findings follow NEW's direction.
            let required = ni.direction_kind() == Some(crate::model::Direction::Required);
            let outcome = idl.outcome(&ty, ctx.component);
            for f in &outcome.findings {
                let path = format!("servicePorts/{plabel}/interfaces/{ilabel}/type");
                let role = if required { "required" } else { "provided" };
                ctx.push(
                    out,
                    code_of(f.kind, required),
                    &[sub(&path, &f.path)],
                    pos(ni.pos),
                    (f.old.clone(), f.new.clone()),
                    format!(
                        "{role} interface `{ilabel}` (`{ty}`) of service port `{plabel}`: {}",
                        f.message
                    ),
                );
            }
        }
    }
}

/// The definitions an IDL set defines (types and constants), by scoped name (modules walked;
/// forward declarations, natives and skipped declarations are not definitions to compare), each
/// with the file and position of its definition.
pub(crate) fn defined_types(set: &IdlSet) -> Defined {
    fn walk(defs: &[IdlDefinition], file: &str, out: &mut Defined) {
        for d in defs {
            match d {
                IdlDefinition::Module(m) => walk(&m.definitions, file, out),
                IdlDefinition::Struct(_)
                | IdlDefinition::Union(_)
                | IdlDefinition::Enum(_)
                | IdlDefinition::Typedef(_)
                | IdlDefinition::Interface(_)
                | IdlDefinition::Exception(_)
                | IdlDefinition::Const(_) => {
                    out.entry(d.scoped_name().to_string())
                        .or_insert_with(|| (file.to_string(), d.pos()));
                }
                IdlDefinition::Forward(_)
                | IdlDefinition::Native(_)
                | IdlDefinition::Skipped(_) => {}
            }
        }
    }
    let mut out = BTreeMap::new();
    for f in &set.files {
        walk(&f.definitions, &f.path, &mut out);
    }
    out
}

/// DIFF140 / DIFF334 for a type defined in one set and not the other, located at its
/// definition (files named by `old_name` / `new_name`), unless `skip` says it is reported
/// already; `component` is `label`, else the file defining the type.
fn types_on_one_side(
    (old, old_name): (&Defined, super::Namer),
    (new, new_name): (&Defined, super::Namer),
    label: Option<&str>,
    skip: &dyn Fn(&str) -> bool,
    out: &mut Vec<Change>,
) {
    let known = |p: crate::model::Pos| (!p.is_unknown()).then_some(p);
    for (name, (file, pos)) in old.iter().filter(|(n, _)| !new.contains_key(*n)) {
        if !skip(name) {
            let shown = old_name(file);
            let mut c = super::change(
                codes::IDL_TYPE_REMOVED,
                label.map_or_else(|| shown.clone(), str::to_string),
                format!("idl/{name}"),
                Some(name.clone()),
                None,
                format!("`{name}` is no longer defined (it was in `{shown}`)"),
            );
            c.old_file = Some(shown);
            c.old_line = known(*pos).map(|p| p.line);
            c.old_column = known(*pos).map(|p| p.column);
            out.push(c);
        }
    }
    for (name, (file, pos)) in new.iter().filter(|(n, _)| !old.contains_key(*n)) {
        if !skip(name) {
            let shown = new_name(file);
            let mut c = super::change(
                codes::IDL_TYPE_ADDED,
                label.map_or_else(|| shown.clone(), str::to_string),
                format!("idl/{name}"),
                None,
                Some(name.clone()),
                format!("`{name}` is defined in `{shown}`"),
            );
            c.file = Some(shown);
            c.line = known(*pos).map(|p| p.line);
            c.column = known(*pos).map(|p| p.column);
            out.push(c);
        }
    }
}

/// The IDL of both sides beyond what the ports' types led to (`compared`): every definition
/// both define that no port's type led to, compared on its own ([`compare_defined`]), so that
/// IDL no profile uses (an IDL folder diffed alone) is compared too; then the definitions one
/// side defines only, other than those a port carries (DIFF332 names those, once each, already
/// in `out`). Nothing is compared when a side has no IDL at all. The counts of the
/// definitions of both sides.
pub(super) fn unused_types(
    (old, old_name): (&IdlSet, super::Namer),
    (new, new_name): (&IdlSet, super::Namer),
    compared: &Compared,
    out: &mut Vec<Change>,
) -> super::Counts {
    let (o, n) = (defined_types(old), defined_types(new));
    let mut counts = super::Counts {
        old: o.len(),
        new: n.len(),
        ..Default::default()
    };
    if old.is_empty() || new.is_empty() {
        return counts;
    }
    counts.matched = o.keys().filter(|k| n.contains_key(*k)).count();
    let mut changed = compare_defined(
        (old, &o, old_name),
        (new, &n, new_name),
        None,
        &compared.visited,
        out,
    );
    changed.extend(
        compared
            .changed
            .iter()
            .filter(|t| o.contains_key(*t) && n.contains_key(*t))
            .cloned(),
    );
    counts.changed = changed.len();
    counts.added = n.keys().filter(|k| !o.contains_key(*k)).count();
    counts.removed = o.keys().filter(|k| !n.contains_key(*k)).count();
    let mut reported: BTreeSet<String> = out
        .iter()
        .filter(|c| c.code == codes::IDL_TYPE_ON_ONE_SIDE)
        .map(|c| c.path.clone())
        .collect();
    openrtm_copies((&o, old_name), &n, false, &mut reported, out);
    openrtm_copies((&n, new_name), &o, true, &mut reported, out);
    types_on_one_side(
        (&o, old_name),
        (&n, new_name),
        None,
        &|name| reported.contains(&format!("idl/{name}")),
        out,
    );
    counts
}

/// DIFF335 for each copy of one of OpenRTM's own IDL files whose types (other than those
/// `reported`) `side` defines and `other` does not: one change per file, on the NEW side when
/// `added`; its types join `reported`.
fn openrtm_copies(
    (side, name): (&Defined, super::Namer),
    other: &Defined,
    added: bool,
    reported: &mut BTreeSet<String>,
    out: &mut Vec<Change>,
) {
    // Each file's types, and the first of their definitions (where the change is located).
    let mut by_file: BTreeMap<&str, (Vec<&str>, Option<crate::model::Pos>)> = BTreeMap::new();
    for (ty, (file, pos)) in side {
        if crate::types::is_openrtm_idl_file(file)
            && !other.contains_key(ty)
            && !reported.contains(&format!("idl/{ty}"))
        {
            let (types, first) = by_file.entry(file).or_default();
            types.push(ty);
            if !pos.is_unknown()
                && first.is_none_or(|f| (pos.line, pos.column) < (f.line, f.column))
            {
                *first = Some(*pos);
            }
        }
    }
    for (file, (types, first)) in by_file {
        let shown = name(file);
        const NAMED: usize = 5;
        let mut list: Vec<String> = types.iter().take(NAMED).map(|t| format!("`{t}`")).collect();
        if types.len() > NAMED {
            list.push(format!("+{}", types.len() - NAMED));
        }
        let message = format!(
            "`{shown}`, a copy of OpenRTM's own IDL, is {} read: its {} type(s) ({}) come from an OpenRTM installation; pass `--idl-path` with OpenRTM's IDL to compare them",
            if added { "now" } else { "no longer" },
            types.len(),
            list.join(", ")
        );
        let (old_v, new_v) = if added {
            (None, Some(shown.clone()))
        } else {
            (Some(shown.clone()), None)
        };
        let mut c = super::change(
            codes::OPENRTM_IDL_COPY,
            shown.clone(),
            format!("idlFiles/{}", crate::idl::pp::file_name(file)),
            old_v,
            new_v,
            message,
        );
        if added {
            c.file = Some(shown);
            c.line = first.map(|p| p.line);
            c.column = first.map(|p| p.column);
        } else {
            c.old_file = Some(shown);
            c.old_line = first.map(|p| p.line);
            c.old_column = first.map(|p| p.column);
        }
        out.push(c);
        reported.extend(types.iter().map(|t| format!("idl/{t}")));
    }
}

/// The definitions of an IDL set by scoped name, each with its file and position.
pub(crate) type Defined = BTreeMap<String, (String, crate::model::Pos)>;

/// One side of a definition-by-definition comparison: its IDL, what it defines, and how its
/// files are named in the changes.
type DefSide<'a> = (&'a IdlSet, &'a Defined, super::Namer<'a>);

/// Every definition both sides define (but those `skip` names) compared as the type of a port
/// is ([`compare_type`]: members, enum values, union cases, typedefs, operations, constants,
/// with the types they hold), its changes under `idl/<scoped name>` with the codes
/// [`code_of`] gives (as a provided interface's): the one classification of IDL changes, for
/// `rtcdoc diff` and for the history of IDL files. Each change points at its item in NEW's IDL
/// (and in OLD's for an item only OLD has), else at the definition. `label` is each change's
/// `component`, else NEW's file of the definition. The names of the definitions that changed.
fn compare_defined(
    (old, od, old_name): DefSide,
    (new, nd, new_name): DefSide,
    label: Option<&str>,
    through_ports: &BTreeSet<String>,
    out: &mut Vec<Change>,
) -> BTreeSet<String> {
    let known = |p: &crate::model::Pos| (!p.is_unknown()).then_some(*p);
    let mut changed = BTreeSet::new();
    // Each definition's changes are reported once, at its own path: those compared through a
    // port there, the others here on their own, never again inside the definitions using them
    // (an enum every operation of three interfaces returns).
    let mut own = through_ports.clone();
    own.extend(nd.keys().filter(|k| od.contains_key(*k)).cloned());
    for (name, (nfile, npos)) in nd {
        let Some((ofile, _)) = od.get(name) else {
            continue;
        };
        if through_ports.contains(name) {
            continue;
        }
        let outcome = compare_type_past(old, new, name, &own);
        if outcome.findings.is_empty() {
            continue;
        }
        changed.insert(name.clone());
        let component = label.map_or_else(|| new_name(nfile), str::to_string);
        for f in &outcome.findings {
            let mut c = super::change(
                code_of(f.kind, false),
                component.clone(),
                sub(&format!("idl/{name}"), &f.path),
                f.old.clone(),
                f.new.clone(),
                format!("`{name}`: {}", f.message),
            );
            let (mut at_new, mut at_old) = ((nfile.as_str(), known(npos)), (ofile.as_str(), None));
            match &f.loc {
                Some(l) if l.in_old => at_old = (l.file.as_str(), known(&l.pos)),
                Some(l) => at_new = (l.file.as_str(), known(&l.pos)),
                None => {}
            }
            c.file = Some(new_name(at_new.0));
            c.line = at_new.1.map(|p| p.line);
            c.column = at_new.1.map(|p| p.column);
            c.old_file = Some(old_name(at_old.0));
            c.old_line = at_old.1.map(|p| p.line);
            c.old_column = at_old.1.map(|p| p.column);
            out.push(c);
        }
    }
    changed
}

/// Two versions of IDL files compared definition by definition (an IDL file's history), as
/// `rtcdoc diff` compares IDL no port uses ([`compare_defined`]); a definition one version
/// has only is DIFF140 (removed) or DIFF334 (added). `label` is each change's `component`
/// (the file).
pub fn compare_idl_files(old: &IdlSet, new: &IdlSet, label: &str) -> Vec<Change> {
    let (o, n) = (defined_types(old), defined_types(new));
    let mut out = Vec::new();
    let same = |f: &str| f.to_string();
    compare_defined(
        (old, &o, &same),
        (new, &n, &same),
        Some(label),
        &BTreeSet::new(),
        &mut out,
    );
    types_on_one_side((&o, &same), (&n, &same), Some(label), &|_| false, &mut out);
    super::sort(&mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(text: &str) -> IdlSet {
        crate::idl::read(
            &[crate::idl::SourceFile::new(
                "t.idl",
                text.as_bytes().to_vec(),
            )],
            &Default::default(),
        )
    }

    /// (kind, path) of every finding of `name` between the two texts.
    fn found(old: &str, new: &str, name: &str) -> Vec<(Kind, String)> {
        let (o, n) = (set(old), set(new));
        compare_type(&o, &n, name)
            .findings
            .into_iter()
            .map(|f| (f.kind, f.path))
            .collect()
    }

    fn one(kind: Kind, path: &str) -> Vec<(Kind, String)> {
        vec![(kind, path.to_string())]
    }

    #[test]
    fn inherited_operations_and_attributes() {
        let old = "interface B { void ping(); attribute long level; }; interface I : B { void go(in long a); };";
        // ping dropped from the base: removed from I.
        let new = "interface B { attribute long level; }; interface I : B { void go(in long a); };";
        assert_eq!(
            found(old, new, "I"),
            one(Kind::OperationRemoved, "operations/ping")
        );
        // level retyped and made readonly; a parameter's direction changed; oneway.
        let new = "interface B { void ping(); readonly attribute long level; }; interface I : B { void go(inout long a); };";
        assert_eq!(
            found(old, new, "I"),
            vec![
                (Kind::OperationChanged, "operations/go".to_string()),
                (Kind::OperationChanged, "attributes/level".to_string()),
            ]
        );
        let new = "interface B { oneway void ping(); attribute long level; attribute double x; }; interface I : B { void go(in long b); };";
        assert_eq!(
            found(old, new, "I"),
            vec![
                (Kind::Other, "operations/go".to_string()),
                (Kind::OperationChanged, "operations/ping".to_string()),
                (Kind::OperationAdded, "attributes/x".to_string()),
            ]
        );
    }

    #[test]
    fn struct_parameters_and_raised_exceptions_are_followed() {
        let old = "struct P { long a; }; exception E { string why; }; interface I { void set(in P p) raises (E); };";
        let new = "struct P { long a; long b; }; exception E { string why; long code; }; interface I { void set(in P p) raises (E); };";
        assert_eq!(
            found(old, new, "I"),
            vec![
                (Kind::MemberAdded, "operations/set/params/p.b".to_string()),
                (
                    Kind::MemberAdded,
                    "operations/set/raises/E/fields/code".to_string()
                ),
            ]
        );
    }

    #[test]
    fn unions_enums_and_kinds() {
        let old = "union U switch (long) { case 0: long a; case 1: double b; };";
        let new = "union U switch (short) { case 1: double b; case 2: string c; };";
        assert_eq!(
            found(old, new, "U"),
            vec![
                (Kind::Union, "switch".to_string()),
                (Kind::Union, "cases/a".to_string()),
                (Kind::Union, "cases/c".to_string()),
            ]
        );
        // Reordering the cases is no change.
        let new = "union U switch (long) { case 1: double b; case 0: long a; };";
        assert!(found(old, new, "U").is_empty());
        // A value inserted renumbers the ones after it.
        let f = found("enum E { A, B };", "enum E { A, X, B };", "E");
        assert_eq!(f, one(Kind::EnumRemoved, "values"));
        // A struct that became a typedef.
        let f = found("struct S { long a; };", "typedef long S;", "S");
        assert_eq!(f, one(Kind::Typedef, ""));
    }

    #[test]
    fn recursive_types_end_and_one_sided_nested_types_are_noted() {
        let text =
            "struct Node; typedef sequence<Node> Nodes; struct Node { long v; Nodes kids; };";
        assert!(found(text, text, "Node").is_empty());
        let new = "struct Node; typedef sequence<Node> Nodes; struct Node { long v; Nodes kids; long w; };";
        assert_eq!(found(text, new, "Node"), one(Kind::MemberAdded, "fields/w"));
        // Elements of arrays are marked like those of sequences.
        let f = found(
            "struct P { long a; }; struct T { P ps[2]; };",
            "struct P { short a; }; struct T { P ps[2]; };",
            "T",
        );
        assert_eq!(f, one(Kind::MemberRetyped, "fields/ps[].a"));
        let (o, n) = (
            set("struct In { long a; }; struct T { In i; };"),
            set("struct T { In i; };"),
        );
        let out = compare_type(&o, &n, "T");
        assert_eq!(out.one_side, vec![("In".to_string(), false)]);
    }

    #[test]
    fn a_long_chain_of_nested_structs_stops_instead_of_overflowing() {
        // S<i> holds S<i-1>: 1000 links deep, past the stack without a limit.
        let chain = |first: &str| {
            let mut text = format!("struct S0 {{ {first} }};");
            for i in 1..1000 {
                text.push_str(&format!(" struct S{i} {{ long a; S{} p; }};", i - 1));
            }
            text
        };
        let (o, n) = (set(&chain("long a;")), set(&chain("long a; long b;")));
        let out = compare_type(&o, &n, "S999");
        assert_eq!(out.findings.len(), 1, "{:?}", out.findings);
        assert_eq!(out.findings[0].kind, Kind::Other);
        assert!(
            out.findings[0]
                .message
                .contains("nested more than 128 definitions deep"),
            "{}",
            out.findings[0].message
        );
        // Closer to the change, the change itself.
        let out = compare_type(&o, &n, "S3");
        assert_eq!(out.findings[0].kind, Kind::MemberAdded);
        assert_eq!(out.findings[0].path, "fields/p.p.p.b");
    }

    #[test]
    fn idl_files_are_compared_definition_by_definition_with_positions() {
        let old = "module M {\n  const long N = 1;\n  struct P { long a;\n    long b; };\n};\n";
        let new = "module M {\n  const long N = 2;\n  struct P { long a; };\n  interface I { void f(); };\n};\n";
        let changes = compare_idl_files(&set(old), &set(new), "t.idl");
        let got: Vec<(&str, &str, Option<u32>, Option<u32>)> = changes
            .iter()
            .map(|c| (c.code, c.path.as_str(), c.line, c.old_line))
            .collect();
        assert_eq!(
            got,
            vec![
                (codes::IDL_TYPE_ADDED, "idl/M::I", Some(4), None),
                (codes::OTHER_CHANGED, "idl/M::N", Some(2), None),
                // At the struct in NEW, at the member in OLD.
                (
                    codes::IDL_MEMBER_REMOVED,
                    "idl/M::P/fields/b",
                    Some(3),
                    Some(4)
                ),
            ]
        );
    }

    #[test]
    fn codes_follow_the_use() {
        assert_eq!(
            code_of(Kind::OperationRemoved, false),
            codes::IDL_OPERATION_REMOVED
        );
        assert_eq!(
            code_of(Kind::OperationRemoved, true),
            codes::IDL_REQUIRED_OPERATION_REMOVED
        );
        assert_eq!(code_of(Kind::Other, true), codes::OTHER_CHANGED);
    }
}
