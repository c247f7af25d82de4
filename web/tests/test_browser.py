"""The page in a real browser: Debian's chromium, headless, loads the served
page and runs its JavaScript; the DOM it dumps must show the store's values
(the runs table, a comparison figure's data, a run's steps). Screenshots go to
BUILD/web-screenshots/."""
import html
import json
import os
import re
import shutil
import subprocess
import urllib.parse

import pytest

from conftest import Server

CHROMIUM = shutil.which("chromium")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (scripts/deps.sh)")


def browse(url, name, shot=True):
    """The DOM of url after its scripts ran, and a screenshot NAME.png
    (unless not shot: each chromium start costs a few seconds)."""
    shots = os.path.join(os.environ.get("ICPBENCH_BUILD_DIR", "build"), "web-screenshots")
    os.makedirs(shots, exist_ok=True)
    common = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
              "--no-first-run", "--disable-dev-shm-usage", "--virtual-time-budget=10000",
              "--window-size=1280,1800", f"--user-data-dir={shots}/profile-{name}"]
    dom = subprocess.run(common + ["--dump-dom", url], capture_output=True, text=True,
                         timeout=60, check=True).stdout
    if not shot:
        return dom
    subprocess.run(common + [f"--screenshot={shots}/{name}.png", url], capture_output=True,
                   timeout=60, check=True)
    assert os.path.getsize(f"{shots}/{name}.png") > 10000
    return dom


