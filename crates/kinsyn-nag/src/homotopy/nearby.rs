//! Finding the points near a given one among many: the endpoints that coincide (a path jump),
//! the endpoints that are one solution, the witness points a loop returns to. Comparing every
//! pair costs the square of the number of points — 65 536 endpoints are 4·10⁹ comparisons,
//! minutes — so the points are kept sorted along one generic real-linear form `ℓ`, and only
//! those whose `ℓ` lies within the tolerance's reach of the query's are compared: the same
//! answers as the full scan, at a cost of the points that share the query's neighbourhood
//! along `ℓ` (a few, for points in general position).

use super::C64;
use std::collections::BTreeSet;

/// Points by their value of `ℓ(z) = Σ Re(c_i z_i)`, `c_i` on the unit circle at the golden
/// angle's multiples (generic, and the same every run), with an id each.
// Public for the tests in tests/suite/; not part of the API.
#[derive(Debug, Default)]
pub struct NearPoints {
    sorted: BTreeSet<(i64, usize)>,
}

/// `ℓ(z)` (module documentation).
fn form(z: &[C64]) -> f64 {
    const GOLDEN: f64 = 0.618_033_988_749_894_9;
    z.iter()
        .enumerate()
        .map(|(i, v)| {
            let c = C64::from_polar(
                1.0,
                std::f64::consts::TAU * ((i as f64 + 1.0) * GOLDEN).fract(),
            );
            (c * v).re
        })
        .sum()
}

/// An integer whose order is that of the finite doubles (the bits of a negative double
/// reversed): a key of the sorted set.
// Public for the tests in tests/suite/; not part of the API.
#[must_use]
pub fn ordered(x: f64) -> i64 {
    let bits = x.to_bits().cast_signed();
    bits ^ ((bits >> 63).cast_unsigned() >> 1).cast_signed()
}

impl NearPoints {
    /// Adds the point `z` under `id`.
    pub fn insert(&mut self, id: usize, z: &[C64]) {
        self.sorted.insert((ordered(form(z)), id));
    }

    /// The ids of the points that may lie within relative distance `tolerance` of `z`, either
    /// way (`|y − z| ≤ tolerance · (1 + |z|)` or `≤ tolerance · (1 + |y|)`), in the order of
    /// `ℓ`; a superset, to be checked with the distance itself. For `tolerance < 1`; every
    /// point when `z` is not finite.
    #[must_use]
    pub fn candidates(&self, z: &[C64], tolerance: f64) -> Vec<usize> {
        let size = z.iter().map(C64::norm_sqr).sum::<f64>().sqrt();
        // |ℓ(y) − ℓ(z)| ≤ √n |y − z|, and |y| ≤ (|z| + tolerance) / (1 − tolerance) when y is
        // within the tolerance relative to its own size; a margin covers the rounding of ℓ.
        let lipschitz = (z.len() as f64).sqrt();
        let reach = lipschitz
            * (tolerance * (1.0 + (size + tolerance) / (1.0 - tolerance))
                + 8.0 * z.len() as f64 * f64::EPSILON * (1.0 + size));
        let at = form(z);
        let (low, high) = (at - reach, at + reach);
        if low.is_finite() && high.is_finite() {
            self.sorted
                .range((ordered(low), 0)..=(ordered(high), usize::MAX))
                .map(|(_, id)| *id)
                .collect()
        } else {
            self.sorted.iter().map(|(_, id)| *id).collect()
        }
    }
}

/// Points kept with their index ([`NearPoints`]): a list in which a point is looked up near
/// others at the cost of its neighbours, not of the list.
#[derive(Debug, Default)]
pub(crate) struct PointList {
    points: Vec<Vec<C64>>,
    index: NearPoints,
}

impl PointList {
    /// Whether a kept point `y` lies within relative distance `tolerance` of `x`, relative to
    /// its own size (`|y − x| ≤ tolerance · (1 + |y|)`, [`super::relative_distance`]`(y, x)`).
    pub(crate) fn contains(&self, x: &[C64], tolerance: f64) -> bool {
        self.index
            .candidates(x, tolerance)
            .into_iter()
            .any(|k| super::relative_distance(&self.points[k], x) <= tolerance)
    }

    /// Adds `x` unless [`Self::contains`] finds it; whether it was added.
    pub(crate) fn insert_new(&mut self, x: Vec<C64>, tolerance: f64) -> bool {
        if self.contains(&x, tolerance) {
            return false;
        }
        self.push(x);
        true
    }

    /// Adds `x`.
    pub(crate) fn push(&mut self, x: Vec<C64>) {
        self.index.insert(self.points.len(), &x);
        self.points.push(x);
    }

    /// The points, in the order added.
    pub(crate) fn into_points(self) -> Vec<Vec<C64>> {
        self.points
    }
}
