"""`icpbench serve`'s JSON API against a small store: every endpoint's answer
matches the store read directly, and bad requests get a 4xx with a message."""
import http.client
import json
import math
import os
import shutil
import socket
import statistics
import time
import urllib.parse

import pytest

from conftest import Server, run_spec


def runs_where(db, where="1", *args):
    return db.execute(f"SELECT * FROM runs WHERE {where} ORDER BY id", args).fetchall()


def test_runs_lists_every_run_with_its_parameters(server, db):
    runs = server.json("/api/runs")
    stored = runs_where(db)
    assert [r["id"] for r in runs] == [r["id"] for r in stored]
    assert len(runs) == 9
    for got, want in zip(runs, stored):
        assert got["key"] == want["key"]
        assert (got["algorithm"], got["problem"], got["status"]) == (
            want["algorithm"], want["problem"], want["status"])
        assert got["experiment"] == want["spec_file"].split("#")[1]
        assert got["parameters"]["problem"] == json.loads(want["problem_params"])
        assert got["parameters"]["algorithm"] == json.loads(want["algorithm_params"])
        assert got["mean_area"] == pytest.approx(want["mean_area"])


@pytest.mark.parametrize("query, where, args", [
    ("algorithm=hc4", "algorithm = ?", ["hc4"]),
    ("algorithm=hc4,3b-bc4", "algorithm IN (?, ?)", ["hc4", "3b-bc4"]),
    ("status=timeout", "status = ?", ["timeout"]),
    ("experiment=sweep", "spec_file LIKE ?", ["%#sweep"]),
    ("param.w=10", "json_extract(problem_params, '$.w') = ?", ["10"]),
    ("param.w=10&algorithm=bc4", "json_extract(problem_params, '$.w') = ? AND algorithm = ?",
     ["10", "bc4"]),
])
def test_runs_filters_as_the_store_does(server, db, query, where, args):
    ids = [r["id"] for r in server.json("/api/runs?" + query)]
    assert ids == [r["id"] for r in runs_where(db, where, *args)]
    assert ids  # every filter here selects something
    summary = server.json("/api/summary?" + query)
    assert summary["total"] == len(ids)


def test_runs_pages_and_sorts(server, db):
    all_ids = [r["id"] for r in runs_where(db)]
    assert [r["id"] for r in server.json("/api/runs?limit=4&offset=2")] == all_ids[2:6]
    assert server.json("/api/runs?offset=100") == []
    by_area = server.json("/api/runs?sort=mean_area&desc=1&status=ok")
    areas = [r["mean_area"] for r in by_area]
    assert areas == sorted(areas, reverse=True)


def test_summary_counts_statuses_and_reasons(server, db):
    summary = server.json("/api/summary")
    counts = dict(db.execute("SELECT status, count(*) FROM runs GROUP BY status").fetchall())
    assert summary["status"] == counts
    assert summary["total"] == sum(counts.values())
    assert counts.get("timeout") == 1
    timeout = db.execute("SELECT reason FROM runs WHERE status = 'timeout'").fetchone()[0]
    assert {"status": "timeout", "reason": timeout, "count": 1} in summary["reasons"]


def test_options_list_the_filters_choices(server, db):
    options = server.json("/api/options")
    assert options["algorithms"] == ["3b-bc4", "bc4", "hc4"]
    assert options["experiments"] == ["slow", "sweep"]
    assert options["parameters"]["w"] == ["5", "10", "40"]  # in numeric order
    assert options["truncated_parameters"] == []
    names = {r[0] for r in db.execute("SELECT DISTINCT name FROM run_properties "
                                      "WHERE type IN ('int', 'real')")}
    assert set(options["properties"]) == names and names


def test_one_run_has_its_steps_properties_and_provenance(server, db):
    run_id = runs_where(db, "algorithm = 'bc4' AND status = 'ok'")[0]["id"]
    run = server.json(f"/api/runs/{run_id}")
    want = runs_where(db, "id = ?", run_id)[0]
    for column in ("key", "git_revision", "machine", "compiler", "date", "seed", "steps"):
        assert run[column] == want[column]
    assert run["problem_params"] == json.loads(want["problem_params"])
    steps = db.execute("SELECT * FROM steps WHERE run_id = ? ORDER BY step", (run_id,)).fetchall()
    assert len(run["step_rows"]) == len(steps) == want["steps"]
    for got, s in zip(run["step_rows"], steps):
        assert (got["step"], got["status"], got["contained"], got["estimate"]) == (
            s["step"], s["status"], s["contained"], s["estimate"])
        assert got["area"] == pytest.approx(s["area"])
    props = dict(db.execute("SELECT name, value FROM run_properties WHERE run_id = ?", (run_id,)))
    assert run["properties"] == pytest.approx(props)


