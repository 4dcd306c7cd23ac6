//! Mechanisms as graphs of bodies and joints: loop closure, mobility, the twist space of a body,
//! and finite motion sampled by position-level loop closure.
//!
//! A [`Mechanism`] is an undirected graph (petgraph) whose nodes are rigid bodies and whose edges
//! are primitive joints (P or R; C, U and S joints are chains of primitives through massless
//! intermediate bodies). One body is the ground. Every joint is given at the *reference
//! configuration* (all joint values zero): its kind, its unit axis and a point of the axis in
//! the ground frame, and the two bodies it joins, `from` and `to`: its joint value moves `to`
//! relative to `from`.
//!
//! A spanning tree grown from the ground gives every body a path of joints; the joints off the
//! tree (chords) close one loop each — a fundamental cycle basis, so the mechanism has
//! `joints − bodies + 1` independent loops. With the screws of the product-of-exponentials
//! convention (ARCHITECTURE.md: twist `(ω; v)` at the ground origin),
//! - a body's displacement is the product of `exp(±ξ q)` along its tree path;
//! - a chord `a → b` closes when `g_a exp(ξ q) g_b⁻¹ = I`;
//! - the loop-closure Jacobian `C` says `V_b − V_a − ξ' q̇ = 0` for each chord, with `V` the
//!   spatial twist of a body and `ξ'` the chord's current screw;
//! - the mobility is the dimension of the null space of `C` (joint rates compatible with every
//!   loop), and a body's local degrees of freedom are the dimension of its twists over it.
//!
//! Rank decisions use a dimensionless copy of each matrix: twists and wrenches are referred to the
//! mechanism's characteristic point [`Mechanism::centre`] and lengths are divided by its
//! characteristic length [`Mechanism::scale`] (the RMS distance of the revolute axis points from
//! their centroid), so millimetres and metres, or a mechanism far from the origin, give the same
//! ranks. Tolerances are relative to quantities that cannot be round-off (the norm of a Jacobian
//! whose columns are unit screws, or 1 for an orthonormal basis), never to a product's own
//! largest singular value.
//!
//! ```
//! use kinsyn::mechanism::{Mechanism, JointSpec};
//! use kinsyn::notation::Primitive::R;
//! use nalgebra::Vector3;
//! // A planar four-bar: ground, crank, coupler, rocker; axes along z.
//! let z = Vector3::z();
//! let p = |x: f64, y: f64| Vector3::new(x, y, 0.0);
//! let m = Mechanism::new(
//!     &["ground", "crank", "coupler", "rocker"],
//!     0,
//!     vec![
//!         JointSpec::new(R, z, p(0.0, 0.0), 0, 1),
//!         JointSpec::new(R, z, p(0.0, 1.0), 1, 2),
//!         JointSpec::new(R, z, p(2.0, 1.5), 2, 3),
//!         JointSpec::new(R, z, p(2.5, 0.0), 3, 0),
//!     ],
//! ).unwrap();
//! assert_eq!(m.loop_count(), 1);
//! let q = vec![0.0; 4];
//! // Grübler–Kutzbach in the plane gives 1; the spatial count 4 − 6 would give −2.
//! assert_eq!(m.mobility(&q, &[false; 4]).dof, 1);
//! ```

mod assembly;
mod closure;
mod joint;
mod mobility;
mod motion;
mod relative;

pub use assembly::{ASSEMBLY_STEPS, ASSEMBLY_TOLERANCE, AssemblySettings, Coordinate, Goal};
pub use joint::JointSpec;
pub use mobility::{ImageRanks, Mobility};
pub use motion::{
    MotionSample, RANDOM_ASSEMBLY_STEPS, STEP_TRIES, SampleSettings, SampledMotion, WALK_ATTEMPTS,
};

use crate::notation::Primitive;
use crate::screw;
pub use crate::spatial::{compose, exp, inverse, log, rotation_log};
use nalgebra::{DMatrix, Vector3};
use petgraph::graph::{NodeIndex, UnGraph};
use petgraph::visit::{Bfs, EdgeRef};

