//! Homotopy continuation against known root counts, each cited, and against independent
//! methods (companion-matrix eigenvalues); the weights of paths and the estimates and limits of
//! their numbers, by hand; over-determined systems randomised to square ones; and (`nearby`) the index that finds the points near a given one.

use kinsyn_nag::homotopy::{
    DecomposeError, DecomposeSettings, HomotopyError, SolveSettings, StartSystem, decompose,
    decompose_paths, path_weight, regeneration_paths, solve, solve_overdetermined,
    square_randomisation,
};
use kinsyn_nag::poly::families::{cyclic, katsura};
use kinsyn_nag::poly::{C64, Poly, System};

fn names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("x{i}")).collect()
}

#[test]
fn katsura_counts() {
    for n in [3, 4, 5] {
        let report = solve(&katsura(n), &SolveSettings::default()).unwrap();
        eprintln!("katsura-{n}: {} ({:.3}s)", report.summary(), report.seconds);
        assert_eq!(
            report.nonsingular(),
            1 << n,
            "Katsura-{n} has 2^{n} solutions"
        );
    }
}

#[test]
fn cyclic5_count() {
    let report = solve(&cyclic(5), &SolveSettings::default()).unwrap();
    eprintln!(
        "cyclic-5: {} ({:.3}s) retracked {}",
        report.summary(),
        report.seconds,
        report.retracked
    );
    assert_eq!(
        report.nonsingular(),
        70,
        "cyclic-5 has 70 solutions (Björck & Fröberg 1991)"
    );
    assert_eq!(report.at_infinity(), 50, "Bézout 120 − 70");
}

#[test]
fn univariate_against_companion_eigenvalues() {
    // p(x) = x^5 − 3x^4 + (2 + i) x^2 − 7x + 0.5: the roots are the eigenvalues of the
    // companion matrix, computed by nalgebra's Schur decomposition, an independent method.
    let coefficients = [
        C64::new(0.5, 0.0),
        C64::new(-7.0, 0.0),
        C64::new(2.0, 1.0),
        C64::new(0.0, 0.0),
        C64::new(-3.0, 0.0),
    ];
    let x = Poly::variable(1, 0);
    let mut p = x.pow(5);
    for (k, c) in (0u32..).zip(&coefficients) {
        p = p + x.pow(k).scale(*c);
    }
    let report = solve(
        &System::new(names(1), vec![p]).unwrap(),
        &SolveSettings::default(),
    )
    .unwrap();
    assert_eq!(report.nonsingular(), 5);
    let mut companion = nalgebra::DMatrix::<C64>::zeros(5, 5);
    for k in 0..5 {
        companion[(k, 4)] = -coefficients[k];
        if k > 0 {
            companion[(k, k - 1)] = C64::new(1.0, 0.0);
        }
    }
    let eigenvalues = companion
        .eigenvalues()
        .expect("a complex Schur form is triangular");
    for e in eigenvalues.iter() {
        let nearest = report
            .solutions
            .iter()
            .map(|s| (s.x[0] - e).norm())
            .fold(f64::INFINITY, f64::min);
        assert!(nearest < 1e-9, "eigenvalue {e} found to {nearest:e}");
    }
}

#[test]
fn singular_endpoint_multiplicity() {
    // (x − 1)^3 (x + 2) = 0: a triple root reached by three paths with winding number 3
    // (the Puiseux series of a triple root has cycle number 3 for a generic start).
    let x = Poly::variable(1, 0);
    let p = (&x - &Poly::real(1, 1.0)).pow(3) * (&x + &Poly::real(1, 2.0));
    let report = solve(
        &System::new(names(1), vec![p]).unwrap(),
        &SolveSettings::default(),
    )
    .unwrap();
    assert_eq!(report.nonsingular(), 1);
    assert_eq!(report.singular(), 1);
    let triple = report.solutions.iter().find(|s| !s.regular).unwrap();
    assert_eq!(triple.multiplicity, 3);
    assert!(
        (triple.x[0] - C64::new(1.0, 0.0)).norm() < 1e-6,
        "{:?}",
        triple.x
    );
}

