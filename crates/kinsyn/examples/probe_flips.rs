//! Finds lock subsets whose pattern flips between two seeds, and shows their conditioning.
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
    let lines: Vec<String> = picked
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
                if pats.iter().any(|p| p != &pats[0]) {
                    let mask = m.lock_mask(&locked);
                    let mob = m.mechanism().mobility(&m.reference(), &mask);
                    let sv = &mob.closure_rank.singular_values;
                    let top = sv.first().copied().unwrap_or(0.0);
                    let kept = mob.closure_rank.smallest_kept();
                    let dropped = mob.closure_rank.largest_dropped();
                    out.push(format!(
                        "{} {} {:?} lock {} : {:?} closure kept {:.1e} dropped {:.1e}",
                        d.index,
                        d.notation,
                        d.actuated,
                        m.lock_text(&locked),
                        pats,
                        kept / top,
                        dropped / top
                    ));
                }
            }
            out
        })
        .collect();
    for l in &lines {
        println!("{l}");
    }
    println!("{} flipping subsets", lines.len());
}
