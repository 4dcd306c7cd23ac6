//! kinsyn: structural synthesis and kinematic analysis of parallel manipulators.
//!
//! The crate follows the data flow of `ARCHITECTURE.md`. At the bottom, [`spatial`] holds the
//! rigid displacements SE(3) and their twists: composition, inverse, exponential and logarithm,
//! the adjoint, and Study parameters (paper 004 eqs. 4–7); beside it a private `linalg` layer
//! holds the checked SVD, ranks, span and null-space bases and least squares, re-exported from
//! [`screw`]. [`notation`] reads and prints chains
//! in paper 000's letters with their parallel-axis marks; [`synthesis`] enumerates the 6-dof
//! P/R chains of paper 000 §2 with their provenance; [`published`] compares the enumeration row
//! by row with a printed table given as data (paper 000's Appendix is in `kinsyn-papers`);
//! [`catalogue`] deduplicates the candidates into
//! catalogue entries and writes the `catalogue/` files; [`screw`], [`chain`], [`motion`] and
//! [`verification`] check each entry numerically. [`mechanism`] holds general body–joint graphs
//! (loops, mobility, assembly, finite motion) and [`manipulator`] builds parallel manipulators on
//! them from description files: Jacobians in the form of paper 000 §4–5, singularities, and the
//! motion patterns reached by locking inputs; [`geometry`] writes their legs as constraint
//! polynomials in Study parameters. [`workspace`] holds the grids of end-effector positions on
//! which workspaces are searched: sets of cells, their volumes and the largest regular cylinder
//! inside them. The polynomial systems are solved and their roots
//! certified by the crate `kinsyn-nag`, re-exported here as [`poly`], [`homotopy`] and
//! [`certify`]. Every file the crate and the command write goes through [`output`]: whole or
//! not at all, never through a symbolic link.
//!
//! The case studies of single papers (the HEXA of paper 001, the series-parallel Jacobian of
//! paper 002, the configurable 4-RRR of paper 003, the 4-RUU of paper 004, and the printed
//! Appendix of paper 000 that the catalogue is compared with) are the crate
//! `kinsyn-papers`, on this one: second methods and the papers' data, which this crate never
//! imports.
#![deny(missing_docs)]

pub mod catalogue;
pub mod chain;
pub mod export_tree;
pub mod geometry;
mod linalg;
pub mod lockset;
pub mod manipulator;
pub mod markup;
pub mod mechanism;
pub mod mjcf;
pub mod motion;
pub mod notation;
pub mod output;
pub mod published;
pub mod schematic;
pub mod screw;
pub mod spatial;
pub mod sweep;
pub mod synthesis;
pub mod urdf;
pub mod verification;
pub mod view;
pub mod workspace;

pub use kinsyn_nag::{certify, homotopy, poly, polyhedral};
