//! What a history leaves out, and how it says what it shows (issue #55, "noise in
//! histories"): RTCBuilder's first save (its placeholder id) named later, callbacks listed as
//! not implemented, a save that only rewrote `updateDate`, messages that say their path once,
//! a long description's word-level difference, and RTCBuilder's `<br/>` as a line break.

use crate::common;
use common::history_repo::{build, commit, init, page};
use common::write;
use serde_json::Value;

/// A profile as RTCBuilder saves it: `vendor`/`category` (its placeholders at first), the
/// description, the callbacks not implemented it lists, and the save time.
fn profile(
    vendor: &str,
    category: &str,
    description: &str,
    unlisted: &[&str],
    saved: &str,
) -> String {
    let mut actions = String::from(
        "    <rtc:OnInitialize xsi:type=\"rtcDoc:action_status_doc\" rtc:implemented=\"true\"/>\n",
    );
    for a in unlisted {
        actions.push_str(&format!(
            "    <rtc:{a} xsi:type=\"rtcDoc:action_status_doc\" rtc:implemented=\"false\"/>\n"
        ));
    }
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcDoc="http://www.openrtp.org/namespaces/rtc_doc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:{vendor}:{category}:Base:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="Base" rtc:vendor="{vendor}" rtc:category="{category}" rtc:version="1.0.0" rtc:description="{description}" rtc:componentType="STATIC" rtc:activityType="PERIODIC" rtc:componentKind="DataFlowComponent" rtc:executionType="PeriodicExecutionContext" rtc:executionRate="1000.0" rtc:creationDate="2024-01-01T10:00:00.000+09:00" rtc:updateDate="{saved}"/>
  <rtc:Actions>
{actions}  </rtc:Actions>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataInPort" rtc:name="cmd" rtc:type="RTC::TimedLong"/>
  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="C++"/>
</rtc:RtcProfile>
"#
    )
}

const CALLBACKS: [&str; 3] = ["OnFinalize", "OnStartup", "OnShutdown"];
const LONG_OLD: &str = "Drives the mobile base from velocity commands and reports the wheel odometry at the rate of the execution context.";
const LONG_NEW: &str = "Drives the mobile base from velocity commands and reports the wheel odometry and the battery state at the rate of the execution context.&lt;br/&gt;Second line.";

/// The test repository in `d` (oldest first): RTCBuilder's first save (placeholder vendor and
/// category), the wizard filled in, the unimplemented callbacks listed, a save that changed
/// nothing but `updateDate`, then the description changed in a few words; `false` without git.
fn repository(d: &std::path::Path) -> bool {
    if !init(d) {
        return false;
    }
    let t = |day: u32| format!("2024-01-0{day}T10:00:00.000+09:00");
    let versions = [
        (
            "First save",
            profile("VenderName", "Category", "ModuleDescription", &[], &t(1)),
        ),
        (
            "Fill in the wizard",
            profile("Lab", "Mobile", LONG_OLD, &[], &t(2)),
        ),
        (
            "List the callbacks",
            profile("Lab", "Mobile", LONG_OLD, &CALLBACKS, &t(3)),
        ),
        (
            "Save again",
            profile("Lab", "Mobile", LONG_OLD, &CALLBACKS, &t(4)),
        ),
        (
            "Describe the battery",
            profile("Lab", "Mobile", LONG_NEW, &CALLBACKS, &t(5)),
        ),
    ];
    for (i, (subject, text)) in versions.into_iter().enumerate() {
        write(d, "Base/RTC.xml", &text);
        commit(d, i + 1, subject);
    }
    true
}

/// (subject, changes) of each version, newest first.
fn history(site: &std::path::Path) -> Vec<(String, Vec<Value>)> {
    let json: Value = serde_json::from_str(&page(site, "catalog.json")).unwrap();
    json["components"]["RTC:Lab:Mobile:Base:1.0.0"]["history"]
        .as_array()
        .expect("a history")
        .iter()
        .map(|e| {
            (
                e["subject"].as_str().unwrap_or("").to_string(),
                e["changes"].as_array().cloned().unwrap_or_default(),
            )
        })
        .collect()
}

