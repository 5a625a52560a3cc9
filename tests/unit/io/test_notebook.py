"""How a notebook shows a system and a result (hydroservo.io.notebook), their text reprs, and what plot() does
where nothing would show it."""

from __future__ import annotations

import base64
import re
import warnings

import pytest

import hydroservo as hs


@pytest.fixture(scope="module")
def flight() -> tuple[hs.System, hs.Result]:
    system = hs.load_model("flight-simulator")
    return system, system.simulate(t_end=0.3, n_points=61)


def test_a_system_shows_what_it_is_its_source_notes_circuit_and_parameters(flight) -> None:
    system, _ = flight
    text = repr(system)
    assert text.startswith("<System 'flight-simulator': Closed-loop") and "12 components" in text
    assert "object at 0x" not in text
    page = system._repr_html_()
    assert "FlightSimulatorND (published)" in page and "loop gain is about four times" in page  # source, note
    assert "<svg" in page and 'id="component:cyl"' in page  # the circuit
    folded = page[page.index("<summary>Parameters</summary>"):]
    assert "6400 lbf" in folded and "1500 psi" in folded  # parameters as the file gives them
    assert "<script" not in page  # shows in untrusted and exported notebooks too


def test_a_result_shows_its_run_main_signals_in_the_model_units_and_a_plot(flight) -> None:
    _, result = flight
    text = repr(result)
    assert re.fullmatch(r"<Result of 'flight-simulator': 0 to 0\.3 s, 61 times, 38 signals \(rodas3, \d+ steps\)>", text)
    page = result._repr_html_()
    main = page[: page.index("<details>")]
    rows = re.findall(r"<tr><td>([^<]+)</td><td>([^<]+)</td>", main)
    assert rows == [("vi", "V"), ("eo", "V"), ("xv", "in"), ("ydot", "in/s"), ("y", "in"), ("p1", "psi"), ("p2", "psi")]
    png = base64.b64decode(re.search(r'src="data:image/png;base64,([^"]+)"', page).group(1))
    assert png.startswith(b"\x89PNG") and len(png) > 20_000
    every = page[page.index("<details>"):]
    assert "All 38 signals" in every and "<td>cyl.m_oil</td>" in every


def test_a_result_with_warnings_says_so_first(tmp_path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = hs.load_model("position-servo").simulate(t_end=1.2, n_points=1201)
    assert "2 warning(s)" in repr(result)
    page = result._repr_html_()
    flagged = re.search(r"cyl\.pB = 8\d\.\d+ MPa", page)
    assert flagged and flagged.start() < page.index("<table>")


def test_plot_without_a_file_warns_where_nothing_can_show_it(flight, tmp_path) -> None:
    import matplotlib
    import matplotlib.pyplot as plt

    _, result = flight
    assert matplotlib.get_backend().lower() == "agg"  # the tests run headless
    with pytest.warns(UserWarning, match="the figure is not shown.*give file="):
        fig = result.plot("y")
    plt.close(fig)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # written to a file: nothing to warn of
        fig = result.plot("y", file=tmp_path / "y.png")
    assert fig.axes[0].get_ylabel() == "y [in]" and (tmp_path / "y.png").stat().st_size > 5000


def test_showing_a_system_and_writing_a_plot_never_choose_a_backend(tmp_path) -> None:
    """In a fresh interpreter (a notebook's kernel before its first plot): drawing the circuit and writing a plot
    to a file neither import pyplot nor choose matplotlib's backend, so the notebook's own stays."""
    import subprocess
    import sys

    script = f"""
import sys
import matplotlib
chosen = []
matplotlib.use = lambda *a, **k: chosen.append(a)
import hydroservo as hs
system = hs.load_model("flight-simulator")
system._repr_html_()
result = system.simulate(t_end=0.05, n_points=11)
result._repr_html_()
result.plot("y", file={str(tmp_path / "y.png")!r})
print(chosen, "matplotlib.pyplot" in sys.modules)
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["[]", "False"] and (tmp_path / "y.png").stat().st_size > 5000


def test_a_batch_shows_its_runs_and_the_signal_they_differ_in_most(flight) -> None:
    system, _ = flight
    batch = system.batch({"load.m": ["2500 kg", "2900 kg", "3300 kg"]}, t_end=0.3)
    page = batch._repr_html_()
    assert page.startswith('<div class="hydroservo">') and "3 of 3 runs succeeded" in page
    assert "<th>load.m [kg]</th>" in page and page.count("<td>ok</td>") == 3
    assert "in every run that did not fail" in page and "vi in every run" not in page  # not the command: it is the same


def test_sensitivity_studies_show_their_table_and_plot() -> None:
    from hydroservo.analysis.sensitivity import one_at_a_time, sobol

    arm = hs.load_model("robot-arm")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        study = sobol(arm, {"valve.c_v": (1e-4, 2e-4), "load.m": ("15 kg", "35 kg")}, 8)
        oat = one_at_a_time(arm, {"load.m": ["15 kg", "35 kg"]}, n_points=101)
    page = study._repr_html_()
    assert "Sobol sensitivity study: valve.c_v, load.m (32 runs, 0 failed)" in page
    assert "<th>ST_conf</th>" in page and "data:image/png;base64," in page
    page = oat._repr_html_()
    assert "One-at-a-time study of &#x27;robot-arm&#x27;: load.m (2 levels)" in page and "data:image/png;base64," in page
