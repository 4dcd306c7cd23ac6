//! Numerical irreducible decomposition (Sommese, Verschelde & Wampler, SIAM J. Numer. Anal. 38,
//! 2001; Sommese & Wampler 2005, ch. 13–15) on solution sets whose components are known by
//! hand: each expected `(dimension, degree)` is derived in the test's comment. Both algorithms
//! run on every system — witness supersets by dimension (`decompose`) and equation-by-equation
//! regeneration (`regenerate`, Hauenstein, Sommese & Wampler 2011) — and must agree.

use kinsyn_nag::homotopy::{DecomposeSettings, Decomposition, decompose, regenerate};
use kinsyn_nag::poly::{Poly, System};

fn xyz() -> (Poly, Poly, Poly) {
    (
        Poly::variable(3, 0),
        Poly::variable(3, 1),
        Poly::variable(3, 2),
    )
}

fn system(equations: Vec<Poly>) -> System {
    System::new(vec!["x".into(), "y".into(), "z".into()], equations).unwrap()
}

fn c(v: f64) -> Poly {
    Poly::real(3, v)
}

/// The decomposition by dimension, checked against regeneration (same components, both with
/// the trace test passed and witness points on the solution set).
fn run(s: &System, seed: u64) -> Decomposition {
    let settings = DecomposeSettings {
        seed,
        ..DecomposeSettings::default()
    };
    let d = decompose(s, &settings).unwrap();
    let r = regenerate(s, &settings).unwrap();
    for (name, d) in [("by dimension", &d), ("regeneration", &r)] {
        eprintln!(
            "{name}, seed {seed}: {:?} junk {} unresolved {} paths {} in {:.3} s",
            d.signature(),
            d.junk,
            d.unresolved.len(),
            d.paths,
            d.seconds
        );
        for comp in &d.components {
            assert!(comp.trace_test_passed, "{name}: {comp:?}");
            for p in &comp.witness_points {
                assert!(s.evaluate(p).iter().all(|v| v.norm() < 1e-7), "{name}");
            }
        }
    }
    assert_eq!(
        r.signature(),
        d.signature(),
        "the two algorithms, seed {seed}"
    );
    d
}

/// The twisted cubic `(t, t², t³) = V(y − x², z − xy)` (degree 3: `a + bt + ct² + dt³ = 0`
/// has three roots) and the line `x = 1, y = 2` (degree 1, disjoint from the cubic since
/// `x = 1` forces `y = 1` on it); the union is cut out by the four products of generators
/// (Sommese & Wampler 2005, §13's twisted cubic example, with a line added).
fn twisted_cubic_and_line() -> System {
    let (x, y, z) = xyz();
    let g = [&y - &(&x * &x), &z - &(&x * &y)];
    let h = [&x - &c(1.0), &y - &c(2.0)];
    system(
        g.iter()
            .flat_map(|a| h.iter().map(move |b| a * b))
            .collect(),
    )
}

#[test]
fn twisted_cubic_and_a_line() {
    let d = run(&twisted_cubic_and_line(), 1);
    assert_eq!(d.signature(), vec![(1, 3), (1, 1)]);
    assert!(d.unresolved.is_empty());
}

/// `z(x − 1) = z(y − 1) = z(z − 1) = 0`: either `z = 0` (the plane, dimension 2, degree 1) or
/// `x = y = z = 1` (an isolated point, regular: the Jacobian there is the identity).
#[test]
fn plane_and_point() {
    let (x, y, z) = xyz();
    let s = system(vec![
        &z * &(&x - &c(1.0)),
        &z * &(&y - &c(1.0)),
        &z * &(&z - &c(1.0)),
    ]);
    let d = run(&s, 1);
    assert_eq!(d.signature(), vec![(2, 1), (0, 1)]);
    let point = &d
        .components
        .iter()
        .find(|c| c.dimension == 0)
        .unwrap()
        .sample_point;
    assert!(point.iter().all(|v| (v - 1.0).norm() < 1e-8), "{point:?}");
    assert!(d.unresolved.is_empty());
}

/// `S (x − 2) = S y = 0` with `S` the unit sphere: the sphere (dimension 2, degree 2) and the
/// line `x = 2, y = 0` (dimension 1, degree 1; it meets the sphere at `z = ±i√3`, which generic
/// slices avoid). Points of the sphere on the curve slice are junk for the membership test.
#[test]
fn sphere_and_line() {
    let (x, y, z) = xyz();
    let sphere = &(&(&x * &x) + &(&y * &y)) + &(&(&z * &z) - &c(1.0));
    let s = system(vec![&sphere * &(&x - &c(2.0)), &sphere * &y]);
    let d = run(&s, 1);
    assert_eq!(d.signature(), vec![(2, 2), (1, 1)]);
    assert!(d.unresolved.is_empty());
}

/// Viviani's curve: the sphere `x² + y² + z² = 4` met by the cylinder `(x − 1)² + y² = 1`, a
/// complete intersection of two quadrics (degree 2·2 = 4) and irreducible, being the image of
/// `θ ↦ (1 + cos θ, sin θ, 2 sin(θ/2))`: one component of dimension 1 and degree 4 that the
/// trace test must not split.
#[test]
fn viviani_curve_is_one_quartic() {
    let (x, y, z) = xyz();
    let sphere = &(&(&x * &x) + &(&y * &y)) + &(&(&z * &z) - &c(4.0));
    let xm = &x - &c(1.0);
    let cylinder = &(&(&xm * &xm) + &(&y * &y)) - &c(1.0);
    let d = run(&system(vec![sphere, cylinder]), 1);
    assert_eq!(d.signature(), vec![(1, 4)]);
}

