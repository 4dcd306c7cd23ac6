//! Command-line interface: parses arguments, runs the library, prints results.
//!
//! Exit codes (docs/limits.md): 0 success (also `--help`, `--version`, and a reader that went
//! away); 2 bad input (arguments, chain strings, patterns, poses, input values, files that are
//! missing or not descriptions, faulty fields, limits); 1 an environment failure (an output that
//! cannot be written) or a damaged build (a compiled-in catalogue that does not read). Errors are one line on stderr, prefixed `kinsyn: error:`, with echoed
//! input escaped ([`terminal::one_line`]).

mod manipulator;
mod terminal;

use clap::{Args, Parser, Subcommand, ValueEnum};
use kinsyn::catalogue::{Catalogue, Entry, VERIFICATION_SEED};
use kinsyn::motion::PatternQuery;
use kinsyn::notation::Chain;
use kinsyn::synthesis::{Options, PrismaticReading, tables};
use kinsyn::verification::{self, Settings};
use std::fmt::Write as _;
use std::path::PathBuf;

/// Structural synthesis and kinematic analysis of parallel manipulators.
///
/// kinsyn enumerates the 6-dof serial chains of P and R joints of paper 000 (Ibarreche et al.,
/// "Multioperation capacity of parallel manipulators basing on generic kinematic chain
/// approach", §2), reads them in C/U/S letters with their parallel-axis groups, and compares
/// the result row by row with the paper's printed Appendix.
#[derive(Debug, Parser)]
#[command(
    name = "kinsyn",
    version,
    propagate_version = true,
    subcommand_required = true,
    arg_required_else_help = false
)]
#[command(
    after_help = "Examples:\n  kinsyn catalogue summary\n  kinsyn catalogue list --family PPRRRR\n  kinsyn catalogue show T1-001\n  kinsyn catalogue show 'RaU(a,b)U(b,c)Rc'\n  kinsyn notation 'U(!,-)P!S'"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// The catalogue of 6-dof leg chains (paper 000 §2, Tables 1–8).
    #[command(subcommand, subcommand_required = true, arg_required_else_help = false)]
    Catalogue(CatalogueCommand),
    /// Find the verified chains that give a motion pattern, directly or by locking joints.
    ///
    /// Patterns: the 12 displacement groups E, T(u), R(u), H(u), T2(plane), C(u), G(plane), T3,
    /// S, Y(u), X(u), D, with u one of x, y, z and plane one of xy, yz, xz (leave the parentheses
    /// out for any direction), or a non-group pattern nTmR such as 3T1R. Directions are those of
    /// the entry's reference configuration, where locked joints are held. Each hit lists its
    /// minimal lock sets: joint positions in the entry's P/R word ('-' for none).
    Query {
        /// The pattern, e.g. T3, 'X(z)', 'G(xy)', S, 2T1R (quote parentheses in the shell).
        #[arg(long)]
        pattern: String,
        /// Lock at most this many joints (0: the chain's own motion).
        #[arg(long, default_value_t = 6)]
        max_locks: usize,
        /// Only this family: PPPRRR, PPRRRR, PRRRRR or RRRRRR.
        #[arg(long)]
        family: Option<String>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        reading: Reading,
    },
    /// Check a chain string and show what it means: letters, primitive joints, parallel
    /// groups, actuated joints.
    ///
    /// Notation (docs/notation.md): letters P R C U S; a parallel group is a letter a, b, c
    /// after the revolute it holds; '!' marks an actuated joint; C, U and S take one slot per
    /// primitive joint in parentheses, e.g. U(a,-), S(-,-,b), C(!,-). 'Ca' marks the R of a C.
    Notation {
        /// The chain, e.g. 'RaU(a,b)U(b,c)Rc' or 'U(!,-)P!S' (quote it in the shell).
        chain: String,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Multioperation capacity: the platform's dof and motion pattern for subsets of locked
    /// inputs, then the displacement groups reached with their minimal lock sets.
    ///
    /// Each locked input is held at its value at the start configuration (the file's reference,
    /// or --pose); the platform's finite motion is sampled from there by loop closure (Newton
    /// steps along random compatible joint rates, seeded) and classified among the 12
    /// displacement groups, or as nTmR when it is not a group (paper 000 §1, §5). Inputs are
    /// labelled by kind, leg and joint: P1.3 is leg 1's third joint.
    ///
    /// The work is exponential in the number of inputs n: all the lock subsets are 2^n sampled
    /// motions (64 for 6 inputs, 4096 for 12, 65536 for 16). One subset costs about 0.8 ms of
    /// CPU (3-UPS) to 4 ms (6-UPS) with the default 3 samples, in proportion to --samples; the
    /// subsets share the cores. --max-locks N samples Σ_{k≤N} C(n,k) subsets, --lock one;
    /// more than --max-subsets are refused.
    #[command(
        after_help = "Examples:\n  kinsyn modes mechanisms/3-ups.json\n  kinsyn modes mechanisms/3-ups.json --lock R1.1,R2.1,R3.1\n  kinsyn modes mechanisms/6-ups.json --max-locks 2 --pose 0.05,0,1.1,0,5,10\n  kinsyn modes mechanisms/6-ups.json --json > modes.json"
    )]
    Modes {
        /// A manipulator file (docs/mechanism-format.md), e.g. mechanisms/3-ups.json.
        file: PathBuf,
        /// The start configuration, in the forms of analyze --pose: x,y,z,rx,ry,rz (the platform
        /// frame's origin and rotation vector, angles in the file's unit) or some coordinates by
        /// name (z=1.1,rx=5), assembled with every input free; the locked inputs are held at
        /// their values there. Default: the reference.
        #[arg(long, allow_hyphen_values = true)]
        pose: Option<String>,
        /// Only the subsets with at most N inputs locked: Σ_{k≤N} C(n,k) of them.
        #[arg(long, value_name = "N", conflicts_with = "lock")]
        max_locks: Option<usize>,
        /// Only this subset, printed in detail: labels as in analyze, e.g. 'R1.1,R2.1,R3.1'
        /// ('-' for none).
        #[arg(long, value_name = "SET", allow_hyphen_values = true)]
        lock: Option<String>,
        /// Refuse more lock subsets than this (each is a sampled motion of about 1–5 ms of CPU;
        /// 4096 take about 16–20 s on a 6-UPS).
        /// A moving body of a kinsyn-manipulator/2 file whose patterns to report instead of the
        /// end-effector's.
        #[arg(long, value_name = "NAME")]
        body: Option<String>,
        #[arg(long, value_name = "COUNT", default_value_t = manipulator::DEFAULT_MAX_SUBSETS,
              value_parser = clap::value_parser!(u32).range(1..=i64::from(manipulator::MAX_SUBSETS_CEILING)))]
        max_subsets: u32,
        #[command(flatten)]
        sampling: Sampling,
        /// Print JSON instead of text: every subset, its classification and the patterns with
        /// all their minimal lock sets.
        #[arg(long)]
        json: bool,
    },
    /// Jacobians J_D and J_I (paper 000 eqs. 11, 18–21), mobility and singularities at a pose.
    ///
    /// Rows of J_D are wrenches (f; m_P) at the platform point P acting on (v_P; ω): one per
    /// free input (its J_I entry), one per locked input and one per leg constraint wrench (zero
    /// J_I rows: the constraint equations, eq. 22). The platform dof is six minus the rank of
    /// the constraint rows. Every rank is decided on a dimensionless copy (lengths over the
    /// mechanism's characteristic length) and printed with its gap. Singularities are ranks
    /// below those at random assemblies of the same mechanism around the pose (generic ranks):
    /// inverse (an input without effect), leg (a leg loses rank), constraint (the constraint
    /// wrenches lose rank: the platform gains a motion), direct (J_D loses rank).
    Analyze {
        /// A manipulator file (docs/mechanism-format.md).
        file: PathBuf,
        /// The platform pose: six numbers x,y,z,rx,ry,rz (the platform frame's origin, then its
        /// rotation vector, angles in the file's unit, like the file's platform.position and
        /// platform.orientation), or some of them by name, e.g. 'z=1.1,rx=5,ry=-3' for a
        /// 3-dof platform: the others (its parasitic motion) are solved. Default: the file's
        /// reference pose.
        #[arg(long, allow_hyphen_values = true)]
        pose: Option<String>,
        /// Input values (forward kinematics), e.g. 'P1.3=0.05,P2.3=-0.02': joint values from
        /// the reference configuration, lengths in the file's unit, angles in its angle unit.
        /// Inputs not named keep their values at the start. With --pose too, both are met.
        #[arg(long, allow_hyphen_values = true)]
        inputs: Option<String>,
        /// Start from the configuration at this pose (same forms as --pose) instead of the
        /// reference: --pose and --inputs are reached by continuation from the start, so the
        /// start chooses the assembly mode when there are several.
        #[arg(long, allow_hyphen_values = true)]
        from: Option<String>,
        /// Inputs to lock, e.g. 'R1.1,R2.1,R3.1' (labels as in kinsyn modes); they are held at
        /// their values at the start.
        #[arg(long)]
        lock: Option<String>,
        /// A moving body of a kinsyn-manipulator/2 file to analyse instead of the end-effector
        /// (its pose is then the one --pose, --from and P refer to).
        #[arg(long, value_name = "NAME")]
        body: Option<String>,
        /// Seed of the random assemblies that give the generic ranks.
        #[arg(long, default_value_t = 2026)]
        seed: u64,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Write a manipulator file with a symmetric geometry whose legs are one chain.
    ///
    /// Legs stand on a base circle, one every 360°/n, and reach a platform circle above it, so
    /// they lie in different planes (paper 000 §3). The chain's axis letters x, y, z (from the
    /// catalogue, or --axes) are read in each leg's frame: z along the leg, y horizontal, x = y × z.
    #[command(
        after_help = "Examples:\n  kinsyn build --legs 3 --chain 'U(!,-)P!S' --name 3-UPS\n  kinsyn build --legs 3 --chain RP!S --axes yzxyz --name 3-RPS\n  kinsyn build --legs 6 --chain T4-034 --actuated 3 --twist 20 --alternate"
    )]
    Build {
        #[command(flatten)]
        spec: BuildArgs,
        /// Write to this file instead of standard output.
        #[arg(long, short)]
        output: Option<PathBuf>,
    },
}

