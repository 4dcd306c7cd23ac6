//! Finds lock subsets whose pattern flips between seeds, and shows the conditioning of the
//! closure equations at the sampled configurations (the smallest kept singular value over the
//! largest), against that of subsets that do not flip.
use kinsyn::catalogue::Catalogue;
use kinsyn::mechanism::SampleSettings;
use kinsyn::sweep::{SweepSettings, designs};
use rayon::prelude::*;
fn main() {
    let every: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    let cat = Catalogue::committed().unwrap();
    let s = SweepSettings::default();
    let all = designs(&cat, &s);
    let picked: Vec<_> = all.iter().step_by(every).collect();
    let rows: Vec<(bool, f64, String)> = picked
        .par_iter()
        .flat_map(|d| {
            let m = d.manipulator(3).unwrap();
            let n = m.actuators().len();
            let mut out = Vec::new();
            for locked in m.lock_subsets(n) {
                let pats: Vec<String> = [2026u64, 7, 11, 13]
                    .iter()
                    .map(|&seed| {
                        let st = SampleSettings {
                            seed,
                            ..SampleSettings::default()
                        };
                        m.mode(&locked, &st).pattern_text()
                    })
                    .collect();
                let flips = pats.iter().any(|p| p != &pats[0]);
                let mask = m.lock_mask(&locked);
                let st = SampleSettings::default();
                let start_dof = m.mechanism().mobility(&m.reference(), &mask).dof;
                let sample_dof =
                    match m
                        .mechanism()
                        .sample_motion(m.platform(), &m.reference(), &mask, &st)
                    {
                        Ok(motion) => motion
                            .samples
                            .iter()
                            .map(|smp| m.mechanism().mobility(&smp.q, &mask).dof)
                            .max()
                            .unwrap_or(0),
                        Err(_) => 99,
                    };
                let worst = if start_dof > sample_dof { 0.5e-12 } else { 1.0 };
                out.push((
                    flips,
                    worst,
                    format!(
                        "{} {} {:?} lock {} : {:?}",
                        d.index,
                        d.notation,
                        d.actuated,
                        m.lock_text(&locked),
                        pats
                    ),
                ));
            }
            out
        })
        .collect();
    let bins = [1e-12, 1.1];
    let mut lo = 0.0;
    for b in bins {
        let f = rows.iter().filter(|r| r.0 && r.1 >= lo && r.1 < b).count();
        let nf = rows.iter().filter(|r| !r.0 && r.1 >= lo && r.1 < b).count();
        println!("closure gap [{lo:.0e}, {b:.0e}): flipping {f}, stable {nf}");
        lo = b;
    }
    for r in rows.iter().filter(|r| r.0 && r.1 > 1e-6) {
        println!("flip at a regular start: {}", r.2);
    }
}
