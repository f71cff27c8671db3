//! The implementation of a component: the source files RTCBuilder lays out beside its
//! `RTC.xml` (C++ `src/<Name>.cpp` and `include/<Name>/<Name>.h`, Python `<Name>.py`, Java
//! `src/<Name>Impl.java` …), read by [`lex`] and [`extract`], and compared with the profile by
//! [`drift`]: whether the code still does what the specification says.

pub mod drift;
pub mod extract;
pub mod lex;
pub mod recover;

use crate::diagnostic::Diagnostic;
use crate::model::{Pos, Text};
pub use lex::Language;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Diagnostic codes of the reading (the drift codes are in [`drift`]).
pub mod codes {
    /// A source file that could not be read (too large, too deeply nested): not verified.
    pub const UNREADABLE: &str = "RTC811";
    /// A component with code and no profile, documented from its code ([`super::recover`]).
    pub const RECOVERED: &str = "RTC812";
}

/// A place in a source file (the file as shown: relative to the input, forward slashes).
#[derive(Debug, Clone, Default, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub struct At {
    /// Shared by every place of the file (thousands of components each keep dozens).
    pub file: std::sync::Arc<str>,
    pub pos: Pos,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Direction {
    In,
    Out,
    Provided,
    Required,
}

impl Direction {
    /// The profile's word for it (`DataInPort`, `Provided`).
    pub fn profile_word(self) -> &'static str {
        match self {
            Direction::In => "DataInPort",
            Direction::Out => "DataOutPort",
            Direction::Provided => "Provided",
            Direction::Required => "Required",
        }
    }
}

/// One key of the spec array (`"version", "1.0.0"`); a value that is no literal (a macro such
/// as `PACKAGE_VERSION`) is `unresolved`, as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct SpecValue {
    pub key: Text,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<Text>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unresolved: Option<Text>,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeDataPort {
    pub name: Text,
    pub direction: Direction,
    pub variable: Text,
    /// `T` of `InPort<T>`, or the data object's type (Python); `None`: not found.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub data_type: Option<Text>,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeInterface {
    pub instance_name: Text,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub type_name: Option<Text>,
    pub direction: Direction,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeServicePort {
    /// The name its constructor gives it (`m_xPort("x")`); `None`: not a literal.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    pub variable: String,
    pub interfaces: Vec<CodeInterface>,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeParameter {
    pub name: Text,
    pub variable: Text,
    /// The declared type of the variable (`int`, `std::string`; Python: the literal's type).
    #[serde(default, rename = "type", skip_serializing_if = "Option::is_none")]
    pub type_: Option<Text>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub default: Option<Text>,
    pub at: At,
}

/// A lifecycle callback the class defines; `implemented`: its body is more than the generated
/// `return RTC::RTC_OK;` (and registrations).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Callback {
    pub name: Text,
    pub implemented: bool,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeClass {
    pub name: String,
    pub bases: Vec<String>,
    pub at: At,
}

/// What an [`Unverified`] construct could have registered: the kinds of element nothing is
/// reported missing from the code of once one of them could not be read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Unread {
    DataPort,
    ServicePort,
    Parameter,
    /// A macro: any kind.
    Any,
    /// A base class whose file is not found: any kind, and callbacks.
    Base,
    /// A spec array value (no element kind).
    SpecValue,
}

/// A construct a static reading cannot verify (a name built at run time, a macro).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Unverified {
    pub construct: String,
    pub what: String,
    pub of: Unread,
    pub at: At,
}

/// What the code of one component registers, and where it differs from the profile.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Implementation {
    pub language: Language,
    /// The files read, relative to the input (`[[source]]` files as `<name>/<path>`).
    pub files: Vec<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub class: Option<CodeClass>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub spec: Vec<SpecValue>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub data_ports: Vec<CodeDataPort>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub service_ports: Vec<CodeServicePort>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub parameters: Vec<CodeParameter>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub callbacks: Vec<Callback>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unverified: Vec<Unverified>,
    /// Where the code and the profile disagree ([`drift::compare`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub drift: Vec<drift::Drift>,
}

impl Implementation {
    /// Whether the code read registers no port and no parameter at all (a base class, a
    /// library or another file does).
    pub fn registers_nothing(&self) -> bool {
        self.data_ports.is_empty() && self.service_ports.is_empty() && self.parameters.is_empty()
    }

