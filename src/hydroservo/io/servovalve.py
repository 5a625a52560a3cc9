"""Files of the servovalve test bench as CSV, in the units a bench reports (mA, L/min, bar, ms, um, Hz, dB)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = [
    "write_static_characteristic",
    "write_sensitivity",
    "write_figures",
    "write_steps",
    "write_hysteresis",
    "write_blocked",
    "write_bench_bode",
]


def write_static_characteristic(bench: Any, path: str | Path) -> Path:
    """Write the flow-current characteristic of a :class:`hydroservo.analysis.servovalve.StaticBench`."""
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


def write_sensitivity(sens: Any, path: str | Path) -> Path:
    """Write the elasticities of a :class:`hydroservo.analysis.servovalve.Sensitivity` (one row per parameter)."""
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


def write_figures(report: Any, path: str | Path) -> Path:
    """The figures of a :class:`hydroservo.analysis.servovalve_bench.Report`: figure, value, unit."""
    rows = [f'"{name}", {float(value)!r}, "{unit}"' for name, value, unit in report.table()]
    return _write(path, [f"# {report.label} at {report.p_s / 1e5!r} bar, rated current {report.i_rated * 1e3!r} mA",
                         "figure, value, unit"], rows)


def write_steps(report: Any, path: str | Path) -> Path:
    """The square-wave tests: time from the rising step, then current, flow and flapper tip per fraction."""
    steps = report.steps
    cols = ", ".join(f"i {s.fraction * 100:g}% [mA], Q {s.fraction * 100:g}% [L/min], x {s.fraction * 100:g}% [um]"
                     for s in steps)
    rows = []
    for k, t in enumerate(steps[0].t):
        vals = [f"{t * 1e3!r}"]
        for s in steps:
            vals += [f"{s.current[k] * 1e3!r}", f"{s.flow[k] * 6e4!r}", f"{s.flapper[k] * 1e6!r}"]
        rows.append(", ".join(vals))
    return _write(path, ["t [ms], " + cols], rows)


def write_hysteresis(report: Any, path: str | Path) -> Path:
    """The slow-sine loop: current and no-load flow over one period."""
    hy = report.hysteresis
    rows = [f"{i * 1e3!r}, {q * 6e4!r}" for i, q in zip(hy.currents, hy.flows, strict=True)]
    return _write(path, [f"# sine of rated amplitude at {hy.frequency!r} Hz", "i [mA], Q [L/min]"], rows)


def write_blocked(report: Any, path: str | Path) -> Path:
    """The blocked-port cycle: current, load pressure and flow from supply."""
    bl = report.blocked
    rows = [
        f"{i * 1e3!r}, {p / 1e5!r}, {q * 6e4!r}"
        for i, p, q in zip(bl.currents, bl.load_pressure, bl.leakage, strict=True)
    ]
    return _write(path, [f"# ports blocked, sine at {bl.frequency!r} Hz", "i [mA], p_A - p_B [bar], Q_supply [L/min]"], rows)


def write_bench_bode(report: Any, path: str | Path) -> Path:
    """The frequency response: frequency, then amplitude ratio and phase per amplitude (empty: not periodic)."""
    bode = report.bode

    def num(v: float) -> str:
        return repr(float(v)) if v == v else ""

    cols = ", ".join(f"gain {a * 100:g}% [dB], phase {a * 100:g}% [deg]" for a in bode.amplitudes)
    rows = [
        ", ".join([f"{f!r}"] + [f"{num(bode.gain_db[k, j])}, {num(bode.phase_deg[k, j])}" for k in range(len(bode.amplitudes))])
        for j, f in enumerate(bode.frequencies)
    ]
    return _write(path, ["# no-load flow against current, relative to the lowest frequency", "f [Hz], " + cols], rows)
