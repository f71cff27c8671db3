//! README Markdown → safe HTML (no catalogue, no page paths: [`Resolve`] is asked for every
//! URL). Used to find a README's images ([`image_sources`]) and, by the renderers, to show it.
//!
//! pulldown-cmark (tables, strikethrough, task lists, footnotes) then ammonia. Headings are
//! shifted so that the README's top level is an `<h3>` (under the page's "README" `<h2>`) and
//! the levels it uses follow without a gap, capped at `<h6>` ([`Levels`]), and get ids `readme-<GitHub-style slug>`, unique within the page; a fragment link
//! `#foo` goes to the heading whose slug is `foo`, or is dropped (its text kept). Raw HTML goes
//! through the same sanitiser: no script, style, iframe, form, event handler, `javascript:` or
//! `data:` URL; `<h1>`/`<h2>` of raw HTML keep only their text (the page has its own).
//!
//! Every URL goes through one attribute filter, which asks a [`Resolve`]: `http`, `https` and
//! `mailto` links are kept (`rel="noopener noreferrer"`), relative links are resolved by the
//! caller (a component page, the source URL, or dropped). Images: a local image the README's
//! check found ([`crate::readme::Image`]) becomes an `<img loading="lazy">` of its copy; an
//! absolute `http(s)` image becomes a link to it (the site makes no external requests); any
//! other is dropped and its alt text shown as text. A task list marker is a ☑/☐ character (a
//! checkbox would be a form control without a label).

use pulldown_cmark::{CowStr, Event, HeadingLevel, Options, Parser, Tag, TagEnd};
use std::borrow::Cow;
use std::collections::{HashMap, HashSet};
use std::sync::{Arc, Mutex};

/// How the URLs of one README are resolved: each gets a URL as the README wrote it (after
/// HTML entity decoding) and returns the URL to write, or `None` to drop it.
pub struct Resolve {
    /// A link's `href` that is not a fragment.
    pub link: Rewrite,
    /// An image's `src`.
    pub image: Rewrite,
}

/// A URL as written → the URL to write, or `None` to drop it.
pub type Rewrite = Box<dyn Fn(&str) -> Option<String> + Send + Sync>;

fn options() -> Options {
    Options::ENABLE_TABLES
        | Options::ENABLE_STRIKETHROUGH
        | Options::ENABLE_TASKLISTS
        | Options::ENABLE_FOOTNOTES
}

