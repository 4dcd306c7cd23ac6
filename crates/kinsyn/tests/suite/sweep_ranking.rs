//! The ranking of a sweep's designs (`kinsyn::sweep::ranking`) on rows whose front is derived by
//! hand, against the definition of dominance applied pair by pair, and the sweep rows of
//! designs whose multioperation capacity is known: paper 000 §5's 3-UPS/3-RPS and two designs
//! derived from first principles.

use kinsyn::catalogue::Catalogue;
use kinsyn::sweep::ranking::{Ranking, dominates, kind_locks, pareto_front, top_per_inputs};
use kinsyn::sweep::{Design, DesignRow, Reached, SweepSettings};
use proptest::prelude::*;

fn row(design: usize, inputs: usize, kinds: usize, subgroups: usize, family: &str) -> DesignRow {
    DesignRow {
        design,
        chain: format!("T9-{design:03}"),
        notation: "X".into(),
        family: family.into(),
        legs: 3,
        actuated: vec![1],
        inputs,
        dof: 6,
        subgroups,
        group_kinds: Vec::new(),
        kinds,
        groups: Vec::new(),
        non_groups: Vec::new(),
        unsampled: 0,
        singular: 0,
        singular_lock_sets: Vec::new(),
        error: None,
    }
}

/// (inputs, kinds, subgroups) per design index; design 9 failed to build.
fn hand_rows() -> Vec<DesignRow> {
    let table = [
        (3, 2, 2), // d0: below d1 (same inputs, fewer subgroups)
        (3, 2, 3), // d1: best of 3 inputs, beats everything with 2 inputs → front
        (3, 1, 5), // d2: fewer kinds than d1 (kinds before subgroups) → dominated
        (6, 2, 9), // d3: below d4 at 6 inputs (2 kinds < 4) → dominated
        (6, 4, 4), // d4: best of 6, beats (2,3) → front
        (9, 4, 4), // d5: same capacity as d4 with more inputs → dominated
        (9, 5, 1), // d6: best of 9, 5 kinds > 4 → front
        (4, 2, 3), // d7: same capacity as d1 with more inputs → dominated
        (6, 4, 4), // d8: tie with d4 → front too
        (2, 0, 0), // d9: failed (error): not ranked although it has the fewest inputs
        (2, 1, 1), // d10: the fewest inputs among built designs → front
    ];
    let mut rows: Vec<DesignRow> = table
        .iter()
        .enumerate()
        .map(|(i, &(n, k, s))| row(i, n, k, s, if i <= 4 { "A" } else { "B" }))
        .collect();
    rows[9].error = Some("leg singular everywhere".into());
    rows[5].unsampled = 2;
    rows
}

fn indices(rows: &[&DesignRow]) -> Vec<usize> {
    rows.iter().map(|r| r.design).collect()
}

#[test]
fn pareto_front_of_hand_made_rows() {
    let rows = hand_rows();
    // Derived in the table's comments: d10 (2 inputs), d1 (3), d4 and d8 (6), d6 (9).
    assert_eq!(indices(&pareto_front(&rows)), vec![10, 1, 4, 8, 6]);
    // The order of the rows does not matter.
    let mut reversed = rows.clone();
    reversed.reverse();
    assert_eq!(indices(&pareto_front(&reversed)), vec![10, 1, 4, 8, 6]);
}

