"""icpbench from Python: the same registries, solvers, sweeps and results store
as the command line (docs/python.md).

    import icpbench
    icpbench.solve("examples/paper_example.bxx", algorithm="hc4")["box"]
    for step in icpbench.problem("car-track", seed=1, steps=5): ...
    icpbench.run("specs/tour.yaml", out="results/tour", jobs=2)
    icpbench.open("results/tour").runs()            # a pandas DataFrame

Bad input raises ValueError with the command line's message; the environment
(disk, processes) raises OSError.
"""

import inspect
import json
import math
import numbers
import operator
import os
import tempfile

import numpy as np

from . import _icpbench
from ._icpbench import Estimate, Estimator, InvalidResult, Problem, Step, View
from .store import Store, open  # noqa: A001 (icpbench.open reads a results directory)

__all__ = ["algorithms", "problems", "solve", "problem", "estimator", "run", "open",
           "register_algorithm", "Store", "Step", "View", "Problem", "Estimator", "Estimate",
           "InvalidResult"]


def algorithms():
    """The registered algorithms: the records of `icpbench list algorithms --format json`."""
    return json.loads(_icpbench.list_json("algorithms"))


def problems():
    """The registered problems: the records of `icpbench list problems --format json`."""
    return json.loads(_icpbench.list_json("problems"))


def _looks_like_minibex_text(minibex):
    # A path-like object is a path, whatever its name; text has a newline or
    # starts with a section word (and is then not an existing file).
    if not isinstance(minibex, str):
        return False
    if "\n" in minibex:
        return True
    return minibex.lstrip().startswith(("Variables", "Constants")) and not os.path.isfile(minibex)


def _bounds(pair):
    """A JSON [lo, hi] pair; null stands for an infinite bound."""
    lo, hi = pair
    return (-math.inf if lo is None else float(lo), math.inf if hi is None else float(hi))


def solve(minibex, algorithm="hc4", repeat=1, timeout=math.inf, **params):
    """Contracts (or, for a relaxed solver, solves) a Minibex system.

    minibex: the text of a Minibex system, or the path of a file holding one.
    params: the algorithm's parameters, as `solve --param key=value`.
    Returns the dict of `icpbench solve --format json` with each box's bounds
    as floats (+-inf where the command line writes null), plus `lo` and `hi`:
    the box as NumPy arrays in the variables' order ("variables").
    """
    if not isinstance(algorithm, str):
        raise ValueError(f"algorithm: {algorithm!r} is not an algorithm's name")
    if isinstance(repeat, bool) or not isinstance(repeat, numbers.Integral) or not 1 <= repeat < 2**31:
        raise ValueError(f"repeat: {repeat!r} is not a count of contractions from 1 to 2^31 - 1")
    if isinstance(timeout, bool) or not isinstance(timeout, numbers.Real):
        raise ValueError(f"timeout: {timeout!r} is not a number of seconds")
    is_text = _looks_like_minibex_text(minibex)
    minibex = os.fspath(minibex)
    if is_text:
        with tempfile.NamedTemporaryFile("w", suffix=".bxx", delete=False) as f:
            f.write(minibex)
        try:
            text, names = _icpbench.solve_json(f.name, algorithm, params, repeat, timeout, True)
        except ValueError as e:  # the text's errors, not the temporary file's name
            raise ValueError(str(e).replace(f.name, "<minibex text>")) from None
        finally:
            os.unlink(f.name)
    else:
        text, names = _icpbench.solve_json(minibex, algorithm, params, repeat, timeout)
    result = json.loads(text)

    def box_of(box):
        return {name: _bounds(pair) for name, pair in box.items()}

    result["box"] = box_of(result["box"])
    for by_q in result.get("by_q", []):
        by_q["box"] = box_of(by_q["box"])
    result["variables"] = list(names)
    empty = result["status"] == "empty"
    result["lo"] = np.array([math.inf if empty else result["box"][n][0] for n in names])
    result["hi"] = np.array([-math.inf if empty else result["box"][n][1] for n in names])
    return result


def _seed(seed):
    # The command line's rule for a seed: an integer in [0, 2^64) (NumPy's
    # integers too); bool is not one.
    try:
        value = None if isinstance(seed, (bool, np.bool_)) else operator.index(seed)
    except TypeError:
        value = None
    if value is None or not 0 <= value < 2**64:
        raise ValueError(f"seed: {seed!r} is not a non-negative integer below 2^64")
    return value


def problem(name, seed=0, **params):
    """A problem's steps as an iterator (icpbench.Step: truth, views)."""
    return Problem(name, params, _seed(seed))


def estimator(name, seed=0, **params):
    """An algorithm to feed by hand: `.step(step)` returns an icpbench.Estimate."""
    return Estimator(name, params, _seed(seed))


def run(spec, out, jobs=1, force=False, no_retry=False, name="python"):
    """Runs a sweep as `icpbench run SPEC --out OUT --jobs JOBS` does.

    spec: the path of a spec file, or a dict with the same content (see
    docs/specs.md). Runs already in OUT's store are skipped (a sweep resumes),
    failed ones retried unless no_retry. Progress goes to sys.stderr. Returns
    the sweep's counts: planned, already_stored, ok, failed, timed_out,
    skipped (and interrupted_by, the signal that stopped it or 0, and
    stopped, the runs it stopped in flight); raises KeyboardInterrupt if a
    signal stopped it (finished runs are kept).
    """
    if isinstance(jobs, bool) or not isinstance(jobs, numbers.Integral) or not 1 <= jobs < 2**31:
        raise ValueError(f"jobs: {jobs!r} is not a number of worker processes from 1 to 2^31 - 1")
    if not os.fspath(out):
        raise ValueError("out: an empty path; name the directory the sweep writes into")
    if isinstance(spec, dict):
        summary = _icpbench.run_sweep(json.dumps(spec, default=_json_value), False, name,  # YAML reads JSON
                                      os.fspath(out), jobs, force, no_retry)
    else:
        summary = _icpbench.run_sweep(os.fspath(spec), True, "", os.fspath(out), jobs, force,
                                      no_retry)
    if summary["interrupted_by"]:
        raise KeyboardInterrupt(f"sweep interrupted: {summary['stopped']} runs in flight stopped")
    return summary



