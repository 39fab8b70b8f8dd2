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
