//! Screws: twists, wrenches, Plücker lines, adjoint transforms, the reciprocal product and the
//! rank of screw systems.
//!
//! The ranks, span and null-space bases and the checked SVD ([`svd`], [`rank`], [`rank6`],
//! [`span_basis`], [`nullspace`], [`Rank`]), the ranks a QR certifies to be the SVD's
//! ([`rank_quick`], [`span_basis_quick`], [`full_row_rank`]), the least-norm Newton step
//! ([`min_norm_step`]), random null-space directions ([`null_direction`]) and truncated least
//! squares ([`least_squares`]) are the crate's linear-algebra layer, re-exported here; this
//! module adds the screw theory on top of them ([`reciprocal_complement`]).
//!
//! Conventions (ARCHITECTURE.md): a twist is `t = (ω; v)`, the angular velocity and the velocity of
//! the body point that coincides with the frame origin; a wrench is `w = (f; m)`, the force and
//! the moment about the origin. The reciprocal (virtual power) product is `w · t = f·v + m·ω`.
//! The joint screw of a revolute with unit axis `u` through `p` is `(u; p × u)`; of a prismatic
//! joint along `u`, `(0; u)`.
//!
//! ```
//! use kinsyn::screw::{Twist, Wrench, reciprocal_product};
//! use nalgebra::Vector3;
//! // A revolute about z through (1, 0, 0) and a pure force along z through the same point:
//! // the force does no work on the rotation (they intersect).
//! let r = Twist::revolute(Vector3::z(), Vector3::new(1.0, 0.0, 0.0));
//! let f = Wrench::force(Vector3::z(), Vector3::new(1.0, 0.0, 0.0));
//! assert!(reciprocal_product(&f, &r).abs() < 1e-12);
//! ```

pub use crate::linalg::{
    DEFAULT_RANK_TOLERANCE, FullRowRank, LeastSquares, Rank, Svd, full_row_rank, least_squares,
    min_norm_step, null_direction, nullspace, nullspace_scaled, rank, rank_quick, rank6,
    span_basis, span_basis_quick, span_basis_scaled, svd,
};
pub use crate::spatial::{Twist, adjoint, skew, transform_twist};
use nalgebra::{DMatrix, Vector3, Vector6};

/// A wrench `(f; m)`: a force and its moment about the frame origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrench {
    /// Force.
    pub f: Vector3<f64>,
    /// Moment about the origin.
    pub m: Vector3<f64>,
}

/// The joint screws of screw theory and the geometry of a twist (its pitch and axis); the
/// type and its coordinates are defined with the displacements in [`crate::spatial`].
impl Twist {
    /// The unit twist of a revolute joint: rotation about the line through `point` along the
    /// unit vector `axis`, `(u; p × u)`.
    #[must_use]
    pub fn revolute(axis: Vector3<f64>, point: Vector3<f64>) -> Self {
        Twist {
            w: axis,
            v: point.cross(&axis),
        }
    }

    /// The unit twist of a prismatic joint along `axis`, `(0; u)`.
    #[must_use]
    pub fn prismatic(axis: Vector3<f64>) -> Self {
        Twist {
            w: Vector3::zeros(),
            v: axis,
        }
    }

    /// A helical twist of pitch `pitch` about the line through `point` along `axis`.
    #[must_use]
    pub fn helical(axis: Vector3<f64>, point: Vector3<f64>, pitch: f64) -> Self {
        Twist {
            w: axis,
            v: point.cross(&axis) + axis * pitch,
        }
    }

    /// The velocity of the body point at `point`: `v + ω × p`.
    #[must_use]
    pub fn velocity_at(&self, point: &Vector3<f64>) -> Vector3<f64> {
        self.v + self.w.cross(point)
    }

    /// The same motion with its reference point moved to `point` (twist about a new origin at
    /// `point`, axes unchanged): `(ω; v + ω × p)`.
    #[must_use]
    pub fn at_point(&self, point: &Vector3<f64>) -> Self {
        Twist {
            w: self.w,
            v: self.velocity_at(point),
        }
    }

    /// The pitch `ω·v / ω·ω` of a twist with rotation; `None` for a pure translation.
    #[must_use]
    pub fn pitch(&self) -> Option<f64> {
        let ww = self.w.norm_squared();
        (ww > 0.0).then(|| self.w.dot(&self.v) / ww)
    }

