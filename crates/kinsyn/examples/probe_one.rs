//! Looks into one lock subset's sampled motion: twist-space deviation against distance.
use kinsyn::manipulator::Manipulator;
use kinsyn::mechanism::SampleSettings;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let m = Manipulator::from_json(&std::fs::read_to_string(&a[1]).unwrap()).unwrap();
    let locked = m.parse_locks(&a[2]).unwrap();
    let mask = m.lock_mask(&locked);
    let mech = m.mechanism();
    for step in [0.001, 0.003, 0.01, 0.03, 0.1, 0.3] {
        let s = SampleSettings {
            seed: 5,
            samples: 2,
            steps: 3,
            step,
        };
        let motion = mech
            .sample_motion(m.platform(), &m.reference(), &mask, &s)
            .unwrap();
        let b0 = &motion.samples[0].twists;
        let smp = &motion.samples[1];
        let p = b0 * b0.transpose();
        let d = (&smp.twists - &p * &smp.twists).norm();
        let mob = mech.mobility(&smp.q, &mask);
        println!(
            "step {step}: sep {:.3e} dev {d:.3e} closure sv {:?} dof {}",
            motion.min_separation,
            mob.closure_rank
                .singular_values
                .iter()
                .map(|x| format!("{x:.2e}"))
                .collect::<Vec<_>>(),
            mob.dof
        );
    }
}
#[allow(dead_code)]
fn unused() {}
