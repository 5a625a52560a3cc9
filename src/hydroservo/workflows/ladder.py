"""The model-fidelity ladder of a system and its error table ([Efe2014] Table 5.3), as ``hydroservo ladder`` runs it.

>>> from hydroservo.workflows import ladder
>>> report = ladder.run("robot-arm", steps=[0.368], models=["nonlinear", "linear"], points=101)
>>> list(report.ladder.table.index)
['nonlinear', 'linear', 'improved nonlinear', 'improved linear']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import (
    Artifact,
    Progress,
    Report,
    Workflow,
    asked_units,
    json_records,
    load_with_sets,
    safe_name,
)

if TYPE_CHECKING:
    from hydroservo.analysis.ladder import LadderTable
    from hydroservo.io.html import Page
    from hydroservo.system.system import System
    from hydroservo.units import UnitChoice

__all__ = ["Ladder", "LadderReport", "run"]

#: A measured response: a file (time [s] in column 0, the output in column 1), a file and its column, or (t, y).
Measured = str | Path | tuple[Any, Any]


@dataclass
class LadderReport(Report):
    """Every rung's response at each step, its error against the reference, its class and its cost."""

    command: ClassVar[str] = "ladder"

    system: System
    ladder: LadderTable
    t: float  #: time of the operating point [s]
    free: list[str]
    unit: str  #: the output's unit (SI)
    #: the units the displacements are shown in (None: the model's)
    units: UnitChoice | None = None
    #: whether :meth:`artifacts` names the files (the CSV and the plots)
    write_files: bool = True

    def _shown(self) -> tuple[float, str]:
        """The factor from SI to the unit the output's displacements (changes) are shown in, and that unit."""
        choice = self.units if self.units is not None else self.system.unit_choice()
        return choice.scale(self.ladder.output, self.unit)

    def table(self) -> Any:
        """The ladder's table (a DataFrame, a row per model), its displacements in the unit they are shown in."""
        from hydroservo.units import si_unit

        factor, unit = self._shown()
        table = self.ladder.table.copy()
        renamed = {}
        for column in table.columns:
            if str(column).startswith("displacement "):
                table[column] = table[column] * factor
                renamed[column] = f"{column} [{si_unit(unit) or '-'}]"
        for count in ("states", "solver steps"):  # counts, whole
            if count in table:
                table[count] = [None if v != v else int(v) for v in table[count]]
        return table.rename(columns=renamed)

    def title(self) -> str:
        lad = self.ladder
        return (f"{self.system.name}: model-fidelity ladder, linearised at the steady motion at t = {self.t:g} s "
                f"(free: {', '.join(self.free) or 'none'}); steps of {lad.parameter}; {lad.output} against "
                f"{lad.reference}")

    def artifacts(self) -> list[Artifact]:
        from hydroservo.io.results import write_frame
        from hydroservo.plotting.ladder import plot_ladder_classes, plot_ladder_responses

        lad = self.ladder
        if not self.write_files:
            return []
        return [
            Artifact("ladder.csv", "ladder.csv", lambda p: write_frame(self.table(), p, index=True)),
            Artifact("ladder-responses.png", "ladder-responses.png", lambda p: plot_ladder_responses(
                lad, unit=self._shown()[1], scale=self._shown()[0], file=p,
                title=f"{self.system.name}: {lad.output} of every model at each step of {lad.parameter}")),
            Artifact("ladder-classes.png", "ladder-classes.png", lambda p: plot_ladder_classes(lad, file=p)),
        ]

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.system.name, "operating_point": {"t": self.t, "free": self.free},
                **self.ladder.to_dict(), "models": json_records(self.table().reset_index()), "files": self.files}

    def lines(self) -> list[str]:
        from hydroservo.io.text import text_table
        from hydroservo.units import si_unit

        lad = self.ladder
        out = [self.title()]
        short = {"accurate": "A", "moderate": "M", "inaccurate": "I", "failed": "F"}
        out.append("  error against the reference [%] and class (A accurate < 7.5 %, M moderate to 20 %, "
                   "I inaccurate; * implausible run)")
        rows = []
        for model, row in lad.table.iterrows():
            cells = []
            for s in lad.steps:
                cls = str(row[f"class {100 * s:g} %"])
                mark = short.get(cls.split(" ")[0], "?") + ("*" if "implausible" in cls else "")
                cells.append(f"{round(row[f'error {100 * s:g} % [%]'], 1) + 0.0:+.1f} {mark}")  # no -0.0
            rows.append([model, *cells, f"{int(row['states'])} states, {row['solver steps']:.0f} steps, "
                         f"{row['wall time [ms]']:.1f} ms"])
        out += text_table(rows, ["model", *(f"{100 * s:g} %" for s in lad.steps), "cost"], indent=4,
                          align=["left", *["right"] * len(lad.steps), "left"])
        factor, unit = self._shown()
        if lad.reference in lad.table.index:
            ref = lad.table.loc[lad.reference]
            changes = ", ".join(f"{factor * ref[f'displacement {100 * s:g} %']:.4g}" for s in lad.steps)
            out.append(f"  the reference's change of {lad.output} [{si_unit(unit) or '-'}]: {changes}")
        for f, path in self.files.items():
            out.append(f"  {f}: {path}")
        return out

    def document(self) -> Page:
        """The error table, its classes, and every rung's response at each step (interactive)."""
        import numpy as np

        from hydroservo.io.html import Figure, Section
        from hydroservo.plotting.interactive import xy_figure
        from hydroservo.units import si_unit
        from hydroservo.workflows import pages

        lad = self.ladder
        factor, unit = self._shown()
        figures = []
        for k, step in enumerate(lad.steps):
            curves = []
            for rung, batch in lad.runs.items():
                t = np.asarray(batch.t, dtype=float)
                y = np.asarray(batch[lad.output], dtype=float)
                curves.append((t, (y[k] if y.ndim > 1 else y) * factor, rung))
            if curves:
                figures.append(Figure(xy_figure(curves, "t [s]", f"{lad.output} [{si_unit(unit)}]",
                                                title=f"step {100 * step:g} % of {lad.parameter}")))
        return pages.page(self.title(), f"against {lad.reference}", [
            Section("Errors and classes ([Efe2014] Table 5.3)", [pages.dataframe_table(self.table(), index=True)]),
            Section("Responses", figures) if figures else None,
            pages.circuit_section(self.system),
            pages.references_section(self.system.references()),
            pages.files_section(self.files),
        ], self.warnings)


