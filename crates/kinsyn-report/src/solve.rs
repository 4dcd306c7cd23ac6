//! `kinsyn solve`: every isolated solution of a polynomial system in a Bertini input file, by
//! homotopy continuation, certified.

use crate::{Error, terminal};
use kinsyn::certify::Reality;
use kinsyn::homotopy::{self, RunsReport, Solution, SolveSettings, StartSystem};
use kinsyn::poly::{C64, System, bertini};
use serde::Serialize;
use std::path::Path;

/// Which solutions the text lists.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Show {
    /// Every finite solution.
    All,
    /// The real non-singular ones.
    Real,
    /// None: the counts only.
    None,
}

/// How `kinsyn solve` runs.
#[derive(Debug, Clone)]
pub struct SolveOptions {
    /// The start system.
    pub start: StartSystem,
    /// The first seed.
    pub seed: u64,
    /// Independent runs (seeds `seed, seed + 1, …`).
    pub runs: usize,
    /// Worker threads (`None`: one per core).
    pub threads: Option<usize>,
    /// The most paths of a run (`--max-paths`; [`homotopy::DEFAULT_MAX_PATHS`] by default, at
    /// most [`homotopy::MAX_PATHS`]).
    pub max_paths: u64,
    /// Certify the regular solutions.
    pub certify: bool,
    /// Which solutions the text lists.
    pub show: Show,
}

/// The most independent runs `--runs` takes.
pub const MAX_RUNS: usize = 64;

/// The most threads `--threads` takes.
pub const MAX_THREADS: usize = 256;

/// What a file that is not a Bertini input file is, in refusals.
const NOT_BERTINI: &str = "not a Bertini input file";

/// Reads a Bertini input file; errors name the file and the line.
///
/// # Errors
/// [`Error::Input`] for a file that is not a readable Bertini input within the limits.
pub fn read_input(path: &Path) -> Result<bertini::BertiniInput, Error> {
    let text = crate::files::read_text(path, NOT_BERTINI)?;
    parse_input(&text, &path.display().to_string())
}

/// The system of the Bertini input `text`; errors name `source` and the line.
fn parse_input(text: &str, source: &str) -> Result<bertini::BertiniInput, Error> {
    if !text.lines().any(|l| {
        l.split('%')
            .next()
            .is_some_and(|code| code.trim_start().starts_with("INPUT"))
    }) {
        return Err(Error::Input(format!(
            "{source} is {NOT_BERTINI} (no INPUT section)"
        )));
    }
    bertini::parse(text).map_err(|e| Error::Input(format!("{source}: {e}")))
}

/// `n word` or `n words`.
#[must_use]
pub fn count(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}

/// A path count as text: the number, or "more than 10^38" when it saturated (at `u128::MAX`).
#[must_use]
pub fn paths_text(n: u128) -> String {
    if n == u128::MAX {
        "more than 10^38".into()
    } else {
        n.to_string()
    }
}

/// The multi-homogeneous count as text: [`paths_text`], or "not counted" when the variable
/// groups are too many to count ([`kinsyn::poly::multihomogeneous::MAX_GROUP_STATES`]).
#[must_use]
pub fn multihomogeneous_text(system: &System) -> String {
    system
        .multihomogeneous_bezout()
        .map_or_else(|| "not counted".into(), paths_text)
}

/// The linear-product count as text ([`kinsyn::poly::linear_product`]): [`paths_text`], or
/// "not counted" when its choices are too many to walk.
#[must_use]
pub fn linear_product_text(system: &System) -> String {
    kinsyn::poly::linear_product::SetStructure::of(system)
        .count()
        .map_or_else(|| "not counted".into(), paths_text)
}

/// `N paths`, and when each path of a system in `unknowns` unknowns counts `weight` times
/// against the limit ([`homotopy::path_weight`]), what they count in all.
pub(crate) fn weighted_paths(paths: u128, weight: u64, unknowns: usize) -> String {
    if weight == 1 {
        format!("{} paths", paths_text(paths))
    } else {
        format!(
            "{} paths in {unknowns} unknowns, each counting {weight} times (a path's cost grows as the cube of the unknowns beyond {}): {} in all",
            paths_text(paths),
            homotopy::PATH_WEIGHT_UNKNOWNS,
            paths_text(paths.saturating_mul(u128::from(weight)))
        )
    }
}

/// How a refusal names the option that raises the path limit: `kinsyn solve`'s `--max-paths`,
/// or nothing where the command has no such option (`analyze --all-assemblies`, which keeps the
/// default).
#[derive(Clone, Copy)]
pub enum PathOption {
    /// `--max-paths` raises the limit.
    MaxPaths,
    /// The default limit holds.
    Default,
}

