//! `PHCpack` (J. Verschelde, *Algorithm 795: `PHCpack`*, ACM TOMS 25(2), 1999), the
//! polyhedral homotopy solver, as an independent solver to compare kinsyn's homotopy against:
//! [`write()`] gives a system in `PHCpack`'s input format, [`solve`] runs its blackbox solver
//! (`phc -b`) on it and reads back every solution with `PHCpack`'s own diagnostics and root
//! counts.
//!
//! `PHCpack`'s input format (`phc -h`): the number of equations (followed by the number of
//! variables when they differ), then the polynomials, each ended by `;`; `i` and `I` are the
//! imaginary unit and `e`, `E` belong to the scientific notation of numbers, so variable
//! names starting with those letters are misread: such names (and any name that is not an
//! identifier of at most 80 characters, `PHCpack`'s limit) are written as `x1, x2, …` and
//! mapped back when the solutions are read.

use super::bertini::{format_poly, safe_names};
use super::{C64, System};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Why `PHCpack` could not be run or its answer not read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PhcError {
    /// `PHCpack`'s blackbox solver takes square systems only.
    #[error(
        "PHCpack's blackbox solver needs as many equations as variables ({equations} equations, {variables} variables)"
    )]
    NotSquare {
        /// The number of equations.
        equations: usize,
        /// The number of variables.
        variables: usize,
    },
    /// The temporary files or the process could not be made.
    #[error("running {program}: {message}")]
    Io {
        /// The program run.
        program: String,
        /// The operating system's message.
        message: String,
    },
    /// The run took longer than the limit and was killed.
    #[error("PHCpack did not finish within {0:?} and was stopped")]
    Timeout(Duration),
    /// `PHCpack` exited with an error.
    #[error("PHCpack failed ({status}): {message}")]
    Failed {
        /// The exit status.
        status: String,
        /// The last line `PHCpack` printed, if any.
        message: String,
    },
    /// `PHCpack`'s output file is not as expected.
    #[error("cannot read PHCpack's output: {0}")]
    Output(String),
}

/// `PHCpack`'s verdict on one solution, as printed at the end of its `== err … ==` line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PhcClass {
    /// Non-singular (`rco` above `PHCpack`'s tolerance) with real coordinates.
    RealRegular,
    /// Non-singular with some non-real coordinate.
    ComplexRegular,
    /// Singular (ill-conditioned Jacobian: a multiple root or on a positive-dimensional set),
    /// real.
    RealSingular,
    /// Singular, non-real.
    ComplexSingular,
    /// The path diverged: a solution at infinity, not a finite root.
    AtInfinity,
    /// Clustered with the solution of the given (1-based) number: two paths reached the
    /// same point.
    Clustered(usize),
    /// The path failed (`no solution`).
    Failed,
    /// Any other label, as printed.
    Other(String),
}

/// One solution of `PHCpack`'s final list.
#[derive(Clone, Debug, PartialEq)]
pub struct PhcSolution {
    /// The coordinates, in the system's variable order.
    pub point: Vec<C64>,
    /// `PHCpack`'s multiplicity `m`.
    pub multiplicity: u32,
    /// The last Newton correction (`err`): the forward error estimate.
    pub err: f64,
    /// The inverse condition number of the Jacobian (`rco`); near zero at singular roots.
    pub rco: f64,
    /// The residual (`res`): the largest equation value at the point.
    pub res: f64,
    /// `PHCpack`'s classification; `None` where it prints none (its special solvers for one
    /// univariate polynomial and for linear systems).
    pub class: Option<PhcClass>,
}

impl PhcSolution {
    /// The real point, if every imaginary part is at most `tol` in magnitude.
    #[must_use]
    pub fn real(&self, tol: f64) -> Option<Vec<f64>> {
        self.point
            .iter()
            .all(|z| z.im.abs() <= tol)
            .then(|| self.point.iter().map(|z| z.re).collect())
    }

    /// Whether this is a finite root: not at infinity and not a failed path.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        !matches!(self.class, Some(PhcClass::AtInfinity | PhcClass::Failed))
    }

    /// Whether `PHCpack` found the root regular (non-singular); for the unclassified
    /// solutions of its special solvers, whether `rco` exceeds `1e-8`.
    #[must_use]
    pub fn is_regular(&self) -> bool {
        match self.class {
            Some(PhcClass::RealRegular | PhcClass::ComplexRegular) => true,
            None => self.rco > 1e-8,
            Some(_) => false,
        }
    }
}

