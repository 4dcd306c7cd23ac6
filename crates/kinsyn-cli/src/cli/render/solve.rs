//! The text of `kinsyn solve`, and the certificate line it shares with `analyze
//! --all-assemblies`.

use kinsyn::certify::Reality;
use kinsyn::homotopy::{Solution, SolveReport, StartSystem};
use kinsyn_report::solve::{
    Show, Solved, complex_text, count, linear_product_text, multihomogeneous_text, paths_text,
    reality,
};
use kinsyn_report::solve_shards::ShardSummary;
use std::fmt::Write as _;

/// What `kinsyn solve --shard` did, in one line.
pub(in crate::cli) fn shard_text(s: &ShardSummary) -> String {
    format!(
        "{}: shard {}/{} of the {} start system's {} paths: {} tracked in {:.3} s, written to {} (finish with --merge)\n",
        s.source,
        s.shard,
        s.shards,
        s.start,
        s.paths,
        s.tracked,
        s.seconds,
        s.out.display()
    )
}

/// The certificate counts of a solve in one line.
pub(super) fn certificate_line(report: &SolveReport) -> String {
    let regular = report.nonsingular();
    let non_real = report
        .solutions
        .iter()
        .filter(|s| {
            s.is_certified()
                && s.certificate
                    .as_ref()
                    .is_some_and(|c| c.real == Reality::CertifiedNonReal)
        })
        .count();
    format!(
        "certified (Krawczyk, interval arithmetic): {} of {regular} non-singular solutions unique and distinct, {} proven real, {non_real} proven non-real",
        report.certified(),
        report.certified_real()
    )
}

/// The text report of `kinsyn solve`: the system, the start system, the counts, the
/// certificates, the runs, and the solutions `--show` lists.
pub(in crate::cli) fn text(solved: &Solved) -> String {
    let (path, system, options, threads, runs) = (
        &solved.source,
        &solved.system,
        &solved.options,
        solved.threads,
        &solved.runs,
    );
    let report = &runs.runs[0];
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}: {} in {} ({})",
        path,
        count(system.len(), "equation"),
        count(system.nvars(), "variable"),
        system.variables().join(", ")
    );
    let _ = writeln!(
        out,
        "start system: {}{}, {} paths (Bézout number {}, multi-homogeneous {}, linear-product {} for {} variable group{}), seed {}",
        match report.start {
            StartSystem::TotalDegree => "total degree",
            StartSystem::MultiHomogeneous => "multi-homogeneous",
            StartSystem::LinearProduct => "linear-product",
            StartSystem::Polyhedral => "polyhedral",
            StartSystem::Auto => "auto",
        },
        if options.start == StartSystem::Auto {
            " (chosen by auto: the fewest paths)"
        } else {
            ""
        },
        report.paths(),
        paths_text(system.bezout_number()),
        multihomogeneous_text(system),
        linear_product_text(system),
        system.groups().len(),
        if system.groups().len() == 1 { "" } else { "s" },
        options.seed
    );
    let _ = writeln!(out, "{}", report.summary());
    if !report.complete() {
        let _ = writeln!(
            out,
            "incomplete: {} path{} failed even after {} rounds of stricter steps; a root may be missing (another --seed, or --runs K, finds it)",
            report.failed(),
            if report.failed() == 1 { "" } else { "s" },
            kinsyn::homotopy::SolveSettings::default().retrack_rounds
        );
    }
    if options.certify {
        let _ = writeln!(out, "{}", certificate_line(report));
    }
    if runs.runs.len() > 1 {
        let _ = writeln!(
            out,
            "runs: {} independent runs (seeds {}–{}) found {} distinct non-singular solutions; {} of {} runs found all of them",
            runs.runs.len(),
            options.seed,
            options.seed.wrapping_add(runs.runs.len() as u64 - 1),
            runs.union.len(),
            runs.complete_count(),
            runs.runs.len()
        );
    }
    if report.retracked > 0 {
        let _ = writeln!(
            out,
            "re-tracked: {} paths (coinciding endpoints or failures)",
            report.retracked
        );
    }
    let _ = writeln!(
        out,
        "time: {:.3} s on {threads} thread{}",
        report.seconds,
        if threads == 1 { "" } else { "s" }
    );
    out += &solutions_text(solved);
    out
}

/// The solutions `--show` lists (every finite one, the real non-singular ones, or none), one
/// line each with its coordinates, what it is known to be and its residual.
fn solutions_text(solved: &Solved) -> String {
    let (system, options, report) = (&solved.system, &solved.options, &solved.runs.runs[0]);
    let mut out = String::new();
    let listed: Vec<&Solution> = match options.show {
        Show::None => Vec::new(),
        Show::Real => report
            .solutions
            .iter()
            .filter(|s| s.regular && s.real)
            .collect(),
        Show::All => report.solutions.iter().collect(),
    };
    if !listed.is_empty() {
        let _ = writeln!(
            out,
            "{} solutions ({}):",
            if options.show == Show::Real {
                "real"
            } else {
                "finite"
            },
            listed.len()
        );
    }
    for (k, s) in listed.iter().enumerate() {
        let coordinates: Vec<String> = system
            .variables()
            .iter()
            .zip(&s.x)
            .map(|(n, c)| format!("{n} = {}", complex_text(*c)))
            .collect();
        let kind = if s.regular {
            reality(s).to_string()
        } else {
            format!("singular, multiplicity {}", s.multiplicity)
        };
        let _ = writeln!(
            out,
            "  {:>3}  {}  [{kind}; residual {:.1e}]",
            k + 1,
            coordinates.join(", "),
            s.residual
        );
    }
    out
}
