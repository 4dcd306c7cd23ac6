//! kinsyn-nag: numerical algebraic geometry for square and non-square polynomial systems.
//!
//! Four layers, each using only those before it:
//! - [`poly`]: sparse multivariate polynomials with complex coefficients and systems of them;
//!   the Bertini and PHCpack input formats read and written ([`poly::bertini`], [`poly::phc`])
//!   with limits decided before any expansion; multi-homogeneous Bézout counts; a compiled
//!   straight-line [`poly::Program`] for the values and the Jacobian.
//! - [`polyhedral`]: Newton polytopes: mixed volumes (the BKK root count) and mixed cells of a
//!   random lifting, binomial systems.
//! - [`homotopy`]: every isolated solution of a square system by homotopy continuation
//!   (total-degree, multi-homogeneous, polyhedral and parameter homotopies, a predictor–corrector tracker
//!   with an endgame), and the numerical irreducible decomposition of a solution set into
//!   witness sets (by dimension, or by regeneration; monodromy and the trace test).
//! - [`certify`]: Krawczyk's operator in interval arithmetic, which proves that a box holds
//!   exactly one root, and which roots are distinct and which real.
//!
//! Nothing here knows of kinematics: the `kinsyn` crate builds the position equations of
//! mechanisms on this crate and re-exports its modules as `kinsyn::poly`, `kinsyn::homotopy`
//! and `kinsyn::certify`. Depend on this crate alone to solve polynomial systems.
//!
//! ```
//! use kinsyn_nag::homotopy::{SolveSettings, solve};
//! use kinsyn_nag::poly::bertini;
//! // A circle of radius 2 and the parabola y = x² − 1: four intersections, all regular, two
//! // real (y = (−1 ± √13)/2; the root y ≈ −2.30 gives x² < 0).
//! let input = bertini::parse(
//!     "INPUT\nvariable_group x, y;\nfunction f, g;\nf = x^2 + y^2 - 4;\ng = y - x^2 + 1;\nEND;\n",
//! )
//! .unwrap();
//! let report = solve(&input.system, &SolveSettings::default()).unwrap();
//! assert_eq!((report.nonsingular(), report.real()), (4, 2));
//! ```
#![deny(missing_docs)]

pub mod certify;
pub mod homotopy;
pub mod poly;
pub mod polyhedral;
