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


def test_the_stub_of_the_compiled_module_is_current():
    import stubs
    with open(os.path.join(ROOT, "python", "rbcstab", "_rbcstab.pyi")) as f:
        text = f.read()
    assert stubs.render() == text, (
        "python/rbcstab/_rbcstab.pyi is out of date: run PYTHONPATH=build/release/python /usr/bin/python3 "
        "python/tools/stubs.py --write python/rbcstab/_rbcstab.pyi")
    assert os.path.exists(os.path.join(ROOT, "python", "rbcstab", "py.typed"))


def test_a_type_checker_sees_every_keyword_and_its_type(tmp_path):
    """mypy over the package as built (its .py files and the stub) accepts the documented calls and flags a wrong
    type, a name outside a keyword's allowed values and an unknown keyword, each on its line."""
    import subprocess
    import pytest
    pytest.importorskip("mypy")
    import rbcstab
    package = os.path.dirname(os.path.dirname(rbcstab.__file__))
    (tmp_path / "good.py").write_text(
        "import rbcstab\n"
        "s = rbcstab.Scene(lambda_=5.0, B=2, model='modal', radius='3.9um', delta_l={3: 0.01})\n"
        "m = rbcstab.Model(s, 'modal')\n"
        "y = m.rhs(0.0, m.y0)\n"
        "x: float = s.Lambda\n")
    (tmp_path / "bad.py").write_text(
        "import rbcstab\n"
        "a = rbcstab.Scene(lambda_='five')\n"
        "b = rbcstab.Scene(model='bogus')\n"
        "c = rbcstab.Scene(nonsense=1)\n")
    env = dict(os.environ, MYPYPATH=package)

    def mypy(name):
        return subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", os.devnull,
                               "--ignore-missing-imports", name], cwd=tmp_path, env=env, capture_output=True,
                              text=True)

    good = mypy("good.py")
    assert good.returncode == 0, good.stdout + good.stderr
    bad = mypy("bad.py")
    assert bad.returncode == 1
    for line, what in ((2, '"lambda_"'), (3, '"model"'), (4, '"nonsense"')):
        assert any(out.startswith(f"bad.py:{line}: error") and what in out for out in bad.stdout.splitlines()), \
            bad.stdout
