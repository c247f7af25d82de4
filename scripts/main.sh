#!/usr/bin/env bash
# The main job of the README: installs what is missing, builds, then lists
# the registered algorithms and solves the shipped examples with each one.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
./build/icpbench list algorithms
for file in examples/*.bch; do
  for algorithm in $(./build/icpbench list algorithms | grep -v '^ ' | grep -v 'test plugin'); do
    echo "== $file with $algorithm"
    ./build/icpbench solve "$file" --algorithm "$algorithm"
  done
done
