//! Homotopy continuation on systems whose roots are known by construction: roots of unity
//! (`x^n − 1`: the `n` numbers `e^{2πik/n}`, all simple, two real for even `n` and one for
//! odd), products of such factors, roots of very different sizes, and random products of
//! linear factors (a property test). Every root must be found once, regular and certified
//! (Krawczyk, `kinsyn_nag::certify`); the expected roots come from the construction, never from a
//! run of the solver.

use kinsyn_nag::homotopy::{SolveReport, SolveSettings, StartSystem, solve};
use kinsyn_nag::poly::{C64, Poly, System};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use std::f64::consts::TAU;

/// The `n` roots of `x^n = c` for real `c > 0`: `c^{1/n} e^{2πik/n}`.
fn roots_of(n: u32, c: f64) -> Vec<C64> {
    (0..n)
        .map(|k| {
            C64::from_polar(
                c.powf(1.0 / f64::from(n)),
                TAU * f64::from(k) / f64::from(n),
            )
        })
        .collect()
}

/// Checks that `report` found exactly the roots `expected` (each matched by one certified
/// regular solution within `1e-9` of its own size), of which `real` are real, and nothing
/// else: no singular solution, no failed path, every other path at infinity.
fn assert_exactly(report: &SolveReport, expected: &[Vec<C64>], real: usize, what: &str) {
    assert_eq!(
        report.failed(),
        0,
        "{what}: no failed path ({})",
        report.summary()
    );
    assert_eq!(
        report.singular(),
        0,
        "{what}: every root is simple ({})",
        report.summary()
    );
    assert_eq!(
        report.nonsingular(),
        expected.len(),
        "{what}: {} roots ({})",
        expected.len(),
        report.summary()
    );
    assert_eq!(
        report.certified(),
        expected.len(),
        "{what}: every root certified ({})",
        report.summary()
    );
    assert_eq!(
        report.real(),
        real,
        "{what}: {real} real roots ({})",
        report.summary()
    );
    assert_eq!(
        report.certified_real(),
        real,
        "{what}: the real roots certified real ({})",
        report.summary()
    );
    for root in expected {
        let size = root.iter().map(|c| c.norm()).fold(0.0, f64::max);
        let matches = report
            .solutions
            .iter()
            .filter(|s| {
                s.x.iter()
                    .zip(root)
                    .all(|(a, b)| (a - b).norm() <= 1e-9 * size.max(b.norm()).max(1e-300))
            })
            .count();
        assert_eq!(matches, 1, "{what}: the root {root:?} found once");
    }
}

fn univariate(p: &Poly) -> System {
    System::new(vec!["x".into()], vec![p.clone()]).unwrap()
}

fn power(n: u32) -> Poly {
    Poly::variable(1, 0).pow(n)
}

/// `x^n − 1`: roots of unity, two real (±1) for even `n`, one for odd.
fn roots_of_unity(n: u32) {
    let report = solve(
        &univariate(&(power(n) - Poly::real(1, 1.0))),
        &SolveSettings::default(),
    )
    .unwrap();
    let expected: Vec<Vec<C64>> = roots_of(n, 1.0).into_iter().map(|r| vec![r]).collect();
    let real = if n.is_multiple_of(2) { 2 } else { 1 };
    assert_exactly(&report, &expected, real, &format!("x^{n} - 1"));
    assert_eq!(report.paths(), n as usize, "Bézout's n paths");
}

#[test]
fn roots_of_unity_are_simple_regular_and_certified_up_to_degree_64() {
    for n in (1..=20).chain([31, 32, 33, 48, 63, 64]) {
        roots_of_unity(n);
    }
}

/// `x^1024 − 1`: 1024 roots of unity, 2 real. The solver once found 14 regular roots, 280
/// "singular" and 730 failed paths (coordinates on a fixed patch whose 1023rd powers
/// overflowed), and certification failed on roots far from the axes (the wrapping effect of
/// a chain of 1023 interval products).
#[test]
fn the_1024th_roots_of_unity() {
    roots_of_unity(1024);
}

/// More large degrees and a product of two degree-512 factors: about 12 s in a debug build,
/// run by CI's exhaustive step (`cargo test -p kinsyn-nag --test suite homotopy_known_roots:: --
/// --ignored`).
#[test]
#[ignore = "exhaustive: degrees 100 to 1024, about 12 s (run with --ignored)"]
fn roots_of_unity_up_to_degree_1024_exhaustive() {
    for n in [100, 127, 128, 255, 256, 511, 512, 1000, 1023, 1024] {
        roots_of_unity(n);
    }
    // A product of two such factors: the 512th roots of unity and of 2, 1024 roots, 2 + 2 real.
    let x = power(512);
    let p = (&x - Poly::real(1, 1.0)) * (&x - Poly::real(1, 2.0));
    let report = solve(&univariate(&p), &SolveSettings::default()).unwrap();
    let expected: Vec<Vec<C64>> = roots_of(512, 1.0)
        .into_iter()
        .chain(roots_of(512, 2.0))
        .map(|r| vec![r])
        .collect();
    assert_exactly(&report, &expected, 4, "(x^512 - 1)(x^512 - 2)");
}

