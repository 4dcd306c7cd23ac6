//! Paper 001 §4 (Figs. 3–4) by `kinsyn_papers::hexa`'s workspace search and index maps, each against an
//! independent method or a hand argument: the limbs' reach by the distance from a point to the
//! circle of the active link's end (not eq. 5), the index zeros by finite differences of the
//! inverse geometry (not the Jacobians), the reach along the z axis in closed form, and the
//! paper's observations on the maps (λ > 0.2, σ near the boundary, ξ inside, y ≤ 0).

use kinsyn_papers::hexa::{
    Hexa, IndexMap, IndexMapSettings, Indices, Pose, Workspace, WorkspaceSettings, mu, rz,
};
use nalgebra::{Matrix2, Vector3};

fn quiet(_: usize, _: usize) {}

fn workspace(h: &Hexa, step: f64, phi1: f64, phi2: f64) -> Workspace {
    h.workspace(
        &WorkspaceSettings {
            step,
            phi1,
            phi2,
            curve_samples: 90,
        },
        &quiet,
    )
    .unwrap()
}

fn map(h: &Hexa, z: f64, half_width: f64, step: f64, phi: (f64, f64)) -> IndexMap {
    h.index_map(
        &IndexMapSettings {
            z,
            half_width,
            step,
            phi1: phi.0,
            phi2: phi.1,
        },
        &quiet,
    )
    .unwrap()
}

const DEG45: f64 = std::f64::consts::FRAC_PI_4;
const ORIENTATIONS: [(f64, f64); 2] = [(0.0, 0.0), (DEG45, -DEG45)];

/// Whether a limb of length `l` on the circle of radius `b` about `a` (in the plane normal to
/// `u`) reaches `c`: the distances from `c` to that circle run from
/// `√(m∥² + (m⊥ − b)²)` to `√(m∥² + (m⊥ + b)²)` (`m = c − a`) — elementary geometry, not eq. 5.
fn circle_reaches(h: &Hexa, i: usize, c: &Vector3<f64>) -> bool {
    let m = c - h.base_joint(i);
    let along = m.dot(&h.axis(i));
    let across = (m.norm_squared() - along * along).max(0.0).sqrt();
    let near = along.hypot(across - h.b);
    let far = along.hypot(across + h.b);
    near <= h.l && h.l <= far
}

#[test]
fn the_grid_search_agrees_with_the_circle_criterion_and_the_axis_reach_with_eq4() {
    let h = Hexa::paper001();
    let w = workspace(&h, 40.0, 0.0, 0.0);
    let g = w.grid;
    // End-effector 1 needs limbs 1, 2, 3, 6 (and a four-bar position limbs 4, 5 reach): every
    // reachable cell passes the circle criterion for limbs 1, 2, 3, 6.
    for (index, reachable) in w.end_effector1.iter().enumerate() {
        let (i, j, k) = g.cell(index);
        let p1 = g.centre(i, j, k);
        let joints = h.platform_joints(&Pose::new(&p1, 0.0, &p1, 0.0));
        let by_circles = [0, 1, 2, 5]
            .iter()
            .all(|&l| circle_reaches(&h, l, &joints[l]));
        assert_eq!(h.reaches_end_effector1(&p1, 0.0), by_circles, "{p1:?}");
        if *reachable {
            assert!(by_circles, "{p1:?}");
        }
    }
    // On the z axis (φ1 = 0) c1 = (r1, 0, z) lies in the plane of limb 1's circle (x = a = r1),
    // at √(R² + z²) from a1: limb 1 reaches it iff l − b ≤ √(R² + z²) ≤ l + b, i.e.
    // z ∈ [−√((b+l)² − R²), −√((l−b)² − R²)] = [−784.9, −210.0] mm.
    let deepest = -((h.b + h.l).powi(2) - h.big_r.powi(2)).sqrt();
    let highest = -((h.l - h.b).powi(2) - h.big_r.powi(2)).sqrt();
    assert!((deepest + 784.92).abs() < 0.01 && (highest + 210.0).abs() < 1e-9);
    let axis: Vec<f64> = (0..g.layers)
        .filter(|&k| w.end_effector1[g.index(g.n, g.n, k)])
        .map(|k| -(k as f64) * g.step)
        .collect();
    assert!(
        axis.iter().all(|z| (deepest..=highest).contains(z)),
        "{axis:?}"
    );
    // The deepest reachable axis cell is the last grid layer above −784.9 (−760 at 40 mm):
    // at the bottom limb 1 is the one that stops the robot.
    assert_eq!(axis.last().copied(), Some(-760.0));
    // Just beyond b + l from a1 nothing is reachable: P1 with c1 at (b + l)(1 + 1e-9) from a1.
    let a1 = h.base_joint(0);
    let out = a1 + Vector3::new(0.0, -0.6, -0.8) * (h.b + h.l) * (1.0 + 1e-9)
        - Vector3::new(h.r[0], 0.0, 0.0);
    assert!(!h.reaches_end_effector1(&out, 0.0));
    let inside = a1 + Vector3::new(0.0, -0.6, -0.8) * (h.b + h.l) * (1.0 - 1e-9)
        - Vector3::new(h.r[0], 0.0, 0.0);
    assert!(circle_reaches(
        &h,
        0,
        &(inside + Vector3::new(h.r[0], 0.0, 0.0))
    ));
    // The grid's half-width bounds both workspaces with room to spare.
    let half = g.n as f64 * g.step;
    for p in w.points(0).iter().chain(&w.points(1)) {
        assert!(
            p.x.abs() < half - g.step && p.y.abs() < half - g.step,
            "{p:?}"
        );
    }
}