    /// The screw axis of a twist with rotation: the point of the axis nearest the origin and
    /// the unit direction, `p = ω × v / |ω|²`.
    #[must_use]
    pub fn axis(&self) -> Option<(Vector3<f64>, Vector3<f64>)> {
        let ww = self.w.norm_squared();
        (ww > 0.0).then(|| (self.w.cross(&self.v) / ww, self.w / ww.sqrt()))
    }
}

impl Wrench {
    /// A pure force of unit direction `dir` along the line through `point`: `(f; p × f)`.
    #[must_use]
    pub fn force(dir: Vector3<f64>, point: Vector3<f64>) -> Self {
        Wrench {
            f: dir,
            m: point.cross(&dir),
        }
    }

    /// A pure couple (moment) `m`.
    #[must_use]
    pub fn couple(m: Vector3<f64>) -> Self {
        Wrench {
            f: Vector3::zeros(),
            m,
        }
    }

    /// The six coordinates `(f; m)`.
    #[must_use]
    pub fn to_vector(&self) -> Vector6<f64> {
        Vector6::new(self.f.x, self.f.y, self.f.z, self.m.x, self.m.y, self.m.z)
    }

    /// From six coordinates `(f; m)`.
    #[must_use]
    pub fn from_vector(x: &Vector6<f64>) -> Self {
        Wrench {
            f: Vector3::new(x[0], x[1], x[2]),
            m: Vector3::new(x[3], x[4], x[5]),
        }
    }
}

/// The virtual power of a wrench on a twist, `f·v + m·ω`: zero when the wrench is reciprocal
/// to (does no work on) the twist.
#[must_use]
pub fn reciprocal_product(w: &Wrench, t: &Twist) -> f64 {
    w.f.dot(&t.v) + w.m.dot(&t.w)
}

/// The Lie bracket of two twists, `[t1, t2] = (ω1 × ω2; ω1 × v2 − ω2 × v1)`: the motion that
/// the commutator of the two infinitesimal displacements produces. A set of twists is the Lie
/// algebra of a displacement subgroup exactly when its span is closed under this bracket.
#[must_use]
pub fn lie_bracket(a: &Twist, b: &Twist) -> Twist {
    Twist {
        w: a.w.cross(&b.w),
        v: a.w.cross(&b.v) - b.w.cross(&a.v),
    }
}

/// A Plücker line: unit direction and moment about the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// Unit direction.
    pub direction: Vector3<f64>,
    /// Moment `p × direction` for any point `p` of the line.
    pub moment: Vector3<f64>,
}

impl Line {
    /// The line through `point` along `direction` (normalised).
    #[must_use]
    pub fn through(point: Vector3<f64>, direction: Vector3<f64>) -> Self {
        let d = direction.normalize();
        Line {
            direction: d,
            moment: point.cross(&d),
        }
    }

    /// The point of the line nearest the origin.
    #[must_use]
    pub fn nearest_point(&self) -> Vector3<f64> {
        self.direction.cross(&self.moment)
    }

    /// The reciprocal product of two lines as screws (mutual moment): zero when they are
    /// coplanar (intersect or are parallel).
    #[must_use]
    pub fn mutual_moment(&self, other: &Line) -> f64 {
        self.direction.dot(&other.moment) + self.moment.dot(&other.direction)
    }
}

/// The wrenches reciprocal to every twist in the columns of `twists`: the constraint wrench
/// system of a twist system (a basis, one wrench `(f; m)` per column).
///
/// A wrench `w` is reciprocal to `t` when `f·v + m·ω = 0`, i.e. `(Δ t)ᵀ w = 0` with `Δ` the
/// block swap; the result is the null space of `(Δ T)ᵀ`.
#[must_use]
pub fn reciprocal_complement(twists: &DMatrix<f64>, tolerance: f64) -> DMatrix<f64> {
    let n = twists.ncols();
    let mut swapped = DMatrix::zeros(n, 6);
    for j in 0..n {
        for k in 0..3 {
            swapped[(j, k)] = twists[(k + 3, j)];
            swapped[(j, k + 3)] = twists[(k, j)];
        }
    }
    if n == 0 {
        return DMatrix::identity(6, 6);
    }
    nullspace(&swapped, tolerance).0
}
