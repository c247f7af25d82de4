#!/usr/bin/env bash
# Measures the MPI sweep (icpbench run --mpi) on this machine:
#  - the dispatcher: rank 0's CPU time a run, dispatching (sending runs,
#    receiving results) and storing apart, over a sweep of SHORT trivial
#    runs (HC4 on chain) where the overhead is all there is; rank 0 prints
#    both ("rank 0 per run: ...");
#  - the speedup of a CPU-bound sweep (CPU_RUNS runs of 3B-BC4 on a
#    car-track window, about a second each) with 1 and 2 worker ranks
#    (mpirun -n 2 and -n 3, --jobs 1 each), against the local runner with
#    --jobs 1 and 2. Wall time of the whole command, mpirun's start and end
#    included; they are timed apart too (the same sweep again, every run
#    then stored).
# Prints the median of REPS repetitions as a Markdown table.
#   bash scripts/bench_mpi.sh [SHORT [CPU_RUNS [REPS]]]
set -euo pipefail
cd "$(dirname "$0")/.."
short=${1:-400}
cpu_runs=${2:-24}
reps=${3:-3}
bin=${ICPBENCH:-build/icpbench}
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

ratio() { awk -v a="$1" -v b="$2" 'BEGIN {print a / b}'; }
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# Wall seconds of a command (its output to $work/log).
timed() {
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >"$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}' 
}

cat >"$work/short.yaml" <<YAML
repetitions: $short
algorithms: [hc4]
problems: [chain]
YAML
cat >"$work/cpu.yaml" <<YAML
repetitions: $cpu_runs
algorithms: [3b-bc4]
problems: [{name: car-track, params: {w: 20, steps: 60}}]
YAML

: >"$work/dispatch"; : >"$work/storing"; : >"$work/short_wall"; : >"$work/fixed"
for ((i = 0; i < reps; ++i)); do
  rm -rf "$work/out"
  timed "${mpirun[@]}" -n 3 "$bin" run "$work/short.yaml" --mpi --jobs 1 --out "$work/out" >>"$work/short_wall"
  sed -n 's/.*rank 0 per run: \([0-9.]*\) ms CPU dispatching, \([0-9.]*\) ms CPU storing.*/\1 \2/p' "$work/log" >"$work/per_run"
  cut -d' ' -f1 "$work/per_run" >>"$work/dispatch"
  cut -d' ' -f2 "$work/per_run" >>"$work/storing"
done

# The setups take turns within each repetition, so that a slower spell of
# the machine falls on all of them.
setups=(local1 local2 mpi1 mpi2)
for setup in "${setups[@]}"; do : >"$work/$setup"; done
for ((i = 0; i < reps; ++i)); do
  for setup in "${setups[@]}"; do
    rm -rf "$work/out"
    case $setup in
      local1) timed "$bin" run "$work/cpu.yaml" --jobs 1 --out "$work/out" ;;
      local2) timed "$bin" run "$work/cpu.yaml" --jobs 2 --out "$work/out" ;;
      mpi1) timed "${mpirun[@]}" -n 2 "$bin" run "$work/cpu.yaml" --mpi --jobs 1 --out "$work/out" ;;
      mpi2) timed "${mpirun[@]}" -n 3 "$bin" run "$work/cpu.yaml" --mpi --jobs 1 --out "$work/out" ;;
    esac >>"$work/$setup"
    [ "$setup" = mpi2 ] &&
      timed "${mpirun[@]}" -n 3 "$bin" run "$work/cpu.yaml" --mpi --jobs 1 --out "$work/out" >>"$work/fixed"
  done
done
declare -A wall
for setup in "${setups[@]}"; do wall[$setup]=$(median <"$work/$setup"); done

echo "MPI sweep on $(nproc) cores, median of $reps; $short short runs, $cpu_runs CPU-bound runs"
echo
echo "| measure | value |"
echo "|---|---|"
printf '| rank 0 dispatching a run (CPU time) | %.3f ms |\n' "$(median <"$work/dispatch")"
printf '| rank 0 storing a run (CPU time) | %.3f ms |\n' "$(median <"$work/storing")"
printf '| %d short runs, 2 worker ranks (wall) | %.2f s |\n' "$short" "$(median <"$work/short_wall")"
printf '| CPU-bound sweep, local --jobs 1 | %.2f s |\n' "${wall[local1]}"
printf '| CPU-bound sweep, local --jobs 2 | %.2f s (%.2fx) |\n' "${wall[local2]}" "$(ratio "${wall[local1]}" "${wall[local2]}")"
printf '| CPU-bound sweep, MPI 1 worker rank | %.2f s |\n' "${wall[mpi1]}"
printf '| CPU-bound sweep, MPI 2 worker ranks | %.2f s (%.2fx) |\n' "${wall[mpi2]}" "$(ratio "${wall[mpi1]}" "${wall[mpi2]}")"
fixed=$(median <"$work/fixed")
printf '| mpirun start and end, 3 ranks (the sweep with every run stored) | %.2f s |\n' "$fixed"
printf '| MPI speedup, 2 vs 1 worker ranks, start and end left out | %.2fx |\n' \
  "$(awk -v a="${wall[mpi1]}" -v b="${wall[mpi2]}" -v f="$fixed" 'BEGIN {print (a - f) / (b - f)}')"
