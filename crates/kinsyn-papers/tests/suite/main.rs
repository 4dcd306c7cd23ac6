//! The tests of the case studies: each paper's closed forms against its printed numbers, and
//! against the general engine on the paper's description file.
//!
//! One test binary for the crate, one module per file. Run one module with
//! `cargo test -p kinsyn-papers --test suite MODULE::`; the exhaustive checks are `#[ignore]`d and
//! run by `.ci/run` (`cargo test --locked -- --ignored`).

/// Singular, the exact check of some tests: the kinematics library's tests' helper (one file
/// for both).
#[path = "../../../kinsyn/tests/suite/common/singular.rs"]
pub mod singular;

/// The helpers shared by the modules, as the kinematics library's tests name them.
mod common {
    pub use super::singular;
}

mod appendix;
mod configurable;
mod configurable_general;
mod configurable_mechanism;
mod configurable_methods;
mod configurable_position;
mod configurable_trajectory;
mod configurable_velocity;
mod hexa;
mod hexa_mechanism;
mod hexa_workspace;
mod ruu;
mod ruu_input_space;
mod ruu_mechanism;
mod ruu_modes;
mod ruu_self_motions;
mod ruu_singularities;
mod series;
mod spm;
mod spm_methods;
