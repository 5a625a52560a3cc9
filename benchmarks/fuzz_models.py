"""Fuzz the built-in and example models: random parameter sets inside the declared ranges, each run classified.

Run: ``python benchmarks/fuzz_models.py [N] [--seed S] [--json OUT]`` (N sets per model, default 300).

For every built-in model (``hydroservo.data.model_names()``) and every example
model file (``hydroservo.data.example_files()``, written to a temporary folder
so that files they include are found), each numeric parameter of each
component is a candidate, except

* parameters the model does not depend on (neither the right-hand side nor the
  initial state: options not in use such as ``cyl.E_max`` under a constant bulk
  modulus, initial values overridden by ``[initial]``, an unconnected input's
  gain),
* parameters that are structural in effect: the gains of a ``Sum`` (they make
  a feedback loop negative or positive). ``Cylinder.k_V`` is a switch
  (1: volumes follow the piston, 0: frozen): it is drawn at 0 or 1.

A set gives 1 to 5 candidates (one set in ten: all of them) values inside
their declared ranges (:class:`hydroservo.components.Param`):

* a range closed on both sides: uniform on it;
* otherwise log-uniform between the current value divided and multiplied by a
  factor (10, or 100 in three sets of ten), truncated to the declared range;
  the sign of the current value is kept (a feedback gain stays negative);
* parameters that are zero or may take either sign (valve laps, initial
  positions, offsets) get a typical magnitude (:data:`SCALES`) and, where
  both signs are meaningful, a random sign; initial pressures are drawn
  between 0 and the largest source pressure, initial positions inside the
  stroke;
* temperatures in degC: uniform within 50 K (factor 10) or 500 K (factor 100)
  of the current value, inside the declared range;
* one value in twenty is a closed end of the declared range (``p_tr = 0``,
  ``zeta_n = 0``, ``s0 = 1``), which is inside the range too.

Each set runs as ``system.simulate(params=...)`` with the model's own
``t_end`` (and ``--method``, default ``auto`` as a user runs), in one of ``--workers`` worker processes (``--worker``; the runs of
all models interleaved) whose wall time is bounded: a run over ``--timeout``
seconds is a *hang*, the worker is killed and replaced. Each record also says
whether the set would pass the components' own cross-parameter checks
(``Component.check``: x_min < x_max, chamber volumes positive over the stroke,
...), which ``simulate(params=...)`` does not apply today. Outcomes:

* ``ok``: finite and physically plausible (:func:`plausibility`);
* ``implausible``: finite but a check fails (chamber pressure above the largest
  source pressure, tanks included, by more than 10 % of its absolute pressure (``--pressure-margin``)
  or below absolute vacuum (-101325 Pa gauge), piston beyond its
  end stops by more than 1 % of the stroke, a chamber volume at or below
  zero, a non-finite output); split into *warned* when the result carries
  ``result.warnings`` (issue 10) and *silent* otherwise;
* ``clean_error``: a :class:`hydroservo.errors.HydroservoError`;
* ``crash``: any other exception, or the worker process dying;
* ``hang``: over the time bound;
* ``slow`` (counted apart, on top of the above): more than 5 s of wall time.

Then a few ``system.batch`` calls per model: one of fresh random sets, and one
mixing sets that ran well alone with one that failed alone, to record what a
batch does when one of its runs fails.

The functions here are also what ``tests/integration/test_fuzz.py`` runs.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import queue
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import tomllib
import traceback
import warnings
import zlib
from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

HERE = Path(__file__).resolve()

OUTCOMES = ("ok", "implausible_warned", "implausible_silent", "clean_error", "crash", "hang")
SLOW_S = 5.0
VACUUM_PA = -1.01325e5  # absolute vacuum, gauge
# The margins are hydroservo's documented ones (docs/reliability.md, hydroservo.system.plausibility); the checks
# below are written independently of the package's, so the two implementations check each other.
PRESSURE_MARGIN = 0.5  # above the largest source pressure, fraction of its absolute pressure
VACUUM_MARGIN = 0.01  # below vacuum, fraction of the largest source's absolute pressure
STROKE_MARGIN = 0.01  # beyond an end stop, fraction of the stroke
SIMULATE_POINTS = 1001  # the output times of System.simulate by default (a mixed batch uses the same)
EDGE_PROB = 0.05  # probability that a value is a closed end of the declared range
ALL_PROB = 0.10  # probability that a set varies every candidate

#: Parameters skipped as structural in effect: (component type, parameter).
STRUCTURAL = {("Sum", "gain1"), ("Sum", "gain2"), ("Sum", "gain3")}
#: Parameters that are switches in effect: drawn at one of these values.
SWITCHES = {("Cylinder", "k_V"): (0.0, 1.0)}
#: Parameters where both signs are ordinary (laps, initial values, offsets): a random sign.
TWO_SIDED = {
    ("FourWayValve", "x_PA"),
    ("FourWayValve", "x_AT"),
    ("FourWayValve", "x_PB"),
    ("FourWayValve", "x_BT"),
    ("StagedSlotValve", "X_a0"),
    ("StagedSlotValve", "X_b0"),
    ("StagedSlotValve", "X_c0"),
    ("StagedSlotValve", "X_d0"),
    ("FlapperNozzleSpool", "xv0"),
    ("Lag", "y0"),
    ("Step", "offset"),
    ("Ramp", "offset"),
    ("Sine", "offset"),
    ("Square", "offset"),
    ("Mass", "v0"),
}


# -- models -----------------------------------------------------------------------------------
@dataclass
class ModelSpec:
    """A model to fuzz: its label, and what ``hydroservo.io.load_model`` takes (a name or a path)."""

    label: str
    source: str


def write_examples(folder: Path) -> list[ModelSpec]:
    """Write every example file into ``folder``; the model files among them."""
    from hydroservo.data import example_files

    folder.mkdir(parents=True, exist_ok=True)
    specs = []
    for name, text in example_files().items():
        (folder / name).write_text(text, encoding="utf-8")
    for name, text in example_files().items():
        if name.endswith(".toml"):
            try:
                data = tomllib.loads(text)
            except tomllib.TOMLDecodeError:
                continue
            if "components" in data:
                specs.append(ModelSpec(name, str(folder / name)))
    return specs


def model_specs(folder: Path) -> list[ModelSpec]:
    """The built-in models and the example model files (written into ``folder``)."""
    from hydroservo.data import model_names

    return [ModelSpec(n, n) for n in model_names()] + write_examples(folder)


# -- drawing parameter sets ---------------------------------------------------------------------
@dataclass
class Candidate:
    key: str  # "comp.param"
    comp: str
    name: str
    ctype: str
    spec: Any  # hydroservo Param
    value: float  # the model's value (SI)
    late: bool = False  # drawn after the others (depends on them: initial pressures and positions)


def _sources_max(values: Mapping[str, float], system: Any) -> float | None:
    """Largest source pressure (ConstantPressure, PressureTable, Tank) with parameter values ``values``."""
    tops = []
    for name, comp in system.components.items():
        t = type(comp).__name__
        if t in ("ConstantPressure", "Tank"):
            tops.append(values[f"{name}.p"])
        elif t == "PressureTable":
            tops.append(values[f"{name}.scale"] * float(np.max(comp.pressures)))
        elif t in ("Pump", "VariablePump"):  # a pump's rated pressure (docs/reliability.md)
            tops.append(values[f"{name}.p_rated"])
    return max(tops) if tops else None


def _cylinder_of(system: Any, mass: str) -> str | None:
    """The cylinder whose position input is the output ``x`` of ``mass``."""
    for name, comp in system.components.items():
        if type(comp).__name__ == "Cylinder" and system.connections.get(f"{name}.x") == f"{mass}.x":
            return str(name)
    return None


def _stroke(system: Any, values: Mapping[str, float], mass: str) -> tuple[float, float]:
    cyl = _cylinder_of(system, mass)
    if cyl is None:
        return -0.05, 0.05
    return values[f"{cyl}.x_min"], values[f"{cyl}.x_max"]


def _within_stroke(system: Any, values: Mapping[str, float], mass: str, frac: float) -> tuple[str, float, float]:
    lo, hi = _stroke(system, values, mass)
    return "uniform", frac * lo, frac * hi


Scale = Callable[[Any, Mapping[str, float], str], tuple[str, float, float]]

#: Draws for parameters whose current value is zero (or that depend on others):
#: (type, parameter) -> f(system, values, component) -> ("log", centre, sign) | ("uniform", lo, hi).
#: "log": log-uniform magnitude around ``centre`` (factor as for the others), sign 0 = random.
SCALES: dict[tuple[str, str], Scale] = {
    ("Cylinder", "C_Li"): lambda s, v, c: ("log", 1e-12, 1.0),
    ("Cylinder", "C_LeA"): lambda s, v, c: ("log", 1e-13, 1.0),
    ("Cylinder", "C_LeB"): lambda s, v, c: ("log", 1e-13, 1.0),
    ("Cylinder", "k_stop"): lambda s, v, c: ("log", 1e8, 1.0),
    ("Cylinder", "c_stop"): lambda s, v, c: ("log", 1e4, 1.0),
    ("Cylinder", "p_floor"): lambda s, v, c: ("uniform", -0.9e5, 5e5),
    ("Cylinder", "pA0"): lambda s, v, c: ("uniform", 0.0, _sources_max(v, s) or 1e7),
    ("Cylinder", "pB0"): lambda s, v, c: ("uniform", 0.0, _sources_max(v, s) or 1e7),
    ("Volume", "p0"): lambda s, v, c: ("uniform", 0.0, _sources_max(v, s) or 1e7),
    ("Mass", "W"): lambda s, v, c: ("log", 9.80665 * v[f"{c}.m"], 1.0),
    ("Mass", "F_c0"): lambda s, v, c: ("log", 0.1 * 9.80665 * v[f"{c}.m"], 1.0),
    ("Mass", "F_s0"): lambda s, v, c: ("log", 0.05 * 9.80665 * v[f"{c}.m"], 1.0),
    ("Mass", "k_spring"): lambda s, v, c: ("log", v[f"{c}.m"] * (2 * math.pi * 10) ** 2, 1.0),
    ("Mass", "x_spring"): lambda s, v, c: _within_stroke(s, v, c, 0.5),
    ("Mass", "x0"): lambda s, v, c: _within_stroke(s, v, c, 0.9),
    ("Mass", "v0"): lambda s, v, c: ("log", 0.05, 0.0),
    ("FourWayValve", "G_leak"): lambda s, v, c: ("log", 1e-12, 1.0),
    **{
        ("FourWayValve", e): (lambda s, v, c: ("log", 0.02 * v[f"{c}.xv_max"], 0.0))
        for e in ("x_PA", "x_AT", "x_PB", "x_BT")
    },
    ("FlapperNozzleSpool", "xv0"): lambda s, v, c: ("log", 2.54e-4, 0.0),
    ("Lag", "y0"): lambda s, v, c: ("log", 0.1, 0.0),
    ("Step", "offset"): lambda s, v, c: ("log", 0.2 * abs(v[f"{c}.amplitude"]) or 0.1, 0.0),
    ("Step", "t_step"): lambda s, v, c: ("uniform", 0.0, 0.5 * s.t_end),
    ("Tank", "p"): lambda s, v, c: ("uniform", -1e5, 5e5),
}
#: Drawn after the others, because their draw reads other values.
LATE = {("Cylinder", "pA0"), ("Cylinder", "pB0"), ("Volume", "p0"), ("Mass", "x0"), ("Mass", "x_spring")}


def influential_parameters(system: Any) -> set[str]:
    """Parameters the model's right-hand side or initial state depends on (structural sparsity of CasADi)."""
    import casadi as ca

    model = system.build()
    dep: np.ndarray = np.zeros(len(model.parameter_names), dtype=bool)
    for fn, iin in ((model.f, 2), (model.x0, 0)):
        sp = fn.sparsity_jac(iin, 0)
        dep |= np.asarray(ca.DM(sp, 1), dtype=float).any(axis=0)
    return {n for n, d in zip(model.parameter_names, dep) if d}


