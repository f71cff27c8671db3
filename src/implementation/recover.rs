//! Components that have code and no profile: a source file holding a spec array
//! (`<name>_spec[]`, `<name>_spec = [...]`, Java's `component_conf`) in a folder no profile
//! documents. Such a component is documented from its code ([`profile`]), marked
//! "recovered from the source" with every value that could not be read named
//! ([`Recovered::unread`]), and `rtcdoc extract` writes the `RTC.xml` RTCBuilder would read
//! ([`rtc_xml`]).

use super::{At, Direction, Implementation};
use crate::model::{
    Action, ActionKind, BasicInfo, Configuration, ConfigurationSet, DataPort, Profile, Property,
    ServiceInterface, ServicePort, Text,
};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// What a profile recovered from the code could not say: the values of the spec array that
/// are no literal (a macro such as `PACKAGE_VERSION`), the ports whose data type was not found.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Recovered {
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unread: Vec<UnreadValue>,
}

/// One value a recovered profile leaves empty because the code does not spell it out.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct UnreadValue {
    /// The profile field (`basicInfo/version`, `dataPorts/in/type`).
    pub field: String,
    /// What the code has instead (`PACKAGE_VERSION`), or why nothing was found.
    pub written: String,
    pub at: At,
}

/// A component found in the code alone.
#[derive(Debug, Clone)]
pub struct Found {
    /// The file holding the spec array, relative to the input: the component's source.
    pub source: String,
    pub profile: Profile,
    pub recovered: Recovered,
    pub implementation: Implementation,
}

pub use crate::walk::is_code_file;

/// The folder a source file documents a component of: the folder above its last `src`
/// (RTCBuilder's `src/<Name>.cpp`, Java's `src/<package>/…`), else its own folder.
pub fn component_folder(rel: &str) -> &str {
    let dir = rel.rsplit_once('/').map_or("", |(d, _)| d);
    let segs: Vec<&str> = dir.split('/').collect();
    match segs.iter().rposition(|s| *s == "src") {
        Some(0) => "",
        Some(k) => {
            let len: usize = segs[..k].iter().map(|s| s.len() + 1).sum::<usize>() - 1;
            &dir[..len]
        }
        None => dir,
    }
}

/// The component folders whose code the profile at `rel` documents: its own folder and that
/// folder's [`component_folder`] (`X/RTC.xml` documents the code of `X/src/`; `X/src/RTC.xml`,
/// a project kept in a folder named src, the code of `X/src/src/`). Twice the same when
/// they agree.
pub fn profile_folders(rel: &str) -> [&str; 2] {
    let own = rel.rsplit_once('/').map_or("", |(d, _)| d);
    [own, component_folder(rel)]
}

/// What to do about a component recovered from the code in `folder` (as the user names it).
pub fn extract_hint(folder: &str) -> String {
    let folder = if folder.is_empty() { "." } else { folder };
    format!(
        "run `rtcdoc extract {}` to write its RTC.xml (then describe the component there), or exclude the folder",
        crate::quote::shell_word(folder)
    )
}

/// The components of `code` (source files: absolute path, shown path) that no profile
/// documents: each file with a spec array whose [`component_folder`] is none of
/// `profile_folders` (those of the profiles read) and that no profile read as its code
/// (`read`). Test and build folders are left out; each file is read at most `max_size`.
pub fn find_all(
    code: &[(PathBuf, String)],
    profile_folders: &std::collections::HashSet<String>,
    max_size: u64,
) -> (Vec<Found>, Vec<crate::diagnostic::Diagnostic>) {
    use rayon::prelude::*;
    let per_file: Vec<(Option<Found>, Vec<crate::diagnostic::Diagnostic>)> = code
        .par_iter()
        .filter(|(_, rel)| {
            !rel.split('/')
                .any(|s| matches!(s, "test" | "tests" | "build" | "Templates"))
                && !profile_folders.contains(component_folder(rel))
        })
        .map(|(path, rel)| one(path, rel, max_size))
        .collect();
    let mut found = Vec::new();
    let mut diags = Vec::new();
    for (f, d) in per_file {
        found.extend(f);
        diags.extend(d);
    }
    found.sort_by(|a, b| a.source.cmp(&b.source));
    (found, diags)
}