@dataclass
class Ladder(Workflow):
    """Derive the ladder of ``model``, run every rung at each step and classify the errors.

    Parameters
    ----------
    model : str, Path or System
        A built-in model's name, a model file or a system.
    sets : list of "COMPONENT.PARAMETER=VALUE" or dict, optional
        Changes to its parameters first.
    steps : list of float, optional
        Valve-signal steps as fractions (0 to 1]; default :data:`hydroservo.analysis.ladder.STEPS`.
    parameter : str, optional
        What a step sets (default: the amplitude of the first Step or Pulse block).
    output : str, optional
        The displacement compared (default: the first alias or position).
    t : float or str, optional
        Time of the operating point [s] (default: while the signal is on).
    free : list of str, optional
        States free in the operating point (default: the masses' positions, a steady motion), at the values a run
        from the initial state has at ``t`` (:func:`hydroservo.analysis.linear.operating_point`).
    models : list of str, optional
        Some of :data:`hydroservo.analysis.ladder.RUNGS` (default all).
    measured : mapping, optional
        Measured responses, the reference: step (a fraction) -> a CSV file (time [s] in column 0, the output in
        its unit in column 1), ``(file, column)``, or ``(t, y)`` arrays.
    points : int
        Output times per run.
    units : str or dict, optional
        Units to show the output's displacements in, over the model's own (``"mm"``;
        :class:`~hydroservo.units.UnitChoice`): the table, the CSV, the JSON and the plots.
    si : bool
        Show them in SI instead.
    write : bool
        Whether the report writes its files (the table as CSV, the responses and the classes as PNG).
    """

    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set"}

    model: str | Path | System
    sets: Sequence[str] | Mapping[str, Any] | None = None
    steps: Sequence[float] | None = None
    parameter: str | None = None
    output: str | None = None
    t: float | str | None = None
    free: Sequence[str] | None = None
    models: Sequence[str] | None = None
    measured: Mapping[float, Measured] | None = None
    points: int = 301
    units: str | Mapping[str, str] | None = None
    si: bool = False
    write: bool = True

    def __post_init__(self) -> None:
        from hydroservo.analysis.ladder import RUNGS, STEPS, ladder_defaults
        from hydroservo.units import to_si

        system = self.system = load_with_sets(self.model, self.sets, self.name("sets"))
        self.unit_choice = system.unit_choice(asked_units(system, self.units, self.si, self.name))
        defaults = ladder_defaults(system)
        self.stepped = self.parameter or defaults["parameter"]
        if self.stepped is None:
            raise ParameterError(
                f"{system.name}: no Step or Pulse signal block to step; name the parameter with {self.name('parameter')}"
            )
        system.parameter_key(self.stepped)
        self.compared = self.output or defaults["output"]
        if self.compared is None or self.compared not in system.build().units:
            raise ParameterError(
                f"{self.name('output')} {self.compared!r}: expected a signal of {system.name!r} (a state, output or alias)"
            )
        self.step_values = list(self.steps) if self.steps else list(STEPS)
        from hydroservo.analysis.linear import operating_time

        self.time = operating_time(to_si(self.t, "s", what=self.name("t")), self.name("t"), self.t) \
            if self.t is not None else defaults["t"]
        self.free_states = list(self.free) if self.free is not None else defaults["free"]
        self.kinds = list(self.models) if self.models else list(RUNGS)
        for k in self.kinds:
            if k not in RUNGS:
                raise ParameterError(
                    f"{self.name('models')} {','.join(self.kinds)!r}: {k!r} is not a model of the ladder; "
                    f"expected some of {', '.join(RUNGS)}"
                )
        self.reference = self._read_measured()

    def _read_measured(self) -> dict[float, tuple[Any, Any]] | None:
        from hydroservo.io import read_time_table

        if not self.measured:
            return None
        out: dict[float, tuple[Any, Any]] = {}
        for step, source in self.measured.items():
            what = f"{self.name('measured')} {100 * step:g}"
            if isinstance(source, tuple) and len(source) == 2 and not isinstance(source[0], str | Path):
                out[float(step)] = source
                continue
            file, column = (source if isinstance(source, tuple) else (source, 1))
            out[float(step)] = read_time_table(str(file), column, what=what)
        return out

    def folder(self) -> str:
        return f"hydroservo-{safe_name(self.system.name)}-ladder"

    def planned(self) -> list[str]:
        return ["ladder.csv", "ladder-responses.png", "ladder-classes.png"] if self.write else []

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> LadderReport:
        from hydroservo.analysis.ladder import build_ladder, ladder_table

        if progress is not None:
            progress("building the rungs (trim, linearisation, simplified models)")
        rungs = build_ladder(self.system, "trim", t=self.time, free=self.free_states, kinds=self.kinds)
        if progress is not None:
            progress(f"running {len(rungs)} rungs at {len(self.step_values)} steps each")
        table = ladder_table(rungs, self.step_values, parameter=self.stepped, output=self.compared,
                             n_points=self.points, reference=self.reference)
        unit = self.system.build().units.get(self.compared, "")
        return LadderReport(self.system, table, self.time, self.free_states, unit, self.unit_choice, self.write)


def run(model: str | Path | System, **inputs: Any) -> LadderReport:
    """The ladder of ``model`` (:class:`Ladder`'s inputs as keywords)."""
    return Ladder(model, **inputs).run()
