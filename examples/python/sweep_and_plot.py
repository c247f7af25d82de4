"""A small sweep from Python, read back as a DataFrame and drawn with
matplotlib: HC4 and BC4 on the car track at three window lengths.

    PYTHONPATH=build/python python3 examples/python/sweep_and_plot.py results/python-example
"""

import json
import sys

import matplotlib
import matplotlib.pyplot as plt

import icpbench

out = sys.argv[1] if len(sys.argv) > 1 else "results/python-example"
spec = {
    "name": "python-example",
    "seeds": [1],
    "experiments": [{
        "name": "window-length",
        "algorithms": ["hc4", "bc4"],
        "problems": [{"name": "car-track", "params": {"w": [2, 5, 10], "steps": 50}}],
    }],
}
print(icpbench.run(spec, out=out, jobs=2))

with icpbench.open(out) as store:
    runs = store.runs()
runs["w"] = runs["problem_params"].map(lambda p: int(json.loads(p)["w"]))
table = runs.pivot(index="w", columns="algorithm", values="mean_area")
print(table)

matplotlib.rcParams["figure.figsize"] = (5, 3.5)
ax = table.plot(marker="o")
ax.set_xlabel("window length w (steps)")
ax.set_ylabel("mean x-y area (m²)")
ax.figure.tight_layout()
ax.figure.savefig(f"{out}/mean_area.png", dpi=120)
print(f"{out}/mean_area.png")
