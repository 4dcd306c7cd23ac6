//! Newton polytopes, mixed volumes and mixed cells: the combinatorics of the polyhedral
//! homotopy (Huber & Sturmfels, *A polyhedral method for solving sparse polynomial systems*,
//! Math. Comp. 64, 1995; T. Y. Li, *Numerical solution of polynomial systems by homotopy
//! continuation methods*, Handbook of Numerical Analysis XI, 2003, §4).
//!
//! A square system's equation `f_i` has a **support** `A_i`, the exponent vectors of its terms.
//! Bernstein's theorem (the BKK bound): a system with these supports and generic coefficients
//! has exactly `MV(A_1, …, A_n)` isolated roots in the torus `(ℂ*)ⁿ`, the **mixed volume** of
//! the Newton polytopes; with the origin added to every support (Li & Wang 1996) the bound
//! counts the isolated roots in `ℂⁿ`. It is never above the Bézout number and far below it for
//! sparse systems (cyclic-7: 924 against 5 040).
//!
//! [`mixed_cells`] computes the mixed volume the way the polyhedral homotopy needs it: a
//! random **lifting** `ω_i : A_i → ℝ` induces a fine mixed subdivision, whose **mixed cells**
//! are `n`-tuples of edges `{p_i, q_i} ⊂ A_i` with a common inner normal `α̂ = (α, 1)`: for every
//! `i`, `⟨(a, ω_i(a)), α̂⟩` is least over `A_i` exactly at `p_i` and `q_i`. The mixed volume is
//! the sum of the cells' volumes `|det(q_i − p_i)|`.
//!
//! The enumeration is the depth-first search of Li's survey (§4.3) and of `MixedVol` (Gao, Li &
//! Wu, ACM TOMS 31, 2005) without its dynamic ordering: the **lower edges** of each lifted
//! support are found first, each by a linear program; then, for each pair of supports, which
//! lower edges are compatible (their two-support system is feasible), a table that prunes the
//! search; then a partial choice of edges is extended by the support with the fewest lower edges
//! compatible with every edge chosen (fail first; none ends the branch), and only while its
//! linear program (the equalities of its edges, the inequalities of their supports) stays
//! feasible. A complete choice is a cell when its normal, solved from the equalities, puts each
//! edge at its support's minimum: the linear programs only prune. They are small and dense, by
//! the hundred thousand, and solved by a dense dual simplex of their own ([`feasibility`]:
//! 5–50 µs each where a general sparse solver took 60–200 µs and failed on degenerate ones). A
//! budget of linear programs ([`MixedCellSettings::max_linear_programs`]) bounds the cost
//! before anything large is attempted.
//!
//! The mixed volume does not depend on the lifting: the tests check it against known values
//! (cyclic-n, Katsura-n), against PHCpack's `phc -m` and gfan's `_mixedvolume`, and across
//! liftings.

mod binomial;
mod cells;
// Public for the tests in tests/suite/; not part of the API.
#[doc(hidden)]
pub mod feasibility;

pub use binomial::{
    BinomialError, IntegerMatrix, MAX_BINOMIAL_SOLUTIONS, binomial_roots, hermite_lower,
};
pub use cells::{
    DEFAULT_MAX_LINEAR_PROGRAMS, MixedCell, MixedCellError, MixedCellSettings, MixedSubdivision,
    mixed_cells, mixed_volume, supports_of,
};
