//! Paper 004's 4-RUU (`kinsyn_papers::ruu`): the constraint equations derived from the geometry,
//! compared with the printed ones (`data/paper004-constraints.txt`, eqs. 11–13), evaluated at
//! poses assembled independently with nalgebra, and on the Schönflies modes of eqs. 14–23.

use kinsyn::poly::{C64, Poly, System, bertini};
use kinsyn::spatial::Displacement;
use kinsyn::spatial::study;
use kinsyn_papers::ruu::{InputMode, Ruu, RuuError};
use nalgebra::{Rotation3, Translation3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const PRINTED: &str = include_str!("../../../../data/paper004-constraints.txt");

fn printed() -> System {
    bertini::parse(PRINTED)
        .expect("the transcription parses")
        .system
}

fn cplx(rng: &mut ChaCha8Rng) -> C64 {
    C64::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0))
}

/// A random complex point of the Study quadric `x·y = 0` (the complex bilinear form) with
/// random complex tangents `t11 … t14, t21 … t24`: 16 coordinates in `Ruu::variable_names`
/// order for `InputMode::Free`.
fn quadric_point(rng: &mut ChaCha8Rng) -> Vec<C64> {
    let mut p: Vec<C64> = (0..16).map(|_| cplx(rng)).collect();
    let xx: C64 = (0..4).map(|k| p[k] * p[k]).sum();
    let xy: C64 = (0..4).map(|k| p[k] * p[4 + k]).sum();
    for k in 0..4 {
        let xk = p[k];
        p[4 + k] -= xk * (xy / xx);
    }
    p
}

/// The ratios derived/printed of equation `k` at `points` (design `ruu` substituted into the
/// printed equations' `a, b, l, r`).
fn ratios(
    ruu: &Ruu,
    derived: &System,
    printed: &System,
    k: usize,
    points: &[Vec<C64>],
) -> Vec<C64> {
    points
        .iter()
        .map(|p| {
            let mut q = p.clone();
            q.extend([ruu.a, ruu.b, ruu.l, ruu.r].map(|v| C64::new(v, 0.0)));
            derived.equations()[k].eval(p) / printed.equations()[k].eval(&q)
        })
        .collect()
}

/// The largest relative spread `|ρ_j − ρ_0| / |ρ_0|` of the ratios.
fn spread(r: &[C64]) -> f64 {
    r.iter()
        .map(|v| (v - r[0]).norm() / r[0].norm())
        .fold(0.0, f64::max)
}

/// Criterion: two polynomials agree up to a non-zero constant factor **modulo the Study
/// quadric** exactly when their ratio is the same non-zero constant at every point of the
/// quadric where the printed one does not vanish (the quadric `x·y` in eight variables is
/// irreducible, so a polynomial vanishing on it is a multiple of it; random complex points of
/// it with random complex tangents and design are generic with probability one). Six points,
/// spread below 1e-9, for paper 004's design and a second, arbitrary one (the printed
/// equations keep `a, b, l, r` symbolic).
#[test]
fn derived_equations_equal_the_printed_ones_modulo_the_study_quadric() {
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let printed = printed();
    assert_eq!(printed.len(), 12);
    for ruu in [Ruu::paper004(), Ruu::new(2.3, 0.7, 1.1, 2.9).unwrap()] {
        let derived = ruu.constraints(InputMode::Free).unwrap();
        assert_eq!(derived.len(), 14);
        let points: Vec<Vec<C64>> = (0..6).map(|_| quadric_point(&mut rng)).collect();
        for k in 0..12 {
            let r = ratios(&ruu, &derived, &printed, k, &points);
            assert!(r[0].norm() > 1e-3, "g{}: ratio {}", k + 1, r[0]);
            assert!(spread(&r) < 1e-9, "g{}: ratios {r:?}", k + 1);
        }
    }
}

