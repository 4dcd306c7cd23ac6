#!/bin/sh
# Paper 004 (4-RUU): the exact counterparts of crates/kinsyn/benches/decomposition.rs, timed.
# Run from the repository root:  sh benches/singular/run.sh [--full]
#   fixed_inputs.sing                  case 1, minAssGTZ of I at fixed inputs        (< 1 s)
#   two_ruu_input_space_sliced.sing    case 2 on a generic linear section             (~ 1 s)
#   two_ruu_generic_inputs.sing        case 2 as the paper does it, inputs in Q(t11,t13) (~ 2 s)
#   four_ruu_generic_inputs.sing       case 3 as the paper does it, inputs in Q(t11..t14) (~ 2 s)
#   four_ruu_input_space_sliced.sing   case 3 on a generic linear section              (> 5 min)
#   two_ruu_input_space.sing           case 2, minAssGTZ with t11, t13 ring variables  (> 10 min)
#   four_ruu_input_space.sing          case 3, minAssGTZ with t11..t14 ring variables  (> 10 min)
# The last three run only with --full; every run is stopped after $LIMIT seconds (default 600).
set -u
dir=$(dirname "$0")
data="$dir/../../data/paper004-constraints.txt"
LIMIT=${LIMIT:-600}
# The equations in the scripts must be the printed ones, verbatim.
for f in "$dir"/*.sing; do
  grep -E '^poly g([1-9]|1[0-2]) = ' "$f" | sed 's/^poly //' | while IFS= read -r line; do
    grep -qxF "$line" "$data" || { echo "$f: not in $data: $line"; exit 1; }
  done || exit 1
done
scripts="fixed_inputs two_ruu_input_space_sliced two_ruu_generic_inputs four_ruu_generic_inputs"
[ "${1:-}" = "--full" ] && scripts="$scripts four_ruu_input_space_sliced two_ruu_input_space four_ruu_input_space"
for s in $scripts; do
  echo "== $s.sing"
  start=$(date +%s.%N)
  out=$(mktemp)
  timeout "$LIMIT" Singular -q < "$dir/$s.sing" > "$out" 2>&1
  rc=$?
  grep -v '^// \*\* redefining' "$out"; rm -f "$out"
  end=$(date +%s.%N)
  if [ "$rc" = 124 ]; then echo "   > $LIMIT s (stopped)"; else
    echo "   wall $(echo "$end - $start" | bc) s"; fi
done
