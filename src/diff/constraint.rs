//! Is a new constraint narrower or wider than the old one?
//!
//! A sound approximation, never a guess: `Narrower` and `Wider` are only answered when they are
//! proven on one of these shapes, and everything else is `Other` (treated like a narrowing):
//! - no constraint accepts everything (a placeholder counts as none);
//! - numeric `<`, `>`, `≤`, `≥`, `=` of a number, `between`, `and` of those (intersection) and
//!   `or` of those (union) are unions of intervals; A ⊆ B when every interval of A lies inside
//!   one interval of B (an interval covered only by two adjacent ones of B is not recognised:
//!   the answer is then `Other`, never a wrong `Narrower`/`Wider`);
//! - `=` of literals and `or` of those are sets of literals (compared as written, so only
//!   case-sensitive comparisons take part);
//! - hash constraints are compared key by key (a key only NEW constrains narrows, a key only OLD
//!   constrained widens), list constraints item by item (more items narrow: a missing element
//!   violates a list constraint).

use crate::model::{Comparison, Condition, Constraint, ConstraintKind};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    /// Accepts the same values.
    Same,
    /// Accepts fewer values (NEW ⊂ OLD).
    Narrower,
    /// Accepts more values (NEW ⊃ OLD).
    Wider,
    /// Neither could be proven.
    Other,
}

impl Relation {
    fn and(self, other: Relation) -> Relation {
        use Relation::*;
        match (self, other) {
            (Same, x) | (x, Same) => x,
            (Narrower, Narrower) => Narrower,
            (Wider, Wider) => Wider,
            _ => Other,
        }
    }
}

/// How `new` relates to `old` (`None`: no constraint).
pub fn relation(old: Option<&Constraint>, new: Option<&Constraint>) -> Relation {
    match (old, new) {
        (None, None) => Relation::Same,
        (None, Some(_)) => Relation::Narrower,
        (Some(_), None) => Relation::Wider,
        (Some(a), Some(b)) => between(a, b, 0),
    }
}

/// Deepest nesting compared (the readers bound nesting already).
const MAX_DEPTH: usize = 64;

fn between(a: &Constraint, b: &Constraint, depth: usize) -> Relation {
    if same(a, b) {
        return Relation::Same;
    }
    if depth > MAX_DEPTH {
        return Relation::Other;
    }
    match (&a.kind, &b.kind) {
        (ConstraintKind::Hash { items: ai }, ConstraintKind::Hash { items: bi }) => {
            let key = |c: &Constraint| match &c.kind {
                ConstraintKind::Unit { key, .. } => key.as_deref().map(|k| k.trim().to_string()),
                _ => None,
            };
            let (mut ak, mut bk) = (Vec::new(), Vec::new());
            for c in ai {
                match key(c) {
                    Some(k) => ak.push((k, c)),
                    None => return Relation::Other,
                }
            }
            for c in bi {
                match key(c) {
                    Some(k) => bk.push((k, c)),
                    None => return Relation::Other,
                }
            }
            let mut keys: Vec<&String> = ak.iter().chain(&bk).map(|(k, _)| k).collect();
            keys.sort();
            keys.dedup();
            let mut rel = Relation::Same;
            for k in keys {
                fn find<'c>(v: &[(String, &'c Constraint)], k: &str) -> Vec<&'c Constraint> {
                    v.iter().filter(|(x, _)| x == k).map(|(_, c)| *c).collect()
                }
                let (x, y) = (find(&ak, k), find(&bk, k));
                rel = rel.and(match (x.as_slice(), y.as_slice()) {
                    ([], [_]) => Relation::Narrower,
                    ([_], []) => Relation::Wider,
                    ([x], [y]) => unkeyed(x, y, depth + 1),
                    _ => Relation::Other,
                });
            }
            rel
        }
        (ConstraintKind::List { items: ai }, ConstraintKind::List { items: bi }) => {
            let mut rel = Relation::Same;
            for i in 0..ai.len().max(bi.len()) {
                rel = rel.and(match (ai.get(i), bi.get(i)) {
                    (Some(x), Some(y)) => between(x, y, depth + 1),
                    (Some(_), None) => Relation::Wider,
                    (None, Some(_)) => Relation::Narrower,
                    (None, None) => Relation::Same,
                });
            }
            rel
        }
        (ConstraintKind::Unit { key: ka, .. }, ConstraintKind::Unit { key: kb, .. })
            if ka.as_deref().map(str::trim) == kb.as_deref().map(str::trim) =>
        {
            match (shape(a, 0), shape(b, 0)) {
                (Some(x), Some(y)) => {
                    let (ab, ba) = (x.subset_of(&y), y.subset_of(&x));
                    match (ab, ba) {
                        (Some(true), Some(true)) => Relation::Same,
                        (Some(false), Some(true)) => Relation::Narrower,
                        (Some(true), Some(false)) => Relation::Wider,
                        _ => Relation::Other,
                    }
                }
                _ => Relation::Other,
            }
        }
        _ => Relation::Other,
    }
}

