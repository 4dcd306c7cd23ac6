//! Paper 003 §4: the velocities of the configurable 4-RRR by screw theory (eqs. 16–29),
//! checked at Table 2's configuration against two independent methods — implicit
//! differentiation of the position equations of §3.2 (method 2) and central finite differences
//! of the forward position — and against hand derivations.

use kinsyn::screw::{Line, Wrench, reciprocal_product};
use kinsyn_papers::configurable::velocity::{
    Configuration, VelocityError, input_output, klein_form, loop_coefficients, planar_line,
    planar_twist, plucker_line, polarity, revolute, twist_from_planar, velocities,
};
use kinsyn_papers::configurable::{Configurable, CornerPose};
use nalgebra::{SMatrix, SVector, Vector2, Vector3, Vector4};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

type V6 = SVector<f64, 6>;
type M6 = SMatrix<f64, 6, 6>;
type M64 = SMatrix<f64, 6, 4>;

/// Paper 003 §5: the input angles of the forward example (degrees, printed to 3 decimals).
const Q_DEG: [f64; 4] = [141.956, 203.366, 337.773, 305.499];

/// Table 2's printed corners `C_i` and elbows `B_i`.
const TABLE2_C: [(f64, f64); 4] = [
    (45.949, -28.866),
    (14.889, 87.042),
    (-5.947, -31.133),
    (25.112, -147.043),
];
const TABLE2_B: [(f64, f64); 4] = [
    (136.996, 49.301),
    (-73.439, 168.271),
    (-125.944, -30.262),
    (46.455, -265.130),
];

fn q_rad() -> [f64; 4] {
    Q_DEG.map(f64::to_radians)
}

/// The corners of method 2's unknowns `x = (x4, y4, sθ, cθ, sφ, cφ)` (eqs. 12–14).
fn corners_of(m: &Configurable, x: &V6) -> [Vector2<f64>; 4] {
    let c4 = Vector2::new(x[0], x[1]);
    let c1 = c4 + m.c * Vector2::new(x[3], x[2]);
    let c3 = c4 + m.c * Vector2::new(x[5], x[4]);
    [c1, c1 + c3 - c4, c3, c4]
}

/// Method 2's six equations `f_i = |C_i − B_i(q)|² − b²` (eq. 6), `sθ² + cθ² − 1`,
/// `sφ² + cφ² − 1` (eq. 15), with their Jacobians in `x` and in `q`, by hand.
fn system(m: &Configurable, q: &[f64; 4], x: &V6) -> (V6, M6, M64) {
    let c = corners_of(m, x);
    // ∂C_i/∂x, columns (x4, y4, sθ, cθ, sφ, cφ).
    let dc = |i: usize| {
        let mut d = SMatrix::<f64, 2, 6>::zeros();
        d[(0, 0)] = 1.0;
        d[(1, 1)] = 1.0;
        if i == 0 || i == 1 {
            d[(0, 3)] = m.c;
            d[(1, 2)] = m.c;
        }
        if i == 1 || i == 2 {
            d[(0, 5)] = m.c;
            d[(1, 4)] = m.c;
        }
        d
    };
    let (mut f, mut fx, mut fq) = (V6::zeros(), M6::zeros(), M64::zeros());
    for i in 0..4 {
        let e = c[i] - m.elbow(i, q[i]);
        f[i] = e.norm_squared() - m.b * m.b;
        fx.set_row(i, &(2.0 * e.transpose() * dc(i)));
        let db = m.a * Vector2::new(-q[i].sin(), q[i].cos());
        fq[(i, i)] = -2.0 * e.dot(&db);
    }
    f[4] = x[2] * x[2] + x[3] * x[3] - 1.0;
    f[5] = x[4] * x[4] + x[5] * x[5] - 1.0;
    fx[(4, 2)] = 2.0 * x[2];
    fx[(4, 3)] = 2.0 * x[3];
    fx[(5, 4)] = 2.0 * x[4];
    fx[(5, 5)] = 2.0 * x[5];
    (f, fx, fq)
}

/// The forward position by Newton on method 2's equations from `x0`.
fn newton(m: &Configurable, q: &[f64; 4], x0: &V6) -> V6 {
    let mut x = *x0;
    for _ in 0..50 {
        let (f, fx, _) = system(m, q, &x);
        let dx = fx.lu().solve(&f).expect("regular Jacobian");
        x -= dx;
        if dx.norm() < 1e-14 * (1.0 + x.norm()) {
            break;
        }
    }
    let (f, _, _) = system(m, q, &x);
    assert!(f.norm() < 1e-9, "Newton did not converge: residual {f:?}");
    x
}

