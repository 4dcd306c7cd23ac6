//! The `kinsyn` command line as a library. [`run`] is the whole command (the binary `kinsyn` is
//! `fn main` calling it); the other items are what the Python package `kinsyn` (crate
//! `kinsyn-py`) shares with the command, so that both read the same files, compute the same
//! `--json` reports and refuse bad input with the same one-line messages:
//!
//! - files: [`read_text`] (and [`read_text_within`], [`read_bytes_within`], [`check_file`]
//!   with a [`SizeLimit`]), [`parse_description`];
//! - errors: [`Error`], [`one_line`];
//! - `kinsyn build`: [`build_checked`], [`build_flag`];
//! - `kinsyn analyze`: [`analyse_placed`] and [`Analyzed::json`];
//! - `kinsyn modes`: [`sample_modes`] and [`modes_json`];
//! - `kinsyn analyze --all-assemblies`: [`all_assemblies_of`] and [`AllAssemblies::json`];
//! - `--body`, `--relative-to`, `--legs`: [`select_body`], [`parse_description_legs`];
//! - `kinsyn solve`: [`solve_system`] and [`Solved::json`];
//! - `kinsyn configurable inverse|forward|velocity`: [`configurable_inverse`],
//!   [`configurable_forward`], [`configurable_velocity`] (their `--json` reports as text);
//! - `kinsyn components`: [`components`] with [`ComponentsOptions`] (its `--json` report);
//! - `kinsyn sweep` and `kinsyn sweep merge`: the module [`sweep`] ([`sweep::sweep`],
//!   [`sweep::merge`], the files' readers and writers; [`sweep::read_results`], the rows read
//!   back and checked by [`kinsyn::sweep::rows::Known`]).
//!
//! The computations are the crate `kinsyn`'s; this crate turns options into requests and
//! results into reports.

mod cli;

pub use cli::components::{ComponentsOptions, components};
pub use cli::configurable::{
    forward as configurable_forward, inverse as configurable_inverse,
    velocity as configurable_velocity,
};
pub use cli::files::{
    INPUT_FILES, MAX_FILE_BYTES, SizeLimit, check_file, read_bytes_within, read_text,
    read_text_within,
};
pub use cli::manipulator::{
    AllAssemblies, Analyzed, DEFAULT_MAX_SUBSETS, MAX_SAMPLES, MAX_SUBSETS_CEILING, Placement,
    Selection, all_assemblies_of, analyse_placed, build_checked, build_flag, modes_json,
    parse_description, parse_description_legs, sample_modes, select_body,
};
pub use cli::solve::{MAX_RUNS, MAX_THREADS, Show, SolveOptions, Solved, solve_system};
pub use cli::sweep;
pub use cli::terminal::one_line;
pub use cli::{Error, run};
