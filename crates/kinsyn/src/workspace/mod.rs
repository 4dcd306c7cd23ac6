//! Workspaces on a grid: the positions an end-effector reaches, found cell by cell.
//!
//! A **workspace** here is a set of cells of a [`Grid`] of end-effector positions: a cube of
//! side `s` (the step) around each centre `(i s, j s, −k s)`, the cell in the set when its
//! centre is a position the end-effector reaches (or, for a set filled by binning, when some
//! reached position is nearest that centre). The grid is centred on the `z` axis and runs
//! downwards from `z = 0`, the height of a robot's base: a manipulator hangs below its base.
//! A set is a `[bool]` of [`Grid::cells`] entries, in the order of [`Grid::index`].
//!
//! - [`Grid`] gives the cells' centres, flat indices and the cell nearest a point;
//!   [`Grid::covering`] makes the grid over a box with the cell-count limit [`MAX_CELLS`]
//!   checked first, and [`WorkspaceError`] says why a grid or search cannot be made.
//! - [`Grid::points`] and [`Grid::volume`]: a set's cell centres, and its volume as its count of
//!   cells times `s³`.
//! - [`Grid::regular_cylinder`]: the largest vertical [`Cylinder`] on the `z` axis whose cells
//!   are all in several sets (a regular common workspace), conservative by up to a step.
//! - [`Grid::map_rows`] and [`Grid::select`]: a function of each row, or a predicate of each
//!   cell centre, evaluated in parallel (rayon) with a [`Progress`] report per row; the result
//!   does not depend on the number of threads.
//!
//! Lengths are in any one unit: the grid's step sets it, and every length and volume here is in
//! it (a step ten times larger, in a unit ten times smaller, gives the same cells).

mod cells;
mod cylinder;
mod grid;
mod scan;

pub use cylinder::Cylinder;
pub use grid::{Grid, MAX_CELLS, WorkspaceError, check_step, count, finite};
pub use scan::{Progress, map_in_parallel};
