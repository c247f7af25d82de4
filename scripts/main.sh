#!/usr/bin/env bash
# The main job of the README: installs what is missing, builds, runs the
# default benchmark suite (specs/default.yaml, then paper 004's repeat phase,
# specs/repeat.yaml, on the map its teach run left) into results/default, then
# writes its tables (Markdown, LaTeX, CSV), figures (PNG, PDF) and, last,
# the paper (PDF); its last line is the command that serves them as a web page.
# Rerunning resumes: runs already stored are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
out=${ICPBENCH_OUT:-results/default}
jobs=${ICPBENCH_JOBS:-$(nproc)}
./build/icpbench run specs/default.yaml --out "$out" --jobs "$jobs"
# Paper 004's repeat phase reads the map of the suite's loop teach run.
./build/icpbench map "$out" route=loop phase=teach '|seed=1' -o "$out/visual_map.csv"
repeat=specs/repeat.yaml
if [ "$out" != results/default ]; then
  repeat="$out/repeat.yaml"
  sed "s|results/default/visual_map.csv|$out/visual_map.csv|" specs/repeat.yaml > "$repeat"
fi
./build/icpbench run "$repeat" --out "$out" --jobs "$jobs"
./build/icpbench report "$out" --format md > "$out/report.md"
./build/icpbench report "$out" --format tex > "$out/report.tex"
./build/icpbench report "$out" --format csv > "$out/report.csv"
./build/icpbench plot "$out" --out "$out/figures" > /dev/null
paper=$(./build/icpbench paper "$out")
echo
echo "results store: $out/results.sqlite"
echo "tables:        $out/report.md, $out/report.tex, $out/report.csv"
echo "figures:       $out/figures/ ($(ls "$out/figures" | tr '\n' ' '))"
echo "paper:         $paper"
echo "to look at the results in a browser (docs/web.md):"
echo "  build/icpbench serve $out"
