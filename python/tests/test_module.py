"""The module against the command line: same registries, same solve results
bit for bit, the same boxes stepping by hand as `icpbench run`, sweeps that
resume, and the command line's messages on bad input."""

import concurrent.futures
import glob
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import icpbench


def test_registries_are_the_command_lines(cli):
    # Estimators registered from Python (test_python_estimators.py) come after.
    theirs = cli.json("list", "algorithms", "--format", "json")
    ours = icpbench.algorithms()
    assert ours[:len(theirs)] == theirs
    assert all(any(p["name"] == "python" for p in a["params"]) for a in ours[len(theirs):])
    assert icpbench.problems() == cli.json("list", "problems", "--format", "json")


def _cli_box(box):
    return {name: (-math.inf if lo is None else lo, math.inf if hi is None else hi)
            for name, (lo, hi) in box.items()}


@pytest.mark.parametrize("algorithm", ["hc4", "bc4", "3b-bc4"])
def test_solve_equals_the_command_line_bit_for_bit(cli, source_dir, algorithm):
    files = sorted(glob.glob(os.path.join(source_dir, "examples", "*.bch")))
    assert files, "no example Minibex files"
    for path in files:
        ours = icpbench.solve(path, algorithm=algorithm)
        theirs = cli.json("solve", path, "--algorithm", algorithm, "--format", "json")
        assert ours["status"] == theirs["status"], path
        assert ours["box"] == _cli_box(theirs["box"]), path  # == on floats: bit for bit
        if ours["status"] == "nonempty":
            assert list(ours["lo"]) == [ours["box"][n][0] for n in ours["variables"]]
            assert list(ours["hi"]) == [ours["box"][n][1] for n in ours["variables"]]


def test_solve_takes_text_and_a_relaxed_solvers_fields(cli, tmp_path):
    text = ("Variables x in [-10, 10]; y in [-10, 10];\n"
            "Constraints x + y = 2; x - y = 0; x = 1; y = 5; end")
    path = tmp_path / "lines.bch"
    path.write_text(text)
    ours = icpbench.solve(text, algorithm="q-relaxed", q=1)
    theirs = cli.json("solve", str(path), "--algorithm", "q-relaxed", "--param", "q=1",
                      "--format", "json")
    assert ours["q"] == theirs["q"] == 1
    assert ours["box"] == _cli_box(theirs["box"])
    assert ours["estimate"] == theirs["estimate"]
    assert ours["lo"][0] <= 1 <= ours["hi"][0]


def test_bad_input_raises_value_error_with_the_command_lines_message(cli, source_dir):
    path = os.path.join(source_dir, "examples", "paper002_sum.bch")
    with pytest.raises(ValueError) as error:
        icpbench.solve(path, algorithm="hc4", ratio=-1)
    theirs = cli("solve", path, "--algorithm", "hc4", "--param", "ratio=-1", check=False)
    assert theirs.returncode == 2
    assert str(error.value) in theirs.stderr
    with pytest.raises(ValueError, match="unknown algorithm|no algorithm"):
        icpbench.estimator("no-such-algorithm")
    with pytest.raises(ValueError):
        icpbench.solve("Variables x in [0, 1]; Constraints x = ; end")


def _car_spec(steps=12):
    return {"name": "python-test", "seeds": [3], "experiments": [
        {"name": "window", "algorithms": ["hc4"],
         "problems": [{"name": "car-track", "params": {"w": 5, "steps": steps}}]}]}


def test_stepping_by_hand_gives_the_boxes_of_icpbench_run(tmp_path):
    summary = icpbench.run(_car_spec(), out=tmp_path)
    assert summary["ok"] == 1
    with icpbench.open(tmp_path) as store:
        run_id = int(store.runs()["id"][0])
        stored = store.step_values(run_id)
    estimator = icpbench.estimator("hc4", seed=3)
    steps = 0
    for step in icpbench.problem("car-track", seed=3, w=5, steps=12):
        estimate = estimator.step(step)
        assert estimate.contained
        rows = stored[stored["step"] == step.index]
        for _, row in rows.iterrows():
            assert estimate.values[row["var"]] == (row["lo"], row["hi"]), (step.index, row["var"])
        steps += 1
    assert steps == 12 and len(stored) == 12 * 3


def test_a_sweep_from_a_dict_resumes(tmp_path):
    first = icpbench.run(_car_spec(5), out=tmp_path)
    assert (first["planned"], first["ok"], first["already_stored"]) == (1, 1, 0)
    again = icpbench.run(_car_spec(5), out=tmp_path)
    assert (again["planned"], again["ok"], again["already_stored"]) == (1, 0, 1)


