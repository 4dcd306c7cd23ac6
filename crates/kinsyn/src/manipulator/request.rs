//! What a caller asks of a manipulator by name or in text — an actuator (`P1.3`), a moving body,
//! input values (`P1.3=0.05`), a platform pose (`x,y,z,rx,ry,rz` or `z=1.1,rx=5`) — and why a
//! request can be refused ([`RequestError`]), or a position not reached ([`PositionError`]).

use super::position::CONTINUATION_TRIES;

/// A request that names something the manipulator does not have, or a value that is not one.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// No actuator has this label.
    #[error("{label:?} is not an actuator of {manipulator} (actuators: {})", known.join(" "))]
    UnknownActuator {
        /// The label asked for.
        label: String,
        /// The manipulator's name.
        manipulator: String,
        /// The labels of its actuators.
        known: Vec<String>,
    },
    /// No moving body has this name.
    #[error("{name:?} is not a moving body of {manipulator} (moving bodies: {})", known.join(", "))]
    UnknownBody {
        /// The name asked for.
        name: String,
        /// The manipulator's name.
        manipulator: String,
        /// The names of its moving bodies.
        known: Vec<String>,
    },
    /// A body's motion asked for relative to itself.
    #[error(
        "{name:?} is the body analysed: its motion relative to itself is none; name another moving body"
    )]
    RelativeToItself {
        /// The name asked for.
        name: String,
    },
    /// An input value item without `=`.
    #[error("{item:?} is not LABEL=VALUE (e.g. {example}=0.1)")]
    NotLabelValue {
        /// The item.
        item: String,
        /// A label of this manipulator, for the example.
        example: String,
    },
    /// The same input given two values.
    #[error("input {0} given twice")]
    InputTwice(String),
    /// No input value at all.
    #[error("no input value given (e.g. P1.3=0.1)")]
    NoInput,
    /// A pose given as plain numbers that are not six.
    #[error(
        "{0} number{s}: a whole pose is six numbers x,y,z,rx,ry,rz (or name some of them: z=1.1,rx=5)",
        s = if *.0 == 1 { "" } else { "s" }
    )]
    PoseCount(usize),
    /// A pose item without a name among named ones.
    #[error("{0:?}: name every coordinate (x, y, z, rx, ry, rz), e.g. z=1.1")]
    UnnamedCoordinate(String),
    /// A name that is not one of x, y, z, rx, ry, rz.
    #[error("{0:?} is not a coordinate: x, y, z, rx, ry or rz")]
    UnknownCoordinate(String),
    /// A coordinate given twice.
    #[error("{0} given twice")]
    CoordinateTwice(&'static str),
    /// Text that is not a finite number.
    #[error("{0:?} is not a finite number")]
    NotANumber(String),
    /// A number beyond the coordinates kinsyn computes with (docs/limits.md).
    #[error("{0:e} is beyond ±{max:e} (docs/limits.md)", max = super::LARGEST_COORDINATE)]
    BeyondLimit(f64),
    /// More inputs than can have all their lock subsets enumerated.
    #[error(
        "{manipulator} has {inputs} inputs; at most {max} can have all their lock subsets enumerated",
        max = super::MAX_INPUTS
    )]
    TooManyInputs {
        /// The manipulator's name.
        manipulator: String,
        /// Its number of inputs.
        inputs: usize,
    },
    /// Not one set of Study parameters per moving body.
    #[error(
        "{given} set{s} of Study parameters for the {bodies} moving bodies of {manipulator}: give one per moving body, in series order from the ground",
        s = if *given == 1 { "" } else { "s" }
    )]
    StudyCount {
        /// The manipulator's name.
        manipulator: String,
        /// Sets given.
        given: usize,
        /// Its moving bodies.
        bodies: usize,
    },
    /// Study parameters that are not eight numbers `x0:x1:…:x7` (any scale).
    #[error("{0:?}: Study parameters are eight numbers x0:x1:x2:x3:y0:y1:y2:y3 (any common scale)")]
    StudyFormat(String),
    /// Study parameters of a body that are not those of a displacement (off the Study quadric
    /// beyond the tolerance, `x = 0`, or not finite).
    #[error("the Study parameters of body {body:?}: {source}")]
    Study {
        /// The body's name.
        body: String,
        /// Why they are no displacement.
        source: crate::spatial::study::StudyError,
    },
}

