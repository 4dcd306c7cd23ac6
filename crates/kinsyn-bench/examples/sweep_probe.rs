//! Times the sweep core on every n-th design (a probe for the speed work).
use kinsyn::catalogue::Catalogue;
use kinsyn::sweep::{SweepSettings, designs};
use rayon::prelude::*;
fn main() {
    let every: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    let cat = Catalogue::committed().unwrap();
    let mut s = SweepSettings::default();
    if let Some(seed) = std::env::args().nth(3).and_then(|a| a.parse().ok()) {
        s.sampling.seed = seed;
    }
    let all = designs(&cat, &s);
    let picked: Vec<_> = all.iter().step_by(every).collect();
    let t = std::time::Instant::now();
    let rows: Vec<_> = picked.par_iter().map(|d| d.evaluate(&s)).collect();
    let dt = t.elapsed().as_secs_f64();
    let errors = rows.iter().filter(|r| r.error.is_some()).count();
    let kinds: usize = rows.iter().map(|r| r.kinds).sum();
    println!(
        "{} designs of {}: {dt:.2} s, {:.2} ms/design wall; errors {errors}; kinds sum {kinds}; extrapolated {:.0} s",
        picked.len(),
        all.len(),
        1e3 * dt / picked.len() as f64,
        dt * all.len() as f64 / picked.len() as f64
    );
    if std::env::args().nth(2).is_some() {
        for r in &rows {
            println!("{}", serde_json::to_string(r).unwrap());
        }
    }
}
