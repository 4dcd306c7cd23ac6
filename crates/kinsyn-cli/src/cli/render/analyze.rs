//! The text of `kinsyn analyze`: the configuration analysed, how it was reached, its mobility,
//! Jacobians, ranks and singularities, from the [`AnalyzeReport`].

use kinsyn::manipulator::Manipulator;
use kinsyn_report::manipulator::{
    AnalyzeReport, RankReport, RelativeMotionReport, SeriesParallelReport, clean,
};
use std::fmt::Write as _;

/// The text report of `kinsyn analyze` for the manipulator `m` analysed.
pub(in crate::cli) fn text(m: &Manipulator, r: &AnalyzeReport) -> String {
    let mut s = study_text(r);
    s += &configuration_text(m, r);
    let several = m.bodies().len() > 1;
    if several {
        let dofs: Vec<String> = r
            .bodies
            .iter()
            .map(|b| format!("{} {}", b.name, b.dof))
            .collect();
        let _ = writeln!(
            s,
            "mobility {} (joint rates closing the loops); moving bodies' dof (twist spaces on the loop closure): {}; end-effector {:?}",
            r.mobility,
            dofs.join(", "),
            r.end_effector
        );
    } else {
        let _ = writeln!(
            s,
            "mobility {} (joint rates closing the loops), platform dof {} (6 − rank of the constraint wrenches; {} internal)",
            r.mobility,
            r.platform_dof,
            r.mobility.saturating_sub(r.platform_dof)
        );
    }
    let _ = writeln!(
        s,
        "loop closure: rank {} over {} free joint rates, gap {:.3e} kept / {:.3e} dropped",
        r.closure_rank.rank,
        r.closure_rank.rank + r.mobility,
        r.closure_rank.gap.smallest_kept,
        r.closure_rank.gap.largest_dropped,
    );
    if r.leg_wrench_jacobians {
        s += &jacobian_text(r);
    } else {
        s += &closure_io_text(m, r);
    }
    for (i, rank) in r.leg_ranks.iter().enumerate() {
        let _ = writeln!(
            s,
            "leg {} joint twists: {} (generic {})",
            i + 1,
            rank_text(rank),
            generic(rank)
        );
    }
    if r.constraint_rank.generic == Some(6) && r.locked == "-" {
        let _ = writeln!(
            s,
            "note: the constraint wrenches have rank 6 at every generic configuration: with every input free the platform cannot move (a structure, not a manipulator)"
        );
    }
    if let Some(sp) = &r.series_parallel {
        s += &series_text(m, sp);
    }
    if r.singularities.is_empty() {
        let _ = writeln!(s, "no singularity");
    }
    for sing in &r.singularities {
        let _ = writeln!(s, "singularity ({:?}): {}", sing.kind, sing.detail());
    }
    if let Some(rel) = &r.relative_motion {
        s += &relative_text(rel);
    }
    s
}

/// A rank decision in words: the rank, its gap and every singular value (as
/// [`kinsyn::manipulator::rank_text`] words a [`kinsyn::screw::Rank`]).
fn rank_text(r: &RankReport) -> String {
    format!(
        "rank {}, gap {:.3e} kept / {:.3e} dropped, singular values {}",
        r.rank,
        r.gap.smallest_kept,
        r.gap.largest_dropped,
        r.singular_values
            .iter()
            .map(|x| format!("{x:.3e}"))
            .collect::<Vec<_>>()
            .join(" ")
    )
}

/// The generic value a rank is compared with (0 where none is).
fn generic(r: &RankReport) -> usize {
    r.generic.unwrap_or(0)
}

/// The lines on `--study`: each pose's Study quadric residual, then with `--nearest` how far
/// the nearest assembly moved each body.
fn study_text(r: &AnalyzeReport) -> String {
    let mut s = String::new();
    for e in &r.study {
        let _ = writeln!(
            s,
            "--study {:?}: relative Study quadric residual |x·y|/(|x| |y|) = {:.3e} (tolerance {:.0e}, values printed to two decimals)",
            e.body, e.relative_quadric_residual, e.tolerance
        );
    }
    for n in r.study.iter().filter_map(|e| e.nearest.as_ref()) {
        let (length, angle, rounding) = (&n.length_unit, n.angle_unit, n.rounding);
        let _ = writeln!(
            s,
            "--nearest {:?}: moved {:.3e} {length} and {:.3e} {angle} from its --study pose (rounding each parameter by {rounding} explains up to {:.3e} {length} and {:.3e} {angle})",
            n.body, n.translation, n.rotation, n.translation_bound, n.rotation_bound,
        );
    }
    s
}

