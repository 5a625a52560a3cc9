"""Parameter studies: designs over named parameters, and a table of every run's parameters and metrics.

A design is a mapping ``"comp.param" -> values``, one value per run, as
:meth:`hydroservo.system.System.batch` takes it:

* :func:`grid`: every combination of given values (a full factorial);
* :func:`sample`: ``n`` points between bounds, uniformly at random, by a
  scrambled Sobol sequence or a Latin hypercube (``scipy.stats.qmc``), on a
  linear or logarithmic scale.

Bounds and values may carry units (``("2500 kg", "3300 kg")``); the design then
keeps them, so the batch converts and checks each value.
:func:`metrics_table` turns a :class:`~hydroservo.system.BatchResult` into a
pandas DataFrame: the varied parameters, each run's status, and the step
metrics of a signal (:mod:`hydroservo.analysis.step`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.analysis.step import METRICS, step_metrics
from hydroservo.errors import ParameterError
from hydroservo.units import si_unit, split_quantity

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["grid", "sample", "metrics_table", "METHODS"]

#: Sampling methods of :func:`sample`.
METHODS = ("random", "sobol", "lhs")

#: Most runs a design may have (a batch of this many is already hours of work for a large model).
MAX_RUNS = 1_000_000


def grid(axes: Mapping[str, Sequence[Any]]) -> dict[str, list[Any]]:
    """Every combination of the values of ``axes`` (name -> values), the first name varying slowest.

    >>> grid({"load.m": [1, 2], "load.B": [10, 20, 30]})["load.B"]
    [10, 20, 30, 10, 20, 30]
    """
    if not axes:
        raise ParameterError("grid: no parameters; give a mapping 'comp.param' -> values")
    columns: dict[str, list[Any]] = {}
    for name, values in axes.items():
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise ParameterError(f"grid: {name} = {values!r}: expected a sequence of values")
        columns[name] = list(values)
        if not columns[name]:
            raise ParameterError(f"grid: {name}: no values")
    size = math.prod(len(v) for v in columns.values())
    if size > MAX_RUNS:
        raise ParameterError(f"grid: {size} combinations; expected at most {MAX_RUNS}")
    combos = list(itertools.product(*columns.values()))
    return {name: [c[i] for c in combos] for i, name in enumerate(columns)}


def _bound(name: str, value: Any) -> tuple[float, str]:
    if isinstance(value, str):
        magnitude, unit = split_quantity(value, what=f"sample: {name}")
        return magnitude, unit
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"sample: {name}: bound {value!r} is not a number or a quantity") from None
    return number, ""


def sample(
    ranges: Mapping[str, tuple[Any, Any]],
    n: int,
    *,
    method: str = "sobol",
    log: Sequence[str] = (),
    seed: int | None = None,
) -> dict[str, list[Any]]:
    """``n`` points with each parameter between its bounds (name -> (low, high)).

    Parameters
    ----------
    ranges : mapping
        Bounds per parameter, numbers (SI) or quantities in one unit (``("2 mm", "5 mm")``).
    n : int
        Number of points (runs). A Sobol sequence is balanced for powers of two.
    method : {"sobol", "lhs", "random"}
        Scrambled Sobol sequence, Latin hypercube, or independent uniform draws.
    log : sequence of str
        Parameters sampled uniformly in their logarithm (bounds must be positive).
    seed : int, optional
        Seed of the generator, for a repeatable design.
    """
    from scipy.stats import qmc  # SciPy's samplers are imported where they are used

    if method not in METHODS:
        raise ParameterError(f"sample: method {method!r}: expected one of {', '.join(METHODS)}")
    if not ranges:
        raise ParameterError("sample: no parameters; give a mapping 'comp.param' -> (low, high)")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 1 <= n <= MAX_RUNS:
        raise ParameterError(f"sample: n = {n!r}: expected a whole number of runs from 1 to {MAX_RUNS}")
    unknown = set(log) - set(ranges)
    if unknown:
        raise ParameterError(f"sample: log = {sorted(unknown)}: not among the sampled parameters")
    lows, highs, units = [], [], []
    for name, pair in ranges.items():
        if isinstance(pair, (str, bytes)) or len(pair) != 2:
            raise ParameterError(f"sample: {name} = {pair!r}: expected (low, high)")
        (lo, u_lo), (hi, u_hi) = _bound(name, pair[0]), _bound(name, pair[1])
        if u_lo != u_hi:
            raise ParameterError(f"sample: {name}: bounds in {u_lo or 'SI'} and {u_hi or 'SI'}; expected one unit")
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ParameterError(f"sample: {name} = {pair!r}: expected finite bounds, low < high")
        if name in log:
            if lo <= 0:
                raise ParameterError(f"sample: {name} = {pair!r}: a logarithmic scale needs positive bounds")
            lo, hi = math.log(lo), math.log(hi)
        lows.append(lo)
        highs.append(hi)
        units.append(u_lo)
    d = len(ranges)
    if method == "random":
        unit_points = np.random.default_rng(seed).random((n, d))
    else:
        engine = qmc.Sobol(d, scramble=True, seed=seed) if method == "sobol" else qmc.LatinHypercube(d, seed=seed)
        unit_points = engine.random(n)
    points = qmc.scale(unit_points, lows, highs)
    design: dict[str, list[Any]] = {}
    for j, name in enumerate(ranges):
        column = np.exp(points[:, j]) if name in log else points[:, j]
        design[name] = [f"{v!r} {units[j]}" if units[j] else float(v) for v in column.tolist()]
    return design


def metrics_table(
    batch: Any,
    signal: str | None = None,
    *,
    unit: str | None = None,
    t_step: float = 0.0,
    y_final: float | None = None,
    reference: float | None = None,
    band: float = 0.02,
) -> pd.DataFrame:
    """A DataFrame of a batch: one row per run; the varied parameters, status and reason, and step metrics.

    Parameters
    ----------
    batch : BatchResult
    signal : str, optional
        The response whose :func:`~hydroservo.analysis.step.step_metrics` are added.
    unit : str, optional
        Unit to show the signal (and its metrics) in; default SI.
    t_step, y_final, reference, band
        As :func:`~hydroservo.analysis.step.step_metrics` (``y_final`` and ``reference`` in ``unit``).
        By default a run's final value is its last sample: simulate until the
        response has settled, or give ``y_final``.

    Columns are named ``"name [unit]"``; ``status`` is ``ok``, ``implausible``
    (a physical bound crossed: ``reason`` says which) or ``failed``.
    """
    import pandas as pd

    n = len(batch)
    data: dict[str, Any] = {}
    for name in batch.varied:
        data[f"{name} [{si_unit(batch.param_units.get(name, ''))}]"] = batch.params[name]
    status = ["ok"] * n
    reason = [""] * n
    for k, found in batch.warnings.items():
        status[k], reason[k] = "implausible", "; ".join(str(w) for w in found)
    for k, why in batch.failed.items():
        status[k], reason[k] = "failed", why
    data["status"], data["reason"] = status, reason
    if signal is not None:
        values = batch.get(signal, unit) if unit else batch[signal]
        shown = unit or si_unit(batch.units.get(signal, ""))
        rows = [
            step_metrics(batch.t, values[k], t_step=t_step, y_final=y_final, reference=reference, band=band)
            if k not in batch.failed
            else dict.fromkeys(METRICS, float("nan"))
            for k in range(n)
        ]
        for key, kind in METRICS.items():
            data[f"{signal} {key} [{shown if kind == 'signal' else kind}]"] = [r[key] for r in rows]
    return pd.DataFrame(data, index=pd.RangeIndex(n, name="run"))
