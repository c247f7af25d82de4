"""Estimators written in Python, run by icpbench.run in worker processes
beside the C++ ones: the same boxes as the C++ algorithm they wrap, their
parameters checked like a plugin's, and one that raises recorded as failed
while the others finish."""

import math

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
    # A str parameter's choices are checked when the sweep is planned (every
    # run failed in its worker), and listed as a C++ plugin's are.
    with pytest.raises(ValueError, match=r"kind = sometimes: must be one of nan\|crossed"):
        icpbench.run(_spec({"name": "broken-bounds-python", "params": {"kind": "sometimes"}}),
                     out=tmp_path)
    kind = [p for p in listed["broken-bounds-python"]["params"] if p["name"] == "kind"][0]
    assert kind["range"] == "one of nan|crossed"
    for bad in ("abc", ["a", 1], [], ["a|b"]):
        with pytest.raises(ValueError, match="choices must be a list"):
            icpbench.register_algorithm("bad-choices", Raises, params={"m": ("a", "", bad)})


def test_a_python_estimator_steps_by_hand_too():
    # The same object outside a sweep, fed by hand.
    estimator = HC4InPython(0.001, 0)
    problem = icpbench.problem("car-track", seed=2, w=5, steps=3)
    hc4 = icpbench.estimator("hc4", seed=2, carry="none")
    for step in problem:
        lo, hi = estimator.step(step.view)
        theirs = hc4.step(step)
        assert list(lo) == list(theirs.lo) and list(hi) == list(theirs.hi)


class NearestOfItsType:
    """A toy association rule on paper 002's landmark-observation view: the
    odometry's prediction, then each return given the landmark of its type
    nearest its world position, kept when its sighting leaves the box
    non-empty."""

    def __init__(self):
        self.pose, self.matched = None, []

    def step(self, view):
        lo, hi = view.observation_prior
        if self.pose is not None and view.odometry is not None:
            lo, hi = self._predict(*self.pose, view.odometry)
        returns, landmarks = view.returns, view.landmark_map
        self.matched = []
        for i, kind in enumerate(returns["type"]):
            rng = (returns["range"][0][i] + returns["range"][1][i]) / 2
            bearing = (returns["bearing"][0][i] + returns["bearing"][1][i]) / 2
            theta = (lo[2] + hi[2]) / 2
            wx = (lo[0] + hi[0]) / 2 + rng * math.cos(theta + bearing)
            wy = (lo[1] + hi[1]) / 2 + rng * math.sin(theta + bearing)
            same = [j for j in range(len(landmarks["id"])) if landmarks["type"][j] == kind]
            best = min(same, key=lambda j: (landmarks["x"][j] - wx) ** 2 + (landmarks["y"][j] - wy) ** 2)
            nlo, nhi = view.contract_sighting(i, int(landmarks["id"][best]), lo, hi)
            if all(a <= b for a, b in zip(nlo, nhi)):
                lo, hi = nlo, nhi
                self.matched.append(int(landmarks["id"][best]))
            else:
                self.matched.append(-1)
        self.pose = (lo, hi)
        return lo, hi

    def associations(self):
        return self.matched

    @staticmethod
    def _predict(lo, hi, odometry):
        # Eq. 5-7 by corners: a sketch, widened so that it stays an enclosure.
        d_lo, d_hi = odometry["distance"]
        t_lo, t_hi = odometry["turn"]
        xs, ys, ts = [], [], []
        for theta in (lo[2], hi[2]):
            for d in (d_lo, d_hi):
                for t in (t_lo, t_hi):
                    xs.append(d * math.cos(theta + t / 2))
                    ys.append(d * math.sin(theta + t / 2))
                    ts.append(theta + t)
        pad = 1e-3 + 0.05 * (hi[2] - lo[2])
        return ([lo[0] + min(xs) - pad, lo[1] + min(ys) - pad, min(ts) - pad],
                [hi[0] + max(xs) + pad, hi[1] + max(ys) + pad, max(ts) + pad])


icpbench.register_algorithm("nearest-python", NearestOfItsType, needs="landmark-observations")


def test_a_python_association_rule_on_paper_002s_view_is_scored(tmp_path):
    spec = {"name": "python-association", "seeds": [1], "experiments": [
        {"name": "indoor", "algorithms": ["nearest-python", "landmark-tracking"],
         "problems": [{"name": "indoor-landmarks", "params": {"steps": 12, "spurious_rate": 0}}]}]}
    summary = icpbench.run(spec, out=tmp_path, jobs=2)
    assert summary["ok"] == 2
    with icpbench.open(tmp_path) as store:
        runs = store.runs().set_index("algorithm")
        props = store.step_properties(int(runs.loc["nearest-python", "id"]))
    right = props[props["name"] == "associations_right"]["value"].astype(int)
    assert len(right) == 12 and right.sum() > 12  # several landmarks a step, mostly right


