//! `kinsyn plot workspace` and `kinsyn plot indices`: paper 001's Figs. 3 and 4 (the HEXA with
//! reconfigurable platforms) drawn by kinsyn, as SVG and PNG.

use super::args::HexaPlot;
use super::output::OutputFolder;
use super::plot::{draw_error, png, register_font, svg};
use super::{CliError, json, terminal};
use kinsyn_papers::hexa::{
    Cylinder, Hexa, IndexMap, IndexMapSettings, Indices, Workspace, WorkspaceError,
    WorkspaceSettings,
};
use nalgebra::Vector3;
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;

/// The HEXA a description file holds (`Hexa::from_description`: its dimensions read and the
/// whole file checked against a fresh copy), or a one-line refusal naming the file.
fn hexa_geometry(file: &Path) -> Result<Hexa, CliError> {
    let d = super::manipulator::load_description(file)?;
    Hexa::from_description(&d).map_err(|e| CliError::Input(format!("{}: {e}", file.display())))
}

/// A refusal of the workspace search as bad input.
fn input_error(e: &WorkspaceError) -> CliError {
    CliError::Input(e.to_string())
}

/// An orientation given in degrees, checked (finite, within ±180°), in radians.
fn angle(name: &str, degrees: f64) -> Result<f64, CliError> {
    if degrees.is_finite() && degrees.abs() <= 180.0 {
        Ok(degrees.to_radians())
    } else {
        Err(CliError::Input(format!(
            "{name} {degrees}: give an angle in degrees from -180 to 180"
        )))
    }
}

/// A grid step in mm, checked (finite, positive).
fn step(name: &str, mm: f64) -> Result<f64, CliError> {
    if mm.is_finite() && mm > 0.0 {
        Ok(mm)
    } else {
        Err(CliError::Input(format!(
            "{name} {mm}: give a positive length in mm"
        )))
    }
}

