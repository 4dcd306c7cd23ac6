#[test]
fn c6() {
    use kinsyn::homotopy::*;
    for seed in 1..6 {
        let r = solve(&kinsyn::poly::families::cyclic(6), &SolveSettings { seed, ..SolveSettings::default() }).unwrap();
        let total: usize = r.ends.iter().map(|e| e.steps).sum();
        eprintln!("seed {seed} {} certified {} real {} retracked {} steps {} time {:.3}", r.summary(), r.certified(), r.certified_real(), r.retracked, total, r.seconds);
    }
}
