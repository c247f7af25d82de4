"""What an outside probe of `icpbench serve` found, each held: dotted
parameter names, request bodies, byte ranges on errors, methods cpp-httplib
refuses itself, a linked figures folder, the confidence interval's precision,
port 80's Host header and a second Ctrl-C during a re-run."""
import http.client
import json
import math
import os
import shutil
import signal
import socket
import sqlite3
import statistics
import subprocess
import threading
import time

import pytest

from conftest import Server, binary, run_spec


def request(server, method, path, body=None, headers=None):
    """(status, headers, parsed JSON body) of one request."""
    connection = http.client.HTTPConnection(server.host, server.port, timeout=30)
    connection.request(method, path, body=body, headers=headers or {})
    response = connection.getresponse()
    raw = response.read()
    connection.close()
    return response.status, dict(response.getheaders()), json.loads(raw) if raw else None


def test_a_nested_algorithms_dotted_parameters_filter_and_group(server, db):
    # 3b-bc4 stores its inner contractor's as inner.ratio: /api/options
    # offered them, and every filter or axis on one was a 400.
    row = db.execute("SELECT id, algorithm_params FROM runs WHERE algorithm = '3b-bc4'").fetchone()
    ratio = json.loads(row["algorithm_params"])["inner.ratio"]
    assert "inner.ratio" in server.json("/api/options")["parameters"]
    runs = server.json(f"/api/runs?param.inner.ratio={ratio}")
    assert [r["id"] for r in runs] == [row["id"]]
    server.json("/api/aggregate?group=param.inner.ratio&metric=wall_time_s")
    assert "at most 64" in server.json("/api/runs?param." + "x" * 65, status=400)["error"]


def test_a_request_body_is_refused_before_it_is_read(server):
    # A 1 GiB body was read whole into memory before the 405 (a GET's body
    # is now skipped unread).
    for method in ("POST", "PUT"):
        status, _, body = request(server, method, "/api/summary", body=b"x" * (1 << 20))
        assert status == 413 and "takes none" in body["error"], method


def test_errors_are_sent_whole_whatever_range_was_asked(server):
    status, headers, body = request(server, "GET", "/api/summary", headers={"Range": "bytes=0-0,1-1"})
    assert status == 416 and body == {"error": "one byte range per request"}
    status, headers, body = request(server, "GET", "/api/runs?limit=0", headers={"Range": "bytes=10-"})
    assert status == 400 and "limit" in body["error"] and "Content-Range" not in headers


@pytest.mark.parametrize("method", ["TRACE", "FOO", "POST"])
def test_methods_refused_before_routing_are_405(server, method):
    # cpp-httplib answered 400 to a method it does not know or a POST without a body.
    connection = http.client.HTTPConnection(server.host, server.port, timeout=30)
    connection.putrequest(method, "/api/runs")
    connection.endheaders()
    response = connection.getresponse()
    body = json.loads(response.read())
    connection.close()
    assert response.status == 405 and response.getheader("Allow") == "GET, HEAD"
    assert "only reads" in body["error"]


def test_a_figures_folder_that_is_a_link_serves_nothing(store_dir, tmp_path):
    copy = tmp_path / "store"
    shutil.copytree(store_dir, copy, ignore=shutil.ignore_patterns("figures"))
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "secret.png").write_bytes(b"\x89PNG\r\n\x1a\n not the store's")
    os.symlink(outside, copy / "figures")
    s = Server(str(copy))
    try:
        assert s.json("/api/figures") == []
        assert s.get("/figures/secret.png")[0] == 404
    finally:
        assert s.stop() == 0


def test_the_confidence_interval_keeps_its_digits_for_a_large_mean(store_dir, tmp_path):
    # avg(m * m) - mean^2 made the half-width 0.3 where it is 1e-4.
    copy = tmp_path / "store"
    shutil.copytree(store_dir, copy)
    db = sqlite3.connect(copy / "results.sqlite")
    ids = [r[0] for r in db.execute("SELECT id FROM runs WHERE algorithm = 'hc4' AND status = 'ok' ORDER BY id")]
    for i, run_id in enumerate(ids):
        db.execute("UPDATE runs SET wall_time_s = ? WHERE id = ?", (1e8 + 1e-4 * i, run_id))
    db.commit()
    db.close()
    values = [1e8 + 1e-4 * i for i in range(len(ids))]
    half = 1.96 * statistics.stdev(values) / math.sqrt(len(values))
    s = Server(str(copy))
    try:
        rows = s.json("/api/aggregate?metric=wall_time_s&algorithm=hc4")
        (row,) = rows
        assert row["n"] == len(ids)
        assert abs((row["ci_hi"] - row["ci_lo"]) / 2 - half) < 0.01 * half
    finally:
        assert s.stop() == 0


def test_port_80_answers_a_host_without_its_port(store_dir):
    # Clients leave the default port out of Host: every request was a 403.
    with socket.socket() as probe:
        try:
            probe.bind(("127.0.0.1", 80))
        except OSError:
            pytest.skip("port 80 cannot be bound here")
    s = Server(store_dir, "--port", "80")
    try:
        for host in ("127.0.0.1", "localhost", "127.0.0.1:80"):
            status, _, _ = request(s, "GET", "/api/summary", headers={"Host": host})
            assert status == 200, host
    finally:
        assert s.stop() == 0


def test_a_second_signal_does_not_wait_for_a_re_run(tmp_path):
    # The first stops the server, which waits for the re-runs in progress
    # (up to 10 s each); a second one was ignored.
    spec = tmp_path / "slow.yaml"
    spec.write_text("name: slow\nseeds: [1]\nexperiments:\n  - name: e\n"
                    "    algorithms: [{name: fault, params: {mode: slow, slow_ms: 25}}]\n"
                    "    problems: [{name: car-track, params: {w: 5, steps: 160}}]\n")
    out = str(tmp_path / "out")
    run_spec(str(spec), out, jobs=1)
    s = Server(out)
    def re_run():  # the server ends before it answers
        try:
            s.get("/api/runs/1/steps/159/estimate")
        except (ConnectionError, http.client.HTTPException):
            pass

    threading.Thread(target=re_run, daemon=True).start()
    time.sleep(0.5)  # the re-run is under way (4 s)
    s.process.send_signal(signal.SIGINT)
    time.sleep(0.2)
    start = time.monotonic()
    s.process.send_signal(signal.SIGINT)
    assert s.process.wait(10) == 128 + signal.SIGINT
    assert time.monotonic() - start < 1.5
    assert "second signal" in s.process.stderr.read()
