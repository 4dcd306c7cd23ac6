//! scratch
use kinsyn::homotopy::{DecomposeSettings, regenerate_with_progress};
use kinsyn::poly::{Poly, System};
use kinsyn::ruu::{InputMode, Ruu};

/// The equations `which` of the 4-RUU with free inputs, in the Study parameters and the inputs
/// `t11 … t14` (the passive `t2i` dropped: `which` must not involve them).
fn free_system(which: &[usize], inputs: &[usize]) -> System {
    let full = Ruu::paper004().constraints(InputMode::Free).unwrap();
    let keep: Vec<usize> = (0..8).chain(inputs.iter().map(|i| 8 + i)).collect();
    let n = keep.len();
    let equations: Vec<Poly> = which
        .iter()
        .map(|k| {
            let f = &full.equations()[*k];
            Poly::from_terms(
                n,
                f.terms().map(|(e, c)| {
                    assert!(e.iter().enumerate().all(|(j, p)| *p == 0 || keep.contains(&j)));
                    (keep.iter().map(|j| e[*j]).collect(), c)
                }),
            )
        })
        .collect();
    let names = keep.iter().map(|j| full.variables()[*j].clone()).collect();
    System::new(names, equations).unwrap()
}

#[test]
fn scratch() {
    for (label, which, inputs) in [
        ("I legs order", vec![12usize, 13, 0, 4, 1, 5, 2, 6, 3, 7], vec![0usize, 1, 2, 3]),
    ] {
        let s = free_system(&which, &inputs);
        let t0 = std::time::Instant::now();
        let d = regenerate_with_progress(&s, &DecomposeSettings::default(), &mut |p| eprintln!("  {p:?} {:.1}s", t0.elapsed().as_secs_f64())).unwrap();
        eprintln!(
            "{label}: {:?} junk {} unresolved {:?} paths {} {:.2}s",
            d.signature(),
            d.junk,
            d.unresolved.iter().map(|u| u.0).collect::<Vec<_>>(),
            d.paths,
            d.seconds
        );
        for c in &d.components {
            let p = &c.sample_point;
            eprintln!("  dim {} deg {} trace {} x=({:.2e},{:.2e},{:.2e},{:.2e})", c.dimension, c.degree, c.trace_test_passed, p[0].norm(), p[1].norm(), p[2].norm(), p[3].norm());
        }
    }
}
