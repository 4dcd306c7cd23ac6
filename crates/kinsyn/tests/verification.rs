//! The numerical verification of the catalogue (src/verification.rs, src/catalogue.rs), checked
//! with an independent Jacobian (finite differences of the forward kinematics) and against
//! docs/deviations.md.

mod common;

use common::finite_difference_jacobian;
use kinsyn::catalogue::{Catalogue, VERIFICATION_SEED};
use kinsyn::lockset::LockSet;
use kinsyn::motion::{PatternName, PatternQuery};
use kinsyn::synthesis::Options;
use kinsyn::verification::random_configuration;
use rand::SeedableRng;
use std::sync::OnceLock;

/// A pattern name as the catalogue writes it.
fn name(text: &str) -> PatternName {
    text.parse().unwrap()
}

/// A lock set as the catalogue writes it.
fn lock(text: &str) -> LockSet {
    text.parse().unwrap()
}

fn catalogue() -> &'static Catalogue {
    static C: OnceLock<Catalogue> = OnceLock::new();
    C.get_or_init(|| Catalogue::generate(&Options::default()))
}

#[test]
fn an_unaligned_query_finds_each_typed_direction() {
    // PPPS (T1-001, Table 1 row 1, axes xyzxyz): the S's revolutes 4, 5, 6 turn about x, y, z
    // at the reference configuration. Locking two of them leaves three translations and one
    // rotation about the third (held at reference values, the others keep their directions):
    // Schönflies motion X(x) with 5 and 6 locked, X(y) with 4 and 6, X(z) with 4 and 5. A query
    // for X with no direction covers all three, and each hit carries the classified direction
    // as a typed name, not as text to parse again.
    use kinsyn::motion::{Direction, GroupKind};
    use kinsyn::notation::Axis;
    let hits = catalogue().query(&"X".parse().unwrap(), 2, Some("PPPRRR"));
    let ppps: Vec<(PatternName, Vec<LockSet>)> = hits
        .iter()
        .filter(|h| h.entry.id == "T1-001")
        .map(|h| (h.pattern, h.lock_sets.clone()))
        .collect();
    let x = |axis| PatternName::Group {
        kind: GroupKind::X,
        direction: Some(Direction::Along(axis)),
    };
    let locks = |joints: &[usize]| vec![joints.iter().copied().collect::<LockSet>()];
    assert_eq!(
        ppps,
        vec![
            (x(Axis::X), locks(&[5, 6])),
            (x(Axis::Y), locks(&[4, 6])),
            (x(Axis::Z), locks(&[4, 5])),
        ]
    );
    let covers = |q: &str, n: &str| q.parse::<PatternQuery>().unwrap().covers(&name(n));
    assert!(covers("X", "X(y)") && covers("X(y)", "X(y)") && !covers("X(z)", "X(y)"));
    // nTmR names of groups (3T0R is always T3) and of non-group motions.
    assert!(covers("3T0R", "T3") && covers("1T2R", "1T2R") && !covers("2T1R", "G(xy)"));
}

#[test]
fn verified_entries_have_a_clear_rank_6_and_rejected_ones_a_clear_rank_5() {
    // Issue 3: every verified entry has rank 6 at every sample with a clear gap; every rejected
    // entry drops a singular value to round-off. Independent check: the finite-difference
    // Jacobian at a fresh random configuration has the same rank (5 or 6) with a wide margin.
    let cat = catalogue();
    let mut rejected = 0;
    for e in &cat.entries {
        let v = e.verification.as_ref().expect("verified");
        let chain = e.serial_chain(VERIFICATION_SEED).unwrap();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(99);
        let q = random_configuration(&chain, &mut rng);
        let sv = finite_difference_jacobian(&chain, &q, 1e-6).singular_values();
        let ratio = sv.min() / sv.max();
        if v.is_3t3r {
            assert_eq!(v.rank, 6, "{}", e.id);
            // A clear gap: the smallest kept singular value at least 1000× the rank tolerance.
            assert!(v.gap > 1e-6, "{}: gap {}", e.id, v.gap);
            assert!(
                ratio > 1e-5,
                "{}: finite differences give σ6/σ1 = {ratio}",
                e.id
            );
        } else {
            rejected += 1;
            assert!(v.rank < 6 || !v.idle_joints.is_empty(), "{}", e.id);
            assert!(v.dropped < 1e-12, "{}: dropped {}", e.id, v.dropped);
            assert!(
                ratio < 1e-8,
                "{}: finite differences give σ6/σ1 = {ratio}",
                e.id
            );
        }
    }
    assert!(rejected > 0);
}

