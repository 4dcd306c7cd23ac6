//! The path tracker: follows a solution `z(t)` of `H(z, t) = 0` as the continuation parameter
//! `t` moves along a path in ℂ, by a fourth-order Runge–Kutta predictor on the Davidenko
//! equation `H_z ż = −H_t ṫ` and a Newton corrector, with step-size control; and the Cauchy
//! endgame, which finds the limit `z(0)` of a path whose endpoint may be singular by tracking
//! around circles `t = r e^{iθ}` and averaging (the Cauchy integral formula by the trapezoid
//! rule; Morgan, Sommese & Wampler, *Computing singular solutions to nonlinear analytic systems*,
//! Numer. Math. 58, 1991).

use super::C64;
use nalgebra::{DMatrix, DVector};

/// A homotopy `H(z, t)`: square, `dim` equations in `dim` unknowns, analytic in `z` and `t`.
pub(crate) trait Homotopy: Sync {
    /// Per-thread scratch space.
    type Workspace;
    /// The number of unknowns (and of equations).
    fn dim(&self) -> usize;
    /// A fresh workspace.
    fn workspace(&self) -> Self::Workspace;
    /// `H(z, t)` into `h`, `∂H/∂z` into `hz`, `∂H/∂t` into `ht`.
    fn evaluate(
        &self,
        z: &DVector<C64>,
        t: C64,
        ws: &mut Self::Workspace,
        h: &mut DVector<C64>,
        hz: &mut DMatrix<C64>,
        ht: &mut DVector<C64>,
    );
    /// Whether `z` is, beyond doubt, a point at infinity (the endgame stops there: the limit
    /// of such a path is not a solution, and its exact position does not matter).
    fn at_infinity(&self, _z: &DVector<C64>) -> bool {
        false
    }
    /// How close `z` is to infinity (the smallest homogenising coordinate over its group's
    /// size), for homotopies in projective coordinates; `None` for affine ones.
    fn infinity_measure(&self, _z: &DVector<C64>) -> Option<f64> {
        None
    }
    /// The inverse condition of `z` as a solution of `H(·, 0) = 0`, the target system: the
    /// scale-free measure of [`super::SINGULAR_TOLERANCE`] that decides regular or singular.
    fn inverse_condition(&self, z: &DVector<C64>, ws: &mut Self::Workspace) -> f64;
    /// For homotopies in projective coordinates: moves `z` to the chart in which it is best
    /// represented (each group's coordinates scaled to largest modulus 1, on the patch normal
    /// to them), the same projective point. Called between the steps of the tracker, so that
    /// the coordinates stay of unit size along the whole path (a fixed patch puts some points
    /// of a high-degree system at coordinates whose powers overflow). Affine homotopies keep
    /// their coordinates (the default).
    fn rechart(&self, _z: &mut DVector<C64>, _ws: &mut Self::Workspace) {}
}

/// The settings of one path: tolerances are relative to `1 + |z|`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackerSettings {
    /// Newton tolerance of the corrector while tracking.
    pub corrector_tolerance: f64,
    /// The most Newton iterations per step.
    pub max_corrector_iterations: usize,
    /// The largest step, as a fraction of the path's length in `t`.
    pub max_step: f64,
    /// The smallest step before the path is given up.
    pub min_step: f64,
    /// The most steps before the path is given up.
    pub max_steps: usize,
    /// Where the endgame starts (`t = endgame_start`).
    pub endgame_start: f64,
    /// Agreement of successive Cauchy estimates that ends the endgame.
    pub endgame_tolerance: f64,
    /// The largest winding number tried around a singular endpoint.
    pub max_winding: usize,
}

impl Default for TrackerSettings {
    fn default() -> Self {
        Self {
            corrector_tolerance: 1e-9,
            max_corrector_iterations: 3,
            max_step: 0.1,
            min_step: 1e-12,
            max_steps: 20_000,
            endgame_start: 0.1,
            endgame_tolerance: 1e-9,
            max_winding: 16,
        }
    }
}

impl TrackerSettings {
    /// Stricter steps: smaller largest step and a tighter corrector, for paths re-tracked after
    /// a suspected path jump.
    #[must_use]
    pub fn stricter(&self) -> Self {
        Self {
            corrector_tolerance: self.corrector_tolerance * 1e-2,
            max_corrector_iterations: 2,
            max_step: self.max_step / 4.0,
            max_steps: self.max_steps * 4,
            ..*self
        }
    }
}

