//! Certified roots: interval operations against exact results (error-free transformations and
//! Shewchuk's exact expansion sums, an arithmetic independent of the intervals'), and the
//! Krawczyk certificates against roots known in closed form (hand-factored polynomials, conics
//! solved by hand), checked exactly where the root is a float or a square root.

use kinsyn_nag::certify::{
    Certificate, CertificateStatus, CertifyError, CertifyOptions, ComplexInterval, FailureReason,
    Interval, Reality, certify_root, certify_root_with, certify_roots, separate,
};
use kinsyn_nag::poly::{C64, Poly, Program, Scalar, System};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn c(re: f64, im: f64) -> C64 {
    C64::new(re, im)
}

// ---------------------------------------------------------------------------------------------
// Exact reference arithmetic.

/// Knuth's `TwoSum`: `a + b = s + e` exactly.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `TwoProduct` with a fused multiply-add: `a · b = p + e` exactly (no underflow in our ranges).
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// The exact sign of `Σ terms` (Shewchuk's Grow-Expansion: the running sum as a
/// non-overlapping expansion, whose largest non-zero component carries the sign).
fn exact_sign(terms: &[f64]) -> i32 {
    let mut e: Vec<f64> = Vec::new();
    for &b in terms {
        let mut q = b;
        let mut h = Vec::with_capacity(e.len() + 1);
        for &ei in &e {
            let (s, err) = two_sum(q, ei);
            if err != 0.0 {
                h.push(err);
            }
            q = s;
        }
        h.push(q);
        e = h;
    }
    e.iter()
        .rev()
        .find(|x| **x != 0.0)
        .map_or(0, |x| if *x > 0.0 { 1 } else { -1 })
}

/// Whether `iv` contains the exact value `Σ terms`.
fn encloses(iv: Interval, terms: &[f64]) -> bool {
    let mut lower = terms.to_vec();
    lower.push(-iv.lo);
    let mut upper = terms.iter().map(|t| -t).collect::<Vec<_>>();
    upper.push(iv.hi);
    exact_sign(&lower) >= 0 && exact_sign(&upper) >= 0
}

/// Whether `iv` (of one sign) contains `sign · √q`, decided exactly by squaring the bounds.
fn encloses_sqrt(iv: Interval, q: f64, sign: f64) -> bool {
    let (near, far) = if sign > 0.0 {
        (iv.lo, iv.hi)
    } else {
        (-iv.hi, -iv.lo)
    };
    if near < 0.0 {
        return false;
    }
    let (p, e) = two_prod(near, near);
    let (p2, e2) = two_prod(far, far);
    exact_sign(&[p, e, -q]) <= 0 && exact_sign(&[p2, e2, -q]) >= 0
}

// ---------------------------------------------------------------------------------------------
// Interval arithmetic.

#[test]
fn exact_reference_is_exact() {
    // The reference itself: 0.1 + 0.2 rounds up (0.30000000000000004), so the exact sum of the
    // two binary64 numbers lies below the float sum, and above the float below it.
    let s = 0.1 + 0.2;
    assert_eq!(exact_sign(&[0.1, 0.2, -s]), -1);
    assert_eq!(exact_sign(&[0.1, 0.2, -s.next_down()]), 1);
    assert_eq!(exact_sign(&[1e300, 1.0, -1e300, -1.0]), 0);
    assert_eq!(exact_sign(&[1e300, 1e-300, -1e300]), 1);
}

