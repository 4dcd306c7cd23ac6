//! Paper 003's position analysis (Gallardo-Alvarado, Tinajero-Campos, Sánchez-Rodríguez, RIAI
//! 18, 2021, §3.2 and §5): the inverse position against the loop closures (eqs. 6, 8) and the
//! published inputs; the forward position's two formulations against the paper's printed
//! equations (§5 step 3), against each other (one corner set per method-2 solution, two per
//! method-1 solution), against `PHCpack` (skipped with a notice when `phc` is absent), against
//! Tables 1–2 and the "two real solutions" of Fig. 10, and against the inverse position.

use kinsyn::poly::{C64, phc};
use kinsyn_papers::configurable::{
    CentrePose, Configurable, CornerPose, ForwardMethod, ForwardPosition, PositionError,
    angle_distance, centre_system, corner_system, forward_position, inverse_position, leg_inverse,
    solution_corners,
};
use nalgebra::Vector2;
use std::collections::HashMap;

/// §5: "θ = 75°, φ = 100°, C = (20, −30) mm" (eq. 11's sense).
fn example_pose() -> CentrePose {
    CentrePose {
        centre: Vector2::new(20.0, -30.0),
        theta: 75f64.to_radians(),
        phi: 100f64.to_radians(),
    }
}

/// §5: the published inputs "q1 = 141,956°, q2 = 203,366°, q3 = 337,773°, q4 = 305,499°".
fn published_q() -> [f64; 4] {
    [141.956f64, 203.366, 337.773, 305.499].map(f64::to_radians)
}

fn closes_every_loop(m: &Configurable, q: &[f64; 4], corners: &[Vector2<f64>; 4]) {
    for (i, corner) in corners.iter().enumerate() {
        let b = m.elbow(i, q[i]);
        assert!(
            ((b - m.base[i]).norm() - m.a).abs() < 1e-9,
            "eq. 8, leg {i}"
        );
        assert!(((corner - b).norm() - m.b).abs() < 1e-9, "eq. 6, leg {i}");
    }
}

#[test]
fn the_inverse_example_has_16_input_sets_that_close_every_loop() {
    let m = Configurable::paper003();
    let pose = example_pose();
    let inverse = m.inverse_centre_pose(&pose).unwrap();
    let sets = inverse.sets();
    // §5, Fig. 9: "16 configuraciones factibles".
    assert_eq!(sets.len(), 16);
    for (k, q) in sets.iter().enumerate() {
        assert!(q.iter().all(|x| (0.0..std::f64::consts::TAU).contains(x)));
        closes_every_loop(&m, q, &inverse.corners);
        for other in &sets[..k] {
            assert!(
                (0..4).any(|i| angle_distance(q[i], other[i]) > 1e-6),
                "the 16 sets are distinct"
            );
        }
    }
    // The published q is one of them to within 1e-3° (its last printed digit): three of its
    // angles differ from the exact ones by 5.2e-4° to 6.4e-4°, a little more than half a unit
    // of the last digit (docs/deviations.md, paper 003).
    let published = published_q();
    assert!(inverse.contains(&published, 1e-3f64.to_radians()));
    assert!(!inverse.contains(&published, 5e-4f64.to_radians()));
    // The same 16 sets from the pose in eq. 13's sense (θ13 = π − φ11, φ13 = π − θ11).
    let by_corner = m.inverse_corner_pose(&pose.to_corner_pose(m.c)).unwrap();
    for i in 0..4 {
        for s in 0..2 {
            assert!(angle_distance(by_corner.legs[i].q[s], inverse.legs[i].q[s]) < 1e-12);
        }
    }
}