/// Why a path was given up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum PathFailure {
    /// The step size fell below its minimum: a near-singular point on the path, or a path that
    /// cannot be followed with these settings.
    #[error("step size below its minimum")]
    StepTooSmall,
    /// More steps than allowed.
    #[error("too many steps")]
    TooManySteps,
    /// The Cauchy endgame found no loop closing within the largest winding number, or its
    /// estimates did not settle.
    #[error("the endgame did not converge")]
    Endgame,
    /// A value became NaN or infinite.
    #[error("non-finite values")]
    NotFinite,
}

/// A point whose homogenising coordinates fall below this fraction of their group (an affine
/// point beyond 10⁵ in the patch's scale) while the valuations say the path diverges is
/// declared at infinity.
const FINITE_THRESHOLD: f64 = 1e-5;

/// The smallest `t` the endgame's descent reaches before deciding by the valuations alone.
const MIN_ENDGAME_T: f64 = 1e-12;

/// The most steps of one quarter of the endgame's descent (`t` to `t/4`) before the path is
/// decided by its valuations so far.
const DESCENT_BUDGET: usize = 60;

/// Above this `t` a quarter of the descent may take [`SHALLOW_DESCENT_BUDGET`] steps: a path
/// that is hard to follow there (near a singularity of the homotopy for small `t`) is far from
/// decided, and the Cauchy loops at so large a radius are no way out.
const DEEP_DESCENT: f64 = 1e-4;

/// The most steps of one quarter of the descent above [`DEEP_DESCENT`].
const SHALLOW_DESCENT_BUDGET: usize = 1000;

/// The limit of a path at `t = 0` found by the endgame.
#[derive(Debug, Clone)]
pub(crate) struct Endpoint {
    /// The estimate of `z(0)`.
    pub z: DVector<C64>,
    /// The winding number `c`: the path is a Puiseux series in `t^{1/c}`; 1 for a regular
    /// endpoint.
    pub winding: usize,
    /// Whether successive estimates agreed to the endgame tolerance.
    pub converged: bool,
    /// Whether the path diverges: a homogenising coordinate vanishes like a positive power of
    /// `t` (its valuation), so the endpoint is at infinity.
    pub diverges: bool,
}

/// The scratch of one path: the workspace of the homotopy and the buffers of the steps.
pub(crate) struct Tracker<'a, H: Homotopy> {
    homotopy: &'a H,
    settings: TrackerSettings,
    ws: H::Workspace,
    h: DVector<C64>,
    hz: DMatrix<C64>,
    ht: DVector<C64>,
    /// Steps taken (accepted and rejected).
    pub steps: usize,
    /// Whether the chart follows the point ([`Homotopy::rechart`]); off in the Cauchy
    /// endgame, whose averages and comparisons need one fixed chart.
    recharting: bool,
}

/// A segment of the continuation path: `t(s)` for `s ∈ [0, 1]`.
#[derive(Debug, Clone, Copy)]
enum Segment {
    /// `t = a + s (b − a)`.
    Line(C64, C64),
    /// `t = r e^{i (θ0 + s Δθ)}`.
    Arc { r: f64, theta0: f64, dtheta: f64 },
}

impl Segment {
    fn t(&self, s: f64) -> C64 {
        match *self {
            Self::Line(a, b) => a + (b - a) * s,
            Self::Arc { r, theta0, dtheta } => C64::from_polar(r, theta0 + s * dtheta),
        }
    }
    fn dt(&self, s: f64) -> C64 {
        match *self {
            Self::Line(a, b) => b - a,
            Self::Arc { r, theta0, dtheta } => {
                C64::new(0.0, dtheta) * C64::from_polar(r, theta0 + s * dtheta)
            }
        }
    }
}

fn scale(z: &DVector<C64>) -> f64 {
    1.0 + z.norm()
}

impl<'a, H: Homotopy> Tracker<'a, H> {
    pub(crate) fn new(homotopy: &'a H, settings: TrackerSettings) -> Self {
        let n = homotopy.dim();
        Self {
            homotopy,
            settings,
            ws: homotopy.workspace(),
            h: DVector::zeros(n),
            hz: DMatrix::zeros(n, n),
            ht: DVector::zeros(n),
            steps: 0,
            recharting: true,
        }
    }

