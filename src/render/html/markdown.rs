//! Free text of a profile (descriptions, doc fields, comments) → safe HTML.
//!
//! Text is read as Markdown (pulldown-cmark) with single line breaks kept (so plain text written
//! over several lines stays readable), then sanitised with ammonia: no script, no event handler,
//! no `javascript:` URL, no iframe, no style, no SVG and no image (the site makes no external
//! requests). Relative URLs are dropped because they could not resolve inside the site; links
//! get `rel="noopener noreferrer"`.

use pulldown_cmark::{Event, Options, Parser, Tag};
use std::sync::OnceLock;

fn sanitizer() -> &'static ammonia::Builder<'static> {
    static B: OnceLock<ammonia::Builder<'static>> = OnceLock::new();
    B.get_or_init(|| {
        let mut b = ammonia::Builder::default();
        b.link_rel(Some("noopener noreferrer"))
            .url_relative(ammonia::UrlRelative::Deny)
            .rm_tags(["img"])
            .url_schemes(["http", "https", "mailto"].into_iter().collect());
        b
    })
}

/// Renders Markdown `text` to sanitised HTML. Single newlines become `<br>`.
///
/// Most profile text is plain prose. When the Markdown has no raw HTML, no link and no image,
/// pulldown-cmark's own output is already safe (it escapes all text and emits only formatting
/// tags), so the HTML parse of the sanitiser is skipped; anything else goes through ammonia.
pub fn to_html(text: &str) -> String {
    let text = crate::model::prose(text);
    match prose_html(&text) {
        Some(html) => html,
        None => parsed_html(&text),
    }
}

/// Renders a short documented value ([`crate::render::facts::FactKind::Phrase`]) as
/// [`to_html`] does, with what would open a block at the start of a line taken as text: a
/// range `> 0.01` stays a comparison, `# of samples` and `1. axis` stay text. Code spans,
/// emphasis and line breaks are kept.
pub fn phrase_to_html(text: &str) -> String {
    let text = crate::model::prose(text);
    let mut inline = String::with_capacity(text.len() + 8);
    for (i, line) in text.split('\n').enumerate() {
        if i > 0 {
            inline.push('\n');
        }
        let line = line.trim_start_matches([' ', '\t']);
        match block_marker(line) {
            Some(at) => {
                inline.push_str(&line[..at]);
                inline.push('\\');
                inline.push_str(&line[at..]);
            }
            None => inline.push_str(line),
        }
    }
    to_html(&inline)
}

/// Where a backslash keeps `line` (without leading blanks) from opening a block: before a
/// quotation, heading, list, fence, HTML block, table or rule marker, or before the `.` / `)`
/// of an ordered list number. `None` when the line opens none.
fn block_marker(line: &str) -> Option<usize> {
    let b = line.as_bytes();
    let first = *b.first()?;
    let blank_after = |i: usize| b.get(i).is_none_or(|c| *c == b' ' || *c == b'\t');
    // A table's delimiter row (`-|`, `:--|--:`): with its first character escaped it is text.
    if b.contains(&b'-') && b.iter().all(|c| b"|-: \t".contains(c)) {
        return Some(0);
    }
    let marker = match first {
        b'>' | b'#' | b'=' | b'|' | b'~' | b'<' => true,
        // A bullet, or a rule / setext underline (`---`, `***`, `___`).
        b'-' | b'+' | b'*' | b'_' => {
            blank_after(1) || b.iter().all(|c| matches!(c, b' ' | b'\t') || *c == first)
        }
        b'`' => line.starts_with("```"),
        b'0'..=b'9' if list_number(line) => {
            return b.iter().position(|c| matches!(c, b'.' | b')'));
        }
        _ => false,
    };
    marker.then_some(0)
}

