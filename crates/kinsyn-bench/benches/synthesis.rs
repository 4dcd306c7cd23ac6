//! Speed of the structural synthesis: the full enumeration of paper 000 §2 (all six Appendix
//! tables, every axis assignment and reading) and the catalogue built from it (deduplication
//! and the row-by-row comparison with the printed Appendix).

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::catalogue::Catalogue;
use kinsyn::synthesis::{Options, enumerate};
use std::hint::black_box;

fn synthesis(c: &mut Criterion) {
    let options = Options::default();
    c.bench_function("enumerate all tables", |b| {
        b.iter(|| enumerate(black_box(&options)));
    });
    c.bench_function("catalogue synthesise (enumerate + dedupe + compare)", |b| {
        b.iter(|| Catalogue::synthesise(black_box(&options)));
    });
    let mut group = c.benchmark_group("catalogue");
    group.sample_size(10);
    group.bench_function("generate (synthesise + verify every entry)", |b| {
        b.iter(|| Catalogue::generate(black_box(&options)));
    });
    group.finish();
    let cat = Catalogue::generate(&options);
    c.bench_function("catalogue files to text", |b| {
        b.iter(|| (cat.to_json(), cat.to_csv(), cat.readme()));
    });
}

criterion_group!(benches, synthesis);
criterion_main!(benches);
