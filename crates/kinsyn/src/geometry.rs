//! Constraint polynomials from geometry: the conditions that points, vectors, lines and planes
//! of a moving body meet those of the ground, written in the body's **Study parameters**
//! (paper 004 §3, eqs. 4–13; Husty, Pfurner, Schröcker, Brunthaler 2007), and the plain
//! distance, unit-vector and sine–cosine conditions of other formulations (paper 003 eqs. 3,
//! 6, 8, 9, 15).
//!
//! # Study parameters as polynomials
//! [`StudyVariables`] names eight variables of a ring `x0, x1, x2, x3, y0, y1, y2, y3` with the
//! conventions of [`crate::spatial::study`]: the matrix `M = [[Δ, 0ᵀ], [M_T, M_R]]` of paper 004
//! eqs. 4–5, `Δ = x·x = x0² + x1² + x2² + x3²`, a displacement `p ↦ R p + t` with `R = M_R / Δ`,
//! `t = M_T / Δ`, `M_R v = x v x̄` and `M_T = 2 vec(x ȳ)` in quaternion products (Husty's sign of
//! `y`). Since `R` and `t` are rational, a moving point and a moving vector are written scaled by
//! `Δ`: [`StudyVariables::point`] is `Δ (R p + t) = M_R p + M_T` and [`StudyVariables::vector`]
//! is `Δ R v = M_R v`, both quadratic.
//!
//! Every constraint below is a **homogeneous quadratic** in the eight parameters (the degree is
//! repeated in each doc), so that a system of them with the Study quadric and a linear chart has
//! Bézout number `2^7`. Three identities, exact for any eight numbers (quaternion algebra: for
//! a pure quaternion `p`, `p·vec(q) = −scal(p q)`, and `scal(p q̄)` is the dot product of `p`
//! and `q` in R⁴), bring the constraints down to degree 2:
//! - `Δ (R v)·a = (M_R v)·a` — degree 2;
//! - `Δ (R v)·t = (M_R v)·M_T / Δ = −2 scal(x v x̄ x ȳ) / Δ = −2 scal(x v ȳ) = −2 (x v)·y`
//!   (the last a dot product in R⁴) — degree 2, bilinear in `x` and `y`;
//! - `Δ |t|² = 4 |vec(x ȳ)|² / Δ = 4 (Δ |y|² − (x·y)²) / Δ`, which **on the Study quadric**
//!   `x·y = 0` is `4 |y|²` — degree 2.
//!
//! The conditions that use the third identity ([`StudyVariables::distance`],
//! [`StudyVariables::lines_coplanar`]) hold on the quadric only, which every system built here
//! contains.

use crate::poly::{C64, Poly, System};
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};

/// A 3-vector of polynomials of one ring.
pub type PolyVector = [Poly; 3];

/// The names of the Study parameters in a [`System`] built here: `x0 … x3, y0 … y3`.
pub const STUDY_NAMES: [&str; 8] = ["x0", "x1", "x2", "x3", "y0", "y1", "y2", "y3"];

/// The constant vector `v` in a ring of `nvars` variables.
#[must_use]
pub fn constant_vector(nvars: usize, v: &Vector3<f64>) -> PolyVector {
    [
        Poly::real(nvars, v.x),
        Poly::real(nvars, v.y),
        Poly::real(nvars, v.z),
    ]
}

/// The vector of the variables `indices` of a ring of `nvars` variables.
///
/// # Panics
/// If an index is not below `nvars`.
#[must_use]
pub fn variable_vector(nvars: usize, indices: [usize; 3]) -> PolyVector {
    indices.map(|i| Poly::variable(nvars, i))
}

