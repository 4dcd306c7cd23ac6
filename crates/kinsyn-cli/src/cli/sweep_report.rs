//! `kinsyn sweep report`: the ranking of a sweep's designs ([`kinsyn::sweep::ranking`]) as a
//! Markdown report with two figures (SVG and PNG), and a short summary on stdout.

use super::args::ReportArgs;
use super::output::OutputFolder;
use super::plot::{draw_error, png, register_font, svg};
use super::{CliError, json, sweep};
use kinsyn::markup;
use kinsyn::sweep::DesignRow;
use kinsyn::sweep::ranking::{RankedDesign, Ranking};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::PathBuf;
use sweep::SweepRows;

/// The report's figures, each written as `NAME.svg` and `NAME.png`.
const FIGURES: [&str; 2] = ["capacity-by-family", "capacity-vs-inputs"];
/// The report's text.
const MARKDOWN: &str = "report.md";

/// `kinsyn sweep report RESULTS`: ranks the designs, writes the report and figures, and returns
/// the summary (or the ranking as JSON).
pub(super) fn report(args: &ReportArgs) -> Result<String, CliError> {
    let results = sweep::read_results(&args.results)?;
    let top = args.top as usize;
    let ranking = Ranking::new(&results.rows, top);
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| results.folder.join("report"));
    let folder = OutputFolder::check(
        "--out",
        &out,
        std::iter::once(MARKDOWN.to_string()).chain(
            FIGURES
                .iter()
                .flat_map(|n| [format!("{n}.svg"), format!("{n}.png")]),
        ),
        args.force.force,
    )?;
    register_font();
    let mut figures = Vec::new();
    for (name, size) in FIGURES
        .into_iter()
        .zip([family_figure_size(&ranking), (900, 600)])
    {
        let text = svg(size, |root| draw(name, root, &ranking, &results.rows))?;
        figures.push((format!("{name}.svg"), text.into_bytes()));
        let bytes = png(size, |root| draw(name, root, &ranking, &results.rows))?;
        figures.push((format!("{name}.png"), bytes));
    }
    let markdown = markdown_report(&results, &ranking);
    folder.create(&[])?;
    let mut files = vec![folder.write(MARKDOWN, markdown.as_bytes())?];
    for (name, bytes) in &figures {
        files.push(folder.write(name, bytes)?);
    }
    if args.json {
        return Ok(json(&serde_json::json!({
            "results": results.file.display().to_string(),
            "settings": results.manifest.as_ref().map(|m| &m.settings),
            "ranking": ranking,
            "files": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        })));
    }
    Ok(summary(&results, &ranking, &files))
}

/// The summary printed on stdout.
fn summary(results: &SweepRows, ranking: &Ranking, files: &[PathBuf]) -> String {
    let mut text = String::new();
    let _ = writeln!(
        text,
        "{}: {} designs, {} built, {} not built, {} with unsampled lock subsets, {} with lock subsets at a singular start (not counted)",
        results.file.display(),
        ranking.designs,
        ranking.built,
        ranking.failed.len(),
        ranking.unsampled.len(),
        ranking.singular.0
    );
    let _ = writeln!(
        text,
        "Pareto front of capacity (group kinds, then subgroups) against inputs: {} designs",
        ranking.front.len()
    );
    for d in ranking.front.iter().take(10) {
        let _ = writeln!(
            text,
            "  {} inputs: design {} {} {} actuated {}: {} kinds ({}), {} subgroups",
            d.inputs,
            d.design,
            d.chain,
            d.notation,
            joints(&d.actuated),
            d.kinds,
            kinds_list(d),
            d.subgroups
        );
    }
    if ranking.front.len() > 10 {
        let _ = writeln!(text, "  … {} more in the report", ranking.front.len() - 10);
    }
    for t in &ranking.top {
        if let Some(best) = t.top.first() {
            let _ = writeln!(
                text,
                "best of {} inputs ({} designs): design {} {} {} actuated {}, {} kinds, {} subgroups",
                t.inputs,
                t.designs,
                best.design,
                best.chain,
                best.notation,
                joints(&best.actuated),
                best.kinds,
                best.subgroups
            );
        }
    }
    for f in files {
        let _ = writeln!(text, "wrote {}", f.display());
    }
    text
}

fn joints(actuated: &[usize]) -> String {
    actuated
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(",")
}

fn kinds_list(d: &RankedDesign) -> String {
    d.kind_locks
        .iter()
        .map(|k| k.kind.as_str())
        .collect::<Vec<_>>()
        .join(" ")
}

