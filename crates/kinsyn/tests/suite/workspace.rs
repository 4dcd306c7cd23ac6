//! Workspaces on a grid (src/workspace/): the grid's cells, centres and indices, its cell-count
//! limit, the volume and points of a set of cells, the largest regular cylinder in several sets
//! and the parallel scans, each against a hand derivation (cells counted, centres and radii
//! worked out, cylinders compared by `π ρ² h`) or a plain sequential loop.

use kinsyn::workspace::{
    Cylinder, Grid, MAX_CELLS, WorkspaceError, check_step, count, finite, map_in_parallel,
};
use nalgebra::Vector3;
use std::f64::consts::PI;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

fn quiet(_: usize, _: usize) {}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

#[test]
fn centres_indices_and_nearest_cells_invert_each_other() {
    // n = 2, 3 layers, step 0.7: 5 × 5 × 3 = 75 cells, centres at x, y ∈ {−1.4, −0.7, 0, 0.7,
    // 1.4} and z ∈ {0, −0.7, −1.4}.
    let g = Grid {
        step: 0.7,
        n: 2,
        layers: 3,
    };
    assert_eq!((g.side(), g.cells()), (5, 75));
    let mut seen = vec![false; g.cells()];
    for k in 0..3 {
        for j in 0..5 {
            for i in 0..5 {
                let index = g.index(i, j, k);
                assert!(!seen[index], "{i} {j} {k}");
                seen[index] = true;
                assert_eq!(g.cell(index), (i, j, k));
                let c = g.centre(i, j, k);
                let expected = Vector3::new(
                    0.7 * (i as f64 - 2.0),
                    0.7 * (j as f64 - 2.0),
                    -0.7 * k as f64,
                );
                assert!((c - expected).norm() < 1e-12, "{c:?}");
                assert_eq!(g.nearest(&c), Some((i, j, k)));
                // Anywhere less than half a step from the centre, in each coordinate, is in
                // the same cell.
                for d in [
                    Vector3::new(0.34, -0.34, 0.34),
                    Vector3::new(-0.34, 0.34, -0.34),
                ] {
                    assert_eq!(g.nearest(&(c + d)), Some((i, j, k)));
                }
            }
        }
    }
    assert!(seen.iter().all(|s| *s));
    // By hand on n = 1 (side 3), step 2: cell (2, 1, 1) is layer 1, row 1, column 2:
    // (1·3 + 1)·3 + 2 = 14, centre (2, 0, −2).
    let small = Grid {
        step: 2.0,
        n: 1,
        layers: 2,
    };
    assert_eq!(small.index(2, 1, 1), 14);
    assert_eq!(small.cell(14), (2, 1, 1));
    assert_eq!(small.centre(2, 1, 1), Vector3::new(2.0, 0.0, -2.0));
    // Beyond the outer faces (|x| or |y| > (n + ½) s, z > s/2 or z < −(layers − ½) s): no cell.
    for p in [
        Vector3::new(1.76, 0.0, 0.0),
        Vector3::new(0.0, -1.76, 0.0),
        Vector3::new(0.0, 0.0, 0.36),
        Vector3::new(0.0, 0.0, -1.76),
    ] {
        assert_eq!(g.nearest(&p), None, "{p:?}");
    }
    assert_eq!(
        g.nearest(&Vector3::new(1.74, -1.74, -1.74)),
        Some((4, 0, 2))
    );
}

