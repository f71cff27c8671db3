//! Constraints, shared by the renderers and `rtcdoc check`:
//!
//! - [`describe`]: one rendering of the constraint tree for humans (`0 ≤ x ≤ 100`, `x < 100`,
//!   `one of: RGB, GRAY, JPEG`, `x ≤ 100 or x ≥ 200`, `not null`);
//! - [`evaluate`]: does a value (a configuration's `defaultValue`) satisfy the constraint?
//! - [`problems`]: literals that do not parse for the type and malformed constraint nodes.
//!
//! Evaluation semantics (spec 2.3.17–2.3.41, samples 8.1):
//! - comparisons and `between` are numeric when the value type is numeric (or unknown) and both
//!   sides parse as numbers, string comparisons otherwise; `matchCase="false"` compares strings
//!   without case, an absent `matchCase` is case-sensitive (8.1); `between` is inclusive;
//! - `propertyIsNull` holds when the value is empty (after trimming);
//! - `propertyIsLike` matches the whole value against the literal, where `wildCard` stands for
//!   any text, `singleChar` for exactly one character and `escapeChar` makes the next character
//!   literal (each attribute: its first non-space character; absent = `*`, `?`, `\\`); no
//!   regular expressions are built from profile text;
//! - a unit constraint over a vector value applies, as a whole, to every element
//!   (`propertyIsNull` still looks at the whole value);
//! - `ConstraintListType` applies item *i* to element *i* of the comma-separated value: a missing
//!   element violates it, elements beyond the list are unconstrained;
//! - `ConstraintHashType` reads the value as comma-separated `key:value` pairs (whatever the
//!   declared type); the keyed item `k` applies to the value of pair `k`; a key the value does
//!   not set violates it; pairs without an item are unconstrained; a value mixing pairs and
//!   plain items is unevaluable. Over a *plain* value (no `:` at all) the keys label
//!   alternatives, as real profiles use it (`twochar` = 2, `threechar` = 3): the value must
//!   satisfy one of the items. A keyed unit outside a hash is read as a hash of one item.
//! - list and hash items of a vector are typed by the vector's element type; those of a plain
//!   value by what they look like (numeric when both sides parse as numbers), since the declared
//!   type (`string`) describes the whole text.
//!
//! Evaluation is three-valued: a comparison that cannot be made (a literal or value that does not
//! parse for a numeric type, a malformed node) is *unevaluable*; `not` keeps it unevaluable,
//! `and` is false if any operand is false, `or` is true if any operand is true. Evaluation
//! never panics and its recursion is bounded by [`MAX_DEPTH`].

use crate::i18n::Lang;
use crate::model::{Comparison, Condition, Constraint, ConstraintKind, Pos};
use crate::quote::Code;
use crate::value::{self, ScalarType, ValueType};

/// Renders a constraint as a short plain-text formula. `x` stands for the value. (English:
/// messages and `catalog.json`; pages use [`describe_in`].)
pub fn describe(c: &Constraint) -> String {
    describe_in(c, Lang::En)
}

/// [`describe`] with its words (`one of`, `or`, `and`, `not`, the legend of a pattern) in `lang`.
pub fn describe_in(c: &Constraint, lang: Lang) -> String {
    describe_kind(c, false, lang)
}

fn text(s: &Option<crate::model::Text>) -> &str {
    s.as_deref().map(str::trim).unwrap_or("")
}

fn is_case_insensitive(match_case: &Option<crate::model::Text>) -> bool {
    crate::model::parse_bool(match_case.as_deref()) == Some(false)
}

/// `x = lit`, `x ≤ lit`, …, with ` (any case)` for a comparison that ignores case.
fn comparison_text(
    comparison: Comparison,
    literal: &Option<crate::model::Text>,
    match_case: &Option<crate::model::Text>,
    lang: Lang,
) -> String {
    let case = if is_case_insensitive(match_case) {
        lang.t("constraint_any_case")
    } else {
        ""
    };
    format!("x {} {}{case}", comparison.symbol(), text(literal))
}

