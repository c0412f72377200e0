"""docs/python.md runs: its ```python blocks, in order, in one namespace, from a folder whose
configs/ is the clone's (so that what the walk-through writes stays out of the clone)."""

import os
import re

SOURCE = os.environ.get("DRAPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def test_the_walk_through_runs(tmp_path, monkeypatch):
    with open(os.path.join(SOURCE, "docs", "python.md")) as page:
        blocks = re.findall(r"^```python\n(.*?)^```", page.read(), flags=re.S | re.M)
    assert len(blocks) >= 4
    os.symlink(os.path.join(os.path.abspath(SOURCE), "configs"), tmp_path / "configs")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for number, block in enumerate(blocks, 1):
        exec(compile(block, f"docs/python.md, block {number}", "exec"), namespace)
    assert (tmp_path / "tester.png").stat().st_size > 0
    assert abs(namespace["last"]["result"].drape_coefficient - 0.72) < 0.01
