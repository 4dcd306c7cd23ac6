//! Paper 002 (Nayak, Caro, Wenger, "Local and full-cycle mobility analysis of a 3-RPS-3-SPR
//! series-parallel manipulator", CK2017), Table 1: the four printed configurations of the
//! 3-RPS-3-SPR S-PM with h0 = 2, h1 = 1, h2 = 2 (`mechanisms/multibody/3-rps-3-spr.json`), their
//! Study parameters `x` (coupler frame F1 from the base frame F0) and `y` (end-effector frame
//! F2 from F1, §5), and the printed rank of `J_S-PM` (5, 6, 6, 5).
//!
//! The printed parameters are rounded to two decimals, so the legs' plane conditions (each S
//! centre in the plane through its R joint normal to the R axis) hold only to about 1e-2: each
//! row is checked on those conditions directly, then projected onto the constraint set
//! (Gauss–Newton on the two poses, least change) and assembled by
//! [`Manipulator::solve_poses`]; the end-effector's dof there is the paper's rank. Where the
//! printed values cannot be a configuration of this geometry, the test asserts that, with the
//! residual as the proof (docs/deviations.md, "Paper 002 — 3-RPS-3-SPR").

use kinsyn::chain::Displacement;
use kinsyn::manipulator::{Manipulator, ManipulatorError, PRINTED_STUDY_TOLERANCE, PositionError};
use kinsyn::mechanism::{compose, exp};
use kinsyn::screw::Twist;
use kinsyn::spatial::study::{self, StudyParameters};
use nalgebra::{DMatrix, DVector, Point3, Vector3};

const FILE: &str = "mechanisms/multibody/3-rps-3-spr.json";

/// Table 1, rows 1–4: `x`, `y` as printed.
const ROWS: [(StudyParameters, StudyParameters); 4] = [
    (
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.75],
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.8],
    ),
    (
        [0.35, -0.9, 0.25, 0.0, 0.57, 0.27, -1.76, -1.33],
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.8],
    ),
    (
        [0.99, 0.0, -0.10, 0.0, 0.0, 0.21, 0.0, 1.92],
        [-0.79, -0.59, 0.16, 0.0, -0.16, -0.13, -1.25, -2.04],
    ),
    (
        [0.99, 0.0, -0.10, 0.0, 0.0, 0.21, 0.0, 1.92],
        [-0.39, 0.0, 0.92, 0.0, 0.0, -1.88, 0.0, 0.12],
    ),
];

fn load() -> Manipulator {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../");
    let text = std::fs::read_to_string(format!("{root}{FILE}")).unwrap();
    Manipulator::from_json(&text).unwrap()
}

/// Vertex `i` (A, B, C) of an equilateral triangle of circum-radius `h` in its frame (§2).
fn vertex(h: f64, i: usize) -> Vector3<f64> {
    let a = 2.0 * std::f64::consts::PI / 3.0 * f64::from(u8::try_from(i).unwrap());
    Vector3::new(h * a.cos(), h * a.sin(), 0.0)
}

/// The tangent R axis at vertex `i`, in the platform's frame: `z × OA/|OA|`.
fn tangent(i: usize) -> Vector3<f64> {
    Vector3::z().cross(&vertex(1.0, i))
}

fn apply(g: &Displacement, p: &Vector3<f64>) -> Vector3<f64> {
    g.transform_point(&Point3::from(*p)).coords
}

/// The six plane conditions of §5 for the coupler frame `f1` and end-effector frame `f2`:
/// 3-RPS, `u_i · (A1 − A0) = 0`; 3-SPR, `v_i · (A1 − A2) = 0` (ground frame, lengths in m).
fn planes(f1: &Displacement, f2: &Displacement) -> [f64; 6] {
    let mut r = [0.0; 6];
    for i in 0..3 {
        let s = apply(f1, &vertex(1.0, i));
        r[i] = tangent(i).dot(&(s - vertex(2.0, i)));
        r[3 + i] = (f2.rotation * tangent(i)).dot(&(s - apply(f2, &vertex(2.0, i))));
    }
    r
}

/// The displacement of printed Study parameters, in kinsyn's sign (`sign` = 1, paper 004:
/// `y = −½ t x`) or the opposite one (`sign` = −1: `y` negated, the translation reversed).
fn displacement(s: &StudyParameters, sign: f64) -> Displacement {
    let mut s = *s;
    for c in &mut s[4..] {
        *c *= sign;
    }
    study::to_displacement(&s, PRINTED_STUDY_TOLERANCE).unwrap()
}

fn largest(r: &[f64]) -> f64 {
    r.iter().fold(0.0, |m, c| m.max(c.abs()))
}

