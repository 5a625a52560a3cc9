"""Friction of a cylinder from a rig record, and the Stribeck law fitted to it ([Efe2014] sections 4.5.4, 5.1.1).

The experiment: the rod is driven at several constant speeds (the valve signal
held at several levels, both directions); the chamber pressures and the rod
position are logged. At each speed the friction force is the piston's force
balance, [Efe2014] eq. 4.24,

.. math:: F_f = p_A A_A - p_B A_B - m \\ddot x \\; (- F_{ext}),

which in steady motion is eq. 4.25 (no acceleration). The transient after
each change of the valve signal is left out
(:func:`~hydroservo.identification.steady.segments`); over the rest of each
held interval the position is fitted by a quadratic in time, whose slope is
the interval's mean speed and whose curvature its (constant) acceleration.
The fit uses the interval's own samples only. A smoothing window centred on
the last samples of a hold would see the deceleration after it, and its
acceleration times the mass would bias every force in the direction of the
motion: a centred 50 ms Savitzky-Golay filter over the whole record put the
viscous coefficient of the example record (docs/calibration.md) at 366.6 ±
12.1 N s/m against its truth of 350, and at 372 on the same programme without
noise, where eq. 4.25's plain averages give the truth. The forces are averaged over each held
interval: one point per speed, as Table 5.2 lists them; in a steady hold they
are eq. 4.25's plain averages.

The Stribeck law, eq. 3.47 (:func:`hydroservo.laws.friction.stribeck`, the
published form with the sign not smoothed), is then fitted to the points by
least squares in log scale (all four parameters positive); relative errors
follow the thesis's convention, (experimental - simulated) / experimental.
Parameters the points cannot determine can be held at given values
(``held``): ``hydroservo identify friction`` holds an undetermined static
term (``F_s0``, ``c_s``) at the model's own values and fits ``B`` and
``F_c0`` with it, since left free it trades with them along a flat valley.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.identification.calibration import record_fault
from hydroservo.identification.records import Record
from hydroservo.identification.steady import segments
from hydroservo.laws.friction import stribeck

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["FrictionPoints", "friction_from_record", "StribeckFit", "fit_stribeck", "STRIBECK_PARAMETERS"]

#: The Stribeck parameters as the load components name them, with their units: eq. 3.47's sigma (F_v), F_c0,
#: F_s0 and c_s.
STRIBECK_PARAMETERS = {"B": "N*s/m", "F_c0": "N", "F_s0": "N", "c_s": "m/s"}


@dataclass
class FrictionPoints:
    """Friction force against speed: one point per held valve signal (speed [m/s], force [N], the force's
    standard deviation over the interval [N], the valve signal, and the interval [s])."""

    velocity: np.ndarray
    force: np.ndarray
    spread: np.ndarray
    command: np.ndarray
    intervals: list[tuple[float, float]]
    source: str = ""

    def __len__(self) -> int:
        return int(self.velocity.size)


def friction_from_record(
    system: System,
    record: Record,
    *,
    command: str = "command.y",
    position: str = "load.x",
    pressures: tuple[str, str] = ("cyl.pA", "cyl.pB"),
    cylinder: str = "cyl",
    load: str = "load",
    external: str | None = None,
    settle: float = 0.25,
    min_speed: float = 1e-3,
) -> FrictionPoints:
    """The friction force at each held valve signal of ``record`` ([Efe2014] eqs. 4.24-4.25).

    The piston areas come from ``system[cylinder]`` (``A_A``, ``A_B``), the moving mass from
    ``system[load]`` (``m``); ``external`` names a recorded external force on the rod (+ extends), if any.
    Intervals slower than ``min_speed`` [m/s] (the rod held by its overlap or by friction) are left out.
    """
    cyl, mass = system[cylinder], system[load]
    for comp, key in ((cyl, "A_A"), (cyl, "A_B"), (mass, "m")):
        if key not in comp.values:
            raise ParameterError(f"friction: {comp.name} has no parameter {key!r}; expected a cylinder and a mass")
    A_A, A_B, m = cyl.values["A_A"], cyl.values["A_B"], mass.values["m"]
    segs = segments(record, command, settle=settle)
    if not segs:
        raise ParameterError(f"record {record.name!r}: no interval where {command} is held for long enough")
    for n in (position, *pressures):
        if n not in record:
            raise ParameterError(f"record {record.name!r}: no column {n!r}; the friction test needs the rod position and both chamber pressures")
    fault = record_fault(system.build(), system.parameter_vector(), record, [position, *pressures, command])
    if fault:
        raise ParameterError(fault)
    ch = record[position]
    x_all = ch.to("m")
    pa = record[pressures[0]]  # the forces at chamber A's samples, the other signals interpolated to them

    def at(name: str, unit: str, times: np.ndarray) -> np.ndarray:
        """A channel at the chamber-A pressure's sample times (linear between its own samples with a value)."""
        c = record[name]
        return np.interp(times, c.t[c.valid], c.to(unit)[c.valid])

    rows = []
    for s in segs:
        inside = (ch.t >= s.start) & (ch.t <= s.end) & np.isfinite(x_all)
        if np.count_nonzero(inside) < 4:  # a quadratic and one degree of freedom
            continue
        t_hold = ch.t[inside]
        t_mid = float(np.mean(t_hold))
        # the whole hold's own samples: no window reaches past its ends (see the module notes)
        curve, slope, _ = np.polyfit(t_hold - t_mid, x_all[inside], 2)
        v, a = float(slope), 2.0 * float(curve)
        if abs(v) < min_speed:
            continue
        times = pa.t[pa.valid & (pa.t >= s.start) & (pa.t <= s.end)]
        if times.size == 0:
            continue
        force = at(pressures[0], "Pa", times) * A_A - at(pressures[1], "Pa", times) * A_B  # eq. 4.24
        force -= m * a
        if external:
            force -= at(external, "N", times)
        rows.append((v, float(np.mean(force)), float(np.std(force)), s.command, (s.start, s.end)))
    if len(rows) < 1:
        raise ParameterError(f"record {record.name!r}: the rod never moved faster than {min_speed:g} m/s in a held interval")
    rows.sort(key=lambda r: r[0])
    return FrictionPoints(
        np.array([r[0] for r in rows]), np.array([r[1] for r in rows]), np.array([r[2] for r in rows]),
        np.array([r[3] for r in rows]), [r[4] for r in rows], record.name,
    )


