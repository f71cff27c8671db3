//! What the code of a component registers, read from its tokens ([`super::lex`]): the spec
//! array, data ports (with their data types from the `InPort<T>` / `OutPort<T>` declarations,
//! or the data object given to `OpenRTM_aist.InPort`), service ports and their interfaces,
//! configuration parameters (with the declared type of their variable) and the lifecycle
//! callbacks the class really defines. Every registration whose name is not a literal is kept
//! as [`Unverified`], never guessed.

use super::lex::{Kind, Language, Tokens};
use super::{
    At, Callback, CodeDataPort, CodeInterface, CodeParameter, CodeServicePort, Direction,
    Implementation, SpecValue, Unverified,
};
use std::collections::BTreeMap;

/// The calls OpenRTM's generated code registers with (their statements are what a generated
/// `onInitialize` holds besides its `return`).
const REGISTRATIONS: &[&str] = &[
    "addInPort",
    "addOutPort",
    "addPort",
    "registerProvider",
    "registerConsumer",
    "bindParameter",
    "registerInPort",
    "registerOutPort",
];

/// The lifecycle callbacks (spec 2.3.4), as the code names them.
pub const CALLBACKS: &[&str] = &[
    "onInitialize",
    "onFinalize",
    "onStartup",
    "onShutdown",
    "onActivated",
    "onDeactivated",
    "onAborting",
    "onError",
    "onReset",
    "onExecute",
    "onStateUpdate",
    "onRateChanged",
    "onAction",
    "onModeChanged",
];

/// A `registerProvider` / `registerConsumer` call: (port variable, instance name, type name,
/// direction, where, the call as written).
pub type InterfaceReg = (
    String,
    Option<String>,
    Option<String>,
    Direction,
    At,
    String,
);
/// A `bindParameter` call: (name, variable, default, where, the call as written).
pub type ParamReg = (Option<String>, String, Option<String>, At, String);

/// What one file gives, before the files of a component are joined.
#[derive(Default)]
pub struct FileFacts {
    pub spec: Option<Vec<SpecValue>>,
    /// (name or None, direction, variable, where, construct when not a literal)
    pub port_regs: Vec<(Option<String>, Direction, String, At, String)>,
    /// variable → data type (`InPort<T> var`, `var = new InPort<T>(…)`, Python chains resolved
    /// at the end)
    pub port_types: BTreeMap<String, String>,
    /// variable → the first string a constructor call or initializer gives it (`m_xPort("x")`,
    /// `CorbaPort("x")`)
    pub ctor_name: BTreeMap<String, String>,
    /// (port variable, instance name, type name, direction, where, construct)
    pub iface_regs: Vec<InterfaceReg>,
    /// (name, variable, default, where, construct)
    pub param_regs: Vec<ParamReg>,
    /// variable → declared type
    pub var_types: BTreeMap<String, String>,
    /// Python: `self.X = …` right-hand sides, as (callee dotted name, first argument text,
    /// second argument's last identifier)
    pub py_assign: BTreeMap<String, (String, String, String)>,
    pub callbacks: Vec<Callback>,
    /// (class name, base names, where)
    pub classes: Vec<(String, Vec<String>, At)>,
    pub macros: Vec<(String, At)>,
}

/// Reads the facts of one file.
pub fn file_facts(t: &Tokens<'_>, lang: Language, file: &str) -> FileFacts {
    let mut f = FileFacts::default();
    let at = |i: usize| At {
        file: file.to_string(),
        pos: t.toks[i].pos,
    };
    let n = t.toks.len();
    for i in 0..n {
        match &t.toks[i].kind {
            Kind::Open(b'{' | b'[') if i > 0 && t.is(i - 1, "=") && f.spec.is_none() => {
                if let Some(spec) = spec_array(t, i, file) {
                    f.spec = Some(spec);
                }
            }
            Kind::Ident => ident(t, i, lang, &mut f, &at),
            _ => {}
        }
    }
    f
}

