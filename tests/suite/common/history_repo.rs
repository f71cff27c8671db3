//! A git work tree whose one profile has a history with every kind of entry the history pages
//! show: a first version, a release that adds a data port, a service port with its interface
//! and a configuration parameter, a commit that changes nothing of the specification, and a
//! breaking rename without a version bump (DIFF208). Commits are dated 2024-01-01 … 04.

use std::path::Path;

const V1: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:Lab:Mobile:Base:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="Base" rtc:vendor="Lab" rtc:category="Mobile" rtc:version="1.0.0" rtc:componentType="STATIC" rtc:activityType="PERIODIC" rtc:componentKind="DataFlowComponent" rtc:executionType="PeriodicExecutionContext" rtc:executionRate="100.0"/>
  <rtc:ConfigurationSet>
    <rtc:Configuration xsi:type="rtcExt:configuration_ext" rtc:type="double" rtc:name="max_speed" rtc:defaultValue="1.0"/>
  </rtc:ConfigurationSet>
  <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtc:portType="DataInPort" rtc:name="cmd" rtc:type="RTC::TimedVelocity2D"/>
  <rtc:Language xsi:type="rtcExt:language_ext" rtc:kind="C++"/>
</rtc:RtcProfile>
"#;

/// `text` with each (from, to) replaced once; every `from` must be there.
pub fn edit(text: &str, edits: &[(&str, &str)]) -> String {
    let mut s = text.to_string();
    for (from, to) in edits {
        assert!(s.contains(from), "edit `{from}` does not apply");
        s = s.replacen(from, to, 1);
    }
    s
}

/// The versions, oldest first: (subject, profile).
pub fn versions() -> Vec<(&'static str, String)> {
    let v2 = edit(
        V1,
        &[
            (":Base:1.0.0\"", ":Base:1.1.0\""),
            ("rtc:version=\"1.0.0\"", "rtc:version=\"1.1.0\""),
            (
                "  </rtc:ConfigurationSet>",
                "    <rtc:Configuration xsi:type=\"rtcExt:configuration_ext\" rtc:type=\"int\" rtc:name=\"gain\" rtc:defaultValue=\"2\"/>\n  </rtc:ConfigurationSet>",
            ),
            (
                "  <rtc:Language",
                "  <rtc:DataPorts xsi:type=\"rtcExt:dataport_ext\" rtc:portType=\"DataOutPort\" rtc:name=\"status\" rtc:type=\"RTC::TimedLong\"/>\n  <rtc:ServicePorts xsi:type=\"rtcExt:serviceport_ext\" rtc:name=\"svc\">\n    <rtc:ServiceInterface xsi:type=\"rtcExt:serviceinterface_ext\" rtc:type=\"Lab::Map\" rtc:direction=\"Provided\" rtc:name=\"map\"/>\n  </rtc:ServicePorts>\n  <rtc:Language",
            ),
        ],
    );
    let v3 = edit(&v2, &[("  <rtc:Language", "<rtc:Language")]);
    let v4 = edit(&v3, &[(r#"rtc:name="cmd""#, r#"rtc:name="velocity""#)]);
    vec![
        ("First version", V1.to_string()),
        ("Release 1.1.0 <with status>", v2),
        ("Reformat", v3),
        ("Rename cmd", v4),
    ]
}

/// `git ARGS` in `dir` with author and committer date `date`, without the user's or the
/// system's configuration; whether it succeeded.
pub fn git(dir: &Path, args: &[&str], date: &str) -> bool {
    super::git_with(
        dir,
        args,
        &[("GIT_AUTHOR_DATE", date), ("GIT_COMMITTER_DATE", date)],
    )
}

/// A fresh repository in `d`, or `false` when git does not run.
pub fn init(d: &Path) -> bool {
    std::fs::create_dir_all(d).expect("mkdir");
    if !git(d, &["--version"], "") {
        return false;
    }
    assert!(git(d, &["init", "-q"], ""));
    assert!(git(d, &["config", "user.name", "Tester"], ""));
    assert!(git(d, &["config", "user.email", "t@example.org"], ""));
    true
}

/// Commits everything on day `day` of January 2024.
pub fn commit(d: &Path, day: usize, subject: &str) {
    let date = format!("2024-01-{day:02} 10:00:00 +0900");
    assert!(git(d, &["add", "-A"], &date));
    assert!(git(d, &["commit", "-q", "-m", subject], &date));
}

/// Commits `versions` (oldest first) as `Base/RTC.xml` in a new work tree `d`, one a day from
/// 2024-01-01; `false` without git.
pub fn commit_versions(d: &Path, versions: Vec<(&str, String)>) -> bool {
    if !init(d) {
        return false;
    }
    for (i, (subject, text)) in versions.into_iter().enumerate() {
        super::write(d, "Base/RTC.xml", &text);
        commit(d, i + 1, subject);
    }
    true
}

/// Commits [`versions`] as `Base/RTC.xml` in a new work tree `d`; `false` without git.
pub fn history_repo(d: &Path) -> bool {
    commit_versions(d, versions())
}

/// `rtcdoc build INPUT -o OUT EXTRA…`, which must succeed.
pub fn build(input: &Path, out: &Path, extra: &[&str]) {
    let mut args = vec![
        "build",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = super::rtcdoc(&args, input);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Builds `dir/proj`, whose `rtcdoc.toml` has one `[[source]]` `lab` (git `dir/repo`, a
/// `source-url` with `{commit}`), in `formats` into `dir/site` with the cache `dir/cache`;
/// the output folder.
pub fn build_source_project(dir: &Path, formats: &str) -> std::path::PathBuf {
    let proj = dir.join("proj");
    super::write(
        &proj,
        "rtcdoc.toml",
        "[[source]]\ngit = \"../repo\"\nname = \"lab\"\nsource-url = \"https://git.example.org/lab/blob/{commit}/{path}\"\n",
    );
    let (cache, out) = (dir.join("cache"), dir.join("site"));
    let args = ["-f", formats, "--cache-dir", cache.to_str().unwrap()];
    let mut all = vec!["build", "-o", out.to_str().unwrap()];
    all.extend_from_slice(&args);
    let o = super::rtcdoc(&all, &proj);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out
}

/// The text of output file `rel` of `dir`.
pub fn page(dir: &Path, rel: &str) -> String {
    super::read_page(&dir.join(rel))
}

/// The change codes of a history entry of catalog.json.
pub fn codes(entry: &serde_json::Value) -> Vec<&str> {
    entry["changes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["code"].as_str().unwrap())
        .collect()
}
