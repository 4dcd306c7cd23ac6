//! The command line's grammar: subcommands, options and their help texts (clap derive). What
//! each command does is in the sibling modules.

use clap::{Args, Parser, Subcommand, ValueEnum};
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
pub(super) struct Cli {
    #[command(subcommand)]
    pub(super) command: Command,
}

#[derive(Debug, Subcommand)]
pub(super) enum Command {
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
    /// motions (64 for 6 inputs, 4096 for 12, 65536 for 16). A motion is one loop closure where
    /// the locks leave the start rigid, 1 + 3 × --samples (10 by default) from a regular start,
    /// and up to 1 + 240 × --samples closures of up to 100 Newton steps each from a start where
    /// the locked mechanism is singular. By default a subset takes about 0.3 ms of CPU for the
    /// 3-UPS, 1 ms for the 6-UPS and 25 ms for the 51-joint HEXA, a singular start from a few
    /// ms to seconds (the 4096 subsets of a 12-input 6-UPS take 4 s, the 12616 of an 18-input one
    /// with up to five locks 87 s); the subsets share the cores. --max-locks N samples
    /// Σ_{k≤N} C(n,k) subsets, --lock one; more than --max-subsets are refused.
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
        /// A moving body of a kinsyn-manipulator/2 file whose patterns to report instead of the
        /// end-effector's.
        #[arg(long, value_name = "NAME")]
        body: Option<String>,
        /// Report the patterns of the body's motion relative to this other moving body (the
        /// displacements of the body seen from NAME, in NAME's frame at the reference) instead of relative
        /// to the ground.
        #[arg(long, value_name = "NAME")]
        relative_to: Option<String>,
        /// Keep only these legs (1-based, ranges: '1-4', '1-8,29') and the bodies they still
        /// join to the ground: the sub-mechanism, e.g. one limb, whose bond --body shows.
        #[arg(long, value_name = "LIST")]
        legs: Option<String>,
        /// Refuse more lock subsets than this (each a sampled motion: 10 loop closures by default
        /// from a regular start, about 0.3–1 ms of CPU for three or six UPS legs; one where the
        /// locks leave the start rigid; up to seconds from a singular start; 4096 take about 4 s
        /// on a 12-input 6-UPS).
        #[arg(long, value_name = "COUNT", default_value_t = super::manipulator::DEFAULT_MAX_SUBSETS,
              value_parser = clap::value_parser!(u32).range(1..=i64::from(super::manipulator::MAX_SUBSETS_CEILING)))]
        max_subsets: u32,
        #[command(flatten)]
        sampling: Sampling,
        /// Print JSON instead of text: every subset, its classification and the patterns with
        /// all their minimal lock sets.
        #[arg(long)]
        json: bool,
    },
    /// Jacobians `J_D` and `J_I` (paper 000 eqs. 11, 18–21), mobility and singularities at a pose.
    ///
    /// Rows of `J_D` are wrenches (f; `m_P`) at the platform point P acting on (`v_P`; ω): one per
    /// free input (its `J_I` entry), one per locked input and one per leg constraint wrench (zero
    /// `J_I` rows: the constraint equations, eq. 22). The platform dof is six minus the rank of
    /// the constraint rows. Every rank is decided on a dimensionless copy (lengths over the
    /// mechanism's characteristic length) and printed with its gap. Singularities are ranks
    /// below those at random assemblies of the same mechanism around the pose (generic ranks):
    /// inverse (an input without effect), leg (a leg loses rank), constraint (the constraint
    /// wrenches lose rank: the platform gains a motion), direct (`J_D` loses rank).
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
        /// Study parameters x0:x1:x2:x3:y0:y1:y2:y3 (any common scale) of a moving body's frame,
        /// once per moving body in series order from the ground (the file's body order): the
        /// first from the ground frame, each next from the previous body's frame (paper 002 §5:
        /// --study X --study Y for the coupler and the end-effector). Checked on the Study
        /// quadric within 2e-2 (relative, |x·y|/(|x| |y|): values printed to two decimals
        /// pass); the poses are assembled by continuation from the start, or refused with the
        /// residual.
        #[arg(long, value_name = "X0:…:Y3", allow_hyphen_values = true, conflicts_with_all = ["pose", "inputs"])]
        study: Vec<String>,
        /// With --study: analyse the assembled configuration nearest to the Study poses instead of
        /// refusing poses that miss every assembly, as rounded printed values do (paper 002
        /// Table 1: two decimals miss by about 1e-2). The nearest assembly closes every loop and
        /// puts the bodies as near their poses as the loops allow (least squares, Gauss–Newton);
        /// how far it moved each body is reported (translation in the file's length unit,
        /// rotation in its angle unit) beside how far the rounding alone can move it (to first
        /// order, every parameter changed by --rounding). A body moved further is refused:
        /// the values are no rounded configuration of this mechanism.
        #[arg(long, requires = "study")]
        nearest: bool,
        /// With --nearest: how far each printed Study parameter may lie from the exact one, half
        /// a unit of its last printed place (0.005 for two decimals, 0.0005 for three).
        #[arg(long, value_name = "HALF_UNIT", default_value_t = kinsyn::manipulator::PRINTED_ROUNDING)]
        rounding: f64,
        /// A moving body of a kinsyn-manipulator/2 file to analyse instead of the end-effector
        /// (its pose is then the one --pose, --from and P refer to).
        #[arg(long, value_name = "NAME")]
        body: Option<String>,
        /// Also report the analysed body's motion relative to this other moving body: its
        /// relative dof and twists (in NAME's frame at the reference), and whether they are all
        /// translations.
        #[arg(long, value_name = "NAME")]
        relative_to: Option<String>,
        /// Every assembly at the inputs instead of one: the manipulator's constraint
        /// polynomials in the Study parameters of its platform (legs recognised with their
        /// inputs locked: S–S such as UPS, R–S such as RPS, S–R such as SPR), solved by
        /// homotopy continuation and certified; the real assemblies are listed as poses that
        /// --pose takes. Inputs not named in --inputs keep their reference values.
        #[arg(long, conflicts_with_all = ["pose", "from", "study", "lock"])]
        all_assemblies: bool,
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
        /// Write to this file instead of standard output (its folder must exist; an existing
        /// file is refused unless --force).
        #[arg(long, short)]
        output: Option<PathBuf>,
        #[command(flatten)]
        force: Force,
    },
    /// Every isolated solution of a polynomial system, by homotopy continuation, certified.
    ///
    /// The system is a Bertini input file (docs/position-analysis.md): `variable_group x, y;`
    /// (several groups give a multi-homogeneous structure), `function f1, f2;`, `constant`s and
    /// subfunctions, then `f1 = x^2 + y^2 - 1;`, with `I` the imaginary unit. Every path of the
    /// start system is tracked (in parallel) to its end, which is classified: a non-singular
    /// solution, a singular one (with its multiplicity), or a point at infinity. Each
    /// non-singular solution is then certified by the Krawczyk test in interval arithmetic:
    /// proven to be a unique root in a small box, distinct from the others, and real or non-real
    /// where the box decides it. --runs K solves K times with different random choices (seeds)
    /// and reports how many runs found every root, the check that no path jumped.
    #[command(
        after_help = "Examples:\n  kinsyn solve examples/systems/cyclic5.bertini\n  kinsyn solve examples/systems/katsura5.bertini --show all --json > roots.json\n  kinsyn solve examples/systems/circle-line.bertini --runs 8\n  kinsyn solve system.bertini --start multi-homogeneous --threads 1"
    )]
    Solve {
        /// A Bertini input file, e.g. examples/systems/cyclic5.bertini.
        file: PathBuf,
        /// The start system: auto (whichever of the others has the fewest paths, named in the
        /// report), total-degree (Bézout's number of paths), multi-homogeneous (products of
        /// linear forms per `variable_group`: fewer paths when the equations have low degree in
        /// each group) or polyhedral (the mixed volume of the Newton polytopes: fewer paths for
        /// sparse systems, after a search for the mixed cells that auto bounds to 12 linear
        /// programs per path saved).
        #[arg(long, value_enum, default_value = "auto")]
        start: StartArg,
        /// Seed of every random choice (γ, patches, start forms): the same seed, the same paths.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Solve this many times with seeds seed, seed+1, … and report how many runs found
        /// every root (1 to 64).
        #[arg(long, default_value_t = 1)]
        runs: usize,
        /// Worker threads for the paths (default: one per core).
        #[arg(long)]
        threads: Option<usize>,
        /// Refuse a start system with more paths than this, before tracking any (per run); a
        /// path in n > 12 unknowns counts ⌈(n/12)³⌉ times, its cost growing as the cube of the
        /// unknowns. The default is at most a few minutes on two cores; at most 1048576 (2^20).
        /// Systems of more than 100 unknowns are refused whatever this says (docs/limits.md).
        #[arg(long, value_name = "N", default_value_t = kinsyn::homotopy::DEFAULT_MAX_PATHS,
              value_parser = clap::value_parser!(u64).range(1..=kinsyn::homotopy::MAX_PATHS))]
        max_paths: u64,
        /// Which solutions to list: real (the real non-singular ones), all (every finite one),
        /// none.
        #[arg(long, value_enum, default_value = "real")]
        show: ShowArg,
        /// Skip the Krawczyk certificates.
        #[arg(long)]
        no_certify: bool,
        /// Print JSON instead of text (every finite solution).
        #[arg(long)]
        json: bool,
        /// Track only shard K of N of the paths (K is 1-based: the paths k with k mod N = K − 1)
        /// and write their ends to --out, for --merge to finish: a solve spread over processes
        /// or machines (docs/scale.md). --max-paths then applies to the shard's share.
        #[arg(long, value_name = "K/N", requires = "out", conflicts_with_all = ["merge", "show"])]
        shard: Option<String>,
        /// The shard file --shard writes (JSON; whole or not at all).
        #[arg(long, value_name = "PART", requires = "shard")]
        out: Option<PathBuf>,
        /// Replace the file --out names if it exists.
        #[arg(long, requires = "out")]
        force: bool,
        /// Finish a solve from the shard files of --shard 1/N … N/N (any order, each once, of
        /// the same FILE, --start, --seed and kinsyn version): the report of one process,
        /// path for path.
        #[arg(long, value_name = "PART", num_args = 1..)]
        merge: Vec<PathBuf>,
    },
    /// The irreducible components of a polynomial system or of a manipulator's constraints:
    /// assemblies, self-motions and operation modes, by numerical irreducible decomposition.
    ///
    /// FILE is a Bertini input file (any number of equations and unknowns: the components of
    /// every dimension are found, each with its degree and a point) or a manipulator file whose
    /// legs are of a kind with a polynomial form (S–S, R–S, planar and spherical dyads, RPS,
    /// RUU and more; several bodies as a body tree; docs/position-analysis.md). For a
    /// manipulator the unknowns are the Study parameters of the platform (normalised, so each
    /// pose appears twice as ±(x, y)) and the joints that join bodies: at fixed inputs
    /// (--inputs, default the reference values) the components are the assemblies (dimension 0)
    /// and the self-motions (positive dimension: the platform moves while every input is
    /// held); each real assembly is reported with its operation mode — the dof and the motion
    /// pattern of the platform with the inputs released (e.g. X(z), a Schönflies motion). With
    /// --free-inputs (or --free for some) the inputs are unknowns too and the components are
    /// the operation modes over input and pose space, their dimension the dof. On each
    /// component with a real point the legs reach, the whole mechanism is placed: the
    /// end-effector's motion (or --body's) with the held inputs locked, and which inputs move.
    /// By-dimension (the default) solves a sliced system per dimension; regeneration brings the
    /// equations in one at a time (docs/operation-modes.md).
    #[command(
        after_help = "Examples:\n  kinsyn components mechanisms/4-ruu.json --inputs 'R1.1=17,R2.1=-11,R3.1=14,R4.1=6'\n  kinsyn components mechanisms/3-prrr.json --free-inputs\n  kinsyn components mechanisms/3-rps.json --free P1.2 --inputs 'P2.2=0.1,P3.2=-0.1'\n  kinsyn components mechanisms/4-ruu.json --inputs 'R1.1=107.19,R2.1=17.19,R3.1=-72.81,R4.1=17.19'\n  kinsyn components examples/systems/twisted-cubic-and-line.bertini --json"
    )]
    Components {
        /// A Bertini input file or a manipulator file.
        file: PathBuf,
        /// Input values of a manipulator (as for analyze: joint values from the reference,
        /// angles in the file's unit), e.g. 'R1.1=10,R2.1=-5'; inputs not named are held at
        /// their reference values.
        #[arg(long, allow_hyphen_values = true)]
        inputs: Option<String>,
        /// Every input of the manipulator an unknown: the operation modes over input and pose
        /// space (much larger systems: minutes where fixed inputs take a second; the 4-RUU's
        /// needs --max-paths 700000 with --method regeneration).
        #[arg(long)]
        free_inputs: bool,
        /// Some inputs of the manipulator unknowns, e.g. 'R1.1,R3.1': the operation modes with
        /// the others held (at --inputs, or their reference values).
        #[arg(long, value_name = "LABELS", conflicts_with = "free_inputs")]
        free: Option<String>,
        /// The body whose motion is classified on each component (default: the
        /// end-effector).
        #[arg(long, value_name = "NAME")]
        body: Option<String>,
        /// The algorithm: by-dimension (a sliced system per dimension; robust) or regeneration
        /// (equation by equation; fewer paths on large systems such as --free-inputs, but it
        /// can lose components at special inputs — a warning then lists unresolved points).
        #[arg(long, value_enum, default_value = "by-dimension")]
        method: MethodArg,
        /// Seed of every random choice (slices, randomisations, loops).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// The most paths to track in all. The start systems' paths are estimated from the
        /// degrees before any is tracked (by dimension: the Bézout numbers of the sliced
        /// systems; regeneration: Σ 2·e1⋯em over the equations by increasing degree), and a
        /// system estimated beyond this is refused; monodromy loops and membership tests then
        /// track more, within the same limit. A path in n > 12 unknowns counts ⌈(n/12)³⌉
        /// times. The default is at most a few minutes on two cores; at most 4194304 (2^22):
        /// --free-inputs on the 4-RUU needs 700000 with --method regeneration. Systems of more
        /// than 32 unknowns or 128 equations are refused whatever this says (docs/limits.md).
        #[arg(long, value_name = "N", default_value_t = kinsyn::homotopy::DEFAULT_DECOMPOSE_PATHS,
              value_parser = clap::value_parser!(u64).range(1..=kinsyn::homotopy::MAX_DECOMPOSE_PATHS))]
        max_paths: u64,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Paper 003's planar 4-RRR with a configurable platform by the paper's formulas: inverse
    /// and forward position, velocities by screw theory (geometry of §5; angles in degrees).
    #[command(subcommand)]
    Configurable(ConfigurableCommand),
    /// Figures of the papers drawn by kinsyn (SVG, and PNG for paper 001).
    #[command(subcommand)]
    Plot(PlotCommand),
    /// Write a series-parallel stack of three-legged modules (paper 002) as a description file.
    ///
    /// Equilateral platforms joined in series, each module a 3-RPS (revolutes on its lower
    /// platform) or a 3-SPR (revolutes on its upper one), with the frames of paper 002 §2 and
    /// revolute axes tangent to the circumcircles; the prismatic joints are the inputs. Each
    /// module's reference pose is generic and assembled (a chosen tilt, its in-plane
    /// coordinates solved by Newton). `kinsyn analyze` on the file compares the paper's Jacobian
    /// with the loop closure.
    #[command(
        after_help = "Examples:\n  kinsyn stack --modules RPS,SPR --radii 2,1,2 --heights=-1.5,-1.6   # paper 002's S-PM\n  kinsyn stack --modules RPS,SPR,RPS --radii 2,1,2,1 --heights=-1.5,-1.6,-1.4 -o stack.json"
    )]
    Stack {
        /// The modules from the ground up, each RPS or SPR.
        #[arg(long, value_delimiter = ',', required = true)]
        modules: Vec<String>,
        /// The platforms' circum-radii, the base first (one more than the modules).
        #[arg(long, value_delimiter = ',', required = true)]
        radii: Vec<f64>,
        /// Each module's height, upper platform over lower along the lower normal (negative:
        /// below, as in paper 002's Table 1).
        #[arg(
            long,
            value_delimiter = ',',
            allow_negative_numbers = true,
            required = true
        )]
        heights: Vec<f64>,
        /// Write to this file instead of standard output (its folder must exist; an existing
        /// file is refused unless --force).
        #[arg(long, short)]
        output: Option<PathBuf>,
        #[command(flatten)]
        force: Force,
    },
    /// The catalogue-wide multioperation sweep as files (docs/sweep.md): every verified chain
    /// as the legs of a symmetric manipulator, every choice of actuated joints per leg, every
    /// lock subset of the inputs sampled, one row per design.
    ///
    /// DIR gets designs.jsonl and designs.parquet (one row per design, by design index) and
    /// sweep.json (the settings, selection and shard). Each finished row is appended at once to
    /// DIR/checkpoint.jsonl, so an interrupted run resumes where it stopped when run again with
    /// the same options. --shard K/N evaluates every N-th design; `kinsyn sweep merge` joins
    /// the N shard directories into the files of one run.
    #[command(
        args_conflicts_with_subcommands = true,
        subcommand_negates_reqs = true,
        after_help = "Examples:\n  kinsyn sweep --out sweep\n  kinsyn sweep --out small --chains T1-001,T4-034 --actuated 1 --bench\n  kinsyn sweep --out part1 --shard 1/2   # and --out part2 --shard 2/2 elsewhere\n  kinsyn sweep merge part1 part2 --out sweep"
    )]
    Sweep {
        #[command(flatten)]
        run: SweepArgs,
        #[command(subcommand)]
        command: Option<SweepCommand>,
    },
    /// Write a 3D view of a manipulator: one self-contained HTML page (docs/view.md).
    ///
    /// The page draws the mechanism (bodies, joints by type, inputs in orange, the end-effector
    /// in green) with orbit and zoom, a slider per input (that input swept with the others
    /// held), the operation modes reached by locking inputs (choose one to animate its
    /// motion), and every real assembly at the inputs. kinsyn computes every configuration
    /// before writing the page; it needs no network and no server.
    #[command(
        after_help = "Examples:\n  kinsyn view mechanisms/3-ups.json --out 3-ups.html\n  kinsyn view mechanisms/6-ups.json --out 6-ups.html --inputs 'P1.3=0.05,P2.3=0.02' --steps 24\n  kinsyn view mechanisms/6-ruu-hexa.json --out hexa.html --no-assemblies\n  kinsyn view mechanisms/4-ruu.json --out 4-ruu.html --inputs 'R1.1=180,R2.1=0,R3.1=-90,R4.1=90' --components"
    )]
    View {
        /// The manipulator description (kinsyn-manipulator/1 or /2).
        file: PathBuf,
        /// Write the page to this file (its folder must exist; an existing file is refused
        /// unless --force).
        #[arg(long)]
        out: PathBuf,
        /// The input values of the configuration shown first, as `LABEL=VALUE` pairs in the
        /// description's units (the others at their reference values); the reference
        /// configuration when absent.
        #[arg(long)]
        inputs: Option<String>,
        /// Steps to either side of each input's sweep (30° for a revolute, a fifth of the
        /// characteristic length for a slider) and of each mode's motion; 1 to 200.
        #[arg(long, default_value_t = 16)]
        steps: usize,
        /// Do not solve for every assembly at the inputs (the global analysis).
        #[arg(long)]
        no_assemblies: bool,
        /// Add the operation modes and self-motions of the global decomposition (as `kinsyn
        /// components`): each component with a real point is animated from there, its held
        /// inputs locked.
        #[arg(long)]
        components: bool,
        /// With --components: every input an unknown (the modes over input and pose space).
        #[arg(long, requires = "components", conflicts_with = "inputs")]
        free_inputs: bool,
        /// With --components: the most paths the decomposition may track.
        #[arg(long, requires = "components", default_value_t = kinsyn::homotopy::DEFAULT_DECOMPOSE_PATHS)]
        max_paths: u64,
        /// Seed of the sampled modes and of the assembly solve.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Print what the page holds as JSON instead of the summary line.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        force: Force,
    },
    /// Export a manipulator to a simulator or a kinematics library: a MuJoCo MJCF model, a
    /// URDF robot, or both (docs/export.md).
    ///
    /// The mechanism's spanning tree becomes nested bodies with hinge and slide joints. In the
    /// MJCF, each loop-closing joint is an equality constraint and each input a position servo
    /// whose ctrl is kinsyn's input value; qpos0 is the reference configuration, gravity is off.
    /// The URDF holds the tree only (continuous revolutes, prismatic joints with placeholder
    /// limits); its loop-closing joints are listed in a comment. Pinocchio reads both.
    #[command(
        after_help = "Examples:\n  kinsyn export mechanisms/6-ups.json --mjcf 6-ups.xml\n  kinsyn export mechanisms/6-ups.json --urdf 6-ups.urdf\n  kinsyn export mechanisms/3-rps.json --mjcf 3-rps.xml --urdf 3-rps.urdf --force",
        group(clap::ArgGroup::new("model").required(true).multiple(true).args(["mjcf", "urdf"]))
    )]
    Export {
        /// The manipulator description (kinsyn-manipulator/1 or /2).
        file: PathBuf,
        /// Write the MuJoCo model (MJCF XML) to this file (its folder must exist; an existing
        /// file is refused unless --force).
        #[arg(long)]
        mjcf: Option<PathBuf>,
        /// Write the spanning tree as a URDF robot to this file (its folder must exist; an
        /// existing file is refused unless --force).
        #[arg(long)]
        urdf: Option<PathBuf>,
        #[command(flatten)]
        force: Force,
    },
}