/// Table 2's configuration made exact: Newton from the printed coordinates at the paper's q.
fn exact() -> (Configurable, [f64; 4], V6) {
    let m = Configurable::paper003();
    let p = |k: usize| Vector2::new(TABLE2_C[k].0, TABLE2_C[k].1);
    let (d1, d3) = ((p(0) - p(3)).normalize(), (p(2) - p(3)).normalize());
    let x0 = V6::from_column_slice(&[p(3).x, p(3).y, d1.y, d1.x, d3.y, d3.x]);
    let q = q_rad();
    let x = newton(&m, &q, &x0);
    (m, q, x)
}

fn pose(x: &V6) -> CornerPose {
    CornerPose {
        c4: Vector2::new(x[0], x[1]),
        theta: x[2].atan2(x[3]),
        phi: x[4].atan2(x[5]),
    }
}

fn configuration() -> (Configuration, Configurable, [f64; 4], V6) {
    let (m, q, x) = exact();
    (Configuration::new(&m, q, &pose(&x)), m, q, x)
}

/// Implicit differentiation (method 2 of §3.2): `ẋ = −F_x⁻¹ F_q q̇`; returns (θ̇, φ̇, Ċ1..Ċ4).
fn implicit(
    m: &Configurable,
    q: &[f64; 4],
    x: &V6,
    qdot: &Vector4<f64>,
) -> (f64, f64, [Vector2<f64>; 4]) {
    let (_, fx, fq) = system(m, q, x);
    let xd = -fx.lu().solve(&(fq * qdot)).expect("regular Jacobian");
    let thetad = x[3] * xd[2] - x[2] * xd[3];
    let phid = x[5] * xd[4] - x[4] * xd[5];
    let c4 = Vector2::new(xd[0], xd[1]);
    let c1 = c4 + m.c * Vector2::new(xd[3], xd[2]);
    let c3 = c4 + m.c * Vector2::new(xd[5], xd[4]);
    (thetad, phid, [c1, c1 + c3 - c4, c3, c4])
}

/// Central finite differences of the forward position along `q̇`: (θ̇, φ̇, Ċ1..Ċ4).
fn finite_differences(
    m: &Configurable,
    q: &[f64; 4],
    x: &V6,
    qdot: &Vector4<f64>,
) -> (f64, f64, [Vector2<f64>; 4]) {
    let h = 1e-5;
    let at = |sign: f64| {
        let qs: [f64; 4] = std::array::from_fn(|i| q[i] + sign * h * qdot[i]);
        newton(m, &qs, x)
    };
    let (xp, xm) = (at(1.0), at(-1.0));
    let (pp, pm) = (pose(&xp), pose(&xm));
    let (cp, cm) = (corners_of(m, &xp), corners_of(m, &xm));
    (
        (pp.theta - pm.theta) / (2.0 * h),
        (pp.phi - pm.phi) / (2.0 * h),
        std::array::from_fn(|i| (cp[i] - cm[i]) / (2.0 * h)),
    )
}

fn assert_rel(what: &str, a: f64, b: f64, scale: f64) {
    assert_tol(what, a, b, scale, 1e-6);
}

fn assert_tol(what: &str, a: f64, b: f64, scale: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * scale,
        "{what}: {a} vs {b} (scale {scale})"
    );
}

#[test]
fn table2_configuration_is_recovered_exactly() {
    let (cfg, m, _, x) = configuration();
    for i in 0..4 {
        // Table 2 (3 decimals).
        let c = Vector2::new(TABLE2_C[i].0, TABLE2_C[i].1);
        let b = Vector2::new(TABLE2_B[i].0, TABLE2_B[i].1);
        assert!(
            (cfg.corners[i] - c).amax() < 5e-3,
            "C{}: {:?}",
            i + 1,
            cfg.corners[i]
        );
        assert!(
            (cfg.elbows[i] - b).amax() < 5e-3,
            "B{}: {:?}",
            i + 1,
            cfg.elbows[i]
        );
        // §5's lengths: a = 80, b = 120, c = 120, exact.
        assert!(((cfg.elbows[i] - cfg.base[i]).norm() - m.a).abs() < 1e-9);
        assert!(((cfg.corners[i] - cfg.elbows[i]).norm() - m.b).abs() < 1e-9);
        assert!(((cfg.corners[i] - cfg.corners[(i + 1) % 4]).norm() - m.c).abs() < 1e-9);
    }
    // Table 1's last row: θ = 79.999°, φ = 105.000°.
    let p = pose(&x);
    assert!(
        (p.theta.to_degrees() - 79.999).abs() < 1.5e-3,
        "θ = {}",
        p.theta.to_degrees()
    );
    assert!(
        (p.phi.to_degrees() - 105.0).abs() < 1.5e-3,
        "φ = {}",
        p.phi.to_degrees()
    );
}