#[test]
fn products_of_roots_of_unity_factors() {
    // (x^5 − 1)(x^7 − 2): the fifth roots of unity and the seventh roots of 2; real: 1 and 2^{1/7}.
    let p = (power(5) - Poly::real(1, 1.0)) * (power(7) - Poly::real(1, 2.0));
    let report = solve(&univariate(&p), &SolveSettings::default()).unwrap();
    let expected: Vec<Vec<C64>> = roots_of(5, 1.0)
        .into_iter()
        .chain(roots_of(7, 2.0))
        .map(|r| vec![r])
        .collect();
    assert_exactly(&report, &expected, 2, "(x^5 - 1)(x^7 - 2)");

    // x^n = 1, y^m = 3 in two variables: n·m roots (ω_n^j, 3^{1/m} ω_m^k), real for
    // x = ±1 (n even) and y = 3^{1/m} (m odd): 2 real roots; total degree, multi-homogeneous
    // and linear-product start alike.
    for (n, m) in [(16, 3), (40, 5), (64, 1)] {
        let x = Poly::variable(2, 0);
        let y = Poly::variable(2, 1);
        let system = System::new(
            vec!["x".into(), "y".into()],
            vec![x.pow(n) - Poly::real(2, 1.0), y.pow(m) - Poly::real(2, 3.0)],
        )
        .unwrap()
        .with_groups(vec![vec![0], vec![1]])
        .unwrap();
        let mut expected = Vec::new();
        for a in roots_of(n, 1.0) {
            for b in roots_of(m, 3.0) {
                expected.push(vec![a, b]);
            }
        }
        for start in [
            StartSystem::TotalDegree,
            StartSystem::MultiHomogeneous,
            StartSystem::LinearProduct,
        ] {
            let settings = SolveSettings {
                start,
                ..SolveSettings::default()
            };
            let report = solve(&system, &settings).unwrap();
            assert_exactly(
                &report,
                &expected,
                2,
                &format!("x^{n} = 1, y^{m} = 3, {start:?}"),
            );
        }
    }

    // The same in skew coordinates u = x + y, v = x − 2y: u^12 = 1, v^5 = 1 expand into
    // binomial coefficients up to 924 that cancel at the roots; x = (2u + v)/3, y = (u − v)/3.
    // Real roots: u = ±1 with v = 1.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let u = &x + &y;
    let v = &x - &(y.clone() * 2.0);
    let system = System::new(
        vec!["x".into(), "y".into()],
        vec![
            u.pow(12) - Poly::real(2, 1.0),
            v.pow(5) - Poly::real(2, 1.0),
        ],
    )
    .unwrap();
    let mut expected = Vec::new();
    for a in roots_of(12, 1.0) {
        for b in roots_of(5, 1.0) {
            expected.push(vec![(a * 2.0 + b) / 3.0, (a - b) / 3.0]);
        }
    }
    let report = solve(&system, &SolveSettings::default()).unwrap();
    assert_exactly(&report, &expected, 2, "(x + y)^12 = 1, (x - 2y)^5 = 1");
}

#[test]
fn roots_twelve_orders_of_magnitude_apart() {
    // (x − 1e-6)(x − 1)(x − 1e6): three simple real roots.
    let x = Poly::variable(1, 0);
    let factors = [1e-6, 1.0, 1e6];
    let p = factors
        .iter()
        .fold(Poly::real(1, 1.0), |acc, a| acc * (&x - Poly::real(1, *a)));
    let report = solve(&univariate(&p), &SolveSettings::default()).unwrap();
    let expected: Vec<Vec<C64>> = factors.iter().map(|a| vec![C64::from(*a)]).collect();
    assert_exactly(&report, &expected, 3, "(x - 1e-6)(x - 1)(x - 1e6)");

    // Two variables: (x − 1e-6)(x − 1)(x − 1e6) = 0 and (y − 1e-4 x)(y − 1e4) = 0, whose 6
    // roots are (a, 1e-4 a) and (a, 1e4): coordinates from 1e-10 to 1e6, all real.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let f1 = factors
        .iter()
        .fold(Poly::real(2, 1.0), |acc, a| acc * (&x - Poly::real(2, *a)));
    let f2 = (&y - &(x.clone() * 1e-4)) * (&y - Poly::real(2, 1e4));
    let system = System::new(vec!["x".into(), "y".into()], vec![f1, f2]).unwrap();
    let mut expected = Vec::new();
    for a in factors {
        expected.push(vec![C64::from(a), C64::from(1e-4 * a)]);
        expected.push(vec![C64::from(a), C64::from(1e4)]);
    }
    let report = solve(&system, &SolveSettings::default()).unwrap();
    assert_exactly(
        &report,
        &expected,
        6,
        "roots from 1e-10 to 1e6 in two variables",
    );
}

