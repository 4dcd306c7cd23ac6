//! The library of hand-written manipulators (`tests/library/*.json`): for each file,
//!
//! - **dof and motion pattern** from the literature (each file's `source` and the comment at its
//!   test cite the paper or give the first-principles derivation), checked against the
//!   platform's twist space at the reference configuration and against the finite-motion
//!   classification `Manipulator::mode` with no input locked, over three seeds;
//! - **`J_I` by finite differences of the inverse kinematics**: at the reference and at two more
//!   assembled poses, the platform frame is moved by `exp(±h t)` for each basis twist `t` of its
//!   allowed twist space, the legs are solved by loop closure with the platform held
//!   (`assemble_at`), and the central difference of every input joint's value must equal
//!   `(J_D row · t) / J_I entry` for that input's actuation row (rows `(f; m_P)` acting on
//!   `(v_P; ω)` at P). This is independent of how the actuation wrench was chosen: a wrench that
//!   is really a constraint gives `J_I = 0` there, or the wrong rate;
//! - **no zero `J_I` entry** at those generic poses, measured dimensionlessly.
//!
//! The expected values come from the literature, hand derivations (in the files' `source` and
//! the comments here) or finite differences; none is copied from kinsyn's output.

use kinsyn::chain::Displacement;
use kinsyn::manipulator::{Manipulator, RowKind};
use kinsyn::mechanism::SampleSettings;
use kinsyn::motion::{GroupKind, Pattern};
use kinsyn::notation::Primitive;
use nalgebra::{DVector, Matrix3, Rotation3, Vector3};