#[test]
fn klein_form_is_the_symmetric_reciprocal_product() {
    // Hand: the x axis (s = x̂ through the origin) and a revolute along ẑ through (0, d):
    // {s; $} = s · (p × ẑ) + ẑ · (r × s) = x̂ · (d x̂) = d, the axis' distance from the line.
    let d = 3.5;
    let s = plucker_line(Vector2::zeros(), Vector2::new(2.0, 0.0)).unwrap();
    let r = revolute(Vector2::new(0.0, d));
    assert!((klein_form(&s, &r) - d).abs() < 1e-15);
    assert!((klein_form(&r, &s) - d).abs() < 1e-15);
    // A line through the axis is reciprocal to it.
    let through = plucker_line(Vector2::new(-1.0, 2.0), Vector2::new(0.0, d)).unwrap();
    assert!(klein_form(&through, &r).abs() < 1e-14);
    // The same number as kinsyn's virtual power of a unit force along the line.
    let (a, b) = (Vector2::new(1.3, -0.4), Vector2::new(-2.0, 5.0));
    let line = Line::through(
        Vector3::new(a.x, a.y, 0.0),
        Vector3::new(b.x - a.x, b.y - a.y, 0.0),
    );
    let force = Wrench {
        f: line.direction,
        m: line.moment,
    };
    let t = revolute(Vector2::new(0.7, 2.2));
    let k = klein_form(&plucker_line(a, b).unwrap(), &t);
    assert!((k - reciprocal_product(&force, &t)).abs() < 1e-14);
    // Eq. 26's polarity Δ on the planar coordinates is the same form.
    let s = plucker_line(a, b).unwrap();
    let planar = planar_line(&s).dot(&(polarity() * planar_twist(&t)));
    assert!((planar - k).abs() < 1e-14);
}

#[test]
fn loop_coefficients_of_a_rhombus_and_of_any_four_bar() {
    // Hand (a parallelogram): ω_{m3} = ω_{m1}, ω_{m4} = ω_{m2}, so with m1ωm2 = ω2 − ω1,
    // m2ωm3 = ω3 − ω2 = −ω12, m3ωm4 = ω4 − ω3 = ω12, m4ωm1 = ω1 − ω4 = −ω12.
    let (cfg, ..) = configuration();
    let g = loop_coefficients(&cfg).unwrap();
    assert!((g.g23 + 1.0).abs() < 1e-12, "{g:?}");
    assert!((g.g34 - 1.0).abs() < 1e-12, "{g:?}");
    assert!((g.g41 + 1.0).abs() < 1e-12, "{g:?}");
    // Any planar 4R loop: the rates of eq. 18 close eq. 17 (the screw sum vanishes).
    let mut rng = ChaCha8Rng::seed_from_u64(17);
    for _ in 0..20 {
        let mut c = cfg;
        c.corners = std::array::from_fn(|_| {
            Vector2::new(
                rng.random_range(-100.0..100.0),
                rng.random_range(-100.0..100.0),
            )
        });
        let g = loop_coefficients(&c).unwrap();
        let rates = [1.0, g.g23, g.g34, g.g41];
        let (mut w, mut v) = (Vector3::zeros(), Vector3::zeros());
        for (k, r) in rates.iter().enumerate() {
            let s = c.loop_screw(k);
            w += s.w * *r;
            v += s.v * *r;
        }
        let size = rates.iter().map(|r| r.abs()).fold(1.0, f64::max);
        assert!(
            w.norm() < 1e-12 * size && v.norm() < 1e-9 * size,
            "{w:?} {v:?} {g:?}"
        );
    }
}

