//! Paper 003's configurable 4-RRR through the general path — its description file's body tree
//! (one planar block: `m1`'s frame and the three hinge tangents that place `m2 … m4`),
//! `Manipulator::body_blocks` and the randomised solve of `analyze --all-assemblies` — against
//! the paper's own formulation (`configurable::forward_position`, method 2) at the published
//! inputs.

use kinsyn::geometry::{Chart, StudyVariables};
use kinsyn::homotopy::{SolveSettings, StartSystem, fewest_paths_start, solve_overdetermined};
use kinsyn::manipulator::{InputValues, Manipulator};
use kinsyn::poly::C64;
use kinsyn_papers::configurable::{Configurable, ForwardMethod, forward_position};

/// The dual-quaternion product of two Study parameter vectors (`a` then `b` as frames: `b`
/// relative to `a`), as `kinsyn::geometry::study_product` writes it.
fn product(a: &[C64; 8], b: &[C64; 8]) -> [C64; 8] {
    let q = |a: &[C64], b: &[C64]| {
        [
            a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] + a[2] * b[0] + a[3] * b[1] - a[1] * b[3],
            a[0] * b[3] + a[3] * b[0] + a[1] * b[2] - a[2] * b[1],
        ]
    };
    let (x, y1, y2) = (
        q(&a[..4], &b[..4]),
        q(&a[..4], &b[4..]),
        q(&a[4..], &b[..4]),
    );
    std::array::from_fn(|k| if k < 4 { x[k] } else { y1[k - 4] + y2[k - 4] })
}

#[test]
fn the_4_rrr_description_has_paper_003s_assemblies_and_those_of_the_folded_rhombus() {
    let file = format!(
        "{}/../../mechanisms/4-rrr-configurable.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let m = Manipulator::from_json(&std::fs::read_to_string(file).unwrap()).unwrap();
    // The description's reference inputs are the published q (Table 2).
    let inputs: Vec<(usize, f64)> = (0..4).map(|a| (a, 0.0)).collect();
    let blocks = m
        .body_blocks(&InputValues::Given(&inputs), &Chart::random_linear(3))
        .unwrap();
    assert_eq!(blocks.len(), 1);
    let block = &blocks[0];
    assert_eq!(block.members.len(), 3);
    let ps = &block.system;
    assert_eq!((ps.system().nvars(), ps.system().len()), (7, 7));
    // The start `analyze --all-assemblies` chooses: multi-homogeneous over the Study
    // parameters and each hinge tangent, 512 paths where the total degree has 5 760.
    let (grouped, start) = fewest_paths_start(ps.system(), &ps.variable_groupings(), 1);
    // Its count by brute force: the coefficient of Π α_j^{n_j} in Π_i Σ_j d_ij α_j, summed
    // over every choice of a group per equation (4⁷ of them) — not the library's walk over
    // assignments — and below the total degree, the product of the degrees.
    let groups = grouped.groups();
    let degrees: Vec<Vec<u128>> = grouped
        .equations()
        .iter()
        .map(|e| groups.iter().map(|g| u128::from(e.degree_in(g))).collect())
        .collect();
    let mut by_hand = 0_u128;
    for choice in 0..groups.len().pow(u32::try_from(degrees.len()).unwrap()) {
        let mut c = choice;
        let mut used = vec![0; groups.len()];
        let mut product = 1_u128;
        for row in &degrees {
            let j = c % groups.len();
            c /= groups.len();
            used[j] += 1;
            product *= row[j];
        }
        if used.iter().zip(groups).all(|(u, g)| *u == g.len()) {
            by_hand += product;
        }
    }
    let total: u128 = grouped.degrees().iter().map(|&d| u128::from(d)).product();
    assert_eq!(start, StartSystem::MultiHomogeneous);
    assert_eq!(grouped.multihomogeneous_bezout(), Some(by_hand));
    assert!(by_hand < total, "{by_hand} paths against {total}");
    let settings = SolveSettings {
        seed: 3,
        start,
        ..SolveSettings::default()
    };
    let r = solve_overdetermined(&grouped, &settings).unwrap();
    // Each solution's corners C1 … C4: the origins of m1 … m4 (the description's frames).
    let s = StudyVariables::leading(8);
    let (t, delta) = (s.translation(), s.delta());
    let origin = |st: &[C64; 8]| {
        [
            t[0].eval(st) / delta.eval(st),
            t[1].eval(st) / delta.eval(st),
        ]
    };
    let mut ours: Vec<([[C64; 2]; 4], bool)> = Vec::new();
    for sol in r
        .solutions()
        .filter(|s| s.regular && !ps.on_null_cone(&s.x))
    {
        let root = ps.study(&sol.x).unwrap();
        let mut corners = [[C64::new(0.0, 0.0); 2]; 4];
        corners[block.body] = origin(&root);
        for (b, g) in ps.member_study(&sol.x) {
            corners[b] = origin(&product(&root, &g));
        }
        ours.push((corners, sol.real));
    }
    // The rhombus C1 C2 C3 C4 (all four platform links 120 mm) folds onto a diagonal in two
    // operation modes, C1 = C3 or C2 = C4; paper 003's angles θ, φ describe the unfolded one.
    let gap = |a: [C64; 2], b: [C64; 2]| (a[0] - b[0]).norm() + (a[1] - b[1]).norm();
    let folded = |c: &[[C64; 2]; 4]| gap(c[0], c[2]) < 1e-6 || gap(c[1], c[3]) < 1e-6;
    let unfolded: Vec<&([[C64; 2]; 4], bool)> = ours.iter().filter(|(c, _)| !folded(c)).collect();
    let paper = forward_position(
        &Configurable::paper003(),
        [141.956f64, 203.366, 337.773, 305.499].map(f64::to_radians),
        ForwardMethod::Corner,
    )
    .unwrap();
    assert!(paper.complete);
    assert_eq!((paper.complex_assemblies, paper.real), (12, 2));
    assert_eq!(unfolded.len(), paper.complex_assemblies);
    let real: Vec<_> = unfolded.iter().filter(|(_, r)| *r).collect();
    assert_eq!(real.len(), paper.real);
    for a in &paper.assemblies {
        assert!(
            real.iter().any(|(c, _)| (0..4).all(|i| {
                (c[i][0].re - a.corners[i].x).abs() < 1e-6
                    && (c[i][1].re - a.corners[i].y).abs() < 1e-6
            })),
            "the paper's assembly {:?} is not found",
            a.corners
        );
    }
    // The other solutions are assemblies of the folded modes (complex at these inputs): more
    // than the paper's formulation can describe, not spurious.
    assert!(ours.len() > unfolded.len());
    assert!(ours.iter().filter(|(c, _)| folded(c)).all(|(_, r)| !r));
}