def test_a_runs_values_and_one_step(server, db):
    run_id = runs_where(db, "algorithm = 'hc4'")[0]["id"]
    values = server.json(f"/api/runs/{run_id}/values")
    rows = db.execute("SELECT step, var, lo, hi, truth FROM step_values WHERE run_id = ? "
                      "ORDER BY step, pos", (run_id,)).fetchall()
    assert values["columns"] == ["step", "var", "lo", "hi", "truth"]
    assert len(values["rows"]) == len(rows) > 0
    assert values["rows"][3] == pytest.approx(list(rows[3]))
    step = rows[-1]["step"]
    detail = server.json(f"/api/runs/{run_id}/steps/{step}")
    assert [v["var"] for v in detail["values"]] == [r["var"] for r in rows if r["step"] == step]
    props = dict(db.execute("SELECT name, value FROM step_properties WHERE run_id = ? AND step = ?",
                            (run_id, step)))
    assert detail["properties"] == pytest.approx(props)


def test_aggregate_gives_means_with_confidence_intervals(server, db):
    rows = server.json("/api/aggregate?metric=mean_area&group=algorithm&x=param.w&experiment=sweep")
    assert len(rows) == 4  # hc4 and bc4 at w = 5 and 10
    for row in rows:
        values = [r[0] for r in db.execute(
            "SELECT mean_area FROM runs WHERE algorithm = ? AND json_extract(problem_params, '$.w') = ? "
            "AND status = 'ok' AND spec_file LIKE '%#sweep'", (row["group"], row["x"]))]
        assert row["n"] == len(values) == 2
        assert row["mean"] == pytest.approx(statistics.mean(values))
        half = 1.96 * statistics.stdev(values) / math.sqrt(2)
        assert row["ci_lo"] == pytest.approx(row["mean"] - half, rel=1e-6, abs=1e-9)
        assert row["ci_hi"] == pytest.approx(row["mean"] + half, rel=1e-6, abs=1e-9)


def test_aggregate_of_a_property_and_without_x(server, db):
    name = db.execute("SELECT name FROM run_properties WHERE type = 'int' ORDER BY name").fetchone()[0]
    rows = server.json(f"/api/aggregate?metric=prop.{name}&group=algorithm")
    for row in rows:
        values = [r[0] for r in db.execute(
            "SELECT p.value FROM run_properties p JOIN runs r ON r.id = p.run_id "
            "WHERE p.name = ? AND r.algorithm = ? AND r.status = 'ok'", (name, row["group"]))]
        assert row["x"] == "" and row["n"] == len(values)
        assert row["mean"] == pytest.approx(statistics.mean(values))


def test_profile_ratios_are_to_the_best_of_each_instance(server, db):
    profile = server.json("/api/profile?metric=time_mean_s&experiment=sweep")
    assert profile["instances"] == 4  # w in {5, 10} x seeds {1, 2}
    assert set(profile["solvers"]) == {"hc4", "bc4"}
    ratios = [t for ts in profile["solvers"].values() for t in ts]
    assert len(ratios) == 8 and min(ratios) == 1 and all(t >= 1 for t in ratios)
    assert sum(t == 1 for t in ratios) >= 4  # each instance has a best


def test_figures_are_listed_and_served(server, store_dir):
    # Listed: what /figures/ serves (no hidden file, no text, not the link out of DIR).
    assert server.json("/api/figures") == ["area.png"]
    status, headers, body = server.get("/figures/area.png")
    assert status == 200 and headers["Content-Type"] == "image/png"
    assert body == open(os.path.join(store_dir, "figures", "area.png"), "rb").read()
    # Sandboxed: an SVG's script would run with the page's origin.
    assert "sandbox" in headers["Content-Security-Policy"]


def test_claims_are_empty_until_the_paper_writes_them(server, store_dir):
    assert server.json("/api/claims") == {"file": None, "claims": []}
    paper = os.path.join(store_dir, "paper")
    os.makedirs(paper)
    claims = [{"claim": "HC4 is faster than BC4", "verdict": "match"}]
    try:
        with open(os.path.join(paper, "claims.json"), "w") as f:
            json.dump(claims, f)
        assert server.json("/api/claims") == {"file": "paper/claims.json", "claims": claims}
        with open(os.path.join(paper, "claims.json"), "w") as f:
            f.write("{not json")
        assert "not JSON" in server.json("/api/claims", status=500)["error"]
        # A link to a file outside the store is not followed.
        outside = os.path.join(os.path.dirname(store_dir), "outside-claims.json")
        with open(outside, "w") as f:
            json.dump([{"claim": "secret"}], f)
        os.remove(os.path.join(paper, "claims.json"))
        os.symlink(outside, os.path.join(paper, "claims.json"))
        assert server.json("/api/claims") == {"file": None, "claims": []}
    finally:
        shutil.rmtree(paper)