#[test]
fn top_designs_counts_and_failures_of_hand_made_rows() {
    let rows = hand_rows();
    let top: Vec<(usize, Vec<usize>)> = top_per_inputs(&rows, 2)
        .into_iter()
        .map(|(n, d)| (n, indices(&d)))
        .collect();
    // Per inputs, by kinds then subgroups then index: 2: d10; 3: d1 (2,3), d0 (2,2) before
    // d2 (1,5); 4: d7; 6: d4, d8 (tie, lower index first) before d3; 9: d6 (5 kinds), d5.
    assert_eq!(
        top,
        vec![
            (2, vec![10]),
            (3, vec![1, 0]),
            (4, vec![7]),
            (6, vec![4, 8]),
            (9, vec![6, 5]),
        ]
    );
    let r = Ranking::new(&rows, 2);
    assert_eq!((r.designs, r.built), (11, 10));
    // Kinds of the built designs: 2, 2, 1, 2, 4, 4, 5, 2, 4, 1.
    assert_eq!(r.histogram, vec![0, 2, 4, 0, 3, 1]);
    // Family A: d0..d4, kinds 2, 2, 1, 2, 4 (mean 11/5); B: d5..d8 and d10, 4, 5, 2, 4, 1
    // (mean 16/5; d9 not built).
    let fam: Vec<(String, usize, f64, usize)> = r
        .families
        .iter()
        .map(|f| (f.family.clone(), f.designs, f.mean_kinds, f.max_kinds))
        .collect();
    assert_eq!(fam[0].0, "A");
    assert_eq!((fam[0].1, fam[0].3), (5, 4));
    assert!((fam[0].2 - 2.2).abs() < 1e-12);
    assert_eq!(fam[1].0, "B");
    assert_eq!((fam[1].1, fam[1].3), (5, 5));
    assert!((fam[1].2 - 3.2).abs() < 1e-12);
    assert_eq!(r.failed.len(), 1);
    assert_eq!(r.failed[0].design, 9);
    assert_eq!(r.unsampled.len(), 1);
    assert_eq!((r.unsampled[0].design, r.unsampled[0].unsampled), (5, 2));
    // Legs: every chain of the top lists (d10, d1, d0, d7, d4, d8, d6, d5) once each; the
    // front's (d10, d1, d4, d8, d6) twice. Most top designs, then most front designs, then id.
    let legs: Vec<(String, usize, usize)> = r
        .legs
        .iter()
        .map(|l| (l.chain.clone(), l.top_designs, l.front_designs))
        .collect();
    assert_eq!(
        legs,
        vec![
            ("T9-001".into(), 1, 1),
            ("T9-004".into(), 1, 1),
            ("T9-006".into(), 1, 1),
            ("T9-008".into(), 1, 1),
            ("T9-010".into(), 1, 1),
            ("T9-000".into(), 1, 0),
            ("T9-005".into(), 1, 0),
            ("T9-007".into(), 1, 0),
        ]
    );
}

#[test]
fn kind_locks_take_the_fewest_inputs() {
    let mut r = row(0, 6, 2, 3, "A");
    r.group_kinds = vec!["X".into(), "D".into()];
    let reached = |pattern: &str, locks: &[&str]| Reached {
        pattern: pattern.into(),
        parameters: None,
        dof: 4,
        subsets: locks.len(),
        lock_sets: locks.iter().map(|s| (*s).to_string()).collect(),
    };
    r.groups = vec![
        reached("D", &["-"]),
        reached("X(x)", &["R1.5 R1.6", "R2.5 R2.6"]),
        reached("X(z)", &["R3.4 R3.5 R3.6", "P1.1"]),
    ];
    let k = kind_locks(&r);
    assert_eq!(k.len(), 2);
    assert_eq!(
        (
            k[0].kind.as_str(),
            k[0].pattern.as_str(),
            k[0].lock_set.as_str()
        ),
        ("X", "X(z)", "P1.1")
    );
    assert_eq!((k[1].kind.as_str(), k[1].lock_set.as_str()), ("D", "-"));
}

proptest! {
    /// The front equals the designs no other dominates, pair by pair (the definition, O(n²)).
    #[test]
    fn front_is_the_undominated_designs(
        table in prop::collection::vec((1usize..8, 0usize..5, 0usize..4, any::<bool>()), 1..40)
    ) {
        let rows: Vec<DesignRow> = table
            .iter()
            .enumerate()
            .map(|(i, &(n, k, s, failed))| {
                let mut r = row(i, n, k, s, "A");
                if failed && i % 3 == 0 {
                    r.error = Some("failed".into());
                }
                r
            })
            .collect();
        let built: Vec<&DesignRow> = rows.iter().filter(|r| r.error.is_none()).collect();
        let mut expected: Vec<usize> = built
            .iter()
            .filter(|b| !built.iter().any(|a| dominates(a, b)))
            .map(|r| r.design)
            .collect();
        expected.sort_unstable();
        let mut front = indices(&pareto_front(&rows));
        front.sort_unstable();
        prop_assert_eq!(front, expected);
    }
}

