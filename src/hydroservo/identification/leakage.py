r"""Internal leakage of a cylinder from a locked-piston record ([Efe2014] section 4.5.5).

The experiment: the piston is held rigidly and the valve opened a little
towards chamber A. Without leakage chamber A would reach the supply pressure;
with leakage across the piston, oil flows P -> A -> B -> T and chamber A settles
below the supply while chamber B stays near the tank. The settled pressures
give the leakage coefficient of eq. 3.42, :math:`Q_{Li} = C_{Li}(p_A - p_B)`:
it is the value at which the model's chamber A is in balance (the valve's flow
in, through the model's own valve law with its laps, equal to the leakage out),
:func:`hydroservo.identification.steady.balancing_value`. The same balance in
chamber B is a cross-check.

Its uncertainty follows from the pressures' scatter over the settled interval
(the standard error of their means, propagated through the balance).

**How much the valve law decides it.** The leakage flow is small, so the
valve's P-A edge passes it at a small pressure drop, and there the orifice
law's regularisation (its laminar transition, :mod:`hydroservo.laws.orifice`)
is not negligible: the regularised root lies below the turbulent one by about
:math:`p_{tr}^2/(4\Delta p^2)`. The balance is therefore solved twice, with
the model's law and with the plain turbulent law (the transition taken to
zero), and the relative difference is reported as the *law sensitivity*, with
the edge's drop beside its transition pressure. On the example record (15 %
signal, 10 % overlap) the edge drops 0.34 bar, twice its transition, and the
two laws give C_Li 6.4 % apart (3.05e-13 and 3.25e-13 m^3/s/Pa, truth 3e-13): the model's own law is the one the model
simulates, but the answer is only as good as that law is near its transition.
Above a drop of about five times the transition the laws agree within 1 %; a
smaller opening (nearer the overlap) raises the drop. A warning says so when
the sensitivity exceeds 1 %.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.identification.calibration import driven_system, record_fault
from hydroservo.identification.records import Record
from hydroservo.identification.steady import balancing_value

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["LeakageEstimate", "leakage_from_record"]


@dataclass
class LeakageEstimate:
    """The internal leakage coefficient [m^3/s/Pa] from chamber A's balance (and B's, as a cross-check), its
    standard error, and the settled conditions it was read at (SI)."""

    parameter: str
    value: float
    stderr: float
    from_b: float
    interval: tuple[float, float]
    conditions: dict[str, float]
    warnings: list[str] = field(default_factory=list)
    #: the value with the plain turbulent orifice law (the valves' laminar transition taken to zero) [m^3/s/Pa]
    turbulent: float = math.nan
    #: the supply edge's pressure drop at the settled point and the valve law's transition pressure there [Pa]
    edge_drop: float = math.nan
    transition: float = math.nan

    @property
    def law_sensitivity(self) -> float:
        """(plain turbulent law - model's law) / model's law: how much the orifice law's laminar transition moves
        the answer [-] (NaN when the model has no such law)."""
        return self.turbulent / self.value - 1.0 if self.value and math.isfinite(self.turbulent) else math.nan

    def to_dict(self) -> dict[str, Any]:
        def finite(x: float) -> float | None:
            return x if math.isfinite(x) else None

        return {
            "parameter": self.parameter, "value": self.value, "unit": "m^3/s/Pa", "stderr": self.stderr,
            "from_chamber_b": finite(self.from_b),
            "law_sensitivity": {
                "turbulent_law_value": finite(self.turbulent),
                "relative_change_percent": finite(100.0 * self.law_sensitivity),
                "supply_edge_drop_Pa": finite(self.edge_drop), "transition_pressure_Pa": finite(self.transition),
            },
            "interval_s": list(self.interval), "conditions": dict(self.conditions), "warnings": list(self.warnings),
        }


def leakage_from_record(
    system: System,
    record: Record,
    *,
    inputs: Sequence[str] = ("command.y",),
    cylinder: str = "cyl",
    load: str = "load",
    window: tuple[float, float] | None = None,
) -> LeakageEstimate:
    """The internal leakage coefficient of ``system[cylinder]`` from a locked-piston ``record``.

    ``inputs`` drive the model from the record (the valve signal; add ``"supply.p"`` when the supply was
    logged); ``window`` is the settled interval [s] (default: the second half of the record). The piston is
    held where the record has it (``load.x``, else the model's start) at rest.
    """
    pA, pB = f"{cylinder}.pA", f"{cylinder}.pB"
    for n in (pA, pB):
        if n not in record:
            raise ParameterError(f"record {record.name!r}: no column {n!r}; the locked-piston test needs both chamber pressures")
    driven = driven_system(system, record, inputs)
    model = driven.build()
    p = driven.parameter_vector()
    fault = record_fault(model, p, record, [pA, pB, f"{load}.x", *inputs])
    if fault:
        raise ParameterError(fault)
    parameter = f"{cylinder}.C_Li"
    if parameter not in model.parameter_names:
        raise ParameterError(f"leakage: {system.name!r} has no parameter {parameter}")
    t0, t1 = record.span
    lo, hi = window if window is not None else (0.5 * (t0 + t1), t1)
    if not lo < hi:
        raise ParameterError(f"leakage: window {lo:g}..{hi:g} s: expected a start before the end")
    means, errors, halves = {}, {}, {}
    for n in (pA, pB):
        ch = record[n]
        sel = ch.valid & (ch.t >= lo) & (ch.t <= hi)
        if sel.sum() < 4:
            raise ParameterError(f"record {record.name!r}: fewer than four samples of {n} between {lo:g} s and {hi:g} s")
        vals = ch.to("Pa")[sel]
        means[n] = float(np.mean(vals))
        errors[n] = float(np.std(vals, ddof=1) / math.sqrt(vals.size))
        halves[n] = (float(np.mean(vals[: vals.size // 2])), float(np.mean(vals[vals.size // 2 :])))
    if not means[pA] > means[pB]:
        raise ParameterError(
            f"record {record.name!r}: over {lo:g}..{hi:g} s chamber A's pressure ({means[pA] / 1e5:.4g} bar, column "
            f"{pA!r}) is not above chamber B's ({means[pB] / 1e5:.4g} bar, column {pB!r}): no pressure difference drives "
            "a leakage flow from A to B; expected the piston locked and the valve a little open towards A"
        )
    held = {pA: means[pA], pB: means[pB]}
    x_name, v_name = f"{load}.x", f"{load}.v"
    if x_name in model.state_names:
        held[x_name] = record.value_at(x_name, hi, "m") if x_name in record else float(model.x0(p)[model.state_names.index(x_name)])
    if v_name in model.state_names:
        held[v_name] = 0.0
    t = float(hi)

    def solve(conditions: dict[str, float], state: str) -> float:
        return balancing_value(model, p, t, conditions, parameter, state)

    value = solve(held, pA)
    # the scatter of the settled pressures, propagated through the balance
    var = 0.0
    for n in (pA, pB):
        bumped = dict(held)
        bumped[n] += errors[n]
        var += (solve(bumped, pA) - value) ** 2
    try:
        from_b = solve(held, pB)
    except ParameterError:
        from_b = math.nan
    # settled? the balance at the first and at the second half of the window's pressures
    early, late = (solve({**held, pA: halves[pA][k], pB: halves[pB][k]}, pA) for k in (0, 1))
    settling = not abs(late - early) <= max(6.0 * math.sqrt(var), 0.01 * abs(value))  # 3 sigma of a difference of halves
    turbulent, drop, p_tr = _law_sensitivity(driven, model, p, t, held, parameter, pA)
    notes = []
    sensitivity = turbulent / value - 1.0 if value and math.isfinite(turbulent) else math.nan
    if abs(sensitivity) > 0.01:
        where = (f": the supply edge drops {drop / 1e5:.3g} bar, {drop / p_tr:.2g} times the valve law's laminar "
                 f"transition ({p_tr / 1e5:.3g} bar)") if math.isfinite(drop) and p_tr > 0 else ""
        notes.append(
            f"the orifice law's laminar transition moves C_Li by {100 * sensitivity:+.1f} % (the plain turbulent law "
            f"gives {turbulent:.3g} m^3/s/Pa){where}; the answer is as good as the law is there. Open the valve less, "
            "nearer its overlap, so that the edge drops more than about five times the transition (the laws then "
            "agree within 1 %), and hold it until chamber A has settled"
        )
    if settling:
        notes.append(
            f"the chamber pressures are still changing over {lo:g}..{hi:g} s: the first half of the window gives "
            f"C_Li = {early:.3g}, the second {late:.3g} m^3/s/Pa. Hold the valve longer (a small opening fills "
            "chamber A slowly) or choose a later window"
        )
    if not value > 0:
        notes.append(f"the balance of chamber A gives C_Li = {value:.3g} m^3/s/Pa, not positive: is the piston locked and the valve open towards A?")
    if math.isfinite(from_b) and value > 0 and not 0.5 < from_b / value < 2.0:
        notes.append(
            f"chamber B's balance gives {from_b:.3g} m^3/s/Pa against A's {value:.3g}: the valve's B side (its laps, "
            "the tank line) is not as the model has it, or chamber B is not settled"
        )
    return LeakageEstimate(parameter, value, math.sqrt(var), from_b, (lo, hi), held, notes, turbulent, drop, p_tr)


def _law_sensitivity(
    driven: System, model: Any, p: np.ndarray, t: float, held: dict[str, float], parameter: str, state: str,
) -> tuple[float, float, float]:
    """The balance again with the plain turbulent orifice law (every valve's critical flow number, and with it its
    transition pressure, taken a million times smaller: the transition 1e-12 of its value), the drop across the
    P-A edge of the model's valve and that valve's transition pressure [Pa]; NaN where the model has no such law
    (or several valves), or the balance has no solution with it."""
    from hydroservo.analysis.linear import input_values
    from hydroservo.laws.orifice import transition_pressure

    names = model.parameter_names
    crit = [k for k, n in enumerate(names) if n.endswith(".lambda_crit")]
    if not crit:
        return math.nan, math.nan, math.nan
    q = p.copy()
    q[crit] *= 1e-6
    try:
        turbulent = balancing_value(model, q, t, held, parameter, state)
    except ParameterError:
        turbulent = math.nan
    drop = p_tr = math.nan
    # the valve's law and its supply edge: the one valve of the model with a supply port and the turbulent law
    valves = [c for c, comp in driven.components.items() if {"pS", "pA"} <= set(comp.INPUTS) and f"{c}.lambda_crit" in names]
    valve = valves[0] if len(valves) == 1 else None
    if valve is not None:
        value = {n: float(p[names.index(f"{valve}.{n}")]) for n in ("D_h", "rho", "nu", "lambda_crit")}
        p_tr = float(transition_pressure(value["D_h"], value["rho"], value["nu"], value["lambda_crit"]))
        x = dict(zip(model.state_names, np.asarray(model.x0(p), dtype=float).ravel().tolist()))
        x.update(held)
        try:
            supply = input_values(driven, x, t=t, components=[valve])[f"{valve}.pS"]
            drop = float(supply - held[state])
        except (HydroservoError, KeyError):
            drop = math.nan
    return turbulent, drop, p_tr