fn ident(t: &Tokens<'_>, i: usize, lang: Language, f: &mut FileFacts, at: &dyn Fn(usize) -> At) {
    let word = t.src(i);
    let call = t.is_open(i + 1, b'(');
    let prev = if i > 0 { t.src(i - 1) } else { "" };
    // `bool addInPort(const char* name, …)`: a definition, not a call.
    let definition = i > 0
        && t.is_ident(i - 1)
        && !matches!(
            prev,
            "return" | "await" | "else" | "not" | "and" | "or" | "in"
        );
    match word {
        "addInPort" | "addOutPort" | "registerInPort" | "registerOutPort"
            if call && !definition =>
        {
            let args = t.args(i + 1);
            if args.len() >= 2 {
                let dir = if word.contains("In") {
                    Direction::In
                } else {
                    Direction::Out
                };
                let var = last_ident(t, args[1]).unwrap_or_default();
                f.port_regs
                    .push((t.literal(args[0]), dir, var, at(i), call_text(t, i)));
            }
        }
        "registerProvider" | "registerConsumer" if call && !definition => {
            let args = t.args(i + 1);
            let port = if i >= 2 && (t.is(i - 1, ".") || t.is(i - 1, "->")) {
                t.src(i - 2).to_string()
            } else {
                String::new()
            };
            let dir = if word == "registerProvider" {
                Direction::Provided
            } else {
                Direction::Required
            };
            if !args.is_empty() {
                let ty = args.get(1).and_then(|&a| t.literal(a));
                f.iface_regs
                    .push((port, t.literal(args[0]), ty, dir, at(i), call_text(t, i)));
            }
        }
        "bindParameter" if call && !definition => {
            let args = t.args(i + 1);
            if args.len() >= 2 {
                let var = last_ident(t, args[1]).unwrap_or_default();
                let default = args.get(2).and_then(|&a| t.literal(a));
                f.param_regs
                    .push((t.literal(args[0]), var, default, at(i), call_text(t, i)));
            }
        }
        "class" if t.is_ident(i + 1) => class(t, i, lang, f, at),
        w if CALLBACKS.contains(&w) && call => {
            if let Some(cb) = callback(t, i, lang, at) {
                f.callbacks.push(cb);
            }
        }
        w if (w.ends_with("InPort") || w.ends_with("OutPort")) && t.is(i + 1, "<") => {
            if let Some((ty, after)) = template_arg(t, i + 1) {
                // `InPort<T> m_xIn;` / `m_xIn = new InPort<T>(…)`.
                if t.is_ident(after) {
                    f.port_types.insert(t.src(after).to_string(), ty);
                } else if i >= 3 && t.is(i - 1, "new") && t.is(i - 2, "=") && t.is_ident(i - 3) {
                    f.port_types.insert(t.src(i - 3).to_string(), ty);
                }
            }
        }
        _ => {}
    }
    // `m_xPort("x")` in an initializer list; `m_xPort = new CorbaPort("x")`;
    // `self._xPort = OpenRTM_aist.CorbaPort("x")`.
    if call && !CALLBACKS.contains(&word) {
        if let Some(name) = t.args(i + 1).first().and_then(|&a| t.literal(a)) {
            let var = if i >= 1 && (t.is(i - 1, ",") || t.is(i - 1, ":")) {
                Some(word.to_string())
            } else {
                assigned_var(t, i)
            };
            if let Some(v) = var {
                f.ctor_name.entry(v).or_insert(name);
            }
        }
    }
    if lang == Language::Python
        && word == "self"
        && t.is(i + 1, ".")
        && t.is_ident(i + 2)
        && t.is(i + 3, "=")
        && !t.is(i + 4, "=")
    {
        python_assign(t, i, f);
    }
    if lang != Language::Python && (t.is(i + 1, ";") || t.is(i + 1, "=")) && i > 0 {
        if let Some(ty) = declared_type(t, i) {
            f.var_types.entry(word.to_string()).or_insert(ty);
        }
    }
}

