"""The top-level README's Python example runs as shown (from the repository's root)."""
import os
import re
import subprocess
import pathlib
import sys

import dda
from conftest import REPO


def test_readme_python_example():
    text = (REPO / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "README.md has no ```python block"
    r = subprocess.run([sys.executable, "-c", blocks[0]], cwd=REPO, capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, PYTHONPATH=str(pathlib.Path(dda.__file__).resolve().parents[1])))
    assert r.returncode == 0, r.stderr
    # Two squares exchange their velocities (Paper A Sect. 4.1): the printed time is the run's end.
    assert r.stdout.split()[0].startswith("1.0") or r.stdout.split()[0].startswith("0.99"), r.stdout