#[test]
fn decimal_sum_is_enclosed() {
    // 0.1 and 0.2 as the user writes them: their binary64 values are off by < half an ulp, so
    // the coefficient enclosures contain the decimals and their sum must contain 3/10 exactly.
    // x < 3/10 ⇔ 10·x − 3 < 0, decided exactly with TwoProduct.
    let tenth = Interval::coefficient(c(0.1, 0.0));
    let fifth = Interval::coefficient(c(0.2, 0.0));
    let sum = tenth + fifth;
    let (p, e) = two_prod(10.0, sum.lo);
    assert_eq!(exact_sign(&[p, e, -3.0]), -1, "lower bound below 3/10");
    let (p, e) = two_prod(10.0, sum.hi);
    assert_eq!(exact_sign(&[p, e, -3.0]), 1, "upper bound above 3/10");
    // The rounded float sum alone misses 3/10: it is above it.
    let (p, e) = two_prod(10.0, 0.1 + 0.2);
    assert_eq!(exact_sign(&[p, e, -3.0]), 1);
    // Point intervals of the binary64 numbers enclose their exact binary sum, a few ulps wide.
    let bin = Interval::point(0.1) + Interval::point(0.2);
    assert!(encloses(bin, &[0.1, 0.2]));
    assert!(bin.hi - bin.lo <= 4.0 * f64::EPSILON * 0.3);
}

fn random_float(rng: &mut ChaCha8Rng) -> f64 {
    let mantissa: f64 = rng.random_range(1.0..2.0);
    let exponent: i32 = rng.random_range(-20..20);
    let sign = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
    sign * mantissa * 2f64.powi(exponent)
}

fn random_interval(rng: &mut ChaCha8Rng) -> Interval {
    let a = random_float(rng);
    let b = if rng.random_bool(0.2) {
        a
    } else {
        random_float(rng)
    };
    Interval::new(a.min(b), a.max(b))
}

/// Members of an interval: both bounds and a float inside.
fn members(iv: Interval, rng: &mut ChaCha8Rng) -> [f64; 3] {
    let t: f64 = rng.random_range(0.0..1.0);
    let inside = (iv.lo + t * (iv.hi - iv.lo)).clamp(iv.lo, iv.hi);
    [iv.lo, iv.hi, inside]
}

#[test]
fn real_operations_enclose_exact_results() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..4000 {
        let a = random_interval(&mut rng);
        let b = random_interval(&mut rng);
        let (sum, difference, product) = (a + b, a - b, a * b);
        for x in members(a, &mut rng) {
            for y in members(b, &mut rng) {
                assert!(encloses(sum, &[x, y]), "{x} + {y} ∉ {sum:?}");
                assert!(encloses(difference, &[x, -y]), "{x} − {y} ∉ {difference:?}");
                let (p, e) = two_prod(x, y);
                assert!(encloses(product, &[p, e]), "{x} · {y} ∉ {product:?}");
            }
        }
        assert!(encloses(-a, &[-a.lo]) && encloses(-a, &[-a.hi]));
    }
}

#[test]
fn complex_operations_enclose_exact_results() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    for _ in 0..2000 {
        let a = ComplexInterval::new(random_interval(&mut rng), random_interval(&mut rng));
        let b = ComplexInterval::new(random_interval(&mut rng), random_interval(&mut rng));
        let (sum, product) = (a + b, a * b);
        for (ar, ai) in members(a.re, &mut rng)
            .into_iter()
            .zip(members(a.im, &mut rng))
        {
            for (br, bi) in members(b.re, &mut rng)
                .into_iter()
                .zip(members(b.im, &mut rng))
            {
                assert!(encloses(sum.re, &[ar, br]) && encloses(sum.im, &[ai, bi]));
                // (ar + i ai)(br + i bi) = (ar br − ai bi) + i (ar bi + ai br).
                let (p1, e1) = two_prod(ar, br);
                let (p2, e2) = two_prod(ai, bi);
                let (p3, e3) = two_prod(ar, bi);
                let (p4, e4) = two_prod(ai, br);
                assert!(encloses(product.re, &[p1, e1, -p2, -e2]));
                assert!(encloses(product.im, &[p3, e3, p4, e4]));
            }
        }
    }
}

#[test]
fn nan_and_infinity_give_no_information() {
    let entire = Interval::ENTIRE;
    // 0 · ∞ and ∞ − ∞ are NaN in floating point: the result must be everything.
    let zero_one = Interval::new(0.0, 1.0);
    assert_eq!(zero_one * entire, entire);
    let inf = Interval::new(f64::INFINITY, f64::INFINITY);
    assert_eq!(inf - inf, entire);
    assert_eq!(Interval::point(f64::NAN), entire);
    assert_eq!(Interval::coefficient(c(f64::NAN, 0.0)), entire);
    // A complex coefficient has no real enclosure.
    assert_eq!(Interval::coefficient(c(1.0, 1e-300)), entire);
    assert!(!entire.is_finite() && entire.contains_zero());
    // Overflow: the exact sum MAX + MAX lies above MAX, the lower bound.
    let big = Interval::point(f64::MAX) + Interval::point(f64::MAX);
    assert_eq!(big, Interval::new(f64::MAX, f64::INFINITY));
}

