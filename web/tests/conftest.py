"""Fixtures of the results browser's tests: a small store made by
`icpbench run`, and `icpbench serve` on it (its URL from its first line)."""
import http.client
import json
import os
import shutil
import sqlite3
import subprocess
import urllib.parse

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))


def binary():
    path = os.environ.get("ICPBENCH_BINARY")
    if not path:
        pytest.skip("ICPBENCH_BINARY is not set (run through ctest)")
    return path


class Server:
    """`icpbench serve DIR` as a subprocess; get() sends a raw path (no
    client-side normalisation, so traversal attempts reach the server)."""

    def __init__(self, directory, *args):
        self.process = subprocess.Popen([binary(), "serve", directory, *args],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.url = self.process.stdout.readline().strip()
        if not self.url:
            self.process.wait(10)
            raise RuntimeError("serve printed no URL: " + self.process.stderr.read())
        parsed = urllib.parse.urlsplit(self.url)
        self.host, self.port = parsed.hostname, parsed.port

    def get(self, path):
        """(status, headers, body bytes) of GET path."""
        connection = http.client.HTTPConnection(self.host, self.port, timeout=30)
        connection.request("GET", path)
        response = connection.getresponse()
        body = response.read()
        connection.close()
        return response.status, dict(response.getheaders()), body

    def json(self, path, status=200):
        code, headers, body = self.get(path)
        assert code == status, (path, code, body)
        assert headers["Content-Type"].startswith("application/json"), headers
        return json.loads(body)

    def stop(self):
        self.process.terminate()
        return self.process.wait(10)


def run_spec(spec, out, jobs=2):
    subprocess.run([binary(), "run", spec, "--out", out, "--jobs", str(jobs)], check=True,
                   stderr=subprocess.DEVNULL)


def read_only(directory):
    """DIR's store through Python's sqlite3, closed after the session."""
    # immutable: like the server, it creates no -wal/-shm files next to the finished store.
    connection = sqlite3.connect(f"file:{directory}/results.sqlite?immutable=1", uri=True)
    connection.row_factory = sqlite3.Row
    yield connection
    connection.close()


@pytest.fixture(scope="session")
def store_dir(tmp_path_factory):
    out = str(tmp_path_factory.mktemp("web") / "tiny")
    run_spec(os.path.join(HERE, "tiny.yaml"), out)
    return out


@pytest.fixture(scope="session")
def db(store_dir):
    """The store through Python's sqlite3, read-only: what the answers must match."""
    yield from read_only(store_dir)


@pytest.fixture(scope="session")
def server(store_dir, db):
    os.makedirs(os.path.join(store_dir, "figures", "sub"), exist_ok=True)
    shutil.copy(os.path.join(HERE, "..", "assets", "style.css"),
                os.path.join(store_dir, "figures", "sub", "not-a-figure.css"))
    with open(os.path.join(store_dir, "figures", "area.png"), "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n fake png for the test")
    os.symlink("/etc/passwd", os.path.join(store_dir, "figures", "outside.png"))
    for name in (".hidden.png", "notes.txt"):  # neither listed nor served
        with open(os.path.join(store_dir, "figures", name), "wb") as f:
            f.write(b"not a figure to show")
    s = Server(store_dir)
    yield s
    assert s.stop() == 0


@pytest.fixture(scope="session")
def kinds_dir(tmp_path_factory):
    """A store with one run per kind of estimate (estimate.yaml)."""
    out = str(tmp_path_factory.mktemp("web") / "kinds")
    run_spec(os.path.join(HERE, "estimate.yaml"), out)
    return out


@pytest.fixture(scope="session")
def kinds_db(kinds_dir):
    yield from read_only(kinds_dir)


@pytest.fixture(scope="session")
def kinds_server(kinds_dir, kinds_db):
    s = Server(kinds_dir)
    yield s
    assert s.stop() == 0