fn load(name: &str) -> Manipulator {
    let path = format!("tests/library/{name}.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Manipulator::from_json(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The platform motion the literature gives with every input free.
enum Motion {
    /// One of the displacement groups, with its direction (or plane normal) and its point
    /// (centre of S) when it has them.
    Group {
        kind: GroupKind,
        direction: Option<Vector3<f64>>,
        point: Option<Vector3<f64>>,
    },
    /// Not a group: `nTmR`.
    NonGroup(&'static str),
}

fn group(kind: GroupKind) -> Motion {
    Motion::Group {
        kind,
        direction: None,
        point: None,
    }
}

/// Checks the platform's dof and motion pattern with no input locked.
fn check_pattern(name: &str, dof: usize, expected: &Motion) {
    let m = load(name);
    // The reference is generic: its instantaneous dof is the literature's.
    let (_, local) = m.mechanism().twist_space(m.platform(), &m.reference(), &[]);
    assert_eq!(local, dof, "{name}: platform dof at the reference");
    for seed in [2026, 1, 2] {
        let settings = SampleSettings {
            seed,
            ..SampleSettings::default()
        };
        let mode = m.mode(&[], &settings);
        assert!(
            mode.error.is_none(),
            "{name}, seed {seed}: {:?}",
            mode.error
        );
        assert_eq!(mode.dof, dof, "{name}, seed {seed}: dof");
        let c = mode.classification.expect("sampled");
        match (expected, c.pattern) {
            (Motion::NonGroup(text), p) => {
                assert_eq!(p.to_string(), *text, "{name}, seed {seed}: pattern");
            }
            (
                Motion::Group {
                    kind,
                    direction,
                    point,
                },
                Pattern::Group(g),
            ) => {
                assert_eq!(g.kind, *kind, "{name}, seed {seed}: group {}", c.pattern);
                if let Some(d) = direction {
                    let got = Vector3::from(g.direction.expect("a direction"));
                    assert!(
                        got.cross(&d.normalize()).norm() < 1e-6,
                        "{name}, seed {seed}: direction {got} vs {d}"
                    );
                }
                if let Some(p) = point {
                    let got = Vector3::from(g.point.expect("a point"));
                    assert!(
                        (got - p).norm() < 1e-6,
                        "{name}, seed {seed}: point {got} vs {p}"
                    );
                }
            }
            (Motion::Group { kind, .. }, p) => {
                panic!("{name}, seed {seed}: {p} is not the group {kind:?}")
            }
        }
    }
}

/// A length to make twists and wrenches dimensionless (the test's own choice, not kinsyn's):
/// the RMS distance of the revolute joints' points from P at the reference.
fn length(m: &Manipulator) -> f64 {
    let p = m.point(&m.reference());
    let d: Vec<f64> = m
        .mechanism()
        .joints()
        .iter()
        .filter(|j| j.kind == Primitive::R)
        .map(|j| (j.point - p).norm_squared())
        .collect();
    (d.iter().sum::<f64>() / d.len() as f64).sqrt()
}

/// `exp` of the spatial twist `(w; v)` (v: velocity of the point at the origin), written out:
/// rotation `exp([w])`, translation `V v` with `V = I + a [w] + b [w]²`, `a = (1 − cos θ)/θ²`,
/// `b = (θ − sin θ)/θ³` (Murray, Li & Sastry 1994, eq. 2.36), by their series for small θ.
fn exp(w: &Vector3<f64>, v: &Vector3<f64>) -> (Rotation3<f64>, Vector3<f64>) {
    let theta = w.norm();
    let (a, b) = if theta < 1e-3 {
        let t2 = theta * theta;
        (0.5 - t2 / 24.0 + t2 * t2 / 720.0, 1.0 / 6.0 - t2 / 120.0)
    } else {
        (
            (1.0 - theta.cos()) / (theta * theta),
            (theta - theta.sin()) / (theta * theta * theta),
        )
    };
    let k = Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0);
    let vmap = Matrix3::identity() + k * a + k * k * b;
    (Rotation3::from_scaled_axis(*w), vmap * v)
}

/// The rotation vector of `r`, accurate for small angles: the angle from `atan2(sin θ, cos θ)`
/// with `sin θ` read from the skew part (nalgebra's `scaled_axis` takes `acos` of the trace,
/// which loses about half the digits of a rotation of 1e-6 rad). Used below π/2 only.
fn rotation_vector(r: &Rotation3<f64>) -> Vector3<f64> {
    let m = r.matrix();
    let skew = Vector3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    ) / 2.0;
    let sin = skew.norm();
    let cos = (m.trace() - 1.0) / 2.0;
    assert!(cos > 0.0, "a turn beyond π/2");
    if sin == 0.0 {
        return Vector3::zeros();
    }
    skew * (sin.atan2(cos) / sin)
}

/// The joint values with the platform frame at `exp(s (w; v)) · frame`, the legs solved by loop
/// closure with the platform held.
fn solve(
    m: &Manipulator,
    frame: &Displacement,
    w: &Vector3<f64>,
    v: &Vector3<f64>,
    s: f64,
) -> Result<Vec<f64>, String> {
    let (r, d) = exp(&(w * s), &(v * s));
    let moved = (r * frame.rotation, r * frame.translation.vector + d);
    m.assemble_at(moved.1, rotation_vector(&moved.0), &[])
        .map_err(|e| e.to_string())
}

/// Step of the central differences (dimensionless: radians, lengths over [`length`]).
const H: f64 = 1e-6;
/// Agreement asked of a finite difference, relative to 1 + the rate (dimensionless).
const TOLERANCE: f64 = 1e-6;
/// A `J_I` entry smaller than this (dimensionless, per unit wrench) counts as zero.
const ZERO: f64 = 1e-6;

/// What a check found wrong at one configuration.
#[derive(Default)]
struct Findings {
    /// Finite differences that disagree with `J_D t / J_I`.
    rates: Vec<String>,
    /// Inputs without an actuation row or with a zero `J_I` entry.
    zeros: Vec<String>,
}

/// Checks `J_I` at joint values `q` by finite differences of the inverse kinematics.
fn check_at(m: &Manipulator, q: &[f64], what: &str, found: &mut Findings) {
    let len = length(m);
    let j = m.jacobians(q, &[]);
    let p = j.point;
    let frame = m.platform_frame(q);
    let (basis, dof) = m.mechanism().twist_space(m.platform(), q, &[]);
    // The actuation row of each input, its J_I entry, and the entry made dimensionless:
    // entry × (joint unit) over the norm of (f·len; m_P).
    let mut inputs = Vec::new();
    for (a, act) in m.actuators().iter().enumerate() {
        let label = act.label();
        let unit = if act.kind == Primitive::P { len } else { 1.0 };
        let Some(k) = j
            .rows
            .iter()
            .position(|r| r.kind == RowKind::Actuation { actuator: a })
        else {
            found
                .zeros
                .push(format!("{what}: {label} has no actuation row"));
            continue;
        };
        let col = j.free.iter().position(|&f| f == a).expect("a free input");
        let entry = j.ji[(k, col)];
        let wrench = j.jd.row(k);
        let size = (Vector3::new(wrench[0], wrench[1], wrench[2]) * len).norm_squared()
            + Vector3::new(wrench[3], wrench[4], wrench[5]).norm_squared();
        let dimensionless = entry * unit / size.sqrt();
        if dimensionless.abs() <= ZERO || !dimensionless.is_finite() {
            found.zeros.push(format!(
                "{what}: {label}: J_I entry {entry:e} (dimensionless {dimensionless:e}), wrench {:?}",
                wrench.iter().collect::<Vec<_>>()
            ));
        }
        inputs.push((act.joint, label, unit, k, entry));
    }
    for c in 0..dof {
        // The basis twist (ω; v) at the origin, as (v_P; ω) at P, scaled to a unit
        // dimensionless twist (ω; v_P / len).
        let mut w = Vector3::new(basis[(0, c)], basis[(1, c)], basis[(2, c)]);
        let mut v = Vector3::new(basis[(3, c)], basis[(4, c)], basis[(5, c)]);
        let mut vp = v + w.cross(&p);
        let n = (w.norm_squared() + (vp / len).norm_squared()).sqrt();
        w /= n;
        v /= n;
        vp /= n;
        let t = DVector::from_vec(vec![vp.x, vp.y, vp.z, w.x, w.y, w.z]);
        // Every constraint row (locked or structural) must annihilate an allowed twist.
        for (k, row) in j.rows.iter().enumerate() {
            if !matches!(row.kind, RowKind::Actuation { .. }) {
                let power = (j.jd.row(k) * &t)[0];
                if power.abs() > 1e-9 * len {
                    found.rates.push(format!(
                        "{what}: twist {c}: constraint row {k} ({:?}) does work {power:e}",
                        row.kind
                    ));
                }
            }
        }
        let (plus, minus) = match (solve(m, &frame, &w, &v, H), solve(m, &frame, &w, &v, -H)) {
            (Ok(a), Ok(b)) => (a, b),
            (a, b) => {
                found.rates.push(format!(
                    "{what}: twist {c}: the moved platform does not assemble: {:?} {:?}",
                    a.err(),
                    b.err()
                ));
                continue;
            }
        };
        for (joint, label, unit, k, entry) in &inputs {
            let fd = (plus[*joint] - minus[*joint]) / (2.0 * H);
            let jdt = (j.jd.row(*k) * &t)[0];
            let predicted = jdt / entry;
            let error = (fd - predicted).abs() / unit;
            let agrees = error <= TOLERANCE * (1.0 + (fd / unit).abs()); // false for NaN
            if !agrees {
                found.rates.push(format!(
                    "{what}: {label}, twist {c}: finite difference {fd:.9} vs J_D·t / J_I = \
                     {jdt:.3e} / {entry:.3e} = {predicted:.9}"
                ));
            }
        }
    }
}

/// The reference and two more poses reached by the platform's own motion (short random walks
/// with all inputs free, each then assembled from the reference by `assemble_at`, as the finite
/// differences are, so that both use one branch of the inverse kinematics).
fn poses(m: &Manipulator) -> Vec<(String, Vec<f64>)> {
    let settings = SampleSettings {
        samples: 2,
        steps: 4,
        step: 0.2,
        seed: 7,
    };
    let walks = m
        .mechanism()
        .sample_motion(m.platform(), &m.reference(), &[], &settings)
        .expect("the platform moves");
    let mut out = vec![("reference".to_string(), m.reference())];
    for walk in walks.samples {
        let g = m.platform_frame(&walk.q);
        let (r, o) = (g.rotation, g.translation.vector);
        let q = m
            .assemble_at(o, rotation_vector(&r), &[])
            .expect("the walked pose assembles from the reference");
        let back = m.platform_frame(&q);
        assert!(
            (back.translation.vector - o).norm() < 1e-9
                && (back.rotation.matrix() - r.matrix()).norm() < 1e-9,
            "{back:?} vs {:?}",
            (r, o)
        );
        assert!(
            q.iter().any(|x| x.abs() > 5e-3),
            "the walk hardly moved: {q:?}"
        );
        out.push((
            format!("pose {:.3?} turned {:.3?}", o, rotation_vector(&r)),
            q,
        ));
    }
    out
}

fn findings(name: &str) -> Findings {
    let m = load(name);
    let mut found = Findings::default();
    for (what, q) in poses(&m) {
        check_at(&m, &q, &format!("{name} at the {what}"), &mut found);
    }
    found
}

/// `J_I` against finite differences of the inverse kinematics, at three poses.
fn check_rates(name: &str) {
    let f = findings(name);
    assert!(f.rates.is_empty(), "{}", f.rates.join("\n"));
}

/// No zero `J_I` entry (and an actuation row for every input) at three generic poses.
fn check_no_zero_entry(name: &str) {
    let f = findings(name);
    assert!(f.zeros.is_empty(), "{}", f.zeros.join("\n"));
}

/// Three tests per file: pattern, rates, zero entries.
macro_rules! library {
    ($module:ident, $file:literal, $dof:expr, $motion:expr) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;
            #[test]
            fn dof_and_motion_pattern() {
                check_pattern($file, $dof, &$motion);
            }
            #[test]
            fn input_jacobian_by_finite_differences() {
                check_rates($file);
            }
            #[test]
            fn input_jacobian_has_no_zero_entry() {
                check_no_zero_entry($file);
            }
        }
    };
}