/// Runs `work` with a progress bar over its rows on stderr.
fn with_progress<T>(message: &str, work: impl FnOnce(kinsyn_papers::hexa::Progress<'_>) -> T) -> T {
    let bar = terminal::progress(0, "rows", message);
    let result = work(&|_, total| {
        bar.set_length(total as u64);
        bar.inc(1);
    });
    bar.finish_and_clear();
    result
}

/// `(min, mean, max)` of the values, `None` for none.
fn statistics(values: &[f64]) -> Option<(f64, f64, f64)> {
    if values.is_empty() {
        return None;
    }
    let min = values.iter().copied().fold(f64::INFINITY, f64::min);
    let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Some((min, values.iter().sum::<f64>() / values.len() as f64, max))
}

fn statistics_json(values: &[f64]) -> serde_json::Value {
    statistics(values).map_or(
        serde_json::Value::Null,
        |(min, mean, max)| serde_json::json!({"min": min, "mean": mean, "max": max}),
    )
}

fn cylinder_json(c: Option<&Cylinder>) -> serde_json::Value {
    c.map_or(serde_json::Value::Null, |c| {
        serde_json::json!({
            "radius": c.radius,
            "z_lo": c.z_lo,
            "z_hi": c.z_hi,
            "volume_mm3": c.volume(),
        })
    })
}

/// The files of the figures `names`, each as `NAME.svg` and `NAME.png`.
fn figure_files(names: &[&str]) -> Vec<String> {
    names
        .iter()
        .flat_map(|n| [format!("{n}.svg"), format!("{n}.png")])
        .collect()
}

/// Draws one figure by `$draw(root, args…)` as SVG and PNG, the same picture, and writes them
/// into `$folder` as `NAME.svg` and `NAME.png`; their paths. (A macro: `$draw` is generic over
/// the drawing backend, which a closure cannot be.)
macro_rules! svg_and_png {
    ($folder:expr, $name:expr, $size:expr, $draw:ident ( $($arg:expr),* )) => {{
        let svg_text = svg($size, |root| $draw(root, $($arg),*))?;
        let png_bytes = png($size, |root| $draw(root, $($arg),*))?;
        [
            $folder.write(format!("{}.svg", $name), svg_text.as_bytes())?,
            $folder.write(format!("{}.png", $name), &png_bytes)?,
        ]
    }};
}

/// `kinsyn plot workspace`: the reachable workspaces of both end-effectors (Fig. 3b) as three
/// sections with the regular common workspace, and the positions of end-effector 2 relative to
/// end-effector 1 (Fig. 3a); existing figures are replaced only with `--force`.
pub fn workspace(hexa: &HexaPlot, step_mm: f64, as_json: bool) -> Result<String, CliError> {
    let (file, phi) = (&hexa.file, (hexa.phi1, hexa.phi2));
    let (phi1, phi2) = (angle("--phi1", phi.0)?, angle("--phi2", phi.1)?);
    let settings = WorkspaceSettings {
        step: step("--step", step_mm)?,
        phi1,
        phi2,
        ..WorkspaceSettings::default()
    };
    let h = hexa_geometry(file)?;
    h.workspace_grid(settings.step)
        .map_err(|e| input_error(&e))?;
    let folder = OutputFolder::check(
        "--out",
        &hexa.out,
        figure_files(&["hexa-workspace", "hexa-four-bar"]),
        hexa.force.force,
    )?;
    register_font();
    let w = with_progress("reachable workspace", |p| h.workspace(&settings, p))
        .map_err(|e| input_error(&e))?;
    let cylinder = w.regular_cylinder();
    let z = cylinder.map_or(-0.5 * (h.b + h.l), |c| c.middle());
    let p1 = Vector3::new(0.0, 0.0, z);
    let curve = h.end_effector2_positions(&p1, phi1, phi2, 720);
    folder.create(&[])?;
    let mut files = Vec::new();
    files.extend(svg_and_png!(
        folder,
        "hexa-workspace",
        (1500, 560),
        draw_workspace(&w, cylinder.as_ref(), phi)
    ));
    files.extend(svg_and_png!(
        folder,
        "hexa-four-bar",
        (900, 720),
        draw_four_bar(&h, &p1, phi, &curve)
    ));
    let (n1, n2) = (w.points(0).len(), w.points(1).len());
    let reachable = curve.iter().filter(|(_, r)| *r).count();
    if as_json {
        return Ok(json(&serde_json::json!({
            "geometry": geometry_json(&h),
            "phi1_deg": phi.0,
            "phi2_deg": phi.1,
            "grid": {
                "step": w.grid.step,
                "half_width": w.grid.n as f64 * w.grid.step,
                "layers": w.grid.layers,
                "z_min": -((w.grid.layers - 1) as f64) * w.grid.step,
                "cells": w.grid.cells(),
            },
            "end_effector1": {"cells": n1, "volume_mm3": w.volume(0)},
            "end_effector2": {"cells": n2, "volume_mm3": w.volume(1)},
            "cylinder": cylinder_json(cylinder.as_ref()),
            "four_bar": {"p1": [p1.x, p1.y, p1.z], "points": curve.len(), "reachable": reachable},
            "figures": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        })));
    }
    let mut text = String::new();
    let _ = writeln!(
        text,
        "paper 001 HEXA, φ1 = {}°, φ2 = {}°, grid step {} mm ({} cells)",
        phi.0,
        phi.1,
        w.grid.step,
        w.grid.cells()
    );
    let _ = writeln!(
        text,
        "end-effector 1: {n1} cells, {:.4e} mm³; end-effector 2: {n2} cells, {:.4e} mm³",
        w.volume(0),
        w.volume(1)
    );
    match cylinder {
        Some(c) => {
            let _ = writeln!(
                text,
                "regular common workspace: cylinder radius {:.1} mm, z from {:.1} to {:.1} mm, {:.4e} mm³",
                c.radius,
                c.z_lo,
                c.z_hi,
                c.volume()
            );
        }
        None => {
            let _ = writeln!(text, "regular common workspace: none");
        }
    }
    let _ = writeln!(
        text,
        "end-effector 2 relative to P1 = (0, 0, {z:.1}): {} coupler points, {reachable} reached by limbs 4 and 5",
        curve.len()
    );
    for f in &files {
        let _ = writeln!(text, "figure: {}", f.display());
    }
    Ok(text)
}

fn geometry_json(h: &Hexa) -> serde_json::Value {
    serde_json::json!({
        "R": h.big_r, "a": h.a, "b": h.b, "l": h.l, "r": h.r, "gamma_deg": h.gamma.to_degrees(),
    })
}

const GREEN_CELL: RGBColor = RGBColor(40, 160, 60);
const RED_CELL: RGBColor = RGBColor(210, 40, 40);

#[allow(
    clippy::too_many_lines,
    reason = "one figure: three panels, their cells, outlines and legend"
)]
/// Fig. 3(b) as three sections: `x–z` at `y = 0`, `y–z` at `x = 0` and `x–y` at the cylinder's
/// middle layer; green end-effector 1, red end-effector 2, the cylinder in black.
fn draw_workspace<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    w: &Workspace,
    cylinder: Option<&Cylinder>,
    phi: (f64, f64),
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let root = root
        .titled(
            &format!(
                "Paper 001 HEXA: reachable workspaces at φ1 = {}°, φ2 = {}° (grid {} mm); green P1, red P2, black the regular common cylinder",
                phi.0, phi.1, w.grid.step
            ),
            ("sans-serif", 18),
        )
        .map_err(draw_error)?;
    let g = w.grid;
    let side = g.side();
    let half = g.n as f64 * g.step;
    let extent = w
        .points(0)
        .iter()
        .chain(&w.points(1))
        .fold(g.step, |m, p| m.max(p.x.abs()).max(p.y.abs()))
        + 2.0 * g.step;
    let extent = extent.min(half + g.step);
    let bottom = -((g.layers - 1) as f64 + 1.0) * g.step;
    let middle_layer = cylinder.map_or(g.layers / 2, |c| {
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a layer index within the grid"
        )]
        let k = (-c.middle() / g.step).round().max(0.0) as usize;
        k.min(g.layers - 1)
    });
    let panels = root.split_evenly((1, 3));
    let s = g.step / 2.0;
    for (p, panel) in panels.iter().enumerate() {
        let (caption, x_desc, y_desc) = match p {
            0 => ("section y = 0", "x (mm)", "z (mm)"),
            1 => ("section x = 0", "y (mm)", "z (mm)"),
            _ => ("", "x (mm)", "y (mm)"),
        };
        let caption = if p == 2 {
            format!("section z = {} mm", -(middle_layer as f64) * g.step)
        } else {
            caption.to_string()
        };
        let (y_range, cells): (std::ops::Range<f64>, Vec<(usize, f64, f64)>) = match p {
            0 => (
                bottom..g.step,
                (0..g.layers)
                    .flat_map(|k| (0..side).map(move |i| (g.index(i, g.n, k), i, k)))
                    .map(|(index, i, k)| {
                        let c = g.centre(i, g.n, k);
                        (index, c.x, c.z)
                    })
                    .collect(),
            ),
            1 => (
                bottom..g.step,
                (0..g.layers)
                    .flat_map(|k| (0..side).map(move |j| (g.index(g.n, j, k), j, k)))
                    .map(|(index, j, k)| {
                        let c = g.centre(g.n, j, k);
                        (index, c.y, c.z)
                    })
                    .collect(),
            ),
            _ => (
                -extent..extent,
                (0..side)
                    .flat_map(|j| (0..side).map(move |i| (i, j)))
                    .map(|(i, j)| {
                        let c = g.centre(i, j, middle_layer);
                        (g.index(i, j, middle_layer), c.x, c.y)
                    })
                    .collect(),
            ),
        };
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d(-extent..extent, y_range)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(draw_error)?;
        // End-effector 2 over the whole cell, end-effector 1 over its upper-left half: where
        // both are reachable the cell shows both colours.
        chart
            .draw_series(cells.iter().filter(|c| w.end_effector2[c.0]).map(|c| {
                Rectangle::new([(c.1 - s, c.2 - s), (c.1 + s, c.2 + s)], RED_CELL.filled())
            }))
            .map_err(draw_error)?
            .label("end-effector 2 (P2)")
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], RED_CELL.filled()));
        chart
            .draw_series(cells.iter().filter(|c| w.end_effector1[c.0]).map(|c| {
                Polygon::new(
                    vec![(c.1 - s, c.2 - s), (c.1 - s, c.2 + s), (c.1 + s, c.2 + s)],
                    GREEN_CELL.filled(),
                )
            }))
            .map_err(draw_error)?
            .label("end-effector 1 (P1)")
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], GREEN_CELL.filled()));
        if let Some(c) = cylinder {
            let outline: Vec<(f64, f64)> = if p == 2 {
                (0..=120)
                    .map(|t| {
                        let a = std::f64::consts::TAU * f64::from(t) / 120.0;
                        (c.radius * a.cos(), c.radius * a.sin())
                    })
                    .collect()
            } else {
                vec![
                    (-c.radius, c.z_lo),
                    (c.radius, c.z_lo),
                    (c.radius, c.z_hi),
                    (-c.radius, c.z_hi),
                    (-c.radius, c.z_lo),
                ]
            };
            chart
                .draw_series(LineSeries::new(outline, BLACK.stroke_width(3)))
                .map_err(draw_error)?
                .label("regular common workspace")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 12, y)], BLACK.stroke_width(3))
                });
        }
        if p == 0 {
            legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
        }
    }
    Ok(())
}

