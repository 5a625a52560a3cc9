r"""Sensitivity studies of any system: one parameter at a time, and global (Sobol, Morris).

* :func:`one_at_a_time` runs the system at each level of one factor, the others
  at their values: the response families of [Efe2014] Figs. 5.14-5.19. A
  factor is a parameter (numbers or quantities) or an option, a discrete
  choice such as a cylinder's ``bulk_modulus`` law (Fig. 5.19).
* :func:`sobol` estimates first-order and total Sobol indices
  ([Saltelli2010] estimators, as SALib implements them) with bootstrap
  confidence intervals; :func:`morris` screens with elementary effects
  ([Campolongo2007] :math:`\mu^*`, and :math:`\sigma`). SALib draws the points
  and analyses the metrics; hydroservo runs the system at every point
  (:func:`hydroservo.analysis.campaign.run_design`: chunks on local threads or
  a Dask cluster, written as they arrive, resumable).

Each run is reduced to scalar metrics (:mod:`hydroservo.analysis.metrics`):
the model's own (``[model] metrics``), or any the user names or writes.
A run that fails is kept apart with its reason; the indices of a metric with
failed runs are not estimated (NaN), since the estimators need every point.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.analysis.campaign import Runs, run_design
from hydroservo.analysis.metrics import Metric, default_metrics, describe, metrics_of, parse_metric
from hydroservo.errors import ParameterError, did_you_mean
from hydroservo.units import split_quantity

if TYPE_CHECKING:
    import pandas as pd

    from hydroservo.system.system import System

__all__ = ["OneAtATime", "GlobalStudy", "one_at_a_time", "sobol", "morris", "bounds", "custom_metric", "METHODS"]

#: Global methods.
METHODS = ("sobol", "morris")


def _metrics(system: System, metrics: Sequence[str | Metric] | None, t_end: float) -> list[Metric]:
    if not metrics:
        return default_metrics(system, t_end)
    units = system.build().units
    return [m if isinstance(m, Metric) else parse_metric(m, units, t_end) for m in metrics]


# -- one at a time --------------------------------------------------------------------------------------
@dataclass
class OneAtATime:
    """Responses and metrics of each level of each factor, the other factors at their values.

    ``levels[factor]`` are the levels as given (text with units, or option
    names); ``responses[factor][k]`` maps each kept signal to its response
    at level k (SI, on ``t``); ``table`` has one row per (factor, level).
    """

    model: str
    t: np.ndarray
    levels: dict[str, list[str]]
    responses: dict[str, list[dict[str, np.ndarray]]]
    table: pd.DataFrame
    metrics: list[Metric]
    units: dict[str, str]
    failed: dict[tuple[str, int], str] = field(default_factory=dict)

    def _repr_html_(self) -> str:
        """In a notebook: the metrics of each level, the response family of the first factor."""
        from hydroservo.io.notebook import study_html

        return study_html(self)

    def plot(self, factor: str, signals: Sequence[str] | None = None, *, units: Mapping[str, str] | None = None,
             title: str = "", file: Any = None) -> Any:
        """The response family of ``factor``: a panel per signal, a line per level ([Efe2014] Figs. 5.14-5.19)."""
        from hydroservo.plotting.sensitivity import plot_one_at_a_time

        return plot_one_at_a_time(self, factor, signals, units=units, title=title, file=file)


def _levels(system: System, name: str, values: Sequence[Any]) -> tuple[str, list[Any], bool]:
    """(key, levels, is_option) of a factor."""
    cname, _, pname = name.partition(".")
    if cname not in system.components:
        raise ParameterError(f"factor {name!r}: no component {cname!r}{did_you_mean(cname, system.components)}; "
                             f"components: {', '.join(system.components)}")
    comp = system.components[cname]
    if pname in comp.OPTIONS:
        choices = comp.OPTIONS[pname].choices
        for v in values:
            if v not in choices:
                raise ParameterError(f"factor {name!r}: option value {v!r}; expected one of {', '.join(choices)}")
        return f"{cname}.{pname}", list(values), True
    return system.parameter_key(name), list(values), False


def one_at_a_time(
    system: System,
    factors: Mapping[str, Sequence[Any]],
    *,
    metrics: Sequence[str | Metric] | None = None,
    signals: Sequence[str] | None = None,
    t_end: float | None = None,
    n_points: int = 301,
    rtol: float = 1e-6,
) -> OneAtATime:
    """Run ``system`` at each level of each factor (name -> levels), the others at their values."""
    import pandas as pd

    model = system.build()
    t_end = system.t_end if t_end is None else float(t_end)
    chosen = _metrics(system, metrics, t_end)
    keep = list(signals) if signals else [s for panel in system.default_panels() for s in panel]
    for s in keep:
        if s not in model.units:
            raise ParameterError(f"signal {s!r}: not a state, output or alias of {system.name!r}{did_you_mean(s, model.units)}")
    needed = sorted({*keep, *(s for m in chosen for s in m.signals)})
    if not factors:
        raise ParameterError("one at a time: no factors; give a mapping 'comp.param' -> levels")
    levels: dict[str, list[str]] = {}
    responses: dict[str, list[dict[str, np.ndarray]]] = {}
    rows: list[dict[str, Any]] = []
    failed: dict[tuple[str, int], str] = {}
    t = np.linspace(0.0, t_end, n_points)
    for name, values in factors.items():
        if isinstance(values, (str, bytes)) or not values:
            raise ParameterError(f"factor {name!r}: expected a list of levels")
        key, lv, is_option = _levels(system, name, values)
        runs: list[dict[str, np.ndarray] | None] = []
        if is_option:
            for v in lv:
                variant = system.copy()
                variant.set(key, v)
                try:
                    res = variant.simulate(t_end, n_points=n_points, rtol=rtol)
                    runs.append({s: np.asarray(res[s]) for s in needed})
                except Exception as exc:  # noqa: BLE001 - a failed level is reported, the others go ahead
                    failed[(key, len(runs))] = str(exc)
                    runs.append(None)
        else:
            batch = system.batch({key: lv}, t_end, n_points=n_points, rtol=rtol)
            arrays = {s: batch[s] for s in needed}
            for k in range(len(lv)):
                if k in batch.failed:
                    failed[(key, k)] = batch.failed[k]
                    runs.append(None)
                else:
                    runs.append({s: arrays[s][k] for s in needed})
        levels[key] = [str(v) for v in lv]
        responses[key] = [r if r is not None else {s: np.full(t.size, np.nan) for s in needed} for r in runs]
        for k, r in enumerate(responses[key]):
            values_k = metrics_of(chosen, t, {s: r[s][None, :] for s in needed})[0]
            rows.append({"factor": key, "level": levels[key][k], **{describe(m): values_k[j] for j, m in enumerate(chosen)},
                         "status": "failed" if (key, k) in failed else "ok", "reason": failed.get((key, k), "")})
    table = pd.DataFrame(rows)
    return OneAtATime(system.name, t, levels, responses, table, chosen, {s: model.units[s] for s in needed}, failed)


# -- global ---------------------------------------------------------------------------------------------
def bounds(ranges: Mapping[str, tuple[Any, Any]]) -> tuple[list[str], list[tuple[float, float]], list[str]]:
    """Names, (low, high) magnitudes and units of ranges given as numbers (SI) or quantities in one unit."""
    names, pairs, units = [], [], []
    for name, pair in ranges.items():
        if isinstance(pair, (str, bytes)) or len(pair) != 2:
            raise ParameterError(f"range of {name!r}: {pair!r}: expected (low, high)")
        parsed = []
        for v in pair:
            if isinstance(v, str):
                parsed.append(split_quantity(v, what=f"range of {name!r}"))
            else:
                try:
                    parsed.append((float(v), ""))
                except (TypeError, ValueError):
                    raise ParameterError(f"range of {name!r}: {v!r} is not a number or a quantity") from None
        (lo, u_lo), (hi, u_hi) = parsed
        if u_lo != u_hi:
            raise ParameterError(f"range of {name!r}: bounds in {u_lo or 'SI'} and {u_hi or 'SI'}; expected one unit")
        if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
            raise ParameterError(f"range of {name!r}: {pair!r}: expected finite bounds, low < high")
        names.append(name)
        pairs.append((lo, hi))
        units.append(u_lo)
    if not names:
        raise ParameterError("global study: no parameters; give a mapping 'comp.param' -> (low, high)")
    return names, pairs, units


@dataclass
class GlobalStudy:
    """Indices of a global study, per metric and parameter, with the runs behind them.

    ``indices`` has one row per (metric, parameter): for Sobol ``S1``,
    ``S1_conf``, ``ST``, ``ST_conf`` (half-widths of the ``conf_level``
    bootstrap intervals); for Morris ``mu_star``, ``mu_star_conf``, ``sigma``,
    ``mu`` (in the metric's unit). ``notes`` say which metrics could not be
    analysed and why.
    """

    method: str
    parameters: list[str]
    units: list[str]
    bounds: list[tuple[float, float]]
    runs: Runs
    indices: pd.DataFrame
    conf_level: float
    notes: list[str] = field(default_factory=list)

    def to_dict(self) -> dict[str, Any]:
        rows = self.indices.to_dict(orient="records")
        return {
            "method": self.method,
            "parameters": [
                {"name": n, "low": lo, "high": hi, "unit": u} for n, (lo, hi), u in zip(self.parameters, self.bounds, self.units)
            ],
            "conf_level": self.conf_level,
            "runs": self.runs.stats,
            "indices": [{k: (None if isinstance(v, float) and not np.isfinite(v) else v) for k, v in r.items()} for r in rows],
            "notes": self.notes,
        }

    def _repr_html_(self) -> str:
        """In a notebook: the indices with their confidence intervals, and their bar chart."""
        from hydroservo.io.notebook import study_html

        return study_html(self)

    def plot(self, *, title: str = "", file: Any = None) -> Any:
        """Bar chart of the indices with their confidence intervals, a panel per metric."""
        from hydroservo.plotting.sensitivity import plot_indices

        return plot_indices(self, title=title, file=file)


def _analyse(
    runs: Runs, names: list[str], keys: tuple[str, ...], estimate: Callable[[np.ndarray], dict[str, Any]]
) -> tuple[pd.DataFrame, list[str]]:
    """A row per (metric, parameter) of the indices ``keys`` that ``estimate`` gives for each metric's values;
    a metric with a failed run gets NaN and a note (the estimators need every point)."""
    import pandas as pd

    Y = runs.values()
    rows, notes = [], []
    for j, m in enumerate(runs.metrics):
        y = Y[:, j]
        bad = int((~np.isfinite(y)).sum())
        res: dict[str, Any] = {}
        if bad:
            notes.append(f"{m.name}: {bad} of {y.size} runs without a value (failed); its indices are not estimated")
        else:
            res = estimate(y)
            if np.ptp(y) == 0:
                notes.append(f"{m.name}: the same in every run; no parameter moves it")
        for i, name in enumerate(names):
            rows.append({"metric": describe(m), "parameter": name,
                         **{k: float(res[k][i]) if res else float("nan") for k in keys}})
    return pd.DataFrame(rows), notes


def _seed(seed: int | None) -> int | None:
    """SALib's seed for hydroservo's: SALib takes a seed of 0 for none (``if seed:``), so 0 becomes 1."""
    return None if seed is None else int(seed) + 1


def _problem(names: list[str], pairs: list[tuple[float, float]]) -> dict[str, Any]:
    return {"num_vars": len(names), "names": list(names), "bounds": [list(p) for p in pairs]}


def _design(names: list[str], units: list[str], X: np.ndarray) -> dict[str, list[Any]]:
    return {n: [f"{v!r} {u}" if u else float(v) for v in X[:, j].tolist()] for j, (n, u) in enumerate(zip(names, units))}


def _run(system: System, names: list[str], units: list[str], X: np.ndarray, metrics: Sequence[str | Metric] | None,
         t_end: float | None, kwargs: dict[str, Any]) -> Runs:
    t = system.t_end if t_end is None else float(t_end)
    return run_design(system, _design(names, units, X), _metrics(system, metrics, t), t_end=t, **kwargs)


def sobol(
    system: System,
    ranges: Mapping[str, tuple[Any, Any]],
    n: int,
    *,
    metrics: Sequence[str | Metric] | None = None,
    t_end: float | None = None,
    conf_level: float = 0.95,
    seed: int | None = 0,
    **run: Any,
) -> GlobalStudy:
    """First-order and total Sobol indices of every metric for parameters in ``ranges`` (uniform).

    ``n`` is the base sample (a power of two); the study runs ``n (d + 2)``
    points for ``d`` parameters (Saltelli's scheme, SALib ``sample.sobol``).
    ``run`` goes to :func:`~hydroservo.analysis.campaign.run_design`
    (``threads``, ``chunk``, ``scheduler``, ``store``, ``progress``, ``n_points``).
    """
    from SALib.analyze import sobol as analyze
    from SALib.sample import sobol as sample

    names, pairs, units = bounds(ranges)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2 or (n & (n - 1)):
        raise ParameterError(f"sobol: n = {n!r}: expected a power of two (the base sample), e.g. 256")
    problem = _problem(names, pairs)
    X = sample.sample(problem, int(n), calc_second_order=False, seed=_seed(seed))
    runs = _run(system, names, units, X, metrics, t_end, run)

    def estimate(y: np.ndarray) -> dict[str, Any]:
        if np.ptp(y) == 0:  # the same in every run: SALib would divide by its zero variance
            return {k: np.zeros(len(names)) for k in ("S1", "S1_conf", "ST", "ST_conf")}
        result: dict[str, Any] = analyze.analyze(problem, y, calc_second_order=False, conf_level=conf_level, seed=_seed(seed))
        return result

    table, notes = _analyse(runs, names, ("S1", "S1_conf", "ST", "ST_conf"), estimate)
    return GlobalStudy("sobol", names, units, pairs, runs, table, conf_level, notes)


def morris(
    system: System,
    ranges: Mapping[str, tuple[Any, Any]],
    trajectories: int,
    *,
    levels: int = 4,
    metrics: Sequence[str | Metric] | None = None,
    t_end: float | None = None,
    conf_level: float = 0.95,
    seed: int | None = 0,
    **run: Any,
) -> GlobalStudy:
    """Morris screening: :math:`\\mu^*` (with its bootstrap interval), :math:`\\sigma` and :math:`\\mu` of the
    elementary effects of every parameter on every metric; ``trajectories (d + 1)`` runs."""
    from SALib.analyze import morris as analyze
    from SALib.sample import morris as sample

    names, pairs, units = bounds(ranges)
    if isinstance(trajectories, bool) or not isinstance(trajectories, (int, np.integer)) or trajectories < 2:
        raise ParameterError(f"morris: trajectories = {trajectories!r}: expected at least 2")
    if levels < 2 or levels % 2:
        raise ParameterError(f"morris: levels = {levels!r}: expected an even number of grid levels, at least 2")
    problem = _problem(names, pairs)
    X = sample.sample(problem, int(trajectories), num_levels=levels, seed=_seed(seed))
    runs = _run(system, names, units, X, metrics, t_end, run)

    def estimate(y: np.ndarray) -> dict[str, Any]:
        result: dict[str, Any] = analyze.analyze(problem, X, y, conf_level=conf_level, num_levels=levels, seed=_seed(seed))
        return result

    table, notes = _analyse(runs, names, ("mu_star", "mu_star_conf", "sigma", "mu"), estimate)
    return GlobalStudy("morris", names, units, pairs, runs, table, conf_level, notes)


def custom_metric(name: str, function: Callable[[np.ndarray, Mapping[str, np.ndarray]], float], unit: str = "") -> Metric:
    """A metric of the user's own: ``function(t, signals) -> float`` (``signals``: name -> array, SI)."""
    return Metric(name, "custom", "", None, None, unit, function)