// Tsai 1996; Di Gregorio & Parenti-Castelli 1998: with the base U's first axis parallel to the
// platform U's last and the inner axes parallel, each UPU leg's constraint is one couple
// (perpendicular to both U axes); three independent couples forbid every rotation: T3, 3 dof.
// The actuation wrench of the slider is the force along the leg through both U centres.
library!(upu_3_tsai, "3-upu", 3, group(GroupKind::T3));

// Kong & Gosselin 2002: a CRR leg with all four axes parallel to u_i allows X(u_i) (two couples
// perpendicular to u_i as constraints); three independent oblique u_i leave T3, 3 dof. The
// slider's actuation wrench is a force along u_i.
library!(crr_3_oblique, "3-crr", 3, group(GroupKind::T3));

// Carretero, Podhorodeski, Nahon & Gosselin 2000: 3 dof, z translation and two rotations about
// horizontal axes independent, the other three parasitic: 1T2R, not a group. (The constraint
// forces are horizontal, so v_z is free and ω is bound by one equation: rotation rank 2.)
library!(prs_3, "3-prs", 3, Motion::NonGroup("1T2R"));

// Hunt 1983; Lee & Shah 1988: the 3-RPS has 3 dof, 1T2R with parasitic motion (paper 000 §5.2).
library!(rps_3, "3-rps", 3, Motion::NonGroup("1T2R"));