    /// Whether every registration of `kind` was read, so that what the code lacks of it can
    /// be reported: the code registers some of it, and none through a name that is not a
    /// literal or a macro.
    pub fn reads_all(&self, kind: Unread) -> bool {
        let some = match kind {
            Unread::DataPort => !self.data_ports.is_empty(),
            Unread::ServicePort => !self.service_ports.is_empty(),
            Unread::Parameter => !self.parameters.is_empty(),
            Unread::Any | Unread::Base | Unread::SpecValue => true,
        };
        some && !self
            .unverified
            .iter()
            .any(|u| u.of == kind || matches!(u.of, Unread::Any | Unread::Base))
    }

    /// Gives back the room the lists grew into: the catalogue keeps thousands of these for
    /// the whole build (a spec array of 19 values had room for 32).
    pub fn shrink(&mut self) {
        self.files.shrink_to_fit();
        self.spec.shrink_to_fit();
        self.data_ports.shrink_to_fit();
        self.service_ports.shrink_to_fit();
        for s in &mut self.service_ports {
            s.interfaces.shrink_to_fit();
        }
        self.parameters.shrink_to_fit();
        self.callbacks.shrink_to_fit();
        self.unverified.shrink_to_fit();
        self.drift.shrink_to_fit();
    }

    /// Keeps of the spec array only what the profile does not say alike: the values a drift
    /// finding names and those that are no literal. The rest is the profile's (and the spec
    /// array is the largest part of an implementation: a third of the memory code adds to a
    /// build). A component recovered from its code keeps it all.
    pub fn keep_spec_the_profile_lacks(&mut self) {
        let named: Vec<&At> = self.drift.iter().filter_map(|d| d.at.as_ref()).collect();
        self.spec
            .retain(|s| s.unresolved.is_some() || named.contains(&&s.at));
        self.spec.shrink_to_fit();
    }

    /// The spec array's value of `key`, when it is a literal.
    pub fn spec_value(&self, key: &str) -> Option<&SpecValue> {
        self.spec.iter().find(|s| s.key == key)
    }
}

/// The most source files read for one component (a folder of generated code holds 2–4).
const MAX_FILES: usize = 16;

/// The files RTCBuilder generates for component `name` in `lang`, relative to the profile's
/// folder, in reading order (the spec array's file first).
fn layout(name: &str, lang: Language) -> Vec<String> {
    match lang {
        Language::Cpp => vec![
            format!("src/{name}.cpp"),
            format!("{name}.cpp"),
            format!("include/{name}/{name}.h"),
            format!("include/{name}.h"),
            format!("src/{name}.h"),
            format!("{name}.h"),
            format!("include/{name}/{name}.hpp"),
            format!("src/{name}.hpp"),
        ],
        // `<Name>Comp.py`: older RTCBuilder projects (OpenRTM's TkCalibGUI).
        Language::Python => vec![
            format!("{name}.py"),
            format!("src/{name}.py"),
            format!("{name}Comp.py"),
        ],
        Language::Java => vec![
            format!("src/{name}.java"),
            format!("src/{name}Impl.java"),
            format!("{name}.java"),
            format!("{name}Impl.java"),
        ],
    }
}

/// The languages to look for, from the profile's `Language kind` (all three when it names
/// none of them).
pub fn languages(kind: Option<&str>) -> Vec<Language> {
    let k = kind.unwrap_or("").trim().to_ascii_lowercase();
    if k.starts_with("c++") || k == "cpp" || k == "c" {
        vec![Language::Cpp]
    } else if k.starts_with("python") {
        vec![Language::Python]
    } else if k.starts_with("java") {
        vec![Language::Java]
    } else {
        vec![Language::Cpp, Language::Python, Language::Java]
    }
}