#[test]
fn multihomogeneous_start_counts() {
    // Two bilinear equations in groups {x}, {y}: 2 paths instead of Bézout's 4, and both
    // solutions: x y = 1, x y + 3x = 2 → x = 1/3, y = 3.  Single solution? x y = 1 and 3x = 1.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let f1 = &x * &y - Poly::real(2, 1.0);
    let f2 = &(&x * &y) + &(x.clone() * 3.0) + &(y.clone() * 2.0) - Poly::real(2, 2.0);
    let system = System::new(names(2), vec![f1, f2])
        .unwrap()
        .with_groups(vec![vec![0], vec![1]])
        .unwrap();
    let settings = SolveSettings {
        start: StartSystem::MultiHomogeneous,
        ..SolveSettings::default()
    };
    let report = solve(&system, &settings).unwrap();
    assert_eq!(report.paths(), 2);
    // 1 + 3x + 2y = 2 with y = 1/x: 3x^2 − x + 2 = 0 → two complex roots.
    assert_eq!(report.nonsingular(), 2);
    for s in &report.solutions {
        let x = s.x[0];
        assert!((x * x * 3.0 - x + 2.0).norm() < 1e-10);
    }
}

/// A random "two legs" system in groups `X = {x0, x1, x2}`, `{t1}`, `{t2}`: two equations of
/// degree (1, 1) in `(X, t_i)` for each `i` and one dense hyperplane. Hand count of the
/// linear-product start: the two equations of one `t_i` cannot both take its one slot, so each
/// pair takes `{X}{X}`, `{X}{t}` or `{t}{X}` (3 ways), and at least one `t` slot must be taken
/// (four `X` slots exceed three variables): `3² − 1 = 8` paths, where the total degree tracks
/// 16. Every root the total degree finds, the linear-product start finds too (same roots to
/// 1e-8), and no more.
#[test]
fn linear_product_start_finds_the_total_degree_roots_with_fewer_paths() {
    let n = 5;
    let v = |i| Poly::variable(n, i);
    let mut k = 0.0f64;
    let mut c = || {
        k += 1.0;
        C64::new((k * 1.618).sin(), (k * 2.5).cos())
    };
    let affine = |vars: &[usize], c: &mut dyn FnMut() -> C64| {
        vars.iter()
            .fold(Poly::constant(n, c()), |p, i| &p + &v(*i).scale(c()))
    };
    let mut equations = Vec::new();
    for t in [3, 4] {
        for _ in 0..2 {
            let a = affine(&[0, 1, 2], &mut c);
            let b = affine(&[0, 1, 2], &mut c);
            equations.push(&(&a * &v(t)) + &b);
        }
    }
    equations.push(affine(&[0, 1, 2, 3, 4], &mut c));
    let system = System::new(names(n), equations)
        .unwrap()
        .with_groups(vec![vec![0, 1, 2], vec![3], vec![4]])
        .unwrap();
    let solve_with = |start| {
        solve(
            &system,
            &SolveSettings {
                start,
                ..SolveSettings::default()
            },
        )
        .unwrap()
    };
    let total = solve_with(StartSystem::TotalDegree);
    let product = solve_with(StartSystem::LinearProduct);
    assert_eq!((total.paths(), product.paths()), (16, 8));
    assert!(total.complete() && product.complete());
    let roots = |r: &kinsyn_nag::homotopy::SolveReport| -> Vec<Vec<C64>> {
        r.solutions
            .iter()
            .filter(|s| s.regular)
            .map(|s| s.x.clone())
            .collect()
    };
    let (a, b) = (roots(&total), roots(&product));
    assert_eq!(a.len(), b.len());
    assert!(
        a.len() >= 6,
        "a generic system of this structure has several roots"
    );
    for x in &a {
        assert!(
            b.iter()
                .any(|y| kinsyn_nag::homotopy::relative_distance(x, y) < 1e-8),
            "a root of the total degree missing from the linear-product solve"
        );
    }
}