/// Fig. 3(a): the positions of `P2` relative to `P1` on the coupler curve (red where limbs 4
/// and 5 reach, grey elsewhere), with end-effector 1, the sub-platforms and the four-bar at its
/// nominal assembly.
fn draw_four_bar<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    h: &Hexa,
    p1: &Vector3<f64>,
    phi: (f64, f64),
    curve: &[(nalgebra::Vector2<f64>, bool)],
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let phi1 = phi.0.to_radians();
    let joints = h.platform_joints(&kinsyn_papers::hexa::Pose::new(p1, phi1, p1, 0.0));
    let rel = |v: &Vector3<f64>| (v.x - p1.x, v.y - p1.y);
    // The sub-platforms' span in x, and the four-bar's in y, with a margin; equal scales.
    let half = h.r[0] + h.r[1] + 0.5 * (h.r[2] + h.r[3]);
    let mut chart = ChartBuilder::on(root)
        .caption(
            format!(
                "Paper 001 Fig. 3(a): P2 relative to P1 = (0, 0, {:.0}) mm, φ1 = {}°, φ2 = {}°",
                p1.z, phi.0, phi.1
            ),
            ("sans-serif", 17),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d(-half..half, -1.1 * half..0.5 * half)
        .map_err(draw_error)?;
    chart
        .configure_mesh()
        .x_desc("x2 − x1 (mm)")
        .y_desc("y2 − y1 (mm)")
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(draw_error)?;
    chart
        .draw_series(
            curve
                .iter()
                .filter(|(_, r)| !*r)
                .map(|(p, _)| Circle::new((p.x, p.y), 2, RGBColor(170, 170, 170).filled())),
        )
        .map_err(draw_error)?
        .label("coupler curve, limbs 4, 5 out of reach")
        .legend(|(x, y)| Circle::new((x + 6, y), 3, RGBColor(170, 170, 170).filled()));
    chart
        .draw_series(
            curve
                .iter()
                .filter(|(_, r)| *r)
                .map(|(p, _)| Circle::new((p.x, p.y), 2, RED_CELL.filled())),
        )
        .map_err(draw_error)?
        .label("possible positions of P2 (coupler curve, limbs 4, 5 reach)")
        .legend(|(x, y)| Circle::new((x + 6, y), 3, RED_CELL.filled()));
    // End-effector 1 (C1–C2) and the sub-platforms' arms (C2–C3, C1–C6).
    chart
        .draw_series(LineSeries::new(
            [
                rel(&joints[2]),
                rel(&joints[1]),
                rel(&joints[0]),
                rel(&joints[5]),
            ],
            GREEN_CELL.stroke_width(4),
        ))
        .map_err(draw_error)?
        .label("end-effector 1 and sub-platforms: C3–C2–C1–C6")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 12, y)], GREEN_CELL.stroke_width(4)));
    if let Some(n) = h.nominal_four_bar(p1, phi1) {
        chart
            .draw_series(LineSeries::new(
                [rel(&joints[2]), rel(&n.d3), rel(&n.d6), rel(&joints[5])],
                BLUE.stroke_width(2),
            ))
            .map_err(draw_error)?
            .label("four-bar C3–D3–D6–C6 at the nominal assembly")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 12, y)], BLUE.stroke_width(2)));
        chart
            .draw_series([Circle::new(rel(&n.p2), 5, BLUE.filled())])
            .map_err(draw_error)?
            .label("nominal P2")
            .legend(|(x, y)| Circle::new((x + 6, y), 4, BLUE.filled()));
    }
    chart
        .draw_series([Circle::new((0.0, 0.0), 5, GREEN_CELL.filled())])
        .map_err(draw_error)?
        .label("P1")
        .legend(|(x, y)| Circle::new((x + 6, y), 4, GREEN_CELL.filled()));
    legend(&mut chart, SeriesLabelPosition::LowerMiddle)?;
    Ok(())
}