/// The source files of component `name` below `abs_dir` (shown as `rel_dir`), in the first
/// of `langs` that has any: RTCBuilder's layout, else (older or hand-made projects) the files
/// named after the component anywhere in the folder's `src/` tree or in the folder itself.
pub fn find(
    abs_dir: &Path,
    rel_dir: &str,
    name: &str,
    langs: &[Language],
    extra: &[String],
) -> Option<(Language, Vec<(std::path::PathBuf, String)>)> {
    let shown = |r: &str| {
        if rel_dir.is_empty() {
            r.to_string()
        } else {
            format!("{rel_dir}/{r}")
        }
    };
    if !extra.is_empty() {
        let files: Vec<_> = extra
            .iter()
            .filter(|r| safe_relative(r))
            .map(|r| (abs_dir.join(r), shown(r)))
            .filter(|(p, _)| is_plain_file(p))
            .take(MAX_FILES)
            .collect();
        let lang = files.first().and_then(|(p, _)| language_of(p))?;
        return Some((lang, files));
    }
    if name.is_empty() || !safe_relative(name) {
        return None;
    }
    for &lang in langs {
        let files: Vec<_> = layout(name, lang)
            .into_iter()
            .map(|r| (abs_dir.join(&r), shown(&r)))
            .filter(|(p, _)| is_plain_file(p))
            .collect();
        if !files.is_empty() {
            return Some((lang, files));
        }
    }
    // Java packages (`src/RTMExamples/SimpleIO/ConsoleInImpl.java`), hand-made layouts.
    let wanted: Vec<(Language, String)> = langs
        .iter()
        .flat_map(|&l| match l {
            Language::Cpp => vec![(l, format!("{name}.cpp")), (l, format!("{name}.h"))],
            Language::Python => vec![(l, format!("{name}.py"))],
            Language::Java => vec![(l, format!("{name}.java")), (l, format!("{name}Impl.java"))],
        })
        .collect();
    let mut found: Vec<(Language, std::path::PathBuf, String)> = Vec::new();
    for e in walkdir::WalkDir::new(abs_dir)
        .follow_links(false)
        .max_depth(5)
        .sort_by_file_name()
        .into_iter()
        .filter_entry(|e| e.depth() == 0 || !e.file_name().to_string_lossy().starts_with('.'))
        .filter_map(Result::ok)
        .take(2_000)
    {
        if !e.file_type().is_file() {
            continue;
        }
        let fname = e.file_name().to_string_lossy();
        if let Some((l, _)) = wanted.iter().find(|(_, w)| w.eq_ignore_ascii_case(&fname)) {
            let rel = e
                .path()
                .strip_prefix(abs_dir)
                .map(|p| p.to_string_lossy().replace('\\', "/"))
                .unwrap_or_default();
            // Test folders hold a copy named `<Name>Test`; not the component.
            if rel
                .split('/')
                .any(|s| s == "test" || s == "tests" || s == "build")
            {
                continue;
            }
            found.push((*l, e.path().to_path_buf(), shown(&rel)));
        }
    }
    let lang = langs
        .iter()
        .copied()
        .find(|l| found.iter().any(|(fl, _, _)| fl == l))?;
    // A file named exactly after the component is its own; one equal but for case is taken
    // only when there is none (a library header `vector.h` beside a component `Vector`).
    let exact = |p: &std::path::Path| {
        let f = p
            .file_name()
            .map(|f| f.to_string_lossy())
            .unwrap_or_default();
        wanted.iter().any(|(l, w)| *l == lang && *w == f)
    };
    let any_exact = found.iter().any(|(l, p, _)| *l == lang && exact(p));
    let files: Vec<_> = found
        .into_iter()
        .filter(|(l, p, _)| *l == lang && (!any_exact || exact(p)))
        .map(|(_, p, r)| (p, r))
        .take(MAX_FILES)
        .collect();
    Some((lang, files))
}

fn is_plain_file(p: &Path) -> bool {
    std::fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_file())
}

/// The language of a source file the check reads, by its extension (headers included).
pub(crate) fn language_of(p: &Path) -> Option<Language> {
    match p.extension()?.to_str()?.to_ascii_lowercase().as_str() {
        "cpp" | "cc" | "cxx" | "h" | "hpp" | "hh" | "hxx" => Some(Language::Cpp),
        "py" => Some(Language::Python),
        "java" => Some(Language::Java),
        _ => None,
    }
}

/// A source file as text: UTF-8 (a BOM dropped), else Shift_JIS (Windows editors), else
/// UTF-8 with the invalid bytes replaced — the names the check reads are ASCII either way.
pub fn decode(bytes: &[u8]) -> String {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_string(),
        Err(_) => {
            let (s, _, bad) = encoding_rs::SHIFT_JIS.decode(bytes);
            if bad {
                String::from_utf8_lossy(bytes).into_owned()
            } else {
                s.into_owned()
            }
        }
    }
}

/// Reads the implementation of one component from `files` (shown names beside them), at most
/// `max_size` bytes each; a file that cannot be read is named in a diagnostic and left out.
pub fn read(
    lang: Language,
    files: &[(std::path::PathBuf, String)],
    max_size: u64,
) -> (Option<Implementation>, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    let mut read = Read::default();
    for (path, shown) in files {
        if let Some(f) = read_one(lang, path, shown, max_size, &mut diags) {
            read.push(path, shown, f);
        }
    }
    if read.files.is_empty() {
        return (None, diags);
    }
    follow_bases(lang, &mut read, max_size);
    (Some(extract::join(lang, read.files, read.facts)), diags)
}

