//! `rtcdoc serve`: incremental rebuilds equal clean builds, errors keep the last good site, and
//! the live server reloads browsers over its websocket.

use crate::common;
use common::*;
use rtcdoc::build::BuildOptions;
use rtcdoc::incremental::{UpdateError, Workspace};
use rtcdoc::render::{Format, SiteOptions};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn copy_examples(dst: &Path) {
    for (rel, bytes) in tree(&root().join("examples")) {
        let p = dst.join(&rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
}

fn options(input: &Path) -> BuildOptions {
    BuildOptions {
        input: input.to_path_buf(),
        output: input.join("site"),
        formats: vec![Format::Html],
        strict: false,
        load: Default::default(),
        site: SiteOptions::default(),
    }
}

fn edit(path: &Path, from: &str, to: &str) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.contains(from), "{} lacks {from:?}", path.display());
    std::fs::write(path, text.replacen(from, to, 1)).unwrap();
}

fn assert_same_as_clean_build(ws: &Workspace, input: &Path) {
    let clean = Workspace::open(&options(input)).unwrap();
    let a: Vec<&String> = ws.files().keys().collect();
    let b: Vec<&String> = clean.files().keys().collect();
    assert_eq!(a, b, "same file list");
    for (k, v) in clean.files() {
        assert!(ws.files()[k] == *v, "{k} differs from a clean build");
    }
}

#[test]
fn incremental_updates_equal_clean_builds() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("cat");
    copy_examples(&input);
    let mut ws = Workspace::open(&options(&input)).unwrap();
    let total = ws.files().len();

    // 1. Text only: the component page and the indexes, not the whole site.
    let pp = input.join("PathPlanner/RTC.xml");
    edit(&pp, "Grid path planner", "Grid path planner (edited)");
    let r = ws.update(std::slice::from_ref(&pp)).unwrap();
    assert!(!r.full && r.rendered < total, "{r:?} of {total}");
    assert!(
        String::from_utf8_lossy(&ws.files()["components/pathplanner.html"]).contains("(edited)")
    );
    assert_same_as_clean_build(&ws, &input);

    // 2. A port changes type: cross-links of both types change on other components' pages.
    let joy = input.join("Joystick/RTC.xml");
    edit(
        &joy,
        "rtc:type=\"RTC::TimedVelocity2D\"",
        "rtc:type=\"RTC::TimedPose2D\"",
    );
    let r = ws.update(std::slice::from_ref(&joy)).unwrap();
    assert!(!r.full, "{r:?}");
    assert_same_as_clean_build(&ws, &input);

    // 3. A new type appears (new type page), then a component is renamed (full rebuild).
    edit(
        &joy,
        "rtc:type=\"RTC::TimedPose2D\"",
        "rtc:type=\"Joy::TimedJoystick\"",
    );
    ws.update(std::slice::from_ref(&joy)).unwrap();
    assert_same_as_clean_build(&ws, &input);
    assert!(ws
        .files()
        .keys()
        .any(|k| k.starts_with("types/joy-timedjoystick")));
    edit(&joy, "rtc:name=\"Joystick\"", "rtc:name=\"Gamepad\"");
    let r = ws.update(std::slice::from_ref(&joy)).unwrap();
    assert!(r.full);
    assert_same_as_clean_build(&ws, &input);

    // 4. A profile is deleted, another is added.
    std::fs::remove_dir_all(input.join("Navigator")).unwrap();
    write(
        &input,
        "New/RTC.xml",
        &xml_profile("NewComp", &[("DataInPort", "in", "RTC::RangeData")]),
    );
    ws.update(&[input.join("Navigator/RTC.xml"), input.join("New/RTC.xml")])
        .unwrap();
    assert_same_as_clean_build(&ws, &input);
}

#[test]
fn a_broken_profile_keeps_the_last_good_site() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("cat");
    copy_examples(&input);
    let mut ws = Workspace::open(&options(&input)).unwrap();
    let before = ws.files().clone();
    let pp = input.join("PathPlanner/RTC.xml");
    edit(&pp, "</rtc:BasicInfo>", "</rtc:Basic>");
    match ws.update(std::slice::from_ref(&pp)) {
        Err(UpdateError::Profiles(d)) => {
            assert_eq!(d[0].file, "PathPlanner/RTC.xml");
            assert!(d[0].pos.is_some());
        }
        other => panic!("expected a profile error, got {other:?}"),
    }
    assert!(ws.files() == &before, "the last good site stays");
}

