use kinsyn::hexa::*;
use nalgebra::Vector3;

#[test]
fn explore() {
    let h = Hexa::paper001();
    for step in [40.0, 20.0] {
        let t = std::time::Instant::now();
        let w = h.workspace(&WorkspaceSettings { step, ..Default::default() }, &|_, _| {}).unwrap();
        println!("step {step}: grid {:?} time {:?} n1 {} n2 {} cyl {:?}", w.grid, t.elapsed(), w.points(0).len(), w.points(1).len(), w.regular_cylinder());
        for k in 0..w.grid.layers { println!("  layer z={} r={:?} n1 {} n2 {}", -(k as f64)*step, w.layer_radius(k),
            w.end_effector1[k*w.grid.side()*w.grid.side()..(k+1)*w.grid.side()*w.grid.side()].iter().filter(|b|**b).count(),
            w.end_effector2[k*w.grid.side()*w.grid.side()..(k+1)*w.grid.side()*w.grid.side()].iter().filter(|b|**b).count()); }
        let pts = w.points(0); let m = pts.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        let pts2 = w.points(1); let m2 = pts2.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        println!("max |x|,|y| P1 {m} P2 {m2}, H {}", h.workspace_half_width());
        if step < 30.0 { let c = w.regular_cylinder().unwrap();
          for phi in [(0.0,0.0),(45f64.to_radians(), -45f64.to_radians())] {
            let t = std::time::Instant::now();
            let map = h.index_map(&IndexMapSettings{z: c.middle(), half_width: c.radius, step: 10.0, phi1: phi.0, phi2: phi.1}, &|_,_|{}).unwrap();
            let cells: Vec<_> = map.iter().filter(|(x,y,_)| x*x+y*y <= c.radius*c.radius).collect();
            let ok: Vec<_> = cells.iter().filter_map(|c| c.2).collect();
            let lmin = ok.iter().map(|i| i.lambda_min()).fold(f64::INFINITY, f64::min);
            let smin = ok.iter().map(|i| i.sigma).fold(f64::INFINITY, f64::min);
            let smax = ok.iter().map(|i| i.sigma).fold(0.0, f64::max);
            let xmin = ok.iter().map(|i| i.xi_min()).fold(f64::INFINITY, f64::min);
            let xmax = ok.iter().map(|i| i.xi_min()).fold(0.0, f64::max);
            println!("phi {phi:?}: {} cells, {} ok, time {:?}, lambda_min {lmin}, sigma {smin}..{smax}, xi {xmin}..{xmax}", cells.len(), ok.len(), t.elapsed());
            let mean = |f: &dyn Fn(&Indices)->f64, neg: bool| { let v: Vec<f64> = cells.iter().filter(|c| (c.1 <= 0.0) == neg).filter_map(|c| c.2.map(f)).collect(); v.iter().sum::<f64>()/v.len() as f64 };
            println!("  y<=0 mean lam {} sig {} xi {} ; y>0 lam {} sig {} xi {}", mean(&|i| i.lambda_min(), true), mean(&|i| i.sigma, true), mean(&|i| i.xi_min(), true), mean(&|i| i.lambda_min(), false), mean(&|i| i.sigma, false), mean(&|i| i.xi_min(), false));
          }
        }
    }
    let _ = Vector3::<f64>::zeros();
}
