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
//! Every body's frame at the reference configuration is the ground frame, except the moving
//! bodies a description names, whose frames are the description's; the reference configuration
//! is MuJoCo's `qpos0` (all joint values 0), where every constraint holds by construction. The
//! named bodies' poses (`xpos`, `xquat`) are then kinsyn's
//! [`Manipulator::body_frame`](crate::manipulator::Manipulator::body_frame).
//!
//! Masses and inertias are not physical: the descriptions carry none, and the export is for
//! kinematics (gravity off, no contacts). Named bodies weigh [`BODY_MASS`], intermediate bodies
//! [`LINK_MASS`]; servo gains and joint damping are scaled by the characteristic length so that
//! a description in millimetres moves as the same one in metres.


use crate::manipulator::Manipulator;
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

/// The mass of a moving body the description names (the platform).
pub const BODY_MASS: f64 = 1.0;

/// The mass of an intermediate body of a leg (massless in kinsyn).
pub const LINK_MASS: f64 = 0.1;

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

/// The MJCF model of a manipulator (module documentation): XML text that MuJoCo loads, whose
/// `qpos0` is the reference configuration and whose actuators, named by the inputs' labels
/// (`P1.3`), take kinsyn's input values as `ctrl`.
#[must_use]
pub fn to_mjcf(m: &Manipulator) -> String {
    Export::new(m).xml()
}

/// How a chord closes its loop in MuJoCo.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChordClosure {
    /// Two `<connect>` constraints on the revolute's axis.
    Connect,
    /// The joint on an extra body, welded to the joint's `to` body.
    Weld,
}

/// The spanning tree the export uses: each body's parent and the joint to it, and the chords.
#[derive(Debug, Clone)]
pub struct ExportTree {
    /// For each body, its parent body and the joint that joins them (`None` for the ground).
    pub parent: Vec<Option<(usize, usize)>>,
    /// The joints off the tree and how each closes its loop.
    pub chords: Vec<(usize, ChordClosure)>,
}

impl ExportTree {
    /// The spanning tree of `m`'s mechanism that takes the inputs first, then the sliders, then
    /// the revolutes (in joint order within each), so that a chord is a passive revolute
    /// unless every joint of its loop is an input or a slider.
    #[must_use]
    pub fn new(m: &Manipulator) -> Self {
        let mech = m.mechanism();
        let joints = mech.joints();
        let actuated: Vec<bool> = (0..joints.len())
            .map(|j| m.actuators().iter().any(|a| a.joint == j))
            .collect();
        let mut order: Vec<usize> = (0..joints.len()).collect();
        order.sort_by_key(|&j| (!actuated[j], joints[j].kind == Primitive::R));
        let mut set: Vec<usize> = (0..mech.body_count()).collect();
        let find = |set: &mut Vec<usize>, mut b: usize| {
            while set[b] != b {
                set[b] = set[set[b]];
                b = set[b];
            }
            b
        };
        let mut in_tree = vec![false; joints.len()];
        for &j in &order {
            let (a, b) = (find(&mut set, joints[j].from), find(&mut set, joints[j].to));
            if a != b {
                set[a] = b;
                in_tree[j] = true;
            }
        }
        let mut parent = vec![None; mech.body_count()];
        let mut reached = vec![false; mech.body_count()];
        reached[mech.ground()] = true;
        let mut queue = std::collections::VecDeque::from([mech.ground()]);
        while let Some(b) = queue.pop_front() {
            for (j, joint) in joints.iter().enumerate() {
                let other = if joint.from == b {
                    joint.to
                } else if joint.to == b {
                    joint.from
                } else {
                    continue;
                };
                if in_tree[j] && !reached[other] {
                    reached[other] = true;
                    parent[other] = Some((b, j));
                    queue.push_back(other);
                }
            }
        }
        let chords = (0..joints.len())
            .filter(|&j| !in_tree[j])
            .map(|j| {
                let closure = if joints[j].kind == Primitive::R && !actuated[j] {
                    ChordClosure::Connect
                } else {
                    ChordClosure::Weld
                };
                (j, closure)
            })
            .collect();
        ExportTree { parent, chords }
    }
}

/// What the XML is written from: the manipulator, its tree, and each body's frame and name.
struct Export<'a> {
    m: &'a Manipulator,
    tree: ExportTree,
    /// Each body's frame at the reference configuration.
    frames: Vec<Displacement>,
    names: Vec<String>,
    labels: Vec<String>,
    scale: f64,
}