def candidates(system: Any) -> tuple[list[Candidate], dict[str, str]]:
    """The parameters to draw, and the skipped ones with the reason."""
    used = influential_parameters(system)
    cands, skipped = [], {}
    for cname, comp in system.components.items():
        ctype = type(comp).__name__
        for pname, spec in comp.PARAMETERS.items():
            key = f"{cname}.{pname}"
            if (ctype, pname) in STRUCTURAL:
                skipped[key] = "structural in effect"
            elif key not in used:
                skipped[key] = "the model does not depend on it (option not in use, or overridden by [initial])"
            else:
                value = float(comp.values[pname])
                if (
                    value == 0.0
                    and (ctype, pname) not in SCALES
                    and not _bounded(spec)
                    and (ctype, pname) not in SWITCHES
                ):
                    skipped[key] = "zero, no declared range and no typical scale"
                    continue
                cands.append(Candidate(key, cname, pname, ctype, spec, value, (ctype, pname) in LATE))
    return cands, skipped


def _at_edge(spec: Any, x: float) -> bool:
    """Whether ``x`` is a closed end of the declared range."""
    return (spec.min is not None and spec.min_inclusive and x == spec.min) or (
        spec.max is not None and spec.max_inclusive and x == spec.max
    )


def _bounded(spec: Any) -> bool:
    return spec.min is not None and spec.max is not None


def _inside(spec: Any, x: float) -> bool:
    if not math.isfinite(x):
        return False
    if spec.min is not None and (x < spec.min or (x == spec.min and not spec.min_inclusive)):
        return False
    if spec.max is not None and (x > spec.max or (x == spec.max and not spec.max_inclusive)):
        return False
    return True


def _clip_interval(spec: Any, a: float, b: float) -> tuple[float, float]:
    lo = a if spec.min is None else max(a, spec.min)
    hi = b if spec.max is None else min(b, spec.max)
    return lo, hi