// Kong & Gosselin 2004 (type synthesis of TPMs): the RUU leg with the base R and the outer U
// axes parallel and the inner U axes parallel has one constraint couple (perpendicular to both
// directions); three independent couples leave T3, 3 dof. The actuation wrench of the base R is the force along the middle link.
library!(ruu_3_translational, "3-ruu", 3, group(GroupKind::T3));

// Gosselin & Angeles 1989: all axes through N = (0.1, −0.2, 0.6): S(N), 3 dof. The actuation
// wrench of a base R is the couple perpendicular to the leg's other two axes.
library!(
    rrr_3_spherical,
    "3-rrr-spherical",
    3,
    Motion::Group {
        kind: GroupKind::S,
        direction: None,
        point: Some(Vector3::new(0.1, -0.2, 0.6)),
    }
);

// Gosselin & Angeles 1990; Bonev, Zlatanov & Gosselin 2003: all axes along z: G(xy), 3 dof.
library!(
    rpr_3_planar,
    "3-rpr-planar",
    3,
    Motion::Group {
        kind: GroupKind::G,
        direction: Some(Vector3::z()),
        point: None,
    }
);

// The planar 3-RRR (Gosselin & Angeles; Bonev et al. 2003) in the plane normal to
// n = (0.2, −0.3, 1): G(n), 3 dof.
library!(
    rrr_3_planar_oblique,
    "3-rrr-planar-oblique",
    3,
    Motion::Group {
        kind: GroupKind::G,
        direction: Some(Vector3::new(0.2, -0.3, 1.0)),
        point: None,
    }
);

