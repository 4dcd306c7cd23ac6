//! Mixed volumes, mixed cells and binomial systems (`kinsyn_nag::polyhedral`).

use kinsyn_nag::poly::C64;
use kinsyn_nag::poly::families::{cyclic, katsura};
use kinsyn_nag::polyhedral::{
    MixedCellSettings, binomial_roots, mixed_cells, mixed_volume, supports_of,
};

fn mv(system: &kinsyn_nag::poly::System, origin: bool, seed: u64) -> u128 {
    let settings = MixedCellSettings {
        seed,
        ..MixedCellSettings::default()
    };
    mixed_volume(&supports_of(system, origin), &settings).unwrap()
}

#[test]
fn probe() {
    for n in [3, 4, 5, 6, 7] {
        let s = cyclic(n);
        let t = std::time::Instant::now();
        let sub = mixed_cells(&supports_of(&s, false), &MixedCellSettings::default()).unwrap();
        eprintln!(
            "cyclic-{n} torus MV {} cells {} lps {} {:?}",
            sub.mixed_volume(),
            sub.cells.len(),
            sub.linear_programs,
            t.elapsed()
        );
        let t = std::time::Instant::now();
        eprintln!("cyclic-{n} origin MV {} {:?}", mv(&s, true, 1), t.elapsed());
    }
    for n in [2, 3, 4, 5, 6, 7, 8] {
        let s = katsura(n);
        let t = std::time::Instant::now();
        let sub = mixed_cells(&supports_of(&s, true), &MixedCellSettings::default()).unwrap();
        eprintln!(
            "katsura-{n} MV {} lps {} {:?}",
            sub.mixed_volume(),
            sub.linear_programs,
            t.elapsed()
        );
    }
}
