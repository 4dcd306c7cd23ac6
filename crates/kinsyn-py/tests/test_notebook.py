"""The notebook examples/python/tour.ipynb: it is the cells of examples/python/tour.py (as
examples/python/make_notebook.py writes them), saved with its outputs (a table, a figure and the
3D view, shown in the saved notebook and in its HTML rendering by nbconvert), it runs without a
cell error in a fresh Python kernel (nbclient; the kernel ``python3`` of this interpreter, from
ipykernel), and its result lines ``paper NNN: WHAT: kinsyn X, paper Y`` give the papers' values,
written here from the papers:

- 000 §5.1: the 3-UPS has 6 dof with every input free;
- 001 §2: both end-effectors of the HEXA make the Schönflies motion, 4 dof;
- 002 §4–5: the 3-RPS-3-SPR has 6 dof at a general configuration;
- 003 §5, Fig. 10: two real assemblies at the inputs (141.956°, 203.366°, 337.773°, 305.499°);
- 004 §4: the 4-RUU's Schönflies operation mode, 4 dof.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples" / "python"
NOTEBOOK = EXAMPLES / "tour.ipynb"

# (paper, what the line names) -> the paper's value.
PAPER_VALUES = {
    ("000", "3-UPS platform dof, every input free"): 6,
    ("001", "ee1 dof"): 4,
    ("001", "ee2 dof"): 4,
    ("002", "end-effector dof at a general configuration"): 6,
    ("003", "real assemblies"): 2,
    ("004", "platform dof with the inputs free"): 4,
}
RESULT = re.compile(r"^paper (\d{3}): (.+?): kinsyn (\S+), paper (\S+)")


def _rich_outputs(nb) -> dict:
    """How many outputs of each kind the notebook shows: tables (HTML with a table), figures
    (PNG images) and views (the kinsyn view's frame)."""
    found = {"table": 0, "figure": 0, "view": 0}
    for c in nb.cells:
        if c.cell_type != "code":
            continue
        for o in c.outputs:
            data = o.get("data", {})
            html = data.get("text/html", "")
            found["table"] += "<table" in html
            found["figure"] += "image/png" in data
            found["view"] += bool(re.search(r"<iframe[^>]*srcdoc=", html)) and "kinsyn-data" in html
    return found


def test_notebook_is_the_scripts_cells_with_their_outputs():
    sys.path.insert(0, str(EXAMPLES))
    try:
        import make_notebook
    finally:
        sys.path.remove(str(EXAMPLES))
    want = make_notebook.notebook((EXAMPLES / "tour.py").read_text("utf-8"))
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nbformat.validate(nb)
    assert make_notebook.sources(nb) == make_notebook.sources(want), "run python examples/python/make_notebook.py"
    assert sum(bool(c.get("outputs")) for c in nb.cells if c.cell_type == "code") >= 8, "cells saved without outputs"
    found = _rich_outputs(nb)
    assert all(found.values()), found


def test_notebook_runs_and_gives_the_papers_values(tmp_path):
    sys.path.insert(0, str(EXAMPLES))
    try:
        import make_notebook
    finally:
        sys.path.remove(str(EXAMPLES))
    nb = make_notebook.notebook((EXAMPLES / "tour.py").read_text("utf-8"))
    make_notebook.executed(nb)  # raises CellExecutionError on the first cell error
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert not errors, errors
    lines = [
        line
        for c in nb.cells
        if c.cell_type == "code"
        for o in c.outputs
        if o.output_type == "stream" and o.name == "stdout"
        for line in o.text.splitlines()
    ]
    found = {}
    for line in lines:
        m = RESULT.match(line)
        if m:
            found[(m.group(1), m.group(2))] = (m.group(3), m.group(4))
    assert set(found) == set(PAPER_VALUES), found
    for key, value in PAPER_VALUES.items():
        kinsyn_value, printed = found[key]
        assert int(printed) == value, (key, printed)
        assert int(kinsyn_value) == value, (key, kinsyn_value)
    assert {k[0] for k in found} == {"000", "001", "002", "003", "004"}

    # Written with its outputs, and rendered as HTML: the table, the figure and the view show.
    assert all(_rich_outputs(nb).values()), _rich_outputs(nb)
    nbconvert = pytest.importorskip("nbconvert")
    html, _ = nbconvert.HTMLExporter().from_notebook_node(nb)
    (tmp_path / "tour.html").write_text(html, encoding="utf-8")
    assert "<table" in html
    assert "data:image/png;base64," in html
    assert re.search(r"<iframe[^>]*srcdoc=", html) and "kinsyn-data" in html