def test_the_landmark_observation_view_from_python():
    steps = list(icpbench.problem("indoor-landmarks", seed=2, steps=3))
    first, second = steps[0].view, steps[1].view
    assert "landmark-observations" in first.offers
    assert first.odometry is None and second.odometry is not None
    lo, hi = second.odometry["distance"]
    assert lo < 0.30 < hi
    assert first.type_names == ["corner", "edge", "other"]
    returns = first.returns
    assert len(returns["type"]) > 3 and all((returns["range"][0] < returns["range"][1]))
    lo, hi = first.observation_prior
    with pytest.raises(ValueError, match="no landmark 999"):
        first.contract_sighting(0, 999, lo, hi)
    with pytest.raises(IndexError):
        first.contract_sighting(len(returns["type"]), 0, lo, hi)


class BrokenBounds:
    """Returns a NaN bound, or a lower bound above the upper one: not an empty estimate."""

    def __init__(self, kind, seed):
        self.kind = kind

    def step(self, view):
        lo, hi = view.newest_state(*view.csp_domains)
        lo, hi = list(lo), list(hi)
        if self.kind == "nan":
            lo[1] = math.nan
        else:
            lo[0], hi[0] = hi[0], lo[0]
        return lo, hi


icpbench.register_algorithm("broken-bounds-python", BrokenBounds,
                            params={"kind": ("nan", "nan or crossed", ["nan", "crossed"])})


def test_nan_or_crossed_bounds_fail_the_run_instead_of_reading_as_empty(tmp_path):
    summary = icpbench.run(_spec({"name": "broken-bounds-python", "params": {"kind": ["nan", "crossed"]}}),
                           out=tmp_path)
    assert (summary["ok"], summary["failed"]) == (0, 2)
    with icpbench.open(tmp_path) as store:
        for reason in store.runs()["reason"]:
            assert "step() returned lo" in reason and "NaN or lo > hi" in reason, reason
            assert "an empty box is None, or lo +inf and hi -inf throughout" in reason, reason


def test_a_registration_that_would_fail_every_run_is_refused_and_leaves_no_trace():
    def fresh(step=True, init=lambda self, n=1: None):
        body = {"__init__": init}
        if step:
            body["step"] = lambda self, view: None
        return type("Fresh", (), body)

    cases = [
        ("py-big", fresh(), {"params": {"n": 2**40}}, "n"),
        ("Upper-Case", fresh(), {}, "not a valid name"),
        ("a,b", fresh(), {}, "not a valid name"),
        ("py-bad-param", fresh(init=lambda self, **kw: None), {"params": {"bad name": 1}}, "not a valid name"),
        ("py-seed", fresh(init=lambda self, seed=0: None), {"params": {"seed": 1}}, "reserved"),
        ("py-no-step", fresh(step=False), {}, "no step"),
        ("py-no-such", fresh(), {"params": {"m": 1}}, "takes no parameter 'm'"),
        ("py-choice", fresh(init=lambda self, mode="zz": None),
         {"params": {"mode": ("zz", "d", ["a", "b"])}}, "not one of its choices"),
    ]
    for name, cls, kwargs, message in cases:
        with pytest.raises(ValueError, match=message):
            icpbench.register_algorithm(name, cls, **kwargs)
        assert name not in {a["name"] for a in icpbench.algorithms()}
    # A failed attempt leaves the name free.
    icpbench.register_algorithm("py-big", fresh(), params={"n": 2})
    assert "py-big" in {a["name"] for a in icpbench.algorithms()}


def _versioned(version, needs_csp=True):
    # The same class name twice, as a notebook cell run again defines it.
    class Edited:
        def step(self, view):
            lo, hi = view.csp_domains
            return view.newest_state(lo, hi)

        def properties(self):
            return {"version": version}
    return Edited


