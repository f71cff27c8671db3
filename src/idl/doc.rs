//! Doc comments → [`IdlDoc`]: Doxygen commands (`@cmd` or `\cmd`, at the start of the text
//! or after whitespace) split the text into parts. `@if LANG … @else … @endif` (OpenRTM's
//! bilingual comments) are separated first; then `@brief` (or the first sentence of the
//! untagged text), `@param[dir] name`, `@return`, `@exception`, `@note`, `@see`, `@section`,
//! structural labels (`@struct X`) and any other tag, kept as (tag, text).

use crate::model::idl::{IdlDoc, IdlDocLanguage, IdlDocParam, IdlDocSection, IdlDocTag};

/// A command found in the text: byte range of `@cmd`, and its name.
struct Cmd<'a> {
    start: usize,
    end: usize,
    name: &'a str,
}

fn commands(text: &str) -> Vec<Cmd<'_>> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if (c == b'@' || c == b'\\') && (i == 0 || b[i - 1].is_ascii_whitespace()) {
            let s = i + 1;
            let mut e = s;
            while e < b.len() && (b[e].is_ascii_alphanumeric() || b[e] == b'_') {
                e += 1;
            }
            if e > s && b[s].is_ascii_alphabetic() {
                out.push(Cmd {
                    start: i,
                    end: e,
                    name: &text[s..e],
                });
                i = e;
                continue;
            }
        }
        i += 1;
    }
    out
}

const LABELS: &[&str] = &[
    "struct",
    "interface",
    "enum",
    "typedef",
    "union",
    "class",
    "var",
    "fn",
    "def",
    "file",
    "namespace",
    "module",
    "property",
    "typeinfo",
];

/// Doxygen's commands inside a sentence: `@c word` / `@p word` (code), `@a` / `@e` / `@em`
/// (emphasis), `@b` (bold), `@ref name`, `@link … @endlink` and `\n` (a line break). They mark
/// their word up; they start no part of the comment.
const INLINE: &[&str] = &["c", "p", "a", "e", "em", "b", "ref", "link", "endlink", "n"];

/// `text` with its inline commands ([`INLINE`]) taken out, their words kept as written and
/// `\n` a line break: `Returns @c true when ready` → `Returns true when ready`.
fn inline_commands(text: &str) -> std::borrow::Cow<'_, str> {
    let cmds: Vec<Cmd<'_>> = commands(text)
        .into_iter()
        .filter(|c| INLINE.contains(&c.name))
        .collect();
    if cmds.is_empty() {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len());
    let mut pos = 0;
    for c in cmds {
        out.push_str(&text[pos..c.start]);
        pos = c.end;
        if c.name == "n" {
            out.push('\n');
        }
        // The one blank between the command and its word goes with the command.
        if text[pos..].starts_with([' ', '\t']) {
            pos += 1;
        }
    }
    out.push_str(&text[pos..]);
    std::borrow::Cow::Owned(out)
}

/// Parses a doc comment's stripped text.
pub(crate) fn parse_doc(text: &str) -> IdlDoc {
    let original = text;
    let text = &*inline_commands(text);
    let (main, langs) = split_languages(text);
    let mut doc = parse_body(&main);
    doc.text = original.to_string();
    for (lang, body) in langs {
        let mut d = parse_body(&body);
        d.text = body.trim().to_string();
        doc.languages.push(IdlDocLanguage {
            lang,
            doc: Box::new(d),
        });
    }
    doc
}

/// Splits `@if LANG … @else … @endif`: the text outside any `@if` and the `@else` parts form
/// the main text; each language gets the outside text plus its `@if` part.
fn split_languages(text: &str) -> (String, Vec<(String, String)>) {
    let cmds = commands(text);
    if !cmds.iter().any(|c| c.name == "if") {
        return (text.to_string(), Vec::new());
    }
    let mut main = String::new();
    let mut langs: Vec<(String, String)> = Vec::new();
    // Stack of (language, in-else) for open `@if`s.
    let mut stack: Vec<(String, bool)> = Vec::new();
    let mut pos = 0;
    let route = |seg: &str,
                 stack: &[(String, bool)],
                 langs: &mut Vec<(String, String)>,
                 main: &mut String| {
        match stack.last() {
            None => {
                main.push_str(seg);
                for (_, t) in langs.iter_mut() {
                    t.push_str(seg);
                }
            }
            Some((_, true)) => main.push_str(seg),
            Some((lang, false)) => {
                if let Some((_, t)) = langs.iter_mut().find(|(l, _)| l == lang) {
                    t.push_str(seg);
                }
            }
        }
    };
    for c in &cmds {
        match c.name {
            "if" | "else" | "endif" => {}
            _ => continue,
        }
        route(&text[pos..c.start], &stack, &mut langs, &mut main);
        pos = c.end;
        match c.name {
            "if" => {
                let rest = &text[c.end..];
                let word: String = rest
                    .trim_start_matches([' ', '\t'])
                    .chars()
                    .take_while(|ch| ch.is_alphanumeric() || *ch == '_')
                    .collect();
                let skip = rest.len() - rest.trim_start_matches([' ', '\t']).len() + word.len();
                pos = c.end + skip;
                if !langs.iter().any(|(l, _)| *l == word) {
                    // The shared text seen so far belongs to the new language too.
                    langs.push((word.clone(), main.clone()));
                }
                stack.push((word, false));
            }
            "else" => {
                if let Some(top) = stack.last_mut() {
                    top.1 = true;
                }
            }
            _ => {
                stack.pop();
            }
        }
    }
    route(&text[pos..], &stack, &mut langs, &mut main);
    (main, langs)
}

