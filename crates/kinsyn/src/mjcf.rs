//! MuJoCo export: a manipulator as an MJCF model (docs/export.md).
//!
//! MuJoCo simulates trees of bodies; the loops of a parallel manipulator are closed by equality
//! constraints. The export chooses a spanning tree of the mechanism that keeps every input and
//! every slider in the tree, so that the joints left over (the chords, one per loop) are
//! passive revolutes wherever the mechanism allows it:
//!
//! - a tree joint is a `<joint type="hinge|slide">` of the body it reaches, with its axis and
//!   point in that body's frame, signed so that MuJoCo's joint value is kinsyn's (the value
//!   moves the joint's `to` body relative to its `from` body);
//! - a passive revolute chord is two `<connect>` constraints at two points of its axis, one
//!   characteristic length ([`Mechanism::scale`](crate::mechanism::Mechanism::scale)) apart:
//!   the two bodies then keep those two points in common, which leaves exactly the rotation
//!   about the axis free;
//! - any other chord (a slider, or an input, when a loop has no passive revolute) is the joint
//!   itself on an extra body hung from its `from` body, welded (`<weld>`) to its `to` body;
//! - each input drives its joint through a `<position>` servo whose target (`ctrl`) is kinsyn's
//!   input value.
//!
//! The ground is a fixed body (named as in kinsyn) and the only body of the `worldbody`; every
//! other body hangs from it. MuJoCo reads several bodies in the `worldbody` as well as one, but
//! Pinocchio's MJCF reader takes only the first `<body>` there, so that a tree with one chain
//! per leg directly in the `worldbody` would lose every leg but the first. Pinocchio ignores the
//! equality constraints: it reads the spanning tree (docs/export.md, "Pinocchio").
//!
//! Every body's frame at the reference configuration is the ground frame, except the moving
//! bodies a description names, whose frames are the description's; the reference configuration
//! is MuJoCo's `qpos0` (all joint values 0), where every constraint holds by construction. The
//! named bodies' poses (`xpos`, `xquat`) are then kinsyn's
//! [`Manipulator::body_frame`](crate::manipulator::Manipulator::body_frame).
//!
//! For MuJoCo's viewer, a floor plane below the mechanism, two lights, and geometry without
//! mass: the ground and the platform as outlines through their joints' points, each
//! intermediate body as capsules between its joints' points, each slider as a sleeve on its
//! `from` body and a rod on its `to` body.
//!
//! Masses and inertias are not physical: the descriptions carry none, and the export is for
//! kinematics (gravity off, no contacts). Named bodies weigh [`BODY_MASS`], intermediate bodies
//! [`LINK_MASS`]; servo gains and joint damping are scaled by the characteristic length so that
//! a description in millimetres moves as the same one in metres.

pub use crate::export_tree::{ChordClosure, ExportTree};

use crate::export_tree::{ExportNames, placeholder_inertia, vec3};
use crate::manipulator::Manipulator;
use crate::markup::escape;
use crate::notation::Primitive;
use crate::spatial::Displacement;
use nalgebra::{Point3, UnitQuaternion, Vector3};
use std::fmt::Write as _;

/// The simulation time step (s).
pub const TIMESTEP: f64 = 1e-3;

/// The equality constraints' `solref`: time constant (s) and damping ratio of the error's
/// decay. The time constant is the smallest MuJoCo accepts at [`TIMESTEP`] without warning
/// (two steps), doubled for margin.
pub const EQUALITY_SOLREF: [f64; 2] = [4e-3, 1.0];

/// The equality constraints' `solimp` (`dmin dmax width midpoint power`): an impedance of
/// 0.9999 at any violation, the stiffest MuJoCo allows.
pub const EQUALITY_SOLIMP: [f64; 5] = [0.9999, 0.9999, 1e-3, 0.5, 2.0];

/// The constraint solver's iteration limit (Newton) and its tolerance.
pub const SOLVER_ITERATIONS: usize = 100;

