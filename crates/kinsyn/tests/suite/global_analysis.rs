//! Global analysis of descriptions through the general path — the constraint system of
//! [`Manipulator::constraint_system`] solved by [`solve_overdetermined`], as
//! `analyze --all-assemblies` does — on mechanisms written here: assembly counts from the
//! literature (each cited), the real assemblies of planar ones against an independent
//! one-dimensional scan, the same counts in another length unit and for other solver seeds.

use kinsyn::geometry::Chart;
use kinsyn::homotopy::{SolveSettings, solve_overdetermined};
use kinsyn::manipulator::{InputValues, LegKind, Manipulator, OperationModeSettings};
use kinsyn::spatial::Displacement;
use nalgebra::{Rotation2, Vector2, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// Every isolated assembly of `m` with its inputs at their reference values: how many complex
/// ones (regular solutions off the null cone `Δ = 0`) and the real ones' platform frames.
fn assemblies(m: &Manipulator, seed: u64) -> (usize, Vec<Displacement>) {
    let inputs: Vec<(usize, f64)> = (0..m.actuators().len()).map(|a| (a, 0.0)).collect();
    let ps = m
        .constraint_system(&InputValues::Given(&inputs), &Chart::random_linear(seed))
        .unwrap();
    let settings = SolveSettings {
        seed,
        ..SolveSettings::default()
    };
    let r = solve_overdetermined(ps.system(), &settings).unwrap();
    let found: Vec<_> = r
        .solutions()
        .filter(|s| {
            let delta: kinsyn::poly::C64 = s.x[..4].iter().map(|c| c * c).sum();
            s.regular && delta.norm() > 1e-8
        })
        .collect();
    let real = found
        .iter()
        .filter(|s| s.real)
        .map(|s| {
            let x: Vec<f64> = s.x.iter().map(|c| c.re).collect();
            ps.displacement(&x).unwrap()
        })
        .collect();
    (found.len(), real)
}

/// The angle of a planar platform frame about z (radians), and its origin in the plane.
fn planar_pose(g: &Displacement) -> (f64, Vector2<f64>) {
    let r = g.rotation.matrix();
    let t = g.translation.vector;
    (r[(1, 0)].atan2(r[(0, 0)]), Vector2::new(t.x, t.y))
}

/// A planar 3-RPR (`revolute_legs`: false) or 3-RRR (true) in the plane z = 0: base pivots
/// `a`, platform pins `b` (platform frame), the platform at angle `phi` (degrees) and origin
/// `p`; an RRR's middle joint sits at `elbow[i]`, its first (actuated) revolute at `a[i]`.
fn planar(
    a: &[Vector2<f64>; 3],
    b: &[Vector2<f64>; 3],
    elbow: Option<&[Vector2<f64>; 3]>,
    phi: f64,
    p: Vector2<f64>,
    scale: f64,
) -> Manipulator {
    let r = Rotation2::new(phi.to_radians());
    let legs: Vec<_> = (0..3)
        .map(|i| {
            let c = p + r * b[i];
            let (chain, middle, axes) = match elbow {
                None => (
                    "RP!R",
                    (a[i] + c) / 2.0,
                    json!([[0, 0, 1], "leg", [0, 0, 1]]),
                ),
                Some(e) => ("R!RR", e[i], json!([[0, 0, 1], [0, 0, 1], [0, 0, 1]])),
            };
            json!({
                "chain": chain,
                "base": [a[i].x * scale, a[i].y * scale, 0.0],
                "platform": [b[i].x * scale, b[i].y * scale, 0.0],
                "points": [[middle.x * scale, middle.y * scale, 0.0]],
                "axes": axes,
            })
        })
        .collect();
    let d = json!({
        "format": "kinsyn-manipulator/1",
        "name": "planar test",
        "units": {"length": if scale > 1.0 { "mm" } else { "m" }, "angle": "deg"},
        "platform": {"position": [p.x * scale, p.y * scale, 0.0], "orientation": [0.0, 0.0, phi], "point": [0.0, 0.0, 0.0]},
        "legs": legs,
    });
    Manipulator::from_json(&d.to_string()).unwrap()
}

/// The real assemblies of a planar platform on three RR dyads (pivot `a[i]`, pin `b[i]` on the
/// platform, `|a[i] − p − R b[i]| = rho[i]`), by a method that shares nothing with the
/// homotopy: for each platform angle on a fine grid, dyads 1 and 2 place the platform at the
/// two intersections of two circles; each root of dyad 3's residual along either branch is an
/// assembly (refined by bisection).
fn scanned_assemblies(
    a: &[Vector2<f64>; 3],
    b: &[Vector2<f64>; 3],
    rho: &[f64; 3],
) -> Vec<(f64, Vector2<f64>)> {
    let place = |phi: f64, branch: f64| -> Option<(Vector2<f64>, f64)> {
        let r = Rotation2::new(phi);
        let (c1, c2) = (a[0] - r * b[0], a[1] - r * b[1]);
        let d = (c2 - c1).norm();
        if d == 0.0 || d > rho[0] + rho[1] || d < (rho[0] - rho[1]).abs() {
            return None;
        }
        let e = (c2 - c1) / d;
        let h = (rho[0] * rho[0] - rho[1] * rho[1] + d * d) / (2.0 * d);
        let s = (rho[0] * rho[0] - h * h).max(0.0).sqrt();
        let p = c1 + e * h + Vector2::new(-e.y, e.x) * (branch * s);
        Some((p, (a[2] - p - r * b[2]).norm_squared() - rho[2] * rho[2]))
    };
    let n = 200_000;
    let mut roots = Vec::new();
    for branch in [1.0, -1.0] {
        for k in 0..n {
            let (lo, hi) = (
                std::f64::consts::TAU * f64::from(k) / f64::from(n),
                std::f64::consts::TAU * f64::from(k + 1) / f64::from(n),
            );
            let (Some((_, f0)), Some((_, f1))) = (place(lo, branch), place(hi, branch)) else {
                continue;
            };
            if f0.signum() == f1.signum() {
                continue;
            }
            let (mut l, mut h, mut fl) = (lo, hi, f0);
            for _ in 0..60 {
                let m = 0.5 * (l + h);
                let Some((_, fm)) = place(m, branch) else {
                    break;
                };
                if fm.signum() == fl.signum() {
                    (l, fl) = (m, fm);
                } else {
                    h = m;
                }
            }
            let (p, _) = place(l, branch).unwrap();
            roots.push((l, p));
        }
    }
    roots
}

/// The angle difference folded into (−π, π].
fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// Each scanned assembly is one of kinsyn's real assemblies and the other way round.
fn assert_same_real(found: &[Displacement], scanned: &[(f64, Vector2<f64>)], scale: f64) {
    assert_eq!(found.len(), scanned.len(), "{found:?} vs {scanned:?}");
    for (phi, p) in scanned {
        assert!(
            found.iter().any(|g| {
                let (f, q) = planar_pose(g);
                angle_gap(f, *phi) < 1e-6 && (q / scale - p).norm() < 1e-6
            }),
            "the scan's assembly at {phi} rad, {p:?} is not found"
        );
    }
}

/// Three points of the plane.
type Triangle = [Vector2<f64>; 3];

/// A random planar platform: base pivots, platform pins, the reference angle (degrees) and
/// origin.
fn random_planar(rng: &mut ChaCha8Rng) -> (Triangle, Triangle, f64, Vector2<f64>) {
    let mut v = |r: f64| Vector2::new(rng.random_range(-r..r), rng.random_range(-r..r));
    let a = [v(1.0), v(1.0), v(1.0)];
    let b = [v(0.4), v(0.4), v(0.4)];
    let p = v(0.3);
    let phi = rng.random_range(-60.0..60.0);
    (a, b, phi, p)
}

#[test]
fn a_general_planar_3_rpr_has_six_assemblies_and_its_real_ones_are_the_scans() {
    // Gosselin, Sefrioui & Richard 1992 (Mech. Mach. Theory 27(2)); Hunt 1983: the forward
    // problem of the general planar 3-RPR is a polynomial of degree 6 — six complex
    // assemblies.
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..2 {
        let (a, b, phi, p) = random_planar(&mut rng);
        let r = Rotation2::new(phi.to_radians());
        let rho = [0, 1, 2].map(|i| (a[i] - p - r * b[i]).norm());
        let scanned = scanned_assemblies(&a, &b, &rho);
        for scale in [1.0, 1000.0] {
            let m = planar(&a, &b, None, phi, p, scale);
            let (complex, real) = assemblies(&m, 1);
            assert_eq!(complex, 6, "scale {scale}");
            assert_same_real(&real, &scanned, scale);
        }
    }
}

#[test]
fn a_general_planar_3_rrr_with_its_inputs_fixed_has_six_assemblies_for_every_seed() {
    // With its first revolutes locked, each RRR leg is an RR dyad from its elbow: the 3-RPR's
    // forward problem with fixed lengths, degree 6 (Gosselin, Sefrioui & Richard 1992).
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let (a, b, phi, p) = random_planar(&mut rng);
    let elbow = [0, 1, 2]
        .map(|i| a[i] + Vector2::new(rng.random_range(-0.5..0.5), rng.random_range(-0.5..0.5)));
    let r = Rotation2::new(phi.to_radians());
    let rho = [0, 1, 2].map(|i| (elbow[i] - p - r * b[i]).norm());
    let scanned = scanned_assemblies(&elbow, &b, &rho);
    let m = planar(&a, &b, Some(&elbow), phi, p, 1.0);
    let ps = m
        .constraint_system(
            &InputValues::Given(&[(0, 0.0), (1, 0.0), (2, 0.0)]),
            &Chart::Unit,
        )
        .unwrap();
    assert!(ps.legs().iter().all(|c| c.kind == LegKind::PlanarDistance));
    for seed in 1..=5 {
        let (complex, real) = assemblies(&m, seed);
        assert_eq!(complex, 6, "seed {seed}");
        assert_same_real(&real, &scanned, 1.0);
    }
}

#[test]
fn a_general_spherical_3_rrr_has_eight_assemblies() {
    // Gosselin, Sefrioui & Richard 1994 (ASME J. Mech. Design 116(2), "On the direct
    // kinematics of spherical three-degree-of-freedom parallel manipulators of general
    // architecture"): at most eight, generically eight complex solutions.
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut unit = || {
        let v = Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        v.normalize()
    };
    let centre = Vector3::new(0.1, -0.2, 0.5);
    let legs: Vec<_> = (0..3)
        .map(|_| {
            let (u, v, w) = (unit(), unit(), unit());
            let at = |d: Vector3<f64>| centre + d;
            json!({
                "chain": "R!RR",
                "base": at(u).as_slice(),
                "platform": w.as_slice(),
                "points": [at(v).as_slice()],
                "axes": [u.as_slice(), v.as_slice(), w.as_slice()],
            })
        })
        .collect();
    let d = json!({
        "format": "kinsyn-manipulator/1",
        "name": "spherical test",
        "units": {"length": "m", "angle": "deg"},
        "platform": {"position": centre.as_slice(), "orientation": [0.0, 0.0, 0.0], "point": [0.0, 0.0, 0.0]},
        "legs": legs,
    });
    let m = Manipulator::from_json(&d.to_string()).unwrap();
    for seed in 1..=5 {
        let (complex, real) = assemblies(&m, seed);
        assert_eq!(complex, 8, "seed {seed}");
        // The reference (the platform frame at the centre, unturned) is among the real ones,
        // and every real one keeps the platform's origin, the centre, fixed.
        assert!(
            real.iter()
                .any(|g| (g.rotation.matrix() - nalgebra::Matrix3::identity()).amax() < 1e-9)
        );
        for g in &real {
            assert!((g.translation.vector - centre).norm() < 1e-9);
        }
    }
}

#[test]
fn a_general_gough_stewart_description_has_forty_assemblies() {
    // Raghavan 1993 (ASME J. Mech. Design 115(2)), Husty 1996 (Mech. Mach. Theory 31(4)): the
    // general Gough–Stewart platform has 40 complex assemblies.
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut point = |r: f64, z: f64| {
        [
            rng.random_range(-r..r),
            rng.random_range(-r..r),
            rng.random_range(-z..z),
        ]
    };
    let legs: Vec<_> = (0..6)
        .map(|_| json!({"chain": "UP!S", "base": point(1.0, 0.2), "platform": point(0.5, 0.1)}))
        .collect();
    let d = json!({
        "format": "kinsyn-manipulator/1",
        "name": "general 6-UPS",
        "units": {"length": "m", "angle": "deg"},
        "platform": {"position": [0.05, -0.1, 1.0], "orientation": [5.0, -10.0, 20.0], "point": [0.0, 0.0, 0.0]},
        "legs": legs,
    });
    let m = Manipulator::from_json(&d.to_string()).unwrap();
    let (complex, real) = assemblies(&m, 2);
    assert_eq!(complex, 40);
    let reference = m.platform_frame(&m.reference());
    assert!(
        real.iter()
            .any(|g| (g.to_homogeneous() - reference.to_homogeneous()).amax() < 1e-8)
    );
}

#[test]
fn the_3_rps_with_free_leg_lengths_has_the_two_operation_modes_x0_0_and_x3_0() {
    // Schadlbauer, Walter & Husty 2014 (Mech. Mach. Theory 75, "The 3-RPS parallel manipulator
    // from an algebraic viewpoint", §4): with the leg lengths free, the three plane conditions
    // of the R joints and the Study quadric decompose into two components of dimension 3,
    // x0 = 0 and x3 = 0 (base and platform frames at the centres, z normal to them, the R axes
    // tangent to the circles, as in this description).
    let m = Manipulator::from_json(
        &std::fs::read_to_string(format!(
            "{}/../../mechanisms/3-rps.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap(),
    )
    .unwrap();
    let modes = m
        .operation_modes(&InputValues::Free, &OperationModeSettings::default())
        .unwrap();
    assert!(modes.system.legs().iter().all(|c| c.kind == LegKind::Plane));
    let dims: Vec<usize> = modes.components.iter().map(|c| c.dimension).collect();
    assert_eq!(dims, [3, 3]);
    let vanishing = |k: usize| {
        modes
            .decomposition
            .components
            .iter()
            .position(|w| w.witness_points.iter().all(|x| x[k].norm() < 1e-8))
    };
    let (x0, x3) = (vanishing(0), vanishing(3));
    assert!(x0.is_some() && x3.is_some() && x0 != x3, "{x0:?} {x3:?}");
}

#[test]
fn the_committed_planar_3_rrr_has_the_real_assemblies_of_the_scan() {
    // Its elbows (the middle joints, fixed with the cranks locked) and platform pins from the
    // file; the platform frame at the origin, unturned, at the reference.
    let file = format!(
        "{}/../../mechanisms/3-rrr-planar.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    let xy = |p: &serde_json::Value| Vector2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
    let elbow: Triangle = [0, 1, 2].map(|i| xy(&v["legs"][i]["points"][0]));
    let pin: Triangle = [0, 1, 2].map(|i| xy(&v["legs"][i]["platform"]));
    let rho = [0, 1, 2].map(|i| (elbow[i] - pin[i]).norm());
    let scanned = scanned_assemblies(&elbow, &pin, &rho);
    let m = Manipulator::from_json(&std::fs::read_to_string(&file).unwrap()).unwrap();
    let (_, real) = assemblies(&m, 1);
    assert_same_real(&real, &scanned, 1.0);
}

/// The description at `path` (under the repository) with every length multiplied by `k`: the
/// points of both formats (`position`, `point`, `base`, `platform` when a point, `first`,
/// `last`, `points`); orientations and axes unchanged.
fn scaled_file(path: &str, k: f64) -> Manipulator {
    fn scale(v: &mut serde_json::Value, k: f64) {
        match v {
            serde_json::Value::Object(map) => {
                for (key, value) in map.iter_mut() {
                    let point = |v: &serde_json::Value| {
                        v.as_array().is_some_and(|a| {
                            a.len() == 3 && a.iter().all(serde_json::Value::is_number)
                        })
                    };
                    match key.as_str() {
                        "position" | "point" | "base" | "platform" | "first" | "last"
                            if point(value) =>
                        {
                            for x in value.as_array_mut().unwrap() {
                                *x = json!(x.as_f64().unwrap() * k);
                            }
                        }
                        "points" => {
                            for p in value.as_array_mut().unwrap() {
                                for x in p.as_array_mut().unwrap() {
                                    *x = json!(x.as_f64().unwrap() * k);
                                }
                            }
                        }
                        _ => scale(value, k),
                    }
                }
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(|i| scale(i, k)),
            _ => {}
        }
    }
    let file = format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"));
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    scale(&mut v, k);
    Manipulator::from_json(&v.to_string()).unwrap()
}

/// Each block's count of complex and real assemblies at the reference inputs, solved with
/// `seed`.
fn block_counts(m: &Manipulator, seed: u64) -> Vec<(usize, usize)> {
    let inputs: Vec<(usize, f64)> = (0..m.actuators().len()).map(|a| (a, 0.0)).collect();
    m.body_blocks(&InputValues::Given(&inputs), &Chart::random_linear(seed))
        .unwrap()
        .iter()
        .map(|b| {
            let ps = &b.system;
            let settings = SolveSettings {
                seed,
                ..SolveSettings::default()
            };
            let r = solve_overdetermined(ps.system(), &settings).unwrap();
            let found: Vec<_> = r
                .solutions()
                .filter(|s| s.regular && !ps.on_null_cone(&s.x))
                .collect();
            (found.len(), found.iter().filter(|s| s.real).count())
        })
        .collect()
}

#[test]
fn every_assembly_count_is_the_same_in_other_length_units_and_for_five_seeds() {
    // A unit change multiplies every length by 10^±3 and changes no count; nor may the seed of
    // the charts and of the solve. The stack of paper 002 (two blocks of 16: Schadlbauer et
    // al. 2014), the spherical 3-RRR (randomised; 8, Gosselin et al. 1994) and the planar
    // 3-RRR (the planar restriction; its 2 real ones are the scan's, above).
    for (path, complex) in [
        ("mechanisms/multibody/3-rps-3-spr.json", vec![16, 16]),
        ("mechanisms/3-rrr-spherical.json", vec![8]),
        ("mechanisms/3-rrr-planar.json", vec![2]),
    ] {
        let expected = block_counts(&scaled_file(path, 1.0), 1);
        assert_eq!(
            expected.iter().map(|c| c.0).collect::<Vec<_>>(),
            complex,
            "{path}"
        );
        for k in [1e-3, 1e3] {
            assert_eq!(
                block_counts(&scaled_file(path, k), 1),
                expected,
                "{path} ×{k}"
            );
        }
        // (The spherical 3-RRR's five seeds are the test above.)
        for seed in (2..=5).filter(|_| !path.contains("spherical")) {
            assert_eq!(
                block_counts(&scaled_file(path, 1.0), seed),
                expected,
                "{path} seed {seed}"
            );
        }
    }
}

#[test]
fn operation_modes_are_the_same_in_other_length_units() {
    // The 3-RPS's two modes (Schadlbauer et al. 2014) and the stack's two per block, in
    // millimetres and kilometres: the same dimensions and degrees.
    for path in [
        "mechanisms/3-rps.json",
        "mechanisms/multibody/3-rps-3-spr.json",
    ] {
        let signature = |k: f64| -> Vec<Vec<(usize, usize)>> {
            scaled_file(path, k)
                .block_operation_modes_with_progress(
                    &InputValues::Free,
                    &OperationModeSettings::default(),
                    &mut |_| {},
                )
                .unwrap()
                .iter()
                .map(|b| {
                    let mut s: Vec<(usize, usize)> = b
                        .modes
                        .components
                        .iter()
                        .map(|c| (c.dimension, c.degree))
                        .collect();
                    s.sort_unstable();
                    s
                })
                .collect()
        };
        // Two modes of dimension 3 per block (Schadlbauer et al. 2014; paper 002 §5); their
        // degrees must not move with the unit.
        let metres = signature(1.0);
        assert!(
            metres
                .iter()
                .all(|b| b.len() == 2 && b.iter().all(|(d, _)| *d == 3)),
            "{path}: {metres:?}"
        );
        for k in [1e-3, 1e3] {
            assert_eq!(signature(k), metres, "{path} ×{k}");
        }
    }
}

/// `|f(z)|` relative to the size of `f`'s terms there, `z` the solution vector of the
/// platform pose `pose` on the system `ps` (zero to rounding exactly when `f` vanishes).
fn relative_value(
    ps: &kinsyn::manipulator::PositionSystem,
    f: &kinsyn::poly::Poly,
    pose: &Displacement,
) -> f64 {
    let z: Vec<kinsyn::poly::C64> = ps
        .solution_of(pose)
        .unwrap()
        .iter()
        .map(|x| kinsyn::poly::C64::new(*x, 0.0))
        .collect();
    let size: Vec<kinsyn::poly::C64> = z
        .iter()
        .map(|x| kinsyn::poly::C64::new(x.norm(), 0.0))
        .collect();
    f.eval(&z).norm() / f.magnitudes().eval(&size).norm()
}

#[test]
fn a_slider_not_across_its_revolute_keeps_the_sphere_centre_on_a_quadric_of_revolution() {
    // Leg 1 of the 3-RPS with its slider tilted out of the plane normal to its revolute: with
    // the slider free, the S centre B = A + R_n(θ)(b₀ + s d) sweeps a surface of revolution
    // about the R axis. Points made by the leg's own motion (θ, s) must satisfy its equation;
    // a point lifted along the axis without sliding must not.
    let file = format!("{}/../../mechanisms/3-rps.json", env!("CARGO_MANIFEST_DIR"));
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    let d = Vector3::new(-0.447_213_595_5, 0.3, 0.894_427_191).normalize();
    v["legs"][0]["axes"][1] = json!([d.x, d.y, d.z]);
    let m = Manipulator::from_json(&v.to_string()).unwrap();
    let ps = m
        .constraint_system(&InputValues::Free, &kinsyn::geometry::Chart::Unit)
        .unwrap();
    let kinds: Vec<LegKind> = ps.legs().iter().map(|c| c.kind).collect();
    assert_eq!(kinds, [LegKind::Cone, LegKind::Plane, LegKind::Plane]);
    let c = &ps.legs()[0];
    let n = Vector3::new(0.0, -1.0, 0.0);
    let reference = m.platform_frame(&m.reference());
    let b_ref = reference.transform_point(&c.platform.into()).coords;
    let f = &ps.system().equations()[0];
    let value = |b: Vector3<f64>| {
        let pose = kinsyn::spatial::displacement(
            reference.rotation,
            reference.translation.vector + (b - b_ref),
        );
        relative_value(&ps, f, &pose)
    };
    for (theta, s) in [(0.3, 0.2), (-0.7, -0.4), (1.2, 0.5)] {
        let turn = nalgebra::Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(n), theta);
        let b = c.base + turn * (b_ref - c.base + d * s);
        assert!(value(b) < 1e-12, "θ = {theta}, s = {s}: {}", value(b));
    }
    assert!(value(b_ref + n * 0.1) > 1e-4);
}

#[test]
fn a_slider_not_across_the_platform_revolute_keeps_the_base_point_on_a_moving_quadric() {
    // A 3-SPR with leg 1's slider tilted out of the plane normal to its platform revolute:
    // the base point A stays on a quadric of revolution about the platform's axis. Platform
    // poses that the leg's own motion (θ, s) reaches satisfy its equation; a platform moved
    // along that axis without sliding does not.
    let d = Vector3::new(-0.5, 0.3, 1.0).normalize();
    let legs: Vec<_> = (0..3)
        .map(|k| {
            let r = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), f64::from(k) * 2.0944);
            let base = r * Vector3::new(1.0, 0.0, 0.0);
            let top = r * Vector3::new(0.5, 0.0, 1.0);
            let m = r * Vector3::new(0.0, 1.0, 0.0);
            let slider = if k == 0 { d } else { (top - base).normalize() };
            let mid = (base + top) / 2.0;
            let platform = r * Vector3::new(0.5, 0.0, 0.0);
            json!({
                "chain": "SP!R",
                "base": base.as_slice(),
                "platform": platform.as_slice(),
                "points": [mid.as_slice()],
                "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1], slider.as_slice(), m.as_slice()],
            })
        })
        .collect();
    let v = json!({
        "format": "kinsyn-manipulator/1",
        "name": "3-SPR with a tilted slider",
        "units": {"length": "m", "angle": "deg"},
        "platform": {"position": [0.0, 0.0, 1.0], "orientation": [0.0, 0.0, 0.0], "point": [0.0, 0.0, 0.0]},
        "legs": legs,
    });
    let m = Manipulator::from_json(&v.to_string()).unwrap();
    let ps = m
        .constraint_system(&InputValues::Free, &kinsyn::geometry::Chart::Unit)
        .unwrap();
    let kinds: Vec<LegKind> = ps.legs().iter().map(|c| c.kind).collect();
    assert_eq!(
        kinds,
        [
            LegKind::MovingCone,
            LegKind::MovingPlane,
            LegKind::MovingPlane
        ]
    );
    let a = Vector3::new(1.0, 0.0, 0.0);
    let foot = Vector3::new(0.5, 0.0, 1.0);
    let axis = Vector3::new(0.0, 1.0, 0.0);
    let reference = m.platform_frame(&m.reference());
    let f = &ps.system().equations()[0];
    // The platform translated so that A, seen from it, is at `seen` of its reference.
    let value = |seen: Vector3<f64>| {
        let pose = kinsyn::spatial::displacement(
            reference.rotation,
            reference.translation.vector + (a - seen),
        );
        relative_value(&ps, f, &pose)
    };
    for (theta, s) in [(0.3, 0.2), (-0.7, -0.4), (1.2, 0.5)] {
        let turn =
            nalgebra::Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), theta);
        let seen = foot + turn * (a - foot + d * s);
        assert!(value(seen) < 1e-12, "θ = {theta}, s = {s}: {}", value(seen));
    }
    assert!(value(a + axis * 0.1) > 1e-4);
}