/// The design of the sweep with this leg chain and actuated joints.
fn design(chain: &str, actuated: &[usize]) -> Design {
    let catalogue = Catalogue::committed().unwrap();
    let entry = catalogue.verified().find(|e| e.id == chain).unwrap();
    Design {
        index: 0,
        chain: chain.into(),
        notation: entry.notation.clone(),
        family: entry.family.clone(),
        actuated: actuated.to_vec(),
    }
}

fn group<'a>(row: &'a DesignRow, lock_set: &str) -> Option<&'a Reached> {
    row.groups
        .iter()
        .find(|g| g.lock_sets.iter().any(|s| s == lock_set))
}

/// Paper 000 §5: the 3-UPS (catalogue T4-034, `RRPRRR`, axes `xyzxyz`) with the first
/// revolute of each U (α, joint 1) and the slider (c, joint 3) actuated.
#[test]
fn paper000_3ups_reconfigured_into_the_3rps() {
    let d = design("T4-034", &[1, 3]);
    assert_eq!(d.notation, "UPS");
    let r = d.evaluate(&SweepSettings::default());
    assert_eq!(r.error, None);
    // §5: "Each kinematic chain incorporates two actuators in order to get the total dof":
    // 3 legs × 2 = 6 inputs, a 6-dof platform, whose motion is the whole group D.
    assert_eq!(r.inputs, 6);
    assert_eq!(r.dof, 6);
    let free = group(&r, "-").expect("D with no input locked");
    assert_eq!((free.pattern.as_str(), free.dof), ("D", 6));
    // §5: "blocking the first rotational joint so that α angle remains constant, the
    // manipulator becomes the 3-RPS …, the robot has only three dof in its moving platform";
    // eq. 22 gives its three constraint equations. Its motion is the mixed 1T2R of §1 (the
    // 3-RPS's one translation and two rotations), not a displacement group.
    assert!(group(&r, "R1.1 R2.1 R3.1").is_none());
    let rps = r
        .non_groups
        .iter()
        .find(|p| p.lock_sets.iter().any(|s| s == "R1.1 R2.1 R3.1"))
        .expect("the 3-RPS subset among the non-group patterns");
    assert_eq!((rps.pattern.as_str(), rps.dof), ("1T2R", 3));
}

/// The 3-UPS with only the sliders actuated. Locking k sliders holds k base-to-platform
/// distances: with k = 1, 2, 3 the platform keeps 5, 4, 3 dof, and no such set of distance
/// constraints is a group: SE(3) has no 5-dimensional subgroup; the only 4-dimensional ones are
/// the Schönflies X(u), in which a platform point's distance to a fixed point changes; a
/// 3-dimensional group would be T3, S, G or Y, and translations, rotations about a point other
/// than the base points, and planar motions all change some of the three distances. So D, with
/// nothing locked, is the only group: one kind, one subgroup.
#[test]
fn three_ups_with_sliders_actuated_reaches_only_d() {
    let r = design("T4-034", &[3]).evaluate(&SweepSettings::default());
    assert_eq!(r.error, None);
    assert_eq!((r.inputs, r.dof), (3, 6));
    assert_eq!(r.group_kinds, vec!["D".to_string()]);
    assert_eq!((r.kinds, r.subgroups), (1, 1));
    // The three distances held: 3 dof.
    let all = r
        .non_groups
        .iter()
        .find(|p| p.lock_sets.iter().any(|s| s == "P1.3 P2.3 P3.3"))
        .unwrap();
    assert_eq!(all.dof, 3);
}

/// The direction in a pattern name such as `R([0.866,-0.500,0.000])` or `R(y)`.
fn direction(pattern: &str) -> [f64; 3] {
    match pattern.split(['(', ')']).nth(1) {
        Some("x") => return [1.0, 0.0, 0.0],
        Some("y") => return [0.0, 1.0, 0.0],
        Some("z") => return [0.0, 0.0, 1.0],
        _ => {}
    }
    let inside = pattern.split(['[', ']']).nth(1).unwrap();
    let v: Vec<f64> = inside
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect();
    [v[0], v[1], v[2]]
}

