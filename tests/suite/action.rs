//! The GitHub composite action (`action.yml`), run the way GitHub runs it, without GitHub.
//!
//! Static checks: no step script interpolates `${{ … }}` (script injection), every expression
//! names a declared input or an earlier step, every step output read is one its script writes.
//!
//! Runs: the composite steps in order, as the runner would — `uses:` steps (actions/cache) are
//! simulated as a cache miss or hit, `if:` conditions are evaluated, each `run:` goes to
//! `bash --noprofile --norc -eo pipefail FILE` (GitHub's `shell: bash`) with the step's `env:`
//! (inputs substituted), `GITHUB_ACTION_PATH` = the repository, `GITHUB_OUTPUT`/`GITHUB_PATH`/
//! `GITHUB_STEP_SUMMARY` files per step, lines of `GITHUB_PATH` prepended to the next steps'
//! PATH, and a stub `cargo` whose `install` links the freshly built rtcdoc into
//! `~/.cargo/bin` — so later steps find rtcdoc only through what the action installs.
#![cfg(unix)]

use crate::common;
use common::OutputWithin;

use serde_norway::Value;
use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn action() -> Value {
    let path = repo().join("action.yml");
    let text = fs::read_to_string(&path).expect("action.yml at the repository root");
    serde_norway::from_str(&text).expect("action.yml is valid YAML")
}

fn steps(action: &Value) -> Vec<Value> {
    assert_eq!(action["runs"]["using"].as_str(), Some("composite"));
    action["runs"]["steps"]
        .as_sequence()
        .expect("runs.steps is a list")
        .clone()
}

fn inputs(action: &Value) -> BTreeMap<String, String> {
    action["inputs"]
        .as_mapping()
        .expect("inputs is a mapping")
        .iter()
        .map(|(k, v)| {
            let name = k.as_str().expect("input name").to_string();
            let default = match &v["default"] {
                Value::String(s) => s.clone(),
                Value::Null => String::new(),
                other => panic!("input {name}: default {other:?} is not a string"),
            };
            (name, default)
        })
        .collect()
}

/// The `${{ … }}` expressions of a string, trimmed.
fn expressions(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = s;
    while let Some(start) = rest.find("${{") {
        let after = &rest[start + 3..];
        let end = after.find("}}").expect("unterminated ${{ expression");
        out.push(after[..end].trim().to_string());
        rest = &after[end + 2..];
    }
    out
}

/// Every string in a YAML value, with its place, for the expression checks.
fn strings<'a>(v: &'a Value, place: String, out: &mut Vec<(String, &'a str)>) {
    match v {
        Value::String(s) => out.push((place, s)),
        Value::Sequence(items) => {
            for (i, item) in items.iter().enumerate() {
                strings(item, format!("{place}[{i}]"), out);
            }
        }
        Value::Mapping(m) => {
            for (k, item) in m {
                strings(item, format!("{place}.{}", k.as_str().unwrap_or("?")), out);
            }
        }
        _ => {}
    }
}

fn step_id(step: &Value) -> Option<&str> {
    step["id"].as_str()
}

/// The script file a `run:` calls (`bash "$GITHUB_ACTION_PATH/FILE"`), relative to the repo.
fn script_of(run: &str) -> &str {
    let run = run.trim();
    let file = run
        .strip_prefix("bash \"$GITHUB_ACTION_PATH/")
        .and_then(|r| r.strip_suffix('"'))
        .unwrap_or_else(|| panic!("run: `{run}` is not `bash \"$GITHUB_ACTION_PATH/FILE\"`"));
    assert!(!file.contains('"') && !file.contains('$'), "run: `{run}`");
    file
}

