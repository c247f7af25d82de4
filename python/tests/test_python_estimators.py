"""Estimators written in Python, run by icpbench.run in worker processes
beside the C++ ones: the same boxes as the C++ algorithm they wrap, their
parameters checked like a plugin's, and one that raises recorded as failed
while the others finish."""

import pytest

import icpbench


class HC4InPython:
    """HC4 on each window from its domains (no carry), the newest state's box."""

    def __init__(self, ratio, seed):
        self.ratio, self.steps = ratio, 0

    def step(self, view):
        lo, hi = view.contract(*view.csp_domains, algorithm="hc4", params={"ratio": self.ratio})
        self.steps += 1
        return view.newest_state(lo, hi)

    def properties(self):
        return {"python_steps": self.steps}


class Raises:
    def step(self, view):
        raise ZeroDivisionError("on purpose")


icpbench.register_algorithm("hc4-python", HC4InPython, params={"ratio": (0.001, "HC4's ratio")})
icpbench.register_algorithm("raises-python", Raises)


def _spec(*algorithms):
    return {"name": "python-estimators", "seeds": [2], "experiments": [
        {"name": "window", "algorithms": list(algorithms),
         "problems": [{"name": "car-track", "params": {"w": 5, "steps": 15}}]}]}


def test_a_python_estimator_runs_beside_hc4_with_the_same_boxes(tmp_path):
    summary = icpbench.run(_spec({"name": "hc4", "params": {"carry": "none"}}, "hc4-python",
                                 "raises-python"), out=tmp_path, jobs=2)
    assert (summary["ok"], summary["failed"]) == (2, 1)
    with icpbench.open(tmp_path) as store:
        runs = store.runs().set_index("algorithm")
        assert "ZeroDivisionError: on purpose" in runs.loc["raises-python", "reason"]
        assert '"python":"test_python_estimators.HC4InPython"' in runs.loc["hc4-python", "algorithm_params"]
        values = store.step_values()
        props = store.step_properties(int(runs.loc["hc4-python", "id"]))
    ours = values[values["run_id"] == runs.loc["hc4-python", "id"]][["step", "var", "lo", "hi"]]
    theirs = values[values["run_id"] == runs.loc["hc4", "id"]][["step", "var", "lo", "hi"]]
    assert len(ours) == 15 * 3
    assert ours.reset_index(drop=True).equals(theirs.reset_index(drop=True))
    assert list(props[props["name"] == "python_steps"]["value"]) == list(range(1, 16))


def test_python_parameters_are_checked_like_a_plugins(tmp_path):
    with pytest.raises(ValueError, match="ratio"):
        icpbench.run(_spec({"name": "hc4-python", "params": {"ratio": "often"}}), out=tmp_path)
    with pytest.raises(ValueError, match="unknown|no parameter"):
        icpbench.run(_spec({"name": "hc4-python", "params": {"rate": 1}}), out=tmp_path)
    with pytest.raises(ValueError, match="already registered"):
        icpbench.register_algorithm("hc4-python-again", HC4InPython)
    with pytest.raises(ValueError, match="needs"):
        icpbench.register_algorithm("bad-needs", Raises, needs="pictures")
    listed = {a["name"]: a for a in icpbench.algorithms()}
    assert "hc4-python" in listed


def test_a_python_estimator_steps_by_hand_too():
    # The same object outside a sweep, fed by hand.
    estimator = HC4InPython(0.001, 0)
    problem = icpbench.problem("car-track", seed=2, w=5, steps=3)
    hc4 = icpbench.estimator("hc4", seed=2, carry="none")
    for step in problem:
        lo, hi = estimator.step(step.view)
        theirs = hc4.step(step)
        assert list(lo) == list(theirs.lo) and list(hi) == list(theirs.hi)
