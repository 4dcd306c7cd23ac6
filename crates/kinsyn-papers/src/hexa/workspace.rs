//! The reachable workspaces of both end-effectors, their regular common workspace and the maps
//! of the transmission indices over it (paper 001 §4, Figs. 3–4), by numerical search on a grid.
//!
//! # The reachable workspaces (Fig. 3b)
//! At constant orientations `(φ1, φ2)`, a position `P1` of end-effector 1 is **reachable** when
//! limbs 1, 2, 3 and 6 reach their platform joints (eq. 5 has real roots) and the four-bar of
//! eqs. 7–8 can put `P2` at some point of its coupler curve where limbs 4 and 5 reach theirs.
//! The reachable set of `P2` is the union, over the reachable `P1`, of those coupler-curve
//! points, binned on the same grid. The coupler curve is sampled at evenly spaced crank angles
//! `α` **and** `β` (eq. 7a is symmetric under `(α, β) → (π − β, π − α)`, so `α` of a given `β` is
//! `π − ` a rocker angle of `π − β`): the four-bar of paper 001 is a non-Grashof triple rocker,
//! and near a dead point of one crank the other moves fast, so sampling one crank alone leaves
//! gaps in the curve there.
//!
//! # The grid
//! A [`kinsyn::workspace::Grid`]: cell centres at `(i s, j s, −k s)` for the step `s`,
//! `k = 0 … ⌊(b + l)/s⌋` (every platform joint is at the height `z` and must be within `b + l`
//! of its base joint, at height 0; the robot hangs below its base, so `z ≤ 0`), and
//! `|i s|, |j s| ≤ H` with a cell to spare ([`kinsyn::workspace::Grid::covering`]):
//! every platform joint is within `r1 + r2` of `P1`, each base joint within `a` of its pair's
//! centre `m_μ = R_z(μ)(0, R, 0)`, so a reachable `P1` is within `D = b + l + r1 + r2 + a` of the
//! three `m_μ` (limbs 1, 3 and 6 have the three directions `μ`); one of them is at least 120°
//! from `P1`'s direction, so `|P1_xy|² + R² + R |P1_xy| ≤ D²`, i.e.
//! `|P1_xy| ≤ (√(4D² − 3R²) − R)/2`. `P2` is within `r1 + r2 + r3 + r4` of `P1`; `H` is the sum.
//!
//! # The regular common workspace
//! The vertical cylinder centred on the `z` axis, radius `ρ`, `z ∈ [z_lo, z_hi]`, of largest
//! volume `π ρ² (z_hi − z_lo)` whose grid cells (centres within `ρ` of the axis, layers from
//! `z_lo` to `z_hi`) are all in both reachable sets
//! ([`kinsyn::workspace::Grid::regular_cylinder`]). In each layer `ρ` is the largest
//! cell-centre radius such that every cell centre at most that far from the axis is in both
//! sets; a run of consecutive layers takes the smallest; the run of largest volume wins (the
//! highest first on ties). Heights and radii are those of cell centres, so the cylinder is
//! conservative by up to a step.
//!
//! # Index maps (Fig. 4)
//! Over a square `x–y` grid of `P1` positions at a height `z`, end-effector 2 at the four-bar's
//! **nominal** (symmetric) assembly relative to `P1` ([`Hexa::nominal_four_bar`]): each cell's
//! [`Indices`], or `None` where that pose is not assemblable.
//!
//! The searches run in parallel (rayon, [`kinsyn::workspace::map_in_parallel`]); their results
//! do not depend on the number of threads. The grid, its cell-count limit and errors, the sets'
//! volumes and the cylinder are the engine's `kinsyn::workspace`, re-exported here.

use super::{Hexa, Indices, Pose};
pub use kinsyn::workspace::{Cylinder, Grid, MAX_CELLS, Progress, WorkspaceError};
use kinsyn::workspace::{check_step, count, finite, map_in_parallel};
use nalgebra::{Vector2, Vector3};
use std::f64::consts::PI;

/// The settings of [`Hexa::workspace`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorkspaceSettings {
    /// The grid step (mm).
    pub step: f64,
    /// `φ1` (rad).
    pub phi1: f64,
    /// `φ2` (rad).
    pub phi2: f64,
    /// Crank angles sampled over a turn, for each crank, on the coupler curve.
    pub curve_samples: usize,
}

impl Default for WorkspaceSettings {
    /// A 20 mm grid, `φ1 = φ2 = 0`, 180 samples (2°) of each crank.
    fn default() -> Self {
        Self {
            step: 20.0,
            phi1: 0.0,
            phi2: 0.0,
            curve_samples: 180,
        }
    }
}

