//! Speed of the numerical core: one 6-joint chain Jacobian, Jacobian + rank, one chain's full
//! verification (rank, idle joints, 64 lock subsets), and the whole catalogue's verification.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::catalogue::{Catalogue, VERIFICATION_SEED};
use kinsyn::published::PrintedTables;
use kinsyn::screw;
use kinsyn::synthesis::Options;
use kinsyn::verification::{self, Settings};
use nalgebra::{DMatrix, Matrix6xX};
use rand::SeedableRng;
use std::hint::black_box;

fn numerics(c: &mut Criterion) {
    let cat = Catalogue::synthesise(&Options::default(), &PrintedTables::default());
    let entry = cat.find("PPPS").expect("PPPS is in Table 1");
    let chain = entry.serial_chain(VERIFICATION_SEED).unwrap();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let q = verification::random_configuration(&chain, &mut rng);
    let mut j = Matrix6xX::zeros(6);
    c.bench_function("jacobian, 6 joints", |b| {
        b.iter(|| chain.jacobian_into(black_box(&q), &mut j));
    });
    c.bench_function("jacobian + rank (certified pivoted QR), 6 joints", |b| {
        b.iter(|| {
            chain.jacobian_into(black_box(&q), &mut j);
            screw::rank6(&j, screw::DEFAULT_RANK_TOLERANCE)
        });
    });
    c.bench_function(
        "jacobian + rank with singular values (SVD), 6 joints",
        |b| {
            b.iter(|| {
                chain.jacobian_into(black_box(&q), &mut j);
                screw::rank(
                    &DMatrix::from_column_slice(6, 6, j.as_slice()),
                    screw::DEFAULT_RANK_TOLERANCE,
                )
            });
        },
    );
    let settings = Settings::default();
    c.bench_function("verify one chain (64 lock subsets)", |b| {
        b.iter(|| verification::verify(black_box(&chain), &settings, 7));
    });
    let mut group = c.benchmark_group("catalogue");
    group.sample_size(10);
    group.bench_function("verify all entries", |b| {
        b.iter_batched(
            || cat.clone(),
            |mut cat| cat.verify(&settings, VERIFICATION_SEED),
            criterion::BatchSize::LargeInput,
        );
    });
    group.finish();
}

criterion_group!(benches, numerics);
criterion_main!(benches);