/// The text of the call at `i`, shortened, for "could not verify" messages.
fn call_text(t: &Tokens<'_>, i: usize) -> String {
    let end = t
        .close
        .get(i + 1)
        .copied()
        .unwrap_or(i + 1)
        .min(t.toks.len().saturating_sub(1));
    let s = t.span_text(i, end + 1);
    if s.chars().count() > 80 {
        s.chars().take(77).collect::<String>() + "…"
    } else {
        s
    }
}

fn last_ident(t: &Tokens<'_>, (a, b): (usize, usize)) -> Option<String> {
    (a..b)
        .rev()
        .find(|&k| t.is_ident(k) && !matches!(t.src(k), "self" | "this"))
        .map(|k| t.src(k).to_string())
}

/// The variable an expression at `i` is assigned to (`X = new Y(…)`, `self.X = a.Y(…)`).
fn assigned_var(t: &Tokens<'_>, i: usize) -> Option<String> {
    let mut k = i;
    // Back over `a.b.`, `new`, `::` to the `=`.
    while k >= 2 && (t.is(k - 1, ".") || t.is(k - 1, "::")) && t.is_ident(k - 2) {
        k -= 2;
    }
    if k >= 1 && t.is(k - 1, "new") {
        k -= 1;
    }
    (k >= 2 && t.is(k - 1, "=") && t.is_ident(k - 2)).then(|| t.src(k - 2).to_string())
}

/// `<T>` at `lt`: the type as written without spaces, and the index after the `>`.
fn template_arg(t: &Tokens<'_>, lt: usize) -> Option<(String, usize)> {
    let mut depth = 0usize;
    let mut s = String::new();
    for k in lt..t.toks.len().min(lt + 64) {
        match t.src(k) {
            "<" => {
                depth += 1;
                if depth > 1 {
                    s.push('<');
                }
            }
            ">" => {
                depth -= 1;
                if depth == 0 {
                    return Some((s, k + 1));
                }
                s.push('>');
            }
            ";" | "{" | "}" | "(" | ")" => return None,
            x => s.push_str(x),
        }
    }
    None
}

/// The declared type of the variable at `i` (`int m_x;`, `std::vector<double> m_v;`,
/// `IntegerHolder m_x = …`): the type words of its statement before it.
fn declared_type(t: &Tokens<'_>, i: usize) -> Option<String> {
    let mut k = i;
    while k > 0 {
        let p = t.src(k - 1);
        if matches!(p, ";" | "{" | "}" | ":" | ")") || t.toks[k - 1].kind == Kind::Str {
            break;
        }
        if matches!(p, "=" | "(" | "," | "." | "->" | "return" | "[" | "]") {
            return None;
        }
        k -= 1;
        if i - k > 24 {
            return None;
        }
    }
    let words: Vec<&str> = (k..i)
        .map(|j| t.src(j))
        .filter(|w| {
            !matches!(
                *w,
                "static"
                    | "const"
                    | "mutable"
                    | "volatile"
                    | "private"
                    | "protected"
                    | "public"
                    | "final"
                    | "transient"
            )
        })
        .collect();
    if words.is_empty() || !t.is_ident(k) {
        return None;
    }
    Some(words.concat())
}

