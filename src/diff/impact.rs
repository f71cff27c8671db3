//! What a comparison's changes reach beyond the components they are to.
//!
//! Computed once per comparison from the two catalogues and the sorted changes
//! ([`Facts::of`], at the end of [`super::diff_with_systems`]): the reach of each change to a
//! port's type, an interface or an IDL definition (the other components that produce,
//! consume, provide or require it: in NEW's catalogue, or OLD's when NEW no longer has it;
//! [`crate::catalog::reach`]), and the types that lose their last producer while NEW still
//! consumes them, or their last provider while NEW still requires them.
//!
//! The summary every report shows ([`Impact`], from [`super::Diff::impact`]) counts only the
//! changes that count, as the other counts do: a connector whose DIFF14x change the policy
//! ignores or a baseline accepts is not among the connectors it breaks, a lost producer or
//! provider is counted when one of the changes that caused it counts, and the components
//! reached are those of the changes that count. Each change keeps its reach whatever its
//! standing.

use super::{codes, ident, Change, Key, Status};
use crate::catalog::reach::{profile_lookup, subject_of, Reached, Subject};
use crate::catalog::{Catalog, Component};
use crate::diagnostic::counted;
use crate::model::Profile;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// The components (OLD's and NEW's positions) behind each component label of the changes.
pub(super) type Labels = BTreeMap<String, (Option<usize>, Option<usize>)>;

/// A type that lost its last producer (a data type) or provider (an interface).
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Lost {
    /// The type's canonical name.
    #[serde(rename = "type")]
    pub type_name: String,
    /// The components of NEW that still consume (require) it, by id, sorted.
    pub components: Vec<String>,
    /// The changes that took the last producer (provider) away, by position in the changes.
    #[serde(skip)]
    pub causes: Vec<usize>,
}

/// What the catalogues say about the changes, whatever their standing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Facts {
    /// The reach of each change, in the order of the changes (empty: none).
    pub reach: Vec<Vec<Reached>>,
    pub lost_producers: Vec<Lost>,
    pub lost_providers: Vec<Lost>,
}

/// The connectors of one system that the changes break.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct SystemImpact {
    /// The system's name.
    pub system: String,
    pub connectors: usize,
}

/// The impact of the changes that count: what every report shows at its top.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Impact {
    /// Distinct connectors broken (DIFF141–DIFF143), all systems.
    pub connectors: usize,
    /// By system name.
    pub systems: Vec<SystemImpact>,
    /// By type name.
    pub lost_producers: Vec<Lost>,
    /// By interface name.
    pub lost_providers: Vec<Lost>,
    /// The components the changes reach, by id, sorted.
    pub reached: Vec<String>,
    /// The summary sentence (`None`: no impact).
    pub summary: Option<String>,
}

impl Facts {
    /// The facts of `changes` (sorted, final) between `old` and `new`; `labels` names the
    /// components behind the changes' labels.
    pub(super) fn of(old: &Catalog, new: &Catalog, changes: &[Change], labels: &Labels) -> Facts {
        let sides = [old, new];
        let mut reach = Vec::with_capacity(changes.len());
        // Canonical type name in OLD → the changes that are to it.
        let (mut data_causes, mut iface_causes) = (
            BTreeMap::<String, Vec<usize>>::new(),
            BTreeMap::<String, Vec<usize>>::new(),
        );
        for (i, c) in changes.iter().enumerate() {
            let (o, n) = labels.get(&c.component).copied().unwrap_or((None, None));
            let profiles = [o.map(|o| &old.components[o]), n.map(|n| &new.components[n])];
            let subjects = subjects(c, profiles.map(|c| c.map(|c| &*c.profile)));
            let key: Option<Key> = profiles.iter().flatten().next().map(|c| ident(c).key);
            let except = |x: &Component| key.as_ref().is_some_and(|k| ident(x).key == *k);
            let mut r: BTreeSet<Reached> = BTreeSet::new();
            for s in &subjects {
                let cat = if new.knows(s) { new } else { old };
                r.extend(cat.reach(std::slice::from_ref(s), &except));
            }
            reach.push(r.into_iter().collect());
            let mut causes = subjects;
            if c.code == codes::COMPONENT_REMOVED {
                causes.extend(profiles[0].into_iter().flat_map(|c| every_type(&c.profile)));
            }
            for s in causes {
                note_cause(sides, &s, i, (&mut data_causes, &mut iface_causes));
            }
        }
        Facts {
            reach,
            lost_producers: lost(sides, &data_causes, true),
            lost_providers: lost(sides, &iface_causes, false),
        }
    }
}