/// The constraint solver's tolerance (relative improvement of its cost at which it stops).
pub const SOLVER_TOLERANCE: f64 = 1e-12;

pub use crate::export_tree::{BODY_MASS, LINK_MASS};

/// The servos' stiffness per unit of [`BODY_MASS`] (1/s²): a slider's `kp` is this times the
/// mass, a revolute's this times the mass and the squared characteristic length.
pub const SERVO_STIFFNESS: f64 = 1e4;

/// The servos' damping (`kv`) per unit of [`BODY_MASS`] (1/s), scaled as [`SERVO_STIFFNESS`]:
/// a damping ratio of one half for the platform alone, heavily damped once the legs' damping is
/// added.
pub const SERVO_DAMPING: f64 = 100.0;

/// The damping of every joint per unit of [`LINK_MASS`] (1/s; times the squared
/// characteristic length for a revolute): it stops the motions the servos do not drive, such
/// as a UPS leg spinning about its line.
pub const JOINT_DAMPING: f64 = 20.0;

/// The floor's distance below the lowest joint point, in characteristic lengths.
pub const FLOOR_GAP: f64 = 0.1;

/// Half the length of a slider's sleeve (on its `from` body) and of its rod (on its `to`
/// body), in characteristic lengths: the two overlap while the slider is within twice this of
/// its reference value.
pub const SLEEVE_HALF_LENGTH: f64 = 0.15;

/// The radius of the capsules that show an intermediate body, in characteristic lengths.
pub const LINK_RADIUS: f64 = 0.01;

/// The radius of the outline that shows a named body (the ground, the platform).
pub const PLATE_RADIUS: f64 = 0.02;

/// The radius of a slider's sleeve.
pub const SLEEVE_RADIUS: f64 = 0.025;

/// The radius of a slider's rod.
pub const ROD_RADIUS: f64 = 0.012;

const LINK_RGBA: &str = "0.55 0.6 0.7 1";
const GROUND_RGBA: &str = "0.3 0.3 0.3 1";
const BODY_RGBA: &str = "0.9 0.55 0.2 1";
const SLEEVE_RGBA: &str = "0.25 0.35 0.55 1";
const ROD_RGBA: &str = "0.8 0.8 0.85 1";
const FLOOR_RGBA: &str = "0.85 0.85 0.8 1";

/// The MJCF model of a manipulator (module documentation): XML text that MuJoCo loads, whose
/// `qpos0` is the reference configuration and whose actuators, named by the inputs' labels
/// (`P1.3`), take kinsyn's input values as `ctrl`.
#[must_use]
pub fn to_mjcf(m: &Manipulator) -> String {
    Export::new(m).xml()
}

/// Which mechanism body an MJCF body stands for.
#[derive(Debug, Clone, Copy)]
enum Shown {
    /// The body itself: its inertia and its geometry.
    Body(usize),
    /// A weld chord's extra body, held to this body (the chord's `to` body): its inertia, no
    /// geometry (the body shows it).
    Chord(usize),
}

/// What the XML is written from: the manipulator, its tree, and each body's frame and name.
struct Export<'a> {
    m: &'a Manipulator,
    tree: ExportTree,
    /// Body names, joint labels and each body's frame at the reference configuration.
    names: ExportNames,
    scale: f64,
}

impl<'a> Export<'a> {
    fn new(m: &'a Manipulator) -> Self {
        Export {
            m,
            tree: ExportTree::new(m),
            // MuJoCo names the world body `world`.
            names: ExportNames::new(m, &["world"]),
            scale: m.mechanism().scale(),
        }
    }