/// The decomposition does not depend on the random choices: four seeds, the same components.
#[test]
fn seed_stability() {
    let s = twisted_cubic_and_line();
    for seed in [2, 3, 4, 5] {
        assert_eq!(
            run(&s, seed).signature(),
            vec![(1, 3), (1, 1)],
            "seed {seed}"
        );
    }
}

/// The trace test alone, without monodromy loops: every witness point starts as its own piece
/// and the pieces are merged only where the traces' nonlinear parts cancel, which must rebuild
/// the cubic (3 points) and the line (1 point) of [`twisted_cubic_and_line`] and the single
/// quartic of Viviani's curve.
#[test]
fn trace_test_alone_groups_the_points() {
    let settings = DecomposeSettings {
        max_loops: 0,
        ..DecomposeSettings::default()
    };
    let d = decompose(&twisted_cubic_and_line(), &settings).unwrap();
    assert_eq!(d.signature(), vec![(1, 3), (1, 1)]);
    assert!(d.components.iter().all(|c| c.trace_test_passed));
    let (x, y, z) = xyz();
    let sphere = &(&(&x * &x) + &(&y * &y)) + &(&(&z * &z) - &c(4.0));
    let xm = &x - &c(1.0);
    let cylinder = &(&(&xm * &xm) + &(&y * &y)) - &c(1.0);
    let d = decompose(&system(vec![sphere, cylinder]), &settings).unwrap();
    assert_eq!(d.signature(), vec![(1, 4)]);
}

/// `x² = y = 0`: the z-axis counted twice, a non-reduced line. Its witness point is a singular
/// endpoint that no larger component contains; deflation makes it a regular point of
/// `[F; J B λ; h·λ − 1]`, and the line is reported with multiplicity 2 by both methods (by
/// dimension: the two paths that end there; regeneration brings in y first, then x² = 0 on the
/// plane y = 0: two paths to the same point).
#[test]
fn non_reduced_line_by_deflation() {
    let (x, y, _) = xyz();
    let s = system(vec![&x * &x, y]);
    for d in [
        decompose(&s, &DecomposeSettings::default()).unwrap(),
        regenerate(&s, &DecomposeSettings::default()).unwrap(),
    ] {
        assert!(d.unresolved.is_empty(), "{:?}", d.unresolved);
        assert_eq!(d.signature(), vec![(1, 1)]);
        let line = &d.components[0];
        assert_eq!(line.multiplicity, 2);
        assert!(line.trace_test_passed);
        let p = &line.witness_points[0];
        assert!(p[0].norm() < 1e-6 && p[1].norm() < 1e-8, "{p:?}");
    }
}

/// Bad input is an error, not a panic.
#[test]
fn zero_equation_is_refused() {
    let (x, _, _) = xyz();
    let s = system(vec![x, Poly::zero(3)]);
    assert!(decompose(&s, &DecomposeSettings::default()).is_err());
    assert!(regenerate(&s, &DecomposeSettings::default()).is_err());
}

/// A component's `(dimension, degree, multiplicity)`.
type Signature = (usize, usize, usize);

/// The components of `equations` (in x, y, z) by dimension: `(dimension, degree,
/// multiplicity)`, sorted, with nothing left unresolved.
fn with_multiplicities(equations: Vec<Poly>, seed: u64) -> Vec<Signature> {
    let d = decompose(
        &system(equations),
        &DecomposeSettings {
            seed,
            ..DecomposeSettings::default()
        },
    )
    .unwrap();
    assert!(d.unresolved.is_empty(), "unresolved: {:?}", d.unresolved);
    assert!(d.components.iter().all(|c| c.trace_test_passed), "{d:?}");
    let mut found: Vec<Signature> = d
        .components
        .iter()
        .map(|c| (c.dimension, c.degree, c.multiplicity))
        .collect();
    found.sort_unstable();
    found
}

/// Non-reduced components by deflation, each against its hand count (Sommese & Wampler 2005,
/// §13.3 and ch. 15 on multiplicity): `V(x², y)` is the z-axis counted twice; `V((y − x²)²,
/// z − xy)` the twisted cubic (degree 3) twice; `x (y − 1)²` the plane `x = 0` once and the
/// plane `y = 1` twice; `(x², y − 1, z)`'s point twice. Before deflation each was left
/// unresolved. Three seeds each.
#[test]
fn non_reduced_components_by_deflation() {
    let v = |i| Poly::variable(3, i);
    let one = Poly::real(3, 1.0);
    let cubic = &v(1) - &(&v(0) * &v(0));
    let cases: Vec<(&str, Vec<Poly>, Vec<Signature>)> = vec![
        ("double line", vec![&v(0) * &v(0), v(1)], vec![(1, 1, 2)]),
        (
            "double twisted cubic",
            vec![&cubic * &cubic, &v(2) - &(&v(0) * &v(1))],
            vec![(1, 3, 2)],
        ),
        (
            "a plane and a double plane",
            vec![&v(0) * &(&(&v(1) - &one) * &(&v(1) - &one))],
            vec![(2, 1, 1), (2, 1, 2)],
        ),
        (
            "a double point",
            vec![&v(0) * &v(0), &v(1) - &one, v(2)],
            vec![(0, 1, 2)],
        ),
    ];
    for (name, equations, expected) in cases {
        for seed in 1..=3 {
            assert_eq!(
                with_multiplicities(equations.clone(), seed),
                expected,
                "{name}, seed {seed}"
            );
        }
    }
}
