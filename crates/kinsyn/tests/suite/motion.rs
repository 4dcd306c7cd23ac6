//! Motion patterns (src/motion.rs): the displacement groups of paper 000 §1 recognised from
//! chains whose motion is known by hand, and the text forms.

use kinsyn::chain::SerialChain;
use kinsyn::motion::{GroupKind, Pattern, PatternName, PatternQuery};
use kinsyn::notation::Axis::{self, X, Y, Z};
use kinsyn::notation::Primitive::{self, P, R};
use kinsyn::verification::{Settings, configurations, locked_motion, random_configuration, verify};
use nalgebra::{Rotation3, Vector3};
use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A pattern name as the catalogue writes it.
fn name(text: &str) -> PatternName {
    text.parse().unwrap()
}

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

fn chain(joints: &[(Primitive, Vector3<f64>, Vector3<f64>)]) -> SerialChain {
    SerialChain::new(joints.to_vec()).unwrap()
}

/// The pattern of the whole chain (nothing locked), from three random configurations.
fn pattern(c: &SerialChain, seed: u64) -> Pattern {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let qs: Vec<Vec<f64>> = (0..3).map(|_| random_configuration(c, &mut rng)).collect();
    locked_motion(c, 0, &qs, &Settings::default()).pattern
}

fn group(p: &Pattern) -> kinsyn::motion::Group {
    match p {
        Pattern::Group(g) => *g,
        other @ Pattern::NonGroup { .. } => panic!("expected a group, got {other}"),
    }
}

#[test]
fn three_perpendicular_guides_give_t3() {
    // Hand derivation: PPP along x, y, z translates in space, T3 (§1's spatial translation).
    let c = chain(&[
        (P, v(1., 0., 0.), v(0., 0., 0.)),
        (P, v(0., 1., 0.), v(0., 0., 0.)),
        (P, v(0., 0., 1.), v(0., 0., 0.)),
    ]);
    assert_eq!(pattern(&c, 1).to_string(), "T3");
}

#[test]
fn three_parallel_revolutes_give_planar_motion() {
    // Three parallel R (not coaxial) about z: planar motion G(P), P the xy plane.
    let c = chain(&[
        (R, v(0., 0., 1.), v(0., 0., 0.)),
        (R, v(0., 0., 1.), v(1., 0., 0.)),
        (R, v(0., 0., 1.), v(1., 1., 0.)),
    ]);
    let p = pattern(&c, 2);
    assert_eq!(p.to_string(), "G(xy)");
    // Two of them: a planar 2R arm, not a group (its twist space turns with the first joint).
    let arm = chain(&[
        (R, v(0., 0., 1.), v(0., 0., 0.)),
        (R, v(0., 0., 1.), v(1., 0., 0.)),
    ]);
    assert_eq!(pattern(&arm, 2).to_string(), "1T1R");
}

#[test]
fn intersecting_perpendicular_revolutes_give_spherical_motion() {
    // RRR with mutually perpendicular axes through N = (1, 2, 3): S(N).
    let n = v(1., 2., 3.);
    let c = chain(&[
        (R, v(1., 0., 0.), n),
        (R, v(0., 1., 0.), n),
        (R, v(0., 0., 1.), n),
    ]);
    let g = group(&pattern(&c, 3));
    assert_eq!(g.kind, GroupKind::S);
    let point = g.point.unwrap();
    assert!((Vector3::from(point) - n).norm() < 1e-9, "{point:?}");
    // Two of them (a U joint): rotations about two axes, not a group.
    let u = chain(&[(R, v(1., 0., 0.), n), (R, v(0., 1., 0.), n)]);
    assert_eq!(pattern(&u, 3).to_string(), "0T2R");
}

#[test]
fn cylindrical_pair_and_single_joints() {
    // C: P and R along the line through (0, 1, 0) in direction x: C(N, x).
    let n = v(0., 1., 0.);
    let c = chain(&[(P, v(1., 0., 0.), n), (R, v(1., 0., 0.), n)]);
    let g = group(&pattern(&c, 4));
    assert_eq!(g.kind, GroupKind::C);
    assert_eq!(pattern(&c, 4).to_string(), "C(x)");
    // The point of the axis nearest the origin is N = (0, 1, 0).
    assert!((Vector3::from(g.point.unwrap()) - n).norm() < 1e-9);
    // R alone: R(N, u); P alone: T(u).
    let r = chain(&[(R, v(0., 1., 0.), v(2., 0., 0.))]);
    let g = group(&pattern(&r, 5));
    assert_eq!(
        (g.kind, pattern(&r, 5).to_string()),
        (GroupKind::R, "R(y)".to_string())
    );
    assert!((Vector3::from(g.point.unwrap()) - v(2., 0., 0.)).norm() < 1e-9);
    let p = chain(&[(P, v(0., 0., 1.), v(0., 0., 0.))]);
    assert_eq!(pattern(&p, 5).to_string(), "T(z)");
}

#[test]
fn schoenflies_and_translating_screw() {
    // PPP + R about z: X(z). Two guides in the xy plane + R about z: G(xy).
    let o = v(0., 0., 0.);
    let x = chain(&[
        (P, v(1., 0., 0.), o),
        (P, v(0., 1., 0.), o),
        (P, v(0., 0., 1.), o),
        (R, v(0., 0., 1.), v(1., 1., 0.)),
    ]);
    assert_eq!(pattern(&x, 6).to_string(), "X(z)");
    let g = chain(&[
        (P, v(1., 0., 0.), o),
        (P, v(0., 1., 0.), o),
        (R, v(0., 0., 1.), v(1., 1., 0.)),
    ]);
    assert_eq!(pattern(&g, 6).to_string(), "G(xy)");
    // Two guides in the xy plane: T2(xy).
    let t2 = chain(&[(P, v(1., 0., 0.), o), (P, v(1., 1., 0.), o)]);
    assert_eq!(pattern(&t2, 6).to_string(), "T2(xy)");
}

