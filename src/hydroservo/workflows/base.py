"""What every workflow shares: the report it returns, the files it writes, the model it loads.

A workflow is one whole task as a command runs it: its inputs are checked when
it is made (:class:`Workflow`), :meth:`Workflow.run` does the work and returns
a :class:`Report`, which

* prints itself (:meth:`Report.lines`, the text the command line shows),
* serialises itself (:meth:`Report.to_dict`, the JSON of ``--json``),
* writes its files (:meth:`Report.artifacts`, each a name and a writer;
  :meth:`Report.write` puts them into a folder, all or nothing),
* and shows itself as a page (:meth:`Report.document`, :meth:`Report.to_html`,
  and in a notebook).

A Python user gets from a workflow everything the command gives::

    from hydroservo.workflows import simulate
    report = simulate.run("flight-simulator", sets={"load.W": "3000 lbf"})
    print(report)                       # what the command prints
    report.write("results")             # its CSV and plot
    report.to_html("step.html")         # one page to send a colleague

Errors in the inputs name them as a Python user wrote them (``t_end``), or,
for a workflow made by the command line (``cli=True``), as the command's
options (``--t-end``).
"""

from __future__ import annotations

import html
import json
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, NamedTuple

from hydroservo.errors import BareNumberWarning, HydroservoError, ParameterError, did_you_mean, shorten
from hydroservo.io.files import plain_float

if TYPE_CHECKING:
    from hydroservo.io.files import OutputFolder
    from hydroservo.io.html import Page
    from hydroservo.system.system import System
    from hydroservo.units import UnitChoice

__all__ = [
    "Artifact",
    "Report",
    "Workflow",
    "Progress",
    "numbers",
    "load_with_sets",
    "check_names",
    "parse_sets",
    "output_folder",
    "safe_name",
]


class Artifact(NamedTuple):
    """A file a report writes: its key (in :attr:`Report.files` and the JSON's ``files``), its name, its writer."""

    key: str
    name: str
    write: Callable[[Path], Any]


#: How a workflow tells what it is doing: ``progress(text)`` at each stage of a long run.
Progress = Callable[[str], None]


@dataclass
class Report:
    """What a workflow returns (module notes). Subclasses hold the results as fields and override the methods."""

    #: The command that makes this report ("simulate", "valve fit", ...).
    command: ClassVar[str] = ""

    #: The files written, by key, as they are named after :meth:`write` (paths as strings).
    files: dict[str, str] = field(default_factory=dict, kw_only=True)
    #: What a person must know of the result: physical bounds crossed, points that did not converge.
    warnings: list[str] = field(default_factory=list, kw_only=True)

    # -- what subclasses give -------------------------------------------------------
    def title(self) -> str:
        """One line naming what was done, and to what."""
        return self.command

    def lines(self) -> list[str]:
        """The text the command line prints (the files written last, once :meth:`write` has run)."""
        return [self.title()]

    def to_dict(self) -> dict[str, Any]:
        """Everything the report holds as plain data (what ``--json`` prints)."""
        return {"files": self.files}

    def artifacts(self) -> list[Artifact]:
        """The files the report writes: names and writers (none by default)."""
        return []

    def exit_code(self) -> int:
        """The command's exit code: 0, or 1 where the report found what its command exists to catch
        (a validation verdict that changed)."""
        return 0

    def document(self) -> Page:
        """The report as a page (:mod:`hydroservo.io.html`): by default its title, its lines and its warnings."""
        from hydroservo.io.html import Notice, Page, Section, Text

        sections = [Section("Summary", [Text("\n".join(self.lines()), preformatted=True)])]
        if self.warnings:
            sections.insert(0, Section("Warnings", [Notice(w) for w in self.warnings]))
        return Page(self.title(), sections=sections, footer=footer())

    # -- what every report does the same way ------------------------------------------
    def write(self, out: OutputFolder | str | Path, *, force: bool = False) -> dict[str, str]:
        """Write :meth:`artifacts` into ``out`` (a folder, made if missing), all or nothing.

        Files already there are replaced only with ``force``. Returns (and keeps in :attr:`files`)
        the path of each file written, by key.
        """
        from hydroservo.io.files import OutputFolder

        folder = out if isinstance(out, OutputFolder) else OutputFolder(Path(out), force=force, what="folder")
        artifacts = self.artifacts()
        folder.expect([a.name for a in artifacts])
        with folder:
            for artifact in artifacts:
                artifact.write(folder.file(artifact.name))
        self.files = {a.key: folder.final(a.name) for a in artifacts}
        return self.files

    def to_json(self) -> str:
        """:meth:`to_dict` as indented JSON (NumPy numbers as numbers, non-finite ones as ``NaN``)."""
        return json.dumps(self.to_dict(), indent=2, default=float)

    def to_html(self, path: str | Path | None = None) -> str:
        """The report as one self-contained HTML page (written to ``path`` if given); returns the HTML."""
        from hydroservo.io.html import render_html

        text = render_html(self.document())
        if path is not None:
            Path(path).write_text(text, encoding="utf-8")
        return text

    def _repr_html_(self) -> str:
        """In a notebook, the page in a frame of its own (its styles and scripts kept apart from the notebook's)."""
        page = html.escape(self.to_html(), quote=True)
        return f'<iframe srcdoc="{page}" style="width: 100%; height: 820px; border: 1px solid #d9dee4;"></iframe>'

    def __str__(self) -> str:
        return "\n".join(self.lines())

    def __repr__(self) -> str:
        return f"<{type(self).__name__}: {html.escape(self.title())}>"