#[test]
fn a_leg_out_of_reach_is_a_typed_error() {
    let m = Configurable::paper003();
    // |C − A1| = 250 > a + b = 200, and 30 < |a − b| = 40.
    for (d, side) in [(250.0, "far"), (30.0, "near")] {
        let err = leg_inverse(&m, 0, m.base[0] + Vector2::new(0.0, d)).unwrap_err();
        assert_eq!(
            err,
            PositionError::Unreachable {
                leg: 1,
                distance: d,
                min: 40.0,
                max: 200.0
            },
            "{side}"
        );
        assert!(!err.to_string().contains('\n'));
    }
    // At full stretch the two elbows coincide on the segment A C, a from A (hand derivation).
    let stretched = leg_inverse(&m, 1, m.base[1] + Vector2::new(200.0, 0.0)).unwrap();
    for b in stretched.elbows {
        assert!((b - (m.base[1] + Vector2::new(80.0, 0.0))).norm() < 1e-6);
    }
    // A platform whose corner C3 is out of reach: the error names leg 3.
    let mut corners = example_pose().corners(m.c);
    corners[2] = m.base[2] + Vector2::new(0.0, -260.0);
    assert!(matches!(
        inverse_position(&m, &corners),
        Err(PositionError::Unreachable { leg: 3, .. })
    ));
    let nan = CornerPose {
        c4: Vector2::new(f64::NAN, 0.0),
        theta: 0.0,
        phi: 1.0,
    };
    assert!(matches!(
        m.inverse_corner_pose(&nan),
        Err(PositionError::NotFinite(_))
    ));
    let mut q = published_q();
    q[1] = f64::INFINITY;
    assert!(matches!(
        forward_position(&m, q, ForwardMethod::Corner),
        Err(PositionError::NotFinite(_))
    ));
    let flat = Configurable {
        b: 0.0,
        ..Configurable::paper003()
    };
    assert!(matches!(
        corner_system(&flat, &published_q()),
        Err(PositionError::Lengths { .. })
    ));
}

/// Exponents in the order of `corner_system`'s unknowns `(x4, y4, sin θ, cos θ, sin φ, cos φ)`.
const X: usize = 0;
const Y: usize = 1;
const ST: usize = 2;
const CT: usize = 3;
const SP: usize = 4;
const CP: usize = 5;

fn term(vars: &[usize], coefficient: f64) -> (Vec<u32>, f64) {
    let mut e = vec![0u32; 6];
    for v in vars {
        e[*v] += 1;
    }
    (e, coefficient)
}

/// Whether `value` cut (towards zero) to three decimals is `printed`.
fn truncates_to(value: f64, printed: f64) -> bool {
    ((value * 1000.0).trunc() - (printed * 1000.0).round()).abs() < 0.5
}