#[test]
fn box_predicates() {
    let a = Interval::new(0.0, 1.0);
    let b = Interval::new(0.5, 2.0);
    assert!(!a.disjoint(b) && a.disjoint(Interval::new(1.5, 2.0)));
    assert_eq!(a.hull(b), Interval::new(0.0, 2.0));
    assert_eq!(a.intersection(b), Some(Interval::new(0.5, 1.0)));
    assert!(Interval::new(0.1, 0.9).interior_of(a) && !Interval::new(0.0, 0.9).interior_of(a));
    assert!(Interval::new(0.0, 0.9).subset_of(a));
    assert_eq!(b.mag().to_bits(), 2f64.to_bits());
    assert_eq!(a.midpoint().to_bits(), 0.5f64.to_bits());
    assert!(a.width() >= 1.0);
    let z = ComplexInterval::new(a, Interval::new(-1.0, -0.5));
    assert!(!z.contains_zero() && z.contains(c(0.5, -0.75)));
}

// ---------------------------------------------------------------------------------------------
// Systems with known roots.

fn univariate(coefficients_low_first: &[C64]) -> (Program, bool) {
    let terms = coefficients_low_first
        .iter()
        .enumerate()
        .map(|(k, a)| (vec![u32::try_from(k).unwrap()], *a));
    let system = System::new(vec!["x".into()], vec![Poly::from_terms(1, terms)]).unwrap();
    (system.program(), system.is_real())
}

/// (x − 1)(x − 2)(x − 3) = x³ − 6x² + 11x − 6.
fn cubic() -> (Program, bool) {
    univariate(&[c(-6.0, 0.0), c(11.0, 0.0), c(-6.0, 0.0), c(1.0, 0.0)])
}

fn enclosure_holds(cert: &Certificate, root: &[C64]) -> bool {
    cert.enclosure.iter().zip(root).all(|(e, z)| e.contains(*z))
}

/// Whether `root` lies in the certificate's box of uniqueness `refined ± radius` (exactly:
/// the differences below are of nearby floats, computed exactly by `TwoSum`).
fn uniqueness_box_holds(cert: &Certificate, root: &[C64]) -> bool {
    let r = cert.radius().unwrap();
    cert.refined.iter().zip(root).all(|(x, z)| {
        [(x.re, z.re), (x.im, z.im)].iter().all(|(a, b)| {
            let (s, e) = two_sum(*b, -*a);
            exact_sign(&[s, e, -r]) <= 0 && exact_sign(&[s, e, r]) >= 0
        })
    })
}

#[test]
fn cubic_roots_are_certified_real_and_distinct() {
    let (program, real) = cubic();
    assert!(real);
    let given = [
        vec![c(1.0 + 1e-9, 2e-10)],
        vec![c(2.0 - 3e-10, 0.0)],
        vec![c(3.0 + 1e-9, -1e-10)],
    ];
    let certificates = certify_roots(&program, &given, real).unwrap();
    for (k, cert) in certificates.iter().enumerate() {
        let root = [c((k + 1) as f64, 0.0)];
        assert!(cert.is_certified(), "root {k}: {:?}", cert.status);
        assert_eq!(cert.real, Reality::CertifiedReal);
        assert!(cert.distinct && cert.same_as.is_none());
        assert!(enclosure_holds(cert, &root), "{:?}", cert.enclosure);
        assert!(uniqueness_box_holds(cert, &root));
        assert!(cert.radius().unwrap() < 1e-12, "{:?}", cert.status);
        for other in 1..=3 {
            if other != k + 1 {
                assert!(!cert.enclosure[0].contains(c(other as f64, 0.0)));
            }
        }
    }
    // Without the promise of real coefficients nothing proves the roots real, and nothing may
    // prove them non-real either.
    let certificates = certify_roots(&program, &given, false).unwrap();
    assert!(
        certificates
            .iter()
            .all(|c| c.is_certified() && c.real == Reality::Unknown)
    );
}

