//! Paper 003 §5: the trajectory `q1 = 2.477 − 1.5 sin t cos t`, … followed from the Table 2
//! assembly. Checked against independent methods: the whole forward position solved by
//! homotopy at instants on either side of where the followed assembly ends, and finite
//! differences of the assembly for the corner velocities.

use kinsyn::homotopy::{SolveSettings, solve};
use kinsyn::poly::C64;
use kinsyn_papers::configurable::trajectory::{
    TrajectoryEnd, assemble, elbow_family, follow, paper_input_rates, paper_inputs,
    paper_recurring_intervals,
};
use kinsyn_papers::configurable::velocity::{Configuration, velocities};
use kinsyn_papers::configurable::{Configurable, CornerPose};
use nalgebra::{Vector2, Vector4};

fn table1() -> CornerPose {
    // Table 1's converged solution (eq. 13's parametrisation), printed to 3 decimals.
    CornerPose {
        c4: Vector2::new(25.112, -147.043),
        theta: 79.999f64.to_radians(),
        phi: 105.0f64.to_radians(),
    }
}

/// The real assemblies at time `t`, by the homotopy solver on method 2's equations (all of
/// them, certified): an independent count.
fn real_assemblies(m: &Configurable, t: f64) -> Vec<Vec<f64>> {
    let q = paper_inputs(t);
    let p: Vec<C64> = (0..4)
        .flat_map(|i| {
            let b = m.elbow(i, q[i]);
            [C64::from(b.x), C64::from(b.y)]
        })
        .collect();
    let report = solve(&elbow_family(m).at(&p).unwrap(), &SolveSettings::default()).unwrap();
    assert_eq!(report.nonsingular(), 12, "t = {t}: {}", report.summary());
    report
        .solutions
        .iter()
        .filter(|s| s.regular && s.real)
        .map(|s| s.x.iter().map(|c| c.re).collect())
        .collect()
}

