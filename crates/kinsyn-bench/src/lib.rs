//! The benchmarks of kinsyn, in `benches/` (criterion): `cargo bench -p kinsyn-bench --bench
//! NAME`, each measuring one method of the library on the papers' mechanisms and the standard
//! polynomial systems, side by side with the anchors where docs/ names them. The crate has no
//! code of its own.