/// The HTML of text that contains nothing Markdown or HTML would read specially — one
/// paragraph of lines without leading/trailing blanks or markup characters, where `<`, `>` and
/// `&` can only be literal (`x > 0`, `< 3.14`, `a & b`) and a leading number is no list item
/// (`0.5`, `20 Hz`) — built without running the parser. `None` for anything else. For such
/// text this is exactly what [`parsed_html`] gives (a property test checks it).
fn prose_html(text: &str) -> Option<String> {
    // A single `~` cannot open or close strikethrough; two might.
    if memchr::memchr_iter(b'~', text.as_bytes()).nth(1).is_some() {
        return None;
    }
    // A table needs a header line and a delimiter line: in one line, `|` is text.
    let one_line = memchr::memchr(b'\n', text.as_bytes()).is_none();
    let mut out = String::with_capacity(text.len() + 16);
    out.push_str("<p>");
    for (i, line) in text.split('\n').enumerate() {
        let first = line.chars().next()?;
        if matches!(first, '#' | '-' | '+' | '=' | ':' | '>') || list_number(line) {
            return None;
        }
        if line.ends_with(' ') || line.starts_with(' ') {
            return None;
        }
        if i > 0 {
            out.push_str("<br>\n");
        }
        prose_line(line, one_line, &mut out)?;
    }
    out.push_str("</p>\n");
    Some(out)
}

/// True for a byte that is text wherever it stands inside a line: not a control character
/// (C0, DEL, or the lead byte 0xC2 of C1 and of other Latin-1 characters), no character
/// Markdown reads specially and none that HTML escapes. Comparisons joined by `&`, so that
/// [`crate::bytes::run_len`] tests sixteen bytes at once.
const fn ordinary(c: u8) -> bool {
    (c >= 0x20)
        & (c != 0x7f)
        & (c != 0xc2)
        & (c != b'\\')
        & (c != b'`')
        & (c != b'*')
        & (c != b'[')
        & (c != b']')
        & (c != b'!')
        & (c != b'|')
        & (c != b'_')
        & (c != b'<')
        & (c != b'>')
        & (c != b'&')
}

/// The bytes that are not [`ordinary`], as a table for the byte-by-byte part of the scan (a
/// test holds the two to the same set).
static SPECIAL: [bool; 256] = crate::render::byte_set(true, b"\\`*[]!|_<>&\x7f\xc2");

/// Writes the HTML of one line of [`prose_html`]'s text to `out`, or `None` when the line
/// holds anything the parser might read as markup. Code spans of single backticks closed on
/// the same line are taken (`arrival_radius` in backticks is common in descriptions).
fn prose_line(line: &str, one_line: bool, out: &mut String) -> Option<()> {
    let b = line.as_bytes();
    // `<` and `&` followed by a space or a digit start no tag, autolink or entity.
    let literal = |i: usize| {
        b.get(i + 1)
            .is_some_and(|c| *c == b' ' || c.is_ascii_digit())
    };
    // `_` between two ASCII letters or digits (`image_width`) can neither open nor close
    // emphasis; anywhere else it might.
    let inert = |i: usize| {
        i > 0
            && b[i - 1].is_ascii_alphanumeric()
            && b.get(i + 1).is_some_and(u8::is_ascii_alphanumeric)
    };
    let mut at = 0;
    while at < b.len() {
        let run = crate::bytes::run_len(&b[at..], ordinary, |c| !SPECIAL[usize::from(c)]);
        // Ordinary bytes are whole characters: the run ends before an ASCII byte, 0xC2 or
        // the end of the line, all of them character boundaries.
        out.push_str(line.get(at..at + run)?);
        at += run;
        let Some(&c) = b.get(at) else { break };
        match c {
            b'<' | b'&' if literal(at) => out.push_str(if c == b'<' { "&lt;" } else { "&amp;" }),
            b'>' => out.push_str("&gt;"),
            b'_' if inert(at) => out.push('_'),
            b'|' if one_line => out.push('|'),
            // A Latin-1 character that is no C1 control (U+00A0–U+00BF).
            0xc2 if b.get(at + 1).is_some_and(|n| *n >= 0xa0) => {
                out.push_str(line.get(at..at + 2)?)
            }
            b'`' => {
                at = code_span(line, at, one_line, out)?;
                continue;
            }
            _ => return None,
        }
        at += if c == 0xc2 { 2 } else { 1 };
    }
    Some(())
}

