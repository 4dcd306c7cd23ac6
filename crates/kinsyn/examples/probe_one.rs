//! Looks into one lock subset's sampled motion: the platform's twist singular values at each
//! sample (over the scale they are judged against) and the closure's conditioning.
use kinsyn::manipulator::Manipulator;
use kinsyn::mechanism::SampleSettings;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let m = Manipulator::from_json(&std::fs::read_to_string(&a[1]).unwrap()).unwrap();
    let locked = m.parse_locks(&a[2]).unwrap();
    let mask = m.lock_mask(&locked);
    let mech = m.mechanism();
    for seed in [2026u64, 7, 11, 13] {
        let s = SampleSettings {
            seed,
            ..SampleSettings::default()
        };
        let mode = m.mode(&locked, &s);
        let motion = mech
            .sample_motion(m.platform(), &m.reference(), &mask, &s)
            .unwrap();
        println!(
            "seed {seed}: {} sep {:.2e}",
            mode.pattern_text(),
            motion.min_separation
        );
        for smp in &motion.samples {
            let r = &smp.rank;
            let c = mech.mobility(&smp.q, &mask).closure_rank;
            let top = c.singular_values.first().copied().unwrap_or(1.0);
            println!(
                "   twist sv/scale {:?} rank {}; closure gap {:.1e} dof {}",
                r.singular_values
                    .iter()
                    .map(|x| format!("{:.1e}", x / r.scale))
                    .collect::<Vec<_>>(),
                r.rank,
                c.smallest_kept() / top,
                mech.mobility(&smp.q, &mask).dof
            );
            let t = &smp.twists;
            println!(
                "   twist basis rot rows norm {:.2e}, trans rows norm {:.2e}",
                t.rows(0, 3).norm(),
                t.rows(3, 3).norm()
            );
        }
    }
}