impl<'a> Export<'a> {
    fn new(m: &'a Manipulator) -> Self {
        let mech = m.mechanism();
        let mut frames = vec![Displacement::identity(); mech.body_count()];
        for b in m.bodies() {
            frames[b.body] = b.frame;
        }
        let mut names: Vec<String> = Vec::with_capacity(mech.body_count());
        for b in 0..mech.body_count() {
            let name = mech.body_name(b).to_string();
            let name = if names.contains(&name) {
                format!("{name} #{b}")
            } else {
                name
            };
            names.push(name);
        }
        let mut labels: Vec<String> = (0..mech.joints().len())
            .map(|j| format!("joint {}", j + 1))
            .collect();
        for (l, leg) in m.legs().iter().enumerate() {
            for (k, j) in leg.joints.clone().enumerate() {
                labels[j] = format!("{}{}.{}", mech.joints()[j].kind.letter(), l + 1, k + 1);
            }
        }
        Export {
            m,
            tree: ExportTree::new(m),
            frames,
            names,
            labels,
            scale: mech.scale(),
        }
    }

    fn xml(&self) -> String {
        let mech = self.m.mechanism();
        let l = self.scale;
        let mut x = String::new();
        let _ = writeln!(x, "<mujoco model=\"{}\">", escape(self.m.name()));
        let _ = writeln!(
            x,
            "  <!-- kinsyn export (docs/export.md): qpos0 is the reference configuration; \
             ctrl of an actuator is kinsyn's input value (length or radian). -->"
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
            "    <geom contype=\"0\" conaffinity=\"0\" rgba=\"0.6 0.6 0.7 1\"/>"
        );
        let _ = writeln!(
            x,
            "    <equality solref=\"{}\" solimp=\"{}\"/>",
            join(&EQUALITY_SOLREF),
            join(&EQUALITY_SOLIMP)
        );
        let _ = writeln!(x, "  </default>");
        let _ = writeln!(x, "  <worldbody>");
        let ground = mech.ground();
        for j in mech.joints() {
            if j.from == ground || j.to == ground {
                let _ = writeln!(
                    x,
                    "    <geom type=\"sphere\" size=\"{}\" pos=\"{}\"/>",
                    0.03 * l,
                    vec3(&j.point)
                );
            }
        }
        self.write_children(&mut x, ground, 2);
        self.write_weld_bodies(&mut x, ground, 2);
        let _ = writeln!(x, "  </worldbody>");
        self.write_equalities(&mut x);
        self.write_actuators(&mut x);
        let _ = writeln!(x, "</mujoco>");
        x
    }

    /// The bodies whose parent in the tree is `body`, nested.
    fn write_children(&self, x: &mut String, body: usize, depth: usize) {
        for (child, link) in self.tree.parent.iter().enumerate() {
            if let Some((parent, joint)) = *link
                && parent == body
            {
                let spec = &self.m.mechanism().joints()[joint];
                let sign = if spec.to == child { 1.0 } else { -1.0 };
                self.open_body(x, child, &self.names[child], body, depth);
                self.write_joint(x, joint, child, sign, depth + 1);
                self.write_children(x, child, depth + 1);
                self.write_weld_bodies(x, child, depth + 1);
                let _ = writeln!(x, "{}</body>", indent(depth));
            }
        }
    }

    /// The extra bodies of the weld chords whose `from` body is `body`.
    fn write_weld_bodies(&self, x: &mut String, body: usize, depth: usize) {
        let mech = self.m.mechanism();
        for &(joint, closure) in &self.tree.chords {
            let spec = &mech.joints()[joint];
            if closure == ChordClosure::Weld && spec.from == body {
                let name = self.chord_body(joint);
                // The extra body's frame is the `to` body's: the weld holds them together.
                self.open_body_at(x, &name, &self.frames[spec.to], body, spec.to, depth);
                self.write_joint_in(x, joint, &self.frames[spec.to], 1.0, depth + 1);
                let _ = writeln!(x, "{}</body>", indent(depth));
            }
        }
    }

    fn chord_body(&self, joint: usize) -> String {
        format!("{} chord", self.labels[joint])
    }

    fn open_body(&self, x: &mut String, body: usize, name: &str, parent: usize, depth: usize) {
        self.open_body_at(x, name, &self.frames[body], parent, body, depth);
    }

