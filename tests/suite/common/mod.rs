//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod books;
pub mod history_repo;
pub mod search_index;

use std::path::{Path, PathBuf};
use std::time::Duration;

/// How long one run of `rtcdoc` (or git, mdbook, doxygen) may take in a test before it is
/// killed and the test fails: far above any real run, so that a hang fails its test with the
/// command's name instead of stalling the whole test run.
pub const COMMAND_LIMIT: Duration = Duration::from_secs(300);

/// How long one browser harness (a Chromium started by node) may take.
pub const BROWSER_LIMIT: Duration = Duration::from_secs(600);

/// `Command::output` with a deadline.
pub trait OutputWithin {
    /// Runs the command to its end, its standard output and error captured, as
    /// [`std::process::Command::output`] does; panics naming the command (and what it printed
    /// so far) when it has not ended within `limit`, after killing it.
    fn output_within(&mut self, limit: Duration) -> std::io::Result<std::process::Output>;
}

impl OutputWithin for std::process::Command {
    fn output_within(&mut self, limit: Duration) -> std::io::Result<std::process::Output> {
        use std::io::Read;
        use std::process::Stdio;
        let mut child = self
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()?;
        let drain = |pipe: Option<Box<dyn Read + Send>>| {
            std::thread::spawn(move || {
                let mut bytes = Vec::new();
                if let Some(mut p) = pipe {
                    let _ = p.read_to_end(&mut bytes);
                }
                bytes
            })
        };
        let out = drain(
            child
                .stdout
                .take()
                .map(|p| Box::new(p) as Box<dyn Read + Send>),
        );
        let err = drain(
            child
                .stderr
                .take()
                .map(|p| Box::new(p) as Box<dyn Read + Send>),
        );
        let start = std::time::Instant::now();
        let status = loop {
            if let Some(status) = child.try_wait()? {
                break status;
            }
            if start.elapsed() > limit {
                let _ = child.kill();
                let _ = child.wait();
                let err = err.join().unwrap_or_default();
                panic!(
                    "{self:?} did not end within {} s and was killed; its standard error:\n{}",
                    limit.as_secs(),
                    String::from_utf8_lossy(&err)
                );
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        Ok(std::process::Output {
            status,
            stdout: out.join().unwrap_or_default(),
            stderr: err.join().unwrap_or_default(),
        })
    }
}

/// The crate root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `../shared/corpus` when it exists (it does on the developers' machines and in CI, not in a
/// plain clone); tests print a visible "skipped" line otherwise.
pub fn corpus() -> Option<PathBuf> {
    let p = root().join("../shared/corpus");
    if p.is_dir() {
        Some(p)
    } else {
        println!("skipped: ../shared/corpus not present");
        None
    }
}

/// Runs a harness of `tests/browser` (`node SCRIPT ARGS…`), one at a time in a test binary:
/// each starts its own Chromium, and two starting together on a small machine made both miss
/// their start deadline. `None` when node cannot be run at all.
pub fn run_browser_harness(cmd: &mut std::process::Command) -> Option<std::process::Output> {
    static ONE_BROWSER: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _turn = ONE_BROWSER
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    match cmd.output_within(BROWSER_LIMIT) {
        Ok(o) => Some(o),
        Err(e) => {
            missing_tool(&format!("cannot run node: {e}"));
            None
        }
    }
}

/// `../shared/tools/NAME` when present.
pub fn shared_tool(name: &str) -> Option<PathBuf> {
    let p = root().join("../shared/tools").join(name);
    p.is_file().then_some(p)
}

/// A minimal valid component profile in RTCBuilder's XML style.
pub fn xml_profile(name: &str, ports: &[(&str, &str, &str)]) -> String {
    let mut s = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcDoc="http://www.openrtp.org/namespaces/rtc_doc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:Test:Cat:{name}:1.0.0" rtc:version="0.2">
  <rtc:BasicInfo xsi:type="rtcExt:basic_info_ext" rtc:name="{name}" rtc:vendor="Test" rtc:category="Cat" rtc:version="1.0.0" rtc:componentType="STATIC" rtc:activityType="PERIODIC" rtc:componentKind="DataFlowComponent" rtc:executionType="PeriodicExecutionContext" rtc:executionRate="1000.0" rtc:creationDate="2024-01-01T00:00:00+09:00" rtc:updateDate="2024-01-01T00:00:00+09:00"/>
  <rtc:Actions>
    <rtc:OnInitialize xsi:type="rtcDoc:action_status_doc" rtc:implemented="true"/>
  </rtc:Actions>
"#
    );
    for (dir, pname, ty) in ports {
        s.push_str(&format!(
            "  <rtc:DataPorts xsi:type=\"rtcExt:dataport_ext\" rtc:portType=\"{dir}\" rtc:name=\"{pname}\" rtc:type=\"{ty}\" rtcExt:position=\"LEFT\"/>\n"
        ));
    }
    s.push_str("</rtc:RtcProfile>\n");
    s
}

/// Writes `content` to `dir/rel`, creating parents.
/// `git ARGS` in `dir` without the user's or the system's configuration (`HOME` is `dir`);
/// whether it succeeded within [`COMMAND_LIMIT`].
pub fn git(dir: &Path, args: &[&str]) -> bool {
    git_with(dir, args, &[])
}

/// [`git`] with extra environment variables (a commit's dates).
pub fn git_with(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> bool {
    std::process::Command::new("git")
        .args(args)
        .current_dir(dir)
        .env("GIT_CONFIG_NOSYSTEM", "1")
        .env("HOME", dir)
        .envs(env.iter().copied())
        .output_within(COMMAND_LIMIT)
        .map(|o| o.status.success())
        .unwrap_or(false)
}

/// A written page as the tests read what it says: its `<wbr>` (the break opportunities the
/// HTML puts inside names, `RTC::<wbr>Timed<wbr>Long`) are markup, not text, and are left out,
/// so that an assertion names `<code>RTC::TimedLong</code>` as a reader sees it. The audit of
/// the browser tests checks the breaks themselves.
pub fn read_page(p: &Path) -> String {
    std::fs::read_to_string(p)
        .unwrap_or_else(|e| panic!("{}: {e}", p.display()))
        .replace("<wbr>", "")
}

pub fn write(dir: &Path, rel: &str, content: &str) {
    let p = dir.join(rel);
    std::fs::create_dir_all(p.parent().expect("parent")).expect("mkdir");
    std::fs::write(p, content).expect("write");
}

/// Runs the built `rtcdoc` binary.
pub fn rtcdoc(args: &[&str], cwd: &Path) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(args)
        .current_dir(cwd)
        .env("NO_COLOR", "1")
        // The fixtures are in this repository: their pages must not show its history (which
        // differs between clones). Temporary repositories of the history tests are elsewhere.
        .env("GIT_CEILING_DIRECTORIES", root())
        .output_within(COMMAND_LIMIT)
        .expect("run rtcdoc")
}

/// The findings of `rtcdoc check INPUT --format json`, run in `cwd`, whose code is one of
/// `codes`, in the report's order.
pub fn findings(cwd: &Path, input: &str, codes: &[&str]) -> Vec<serde_json::Value> {
    let o = rtcdoc(&["check", input, "--format", "json"], cwd);
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("check prints JSON");
    json["diagnostics"]
        .as_array()
        .expect("diagnostics")
        .iter()
        .filter(|d| codes.iter().any(|c| d["code"] == *c))
        .cloned()
        .collect()
}

/// The rest of the standard error of a running `rtcdoc serve`, line by line, as a reader
/// thread receives it (`recv_timeout` waits for a line without hanging the test).
pub type ServeLines = std::sync::mpsc::Receiver<String>;

/// `rtcdoc ARGS` (a `serve`) started in `cwd`, its standard error read up to the line
/// "serving at …" (or 200 lines): the process, the rest of its standard error, the lines read.
/// Panics, after killing it, when it prints no "serving at" line within [`COMMAND_LIMIT`].
pub fn serve_until_ready(
    args: &[&str],
    cwd: &Path,
) -> (std::process::Child, ServeLines, Vec<String>) {
    serve_until_ready_with(args, cwd, &[])
}

/// [`serve_until_ready`] with extra environment variables.
pub fn serve_until_ready_with(
    args: &[&str],
    cwd: &Path,
    env: &[(&str, std::ffi::OsString)],
) -> (std::process::Child, ServeLines, Vec<String>) {
    use std::io::BufRead;
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(args)
        .current_dir(cwd)
        .env("NO_COLOR", "1")
        .envs(env.iter().map(|(k, v)| (k, v)))
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("start rtcdoc serve");
    let stderr = child.stderr.take().expect("stderr");
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stderr)
            .lines()
            .map_while(Result::ok)
        {
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    let deadline = std::time::Instant::now() + COMMAND_LIMIT;
    let mut lines = Vec::new();
    loop {
        let left = deadline.saturating_duration_since(std::time::Instant::now());
        match rx.recv_timeout(left) {
            Ok(line) => {
                let done = line.starts_with("serving at");
                lines.push(line);
                if done || lines.len() > 200 {
                    break;
                }
            }
            Err(std::sync::mpsc::RecvTimeoutError::Disconnected) => break,
            Err(std::sync::mpsc::RecvTimeoutError::Timeout) => {
                let _ = child.kill();
                let _ = child.wait();
                panic!(
                    "rtcdoc {} printed no \"serving at\" within {} s; it printed:\n{}",
                    args.join(" "),
                    COMMAND_LIMIT.as_secs(),
                    lines.join("\n")
                );
            }
        }
    }
    (child, rx, lines)
}

/// `dir/in` holding copies of the hostile-input fixtures `xss.xml` and `xss.yaml`.
pub fn hostile_input(dir: &Path) -> PathBuf {
    let input = dir.join("in");
    std::fs::create_dir_all(&input).expect("mkdir");
    for f in ["xss.xml", "xss.yaml"] {
        std::fs::copy(root().join("tests/fixtures/hostile").join(f), input.join(f))
            .expect("copy fixture");
    }
    input
}

/// Every file below `dir` with its bytes, sorted by relative path.
pub fn tree(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<(String, Vec<u8>)> = walkdir::WalkDir::new(dir)
        .sort_by_file_name()
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file())
        .map(|e| {
            let rel = e
                .path()
                .strip_prefix(dir)
                .expect("prefix")
                .to_string_lossy()
                .replace('\\', "/");
            (rel, std::fs::read(e.path()).expect("read"))
        })
        .collect();
    out.sort();
    out
}