def test_a_bad_seed_raises_value_error():
    for seed in (-1, 2**64, 1.5, float("nan"), True, "1"):
        with pytest.raises(ValueError, match="not a non-negative integer"):
            icpbench.problem("chain", seed=seed)
        with pytest.raises(ValueError, match="not a non-negative integer"):
            icpbench.estimator("hc4", seed=seed)
    assert next(iter(icpbench.problem("chain", seed=2**64 - 1))).index == 0


def test_a_bad_spec_raises_value_error(tmp_path):
    spec = _car_spec()
    spec["experiments"][0]["algorithms"] = ["no-such-algorithm"]
    with pytest.raises(ValueError, match="no-such-algorithm"):
        icpbench.run(spec, out=tmp_path)
    with pytest.raises(ValueError, match="results store"):
        icpbench.open(tmp_path / "nothing-here")


def test_estimates_of_each_kind_expose_their_data():
    step = next(iter(icpbench.problem("line-intersection", seed=1, lines=20, outliers=7)))
    paving = icpbench.estimator("q-relaxed", mode="pave", epsilon=0.5).step(step)
    assert paving.kind == "paving"
    boxes = paving.boxes["boundary"]
    assert boxes.ndim == 3 and boxes.shape[2] == 2 and np.all(boxes[:, :, 0] <= boxes[:, :, 1])
    accumulator = icpbench.estimator("accumulator").step(step)
    assert accumulator.kind == "accumulator" and accumulator.counts.ndim == 2
    assert accumulator.counts.max() == accumulator.properties["max_count"]
    marina = next(iter(icpbench.problem("marina-sonar", seed=1, steps=1)))
    cloud = icpbench.estimator("particle-filter", seed=1).step(marina)
    assert cloud.particles.shape[0] == cloud.weights.shape[0] > 0
    assert math.isclose(cloud.weights.sum(), 1.0, rel_tol=1e-9)


def test_the_example_script_runs(source_dir, tmp_path):
    script = os.path.join(source_dir, "examples", "python", "sweep_and_plot.py")
    done = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True, text=True,
                          env={**os.environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "mean_area.png").stat().st_size > 0


def test_solving_again_reuses_nothing_stale(cli, tmp_path):
    # solve() keeps what it parsed and built per file, algorithm and parameters:
    # a second call gives the same box, a changed file or parameter a new one.
    path = tmp_path / "sum.bch"
    path.write_text("Variables x1 in [1, 4]; x2 in [1, 2]; x3 in [5, 7];\n"
                    "Constraints x3 = x1 + x2; end")
    first = icpbench.solve(path, algorithm="bc4")
    assert icpbench.solve(path, algorithm="bc4")["box"] == first["box"]
    assert first["box"]["x1"] == (3.0, 4.0)
    path.write_text("Variables x1 in [1, 4]; x2 in [1, 2]; x3 in [5, 5.5];\n"
                    "Constraints x3 = x1 + x2; end")
    changed = icpbench.solve(path, algorithm="bc4")
    theirs = cli.json("solve", str(path), "--algorithm", "bc4", "--format", "json")
    assert changed["box"] == _cli_box(theirs["box"]) and changed["box"]["x3"][1] == 5.5
    coarse = icpbench.solve(path, algorithm="bc4", ratio=0.5)
    theirs = cli.json("solve", str(path), "--algorithm", "bc4", "--param", "ratio=0.5",
                      "--format", "json")
    assert coarse["box"] == _cli_box(theirs["box"])


@pytest.mark.parametrize("out", ["/sys/icpbench-not-here", "/dev/null/icpbench-not-here"])
def test_errors_are_classed_as_the_command_lines_exit_codes(cli, source_dir, out):
    # exit 3 (the environment) is OSError, exit 2 (bad input) is ValueError.
    spec = os.path.join(source_dir, "specs", "tour.yaml")
    theirs = cli("run", spec, "--out", out, check=False)
    expected = {2: ValueError, 3: OSError}[theirs.returncode]
    with pytest.raises(expected) as error:
        icpbench.run(spec, out=out)
    assert type(error.value) is expected
    assert str(error.value).split(" (")[0] in theirs.stderr


def test_solving_text_from_threads_is_safe_and_agrees(source_dir):
    # Each thread gets its own contractor: a cached one is taken out while in use.
    text = open(os.path.join(source_dir, "examples", "car_window.bch")).read()
    path = os.path.join(source_dir, "examples", "car_window.bch")
    alone = icpbench.solve(path)["box"]

    def solve_many(k):
        return [icpbench.solve(text if i % 2 else path)["box"] for i in range(40)]

    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        for boxes in pool.map(solve_many, range(4)):
            assert all(box == alone for box in boxes)


