//! `kinsyn plot`: the figures of paper 003 drawn by kinsyn, as SVG; and how every figure is
//! drawn in memory ([`svg`], [`png`]) and written whole through [`super::output`].

use super::output::OutputFolder;
use super::{CliError, json};
use kinsyn_papers::configurable::trajectory::{
    TrajectoryEnd, TrajectoryReport, assemble, follow, paper_input_rates, paper_inputs,
    paper_recurring_intervals,
};
use kinsyn_papers::configurable::{CentrePose, Configurable, CornerPose, InversePosition};
use nalgebra::Vector2;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;

/// The figure `kinsyn plot trajectory` writes in its folder.
const TRAJECTORY_FIGURE: &str = "trajectory-velocities.svg";
/// The figure `kinsyn plot inverse` writes in its folder.
const INVERSE_FIGURE: &str = "inverse-configurations.svg";

/// The most instants `--steps` takes.
pub const MAX_STEPS: usize = 100_000;

/// Table 1's converged solution (paper 003, eq. 13's parametrisation), the start of §5.
fn table1() -> CornerPose {
    CornerPose {
        c4: Vector2::new(25.112, -147.043),
        theta: 79.999f64.to_radians(),
        phi: 105.0f64.to_radians(),
    }
}

/// Registers `DejaVu` Sans as plotters' "sans-serif", once: the PNG figures' text needs no
/// system font, and the SVG figures' text is measured with it.
pub(super) fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid font compiled in; a failure would only lose PNG text.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            dejavu::sans::regular(),
        );
    });
}

/// A figure that could not be drawn (in memory: a fault of the drawing, not of the input or
/// of the files, which [`super::output`] reports).
pub(super) fn draw_error(e: impl std::fmt::Display) -> CliError {
    CliError::Internal(format!("cannot draw the figure: {e}"))
}

/// A figure as SVG text: `draw` on an SVG canvas of `size` pixels, then presented.
pub(super) fn svg(
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<SVGBackend<'_>, Shift>) -> Result<(), CliError>,
) -> Result<String, CliError> {
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
        draw(&root)?;
        root.present().map_err(draw_error)?;
    }
    Ok(text)
}

/// A figure as PNG bytes: `draw` on an RGB bitmap of `size` pixels, encoded by the `png` crate
/// with the settings of the `image` crate's default PNG encoder (default compression, adaptive
/// filtering), which plotters' bitmap backend uses when it saves a `.png` file itself.
pub(super) fn png(
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), CliError>,
) -> Result<Vec<u8>, CliError> {
    let (w, h) = size;
    let mut pixels = vec![0u8; 3 * w as usize * h as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, size).into_drawing_area();
        draw(&root)?;
        root.present().map_err(draw_error)?;
    }
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, w, h);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_compression(png::Compression::Default);
        encoder.set_filter(png::FilterType::Sub);
        encoder.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
        let mut writer = encoder.write_header().map_err(draw_error)?;
        writer.write_image_data(&pixels).map_err(draw_error)?;
        writer.finish().map_err(draw_error)?;
    }
    Ok(bytes)
}

