//! Where a component's code and its profile disagree. Each [`Drift`] names the element, what
//! the profile says, what the code says and where both say it; the check reports them as
//! RTC801–RTC809 and the component page lists them.
//!
//! Never a false alarm: what the code registers through a name that is not a literal, a macro
//! or a base class is "could not verify" (RTC810), and then nothing of that kind is reported as
//! missing from the code.

use super::extract::CALLBACKS;
use super::{At, Implementation};
use crate::model::{ActionKind, Pos, Profile};
use serde::{Deserialize, Serialize};

pub mod codes {
    pub const ONLY_IN_PROFILE: &str = "RTC801";
    pub const ONLY_IN_CODE: &str = "RTC802";
    pub const NAME_CASE: &str = "RTC803";
    pub const DATA_TYPE: &str = "RTC804";
    pub const DIRECTION: &str = "RTC805";
    pub const DEFAULT: &str = "RTC806";
    pub const CALLBACK_UNMARKED: &str = "RTC807";
    pub const CALLBACK_MISSING: &str = "RTC808";
    pub const SPEC_VALUE: &str = "RTC809";
    pub const UNVERIFIED: &str = "RTC810";
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum DriftKind {
    OnlyInProfile,
    OnlyInCode,
    NameCase,
    DataType,
    Direction,
    Default,
    CallbackUnmarked,
    CallbackMissing,
    SpecValue,
}

impl DriftKind {
    pub fn code(self) -> &'static str {
        match self {
            DriftKind::OnlyInProfile => codes::ONLY_IN_PROFILE,
            DriftKind::OnlyInCode => codes::ONLY_IN_CODE,
            DriftKind::NameCase => codes::NAME_CASE,
            DriftKind::DataType => codes::DATA_TYPE,
            DriftKind::Direction => codes::DIRECTION,
            DriftKind::Default => codes::DEFAULT,
            DriftKind::CallbackUnmarked => codes::CALLBACK_UNMARKED,
            DriftKind::CallbackMissing => codes::CALLBACK_MISSING,
            DriftKind::SpecValue => codes::SPEC_VALUE,
        }
    }
}

/// One difference between the profile and the code.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Drift {
    pub kind: DriftKind,
    /// What differs, as a path of the profile (`dataPorts/in`, `basicInfo/version`,
    /// `actions/onActivated`, `configurationSet/gain/defaultValue`).
    pub element: String,
    /// What the profile says (`None`: it has no such element).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<String>,
    /// What the code says (`None`: it has no such registration).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub code: Option<String>,
    /// Where the code says it (`None`: the code has nothing there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<At>,
    /// Where the profile says it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile_pos: Option<Pos>,
}

struct Acc {
    out: Vec<Drift>,
}

impl Acc {
    fn push(
        &mut self,
        kind: DriftKind,
        element: String,
        profile: Option<String>,
        code: Option<String>,
        at: Option<At>,
        profile_pos: Option<Pos>,
    ) {
        self.out.push(Drift {
            kind,
            element,
            profile,
            code,
            at,
            profile_pos: profile_pos.filter(|p| p.line > 0),
        });
    }
}

/// Whether a value of the code and one of the profile say the same: equal as text (spaces at
/// the ends ignored), equal as numbers (`0.0` and `0.00`), or equal once the backslashes a
/// profile value pasted into a literal doubled are read as written (`host\\Comp0`), or equal
/// but for the quotes around the profile's (`"debug"`: RTCBuilder pastes a default into the
/// code's string literal as typed, so its quotes can only be the literal's own — `""debug""`
/// does not compile, `"debug"` is what the code says).
fn same_value(code: &str, profile: &str) -> bool {
    let (c, p) = (code.trim(), profile.trim());
    if c == p || c == p.replace("\\\\", "\\") {
        return true;
    }
    let unquoted = p
        .strip_prefix('"')
        .and_then(|r| r.strip_suffix('"'))
        .filter(|inner| !inner.contains('"'));
    if unquoted.is_some_and(|u| u.trim() == c) {
        return true;
    }
    matches!((c.parse::<f64>(), p.parse::<f64>()), (Ok(a), Ok(b)) if a == b)
}