/// The geometry and legs of `kinsyn build` (docs/mechanism-format.md).
#[derive(Debug, Args)]
struct BuildArgs {
    /// Number of legs, 3 to 6.
    #[arg(long, default_value_t = 3)]
    legs: usize,
    /// The leg: a catalogue id (T4-034) or a chain in notation, '!' marking inputs.
    #[arg(long)]
    chain: String,
    /// Axis letters x, y, z per primitive joint in the leg frame (default: the catalogue's).
    #[arg(long)]
    axes: Option<String>,
    /// Actuated primitive joints, 1-based, comma separated (instead of '!' marks).
    #[arg(long, value_delimiter = ',')]
    actuated: Option<Vec<usize>>,
    /// Radius of the base circle.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    base_radius: f64,
    /// Radius of the platform circle.
    #[arg(long, default_value_t = 0.5, allow_hyphen_values = true)]
    platform_radius: f64,
    /// Height of the platform above the base.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    height: f64,
    /// Degrees each platform point is turned from its leg's base point about the vertical.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    twist: f64,
    /// Turn legs 2, 4, 6 the other way: pairs the platform points of a six-legged
    /// Gough–Stewart platform (the regular-hexagon form is singular everywhere).
    #[arg(long)]
    alternate: bool,
    /// The manipulator's name (default n-LETTERS).
    #[arg(long)]
    name: Option<String>,
}