/// The component whose spec array `path` holds, read with its companion files (the header
/// of a C++ file, the `Impl` class of a Java one).
fn one(
    path: &Path,
    rel: &str,
    max_size: u64,
) -> (Option<Found>, Vec<crate::diagnostic::Diagnostic>) {
    let Ok(bytes) = crate::walk::read_at_most(path, max_size.saturating_add(1)) else {
        return (None, Vec::new());
    };
    if bytes.len() as u64 > max_size || memchr::memmem::find(&bytes, b"implementation_id").is_none()
    {
        return (None, Vec::new());
    }
    let Some(lang) = super::language_of(path) else {
        return (None, Vec::new());
    };
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    // The companions are looked for from the component folder, in RTCBuilder's layout.
    let rel_dir = component_folder(rel);
    let below = rel[rel_dir.len()..]
        .trim_start_matches('/')
        .matches('/')
        .count();
    let abs_dir = path.ancestors().nth(below + 1).unwrap_or(Path::new(""));
    let mut files = vec![(path.to_path_buf(), rel.to_string())];
    if let Some((l, more)) = super::find(abs_dir, rel_dir, &stem, &[lang], &[]) {
        if l == lang {
            files.extend(more.into_iter().filter(|(_, r)| r != rel));
        }
    }
    let (imp, diags) = super::read(lang, &files, max_size);
    // A framework's default profile (`"implementation_id", ""` in OpenRTM's RTObject) names
    // no component.
    let names = |i: &Implementation| {
        i.spec_value("implementation_id").is_some_and(|s| {
            s.value
                .as_deref()
                .map_or(s.unresolved.is_some(), |v| !v.trim().is_empty())
        })
    };
    let Some(imp) = imp.filter(names) else {
        return (None, diags);
    };
    // The spec array must be this file's: a header including another's is not a component.
    if imp.spec_value("implementation_id").map(|s| &*s.at.file) != Some(rel) {
        return (None, diags);
    }
    let (profile, recovered) = profile(&imp, &stem);
    (
        Some(Found {
            source: rel.to_string(),
            profile,
            recovered,
            implementation: imp,
        }),
        diags,
    )
}

/// The text of an optional value.
fn s(t: &Option<Text>) -> Option<&str> {
    t.as_deref()
}

fn text(s: &str) -> Option<Text> {
    Some(Text::from(s))
}