/// The cost of a solve, decided before any path is tracked: the library's checks
/// ([`homotopy::check_solvable`]: unknowns, constant equations, the start system's paths against
/// `settings.max_paths`) as one line that names `source`, the number and the limit, and the
/// option that raises it. The paths of one run if it may go ahead.
///
/// # Errors
/// [`Error::Input`] for a system the library refuses (too many unknowns, a constant equation,
/// coefficients beyond double precision) or whose paths exceed the limit, naming the estimate
/// and the limit.
pub fn check_cost(
    source: &str,
    system: &System,
    settings: &SolveSettings,
    option: PathOption,
) -> Result<u128, Error> {
    homotopy::check_solvable(system, settings).map_err(|e| {
        Error::Input(match e {
            homotopy::HomotopyError::TooManyPaths {
                paths,
                weight,
                limit,
            } => {
                let hint = match settings.start {
                    StartSystem::TotalDegree => system
                        .multihomogeneous_bezout()
                        .filter(|m| *m < paths && *m <= u128::from(homotopy::MAX_PATHS))
                        .map(|m| {
                            format!("; --start multi-homogeneous needs {m} for these variable groups")
                        })
                        .unwrap_or_default(),
                    StartSystem::MultiHomogeneous
                    | StartSystem::LinearProduct
                    | StartSystem::Polyhedral
                    | StartSystem::Auto => String::new(),
                };
                let raise = match option {
                    PathOption::MaxPaths if limit < homotopy::MAX_PATHS => format!(
                        "more than --max-paths {limit}: raise it (at most {} = 2^20)",
                        homotopy::MAX_PATHS
                    ),
                    PathOption::MaxPaths => format!(
                        "more than the limit of {limit} (2^20), the most --max-paths takes"
                    ),
                    PathOption::Default => format!("more than the limit of {limit}"),
                };
                let start = homotopy::resolve_start(system, settings.start, settings.seed)
                    .map_or(settings.start, |(s, _)| s);
                format!(
                    "{source}: the {} start system has {}, {raise}{hint}",
                    start.name(),
                    weighted_paths(paths, weight, system.nvars())
                )
            }
            homotopy::HomotopyError::TooManyUnknowns { unknowns } => format!(
                "{source}: {unknowns} unknowns: homotopy continuation here takes at most {} (a hard limit: each step factors the Jacobian; docs/limits.md)",
                homotopy::MAX_UNKNOWNS
            ),
            homotopy::HomotopyError::TooManyGroups { groups } => format!(
                "{source}: {groups} variable groups are too many to count the multi-homogeneous start solutions (at most {} states, docs/limits.md): use --start total-degree",
                kinsyn::poly::multihomogeneous::MAX_GROUP_STATES
            ),
            other => format!("{source}: {other}"),
        })
    })
}

/// Refuses, naming the file and the equation, a system homotopy continuation cannot solve:
/// not square, an equation that is a constant (no solution, or no isolated one if zero), a
/// coefficient that overflowed double precision. The cost is checked next ([`check_cost`]).
pub(crate) fn check_solvable(file: &str, input: &bertini::BertiniInput) -> Result<(), Error> {
    let system = &input.system;
    let (equations, variables) = (system.len(), system.nvars());
    if equations != variables {
        return Err(Error::Input(format!(
            "{file}: {} in {}: {} equations than variables; kinsyn solve needs a square system (as many equations as variables)",
            count(equations, "equation"),
            count(variables, "variable"),
            if equations > variables {
                "more"
            } else {
                "fewer"
            }
        )));
    }
    let name = |i: usize| {
        input
            .functions
            .get(i)
            .map_or_else(|| (i + 1).to_string(), Clone::clone)
    };
    for (i, p) in system.equations().iter().enumerate() {
        if p.total_degree() == 0 {
            let value = p.terms().map(|(_, c)| c).sum::<C64>();
            return Err(Error::Input(if value == C64::new(0.0, 0.0) {
                format!(
                    "{file}: equation {} is identically zero: the solutions are not isolated",
                    name(i)
                )
            } else {
                format!(
                    "{file}: equation {} is the non-zero constant {}: the system has no solution",
                    name(i),
                    if value.im == 0.0 {
                        value.re.to_string()
                    } else {
                        complex_text(value)
                    }
                )
            }));
        }
        if p.terms()
            .any(|(_, c)| !(c.re.is_finite() && c.im.is_finite()))
        {
            return Err(Error::Input(format!(
                "{file}: equation {} has a coefficient beyond the range of double precision (its expansion overflows)",
                name(i)
            )));
        }
    }
    Ok(())
}