/// The Pareto front as its points: for each number of inputs whose best capacity beats every
/// smaller one, the designs tied there, counted, the first `top_k` (by the tie-breaks) listed.
fn front_section(md: &mut String, r: &Ranking) {
    let _ = writeln!(md, "## Pareto front: capacity against inputs\n");
    // The front is the best capacity of each number of inputs that beats every smaller one;
    // the designs tied there are counted, and the first `top_k` (by the tie-breaks) listed.
    let points = r.front.chunk_by(|a, b| a.inputs == b.inputs);
    for tied in points {
        let first = &tied[0];
        let _ = writeln!(
            md,
            "**{} inputs: {} kinds, {} subgroups**, reached by {} design{}{}:\n",
            first.inputs,
            first.kinds,
            first.subgroups,
            tied.len(),
            if tied.len() == 1 { "" } else { "s" },
            if tied.len() > r.top_k {
                format!(" (the first {} listed; all of them with `--json`)", r.top_k)
            } else {
                String::new()
            }
        );
        let _ = writeln!(
            md,
            "| design | chain | notation | actuated | dof | group kinds |"
        );
        let _ = writeln!(md, "| ---: | --- | --- | --- | ---: | --- |");
        for d in tied.iter().take(r.top_k) {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} |",
                d.design,
                markup::markdown(&d.chain),
                markup::markdown_code(&d.notation),
                joints(&d.actuated),
                d.dof,
                markup::markdown(&kinds_list(d))
            );
        }
        let _ = writeln!(md);
    }
}

/// `report.md`: the settings, counts, front, top designs with their lock sets, legs, family
/// capacity, histogram, failures and the figures. Every text from the rows or the file names
/// passes the one Markdown escaper ([`markup::markdown`] for text, [`markup::markdown_code`] for code spans).
fn markdown_report(results: &SweepRows, r: &Ranking) -> String {
    let mut md = String::new();
    let _ = writeln!(md, "# Multioperation sweep: ranking of the designs\n");
    let _ = writeln!(
        md,
        "Rows: {}: {} designs, {} built, {} not built, {} with unsampled lock subsets, {} with {} lock subsets whose start is a singular configuration of the locked manipulator (not counted: the motion branches there, and the pattern sampled depends on the branch; see docs/deviations.md, \"What the catalogue-wide sweep changed\").\n",
        markup::markdown_code(&results.file.display().to_string()),
        r.designs,
        r.built,
        r.failed.len(),
        r.unsampled.len(),
        r.singular.0,
        r.singular.1
    );
    match results.manifest.as_ref().map(|m| &m.settings) {
        Some(s) => {
            let _ = writeln!(
                md,
                "Settings (sweep.json): {} legs; actuated joints per leg: {}; sampling: {}.\n",
                s.legs,
                joints(&s.actuated_per_leg),
                markup::markdown_code(&serde_json::to_string(&s.sampling).unwrap_or_default())
            );
        }
        None => {
            let _ = writeln!(md, "Settings: not recorded (no readable sweep.json).\n");
        }
    }
    let _ = writeln!(
        md,
        "A design's capacity is the number of kinds of displacement group its platform reaches by locking inputs (paper 000 §1), ties broken by the number of distinct subgroups (a group with its axis, plane or centre). A design is on the Pareto front when no other has no more inputs and no less capacity, one of them strictly. Designs not built are left out of the ranking; designs with unsampled lock subsets are ranked on what was sampled.\n"
    );
    front_section(&mut md, r);
    let _ = writeln!(md, "![capacity against inputs](capacity-vs-inputs.png)\n");
    top_section(&mut md, r);
    let _ = writeln!(md, "## Legs of the front and the best designs\n");
    let _ = writeln!(
        md,
        "| chain | notation | family | best designs | front designs |"
    );
    let _ = writeln!(md, "| --- | --- | --- | ---: | ---: |");
    for l in &r.legs {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} |",
            markup::markdown(&l.chain),
            markup::markdown_code(&l.notation),
            markup::markdown(&l.family),
            l.top_designs,
            l.front_designs
        );
    }
    let _ = writeln!(md, "\n## Capacity per family\n");
    let _ = writeln!(md, "| family | designs | mean kinds | max kinds |");
    let _ = writeln!(md, "| --- | ---: | ---: | ---: |");
    for f in &r.families {
        let _ = writeln!(
            md,
            "| {} | {} | {:.2} | {} |",
            markup::markdown(&f.family),
            f.designs,
            f.mean_kinds,
            f.max_kinds
        );
    }
    let _ = writeln!(md, "\n![capacity per family](capacity-by-family.png)\n");
    let _ = writeln!(md, "## Group kinds reached\n");
    let _ = writeln!(md, "| kinds | designs |");
    let _ = writeln!(md, "| ---: | ---: |");
    for (k, n) in r.histogram.iter().enumerate() {
        let _ = writeln!(md, "| {k} | {n} |");
    }
    failures_section(&mut md, r);
    md
}