@dataclass
class StribeckFit:
    """The Stribeck law fitted to friction points: parameters (SI, by the load's names ``B``, ``F_c0``, ``F_s0``,
    ``c_s``), their standard errors (NaN with no degrees of freedom left), the law at the points and the relative
    errors in % ((experimental - simulated) / experimental)."""

    parameters: dict[str, float]
    stderr: dict[str, float]
    velocity: np.ndarray
    force: np.ndarray
    simulated: np.ndarray
    relative_error: np.ndarray
    warnings: list[str] = field(default_factory=list)
    #: parameters held at given values, not fitted (SI)
    held: dict[str, float] = field(default_factory=dict)

    def law(self, v: Any) -> Any:
        """The fitted law at speeds ``v`` [m/s] [N]."""
        p = self.parameters
        return stribeck(np.asarray(v, dtype=float), p["B"], p["F_c0"], p["F_s0"], p["c_s"])

    def to_dict(self) -> dict[str, Any]:
        return {
            "parameters": {
                k: {"value": v, "unit": STRIBECK_PARAMETERS[k], "stderr": _finite(self.stderr[k]), **({"held": True} if k in self.held else {})}
                for k, v in self.parameters.items()
            },
            "points": [
                {"velocity": float(v), "experimental": float(f), "simulated": float(s), "relative_error_percent": float(e)}
                for v, f, s, e in zip(self.velocity, self.force, self.simulated, self.relative_error)
            ],
            "max_relative_error_percent": float(np.max(np.abs(self.relative_error))),
            "warnings": list(self.warnings),
        }