/// The least change of the two frames (twists applied on the left, ground frame) that meets
/// the six plane conditions: Gauss–Newton with minimum-norm steps, Jacobian by central
/// differences. Returns the frames and the size of the change (rad and m, largest component).
fn project(f1: &Displacement, f2: &Displacement) -> (Displacement, Displacement, f64) {
    let moved = |p: &DVector<f64>| {
        let t = |k: usize| {
            exp(&Twist::from_vector(&nalgebra::Vector6::from_iterator(
                p.rows(6 * k, 6).iter().copied(),
            )))
        };
        (compose(&t(0), f1), compose(&t(1), f2))
    };
    let mut p = DVector::zeros(12);
    for _ in 0..30 {
        let (g1, g2) = moved(&p);
        let r = DVector::from_row_slice(&planes(&g1, &g2));
        if r.amax() < 1e-14 {
            break;
        }
        let mut j = DMatrix::zeros(6, 12);
        for k in 0..12 {
            let h = 1e-7;
            let (mut a, mut b) = (p.clone(), p.clone());
            a[k] += h;
            b[k] -= h;
            let (a1, a2) = moved(&a);
            let (b1, b2) = moved(&b);
            let d = (DVector::from_row_slice(&planes(&a1, &a2))
                - DVector::from_row_slice(&planes(&b1, &b2)))
                / (2.0 * h);
            j.set_column(k, &d);
        }
        let step = j.transpose() * (&j * j.transpose()).try_inverse().unwrap() * r;
        p -= step;
    }
    let (g1, g2) = moved(&p);
    (g1, g2, p.amax())
}

/// The end-effector's dof and the mobility at the configuration with the coupler frame at
/// `f1` and the end-effector frame at `f2`, assembled from the reference by
/// [`Manipulator::solve_poses`].
fn dof_at(m: &Manipulator, f1: &Displacement, f2: &Displacement) -> (usize, usize) {
    let q = m
        .solve_poses(&m.reference(), &[(0, *f1), (1, *f2)])
        .unwrap_or_else(|e| panic!("the projected poses assemble: {e}"));
    let ee = m.end_effector();
    (
        m.body_twists(ee, &q, &[]).1,
        m.mechanism().mobility(&q, &vec![false; q.len()]).dof,
    )
}

/// Table 1's Study parameters in both conventions: the plane residuals for F2 = X∘Y (§5) and,
/// for the record, F2 = Y∘X (y read in the base frame).
fn residuals(row: usize) -> Vec<(f64, bool, [f64; 6])> {
    let (x, y) = ROWS[row];
    let mut out = Vec::new();
    for sign in [1.0, -1.0] {
        let (fx, fy) = (displacement(&x, sign), displacement(&y, sign));
        out.push((sign, false, planes(&fx, &compose(&fx, &fy))));
        out.push((sign, true, planes(&fx, &compose(&fy, &fx))));
    }
    out
}

#[test]
fn table_1_row_1_parallel_platforms_assemble_with_five_dof() {
    // Table 1 row 1: x = (1:0:0:0:0:0:0:0.75), y = (1:0:0:0:0:0:0:0.8); printed rank 5.
    let m = load();
    let (x, y) = ROWS[0];
    // Pure translations along z: every plane condition holds exactly, in both signs
    // (u_i, v_i horizontal and tangent, the vertices on their radial planes).
    for (sign, _, r) in residuals(0) {
        assert!(largest(&r) < 1e-12, "Table 1 row 1, sign {sign}: {r:?}");
    }
    // kinsyn's sign (paper 004): the coupler 2·0.75 = 1.5 below the base, the end-effector 1.6
    // below the coupler (the file's reference hangs on that side too).
    let frames = m
        .frames_from_study(&[x, y], PRINTED_STUDY_TOLERANCE)
        .unwrap();
    assert!((frames[0].1.translation.vector - Vector3::new(0.0, 0.0, -1.5)).norm() < 1e-12);
    assert!((frames[1].1.translation.vector - Vector3::new(0.0, 0.0, -3.1)).norm() < 1e-12);
    let q = m
        .solve_study(&m.reference(), &[x, y], PRINTED_STUDY_TOLERANCE)
        .unwrap();
    // Table 1 row 1 prints rank 5; kinsyn finds 3, a documented deviation. Hand derivation:
    // the coupler is the plane z = −1.5 and every R axis is horizontal, so the proximal
    // constraint forces (along u_i through A1, B1, C1, eq. 9) and the distal ones (along v_i
    // through the same A1, B1, C1) are coplanar forces of that plane, both spanning the same
    // 3-system {fx, fy, mz about a point of it}. Both modules' twist systems are its reciprocal,
    // {tz, rotations about lines of the plane}, the same 3-system, and their sum has order 3.
    let paper_rank = 5;
    let dof = m.body_twists(m.end_effector(), &q, &[]).1;
    assert_eq!(
        dof, 3,
        "Table 1 row 1 (paper: {paper_rank}; docs/deviations.md)"
    );
    // Grübler (hand): 6·(15 − 1) − 6·13 = 6 joint-rate freedoms, the modules' 3 + 3.
    assert_eq!(m.mechanism().mobility(&q, &vec![false; q.len()]).dof, 6);
}