/// The criterion can fail: one printed coefficient changed (`+ x0*x1` added to `g1`, or `g5`
/// with `r` replaced by `1.01 r`) gives ratios that vary across the quadric.
#[test]
fn the_comparison_detects_a_changed_term() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let printed = printed();
    let ruu = Ruu::paper004();
    let derived = ruu.constraints(InputMode::Free).unwrap();
    let points: Vec<Vec<C64>> = (0..6).map(|_| quadric_point(&mut rng)).collect();
    let n = printed.nvars();
    let wrong_g1 = printed.equations()[0].clone() + Poly::variable(n, 0) * Poly::variable(n, 1);
    let wrong = System::new(printed.variables().to_vec(), vec![wrong_g1]).unwrap();
    assert!(spread(&ratios(&ruu, &derived, &wrong, 0, &points)) > 1e-3);
    let other = Ruu::new(2.0, 1.0, 1.0, 2.02).unwrap();
    let r = ratios(&ruu, &derived, &printed, 4, &points);
    let r_other = ratios(&other, &derived, &printed, 4, &points);
    assert!(spread(&r) < 1e-9);
    assert!(spread(&r_other) > 1e-4);
}

fn half_tan(theta: f64) -> f64 {
    (theta / 2.0).tan()
}

fn eval_real(p: &Poly, x: &[f64]) -> f64 {
    let z: Vec<C64> = x.iter().map(|v| C64::new(*v, 0.0)).collect();
    p.eval(&z).re
}

/// One leg closed by an independent computation (nalgebra, no Study parameters): for a
/// platform pose `g`, the input `θ1` putting `B` in the plane of `Z` and the platform's `z`
/// axis through `C` (`l (cos θ, sin θ)·w = (C − A)·w`, `w = Z × R z`), the coupler length
/// `r = |C − B|` that this leg then has, and the passive angle `θ2` of the axis
/// `s = Z × (C − B)`. `None` if the leg cannot close for this pose.
fn close_leg(ruu: &Ruu, i: usize, g: &Displacement) -> Option<(f64, f64, f64)> {
    let c = g * nalgebra::Point3::from(ruu.platform_joint(i));
    let a = ruu.base_joint(i);
    let w = Vector3::z().cross(&(g.rotation * Vector3::z()));
    let rho = w.xy().norm();
    let rhs = (c.coords - a).dot(&w) / (ruu.l * rho);
    if rho < 1e-3 || rhs.abs() > 0.99 {
        return None;
    }
    let theta1 = w.y.atan2(w.x) + rhs.acos();
    let b = ruu.crank_joint(i, theta1);
    let cb = c.coords - b;
    let s = Vector3::z().cross(&cb);
    Some((theta1, cb.norm(), s.y.atan2(s.x)))
}

/// Tilted platform poses (outside both Schönflies modes): leg `i` closed by [`close_leg`] with
/// its own coupler length; `g_i`, `g_{4+i}`, `g_{8+i}` of the 4-RUU with that `r` vanish at
/// the pose's Study parameters and the leg's `t1i`, `t2i`, and `g_i` does not when `θ1i` is
/// off by 0.01 rad.
#[test]
fn leg_equations_vanish_at_independently_closed_legs() {
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let mut checked = 0;
    while checked < 40 {
        let axis = Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let rot = Rotation3::from_scaled_axis(axis * rng.random_range(0.1..0.8));
        let tr = Translation3::new(
            rng.random_range(-0.5..0.5),
            rng.random_range(-0.5..0.5),
            rng.random_range(0.8..2.0),
        );
        let g = Displacement::from_parts(tr, rot);
        let sp = study::from_displacement(&g);
        let i = rng.random_range(0..4);
        let Some((theta1, r, theta2)) = close_leg(&Ruu::paper004(), i, &g) else {
            continue;
        };
        let (t1, t2) = (half_tan(theta1), half_tan(theta2));
        if t1.abs() > 20.0 || t2.abs() > 20.0 {
            continue;
        }
        let ruu = Ruu::new(2.0, 1.0, 1.0, r).unwrap();
        let mut inputs = [0.3; 4];
        inputs[i] = t1;
        let sys = ruu.constraints(InputMode::Given(inputs)).unwrap();
        let mut x = sp.to_vec();
        let mut passive = [0.7; 4];
        passive[i] = t2;
        x.extend(passive);
        let scale = (1.0 + t1 * t1) * (1.0 + t2 * t2) * 100.0;
        for k in [i, 4 + i, 8 + i, 12, 13] {
            let v = eval_real(&sys.equations()[k], &x);
            assert!(v.abs() < 1e-10 * scale, "leg {i} g{}: {v}", k + 1);
        }
        inputs[i] = half_tan(theta1 + 0.01);
        let off = ruu.constraints(InputMode::Given(inputs)).unwrap();
        assert!(eval_real(&off.equations()[i], &x).abs() > 1e-5);
        checked += 1;
    }
}

