//! Certified roots of square polynomial systems: a computer proof, by the Krawczyk operator in
//! interval arithmetic, that an approximate root returned by a solver (such as the homotopy
//! continuation of `crate::homotopy`) approximates exactly one true root, that the roots of a
//! list are pairwise distinct, and, for real systems, which roots are real.
//!
//! # The test
//!
//! Let `F : ℂⁿ → ℂⁿ` be the system, `x̃` an approximate root, `Y ≈ J(x̃)⁻¹` any fixed matrix and
//! `D` a box of offsets (a rectangle per coordinate) containing 0. The Krawczyk operator in
//! offset form is
//!
//! ```text
//! K(D) = −Y·F(x̃) + (I − Y·J(x̃ + D))·D
//! ```
//!
//! evaluated in interval arithmetic ([`interval`]): `F(x̃)` over the point `x̃`, the Jacobian over
//! the box `x̃ + D`, `Y` as point intervals. If `K(D)` lies in the interior of `D`, then `Y` and
//! every Jacobian in `J(x̃ + D)` are non-singular and `x̃ + D` holds **exactly one** root of `F`
//! (Krawczyk, *Computing* 4 (1969) 187–201; Moore, *SIAM J. Numer. Anal.* 14 (1977) 611–615;
//! Rump, *Acta Numerica* 19 (2010) 287–449, §13). The theorem is stated over ℝⁿ; rectangular
//! complex interval arithmetic is exactly real interval arithmetic on the real and imaginary
//! parts (the realified `2n × 2n` system, whose Jacobian is the realification of `J`), so it
//! applies to complex boxes. Whether or not the test passes, every root in `x̃ + D` lies in
//! `x̃ + K(D)`: the certificate's [`Certificate::enclosure`] is the intersection of such sets,
//! far smaller than the box of uniqueness.
//!
//! A **singular root** (a double root, a positive-dimensional component) can never pass: the
//! test proves non-singularity of the Jacobian on the box. Such roots are reported as
//! [`FailureReason::Singular`] or [`FailureReason::NotContracting`], never as certified.
//!
//! # Strategy
//!
//! 1. Up to [`CertifyOptions::newton_steps`] floating-point Newton steps polish `x̃` (stopping
//!    when a step no longer shrinks).
//! 2. `Y` is the floating-point inverse of `J(x̃)` (LU with partial pivoting).
//! 3. With `a = max |−Y·F(x̃)|` (the interval Newton step, rounding included), the radii
//!    `r = 2a, 4a, 16a, 256a, 4096a` are tried in turn for `D = [−r, r] + i·[−r, r]` in every
//!    coordinate: the first that passes is the certificate's radius. Small radii keep the
//!    enclosure tight; larger ones absorb a contraction factor `‖I − Y·J‖` near 1
//!    (ill-conditioned roots).
//! 4. The enclosure is tightened by Krawczyk iteration, `D ← D ∩ hull(K(D), 0)`.
//! 5. The whole box must lie within [`CertifyOptions::tolerance`] (relative to
//!    `max(1, ‖x̃‖∞)`) of the point given: a certificate says that point *is* an approximate
//!    root, not merely that Newton's method from it found one somewhere.
//!
//! # Real roots
//!
//! For a system with real coefficients and a point within the tolerance of ℝⁿ, the same test
//! runs on the real box `Re x̃ + [−r, r]ⁿ` with the real `Y = J(Re x̃)⁻¹` in real interval
//! arithmetic. Success proves a real root in the real box; the complex test is then run at the
//! same real centre with a radius at least `r`, so the real box lies in the complex box of
//! uniqueness, and the unique complex root is that real one: [`Reality::CertifiedReal`].
//! Otherwise, if some coordinate of a certified enclosure has an imaginary part excluding 0,
//! the root is [`Reality::CertifiedNonReal`] (for any system); else [`Reality::Unknown`].
//!
//! # Distinct roots
//!
//! Two certified roots with disjoint enclosures are different roots. [`certify_roots`] compares
//! every pair; overlapping enclosures are first tightened by further Krawczyk iterations
//! (shrinking them towards the rounding level), and if they still overlap both are reported not
//! [`Certificate::distinct`]. When one enclosure lies inside the other root's box of uniqueness
//! the two are *proven* to be the same root, found twice ([`Certificate::same_as`]): the sign of
//! a path jump in a homotopy.
//!
//! ```
//! use kinsyn_nag::certify::{certify_roots, CertificateStatus, Reality};
//! use kinsyn_nag::poly::{Poly, System, C64};
//! // x² − 2 = 0, roots ±√2.
//! let x = Poly::variable(1, 0);
//! let system = System::new(vec!["x".into()], vec![&x * &x - Poly::real(1, 2.0)]).unwrap();
//! let roots = [vec![C64::new(1.41421356, 0.0)], vec![C64::new(-1.41421356, 0.0)]];
//! let certificates = certify_roots(&system.program(), &roots, system.is_real()).unwrap();
//! for c in &certificates {
//!     assert!(matches!(c.status, CertificateStatus::Certified { .. }));
//!     assert_eq!(c.real, Reality::CertifiedReal);
//!     assert!(c.distinct);
//! }
//! ```

