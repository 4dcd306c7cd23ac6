"""The notebook examples/python/tour.ipynb: it is the cells of examples/python/tour.py (as
examples/python/make_notebook.py writes them, outputs cleared), it runs without a cell error in
a fresh Python kernel (nbclient; the kernel ``python3`` of this interpreter, from ipykernel),
and its result lines ``paper NNN: WHAT: kinsyn X, paper Y`` give the papers' values, written
here from the papers:

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


def test_notebook_is_the_scripts_cells_without_outputs():
    sys.path.insert(0, str(EXAMPLES))
    try:
        import make_notebook
    finally:
        sys.path.remove(str(EXAMPLES))
    want = make_notebook.text(make_notebook.notebook((EXAMPLES / "tour.py").read_text("utf-8")))
    assert NOTEBOOK.read_text("utf-8") == want, "run python examples/python/make_notebook.py"
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nbformat.validate(nb)
    assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code")


def test_notebook_runs_and_gives_the_papers_values():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb,
        kernel_name="python3",
        timeout=600,
        resources={"metadata": {"path": str(EXAMPLES)}},
    )
    client.execute()  # raises CellExecutionError on the first cell error
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