/// The root counts `PHCpack` printed (each `None` when not printed: the special solvers print
/// none, and which bounds appear depends on the system).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RootCounts {
    /// The total degree (Bézout number): the product of the degrees.
    pub total_degree: Option<u128>,
    /// The best multi-homogeneous Bézout number found, with its number of groups `m`.
    pub multihomogeneous: Option<(usize, u128)>,
    /// The general linear-product Bézout number.
    pub linear_product: Option<u128>,
    /// The mixed volume: the BKK bound on the isolated roots with non-zero coordinates.
    pub mixed_volume: Option<u128>,
    /// The stable mixed volume: a bound on all isolated roots, zero coordinates included.
    pub stable_mixed_volume: Option<u128>,
}

/// What `PHCpack`'s output file says: the final solution list, root counts and seed.
#[derive(Clone, Debug, PartialEq)]
pub struct PhcOutput {
    /// The final (refined) solutions, every path's end included (at infinity, failed).
    pub solutions: Vec<PhcSolution>,
    /// The root counts.
    pub root_counts: RootCounts,
    /// The seed of `PHCpack`'s random numbers, if printed.
    pub seed: Option<u64>,
}

impl PhcOutput {
    /// The finite solutions ([`PhcSolution::is_finite`]).
    #[must_use]
    pub fn finite(&self) -> Vec<&PhcSolution> {
        self.solutions.iter().filter(|s| s.is_finite()).collect()
    }

    /// The finite solutions that are real within `tol` (every imaginary part at most `tol`),
    /// as real points.
    #[must_use]
    pub fn real_solutions(&self, tol: f64) -> Vec<Vec<f64>> {
        self.solutions
            .iter()
            .filter(|s| s.is_finite())
            .filter_map(|s| s.real(tol))
            .collect()
    }
}

/// The result of a `PHCpack` run.
#[derive(Clone, Debug, PartialEq)]
pub struct PhcResult {
    /// What `PHCpack` printed.
    pub output: PhcOutput,
    /// The wall-clock time of the run (process start to exit).
    pub wall_time: Duration,
}

/// The limit [`solve`] puts on a run.
pub const DEFAULT_LIMIT: Duration = Duration::from_mins(2);

/// Whether `PHCpack` reads `name` as a variable name: an identifier of at most 80 characters
/// not starting with `e`, `E` (exponent letters) or `i`, `I` (the imaginary unit).
#[must_use]
pub fn is_valid_name(name: &str) -> bool {
    let mut chars = name.chars();
    name.len() <= 80
        && chars
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() && !"eEiI".contains(c))
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The names [`write()`] gives the variables (see [`is_valid_name`]).
#[must_use]
pub fn phc_names(system: &System) -> Vec<String> {
    safe_names(system.variables(), is_valid_name, "x")
}

/// `system` in `PHCpack`'s input format: the number of equations (and of variables, when it
/// differs), then each polynomial ended by `;`, coefficients in shortest round-trip decimals,
/// complex ones as `(a + b*i)`; variables named by [`phc_names`].
#[must_use]
pub fn write(system: &System) -> String {
    let names = phc_names(system);
    let mut out = if system.is_square() {
        format!("{}\n", system.len())
    } else {
        format!("{} {}\n", system.len(), system.nvars())
    };
    for p in system.equations() {
        let _ = writeln!(out, " {};", format_poly(p, &names, "i"));
    }
    out
}

/// `phc` on the `PATH`, if there is one.
#[must_use]
pub fn find_phc() -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join("phc"))
        .find(|p| p.is_file())
}

/// Solves `system` with `PHCpack`'s blackbox solver (`phc -b -0`, fixed seed) run by the
/// program `phc`, stopped after [`DEFAULT_LIMIT`].
///
/// # Errors
/// See [`solve_within`].
pub fn solve(system: &System, phc: &Path) -> Result<PhcResult, PhcError> {
    solve_within(system, phc, DEFAULT_LIMIT)
}

