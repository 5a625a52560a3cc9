"""Files of the servovalve test bench: the static characteristic as CSV (mA, L/min)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["write_static_characteristic", "write_sensitivity"]


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
