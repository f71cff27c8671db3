//! Micro-benchmark of the readers: MB/s of XML and YAML profiles parsed into the model, and of
//! a generated ~1 MB IDL file read by the IDL reader.
//!
//! `cargo bench --bench reader`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rtcdoc::parse::{self, Limits, SourceFormat};
use std::hint::black_box;

/// The allocator the `rtcdoc` binary uses, so the numbers match real runs.
#[global_allocator]
static GLOBAL: rtcdoc::allocator::Mi = rtcdoc::allocator::Mi;

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

/// About 1 MB of IDL in the shapes OpenRTM files have: documented structs with sequences,
/// arrays and bounded strings, enums, typedefs and documented service interfaces.
fn generated_idl() -> Vec<u8> {
    let mut s = String::from(
        "#ifndef GEN_IDL\n#define GEN_IDL\n#pragma prefix \"example.org\"\nmodule Gen {\n  struct Time { unsigned long sec; unsigned long nsec; };\n  exception Failure { string reason; };\n  interface Base { void ping(); };\n",
    );
    let mut i = 0;
    while s.len() < 1_000_000 {
        s.push_str(&format!(
            "  /*!\n   * @struct TimedThing{i}\n   * @brief Thing number {i}.\n   */\n  struct TimedThing{i} {{\n    Time tm;            ///< Time stamp.\n    /// The values.\n    double data[3];\n    sequence<long, 8> seq;\n    string<32> label;\n  }};\n  enum Mode{i} {{ MODE{i}_A, MODE{i}_B }};\n  typedef sequence<TimedThing{i}> TimedThing{i}Seq;\n  /// Service {i}.\n  interface Service{i} : Base {{\n    /**\n     * @brief Operation {i}.\n     * @param[in] x The input.\n     * @return A code.\n     */\n    long op{i}(in long x, out double y, inout TimedThing{i}Seq z) raises (Failure);\n    readonly attribute long count{i};\n  }};\n"
        ));
        i += 1;
    }
    s.push_str("};\n#endif\n");
    s.into_bytes()
}

fn idl_reader(c: &mut Criterion) {
    let files = [rtcdoc::idl::SourceFile::new("gen.idl", generated_idl())];
    let opts = rtcdoc::idl::IdlOptions::default();
    let set = rtcdoc::idl::read(&files, &opts);
    assert!(set.diagnostics.is_empty(), "{:?}", set.diagnostics.first());
    let mut g = c.benchmark_group("reader");
    g.throughput(Throughput::Bytes(files[0].bytes.len() as u64));
    g.sample_size(20);
    g.bench_function("idl", |b| {
        b.iter(|| rtcdoc::idl::read(black_box(&files), &opts))
    });
    g.finish();
}

criterion_group!(benches, readers, idl_reader);
criterion_main!(benches);
