"""A system and a result as a notebook shows them (``_repr_html_``), and the tables they share with the reports'
pages (:mod:`hydroservo.workflows.pages`): a system's parameters, a run's signals.

In Jupyter a :class:`~hydroservo.system.System` shows its name, what it is and where it comes from, its notes,
its circuit and (folded) its parameters; a :class:`~hydroservo.system.result.Result` its run, its warnings, its
main signals in the model's units, a plot of them and (folded) every signal. Both are HTML without scripts, so
they also show where a notebook is not trusted and in exported notebooks.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from hydroservo.io.html import Table
    from hydroservo.system.result import BatchResult, Result
    from hydroservo.system.system import System

__all__ = ["parameter_table", "signal_table", "dataframe_table", "system_html", "result_html", "batch_html", "study_html",
           "departures", "scoped_notes"]


def _value(value: float, unit: str) -> str:
    from hydroservo.units import si_unit

    shown = f"{value:.6g}"
    unit = si_unit(unit)
    return f"{shown} {unit}".strip() if unit not in ("", "-") else shown


def parameter_table(system: System) -> Table:
    """Every parameter and option of every component: its value as given (the user's unit) or in SI, what it
    is, and where the value comes from (the model, a parameter set, the circuit's fluid, the default)."""
    from hydroservo.components.base import FromSet
    from hydroservo.io.html import Table

    rows: list[list[Any]] = []
    fluid = system.fluid
    for cname, comp in system.components.items():
        kind = type(comp).__name__
        for key, option in comp.OPTIONS.items():
            value = comp.option_values[key]
            rows.append([cname, kind, key, value, option.description, "set" if value != option.default else "default"])
        for key, spec in comp.PARAMETERS.items():
            shown = comp.given.get(key) or _value(comp.values[key], spec.unit)
            if key in comp.explicit:
                source = "set"
            elif spec.fluid and fluid is not None:
                source = f"fluid: {fluid.describe()}"
            elif isinstance(spec.default, FromSet):
                source = f"parameter set {spec.default.set_name}"
            else:
                source = "default"
            rows.append([cname, kind, key, shown, spec.description, source])
    return Table(["component", "type", "parameter", "value", "meaning", "from"], rows,
                 caption="Values as given, in their units; SI where no unit was given.")


def signal_table(result: Result, units: Mapping[str, str] | None = None, names: Sequence[str] | None = None) -> Table:
    """Final, minimum and maximum of each signal (``names``, default all), in its plot unit where ``units`` has one."""
    import numpy as np

    from hydroservo.io.html import Table
    from hydroservo.units import si_unit

    units = units or {}
    rows = []
    for name in names if names is not None else list(result.data):
        unit = units.get(name) or result.units.get(name, "")
        try:
            values = np.asarray(result.get(name, unit), dtype=float)
        except Exception:  # noqa: BLE001 - a plot unit the model file got wrong is refused elsewhere; show SI
            unit = result.units.get(name, "")
            values = np.asarray(result[name], dtype=float)
        description = result.descriptions.get(name, "")
        rows.append([name, si_unit(unit), float(values[-1]), float(np.min(values)), float(np.max(values)), description])
    return Table(["signal", "unit", "final", "min", "max", "meaning"], rows)


def departures(system: System) -> list[str]:
    """What ``system`` changes of the model its file describes (read again from :attr:`System.source`): the
    parameters and options whose values differ, a component added or removed, other initial values, another
    duration, by name. A model's notes (``[model] notes``) were measured on the model as its file gives it: they
    hold only for a run with none of these (:func:`scoped_notes`). Empty for a system built in Python (no file)."""
    import math

    from hydroservo.errors import HydroservoError
    from hydroservo.io.model_file import load_model

    if not system.source or not system.notes:
        return []
    try:
        base = load_model(system.source.removeprefix("built-in:"))
    except HydroservoError:
        return ["the model file, which no longer loads"]
    if list(base.components) != list(system.components):
        return ["the circuit's components"]
    found = []
    before = base.parameter_values()
    for key, value in system.parameter_values().items():
        old = before.get(key)
        if old is None or not (old == value or (math.isnan(old) and math.isnan(value))):
            found.append(key)
    for cname, comp in system.components.items():
        found += [f"{cname}.{k}" for k, v in comp.option_values.items() if base.components[cname].option_values.get(k) != v]
    if base.initial != system.initial:
        found.append("the initial values")
    if base.t_end != system.t_end:
        found.append("t_end")
    return found


def scoped_notes(system: System, changes: Sequence[str] = (), what: str = "run") -> list[str]:
    """The model's notes as they are true of a run: as they are where the run is the model's default run (the
    model as its file gives it, its duration, the default solver and output times), else each said to be
    measured on the default run, with what this run (``what``: or this system) ``changes`` (:func:`departures`
    and the run's own settings), so that no figure of a note is shown as this run's."""
    if not changes:
        return list(system.notes)
    shown = ", ".join(changes[:6]) + (f" and {len(changes) - 6} more" if len(changes) > 6 else "")
    return [f"[measured on the model's default run; this {what} changes {shown}, so it may not hold here] {note}"
            for note in system.notes]


def system_html(system: System) -> str:
    """The notebook's display of ``system``: name and description, source, notes, circuit, parameters (folded)."""
    from hydroservo.io.html import Drawing, Notice, Text, fragment

    head = f"System {system.name!r}" + (f": {system.description}" if system.description else "")
    about = [f"{len(system.components)} components"]
    if system.meta.get("citation"):
        about.append(f"source {system.meta['citation']} ({system.meta.get('status', '')})")
    if system.meta.get("validation"):
        about.append(f"validation: {system.meta['validation']}")
    items: list[Any] = [Text("; ".join(about) + ".")]
    items += [Notice(note, "info") for note in scoped_notes(system, departures(system), "system")]
    try:
        items.append(Drawing(system.diagram().svg))
    except Exception as exc:  # noqa: BLE001 - a circuit that cannot be drawn still shows the rest
        items.append(Notice(f"circuit not drawn: {exc}"))
    return fragment(head, items, [("Parameters", [parameter_table(system)])])


def result_html(result: Result) -> str:
    """The notebook's display of ``result``: the run, its warnings, its main signals in the model's units with
    a plot of them, and (folded) every signal."""
    import io

    from hydroservo.io.html import Notice, Picture, fragment

    shown = result.shown_units()
    main = result.main_signals()
    items: list[Any] = [Notice(str(w)) for w in result.warnings]
    items.append(signal_table(result, shown, main))
    if main:
        buffer = io.BytesIO()
        result.plot(file=buffer)
        items.append(Picture(buffer.getvalue(), "the main signals, in the model's units (Result.plot)"))
    return fragment(result_title(result), items, [(f"All {len(shown)} signals", [signal_table(result, shown)])])


def result_title(result: Result) -> str:
    """One line: the model, the time span, the number of signals and how the run was integrated."""
    stats = result.stats
    run = f"{stats['method']}, {stats['nsteps']} steps" if "method" in stats and "nsteps" in stats else ""
    return (f"Result of {result.model!r}: {result.t[0]:g} to {result.t[-1]:g} s, {result.t.size} times, "
            f"{len(result.names)} signals" + (f" ({run})" if run else "")
            + (f"; {len(result.warnings)} warning(s)" if result.warnings else ""))


def batch_html(batch: BatchResult) -> str:
    """The notebook's display of a batch: how many runs succeeded, each run's varied values (in the units the
    parameters are declared in) and status, and the family of curves of the main signal the runs differ in most."""
    import io

    from hydroservo.io.html import Notice, Picture, Table, fragment
    from hydroservo.units import si_unit

    items: list[Any] = [Notice(batch.summary(), "warning" if batch.failed else "info")]
    varied = list(batch.varied)
    rows = []
    for k in range(len(batch)):
        status = f"failed: {batch.failed[k]}" if k in batch.failed else (
            f"implausible: {batch.warnings[k][0]}" if k in batch.warnings else "ok")
        rows.append([k, *(float(batch.params[v][k]) for v in varied), status])
    columns = ["run", *(f"{v} [{si_unit(batch.param_units.get(v, ''))}]" for v in varied), "status"]
    table = Table(columns, rows[:200], caption=f"{len(rows)} runs" + (", the first 200 shown" if len(rows) > 200 else ""))
    signal = _most_varied(batch)
    if signal is not None and len(batch.failed) < len(batch):
        buffer = io.BytesIO()
        batch.plot(signal, file=buffer)
        items.append(Picture(buffer.getvalue(), f"{signal} in every run that did not fail (BatchResult.plot)"))
    return fragment(repr(batch).strip("<>"), items, [("Runs", [table])])


def _most_varied(batch: BatchResult) -> str | None:
    """Of the model's main signals, the one whose runs differ most, relative to its range (None if none do)."""
    import numpy as np

    best, spread = None, 0.0
    ok = batch.ok
    for name in batch.main_signals():
        values = np.asarray(batch[name], dtype=float)[ok]
        finite = values[np.isfinite(values)]
        if finite.size == 0:
            continue
        scale = float(np.ptp(finite)) or 1.0
        differ = float(np.nanmax(np.nanmax(values, axis=0) - np.nanmin(values, axis=0))) / scale
        if differ > spread:
            best, spread = name, differ
    return best


def dataframe_table(frame: Any, caption: str = "", index: bool = False) -> Table:
    """A pandas DataFrame as a table (its index as the first column when ``index``)."""
    from hydroservo.io.html import Table

    columns = ([str(frame.index.name or "")] if index else []) + [str(c) for c in frame.columns]
    rows = [([str(i)] if index else []) + [_plain(v) for v in row] for i, row in zip(frame.index, frame.itertuples(index=False))]
    return Table(columns, rows, caption)


def _plain(value: Any) -> Any:
    """A cell of a frame: numbers as floats, the rest as text."""
    if isinstance(value, bool):
        return value
    try:
        return float(value)
    except (TypeError, ValueError):
        return None if value is None else str(value)


def study_html(study: Any) -> str:
    """The notebook's display of a sensitivity study (:mod:`hydroservo.analysis.sensitivity`): a one-at-a-time
    study's table of metrics by level and the response family of its first factor; a global study's indices
    with their confidence intervals and its bar chart."""
    import io

    from hydroservo.io.html import Notice, Picture, fragment

    buffer = io.BytesIO()
    if hasattr(study, "indices"):  # GlobalStudy
        title = (f"{study.method.capitalize()} sensitivity study: {', '.join(study.parameters)} "
                 f"({study.runs.stats.get('runs', '?')} runs, {study.runs.stats.get('failed', 0)} failed)")
        study.plot(file=buffer)
        items: list[Any] = [Notice(n) for n in study.notes]
        items += [Picture(buffer.getvalue(), "the indices (GlobalStudy.plot)"), dataframe_table(study.indices)]
        return fragment(title, items)
    factors = list(study.levels)
    title = f"One-at-a-time study of {study.model!r}: " + ", ".join(f"{f} ({len(study.levels[f])} levels)" for f in factors)
    items = [Notice(f"{factor} = {study.levels[factor][k]}: {why}") for (factor, k), why in study.failed.items()]
    items.append(dataframe_table(study.table))
    if factors:
        study.plot(factors[0], file=buffer)
        items.append(Picture(buffer.getvalue(), f"the responses at each level of {factors[0]} (OneAtATime.plot)"))
    return fragment(title, items)
