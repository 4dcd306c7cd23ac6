//! Series-parallel manipulators (src/series.rs) against paper 002 (Nayak, Caro, Wenger, *Local
//! and full-cycle mobility analysis of a 3-RPS-3-SPR series-parallel manipulator*, CK 2017):
//! the Jacobian of eqs. 2–8 against finite differences of the leg lengths, the misprinted
//! augmented rotation of eq. 5, the twist system of eqs. 9–10, and the mobility of Table 1's
//! configurations.
//!
//! The geometry is the paper's (§2, Table 1): equilateral platforms of circum-radii h0 = 2 (base),
//! h1 = 1 (coupler), h2 = 2 (end-effector), `x_i` towards vertex `A_i`, vertices at 0°, 120°, 240°;
//! 3-RPS revolute axes at the base vertices, tangent to the circumcircle, S centres at the coupler
//! vertices; 3-SPR S centres at the coupler vertices, revolute axes at the end-effector vertices,
//! tangent. Configurations are made here, independently of the library: the poses satisfy the
//! revolute constraints (Newton on the pose parameters, finite-difference Jacobian), and the
//! reference Jacobian moves each leg length by ±ε and solves the module's closure again.

use kinsyn::screw::{self, DEFAULT_RANK_TOLERANCE, adjoint};
use kinsyn::spatial::{Displacement, displacement, rotation_log, study};
use kinsyn_papers::series::{
    AugmentedRotation, Leg, Module, SeriesParallel, augmented_rotation, reference_shift,
};
use nalgebra::{DMatrix, DVector, Rotation3, Vector3, Vector6};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

// ---------------------------------------------------------------------------------------------
// The 3-RPS and 3-SPR modules of paper 002 §2, written here from the description.

/// Vertex `i` (0, 1, 2 for A, B, C) of a platform of circum-radius `h`, in its own frame.
fn vertex(h: f64, i: usize) -> Vector3<f64> {
    let (s, c) = (120.0 * i as f64).to_radians().sin_cos();
    h * Vector3::new(c, s, 0.0)
}

/// The unit tangent of the circumcircle at vertex `i`, in the platform's plane.
fn tangent(i: usize) -> Vector3<f64> {
    let (s, c) = (120.0 * i as f64).to_radians().sin_cos();
    Vector3::new(-s, c, 0.0)
}

#[derive(Debug, Clone, Copy)]
enum Kind {
    /// R at the lower vertex (tangent axis), S at the upper vertex.
    Rps,
    /// S at the lower vertex, R at the upper vertex (tangent axis in the upper platform).
    Spr,
}

/// A module type with its two circum-radii; its pose is six numbers
/// `(x, y, z, roll, pitch, yaw)`: `R = Rz(yaw) Ry(pitch) Rx(roll)`.
#[derive(Debug, Clone, Copy)]
struct Spec {
    kind: Kind,
    lower: f64,
    upper: f64,
}

const PROX: Spec = Spec {
    kind: Kind::Rps,
    lower: 2.0,
    upper: 1.0,
};
const DIST: Spec = Spec {
    kind: Kind::Spr,
    lower: 1.0,
    upper: 2.0,
};

fn pose(p: &[f64; 6]) -> Displacement {
    displacement(
        Rotation3::from_euler_angles(p[3], p[4], p[5]),
        Vector3::new(p[0], p[1], p[2]),
    )
}

/// Per leg, in the lower frame: the S centre, the other end of the prismatic joint, the
/// revolute axis.
fn leg_points(spec: Spec, g: &Displacement) -> [(Vector3<f64>, Vector3<f64>, Vector3<f64>); 3] {
    let apply = |x: Vector3<f64>| g.rotation * x + g.translation.vector;
    std::array::from_fn(|i| match spec.kind {
        Kind::Rps => (
            apply(vertex(spec.upper, i)),
            vertex(spec.lower, i),
            tangent(i),
        ),
        Kind::Spr => (
            vertex(spec.lower, i),
            apply(vertex(spec.upper, i)),
            g.rotation * tangent(i),
        ),
    })
}