def test_the_page_and_its_assets(server):
    for path, kind in [("/", "text/html"), ("/app.js", "text/javascript"),
                       ("/style.css", "text/css"), ("/chart.js", "text/javascript")]:
        status, headers, body = server.get(path)
        assert status == 200 and headers["Content-Type"].startswith(kind) and body, path
    assert b"Chart.js v3" in server.get("/chart.js")[2]


@pytest.mark.parametrize("path, status, words", [
    ("/api/runs/999999", 404, "no run with id 999999"),
    ("/api/runs/abc", 400, "bad run id"),
    ("/api/runs/999999/values", 404, "no run"),
    ("/api/runs/1/steps/99999", 404, "has no step"),
    ("/api/runs?status=bogus", 400, "unknown status"),
    ("/api/runs?colour=red", 400, "unknown query parameter 'colour'"),
    ("/api/runs?limit=0", 400, "limit='0'"),
    ("/api/runs?limit=ten", 400, "must be an integer"),
    ("/api/runs?algorithm=", 400, "empty value"),
    ("/api/runs?sort=key;DROP", 400, "encode them"),
    ("/api/runs?sort=key%3BDROP", 400, "cannot sort"),
    ("/api/runs?param.w%27)%20OR%201--=1", 400, "bad parameter name"),
    ("/api/aggregate?metric=bogus", 400, "unknown metric"),
    ("/api/aggregate?x=colour", 400, "bad x"),
    ("/api/profile?metric=consistency_rate", 400, "lower is better"),
    ("/api/options?algorithm=hc4", 400, "no query parameters"),
    ("/api/nothing", 404, "no such page"),
    ("/api/runs?algorithm=hc4%00x", 400, "NUL byte"),
    ("/api/runs?algorithm=hc4&algorithm=bc4", 400, "'algorithm' given twice"),
    ("/api/runs?limit=1&limit=2", 400, "'limit' given twice"),
    ("/figures/notes.txt", 404, "no figure"),
    ("/api/runs?x=" + "a" * 9000, 414, "too long"),
])
def test_bad_requests_get_a_4xx_with_a_message(server, path, status, words):
    assert words in server.json(path, status=status)["error"]


@pytest.mark.parametrize("path", [
    "/figures/../../etc/passwd",
    "/figures/..%2f..%2f..%2fetc%2fpasswd",
    "/figures/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
    "/figures/%2E%2E%2F%2E%2E%2Fresults.sqlite",
    "/figures/../results.sqlite",
    "/figures//etc/passwd",
    "/figures/sub/../../results.sqlite",
    "/figures/outside.png",  # a symbolic link out of DIR/figures
    "/figures/.hidden",
    "/../../../../etc/passwd",
    "/%2e%2e/%2e%2e/etc/passwd",
    "/app.js/../../../etc/passwd",
])
def test_no_file_outside_dir_or_the_assets_is_served(server, path):
    status, _, body = server.get(path)
    assert 400 <= status < 500, (path, status)
    assert b"root:" not in body and b"SQLite format" not in body
    assert "error" in json.loads(body)


def test_the_server_writes_nothing(server, store_dir):
    store = os.path.join(store_dir, "results.sqlite")
    before = os.stat(store)
    for path in ("/api/runs", "/api/summary", "/api/runs/1", "/api/options", "/api/aggregate"):
        server.json(path)
    after = os.stat(store)
    assert (after.st_size, after.st_mtime_ns) == (before.st_size, before.st_mtime_ns)
    # Immutable (no sweep writing): not even SQLite's -wal/-shm files.
    assert not any(n.startswith("results.sqlite-") for n in os.listdir(store_dir))


def test_another_host_name_is_refused(server):
    """A DNS-rebinding page names its own host: it gets a 403, not the store."""
    connection = http.client.HTTPConnection(server.host, server.port, timeout=30)
    connection.request("GET", "/api/runs", headers={"Host": f"evil.example:{server.port}"})
    response = connection.getresponse()
    body = json.loads(response.read())
    connection.close()
    assert response.status == 403 and "not served" in body["error"]
    connection = http.client.HTTPConnection(server.host, server.port, timeout=30)
    connection.request("GET", "/api/summary", headers={"Host": f"localhost:{server.port}"})
    assert connection.getresponse().status == 200
    connection.close()


def test_a_spec_path_holding_a_hash_groups_runs_as_the_report_does(tmp_path):
    # Runs are stored under SPEC#EXPERIMENT: the experiment follows the last '#'.
    spec_dir = tmp_path / "specs#1"
    spec_dir.mkdir()
    spec = spec_dir / "hash.yaml"
    spec.write_text("seeds: [1]\nexperiments:\n  - name: e\n    algorithms: [hc4]\n"
                    "    problems: [{name: car-track, params: {w: 2, steps: 3}}]\n")
    out = str(tmp_path / "out")
    run_spec(str(spec), out)
    s = Server(out)
    try:
        assert s.json("/api/options")["experiments"] == ["e"]
        runs = s.json("/api/runs?experiment=e")
        assert [r["experiment"] for r in runs] == ["e"]
        assert s.json("/api/summary?experiment=e")["total"] == 1
    finally:
        assert s.stop() == 0


