//! A component's neighbourhood (issue #26): for each of its ports, the other components of the
//! catalogue that can connect to it, one hop — the producers of an in-port's data type, the
//! consumers of an out-port's, the providers of a required interface and the requirers of a
//! provided one. Read from the cross-references the catalogue already keeps
//! ([`Catalog::data_port_peers`], [`Catalog::interface_peers`]), grouped by component, capped
//! per port at [`PEER_COMPONENTS_CAP`] with the exact number left out: nothing is dropped
//! without saying so. Every component page asks, so it costs one pass over each port's peer
//! list and no lookup by name.

use super::{Catalog, ComponentIx, Ix, PeerRefs, TypeIx};
use crate::model::{Direction, PortDirection};

/// At most this many peer components are named per port, in every output: in a port's
/// "connects to" answer and in the neighbourhood; the rest are counted and linked to the type
/// or interface page.
pub const PEER_COMPONENTS_CAP: usize = 5;

/// The peers of a port of component `ci` as every output shows them: the ports of *other*
/// components (`all`, in catalogue order, so sorted by component) grouped by component, and
/// the number of groups (components) in all. A component's own ports are never its peers.
pub fn peer_groups<'a, R>(
    ci: ComponentIx,
    all: PeerRefs<'a, R>,
    component: impl Fn(&R) -> ComponentIx,
) -> (Vec<(ComponentIx, Vec<&'a R>)>, usize) {
    capped_groups(ci, all, PEER_COMPONENTS_CAP, component)
}

/// [`peer_groups`] with at most `cap` groups collected.
fn capped_groups<'a, R>(
    ci: ComponentIx,
    all: PeerRefs<'a, R>,
    cap: usize,
    component: impl Fn(&R) -> ComponentIx,
) -> (Vec<(ComponentIx, Vec<&'a R>)>, usize) {
    // Only the groups shown are collected; the others are counted (a popular type's list holds
    // thousands of references, and every one of its ports asks). When the catalogue knows how
    // many components the list names, the walk stops after the groups shown: the component's
    // own references are one run of the sorted list, found by bisection.
    let known = all.components.map(|runs| {
        let at = all.refs.partition_point(|r| component(r) < ci);
        let own = all.refs.get(at).is_some_and(|r| component(r) == ci);
        runs - usize::from(own)
    });
    let mut groups: Vec<(ComponentIx, Vec<&'a R>)> = Vec::new();
    let mut total = 0;
    let mut last = None;
    for r in all.refs {
        let c = component(r);
        if c == ci {
            continue;
        }
        if last != Some(c) {
            if known.is_some() && total == cap {
                break;
            }
            last = Some(c);
            total += 1;
            if total <= cap {
                groups.push((c, Vec::new()));
            }
        }
        if total <= cap {
            if let Some((_, list)) = groups.last_mut() {
                list.push(r);
            }
        }
    }
    (groups, known.unwrap_or(total))
}

/// A port of a component: a data port, or an interface of a service port (indices into the
/// component's profile).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum PortAt {
    Data(usize),
    Interface(usize, usize),
}

/// One neighbour of a port: a component and its ports that connect to the port.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Neighbour {
    /// The neighbouring component.
    pub component: ComponentIx,
    /// Its matching ports, in profile order.
    pub ports: Vec<PortAt>,
}

/// The neighbours of one port of the component.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PortNeighbours {
    /// The component's own port.
    pub port: PortAt,
    /// True when the neighbours are upstream (drawn on the left): they feed this in-port or
    /// call this provided interface; false when this out-port feeds them or this required
    /// interface calls them.
    pub upstream: bool,
    /// The port's data type or interface type: the page that lists every neighbour when some
    /// are left out.
    pub type_: TypeIx,
    /// The first neighbours, in catalogue order, at most the cap.
    pub shown: Vec<Neighbour>,
    /// How many neighbour components there are in all (`shown.len()` when none is left out).
    pub total: usize,
}

impl PortNeighbours {
    /// How many neighbour components are counted but not named.
    pub fn more(&self) -> usize {
        self.total - self.shown.len()
    }

    /// True for a service interface (the data type index is an interface index).
    pub fn is_service(&self) -> bool {
        matches!(self.port, PortAt::Interface(..))
    }
}

/// A component's neighbourhood: its ports with at least one neighbour, data ports first, in
/// profile order.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Neighbourhood {
    pub ports: Vec<PortNeighbours>,
}