#[test]
fn run_scripts_interpolate_no_expression_and_live_in_files() {
    let action = action();
    let mut runs = 0;
    for step in steps(&action) {
        let Some(run) = step["run"].as_str() else {
            continue;
        };
        runs += 1;
        let name = step["name"].as_str().unwrap_or("?");
        assert!(
            !run.contains("${{"),
            "step `{name}`: its run: interpolates an expression (script injection): {run}"
        );
        assert_eq!(
            step["shell"].as_str(),
            Some("bash"),
            "step `{name}`: composite run steps need `shell: bash`"
        );
        let file = script_of(run);
        let text = fs::read_to_string(repo().join(file))
            .unwrap_or_else(|e| panic!("step `{name}` runs {file}: {e}"));
        assert!(
            !text.contains("${{"),
            "{file} holds a GitHub expression; it would not be evaluated there"
        );
        assert!(
            text.contains("set -euo pipefail"),
            "{file} must stop on errors"
        );
        // Values from the action reach the script through env: only.
        if let Some(env) = step["env"].as_mapping() {
            for (k, v) in env {
                let k = k.as_str().expect("env name");
                let v = v.as_str().expect("env value");
                assert!(
                    v.trim().starts_with("${{") && expressions(v).len() == 1,
                    "step `{name}`: env {k} should be one `${{{{ inputs.X }}}}`, is `{v}`"
                );
                assert!(
                    text.contains(&format!("${{{k}")) || text.contains(&format!("${k}")),
                    "step `{name}`: env {k} is not read by {file}"
                );
            }
        }
    }
    assert_eq!(runs, 4, "prepare, install, check, build");
}

#[test]
fn expressions_name_declared_inputs_and_earlier_steps_outputs() {
    let action = action();
    let inputs = inputs(&action);
    let steps = steps(&action);
    let mut used_inputs = Vec::new();
    let check = |place: &str, expr: &str, known_steps: &[&Value], used: &mut Vec<String>| {
        for word in expr.split(|c: char| !(c.is_alphanumeric() || "._-".contains(c))) {
            if let Some(name) = word.strip_prefix("inputs.") {
                assert!(
                    inputs.contains_key(name),
                    "{place}: `{expr}` reads input `{name}`, which inputs: does not declare"
                );
                used.push(name.to_string());
            } else if let Some(rest) = word.strip_prefix("steps.") {
                let (id, output) = rest
                    .split_once(".outputs.")
                    .unwrap_or_else(|| panic!("{place}: `{expr}`"));
                let step = known_steps
                    .iter()
                    .find(|s| step_id(s) == Some(id))
                    .unwrap_or_else(|| panic!("{place}: `{expr}` reads step `{id}`, not before"));
                if let Some(run) = step["run"].as_str() {
                    let text = fs::read_to_string(repo().join(script_of(run))).expect("script");
                    assert!(
                        text.contains(&format!("echo \"{output}=")),
                        "{place}: `{expr}`: the script of step `{id}` never writes `{output}`"
                    );
                } else {
                    assert!(
                        step["uses"]
                            .as_str()
                            .is_some_and(|u| u.starts_with("actions/cache@"))
                            && output == "cache-hit",
                        "{place}: `{expr}`: unknown output of a `uses:` step"
                    );
                }
            } else if ["runner.os", "runner.arch"].contains(&word) {
            } else if word.contains('.') {
                panic!("{place}: `{expr}` uses `{word}`, which tests/suite/action.rs cannot check");
            }
        }
    };
    for (i, step) in steps.iter().enumerate() {
        let earlier: Vec<&Value> = steps[..i].iter().collect();
        let mut found = Vec::new();
        strings(step, format!("steps[{i}]"), &mut found);
        for (place, s) in found {
            for expr in expressions(s) {
                check(&place, &expr, &earlier, &mut used_inputs);
            }
        }
        if let Some(cond) = step["if"].as_str() {
            check(&format!("steps[{i}].if"), cond, &earlier, &mut used_inputs);
        }
    }
    let all: Vec<&Value> = steps.iter().collect();
    let mut found = Vec::new();
    strings(&action["outputs"], "outputs".into(), &mut found);
    for (place, s) in found {
        for expr in expressions(s) {
            check(&place, &expr, &all, &mut used_inputs);
        }
    }
    for name in inputs.keys() {
        assert!(
            used_inputs.contains(name),
            "input `{name}` is declared but never used"
        );
    }
    for key in ["site", "errors", "warnings"] {
        assert!(
            action["outputs"][key]["value"].is_string(),
            "output {key} missing"
        );
    }
}

#[test]
fn inputs_have_the_documented_defaults() {
    let inputs = inputs(&action());
    for (name, default) in [
        ("input", "."),
        ("output", "site"),
        ("formats", "html"),
        ("base-url", ""),
        ("fail-on", "error"),
        ("args", ""),
        ("check-args", ""),
    ] {
        assert_eq!(
            inputs.get(name).map(String::as_str),
            Some(default),
            "{name}"
        );
    }
}