pub mod interval;

pub use interval::{ComplexInterval, Interval};

use crate::poly::{C64, Program, Scalar, Workspace};
use nalgebra::DMatrix;
use rayon::prelude::*;

/// Why roots cannot be certified at all: the input does not describe a square system and its
/// points.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CertifyError {
    /// The system has another number of equations than variables.
    #[error("the system is not square: {equations} equations in {variables} variables")]
    NotSquare {
        /// The number of equations.
        equations: usize,
        /// The number of variables.
        variables: usize,
    },
    /// A point has another number of coordinates than the system has variables.
    #[error("root {root} has {found} coordinates, the system has {expected} variables")]
    RootLength {
        /// The point (0-based).
        root: usize,
        /// The number of variables.
        expected: usize,
        /// The number of coordinates given.
        found: usize,
    },
}

/// Why one point was not certified.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum FailureReason {
    /// The point, or the system's value or Jacobian there, is not finite.
    #[error("the point or the system's values there are not finite")]
    NonFinite,
    /// The Jacobian at the point is singular in floating point: no Newton step, no `Y`.
    #[error("the Jacobian is singular at the point")]
    Singular,
    /// The Krawczyk inclusion failed at every radius tried: the point is not close enough to a
    /// regular root (or the root is singular, or too ill-conditioned for double precision).
    #[error("the Krawczyk operator does not contract at any radius tried")]
    NotContracting,
    /// Newton's corrections, or the box a root was proven in, reach farther from the given
    /// point than the tolerance allows: the point is not an approximate root.
    #[error("the nearest root found is {distance:e} away, beyond the tolerance")]
    TooFar {
        /// The distance (max-norm over real and imaginary parts) reached.
        distance: f64,
    },
}

/// The outcome of the Krawczyk test for one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CertificateStatus {
    /// The set `refined ± radius` (in each real and imaginary part, exact real arithmetic)
    /// contains exactly one root of the system, and the root is regular.
    Certified {
        /// The half-width of the box of uniqueness.
        radius: f64,
    },
    /// Nothing is claimed about the point.
    Failed(FailureReason),
}

/// What is proven about the root being real.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reality {
    /// The certified root has real coordinates.
    CertifiedReal,
    /// Some coordinate of the certified root has a non-zero imaginary part.
    CertifiedNonReal,
    /// Not proven either way (or the root is not certified).
    Unknown,
}

