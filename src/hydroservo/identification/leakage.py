"""Internal leakage of a cylinder from a locked-piston record ([Efe2014] section 4.5.5).

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
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.identification.calibration import driven_system
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

    def to_dict(self) -> dict[str, Any]:
        return {
            "parameter": self.parameter, "value": self.value, "unit": "m^3/s/Pa", "stderr": self.stderr,
            "from_chamber_b": self.from_b if math.isfinite(self.from_b) else None,
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
    parameter = f"{cylinder}.C_Li"
    if parameter not in model.parameter_names:
        raise ParameterError(f"leakage: {system.name!r} has no parameter {parameter}")
    t0, t1 = record.span
    lo, hi = window if window is not None else (0.5 * (t0 + t1), t1)
    if not lo < hi:
        raise ParameterError(f"leakage: window {lo:g}..{hi:g} s: expected a start before the end")
    means, errors = {}, {}
    for n in (pA, pB):
        ch = record[n]
        sel = ch.valid & (ch.t >= lo) & (ch.t <= hi)
        if sel.sum() < 2:
            raise ParameterError(f"record {record.name!r}: fewer than two samples of {n} between {lo:g} s and {hi:g} s")
        vals = ch.to("Pa")[sel]
        means[n] = float(np.mean(vals))
        errors[n] = float(np.std(vals, ddof=1) / math.sqrt(vals.size))
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
    notes = []
    if not value > 0:
        notes.append(f"the balance of chamber A gives C_Li = {value:.3g} m^3/s/Pa, not positive: is the piston locked and the valve open towards A?")
    if math.isfinite(from_b) and value > 0 and not 0.5 < from_b / value < 2.0:
        notes.append(
            f"chamber B's balance gives {from_b:.3g} m^3/s/Pa against A's {value:.3g}: the valve's B side (its laps, "
            "the tank line) is not as the model has it, or chamber B is not settled"
        )
    return LeakageEstimate(parameter, value, math.sqrt(var), from_b, (lo, hi), held, notes)