def test_many_byte_ranges_are_refused(server):
    """300 ranges of one body multiplied it in memory (a 60 MB answer)."""
    connection = http.client.HTTPConnection(server.host, server.port, timeout=30)
    connection.request("GET", "/figures/area.png", headers={"Range": "bytes=0-10,0-10,0-10"})
    response = connection.getresponse()
    response.read()
    connection.close()
    assert response.status == 416


def test_idle_connections_do_not_stall_the_others(server):
    """Twenty idle connections held cpp-httplib's eight threads: a request
    waited for their keep-alive to end (9.7 s)."""
    idle = [socket.create_connection((server.host, server.port)) for _ in range(20)]
    try:
        start = time.monotonic()
        server.json("/api/summary")
        assert time.monotonic() - start < 3
    finally:
        for s in idle:
            s.close()


def test_a_damaged_store_is_a_500_and_an_undefined_mean_is_null(store_dir, tmp_path):
    """A malformed JSON column was sent as <discarded> in a 200 (not JSON);
    avg() of +inf and -inf (NULL) was sent as a mean of 0."""
    import sqlite3
    damaged = str(tmp_path / "damaged")
    os.makedirs(damaged)
    shutil.copy(os.path.join(store_dir, "results.sqlite"), damaged)
    with sqlite3.connect(os.path.join(damaged, "results.sqlite")) as c:
        first, second = [r[0] for r in c.execute("SELECT id FROM runs WHERE status = 'ok' "
                                                  "ORDER BY id LIMIT 2")]
        c.execute("UPDATE runs SET mean_area = 1e999 WHERE id = ?", (first,))
        c.execute("UPDATE runs SET mean_area = -1e999 WHERE id = ?", (second,))
        algorithm = c.execute("SELECT algorithm FROM runs WHERE id = ?", (first,)).fetchone()[0]
        c.execute("UPDATE runs SET algorithm = ? WHERE id = ?", (algorithm, second))
        c.execute("UPDATE runs SET algorithm_params = '{not json' WHERE id = ?", (first,))
    s = Server(damaged)
    try:
        status, _, body = s.get(f"/api/runs/{first}")
        assert status == 500 and "not JSON" in json.loads(body)["error"]
        rows = s.json(f"/api/aggregate?metric=mean_area&algorithm={algorithm}")
        assert rows and all(r["mean"] is None for r in rows if r["min"] == "-inf" and r["max"] == "inf")
        assert any(r["min"] == "-inf" and r["max"] == "inf" for r in rows)
    finally:
        s.stop()


def test_a_raw_semicolon_or_second_equals_in_the_query_is_refused(server):
    """cpp-httplib read limit=3;offset=1 as limit 1, and status=ok=failed as failed."""
    for query in ("limit=3;offset=1", "algorithm=hc4;algorithm=bc4", "status=ok=failed"):
        assert "encode them" in server.json(f"/api/runs?{query}", status=400)["error"], query
    assert "unknown status 'ok=failed'" in server.json("/api/runs?status=ok%3Dfailed", status=400)["error"]


def test_a_runs_answers_take_no_query_and_other_methods_are_405(server, db):
    run_id = runs_where(db, "status = 'ok'")[0]["id"]
    for path in (f"/api/runs/{run_id}?foo=bar", f"/api/runs/{run_id}/values?foo=bar",
                 f"/api/runs/{run_id}/steps/0?foo=bar", "/api/runs?limit=+2", "/api/runs?limit=%202"):
        server.json(path, status=400)
    for method in ("POST", "PUT", "PATCH", "DELETE", "OPTIONS"):
        connection = http.client.HTTPConnection(server.host, server.port, timeout=30)
        connection.request(method, "/api/runs", body=b"x" if method != "OPTIONS" else None)
        response = connection.getresponse()
        body = json.loads(response.read())
        connection.close()
        assert response.status == 405 and response.getheader("Allow") == "GET, HEAD", method
        assert "only reads" in body["error"]


def test_a_run_is_found_by_its_key(server, db):
    """A link names the run by key: a retried, forced or merged run gets a new id."""
    row = runs_where(db, "status = 'ok'")[0]
    found = server.json("/api/runs?key=" + urllib.parse.quote(row["key"]))
    assert [r["id"] for r in found] == [row["id"]]
    assert server.json("/api/runs?key=no-such-run") == []