/// The profile the code of `imp` describes (`fallback` names it when the spec array does
/// not), and what it could not say. Every element is located at its line in the code.
pub fn profile(imp: &Implementation, fallback: &str) -> (Profile, Recovered) {
    let mut p = Profile::default();
    let mut unread = Vec::new();
    let mut b = BasicInfo::default();
    let mut defaults: Vec<(String, String)> = Vec::new();
    let mut conf_props: Vec<(String, &'static str, String)> = Vec::new();
    let mut conf_types: Vec<(String, String)> = Vec::new();
    let mut language = None;
    for s in &imp.spec {
        let Some(v) = s.value.as_deref() else {
            unread.push(UnreadValue {
                field: spec_field(&s.key),
                written: s.unresolved.as_deref().unwrap_or_default().to_string(),
                at: s.at.clone(),
            });
            continue;
        };
        let key = s.key.as_str();
        let field = match key {
            "implementation_id" => &mut b.name,
            "description" => &mut b.description,
            "version" => &mut b.version,
            "vendor" => &mut b.vendor,
            "category" => &mut b.category,
            "activity_type" => &mut b.activity_type,
            "kind" => &mut b.component_kind,
            "max_instance" => &mut b.max_instances,
            "exec_cxt.periodic.rate" => &mut b.execution_rate,
            "exec_cxt.periodic.type" => &mut b.execution_type,
            "language" => &mut language,
            _ => {
                if let Some(n) = key.strip_prefix("conf.default.") {
                    defaults.push((n.to_string(), v.to_string()));
                } else if let Some(n) = key.strip_prefix("conf.__type__.") {
                    conf_types.push((n.to_string(), v.to_string()));
                } else if let Some((n, prop)) = conf_property(key) {
                    conf_props.push((n.to_string(), prop, v.to_string()));
                } else if !key.starts_with("conf.") || key.matches('.').count() < 2 {
                    b.properties.push(Property {
                        name: text(key),
                        value: text(v),
                        ..Default::default()
                    });
                }
                continue;
            }
        };
        *field = text(v);
    }
    // Older templates write the component kind (`DataFlowComponent`) or type (`STATIC`)
    // as activity_type: that is what it means.
    if let Some(a) = b.activity_type.clone() {
        let up = a.to_ascii_uppercase();
        if !matches!(up.as_str(), "PERIODIC" | "SPORADIC" | "EVENTDRIVEN") {
            let slot = if matches!(up.as_str(), "STATIC" | "UNIQUE" | "COMMUTATIVE") {
                &mut b.component_type
            } else {
                &mut b.component_kind
            };
            if slot.is_none() {
                *slot = Some(a);
                b.activity_type = None;
            }
        }
    }
    if b.name.is_none() {
        b.name = imp
            .spec_value("type_name")
            .and_then(|s| s.value.as_deref())
            .or(Some(fallback))
            .and_then(text);
    }
    b.pos = imp.spec.first().map(|s| s.at.pos).unwrap_or_default();
    p.basic_info = b;
    p.language = Some(crate::model::Language {
        kind: text(language.as_deref().unwrap_or(imp.language.name())),
        ..Default::default()
    });
    p.actions = actions(imp);
    p.data_ports = data_ports(imp, &mut unread);
    p.service_ports = service_ports(imp);
    let configurations = configurations(imp, defaults, conf_types, conf_props);
    for c in configurations.iter().filter(|c| c.type_.is_none()) {
        let name = s(&c.name).unwrap_or("");
        let bound = imp.parameters.iter().find(|p| p.name == name);
        unread.push(UnreadValue {
            field: format!("configurationSet/{name}/type"),
            written: match bound {
                Some(p) => format!("the declaration of `{}` was not found", p.variable),
                None => "no bindParameter names it".into(),
            },
            at: bound.map_or_else(
                || {
                    imp.spec_value(&format!("conf.default.{name}"))
                        .map(|v| v.at.clone())
                        .unwrap_or_default()
                },
                |p| p.at.clone(),
            ),
        });
    }
    if !configurations.is_empty() {
        p.configuration_set = Some(ConfigurationSet {
            configurations,
            ..Default::default()
        });
    }
    (p, Recovered { unread })
}

/// The profile field of a spec array key (`version` → `basicInfo/version`).
fn spec_field(key: &str) -> String {
    if let Some(el) = super::drift::spec_element(key) {
        return el.to_string();
    }
    match key.strip_prefix("conf.default.") {
        Some(n) => format!("configurationSet/{n}/defaultValue"),
        None => format!("spec/{key}"),
    }
}

/// `conf.__widget__.x` → (`x`, `__widget__`): the parameter properties RTCBuilder keeps.
fn conf_property(key: &str) -> Option<(&str, &'static str)> {
    for prop in [
        "__widget__",
        "__constraints__",
        "__description__",
        "__step__",
    ] {
        if let Some(n) = key
            .strip_prefix("conf.")
            .and_then(|k| k.strip_prefix(prop))
            .and_then(|k| k.strip_prefix('.'))
        {
            return Some((n, prop));
        }
    }
    None
}

fn actions(imp: &Implementation) -> Vec<Action> {
    ActionKind::ALL
        .iter()
        .zip(super::extract::CALLBACKS)
        .map(|(&kind, name)| {
            let cb = imp.callbacks.iter().find(|c| c.name == *name);
            // onInitialize holds the registrations: defined at all, it is implemented.
            let implemented = cb.is_some_and(|c| c.implemented || kind == ActionKind::OnInitialize);
            Action {
                kind,
                implemented: text(if implemented { "true" } else { "false" }),
                doc: None,
                pos: cb.map(|c| c.at.pos).unwrap_or_default(),
                extra: Default::default(),
            }
        })
        .collect()
}

/// A data type as a profile writes it: Python's `RTC.TimedLong` is `RTC::TimedLong`.
fn profile_type(t: &str) -> String {
    if t.contains("::") {
        t.to_string()
    } else {
        t.replace('.', "::")
    }
}

fn data_ports(imp: &Implementation, unread: &mut Vec<UnreadValue>) -> Vec<DataPort> {
    let mut seen = std::collections::HashSet::new();
    imp.data_ports
        .iter()
        .filter(|d| seen.insert(d.name.clone()))
        .map(|d| {
            if d.data_type.is_none() {
                unread.push(UnreadValue {
                    field: format!("dataPorts/{}/type", d.name),
                    written: format!("the declaration of `{}` was not found", d.variable),
                    at: d.at.clone(),
                });
            }
            DataPort {
                port_type: text(match d.direction {
                    Direction::Out => "DataOutPort",
                    _ => "DataInPort",
                }),
                name: text(&d.name),
                type_: d
                    .data_type
                    .as_deref()
                    .map(profile_type)
                    .as_deref()
                    .and_then(text),
                variable_name: text(d.variable.trim_start_matches("self._d_")),
                pos: d.at.pos,
                ..Default::default()
            }
        })
        .collect()
}

fn service_ports(imp: &Implementation) -> Vec<ServicePort> {
    imp.service_ports
        .iter()
        .filter_map(|s| {
            Some(ServicePort {
                name: text(s.name.as_deref()?),
                interfaces: s
                    .interfaces
                    .iter()
                    .map(|i| ServiceInterface {
                        name: text(&i.instance_name),
                        type_: i
                            .type_name
                            .as_deref()
                            .map(profile_type)
                            .as_deref()
                            .and_then(text),
                        direction: text(i.direction.profile_word()),
                        instance_name: text(&i.instance_name),
                        pos: i.at.pos,
                        ..Default::default()
                    })
                    .collect(),
                pos: s.at.pos,
                ..Default::default()
            })
        })
        .collect()
}

/// A C++ variable's type as a profile writes a parameter's (`std::string` → `string`).
fn parameter_type(t: &str) -> String {
    t.trim().trim_start_matches("std::").replace("std::", "")
}

fn configurations(
    imp: &Implementation,
    defaults: Vec<(String, String)>,
    types: Vec<(String, String)>,
    props: Vec<(String, &'static str, String)>,
) -> Vec<Configuration> {
    let mut out: Vec<Configuration> = Vec::new();
    for c in &imp.parameters {
        if out
            .iter()
            .any(|o| o.name.as_deref() == Some(c.name.as_str()))
        {
            continue;
        }
        out.push(Configuration {
            name: text(&c.name),
            type_: c
                .type_
                .as_deref()
                .map(parameter_type)
                .as_deref()
                .and_then(text),
            default_value: c.default.as_deref().and_then(text),
            variable_name: text(c.variable.trim_start_matches("self._")),
            pos: c.at.pos,
            ..Default::default()
        });
    }
    // The spec array's defaults are what the component starts with; one no bindParameter
    // names is a parameter all the same.
    for (name, v) in defaults {
        match out
            .iter_mut()
            .find(|o| o.name.as_deref() == Some(name.as_str()))
        {
            Some(o) => o.default_value = text(&v),
            None => out.push(Configuration {
                name: text(&name),
                default_value: text(&v),
                ..Default::default()
            }),
        }
    }
    for (name, t) in types {
        if let Some(o) = out
            .iter_mut()
            .find(|o| o.name.as_deref() == Some(name.as_str()))
        {
            o.type_ = text(&t);
        }
    }
    for (name, prop, v) in props {
        if let Some(o) = out
            .iter_mut()
            .find(|o| o.name.as_deref() == Some(name.as_str()))
        {
            o.properties.push(Property {
                name: text(prop),
                value: text(&v),
                ..Default::default()
            });
        }
    }
    out
}

/// One profile `rtcdoc extract` writes: where, for which component, and its text.
#[derive(Debug, Clone)]
pub struct Extracted {
    /// The file to write: `RTC.xml` in the component folder, `<Name>.xml` when several
    /// components share it.
    pub target: PathBuf,
    /// A profile documents the component's folder already (`rtcdoc check` compares the two):
    /// it is written only when asked to overwrite.
    pub documented: bool,
    pub found: Found,
    pub xml: String,
}

/// The `RTC.xml` of every component implemented below `input` (a folder, or one source
/// file), whether or not a profile documents it already. Files are named relative to `input`
/// (the folder of a file named). The `<Name>.xml` of a folder of several components is named
/// after the file holding each one's spec array.
pub fn extract(input: &Path, max_size: u64) -> anyhow::Result<Vec<Extracted>> {
    let mut profiles: std::collections::HashMap<String, Vec<PathBuf>> = Default::default();
    let code: Vec<(PathBuf, String)> = if input.is_file() {
        let name = input
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if !is_code_file(input) {
            anyhow::bail!(
                "`{}` is not a C++, Python or Java source file (.cpp, .cc, .cxx, .py, .java); name the file holding the spec array, or its folder",
                input.display()
            );
        }
        vec![(input.to_path_buf(), name)]
    } else {
        let c = crate::walk::candidates(input, &crate::walk::WalkOptions::default())?;
        for (path, rel) in &c.files {
            let head = crate::walk::read_at_most(path, 64 * 1024).unwrap_or_default();
            if !crate::walk::is_backup(path) && crate::walk::detect(path, &head).is_some() {
                let both = profile_folders(rel);
                let n = if both[0] == both[1] { 1 } else { 2 };
                for folder in &both[..n] {
                    profiles
                        .entry(folder.to_string())
                        .or_default()
                        .push(path.clone());
                }
            }
        }
        c.code
    };
    let (found, _) = find_all(&code, &std::collections::HashSet::new(), max_size);
    let now = extraction_time();
    let mut per_folder: std::collections::HashMap<String, usize> = Default::default();
    for f in &found {
        *per_folder
            .entry(component_folder(&f.source).to_string())
            .or_default() += 1;
    }
    let base = if input.is_file() {
        input.parent().unwrap_or(Path::new("")).to_path_buf()
    } else {
        input.to_path_buf()
    };
    Ok(found
        .into_iter()
        .map(|f| {
            let folder = component_folder(&f.source);
            let existing = profiles.get(folder).map_or(&[][..], Vec::as_slice);
            // The one profile of a folder of one component is the one to replace.
            if let ([only], 1) = (existing, per_folder[folder]) {
                let xml = rtc_xml(&f.profile, &f.recovered, &f.implementation.files, now);
                return Extracted {
                    target: only.clone(),
                    documented: true,
                    found: f,
                    xml,
                };
            }
            let file = if per_folder[folder] > 1 {
                // The spec array's file's name: an existing, safe file name.
                let stem = Path::new(&f.source)
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                format!("{stem}.xml")
            } else {
                "RTC.xml".to_string()
            };
            let xml = rtc_xml(&f.profile, &f.recovered, &f.implementation.files, now);
            Extracted {
                target: base.join(folder).join(file),
                documented: !existing.is_empty(),
                found: f,
                xml,
            }
        })
        .collect())
}

/// XML attribute text.
fn attr(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' => out.push_str("&#9;"),
            c => out.push(c),
        }
    }
    out
}

