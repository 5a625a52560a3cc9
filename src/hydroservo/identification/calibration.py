"""Calibration of any system against rig records: weighted least squares with exact gradients.

The problem
-----------
Given records :math:`e = 1..E` (one experiment each; channels :math:`j` at their
own times :math:`t_{ejk}`), find the parameters :math:`\\theta` minimising

.. math:: \\sum_{e,j,k} \\left(\\frac{y_j(t_{ejk}; \\theta) - \\tilde y_{ejk}}{\\sigma_j}\\right)^2

where :math:`y_j` is the model's signal (a state, output or alias) and
:math:`\\sigma_j` the noise of channel :math:`j`: stated by the user, or
estimated from the residuals of a first fit (then the fit is repeated with
those weights). Parameters are shared by all experiments. A positive
parameter is fitted in log scale (:math:`\\theta = \\ln p`: relative steps,
and it stays positive); others are scaled by their starting value.

Gradients are exact: the sensitivity equations
:math:`\\dot S = f_x S + f_p` are built from the model's CasADi graph and
integrated by CVODES with the states (:meth:`hydroservo.system.model.Model.sensitivities`),
so the Jacobian of the residuals costs one integration of a larger system, not
one integration per parameter as finite differences do, and it is as accurate
as the integration. The optimiser is SciPy's trust-region reflective least
squares (bounds); a trial point where the integrator fails is a rejected step
(its residuals are NaN, which the optimiser answers by shrinking its trust
region), never a crash.

Uncertainty
-----------
At the optimum the Fisher information is :math:`F = J^T J` of the weighted
residuals; the covariance of :math:`\\theta` is :math:`F^{-1}` (Gauss-Newton,
Bard 1974, ch. 7); a parameter's standard error follows by the delta method,
its 95 % interval is taken in the fitted scale (asymmetric in log scale). The
singular value decomposition of :math:`J` names the directions the records do
not determine: a direction whose standard error exceeds
:data:`UNDETERMINED` (relative) is reported with the parameters in it and the
combination that *is* determined.
"""

from __future__ import annotations

import difflib
import math
import re
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.analysis.ladder import classify
from hydroservo.components.signals import Table
from hydroservo.components.sources import PressureTable
from hydroservo.errors import HydroservoError, ParameterError, SolverError, TrimError, UnitError
from hydroservo.identification.records import Channel, Record
from hydroservo.system.integration import Interrupted, SolverSettings, interruptible
from hydroservo.units import coherent_unit, from_si, same_dimension, si_unit, split_quantity, to_si

if TYPE_CHECKING:
    from hydroservo.system.model import Model
    from hydroservo.system.system import System

__all__ = [
    "FitParameter",
    "parse_fit",
    "Experiment",
    "prepare",
    "driven_system",
    "Calibration",
    "calibrate",
    "Prediction",
    "predict",
    "ExperimentPlan",
    "plan_experiment",
    "UNDETERMINED",
]

#: A direction of the parameters whose relative standard error exceeds this is not determined by the records.
UNDETERMINED = 1.0
#: The normal distribution's 97.5 % quantile: a 95 % interval is ±Z95 standard errors (noise stated; Student's t when
#: the noise is estimated from the residuals).
Z95 = 1.959963984540054
#: Correlation beyond which two parameters are reported as hard to tell apart.
CORRELATED = 0.95
#: Default accuracy of the integrations inside a calibration (relative to each signal's range): tighter than a
#: plain simulation's, so that the model's integration error stays well below any sensor's noise.
CALIBRATION_ACCURACY = 1e-7
#: Fits repeated at most with the noise re-estimated from the residuals (signals without a stated noise), until the
#: estimates change by less than REWEIGHT_TOLERANCE (relative).
MAX_REWEIGHTS = 6
REWEIGHT_TOLERANCE = 0.05
#: Bounds of a positive parameter given none: this factor either side of its starting value.
DEFAULT_SPAN = 100.0

_RANGE = re.compile(r"^\s*(?P<lo>[^.]+(?:\.\d*)?(?:[eE][-+]?\d+)?[^.]*?)\s*\.\.\s*(?P<hi>.+?)\s*$")


# -- what is fitted -----------------------------------------------------------
@dataclass(frozen=True)
class FitParameter:
    """One fitted parameter: ``name`` ("comp.param"), the ``unit`` its values are shown in (as the user gave it),
    bounds and start (SI), and whether it is fitted in log scale."""

    name: str
    unit: str
    si_unit: str
    start: float
    lower: float
    upper: float
    log: bool

    def shown(self, value: float) -> float:
        """``value`` (SI) in the user's unit."""
        return from_si(value, self.si_unit, self.unit) if self.unit != self.si_unit else float(value)

    def theta(self, value: float) -> float:
        return math.log(value) if self.log else value / self.scale

    def value(self, theta: float) -> float:
        return math.exp(theta) if self.log else theta * self.scale

    @property
    def scale(self) -> float:
        """Linear-scale parameters are fitted as multiples of this (their starting magnitude, or 1)."""
        return abs(self.start) if self.start != 0 else 1.0


def _user_unit(given: str | None, si: str) -> str:
    if given:
        try:
            _, unit = split_quantity(given)
        except HydroservoError:
            return si
        if unit and same_dimension(unit, si):
            return unit
    return si


