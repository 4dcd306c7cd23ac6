//! Searches over a grid in parallel: a function of each row, or a predicate of each cell, on
//! rayon's threads, with progress reported per row and results in row order, so that they do
//! not depend on the number of threads.

use super::Grid;
use nalgebra::Vector3;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A progress report: `(done, total)` units of work, called from any thread.
pub type Progress<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// `row(0) … row(rows − 1)`, evaluated in parallel (rayon); `progress` hears
/// `(rows done, rows)` once after each row. The results are in row order whatever the order
/// of evaluation, so they do not depend on the number of threads.
pub fn map_in_parallel<T: Send>(
    rows: usize,
    progress: Progress<'_>,
    row: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let done = AtomicUsize::new(0);
    (0..rows)
        .into_par_iter()
        .map(|r| {
            let result = row(r);
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, rows);
            result
        })
        .collect()
}

impl Grid {
    /// The rows of cells along `x`, one for each `(j, k)`: `(2n + 1) layers`.
    #[must_use]
    pub fn rows(&self) -> usize {
        self.side() * self.layers
    }

    /// `row(j, k)` for every row of cells along `x` (cells `(0 … 2n, j, k)`), evaluated in
    /// parallel ([`map_in_parallel`]; `progress` hears `(rows done, rows)`), in the order of
    /// [`Grid::index`]: row `(j, k)` at `k (2n + 1) + j`.
    pub fn map_rows<T: Send>(
        &self,
        progress: Progress<'_>,
        row: impl Fn(usize, usize) -> T + Sync,
    ) -> Vec<T> {
        let side = self.side();
        map_in_parallel(self.rows(), progress, |r| row(r % side, r / side))
    }

    /// The set of cells whose centres satisfy `inside` (a `[bool]` indexed by [`Grid::index`]):
    /// a workspace found by testing each cell centre, in parallel, row by row
    /// ([`Grid::map_rows`]; `progress` hears `(rows done, rows)`).
    pub fn select(
        &self,
        progress: Progress<'_>,
        inside: impl Fn(&Vector3<f64>) -> bool + Sync,
    ) -> Vec<bool> {
        let side = self.side();
        self.map_rows(progress, |j, k| {
            (0..side)
                .map(|i| inside(&self.centre(i, j, k)))
                .collect::<Vec<_>>()
        })
        .into_iter()
        .flatten()
        .collect()
    }
}