/// Writes the code span that opens with the single backtick at `open` and returns where the
/// line goes on after it, or `None` when it is no such span: a run of two or more backticks,
/// no closing backtick on the line, or a control character (or, in text of several lines, a
/// `|`) inside.
fn code_span(line: &str, open: usize, one_line: bool, out: &mut String) -> Option<usize> {
    let b = line.as_bytes();
    if b.get(open + 1) == Some(&b'`') {
        return None;
    }
    let close = open + 1 + memchr::memchr(b'`', &b[open + 1..])?;
    if b.get(close + 1) == Some(&b'`') {
        return None;
    }
    let code = line.get(open + 1..close)?;
    let bad = code
        .bytes()
        .zip(code.bytes().skip(1).chain([0]))
        .any(|(c, n)| {
            c < 0x20
                || c == 0x7f
                || (c == 0xc2 && (0x80..0xa0).contains(&n))
                || (c == b'|' && !one_line)
        });
    if bad {
        return None;
    }
    // One space is stripped from each side when both are there and the span is not all spaces.
    let code = match code.strip_prefix(' ').and_then(|c| c.strip_suffix(' ')) {
        Some(inner) if code.bytes().any(|c| c != b' ') => inner,
        _ => code,
    };
    out.push_str("<code>");
    // The parser's own text escaper (`<`, `>`, `&`); writing to a String cannot fail.
    let _ = pulldown_cmark_escape::escape_html_body_text(&mut *out, code);
    out.push_str("</code>");
    Some(close + 1)
}

/// True when the line starts like an ordered list item: up to nine digits, `.` or `)`, then a
/// blank or the end.
fn list_number(line: &str) -> bool {
    let b = line.as_bytes();
    let digits = b.iter().take_while(|c| c.is_ascii_digit()).count();
    (1..=9).contains(&digits)
        && matches!(b.get(digits), Some(b'.' | b')'))
        && b.get(digits + 1).is_none_or(|c| *c == b' ' || *c == b'\t')
}

/// Markdown → HTML through pulldown-cmark, and through the sanitiser when the output could
/// carry anything unsafe.
fn parsed_html(text: &str) -> String {
    let mut opts = Options::empty();
    opts.insert(Options::ENABLE_TABLES);
    opts.insert(Options::ENABLE_STRIKETHROUGH);
    let events: Vec<Event<'_>> = Parser::new_ext(text, opts)
        .map(|e| match e {
            Event::SoftBreak => Event::HardBreak,
            // Words in angle brackets that are no HTML the page keeps (`std::vector<double>`,
            // `<N> joints`, `<port_name>`) are text, not tags for the sanitiser to drop.
            Event::InlineHtml(h) if !kept_html(&h) => Event::Text(h),
            Event::Html(h) if !kept_html(&h) => Event::Text(h),
            other => other,
        })
        .collect();
    let plain = !events.iter().any(|e| {
        matches!(
            e,
            Event::Html(_)
                | Event::InlineHtml(_)
                | Event::Start(Tag::Link { .. } | Tag::Image { .. } | Tag::HtmlBlock)
        )
    });
    let mut raw = String::with_capacity(text.len() + text.len() / 2);
    pulldown_cmark::html::push_html(&mut raw, events.into_iter());
    if plain {
        // Same markup as the sanitiser would give back.
        return raw.replace("<br />", "<br>");
    }
    sanitizer().clean(&raw).to_string()
}