    fn eval(&mut self, z: &DVector<C64>, t: C64) {
        self.homotopy
            .evaluate(z, t, &mut self.ws, &mut self.h, &mut self.hz, &mut self.ht);
    }

    /// The tangent `dz/ds` at `(z, s)` on a segment.
    fn tangent(&mut self, z: &DVector<C64>, seg: Segment, s: f64) -> Option<DVector<C64>> {
        self.eval(z, seg.t(s));
        let rhs = -&self.ht * seg.dt(s);
        self.hz.clone().lu().solve(&rhs)
    }

    /// Newton's method at fixed `t`; `Some(iterations)` when the last update is below the
    /// tolerance and the updates contract.
    fn correct(
        &mut self,
        z: &mut DVector<C64>,
        t: C64,
        tolerance: f64,
        iterations: usize,
    ) -> Option<usize> {
        let mut previous = f64::INFINITY;
        for k in 0..iterations {
            self.eval(z, t);
            let dz = self.hz.clone().lu().solve(&(-&self.h))?;
            let norm = dz.norm();
            if !norm.is_finite() {
                return None;
            }
            *z += &dz;
            if norm <= tolerance * scale(z) {
                return Some(k + 1);
            }
            if k > 0 && norm > 0.5 * previous {
                return None;
            }
            previous = norm;
        }
        None
    }

    /// Follows `z` along the segment from `s = 0` to `s = 1`.
    fn follow(
        &mut self,
        z: &mut DVector<C64>,
        seg: Segment,
        first_step: f64,
    ) -> Result<(), PathFailure> {
        self.follow_within(
            z,
            seg,
            first_step,
            self.settings.max_step,
            self.settings.max_steps,
        )
    }

    /// Whether `z` is a well-conditioned solution of the target: its inverse condition
    /// ([`Homotopy::inverse_condition`]) above the singular tolerance.
    fn well_conditioned(&mut self, z: &DVector<C64>) -> bool {
        self.inverse_condition(z) > super::SINGULAR_TOLERANCE
    }

    /// The inverse condition of `z` as a solution of the target ([`Homotopy::inverse_condition`]).
    pub(crate) fn inverse_condition(&mut self, z: &DVector<C64>) -> f64 {
        self.homotopy.inverse_condition(z, &mut self.ws)
    }

    /// [`Homotopy::rechart`] on straight segments while recharting is on.
    fn rechart(&mut self, z: &mut DVector<C64>, seg: Segment) {
        if self.recharting && matches!(seg, Segment::Line(..)) {
            self.homotopy.rechart(z, &mut self.ws);
        }
    }

    /// [`Self::follow`] with a largest step (a fraction of the segment) and a budget of steps.
    fn follow_within(
        &mut self,
        z: &mut DVector<C64>,
        seg: Segment,
        first_step: f64,
        max_step: f64,
        budget: usize,
    ) -> Result<(), PathFailure> {
        let mut s = 0.0;
        let mut ds = first_step.min(max_step);
        let mut successes = 0;
        let limit = (self.steps + budget).min(self.settings.max_steps);
        self.rechart(z, seg);
        while s < 1.0 {
            if self.steps >= limit {
                return Err(PathFailure::TooManySteps);
            }
            self.steps += 1;
            let step = ds.min(1.0 - s);
            let predicted = self.runge_kutta(z, seg, s, step);
            let accepted = predicted.and_then(|mut y| {
                // The predictor must land close: a large first correction is a warning of a
                // jump to another path.
                let t = seg.t(s + step);
                self.correct(
                    &mut y,
                    t,
                    self.settings.corrector_tolerance,
                    self.settings.max_corrector_iterations,
                )
                .map(|_| y)
            });
            match accepted {
                Some(y) if y.iter().all(|c| c.re.is_finite() && c.im.is_finite()) => {
                    *z = y;
                    self.rechart(z, seg);
                    s += step;
                    successes += 1;
                    if successes >= 3 {
                        ds = (ds * 2.0).min(max_step);
                        successes = 0;
                    }
                }
                _ => {
                    ds *= 0.5;
                    successes = 0;
                    if ds < self.settings.min_step {
                        return Err(PathFailure::StepTooSmall);
                    }
                }
            }
        }
        Ok(())
    }