/// The rank tolerance of loop-closure and twist-space matrices (relative to the largest
/// singular value of their dimensionless form).
pub const MOBILITY_TOLERANCE: f64 = 1e-9;

/// Why a mechanism could not be built or moved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MechanismError {
    /// A joint names a body that does not exist.
    #[error("joint {joint}: body {body} does not exist ({bodies} bodies)")]
    UnknownBody {
        /// 1-based joint index.
        joint: usize,
        /// The body index named.
        body: usize,
        /// The number of bodies.
        bodies: usize,
    },
    /// A joint joins a body to itself.
    #[error("joint {joint} joins body {body:?} to itself")]
    SelfJoint {
        /// 1-based joint index.
        joint: usize,
        /// The body's name.
        body: String,
    },
    /// An axis of no length or a non-finite point.
    #[error("joint {joint}: {what}")]
    BadAxis {
        /// 1-based joint index.
        joint: usize,
        /// What is wrong.
        what: String,
    },
    /// A body no chain of joints connects to the ground.
    #[error("body {0:?} is not connected to the ground")]
    Disconnected(String),
    /// Newton's method did not close the loops (or reach the asked-for pose).
    #[error(
        "the loops do not close: residual {residual:.3e} after {iterations} damped Newton steps"
    )]
    NotAssembled {
        /// The final residual (rotation in rad, translation over the length scale).
        residual: f64,
        /// Newton steps taken.
        iterations: usize,
    },
}

/// One step of a body's tree path: the joint, and +1 when the path crosses it from `from` to
/// `to`, −1 the other way.
type PathStep = (usize, f64);

/// A mechanism: bodies, primitive joints, a ground, and the loops they close.
#[derive(Debug, Clone)]
pub struct Mechanism {
    graph: UnGraph<String, usize>,
    joints: Vec<JointSpec>,
    ground: usize,
    /// For each body, the joints from the ground to it along the spanning tree.
    paths: Vec<Vec<PathStep>>,
    /// Bodies in breadth-first order from the ground, with the tree joint reaching each.
    order: Vec<(usize, Option<PathStep>)>,
    /// The joints off the spanning tree: one independent loop each.
    chords: Vec<usize>,
    centre: Vector3<f64>,
    scale: f64,
}