/// Whether `program` runs (`program --version` succeeds).
#[allow(dead_code)]
pub fn tool_available(program: &str) -> bool {
    std::process::Command::new(program)
        .arg("--version")
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false)
}

/// An RT System profile whose naming paths name hosts with and without the name server's
/// port (`COMPONENT_PATH_ID` as RTSystemEditor writes it), and two values that only look like
/// paths.
pub fn naming_path_system(name: &str) -> String {
    format!(
        r#"<?xml version="1.0"?>
<rts:RtsProfile rts:version="0.2" rts:id="RTSystem:Lab:{name}:1.0.0" xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <rts:Components xsi:type="rtsExt:component_ext" rts:isRequired="false" rts:compositeType="None" rts:activeConfigurationSet="default" rts:instanceName="Cam0" rts:pathUri="cam-pc.example.local/Cam0.rtc" rts:id="RTC:Lab:Sensor:Cam:1.0.0">
    <rts:DataPorts xsi:type="rtsExt:dataport_ext" rts:name="Cam0.out"/>
    <rtsExt:Properties rtsExt:value="N/A" rtsExt:name="note"/>
    <rtsExt:Properties rtsExt:value="in/out" rtsExt:name="direction_note"/>
  </rts:Components>
  <rts:Components xsi:type="rtsExt:component_ext" rts:isRequired="false" rts:compositeType="None" rts:activeConfigurationSet="default" rts:instanceName="View0" rts:pathUri="view-pc:2809/View0.rtc" rts:id="RTC:Lab:Sensor:View:1.0.0">
    <rts:DataPorts xsi:type="rtsExt:dataport_ext" rts:name="View0.in"/>
  </rts:Components>
  <rts:DataPortConnectors rts:connectorId="c1" rts:name="Cam0.out_View0.in" rts:dataType="IDL:RTC/CameraImage:1.0" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="flush">
    <rts:sourceDataPort xsi:type="rtsExt:target_port_ext" rts:portName="Cam0.out" rts:instanceName="Cam0" rts:componentId="RTC:Lab:Sensor:Cam:1.0.0">
      <rtsExt:Properties rtsExt:value="150.29.145.246/Cam0.rtc" rtsExt:name="COMPONENT_PATH_ID"/>
    </rts:sourceDataPort>
    <rts:targetDataPort xsi:type="rtsExt:target_port_ext" rts:portName="View0.in" rts:instanceName="View0" rts:componentId="RTC:Lab:Sensor:View:1.0.0">
      <rtsExt:Properties rtsExt:value="rtcname://view-pc.example.local/lab.host_cxt/View0.rtc" rtsExt:name="COMPONENT_PATH_ID"/>
    </rts:targetDataPort>
  </rts:DataPortConnectors>
</rts:RtsProfile>
"#
    )
}

/// A test that needs a tool this machine lacks (git, doxygen, mdbook, tidy, dot, chromium, the
/// npm install of tests/browser). With `CI` set (`.ci/run` sets it, as CI services do) the test
/// fails: CI installs every tool, so a missing one is a broken setup, and a test that did not run
/// is no evidence. Elsewhere it prints a visible `skipped: …` line and the caller returns.
pub fn missing_tool(what: &str) {
    skip_or_fail(in_ci(), what);
}

fn skip_or_fail(ci: bool, what: &str) {
    if ci {
        panic!(
            "{what}, and CI is set: a test that cannot run is no evidence \
             (.ci/run installs every tool the tests drive; unset CI to skip it locally)"
        );
    }
    println!("skipped: {what}");
}

/// Whether `CI` is set to anything but empty, `0` or `false`.
pub fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| !matches!(v.trim(), "" | "0" | "false"))
}

#[test]
#[should_panic(expected = "mdbook not installed, and CI is set")]
fn a_missing_tool_fails_under_ci() {
    skip_or_fail(true, "mdbook not installed");
}

#[test]
fn a_missing_tool_is_a_visible_skip_elsewhere() {
    skip_or_fail(false, "mdbook not installed");
}
