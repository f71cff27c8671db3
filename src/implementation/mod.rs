//! The implementation of a component: the source files RTCBuilder lays out beside its
//! `RTC.xml` (C++ `src/<Name>.cpp` and `include/<Name>/<Name>.h`, Python `<Name>.py`, Java
//! `src/<Name>Impl.java` …), read by [`lex`] and [`extract`], and compared with the profile by
//! [`drift`]: whether the code still does what the specification says.

pub mod drift;
pub mod extract;
pub mod lex;
pub mod recover;

use crate::diagnostic::Diagnostic;
use crate::model::Pos;
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
    pub file: String,
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
    pub key: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unresolved: Option<String>,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeDataPort {
    pub name: String,
    pub direction: Direction,
    pub variable: String,
    /// `T` of `InPort<T>`, or the data object's type (Python); `None`: not found.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub data_type: Option<String>,
    pub at: At,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct CodeInterface {
    pub instance_name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub type_name: Option<String>,
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
    pub name: String,
    pub variable: String,
    /// The declared type of the variable (`int`, `std::string`; Python: the literal's type).
    #[serde(default, rename = "type", skip_serializing_if = "Option::is_none")]
    pub type_: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub default: Option<String>,
    pub at: At,
}

/// A lifecycle callback the class defines; `implemented`: its body is more than the generated
/// `return RTC::RTC_OK;` (and registrations).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Callback {
    pub name: String,
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
            Unread::Any | Unread::SpecValue => true,
        };
        some && !self
            .unverified
            .iter()
            .any(|u| u.of == kind || u.of == Unread::Any)
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
    let files: Vec<_> = found
        .into_iter()
        .filter(|(l, _, _)| *l == lang)
        .map(|(_, p, r)| (p, r))
        .take(MAX_FILES)
        .collect();
    Some((lang, files))
}

fn is_plain_file(p: &Path) -> bool {
    std::fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_file())
}

fn language_of(p: &Path) -> Option<Language> {
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
    let mut facts = Vec::new();
    let mut read_files = Vec::new();
    for (path, shown) in files {
        let bytes = match crate::walk::read_at_most(path, max_size.saturating_add(1)) {
            Ok(b) => b,
            Err(e) => {
                diags.push(unreadable(
                    shown,
                    format!("cannot read the source file: {e}"),
                    None,
                ));
                continue;
            }
        };
        if bytes.len() as u64 > max_size {
            diags.push(unreadable(
                shown,
                format!("the source file is larger than {max_size} bytes; it is not read, so the implementation is not verified against it"),
                None,
            ));
            continue;
        }
        let text = decode(&bytes);
        let lang = language_of(path).unwrap_or(lang);
        match lex::lex(&text, lang) {
            Ok(t) => {
                let mut f = extract::file_facts(&t, lang, shown);
                f.macros = macro_registrations(&text, shown);
                facts.push(f);
                read_files.push(shown.clone());
            }
            Err(e) => diags.push(unreadable(
                shown,
                format!("the source file is not read: {}", e.message),
                Some(e.pos),
            )),
        }
    }
    if read_files.is_empty() {
        return (None, diags);
    }
    (Some(extract::join(lang, read_files, facts)), diags)
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
                    file: file.to_string(),
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