/// The family `f_i = x_i² + Σ_j a_ij x_j + b_i` (`i = 1 … 3`), parameters `a` (9) and `b` (3)
/// after the unknowns: generic members have Bézout's 2³ = 8 solutions.
fn quadrics_family() -> kinsyn_nag::homotopy::ParametrizedSystem {
    let n = 3;
    let nv = n + n * n + n;
    let mut eqs = Vec::new();
    for i in 0..n {
        let xi = Poly::variable(nv, i);
        let mut f = &xi * &xi + Poly::variable(nv, n + n * n + i);
        for j in 0..n {
            f = f + Poly::variable(nv, n + n * i + j) * Poly::variable(nv, j);
        }
        eqs.push(f);
    }
    let names: Vec<String> = (0..nv).map(|i| format!("v{i}")).collect();
    kinsyn_nag::homotopy::ParametrizedSystem::new(System::new(names, eqs).unwrap(), n * n + n)
        .unwrap()
}

#[test]
fn monodromy_fills_a_generic_family_from_one_solution() {
    // Build a start pair: pick x* and a, then b_i = −(x_i*² + Σ a_ij x_j*), so x* solves the
    // member at p = (a, b). Monodromy must find all 8 solutions, which a total-degree solve of
    // the same member confirms (an independent method).
    let family = quadrics_family();
    let x: Vec<C64> = vec![C64::new(0.3, -0.2), C64::new(-1.1, 0.4), C64::new(0.7, 0.9)];
    let a: Vec<C64> = (0..9)
        .map(|k| C64::new((f64::from(k) * 0.77).sin(), (f64::from(k) * 1.3).cos()))
        .collect();
    let b: Vec<C64> = (0..3)
        .map(|i| -(x[i] * x[i] + (0..3).map(|j| a[3 * i + j] * x[j]).sum::<C64>()))
        .collect();
    let p: Vec<C64> = a.iter().chain(&b).copied().collect();
    let report = kinsyn_nag::homotopy::monodromy_solve(
        &family,
        &p,
        &x,
        &kinsyn_nag::homotopy::MonodromySettings::default(),
    )
    .unwrap();
    assert_eq!(report.solutions.len(), 8, "after {} loops", report.loops);
    let direct = solve(&family.at(&p).unwrap(), &SolveSettings::default()).unwrap();
    assert_eq!(direct.nonsingular(), 8);
    for s in &report.solutions {
        assert!(
            direct
                .solutions
                .iter()
                .any(|d| d.x.iter().zip(s).all(|(u, v)| (u - v).norm() < 1e-8))
        );
    }
    // With the count known, monodromy stops as soon as it has them.
    let settings = kinsyn_nag::homotopy::MonodromySettings {
        target: Some(8),
        ..Default::default()
    };
    assert_eq!(
        kinsyn_nag::homotopy::monodromy_solve(&family, &p, &x, &settings)
            .unwrap()
            .solutions
            .len(),
        8
    );

    // Parameter homotopy: all 8 followed to a real member equal its total-degree solutions.
    let q: Vec<C64> = (0..12)
        .map(|k| C64::new((f64::from(k * k) * 0.31).cos() * 2.0, 0.0))
        .collect();
    let moved = kinsyn_nag::homotopy::track_parameters(
        &family,
        &p,
        &q,
        &report.solutions,
        kinsyn_nag::homotopy::TrackerSettings::default(),
    )
    .unwrap();
    let direct = solve(&family.at(&q).unwrap(), &SolveSettings::default()).unwrap();
    assert_eq!(direct.nonsingular(), 8);
    for m in &moved {
        let m = m
            .as_ref()
            .expect("the segment from a generic complex member meets no singularity");
        assert!(
            direct
                .solutions
                .iter()
                .any(|d| d.x.iter().zip(m).all(|(u, v)| (u - v).norm() < 1e-8))
        );
    }
}