    fn runge_kutta(
        &mut self,
        z: &DVector<C64>,
        seg: Segment,
        s: f64,
        h: f64,
    ) -> Option<DVector<C64>> {
        let k1 = self.tangent(z, seg, s)?;
        let k2 = self.tangent(&(z + &k1 * C64::from(h / 2.0)), seg, s + h / 2.0)?;
        let k3 = self.tangent(&(z + &k2 * C64::from(h / 2.0)), seg, s + h / 2.0)?;
        let k4 = self.tangent(&(z + &k3 * C64::from(h)), seg, s + h)?;
        Some(z + (k1 + k2 * C64::from(2.0) + k3 * C64::from(2.0) + k4) * C64::from(h / 6.0))
    }

    /// Follows `z` from `t = a` to `t = b` along the straight segment.
    pub(crate) fn track(
        &mut self,
        z: &mut DVector<C64>,
        a: C64,
        b: C64,
    ) -> Result<(), PathFailure> {
        self.follow(z, Segment::Line(a, b), 0.05)
    }

    /// From `t = 1` to the limit at `t = 0`: tracking to the endgame's start, then the Cauchy
    /// endgame.
    pub(crate) fn track_to_end(&mut self, z: &mut DVector<C64>) -> Result<Endpoint, PathFailure> {
        let te = self.settings.endgame_start;
        self.follow(z, Segment::Line(C64::from(1.0), C64::from(te)), 0.05)?;
        if let Some(end) = self.finish_regular(z, te) {
            return Ok(end);
        }
        self.endgame(z, te)
    }

    /// A regular endpoint from `z` at `t`: tracking on to `t = 0` in a few steps, and Newton
    /// converging at `t = 0` on a well-conditioned Jacobian; `None` (and `z` unchanged)
    /// otherwise.
    fn finish_regular(&mut self, z: &DVector<C64>, t: f64) -> Option<Endpoint> {
        let mut w = z.clone();
        let reached = self.follow_within(
            &mut w,
            Segment::Line(C64::from(t), C64::from(0.0)),
            0.25,
            0.25,
            40,
        );
        (reached.is_ok()
            && self.correct(&mut w, C64::from(0.0), 1e-13, 4).is_some()
            && self.well_conditioned(&w))
        .then_some(Endpoint {
            z: w,
            winding: 1,
            converged: true,
            diverges: false,
        })
    }

    /// The endgame from `z` at `t = r` for a path that is not plainly regular. Along
    /// `t = r/4, r/16, …` the valuation `v = d log m / d log t` of the homogenising coordinates
    /// (`m`, [`Homotopy::infinity_measure`]) tells where the path goes: stable and positive with
    /// `m` below [`FINITE_THRESHOLD`] (the point already beyond `1/FINITE_THRESHOLD` in the
    /// patch's scale), or stable and positive all the way down to [`MIN_ENDGAME_T`], is a
    /// diverging path (Bertini declares infinity by such a norm threshold); stable and zero is a
    /// finite limit, regular (tracked on to 0) or singular (the Cauchy loops). A path can look
    /// diverging for decades of `t` and still turn back to a finite root with large
    /// coordinates, hence both conditions.
    fn endgame(&mut self, z: &mut DVector<C64>, mut r: f64) -> Result<Endpoint, PathFailure> {
        if let Some(mut m) = self.homotopy.infinity_measure(z) {
            let mut valuations: Vec<f64> = Vec::new();
            let mut stable_positive = false;
            while r > MIN_ENDGAME_T {
                let inner = r / 4.0;
                // A path that stalls on its way down (ever smaller steps near a singular point
                // at infinity) is decided by what its valuations said so far.
                if self
                    .follow_within(
                        z,
                        Segment::Line(C64::from(r), C64::from(inner)),
                        0.25,
                        1.0,
                        if r > DEEP_DESCENT {
                            SHALLOW_DESCENT_BUDGET
                        } else {
                            DESCENT_BUDGET
                        },
                    )
                    .is_err()
                {
                    break;
                }
                r = inner;
                let next = self.homotopy.infinity_measure(z).unwrap_or(m);
                valuations.push((next / m).ln() / 0.25f64.ln());
                m = next;
                if let [.., a, b, c] = valuations[..] {
                    let stable = (a - b).abs() < 0.01 && (b - c).abs() < 0.01;
                    stable_positive = stable && c > 0.04;
                    if stable_positive && m < FINITE_THRESHOLD {
                        return Ok(Endpoint {
                            z: z.clone(),
                            winding: 0,
                            converged: true,
                            diverges: true,
                        });
                    }
                    if stable && c.abs() < 0.01 {
                        if let Some(end) = self.finish_regular(z, r) {
                            return Ok(end);
                        }
                        break;
                    }
                }
            }
            // Where the descent ends (at its floor, or stalled), a point beyond 10⁵ in the
            // patch's scale is at infinity whatever its valuations (Bertini's finite threshold;
            // the valuations are noise that far out).
            if stable_positive || m < FINITE_THRESHOLD {
                return Ok(Endpoint {
                    z: z.clone(),
                    winding: 0,
                    converged: true,
                    diverges: true,
                });
            }
        }
        self.cauchy_endgame(z, r)
    }

