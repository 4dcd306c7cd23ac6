//! kinsyn: structural synthesis and kinematic analysis of parallel manipulators.
//!
//! The crate follows the data flow of `ARCHITECTURE.md`: [`notation`] reads and prints chains
//! in paper 000's letters with their parallel-axis marks; [`synthesis`] enumerates the 6-dof
//! P/R chains of paper 000 §2 with their provenance; [`paper`] holds the printed Appendix and
//! compares it row by row with the enumeration; [`catalogue`] deduplicates the candidates into
//! catalogue entries and writes the `catalogue/` files.
#![deny(missing_docs)]

pub mod catalogue;
pub mod chain;
pub mod manipulator;
pub mod mechanism;
pub mod motion;
pub mod notation;
pub mod paper;
pub mod screw;
pub mod synthesis;
pub mod verification;
