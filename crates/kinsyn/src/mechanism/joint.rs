//! The primitive joints of a mechanism: a P or an R between two bodies, with its axis at the
//! reference configuration.

use crate::chain::{Displacement, JointAxis};
use crate::notation::Primitive;
use crate::screw::Twist;
use nalgebra::Vector3;

/// A primitive joint of a mechanism at the reference configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointSpec {
    /// P or R.
    pub kind: Primitive,
    /// Unit axis (rotation axis or sliding direction) in the ground frame.
    pub axis: Vector3<f64>,
    /// A point of the axis in the ground frame (ignored for P).
    pub point: Vector3<f64>,
    /// The body the joint is fixed to.
    pub from: usize,
    /// The body the joint value moves relative to `from`.
    pub to: usize,
}

impl JointSpec {
    /// A joint from `from` to `to`; the axis is normalised by [`Mechanism::new`](super::Mechanism::new).
    #[must_use]
    pub fn new(
        kind: Primitive,
        axis: Vector3<f64>,
        point: Vector3<f64>,
        from: usize,
        to: usize,
    ) -> Self {
        JointSpec {
            kind,
            axis,
            point,
            from,
            to,
        }
    }

    /// The joint's axis as a serial-chain joint, whose screw and displacement are the joint's.
    #[must_use]
    pub fn primitive(&self) -> JointAxis {
        JointAxis {
            kind: self.kind,
            axis: self.axis,
            point: self.point,
        }
    }

    /// The unit screw at the reference configuration.
    #[must_use]
    pub fn screw(&self) -> Twist {
        self.primitive().screw()
    }

    pub(super) fn displacement(&self, q: f64) -> Displacement {
        self.primitive().displacement(q)
    }
}
