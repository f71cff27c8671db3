//! The catalogue's data flow (spec §10.6, reuse): an out-port of type T can feed every in-port
//! of type T. Which groups of components (categories or vendors) can feed which is a graph of
//! groups, not of components, so that it stays readable at 10,000 components; each edge counts
//! the port pairs behind it. Computed from the producers and consumers of each data type in
//! O(ports + groups²) per type, never pair by pair.

use super::{Catalog, ComponentIx, DataTypeIx, Ix};
use std::collections::BTreeMap;

/// How components are grouped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grouping {
    Category,
    Vendor,
}

/// Port pairs from the components of one group to those of another (or the same) group.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FlowEdge {
    /// Facet indices ([`Catalog::categories`] or [`Catalog::vendors`]).
    pub from: usize,
    pub to: usize,
    /// Out-port/in-port pairs of one data type, across different components.
    pub pairs: u64,
    /// The data types of those pairs, in catalogue order.
    pub types: Vec<DataTypeIx>,
}

impl Catalog {
    /// The data flow between groups: every edge with at least one port pair, sorted by
    /// (from, to); an edge from a group to itself is a flow inside the group. A component's
    /// out-port feeding its own in-port is not counted.
    pub fn data_flow(&self, grouping: Grouping) -> Vec<FlowEdge> {
        let of = match grouping {
            Grouping::Category => self.category_of_each(),
            Grouping::Vendor => self.vendor_of_each(),
        };
        let mut edges: BTreeMap<(usize, usize), (u64, Vec<DataTypeIx>)> = BTreeMap::new();
        for (ti, t) in Ix::all(self.data_types.len()).zip(&self.data_types) {
            let count = |refs: &[super::PortRef]| {
                let mut by_component: BTreeMap<ComponentIx, u64> = BTreeMap::new();
                for r in refs {
                    if let Some(ci) = self.port_component(r) {
                        *by_component.entry(ci).or_default() += 1;
                    }
                }
                by_component
            };
            let (out, inp) = (count(&t.uses.producers), count(&t.uses.consumers));
            if out.is_empty() || inp.is_empty() {
                continue;
            }
            let per_group = |m: &BTreeMap<ComponentIx, u64>| {
                let mut g: BTreeMap<usize, u64> = BTreeMap::new();
                for (&ci, &n) in m {
                    *g.entry(of[ci]).or_default() += n;
                }
                g
            };
            let (gout, ginp) = (per_group(&out), per_group(&inp));
            for (&a, &na) in &gout {
                for (&b, &nb) in &ginp {
                    let mut pairs = na * nb;
                    if a == b {
                        // Not a component with itself.
                        pairs -= out
                            .iter()
                            .filter(|(&ci, _)| of[ci] == a)
                            .map(|(ci, n)| n * inp.get(ci).copied().unwrap_or(0))
                            .sum::<u64>();
                    }
                    if pairs > 0 {
                        let e = edges.entry((a, b)).or_default();
                        e.0 += pairs;
                        e.1.push(ti);
                    }
                }
            }
        }
        edges
            .into_iter()
            .map(|((from, to), (pairs, types))| FlowEdge {
                from,
                to,
                pairs,
                types,
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog::LoadedProfile;

    fn profile(name: &str, category: &str, ports: &[(&str, &str)]) -> LoadedProfile {
        crate::catalog::tests::xml_profile(name, category, ports, &[])
    }

    #[test]
    fn pairs_between_groups_without_self_pairs() {
        let cat = Catalog::build(
            vec![
                profile("Cam", "Sensor", &[("DataOutPort", "RTC::TimedLong")]),
                profile("Cam2", "Sensor", &[("DataOutPort", "RTC::TimedLong")]),
                // A filter: in and out of the same type; its own ports are no pair.
                profile(
                    "Filter",
                    "Vision",
                    &[
                        ("DataInPort", "RTC::TimedLong"),
                        ("DataOutPort", "RTC::TimedLong"),
                    ],
                ),
                profile("Log", "Vision", &[("DataInPort", "RTC::TimedLong")]),
            ],
            Vec::new(),
        );
        let edges = cat.data_flow(Grouping::Category);
        let sensor = cat
            .categories
            .iter()
            .position(|f| f.name == "Sensor")
            .unwrap();
        let vision = cat
            .categories
            .iter()
            .position(|f| f.name == "Vision")
            .unwrap();
        let pairs = |a, b| {
            edges
                .iter()
                .find(|e| e.from == a && e.to == b)
                .map(|e| e.pairs)
        };
        // Cam, Cam2 → Filter, Log: 4 pairs; Filter → Log: 1 (not Filter → Filter).
        assert_eq!(pairs(sensor, vision), Some(4));
        assert_eq!(pairs(vision, vision), Some(1));
        assert_eq!(pairs(vision, sensor), None);
        assert_eq!(edges.len(), 2);
    }
}