/// The geometry and legs of `kinsyn build` (docs/mechanism-format.md).
#[derive(Debug, Args)]
pub(super) struct BuildArgs {
    /// Number of legs, 3 to 6.
    #[arg(long, default_value_t = 3)]
    pub(super) legs: usize,
    /// The leg: a catalogue id (T4-034) or a chain in notation, '!' marking inputs.
    #[arg(long)]
    pub(super) chain: String,
    /// Axis letters x, y, z per primitive joint in the leg frame (default: the catalogue's).
    #[arg(long)]
    pub(super) axes: Option<String>,
    /// Actuated primitive joints, 1-based, comma separated (instead of '!' marks).
    #[arg(long, value_delimiter = ',')]
    pub(super) actuated: Option<Vec<usize>>,
    /// Radius of the base circle.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub(super) base_radius: f64,
    /// Radius of the platform circle.
    #[arg(long, default_value_t = 0.5, allow_hyphen_values = true)]
    pub(super) platform_radius: f64,
    /// Height of the platform above the base.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub(super) height: f64,
    /// Degrees each platform point is turned from its leg's base point about the vertical.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub(super) twist: f64,
    /// Turn legs 2, 4, 6 the other way: pairs the platform points of a six-legged
    /// Gough–Stewart platform (the regular-hexagon form is singular everywhere).
    #[arg(long)]
    pub(super) alternate: bool,
    /// The manipulator's name (default n-LETTERS).
    #[arg(long)]
    pub(super) name: Option<String>,
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

/// How finite motion is sampled (seeded, reproducible).
#[derive(Debug, Args)]
pub(super) struct Sampling {
    /// Seed of the random walks (continuous random step lengths and directions).
    #[arg(long, default_value_t = 2026)]
    pub(super) seed: u64,
    /// Configurations sampled per motion, 2 to 64: a group is recognised by its twist space
    /// staying the same at samples at least 1e-3 apart; each sample is a random walk, so a
    /// subset's cost grows in proportion.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u16).range(2..=i64::from(super::manipulator::MAX_SAMPLES)))]
    pub(super) samples: u16,
}

impl Sampling {
    pub(super) fn settings(&self) -> kinsyn::mechanism::SampleSettings {
        kinsyn::mechanism::SampleSettings {
            seed: self.seed,
            samples: usize::from(self.samples),
            ..Default::default()
        }
    }
}

#[derive(Debug, Subcommand)]
pub(super) enum CatalogueCommand {
    /// Enumerate the chains and write chains.json, chains.csv and README.md.
    ///
    /// The files are byte-for-byte reproducible; the committed catalogue/ is what this writes
    /// with the default reading.
    Generate {
        /// Folder to write into (created if missing, not its parent; the committed catalogue/
        /// is replaced only with --force).
        #[arg(long, default_value = "catalogue")]
        out: PathBuf,
        #[command(flatten)]
        force: Force,
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
    /// Write a static, browsable site of the catalogue: an index with filters (pattern, family,
    /// lock count: `kinsyn query`'s rows), and a page per entry with its lock table and a
    /// schematic of its chain. No server or network needed: open DIR/index.html.
    Site {
        /// Folder to write into (created if missing, not its parent).
        #[arg(long)]
        out: PathBuf,
        #[command(flatten)]
        force: Force,
        #[command(flatten)]
        reading: Reading,
    },
    /// The entries the numerical check rejects (no reading of the notation is 3T3R), with rank,
    /// singular values, idle joints and readings tried; then the entries verified with another
    /// reading than their first (the tables kept in docs/deviations.md).
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

/// `--force` of the commands that write files (docs/limits.md, "Output files").
#[derive(Debug, Clone, Copy, Args)]
pub struct Force {
    /// Replace output files that exist (each written whole, then renamed over the old one; a
    /// symbolic link there is replaced, never followed). Without it an existing file is
    /// refused before anything is written.
    #[arg(long)]
    pub force: bool,
}

/// The options of the paper reading (docs/synthesis.md).
#[derive(Debug, Args)]
pub(super) struct Reading {
    /// How far apart two parallel prismatic guides may be: 'separated' (default: allowed when
    /// a revolute not parallel to them lies between them) or 'perpendicular' (never parallel).
    #[arg(long, value_enum, default_value_t = PrismaticsArg::Separated)]
    pub(super) prismatics: PrismaticsArg,
    /// Do not apply §2.3's "three parallel R need a guide along them" to chains with a P.
    #[arg(long)]
    pub(super) no_triple_guide: bool,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub(super) enum PrismaticsArg {
    Separated,
    Perpendicular,
}

/// `--method` of `kinsyn components`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(super) enum MethodArg {
    /// Equation-by-equation regeneration.
    Regeneration,
    /// A sliced system per dimension.
    ByDimension,
}

impl From<MethodArg> for kinsyn::manipulator::DecompositionMethod {
    fn from(m: MethodArg) -> Self {
        match m {
            MethodArg::Regeneration => Self::Regeneration,
            MethodArg::ByDimension => Self::ByDimension,
        }
    }
}

/// `--show` of `kinsyn solve`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(super) enum ShowArg {
    /// Every finite solution.
    All,
    /// The real non-singular ones.
    Real,
    /// None: the counts only.
    None,
}

impl From<ShowArg> for kinsyn_report::solve::Show {
    fn from(s: ShowArg) -> Self {
        match s {
            ShowArg::All => Self::All,
            ShowArg::Real => Self::Real,
            ShowArg::None => Self::None,
        }
    }
}

/// `--start` of `kinsyn solve`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(super) enum StartArg {
    /// The fewest paths of the four below.
    Auto,
    /// Bézout's number of paths.
    TotalDegree,
    /// The multi-homogeneous Bézout number of paths, for the file's variable groups.
    MultiHomogeneous,
    /// One random linear factor per slot of the set structure of the file's variable groups:
    /// fewer paths than multi-homogeneous when an equation is dense in several groups.
    LinearProduct,
    /// The mixed volume's number of paths (the BKK bound): fewest for sparse systems.
    Polyhedral,
}

impl From<StartArg> for kinsyn::homotopy::StartSystem {
    fn from(s: StartArg) -> Self {
        match s {
            StartArg::TotalDegree => Self::TotalDegree,
            StartArg::MultiHomogeneous => Self::MultiHomogeneous,
            StartArg::LinearProduct => Self::LinearProduct,
            StartArg::Polyhedral => Self::Polyhedral,
            StartArg::Auto => Self::Auto,
        }
    }
}

/// `kinsyn plot …`.
#[derive(Debug, clap::Subcommand)]
pub(super) enum PlotCommand {
    /// Paper 003's inverse position drawn: every input set of a platform pose, one panel each
    /// (like Fig. 9); default §5's example.
    #[command(after_help = "Example:\n  kinsyn plot inverse --out figures")]
    Inverse {
        /// The folder for inverse-configurations.svg (created if missing, not its parent).
        #[arg(long, default_value = ".")]
        out: PathBuf,
        #[command(flatten)]
        force: Force,
        /// The platform centre C = x,y (mm).
        #[arg(long, default_value = "20,-30", allow_hyphen_values = true)]
        centre: String,
        /// θ in degrees (eq. 11's sense).
        #[arg(long, default_value_t = 75.0, allow_hyphen_values = true)]
        theta: f64,
        /// φ in degrees (eq. 11's sense).
        #[arg(long, default_value_t = 100.0, allow_hyphen_values = true)]
        phi: f64,
    },
    /// Paper 001 (the HEXA with reconfigurable platforms), Fig. 3: the reachable workspaces of
    /// both end-effectors at constant orientations by a grid search, as three sections with the
    /// regular common workspace (the largest vertical cylinder on the z axis inside both), and
    /// the positions of end-effector 2 relative to end-effector 1 (the four-bar's coupler
    /// curve); DIR/hexa-workspace.svg/.png and DIR/hexa-four-bar.svg/.png.
    #[command(
        after_help = "Examples:\n  kinsyn plot workspace mechanisms/6-ruu-hexa.json --out figures\n  kinsyn plot workspace mechanisms/6-ruu-hexa.json --phi1 45 --phi2 -45 --step 20 --json"
    )]
    Workspace {
        #[command(flatten)]
        hexa: HexaPlot,
        /// The grid step in mm.
        #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
        step: f64,
        /// Print JSON (grid, volumes, cylinder) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Paper 001 (the HEXA), Fig. 4: the input index `λ_min` and the output indices σ and `ξ_min`
    /// over the regular common workspace at one height, end-effector 2 at the four-bar's
    /// nominal (symmetric) assembly; three banded maps as DIR/hexa-indices.svg/.png.
    #[command(
        after_help = "Examples:\n  kinsyn plot indices mechanisms/6-ruu-hexa.json --out figures\n  kinsyn plot indices mechanisms/6-ruu-hexa.json --phi1 45 --phi2 -45 --json"
    )]
    Indices {
        #[command(flatten)]
        hexa: HexaPlot,
        /// The height of the map in mm (default: the middle of the regular workspace).
        #[arg(long, allow_hyphen_values = true)]
        z: Option<f64>,
        /// The map's grid step in mm.
        #[arg(long, default_value_t = 5.0, allow_hyphen_values = true)]
        step: f64,
        /// The grid step in mm of the workspace search that finds the regular workspace.
        #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
        workspace_step: f64,
        /// Print JSON (cylinder, index statistics) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Paper 003 §5: the inputs' trajectory followed from Table 2's assembly by parameter
    /// homotopy; the corner speeds against time (like Fig. 12) as SVG, and where the followed
    /// assembly stops existing (a turning point, where it meets another assembly).
    #[command(after_help = "Example:\n  kinsyn plot trajectory --out figures")]
    Trajectory {
        /// The folder for trajectory-velocities.svg (created if missing, not its parent).
        #[arg(long, default_value = ".")]
        out: PathBuf,
        #[command(flatten)]
        force: Force,
        /// Instants over t in [0, 2π] (2 to 100000).
        #[arg(long, default_value_t = 2000)]
        steps: usize,
        /// Print JSON (every instant) instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// `kinsyn configurable …`.
#[derive(Debug, clap::Subcommand)]
pub(super) enum ConfigurableCommand {
    /// The input sets (two elbows per leg, up to 16) that put the platform at a pose (§3.2).
    #[command(
        after_help = "Examples:\n  kinsyn configurable inverse --centre 20,-30 --theta 75 --phi 100   # §5's example (eq. 11's θ, φ)\n  kinsyn configurable inverse --c4 25.112,-147.043 --theta 80 --phi 105   # the same platform (eq. 13's)"
    )]
    Inverse {
        /// The platform centre C = (x, y) mm, with θ, φ in eq. 11's sense.
        #[arg(long, allow_hyphen_values = true, conflicts_with = "c4")]
        centre: Option<String>,
        /// The corner C4 = (x, y) mm, with θ, φ the directions of C4→C1 and C4→C3 (eq. 13).
        #[arg(long, allow_hyphen_values = true)]
        c4: Option<String>,
        /// θ in degrees.
        #[arg(long, allow_hyphen_values = true)]
        theta: f64,
        /// φ in degrees.
        #[arg(long, allow_hyphen_values = true)]
        phi: f64,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Every assembly at the inputs (§3.2): method 1 or 2's equations solved by homotopy
    /// continuation, certified; the real assemblies listed.
    #[command(
        after_help = "Example:\n  kinsyn configurable forward --q 141.956,203.366,337.773,305.499   # §5: two real assemblies"
    )]
    Forward {
        /// q1, q2, q3, q4 in degrees.
        #[arg(long, allow_hyphen_values = true)]
        q: String,
        /// 1: unknowns w1..w6 (eqs. 1-5, 10); 2: x4, y4 and the sines and cosines of θ, φ (eqs. 12-15).
        #[arg(long, default_value_t = 2)]
        method: u8,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The corner velocities by screw theory (§4) at the assembly nearest a pose.
    #[command(
        after_help = "Example:\n  kinsyn configurable velocity --q 141.956,203.366,337.773,305.499 --qdot=-1.5,-1.25,-2,1.5"
    )]
    Velocity {
        /// q1, q2, q3, q4 in degrees.
        #[arg(long, allow_hyphen_values = true)]
        q: String,
        /// q̇1, q̇2, q̇3, q̇4 in rad/s.
        #[arg(long, allow_hyphen_values = true)]
        qdot: String,
        /// The assembly nearest C4x,C4y,θ,φ (mm, degrees; eq. 13); default Table 1's.
        #[arg(long, allow_hyphen_values = true)]
        near: Option<String>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// What both paper 001 figures take: the HEXA's file, the output folder, the orientations.
#[derive(Debug, Args)]
pub struct HexaPlot {
    /// The HEXA's description, mechanisms/6-ruu-hexa.json or another written by
    /// `Hexa::description` (its dimensions are read from it; docs/hexa.md).
    pub file: PathBuf,
    /// The folder for the figures (created if missing, not its parent).
    #[arg(long, default_value = ".")]
    pub out: PathBuf,
    #[command(flatten)]
    pub force: Force,
    /// φ1, end-effector 1's turn about z, in degrees (-180 to 180).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub phi1: f64,
    /// φ2, end-effector 2's turn about z, in degrees (-180 to 180).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub phi2: f64,
}

/// The options of `kinsyn sweep` (docs/sweep.md).
#[derive(Debug, Args)]
pub(super) struct SweepArgs {
    /// The directory of the results (created if missing, not its parent; an interrupted run
    /// of the same sweep there is resumed, with or without --force).
    #[arg(long, value_name = "DIR", required = true)]
    pub(super) out: Option<PathBuf>,
    /// Replace the files of another sweep, or of none, that DIR holds (the sweep then starts
    /// afresh there); the same sweep is resumed or left complete, never discarded.
    #[arg(long)]
    pub(super) force: bool,
    /// Legs of every manipulator, 3 to 6.
    #[arg(long, default_value_t = 3)]
    pub(super) legs: usize,
    /// The numbers of actuated joints per leg tried, e.g. 1,2 (each set of that many of the 6
    /// joints is a design).
    #[arg(long, value_delimiter = ',', default_value = "1,2")]
    pub(super) actuated: Vec<usize>,
    /// Seed of the sampled motions (each lock subset's walk derives its own from it).
    #[arg(long, default_value_t = kinsyn::mechanism::SampleSettings::default().seed)]
    pub(super) seed: u64,
    /// Only these catalogue chains, by id, e.g. T1-001,T4-034.
    #[arg(long, value_name = "LIST")]
    pub(super) chains: Option<String>,
    /// Only chains of this family: PPPRRR, PPRRRR, PRRRRR or RRRRRR.
    #[arg(long)]
    pub(super) family: Option<String>,
    /// Only shard K of N (1-based): the designs i with (i mod N) + 1 = K.
    #[arg(long, value_name = "K/N")]
    pub(super) shard: Option<String>,
    /// Worker threads (default: one per core).
    #[arg(long)]
    pub(super) threads: Option<usize>,
    /// After the run, print its figures: designs, lock subsets, wall seconds, designs/s,
    /// subsets per core-second, threads, writing time.
    #[arg(long)]
    pub(super) bench: bool,
    /// Print a JSON summary instead of text.
    #[arg(long)]
    pub(super) json: bool,
    /// Stop as an interruption would once this many rows are checkpointed (for tests).
    #[arg(long, hide = true, value_name = "N")]
    pub(super) stop_after: Option<usize>,
}

/// `kinsyn sweep …`.
#[derive(Debug, Subcommand)]
pub(super) enum SweepCommand {
    /// Join the shard directories of one sweep (same options, shards 1/N to N/N each once,
    /// each complete) into OUT: the same files as one run of the whole sweep.
    #[command(after_help = "Example:\n  kinsyn sweep merge part1 part2 part3 --out sweep")]
    Merge {
        /// The shard directories.
        #[arg(required = true, value_name = "DIR")]
        dirs: Vec<PathBuf>,
        /// The directory of the merged results (created if missing, not its parent).
        #[arg(long, value_name = "OUT")]
        out: PathBuf,
        #[command(flatten)]
        force: Force,
        /// Print the merged manifest as JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Rank a sweep's designs by multioperation capacity (group kinds reached, then distinct
    /// subgroups) against inputs: the Pareto front, the best designs per number of inputs with
    /// a minimal lock set for each kind, their legs, capacity per family; report.md with two
    /// figures (SVG and PNG).
    #[command(
        after_help = "Examples:\n  kinsyn sweep report results/\n  kinsyn sweep report results/designs.jsonl --top 10 --out ranking"
    )]
    Report(ReportArgs),
}

/// The most best designs `--top` keeps per number of inputs.
pub const MAX_TOP: usize = 1000;

/// `kinsyn sweep report`'s arguments.
#[derive(Debug, clap::Args)]
pub(super) struct ReportArgs {
    /// A sweep's results: its folder (designs.jsonl is read there, and the settings from
    /// sweep.json when present) or a .jsonl file of design rows.
    pub(super) results: PathBuf,
    /// The folder for report.md and the figures (created if missing, not its parent).
    /// Default: report/ in the results folder (beside the .jsonl file when a file is given).
    #[arg(long, value_name = "DIR")]
    pub(super) out: Option<PathBuf>,
    #[command(flatten)]
    pub(super) force: Force,
    /// The best designs kept per number of inputs.
    #[arg(long, value_name = "K", default_value_t = 5,
          value_parser = clap::value_parser!(u32).range(1..=MAX_TOP as i64))]
    pub(super) top: u32,
    /// Print the ranking as JSON instead of the text summary.
    #[arg(long)]
    pub(super) json: bool,
}