/// The reachable workspaces of both end-effectors on a grid (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct Workspace {
    /// The grid.
    pub grid: Grid,
    /// The settings searched with.
    pub settings: WorkspaceSettings,
    /// Whether each cell (flat index, [`Grid::index`]) is a reachable `P1`.
    pub end_effector1: Vec<bool>,
    /// Whether each cell is a reachable `P2`.
    pub end_effector2: Vec<bool>,
}

impl Workspace {
    /// The reachable cells of end-effector 1 (`which = 0`) or 2 (`which = 1`).
    fn set(&self, which: usize) -> &[bool] {
        if which == 0 {
            &self.end_effector1
        } else {
            &self.end_effector2
        }
    }

    /// The centres of the reachable cells of end-effector 1 (`which = 0`) or 2 (`which = 1`).
    #[must_use]
    pub fn points(&self, which: usize) -> Vec<Vector3<f64>> {
        self.grid.points(self.set(which))
    }

    /// The volume of the reachable cells of end-effector 1 (`which = 0`) or 2 (mm³: cells × s³).
    #[must_use]
    pub fn volume(&self, which: usize) -> f64 {
        self.grid.volume(self.set(which))
    }

    /// The radius of the largest disc on the axis, in layer `k`, whose cell centres are all in
    /// both sets (the largest such cell-centre radius), or `None` when the axis cell is not.
    #[must_use]
    pub fn layer_radius(&self, k: usize) -> Option<f64> {
        self.grid
            .layer_radius(&[&self.end_effector1, &self.end_effector2], k)
    }

    /// The regular common workspace (module documentation), or `None` when no layer has its
    /// axis cell in both sets or the largest cylinder has no volume.
    #[must_use]
    pub fn regular_cylinder(&self) -> Option<Cylinder> {
        self.grid
            .regular_cylinder(&[&self.end_effector1, &self.end_effector2])
    }
}

/// The map of the indices over a square of `P1` positions at one height (module
/// documentation): cell `(i, j)` at `(xs[i], ys[j])`, `cells[j * xs.len() + i]`.
#[derive(Debug, Clone, PartialEq)]
pub struct IndexMap {
    /// The height `z` (mm).
    pub z: f64,
    /// `φ1`, `φ2` (rad).
    pub phi: [f64; 2],
    /// The cell centres' `x` (mm).
    pub xs: Vec<f64>,
    /// The cell centres' `y` (mm).
    pub ys: Vec<f64>,
    /// Each cell's indices, `None` where the pose is not assemblable.
    pub cells: Vec<Option<Indices>>,
}

impl IndexMap {
    /// The cells as `(x, y, indices)`.
    pub fn iter(&self) -> impl Iterator<Item = (f64, f64, Option<&Indices>)> + '_ {
        self.cells.iter().enumerate().map(|(index, c)| {
            (
                self.xs[index % self.xs.len()],
                self.ys[index / self.xs.len()],
                c.as_ref(),
            )
        })
    }
}

/// The settings of [`Hexa::index_map`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IndexMapSettings {
    /// The height `z` of `P1` (mm).
    pub z: f64,
    /// The square's half-width (mm): cell centres at multiples of `step` within it.
    pub half_width: f64,
    /// The grid step (mm).
    pub step: f64,
    /// `φ1` (rad).
    pub phi1: f64,
    /// `φ2` (rad).
    pub phi2: f64,
}

/// Eq. 5's reach test with everything that does not depend on the platform's position worked
/// out once: the base joints `a_i`, `(sin μ_i, cos μ_i)`, and the platform joints' offsets from
/// `P1` at `φ1` and from `P2` at `φ2`. Limb `i` reaches `c` where `I² + J² ≥ K²`.
struct Reach {
    hexa: Hexa,
    base: [Vector3<f64>; 6],
    mu: [(f64, f64); 6],
    offsets: [Vector3<f64>; 6],
}

impl Reach {
    fn new(h: &Hexa, phi1: f64, phi2: f64) -> Self {
        let origin = Vector3::zeros();
        let offsets = h.platform_joints(&Pose::new(&origin, phi1, &origin, phi2));
        Self {
            base: std::array::from_fn(|i| h.base_joint(i)),
            mu: std::array::from_fn(|i| super::mu(i).sin_cos()),
            offsets,
            hexa: *h,
        }
    }

