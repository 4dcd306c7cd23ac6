//! URDF export: the spanning tree of a manipulator as a URDF robot (docs/export.md, "URDF").
//!
//! URDF describes trees only. The export writes the spanning tree of [`ExportTree`] (the one
//! the MJCF export uses): each body a `<link>` named as in kinsyn, each tree joint a `<joint>`
//! named by its label (`P1.3`), `revolute` for a revolute and `prismatic` for a slider, whose
//! value is kinsyn's joint value (the axis is negated where the tree crosses a joint from its
//! `to` body to its `from` body). All joint values 0 is the reference configuration. The joints
//! that close the loops (the chords) have no URDF form: an XML comment lists each, with the two
//! links it joins and its axis and point, for a user to add as constraints.
//!
//! URDF turns a joint's child link about (or slides it along) an axis through the link's
//! origin. So an intermediate body's link frame is at the point of the tree joint that reaches
//! it, its axes parallel to the ground's at the reference configuration. The ground's link frame
//! is the ground frame, and a body the description names (the platform) keeps its frame: when
//! that frame is off the axis of the revolute that reaches it, the joint reaches an extra
//! massless link `NAME (LABEL)` at the joint's point, to which the body's link is fixed.
//!
//! Limits: kinsyn's descriptions carry none. A revolute gets ±[`REVOLUTE_RANGE`] (one turn
//! either way: `revolute`, not `continuous`, so that Pinocchio gives it one coordinate, its
//! angle, and `nq` is the number of tree joints); a slider gets ±[`PRISMATIC_RANGE`]
//! characteristic lengths from its reference value, and every joint
//! [`EFFORT_LIMIT`] and [`VELOCITY_LIMIT`], placeholders that URDF requires. Masses and
//! inertias are the MJCF export's placeholders
//! ([`placeholder_inertia`]); there is no visual or
//! collision geometry.

use crate::export_tree::{ExportNames, ExportTree, placeholder_inertia, vec3};
use crate::manipulator::Manipulator;
use crate::markup::escape;
use crate::notation::Primitive;
use crate::spatial::Displacement;
use nalgebra::{Point3, Vector3};
use std::fmt::Write as _;

/// A revolute's range either side of its reference value (radians): one turn, wide enough
/// never to bind in a parallel manipulator.
pub const REVOLUTE_RANGE: f64 = std::f64::consts::TAU;

/// A slider's range either side of its reference value, in characteristic lengths
/// ([`Mechanism::scale`](crate::mechanism::Mechanism::scale)): wide enough never to bind.
pub const PRISMATIC_RANGE: f64 = 10.0;

/// The `effort` of a slider's `<limit>` (URDF requires one): a placeholder, kinsyn has no
/// forces.
pub const EFFORT_LIMIT: f64 = 1e6;

/// The `velocity` of a slider's `<limit>` (URDF requires one): a placeholder.
pub const VELOCITY_LIMIT: f64 = 1e6;

/// The URDF robot of a manipulator's spanning tree (module documentation): links named as
/// kinsyn's bodies, joints named by kinsyn's labels whose values are kinsyn's joint values, the
/// loop-closing joints listed in a comment.
#[must_use]
pub fn to_urdf(m: &Manipulator) -> String {
    let export = Export {
        m,
        tree: ExportTree::new(m),
        names: ExportNames::new(m, &[]),
    };
    export.xml()
}

struct Export<'a> {
    m: &'a Manipulator,
    tree: ExportTree,
    names: ExportNames,
}

