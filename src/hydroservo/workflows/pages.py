"""The parts of a report's page that several reports show: a system's circuit and parameters, a run's signals
and solver statistics, warnings, references.

Each function returns items or sections of :mod:`hydroservo.io.html`; a report's
:meth:`~hydroservo.workflows.base.Report.document` puts them together.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from hydroservo.io.notebook import dataframe_table, parameter_table, signal_table

if TYPE_CHECKING:
    from hydroservo.io.html import Item, Section, Table
    from hydroservo.system.system import System

__all__ = [
    "parameter_table",
    "signal_table",
    "solver_table",
    "warnings_section",
    "references_section",
    "circuit_section",
    "system_summary",
    "dataframe_table",
    "files_section",
    "notes_section",
    "page",
]


def solver_table(stats: Mapping[str, Any]) -> Table:
    """The integrator's statistics: steps, right-hand sides, Jacobians, failures, tolerances, wall time."""
    from hydroservo.io.html import Table

    labels = {
        "nsteps": "steps", "nfevals": "right-hand side evaluations", "nlinsetups": "Jacobians (linear solver setups)",
        "netfails": "error-test failures", "nniters": "Newton iterations", "nncfails": "Newton failures",
        "rtol": "relative tolerance", "atol": "absolute tolerance", "wall_time_s": "integration wall time [s]",
        "nrejected": "rejected steps", "njevals": "Jacobians", "nevents": "events (steps ended at a kink)",
        "compile_load_wall_time_s": "model compiled to C, or loaded from the cache [s]",
        "run_wall_time_s": "whole run, model build included [s]",
    }
    rows = [[labels.get(k, k), v] for k, v in stats.items() if isinstance(v, int | float) and math.isfinite(v)]
    captions = {
        "rodas3": "rodas3 (compiled): Rosenbrock 3(2) of Sandu et al., L-stable, on the exact Jacobian",
        "ros23": "ros23 (compiled): Rosenbrock 2(3) of Shampine and Reichelt on the exact Jacobian",
        "dopri5": "dopri5 (compiled): Dormand-Prince 5(4), explicit",
    }
    caption = captions.get(str(stats.get("method")), "CVODES (SUNDIALS), BDF with the exact Jacobian")
    return Table(["statistic", "value"], rows, caption=caption)


def warnings_section(warnings: Sequence[str], title: str = "Warnings") -> Section | None:
    """The warnings as notices, or None when there are none."""
    from hydroservo.io.html import Notice, Section

    if not warnings:
        return None
    return Section(title, [Notice(w, "warning") for w in warnings])


def references_section(keys: Sequence[str], title: str = "References") -> Section:
    """The bibliography entries, in full (:func:`hydroservo.references.cite`)."""
    from hydroservo.io.html import Section, Table
    from hydroservo.references import cite

    return Section(title, [Table(["key", "reference"], [[k, cite(k)] for k in keys])])


def circuit_section(system: System) -> Section:
    """The circuit's schematic (:meth:`hydroservo.system.System.diagram`)."""
    from hydroservo.io.html import Drawing, Section

    drawing = system.diagram()
    return Section("Circuit", [Drawing(drawing.svg, f"{system.name}: {len(system.components)} components")])


def system_summary(system: System) -> list[Item]:
    """What the system is: its description, its source and status, its fluid."""
    from hydroservo.io.html import Text

    items: list[Item] = []
    if system.description:
        items.append(Text(system.description))
    meta = system.meta
    facts = []
    if meta.get("citation"):
        facts.append(f"source: [{meta['citation']}] ({meta.get('status', '')})")
    if meta.get("validation"):
        facts.append(f"validation: {meta['validation']}")
    if system.fluid is not None:
        facts.append(f"fluid: {system.fluid.describe()}")
    if system.source:
        facts.append(f"from: {system.source}")
    if facts:
        items.append(Text("; ".join(facts)))
    return items


def notes_section(notes: Sequence[str], title: str = "Notes") -> Section | None:
    """The model's notes (as a run shows them: :meth:`~hydroservo.workflows.simulate.SimulationReport.notes`), or
    None when it has none."""
    from hydroservo.io.html import Notice, Section

    if not notes:
        return None
    return Section(title, [Notice(note, "info") for note in notes])


def files_section(files: Mapping[str, str]) -> Section | None:
    """The files the report wrote, or None before it wrote any."""
    from hydroservo.io.html import Section, Table

    if not files:
        return None
    return Section("Files", [Table(["file", "path"], [[k, v] for k, v in files.items()])])


def page(title: str, subtitle: str, sections: Sequence[Section | None], warnings: Sequence[str] = ()) -> Any:
    """A page of ``sections`` (None left out), its warnings first."""
    from hydroservo.io.html import Page
    from hydroservo.workflows.base import footer

    kept = [s for s in sections if s is not None]
    warned = warnings_section(warnings)
    return Page(title, subtitle, ([warned] if warned else []) + kept, footer())