/// What one run of the action did.
#[derive(Debug)]
struct Run {
    /// `(step id or name, exit status, stdout + stderr)` of each `run:` step executed.
    steps: Vec<(String, i32, String)>,
    /// `GITHUB_OUTPUT` of each step, by step id.
    outputs: BTreeMap<String, BTreeMap<String, String>>,
    /// The action's outputs, evaluated from `outputs:`.
    action_outputs: BTreeMap<String, String>,
    /// Whether every step succeeded.
    success: bool,
    /// Arguments the stub `cargo` was called with, one per line (empty if never called).
    cargo_args: String,
    /// The job summary written.
    summary: String,
}

impl Run {
    fn step(&self, id: &str) -> &(String, i32, String) {
        self.steps
            .iter()
            .find(|s| s.0 == id)
            .unwrap_or_else(|| panic!("step {id} did not run: {self:#?}"))
    }
    fn output(&self, id: &str, name: &str) -> Option<&str> {
        self.outputs.get(id)?.get(name).map(String::as_str)
    }
}

struct Runner {
    tmp: tempfile::TempDir,
    /// `with:` of the action, by input name; inputs not given take their default.
    with: BTreeMap<String, String>,
    /// Simulate actions/cache restoring the binary (cache-hit = true).
    cache_hit: bool,
    /// Leave `cargo` off PATH.
    no_cargo: bool,
}

impl Runner {
    fn new(with: &[(&str, &str)]) -> Runner {
        Runner {
            tmp: tempfile::tempdir().expect("temp dir"),
            with: with
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            cache_hit: false,
            no_cargo: false,
        }
    }
    fn workspace(&self) -> PathBuf {
        self.tmp.path().join("workspace")
    }
    fn home(&self) -> PathBuf {
        self.tmp.path().join("home")
    }

    fn run(&self) -> Run {
        let action = action();
        let declared = inputs(&action);
        for name in self.with.keys() {
            assert!(declared.contains_key(name), "with: {name} is not an input");
        }
        let input = |name: &str| -> String {
            self.with
                .get(name)
                .cloned()
                .unwrap_or_else(|| declared[name].clone())
        };
        let (workspace, home) = (self.workspace(), self.home());
        let stub = self.tmp.path().join("stub-bin");
        let scratch = self.tmp.path().join("runner");
        for d in [&workspace, &home, &stub, &scratch] {
            fs::create_dir_all(d).expect("mkdir");
        }
        let rtcdoc = PathBuf::from(env!("CARGO_BIN_EXE_rtcdoc"));
        let cargo_log = self.tmp.path().join("cargo-args");
        if !self.no_cargo {
            // `cargo install --path P --locked --force --root R`: link the built binary into R/bin.
            let script = format!(
                "#!/bin/sh\nprintf '%s\\n' \"$@\" > '{log}'\nroot=\"$HOME/.cargo\"\nprev=\nfor a in \"$@\"; do [ \"$prev\" = --root ] && root=\"$a\"; prev=\"$a\"; done\nmkdir -p \"$root/bin\" && ln -sf '{bin}' \"$root/bin/rtcdoc\"\n",
                log = cargo_log.display(),
                bin = rtcdoc.display()
            );
            let path = stub.join("cargo");
            fs::write(&path, script).expect("stub cargo");
            make_executable(&path);
        }
        if self.cache_hit {
            let bin = home.join(".cargo/bin");
            fs::create_dir_all(&bin).expect("mkdir");
            std::os::unix::fs::symlink(&rtcdoc, bin.join("rtcdoc")).expect("symlink");
        }
        // The system PATH without any rtcdoc or cargo of this machine.
        let system: Vec<PathBuf> =
            std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default())
                .filter(|d| !d.join("rtcdoc").exists() && !d.join("cargo").exists())
                .collect();
        let mut added_paths: Vec<PathBuf> = Vec::new();