/// The elements of HTML, current and obsolete, sorted.
const HTML_ELEMENTS: &[&str] = &[
    "a",
    "abbr",
    "acronym",
    "address",
    "applet",
    "area",
    "article",
    "aside",
    "audio",
    "b",
    "base",
    "basefont",
    "bdi",
    "bdo",
    "bgsound",
    "big",
    "blink",
    "blockquote",
    "body",
    "br",
    "button",
    "canvas",
    "caption",
    "center",
    "cite",
    "code",
    "col",
    "colgroup",
    "data",
    "datalist",
    "dd",
    "del",
    "details",
    "dfn",
    "dialog",
    "dir",
    "div",
    "dl",
    "dt",
    "em",
    "embed",
    "fieldset",
    "figcaption",
    "figure",
    "font",
    "footer",
    "form",
    "frame",
    "frameset",
    "h1",
    "h2",
    "h3",
    "h4",
    "h5",
    "h6",
    "head",
    "header",
    "hgroup",
    "hr",
    "html",
    "i",
    "iframe",
    "image",
    "img",
    "input",
    "ins",
    "isindex",
    "kbd",
    "keygen",
    "label",
    "legend",
    "li",
    "link",
    "listing",
    "main",
    "map",
    "mark",
    "marquee",
    "math",
    "menu",
    "menuitem",
    "meta",
    "meter",
    "multicol",
    "nav",
    "nextid",
    "nobr",
    "noembed",
    "noframes",
    "noscript",
    "object",
    "ol",
    "optgroup",
    "option",
    "output",
    "p",
    "param",
    "picture",
    "plaintext",
    "portal",
    "pre",
    "progress",
    "q",
    "rb",
    "rp",
    "rt",
    "rtc",
    "ruby",
    "s",
    "samp",
    "script",
    "search",
    "section",
    "select",
    "slot",
    "small",
    "source",
    "spacer",
    "span",
    "strike",
    "strong",
    "style",
    "sub",
    "summary",
    "sup",
    "svg",
    "table",
    "tbody",
    "td",
    "template",
    "textarea",
    "tfoot",
    "th",
    "thead",
    "time",
    "title",
    "tr",
    "track",
    "tt",
    "u",
    "ul",
    "var",
    "video",
    "wbr",
    "xmp",
];

/// Whether raw HTML in profile text is HTML: a comment, or a tag (the fragment's first) that
/// names an HTML element. The sanitiser then keeps it (`<br>`, `<b>`, `</sub>`) or removes it
/// (`<script>`, `<img>`). Anything else in angle brackets (`<double>`, `<N>`, `<port_name>`)
/// is text.
fn kept_html(html: &str) -> bool {
    let h = html.trim_start();
    if h.starts_with("<!--") {
        return true;
    }
    let Some(rest) = h.strip_prefix('<') else {
        return false;
    };
    let rest = rest.strip_prefix('/').unwrap_or(rest);
    let end = rest
        .find(|c: char| c.is_whitespace() || c == '/' || c == '>')
        .unwrap_or(rest.len());
    let name = rest[..end].to_ascii_lowercase();
    HTML_ELEMENTS.binary_search(&name.as_str()).is_ok()
}