fn class(t: &Tokens<'_>, i: usize, lang: Language, f: &mut FileFacts, at: &dyn Fn(usize) -> At) {
    let name = t.src(i + 1).to_string();
    let mut bases = Vec::new();
    let mut k = i + 2;
    let end = (k + 64).min(t.toks.len());
    match lang {
        Language::Python if t.is_open(k, b'(') => {
            for a in t.args(k) {
                bases.push(t.span_text(a.0, a.1).replace(' ', ""));
            }
        }
        _ => {
            while k < end && !t.is_open(k, b'{') && !t.is(k, ";") {
                if t.is_ident(k)
                    && !matches!(
                        t.src(k),
                        "public"
                            | "protected"
                            | "private"
                            | "virtual"
                            | "extends"
                            | "implements"
                            | "final"
                    )
                {
                    let mut s = t.src(k).to_string();
                    while (t.is(k + 1, "::") || t.is(k + 1, ".")) && t.is_ident(k + 2) {
                        s.push_str("::");
                        s.push_str(t.src(k + 2));
                        k += 2;
                    }
                    bases.push(s);
                }
                k += 1;
            }
            if !t.is_open(k, b'{') {
                return; // a forward declaration
            }
        }
    }
    f.classes.push((name, bases, at(i)));
}

/// A callback definition at `i` (the name before its parameter list), with whether its body is
/// more than the generated `return RTC::RTC_OK;` and registrations.
fn callback(
    t: &Tokens<'_>,
    i: usize,
    lang: Language,
    at: &dyn Fn(usize) -> At,
) -> Option<Callback> {
    let close = *t.close.get(i + 1)?;
    let (body_start, body_end) = match lang {
        Language::Python => {
            if !(i >= 1 && t.is(i - 1, "def")) {
                return None;
            }
            if !t.is(close + 1, ":") {
                return None;
            }
            let indent = t.toks[i - 1].pos.column;
            let mut e = close + 2;
            while e < t.toks.len()
                && !(t.toks[e].line_start
                    && t.toks[e].pos.column <= indent
                    && t.toks[e].pos.line > t.toks[close].pos.line)
            {
                e += 1;
            }
            (close + 2, e)
        }
        _ => {
            if i >= 1
                && (t.is(i - 1, ".")
                    || t.is(i - 1, "->")
                    || t.is(i - 1, "=")
                    || t.is(i - 1, "return"))
            {
                return None;
            }
            let mut k = close + 1;
            while k < t.toks.len() && k < close + 8 && !t.is_open(k, b'{') {
                if !(t.is_ident(k) || t.is(k, ",") || t.is(k, ".")) {
                    return None; // a declaration (`;`) or a call
                }
                k += 1;
            }
            if !t.is_open(k, b'{') {
                return None;
            }
            (k + 1, *t.close.get(k)?)
        }
    };
    let name = t.src(i).to_string();
    Some(Callback {
        implemented: !generated_body(t, body_start, body_end.min(t.toks.len()), &name),
        name,
        at: at(i),
    })
}

/// Whether a callback body holds only what RTCBuilder generates: `return RTC::RTC_OK;`
/// (`return RTC.RTC_OK`, `return super.onX(ec_id);`), `pass`, a docstring, and registration
/// statements.
fn generated_body(t: &Tokens<'_>, a: usize, b: usize, name: &str) -> bool {
    let mut k = a;
    while k < b {
        if t.is_ident(k) && REGISTRATIONS.contains(&t.src(k)) && t.is_open(k + 1, b'(') {
            k = t.close[k + 1].max(k + 1) + 1;
            continue;
        }
        let ok = match t.toks[k].kind {
            Kind::Ident => {
                let w = t.src(k);
                matches!(
                    w,
                    "return"
                        | "RTC"
                        | "RTC_OK"
                        | "super"
                        | "ReturnCode_t"
                        | "pass"
                        | "self"
                        | "ec_id"
                        | "this"
                        | "m_ec_id"
                ) || w == name
                    || (w.starts_with("m_") && w.ends_with("Port"))
                    || (w.starts_with('_') && w.ends_with("Port"))
            }
            // A Python docstring.
            Kind::Str => t.toks[k].line_start,
            Kind::Punct => matches!(t.src(k), "::" | "." | ";" | "->"),
            Kind::Open(b'(') | Kind::Close(b')') => true,
            _ => false,
        };
        if !ok {
            return false;
        }
        k += 1;
    }
    true
}