/// ` rtc:key="value"` for each value present, in order.
fn attrs(pairs: &[(&str, Option<&str>)]) -> String {
    pairs
        .iter()
        .filter_map(|(k, v)| v.map(|v| format!(" {k}=\"{}\"", attr(v))))
        .collect()
}

/// `seconds` since 1970 as RTCBuilder writes a date (`2013-06-12T09:26:16+00:00`, UTC).
fn rtcbuilder_date(seconds: u64) -> String {
    let days = (seconds / 86_400) as i64;
    let rem = seconds % 86_400;
    // Days to a proleptic Gregorian date (eras of 400 years from 0000-03-01).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1_460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}+00:00",
        rem / 3_600,
        rem / 60 % 60,
        rem % 60
    )
}

/// The time a profile is extracted at: `SOURCE_DATE_EPOCH` when set (reproducible output),
/// else now.
pub fn extraction_time() -> u64 {
    std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs())
        })
}

/// The values RTCBuilder always writes that no spec array holds, at RTCBuilder's defaults
/// (named in a comment of the file), and the dates of `now`.
fn with_rtcbuilder_defaults(b: &BasicInfo, now: u64) -> (BasicInfo, Vec<&'static str>) {
    let mut b = b.clone();
    let mut defaulted = Vec::new();
    for (slot, value, name) in [
        (&mut b.component_type, "STATIC", "componentType"),
        (&mut b.activity_type, "PERIODIC", "activityType"),
        (&mut b.component_kind, "DataFlowComponent", "componentKind"),
        (
            &mut b.execution_type,
            "PeriodicExecutionContext",
            "executionType",
        ),
    ] {
        if slot.is_none() {
            *slot = text(value);
            defaulted.push(name);
        }
    }
    let date = rtcbuilder_date(now);
    b.creation_date = text(&date);
    b.update_date = text(&date);
    // `type_name` is the name again (RTCBuilder writes both from it).
    b.properties
        .retain(|p| !(s(&p.name) == Some("type_name") && s(&p.value) == s(&b.name)));
    (b, defaulted)
}

