"""The README's Python session runs as written, from a folder laid out like
the repository root."""

import os
import re


def test_the_readmes_python_session_runs(source_dir, tmp_path, monkeypatch):
    readme = open(os.path.join(source_dir, "README.md"), encoding="utf-8").read()
    block = re.search(r"<!-- python session[^>]*-->\n```python\n(.*?)```", readme, re.S)
    assert block, "README.md has no python session block"
    lines = [l for l in block.group(1).splitlines() if l.strip()]
    assert len(lines) == 5, "the README promises a five-line session"
    for d in ("examples", "specs"):
        os.symlink(os.path.join(source_dir, d), tmp_path / d)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    *body, last = lines
    exec("\n".join(body), namespace)
    table = eval(last, namespace)
    assert set(namespace["runs"]["status"]) == {"ok"}
    # 3B-BC4 runs only on the car track, where every box holds the truth.
    assert table.loc["3b-bc4", "consistency_rate"] == 1.0 and table["mean_area"].notna().all()
