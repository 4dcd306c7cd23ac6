//! What a view draws of a manipulator, independent of its configuration: the bodies with their
//! roles, every primitive joint with its description-level joint (R, P, U, S, C), its leg and
//! whether it is an input, and the spanning tree along which the page computes every body's
//! displacement from joint values (the product of exponentials of
//! [`crate::mechanism::Mechanism::poses`], done again in the page).

use crate::manipulator::Manipulator;
use crate::mechanism::Mechanism;
use crate::notation::Primitive;
use crate::spatial::Displacement;
use nalgebra::{Matrix3, SymmetricEigen, Vector3};
use serde::Serialize;

/// A body of the mechanism as drawn.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneBody {
    /// Its name (`ground`, `platform`, `leg 2 link 3`, or a `/2` description's name).
    pub name: String,
    /// `ground`, `end-effector`, `body` (another body the description names) or `link` (an
    /// intermediate body of a leg).
    pub role: &'static str,
    /// The joints on it (indices into [`Scene::joints`]) in the order its outline joins their
    /// sites: around the body's best-fitting plane for a named body (a polygon), along the
    /// leg for a link (a chain of bars).
    pub outline: Vec<usize>,
}

/// A primitive joint as drawn.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneJoint {
    /// Its label: kind, leg and position in the leg (`R1.1`), as inputs are named.
    pub label: String,
    /// `P` or `R`.
    pub kind: char,
    /// The description's joint it is part of: `P`, `R`, `C`, `U` or `S`.
    pub group: char,
    /// An identifier shared by the primitives of one description joint (a U's two revolutes).
    pub group_id: usize,
    /// Its leg, from 1.
    pub leg: usize,
    /// The body it is fixed to (index into [`Scene::bodies`]).
    pub from: usize,
    /// The body its value moves.
    pub to: usize,
    /// Whether it is an input.
    pub actuated: bool,
    /// Its unit axis at the reference configuration (ground frame).
    pub axis: [f64; 3],
    /// A point of its axis at the reference configuration (ground frame; a revolute's site).
    pub point: [f64; 3],
    /// For a prismatic joint, where it is drawn: between the sites of the revolutes before and
    /// after it in its leg (`[before, after]`, indices into [`Scene::joints`], either absent at
    /// a leg's end) at this fraction of the way.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub between: Option<Between>,
}

impl SceneJoint {
    /// The joint `spec` as drawn: named `label`, part of the description joint `group` (its
    /// letter and identifier), on leg `leg` (from 1; 0 for none), an input or not; where a
    /// slider is drawn is set afterwards.
    #[must_use]
    pub fn of(
        spec: &crate::mechanism::JointSpec,
        label: String,
        (group, group_id): (char, usize),
        leg: usize,
        actuated: bool,
    ) -> Self {
        Self {
            label,
            kind: spec.kind.letter(),
            group,
            group_id,
            leg,
            from: spec.from,
            to: spec.to,
            actuated,
            axis: spec.axis.into(),
            point: spec.point.into(),
            between: None,
        }
    }
}

/// Where a prismatic joint is drawn: a fraction of the way between two revolute sites.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Between {
    /// The revolute before it in its leg, if any.
    pub before: Option<usize>,
    /// The revolute after it in its leg, if any.
    pub after: Option<usize>,
    /// The fraction of the way from `before` to `after`.
    pub fraction: f64,
}

/// One step of the spanning tree: `body` is reached from `parent` across `joint`, `sign` +1
/// when the joint is crossed from its `from` body to its `to` body.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TreeStep {
    /// The body reached.
    pub body: usize,
    /// The body it hangs from.
    pub parent: usize,
    /// The joint between them.
    pub joint: usize,
    /// +1 or −1.
    pub sign: f64,
}