@dataclass
class Workflow:
    """A task's inputs, checked when it is made; :meth:`run` does the task and returns its :class:`Report`.

    ``cli`` makes errors name the inputs as the command's options (``--t-end``) rather than as
    Python arguments (``t_end``); :attr:`OPTIONS` gives the options not spelled ``--`` and the
    field's name with dashes.
    """

    #: Fields whose option is not ``--field-name`` (e.g. ``{"sets": "--set"}``).
    OPTIONS: ClassVar[dict[str, str]] = {}
    #: True for a workflow that writes its own files while it runs (into ``run``'s ``folder``, all or nothing):
    #: its report has no artifacts to write afterwards.
    WRITES_ITSELF: ClassVar[bool] = False

    cli: bool = field(default=False, kw_only=True, repr=False)

    def name(self, field_name: str) -> str:
        """How an error names input ``field_name``: the option (``--t-end``) or the argument (``t_end``)."""
        if not self.cli:
            return field_name
        return self.OPTIONS.get(field_name, "--" + field_name.replace("_", "-"))

    def folder(self) -> str:
        """The default output folder's name (``hydroservo-NAME``); a new one is numbered (``-2``, ``-3``)."""
        return "hydroservo-output"

    def planned(self) -> list[str]:
        """The names of the files the report will write, known before the run: a folder that already holds
        one refuses before the work, not after."""
        return []

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> Report:
        """Do the task. ``progress(text)`` hears of each stage of a long one; ``folder`` is where the report's
        files will go, for a workflow that writes as it runs (a study's runs, resumable; an export)."""
        raise NotImplementedError


def footer() -> str:
    """Who made a page, and with what."""
    import datetime

    from hydroservo.version import __version__

    return f"made by hydroservo {__version__} on {datetime.date.today().isoformat()}"


