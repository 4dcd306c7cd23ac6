//! The **body tree** of a manipulator's global analysis: the moving bodies of a description
//! with several (`/2`: stacked modules), each hanging from one other body — its **parent**, the
//! ground or a moving body — by all of its legs. Each body's constraints are then those of a
//! one-platform manipulator on its legs, in the Study parameters of its frame **relative to its
//! parent's** ([`BodyBlock`]): the blocks share no unknown, so that the constraint variety of
//! the mechanism is the product of the blocks' varieties. Its assemblies are the combinations of
//! one assembly per block (their numbers multiply), its operation modes the products of one
//! component per block (their dimensions add): a stack of modules costs the sum of its modules'
//! paths, not the product.
//!
//! A leg that closes a loop between moving bodies (two bodies both held by the ground and
//! joined to each other, a ring of bodies) does not fit a tree and is refused
//! ([`PositionSystemError::BodyLoop`]).

use super::Manipulator;
use super::construction::MechanismBuilder;
use super::polynomial::{InputValues, PositionSystem, PositionSystemError};
use crate::geometry::Chart;
use crate::spatial::Displacement;

/// One moving body of the body tree: its parent and the legs that hold it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BodyNode {
    /// The body: an index into [`Manipulator::bodies`].
    pub body: usize,
    /// Its parent: an index into [`Manipulator::bodies`]; `None` for the ground.
    pub parent: Option<usize>,
    /// Its legs (0-based), all from the parent to it.
    pub legs: Vec<usize>,
}

/// One moving body's block of a manipulator's constraint system (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyBlock {
    /// The body: an index into [`Manipulator::bodies`].
    pub body: usize,
    /// Its parent: an index into [`Manipulator::bodies`]; `None` for the ground.
    pub parent: Option<usize>,
    /// Its legs (0-based), all from the parent to it.
    pub legs: Vec<usize>,
    /// Its constraint system, in the Study parameters of its frame relative to the parent's
    /// ([`Manipulator::constraint_system`]'s form; a solution's
    /// [`PositionSystem::displacement`] is the body's frame in the parent's frame).
    pub system: PositionSystem,
}

impl Manipulator {
    /// The body tree (module documentation): for each moving body, parents first, its parent
    /// and its legs.
    ///
    /// # Errors
    /// [`PositionSystemError::BodyLoop`] for a leg that ends on the ground, joins a body to
    /// itself, or reaches a body that another body already holds (a loop between moving
    /// bodies); [`PositionSystemError::Multibody`] for a body no leg reaches.
    pub fn body_tree(&self) -> Result<Vec<BodyNode>, PositionSystemError> {
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let name = |body: usize| {
            index(body).map_or_else(|| self.ground.clone(), |k| self.bodies[k].name.clone())
        };
        let looped = |i: usize| PositionSystemError::BodyLoop {
            leg: i + 1,
            from: name(self.legs[i].from),
            to: name(self.legs[i].to),
        };
        // The parent of each body: the one body all its legs come from.
        let mut parent: Vec<Option<usize>> = vec![None; self.bodies.len()];
        for (i, leg) in self.legs.iter().enumerate() {
            let to = index(leg.to).ok_or_else(|| looped(i))?;
            if leg.from == leg.to {
                return Err(looped(i));
            }
            match parent[to] {
                None => parent[to] = Some(leg.from),
                Some(p) if p == leg.from => {}
                Some(_) => return Err(looped(i)),
            }
        }
        // Parents first, from the ground: a body whose chain of parents does not reach the
        // ground (a cycle of bodies) is never placed.
        let mut order: Vec<BodyNode> = Vec::new();
        let mut placed = vec![false; self.bodies.len()];
        while order.len() < self.bodies.len() {
            let next = (0..self.bodies.len()).find(|&k| {
                !placed[k]
                    && parent[k].is_some_and(|p| {
                        p == MechanismBuilder::GROUND || index(p).is_some_and(|q| placed[q])
                    })
            });
            let Some(k) = next else {
                let stuck = (0..self.bodies.len()).find(|&k| !placed[k]).unwrap_or(0);
                return match self.legs.iter().position(|l| index(l.to) == Some(stuck)) {
                    Some(i) => Err(looped(i)),
                    None => Err(PositionSystemError::Multibody {
                        manipulator: self.name.clone(),
                    }),
                };
            };
            placed[k] = true;
            let p = parent[k].and_then(index);
            let legs = (0..self.legs.len())
                .filter(|&i| index(self.legs[i].to) == Some(k))
                .collect();
            order.push(BodyNode {
                body: k,
                parent: p,
                legs,
            });
        }
        Ok(order)
    }

    /// The manipulator's constraint system as one block per moving body of its body tree
    /// (module documentation), each with the chart `chart`; a one-platform manipulator has one
    /// block, [`Manipulator::constraint_system`].
    ///
    /// # Errors
    /// As [`Manipulator::body_tree`] and [`Manipulator::constraint_system`].
    pub fn body_blocks(
        &self,
        inputs: &InputValues,
        chart: &Chart,
    ) -> Result<Vec<BodyBlock>, PositionSystemError> {
        self.body_tree()?
            .into_iter()
            .map(|n| {
                let system = self.block_system(n.body, n.parent, &n.legs, inputs, chart)?;
                Ok(BodyBlock {
                    body: n.body,
                    parent: n.parent,
                    legs: n.legs,
                    system,
                })
            })
            .collect()
    }

    /// The frame of every moving body (in [`Manipulator::bodies`] order, ground frame) from
    /// one relative displacement per block of `blocks` (in their order): each body's frame is
    /// its parent's composed with its block's displacement.
    #[must_use]
    pub fn body_frames(
        &self,
        blocks: &[BodyBlock],
        relative: &[Displacement],
    ) -> Vec<Displacement> {
        let mut frames = vec![crate::spatial::identity(); self.bodies.len()];
        for (b, g) in blocks.iter().zip(relative) {
            let parent = b
                .parent
                .map_or_else(crate::spatial::identity, |p| frames[p]);
            frames[b.body] = parent * g;
        }
        frames
    }
}