#[test]
fn cyclic6_count_without_failed_paths() {
    // Cyclic-6 has 156 solutions (Björck & Fröberg 1991), all regular; 564 of its 720 paths
    // go to positive-dimensional sets at infinity, where the endgame's descent stalls: such a
    // path beyond 10⁵ is declared at infinity (Bertini's finite threshold), not failed.
    let report = solve(&cyclic(6), &SolveSettings::default()).unwrap();
    assert_eq!(report.nonsingular(), 156, "{}", report.summary());
    assert_eq!(report.certified(), 156);
    assert_eq!(report.failed(), 0, "{}", report.summary());
}

// `src/homotopy/mod.rs`: the weight of a path, the estimates of the decompositions and the
// limit on the paths, by hand.

/// `⌈n³ / 12³⌉`, by hand: 12³ = 1728; 13³ = 2197 (2), 16³ = 4096 (3), 32³ = 32768 (19),
/// 100³ = 10⁶ (579).
#[test]
fn path_weights_by_hand() {
    for (n, w) in [(1, 1), (12, 1), (13, 2), (16, 3), (32, 19), (100, 579)] {
        assert_eq!(path_weight(n), w, "{n} unknowns");
    }
}

/// The estimates of the decompositions from the degrees, by hand. Four cubics in three
/// unknowns (the twisted cubic and a line): by dimension 3 + 9 + 27 = 39, by regeneration
/// 2 (3 + 9 + 27 + 81) = 240. Two equations of degrees 2 and 1 in two unknowns (exactly
/// N − 0 at dimension 0: the product 2, and 2 at dimension 1): 4; regeneration
/// 2 (1 + 2) = 6.
#[test]
fn decomposition_estimates_by_hand() {
    let v = |i| Poly::variable(3, i);
    let cubic = |a: Poly, b: Poly| a * b;
    let (x, y, z) = (v(0), v(1), v(2));
    let one = Poly::real(3, 1.0);
    let q1 = &y - &(&x * &x);
    let q2 = &z - &(&x * &y);
    let l1 = &x - &one;
    let l2 = &y - &(one.clone() * 2.0);
    let system = System::new(
        vec!["x".into(), "y".into(), "z".into()],
        vec![
            cubic(q1.clone(), l1.clone()),
            cubic(q1, l2.clone()),
            cubic(q2.clone(), l1),
            cubic(q2, l2),
        ],
    )
    .unwrap();
    assert_eq!(system.degrees(), vec![3, 3, 3, 3]);
    assert_eq!(decompose_paths(&system), 39);
    assert_eq!(regeneration_paths(&system), 240);
    let a = Poly::variable(2, 0);
    let b = Poly::variable(2, 1);
    let small = System::new(vec!["a".into(), "b".into()], vec![&a * &a - &b, &a - &b]).unwrap();
    assert_eq!(decompose_paths(&small), 2 + 2);
    assert_eq!(regeneration_paths(&small), 6);
}

