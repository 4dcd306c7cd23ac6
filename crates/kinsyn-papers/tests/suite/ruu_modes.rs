//! Operation modes of the 4-RUU (paper 004 §4): the coplanarity
//! equations g1–g4 with the Study quadric g13 and the normalisation g14, at fixed random inputs,
//! decomposed numerically (`homotopy::decompose`) and exactly (Singular's `minAssGTZ`, the
//! paper's own tool, when installed).

use kinsyn::homotopy::{DecomposeSettings, decompose};
use kinsyn::poly::System;
use kinsyn_papers::ruu::{InputMode, Ruu};

use crate::common::singular;

/// The inputs `t1i = tan(θ1i/2)`: generic values, exactly 3/10, −7/10, 11/10, 9/20.
const INPUTS: [f64; 4] = [0.3, -0.7, 1.1, 0.45];

/// g1–g4, g13, g14 at the inputs, in the eight Study parameters alone.
fn coplanarity_system() -> System {
    let full = Ruu::paper004()
        .constraints(InputMode::Given(INPUTS))
        .unwrap();
    let study: Vec<usize> = (0..8).collect();
    full.subsystem(&[0, 1, 2, 3, 12, 13], &study).unwrap()
}

#[test]
fn two_four_dimensional_schoenflies_modes_at_generic_inputs() {
    // Paper 004 §4 (eqs. 14–21): K1 (x0 = x3 = 0, the platform upside down) and K2
    // (x1 = x2 = 0), each a 4-dof Schönflies mode. Numerically: two components of dimension 4
    // and degree 4 (the degree-2 cones of the exact check below cut by the quadric g14), one
    // with x0 = x3 = 0 and one with x1 = x2 = 0; the same for two seeds.
    for seed in [1, 2] {
        let d = decompose(
            &coplanarity_system(),
            &DecomposeSettings {
                seed,
                ..DecomposeSettings::default()
            },
        )
        .unwrap();
        assert_eq!(d.signature(), vec![(4, 4), (4, 4)], "seed {seed}");
        assert!(d.unresolved.is_empty());
        let k1 = d
            .components
            .iter()
            .filter(|c| c.sample_point[0].norm() < 1e-8 && c.sample_point[3].norm() < 1e-8)
            .count();
        let k2 = d
            .components
            .iter()
            .filter(|c| c.sample_point[1].norm() < 1e-8 && c.sample_point[2].norm() < 1e-8)
            .count();
        assert_eq!((k1, k2), (1, 1), "seed {seed}: one K1 and one K2");
        assert!(d.components.iter().all(|c| c.trace_test_passed));
    }
}

#[test]
fn singular_finds_the_same_two_modes() {
    // The exact cross-check: Singular's minimal associated primes of ⟨g1..g4, g13⟩ (the printed
    // equations of data/paper004-constraints.txt, a = 2, b = 1, l = 1, r = 2, the same inputs
    // as rationals): exactly K1 = ⟨x0, x3, x1 y1 + x2 y2⟩ and K2 = ⟨x1, x2, x0 y0 + x3 y3⟩,
    // cones of dimension 5 and degree 2 — the numerical components above plus one dimension
    // and with half the degree (the normalisation g14 is a quadric).
    let mut script = String::from(
        "LIB \"primdec.lib\";\nring R = 0,(x0,x1,x2,x3,y0,y1,y2,y3),dp;\nnumber a=2; number b=1; number l=1; number r=2;\nnumber t11=3/10; number t12=-7/10; number t13=11/10; number t14=9/20;\n",
    );
    script += &singular::printed_paper004(&["g1", "g2", "g3", "g4"]);
    script += "poly g13 = x0*y0+x1*y1+x2*y2+x3*y3;\nideal I = g1,g2,g3,g4,g13;\nlist P = minAssGTZ(I);\nint k;\nfor (k=1; k<=size(P); k++) { ideal S(k) = std(P[k]); print(string(dim(S(k))) + \" \" + string(mult(S(k))) + \" : \" + string(P[k])); }\nquit;\n";
    let Some(out) = singular::run(&script, "the exact check of the 4-RUU's modes") else {
        return;
    };
    let mut primes: Vec<&str> = out.lines().filter(|l| l.contains(" : ")).collect();
    primes.sort_unstable();
    assert_eq!(
        primes,
        vec!["5 2 : x0*y0+x3*y3,x2,x1", "5 2 : x1*y1+x2*y2,x3,x0"],
        "Singular printed {out:?}"
    );
}
