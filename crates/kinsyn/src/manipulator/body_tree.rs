//! The **body tree** of a manipulator's global analysis: the moving bodies of a description
//! with several (`/2`: stacked modules, split platforms), in **blocks**, each hanging from one
//! **parent** — the ground or a moving body — by all the legs that reach it from outside.
//!
//! - Bodies joined by a **one-joint leg** (a revolute or a slider between two moving bodies)
//!   are one block: its **root** has Study parameters, each other **member** is the root
//!   composed with the joints on its path from the root, whose values are unknowns of the
//!   block (`h<leg>`, the tangent of a revolute's half turn from the reference; `d<leg>`, a
//!   slider's displacement) or given inputs. A leg from the parent to a member, or between two
//!   bodies of the block (a loop inside it), gives the equations of its kind in the Study
//!   parameters of its end relative to its start, written as polynomials of the block's
//!   unknowns by dual-quaternion products ([`crate::geometry::study_product`]).
//! - Each block's constraints are those of a one-platform manipulator on its legs, in the
//!   Study parameters of its root's frame **relative to its parent's** ([`BodyBlock`]): the
//!   blocks share no unknown, so that the constraint variety of the mechanism is the product
//!   of the blocks' varieties. Its assemblies are the combinations of one assembly per block
//!   (their numbers multiply), its operation modes the products of one component per block
//!   (their dimensions add): a stack of modules costs the sum of its modules' paths, not the
//!   product.
//!
//! - A block whose legs come from several bodies, each of which but one is **held** from that
//!   one by a single leg (any serial chain) and reaches nothing but the block otherwise — a
//!   Delta's arms, each on its crank, holding the platform by parallelogram rods; the HEXA's
//!   crank-and-bar holding the platform linkage — takes those bodies in as members whose path
//!   starts at the parent: their frames are the parent's composed with the joints of the leg
//!   that holds them (unknowns, or given inputs), their other legs loops inside the block.
//!
//! Blocks that hang from two bodies otherwise, or from each other in a cycle, do not fit a
//! tree and are refused ([`PositionSystemError::BodyLoop`]).

use super::Manipulator;
use super::component_motion::BlockPart;
use super::polynomial::{InputValues, PositionSystem, PositionSystemError};
use crate::geometry::Chart;
use crate::spatial::Displacement;

/// One block of the body tree: a body, the bodies merged into it through one-joint legs, its
/// parent and the legs that hold it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BodyNode {
    /// The block's root body: an index into [`Manipulator::bodies`].
    pub body: usize,
    /// Its parent: an index into [`Manipulator::bodies`]; `None` for the ground.
    pub parent: Option<usize>,
    /// Its legs (0-based), all from the parent to the root or a member.
    pub legs: Vec<usize>,
    /// The other bodies of the block, each joined to the root by a path of one-joint legs.
    pub members: Vec<Member>,
    /// The legs between bodies of the block that are not on the members' paths: each closes a
    /// loop inside the block.
    pub internal: Vec<usize>,
}

/// A body merged into a block: its frame is the root's (or, for a body held from the parent,
/// the parent's) composed with the joints of its path, whose values are unknowns of the block
/// (or given inputs).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Member {
    /// The body: an index into [`Manipulator::bodies`].
    pub body: usize,
    /// The legs from the root (or the parent) to it, each with whether it is crossed from its
    /// first body to its last (`true`) or back: one-joint legs from the root, or the one leg
    /// (any serial chain) that holds the body from the parent.
    pub path: Vec<(usize, bool)>,
    /// Whether the path starts at the block's parent rather than at its root: a body held
    /// from the parent by one leg whose other legs all reach the block (a Delta's arm, the
    /// HEXA's crank-and-bar), so that the block hangs from one body.
    pub from_parent: bool,
}

/// One block of a manipulator's constraint system (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyBlock {
    /// The root body: an index into [`Manipulator::bodies`].
    pub body: usize,
    /// Its parent: an index into [`Manipulator::bodies`]; `None` for the ground.
    pub parent: Option<usize>,
    /// Its legs (0-based), from the parent to the root or a member.
    pub legs: Vec<usize>,
    /// The other bodies of the block (indices into [`Manipulator::bodies`]).
    pub members: Vec<usize>,
    /// Its constraint system, in the Study parameters of the root's frame relative to the
    /// parent's and the unknown values of the joints that join the members
    /// ([`Manipulator::constraint_system`]'s form; a solution's
    /// [`PositionSystem::displacement`] is the root's frame in the parent's frame,
    /// [`PositionSystem::member_frames`] the members' in the root's).
    pub system: PositionSystem,
}