def _log_between(rng: np.random.Generator, a: float, b: float) -> float:
    """Log-uniform on [a, b] (same sign, nonzero), uniform if it straddles zero."""
    if a == b:
        return a
    if a > 0 and b > 0:
        return float(math.exp(rng.uniform(math.log(a), math.log(b))))
    if a < 0 and b < 0:
        return -float(math.exp(rng.uniform(math.log(-b), math.log(-a))))
    return float(rng.uniform(a, b))


def draw_value(
    cand: Candidate,
    system: Any,
    values: Mapping[str, float],
    rng: np.random.Generator,
    factor: float,
    edge_prob: float = EDGE_PROB,
) -> float:
    """A value of ``cand`` inside its declared range (see the module docstring)."""
    spec, cur, kind = cand.spec, cand.value, (cand.ctype, cand.name)
    if kind in SWITCHES:
        return float(rng.choice(SWITCHES[kind]))
    edges = [e for e, inc in ((spec.min, spec.min_inclusive), (spec.max, spec.max_inclusive)) if e is not None and inc]
    if edges and rng.random() < edge_prob:
        return float(rng.choice(edges))
    for _ in range(50):
        x = _draw(cand, system, values, rng, factor)
        if _inside(spec, x):
            return x
    return cur


def _with_units(system: Any, params: Mapping[str, float]) -> dict[str, Any]:
    """The drawn values, temperatures with their unit (a bare number is not a temperature)."""
    out: dict[str, Any] = {}
    for key, value in params.items():
        cname, pname = key.split(".", 1)
        spec = system.components[cname].PARAMETERS.get(pname)
        out[key] = f"{value!r} degC" if spec is not None and spec.unit == "degC" else value
    return out


def _draw(cand: Candidate, system: Any, values: Mapping[str, float], rng: np.random.Generator, factor: float) -> float:
    spec, cur, kind = cand.spec, cand.value, (cand.ctype, cand.name)
    if _bounded(spec):
        return float(rng.uniform(spec.min, spec.max))
    if spec.unit.replace(" ", "") in ("degC", "°C"):
        span = 5.0 * factor
        lo, hi = _clip_interval(spec, cur - span, cur + span)
        return float(rng.uniform(lo, hi))
    if kind in SCALES and (cur == 0.0 or kind in LATE or kind in TWO_SIDED):
        how, a, b = SCALES[kind](system, values, cand.comp)
        if how == "uniform":
            lo, hi = _clip_interval(spec, a, b)
            return float(rng.uniform(lo, hi)) if hi > lo else lo
        centre, sign = (abs(cur) if cur != 0.0 else a), b
        if sign == 0.0 or kind in TWO_SIDED:
            sign = float(rng.choice((-1.0, 1.0)))
        return sign * _log_between(rng, centre / factor, centre * factor)
    if kind in TWO_SIDED:
        return float(rng.choice((-1.0, 1.0))) * _log_between(rng, abs(cur) / factor, abs(cur) * factor)
    if cur == 0.0:  # bounded on one side, zero, no scale: uniform over a decade from the bound
        base = spec.min if spec.min is not None else spec.max
        step = max(abs(base), 1.0)
        return float(rng.uniform(base, base + step)) if spec.min is not None else float(rng.uniform(base - step, base))
    a, b = sorted((cur / factor, cur * factor))
    lo, hi = _clip_interval(spec, a, b)
    if hi < lo:
        return cur
    return _log_between(rng, lo, hi)


def draw_set(
    system: Any,
    cands: list[Candidate],
    rng: np.random.Generator,
    edge_prob: float = EDGE_PROB,
    all_prob: float = ALL_PROB,
) -> dict[str, float]:
    """One random parameter set: 1 to 5 candidates (sometimes all) with new values (SI)."""
    factor = 100.0 if rng.random() < 0.3 else 10.0
    if rng.random() < all_prob:
        chosen = list(cands)
    else:
        k = int(rng.integers(1, min(5, len(cands)) + 1))
        chosen = [cands[i] for i in sorted(rng.choice(len(cands), size=k, replace=False))]
    values = dict(system.parameter_values())
    out: dict[str, float] = {}
    for cand in sorted(chosen, key=lambda c: c.late):
        x = draw_value(cand, system, values, rng, factor, edge_prob)
        values[cand.key] = x
        out[cand.key] = x
    return out


# -- one run, in a worker -------------------------------------------------------------------------
def _crash(outcome: str, exc: BaseException) -> dict[str, Any]:
    """The record of an exception that is not a HydroservoError: its type, message and the end of its traceback."""
    return {
        "outcome": outcome,
        "error_type": type(exc).__name__,
        "message": str(exc)[:400],
        "traceback": "".join(traceback.format_exception(exc)[-4:])[-1500:],
    }


def plausibility(system: Any, result: Any, pressure_margin: float = PRESSURE_MARGIN) -> list[dict[str, Any]]:
    """The physical checks of a finished run: a list of violations (empty: plausible).

    ``pressure_margin``: how far above the largest source pressure a chamber may go, as a fraction of that
    source's absolute pressure (so that a source at 0 bar gauge still leaves a margin); ``ratio`` is the
    chamber's peak over the source, both absolute.
    """
    params = result.params
    t = np.asarray(result.t, dtype=float)
    data = result.data
    issues: list[dict[str, Any]] = []

    def first(mask: np.ndarray) -> float:
        return float(t[int(np.argmax(mask))])

    for name, values in data.items():
        arr = np.asarray(values, dtype=float)
        if not np.all(np.isfinite(arr)):
            issues.append({"check": "non_finite_signal", "signal": name, "t_first": first(~np.isfinite(arr))})
    p_top = _sources_max(params, system)
    for cname, comp in system.components.items():
        ctype = type(comp).__name__
        chambers = ("pA", "pB") if ctype == "Cylinder" else ("p",) if ctype == "Volume" else ()
        for ch in chambers:
            p = np.asarray(data[f"{cname}.{ch}"], dtype=float)
            top = None if p_top is None else p_top + pressure_margin * (p_top - VACUUM_PA)
            if top is not None and p_top is not None and np.nanmax(p) > top:
                mask = p > top
                issue = {
                    "check": "pressure_above_sources",
                    "signal": f"{cname}.{ch}",
                    "value": float(np.nanmax(p)),
                    "bound": top,
                    "ratio": float((np.nanmax(p) - VACUUM_PA) / (p_top - VACUUM_PA)),
                    "t_first": first(mask),
                    "at_start": bool(mask[0]),
                }
                if ctype == "Cylinder":
                    issue["beyond_static_bound"] = bool(np.nanmax(p) > _static_bound(system, params, cname, p_top))
                issues.append(issue)
            floor = VACUUM_PA - VACUUM_MARGIN * ((p_top if p_top is not None else 0.0) - VACUUM_PA)
            if np.nanmin(p) < floor:
                mask = p < floor
                issues.append(
                    {
                        "check": "pressure_below_vacuum",
                        "signal": f"{cname}.{ch}",
                        "value": float(np.nanmin(p)),
                        "bound": floor,
                        "t_first": first(mask),
                        "at_start": bool(mask[0]),
                    }
                )
        if ctype != "Cylinder":
            continue
        src = system.connections.get(f"{cname}.x")
        if src is None or src not in data:
            continue
        x = np.asarray(data[src], dtype=float)
        lo, hi = params[f"{cname}.x_min"], params[f"{cname}.x_max"]
        margin = STROKE_MARGIN * (hi - lo)
        mask = (x > hi + margin) | (x < lo - margin)
        if np.any(mask):
            issues.append(
                {
                    "check": "position_beyond_stroke",
                    "signal": src,
                    "value": float(x[np.argmax(np.abs(np.where(mask, x, 0.0)))]),
                    "bound": [lo, hi],
                    "t_first": first(mask),
                    "at_start": bool(mask[0]),
                    "end_stops": params[f"{cname}.k_stop"] > 0,
                }
            )
        kv = params[f"{cname}.k_V"]
        VA = params[f"{cname}.V_A0"] + kv * params[f"{cname}.A_A"] * x
        VB = params[f"{cname}.V_B0"] - kv * params[f"{cname}.A_B"] * x
        for side, V in (("A", VA), ("B", VB)):
            if np.nanmin(V) <= 0:
                mask = V <= 0
                issues.append(
                    {
                        "check": "chamber_volume_nonpositive",
                        "signal": f"{cname}.V_{side}",
                        "value": float(np.nanmin(V)),
                        "t_first": first(mask),
                        "at_start": bool(mask[0]),
                    }
                )
    return issues


