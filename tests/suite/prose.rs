//! Text as RTCBuilder writes it: a line break inside a field is the escaped tag `&lt;br/&gt;`
//! (also `<br>`, `<BR>`, `<br />`), and the abstract is often the only Japanese summary. The
//! fixture `tests/fixtures/prose` holds both.

use crate::common;
use common::*;

fn build(formats: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let o = rtcdoc(
        &[
            "build",
            root().join("tests/fixtures/prose").to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "-f",
            formats,
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (dir, out)
}

fn read(p: std::path::PathBuf) -> String {
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

#[test]
fn line_break_tags_are_line_breaks_in_every_output() {
    let (_dir, out) = build("html,markdown,doxygen,json");
    let html = read(out.join("html/components/gaitplanner.html"));
    assert!(
        html.contains("<a href=\"mailto:taro@aist.go.jp\" rel=\"noopener noreferrer\">taro@aist.go.jp</a><br>\n産業技術総合研究所"),
        "{html}"
    );
    assert!(html.contains("Apache-2.0<br>\nsee LICENSE"), "{html}");
    assert!(html.contains("Paper 1<br>\nPaper 2"), "{html}");
    let md = read(out.join("markdown/components/gaitplanner.md"));
    assert!(
        md.contains("| Creator | Taro Yamada &lt;taro@aist.go.jp&gt;<br>産業技術総合研究所 |"),
        "{md}"
    );
    assert!(
        md.contains("| License | Apache-2.0<br>see LICENSE |"),
        "{md}"
    );
    let dox = read(out.join("doxygen/components/gaitplanner.dox"));
    assert!(
        dox.contains("<td>Taro Yamada \\<taro\\@aist.go.jp\\><br>産業技術総合研究所</td>"),
        "{dox}"
    );
    for text in [&html, &md, &dox] {
        for tag in ["br/", "br /", "BR", "&lt;br", "&amp;lt;"] {
            assert!(!text.contains(tag), "{tag} left in the output");
        }
    }
    // The JSON keeps the value as written.
    let json = read(out.join("json/catalog.json"));
    assert!(
        json.contains("taro@aist.go.jp><br/>産業技術総合研究所"),
        "{json}"
    );
}

#[test]
fn the_abstract_and_the_document_profile_are_searchable() {
    let (_dir, out) = build("html");
    let index = common::search_index::read(&out);
    let entry = index.entry("GaitPlanner");
    let tokens: Vec<&String> = entry.groups.iter().flatten().collect();
    // 四足歩行 (in the abstract only), the creator, the license.
    for token in ["四足", "足歩", "歩行", "taro", "yamada", "apache"] {
        assert!(
            tokens.iter().any(|t| t.starts_with(token)),
            "{token} not indexed: {tokens:?}"
        );
    }
    assert!(!tokens.iter().any(|t| *t == "br"), "{tokens:?}");
}