/// `x like “pattern”`, with a legend of the wild card, single-character and escape characters
/// the constraint names.
fn like_text(
    literal: &Option<crate::model::Text>,
    marks: [(&Option<crate::model::Text>, &str); 3],
) -> String {
    let legend: Vec<String> = marks
        .iter()
        .filter(|(c, _)| !text(c).is_empty())
        .map(|(c, means)| format!("{} = {means}", text(c)))
        .collect();
    if legend.is_empty() {
        format!("x like “{}”", text(literal))
    } else {
        format!("x like “{}” ({})", text(literal), legend.join(", "))
    }
}

fn describe_kind(c: &Constraint, nested: bool, lang: Lang) -> String {
    match &c.kind {
        ConstraintKind::Unit { key, condition } => {
            let body = describe_condition(condition, nested && key.is_none(), lang);
            match key.as_deref().map(str::trim).filter(|k| !k.is_empty()) {
                Some(k) => format!("{k}: {body}"),
                None => body,
            }
        }
        ConstraintKind::List { items } => {
            let parts: Vec<String> = items
                .iter()
                .enumerate()
                .map(|(i, item)| format!("[{i}] {}", describe_kind(item, false, lang)))
                .collect();
            parts.join("; ")
        }
        ConstraintKind::Hash { items } => {
            let parts: Vec<String> = items
                .iter()
                .map(|item| describe_kind(item, false, lang))
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

fn describe_condition(cond: &Condition, nested: bool, lang: Lang) -> String {
    match cond {
        Condition::Compare {
            comparison,
            literal,
            match_case,
        } => comparison_text(*comparison, literal, match_case, lang),
        Condition::Between { lower, upper } => format!("{} ≤ x ≤ {}", text(lower), text(upper)),
        Condition::IsNull { .. } => "null".to_string(),
        Condition::Like {
            literal,
            wild_card,
            single_char,
            escape_char,
        } => like_text(
            literal,
            [
                (wild_card, lang.t("constraint_any_text")),
                (single_char, lang.t("constraint_one_char")),
                (escape_char, lang.t("constraint_escape")),
            ],
        ),
        Condition::Not { operand } => match unit_condition(operand) {
            Some(Condition::IsNull { .. }) => lang.t("constraint_not_null").to_string(),
            Some(Condition::Compare {
                comparison: Comparison::EqualTo,
                literal,
                match_case,
            }) => comparison_text(Comparison::NotEqualTo, literal, match_case, lang),
            _ => format!(
                "{}{}{}",
                lang.t("constraint_not_before"),
                describe_kind(operand, false, lang),
                lang.t("constraint_not_after")
            ),
        },
        Condition::Or { operands } => match enumeration(operands) {
            Some(l) if l.len() > 1 => format!("{}{}", lang.t("constraint_one_of"), l.join(", ")),
            _ => joined(operands, lang.t("constraint_or"), nested, lang),
        },
        Condition::And { operands } => {
            if let [a, b] = operands.as_slice() {
                if let Some(s) = range_pair(a, b).or_else(|| range_pair(b, a)) {
                    return s;
                }
            }
            joined(operands, lang.t("constraint_and"), nested, lang)
        }
    }
}

/// The operands of an `or` / `and` joined by `word`; in parentheses when `nested` in another
/// formula.
fn joined(operands: &[Constraint], word: &str, nested: bool, lang: Lang) -> String {
    let s = operands
        .iter()
        .map(|o| describe_kind(o, true, lang))
        .collect::<Vec<_>>()
        .join(word);
    if nested {
        format!("({s})")
    } else {
        s
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

/// Deepest constraint nesting evaluated (readers already limit nesting; this is a second guard).
pub const MAX_DEPTH: usize = 256;

/// The result of evaluating a constraint against a value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// The value satisfies the constraint.
    Satisfied,
    /// The value does not satisfy it; the text says which part failed.
    Violated(String),
    /// The constraint cannot be evaluated for this value; the text says why.
    Unevaluable(String),
}

/// The type a value of a configuration parameter of type `ty` is checked as: RTSystemEditor's
/// checkbox and ordered_list widgets store the selected items as a comma-separated list, each
/// item to satisfy the constraint (an enumeration).
pub fn widget_type(widget: Option<&str>, ty: ValueType) -> ValueType {
    match (widget.map(str::trim), ty) {
        (Some("checkbox" | "ordered_list"), ValueType::Scalar(s)) => ValueType::Vector(s),
        (Some("checkbox" | "ordered_list"), ValueType::Unknown) => {
            ValueType::Vector(ScalarType::Text)
        }
        _ => ty,
    }
}

/// Evaluates `c` against `value` (as written in the profile) of type `ty`.
pub fn evaluate(c: &Constraint, value: &str, ty: ValueType) -> Verdict {
    let subject = match ty {
        ValueType::Vector(_) => Subject::Many(value::split_vector(value)),
        _ => Subject::One(value),
    };
    let ev = Eval {
        raw: value,
        elem: ty.element(),
        item_elem: item_type(ty),
    };
    match ev.constraint(c, &subject, 0) {
        Truth::True => Verdict::Satisfied,
        Truth::False(why) => Verdict::Violated(why),
        Truth::Unknown(why) => Verdict::Unevaluable(why),
    }
}

#[derive(Debug, Clone)]
enum Truth {
    True,
    False(String),
    Unknown(String),
}

enum Subject<'a> {
    One(&'a str),
    Many(Vec<&'a str>),
}

struct Eval<'a> {
    raw: &'a str,
    elem: Option<ScalarType>,
    /// Type of the elements of a list or hash constraint (see [`item_type`]).
    item_elem: Option<ScalarType>,
}

/// The type list and hash items are evaluated with: the element type of a vector; for a plain
/// value (a `string` holding `x:0,y:0`) the declared type describes the whole text, not its
/// parts, so the parts are typed by what they look like (numeric when both sides parse as
/// numbers).
fn item_type(ty: ValueType) -> Option<ScalarType> {
    match ty {
        ValueType::Vector(s) => Some(s),
        _ => None,
    }
}

/// The special characters of a `propertyIsLike` pattern.
#[derive(Debug, Clone, Copy)]
pub struct LikeChars {
    pub wild_card: Option<char>,
    pub single_char: Option<char>,
    pub escape_char: Option<char>,
}

impl LikeChars {
    /// From the attributes as written: first non-space character; absent = `*`, `?`, `\`;
    /// present but blank = no such character.
    pub fn from_attrs(
        w: &Option<crate::model::Text>,
        s: &Option<crate::model::Text>,
        e: &Option<crate::model::Text>,
    ) -> Self {
        let pick = |a: &Option<crate::model::Text>, default: char| match a {
            None => Some(default),
            Some(t) => t.trim().chars().next(),
        };
        LikeChars {
            wild_card: pick(w, '*'),
            single_char: pick(s, '?'),
            escape_char: pick(e, '\\'),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Tok {
    Any,
    One,
    Lit(char),
}

/// Matches `text` against a `propertyIsLike` pattern (whole text). Iterative with one
/// backtracking point per wild card: O(len(text) × len(pattern)) at worst, never exponential.
pub fn like_matches(text: &str, pattern: &str, chars: LikeChars) -> bool {
    let mut toks = Vec::new();
    let mut it = pattern.chars();
    while let Some(ch) = it.next() {
        if Some(ch) == chars.escape_char {
            // A trailing escape character stands for itself.
            toks.push(Tok::Lit(it.next().unwrap_or(ch)));
        } else if Some(ch) == chars.wild_card {
            if toks.last() != Some(&Tok::Any) {
                toks.push(Tok::Any);
            }
        } else if Some(ch) == chars.single_char {
            toks.push(Tok::One);
        } else {
            toks.push(Tok::Lit(ch));
        }
    }
    let text: Vec<char> = text.chars().collect();
    let (mut t, mut p) = (0usize, 0usize);
    let mut star: Option<(usize, usize)> = None;
    while t < text.len() {
        match toks.get(p) {
            Some(Tok::One) => {
                t += 1;
                p += 1;
            }
            Some(Tok::Lit(c)) if *c == text[t] => {
                t += 1;
                p += 1;
            }
            Some(Tok::Any) => {
                star = Some((p, t));
                p += 1;
            }
            _ => match star {
                Some((sp, st)) => {
                    p = sp + 1;
                    t = st + 1;
                    star = Some((sp, st + 1));
                }
                None => return false,
            },
        }
    }
    toks[p.min(toks.len())..].iter().all(|k| *k == Tok::Any)
}

fn opt(s: &Option<crate::model::Text>) -> Option<&str> {
    s.as_deref().map(str::trim)
}

/// A number for comparisons, when the element type allows one and `s` parses.
fn number(elem: Option<ScalarType>, s: &str) -> Option<f64> {
    match elem {
        Some(ScalarType::Integer { .. }) | Some(ScalarType::Float) | None => value::parse_float(s),
        _ => None,
    }
}

fn is_numeric(elem: Option<ScalarType>) -> bool {
    matches!(
        elem,
        Some(ScalarType::Integer { .. }) | Some(ScalarType::Float)
    )
}

impl Eval<'_> {
    fn constraint(&self, c: &Constraint, subject: &Subject, depth: usize) -> Truth {
        if depth > MAX_DEPTH {
            return Truth::Unknown("the constraint nests too deeply".into());
        }
        match &c.kind {
            // A unit over a non-empty vector: every element must satisfy the whole condition
            // tree (`one of: a, b` means each element is a or b, not "all are a or all are b");
            // `propertyIsNull` still looks at the whole value. An empty vector reaches the
            // leaves with no elements, where comparisons hold vacuously.
            ConstraintKind::Unit {
                key: None,
                condition,
            } => match subject {
                Subject::Many(elements) if !elements.is_empty() => {
                    let mut unknown = None;
                    for (i, e) in elements.iter().enumerate() {
                        match self.condition(condition, &Subject::One(e), depth + 1) {
                            Truth::True => {}
                            Truth::False(w) => {
                                return Truth::False(format!("element {i} ({}): {w}", Code(e)))
                            }
                            Truth::Unknown(w) => unknown = unknown.or(Some(w)),
                        }
                    }
                    unknown.map_or(Truth::True, Truth::Unknown)
                }
                _ => self.condition(condition, subject, depth + 1),
            },
            ConstraintKind::Unit { key: Some(_), .. } => {
                self.hash(std::slice::from_ref(c), depth + 1)
            }
            ConstraintKind::List { items } => {
                let elements = value::split_vector(self.raw);
                let mut unknown = None;
                for (i, item) in items.iter().enumerate() {
                    let Some(e) = elements.get(i) else {
                        return Truth::False(format!(
                            "the constraint list has {} item(s) but the value only {} element(s)",
                            items.len(),
                            elements.len()
                        ));
                    };
                    match self.item(item, e, depth) {
                        Truth::True => {}
                        Truth::False(why) => return Truth::False(format!("element {i}: {why}")),
                        Truth::Unknown(why) => unknown = unknown.or(Some(why)),
                    }
                }
                unknown.map_or(Truth::True, Truth::Unknown)
            }
            ConstraintKind::Hash { items } => self.hash(items, depth + 1),
            ConstraintKind::Empty => Truth::Unknown("the constraint is empty".into()),
        }
    }

    /// One element of a list or hash: evaluated as a scalar of the element type.
    fn item(&self, item: &Constraint, element: &str, depth: usize) -> Truth {
        let sub = Eval {
            raw: element,
            elem: self.item_elem,
            item_elem: self.item_elem,
        };
        let c = match &item.kind {
            // The key of a hash item has been used to pick the element.
            ConstraintKind::Unit {
                key: Some(_),
                condition,
            } => return sub.condition(condition, &Subject::One(element), depth + 1),
            _ => item,
        };
        sub.constraint(c, &Subject::One(element), depth + 1)
    }

    fn hash(&self, items: &[Constraint], depth: usize) -> Truth {
        if !self.raw.contains(':') {
            return self.labelled_alternatives(items, depth);
        }
        let mut pairs = Vec::new();
        for part in value::split_vector(self.raw) {
            match part.split_once(':') {
                Some((k, v)) => pairs.push((k.trim(), v.trim())),
                None => {
                    return Truth::Unknown(format!(
                        "a hash constraint needs `key:value` pairs; {} is not one",
                        Code(part)
                    ))
                }
            }
        }
        let mut unknown = None;
        for item in items {
            let key = match &item.kind {
                ConstraintKind::Unit { key: Some(k), .. } if !k.trim().is_empty() => k.trim(),
                _ => {
                    unknown = unknown.or(Some("a hash constraint item has no key".to_string()));
                    continue;
                }
            };
            let Some((_, v)) = pairs.iter().find(|(k, _)| *k == key) else {
                return Truth::False(format!("the value sets no {}", Code(key)));
            };
            match self.item(item, v, depth) {
                Truth::True => {}
                Truth::False(why) => return Truth::False(format!("{}: {why}", Code(key))),
                Truth::Unknown(why) => unknown = unknown.or(Some(why)),
            }
        }
        unknown.map_or(Truth::True, Truth::Unknown)
    }

    /// A hash constraint over a plain value (no `key:value` pair at all): the keys label
    /// alternatives (UrgRTC's `encoding`: `twochar` = 2, `threechar` = 3) and the value must
    /// satisfy one of the items.
    fn labelled_alternatives(&self, items: &[Constraint], depth: usize) -> Truth {
        let mut unknown = None;
        let mut keys = Vec::new();
        for item in items {
            if let ConstraintKind::Unit { key: Some(k), .. } = &item.kind {
                keys.push(k.trim());
            }
            match self.item(item, self.raw, depth) {
                Truth::True => return Truth::True,
                Truth::False(_) => {}
                Truth::Unknown(w) => unknown = unknown.or(Some(w)),
            }
        }
        unknown.map_or_else(
            || {
                Truth::False(format!(
                    "{} satisfies none of the keyed alternatives ({})",
                    Code(self.raw.trim()),
                    keys.join(", ")
                ))
            },
            Truth::Unknown,
        )
    }

    fn condition(&self, cond: &Condition, subject: &Subject, depth: usize) -> Truth {
        if depth > MAX_DEPTH {
            return Truth::Unknown("the constraint nests too deeply".into());
        }
        match cond {
            Condition::Not { operand } => match self.constraint(operand, subject, depth + 1) {
                Truth::True => Truth::False(format!("`not ({})` is false", describe(operand))),
                Truth::False(_) => Truth::True,
                u @ Truth::Unknown(_) => u,
            },
            Condition::And { operands } => {
                if operands.is_empty() {
                    return Truth::Unknown("`and` has no operands".into());
                }
                let mut unknown = None;
                for o in operands {
                    match self.constraint(o, subject, depth + 1) {
                        Truth::True => {}
                        f @ Truth::False(_) => return f,
                        Truth::Unknown(w) => unknown = unknown.or(Some(w)),
                    }
                }
                unknown.map_or(Truth::True, Truth::Unknown)
            }
            Condition::Or { operands } => {
                if operands.is_empty() {
                    return Truth::Unknown("`or` has no operands".into());
                }
                // An enumeration (an Or of equalities) that fails says so once.
                let one_of = match (enumeration(operands), subject) {
                    (Some(l), Subject::One(v)) if l.len() > 1 => Some(format!(
                        "{} is not one of: {}",
                        Code(v.trim()),
                        l.join(", ")
                    )),
                    _ => None,
                };
                let mut unknown = None;
                let mut reasons = Vec::new();
                for o in operands {
                    match self.constraint(o, subject, depth + 1) {
                        Truth::True => return Truth::True,
                        Truth::False(w) => reasons.push(w),
                        Truth::Unknown(w) => unknown = unknown.or(Some(w)),
                    }
                }
                match unknown {
                    Some(w) => Truth::Unknown(w),
                    None => Truth::False(one_of.unwrap_or_else(|| reasons.join("; and "))),
                }
            }
            Condition::IsNull { .. } => {
                if self.raw.trim().is_empty() {
                    Truth::True
                } else {
                    Truth::False(format!("`{}` is not null (empty)", self.raw.trim()))
                }
            }
            _ => match subject {
                Subject::One(v) => self.scalar(cond, v),
                Subject::Many(vs) => {
                    let mut unknown = None;
                    for (i, v) in vs.iter().enumerate() {
                        match self.scalar(cond, v) {
                            Truth::True => {}
                            Truth::False(w) => return Truth::False(format!("element {i}: {w}")),
                            Truth::Unknown(w) => unknown = unknown.or(Some(w)),
                        }
                    }
                    unknown.map_or(Truth::True, Truth::Unknown)
                }
            },
        }
    }

    /// `v` against a comparison's literal: as booleans, numbers or text, by the element type.
    fn compare(
        &self,
        v: &str,
        comparison: Comparison,
        literal: &Option<crate::model::Text>,
        match_case: &Option<crate::model::Text>,
    ) -> Truth {
        let Some(lit) = opt(literal) else {
            return Truth::Unknown("a comparison has no literal".into());
        };
        let ok = match self.elem {
            Some(ScalarType::Bool) => {
                let (Some(a), Some(b)) =
                    (value::parse_config_bool(v), value::parse_config_bool(lit))
                else {
                    return Truth::Unknown(format!("`{lit}` or `{v}` is not a boolean"));
                };
                match comparison {
                    Comparison::EqualTo => a == b,
                    Comparison::NotEqualTo => a != b,
                    _ => return Truth::Unknown("booleans have no order".into()),
                }
            }
            elem => match (number(elem, v), number(elem, lit)) {
                (Some(a), Some(b)) => ordering_holds(comparison, a.partial_cmp(&b)),
                _ if is_numeric(elem) => {
                    return Truth::Unknown(format!(
                        "`{v}` and `{lit}` cannot both be read as numbers"
                    ))
                }
                _ => {
                    let ord = if is_case_insensitive(match_case) {
                        v.to_lowercase().cmp(&lit.to_lowercase())
                    } else {
                        v.cmp(lit)
                    };
                    ordering_holds(comparison, Some(ord))
                }
            },
        };
        if ok {
            Truth::True
        } else {
            Truth::False(format!("`{v}` is not {} {lit}", comparison.symbol()))
        }
    }

    /// A leaf condition (comparison, like, between) against one scalar.
    fn scalar(&self, cond: &Condition, v: &str) -> Truth {
        let v = v.trim();
        match cond {
            Condition::Compare {
                comparison,
                literal,
                match_case,
            } => self.compare(v, *comparison, literal, match_case),
            Condition::Between { lower, upper } => {
                let (Some(lo), Some(hi)) = (opt(lower), opt(upper)) else {
                    return Truth::Unknown("`between` needs both boundaries".into());
                };
                let inside = match (
                    number(self.elem, v),
                    number(self.elem, lo),
                    number(self.elem, hi),
                ) {
                    (Some(x), Some(a), Some(b)) => a <= x && x <= b,
                    _ if is_numeric(self.elem) => {
                        return Truth::Unknown(format!(
                            "`{v}`, `{lo}` and `{hi}` cannot all be read as numbers"
                        ))
                    }
                    _ => lo <= v && v <= hi,
                };
                if inside {
                    Truth::True
                } else {
                    Truth::False(format!("`{v}` is not between {lo} and {hi}"))
                }
            }
            Condition::Like {
                literal,
                wild_card,
                single_char,
                escape_char,
            } => {
                let Some(pattern) = opt(literal) else {
                    return Truth::Unknown("`like` has no pattern".into());
                };
                let chars = LikeChars::from_attrs(wild_card, single_char, escape_char);
                if like_matches(v, pattern, chars) {
                    Truth::True
                } else {
                    Truth::False(format!("`{v}` does not match the pattern `{pattern}`"))
                }
            }
            // Logical operators and null are handled by `condition`.
            _ => Truth::Unknown("unexpected condition".into()),
        }
    }
}

/// The literals of an Or of plain equalities (an enumeration: `one of: RGB, GRAY`), in order.
fn enumeration(operands: &[Constraint]) -> Option<Vec<&str>> {
    operands
        .iter()
        .map(|o| match unit_condition(o) {
            Some(Condition::Compare {
                comparison: Comparison::EqualTo,
                literal,
                ..
            }) => Some(text(literal)),
            _ => None,
        })
        .collect()
}

fn ordering_holds(c: Comparison, ord: Option<std::cmp::Ordering>) -> bool {
    use std::cmp::Ordering::*;
    let Some(o) = ord else { return false };
    match c {
        Comparison::EqualTo => o == Equal,
        Comparison::NotEqualTo => o != Equal,
        Comparison::LessThan => o == Less,
        Comparison::GreaterThan => o == Greater,
        Comparison::LessThanOrEqualTo => o != Greater,
        Comparison::GreaterThanOrEqualTo => o != Less,
    }
}

/// What is wrong with a constraint itself, independent of the value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Problem {
    /// A literal or boundary does not parse for the value type.
    Literal { pos: Pos, message: String },
    /// A node is malformed (empty, an operator without operands, a comparison without literal,
    /// a hash item without key).
    Structure { pos: Pos, message: String },
}

/// Checks every literal of `c` against the element type of `ty` and every node's shape.
pub fn problems(c: &Constraint, ty: ValueType) -> Vec<Problem> {
    let mut out = Vec::new();
    walk_problems(c, ty.element(), item_type(ty), false, c.pos, &mut out, 0);
    out
}

#[allow(clippy::too_many_arguments)]
fn walk_problems(
    c: &Constraint,
    elem: Option<ScalarType>,
    item_elem: Option<ScalarType>,
    in_hash: bool,
    parent: Pos,
    out: &mut Vec<Problem>,
    depth: usize,
) {
    if depth > MAX_DEPTH {
        return;
    }
    let pos = if c.pos.is_unknown() { parent } else { c.pos };
    let structure =
        |out: &mut Vec<Problem>, message: String| out.push(Problem::Structure { pos, message });
    let check_literal = |out: &mut Vec<Problem>, what: &str, lit: &Option<crate::model::Text>| {
        let Some(l) = opt(lit) else {
            out.push(Problem::Structure {
                pos,
                message: format!("{what} is missing"),
            });
            return;
        };
        let Some(ty) = elem else { return };
        if matches!(ty, ScalarType::Text | ScalarType::Char) {
            return;
        }
        if let Err(m) = value::parse_scalar(ty, l) {
            out.push(Problem::Literal {
                pos,
                message: format!("{what} {m}"),
            });
        }
    };
    match &c.kind {
        ConstraintKind::Empty => structure(out, "the constraint has no condition".into()),
        ConstraintKind::List { items } | ConstraintKind::Hash { items } => {
            let hash = matches!(c.kind, ConstraintKind::Hash { .. });
            if items.is_empty() {
                structure(out, "the constraint list or hash has no items".into());
            }
            for i in items {
                walk_problems(i, item_elem, item_elem, hash, pos, out, depth + 1);
            }
        }
        ConstraintKind::Unit { key, condition } => {
            if in_hash && key.as_deref().is_none_or(|k| k.trim().is_empty()) {
                structure(out, "a hash constraint item has no key".into());
            }
            match condition.as_ref() {
                Condition::Not { operand } => {
                    walk_problems(operand, elem, item_elem, false, pos, out, depth + 1)
                }
                Condition::And { operands } | Condition::Or { operands } => {
                    if operands.is_empty() {
                        structure(out, "a logical operator has no operands".into());
                    }
                    for o in operands {
                        walk_problems(o, elem, item_elem, false, pos, out, depth + 1);
                    }
                }
                Condition::IsNull { .. } => {}
                Condition::Compare {
                    literal,
                    match_case,
                    ..
                } => {
                    check_literal(out, "the literal", literal);
                    if let Some(m) = match_case {
                        if crate::model::parse_bool(Some(m)).is_none() {
                            structure(out, format!("matchCase `{m}` is not a boolean"));
                        }
                    }
                }
                Condition::Between { lower, upper } => {
                    check_literal(out, "the lower boundary", lower);
                    check_literal(out, "the upper boundary", upper);
                    if let (Some(ty), Some(lo), Some(hi)) = (elem, opt(lower), opt(upper)) {
                        if let (
                            Ok(Some(value::Scalar::Number(a))),
                            Ok(Some(value::Scalar::Number(b))),
                        ) = (value::parse_scalar(ty, lo), value::parse_scalar(ty, hi))
                        {
                            if a > b {
                                structure(out, format!("the lower boundary {lo} is above the upper boundary {hi}: no value can satisfy it"));
                            }
                        }
                    }
                }
                Condition::Like { literal: l, .. } => {
                    if opt(l).is_none() {
                        structure(out, "the pattern is missing".into());
                    }
                }
            }
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::model::Pos;

    /// A constraint of one condition (also for `diff::constraint`'s tests).
    pub(crate) fn unit(cond: Condition) -> Constraint {
        Constraint {
            kind: ConstraintKind::Unit {
                key: None,
                condition: Box::new(cond),
            },
            pos: Pos::default(),
            extra: crate::model::Extras::new(),
        }
    }
    /// `x <comparison> lit`.
    pub(crate) fn cmp(c: Comparison, lit: &str) -> Constraint {
        unit(Condition::Compare {
            comparison: c,
            literal: Some(lit.into()),
            match_case: None,
        })
    }
    /// `lo ≤ x ≤ hi`.
    pub(crate) fn between(lo: &str, hi: &str) -> Constraint {
        unit(Condition::Between {
            lower: Some(lo.into()),
            upper: Some(hi.into()),
        })
    }
    pub(crate) fn or(operands: Vec<Constraint>) -> Constraint {
        unit(Condition::Or { operands })
    }
    pub(crate) fn and(operands: Vec<Constraint>) -> Constraint {
        unit(Condition::And { operands })
    }

    #[test]
    fn between_and_comparisons() {
        let b = between("0", "100");
        assert_eq!(describe(&b), "0 ≤ x ≤ 100");
        assert_eq!(describe(&cmp(Comparison::LessThan, "100")), "x < 100");
    }

    #[test]
    fn enumeration_and_or() {
        let e = or(vec![
            cmp(Comparison::EqualTo, "RGB"),
            cmp(Comparison::EqualTo, "GRAY"),
            cmp(Comparison::EqualTo, "JPEG"),
        ]);
        assert_eq!(describe(&e), "one of: RGB, GRAY, JPEG");
        let o = or(vec![
            cmp(Comparison::LessThanOrEqualTo, "100"),
            cmp(Comparison::GreaterThanOrEqualTo, "200"),
        ]);
        assert_eq!(describe(&o), "x ≤ 100 or x ≥ 200");
    }

    #[test]
    fn the_words_of_a_formula_are_in_the_page_language() {
        let e = or(vec![
            cmp(Comparison::EqualTo, "RGB"),
            cmp(Comparison::EqualTo, "GRAY"),
        ]);
        assert_eq!(describe_in(&e, Lang::Ja), "次のいずれか: RGB, GRAY");
        let o = or(vec![
            cmp(Comparison::LessThanOrEqualTo, "100"),
            and(vec![
                cmp(Comparison::GreaterThanOrEqualTo, "200"),
                cmp(Comparison::NotEqualTo, "300"),
            ]),
        ]);
        assert_eq!(describe(&o), "x ≤ 100 or (x ≥ 200 and x ≠ 300)");
        assert_eq!(
            describe_in(&o, Lang::Ja),
            "x ≤ 100 または (x ≥ 200 かつ x ≠ 300)"
        );
        let n = unit(Condition::Not {
            operand: unit(Condition::IsNull { text: None }),
        });
        assert_eq!(describe_in(&n, Lang::Ja), "null でない");
        let not_or = unit(Condition::Not { operand: o });
        assert_eq!(
            describe_in(&not_or, Lang::Ja),
            "(x ≤ 100 または (x ≥ 200 かつ x ≠ 300)) でない"
        );
    }

    #[test]
    fn not_null_and_range_and() {
        let n = unit(Condition::Not {
            operand: unit(Condition::IsNull { text: None }),
        });
        assert_eq!(describe(&n), "not null");
        let a = and(vec![
            cmp(Comparison::GreaterThan, "0"),
            cmp(Comparison::LessThanOrEqualTo, "10"),
        ]);
        assert_eq!(describe(&a), "0 < x ≤ 10");
    }
}