/// What change `c` is to: its path's subject, the ports looked up in NEW's profile, else
/// OLD's.
fn subjects(c: &Change, [old, new]: [Option<&Profile>; 2]) -> Vec<Subject> {
    let lookup = |port: &str, iface: Option<&str>| -> Vec<Subject> {
        [new, old]
            .into_iter()
            .flatten()
            .map(|p| profile_lookup(p, port, iface))
            .find(|v| !v.is_empty())
            .unwrap_or_default()
    };
    subject_of(&c.path, c.old.as_deref(), c.new.as_deref(), &lookup)
}

/// Every data port type and interface type of a profile (a removed component's: what it may
/// have been the last to produce or provide).
fn every_type(p: &Profile) -> Vec<Subject> {
    let t = |t: &Option<crate::model::Text>| t.as_deref().map(str::trim).map(str::to_string);
    let data = p.data_ports.iter().filter_map(|d| t(&d.type_));
    let ifaces = p
        .service_ports
        .iter()
        .flat_map(|s| &s.interfaces)
        .filter_map(|i| t(&i.type_));
    data.map(Subject::DataType)
        .chain(ifaces.map(Subject::Interface))
        .collect()
}

type Causes = BTreeMap<String, Vec<usize>>;

/// Notes change `i` as a cause of what happens to subject `s` (by its canonical name in OLD).
fn note_cause(
    [old, _]: [&Catalog; 2],
    s: &Subject,
    i: usize,
    (data, ifaces): (&mut Causes, &mut Causes),
) {
    let n = s.name();
    if !matches!(s, Subject::Interface(_)) {
        if let Some(t) = old.data_type(n) {
            data.entry(t.name.clone()).or_default().push(i);
        }
    }
    if !matches!(s, Subject::DataType(_)) {
        if let Some(t) = old.interface(n) {
            ifaces.entry(t.name.clone()).or_default().push(i);
        }
    }
}

/// Each type of `new` by name: whether its entry in OLD (`old`) had a supplier (a producer or
/// provider), how many suppliers it has now, and the components using it now (consumers or
/// requirers).
fn supplies<'a, U: crate::catalog::Uses + 'a>(
    new: &[crate::catalog::TypeEntry<U>],
    old: &dyn Fn(&str) -> Option<&'a U>,
) -> Vec<(String, bool, usize, Vec<String>)> {
    use crate::catalog::UseRef;
    new.iter()
        .map(|t| {
            let [(_, suppliers), (_, users), _] = t.uses.by_role();
            let before = old(&t.name).is_some_and(|o| !o.by_role()[0].1.is_empty());
            let users = users.iter().map(|r| r.component().as_str().to_string());
            (t.name.clone(), before, suppliers.len(), users.collect())
        })
        .collect()
}

/// The types OLD produced (`data`) or provided, that NEW still consumes (requires) and no
/// longer produces (provides), by name, with the changes to them.
fn lost([old, new]: [&Catalog; 2], causes: &Causes, data: bool) -> Vec<Lost> {
    // (name, whether OLD supplied it, NEW's suppliers, NEW's users)
    let entries = if data {
        supplies(&new.data_types, &|n| old.data_type(n).map(|t| &t.uses))
    } else {
        supplies(&new.interfaces, &|n| old.interface(n).map(|t| &t.uses))
    };
    let mut out: Vec<Lost> = entries
        .into_iter()
        .filter(|(_, before, now, users)| *before && *now == 0 && !users.is_empty())
        .map(|(name, _, _, users)| {
            let components: BTreeSet<String> = users.into_iter().collect();
            Lost {
                causes: causes.get(&name).cloned().unwrap_or_default(),
                type_name: name,
                components: components.into_iter().collect(),
            }
        })
        .collect();
    out.sort_by(|a, b| a.type_name.cmp(&b.type_name));
    out
}