impl Mechanism {
    /// A mechanism of named bodies, the body that is the ground, and primitive joints.
    ///
    /// # Errors
    /// A joint naming a body that does not exist or the same body twice, an axis of no length,
    /// a non-finite point, or a body not connected to the ground.
    pub fn new(
        bodies: &[&str],
        ground: usize,
        joints: Vec<JointSpec>,
    ) -> Result<Self, MechanismError> {
        let mut graph = UnGraph::<String, usize>::new_undirected();
        let nodes: Vec<NodeIndex> = bodies
            .iter()
            .map(|b| graph.add_node((*b).to_string()))
            .collect();
        let mut normalised = Vec::with_capacity(joints.len());
        for (i, mut j) in joints.into_iter().enumerate() {
            for body in [j.from, j.to] {
                if body >= bodies.len() {
                    return Err(MechanismError::UnknownBody {
                        joint: i + 1,
                        body,
                        bodies: bodies.len(),
                    });
                }
            }
            if j.from == j.to {
                return Err(MechanismError::SelfJoint {
                    joint: i + 1,
                    body: bodies[j.from].to_string(),
                });
            }
            let n = j.axis.norm();
            if !n.is_finite() || n < 1e-12 {
                return Err(MechanismError::BadAxis {
                    joint: i + 1,
                    what: "the axis direction has no length".into(),
                });
            }
            if !j.point.iter().all(|c| c.is_finite()) {
                return Err(MechanismError::BadAxis {
                    joint: i + 1,
                    what: "the axis point is not finite".into(),
                });
            }
            j.axis /= n;
            graph.add_edge(nodes[j.from], nodes[j.to], i);
            normalised.push(j);
        }
        if ground >= bodies.len() {
            return Err(MechanismError::Disconnected(format!("ground #{ground}")));
        }
        // Spanning tree by breadth-first search from the ground.
        let mut paths: Vec<Option<Vec<PathStep>>> = vec![None; bodies.len()];
        paths[ground] = Some(Vec::new());
        let mut order = vec![(ground, None)];
        let mut tree = vec![false; normalised.len()];
        let mut bfs = Bfs::new(&graph, nodes[ground]);
        while let Some(node) = bfs.next(&graph) {
            let here = node.index();
            for edge in graph.edges(node) {
                let other = if edge.source() == node {
                    edge.target()
                } else {
                    edge.source()
                }
                .index();
                let joint = *edge.weight();
                if paths[other].is_none() {
                    let sign = if normalised[joint].from == here {
                        1.0
                    } else {
                        -1.0
                    };
                    let mut path = paths[here].clone().unwrap_or_default();
                    path.push((joint, sign));
                    paths[other] = Some(path);
                    order.push((other, Some((joint, sign))));
                    tree[joint] = true;
                }
            }
        }
        let paths = paths
            .into_iter()
            .enumerate()
            .map(|(b, p)| p.ok_or_else(|| MechanismError::Disconnected(bodies[b].to_string())))
            .collect::<Result<Vec<_>, _>>()?;
        let chords = (0..normalised.len()).filter(|&j| !tree[j]).collect();
        let (centre, scale) = characteristic(&normalised);
        Ok(Mechanism {
            graph,
            joints: normalised,
            ground,
            paths,
            order,
            chords,
            centre,
            scale,
        })
    }

    /// The joints, in the order given.
    #[must_use]
    pub fn joints(&self) -> &[JointSpec] {
        &self.joints
    }

    /// The number of bodies, ground included.
    #[must_use]
    pub fn body_count(&self) -> usize {
        self.graph.node_count()
    }

    /// A body's name.
    #[must_use]
    pub fn body_name(&self, body: usize) -> &str {
        &self.graph[NodeIndex::new(body)]
    }

    /// The ground body.
    #[must_use]
    pub fn ground(&self) -> usize {
        self.ground
    }

    /// The number of independent loops (joints off the spanning tree).
    #[must_use]
    pub fn loop_count(&self) -> usize {
        self.chords.len()
    }

    /// The joints that close the loops, one per loop.
    #[must_use]
    pub fn loop_joints(&self) -> &[usize] {
        &self.chords
    }

    /// The characteristic length: the root-mean-square distance of the revolute axis points from
    /// their centroid (of every joint point when there is no revolute; 1 when all the points
    /// coincide, where no length enters the kinematics). Rank decisions and tolerances are taken
    /// relative to it, so they do not depend on the length unit.
    #[must_use]
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// The characteristic point: the centroid of the points that define [`Mechanism::scale`].
    /// Dimensionless twists and wrenches are referred to it, so that a mechanism far from the
    /// ground origin is not ill-conditioned.
    #[must_use]
    pub fn centre(&self) -> Vector3<f64> {
        self.centre
    }

    /// Spatial twists `(ω; v)` (6-row blocks of `m`, `v` the velocity of the point at the ground
    /// origin) in the dimensionless form: `(ω; (v + ω × c) / L)`, the velocity of the point at
    /// the centre `c` over the characteristic length `L`.
    #[must_use]
    pub fn unitless_twists(&self, m: &DMatrix<f64>) -> DMatrix<f64> {
        map_velocities(m, |w, v| (v + w.cross(&self.centre)) / self.scale)
    }

    /// The inverse of [`Mechanism::unitless_twists`]: physical twists at the ground origin.
    #[must_use]
    pub fn physical_twists(&self, m: &DMatrix<f64>) -> DMatrix<f64> {
        map_velocities(m, |w, vc| vc * self.scale - w.cross(&self.centre))
    }

