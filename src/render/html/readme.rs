//! A component folder's README on a component page: its Markdown made safe HTML by
//! [`crate::readme::html`], with relative links resolved to the pages and source files of this
//! output ([`Targets`]).

use crate::readme::html::{to_html, Resolve};
use std::collections::HashMap;
use std::sync::Arc;

/// Where the links of the READMEs of one output go: the page of each component (by profile
/// path), the `source-url` template, and the prefix from a component page to the output root.
pub struct Targets {
    /// Profile path (input-relative) → URL of its page from a component page.
    pub pages: HashMap<String, String>,
    pub source_url: Option<String>,
    /// The `[[source]]` repositories: a file of one links into it at the pinned commit.
    pub sources: Vec<crate::model::SourceInfo>,
    /// From a component page to the output root (`../`).
    pub root: String,
}

impl Targets {
    /// The targets of `catalog`'s READMEs; `page(ci)` is component `ci`'s page path from the
    /// output root.
    pub fn new(
        catalog: &crate::catalog::Catalog,
        source_url: Option<&str>,
        root: &str,
        page: impl Fn(crate::catalog::ComponentIx) -> String,
    ) -> Targets {
        Targets {
            pages: crate::catalog::Ix::enumerate(&catalog.components)
                .map(|(ci, c)| (c.source.clone(), format!("{root}{}", page(ci))))
                .collect(),
            source_url: source_url.map(str::to_string),
            sources: catalog.sources.clone(),
            root: root.to_string(),
        }
    }
}

/// The HTML of README `r` on a component page, with its links resolved by `targets`.
pub fn readme_html(r: &crate::readme::Readme, targets: &Arc<Targets>) -> String {
    use crate::readme::{classify, resolve, Target};
    let dir = r.dir().to_string();
    let t = Arc::clone(targets);
    let link = move |url: &str| -> Option<String> {
        match classify(url) {
            Target::External => Some(url.to_string()),
            Target::Relative(path, suffix) => {
                let to = resolve(&dir, &path)?;
                if let Some(page) = t.pages.get(&to) {
                    return Some(page.clone());
                }
                let (name, in_repo) = to.split_once('/').unwrap_or(("", ""));
                if let Some(s) = t.sources.iter().find(|s| s.name == name) {
                    let tmpl = s.source_url.as_deref()?;
                    return super::repo::pinned_source_url(tmpl, &s.commit, in_repo)
                        .map(|u| format!("{u}{suffix}"));
                }
                let tmpl = t.source_url.as_deref()?;
                super::repo::source_url(tmpl, &to).map(|u| format!("{u}{suffix}"))
            }
            Target::Fragment(_) | Target::Dropped => None,
        }
    };
    let images: HashMap<String, String> = r
        .images
        .iter()
        .map(|i| (i.src.clone(), format!("{}{}", targets.root, i.asset)))
        .collect();
    let image = move |src: &str| -> Option<String> {
        match classify(src) {
            Target::External if src.starts_with("http://") || src.starts_with("https://") => {
                Some(src.to_string())
            }
            Target::Relative(..) => images.get(src).cloned(),
            _ => None,
        }
    };
    to_html(
        &r.text,
        Resolve {
            link: Box::new(link),
            image: Box::new(image),
        },
    )
}