impl super::Diff {
    /// The impact of the changes that count ([`Impact`]).
    pub fn impact(&self) -> Impact {
        let counts = |i: &usize| *self.status(*i) == Status::Counts;
        let mut connectors: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
        let mut reached = BTreeSet::new();
        for (i, c) in self.changes.iter().enumerate().filter(|(i, _)| counts(i)) {
            if matches!(
                c.code,
                codes::CONNECTOR_COMPONENT_REMOVED
                    | codes::CONNECTOR_PORT_REMOVED
                    | codes::CONNECTOR_PORT_CHANGED
            ) {
                // `connectors/<system>/<connector>`
                let mut p = c.path.splitn(3, '/').skip(1);
                if let (Some(system), Some(name)) = (p.next(), p.next()) {
                    connectors.entry(system).or_default().insert(name);
                }
            }
            if let Some(r) = self.facts.reach.get(i) {
                reached.extend(r.iter().map(|r| r.component.clone()));
            }
        }
        let lost = |l: &[Lost]| -> Vec<Lost> {
            l.iter()
                .filter(|l| l.causes.is_empty() || l.causes.iter().any(counts))
                .cloned()
                .collect()
        };
        let systems: Vec<SystemImpact> = connectors
            .into_iter()
            .map(|(s, c)| SystemImpact {
                system: s.to_string(),
                connectors: c.len(),
            })
            .collect();
        let mut impact = Impact {
            connectors: systems.iter().map(|s| s.connectors).sum(),
            systems,
            lost_producers: lost(&self.facts.lost_producers),
            lost_providers: lost(&self.facts.lost_providers),
            reached: reached.into_iter().collect(),
            summary: None,
        };
        impact.summary = impact.sentence();
        impact
    }

    /// The reach of the `i`-th change (empty: none).
    pub fn reach(&self, i: usize) -> &[Reached] {
        self.facts.reach.get(i).map_or(&[], Vec::as_slice)
    }
}

impl Impact {
    /// `breaks 3 connectors in 1 system (PatrolRobot); 2 components lose their only producer
    /// of RTC::RangeData; 1 component loses its only provider of Nav::MapService; reaches 4
    /// components`, or `None` when the changes reach nothing.
    fn sentence(&self) -> Option<String> {
        let parts = self.parts();
        (!parts.is_empty()).then(|| parts.join("; "))
    }

    /// The parts of the summary sentence, in its order (the Markdown report lists them).
    pub fn parts(&self) -> Vec<String> {
        let mut parts = Vec::new();
        if self.connectors > 0 {
            let names: Vec<&str> = self.systems.iter().map(|s| s.system.as_str()).collect();
            parts.push(format!(
                "breaks {} in {} ({})",
                counted(self.connectors, "connector"),
                counted(self.systems.len(), "system"),
                names.join(", ")
            ));
        }
        for (lost, what) in [
            (&self.lost_producers, "producer"),
            (&self.lost_providers, "provider"),
        ] {
            for l in lost {
                let n = l.components.len();
                let (verb, their) = if n == 1 {
                    ("loses", "its")
                } else {
                    ("lose", "their")
                };
                parts.push(format!(
                    "{} {verb} {their} only {what} of {}",
                    counted(n, "component"),
                    l.type_name
                ));
            }
        }
        if !self.reached.is_empty() {
            parts.push(format!(
                "reaches {}",
                counted(self.reached.len(), "component")
            ));
        }
        parts
    }
}

/// `reaches 2 components` and, with `names`, `: A (consumer), B (producer)`: the line of a
/// change's reach in the human and Markdown reports.
pub fn reach_line(reach: &[Reached], names: bool) -> Option<String> {
    if reach.is_empty() {
        return None;
    }
    let components: BTreeSet<&str> = reach.iter().map(|r| r.component.as_str()).collect();
    let mut line = format!("reaches {}", counted(components.len(), "component"));
    if names {
        let each: Vec<String> = reach
            .iter()
            .map(|r| format!("{} ({})", r.component, r.role))
            .collect();
        line.push_str(": ");
        line.push_str(&each.join(", "));
    }
    Some(line)
}