// Paper 004 (Nurahmi et al. 2016) §2 and §4: in the first Schönflies mode the 4-RUU's platform
// has 3T1R about z, X(z), 4 dof. Each leg's constraint is a horizontal couple (perpendicular to
// Z and to its inner U axis); the four span the two horizontal couples.
library!(
    ruu_4_schoenflies,
    "4-ruu",
    4,
    Motion::Group {
        kind: GroupKind::X,
        direction: Some(Vector3::z()),
        point: None,
    }
);

// Gough 1962, Stewart 1965, Merlet 2006: 6 dof, every displacement, D.
library!(ups_6_gough_stewart, "6-ups", 6, group(GroupKind::D));

// Planar five-bar (Cervantes-Sánchez & Rendón-Sánchez 1999): mobility 3(5 − 1) − 2·5 = 2; the
// platform link B1C turns and translates in the plane: 2 dof, rotation rank 1, 1T1R.
library!(five_bar_planar, "5r-planar", 2, Motion::NonGroup("1T1R"));

// Spherical five-bar (Ouerfelli & Kumar 1994): spherical mobility 3(5 − 1) − 2·5 = 2, every
// axis through one centre: the platform link only turns, 2 dof, 0T2R.
library!(
    five_bar_spherical,
    "5r-spherical",
    2,
    Motion::NonGroup("0T2R")
);

// Bonev, Zlatanov & Gosselin 2003: three planar PPR legs: G(xy), 3 dof.
library!(
    ppr_3_planar,
    "3-ppr-planar",
    3,
    Motion::Group {
        kind: GroupKind::G,
        direction: Some(Vector3::z()),
        point: None,
    }
);

// First principles (the file's source), after Kong & Gosselin: X(u_1) ∩ X(u_2) ∩ G(n) = the
// translations normal to n, T2(n), 2 dof; the slider rates are u_i·v. Legs 1 and 2 have couple
// constraints, leg 3 a force along n and two couples.
library!(
    translational_2_crr_rrr,
    "2t-crr-rrr",
    2,
    Motion::Group {
        kind: GroupKind::T2,
        direction: Some(Vector3::new(0.1, 0.2, 1.0)),
        point: None,
    }
);

#[test]
fn the_library_has_at_least_twelve_hand_written_files_with_a_source() {
    // At least 12 manipulators written by hand, each citing its source; none is the output of
    // `kinsyn build` (whose `source` is the command).
    let mut count = 0;
    for entry in std::fs::read_dir("tests/library").unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "json") {
            let text = std::fs::read_to_string(&path).unwrap();
            let d = kinsyn::manipulator::file::Description::from_json(&text).unwrap();
            let source = d.source.unwrap_or_default();
            assert!(
                source.len() > 40 && !source.starts_with("kinsyn build"),
                "{}: {source}",
                path.display()
            );
            count += 1;
        }
    }
    assert!(count >= 12, "{count} files");
}