/// Why a position (input values, a pose, or both) was not reached.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PositionError {
    /// Neither the continuation from the start nor Newton steps straight from it closed the
    /// loops: the values lie beyond the workspace, or a singularity lies between.
    #[error("no assembly reached: {0}")]
    NotReached(ContinuationFailure),
    /// The values given leave the platform free: it needs `0` more inputs or coordinates.
    #[error(
        "the values given leave the platform {0} degree{s} of freedom: give {0} more input{s} or platform coordinate{s}",
        s = if *.0 == 1 { "" } else { "s" }
    )]
    Undetermined(usize),
    /// No random assembly closes around the configuration, so its generic ranks are unknown.
    #[error(
        "no random assembly around this configuration closes, so its generic ranks are unknown"
    )]
    NoGenericAssembly,
    /// The bodies' poses asked for at once ([`super::Manipulator::solve_poses`]) do not meet the
    /// loop closure: no joint values put every body there, within the assembly tolerance.
    #[error(
        "the poses asked for cannot be assembled: damped Newton stops at residual {residual:.3e} (rad, or length over the characteristic length; tolerance {tolerance:.0e}), {:.1}% of the way from the start",
        100.0 * .done
    )]
    PosesNotAssembled {
        /// The largest dimensionless residual of the loop closure and the pose equations where
        /// the solver stopped: how far the poses are from an assembly.
        residual: f64,
        /// The tolerance it exceeds ([`crate::mechanism::ASSEMBLY_TOLERANCE`]).
        tolerance: f64,
        /// The fraction of the path from the start poses done.
        done: f64,
    },
    /// The nearest configuration to poses given by rounded data
    /// ([`super::Manipulator::nearest_study`]) moves a body further than the rounding can:
    /// the data are no rounded configuration of this mechanism (another reading of the
    /// mechanism, or a misprint).
    #[error(
        "the nearest assembly moves {body:?} by {translation:.3e} (length) and {rotation:.3e} rad, more than rounding the parameters by {rounding} explains ({translation_bound:.3e} and {rotation_bound:.3e} rad): no rounded configuration of this mechanism"
    )]
    BeyondRounding {
        /// The body moved too far.
        body: String,
        /// How far its frame's origin moved (the description's length unit).
        translation: f64,
        /// By how much its frame turned (radians).
        rotation: f64,
        /// The most its origin can move when each parameter changes by the rounding.
        translation_bound: f64,
        /// The most it can turn when each parameter changes by the rounding (radians).
        rotation_bound: f64,
        /// The half unit of the last printed place of each parameter.
        rounding: f64,
    },
}

/// Where a continuation stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContinuationFailure {
    /// It needed more than [`CONTINUATION_TRIES`] steps.
    #[error(
        "the continuation from the start needs more than {CONTINUATION_TRIES} steps ({:.1}% of the way done): the values are far from the start; start nearer them",
        100.0 * .done
    )]
    TooManySteps {
        /// The fraction of the path done.
        done: f64,
    },
    /// A step could not be made smaller and still close the loops.
    #[error(
        "the continuation from the start stopped {:.1}% of the way, where {why}; the values lie beyond the workspace, or a singularity lies between",
        100.0 * .done
    )]
    Stopped {
        /// The fraction of the path done.
        done: f64,
        /// What failed at the last step.
        why: String,
    },
}

impl ContinuationFailure {
    /// The fraction of the path done when the continuation stopped.
    #[must_use]
    pub fn done(&self) -> f64 {
        match self {
            ContinuationFailure::TooManySteps { done }
            | ContinuationFailure::Stopped { done, .. } => *done,
        }
    }
}