/// The first line of `text`, trimmed and cut to at most `max` characters (with `…`), for
/// one-line summaries. Plain text: the caller escapes it.
pub fn first_line(text: &str, max: usize) -> String {
    let text = crate::model::prose(text);
    let line = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty())
        .unwrap_or("");
    if line.chars().count() <= max {
        return line.to_string();
    }
    let mut s: String = line.chars().take(max.saturating_sub(1)).collect();
    s.push('…');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Angle-bracketed words that are no HTML stay as text; tags the page keeps stay tags,
    /// and a script is still removed.
    #[test]
    fn words_in_angle_brackets_are_text() {
        for (text, want) in [
            (
                "outputs std::vector<double> values",
                "std::vector&lt;double&gt; values",
            ),
            (
                "array of std::vector<int> for <N> joints",
                "std::vector&lt;int&gt; for &lt;N&gt; joints",
            ),
            ("set <port_name> first", "set &lt;port_name&gt; first"),
            ("<N> joints\n\nsecond", "&lt;N&gt; joints"),
            ("a <b>bold</b> word", "a <b>bold</b> word"),
            ("x<sub>2</sub>", "x<sub>2</sub>"),
        ] {
            let html = to_html(text);
            assert!(html.contains(want), "{text:?} gave {html:?}");
        }
        assert!(HTML_ELEMENTS.windows(2).all(|w| w[0] < w[1]), "sorted");
        let html = to_html("a <script>alert(1)</script> b");
        assert!(!html.contains("script"), "{html}");
    }

    #[test]
    fn rtcbuilder_line_break_tags_are_line_breaks() {
        for tag in ["<br/>", "<br>", "<BR>", "<br />", "&lt;br/&gt;"] {
            let text = format!("aist.go.jp{tag}産業技術総合研究所");
            assert_eq!(
                to_html(&text),
                "<p>aist.go.jp<br>\n産業技術総合研究所</p>\n",
                "{tag}"
            );
            assert_eq!(first_line(&text, 90), "aist.go.jp", "{tag}");
        }
        assert_eq!(to_html("a <b>c"), to_html(&crate::model::prose("a <b>c")));
        assert_eq!(crate::model::prose("x <brick> & y"), "x <brick> & y");
    }

    #[test]
    fn line_breaks_are_kept() {
        assert_eq!(to_html("a\nb"), "<p>a<br>\nb</p>\n");
    }

    #[test]
    fn payloads_are_removed() {
        let h = to_html(
            "<script>alert(1)</script><img src=x onerror=alert(2)> [x](javascript:alert(3)) \
             <iframe src=\"https://e.invalid\"></iframe><a href=\"https://e.org\" onclick=\"x()\">e</a>",
        );
        assert!(!h.contains("<script"), "{h}");
        assert!(!h.contains("onerror"), "{h}");
        assert!(!h.contains("href=\"javascript:"), "{h}");
        let l = to_html("[x](javascript:alert(3)) and [y](https://e.org)");
        assert!(!l.contains("href=\"javascript:"), "{l}");
        assert!(l.contains("href=\"https://e.org\""), "{l}");
        assert!(!h.contains("<iframe"), "{h}");
        assert!(!h.contains("onclick"), "{h}");
        assert!(h.contains("rel=\"noopener noreferrer\""), "{h}");
    }

    #[test]
    fn plain_text_takes_the_fast_path_with_the_same_markup() {
        for t in [
            "plain words",
            "a\nb",
            "**bold** and `code` & <less>",
            "1. one\n2. two",
            "| a | b |\n|---|---|\n| 1 | 2 |",
        ] {
            let fast = to_html(t);
            assert!(!fast.contains("<br />"));
            assert!(!fast.contains("<less>"), "{fast}");
        }
        assert_eq!(to_html("a & b < c"), "<p>a &amp; b &lt; c</p>\n");
    }

    #[test]
    fn prose_skips_the_parser() {
        assert_eq!(
            prose_html("Images from the camera.\n画像を配信する"),
            Some("<p>Images from the camera.<br>\n画像を配信する</p>\n".to_string())
        );
        assert_eq!(
            prose_html("image_width is \"it's\""),
            Some("<p>image_width is \"it's\"</p>\n".to_string())
        );
        for (t, html) in [
            ("a & b", "<p>a &amp; b</p>\n"),
            ("0.5", "<p>0.5</p>\n"),
            ("20 Hz\n1", "<p>20 Hz<br>\n1</p>\n"),
            ("x > 0", "<p>x &gt; 0</p>\n"),
            ("< 3.14", "<p>&lt; 3.14</p>\n"),
            ("~10 Hz", "<p>~10 Hz</p>\n"),
            // Code spans of one backtick pair, and `|` in one line.
            (
                "see `arrival_radius`",
                "<p>see <code>arrival_radius</code></p>\n",
            ),
            (
                "`a<b & *c*` ok",
                "<p><code>a&lt;b &amp; *c*</code> ok</p>\n",
            ),
            (
                "` x `\n`C:\\tmp`",
                "<p><code>x</code><br>\n<code>C:\\tmp</code></p>\n",
            ),
            ("` `", "<p><code> </code></p>\n"),
            ("`  ` x", "<p><code>  </code> x</p>\n"),
            ("IDLE | RUNNING", "<p>IDLE | RUNNING</p>\n"),
            ("\u{a0}x\u{b0}", "<p>\u{a0}x\u{b0}</p>\n"),
        ] {
            assert_eq!(prose_html(t).as_deref(), Some(html), "{t:?}");
            assert_eq!(parsed_html(t), html, "{t:?}");
        }
        // The last line: code spans the fast path leaves to the parser, and a possible table.
        for t in [
            "",
            "a\n\nb",
            "1. x",
            "2) x",
            "1.",
            "a *b*",
            " a",
            "a  \nb",
            "x\r\ny",
            "- a",
            "_a_",
            "a _b_",
            "a_",
            "~~a~~",
            "> q",
            "<b>",
            "&amp;",
            "a<b",
            "~~~",
            "`a",
            "``a``",
            "`a\nb`",
            "```",
            "``",
            "a|b\n|-|-|",
            "`a`_b",
            "`a|b`\nc",
            "`\u{85}`",
        ] {
            assert_eq!(prose_html(t), None, "{t:?}");
        }
    }

    #[test]
    fn the_byte_table_is_the_ordinary_test() {
        for c in 0..=255u8 {
            assert_eq!(ordinary(c), !SPECIAL[usize::from(c)], "{c:#x}");
        }
    }

    /// Where the fast path takes `t`, it writes what the parser writes.
    fn fast_path_agrees(t: &str) -> Result<(), proptest::test_runner::TestCaseError> {
        if let Some(fast) = prose_html(t) {
            proptest::prop_assert_eq!(fast, parsed_html(t));
        }
        Ok(())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 4096, ..Default::default() })]
        #[test]
        fn prose_matches_the_parser(t in "[a-zA-Z0-9 .,:;()?/=+#@%$^{}_'\"*\\-\n\t\u{3042}\u{FF01}\u{a0}\u{85}<>&~`|\\\\]{0,40}") {
            fast_path_agrees(&t)?;
        }

        /// A small alphabet of the characters that decide between literal text and markup
        /// (`<a>`, `&#1;`, `1. `, `~a~`), so that such sequences actually occur.
        #[test]
        fn prose_matches_the_parser_on_markup_characters(t in "[ab1.;#<>&~/ )\n:`|_\\\\-]{0,16}") {
            fast_path_agrees(&t)?;
        }

        /// Text around a code span of one backtick pair, so that spans actually occur.
        #[test]
        fn code_spans_match_the_parser(
            before in "[a_ `<&|*]{0,6}",
            code in "[a_ `<&|*\\\\\n\t]{0,8}",
            after in "[a_ `<&|*]{0,6}",
        ) {
            let t = format!("{before}`{code}`{after}");
            fast_path_agrees(&t)?;
        }

        /// `|` in one line is text; in several lines it may build a table.
        #[test]
        fn pipes_match_the_parser(t in "[a|\n -]{0,10}") {
            fast_path_agrees(&t)?;
        }

        /// A short documented value opens no block (a blank line still parts paragraphs),
        /// whatever its lines start with.
        #[test]
        fn phrases_open_no_block(t in "[a1.)>#=|~<`*_+\\- \t\n]{0,14}") {
            let html = phrase_to_html(&t);
            for tag in ["<blockquote", "<h", "<ul", "<ol", "<li", "<pre", "<table", "<div"] {
                proptest::prop_assert!(!html.contains(tag), "{:?} gave {}", t, html);
            }
        }
    }

    #[test]
    fn phrases_keep_their_markers_as_text() {
        for (text, want) in [
            ("> 0.01", "<p>&gt; 0.01</p>\n"),
            ("# of samples", "<p># of samples</p>\n"),
            ("1. axis", "<p>1. axis</p>\n"),
            ("2) axis", "<p>2) axis</p>\n"),
            ("- 1 to 1", "<p>- 1 to 1</p>\n"),
            ("-1.0 to 1.0", "<p>-1.0 to 1.0</p>\n"),
            ("metres\n---", "<p>metres<br>\n---</p>\n"),
            ("  < 3.14", "<p>&lt; 3.14</p>\n"),
            ("`x` > 0", "<p><code>x</code> &gt; 0</p>\n"),
            ("*rad*\n> 0", "<p><em>rad</em><br>\n&gt; 0</p>\n"),
            ("```\nx", "<p>```<br>\nx</p>\n"),
        ] {
            assert_eq!(phrase_to_html(text), want, "{text:?}");
        }
        // No table either.
        for t in ["-|\n-|", "a | b\n--|--", "x\n:-:|"] {
            assert!(!phrase_to_html(t).contains("<table"), "{t:?}");
        }
        // Free text keeps its blocks.
        assert!(to_html("> quoted").starts_with("<blockquote>"));
    }

    #[test]
    fn first_lines() {
        assert_eq!(first_line("\n  hello \nworld", 10), "hello");
        assert_eq!(first_line("abcdef", 4), "abc…");
    }
}
