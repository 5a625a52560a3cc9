"""The package's own data: published parameter sets, example sets and built-in models, as TOML files.

* ``parameters/NAME.toml``: a parameter set named after its source (the
  citation key of :mod:`hydroservo.references`, plus a suffix for a second set
  of the same source). Every value is written as its source prints it, in the
  source's units ("0.1149 L/min/bar^0.5"); a ``[set]`` table says where it
  comes from and whether it is ``published`` or an ``example`` (values chosen
  by hydroservo where the source gives none).
* ``models/NAME.toml``: the built-in systems, as model files
  (:mod:`hydroservo.io.model_file`), in their source's units.
* ``examples/``: the files the README's commands use (``hydroservo examples DIR``
  copies them).
* ``servovalves.toml``: the built-in servovalves of ``hydroservo servovalve``: what each is, its parameter
  set and its rated design point.
* ``units.json``: the conversions of the units the package uses and engineers
  commonly write, computed by pint (:func:`hydroservo.units.unit_table` reads them so that
  a run need not build the unit registry; ``scripts/unit_table.py`` writes it).
* ``reference/``: results of other tools that hydroservo compares itself with
  (Hopsan's Position Servo), with a README on how each was made.
* ``c/``: the C templates of the fixed-step stepper that :mod:`hydroservo.codegen.c`
  fills in for a model (``@NAME@`` and the like replaced by its identifier and sizes).

This module only finds and parses the package's files (standard-library
TOML, no unit registry); values are converted to SI by whoever uses them
(:meth:`ParameterSet.si`), and user files are read by :mod:`hydroservo.io`.
"""

from __future__ import annotations

import functools
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from hydroservo.errors import ParameterError

__all__ = [
    "guide_folder",
    "ParameterSet",
    "parameter_set",
    "parameter_sets",
    "model_names",
    "model_text",
    "example_files",
    "reference_text",
    "reference_path",
    "c_template",
    "servovalves",
]

_ROOT = resources.files("hydroservo.data")


@dataclass(frozen=True)
class ParameterSet:
    """A parameter set of the package: its tables as printed, and where they come from."""

    name: str
    title: str
    citation: str
    status: str
    where: str
    tables: dict[str, Any]

    def table(self, name: str) -> dict[str, Any]:
        """Table ``name`` as printed (strings with units)."""
        try:
            return dict(self.tables[name])
        except KeyError:
            raise ParameterError(
                f"parameter set {self.name!r} has no table {name!r}; tables: {', '.join(self.tables)}"
            ) from None

    def si(self, table: str, key: str, unit: str) -> float:
        """Value ``key`` of ``table`` in the SI unit ``unit``."""
        from hydroservo.units import to_si

        entries = self.table(table)
        if key not in entries:
            raise ParameterError(f"parameter set {self.name!r}, [{table}]: no {key!r}")
        return to_si(entries[key], unit, what=f"{self.name} [{table}] {key}")


@functools.cache
def parameter_set(name: str) -> ParameterSet:
    """A parameter set of the package by name (:func:`parameter_sets`)."""
    path = _ROOT / "parameters" / f"{name}.toml"
    if not path.is_file():
        raise ParameterError(f"no parameter set {name!r}; the package has {', '.join(parameter_sets())}")
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    meta = data.pop("set")
    return ParameterSet(name, meta["title"], meta["citation"], meta["status"], meta.get("where", ""), data)


def parameter_sets() -> list[str]:
    """Names of the package's parameter sets."""
    return sorted(p.name[: -len(".toml")] for p in (_ROOT / "parameters").iterdir() if p.name.endswith(".toml"))


def model_names() -> list[str]:
    """Names of the built-in models, in the order ``hydroservo models`` lists them."""
    names = [p.name[: -len(".toml")] for p in (_ROOT / "models").iterdir() if p.name.endswith(".toml")]
    return sorted(names, key=lambda n: (n != "flight-simulator", n))


def model_text(name: str) -> str:
    """The model file of built-in model ``name``."""
    path = _ROOT / "models" / f"{name}.toml"
    if not path.is_file():
        raise ParameterError(f"no built-in model {name!r}; built-in models: {', '.join(model_names())}")
    return path.read_text(encoding="utf-8")


def example_files() -> dict[str, str]:
    """The example files the README uses: file name -> text."""
    folder = _ROOT / "examples"
    return {p.name: p.read_text(encoding="utf-8") for p in sorted(folder.iterdir(), key=lambda p: p.name) if p.is_file()}


def reference_text(name: str) -> str:
    """A result of another tool that hydroservo compares itself with (``reference/NAME``; provenance in its README)."""
    path = _ROOT / "reference" / name
    if not path.is_file():
        raise ParameterError(f"no reference result {name!r}")
    return path.read_text(encoding="utf-8")


def reference_path(name: str) -> Path:
    """The file of a result of another tool, or of the model it was compared with (``reference/NAME``)."""
    path = Path(str(_ROOT / "reference" / name))
    if not path.is_file():
        raise ParameterError(f"no reference file {name!r}")
    return path


def c_template(name: str) -> str:
    """A C template of the real-time stepper (``c/NAME``: ``stepper.c``, ``stepper.h``)."""
    path = _ROOT / "c" / name
    if not path.is_file():
        raise ParameterError(f"no C template {name!r}")
    return path.read_text(encoding="utf-8")


@functools.cache
def servovalves() -> dict[str, dict[str, str]]:
    """The built-in servovalves (``servovalves.toml``): name -> description, component type, parameter set, and
    the rated supply and current as printed."""
    with _ROOT.joinpath("servovalves.toml").open("rb") as f:
        return {name: dict(entry) for name, entry in tomllib.load(f).items()}


def guide_folder() -> Path | None:
    """Where the user guide's pages (``docs/NAME.md``, the pages the package's messages name) are: in the
    installed package (a wheel carries them as ``hydroservo/docs``), else in the repository beside ``src/`` (a
    clone, an editable install); None if neither holds them."""
    package = Path(__file__).resolve().parents[1]
    for folder in (package / "docs", package.parents[1] / "docs"):
        if (folder / "validation.md").is_file():
            return folder
    return None