    /// Whether limb `i` reaches the platform joint of the platform point `p` (eq. 5).
    fn limb(&self, i: usize, p: &Vector3<f64>) -> bool {
        let (ii, jj, kk) = self
            .hexa
            .coefficients_of(&(p + self.offsets[i] - self.base[i]), self.mu[i]);
        ii * ii + jj * jj >= kk * kk
    }

    fn end_effector1(&self, p1: &Vector3<f64>) -> bool {
        [0, 1, 2, 5].into_iter().all(|i| self.limb(i, p1))
    }

    fn end_effector2(&self, p2: &Vector3<f64>) -> bool {
        self.limb(3, p2) && self.limb(4, p2)
    }
}

impl Hexa {
    /// The half-width `H` of the search grid in `x` and `y` (module documentation): no
    /// reachable `P1` or `P2` is farther from the `z` axis.
    #[must_use]
    pub fn workspace_half_width(&self) -> f64 {
        let [r1, r2, r3, r4, _] = self.r;
        let d = self.b + self.l + r1 + r2 + self.a;
        let big_r = self.big_r;
        0.5 * ((4.0 * d * d - 3.0 * big_r * big_r).max(0.0).sqrt() - big_r) + r1 + r2 + r3 + r4
    }

    /// The grid of [`Hexa::workspace`] at the step `step`.
    ///
    /// # Errors
    /// [`WorkspaceError::Step`] for a step that is not a positive length,
    /// [`WorkspaceError::TooManyCells`] beyond [`MAX_CELLS`].
    pub fn workspace_grid(&self, step: f64) -> Result<Grid, WorkspaceError> {
        Grid::covering(step, self.workspace_half_width(), self.b + self.l)
    }

    /// Whether limbs 4 and 5 reach end-effector 2 at `(p2, φ2)` (eq. 5 has real roots).
    #[must_use]
    pub fn reaches_end_effector2(&self, p2: &Vector3<f64>, phi2: f64) -> bool {
        Reach::new(self, 0.0, phi2).end_effector2(p2)
    }

    /// Whether limbs 1, 2, 3 and 6 reach end-effector 1 at `(p1, φ1)`.
    #[must_use]
    pub fn reaches_end_effector1(&self, p1: &Vector3<f64>, phi1: f64) -> bool {
        Reach::new(self, phi1, 0.0).end_effector1(p1)
    }

    /// The coupler curve's points `P2` with end-effector 1 at `(p1, φ1)`: `samples` evenly
    /// spaced angles of each crank, both assemblies of each (module documentation).
    #[must_use]
    pub fn coupler_points(
        &self,
        p1: &Vector3<f64>,
        phi1: f64,
        samples: usize,
    ) -> Vec<Vector3<f64>> {
        let fb = self.four_bar(p1, phi1);
        let mut points = Vec::with_capacity(4 * samples);
        for k in 0..samples {
            let t = std::f64::consts::TAU * k as f64 / samples as f64;
            if let Some(betas) = self.rocker_angles(&fb, t) {
                points.extend(betas.map(|beta| self.four_bar_pose(&fb, t, beta).p2));
            }
            // β = t: the α paired with it are π − the rocker angles of π − t (eq. 7a's symmetry).
            if let Some(others) = self.rocker_angles(&fb, PI - t) {
                points.extend(others.map(|o| self.four_bar_pose(&fb, PI - o, t).p2));
            }
        }
        points
    }

    /// Fig. 3(a): the positions of `P2` relative to `P1` that the four-bar allows with
    /// end-effector 1 at `(p1, φ1)` ([`Hexa::coupler_points`]), each with whether limbs 4 and 5
    /// reach end-effector 2 there at `φ2`.
    #[must_use]
    pub fn end_effector2_positions(
        &self,
        p1: &Vector3<f64>,
        phi1: f64,
        phi2: f64,
        samples: usize,
    ) -> Vec<(Vector2<f64>, bool)> {
        self.coupler_points(p1, phi1, samples)
            .into_iter()
            .map(|p2| ((p2 - p1).xy(), self.reaches_end_effector2(&p2, phi2)))
            .collect()
    }