/// A complex number of modulus between 0.1 and 10 (log-uniform) and any argument, or a real
/// one of either sign.
fn coordinate() -> impl Strategy<Value = C64> {
    (-1.0f64..1.0, 0.0..TAU, any::<bool>()).prop_map(|(e, theta, real)| {
        let r = 10f64.powf(e);
        if real {
            C64::from(if theta < std::f64::consts::PI { r } else { -r })
        } else {
            C64::from_polar(r, theta)
        }
    })
}

/// Whether the points are pairwise at least `gap` apart relative to their size: the roots of
/// the products are simple, and far enough apart for a test of double precision.
fn separated(points: &[C64], gap: f64) -> bool {
    points.iter().enumerate().all(|(i, a)| {
        points[..i]
            .iter()
            .all(|b| (a - b).norm() > gap * (1.0 + a.norm().max(b.norm())))
    })
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 24,
        rng_seed: RngSeed::Fixed(20_261_127),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

fn real_count(points: &[Vec<C64>]) -> usize {
    points
        .iter()
        .filter(|p| p.iter().all(|c| c.im == 0.0))
        .count()
}

proptest! {
    #![proptest_config(config())]

    /// `Π (x − a_i)` for 1 to 9 distinct random roots: each found once, regular, certified,
    /// and the real ones (the real `a_i`) certified real.
    #[test]
    fn every_root_of_a_product_of_linear_factors(
        roots in prop::collection::vec(coordinate(), 1..10)
    ) {
        prop_assume!(separated(&roots, 0.02));
        let x = Poly::variable(1, 0);
        let p = roots
            .iter()
            .fold(Poly::real(1, 1.0), |acc, a| acc * (&x - Poly::constant(1, *a)));
        let report = solve(&univariate(&p), &SolveSettings::default()).unwrap();
        let expected: Vec<Vec<C64>> = roots.iter().map(|a| vec![*a]).collect();
        // Reality is decided for real systems only (a real root of a system with complex
        // coefficients is not counted real).
        let real = if p.is_real() { real_count(&expected) } else { 0 };
        assert_exactly(&report, &expected, real, "a product of linear factors");
    }

    /// `Π (ℓ1 − a_i) = 0`, `Π (ℓ2 − b_j) = 0` for random real linear forms `ℓ1`, `ℓ2` of
    /// `(x, y)` (a random change of coordinates): the roots are the `(a_i, b_j)` mapped back,
    /// each found once, regular and certified.
    #[test]
    fn every_root_of_two_products_of_linear_forms(
        a in prop::collection::vec(-10.0f64..10.0, 1..5),
        b in prop::collection::vec(-10.0f64..10.0, 1..5),
        m in prop::array::uniform4(-2.0f64..2.0),
    ) {
        let det = m[0] * m[3] - m[1] * m[2];
        prop_assume!(det.abs() > 0.25);
        let real_points = |v: &[f64]| v.iter().map(|t| C64::from(*t)).collect::<Vec<_>>();
        prop_assume!(separated(&real_points(&a), 0.02) && separated(&real_points(&b), 0.02));
        let x = Poly::variable(2, 0);
        let y = Poly::variable(2, 1);
        let l1 = x.clone() * m[0] + y.clone() * m[1];
        let l2 = x.clone() * m[2] + y.clone() * m[3];
        let f1 = a.iter().fold(Poly::real(2, 1.0), |acc, t| acc * (&l1 - Poly::real(2, *t)));
        let f2 = b.iter().fold(Poly::real(2, 1.0), |acc, t| acc * (&l2 - Poly::real(2, *t)));
        let system = System::new(vec!["x".into(), "y".into()], vec![f1, f2]).unwrap();
        let mut expected = Vec::new();
        for s in &a {
            for t in &b {
                // The inverse of [[m0, m1], [m2, m3]] applied to (s, t).
                expected.push(vec![
                    C64::from((m[3] * s - m[1] * t) / det),
                    C64::from((m[0] * t - m[2] * s) / det),
                ]);
            }
        }
        let report = solve(&system, &SolveSettings::default()).unwrap();
        assert_exactly(&report, &expected, expected.len(), "two products of linear forms");
    }
}
