"""Steady parts of a record, and parameters read off a model at a measured steady state.

[Efe2014] section 4.5 identifies the robot arm's friction, internal leakage
and valve flow coefficient from *steady* conditions: constant rod speed under
a held valve signal, or a locked piston with the pressures settled. Two tools
serve all three procedures:

* :func:`segments` cuts a record into the intervals where the valve signal is
  held, dropping the transient at the start of each;
* :func:`balancing_value` finds the value of one model parameter at which the
  model's rate of one state vanishes at a measured operating point. The model's
  own equations are used, so the law is the one the model simulates (the
  valve's edges and laps, the chamber's leakage), implemented once. The states
  that were not measured (a spool) are set to their own steady value first
  (:meth:`hydroservo.system.model.Model.trim` with the measured states held).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.identification.records import Record
from hydroservo.system.model import Model

__all__ = ["Segment", "segments", "balancing_value"]


@dataclass(frozen=True)
class Segment:
    """An interval of a record where the command is held: from ``start`` to ``end`` [s] (after the transient),
    the command's value, and whether it was reached by opening the valve further (``opening``) or by closing it."""

    start: float
    end: float
    command: float
    opening: bool


def segments(record: Record, command: str, *, settle: float = 0.25, min_length: float = 0.1, tolerance: float = 1e-3) -> list[Segment]:
    """The intervals where ``command`` is held (changes by less than ``tolerance``), each without its first
    ``settle`` seconds, keeping those at least ``min_length`` long."""
    ch = record[command]
    ok = ch.valid
    t, u = ch.t[ok], ch.values[ok]
    edges = np.flatnonzero(np.abs(np.diff(u)) > tolerance)
    bounds = [0, *(edges + 1).tolist(), u.size]
    out = []
    previous = 0.0
    for a, b in zip(bounds[:-1], bounds[1:]):
        if b - a < 2:
            continue
        level = float(np.median(u[a:b]))
        start, end = float(t[a]) + settle, float(t[b - 1])
        if end - start >= min_length:
            out.append(Segment(start, end, level, abs(level) > abs(previous) + tolerance))
        previous = level
    return out


def balancing_value(
    model: Model, p: np.ndarray, t: float, measured: Mapping[str, float], parameter: str, state: str,
    probe: float | None = None, x: np.ndarray | None = None,
) -> float:
    """The value of ``parameter`` at which the rate of ``state`` vanishes, with the ``measured`` states (SI)
    held and the other states at their own steady value.

    With ``x`` given (SI, every state: a simulation of the unmeasured ones, such as a spool that lags its
    signal during a sweep) the unmeasured states are taken from it instead of trimmed.

    The rate must be affine in the parameter (a flow coefficient, a leakage conductance): it is evaluated at 0
    and at ``probe`` (default: the parameter's value in ``p``) and checked at a third point.

    Raises
    ------
    ParameterError
        If the rate does not depend on the parameter there, or not affinely.
    """
    names = model.parameter_names
    k = names.index(parameter)
    i = model.state_names.index(state)
    guess = np.asarray(model.x0(p) if x is None else x, dtype=float).ravel().copy()
    for n, v in measured.items():
        guess[model.state_names.index(n)] = v
    if x is not None:
        x = guess
    elif len(measured) < model.nx:
        try:
            steady = model.trim(p, t=t, x_guess=guess, free=list(measured), steady_motion=False)
            x = np.array([steady[n] for n in model.state_names])
        except HydroservoError as exc:
            raise ParameterError(f"no steady state of the unmeasured states at t = {t:g} s: {exc}") from None
    else:
        x = guess
    base = probe if probe is not None else float(p[k]) or 1.0

    def rate(value: float) -> float:
        q = p.copy()
        q[k] = value
        return float(np.asarray(model.f(t, x, q)).ravel()[i])

    r0, r1, r2 = rate(0.0), rate(base), rate(2.0 * base)
    slope = (r1 - r0) / base
    if slope == 0 or not np.isfinite(slope):
        raise ParameterError(f"the rate of {state} does not depend on {parameter} at t = {t:g} s (is the valve open?)")
    if abs((r2 - r0) - 2 * (r1 - r0)) > 1e-6 * max(abs(r2 - r0), abs(r0), 1e-300):
        raise ParameterError(f"the rate of {state} is not affine in {parameter}; cannot solve for it directly")
    return -r0 / slope
