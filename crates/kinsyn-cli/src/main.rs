//! The `kinsyn` command line. See `kinsyn --help`.

mod cli;

fn main() {
    std::process::exit(cli::run());
}
