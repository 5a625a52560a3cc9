"""The valve's flow-coefficient compensation K(x_v) and hysteresis H(x_v, d_f) from rig records
([Efe2014] sections 3.2.1, 5.1.2-5.1.3, eqs. 3.18, 3.22-3.23).

The experiment: the valve signal is swept slowly up and down (a triangle, or
held steps) while the supply and chamber pressures and the rod position are
logged. At each pressure sample the rod's speed (the smoothed derivative of
its position) fixes the flow into the meter-in chamber; the flow coefficient
that puts that chamber in balance under the model's own valve law with
K = H = 1 (eq. 3.18 with the laps of eqs. 3.19-3.21) is found by
:func:`~hydroservo.identification.steady.balancing_value`, and its ratio to
the nominal ``c_v`` is the compensation the valve shows there. Samples are
grouped by the valve signal (bins of ``bin_width``):

* K(x_v) is the median ratio over the samples where the valve was *opening*
  (the magnitude of its signal rising), which [Efe2014] section 5.1.2 uses;
* H(x_v, closing) is the median ratio while *closing* divided by K at the
  same signal (Fig. 5.2), and H(x_v, opening) is 1; it is not read within
  twice the valve's largest lap of the null, where the flow is a small
  difference of large ones.

The relative spool position is taken as the valve signal, as the valve's
spool holds it in steady state; during a sweep the spool lags the signal, so
the states that are not measured (the spool's) are taken from a simulation
of the model along the record, the measured ones (pressures, rod position and
speed) from the record. The tables come out
in the form :class:`~hydroservo.components.valves.four_way.FourWayValve`
takes (``K_x``, ``K``, ``H_x``, ``H_opening``, ``H_closing``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.components.valves.four_way import FourWayValve
from hydroservo.errors import ParameterError
from hydroservo.identification.calibration import driven_system
from hydroservo.identification.records import Record, derivatives
from hydroservo.identification.steady import balancing_value

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["FlowCoefficientTables", "flow_coefficient_tables"]


@dataclass
class FlowCoefficientTables:
    """K(x_v) and H(x_v, d_f) as :class:`FourWayValve` tables, with the samples they were made from (signal,
    ratio c_v,eff / c_v, opening or not)."""

    tables: dict[str, list[float]]
    signal: np.ndarray
    ratio: np.ndarray
    opening: np.ndarray
    valve: str
    warnings: list[str] = field(default_factory=list)

    def to_dict(self) -> dict[str, Any]:
        return {
            "valve": self.valve, "tables": {k: list(v) for k, v in self.tables.items()}, "samples": int(self.signal.size),
            "opening_samples": int(self.opening.sum()), "closing_samples": int((~self.opening).sum()),
            "warnings": list(self.warnings),
        }


def _direction(t: np.ndarray, u: np.ndarray, at: np.ndarray) -> np.ndarray:
    """Whether the valve was opening (its signal's magnitude last rose rather than fell) at the times ``at``."""
    change = np.diff(np.abs(u))
    moving = np.flatnonzero(np.abs(change) > 1e-9)
    if moving.size == 0:
        return np.ones(at.size, dtype=bool)
    last = np.searchsorted(t[moving + 1], at, side="right") - 1  # the last change at or before each time
    out: np.ndarray = np.where(last >= 0, change[moving[np.maximum(last, 0)]] > 0, True)
    return out


def flow_coefficient_tables(
    system: System,
    records: Sequence[Record],
    *,
    inputs: Sequence[str] = ("command.y",),
    command: str = "command.y",
    valve: str = "valve",
    cylinder: str = "cyl",
    load: str = "load",
    bin_width: float = 0.05,
    window: float = 0.05,
    min_speed: float = 2e-3,
) -> FlowCoefficientTables:
    """K(x_v) and H(x_v, d_f) of ``system[valve]`` from ``records`` of a swept valve signal (module notes)."""
    comp = system[valve]
    if not isinstance(comp, FourWayValve):
        raise ParameterError(f"flow coefficient: {valve} is a {type(comp).__name__}; expected a FourWayValve")
    if not 0 < bin_width <= 0.5:
        raise ParameterError(f"bin width = {bin_width!r}: expected a fraction of the stroke in (0, 0.5]")
    pA, pB, x_name, v_name = f"{cylinder}.pA", f"{cylinder}.pB", f"{load}.x", f"{load}.v"
    signal, ratio, opening = [], [], []
    notes: list[str] = []
    for record in records:
        for n in (pA, pB, x_name, command):
            if n not in record:
                raise ParameterError(f"record {record.name!r}: no column {n!r}; the flow-coefficient test needs it")
        plain = system.copy()
        plain.replace(comp.with_tables(None))
        driven = driven_system(plain, record, inputs)
        model = driven.build()
        p = driven.parameter_vector()
        c_v = float(comp.values["c_v"])
        pos = record[x_name]
        speed, _ = derivatives(pos.t, pos.to("m"), window)
        cmd = record[command]
        ok = cmd.valid
        u_t, u = cmd.t[ok], cmd.values[ok]
        a, b = record[pA], record[pB]
        sel = a.valid & b.valid if np.array_equal(a.t, b.t) else a.valid
        times = a.t[sel]
        pa = a.to("Pa")[sel]
        pb = np.interp(times, b.t[b.valid], b.to("Pa")[b.valid])
        v = np.interp(times, pos.t, speed)
        x = np.interp(times, pos.t, pos.to("m"))
        uu = np.interp(times, u_t, u)
        direction = _direction(u_t, u, times)
        # the unmeasured states (the spool, lagging the signal) as the model has them along the record
        run = model.simulate(0.0, p, t_eval=times.tolist(), accuracy=1e-7, max_steps=5_000_000)
        states = np.vstack([run[n] for n in model.state_names])
        for k in range(times.size):
            if abs(v[k]) < min_speed or abs(uu[k]) < 1e-6 or np.sign(v[k]) != np.sign(uu[k]):
                continue
            held = {pA: pa[k], pB: pb[k], x_name: x[k], v_name: v[k]}
            chamber = pA if v[k] > 0 else pB  # the meter-in chamber
            try:
                c_eff = balancing_value(model, p, float(times[k]), held, f"{valve}.c_v", chamber, probe=c_v, x=states[:, k])
            except ParameterError:
                continue
            signal.append(uu[k])
            ratio.append(c_eff / c_v)
            opening.append(direction[k])
    if len(signal) < 3:
        raise ParameterError("flow coefficient: fewer than three samples with the rod moving; the records show no steady motion")
    s, r, o = np.array(signal), np.array(ratio), np.array(opening)
    # near the laps the flow is a small difference of large numbers: H is not read there (K still is)
    lap = max(float(comp.values.get(k, 0.0)) for k in ("x_PA", "x_AT", "x_PB", "x_BT")) / float(comp.values["xv_max"])
    edges = np.arange(-1.0, 1.0 + 1e-9, bin_width)
    K_x, K, H_x, H_c = [], [], [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        inside = (s >= lo) & (s < hi)
        opened = inside & o
        if opened.sum() >= 2:
            centre = float(np.median(s[opened]))
            k_open = float(np.median(r[opened]))
            K_x.append(centre)
            K.append(k_open)
            closed = inside & ~o
            if closed.sum() >= 2 and abs(centre) > 2 * lap:
                H_x.append(centre)
                H_c.append(float(np.median(r[closed])) / k_open)
    if len(K_x) < 2:
        raise ParameterError("flow coefficient: the opening samples fill fewer than two bins; sweep the valve signal wider")
    for name, values in (("K", K), ("H_closing", H_c)):
        if any(not 0 <= val <= 1.5 for val in values):
            notes.append(f"{name} leaves 0..1.5 (from {min(values):.3g} to {max(values):.3g}); clipped: check c_v and the laps")
    K = [min(max(val, 0.0), 1.5) for val in K]
    H_c = [min(max(val, 0.0), 1.5) for val in H_c]
    tables: dict[str, list[float]] = {"K_x": K_x, "K": K}
    if len(H_x) >= 2:
        tables.update({"H_x": H_x, "H_opening": [1.0] * len(H_x), "H_closing": H_c})
    elif (~o).any():
        notes.append("too few closing samples for H (fewer than two bins): sweep the valve signal back down")
    if not (~o).any():
        notes.append("no closing samples: H(x_v, d_f) needs the valve signal swept back down as well")
    if float(np.max(np.abs(s))) < 0.5:
        notes.append(f"the records reach only {float(np.max(np.abs(s))):.2f} of the stroke: K beyond it is held at its last value")
    return FlowCoefficientTables(tables, s, r, o, valve, notes)
