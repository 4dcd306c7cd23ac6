//! The multi-homogeneous Bézout number of a square system with variable groups, and which
//! partial assignments of its equations to the groups can be completed: the count and the
//! enumeration of the start solutions of a linear-product start system
//! ([`crate::homotopy::StartSystem::MultiHomogeneous`]).
//!
//! An assignment gives each equation `i` a group `j` in which it has degree `d_ij > 0`, group
//! `j` receiving exactly as many equations as it has variables (`n_j`); the Bézout number is
//! the sum over assignments of `Π_i d_ij`. Both are computed over the **states** of a partial
//! assignment — how many equations each group has received, `Π_j (n_j + 1)` vectors — which
//! are few for a few large groups and exponentially many for many small ones (with one group
//! per variable the number is a permanent, hard to compute). So the states are bounded:
//! [`MAX_GROUP_STATES`], and beyond it the count is not attempted.

/// The most states (module documentation) the count and the enumeration walk: 2¹⁶ admits sixteen
/// groups of one variable, or two of 255. The walk costs at most
/// `equations × groups × 2¹⁶` steps (a few milliseconds) and `equations × 2¹⁶` bytes.
pub const MAX_GROUP_STATES: u64 = 1 << 16;

/// The assignments of a square system's equations to its variable groups (module
/// documentation): a state is the number of equations given to each group so far, indexed in
/// mixed radix (group `j`'s digit in base `n_j + 1`).
#[derive(Debug, Clone)]
pub struct Assignments {
    sizes: Vec<usize>,
    strides: Vec<usize>,
    /// `completes[i][s]`: whether equations `i, i + 1, …` can be assigned from state `s` so
    /// that every group is full.
    completes: Vec<Vec<bool>>,
    count: u128,
}

impl Assignments {
    /// The assignments for the degrees `d[i][j]` of equation `i` in group `j` and the group
    /// sizes; `None` when the states exceed [`MAX_GROUP_STATES`].
    ///
    /// # Panics
    /// If an equation has more degrees than there are groups.
    #[must_use]
    pub fn new(degrees: &[Vec<u32>], sizes: &[usize]) -> Option<Self> {
        let mut strides = Vec::with_capacity(sizes.len());
        let mut states: u64 = 1;
        for n in sizes {
            strides.push(usize::try_from(states).ok()?);
            states = states.checked_mul(*n as u64 + 1)?;
            if states > MAX_GROUP_STATES {
                return None;
            }
        }
        let states = usize::try_from(states).ok()?;
        let full: usize = sizes.iter().zip(&strides).map(|(n, s)| n * s).sum();
        let m = degrees.len();
        let mut completes = vec![vec![false; states]; m + 1];
        let mut after = vec![0u128; states];
        after[full] = 1;
        completes[m][full] = true;
        for i in (0..m).rev() {
            let mut here = vec![0u128; states];
            for s in 0..states {
                for (j, dij) in degrees[i].iter().enumerate() {
                    let used = (s / strides[j]) % (sizes[j] + 1);
                    if *dij == 0 || used == sizes[j] || !completes[i + 1][s + strides[j]] {
                        continue;
                    }
                    completes[i][s] = true;
                    here[s] = here[s]
                        .saturating_add(after[s + strides[j]].saturating_mul(u128::from(*dij)));
                }
            }
            after = here;
        }
        Some(Self {
            sizes: sizes.to_vec(),
            strides,
            count: after[0],
            completes,
        })
    }

    /// The multi-homogeneous Bézout number: the sum over complete assignments of the product
    /// of the chosen degrees (saturating at `u128::MAX`).
    #[must_use]
    pub fn count(&self) -> u128 {
        self.count
    }

    /// Whether equation `i` may go to group `j` from state `state`, the rest still completing:
    /// the next state if so. The walk starts from the empty assignment, state 0, with
    /// equation 0.
    ///
    /// # Panics
    /// If `j` is not a group; possibly if `i` is not an equation or `state` not a state.
    #[must_use]
    pub fn step(&self, i: usize, state: usize, j: usize) -> Option<usize> {
        let used = (state / self.strides[j]) % (self.sizes[j] + 1);
        let next = state + self.strides[j];
        (used < self.sizes[j] && self.completes[i + 1][next]).then_some(next)
    }
}