/// Leg lengths `ρ_i` (S centre to the revolute's vertex) and the revolute constraints (the leg
/// normal to the revolute axis).
fn lengths_and_constraints(spec: Spec, g: &Displacement) -> ([f64; 3], [f64; 3]) {
    let legs = leg_points(spec, g);
    (
        legs.map(|(s, other, _)| (s - other).norm()),
        legs.map(|(s, other, axis)| axis.dot(&(s - other))),
    )
}

/// The library's description of the module at pose `g`.
fn module(spec: Spec, g: &Displacement) -> Module {
    let legs = leg_points(spec, g).map(|(centre, other, axis)| {
        let actuation = match spec.kind {
            Kind::Rps => (centre - other).normalize(),
            Kind::Spr => (other - centre).normalize(),
        };
        Leg {
            centre,
            actuation,
            constraint: axis,
        }
    });
    Module { pose: *g, legs }
}

/// Newton on the pose parameters listed in `free`, the others held, for the residual `f`
/// (as many equations as free parameters); a central-difference Jacobian.
fn newton(p: &mut [f64; 6], free: &[usize], f: &dyn Fn(&[f64; 6]) -> DVector<f64>) {
    for _ in 0..60 {
        let r = f(p);
        if r.norm() < 1e-14 {
            return;
        }
        let h = 1e-7;
        let mut jac = DMatrix::zeros(r.len(), free.len());
        for (c, &k) in free.iter().enumerate() {
            let (mut a, mut b) = (*p, *p);
            a[k] += h;
            b[k] -= h;
            jac.set_column(c, &((f(&a) - f(&b)) / (2.0 * h)));
        }
        let step = jac.lu().solve(&(-r)).expect("a regular closure Jacobian");
        for (c, &k) in free.iter().enumerate() {
            p[k] += step[c];
        }
    }
    assert!(
        f(p).norm() < 1e-11,
        "Newton did not converge: {}",
        f(p).norm()
    );
}

/// A pose of the module with `(z, roll, pitch)` as given and `(x, y, yaw)` solved from the three
/// revolute constraints (paper 002 §2: each S centre in the plane normal to its revolute axis).
fn assemble(spec: Spec, z: f64, roll: f64, pitch: f64) -> [f64; 6] {
    let mut p = [0.0, 0.0, z, roll, pitch, 0.0];
    newton(&mut p, &[0, 1, 5], &|p| {
        DVector::from_row_slice(&lengths_and_constraints(spec, &pose(p)).1)
    });
    p
}

/// The pose with leg lengths `rho`, from the nearby pose `p` (the module's direct kinematics).
fn drive(spec: Spec, p: &[f64; 6], rho: [f64; 3]) -> [f64; 6] {
    let mut q = *p;
    newton(&mut q, &[0, 1, 2, 3, 4, 5], &|q| {
        let (l, c) = lengths_and_constraints(spec, &pose(q));
        DVector::from_fn(6, |k, _| if k < 3 { l[k] - rho[k] } else { c[k - 3] })
    });
    q
}

fn spm(stack: &[(Spec, [f64; 6])]) -> SeriesParallel {
    SeriesParallel::new(stack.iter().map(|(s, p)| module(*s, &pose(p))).collect()).expect("modules")
}

fn end_effector(stack: &[(Spec, [f64; 6])]) -> Displacement {
    stack
        .iter()
        .fold(Displacement::identity(), |g, (_, p)| g * pose(p))
}

/// The reference Jacobian: for each leg, its length moved by ±ε with the others held, the
/// module's pose solved again, and the end-effector twist `(ω; v_{O_n})` in base axes from the
/// two end-effector poses by central differences (paper 002 eq. 7's definition of `J_S-PM`).
fn finite_difference_jacobian(stack: &[(Spec, [f64; 6])]) -> DMatrix<f64> {
    let eps = 1e-6;
    let mut j = DMatrix::zeros(6, 3 * stack.len());
    for (m, (spec, p)) in stack.iter().enumerate() {
        let rho = lengths_and_constraints(*spec, &pose(p)).0;
        for k in 0..3 {
            let moved = |sign: f64| {
                let mut r = rho;
                r[k] += sign * eps;
                let mut s = stack.to_vec();
                s[m].1 = drive(*spec, p, r);
                end_effector(&s)
            };
            let (gp, gm) = (moved(1.0), moved(-1.0));
            let w = rotation_log(&(gp.rotation * gm.rotation.inverse())) / (2.0 * eps);
            let v = (gp.translation.vector - gm.translation.vector) / (2.0 * eps);
            j.set_column(3 * m + k, &Vector6::new(w.x, w.y, w.z, v.x, v.y, v.z));
        }
    }
    j
}