def _static_bound(system: Any, params: Mapping[str, float], cyl: str, p_top: float) -> float:
    """A generous static bound of a chamber pressure: intensification by the area ratio plus the load's
    weight and friction over the smaller area (pressures above it need dynamics: a decelerated mass)."""
    A_A, A_B = params[f"{cyl}.A_A"], params[f"{cyl}.A_B"]
    load = 0.0
    src = system.connections.get(f"{cyl}.x", "")
    mass = src.split(".")[0]
    if mass in system.components and type(system.components[mass]).__name__ == "Mass":
        load = abs(params[f"{mass}.W"]) + params[f"{mass}.F_c0"] + params[f"{mass}.F_s0"]
    return (1.0 + PRESSURE_MARGIN) * (p_top * max(A_A / A_B, A_B / A_A) + load / min(A_A, A_B))


def _located(message: str, state_names: Iterable[str]) -> bool:
    """Whether an error message names a time and a state."""
    return "t = " in message and any(re.search(rf"\b{re.escape(s)}\b", message) for s in state_names)


def cross_check(system: Any, params: Mapping[str, float]) -> str | None:
    """The message of the first component check (``Component.check``: x_min < x_max, chamber volumes positive
    over the stroke, ...) that ``params`` would fail if set on the system; None if they pass. ``simulate(params=...)``
    itself applies only each parameter's declared range."""
    from hydroservo.errors import HydroservoError

    by_comp: dict[str, dict[str, float]] = {}
    for key, value in params.items():
        cname, pname = key.split(".", 1)
        by_comp.setdefault(cname, {})[pname] = value
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for cname, values in by_comp.items():
            comp = system.components[cname]
            try:
                trial = comp.replace(check=False, **values)
                trial.check()
            except HydroservoError as exc:
                return str(exc)[:200]
            except Exception as exc:  # noqa: BLE001 - reported, not fatal: the run itself is what is classified
                return f"<{cname}.check() raised {type(exc).__name__}: {str(exc)[:150]}>"
    return None


class Runner:
    """Loads models once and runs sets in this process (the worker's side)."""

    def __init__(self) -> None:
        self.systems: dict[str, Any] = {}

    def system(self, source: str) -> Any:
        if source not in self.systems:
            from hydroservo.io import load_model

            self.systems[source] = load_model(source)
        return self.systems[source]

    def run(
        self,
        source: str,
        params: Mapping[str, float],
        pressure_margin: float = PRESSURE_MARGIN,
        method: str = "auto",
    ) -> dict[str, Any]:
        from hydroservo.errors import HydroservoError

        system = self.system(source)
        out: dict[str, Any] = {"py_warnings": [], "cross_check": cross_check(system, params)}
        start = time.perf_counter()
        phase = "simulate"
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                result = system.simulate(params=_with_units(system, params), method=method)
                out["wall_s"] = time.perf_counter() - start
                phase = "checks"
                issues = plausibility(system, result, pressure_margin)
                res_warn = getattr(result, "warnings", None)
                out["has_warnings_attr"] = res_warn is not None
                out["warnings"] = [str(w) for w in res_warn] if res_warn else []
                out["issues"] = issues
                out["final"] = {n: float(result[n][-1]) for n in system.build().state_names}
                if not issues:
                    out["outcome"] = "ok"
                else:
                    out["outcome"] = "implausible_warned" if out["warnings"] else "implausible_silent"
            except HydroservoError as exc:
                out["wall_s"] = out.get("wall_s", time.perf_counter() - start)
                msg = str(exc)
                out.update(
                    outcome="clean_error" if phase == "simulate" else "crash",
                    error_type=type(exc).__name__,
                    message=msg[:400],
                    located=_located(msg, system.build().state_names),
                    phase=phase,
                )
            except Exception as exc:  # noqa: BLE001 - a crash is what we are looking for
                out["wall_s"] = out.get("wall_s", time.perf_counter() - start)
                out.update(_crash("crash", exc), phase=phase)
        out["py_warnings"] = sorted({f"{w.category.__name__}: {str(w.message)[:150]}" for w in caught})
        return out

    def batch(
        self,
        source: str,
        sets: Mapping[str, list[float]],
        pressure_margin: float = PRESSURE_MARGIN,
        n_points: int | None = None,
    ) -> dict[str, Any]:
        from hydroservo.errors import HydroservoError

        system = self.system(source)
        out: dict[str, Any] = {}
        start = time.perf_counter()
        with warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            try:
                kwargs = {} if n_points is None else {"n_points": n_points}
                br = system.batch({k: list(_with_units(system, {k: x})[k] for x in v) for k, v in sets.items()}, **kwargs)
            except HydroservoError as exc:
                out.update(outcome="clean_error", error_type=type(exc).__name__, message=str(exc)[:400])
                br = None
            except Exception as exc:  # noqa: BLE001
                out.update(_crash("crash", exc))
                br = None
            out["wall_s"] = time.perf_counter() - start
            if br is None:
                return out
            out["outcome"] = "returned"
            out["runs_returned"] = len(br)
            marks = {}
            for attr in ("failed", "failures", "errors", "ok", "success", "status", "warnings"):
                if hasattr(br, attr):
                    with contextlib.suppress(Exception):
                        marks[attr] = repr(getattr(br, attr))[:300]
            out["failure_marking"] = marks
            state_names = system.build().state_names
            finals, finite, per_run = [], [], []
            marked = getattr(br, "failed", None) or {}
            out["marked_failed"] = sorted(int(k) for k in marked)
            try:
                for k in range(len(br)):
                    X = np.array([br[n][k] for n in state_names], dtype=float)
                    finite.append(bool(np.all(np.isfinite(X))))
                    finals.append({n: float(X[i, -1]) for i, n in enumerate(state_names)})
                    if k in marked:
                        per_run.append("marked_failed")
                        continue
                    if not finite[-1]:
                        per_run.append("non_finite_unmarked")
                        continue
                    try:
                        run = br.run(k)
                    except HydroservoError:
                        per_run.append("run_k_refused")
                        continue
                    issues = plausibility(system, run, pressure_margin)
                    warned = bool(getattr(run, "warnings", None))
                    per_run.append("ok" if not issues else "implausible_warned" if warned else "implausible_silent")
            except Exception as exc:  # noqa: BLE001
                out.update(_crash("crash_reading", exc))
            out.update(finals=finals, finite=finite, per_run=per_run)
        return out


