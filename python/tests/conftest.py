"""Shared fixtures: the CLI built beside the package (RBCSTAB_CLI, set by ctest) for comparisons."""
import json
import os
import shutil
import subprocess

import pytest


def _cli_path():
    path = os.environ.get("RBCSTAB_CLI") or shutil.which("rbcstab")
    if not path:
        pytest.skip("the rbcstab CLI is not available (ctest sets RBCSTAB_CLI)")
    return path


@pytest.fixture
def cli():
    """cli(*args) -> the parsed JSON of `rbcstab <args> --json` (asserting exit 0)."""
    path = _cli_path()

    def run(*args):
        out = subprocess.run([path, *map(str, args), "--json"], check=True, capture_output=True, text=True)
        return json.loads(out.stdout)

    return run


def without_timing(d):
    """A CLI JSON object without its wall-clock fields (the only non-deterministic ones)."""
    if isinstance(d, dict):
        return {k: without_timing(v) for k, v in d.items() if k != "seconds" and not k.endswith("_seconds")}
    if isinstance(d, list):
        return [without_timing(v) for v in d]
    return d