def test_errors_in_text_name_the_text_not_a_temporary_file():
    with pytest.raises(ValueError, match=r"^<minibex text>:1:"):
        icpbench.solve("Variables x in [0, 1]; Constraints x + = 1; end")


def test_a_state_of_the_wrong_length_is_refused():
    step = next(iter(icpbench.problem("car-track", seed=1, w=3, steps=1)))
    for state in ([], [0.0], [1e9] * 10):
        with pytest.raises(ValueError, match="a state needs 3 components"):
            step.view.log_likelihood(state)


def test_an_open_store_sees_a_later_sweep_and_refuses_bad_queries(tmp_path):
    icpbench.run(_car_spec(3), out=tmp_path)
    with icpbench.open(tmp_path) as store:
        assert len(store.runs()) == 1
        spec = _car_spec(3)
        spec["experiments"][0]["algorithms"].append("bc4")
        icpbench.run(spec, out=tmp_path)
        assert len(store.runs()) == 2
        with pytest.raises(ValueError, match="no such table"):
            store.query("SELECT * FROM no_such_table")
        with pytest.raises(ValueError, match="not a SELECT"):
            store.query("")
        attached = tmp_path / "attached.sqlite"
        with pytest.raises(ValueError, match="not authorized"):
            store.query(f"ATTACH DATABASE '{attached}' AS other")
        assert not attached.exists()
        # A refused write leaves no transaction behind: later sweeps still show.
        with pytest.raises(ValueError):
            store.query("DELETE FROM runs")
        spec["experiments"][0]["algorithms"].append("hc3")
        icpbench.run(spec, out=tmp_path)
        assert len(store.runs()) == 3


def test_a_step_limit_and_a_point_are_checked_as_solves_are():
    step = next(iter(icpbench.problem("car-track", seed=1, w=3, steps=1)))
    estimator = icpbench.estimator("hc4")
    for bad in (-1, 0, math.nan):
        with pytest.raises(ValueError, match="must be a number of seconds > 0"):
            estimator.step(step, timeout_s=bad)
    estimate = estimator.step(step)
    assert estimate.contains(step.truth)
    with pytest.raises(ValueError, match="a point needs 3 components, got 1"):
        estimate.contains([1.0])


def test_a_file_replaced_with_the_same_size_and_time_is_solved_anew(tmp_path):
    # The cache was keyed by path, size and time: cp -p of another system of
    # the same size gave the old box.
    path = tmp_path / "replaced.bch"
    path.write_text("Variables x in [0, 10]; Constraints x >= 7; end")
    stat = os.stat(path)
    assert icpbench.solve(path)["box"]["x"] == (7.0, 10.0)
    path.write_text("Variables x in [0, 10]; Constraints x <= 3; end")
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert icpbench.solve(path)["box"]["x"] == (0.0, 3.0)


def test_a_path_is_a_path_whatever_its_name(tmp_path, monkeypatch):
    path = tmp_path / "Variables.bch"
    path.write_text("Variables x in [0, 10]; Constraints x <= 3; end")
    assert icpbench.solve(path)["box"]["x"] == (0.0, 3.0)
    assert icpbench.solve(str(path))["box"]["x"] == (0.0, 3.0)
    monkeypatch.chdir(tmp_path)
    assert icpbench.solve("Variables.bch")["box"]["x"] == (0.0, 3.0)


def test_a_sweep_runs_without_a_stderr(tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "stderr", None)
    assert icpbench.run(_car_spec(3), out=tmp_path)["ok"] == 1


def test_a_store_is_read_from_other_threads(tmp_path):
    # sqlite3 refused a connection made in another thread: a thread pool or a
    # widget's callback got "SQLite objects created in a thread ..." as a bad query.
    from concurrent.futures import ThreadPoolExecutor
    icpbench.run(_car_spec(3), out=tmp_path)
    with icpbench.open(tmp_path) as store:
        expected = len(store.steps())
        with ThreadPoolExecutor(max_workers=4) as pool:
            counts = list(pool.map(lambda _: len(store.steps()) + len(store.runs()), range(40)))
    assert counts == [expected + 1] * 40


def test_a_version_one_store_has_no_properties_rather_than_an_error(tmp_path):
    import sqlite3
    icpbench.run(_car_spec(3), out=tmp_path)
    with sqlite3.connect(tmp_path / "results.sqlite") as c:
        c.executescript("DROP TABLE step_properties; DROP TABLE run_properties; "
                        "UPDATE meta SET value = '1' WHERE key = 'schema_version'")
    with icpbench.open(tmp_path) as store:
        assert store.schema_version == 1 and len(store.runs()) == 1
        assert len(store.step_properties()) == 0 and "step" in store.step_properties().columns
        assert len(store.run_properties(1)) == 0