#[test]
fn method_2_equations_are_the_papers_printed_f1_to_f4() {
    // Paper 003 §5, step 3, transcribed term by term (decimal commas as points).
    let f1 = vec![
        term(&[], 6798.792),
        term(&[X], -273.993),
        term(&[CT], -32879.275),
        term(&[X, X], 1.0),
        term(&[X, CT], 240.0),
        term(&[CT, CT], 14400.0),
        term(&[Y], -98.602),
        term(&[ST], -11832.315),
        term(&[Y, Y], 1.0),
        term(&[Y, ST], 240.0),
        term(&[ST, ST], 14400.0),
    ];
    let f2 = vec![
        term(&[], 19308.697),
        term(&[X], 146.878),
        term(&[CT], 17625.410),
        term(&[CP], 17625.410),
        term(&[X, X], 1.0),
        term(&[X, CT], 240.0),
        term(&[X, CP], 240.0),
        term(&[CT, CT], 14400.0),
        term(&[CT, CP], 28800.0),
        term(&[CP, CP], 14400.0),
        term(&[Y], -336.543),
        term(&[ST], -40385.218),
        term(&[SP], -40385.218),
        term(&[Y, Y], 1.0),
        term(&[Y, ST], 240.0),
        term(&[Y, SP], 240.0),
        term(&[ST, ST], 14400.0),
        term(&[ST, SP], 28800.0),
        term(&[SP, SP], 14400.0),
    ];
    let f3 = vec![
        term(&[], 2377.842),
        term(&[X], 251.889),
        term(&[CP], 30226.705),
        term(&[X, X], 1.0),
        term(&[X, CP], 240.0),
        term(&[CP, CP], 14400.0),
        term(&[Y], 60.524),
        term(&[SP], 7262.919),
        term(&[Y, Y], 1.0),
        term(&[Y, SP], 240.0),
        term(&[SP, SP], 14400.0),
    ];
    let f4 = vec![
        term(&[], 58052.020),
        term(&[X], -92.910),
        term(&[X, X], 1.0),
        term(&[Y], 530.260),
        term(&[Y, Y], 1.0),
    ];
    // Step 4: f5 = sin²θ + cos²θ − 1, f6 = sin²φ + cos²φ − 1.
    let f5 = vec![term(&[ST, ST], 1.0), term(&[CT, CT], 1.0), term(&[], -1.0)];
    let f6 = vec![term(&[SP, SP], 1.0), term(&[CP, CP], 1.0), term(&[], -1.0)];
    let m = Configurable::paper003();
    let system = corner_system(&m, &published_q()).unwrap();
    for (k, printed) in [f1, f2, f3, f4, f5, f6].iter().enumerate() {
        let ours: HashMap<Vec<u32>, C64> = system.equations()[k]
            .terms()
            .map(|(e, c)| (e.to_vec(), c))
            .collect();
        assert_eq!(ours.len(), printed.len(), "f{}: the same terms", k + 1);
        for (e, p) in printed {
            let c = ours
                .get(e)
                .unwrap_or_else(|| panic!("f{}: no term {e:?}", k + 1));
            assert!(c.im == 0.0);
            // Every coefficient built from the published q is the printed one to its last digit:
            // the paper truncates to three decimals (e.g. 6798.7927 → 6798.792).
            assert!((c.re - p).abs() < 1e-3, "f{} {e:?}: {} vs {p}", k + 1, c.re);
            assert!(
                truncates_to(c.re, *p),
                "f{} {e:?}: {} truncates to {p}",
                k + 1,
                c.re
            );
        }
    }
    // Step 1 / Table 2: the elbows B_i of eq. 7 at the published q, truncated the same way.
    let printed_b = [
        (136.996, 49.301),
        (-73.439, 168.271),
        (-125.944, -30.262),
        (46.455, -265.130),
    ];
    for (b, (x, y)) in m.elbows(&published_q()).iter().zip(printed_b) {
        assert!(truncates_to(b.x, x) && truncates_to(b.y, y), "{b:?}");
    }
}

#[test]
fn eq_4_not_step_2_gives_the_second_unit_vector() {
    // Table 2's corners (3 decimals): û is along C3 → C1 (eq. 5), and C4 → C2 must be along v̂.
    let c = [
        Vector2::new(45.949, -28.866),
        Vector2::new(14.889, 87.042),
        Vector2::new(-5.947, -31.133),
        Vector2::new(25.112, -147.043),
    ];
    let u = (c[0] - c[2]).normalize();
    let along = (c[1] - c[3]).normalize();
    let eq4 = Vector2::new(-u.y, u.x); // v̂ = −w4 î + w3 ĵ
    let step2 = Vector2::new(u.y, u.x); // v̂ = w4 î + w3 ĵ (§3.2 method 1 step 2)
    assert!((along - eq4).norm() < 1e-4, "eq. 4 holds at Table 2");
    assert!((along - step2).norm() > 0.08, "step 2's v̂ does not");
    // With step 2's v̂ the corners of eq. 5 are no rhombus: |C1 − C2|² = c² − 4 w5 w6 w3 w4
    // (hand derivation), not c² (eq. 9), unless û is along an axis.
    let (w5, w6): (f64, f64) = ((c[0] - c[2]).norm() / 2.0, (c[1] - c[3]).norm() / 2.0);
    let centre = (c[0] + c[2]) / 2.0;
    let side: f64 = ((centre + u * w5) - (centre + step2 * w6)).norm_squared();
    let expected = w5 * w5 + w6 * w6 - 4.0 * w5 * w6 * u.x * u.y;
    assert!((side - expected).abs() < 1e-6);
    assert!((side.sqrt() - 120.0).abs() > 1.0);
}

