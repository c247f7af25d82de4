"""The Python module's overhead against the command line (docs/python.md).

  1. solve: icpbench.solve(FILE, "hc4") wall time per call, from Python,
     against the contraction time the command line reports (`solve --format
     json`'s time_s) on a car-track window of w = 20 steps (the form of
     examples/car_window.bch); goal: within 2x.
  2. stepping by hand: a Python loop of problem steps fed to
     icpbench.estimator("hc4") against `icpbench run` of the same run
     (wall time per step, store's wall_time_s / steps); goal: within 1.5x.

Medians of repeated measurements. Usage (from the source tree, after the build):
  PYTHONPATH=build/python python3 bench/python_overhead.py [build/icpbench]
"""

import json
import statistics
import subprocess
import sys
import tempfile
import time

import icpbench

binary = sys.argv[1] if len(sys.argv) > 1 else "build/icpbench"


def car_window(w):
    return f"""Constants
  dth = [0.010, 0.014];
Variables
  x[{w + 1}] in [-2.5, {2.75 * w + 4}];
  y[{w + 1}] in [-2.5, 2.5];
  th[{w + 1}] in [-3.1416, 3.1416];
Constraints
  for k = 1:{w};
    x(k+1) = x(k) + [2.70, 2.80] * cos(th(k) + dth / 2);
    y(k+1) = y(k) + [2.70, 2.80] * sin(th(k) + dth / 2);
    th(k+1) = th(k) + dth;
  end;
end
"""


def solve_overhead(rounds=30):
    with tempfile.NamedTemporaryFile("w", suffix=".bch", delete=False) as f:
        f.write(car_window(20))
    cli = []
    for _ in range(rounds // 3):
        out = subprocess.run([binary, "solve", f.name, "--algorithm", "hc4", "--format", "json"],
                             capture_output=True, text=True, check=True).stdout
        cli.append(json.loads(out)["time_s"])
    python = []
    for _ in range(rounds):
        t = time.perf_counter()
        icpbench.solve(f.name, "hc4")
        python.append(time.perf_counter() - t)
    return statistics.median(python), statistics.median(cli)


def stepping_overhead(steps=1000, rounds=3):
    by_hand, run = [], []
    for _ in range(rounds):
        t = time.perf_counter()
        estimator = icpbench.estimator("hc4", seed=1)
        for step in icpbench.problem("car-track", seed=1, w=20, steps=steps):
            estimator.step(step)
        by_hand.append((time.perf_counter() - t) / steps)
        with tempfile.TemporaryDirectory() as out:
            spec = f"""name: overhead
seeds: [1]
experiments:
  - name: hand
    algorithms: [hc4]
    problems: [{{name: car-track, params: {{w: 20, steps: {steps}}}}}]
"""
            with open(f"{out}/spec.yaml", "w") as s:
                s.write(spec)
            subprocess.run([binary, "run", f"{out}/spec.yaml", "--out", out], check=True,
                           capture_output=True)
            with icpbench.open(out) as store:
                row = store.runs().iloc[0]
                run.append(row["wall_time_s"] / row["steps"])
    return statistics.median(by_hand), statistics.median(run)


python, cli = solve_overhead()
print(f"solve, w = 20: Python {python * 1e6:.1f} us per call, command line's contraction "
      f"{cli * 1e6:.1f} us: {python / cli:.2f}x (goal <= 2)")
hand, run = stepping_overhead()
print(f"stepping HC4, w = 20: by hand {hand * 1e6:.1f} us per step, icpbench run "
      f"{run * 1e6:.1f} us: {hand / run:.2f}x (goal <= 1.5)")