/// The `RTC.xml` of `p` as RTCBuilder writes it (profile version 0.2, the `rtcExt`
/// extensions), dated `now` (seconds since 1970), with a comment naming each value of `r` the
/// code does not spell out and each RTCBuilder default filled in.
pub fn rtc_xml(p: &Profile, r: &Recovered, from: &[String], now: u64) -> String {
    let (b, defaulted) = with_rtcbuilder_defaults(&p.basic_info, now);
    let b = &b;
    // Files are named relative to the component folder, where the profile is written.
    let folder = from.first().map_or("", |f| component_folder(f));
    let local = |f: &str| -> String {
        let f = f.strip_prefix(folder).unwrap_or(f);
        f.trim_start_matches('/').replace("--", "- -")
    };
    let from: Vec<String> = from.iter().map(|f| local(f)).collect();
    let id = format!(
        "RTC:{}:{}:{}:{}",
        s(&b.vendor).unwrap_or(""),
        s(&b.category).unwrap_or(""),
        s(&b.name).unwrap_or(""),
        s(&b.version).unwrap_or("")
    );
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n");
    x.push_str(&format!(
        "<!-- Recovered by rtcdoc extract from {}. -->\n",
        from.join(", ")
    ));
    if !defaulted.is_empty() {
        x.push_str(&format!(
            "<!-- {} are RTCBuilder's defaults: the code does not say. -->\n",
            defaulted.join(", ")
        ));
    }
    for u in &r.unread {
        x.push_str(&format!(
            "<!-- {} is not read from the code ({} at {}:{}): set it. -->\n",
            u.field,
            u.written.replace("--", "- -"),
            local(&u.at.file),
            u.at.pos.line
        ));
    }
    x.push_str(&format!(
        "<rtc:RtcProfile rtc:version=\"0.2\" rtc:id=\"{}\" xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\" xmlns:rtcExt=\"http://www.openrtp.org/namespaces/rtc_ext\" xmlns:rtcDoc=\"http://www.openrtp.org/namespaces/rtc_doc\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n",
        attr(&id)
    ));
    x.push_str(&format!(
        "    <rtc:BasicInfo xsi:type=\"rtcExt:basic_info_ext\"{}>\n",
        attrs(&[
            ("rtc:name", s(&b.name)),
            ("rtc:componentType", s(&b.component_type)),
            ("rtc:activityType", s(&b.activity_type)),
            ("rtc:componentKind", s(&b.component_kind)),
            ("rtc:category", s(&b.category)),
            ("rtc:description", s(&b.description)),
            ("rtc:executionRate", s(&b.execution_rate)),
            ("rtc:executionType", s(&b.execution_type)),
            ("rtc:maxInstances", s(&b.max_instances)),
            ("rtc:vendor", s(&b.vendor)),
            ("rtc:version", s(&b.version)),
            ("rtc:creationDate", s(&b.creation_date)),
            ("rtc:updateDate", s(&b.update_date)),
        ])
    ));
    properties_xml(&mut x, "        ", &b.properties);
    x.push_str("    </rtc:BasicInfo>\n    <rtc:Actions>\n");
    for a in &p.actions {
        x.push_str(&format!(
            "        <rtc:{} xsi:type=\"rtcDoc:action_status_doc\"{}/>\n",
            a.kind.xml_name(),
            attrs(&[("rtc:implemented", s(&a.implemented))])
        ));
    }
    x.push_str("    </rtc:Actions>\n");
    configuration_xml(&mut x, p);
    for d in &p.data_ports {
        x.push_str(&format!(
            "    <rtc:DataPorts xsi:type=\"rtcExt:dataport_ext\"{}/>\n",
            attrs(&[
                ("rtcExt:variableName", s(&d.variable_name)),
                ("rtc:type", s(&d.type_)),
                ("rtc:name", s(&d.name)),
                ("rtc:portType", s(&d.port_type)),
            ])
        ));
    }
    for sp in &p.service_ports {
        x.push_str(&format!(
            "    <rtc:ServicePorts xsi:type=\"rtcExt:serviceport_ext\"{}>\n",
            attrs(&[("rtc:name", s(&sp.name))])
        ));
        for i in &sp.interfaces {
            x.push_str(&format!(
                "        <rtc:ServiceInterface xsi:type=\"rtcExt:serviceinterface_ext\"{}/>\n",
                attrs(&[
                    ("rtc:type", s(&i.type_)),
                    ("rtc:instanceName", s(&i.instance_name)),
                    ("rtc:direction", s(&i.direction)),
                    ("rtc:name", s(&i.name)),
                ])
            ));
        }
        x.push_str("    </rtc:ServicePorts>\n");
    }
    if let Some(l) = &p.language {
        x.push_str(&format!(
            "    <rtc:Language xsi:type=\"rtcExt:language_ext\"{}/>\n",
            attrs(&[("rtc:kind", s(&l.kind))])
        ));
    }
    x.push_str("</rtc:RtcProfile>\n");
    x
}

