//! Rigid displacements (src/spatial): the exponential and logarithm through a half turn, the
//! adjoint (Murray, Li, Sastry, *A Mathematical Introduction to Robotic Manipulation*, 1994,
//! §2.3–2.4), and Study parameters against paper 004 (Nurahmi, Caro, Wenger, Schadlbauer,
//! Husty, *Reconfiguration analysis of a 4-RUU parallel manipulator*) eqs. 4–7, 11a and 12a,
//! with dual quaternions multiplied by a formula written only here.

use kinsyn::spatial::{
    self, Displacement, Twist, adjoint, compose, exp, inverse, inverse_left_jacobian, log,
    rotation_log, study, transform_twist,
};
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3, Vector4};
use proptest::prelude::*;
use std::f64::consts::PI;

// ---------------------------------------------------------------------------------------------
// Generators and independent formulas (test-only)

/// Rotation angles: uniform up to π − 1e-9, and the values next to 0 and π where the closed
/// forms cancel (exactly π has its own test).
fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => 0.0..(PI - 1e-9),
        1 => prop::sample::select(vec![
            0.0, 1e-300, 1e-15, 1e-12, 1e-9, 1e-8, 1e-6, 1e-4, 0.009, 0.011,
            PI - 1e-3, PI - 1e-6, PI - 1e-8, PI - 1e-9,
        ]),
    ]
}

fn unit_axis() -> impl Strategy<Value = Unit<Vector3<f64>>> {
    prop::array::uniform3(-1.0f64..1.0)
        .prop_filter("an axis", |a| Vector3::from(*a).norm() > 0.1)
        .prop_map(|a| Unit::new_normalize(Vector3::from(a)))
}

/// A displacement built without `exp`: nalgebra's axis–angle rotation and a translation.
fn displacement() -> impl Strategy<Value = Displacement> {
    (unit_axis(), angle(), prop::array::uniform3(-3.0f64..3.0)).prop_map(|(u, theta, t)| {
        spatial::displacement(Rotation3::from_axis_angle(&u, theta), Vector3::from(t))
    })
}

fn twist() -> impl Strategy<Value = Twist> {
    (
        prop::array::uniform3(-2.0f64..2.0),
        prop::array::uniform3(-2.0f64..2.0),
    )
        .prop_map(|(w, v)| Twist {
            w: Vector3::from(w),
            v: Vector3::from(v),
        })
}

fn close(a: &Displacement, b: &Displacement, tol: f64) -> bool {
    (a.rotation.matrix() - b.rotation.matrix()).amax() <= tol
        && (a.translation.vector - b.translation.vector).norm()
            <= tol * (1.0 + a.translation.vector.norm())
}

/// The Hamilton product of quaternions `(w, x, y, z)`, written out.
fn qmul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

fn conj(a: [f64; 4]) -> [f64; 4] {
    [a[0], -a[1], -a[2], -a[3]]
}

fn halves(s: &[f64; 8]) -> ([f64; 4], [f64; 4]) {
    ([s[0], s[1], s[2], s[3]], [s[4], s[5], s[6], s[7]])
}

/// The dual-quaternion product `(x_a + ε y_a)(x_b + ε y_b) = x_a x_b + ε (x_a y_b + y_a x_b)`
/// (ε² = 0; Husty et al. 2007 §2, Selig, *Geometric Fundamentals of Robotics*, ch. 9).
fn dual_product(a: &[f64; 8], b: &[f64; 8]) -> [f64; 8] {
    let (xa, ya) = halves(a);
    let (xb, yb) = halves(b);
    let x = qmul(xa, xb);
    let (p, q) = (qmul(xa, yb), qmul(ya, xb));
    [
        x[0],
        x[1],
        x[2],
        x[3],
        p[0] + q[0],
        p[1] + q[1],
        p[2] + q[2],
        p[3] + q[3],
    ]
}

/// Whether two sets of Study parameters are the same projective point: equal after each is
/// divided by its `|x|` and signed alike.
fn same_point(a: &[f64; 8], b: &[f64; 8], tol: f64) -> bool {
    let na = a[..4].iter().map(|c| c * c).sum::<f64>().sqrt();
    let nb = b[..4].iter().map(|c| c * c).sum::<f64>().sqrt();
    let dot: f64 = a[..4].iter().zip(&b[..4]).map(|(p, q)| p * q).sum();
    let sign = if dot < 0.0 { -1.0 } else { 1.0 };
    let scale = 1.0 + a[4..].iter().map(|c| c.abs()).fold(0.0, f64::max) / na;
    a.iter()
        .zip(b)
        .all(|(p, q)| (p / na - sign * q / nb).abs() <= tol * scale)
}

