//! kinsyn-papers: the case studies of single papers, each by the paper's own formulas — the
//! second method beside the general engine (`kinsyn`), through which the papers' mechanisms
//! themselves go as description files (`mechanisms/`).
//!
//! - [`appendix`]: paper 000's printed Appendix (Tables 1–4, 7, 8), transcribed, as the printed
//!   table the catalogue of the engine is marked against and compared with row by row; the
//!   committed catalogue is [`appendix::generate`] with the default options.
//! - [`hexa`]: paper 001's 6-RUU HEXA with reconfigurable platforms: the closed-form inverse
//!   geometry, the four-bar of the platforms, the transmission indices, the workspaces and the
//!   description file it writes.
//! - [`series`]: paper 002's series-parallel manipulators from the geometry of stacked
//!   three-legged modules: the Jacobian `J_S-PM` and the twist system, and ([`series::stack`])
//!   a manipulator of the engine read as such a stack.
//! - [`configurable`]: paper 003's planar 4-RRR with a configurable platform: the two
//!   parametrisations, inverse and forward position as polynomial systems, velocities by screw
//!   theory, the trajectory by parameter homotopy.
//! - [`ruu`]: paper 004's 4-RUU and its constraint equations `g1 … g14` in Study parameters.
//!
//! The engine never imports this crate; the command line and the tests set its answers beside
//! the engine's.
#![deny(missing_docs)]

pub mod appendix;
pub mod configurable;
pub mod hexa;
pub mod ruu;
pub mod series;