/// A Delta (Clavel 1988) as a description of several bodies: three arms on cranks about
/// horizontal axes tangent to the base circle (radius `rb`, arm length `la`), each holding the
/// platform (radius `r`, `depth` below the base) by a pair of U–S rods of equal length, a
/// parallelogram `2 h` wide; all frames unturned. Returns the description and, for each arm,
/// its pivot, its axis and its platform point's radial direction.
fn delta(rb: f64, la: f64, r: f64, depth: f64, h: f64) -> (Manipulator, Vec<[Vector3<f64>; 3]>) {
    let mut bodies = Vec::new();
    let mut legs = Vec::new();
    let mut arms = Vec::new();
    for i in 0..3 {
        let phi = (90.0 + 120.0 * f64::from(i)).to_radians();
        let u = Vector3::new(phi.cos(), phi.sin(), 0.0);
        let t = Vector3::new(-phi.sin(), phi.cos(), 0.0);
        let (a, e) = (u * rb, u * (rb + la));
        let arm = format!("arm{}", i + 1);
        bodies.push(json!({"name": arm, "position": [e.x, e.y, e.z]}));
        legs.push(
            json!({"chain": "R!", "from": "base", "to": arm, "first": [a.x, a.y, 0.0],
            "last": [a.x - e.x, a.y - e.y, 0.0], "axes": [[t.x, t.y, 0.0]]}),
        );
        for s in [1.0, -1.0] {
            let p = u * r + t * (s * h);
            legs.push(json!({"chain": "US", "from": arm, "to": "platform",
                "first": [s * h * t.x, s * h * t.y, 0.0], "last": [p.x, p.y, p.z],
                "axes": [[t.x, t.y, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]}));
        }
        arms.push([a, t, u]);
    }
    bodies.push(json!({"name": "platform", "position": [0.0, 0.0, -depth]}));
    let d = json!({
        "format": "kinsyn-manipulator/2",
        "name": "Delta",
        "units": {"length": "mm", "angle": "deg"},
        "ground": "base",
        "bodies": bodies,
        "end_effector": "platform",
        "legs": legs,
    });
    (Manipulator::from_json(&d.to_string()).unwrap(), arms)
}

#[test]
fn a_delta_has_two_translational_assemblies_those_of_its_three_spheres() {
    // Clavel 1988 (Proc. 18th ISIR); Pierrot, Reynaud & Fournier 1990 (Robotica 8): with the
    // forearms parallelograms the platform only translates, and its centre lies on a sphere of
    // the forearm's length about each elbow (moved in by the platform radius): two assemblies.
    // The arms are bodies held by their cranks (the body tree's held members); the pairs of
    // U–S rods are distance legs, so the general path also finds the assemblies where the
    // pairs are not parallelograms (the platform turned).
    let (rb, la, r, depth, h) = (200.0, 200.0, 50.0, 400.0, 30.0);
    let (m, arms) = delta(rb, la, r, depth, h);
    let lb = (rb + la - r).hypot(depth);
    for (seed, theta) in [(1, [10.0_f64, -5.0, 20.0]), (2, [-30.0, 15.0, 0.0])] {
        let inputs: Vec<(usize, f64)> = theta
            .iter()
            .enumerate()
            .map(|(a, t)| (a, t.to_radians()))
            .collect();
        let blocks = m
            .body_blocks(&InputValues::Given(&inputs), &Chart::random_linear(seed))
            .unwrap();
        assert_eq!(blocks.len(), 1, "one block: the platform and its arms");
        let ps = &blocks[0].system;
        let settings = SolveSettings {
            seed,
            ..SolveSettings::default()
        };
        let found = solve_overdetermined(ps.system(), &settings).unwrap();
        let translational: Vec<Vector3<f64>> = found
            .solutions()
            .filter(|s| s.regular && s.real && !ps.on_null_cone(&s.x))
            .filter_map(|s| {
                let x: Vec<f64> = s.x.iter().map(|c| c.re).collect();
                let g = ps.displacement(&x).ok()?;
                (g.rotation.angle() < 1e-9).then_some(g.translation.vector)
            })
            .collect();
        // The three spheres by hand: elbow i turned by θ_i about its crank's axis.
        let centres: Vec<Vector3<f64>> = arms
            .iter()
            .zip(theta)
            .map(|([a, t, u], th)| {
                let turn = nalgebra::Rotation3::from_axis_angle(
                    &nalgebra::Unit::new_normalize(*t),
                    th.to_radians(),
                );
                a + turn * (u * la) - u * r
            })
            .collect();
        let (c1, c2, c3) = (centres[0], centres[1], centres[2]);
        // Trilateration: the plane of the two radical planes' line, then the line's two points
        // at distance lb from c1.
        let n = (c2 - c1).cross(&(c3 - c1));
        let mid = |p: Vector3<f64>, q: Vector3<f64>| (p.norm_squared() - q.norm_squared()) / 2.0;
        let m3 = nalgebra::Matrix3::from_rows(&[
            (c2 - c1).transpose(),
            (c3 - c1).transpose(),
            n.transpose(),
        ]);
        let foot = m3
            .lu()
            .solve(&Vector3::new(mid(c2, c1), mid(c3, c1), n.dot(&c1)))
            .unwrap();
        let depth_left = (lb * lb - (foot - c1).norm_squared()).sqrt();
        let expected = [
            foot + n.normalize() * depth_left,
            foot - n.normalize() * depth_left,
        ];
        assert_eq!(translational.len(), 2, "θ = {theta:?}: {translational:?}");
        for e in expected {
            assert!(
                translational.iter().any(|p| (p - e).norm() < 1e-8 * lb),
                "θ = {theta:?}: {e} not among {translational:?}"
            );
        }
    }
}

/// The start paths of the by-dimension decomposition of the 4-RUU with its four inputs free
/// (10 equations in the Study parameters `X` and the tangents `t1 … t4`: two of degree
/// `2 + 2` in `(X, t_i)` per leg, the Study quadric and the chart of degree 2 in `X`), counted
/// by hand for the linear-product start. At dimension `d` the `12 − d` combinations keep the
/// leg equations of largest degree, the rest (another leg's equations, the quadric, the chart)
/// added; the `d` slices are one slot of every unknown. Each leg equation chosen takes an `X`
/// slot or a tangent slot (2 of each); the two equations of one leg cannot both take its one
/// tangent, so a leg contributes `1 + 2 = 3` ways with one or no tangent taken (2 for which
/// equation):
/// - `d = 4`: the 8 leg equations with the quadric and the chart added: `2⁸ · 3⁴ = 20 736`;
/// - `d = 3`: the same and the quadric (plus the chart), whose two `X` slots need at least one
///   tangent taken among the legs (9 `X` equations, 8 `X` unknowns): `2⁹ (3⁴ − 1) = 40 960`;
/// - `d = 2`: quadric and chart apart: at least two tangents taken:
///   `2¹⁰ (3⁴ − 1 − 4·2) = 73 728`;
/// - `d = 5`: seven combinations, the first six (legs 1–3) with leg 4's second equation
///   added (slots `{X}{X}{t_j, t4}{t_j, t4}`), the seventh leg 4's first: a leg takes two
///   tangents only through `t4`, which one of them (or leg 4's equation) may use:
///   `2⁷ (3³ + 3³ + 3 · 3²) = 2⁷ · 3⁴ = 10 368`.
///
/// The total-degree counts were `4⁸ = 65 536`, `4⁸ · 2`, `4⁸ · 4` and `4⁷`.
#[test]
fn the_free_input_4_ruu_decomposition_paths_by_hand() {
    let m = Manipulator::from_json(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../mechanisms/4-ruu.json"
        ))
        .unwrap(),
    )
    .unwrap();
    let ps = m
        .constraint_system(&InputValues::Free, &Chart::Unit)
        .unwrap();
    let by_dimension = kinsyn::homotopy::decompose_paths_by_dimension(ps.system());
    let at = |d: usize| by_dimension.iter().find(|(e, _)| *e == d).unwrap().1;
    assert_eq!(
        [at(5), at(4), at(3), at(2)],
        [10_368, 20_736, 40_960, 73_728]
    );
    // Above, never more than the total degree of the same dimension: the 12 − d largest
    // degrees of 4 × 8, 2, 2.
    let degrees = [4u128, 4, 4, 4, 4, 4, 4, 4, 2, 2];
    for (d, paths) in &by_dimension {
        let bezout: u128 = degrees[..12 - d].iter().product();
        assert!(*paths <= bezout, "dimension {d}");
        assert!(*d >= 2, "no dimension below 12 − 10 is sliced");
    }
}
