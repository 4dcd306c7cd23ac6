//! Speed of one velocity evaluation of paper 003's configurable 4-RRR by screw theory (§4,
//! eqs. 16–29, `src/configurable/velocity.rs`): the loop coefficients, the input–output
//! equation of `m1`, the twist of `m3` and the four corner velocities, at Table 2's printed
//! configuration with the rates of §5's trajectory at `t = 0`,
//! `q̇ = (−1.5, −1.25, −2, 1.5)` rad/s.

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn_papers::configurable::velocity::{Configuration, velocities};
use nalgebra::{Vector2, Vector4};
use std::hint::black_box;
use std::time::Duration;

fn table2() -> Configuration {
    let p = |x: f64, y: f64| Vector2::new(x, y);
    Configuration {
        base: [p(200.0, 0.0), p(0.0, 200.0), p(-200.0, 0.0), p(0.0, -200.0)],
        elbows: [
            p(136.996, 49.301),
            p(-73.439, 168.271),
            p(-125.944, -30.262),
            p(46.455, -265.130),
        ],
        corners: [
            p(45.949, -28.866),
            p(14.889, 87.042),
            p(-5.947, -31.133),
            p(25.112, -147.043),
        ],
    }
}

fn configurable_velocity(c: &mut Criterion) {
    let cfg = table2();
    let qdot = Vector4::new(-1.5, -1.25, -2.0, 1.5);
    let mut group = c.benchmark_group("configurable_velocity");
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(3));
    group.bench_function(
        "twists of m1, m3 and corner velocities (paper 003 §4)",
        |b| {
            b.iter(|| velocities(black_box(&cfg), black_box(&qdot)));
        },
    );
    group.finish();
}

criterion_group!(benches, configurable_velocity);
criterion_main!(benches);
