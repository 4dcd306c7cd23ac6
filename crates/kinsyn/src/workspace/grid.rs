//! The search grid of a workspace: cells of side `s` centred at `(i s, j s, −k s)`, on the `z`
//! axis and below `z = 0`, with a limit on their number and the checks of a step.

use nalgebra::Vector3;

/// The most grid cells a search takes (20 million: 20 MB for each set of cells).
pub const MAX_CELLS: usize = 20_000_000;

/// Why a grid, a workspace search or a map on a grid cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WorkspaceError {
    /// The grid step is not a positive finite length.
    #[error("grid step {0}: give a positive length")]
    Step(f64),
    /// The grid would have too many cells.
    #[error("grid step {step} makes {cells} cells, more than {max}: give a larger step")]
    TooManyCells {
        /// The step asked for.
        step: f64,
        /// The cells it makes (`usize::MAX` when too many to count).
        cells: usize,
        /// [`MAX_CELLS`].
        max: usize,
    },
    /// A value (orientation, height, size, geometry) is not finite or out of its range.
    #[error("{0}")]
    Value(String),
}

/// A grid of end-effector positions: cell centres `(i s, j s, −k s)` for the step `s`,
/// `|i|, |j| ≤ n`, `k = 0 … layers − 1`. Each cell is the cube of side `s` about its centre, so
/// the grid fills the box `|x|, |y| ≤ (n + ½) s`, `−(layers − ½) s ≤ z ≤ s/2`, one layer of
/// cells above another, the top layer centred on `z = 0`.
///
/// Cells are named by `(i, j, k)` with `i, j` counted from 0 at `x, y = −n s` (so the centre is
/// `((i − n) s, (j − n) s, −k s)`), or by one flat index ([`Grid::index`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// The step `s`: the cells' side, the distance between neighbouring centres.
    pub step: f64,
    /// `n`: cells on each side of the axis in `x` and `y`.
    pub n: usize,
    /// The number of layers in `z`, from `z = 0` down.
    pub layers: usize,
}

impl Grid {
    /// The grid of step `step` that covers `|x|, |y| ≤ half_width` with a cell to spare on each
    /// side (`n = ⌊half_width/s⌋ + 1`, so every such `x` and `y` rounds to a cell of the grid) and
    /// has the layers `z = 0, −s, −2s, …` down to `−depth` (`⌊depth/s⌋ + 1` of them). A negative
    /// half-width or depth counts as 0.
    ///
    /// # Errors
    /// [`WorkspaceError::Step`] for a step that is not a positive length,
    /// [`WorkspaceError::TooManyCells`] beyond [`MAX_CELLS`] cells.
    pub fn covering(step: f64, half_width: f64, depth: f64) -> Result<Self, WorkspaceError> {
        let step = check_step(step)?;
        let n = count(half_width, step)? + 1;
        let layers = count(depth, step)? + 1;
        let grid = Self { step, n, layers };
        let cells = (grid.side() as f64).powi(2) * layers as f64;
        if cells > MAX_CELLS as f64 {
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a count, saturating"
            )]
            return Err(WorkspaceError::TooManyCells {
                step,
                cells: cells as usize,
                max: MAX_CELLS,
            });
        }
        Ok(grid)
    }

    /// Cells along `x` (and `y`): `2n + 1`.
    #[must_use]
    pub fn side(&self) -> usize {
        2 * self.n + 1
    }

    /// Every cell: `(2n + 1)² layers`.
    #[must_use]
    pub fn cells(&self) -> usize {
        self.side() * self.side() * self.layers
    }

    /// The centre of cell `(i, j, k)`: `((i − n) s, (j − n) s, −k s)`.
    #[must_use]
    pub fn centre(&self, i: usize, j: usize, k: usize) -> Vector3<f64> {
        let n = self.n as f64;
        Vector3::new(
            (i as f64 - n) * self.step,
            (j as f64 - n) * self.step,
            -(k as f64) * self.step,
        )
    }

    /// The flat index of cell `(i, j, k)`: layers, then rows `j`, then `i`
    /// (`(k (2n + 1) + j)(2n + 1) + i`).
    #[must_use]
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        (k * self.side() + j) * self.side() + i
    }

    /// The cell `(i, j, k)` of flat index `index` (the inverse of [`Grid::index`]).
    #[must_use]
    pub fn cell(&self, index: usize) -> (usize, usize, usize) {
        let side = self.side();
        (index % side, (index / side) % side, index / (side * side))
    }

    /// The cell whose centre is nearest `p` (the cell that contains it), if inside the grid.
    #[must_use]
    pub fn nearest(&self, p: &Vector3<f64>) -> Option<(usize, usize, usize)> {
        let n = self.n as f64;
        let i = (p.x / self.step).round() + n;
        let j = (p.y / self.step).round() + n;
        let k = (-p.z / self.step).round();
        let side = self.side() as f64;
        let inside = (0.0..side).contains(&i)
            && (0.0..side).contains(&j)
            && (0.0..self.layers as f64).contains(&k);
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "non-negative whole numbers below the grid's size"
        )]
        inside.then_some((i as usize, j as usize, k as usize))
    }
}

/// `value` if it is finite.
///
/// # Errors
/// [`WorkspaceError::Value`] naming it (`"{name} {value}: not finite"`) otherwise.
pub fn finite(name: &str, value: f64) -> Result<f64, WorkspaceError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(WorkspaceError::Value(format!("{name} {value}: not finite")))
    }
}

/// `step` if it is a positive length (finite and above 0).
///
/// # Errors
/// [`WorkspaceError::Step`] otherwise.
pub fn check_step(step: f64) -> Result<f64, WorkspaceError> {
    if step.is_finite() && step > 0.0 {
        Ok(step)
    } else {
        Err(WorkspaceError::Step(step))
    }
}

/// `⌊x/s⌋`, the whole steps in the length `x`, as a count (0 for a negative `x` or not a number).
///
/// # Errors
/// [`WorkspaceError::TooManyCells`] (with `usize::MAX` cells) for more than [`MAX_CELLS`]
/// steps.
pub fn count(x: f64, step: f64) -> Result<usize, WorkspaceError> {
    let n = (x / step).floor();
    if n > MAX_CELLS as f64 {
        return Err(WorkspaceError::TooManyCells {
            step,
            cells: usize::MAX,
            max: MAX_CELLS,
        });
    }
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a non-negative whole number at most MAX_CELLS"
    )]
    Ok(n.max(0.0) as usize)
}