#[test]
fn a_history_leaves_out_what_changes_nothing_and_says_each_change_once() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !repository(&repo) {
        println!("skipped: git not available");
        return;
    }
    let site = dir.path().join("json");
    build(&repo, &site, &["-f", "json"]);
    let h = history(&site);
    let subjects: Vec<&str> = h.iter().map(|(s, _)| s.as_str()).collect();
    assert_eq!(
        subjects,
        [
            "Describe the battery",
            "Save again",
            "List the callbacks",
            "Fill in the wizard",
            "First save"
        ]
    );
    let all: Vec<&Value> = h.iter().flat_map(|(_, c)| c).collect();
    // The placeholder id named: information, not a breaking change (nor DIFF208).
    let named = &h[3].1;
    assert!(
        named.iter().all(|c| c["severity"] != "breaking"),
        "{named:#?}"
    );
    assert!(named.iter().all(|c| c["code"] != "DIFF208"), "{named:#?}");
    let id = named
        .iter()
        .find(|c| c["path"] == "id")
        .unwrap_or_else(|| panic!("the id change: {named:#?}"));
    assert_eq!(id["code"], "DIFF308");
    assert!(
        id["message"]
            .as_str()
            .unwrap()
            .contains("named for the first time"),
        "{id:#?}"
    );
    // Callbacks listed as not implemented, and a save that only rewrote `updateDate`: nothing.
    assert_eq!(h[2].1, Vec::<Value>::new(), "{:#?}", h[2].1);
    assert_eq!(h[1].1, Vec::<Value>::new(), "{:#?}", h[1].1);
    assert!(
        all.iter().all(|c| c["path"] != "basicInfo/updateDate"),
        "{all:#?}"
    );
    // No message repeats its path.
    for c in &all {
        let (path, message) = (c["path"].as_str().unwrap(), c["message"].as_str().unwrap());
        assert!(!path.contains('/') || !message.contains(path), "{c:#?}");
    }
    // A long text: its words that changed, not both texts in full.
    let described = &h[0].1;
    let [d] = &described[..] else {
        panic!("one change: {described:#?}")
    };
    assert_eq!(d["path"], "basicInfo/description");
    let message = d["message"].as_str().unwrap();
    assert!(message.starts_with("changed: "), "{message}");
    assert!(
        message.contains("odometry {+and the battery state +}at the rate"),
        "{message}"
    );
    assert!(message.contains("context{+.\nSecond line+}."), "{message}");
    assert!(!message.contains("Drives the mobile base"), "{message}");
    // The values stay whole in the JSON.
    assert_eq!(d["new"], LONG_NEW.replace("&lt;", "<").replace("&gt;", ">"));
}

#[test]
fn the_pages_show_a_long_text_s_words_and_its_line_breaks() {
    let dir = tempfile::tempdir().unwrap();
    let repo = dir.path().join("repo");
    if !repository(&repo) {
        println!("skipped: git not available");
        return;
    }
    let site = dir.path().join("site");
    build(&repo, &site, &["-f", "html,markdown,doxygen"]);
    let html = page(&site, "html/history/base.html");
    assert!(
        html.contains("odometry <ins>and the battery state </ins>at the rate"),
        "{html}"
    );
    assert!(html.contains("<ins>.<br>Second line</ins>"), "{html}");
    assert!(!html.contains("&lt;br"), "{html}");
    // The save that only rewrote `updateDate` and the callbacks are folded.
    assert!(
        html.contains("2 versions without changes to the specification"),
        "{html}"
    );
    let news = page(&site, "html/whats-new.html");
    assert!(!news.contains("updateDate"), "{news}");
    assert!(!news.contains("Save again"), "{news}");
    assert!(news.contains("<ins>and the battery state </ins>"), "{news}");
    for (file, open, br) in [
        // Markdown escapes the braces (mdBook would read `{{`), the brackets too.
        (
            "markdown/history/base.md",
            "&#123;+and the battery state +&#125;",
            "&#123;+.<br>Second line+&#125;",
        ),
        (
            "doxygen/history/base.dox",
            "{+and the battery state +}",
            "{+.<br>Second line+}",
        ),
    ] {
        let text = page(&site, file);
        assert!(text.contains(open), "{file}: {text}");
        assert!(text.contains(br), "{file}: {text}");
        assert!(!text.contains("br/"), "{file}: {text}");
    }
}