def worker_main() -> None:
    """``--worker``: read one JSON request per line on stdin, answer one JSON line on the original stdout.

    File descriptor 1 is pointed at stderr so that anything printed by C code
    (CasADi, SUNDIALS) cannot corrupt the protocol.
    """
    proto = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    runner = Runner()
    for line in sys.stdin:
        req = json.loads(line)
        try:
            resp = _serve(runner, req)
        except Exception as exc:  # noqa: BLE001 - a fault of the harness itself, reported as such
            resp = {
                "outcome": "crash",
                "error_type": type(exc).__name__,
                "message": str(exc)[:400],
                "phase": "harness",
                "traceback": "".join(traceback.format_exception(exc)[-4:])[-1500:],
            }
        resp["id"] = req.get("id")
        proto.write(json.dumps(resp) + "\n")
        proto.flush()


def _serve(runner: Runner, req: Mapping[str, Any]) -> dict[str, Any]:
    """One request of the worker protocol."""
    if req["op"] == "run":
        return runner.run(
            req["model"], req["params"], req.get("pressure_margin", PRESSURE_MARGIN), req.get("method", "auto")
        )
    if req["op"] == "batch":
        return runner.batch(req["model"], req["sets"], req.get("pressure_margin", PRESSURE_MARGIN), req.get("n_points"))
    if req["op"] == "ping":
        return {"outcome": "pong"}
    return {"outcome": "crash", "error_type": "Protocol", "message": f"unknown op {req['op']!r}"}


# -- workers, from the parent -------------------------------------------------------------------
class Worker:
    """A ``--worker`` child process; :meth:`call` bounds each request's wall time."""

    def __init__(self, log_dir: Path) -> None:
        self.log_dir = log_dir
        self.proc: subprocess.Popen[str] | None = None
        self.lines: queue.Queue[str | None] = queue.Queue()
        self.restarts = 0

    def start(self) -> None:
        fd, path = tempfile.mkstemp(prefix="worker-", suffix=".log", dir=self.log_dir)
        self.log = path
        self.proc = subprocess.Popen(
            [sys.executable, str(HERE), "--worker"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=fd,
            text=True,
            bufsize=1,
        )
        os.close(fd)
        self.lines = queue.Queue()
        threading.Thread(target=self._read, args=(self.proc, self.lines), daemon=True).start()

    @staticmethod
    def _read(proc: subprocess.Popen[str], lines: queue.Queue[str | None]) -> None:
        assert proc.stdout is not None
        for line in proc.stdout:
            lines.put(line)
        lines.put(None)

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.kill()  # our own child, by its handle
            self.proc.wait()
        self.proc = None

    def call(self, req: dict[str, Any], timeout: float) -> dict[str, Any]:
        if self.proc is None or self.proc.poll() is not None:
            self.start()
        assert self.proc is not None and self.proc.stdin is not None
        start = time.perf_counter()
        try:
            self.proc.stdin.write(json.dumps(req) + "\n")
            self.proc.stdin.flush()
            line = self.lines.get(timeout=timeout)
        except queue.Empty:
            self.stop()
            self.restarts += 1
            return {"outcome": "hang", "wall_s": time.perf_counter() - start, "message": f"over {timeout:g} s"}
        except (BrokenPipeError, OSError) as exc:
            line = None
            err = repr(exc)
        else:
            err = ""
        if line is None:
            code = self.proc.wait() if self.proc is not None else None
            tail = Path(self.log).read_text(errors="replace")[-800:] if os.path.exists(self.log) else ""
            self.stop()
            self.restarts += 1
            return {
                "outcome": "crash",
                "error_type": "WorkerDied",
                "message": f"worker process ended with code {code} {err}; stderr tail: {tail}"[:1200],
                "wall_s": time.perf_counter() - start,
            }
        resp: dict[str, Any] = json.loads(line)
        resp["roundtrip_s"] = time.perf_counter() - start
        return resp


class Pool:
    """``n`` workers; :meth:`map` runs requests with a per-request time bound, results in order."""

    def __init__(self, n: int, log_dir: Path) -> None:
        self.workers = [Worker(log_dir) for _ in range(max(1, n))]

    def map(
        self, reqs: list[dict[str, Any]], timeout: float, progress: Callable[[int], None] | None = None
    ) -> list[dict[str, Any]]:
        todo: queue.Queue[int] = queue.Queue()
        for i in range(len(reqs)):
            todo.put(i)
        results: list[dict[str, Any] | None] = [None] * len(reqs)
        done = [0]
        lock = threading.Lock()

        def loop(w: Worker) -> None:
            while True:
                try:
                    i = todo.get_nowait()
                except queue.Empty:
                    return
                results[i] = w.call(reqs[i], timeout)
                with lock:
                    done[0] += 1
                    if progress:
                        progress(done[0])

        threads = [threading.Thread(target=loop, args=(w,)) for w in self.workers]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        return [r if r is not None else {"outcome": "crash", "message": "no result"} for r in results]

    def close(self) -> None:
        for w in self.workers:
            w.stop()


# -- the fuzz campaign --------------------------------------------------------------------------
@dataclass
class Config:
    n: int = 300
    seed: int = 0
    workers: int = min(2, os.cpu_count() or 1)
    timeout: float = 60.0
    batch_size: int = 100
    batches: bool = True
    models: list[str] | None = None
    edge_prob: float = EDGE_PROB
    all_prob: float = ALL_PROB
    pressure_margin: float = PRESSURE_MARGIN
    method: str = "auto"
    quiet: bool = False
    extra: dict[str, Any] = field(default_factory=dict)


def _rng(seed: int, label: str, salt: str = "") -> np.random.Generator:
    return np.random.default_rng([seed, zlib.crc32((label + salt).encode())])


def _sets_table(system: Any, sets: list[dict[str, float]]) -> dict[str, list[float]]:
    """Random sets (each its own keys) as one ``batch`` mapping: missing keys keep the model's value.

    A valve and the spool that drives it have one stroke (``System.stroke_pairs``): a set that gives one of
    the pair gives it to both, as ``simulate(params=...)`` does, so that the batch runs what the set ran alone.
    """
    base = dict(zip(system.build().parameter_names, system.parameter_vector().tolist()))  # the strokes shared
    sets = [dict(s) for s in sets]
    for a, b in system.stroke_pairs():
        for s in sets:
            if (a in s) != (b in s):
                s[b if a in s else a] = s[a if a in s else b]
    keys = sorted({k for s in sets for k in s})
    return {k: [s.get(k, base[k]) for s in sets] for k in keys}


def _compare_finals(individual: Mapping[str, float], batch: Mapping[str, float], nominal: Mapping[str, float]) -> float:
    """Largest difference of final states, relative to each state's nominal magnitude."""
    return max((abs(individual[n] - batch[n]) / nominal[n] for n in individual), default=0.0)


def fuzz(cfg: Config) -> dict[str, Any]:
    """Run the campaign; a report (records, per-model summaries, batches) as plain data."""
    from hydroservo.io import load_model

    folder = Path(tempfile.mkdtemp(prefix="hydroservo-fuzz-"))
    specs = model_specs(folder / "examples")
    if cfg.models:
        specs = [s for s in specs if s.label in cfg.models or s.label.removesuffix(".toml") in cfg.models]
    pool = Pool(cfg.workers, folder)
    report: dict[str, Any] = {
        "config": {k: v for k, v in vars(cfg).items() if k != "extra"},
        "models": {},
        "records": [],
        "batches": [],
    }
    t0 = time.perf_counter()
    try:
        # draw every set first, then run them all interleaved, so that a slow run of one model
        # does not leave the other workers idle at the end of that model's turn
        plans = []
        for spec in specs:
            system = load_model(spec.source)
            cands, skipped = candidates(system)
            rng = _rng(cfg.seed, spec.label)
            sets = [draw_set(system, cands, rng, cfg.edge_prob, cfg.all_prob) for _ in range(cfg.n)]
            plans.append((spec, system, cands, skipped, sets))
            report["models"][spec.label] = {
                "source": spec.source if spec.source == spec.label else f"example file {spec.label}",
                "t_end": system.t_end,
                "candidates": [c.key for c in cands],
                "skipped": skipped,
            }
        reqs: list[dict[str, Any]] = []
        where: list[tuple[int, int]] = []
        for i in range(cfg.n):
            for m, (spec, _, _, _, sets) in enumerate(plans):
                reqs.append(
                    {
                        "op": "run",
                        "model": spec.source,
                        "params": sets[i],
                        "id": len(reqs),
                        "pressure_margin": cfg.pressure_margin,
                        "method": cfg.method,
                    }
                )
                where.append((m, i))
        total = len(reqs)

        def progress(k: int) -> None:
            if not cfg.quiet and (k % 100 == 0 or k == total):
                print(f"  {k}/{total} runs, {time.perf_counter() - t0:.0f} s", file=sys.stderr)

        results = pool.map(reqs, cfg.timeout, progress)
        report["runs_elapsed_s"] = time.perf_counter() - t0
        by_model: list[list[dict[str, Any]]] = [[{}] * cfg.n for _ in plans]
        for (m, i), r in zip(where, results):
            by_model[m][i] = r
        for (spec, _system, cands, _, sets), outs in zip(plans, by_model):
            specs_by_key = {c.key: c.spec for c in cands}
            records = []
            for i, (s, r) in enumerate(zip(sets, outs)):
                rec = {"model": spec.label, "index": i, "params": s, **r}
                rec["all"] = len(s) == len(cands)
                rec["edges"] = [k for k, v in s.items() if _at_edge(specs_by_key[k], v)]
                rec["slow"] = rec.get("wall_s", 0.0) > SLOW_S or rec.get("roundtrip_s", 0.0) > SLOW_S
                records.append(rec)
            report["records"].extend(records)
        if cfg.batches:
            for spec, system, cands, _, _ in plans:
                records = [r for r in report["records"] if r["model"] == spec.label]
                report["batches"].extend(_batches(cfg, pool, system, spec, cands, records))
    finally:
        pool.close()
        shutil.rmtree(folder, ignore_errors=True)
    report["elapsed_s"] = time.perf_counter() - t0
    report["code"] = _code_version()
    report["worker_restarts"] = sum(w.restarts for w in pool.workers)
    report["summary"] = summarise(report)
    return report


def _code_version() -> str:
    """The commit of the package's checkout (and whether it has changes), for the record."""
    import hydroservo

    root = Path(hydroservo.__file__).resolve().parents[2]
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=root, capture_output=True, text=True)
        dirty = subprocess.run(["git", "status", "--porcelain", "src"], cwd=root, capture_output=True, text=True)
    except OSError:
        return str(root)
    if head.returncode != 0:
        return str(root)
    return head.stdout.strip() + (" + changes in src/" if dirty.stdout.strip() else "")


