"""The module under threads, Ctrl-C and odd input: objects shared by threads
take turns, a long step stops at Ctrl-C, overlapping sweeps give Ctrl-C back,
and what cannot be read is refused with ValueError instead of being stored as
something else."""

import math
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import icpbench


def _python(script, timeout=120):
    """Runs script in a fresh interpreter (a crash must not take pytest with it)."""
    return subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=timeout)


def test_threads_sharing_an_estimator_and_a_problem_take_turns():
    # Four threads stepping one estimator corrupted its heap: abort, exit 134.
    done = _python("""
import icpbench, threading
problem = icpbench.problem("car-track", seed=1, steps=400, w=10)
estimator = icpbench.estimator("hc4", seed=1)
count = [0]
def work():
    for step in problem:  # the threads share the iterator too
        assert estimator.step(step).kind == "box"
        count[0] += 1
threads = [threading.Thread(target=work) for _ in range(4)]
[t.start() for t in threads]
[t.join() for t in threads]
print("stepped", count[0])
""")
    assert done.returncode == 0, done.stderr[-2000:]
    assert "stepped 400" in done.stdout


def test_a_long_step_stops_at_ctrl_c():
    estimator = icpbench.estimator("q-relaxed", mode="pave", epsilon=1e-6, max_boxes=2_000_000_000,
                                   q=60, auto_q=False)
    step = next(icpbench.problem("line-intersection", seed=1, lines=600, outliers=30))
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        estimator.step(step)
    assert time.monotonic() - start < 5


def test_ctrl_c_works_after_sweeps_overlapping_in_threads(tmp_path):
    # The second sweep saved the first's handler and put it back last: Ctrl-C
    # then never raised KeyboardInterrupt again in that process.
    done = _python(f"""
import icpbench, signal, threading, time
def spec(steps):
    return {{"name": "overlap", "seeds": [1], "experiments": [{{"name": "e", "algorithms": ["hc4"],
            "problems": [{{"name": "car-track", "params": {{"w": 5, "steps": steps}}}}]}}]}}
first = threading.Thread(target=icpbench.run, args=(spec(3000), {str(tmp_path / "a")!r}))
first.start()
time.sleep(0.2)
icpbench.run(spec(10000), {str(tmp_path / "b")!r})  # the first ends while this runs
first.join()
try:
    signal.raise_signal(signal.SIGINT)
    time.sleep(1)
    print("no KeyboardInterrupt")
except KeyboardInterrupt:
    print("KeyboardInterrupt")
""")
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.strip().endswith("KeyboardInterrupt") and "no " not in done.stdout


def test_an_estimator_refuses_a_step_of_another_problem():
    # Its window carried seed 1's boxes into seed 2's step: an empty box,
    # judged "not contained", read as an unsound HC4.
    first = list(icpbench.problem("car-track", seed=1, steps=4, w=3))
    other = list(icpbench.problem("car-track", seed=2, steps=4, w=3))
    estimator = icpbench.estimator("hc4")
    estimator.step(first[0])
    with pytest.raises(ValueError, match="another icpbench.problem"):
        estimator.step(other[1])
    assert estimator.step(first[1]).contained  # its own stream goes on


def test_a_python_estimators_box_with_no_real_number_in_a_component_is_refused():
    class Overflowed:
        def step(self, view):
            lo, hi = view.newest_state(*view.contract(*view.csp_domains))
            lo[0] = hi[0] = math.inf  # was read as "no solution" for the whole box
            return lo, hi

    icpbench.register_algorithm("overflowed", Overflowed)
    step = next(icpbench.problem("car-track", seed=1, steps=2, w=3))
    with pytest.raises(ValueError, match="infinite point"):
        icpbench.estimator("overflowed").step(step)


def test_numpy_properties_are_numbers_and_other_values_are_refused():
    unset = object()

    class Counting:
        def __init__(self):
            self.value = unset

        def step(self, view):
            return view.newest_state(*view.contract(*view.csp_domains))

        def properties(self):
            return {"count": np.int64(3), "flag": np.bool_(True), "share": np.float32(0.5),
                    **({} if self.value is unset else {"other": self.value})}

    icpbench.register_algorithm("counting", Counting)
    step = next(icpbench.problem("car-track", seed=1, steps=2, w=3))
    properties = icpbench.estimator("counting").step(step).properties
    assert (properties["count"], properties["flag"], properties["share"]) == (3, 1, 0.5)
    assert all(type(properties[k]) in (int, float) for k in ("count", "flag", "share"))
    for value in (None, [1, 2], 2**70):
        Counting.__init__ = lambda self, v=value: setattr(self, "value", v)
        with pytest.raises(ValueError, match="other"):
            icpbench.estimator("counting").step(step)


def test_numpy_seeds_and_parameters_are_python_ones():
    class Numpy2Float(float):  # NumPy 2's repr: np.float64(0.01)
        def __repr__(self):
            return f"np.float64({float(self)!r})"

    step = next(icpbench.problem("car-track", seed=np.int64(3), steps=2, w=3))
    ours = icpbench.estimator("hc4", seed=np.uint64(3), ratio=Numpy2Float(0.01)).step(step)
    assert ours.values == icpbench.estimator("hc4", seed=3, ratio=0.01).step(step).values


@pytest.mark.parametrize("call,message", [
    (lambda: icpbench.register_algorithm("none", None), "register a class"),
    (lambda: icpbench.solve("x", algorithm=None), "algorithm"),
    (lambda: icpbench.solve("x", repeat=1.5), "repeat"),
    (lambda: icpbench.solve("x", timeout=None), "timeout"),
    (lambda: icpbench.run({}, out="", jobs=1), "empty path"),
    (lambda: icpbench.run({}, out="x", jobs=2**40), "jobs"),
])
def test_arguments_of_the_wrong_kind_are_value_errors(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_contract_refuses_a_windows_carry():
    view = next(icpbench.problem("car-track", seed=1, steps=2, w=3)).view
    with pytest.raises(ValueError, match="carry"):
        view.contract(*view.csp_domains, params={"carry": "none"})


def test_a_property_named_like_an_annotation_is_refused():
    # The store keeps one value per name: the problem's annotation replaced it.
    class Clashing:
        def step(self, view):
            return view.newest_state(*view.contract(*view.csp_domains))

        def properties(self):
            return {"gps_x_lo": 1.0}

    icpbench.register_algorithm("clashing", Clashing)
    step = next(icpbench.problem("car-track", seed=1, steps=2, w=3))
    assert "gps_x_lo" in step.annotations
    with pytest.raises(icpbench.InvalidResult, match="annotations: rename it"):
        icpbench.estimator("clashing").step(step)


def test_an_empty_estimates_centre_has_a_nan_per_component():
    class Nothing:
        def step(self, view):
            return None

    icpbench.register_algorithm("nothing", Nothing)
    estimate = icpbench.estimator("nothing").step(next(icpbench.problem("car-track", seed=1, steps=2, w=3)))
    assert estimate.status == "empty"
    assert len(estimate.centre) == len(estimate.lo) == 3 and np.isnan(estimate.centre).all()