/// A fresh directory under the system's temporary directory, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new() -> std::io::Result<Self> {
        use std::sync::atomic::{AtomicU64, Ordering};
        static COUNTER: AtomicU64 = AtomicU64::new(0);
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.subsec_nanos());
        loop {
            let k = COUNTER.fetch_add(1, Ordering::Relaxed);
            let dir =
                std::env::temp_dir().join(format!("kinsyn-phc-{}-{nanos}-{k}", std::process::id()));
            match std::fs::create_dir(&dir) {
                Ok(()) => return Ok(Self(dir)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
                Err(e) => return Err(e),
            }
        }
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Solves `system` with `PHCpack`'s blackbox solver (`phc -b -0`: fixed seed, so a run is
/// reproducible) in a fresh temporary directory, killing the run after `limit`.
///
/// # Errors
/// [`PhcError::NotSquare`] for a non-square system (not run), [`PhcError::Io`] if the files
/// or the process cannot be made, [`PhcError::Timeout`] if the run exceeds `limit`,
/// [`PhcError::Failed`] if `phc` exits with an error, [`PhcError::Output`] if its output
/// cannot be read.
pub fn solve_within(system: &System, phc: &Path, limit: Duration) -> Result<PhcResult, PhcError> {
    if !system.is_square() || system.is_empty() {
        return Err(PhcError::NotSquare {
            equations: system.len(),
            variables: system.nvars(),
        });
    }
    let io = |e: std::io::Error| PhcError::Io {
        program: phc.display().to_string(),
        message: e.to_string(),
    };
    let dir = TempDir::new().map_err(io)?;
    std::fs::write(dir.0.join("input"), write(system)).map_err(io)?;
    let log = std::fs::File::create(dir.0.join("log")).map_err(io)?;
    let log_err = log.try_clone().map_err(io)?;
    let start = Instant::now();
    let mut child = Command::new(phc)
        .args(["-b", "-0", "input", "output"])
        .current_dir(&dir.0)
        .stdin(Stdio::null())
        .stdout(log)
        .stderr(log_err)
        .spawn()
        .map_err(io)?;
    let status = loop {
        if let Some(status) = child.try_wait().map_err(io)? {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return Err(PhcError::Timeout(limit));
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let wall_time = start.elapsed();
    if !status.success() {
        let log = std::fs::read_to_string(dir.0.join("log")).unwrap_or_default();
        let message = log
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("no message")
            .trim()
            .to_string();
        return Err(PhcError::Failed {
            status: status.to_string(),
            message,
        });
    }
    let text = std::fs::read_to_string(dir.0.join("output")).map_err(io)?;
    let output = parse_output(&text, system)?;
    Ok(PhcResult { output, wall_time })
}

/// Reads the output file of `phc -b` for `system` (written by [`write()`]): the final solution
/// lists (`PHCpack` may refine several, e.g. the roots with zero coordinates apart; all are
/// collected, the path trackers' intermediate lists skipped), the root counts and the seed.
///
/// # Errors
/// [`PhcError::Output`] if a solution list is malformed or names an unknown variable.
pub fn parse_output(text: &str, system: &System) -> Result<PhcOutput, PhcError> {
    let names = phc_names(system);
    let lines: Vec<&str> = text.lines().collect();
    let mut solutions = Vec::new();
    let mut k = 0;
    while k < lines.len() {
        if lines[k].trim() == "THE SOLUTIONS :" {
            k = read_list(&lines, k + 1, &names, &mut solutions)?;
        } else {
            k += 1;
        }
    }
    Ok(PhcOutput {
        solutions,
        root_counts: root_counts(&lines),
        seed: lines.iter().find_map(|l| {
            l.trim()
                .strip_prefix("Seed used in random number generators :")
                .and_then(|s| s.trim().trim_end_matches('.').parse().ok())
        }),
    })
}

fn bad(line: usize, what: &str) -> PhcError {
    PhcError::Output(format!("line {}: {what}", line + 1))
}

/// Reads the list after a `THE SOLUTIONS :` line (at `k`); returns the line after it. Lists
/// of the path trackers (blocks headed `== 1 = #step …`) are skipped.
fn read_list(
    lines: &[&str],
    mut k: usize,
    names: &[String],
    out: &mut Vec<PhcSolution>,
) -> Result<usize, PhcError> {
    while k < lines.len() && lines[k].trim().is_empty() {
        k += 1;
    }
    let counts: Vec<usize> = lines
        .get(k)
        .map(|l| {
            l.split_whitespace()
                .filter_map(|w| w.parse().ok())
                .collect()
        })
        .unwrap_or_default();
    let [count, dim] = counts[..] else {
        return Err(bad(k, "a solution list without its 'count dimension' line"));
    };
    if dim != names.len() {
        return Err(bad(
            k,
            &format!(
                "solutions of dimension {dim}, the system has {}",
                names.len()
            ),
        ));
    }
    k += 1;
    if count == 0 {
        return Ok(k);
    }
    // The separator, then the first block's header.
    while k < lines.len() && (lines[k].trim().is_empty() || lines[k].starts_with("====")) {
        k += 1;
    }
    if !lines.get(k).is_some_and(|l| l.starts_with("solution ")) {
        return Ok(k); // a path tracker's report, refined later
    }
    for _ in 0..count {
        k = read_solution(lines, k, names, out)?;
    }
    Ok(k)
}

fn read_solution(
    lines: &[&str],
    mut k: usize,
    names: &[String],
    out: &mut Vec<PhcSolution>,
) -> Result<usize, PhcError> {
    if !lines.get(k).is_some_and(|l| l.starts_with("solution ")) {
        return Err(bad(k, "a solution block was expected"));
    }
    k += 1;
    let mut point = vec![None; names.len()];
    let mut multiplicity = 1;
    let mut in_point = false;
    loop {
        let Some(line) = lines.get(k) else {
            return Err(bad(k, "the solution list ends inside a solution"));
        };
        let t = line.trim();
        if t.starts_with("== err") {
            break;
        }
        if t.starts_with("the solution for t") {
            in_point = true;
        } else if let Some(m) = t.strip_prefix("m :") {
            multiplicity = m
                .split_whitespace()
                .next()
                .and_then(|w| w.parse().ok())
                .ok_or_else(|| bad(k, "a multiplicity that is not a number"))?;
        } else if in_point {
            let (name, value) = t
                .split_once(" : ")
                .ok_or_else(|| bad(k, "a coordinate line that is not 'name : re im'"))?;
            let parts: Vec<f64> = value
                .split_whitespace()
                .map(str::parse)
                .collect::<Result<_, _>>()
                .map_err(|_| bad(k, "a coordinate that is not a number"))?;
            let [re, im] = parts[..] else {
                return Err(bad(k, "a coordinate without real and imaginary parts"));
            };
            let i = names
                .iter()
                .position(|n| n == name.trim())
                .ok_or_else(|| bad(k, &format!("unknown variable '{}'", name.trim())))?;
            point[i] = Some(C64::new(re, im));
        }
        k += 1;
    }
    let diagnostics = lines[k].trim();
    let value = |key: &str| -> Result<f64, PhcError> {
        diagnostics
            .split(key)
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .and_then(|w| w.parse().ok())
            .ok_or_else(|| bad(k, &format!("no '{key}' in the diagnostics")))
    };
    let (err, rco, res) = (value("err :")?, value("rco :")?, value("res :")?);
    // "== err : a = rco : b = res : c = real regular ==": the label after the fourth '='.
    let label = diagnostics
        .trim_start_matches('=')
        .trim_end_matches('=')
        .split(" = ")
        .nth(3)
        .map(str::trim)
        .filter(|s| !s.is_empty());
    let class = label.map(|l| match l {
        "real regular" => PhcClass::RealRegular,
        "complex regular" => PhcClass::ComplexRegular,
        "real singular" => PhcClass::RealSingular,
        "complex singular" => PhcClass::ComplexSingular,
        "at infinity" => PhcClass::AtInfinity,
        "no solution" => PhcClass::Failed,
        other => other
            .strip_prefix("clustered with")
            .and_then(|n| n.trim().parse().ok())
            .map_or_else(|| PhcClass::Other(other.to_string()), PhcClass::Clustered),
    });
    let point = point
        .into_iter()
        .collect::<Option<Vec<C64>>>()
        .ok_or_else(|| bad(k, "a solution without every coordinate"))?;
    out.push(PhcSolution {
        point,
        multiplicity,
        err,
        rco,
        res,
        class,
    });
    Ok(k + 1)
}

fn root_counts(lines: &[&str]) -> RootCounts {
    let mut counts = RootCounts::default();
    let Some(start) = lines.iter().position(|l| l.trim() == "ROOT COUNTS :") else {
        return counts;
    };
    for line in &lines[start + 1..] {
        if line.starts_with("TIMING") {
            break;
        }
        let Some((key, value)) = line.split_once(" : ") else {
            continue;
        };
        let Ok(value) = value.trim().parse::<u128>() else {
            continue;
        };
        let key = key.trim();
        match key {
            "total degree" => counts.total_degree = Some(value),
            "general linear-product Bezout number" => counts.linear_product = Some(value),
            "mixed volume" => counts.mixed_volume = Some(value),
            "stable mixed volume" => counts.stable_mixed_volume = Some(value),
            _ => {
                if let Some(m) = key
                    .strip_suffix("-homogeneous Bezout number")
                    .and_then(|m| m.parse().ok())
                {
                    counts.multihomogeneous = Some((m, value));
                }
            }
        }
    }
    counts
}