        let mut run = Run {
            steps: Vec::new(),
            outputs: BTreeMap::new(),
            action_outputs: BTreeMap::new(),
            success: true,
            cargo_args: String::new(),
            summary: String::new(),
        };
        let summary = scratch.join("step-summary.md");
        for (i, step) in steps(&action).iter().enumerate() {
            let id = step_id(step)
                .map(str::to_string)
                .unwrap_or(format!("step{i}"));
            if let Some(uses) = step["uses"].as_str() {
                assert!(
                    uses.starts_with("actions/cache@"),
                    "unexpected uses: {uses}"
                );
                let hit = if self.cache_hit { "true" } else { "false" };
                run.outputs
                    .entry(id)
                    .or_default()
                    .insert("cache-hit".into(), hit.into());
                continue;
            }
            if let Some(cond) = step["if"].as_str() {
                if !evaluate_if(cond, &run.outputs) {
                    continue;
                }
            }
            let script_text = step["run"].as_str().expect("a run: or uses: step");
            let script = scratch.join(format!("step{i}.sh"));
            fs::write(&script, script_text).expect("write step");
            let output_file = scratch.join(format!("output{i}"));
            let path_file = scratch.join(format!("path{i}"));
            fs::write(&output_file, "").expect("output file");
            fs::write(&path_file, "").expect("path file");
            let mut path: Vec<PathBuf> = added_paths.iter().rev().cloned().collect();
            path.push(stub.clone());
            path.extend(system.iter().cloned());
            let mut cmd = Command::new("bash");
            cmd.args(["--noprofile", "--norc", "-eo", "pipefail"])
                .arg(&script)
                .current_dir(&workspace)
                .env_clear()
                .env("PATH", std::env::join_paths(path).expect("PATH"))
                .env("HOME", &home)
                .env("GITHUB_ACTIONS", "true")
                .env("GITHUB_ACTION_PATH", repo())
                .env("GITHUB_WORKSPACE", &workspace)
                .env("GITHUB_OUTPUT", &output_file)
                .env("GITHUB_PATH", &path_file)
                .env("GITHUB_STEP_SUMMARY", &summary)
                .env("RUNNER_TEMP", &scratch);
            if let Some(env) = step["env"].as_mapping() {
                for (k, v) in env {
                    let value = substitute(v.as_str().expect("env value"), &input);
                    cmd.env(k.as_str().expect("env name"), value);
                }
            }
            let out = cmd.output_within(common::COMMAND_LIMIT).expect("run bash");
            let text = format!(
                "{}{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            );
            let status = out.status.code().unwrap_or(-1);
            run.steps.push((id.clone(), status, text));
            let written = fs::read_to_string(&output_file).expect("read GITHUB_OUTPUT");
            let map = run.outputs.entry(id).or_default();
            for line in written.lines() {
                let (k, v) = line
                    .split_once('=')
                    .unwrap_or_else(|| panic!("GITHUB_OUTPUT line `{line}` is not name=value"));
                map.insert(k.to_string(), v.to_string());
            }
            for line in fs::read_to_string(&path_file).expect("GITHUB_PATH").lines() {
                added_paths.push(PathBuf::from(line));
            }
            if status != 0 {
                run.success = false;
                break;
            }
        }
        if let Some(m) = action["outputs"].as_mapping() {
            for (k, v) in m {
                let expr = expressions(v["value"].as_str().expect("output value"));
                let (id, name) = expr[0]
                    .strip_prefix("steps.")
                    .and_then(|r| r.split_once(".outputs."))
                    .expect("steps.ID.outputs.NAME");
                let value = run.output(id, name).unwrap_or("").to_string();
                run.action_outputs
                    .insert(k.as_str().expect("output name").to_string(), value);
            }
        }
        run.cargo_args = fs::read_to_string(&cargo_log).unwrap_or_default();
        run.summary = fs::read_to_string(&summary).unwrap_or_default();
        run
    }
}

fn make_executable(path: &Path) {
    use std::os::unix::fs::PermissionsExt;
    let mut perm = fs::metadata(path).expect("stat").permissions();
    perm.set_mode(0o755);
    fs::set_permissions(path, perm).expect("chmod");
}

/// `${{ inputs.X }}` replaced by the input's value, as the runner does before the shell starts.
fn substitute(value: &str, input: &dyn Fn(&str) -> String) -> String {
    let mut out = String::new();
    let mut rest = value;
    while let Some(start) = rest.find("${{") {
        out.push_str(&rest[..start]);
        let after = &rest[start + 3..];
        let end = after.find("}}").expect("unterminated expression");
        let expr = after[..end].trim();
        let name = expr
            .strip_prefix("inputs.")
            .unwrap_or_else(|| panic!("env expression `{expr}` is not inputs.X"));
        out.push_str(&input(name));
        rest = &after[end + 2..];
    }
    out.push_str(rest);
    out
}