    /// Opens a body named `name` whose reference frame is `frame`, in `parent`'s frame, with the
    /// inertia and the geoms of mechanism body `like`.
    fn open_body_at(
        &self,
        x: &mut String,
        name: &str,
        frame: &Displacement,
        parent: usize,
        like: usize,
        depth: usize,
    ) {
        let mech = self.m.mechanism();
        let l = self.scale;
        let relative = self.frames[parent].inverse() * frame;
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
        let points: Vec<Vector3<f64>> = mech
            .joints()
            .iter()
            .filter(|j| j.from == like || j.to == like)
            .map(|j| frame.inverse_transform_point(&Point3::from(j.point)).coords)
            .collect();
        #[allow(clippy::cast_precision_loss, reason = "a body has a few joints")]
        let centre = points.iter().sum::<Vector3<f64>>() / points.len().max(1) as f64;
        let named = self.m.bodies().iter().any(|b| b.body == like);
        let (mass, gyration) = if named {
            (BODY_MASS, 0.25 * l)
        } else {
            (LINK_MASS, 0.05 * l)
        };
        let inertia = mass * gyration * gyration;
        let _ = writeln!(
            x,
            "{}<inertial pos=\"{}\" mass=\"{mass}\" diaginertia=\"{inertia} {inertia} {inertia}\"/>",
            indent(depth + 1),
            vec3(&centre)
        );
        let _ = writeln!(
            x,
            "{}<geom type=\"sphere\" size=\"{}\" pos=\"{}\"/>",
            indent(depth + 1),
            if named { 0.06 } else { 0.02 } * l,
            vec3(&centre)
        );
        for p in &points {
            if (p - centre).norm() > 1e-9 * l {
                let _ = writeln!(
                    x,
                    "{}<geom type=\"capsule\" size=\"{}\" fromto=\"{} {}\"/>",
                    indent(depth + 1),
                    0.01 * l,
                    vec3(&centre),
                    vec3(p)
                );
            }
        }
    }

    fn write_joint(&self, x: &mut String, joint: usize, body: usize, sign: f64, depth: usize) {
        self.write_joint_in(x, joint, &self.frames[body], sign, depth);
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
            escape(&self.labels[joint]),
            vec3(&point),
            vec3(&axis)
        );
    }

    fn write_equalities(&self, x: &mut String) {
        if self.tree.chords.is_empty() {
            return;
        }
        let mech = self.m.mechanism();
        let _ = writeln!(x, "  <equality>");
        for &(joint, closure) in &self.tree.chords {
            let spec = &mech.joints()[joint];
            match closure {
                ChordClosure::Connect => {
                    let frame = self.frames[spec.from];
                    let points = [spec.point, spec.point + spec.axis * self.scale];
                    for (k, point) in points.into_iter().enumerate() {
                        let anchor = frame.inverse_transform_point(&Point3::from(point)).coords;
                        let _ = writeln!(
                            x,
                            "    <connect name=\"{} chord {}\" {}body2=\"{}\" anchor=\"{}\"/>",
                            escape(&self.labels[joint]),
                            k + 1,
                            self.body1(spec.from),
                            escape(&self.names[spec.to]),
                            vec3(&anchor)
                        );
                    }
                }
                ChordClosure::Weld => {
                    let _ = writeln!(
                        x,
                        "    <weld name=\"{} chord\" body1=\"{}\" body2=\"{}\"/>",
                        escape(&self.labels[joint]),
                        escape(&self.chord_body(joint)),
                        escape(&self.names[spec.to])
                    );
                }
            }
        }
        let _ = writeln!(x, "  </equality>");
    }

    /// The `body1` attribute (with its trailing space) naming `body`; nothing for the ground,
    /// which MuJoCo takes as the world body.
    fn body1(&self, body: usize) -> String {
        if body == self.m.mechanism().ground() {
            String::new()
        } else {
            format!("body1=\"{}\" ", escape(&self.names[body]))
        }
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
                escape(&self.labels[a.joint]),
                SERVO_STIFFNESS * unit,
                SERVO_DAMPING * unit
            );
        }
        let _ = writeln!(x, "  </actuator>");
    }
}

fn indent(depth: usize) -> String {
    "  ".repeat(depth)
}

/// A vector as MJCF writes it: three numbers separated by spaces, each the shortest decimal
/// that reads back as the same `f64`.
fn vec3(v: &Vector3<f64>) -> String {
    format!("{} {} {}", v.x, v.y, v.z)
}

fn join(values: &[f64]) -> String {
    values
        .iter()
        .map(f64::to_string)
        .collect::<Vec<_>>()
        .join(" ")
}

/// Text safe inside an XML attribute.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if c.is_control() => out.push(' '),
            c => out.push(c),
        }
    }
    out
}