/// The dot product `a·b` (degree: the sum of the degrees).
#[must_use]
pub fn dot(a: &PolyVector, b: &PolyVector) -> Poly {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// The cross product `a × b`.
#[must_use]
pub fn cross(a: &PolyVector, b: &PolyVector) -> PolyVector {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// `a − b`.
#[must_use]
pub fn difference(a: &PolyVector, b: &PolyVector) -> PolyVector {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

/// `c · a` for a real `c`.
#[must_use]
pub fn scaled(a: &PolyVector, c: f64) -> PolyVector {
    [a[0].clone() * c, a[1].clone() * c, a[2].clone() * c]
}

/// The squared distance `|p − q|²` of two points given as polynomial vectors.
#[must_use]
pub fn squared_distance(p: &PolyVector, q: &PolyVector) -> Poly {
    let d = difference(p, q);
    dot(&d, &d)
}

/// The distance condition `|p − q|² − l²` (paper 003 eqs. 6, 8: a link of length `l` between
/// two points; paper 001 eq. 4): zero exactly when the points are `l` apart (for real points).
/// Twice the degree of the points (degree 2 for points linear in the unknowns, as paper 003's
/// planar ones).
#[must_use]
pub fn distance_condition(p: &PolyVector, q: &PolyVector, length: f64) -> Poly {
    let n = p[0].nvars();
    squared_distance(p, q) - Poly::real(n, length * length)
}

/// The unit-vector condition `u·u − 1` (twice the degree of `u`).
#[must_use]
pub fn unit_vector(u: &PolyVector) -> Poly {
    let n = u[0].nvars();
    dot(u, u) - Poly::real(n, 1.0)
}

/// The sine–cosine identity `s² + c² − 1` (paper 003 eqs. 3, 15): `s` and `c` are the sine and
/// cosine of one angle (degree 2 for variables).
#[must_use]
pub fn sin_cos(s: &Poly, c: &Poly) -> Poly {
    let n = s.nvars();
    s * s + c * c - Poly::real(n, 1.0)
}

/// How the projective Study parameters are made affine, so that a system has isolated
/// solutions and excludes the exceptional generator `x = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Chart {
    /// `x·x − 1 = 0` (paper 004's `g14`): quadratic, every pose twice (`x` and `−x`).
    Unit,
    /// `a·x − 1 = 0` for a real `a`: linear, every pose once — except the poses with
    /// `a·x = 0`, a measure-zero set a random `a` misses. Real poses have real parameters.
    Linear([f64; 4]),
}

impl Chart {
    /// The linear chart with `a` drawn uniformly from `[−1, 1]⁴` by a generator seeded with
    /// `seed` (ChaCha8): reproducible, generic, and real (real poses stay real solutions).
    #[must_use]
    pub fn random_linear(seed: u64) -> Self {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        Chart::Linear(std::array::from_fn(|_| rng.random_range(-1.0..1.0)))
    }

    /// The representative of Study parameters `s` (any scale) on this chart: `s / (a·x)` for
    /// the linear chart, `s / |x|` with `x0 ≥ 0` for the unit one. `None` when `s` has no
    /// representative (`a·x = 0`, or `x = 0`).
    #[must_use]
    pub fn representative(&self, s: &[f64; 8]) -> Option<[f64; 8]> {
        let scale = match self {
            Chart::Unit => {
                let n = s[..4].iter().map(|c| c * c).sum::<f64>().sqrt();
                let leading = s[..4].iter().copied().find(|c| *c != 0.0)?;
                n.copysign(leading)
            }
            Chart::Linear(a) => (0..4).map(|i| a[i] * s[i]).sum(),
        };
        (scale != 0.0 && scale.is_finite()).then(|| s.map(|c| c / scale))
    }
}

/// Eight variables of a ring taken as the Study parameters `x0 … x3, y0 … y3` of a moving
/// frame (module documentation), and the constraint polynomials of that frame's points,
/// vectors, lines and planes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StudyVariables {
    nvars: usize,
    indices: [usize; 8],
}

impl StudyVariables {
    /// The Study parameters `x0 … x3, y0 … y3` as the variables `indices` of a ring of `nvars`.
    ///
    /// # Panics
    /// If an index is not below `nvars` or two indices are equal (a programming error).
    #[must_use]
    pub fn new(nvars: usize, indices: [usize; 8]) -> Self {
        for (k, i) in indices.iter().enumerate() {
            assert!(*i < nvars, "variable {i} of a ring with {nvars} variables");
            assert!(!indices[..k].contains(i), "variable {i} named twice");
        }
        Self { nvars, indices }
    }

    /// The Study parameters as the first eight variables of a ring of `nvars ≥ 8`.
    ///
    /// # Panics
    /// If `nvars < 8`.
    #[must_use]
    pub fn leading(nvars: usize) -> Self {
        Self::new(nvars, [0, 1, 2, 3, 4, 5, 6, 7])
    }

    /// The number of variables of the ring.
    #[must_use]
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    /// The variables' indices, `x0 … x3, y0 … y3`.
    #[must_use]
    pub fn indices(&self) -> [usize; 8] {
        self.indices
    }

    /// The rotation quaternion `x = (x0, x1, x2, x3)`.
    #[must_use]
    pub fn x(&self) -> [Poly; 4] {
        std::array::from_fn(|k| Poly::variable(self.nvars, self.indices[k]))
    }

    /// The dual part `y = (y0, y1, y2, y3)`.
    #[must_use]
    pub fn y(&self) -> [Poly; 4] {
        std::array::from_fn(|k| Poly::variable(self.nvars, self.indices[4 + k]))
    }

    fn constant(&self, c: f64) -> Poly {
        Poly::real(self.nvars, c)
    }

    /// `Δ = x0² + x1² + x2² + x3²` (degree 2): the scale of `M` (paper 004 eq. 4).
    #[must_use]
    pub fn delta(&self) -> Poly {
        let x = self.x();
        dot4(&x, &x)
    }

    /// The Study quadric `x0 y0 + x1 y1 + x2 y2 + x3 y3` (paper 004 eq. 7, `g13`; degree 2):
    /// zero at the parameters of every displacement.
    #[must_use]
    pub fn quadric(&self) -> Poly {
        dot4(&self.x(), &self.y())
    }

    /// The unit normalisation `x·x − 1` (paper 004's `g14`; degree 2).
    #[must_use]
    pub fn unit_normalisation(&self) -> Poly {
        self.delta() - self.constant(1.0)
    }

    /// The linear chart `a·x − 1` (degree 1).
    #[must_use]
    pub fn linear_chart(&self, a: &[f64; 4]) -> Poly {
        let x = self.x();
        (0..4).fold(-self.constant(1.0), |acc, i| acc + x[i].clone() * a[i])
    }

    /// The chart's equation: [`Self::unit_normalisation`] or [`Self::linear_chart`].
    #[must_use]
    pub fn chart(&self, chart: &Chart) -> Poly {
        match chart {
            Chart::Unit => self.unit_normalisation(),
            Chart::Linear(a) => self.linear_chart(a),
        }
    }

    /// `M_R` of paper 004 eq. 5 (entries of degree 2 in `x`): `Δ` times the rotation.
    #[must_use]
    pub fn rotation(&self) -> [[Poly; 3]; 3] {
        let [x0, x1, x2, x3] = self.x();
        let sq = |a: &Poly| a * a;
        let two = |p: Poly| p * 2.0;
        [
            [
                sq(&x0) + sq(&x1) - sq(&x2) - sq(&x3),
                two(&x1 * &x2 - &x0 * &x3),
                two(&x1 * &x3 + &x0 * &x2),
            ],
            [
                two(&x1 * &x2 + &x0 * &x3),
                sq(&x0) - sq(&x1) + sq(&x2) - sq(&x3),
                two(&x2 * &x3 - &x0 * &x1),
            ],
            [
                two(&x1 * &x3 - &x0 * &x2),
                two(&x2 * &x3 + &x0 * &x1),
                sq(&x0) - sq(&x1) - sq(&x2) + sq(&x3),
            ],
        ]
    }

    /// `M_T` of paper 004 eq. 5 (bilinear in `x` and `y`): `Δ` times the translation.
    #[must_use]
    pub fn translation(&self) -> PolyVector {
        let [x0, x1, x2, x3] = self.x();
        let [y0, y1, y2, y3] = self.y();
        [
            (-(&x0 * &y1) + &x1 * &y0 - &x2 * &y3 + &x3 * &y2) * 2.0,
            (-(&x0 * &y2) + &x1 * &y3 + &x2 * &y0 - &x3 * &y1) * 2.0,
            (-(&x0 * &y3) - &x1 * &y2 + &x2 * &y1 + &x3 * &y0) * 2.0,
        ]
    }

    /// The moving vector `v` (body frame) in the ground frame, times `Δ`: `Δ R v = M_R v`
    /// (degree 2 in `x`).
    #[must_use]
    pub fn vector(&self, v: &Vector3<f64>) -> PolyVector {
        let m = self.rotation();
        std::array::from_fn(|i| {
            m[i][0].clone() * v.x + m[i][1].clone() * v.y + m[i][2].clone() * v.z
        })
    }

    /// The moving point `p` (body frame) in the ground frame, times `Δ`:
    /// `Δ (R p + t) = M_R p + M_T` (paper 004 eq. 9; degree 2).
    #[must_use]
    pub fn point(&self, p: &Vector3<f64>) -> PolyVector {
        let r = self.vector(p);
        let t = self.translation();
        std::array::from_fn(|i| &r[i] + &t[i])
    }

    /// The quaternion product `x v` with `v = (0, v)` pure.
    fn x_times(&self, v: &Vector3<f64>) -> [Poly; 4] {
        let [x0, x1, x2, x3] = self.x();
        [
            -(x1.clone() * v.x + x2.clone() * v.y + x3.clone() * v.z),
            x0.clone() * v.x + x2.clone() * v.z - x3.clone() * v.y,
            x0.clone() * v.y + x3.clone() * v.x - x1.clone() * v.z,
            x0 * v.z + x1 * v.y - x2 * v.x,
        ]
    }

    /// `Δ (R v)·t = −2 (x v)·y` (module documentation; exact, bilinear).
    fn rotated_dot_translation(&self, v: &Vector3<f64>) -> Poly {
        dot4(&self.x_times(v), &self.y()) * -2.0
    }

    /// `Δ (R v × t)`, equal on the Study quadric to `2 vec(x v ȳ)` (bilinear): with `p = x v`,
    /// `vec(p ȳ) = y0 p⃗ − p0 y⃗ − p⃗ × y⃗`.
    fn rotated_cross_translation(&self, v: &Vector3<f64>) -> PolyVector {
        let p = self.x_times(v);
        let y = self.y();
        let pv = [p[1].clone(), p[2].clone(), p[3].clone()];
        let yv = [y[1].clone(), y[2].clone(), y[3].clone()];
        let c = cross(&pv, &yv);
        std::array::from_fn(|i| (&y[0] * &pv[i] - &p[0] * &yv[i] - &c[i]) * 2.0)
    }

    /// The **distance** condition between the fixed point `a` (ground frame) and the moving
    /// point `b` (body frame): `|R b + t − a| = l` (paper 003 eqs. 6, 8, 9; paper 001 eq. 4;
    /// paper 004 eqs. 12), in Husty's quadratic form (Husty 1996, *An algorithm for solving
    /// the direct kinematics of general Stewart–Gough platforms*, Mech. Mach. Theory 31(4)).
    ///
    /// Derivation: expand
    ///
    /// `|R b + t − a|² − l² = |a|² + |b|² − l² − 2 a·R b − 2 a·t + 2 (R b)·t + |t|²`
    ///
    /// and multiply by `Δ`. With `Δ R b = M_R b`, `Δ t = M_T`, `Δ (R b)·t = −2 (x b)·y` and,
    /// on the quadric, `Δ |t|² = 4 y·y` (module documentation):
    ///
    /// `(|a|² + |b|² − l²) Δ − 2 a·(M_R b) − 2 a·M_T − 4 (x b)·y + 4 y·y = 0`,
    ///
    /// a homogeneous **quadric** in `(x, y)` (degree 2), equal to
    /// `Δ (|R b + t − a|² − l²) + 4 (x·y)² / Δ` for any eight numbers, hence to `Δ (d² − l²)`
    /// on the Study quadric: for a displacement it vanishes exactly when the points are `l`
    /// apart. (Paper 004's `g5 … g8` have this form, with the factor `1 + t₁ᵢ²` of their
    /// half-angle substitution: `(4 t² + 4) y·y`.)
    #[must_use]
    pub fn distance(&self, a: &Vector3<f64>, b: &Vector3<f64>, length: f64) -> Poly {
        let av = constant_vector(self.nvars, a);
        let y = self.y();
        self.delta() * (a.norm_squared() + b.norm_squared() - length * length)
            - dot(&av, &self.vector(b)) * 2.0
            - dot(&av, &self.translation()) * 2.0
            + self.rotated_dot_translation(b) * 2.0
            + dot4(&y, &y) * 4.0
    }

    /// The moving point `b` (body frame) lies on the fixed plane through `a` with normal `n`
    /// (ground frame): `n·(R b + t − a) = 0` times `Δ`,
    /// `n·(M_R b + M_T) − Δ n·a = 0` — degree 2, exact off the quadric too. (An R joint of axis
    /// `n` at the base keeps the centre of a spherical joint in such a plane: 3-RPS.)
    #[must_use]
    pub fn moving_point_on_fixed_plane(
        &self,
        b: &Vector3<f64>,
        a: &Vector3<f64>,
        n: &Vector3<f64>,
    ) -> Poly {
        let nv = constant_vector(self.nvars, n);
        dot(&nv, &self.point(b)) - self.delta() * n.dot(a)
    }

    /// The fixed point `a` (ground frame) lies on the moving plane through `b` with normal `m`
    /// (body frame): `(R m)·(a − R b − t) = 0` times `Δ`,
    /// `(M_R m)·a − Δ m·b + 2 (x m)·y = 0` (`(x m)·y` the dot product in R⁴ of the quaternion
    /// product `x (0, m)` with `y`) — degree 2, exact off the quadric too. (An R joint of axis
    /// `m` on the platform keeps the centre of a spherical joint on the base in such a plane:
    /// SPR legs.)
    #[must_use]
    pub fn fixed_point_on_moving_plane(
        &self,
        a: &Vector3<f64>,
        b: &Vector3<f64>,
        m: &Vector3<f64>,
    ) -> Poly {
        let av = constant_vector(self.nvars, a);
        dot(&av, &self.vector(m)) - self.delta() * m.dot(b) - self.rotated_dot_translation(m)
    }

    /// The moving vector `v` (body frame) is orthogonal to the fixed vector `n` (ground
    /// frame): `n·(M_R v) = 0` — degree 2, in `x` only (paper 004 eq. 13's scalar product).
    #[must_use]
    pub fn moving_vector_orthogonal(&self, v: &Vector3<f64>, n: &Vector3<f64>) -> Poly {
        dot(&constant_vector(self.nvars, n), &self.vector(v))
    }

    /// The moving point `b` (body frame) coincides with the fixed point `a`:
    /// `M_R b + M_T − Δ a = 0`, three equations of degree 2 (a spherical joint between the
    /// body and the ground).
    #[must_use]
    pub fn moving_point_at(&self, b: &Vector3<f64>, a: &Vector3<f64>) -> PolyVector {
        let p = self.point(b);
        let d = self.delta();
        std::array::from_fn(|i| &p[i] - &(d.clone() * a[i]))
    }

    /// The moving unit vector `m` (body frame) is carried onto the fixed unit vector `n`
    /// (ground frame): `R m = n`. For a real `x ≠ 0`, `x m x̄ = Δ n` is equivalent to the
    /// quaternion equation `x m = n x`, four **linear** equations in `x` of rank 2 (the
    /// rotations that carry `m` onto `n` form a circle: a line of the projective space of `x`).
    /// Returned: two independent real combinations of them (the right singular vectors of
    /// their coefficient matrix for its two nonzero singular values), `x` only — degree 1. (The
    /// platform of a planar leg turns about the leg's axis only: `R m = n` for its axis `m` in
    /// the platform frame.)
    ///
    /// # Panics
    /// Never: the singular value decomposition is asked for its right singular vectors.
    #[must_use]
    pub fn vector_onto(&self, m: &Vector3<f64>, n: &Vector3<f64>) -> [Poly; 2] {
        let c = vector_onto_coefficients(m, n);
        let svd = c.svd(false, true);
        let v_t = svd.v_t.expect("the right singular vectors were asked for");
        let mut order = [0, 1, 2, 3];
        order.sort_by(|a, b| svd.singular_values[*b].total_cmp(&svd.singular_values[*a]));
        let x = self.x();
        order[..2]
            .iter()
            .map(|&k| {
                (0..4).fold(Poly::zero(self.nvars), |acc, j| {
                    acc + x[j].clone() * v_t[(k, j)]
                })
            })
            .collect::<Vec<_>>()
            .try_into()
            .expect("two rows")
    }

    /// The four linear equations `x m − n x = 0` of [`Self::vector_onto`] (degree 1), for a
    /// fixed vector `n` that is itself a polynomial vector (a turned axis, scaled by any
    /// weight `w`: then `w x m − (w n) x`, with `w` the polynomial `weight`).
    #[must_use]
    pub fn vector_onto_turned(&self, m: &Vector3<f64>, n: &PolyVector, weight: &Poly) -> [Poly; 4] {
        let x = self.x();
        let xm = self.x_times(m);
        // n x = [−n·x⃗, x0 n + n × x⃗] for the pure quaternion n.
        let xv = [x[1].clone(), x[2].clone(), x[3].clone()];
        let nx0 = -dot(n, &xv);
        let nc = cross(n, &xv);
        let nxv: [Poly; 3] = std::array::from_fn(|i| &(&x[0] * &n[i]) + &nc[i]);
        [
            weight * &xm[0] - nx0,
            weight * &xm[1] - nxv[0].clone(),
            weight * &xm[2] - nxv[1].clone(),
            weight * &xm[3] - nxv[2].clone(),
        ]
    }

    /// The angle between the fixed unit vector `n` (ground frame) and the moving unit vector
    /// `m` (body frame) has cosine `c`: `n·(M_R m) − c Δ = 0` — degree 2, in `x` only. (The two
    /// revolutes of a spherical RR dyad keep their axes at the link's twist angle.)
    #[must_use]
    pub fn vectors_at_angle(&self, n: &Vector3<f64>, m: &Vector3<f64>, c: f64) -> Poly {
        self.moving_vector_orthogonal(m, n) - self.delta() * c
    }

    /// The fixed line through `a` along `u` (ground frame) and the moving line through `b`
    /// along `m` (body frame) are coplanar — they meet or are parallel (paper 004 eq. 10:
    /// `(r_C − r_B)·(v × n) = 0`, the link of an RUU leg in the plane of its two axes):
    /// `(R b + t − a)·(u × R m) = 0` times `Δ`, which on the Study quadric is
    ///
    /// `u·(M_R (m × b)) + 2 u·vec(x m ȳ) − a·(u × M_R m) = 0`
    ///
    /// (using `Δ (R m × t) = 2 vec(x m ȳ)` there) — degree 2, like paper 004's `g1 … g4`.
    #[must_use]
    pub fn lines_coplanar(
        &self,
        a: &Vector3<f64>,
        u: &Vector3<f64>,
        b: &Vector3<f64>,
        m: &Vector3<f64>,
    ) -> Poly {
        let uv = constant_vector(self.nvars, u);
        let av = constant_vector(self.nvars, a);
        dot(&uv, &self.vector(&m.cross(b))) + dot(&uv, &self.rotated_cross_translation(m))
            - dot(&av, &cross(&uv, &self.vector(m)))
    }
}

/// The coefficient matrix `C` of the four linear equations `x m − n x = C x` (rows: the
/// scalar part, then the vector part) of [`StudyVariables::vector_onto`]:
/// `x m − n x = [−x⃗·(m − n), x0 (m − n) + x⃗ × (m + n)]`.
fn vector_onto_coefficients(m: &Vector3<f64>, n: &Vector3<f64>) -> nalgebra::Matrix4<f64> {
    let d = m - n;
    let s = m + n;
    // x⃗ × s = −[s]ₓ x⃗.
    nalgebra::Matrix4::new(
        0.0, -d.x, -d.y, -d.z, //
        d.x, 0.0, s.z, -s.y, //
        d.y, -s.z, 0.0, s.x, //
        d.z, s.y, -s.x, 0.0,
    )
}

/// Study parameters whose entries are polynomials `x0 … x3, y0 … y3` of one ring: a
/// displacement that depends on unknowns (a body's frame relative to another through joints
/// whose values are unknowns), up to a non-zero factor like the Study parameters themselves.
pub type StudyPolys = [Poly; 8];

/// The constant Study parameters `s` in a ring of `nvars` variables.
#[must_use]
pub fn study_constant(nvars: usize, s: &[f64; 8]) -> StudyPolys {
    std::array::from_fn(|k| Poly::real(nvars, s[k]))
}

/// The quaternion product of `a` and `b` (scalar first).
fn quaternion_product(a: &[Poly; 4], b: &[Poly; 4]) -> [Poly; 4] {
    [
        &a[0] * &b[0] - &a[1] * &b[1] - &a[2] * &b[2] - &a[3] * &b[3],
        &a[0] * &b[1] + &a[1] * &b[0] + &a[2] * &b[3] - &a[3] * &b[2],
        &a[0] * &b[2] + &a[2] * &b[0] + &a[3] * &b[1] - &a[1] * &b[3],
        &a[0] * &b[3] + &a[3] * &b[0] + &a[1] * &b[2] - &a[2] * &b[1],
    ]
}

/// The Study parameters of the composition `a ∘ b` (first `b`, then `a`; as frames, `b`
/// relative to `a`'s): the dual-quaternion product `(x_a + ε y_a)(x_b + ε y_b)`, i.e.
/// `x = x_a x_b`, `y = x_a y_b + y_a x_b` — with [`crate::spatial::study`]'s `y = −½ t x`,
/// `R = R_a R_b` and `t = R_a t_b + t_a` give exactly these. Bilinear: the degrees add.
#[must_use]
pub fn study_product(a: &StudyPolys, b: &StudyPolys) -> StudyPolys {
    let (xa, ya) = split(a);
    let (xb, yb) = split(b);
    let x = quaternion_product(&xa, &xb);
    let y1 = quaternion_product(&xa, &yb);
    let y2 = quaternion_product(&ya, &xb);
    std::array::from_fn(|k| {
        if k < 4 {
            x[k].clone()
        } else {
            &y1[k - 4] + &y2[k - 4]
        }
    })
}

/// The Study parameters of the inverse displacement: the conjugate `(x̄, ȳ)` (on the Study
/// quadric, `(x + εy)(x̄ + εȳ) = Δ`, a real number). Linear.
#[must_use]
pub fn study_inverse(a: &StudyPolys) -> StudyPolys {
    std::array::from_fn(|k| {
        if k % 4 == 0 {
            a[k].clone()
        } else {
            -a[k].clone()
        }
    })
}

fn split(a: &StudyPolys) -> ([Poly; 4], [Poly; 4]) {
    (
        std::array::from_fn(|k| a[k].clone()),
        std::array::from_fn(|k| a[4 + k].clone()),
    )
}

/// The Study parameters of the turn by `θ` about the line through `p` along the unit `u`,
/// with `t = tan(θ/2)` the variable `t` of a ring of `nvars`: `x = (1, t u)`,
/// `y = (0, t u × p)` — `cos(θ/2)` times the normalised parameters (the translation of the
/// turn is `p − R p`, and `−½ (p − R p) x = (0, sin(θ/2) u × p)`), **affine in `t`**.
#[must_use]
pub fn study_turn(nvars: usize, t: usize, u: &Vector3<f64>, p: &Vector3<f64>) -> StudyPolys {
    let t = Poly::variable(nvars, t);
    let m = u.cross(p);
    let zero = Poly::zero(nvars);
    [
        Poly::real(nvars, 1.0),
        t.clone() * u.x,
        t.clone() * u.y,
        t.clone() * u.z,
        zero,
        t.clone() * m.x,
        t.clone() * m.y,
        t * m.z,
    ]
}

/// The Study parameters of the slide by `d` along the unit `u`, with `d` the variable `d` of a
/// ring of `nvars`: `x = (1, 0)`, `y = (0, −½ d u)`. Affine in `d`.
#[must_use]
pub fn study_slide(nvars: usize, d: usize, u: &Vector3<f64>) -> StudyPolys {
    let d = Poly::variable(nvars, d);
    let zero = Poly::zero(nvars);
    [
        Poly::real(nvars, 1.0),
        zero.clone(),
        zero.clone(),
        zero.clone(),
        zero,
        d.clone() * (-0.5 * u.x),
        d.clone() * (-0.5 * u.y),
        d * (-0.5 * u.z),
    ]
}

/// The dot product of two quaternions as vectors of R⁴.
fn dot4(a: &[Poly; 4], b: &[Poly; 4]) -> Poly {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2] + &a[3] * &b[3]
}

