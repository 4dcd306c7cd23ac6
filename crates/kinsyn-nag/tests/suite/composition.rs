//! Composed systems (`poly::Composition`): the two-stage program against the expanded
//! equations, the transformations the solvers apply against the same on the expansion, and
//! a solve and a decomposition of a resultant kept composed.

use kinsyn_nag::homotopy::{DecomposeSettings, SolveSettings, decompose, solve};
use kinsyn_nag::poly::{C64, Composition, Poly, System};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn random_point(n: usize, seed: u64) -> Vec<C64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|_| C64::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)))
        .collect()
}

/// `x² + y z − 1`, `x − 2y + z`, `y² − z²`, … : small pieces in three unknowns, and outer
/// polynomials mixing them with powers, products and constants.
fn example() -> Composition {
    let v = |i| Poly::variable(3, i);
    let one = Poly::real(3, 1.0);
    let inner = vec![
        &(&v(0) * &v(0)) + &(&(&v(1) * &v(2)) - &one),
        &(&v(0) - &v(1).scale(C64::new(2.0, 0.0))) + &v(2),
        &(&v(1) * &v(1)) - &(&v(2) * &v(2)),
    ];
    let a = |i| Poly::variable(3, i);
    let outer = vec![
        &(&a(0) * &a(0)) - &(&a(1) * &a(2)),
        &(&a(2) * &(&a(0) * &a(1))) + &Poly::real(3, 3.0),
        a(1).scale(C64::new(0.5, -1.0)),
    ];
    Composition::new(inner, outer).unwrap()
}

fn names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("x{i}")).collect()
}

/// Values and Jacobians of the composed program equal those of the expanded equations (the
/// flat program, an independent evaluation) at random complex points.
#[test]
fn the_composed_program_is_the_expanded_one() {
    let composed = System::composed(names(3), example()).unwrap();
    let flat = System::new(names(3), composed.equations().to_vec()).unwrap();
    assert_eq!(composed.degrees(), [4, 5, 1]);
    let (pc, pf) = (composed.program(), flat.program());
    let (mut wc, mut wf) = (pc.workspace(), pf.workspace());
    for seed in 0..10 {
        let x = random_point(3, seed);
        let (mut vc, mut jc) = (vec![C64::new(0.0, 0.0); 3], vec![C64::new(0.0, 0.0); 9]);
        let (mut vf, mut jf) = (vc.clone(), jc.clone());
        pc.evaluate_with_jacobian(&x, &mut vc, &mut jc, &mut wc);
        pf.evaluate_with_jacobian(&x, &mut vf, &mut jf, &mut wf);
        for (a, b) in vc.iter().zip(&vf).chain(jc.iter().zip(&jf)) {
            assert!((a - b).norm() <= 1e-12 * (1.0 + b.norm()), "{a} vs {b}");
        }
        let values = composed.evaluate(&x);
        for (a, b) in values.iter().zip(&vf) {
            assert!((a - b).norm() <= 1e-12 * (1.0 + b.norm()));
        }
    }
}

/// Homogenising, combining and widening a composed system give the same polynomials as on
/// the expansion, evaluated through the composed programs.
#[test]
fn transformations_keep_the_composition_equal_to_the_expansion() {
    let composed = System::composed(names(3), example()).unwrap();
    let flat = System::new(names(3), composed.equations().to_vec()).unwrap();
    let check = |c: &System, f: &System| {
        assert!(c.composition().is_some());
        assert_eq!(c.equations(), f.equations());
        let n = c.nvars();
        let (pc, pf) = (c.program(), f.program());
        for seed in 0..5 {
            let x = random_point(n, 100 + seed);
            let mut vc = vec![C64::new(0.0, 0.0); c.len()];
            let mut vf = vc.clone();
            let mut jc = vec![C64::new(0.0, 0.0); c.len() * n];
            let mut jf = jc.clone();
            pc.evaluate_with_jacobian(&x, &mut vc, &mut jc, &mut pc.workspace());
            pf.evaluate_with_jacobian(&x, &mut vf, &mut jf, &mut pf.workspace());
            for (a, b) in vc.iter().zip(&vf).chain(jc.iter().zip(&jf)) {
                assert!((a - b).norm() <= 1e-11 * (1.0 + b.norm()), "{a} vs {b}");
            }
        }
    };
    // One group, and two groups.
    for groups in [vec![vec![0, 1, 2]], vec![vec![0], vec![1, 2]]] {
        check(&composed.homogenized(&groups), &flat.homogenized(&groups));
    }
    let rows = vec![
        vec![C64::new(1.0, 0.0), C64::new(0.0, 0.0), C64::new(0.3, -0.2)],
        vec![C64::new(0.0, 0.0), C64::new(1.0, 0.0), C64::new(-1.1, 0.4)],
    ];
    check(&composed.combinations(&rows), &flat.combinations(&rows));
    let wide = names(5);
    let extra = vec![&Poly::variable(5, 3) * &Poly::variable(5, 0) - Poly::variable(5, 4)];
    check(
        &composed.widened(wide.clone(), extra.clone()).unwrap(),
        &flat.widened(wide, extra).unwrap(),
    );
}

