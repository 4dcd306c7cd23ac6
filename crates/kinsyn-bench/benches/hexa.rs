//! Paper 001's HEXA (`cargo bench -p kinsyn-bench --bench hexa`): one inverse geometry, one Jacobians-and-indices
//! evaluation, the full workspace search and the index map at the CLI's default grids
//! (workspace 10 mm, map 5 mm over the regular workspace at its middle height).

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn_papers::hexa::{Hexa, IndexMapSettings, Pose, WorkspaceSettings};
use nalgebra::Vector3;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let h = Hexa::paper001();
    let p1 = Vector3::new(30.0, -40.0, -450.0);
    let p2 = h.nominal_four_bar(&p1, 0.2).expect("assembles").p2;
    let pose = Pose::new(&p1, 0.2, &p2, -0.1);
    let conf = h.inverse(&pose).expect("reachable");
    let mut group = c.benchmark_group("hexa");
    group.bench_function("inverse", |b| b.iter(|| h.inverse(black_box(&pose))));
    group.bench_function("jacobians+indices", |b| {
        b.iter(|| (h.jacobians(black_box(&conf)), h.indices(black_box(&conf))));
    });
    group.sample_size(10);
    let settings = WorkspaceSettings {
        step: 10.0,
        ..WorkspaceSettings::default()
    };
    let quiet = |_: usize, _: usize| {};
    group.bench_function("workspace-10mm", |b| {
        b.iter(|| h.workspace(&settings, &quiet).expect("valid"));
    });
    let cylinder = h
        .workspace(&settings, &quiet)
        .expect("valid")
        .regular_cylinder()
        .expect("a regular workspace");
    let map = IndexMapSettings {
        z: cylinder.middle(),
        half_width: cylinder.radius,
        step: 5.0,
        phi1: 0.0,
        phi2: 0.0,
    };
    group.bench_function("index-map-5mm", |b| {
        b.iter(|| h.index_map(&map, &quiet).expect("valid"));
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
