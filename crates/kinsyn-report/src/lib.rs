//! kinsyn's commands as functions, shared by its two front ends (the command line,
//! `kinsyn-cli`, and the Python package, `kinsyn-py`): a request checked, the work run by the
//! library (`kinsyn`, `kinsyn-papers`), and the result as a typed report, with failures as one
//! [`Error`] whose message is one line and warnings as data (one line each). What a report
//! contains is decided here; how it is printed is the front end's: the command line writes
//! the text a terminal shows and the `--json` text from these values, Python turns them into
//! objects and exceptions, so that both read the same files, compute the same reports and
//! refuse bad input with the same words.
//!
//! - files: [`files::read_text`] (and [`files::read_text_within`],
//!   [`files::read_bytes_within`], [`files::check_file`] with a [`files::SizeLimit`]),
//!   [`manipulator::parse_description`];
//! - errors: [`Error`], [`terminal::one_line`];
//! - `kinsyn build`: [`manipulator::build_checked`], [`manipulator::build_flag`];
//! - `kinsyn analyze`: [`manipulator::analyze`] (a file read, a [`manipulator::Loaded`]),
//!   [`manipulator::analyse_placed`] and [`manipulator::Analyzed::report`] (a
//!   [`manipulator::AnalyzeReport`]);
//! - `kinsyn modes`: [`manipulator::modes`], [`manipulator::sample_modes`] and
//!   [`manipulator::modes_report`] (a [`manipulator::ModesReport`]);
//! - `kinsyn analyze --all-assemblies`: [`manipulator::all_assemblies`],
//!   [`manipulator::all_assemblies_of`] and [`manipulator::AllAssemblies::report`] (a
//!   [`manipulator::AssembliesReport`]);
//! - `--body`, `--relative-to`, `--legs`: [`manipulator::select_body`],
//!   [`manipulator::parse_description_legs`];
//! - `kinsyn solve`: [`solve::solve`], [`solve::solve_system`] (a [`solve::Solved`]) and
//!   [`solve::Solved::json`];
//! - `kinsyn configurable inverse|forward|velocity`: [`configurable::inverse_report`],
//!   [`configurable::forward_report`], [`configurable::velocity_report`];
//! - `kinsyn components`: [`components::components_of`] with [`components::ComponentsOptions`]
//!   (a [`components::Components`]) and [`components::Components::report`] (a
//!   [`components::ComponentsReport`]);
//!
//! The reports are typed values (`#[derive(Serialize)]` structs, each field documented with
//! its meaning and unit): the front ends print them as JSON with [`sorted_json`] (the command)
//! or hand them to Python as the text of [`sorted_value`]; the command's text output is
//! written by the command line from the same values.
//! - `kinsyn view`: [`view::view_of`] with [`view::ViewOptions`] (a [`kinsyn::view::View`],
//!   written as a page by [`kinsyn::view::page`]);
//! - `kinsyn sweep` and `kinsyn sweep merge`: [`sweep`] (the run, the merge, the files'
//!   readers and writers; `designs.parquet` is encoded by the front end, [`sweep::Table`]).
//!
//! This crate depends on no command-line parser, plotting or file-format crate: what only
//! the command needs (argument grammar, text rendering, figures, the Parquet encoder) is in
//! `kinsyn-cli`.

#![deny(missing_docs)]

pub mod components;
pub mod configurable;
pub mod files;
pub mod manipulator;
pub mod output;
pub mod solve;
pub mod solve_shards;
pub mod sweep;
pub mod terminal;
pub mod view;

/// A failure the user sees, as one message (printed after `kinsyn: error: ` by the command,
/// raised as an exception by Python; made one line by [`terminal::one_line`]): bad input
/// (exit 2) or an environment problem (exit 1).
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input: arguments, chains, patterns, poses, input values, files that are missing or
    /// not what they should be, faulty fields, limits (exit 2).
    #[error("{0}")]
    Input(String),
    /// An output that cannot be written (exit 1).
    #[error("{0}")]
    Io(#[from] std::io::Error),
    /// A fault of the build, not of the input or the environment (exit 1).
    #[error("{0}")]
    Internal(String),
}

/// `value` as the pretty JSON a command prints, one trailing newline, with every control or
/// bidirectional-formatting character in its strings as a `\uXXXX` escape
/// ([`kinsyn::markup::json_visible`]): valid JSON of the same value that cannot drive a terminal.
///
/// # Panics
/// Never for the reports of this crate: each serialises (string keys, finite or `null` numbers).
#[must_use]
pub fn json<T: serde::Serialize>(value: &T) -> String {
    let mut s =
        kinsyn::markup::json_visible(&serde_json::to_string_pretty(value).expect("serialisable"))
            .into_owned();
    s.push('\n');
    s
}

/// A report as a JSON value whose objects have their keys in alphabetical order at every
/// level, whatever the order of the report's fields: `serde_json` is built here without its
/// `preserve_order` feature, so its [`serde_json::Map`] is sorted. The reports of `analyze`,
/// `modes`, `analyze --all-assemblies`, `components` and `configurable` are printed through this
/// value ([`sorted_json`]), and handed to Python as its text, so that their keys come in the
/// order they always had.
///
/// # Panics
/// Never for the reports of this crate: each serialises (string keys, finite or `null` numbers).
#[must_use]
pub fn sorted_value<T: serde::Serialize>(report: &T) -> serde_json::Value {
    serde_json::to_value(report).expect("serialisable")
}

/// [`json`] of [`sorted_value`]: the pretty JSON of a report with its keys in alphabetical
/// order at every level.
#[must_use]
pub fn sorted_json<T: serde::Serialize>(report: &T) -> String {
    json(&sorted_value(report))
}

/// The items joined by commas, or "none".
#[must_use]
pub fn list_or_none(items: &[String]) -> String {
    if items.is_empty() {
        "none".to_string()
    } else {
        items.join(", ")
    }
}