def _finite(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def relative_errors(force: np.ndarray, simulated: np.ndarray) -> np.ndarray:
    """[Efe2014] Table 5.2's relative error [%]: (experimental - simulated) / experimental."""
    return 100.0 * (force - simulated) / force


def _profile_start(v: np.ndarray, f: np.ndarray) -> dict[str, float]:
    """The start of :func:`fit_stribeck`: for a given ``c_s`` the law is linear in ``B``, ``F_c0`` and ``F_s0``,
    solved exactly (non-negative least squares on the relative errors); ``c_s`` is the best of a log-spaced grid
    from a hundredth of the slowest speed to a hundred times the fastest (the first of equals). A term the points
    do not support comes out 0 and starts at a millionth of ``F_c0``, where the fit leaves it and the
    identifiability check finds it: the same answer from every SciPy, where a start far off let the optimiser
    drift along the flat valley (``c_s`` above every speed makes ``F_s0`` a second ``F_c0``)."""
    from scipy.optimize import nnls

    speed = np.abs(v)
    best: tuple[float, float, np.ndarray] | None = None
    for c_s in np.geomspace(speed.min() / 100.0, 100.0 * speed.max(), 121):
        A = np.column_stack([v, np.sign(v), np.sign(v) * np.exp(-speed / c_s)]) / f[:, None]
        theta, norm = nnls(A, np.ones_like(f))
        if best is None or norm < best[0] * (1.0 - 1e-9):
            best = (norm, float(c_s), theta)
    assert best is not None
    _, c_s, theta = best
    floor = 1e-6 * max(float(theta[1]), float(np.abs(f).min()))
    B, F_c0, F_s0 = (max(float(value), floor) for value in theta)
    return {"B": B, "F_c0": F_c0, "F_s0": F_s0, "c_s": c_s}


def fit_stribeck(
    velocity: Sequence[float] | np.ndarray,
    force: Sequence[float] | np.ndarray,
    *,
    start: dict[str, float] | None = None,
    held: Mapping[str, float] | None = None,
) -> StribeckFit:
    """Fit eq. 3.47 to friction forces [N] at speeds [m/s] (both directions allowed: the law is odd).

    Least squares on the relative errors (Table 5.2 judges the law by them), in log scale of the positive
    parameters; ``start`` defaults to the best linear fit over a grid of ``c_s`` (:func:`_profile_start`).
    ``held`` names parameters kept at the given values (SI) and not fitted, e.g. a static term the points
    cannot determine, held at the model's own values (their standard errors are reported as 0).
    """
    from scipy.optimize import least_squares

    v = np.asarray(velocity, dtype=float)
    f = np.asarray(force, dtype=float)
    if v.size != f.size or v.size < 2:
        raise ParameterError(f"fit_stribeck: {v.size} speeds and {f.size} forces; expected equally many, at least two")
    if np.any(v == 0) or np.any(np.sign(v) != np.sign(f)):
        raise ParameterError("fit_stribeck: every point needs a non-zero speed and a force opposing it (the same sign)")
    fixed = {k: float(x) for k, x in (held or {}).items()}
    for k, x in fixed.items():
        if k not in STRIBECK_PARAMETERS or not (math.isfinite(x) and x >= 0) or (k == "c_s" and x <= 0):
            raise ParameterError(
                f"fit_stribeck: held {k} = {x!r}: expected one of {', '.join(STRIBECK_PARAMETERS)} at a value >= 0 "
                "(c_s > 0)"
            )
    names = [n for n in STRIBECK_PARAMETERS if n not in fixed]
    if not names:
        raise ParameterError("fit_stribeck: every parameter is held; nothing to fit")
    if start is None:
        start = _profile_start(v, f) if not fixed else _held_start(v, f, fixed)
    # a held zero stays zero; a fitted parameter is positive and fitted in log scale
    x0 = np.log([max(start[n], 1e-300) for n in names])

    def full(x: np.ndarray) -> dict[str, float]:
        return {**fixed, **dict(zip(names, np.exp(x).tolist()))}

    def residuals(x: np.ndarray) -> np.ndarray:
        q = full(x)
        return np.asarray((f - stribeck(v, q["B"], q["F_c0"], q["F_s0"], q["c_s"])) / f)

    sol = least_squares(residuals, x0, method="trf", xtol=1e-14, ftol=1e-14, gtol=1e-14, max_nfev=5000)
    values = np.exp(sol.x)
    dof = v.size - len(names)
    stderr = {n: (0.0 if n in fixed else math.nan) for n in STRIBECK_PARAMETERS}
    if dof > 0:
        s2 = float(np.sum(sol.fun**2)) / dof
        _, sv, vt = np.linalg.svd(sol.jac, full_matrices=False)
        lost = sv <= 1e-8 * sv[0]  # directions the points do not reach at all (a Stribeck velocity far below them)
        var = np.sum((vt[~lost] / sv[~lost, None]) ** 2, axis=0) * s2
        blind = np.any(np.abs(vt[lost]) > 0.05, axis=0) if lost.any() else np.zeros(len(names), dtype=bool)
        stderr.update({n: (math.inf if b else float(val * math.sqrt(w))) for n, val, w, b in zip(names, values, var, blind)})
    params = {n: full(sol.x)[n] for n in STRIBECK_PARAMETERS}
    sim = np.asarray(stribeck(v, params["B"], params["F_c0"], params["F_s0"], params["c_s"]))
    notes = [
        f"{n} is not determined by these points (standard error {'infinite' if math.isinf(stderr[n]) else f'{100 * stderr[n] / params[n]:.0f} %'}): "
        + ("the static term needs speeds near and below the Stribeck velocity c_s" if n in ("F_s0", "c_s") else "too few or too similar speeds")
        for n in names if math.isfinite(params[n]) and params[n] > 0 and not stderr[n] <= params[n]
    ]
    return StribeckFit(params, stderr, v, f, sim, relative_errors(f, sim), notes, held=dict(fixed))


def _held_start(v: np.ndarray, f: np.ndarray, held: Mapping[str, float]) -> dict[str, float]:
    """A start for :func:`fit_stribeck` with some parameters held: with ``c_s`` known the law is linear in the
    others, solved by non-negative least squares on the relative errors (a zero raised to a millionth of the force,
    as in :func:`_profile_start`); else the profile start with the held values put in."""
    from scipy.optimize import nnls

    if "c_s" not in held:
        return {**_profile_start(v, f), **held}
    c_s = held["c_s"]
    columns = {"B": v, "F_c0": np.sign(v), "F_s0": np.sign(v) * np.exp(-np.abs(v) / c_s)}
    rest = f - sum((held[k] * col for k, col in columns.items() if k in held), np.zeros_like(f))
    free = [k for k in columns if k not in held]
    start = dict(held)
    if free:
        A = np.column_stack([columns[k] for k in free]) / f[:, None]
        theta, _ = nnls(A, rest / f)
        floor = 1e-6 * float(np.abs(f).min())
        start.update({k: max(float(x), floor) for k, x in zip(free, theta)})
    return start
