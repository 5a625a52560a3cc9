"""Files of the servovalve test bench as CSV, in the units a bench reports (mA, L/min, bar, ms, um, Hz, dB)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

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
    path = Path(path)
    lines = [
        f"# supply pressure = {bench.p_s / 1e5!r} bar",
        f"# rated current = {bench.i_rated * 1e3!r} mA",
        "i [mA], Q_SV [L/min], Q_supply [L/min]",
    ]
    lines += [
        f"{i * 1e3!r}, {q * 6e4!r}, {s * 6e4!r}"
        for i, q, s in zip(bench.currents, bench.flows, bench.supply_flows, strict=True)
    ]
    path.write_text("\n".join(lines) + "\n")
    return path


def write_sensitivity(sens: DesignStudy, path: str | Path) -> Path:
    """Write the elasticities of a :class:`hydroservo.analysis.servovalve_design.DesignStudy` (a row per parameter)."""
    path = Path(path)
    figures = list(sens.figures)
    params = list(next(iter(sens.elasticity.values())))
    lines = ["# elasticity: d ln(figure) / d ln(parameter), central differences of 1 %", "parameter, " + ", ".join(figures)]
    lines += [name + ", " + ", ".join(repr(float(sens.elasticity[f][name])) for f in figures) for name in params]
    path.write_text("\n".join(lines) + "\n")
    return path


def _write(path: str | Path, header: list[str], rows: list[str]) -> Path:
    path = Path(path)
    path.write_text("\n".join(header + rows) + "\n")
    return path


def write_figures(report: Report, path: str | Path) -> Path:
    """The figures of a :class:`hydroservo.analysis.servovalve_bench.Report`: figure, value, unit."""
    rows = [f'"{name}", {float(value)!r}, "{unit}"' for name, value, unit in report.table()]
    return _write(path, [f"# {report.label} at {report.p_s / 1e5!r} bar, rated current {report.i_rated * 1e3!r} mA",
                         "figure, value, unit"], rows)


def write_steps(report: Report, path: str | Path) -> Path:
    """The square-wave tests: time from the rising step, then current, flow and flapper tip per fraction."""
    steps = report.steps or []
    cols = ", ".join(f"i {s.fraction * 100:g}% [mA], Q {s.fraction * 100:g}% [L/min], x {s.fraction * 100:g}% [um]"
                     for s in steps)
    rows = []
    for k, t in enumerate(steps[0].t):
        vals = [f"{t * 1e3!r}"]
        for s in steps:
            vals += [f"{s.current[k] * 1e3!r}", f"{s.flow[k] * 6e4!r}", f"{s.flapper[k] * 1e6!r}"]
        rows.append(", ".join(vals))
    return _write(path, ["t [ms], " + cols], rows)


def write_hysteresis(report: Report, path: str | Path) -> Path:
    """The slow-sine loop: current and no-load flow over one period."""
    hy = report.hysteresis
    assert hy is not None, "the report has no hysteresis test"
    rows = [f"{i * 1e3!r}, {q * 6e4!r}" for i, q in zip(hy.currents, hy.flows, strict=True)]
    return _write(path, [f"# sine of rated amplitude at {hy.frequency!r} Hz", "i [mA], Q [L/min]"], rows)


def write_blocked(report: Report, path: str | Path) -> Path:
    """The blocked-port cycle: current, load pressure and flow from supply."""
    bl = report.blocked
    assert bl is not None, "the report has no blocked-port test"
    rows = [
        f"{i * 1e3!r}, {p / 1e5!r}, {q * 6e4!r}"
        for i, p, q in zip(bl.currents, bl.load_pressure, bl.leakage, strict=True)
    ]
    return _write(path, [f"# ports blocked, sine at {bl.frequency!r} Hz", "i [mA], p_A - p_B [bar], Q_supply [L/min]"], rows)


def write_bench_bode(report: Report, path: str | Path) -> Path:
    """The frequency response: frequency, then amplitude ratio and phase per amplitude (empty: not periodic)."""
    bode = report.bode
    assert bode is not None, "the report has no frequency response"

    def num(v: float) -> str:
        return repr(float(v)) if v == v else ""

    cols = ", ".join(f"gain {a * 100:g}% [dB], phase {a * 100:g}% [deg]" for a in bode.amplitudes)
    rows = [
        ", ".join([f"{f!r}"] + [f"{num(bode.gain_db[k, j])}, {num(bode.phase_deg[k, j])}" for k in range(len(bode.amplitudes))])
        for j, f in enumerate(bode.frequencies)
    ]
    return _write(path, ["# no-load flow against current, relative to the lowest frequency", "f [Hz], " + cols], rows)


def write_catalogue(fits: Sequence[CatalogueFit], path: str | Path, header: str) -> Path:
    """The catalogue models fitted to a servovalve: order, time constant, natural frequency, damping and the fit's
    largest gain and phase errors, a row per order (``header`` as the first comment line)."""
    rows = []
    for fit in fits:
        tau = fit.params.get("tau", float("nan")) * 1e3
        rows.append(f"{fit.order}, {tau!r}, {fit.params.get('omega_n', float('nan'))!r}, "
                    f"{fit.params.get('zeta', float('nan'))!r}, {fit.gain_error_db!r}, {fit.phase_error_deg!r}")
    return _write(path, [f"# {header}", "order, tau [ms], omega_n [rad/s], zeta [-], gain error [dB], phase error [deg]"],
                  rows)
