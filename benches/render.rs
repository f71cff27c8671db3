//! Micro-benchmarks of rendering: component pages per second (HTML), and the incremental
//! rebuild `rtcdoc serve` does when one profile of a 1,000-profile catalogue changes.
//!
//! `cargo bench --bench render`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rtcdoc::build::{BuildOptions, LoadOptions};
use rtcdoc::output::MemorySink;
use rtcdoc::render::html::HtmlRenderer;
use rtcdoc::render::{Format, RenderContext, SiteOptions};
use std::path::{Path, PathBuf};

/// Writes `n` profiles cloned from the examples (renamed, types spread over groups of ~40, like
/// `bench/gen_catalogue.py`) below `dir`.
/// The allocator the `rtcdoc` binary uses, so the numbers match real runs.
#[global_allocator]
static GLOBAL: rtcdoc::allocator::Mi = rtcdoc::allocator::Mi;

fn synthetic(dir: &Path, n: usize) {
    let ex = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut templates: Vec<(String, String, String)> = Vec::new();
    let mut names: Vec<_> = std::fs::read_dir(&ex)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    names.sort();
    for d in names.into_iter().filter(|p| p.is_dir()) {
        for f in ["RTC.xml", "RTC.yaml"] {
            if let Ok(t) = std::fs::read_to_string(d.join(f)) {
                let name = d.file_name().unwrap().to_string_lossy().into_owned();
                templates.push((name, f.to_string(), t));
            }
        }
    }
    let groups = (n / 40).max(1);
    for i in 0..n {
        let (name, file, text) = &templates[i % templates.len()];
        let g = (i / templates.len()) % groups;
        let new_name = format!("{name}{i:05}");
        let t = text
            .replace(name.as_str(), &new_name)
            .replace("RTC::", &format!("Bench{g:03}::"));
        let d = dir.join(format!("{:02}", i / 1000)).join(&new_name);
        std::fs::create_dir_all(&d).unwrap();
        std::fs::write(d.join(file), t).unwrap();
    }
}

fn options(input: &Path) -> BuildOptions {
    BuildOptions {
        input: input.to_path_buf(),
        output: input.join("site"),
        formats: vec![Format::Html],
        strict: false,
        load: LoadOptions::default(),
        site: SiteOptions::default(),
    }
}

fn pages(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    synthetic(dir.path(), 200);
    let loaded = rtcdoc::build::load(dir.path(), &LoadOptions::default()).unwrap();
    let site = SiteOptions::default();
    let ctx = RenderContext {
        catalog: &loaded.catalog,
        site: &site,
    };
    let n = loaded.catalog.components.len() as u64;
    let mut g = c.benchmark_group("html");
    g.sample_size(10);
    g.throughput(Throughput::Elements(n));
    g.bench_function("component_pages_200", |b| {
        b.iter(|| {
            let sink = MemorySink::new();
            HtmlRenderer
                .render_some(&ctx, &sink, &|p: &str| p.starts_with("components/"))
                .unwrap()
        })
    });
    g.finish();
}

fn incremental(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    synthetic(dir.path(), 1000);
    let mut ws = rtcdoc::incremental::Workspace::open(&options(dir.path())).unwrap();
    let target: PathBuf = dir.path().join("00/PathPlanner00007/RTC.xml");
    let original = std::fs::read_to_string(&target).unwrap();
    let mut flip = false;
    let mut g = c.benchmark_group("serve");
    g.sample_size(20);
    g.bench_function("one_profile_of_1000", |b| {
        b.iter(|| {
            flip = !flip;
            let text = if flip {
                original.replace("Grid path planner", "Grid path planner, edited")
            } else {
                original.clone()
            };
            std::fs::write(&target, text).unwrap();
            let r = ws.update(std::slice::from_ref(&target)).unwrap();
            assert!(!r.full);
        })
    });
    g.finish();
}

criterion_group!(benches, pages, incremental);
criterion_main!(benches);