impl Manipulator {
    /// The body tree (module documentation): for each block, parents first, its root body,
    /// its parent, the legs that hold it, the bodies merged into it through one-joint legs, and
    /// the legs that close loops inside it.
    ///
    /// # Errors
    /// [`PositionSystemError::BodyLoop`] for a leg that ends on the ground, joins a body to
    /// itself, or reaches a block that another body already holds (a loop between blocks);
    /// [`PositionSystemError::Multibody`] for a body no leg reaches.
    pub fn body_tree(&self) -> Result<Vec<BodyNode>, PositionSystemError> {
        let n = self.bodies.len();
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let name = |body: usize| {
            index(body).map_or_else(|| self.ground.clone(), |k| self.bodies[k].name.clone())
        };
        let looped = |i: usize| PositionSystemError::BodyLoop {
            leg: i + 1,
            from: name(self.legs[i].from),
            to: name(self.legs[i].to),
        };
        for (i, leg) in self.legs.iter().enumerate() {
            if leg.from == leg.to || index(leg.to).is_none() {
                return Err(looped(i));
            }
        }
        // Groups of bodies joined by one-joint legs (union–find).
        let joins = |i: usize| {
            let l = &self.legs[i];
            l.joints.len() == 1 && index(l.from).is_some()
        };
        let mut groups = petgraph::unionfind::UnionFind::<usize>::new(n);
        for i in (0..self.legs.len()).filter(|&i| joins(i)) {
            groups.union(
                index(self.legs[i].from).unwrap_or(0),
                index(self.legs[i].to).unwrap_or(0),
            );
        }
        let mut group: Vec<usize> = groups.into_labeling();
        let held = self.held_bodies(&mut group);
        let holding = |i: usize| held.iter().any(|&(_, l)| l == i);
        let in_group = |g: usize, body: usize| index(body).is_some_and(|k| group[k] == g);
        // Each group: the one body all its incoming legs come from, its root (the first member
        // such a leg reaches), its members' paths from the root, the loops inside.
        let mut order: Vec<BodyNode> = Vec::new();
        let mut placed = vec![false; n];
        let mut roots: Vec<usize> = (0..n).filter(|&k| group[k] == k).collect();
        while !roots.is_empty() {
            let mut progressed = false;
            for g in roots.clone() {
                let incoming: Vec<usize> = (0..self.legs.len())
                    .filter(|&i| in_group(g, self.legs[i].to) && !in_group(g, self.legs[i].from))
                    .collect();
                let Some(&first) = incoming.first() else {
                    return Err(PositionSystemError::Multibody {
                        manipulator: self.name.clone(),
                    });
                };
                let parent_body = self.legs[first].from;
                if let Some(&i) = incoming.iter().find(|&&i| self.legs[i].from != parent_body) {
                    return Err(looped(i));
                }
                let incoming: Vec<usize> = incoming.into_iter().filter(|&i| !holding(i)).collect();
                let parent = index(parent_body);
                if parent.is_some_and(|p| !placed[p]) {
                    continue;
                }
                // The root: the body whose paths to the others are shortest in all (each joint
                // of a path raises the degree of the legs beyond it).
                let is_held = |k: usize| held.iter().any(|&(b, _)| b == k);
                let root = (0..n)
                    .filter(|&k| group[k] == g && !is_held(k))
                    .min_by_key(|&k| {
                        let (members, _) = self.group_paths(k, |b| group[b] == g);
                        members.iter().map(|m| m.path.len()).sum::<usize>()
                    })
                    .unwrap_or(g);
                let (mut members, internal) = self.group_paths(root, |k| group[k] == g);
                members.extend(
                    held.iter()
                        .filter(|&&(b, _)| group[b] == g)
                        .map(|&(body, leg)| Member {
                            body,
                            path: vec![(leg, true)],
                            from_parent: true,
                        }),
                );
                for k in (0..n).filter(|&k| group[k] == g) {
                    placed[k] = true;
                }
                order.push(BodyNode {
                    body: root,
                    parent,
                    legs: incoming,
                    members,
                    internal,
                });
                roots.retain(|&r| r != g);
                progressed = true;
            }
            if !progressed {
                // Groups that hang from each other in a cycle.
                let g = roots[0];
                let i = (0..self.legs.len())
                    .find(|&i| in_group(g, self.legs[i].to) && !in_group(g, self.legs[i].from))
                    .unwrap_or(0);
                return Err(looped(i));
            }
        }
        Ok(order)
    }