/// The certificate of one approximate root.
#[derive(Debug, Clone, PartialEq)]
pub struct Certificate {
    /// Whether a unique root is proven near the point, and in which box.
    pub status: CertificateStatus,
    /// Whether that root is proven real or non-real.
    pub real: Reality,
    /// Whether the root is proven different from every other certified root of the list
    /// ([`certify_roots`]); `false` for a failed certificate, and from [`certify_root`] alone
    /// (which has nothing to compare with).
    pub distinct: bool,
    /// `Some(j)`: the root is proven to be the same as the root of certificate `j` (the
    /// first such of the list): one root found twice.
    pub same_as: Option<usize>,
    /// The centre of the box: the point given after Newton's polishing (its real part for a
    /// certified real root). For a failed certificate, the last Newton iterate.
    pub refined: Vec<C64>,
    /// A box containing the root, one rectangle per coordinate, inside the box of uniqueness
    /// (up to outward rounding); empty for a failed certificate.
    pub enclosure: Vec<ComplexInterval>,
}

impl Certificate {
    /// Whether a unique regular root is proven.
    #[must_use]
    pub fn is_certified(&self) -> bool {
        matches!(self.status, CertificateStatus::Certified { .. })
    }

    /// The half-width of the box of uniqueness, if certified.
    #[must_use]
    pub fn radius(&self) -> Option<f64> {
        match self.status {
            CertificateStatus::Certified { radius } => Some(radius),
            CertificateStatus::Failed(_) => None,
        }
    }

    fn failed(reason: FailureReason, refined: Vec<C64>) -> Self {
        Self {
            status: CertificateStatus::Failed(reason),
            real: Reality::Unknown,
            distinct: false,
            same_as: None,
            refined,
            enclosure: Vec::new(),
        }
    }
}

/// The knobs of the certification.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CertifyOptions {
    /// How far (max-norm over real and imaginary parts, relative to `max(1, ‖x‖∞)` of the given
    /// point `x`) the box of uniqueness may reach from the given point. Default `1e-6`.
    pub tolerance: f64,
    /// The most floating-point Newton steps polishing a point before the test. Default 3.
    pub newton_steps: usize,
    /// Krawczyk iterations tightening the enclosure after the test passes. Default 2.
    pub tightening: usize,
}

impl Default for CertifyOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-6,
            newton_steps: 3,
            tightening: 2,
        }
    }
}

/// Multiples of the interval Newton step tried as radii.
const RADIUS_FACTORS: [f64; 5] = [2.0, 4.0, 16.0, 256.0, 4096.0];
/// Extra tightening iterations for overlapping enclosures.
const RETRY_TIGHTENING: usize = 8;

/// Certifies each point of `roots` as an approximate root of the square system `program`, and
/// proves which are distinct; `real_coefficients` says the system has real coefficients (as
/// [`crate::poly::System::is_real`]), which allows real roots to be proven real. The points are
/// certified in parallel. Default [`CertifyOptions`].
///
/// # Errors
/// [`CertifyError::NotSquare`] for a non-square system, [`CertifyError::RootLength`] for a
/// point with the wrong number of coordinates.
pub fn certify_roots(
    program: &Program,
    roots: &[Vec<C64>],
    real_coefficients: bool,
) -> Result<Vec<Certificate>, CertifyError> {
    certify_roots_with(
        program,
        roots,
        real_coefficients,
        &CertifyOptions::default(),
    )
}

/// [`certify_roots`] with the given options.
///
/// # Errors
/// As [`certify_roots`].
pub fn certify_roots_with(
    program: &Program,
    roots: &[Vec<C64>],
    real_coefficients: bool,
    options: &CertifyOptions,
) -> Result<Vec<Certificate>, CertifyError> {
    check_square(program)?;
    for (root, x) in roots.iter().enumerate() {
        check_length(program, root, x)?;
    }
    let mut certificates: Vec<Certificate> = roots
        .par_iter()
        .map(|x| Certifier::new(program, options).certify(x, real_coefficients))
        .collect();
    separate(program, &mut certificates);
    Ok(certificates)
}