impl From<BuildArgs> for kinsyn::manipulator::build::BuildSpec {
    fn from(a: BuildArgs) -> Self {
        kinsyn::manipulator::build::BuildSpec {
            legs: a.legs,
            chain: a.chain,
            axes: a.axes,
            actuated: a.actuated,
            base_radius: a.base_radius,
            platform_radius: a.platform_radius,
            height: a.height,
            twist: a.twist,
            alternate: a.alternate,
            name: a.name,
        }
    }
}

/// The most `--samples` per motion: 64 walks, about 20 times the default cost of a subset,
/// far more evidence than a group claim needs (two samples 1e-3 apart, docs/verification.md).
const MAX_SAMPLES: i64 = 64;

/// How finite motion is sampled (seeded, reproducible).
#[derive(Debug, Args)]
struct Sampling {
    /// Seed of the random walks (continuous random step lengths and directions).
    #[arg(long, default_value_t = 2026)]
    seed: u64,
    /// Configurations sampled per motion, 2 to 64: a group is recognised by its twist space
    /// staying the same at samples at least 1e-3 apart; each sample is a random walk, so a
    /// subset's cost grows in proportion.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u16).range(2..=MAX_SAMPLES))]
    samples: u16,
}

impl Sampling {
    fn settings(&self) -> kinsyn::mechanism::SampleSettings {
        kinsyn::mechanism::SampleSettings {
            seed: self.seed,
            samples: usize::from(self.samples),
            ..Default::default()
        }
    }
}