def table_rows(dom, table_id):
    """The cells' texts of each row of table id (header first)."""
    table = re.search(rf'<table id="{table_id}"[^>]*>(.*?)</table>', dom, re.S).group(1)
    return [[html.unescape(re.sub("<[^>]+>", "", c)) for c in re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", row, re.S)]
            for row in re.findall(r"<tr[^>]*>(.*?)</tr>", table, re.S)]


def csv_rows(dom, table_id):
    """What table id's CSV button downloads: each cell's full value (its
    data-value, where the display rounds) or else its text."""
    table = re.search(rf'<table id="{table_id}"[^>]*>(.*?)</table>', dom, re.S).group(1)
    cell = lambda attrs, text: html.unescape(
        (re.search(r'data-value="([^"]*)"', attrs) or re.match(r"(.*)", re.sub("<[^>]+>", "", text), re.S)).group(1))
    return [[cell(a, t) for a, t in re.findall(r"<t[hd]([^>]*)>(.*?)</t[hd]>", row, re.S)]
            for row in re.findall(r"<tr[^>]*>(.*?)</tr>", table, re.S)]


def page_text(dom):
    return html.unescape(re.search(r'<span id="page">(.*?)</span>', dom).group(1))


def test_the_runs_table_shows_the_stores_runs(server, db):
    dom = browse(server.url + "#view=runs", "runs")
    assert 'data-ready="runs"' in dom
    rows = table_rows(dom, "runs-table")
    keys = [r[0] for r in db.execute("SELECT key FROM runs ORDER BY id")]
    assert [r[-1] for r in rows[1:]] == keys
    assert "9 runs: 8 ok, 0 failed, 1 timeout, 0 skipped" in dom
    assert page_text(dom) == "1–9 of 9"
    assert '<link rel="icon" href="data:,">' in dom  # no request for /favicon.ico, no 404


def test_a_page_past_the_last_run_shows_the_last_page(server, db):
    dom = browse(server.url + "#view=runs&offset=100", "runs-past-the-end", shot=False)
    assert 'data-ready="runs"' in dom
    assert page_text(dom) == "1–9 of 9"
    keys = [r[0] for r in db.execute("SELECT key FROM runs ORDER BY id")]
    assert [r[-1] for r in table_rows(dom, "runs-table")[1:]] == keys
    dom = browse(server.url + "#view=runs&status=skipped&offset=100", "runs-none", shot=False)  # no run matches
    assert page_text(dom) == "no runs"
    assert len(table_rows(dom, "runs-table")) == 1


def test_a_comparison_figure_draws_the_stores_means(server, db):
    dom = browse(server.url + "#view=compare&metric=mean_area&group=algorithm&x=param.w"
                 "&experiment=sweep", "compare")
    assert 'data-ready="compare"' in dom
    assert re.search(r'<canvas id="compare-chart"[^>]*data-points="4"', dom), "figure not drawn"
    shown = json.loads(html.unescape(re.search(r'<pre id="compare-data"[^>]*>(.*?)</pre>', dom, re.S).group(1)))
    for row in shown:
        want = db.execute("SELECT avg(mean_area) FROM runs WHERE algorithm = ? AND status = 'ok' "
                          "AND json_extract(problem_params, '$.w') = ? AND spec_file LIKE '%#sweep'",
                          (row["group"], row["x"])).fetchone()[0]
        assert row["mean"] == pytest.approx(want)
    assert re.search(r'<canvas id="profile-chart"[^>]*data-instances="4"', dom)


def test_a_runs_steps_render(server, db):
    run = db.execute("SELECT id, algorithm, steps FROM runs WHERE algorithm = 'hc4' ORDER BY id").fetchone()
    dom = browse(server.url + f"#view=run&id={run['id']}&step=3", "run")
    assert 'data-ready="run"' in dom
    rows = table_rows(dom, "steps-table")
    steps = db.execute("SELECT step, status FROM steps WHERE run_id = ? ORDER BY step", (run["id"],)).fetchall()
    assert len(rows) - 1 == len(steps) == run["steps"]
    assert [(r[0], r[1]) for r in rows[1:]] == [(str(s["step"]), s["status"]) for s in steps]
    assert re.search(rf'<canvas id="steps-chart"[^>]*data-steps="{len(steps)}"', dom)
    values = table_rows(dom, "step-values")
    assert [r[0] for r in values[1:]] == [r[0] for r in db.execute(
        "SELECT var FROM step_values WHERE run_id = ? AND step = 3 ORDER BY pos", (run["id"],))]
    # Every table has a CSV button; its CSV holds the API's full values, not the rounded display.
    tables = re.findall(r'<table id="([^"]+)"', dom)
    assert sorted(re.findall(r'<button class="csv" data-table="([^"]+)"', dom)) == sorted(tables)
    full = csv_rows(dom, "steps-table")
    assert full != rows  # the display rounds
    value = lambda t: None if t == "" else float(t)
    stored = db.execute("SELECT area, centre_error, solve_time_s FROM steps WHERE run_id = ? ORDER BY step",
                        (run["id"],)).fetchall()
    assert [tuple(map(value, r[3:6])) for r in full[1:]] == [tuple(r) for r in stored]
    info = dict(csv_rows(dom, "run-info")[1:])
    assert value(info["mean_area"]) == db.execute("SELECT mean_area FROM runs WHERE id = ?", (run["id"],)).fetchone()[0]


def test_a_run_link_finds_its_run_by_key_or_says_it_is_gone(server, db):
    linked, other = db.execute("SELECT id, key FROM runs ORDER BY id LIMIT 2").fetchall()
    # The link's id now names another run (a retry, --force or merge renumbered): the key wins.
    dom = browse(server.url + f"#view=run&id={linked['id']}&key={urllib.parse.quote(other['key'], safe='')}",
                 "run-by-key", shot=False)
    assert 'data-ready="run"' in dom
    assert table_rows(dom, "run-info")[1] == ["key", other["key"]]
    dom = browse(server.url + f"#view=run&id={linked['id']}&key=no-such-key", "run-key-gone", shot=False)
    assert 'data-ready="error"' in dom
    assert "The linked run (key no-such-key) is not in this store." in dom
    assert table_rows(dom, "run-info") == table_rows(dom, "steps-table") == []  # not run linked['id']


@pytest.fixture(scope="module")
def claims(store_dir, tmp_path_factory):
    """A server of a copy of the store, and the path of its paper/claims.json
    for a test to write (the shared store's has none: test_api checks that)."""
    directory = tmp_path_factory.mktemp("claims")
    shutil.copy(os.path.join(store_dir, "results.sqlite"), directory)
    os.makedirs(directory / "paper")
    s = Server(str(directory))
    yield s, directory / "paper" / "claims.json"
    assert s.stop() == 0


def test_claims_that_are_not_objects_are_skipped_with_a_note(claims):
    server, path = claims
    path.write_text('[{"claim": "a", "verdict": "ok"}, null, 3, {"claim": "b", "measured": 18.82390382932919}]')
    dom = browse(server.url + "#view=claims", "claims-skipped", shot=False)
    assert 'data-ready="claims"' in dom
    assert csv_rows(dom, "claims-table") == [["claim", "verdict", "measured"], ["a", "ok", ""],
                                             ["b", "", "18.82390382932919"]]
    assert "Skipped the entries that are not objects: #2 (null), #3 (a number)." in dom


def test_a_claims_file_of_the_wrong_shape_says_so(claims):
    server, path = claims
    path.write_text('{"claims": {"a": 1}}')
    dom = browse(server.url + "#view=claims", "claims-wrong-shape", shot=False)
    assert 'data-ready="error"' in dom
    assert ('paper/claims.json is not a list of claims: its "claims" holds an object, not an array of objects.'
            in html.unescape(dom))
    assert table_rows(dom, "claims-table") == []


def test_the_figures_view_shows_dir_figures(server):
    dom = browse(server.url + "#view=figures", "figures")
    assert 'data-ready="figures"' in dom
    assert re.findall(r'<img src="([^"]+)"', dom) == ["/figures/area.png"]


def test_a_chosen_steps_estimate_is_drawn(kinds_server, kinds_db):
    run = kinds_db.execute("SELECT id FROM runs WHERE algorithm = 'particle-filter'").fetchone()["id"]
    estimate = kinds_server.json(f"/api/runs/{run}/steps/2/estimate")
    dom = browse(kinds_server.url + f"#view=run&id={run}&step=2", "estimate")
    assert 'data-ready="run"' in dom
    canvas = re.search(r'<canvas id="estimate-chart"[^>]*>', dom).group(0)
    assert 'data-kind="particles"' in canvas
    assert f'data-drawn="{len(estimate["data"]["x"]) + 1}"' in canvas  # particles and their box
    assert "re-run reproduces the stored step" in dom