/// Paper 000 Table 1 row 1, PPPS, with the three sliders of each leg actuated (9 inputs).
/// The geometry of `manipulator::build` (module documentation): leg i's platform point, the S
/// centre `A_i`, is on the platform circle of radius 0.5 at height 1, at angle 120°·(i−1); the
/// sliders run along the leg frame x, y, z (x and z in the leg's vertical plane and not
/// horizontal, y horizontal). Each leg moves `A_i` freely, so with nothing locked the platform
/// has D (6 dof). Derived kinds and subgroups:
/// - `S(A_i)`: the three sliders of leg i locked fix `A_i`; any further lock moves another
///   platform point in a plane or a line, which no rotation about `A_i` keeps, so that one
///   subset alone gives it (3 dof).
/// - R about the line `A_aA_b`: leg a's three sliders and two of leg b's locked fix `A_a` and hold
///   `A_b` on a line; of the rotations about `A_a` (3 dof) the two constraints leave one, the
///   rotation about `A_aA_b`, which keeps `A_b` fixed: a minimal lock set of 5 (1 dof).
/// - E: add leg c's slider x to that set: the rotation about `A_aA_b` (a horizontal line) moves
///   `A_c` vertically, and x has a vertical component, so nothing moves (0 dof).
#[test]
fn three_ppps_with_sliders_actuated() {
    let r = design("T1-001", &[1, 2, 3]).evaluate(&SweepSettings::default());
    assert_eq!(r.error, None);
    assert_eq!((r.inputs, r.dof), (9, 6));
    for kind in ["E", "R", "S", "D"] {
        assert!(
            r.group_kinds.iter().any(|k| k == kind),
            "{kind} in {:?}",
            r.group_kinds
        );
    }
    assert_eq!(group(&r, "-").unwrap().pattern, "D");
    for leg in 1..=3 {
        let set = format!("P{leg}.1 P{leg}.2 P{leg}.3");
        let s = group(&r, &set).unwrap_or_else(|| panic!("{set}: {:?}", r.groups));
        assert!(s.pattern.starts_with('S'), "{}", s.pattern);
        assert_eq!((s.dof, s.subsets, s.lock_sets.len()), (3, 1, 1));
    }
    let point = |leg: usize| {
        let t = (120.0 * (leg as f64 - 1.0)).to_radians();
        [0.5 * t.cos(), 0.5 * t.sin(), 1.0]
    };
    for (a, b, c) in [(1, 2, 3), (1, 3, 2), (2, 3, 1)] {
        let set = format!("P{a}.1 P{a}.2 P{a}.3 P{b}.1 P{b}.2");
        let g = group(&r, &set).unwrap_or_else(|| panic!("{set}: {:?}", r.groups));
        assert!(g.pattern.starts_with('R'), "{}", g.pattern);
        assert_eq!(g.dof, 1);
        let (pa, pb) = (point(a), point(b));
        let line = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
        let u = direction(&g.pattern);
        let cross = [
            u[1] * line[2] - u[2] * line[1],
            u[2] * line[0] - u[0] * line[2],
            u[0] * line[1] - u[1] * line[0],
        ];
        let norm = line.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!(
            cross.iter().map(|x| x * x).sum::<f64>().sqrt() < 2e-3 * norm,
            "{} not along A{a}A{b}",
            g.pattern
        );
        let rigid = format!("{set} P{c}.1");
        let mut sorted: Vec<&str> = rigid.split(' ').collect();
        sorted.sort_unstable();
        let e = group(&r, &sorted.join(" ")).unwrap_or_else(|| panic!("{rigid}"));
        assert_eq!((e.pattern.as_str(), e.dof), ("E", 0));
    }
    // One S per leg's centre.
    let count = |k: &str| {
        r.groups
            .iter()
            .filter(|g| g.pattern.split('(').next() == Some(k))
            .count()
    };
    assert_eq!(count("S"), 3);
}