/// A random assemblable 3-RPS-3-SPR (paper 002 Fig. 1): heights, roll and pitch drawn, the
/// rest solved.
fn random_spm(rng: &mut ChaCha8Rng) -> Vec<(Spec, [f64; 6])> {
    let mut draw = |spec: Spec| {
        assemble(
            spec,
            rng.random_range(1.2..2.0),
            rng.random_range(-0.5..0.5),
            rng.random_range(-0.5..0.5),
        )
    };
    let prox = draw(PROX);
    let dist = draw(DIST);
    vec![(PROX, prox), (DIST, dist)]
}

fn rank(m: &DMatrix<f64>) -> screw::Rank {
    screw::rank(m, DEFAULT_RANK_TOLERANCE)
}

/// The distance from `t` to the span of the columns of `m` (relative to |t|).
fn distance_to_span(m: &DMatrix<f64>, t: &Vector6<f64>) -> f64 {
    let (basis, _) = screw::span_basis(m, DEFAULT_RANK_TOLERANCE);
    let t = DVector::from_column_slice(t.as_slice());
    (&t - &basis * (basis.transpose() * &t)).norm() / t.norm()
}

// ---------------------------------------------------------------------------------------------
// Eqs. 2–7: the Jacobian against finite differences

/// Paper 002 eq. (7): `J_S-PM = [²Ad₁ A_PROX⁻¹ B_PROX, ⁰R̄₁ A_DIST⁻¹ B_DIST]` gives the
/// end-effector twist per unit leg rate; finite differences of the closure agree at random
/// configurations, and the library's eq. (8) for two modules is eq. (7) written out.
#[test]
fn eq7_jacobian_equals_finite_differences_at_random_configurations() {
    let mut rng = ChaCha8Rng::seed_from_u64(2002);
    for _ in 0..5 {
        let stack = random_spm(&mut rng);
        let s = spm(&stack);
        let j = s.jacobian().expect("no parallel singularity");
        let fd = finite_difference_jacobian(&stack);
        assert!((&j - &fd).amax() < 1e-6, "J = {j}, finite differences {fd}");

        // Eq. (7) term by term from eqs. (2)–(5).
        let [prox, dist] = [s.modules()[0], s.modules()[1]];
        let o1 = prox.pose.translation.vector;
        let o2 = (prox.pose * dist.pose).translation.vector;
        let b = Module::inverse_jacobian();
        let left = reference_shift(&o1, &o2) * prox.forward_jacobian().try_inverse().unwrap() * b;
        let right = augmented_rotation(&prox.pose.rotation)
            * dist.forward_jacobian().try_inverse().unwrap()
            * b;
        assert!((j.columns(0, 3) - left).amax() < 1e-12);
        assert!((j.columns(3, 3) - right).amax() < 1e-12);
    }
}

/// Paper 002 eq. (5) prints `⁰R̄₁ = [[R, I], [I, R]]`: with it, `J_S-PM` disagrees with finite
/// differences in the distal columns (documented in docs/deviations.md); the proximal columns,
/// which do not use it, still agree.
#[test]
fn eq5_printed_augmented_rotation_disagrees_with_finite_differences() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let stack = random_spm(&mut rng);
    let printed = spm(&stack)
        .jacobian_with(AugmentedRotation::AsPrinted)
        .unwrap();
    let fd = finite_difference_jacobian(&stack);
    assert!((printed.columns(0, 3) - fd.columns(0, 3)).amax() < 1e-6);
    let error = (printed.columns(3, 3) - fd.columns(3, 3)).amax();
    // The printed form adds the angular velocity to the linear one and back: an error of the
    // size of the twists themselves.
    assert!(error > 0.1, "printed R̄ error {error}");
}