/// The limit is checked before any tracking: a solve of `x² = 1` with `max_paths` 1 is
/// refused, with 2 it runs; a decomposition whose estimate fits but whose tracking
/// (monodromy, trace test) goes beyond the limit stops with the count it reached.
#[test]
fn limits_hold_before_and_during_the_work() {
    let x = Poly::variable(1, 0);
    let square = System::new(vec!["x".into()], vec![&x * &x - Poly::real(1, 1.0)]).unwrap();
    let tight = SolveSettings {
        max_paths: 1,
        ..SolveSettings::default()
    };
    assert_eq!(
        solve(&square, &tight).unwrap_err(),
        HomotopyError::TooManyPaths {
            paths: 2,
            weight: 1,
            limit: 1
        }
    );
    let report = solve(
        &square,
        &SolveSettings {
            max_paths: 2,
            ..tight
        },
    )
    .unwrap();
    assert_eq!(report.nonsingular(), 2);
    // A circle in the plane: one quadric in two unknowns, estimated at 2 start paths by
    // dimension (dimension 1); its two witness points then need 4 paths for the trace test.
    let (a, b) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let circle = System::new(
        vec!["a".into(), "b".into()],
        vec![&a * &a + &b * &b - Poly::real(2, 1.0)],
    )
    .unwrap();
    assert_eq!(decompose_paths(&circle), 2);
    let settings = DecomposeSettings {
        max_paths: 2,
        ..DecomposeSettings::default()
    };
    match decompose(&circle, &settings) {
        Err(DecomposeError::PathLimit { tracked, limit, .. }) => {
            assert_eq!((tracked, limit), (2, 2));
        }
        other => panic!("{other:?}"),
    }
    let d = decompose(
        &circle,
        &DecomposeSettings {
            max_paths: 100,
            ..settings
        },
    )
    .unwrap();
    assert_eq!(d.signature(), vec![(1, 2)]);
    assert_eq!(d.estimated_paths, 2);
}

/// `src/homotopy/nearby.rs`: the index of points sorted along a generic linear form finds every
/// near point that the full scan finds.
mod nearby {
    use kinsyn_nag::homotopy::nearby::{NearPoints, ordered};
    use kinsyn_nag::homotopy::relative_distance;
    use kinsyn_nag::poly::C64;

    /// The keys order the doubles as `<` does.
    #[test]
    fn keys_keep_the_order_of_doubles() {
        let xs = [-1e300, -2.5, -1e-300, -0.0, 0.0, 1e-300, 3.0, 1e300];
        for w in xs.windows(2) {
            assert!(ordered(w[0]) <= ordered(w[1]), "{w:?}");
        }
    }

    /// On points of a lattice and their copies moved by less than the tolerance, the window
    /// gives every point that the full scan finds within the tolerance (both ways).
    #[test]
    fn the_candidates_hold_every_near_point() {
        let mut points: Vec<Vec<C64>> = Vec::new();
        for i in 0..12 {
            for j in 0..12 {
                let p = vec![
                    C64::new(f64::from(i), -1.0),
                    C64::new(0.5, f64::from(j) * 1e-6),
                ];
                points.push(p);
            }
        }
        let mut index = NearPoints::default();
        for (k, p) in points.iter().enumerate() {
            index.insert(k, p);
        }
        for tolerance in [1e-6, 1e-4, 0.3] {
            for q in &points {
                let found = index.candidates(q, tolerance);
                for (k, p) in points.iter().enumerate() {
                    if relative_distance(p, q) <= tolerance || relative_distance(q, p) <= tolerance
                    {
                        assert!(found.contains(&k), "{q:?} ~ {p:?} at {tolerance}");
                    }
                }
            }
        }
    }
}

// ---- over-determined systems: randomisation to a square system ----

