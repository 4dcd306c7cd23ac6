//! A 3D view of a manipulator: one self-contained HTML page (docs/view.md).
//!
//! kinsyn computes everything the page shows before writing it: the [`Scene`] (bodies, joints
//! and the spanning tree), and configurations as joint values — a sweep per input
//! ([`input_sweep`]), a walk per operation mode ([`mode_walk`]), every real assembly at the
//! given inputs. The page itself only computes the bodies' displacements from those joint
//! values, by the same product of exponentials as [`crate::mechanism::Mechanism::poses`] (a
//! second implementation, which the tests compare with this one), and draws them with
//! three.js (vendored with its licence: no network, no server).
//!
//! A catalogue entry's leg chain has its own view ([`chain_view`]): the serial chain of the
//! catalogue's verification at a generic configuration, with a walk per minimal lock set. The
//! catalogue site writes three.js and the viewer script once ([`SCRIPT_FILES`]) and each entry
//! page refers to them ([`Scripts::Linked`]).

mod animation;
mod chain;
mod page;
mod scene;

pub use animation::{InputSweep, MAX_STEPS, Stop, WALK_STEP, Walk, input_sweep, mode_walk, walk};
pub use chain::{
    CHAIN_WALK_STEP, CHAIN_WALK_STEPS, ChainViewError, DECIMALS, chain_view, serial_mechanism,
};
pub use page::{
    LEGEND, SCRIPT_FILES, Scripts, THREE_JS_VERSION, ViewParts, page, page_with, parts,
};
pub use scene::{Between, Roles, Scene, SceneBody, SceneJoint, TreeStep};

use serde::Serialize;

/// An operation mode as the page lists and animates it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModeView {
    /// Where it comes from: `modes` (locked inputs, sampled) or `components`.
    pub source: String,
    /// The locked inputs (`R1.1 R2.1`, `-` for none).
    pub locks: String,
    /// The motion pattern's name (`X(z)`, `1T2R`, `?` when it could not be sampled).
    pub pattern: String,
    /// The end-effector's degrees of freedom.
    pub dof: usize,
    /// Whether the pattern is a displacement group.
    pub group: bool,
    /// The group's parameters in words (axis point, pitch), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameters: Option<String>,
    /// The configurations of its walk (every joint value: radians for revolutes, the length
    /// unit for sliders).
    pub joint_values: Vec<Vec<f64>>,
    /// The index of the start configuration.
    pub start: usize,
    /// The sides of the walk that stopped early.
    pub stops: Vec<Stop>,
}

/// A real assembly at the view's inputs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AssemblyView {
    /// Its label in the list (`assembly 3`).
    pub label: String,
    /// Whether its solution is certified (Krawczyk).
    pub certified: bool,
    /// Whether it is the one continued from the reference configuration.
    pub continued_from_reference: bool,
    /// Every joint value (radians for revolutes, the length unit for sliders).
    pub joint_values: Vec<f64>,
}

/// Everything one page shows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct View {
    /// The page's format, `kinsyn-view/1`.
    pub format: &'static str,
    /// The manipulator.
    pub scene: Scene,
    /// The configuration shown first (every joint value): the reference, or the one reached
    /// at the given inputs.
    pub start: Vec<f64>,
    /// The inputs at the start, as text (`R1.1=0`).
    pub inputs: Vec<String>,
    /// The end-effector's motion pattern at the start with no input locked, and its dof.
    pub classification: String,
    /// One sweep per input.
    pub sweeps: Vec<InputSweep>,
    /// The operation modes.
    pub modes: Vec<ModeView>,
    /// The real assemblies at the start's inputs (empty when not computed: `notes` says why).
    pub assemblies: Vec<AssemblyView>,
    /// What the page could not show, in words.
    pub notes: Vec<String>,
}

/// The format name written in [`View::format`].
pub const FORMAT: &str = "kinsyn-view/1";