#[derive(Debug, Subcommand)]
enum CatalogueCommand {
    /// Enumerate the chains and write chains.json, chains.csv and README.md.
    ///
    /// The files are byte-for-byte reproducible; the committed catalogue/ is what this writes
    /// with the default reading.
    Generate {
        /// Folder to write into (created if missing).
        #[arg(long, default_value = "catalogue")]
        out: PathBuf,
        #[command(flatten)]
        reading: Reading,
    },
    /// Counts per Appendix table: published, printed, generated (letters only and letters +
    /// parallel marks), and the differences from the printed Appendix by kind.
    Summary {
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        reading: Reading,
    },
    /// List catalogue entries, one per line: id, notation, P/R word, axes, provenance.
    List {
        /// Only this family: PPPRRR, PPRRRR, PRRRRR or RRRRRR.
        #[arg(long)]
        family: Option<String>,
        /// Only entries first found in this Appendix table (1, 2, 3, 4, 7 or 8).
        #[arg(long)]
        table: Option<u8>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        reading: Reading,
    },
    /// Show one entry, by id (e.g. T2-017) or by notation (e.g. 'PPUU' or 'PPU(-,a)U(a,-)').
    ///
    /// A notation is matched with its parallel marks. Letters without marks find the entry with
    /// no parallel group, or, if there is none, every entry with those letters.
    Show {
        /// Entry id or chain notation.
        query: String,
        /// Also classify the motion with these joints locked (positions in the entry's word,
        /// e.g. 45 or 1,2,3).
        #[arg(long)]
        lock: Option<String>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        reading: Reading,
    },
    /// The entries the numerical check rejects (not 3T3R), with rank, singular values and idle
    /// joints (the table kept in docs/deviations.md).
    Rejected {
        #[command(flatten)]
        reading: Reading,
    },
    /// Every difference between the enumeration and the printed Appendix, row by row, with
    /// its evidence (the table kept in docs/deviations.md).
    Compare {
        /// Print JSON instead of a Markdown table.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        reading: Reading,
    },
}

/// The options of the paper reading (docs/synthesis.md).
#[derive(Debug, Args)]
struct Reading {
    /// How far apart two parallel prismatic guides may be: 'separated' (default: allowed when
    /// a revolute not parallel to them lies between them) or 'perpendicular' (never parallel).
    #[arg(long, value_enum, default_value_t = PrismaticsArg::Separated)]
    prismatics: PrismaticsArg,
    /// Do not apply §2.3's "three parallel R need a guide along them" to chains with a P.
    #[arg(long)]
    no_triple_guide: bool,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum PrismaticsArg {
    Separated,
    Perpendicular,
}

impl Reading {
    /// The catalogue in this reading. The default reading is the committed catalogue, compiled
    /// into the binary ([`Catalogue::committed`]: read, not re-verified, in milliseconds); any
    /// other reading is enumerated and verified ([`Reading::generated`]).
    fn catalogue(&self) -> Result<Catalogue, CliError> {
        let options = self.options();
        if options != Options::default() {
            return Ok(self.generated());
        }
        Catalogue::committed().map_err(|e| {
            CliError::Internal(format!(
                "the catalogue compiled into kinsyn cannot be read: {e} (a damaged build: regenerate catalogue/chains.json with `kinsyn catalogue generate` and rebuild)"
            ))
        })
    }

    /// The catalogue in this reading, enumerated and verified (about a second: a spinner
    /// shows on a terminal).
    fn generated(&self) -> Catalogue {
        terminal::working("enumerating and verifying the catalogue", || {
            Catalogue::generate(&self.options())
        })
    }

    fn options(&self) -> Options {
        Options {
            prismatics: match self.prismatics {
                PrismaticsArg::Separated => PrismaticReading::Separated,
                PrismaticsArg::Perpendicular => PrismaticReading::Perpendicular,
            },
            triple_group_needs_guide: !self.no_triple_guide,
        }
    }
}

/// A failure the user sees: bad input (exit 2) or an environment problem (exit 1).
#[derive(Debug, thiserror::Error)]
enum CliError {
    #[error("{0}")]
    Input(String),
    #[error("{0}")]
    Io(#[from] std::io::Error),
    /// A fault of the build, not of the input or the environment (exit 1).
    #[error("{0}")]
    Internal(String),
}

/// Runs the command line and returns the process exit code.
pub fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            terminal::error(&format!("{} (see kinsyn --help)", usage_error(&e)));
            return 2;
        }
        Err(e) => {
            // --help and --version: their text is the result.
            let mut text = e.render().to_string();
            if !text.ends_with('\n') {
                text.push('\n');
            }
            return match terminal::print(&text) {
                Ok(()) => 0,
                Err(_) => 1,
            };
        }
    };
    let result = execute(cli.command).and_then(|text| Ok(terminal::print(&text)?));
    match result {
        Ok(()) => 0,
        Err(e) => {
            terminal::error(&e.to_string());
            match e {
                CliError::Input(_) => 2,
                CliError::Io(_) | CliError::Internal(_) => 1,
            }
        }
    }
}