    /// The bodies held from a block's parent (module documentation), each with the leg that
    /// holds it, moved into the group of the block they hold (`group`: each body's group
    /// label): a body alone in its group, reached by one leg (from the ground or a body outside
    /// the block), whose other legs all start on it and end in one group whose legs come from
    /// more than one body.
    fn held_bodies(&self, group: &mut [usize]) -> Vec<(usize, usize)> {
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let n = self.bodies.len();
        let mut held = Vec::new();
        for k in 0..n {
            if (0..n).any(|m| m != k && group[m] == group[k]) {
                continue;
            }
            let body = self.bodies[k].body;
            let into: Vec<usize> = (0..self.legs.len())
                .filter(|&i| self.legs[i].to == body)
                .collect();
            let out: Vec<usize> = (0..self.legs.len())
                .filter(|&i| self.legs[i].from == body)
                .collect();
            let [leg] = into[..] else { continue };
            let targets: Vec<usize> = out
                .iter()
                .filter_map(|&i| index(self.legs[i].to))
                .map(|t| group[t])
                .collect();
            let Some(&g) = targets.first() else { continue };
            if targets.len() != out.len()
                || targets.iter().any(|&t| t != g)
                || index(self.legs[leg].from).is_some_and(|p| group[p] == g)
            {
                continue;
            }
            // The block it reaches must hang from more than one body.
            let sources: std::collections::BTreeSet<usize> = (0..self.legs.len())
                .filter(|&i| {
                    index(self.legs[i].to).is_some_and(|t| group[t] == g)
                        && index(self.legs[i].from).is_none_or(|f| group[f] != g)
                })
                .map(|i| self.legs[i].from)
                .collect();
            if sources.len() > 1 {
                held.push((k, leg, g));
            }
        }
        // A body held by a held body is not taken in: the block it would join moves itself.
        let singles: Vec<usize> = held.iter().map(|&(k, _, _)| group[k]).collect();
        let held: Vec<(usize, usize)> = held
            .into_iter()
            .filter(|(_, _, g)| !singles.contains(g))
            .map(|(k, leg, _)| (k, leg))
            .collect();
        for &(k, _) in &held {
            let body = self.bodies[k].body;
            if let Some(t) = self
                .legs
                .iter()
                .find(|l| l.from == body)
                .and_then(|l| index(l.to))
            {
                group[k] = group[t];
            }
        }
        held
    }

    /// The members of the group of `root` (the bodies `member` accepts) other than the root,
    /// each with its path of one-joint legs from the root (breadth first), and the legs inside
    /// the group that are not on those paths.
    fn group_paths(
        &self,
        root: usize,
        member: impl Fn(usize) -> bool,
    ) -> (Vec<Member>, Vec<usize>) {
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let inside = |i: usize| {
            let l = &self.legs[i];
            index(l.from).is_some_and(&member) && index(l.to).is_some_and(&member)
        };
        let mut paths: Vec<Option<Vec<(usize, bool)>>> = vec![None; self.bodies.len()];
        paths[root] = Some(Vec::new());
        let mut used = Vec::new();
        let mut queue = std::collections::VecDeque::from([root]);
        while let Some(k) = queue.pop_front() {
            for i in (0..self.legs.len()).filter(|&i| inside(i) && self.legs[i].joints.len() == 1) {
                let l = &self.legs[i];
                let (from, to) = (index(l.from), index(l.to));
                let next = if from == Some(k) {
                    to.map(|t| (t, true))
                } else if to == Some(k) {
                    from.map(|f| (f, false))
                } else {
                    None
                };
                if let Some((next, along)) = next
                    && paths[next].is_none()
                {
                    let mut path = paths[k].clone().unwrap_or_default();
                    path.push((i, along));
                    paths[next] = Some(path);
                    used.push(i);
                    queue.push_back(next);
                }
            }
        }
        let members = paths
            .into_iter()
            .enumerate()
            .filter(|(k, p)| *k != root && p.is_some())
            .map(|(body, path)| Member {
                body,
                path: path.unwrap_or_default(),
                from_parent: false,
            })
            .collect();
        let internal = (0..self.legs.len())
            .filter(|&i| inside(i) && !used.contains(&i))
            .collect();
        (members, internal)
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
                let system = self.block_system(&n, inputs, chart)?;
                Ok(BodyBlock {
                    body: n.body,
                    parent: n.parent,
                    legs: n.legs,
                    members: n.members.iter().map(|m| m.body).collect(),
                    system,
                })
            })
            .collect()
    }

    /// The frame of every moving body (in [`Manipulator::bodies`] order, ground frame) from
    /// one real solution per block of `blocks` (in their order): each root's frame is its
    /// parent's composed with the block's displacement, each member's the root's composed with
    /// its joints'.
    ///
    /// # Errors
    /// A solution that is no displacement ([`crate::spatial::study::StudyError`]).
    pub fn body_frames(
        &self,
        blocks: &[BodyBlock],
        solutions: &[&[f64]],
    ) -> Result<Vec<Displacement>, crate::spatial::study::StudyError> {
        let parts: Vec<BlockPart<'_>> = blocks
            .iter()
            .map(|b| (b.parent, b.body, &b.system))
            .collect();
        self.frames_of_blocks(&parts, solutions)
    }
}