/// `<rtcExt:Properties rtcExt:name=… rtcExt:value=…/>` lines, as RTCBuilder writes them.
fn properties_xml(x: &mut String, indent: &str, props: &[Property]) {
    for prop in props {
        x.push_str(&format!(
            "{indent}<rtcExt:Properties{}/>\n",
            attrs(&[
                ("rtcExt:name", s(&prop.name)),
                ("rtcExt:value", s(&prop.value))
            ])
        ));
    }
}

fn configuration_xml(x: &mut String, p: &Profile) {
    let Some(set) = &p.configuration_set else {
        return;
    };
    x.push_str("    <rtc:ConfigurationSet>\n");
    for c in &set.configurations {
        let head = format!(
            "        <rtc:Configuration xsi:type=\"rtcExt:configuration_ext\"{}",
            attrs(&[
                ("rtcExt:variableName", s(&c.variable_name)),
                ("rtc:defaultValue", s(&c.default_value)),
                ("rtc:type", s(&c.type_)),
                ("rtc:name", s(&c.name)),
            ])
        );
        if c.properties.is_empty() {
            x.push_str(&head);
            x.push_str("/>\n");
            continue;
        }
        x.push_str(&head);
        x.push_str(">\n");
        properties_xml(x, "            ", &c.properties);
        x.push_str("        </rtc:Configuration>\n");
    }
    x.push_str("    </rtc:ConfigurationSet>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn component_folder_is_above_src() {
        assert_eq!(component_folder("rtc/Foo/Foo.cpp"), "rtc/Foo");
        assert_eq!(component_folder("Foo/src/Foo.cpp"), "Foo");
        assert_eq!(component_folder("Foo/src/pkg/a/FooImpl.java"), "Foo");
        assert_eq!(component_folder("src/Foo.cpp"), "");
        assert_eq!(component_folder("Foo.py"), "");
        assert_eq!(profile_folders("Foo/RTC.xml"), ["Foo", "Foo"]);
        assert_eq!(profile_folders("Foo/src/RTC.xml"), ["Foo/src", "Foo"]);
    }

    #[test]
    fn dates_as_rtcbuilder_writes_them() {
        assert_eq!(rtcbuilder_date(0), "1970-01-01T00:00:00+00:00");
        assert_eq!(rtcbuilder_date(951_782_400), "2000-02-29T00:00:00+00:00");
        assert_eq!(rtcbuilder_date(1_796_687_999), "2026-12-07T23:59:59+00:00");
    }

    #[test]
    fn attribute_text_is_escaped() {
        assert_eq!(attr("a<b & \"c\"\n"), "a&lt;b &amp; &quot;c&quot;&#10;");
    }
}
