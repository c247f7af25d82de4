#!/usr/bin/env bash
# The main job of the README: installs what is missing, builds, runs the
# default benchmark suite (specs/default.yaml) into results/default, then
# writes its tables (Markdown, LaTeX, CSV), figures (PNG, PDF) and, last,
# the paper (PDF); its last line is the command that serves them as a web page.
# Rerunning resumes: runs already stored are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
out=${ICPBENCH_OUT:-results/default}
./build/icpbench run specs/default.yaml --out "$out" --jobs "${ICPBENCH_JOBS:-$(nproc)}"
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