/// Paper 002 §3–4 and Table 1 rows 2–3: at general configurations rank `J_S-PM` = order of
/// `⁰T_S-PM` = 6, with a clear gap.
#[test]
fn table1_general_configurations_have_mobility_six() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..10 {
        let s = spm(&random_spm(&mut rng));
        let j = rank(&s.jacobian().unwrap());
        let t = s.twist_system(DEFAULT_RANK_TOLERANCE);
        assert_eq!(j.rank, 6, "rank J_S-PM: {:?}", j.singular_values);
        assert_eq!(
            t.order.rank, 6,
            "order of T_S-PM: {:?}",
            t.order.singular_values
        );
        assert!(j.gap().0 > 1e-4 && t.order.gap().0 > 1e-4);
        assert_eq!(t.constraint_wrenches.ncols(), 0);
        // Each module's twist system is of order 3 (§4: three constraint forces per module).
        assert!(t.modules.iter().all(|m| m.ncols() == 3));
    }
}

/// Paper 002 eqs. (9)–(10): the twist system of each module is the span of its columns of
/// `J_S-PM` (both are the twists reciprocal to its constraint forces, referred to `O_2`).
#[test]
fn eq10_module_twist_systems_are_the_jacobian_blocks() {
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    let s = spm(&random_spm(&mut rng));
    let j = s.jacobian().unwrap();
    let t = s.twist_system(DEFAULT_RANK_TOLERANCE);
    for (m, twists) in t.modules.iter().enumerate() {
        let block = j.columns(3 * m, 3).into_owned();
        for c in 0..3 {
            let col = Vector6::from_iterator(block.column(c).iter().copied());
            assert!(distance_to_span(twists, &col) < 1e-9);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Table 1 rows 1 and 4: the singular configurations

/// Table 1 row 1, decoded from its Study parameters (paper 004's convention, `spatial::study`):
/// `x = (1:0:0:0:0:0:0:0.75)`, `y = (1:0:0:0:0:0:0:0.8)` — the three platforms parallel and
/// coaxial. The paper prints rank 5 (the rotation about the common vertical axis lost).
///
/// By hand: the constraint forces of both modules are then the *same* three lines — tangent to
/// the coupler's circumcircle through its vertices (3-RPS: through the S centre along `u_i`;
/// 3-SPR: through the same S centre along `v_i`, and `v_i ∥ u_i`). The two twist systems are
/// the same, the S-PM's is of order 3: the lost motions are the rotation about the common
/// vertical axis *and* the two horizontal translations; the common constraint wrench system is
/// spanned by the couple about the vertical and the horizontal forces through `O_1`. Finite
/// differences of the closure agree (rank 3). Table 1's 5 is what one gets by adding the
/// module twists without the screw transformation `²Ad₁` (the step §3 criticises in its
/// reference [4]); the printed `R̄` gives 6. docs/deviations.md records this.
#[test]
fn table1_row1_coaxial_platforms() {
    let decode = |s: [f64; 8]| {
        let g = study::to_displacement(&s, study::QUADRIC_TOLERANCE).unwrap();
        let (roll, pitch, yaw) = g.rotation.euler_angles();
        let t = g.translation.vector;
        [t.x, t.y, t.z, roll, pitch, yaw]
    };
    let stack = vec![
        (PROX, decode([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.75])),
        (DIST, decode([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.8])),
    ];
    for (spec, p) in &stack {
        let c = lengths_and_constraints(*spec, &pose(p)).1;
        assert!(c.iter().all(|x| x.abs() < 1e-12), "row 1 is assembled");
    }
    let s = spm(&stack);
    let j = s.jacobian().unwrap();
    let fd = finite_difference_jacobian(&stack);
    assert!((&j - &fd).amax() < 1e-6);
    assert_eq!(rank(&j).rank, 3, "{:?}", rank(&j).singular_values);
    assert_eq!(rank(&fd).rank, 3);
    let t = s.twist_system(DEFAULT_RANK_TOLERANCE);
    assert_eq!(t.order.rank, 3);

    // The lost motions, in the Jacobian's convention (ω; v at O_2, base axes): the rotation
    // about the common vertical axis (O_2 on it: v = 0), the translations along x and y.
    let z = Vector3::z();
    let lost = [
        Vector6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, 1.0, 0.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0),
    ];
    let mut all = j.clone();
    for l in &lost {
        // Far from the span: the nearest motions are rotations about horizontal lines in the
        // coupler plane, whose velocity at O_2 mixes in |O_1O_2| = 1.6 times the rotation.
        assert!(
            distance_to_span(&j, l) > 0.5,
            "{l} is not a motion of the S-PM"
        );
        let last = all.ncols();
        all = all.insert_column(last, 0.0);
        all.set_column(last, l);
    }
    assert_eq!(rank(&all).rank, 6, "J and the lost motions span all twists");

    // The common constraint wrenches, (f; m) with moments about O_2: the couple about the
    // vertical and the horizontal forces through O_1.
    let o1 = s.modules()[0].pose.translation.vector;
    let o2 = s.poses()[2].translation.vector;
    assert!(
        o1.x.abs() < 1e-12 && o1.y.abs() < 1e-12 && o2.x.abs() < 1e-12,
        "coaxial"
    );
    let force = |f: Vector3<f64>| {
        let m = (o1 - o2).cross(&f);
        Vector6::new(f.x, f.y, f.z, m.x, m.y, m.z)
    };
    let expected = [
        Vector6::new(0.0, 0.0, 0.0, z.x, z.y, z.z),
        force(Vector3::x()),
        force(Vector3::y()),
    ];
    assert_eq!(t.constraint_wrenches.ncols(), 3);
    for w in &expected {
        assert!(distance_to_span(&t.constraint_wrenches, w) < 1e-9);
    }

    // What reproduces the printed 5: the module twists added as they are, the proximal one at
    // O_1 and the distal one at O_2 (no ²Ad₁) — missing only the rotation about the vertical.
    let [prox, dist] = [s.modules()[0], s.modules()[1]];
    let mut naive = DMatrix::zeros(6, 6);
    naive
        .fixed_view_mut::<6, 3>(0, 0)
        .copy_from(&prox.input_twists().unwrap());
    naive
        .fixed_view_mut::<6, 3>(0, 3)
        .copy_from(&(augmented_rotation(&prox.pose.rotation) * dist.input_twists().unwrap()));
    assert_eq!(rank(&naive).rank, 5);
    assert!(distance_to_span(&naive, &lost[0]) > 0.999);
    // And the printed R̄ (eq. 5) with R = I mixes ω and v: rank 6.
    let printed = s.jacobian_with(AugmentedRotation::AsPrinted).unwrap();
    assert_eq!(rank(&printed).rank, 6);
}

/// Table 1 row 4's situation: a revolute axis of the end-effector parallel to the corresponding
/// axis of the base. Both platforms turned about the y axis only (as in row 4, whose Study
/// parameters have only `x0, x2` and `y0, y2` rotational), so `v_1 ∥ u_1 ∥ y`. Paper 002 §4:
/// mobility 5, with a constraint force `f` parallel to the two axes. By hand it is the force
/// along y through the coupler vertex `A_1`: both modules' first constraint force (through the S
/// centre `A_1`, along `u_1` and along `v_1`).
#[test]
fn table1_row4_parallel_revolute_axes() {
    for (pitch1, pitch2) in [(-0.2, 0.9), (0.35, -0.6), (0.1, 0.4)] {
        let stack = vec![
            (PROX, assemble(PROX, 1.9, 0.0, pitch1)),
            (DIST, assemble(DIST, 1.4, 0.0, pitch2)),
        ];
        let s = spm(&stack);
        let poses = s.poses();
        let v1 = poses[2].rotation * tangent(0);
        assert!(v1.cross(&tangent(0)).norm() < 1e-12, "v_1 ∥ u_1");
        let j = s.jacobian().unwrap();
        let fd = finite_difference_jacobian(&stack);
        assert!((&j - &fd).amax() < 1e-6);
        let r = rank(&j);
        assert_eq!(r.rank, 5, "{:?}", r.singular_values);
        assert!(r.gap().0 > 1e-4, "one motion lost, not more");
        let t = s.twist_system(DEFAULT_RANK_TOLERANCE);
        assert_eq!(t.order.rank, 5);
        assert_eq!(t.constraint_wrenches.ncols(), 1);

        // The common constraint wrench, (f; m) about O_2: a pure force along y through A_1.
        let w = t.constraint_wrenches.column(0);
        let f = Vector3::new(w[0], w[1], w[2]);
        let m = Vector3::new(w[3], w[4], w[5]);
        assert!(
            f.cross(&Vector3::y()).norm() < 1e-9 * f.norm(),
            "f ∥ u_1, v_1"
        );
        let a1 = poses[1].rotation * vertex(1.0, 0) + poses[1].translation.vector;
        let expected = (a1 - poses[2].translation.vector).cross(&f);
        assert!((m - expected).norm() < 1e-9, "the force passes through A_1");
        // It does no work on any twist the Jacobian gives.
        let swapped = Vector6::new(m.x, m.y, m.z, f.x, f.y, f.z);
        assert!((swapped.transpose() * &j).amax() < 1e-9);
    }
}

// ---------------------------------------------------------------------------------------------
// Eq. 8: n modules

/// Paper 002 eq. (8) for three modules (3-RPS, 3-SPR, 3-RPS): the Jacobian equals the direct
/// composition of the module twists as spatial twists (Murray–Li–Sastry's adjoint of each lower
/// body's pose, then referred to `O_3`), and finite differences; rank 6 at a general
/// configuration.
#[test]
fn eq8_three_modules_equal_direct_composition() {
    let third = Spec {
        kind: Kind::Rps,
        lower: 2.0,
        upper: 1.0,
    };
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut stack = random_spm(&mut rng);
    stack.push((third, assemble(third, 1.6, 0.3, -0.25)));
    let s = spm(&stack);
    let j = s.jacobian().unwrap();
    assert_eq!(j.ncols(), 9);

    let poses = s.poses();
    let o3 = poses[3].translation.vector;
    let mut direct = DMatrix::zeros(6, 9);
    for (i, m) in s.modules().iter().enumerate() {
        // (ω; v at O_i) in F_{i−1} → (ω; v at the origin of F_{i−1}) → F_0 at its origin → at O_3.
        let at_origin = adjoint(&Rotation3::identity(), &m.pose.translation.vector);
        let to_base = adjoint(&poses[i].rotation, &poses[i].translation.vector);
        let to_o3 = adjoint(&Rotation3::identity(), &(-o3));
        direct
            .fixed_view_mut::<6, 3>(0, 3 * i)
            .copy_from(&(to_o3 * to_base * at_origin * m.input_twists().unwrap()));
    }
    assert!((&j - &direct).amax() < 1e-12);
    let fd = finite_difference_jacobian(&stack);
    assert!((&j - &fd).amax() < 1e-6);
    let r = rank(&j);
    assert_eq!(r.rank, 6);
    assert_eq!(s.twist_system(DEFAULT_RANK_TOLERANCE).order.rank, 6);
}

/// A module in a parallel singularity is reported with its number and rank (paper 002 §3,
/// footnote 1: eq. 7 needs `A` invertible); the twist system is still defined.
#[test]
fn parallel_singularity_is_a_typed_error() {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let stack = random_spm(&mut rng);
    let mut modules: Vec<Module> = stack.iter().map(|(sp, p)| module(*sp, &pose(p))).collect();
    // The distal legs' actuation forces made parallel to their constraint forces: rank A ≤ 5.
    for leg in &mut modules[1].legs {
        leg.actuation = leg.constraint;
    }
    let s = SeriesParallel::new(modules).unwrap();
    match s.jacobian() {
        Err(kinsyn_papers::series::SeriesError::ParallelSingularity { module, rank, .. }) => {
            assert_eq!(module, 2);
            assert!(rank <= 5);
        }
        other => panic!("expected a parallel singularity, got {other:?}"),
    }
    assert!(SeriesParallel::new(Vec::new()).is_err());
}