#[test]
fn ppps_locks_give_t3_and_s() {
    // Hand derivation: PPPS with the S locked translates (T3); with the three P locked it turns
    // about the centre of the S (S(N)).
    let n = v(0.5, -0.2, 0.3);
    let o = v(0., 0., 0.);
    let c = chain(&[
        (P, v(1., 0., 0.), o),
        (P, v(0., 1., 0.), o),
        (P, v(0., 0., 1.), o),
        (R, v(1., 0., 0.), n),
        (R, v(0., 1., 0.), n),
        (R, v(0., 0., 1.), n),
    ]);
    let ver = verify(&c, &Settings::default(), 11);
    assert!(ver.is_3t3r);
    assert_eq!(ver.patterns[&name("T3")], vec!["456"]);
    assert_eq!(ver.patterns[&name("S")], vec!["123"]);
    assert_eq!(ver.patterns[&name("D")], vec!["-"]);
    assert_eq!(ver.patterns[&name("E")], vec!["123456"]);
}

#[test]
fn redundant_parallel_guides_are_not_3t3r() {
    // Two guides that stay parallel translate along one line; with three R the chain has rank 5 and
    // one of the guides is idle.
    let n = v(0.3, 0.1, 0.2);
    let o = v(0., 0., 0.);
    let c = chain(&[
        (P, v(1., 0., 0.), o),
        (P, v(1., 0., 0.), o),
        (P, v(0., 1., 0.), o),
        (R, v(1., 0., 0.), n),
        (R, v(0., 1., 0.), n),
        (R, v(0., 0., 1.), n),
    ]);
    let ver = verify(&c, &Settings::default(), 12);
    assert_eq!(ver.rank, 5);
    assert!(!ver.is_3t3r);
    assert_eq!(ver.idle_joints, vec![1, 2]);
}

#[test]
fn pattern_text_forms() {
    for text in [
        "E", "T(x)", "R(z)", "H(y)", "T2(xy)", "C(z)", "G(yz)", "T3", "S", "Y(z)", "X(z)", "D",
        "3T1R", "1T2R", "X", "G",
    ] {
        let q: PatternQuery = text.parse().unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(q.to_string(), text);
    }
    for bad in ["", "Q", "X(w)", "T3(x)", "G(xx)", "4T3R", "X(z", "S(x)"] {
        assert!(bad.parse::<PatternQuery>().is_err(), "{bad}");
    }
    let q: PatternQuery = "X(z)".parse().unwrap();
    let o = v(0., 0., 0.);
    let x = chain(&[
        (P, v(1., 0., 0.), o),
        (P, v(0., 1., 0.), o),
        (P, v(0., 0., 1.), o),
        (R, v(0., 0., 1.), v(1., 1., 0.)),
    ]);
    assert!(q.matches(&pattern(&x, 1)));
    assert!(
        !"X(x)"
            .parse::<PatternQuery>()
            .unwrap()
            .matches(&pattern(&x, 1))
    );
    assert!(
        "X".parse::<PatternQuery>()
            .unwrap()
            .matches(&pattern(&x, 1))
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// Frame invariance: rotating and translating the base frame, or sampling other
    /// configurations, changes no classification of any lock subset (kind and dimensions).
    #[test]
    fn classification_is_frame_invariant(seed in 0u64..1000, ax in -3.0f64..3.0, ay in -3.0f64..3.0, az in -3.0f64..3.0, tx in -2.0f64..2.0) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let words: [(&[Primitive], &[Axis], &[usize]); 3] = [
            (&[P, P, R, R, R, R], &[X, Y, X, X, Y, Z], &[1, 1, 1, 3]),
            (&[R, R, R, P, R, R], &[X, X, X, X, Y, Z], &[1, 1, 2, 2]),
            (&[P, R, R, R, R, P], &[Y, X, Y, Z, X, Z], &[1, 1, 3, 1]),
        ];
        let (word, axes, blocks) = words[(seed % 3) as usize];
        let c = SerialChain::from_layout(word, axes, blocks, &mut rng).unwrap();
        let moved = c.transformed(&Rotation3::from_euler_angles(ax, ay, az), &Vector3::new(tx, -tx, 0.5));
        // Sample configurations differ between the two (another seed): the classification of every
        // lock subset must not. (The verification's sampler keeps samples apart; samples that
        // nearly coincide prove no group: docs/verification.md.)
        let q1 = configurations(&c, &Settings::default(), seed + 1);
        let q2 = configurations(&c, &Settings::default(), seed + 2);
        let kind = |p: &Pattern| match p {
            Pattern::Group(g) => g.kind.symbol().to_string(),
            other @ Pattern::NonGroup { .. } => other.to_string(),
        };
        for mask in 0u32..64 {
            let a = locked_motion(&c, mask, &q1, &Settings::default()).pattern;
            let b = locked_motion(&moved, mask, &q2, &Settings::default()).pattern;
            prop_assert_eq!(kind(&a), kind(&b), "mask {:06b}", mask);
        }
    }
}