    fn xml(&self) -> String {
        let mut x = String::new();
        let _ = writeln!(x, "<mujoco model=\"{}\">", escape(self.m.name()));
        let _ = writeln!(
            x,
            "  <!-- kinsyn export (docs/export.md): qpos0 is the reference configuration; \
             ctrl of an actuator is kinsyn's input value (length or radian). The ground is the \
             fixed body `{}`, the one body of the worldbody, so that readers that take a single \
             root (Pinocchio) read the whole tree. -->",
            escape(&self.names.bodies[self.m.mechanism().ground()])
        );
        let _ = writeln!(
            x,
            "  <compiler angle=\"radian\" inertiafromgeom=\"false\" autolimits=\"true\"/>"
        );
        let _ = writeln!(
            x,
            "  <option timestep=\"{TIMESTEP}\" gravity=\"0 0 0\" integrator=\"implicitfast\" \
             solver=\"Newton\" iterations=\"{SOLVER_ITERATIONS}\" tolerance=\"{SOLVER_TOLERANCE}\">"
        );
        let _ = writeln!(x, "    <flag contact=\"disable\"/>");
        let _ = writeln!(x, "  </option>");
        let _ = writeln!(x, "  <default>");
        let _ = writeln!(
            x,
            "    <geom contype=\"0\" conaffinity=\"0\" rgba=\"{LINK_RGBA}\"/>"
        );
        let _ = writeln!(
            x,
            "    <equality solref=\"{}\" solimp=\"{}\"/>",
            join(&EQUALITY_SOLREF),
            join(&EQUALITY_SOLIMP)
        );
        let _ = writeln!(x, "  </default>");
        let _ = writeln!(x, "  <worldbody>");
        self.write_scene(&mut x);
        let ground = self.m.mechanism().ground();
        self.open_body_at(
            &mut x,
            &self.names.bodies[ground],
            &Displacement::identity(),
            None,
            Shown::Body(ground),
            2,
        );
        self.write_children(&mut x, ground, 3);
        self.write_weld_bodies(&mut x, ground, 3);
        let _ = writeln!(x, "    </body>");
        let _ = writeln!(x, "  </worldbody>");
        self.write_equalities(&mut x);
        self.write_actuators(&mut x);
        let _ = writeln!(x, "</mujoco>");
        x
    }

    /// The floor and the lights, in the world body: a plane below the lowest joint point
    /// (descriptions have z up), and two lights above the mechanism.
    fn write_scene(&self, x: &mut String) {
        let l = self.scale;
        let points: Vec<Vector3<f64>> = self
            .m
            .mechanism()
            .joints()
            .iter()
            .map(|j| j.point)
            .chain(self.m.bodies().iter().map(|b| b.frame.translation.vector))
            .collect();
        #[allow(clippy::cast_precision_loss, reason = "a mechanism has a few joints")]
        let centre = points.iter().sum::<Vector3<f64>>() / points.len().max(1) as f64;
        let low = points.iter().map(|p| p.z).fold(f64::INFINITY, f64::min);
        let high = points.iter().map(|p| p.z).fold(f64::NEG_INFINITY, f64::max);
        let reach = points
            .iter()
            .map(|p| (p - centre).norm())
            .fold(0.0, f64::max)
            .max(l);
        let floor = Vector3::new(centre.x, centre.y, low - FLOOR_GAP * l);
        let top = Vector3::new(centre.x, centre.y, high + 3.0 * reach);
        let side = Vector3::new(centre.x + 2.0 * reach, centre.y - 2.0 * reach, high + reach);
        let _ = writeln!(
            x,
            "    <light name=\"overhead\" directional=\"true\" pos=\"{}\" dir=\"0 0 -1\" diffuse=\"0.6 0.6 0.6\"/>",
            vec3(&top)
        );
        let _ = writeln!(
            x,
            "    <light name=\"side\" pos=\"{}\" dir=\"{}\" diffuse=\"0.4 0.4 0.4\"/>",
            vec3(&side),
            vec3(&(centre - side).normalize())
        );
        let _ = writeln!(
            x,
            "    <geom name=\"floor\" type=\"plane\" pos=\"{}\" size=\"{} {} {}\" rgba=\"{}\"/>",
            vec3(&floor),
            2.0 * reach,
            2.0 * reach,
            0.25 * l,
            FLOOR_RGBA
        );
    }

