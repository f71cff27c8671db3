//! Micro-benchmark of the readers: MB/s of XML and YAML profiles parsed into the model.
//!
//! `cargo bench --bench reader`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rtcdoc::parse::{self, Limits, SourceFormat};
use std::hint::black_box;

/// The allocator the `rtcdoc` binary uses, so the numbers match real runs.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn example(rel: &str) -> Vec<u8> {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(rel);
    std::fs::read(p).expect("example profile")
}

fn readers(c: &mut Criterion) {
    let limits = Limits::default();
    let mut g = c.benchmark_group("reader");
    for (name, rel, fmt) in [
        ("xml", "PathPlanner/RTC.xml", SourceFormat::Xml),
        ("yaml", "UsbCamera/RTC.yaml", SourceFormat::Yaml),
    ] {
        let bytes = example(rel);
        g.throughput(Throughput::Bytes(bytes.len() as u64));
        g.bench_function(name, |b| {
            b.iter(|| parse::parse(fmt, black_box(&bytes), "bench", &limits).expect("parses"))
        });
    }
    g.finish();
}

criterion_group!(benches, readers);
criterion_main!(benches);
