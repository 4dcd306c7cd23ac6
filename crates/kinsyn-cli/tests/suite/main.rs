//! The tests that run the `kinsyn` binary: its commands, messages, files and limits.
//!
//! One test binary for the crate, one module per file (named after the module of `src/` it
//! checks), so that the library is linked once. Run one module with
//! `cargo test -p kinsyn-cli --test suite MODULE::`; the exhaustive checks are `#[ignore]`d and run
//! by `.ci/run` (`cargo test --locked -- --ignored`).

mod catalogue_site;
mod cli;
mod cli_components;
mod cli_configurable;
mod cli_global;
mod cli_manipulator;
mod cli_modes_cost;
mod cli_paper003;
mod cli_platforms;
mod cli_plot;
mod cli_robustness;
mod cli_robustness_files;
mod cli_robustness_output;
mod cli_robustness_polynomials;
mod cli_solve;
mod cli_sweep;
mod cli_sweep_report;
mod common;
mod hexa_cli;
mod hexa_plot;
mod mujoco_export;
mod pinocchio_export;
mod ruu_cli;
mod view_page;