fn solve_both(q: [f64; 4]) -> (ForwardPosition, ForwardPosition) {
    let m = Configurable::paper003();
    let two = forward_position(&m, q, ForwardMethod::Corner).unwrap();
    let one = forward_position(&m, q, ForwardMethod::Centre).unwrap();
    (two, one)
}

fn corner_sets(m: &Configurable, f: &ForwardPosition) -> Vec<[[C64; 2]; 4]> {
    f.solutions
        .iter()
        .map(|s| solution_corners(m, f.method, &s.x))
        .collect()
}

fn same(a: &[[C64; 2]; 4], b: &[[C64; 2]; 4]) -> bool {
    (0..4).all(|i| (0..2).all(|j| (a[i][j] - b[i][j]).norm() < 1e-7))
}

#[test]
fn forward_position_at_the_published_q() {
    let m = Configurable::paper003();
    let q = published_q();
    let (two, one) = solve_both(q);
    for f in [&two, &one] {
        assert!(f.complete, "method {}", f.method.number());
        assert!(
            f.solutions
                .iter()
                .all(kinsyn::homotopy::Solution::is_certified)
        );
    }
    // Method 2: 12 complex solutions (PHCpack's count, test below), 2 real: "En total se
    // generaron dos soluciones reales" (§5, Fig. 10).
    assert_eq!((two.complex, two.real), (12, 2));
    assert_eq!(two.complex_assemblies, 12, "method 2 is one-to-one");
    // Method 1: each corner set twice, (û, w5, w6) and (−û, −w5, −w6): twice the solutions,
    // the same corner sets.
    assert_eq!((one.complex, one.real), (24, 4));
    assert_eq!(one.complex_assemblies, 12);
    let (sets2, sets1) = (corner_sets(&m, &two), corner_sets(&m, &one));
    for s in &sets2 {
        assert_eq!(sets1.iter().filter(|t| same(s, t)).count(), 2);
    }
    assert_eq!(two.assemblies.len(), 2);
    assert_eq!(one.assemblies.len(), 2);
    for (a, b) in two.assemblies.iter().zip(&one.assemblies) {
        assert!(a.certified && b.certified);
        assert_eq!((a.solutions, b.solutions), (1, 2));
        for i in 0..4 {
            assert!((a.corners[i] - b.corners[i]).norm() < 1e-8);
        }
    }
    for a in &two.assemblies {
        // A rhombus of side c (eq. 9) closing every loop (eq. 6) ...
        assert!(a.closure_error < 1e-9);
        for i in 0..4 {
            assert!(((a.corners[i] - a.corners[(i + 1) % 4]).norm() - m.c).abs() < 1e-9);
        }
        assert!((a.pose.corners(m.c)[1] - a.corners[1]).norm() < 1e-9);
        // ... whose inverse position gives back q.
        let inverse = inverse_position(&m, &a.corners).unwrap();
        assert!(inverse.contains(&q, 1e-9));
    }
    // Table 1's converged solution: x4 = 25.112, y4 = −147.043, θ = 79.999°, φ = 105.000°.
    // Agreement to 1.3e-3 mm and 8.5e-4°, not to the last printed digit: Table 1's Newton
    // iterates still moved by 0.022 mm in the last step shown (docs/deviations.md, paper 003).
    let table1 = two
        .assemblies
        .iter()
        .find(|a| (a.pose.c4 - Vector2::new(25.112, -147.043)).norm() < 0.01)
        .expect("Table 1's assembly");
    assert!((table1.pose.c4.x - 25.112).abs() < 1.5e-3);
    assert!((table1.pose.c4.y + 147.043).abs() < 1e-3);
    assert!((table1.pose.theta.to_degrees() - 79.999).abs() < 1e-3);
    assert!((table1.pose.phi.to_degrees() - 105.000).abs() < 5e-4);
    // Table 2's corners: within 2.4e-3 mm (C2's y the worst); the printed corners themselves
    // miss eq. 14 by 2e-3 (C1 + C3 − C4 = (14.890, 87.044) against the printed C2).
    let table2 = [
        (45.949, -28.866),
        (14.889, 87.042),
        (-5.947, -31.133),
        (25.112, -147.043),
    ];
    for (c, (x, y)) in table1.corners.iter().zip(table2) {
        assert!(
            (c - Vector2::new(x, y)).amax() < 2.5e-3,
            "{c:?} vs ({x}, {y})"
        );
    }
    // The paper's PHCpack solution (§5): C1 = (45.949, −28.862), C2 = (14.890, 87.048),
    // C3 = (−5.947, −31.128), C4 = (25.111, −147.042): within 5e-3 mm.
    let paper_phc = [
        (45.949, -28.862),
        (14.890, 87.048),
        (-5.947, -31.128),
        (25.111, -147.042),
    ];
    for (c, (x, y)) in table1.corners.iter().zip(paper_phc) {
        assert!(
            (c - Vector2::new(x, y)).amax() < 5e-3,
            "{c:?} vs ({x}, {y})"
        );
    }
}