/// Certifies one point as an approximate root of the square system `program` (see the module
/// documentation); [`Certificate::distinct`] stays `false`, since there is nothing to compare
/// with ([`separate`] compares certificates made one by one). Default [`CertifyOptions`].
///
/// # Errors
/// [`CertifyError::NotSquare`] for a non-square system, [`CertifyError::RootLength`] for a
/// point with the wrong number of coordinates.
pub fn certify_root(
    program: &Program,
    root: &[C64],
    real_coefficients: bool,
) -> Result<Certificate, CertifyError> {
    certify_root_with(program, root, real_coefficients, &CertifyOptions::default())
}

/// [`certify_root`] with the given options.
///
/// # Errors
/// As [`certify_root`].
pub fn certify_root_with(
    program: &Program,
    root: &[C64],
    real_coefficients: bool,
    options: &CertifyOptions,
) -> Result<Certificate, CertifyError> {
    check_square(program)?;
    check_length(program, 0, root)?;
    Ok(Certifier::new(program, options).certify(root, real_coefficients))
}

/// Proves which certified roots of a list are distinct and which are one root found twice:
/// sets [`Certificate::distinct`] and [`Certificate::same_as`] of every certificate (made by
/// [`certify_root`] on `program`, perhaps in parallel). Overlapping enclosures are tightened
/// first.
pub fn separate(program: &Program, certificates: &mut [Certificate]) {
    let n = certificates.len();
    let retry: Vec<usize> = overlapping(certificates);
    if !retry.is_empty() {
        let options = CertifyOptions::default();
        let mut certifier = Certifier::new(program, &options);
        for &i in &retry {
            certifier.tighten_certificate(&mut certificates[i]);
        }
    }
    let mut overlaps = vec![false; n];
    for i in overlapping(certificates) {
        overlaps[i] = true;
    }
    for i in 0..n {
        let certified = certificates[i].is_certified();
        let distinct = certified && !overlaps[i];
        let same_as = if certified && !distinct {
            (0..n).find(|&j| {
                j != i && certificates[j].is_certified() && {
                    same_root(&certificates[i], &certificates[j])
                }
            })
        } else {
            None
        };
        certificates[i].distinct = distinct;
        certificates[i].same_as = same_as;
    }
}

fn check_square(program: &Program) -> Result<(), CertifyError> {
    if program.len() == program.nvars() {
        Ok(())
    } else {
        Err(CertifyError::NotSquare {
            equations: program.len(),
            variables: program.nvars(),
        })
    }
}

fn check_length(program: &Program, root: usize, x: &[C64]) -> Result<(), CertifyError> {
    if x.len() == program.nvars() {
        Ok(())
    } else {
        Err(CertifyError::RootLength {
            root,
            expected: program.nvars(),
            found: x.len(),
        })
    }
}

/// The certified certificates whose enclosure meets another certified one's, in increasing
/// order. Comparing every pair would cost the square of the roots (65 536 roots: 2·10⁹
/// comparisons, many minutes), so the enclosures are swept along a generic real-linear form
/// `ℓ(z) = Σ Re(c_k z_k)` (`c_k` on the unit circle at the golden angle's multiples): two
/// enclosures that meet have ranges of `ℓ` that meet (the ranges are computed in outward-rounded
/// interval arithmetic, so they hold the true ones), and after sorting the ranges by their lower
/// ends only the pairs whose ranges meet are compared — a few per root in general position.
fn overlapping(certificates: &[Certificate]) -> Vec<usize> {
    const GOLDEN: f64 = 0.618_033_988_749_894_9;
    let range = |c: &Certificate| -> Interval {
        c.enclosure
            .iter()
            .enumerate()
            .fold(Interval::point(0.0), |acc, (k, z)| {
                let angle = std::f64::consts::TAU * ((k as f64 + 1.0) * GOLDEN).fract();
                let (sin, cos) = angle.sin_cos();
                acc + Interval::point(cos) * z.re - Interval::point(sin) * z.im
            })
    };
    let mut sorted: Vec<(Interval, usize)> = certificates
        .iter()
        .enumerate()
        .filter(|(_, c)| c.is_certified())
        .map(|(i, c)| (range(c), i))
        .collect();
    sorted.sort_by(|a, b| a.0.lo.total_cmp(&b.0.lo));
    let mut overlaps = vec![false; certificates.len()];
    for (k, (a, i)) in sorted.iter().enumerate() {
        for (b, j) in &sorted[k + 1..] {
            if b.lo > a.hi {
                break;
            }
            if !disjoint(&certificates[*i], &certificates[*j]) {
                overlaps[*i] = true;
                overlaps[*j] = true;
            }
        }
    }
    (0..certificates.len()).filter(|i| overlaps[*i]).collect()
}