    /// The reachable workspaces of both end-effectors at constant orientations (module
    /// documentation); `progress` hears `(layers rows done, rows)`.
    ///
    /// # Errors
    /// The grid's ([`Hexa::workspace_grid`]), and [`WorkspaceError::Value`] for an orientation
    /// that is not finite or no curve samples.
    pub fn workspace(
        &self,
        settings: &WorkspaceSettings,
        progress: Progress<'_>,
    ) -> Result<Workspace, WorkspaceError> {
        finite("φ1", settings.phi1)?;
        finite("φ2", settings.phi2)?;
        if settings.curve_samples == 0 {
            return Err(WorkspaceError::Value(
                "curve samples: give at least one".into(),
            ));
        }
        let grid = self.workspace_grid(settings.step)?;
        let side = grid.side();
        // Each row (j, k): its reachable P1 cells and the P2 cells they reach.
        let reach = Reach::new(self, settings.phi1, settings.phi2);
        // The coupler curve relative to P1 depends on φ1 only (the sub-platforms translate).
        let curve = self.coupler_points(&Vector3::zeros(), settings.phi1, settings.curve_samples);
        let found: Vec<(Vec<usize>, Vec<usize>)> = grid.map_rows(progress, |j, k| {
            let mut ones = Vec::new();
            let mut twos = Vec::new();
            for i in 0..side {
                let p1 = grid.centre(i, j, k);
                if !reach.end_effector1(&p1) {
                    continue;
                }
                let before = twos.len();
                for offset in &curve {
                    let p2 = p1 + offset;
                    if reach.end_effector2(&p2)
                        && let Some((a, b, c)) = grid.nearest(&p2)
                    {
                        twos.push(grid.index(a, b, c));
                    }
                }
                if twos.len() > before {
                    ones.push(grid.index(i, j, k));
                    // One P1's curve falls in a few cells: keep each once.
                    twos[before..].sort_unstable();
                    let mut kept = before;
                    for n in before..twos.len() {
                        if n == before || twos[n] != twos[kept - 1] {
                            twos[kept] = twos[n];
                            kept += 1;
                        }
                    }
                    twos.truncate(kept);
                }
            }
            (ones, twos)
        });
        let mut end_effector1 = vec![false; grid.cells()];
        let mut end_effector2 = vec![false; grid.cells()];
        for (ones, twos) in found {
            for index in ones {
                end_effector1[index] = true;
            }
            for index in twos {
                end_effector2[index] = true;
            }
        }
        Ok(Workspace {
            grid,
            settings: *settings,
            end_effector1,
            end_effector2,
        })
    }

    /// The indices at end-effector 1's pose `(p1, φ1)` with end-effector 2 at the four-bar's
    /// nominal assembly and `φ2`, or `None` where that pose is not assemblable.
    #[must_use]
    pub fn nominal_indices(&self, p1: &Vector3<f64>, phi1: f64, phi2: f64) -> Option<Indices> {
        let p2 = self.nominal_four_bar(p1, phi1)?.p2;
        let conf = self.inverse(&Pose::new(p1, phi1, &p2, phi2))?;
        Some(self.indices(&conf))
    }

    /// The map of the indices over the square `|x|, |y| ≤ half_width` at the height `z`
    /// (module documentation); `progress` hears `(rows done, rows)`.
    ///
    /// # Errors
    /// [`WorkspaceError::Step`], [`WorkspaceError::TooManyCells`] and
    /// [`WorkspaceError::Value`] for values that are not finite or a negative half-width.
    pub fn index_map(
        &self,
        settings: &IndexMapSettings,
        progress: Progress<'_>,
    ) -> Result<IndexMap, WorkspaceError> {
        let step = check_step(settings.step)?;
        let (z, phi1, phi2) = (
            finite("z", settings.z)?,
            finite("φ1", settings.phi1)?,
            finite("φ2", settings.phi2)?,
        );
        let half = finite("half-width", settings.half_width)?;
        if half < 0.0 {
            return Err(WorkspaceError::Value(format!(
                "half-width {half}: give a non-negative length"
            )));
        }
        let n = count(half, step)?;
        let side = 2 * n + 1;
        if (side as f64).powi(2) > MAX_CELLS as f64 {
            return Err(WorkspaceError::TooManyCells {
                step,
                cells: side.saturating_mul(side),
                max: MAX_CELLS,
            });
        }
        let axis: Vec<f64> = (0..side).map(|i| (i as f64 - n as f64) * step).collect();
        let rows: Vec<Vec<Option<Indices>>> = map_in_parallel(side, progress, |j| {
            axis.iter()
                .map(|&x| self.nominal_indices(&Vector3::new(x, axis[j], z), phi1, phi2))
                .collect()
        });
        Ok(IndexMap {
            z,
            phi: [phi1, phi2],
            xs: axis.clone(),
            ys: axis,
            cells: rows.into_iter().flatten().collect(),
        })
    }
}