/// What a view draws of a manipulator (module documentation).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scene {
    /// The manipulator's name.
    pub name: String,
    /// The description's length unit.
    pub length_unit: String,
    /// The description's angle unit (`deg` or `rad`).
    pub angle_unit: &'static str,
    /// The characteristic length ([`crate::mechanism::Mechanism::scale`]) in the length unit:
    /// the size of the joint symbols.
    pub scale: f64,
    /// The bodies, indexed as in the mechanism.
    pub bodies: Vec<SceneBody>,
    /// The primitive joints, indexed as in the mechanism.
    pub joints: Vec<SceneJoint>,
    /// The spanning tree, parents before children.
    pub tree: Vec<TreeStep>,
    /// The ground (index into `bodies`).
    pub ground: usize,
    /// The end-effector's body (index into `bodies`).
    pub end_effector: usize,
    /// The end-effector's frame at the reference configuration: rotation matrix, row by row.
    pub end_effector_rotation: [f64; 9],
    /// The end-effector's frame origin at the reference configuration.
    pub end_effector_origin: [f64; 3],
}

/// What a scene needs besides its mechanism: the names and units it shows, the joints as drawn
/// and the roles of the bodies.
#[derive(Debug, Clone, PartialEq)]
pub struct Roles {
    /// The manipulator's or chain's name.
    pub name: String,
    /// The length unit.
    pub length_unit: String,
    /// The angle unit (`deg` or `rad`).
    pub angle_unit: &'static str,
    /// The primitive joints as drawn, indexed as in the mechanism.
    pub joints: Vec<SceneJoint>,
    /// The end-effector's body.
    pub end_effector: usize,
    /// The other bodies drawn as named bodies (a polygon through their joints), not links.
    pub named: Vec<usize>,
    /// The end-effector's frame at the reference configuration (ground frame).
    pub end_effector_frame: Displacement,
}

impl Scene {
    /// The scene of manipulator `m`.
    #[must_use]
    pub fn of(m: &Manipulator) -> Self {
        Self::of_mechanism(
            m.mechanism(),
            Roles {
                name: m.name().to_string(),
                length_unit: m.units().length.clone(),
                angle_unit: m.units().angle.symbol(),
                joints: joints_of(m),
                end_effector: m.platform(),
                named: m.bodies().iter().map(|b| b.body).collect(),
                end_effector_frame: m.platform_frame(&m.reference()),
            },
        )
    }

    /// The scene of mechanism `mech` with the bodies' and joints' `roles`: the ground is the
    /// mechanism's, the spanning tree its own (the path of each body from the ground).
    #[must_use]
    pub fn of_mechanism(mech: &Mechanism, roles: Roles) -> Self {
        let joints = roles.joints;
        let bodies = (0..mech.body_count())
            .map(|b| {
                let role = if b == mech.ground() {
                    "ground"
                } else if b == roles.end_effector {
                    "end-effector"
                } else if roles.named.contains(&b) {
                    "body"
                } else {
                    "link"
                };
                let on: Vec<usize> = (0..joints.len())
                    .filter(|&j| joints[j].from == b || joints[j].to == b)
                    .collect();
                let outline = if role == "link" {
                    on
                } else {
                    around(&on, &joints)
                };
                SceneBody {
                    name: mech.body_name(b).to_string(),
                    role,
                    outline,
                }
            })
            .collect();
        let mut tree: Vec<TreeStep> = (0..mech.body_count())
            .filter_map(|b| {
                let &(joint, sign) = mech.path(b).last()?;
                let j = &mech.joints()[joint];
                let parent = if sign > 0.0 { j.from } else { j.to };
                Some(TreeStep {
                    body: b,
                    parent,
                    joint,
                    sign,
                })
            })
            .collect();
        tree.sort_by_key(|s| mech.path(s.body).len());
        let frame = roles.end_effector_frame;
        let r = frame.rotation.matrix();
        Scene {
            name: roles.name,
            length_unit: roles.length_unit,
            angle_unit: roles.angle_unit,
            scale: mech.scale(),
            bodies,
            joints,
            tree,
            ground: mech.ground(),
            end_effector: roles.end_effector,
            end_effector_rotation: std::array::from_fn(|k| r[(k / 3, k % 3)]),
            end_effector_origin: frame.translation.vector.into(),
        }
    }
}

