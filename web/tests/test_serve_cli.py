"""`icpbench serve` on the command line: its URL line, --host and --port, its
exit codes, and serving a store while `icpbench run` is still writing it."""
import http.client
import os
import shutil
import signal
import socket
import sqlite3
import subprocess
import threading
import time

import pytest

from conftest import HERE, Server, binary


def test_it_binds_localhost_on_a_free_port_and_prints_the_url(store_dir):
    s = Server(store_dir)
    try:
        assert s.url.startswith("http://127.0.0.1:") and s.url.endswith("/")
        assert s.port > 0
        assert s.get("/")[0] == 200
    finally:
        assert s.stop() == 0  # SIGTERM stops it cleanly


def test_host_and_port_are_honoured(store_dir):
    with socket.socket() as probe:  # a port free a moment ago
        probe.bind(("127.0.0.2", 0))
        port = probe.getsockname()[1]
    s = Server(store_dir, "--host", "127.0.0.2", "--port", str(port))
    try:
        assert s.url == f"http://127.0.0.2:{port}/"
        assert s.json("/api/summary")["total"] == 9
    finally:
        s.stop()


def _status(s, host_header):
    connection = http.client.HTTPConnection("127.0.0.1", s.port, timeout=30)
    connection.request("GET", "/api/summary", headers={"Host": host_header})
    status = connection.getresponse().status
    connection.close()
    return status


def test_a_loopback_host_in_any_spelling_answers_only_its_own_names(store_dir):
    """127.1 and 2130706433 are 127.0.0.1: the DNS-rebinding check is kept
    (it was off for such spellings), and the numeric address is answered."""
    for spelling in ("127.1", "2130706433"):
        s = Server(store_dir, "--host", spelling)
        try:
            assert _status(s, f"evil.example:{s.port}") == 403
            assert _status(s, f"127.0.0.1:{s.port}") == 200
            assert _status(s, f"LOCALHOST:{s.port}") == 200
            assert _status(s, f"{spelling}:{s.port}") == 200  # the URL it printed
        finally:
            s.stop()


def test_a_port_in_use_is_the_environment(store_dir):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        r = subprocess.run([binary(), "serve", store_dir, "--port", str(taken.getsockname()[1])],
                           capture_output=True, text=True, timeout=30)
    assert r.returncode == 3, r.stderr
    assert "cannot bind" in r.stderr


def test_a_port_another_server_holds_is_the_environment(store_dir):
    # Two servers on one port would split the requests between two stores.
    first = subprocess.Popen([binary(), "serve", store_dir, "--port", "0"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        port = first.stdout.readline().strip().rsplit(":", 1)[1].rstrip("/")
        r = subprocess.run([binary(), "serve", store_dir, "--port", port],
                           capture_output=True, text=True, timeout=30)
        assert r.returncode == 3, r.stderr
        assert "cannot bind" in r.stderr
    finally:
        first.terminate()
        first.wait(10)


@pytest.mark.parametrize("args, words", [
    (["/nonexistent/dir"], "no such file"),
    ([HERE], "no such file"),
    (["--port", "70000"], "70000"),
    (["--host", ""], "must not be empty"),
])
def test_bad_input_exits_2(store_dir, args, words):
    if args[0].startswith("--"):
        args = [store_dir] + args
    r = subprocess.run([binary(), "serve", *args], capture_output=True, text=True, timeout=30)
    assert r.returncode == 2, r.stderr
    assert words in r.stderr


def test_a_foreign_file_is_bad_input(tmp_path):
    (tmp_path / "results.sqlite").write_text("not a store")
    r = subprocess.run([binary(), "serve", str(tmp_path)], capture_output=True, text=True, timeout=30)
    assert r.returncode == 2, r.stderr


def test_it_serves_the_default_suites_store_while_the_sweep_writes_it(tmp_path):
    """The first runs of specs/default.yaml (a few seconds), served as they
    are stored; then the sweep is interrupted (its finished runs kept)."""
    source = os.environ.get("ICPBENCH_SOURCE_DIR", os.path.join(HERE, "..", ".."))
    out = str(tmp_path / "default")
    sweep = subprocess.Popen([binary(), "run", "specs/default.yaml", "--out", out, "--jobs", "2"],
                             cwd=source, stderr=subprocess.DEVNULL)
    deadline = time.time() + 60
    s = None
    try:
        while s is None:  # until the sweep has made the store
            try:
                s = Server(out)
            except RuntimeError:
                assert time.time() < deadline and sweep.poll() is None
                time.sleep(0.05)
        seen = []
        while len(set(seen)) < 3 and time.time() < deadline:
            summary = s.json("/api/summary")
            runs = s.json("/api/runs?limit=10000")
            assert len(runs) >= summary["total"]  # a later snapshot has no fewer runs
            if runs:
                s.json(f"/api/runs/{runs[-1]['id']}")  # the newest run reads whole
            seen.append(summary["total"])
            time.sleep(0.1)
        assert sweep.poll() is None, "the sweep ended before the test saw it write"
        assert seen == sorted(seen) and len(set(seen)) >= 3, seen  # it saw the store grow
    finally:
        # Reading while the sweep closes its store: its runs stayed in -wal,
        # and results.sqlite copied alone was malformed.
        reading = threading.Event()
        reading.set()
        reader = threading.Thread(target=lambda: [s.get("/api/summary") for _ in iter(reading.is_set, False)])
        reader.start()
        sweep.send_signal(signal.SIGINT)
        code = sweep.wait(60)
        reading.clear()
        reader.join()
        assert code == 128 + signal.SIGINT
    try:
        stored = [r["id"] for r in s.json("/api/runs?limit=10000")]
        assert len(stored) >= seen[-1]
        alone = tmp_path / "alone"
        alone.mkdir()
        shutil.copy(os.path.join(out, "results.sqlite"), alone)
        db = sqlite3.connect(f"file:{alone}/results.sqlite?immutable=1", uri=True)
        assert stored == [r[0] for r in db.execute("SELECT id FROM runs ORDER BY id")]
        db.close()
    finally:
        assert s.stop() == 0
