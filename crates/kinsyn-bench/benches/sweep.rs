//! Speed of the catalogue-wide multioperation sweep: one design (a symmetric
//! 3-legged manipulator, every lock subset of its inputs sampled and classified) with one and
//! with two actuated joints per leg, and a slice of 21 consecutive designs (one chain, every
//! actuation choice). `kinsyn sweep --bench` gives the figure of the whole sweep.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::catalogue::Catalogue;
use kinsyn::sweep::{SweepSettings, designs};
use std::hint::black_box;

fn sweep(c: &mut Criterion) {
    let catalogue = Catalogue::committed().expect("the committed catalogue reads");
    let settings = SweepSettings::default();
    let all = designs(&catalogue, &settings);
    // The 3-UPS of paper 000 §5 (T4-034), sliders actuated (8 lock subsets), and with the
    // U's first revolute too (64 subsets).
    let ups = |actuated: &[usize]| {
        all.iter()
            .find(|d| d.chain == "T4-034" && d.actuated == actuated)
            .expect("T4-034 is a verified chain")
    };
    let one = ups(&[3]);
    let two = ups(&[1, 3]);
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("one design, 3-UPS, 3 inputs (8 lock subsets)", |b| {
        b.iter(|| black_box(one.evaluate(&settings)));
    });
    group.bench_function("one design, 3-UPS, 6 inputs (64 lock subsets)", |b| {
        b.iter(|| black_box(two.evaluate(&settings)));
    });
    let slice: Vec<_> = all.iter().filter(|d| d.chain == "T4-034").collect();
    group.bench_function(
        "21 designs of one chain (T4-034), every actuation choice",
        |b| {
            b.iter(|| {
                slice
                    .iter()
                    .map(|d| d.evaluate(&settings).kinds)
                    .sum::<usize>()
            });
        },
    );
    group.finish();
}

criterion_group!(benches, sweep);
criterion_main!(benches);
