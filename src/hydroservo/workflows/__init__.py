"""Workflows: each module runs one whole task as its command does, and returns a report.

=========================  ===============================================================
module                     task (command)
=========================  ===============================================================
:mod:`.simulate`           a run of a model (``simulate``)
:mod:`.report`             one page of a model's run or a result file (``report``)
:mod:`.draw`               a circuit diagram (``draw``)
:mod:`.export`             a model written out: a model file (``export``)
:mod:`.linear`             linear model, modes, valve coefficients (``linearize``)
:mod:`.ladder`             the model-fidelity ladder (``ladder``)
:mod:`.sensitivity`        one at a time, Sobol, Morris (``sensitivity``)
:mod:`.staged_slot`        staged-slot valve characteristics and identification
                           (``valve characteristics``, ``valve identify``)
:mod:`.valve`              the servo-solenoid valve: datasheet fit, Bode, dynamics fit (``valve``)
:mod:`.servovalve`         the two-stage servovalve: bench, design, catalogue fit (``servovalve``)
:mod:`.calibrate`          rig records to a calibrated model, experiment design, the virtual
                           rig (``calibrate``, ``calibrate --plan``, ``rig``)
:mod:`.identify`           Efe's procedures on rig records (``identify friction``,
                           ``identify leakage``, ``identify flow-coefficient``)
:mod:`.validate`           published figures beside computed ones (``validate``)
:mod:`.fluid`              fluid properties (``fluid``)
:mod:`.components`         the component reference (``components``, ``describe``)
:mod:`.models`             the built-in models (``models``)
:mod:`.examples`           the example files (``examples``)
:mod:`.cache`              the compiled models' folder (``cache``)
:mod:`.base`               what they share: :class:`~.base.Report`, :class:`~.base.Workflow`,
                           loading a model with changes, output folders
:mod:`.pages`              the parts of report pages several reports show
=========================  ===============================================================

A workflow checks its inputs when it is made and does its work in ``run()``,
which returns a :class:`~hydroservo.workflows.base.Report`: the lines the
command prints, the JSON of ``--json``, the files it writes, and a page that
shows it all (``report.to_html(path)``; in a notebook, the report itself). The
command line only parses its options into a workflow, runs it, writes its
files and prints its report; a script or a notebook calls the same workflow.

Like pvlib's ``ModelChain`` and PyBaMM's ``Simulation``, this layer sits on top
of the library (analysis, identification, io, plotting, validation) and below
the command line. Its modules are imported on first use.
"""

from __future__ import annotations

import importlib
from typing import Any

#: The workflow modules, imported on first use.
MODULES: tuple[str, ...] = (
    "base", "cache", "calibrate", "components", "draw", "examples", "export", "fluid", "identify", "ladder", "linear", "models",
    "pages", "report", "sensitivity", "servovalve", "simulate", "staged_slot", "validate", "valve",
)


def __getattr__(name: str) -> Any:
    if name not in MODULES:
        raise AttributeError(f"module 'hydroservo.workflows' has no attribute {name!r}")
    module = importlib.import_module(f"hydroservo.workflows.{name}")
    globals()[name] = module
    return module


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(MODULES))