/// The figures' legend box, at `position`.
fn legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    position: SeriesLabelPosition,
) -> Result<(), CliError> {
    chart
        .configure_series_labels()
        .position(position)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(draw_error)
}

/// The index maps' settings from the command line.
pub struct IndexOptions {
    /// `(φ1, φ2)` in degrees.
    pub phi: (f64, f64),
    /// The height, default the regular workspace's middle.
    pub z: Option<f64>,
    /// The map's step (mm).
    pub step: f64,
    /// The workspace search's step (mm).
    pub workspace_step: f64,
}

#[allow(
    clippy::too_many_lines,
    reason = "one command: checks, searches, statistics, figure and report"
)]
/// `kinsyn plot indices`: `λ_min`, `σ` and `ξ_min` over the regular common workspace at one
/// height (Fig. 4), end-effector 2 at the four-bar's nominal assembly; an existing figure is
/// replaced only with `--force`.
pub fn indices(hexa: &HexaPlot, options: &IndexOptions, as_json: bool) -> Result<String, CliError> {
    let file = &hexa.file;
    let (phi1, phi2) = (
        angle("--phi1", options.phi.0)?,
        angle("--phi2", options.phi.1)?,
    );
    let map_step = step("--step", options.step)?;
    let settings = WorkspaceSettings {
        step: step("--workspace-step", options.workspace_step)?,
        phi1,
        phi2,
        ..WorkspaceSettings::default()
    };
    let h = hexa_geometry(file)?;
    h.workspace_grid(settings.step)
        .map_err(|e| input_error(&e))?;
    if let Some(z) = options.z
        && !(z.is_finite() && (-(h.b + h.l)..=0.0).contains(&z))
    {
        return Err(CliError::Input(format!(
            "--z {z}: give a height in mm from {} to 0",
            -(h.b + h.l)
        )));
    }
    let folder = OutputFolder::check(
        "--out",
        &hexa.out,
        figure_files(&["hexa-indices"]),
        hexa.force.force,
    )?;
    register_font();
    let w = with_progress("reachable workspace", |p| h.workspace(&settings, p))
        .map_err(|e| input_error(&e))?;
    let cylinder = w.regular_cylinder().ok_or_else(|| {
        CliError::Input(format!(
            "no regular common workspace at φ1 = {}°, φ2 = {}°",
            options.phi.0, options.phi.1
        ))
    })?;
    let z = options.z.unwrap_or_else(|| cylinder.middle());
    let map_settings = IndexMapSettings {
        z,
        half_width: cylinder.radius,
        step: map_step,
        phi1,
        phi2,
    };
    let map = with_progress("index map", |p| h.index_map(&map_settings, p))
        .map_err(|e| input_error(&e))?;
    let radius = cylinder.radius;
    let inside: Vec<(f64, f64, Option<&Indices>)> = map
        .iter()
        .filter(|(x, y, _)| x.hypot(*y) <= radius)
        .collect();
    let values = |f: &dyn Fn(&Indices) -> f64, keep: &dyn Fn(f64) -> bool| -> Vec<f64> {
        inside
            .iter()
            .filter(|c| keep(c.1))
            .filter_map(|c| c.2.map(f))
            .collect()
    };
    let all = |_: f64| true;
    let south = |y: f64| y <= 0.0;
    let north = |y: f64| y > 0.0;
    let lambda = |i: &Indices| i.lambda_min();
    let sigma = |i: &Indices| i.sigma;
    let xi = |i: &Indices| i.xi_min();
    let assemblable = inside.iter().filter(|c| c.2.is_some()).count();
    folder.create(&[])?;
    let files = svg_and_png!(
        folder,
        "hexa-indices",
        (1560, 560),
        draw_indices(&map, radius, options.phi)
    );
    if as_json {
        let half = |keep: &dyn Fn(f64) -> bool| {
            serde_json::json!({
                "lambda_min": statistics_json(&values(&lambda, keep)),
                "sigma": statistics_json(&values(&sigma, keep)),
                "xi_min": statistics_json(&values(&xi, keep)),
            })
        };
        return Ok(json(&serde_json::json!({
            "geometry": geometry_json(&h),
            "phi1_deg": options.phi.0,
            "phi2_deg": options.phi.1,
            "z": z,
            "step": map_step,
            "workspace_step": settings.step,
            "cylinder": cylinder_json(Some(&cylinder)),
            "cells": inside.len(),
            "assemblable": assemblable,
            "all": half(&all),
            "y_le_0": half(&south),
            "y_gt_0": half(&north),
            "figures": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        })));
    }
    let mut text = String::new();
    let _ = writeln!(
        text,
        "paper 001 HEXA, φ1 = {}°, φ2 = {}°, z = {z:.1} mm, P1 over the disc of radius {radius:.1} mm (regular common workspace, z from {:.1} to {:.1} mm), step {map_step} mm, end-effector 2 at the nominal four-bar assembly",
        options.phi.0, options.phi.1, cylinder.z_lo, cylinder.z_hi
    );
    let _ = writeln!(text, "{} cells, {assemblable} assemblable", inside.len());
    for (name, f) in [
        ("λ_min", &lambda as &dyn Fn(&Indices) -> f64),
        ("σ", &sigma),
        ("ξ_min", &xi),
    ] {
        let line = [
            ("all", &all as &dyn Fn(f64) -> bool),
            ("y ≤ 0", &south),
            ("y > 0", &north),
        ]
        .iter()
        .map(|(part, keep)| match statistics(&values(f, keep)) {
            Some((min, mean, max)) => {
                format!("{part}: min {min:.3}, mean {mean:.3}, max {max:.3}")
            }
            None => format!("{part}: none"),
        })
        .collect::<Vec<_>>()
        .join("; ");
        let _ = writeln!(text, "{name}: {line}");
    }
    for f in &files {
        let _ = writeln!(text, "figure: {}", f.display());
    }
    Ok(text)
}

