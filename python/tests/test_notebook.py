"""The tutorial notebook runs from the repository's root, as CI executes it, and prints
the worked examples' numbers (its own cells assert them too)."""

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
NOTEBOOK = REPO / "python" / "notebooks" / "tutorial.ipynb"


def test_the_tutorial_runs_and_prints_table_2() -> None:
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=120, resources={"metadata": {"path": str(REPO)}})
    client.execute()
    printed = "".join(
        out.get("text", "") + out.get("data", {}).get("text/plain", "")
        for cell in nb.cells
        if cell.cell_type == "code"
        for out in cell.get("outputs", [])
    )
    for line in ("A  =  9.59 µm", "E  =  7.70 µm", "M  =  3.99 µm", "R  =  6.55 µm", "B  =  4.12 µm"):
        assert line in printed, printed
    # 1 µm added to every upward reading adds 1 µm to the mean reversal value B̄.
    assert "B_mean: -3.69 µm → -2.69 µm" in printed, printed
    assert "['reversal_variation']" in printed, printed
