//! The IDL file a data type or interface is defined in, as its page shows it: the file linked
//! into its repository ("Source": `source-url`, a `[[source]]`'s template at the pinned commit)
//! and the file's latest versions ([`crate::catalog::Catalog::idl_history`]), each with the
//! changes to its types. The file's whole history is on its history page
//! (`idl-history/<slug>`); the type pages are where a reader looks at a type, and they name the
//! file defining it.

use super::history::HistoryView;
use crate::catalog::Catalog;
use crate::i18n::Lang;

/// The IDL file section of a type page.
#[derive(Debug, Clone)]
pub struct IdlFileView<'a> {
    /// The file's path as the catalogue read it.
    pub file: String,
    /// Where the file is in its repository.
    pub source_url: Option<String>,
    pub history: HistoryView,
    /// The file's history page (every version), when it has a history.
    pub history_page: Option<&'a crate::catalog::Page>,
}

/// The section for the type `name` (any spelling the IDL set resolves); `None` when no IDL
/// file defines it, or the file has neither a link nor a history to show. `source_url` is the
/// site's `source-url` template.
pub fn idl_file_view<'a>(
    cat: &'a Catalog,
    name: &str,
    lang: Lang,
    source_url: Option<&str>,
) -> Option<IdlFileView<'a>> {
    let file = cat.idl.find(name)?.file;
    let history_page = cat
        .idl_file_index(file)
        .and_then(|fi| cat.history_page_of(crate::catalog::history::HistoryOf::Idl(fi)));
    let url = crate::render::html::repo::history_file_urls(
        &cat.sources,
        file.origin.as_ref(),
        source_url,
    );
    let history = cat
        .idl_history
        .get(&file.path)
        .map(|h| {
            let of = cat
                .idl_file_index(file)
                .map(crate::catalog::history::HistoryOf::Idl);
            let reach = |ch: &crate::catalog::history::Change| {
                (
                    None,
                    of.and_then(|of| super::history::reach_text(cat, of, ch, lang)),
                )
            };
            HistoryView::of(h, lang, &url, (None, &reach))
        })
        .unwrap_or_default();
    let source_url = crate::render::html::repo::document_source_url(
        &cat.sources,
        file.origin.as_ref(),
        &file.path,
        source_url,
    );
    (source_url.is_some() || !history.rows.is_empty()).then(|| IdlFileView {
        file: file.path.clone(),
        source_url,
        history,
        history_page,
    })
}