/// The forward kinematics of a general **Gough–Stewart platform** in Study parameters (Husty
/// 1996): leg `i` joins the base point `base[i]` (ground frame) to the platform point
/// `platform[i]` (platform frame) with length `lengths[i]`. The system in `x0 … y3`
/// ([`STUDY_NAMES`]) is the six [`StudyVariables::distance`] quadrics, the Study quadric and
/// the chart's equation: degrees `2⁷ · 1` (Bézout number 128) with a linear chart, `2⁸` with
/// the unit one. A generic platform has 40 complex assemblies (Raghavan 1993; Husty 1996),
/// each once in the linear chart and twice (`±`) in the unit one.
///
/// # Panics
/// Never: the eight names are distinct and every equation is in their ring.
#[must_use]
pub fn gough_stewart(
    base: &[Vector3<f64>; 6],
    platform: &[Vector3<f64>; 6],
    lengths: &[f64; 6],
    chart: &Chart,
) -> System {
    let s = StudyVariables::leading(8);
    let mut equations: Vec<Poly> = (0..6)
        .map(|i| s.distance(&base[i], &platform[i], lengths[i]))
        .collect();
    equations.push(s.quadric());
    equations.push(s.chart(chart));
    study_system(equations)
}

/// The system of `equations` in the eight Study parameters named [`STUDY_NAMES`].
///
/// # Panics
/// If an equation is not in a ring of eight variables (a programming error).
#[must_use]
pub fn study_system(equations: Vec<Poly>) -> System {
    System::new(STUDY_NAMES.map(String::from).to_vec(), equations)
        .expect("eight distinct names, equations in their ring")
}

/// The values of a polynomial vector at a real point (test and diagnostic helper).
#[must_use]
pub fn evaluate_vector(v: &PolyVector, x: &[f64]) -> Vector3<f64> {
    let z: Vec<C64> = x.iter().map(|r| C64::new(*r, 0.0)).collect();
    Vector3::new(v[0].eval(&z).re, v[1].eval(&z).re, v[2].eval(&z).re)
}