/// A profile that grows past the size limit while served is reported (RTC002) from what was
/// read up to the limit, not read whole.
#[test]
fn a_profile_grown_past_the_limit_is_reported_not_read() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("cat");
    copy_examples(&input);
    let mut opts = options(&input);
    opts.load.limits.max_file_size = 64 * 1024;
    let mut ws = Workspace::open(&opts).unwrap();
    let pp = input.join("PathPlanner/RTC.xml");
    let text = std::fs::read_to_string(&pp).unwrap();
    let padding = "<!-- padding -->".repeat(8 * 1024);
    std::fs::write(
        &pp,
        text.replacen("</rtc:BasicInfo>", &format!("</rtc:BasicInfo>{padding}"), 1),
    )
    .unwrap();
    match ws.update(std::slice::from_ref(&pp)) {
        Err(UpdateError::Profiles(d)) => {
            assert_eq!(d[0].code, "RTC002", "{d:?}");
            assert!(d[0].message.contains("65536"), "{}", d[0].message);
        }
        other => panic!("expected RTC002, got {other:?}"),
    }
}

fn http_get(port: u16, path: &str) -> (String, String) {
    let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    // A server that never answers fails the test instead of stalling the run.
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut buf = String::new();
    s.read_to_string(&mut buf).unwrap();
    let (head, body) = buf.split_once("\r\n\r\n").unwrap_or((&buf, ""));
    (
        head.lines().next().unwrap_or("").to_string(),
        body.to_string(),
    )
}

fn next_message(ws: &mut Socket) -> String {
    loop {
        match ws.read().expect("websocket message") {
            tungstenite::Message::Text(t) => return t.to_string(),
            _ => continue,
        }
    }
}

type Socket = tungstenite::WebSocket<tungstenite::stream::MaybeTlsStream<std::net::TcpStream>>;

/// The live-reload websocket of the server on `port`, once the watcher had a moment to be
/// armed (slow machines).
fn live_socket(port: u16) -> Socket {
    let (mut ws, _) = tungstenite::connect(format!("ws://127.0.0.1:{port}/__rtcdoc/ws")).unwrap();
    if let tungstenite::stream::MaybeTlsStream::Plain(s) = ws.get_mut() {
        s.set_read_timeout(Some(Duration::from_secs(20))).ok();
    }
    std::thread::sleep(Duration::from_millis(300));
    ws
}

#[test]
fn server_serves_rebuilds_and_live_reloads() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("cat");
    copy_examples(&input);
    let handle = rtcdoc::serve::start(
        rtcdoc::serve::ServeOptions {
            build: options(&input),
            port: 0,
            watch: vec![],
            reconfigure: None,
            file_name: None,
        },
        std::sync::Arc::new(|_: &str| {}),
    )
    .unwrap();
    let port = handle.port();

    let (status, body) = http_get(port, "/");
    assert!(status.contains("200"), "{status}");
    assert!(
        body.contains("/__rtcdoc/livereload.js"),
        "live-reload script injected"
    );
    let (status, _) = http_get(port, "/components/pathplanner.html");
    assert!(status.contains("200"));
    let (status, body) = http_get(port, "/no/such/page.html");
    assert!(status.contains("404"));
    assert!(body.contains("<html"));
    let (_, js) = http_get(port, "/__rtcdoc/livereload.js");
    assert!(js.contains("WebSocket"));

    let mut ws = live_socket(port);
    let pp: PathBuf = input.join("PathPlanner/RTC.xml");
    let start = Instant::now();
    edit(&pp, "Grid path planner", "Grid path planner LIVE");
    assert_eq!(next_message(&mut ws), "reload");
    println!(
        "change → reload message in {} ms",
        start.elapsed().as_millis()
    );
    let (_, body) = http_get(port, "/components/pathplanner.html");
    assert!(body.contains("LIVE"));

    // A broken profile: an error message for the overlay, and the last good page is served.
    edit(&pp, "</rtc:BasicInfo>", "</rtc:Basic>");
    let msg = next_message(&mut ws);
    assert!(
        msg.starts_with("error:") && msg.contains("PathPlanner/RTC.xml"),
        "{msg}"
    );
    let (status, body) = http_get(port, "/components/pathplanner.html");
    assert!(status.contains("200") && body.contains("LIVE"));
    handle.stop();
}