#[test]
fn forward_position_at_the_exact_inputs_recovers_the_exact_pose() {
    // The inputs of the example pose itself (the 16 sets' member nearest the published q):
    // Table 1's pose θ = 80°, φ = 105° (eq. 13), C4 from eq. 5, must come back to rounding.
    let m = Configurable::paper003();
    let pose = example_pose();
    let inverse = m.inverse_centre_pose(&pose).unwrap();
    let published = published_q();
    let q: [f64; 4] = std::array::from_fn(|i| {
        *inverse.legs[i]
            .q
            .iter()
            .min_by(|a, b| {
                angle_distance(**a, published[i]).total_cmp(&angle_distance(**b, published[i]))
            })
            .unwrap()
    });
    let exact = pose.corners(m.c);
    for method in [ForwardMethod::Corner, ForwardMethod::Centre] {
        let f = forward_position(&m, q, method).unwrap();
        assert_eq!(f.assemblies.len(), 2, "method {}", method.number());
        let found = f
            .assemblies
            .iter()
            .find(|a| (0..4).all(|i| (a.corners[i] - exact[i]).norm() < 1e-9))
            .expect("the example pose");
        assert!((found.pose.theta.to_degrees() - 80.0).abs() < 1e-9);
        assert!((found.pose.phi.to_degrees() - 105.0).abs() < 1e-9);
        assert!((found.centre - pose.centre).norm() < 1e-9);
        assert!(found.certified);
    }
}

fn phc_or_skip() -> Option<std::path::PathBuf> {
    let found = phc::find_phc();
    if found.is_none() {
        eprintln!("phc (Debian package phcpack) not found: the PHCpack comparison is skipped");
    }
    found
}

#[test]
#[ignore = "exhaustive: PHCpack's blackbox on both formulations of paper 003's forward problem, about 7 s (run with --ignored)"]
fn phcpack_finds_the_same_solutions() {
    let Some(path) = phc_or_skip() else { return };
    let m = Configurable::paper003();
    let q = published_q();
    let (two, one) = solve_both(q);
    for (ours, system) in [
        (&two, corner_system(&m, &q).unwrap()),
        (&one, centre_system(&m, &q).unwrap()),
    ] {
        let theirs = phc::solve(&system, &path).unwrap().output;
        let finite: Vec<_> = theirs
            .finite()
            .into_iter()
            .filter(|s| s.is_regular())
            .collect();
        assert_eq!(
            finite.len(),
            ours.complex,
            "method {}",
            ours.method.number()
        );
        assert_eq!(theirs.real_solutions(1e-6).len(), ours.real);
        for s in finite {
            assert!(
                ours.solutions.iter().any(|o| o
                    .x
                    .iter()
                    .zip(&s.point)
                    .all(|(a, b)| (a - b).norm() < 1e-6 * (1.0 + a.norm()))),
                "PHCpack's {:?} is one of ours",
                s.point
            );
        }
    }
}