/// The best designs per number of inputs, each with its kinds and lock sets.
fn top_section(md: &mut String, r: &Ranking) {
    let _ = writeln!(
        md,
        "## The best {} designs per number of inputs\n\nEach kind reached is shown with one of its subgroups and a minimal lock set reaching it with the fewest inputs locked (`-`: none).\n",
        r.top_k
    );
    for t in &r.top {
        let _ = writeln!(md, "### {} inputs ({} designs)\n", t.inputs, t.designs);
        for (rank, d) in t.top.iter().enumerate() {
            let _ = writeln!(
                md,
                "{}. design {}: {} {} ({}), actuated {}: dof {}, {} kinds, {} subgroups{}\n",
                rank + 1,
                d.design,
                markup::markdown(&d.chain),
                markup::markdown_code(&d.notation),
                markup::markdown(&d.family),
                joints(&d.actuated),
                d.dof,
                d.kinds,
                d.subgroups,
                if d.unsampled > 0 {
                    format!(" ({} lock subsets not sampled)", d.unsampled)
                } else {
                    String::new()
                }
            );
            let _ = writeln!(md, "   | kind | subgroup | dof | lock set |");
            let _ = writeln!(md, "   | --- | --- | ---: | --- |");
            for k in &d.kind_locks {
                let _ = writeln!(
                    md,
                    "   | {} | {} | {} | {} |",
                    markup::markdown(&k.kind),
                    markup::markdown_code(&k.pattern),
                    k.dof,
                    markup::markdown(&k.lock_set)
                );
            }
            let _ = writeln!(md);
        }
    }
}

/// The designs not built and those with unsampled lock subsets.
fn failures_section(md: &mut String, r: &Ranking) {
    let _ = writeln!(md, "\n## Designs not built ({})\n", r.failed.len());
    if !r.failed.is_empty() {
        let _ = writeln!(md, "| design | chain | actuated | error |");
        let _ = writeln!(md, "| ---: | --- | --- | --- |");
        for f in &r.failed {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} |",
                f.design,
                markup::markdown(&f.chain),
                joints(&f.actuated),
                markup::markdown(&f.error)
            );
        }
        let _ = writeln!(md);
    }
    let _ = writeln!(
        md,
        "## Designs with unsampled lock subsets ({})\n",
        r.unsampled.len()
    );
    if !r.unsampled.is_empty() {
        let _ = writeln!(md, "| design | chain | actuated | unsampled subsets |");
        let _ = writeln!(md, "| ---: | --- | --- | ---: |");
        for u in &r.unsampled {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} |",
                u.design,
                markup::markdown(&u.chain),
                joints(&u.actuated),
                u.unsampled
            );
        }
    }
}

/// The family figure's size: a bar row per family.
fn family_figure_size(r: &Ranking) -> (u32, u32) {
    let rows = u32::try_from(r.families.len()).unwrap_or(u32::MAX);
    (900, rows.saturating_mul(22).saturating_add(140).min(4000))
}

/// Draws the figure `name` on `root`.
fn draw<DB: DrawingBackend>(
    name: &str,
    root: &DrawingArea<DB, Shift>,
    ranking: &Ranking,
    rows: &[DesignRow],
) -> Result<(), CliError> {
    if name == "capacity-by-family" {
        draw_families(root, ranking)
    } else {
        draw_scatter(root, ranking, rows)
    }
}

const MEAN_BAR: RGBColor = RGBColor(70, 110, 200);
const MAX_BAR: RGBColor = RGBColor(230, 140, 60);