/// `kinsyn plot trajectory`: paper 003 §5 followed from Table 2's assembly; the corner speeds
/// against time (like Fig. 12) as `DIR/trajectory-velocities.svg` (replacing an existing one
/// only when `force`), the report on stdout.
pub fn trajectory(
    out: &Path,
    force: bool,
    steps: usize,
    as_json: bool,
) -> Result<String, CliError> {
    if !(2..=MAX_STEPS).contains(&steps) {
        return Err(CliError::Input(format!(
            "--steps {steps}: give 2 to {MAX_STEPS}"
        )));
    }
    let folder = OutputFolder::check("--out", out, [TRAJECTORY_FIGURE], force)?;
    let m = Configurable::paper003();
    let start = assemble(&m, &paper_inputs(0.0), &table1())
        .ok_or_else(|| CliError::Internal("Table 1's assembly does not close at q(0)".into()))?;
    let times: Vec<f64> = (0..=steps)
        .map(|k| std::f64::consts::TAU * k as f64 / steps as f64)
        .collect();
    let report = follow(&m, &start, paper_inputs, paper_input_rates, &times);
    let figure = svg((900, 560), |root| draw_speeds(&report, root))?;
    folder.create(&[])?;
    let file = folder.write(TRAJECTORY_FIGURE, figure.as_bytes())?;
    if as_json {
        let v = serde_json::json!({
            "figure": file.display().to_string(),
            "samples": report.samples.iter().map(|s| serde_json::json!({
                "t": s.t,
                "q": s.q,
                "corners": s.corners.iter().map(|c| [c.x, c.y]).collect::<Vec<_>>(),
                "corner_velocities": s.corner_velocities.iter().map(|c| [c.x, c.y]).collect::<Vec<_>>(),
                "inverse_condition": s.inverse_condition,
            })).collect::<Vec<_>>(),
            "end": match &report.end {
                TrajectoryEnd::Completed => serde_json::json!({"completed": true}),
                TrajectoryEnd::Ceased { last, next, reason } => serde_json::json!({
                    "completed": false, "last": last, "next": next, "reason": reason,
                    "recurring_intervals_s": paper_recurring_intervals(*last),
                }),
            },
        });
        return Ok(json(&v));
    }
    let mut text = String::new();
    let _ = writeln!(
        text,
        "paper 003 §5: q1 = 2.477 − 1.5 sin t cos t, q2 = 3.549 − 1.25 sin t cos t, q3 = 5.895 − 2 sin t cos t, q4 = 5.331 + 1.5 sin t cos t (rad), t in [0, 2π] s, {steps} steps"
    );
    let _ = writeln!(
        text,
        "start: Table 1's assembly at q(0): C4 = ({:.3}, {:.3}) mm, θ = {:.3}°, φ = {:.3}°",
        start.c4.x,
        start.c4.y,
        start.theta.to_degrees(),
        start.phi.to_degrees()
    );
    match &report.end {
        TrajectoryEnd::Completed => {
            let _ = writeln!(
                text,
                "followed over the whole period ({} instants)",
                report.samples.len()
            );
        }
        TrajectoryEnd::Ceased { last, next, reason } => {
            let _ = writeln!(
                text,
                "followed to t = {last:.6} s ({} instants); not beyond t = {next:.6} s: {reason}",
                report.samples.len()
            );
            if let Some([_, b, c]) = paper_recurring_intervals(*last) {
                let _ = writeln!(
                    text,
                    "the inputs depend on t through sin 2t only: they take the values of [0, {last:.6}] again on [π/2 − t*, π + t*] = [{:.6}, {:.6}] and [3π/2 − t*, 2π] = [{:.6}, {:.6}] s (t* = {last:.6}); real assemblies exist there, none in between",
                    b.0, b.1, c.0, c.1
                );
            }
        }
    }
    if let Some(s) = report.samples.last() {
        let speeds: Vec<String> = s
            .corner_velocities
            .iter()
            .enumerate()
            .map(|(i, v)| format!("|Ċ{}| = {:.3}", i + 1, v.norm()))
            .collect();
        let _ = writeln!(
            text,
            "at the last instant t = {:.6} s: {} mm/s",
            s.t,
            speeds.join(", ")
        );
    }
    let _ = writeln!(text, "figure: {}", file.display());
    Ok(text)
}

/// The corner speeds against time, the end of the followed branch marked.
fn draw_speeds<DB: DrawingBackend>(
    report: &TrajectoryReport,
    root: &DrawingArea<DB, Shift>,
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let top = report
        .samples
        .iter()
        .flat_map(|s| s.corner_velocities.iter().map(nalgebra::Vector2::norm))
        .fold(1.0, f64::max)
        .min(1e6);
    // The followed branch only: up to its end (with a margin), or the whole period.
    let right = match report.end {
        TrajectoryEnd::Ceased { last, .. } => (last * 1.15).min(std::f64::consts::TAU),
        TrajectoryEnd::Completed => std::f64::consts::TAU,
    };
    let mut chart = ChartBuilder::on(root)
        .caption(
            "Paper 003 §5: corner speeds along the followed assembly",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..right, 0.0..top * 1.05)
        .map_err(draw_error)?;
    chart
        .configure_mesh()
        .x_desc("t (s)")
        .y_desc("|dC_i/dt| (mm/s)")
        .draw()
        .map_err(draw_error)?;
    for (i, colour) in [RED, BLUE, GREEN, MAGENTA].into_iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                report
                    .samples
                    .iter()
                    .map(|s| (s.t, s.corner_velocities[i].norm().min(top))),
                colour,
            ))
            .map_err(draw_error)?
            .label(format!("C{}", i + 1))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
    }
    if let TrajectoryEnd::Ceased { last, .. } = report.end {
        chart
            .draw_series(LineSeries::new(
                [(last, 0.0), (last, top * 1.05)],
                BLACK.stroke_width(1),
            ))
            .map_err(draw_error)?
            .label(format!("turning point, t = {last:.4} s"))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(draw_error)
}

