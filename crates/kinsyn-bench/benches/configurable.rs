//! The forward position of paper 003's configurable 4-RRR at the published inputs (§5:
//! q = (141.956°, 203.366°, 337.773°, 305.499°)), `cargo bench -p kinsyn-bench --bench configurable`:
//! [`forward_position`] by method 2 (64 paths, 12 complex solutions, 2 real) and method 1
//! (1024 paths per run, 24 complex solutions, 4 real; runs with further seeds while paths fail
//! or a mirror solution is missing), one homotopy run of each system alone (all paths, with
//! certificates), and `phc -b` on each system when `PHCpack` is installed. Every measured
//! solve is checked to find every root.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::homotopy::{SolveSettings, solve};
use kinsyn::poly::phc;
use kinsyn_papers::configurable::{
    Configurable, ForwardMethod, centre_system, corner_system, forward_position,
};

fn bench(c: &mut Criterion) {
    let m = Configurable::paper003();
    let q = [141.956f64, 203.366, 337.773, 305.499].map(f64::to_radians);
    let phc_path = phc::find_phc();
    let mut group = c.benchmark_group("configurable-forward");
    group.sample_size(10);
    for (name, method, system, roots) in [
        (
            "method-2",
            ForwardMethod::Corner,
            corner_system(&m, &q).expect("finite"),
            12,
        ),
        (
            "method-1",
            ForwardMethod::Centre,
            centre_system(&m, &q).expect("finite"),
            24,
        ),
    ] {
        group.bench_function(format!("{name}/forward_position"), |b| {
            b.iter(|| {
                let f = forward_position(&m, q, method).expect("solves");
                assert_eq!((f.complex, f.assemblies.len()), (roots, 2), "{name}");
            });
        });
        group.bench_function(format!("{name}/one-run"), |b| {
            b.iter(|| {
                let r = solve(&system, &SolveSettings::default()).expect("square");
                assert!(r.nonsingular() + r.failed() >= roots, "{name}");
            });
        });
        if let Some(path) = &phc_path {
            group.bench_function(format!("{name}/phc-b"), |b| {
                b.iter(|| {
                    let out = phc::solve(&system, path).expect("phc runs");
                    let found = out
                        .output
                        .solutions
                        .iter()
                        .filter(|s| s.is_finite() && s.is_regular())
                        .count();
                    assert_eq!(found, roots, "{name}");
                });
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