/// A command-line mistake in one line: what is missing or wrong, with the names of the
/// arguments or subcommands concerned (clap spreads these over several lines).
fn usage_error(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let values = |kind| match e.get(kind) {
        Some(ContextValue::Strings(v)) => v.join(", "),
        Some(ContextValue::String(v)) => v.clone(),
        _ => String::new(),
    };
    match e.kind() {
        ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let command = values(ContextKind::InvalidSubcommand);
            let available = values(ContextKind::ValidSubcommand);
            format!(
                "{} needs a subcommand: {}",
                if command.is_empty() {
                    "kinsyn".into()
                } else {
                    command
                },
                available
            )
        }
        ErrorKind::MissingRequiredArgument => {
            format!(
                "missing required argument {}",
                values(ContextKind::InvalidArg)
            )
        }
        _ => {
            // The message lines, without the usage and "for more information" footer.
            let text = e.render().to_string();
            text.lines()
                .map(str::trim)
                .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
                .filter(|l| !l.is_empty())
                .map(|l| l.trim_start_matches("error: "))
                .collect::<Vec<_>>()
                .join(" ")
        }
    }
}

fn execute(command: Command) -> Result<String, CliError> {
    match command {
        Command::Notation { chain, json } => notation(&chain, json),
        Command::Catalogue(c) => catalogue(c),
        Command::Query {
            pattern,
            max_locks,
            family,
            json: as_json,
            reading,
        } => query(&pattern, max_locks, family.as_deref(), as_json, &reading),
        Command::Modes {
            file,
            pose,
            max_locks,
            lock,
            max_subsets,
            body,
            sampling,
            json: as_json,
        } => {
            let selection = match (lock, max_locks) {
                (Some(set), _) => manipulator::Selection::Lock(set),
                (None, Some(k)) => manipulator::Selection::MaxLocks(k),
                (None, None) => manipulator::Selection::All,
            };
            manipulator::modes(
                &file,
                (pose.as_deref(), body.as_deref()),
                &selection,
                max_subsets,
                &sampling.settings(),
                as_json,
            )
        }
        Command::Analyze {
            file,
            pose,
            inputs,
            from,
            lock,
            body,
            seed,
            json: as_json,
        } => manipulator::analyze(
            &file,
            &manipulator::Placement {
                pose: pose.as_deref(),
                inputs: inputs.as_deref(),
                from: from.as_deref(),
                body: body.as_deref(),
            },
            lock.as_deref(),
            &kinsyn::mechanism::SampleSettings {
                seed,
                ..Default::default()
            },
            as_json,
        ),
        Command::Build { spec, output } => {
            manipulator::build_command(&spec.into(), output.as_deref())
        }
    }
}

fn check_family(family: Option<&str>) -> Result<(), CliError> {
    match family {
        Some(f) if !tables::families().contains(&f) => Err(CliError::Input(format!(
            "unknown family {f:?}; the families are {}",
            tables::families().join(", ")
        ))),
        _ => Ok(()),
    }
}

fn query(
    pattern: &str,
    max_locks: usize,
    family: Option<&str>,
    as_json: bool,
    reading: &Reading,
) -> Result<String, CliError> {
    let q: PatternQuery = pattern
        .parse()
        .map_err(|e| CliError::Input(format!("{e}")))?;
    check_family(family)?;
    if max_locks > 6 {
        return Err(CliError::Input(format!(
            "--max-locks {max_locks}: a leg has six joints"
        )));
    }
    let cat = reading.catalogue()?;
    let hits = cat.query(&q, max_locks, family);
    if as_json {
        let rows: Vec<serde_json::Value> = hits
            .iter()
            .map(|h| serde_json::json!({"id": h.entry.id, "notation": h.entry.notation, "family": h.entry.family, "word": h.entry.word, "axes": h.entry.axes, "pattern": h.pattern, "lock_sets": h.lock_sets}))
            .collect();
        return Ok(json(&rows));
    }
    let mut s = String::new();
    for h in &hits {
        let _ = writeln!(
            s,
            "{:<8} {:<22} {} {} {:<7} lock {}",
            h.entry.id,
            h.entry.notation,
            h.entry.word,
            h.entry.axes,
            h.pattern,
            h.lock_sets.join(" | ")
        );
    }
    let chains: std::collections::BTreeSet<&str> =
        hits.iter().map(|h| h.entry.id.as_str()).collect();
    let _ = writeln!(
        s,
        "{} verified chains give {q} with at most {max_locks} locked joints{}",
        chains.len(),
        pattern_note(&q)
    );
    Ok(s)
}