/// Runs `work` on a pool of `threads` workers (all cores when `None`).
///
/// # Errors
/// [`Error::Input`] for a thread count of 0 or above [`MAX_THREADS`]; [`Error::Internal`] when the pool cannot start.
pub fn with_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, Error> {
    match threads {
        None => Ok(work()),
        Some(n) if n == 0 || n > MAX_THREADS => Err(Error::Input(format!(
            "--threads {n}: give 1 to {MAX_THREADS}"
        ))),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map(|pool| pool.install(work))
            .map_err(|e| Error::Internal(format!("cannot start {n} threads: {e}"))),
    }
}

/// Solves with a progress bar over the paths (shown only on a terminal), after the cost is
/// checked ([`check_cost`], the refusal naming `source` and `option`).
///
/// # Errors
/// [`Error::Input`] when the system cannot be solved as asked (its refusal in words).
pub fn solve_with_bar(
    source: &str,
    system: &System,
    settings: &SolveSettings,
    runs: usize,
    option: PathOption,
) -> Result<RunsReport, Error> {
    let paths = check_cost(source, system, settings, option)?;
    let paths = usize::try_from(paths).unwrap_or(usize::MAX);
    let bar = terminal::progress(paths.saturating_mul(runs), "paths", "solve");
    let mut reports = Vec::with_capacity(runs);
    for k in 0..runs as u64 {
        let s = SolveSettings {
            seed: settings.seed.wrapping_add(k),
            ..settings.clone()
        };
        let report = homotopy::solve_with_progress(system, &s, &|| bar.inc(1))
            .map_err(|e| Error::Input(e.to_string()))?;
        reports.push(report);
    }
    bar.finish_and_clear();
    Ok(homotopy::combine_runs(reports))
}

/// `kinsyn solve FILE`: the system of the Bertini input file at `path`, solved as `options`
/// say ([`solve_system`]).
///
/// # Errors
/// As [`read_input`], [`check_cost`] and [`solve_with_bar`].
pub fn solve(path: &Path, options: &SolveOptions) -> Result<Solved, Error> {
    let text = crate::files::read_text(path, NOT_BERTINI)?;
    solve_system(&text, &path.display().to_string(), options)
}

/// A system solved as `kinsyn solve` solves it.
pub struct Solved {
    /// The file's name, or what stands for it.
    pub source: String,
    /// The system solved.
    pub system: System,
    /// The options it was solved with.
    pub options: SolveOptions,
    /// The worker threads.
    pub threads: usize,
    /// Every run.
    pub runs: RunsReport,
}

/// Every isolated solution of the polynomial system of the Bertini input `text` (`source`
/// naming it in messages: the file's path, or `<string>`), by homotopy continuation, run as
/// `options` say. A progress bar over the paths is drawn on stderr when it is a terminal.
///
/// # Errors
///
/// [`Error::Input`]: options out of range (`--runs`, `--threads`), text that is not a
/// Bertini input, a system that is not square, has a constant equation or overflowing
/// coefficients or too many paths, or a solve that fails; [`Error::Internal`] when the
/// threads cannot be started.
pub fn solve_system(text: &str, source: &str, options: &SolveOptions) -> Result<Solved, Error> {
    if options.runs == 0 || options.runs > MAX_RUNS {
        return Err(Error::Input(format!(
            "--runs {}: give 1 to {MAX_RUNS}",
            options.runs
        )));
    }
    let input = parse_input(text, source)?;
    let settings = SolveSettings {
        seed: options.seed,
        start: options.start,
        certify: options.certify,
        max_paths: options.max_paths,
        ..SolveSettings::default()
    };
    check_solvable(source, &input)?;
    let system = input.system;
    let runs = with_threads(options.threads, || {
        solve_with_bar(
            source,
            &system,
            &settings,
            options.runs,
            PathOption::MaxPaths,
        )
    })??;
    let threads = options.threads.unwrap_or_else(rayon::current_num_threads);
    Ok(Solved {
        source: source.to_string(),
        system,
        options: options.clone(),
        threads,
        runs,
    })
}

impl Solved {
    /// The warnings of the solve, one line each, without the file's name: a multi-homogeneous
    /// start system asked for a system of one variable group.
    #[must_use]
    pub fn warnings(&self) -> Vec<String> {
        let grouped = matches!(
            self.options.start,
            StartSystem::MultiHomogeneous | StartSystem::LinearProduct
        );
        if grouped && self.system.groups().len() < 2 {
            vec![format!(
                "one variable group: the {} start system is the total-degree count",
                self.options.start.name()
            )]
        } else {
            Vec::new()
        }
    }

