//! What a page shows, independent of the output format.
//!
//! Every renderer (HTML, Markdown, Doxygen) lists the same values for a component, a port, an
//! interface or a configuration parameter. This module turns the model into rows of
//! ([`Fact::label`], [`Fact::value`]) — labels already translated through [`Lang::t`], values as
//! the profile wrote them (trimmed; empty values left out, see [`model::non_empty`]). Both are
//! *unescaped* plain text: each renderer escapes them for its own format.
//!
//! Values that a renderer shows in a dedicated column (a port's name, direction, type and
//! description) are not repeated here; everything else the profile holds is.

use crate::catalog::Component;
use crate::constraint;
use crate::i18n::Lang;
use crate::model::{
    self, Action, BasicDoc, Configuration, DataPort, Extra, ExtraKind, Language, Parameter,
    Profile, Property, ServiceInterface, ServicePort, Target,
};
use crate::types::canonical_type;
use std::borrow::Cow;

/// What kind of value a [`Fact`] holds, for renderers that present the two differently.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FactKind {
    /// A plain value: an identifier, a number, a date, a type name.
    #[default]
    Value,
    /// Free text written for humans (descriptions, comments, algorithm notes), which may hold
    /// Markdown; the HTML site renders it as sanitised Markdown.
    Text,
    /// A short documented value (a data name, range, unit, number, occurrence): Markdown inside
    /// its lines (code spans, emphasis) but never a block, so that a range written `> 0.01` is
    /// a comparison and not a quotation, and `# of samples` no heading. The Markdown and
    /// Doxygen outputs show every free text that way.
    Phrase,
}

/// One labelled value of a page.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fact {
    /// A translated label, or a name taken from the profile (property names, extra paths).
    pub label: Cow<'static, str>,
    /// The value as the profile wrote it (plain text, may contain line breaks).
    pub value: String,
    /// Whether the value is a plain value or free text.
    pub kind: FactKind,
}

impl Fact {
    /// A plain-value fact ([`FactKind::Value`]).
    pub fn new(label: impl Into<Cow<'static, str>>, value: impl Into<String>) -> Fact {
        Fact {
            label: label.into(),
            value: value.into(),
            kind: FactKind::Value,
        }
    }
}

/// Collects facts, skipping absent and empty values.
struct Facts {
    lang: Lang,
    out: Vec<Fact>,
}