/// The `if:` forms the action uses: `steps.ID.outputs.NAME != 'LIT'` (or `==`).
fn evaluate_if(cond: &str, outputs: &BTreeMap<String, BTreeMap<String, String>>) -> bool {
    let cond = cond.trim();
    let (lhs, op, rhs) = if let Some((l, r)) = cond.split_once("!=") {
        (l, "!=", r)
    } else if let Some((l, r)) = cond.split_once("==") {
        (l, "==", r)
    } else {
        panic!("if: `{cond}` is not a comparison tests/suite/action.rs understands");
    };
    let (id, name) = lhs
        .trim()
        .strip_prefix("steps.")
        .and_then(|r| r.split_once(".outputs."))
        .unwrap_or_else(|| panic!("if: `{cond}`"));
    let value = outputs
        .get(id)
        .and_then(|m| m.get(name))
        .map(String::as_str)
        .unwrap_or("");
    let lit = rhs.trim().trim_matches('\'');
    (value == lit) == (op == "==")
}

fn examples() -> String {
    repo().join("examples").display().to_string()
}

fn error_fixture() -> String {
    repo()
        .join("tests/fixtures/check/RTC101-bad.xml")
        .display()
        .to_string()
}

/// Errors and warnings of `rtcdoc check --format json`, counted from its diagnostics.
fn counts(input: &str) -> (usize, usize) {
    let out = Command::new(env!("CARGO_BIN_EXE_rtcdoc"))
        .args(["check", "--format", "json", input])
        .output_within(common::COMMAND_LIMIT)
        .expect("run rtcdoc");
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON report");
    let diags = json["diagnostics"].as_array().expect("diagnostics");
    let count = |sev: &str| diags.iter().filter(|d| d["severity"] == sev).count();
    (count("error"), count("warning"))
}

#[test]
fn cache_miss_installs_from_the_action_checkout_then_checks_and_builds() {
    let runner = Runner::new(&[("input", &examples())]);
    let run = runner.run();
    assert!(run.success, "{run:#?}");
    // Installed from the action's own checkout, locked, into the cached ~/.cargo/bin.
    let root = runner.home().join(".cargo");
    let expected = format!(
        "install\n--path\n{}\n--locked\n--force\n--root\n{}\n",
        repo().display(),
        root.display()
    );
    assert_eq!(run.cargo_args, expected);
    let key = run.output("prepare", "key").expect("cache key");
    let version = run.output("prepare", "version").expect("version");
    assert_eq!(version, env!("CARGO_PKG_VERSION"));
    let hash = key
        .strip_prefix(&format!("rtcdoc-{version}-"))
        .unwrap_or_else(|| panic!("key {key}"));
    assert!(
        hash.len() == 16 && hash.bytes().all(|b| b.is_ascii_hexdigit()),
        "{key}"
    );
    // The site went into the default output directory of the workspace.
    assert!(runner.workspace().join("site/index.html").is_file());
    assert_eq!(run.action_outputs["site"], "site");
    let (errors, warnings) = counts(&examples());
    assert_eq!(errors, 0, "the examples have no error");
    assert!(warnings > 0, "the examples are expected to carry warnings");
    assert_eq!(run.action_outputs["errors"], errors.to_string());
    assert_eq!(run.action_outputs["warnings"], warnings.to_string());
    assert!(
        run.summary
            .contains(&format!("0 error(s), {warnings} warning(s)")),
        "{}",
        run.summary
    );
}

#[test]
fn cache_hit_skips_the_install_and_uses_the_restored_binary() {
    let mut runner = Runner::new(&[("input", &examples()), ("output", "out/docs")]);
    runner.cache_hit = true;
    runner.no_cargo = true;
    let run = runner.run();
    assert!(run.success, "{run:#?}");
    assert!(
        run.steps.iter().all(|s| s.0 != "install"),
        "install ran: {run:#?}"
    );
    assert_eq!(run.cargo_args, "");
    assert!(runner.workspace().join("out/docs/index.html").is_file());
    assert_eq!(run.action_outputs["site"], "out/docs");
}

#[test]
fn install_without_cargo_fails_and_says_what_to_add() {
    let mut runner = Runner::new(&[("input", &examples())]);
    runner.no_cargo = true;
    let run = runner.run();
    assert!(!run.success);
    let (_, status, text) = run.steps.last().expect("a step ran");
    assert_eq!(*status, 2, "{text}");
    assert!(text.contains("::error::cargo is not on PATH"), "{text}");
    assert!(text.contains("dtolnay/rust-toolchain"), "{text}");
}