/// A change to a watched path (the configuration file) rebuilds the whole site with the
/// options `reconfigure` reads anew.
#[test]
fn a_watched_configuration_change_reconfigures_the_site() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("cat");
    copy_examples(&input);
    let config = dir.path().join("title.txt");
    std::fs::write(&config, "First title").unwrap();
    let (path, base) = (config.clone(), options(&input));
    let reconfigure: rtcdoc::serve::Reconfigure = std::sync::Arc::new(move || {
        let mut o = base.clone();
        o.site.title = std::fs::read_to_string(&path)?;
        Ok(o)
    });
    let mut first = options(&input);
    first.site.title = "First title".into();
    let handle = rtcdoc::serve::start(
        rtcdoc::serve::ServeOptions {
            build: first,
            port: 0,
            watch: vec![config.clone()],
            reconfigure: Some(reconfigure),
            file_name: None,
        },
        std::sync::Arc::new(|_: &str| {}),
    )
    .unwrap();
    let port = handle.port();
    let (_, body) = http_get(port, "/");
    assert!(body.contains("First title"));
    let mut ws = live_socket(port);
    std::fs::write(&config, "Second title").unwrap();
    assert_eq!(next_message(&mut ws), "reload");
    let (_, body) = http_get(port, "/");
    assert!(body.contains("Second title") && !body.contains("First title"));
    handle.stop();
}

/// Source code edited, added or removed while serving: the implementations are read again and
/// a component with code and no profile appears or goes, as a clean build has it.
#[test]
fn code_edits_update_the_implementation_and_the_recovered_components() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("cat");
    let fixtures = root().join("tests/fixtures/implementation");
    for (rel, bytes) in tree(&fixtures.join("python-edited")) {
        let p = input.join("Sensor").join(&rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
    let mut ws = Workspace::open(&options(&input)).unwrap();
    let drift = |ws: &Workspace| {
        ws.catalog().components[0]
            .implementation
            .as_ref()
            .map_or(0, |i| i.drift.len())
    };
    assert!(drift(&ws) > 0);
    // The code put back in line with the profile's in-port.
    let py = std::fs::read_dir(input.join("Sensor"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "py"))
        .unwrap();
    let text = std::fs::read_to_string(&py).unwrap();
    std::fs::write(&py, text.replace("distance_sensor", "ir_sensor")).unwrap();
    ws.update(std::slice::from_ref(&py)).unwrap();
    assert_same_as_clean_build(&ws, &input);
    // A component with code and no profile, added.
    let counter = input.join("Counter/Counter.py");
    std::fs::create_dir_all(counter.parent().unwrap()).unwrap();
    std::fs::copy(fixtures.join("recovered/Counter/Counter.py"), &counter).unwrap();
    ws.update(std::slice::from_ref(&counter)).unwrap();
    assert!(ws
        .catalog()
        .components
        .iter()
        .any(|c| c.recovered.is_some() && c.profile.name() == "Counter"));
    assert_same_as_clean_build(&ws, &input);
    // A profile edit keeps the recovered component as it was.
    let rtc = input.join("Sensor/RTC.xml");
    edit(&rtc, "</rtc:BasicInfo>", "</rtc:BasicInfo>\n");
    ws.update(std::slice::from_ref(&rtc)).unwrap();
    assert_same_as_clean_build(&ws, &input);
    std::fs::remove_file(&counter).unwrap();
    ws.update(std::slice::from_ref(&counter)).unwrap();
    assert!(!ws
        .catalog()
        .components
        .iter()
        .any(|c| c.recovered.is_some()));
    assert_same_as_clean_build(&ws, &input);
}
