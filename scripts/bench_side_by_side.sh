#!/usr/bin/env bash
# Two icpbench binaries side by side on the same single car-track windows
# (bench/chain_windows.h: w = 5, 10, 20, prior and cold, 12 seeds): each
# window is contracted with `solve --repeat 101` by one binary, then the
# other, alternated ROUNDS times; prints, per algorithm, w and heading, both
# medians (µs per contraction) and the median over the windows of the
# per-window ratio B / A (each window's median time over the rounds).
#   bash scripts/bench_side_by_side.sh A_BINARY B_BINARY [ROUNDS] [ALGORITHMS]
# e.g. A = the binary at revision 7d15298 (before the estimators redesign),
# B = build/icpbench; ALGORITHMS defaults to "hc4 3b-bc4". Both contract the
# same files and must print the same boxes, or the script stops.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 2 ]]; then
  echo "usage: $0 A_BINARY B_BINARY [ROUNDS] [ALGORITHMS]" >&2
  exit 2
fi
a=$1 b=$2 rounds=${3:-2} algorithms=${4:-hc4 3b-bc4}
ninja -C build -j"${ICPBENCH_JOBS:-2}" bench/write_chain_windows >/dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
build/bench/write_chain_windows "$dir" >/dev/null
times=$dir/times.tsv
for algorithm in $algorithms; do
  repeat=101
  [[ $algorithm == 3b-* ]] && repeat=11
  for file in "$dir"/*.bch; do
    window=$(basename "$file" .bch)
    for ((r = 0; r < rounds; ++r)); do
      for side in a b; do
        binary=$a
        [[ $side == b ]] && binary=$b
        "$binary" solve "$file" -a "$algorithm" -r "$repeat" -f json > "$dir/$side.json"
      done
      python3 - "$dir/a.json" "$dir/b.json" "$algorithm" "$window" >> "$times" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
if a["box"] != b["box"]:
    sys.exit(f"{sys.argv[4]}: the two binaries give different boxes with {sys.argv[3]}")
print(sys.argv[3], sys.argv[4], a["time_s"], b["time_s"], sep="\t")
PY
    done
  done
done
python3 - "$times" <<'PY'
import collections, statistics, sys
per_window = collections.defaultdict(lambda: ([], []))
for line in open(sys.argv[1]):
    algorithm, window, ta, tb = line.split("\t")
    per_window[(algorithm, window)][0].append(float(ta))
    per_window[(algorithm, window)][1].append(float(tb))
groups = collections.defaultdict(list)
for (algorithm, window), (ta, tb) in per_window.items():
    w, heading = window.split("_")[1:3]
    groups[(algorithm, int(w[1:]), heading)].append((statistics.median(ta), statistics.median(tb)))
print("algorithm  w   heading  A (us)   B (us)   B/A median over windows")
for (algorithm, w, heading), pairs in sorted(groups.items()):
    ta = statistics.median(p[0] for p in pairs) * 1e6
    tb = statistics.median(p[1] for p in pairs) * 1e6
    ratio = statistics.median(p[1] / p[0] for p in pairs)
    print(f"{algorithm:9}  {w:2}  {heading:7}  {ta:7.1f}  {tb:7.1f}  {ratio:.3f}")
PY