/// By hand: `x² − 1`, `y − x`, `y² − 1` in `(x, y)` have the two solutions `±(1, 1)`. The square
/// randomisation keeps the two quadrics, each plus a random multiple of `y − x`: four finite
/// solutions (Bézout 4, none at infinity, where `x² = y² = 0`), of which the two on `y = x` are
/// the system's and the other two (`y ≠ x`) are refused by the original equations.
#[test]
fn an_over_determined_system_keeps_the_solutions_that_satisfy_every_equation() {
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let one = Poly::real(2, 1.0);
    let system = System::new(
        vec!["x".into(), "y".into()],
        vec![&(&x * &x) - &one, &y - &x, &(&y * &y) - &one],
    )
    .unwrap();
    let square = square_randomisation(&system, 7).unwrap();
    assert_eq!(square.degrees(), [2, 2]);
    assert!(
        square.is_real(),
        "real random combinations keep a real system real"
    );
    for seed in 1..=5 {
        let settings = SolveSettings {
            seed,
            ..SolveSettings::default()
        };
        let o = solve_overdetermined(&system, &settings).unwrap();
        assert_eq!(o.report.paths(), 4);
        assert_eq!(o.report.nonsingular(), 4, "seed {seed}");
        assert_eq!(o.spurious(), 2, "seed {seed}");
        let mut found: Vec<f64> = o
            .solutions()
            .map(|s| {
                assert!(s.real && s.is_certified(), "seed {seed}");
                assert!((s.x[0] - s.x[1]).norm() < 1e-12);
                s.x[0].re
            })
            .collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found.len(), 2);
        assert!((found[0] + 1.0).abs() < 1e-12 && (found[1] - 1.0).abs() < 1e-12);
    }
    // A square system is solved as it is; an under-determined one has no isolated solutions.
    let circle = System::new(
        vec!["x".into(), "y".into()],
        vec![&(&x * &x) - &one, &y - &x],
    )
    .unwrap();
    assert_eq!(square_randomisation(&circle, 1).unwrap(), circle);
    let under = System::new(vec!["x".into(), "y".into()], vec![&y - &x]).unwrap();
    assert!(matches!(
        square_randomisation(&under, 1),
        Err(HomotopyError::NotSquare { .. })
    ));
}

/// A solve split into shards and merged is the one-process solve, path for path: every end
/// (kind, endpoint bits, winding, steps, re-tracking) and every solution, for a total-degree
/// start (Katsura-5) and a polyhedral one (cyclic-5, chosen by auto), in 1, 3 and 7 shards
/// given in any order; shards that do not make one solve are refused.
#[test]
fn shards_merged_are_the_one_process_solve() {
    use kinsyn_nag::homotopy::{Shard, merge_shards, solve_shard};
    use kinsyn_nag::poly::families;
    for (system, start) in [
        (families::katsura(5), StartSystem::TotalDegree),
        (families::cyclic(5), StartSystem::Auto),
    ] {
        let settings = SolveSettings {
            seed: 7,
            start,
            ..SolveSettings::default()
        };
        let one = solve(&system, &settings).unwrap();
        for count in [1, 3, 7] {
            let mut parts: Vec<_> = (1..=count)
                .map(|k| {
                    solve_shard(&system, &settings, Shard::new(k, count).unwrap(), &|| {}).unwrap()
                })
                .collect();
            parts.reverse();
            assert_eq!(
                parts.iter().map(|p| p.ends.len()).sum::<usize>(),
                one.ends.len()
            );
            let merged = merge_shards(&system, &settings, &parts).unwrap();
            assert_eq!(merged.start, one.start);
            assert_eq!(merged.ends, one.ends, "{count} shards");
            assert_eq!(merged.solutions, one.solutions, "{count} shards");
            assert_eq!(merged.retracked, one.retracked);
        }
        let parts: Vec<_> = (1..=3)
            .map(|k| solve_shard(&system, &settings, Shard::new(k, 3).unwrap(), &|| {}).unwrap())
            .collect();
        let missing = merge_shards(&system, &settings, &parts[..2]).unwrap_err();
        assert!(
            missing.to_string().contains("missing shard 3/3"),
            "{missing}"
        );
        let twice = [parts[0].clone(), parts[0].clone(), parts[1].clone()];
        assert!(merge_shards(&system, &settings, &twice).is_err());
        let other_seed = SolveSettings {
            seed: 8,
            ..settings.clone()
        };
        assert!(merge_shards(&system, &other_seed, &parts).is_err());
    }
    assert!(Shard::new(0, 3).is_none() && Shard::new(4, 3).is_none());
}