/// GitHub's heading slug: lower case, letters, digits, `-` and `_` kept, spaces to `-`, the
/// rest dropped.
pub fn github_slug(s: &str) -> String {
    s.trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The ids of a README's headings and footnotes.
#[derive(Default)]
struct Ids {
    /// One per heading, in order.
    headings: Vec<String>,
    /// Footnote label (lower case) → (id, number).
    footnotes: HashMap<String, (String, usize)>,
    /// What a fragment may name (a heading's slug, or an id itself) → id.
    fragments: HashMap<String, String>,
}

fn collect_ids(events: &[Event<'_>]) -> Ids {
    let mut ids = Ids::default();
    let mut used: HashMap<String, usize> = HashMap::new();
    let mut text: Option<String> = None;
    let mut next_note = 1;
    let mut note_ids: HashSet<String> = HashSet::new();
    let mut note_slugs: HashMap<String, usize> = HashMap::new();
    let mut note = |label: &str, ids: &mut Ids| {
        let key = label.to_lowercase();
        if ids.footnotes.contains_key(&key) {
            return;
        }
        // Labels with the same slug (`a!`, `a?`) are numbered, as headings are.
        let slug = github_slug(label);
        let n = note_slugs.entry(slug.clone()).or_default();
        let mut id = if *n == 0 {
            format!("readme-fn-{slug}")
        } else {
            format!("readme-fn-{slug}-{n}")
        };
        *n += 1;
        while !note_ids.insert(id.clone()) {
            id.push('_');
        }
        ids.footnotes.insert(key, (id, next_note));
        next_note += 1;
    };
    for e in events {
        match e {
            Event::Start(Tag::Heading { .. }) => text = Some(String::new()),
            Event::Text(t) | Event::Code(t) => {
                if let Some(s) = text.as_mut() {
                    s.push_str(t);
                }
            }
            Event::End(TagEnd::Heading(_)) => {
                let slug = github_slug(&text.take().unwrap_or_default());
                let base = if slug.is_empty() {
                    "section".to_string()
                } else {
                    slug
                };
                let n = used.entry(base.clone()).or_default();
                let mut unique = if *n == 0 {
                    base.clone()
                } else {
                    format!("{base}-{n}")
                };
                *n += 1;
                // `a-1` written as a heading of its own after two `a`s.
                while ids.fragments.contains_key(&unique) {
                    unique.push('_');
                }
                let id = format!("readme-{unique}");
                ids.fragments.insert(unique, id.clone());
                ids.fragments.entry(id.clone()).or_insert(id.clone());
                ids.headings.push(id);
            }
            Event::FootnoteReference(l) => note(l, &mut ids),
            _ => {}
        }
    }
    for e in events {
        if let Event::Start(Tag::FootnoteDefinition(l)) = e {
            note(l, &mut ids);
        }
    }
    for (id, _) in ids.footnotes.values() {
        ids.fragments.entry(id.clone()).or_insert(id.clone());
    }
    ids
}

/// The page level of each README heading level: the levels the README uses, in order, become
/// h3, h4, … (capped at h6), so the README's top heading sits right under the section's h2 and
/// no level is skipped (a README starting at `##`, or jumping from `#` to `###`, reads as
/// h3, h4).
struct Levels([HeadingLevel; 6]);

impl Levels {
    fn of(events: &[Event<'_>]) -> Levels {
        let mut used = [false; 6];
        for e in events {
            if let Event::Start(Tag::Heading { level, .. }) = e {
                used[*level as usize - 1] = true;
            }
        }
        let page = [
            HeadingLevel::H3,
            HeadingLevel::H4,
            HeadingLevel::H5,
            HeadingLevel::H6,
        ];
        let mut map = [HeadingLevel::H6; 6];
        let mut rank = 0;
        for (i, u) in used.iter().enumerate() {
            map[i] = page[rank.min(page.len() - 1)];
            if *u {
                rank += 1;
            }
        }
        Levels(map)
    }

    fn shift(&self, level: HeadingLevel) -> HeadingLevel {
        self.0[level as usize - 1]
    }
}

/// The README's Markdown with shifted headings, heading and footnote ids, and task list
/// markers as characters, as HTML (not yet sanitised).
fn raw_html(text: &str) -> (String, Ids) {
    let events: Vec<Event<'_>> = Parser::new_ext(text, options()).collect();
    let ids = collect_ids(&events);
    let levels = Levels::of(&events);
    let shift = |l| levels.shift(l);
    let mut heading = ids.headings.iter();
    let note = |l: &str| ids.footnotes.get(&l.to_lowercase()).cloned();
    let out = events.into_iter().map(|e| match e {
        Event::Start(Tag::Heading { level, .. }) => Event::Start(Tag::Heading {
            level: shift(level),
            id: heading.next().map(|i| CowStr::from(i.clone())),
            classes: Vec::new(),
            attrs: Vec::new(),
        }),
        Event::End(TagEnd::Heading(level)) => Event::End(TagEnd::Heading(shift(level))),
        Event::TaskListMarker(done) => Event::Text(if done { "☑ " } else { "☐ " }.into()),
        Event::FootnoteReference(l) => match note(&l) {
            Some((id, n)) => {
                Event::InlineHtml(format!("<sup><a href=\"#{id}\">{n}</a></sup>").into())
            }
            None => Event::Text(format!("[^{l}]").into()),
        },
        Event::Start(Tag::FootnoteDefinition(l)) => {
            let (id, n) = note(&l).unwrap_or_default();
            Event::Html(format!("<div id=\"{id}\" class=\"footnote\"><sup>{n}</sup>\n").into())
        }
        Event::End(TagEnd::FootnoteDefinition) => Event::Html("</div>\n".into()),
        other => other,
    });
    let mut html = String::with_capacity(text.len() + text.len() / 2);
    pulldown_cmark::html::push_html(&mut html, out);
    (html, ids)
}

/// Attributes that hold a URL; only `a href` and `img src` are kept (resolved).
const URL_ATTRIBUTES: &[&str] = &["href", "src", "cite", "longdesc", "srcset", "action"];

fn sanitise(raw: &str, ids: Ids, resolve: Resolve) -> String {
    let allowed: HashSet<String> = ids.fragments.values().cloned().collect();
    let fragments = ids.fragments;
    let seen: Mutex<HashSet<String>> = Mutex::new(HashSet::new());
    let mut b = ammonia::Builder::default();
    b.rm_tags(["h1", "h2"])
        .rm_tag_attributes("img", ["align"])
        .add_tag_attributes("h3", ["id"])
        .add_tag_attributes("h4", ["id"])
        .add_tag_attributes("h5", ["id"])
        .add_tag_attributes("h6", ["id"])
        .add_tag_attributes("div", ["id"])
        .add_allowed_classes("div", ["footnote"])
        .set_tag_attribute_value("img", "loading", "lazy")
        .link_rel(Some("noopener noreferrer"))
        .url_relative(ammonia::UrlRelative::PassThrough)
        .url_schemes(["http", "https", "mailto"].into_iter().collect());
    b.attribute_filter(move |element, attribute, value| {
        let keep = |s: Option<String>| s.map(Cow::Owned);
        match (element, attribute) {
            // Only the ids made here, each once (raw HTML may repeat one).
            (_, "id") => {
                let first = seen
                    .lock()
                    .map(|mut s| s.insert(value.to_string()))
                    .unwrap_or(false);
                (allowed.contains(value) && first).then_some(Cow::Borrowed(value))
            }
            ("a", "href") => match crate::readme::classify(value) {
                crate::readme::Target::Fragment(f) => keep(
                    fragments
                        .get(&f)
                        .or_else(|| fragments.get(&f.to_lowercase()))
                        .map(|id| format!("#{id}")),
                ),
                _ => keep((resolve.link)(value)),
            },
            ("img", "src") => keep((resolve.image)(value)),
            (_, a) if URL_ATTRIBUTES.contains(&a) => None,
            _ => Some(Cow::Borrowed(value)),
        }
    });
    b.clean(raw).to_string()
}

/// One attribute of a serialised tag: name and value as serialised (`&amp;`, `&quot;`).
type Attr<'a> = (&'a str, &'a str);

/// Parses the tag starting at `s[0] == '<'` of the sanitiser's output (html5ever writes every
/// attribute as `name="value"`): its name, attributes and length.
fn parse_tag(s: &str) -> Option<(&str, Vec<Attr<'_>>, usize)> {
    let b = s.as_bytes();
    let mut i = if b.get(1) == Some(&b'/') { 2 } else { 1 };
    while i < b.len() && !matches!(b[i], b' ' | b'>' | b'/') {
        i += 1;
    }
    let name = &s[1..i];
    let mut attrs = Vec::new();
    loop {
        while i < b.len() && matches!(b[i], b' ' | b'/') {
            i += 1;
        }
        if i >= b.len() {
            return None;
        }
        if b[i] == b'>' {
            return Some((name, attrs, i + 1));
        }
        let start = i;
        while i < b.len() && !matches!(b[i], b'=' | b' ' | b'>') {
            i += 1;
        }
        let key = &s[start..i];
        if b.get(i) == Some(&b'=') && b.get(i + 1) == Some(&b'"') {
            let vstart = i + 2;
            let len = s[vstart..].find('"')?;
            attrs.push((key, &s[vstart..vstart + len]));
            i = vstart + len + 1;
        } else {
            attrs.push((key, ""));
        }
    }
}

/// An attribute value as serialised, written as text (html5ever leaves `<` and `>` raw in
/// attribute values).
fn attr_as_text(v: &str) -> String {
    v.replace('<', "&lt;").replace('>', "&gt;")
}

/// The last step: an `<img>` of an `http(s)` URL becomes a link to it (its alt text inside,
/// or the URL; only the text when it already stands in a link), an `<img>` whose `src` was
/// dropped becomes its alt text, and an `<a>` whose `href` was dropped becomes its text.
fn finish(html: &str) -> String {
    let mut out = String::with_capacity(html.len());
    let mut rest = html;
    let mut in_link = false;
    let mut drop_close = false;
    while let Some(at) = rest.find('<') {
        out.push_str(&rest[..at]);
        rest = &rest[at..];
        let Some((name, attrs, len)) = parse_tag(rest) else {
            out.push_str(rest);
            return out;
        };
        let get = |k: &str| attrs.iter().find(|(n, _)| *n == k).map(|(_, v)| *v);
        let tag = &rest[..len];
        match name {
            "img" => {
                let alt = get("alt").filter(|a| !a.is_empty());
                match get("src") {
                    Some(src) if src.starts_with("http://") || src.starts_with("https://") => {
                        let text = attr_as_text(alt.unwrap_or(src));
                        if in_link {
                            out.push_str(&text);
                        } else {
                            out.push_str(&format!(
                                "<a href=\"{src}\" rel=\"noopener noreferrer\">{text}</a>"
                            ));
                        }
                    }
                    // An image needs a text alternative: none written, it is decoration.
                    Some(_) if get("alt").is_none() => {
                        out.push_str(&tag[..tag.len() - 1]);
                        out.push_str(" alt=\"\">");
                    }
                    Some(_) => out.push_str(tag),
                    None => out.push_str(&attr_as_text(alt.unwrap_or(""))),
                }
            }
            "a" if get("href").is_none() => drop_close = true,
            "a" => {
                in_link = true;
                out.push_str(tag);
            }
            "/a" if drop_close => drop_close = false,
            "/a" => {
                in_link = false;
                out.push_str(tag);
            }
            _ => out.push_str(tag),
        }
        rest = &rest[len..];
    }
    out.push_str(rest);
    out
}

/// The sanitised HTML of README `text`.
pub fn to_html(text: &str, resolve: Resolve) -> String {
    let (raw, ids) = raw_html(text);
    finish(&sanitise(&raw, ids, resolve))
}

/// The `src` of every image of README `text` (Markdown images and raw-HTML `<img>`), as the
/// sanitiser sees them, in order, each once.
pub fn image_sources(text: &str) -> Vec<String> {
    let found: Arc<Mutex<Vec<String>>> = Arc::default();
    let sink = Arc::clone(&found);
    to_html(
        text,
        Resolve {
            link: Box::new(|_| None),
            image: Box::new(move |src| {
                if let Ok(mut v) = sink.lock() {
                    if !v.iter().any(|s| s == src) {
                        v.push(src.to_string());
                    }
                }
                None
            }),
        },
    );
    let v = found.lock().map(|v| v.clone()).unwrap_or_default();
    v
}
#[cfg(test)]
mod tests {
    use super::*;

    /// A kept link as the sanitiser writes it.
    fn a(href: &str, text: &str) -> String {
        format!("<a href=\"{href}\" rel=\"noopener noreferrer\">{text}</a>")
    }

    fn html(text: &str) -> String {
        to_html(
            text,
            Resolve {
                link: Box::new(|u| u.starts_with("https:").then(|| u.to_string())),
                image: Box::new(|u| {
                    (u.starts_with("https:") || u == "ok.png").then(|| u.to_string())
                }),
            },
        )
    }

    #[test]
    fn headings_shift_and_get_unique_ids() {
        let h = html("# Camera\n## Usage\n## Usage\n#### Deep\n###### Deeper\n");
        assert!(h.contains("<h3 id=\"readme-camera\">Camera</h3>"), "{h}");
        assert!(h.contains("<h4 id=\"readme-usage\">"), "{h}");
        assert!(h.contains("<h4 id=\"readme-usage-1\">"), "{h}");
        assert!(h.contains("<h5 id=\"readme-deep\">"), "{h}");
        assert!(h.contains("<h6 id=\"readme-deeper\">"), "{h}");
        assert!(!h.contains("<h1") && !h.contains("<h2"), "{h}");
    }

    #[test]
    fn headings_skip_no_level() {
        // A README that starts at `##` and jumps to `####`: h3, h4 on the page.
        let h = html(
            "## Build
#### Linux
## Run
",
        );
        assert!(h.contains("<h3 id=\"readme-build\">"), "{h}");
        assert!(h.contains("<h4 id=\"readme-linux\">"), "{h}");
        assert!(h.contains("<h3 id=\"readme-run\">"), "{h}");
        // Seven levels deep would need h9: the deepest share h6.
        let d = html(
            "# a
## b
### c
#### d
##### e
###### f
",
        );
        assert!(d.contains("<h5 id=\"readme-c\">"), "{d}");
        assert!(
            d.contains("<h6 id=\"readme-d\">") && d.contains("<h6 id=\"readme-f\">"),
            "{d}"
        );
    }

    #[test]
    fn fragments_go_to_headings_or_are_dropped() {
        let h = html("# Build Steps\n[go](#build-steps) [up](#Build-Steps) [gone](#nowhere)\n");
        assert!(h.contains(&a("#readme-build-steps", "go")), "{h}");
        assert!(h.contains(&a("#readme-build-steps", "up")), "{h}");
        assert!(h.contains(" gone</p>"), "{h}");
        assert!(!h.contains("nowhere"), "{h}");
    }

    #[test]
    fn raw_html_payloads_are_removed() {
        let h = html(
            "<script>alert(1)</script>\n\n<img src=ok.png onerror=alert(2)>\n\n[x](javascript:alert(3))\n\n\
             ![d](data:image/png;base64,AAAA)\n\n<iframe src=\"https://e.invalid\"></iframe>\n\n\
             <style>body{display:none}</style>\n\n<h1 id=\"overview\">Big</h1>\n\n<a href=\"https://e.org\" onclick=\"x()\">e</a>",
        );
        for bad in [
            "<script",
            "onerror",
            "javascript:",
            "data:",
            "<iframe",
            "<style",
            "display:none",
            "onclick",
            "id=\"overview\"",
            "<h1",
        ] {
            assert!(!h.contains(bad), "{bad}: {h}");
        }
        assert!(h.contains("<img src=\"ok.png\""), "{h}");
        assert!(h.contains("loading=\"lazy\""), "{h}");
        assert!(
            h.contains(">d<") || h.contains("d</p>"),
            "alt text kept: {h}"
        );
        assert!(h.contains("Big"), "{h}");
    }

    #[test]
    fn external_images_become_links_and_dropped_ones_text() {
        let h = html("![logo](https://x.org/l.png) ![gone](missing.png) [![badge](https://b.org/b.svg)](https://b.org)\n");
        assert!(h.contains(&a("https://x.org/l.png", "logo")), "{h}");
        assert!(h.contains(" gone "), "{h}");
        assert!(h.contains(&a("https://b.org", "badge")), "{h}");
        assert!(!h.contains("<img"), "{h}");
    }

    #[test]
    fn tables_task_lists_and_footnotes() {
        let h = html("| a | b |\n|---|---|\n| 1 | 2 |\n\n- [x] done\n- [ ] todo\n\nSee[^n].\n\n[^n]: The note.\n");
        assert!(h.contains("<table>") && h.contains("<td>2</td>"), "{h}");
        assert!(
            h.contains("☑ done") && h.contains("☐ todo") && !h.contains("<input"),
            "{h}"
        );
        assert!(h.contains(&a("#readme-fn-n", "1")), "{h}");
        assert!(
            h.contains("<div id=\"readme-fn-n\" class=\"footnote\">"),
            "{h}"
        );
    }

    #[test]
    fn image_sources_are_found_in_markdown_and_raw_html() {
        assert_eq!(
            image_sources("![a](x.png)\n\n<img src=\"y&amp;z.svg\">\n\n![b](x.png)"),
            vec!["x.png".to_string(), "y&z.svg".to_string()]
        );
    }

    #[test]
    fn slugs() {
        assert_eq!(github_slug("Hello, World!"), "hello-world");
        assert_eq!(github_slug("使い方 (Usage)"), "使い方-usage");
        assert_eq!(github_slug("a_b-c"), "a_b-c");
    }
}