/// θ4, θ5 by the inverse geometry, end-effector 1 at `(p1, φ1)`, the four-bar at crank angle
/// `alpha` on the branch of `beta0`, end-effector 2 at `φ2`.
fn thetas45(h: &Hexa, p1: &Vector3<f64>, phi1: f64, alpha: f64, beta0: f64, phi2: f64) -> [f64; 2] {
    let fb = h.four_bar(p1, phi1);
    let betas = h.rocker_angles(&fb, alpha).unwrap();
    let gap = |b: f64| (b - beta0).sin().abs() + (1.0 - (b - beta0).cos());
    let beta = if gap(betas[0]) <= gap(betas[1]) {
        betas[0]
    } else {
        betas[1]
    };
    let p2 = h.four_bar_pose(&fb, alpha, beta).p2;
    let c = h.platform_joints(&Pose::new(p1, phi1, &p2, phi2));
    [3, 4].map(|i| h.working_root(i, &c[i]).unwrap())
}

/// `|det J| / (‖row 1‖ ‖row 2‖)` of end-effector 2's input Jacobian `∂(θ4, θ5)/∂(α, φ2)` by
/// central differences of the inverse geometry: 0 exactly where the two limbs cannot resist a
/// motion (a parallel singularity).
fn xi_singularity_fd(h: &Hexa, p1: &Vector3<f64>, phi1: f64, phi2: f64) -> f64 {
    let n = h.nominal_four_bar(p1, phi1).unwrap();
    let e = 1e-6;
    let d_alpha = [0, 1].map(|r| {
        (thetas45(h, p1, phi1, n.alpha + e, n.beta, phi2)[r]
            - thetas45(h, p1, phi1, n.alpha - e, n.beta, phi2)[r])
            / (2.0 * e)
    });
    let d_phi = [0, 1].map(|r| {
        (thetas45(h, p1, phi1, n.alpha, n.beta, phi2 + e)[r]
            - thetas45(h, p1, phi1, n.alpha, n.beta, phi2 - e)[r])
            / (2.0 * e)
    });
    let m = Matrix2::new(d_alpha[0], d_phi[0], d_alpha[1], d_phi[1]);
    m.determinant().abs() / (m.row(0).norm() * m.row(1).norm())
}