    /// The bodies whose parent in the tree is `body`, nested.
    fn write_children(&self, x: &mut String, body: usize, depth: usize) {
        for (child, joint, sign) in self.tree.children(self.m, body) {
            self.open_body_at(
                x,
                &self.names.bodies[child],
                &self.names.frames[child],
                Some(body),
                Shown::Body(child),
                depth,
            );
            self.write_joint_in(x, joint, &self.names.frames[child], sign, depth + 1);
            self.write_children(x, child, depth + 1);
            self.write_weld_bodies(x, child, depth + 1);
            let _ = writeln!(x, "{}</body>", indent(depth));
        }
    }

    /// The extra bodies of the weld chords whose `from` body is `body`.
    fn write_weld_bodies(&self, x: &mut String, body: usize, depth: usize) {
        let mech = self.m.mechanism();
        for &(joint, closure) in &self.tree.chords {
            let spec = &mech.joints()[joint];
            if closure == ChordClosure::Weld && spec.from == body {
                let name = self.chord_body(joint);
                // The extra body's frame is the `to` body's: the weld holds them together. It
                // has the `to` body's inertia, and no geometry (the `to` body shows it).
                let frame = self.names.frames[spec.to];
                self.open_body_at(x, &name, &frame, Some(body), Shown::Chord(spec.to), depth);
                self.write_joint_in(x, joint, &frame, 1.0, depth + 1);
                let _ = writeln!(x, "{}</body>", indent(depth));
            }
        }
    }

    fn chord_body(&self, joint: usize) -> String {
        format!("{} chord", self.names.joints[joint])
    }

    /// The reference points, in `frame`, of the joints of mechanism body `body`, in joint
    /// order.
    fn joint_points(&self, body: usize, frame: &Displacement) -> Vec<Vector3<f64>> {
        self.m
            .mechanism()
            .joints()
            .iter()
            .filter(|j| j.from == body || j.to == body)
            .map(|j| frame.inverse_transform_point(&Point3::from(j.point)).coords)
            .collect()
    }

    /// Opens a body named `name` whose reference frame is `frame`, in `parent`'s frame (the
    /// world's when `None`), with the inertia of the mechanism body `shown` names and, for a
    /// body of the mechanism, its geometry.
    fn open_body_at(
        &self,
        x: &mut String,
        name: &str,
        frame: &Displacement,
        parent: Option<usize>,
        shown: Shown,
        depth: usize,
    ) {
        let parent_frame = parent.map_or(Displacement::identity(), |p| self.names.frames[p]);
        let relative = parent_frame.inverse() * frame;
        let q = UnitQuaternion::from_rotation_matrix(&relative.rotation);
        let _ = writeln!(
            x,
            "{}<body name=\"{}\" pos=\"{}\" quat=\"{} {} {} {}\">",
            indent(depth),
            escape(name),
            vec3(&relative.translation.vector),
            q.w,
            q.i,
            q.j,
            q.k
        );
        let (Shown::Body(like) | Shown::Chord(like)) = shown;
        let (centre, mass, inertia) = placeholder_inertia(self.m, like, frame);
        let _ = writeln!(
            x,
            "{}<inertial pos=\"{}\" mass=\"{mass}\" diaginertia=\"{inertia} {inertia} {inertia}\"/>",
            indent(depth + 1),
            vec3(&centre)
        );
        if let Shown::Body(body) = shown {
            for geom in self.geoms(body, frame) {
                let _ = writeln!(x, "{}{geom}", indent(depth + 1));
            }
        }
    }