def numbers(
    text: str,
    what: str,
    *,
    above: float | None = None,
    at_most: float | None = None,
    expected: str = "",
) -> list[float]:
    """Comma-separated finite numbers, e.g. ``5,25,50``; each above ``above`` and at most ``at_most`` if given.

    An error names the option ``what``, the value and ``expected``.
    """
    import math

    try:
        vals = [plain_float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise ParameterError(f"{what} {text!r}: expected comma-separated numbers, e.g. 5,25,50") from None
    if not vals:
        raise ParameterError(f"{what} {text!r}: expected at least one number")
    for v in vals:
        bad = not math.isfinite(v) or (above is not None and v <= above) or (at_most is not None and v > at_most)
        if bad:
            raise ParameterError(f"{what} {text!r}: {v:g} is not acceptable; expected {expected or 'finite numbers'}")
    return vals


# -- loading a model with changes ---------------------------------------------------------
def parse_sets(items: Sequence[str] | Mapping[str, Any] | None, what: str = "--set") -> list[tuple[str, Any]]:
    """``["load.W=3000 lbf", ...]`` or ``{"load.W": "3000 lbf"}`` -> ``[("load.W", "3000 lbf"), ...]``."""
    if not items:
        return []
    if isinstance(items, Mapping):
        return [(str(k).strip(), v) for k, v in items.items()]
    out = []
    for item in items:
        if "=" not in item:
            raise ParameterError(
                f'{what} {shorten(item)!r}: expected COMPONENT.PARAMETER=VALUE, e.g. {what} "load.W=3000 lbf"'
            )
        key, val = item.split("=", 1)
        out.append((key.strip(), val.strip()))
    return out


def load_with_sets(
    model: str | Path | System, sets: Sequence[str] | Mapping[str, Any] | None = None, what: str = "--set"
) -> System:
    """A built-in model, a model file or a system (copied), with the values of ``sets`` applied and checked.

    An error names ``what`` (the option or argument that gave the values), the value and what was expected.
    """
    from hydroservo.io.model_file import load_model
    from hydroservo.system.system import System

    system = model.copy() if isinstance(model, System) else load_model(str(model))
    touched: dict[str, list[str]] = {}
    for key, val in parse_sets(sets, what):
        shown = f"{what} {shorten(key)}={shorten(str(val))}"
        if key.count(".") != 1:
            raise ParameterError(f"{shown}: expected COMPONENT.PARAMETER, e.g. load.W")
        cname, pname = key.split(".")
        if cname not in system.components:
            raise ParameterError(
                f"{shown}: no component {cname!r}{did_you_mean(cname, system.components)}; components: "
                f"{', '.join(system.components)}"
            )
        comp = system.components[cname]
        known = set(comp.PARAMETERS) | set(comp.OPTIONS) | set(comp.RENAMED)
        if pname not in known:
            names = ", ".join(list(comp.PARAMETERS) + list(comp.OPTIONS))
            raise ParameterError(
                f"{shown}: {cname!r} has no parameter {pname!r}{did_you_mean(pname, known)}; parameters: {names}"
            )
        _refuse_ambiguous_number(comp, pname, val, shown, what)
        try:
            system.set(key, val)
        except HydroservoError as exc:
            raise ParameterError(f"{what} {key}={shorten(str(val))}: {exc}") from None
        touched.setdefault(cname, []).append(f"{key}={shorten(str(val))}")
    for cname, items in touched.items():  # a cross-parameter check the values break is theirs, not the file's
        try:
            system.components[cname].check()
        except HydroservoError as exc:
            raise ParameterError(f"{what} {', '.join(items)}: {exc}") from None
    return system


def check_names(system: System, what: str, names: Iterable[str] | None, kind: str) -> None:
    """Refuse, before any work, the first of ``names`` that ``system`` has not as ``kind``: ``"signal"`` (a state,
    an output or an alias), ``"state"``, or ``"input"`` (a component input or a parameter, a former name too);
    the message names ``what`` (the option or argument: ``--outputs``) and the closest names
    (:func:`~hydroservo.errors.did_you_mean`)."""
    if not names:
        return
    model = system.build()
    known: dict[str, list[str]] = {
        "signal": [*model.state_names, *model.output_names],
        "state": list(model.state_names),
        "input": [f"{c}.{k}" for c, comp in system.components.items() for k in [*comp.INPUTS, *comp.PARAMETERS, *comp.RENAMED]],
    }
    said = {"signal": "not a state, output or alias", "state": "not a state", "input": "neither a component input nor a parameter"}
    for name in names:
        if name not in known[kind]:
            raise ParameterError(
                f"{what} {shorten(str(name))!r}: {said[kind]} of {system.name!r}{did_you_mean(str(name), known[kind])}"
            )


def asked_units(system: System, units: Any, si: bool, what: Callable[[str], str]) -> UnitChoice:
    """The units a workflow's options ask for (``units``: ``"p=bar, mm"``, a mapping; ``si``), checked against
    ``system``'s signals before anything runs; ``what`` names an option (``--units`` or ``units``).

    Raises
    ------
    ParameterError
        For both options at once, a unit that is not one, or a unit chosen for a signal the model lacks or of
        another dimension than the signal's.
    """
    from hydroservo.units import UnitChoice

    if si and units:
        raise ParameterError(f"{what('si')} and {what('units')} {shorten(str(units))!r}: give one of them")
    if si:
        return UnitChoice.SI
    try:
        choice = UnitChoice.parse(units, what=what("units"))
    except HydroservoError as exc:
        raise ParameterError(str(exc)) from None
    if choice.signals:
        choice.check(system.build().units, what("units"))
    return choice


def _refuse_ambiguous_number(comp: Any, pname: str, val: Any, shown: str, what: str) -> None:
    """Refuse a bare number given as text (``--set load.W=3000``) for a dimensional parameter that the model
    gives in a unit other than SI (``"6400 lbf"``): it would be taken in SI (N), not in the model's unit
    (:func:`hydroservo.system.system.model_unit`; the Python API warns of a number, which it documents as SI).
    A number in a model that gives the parameter in SI, or without a unit, is SI as everywhere; zero is zero.
    A number (not text) from Python is taken in SI with a :class:`~hydroservo.errors.BareNumberWarning`."""
    import warnings

    from hydroservo.system.system import model_unit
    from hydroservo.units import coherent_unit

    unit = model_unit(comp, pname, val)
    if unit is None:
        return
    given, si = comp.given[pname], coherent_unit(comp.PARAMETERS[pname].unit)
    if not isinstance(val, str):  # a number in Python is SI, as the API documents it: said, not refused
        warnings.warn(BareNumberWarning(
            f"{shown}: taken in SI, {val} {si}, but the model gives {comp.name}.{pname} in {unit} ({given!r}); "
            f"give the unit to say which you mean: '{val} {unit}' or '{val} {si}'"), stacklevel=4)
    else:
        raise ParameterError(
            f"{shown}: the model gives {comp.name}.{pname} in {unit} ({given!r}), and a bare number would be taken "
            f"in SI ({si}); give the unit you mean: {what} \"{comp.name}.{pname}={val.strip()} "
            f"{unit}\" or {what} \"{comp.name}.{pname}={val.strip()} {si}\""
        )


# -- output folders -------------------------------------------------------------------
def safe_name(name: str) -> str:
    """A plain file name from a model's name (:func:`hydroservo.io.files.safe_name`)."""
    from hydroservo.io.files import safe_name as _safe

    return _safe(name)


def output_folder(out: str | Path | None, default: str, *, force: bool = False, what: str = "--out") -> OutputFolder:
    """The folder a command writes to, all or nothing, nothing replaced unasked.

    ``out`` is used as given (files already in it are replaced only with ``force``); without it, a
    fresh folder: ``default``, or ``default-2``, ``default-3``, ... if it exists, so repeated runs never
    collide.
    """
    from hydroservo.io.files import OutputFolder
    from hydroservo.io.files import safe_name as _safe

    if out:
        return OutputFolder(Path(out), force=force, what=what)
    base = _safe(default)
    target, n = Path(base), 1
    while target.exists() and not force:
        n += 1
        target = Path(f"{base}-{n}")
    return OutputFolder(target, force=force, what="output folder")


def finite_or_none(value: float | None) -> float | None:
    """``value``, or None where it is missing or not finite (for JSON)."""
    return None if value is None or not math.isfinite(value) else float(value)


def json_records(frame: Any) -> list[dict[str, Any]]:
    """The rows of a DataFrame as JSON records: a number that is not finite (a failed run's metric) as None."""
    return [{k: finite_or_none(v) if isinstance(v, float) else v for k, v in row.items()}
            for row in frame.to_dict(orient="records")]