/// A type name as comparable text: `IDL:RTC/TimedLong:1.0` and `RTC.TimedLong` as
/// `RTC::TimedLong`, no spaces.
pub fn type_key(t: &str) -> String {
    let t = t.trim();
    let t = t
        .strip_prefix("IDL:")
        .map(|r| r.rsplit_once(':').map_or(r, |(a, _)| a).replace('/', "::"))
        .unwrap_or_else(|| t.to_string());
    t.replace('.', "::").replace(' ', "")
}

/// Whether two type names name the same type: equal, or equal in their last segment when one
/// of them is written without its module (`TimedLong` under `using namespace RTC`, Java's
/// imports).
pub fn same_type(a: &str, b: &str) -> bool {
    let (a, b) = (type_key(a), type_key(b));
    if a == b {
        return true;
    }
    let last = |s: &str| s.rsplit("::").next().unwrap_or(s).to_string();
    (!a.contains("::") || !b.contains("::")) && last(&a) == last(&b)
}

/// A configuration type's family, for comparing a profile's `type` with a variable's declared
/// type: `None` when either is not a plain scalar (then nothing is compared).
fn type_family(t: &str) -> Option<&'static str> {
    let t = t.trim().trim_start_matches("std::").replace(' ', "");
    Some(match t.as_str() {
        "short" | "int" | "long" | "longlong" | "unsignedshort" | "unsignedint"
        | "unsignedlong" | "unsignedlonglong" | "unsigned" | "signed" | "shortint" | "longint"
        | "longlongint" | "unsignedlongint" | "unsignedshortint" | "int8_t" | "uint8_t"
        | "int16_t" | "int32_t" | "int64_t" | "uint16_t" | "uint32_t" | "uint64_t" | "Integer"
        | "IntegerHolder" | "ShortHolder" | "LongHolder" | "size_t" => "integer",
        "float" | "double" | "longdouble" | "FloatHolder" | "DoubleHolder" | "Double" | "Float" => {
            "real"
        }
        "string" | "String" | "StringHolder" | "str" => "string",
        "bool" | "boolean" | "Boolean" | "BooleanHolder" => "bool",
        "char" | "CharHolder" | "Character" => "char",
        _ => return None,
    })
}

/// Python parameter literals (`[0]`) carry a value type, not a declared type: an `int` literal
/// may stand for a `double` parameter (`[0]` for `0.0`).
fn python_family(t: &str) -> Option<&'static str> {
    match t {
        "string" => Some("string"),
        _ => None,
    }
}

fn text(s: &Option<crate::model::Text>) -> Option<&str> {
    s.as_deref().map(str::trim)
}

/// Compares `imp` with `profile`.
pub fn compare(profile: &Profile, imp: &Implementation) -> Vec<Drift> {
    let mut acc = Acc { out: Vec::new() };
    // A kind the code registers nothing of (ports made by helper objects, a base class, another
    // file), or some of through a name or macro that cannot be read, is not reported missing.
    use super::Unread;
    data_ports(profile, imp, &mut acc, imp.reads_all(Unread::DataPort));
    service_ports(profile, imp, &mut acc, imp.reads_all(Unread::ServicePort));
    parameters(profile, imp, &mut acc, imp.reads_all(Unread::Parameter));
    callbacks(profile, imp, &mut acc);
    spec(profile, imp, &mut acc);
    acc.out
}

/// Pairs profile names with code names: exact first, then equal but for case.
/// Profile and code names paired: exact pairs, pairs equal but for case, the profile's
/// unpaired, the code's unpaired.
type Pairing = (
    Vec<(usize, usize)>,
    Vec<(usize, usize)>,
    Vec<usize>,
    Vec<usize>,
);