/// The opening lines of `analyze`: the configuration analysed (the end-effector's point P and
/// rotation vector, the locked inputs), how it was reached from the start, and the input
/// values.
fn configuration_text(m: &Manipulator, r: &AnalyzeReport) -> String {
    let mut s = String::new();
    let [px, py, pz] = r.point;
    // In the description's angle unit, as `--pose` takes it and `modes` prints it.
    let [rx, ry, rz] = r
        .platform_rotation_vector_rad
        .map(|a| m.units().angle.from_radians(a));
    let title = if m.bodies().len() > 1 {
        format!("{}, end-effector {:?}", r.manipulator, r.end_effector)
    } else {
        r.manipulator.clone()
    };
    let _ = writeln!(
        s,
        "{title}: P = [{:.6}, {:.6}, {:.6}] {}; platform rotation vector [{:.6}, {:.6}, {:.6}] {}; locked: {}",
        clean(px),
        clean(py),
        clean(pz),
        r.units.length,
        clean(rx),
        clean(ry),
        clean(rz),
        m.units().angle.symbol(),
        r.locked
    );
    if !r.continuous_with_start {
        let _ = writeln!(
            s,
            "reached from {} by damped Newton steps, not by continuation: the path of the values from the start leaves the workspace or meets a singularity, so this may be another assembly mode than the start's",
            r.reached_from
        );
    } else if r.continuation_steps > 0 || r.start_given {
        let _ = writeln!(
            s,
            "reached from {} in {} continuation step{}: the assembly continuous with it (another start, --from POSE, may give another assembly)",
            r.reached_from,
            r.continuation_steps,
            if r.continuation_steps == 1 { "" } else { "s" }
        );
    }
    // In the order of the inputs, not of their labels.
    let values: Vec<String> = m
        .actuators()
        .iter()
        .filter_map(|a| {
            let label = a.label();
            let v = *r.input_values.get(&label)?;
            Some(format!("{label} = {:.6}", clean(v)))
        })
        .collect();
    let _ = writeln!(
        s,
        "input values (from the reference; {}, angles in {}): {}",
        r.units.length,
        r.units.angle.name(),
        values.join(", ")
    );
    s
}

/// `J_D [v_P; ω] = J_I q̇` row by row, and the ranks of `J_D` and of the constraint rows.
fn jacobian_text(r: &AnalyzeReport) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "J_D [v_P; ω] = J_I [{}]   (rows: wrenches (f; m_P) at P; J_I column of the row's input)",
        r.inputs.join(" ")
    );
    for row in &r.rows {
        let cells: Vec<String> = row
            .jd
            .iter()
            .map(|&x| format!("{:>10.6}", clean(x)))
            .collect();
        let _ = writeln!(s, "  {:<20} [{}] | {:.6}", row.row, cells.join(" "), row.ji);
    }
    let _ = writeln!(
        s,
        "J_D: {} (generic {})",
        rank_text(&r.jd_rank),
        generic(&r.jd_rank)
    );
    let _ = writeln!(
        s,
        "constraint rows: {} (generic {})",
        rank_text(&r.constraint_rank),
        generic(&r.constraint_rank)
    );
    s
}

/// What replaces `J_D`, `J_I` when the legs do not all run from the ground to the end-effector:
/// why they are not defined, and the end-effector's input–output freedoms from the loop
/// closure (docs/manipulators.md, "Several moving bodies").
fn closure_io_text(m: &Manipulator, r: &AnalyzeReport) -> String {
    let mut s = String::new();
    let ee = m.platform();
    let off: Vec<String> = m
        .legs()
        .iter()
        .enumerate()
        .filter(|(_, l)| l.from != m.mechanism().ground() || l.to != ee)
        .map(|(i, l)| {
            format!(
                "leg {} {} → {}",
                i + 1,
                m.mechanism().body_name(l.from),
                m.mechanism().body_name(l.to)
            )
        })
        .collect();
    let _ = writeln!(
        s,
        "J_D, J_I: not defined: paper 000's leg wrenches act on the end-effector only when every leg runs from the ground to it, and {} do not; from the loop-closure Jacobian instead:",
        off.join(", ")
    );
    let plural = |n: usize| if n == 1 { "" } else { "s" };
    let held = 6 - r.jd_rank.rank;
    let generic_held = 6 - generic(&r.jd_rank);
    let _ = writeln!(
        s,
        "  with every input held, the end-effector keeps {held} dof (generic {generic_held}; 0 when the inputs fix it)"
    );
    let _ = writeln!(
        s,
        "  with the locked inputs held, the end-effector has {} dof: constraint wrenches of rank {} (generic {})",
        r.platform_dof,
        r.constraint_rank.rank,
        generic(&r.constraint_rank)
    );
    let held = &r.inputs_with_end_effector_held;
    let _ = writeln!(
        s,
        "  with the end-effector held, the free inputs [{}] keep {} independent rate{} (generic {})",
        r.inputs.join(" "),
        held.here,
        plural(held.here),
        held.generic
    );
    s
}

