//! Page views: for each page kind, what its page says, built once from the catalogue and
//! rendered by every output (HTML through its templates, Markdown and Doxygen through
//! [`crate::render::text::Markup`]).
//!
//! A view holds plain, unescaped text ([`Fact`](super::facts::Fact)s, names) and links as
//! pages of [`Catalog::pages`] ([`Linked`]), never a path: each output turns a link into its
//! own target with [`Catalog::href`]. Adding a page kind is a view builder here and its
//! rendering in each output.

pub mod component;
pub mod facets;
pub mod front;
pub mod history;
pub mod history_page;
pub mod idl_file;
pub mod system;
pub mod types;

use crate::catalog::{Catalog, ComponentIx, Output, Page};
use crate::render::facts::{self, PEER_COMPONENTS_CAP};

/// A text that links to a page of the catalogue (to an anchor of it if given), or is plain text
/// when `to` is `None`.
#[derive(Debug, Clone)]
pub struct Linked<'a> {
    pub text: String,
    pub to: Option<(&'a Page, Option<&'a str>)>,
}

impl<'a> Linked<'a> {
    pub fn new(text: &str, page: Option<&'a Page>, anchor: Option<&'a str>) -> Linked<'a> {
        Linked {
            text: text.to_string(),
            to: page.map(|p| (p, anchor)),
        }
    }

    /// The link's target from page `from` in output `out`.
    pub fn target(&self, cat: &Catalog, from: &Page, out: Output) -> Option<String> {
        self.to.map(|(to, anchor)| cat.href(from, to, anchor, out))
    }
}

/// A port's direction as shown: its label and a class (`in`, `out`, `event`, `provided`,
/// `required`, `other`) for styles.
#[derive(Debug, Clone)]
pub struct Dir {
    pub label: String,
    pub class: &'static str,
}

impl Dir {
    pub fn new(label: &str, class: &'static str) -> Dir {
        Dir {
            label: label.to_string(),
            class,
        }
    }
}

/// A port's "connects to" answer: the other components' ports, one link per component (to its
/// first port, naming up to [`facts::PEER_PORTS_SHOWN`] ports), at most
/// [`PEER_COMPONENTS_CAP`] components; `more` says how many more there are and links to the
/// type or interface page that lists them all. Never dropped silently.
#[derive(Debug, Clone, Default)]
pub struct Peers<'a> {
    pub shown: Vec<Linked<'a>>,
    pub more: Option<Linked<'a>>,
}

impl<'a> Peers<'a> {
    /// The peers of a port of component `ci` among `refs` (sorted by component):
    /// `component(r)` is a reference's component, `resolve(r)` its component, port label and
    /// port anchor; `all` is the type or interface page, `more_label` the words after "+N —".
    #[allow(clippy::too_many_arguments)]
    pub fn of<R>(
        ci: ComponentIx,
        refs: crate::catalog::PeerRefs<'a, R>,
        component: impl Fn(&R) -> ComponentIx,
        resolve: impl Fn(&R) -> Option<(ComponentIx, String, &'a str)>,
        cat: &'a Catalog,
        all: Option<&'a Page>,
        more_label: &str,
    ) -> Peers<'a> {
        let (groups, total) = facts::peer_groups(ci, refs, component);
        let shown = groups
            .iter()
            .filter_map(|(_, list)| {
                let ports: Vec<(ComponentIx, String, &'a str)> =
                    list.iter().filter_map(|r| resolve(r)).collect();
                let (pc, _, anchor) = ports.first()?;
                let names: Vec<&str> = ports.iter().map(|(_, n, _)| n.as_str()).collect();
                let name = cat[*pc].display_name();
                Some(Linked::new(
                    &facts::peer_text(&name, &names, " · "),
                    Some(cat.component_page(*pc)),
                    Some(anchor),
                ))
            })
            .collect();
        let more = (total > PEER_COMPONENTS_CAP).then(|| {
            Linked::new(
                &format!("+{} — {more_label}", total - PEER_COMPONENTS_CAP),
                all,
                None,
            )
        });
        Peers { shown, more }
    }
}

/// A stability mark as a page shows it, under its title: "Deprecated since 2.0 — use X" (X
/// linked when the catalogue has it), "Experimental", then the note. The one wording of every
/// output.
#[derive(Debug, Clone)]
pub struct StabilityView<'a> {
    /// `experimental`, `stable` or `deprecated` (a class for styles).
    pub class: &'static str,
    pub deprecated: bool,
    /// `Deprecated since 2.0`, `Experimental`.
    pub headline: String,
    /// The words before and after the replacement (`use `, ``), and the replacement.
    pub replacement: Option<(&'static str, &'static str, Linked<'a>)>,
    pub note: Option<&'a str>,
}

impl StabilityView<'_> {
    /// The line as plain text: `Deprecated since 2.0 — use X. Note`.
    pub fn plain(&self) -> String {
        let mut s = self.headline.clone();
        if let Some((before, after, r)) = &self.replacement {
            s.push_str(&format!(" — {before}{}{after}", r.text));
        }
        if let Some(n) = self.note {
            s.push_str(&format!(". {n}"));
        }
        s
    }
}

/// The view of an entry's stability mark, if it has one.
pub fn stability_view<'a>(
    cat: &'a Catalog,
    mark: Option<&'a crate::model::stability::Stability>,
    lang: crate::i18n::Lang,
) -> Option<StabilityView<'a>> {
    use crate::model::stability::Status;
    let s = mark?;
    let status = match s.status {
        Status::Experimental => lang.t("stability_experimental"),
        Status::Stable => lang.t("stability_stable"),
        Status::Deprecated => lang.t("stability_deprecated"),
    };
    let headline = match &s.since {
        Some(v) => lang
            .t("stability_since")
            .replace("{since}", v)
            .replace("{status}", status),
        None => status.to_string(),
    };
    let replacement = s.replacement.as_deref().map(|r| {
        let words = lang.t("stability_use");
        let (before, after) = words.split_once("{}").unwrap_or((words, ""));
        (before, after, Linked::new(r, cat.replacement_page(r), None))
    });
    Some(StabilityView {
        class: s.status.as_str(),
        deprecated: s.status == Status::Deprecated,
        headline,
        replacement,
        note: s.note.as_deref(),
    })
}
