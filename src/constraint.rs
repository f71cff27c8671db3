//! Constraints for humans: one shared rendering of the constraint tree used by every renderer
//! (`0 ≤ x ≤ 100`, `x < 100`, `one of: RGB, GRAY, JPEG`, `x ≤ 100 or x ≥ 200`, `not null`).

use crate::model::{Comparison, Condition, Constraint, ConstraintKind};

/// Renders a constraint as a short plain-text formula. `x` stands for the value.
pub fn describe(c: &Constraint) -> String {
    describe_kind(c, false)
}

fn text(s: &Option<String>) -> &str {
    s.as_deref().map(str::trim).unwrap_or("")
}

fn is_case_insensitive(match_case: &Option<String>) -> bool {
    crate::model::parse_bool(match_case.as_deref()) == Some(false)
}

fn describe_kind(c: &Constraint, nested: bool) -> String {
    match &c.kind {
        ConstraintKind::Unit { key, condition } => {
            let body = describe_condition(condition, nested && key.is_none());
            match key.as_deref().map(str::trim).filter(|k| !k.is_empty()) {
                Some(k) => format!("{k}: {body}"),
                None => body,
            }
        }
        ConstraintKind::List { items } => {
            let parts: Vec<String> = items
                .iter()
                .enumerate()
                .map(|(i, item)| format!("[{i}] {}", describe_kind(item, false)))
                .collect();
            parts.join("; ")
        }
        ConstraintKind::Hash { items } => {
            let parts: Vec<String> = items
                .iter()
                .map(|item| describe_kind(item, false))
                .collect();
            parts.join("; ")
        }
        ConstraintKind::Empty => String::new(),
    }
}

/// The condition of a unit, when `c` is a plain unit (no key needed).
fn unit_condition(c: &Constraint) -> Option<&Condition> {
    match &c.kind {
        ConstraintKind::Unit { condition, .. } => Some(condition),
        _ => None,
    }
}

fn describe_condition(cond: &Condition, nested: bool) -> String {
    match cond {
        Condition::Compare {
            comparison,
            literal,
            match_case,
        } => {
            let case = if is_case_insensitive(match_case) {
                " (any case)"
            } else {
                ""
            };
            format!("x {} {}{case}", comparison.symbol(), text(literal))
        }
        Condition::Between { lower, upper } => format!("{} ≤ x ≤ {}", text(lower), text(upper)),
        Condition::IsNull { .. } => "null".to_string(),
        Condition::Like {
            literal,
            wild_card,
            single_char,
            escape_char,
        } => {
            let mut legend = Vec::new();
            if !text(wild_card).is_empty() {
                legend.push(format!("{} = any text", text(wild_card)));
            }
            if !text(single_char).is_empty() {
                legend.push(format!("{} = one character", text(single_char)));
            }
            if !text(escape_char).is_empty() {
                legend.push(format!("{} = escape", text(escape_char)));
            }
            if legend.is_empty() {
                format!("x like “{}”", text(literal))
            } else {
                format!("x like “{}” ({})", text(literal), legend.join(", "))
            }
        }
        Condition::Not { operand } => match unit_condition(operand) {
            Some(Condition::IsNull { .. }) => "not null".to_string(),
            Some(Condition::Compare {
                comparison: Comparison::EqualTo,
                literal,
                match_case,
            }) => {
                let case = if is_case_insensitive(match_case) {
                    " (any case)"
                } else {
                    ""
                };
                format!("x ≠ {}{case}", text(literal))
            }
            _ => format!("not ({})", describe_kind(operand, false)),
        },
        Condition::Or { operands } => {
            // An Or of plain equalities is an enumeration.
            let literals: Option<Vec<&str>> = operands
                .iter()
                .map(|o| match unit_condition(o) {
                    Some(Condition::Compare {
                        comparison: Comparison::EqualTo,
                        literal,
                        ..
                    }) => Some(text(literal)),
                    _ => None,
                })
                .collect();
            let s = match literals {
                Some(l) if l.len() > 1 => format!("one of: {}", l.join(", ")),
                _ => operands
                    .iter()
                    .map(|o| describe_kind(o, true))
                    .collect::<Vec<_>>()
                    .join(" or "),
            };
            if nested && !s.starts_with("one of") {
                format!("({s})")
            } else {
                s
            }
        }
        Condition::And { operands } => {
            if let [a, b] = operands.as_slice() {
                if let Some(s) = range_pair(a, b).or_else(|| range_pair(b, a)) {
                    return s;
                }
            }
            let s = operands
                .iter()
                .map(|o| describe_kind(o, true))
                .collect::<Vec<_>>()
                .join(" and ");
            if nested {
                format!("({s})")
            } else {
                s
            }
        }
    }
}

/// `x ≥ a and x ≤ b` → `a ≤ x ≤ b` (and the strict variants).
fn range_pair(low: &Constraint, high: &Constraint) -> Option<String> {
    let (
        Some(Condition::Compare {
            comparison: lc,
            literal: ll,
            ..
        }),
        Some(Condition::Compare {
            comparison: hc,
            literal: hl,
            ..
        }),
    ) = (unit_condition(low), unit_condition(high))
    else {
        return None;
    };
    let lsym = match lc {
        Comparison::GreaterThan => "<",
        Comparison::GreaterThanOrEqualTo => "≤",
        _ => return None,
    };
    let hsym = match hc {
        Comparison::LessThan => "<",
        Comparison::LessThanOrEqualTo => "≤",
        _ => return None,
    };
    Some(format!("{} {lsym} x {hsym} {}", text(ll), text(hl)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Pos;

    fn unit(cond: Condition) -> Constraint {
        Constraint {
            kind: ConstraintKind::Unit {
                key: None,
                condition: Box::new(cond),
            },
            pos: Pos::default(),
            extra: vec![],
        }
    }
    fn cmp(c: Comparison, lit: &str) -> Constraint {
        unit(Condition::Compare {
            comparison: c,
            literal: Some(lit.into()),
            match_case: None,
        })
    }

    #[test]
    fn between_and_comparisons() {
        let b = unit(Condition::Between {
            lower: Some("0".into()),
            upper: Some("100".into()),
        });
        assert_eq!(describe(&b), "0 ≤ x ≤ 100");
        assert_eq!(describe(&cmp(Comparison::LessThan, "100")), "x < 100");
    }

    #[test]
    fn enumeration_and_or() {
        let e = unit(Condition::Or {
            operands: vec![
                cmp(Comparison::EqualTo, "RGB"),
                cmp(Comparison::EqualTo, "GRAY"),
                cmp(Comparison::EqualTo, "JPEG"),
            ],
        });
        assert_eq!(describe(&e), "one of: RGB, GRAY, JPEG");
        let o = unit(Condition::Or {
            operands: vec![
                cmp(Comparison::LessThanOrEqualTo, "100"),
                cmp(Comparison::GreaterThanOrEqualTo, "200"),
            ],
        });
        assert_eq!(describe(&o), "x ≤ 100 or x ≥ 200");
    }

    #[test]
    fn not_null_and_range_and() {
        let n = unit(Condition::Not {
            operand: unit(Condition::IsNull { text: None }),
        });
        assert_eq!(describe(&n), "not null");
        let a = unit(Condition::And {
            operands: vec![
                cmp(Comparison::GreaterThan, "0"),
                cmp(Comparison::LessThanOrEqualTo, "10"),
            ],
        });
        assert_eq!(describe(&a), "0 < x ≤ 10");
    }
}