#[test]
fn a_covering_grid_counts_its_cells_and_refuses_too_many() {
    // Half-width 25 at step 10: ⌊2.5⌋ + 1 = 3 cells on each side (the outermost centre at 30,
    // beyond 25); depth 31: layers at 0, −10, −20, −30, i.e. ⌊3.1⌋ + 1 = 4.
    let g = Grid::covering(10.0, 25.0, 31.0).unwrap();
    assert_eq!((g.step, g.n, g.layers), (10.0, 3, 4));
    assert_eq!(g.cells(), 7 * 7 * 4);
    // Every x, y within the half-width rounds to a cell of the grid.
    assert!(g.nearest(&Vector3::new(25.0, -25.0, -30.0)).is_some());
    // 20,000,000 = 125² · 1280: at step 1, half-width 61.5 gives n = ⌊61.5⌋ + 1 = 62 (side 125)
    // and depth 1279 gives 1280 layers: exactly the limit, allowed; one more layer is over.
    assert_eq!(MAX_CELLS, 20_000_000);
    let at = Grid::covering(1.0, 61.5, 1279.0).unwrap();
    assert_eq!((at.n, at.layers, at.cells()), (62, 1280, MAX_CELLS));
    assert_eq!(
        Grid::covering(1.0, 61.5, 1280.0),
        Err(WorkspaceError::TooManyCells {
            step: 1.0,
            cells: 125 * 125 * 1281,
            max: MAX_CELLS
        })
    );
    // Half-width 1000, depth 100 at step 1: side 2 · 1001 + 1 = 2003, 101 layers,
    // 2003² · 101 = 4 012 009 · 101 = 405 212 909 cells.
    let e = Grid::covering(1.0, 1000.0, 100.0).unwrap_err();
    assert_eq!(
        e.to_string(),
        "grid step 1 makes 405212909 cells, more than 20000000: give a larger step"
    );
    // Too many steps to count along one side: the count saturates.
    assert_eq!(
        Grid::covering(1.0, 1e12, 1.0).unwrap_err().to_string(),
        format!(
            "grid step 1 makes {} cells, more than 20000000: give a larger step",
            usize::MAX
        )
    );
    for step in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Grid::covering(step, 1.0, 1.0),
            Err(WorkspaceError::Step(_))
        ));
    }
    assert_eq!(
        Grid::covering(0.0, 1.0, 1.0).unwrap_err().to_string(),
        "grid step 0: give a positive length"
    );
    assert_eq!(check_step(0.25), Ok(0.25));
    assert_eq!(
        check_step(-2.0).unwrap_err().to_string(),
        "grid step -2: give a positive length"
    );
    assert_eq!((count(25.0, 10.0), count(30.0, 10.0)), (Ok(2), Ok(3)));
    assert_eq!((count(-5.0, 10.0), count(f64::NAN, 10.0)), (Ok(0), Ok(0)));
    assert_eq!(finite("z", -3.5), Ok(-3.5));
    assert_eq!(
        finite("φ1", f64::NAN).unwrap_err().to_string(),
        "φ1 NaN: not finite"
    );
}

#[test]
fn a_set_of_cells_has_their_centres_and_count_times_the_cube_of_the_step() {
    // n = 2, 3 layers, step 0.5: the axis column (3 cells) and the 4 neighbours of the axis
    // cell in the top layer: 7 cells, 7 · 0.5³ = 0.875.
    let g = Grid {
        step: 0.5,
        n: 2,
        layers: 3,
    };
    let mut set = vec![false; g.cells()];
    for (i, j, k) in [
        (2, 2, 0),
        (2, 2, 1),
        (2, 2, 2),
        (1, 2, 0),
        (3, 2, 0),
        (2, 1, 0),
        (2, 3, 0),
    ] {
        set[g.index(i, j, k)] = true;
    }
    assert!(close(g.volume(&set), 0.875));
    // In index order: the top layer row by row (y = −0.5, then 0, then 0.5), then the axis below.
    let expected = [
        (0.0, -0.5, 0.0),
        (-0.5, 0.0, 0.0),
        (0.0, 0.0, 0.0),
        (0.5, 0.0, 0.0),
        (0.0, 0.5, 0.0),
        (0.0, 0.0, -0.5),
        (0.0, 0.0, -1.0),
    ]
    .map(|(x, y, z)| Vector3::new(x, y, z));
    assert_eq!(g.points(&set), expected);
    assert!(close(g.volume(&vec![false; g.cells()]), 0.0));
    // The whole grid: 75 cells of 0.125.
    assert!(close(g.volume(&vec![true; g.cells()]), 9.375));
}

/// Grid of step `s`, n = 6, 10 layers, and a solid cylinder of cells: centres within
/// `3 s` of the axis in layers 2 to 7 (`z` from `−2 s` to `−7 s`).
fn solid_cylinder(s: f64) -> (Grid, Vec<bool>) {
    let g = Grid {
        step: s,
        n: 6,
        layers: 10,
    };
    let mut set = vec![false; g.cells()];
    for k in 2..=7 {
        for j in 0..g.side() {
            for i in 0..g.side() {
                let (x, y) = (i.abs_diff(6), j.abs_diff(6));
                if x * x + y * y <= 9 {
                    set[g.index(i, j, k)] = true;
                }
            }
        }
    }
    (g, set)
}