    /// A wrench `(f; m_O)` (moment about the ground origin) in the dimensionless form
    /// `(f; m_c / L)`, its moment about the centre over the characteristic length. The
    /// reciprocal product of a dimensionless wrench and twist is the physical one over `L`.
    #[must_use]
    pub fn unitless_wrench(&self, w: &screw::Wrench) -> nalgebra::Vector6<f64> {
        let mc = (w.m - self.centre.cross(&w.f)) / self.scale;
        nalgebra::Vector6::new(w.f.x, w.f.y, w.f.z, mc.x, mc.y, mc.z)
    }

    /// The inverse of [`Mechanism::unitless_wrench`].
    #[must_use]
    pub fn physical_wrench(&self, x: &[f64]) -> screw::Wrench {
        let f = Vector3::new(x[0], x[1], x[2]);
        let mc = Vector3::new(x[3], x[4], x[5]) * self.scale;
        screw::Wrench {
            f,
            m: mc + self.centre.cross(&f),
        }
    }

    /// The size of one dimensionless unit of joint `j`'s value: the length scale for a
    /// prismatic joint, one radian for a revolute.
    #[must_use]
    pub fn unit(&self, j: usize) -> f64 {
        if self.joints[j].kind == Primitive::P {
            self.scale
        } else {
            1.0
        }
    }
}

/// Twists (6-row blocks of the columns of `m`) with their linear parts replaced by
/// `velocity(ω, v)`: a change of reference point or of length unit.
fn map_velocities(
    m: &DMatrix<f64>,
    velocity: impl Fn(Vector3<f64>, Vector3<f64>) -> Vector3<f64>,
) -> DMatrix<f64> {
    let mut out = m.clone();
    for block in (0..m.nrows() / 6).map(|b| 6 * b) {
        for col in 0..m.ncols() {
            let w = Vector3::from_fn(|k, _| m[(block + k, col)]);
            let v = Vector3::from_fn(|k, _| m[(block + 3 + k, col)]);
            let moved = velocity(w, v);
            for k in 0..3 {
                out[(block + 3 + k, col)] = moved[k];
            }
        }
    }
    out
}

/// The characteristic point and length of a set of joints (see [`Mechanism::scale`] and
/// [`Mechanism::centre`]): those of the revolute axis points, or of every joint point when there
/// is no revolute.
fn characteristic(joints: &[JointSpec]) -> (Vector3<f64>, f64) {
    let revolutes: Vec<Vector3<f64>> = joints
        .iter()
        .filter(|j| j.kind == Primitive::R)
        .map(|j| j.point)
        .collect();
    if revolutes.is_empty() {
        characteristic_of(&joints.iter().map(|j| j.point).collect::<Vec<_>>())
    } else {
        characteristic_of(&revolutes)
    }
}

/// The characteristic point and length of a set of points: their centroid and their RMS
/// distance from it; the length is 1 when the points coincide (to round-off of their
/// coordinates), where no length enters the kinematics. Every twist and wrench kinsyn makes
/// dimensionless is referred to such a point and divided by such a length.
pub(crate) fn characteristic_of(points: &[Vector3<f64>]) -> (Vector3<f64>, f64) {
    if points.is_empty() {
        return (Vector3::zeros(), 1.0);
    }
    let n = points.len() as f64;
    let centroid = points.iter().fold(Vector3::zeros(), |s, p| s + p) / n;
    let rms = (points
        .iter()
        .map(|p| (p - centroid).norm_squared())
        .sum::<f64>()
        / n)
        .sqrt();
    let extent = points
        .iter()
        .map(nalgebra::Matrix::norm)
        .fold(0.0, f64::max);
    if rms > 1e-12 * extent && rms > 1e-150 {
        (centroid, rms)
    } else {
        (centroid, 1.0)
    }
}