/// `self.X = callee(first, …, second)` on one logical line.
fn python_assign(t: &Tokens<'_>, i: usize, f: &mut FileFacts) {
    let var = t.src(i + 2).to_string();
    let mut k = i + 4;
    let mut callee = String::new();
    while t.is_ident(k) {
        callee.push_str(t.src(k));
        if t.is(k + 1, ".") && t.is_ident(k + 2) {
            callee.push('.');
            k += 2;
        } else {
            break;
        }
    }
    if callee.is_empty() {
        // `self._p = [0]` (a configuration variable): its literal's type.
        if let Some(ty) = python_literal_type(t, k) {
            f.var_types.entry(var).or_insert(ty.to_string());
        }
        return;
    }
    if !t.is_open(k + 1, b'(') {
        return;
    }
    let args = t.args(k + 1);
    let first = args
        .first()
        .map(|&(a, b)| t.span_text(a, b))
        .unwrap_or_default();
    let second = args
        .get(1)
        .and_then(|&a| last_ident(t, a))
        .unwrap_or_default();
    f.py_assign.entry(var).or_insert((callee, first, second));
}

fn python_literal_type(t: &Tokens<'_>, k: usize) -> Option<&'static str> {
    // `[0]`, `[0.5]`, `["x"]`, `[[…]]`
    if !t.is_open(k, b'[') {
        return None;
    }
    let v = k + 1;
    let neg = usize::from(t.is(v, "-"));
    match &t.tok(v + neg)?.kind {
        Kind::Number => Some(if t.src(v + neg).contains(['.', 'e']) {
            "float"
        } else {
            "int"
        }),
        Kind::Str => Some("string"),
        Kind::Open(b'[') => Some("vector"),
        Kind::Ident if matches!(t.src(v), "True" | "False") => Some("bool"),
        _ => None,
    }
}

/// A spec array whose first value is `"implementation_id"`: its key/value pairs.
fn spec_array(t: &Tokens<'_>, open: usize, file: &str) -> Option<Vec<SpecValue>> {
    let args = t.args(open);
    if t.literal(*args.first()?).as_deref() != Some("implementation_id") {
        return None;
    }
    let mut out = Vec::new();
    let mut it = args.chunks(2);
    for pair in it.by_ref() {
        let key = t.literal(pair[0]);
        let Some(key) = key else {
            out.push(SpecValue {
                key: t.span_text(pair[0].0, pair[0].1),
                value: None,
                unresolved: Some(t.span_text(pair[0].0, pair[0].1)),
                at: At {
                    file: file.into(),
                    pos: t.toks[pair[0].0.min(t.toks.len() - 1)].pos,
                },
            });
            continue;
        };
        if key.is_empty() {
            break; // the terminating ""
        }
        let Some(&v) = pair.get(1) else { break };
        let value = t.literal(v);
        let pos = t.toks.get(v.0).map_or(t.toks[pair[0].0].pos, |x| x.pos);
        out.push(SpecValue {
            unresolved: value.is_none().then(|| t.span_text(v.0, v.1)),
            key,
            value,
            at: At {
                file: file.into(),
                pos,
            },
        });
    }
    Some(out)
}

/// Joins the facts of a component's files into its implementation.
pub fn join(lang: Language, files: Vec<String>, facts: Vec<FileFacts>) -> Implementation {
    let mut port_types = BTreeMap::new();
    let mut ctor_name = BTreeMap::new();
    let mut var_types = BTreeMap::new();
    let mut py_assign = BTreeMap::new();
    let mut imp = Implementation {
        language: lang,
        files,
        ..Default::default()
    };
    let mut port_regs = Vec::new();
    let mut iface_regs = Vec::new();
    let mut param_regs = Vec::new();
    for f in facts {
        if imp.spec.is_empty() {
            if let Some(s) = f.spec {
                imp.spec = s;
            }
        }
        port_types.extend(f.port_types);
        for (k, v) in f.ctor_name {
            ctor_name.entry(k).or_insert(v);
        }
        for (k, v) in f.var_types {
            var_types.entry(k).or_insert(v);
        }
        py_assign.extend(f.py_assign);
        port_regs.extend(f.port_regs);
        iface_regs.extend(f.iface_regs);
        param_regs.extend(f.param_regs);
        for cb in f.callbacks {
            // A header's inline stub and the .cpp definition: the definition with a body wins.
            match imp
                .callbacks
                .iter_mut()
                .find(|c: &&mut Callback| c.name == cb.name)
            {
                Some(c) if cb.implemented && !c.implemented => *c = cb,
                Some(_) => {}
                None => imp.callbacks.push(cb),
            }
        }
        if imp.class.is_none() {
            imp.class = f
                .classes
                .into_iter()
                .find(|(_, bases, _)| !bases.is_empty())
                .map(|(name, bases, at)| super::CodeClass { name, bases, at });
        }
        imp.unverified
            .extend(f.macros.into_iter().map(|(m, at)| Unverified {
                construct: m,
                what: "registrations inside a macro".into(),
                of: super::Unread::Any,
                at,
            }));
    }
    let py_type = |var: &str| -> Option<String> {
        // self._xIn = OpenRTM_aist.InPort("x", self._d_x); self._d_x = RTC.TimedLong(…) or
        // OpenRTM_aist.instantiateDataType(RTC.TimedLong)
        let (_, _, data) = py_assign.get(var)?;
        let (callee, first, _) = py_assign.get(data)?;
        let ty = if callee.ends_with("instantiateDataType") {
            first.replace(' ', "")
        } else {
            callee.clone()
        };
        Some(ty.replace('.', "::"))
    };
    for (name, direction, var, at, construct) in port_regs {
        let data_type = port_types.get(&var).cloned().or_else(|| py_type(&var));
        match name {
            Some(name) => imp.data_ports.push(CodeDataPort {
                name,
                direction,
                variable: var,
                data_type,
                at,
            }),
            None => imp.unverified.push(Unverified {
                construct,
                what: "a data port whose name is not a literal".into(),
                of: super::Unread::DataPort,
                at,
            }),
        }
    }
    for (port, instance, ty, direction, at, construct) in iface_regs {
        let Some(instance) = instance else {
            imp.unverified.push(Unverified {
                construct,
                what: "a service interface whose name is not a literal".into(),
                of: super::Unread::ServicePort,
                at,
            });
            continue;
        };
        let pname = ctor_name.get(&port).cloned();
        let idx = match imp.service_ports.iter().position(|p| p.variable == port) {
            Some(k) => k,
            None => {
                if pname.is_none() {
                    imp.unverified.push(Unverified {
                        construct: port.clone(),
                        what: "a service port whose name is not given by a literal".into(),
                        of: super::Unread::ServicePort,
                        at: at.clone(),
                    });
                }
                imp.service_ports.push(CodeServicePort {
                    name: pname,
                    variable: port.clone(),
                    interfaces: Vec::new(),
                    at: at.clone(),
                });
                imp.service_ports.len() - 1
            }
        };
        imp.service_ports[idx].interfaces.push(CodeInterface {
            instance_name: instance,
            type_name: ty,
            direction,
            at,
        });
    }
    for (name, var, default, at, construct) in param_regs {
        let type_ = var_types.get(&var).cloned();
        match name {
            Some(name) => imp.parameters.push(CodeParameter {
                name,
                variable: var,
                type_,
                default,
                at,
            }),
            None => imp.unverified.push(Unverified {
                construct,
                what: "a configuration parameter whose name is not a literal".into(),
                of: super::Unread::Parameter,
                at,
            }),
        }
    }
    for s in &imp.spec {
        if let Some(u) = &s.unresolved {
            imp.unverified.push(Unverified {
                construct: u.clone(),
                what: format!("the spec array's value of `{}`", s.key),
                of: super::Unread::SpecValue,
                at: s.at.clone(),
            });
        }
    }
    imp
}
