//! The tests of kinsyn-nag: polynomials, Bertini and PHCpack files, homotopy, witness sets, certificates.
//!
//! One test binary for the crate, one module per file (named after the module of `src/` it
//! checks), so that the library is linked once. Run one module with
//! `cargo test -p kinsyn-nag --test suite MODULE::`; the exhaustive checks are `#[ignore]`d and run
//! by `.ci/run` (`cargo test --locked -- --ignored`).

mod certify;
mod composition;
mod homotopy;
mod homotopy_known_roots;
mod poly;
mod polyhedral;
mod real_branch;
mod system_files;
mod witness;