def _batches(
    cfg: Config, pool: Pool, system: Any, spec: ModelSpec, cands: list[Candidate], records: list[dict[str, Any]]
) -> list[dict[str, Any]]:
    """A batch of fresh random sets, and one mixing sets that ran well alone with one that failed alone."""
    out = []
    model = system.build()
    nominal = dict(zip(model.state_names, model.nominal.tolist()))
    rng = _rng(cfg.seed, spec.label, "batch")
    fresh = [draw_set(system, cands, rng, cfg.edge_prob, cfg.all_prob) for _ in range(cfg.batch_size)]
    timeout = 4 * cfg.timeout
    r = pool.workers[0].call(
        {
            "op": "batch",
            "model": spec.source,
            "sets": _sets_table(system, fresh),
            "pressure_margin": cfg.pressure_margin,
        },
        timeout,
    )
    out.append({"model": spec.label, "kind": "random", "size": len(fresh), **_brief_batch(r)})
    good = [rec for rec in records if rec["outcome"] == "ok"]
    # a set that fails alone: a solver failure first, else any clean error (a set refused by a check), else worse
    bad = [rec for rec in records if rec["outcome"] == "clean_error" and rec.get("error_type") == "SolverError"]
    bad = bad or [rec for rec in records if rec["outcome"] == "clean_error"]
    bad = bad or [rec for rec in records if rec["outcome"] in ("crash", "hang")]
    if good and bad:
        size = min(50, len(good) + 1)
        members = good[: size - 1]
        pos = len(members) // 2
        members.insert(pos, bad[0])
        r = pool.workers[0].call(
            {
                "op": "batch",
                "model": spec.source,
                "sets": _sets_table(system, [m["params"] for m in members]),
                "pressure_margin": cfg.pressure_margin,
                "n_points": SIMULATE_POINTS,  # the output grid of the runs alone: results comparable exactly
            },
            timeout,
        )
        entry = {
            "model": spec.label,
            "kind": "mixed",
            "size": len(members),
            "failing_index": pos,
            "failing_alone": {k: bad[0].get(k) for k in ("index", "outcome", "error_type", "message")},
            **_brief_batch(r),
        }
        if r.get("outcome") == "returned":
            finals, finite = r.get("finals", []), r.get("finite", [])
            diffs = [
                _compare_finals(m["final"], finals[k], nominal)
                for k, m in enumerate(members)
                if k != pos and "final" in m and k < len(finals)
            ]
            entry["good_runs_max_rel_diff"] = max(diffs, default=None)
            entry["failing_row_finite"] = finite[pos] if pos < len(finite) else None
            entry["failing_row_final"] = finals[pos] if pos < len(finals) else None
        out.append(entry)
    else:
        out.append({"model": spec.label, "kind": "mixed", "note": "no run failed alone: nothing to mix"})
    return out