/// Whether the enclosures of two certificates are disjoint (then the roots differ).
fn disjoint(a: &Certificate, b: &Certificate) -> bool {
    a.enclosure
        .iter()
        .zip(&b.enclosure)
        .any(|(p, q)| p.disjoint(*q))
}

/// Whether `a`'s root is proven to be `b`'s: `a`'s enclosure, shifted by `b`'s centre (in
/// outward-rounded arithmetic), lies in `b`'s exact box of uniqueness `[−r, r]`, where `b`'s root
/// is the only one.
fn same_root(a: &Certificate, b: &Certificate) -> bool {
    let Some(r) = b.radius() else {
        return false;
    };
    let ball = ComplexInterval::symmetric(r);
    a.enclosure
        .iter()
        .zip(&b.refined)
        .all(|(e, c)| (*e - ComplexInterval::point(*c)).subset_of(ball))
}

/// The max-norm over real and imaginary parts.
fn norm(x: &[C64]) -> f64 {
    x.iter().fold(0.0, |m, z| m.max(z.re.abs()).max(z.im.abs()))
}

fn distance(x: &[C64], y: &[C64]) -> f64 {
    x.iter().zip(y).fold(0.0, |m, (a, b)| {
        m.max((a.re - b.re).abs()).max((a.im - b.im).abs())
    })
}

/// The scalars the Krawczyk operator is evaluated over: real intervals (real boxes of real
/// systems) and complex rectangles.
trait BoxScalar: Scalar {
    fn from_point(z: C64) -> Self;
    fn ball(r: f64) -> Self;
    fn magnitude(self) -> f64;
    fn finite(self) -> bool;
    fn inside(self, outer: Self) -> bool;
    fn meet(self, other: Self) -> Option<Self>;
    fn join(self, other: Self) -> Self;
}

/// The two box scalars share their method names: one implementation, spelled once.
macro_rules! box_scalar {
    ($t:ty, $point:expr) => {
        impl BoxScalar for $t {
            fn from_point(z: C64) -> Self {
                $point(z)
            }
            fn ball(r: f64) -> Self {
                <$t>::symmetric(r)
            }
            fn magnitude(self) -> f64 {
                self.mag()
            }
            fn finite(self) -> bool {
                self.is_finite()
            }
            fn inside(self, outer: Self) -> bool {
                self.interior_of(outer)
            }
            fn meet(self, other: Self) -> Option<Self> {
                self.intersection(other)
            }
            fn join(self, other: Self) -> Self {
                self.hull(other)
            }
        }
    };
}

box_scalar!(Interval, |z: C64| Interval::point(z.re));
box_scalar!(ComplexInterval, ComplexInterval::point);

/// The Krawczyk operator of one centre and one `Y` over scalars `S`, with its scratch space.
struct Krawczyk<'a, S: BoxScalar> {
    program: &'a Program,
    ws: &'a mut Workspace<S>,
    centre: Vec<S>,
    /// `Y`, row-major, as point intervals.
    y: Vec<S>,
    /// `−Y·F(x̃)`.
    step: Vec<S>,
    values: Vec<S>,
    jacobian: Vec<S>,
    point: Vec<S>,
}