    /// The geometry MuJoCo's viewer shows for mechanism body `body`, in its reference frame
    /// `frame`: a named body (the ground, the platform) as a plate outline through its joints'
    /// points, an intermediate body as capsules from joint point to joint point (in joint
    /// order), and each slider as a sleeve on its `from` body and a rod on its `to` body, long
    /// enough to overlap while the slider is within twice [`SLEEVE_HALF_LENGTH`] characteristic
    /// lengths of its reference value. The
    /// geoms carry no mass: the inertias are the `<inertial>` elements (`inertiafromgeom` off).
    fn geoms(&self, body: usize, frame: &Displacement) -> Vec<String> {
        let l = self.scale;
        let named = ExportNames::is_named(self.m, body);
        let points = distinct(&self.joint_points(body, frame), 1e-9 * l);
        let (radius, rgba) = if body == self.m.mechanism().ground() {
            (PLATE_RADIUS * l, GROUND_RGBA)
        } else if named {
            (PLATE_RADIUS * l, BODY_RGBA)
        } else {
            (LINK_RADIUS * l, LINK_RGBA)
        };
        let mut out = Vec::new();
        let path = if named {
            outline(&points)
        } else {
            points.clone()
        };
        for pair in path.windows(2) {
            out.push(format!(
                "<geom type=\"capsule\" size=\"{radius}\" fromto=\"{} {}\" rgba=\"{rgba}\"/>",
                vec3(&pair[0]),
                vec3(&pair[1])
            ));
        }
        let joint_radius = if named { 2.0 } else { 1.5 } * radius;
        for p in &points {
            out.push(format!(
                "<geom type=\"sphere\" size=\"{joint_radius}\" pos=\"{}\" rgba=\"{rgba}\"/>",
                vec3(p)
            ));
        }
        for spec in self.m.mechanism().joints() {
            if spec.kind != Primitive::P || (spec.from != body && spec.to != body) {
                continue;
            }
            let point = frame
                .inverse_transform_point(&Point3::from(spec.point))
                .coords;
            let half = frame.rotation.inverse() * spec.axis * (SLEEVE_HALF_LENGTH * l);
            let (size, rgba) = if spec.from == body {
                (SLEEVE_RADIUS * l, SLEEVE_RGBA)
            } else {
                (ROD_RADIUS * l, ROD_RGBA)
            };
            out.push(format!(
                "<geom type=\"cylinder\" size=\"{size}\" fromto=\"{} {}\" rgba=\"{rgba}\"/>",
                vec3(&(point - half)),
                vec3(&(point + half))
            ));
        }
        out
    }

    /// Joint `joint` in a body whose reference frame is `frame`; `sign` −1 when the body is the
    /// joint's `from` body (the value then moves it the other way).
    fn write_joint_in(
        &self,
        x: &mut String,
        joint: usize,
        frame: &Displacement,
        sign: f64,
        depth: usize,
    ) {
        let spec = &self.m.mechanism().joints()[joint];
        let axis = frame.rotation.inverse() * (spec.axis * sign);
        let point = frame
            .inverse_transform_point(&Point3::from(spec.point))
            .coords;
        let l2 = self.scale * self.scale;
        let (kind, damping, armature) = match spec.kind {
            Primitive::R => (
                "hinge",
                JOINT_DAMPING * l2 * LINK_MASS,
                0.01 * LINK_MASS * l2,
            ),
            Primitive::P => ("slide", JOINT_DAMPING * LINK_MASS, 0.01 * LINK_MASS),
        };
        let _ = writeln!(
            x,
            "{}<joint name=\"{}\" type=\"{kind}\" pos=\"{}\" axis=\"{}\" damping=\"{damping}\" armature=\"{armature}\"/>",
            indent(depth),
            escape(&self.names.joints[joint]),
            vec3(&point),
            vec3(&axis)
        );
    }