/// The files read so far: where each is, as shown, and its facts.
#[derive(Default)]
struct Read {
    paths: Vec<std::path::PathBuf>,
    files: Vec<String>,
    facts: Vec<extract::FileFacts>,
}

impl Read {
    fn push(&mut self, path: &Path, shown: &str, f: extract::FileFacts) {
        self.paths.push(path.to_path_buf());
        self.files.push(shown.to_string());
        self.facts.push(f);
    }
}

/// Reads and lexes one source file; `None` (and a diagnostic) when it cannot be.
fn read_one(
    lang: Language,
    path: &Path,
    shown: &str,
    max_size: u64,
    diags: &mut Vec<Diagnostic>,
) -> Option<extract::FileFacts> {
    let bytes = match crate::walk::read_at_most(path, max_size.saturating_add(1)) {
        Ok(b) => b,
        Err(e) => {
            diags.push(unreadable(
                shown,
                format!("cannot read the source file: {e}"),
                None,
            ));
            return None;
        }
    };
    if bytes.len() as u64 > max_size {
        diags.push(unreadable(
            shown,
            format!("the source file is larger than {max_size} bytes; it is not read, so the implementation is not verified against it"),
            None,
        ));
        return None;
    }
    let text = decode(&bytes);
    let lang = language_of(path).unwrap_or(lang);
    match lex::lex(&text, lang) {
        Ok(t) => {
            let mut f = extract::file_facts(&t, lang, shown);
            f.macros = macro_registrations(&text, shown);
            if lang == Language::Cpp {
                f.includes = quoted_includes(&text);
            }
            Some(f)
        }
        Err(e) => {
            diags.push(unreadable(
                shown,
                format!("the source file is not read: {}", e.message),
                Some(e.pos),
            ));
            None
        }
    }
}

/// Follows the component class's bases to the files beside it that define them (Python: the
/// module in the same folder it is imported from; C++: a header the component includes from
/// one of its own folders, with the source of the same name; Java: `<Base>.java` in the same
/// package folder), and reads those too: a base class's registrations and callbacks are the
/// component's. A base not found stays "could not verify" ([`extract::pick_class`]).
fn follow_bases(lang: Language, read: &mut Read, max_size: u64) {
    let mut tried: Vec<std::path::PathBuf> = Vec::new();
    while read.files.len() < MAX_FILES {
        let pick = extract::pick_class(&read.facts, &extract::own_stems(&read.files, &read.facts));
        let mut added = false;
        for (fi, base) in pick.missing {
            let last = base.rsplit(['.', ':']).next().unwrap_or(&base).to_string();
            for c in base_candidates(lang, read, fi, &base) {
                if read.paths.contains(&c.path)
                    || tried.contains(&c.path)
                    || !is_plain_file(&c.path)
                {
                    continue;
                }
                tried.push(c.path.clone());
                // A file that fails to read here is no diagnostic: it is not the component's.
                let Some(mut f) = read_one(lang, &c.path, &c.shown, max_size, &mut Vec::new())
                else {
                    continue;
                };
                if !f.classes.iter().any(|k| k.0 == last) {
                    continue; // another module, another header
                }
                f.base_file = true;
                read.push(&c.path, &c.shown, f);
                added = true;
                for (p, s) in c.sources {
                    if read.files.len() >= MAX_FILES {
                        return;
                    }
                    if read.paths.contains(&p) || !is_plain_file(&p) {
                        continue;
                    }
                    if let Some(mut f) = read_one(lang, &p, &s, max_size, &mut Vec::new()) {
                        f.base_file = true;
                        read.push(&p, &s, f);
                    }
                }
                if read.files.len() >= MAX_FILES {
                    return;
                }
                break;
            }
        }
        if !added {
            return;
        }
    }
}

/// A file that may define a base class, and (C++) the sources of the same name beside the
/// component's files that define its members.
struct Candidate {
    path: std::path::PathBuf,
    shown: String,
    sources: Vec<(std::path::PathBuf, String)>,
}

/// `rel` in the folder of `path` (shown as `shown`).
fn beside(path: &Path, shown: &str, rel: &str) -> (std::path::PathBuf, String) {
    let dir = path.parent().unwrap_or(Path::new(""));
    let s = match shown.rsplit_once('/') {
        Some((d, _)) => format!("{d}/{rel}"),
        None => rel.to_string(),
    };
    (dir.join(rel), s)
}