#[test]
fn imaginary_unit_roots_are_certified_non_real() {
    // x² + 1 = (x − i)(x + i).
    let (program, real) = univariate(&[c(1.0, 0.0), c(0.0, 0.0), c(1.0, 0.0)]);
    let given = [vec![c(1e-9, 1.0 - 1e-9)], vec![c(0.0, -1.0 + 2e-9)]];
    let certificates = certify_roots(&program, &given, real).unwrap();
    for (cert, root) in certificates.iter().zip([c(0.0, 1.0), c(0.0, -1.0)]) {
        assert!(cert.is_certified(), "{:?}", cert.status);
        assert_eq!(cert.real, Reality::CertifiedNonReal);
        assert!(cert.distinct);
        assert!(enclosure_holds(cert, &[root]));
        assert!(uniqueness_box_holds(cert, &[root]));
    }
}

#[test]
fn points_that_are_not_roots_fail() {
    let (program, real) = cubic();
    // A root moved by 1e-3 is not an approximate root at the default tolerance 1e-6.
    let moved = certify_root(&program, &[c(1.001, 0.0)], real).unwrap();
    assert!(
        matches!(
            moved.status,
            CertificateStatus::Failed(FailureReason::TooFar { .. })
        ),
        "{:?}",
        moved.status
    );
    assert_eq!(moved.real, Reality::Unknown);
    assert!(moved.enclosure.is_empty());
    // 2.5 is no root; Newton's step from it (f = −0.375, f' = −0.25) is −1.5, so any box
    // around it large enough for the test holds all three roots 1, 2, 3: Krawczyk cannot pass.
    let loose = CertifyOptions {
        tolerance: 10.0,
        newton_steps: 0,
        ..CertifyOptions::default()
    };
    let between = certify_root_with(&program, &[c(2.5, 0.0)], real, &loose).unwrap();
    assert_eq!(
        between.status,
        CertificateStatus::Failed(FailureReason::NotContracting)
    );
    // The same 1e-3 perturbation under a loose tolerance and without polishing: the test
    // passes, and the box it proves does hold the true root 1 (the claim is true).
    let far = CertifyOptions {
        tolerance: 0.1,
        newton_steps: 0,
        ..CertifyOptions::default()
    };
    let cert = certify_root_with(&program, &[c(1.001, 0.0)], real, &far).unwrap();
    assert!(cert.is_certified(), "{:?}", cert.status);
    assert_eq!(cert.refined, vec![c(1.001, 0.0)]);
    assert!(uniqueness_box_holds(&cert, &[c(1.0, 0.0)]));
    assert!(enclosure_holds(&cert, &[c(1.0, 0.0)]));
    // Non-finite input.
    let nan = certify_root(&program, &[c(f64::NAN, 0.0)], real).unwrap();
    assert_eq!(
        nan.status,
        CertificateStatus::Failed(FailureReason::NonFinite)
    );
}

