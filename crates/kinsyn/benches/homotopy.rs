//! Homotopy continuation on the standard test systems (`cargo bench --bench homotopy`):
//! Katsura-7 (128 roots) and cyclic-5 (70 roots), all paths in parallel.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::homotopy::{SolveSettings, solve};
use kinsyn::poly::families::{cyclic, katsura};

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("homotopy");
    group.sample_size(10);
    for (name, system, roots) in [("katsura-7", katsura(7), 128), ("cyclic-5", cyclic(5), 70)] {
        let report = solve(&system, &SolveSettings::default()).expect("square");
        assert_eq!(report.nonsingular(), roots, "{name}: {}", report.summary());
        group.bench_function(name, |b| {
            b.iter(|| solve(&system, &SolveSettings::default()));
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