#[test]
fn finite_differences_of_the_couple_constrained_legs_match_hand_derived_rates() {
    // The finite-difference method itself, checked where kinsyn's J_I is in doubt (legs constrained
    // by couples, where it was wrong before the trustworthy manipulator analysis): at the
    // reference, along the platform motions the literature allows (translations; for the 4-RUU also
    // the rotation about z through P), each input's rate from assemble_at equals a rate derived by
    // hand from the leg's geometry, with v_C = v_P + ω × (C − P) the velocity of the leg's platform
    // point C:
    // - 3-UPU: the slider is the distance |C − A| of the U centres, so ḋ = f·v_C, f = (C − A)/|C − A|;
    // - 3-CRR and the CRR legs of the 2-dof translational one: revolutes about axes parallel to u move no point along u, so u·(C − A) changes by
    //   the slider alone: ḋ = u·v_C;
    // - 3-RUU, 4-RUU: the middle link keeps its length |C − B| and B turns about the base R
    //   (v_B = θ̇ u × (B − A)), so f·(v_C − v_B) = 0 with f = (C − B)/|C − B|:
    //   θ̇ = f·v_C / (((B − A) × f)·u).
    use kinsyn::manipulator::file::{AxisSpec, Description};
    for name in ["3-upu", "3-crr", "3-ruu", "4-ruu", "2t-crr-rrr"] {
        let text = std::fs::read_to_string(format!("tests/library/{name}.json")).unwrap();
        let d = Description::from_json(&text).unwrap();
        let m = load(name);
        let q = m.reference();
        let frame = m.platform_frame(&q);
        let p = m.point(&q);
        let mut twists = vec![
            (Vector3::zeros(), Vector3::x()),
            (Vector3::zeros(), Vector3::y()),
            (Vector3::zeros(), Vector3::z()),
        ];
        if name == "4-ruu" {
            twists.push((Vector3::z(), Vector3::zeros()));
        }
        if name == "2t-crr-rrr" {
            // Only the translations normal to n.
            let n = Vector3::new(0.1, 0.2, 1.0).normalize();
            let e1 = n.cross(&Vector3::x()).normalize();
            twists = vec![(Vector3::zeros(), e1), (Vector3::zeros(), n.cross(&e1))];
        }
        for (w, vp) in twists {
            let v = vp - w.cross(&p); // the velocity of the point at the origin
            let plus = solve(&m, &frame, &w, &v, H).unwrap();
            let minus = solve(&m, &frame, &w, &v, -H).unwrap();
            for (i, leg) in d.legs.iter().enumerate() {
                let Some(act) = m.actuators().iter().find(|a| a.leg == i) else {
                    continue; // the passive RRR leg of the 2-dof translational manipulator
                };
                let fd = (plus[act.joint] - minus[act.joint]) / (2.0 * H);
                let a = Vector3::from(leg.base);
                let c = frame.rotation * Vector3::from(leg.platform) + frame.translation.vector;
                let vc = vp + w.cross(&(c - p));
                let AxisSpec::Vector(u) = leg.axes.as_ref().unwrap()[0] else {
                    panic!("{name}: the first axis is a vector")
                };
                let u = Vector3::from(u).normalize();
                let expected = match name {
                    "3-upu" => (c - a).normalize().dot(&vc),
                    "3-crr" | "2t-crr-rrr" => u.dot(&vc),
                    _ => {
                        let b = Vector3::from(leg.points.as_ref().unwrap()[0]);
                        let f = (c - b).normalize();
                        f.dot(&vc) / (b - a).cross(&f).dot(&u)
                    }
                };
                assert!(
                    (fd - expected).abs() < 1e-6 * (1.0 + expected.abs()),
                    "{name}, leg {}, twist ω {w:?} v_P {vp:?}: finite difference {fd} vs {expected}",
                    i + 1
                );
            }
        }
    }
}