def test_ctrl_c_stops_a_long_solve():
    # It was honoured only when the C++ call returned (10-15 s here).
    import signal
    import threading
    import time
    n = 60
    text = "\n".join(["Variables"] + [f" x{i} in [-10,10];" for i in range(n)] + ["Constraints"]
                     + [f" x{i}^2 + x{i+1}^2 = 2 + 0.0001*x{i}*x{i+1};" for i in range(n - 1)]
                     + [f" x0 + x{n - 1} = 0.1;", "end"]) + "\n"
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        icpbench.solve(text, algorithm="3b-bc4", ratio=0, repeat=100000)
    assert time.monotonic() - start < 5
    # The system solves again afterwards.
    assert icpbench.solve(text, algorithm="hc4")["status"] == "nonempty"


@pytest.mark.parametrize("work", ["solve", "python-estimator", "run"])
def test_exiting_with_a_daemon_thread_inside_icpbench_is_clean(source_dir, tmp_path, work):
    # The thread retook the GIL as Python finalized: "terminate called
    # without an active exception", exit 134 (or 139 with a Python estimator).
    script = f"""
import icpbench, threading, time
window = {os.path.join(source_dir, "examples", "car_window.bch")!r}
class Slow:
    def step(self, view):
        time.sleep(0.01)
        return view.newest_state(*view.contract(*view.csp_domains))
icpbench.register_algorithm("slow-exit", Slow)
steps = list(icpbench.problem("car-track", seed=1, steps=200, w=5))
sweep = {{"name": "long", "seeds": list(range(1, 41)), "experiments": [{{"name": "e",
         "algorithms": ["3b-bc4"], "problems": [{{"name": "car-track", "params": {{"w": 20, "steps": 2000}}}}]}}]}}
def loop():
    while True:
        if {work!r} == "solve":
            icpbench.solve(window, algorithm="3b-bc4", repeat=50)
        elif {work!r} == "run":  # minutes of runs: the exit stops the sweep
            icpbench.run(sweep, out={str(tmp_path)!r})
        else:
            estimator = icpbench.estimator("slow-exit")
            for s in steps:
                estimator.step(s)
threading.Thread(target=loop, daemon=True).start()
time.sleep(0.3)
print("main thread done")
"""
    import time
    for _ in range(3 if work != "run" else 1):
        start = time.monotonic()
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr[-2000:]
        assert time.monotonic() - start < 30
        assert "main thread done" in done.stdout
        assert "terminate called" not in done.stderr


@pytest.mark.parametrize("algorithm,problem,params", [
    ("q-relaxed", "line-intersection", {"lines": 10, "outliers": 2}),
    ("landmark-tracking", "indoor-landmarks", {"steps": 4}),
    ("particle-filter", "car-track", {"w": 5, "steps": 4}),
])
def test_stepping_by_hand_judges_each_step_as_icpbench_run(tmp_path, algorithm, problem, params):
    # By hand, the guarantee, coverage and association properties were missing.
    spec = {"name": "by-hand", "seeds": [2], "experiments": [
        {"name": "e", "algorithms": [algorithm], "problems": [{"name": problem, "params": params}]}]}
    assert icpbench.run(spec, out=tmp_path)["ok"] == 1
    with icpbench.open(tmp_path) as store:
        run_id = int(store.runs()["id"][0])
        stored = store.step_properties(run_id)
        stored_run = store.run_properties(run_id)
    estimator = icpbench.estimator(algorithm, seed=2)
    for step in icpbench.problem(problem, seed=2, **params):
        got = estimator.step(step).properties
        rows = stored[stored["step"] == step.index]
        want = {r["name"]: r["value"] for _, r in rows.iterrows()}
        assert set(got) == set(want), (step.index, set(got) ^ set(want))
        for name, value in want.items():
            if name not in ("time_s", "solve_time_s"):
                assert got[name] == value or (isinstance(value, float) and math.isnan(value)), name
    run_props = estimator.run_properties()
    assert set(run_props) == set(stored_run["name"])


def test_numpy_values_are_parameters_as_python_ones():
    step = next(icpbench.problem("car-track", seed=1, w=np.int64(5), steps=3,
                                 heading_known=np.bool_(True), gps_error=np.float32(2.5)))
    assert step.index == 0


def test_a_spec_dict_may_hold_numpy_values_and_an_empty_one_says_what_it_needs(tmp_path):
    spec = _car_spec(3)
    spec["seeds"] = list(np.arange(3, 4))
    spec["experiments"][0]["problems"][0]["params"]["w"] = np.int64(5)
    assert icpbench.run(spec, out=tmp_path)["ok"] == 1
    with pytest.raises(ValueError, match="a spec needs 'experiments'"):
        icpbench.run({}, out=tmp_path / "empty")