#[test]
fn table_1_row_2_x_is_off_the_study_quadric() {
    // Table 1 row 2: x = (0.35:−0.9:0.25:0:0.57:0.27:−1.76:−1.33): x·y = 0.1995 − 0.243 − 0.44
    // = −0.4835 (hand), |x| = 1.0, |y| = 2.29: relative residual 0.21, ten times what rounding to
    // two decimals allows (PRINTED_STUDY_TOLERANCE = 2e-2): a misprint, no displacement.
    let m = load();
    let (x, y) = ROWS[1];
    assert!(
        (study::quadric_residual(&x) + 0.4835).abs() < 1e-12,
        "Table 1 row 2"
    );
    let e = m
        .frames_from_study(&[x, y], PRINTED_STUDY_TOLERANCE)
        .unwrap_err();
    assert!(e.to_string().contains("off the Study quadric"), "{e}");
    // Read anyway (the quadric ignored), the coupler misses the 3-RPS planes by more than 1 m
    // in every convention: documented deviation, the printed rank 6 cannot be checked here.
    let mut relaxed = x;
    let f = |s: &StudyParameters, sign: f64| {
        let mut s = *s;
        for c in &mut s[4..] {
            *c *= sign;
        }
        study::to_displacement(&s, 1.0).unwrap()
    };
    for sign in [1.0, -1.0] {
        let (fx, fy) = (f(&relaxed, sign), f(&y, sign));
        let r = planes(&fx, &compose(&fx, &fy));
        assert!(largest(&r[..3]) > 1.0, "Table 1 row 2, sign {sign}: {r:?}");
    }
    relaxed[5] = -relaxed[5];
    assert!(study::relative_quadric_residual(&relaxed) < 2e-3);
}

#[test]
fn table_1_row_3_distal_module_misses_its_planes() {
    // Table 1 row 3: printed rank 6. The proximal planes hold to the rounding (|r| ≤ 0.04) in
    // both signs, the distal ones miss by 0.37 m or more in every reading (sign, X∘Y or Y∘X):
    // the printed y is no configuration of this 3-SPR (documented deviation).
    for (sign, yx, r) in residuals(2) {
        assert!(largest(&r[..3]) < 0.04, "Table 1 row 3, sign {sign}: {r:?}");
        assert!(
            largest(&r[3..]) > 0.3,
            "Table 1 row 3, sign {sign}, Y∘X {yx}: {r:?}"
        );
    }
    let m = load();
    let e = m
        .solve_study(
            &m.reference(),
            &[ROWS[2].0, ROWS[2].1],
            PRINTED_STUDY_TOLERANCE,
        )
        .unwrap_err();
    let ManipulatorError::Position(PositionError::PosesNotAssembled { residual, .. }) = e else {
        panic!("Table 1 row 3: {e}");
    };
    assert!(residual > 1e-3, "Table 1 row 3: residual {residual}");
}

#[test]
fn table_1_row_4_assembles_with_y_in_the_base_frame_with_five_dof() {
    // Table 1 row 4: printed rank 5 (a revolute axis of the end-effector parallel to the base's,
    // §4). Read as §5 says (F2 = X∘Y) it misses the distal planes by 0.35 m or more; with
    // kinsyn's sign and F2 = Y∘X (y the coupler-to-end-effector displacement written in F0) every
    // plane holds to the rounding (documented deviation).
    for (sign, yx, r) in residuals(3) {
        if yx && sign > 0.0 {
            assert!(largest(&r) < 0.03, "Table 1 row 4, Y∘X: {r:?}");
        } else if !yx {
            assert!(largest(&r[3..]) > 0.3, "Table 1 row 4, sign {sign}: {r:?}");
        }
    }
    let (x, y) = ROWS[3];
    let m = load();
    let fx = displacement(&x, 1.0);
    let fy = displacement(&y, 1.0);
    // As printed, the poses miss an assembly by the rounding: refused, with the residual.
    let e = m
        .solve_poses(&m.reference(), &[(0, fx), (1, compose(&fy, &fx))])
        .unwrap_err();
    let ManipulatorError::Position(PositionError::PosesNotAssembled { residual, .. }) = e else {
        panic!("Table 1 row 4: {e}");
    };
    assert!(
        residual > 1e-4 && residual < 0.1,
        "Table 1 row 4: residual {residual}"
    );
    // Projected (least change, a few centimetres and milliradians), it assembles.
    let (g1, g2, change) = project(&fx, &compose(&fy, &fx));
    assert!(change < 0.05, "Table 1 row 4: projection moves {change}");
    let (dof, mobility) = dof_at(&m, &g1, &g2);
    assert_eq!(dof, 5, "Table 1 row 4: rank of J_S-PM 5");
    assert_eq!(mobility, 6, "Grübler: 6·(15 − 1) − 6·13 = 6");
}
