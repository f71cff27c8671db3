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
    /// variable → the direction of the port class it is (`InPort<T> m_x`): what the running
    /// port is, whichever of addInPort / addOutPort registers it
    pub port_dirs: BTreeMap<String, Direction>,
    /// variable → the first string a constructor call or initializer gives it (`m_xPort("x")`,
    /// `CorbaPort("x")`)
    pub ctor_name: BTreeMap<String, String>,
    /// Variables a constructor call or initializer gives a name that is not a literal
    /// (`m_xIn(name.c_str(), m_x)`): the port's name is not known.
    pub ctor_unread: std::collections::BTreeSet<String>,
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
    /// Python: the modules a name may come from (`from M import *`, `from M import B`,
    /// `import M`), as (module, the names imported; `*` for all, empty for `import M`).
    pub imports: Vec<(String, Vec<String>)>,
    /// C++: the files `#include "…"` names (set by [`super::read`], which sees the lines).
    pub includes: Vec<String>,
    /// Read because it defines a base class of the component's class, not as one of the
    /// component's own files.
    pub base_file: bool,
}

/// Reads the facts of one file.
pub fn file_facts(t: &Tokens<'_>, lang: Language, file: &str) -> FileFacts {
    let mut f = FileFacts::default();
    let shared: std::sync::Arc<str> = file.into();
    let at = |i: usize| At {
        file: shared.clone(),
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
        "class" if t.is_ident(i + 1) && !t.is(i.wrapping_sub(1), "enum") => {
            class(t, i, lang, f, at);
        }
        w if CALLBACKS.contains(&w) && call => {
            if let Some(cb) = callback(t, i, lang, at) {
                f.callbacks.push(cb);
            }
        }
        w if (w.ends_with("InPort") || w.ends_with("OutPort")) && t.is(i + 1, "<") => {
            let dir = if w.ends_with("InPort") {
                Direction::In
            } else {
                Direction::Out
            };
            if let Some((ty, after)) = template_arg(t, i + 1) {
                // `InPort<T> m_xIn;` / `m_xIn = new InPort<T>(…)`.
                if t.is_ident(after) {
                    // `OutPort<T> m_aOut, m_bOut;`: every declarator is such a port.
                    for v in std::iter::once(after).chain(declarators_after(t, after)) {
                        f.port_dirs.insert(t.src(v).to_string(), dir);
                        f.port_types.insert(t.src(v).to_string(), ty.clone());
                    }
                } else if i >= 3 && t.is(i - 1, "new") && t.is(i - 2, "=") && t.is_ident(i - 3) {
                    let var = t.src(i - 3).to_string();
                    // `m_xIn = new InPort<T>("x", m_x)`: the name the port runs under.
                    if let Some(&first) = t
                        .is_open(after, b'(')
                        .then(|| t.args(after))
                        .as_ref()
                        .and_then(|a| a.first())
                    {
                        match t.literal(first) {
                            Some(name) => {
                                f.ctor_name.entry(var.clone()).or_insert(name);
                            }
                            None => {
                                f.ctor_unread.insert(var.clone());
                            }
                        }
                    }
                    f.port_dirs.insert(var.clone(), dir);
                    f.port_types.insert(var, ty);
                }
            }
        }
        _ => {}
    }
    // `m_xPort("x")` in an initializer list; `m_xPort = new CorbaPort("x")`;
    // `self._xPort = OpenRTM_aist.CorbaPort("x")`.
    if call && !CALLBACKS.contains(&word) {
        if let Some(&first) = t.args(i + 1).first() {
            let var = if i >= 1 && (t.is(i - 1, ",") || t.is(i - 1, ":")) {
                Some(word.to_string())
            } else {
                assigned_var(t, i)
            };
            match (var, t.literal(first)) {
                (Some(v), Some(name)) => {
                    f.ctor_name.entry(v).or_insert(name);
                }
                (Some(v), None) => {
                    f.ctor_unread.insert(v);
                }
                _ => {}
            }
        }
    }
    if lang == Language::Python && (word == "from" || word == "import") && t.toks[i].line_start {
        python_import(t, i, f);
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
    if lang != Language::Python
        && (t.is(i + 1, ";") || t.is(i + 1, "=") || t.is(i + 1, ","))
        && i > 0
    {
        // Before a `,` the words may be a template's first argument (`std::map<int, T>`),
        // no declaration: only a type whose brackets close is one.
        let ty = declared_type(t, i)
            .filter(|ty| !t.is(i + 1, ",") || ty.matches('<').count() == ty.matches('>').count());
        if let Some(ty) = ty {
            // `int a, b;`, `double a = 1.0, b;`: every declarator has the type.
            for v in declarators_after(t, i) {
                f.var_types
                    .entry(t.src(v).to_string())
                    .or_insert_with(|| ty.clone());
            }
            f.var_types.entry(word.to_string()).or_insert(ty);
        }
    }
}

/// The names declared after the declarator at `i` in the same declaration (`int a, *b = 2,
/// c[3];` from `a`: `b`, `c`): each `,` at the statement's level followed by a name. Empty
/// unless the statement ends with `;` (a parameter list, a call's arguments are none).
fn declarators_after(t: &Tokens<'_>, i: usize) -> Vec<usize> {
    let mut out = Vec::new();
    let mut k = i + 1;
    loop {
        // Past this declarator's tail (`[3]`, `= f(x, y)`, `{1, 2}`) to its `,` or `;`.
        loop {
            match t.tok(k).map(|x| &x.kind) {
                None | Some(Kind::Close(_)) => return Vec::new(),
                Some(Kind::Open(_)) => k = t.close.get(k).copied().unwrap_or(k).max(k) + 1,
                _ if t.is(k, ",") || t.is(k, ";") => break,
                _ => k += 1,
            }
        }
        if !t.is(k, ",") || out.len() >= 64 {
            return if t.is(k, ";") { out } else { Vec::new() };
        }
        k += 1;
        while t.is(k, "*") || t.is(k, "&") {
            k += 1;
        }
        if !t.is_ident(k) {
            return Vec::new();
        }
        out.push(k);
        k += 1;
    }
}

/// `from M import *`, `from M import A, B`, `import M, N as O` at `i` (a line's first word).
fn python_import(t: &Tokens<'_>, i: usize, f: &mut FileFacts) {
    let dotted = |mut k: usize| -> (String, usize) {
        let mut s = String::new();
        while t.is_ident(k) {
            s.push_str(t.src(k));
            if t.is(k + 1, ".") && t.is_ident(k + 2) {
                s.push('.');
                k += 2;
            } else {
                k += 1;
                break;
            }
        }
        (s, k)
    };
    let line = t.toks[i].pos.line;
    let same_line = |k: usize| t.tok(k).is_some_and(|x| x.pos.line == line);
    if t.is(i, "from") {
        let (module, mut k) = dotted(i + 1);
        if module.is_empty() || !t.is(k, "import") {
            return;
        }
        k += 1;
        let mut names = Vec::new();
        while same_line(k) && names.len() < 64 {
            match t.src(k) {
                "*" => names.push("*".to_string()),
                w if t.is_ident(k) && w != "as" && !t.is(k.saturating_sub(1), "as") => {
                    names.push(w.to_string());
                }
                _ => {}
            }
            k += 1;
        }
        f.imports.push((module, names));
    } else {
        let mut k = i + 1;
        while same_line(k) && f.imports.len() < 256 {
            let (module, next) = dotted(k);
            if module.is_empty() {
                break;
            }
            f.imports.push((module, Vec::new()));
            k = next;
            if t.is(k, "as") {
                k += 2;
            }
            if !t.is(k, ",") {
                break;
            }
            k += 1;
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

/// Appends the token at `k` to a type's text: a space between two words (`unsigned long`,
/// `long long`), none around punctuation (`std::vector<double>`).
fn push_type_word(t: &Tokens<'_>, s: &mut String, k: usize) {
    if k > 0 && t.is_ident(k) && t.is_ident(k - 1) && !s.is_empty() {
        s.push(' ');
    }
    s.push_str(t.src(k));
}

/// `<T>` at `lt`: the type as written (a space only between words), and the index after the
/// `>`.
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
            _ => push_type_word(t, &mut s, k),
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
    let words: Vec<usize> = (k..i)
        .filter(|&j| {
            !matches!(
                t.src(j),
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
    let mut s = String::new();
    for j in words {
        // A word after a dropped qualifier (`const unsigned`) starts the text: no space.
        if s.is_empty() {
            s.push_str(t.src(j));
        } else {
            push_type_word(t, &mut s, j);
        }
    }
    Some(s)
}

/// The index of a class's name after `class` at `i`: past export macros and attributes
/// (`class __declspec(dllexport) Foo`, `class DLL_EXPORT Foo : public Base`), which are no
/// class and no base.
fn class_name(t: &Tokens<'_>, i: usize) -> usize {
    let mut n = i + 1;
    for _ in 0..8 {
        if matches!(t.src(n), "__declspec" | "__attribute__" | "alignas") && t.is_open(n + 1, b'(')
        {
            n = t.close.get(n + 1).copied().unwrap_or(n) + 1;
        } else if t.is_ident(n)
            && t.is_ident(n + 1)
            && !matches!(t.src(n + 1), "final" | "extends" | "implements")
        {
            n += 1;
        } else {
            break;
        }
    }
    n
}

fn class(t: &Tokens<'_>, i: usize, lang: Language, f: &mut FileFacts, at: &dyn Fn(usize) -> At) {
    let n = if lang == Language::Cpp {
        class_name(t, i)
    } else {
        i + 1
    };
    if !t.is_ident(n) {
        return;
    }
    let name = t.src(n).to_string();
    let mut bases = Vec::new();
    let mut k = n + 1;
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
        name: name.into(),
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
                key: t.span_text(pair[0].0, pair[0].1).into(),
                value: None,
                unresolved: Some(t.span_text(pair[0].0, pair[0].1).into()),
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
            unresolved: value
                .is_none()
                .then(|| t.span_text(v.0, v.1))
                .map(Into::into),
            key: key.into(),
            value: value.map(Into::into),
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
    let stems = own_stems(&files, &facts);
    let pick = pick_class(&facts, &stems);
    let class = pick.class.map(|(fi, ci)| {
        let (name, bases, at) = facts[fi].classes[ci].clone();
        super::CodeClass { name, bases, at }
    });
    let missing_bases: Vec<Unverified> = pick
        .missing
        .iter()
        .map(|(fi, b)| Unverified {
            construct: b.clone(),
            what: "what the base class registers and defines (its file is not found beside the component)".into(),
            of: super::Unread::Base,
            at: facts[*fi]
                .classes
                .iter()
                .find(|c| c.1.contains(b))
                .map(|c| c.2.clone())
                .unwrap_or_default(),
        })
        .collect();
    let mut port_types = BTreeMap::new();
    let mut port_dirs = BTreeMap::new();
    let mut ctor_name = BTreeMap::new();
    let mut var_types = BTreeMap::new();
    let mut py_assign = BTreeMap::new();
    let mut imp = Implementation {
        language: lang,
        files,
        class,
        unverified: missing_bases,
        ..Default::default()
    };
    let mut ctor_unread = std::collections::BTreeSet::new();
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
        port_dirs.extend(f.port_dirs);
        for (k, v) in f.ctor_name {
            ctor_name.entry(k).or_insert(v);
        }
        ctor_unread.extend(f.ctor_unread);
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
    // `self._xIn = OpenRTM_aist.InPort(…)`: an in-port.
    let py_dir = |var: &str| -> Option<Direction> {
        let (callee, _, _) = py_assign.get(var)?;
        match callee.rsplit('.').next()? {
            "InPort" => Some(Direction::In),
            "OutPort" => Some(Direction::Out),
            _ => None,
        }
    };
    for (reg_name, reg_direction, var, at, construct) in port_regs {
        let data_type = port_types.get(&var).cloned().or_else(|| py_type(&var));
        // The port object's class says what it is (an InPort given to addOutPort stays an
        // in-port); the registering call when the class is not seen.
        let direction = port_dirs
            .get(&var)
            .copied()
            .or_else(|| py_dir(&var))
            .unwrap_or(reg_direction);
        // The port runs under the name its constructor gives it (`m_xIn("x", m_x)`: OpenRTM's
        // PortBase keeps it; addInPort's name only keys the port's properties), so that one
        // is compared; the registration's name when the constructor is not seen.
        let name = match ctor_name.get(&var) {
            Some(n) => Some(n.clone()),
            None if ctor_unread.contains(&var) => None,
            None => reg_name,
        };
        // A port registered twice (in two branches, in the constructor and onInitialize) is
        // one port.
        if name.as_ref().is_some_and(|n| {
            imp.data_ports
                .iter()
                .any(|p| p.name == n && p.direction == direction)
        }) {
            continue;
        }
        match name {
            Some(name) => imp.data_ports.push(CodeDataPort {
                name: name.into(),
                direction,
                variable: var.into(),
                data_type: data_type.map(Into::into),
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
        let known = imp.service_ports[idx]
            .interfaces
            .iter()
            .any(|i| i.instance_name == instance && i.direction == direction);
        if known {
            continue; // registered twice
        }
        imp.service_ports[idx].interfaces.push(CodeInterface {
            instance_name: instance.into(),
            type_name: ty.map(Into::into),
            direction,
            at,
        });
    }
    for (name, var, default, at, construct) in param_regs {
        let type_ = var_types.get(&var).cloned();
        if name
            .as_ref()
            .is_some_and(|n| imp.parameters.iter().any(|p| p.name == n))
        {
            continue; // bound twice
        }
        match name {
            Some(name) => imp.parameters.push(CodeParameter {
                name: name.into(),
                variable: var.into(),
                type_: type_.map(Into::into),
                default: default.map(Into::into),
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
                construct: u.to_string(),
                what: format!("the spec array's value of `{}`", s.key),
                of: super::Unread::SpecValue,
                at: s.at.clone(),
            });
        }
    }
    imp.shrink();
    imp
}

/// The last segment of a class name (`RTC::DataFlowComponentBase`,
/// `OpenRTM_aist.DataFlowComponentBase` → `DataFlowComponentBase`).
fn last_segment(b: &str) -> &str {
    let b = b.rsplit("::").next().unwrap_or(b);
    b.rsplit('.').next().unwrap_or(b)
}

/// The classes of OpenRTM a component class derives from.
const RTC_BASES: &[&str] = &[
    "DataFlowComponentBase",
    "RTObject_impl",
    "FiniteStateMachineComponentBase",
    "MultiModeComponentBase",
];

/// Bases that register nothing (Python's `object`).
const INERT_BASES: &[&str] = &["object"];

/// The names a component's own files are named after (`Counter` of `src/CounterImpl.java`,
/// `SensorGUI` of `SensorGUI.py`): the component's name, which its class usually has.
pub fn own_stems(files: &[String], facts: &[FileFacts]) -> Vec<String> {
    files
        .iter()
        .zip(
            facts
                .iter()
                .map(|f| f.base_file)
                .chain(std::iter::repeat(false)),
        )
        .filter(|(_, base)| !base)
        .filter_map(|(f, _)| {
            let stem = f.rsplit('/').next()?.split('.').next()?;
            let stem = stem
                .strip_suffix("Impl")
                .or_else(|| stem.strip_suffix("Comp"))
                .unwrap_or(stem);
            Some(stem.to_string())
        })
        .collect()
}

/// Which class is the component's, and the base classes of its that are not found.
pub struct ClassPick {
    /// (file, class) in the facts.
    pub class: Option<(usize, usize)>,
    /// (file naming it, base class as written): a base whose file was not read, when the
    /// class reaches none of OpenRTM's component classes through the bases that were.
    pub missing: Vec<(usize, String)>,
}

/// Where a class named `name` (its last segment) is defined among the facts.
fn find_class(facts: &[FileFacts], name: &str) -> Option<(usize, usize)> {
    facts.iter().enumerate().find_map(|(fi, f)| {
        f.classes
            .iter()
            .position(|c| c.0 == name)
            .map(|ci| (fi, ci))
    })
}

/// The bases of the class at `start`, followed through the classes the facts define: whether
/// one of them is OpenRTM's component class, and the bases not found.
fn walk_bases(facts: &[FileFacts], start: (usize, usize)) -> (bool, Vec<(usize, String)>) {
    let mut stack = vec![start];
    let mut seen = vec![start];
    let mut reaches = false;
    let mut missing = Vec::new();
    while let Some((fi, ci)) = stack.pop() {
        for b in &facts[fi].classes[ci].1 {
            let last = last_segment(b);
            if RTC_BASES.contains(&last) {
                reaches = true;
            } else if INERT_BASES.contains(&last) {
            } else if let Some(k) = find_class(facts, last) {
                if !seen.contains(&k) && seen.len() < 32 {
                    seen.push(k);
                    stack.push(k);
                }
            } else {
                missing.push((fi, b.clone()));
            }
        }
    }
    (reaches, missing)
}

/// The component's class: among the classes of its own files, one deriving (directly or
/// through a base the facts define) from OpenRTM's component class, the one named after the
/// component first; else the one named after the component; else the first with a base.
/// Helper classes (listeners, a service's servant, the factory of a Java component) are not
/// it.
pub fn pick_class(facts: &[FileFacts], stems: &[String]) -> ClassPick {
    let own: Vec<(usize, usize)> = facts
        .iter()
        .enumerate()
        .filter(|(_, f)| !f.base_file)
        .flat_map(|(fi, f)| (0..f.classes.len()).map(move |ci| (fi, ci)))
        .collect();
    let name = |k: &(usize, usize)| facts[k.0].classes[k.1].0.as_str();
    let named = |k: &(usize, usize)| stems.iter().any(|s| s.eq_ignore_ascii_case(name(k)));
    let deriving: Vec<(usize, usize)> = own
        .iter()
        .copied()
        .filter(|&k| walk_bases(facts, k).0)
        .collect();
    let class = deriving
        .iter()
        .find(|k| named(k))
        .or_else(|| deriving.first())
        .or_else(|| own.iter().find(|k| named(k)))
        .or_else(|| own.iter().find(|k| !facts[k.0].classes[k.1].1.is_empty()))
        .copied();
    let missing = match class {
        Some(k) => match walk_bases(facts, k) {
            (false, m) => m,
            (true, _) => Vec::new(),
        },
        None => Vec::new(),
    };
    ClassPick { class, missing }
}
