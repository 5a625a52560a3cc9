r"""The model-fidelity ladder of [Efe2014], derived automatically from any system.

From a system and an operating point, :func:`build_ladder` makes the rungs,
each an ordinary :class:`~hydroservo.system.System` (so batch runs, plots,
result files and C code work on them):

==========================  =====================================================================
``nonlinear``               the system itself ([Efe2014] section 4.2)
``linear``                  every hydraulic component (valves, cylinders, volumes, lines) replaced
                            by its tangent at the operating point, volumes and bulk moduli frozen
                            (section 4.3, eqs. 4.5-4.14 in general form,
                            :class:`~hydroservo.components.Linearized`); spools, loads, friction
                            and signals stay as they are, as in the thesis
``linear-feedback``         the same, the coefficients re-evaluated from the current state
                            (parameter feedback, section 4.3.3)
``simplified``              where one valve drives one cylinder: the cylinder reduced to its load
                            pressure (section 4.4, eqs. 4.15-4.23,
                            :class:`~hydroservo.components.LoadPressureCylinder`)
``simplified-feedback``     the same with parameter feedback (section 4.4.1)
==========================  =====================================================================

each with the valves' compensation tables :math:`K(x_v)` and
:math:`H(x_v, d_f)` (eqs. 3.22-3.23) on (*improved*, section 5.3) and off
(section 5.2), linearised at the operating point of its own nonlinear model.

:func:`ladder_table` runs every rung for a set of valve-signal steps (the
thesis's 20.3, 25.8, 36.8, 50.5, 71.3 and 91.6 %) and classifies each
model's relative steady-state displacement error as Table 5.3 does: below
7.5 % *accurate*, 7.5-20 % *moderate*, above 20 % *inaccurate*; against the
system as given (the most faithful model) or against measured responses. It
also records each model's cost: states, solver steps and wall time.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from hydroservo.analysis.linear import input_values, operating_point
from hydroservo.components.linearized import Linearized, LoadPressureCylinder
from hydroservo.errors import ModelError, ParameterError, did_you_mean

if TYPE_CHECKING:
    import pandas as pd

    from hydroservo.system.system import System

__all__ = ["RUNGS", "STEPS", "CLASSES", "Rung", "build_ladder", "ladder_table", "classify", "LadderTable", "ladder_defaults"]

RUNGS = ("nonlinear", "linear", "linear-feedback", "simplified", "simplified-feedback")
#: The valve-signal steps of [Efe2014] Table 5.3 [-].
STEPS = (0.203, 0.258, 0.368, 0.505, 0.713, 0.916)
#: Upper bounds of the classes of Table 5.3 [%]: accurate below 7.5, moderate to 20, inaccurate above.
CLASSES = ((7.5, "accurate"), (20.0, "moderate"), (float("inf"), "inaccurate"))


def classify(error_percent: float) -> str:
    """The class of a relative displacement error, [Efe2014] section 5.4."""
    if not np.isfinite(error_percent):
        return "failed"
    for bound, name in CLASSES:
        if abs(error_percent) < bound or (bound == 20.0 and abs(error_percent) <= bound):
            return name
    return "inaccurate"


@dataclass
class Rung:
    """One model of the ladder: its kind, whether the compensation tables are on, and the system."""

    kind: str
    improved: bool
    system: System
    point: dict[str, float] = field(default_factory=dict)

    @property
    def name(self) -> str:
        return ("improved " if self.improved else "") + self.kind


def _probe(comp: Any) -> bool:
    """Whether a component's outputs or rates depend on its states or inputs (a source's do not)."""
    if comp.STATES:
        return True
    if not comp.INPUTS:
        return False
    t = ca.SX.sym("t")
    xs = {k: ca.SX.sym(k) for k in comp.STATES}
    us = {k: ca.SX.sym(k) for k in comp.INPUTS}
    ps = {k: ca.SX.sym(k) for k in comp.PARAMETERS}
    out = comp.output_equations(t, xs, us, ps)
    if not out:
        return False
    g = ca.vertcat(*[ca.SX(v) for v in out.values()])
    return bool(ca.depends_on(g, ca.vertcat(*us.values())))


def _tables_off(system: System) -> bool:
    """Turn the compensation tables of every valve off (K = H = 1); True if any was on."""
    changed = False
    for comp in system.components.values():
        tables = getattr(comp, "tables", None)
        has = getattr(comp, "has_tables", None)
        if isinstance(tables, dict) and callable(has) and has():
            for key in ("K", "H_opening", "H_closing"):
                if key in tables:
                    tables[key] = np.ones_like(tables[key])
            changed = True
    return changed


def _drive(system: System, hydraulic: list[str]) -> tuple[str, str] | None:
    """(valve, cylinder) when the hydraulic components are one four-way valve driving one cylinder."""
    cylinders = [c for c in hydraulic if {"pA", "pB"} == set(system.components[c].STATES)
                 and {"A_A", "A_B"} <= set(system.components[c].PARAMETERS)]
    valves = [c for c in hydraulic if "xv" in system.components[c].INPUTS and {"QA", "QB"} <= set(system.components[c].OUTPUTS)]
    if len(cylinders) == 1 and len(valves) == 1 and set(hydraulic) == {*cylinders, *valves}:
        return valves[0], cylinders[0]
    return None


def build_ladder(
    system: System,
    at: str | Mapping[str, Any] = "trim",
    *,
    t: float = 0.0,
    free: Sequence[str] = (),
    params: Mapping[str, Any] | None = None,
    kinds: Sequence[str] = RUNGS,
    improved: Sequence[bool] = (False, True),
) -> list[Rung]:
    """The rungs (module notes) linearised at the operating point ``at`` (:func:`~hydroservo.analysis.linear.operating_point`:
    with ``free`` states at ``t > 0``, a steady motion through the state a run from the initial state has at ``t``).

    A system without compensation tables has no *improved* rungs apart from its plain ones: they are left out.
    The simplified rungs need one valve driving one cylinder; for other systems they are left out.
    """
    unknown = [k for k in kinds if k not in RUNGS]
    if unknown:
        raise ParameterError(f"ladder: unknown model {unknown[0]!r}; expected some of {', '.join(RUNGS)}")
    rungs: list[Rung] = []
    hydraulic = [n for n, c in system.components.items() if c.HYDRAULIC and _probe(c)]
    if not hydraulic:
        raise ModelError(f"ladder of {system.name!r}: no hydraulic component to linearise")
    drive = _drive(system, hydraulic)
    model = system.build()
    x_init = dict(zip(model.state_names, np.asarray(model.x0(system.parameter_vector(params)), dtype=float).ravel().tolist()))
    flags = [bool(f) for f in improved] if _has_tables(system) else [False]  # no tables: one set of rungs
    for on in flags:
        base = system.copy()
        if not on:
            _tables_off(base)
        x0 = operating_point(base, at, params=params, t=t, free=free)
        u0 = input_values(base, x0, params=params, t=t, components=hydraulic)
        for kind in kinds:
            if kind.startswith("simplified") and drive is None:
                continue
            rung = base.copy()
            rung.name = f"{system.name} ({'improved ' if on else ''}{kind})"
            if kind != "nonlinear":
                mode = "feedback" if kind.endswith("feedback") else "frozen"
                for cname in hydraulic:
                    comp = base.components[cname]
                    point = {**{k: x0[f"{cname}.{k}"] for k in comp.STATES}, **{k: u0[f"{cname}.{k}"] for k in comp.INPUTS}}
                    cls = LoadPressureCylinder if kind.startswith("simplified") and drive and cname == drive[1] else Linearized
                    null = [k for k in ("xv", "vv") if k in comp.INPUTS and {"QA", "QB"} <= set(comp.OUTPUTS)]
                    rung.replace(cls(cname, inner=comp, point=point, null=null, coefficients=mode))
                    if cls is LoadPressureCylinder:
                        a = comp.values["A_B"] / comp.values["A_A"]
                        rung.set_initial(f"{cname}.pL", x_init[f"{cname}.pA"] - a * x_init[f"{cname}.pB"])
            rungs.append(Rung(kind, on, rung, dict(x0)))
    return rungs


def _has_tables(system: System) -> bool:
    """Whether a valve of ``system`` has compensation tables on."""
    for comp in system.components.values():
        has = getattr(comp, "has_tables", None)
        if callable(has) and has():
            return True
    return False


@dataclass
class LadderTable:
    """Final displacements, errors, classes and costs of every rung at every step."""

    steps: list[float]
    parameter: str
    output: str
    reference: str
    table: pd.DataFrame  # rows: rung; columns per step: displacement, error %, class; cost columns
    runs: dict[str, Any] = field(default_factory=dict)  # rung name -> BatchResult

    def classes(self) -> pd.DataFrame:
        """The Table 5.3 view: rung x step, the class of each error."""
        cols = [c for c in self.table.columns if c.startswith("class ")]
        out = self.table[cols].copy()
        out.columns = [c.removeprefix("class ") for c in cols]
        return out.T

    def to_dict(self) -> dict[str, Any]:
        rows = self.table.reset_index().to_dict(orient="records")
        clean = [{k: (None if isinstance(v, float) and not np.isfinite(v) else v) for k, v in r.items()} for r in rows]
        return {"steps": self.steps, "parameter": self.parameter, "output": self.output, "reference": self.reference,
                "classes": {"accurate": "< 7.5 %", "moderate": "7.5-20 %", "inaccurate": "> 20 %"}, "models": clean}


def ladder_table(
    rungs: Sequence[Rung],
    steps: Sequence[float],
    *,
    parameter: str,
    output: str,
    t_end: float | None = None,
    n_points: int = 301,
    reference: Mapping[float, tuple[np.ndarray, np.ndarray]] | None = None,
    repeats: int = 3,
) -> LadderTable:
    """Run every rung at every step (``parameter`` set to each value) and compare the final change of ``output``.

    The reference is the first nonlinear rung with the tables as the system
    has them (the system as given), or measured responses: ``reference[step]
    = (t, y)`` in SI (the change from the first sample to the last). The cost
    of a rung is its states, and the solver steps and wall time (median of
    ``repeats``) of one run at the middle step.
    """
    import pandas as pd

    if not rungs:
        raise ParameterError("ladder: no models")
    steps = [float(s) for s in steps]
    if not steps:
        raise ParameterError("ladder: no steps")
    nonlinear = [r for r in rungs if r.kind == "nonlinear"]
    ref_rung = next((r for r in nonlinear if r.improved), nonlinear[0] if nonlinear else rungs[0])  # the system as given
    t_end = rungs[0].system.t_end if t_end is None else float(t_end)
    finals: dict[str, np.ndarray] = {}
    runs: dict[str, Any] = {}
    costs: dict[str, dict[str, float]] = {}
    for rung in rungs:
        sys_ = rung.system
        if output not in sys_.build().units:
            hint = did_you_mean(output, sys_.build().units)
            raise ParameterError(f"ladder: output {output!r} is not a signal of {sys_.name!r}{hint}")
        batch = sys_.batch({parameter: steps}, t_end, n_points=n_points)
        y = batch[output]
        finals[rung.name] = np.array([y[k, -1] - y[k, 0] if k not in batch.failed else np.nan for k in range(len(steps))])
        runs[rung.name] = batch
        mid = {parameter: steps[len(steps) // 2]}
        walls, nsteps = [], 0.0
        for _ in range(max(1, repeats)):
            t0 = time.perf_counter()
            try:
                res = sys_.simulate(t_end, params=mid, n_points=n_points)
            except Exception:  # noqa: BLE001 - a rung that fails here has failed runs above too
                walls.append(float("nan"))
                continue
            walls.append(time.perf_counter() - t0)
            nsteps = float(res.stats.get("nsteps", np.nan))
        costs[rung.name] = {"states": float(sys_.build().nx), "solver steps": nsteps, "wall time [ms]": 1e3 * float(np.nanmedian(walls))}
    if reference is not None:
        ref_name = "measured"
        ref = np.array([_measured_change(reference, s) for s in steps])
    else:
        ref_name = ref_rung.name
        ref = finals[ref_rung.name]
    rows: dict[str, dict[str, Any]] = {}
    for rung in rungs:
        row: dict[str, Any] = {}
        for k, s in enumerate(steps):
            d = finals[rung.name][k]
            err = 100.0 * (d - ref[k]) / ref[k] if ref[k] else np.nan
            row[f"displacement {100 * s:g} %"] = d
            row[f"error {100 * s:g} % [%]"] = err
            row[f"class {100 * s:g} %"] = classify(err)
            if k in runs[rung.name].warnings:
                row[f"class {100 * s:g} %"] += " (implausible)"
        row.update(costs[rung.name])
        rows[rung.name] = row
    table = pd.DataFrame.from_dict(rows, orient="index")
    table.index.name = "model"
    return LadderTable(steps, parameter, output, ref_name, table, runs)


def _measured_change(reference: Mapping[float, tuple[np.ndarray, np.ndarray]], step: float) -> float:
    for key, (_t, y) in reference.items():
        if abs(float(key) - step) < 1e-9:
            y = np.asarray(y, dtype=float)
            return float(y[-1] - y[0])
    raise ParameterError(f"ladder: no measured response for the step {100 * step:g} %")


def ladder_defaults(system: System) -> dict[str, Any]:
    """What a ladder of ``system`` varies and measures when the user does not say.

    * ``parameter``: the amplitude of the first signal block (Step or Pulse) feeding the system;
    * ``t``: a time when that signal is on (the middle of a pulse; between the step and the end);
    * ``free``: the positions of the masses (``x`` of a component with ``x`` and ``v``), so that the
      operating point is a steady motion;
    * ``output``: the first alias, else the first free position.
    """
    from hydroservo.analysis.linear import SIGNALS

    parameter, t = None, 0.0
    for source in system.connections.values():
        cname = source.split(".")[0]
        comp = system.components.get(cname)
        if comp is not None and type(comp).__name__ in SIGNALS and "amplitude" in comp.PARAMETERS:
            v = comp.values
            if type(comp).__name__ == "Pulse":
                parameter, t = f"{cname}.amplitude", v["t_start"] + 0.5 * v["duration"]
            elif type(comp).__name__ == "Step":
                parameter, t = f"{cname}.amplitude", 0.5 * (v["t_step"] + system.t_end)
            else:
                continue
            break
    free = [f"{n}.x" for n, c in system.components.items() if {"x", "v"} <= set(c.STATES)]
    output = next(iter(system.aliases), free[0] if free else None)
    return {"parameter": parameter, "t": t, "free": free, "output": output}