fn pair(profile: &[&str], code: &[&str]) -> Pairing {
    let mut exact = Vec::new();
    let mut case = Vec::new();
    let mut used_c = vec![false; code.len()];
    let mut used_p = vec![false; profile.len()];
    for (pi, p) in profile.iter().enumerate() {
        if let Some(ci) = code
            .iter()
            .enumerate()
            .position(|(ci, c)| !used_c[ci] && c == p)
        {
            used_c[ci] = true;
            used_p[pi] = true;
            exact.push((pi, ci));
        }
    }
    for (pi, p) in profile.iter().enumerate() {
        if used_p[pi] {
            continue;
        }
        if let Some(ci) = code
            .iter()
            .enumerate()
            .position(|(ci, c)| !used_c[ci] && c.eq_ignore_ascii_case(p))
        {
            used_c[ci] = true;
            used_p[pi] = true;
            case.push((pi, ci));
        }
    }
    // A second declaration of a name already paired (a profile declaring a configuration
    // twice, reported by the profile check) is no element the other side lacks.
    let paired = |names: &[&str], used: &[bool], i: usize| {
        (0..names.len()).any(|j| j != i && used[j] && names[j] == names[i])
    };
    let only_p = (0..profile.len())
        .filter(|&i| !used_p[i] && !paired(profile, &used_p, i))
        .collect();
    let only_c = (0..code.len())
        .filter(|&i| !used_c[i] && !paired(code, &used_c, i))
        .collect();
    (exact, case, only_p, only_c)
}

fn data_ports(profile: &Profile, imp: &Implementation, acc: &mut Acc, complete: bool) {
    let pnames: Vec<&str> = profile
        .data_ports
        .iter()
        .map(|p| text(&p.name).unwrap_or(""))
        .collect();
    let cnames: Vec<&str> = imp.data_ports.iter().map(|p| p.name.as_str()).collect();
    let (exact, case, only_p, only_c) = pair(&pnames, &cnames);
    for &(pi, ci) in exact.iter().chain(&case) {
        let (p, c) = (&profile.data_ports[pi], &imp.data_ports[ci]);
        let el = format!("dataPorts/{}", pnames[pi]);
        if pnames[pi] != cnames[ci] {
            acc.push(
                DriftKind::NameCase,
                el.clone(),
                Some(pnames[pi].into()),
                Some(cnames[ci].into()),
                Some(c.at.clone()),
                Some(p.pos),
            );
        }
        let pdir = text(&p.port_type).unwrap_or("");
        let cdir = c.direction.profile_word();
        if !pdir.is_empty()
            && !pdir.eq_ignore_ascii_case(cdir)
            && matches!(pdir, "DataInPort" | "DataOutPort")
        {
            acc.push(
                DriftKind::Direction,
                el.clone(),
                Some(pdir.into()),
                Some(cdir.into()),
                Some(c.at.clone()),
                Some(p.pos),
            );
        }
        if let (Some(pt), Some(ct)) = (
            text(&p.type_).filter(|t| !t.is_empty()),
            c.data_type.as_deref(),
        ) {
            if !same_type(pt, ct) {
                acc.push(
                    DriftKind::DataType,
                    format!("{el}/type"),
                    Some(pt.into()),
                    Some(ct.into()),
                    Some(c.at.clone()),
                    Some(p.pos),
                );
            }
        }
    }
    if complete {
        for pi in only_p {
            let p = &profile.data_ports[pi];
            acc.push(
                DriftKind::OnlyInProfile,
                format!("dataPorts/{}", pnames[pi]),
                Some(text(&p.port_type).unwrap_or("").to_string()),
                None,
                None,
                Some(p.pos),
            );
        }
    }
    for ci in only_c {
        let c = &imp.data_ports[ci];
        acc.push(
            DriftKind::OnlyInCode,
            format!("dataPorts/{}", c.name),
            None,
            Some(c.direction.profile_word().into()),
            Some(c.at.clone()),
            None,
        );
    }
}

/// The drift of service interface `iel` paired by name (`names`: the profile's, the code's):
/// the name's case, the direction, the type.
fn interface(
    acc: &mut Acc,
    iel: String,
    (pi_, ci_): (&crate::model::ServiceInterface, &super::CodeInterface),
    (pname, cname): (&str, &str),
) {
    if pname != cname {
        acc.push(
            DriftKind::NameCase,
            iel.clone(),
            Some(pname.into()),
            Some(cname.into()),
            Some(ci_.at.clone()),
            Some(pi_.pos),
        );
    }
    let pdir = text(&pi_.direction).unwrap_or("");
    let cdir = ci_.direction.profile_word();
    if matches!(pdir, "Provided" | "Required") && pdir != cdir {
        acc.push(
            DriftKind::Direction,
            iel.clone(),
            Some(pdir.into()),
            Some(cdir.into()),
            Some(ci_.at.clone()),
            Some(pi_.pos),
        );
    }
    if let (Some(pt), Some(ct)) = (
        text(&pi_.type_).filter(|t| !t.is_empty()),
        ci_.type_name.as_deref().filter(|t| !t.is_empty()),
    ) {
        if !same_type(pt, ct) {
            acc.push(
                DriftKind::DataType,
                format!("{iel}/type"),
                Some(pt.into()),
                Some(ct.into()),
                Some(ci_.at.clone()),
                Some(pi_.pos),
            );
        }
    }
}

