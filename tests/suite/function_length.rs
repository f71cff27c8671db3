//! No function in `src/render/` is longer than [`MAX_LINES`] lines, from the line of its `fn` to
//! the line of its closing brace (nested closures and functions count towards the one holding
//! them): a page's rendering is split into its sections, each readable on its own. Elsewhere in
//! `src/` the functions still longer are listed ([`STILL_LONG`]): the list only shrinks (a new
//! long function fails, and so does a listed one that was split and is still listed).

use std::path::{Path, PathBuf};

const MAX_LINES: usize = 120;

/// The functions outside `src/render/` still over [`MAX_LINES`] (file, name), to be split along
/// their phases (issue 52); none may join them.
const STILL_LONG: &[(&str, &str)] = &[
    ("src/catalog.rs", "build_entries"),
    ("src/diff/idl.rs", "operation"),
    ("src/diff/mod.rs", "classify"),
    ("src/diff/mod.rs", "changed"),
    ("src/diff/systems/compare.rs", "data_connector"),
    ("src/history.rs", "follow_by_id"),
    ("src/implementation/extract.rs", "ident"),
    ("src/implementation/extract.rs", "join"),
    ("src/implementation/lex.rs", "run"),
    ("src/incremental.rs", "update"),
    ("src/layout/wiring.rs", "place_vertically"),
    ("src/layout/wiring.rs", "layout_with"),
    ("src/parse/xml/tree.rs", "build_any_tree"),
    ("src/serve.rs", "start"),
    ("src/serve.rs", "handle"),
];

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).expect("src/render is readable") {
        let p = e.expect("entry").path();
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// `text` with the contents of comments, strings and character literals blanked (line breaks
/// kept), so that braces and `fn` are only those of the code.
fn code_only(text: &str) -> Vec<char> {
    let c: Vec<char> = text.chars().collect();
    let mut out = c.clone();
    let blank = |out: &mut Vec<char>, from: usize, to: usize| {
        for ch in out.iter_mut().take(to.min(c.len())).skip(from) {
            if *ch != '\n' {
                *ch = ' ';
            }
        }
    };
    let mut i = 0;
    while i < c.len() {
        let next = c.get(i + 1).copied();
        if c[i] == '/' && next == Some('/') {
            let end = c[i..]
                .iter()
                .position(|&x| x == '\n')
                .map_or(c.len(), |p| i + p);
            blank(&mut out, i, end);
            i = end;
        } else if c[i] == '/' && next == Some('*') {
            let (mut depth, mut j) = (1, i + 2);
            while j < c.len() && depth > 0 {
                if c[j] == '/' && c.get(j + 1) == Some(&'*') {
                    depth += 1;
                    j += 1;
                } else if c[j] == '*' && c.get(j + 1) == Some(&'/') {
                    depth -= 1;
                    j += 1;
                }
                j += 1;
            }
            blank(&mut out, i, j);
            i = j;
        } else if c[i] == 'r'
            && matches!(next, Some('"' | '#'))
            && (i == 0 || !(c[i - 1].is_alphanumeric() || c[i - 1] == '_'))
        {
            // A raw string: r"…", r#"…"#.
            let hashes = c[i + 1..].iter().take_while(|&&x| x == '#').count();
            if c.get(i + 1 + hashes) != Some(&'"') {
                i += 1;
                continue;
            }
            let close: String = std::iter::once('"')
                .chain(std::iter::repeat_n('#', hashes))
                .collect();
            let start = i + 2 + hashes;
            let rest: String = c[start..].iter().collect();
            let end = rest
                .find(&close)
                .map_or(c.len(), |p| start + rest[..p].chars().count() + close.len());
            blank(&mut out, start, end - close.len());
            i = end;
        } else if c[i] == '"' {
            let mut j = i + 1;
            while j < c.len() && c[j] != '"' {
                j += if c[j] == '\\' { 2 } else { 1 };
            }
            blank(&mut out, i + 1, j);
            i = j + 1;
        } else if c[i] == '\'' {
            // A character literal ('x', '\n', '\u{7f}'), else a lifetime.
            let end = if next == Some('\\') {
                c[i + 2..]
                    .iter()
                    .position(|&x| x == '\'')
                    .map(|p| i + 2 + p)
            } else if c.get(i + 2) == Some(&'\'') {
                Some(i + 2)
            } else {
                None
            };
            match end {
                Some(e) => {
                    blank(&mut out, i + 1, e);
                    i = e + 1;
                }
                None => i += 1,
            }
        } else {
            i += 1;
        }
    }
    out
}

/// Every function of a file with a body: (name, first line, number of lines).
fn functions(text: &str) -> Vec<(String, usize, usize)> {
    let c = code_only(text);
    let line_of = |i: usize| c[..i].iter().filter(|&&x| x == '\n').count() + 1;
    let word = |i: usize| i < c.len() && (c[i].is_alphanumeric() || c[i] == '_');
    let mut out = Vec::new();
    for i in 0..c.len().saturating_sub(3) {
        if c[i] != 'f' || c[i + 1] != 'n' || !c[i + 2].is_whitespace() || (i > 0 && word(i - 1)) {
            continue;
        }
        let mut j = i + 2;
        while j < c.len() && c[j].is_whitespace() {
            j += 1;
        }
        let name: String = c[j..]
            .iter()
            .take_while(|&&x| x.is_alphanumeric() || x == '_')
            .collect();
        if name.is_empty() {
            continue; // a `fn(…)` type
        }
        // The body: the first `{` before any `;` (a declaration without a body has none).
        let Some(open) = c[j..]
            .iter()
            .position(|&x| x == '{' || x == ';')
            .map(|p| j + p)
            .filter(|&p| c[p] == '{')
        else {
            continue;
        };
        let mut depth = 0usize;
        let mut k = open;
        while k < c.len() {
            match c[k] {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                _ => {}
            }
            k += 1;
        }
        let first = line_of(i);
        out.push((name, first, line_of(k.min(c.len() - 1)) - first + 1));
    }
    out
}

#[test]
fn no_function_in_render_is_over_the_limit() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    walk(&root.join("src/render"), &mut files);
    files.sort();
    let mut long = Vec::new();
    let mut counted = 0;
    for f in &files {
        let text = std::fs::read_to_string(f).expect("readable");
        for (name, line, lines) in functions(&text) {
            counted += 1;
            if lines > MAX_LINES {
                let rel = f.strip_prefix(root).expect("below the crate");
                long.push(format!("{}:{line} fn {name}: {lines} lines", rel.display()));
            }
        }
    }
    // The scan is real: the renderers have hundreds of functions.
    assert!(
        counted > 300,
        "only {counted} functions found in src/render"
    );
    assert!(
        long.is_empty(),
        "functions over {MAX_LINES} lines (split them by meaning):\n{}",
        long.join("\n")
    );
}

