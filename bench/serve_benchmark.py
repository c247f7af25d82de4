#!/usr/bin/env python3
"""Response times of `icpbench serve` on a large store (docs/web.md).

Makes a small store with `icpbench run web/tests/tiny.yaml`, then copies its
runs into a synthetic store of RUNS runs of STEPS steps each (direct SQL
inserts into the same schema: 10^5 runs and 10^7 steps by default), serves it
and times the first page of /api/runs, one run with its steps, and the other
endpoints the page calls first: the median of REPEATS requests each.

  python3 bench/serve_benchmark.py [--runs N] [--steps N] [--repeats N] [--keep DIR]
"""
import argparse
import http.client
import os
import shutil
import sqlite3
import statistics
import subprocess
import tempfile
import time
import urllib.parse

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build_store(binary, out, runs, steps):
    small = os.path.join(out, "small")
    subprocess.run([binary, "run", os.path.join(ROOT, "web/tests/tiny.yaml"), "--out", small],
                   check=True, stderr=subprocess.DEVNULL)
    big = os.path.join(out, "big")
    os.makedirs(big)
    shutil.copy(os.path.join(small, "results.sqlite"), os.path.join(big, "results.sqlite"))
    db = sqlite3.connect(os.path.join(big, "results.sqlite"))
    db.execute("PRAGMA journal_mode=DELETE")
    db.execute("PRAGMA synchronous=OFF")
    columns = [r[1] for r in db.execute("PRAGMA table_info(runs)") if r[1] not in ("id", "key", "seed")]
    template = [r[0] for r in db.execute("SELECT id FROM runs WHERE status = 'ok' ORDER BY id")]
    first = db.execute("SELECT max(id) FROM runs").fetchone()[0] + 1
    started = time.time()
    with db:
        # Run n copies template run n % len(template), with w = n % 50 and seed n.
        db.execute("CREATE TEMP TABLE template AS SELECT row_number() OVER (ORDER BY id) - 1 AS k, * "
                   "FROM runs WHERE status = 'ok'")
        select = ", ".join("json_set(t.problem_params, '$.w', CAST(n % 50 AS TEXT))"
                           if c == "problem_params" else "t." + c for c in columns)
        db.execute(f"WITH RECURSIVE nums(n) AS (SELECT 1 UNION ALL SELECT n + 1 FROM nums WHERE n < ?) "
                   f"INSERT INTO runs (key, seed, {', '.join(columns)}) "
                   f"SELECT 'synthetic ' || n, n, {select} FROM nums JOIN template t "
                   f"ON t.k = n % ? ORDER BY n", (runs - db.execute("SELECT count(*) FROM runs").fetchone()[0],
                                                 len(template)))
        db.execute(f"UPDATE runs SET steps = ? WHERE id >= ?", (steps, first))
        db.execute("WITH RECURSIVE nums(n) AS (SELECT 0 UNION ALL SELECT n + 1 FROM nums WHERE n < ? - 1) "
                   "INSERT INTO steps (run_id, step, status, contained, area, centre_error, "
                   "solve_time_s, estimate) SELECT r.id, n, 'contracted', 1, 1 + (abs(random()) % 1000) / 10.0, "
                   "(abs(random()) % 100) / 100.0, 1e-4 * (1 + abs(random()) % 100), 'box' "
                   "FROM runs r JOIN nums WHERE r.id >= ? ORDER BY r.id, n", (steps, first))
    db.execute("PRAGMA journal_mode=WAL")  # as icpbench leaves it
    db.close()
    return big, time.time() - started


def request(connection, path):
    started = time.perf_counter()
    connection.request("GET", path)
    response = connection.getresponse()
    body = response.read()
    elapsed = time.perf_counter() - started
    assert response.status == 200, (path, response.status, body[:200])
    return elapsed, len(body)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=100_000)
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--binary", default=os.path.join(ROOT, "build/icpbench"))
    parser.add_argument("--keep", help="build the store in this directory and keep it")
    args = parser.parse_args()
    out = args.keep or tempfile.mkdtemp(prefix="serve-benchmark-")
    try:
        store, build_s = build_store(args.binary, out, args.runs, args.steps)
        db = sqlite3.connect(f"file:{store}/results.sqlite?immutable=1", uri=True)
        n_runs, n_steps = (db.execute(f"SELECT count(*) FROM {t}").fetchone()[0] for t in ("runs", "steps"))
        last = db.execute("SELECT max(id) FROM runs").fetchone()[0]
        db.close()
        size_mb = os.path.getsize(os.path.join(store, "results.sqlite")) / 1e6
        print(f"store: {n_runs} runs, {n_steps} steps, {size_mb:.0f} MB, built in {build_s:.0f} s")
        server = subprocess.Popen([args.binary, "serve", store], stdout=subprocess.PIPE, text=True)
        try:
            url = urllib.parse.urlsplit(server.stdout.readline().strip())
            connection = http.client.HTTPConnection(url.hostname, url.port, timeout=120)
            paths = [("first page of runs", "/api/runs?limit=50&offset=0"),
                     ("a late page of runs", f"/api/runs?limit=50&offset={n_runs - 100}"),
                     ("one run with its steps", f"/api/runs/{last}"),
                     ("a filtered page (algorithm, w)", "/api/runs?limit=50&algorithm=hc4&param.w=7"),
                     ("counts by status", "/api/summary"),
                     ("sweep figure (mean area by algorithm and w)",
                      "/api/aggregate?metric=mean_area&group=algorithm&x=param.w"),
                     ("performance profile (time per step)", "/api/profile?metric=time_mean_s"),
                     ("filter choices", "/api/options")]
            print(f"{'request':45} {'median s':>9} {'first s':>8} {'bytes':>9}   path")
            for name, path in paths:
                times = [request(connection, path) for _ in range(args.repeats)]
                print(f"{name:45} {statistics.median(t for t, _ in times):9.4f} {times[0][0]:8.4f} "
                      f"{times[0][1]:9d}   {path}")
        finally:
            server.terminate()
            server.wait(10)
    finally:
        if not args.keep:
            shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