fn service_ports(profile: &Profile, imp: &Implementation, acc: &mut Acc, complete: bool) {
    let pnames: Vec<&str> = profile
        .service_ports
        .iter()
        .map(|p| text(&p.name).unwrap_or(""))
        .collect();
    let named: Vec<(usize, &str)> = imp
        .service_ports
        .iter()
        .enumerate()
        .filter_map(|(i, p)| p.name.as_deref().map(|n| (i, n)))
        .collect();
    let cnames: Vec<&str> = named.iter().map(|(_, n)| *n).collect();
    let (exact, case, only_p, only_c) = pair(&pnames, &cnames);
    for &(pi, ci) in exact.iter().chain(&case) {
        let (p, c) = (&profile.service_ports[pi], &imp.service_ports[named[ci].0]);
        let el = format!("servicePorts/{}", pnames[pi]);
        if pnames[pi] != cnames[ci] {
            acc.push(
                DriftKind::NameCase,
                el.clone(),
                Some(pnames[pi].into()),
                Some(cnames[ci].into()),
                Some(c.at.clone()),
                Some(p.pos),
            );
        }
        let inames: Vec<&str> = p
            .interfaces
            .iter()
            .map(|i| text(&i.name).unwrap_or(""))
            .collect();
        let cinames: Vec<&str> = c
            .interfaces
            .iter()
            .map(|i| i.instance_name.as_str())
            .collect();
        let (iexact, icase, ionly_p, ionly_c) = pair(&inames, &cinames);
        for &(a, b) in iexact.iter().chain(&icase) {
            let iel = format!("{el}/{}", inames[a]);
            let names = (inames[a], cinames[b]);
            interface(acc, iel, (&p.interfaces[a], &c.interfaces[b]), names);
        }
        for a in ionly_p {
            let i = &p.interfaces[a];
            acc.push(
                DriftKind::OnlyInProfile,
                format!("{el}/{}", inames[a]),
                Some(text(&i.direction).unwrap_or("").to_string()),
                None,
                Some(c.at.clone()),
                Some(i.pos),
            );
        }
        for b in ionly_c {
            let i = &c.interfaces[b];
            acc.push(
                DriftKind::OnlyInCode,
                format!("{el}/{}", cinames[b]),
                None,
                Some(i.direction.profile_word().into()),
                Some(i.at.clone()),
                Some(p.pos),
            );
        }
    }
    if complete {
        for pi in only_p {
            let p = &profile.service_ports[pi];
            acc.push(
                DriftKind::OnlyInProfile,
                format!("servicePorts/{}", pnames[pi]),
                Some("service port".into()),
                None,
                None,
                Some(p.pos),
            );
        }
    }
    for ci in only_c {
        let c = &imp.service_ports[named[ci].0];
        acc.push(
            DriftKind::OnlyInCode,
            format!("servicePorts/{}", cnames[ci]),
            None,
            Some("service port".into()),
            Some(c.at.clone()),
            None,
        );
    }
}

