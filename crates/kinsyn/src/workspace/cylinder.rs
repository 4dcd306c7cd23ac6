//! The largest regular cylinder in several workspaces: a vertical cylinder on the `z` axis, the
//! shape of a regular workspace, found from the cells of a grid.
//!
//! In each layer `k` the disc's radius is the largest cell-centre distance from the axis such
//! that every cell centre of the layer at most that far from the axis is in every set
//! ([`Grid::layer_radius`]). A run of consecutive layers from `top` to `bottom` takes the
//! smallest of its radii and spans `z` from `−bottom s` to `−top s`; the run of largest volume
//! `π ρ² (z_hi − z_lo)` wins, the highest first on ties ([`Grid::regular_cylinder`]).
//!
//! Radii and heights are those of cell centres, not of the cells' faces, so the cylinder is
//! conservative by up to a step: the cells it keeps reach beyond it, and a single layer has no
//! height, hence no volume.

use super::Grid;
use std::f64::consts::PI;

/// A vertical cylinder centred on the `z` axis: radius `ρ`, `z` from `z_lo` to `z_hi`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    /// `ρ`.
    pub radius: f64,
    /// The bottom `z_lo`.
    pub z_lo: f64,
    /// The top `z_hi`.
    pub z_hi: f64,
}

impl Cylinder {
    /// `π ρ² (z_hi − z_lo)`.
    #[must_use]
    pub fn volume(&self) -> f64 {
        PI * self.radius * self.radius * (self.z_hi - self.z_lo)
    }

    /// The middle height `(z_lo + z_hi)/2`.
    #[must_use]
    pub fn middle(&self) -> f64 {
        0.5 * (self.z_lo + self.z_hi)
    }
}

impl Grid {
    /// The radius of the largest disc on the axis, in layer `k`, whose cell centres are all in
    /// every one of `sets` (the largest such cell-centre distance from the axis: every cell of
    /// the layer nearer the axis is in them all), or `None` when the axis cell is not.
    #[must_use]
    pub fn layer_radius(&self, sets: &[&[bool]], k: usize) -> Option<f64> {
        let side = self.side();
        let mut bad = f64::INFINITY;
        let mut radii = Vec::new();
        for j in 0..side {
            for i in 0..side {
                let c = self.centre(i, j, k);
                let r = c.x.hypot(c.y);
                if Self::in_all(sets, self.index(i, j, k)) {
                    radii.push(r);
                } else {
                    bad = bad.min(r);
                }
            }
        }
        radii
            .into_iter()
            .filter(|r| *r < bad)
            .fold(None, |m: Option<f64>, r| Some(m.map_or(r, |m| m.max(r))))
    }

    /// The largest vertical cylinder on the `z` axis whose cells are all in every one of `sets`
    /// (module documentation: radii and heights of cell centres, conservative by up to a step),
    /// or `None` when no layer has its axis cell in them all or the largest cylinder has no
    /// volume.
    #[must_use]
    pub fn regular_cylinder(&self, sets: &[&[bool]]) -> Option<Cylinder> {
        let radii: Vec<Option<f64>> = (0..self.layers)
            .map(|k| self.layer_radius(sets, k))
            .collect();
        let s = self.step;
        let mut best: Option<Cylinder> = None;
        for top in 0..radii.len() {
            let mut radius = f64::INFINITY;
            for (bottom, r) in radii.iter().enumerate().skip(top) {
                let Some(r) = r else { break };
                radius = radius.min(*r);
                let c = Cylinder {
                    radius,
                    z_hi: -(top as f64) * s,
                    z_lo: -(bottom as f64) * s,
                };
                if c.volume() > best.map_or(0.0, |b| b.volume()) {
                    best = Some(c);
                }
            }
        }
        best
    }
}
