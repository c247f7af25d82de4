"""GET /api/runs/ID/steps/N/estimate: the server re-runs a stored run to step
N and sends its estimate; for each kind the data is there, the truth is in
the hull where the store says it is contained, and the re-run reproduces the
stored step's bounds exactly."""
import pytest


def last_step(db, algorithm):
    run = db.execute("SELECT id FROM runs WHERE algorithm = ? AND status = 'ok'", (algorithm,)).fetchone()
    assert run, algorithm
    step = db.execute("SELECT max(step) FROM steps WHERE run_id = ?", (run["id"],)).fetchone()[0]
    return run["id"], step


def check_kind_data(kind, data):
    if kind == "box":
        lo_x, hi_x, lo_y, hi_y = data["box"]
        assert lo_x <= hi_x and lo_y <= hi_y
    elif kind == "paving":
        assert data["inner"] or data["boundary"]
        assert len(data["inner"]) + len(data["boundary"]) == min(
            5000, data["inner_count"] + data["boundary_count"])
        assert data["truncated"] == (data["inner_count"] + data["boundary_count"] > 5000)
    elif kind == "accumulator":
        assert len(data["counts"]) == data["rows"] <= 200
        assert all(len(row) == data["cols"] <= 200 for row in data["counts"])
        assert max(max(row) for row in data["counts"]) >= data["threshold"] > 0
    else:
        assert len(data["x"]) == len(data["y"]) == len(data["weights"]) == min(2000, data["total"])
        assert sum(data["weights"]) > 0


@pytest.mark.parametrize("algorithm, kind", [
    ("hc4", "box"), ("q-relaxed", "paving"), ("accumulator", "accumulator"),
    ("particle-filter", "particles")])
def test_a_steps_estimate_is_re_run_as_stored(kinds_server, kinds_db, algorithm, kind):
    run_id, step = last_step(kinds_db, algorithm)
    got = kinds_server.json(f"/api/runs/{run_id}/steps/{step}/estimate")
    assert (got["run_id"], got["step"], got["kind"]) == (run_id, step, kind)
    stored = kinds_db.execute("SELECT var, lo, hi, truth FROM step_values WHERE run_id = ? AND step = ? "
                              "ORDER BY pos", (run_id, step)).fetchall()
    assert [h["name"] for h in got["hull"]][:len(stored)] == [s["var"] for s in stored]
    assert got["matches_store"] is True
    for h, s in zip(got["hull"], stored):
        assert (h["lo"], h["hi"]) == (s["lo"], s["hi"])
    check_kind_data(kind, got["data"])
    contained = kinds_db.execute("SELECT contained FROM steps WHERE run_id = ? AND step = ?",
                                 (run_id, step)).fetchone()[0]
    assert got["contained"] == contained
    if contained == 1:
        for h, t in zip(got["hull"], got["truth"]):
            if h["name"] != "theta":  # a heading's truth may be another representative
                assert h["lo"] <= t <= h["hi"], (h, t)


def test_bad_estimate_requests_get_a_4xx(kinds_server, kinds_db, server, db):
    run_id, step = last_step(kinds_db, "hc4")
    unknown = kinds_db.execute("SELECT max(id) + 1 FROM runs").fetchone()[0]
    assert "error" in kinds_server.json(f"/api/runs/{unknown}/steps/0/estimate", 404)
    assert "error" in kinds_server.json(f"/api/runs/{run_id}/steps/{step + 1}/estimate", 404)
    assert "error" in kinds_server.json(f"/api/runs/x/steps/0/estimate", 400)
    timeout = db.execute("SELECT id FROM runs WHERE status = 'timeout'").fetchone()["id"]
    assert "error" in server.json(f"/api/runs/{timeout}/steps/0/estimate", 400)


def test_a_python_estimators_run_is_not_re_run(kinds_dir, tmp_path):
    # A run of an estimator registered from Python (its parameters hold
    # `python`, docs/python.md) cannot be re-run by the server: 422.
    import json
    import shutil
    import sqlite3

    from conftest import Server

    copy = tmp_path / "python-run"
    copy.mkdir()
    shutil.copy(f"{kinds_dir}/results.sqlite", copy / "results.sqlite")
    with sqlite3.connect(copy / "results.sqlite") as db:
        run_id, params = db.execute(
            "SELECT id, algorithm_params FROM runs WHERE algorithm = 'hc4' AND status = 'ok'").fetchone()
        params = json.loads(params)
        params["python"] = "my_module.MyEstimator"
        db.execute("UPDATE runs SET algorithm_params = ? WHERE id = ?", (json.dumps(params), run_id))
    s = Server(str(copy))
    try:
        got = s.json(f"/api/runs/{run_id}/steps/0/estimate", 422)
        assert "Python" in got["error"] or "python" in got["error"], got
    finally:
        assert s.stop() == 0
