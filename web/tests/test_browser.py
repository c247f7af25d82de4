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

import pytest

CHROMIUM = shutil.which("chromium")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (scripts/deps.sh)")


def browse(url, name):
    """The DOM of url after its scripts ran, and a screenshot NAME.png."""
    shots = os.path.join(os.environ.get("ICPBENCH_BUILD_DIR", "build"), "web-screenshots")
    os.makedirs(shots, exist_ok=True)
    common = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
              "--no-first-run", "--disable-dev-shm-usage", "--virtual-time-budget=10000",
              "--window-size=1280,1800", f"--user-data-dir={shots}/profile-{name}"]
    dom = subprocess.run(common + ["--dump-dom", url], capture_output=True, text=True,
                         timeout=60, check=True).stdout
    subprocess.run(common + [f"--screenshot={shots}/{name}.png", url], capture_output=True,
                   timeout=60, check=True)
    assert os.path.getsize(f"{shots}/{name}.png") > 10000
    return dom


def table_rows(dom, table_id):
    """The cells' texts of each row of table id (header first)."""
    table = re.search(rf'<table id="{table_id}"[^>]*>(.*?)</table>', dom, re.S).group(1)
    return [[html.unescape(re.sub("<[^>]+>", "", c)) for c in re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", row, re.S)]
            for row in re.findall(r"<tr[^>]*>(.*?)</tr>", table, re.S)]


def test_the_runs_table_shows_the_stores_runs(server, db):
    dom = browse(server.url + "#view=runs", "runs")
    assert 'data-ready="runs"' in dom
    rows = table_rows(dom, "runs-table")
    keys = [r[0] for r in db.execute("SELECT key FROM runs ORDER BY id")]
    assert [r[-1] for r in rows[1:]] == keys
    assert "9 runs: 8 ok, 0 failed, 1 timeout, 0 skipped" in dom


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