/// `set` with the cell at offset `(x, y)` from the axis (in steps) in layer `k` removed.
fn without(g: &Grid, set: &[bool], x: usize, k: usize) -> Vec<bool> {
    let mut holed = set.to_vec();
    holed[g.index(g.n + x, g.n, k)] = false;
    holed
}

#[test]
fn the_largest_cylinder_of_a_solid_cylinder_of_cells_is_that_cylinder() {
    let (g, set) = solid_cylinder(1.0);
    // Layers 2–7: every centre within 3 of the axis is in the set, the nearest one outside is
    // (1, 3) at √10; so ρ = 3, from z = −7 to −2: π · 9 · 5 = 45π. Other layers: the axis cell
    // is out.
    for k in 0..10 {
        let expected = (2..=7).contains(&k).then_some(3.0);
        assert_eq!(g.layer_radius(&[&set], k), expected, "layer {k}");
    }
    let c = g.regular_cylinder(&[&set]).unwrap();
    assert_eq!((c.radius, c.z_lo, c.z_hi), (3.0, -7.0, -2.0));
    assert!(close(c.volume(), 45.0 * PI), "{}", c.volume());
    assert!(close(c.middle(), -4.5));
    // A set with every cell in it does not change the intersection.
    let all = vec![true; g.cells()];
    assert_eq!(g.regular_cylinder(&[&set, &all]), Some(c));
}

#[test]
fn a_hole_in_one_set_shortens_or_thins_the_cylinder_of_both() {
    let (g, set) = solid_cylinder(1.0);
    let all = vec![true; g.cells()];
    // A hole at radius 2 in layer 4 (in the second set only): layer 4's radius drops to √2
    // (centres nearer than 2: 0, 1, √2). Runs: layers 2–7 at √2, π · 2 · 5 = 10π; layers 2–3
    // at 3, π · 9 · 1 = 9π; layers 5–7 at 3, π · 9 · 2 = 18π, the largest: shortened.
    let holed = without(&g, &all, 2, 4);
    assert!(close(
        g.layer_radius(&[&set, &holed], 4).unwrap(),
        2f64.sqrt()
    ));
    let c = g.regular_cylinder(&[&set, &holed]).unwrap();
    assert_eq!((c.radius, c.z_lo, c.z_hi), (3.0, -7.0, -5.0));
    assert!(close(c.volume(), 18.0 * PI));
    // A hole at radius 3 in layer 4: layer 4's radius drops to √8 (the centre (2, 2)). Layers
    // 2–7 at √8: π · 8 · 5 = 40π beats 18π and 9π: the whole height, thinned.
    let holed = without(&g, &all, 3, 4);
    let c = g.regular_cylinder(&[&holed, &set]).unwrap();
    assert!(close(c.radius, 8f64.sqrt()));
    assert_eq!((c.z_lo, c.z_hi), (-7.0, -2.0));
    assert!(close(c.volume(), 40.0 * PI));
    // The axis cell of layer 4 out: two runs, layers 2–3 (9π) and 5–7 (18π).
    let holed = without(&g, &set, 0, 4);
    assert_eq!(g.layer_radius(&[&holed], 4), None);
    let c = g.regular_cylinder(&[&holed]).unwrap();
    assert_eq!((c.radius, c.z_lo, c.z_hi), (3.0, -7.0, -5.0));
}

#[test]
fn equal_cylinders_go_to_the_highest_and_one_layer_has_no_volume() {
    let (g, set) = solid_cylinder(1.0);
    // Axis cells of layers 4 and 5 out: layers 2–3 and 6–7, both π · 9 · 1: the higher wins.
    let split = without(&g, &without(&g, &set, 0, 4), 0, 5);
    let c = g.regular_cylinder(&[&split]).unwrap();
    assert_eq!((c.radius, c.z_lo, c.z_hi), (3.0, -3.0, -2.0));
    // Only layer 3 left: a disc of radius 3 but no height, so no cylinder.
    let mut one = vec![false; g.cells()];
    for (index, in_set) in set.iter().enumerate() {
        one[index] = *in_set && g.cell(index).2 == 3;
    }
    assert_eq!(g.layer_radius(&[&one], 3), Some(3.0));
    assert_eq!(g.regular_cylinder(&[&one]), None);
    assert_eq!(g.regular_cylinder(&[&vec![false; g.cells()]]), None);
}