def parse_fit(system: System, fit: Mapping[str, Any] | Sequence[str]) -> list[FitParameter]:
    """The fitted parameters from ``{"comp.param": None | (lo, hi) | "LO..HI"}`` or ``["comp.param[=LO..HI]"]``.

    Bounds carry units (``"1e-5 m^2/s/Pa^0.5..1e-3 m^2/s/Pa^0.5"``, or ``"5..50 ms"``); without bounds a
    positive parameter may move a factor of :data:`DEFAULT_SPAN` either way, within its declared range. The
    start is the system's value. Values are reported in the unit of the bounds, else the unit the model gives
    the parameter in.
    """
    items: list[tuple[str, Any]] = []
    if isinstance(fit, Mapping):
        items = list(fit.items())
    else:
        for text in fit:
            if not isinstance(text, str):
                raise ParameterError(f"fit: {text!r}: expected 'comp.param' or 'comp.param=LO..HI'")
            name, _, bounds = text.partition("=")
            items.append((name.strip(), bounds.strip() or None))
    if not items:
        raise ParameterError("fit: no parameter to fit; expected at least one 'comp.param'")
    known = system.parameter_names()
    out: list[FitParameter] = []
    for raw, bounds in items:
        try:
            key = system.parameter_key(raw)
        except HydroservoError:
            close = difflib.get_close_matches(raw, known, n=3)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            raise ParameterError(f"fit: {raw!r} is not a parameter of {system.name!r}{hint}") from None
        if any(f.name == key for f in out):
            raise ParameterError(f"fit: {key} is given twice")
        shared = [pair for pair in system.stroke_pairs() if key in pair]
        if shared:
            raise ParameterError(
                f"fit: {key} is the stroke {' and '.join(shared[0])} share; a shared stroke cannot be fitted yet "
                "(fit the flow coefficient, which scales the flow the same way)"
            )
        cname, pname = key.split(".", 1)
        comp = system[cname]
        spec = comp.PARAMETERS[pname]
        si = spec.unit
        start = float(comp.values[pname])
        unit = _user_unit(comp.given.get(pname), si)
        lo, hi = spec.min, spec.max
        log = start > 0 and (spec.min is None or spec.min >= 0)
        if bounds is not None:
            lo_text, hi_text = _bounds(bounds, key)
            hi_unit = _user_unit(hi_text, si) if not _bare(hi_text) else unit
            lo_v = to_si(lo_text if not _bare(lo_text) else f"{lo_text} {hi_unit}" if hi_unit else lo_text, si, what=f"fit {key} lower bound")
            hi_v = to_si(hi_text if not _bare(hi_text) else f"{hi_text} {unit}" if unit else hi_text, si, what=f"fit {key} upper bound")
            unit = hi_unit
            if not lo_v < hi_v:
                raise ParameterError(f"fit: {key} = {bounds}: the lower bound must be below the upper bound")
            lo, hi = lo_v, hi_v
            if not lo <= start <= hi:
                start = math.sqrt(lo * hi) if lo > 0 else 0.5 * (lo + hi)
            log = lo > 0
        elif log:
            lo = max(start / DEFAULT_SPAN, spec.min if spec.min is not None else 0.0) or start / DEFAULT_SPAN
            hi = min(start * DEFAULT_SPAN, spec.max) if spec.max is not None else start * DEFAULT_SPAN
        if lo is None or hi is None or (log and lo <= 0):
            lo = -math.inf if lo is None else lo
            hi = math.inf if hi is None else hi
        if log and lo == start:
            lo = start * (1 - 1e-9)
        out.append(FitParameter(key, unit, si, start, float(lo), float(hi), bool(log)))
    return out