impl<'a, S: BoxScalar> Krawczyk<'a, S> {
    fn new(program: &'a Program, ws: &'a mut Workspace<S>, centre: &[C64], y: &[C64]) -> Self {
        let n = centre.len();
        let centre: Vec<S> = centre.iter().map(|z| S::from_point(*z)).collect();
        let y: Vec<S> = y.iter().map(|z| S::from_point(*z)).collect();
        let mut values = vec![S::zero(); n];
        program.evaluate(&centre, &mut values, ws);
        let step = (0..n)
            .map(|i| -(0..n).fold(S::zero(), |acc, j| acc + y[i * n + j] * values[j]))
            .collect();
        Self {
            program,
            ws,
            centre,
            y,
            step,
            values,
            jacobian: vec![S::zero(); n * n],
            point: vec![S::zero(); n],
        }
    }

    /// `max |−Y·F(x̃)|`, the size of the interval Newton step (`NaN` if unbounded).
    fn step_size(&self) -> f64 {
        if self.step.iter().all(|s| s.finite()) {
            self.step.iter().fold(0.0, |m, s| m.max(s.magnitude()))
        } else {
            f64::NAN
        }
    }

    /// `K(D) = −Y·F(x̃) + (I − Y·J(x̃ + D))·D`; every root in `x̃ + D` is in `x̃ + K(D)` when
    /// `0 ∈ D`.
    fn apply(&mut self, d: &[S]) -> Vec<S> {
        let n = d.len();
        for ((p, c), di) in self.point.iter_mut().zip(&self.centre).zip(d) {
            *p = *c + *di;
        }
        self.program.evaluate_with_jacobian(
            &self.point,
            &mut self.values,
            &mut self.jacobian,
            self.ws,
        );
        (0..n)
            .map(|i| {
                (0..n).fold(self.step[i], |acc, k| {
                    let yj = (0..n).fold(S::zero(), |s, j| {
                        s + self.y[i * n + j] * self.jacobian[j * n + k]
                    });
                    let m = if i == k { S::one() - yj } else { -yj };
                    acc + m * d[k]
                })
            })
            .collect()
    }

    /// The first radius of `radii` whose box passes the test, with the tightened offsets of the
    /// root (`K(D) ∩ D` after `tightening` iterations).
    fn prove(&mut self, radii: &[f64], tightening: usize) -> Option<(f64, Vec<S>)> {
        let n = self.centre.len();
        for &r in radii {
            let d = vec![S::ball(r); n];
            let k = self.apply(&d);
            if k.iter()
                .zip(&d)
                .all(|(ki, di)| ki.finite() && ki.inside(*di))
            {
                return Some((r, self.tighten(k, tightening)));
            }
        }
        None
    }

    /// Krawczyk iteration from offsets `enclosure` known to contain the root's offset: each
    /// step evaluates `K` on `D = hull(enclosure, 0)` (a box holding the root and the centre)
    /// and keeps `K(D) ∩ D`, which still contains the root's offset.
    fn tighten(&mut self, mut enclosure: Vec<S>, iterations: usize) -> Vec<S> {
        for _ in 0..iterations {
            let d: Vec<S> = enclosure.iter().map(|e| e.join(S::zero())).collect();
            let k = self.apply(&d);
            let next: Option<Vec<S>> = k.iter().zip(&d).map(|(ki, di)| ki.meet(*di)).collect();
            match next {
                Some(next) if next.iter().all(|x| x.finite()) => enclosure = next,
                _ => break,
            }
        }
        enclosure
    }
}

/// A point with the floating-point inverse of the Jacobian there.
type Linearised = (Vec<C64>, DMatrix<C64>);

/// The per-call state of a certification: the workspaces of the three scalar types.
struct Certifier<'a> {
    program: &'a Program,
    options: &'a CertifyOptions,
    n: usize,
    complex: Workspace<C64>,
    boxes: Workspace<ComplexInterval>,
    real: Option<Workspace<Interval>>,
    values: Vec<C64>,
    jacobian: Vec<C64>,
}

