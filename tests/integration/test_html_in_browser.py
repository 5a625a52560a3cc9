"""Every kind of report opened in a real browser: headless Chromium (the distribution's package) loads each page
from disk and must show no console error, ask for nothing beyond the file itself, and draw every plot and every
circuit. A screenshot of each page is kept (folder ``HYDROSERVO_ARTIFACTS``, default ``test-artifacts/``).

Chromium is driven through the DevTools protocol by playwright, with ``executable_path`` the system's browser
(playwright never downloads one here). Without Chromium or playwright the tests are skipped, saying why; CI
installs both (``.ci/run``).

Also, without a browser: the writer escapes text, carries plotly.js once per page with figures and not at all
without, and keeps every section and item.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from hydroservo.data import example_files
from hydroservo.io.html import Drawing, Figure, Notice, Page, Section, Table, Text, render_html

ROOT = Path(__file__).resolve().parents[2]
ARTIFACTS = Path(os.environ.get("HYDROSERVO_ARTIFACTS", ROOT / "test-artifacts"))
CHROMIUM = os.environ.get("HYDROSERVO_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")


# -- the writer, without a browser ------------------------------------------------------------------------
def test_the_page_escapes_text_and_keeps_every_section() -> None:
    page = Page("a <b> & c", "sub <i>", [
        Section("one", [Text("x < y"), Table(["n", "v"], [["<s>", 1.23456789], [None, float("nan")]], "cap <t>")]),
        Section("two", [Notice("careful <u>", "error"), Drawing('<?xml version="1.0"?><svg id="d"></svg>', "drawn")]),
    ], "made <here>")
    html = render_html(page)
    assert "<b>" not in html and "&lt;b&gt;" in html and "&lt;s&gt;" in html and "&lt;u&gt;" in html
    assert "1.2346" in html and "–" in html  # 5 significant digits; missing values as a dash
    assert html.count("<section") == 2 and '<svg id="d"></svg>' in html and "<?xml" not in html
    assert "Plotly" not in html  # no figure: no plotly.js


def test_plotly_is_carried_once_whatever_the_number_of_figures() -> None:
    spec = {"data": [{"type": "scatter", "x": [0, 1], "y": [1, 2]}], "layout": {}}
    html = render_html(Page("p", sections=[Section("s", [Figure(spec), Figure(spec), Figure(spec)])]))
    assert html.count("Plotly.newPlot(") == 3
    assert html.count("<script>") == 3  # the configuration, plotly.js, the three plots
    assert "https://" not in html.split("<script>", 2)[1][:200]  # nothing to fetch before plotly.js


# -- every report, in Chromium --------------------------------------------------------------------------
def _reports(folder: Path) -> dict[str, Callable[[], Any]]:
    """A report of every kind, with options that make each quick."""
    from hydroservo.workflows import (
        draw,
        fluid,
        ladder,
        linear,
        report,
        sensitivity,
        servovalve,
        simulate,
        staged_slot,
        validate,
        valve,
    )

    for name, text in example_files().items():
        (folder / name).write_text(text, encoding="utf-8")
    run = simulate.run("flight-simulator", t_end="0.5 s", write="csv")
    run.write(folder / "run")
    return {
        "model-report": lambda: report.run("position-servo", t_end="0.3 s"),
        "result-report": lambda: report.run(str(folder / "run" / "flight-simulator.csv")),
        "simulate": lambda: simulate.run(str(folder / "pump_circuit.toml"), t_end="0.5 s", write="none"),
        "draw": lambda: draw.run("robot-arm"),
        "linearize": lambda: linear.run("robot-arm", t="0.35 s", free=["load.x"], inputs=["spool.u"],
                                        outputs=["load.v"], frequencies=[5.0, 20.0], simulate=[0.003], write=False),
        "ladder": lambda: ladder.run("robot-arm", steps=[0.368], models=["nonlinear", "linear"], points=101),
        "sensitivity-oat": lambda: sensitivity.run("robot-arm", vary={"valve.c_v": "1e-4..2e-4"}, levels=3,
                                                   points=101),
        "sensitivity-sobol": lambda: sensitivity.run("robot-arm", method="sobol", n=4, threads=1, points=101,
                                                     vary={"valve.c_v": "1e-4..2e-4", "load.m": "15kg..35kg"}),
        "valve-fit": lambda: valve.fit(str(folder / "my_valve.toml"), curves=str(folder / "measured.csv")),
        "valve-bode": lambda: valve.bode("KBSDG4V-3", amplitudes=[0.05, 0.5], frequencies=[10, 50, 100, 200]),
        "valve-fit-dynamics": lambda: valve.fit_dynamics(str(folder / "bode.csv"), models="first-order"),
        "characteristics": lambda: staged_slot.characteristics("aerospace-example", temperatures=[-15, 32],
                                                               points=41),
        "servovalve-bench": lambda: servovalve.bench(tests=["static", "steps"], points=5),
        "validate": lambda: validate.run("robot-arm-friction"),
        "fluid": lambda: fluid.run("all", temperature="-40,20,70", pressure="0,30 MPa"),
    }


@pytest.fixture(scope="module")
def browser() -> Any:
    if CHROMIUM is None:
        pytest.skip("no Chromium (Debian: apt-get install chromium; or set HYDROSERVO_CHROMIUM)")
    sync = pytest.importorskip("playwright.sync_api", reason="playwright is in the test extra: pip install -e .[test]")
    with sync.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=[
            "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
            "--disable-sync", "--no-first-run", "--disable-quic"])
        yield b
        b.close()


@pytest.fixture(scope="module")
def pages(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    import matplotlib

    matplotlib.use("Agg")
    folder = tmp_path_factory.mktemp("reports")
    out = {}
    for name, make in _reports(folder).items():
        path = folder / f"{name}.html"
        make().to_html(path)
        out[name] = path
    return out


KINDS = ["model-report", "result-report", "simulate", "draw", "linearize", "ladder", "sensitivity-oat",
         "sensitivity-sobol", "valve-fit", "valve-bode", "valve-fit-dynamics", "characteristics", "servovalve-bench",
         "validate", "fluid"]


@pytest.mark.slow
@pytest.mark.parametrize("kind", KINDS)
def test_every_report_opens_in_a_browser_offline_and_draws_everything(kind: str, pages: dict[str, Path],
                                                                       browser: Any) -> None:
    path = pages[kind]
    context = browser.new_context(viewport={"width": 1280, "height": 900}, offline=True)
    page = context.new_page()
    errors: list[str] = []
    requests: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("request", lambda r: requests.append(r.url))
    page.goto(path.as_uri())
    page.wait_for_load_state("load")
    plots = page.evaluate("document.querySelectorAll('.plot').length")
    drawn = page.evaluate("[...document.querySelectorAll('.plot')].filter(d => d.querySelector('.main-svg')).length")
    traces = page.evaluate("[...document.querySelectorAll('.plot')].map(d => (d.data || []).length)")
    drawings = page.evaluate("document.querySelectorAll('.drawing svg').length")
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(ARTIFACTS / f"{kind}.png"), full_page=True)
    context.close()
    assert errors == [], f"{kind}: console errors {errors[:3]}"
    assert requests == [path.as_uri()], f"{kind}: requests beyond the file: {requests[1:4]}"
    assert drawn == plots, f"{kind}: {plots - drawn} of {plots} plots not drawn"
    assert all(n > 0 for n in traces), f"{kind}: a plot without data: {traces}"
    if kind in ("model-report", "simulate", "draw", "linearize", "ladder", "sensitivity-oat", "sensitivity-sobol"):
        assert drawings == 1, f"{kind}: the circuit is missing"
    if kind not in ("draw", "validate"):
        assert plots >= 1, f"{kind}: no plot"