/// A whole 4-RUU of paper 004's design assembled in a Schönflies pose, by an independent
/// computation: platform parallel to the base (turned by φ about `Z`, and for the first mode
/// also flipped by π about a horizontal axis near the diagonal, which keeps each `C_i` within
/// reach of its crank), `B_i` the intersection of the crank circle
/// about `A_i` with the circle of radius `√(r² − h²)` about `C_i`'s projection (`h` the
/// platform height), `s_i = Z × (C_i − B_i)`. All fourteen equations vanish, with the inputs
/// given and with them free; the parameters lie in the paper's `J2` (`x1 = x2 = 0`, eq. 14)
/// upright and in `J1` (`x0 = x3 = 0`) flipped.
#[test]
fn all_equations_vanish_at_assembled_schoenflies_poses() {
    let ruu = Ruu::paper004();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for flipped in [false, true] {
        for _ in 0..10 {
            let phi = if flipped {
                rng.random_range(-0.1..0.1)
            } else {
                rng.random_range(-0.6..0.6)
            };
            let mut rot = Rotation3::from_axis_angle(&Vector3::z_axis(), phi);
            if flipped {
                let psi: f64 = std::f64::consts::FRAC_PI_4 + rng.random_range(-0.1..0.1);
                let u = nalgebra::Unit::new_normalize(Vector3::new(psi.cos(), psi.sin(), 0.0));
                rot = Rotation3::from_axis_angle(&u, std::f64::consts::PI) * rot;
            }
            let h = if flipped {
                rng.random_range(0.5..0.9)
            } else {
                rng.random_range(0.8..1.6)
            };
            let tr = Translation3::new(rng.random_range(-0.1..0.1), rng.random_range(-0.1..0.1), h);
            let g = Displacement::from_parts(tr, rot);
            let sp = study::from_displacement(&g);
            let mut t1 = [0.0; 4];
            let mut t2 = [0.0; 4];
            for i in 0..4 {
                let c = g * nalgebra::Point3::from(ruu.platform_joint(i));
                let a = ruu.base_joint(i);
                let rho = (ruu.r * ruu.r - h * h).sqrt();
                // Circles |B − A| = l and |B − c_xy| = ρ in the plane z = 0.
                let d = c.coords.xy() - a.xy();
                let dn = d.norm();
                let along = (ruu.l * ruu.l - rho * rho + dn * dn) / (2.0 * dn);
                let across = (ruu.l * ruu.l - along * along).sqrt();
                assert!(
                    across.is_finite(),
                    "leg {i} closes: dn {dn} rho {rho} along {along} c {c}"
                );
                let bxy =
                    a.xy() + d * (along / dn) + Vector3::new(-d.y, d.x, 0.0).xy() * (across / dn);
                let b = Vector3::new(bxy.x, bxy.y, 0.0);
                assert!(((c.coords - b).norm() - ruu.r).abs() < 1e-12);
                let theta1 = (b.y - a.y).atan2(b.x - a.x);
                let s = Vector3::z().cross(&(c.coords - b));
                t1[i] = half_tan(theta1);
                t2[i] = half_tan(s.y.atan2(s.x));
            }
            let sys = ruu.constraints(InputMode::Given(t1)).unwrap();
            let mut x = sp.to_vec();
            x.extend(t2);
            let free = ruu.constraints(InputMode::Free).unwrap();
            let mut xf = sp.to_vec();
            xf.extend(t1);
            xf.extend(t2);
            let scale: f64 = 100.0 * t1.iter().chain(&t2).map(|t| 1.0 + t * t).product::<f64>();
            for k in 0..14 {
                let v = eval_real(&sys.equations()[k], &x);
                let vf = eval_real(&free.equations()[k], &xf);
                assert!(v.abs() < 1e-10 * scale, "flipped {flipped} g{}: {v}", k + 1);
                assert!((v - vf).abs() < 1e-10 * scale);
            }
            if flipped {
                assert!(sp[0].abs() < 1e-12 && sp[3].abs() < 1e-12, "{sp:?}");
            } else {
                assert!(sp[1].abs() < 1e-12 && sp[2].abs() < 1e-12, "{sp:?}");
            }
        }
    }
}

