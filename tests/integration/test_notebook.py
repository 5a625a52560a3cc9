"""A notebook as a newcomer runs it, executed by a real kernel (nbclient, what ``jupyter nbconvert --execute``
runs): a system shows itself, then a result's plot shows once, and matplotlib's backend stays the notebook's."""

from __future__ import annotations

import pytest

nbformat = pytest.importorskip("nbformat", reason="nbformat (the [test] extra) executes notebooks")
nbclient = pytest.importorskip("nbclient", reason="nbclient (the [test] extra) executes notebooks")
pytest.importorskip("ipykernel", reason="ipykernel (the [test] extra) runs the notebook's kernel")


def _run(*cells: str) -> list[list[dict]]:
    """The outputs of each cell of a notebook of ``cells``, executed in a fresh Python kernel."""
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(source) for source in cells]
    nbclient.NotebookClient(nb, timeout=300, kernel_name="python3").execute()
    return [list(cell.outputs) for cell in nb.cells]


def _pictures(outputs: list[dict]) -> int:
    return sum("image/png" in out.get("data", {}) for out in outputs)


def _said(outputs: list[dict]) -> str:
    return "".join(out.get("text", "") for out in outputs if out["output_type"] == "stream")


@pytest.mark.slow
def test_a_notebook_shows_a_system_then_a_plot_once_each_on_its_own_backend() -> None:
    first, system, plot, kept, shown_later, backend = _run(
        'import hydroservo as hs\nresult = hs.load_model("flight-simulator").simulate(t_end=0.3)\nresult.plot("p1")',
        'system = hs.load_model("flight-simulator")\nsystem',
        "result.plot()",  # the cell's value is the figure, which pyplot also holds
        'figure = result.plot("y")',
        "figure",
        "import matplotlib\nprint(matplotlib.get_backend())",
    )
    assert _pictures(first) == 1 and _said(first) == "", first  # once, not as the value and again by pyplot
    # the system: its page (circuit drawn, notes), once
    assert [out["output_type"] for out in system] == ["execute_result"]
    assert "<svg" in system[0]["data"]["text/html"] and "loop gain is about four times" in system[0]["data"]["text/html"]
    # the plot: one picture, no warning (drawing the circuit did not switch matplotlib to Agg)
    assert _pictures(plot) == 1 and _said(plot) == "", plot
    assert _pictures(kept) == 1 and _said(kept) == ""  # shown by the notebook although kept in a variable
    assert _pictures(shown_later) == 1  # and again where a later cell asks for it
    assert "inline" in _said(backend)
