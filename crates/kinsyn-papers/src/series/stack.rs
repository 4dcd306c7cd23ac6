//! A manipulator read as a series-parallel stack (paper 002): when its moving bodies form a
//! chain from the ground, each joined to the one below by three legs of the paper's kind (RPS or
//! SPR, the prismatic joint actuated), its modules' geometry at a configuration
//! ([`Module`]) is read off the assembled mechanism, so that the paper's Jacobian `J_S-PM` and
//! twist system can be set beside the loop-closure answer.

use super::{Leg as ModuleLeg, Module, SeriesParallel};
use kinsyn::manipulator::{Leg, Manipulator};
use kinsyn::spatial::{Displacement, identity};
use nalgebra::{Point3, Vector3};

/// The manipulator as paper 002's stack of three-legged modules at joint values `q`, or
/// `None` when it is not one: its moving bodies must form a chain from the ground
/// (ground → body 1 → … → body n, the end-effector last) with exactly three legs between
/// consecutive bodies and none elsewhere, each leg an RPS or SPR (in either direction) whose
/// prismatic joint is its only input.
#[must_use]
pub fn stack(m: &Manipulator, q: &[f64]) -> Option<SeriesParallel> {
    let order = stack_order(m)?;
    let ground = m.mechanism().ground();
    let mut modules = Vec::with_capacity(order.len());
    let mut lower_frame = identity();
    let mut lower_body = ground;
    for &b in &order {
        let upper = m.bodies()[b].body;
        let frame = m.body_frame(b, q);
        let legs: Vec<usize> = (0..m.legs().len())
            .filter(|&k| {
                let l = &m.legs()[k];
                (l.from, l.to) == (lower_body, upper) || (l.from, l.to) == (upper, lower_body)
            })
            .collect();
        let legs: [usize; 3] = legs.try_into().ok()?;
        let to_lower = lower_frame.inverse();
        let read = |k: usize| module_leg(m, k, q, &to_lower);
        modules.push(Module {
            pose: to_lower * frame,
            legs: [read(legs[0])?, read(legs[1])?, read(legs[2])?],
        });
        lower_frame = frame;
        lower_body = upper;
    }
    SeriesParallel::new(modules).ok()
}

/// The moving bodies in stack order from the ground, if they form a chain joined by legs
/// only between consecutive bodies and end at the end-effector.
fn stack_order(m: &Manipulator) -> Option<Vec<usize>> {
    let ground = m.mechanism().ground();
    let mut order = Vec::new();
    let mut below = ground;
    while order.len() < m.bodies().len() {
        let next: Vec<usize> = (0..m.bodies().len())
            .filter(|&b| !order.contains(&b))
            .filter(|&b| {
                let body = m.bodies()[b].body;
                m.legs()
                    .iter()
                    .any(|l| (l.from, l.to) == (below, body) || (l.from, l.to) == (body, below))
            })
            .collect();
        let [b] = next[..] else { return None };
        order.push(b);
        below = m.bodies()[b].body;
    }
    let joined = |l: &Leg| {
        let index = |body: usize| {
            if body == ground {
                Some(0)
            } else {
                order
                    .iter()
                    .position(|&b| m.bodies()[b].body == body)
                    .map(|p| p + 1)
            }
        };
        matches!((index(l.from), index(l.to)), (Some(a), Some(b)) if a.abs_diff(b) == 1)
    };
    (m.legs().iter().all(joined) && order.last() == Some(&m.end_effector())).then_some(order)
}

/// Leg `k` as a module leg at `q`, in the lower body's frame (`to_lower` from the ground
/// frame): the S centre (where the S's first two revolute axes meet), the actuated prismatic
/// direction and the revolute axis; `None` unless the leg is an RPS or SPR whose only
/// input is its prismatic joint.
fn module_leg(m: &Manipulator, k: usize, q: &[f64], to_lower: &Displacement) -> Option<ModuleLeg> {
    let leg = &m.legs()[k];
    let joints: Vec<usize> = leg.joints.clone().collect();
    let letters = leg.chain.without_actuation().letters();
    let (r, p, s) = match letters.as_str() {
        "RPS" => (joints[0], joints[1], joints[2]),
        "SPR" => (joints[4], joints[3], joints[0]),
        _ => return None,
    };
    let inputs: Vec<usize> = m
        .actuators()
        .iter()
        .filter(|a| a.leg == k)
        .map(|a| a.joint)
        .collect();
    if inputs != [p] {
        return None;
    }
    let screws = m.mechanism().joint_screws(q);
    let (w1, w2) = (screws[s].w, screws[s + 1].w);
    let a1 = w1.cross(&screws[s].v) / w1.norm_squared();
    let a2 = w2.cross(&screws[s + 1].v) / w2.norm_squared();
    let n = w1.cross(&w2);
    if n.norm_squared() == 0.0 {
        return None;
    }
    let centre: Vector3<f64> = a1 + w1 * ((a2 - a1).cross(&w2).dot(&n) / n.norm_squared());
    Some(ModuleLeg {
        centre: to_lower.transform_point(&Point3::from(centre)).coords,
        actuation: to_lower.rotation * screws[p].v.normalize(),
        constraint: to_lower.rotation * screws[r].w.normalize(),
    })
}
