//! Sets of cells of a grid: a workspace's positions and its volume.

use super::Grid;
use nalgebra::Vector3;

impl Grid {
    /// The centres of the cells in `set` (a `[bool]` indexed by [`Grid::index`]), in index
    /// order: the positions of a workspace, one per cell.
    #[must_use]
    pub fn points(&self, set: &[bool]) -> Vec<Vector3<f64>> {
        set.iter()
            .enumerate()
            .filter(|(_, in_set)| **in_set)
            .map(|(index, _)| {
                let (i, j, k) = self.cell(index);
                self.centre(i, j, k)
            })
            .collect()
    }

    /// The volume of the cells in `set`: their count times `s³`, each cell the cube of side `s`
    /// about its centre (a workspace's volume to within the cells its boundary cuts).
    #[must_use]
    pub fn volume(&self, set: &[bool]) -> f64 {
        set.iter().filter(|b| **b).count() as f64 * self.step.powi(3)
    }

    /// Whether cell `index` is in every one of `sets`.
    pub(super) fn in_all(sets: &[&[bool]], index: usize) -> bool {
        sets.iter().all(|set| set[index])
    }
}