#[test]
fn the_table_2_assembly_meets_the_other_one_at_t_0_1786_and_the_inputs_leave_the_workspace() {
    let m = Configurable::paper003();
    // q(0) = (2.477, 3.549, 5.895, 5.331) rad is the published q rounded to 3 decimals in
    // radians: the assembly there is Table 1's to 0.13 mm and 0.07°.
    let start = assemble(&m, &paper_inputs(0.0), &table1()).expect("Table 1's assembly at q(0)");
    assert!((start.c4 - table1().c4).norm() < 0.15);
    assert!(
        (start.theta - table1().theta).abs().to_degrees() < 0.1
            && (start.phi - table1().phi).abs().to_degrees() < 0.1
    );
    let times: Vec<f64> = (0..=400)
        .map(|k| std::f64::consts::TAU * f64::from(k) / 400.0)
        .collect();
    let report = follow(&m, &start, paper_inputs, paper_input_rates, &times);
    let TrajectoryEnd::Ceased { last, next, .. } = report.end else {
        panic!(
            "the paper's trajectory cannot be completed (docs/deviations.md): {:?}",
            report.end
        )
    };
    assert!(
        next - last < 1e-8 && (0.178..0.179).contains(&last),
        "[{last}, {next}]"
    );
    // Independent: just before, two real assemblies close to each other (meeting); just after,
    // none at all (the solve finds all 12 complex assemblies, none real).
    let before = real_assemblies(&m, last - 1e-4);
    assert_eq!(before.len(), 2);
    let gap = (0..6)
        .map(|k| (before[0][k] - before[1][k]).abs())
        .fold(0.0, f64::max);
    assert!(gap < 2.0, "two assemblies about to meet: {gap}");
    assert!(
        real_assemblies(&m, next + 1e-4).is_empty(),
        "no real assembly past the turning point"
    );
    // Over the period the inputs depend on t only through sin t cos t = ½ sin 2t, so they repeat
    // the values of [0, t*] exactly on [0, t*] ∪ [π/2 − t*, π + t*] ∪ [3π/2 − t*, 2π]. At each of
    // the four ends, 2 real assemblies just inside and none just outside.
    let intervals = paper_recurring_intervals(last).expect("t* in (0, π/4]");
    let (a, b, c) = (intervals[1].0, intervals[1].1, intervals[2].0);
    assert!((a - (std::f64::consts::FRAC_PI_2 - last)).abs() < 1e-15);
    for (end, inside) in [(a, 1.0), (b, -1.0), (c, 1.0)] {
        assert_eq!(
            real_assemblies(&m, end + inside * 1e-4).len(),
            2,
            "t = {end} inside"
        );
        assert!(
            real_assemblies(&m, end - inside * 1e-4).is_empty(),
            "t = {end} outside"
        );
    }
    // Inside, the values with sin 2t < 0 are not values of [0, t*]: every one of them (down to
    // sin 2t = −1 at t = 3π/4) has real assemblies too, counted on a grid of each interval ...
    for &(lo, hi) in &intervals {
        for k in 1..8 {
            let t = lo + (hi - lo) * f64::from(k) / 8.0;
            assert_eq!(real_assemblies(&m, t).len(), 2, "t = {t} in [{lo}, {hi}]");
        }
    }
    // Between them (sin 2t above sin 2t*, up to 1 at t = π/4 and 5π/4) there is none.
    for (lo, hi) in [(last, a), (b, c)] {
        for k in 1..8 {
            let t = lo + (hi - lo) * f64::from(k) / 8.0;
            assert!(real_assemblies(&m, t).is_empty(), "t = {t} in ({lo}, {hi})");
        }
    }
    // ... and independently, the Table 2 branch followed back in time from 2π (≡ 0) is real all
    // the way down to 3π/2 − t*, where it meets the other assembly (sin 2t = sin 2t* again).
    let back: Vec<f64> = (0..=300)
        .map(|k| std::f64::consts::TAU - std::f64::consts::PI * f64::from(k) / 400.0)
        .collect();
    let report = follow(&m, &start, paper_inputs, paper_input_rates, &back);
    let TrajectoryEnd::Ceased { last: first, .. } = report.end else {
        panic!("followed back past 5π/4: {:?}", report.end)
    };
    assert!(
        (first - c).abs() < 1e-7,
        "followed back to {first}, 3π/2 − t* = {c}"
    );
}

#[test]
fn corner_velocities_equal_finite_differences_of_the_assembly() {
    // The followed samples' Ċ_i (implicit differentiation of the position equations) against
    // central differences of assemblies at t ± h.
    let m = Configurable::paper003();
    let start = assemble(&m, &paper_inputs(0.0), &table1()).unwrap();
    let times: Vec<f64> = (0..=50).map(|k| 0.17 * f64::from(k) / 50.0).collect();
    let report = follow(&m, &start, paper_inputs, paper_input_rates, &times);
    assert_eq!(report.end, TrajectoryEnd::Completed);
    for s in report.samples.iter().step_by(10) {
        let h = 1e-6;
        let plus = assemble(&m, &paper_inputs(s.t + h), &s.pose)
            .unwrap()
            .corners(m.c);
        let minus = assemble(&m, &paper_inputs(s.t - h), &s.pose)
            .unwrap()
            .corners(m.c);
        for i in 0..4 {
            let fd = (plus[i] - minus[i]) / (2.0 * h);
            let v = s.corner_velocities[i];
            assert!(
                (fd - v).norm() < 1e-5 * (1.0 + v.norm()),
                "t {} C{}: {v:?} vs {fd:?}",
                s.t,
                i + 1
            );
        }
        // And the screw theory of §4 (eqs. 16–29) at the same instant: a third method.
        let configuration = Configuration::new(&m, s.q, &s.pose);
        let screws = velocities(&configuration, &Vector4::from(paper_input_rates(s.t))).unwrap();
        for i in 0..4 {
            let v = s.corner_velocities[i];
            assert!(
                (screws.corners[i] - v).norm() < 1e-8 * (1.0 + v.norm()),
                "t {} C{}",
                s.t,
                i + 1
            );
        }
    }
}
