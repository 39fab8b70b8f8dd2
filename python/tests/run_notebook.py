"""Executes one notebook top to bottom with Debian's Jupyter kernel (nbclient); any cell error, including a
failed claim check (an assert), fails the test. The notebook runs in its own folder (scene paths are relative to
it) and is not modified: outputs are discarded. Usage: run_notebook.py NOTEBOOK.ipynb"""
import os
import sys
import time

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError


def main():
    path = os.path.abspath(sys.argv[1])
    nb = nbformat.read(path, as_version=4)
    os.environ.setdefault("MPLBACKEND", "Agg")
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # quiets the kernel's debugger warning
    client = NotebookClient(nb, timeout=900, kernel_name="python3",
                            resources={"metadata": {"path": os.path.dirname(path)}})
    start = time.monotonic()
    try:
        client.execute()
    except CellExecutionError as e:
        print(f"{os.path.basename(path)}: a cell failed\n{e}", file=sys.stderr)
        return 1
    print(f"{os.path.basename(path)}: {len(nb.cells)} cells executed in {time.monotonic() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