/// The paper 002 lines: the stack's twist-system order, `J_S-PM`, its constraint wrenches and
/// each module's forward Jacobian.
fn series_text(m: &Manipulator, sp: &SeriesParallelReport) -> String {
    let mut s = String::new();
    let order = &sp.twist_system_order;
    let _ = writeln!(
        s,
        "series-parallel stack of {} three-legged modules (paper 002): twist-system order {} (eqs. 9–10: {})",
        sp.modules.len(),
        order.rank,
        rank_text(order)
    );
    match (&sp.jacobian_rank, &sp.jacobian_error) {
        (Some(rank), _) => {
            let _ = writeln!(
                s,
                "  J_S-PM (eqs. 7–8, twist (ω; v) of the end-effector origin per input rate): {}",
                rank_text(rank)
            );
        }
        (None, e) => {
            let _ = writeln!(
                s,
                "  J_S-PM not defined here: {}",
                e.as_deref().unwrap_or_default()
            );
        }
    }
    if order.rank < 6 {
        let _ = writeln!(
            s,
            "  constraint wrench system of the stack (order {}, reciprocal to every end-effector twist; a basis, moments about the ground origin, {}):",
            6 - order.rank,
            m.units().length
        );
        for w in &sp.constraint_wrenches_f_m_about_ground_origin {
            let _ = writeln!(
                s,
                "    {}",
                wrench_text(
                    &kinsyn::screw::Wrench::from_vector(&nalgebra::Vector6::from(*w)),
                    m.mechanism().scale()
                )
            );
        }
    }
    for (i, module) in sp.modules.iter().enumerate() {
        let _ = writeln!(
            s,
            "  module {} forward Jacobian A (eqs. 2–3, actuation and constraint wrenches): {}",
            i + 1,
            rank_text(&module.forward_jacobian_rank)
        );
    }
    s
}

/// A wrench in words: a couple about a direction, a force along a line, or a wrench of some
/// pitch along a line (`length` the mechanism's characteristic length, for what counts as 0).
fn wrench_text(w: &kinsyn::screw::Wrench, length: f64) -> String {
    let ff = w.f.norm_squared();
    let size = (ff.sqrt() * length).max(w.m.norm());
    // Four decimals, round-off (below 5e-5 of the characteristic length) written as 0.
    let c = |x: f64| {
        if x.abs() < 5e-5 * length.max(1.0) {
            0.0
        } else {
            x
        }
    };
    let v = |x: nalgebra::Vector3<f64>| format!("[{:.4}, {:.4}, {:.4}]", c(x.x), c(x.y), c(x.z));
    if ff.sqrt() * length < 1e-9 * size {
        return format!("a couple about {}", v(w.m.normalize()));
    }
    let pitch = w.f.dot(&w.m) / ff;
    let point = w.f.cross(&w.m) / ff;
    let direction = w.f.normalize();
    if pitch.abs() < 1e-9 * length {
        format!("a force along {} through {}", v(direction), v(point))
    } else {
        format!(
            "a wrench of pitch {pitch:.4} along {} through {}",
            v(direction),
            v(point)
        )
    }
}

/// The line on the motion relative to the body of `--relative-to`.
fn relative_text(r: &RelativeMotionReport) -> String {
    let (body, base) = (&r.body, &r.relative_to);
    let what = match (r.dof, r.rotations) {
        (0, _) => "it does not move relative to it".to_string(),
        (_, 0) => format!(
            "every relative twist is a translation ({body:?} and {base:?} have the same angular velocity)"
        ),
        (_, 1) => "1 independent relative angular velocity".to_string(),
        (_, k) => format!("{k} independent relative angular velocities"),
    };
    let mut s = format!(
        "motion of {body:?} relative to {base:?}: {} dof; {what}; twist basis (v of {body:?}'s point; ω), in the frame of {base:?} at the reference:",
        r.dof
    );
    for t in &r.twists_at_point {
        let t: Vec<String> = t.iter().map(|x| format!("{:.6}", clean(*x))).collect();
        let _ = write!(s, " [{}]", t.join(", "));
    }
    s.push('\n');
    s
}