fn clean(s: &str) -> String {
    let lines: Vec<&str> = s.lines().map(str::trim).collect();
    let mut out = String::new();
    let mut blank = false;
    for l in lines {
        if l.is_empty() {
            blank = !out.is_empty();
            continue;
        }
        if !out.is_empty() {
            out.push_str(if blank { "\n\n" } else { "\n" });
        }
        blank = false;
        out.push_str(l);
    }
    out
}

/// Splits text at its first blank line.
fn first_paragraph(s: &str) -> (&str, &str) {
    let t = s.trim_start();
    for (i, _) in t.match_indices('\n') {
        if t[i + 1..]
            .lines()
            .next()
            .is_some_and(|l| l.trim().is_empty())
        {
            return (&t[..i], &t[i + 1..]);
        }
    }
    (t, "")
}

/// The first sentence: up to `. ` / `。` / a blank line.
fn first_sentence(s: &str) -> (String, String) {
    let (para, rest) = first_paragraph(s);
    let mut cut = None;
    for (i, ch) in para.char_indices() {
        if ch == '。' {
            cut = Some(i + ch.len_utf8());
            break;
        }
        if ch == '.' {
            let next = para[i + 1..].chars().next();
            if next.is_none_or(char::is_whitespace) {
                cut = Some(i + 1);
                break;
            }
        }
    }
    match cut {
        Some(c) => (
            clean(&para[..c]).replace('\n', " "),
            clean(&format!("{}\n\n{}", &para[c..], rest)),
        ),
        None => (clean(para).replace('\n', " "), clean(rest)),
    }
}