_TYPES = {bool: "bool", int: "int", float: "double", str: "string"}


def _json_value(value):
    """NumPy values in a spec dict, as JSON reads them (np.arange seeds, say)."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"a spec holds {type(value).__name__} {value!r}: not a YAML value")


def _declared(name, declaration):
    """A parameter's declaration (default, (default, doc) or (default, doc, choices)) as
    the registry's ParamInfo, and its type."""
    default, doc, choices = declaration, "", None
    if isinstance(declaration, tuple):
        if not 2 <= len(declaration) <= 3:
            raise ValueError(f"parameter '{name}': declare it as default, (default, doc) or "
                             f"(default, doc, [choices]), not a tuple of {len(declaration)}")
        default, doc, *rest = declaration
        choices = rest[0] if rest else None
    if isinstance(default, np.generic):  # np.float64(1.0) declares a float
        default = default.item()
    kind = _TYPES.get(type(default))
    if kind is None:
        raise ValueError(f"parameter '{name}': default {default!r} must be a bool, int, float or str")
    if kind == "bool":
        text = "true" if default else "false"
    elif kind == "double":
        if math.isnan(default):
            raise ValueError(f"parameter '{name}': default NaN is not a value (inf is)")
        text = repr(float(default))
    else:
        text = str(default)
    if kind == "int" and not -2**31 <= default < 2**31:
        raise ValueError(f"parameter '{name}': default {default} is outside the int range "
                         f"[-2147483648, 2147483647] (use a float)")
    if choices is not None and kind != "string":
        raise ValueError(f"parameter '{name}': choices are for str parameters")
    if choices is not None:
        if (isinstance(choices, str) or not all(isinstance(c, str) for c in choices)
                or not choices or any(not c or "|" in c for c in choices)):
            raise ValueError(f"parameter '{name}': choices must be a list of non-empty str "
                             f"without '|', got {choices!r}")
        choices = list(choices)
    if choices is not None and default not in choices:
        raise ValueError(f"parameter '{name}': default {default!r} is not one of its choices {choices}")
    # Written as the registry lists choices ("one of a|b"): a spec is checked
    # before any run, as for a C++ plugin.
    allowed = "one of " + "|".join(choices) if choices is not None else ""
    return _icpbench.ParamInfo(name, kind, text, allowed, doc), kind


def register_algorithm(name, cls, needs="csp", params=None, description=""):
    """Registers an estimator written in Python, to run in sweeps beside the C++ ones.

    cls(**params[, seed=...]) makes the estimator; its step(view) gets an
    icpbench.View and returns the estimate's box over view.names as (lo, hi),
    an object with .lo and .hi, or None for an empty estimate; an optional
    properties() returns a dict stored with the step, and an optional
    associations() the landmark each of the step's returns was matched with
    (-1 for none), scored against the truth. needs: the view it needs,
    "csp", "measurement-set", "probabilistic" or "landmark-observations".
    params: name ->
    default, or (default, doc), or (default, doc, [choices]) for a str; the
    type is the default's (bool, int, float, str), checked like a C++
    plugin's. The runs' parameters include `python`, the class's import path.
    """
    if not inspect.isclass(cls):
        raise ValueError(f"{name}: register a class (whose instances have step(view)), "
                         f"not {type(cls).__name__} {cls!r}")
    if not isinstance(needs, str):
        raise ValueError(f"{name}: needs={needs!r}: must be csp, measurement-set, probabilistic "
                         f"or landmark-observations")
    params = params or {}
    if not isinstance(params, dict):
        raise ValueError(f"{name}: params must be a dict of name -> declaration, "
                         f"not a {type(params).__name__}")
    declared = [_declared(k, v) for k, v in params.items()]
    kinds = {info.name: kind for info, kind in declared}
    # What would fail every run in its worker is refused here.
    if not callable(getattr(cls, "step", None)):
        raise ValueError(f"{name}: {cls.__qualname__} has no step(view) method")
    signature = inspect.signature(cls)
    takes_any = any(p.kind == p.VAR_KEYWORD for p in signature.parameters.values())
    for key in params:
        if not takes_any and key not in signature.parameters:
            raise ValueError(f"{name}: {cls.__qualname__}() takes no parameter '{key}'")
    takes_seed = "seed" in signature.parameters

    def typed(texts):
        values = {}
        # Checked already (the registry's ParamSet, choices included): typed only.
        for key, text in texts.items():
            values[key] = {"bool": lambda t: t == "true", "int": int, "double": float,
                           "string": str}[kinds[key]](text)
        return values

    def factory(texts, seed):
        values = typed(texts)
        return cls(**values, seed=seed) if takes_seed else cls(**values)

    class_path = f"{cls.__module__}.{cls.__qualname__}"
    _icpbench.register_python_algorithm(name, factory, class_path, needs,
                                        [info for info, _ in declared], description)
