//! Where each page of [`Catalog::pages`] is in each output, and how one page links another.
//!
//! The renderers never spell a page path or a Doxygen label: they ask for
//! [`Catalog::href`] (a link from one page to another, to a row anchor if given),
//! [`Page::anchor_in`] (the name an anchor is defined under) and [`Catalog::root_from`] (the
//! way up to the output root, for the links of a README or a wiring diagram). Which page kinds
//! an output writes at all is [`Output::carries`].

use super::{Catalog, Output, Page, PageKind};

/// mdBook's table of contents, beside the Markdown pages (no page of the catalogue itself).
pub const MARKDOWN_SUMMARY: &str = "SUMMARY.md";

/// The Markdown front page once more, under the name GitHub shows for a folder (not in the
/// book: `SUMMARY.md` lists `index.md`).
pub const MARKDOWN_README: &str = "README.md";

impl Output {
    /// Every output that writes pages.
    pub const ALL: [Output; 3] = [Output::Html, Output::Markdown, Output::Doxygen];

    /// The output's name, as `--format` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Output::Html => "html",
            Output::Markdown => "markdown",
            Output::Doxygen => "doxygen",
            Output::Manual => "manual",
        }
    }

    /// Whether the output writes the pages of `kind`. The HTML site writes every page. Markdown
    /// and Doxygen leave out the site's own machinery (the search page, the page a server shows
    /// for a missing path) and, for now, the diagnostics page and the categories index: their
    /// category pages hang from the front page (mdBook's `SUMMARY.md`, Doxygen's `\mainpage`).
    /// A system manual holds a system, components and their types, as sections of one file.
    pub fn carries(self, kind: PageKind) -> bool {
        match self {
            Output::Html => true,
            Output::Manual => matches!(
                kind,
                PageKind::System | PageKind::Component | PageKind::DataType | PageKind::Interface
            ),
            Output::Markdown | Output::Doxygen => !matches!(
                kind,
                PageKind::Search
                    | PageKind::NotFound
                    | PageKind::Diagnostics
                    | PageKind::Categories
            ),
        }
    }
}