#[test]
fn three_methods_one_answer_at_table2() {
    let (cfg, m, q, x) = configuration();
    let mut rng = ChaCha8Rng::seed_from_u64(2021);
    // §5's trajectory at t = 0: q̇_i = coefficient of sin t cos t (d/dt = cos 2t = 1).
    let mut rates = vec![Vector4::new(-1.5, -1.25, -2.0, 1.5)];
    for _ in 0..8 {
        rates.push(Vector4::from_fn(|_, _| rng.random_range(-2.0..2.0)));
    }
    for qdot in &rates {
        let v = velocities(&cfg, qdot).unwrap();
        let (td, pd, ci) = implicit(&m, &q, &x, qdot);
        let (tf, pf, cf) = finite_differences(&m, &q, &x, qdot);
        let wscale = td.abs().max(pd.abs());
        let cscale = ci.iter().map(nalgebra::Matrix::norm).fold(0.0, f64::max);
        // Implicit differentiation against finite differences (finite differences: h² error).
        assert!((td - tf).abs() < 1e-6 * wscale && (pd - pf).abs() < 1e-6 * wscale);
        // m1 = C1C2 ∥ C4C3 turns with φ (eq. 27: m3 too); the loop rate is θ̇ − φ̇.
        assert_rel("ω_m1", v.m1.w.z, pd, wscale);
        assert_rel("ω_m3", v.m3.w.z, pd, wscale);
        assert_rel("m1ωm2", v.loop_rate, td - pd, wscale);
        for i in 0..4 {
            for k in 0..2 {
                // Screws against implicit differentiation: both exact, so far below 1e-6.
                let what = format!("Ċ{} implicit", i + 1);
                assert_tol(&what, v.corners[i][k], ci[i][k], cscale, 1e-10);
                assert_rel(
                    &format!("Ċ{} differences", i + 1),
                    v.corners[i][k],
                    cf[i][k],
                    cscale,
                );
            }
        }
        // Eq. 29 on m1 at C1 and on m3 at C4 agrees with the twist of m4 implied by the
        // corners: Ċ1 − Ċ4 = θ̇ ẑ × (C1 − C4).
        let d = cfg.corners[0] - cfg.corners[3];
        let rel = v.corners[0] - v.corners[3];
        let expect = td * Vector2::new(-d.y, d.x);
        assert!((rel - expect).norm() < 1e-6 * cscale);
    }
}

#[test]
fn eq26_as_printed_and_the_readings_that_fail() {
    let (cfg, m, q, x) = configuration();
    let io = input_output(&cfg).unwrap();
    let qdot = Vector4::new(0.3, -1.1, 0.8, 1.7);
    let (_, pd, ci) = implicit(&m, &q, &x, &qdot);
    // The printed Δ (cyclic) solves it.
    let solve = |delta: nalgebra::Matrix3<f64>| {
        twist_from_planar(
            &(io.j1.transpose() * delta)
                .lu()
                .solve(&(io.j1_bar * qdot))
                .unwrap(),
        )
    };
    let v = solve(polarity());
    assert!((v.w.z - pd).abs() < 1e-9 * pd.abs());
    // Its transpose (the other cyclic shift) does not.
    let wrong = solve(polarity().transpose());
    let c1 = Vector2::new(
        wrong.v.x - wrong.w.z * cfg.corners[0].y,
        wrong.v.y + wrong.w.z * cfg.corners[0].x,
    );
    assert!((c1 - ci[0]).norm() > 1e-3 * ci[0].norm());
    // Eq. 22 writes the joint m4–m1 with subscript 4; at C4 it would be reciprocal to s4, so
    // k4 of eq. 24 would vanish and eq. 25 degenerate: the joint is at C1.
    let s4 = cfg.forearm_line(3).unwrap();
    assert!(klein_form(&s4, &revolute(cfg.corners[3])).abs() < 1e-12);
    assert!(io.k4.abs() > 1.0, "k4 = {}", io.k4);
}

#[test]
fn errors_at_singular_and_bad_input() {
    let (cfg, ..) = configuration();
    let nan = Vector4::new(f64::NAN, 0.0, 0.0, 0.0);
    assert!(matches!(
        velocities(&cfg, &nan),
        Err(VelocityError::NonFinite { .. })
    ));
    // Forearm 3 parallel to m4 (C4C1): k2 = {s3; m3$m4 − m4$m1} = 0 (eq. 23).
    let mut c = cfg;
    let dir = (c.corners[0] - c.corners[3]).normalize();
    c.elbows[2] = c.corners[2] - 120.0 * dir;
    let err = velocities(&c, &Vector4::new(1.0, 0.0, 0.0, 0.0)).unwrap_err();
    assert!(
        matches!(err, VelocityError::Singular { quantity: "k2", .. }),
        "{err}"
    );
    // An elbow on its corner: no forearm line.
    let mut c = cfg;
    c.elbows[1] = c.corners[1];
    assert!(matches!(
        velocities(&c, &Vector4::zeros()),
        Err(VelocityError::DegenerateLine { line: "s2" })
    ));
    let msg = VelocityError::Singular {
        quantity: "k2",
        value: 0.0,
        equation: "23",
    }
    .to_string();
    assert!(!msg.contains('\n'));
}