    fn write_equalities(&self, x: &mut String) {
        if self.tree.chords.is_empty() {
            return;
        }
        let mech = self.m.mechanism();
        let labels = &self.names.joints;
        let _ = writeln!(x, "  <equality>");
        for &(joint, closure) in &self.tree.chords {
            let spec = &mech.joints()[joint];
            match closure {
                ChordClosure::Connect => {
                    let frame = self.names.frames[spec.from];
                    let points = [spec.point, spec.point + spec.axis * self.scale];
                    for (k, point) in points.into_iter().enumerate() {
                        let anchor = frame.inverse_transform_point(&Point3::from(point)).coords;
                        // body1 is always named (the ground is a body too): Pinocchio's reader
                        // requires it.
                        let _ = writeln!(
                            x,
                            "    <connect name=\"{} chord {}\" body1=\"{}\" body2=\"{}\" anchor=\"{}\"/>",
                            escape(&labels[joint]),
                            k + 1,
                            escape(&self.names.bodies[spec.from]),
                            escape(&self.names.bodies[spec.to]),
                            vec3(&anchor)
                        );
                    }
                }
                ChordClosure::Weld => {
                    let _ = writeln!(
                        x,
                        "    <weld name=\"{} chord\" body1=\"{}\" body2=\"{}\"/>",
                        escape(&labels[joint]),
                        escape(&self.chord_body(joint)),
                        escape(&self.names.bodies[spec.to])
                    );
                }
            }
        }
        let _ = writeln!(x, "  </equality>");
    }

    fn write_actuators(&self, x: &mut String) {
        if self.m.actuators().is_empty() {
            return;
        }
        let mech = self.m.mechanism();
        let l2 = self.scale * self.scale;
        let _ = writeln!(x, "  <actuator>");
        for a in self.m.actuators() {
            let unit = match mech.joints()[a.joint].kind {
                Primitive::R => BODY_MASS * l2,
                Primitive::P => BODY_MASS,
            };
            let _ = writeln!(
                x,
                "    <position name=\"{}\" joint=\"{}\" kp=\"{}\" kv=\"{}\"/>",
                escape(&a.label()),
                escape(&self.names.joints[a.joint]),
                SERVO_STIFFNESS * unit,
                SERVO_DAMPING * unit
            );
        }
        let _ = writeln!(x, "  </actuator>");
    }
}

/// The points of `points` that differ (by more than `tolerance`) from every earlier one, in
/// order.
fn distinct(points: &[Vector3<f64>], tolerance: f64) -> Vec<Vector3<f64>> {
    let mut out: Vec<Vector3<f64>> = Vec::new();
    for p in points {
        if out.iter().all(|q| (p - q).norm() > tolerance) {
            out.push(*p);
        }
    }
    out
}

/// A closed outline through distinct points: in the order of their angle about their centroid,
/// in the plane of the two largest spreads, back to the first. One or two points are left as
/// they are (a point; a segment).
fn outline(points: &[Vector3<f64>]) -> Vec<Vector3<f64>> {
    if points.len() < 3 {
        return points.to_vec();
    }
    #[allow(clippy::cast_precision_loss, reason = "a body has a few joints")]
    let centre = points.iter().sum::<Vector3<f64>>() / points.len() as f64;
    let spread = points.iter().fold(nalgebra::Matrix3::zeros(), |s, p| {
        s + (p - centre) * (p - centre).transpose()
    });
    let eigen = spread.symmetric_eigen();
    let mut order: Vec<usize> = (0..3).collect();
    order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
    let (u, v) = (
        eigen.eigenvectors.column(order[0]).into_owned(),
        eigen.eigenvectors.column(order[1]).into_owned(),
    );
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| {
        let angle = |p: &Vector3<f64>| (p - centre).dot(&v).atan2((p - centre).dot(&u));
        angle(a).total_cmp(&angle(b))
    });
    sorted.push(sorted[0]);
    sorted
}

fn indent(depth: usize) -> String {
    "  ".repeat(depth)
}

fn join(values: &[f64]) -> String {
    values
        .iter()
        .map(f64::to_string)
        .collect::<Vec<_>>()
        .join(" ")
}