#[test]
fn close_roots_are_told_apart_and_a_repeated_root_is_not() {
    // (x − 1)(x − a) with a = 1 + 2⁻²⁰ ≈ 1 + 9.5e-7: the coefficients 1 + a and a are exact in
    // binary64 (1e-6 itself would be rounded), so the roots are exactly 1 and a.
    let a = 1.0 + 2f64.powi(-20);
    let (program, real) = univariate(&[c(a, 0.0), c(-(1.0 + a), 0.0), c(1.0, 0.0)]);
    let given = [vec![c(1.0 + 1e-12, 0.0)], vec![c(a - 1e-12, 0.0)]];
    let certificates = certify_roots(&program, &given, real).unwrap();
    let roots = [c(1.0, 0.0), c(a, 0.0)];
    for (k, cert) in certificates.iter().enumerate() {
        assert!(cert.is_certified(), "{:?}", cert.status);
        assert!(cert.distinct, "root {k}");
        assert_eq!(cert.real, Reality::CertifiedReal);
        assert!(enclosure_holds(cert, &[roots[k]]));
        assert!(!cert.enclosure[0].contains(roots[1 - k]));
        assert!(uniqueness_box_holds(cert, &[roots[k]]));
    }
    assert!(certificates[0].enclosure[0].disjoint(certificates[1].enclosure[0]));
    // Certified one by one (as a parallel caller would), then compared.
    let mut one_by_one: Vec<Certificate> = given
        .iter()
        .map(|x| certify_root(&program, x, real).unwrap())
        .collect();
    assert!(one_by_one.iter().all(|c| c.is_certified() && !c.distinct));
    separate(&program, &mut one_by_one);
    assert!(one_by_one.iter().all(|c| c.distinct));
    // The same root given twice (once slightly moved): both certified, neither distinct, and
    // each proven the other's.
    let twice = [
        vec![c(1.0, 0.0)],
        vec![c(a, 0.0)],
        vec![c(1.0 + 1e-13, 0.0)],
    ];
    let certificates = certify_roots(&program, &twice, real).unwrap();
    assert!(certificates.iter().all(Certificate::is_certified));
    assert!(!certificates[0].distinct && !certificates[2].distinct);
    assert!(certificates[1].distinct);
    assert_eq!(certificates[0].same_as, Some(2));
    assert_eq!(certificates[2].same_as, Some(0));
    assert_eq!(certificates[1].same_as, None);
}

#[test]
fn double_root_is_never_certified() {
    // (x − 1)² = x² − 2x + 1: the root 1 is singular (f'(1) = 0); Krawczyk proves the
    // Jacobian regular on its box, so it cannot hold, whatever the point and the tolerance.
    let (program, real) = univariate(&[c(1.0, 0.0), c(-2.0, 0.0), c(1.0, 0.0)]);
    let loose = CertifyOptions {
        tolerance: 0.5,
        ..CertifyOptions::default()
    };
    let exact = certify_root_with(&program, &[c(1.0, 0.0)], real, &loose).unwrap();
    assert_eq!(
        exact.status,
        CertificateStatus::Failed(FailureReason::Singular)
    );
    for point in [
        c(1.0 + 1e-8, 0.0),
        c(1.0 - 1e-5, 0.0),
        c(1.0, 1e-4),
        c(1.1, 0.0),
    ] {
        for options in [loose, CertifyOptions::default()] {
            let cert = certify_root_with(&program, &[point], real, &options).unwrap();
            assert!(!cert.is_certified(), "{point}: {:?}", cert.status);
            assert_eq!(cert.real, Reality::Unknown);
        }
    }
}

#[test]
fn circle_meets_line_at_known_points() {
    // x² + y² = 1 and x = y meet at ±(1/√2, 1/√2), checked by squaring the bounds exactly;
    // x = y + 2 (a line missing the circle) at x = 1 ± i/√2, y = −1 ± i/√2.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let circle = &x * &x + &y * &y - Poly::real(2, 1.0);
    let system = System::new(vec!["x".into(), "y".into()], vec![circle.clone(), &x - &y]).unwrap();
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let given = [vec![c(h, 0.0), c(h, 0.0)], vec![c(-h, 0.0), c(-h, 0.0)]];
    let certificates = certify_roots(&system.program(), &given, system.is_real()).unwrap();
    for (cert, sign) in certificates.iter().zip([1.0, -1.0]) {
        assert!(cert.is_certified() && cert.distinct);
        assert_eq!(cert.real, Reality::CertifiedReal);
        for e in &cert.enclosure {
            assert!(encloses_sqrt(e.re, 0.5, sign), "{e:?}");
            assert!(e.im.contains_zero());
        }
    }
    let line = &x - &y - Poly::real(2, 2.0);
    let system = System::new(vec!["x".into(), "y".into()], vec![circle, line]).unwrap();
    let given = [vec![c(1.0, h), c(-1.0, h)], vec![c(1.0, -h), c(-1.0, -h)]];
    let certificates = certify_roots(&system.program(), &given, system.is_real()).unwrap();
    for (cert, sign) in certificates.iter().zip([1.0, -1.0]) {
        assert!(cert.is_certified() && cert.distinct);
        assert_eq!(cert.real, Reality::CertifiedNonReal);
        assert!(cert.enclosure[0].re.contains(1.0) && cert.enclosure[1].re.contains(-1.0));
        for e in &cert.enclosure {
            assert!(encloses_sqrt(e.im, 0.5, sign), "{e:?}");
        }
    }
}

