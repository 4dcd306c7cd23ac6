"""Writes examples/python/tour.ipynb from examples/python/tour.py, cell by cell, executed
with its outputs kept (tables, the figure, the 3D view): the script's docstring becomes the
first text cell, each ``# %%`` line starts a code cell and each ``# %% [markdown]`` line a text
cell (its lines without the leading ``# ``). It needs kinsyn installed (``pip install
./crates/kinsyn-py``), nbclient, ipykernel, pandas and matplotlib.

    python examples/python/make_notebook.py          # rewrite tour.ipynb, executed
    python examples/python/make_notebook.py --check  # exit 1 when its cells are out of date
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import nbformat

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "tour.py"
NOTEBOOK = HERE / "tour.ipynb"


def notebook(script: str) -> nbformat.NotebookNode:
    """The notebook of the cells of ``script`` (the text of tour.py)."""
    doc = ast.get_docstring(ast.parse(script)) or ""
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nb.metadata["language_info"] = {"name": "python"}
    cells = [nbformat.v4.new_markdown_cell("# " + doc)]
    body = script.split("\n# %%", 1)[1]
    for chunk in body.split("\n# %%"):
        head, _, text = chunk.partition("\n")
        text = text.strip("\n")
        if head.strip() == "[markdown]":
            lines = [line[2:] if line.startswith("# ") else line.lstrip("#") for line in text.splitlines()]
            cells.append(nbformat.v4.new_markdown_cell("\n".join(lines)))
        else:
            cells.append(nbformat.v4.new_code_cell(text))
    nb.cells = cells
    # Cell ids from their position, so that the file is the same at every run.
    for k, cell in enumerate(nb.cells):
        cell["id"] = f"cell-{k}"
    return nb


def executed(nb: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """``nb`` run in a fresh ``python3`` kernel from this folder, every output kept; no
    timings, so that a run gives the same file as the last when the results are the same."""
    import nbclient

    nbclient.NotebookClient(
        nb, kernel_name="python3", timeout=600, record_timing=False, resources={"metadata": {"path": str(HERE)}}
    ).execute()
    return nb


def sources(nb: nbformat.NotebookNode) -> list:
    """The cells' kinds and texts: what the script decides, outputs aside."""
    return [(c.cell_type, c.source) for c in nb.cells]


def text(nb: nbformat.NotebookNode) -> str:
    return nbformat.writes(nb) + "\n"


def main() -> int:
    want = notebook(SCRIPT.read_text(encoding="utf-8"))
    if "--check" in sys.argv[1:]:
        if sources(nbformat.read(NOTEBOOK, as_version=4)) != sources(want):
            print(f"{NOTEBOOK} is out of date: run python {Path(__file__).name}", file=sys.stderr)
            return 1
        return 0
    NOTEBOOK.write_text(text(executed(want)), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