/// What an `nTmR` query means when groups have the same numbers: the group it always is, or
/// the groups it leaves out (it matches non-group motions only).
fn pattern_note(q: &PatternQuery) -> String {
    if let Some(kind) = q.forced_group() {
        return format!(" ({q} is always the group {})", kind.symbol());
    }
    let groups: Vec<&str> = q
        .groups_of_the_same_type()
        .iter()
        .map(|k| k.symbol())
        .collect();
    if groups.is_empty() {
        String::new()
    } else {
        format!(
            " ({q} counts non-group motions only; the groups of this type are {}: query them by name)",
            groups.join(", ")
        )
    }
}

fn json<T: serde::Serialize>(value: &T) -> String {
    let mut s = serde_json::to_string_pretty(value).expect("serialisable");
    s.push('\n');
    s
}

fn notation(text: &str, as_json: bool) -> Result<String, CliError> {
    let chain: Chain = text
        .parse()
        .map_err(|e| CliError::Input(format!("{text:?}: {e}")))?;
    let primitives: Vec<String> = chain
        .primitives()
        .enumerate()
        .map(|(i, (p, m))| {
            let mut s = format!("{}{}", i + 1, p.letter());
            if let Some(g) = m.group {
                s.push((b'a' + g) as char);
            }
            if m.actuated {
                s.push('!');
            }
            s
        })
        .collect();
    let actuated: Vec<usize> = chain
        .primitives()
        .enumerate()
        .filter(|(_, (_, m))| m.actuated)
        .map(|(i, _)| i + 1)
        .collect();
    if as_json {
        return Ok(json(&serde_json::json!({
            "notation": chain.to_string(),
            "letters": chain.letters(),
            "word": chain.primitive_word(),
            "parallel_groups": chain.parallel_groups(),
            "actuated": actuated,
        })));
    }
    let mut s = String::new();
    let _ = writeln!(s, "notation  {chain}");
    let _ = writeln!(s, "letters   {}", chain.letters());
    let _ = writeln!(
        s,
        "word      {} ({})",
        chain.primitive_word(),
        primitives.join(" ")
    );
    let groups: Vec<String> = chain
        .parallel_groups()
        .iter()
        .enumerate()
        .map(|(g, m)| format!("{}: {:?}", (b'a' + g as u8) as char, m))
        .collect();
    let _ = writeln!(s, "parallel  {}", list_or_none(&groups));
    let _ = writeln!(
        s,
        "actuated  {}",
        if actuated.is_empty() {
            "none".to_string()
        } else {
            format!("{actuated:?}")
        }
    );
    Ok(s)
}

/// The items joined by commas, or "none".
fn list_or_none(items: &[String]) -> String {
    if items.is_empty() {
        "none".to_string()
    } else {
        items.join(", ")
    }
}