impl Export<'_> {
    fn xml(&self) -> String {
        let mut x = String::new();
        let _ = writeln!(x, "<?xml version=\"1.0\"?>");
        let _ = writeln!(x, "<robot name=\"{}\">", escape(self.m.name()));
        let _ = writeln!(
            x,
            "  <!-- kinsyn export (docs/export.md): the spanning tree; every joint value 0 is the \
             reference configuration, and a joint's value is kinsyn's (radian or {}). Limits are \
             placeholders (descriptions have none): revolutes ±2π rad, sliders ±{} \
             (±{PRISMATIC_RANGE} characteristic lengths). -->",
            comment(&self.m.units().length),
            self.m.mechanism().scale() * PRISMATIC_RANGE
        );
        self.write_chords(&mut x);
        let ground = self.m.mechanism().ground();
        self.write_link(
            &mut x,
            &self.names.bodies[ground],
            Some(ground),
            &self.link_frame(ground),
        );
        self.write_subtree(&mut x, ground);
        let _ = writeln!(x, "</robot>");
        x
    }

    /// The link frame of `body` at the reference configuration: the ground frame for the
    /// ground, the description's frame for a named body, the tree joint's frame for an
    /// intermediate body.
    fn link_frame(&self, body: usize) -> Displacement {
        if ExportNames::is_named(self.m, body) {
            self.names.frames[body]
        } else {
            self.joint_frame(body)
        }
    }

    /// The frame of the tree joint that reaches `body`, at the reference configuration: the
    /// body's frame, moved to the joint's point unless the body is named and the joint leaves
    /// its origin on its axis (a slider, or a revolute through the origin).
    fn joint_frame(&self, body: usize) -> Displacement {
        let frame = self.names.frames[body];
        let Some((_, joint)) = self.tree.parent[body] else {
            return frame;
        };
        let spec = &self.m.mechanism().joints()[joint];
        let origin = frame.translation.vector;
        let off_axis = (origin - spec.point).cross(&spec.axis).norm();
        if ExportNames::is_named(self.m, body)
            && (spec.kind == Primitive::P || off_axis <= 1e-12 * self.m.mechanism().scale())
        {
            frame
        } else {
            Displacement::from_parts(spec.point.into(), frame.rotation)
        }
    }

    /// The joints and links below `body`.
    fn write_subtree(&self, x: &mut String, body: usize) {
        let parent_frame = self.link_frame(body);
        for (child, joint, sign) in self.tree.children(self.m, body) {
            let spec = &self.m.mechanism().joints()[joint];
            let name = &self.names.bodies[child];
            let joint_frame = self.joint_frame(child);
            let link_frame = self.link_frame(child);
            let extra = joint_frame != link_frame;
            let reached = if extra {
                format!("{name} ({})", self.names.joints[joint])
            } else {
                name.clone()
            };
            let axis = joint_frame.rotation.inverse() * (spec.axis * sign);
            let _ = writeln!(
                x,
                "  <joint name=\"{}\" type=\"{}\">",
                escape(&self.names.joints[joint]),
                match spec.kind {
                    Primitive::R => "revolute",
                    Primitive::P => "prismatic",
                }
            );
            write_parent_child_origin(
                x,
                &self.names.bodies[body],
                &reached,
                &(parent_frame.inverse() * joint_frame),
            );
            let _ = writeln!(x, "    <axis xyz=\"{}\"/>", vec3(&axis));
            {
                let range = match spec.kind {
                    Primitive::R => REVOLUTE_RANGE,
                    Primitive::P => PRISMATIC_RANGE * self.m.mechanism().scale(),
                };
                let _ = writeln!(
                    x,
                    "    <limit lower=\"{}\" upper=\"{range}\" effort=\"{EFFORT_LIMIT}\" velocity=\"{VELOCITY_LIMIT}\"/>",
                    -range
                );
            }
            let _ = writeln!(x, "  </joint>");
            if extra {
                self.write_link(x, &reached, None, &joint_frame);
                let _ = writeln!(
                    x,
                    "  <joint name=\"{}\" type=\"fixed\">",
                    escape(&format!("{name} frame"))
                );
                write_parent_child_origin(x, &reached, name, &(joint_frame.inverse() * link_frame));
                let _ = writeln!(x, "  </joint>");
            }
            self.write_link(x, name, Some(child), &link_frame);
            self.write_subtree(x, child);
        }
    }

    /// A link named `name` whose frame at the reference is `frame`, with the placeholder
    /// inertia of mechanism body `body` (none for an extra link).
    fn write_link(&self, x: &mut String, name: &str, body: Option<usize>, frame: &Displacement) {
        let Some(body) = body else {
            let _ = writeln!(x, "  <link name=\"{}\"/>", escape(name));
            return;
        };
        let (centre, mass, inertia) = placeholder_inertia(self.m, body, frame);
        let _ = writeln!(x, "  <link name=\"{}\">", escape(name));
        let _ = writeln!(x, "    <inertial>");
        let _ = writeln!(x, "      <origin xyz=\"{}\" rpy=\"0 0 0\"/>", vec3(&centre));
        let _ = writeln!(x, "      <mass value=\"{mass}\"/>");
        let _ = writeln!(
            x,
            "      <inertia ixx=\"{inertia}\" ixy=\"0\" ixz=\"0\" iyy=\"{inertia}\" iyz=\"0\" izz=\"{inertia}\"/>"
        );
        let _ = writeln!(x, "    </inertial>");
        let _ = writeln!(x, "  </link>");
    }

    /// The comment that lists the loop-closing joints: for each, its kind, the two links it
    /// joins (`from`, then `to`: the value moves `to` relative to `from`), and its axis and
    /// point in the ground frame and in each link's frame, at the reference configuration.
    fn write_chords(&self, x: &mut String) {
        if self.tree.chords.is_empty() {
            return;
        }
        let mech = self.m.mechanism();
        let _ = writeln!(
            x,
            "  <!-- Loop-closing joints (not in URDF: add them as constraints). Each joins two \
             links; its value, 0 at the reference configuration, moves the second relative to \
             the first. Axis and point at the reference configuration:"
        );
        for &(joint, _) in &self.tree.chords {
            let spec = &mech.joints()[joint];
            let kind = match spec.kind {
                Primitive::R => "revolute",
                Primitive::P => "prismatic",
            };
            let actuated = if self.m.actuators().iter().any(|a| a.joint == joint) {
                ", an input"
            } else {
                ""
            };
            let _ = writeln!(
                x,
                "       {} ({kind}{actuated}) from link '{}' to link '{}': axis {} through {} in the ground frame;",
                comment(&self.names.joints[joint]),
                comment(&self.names.bodies[spec.from]),
                comment(&self.names.bodies[spec.to]),
                vec3(&spec.axis),
                vec3(&spec.point)
            );
            for body in [spec.from, spec.to] {
                let frame = self.link_frame(body);
                let _ = writeln!(
                    x,
                    "         axis {} through {} in the frame of link '{}'{}",
                    vec3(&(frame.rotation.inverse() * spec.axis)),
                    vec3(
                        &frame
                            .inverse_transform_point(&Point3::from(spec.point))
                            .coords
                    ),
                    comment(&self.names.bodies[body]),
                    if body == spec.from { ";" } else { "." }
                );
            }
        }
        let _ = writeln!(x, "  -->");
    }
}

/// A joint's `<parent>`, `<child>` and `<origin>` (the child's frame in the parent's, as `xyz`
/// and the fixed-axis roll, pitch, yaw of `rpy`).
fn write_parent_child_origin(x: &mut String, parent: &str, child: &str, origin: &Displacement) {
    let (roll, pitch, yaw) = origin.rotation.euler_angles();
    let _ = writeln!(x, "    <parent link=\"{}\"/>", escape(parent));
    let _ = writeln!(x, "    <child link=\"{}\"/>", escape(child));
    let _ = writeln!(
        x,
        "    <origin xyz=\"{}\" rpy=\"{}\"/>",
        vec3(&origin.translation.vector),
        vec3(&Vector3::new(roll, pitch, yaw))
    );
}

/// Text safe inside an XML comment: escaped, and without the `--` a comment may not hold.
fn comment(text: &str) -> String {
    escape(text).replace("--", "-&#45;")
}
