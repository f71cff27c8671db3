//! Tests of the YAML reader (`src/parse/yaml.rs`): spec chapter 7 schema, 8.2 constraint samples,
//! the RTCBuilder dialect, positions, hostile input and the real corpus.

use rtcdoc::diagnostic::{codes, Diagnostic, Severity};
use rtcdoc::model::*;
use rtcdoc::parse::{yaml, Limits, Parsed};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn parse_str(s: &str) -> Parsed {
    match yaml::parse(s.as_bytes(), "t.yaml", &Limits::default()) {
        Ok(p) => p,
        Err(e) => panic!("unexpected error: {e}"),
    }
}

fn parse_err(b: &[u8]) -> Diagnostic {
    match yaml::parse(b, "bad.yaml", &Limits::default()) {
        Ok(p) => panic!("expected an error, got {:?}", p.profile),
        Err(e) => e,
    }
}

fn corpus_dir() -> Option<PathBuf> {
    let a = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    if a.is_dir() {
        return Some(a);
    }
    let b = PathBuf::from("/work/shared/corpus");
    b.is_dir().then_some(b)
}

#[test]
fn corpus_parses_without_errors() {
    let Some(dir) = corpus_dir() else {
        println!("skipped: ../shared/corpus not present");
        return;
    };
    let mut files = 0;
    let mut errors = Vec::new();
    let mut warnings: std::collections::BTreeMap<String, usize> = Default::default();
    for e in walkdir::WalkDir::new(dir.join("rtc-yaml")).sort_by_file_name() {
        let Ok(e) = e else { continue };
        if !e.file_type().is_file() {
            continue;
        }
        files += 1;
        let bytes = std::fs::read(e.path()).unwrap();
        let name = e.path().display().to_string();
        assert!(yaml::is_profile(&bytes), "{name} not sniffed as a profile");
        match yaml::parse(&bytes, &name, &Limits::default()) {
            Ok(p) => {
                for d in p.diagnostics {
                    assert_eq!(d.severity, Severity::Warning);
                    *warnings
                        .entry(format!("[{}] {}", d.code, d.message))
                        .or_default() += 1;
                }
            }
            Err(d) => errors.push(d.to_string()),
        }
    }
    println!("corpus: {files} files, {} errors", errors.len());
    for (w, n) in &warnings {
        println!("  {n:4} × {w}");
    }
    assert!(files > 0);
    assert!(errors.is_empty(), "{errors:#?}");
}