/// Two keyed units compared as if they had no key.
fn unkeyed(a: &Constraint, b: &Constraint, depth: usize) -> Relation {
    let strip = |c: &Constraint| match &c.kind {
        ConstraintKind::Unit { condition, .. } => Constraint {
            kind: ConstraintKind::Unit {
                key: None,
                condition: condition.clone(),
            },
            pos: Default::default(),
            extra: c.extra.clone(),
        },
        _ => c.clone(),
    };
    between(&strip(a), &strip(b), depth)
}

/// Equal apart from positions.
fn same(a: &Constraint, b: &Constraint) -> bool {
    let v = |c: &Constraint| strip(serde_json::to_value(c).unwrap_or_default());
    v(a) == v(b)
}

fn strip(v: serde_json::Value) -> serde_json::Value {
    use serde_json::Value;
    match v {
        Value::Object(m) => Value::Object(
            m.into_iter()
                .filter(|(k, _)| k != "pos")
                .map(|(k, v)| (k, strip(v)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.into_iter().map(strip).collect()),
        other => other,
    }
}

/// An interval of numbers; `None` bounds are infinite.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Interval {
    lo: Option<(f64, bool)>,
    hi: Option<(f64, bool)>,
}

impl Interval {
    const ALL: Interval = Interval { lo: None, hi: None };

    fn is_empty(&self) -> bool {
        match (self.lo, self.hi) {
            (Some((l, li)), Some((h, hi))) => l > h || (l == h && !(li && hi)),
            _ => false,
        }
    }

    /// `self ⊆ other`.
    fn inside(&self, other: &Interval) -> bool {
        if self.is_empty() {
            return true;
        }
        let lo_ok = match (self.lo, other.lo) {
            (_, None) => true,
            (None, Some(_)) => false,
            (Some((a, ai)), Some((b, bi))) => a > b || (a == b && (bi || !ai)),
        };
        let hi_ok = match (self.hi, other.hi) {
            (_, None) => true,
            (None, Some(_)) => false,
            (Some((a, ai)), Some((b, bi))) => a < b || (a == b && (bi || !ai)),
        };
        lo_ok && hi_ok
    }

    fn intersect(&self, o: &Interval) -> Interval {
        let lo = match (self.lo, o.lo) {
            (None, x) | (x, None) => x,
            (Some(a), Some(b)) => Some(if a.0 > b.0 || (a.0 == b.0 && !a.1) {
                a
            } else {
                b
            }),
        };
        let hi = match (self.hi, o.hi) {
            (None, x) | (x, None) => x,
            (Some(a), Some(b)) => Some(if a.0 < b.0 || (a.0 == b.0 && !a.1) {
                a
            } else {
                b
            }),
        };
        Interval { lo, hi }
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Shape {
    Intervals(Vec<Interval>),
    Set(std::collections::BTreeSet<String>),
}

impl Shape {
    /// `Some(self ⊆ other)` when the shapes are comparable.
    fn subset_of(&self, other: &Shape) -> Option<bool> {
        match (self, other) {
            (Shape::Intervals(a), Shape::Intervals(b)) => Some(
                a.iter()
                    .all(|x| x.is_empty() || b.iter().any(|y| x.inside(y))),
            ),
            (Shape::Set(a), Shape::Set(b)) => Some(a.is_subset(b)),
            _ => None,
        }
    }
}

fn number(s: &Option<crate::model::Text>) -> Option<f64> {
    crate::value::parse_float(s.as_deref()?)
}

fn shape(c: &Constraint, depth: usize) -> Option<Shape> {
    if depth > MAX_DEPTH {
        return None;
    }
    let ConstraintKind::Unit { condition, .. } = &c.kind else {
        return None;
    };
    match condition.as_ref() {
        Condition::Compare {
            comparison,
            literal,
            match_case,
        } => {
            if let Some(v) = number(literal) {
                let iv = match comparison {
                    Comparison::LessThan => Interval {
                        lo: None,
                        hi: Some((v, false)),
                    },
                    Comparison::LessThanOrEqualTo => Interval {
                        lo: None,
                        hi: Some((v, true)),
                    },
                    Comparison::GreaterThan => Interval {
                        lo: Some((v, false)),
                        hi: None,
                    },
                    Comparison::GreaterThanOrEqualTo => Interval {
                        lo: Some((v, true)),
                        hi: None,
                    },
                    Comparison::EqualTo => Interval {
                        lo: Some((v, true)),
                        hi: Some((v, true)),
                    },
                    Comparison::NotEqualTo => return None,
                };
                return Some(Shape::Intervals(vec![iv]));
            }
            let case_sensitive = crate::model::parse_bool(match_case.as_deref()) != Some(false);
            match comparison {
                Comparison::EqualTo if case_sensitive => Some(Shape::Set(
                    [literal.as_deref().unwrap_or("").trim().to_string()].into(),
                )),
                _ => None,
            }
        }
        Condition::Between { lower, upper } => Some(Shape::Intervals(vec![Interval {
            lo: Some((number(lower)?, true)),
            hi: Some((number(upper)?, true)),
        }])),
        Condition::Or { operands } => {
            let shapes: Option<Vec<Shape>> = operands.iter().map(|o| shape(o, depth + 1)).collect();
            let mut ivs = Vec::new();
            let mut set = std::collections::BTreeSet::new();
            for s in shapes? {
                match s {
                    Shape::Intervals(v) => ivs.extend(v),
                    Shape::Set(s) => set.extend(s),
                }
            }
            match (ivs.is_empty(), set.is_empty()) {
                (false, true) => Some(Shape::Intervals(ivs)),
                (true, false) => Some(Shape::Set(set)),
                _ => None,
            }
        }
        Condition::And { operands } => {
            let mut acc = Interval::ALL;
            for o in operands {
                match shape(o, depth + 1)? {
                    Shape::Intervals(v) if v.len() == 1 => acc = acc.intersect(&v[0]),
                    _ => return None,
                }
            }
            Some(Shape::Intervals(vec![acc]))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::constraint::tests::{and, between, cmp, or, unit};

    #[test]
    fn intervals() {
        let r = |a: &Constraint, b: &Constraint| relation(Some(a), Some(b));
        assert_eq!(
            r(&between("0", "10"), &between("0", "5")),
            Relation::Narrower
        );
        assert_eq!(r(&between("0", "5"), &between("0", "10")), Relation::Wider);
        assert_eq!(r(&between("0", "10"), &between("5", "15")), Relation::Other);
        assert_eq!(
            r(
                &cmp(Comparison::LessThan, "2.0"),
                &cmp(Comparison::LessThanOrEqualTo, "2")
            ),
            Relation::Wider
        );
        assert_eq!(
            r(
                &cmp(Comparison::LessThanOrEqualTo, "10"),
                &between("0", "10")
            ),
            Relation::Narrower
        );
        // x ≤ 100 or x ≥ 200 → x ≤ 50 or x ≥ 200
        let a = or(vec![
            cmp(Comparison::LessThanOrEqualTo, "100"),
            cmp(Comparison::GreaterThanOrEqualTo, "200"),
        ]);
        let b = or(vec![
            cmp(Comparison::LessThanOrEqualTo, "50"),
            cmp(Comparison::GreaterThanOrEqualTo, "200"),
        ]);
        assert_eq!(r(&a, &b), Relation::Narrower);
        assert_eq!(r(&b, &a), Relation::Wider);
        // 0 ≤ x ≤ 10 written as an `and` of two comparisons is the same set.
        let both = and(vec![
            cmp(Comparison::GreaterThanOrEqualTo, "0"),
            cmp(Comparison::LessThanOrEqualTo, "10"),
        ]);
        assert_eq!(r(&between("0", "10"), &both), Relation::Same);
    }

    #[test]
    fn sets_and_absence() {
        let set = |v: &[&str]| or(v.iter().map(|s| cmp(Comparison::EqualTo, s)).collect());
        let r = |a: &Constraint, b: &Constraint| relation(Some(a), Some(b));
        assert_eq!(
            r(&set(&["RGB", "GRAY"]), &set(&["RGB"])),
            Relation::Narrower
        );
        assert_eq!(r(&set(&["RGB"]), &set(&["RGB", "JPEG"])), Relation::Wider);
        assert_eq!(r(&set(&["RGB"]), &set(&["JPEG"])), Relation::Other);
        assert_eq!(relation(None, Some(&set(&["a"]))), Relation::Narrower);
        assert_eq!(relation(Some(&set(&["a"])), None), Relation::Wider);
        let like = unit(Condition::Like {
            literal: Some("/dev/*".into()),
            wild_card: None,
            single_char: None,
            escape_char: None,
        });
        assert_eq!(r(&like, &set(&["a"])), Relation::Other);
    }
}
