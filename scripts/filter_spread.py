#!/usr/bin/env python3
"""Whether a particle filter's cloud is as wide as its errors, per run of a
results store (docs/reproduction/thesis003.md, "Particle-filter coverage").

For each particle-filter run and each state component, from the step
properties mean_<c> and cov_<c>_<c> and the stored truth: the share of steps
whose truth lies within z standard deviations of the cloud's mean, z the
Gaussian quantile of each component's share of a 50 % box under the Sidak
split the credible box uses (0.5^(1/d) for d components: 0.794 for three,
0.707 for two); the share where all components do (joint) against the
product of the shares (what independent components would give); and the
stored covered_50. A share above the expected one says the cloud is wider
than its errors in that component; joint above product says the
components' errors go together. Headings are compared modulo 2 pi.

And how much one run's covered_50 share can say: its steps are not
independent (a filter off the truth stays off for a while), so the run's
effective number of steps, n_eff = steps / (1 + 2 sum of the lag
autocorrelations of covered_50, up to the first one below 0), and the
standard deviation of the share a calibrated 50 % box would show over
n_eff independent steps, sqrt(0.25 / n_eff).

    python3 scripts/filter_spread.py results/coverage
"""
import collections
import math
import sqlite3
import statistics
import sys


def effective_steps(series):
    """len(series) / (1 + 2 sum of its lag autocorrelations, up to the
    first one below 0); len(series) for a constant series."""
    n = len(series)
    mean = sum(series) / n
    variance = sum((x - mean) ** 2 for x in series) / n
    if variance == 0:
        return float(n)
    total = 0.0
    for lag in range(1, n // 2):
        rho = sum((series[i] - mean) * (series[i + lag] - mean) for i in range(n - lag)) / (n * variance)
        if rho < 0:
            break
        total += rho
    return n / (1 + 2 * total)


def main(directory):
    db = sqlite3.connect(f"file:{directory}/results.sqlite?mode=ro", uri=True)
    runs = db.execute("SELECT id, key FROM runs WHERE algorithm = 'particle-filter' "
                      "AND status = 'ok' ORDER BY key").fetchall()
    if not runs:
        sys.exit(f"{directory}: no ok particle-filter run")
    print("run\tsteps\tcovered_50\tn_eff\tsd at 50 %\tjoint\tproduct\texpected\t"
          "share within z sd, per component")
    for run_id, key in runs:
        props = collections.defaultdict(dict)
        for step, name, value in db.execute(
                "SELECT step, name, value FROM step_properties WHERE run_id = ?", (run_id,)):
            props[step][name] = value
        truth = collections.defaultdict(dict)
        for step, var, value in db.execute(
                "SELECT step, var, truth FROM step_values WHERE run_id = ?", (run_id,)):
            truth[step][var] = value
        names = sorted({n[5:] for p in props.values() for n in p if n.startswith("mean_")})
        expected = 0.5 ** (1 / len(names))
        z = statistics.NormalDist().inv_cdf((1 + expected) / 2)
        within = {c: 0 for c in names}
        steps = joint = covered = 0
        covered_series = [int(props[k].get("covered_50", 0)) for k in sorted(props) if "covered_50" in props[k]]
        for step, p in props.items():
            if any(f"mean_{c}" not in p or truth[step].get(c) is None for c in names):
                continue
            steps += 1
            covered += int(p.get("covered_50", 0))
            every = True
            for c in names:
                sd = math.sqrt(max(float(p[f"cov_{c}_{c}"]), 0.0))
                error = truth[step][c] - float(p[f"mean_{c}"])
                if c in ("theta", "heading"):
                    error = math.remainder(error, 2 * math.pi)
                inside = abs(error) <= z * sd
                within[c] += inside
                every &= inside
            joint += every
        if steps == 0:
            continue
        product = math.prod(within[c] / steps for c in names)
        shares = ", ".join(f"{c} {within[c] / steps:.3f}" for c in names)
        n_eff = effective_steps(covered_series) if covered_series else float("nan")
        print(f"{key}\t{steps}\t{covered / steps:.3f}\t{n_eff:.0f}\t{math.sqrt(0.25 / n_eff):.3f}\t"
              f"{joint / steps:.3f}\t{product:.3f}\t{expected:.3f}\t{shares}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