#[test]
fn fail_on_error_fails_the_check_step_on_a_profile_error() {
    let runner = Runner::new(&[("input", &error_fixture())]);
    let run = runner.run();
    assert!(!run.success);
    let (_, status, text) = run.step("check");
    assert_eq!(*status, 1, "{text}");
    assert!(
        text.contains("error[RTC101]"),
        "the findings are in the log: {text}"
    );
    assert!(text.contains("::error::rtcdoc check"), "{text}");
    assert_eq!(run.output("check", "errors"), Some("1"));
    assert!(
        run.steps.iter().all(|s| s.0 != "build"),
        "build ran after a failed check"
    );
    assert!(!runner.workspace().join("site").exists());
}

#[test]
fn fail_on_never_reports_errors_and_still_builds() {
    let runner = Runner::new(&[("input", &error_fixture()), ("fail-on", "never")]);
    let run = runner.run();
    assert!(run.success, "{run:#?}");
    let (_, _, text) = run.step("check");
    assert!(text.contains("error[RTC101]"), "{text}");
    assert!(text.contains("::warning::rtcdoc check"), "{text}");
    assert_eq!(run.action_outputs["errors"], "1");
    assert_eq!(run.action_outputs["warnings"], "0");
    assert!(runner.workspace().join("site/index.html").is_file());
}

#[test]
fn fail_on_warning_fails_on_warnings_only_profiles() {
    let runner = Runner::new(&[("input", &examples()), ("fail-on", "warning")]);
    let run = runner.run();
    assert!(!run.success);
    let (_, status, text) = run.step("check");
    assert_eq!(*status, 1, "{text}");
    assert!(text.contains("fail-on: warning"), "{text}");
    assert_eq!(run.output("check", "errors"), Some("0"));
}

#[test]
fn an_unknown_fail_on_value_is_a_usage_error() {
    let runner = Runner::new(&[("input", &examples()), ("fail-on", "warnings")]);
    let run = runner.run();
    assert!(!run.success);
    let (_, status, text) = run.step("check");
    assert_eq!(*status, 2, "{text}");
    assert!(
        text.contains("fail-on must be error, warning or never"),
        "{text}"
    );
}

#[test]
fn fail_on_never_still_fails_when_rtcdoc_cannot_run() {
    let runner = Runner::new(&[("input", "no/such/dir"), ("fail-on", "never")]);
    let run = runner.run();
    assert!(!run.success);
    let (_, status, text) = run.step("check");
    assert_eq!(*status, 2, "{text}");
    assert!(
        text.contains("::error::rtcdoc check could not run"),
        "{text}"
    );
}

#[test]
fn formats_base_url_and_args_reach_the_build() {
    let runner = Runner::new(&[
        ("input", &examples()),
        ("output", "public"),
        ("formats", "html, json"),
        ("base-url", "https://example.org/components/"),
        ("args", "--title ActionTitle123 --language ja"),
    ]);
    let run = runner.run();
    assert!(run.success, "{run:#?}");
    let site = runner.workspace().join("public");
    let index = fs::read_to_string(site.join("html/index.html")).expect("html/index.html");
    assert!(
        index.contains("ActionTitle123"),
        "--title reached the build"
    );
    assert!(
        index.contains("lang=\"ja\""),
        "--language reached the build"
    );
    let sitemap = fs::read_to_string(site.join("html/sitemap.xml")).expect("sitemap.xml");
    assert!(
        sitemap.contains("<loc>https://example.org/components/"),
        "{sitemap}"
    );
    assert!(site.join("json").is_dir(), "the json format was built too");
}

#[test]
fn inputs_are_data_not_shell_code() {
    // What a malicious pull request could put into a workflow's `with:`. With the inputs in
    // env:, the shell never parses them: a directory and an output with these names are used
    // as they are, and nothing runs.
    let evil = "x$(touch pwned)\"; touch pwned; echo \"`touch pwned`";
    let runner = Runner::new(&[("input", evil), ("output", &format!("{evil}-site"))]);
    let dir = runner.workspace().join(evil);
    fs::create_dir_all(&dir).expect("mkdir");
    fs::copy(
        repo().join("examples/Joystick/RTC.xml"),
        dir.join("RTC.xml"),
    )
    .expect("copy");
    let run = runner.run();
    assert!(
        !runner.workspace().join("pwned").exists(),
        "an input ran as code"
    );
    assert!(run.success, "{run:#?}");
    assert!(runner
        .workspace()
        .join(format!("{evil}-site/index.html"))
        .is_file());
    assert_eq!(run.action_outputs["site"], format!("{evil}-site"));
}