/// The files that may define `base`, named in file `fi`.
fn base_candidates(lang: Language, read: &Read, fi: usize, base: &str) -> Vec<Candidate> {
    let (Some(path), Some(shown)) = (read.paths.get(fi), read.files.get(fi)) else {
        return Vec::new();
    };
    let plain = |(path, shown): (std::path::PathBuf, String)| Candidate {
        path,
        shown,
        sources: Vec::new(),
    };
    let last = base.rsplit(['.', ':']).next().unwrap_or(base);
    match lang {
        Language::Python => {
            let mut modules: Vec<String> = Vec::new();
            if let Some((q, _)) = base.rsplit_once('.') {
                modules.push(q.to_string());
            } else {
                for (m, names) in read.facts.iter().flat_map(|f| &f.imports) {
                    if names.iter().any(|n| n == "*" || n == last) {
                        modules.push(m.clone());
                    }
                }
            }
            modules
                .iter()
                .map(|m| format!("{}.py", m.replace('.', "/")))
                .filter(|rel| safe_relative(rel))
                .map(|rel| plain(beside(path, shown, &rel)))
                .collect()
        }
        Language::Java => vec![plain(beside(path, shown, &format!("{last}.java")))],
        Language::Cpp => {
            // The component's own files' folders (`src/`, `include/<Name>/`): a header is
            // included from one and found in another by the include path.
            let own: Vec<(&std::path::PathBuf, &String)> = read
                .paths
                .iter()
                .zip(&read.files)
                .zip(&read.facts)
                .filter(|(_, f)| !f.base_file)
                .map(|(pf, _)| pf)
                .collect();
            let mut out = Vec::new();
            let includes = read
                .facts
                .iter()
                .filter(|f| !f.base_file)
                .flat_map(|f| &f.includes);
            // Only a header of the component's own folders (no library's `a/b.h`).
            for inc in includes.filter(|i| safe_relative(i) && !i.contains('/')) {
                let stem = inc.rsplit_once('.').map_or(inc.as_str(), |(a, _)| a);
                let sources: Vec<(std::path::PathBuf, String)> = own
                    .iter()
                    .flat_map(|(p, s)| {
                        ["cpp", "cc", "cxx"].map(|ext| beside(p, s, &format!("{stem}.{ext}")))
                    })
                    .collect();
                for (p, s) in &own {
                    let (path, shown) = beside(p, s, inc);
                    out.push(Candidate {
                        path,
                        shown,
                        sources: sources.clone(),
                    });
                }
            }
            out
        }
    }
}

/// The files `#include "…"` names (not `<…>`: a library's).
fn quoted_includes(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| {
            let l = l.trim_start().strip_prefix('#')?.trim_start();
            let r = l.strip_prefix("include")?.trim_start().strip_prefix('"')?;
            r.split_once('"').map(|(f, _)| f.to_string())
        })
        .take(256)
        .collect()
}

fn unreadable(file: &str, message: String, pos: Option<Pos>) -> Diagnostic {
    let d = Diagnostic::info(codes::UNREADABLE, file, message).with_hint(
        "nothing to change if the file is generated or vendored; else split it, or name the component's own files in rtcdoc.toml ([[implementation.component]] files)",
    );
    match pos {
        Some(p) => d.at(p),
        None => d,
    }
}

/// `#define` lines that register ports or parameters: what a macro does is not read.
fn macro_registrations(text: &str, file: &str) -> Vec<(String, At)> {
    let mut out = Vec::new();
    let mut lines = text.lines().enumerate();
    while let Some((n, line)) = lines.next() {
        let l = line.trim_start();
        if !l.starts_with('#') || !l[1..].trim_start().starts_with("define") {
            continue;
        }
        let mut whole = l.to_string();
        let mut last = line;
        while last.trim_end().ends_with('\\') {
            match lines.next() {
                Some((_, next)) => {
                    whole.push_str(next);
                    last = next;
                }
                None => break,
            }
        }
        if [
            "addInPort",
            "addOutPort",
            "bindParameter",
            "registerProvider",
            "registerConsumer",
        ]
        .iter()
        .any(|r| whole.contains(r))
        {
            let name: String = l[1..]
                .trim_start()
                .trim_start_matches("define")
                .trim_start()
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            out.push((
                name,
                At {
                    file: file.into(),
                    pos: Pos::new(u32::try_from(n + 1).unwrap_or(u32::MAX), 1),
                },
            ));
        }
    }
    out
}

/// A relative path that stays inside its folder (no `..`, no root, no drive, no backslash).
fn safe_relative(rel: &str) -> bool {
    !rel.is_empty()
        && !rel.starts_with('/')
        && !rel.contains('\\')
        && !rel.contains(':')
        && rel
            .split('/')
            .all(|s| !s.is_empty() && s != "." && s != "..")
}
