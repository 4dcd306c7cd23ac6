# Tasks for kinsyn (https://github.com/casey/just). CI does not need `just`: `.ci/run` is the
# check, and `just ci` runs exactly it (format, clippy -D warnings, tests, the main job, and
# the API docs with RUSTDOCFLAGS="-D warnings").

# List the recipes.
default:
    @just --list

# What CI runs: .ci/run, whose last step is cargo doc with warnings denied.
ci:
    .ci/run

# The API docs alone, rustdoc warnings (broken intra-doc links) denied, as .ci/run builds them.
doc:
    RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --locked

# All tests: unit, integration, doc tests and the fuzz-corpus replay (README: cargo test --locked).
test:
    cargo test --locked

# Criterion benchmarks: all, or one of synthesis, verification, manipulator.
bench BENCH="":
    cargo bench --locked {{ if BENCH == "" { "" } else { "--bench " + BENCH } }}

# Fuzz TARGET (notation, pattern, locks, description, position) for SECONDS; nightly + cargo-fuzz, docs/fuzzing.md.
fuzz TARGET SECONDS="60":
    nice -n 19 cargo +nightly fuzz run {{ TARGET }} -- -max_total_time={{ SECONDS }} -timeout=20 \
        -rss_limit_mb=4096 -dict=fuzz/{{ TARGET }}.dict
