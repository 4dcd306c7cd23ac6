//! The `kinsyn` command line as a library: [`run`] is the whole command (the binary `kinsyn`
//! is `fn main` calling it). It parses the arguments (clap), runs the commands as the crate
//! `kinsyn-report` provides them (the same functions the Python package calls) and prints the
//! typed reports they return, as text or `--json`; what only the command needs is here: the
//! argument grammar, the text of each report, the catalogue site, the figures (plotters, a
//! compiled-in font) and the Parquet encoder of the sweep's table ([`parquet_bytes`]).

mod cli;

/// `designs.parquet` from a sweep's rows and manifest: the command's [`kinsyn_report::sweep::Table`].
pub use cli::parquet_bytes;
pub use cli::{Error, run};
