//! Speed of the manipulator analysis: the multioperation capacity of the 3-UPS (finite motion of
//! the platform for all 64 lock subsets of its six inputs, paper 000 §5), one evaluation of the
//! Jacobians `J_D`, `J_I` from reciprocal screws (eqs. 11, 18–21) on the 3-UPS, the 6-UPS and the
//! 3-PRRR (legs whose constraints are couples), a whole `analyse` of the 3-UPS, and position
//! analysis: the 6-UPS assembled at a displaced platform pose, its forward kinematics from the
//! leg lengths of that pose (`analyze --inputs`), and the 3-RPS at a partial pose with its
//! parasitic motion solved (`analyze --pose z=…,rx=…,ry=…`).

use criterion::{Criterion, criterion_group, criterion_main};
use kinsyn::manipulator::{Manipulator, PositionRequest};
use kinsyn::mechanism::SampleSettings;
use nalgebra::Vector3;
use std::hint::black_box;
use std::time::Duration;

fn load(name: &str) -> Manipulator {
    let path = format!(
        "{}/../../mechanisms/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Manipulator::from_json(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn manipulator(c: &mut Criterion) {
    let ups3 = load("3-ups");
    let ups6 = load("6-ups");
    let settings = SampleSettings::default();
    assert_eq!(ups3.modes(&settings).unwrap().modes.len(), 64);

    let mut group = c.benchmark_group("manipulator");
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(3));

    let q3 = ups3.reference();
    group.bench_function("jacobians J_D, J_I, 3-UPS at the reference", |b| {
        b.iter(|| ups3.jacobians(black_box(&q3), &[]));
    });
    let prrr = load("3-prrr");
    let qp = prrr.reference();
    group.bench_function(
        "jacobians J_D, J_I, 3-PRRR at the reference (couple constraints)",
        |b| b.iter(|| prrr.jacobians(black_box(&qp), &[])),
    );
    group.bench_function(
        "analyse 3-UPS at the reference (ranks, generic assemblies)",
        |b| b.iter(|| ups3.analyse(black_box(&q3), &[], &settings)),
    );
    let q6 = ups6.reference();
    group.bench_function("jacobians J_D, J_I, 6-UPS at the reference", |b| {
        b.iter(|| ups6.jacobians(black_box(&q6), &[]));
    });

    // The platform frame moved by (0.1, 0.05, 0.1) m from its reference (0, 0, 1) and turned by
    // the rotation vector (5°, −3°, 10°).
    let position = Vector3::new(0.1, 0.05, 1.1);
    let orientation = Vector3::new(5.0_f64, -3.0, 10.0).map(f64::to_radians);
    ups6.assemble_at(position, orientation, &[])
        .expect("the displaced 6-UPS pose assembles");
    group.sample_size(20);
    group.bench_function("assemble 6-UPS at a displaced pose (damped Newton)", |b| {
        b.iter(|| ups6.assemble_at(black_box(position), black_box(orientation), &[]));
    });
    // Forward kinematics: the input values of that pose, from the reference.
    let displaced = ups6.assemble_at(position, orientation, &[]).unwrap();
    let inputs = PositionRequest {
        inputs: ups6
            .actuators()
            .iter()
            .enumerate()
            .map(|(a, act)| (a, displaced[act.joint]))
            .collect(),
        ..PositionRequest::default()
    };
    group.bench_function(
        "forward kinematics 6-UPS from the leg lengths of that pose",
        |b| b.iter(|| ups6.solve_position(black_box(&q6), black_box(&inputs))),
    );
    let rps = load("3-rps");
    let partial = PositionRequest {
        platform: Some(rps.parse_pose("z=1.1,rx=5,ry=-3").unwrap()),
        ..PositionRequest::default()
    };
    let qr = rps.reference();
    group.bench_function("3-RPS at z, rx, ry (parasitic x, y, rz solved)", |b| {
        b.iter(|| rps.solve_position(black_box(&qr), black_box(&partial)));
    });

    group.sample_size(10);
    group.bench_function("modes 3-UPS (64 lock subsets, finite motion)", |b| {
        b.iter(|| ups3.modes(black_box(&settings)));
    });
    group.finish();
}

criterion_group!(benches, manipulator);
criterion_main!(benches);