/// A Doxygen label from any slug or anchor: `[a-z0-9-]` → `[a-z0-9_]` (every other character
/// becomes `_` as well).
pub fn doxygen_label(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

impl Page {
    /// The last part of the stem: the slug of an entry page.
    fn slug(&self) -> &str {
        self.stem.rsplit('/').next().unwrap_or(&self.stem)
    }

    /// The id of the page's section in a system manual ([`Output::Manual`]): its stem with
    /// `-` for `/` (`components-camera`), unique as the stems are.
    pub fn section_id(&self) -> String {
        self.stem.replace('/', "-")
    }

    /// The page's Doxygen name (what `\page` declares and `\ref` names): `index` for the
    /// `\mainpage`, `rtc_types` and the like for the index pages, a prefix and the slug for the
    /// entry pages (`rtc_comp_<slug>`, `rtc_type_<slug>`, `rtc_if_<slug>`, `rtc_cat_<slug>`,
    /// `rtc_vendor_<slug>`, `rtc_sys_<slug>`, `rtc_hist_<slug>`, `rtc_syshist_<slug>`, `rtc_idlhist_<slug>`). Labels are globally unique and `[a-z0-9_]` only.
    pub fn doxygen_label(&self) -> String {
        let prefix = match self.kind {
            PageKind::Index => return "index".into(),
            PageKind::DataTypes => return "rtc_types".into(),
            PageKind::Interfaces => return "rtc_interfaces".into(),
            PageKind::Categories => return "rtc_categories".into(),
            PageKind::Vendors => return "rtc_vendors".into(),
            PageKind::Systems => return "rtc_systems".into(),
            PageKind::Search => return "rtc_search".into(),
            PageKind::Diagnostics => return "rtc_diagnostics".into(),
            PageKind::NotFound => return "rtc_not_found".into(),
            PageKind::DataFlow => return "rtc_dataflow".into(),
            PageKind::WhatsNew => return "rtc_whats_new".into(),
            PageKind::ComponentHistory => "rtc_hist_",
            PageKind::SystemHistory => "rtc_syshist_",
            PageKind::IdlHistory => "rtc_idlhist_",
            PageKind::Component => "rtc_comp_",
            PageKind::DataType => "rtc_type_",
            PageKind::Interface => "rtc_if_",
            PageKind::Category => "rtc_cat_",
            PageKind::Vendor => "rtc_vendor_",
            PageKind::System => "rtc_sys_",
        };
        format!("{prefix}{}", doxygen_label(self.slug()))
    }

    /// The name anchor `anchor` (a section or row anchor, `[a-z0-9-]`) of this page is defined
    /// under in `out`: as is in HTML and Markdown; `<page label>__<anchor label>` in Doxygen,
    /// whose labels are global (a double underscore, which no slug holds, so a row anchor can
    /// never equal another page's label). The `\mainpage`'s sections are `rtc_main__<anchor>`.
    /// In a system manual, `<section id>--<anchor>` (no slug holds a double dash), but as is
    /// on the system's own page: a manual holds one system, whose rows keep their anchors.
    pub fn anchor_in(&self, anchor: &str, out: Output) -> String {
        match out {
            Output::Html | Output::Markdown => anchor.to_string(),
            Output::Manual if self.kind == PageKind::System => anchor.to_string(),
            Output::Manual => format!("{}--{anchor}", self.section_id()),
            Output::Doxygen => {
                let page = match self.kind {
                    PageKind::Index => "rtc_main".to_string(),
                    _ => self.doxygen_label(),
                };
                format!("{page}__{}", doxygen_label(anchor))
            }
        }
    }
}

impl Catalog {
    /// The way up from page `from` to the root of output `out`: `../` from a page one folder
    /// down, nothing from a page at the root (Doxygen, whose links are labels, has none).
    pub fn root_from(&self, from: &Page, out: Output) -> String {
        match out {
            Output::Doxygen | Output::Manual => String::new(),
            Output::Html | Output::Markdown => "../".repeat(from.depth_in(out)),
        }
    }

    /// A link to page `to` (to its `anchor` if given) from the root of output `out`, for a
    /// drawing that stands on its own (`rtcdoc graph`).
    pub fn href_from_root(&self, to: &Page, anchor: Option<&str>, out: Output) -> String {
        let root = self.site_page(PageKind::Index);
        match out {
            Output::Doxygen | Output::Manual => self.href(root, to, anchor, out),
            Output::Html | Output::Markdown => {
                let mut href =
                    String::with_capacity(to.stem.len() + 6 + anchor.map_or(0, |a| a.len() + 1));
                to.push_path_in(out, &mut href);
                if let Some(a) = anchor {
                    href.push('#');
                    href.push_str(a);
                }
                href
            }
        }
    }

    /// The target of a link on page `from` to page `to` (to its `anchor` if given) in output
    /// `out`: a relative path in HTML and Markdown (`../vendors/acme.md#x`), a label for
    /// Doxygen's `\ref` (`rtc_vendor_acme`, `rtc_comp_camera__port_image`), an anchor of the
    /// same file in a system manual (`#components-camera--port-image`: the manual leaves out
    /// the links to what it does not hold).
    pub fn href(&self, from: &Page, to: &Page, anchor: Option<&str>, out: Output) -> String {
        match out {
            Output::Manual => match anchor {
                Some(a) => format!("#{}", to.anchor_in(a, out)),
                None => format!("#{}", to.section_id()),
            },
            Output::Doxygen => match anchor {
                Some(a) => to.anchor_in(a, out),
                None => to.doxygen_label(),
            },
            Output::Html | Output::Markdown => {
                let depth = from.depth_in(out);
                let mut href = String::with_capacity(
                    3 * depth + to.stem.len() + 6 + anchor.map_or(0, |a| a.len() + 1),
                );
                for _ in 0..depth {
                    href.push_str("../");
                }
                to.push_path_in(out, &mut href);
                if let Some(a) = anchor {
                    href.push('#');
                    href.push_str(a);
                }
                href
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn page(kind: PageKind, stem: &str) -> Page {
        Page {
            kind,
            id: String::new(),
            stem: stem.into(),
            title: String::new(),
        }
    }

    #[test]
    fn links_go_up_to_the_root_and_down() {
        let cat = Catalog::default().bound().expect("empty catalogue");
        let comp = page(PageKind::Component, "components/camera");
        let vendor = page(PageKind::Vendor, "vendors/acme-inc");
        let index = page(PageKind::Index, "index");
        let vendors = page(PageKind::Vendors, "vendors/index");
        let md = Output::Markdown;
        assert_eq!(cat.href(&comp, &vendor, None, md), "../vendors/acme-inc.md");
        assert_eq!(cat.href(&index, &vendors, None, md), "vendors.md");
        assert_eq!(cat.href(&vendor, &index, None, md), "../index.md");
        assert_eq!(
            cat.href(&vendor, &comp, Some("port-image"), Output::Html),
            "../components/camera.html#port-image"
        );
        let dox = Output::Doxygen;
        assert_eq!(cat.href(&comp, &vendor, None, dox), "rtc_vendor_acme_inc");
        assert_eq!(cat.href(&comp, &index, None, dox), "index");
        assert_eq!(cat.href(&comp, &vendors, None, dox), "rtc_vendors");
        assert_eq!(
            cat.href(&vendor, &comp, Some("port-image"), dox),
            "rtc_comp_camera__port_image"
        );
        assert_eq!(index.anchor_in("catalogue", dox), "rtc_main__catalogue");
        assert_eq!(cat.root_from(&comp, md), "../");
        assert_eq!(cat.root_from(&index, md), "");
    }
}