/// The primitive joints, leg by leg, with their description joints and where prismatic joints
/// are drawn.
fn joints_of(m: &Manipulator) -> Vec<SceneJoint> {
    let mech = m.mechanism();
    let actuated: Vec<usize> = m.actuators().iter().map(|a| a.joint).collect();
    let mut out: Vec<Option<SceneJoint>> = vec![None; mech.joints().len()];
    let mut group_id = 0;
    for (i, leg) in m.legs().iter().enumerate() {
        let mut k = leg.joints.start;
        for joint in leg.chain.joints() {
            for _ in joint.kind.primitives() {
                let spec = &mech.joints()[k];
                out[k] = Some(SceneJoint::of(
                    spec,
                    format!(
                        "{}{}.{}",
                        spec.kind.letter(),
                        i + 1,
                        k - leg.joints.start + 1
                    ),
                    (joint.kind.letter(), group_id),
                    i + 1,
                    actuated.contains(&k),
                ));
                k += 1;
            }
            group_id += 1;
        }
        place_sliders(&mut out, leg.joints.clone(), mech);
    }
    // A joint outside every leg (none in the current formats) is drawn on its own.
    out.into_iter()
        .enumerate()
        .map(|(k, j)| {
            j.unwrap_or_else(|| {
                let spec = &mech.joints()[k];
                SceneJoint::of(
                    spec,
                    format!("joint {}", k + 1),
                    (spec.kind.letter(), usize::MAX - k),
                    0,
                    actuated.contains(&k),
                )
            })
        })
        .collect()
}

/// Each run of prismatic joints in a leg is drawn evenly spaced between the revolutes around
/// it (at the one revolute when the run ends the leg).
fn place_sliders(out: &mut [Option<SceneJoint>], range: std::ops::Range<usize>, mech: &Mechanism) {
    let is_r = |k: usize| mech.joints()[k].kind == Primitive::R;
    let mut k = range.start;
    while k < range.end {
        if is_r(k) {
            k += 1;
            continue;
        }
        let start = k;
        while k < range.end && !is_r(k) {
            k += 1;
        }
        let before = (start > range.start).then(|| start - 1);
        let after = (k < range.end).then_some(k);
        let run = k - start;
        for (n, slot) in out[start..k].iter_mut().enumerate() {
            let fraction = match (before, after) {
                (Some(_), Some(_)) => (n + 1) as f64 / (run + 1) as f64,
                (Some(_), None) => 0.0,
                _ => 1.0,
            };
            if let Some(j) = slot.as_mut() {
                j.between = Some(Between {
                    before,
                    after,
                    fraction,
                });
            }
        }
    }
}

/// The joints `on` a rigid body ordered around its best-fitting plane at the reference
/// configuration (by angle about the centroid in the plane of the two largest principal
/// directions of their points), one per distinct point; the drawn polygon keeps this order
/// as the body moves. Prismatic joints, which have no site of their own, are left out.
fn around(on: &[usize], joints: &[SceneJoint]) -> Vec<usize> {
    let mut sites: Vec<(usize, Vector3<f64>)> = Vec::new();
    for &j in on {
        if joints[j].kind == 'P' {
            continue;
        }
        let p = Vector3::from(joints[j].point);
        if sites
            .iter()
            .all(|(_, q)| (q - p).norm() > 1e-9 * (1.0 + p.norm()))
        {
            sites.push((j, p));
        }
    }
    if sites.len() < 3 {
        return sites.into_iter().map(|(j, _)| j).collect();
    }
    let centre = sites.iter().map(|(_, p)| p).sum::<Vector3<f64>>() / sites.len() as f64;
    let covariance = sites
        .iter()
        .map(|(_, p)| (p - centre) * (p - centre).transpose())
        .sum::<Matrix3<f64>>();
    let eigen = SymmetricEigen::new(covariance);
    let mut order: Vec<usize> = (0..3).collect();
    order.sort_by(|a, b| eigen.eigenvalues[*b].total_cmp(&eigen.eigenvalues[*a]));
    let (u, v) = (
        eigen.eigenvectors.column(order[0]).into_owned(),
        eigen.eigenvectors.column(order[1]).into_owned(),
    );
    let mut angled: Vec<(f64, usize)> = sites
        .iter()
        .map(|(j, p)| ((p - centre).dot(&v).atan2((p - centre).dot(&u)), *j))
        .collect();
    angled.sort_by(|a, b| a.0.total_cmp(&b.0));
    angled.into_iter().map(|(_, j)| j).collect()
}
