"""Workflows: each module runs one whole task as its command does, and returns a report.

=========================  ===============================================================
module                     task (command)
=========================  ===============================================================
:mod:`.base`               what they share: :class:`~.base.Report`, :class:`~.base.Workflow`,
                           loading a model with changes, output folders
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
MODULES: tuple[str, ...] = ("base", "components", "examples", "export", "fluid", "ladder", "linear", "models", "sensitivity", "simulate", "staged_slot", "validate")


def __getattr__(name: str) -> Any:
    if name not in MODULES:
        raise AttributeError(f"module 'hydroservo.workflows' has no attribute {name!r}")
    module = importlib.import_module(f"hydroservo.workflows.{name}")
    globals()[name] = module
    return module


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(MODULES))