def _bare(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _bounds(bounds: Any, key: str) -> tuple[str, str]:
    if isinstance(bounds, (tuple, list)) and len(bounds) == 2:
        return str(bounds[0]).strip(), str(bounds[1]).strip()
    if isinstance(bounds, str) and ".." in bounds:
        lo, hi = bounds.split("..", 1)
        if lo.strip() and hi.strip():
            return lo.strip(), hi.strip()
    raise ParameterError(f"fit: {key} = {bounds!r}: expected bounds LO..HI, e.g. '10 ms..100 ms' or (lo, hi)")


# -- one experiment -------------------------------------------------------------
@dataclass
class Experiment:
    """A record prepared for a system: the system driven by the recorded inputs, the output times, and what is
    compared (channel names, values in the model's units, their sample indices into :attr:`grid`)."""

    record: Record
    system: System
    model: Model
    grid: np.ndarray
    inputs: list[str]
    measured: list[str]
    values: dict[str, np.ndarray]  # measured values at their times, in the model's unit
    index: dict[str, np.ndarray]  # positions of the channel's samples (with a value) in the grid
    fixed_states: dict[str, float]  # initial states taken from the record (SI)
    estimate_initial: list[str] = field(default_factory=list)
    trim: bool = False  # the states not measured start in equilibrium with the measured ones

    @property
    def name(self) -> str:
        return self.record.name

    def unit(self, signal: str) -> str:
        """The model's unit of ``signal``: values, residuals and traces are in it."""
        return self.model.units.get(signal, "")

    def shown(self, signal: str, unit: str | None = None) -> tuple[float, str]:
        """``(factor, unit)``: the unit a person reads ``signal`` in (``unit``, else the record column's) and the
        factor from the model's unit to it."""
        own = self.unit(signal)
        shown = unit or self.record[signal].unit or own
        return (1.0 if shown == own else from_si(1.0, own, shown)), shown


def _signals(model: Model) -> list[str]:
    return [*model.state_names, *model.output_names]


def _closest(name: str, names: Sequence[str]) -> str:
    close = difflib.get_close_matches(name, names, n=3, cutoff=0.5)
    return f"; did you mean {', '.join(close)}?" if close else ""


def _driven(system: System, record: Record, signal: str) -> None:
    """Replace the source of ``signal`` in ``system`` by the recorded ``signal``."""
    cname, _, out = signal.partition(".")
    if cname not in system.components or not out:
        names = [f"{c}.{o}" for c, comp in system.components.items() for o in comp.OUTPUTS]
        raise ParameterError(f"input {signal!r}: not an output of {system.name!r}{_closest(signal, names)}")
    comp = system[cname]
    if out not in comp.OUTPUTS:
        raise ParameterError(f"input {signal!r}: {cname} has no output {out!r}; it has {', '.join(comp.OUTPUTS)}")
    if comp.STATES or comp.INPUTS and any(k.startswith(cname + ".") for k in system.connections):
        raise ParameterError(
            f"input {signal!r}: {cname} is a {type(comp).__name__} with dynamics or inputs; only a signal source or a "
            "pressure source can be replaced by a record"
        )
    channel = record[signal]
    unit = comp.OUTPUTS[out].unit
    ok = channel.valid
    values = channel.to(unit)[ok]
    if out == "y":
        system.replace(Table(cname, times=channel.t[ok], values=values, unit=comp.unit))
    elif out == "p" and "P" in comp.HYDRAULIC:
        system.replace(PressureTable(cname, times=channel.t[ok], pressures=np.maximum(values, 0.0)))
    else:
        raise ParameterError(
            f"input {signal!r}: only a signal block's output y or a pressure source's p can be driven by a record"
        )


def driven_system(system: System, record: Record, inputs: Sequence[str]) -> System:
    """A copy of ``system`` whose sources of ``inputs`` (``"command.y"``, ``"supply.p"``) replay the record."""
    missing = [s for s in inputs if s not in record]
    if missing:
        raise ParameterError(
            f"record {record.name!r}: no column {missing[0]!r} to drive the model with; it has {', '.join(record.names)}"
        )
    driven = system.copy()
    for signal in inputs:
        _driven(driven, record, signal)
    return driven


#: How far below vacuum a recorded pressure may read before it is refused [Pa]: a transducer's offset and noise,
#: a tenth of a bar (oil itself cannot be below absolute zero pressure).
RECORD_VACUUM_SLACK = 1e4
#: A recorded state more than this many times the model's nominal magnitude of it is refused: no unit slip of a
#: real sensor reaches it, an overflowed or garbled cell does (1e308).
RECORD_SCALE_LIMIT = 1e6


def record_fault(model: Model, p: np.ndarray, record: Record, names: Sequence[str]) -> str | None:
    """The first recorded value of the signals ``names`` the model cannot take, as a message naming the record,
    its column and data row, the value and what was expected; None if there is none.

    Checked against the bounds the model's components declare (:mod:`hydroservo.system.plausibility`): a pressure
    more than :data:`RECORD_VACUUM_SLACK` below vacuum, a position beyond its end stops by more than the
    plausibility margin (1 % of the stroke); also a value that is no finite number once in SI, and a state more than
    :data:`RECORD_SCALE_LIMIT` times its nominal magnitude. Such a value (a column in the wrong unit, an overflowed
    cell) would otherwise surface as a model that cannot be integrated or a balance that does not exist.
    """
    from hydroservo.system.plausibility import TRAVEL_MARGIN
    from hydroservo.units import VACUUM

    lows, highs = (np.asarray(b, dtype=float).ravel() for b in model.limit_bounds(p))
    watched = {w.signal: (w, float(lo), float(hi)) for w, lo, hi in zip(model.watched, lows, highs)}
    for name in names:
        if name not in record:
            continue
        ch = record[name]
        unit = coherent_unit(model.units.get(name, ""))
        try:
            with np.errstate(over="ignore", invalid="ignore"):
                v = ch.to(unit)
        except UnitError:
            continue  # the dimension is refused where the column is compared
        given = np.isfinite(ch.values)
        faults: list[tuple[np.ndarray, str]] = [(given & ~np.isfinite(v), f"a finite number in {si_unit(unit)}")]
        w = watched.get(name)
        if w is not None and w[0].kind == "pressure":
            faults.append((given & (v < VACUUM - RECORD_VACUUM_SLACK),
                           f"a pressure at or above vacuum ({VACUUM / 1e5:.4g} bar gauge): oil cannot be below absolute zero"))
        if w is not None and w[0].kind == "travel" and math.isfinite(w[1]) and math.isfinite(w[2]) and abs(w[2] - w[1]) < 1e20:
            slack = TRAVEL_MARGIN * (w[2] - w[1])
            faults.append((given & ((v < w[1] - slack) | (v > w[2] + slack)),
                           f"a position within {w[0].owner}'s stroke, {w[1]:.4g} .. {w[2]:.4g} m"))
        if name in model.state_names:
            scale = float(model.nominal[model.state_names.index(name)])
            faults.append((given & (np.abs(v) > RECORD_SCALE_LIMIT * scale),
                           f"a value within {RECORD_SCALE_LIMIT:.0e} times the model's magnitude of {name} ({scale:g} {si_unit(unit)})"))
        for mask, expected in faults:
            if mask.any():
                k = int(np.argmax(mask))
                row = f"data row {k + 1}" if ch.source else f"sample {k + 1}"
                shown = f"{ch.values[k]:g} {si_unit(ch.unit)}".strip()
                converted = f" = {v[k]:.4g} {si_unit(unit)}" if ch.unit != unit and np.isfinite(v[k]) else ""
                return (
                    f"record {record.name!r} ({ch.where}, {row}, t = {ch.t[k]:g} s): {shown}{converted}; expected "
                    f"{expected}. Is the column's unit ([{ch.unit}]) right?"
                )
    return None


def prepare(
    system: System, record: Record, inputs: Sequence[str] = (), *, initial: str = "record",
) -> Experiment:
    """``record`` as an experiment of ``system``: ``inputs`` replace their sources by the recorded signals, every
    other channel that names a model signal is compared.

    ``initial``: ``"record"`` (states measured at the start take their recorded value, the rest the model's),
    ``"model"`` (the model's initial state), ``"estimate"`` (the measured states' initial values are fitted
    with the parameters, starting from the record's), or ``"trim"`` (the measured states from the record, the
    others in equilibrium with them: :meth:`~hydroservo.system.model.Model.trim` with the measured ones held;
    their derivatives follow by the implicit-function theorem).
    """
    if initial not in ("record", "model", "estimate", "trim"):
        raise ParameterError(f"initial = {initial!r}: expected 'estimate', 'record', 'trim' or 'model'")
    driven = driven_system(system, record, inputs)
    model = driven.build()
    known = _signals(model)
    measured = [n for n in record.names if n not in inputs]
    unknown = [n for n in measured if n not in known]
    if unknown:
        raise ParameterError(
            f"record {record.name!r} ({record[unknown[0]].source or 'given'}): column {unknown[0]!r} is not a signal "
            f"of {system.name!r}{_closest(unknown[0], known)}"
        )
    if not measured:
        raise ParameterError(
            f"record {record.name!r}: no column to compare with the model besides the inputs ({', '.join(inputs)}); "
            f"expected signals such as {', '.join(known[:4])}"
        )
    t0 = record.span[0]
    grid = np.unique(np.concatenate([[t0], *(record[n].t for n in measured)]))
    values, index = {}, {}
    for n in measured:
        ch = record[n]
        ok = ch.valid & (ch.t >= t0)
        values[n] = ch.to(model.units.get(n, ""))[ok]
        index[n] = np.searchsorted(grid, ch.t[ok])
    fault = record_fault(model, driven.parameter_vector(), record, [*measured, *inputs])
    if fault:
        raise ParameterError(fault)
    fixed: dict[str, float] = {}
    estimate: list[str] = []
    if initial in ("record", "estimate", "trim"):
        for n in measured:
            if n in model.state_names:
                fixed[n] = record.value_at(n, t0, coherent_unit(model.units.get(n, "")))
        if initial == "estimate":
            estimate = list(fixed)
    trim = initial == "trim" and len(fixed) < model.nx
    return Experiment(record, driven, model, grid, list(inputs), measured, values, index, fixed, estimate, trim)


# -- the problem -------------------------------------------------------------
class _Problem:
    """Residuals and their Jacobian in the fitted variables, over all experiments."""

    def __init__(
        self, experiments: list[Experiment], params: list[FitParameter], sigma: dict[str, float],
        settings: SolverSettings,
    ) -> None:
        self.experiments, self.params, self.sigma, self.settings = experiments, params, sigma, settings
        self.nfev = 0
        self.njev = 0
        #: the flag of the interrupt guard a start on a worker thread runs under (:func:`interruptible`), or None
        self.stop: Any = None
        # the initial states estimated per experiment come after the shared parameters
        self.extra = [(e, s) for e, exp in enumerate(experiments) for s in exp.estimate_initial]
        self.base = [exp.system.parameter_vector() for exp in experiments]
        self.columns = [[exp.model.parameter_names.index(p.name) for p in params] for exp in experiments]
        self.size = sum(v.size for exp in experiments for v in exp.values.values())

    @property
    def names(self) -> list[str]:
        return [p.name for p in self.params] + [f"{self.experiments[e].name}:{s}(0)" for e, s in self.extra]

    def start(self) -> np.ndarray:
        own = [p.theta(p.start) for p in self.params]
        extra = [self.experiments[e].fixed_states[s] / self._nominal(e, s) for e, s in self.extra]
        return np.array(own + extra, dtype=float)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        lo = [p.theta(p.lower) if math.isfinite(p.lower) else -np.inf for p in self.params] + [-np.inf] * len(self.extra)
        hi = [p.theta(p.upper) if math.isfinite(p.upper) else np.inf for p in self.params] + [np.inf] * len(self.extra)
        return np.array(lo), np.array(hi)

    def _nominal(self, e: int, state: str) -> float:
        m = self.experiments[e].model
        return float(m.nominal[m.state_names.index(state)])

    def values(self, theta: np.ndarray) -> list[float]:
        return [p.value(float(th)) for p, th in zip(self.params, theta)]

    def _setup(self, e: int, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        exp = self.experiments[e]
        p = self.base[e].copy()
        for c, v in zip(self.columns[e], self.values(theta)):
            p[c] = v
        x0 = np.asarray(exp.model.x0(p), dtype=float).ravel()
        for s, v in exp.fixed_states.items():
            x0[exp.model.state_names.index(s)] = v
        for k, (ee, s) in enumerate(self.extra):
            if ee == e:
                x0[exp.model.state_names.index(s)] = theta[len(self.params) + k] * self._nominal(e, s)
        if exp.trim:
            t0 = float(exp.grid[0])
            steady = exp.model.trim(p, t=t0, x_guess=x0, free=list(exp.fixed_states), steady_motion=False)
            x0 = np.array([steady[n] for n in exp.model.state_names])
        return p, x0

    def _trimmed_directions(self, e: int, p: np.ndarray, x0: np.ndarray, dx0: np.ndarray, scale: list[float]) -> None:
        """Derivatives of the trimmed initial states (implicit-function theorem on f_s(x_s, x_m, p) = 0)."""
        exp = self.experiments[e]
        m = exp.model
        t0 = float(exp.grid[0])
        held = np.array([n in exp.fixed_states for n in m.state_names])
        A = m.linearize(x0, p, t0)
        forcing = np.zeros((m.nx, dx0.shape[1]))
        if self.params:
            forcing[:, : len(self.params)] = m.parameter_jacobian(t0, x0, p)[:, self.columns[e]] * np.asarray(scale[: len(self.params)])
        rhs = A[np.ix_(~held, held)] @ dx0[held] + forcing[~held]
        # in scaled states, and least-norm: a state the equilibrium leaves free (a rod's position under a closed
        # valve) keeps its guess, as the trim itself does, and gets no derivative along that freedom
        nom = m.nominal[~held]
        Az = A[np.ix_(~held, ~held)] * nom[None, :] / nom[:, None]
        dz, *_ = np.linalg.lstsq(Az, rhs / nom[:, None], rcond=1e-9)
        dx0[~held] = -dz * nom[:, None]

    def _signals(self, e: int, X: np.ndarray, p: np.ndarray) -> dict[str, np.ndarray]:
        exp = self.experiments[e]
        m = exp.model
        outs = [n for n in exp.measured if n not in m.state_names]
        Y = {}
        if outs:
            vals = m.outputs.map(exp.grid.size)(exp.grid[None, :], X, np.repeat(p[:, None], exp.grid.size, axis=1))
            vals = np.asarray(vals, dtype=float)
            for n in outs:
                Y[n] = vals[m.output_names.index(n)]
        for n in exp.measured:
            if n in m.state_names:
                Y[n] = X[m.state_names.index(n)]
        return Y

    def simulate(self, e: int, theta: np.ndarray) -> dict[str, np.ndarray]:
        """The compared signals of experiment ``e`` over its grid (model units)."""
        exp = self.experiments[e]
        p, x0 = self._setup(e, theta)
        initial = dict(zip(exp.model.state_names, x0.tolist()))
        result = exp.model.simulate(
            0.0, p, t_eval=exp.grid.tolist(), rtol=self.settings.rtol, atol=self.settings.atol,
            max_steps=self.settings.max_steps, initial=initial,
        )
        X = np.vstack([result[s] for s in exp.model.state_names]) if exp.model.nx else np.zeros((0, exp.grid.size))
        return self._signals(e, X, p)

    def _check_stop(self) -> None:
        """Raises :class:`Interrupted` once Ctrl-C has set the flag of a guard this fit runs under (a start on a
        worker thread, whose integrations may not see the signal themselves)."""
        if self.stop is not None and self.stop.value:
            raise Interrupted(f"calibration ({self.nfev} evaluations of this start done)")

    def residuals(self, theta: np.ndarray) -> np.ndarray:
        self._check_stop()
        self.nfev += 1
        parts = []
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # implausible trial points are judged by their residuals
                for e, exp in enumerate(self.experiments):
                    Y = self.simulate(e, theta)
                    parts += [(Y[n][exp.index[n]] - exp.values[n]) / self.sigma[n] for n in exp.measured]
        except (SolverError, ParameterError, TrimError):
            return np.full(self.size, np.nan)  # a rejected trial point
        return np.concatenate(parts)

    def jacobian(self, theta: np.ndarray) -> np.ndarray:
        self._check_stop()
        self.njev += 1
        nth = theta.size
        blocks = []
        for e, exp in enumerate(self.experiments):
            m = exp.model
            p, x0 = self._setup(e, theta)
            values = self.values(theta)
            columns: list[int | None] = list(self.columns[e]) + [None] * len(self.extra)
            scale = [v if par.log else par.scale for par, v in zip(self.params, values)] + [1.0] * len(self.extra)
            dx0 = np.zeros((m.nx, nth))
            if self.params:
                dx0[:, : len(self.params)] = m.initial_jacobian(p)[:, self.columns[e]] * np.asarray(scale[: len(self.params)])
            for s in exp.fixed_states:  # a state taken from the record does not follow the parameters
                dx0[m.state_names.index(s), :] = 0.0
            for k, (ee, s) in enumerate(self.extra):
                if ee == e:
                    i = m.state_names.index(s)
                    dx0[i, len(self.params) + k] = self._nominal(e, s)
            if exp.trim:
                self._trimmed_directions(e, p, x0, dx0, scale)
            X, S = m.sensitivities(exp.grid, p, x0, dx0, columns, scale, self.settings)
            outs = [n for n in exp.measured if n not in m.state_names]
            dY: dict[str, np.ndarray] = {}
            if outs:
                _, dYo = m.output_sensitivities(outs, exp.grid, X, S, p, columns, scale)
                for i, n in enumerate(outs):
                    dY[n] = dYo[:, i, :]
            for n in exp.measured:
                if n in m.state_names:
                    dY[n] = S[:, m.state_names.index(n), :]
            blocks += [dY[n][exp.index[n]] / self.sigma[n] for n in exp.measured]
        return np.vstack(blocks)


# -- the result -------------------------------------------------------------
@dataclass
class SignalFit:
    """How one signal fits: its RMS residual and the noise it was weighted with, in ``unit``."""

    name: str
    unit: str
    rms: float
    noise: float
    noise_given: bool
    samples: int


@dataclass
class Calibration:
    """The outcome of :func:`calibrate`: parameter values (SI and the user's unit), standard errors, 95 %
    intervals, correlations, identifiability warnings, residuals per signal, and the calibrated system."""

    parameters: list[FitParameter]
    values: np.ndarray  # SI
    stderr: np.ndarray  # SI (delta method)
    ci95: np.ndarray  # SI, n x 2
    correlation: np.ndarray
    names: list[str]
    signals: list[SignalFit]
    experiments: list[Experiment]
    traces: list[dict[str, np.ndarray]]  # the model's compared signals per experiment, at the fitted values
    system: System
    success: bool
    message: str
    cost: float
    nfev: int
    njev: int
    seconds: float
    warnings: list[str] = field(default_factory=list)
    initial_states: dict[str, float] = field(default_factory=dict)
    starts: list[dict[str, Any]] = field(default_factory=list)
    gradient: str = "exact"

    def parameter(self, name: str) -> dict[str, Any]:
        k = [p.name for p in self.parameters].index(name)
        p = self.parameters[k]
        return {
            "value": p.shown(self.values[k]),
            "unit": p.unit,
            "stderr": abs(p.shown(self.values[k] + self.stderr[k]) - p.shown(self.values[k])),
            "ci95": [p.shown(self.ci95[k, 0]), p.shown(self.ci95[k, 1])],
            "start": p.shown(p.start),
            "bounds": [p.shown(p.lower), p.shown(p.upper)],
            "log_scale": p.log,
        }

    def to_dict(self) -> dict[str, Any]:
        n = len(self.parameters)
        return {
            "parameters": {p.name: self.parameter(p.name) for p in self.parameters},
            "correlation": {a: {b: float(self.correlation[i, j]) for j, b in enumerate(self.names[:n])} for i, a in enumerate(self.names[:n])},
            "signals": {s.name: {"rms": s.rms, "unit": s.unit, "noise": s.noise, "noise_given": s.noise_given, "samples": s.samples} for s in self.signals},
            "initial_states": dict(self.initial_states),
            "converged": self.success,
            "cost": self.cost,
            "evaluations": {"residuals": self.nfev, "jacobians": self.njev, "gradient": self.gradient},
            "seconds": self.seconds,
            "starts": self.starts,
            "warnings": list(self.warnings),
        }

    def lines(self) -> list[str]:
        from hydroservo.io.text import text_table

        rows = []
        for p in self.parameters:
            d = self.parameter(p.name)
            rows.append([p.name, d["value"], d["stderr"], f"[{d['ci95'][0]:.5g}, {d['ci95'][1]:.5g}]", si_unit(p.unit)])
        out = text_table(rows, ["parameter", "value", "± stderr", "95 % interval", "unit"], digits=[5, 5, 3])
        out.append("")
        out += text_table(
            [[s.name, s.rms, f"{s.noise:.3g}" + ("" if s.noise_given else " (est.)"), si_unit(s.unit)] for s in self.signals],
            ["signal", "RMS residual", "noise", "unit"], digits=4, align=["left", "decimal", "right", "left"],
        )
        n = len(self.parameters)
        if n > 1:
            out.append("")
            out += text_table([[f"{i + 1} {name}", *(f"{self.correlation[i, j]:+.2f}" for j in range(n))]
                               for i, name in enumerate(self.names[:n])], ["correlation", *map(str, range(1, n + 1))],
                              align=["left", *["right"] * n])
        out.append("")
        status = "converged" if self.success else "NOT converged"
        out.append(
            f"{status} after {self.nfev} residual and {self.njev} {self.gradient} Jacobian evaluations ({self.seconds:.2f} s)"
        )
        return out

    def plot(self, experiment: int | str = 0, *, file: Any = None, units: Mapping[str, str] | None = None) -> Any:
        """Measured against model, with the residuals, for one experiment (its index or name)."""
        from hydroservo.plotting.calibration import plot_fit

        k = experiment if isinstance(experiment, int) else [e.name for e in self.experiments].index(experiment)
        return plot_fit(self.experiments[k], self.traces[k], title=f"{self.system.name}: {self.experiments[k].name}", file=file, units=units)


def _noise(
    noise: Mapping[str, Any] | None, experiments: list[Experiment]
) -> tuple[dict[str, float], dict[str, bool]]:
    """The noise of each compared signal in the model's unit: given (a quantity, or a number in the unit of the
    first record that has the signal), else 1 % of its measured range until estimated."""
    measured: dict[str, tuple[Experiment, Channel]] = {}
    for exp in experiments:
        for n in exp.measured:
            measured.setdefault(n, (exp, exp.record[n]))
    sigma, given = {}, {}
    for n, (exp, ch) in measured.items():
        unit = exp.unit(n)
        if noise and n in noise:
            v = noise[n]
            text = f"{v} {ch.unit}" if isinstance(v, (int, float)) or (isinstance(v, str) and _bare(v)) else str(v)
            try:
                si = to_si(text, coherent_unit(unit), what=f"noise of {n}")
            except UnitError as exc:
                raise UnitError(f"noise {n} = {v!r}: {exc}") from None
            if not si > 0:
                raise ParameterError(f"noise {n} = {v!r}: expected a positive standard deviation")
            sigma[n] = from_si(si, coherent_unit(unit), unit) if unit != coherent_unit(unit) else si
            given[n] = True
        else:
            spans = [np.ptp(e.values[n]) for e in experiments if n in e.values]
            span = max(spans) if spans else 0.0
            sigma[n] = 0.01 * span if span > 0 else 1.0
            given[n] = False
    unknown = [n for n in (noise or {}) if n not in measured]
    if unknown:
        raise ParameterError(f"noise: {unknown[0]!r} is not a compared signal; compared: {', '.join(measured)}")
    return sigma, given


def _correlation(cov: np.ndarray) -> np.ndarray:
    """The correlation matrix of a covariance matrix."""
    sd = np.sqrt(np.maximum(np.diag(cov), 1e-300))
    corr: np.ndarray = cov / np.outer(sd, sd)
    return corr


def _intervals(
    params: list[FitParameter], theta: np.ndarray, cov: np.ndarray, quantile: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    values = np.array([p.value(float(t)) for p, t in zip(params, theta)])
    sd = np.sqrt(np.maximum(np.diag(cov)[: len(params)], 0.0))
    stderr = np.array([v * s if p.log else p.scale * s for p, v, s in zip(params, values, sd)])
    lo = np.array([p.value(float(t - quantile * s)) for p, t, s in zip(params, theta, sd)])
    hi = np.array([p.value(float(t + quantile * s)) for p, t, s in zip(params, theta, sd)])
    return values, stderr, np.column_stack([lo, hi])


def _combination(names: list[str], params: list[FitParameter], J: np.ndarray, cov: np.ndarray, involved: list[int]) -> str:
    """The best-determined combination of the parameters ``involved`` (the leading right singular vector of their
    columns of ``J``), as a product of powers (log-scale parameters) or a weighted sum, with its standard error."""
    _, _, vt = np.linalg.svd(J[:, involved], full_matrices=False)
    w = vt[0] / vt[0][np.argmax(np.abs(vt[0]))]
    full = np.zeros(cov.shape[0])
    full[involved] = w
    se = float(np.sqrt(max(full @ cov @ full, 0.0)))
    if all(params[i].log for i in involved):
        text = " · ".join(f"{names[i]}^{wi:.2f}" for i, wi in zip(involved, w))
        return f"{text} (to ±{100 * se:.2g} %)"
    text = " ".join(f"{wi:+.2f}·{names[i]}/{params[i].scale:.3g}" for i, wi in zip(involved, w))
    return f"{text} (to ±{se:.2g})"


def _identifiability(names: list[str], params: list[FitParameter], J: np.ndarray, cov: np.ndarray) -> list[str]:
    """Plain warnings for what ``J`` does not determine: directions of the parameters with a relative standard
    error above :data:`UNDETERMINED`, and pairs correlated beyond :data:`CORRELATED`; each with the combination
    of the same parameters that the records do determine."""
    n = len(params)
    if n == 0 or J.size == 0:
        return []
    Jp = J[:, :n]
    _, s, Vt = np.linalg.svd(Jp, full_matrices=False)
    out = []
    named: list[set[int]] = []
    for k, sk in enumerate(s):
        se = 1.0 / sk if sk > 0 else math.inf
        if se <= UNDETERMINED:
            continue
        v = Vt[k]
        involved = [int(i) for i in np.argsort(-np.abs(v)) if abs(v[i]) >= 0.2]
        if not involved:
            continue
        named.append(set(involved))
        label = ", ".join(names[i] for i in involved)
        size = f"only to ±{100 * se:.0f} %" if math.isfinite(se) and se < 100 else "nothing"
        if len(involved) == 1:
            out.append(f"the records do not determine {label}: they fix it {size}")
            continue
        out.append(
            f"the records cannot separate {label}: along one combination of them they fix {size}; "
            f"what they determine is {_combination(names, params, J, cov, involved)}"
        )
    corr = _correlation(cov)
    for i in range(n):
        for j in range(i + 1, n):
            if abs(corr[i, j]) > CORRELATED and not any({i, j} <= group for group in named):
                out.append(
                    f"{names[i]} and {names[j]} are correlated ({corr[i, j]:+.3f}): the records barely tell them apart; "
                    f"what they determine is {_combination(names, params, J, cov, [i, j])}"
                )
    return out


def _solve(problem: _Problem, theta0: np.ndarray, gradient: str, max_nfev: int) -> Any:
    from scipy.optimize import least_squares

    lo, hi = problem.bounds()
    inside = 1e-9 * (1 + np.abs(theta0))
    theta0 = np.minimum(np.maximum(theta0, lo + inside), hi - inside)
    r0 = problem.residuals(theta0)
    if not np.all(np.isfinite(r0)):
        raise SolverError(
            "calibration: the model cannot be integrated at the starting values "
            f"({', '.join(f'{n} = {v:.4g}' for n, v in zip(problem.names, problem.values(theta0)))}); "
            "give other starting values or narrower bounds"
        )
    jac: Any = problem.jacobian if gradient == "exact" else "2-point"
    # forward differences need a step well above the integration's own error (rtol): sqrt(rtol) in the fitted scale
    step = math.sqrt(problem.settings.rtol) / np.maximum(np.abs(theta0), 1.0) if gradient != "exact" else None
    return least_squares(
        problem.residuals, theta0, jac=jac, bounds=(lo, hi), method="trf", x_scale=1.0,
        xtol=1e-10, ftol=1e-10, gtol=1e-10, max_nfev=max_nfev, diff_step=step,
    )


def calibrate(
    system: System,
    records: Sequence[Record],
    fit: Mapping[str, Any] | Sequence[str],
    *,
    inputs: Sequence[str] = (),
    noise: Mapping[str, Any] | None = None,
    initial: str = "estimate",
    starts: int = 1,
    seed: int | None = 0,
    accuracy: float = CALIBRATION_ACCURACY,
    gradient: str = "exact",
    max_evaluations: int = 200,
    progress: Callable[[str], None] | None = None,
) -> Calibration:
    """Fit the parameters ``fit`` of ``system`` to ``records`` (weighted least squares, shared parameters).

    Parameters
    ----------
    system : System
        The model; it is not changed (the result holds a calibrated copy).
    records : sequence of Record
        One per experiment (:func:`hydroservo.io.records.read_record`).
    fit : mapping or sequence
        The parameters and optional bounds (:func:`parse_fit`).
    inputs : sequence of str
        Recorded signals that drive the model (``"command.y"``): their sources are replaced by the records.
    noise : mapping, optional
        Standard deviation of each compared signal (``{"load.x": "0.02 mm"}``). A signal without one is
        weighted by the noise estimated from a first fit's residuals, and the fit is repeated.
    initial : str
        Initial states: ``"estimate"`` (the default: the measured states' initial values are fitted too, from
        the record's first samples, so that one noisy sample does not bias the fit), ``"record"`` (taken from
        the first samples as they are) or ``"model"`` (the model's own initial state); see :func:`prepare`.
    starts : int
        Number of starting points: the system's values, and ``starts - 1`` drawn over the bounds (Latin
        hypercube in the fitted scale); they are run on all cores at once, and the best fit is kept.
    accuracy : float
        Integration accuracy (relative to each signal's range).
    gradient : "exact" or "finite-differences"
        The residuals' Jacobian from the sensitivity equations, or by SciPy's forward differences (for comparison).
    progress : callable, optional
        Called with a line of text at each stage.

    Returns
    -------
    Calibration

    Raises
    ------
    ParameterError, UnitError
        For a bad record, signal, bound or noise, naming it.
    SolverError
        If the model cannot be integrated at the starting values.
    """
    if gradient not in ("exact", "finite-differences"):
        raise ParameterError(f"gradient = {gradient!r}: expected 'exact' or 'finite-differences'")
    if isinstance(starts, bool) or not isinstance(starts, int) or not 1 <= starts <= 1000:
        raise ParameterError(f"starts = {starts!r}: expected a whole number from 1 to 1000")
    if not records:
        raise ParameterError("calibrate: no record; expected at least one")
    say = progress or (lambda _: None)
    clock = time.perf_counter()
    params = parse_fit(system, fit)
    experiments = [prepare(system, r, inputs, initial=initial) for r in records]
    settings = SolverSettings.of(accuracy=accuracy, max_steps=5_000_000)
    sigma, given = _noise(noise, experiments)
    problem = _Problem(experiments, params, sigma, settings)
    say(f"calibrating {len(params)} parameter(s) on {len(experiments)} record(s), {problem.size} samples")
    grad = "exact" if gradient == "exact" else "finite-differences"
    theta_starts = [problem.start()]
    if starts > 1:
        theta_starts += _draws(problem, starts - 1, seed)
    solutions = _run_starts(problem, theta_starts, grad, max_evaluations, say)
    best = min(solutions, key=lambda s: s[1].cost if s[1] is not None else math.inf)
    if best[1] is None:
        raise best[2] if best[2] is not None else SolverError("calibration: no start could be fitted")
    sol = best[1]
    problem.nfev, problem.njev = sum(s[3] for s in solutions), sum(s[4] for s in solutions)
    if not all(given.values()):
        # weights from the residuals, then the fit again from there, until the noise estimates settle
        for _ in range(MAX_REWEIGHTS):
            parts = _split(problem, problem.residuals(sol.x))
            change = 0.0
            for name, (res, _) in parts.items():
                if not given[name] and res.size:
                    factor = math.sqrt(float(np.mean(res**2)))
                    sigma[name] *= factor
                    change = max(change, abs(factor - 1.0))
            if change < REWEIGHT_TOLERANCE:
                break
            say("noise estimated from the residuals: " + ", ".join(_noise_text(experiments, k, sigma[k]) for k in parts if not given[k]))
            sol = _solve(problem, sol.x, grad, max_evaluations)
    theta = sol.x
    J = problem.jacobian(theta)
    problem.njev -= 1  # the statistics' Jacobian is not the optimiser's
    r = problem.residuals(theta)
    problem.nfev -= 1
    dof = max(problem.size - theta.size, 1)
    from scipy import stats

    quantile = Z95 if all(given.values()) else float(stats.t.ppf(0.975, dof))
    cov = np.linalg.pinv(J.T @ J)
    values, stderr, ci = _intervals(params, theta, cov, quantile)
    corr = _correlation(cov)
    names = problem.names
    warns = _identifiability(names, params, J, cov)
    n = len(params)
    if not sol.success or sol.status == 0:
        warns.append(f"the fit did not converge: {sol.message} (after {sol.nfev} evaluations); raise the evaluation budget (max_evaluations, --max-evaluations) or start nearer")
    for p, v in zip(params, values):
        if (math.isfinite(p.lower) and v <= p.lower * (1 + 1e-6) + 1e-300) or (math.isfinite(p.upper) and v >= p.upper * (1 - 1e-6)):
            warns.append(f"{p.name} ended on its bound ({p.shown(v):.4g} {si_unit(p.unit)}): the optimum may lie beyond it")
    parts = _split(problem, r)
    signals = []
    for nm, (res, count) in parts.items():
        factor, shown = _first(experiments, nm).shown(nm)
        rms = float(math.sqrt(np.mean((res * sigma[nm]) ** 2))) if res.size else math.nan
        signals.append(SignalFit(nm, shown, rms * factor, sigma[nm] * factor, given[nm], count))
    for sf in signals:
        if sf.noise_given and sf.samples > 30 and sf.rms > 1.25 * sf.noise:
            warns.append(
                f"{sf.name}: the RMS residual ({sf.rms:.3g} {si_unit(sf.unit)}) is {sf.rms / sf.noise:.2f} times its stated "
                "noise: the model does not explain this signal to its noise (a missing effect, a wrong initial state, "
                "or a noise figure set too low)"
            )
    calibrated = system.copy()
    for p, v in zip(params, values):
        cname, pname = p.name.split(".", 1)
        calibrated[cname].set(**{pname: f"{p.shown(v)!r} {p.unit}" if p.unit else float(v)})
    traces = [problem.simulate(e, theta) for e in range(len(experiments))]
    initial_states = {nm: float(theta[n + k]) * problem._nominal(e, s) for k, ((e, s), nm) in enumerate(zip(problem.extra, names[n:]))}
    summary = [
        {"start": [p.shown(p.value(float(t))) for p, t in zip(params, s[0])], "cost": (s[1].cost if s[1] is not None else None),
         "error": (str(s[2]) if s[2] is not None else None)}
        for s in solutions
    ] if len(solutions) > 1 else []
    if summary:
        costs = [s["cost"] for s in summary if s["cost"] is not None]
        reached = sum(1 for c in costs if c <= best[1].cost * (1 + 1e-4) + 1e-12)
        say(f"{reached} of {len(summary)} starts reached the best fit")
    return Calibration(
        params, values, stderr, ci, corr, names, signals, experiments, traces, calibrated, bool(sol.success),
        str(sol.message), float(sol.cost), problem.nfev, problem.njev, time.perf_counter() - clock, warns,
        initial_states, summary, grad,
    )


def _first(experiments: list[Experiment], name: str) -> Experiment:
    """The first experiment that compares signal ``name`` (whose record's unit it is shown in)."""
    return next(e for e in experiments if name in e.measured)


def _noise_text(experiments: list[Experiment], name: str, sigma: float) -> str:
    factor, shown = _first(experiments, name).shown(name)
    return f"{name} {sigma * factor:.3g} {si_unit(shown)}"


def _split(problem: _Problem, r: np.ndarray) -> dict[str, tuple[np.ndarray, int]]:
    """Weighted residuals by signal over all experiments (and their number)."""
    out: dict[str, list[np.ndarray]] = {}
    k = 0
    for exp in problem.experiments:
        for n in exp.measured:
            size = exp.values[n].size
            out.setdefault(n, []).append(r[k : k + size])
            k += size
    return {n: (np.concatenate(v), int(sum(x.size for x in v))) for n, v in out.items()}


def _draws(problem: _Problem, count: int, seed: int | None) -> list[np.ndarray]:
    from scipy.stats import qmc

    lo, hi = problem.bounds()
    start = problem.start()
    lo = np.where(np.isfinite(lo), lo, start - 1.0)
    hi = np.where(np.isfinite(hi), hi, start + 1.0)
    sample = qmc.LatinHypercube(d=start.size, seed=seed).random(count)
    points = lo + sample * (hi - lo)
    return [np.where(np.arange(start.size) < len(problem.params), pt, start) for pt in points]


def _run_starts(
    problem: _Problem, starts: list[np.ndarray], gradient: str, max_nfev: int, say: Callable[[str], None]
) -> list[tuple[np.ndarray, Any, Exception | None, int, int]]:
    """Fit from every start, on all cores at once (each fit on its own copy of the problem's counters)."""
    import os

    def one(theta0: np.ndarray, stop: Any = None) -> tuple[np.ndarray, Any, Exception | None, int, int]:
        local = _Problem(problem.experiments, problem.params, problem.sigma, problem.settings)
        local.stop = stop
        try:
            sol = _solve(local, theta0, gradient, max_nfev)
        except SolverError as exc:
            return theta0, None, exc, local.nfev, local.njev
        return theta0, sol, None, local.nfev, local.njev

    if len(starts) == 1:
        return [one(starts[0])]
    say(f"{len(starts)} starts, on {min(len(starts), os.cpu_count() or 1)} threads")
    # Ctrl-C: the guard's flag stops each start at its next evaluation, the starts not begun are cancelled
    with interruptible() as flag:
        pool = ThreadPoolExecutor(max_workers=min(len(starts), os.cpu_count() or 1))
        try:
            futures = [pool.submit(one, start, flag) for start in starts]
            return [future.result() for future in futures]
        finally:
            pool.shutdown(wait=True, cancel_futures=True)


# -- prediction on other records ------------------------------------------------
@dataclass
class Prediction:
    """A system run against records it was not fitted to: per record and signal, the RMS error (in the signal's
    unit and in % of its measured range) and, for a position that comes to rest, the final-value error and its
    class of [Efe2014] Table 5.3."""

    rows: list[dict[str, Any]]
    experiments: list[Experiment]
    traces: list[dict[str, np.ndarray]]

    def to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for row in self.rows:
            out.setdefault(row["record"], {})[row["signal"]] = {k: v for k, v in row.items() if k not in ("record", "signal")}
        return out

    def lines(self) -> list[str]:
        from hydroservo.io.text import text_table

        rows = [[r["record"], r["signal"], r["rms"], si_unit(r["unit"]), f"{r['rms_percent']:.2f}",
                 f"{r['final_error_percent']:+.2f} %" if r.get("final_error_percent") is not None else None,
                 r.get("class") or None] for r in self.rows]
        return text_table(rows, ["record", "signal", "RMS error", "unit", "% range", "final error", "class"], digits=4,
                          align=["left", "left", "decimal", "left", "right", "right", "left"])


def _settled(t: np.ndarray, y: np.ndarray) -> bool:
    """Whether ``y`` has come to rest over the last tenth of the record (moves less than 2 % of its range)."""
    span = np.ptp(y)
    tail = y[t >= t[0] + 0.9 * (t[-1] - t[0])]
    return bool(span > 0 and tail.size >= 2 and np.ptp(tail) <= 0.02 * span)


def predict(
    system: System, records: Sequence[Record], *, inputs: Sequence[str] = (), initial: str = "estimate",
    accuracy: float = CALIBRATION_ACCURACY,
) -> Prediction:
    """Run ``system`` against each record (driven by ``inputs``) and measure how well it predicts them.

    ``initial`` as in :func:`calibrate`: with ``"estimate"`` (the default) the measured states' initial values
    are fitted to each record (and nothing else), so that one noisy first sample does not offset the prediction.
    """
    settings = SolverSettings.of(accuracy=accuracy, max_steps=5_000_000)
    experiments = [prepare(system, r, inputs, initial=initial) for r in records]
    problem = _Problem(experiments, [], {n: 1.0 for e in experiments for n in e.measured}, settings)
    theta = problem.start()
    if theta.size:
        sigma, _ = _noise(None, experiments)  # weights: 1 % of each signal's range
        problem.sigma = sigma
        theta = _solve(problem, theta, "exact", 50).x
    rows, traces = [], []
    for e, exp in enumerate(experiments):
        Y = problem.simulate(e, theta)
        traces.append(Y)
        for n in exp.measured:
            model, meas = Y[n][exp.index[n]], exp.values[n]
            t = exp.grid[exp.index[n]]
            err = model - meas
            span = float(np.ptp(meas))
            factor, unit = exp.shown(n)  # in the record's unit
            row: dict[str, Any] = {
                "record": exp.name, "signal": n, "unit": unit, "rms": factor * float(np.sqrt(np.mean(err**2))),
                "rms_percent": float(100 * np.sqrt(np.mean(err**2)) / span) if span > 0 else math.nan,
                "final_error_percent": None, "class": None,
            }
            if same_dimension(coherent_unit(exp.unit(n)), "m") and _settled(t, meas):
                moved = float(np.mean(meas[-3:]) - meas[0])
                if moved != 0:
                    pct = 100 * (float(np.mean(model[-3:])) - float(np.mean(meas[-3:]))) / abs(moved)
                    row["final_error_percent"], row["class"] = pct, classify(pct)
            rows.append(row)
    return Prediction(rows, experiments, traces)


# -- experiment design ------------------------------------------------------------
@dataclass
class ExperimentPlan:
    """What planned experiments would tell about the parameters, before any record exists: the standard error
    and 95 % interval each would get (at the nominal values, from the Fisher information), the correlations,
    and the combinations they could not separate."""

    parameters: list[FitParameter]
    stderr: np.ndarray
    ci95: np.ndarray
    correlation: np.ndarray
    warnings: list[str]
    samples: int

    def to_dict(self) -> dict[str, Any]:
        return {
            "parameters": {
                p.name: {
                    "value": p.shown(p.start), "unit": p.unit,
                    "stderr": abs(p.shown(p.start + s) - p.shown(p.start)),
                    "relative_stderr": float(s / abs(p.start)) if p.start else None,
                    "ci95": [p.shown(ci[0]), p.shown(ci[1])],
                }
                for p, s, ci in zip(self.parameters, self.stderr, self.ci95)
            },
            "correlation": {a.name: {b.name: float(self.correlation[i, j]) for j, b in enumerate(self.parameters)} for i, a in enumerate(self.parameters)},
            "samples": self.samples,
            "warnings": list(self.warnings),
        }

    def lines(self, warnings: bool = True) -> list[str]:
        """The table; ``warnings``: with the identifiability warnings after it."""
        from hydroservo.io.text import text_table

        rows = [[p.name, p.shown(p.start), abs(p.shown(p.start + s) - p.shown(p.start)),
                 f"{100 * s / abs(p.start):.2f} %" if p.start else None, si_unit(p.unit)]
                for p, s in zip(self.parameters, self.stderr)]
        out = text_table(rows, ["parameter", "nominal", "± stderr", "relative", "unit"], digits=[5, 5, 3],
                         align=["left", "decimal", "decimal", "right", "left"])
        return out + ([f"warning: {w}" for w in self.warnings] if warnings else [])


def plan_experiment(
    system: System,
    records: Sequence[Record],
    fit: Mapping[str, Any] | Sequence[str],
    noise: Mapping[str, Any],
    *,
    inputs: Sequence[str] = (),
    initial: str = "estimate",
    accuracy: float = CALIBRATION_ACCURACY,
) -> ExperimentPlan:
    """The Fisher information of planned experiments at the nominal parameters.

    ``records`` are the planned experiments as the virtual rig would log them (their values do not matter, only
    their signals, times and inputs: :func:`hydroservo.identification.rig.virtual_rig` without noise makes them);
    ``noise`` gives each signal's sensor noise, which sets the information. No fit is made.
    """
    params = parse_fit(system, fit)
    experiments = [prepare(system, r, inputs, initial=initial) for r in records]
    sigma, given = _noise(noise, experiments)
    missing = [n for n, g in given.items() if not g]
    if missing:
        raise ParameterError(f"plan: no noise for {', '.join(missing)}; a plan needs every signal's sensor noise")
    problem = _Problem(experiments, params, sigma, SolverSettings.of(accuracy=accuracy, max_steps=5_000_000))
    theta = problem.start()
    J = problem.jacobian(theta)
    cov = np.linalg.pinv(J.T @ J)
    _, stderr, ci = _intervals(params, theta, cov, Z95)
    corr = _correlation(cov)[: len(params), : len(params)]
    return ExperimentPlan(params, stderr, ci, corr, _identifiability(problem.names, params, J, cov), problem.size)