impl<'a> Certifier<'a> {
    fn new(program: &'a Program, options: &'a CertifyOptions) -> Self {
        let n = program.nvars();
        Self {
            program,
            options,
            n,
            complex: program.workspace(),
            boxes: program.workspace(),
            real: None,
            values: vec![C64::new(0.0, 0.0); n],
            jacobian: vec![C64::new(0.0, 0.0); n * n],
        }
    }

    /// `F(x)` and `J(x)⁻¹` in floating point.
    fn linearise(&mut self, x: &[C64]) -> Result<(Vec<C64>, DMatrix<C64>), FailureReason> {
        self.program.evaluate_with_jacobian(
            x,
            &mut self.values,
            &mut self.jacobian,
            &mut self.complex,
        );
        if !self
            .values
            .iter()
            .chain(&self.jacobian)
            .all(|z| z.re.is_finite() && z.im.is_finite())
        {
            return Err(FailureReason::NonFinite);
        }
        let j = DMatrix::from_row_slice(self.n, self.n, &self.jacobian);
        let inverse = j.lu().try_inverse().ok_or(FailureReason::Singular)?;
        if inverse.iter().all(|z| z.re.is_finite() && z.im.is_finite()) {
            Ok((self.values.clone(), inverse))
        } else {
            Err(FailureReason::Singular)
        }
    }

    /// Newton's method from `x` (kept real if `real`), at most `newton_steps` steps, stopping
    /// when a step is no smaller than the one before; also returns `J⁻¹` at the last iterate.
    fn polish(&mut self, x: &[C64], real: bool) -> Result<Linearised, (FailureReason, Vec<C64>)> {
        let mut x = x.to_vec();
        if real {
            for z in &mut x {
                z.im = 0.0;
            }
        }
        let mut last = f64::INFINITY;
        let mut steps = 0;
        loop {
            let (f, y) = self.linearise(&x).map_err(|e| (e, x.clone()))?;
            if steps == self.options.newton_steps {
                return Ok((x, y));
            }
            let mut dx: Vec<C64> = (0..self.n)
                .map(|i| -(0..self.n).map(|j| y[(i, j)] * f[j]).sum::<C64>())
                .collect();
            if real {
                for z in &mut dx {
                    z.im = 0.0;
                }
            }
            let size = norm(&dx);
            if !size.is_finite() || size >= last || size == 0.0 {
                return Ok((x, y));
            }
            last = size;
            for (xi, di) in x.iter_mut().zip(&dx) {
                *xi += di;
            }
            steps += 1;
        }
    }

    fn certify(&mut self, x0: &[C64], real_coefficients: bool) -> Certificate {
        if !x0.iter().all(|z| z.re.is_finite() && z.im.is_finite()) {
            return Certificate::failed(FailureReason::NonFinite, x0.to_vec());
        }
        let reach = self.options.tolerance * norm(x0).max(1.0);
        if real_coefficients
            && x0.iter().all(|z| z.im.abs() <= reach)
            && let Some(certificate) = self.certify_real(x0, reach)
        {
            return certificate;
        }
        let (x, y) = match self.polish(x0, false) {
            Ok(p) => p,
            Err((reason, x)) => return Certificate::failed(reason, x),
        };
        let moved = distance(&x, x0);
        if moved > reach {
            return Certificate::failed(FailureReason::TooFar { distance: moved }, x);
        }
        let radii_cap = reach - moved;
        match self.prove_complex(&x, &y, None, radii_cap) {
            Ok((radius, enclosure)) => {
                let non_real = enclosure.iter().any(|e| !e.im.contains_zero());
                Certificate {
                    status: CertificateStatus::Certified { radius },
                    real: if non_real {
                        Reality::CertifiedNonReal
                    } else {
                        Reality::Unknown
                    },
                    distinct: false,
                    same_as: None,
                    refined: x,
                    enclosure,
                }
            }
            Err(FailureReason::TooFar { distance }) => Certificate::failed(
                FailureReason::TooFar {
                    distance: distance + moved,
                },
                x,
            ),
            Err(reason) => Certificate::failed(reason, x),
        }
    }

