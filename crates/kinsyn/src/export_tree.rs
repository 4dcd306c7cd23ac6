//! The spanning tree the model exports share (MuJoCo's MJCF in [`crate::mjcf`], URDF in
//! [`crate::urdf`]): which joints become the tree's joints, which close the loops (the
//! chords), and the names and reference frames both formats give the bodies and the joints.
//!
//! A simulator or a kinematics library holds a tree of bodies; a parallel manipulator has
//! loops. The tree keeps every input and every slider wherever the mechanism allows it, so that
//! the joints left over, one per independent loop, are passive revolutes: a revolute chord is
//! the easiest to close by a constraint (two points held in common), and the inputs stay joints
//! a servo can drive.

use crate::manipulator::Manipulator;
use crate::notation::Primitive;
use crate::spatial::Displacement;

/// How a chord closes its loop in a model with equality constraints (MJCF).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChordClosure {
    /// Two `<connect>` constraints on the revolute's axis.
    Connect,
    /// The joint on an extra body, welded to the joint's `to` body.
    Weld,
}

/// The spanning tree the exports use: each body's parent and the joint to it, and the chords.
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
        // Kruskal: a joint enters the tree when it joins two bodies not yet connected.
        let mut connected = petgraph::unionfind::UnionFind::<usize>::new(mech.body_count());
        let mut in_tree = vec![false; joints.len()];
        for &j in &order {
            in_tree[j] = connected.union(joints[j].from, joints[j].to);
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

    /// The bodies whose parent in the tree is `body`, each with the tree joint that reaches it
    /// and the joint's sign along the tree: 1 when the child is the joint's `to` body, −1 when
    /// the tree crosses the joint from its `to` body to its `from` body (the child then moves
    /// by the joint value about the negated axis).
    #[must_use]
    pub fn children(&self, m: &Manipulator, body: usize) -> Vec<(usize, usize, f64)> {
        self.parent
            .iter()
            .enumerate()
            .filter_map(|(child, link)| match *link {
                Some((parent, joint)) if parent == body => {
                    let sign = if m.mechanism().joints()[joint].to == child {
                        1.0
                    } else {
                        -1.0
                    };
                    Some((child, joint, sign))
                }
                _ => None,
            })
            .collect()
    }

    /// The number of joints in the tree: one per body but the ground.
    #[must_use]
    pub fn joint_count(&self) -> usize {
        self.parent.iter().flatten().count()
    }
}

/// The names and reference frames an export gives the bodies and joints of a manipulator.
#[derive(Debug, Clone)]
pub struct ExportNames {
    /// Each body's name: kinsyn's (`platform`, `leg 2 link 3`), with ` #INDEX` appended to a
    /// name used twice or reserved by the format.
    pub bodies: Vec<String>,
    /// Each primitive joint's label: `P1.3` for leg 1's third primitive joint, a P; `joint N`
    /// for a joint outside every leg.
    pub joints: Vec<String>,
    /// Each body's frame at the reference configuration: the ground frame, except for the
    /// moving bodies the description names, whose frames are the description's.
    pub frames: Vec<Displacement>,
}

impl ExportNames {
    /// The names and frames of `m`'s bodies and joints; `reserved` lists body names the format
    /// keeps for itself (MJCF's `world`).
    #[must_use]
    pub fn new(m: &Manipulator, reserved: &[&str]) -> Self {
        let mech = m.mechanism();
        let mut frames = vec![Displacement::identity(); mech.body_count()];
        for b in m.bodies() {
            frames[b.body] = b.frame;
        }
        let mut bodies: Vec<String> = Vec::with_capacity(mech.body_count());
        for b in 0..mech.body_count() {
            let name = mech.body_name(b).to_string();
            let name = if bodies.contains(&name) || reserved.contains(&name.as_str()) {
                format!("{name} #{b}")
            } else {
                name
            };
            bodies.push(name);
        }
        let mut joints: Vec<String> = (0..mech.joints().len())
            .map(|j| format!("joint {}", j + 1))
            .collect();
        for (l, leg) in m.legs().iter().enumerate() {
            for (k, j) in leg.joints.clone().enumerate() {
                joints[j] = format!("{}{}.{}", mech.joints()[j].kind.letter(), l + 1, k + 1);
            }
        }
        ExportNames {
            bodies,
            joints,
            frames,
        }
    }

    /// Whether `body` is one the description names (the platform, the bodies of a `/2` file)
    /// or the ground, rather than an intermediate body of a leg.
    #[must_use]
    pub fn is_named(m: &Manipulator, body: usize) -> bool {
        body == m.mechanism().ground() || m.bodies().iter().any(|b| b.body == body)
    }
}

/// The mass of a moving body the description names (the platform), in both exports.
pub const BODY_MASS: f64 = 1.0;

/// The mass of an intermediate body of a leg (massless in kinsyn), in both exports.
pub const LINK_MASS: f64 = 0.1;

/// The made-up inertia both exports give a body (kinsyn's bodies carry none): [`BODY_MASS`]
/// with a radius of gyration of a quarter of the characteristic length for the ground and the
/// bodies the description names, [`LINK_MASS`] with a twentieth for an intermediate body; the
/// centre of mass at the centroid of its joints' points. Returns the centre (in `frame`, the
/// frame the inertia is written in), the mass and the principal moment (the same about every
/// axis).
#[must_use]
pub fn placeholder_inertia(
    m: &Manipulator,
    body: usize,
    frame: &Displacement,
) -> (nalgebra::Vector3<f64>, f64, f64) {
    let l = m.mechanism().scale();
    let points: Vec<nalgebra::Vector3<f64>> = m
        .mechanism()
        .joints()
        .iter()
        .filter(|j| j.from == body || j.to == body)
        .map(|j| frame.inverse_transform_point(&j.point.into()).coords)
        .collect();
    #[allow(clippy::cast_precision_loss, reason = "a body has a few joints")]
    let centre = points.iter().sum::<nalgebra::Vector3<f64>>() / points.len().max(1) as f64;
    let (mass, gyration) = if ExportNames::is_named(m, body) {
        (BODY_MASS, 0.25 * l)
    } else {
        (LINK_MASS, 0.05 * l)
    };
    (centre, mass, mass * gyration * gyration)
}

/// A vector as the XML formats write it: three numbers separated by spaces, each the shortest
/// decimal that reads back as the same `f64`.
pub(crate) fn vec3(v: &nalgebra::Vector3<f64>) -> String {
    format!("{} {} {}", v.x, v.y, v.z)
}