#[test]
fn complex_coefficients() {
    // (x − 1)(x − i) = x² − (1 + i)x + i and x·y = 2 + i: the roots (1, 2 + i) and
    // (i, (2 + i)/i = 1 − 2i), all floats.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let f1 = &x * &x - x.scale(c(1.0, 1.0)) + Poly::constant(2, c(0.0, 1.0));
    let f2 = &x * &y - Poly::constant(2, c(2.0, 1.0));
    let system = System::new(vec!["x".into(), "y".into()], vec![f1, f2]).unwrap();
    assert!(!system.is_real());
    let roots = [[c(1.0, 0.0), c(2.0, 1.0)], [c(0.0, 1.0), c(1.0, -2.0)]];
    let given: Vec<Vec<C64>> = roots
        .iter()
        .map(|r| r.iter().map(|z| z + c(3e-10, -2e-10)).collect())
        .collect();
    let certificates = certify_roots(&system.program(), &given, system.is_real()).unwrap();
    for (cert, root) in certificates.iter().zip(&roots) {
        assert!(cert.is_certified() && cert.distinct, "{:?}", cert.status);
        assert_eq!(cert.real, Reality::CertifiedNonReal);
        assert!(enclosure_holds(cert, root));
        assert!(uniqueness_box_holds(cert, root));
    }
    // A lie about the coefficients proves nothing false: x − (1 + 10⁻⁹ i) has the non-real
    // root 1 + 10⁻⁹ i, even when called "real".
    let (program, _) = univariate(&[c(-1.0, -1e-9), c(1.0, 0.0)]);
    let cert = certify_root(&program, &[c(1.0, 1e-9)], true).unwrap();
    assert!(cert.is_certified());
    assert_eq!(cert.real, Reality::CertifiedNonReal);
}

#[test]
fn three_variables_real_and_complex_roots() {
    // x² + y² = 5, xy = 2, z² = x: (x, y) ∈ {(1, 2), (2, 1), (−1, −2), (−2, −1)} (from
    // (x ± y)² = 5 ± 4), and z = ±√x: four real roots (z = ±1, ±√2) and four non-real
    // (z = ±i, ±i√2) — all 8 of Bézout's bound 2·2·2.
    let x = Poly::variable(3, 0);
    let y = Poly::variable(3, 1);
    let z = Poly::variable(3, 2);
    let system = System::new(
        vec!["x".into(), "y".into(), "z".into()],
        vec![
            &x * &x + &y * &y - Poly::real(3, 5.0),
            &x * &y - Poly::real(3, 2.0),
            &z * &z - &x,
        ],
    )
    .unwrap();
    assert_eq!(system.bezout_number(), 8);
    let mut given = Vec::new();
    let mut expected = Vec::new();
    for (xv, yv) in [(1.0, 2.0), (2.0, 1.0), (-1.0, -2.0), (-2.0, -1.0)] {
        for sign in [1.0, -1.0] {
            let zv: f64 = sign * f64::abs(xv).sqrt();
            let zc = if xv > 0.0 { c(zv, 0.0) } else { c(0.0, zv) };
            given.push(vec![c(xv + 1e-10, 0.0), c(yv, -1e-10), zc + c(2e-10, 0.0)]);
            expected.push((xv, yv, sign));
        }
    }
    let certificates = certify_roots(&system.program(), &given, system.is_real()).unwrap();
    for (cert, (xv, yv, sign)) in certificates.iter().zip(expected) {
        assert!(cert.is_certified() && cert.distinct, "{:?}", cert.status);
        assert!(cert.enclosure[0].contains(c(xv, 0.0)));
        assert!(cert.enclosure[1].contains(c(yv, 0.0)));
        let ez = cert.enclosure[2];
        if xv > 0.0 {
            assert_eq!(cert.real, Reality::CertifiedReal);
            assert!(encloses_sqrt(ez.re, xv, sign) && ez.im.contains_zero());
        } else {
            assert_eq!(cert.real, Reality::CertifiedNonReal);
            assert!(encloses_sqrt(ez.im, -xv, sign) && ez.re.contains_zero());
        }
    }
}

