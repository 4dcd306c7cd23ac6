//! The `kinsyn` command line. See `kinsyn --help`; the command is [`kinsyn_cli::run`].

fn main() {
    std::process::exit(kinsyn_cli::run());
}
