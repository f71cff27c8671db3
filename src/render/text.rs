//! Building blocks shared by the text renderers (Markdown and Doxygen).
//!
//! Both renderers lay out the same tables of [`Fact`]s and the same peer lists; they differ
//! only in how text is escaped, how a cross-reference is written and how a table looks, which
//! is what a [`Markup`] says.

use super::facts::Fact;
use crate::i18n::Lang;

/// At most this many "connects to" peers are listed per port; the rest are on the type or
/// interface page.
pub const PEER_CAP: usize = 12;

/// The syntax of one text output format.
pub trait Markup {
    /// Escapes plain text for an inline position (a table cell, a heading).
    fn esc(s: &str) -> String;
    /// A cross-reference with plain `text`; `target` (a URL or a label) is generated and safe.
    fn link(text: &str, target: &str) -> String;
    /// Bold text; `escaped` is already escaped.
    fn bold(escaped: &str) -> String;
    /// A table with plain-text `headers`; the cells of `rows` are already escaped.
    fn table(out: &mut String, headers: &[&str], rows: &[Vec<String>]);
}

/// Facts as a two-column table (label, value).
pub fn facts_table<M: Markup>(out: &mut String, lang: Lang, facts: &[Fact]) {
    let rows: Vec<Vec<String>> = facts
        .iter()
        .map(|f| vec![M::esc(&f.label), M::esc(&f.value)])
        .collect();
    M::table(out, &[lang.t("fact_field"), lang.t("fact_value")], &rows);
}

/// Facts inside one cell: bold label, colon, value; one line each.
pub fn facts_cell<M: Markup>(facts: &[Fact]) -> String {
    facts
        .iter()
        .map(|f| format!("{}: {}", M::bold(&M::esc(&f.label)), M::esc(&f.value)))
        .collect::<Vec<_>>()
        .join("<br>")
}

/// Links to up to [`PEER_CAP`] peers, given as (text, target), then "… +N more" pointing at
/// `rest` (the type or interface page), if there is one.
pub fn peers_cell<M: Markup>(
    items: Vec<(String, String)>,
    rest: Option<String>,
    lang: Lang,
) -> String {
    let total = items.len();
    let mut parts: Vec<String> = items
        .into_iter()
        .take(PEER_CAP)
        .map(|(text, target)| M::link(&text, &target))
        .collect();
    if total > PEER_CAP {
        let more = format!("… +{} {}", total - PEER_CAP, lang.t("fact_more"));
        parts.push(match rest {
            Some(target) => M::link(&more, &target),
            None => M::esc(&more),
        });
    }
    parts.join("<br>")
}

/// A category's display name; the empty category has a translated name.
pub fn category_name(name: &str, lang: Lang) -> String {
    if name.is_empty() {
        lang.t("fact_uncategorized").to_string()
    } else {
        name.to_string()
    }
}

/// The spellings and IDL files of a data type or interface as a facts table (nothing when
/// both are empty).
pub fn names_facts<M: Markup>(out: &mut String, lang: Lang, spellings: &[String], idl: &[String]) {
    let mut f = Vec::new();
    if !spellings.is_empty() {
        f.push(Fact::new(lang.t("fact_spellings"), spellings.join(", ")));
    }
    if !idl.is_empty() {
        f.push(Fact::new(lang.t("fact_idl_files"), idl.join("\n")));
    }
    if !f.is_empty() {
        facts_table::<M>(out, lang, &f);
    }
}

/// Column headers of a component list.
pub fn component_cols(lang: Lang) -> [&'static str; 4] {
    [
        lang.t("name"),
        lang.t("description"),
        lang.t("vendor"),
        lang.t("version"),
    ]
}
