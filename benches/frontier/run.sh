#!/bin/sh
# The solver at the frontier side by side with PHCpack's blackbox solver (`phc -b`, Debian
# package `phcpack`): Katsura-8 to -12, cyclic-8 and the 4-RUU at generic inputs, each solved
# by `kinsyn solve` (default start `auto`, all cores) and by `phc -b` in turn, RUNS times each
# (default 1). Prints the wall seconds of each run, kinsyn's summary line and PHCpack's count
# of regular finite solutions, so that every run is seen to find the same roots.
#
#   sh benches/frontier/run.sh [RUNS]
set -eu
runs=${1:-1}
dir=target/frontier
cargo build --release -q --bin kinsyn
cargo run --release -q -p kinsyn-bench --example frontier_systems -- "$dir" > /dev/null
command -v phc > /dev/null || { echo "phc not found: apt-get install phcpack" >&2; exit 2; }
now() { date +%s.%N; }
for name in katsura-8 katsura-9 katsura-10 katsura-11 katsura-12 cyclic-8 4-ruu-generic; do
    i=0
    while [ "$i" -lt "$runs" ]; do
        t0=$(now)
        summary=$(target/release/kinsyn solve "$dir/$name.bertini" --max-paths 1048576 | sed -n 3p)
        t1=$(now)
        rm -f "$dir/$name.phc.out"
        phc -b "$dir/$name.phc" "$dir/$name.phc.out" > /dev/null
        t2=$(now)
        printf '%s: kinsyn %.2f s (%s) | phc -b %.2f s\n' "$name" \
            "$(echo "$t1 - $t0" | bc)" "$summary" "$(echo "$t2 - $t1" | bc)"
        grep "Number of regular solutions" "$dir/$name.phc.out" | tail -n 1
        i=$((i + 1))
    done
done
