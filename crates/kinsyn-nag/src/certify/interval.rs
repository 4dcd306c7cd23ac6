//! Interval arithmetic with floating-point bounds: closed real intervals `[lo, hi]` and complex
//! rectangles `[re] + i·[im]`, each operation returning a set that contains every exact result
//! of the operation on members of its operands. Both implement [`Scalar`], so a
//! [`crate::poly::Program`] evaluates a system and its Jacobian over boxes: the value sets of
//! the certificates.
//!
//! # Floating-point safeguards
//!
//! * **Outward rounding without a rounding mode.** Rust cannot switch the FPU to directed
//!   rounding, so every bound of a sum, difference or product is computed with the ordinary
//!   round-to-nearest operation and then moved one floating-point number outward
//!   (`f64::next_down` for a lower bound, `f64::next_up` for an upper one). A correctly
//!   rounded result `r` of an exact value `s` is the float nearest `s`, so `s` lies between the
//!   floats on either side of `r`: `next_down(r) ≤ s ≤ next_up(r)`. This holds for subnormal
//!   results, for underflow to zero and for overflow to infinity (`next_down(+∞)` is the largest
//!   finite float, still below an `s` that rounded to `+∞`). Negation is exact.
//! * **Coefficients.** [`Scalar::coefficient`] widens each part of a coefficient `c` to
//!   `[next_down(c), next_up(c)]`. The polynomials' coefficients are binary64 numbers, and the
//!   Jacobian's are `k·c` computed in binary64 by the polynomial layer (`k` an exponent), within
//!   half an ulp of the exact `k·c`: both are enclosed, so a certificate is a statement about the
//!   polynomials exactly as stored. The values' enclosure also holds every decimal within half an
//!   ulp of a stored coefficient (such as a `0.1` the user wrote).
//! * **NaN and infinities.** An operation whose bound would be NaN (`∞ − ∞`, `0 · ∞`) returns
//!   the unbounded interval `[−∞, +∞]`, which contains everything; an unbounded or non-finite
//!   interval is never a subset of the interior of anything and never excludes zero, so nothing
//!   is certified by accident. A NaN coefficient becomes `[−∞, +∞]` too.
//! * **Real intervals and complex coefficients.** [`Interval`] is a [`Scalar`] for real systems;
//!   a coefficient with a non-zero imaginary part has no real enclosure and becomes
//!   `[−∞, +∞]`, so a real evaluation of a complex system proves nothing rather than something
//!   false.

use crate::poly::{C64, Scalar};
use std::ops::{Add, Mul, Neg, Sub};

/// A closed real interval `{x : lo ≤ x ≤ hi}` with binary64 bounds; `[−∞, +∞]` stands for
/// "any real number" (the result of an operation that lost all information).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower bound.
    pub lo: f64,
    /// The upper bound.
    pub hi: f64,
}

/// A complex rectangle `{a + i·b : a ∈ re, b ∈ im}`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComplexInterval {
    /// The real parts.
    pub re: Interval,
    /// The imaginary parts.
    pub im: Interval,
}

impl Interval {
    /// The set of all real numbers.
    pub const ENTIRE: Self = Self {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// The interval `[lo, hi]`; `[−∞, +∞]` if a bound is NaN or `lo > hi` (no information
    /// rather than a wrong set).
    #[must_use]
    pub fn new(lo: f64, hi: f64) -> Self {
        if lo <= hi {
            Self { lo, hi }
        } else {
            Self::ENTIRE
        }
    }

    /// The single number `x` (a degenerate interval; `[−∞, +∞]` for NaN).
    #[must_use]
    pub fn point(x: f64) -> Self {
        Self::new(x, x)
    }

    /// The symmetric interval `[−r, r]`.
    #[must_use]
    pub fn symmetric(r: f64) -> Self {
        Self::new(-r, r)
    }

    /// The floats either side of `x`: an enclosure of every real within half an ulp of `x`.
    #[must_use]
    pub fn around(x: f64) -> Self {
        Self::new(x.next_down(), x.next_up())
    }

    /// Outward-rounded bounds from round-to-nearest bounds: the safeguard of every operation.
    fn outward(lo: f64, hi: f64) -> Self {
        if lo.is_nan() || hi.is_nan() {
            Self::ENTIRE
        } else {
            Self::new(lo.next_down(), hi.next_up())
        }
    }

    /// Whether both bounds are finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// The magnitude `max |x|` over the interval.
    #[must_use]
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// The width `hi − lo`, rounded up (an upper bound of the exact width).
    #[must_use]
    pub fn width(self) -> f64 {
        (self.hi - self.lo).next_up()
    }

    /// The midpoint, rounded to nearest (a float inside the interval when it is finite).
    #[must_use]
    pub fn midpoint(self) -> f64 {
        let m = 0.5 * self.lo + 0.5 * self.hi;
        m.clamp(self.lo, self.hi)
    }

    /// Whether `x` is in the interval.
    #[must_use]
    pub fn contains(self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Whether 0 is in the interval.
    #[must_use]
    pub fn contains_zero(self) -> bool {
        self.contains(0.0)
    }

    /// Whether the interval is a subset of `other`.
    #[must_use]
    pub fn subset_of(self, other: Self) -> bool {
        other.lo <= self.lo && self.hi <= other.hi
    }

    /// Whether the interval is a subset of the interior `(other.lo, other.hi)` of `other`.
    #[must_use]
    pub fn interior_of(self, other: Self) -> bool {
        other.lo < self.lo && self.hi < other.hi
    }

    /// Whether the two intervals have no point in common.
    #[must_use]
    pub fn disjoint(self, other: Self) -> bool {
        self.hi < other.lo || other.hi < self.lo
    }

    /// The smallest interval holding both.
    #[must_use]
    pub fn hull(self, other: Self) -> Self {
        Self::new(self.lo.min(other.lo), self.hi.max(other.hi))
    }

    /// The common part, `None` if the intervals are disjoint.
    #[must_use]
    pub fn intersection(self, other: Self) -> Option<Self> {
        if self.disjoint(other) {
            None
        } else {
            Some(Self::new(self.lo.max(other.lo), self.hi.min(other.hi)))
        }
    }
}

impl Add for Interval {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Self::outward(self.lo + rhs.lo, self.hi + rhs.hi)
    }
}

impl Sub for Interval {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Self::outward(self.lo - rhs.hi, self.hi - rhs.lo)
    }
}