/// The resultant of two circles' equations in `t` (`a₂t² + a₁t + a₀` with coefficients
/// linear in x, y), kept composed, solved with a line: the same roots as the expanded system
/// (the flat program), each checked on the expansion.
#[test]
fn a_composed_resultant_solves_as_its_expansion() {
    let v = |i| Poly::variable(2, i);
    let c = |r: f64| Poly::real(2, r);
    // a(t) = (x − 1) t² + y t + (x + y − 2), b(t) = y t² + (x − 3) t + (2x − y + 1).
    let inner = vec![
        &(&v(0) + &v(1)) - &c(2.0),
        v(1),
        &v(0) - &c(1.0),
        &(&v(0).scale(C64::new(2.0, 0.0)) - &v(1)) + &c(1.0),
        &v(0) - &c(3.0),
        v(1),
        &(&v(0) - &v(1).scale(C64::new(0.5, 0.0))) - &c(0.25),
    ];
    let a = |i| Poly::variable(7, i);
    let (a0, a1, a2, b0, b1, b2) = (a(0), a(1), a(2), a(3), a(4), a(5));
    let u = &(&a2 * &b0) - &(&a0 * &b2);
    let w = &(&a2 * &b1) - &(&a1 * &b2);
    let z = &(&a1 * &b0) - &(&a0 * &b1);
    let outer = vec![&(&u * &u) - &(&w * &z), a(6)];
    let composed = System::composed(names(2), Composition::new(inner, outer).unwrap()).unwrap();
    let flat = System::new(names(2), composed.equations().to_vec()).unwrap();
    let settings = SolveSettings {
        seed: 3,
        ..SolveSettings::default()
    };
    let rc = solve(&composed, &settings).unwrap();
    let rf = solve(&flat, &settings).unwrap();
    let finite = |r: &kinsyn_nag::homotopy::SolveReport| {
        let mut xs: Vec<Vec<C64>> = r
            .solutions
            .iter()
            .filter(|s| s.regular)
            .map(|s| s.x.clone())
            .collect();
        xs.sort_by(|p, q| {
            p[0].re
                .total_cmp(&q[0].re)
                .then(p[0].im.total_cmp(&q[0].im))
        });
        xs
    };
    let (xc, xf) = (finite(&rc), finite(&rf));
    // The resultant has degree 4 and the line degree 1: at most 4 roots, all found by both.
    assert_eq!(xc.len(), xf.len());
    assert!(!xc.is_empty());
    for (p, q) in xc.iter().zip(&xf) {
        assert!(p.iter().zip(q).all(|(a, b)| (a - b).norm() < 1e-8));
        assert!(flat.evaluate(p).iter().all(|r| r.norm() < 1e-8));
    }
    // A decomposition of the resultant alone (a curve) by the composed path: its degree is
    // the expansion's, 4, in components whose degrees add up to it.
    let curve = System::composed(
        names(2),
        Composition::new(
            composed.composition().unwrap().inner()[..6].to_vec(),
            vec![composed.composition().unwrap().outer()[0].relabel(6, &[0, 1, 2, 3, 4, 5, 0])],
        )
        .unwrap(),
    )
    .unwrap();
    assert_eq!(curve.degrees(), [4]);
    let d = decompose(&curve, &DecomposeSettings::default()).unwrap();
    let total: usize = d
        .components
        .iter()
        .filter(|c| c.dimension == 1)
        .map(|c| c.degree)
        .sum();
    assert_eq!(total, 4);
}