def _brief_batch(r: Mapping[str, Any]) -> dict[str, Any]:
    keep = (
        "outcome",
        "error_type",
        "message",
        "wall_s",
        "runs_returned",
        "failure_marking",
        "marked_failed",
        "per_run",
        "finite",
    )
    out = {k: r[k] for k in keep if k in r}
    if "per_run" in out:
        out["per_run"] = dict(Counter(out["per_run"]))
    if "finite" in out:
        out["finite"] = int(sum(out["finite"]))
    return out


# -- summaries and printing ---------------------------------------------------------------------
_NUM = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def template(message: str) -> str:
    """An error message with its numbers replaced by '#' (messages differ by times and values)."""
    return _NUM.sub("#", message)


def summarise(report: Mapping[str, Any]) -> dict[str, Any]:
    records = report["records"]
    per_model: dict[str, Any] = {}
    labels = list(report["models"])
    for label in [*labels, "total"]:
        recs = [r for r in records if label == "total" or r["model"] == label]
        counts = Counter(r["outcome"] for r in recs)
        walls = [r.get("wall_s", 0.0) for r in recs if r["outcome"] != "hang"]
        fail_walls = [r.get("wall_s", 0.0) for r in recs if r["outcome"] == "clean_error"]
        per_model[label] = {
            "runs": len(recs),
            **{o: counts.get(o, 0) for o in OUTCOMES},
            "slow": sum(1 for r in recs if r["slow"]),
            "slow_failing": sum(1 for r in recs if r["slow"] and r["outcome"] == "clean_error"),
            "slow_by_outcome": dict(Counter(r["outcome"] for r in recs if r["slow"])),
            "wall_median_s": statistics.median(walls) if walls else None,
            "wall_max_s": max(walls) if walls else None,
            "wall_median_clean_error_s": statistics.median(fail_walls) if fail_walls else None,
            "clean_error_unlocated": sum(
                1
                for r in recs
                if r["outcome"] == "clean_error" and r.get("error_type") == "SolverError" and not r.get("located")
            ),
        }

    def key(r: Mapping[str, Any]) -> tuple[str, str]:
        return r.get("error_type", ""), template(r.get("message", ""))

    failed = [r for r in records if r["outcome"] == "clean_error"]
    errors = Counter(key(r) for r in failed)
    top_errors = [
        {
            "type": t,
            "message": m,
            "count": c,
            "models": sorted({r["model"] for r in failed if key(r) == (t, m)}),
            "example": next(r.get("message", "")[:100] for r in failed if key(r) == (t, m)),
            "median_wall_s": statistics.median(r.get("wall_s", 0.0) for r in failed if key(r) == (t, m)),
        }
        for (t, m), c in errors.most_common(10)
    ]
    crashes = [
        {k: r.get(k) for k in ("model", "index", "error_type", "message", "phase", "params", "traceback")}
        for r in records
        if r["outcome"] == "crash"
    ]
    hangs = [{k: r.get(k) for k in ("model", "index", "params")} for r in records if r["outcome"] == "hang"]
    checks: dict[str, Any] = {}
    for r in records:
        for issue in r.get("issues", []):
            c = checks.setdefault(issue["check"], {"runs": set(), "by_model": Counter(), "at_start": 0, "examples": []})
            if (r["model"], r["index"]) in c["runs"]:
                continue
            c["runs"].add((r["model"], r["index"]))
            c["by_model"][r["model"]] += 1
            c["at_start"] += bool(issue.get("at_start"))
            if issue["check"] == "pressure_above_sources":
                c.setdefault("beyond_static_bound", 0)
                c["beyond_static_bound"] += bool(issue.get("beyond_static_bound"))
                ratio = issue.get("ratio", math.inf)
                bucket = next((f"<{b:g}x" for b in (1.2, 1.5, 3.0, 10.0) if ratio < b), ">10x")
                c.setdefault("ratio_to_source", Counter())[bucket] += 1
            if issue["check"] == "position_beyond_stroke":
                c.setdefault("with_end_stops", 0)
                c["with_end_stops"] += bool(issue.get("end_stops"))
            if issue["check"] == "pressure_below_vacuum":
                c.setdefault("more_than_1_bar_below_vacuum", 0)
                c["more_than_1_bar_below_vacuum"] += bool(issue["value"] < VACUUM_PA - 1e5)
            c["examples"].append({"model": r["model"], "index": r["index"], "params": r["params"], **issue})
    for c in checks.values():
        if "ratio_to_source" in c:
            c["ratio_to_source"] = dict(sorted(c["ratio_to_source"].items()))
        c["runs"] = len(c["runs"])
        c["by_model"] = dict(c["by_model"])
        # the examples with the fewest parameters changed, one per model first
        ranked = sorted(c["examples"], key=lambda e: len(e["params"]))
        firsts = {e["model"]: e for e in reversed(ranked)}
        chosen = sorted(firsts.values(), key=lambda e: len(e["params"]))
        c["examples"] = (chosen + [e for e in ranked if e not in chosen])[:6]
    silent_checks = Counter(
        c for r in records if r["outcome"] == "implausible_silent" for c in sorted({i["check"] for i in r["issues"]})
    )
    warned_checks = Counter(
        c for r in records if r["outcome"] == "implausible_warned" for c in sorted({i["check"] for i in r["issues"]})
    )
    py_warn = Counter(w for r in records for w in r.get("py_warnings", []))
    by_kind = {
        kind: dict(Counter(r["outcome"] for r in records if r.get("all") == (kind == "all parameters")))
        for kind in ("1 to 5 parameters", "all parameters")
    }
    edge_outcomes = dict(Counter(r["outcome"] for r in records if r.get("edges")))
    crossed = [r for r in records if r.get("cross_check")]
    cross = {
        "runs": len(crossed),
        "by_outcome": dict(Counter(r["outcome"] for r in crossed)),
        "messages": dict(Counter(template(r["cross_check"])[:120] for r in crossed).most_common(8)),
        "of_clean_errors": sum(1 for r in records if r["outcome"] == "clean_error" and r.get("cross_check")),
        "of_volume_nonpositive": sum(
            1 for r in crossed if any(i["check"] == "chamber_volume_nonpositive" for i in r.get("issues", []))
        ),
    }
    return {
        "per_model": per_model,
        "top_clean_errors": top_errors,
        "crashes": crashes,
        "hangs": hangs,
        "implausible_checks": checks,
        "implausible_silent_by_check": dict(silent_checks),
        "implausible_warned_by_check": dict(warned_checks),
        "python_warnings": dict(py_warn.most_common(10)),
        "outcomes_by_set_kind": by_kind,
        "outcomes_with_an_edge_value": edge_outcomes,
        "cross_checks": cross,
        "result_warnings_attr": any(r.get("has_warnings_attr") for r in records),
    }


def _ms(x: float | None) -> str:
    return "-" if x is None else f"{1000 * x:.1f}"