impl Facts {
    fn new(lang: Lang) -> Facts {
        Facts {
            lang,
            out: Vec::new(),
        }
    }
    /// Like [`Facts::opt`] for a Basic Profile value RTCBuilder may leave as its placeholder
    /// ([`model::is_placeholder`] of `field`): such a value is shown as written, said to be
    /// the placeholder. With `only_placeholder`, a value that is not one is left out (the
    /// description, which pages show as their lead text).
    fn basic(
        &mut self,
        (key, field): (&'static str, &str),
        v: &Option<crate::model::Text>,
        only_placeholder: bool,
    ) -> &mut Self {
        match model::non_empty(v) {
            Some(s) if model::is_placeholder(field, s) => {
                let note = self.lang.t("fact_placeholder");
                self.out
                    .push(Fact::new(self.lang.t(key), format!("{s} ({note})")));
                self
            }
            Some(_) if only_placeholder => self,
            _ => self.opt(key, v),
        }
    }
    fn opt(&mut self, key: &'static str, v: &Option<crate::model::Text>) -> &mut Self {
        if let Some(s) = model::non_empty(v) {
            self.out.push(Fact::new(self.lang.t(key), s));
        }
        self
    }
    /// Like [`Facts::opt`], for free text ([`FactKind::Text`]).
    fn md(&mut self, key: &'static str, v: &Option<crate::model::Text>) -> &mut Self {
        self.md_str(key, model::non_empty(v))
    }
    fn text(&mut self, key: &'static str, v: &str) -> &mut Self {
        let v = v.trim();
        if !v.is_empty() {
            self.out.push(Fact::new(self.lang.t(key), v));
        }
        self
    }
    fn list<S: AsRef<str>>(&mut self, key: &'static str, v: &[S]) -> &mut Self {
        let items: Vec<&str> = v
            .iter()
            .map(|s| s.as_ref().trim())
            .filter(|s| !s.is_empty())
            .collect();
        if !items.is_empty() {
            self.out.push(Fact::new(self.lang.t(key), items.join(", ")));
        }
        self
    }
    fn properties(&mut self, props: &[Property], skip: &[&str]) -> &mut Self {
        for p in props {
            let name = p.name.as_deref().map(str::trim).unwrap_or("");
            if skip.contains(&name) {
                continue;
            }
            let value = model::non_empty(&p.value).unwrap_or("");
            if name.is_empty() && value.is_empty() {
                continue;
            }
            let label = if name.is_empty() {
                Cow::Borrowed(self.lang.t("properties"))
            } else {
                property_label(name, self.lang)
            };
            self.out.push(Fact::new(label, value));
        }
        self
    }
    /// The Document Profile of a data port or an FSM event, except its description. A
    /// documented type equal to `type_` and a documented unit equal to `unit` (the values shown
    /// already) are not repeated.
    fn data_doc(
        &mut self,
        d: &model::DataPortDoc,
        type_: Option<&str>,
        unit: Option<&str>,
    ) -> &mut Self {
        let doc_type = model::non_empty(&d.type_)
            .filter(|t| type_.map(canonical_type) != Some(canonical_type(t)));
        let doc_unit = model::non_empty(&d.unit).filter(|u| unit != Some(*u));
        self.phrase_str("fact_doc_type", doc_type)
            .phrase("fact_number", &d.number)
            .md("fact_semantics", &d.semantics)
            .phrase_str("fact_doc_unit", doc_unit)
            .phrase("fact_occurrence", &d.occurrence)
            .phrase("fact_operation", &d.operation)
    }
    /// [`Facts::md`] for a value already trimmed and checked non-empty.
    fn md_str(&mut self, key: &'static str, v: Option<&str>) -> &mut Self {
        self.kind_str(key, v, FactKind::Text)
    }
    /// Like [`Facts::md`], for a short documented value ([`FactKind::Phrase`]).
    fn phrase(&mut self, key: &'static str, v: &Option<crate::model::Text>) -> &mut Self {
        self.kind_str(key, model::non_empty(v), FactKind::Phrase)
    }
    /// [`Facts::phrase`] for a value already trimmed and checked non-empty.
    fn phrase_str(&mut self, key: &'static str, v: Option<&str>) -> &mut Self {
        self.kind_str(key, v, FactKind::Phrase)
    }
    fn kind_str(&mut self, key: &'static str, v: Option<&str>, kind: FactKind) -> &mut Self {
        if let Some(s) = v {
            let mut f = Fact::new(self.lang.t(key), s);
            f.kind = kind;
            self.out.push(f);
        }
        self
    }
    fn done(&mut self) -> Vec<Fact> {
        std::mem::take(&mut self.out)
    }
}

/// The label of a property: a translated one for the keys RTCBuilder gives a meaning (`FSM`,
/// `FSMType`, `__container__lib_N`, the `__iso__` keys of ISO 22166-202 profiles, whose
/// name is kept after the standard's), the name as written for any other.
pub fn property_label(name: &str, lang: Lang) -> Cow<'static, str> {
    if let Some(rest) = name.strip_prefix("__iso__").filter(|r| !r.is_empty()) {
        return Cow::Owned(format!("{}: {rest}", lang.t("prop_iso")));
    }
    if let Some(n) = name
        .strip_prefix("__container__lib_")
        .filter(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
    {
        return Cow::Owned(format!("{} {n}", lang.t("prop_container_lib")));
    }
    match name {
        "FSM" => Cow::Borrowed(lang.t("prop_fsm")),
        "FSMType" => Cow::Borrowed(lang.t("prop_fsm_type")),
        _ => Cow::Owned(name.to_string()),
    }
}

/// The execution rate with its unit (spec 2.3.2: Hz) when it is a number; as written otherwise.
fn hertz(rate: &str) -> String {
    let r = rate.trim();
    if !r.is_empty() && r.parse::<f64>().is_ok() {
        format!("{r} Hz")
    } else {
        rate.to_string()
    }
}

/// Header fields of a component page (Basic Profile, spec 2.3.2, and its extended part), in a
/// fixed order. Name and description are left out: pages show them as title and lead text
/// (a description that is RTCBuilder's placeholder is no lead: it is listed here, as the
/// placeholder it is).
pub fn basic_info(c: &Component, lang: Lang) -> Vec<Fact> {
    let p = &c.profile;
    let b = &p.basic_info;
    Facts::new(lang)
        .opt("fact_id", &p.id)
        .basic(("description", "description"), &b.description, true)
        .basic(("category", "category"), &b.category, false)
        .basic(("vendor", "vendor"), &b.vendor, false)
        .opt("version", &b.version)
        .opt("component_type", &b.component_type)
        .opt("activity_type", &b.activity_type)
        .opt("component_kind", &b.component_kind)
        .opt("fact_rtc_type", &b.rtc_type)
        .opt("execution_type", &b.execution_type)
        .opt(
            "execution_rate",
            &b.execution_rate
                .as_ref()
                .map(|r| crate::model::Text::from(hertz(r))),
        )
        .opt("max_instances", &b.max_instances)
        .md("fact_abstract", &b.abstract_)
        .opt("fact_hardware_profile", &b.hardware_profile)
        .opt("creation_date", &b.creation_date)
        .opt("update_date", &b.update_date)
        .md("fact_comment", &b.comment)
        .opt("fact_save_project", &b.save_project)
        .opt("fact_profile_version", &p.version)
        .text("source", &c.source)
        .done()
}

/// The component's Document Profile (spec 2.4.2).
pub fn document(d: &BasicDoc, lang: Lang) -> Vec<Fact> {
    Facts::new(lang)
        .md("description", &d.description)
        .md("inout", &d.inout)
        .md("algorithm", &d.algorithm)
        .md("creator", &d.creator)
        .md("license", &d.license)
        .md("reference", &d.reference)
        .done()
}

/// Everything about a data port except name, port type, data type and description (shown in
/// their own columns): transport attributes, constraint, the rest of its Document Profile,
/// extended attributes, properties and FSM events.
pub fn data_port(p: &DataPort, lang: Lang) -> Vec<Fact> {
    let mut out = data_port_attributes(p, lang);
    out.extend(
        p.events
            .iter()
            .map(|e| Fact::new(lang.t("fact_event"), event_text(e))),
    );
    out
}

/// [`data_port`] without the FSM events, for renderers that list events on their own
/// (see [`event`]).
pub fn data_port_attributes(p: &DataPort, lang: Lang) -> Vec<Fact> {
    data_port_facts(p, lang, true)
}

/// [`data_port_attributes`] without the unit, for renderers that show it in a column of its
/// own ([`data_port_unit`]).
pub fn data_port_attributes_without_unit(p: &DataPort, lang: Lang) -> Vec<Fact> {
    data_port_facts(p, lang, false)
}

fn data_port_facts(p: &DataPort, lang: Lang, with_unit: bool) -> Vec<Fact> {
    let mut f = Facts::new(lang);
    let unit = data_port_unit(p);
    f.opt("fact_idl_file", &p.idl_file)
        .opt("fact_interface_type", &p.interface_type)
        .opt("fact_dataflow_type", &p.dataflow_type)
        .opt("fact_subscription_type", &p.subscription_type)
        .text("unit", unit.filter(|_| with_unit).unwrap_or(""));
    // RTCBuilder's `dp_constraint` placeholder constrains nothing (RTC306): not shown.
    if let Some(c) = p.constraint.as_ref().filter(|c| c.placeholder().is_none()) {
        f.text("constraint", &constraint::describe_in(c, lang));
    }
    if let Some(d) = &p.doc {
        f.data_doc(d, model::non_empty(&p.type_), unit);
    }
    f.md("fact_comment", &p.comment)
        .opt("fact_variable_name", &p.variable_name)
        .opt("fact_position", &p.position)
        .properties(&p.properties, &[])
        .done()
}

/// Everything about one FSM event except its name: type, source, target, condition and its
/// Document Profile.
pub fn event(e: &model::Event, lang: Lang) -> Vec<Fact> {
    let mut f = Facts::new(lang);
    f.opt("type", &e.type_)
        .opt("source", &e.source)
        .opt("event_target", &e.target)
        .opt("condition", &e.condition);
    if let Some(d) = &e.doc {
        f.md("description", &d.description)
            .data_doc(d, model::non_empty(&e.type_), None);
    }
    f.done()
}

/// One FSM event as a line: `name: type (source → target) [condition] description`.
fn event_text(e: &model::Event) -> String {
    let mut s = model::non_empty(&e.name).unwrap_or("").to_string();
    if let Some(t) = model::non_empty(&e.type_) {
        s.push_str(&format!(": {t}"));
    }
    let src = model::non_empty(&e.source);
    let dst = model::non_empty(&e.target);
    if src.is_some() || dst.is_some() {
        s.push_str(&format!(
            " ({} → {})",
            src.unwrap_or("?"),
            dst.unwrap_or("?")
        ));
    }
    if let Some(c) = model::non_empty(&e.condition) {
        s.push_str(&format!(" [{c}]"));
    }
    if let Some(d) = e
        .doc
        .as_ref()
        .and_then(|d| model::non_empty(&d.description))
    {
        s.push_str(&format!(" {d}"));
    }
    s
}

/// The unit of a data port: its own (`rtcExt:unit`), else the one its Document Profile gives.
/// Shown once, as the unit; a documented unit that differs from the port's own is listed as
/// well.
pub fn data_port_unit(p: &DataPort) -> Option<&str> {
    model::non_empty(&p.unit).or_else(|| p.doc.as_ref().and_then(|d| model::non_empty(&d.unit)))
}

/// The unit of a configuration parameter: its own, else the one its Document Profile gives.
pub fn configuration_unit(c: &Configuration) -> Option<&str> {
    model::non_empty(&c.unit).or_else(|| c.doc.as_ref().and_then(|d| model::non_empty(&d.unit)))
}

/// The editor widget of a configuration parameter with its meaning and step, for a Widget
/// column: `slider.0.1 (slider, step 0.1)`, `radio (radio buttons)`.
pub fn configuration_widget(c: &Configuration, lang: Lang) -> Option<String> {
    let w = c.widget().map(str::trim).filter(|w| !w.is_empty());
    let step = c.step().map(str::trim).filter(|s| !s.is_empty());
    match (w, step) {
        (Some(w), Some(s)) => Some(format!(
            "{}, {} {s}",
            widget_text(w, lang),
            lang.t("fact_step")
        )),
        (Some(w), None) => Some(widget_text(w, lang)),
        (None, Some(s)) => Some(format!("{} {s}", lang.t("fact_step"))),
        (None, None) => None,
    }
}

/// Port-level facts of a service port (its interfaces are listed separately).
pub fn service_port(p: &ServicePort, lang: Lang) -> Vec<Fact> {
    let mut f = Facts::new(lang);
    if let Some(d) = &p.doc {
        f.md("description", &d.description)
            .md("fact_if_description", &d.ifdescription);
    }
    let kinds: Vec<String> = p
        .trans_methods
        .iter()
        .filter_map(|t| model::non_empty(&t.kind).map(str::to_string))
        .collect();
    f.list("fact_trans_methods", &kinds)
        .md("fact_comment", &p.comment)
        .opt("fact_position", &p.position)
        .properties(&p.properties, &[])
        .done()
}

/// Everything about a service interface except name, direction, type and description.
pub fn service_interface(i: &ServiceInterface, lang: Lang) -> Vec<Fact> {
    let mut f = Facts::new(lang);
    f.opt("fact_instance_name", &i.instance_name)
        .opt("fact_idl_file", &i.idl_file)
        .opt("fact_path", &i.path);
    if let Some(d) = &i.doc {
        f.md("fact_doc_argument", &d.doc_argument)
            .md("fact_doc_return", &d.doc_return)
            .md("fact_doc_exception", &d.doc_exception)
            .md("pre_condition", &d.doc_pre_condition)
            .md("post_condition", &d.doc_post_condition);
    }
    f.md("fact_comment", &i.comment)
        .opt("fact_variable_name", &i.variable_name)
        .properties(&i.properties, &[])
        .done()
}

/// The constraint of a configuration parameter for humans (shared [`constraint::describe_in`]).
pub fn configuration_constraint(c: &Configuration, lang: Lang) -> Option<String> {
    c.constraint
        .as_ref()
        .filter(|k| k.placeholder().is_none())
        .map(|k| constraint::describe_in(k, lang))
        .filter(|s| !s.trim().is_empty())
}

/// Everything about a configuration parameter except name, type, default value, unit,
/// constraint and description: the rest of its Document Profile, the editor widget and step
/// (`__widget__`, `__step__`, with their meaning), extended attributes and other properties.
pub fn configuration(c: &Configuration, lang: Lang) -> Vec<Fact> {
    let mut f = configuration_doc(c, lang);
    if let Some(w) = c.widget().map(str::trim).filter(|w| !w.is_empty()) {
        f.text("fact_widget", &widget_text(w, lang));
    }
    if let Some(s) = c.step() {
        f.text("fact_step", s);
    }
    f.configuration_rest(c).done()
}

/// [`configuration`] without the widget and its step, for renderers that show them in a
/// column of their own ([`configuration_widget`]).
pub fn configuration_without_widget(c: &Configuration, lang: Lang) -> Vec<Fact> {
    configuration_doc(c, lang).configuration_rest(c).done()
}

/// The Document Profile of a configuration parameter except its description; a documented
/// default equal to the default value and a documented unit equal to the unit shown
/// ([`configuration_unit`]) are not repeated.
fn configuration_doc(c: &Configuration, lang: Lang) -> Facts {
    let mut f = Facts::new(lang);
    if let Some(d) = &c.doc {
        let default = model::non_empty(&c.default_value);
        let unit = configuration_unit(c);
        f.phrase("fact_dataname", &d.dataname)
            .phrase_str(
                "fact_doc_default",
                model::non_empty(&d.default_value).filter(|v| default != Some(*v)),
            )
            .phrase_str(
                "fact_doc_unit",
                model::non_empty(&d.unit).filter(|u| unit != Some(*u)),
            )
            .phrase("fact_range", &d.range)
            .phrase("fact_doc_constraint", &d.constraint);
    }
    f
}

impl Facts {
    /// The end of a configuration parameter's facts: comment, variable name, properties.
    fn configuration_rest(&mut self, c: &Configuration) -> &mut Self {
        self.md("fact_comment", &c.comment)
            .opt("fact_variable_name", &c.variable_name)
            .properties(&c.properties, &["__widget__", "__step__"])
    }
}

/// `slider.0.1` → `slider.0.1 (slider, step 0.1)`; `radio` → `radio (radio buttons)`.
fn widget_text(w: &str, lang: Lang) -> String {
    let (kind, rest) = match w.split_once('.') {
        Some((k, r)) => (k, Some(r)),
        None => (w, None),
    };
    let key = match kind.to_ascii_lowercase().as_str() {
        "text" => "fact_w_text",
        "radio" => "fact_w_radio",
        "slider" => "fact_w_slider",
        "spin" => "fact_w_spin",
        "checkbox" => "fact_w_checkbox",
        "ordered_list" => "fact_w_ordered_list",
        _ => return w.to_string(),
    };
    match rest.filter(|r| !r.is_empty()) {
        Some(step) => format!("{w} ({}, {} {step})", lang.t(key), lang.t("fact_step")),
        None => format!("{w} ({})", lang.t(key)),
    }
}

/// The Document Profile of a lifecycle action: description, pre- and post-condition.
pub fn action(a: Option<&Action>, lang: Lang) -> Vec<Fact> {
    let mut f = Facts::new(lang);
    if let Some(d) = a.and_then(|a| a.doc.as_ref()) {
        f.md("description", &d.description)
            .md("pre_condition", &d.pre_condition)
            .md("post_condition", &d.post_condition);
    }
    f.done()
}

/// A system parameter as (name, default value).
pub fn parameter(p: &Parameter) -> (&str, &str) {
    (
        model::non_empty(&p.name).unwrap_or(""),
        model::non_empty(&p.default_value).unwrap_or(""),
    )
}

/// The implementation language (spec 2.3.12).
pub fn language(l: &Language, lang: Lang) -> Vec<Fact> {
    Facts::new(lang).opt("language", &l.kind).done()
}

/// One target environment (spec 2.5.7) with its libraries.
pub fn target(t: &Target, lang: Lang) -> Vec<Fact> {
    let mut f = Facts::new(lang);
    f.opt("fact_lang_version", &t.lang_version)
        .opt("fact_os", &t.os)
        .list("fact_os_versions", &t.os_versions)
        .opt("fact_other", &t.other)
        .list("fact_cpus", &t.cpus)
        .opt("fact_cpu_other", &t.cpu_other);
    for l in &t.libraries {
        let mut s = model::non_empty(&l.name).unwrap_or("").to_string();
        for v in [&l.version, &l.other]
            .into_iter()
            .filter_map(model::non_empty)
        {
            if !s.is_empty() {
                s.push(' ');
            }
            s.push_str(v);
        }
        f.text("fact_library", &s);
    }
    f.done()
}

/// Component-level properties (`rtcExt:Properties` of BasicInfo), including `FSM` and
/// `__iso__*` keys.
pub fn component_properties(p: &Profile, lang: Lang) -> Vec<Fact> {
    Facts::new(lang)
        .properties(&p.basic_info.properties, &[])
        .done()
}

/// Non-empty version-up log entries.
pub fn version_up_logs(p: &Profile) -> Vec<&str> {
    p.basic_info
        .version_up_logs
        .iter()
        .map(|s| s.trim())
        .filter(|s| !s.is_empty())
        .collect()
}

/// Every extra (unknown) value of the profile, flattened: label = `path: name/child/…`,
/// value = the text (attributes of unknown elements become their own rows). Empty values
/// (wasanbon's `rtcDoc:license=""` …) make no row: they say nothing, and the JSON keeps them.
pub fn extras(p: &Profile) -> Vec<Fact> {
    extras_with_kind(p).into_iter().map(|(f, _)| f).collect()
}

/// [`extras`], each with the kind of node it came from (element, attribute or key).
pub fn extras_with_kind(p: &Profile) -> Vec<(Fact, ExtraKind)> {
    fn walk(prefix: &str, e: &Extra, out: &mut Vec<(Fact, ExtraKind)>) {
        let name = format!("{prefix}{}", e.name);
        let value = e.value.as_deref().map(str::trim).unwrap_or("");
        if !value.is_empty() {
            out.push((Fact::new(name.clone(), value), e.kind));
        }
        for c in &e.children {
            walk(&format!("{name}/"), c, out);
        }
    }
    let mut out = Vec::new();
    for (path, e) in p.all_extras() {
        walk(&format!("{path}: "), e, &mut out);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn empty_values_are_left_out_and_widgets_explained() {
        let mut c = Configuration {
            comment: Some("  ".into()),
            variable_name: Some("m_gain".into()),
            ..Default::default()
        };
        c.properties.push(Property {
            name: Some("__widget__".into()),
            value: Some("slider.0.5".into()),
            ..Default::default()
        });
        let f = configuration(&c, Lang::En);
        assert!(f.iter().all(|f| f.label != "Comment"));
        assert!(f.iter().any(|f| f.value == "m_gain"));
        assert!(f
            .iter()
            .any(|f| f.label == "Widget" && f.value == "slider.0.5 (slider, Step 0.5)"));
        assert!(
            f.iter().all(|f| f.label != "__widget__"),
            "widget is shown once"
        );
    }

    /// Property `key` is labelled `en` in English and `ja` in Japanese.
    fn labelled(key: &str, en: &str, ja: &str) {
        assert_eq!(property_label(key, Lang::En), en);
        assert_eq!(property_label(key, Lang::Ja), ja);
    }

    #[test]
    fn known_property_keys_get_labels() {
        labelled("FSM", "Finite state machine (FSM)", "有限状態機械 (FSM)");
        labelled("FSMType", "FSM type", "FSM の種類");
        labelled(
            "__container__lib_2",
            "Container library 2",
            "コンテナライブラリ 2",
        );
        labelled(
            "__iso__exeType_hardRT",
            "ISO 22166-202: exeType_hardRT",
            "ISO 22166-202: exeType_hardRT",
        );
        // A library suffix that is not a number, a bare prefix and unknown keys: as written.
        for key in ["__container__lib_x", "__iso__", "SIM_Version"] {
            labelled(key, key, key);
        }
    }
}

/// A row of the backups table: the file, when it was saved, what it declares (or why it could
/// not be read).
#[derive(serde::Serialize)]
pub struct BackupRow {
    pub file: String,
    pub saved: String,
    pub declares: String,
}

impl BackupRow {
    pub fn of(c: &crate::catalog::Component, lang: Lang) -> Vec<BackupRow> {
        c.backups
            .iter()
            .map(|b| BackupRow {
                file: b.file_name().to_string(),
                saved: b.saved.clone().unwrap_or_default(),
                declares: match &b.content {
                    crate::catalog::backups::BackupContent::Error(e) => {
                        format!("{}: {e}", lang.t("backup_unreadable"))
                    }
                    crate::catalog::backups::BackupContent::Profile(_) => {
                        let (name, version) = b.declares();
                        [name, version]
                            .into_iter()
                            .flatten()
                            .collect::<Vec<_>>()
                            .join(" ")
                    }
                },
            })
            .collect()
    }
}

/// At most this many peer components are named in a port's "connects to" answer, in every
/// output (and in the neighbourhood); the rest are counted and linked to the type or interface
/// page.
pub use crate::catalog::neighbourhood::{peer_groups, PEER_COMPONENTS_CAP};
/// At most this many ports of one peer component are named.
pub const PEER_PORTS_SHOWN: usize = 3;

/// `Camera · image, depth, +2`: a peer component and up to [`PEER_PORTS_SHOWN`] of its ports.
pub fn peer_text(component: &str, ports: &[&str], sep: &str) -> String {
    let mut s = String::with_capacity(component.len() + sep.len() + 16 * ports.len().min(4));
    s.push_str(component);
    s.push_str(sep);
    for (k, p) in ports.iter().take(PEER_PORTS_SHOWN).enumerate() {
        if k > 0 {
            s.push_str(", ");
        }
        s.push_str(p);
    }
    let rest = ports.len().saturating_sub(PEER_PORTS_SHOWN);
    if rest > 0 {
        use std::fmt::Write;
        let _ = write!(s, ", +{rest}");
    }
    s
}

/// The data-flow page's sections, in order: (grouping, anchor, heading label).
pub const DATAFLOW_SECTIONS: [(crate::catalog::dataflow::Grouping, &str, &str); 2] = [
    (
        crate::catalog::dataflow::Grouping::Category,
        "by-category",
        "dataflow_by_category",
    ),
    (
        crate::catalog::dataflow::Grouping::Vendor,
        "by-vendor",
        "dataflow_by_vendor",
    ),
];

/// At most this many data types are named on a row of the data-flow table; the rest counted.
pub const DATAFLOW_TYPES_SHOWN: usize = 3;

/// One row of a data-flow table: from which group to which, how many port pairs, over which
/// data types (the first [`DATAFLOW_TYPES_SHOWN`]) and how many more types.
pub struct FlowRow<'a> {
    /// The group's name as shown (the empty category or vendor has a translated name).
    pub from: (String, &'a crate::catalog::Page),
    pub to: (String, &'a crate::catalog::Page),
    pub pairs: u64,
    pub types: Vec<(&'a str, &'a crate::catalog::Page)>,
    pub more_types: usize,
}

/// The rows of the data-flow table of `grouping`, the most port pairs first.
pub fn dataflow_rows(
    cat: &crate::catalog::Catalog,
    grouping: crate::catalog::dataflow::Grouping,
    lang: Lang,
) -> Vec<FlowRow<'_>> {
    use crate::catalog::dataflow::Grouping;
    let shown = |name: &str, empty: &str| {
        if name.is_empty() {
            lang.t(empty).to_string()
        } else {
            name.to_string()
        }
    };
    let group = |fi: usize| match grouping {
        Grouping::Category => (
            shown(&cat.categories[fi].name, "fact_uncategorized"),
            cat.category_page(fi),
        ),
        Grouping::Vendor => (
            shown(&cat.vendors[fi].name, "no_vendor"),
            cat.vendor_page(fi),
        ),
    };
    let mut rows: Vec<FlowRow<'_>> = cat
        .data_flow(grouping)
        .into_iter()
        .map(|e| FlowRow {
            from: group(e.from),
            to: group(e.to),
            pairs: e.pairs,
            more_types: e.types.len().saturating_sub(DATAFLOW_TYPES_SHOWN),
            types: e
                .types
                .iter()
                .take(DATAFLOW_TYPES_SHOWN)
                .map(|&ti| (cat[ti].name.as_str(), cat.data_type_page(ti)))
                .collect(),
        })
        .collect();
    rows.sort_by_key(|r| std::cmp::Reverse(r.pairs));
    rows
}

/// The Implementation section of a component page ([`crate::implementation`]): the files
/// read, the language, and "matches the specification" or the differences.
#[derive(serde::Serialize, Clone)]
pub struct ImplementationSection {
    /// `C++ · matches the specification` / `C++ · 3 differences from the specification`.
    pub summary: String,
    pub matches: bool,
    /// The files read: (shown path, link to it at the pinned commit).
    pub files: Vec<ImplementationFile>,
    pub rows: Vec<DriftRow>,
    /// What could not be verified, in words.
    pub unverified: Vec<String>,
    /// The label of the section's introduction: `impl_intro`, or `impl_recovered_intro` for
    /// a component documented from its code alone.
    pub intro: &'static str,
    /// A component recovered from its code: the values its code does not spell out.
    pub unread: Vec<String>,
    /// The component has no profile: it is documented from its code.
    pub recovered: bool,
}

#[derive(serde::Serialize, Clone)]
pub struct ImplementationFile {
    pub text: String,
    pub href: Option<String>,
}

/// A difference: the element, what the profile says, what the code says, where (and the rule).
#[derive(serde::Serialize, Clone)]
pub struct DriftRow {
    pub element: String,
    pub profile: String,
    pub code: String,
    pub at: String,
    pub rule: &'static str,
}

impl ImplementationSection {
    /// The section of `c`, when its implementation was read; `file_url` links a file read.
    pub fn of(
        c: &crate::catalog::Component,
        lang: Lang,
        file_url: &dyn Fn(&str) -> Option<String>,
    ) -> Option<ImplementationSection> {
        let imp = c.implementation.as_deref()?;
        let absent = lang.t("impl_absent");
        let rows: Vec<DriftRow> = imp
            .drift
            .iter()
            .map(|d| DriftRow {
                element: d.element.clone(),
                profile: d.profile.clone().unwrap_or_else(|| absent.to_string()),
                code: d.code.clone().unwrap_or_else(|| absent.to_string()),
                at: match &d.at {
                    Some(a) => format!("{}:{}", a.file, a.pos.line),
                    None => match d.profile_pos {
                        Some(p) => format!("{}:{}", c.source, p.line),
                        None => c.source.clone(),
                    },
                },
                rule: d.kind.code(),
            })
            .collect();
        let state = if c.recovered.is_some() {
            lang.t("impl_recovered").to_string()
        } else if rows.is_empty() {
            lang.t("impl_matches").to_string()
        } else {
            lang.t("impl_differences")
                .replace("{n}", &rows.len().to_string())
        };
        Some(ImplementationSection {
            summary: format!("{} · {state}", imp.language.name()),
            matches: rows.is_empty(),
            files: imp
                .files
                .iter()
                .map(|f| ImplementationFile {
                    text: f.clone(),
                    href: file_url(f),
                })
                .collect(),
            rows,
            unverified: imp
                .unverified
                .iter()
                // A recovered component lists its spec values not read once, as not read.
                .filter(|u| {
                    !(c.recovered.is_some() && u.of == crate::implementation::Unread::SpecValue)
                })
                .map(|u| {
                    format!(
                        "{}: {} ({}:{})",
                        u.what.replace('`', ""),
                        u.construct,
                        u.at.file,
                        u.at.pos.line
                    )
                })
                .collect(),
            recovered: c.recovered.is_some(),
            intro: if c.recovered.is_some() {
                "impl_recovered_intro"
            } else {
                "impl_intro"
            },
            unread: c
                .recovered
                .iter()
                .flat_map(|r| &r.unread)
                .map(|u| {
                    format!(
                        "{}: {} ({}:{})",
                        u.field, u.written, u.at.file, u.at.pos.line
                    )
                })
                .collect(),
        })
    }
}