/// Horizontal bars of mean and most group kinds per family.
#[allow(
    clippy::cast_precision_loss,
    reason = "counts of families and kinds, far below 2^52"
)]
fn draw_families<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    r: &Ranking,
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let n = r.families.len();
    let most = r.families.iter().map(|f| f.max_kinds).max().unwrap_or(0);
    // plotters' SVG backend escapes the markup characters of text, not the characters XML
    // cannot hold: those are written visibly first.
    let families: Vec<String> = r
        .families
        .iter()
        .map(|f| markup::visible(&f.family).into_owned())
        .collect();
    let mut chart = ChartBuilder::on(root)
        .caption(
            "Multioperation capacity per family: group kinds reached",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(0.0..(most as f64 + 1.0), -0.5..(n as f64 - 0.5))
        .map_err(draw_error)?;
    let label = move |y: &f64| {
        let i = y.round();
        if (y - i).abs() < 1e-6 && i >= 0.0 {
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a non-negative whole number below the families' count"
            )]
            families.get(i as usize).cloned().unwrap_or_default()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .disable_y_mesh()
        .y_labels(n.max(1))
        .y_label_formatter(&label)
        .x_desc("group kinds")
        .label_style(("sans-serif", 12))
        .draw()
        .map_err(draw_error)?;
    chart
        .draw_series(r.families.iter().enumerate().map(|(i, f)| {
            let y = i as f64;
            Rectangle::new([(0.0, y - 0.4), (f.mean_kinds, y)], MEAN_BAR.filled())
        }))
        .map_err(draw_error)?
        .label("mean")
        .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], MEAN_BAR.filled()));
    chart
        .draw_series(r.families.iter().enumerate().map(|(i, f)| {
            let y = i as f64;
            Rectangle::new([(0.0, y), (f.max_kinds as f64, y + 0.4)], MAX_BAR.filled())
        }))
        .map_err(draw_error)?
        .label("max")
        .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], MAX_BAR.filled()));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(draw_error)?;
    Ok(())
}

/// A fraction in [-0.5, 0.5) fixed by the design index and a salt (splitmix64): the jitter
/// that keeps equal points apart, the same on every run.
#[allow(
    clippy::cast_precision_loss,
    reason = "53 bits of the hash are kept on purpose"
)]
fn jitter(design: usize, salt: u64) -> f64 {
    let mut z = (design as u64)
        .wrapping_mul(2)
        .wrapping_add(salt)
        .wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    (z >> 11) as f64 / (1u64 << 53) as f64 - 0.5
}

/// Group kinds against inputs for every built design (jittered), the front in red.
#[allow(
    clippy::cast_precision_loss,
    reason = "counts of inputs and kinds, far below 2^52"
)]
fn draw_scatter<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    r: &Ranking,
    rows: &[DesignRow],
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let built: Vec<&DesignRow> = rows.iter().filter(|d| d.error.is_none()).collect();
    let most_inputs = built.iter().map(|d| d.inputs).max().unwrap_or(1);
    let most_kinds = built.iter().map(|d| d.kinds).max().unwrap_or(0);
    let mut chart = ChartBuilder::on(root)
        .caption(
            "Group kinds reached against inputs (points jittered); the Pareto front in red",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(
            0.0..(most_inputs as f64 + 1.0),
            -0.5..(most_kinds as f64 + 1.0),
        )
        .map_err(draw_error)?;
    chart
        .configure_mesh()
        .x_desc("inputs (actuated joints)")
        .y_desc("group kinds")
        .label_style(("sans-serif", 12))
        .draw()
        .map_err(draw_error)?;
    let point = |d: &DesignRow| {
        (
            d.inputs as f64 + 0.5 * jitter(d.design, 1),
            d.kinds as f64 + 0.5 * jitter(d.design, 2),
        )
    };
    chart
        .draw_series(
            built
                .iter()
                .map(|d| Circle::new(point(d), 2, RGBColor(120, 120, 120).filled())),
        )
        .map_err(draw_error)?
        .label(format!("design ({})", built.len()))
        .legend(|(x, y)| Circle::new((x + 6, y), 3, RGBColor(120, 120, 120).filled()));
    let front: Vec<(f64, f64)> = r
        .front
        .iter()
        .map(|d| (d.inputs as f64, d.kinds as f64))
        .collect();
    // The front as a staircase: its capacity holds until the next number of inputs.
    let stairs: Vec<(f64, f64)> = front
        .iter()
        .zip(front.iter().skip(1))
        .flat_map(|(&a, &b)| [a, (b.0, a.1)])
        .chain(front.last().copied())
        .collect();
    chart
        .draw_series(LineSeries::new(stairs, RED.stroke_width(1)))
        .map_err(draw_error)?;
    chart
        .draw_series(front.iter().map(|&p| Circle::new(p, 5, RED.filled())))
        .map_err(draw_error)?
        .label(format!("Pareto front ({})", r.front.len()))
        .legend(|(x, y)| Circle::new((x + 6, y), 5, RED.filled()));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(draw_error)?;
    Ok(())
}