/// `kinsyn plot inverse`: the input sets of a platform pose drawn one panel each (like paper
/// 003's Fig. 9), as `DIR/inverse-configurations.svg` (replacing an existing one only when
/// `force`); default the example of §5.
pub fn inverse(
    out: &Path,
    force: bool,
    centre: (f64, f64),
    theta: f64,
    phi: f64,
) -> Result<String, CliError> {
    let folder = OutputFolder::check("--out", out, [INVERSE_FIGURE], force)?;
    let m = Configurable::paper003();
    let pose = CentrePose {
        centre: Vector2::new(centre.0, centre.1),
        theta: theta.to_radians(),
        phi: phi.to_radians(),
    };
    let inverse = m
        .inverse_centre_pose(&pose)
        .map_err(|e| CliError::Input(e.to_string()))?;
    let sets = inverse.sets();
    let figure = svg((1000, 1000), |root| {
        draw_inverse(root, &m, &inverse, &sets, (centre, theta, phi))
    })?;
    folder.create(&[])?;
    let file = folder.write(INVERSE_FIGURE, figure.as_bytes())?;
    Ok(format!(
        "{} configurations of the inverse position (q in degrees in each panel)\nfigure: {}\n",
        sets.len(),
        file.display()
    ))
}

/// Fig. 9's panels: for each input set `q` of the pose, the legs (base, elbow, corner) in blue
/// and the platform in red, with the inputs in degrees.
fn draw_inverse<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    m: &Configurable,
    inverse: &InversePosition,
    sets: &[[f64; 4]],
    ((cx, cy), theta, phi): ((f64, f64), f64, f64),
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let root = root
        .titled(
            &format!("Paper 003 inverse position: C = ({cx}, {cy}) mm, θ = {theta}°, φ = {phi}° (eq. 11): {} configurations", sets.len()),
            ("sans-serif", 18),
        )
        .map_err(draw_error)?;
    for (panel, q) in root.split_evenly((4, 4)).iter().zip(sets) {
        let mut chart = ChartBuilder::on(panel)
            .margin(6)
            .build_cartesian_2d(-300.0..300.0, -300.0..300.0)
            .map_err(draw_error)?;
        let elbows = m.elbows(q);
        for ((a, b), c) in m.base.iter().zip(&elbows).zip(&inverse.corners) {
            chart
                .draw_series(LineSeries::new(
                    [(a.x, a.y), (b.x, b.y), (c.x, c.y)],
                    BLUE.stroke_width(2),
                ))
                .map_err(draw_error)?;
            chart
                .draw_series([Circle::new((a.x, a.y), 3, BLACK.filled())])
                .map_err(draw_error)?;
        }
        let c = inverse.corners;
        chart
            .draw_series(LineSeries::new(
                [c[0], c[1], c[2], c[3], c[0]].map(|p| (p.x, p.y)),
                RED.stroke_width(2),
            ))
            .map_err(draw_error)?;
        chart
            .draw_series([Text::new(
                format!(
                    "{:.1}, {:.1}, {:.1}, {:.1}",
                    q[0].to_degrees(),
                    q[1].to_degrees(),
                    q[2].to_degrees(),
                    q[3].to_degrees()
                ),
                (-290.0, 280.0),
                ("sans-serif", 11),
            )])
            .map_err(draw_error)?;
    }
    Ok(())
}
