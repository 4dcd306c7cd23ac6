//! Speed of the series-parallel analysis of paper 002 (src/series.rs): one evaluation of the
//! kinematic Jacobian `J_S-PM` of eq. (7) for the 3-RPS-3-SPR (two 6×6 solves, the screw
//! transformations), and its twist system (eqs. 9–10: two reciprocal complements and a rank).
//!
//! The configuration is Table 1 row 4's kind, in closed form: the coupler turned by 0.3 rad and
//! the end-effector by −0.5 rad about y; for a turn θ about y, the revolute constraints of §2
//! put the centre of the platform carrying the S centres (the coupler, circum-radius h1 = 1), seen
//! from the platform carrying the revolutes, at `x = (h1/2)(cos θ − 1)`, `y = 0`.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::screw::DEFAULT_RANK_TOLERANCE;
use kinsyn::spatial::displacement;
use kinsyn_papers::series::{Leg, Module, SeriesParallel};
use nalgebra::{Rotation3, Vector3};
use std::hint::black_box;
use std::time::Duration;

fn vertex(h: f64, i: usize) -> Vector3<f64> {
    let (s, c) = (120.0 * i as f64).to_radians().sin_cos();
    h * Vector3::new(c, s, 0.0)
}

fn tangent(i: usize) -> Vector3<f64> {
    let (s, c) = (120.0 * i as f64).to_radians().sin_cos();
    Vector3::new(-s, c, 0.0)
}

fn spm() -> SeriesParallel {
    let (h0, h1, h2) = (2.0, 1.0, 2.0);
    // 3-RPS: coupler turned by θ1 about y at height 1.8.
    let t1 = 0.3_f64;
    let r1 = Rotation3::from_axis_angle(&Vector3::y_axis(), t1);
    let g1 = displacement(r1, Vector3::new(h1 / 2.0 * (t1.cos() - 1.0), 0.0, 1.8));
    let prox = Module {
        pose: g1,
        legs: std::array::from_fn(|i| {
            let centre = g1.rotation * vertex(h1, i) + g1.translation.vector;
            Leg {
                centre,
                actuation: (centre - vertex(h0, i)).normalize(),
                constraint: tangent(i),
            }
        }),
    };
    // 3-SPR: the coupler seen from the end-effector is a 3-RPS pose of the same kind.
    let t2 = -0.5_f64;
    let r2 = Rotation3::from_axis_angle(&Vector3::y_axis(), t2);
    let s = Vector3::new(h1 / 2.0 * (t2.cos() - 1.0), 0.0, -1.4);
    let g2 = displacement(r2.inverse(), -(r2.inverse() * s));
    let dist = Module {
        pose: g2,
        legs: std::array::from_fn(|i| {
            let far = g2.rotation * vertex(h2, i) + g2.translation.vector;
            let axis = g2.rotation * tangent(i);
            assert!(axis.dot(&(vertex(h1, i) - far)).abs() < 1e-12, "assembled");
            Leg {
                centre: vertex(h1, i),
                actuation: (far - vertex(h1, i)).normalize(),
                constraint: axis,
            }
        }),
    };
    for (i, leg) in prox.legs.iter().enumerate() {
        assert!(leg.constraint.dot(&(leg.centre - vertex(h0, i))).abs() < 1e-12);
    }
    SeriesParallel::new(vec![prox, dist]).expect("two modules")
}

fn series(c: &mut Criterion) {
    let s = spm();
    let mut group = c.benchmark_group("series");
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(3));
    group.bench_function("J_S-PM of the 3-RPS-3-SPR (paper 002 eq. 7)", |b| {
        b.iter(|| black_box(&s).jacobian());
    });
    group.bench_function("twist system of the 3-RPS-3-SPR (eqs. 9-10)", |b| {
        b.iter(|| black_box(&s).twist_system(DEFAULT_RANK_TOLERANCE));
    });
    // The general machinery on the description file: the loop-closure mobility (30 joints, 24
    // closure equations) and the same S-PM read off the mechanism.
    let path = format!(
        "{}/../../mechanisms/multibody/3-rps-3-spr.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let m = kinsyn::manipulator::Manipulator::from_json(&std::fs::read_to_string(path).unwrap())
        .unwrap();
    let q = m.reference();
    let free = vec![false; m.mechanism().joints().len()];
    group.bench_function("loop-closure mobility of the 3-RPS-3-SPR file", |b| {
        b.iter(|| m.mechanism().mobility(black_box(&q), &free));
    });
    group.bench_function("series::stack + J_S-PM from the 3-RPS-3-SPR file", |b| {
        b.iter(|| kinsyn_papers::series::stack(&m, black_box(&q)).map(|s| s.jacobian()));
    });
    group.finish();
}

criterion_group!(benches, series);
criterion_main!(benches);