/// Eight numbers on the Study quadric, not built from a displacement: random `x`, and a random
/// `y` with its component along `x` removed, times a random non-zero factor.
fn on_quadric() -> impl Strategy<Value = [f64; 8]> {
    (
        prop::array::uniform4(-2.0f64..2.0),
        prop::array::uniform4(-2.0f64..2.0),
        prop_oneof![-1e3f64..-1e-3, 1e-3f64..1e3],
    )
        .prop_filter("x ≠ 0", |(x, _, _)| Vector4::from(*x).norm() > 0.1)
        .prop_map(|(x, y, k)| {
            let (x, y) = (Vector4::from(x), Vector4::from(y));
            let y = y - x * (x.dot(&y) / x.norm_squared());
            [x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3]].map(|c| c * k)
        })
}

// ---------------------------------------------------------------------------------------------
// exp and log (Murray–Li–Sastry §2.3)

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]
    /// exp ∘ log = id on SE(3) for rotation angles up to π − 1e-9 and down to 0: every
    /// displacement is the exponential of its logarithm (the exponential is onto, MLS §2.3).
    #[test]
    fn exp_of_log_is_the_identity_up_to_a_half_turn(g in displacement()) {
        let back = exp(&log(&g));
        prop_assert!(close(&back, &g, 1e-12), "{g:?} → {back:?}");
    }

    /// log ∘ exp = id on se(3) below a half turn: the logarithm returns the twist itself when
    /// its rotation angle is in [0, π) (MLS §2.3; the angle of `log` is in [0, π]).
    #[test]
    fn log_of_exp_is_the_identity_below_a_half_turn(
        u in unit_axis(), theta in angle(), v in prop::array::uniform3(-3.0f64..3.0),
    ) {
        let xi = Twist { w: u.into_inner() * theta, v: Vector3::from(v) };
        let back = log(&exp(&xi));
        let err = (back.to_vector() - xi.to_vector()).norm();
        // Up to π − 1e-9 the skew part of R (sin θ ≥ 1e-9) still fixes the sense of the axis,
        // and the symmetric part gives the axis itself to round-off.
        prop_assert!(err <= 1e-12 * (1.0 + xi.v.norm()), "{xi:?} → {back:?}: {err:e}");
    }
}

/// At exactly a half turn both senses of the axis are logarithms: `log` returns one of them,
/// with angle π, and `exp` of it is the displacement again.
#[test]
fn exp_of_log_at_exactly_a_half_turn() {
    let axes = [
        Vector3::x(),
        Vector3::y(),
        Vector3::z(),
        -Vector3::z(),
        Vector3::new(1.0, 1.0, 0.0),
        Vector3::new(0.3, -0.8, 0.52),
        Vector3::new(-1.0, -1.0, -1.0),
    ];
    for axis in axes {
        let u = Unit::new_normalize(axis);
        let g = spatial::displacement(
            Rotation3::from_axis_angle(&u, PI),
            Vector3::new(0.4, -1.1, 2.0),
        );
        let xi = log(&g);
        assert!(
            (xi.w.norm() - PI).abs() < 1e-12,
            "{axis}: angle {}",
            xi.w.norm()
        );
        assert!(
            xi.w.normalize().cross(&u).norm() < 1e-12,
            "{axis}: axis {}",
            xi.w
        );
        let back = exp(&xi);
        assert!(close(&back, &g, 1e-12), "{axis}: {g:?} → {back:?}");
    }
}

/// `rotation_log` near the identity, where nalgebra's `Rotation3::angle` and `scaled_axis` (an
/// `acos` of the trace) return 0 for every angle up to 1e-8 and are 5 % off at 2e-8, 1 % at
/// 1e-7 (nalgebra 0.35): the rotation vector is exact to round-off relative to the angle
/// itself, down to 1e-300.
#[test]
fn rotation_log_is_accurate_near_the_identity() {
    let u = Unit::new_normalize(Vector3::new(0.3, -0.8, 0.52));
    for theta in [1e-300, 1e-200, 1e-16, 1e-12, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2] {
        let r = rotation_log(&Rotation3::from_axis_angle(&u, theta));
        let err = (r - u.into_inner() * theta).norm();
        assert!(err <= 1e-14 * theta, "θ = {theta:e}: {r} ({err:e})");
    }
    assert_eq!(rotation_log(&Rotation3::identity()), Vector3::zeros());
}