fn parameters(profile: &Profile, imp: &Implementation, acc: &mut Acc, complete: bool) {
    let confs = profile.configurations();
    let pnames: Vec<&str> = confs.iter().map(|p| text(&p.name).unwrap_or("")).collect();
    let cnames: Vec<&str> = imp.parameters.iter().map(|p| p.name.as_str()).collect();
    let (exact, case, only_p, only_c) = pair(&pnames, &cnames);
    for &(pi, ci) in exact.iter().chain(&case) {
        let (p, c) = (&confs[pi], &imp.parameters[ci]);
        let el = format!("configurationSet/{}", pnames[pi]);
        if pnames[pi] != cnames[ci] {
            acc.push(
                DriftKind::NameCase,
                el.clone(),
                Some(pnames[pi].into()),
                Some(cnames[ci].into()),
                Some(c.at.clone()),
                Some(p.pos),
            );
        }
        if let (Some(pd), Some(cd)) = (text(&p.default_value), c.default.as_deref()) {
            if !same_value(cd, pd) {
                acc.push(
                    DriftKind::Default,
                    format!("{el}/defaultValue"),
                    Some(pd.into()),
                    Some(cd.into()),
                    Some(c.at.clone()),
                    Some(p.pos),
                );
            }
        }
        if let (Some(pt), Some(ct)) = (text(&p.type_), c.type_.as_deref()) {
            let cf = if imp.language == super::Language::Python {
                python_family(ct)
            } else {
                type_family(ct)
            };
            if let (Some(a), Some(b)) = (type_family(pt), cf) {
                if a != b && !(imp.language == super::Language::Python && a == "char") {
                    acc.push(
                        DriftKind::DataType,
                        format!("{el}/type"),
                        Some(pt.into()),
                        Some(ct.into()),
                        Some(c.at.clone()),
                        Some(p.pos),
                    );
                }
            }
        }
    }
    if complete {
        for pi in only_p {
            let p = &confs[pi];
            acc.push(
                DriftKind::OnlyInProfile,
                format!("configurationSet/{}", pnames[pi]),
                text(&p.default_value).map(|d| format!("default {d}")),
                None,
                None,
                Some(p.pos),
            );
        }
    }
    for ci in only_c {
        let c = &imp.parameters[ci];
        acc.push(
            DriftKind::OnlyInCode,
            format!("configurationSet/{}", c.name),
            None,
            c.default.as_ref().map(|d| format!("default {d}")),
            Some(c.at.clone()),
            None,
        );
    }
}

fn callbacks(profile: &Profile, imp: &Implementation, acc: &mut Acc) {
    // onAction (a state machine's) and onModeChanged (a multi-mode component's) are no
    // callbacks of a data-flow component: RTCBuilder generates neither for one, even when its
    // profile marks every action implemented, so their mark says nothing of its code.
    let kind_words = text(&profile.basic_info.component_kind).unwrap_or("");
    let fsm_or_modes = ["fsm", "multimode", "statemachine"]
        .iter()
        .any(|w| kind_words.to_ascii_lowercase().contains(w));
    // A base class not read may define any callback; files that define none at all (a
    // library header matched by name) say nothing of which ones the component defines.
    let base_unread =
        imp.callbacks.is_empty() || imp.unverified.iter().any(|u| u.of == super::Unread::Base);
    for (k, name) in CALLBACKS.iter().enumerate() {
        let kind = ActionKind::ALL.get(k).copied();
        let Some(kind) = kind else { continue };
        if matches!(*name, "onAction" | "onModeChanged") && !fsm_or_modes {
            continue;
        }
        let action = profile.actions.iter().find(|a| a.kind == kind);
        // An action the profile does not list says nothing.
        let Some(action) = action.filter(|a| a.implemented.is_some()) else {
            continue;
        };
        let marked = action.is_implemented();
        let code = imp.callbacks.iter().find(|c| c.name == *name);
        let el = format!("actions/{name}");
        match code {
            Some(c) if c.implemented && !marked => acc.push(
                DriftKind::CallbackUnmarked,
                el,
                Some("implemented=\"false\"".into()),
                Some("implemented".into()),
                Some(c.at.clone()),
                Some(action.pos),
            ),
            // The generated stub of an action marked implemented, or a real body: as marked.
            Some(_) => {}
            // onInitialize is the base class's when the class does not define it; RTCBuilder
            // always generates it, so only a missing definition of another action is drift.
            None if marked && *name != "onInitialize" && !base_unread => acc.push(
                DriftKind::CallbackMissing,
                el,
                Some("implemented=\"true\"".into()),
                None,
                None,
                Some(action.pos),
            ),
            None => {}
        }
    }
}