def test_a_class_redefined_under_its_name_replaces_the_old_one(tmp_path):
    icpbench.register_algorithm("edited-python", _versioned(1), description="first")
    icpbench.register_algorithm("edited-python", _versioned(2), description="second")  # the cell run again
    assert icpbench.run(_spec("edited-python"), out=tmp_path)["ok"] == 1
    with icpbench.open(tmp_path) as store:
        props = store.step_properties(int(store.runs().iloc[0]["id"]))
    assert set(props[props["name"] == "version"]["value"]) == {2}
    # Its view stays: another `needs` is refused, and the last definition kept.
    with pytest.raises(ValueError, match="another needs"):
        icpbench.register_algorithm("edited-python", _versioned(3), needs="measurement-set")
    # A redefinition that fails its checks leaves the previous one.
    with pytest.raises(ValueError, match="choices|one of"):
        icpbench.register_algorithm("edited-python", _versioned(4),
                                    params={"mode": ("x", "a mode", ["a", "b"])})
    listed = {a["name"]: a for a in icpbench.algorithms()}["edited-python"]
    assert [p["name"] for p in listed["params"]] == ["python"]
    assert listed["description"] == "second"  # it kept the first


def test_an_estimator_made_before_many_registrations_still_steps():
    # The registry grew by reallocating: an estimator made before kept a
    # pointer into freed memory (its needs read '?').
    est = icpbench.estimator("hc4", seed=1)
    step = next(icpbench.problem("car-track", seed=1, w=5, steps=3))
    for i in range(40):
        grown = type(f"Grown{i}", (_versioned(i),), {})  # a class of its own name
        icpbench.register_algorithm(f"grown-registry-{i}", grown)
    _ = [bytearray(200) for _ in range(20000)]  # reuse what was freed
    assert est.needs == "csp"
    assert len(est.step(step).values) == 3


def test_an_empty_contraction_passed_on_is_an_empty_estimate(tmp_path):
    # view.contract writes an empty box as lo +inf, hi -inf; passing it on
    # (docs/python.md's example) failed the run as 'lo > hi'.
    spec = {"name": "python-empty", "seeds": [1], "experiments": [
        {"name": "lines", "algorithms": ["hc4", "hc4-python"],
         "problems": [{"name": "line-intersection", "params": {"lines": 10, "outliers": 3}}]}]}
    assert icpbench.run(spec, out=tmp_path)["ok"] == 2
    with icpbench.open(tmp_path) as store:
        statuses = store.query("SELECT r.algorithm, s.status FROM steps s JOIN runs r ON r.id = s.run_id")
    assert sorted(statuses["algorithm"]) == ["hc4", "hc4-python"]
    assert set(statuses["status"]) == {"empty"}


def test_contains_reads_a_heading_modulo_two_pi_as_contained_does():
    step = next(icpbench.problem("car-track", seed=1, w=5, steps=3))
    estimate = icpbench.estimator("hc4", seed=1).step(step)
    truth = list(step.truth)
    assert estimate.contained and estimate.contains(truth)
    truth[2] += 2 * math.pi
    assert estimate.contains(truth)
    truth[0] += 1e6
    assert not estimate.contains(truth)


class Interrupted:
    def step(self, view):
        raise KeyboardInterrupt


icpbench.register_algorithm("interrupted-python", Interrupted)


def test_ctrl_c_in_a_python_estimator_stepped_by_hand_stays_ctrl_c():
    # It came out as ValueError: a notebook loop catching ValueError went on.
    step = next(icpbench.problem("car-track", seed=1, w=5, steps=3))
    with pytest.raises(KeyboardInterrupt):
        icpbench.estimator("interrupted-python", seed=1).step(step)


class Unbounded:
    def __init__(self, limit):
        self.limit = limit

    def step(self, view):
        return view.newest_state(*view.csp_domains)


def test_a_float_parameter_may_default_to_inf_but_not_nan():
    icpbench.register_algorithm("unbounded-python", Unbounded, params={"limit": (math.inf, "a bound")})
    limit = [p for p in {a["name"]: a for a in icpbench.algorithms()}["unbounded-python"]["params"]
             if p["name"] == "limit"][0]
    assert limit["default"] == "+oo"  # as the command line lists an infinite default
    step = next(icpbench.problem("car-track", seed=1, w=5, steps=2))
    assert icpbench.estimator("unbounded-python", seed=1, limit=2.5).step(step).contained
    with pytest.raises(ValueError, match="NaN"):
        icpbench.register_algorithm("nan-python", Unbounded, params={"limit": (math.nan, "")})


def test_a_malformed_parameter_declaration_says_how_to_declare():
    with pytest.raises(ValueError, match=r"\(default, doc\)"):
        icpbench.register_algorithm("one-tuple-python", Unbounded, params={"limit": (1.0,)})
    with pytest.raises(ValueError, match="must be a dict"):
        icpbench.register_algorithm("list-python", Unbounded, params=[("limit", 1.0)])