impl Neg for Interval {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Self;
    fn mul(self, rhs: Self) -> Self {
        let p = [
            self.lo * rhs.lo,
            self.lo * rhs.hi,
            self.hi * rhs.lo,
            self.hi * rhs.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return Self::ENTIRE;
        }
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Self::outward(lo, hi)
    }
}

impl Scalar for Interval {
    fn zero() -> Self {
        Self::point(0.0)
    }
    fn one() -> Self {
        Self::point(1.0)
    }
    /// The enclosure `[next_down(c), next_up(c)]` of a real coefficient; `[−∞, +∞]` for a
    /// coefficient with a non-zero (or NaN) imaginary part, which has no real enclosure.
    fn coefficient(c: C64) -> Self {
        if c.im == 0.0 {
            Self::around(c.re)
        } else {
            Self::ENTIRE
        }
    }
}

impl ComplexInterval {
    /// The rectangle with the given real and imaginary parts.
    #[must_use]
    pub fn new(re: Interval, im: Interval) -> Self {
        Self { re, im }
    }

    /// The single complex number `z`.
    #[must_use]
    pub fn point(z: C64) -> Self {
        Self::new(Interval::point(z.re), Interval::point(z.im))
    }

    /// The square `[−r, r] + i·[−r, r]`.
    #[must_use]
    pub fn symmetric(r: f64) -> Self {
        Self::new(Interval::symmetric(r), Interval::symmetric(r))
    }

    /// Whether all four bounds are finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }

    /// The largest magnitude of a real or an imaginary part (the max-norm of ℝ²).
    #[must_use]
    pub fn mag(self) -> f64 {
        self.re.mag().max(self.im.mag())
    }

    /// The larger of the two widths.
    #[must_use]
    pub fn width(self) -> f64 {
        self.re.width().max(self.im.width())
    }

    /// The centre, rounded to nearest.
    #[must_use]
    pub fn midpoint(self) -> C64 {
        C64::new(self.re.midpoint(), self.im.midpoint())
    }

    /// Whether `z` is in the rectangle.
    #[must_use]
    pub fn contains(self, z: C64) -> bool {
        self.re.contains(z.re) && self.im.contains(z.im)
    }

    /// Whether 0 is in the rectangle.
    #[must_use]
    pub fn contains_zero(self) -> bool {
        self.re.contains_zero() && self.im.contains_zero()
    }

    /// Whether the rectangle is a subset of `other`.
    #[must_use]
    pub fn subset_of(self, other: Self) -> bool {
        self.re.subset_of(other.re) && self.im.subset_of(other.im)
    }

    /// Whether the rectangle is a subset of the interior of `other`.
    #[must_use]
    pub fn interior_of(self, other: Self) -> bool {
        self.re.interior_of(other.re) && self.im.interior_of(other.im)
    }

    /// Whether the rectangles have no point in common.
    #[must_use]
    pub fn disjoint(self, other: Self) -> bool {
        self.re.disjoint(other.re) || self.im.disjoint(other.im)
    }

    /// The smallest rectangle holding both.
    #[must_use]
    pub fn hull(self, other: Self) -> Self {
        Self::new(self.re.hull(other.re), self.im.hull(other.im))
    }

    /// The common part, `None` if the rectangles are disjoint.
    #[must_use]
    pub fn intersection(self, other: Self) -> Option<Self> {
        Some(Self::new(
            self.re.intersection(other.re)?,
            self.im.intersection(other.im)?,
        ))
    }
}

impl Add for ComplexInterval {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Self::new(self.re + rhs.re, self.im + rhs.im)
    }
}

impl Sub for ComplexInterval {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Self::new(self.re - rhs.re, self.im - rhs.im)
    }
}

impl Neg for ComplexInterval {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.re, -self.im)
    }
}

impl Mul for ComplexInterval {
    type Output = Self;
    /// The rectangle `[a.re·b.re − a.im·b.im] + i·[a.re·b.im + a.im·b.re]`, which contains
    /// every product of a member of `a` and a member of `b`.
    fn mul(self, rhs: Self) -> Self {
        Self::new(
            self.re * rhs.re - self.im * rhs.im,
            self.re * rhs.im + self.im * rhs.re,
        )
    }
}

impl Scalar for ComplexInterval {
    fn zero() -> Self {
        Self::point(C64::new(0.0, 0.0))
    }
    fn one() -> Self {
        Self::point(C64::new(1.0, 0.0))
    }
    /// `[next_down(c.re), next_up(c.re)] + i·[next_down(c.im), next_up(c.im)]`.
    fn coefficient(c: C64) -> Self {
        Self::new(Interval::around(c.re), Interval::around(c.im))
    }
}