    /// The complex test at `x` with `Y`, radii from `min_radius` (or the interval Newton step)
    /// up to `cap`; the radius and the enclosure of the root.
    fn prove_complex(
        &mut self,
        x: &[C64],
        y: &DMatrix<C64>,
        min_radius: Option<f64>,
        cap: f64,
    ) -> Result<(f64, Vec<ComplexInterval>), FailureReason> {
        let y_rows: Vec<C64> = y.transpose().iter().copied().collect();
        let mut k = Krawczyk::new(self.program, &mut self.boxes, x, &y_rows);
        let radii = radii(k.step_size(), min_radius, cap)?;
        let (radius, offsets) = k
            .prove(&radii, self.options.tightening)
            .ok_or(FailureReason::NotContracting)?;
        let enclosure = x
            .iter()
            .zip(&offsets)
            .map(|(c, d)| ComplexInterval::point(*c) + *d)
            .collect();
        Ok((radius, enclosure))
    }

    /// The real test: a real root proven in a real box, then the complex box of uniqueness
    /// around the same real centre and containing that real box. `None` if either fails.
    fn certify_real(&mut self, x0: &[C64], reach: f64) -> Option<Certificate> {
        let (x, y) = self.polish(x0, true).ok()?;
        let moved = distance(&x, x0);
        if moved > reach {
            return None;
        }
        let y_rows: Vec<C64> = y.transpose().iter().copied().collect();
        let ws = self
            .real
            .get_or_insert_with(|| self.program.workspace::<Interval>());
        let mut k = Krawczyk::new(self.program, ws, &x, &y_rows);
        let radii = radii(k.step_size(), None, reach - moved).ok()?;
        let (real_radius, _) = k.prove(&radii, 0)?;
        let (radius, enclosure) = self
            .prove_complex(&x, &y, Some(real_radius), reach - moved)
            .ok()?;
        Some(Certificate {
            status: CertificateStatus::Certified { radius },
            real: Reality::CertifiedReal,
            distinct: false,
            same_as: None,
            refined: x,
            enclosure,
        })
    }

    /// Further Krawczyk iterations on a certificate's enclosure (same centre, fresh `Y`).
    fn tighten_certificate(&mut self, certificate: &mut Certificate) {
        let Ok((_, y)) = self.linearise(&certificate.refined) else {
            return;
        };
        let y_rows: Vec<C64> = y.transpose().iter().copied().collect();
        let centre = certificate.refined.clone();
        let mut k = Krawczyk::new(self.program, &mut self.boxes, &centre, &y_rows);
        let offsets: Vec<ComplexInterval> = certificate
            .enclosure
            .iter()
            .zip(&centre)
            .map(|(e, c)| *e - ComplexInterval::point(*c))
            .collect();
        let offsets = k.tighten(offsets, RETRY_TIGHTENING);
        for ((e, c), d) in certificate.enclosure.iter_mut().zip(&centre).zip(&offsets) {
            if let Some(m) = e.intersection(ComplexInterval::point(*c) + *d) {
                *e = m;
            }
        }
    }
}

/// The radii to try: multiples of the interval Newton step `a` (from `min_radius` on, if
/// given), none beyond `cap`.
fn radii(a: f64, min_radius: Option<f64>, cap: f64) -> Result<Vec<f64>, FailureReason> {
    if !a.is_finite() {
        return Err(FailureReason::NonFinite);
    }
    let base = a.max(f64::MIN_POSITIVE);
    let mut radii: Vec<f64> = match min_radius {
        Some(r) => RADIUS_FACTORS
            .iter()
            .map(|m| r * m / RADIUS_FACTORS[0])
            .collect(),
        None => RADIUS_FACTORS.iter().map(|m| base * m).collect(),
    };
    let smallest = radii[0];
    radii.retain(|r| *r <= cap);
    if radii.is_empty() {
        Err(FailureReason::TooFar { distance: smallest })
    } else {
        Ok(radii)
    }
}