fn catalogue(command: CatalogueCommand) -> Result<String, CliError> {
    match command {
        CatalogueCommand::Generate { out, reading } => {
            let cat = reading.generated();
            cat.write(&out)?;
            let (letters, marks) = cat.totals();
            Ok(format!(
                "wrote {} entries ({letters} distinct by letters) to {}\n",
                marks,
                out.display()
            ))
        }
        CatalogueCommand::Summary {
            json: as_json,
            reading,
        } => {
            let cat = reading.catalogue()?;
            if as_json {
                let diffs: Vec<serde_json::Value> = cat
                    .difference_counts()
                    .iter()
                    .map(
                        |((t, k), n)| serde_json::json!({"table": t, "kind": k.name(), "count": n}),
                    )
                    .collect();
                let (letters, marks) = cat.totals();
                return Ok(json(&serde_json::json!({
                    "options": cat.options,
                    "tables": cat.counts,
                    "published_6r": tables::PUBLISHED_6R,
                    "published_total": tables::PUBLISHED_TOTAL,
                    "total_letters_only": letters,
                    "total_with_marks": marks,
                    "differences": diffs,
                })));
            }
            let readme = cat.readme();
            let body = readme
                .split_once("## Counts per table")
                .map_or(readme.as_str(), |(_, b)| b);
            Ok(format!(
                "kinsyn catalogue: paper 000 §2 structural synthesis{body}"
            ))
        }
        CatalogueCommand::List {
            family,
            table,
            json: as_json,
            reading,
        } => {
            if let Some(f) = &family
                && !tables::families().contains(&f.as_str())
            {
                return Err(CliError::Input(format!(
                    "unknown family {f:?}; the families are {}",
                    tables::families().join(", ")
                )));
            }
            if let Some(t) = table
                && tables::table(t).is_none()
            {
                return Err(CliError::Input(format!(
                    "no Appendix table {t}; the tables with chains are 1, 2, 3, 4, 7, 8"
                )));
            }
            let cat = reading.catalogue()?;
            let entries: Vec<&Entry> = cat
                .entries
                .iter()
                .filter(|e| {
                    family.as_ref().is_none_or(|f| &e.family == f)
                        && table.is_none_or(|t| e.provenance.table == t)
                })
                .collect();
            if as_json {
                return Ok(json(&entries));
            }
            let mut s = String::new();
            for e in entries {
                let _ = writeln!(
                    s,
                    "{:<8} {:<22} {} {} table {} row {} variant {}",
                    e.id,
                    e.notation,
                    e.word,
                    e.axes,
                    e.provenance.table,
                    e.provenance.row,
                    e.provenance.variant
                );
            }
            Ok(s)
        }
        CatalogueCommand::Rejected { reading } => Ok(reading.catalogue()?.not_3t3r_markdown()),
        CatalogueCommand::Show {
            query,
            lock,
            json: as_json,
            reading,
        } => {
            let cat = reading.catalogue()?;
            let entry = match cat.find(&query) {
                Some(e) => e,
                None if query
                    .parse::<Chain>()
                    .is_ok_and(|c| c.parallel_groups().is_empty()) =>
                {
                    // Letters only: show every entry with these letters, if any.
                    let letters = query
                        .parse::<Chain>()
                        .map(|c| c.letters())
                        .unwrap_or_default();
                    let same: Vec<&Entry> = cat
                        .entries
                        .iter()
                        .filter(|e| e.letters == letters)
                        .collect();
                    if same.is_empty() {
                        return Err(CliError::Input(format!(
                            "{letters:?} is not in the catalogue: the rules of paper 000 §2 do not give it"
                        )));
                    }
                    if as_json {
                        return Ok(json(&same));
                    }
                    let mut s = format!(
                        "no entry {letters} without parallel marks; {} entr{} with these letters:\n\n",
                        same.len(),
                        if same.len() == 1 { "y" } else { "ies" }
                    );
                    s.push_str(
                        &same
                            .iter()
                            .map(|e| describe(&cat, e))
                            .collect::<Vec<_>>()
                            .join("\n"),
                    );
                    return Ok(s);
                }
                None => {
                    let looks_like_id = query.trim().starts_with(['T', 't'])
                        && query.contains('-')
                        && query.chars().any(|c| c.is_ascii_digit());
                    return Err(CliError::Input(match query.parse::<Chain>() {
                        Err(_) if looks_like_id => format!(
                            "no entry with id {query:?} (ids look like T2-017; see kinsyn catalogue list)"
                        ),
                        Err(e) => {
                            format!("{query:?} is neither an entry id nor a valid chain: {e}")
                        }
                        Ok(chain) => {
                            let same: Vec<&str> = cat
                                .entries
                                .iter()
                                .filter(|e| e.letters == chain.letters())
                                .map(|e| e.notation.as_str())
                                .collect();
                            if same.is_empty() {
                                format!(
                                    "'{chain}' is not in the catalogue: the rules of paper 000 §2 do not give it"
                                )
                            } else {
                                format!(
                                    "'{chain}' is not in the catalogue; entries with letters {}: {}",
                                    chain.letters(),
                                    same.join(", ")
                                )
                            }
                        }
                    }));
                }
            };
            let locked = match &lock {
                None => None,
                Some(text) => Some(locked_pattern(entry, text)?),
            };
            if as_json {
                let mut v = serde_json::to_value(entry).expect("serialisable");
                if let Some((set, pattern)) = locked {
                    v["locked"] = serde_json::json!({"lock_set": set, "pattern": pattern});
                }
                return Ok(json(&v));
            }
            let mut s = describe(&cat, entry);
            if let Some((set, pattern)) = locked {
                let _ = writeln!(s, "locked {set:<6} {pattern}");
            }
            Ok(s)
        }
        CatalogueCommand::Compare {
            json: as_json,
            reading,
        } => {
            let cat = reading.catalogue()?;
            if as_json {
                return Ok(json(&cat.differences));
            }
            Ok(cat.differences_markdown())
        }
    }
}

