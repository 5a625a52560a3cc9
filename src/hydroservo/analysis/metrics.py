r"""Scalar metrics of a run: what a study measures of each response.

A metric is written ``KIND(SIGNAL[, T0[, T1]])``, times with units or in
seconds:

================================  ==============================================================
``final(x)``                      the last sample
``at(x, T)``                      the value at time T (interpolated)
``peak(x[, T0, T1])``             the sample furthest from zero (signed) in the window
``max``, ``min``                  the largest, smallest sample in the window
``mean(x, T0, T1)``               the time average over the window: a steady level
``rise_time(x[, T0[, T1]])``      10-90 % of the change from T0 (the step) to T1 (the end)
``settling_time(x[, T0[, T1]])``  to within 2 % of the final change, from T0
``overshoot(x[, T0[, T1]])``      beyond the final value, in % of the change
``peak_time(x[, T0[, T1]])``      when the response is furthest in the step's direction, from T0
================================  ==============================================================

The step metrics are those of :func:`hydroservo.analysis.step.step_metrics`.
A user's own metric is any function ``f(t, signals) -> float`` given to
:class:`Metric` with a name (``signals`` maps names to arrays, SI).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hydroservo.analysis.step import step_metrics
from hydroservo.errors import ParameterError, did_you_mean
from hydroservo.units import si_unit, to_si

__all__ = ["KINDS", "Metric", "parse_metric", "metrics_of", "describe", "default_metrics"]

#: Kinds of metric -> the unit of the result ("signal": the signal's own).
KINDS = {
    "final": "signal",
    "at": "signal",
    "peak": "signal",
    "max": "signal",
    "min": "signal",
    "mean": "signal",
    "rise_time": "s",
    "settling_time": "s",
    "overshoot": "%",
    "peak_time": "s",
}
_STEP = ("rise_time", "settling_time", "overshoot", "peak_time")
_FORM = re.compile(r"^\s*([a-z_]+)\s*\(\s*([^,()]+?)\s*(?:,\s*([^,()]+?)\s*)?(?:,\s*([^,()]+?)\s*)?\)\s*$")


@dataclass
class Metric:
    """One scalar of a run: ``kind`` of ``signal`` over ``[t0, t1]`` (SI), or a function of its own."""

    name: str
    kind: str = "custom"
    signal: str = ""
    t0: float | None = None
    t1: float | None = None
    unit: str = ""
    function: Callable[[np.ndarray, Mapping[str, np.ndarray]], float] | None = field(default=None, repr=False)

    @property
    def signals(self) -> list[str]:
        return [self.signal] if self.signal else []

    def __call__(self, t: np.ndarray, signals: Mapping[str, np.ndarray]) -> float:
        if self.function is not None:
            return float(self.function(t, signals))
        y = np.asarray(signals[self.signal], dtype=float)
        if not np.all(np.isfinite(y)):
            return float("nan")
        if self.kind == "final":
            return float(y[-1])
        if self.kind == "at":
            return float(np.interp(float(self.t0 if self.t0 is not None else t[-1]), t, y))
        if self.kind in _STEP:
            t0 = 0.0 if self.t0 is None else self.t0
            keep = t <= (self.t1 if self.t1 is not None else t[-1])
            return float(step_metrics(t[keep], y[keep], t_step=t0)[self.kind])
        lo = t[0] if self.t0 is None else self.t0
        hi = t[-1] if self.t1 is None else self.t1
        window = (t >= lo) & (t <= hi)
        if not window.any():
            return float("nan")
        tw, yw = t[window], y[window]
        if self.kind == "mean":
            return float(np.trapezoid(yw, tw) / (tw[-1] - tw[0])) if tw.size > 1 else float(yw[0])
        if self.kind == "max":
            return float(yw.max())
        if self.kind == "min":
            return float(yw.min())
        return float(yw[int(np.argmax(np.abs(yw)))])  # peak


def parse_metric(text: str, units: Mapping[str, str] | None = None, t_end: float | None = None) -> Metric:
    """A metric from its text, ``"mean(cyl.pA, 0.4 s, 0.6 s)"``.

    ``units`` (signal -> unit) checks the signal exists and gives the metric's
    unit; ``t_end`` checks the times lie within the run.
    """
    m = _FORM.match(text)
    if m is None:
        raise ParameterError(
            f"metric {text!r}: expected KIND(SIGNAL[, T0[, T1]]), e.g. final(x_mm) or mean(cyl.pA, 0.4 s, 0.6 s); "
            f"kinds: {', '.join(KINDS)}"
        )
    kind, signal, a, b = m.groups()
    if kind not in KINDS:
        raise ParameterError(f"metric {text!r}: unknown kind {kind!r}{did_you_mean(kind, KINDS)}; expected one of {', '.join(KINDS)}")
    if units is not None and signal not in units:
        raise ParameterError(f"metric {text!r}: {signal!r} is not a state, output or alias of the model{did_you_mean(signal, units)}")
    times = [None if v is None else to_si(v, "s", what=f"metric {text!r}") for v in (a, b)]
    for v in times:
        if v is not None and (not math.isfinite(v) or v < 0 or (t_end is not None and v > t_end)):
            raise ParameterError(f"metric {text!r}: time {v:g} s: expected within the run, 0 to {t_end:g} s")
    if kind == "at" and times[0] is None:
        raise ParameterError(f"metric {text!r}: at(SIGNAL, T) needs the time T")
    if kind == "mean" and (times[0] is None or times[1] is None):
        raise ParameterError(f"metric {text!r}: mean(SIGNAL, T0, T1) needs the window T0, T1")
    if times[0] is not None and times[1] is not None and times[1] <= times[0]:
        raise ParameterError(f"metric {text!r}: expected T0 < T1")
    unit = KINDS[kind]
    if unit == "signal":
        unit = si_unit((units or {}).get(signal, ""))
    return Metric(text.replace(" ", ""), kind, signal, times[0], times[1], unit)


def metrics_of(
    metrics: Sequence[Metric], t: np.ndarray, signals: Mapping[str, np.ndarray]
) -> np.ndarray:
    """Every metric of every run: ``signals`` maps names to arrays (runs x times); returns (runs x metrics)."""
    first = next(iter(signals.values())) if signals else np.zeros((0, t.size))
    n = np.asarray(first).shape[0]
    out = np.full((n, len(metrics)), np.nan)
    for k in range(n):
        one = {name: np.asarray(v)[k] for name, v in signals.items()}
        for j, metric in enumerate(metrics):
            try:
                out[k, j] = metric(t, one)
            except (ValueError, ZeroDivisionError, FloatingPointError):
                out[k, j] = np.nan
    return out


def describe(metric: Metric) -> str:
    """The metric with its unit, for tables: ``final(x_mm) [mm]``."""
    return f"{metric.name} [{metric.unit or '-'}]"


def default_metrics(system: Any, t_end: float) -> list[Metric]:
    """The system's declared metrics (model file ``[model] metrics``), else the final value and peak of
    the first four signals of its plot panels that are not commands (a source's output) and the step metrics of its response (a load's position if one is
    plotted, else the first signal that is not a command), from the time of the command's step if it has one."""
    model = system.build()
    units = {**model.units}
    if system.metrics:
        return [parse_metric(text, units, t_end) for text in system.metrics]
    plotted = [s for panel in system.default_panels() for s in panel]
    # what the model does, not what it is told: a command (a source's output) is known before the run
    names = ([s for s in plotted if not _is_command(system, s)] or plotted)[:4]
    out = [parse_metric(f"final({n})", units) for n in names]
    out += [parse_metric(f"peak({n})", units) for n in names]
    # the step metrics of the response: a load's position if one is plotted, else the first signal that is not a
    # command (a source's output has no rise time of its own)
    loads = [n for n in plotted if _is_load_position(system, n)]
    responses = loads or [n for n in names if not _is_command(system, n)] or names
    if responses:
        # from the command's step, where the model has one (position-servo's comes at 1 s)
        steps = [c.values["t_step"] for c in system.components.values() if type(c).__name__ == "Step"]
        at = f", {steps[0]:g} s" if steps and 0.0 < steps[0] < t_end else ""
        out += [parse_metric(f"{k}({responses[0]}{at})", units, t_end)
                for k in ("rise_time", "settling_time", "overshoot")]
    return out


def _is_load_position(system: Any, name: str) -> bool:
    """Whether signal ``name`` is a mass's position (``load.x``), or an alias of it alone (``y = -load.x``)."""
    alias = system.aliases.get(name)
    refs = re.findall(r"[A-Za-z_]\w*\.\w+", alias.expr) if alias is not None else [name]
    return len(refs) == 1 and refs[0].endswith(".x") and type(system.components.get(refs[0][:-2])).__name__ == "Mass"


def _is_command(system: Any, name: str, depth: int = 0) -> bool:
    """Whether signal ``name`` is a command: the output of a source (a block without states or inputs: a step,
    a sine, a table), or an alias of such outputs alone."""
    alias = system.aliases.get(name)
    if alias is not None:
        refs = re.findall(r"[A-Za-z_]\w*\.\w+", alias.expr)
        return bool(refs) and depth < 10 and all(_is_command(system, r, depth + 1) for r in refs)
    component = system.components.get(name.partition(".")[0])
    return component is not None and not component.STATES and not component.INPUTS