/// The colour of an index band: bands of 0.1 from 0 to 1, dark blue (0) to yellow (1).
fn band_colour(value: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 5] = [
        (68, 1, 84),
        (59, 82, 139),
        (33, 145, 140),
        (94, 201, 98),
        (253, 231, 37),
    ];
    let band = band(value);
    let t = (f64::from(band) + 0.5) / 10.0 * 4.0;
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "t in [0, 4]"
    )]
    let k = (t.floor() as usize).min(3);
    let f = t - k as f64;
    let mix = |a: u8, b: u8| {
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "between two bytes"
        )]
        let c = (f64::from(a) + (f64::from(b) - f64::from(a)) * f).round() as u8;
        c
    };
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The band `0 … 9` of a value in `[0, 1]`.
fn band(value: f64) -> u8 {
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "clamped to 0..=9"
    )]
    let b = (value * 10.0).floor().clamp(0.0, 9.0) as u8;
    b
}

#[allow(
    clippy::too_many_lines,
    reason = "one figure: three banded panels and the colour bar"
)]
/// Fig. 4: the three index maps side by side, banded by 0.1, with a colour bar.
fn draw_indices<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    map: &IndexMap,
    radius: f64,
    phi: (f64, f64),
) -> Result<(), CliError> {
    root.fill(&WHITE).map_err(draw_error)?;
    let root = root
        .titled(
            &format!(
                "Paper 001 HEXA: transmission indices over the regular workspace, z = {:.0} mm, φ1 = {}°, φ2 = {}° (P2 at the nominal four-bar assembly)",
                map.z, phi.0, phi.1
            ),
            ("sans-serif", 18),
        )
        .map_err(draw_error)?;
    let (maps, bar) = root.split_horizontally(root.dim_in_pixel().0 - 110);
    let step = if map.xs.len() > 1 {
        map.xs[1] - map.xs[0]
    } else {
        1.0
    };
    let s = step / 2.0;
    let edge = radius + step;
    let width = map.xs.len();
    for (p, panel) in maps.split_evenly((1, 3)).iter().enumerate() {
        let (title, f): (&str, fn(&Indices) -> f64) = match p {
            0 => ("input index λ_min (eq. 13)", Indices::lambda_min),
            1 => ("output index σ of end-effector 1 (eq. 16)", |i| i.sigma),
            _ => (
                "output index ξ_min of end-effector 2 (eq. 17)",
                Indices::xi_min,
            ),
        };
        let mut chart = ChartBuilder::on(panel)
            .caption(title, ("sans-serif", 15))
            .margin(8)
            .x_label_area_size(36)
            .y_label_area_size(52)
            .build_cartesian_2d(-edge..edge, -edge..edge)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x1 (mm)")
            .y_desc("y1 (mm)")
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(draw_error)?;
        // Runs of equal band along each row, one rectangle each.
        let mut rects = Vec::new();
        for (j, y) in map.ys.iter().enumerate() {
            let mut run: Option<(usize, u8)> = None;
            for i in 0..=width {
                let here = (i < width)
                    .then(|| {
                        let x = map.xs[i];
                        if x.hypot(*y) > radius {
                            return None;
                        }
                        map.cells[j * width + i].as_ref().map(|c| band(f(c)))
                    })
                    .flatten();
                if run.map(|r| r.1) != here {
                    if let Some((start, b)) = run {
                        rects.push(Rectangle::new(
                            [(map.xs[start] - s, y - s), (map.xs[i - 1] + s, y + s)],
                            band_colour((f64::from(b) + 0.5) / 10.0).filled(),
                        ));
                    }
                    run = here.map(|b| (i, b));
                }
            }
        }
        chart.draw_series(rects).map_err(draw_error)?;
        chart
            .draw_series(LineSeries::new(
                (0..=120).map(|t| {
                    let a = std::f64::consts::TAU * f64::from(t) / 120.0;
                    (radius * a.cos(), radius * a.sin())
                }),
                BLACK.stroke_width(1),
            ))
            .map_err(draw_error)?;
    }
    let mut scale = ChartBuilder::on(&bar)
        .caption("index", ("sans-serif", 14))
        .margin_top(40)
        .margin_bottom(50)
        .margin_right(40)
        .y_label_area_size(40)
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)
        .map_err(draw_error)?;
    scale
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(11)
        .y_label_formatter(&|v| format!("{v:.1}"))
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(draw_error)?;
    scale
        .draw_series((0..10).map(|b| {
            let lo = f64::from(b) / 10.0;
            Rectangle::new(
                [(0.0, lo), (1.0, lo + 0.1)],
                band_colour(lo + 0.05).filled(),
            )
        }))
        .map_err(draw_error)?;
    Ok(())
}
