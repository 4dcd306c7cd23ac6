//! Speed of the structural synthesis: the full enumeration of paper 000 §2 (all six Appendix
//! tables, every axis assignment and reading) and the catalogue built from it (deduplication,
//! entries marked against paper 000's printed Appendix and the row-by-row comparison with it:
//! `kinsyn_papers::appendix`).

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::synthesis::{Options, enumerate};
use kinsyn_papers::appendix;
use std::hint::black_box;

fn synthesis(c: &mut Criterion) {
    let options = Options::default();
    c.bench_function("enumerate all tables", |b| {
        b.iter(|| enumerate(black_box(&options)));
    });
    c.bench_function("catalogue synthesise (enumerate + dedupe + compare)", |b| {
        b.iter(|| appendix::synthesise(black_box(&options)));
    });
    let mut group = c.benchmark_group("catalogue");
    group.sample_size(10);
    group.bench_function("generate (synthesise + verify every entry)", |b| {
        b.iter(|| appendix::generate(black_box(&options)));
    });
    group.finish();
    let (cat, comparison) = appendix::generate(&options);
    c.bench_function("catalogue files to text", |b| {
        b.iter(|| (cat.to_json(), cat.to_csv(), cat.readme(&comparison)));
    });
}

criterion_group!(benches, synthesis);
criterion_main!(benches);