def format_report(report: Mapping[str, Any]) -> str:
    s = report["summary"]
    lines = []
    head = (
        f"{'model':34s} {'runs':>5s} {'ok':>5s} {'impl+w':>6s} {'impl-s':>6s} {'clean':>5s} {'crash':>5s} "
        f"{'hang':>4s} {'slow':>4s}  {'med ms':>7s} {'max ms':>8s} {'med err ms':>10s}"
    )
    lines += [head, "-" * len(head)]
    for label, m in s["per_model"].items():
        if label == "total":
            lines.append("-" * len(head))
        lines.append(
            f"{label:34s} {m['runs']:5d} {m['ok']:5d} {m['implausible_warned']:6d} {m['implausible_silent']:6d} "
            f"{m['clean_error']:5d} {m['crash']:5d} {m['hang']:4d} {m['slow']:4d}  {_ms(m['wall_median_s']):>7s} "
            f"{_ms(m['wall_max_s']):>8s} {_ms(m['wall_median_clean_error_s']):>10s}"
        )
    tot = s["per_model"]["total"]
    lines.append(
        f"(impl+w / impl-s: implausible with / without result.warnings; slow: over {SLOW_S:g} s, of which "
        f"{tot['slow_failing']} clean errors; solver errors not naming a state and a time: {tot['clean_error_unlocated']}; "
        f"result.warnings exists: {s['result_warnings_attr']}; worker restarts: {report['worker_restarts']}; "
        f"elapsed {report['elapsed_s']:.0f} s; code {report.get('code')})"
    )
    lines.append("")
    lines.append("Most frequent clean errors (numbers shown as #):")
    for e in s["top_clean_errors"]:
        lines.append(
            f"  {e['count']:5d}  {e['type']}: {e['message'][:230]}  [{', '.join(e['models'])}; median "
            f"{e['median_wall_s']:.1f} s]"
        )
    lines.append("")
    lines.append(f"Crashes: {len(s['crashes'])}")
    for c in s["crashes"][:30]:
        lines.append(f"  {c['model']} #{c['index']} {c['error_type']} ({c.get('phase')}): {c['message'][:200]}")
        lines.append(f"      params: {c['params']}")
    if s["hangs"]:
        lines.append(f"Hangs: {len(s['hangs'])}")
        for h in s["hangs"][:20]:
            lines.append(f"  {h['model']} #{h['index']}: {h['params']}")
    lines.append("")
    lines.append("Implausible results by check (runs; at t = 0; examples):")
    for name, c in s["implausible_checks"].items():
        extra = "".join(
            f", {k} {c[k]}"
            for k in ("beyond_static_bound", "ratio_to_source", "with_end_stops", "more_than_1_bar_below_vacuum")
            if k in c
        )
        lines.append(f"  {name}: {c['runs']} runs ({c['by_model']}), at start {c['at_start']}{extra}")
        for ex in c["examples"][:3]:
            shown = {k: ex[k] for k in ("signal", "value", "bound", "t_first") if k in ex}
            params = str(ex["params"])
            params = params if len(params) < 300 else f"{len(ex['params'])} parameters"
            lines.append(f"      {ex['model']} #{ex['index']} {shown} params {params}")
    lines.append(
        f"  silent, by check: {s['implausible_silent_by_check']}; warned, by check: {s['implausible_warned_by_check']}"
    )
    lines.append("")
    lines.append(f"Outcomes by kind of set: {s['outcomes_by_set_kind']}")
    lines.append(f"Outcomes of sets with a value at a closed end of its range: {s['outcomes_with_an_edge_value']}")
    cc = s["cross_checks"]
    lines.append(
        f"Sets a component's own check() refuses when set on the system (simulate(params=) does not check): "
        f"{cc['runs']} ({cc['by_outcome']}); of the clean errors {cc['of_clean_errors']}, of the non-positive "
        f"volumes {cc['of_volume_nonpositive']}"
    )
    for m, n in cc["messages"].items():
        lines.append(f"  {n:5d}  {m}")
    if s["python_warnings"]:
        lines.append("")
        lines.append("Python warnings during runs (runs):")
        for w, n in s["python_warnings"].items():
            lines.append(f"  {n:5d}  {w}")
    if report["batches"]:
        lines.append("")
        lines.append("Batches:")
        for b in report["batches"]:
            if "note" in b:
                lines.append(f"  {b['model']} {b['kind']}: {b['note']}")
                continue
            desc = f"  {b['model']} {b['kind']} ({b['size']} sets): {b.get('outcome')} in {b.get('wall_s', 0):.2f} s"
            if b.get("outcome") == "returned":
                desc += f", {b.get('runs_returned')} runs, finite {b.get('finite')}, checks {b.get('per_run')}"
                if b["kind"] == "mixed":
                    desc += (
                        f", failing row {b['failing_index']} finite {b.get('failing_row_finite')}, good runs vs alone "
                        f"max rel diff {b.get('good_runs_max_rel_diff')}"
                    )
                if b.get("failure_marking"):
                    desc += f", marking {b['failure_marking']}"
            else:
                desc += f": {b.get('error_type')}: {str(b.get('message'))[:160]}"
            if b["kind"] == "mixed":
                fa = b["failing_alone"]
                desc += f"  [set {fa['index']} alone: {fa['outcome']} {fa.get('error_type')}]"
            lines.append(desc)
    return "\n".join(lines)


def _jsonable(x: Any) -> Any:
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, list | tuple | set):
        return [_jsonable(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return str(x)
    if isinstance(x, np.generic):
        return _jsonable(x.item())
    return x


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("n", nargs="?", type=int, default=300, help="random sets per model (default 300)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--json", type=Path, help="write the figures and every run's record here")
    ap.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--timeout", type=float, default=60.0, help="wall-time bound of one run [s] (over it: hang)")
    ap.add_argument("--batch-size", type=int, default=100, help="sets in the random batch of each model")
    ap.add_argument("--no-batch", action="store_true")
    ap.add_argument("--models", nargs="*", help="only these models (labels as printed)")
    ap.add_argument(
        "--pressure-margin",
        type=float,
        default=PRESSURE_MARGIN,
        help="fraction of the largest source pressure a chamber may exceed it by before it is implausible",
    )
    ap.add_argument("--all-prob", type=float, default=ALL_PROB, help="fraction of sets that vary every candidate")
    ap.add_argument("--edge-prob", type=float, default=EDGE_PROB, help="probability of a closed end of a range")
    ap.add_argument("--method", default="auto", help="the solver of every run (default: auto, as a user runs)")
    ap.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.worker:
        worker_main()
        return 0
    cfg = Config(
        n=args.n,
        seed=args.seed,
        workers=args.workers,
        timeout=args.timeout,
        batch_size=args.batch_size,
        batches=not args.no_batch,
        models=args.models,
        all_prob=args.all_prob,
        edge_prob=args.edge_prob,
        pressure_margin=args.pressure_margin,
        method=args.method,
    )
    report = fuzz(cfg)
    print(format_report(report))
    if args.json:
        args.json.write_text(json.dumps(_jsonable(report), indent=1))
        print(f"\nwrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