fn parse_body(text: &str) -> IdlDoc {
    let mut doc = IdlDoc::default();
    let cmds = commands(text);
    let lead_end = cmds.first().map_or(text.len(), |c| c.start);
    let mut untagged: Vec<String> = vec![text[..lead_end].to_string()];
    let mut brief_parts: Vec<String> = Vec::new();
    let mut details_parts: Vec<String> = Vec::new();
    for (k, c) in cmds.iter().enumerate() {
        let end = cmds.get(k + 1).map_or(text.len(), |n| n.start);
        let arg = &text[c.end..end];
        let name = c.name;
        match name {
            "brief" | "short" => {
                let (b, rest) = first_paragraph(arg);
                brief_parts.push(clean(b).replace('\n', " "));
                untagged.push(rest.to_string());
            }
            "details" => details_parts.push(clean(arg)),
            "param" | "tparam" | "exception" | "throw" | "throws" | "raise" | "raises" => {
                let (direction, arg) = match arg.strip_prefix('[') {
                    Some(r) => match r.find(']') {
                        Some(e) => (Some(r[..e].trim().to_string()), &r[e + 1..]),
                        None => (None, arg),
                    },
                    None => (None, arg),
                };
                let arg = arg.trim_start();
                let split = arg.find(char::is_whitespace).unwrap_or(arg.len());
                let p = IdlDocParam {
                    name: arg[..split].to_string(),
                    direction,
                    text: clean(&arg[split..]),
                };
                if matches!(name, "param" | "tparam") {
                    doc.params.push(p);
                } else {
                    doc.exceptions.push(p);
                }
            }
            "return" | "returns" | "result" | "retval" => {
                let t = clean(arg);
                doc.returns = Some(match doc.returns.take() {
                    Some(prev) => format!("{prev}\n{t}"),
                    None => t,
                });
            }
            "note" | "remark" | "remarks" => doc.notes.push(clean(arg)),
            "see" | "sa" => doc.see.push(clean(arg)),
            "section" | "subsection" | "subsubsection" | "par" => {
                let arg = arg.trim_start_matches([' ', '\t']);
                let (title, body) = arg.split_once('\n').unwrap_or((arg, ""));
                // `@section id Title`: Doxygen's first word is a label; keep the title words.
                let title = title.trim();
                doc.sections.push(IdlDocSection {
                    title: title.to_string(),
                    text: clean(body),
                });
            }
            "endif" | "else" | "if" => {}
            _ if LABELS.contains(&name) => {
                let arg = arg.trim_start_matches([' ', '\t']);
                let (line, rest) = arg.split_once('\n').unwrap_or((arg, ""));
                doc.labels.push(IdlDocTag {
                    tag: name.to_string(),
                    text: line.trim().to_string(),
                });
                untagged.push(rest.to_string());
            }
            _ => doc.tags.push(IdlDocTag {
                tag: name.to_string(),
                text: clean(arg),
            }),
        }
    }
    let untagged = clean(&untagged.join("\n\n"));
    if brief_parts.iter().any(|b| !b.is_empty()) {
        doc.brief = brief_parts
            .into_iter()
            .filter(|b| !b.is_empty())
            .collect::<Vec<_>>()
            .join(" ");
        if !untagged.is_empty() {
            details_parts.insert(0, untagged);
        }
    } else {
        let (b, rest) = first_sentence(&untagged);
        doc.brief = b;
        if !rest.is_empty() {
            details_parts.insert(0, rest);
        }
    }
    doc.details = details_parts
        .into_iter()
        .filter(|d| !d.is_empty())
        .collect::<Vec<_>>()
        .join("\n\n");
    doc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brief_params_return_and_labels() {
        let d = parse_doc(
            "@struct Pose2D\n@brief A pose.\n\nMore text\nhere.\n@param[in] x The x.\n  continued\n@return OK on success\n@note careful\n@see Other\n@author me",
        );
        assert_eq!(d.brief, "A pose.");
        assert_eq!(d.details, "More text\nhere.");
        assert_eq!(
            d.labels,
            [IdlDocTag {
                tag: "struct".into(),
                text: "Pose2D".into()
            }]
        );
        assert_eq!(d.params[0].name, "x");
        assert_eq!(d.params[0].direction.as_deref(), Some("in"));
        assert_eq!(d.params[0].text, "The x.\ncontinued");
        assert_eq!(d.returns.as_deref(), Some("OK on success"));
        assert_eq!(d.notes, ["careful"]);
        assert_eq!(d.see, ["Other"]);
        assert_eq!(
            d.tags,
            [IdlDocTag {
                tag: "author".into(),
                text: "me".into()
            }]
        );
    }

    #[test]
    fn first_sentence_is_the_brief() {
        let d = parse_doc("Time stamp. In seconds\nsince epoch.");
        assert_eq!(d.brief, "Time stamp.");
        assert_eq!(d.details, "In seconds\nsince epoch.");
        let d = parse_doc("Version 1.2 of the thing");
        assert_eq!(d.brief, "Version 1.2 of the thing");
        let d = parse_doc("時刻。秒単位");
        assert_eq!(d.brief, "時刻。");
        let d = parse_doc("mail n-ando@aist.go.jp \\brief B");
        assert_eq!(d.brief, "B");
        assert_eq!(d.details, "mail n-ando@aist.go.jp");
    }

    #[test]
    fn inline_commands_keep_their_words() {
        let d =
            parse_doc("Returns @c true when ready, else \\p fallback.\n@return @c true on success");
        assert_eq!(d.brief, "Returns true when ready, else fallback.");
        assert_eq!(d.returns.as_deref(), Some("true on success"));
        let d = parse_doc("Same as \\ref b but in metres. \\n Second line.");
        assert_eq!(d.brief, "Same as b but in metres.");
        assert_eq!(d.details, "Second line.");
        // The comment as written is kept.
        assert!(d.text.contains("\\ref b"));
    }

    #[test]
    fn bilingual_blocks() {
        let d = parse_doc("@if jp\n@brief 初期化\n@else\n@brief Initialize\n\n@section Description\nStarts it.\n@endif\n@param h handle");
        assert_eq!(d.brief, "Initialize");
        assert_eq!(d.sections[0].title, "Description");
        assert_eq!(d.sections[0].text, "Starts it.");
        assert_eq!(d.params[0].name, "h");
        assert_eq!(d.languages.len(), 1);
        assert_eq!(d.languages[0].lang, "jp");
        assert_eq!(d.languages[0].doc.brief, "初期化");
        assert_eq!(d.languages[0].doc.params[0].name, "h");
    }
}
