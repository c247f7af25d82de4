#!/usr/bin/env bash
# Times 3B-BC4 over one simulated lap at w = 20 (2000 CSPs, carry=first, as
# in paper 000's Table 1) with warm-started trials (the default) and with
# every trial started cold (warm_start=false), alternated REPS times (default
# 3), one run at a time. Prints each run's mean and median solve time per
# CSP, the medians over the runs, and whether the two stored the same boxes.
# With a second argument, a results store holding an earlier run of the same
# lap (3b-bc4 on car-track {w: 20}, seed 1, e.g. from an older binary), it
# also counts the warm run's bounds that are the same, tighter or looser than
# there: the "boxes at least as tight" check for a change that moves them.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
reps=${1:-3}
baseline=${2:-}
if [ -n "$baseline" ] && [ ! -s "$baseline" ]; then
  echo "bench_3b.sh: $baseline is not a results store" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

spec() {  # spec WARM -> a one-run spec
  cat <<SPEC
name: bench-3b
description: 3B-BC4 over a lap, warm_start=$1
seeds: [1]
algorithms:
  - {name: 3b-bc4, params: {warm_start: $1}}
problems:
  - {name: car-track, params: {w: 20}}
SPEC
}
for warm in true false; do spec "$warm" >"$work/$warm.yaml"; done

for rep in $(seq "$reps"); do
  for warm in true false; do
    out="$work/$warm-$rep"
    ./build/icpbench run "$work/$warm.yaml" --out "$out" --jobs 1 >/dev/null 2>&1
    sqlite3 -separator ' ' "$out/results.sqlite" \
      "select '$warm', time_mean_s * 1e3, time_median_s * 1e3 from runs" >>"$work/times"
  done
done
awk '{printf "warm_start=%-5s mean %6.2f ms  median %6.2f ms\n", $1, $2, $3}' "$work/times"
for warm in true false; do
  awk -v w="$warm" '$1 == w {print $3}' "$work/times" | sort -g |
    awk -v w="$warm" '{v[NR] = $1} END {printf "warm_start=%s: median of the %d run medians %.2f ms\n", w, NR, (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
done
boxes() { sqlite3 "$1/results.sqlite" "select step, pos, lo, hi from step_values order by step, pos"; }
if [ "$(boxes "$work/true-1")" = "$(boxes "$work/false-1")" ]; then
  echo "boxes: the same at every step"
else
  echo "boxes: DIFFER"
fi
if [ -n "$baseline" ]; then
  sqlite3 -separator ' ' "$work/true-1/results.sqlite" "
    attach '$baseline' as b;
    with old as (select step, pos, lo, hi from b.step_values where run_id = (
                   select min(id) from b.runs where algorithm = '3b-bc4' and problem = 'car-track'
                     and seed = 1 and status = 'ok' and problem_params like '%\"w\":\"20\"%'
                     and steps = (select steps from runs)))
    select count(*), sum(n.lo = o.lo and n.hi = o.hi),
           sum((n.lo >= o.lo and n.hi <= o.hi) and not (n.lo = o.lo and n.hi = o.hi)),
           sum(n.lo < o.lo or n.hi > o.hi), coalesce(max(max(o.lo - n.lo, n.hi - o.hi)), 0)
    from step_values n join old o on n.step = o.step and n.pos = o.pos" |
    awk '$1 == 0 {print "baseline: no 3b-bc4 run of the same lap in it"; exit}
         {printf "against the baseline: %d bounds, %d the same, %d tighter, %d looser (by at most %g)\n", $1, $2, $3, $4, ($4 > 0 ? $5 : 0)}'
fi
