"""docs/python.md's API reference is the one the docstrings give (python/tools/api_reference.py)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python", "tools"))

import api_reference  # noqa: E402


def test_docs_python_md_api_reference_is_current():
    with open(os.path.join(ROOT, "docs", "python.md")) as f:
        text = f.read()
    assert api_reference.updated(text) == text, (
        "docs/python.md is out of date: run PYTHONPATH=build/release/python /usr/bin/python3 "
        "python/tools/api_reference.py --write docs/python.md")


def test_every_public_name_has_a_docstring():
    import rbcstab
    missing = [n for n in rbcstab.__all__ if not n.startswith("__") and not (getattr(rbcstab, n).__doc__ or "").strip()]
    assert not missing, missing


def _python_blocks(text):
    """The ```python blocks of a Markdown text, dedented (a block inside a list item is indented)."""
    import re
    import textwrap
    return [textwrap.dedent(m.group(2)) for m in re.finditer(r"^( *)```python\n(.*?)^\1```", text, re.S | re.M)]


def test_python_blocks_are_found():
    blocks = _python_blocks("a\n```python\nx = 1\n```\n- item\n  ```python\n  y = 2\n  ```\n")
    assert blocks == ["x = 1\n", "y = 2\n"]


def test_every_python_block_of_the_docs_runs(tmp_path):
    """Each block of docs/python.md runs as a script from the repository's root (its paths are the docs'),
    with matplotlib drawing off screen: a block that raises fails here with its text."""
    import subprocess
    with open(os.path.join(ROOT, "docs", "python.md")) as f:
        blocks = _python_blocks(f.read())
    assert len(blocks) >= 4
    env = dict(os.environ, MPLBACKEND="Agg")
    for k, block in enumerate(blocks):
        script = tmp_path / f"block_{k}.py"
        script.write_text(block)
        out = subprocess.run([sys.executable, str(script)], cwd=ROOT, env=env, capture_output=True, text=True)
        assert out.returncode == 0, f"docs/python.md block {k + 1} failed:\n{block}\n{out.stderr[-3000:]}"
