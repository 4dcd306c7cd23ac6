//! `kinsyn solve`: every isolated solution of a polynomial system in Bertini's input format,
//! by homotopy continuation, certified; the report of `kinsyn solve --json`.

use crate::error::Error;
use crate::input::read_text;
use kinsyn::certify::Reality;
use kinsyn::homotopy::{self, RunsReport, Solution, SolveSettings, StartSystem};
use kinsyn::poly::{C64, System, bertini};
use pyo3::prelude::*;
use serde::Serialize;
use std::path::PathBuf;

/// The most independent runs `runs` takes.
const MAX_RUNS: usize = 64;

/// The most threads `threads` takes.
const MAX_THREADS: usize = 256;

/// How `kinsyn solve` runs.
struct SolveOptions {
    start: StartSystem,
    seed: u64,
    runs: usize,
    threads: Option<usize>,
    certify: bool,
}

/// The system of a Bertini input text; errors name `source` and the line.
fn read_input(text: &str, source: &str) -> Result<bertini::BertiniInput, Error> {
    const NOT_BERTINI: &str = "not a Bertini input file";
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

/// The start system named `text` (as `kinsyn solve --start`).
fn start_system(text: &str) -> Result<StartSystem, Error> {
    match text {
        "total-degree" => Ok(StartSystem::TotalDegree),
        "multi-homogeneous" => Ok(StartSystem::MultiHomogeneous),
        _ => Err(Error::Input(format!(
            "--start {text:?}: give total-degree or multi-homogeneous"
        ))),
    }
}

/// `kinsyn solve --json` for the system of `text`.
fn solve_text(text: &str, source: &str, options: &SolveOptions) -> Result<String, Error> {
    if options.runs == 0 || options.runs > MAX_RUNS {
        return Err(Error::Input(format!(
            "--runs {}: give 1 to {MAX_RUNS}",
            options.runs
        )));
    }
    let input = read_input(text, source)?;
    check_solvable(source, &input, options.start)?;
    let system = input.system;
    let settings = SolveSettings {
        seed: options.seed,
        start: options.start,
        certify: options.certify,
        ..SolveSettings::default()
    };
    let runs = with_threads(options.threads, || {
        let mut reports = Vec::with_capacity(options.runs);
        for k in 0..options.runs as u64 {
            let s = SolveSettings {
                seed: settings.seed.wrapping_add(k),
                ..settings.clone()
            };
            reports.push(homotopy::solve(&system, &s).map_err(|e| Error::Input(e.to_string()))?);
        }
        Ok::<_, Error>(homotopy::combine_runs(reports))
    })??;
    let threads = options.threads.unwrap_or_else(rayon::current_num_threads);
    Ok(
        serde_json::to_string(&SolveJson::new(source, &system, options, threads, &runs))
            .expect("serialisable"),
    )
}

/// Every isolated solution of the Bertini input `text` (named `source` in messages), as
/// `kinsyn solve FILE --json`, as JSON text.
#[pyfunction]
#[pyo3(signature = (text, source = "<string>", seed = 1, start = "total-degree", runs = 1,
    threads = None, certify = true))]
#[expect(clippy::too_many_arguments, reason = "the options of `kinsyn solve`")]
pub fn solve_json(
    py: Python<'_>,
    text: &str,
    source: &str,
    seed: u64,
    start: &str,
    runs: usize,
    threads: Option<usize>,
    certify: bool,
) -> PyResult<String> {
    let options = SolveOptions {
        start: start_system(start)?,
        seed,
        runs,
        threads,
        certify,
    };
    Ok(py.detach(|| solve_text(text, source, &options))?)
}

/// [`solve_json`] for the Bertini input file at `path` (messages name the file).
#[pyfunction]
#[pyo3(signature = (path, seed = 1, start = "total-degree", runs = 1, threads = None,
    certify = true))]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts a Python path (str or os.PathLike) to an owned PathBuf"
)]
pub fn solve_file_json(
    py: Python<'_>,
    path: PathBuf,
    seed: u64,
    start: &str,
    runs: usize,
    threads: Option<usize>,
    certify: bool,
) -> PyResult<String> {
    let text = read_text(&path, "not a Bertini input file")?;
    let source = path.display().to_string();
    let options = SolveOptions {
        start: start_system(start)?,
        seed,
        runs,
        threads,
        certify,
    };
    Ok(py.detach(|| solve_text(&text, &source, &options))?)
}

/// `n word` or `n words`.
fn count(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}

/// A path count as text: the number, or "more than 10^38" when it saturated (at `u128::MAX`).
fn paths_text(n: u128) -> String {
    if n == u128::MAX {
        "more than 10^38".into()
    } else {
        n.to_string()
    }
}

/// Refuses, naming the file and the equation, a system homotopy continuation cannot solve:
/// not square, an equation that is a constant (no solution, or no isolated one if zero), a
/// coefficient that overflowed double precision, or more paths than [`homotopy::MAX_PATHS`].
fn check_solvable(
    path: &str,
    input: &bertini::BertiniInput,
    start: StartSystem,
) -> Result<(), Error> {
    let system = &input.system;
    let file = path;
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
    let paths = path_count(system, start);
    if paths > homotopy::MAX_PATHS {
        let hint = match start {
            StartSystem::TotalDegree if system.multihomogeneous_bezout() <= homotopy::MAX_PATHS => {
                format!(
                    "; --start multi-homogeneous needs {} for these variable groups",
                    system.multihomogeneous_bezout()
                )
            }
            _ => String::new(),
        };
        return Err(Error::Input(format!(
            "{file}: the {} start system has {} paths; the limit is {} (2^20){hint}",
            match start {
                StartSystem::TotalDegree => "total-degree",
                StartSystem::MultiHomogeneous => "multi-homogeneous",
            },
            paths_text(paths),
            homotopy::MAX_PATHS
        )));
    }
    Ok(())
}

/// Runs `work` on a pool of `threads` workers (all cores when `None`).
fn with_threads<T: Send>(
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

/// The number of paths of the chosen start system.
fn path_count(system: &System, start: StartSystem) -> u128 {
    match start {
        StartSystem::TotalDegree => system.bezout_number(),
        StartSystem::MultiHomogeneous => system.multihomogeneous_bezout(),
    }
}

/// A complex number as text: `1.2345678901` or `1.2345678901 - 0.5000000000i`.
fn complex_text(c: C64) -> String {
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

fn reality(s: &Solution) -> &'static str {
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
    start: StartSystem,
    seed: u64,
    threads: usize,
    summary: String,
    paths: usize,
    nonsingular: usize,
    real: usize,
    singular: usize,
    at_infinity: usize,
    failed: usize,
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
            multihomogeneous_bezout_number: paths_text(system.multihomogeneous_bezout()),
            start: options.start,
            seed: options.seed,
            threads,
            summary: r.summary(),
            paths: r.paths(),
            nonsingular: r.nonsingular(),
            real: r.real(),
            singular: r.singular(),
            at_infinity: r.at_infinity(),
            failed: r.failed(),
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