/// `rotation_log` near a half turn, where the skew part of R vanishes: the angle is exact to
/// round-off and the axis is read from the symmetric part.
#[test]
fn rotation_log_is_accurate_near_a_half_turn() {
    let u = Unit::new_normalize(Vector3::new(-0.2, 0.9, 0.4));
    for gap in [0.0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 0.5] {
        let theta = PI - gap;
        let r = rotation_log(&Rotation3::from_axis_angle(&u, theta));
        assert!(
            (r.norm() - theta).abs() < 1e-14,
            "π − {gap:e}: angle {}",
            r.norm()
        );
        // Up to the sense at exactly π, the axis is u.
        assert!(
            r.normalize().cross(&u).norm() < 1e-9,
            "π − {gap:e}: axis {r}"
        );
        if gap > 1e-9 {
            assert!(r.dot(&u) > 0.0, "π − {gap:e}: sense of {r}");
        }
    }
}

/// ṙ = `J_l⁻¹(r)` ω: turning R by a small spatial rotation ω h changes its rotation vector by
/// `J_l⁻¹(r)` ω h, checked by central differences (angles up to 3 rad and near zero).
#[test]
fn rotation_vector_rates_match_finite_differences() {
    let h = 1e-6;
    for r in [
        Vector3::new(0.3, -0.2, 0.5),
        Vector3::new(1e-6, 2e-6, -1e-6),
        Vector3::new(2.0, 1.0, -1.5),
    ] {
        let j = inverse_left_jacobian(&r);
        for k in 0..3 {
            let w = Vector3::ith(k, 1.0);
            let turned = |s: f64| {
                rotation_log(&(Rotation3::from_scaled_axis(w * s) * Rotation3::from_scaled_axis(r)))
            };
            let fd = (turned(h) - turned(-h)) / (2.0 * h);
            assert!(
                (fd - j.column(k)).norm() < 1e-6,
                "r {r}, ω e{k}: {fd} vs {}",
                j.column(k)
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The adjoint (Murray–Li–Sastry §2.4)

proptest! {
    /// Ad_{g h} = Ad_g Ad_h: the adjoint is a representation of SE(3) on twists (MLS §2.4).
    #[test]
    fn adjoint_of_a_composition_is_the_product_of_adjoints(g in displacement(), h in displacement()) {
        let gh = compose(&g, &h);
        let lhs = adjoint(&gh.rotation, &gh.translation.vector);
        let rhs = adjoint(&g.rotation, &g.translation.vector) * adjoint(&h.rotation, &h.translation.vector);
        prop_assert!((lhs - rhs).amax() < 1e-12 * (1.0 + g.translation.vector.norm() + h.translation.vector.norm()));
        // And Ad_{g⁻¹} = (Ad_g)⁻¹.
        let gi = inverse(&g);
        let product = adjoint(&gi.rotation, &gi.translation.vector) * adjoint(&g.rotation, &g.translation.vector);
        prop_assert!((product - nalgebra::Matrix6::identity()).amax() < 1e-12 * (1.0 + g.translation.vector.norm()));
    }

    /// `transform_twist` is the adjoint matrix applied to the twist's coordinates.
    #[test]
    fn transform_twist_is_the_adjoint_times_the_twist(g in displacement(), t in twist()) {
        let by_matrix = adjoint(&g.rotation, &g.translation.vector) * t.to_vector();
        let direct = transform_twist(&g.rotation, &g.translation.vector, &t).to_vector();
        prop_assert!((by_matrix - direct).amax() < 1e-13 * (1.0 + g.translation.vector.norm()) * (1.0 + t.v.norm()));
    }

    /// exp(Ad_g ξ) = g exp(ξ) g⁻¹: the adjoint is the derivative of conjugation (MLS §2.4).
    #[test]
    fn exp_of_the_adjoint_is_conjugation(g in displacement(), xi in twist()) {
        let moved = Twist::from_vector(&(adjoint(&g.rotation, &g.translation.vector) * xi.to_vector()));
        let lhs = exp(&moved);
        let rhs = compose(&compose(&g, &exp(&xi)), &inverse(&g));
        prop_assert!(close(&lhs, &rhs, 1e-11), "{lhs:?} vs {rhs:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Study parameters (paper 004 §3)

/// The matrix M of paper 004 eqs. 4–5 as the plain-text copy prints it, one entry per line:
/// `M_T[i] = 2 Σ sign · x_j y_k` over the triples of row i, transcribed independently of
/// `study::matrix`.
const PRINTED_M_T: [[(f64, usize, usize); 4]; 3] = [
    // 2(−x0y1 + x1y0 − x2y3 + x3y2)
    [(-1.0, 0, 1), (1.0, 1, 0), (-1.0, 2, 3), (1.0, 3, 2)],
    // 2(−x0y2 + x1y3 + x2y0 − x3y1)
    [(-1.0, 0, 2), (1.0, 1, 3), (1.0, 2, 0), (-1.0, 3, 1)],
    // 2(−x0y3 − x1y2 + x2y1 + x3y0)
    [(-1.0, 0, 3), (-1.0, 1, 2), (1.0, 2, 1), (1.0, 3, 0)],
];

fn printed_m_t(table: &[[(f64, usize, usize); 4]; 3], s: &[f64; 8]) -> Vector3<f64> {
    Vector3::from_fn(|i, _| {
        2.0 * table[i]
            .iter()
            .map(|&(sign, j, k)| sign * s[j] * s[4 + k])
            .sum::<f64>()
    })
}

/// M from the printed `M_T` (eq. 5) and the rotation of the quaternion x (nalgebra), both times
/// Δ = |x|² as eq. 4 has them.
fn printed_m(table: &[[(f64, usize, usize); 4]; 3], s: &[f64; 8]) -> nalgebra::Matrix4<f64> {
    let x = nalgebra::Quaternion::new(s[0], s[1], s[2], s[3]);
    let delta = x.norm_squared();
    let r = UnitQuaternion::from_quaternion(x).to_rotation_matrix();
    let mut m = nalgebra::Matrix4::zeros();
    m[(0, 0)] = delta;
    m.fixed_view_mut::<3, 1>(1, 0)
        .copy_from(&printed_m_t(table, s));
    m.fixed_view_mut::<3, 3>(1, 1)
        .copy_from(&(r.matrix() * delta));
    m
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]
    /// The quadric x0y0 + x1y1 + x2y2 + x3y3 = 0 and the normalisation x0² + … + x3² = 1
    /// (paper 004 eq. 7, g13, g14) hold for the Study parameters of every displacement, with
    /// kinsyn's sign x0 ≥ 0; and the parameters give the displacement back.
    #[test]
    fn every_displacement_lies_on_the_study_quadric(g in displacement()) {
        let s = study::from_displacement(&g);
        prop_assert!(study::quadric_residual(&s).abs() <= 1e-15 * (1.0 + g.translation.vector.norm()), "{s:?}");
        prop_assert!(study::normalisation_residual(&s).abs() <= 1e-15);
        prop_assert!(s[0] >= 0.0);
        prop_assert!(!study::normalise(&s).unwrap()[0].is_sign_negative());
        let back = study::to_displacement(&s, study::QUADRIC_TOLERANCE).unwrap();
        prop_assert!(close(&back, &g, 1e-14), "{g:?} → {back:?}");
    }

    /// Study(M(x)) = x up to scale and sign: eight numbers on the quadric, not normalised and
    /// not built from a displacement, give a matrix M (eq. 4) whose displacement
    /// (R = M_R/Δ, t = M_T/Δ, read here by hand) has the same Study parameters again.
    #[test]
    fn study_parameters_of_m_are_x_up_to_scale_and_sign(s in on_quadric()) {
        let m = study::matrix(&s);
        let delta = m[(0, 0)];
        let r: Matrix3<f64> = m.fixed_view::<3, 3>(1, 1) / delta;
        // M_R / Δ is a rotation for every x ≠ 0 (M_R M_Rᵀ = Δ² I, det M_R = Δ³).
        prop_assert!((r * r.transpose() - Matrix3::identity()).amax() < 1e-14);
        prop_assert!((r.determinant() - 1.0).abs() < 1e-14);
        let g = spatial::displacement(
            Rotation3::from_matrix_unchecked(r),
            Vector3::from(m.fixed_view::<3, 1>(1, 0) / delta),
        );
        let back = study::from_displacement(&g);
        prop_assert!(same_point(&back, &s, 1e-13), "{s:?} → {back:?}");
        // And to_displacement reads the same displacement from the unnormalised numbers.
        let direct = study::to_displacement(&s, study::QUADRIC_TOLERANCE).unwrap();
        prop_assert!(close(&direct, &g, 1e-13));
    }

    /// M acts on homogeneous points with the homogenising coordinate first, as paper 004
    /// writes its points (eqs. 2, 3) and applies M (eq. 9): M (1; p) = Δ (1; R p + t).
    #[test]
    fn m_moves_points_as_the_displacement(
        g in displacement(), p in prop::array::uniform3(-2.0f64..2.0), k in 0.1f64..10.0,
    ) {
        let s = study::from_displacement(&g).map(|c| -k * c);
        let m = study::matrix(&s);
        let p = Vector3::from(p);
        let image = m * nalgebra::Vector4::new(1.0, p.x, p.y, p.z);
        let delta = k * k;
        prop_assert!((image[0] - delta).abs() < 1e-12 * delta);
        let moved = Vector3::new(image[1], image[2], image[3]) / delta;
        prop_assert!((moved - (g.rotation * p + g.translation.vector)).norm() < 1e-12 * (1.0 + g.translation.vector.norm() + p.norm()));
    }

    /// The printed eq. 5 entry by entry: `study::matrix` is the transcription, and it equals the
    /// quaternion form M_R = Δ R(x), M_T = 2 vec(x ȳ) = −2 vec(y x̄) (Husty's sign) for any eight
    /// numbers, on the quadric or not.
    #[test]
    fn printed_m_is_the_quaternion_form(
        x in prop::array::uniform4(-2.0f64..2.0), y in prop::array::uniform4(-2.0f64..2.0),
    ) {
        prop_assume!(Vector4::from(x).norm() > 0.1);
        let s = [x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3]];
        prop_assert!((study::matrix(&s) - printed_m(&PRINTED_M_T, &s)).amax() < 1e-13);
        let xy = qmul(x, conj(y));
        let yx = qmul(y, conj(x));
        let m_t = printed_m_t(&PRINTED_M_T, &s);
        for i in 0..3 {
            prop_assert!((m_t[i] - 2.0 * xy[i + 1]).abs() < 1e-13);
            prop_assert!((m_t[i] + 2.0 * yx[i + 1]).abs() < 1e-13);
        }
    }

    /// Composition of displacements is the product of dual quaternions (Husty et al. 2007 §2):
    /// Study(a · b) = Study(a) ⊗ Study(b) up to sign, and M(a ⊗ b) = M(a) M(b) — with the
    /// product formula written only in this test.
    #[test]
    fn composition_is_the_product_of_dual_quaternions(a in displacement(), b in displacement()) {
        let (sa, sb) = (study::from_displacement(&a), study::from_displacement(&b));
        let product = dual_product(&sa, &sb);
        let composed = study::from_displacement(&compose(&a, &b));
        prop_assert!(same_point(&composed, &product, 1e-13), "{composed:?} vs {product:?}");
        let lhs = study::matrix(&product);
        let rhs = study::matrix(&sa) * study::matrix(&sb);
        prop_assert!((lhs - rhs).amax() < 1e-12 * (1.0 + a.translation.vector.norm()) * (1.0 + b.translation.vector.norm()));
    }
}

/// Eq. 5 as printed is consistent: M(a ⊗ b) = M(a) M(b) holds for the printed signs of `M_T`, and
/// fails when any single one of its twelve signs is flipped — so a sign lost or garbled in the
/// plain-text copy would have been caught, and the printed one is the only single-sign reading
/// that represents SE(3).
#[test]
fn every_printed_sign_of_m_t_is_needed() {
    let a = study::from_displacement(&exp(&Twist {
        w: Vector3::new(0.3, -0.7, 1.1),
        v: Vector3::new(0.5, 0.2, -0.9),
    }));
    let b = study::from_displacement(&exp(&Twist {
        w: Vector3::new(-0.8, 0.4, 0.25),
        v: Vector3::new(-1.2, 0.7, 0.3),
    }));
    let ab = dual_product(&a, &b);
    let mismatch = |table: &[[(f64, usize, usize); 4]; 3]| {
        (printed_m(table, &ab) - printed_m(table, &a) * printed_m(table, &b)).amax()
    };
    assert!(mismatch(&PRINTED_M_T) < 1e-12);
    for i in 0..3 {
        for k in 0..4 {
            let mut flipped = PRINTED_M_T;
            flipped[i][k].0 = -flipped[i][k].0;
            assert!(
                mismatch(&flipped) > 1e-3,
                "flipping term {k} of M_T[{i}] still composes"
            );
        }
    }
}

/// Paper 004 §2–3: the 4-RUU's first leg with a = 2, b = 1, l = 1, r = 2 (§4). `A1 = (a, 0, 0)`,
/// `B1 = (l cos θ11 + a, l sin θ11, 0)` (eq. 2), `C1 = (b, 0, 0)` on the platform (eq. 3),
/// `t11 = tan(θ11/2)` (eq. 8).
struct Leg1 {
    a: f64,
    b: f64,
    l: f64,
    r: f64,
}

const LEG1: Leg1 = Leg1 {
    a: 2.0,
    b: 1.0,
    l: 1.0,
    r: 2.0,
};

impl Leg1 {
    fn b_point(&self, theta: f64) -> Vector3<f64> {
        Vector3::new(self.l * theta.cos() + self.a, self.l * theta.sin(), 0.0)
    }

    /// g5, eq. 12a, term by term as printed.
    fn g5(&self, t: f64, s: &[f64; 8]) -> f64 {
        let Leg1 { a, b, l, r } = *self;
        let [x0, x1, x2, x3, y0, y1, y2, y3] = *s;
        let t2 = t * t;
        let k1 = a * a * t2 - 2.0 * a * b * t2 - 2.0 * a * l * t2
            + b * b * t2
            + 2.0 * b * l * t2
            + l * l * t2
            - r * r * t2
            + a * a
            - 2.0 * a * b
            + 2.0 * a * l
            + b * b
            - 2.0 * b * l
            + l * l
            - r * r;
        let k2 = a * a * t2 + 2.0 * a * b * t2 - 2.0 * a * l * t2 + b * b * t2 - 2.0 * b * l * t2
            + l * l * t2
            - r * r * t2
            + a * a
            + 2.0 * a * b
            + 2.0 * a * l
            + b * b
            + 2.0 * b * l
            + l * l
            - r * r;
        k1 * x0 * x0 - 8.0 * b * l * t * x0 * x3
            + (4.0 * a * t2 - 4.0 * b * t2 - 4.0 * l * t2 + 4.0 * a - 4.0 * b + 4.0 * l) * x0 * y1
            + 8.0 * l * t * x0 * y2
            + k1 * x1 * x1
            - 8.0 * b * l * t * x1 * x2
            + (-4.0 * a * t2 + 4.0 * b * t2 + 4.0 * l * t2 - 4.0 * a + 4.0 * b - 4.0 * l) * x1 * y0
            - 8.0 * l * t * x1 * y3
            + k2 * x2 * x2
            - 8.0 * l * t * x2 * y0
            + (4.0 * a * t2 + 4.0 * b * t2 - 4.0 * l * t2 + 4.0 * a + 4.0 * b + 4.0 * l) * x2 * y3
            + k2 * x3 * x3
            + 8.0 * l * t * x3 * y1
            + (-4.0 * a * t2 - 4.0 * b * t2 + 4.0 * l * t2 - 4.0 * a - 4.0 * b - 4.0 * l) * x3 * y2
            + (4.0 * t2 + 4.0) * (y0 * y0 + y1 * y1 + y2 * y2 + y3 * y3)
    }

    /// g1, eq. 11a, term by term as printed.
    fn g1(&self, t: f64, s: &[f64; 8]) -> f64 {
        let Leg1 { a, b, l, .. } = *self;
        let [x0, x1, x2, x3, y0, _, _, y3] = *s;
        let t2 = t * t;
        (a * t2 - b * t2 - l * t2 + a - b + l) * x0 * x1 + 2.0 * l * t * x0 * x2
            - (2.0 * t2 + 2.0) * x0 * y0
            + 2.0 * l * t * x3 * x1
            + (-a * t2 - b * t2 + l * t2 - a - b - l) * x3 * x2
            + (-2.0 * t2 - 2.0) * y3 * x3
    }
}

proptest! {
    /// Paper 004 eq. 12a (g5, the length r of link B1C1) is `(1 + t11²)(|C1 − B1|² − r²)` at the
    /// normalised Study parameters of any platform pose in kinsyn's convention (y = −½ t x): the
    /// paper's constraint equations use the same convention as its eq. 5 (the opposite sign
    /// fails, `the_opposite_sign_of_y_does_not_satisfy_paper_004`).
    #[test]
    fn paper_004_leg_length_equation_12a_in_this_convention(
        g in displacement(), theta in -3.0f64..3.0,
    ) {
        let s = study::from_displacement(&g);
        let t = (theta / 2.0).tan();
        let c = g.rotation * Vector3::new(LEG1.b, 0.0, 0.0) + g.translation.vector;
        let expected = (1.0 + t * t) * ((c - LEG1.b_point(theta)).norm_squared() - LEG1.r * LEG1.r);
        let g5 = LEG1.g5(t, &s);
        prop_assert!((g5 - expected).abs() < 1e-11 * (1.0 + expected.abs()), "{g5} vs {expected}");
    }

    /// Paper 004 eq. 11a (g1: B1C1 coplanar with v1 = Z and n1 = R z, eq. 10) is
    /// `−½ (1 + t11²) (C1 − B1) · (Z × R z)` at the normalised Study parameters of any pose: the
    /// same triple product up to the constant the paper's clearing of denominators left.
    #[test]
    fn paper_004_coplanarity_equation_11a_in_this_convention(
        g in displacement(), theta in -3.0f64..3.0,
    ) {
        let s = study::from_displacement(&g);
        let t = (theta / 2.0).tan();
        let c = g.rotation * Vector3::new(LEG1.b, 0.0, 0.0) + g.translation.vector;
        let n = g.rotation * Vector3::z();
        let triple = (c - LEG1.b_point(theta)).dot(&Vector3::z().cross(&n));
        let expected = -0.5 * (1.0 + t * t) * triple;
        let g1 = LEG1.g1(t, &s);
        prop_assert!((g1 - expected).abs() < 1e-11 * (1.0 + expected.abs()), "{g1} vs {expected}");
    }
}

/// The sign with y negated (the common dual-quaternion convention x + ε ½ t x) fails eq. 12a at
/// a worked pose — a quarter turn about x and a translation (0.5, −0.3, 0.8), θ11 = 0.7 — where
/// kinsyn's sign meets it: negating y reads the translation as −t.
#[test]
fn the_opposite_sign_of_y_does_not_satisfy_paper_004() {
    let g = spatial::displacement(
        Rotation3::from_axis_angle(&Vector3::x_axis(), PI / 2.0),
        Vector3::new(0.5, -0.3, 0.8),
    );
    let theta: f64 = 0.7;
    let t = (theta / 2.0).tan();
    let s = study::from_displacement(&g);
    let c = g.rotation * Vector3::new(LEG1.b, 0.0, 0.0) + g.translation.vector;
    let expected = (1.0 + t * t) * ((c - LEG1.b_point(theta)).norm_squared() - LEG1.r * LEG1.r);
    assert!((LEG1.g5(t, &s) - expected).abs() < 1e-12);
    let flipped = [s[0], s[1], s[2], s[3], -s[4], -s[5], -s[6], -s[7]];
    assert!((LEG1.g5(t, &flipped) - expected).abs() > 0.1);
}

// ---------------------------------------------------------------------------------------------
// Normalisation, sign and errors

/// kinsyn's sign: x0 ≥ 0, and at x0 = 0 the first non-zero of x1, x2, x3 positive; scale is
/// removed whatever its magnitude (1e-200 to 1e200).
#[test]
#[expect(
    clippy::float_cmp,
    reason = "the norms here (1, 2, 3) divide these components exactly: the sign and scale \
              must come out bit for bit"
)]
fn normalisation_chooses_x0_nonnegative() {
    let s = [-0.5, 0.5, -0.5, 0.5, 0.1, 0.2, 0.3, 0.4];
    let n = study::normalise(&s).unwrap();
    assert_eq!(n, [0.5, -0.5, 0.5, -0.5, -0.1, -0.2, -0.3, -0.4]);
    let half_turn = [0.0, -2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    assert_eq!(
        study::normalise(&half_turn).unwrap(),
        [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -0.5, 0.0]
    );
    let half_turn = [0.0, 0.0, 0.0, -3.0, 0.0, 0.0, 0.0, 0.0];
    assert_eq!(study::normalise(&half_turn).unwrap()[3], 1.0);
    for k in [1e-200, 1e-20, 1.0, 1e20, 1e200] {
        let n = study::normalise(&s.map(|c| c * k)).unwrap();
        assert!(
            study::normalisation_residual(&n).abs() < 1e-15,
            "scale {k:e}"
        );
        assert!((n[4] + 0.1).abs() < 1e-15, "scale {k:e}: {n:?}");
    }
    // A half turn's parameters from a displacement: x0 = cos(π/2) rounds to +6e-17.
    let s = study::from_displacement(&spatial::displacement(
        Rotation3::from_axis_angle(&Vector3::y_axis(), PI),
        Vector3::new(1.0, 2.0, 3.0),
    ));
    assert!(
        s[0] >= 0.0 && s[0] < 1e-16 && (s[2].abs() - 1.0).abs() < 1e-15,
        "{s:?}"
    );
}

/// Near the identity the parameters carry the small rotation to full relative accuracy
/// (x⃗ = sin(θ/2) u from `rotation_log`, not from the trace) and give it back.
#[test]
fn study_parameters_near_the_identity() {
    let u = Unit::new_normalize(Vector3::new(1.0, 2.0, -2.0));
    for theta in [1e-300, 1e-16, 1e-10, 1e-6] {
        let g = spatial::displacement(Rotation3::from_axis_angle(&u, theta), Vector3::zeros());
        let s = study::from_displacement(&g);
        let xv = Vector3::new(s[1], s[2], s[3]);
        let expected = u.into_inner() * (theta / 2.0).sin();
        assert!((xv - expected).norm() <= 1e-15 * theta, "θ {theta:e}: {xv}");
        let back = study::to_displacement(&s, study::QUADRIC_TOLERANCE).unwrap();
        assert!((rotation_log(&back.rotation) - u.into_inner() * theta).norm() <= 1e-14 * theta);
    }
}

/// Eq. 7's inequality and equation as errors: x = 0 (the exceptional generator), a point off
/// the quadric beyond the tolerance (relative residual |x·y| / (|x||y|)), non-finite numbers.
#[test]
fn study_errors() {
    use study::StudyError;
    let tol = study::QUADRIC_TOLERANCE;
    assert_eq!(
        study::to_displacement(&[0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0], tol),
        Err(StudyError::ExceptionalGenerator)
    );
    assert_eq!(
        study::to_displacement(&[0.0; 8], tol),
        Err(StudyError::ExceptionalGenerator)
    );
    assert_eq!(
        study::normalise(&[f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
        Err(StudyError::NotFinite)
    );
    assert_eq!(
        study::to_displacement(&[1.0, 0.0, 0.0, f64::INFINITY, 0.0, 0.0, 0.0, 0.0], tol),
        Err(StudyError::NotFinite)
    );
    // y along x: as far off the quadric as it can be (residual 1).
    let e = study::to_displacement(&[1.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0], tol).unwrap_err();
    assert_eq!(
        e,
        StudyError::OffQuadric {
            residual: 1.0,
            tolerance: tol
        }
    );
    assert!(e.to_string().contains("quadric"), "{e}");
    // Just inside and just outside a tolerance, independent of scale and unit of length.
    let s = study::from_displacement(&spatial::displacement(
        Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4),
        Vector3::new(1.0, 2.0, 3.0),
    ));
    let y = Vector4::new(s[4], s[5], s[6], s[7]);
    let x = Vector4::new(s[0], s[1], s[2], s[3]);
    for scale in [1e-6, 1.0, 1e6] {
        for (eps, ok) in [(1e-10, true), (1e-8, false)] {
            let yp = (y + x * (eps * y.norm())) * scale;
            let off = [s[0], s[1], s[2], s[3], yp[0], yp[1], yp[2], yp[3]];
            assert_eq!(
                study::to_displacement(&off, tol).is_ok(),
                ok,
                "scale {scale:e}, ε {eps:e}"
            );
        }
    }
}

/// The old paths are the same items: `chain::Displacement`, `chain::compose`,
/// `mechanism::{exp, log, inverse, rotation_log}`, `screw::{Twist, adjoint, skew,
/// transform_twist}` are re-exports of `spatial`.
#[test]
fn old_paths_are_re_exports() {
    let g: kinsyn::chain::Displacement = spatial::identity();
    let xi = kinsyn::screw::Twist {
        w: Vector3::new(0.1, 0.2, 0.3),
        v: Vector3::new(1.0, 0.0, 0.0),
    };
    let moved: Twist = kinsyn::screw::transform_twist(&g.rotation, &g.translation.vector, &xi);
    assert_eq!(moved, xi);
    let h = kinsyn::mechanism::exp(&xi);
    assert_eq!(h, spatial::exp(&xi));
    assert_eq!(kinsyn::chain::compose(&g, &h), h);
    assert_eq!(kinsyn::mechanism::log(&h), spatial::log(&h));
    assert_eq!(kinsyn::mechanism::inverse(&h), spatial::inverse(&h));
    assert_eq!(
        kinsyn::mechanism::rotation_log(&h.rotation),
        spatial::rotation_log(&h.rotation)
    );
    assert_eq!(
        kinsyn::screw::adjoint(&h.rotation, &h.translation.vector),
        adjoint(&h.rotation, &h.translation.vector)
    );
    assert_eq!(kinsyn::screw::skew(&xi.w), spatial::skew(&xi.w));
}