#[test]
fn indices_lie_in_0_1_and_vanish_with_the_finite_difference_determinants() {
    let h = Hexa::paper001();
    for phi in ORIENTATIONS {
        let m = map(&h, -420.0, 360.0, 40.0, phi);
        let mut pairs = Vec::new();
        for (x, y, ind) in m.iter() {
            let Some(ind) = ind else { continue };
            for v in ind.lambda.iter().chain(&ind.xi).chain([&ind.sigma]) {
                assert!((0.0..=1.0).contains(v), "{v} at {x}, {y}");
            }
            let p1 = Vector3::new(x, y, m.z);
            let xi_fd = xi_singularity_fd(&h, &p1, phi.0, phi.1);
            // end_effector2_jacobian's determinant, normalised the same way.
            let p2 = h.nominal_four_bar(&p1, phi.0).unwrap().p2;
            let conf = h.inverse(&Pose::new(&p1, phi.0, &p2, phi.1)).unwrap();
            let j2 = h.end_effector2_jacobian(&conf).unwrap();
            let j2_ratio = j2.determinant().abs() / (j2.row(0).norm() * j2.row(1).norm());
            pairs.push((ind.xi_min(), xi_fd, j2_ratio));
        }
        // Where ξ_min = 0 both determinants vanish (end_effector2_jacobian's and the
        // finite-difference one of the inverse geometry). Away from zero they are not functions
        // of ξ_min, nor should they be: a normalised determinant depends on the columns' units
        // (a crank angle against φ2), and ξ_k is the cosine between the limb's force w_k, mostly
        // vertical, and the horizontal motion of C_k, so a cell can have ξ_min = 0.004 and a
        // ratio of 0.83. ξ itself is checked against a position-level method in tests/suite/hexa.rs
        // (`xi_is_the_pressure_angle_found_by_moving_the_robot`).
        let mut zero_xi = 0;
        for (xi, xi_fd, j2) in &pairs {
            if *xi < 1e-9 {
                assert!(*xi_fd < 1e-4 && *j2 < 1e-9, "{xi} {xi_fd} {j2}");
            }
            if *xi < 1e-9 {
                zero_xi += 1;
            }
        }
        // At φ1 = φ2 = 0 the mirror line x1 = 0 is singular for end-effector 2 (ξ = 0).
        if phi.0 == 0.0 {
            assert!(zero_xi >= 15, "{zero_xi}");
        }
    }
}

/// The cells of a map inside the disc of radius `rho`, with their indices.
fn disc(m: &IndexMap, rho: f64) -> Vec<(f64, f64, Indices)> {
    m.iter()
        .filter(|(x, y, _)| x.hypot(*y) <= rho)
        .map(|(x, y, i)| (x, y, *i.expect("the regular workspace is assemblable")))
        .collect()
}

fn mean(v: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = v.fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    sum / n as f64
}

#[test]
fn section_4_observations_over_the_regular_workspace() {
    let h = Hexa::paper001();
    for phi in ORIENTATIONS {
        let w = workspace(&h, 40.0, phi.0, phi.1);
        let c = w.regular_cylinder().expect("a regular workspace");
        // Paper 001 §4: λ > 0.2 over the regular workspace. Measured minimum 0.62 (φ = ±45°)
        // to 0.69 (φ = 0) on a 20 mm grid at the middle height.
        let cells = disc(&map(&h, c.middle(), c.radius, 20.0, phi), c.radius);
        let lambda = cells.iter().map(|c| c.2.lambda_min()).fold(1.0, f64::min);
        assert!(lambda > 0.6, "{lambda}");
        // "better transmission for y ≤ 0": holds for σ in both orientations (mean over the
        // disc's halves).
        let south = |f: &dyn Fn(&Indices) -> f64, s: bool| {
            mean(cells.iter().filter(|c| (c.1 <= 0.0) == s).map(|c| f(&c.2)))
        };
        let sigma = |i: &Indices| i.sigma;
        assert!(south(&sigma, true) > south(&sigma, false) + 0.15, "{phi:?}");
        // σ is smallest at the workspace's edge: the mean over the outer ring (r > 0.8 ρ) is
        // below the mean over the inner disc (r < 0.5 ρ).
        let ring = |lo: f64, hi: f64| {
            mean(
                cells
                    .iter()
                    .filter(|q| (lo * c.radius..hi * c.radius).contains(&q.0.hypot(q.1)))
                    .map(|q| q.2.sigma),
            )
        };
        assert!(ring(0.8, 1.01) < ring(0.0, 0.5), "{phi:?}");
    }
}