    /// The Cauchy endgame from `z` at `t = r`: loops around `t = 0` at radii `r, r/4, …` until
    /// two successive estimates of `z(0)` agree.
    fn cauchy_endgame(
        &mut self,
        z: &mut DVector<C64>,
        mut r: f64,
    ) -> Result<Endpoint, PathFailure> {
        const SAMPLES: usize = 8;
        // One chart for the loops: their averages and the comparison of successive estimates
        // are taken in it.
        self.rechart(z, Segment::Line(C64::from(r), C64::from(0.0)));
        self.recharting = false;
        let mut previous: Option<DVector<C64>> = None;
        let mut last_winding = 0;
        for _ in 0..12 {
            let start = z.clone();
            let mut sum = DVector::<C64>::zeros(z.len());
            let mut count = 0usize;
            let mut winding = 0;
            let closed = loop {
                for j in 0..SAMPLES {
                    sum += &*z;
                    count += 1;
                    let theta0 = std::f64::consts::TAU * j as f64 / SAMPLES as f64;
                    let arc = Segment::Arc {
                        r,
                        theta0,
                        dtheta: std::f64::consts::TAU / SAMPLES as f64,
                    };
                    self.follow_within(z, arc, 1.0, 1.0, self.settings.max_steps)?;
                }
                winding += 1;
                if (&*z - &start).norm() <= 1e-6 * scale(&start) {
                    break true;
                }
                if winding >= self.settings.max_winding {
                    break false;
                }
            };
            if !closed {
                // The circle encloses other branch points of the path (or the path lies on a
                // positive-dimensional set): no estimate at this radius; go inward.
                previous = None;
                let inner = r / 4.0;
                self.follow(z, Segment::Line(C64::from(r), C64::from(inner)), 0.25)?;
                r = inner;
                continue;
            }
            let estimate = sum / C64::from(count as f64);
            if self.homotopy.at_infinity(&estimate) {
                return Ok(Endpoint {
                    z: estimate,
                    winding,
                    converged: true,
                    diverges: false,
                });
            }
            if let Some(p) = &previous
                && (&estimate - p).norm() <= self.settings.endgame_tolerance * scale(&estimate)
            {
                return Ok(Endpoint {
                    z: estimate,
                    winding,
                    converged: true,
                    diverges: false,
                });
            }
            previous = Some(estimate);
            last_winding = winding;
            let inner = r / 4.0;
            self.follow(z, Segment::Line(C64::from(r), C64::from(inner)), 0.25)?;
            r = inner;
        }
        // Estimates that did not settle: the last one, flagged (typically a path to a
        // positive-dimensional set at infinity).
        previous
            .map(|z| Endpoint {
                z,
                winding: last_winding,
                converged: false,
                diverges: false,
            })
            .ok_or(PathFailure::Endgame)
    }

    /// From `z` at `t = 1` to the target at `t = 0` along the straight segment (no endgame: for
    /// homotopies whose paths end regular), refined by Newton's method there; the endpoint, or
    /// why the path was given up.
    pub(crate) fn track_refined(&mut self, mut z: DVector<C64>) -> Result<Vec<C64>, PathFailure> {
        self.track(&mut z, C64::from(1.0), C64::from(0.0))?;
        self.refine(&mut z, C64::from(0.0), 1e-14);
        if z.iter().all(|c| c.re.is_finite() && c.im.is_finite()) {
            Ok(z.iter().copied().collect())
        } else {
            Err(PathFailure::NotFinite)
        }
    }

    /// Newton refinement at fixed `t`; true when it converged.
    pub(crate) fn refine(&mut self, z: &mut DVector<C64>, t: C64, tolerance: f64) -> bool {
        self.correct(z, t, tolerance, 6).is_some()
    }
}