/// The motion of an entry's chain with the joints of `text` locked (its verification's
/// geometry and sample configurations).
fn locked_pattern(entry: &Entry, text: &str) -> Result<(String, String), CliError> {
    let chain = entry
        .serial_chain(VERIFICATION_SEED)
        .map_err(|e| CliError::Input(format!("{}: {e}", entry.id)))?;
    let mask = verification::parse_lock_set(text, chain.len())
        .map_err(|e| CliError::Input(format!("{}: {e}", entry.id)))?;
    let settings = Settings::default();
    let configurations =
        verification::configurations(&chain, &settings, entry.sample_seed(VERIFICATION_SEED));
    let c = verification::locked_motion(&chain, mask, &configurations, &settings);
    Ok((
        verification::lock_text(mask, chain.len()),
        c.pattern.to_string(),
    ))
}

fn describe(cat: &Catalogue, e: &Entry) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}  {}", e.id, e.notation);
    let _ = writeln!(s, "letters      {}", e.letters);
    let _ = writeln!(
        s,
        "family       {} (Table {})",
        e.family, e.provenance.table
    );
    let _ = writeln!(s, "word         {}", e.word);
    let _ = writeln!(
        s,
        "axes         {} (direction of each primitive joint at the reference configuration)",
        e.axes
    );
    let groups: Vec<String> = e.parallel_groups.iter().map(|g| format!("{g:?}")).collect();
    let _ = writeln!(s, "parallel     {}", list_or_none(&groups));
    let c = e.composition;
    let _ = writeln!(
        s,
        "composition  P {} R {} C {} U {} S {}",
        c.p, c.r, c.c, c.u, c.s
    );
    let _ = writeln!(
        s,
        "provenance   Table {} row {} variant {} ({})",
        e.provenance.table, e.provenance.row, e.provenance.variant, e.provenance.variant_label
    );
    let _ = writeln!(
        s,
        "paper        {}",
        match (e.printed_in_row, e.printed_in_appendix) {
            (true, _) => "printed in this row of the Appendix",
            (false, true) => "printed in another row of the Appendix",
            (false, false) => "not printed in the Appendix",
        }
    );
    if let Some(v) = &e.verification {
        let _ = writeln!(
            s,
            "verified     {} (rank {} at every sample, smallest kept singular value {:.3e} of the largest{})",
            if v.is_3t3r { "3T3R" } else { "NOT 3T3R" },
            v.rank,
            v.gap,
            if v.idle_joints.is_empty() {
                String::new()
            } else {
                format!("; idle joints {:?}", v.idle_joints)
            }
        );
        let sv: Vec<String> = v
            .singular_values
            .iter()
            .map(|x| format!("{x:.4}"))
            .collect();
        let _ = writeln!(s, "singular     {}", sv.join(" "));
        let _ = writeln!(
            s,
            "patterns     (lock sets: joint positions in the word; minimal sets only)"
        );
        let mut groups: Vec<(&String, &Vec<String>)> = v
            .patterns
            .iter()
            .filter(|(p, _)| {
                p.parse::<PatternQuery>()
                    .is_ok_and(|q| matches!(q, PatternQuery::Group { .. }))
            })
            .collect();
        groups.sort_by_key(|(p, locks)| {
            (
                locks
                    .iter()
                    .map(|l| if l.as_str() == "-" { 0 } else { l.len() })
                    .min(),
                (*p).clone(),
            )
        });
        for (p, locks) in groups {
            let _ = writeln!(s, "  {p:<8} {}", locks.join(" | "));
        }
        let others: Vec<String> = v
            .patterns
            .keys()
            .filter(|p| {
                p.parse::<PatternQuery>()
                    .is_ok_and(|q| matches!(q, PatternQuery::NonGroup { .. }))
            })
            .cloned()
            .collect();
        let _ = writeln!(s, "  non-group: {}", others.join(" "));
    }
    let others: Vec<String> = cat
        .entries
        .iter()
        .filter(|o| o.letters == e.letters && o.id != e.id)
        .map(|o| format!("{} {}", o.id, o.notation))
        .collect();
    if !others.is_empty() {
        let _ = writeln!(s, "same letters {}", others.join(", "));
    }
    s
}