#[test]
fn a_hundred_and_twenty_eight_roots() {
    // f_i = (l_i(x) − a_i)(l_i(x) − b_i), l_i the rows of an integer matrix A: the roots are
    // A⁻¹c for the 2⁷ choices c_i ∈ {a_i, b_i}, all regular and distinct (A invertible), as
    // many as Bézout's bound.
    let n = 7;
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let (a_matrix, inverse) = loop {
        let m = nalgebra::DMatrix::<f64>::from_fn(n, n, |_, _| f64::from(rng.random_range(-3..=3)));
        if let Some(inv) = m.clone().try_inverse()
            && m.determinant().abs() > 1.0
        {
            break (m, inv);
        }
    };
    let choices: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            (
                f64::from(i32::try_from(i).unwrap()) + 1.0,
                -0.5 - f64::from(i32::try_from(i).unwrap()),
            )
        })
        .collect();
    let vars: Vec<Poly> = (0..n).map(|i| Poly::variable(n, i)).collect();
    let equations: Vec<Poly> = (0..n)
        .map(|i| {
            let l = (0..n).fold(Poly::zero(n), |acc, j| {
                acc + vars[j].clone() * a_matrix[(i, j)]
            });
            (&l - Poly::real(n, choices[i].0)) * (&l - Poly::real(n, choices[i].1))
        })
        .collect();
    let system = System::new((0..n).map(|i| format!("x{i}")).collect(), equations).unwrap();
    assert_eq!(system.bezout_number(), 128);
    let program = system.program();
    let mut roots: Vec<Vec<C64>> = (0..128u32)
        .map(|mask| {
            let rhs = nalgebra::DVector::from_fn(n, |i, _| {
                if mask & (1 << i) == 0 {
                    choices[i].0
                } else {
                    choices[i].1
                }
            });
            (&inverse * rhs).iter().map(|v| c(*v, 0.0)).collect()
        })
        .collect();
    let start = std::time::Instant::now();
    let certificates = certify_roots(&program, &roots, true).unwrap();
    eprintln!("128 roots of 7 quadrics certified in {:?}", start.elapsed());
    for cert in &certificates {
        assert!(cert.is_certified() && cert.distinct, "{:?}", cert.status);
        assert_eq!(cert.real, Reality::CertifiedReal);
    }
    // A path that jumped: root 5 found again in place of root 9.
    roots[9] = roots[5].clone();
    let certificates = certify_roots(&program, &roots, true).unwrap();
    for (k, cert) in certificates.iter().enumerate() {
        assert!(cert.is_certified());
        assert_eq!(cert.distinct, k != 5 && k != 9, "root {k}");
    }
    assert_eq!(certificates[9].same_as, Some(5));
}

#[test]
fn bad_input_is_an_error() {
    let x = Poly::variable(1, 0);
    let system = System::new(vec!["x".into()], vec![x.clone(), &x * &x]).unwrap();
    assert_eq!(
        certify_roots(&system.program(), &[vec![c(0.0, 0.0)]], true),
        Err(CertifyError::NotSquare {
            equations: 2,
            variables: 1
        })
    );
    let (program, real) = cubic();
    let err = certify_roots(&program, &[vec![c(1.0, 0.0)], vec![]], real).unwrap_err();
    assert_eq!(
        err,
        CertifyError::RootLength {
            root: 1,
            expected: 1,
            found: 0
        }
    );
    assert_eq!(
        err.to_string(),
        "root 1 has 0 coordinates, the system has 1 variables"
    );
}
