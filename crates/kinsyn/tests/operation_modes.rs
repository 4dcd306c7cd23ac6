//! scratch
use kinsyn::manipulator::{InputValues, Manipulator, OperationModeSettings};

fn ruu() -> Manipulator {
    Manipulator::from_json(&std::fs::read_to_string("../../mechanisms/4-ruu.json").unwrap()).unwrap()
}

fn show(label: &str, inputs: &[(usize, f64)]) {
    let m = ruu();
    let t0 = std::time::Instant::now();
    let modes = m.operation_modes(&InputValues::Given(inputs), &OperationModeSettings::default()).unwrap();
    eprintln!("{label}: {:?} paths {} unresolved {} junk {} {:.2}s", modes.decomposition.signature(), modes.decomposition.paths, modes.decomposition.unresolved.len(), modes.decomposition.junk, t0.elapsed().as_secs_f64());
    for c in &modes.components {
        let x = &c.sample;
        eprintln!(" dim {} deg {} real {} x0..3 = {:.1e} {:.1e} {:.1e} {:.1e}", c.dimension, c.degree, c.real_points.len(), x[0].norm(), x[1].norm(), x[2].norm(), x[3].norm());
        if let Some(r) = &c.real { eprintln!("   self: dof {} {:?} {}", r.dof, r.motion.pattern.name(), r.motion.dof); }
        if let Some(r) = &c.released { eprintln!("   released: dof {} {:?} sep {:?}", r.dof, r.motion.pattern.name(), r.motion.min_separation); }
    }
}

#[test]
fn scratch() {
    show("generic", &[(0, 0.3), (1, -0.2), (2, 0.25), (3, 0.1)]);
    show("equal", &[(0, 0.3 + std::f64::consts::FRAC_PI_2), (1, 0.3), (2, 0.3 - std::f64::consts::FRAC_PI_2), (3, 0.3)]);
}