#[test]
fn every_entry_reaches_d_and_e_and_queries_find_hand_derived_cases() {
    let cat = catalogue();
    for e in cat.verified() {
        let v = e.verification.as_ref().unwrap();
        // Nothing locked: the whole displacement group; everything locked: the identity.
        assert_eq!(v.patterns[&name("D")], vec!["-"], "{}", e.id);
        assert_eq!(v.patterns[&name("E")], vec!["123456"], "{}", e.id);
    }
    // PPPS (Table 1 row 1): locking the S leaves T3; locking two of its axes leaves X(z) about
    // the last one (z at the reference configuration).
    let t3: PatternQuery = "T3".parse().unwrap();
    let hits = cat.query(&t3, 3, Some("PPPRRR"));
    let ppps = hits
        .iter()
        .find(|h| h.entry.notation == "PPPS")
        .expect("PPPS gives T3");
    assert_eq!(ppps.lock_sets, vec!["456"]);
    let xz: PatternQuery = "X(z)".parse().unwrap();
    assert!(
        cat.query(&xz, 2, None)
            .iter()
            .any(|h| h.entry.notation == "PPPS" && h.lock_sets == vec!["45"])
    );
    // With no lock at all, no 6-dof chain is anything but D.
    assert!(cat.query(&t3, 0, None).is_empty());
}

#[test]
fn every_rejected_entry_is_documented() {
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/deviations.md"
    ))
    .unwrap();
    let begin = doc.find("<!-- not-3t3r:begin -->").expect("begin marker");
    let end = doc.find("<!-- not-3t3r:end -->").expect("end marker");
    let documented: Vec<&str> = doc[begin..end]
        .lines()
        .filter(|l| l.starts_with("| T"))
        .collect();
    let generated = catalogue().not_3t3r_markdown();
    let generated: Vec<&str> = generated.lines().filter(|l| l.starts_with("| T")).collect();
    assert_eq!(
        documented, generated,
        "docs/deviations.md is out of date: regenerate with `kinsyn catalogue rejected`"
    );
}

#[test]
fn equal_guide_columns_do_not_fool_the_classification() {
    // T1-005 PCCR (axes xyyxxz) with C's guide and revolute (joints 2, 3) locked: P1 and P4 both
    // slide along x and nothing turns them apart, R5 turns about x and R6 about an axis that R5
    // swings in the yz plane. Hand derivation: one translation, rotations spanning two
    // directions, not a group: 1T2R. (nalgebra's SVD mis-factored one sample of this motion,
    // which once made it 0T3R; `screw::svd` now checks its factors.)
    let e = catalogue().find("T1-005").expect("T1-005");
    let v = e.verification.as_ref().unwrap();
    assert!(
        v.patterns[&name("1T2R")].contains(&lock("23")),
        "{:?}",
        v.patterns
    );
    assert!(
        !v.patterns
            .get(&name("0T3R"))
            .is_some_and(|l| l.contains(&lock("23")))
    );
}

#[test]
fn two_guides_left_parallel_by_locks_are_one_translation() {
    // T2-105 RPRCaRa (word RPRRPR, axes xyzyyy) with R3 and R4 locked: the guides P2 and P5 both
    // lie along y and no free joint between them turns them apart, so they give one translation;
    // R1 turns about x and R6 about y. Hand derivation: 1T2R (3 dof, rotations in two directions).
    let e = catalogue().find("T2-105").expect("T2-105");
    let v = e.verification.as_ref().unwrap();
    assert!(
        v.patterns[&name("1T2R")].contains(&lock("34")),
        "{:?}",
        v.patterns
    );
}