/// Paper 004 eqs. 14, 19, 23: `J = ⟨g1, g2, g3, g4, g13⟩` has the components
/// `J1 = ⟨x0, x3, x1 y1 + x2 y2⟩` and `J2 = ⟨x1, x2, x0 y0 + x3 y3⟩`. Numerically:
/// `g1 … g4` and `g13` vanish at random complex points of `V(J1)` and of `V(J2)` with random
/// complex inputs, but not at random points of the Study quadric (so the inclusion is not
/// vacuous). Both follow from the printed form of eq. 11 (every term of `g1 … g4` has a factor
/// `x0` or `x3`, and with `x1 = x2 = 0` what is left is `∓(2 t1i² + 2)(x0 y0 + x3 y3)`).
#[test]
fn the_schoenflies_components_lie_in_the_coplanarity_equations() {
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let ruu = Ruu::paper004();
    let sys = ruu.constraints(InputMode::Free).unwrap();
    for _ in 0..10 {
        let mut k1 = quadric_point(&mut rng);
        k1[0] = C64::new(0.0, 0.0);
        k1[3] = C64::new(0.0, 0.0);
        k1[6] = -k1[1] * k1[5] / k1[2];
        let mut k2 = quadric_point(&mut rng);
        k2[1] = C64::new(0.0, 0.0);
        k2[2] = C64::new(0.0, 0.0);
        k2[7] = -k2[0] * k2[4] / k2[3];
        let generic = quadric_point(&mut rng);
        for k in [0, 1, 2, 3, 12] {
            assert!(
                sys.equations()[k].eval(&k1).norm() < 1e-12,
                "J1, g{}",
                k + 1
            );
            assert!(
                sys.equations()[k].eval(&k2).norm() < 1e-12,
                "J2, g{}",
                k + 1
            );
        }
        for k in 0..4 {
            assert!(sys.equations()[k].eval(&generic).norm() > 1e-6);
        }
    }
}

#[test]
fn bad_design_and_inputs_are_refused() {
    assert!(matches!(
        Ruu::new(2.0, -1.0, 1.0, 2.0),
        Err(RuuError::Length { name: "b", .. })
    ));
    assert!(matches!(
        Ruu::new(2.0, 1.0, f64::NAN, 2.0),
        Err(RuuError::Length { name: "l", .. })
    ));
    let e = Ruu::paper004().constraints(InputMode::Given([0.0, f64::INFINITY, 0.0, 0.0]));
    assert_eq!(
        e.unwrap_err(),
        RuuError::Input {
            leg: 2,
            value: f64::INFINITY
        }
    );
    assert_eq!(
        Ruu::variable_names(&InputMode::Free)[8..],
        ["t11", "t12", "t13", "t14", "t21", "t22", "t23", "t24"].map(String::from)
    );
}