impl Neighbourhood {
    /// True when no other component of the catalogue connects to any port.
    pub fn is_empty(&self) -> bool {
        self.ports.is_empty()
    }

    /// The neighbour components named (on any port), each once, in the order first met.
    pub fn components(&self) -> Vec<ComponentIx> {
        let mut seen = Vec::new();
        for p in &self.ports {
            for n in &p.shown {
                if !seen.contains(&n.component) {
                    seen.push(n.component);
                }
            }
        }
        seen
    }
}

/// [`capped_groups`] as neighbours, each with its ports (`at`: where a reference is).
fn neighbours<R>(
    (ci, all, cap): (ComponentIx, PeerRefs<'_, R>, usize),
    component: impl Fn(&R) -> ComponentIx,
    at: impl Fn(&R) -> Option<PortAt>,
) -> (Vec<Neighbour>, usize) {
    let (groups, total) = capped_groups(ci, all, cap, component);
    let shown = groups
        .into_iter()
        .map(|(k, list)| Neighbour {
            component: k,
            ports: list.into_iter().filter_map(&at).collect(),
        })
        .collect();
    (shown, total)
}

impl Catalog {
    /// The neighbourhood of component `ci`, at most `cap` neighbours named per port (the rest
    /// counted in [`PortNeighbours::total`]). Event ports and interfaces of no known direction
    /// have none; the component is never its own neighbour.
    pub fn neighbourhood(&self, ci: ComponentIx, cap: usize) -> Neighbourhood {
        let Some(c) = self.components.get(ci.get()) else {
            return Neighbourhood { ports: Vec::new() };
        };
        let p = &c.profile;
        let data = p.data_ports.iter().enumerate().filter_map(|(pi, port)| {
            let upstream = match port.direction()? {
                PortDirection::In => true,
                PortDirection::Out => false,
                PortDirection::Event => return None,
            };
            let ti = self.port_type(ci, pi)?;
            let refs = self.data_port_peers(ci, pi);
            let (shown, total) = neighbours(
                (ci, refs, cap),
                |r| self.port_component(r).unwrap_or(Ix::NONE),
                |r| self.resolve_port(r).map(|(_, q)| PortAt::Data(q)),
            );
            Some(PortNeighbours {
                port: PortAt::Data(pi),
                upstream,
                type_: TypeIx::Data(ti),
                shown,
                total,
            })
        });
        let interfaces = p.service_ports.iter().enumerate().flat_map(|(si, sp)| {
            sp.interfaces.iter().enumerate().filter_map(move |(ii, i)| {
                let upstream = match i.direction_kind()? {
                    Direction::Provided => true,
                    Direction::Required => false,
                };
                let ti = self.interface_type(ci, si, ii)?;
                let refs = self.interface_peers(ci, si, ii);
                let (shown, total) = neighbours(
                    (ci, refs, cap),
                    |r| self.interface_component(r).unwrap_or(Ix::NONE),
                    |r| {
                        self.resolve_interface(r)
                            .map(|(_, q, j)| PortAt::Interface(q, j))
                    },
                );
                Some(PortNeighbours {
                    port: PortAt::Interface(si, ii),
                    upstream,
                    type_: TypeIx::Interface(ti),
                    shown,
                    total,
                })
            })
        });
        let ports = data.chain(interfaces).filter(|n| n.total > 0).collect();
        Neighbourhood { ports }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog::{InterfaceRef, LoadedProfile, PortRef};

    fn profile(name: &str, ports: &[(&str, &str)], services: &[(&str, &str)]) -> LoadedProfile {
        crate::catalog::tests::xml_profile(name, "C", ports, services)
    }

    fn index(cat: &Catalog, name: &str) -> ComponentIx {
        Ix::enumerate(&cat.components)
            .find(|(_, c)| c.profile.name() == name)
            .expect("component")
            .0
    }

    #[test]
    fn feeders_fed_services_caps_and_never_itself() {
        let mut loaded = vec![
            // A filter: in and out of the same type (its own out-port is no feeder).
            profile(
                "Filter",
                &[
                    ("DataInPort", "RTC::TimedLong"),
                    ("DataOutPort", "RTC::TimedLong"),
                    ("DataInPort", "RTC::TimedNothing"),
                ],
                &[("Required", "Map"), ("Provided", "Ctl")],
            ),
            profile("Log", &[("DataInPort", "RTC::TimedLong")], &[]),
            profile("MapServer", &[], &[("Provided", "Map")]),
            profile("Gui", &[], &[("Required", "Ctl")]),
        ];
        for k in 0..7 {
            loaded.push(profile(
                &format!("Src{k}"),
                &[
                    ("DataOutPort", "RTC::TimedLong"),
                    ("DataOutPort", "RTC::TimedLong"),
                ],
                &[],
            ));
        }
        let cat = Catalog::build(loaded, Vec::new());
        let f = index(&cat, "Filter");
        let n = cat.neighbourhood(f, 3);
        // p0 (in): 7 sources, 3 named, each with both its out-ports; p1 (out): Log; p2: nothing.
        assert_eq!(n.ports.len(), 4, "{n:?}");
        let p0 = &n.ports[0];
        assert_eq!(
            (p0.port, p0.upstream, p0.total, p0.more()),
            (PortAt::Data(0), true, 7, 4)
        );
        assert_eq!(p0.shown.len(), 3);
        assert!(p0.shown.iter().all(|s| s.component != f));
        assert_eq!(p0.shown[0].ports, vec![PortAt::Data(0), PortAt::Data(1)]);
        let p1 = &n.ports[1];
        assert_eq!(
            (p1.port, p1.upstream, p1.total),
            (PortAt::Data(1), false, 1)
        );
        assert_eq!(p1.shown[0].component, index(&cat, "Log"));
        let (req, prov) = (&n.ports[2], &n.ports[3]);
        assert_eq!((req.port, req.upstream), (PortAt::Interface(0, 0), false));
        assert_eq!(req.shown[0].component, index(&cat, "MapServer"));
        assert_eq!((prov.port, prov.upstream), (PortAt::Interface(1, 0), true));
        assert_eq!(prov.shown[0].component, index(&cat, "Gui"));
        assert!(req.is_service() && !p0.is_service());
        // Merged once per component across ports.
        assert_eq!(n.components().len(), 3 + 1 + 1 + 1);
        // A component nobody connects to.
        let lonely = Catalog::build(
            vec![profile("Alone", &[("DataInPort", "RTC::TimedLong")], &[])],
            Vec::new(),
        );
        assert!(lonely.neighbourhood(Ix::new(0), 5).is_empty());
    }

    /// The counted path (the catalogue knows how many components a list names, the walk stops
    /// after the groups shown) gives what walking the whole list gives, for every port, at
    /// every cap, with the component anywhere in the list (first, middle, last, absent).
    #[test]
    fn counted_peers_are_the_walked_ones() {
        let mut loaded = Vec::new();
        for k in 0..12 {
            let mut ports = vec![("DataInPort", "RTC::TimedLong")];
            if k % 3 == 0 {
                ports.push(("DataOutPort", "RTC::TimedLong"));
                ports.push(("DataOutPort", "RTC::TimedLong"));
            }
            if k % 4 == 1 {
                ports.push(("DataOutPort", "RTC::TimedLong"));
            }
            let services: &[(&str, &str)] = match k % 3 {
                0 => &[("Provided", "Map"), ("Required", "Map")],
                1 => &[("Required", "Map")],
                _ => &[("Provided", "Map")],
            };
            loaded.push(profile(&format!("C{k:02}"), &ports, services));
        }
        let cat = Catalog::build(loaded, Vec::new());
        let mut counted = 0;
        for (ci, c) in Ix::enumerate(&cat.components) {
            for pi in 0..c.profile.data_ports.len() {
                let refs = cat.data_port_peers(ci, pi);
                counted += usize::from(refs.components.is_some());
                for cap in [0, 1, 2, 5, 20] {
                    let f = |r: &PortRef| cat.port_component(r).unwrap_or(Ix::NONE);
                    assert_eq!(
                        capped_groups(ci, refs, cap, f),
                        capped_groups(ci, PeerRefs::uncounted(refs.refs), cap, f),
                        "{} port {pi}, cap {cap}",
                        c.profile.name()
                    );
                }
            }
            for (si, sp) in c.profile.service_ports.iter().enumerate() {
                for ii in 0..sp.interfaces.len() {
                    let refs = cat.interface_peers(ci, si, ii);
                    counted += usize::from(refs.components.is_some());
                    for cap in [0, 1, 3, 20] {
                        let f = |r: &InterfaceRef| cat.interface_component(r).unwrap_or(Ix::NONE);
                        assert_eq!(
                            capped_groups(ci, refs, cap, f),
                            capped_groups(ci, PeerRefs::uncounted(refs.refs), cap, f),
                        );
                    }
                }
            }
        }
        assert!(counted > 20, "the counted path was taken {counted} times");
    }
}
