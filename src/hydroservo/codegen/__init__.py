"""A model as code for other programs: C with a fixed-step real-time stepper, and FMI 2.0 FMUs.

=======================  ========================================================
module                   what
=======================  ========================================================
:mod:`.c`                the model's functions as C (CasADi code generation), a fixed-step stepper
                         (rk4, bdf2) with a C API, and :class:`~.c.CStepper`, which compiles and
                         loads it to check it against CVODES (docs/realtime.md)
:mod:`.fmu`              an FMI 2.0 FMU, Model Exchange and Co-Simulation, over the stepper's C API
                         (docs/fmu.md)
=======================  ========================================================

This package sits beside :mod:`hydroservo.system`: it takes a system, assembles it
(:func:`hydroservo.system.assembly.assemble`) and generates from that one graph; the C
templates are package data (``data/c/``). Names are imported on first use.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

#: Public name -> the module that defines it.
_LAZY: dict[str, str] = {
    "CStepper": "hydroservo.codegen.c",
    "export_c": "hydroservo.codegen.c",
    "export_fmu": "hydroservo.codegen.fmu",
}

__all__ = ["CStepper", "export_c", "export_fmu"]


def __getattr__(name: str) -> Any:
    if name not in _LAZY:
        raise AttributeError(f"module 'hydroservo.codegen' has no attribute {name!r}")
    value = getattr(importlib.import_module(_LAZY[name]), name)
    globals()[name] = value
    return value


if TYPE_CHECKING:
    from hydroservo.codegen.c import CStepper, export_c
    from hydroservo.codegen.fmu import export_fmu
