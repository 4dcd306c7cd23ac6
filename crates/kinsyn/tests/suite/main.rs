//! The tests of the kinematics library: every module against papers, hand derivations and second methods.
//!
//! One test binary for the crate, one module per file (named after the module of `src/` it
//! checks), so that the library is linked once. Run one module with
//! `cargo test -p kinsyn --test suite MODULE::`; the exhaustive checks are `#[ignore]`d and run
//! by `.ci/run` (`cargo test --locked -- --ignored`).

mod catalogue;
mod chain;
mod common;
mod component_motion;
mod fuzz_corpus;
mod generic_ranks;
mod geometry_polynomials;
mod global_analysis;
mod invariance;
mod library;
mod linalg;
mod lockset;
mod manipulator;
mod markup;
mod mechanism;
mod modes_cost;
mod motion;
mod notation;
mod operation_modes;
mod output;
mod platforms;
mod position;
mod position_polynomial;
mod published;
mod schematic;
mod screw;
mod spatial;
mod spm_full_cycle;
mod sweep_ranking;
mod sweep_stability;
mod synthesis;
mod verification;
mod workspace;