#[test]
fn xi_vanishes_on_the_mirror_plane_at_zero_orientation() {
    // Hand argument: at φ1 = φ2 = 0 with x1 = 0 and P2 at the symmetric assembly, the mirror
    // x → −x maps the robot onto itself and limb 4 onto limb 5 (μ = ±2π/3, a4 = mirror of a5,
    // c4 = mirror of c5). Turning end-effector 2 (φ̇2) is odd under the mirror, the four-bar's
    // symmetric motion is even; the limbs' rates are mirror images, so the odd motion changes
    // θ4 and θ5 by opposite amounts and the even one by equal amounts: the rows of
    // end-effector 2's Jacobian are (e, o) and (e, −o), singular only if e o = 0. The
    // four-bar's motion at its symmetric assembly is an x-translation of P2 (the coupler
    // parallel to the ground link: both cranks move at equal rates the same way), which is odd:
    // so both columns are odd, e = 0 and the Jacobian is singular (ξ = 0).
    let h = Hexa::paper001();
    for (y, z) in [(0.0, -420.0), (-150.0, -350.0), (200.0, -500.0)] {
        let p1 = Vector3::new(0.0, y, z);
        let a = h.base_joint(3);
        let b = h.base_joint(4);
        assert!((a.x + b.x).abs() < 1e-9 && (a.y - b.y).abs() < 1e-9);
        assert!(h.nominal_indices(&p1, 0.0, 0.0).unwrap().xi_min() < 1e-9);
        assert!(xi_singularity_fd(&h, &p1, 0.0, 0.0) < 1e-5);
        // Off the plane it is not singular.
        let off = Vector3::new(200.0, 100.0, z);
        assert!(h.nominal_indices(&off, 0.0, 0.0).unwrap().xi_min() > 0.05);
    }
    let _ = (mu(0), rz(0.0));
}

#[test]
fn the_indices_do_not_depend_on_the_unit_of_length() {
    let h = Hexa::paper001();
    let big = Hexa {
        big_r: h.big_r * 10.0,
        a: h.a * 10.0,
        b: h.b * 10.0,
        l: h.l * 10.0,
        r: h.r.map(|r| r * 10.0),
        gamma: h.gamma,
    };
    for phi in ORIENTATIONS {
        let small = map(&h, -420.0, 300.0, 50.0, phi);
        let large = map(&big, -4200.0, 3000.0, 500.0, phi);
        assert_eq!(small.cells.len(), large.cells.len());
        for (a, b) in small.cells.iter().zip(&large.cells) {
            let (a, b) = (a.unwrap(), b.unwrap());
            let pairs = a
                .lambda
                .iter()
                .chain(&a.xi)
                .chain([&a.sigma])
                .zip(b.lambda.iter().chain(&b.xi).chain([&b.sigma]));
            for (u, v) in pairs {
                assert!((u - v).abs() < 1e-9, "{u} {v}");
            }
        }
        let ws = workspace(&h, 40.0, phi.0, phi.1);
        let wl = workspace(&big, 400.0, phi.0, phi.1);
        assert_eq!(ws.grid.layers, wl.grid.layers);
        let differ = ws
            .end_effector1
            .iter()
            .zip(&wl.end_effector1)
            .filter(|(a, b)| a != b)
            .count();
        assert!(differ <= 2, "{differ}");
    }
}

#[test]
fn the_search_is_the_same_on_one_thread_and_reports_its_progress() {
    let h = Hexa::paper001();
    let settings = WorkspaceSettings {
        step: 40.0,
        curve_samples: 90,
        ..WorkspaceSettings::default()
    };
    let calls = std::sync::atomic::AtomicUsize::new(0);
    let last = std::sync::Mutex::new((0, 0));
    let many = h
        .workspace(&settings, &|done, total| {
            calls.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let mut l = last.lock().unwrap();
            *l = (l.0.max(done), total);
        })
        .unwrap();
    let (done, total) = *last.lock().unwrap();
    assert_eq!((done, total), (many.grid.side() * many.grid.layers, total));
    assert_eq!(calls.into_inner(), total);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let one = pool.install(|| h.workspace(&settings, &quiet).unwrap());
    assert_eq!(one, many);
    assert!(
        h.workspace(
            &WorkspaceSettings {
                step: 0.0,
                ..settings
            },
            &quiet
        )
        .is_err()
    );
    assert!(
        h.workspace(
            &WorkspaceSettings {
                step: 0.01,
                ..settings
            },
            &quiet
        )
        .is_err()
    );
    assert!(
        h.workspace(
            &WorkspaceSettings {
                phi1: f64::NAN,
                ..settings
            },
            &quiet
        )
        .is_err()
    );
}