    /// The report of `kinsyn solve --json`.
    #[must_use]
    pub fn json(&self) -> impl Serialize + use<'_> {
        SolveJson::new(
            &self.source,
            &self.system,
            &self.options,
            self.threads,
            &self.runs,
        )
    }
}

/// A complex number as text: `1.2345678901` or `1.2345678901 - 0.5000000000i`.
#[must_use]
pub fn complex_text(c: C64) -> String {
    if c.im == 0.0 {
        format!("{:.10}", c.re)
    } else {
        format!(
            "{:.10} {} {:.10}i",
            c.re,
            if c.im < 0.0 { '-' } else { '+' },
            c.im.abs()
        )
    }
}

/// What a regular solution is known to be: `real`, `non-real` (both certified), or `real (not
/// proven)`, `complex (not proven)`.
#[must_use]
pub fn reality(s: &Solution) -> &'static str {
    match s.certificate.as_ref().map(|c| c.real) {
        Some(Reality::CertifiedReal) => "real",
        Some(Reality::CertifiedNonReal) => "non-real",
        _ if s.real => "real (not proven)",
        _ => "complex (not proven)",
    }
}

/// `kinsyn solve --json`.
#[derive(Serialize)]
struct SolveJson {
    file: String,
    variables: Vec<String>,
    equations: usize,
    bezout_number: String,
    multihomogeneous_bezout_number: String,
    /// The paths of the linear-product start for the variable groups.
    linear_product_paths: String,
    /// The start system tracked (`auto` resolved).
    start: StartSystem,
    /// The start system asked for (`auto` by default).
    start_asked: StartSystem,
    seed: u64,
    threads: usize,
    summary: String,
    paths: usize,
    nonsingular: usize,
    real: usize,
    singular: usize,
    at_infinity: usize,
    failed: usize,
    /// Whether every path ended: only then can the solutions be complete.
    complete: bool,
    certified: Option<usize>,
    certified_real: Option<usize>,
    retracked: usize,
    seconds: f64,
    solutions: Vec<SolutionJson>,
    runs: Vec<RunJson>,
    complete_fraction: f64,
}

#[derive(Serialize)]
struct SolutionJson {
    /// Coordinates as `[re, im]` pairs, in the variables' order.
    x: Vec<[f64; 2]>,
    regular: bool,
    real: bool,
    reality: &'static str,
    multiplicity: usize,
    residual: f64,
    certified: bool,
    certificate_radius: Option<f64>,
    paths: Vec<usize>,
}

#[derive(Serialize)]
struct RunJson {
    seed: u64,
    nonsingular: usize,
    complete: bool,
    seconds: f64,
}

impl SolveJson {
    fn new(
        path: &str,
        system: &System,
        options: &SolveOptions,
        threads: usize,
        runs: &RunsReport,
    ) -> Self {
        let r = &runs.runs[0];
        let solution = |s: &Solution| SolutionJson {
            x: s.x.iter().map(|c| [c.re, c.im]).collect(),
            regular: s.regular,
            real: s.real,
            reality: if s.regular { reality(s) } else { "singular" },
            multiplicity: s.multiplicity,
            residual: s.residual,
            certified: s.is_certified(),
            certificate_radius: s
                .certificate
                .as_ref()
                .and_then(kinsyn::certify::Certificate::radius),
            paths: s.paths.clone(),
        };
        Self {
            file: path.to_string(),
            variables: system.variables().to_vec(),
            equations: system.len(),
            bezout_number: paths_text(system.bezout_number()),
            multihomogeneous_bezout_number: multihomogeneous_text(system),
            linear_product_paths: linear_product_text(system),
            start: r.start,
            start_asked: options.start,
            seed: options.seed,
            threads,
            summary: r.summary(),
            paths: r.paths(),
            nonsingular: r.nonsingular(),
            real: r.real(),
            singular: r.singular(),
            at_infinity: r.at_infinity(),
            failed: r.failed(),
            complete: r.complete(),
            certified: options.certify.then(|| r.certified()),
            certified_real: options.certify.then(|| r.certified_real()),
            retracked: r.retracked,
            seconds: r.seconds,
            solutions: r.solutions.iter().map(solution).collect(),
            runs: runs
                .runs
                .iter()
                .zip(&runs.complete)
                .map(|(run, complete)| RunJson {
                    seed: run.seed,
                    nonsingular: run.nonsingular(),
                    complete: *complete,
                    seconds: run.seconds,
                })
                .collect(),
            complete_fraction: runs.complete_fraction(),
        }
    }
}