/// The spec array's keys that are values of the profile's BasicInfo (and its language), with
/// the element findings and recovered profiles name each by.
const SPEC_ELEMENTS: &[(&str, &str)] = &[
    ("implementation_id", "basicInfo/name"),
    ("version", "basicInfo/version"),
    ("vendor", "basicInfo/vendor"),
    ("category", "basicInfo/category"),
    ("activity_type", "basicInfo/activityType"),
    ("max_instance", "basicInfo/maxInstances"),
    ("kind", "basicInfo/componentKind"),
    ("description", "basicInfo/description"),
    ("language", "language/kind"),
];

/// The profile element the spec array's `key` is, when it is one of BasicInfo's.
pub fn spec_element(key: &str) -> Option<&'static str> {
    SPEC_ELEMENTS
        .iter()
        .find(|(k, _)| *k == key)
        .map(|(_, e)| *e)
}

fn spec(profile: &Profile, imp: &Implementation, acc: &mut Acc) {
    let b = &profile.basic_info;
    let lang = profile.language.as_ref().and_then(|l| text(&l.kind));
    // The keys compared, with the profile's value and its field (for the position).
    let pairs: [(&str, Option<&str>, crate::model::fields::Field); 7] = {
        use crate::model::fields::Field as F;
        [
            ("implementation_id", text(&b.name), F::BasicName),
            ("version", text(&b.version), F::BasicVersion),
            ("vendor", text(&b.vendor), F::BasicVendor),
            ("category", text(&b.category), F::BasicCategory),
            (
                "activity_type",
                text(&b.activity_type),
                F::BasicActivityType,
            ),
            ("max_instance", text(&b.max_instances), F::BasicMaxInstances),
            ("language", lang, F::BasicName),
        ]
    };
    for (key, pval, field) in pairs {
        let el = spec_element(key).unwrap_or(key);
        let (Some(s), Some(pv)) = (imp.spec_value(key), pval.filter(|v| !v.is_empty())) else {
            continue;
        };
        let Some(cv) = s.value.as_deref() else {
            continue;
        };
        let same = match key {
            "language" => cv.trim().eq_ignore_ascii_case(pv),
            // RTCBuilder's Python and Java generators write componentType (`STATIC`) there,
            // older templates the component kind (`DataFlowComponent`).
            "activity_type" => [Some(pv), text(&b.component_type), text(&b.component_kind)]
                .into_iter()
                .flatten()
                .any(|v| cv.trim().eq_ignore_ascii_case(v)),
            "max_instance" => same_value(cv, pv),
            _ => cv.trim() == pv,
        };
        if !same {
            let ppos = if key == "language" {
                profile.language.as_ref().map(|l| l.pos)
            } else {
                b.attr_pos.field(field).or(Some(b.pos))
            };
            acc.push(
                DriftKind::SpecValue,
                el.to_string(),
                Some(pv.into()),
                Some(format!("{key} = {cv}")),
                Some(s.at.clone()),
                ppos,
            );
        }
    }
    // conf.default.X against the parameter's default; conf.__widget__.X against its widget;
    // conf.__type__.X against its type.
    for c in profile.configurations() {
        let Some(name) = text(&c.name) else { continue };
        let checks = [
            (
                format!("conf.default.{name}"),
                text(&c.default_value),
                "defaultValue",
                DriftKind::Default,
            ),
            (
                format!("conf.__widget__.{name}"),
                c.widget().map(str::trim),
                "widget",
                DriftKind::SpecValue,
            ),
            (
                format!("conf.__type__.{name}"),
                text(&c.type_),
                "type",
                DriftKind::SpecValue,
            ),
        ];
        for (key, pv, what, kind) in checks {
            let (Some(s), Some(pv)) = (imp.spec_value(&key), pv) else {
                continue;
            };
            let Some(cv) = s.value.as_deref() else {
                continue;
            };
            // RTCBuilder stores a widget with its step: `spin.` is `spin` with none.
            let pv = if what == "widget" {
                pv.trim_end_matches('.')
            } else {
                pv
            };
            if !same_value(cv, pv) {
                acc.push(
                    kind,
                    format!("configurationSet/{name}/{what}"),
                    Some(pv.into()),
                    Some(format!("{key} = {cv}")),
                    Some(s.at.clone()),
                    Some(c.pos),
                );
            }
        }
    }
}
