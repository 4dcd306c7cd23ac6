//! Homotopy continuation side by side with `PHCpack` (`cargo bench -p kinsyn-bench --bench homotopy`): the
//! forward kinematics of a general Gough–Stewart platform (40 roots of 128 paths), Katsura-7
//! (128 roots), cyclic-5 (70 roots), cyclic-7 (924 roots of 924 polyhedral paths) and noon-5
//! (233 roots). kinsyn with its default start (`auto`: the polyhedral start for the cyclic and
//! noon systems, mixed cells included, a new lifting every iteration) on all cores and on one,
//! and `phc -b` (the blackbox solver of `PHCpack`, Debian package `phcpack`; skipped when
//! absent) on the same systems. Every measured solve is checked to find every root.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::geometry::{Chart, gough_stewart};
use kinsyn::homotopy::{SolveSettings, StartSystem, solve};
use kinsyn::poly::{System, families, phc};
use kinsyn::spatial::{self, Twist};
use nalgebra::{Point3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A general Gough–Stewart platform (random base and platform points, the leg lengths of a
/// random pose) in Study parameters.
fn gough_stewart_system(seed: u64) -> System {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut v = |s: f64| {
        Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        ) * s
    };
    let base: [Vector3<f64>; 6] = std::array::from_fn(|_| v(1.0));
    let platform: [Vector3<f64>; 6] = std::array::from_fn(|_| v(0.6));
    let pose = spatial::exp(&Twist {
        w: v(0.5),
        v: v(0.3) + Vector3::z(),
    });
    let lengths = std::array::from_fn(|i| {
        (pose.transform_point(&Point3::from(platform[i])).coords - base[i]).norm()
    });
    gough_stewart(&base, &platform, &lengths, &Chart::random_linear(5))
}

fn bench(c: &mut Criterion) {
    let phc_path = phc::find_phc();
    let single = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a thread");
    let mut group = c.benchmark_group("homotopy");
    group.sample_size(10);
    // Each iteration a new seed: a new lifting, so that the mixed cells are found every time
    // (the last subdivision is kept for the same seed).
    let seed = std::sync::atomic::AtomicU64::new(1);
    let settings = || {
        let next = seed.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        SolveSettings {
            seed: next,
            start: StartSystem::Auto,
            ..SolveSettings::default()
        }
    };
    for (name, system, roots) in [
        ("gough-stewart", gough_stewart_system(11), 40),
        ("katsura-7", families::katsura(7), 128),
        ("cyclic-5", families::cyclic(5), 70),
        ("cyclic-7", families::cyclic(7), 924),
        ("noon-5", families::noon(5), 233),
    ] {
        let check = |found: usize| assert_eq!(found, roots, "{name}: every root");
        group.bench_function(format!("{name}/kinsyn"), |b| {
            b.iter(|| {
                check(solve(&system, &settings()).expect("square").nonsingular());
            });
        });
        group.bench_function(format!("{name}/kinsyn-1-thread"), |b| {
            b.iter(|| {
                single.install(|| {
                    check(solve(&system, &settings()).expect("square").nonsingular());
                });
            });
        });
        if let Some(path) = &phc_path {
            group.bench_function(format!("{name}/phc-b"), |b| {
                b.iter(|| {
                    let out = phc::solve(&system, path).expect("phc runs");
                    check(
                        out.output
                            .solutions
                            .iter()
                            .filter(|s| s.is_finite() && s.is_regular())
                            .count(),
                    );
                });
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