#[test]
fn the_counter_sees_braces_of_code_only() {
    let text = "fn a() {\n    let s = \"}}{\";\n    let c = '}';\n    // }\n    /* { */\n    let r = r#\"{\"#;\n}\nfn b<'x>(v: &'x str) -> &'x str {\n    v\n}\ntrait T { fn c(&self); }\n";
    let f = functions(text);
    let names: Vec<(&str, usize, usize)> = f.iter().map(|(n, a, b)| (n.as_str(), *a, *b)).collect();
    assert_eq!(names, vec![("a", 1, 7), ("b", 8, 3)]);
}

#[test]
fn no_function_elsewhere_in_src_joins_the_long_ones() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    walk(&root.join("src"), &mut files);
    files.sort();
    let mut long = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(root).expect("below the crate");
        let rel = rel.to_string_lossy().replace('\\', "/");
        let text = std::fs::read_to_string(f).expect("readable");
        for (name, line, lines) in functions(&text) {
            if lines > MAX_LINES {
                long.push((rel.clone(), name, line, lines));
            }
        }
    }
    let new: Vec<String> = long
        .iter()
        .filter(|(f, n, ..)| !STILL_LONG.contains(&(f.as_str(), n.as_str())))
        .map(|(f, n, line, lines)| format!("{f}:{line} fn {n}: {lines} lines"))
        .collect();
    assert!(
        new.is_empty(),
        "functions over {MAX_LINES} lines (split them along their phases):\n{}",
        new.join("\n")
    );
    let split: Vec<String> = STILL_LONG
        .iter()
        .filter(|(f, n)| !long.iter().any(|(lf, ln, ..)| lf == f && ln == n))
        .map(|(f, n)| format!("{f} fn {n}"))
        .collect();
    assert!(
        split.is_empty(),
        "no longer over {MAX_LINES} lines: take them off STILL_LONG:\n{}",
        split.join("\n")
    );
}
