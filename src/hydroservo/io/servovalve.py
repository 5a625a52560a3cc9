"""Files of the servovalve test bench as CSV, in the units a bench reports (mA, L/min, bar, ms, um, Hz, dB)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from hydroservo.io.results import write_table

if TYPE_CHECKING:
    from hydroservo.analysis.servovalve_bench import Report, StaticTests
    from hydroservo.analysis.servovalve_design import DesignStudy
    from hydroservo.identification.servovalve_catalogue import CatalogueFit

__all__ = [
    "BENCH_FILES",
    "write_catalogue",
    "write_static_characteristic",
    "write_sensitivity",
    "write_figures",
    "write_steps",
    "write_hysteresis",
    "write_blocked",
    "write_bench_bode",
]


#: The files of the bench, per test (:data:`hydroservo.analysis.servovalve_bench.TESTS`).
BENCH_FILES: dict[str, list[str]] = {
    "static": ["characteristic.csv", "flow-current.png"],
    "blocked": ["blocked.csv", "blocked.png"],
    "steps": ["steps.csv", "steps.png"],
    "hysteresis": ["hysteresis.csv"],
    "threshold": [],
    "bode": ["bode.csv", "bode.png"],
}


def write_static_characteristic(bench: StaticTests, path: str | Path) -> Path:
    """Write the flow-current characteristic of :class:`hydroservo.analysis.servovalve_bench.StaticTests`."""
    rows = zip(bench.currents * 1e3, bench.flows * 6e4, bench.supply_flows * 6e4, strict=True)
    return write_table(path, ["i [mA]", "Q_SV [L/min]", "Q_supply [L/min]"], rows,
                       [f"supply pressure = {bench.p_s / 1e5!r} bar", f"rated current = {bench.i_rated * 1e3!r} mA"])


def write_sensitivity(sens: DesignStudy, path: str | Path) -> Path:
    """Write the elasticities of a :class:`hydroservo.analysis.servovalve_design.DesignStudy` (a row per parameter)."""
    figures = list(sens.figures)
    params = list(next(iter(sens.elasticity.values())))
    rows = [[name, *(float(sens.elasticity[f][name]) for f in figures)] for name in params]
    return write_table(path, ["parameter", *figures], rows,
                       ["elasticity: d ln(figure) / d ln(parameter), central differences of 1 %"])


def write_figures(report: Report, path: str | Path) -> Path:
    """The figures of a :class:`hydroservo.analysis.servovalve_bench.Report`: figure, value, unit (a row each:
    the figures have units of their own)."""
    rows = [[name, float(value), unit] for name, value, unit in report.table()]
    return write_table(path, ["figure", "value", "unit"], rows,
                       [f"{report.label} at {report.p_s / 1e5!r} bar, rated current {report.i_rated * 1e3!r} mA"])


def write_steps(report: Report, path: str | Path) -> Path:
    """The square-wave tests: time from the rising step, then current, flow and flapper tip per fraction."""
    steps = report.steps or []
    columns = ["t [ms]"]
    for s in steps:
        pct = f"{s.fraction * 100:g}%"
        columns += [f"i {pct} [mA]", f"Q {pct} [L/min]", f"x {pct} [um]"]
    rows = []
    for k, t in enumerate(steps[0].t):
        row = [t * 1e3]
        for s in steps:
            row += [s.current[k] * 1e3, s.flow[k] * 6e4, s.flapper[k] * 1e6]
        rows.append(row)
    return write_table(path, columns, rows)


def write_hysteresis(report: Report, path: str | Path) -> Path:
    """The slow-sine loop: current and no-load flow over one period."""
    hy = report.hysteresis
    assert hy is not None, "the report has no hysteresis test"
    rows = zip(hy.currents * 1e3, hy.flows * 6e4, strict=True)
    return write_table(path, ["i [mA]", "Q [L/min]"], rows, [f"sine of rated amplitude at {hy.frequency!r} Hz"])


def write_blocked(report: Report, path: str | Path) -> Path:
    """The blocked-port cycle: current, load pressure and flow from supply."""
    bl = report.blocked
    assert bl is not None, "the report has no blocked-port test"
    rows = zip(bl.currents * 1e3, bl.load_pressure / 1e5, bl.leakage * 6e4, strict=True)
    return write_table(path, ["i [mA]", "p_A - p_B [bar]", "Q_supply [L/min]"], rows,
                       [f"ports blocked, sine at {bl.frequency!r} Hz"])


def write_bench_bode(report: Report, path: str | Path) -> Path:
    """The frequency response: frequency, then amplitude ratio and phase per amplitude (empty: not periodic)."""
    bode = report.bode
    assert bode is not None, "the report has no frequency response"
    columns = ["f [Hz]"]
    for a in bode.amplitudes:
        columns += [f"gain {a * 100:g}% [dB]", f"phase {a * 100:g}% [deg]"]
    rows = []
    for j, f in enumerate(bode.frequencies):
        row = [f]
        for k in range(len(bode.amplitudes)):
            row += [bode.gain_db[k, j], bode.phase_deg[k, j]]
        rows.append(row)
    return write_table(path, columns, rows, ["no-load flow against current, relative to the lowest frequency"])


def write_catalogue(fits: Sequence[CatalogueFit], path: str | Path, header: str) -> Path:
    """The catalogue models fitted to a servovalve: order, time constant, natural frequency, damping and the fit's
    largest gain and phase errors, a row per order (``header`` as the first comment line)."""
    rows = [
        [fit.order, fit.params.get("tau", float("nan")) * 1e3, fit.params.get("omega_n", float("nan")),
         fit.params.get("zeta", float("nan")), fit.gain_error_db, fit.phase_error_deg]
        for fit in fits
    ]
    columns = ["order", "tau [ms]", "omega_n [rad/s]", "zeta [-]", "gain error [dB]", "phase error [deg]"]
    return write_table(path, columns, rows, [header])