#[test]
fn ten_times_the_step_is_ten_times_the_lengths_and_a_thousand_times_the_volumes() {
    // The same cells at step 1 and step 10: radius 3 → 30, z from −7, −5 to −70, −50, volume
    // 18π → 18 000π; the set's cells 1³ → 10³ each.
    let (g1, set) = solid_cylinder(1.0);
    let (g10, _) = solid_cylinder(10.0);
    let holed = without(&g1, &set, 2, 4);
    let (c1, c10) = (
        g1.regular_cylinder(&[&holed]).unwrap(),
        g10.regular_cylinder(&[&holed]).unwrap(),
    );
    assert_eq!(
        c10,
        Cylinder {
            radius: 30.0,
            z_lo: -70.0,
            z_hi: -50.0
        }
    );
    assert!(close(c10.radius, 10.0 * c1.radius));
    assert!(close(c10.z_lo, 10.0 * c1.z_lo) && close(c10.z_hi, 10.0 * c1.z_hi));
    assert!(close(c10.volume(), 1000.0 * c1.volume()));
    assert!(close(c10.volume(), 18_000.0 * PI));
    // 6 layers of the 29 centres within 3 of the axis (1 + 4 + 4 + 4 + 8 + 4 + 4: offsets with
    // x² + y² = 0, 1, 2, 4, 5, 8, 9), less the hole: 173 cells.
    assert!(close(g1.volume(&holed), 173.0));
    assert!(close(g10.volume(&holed), 173_000.0));
    for (p1, p10) in g1.points(&holed).iter().zip(&g10.points(&holed)) {
        assert!((p10 - 10.0 * p1).norm() < 1e-12);
    }
}

#[test]
fn the_parallel_scan_is_the_sequential_loop_on_any_number_of_threads() {
    // Cells within 1.5 s of (0, 0, −s) on n = 2, 4 layers, step 2: offsets (in steps) with
    // x² + y² + z² ≤ 2.25, i.e. ≤ 2: 1 + 6 + 12 = 19 cells, all inside the grid (k = 0 … 2).
    let g = Grid {
        step: 2.0,
        n: 2,
        layers: 4,
    };
    let centre = Vector3::new(0.0, 0.0, -2.0);
    let inside = |p: &Vector3<f64>| (p - centre).norm() <= 3.0;
    let many = g.select(&quiet, inside);
    assert_eq!(many.iter().filter(|b| **b).count(), 19);
    assert!(close(g.volume(&many), 19.0 * 8.0));
    let sequential: Vec<bool> = (0..g.cells())
        .map(|index| {
            let (i, j, k) = g.cell(index);
            inside(&g.centre(i, j, k))
        })
        .collect();
    assert_eq!(many, sequential);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    assert_eq!(pool.install(|| g.select(&quiet, inside)), many);
    // Rows in the order of the flat index: (j, k) at k · 5 + j, 5 · 4 = 20 of them.
    let rows = g.map_rows(&quiet, |j, k| (j, k));
    let by_hand: Vec<(usize, usize)> = (0..4).flat_map(|k| (0..5).map(move |j| (j, k))).collect();
    assert_eq!(rows, by_hand);
    assert_eq!(g.rows(), 20);
}

#[test]
fn the_scans_report_each_row_once() {
    let g = Grid {
        step: 1.0,
        n: 3,
        layers: 5,
    };
    let calls = AtomicUsize::new(0);
    let last = Mutex::new((0, 0));
    let progress = |done: usize, total: usize| {
        calls.fetch_add(1, Ordering::Relaxed);
        let mut l = last.lock().unwrap();
        *l = (l.0.max(done), total);
    };
    let set = g.select(&progress, |p| p.z > -1.5);
    // 7 · 5 = 35 rows, each reported once, the last report 35 of 35; layers 0 and 1 in the set.
    assert_eq!(calls.load(Ordering::Relaxed), 35);
    assert_eq!(*last.lock().unwrap(), (35, 35));
    assert_eq!(set.iter().filter(|b| **b).count(), 2 * 49);
    let squares = map_in_parallel(100, &quiet, |r| r * r);
    assert_eq!(squares, (0..100).map(|r| r * r).collect::<Vec<_>>());
}
