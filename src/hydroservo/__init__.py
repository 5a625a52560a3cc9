"""hydroservo: model, simulate and analyse electro-hydraulic servo systems.

>>> import hydroservo as hs
>>> system = hs.load_model("flight-simulator")
>>> result = system.simulate(t_end=0.5)
>>> round(float(result.get("p2", "psi")[0]))
772

The public namespaces, by layer (each imports only from the ones above it):

===========================  ======================================================
namespace                    what
===========================  ======================================================
``hs.units``, ``hs.errors``  units at the edges, SI inside; exceptions
``hs.references``            the bibliography every docstring cites
``hs.laws``                  published laws, pure functions (NumPy and CasADi)
``hs.fluids``                hydraulic fluids as property sets
``hs.components``            parts with parameters, states, ports, equations
``hs.System``, ``Model``     components connected into one ODE; its solvers
``hs.analysis``              frequency responses, static test benches
``hs.identification``        parameters from datasheets, curves and Bode data
``hs.io``                    every reader and writer; ``hs.load_model``
``hs.data``                  published and example parameter sets, models
``hs.validation``            published figures beside computed ones
``hs.plotting``              the plots; circuit diagrams (``System.diagram``)
``hs.codegen``               a model as C code with a real-time stepper, or an FMU
``hs.workflows``             whole tasks as the commands run them, each returning a
                             report that prints, writes its files and shows itself
===========================  ======================================================

Names are imported on first use, so that ``import hydroservo`` and the command
line's ``--help`` stay fast (``docs/architecture.md``).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from hydroservo.errors import (
    HydroservoError,
    ImplausibleResultError,
    ImplausibleResultWarning,
    ModelError,
    ModelFileError,
    ParameterError,
    SolverError,
    TrimError,
    UnitError,
)
from hydroservo.version import __version__

#: Public name -> (module, attribute; None for the module itself)
_LAZY: dict[str, tuple[str, str | None]] = {
    "System": ("hydroservo.system", "System"),
    "Model": ("hydroservo.system", "Model"),
    "Result": ("hydroservo.system", "Result"),
    "BatchResult": ("hydroservo.system", "BatchResult"),
    "load_model": ("hydroservo.io.model_file", "load_model"),
    "available_models": ("hydroservo.io.model_file", "available_models"),
    "to_si": ("hydroservo.units", "to_si"),
    "ureg": ("hydroservo.units", "ureg"),
    **{
        name: (f"hydroservo.{name}", None)
        for name in (
            "analysis",
            "backend",
            "codegen",
            "components",
            "data",
            "errors",
            "fluids",
            "identification",
            "io",
            "laws",
            "plotting",
            "references",
            "system",
            "units",
            "validation",
            "workflows",
        )
    },
}

__all__ = [
    "__version__",
    "System",
    "Model",
    "Result",
    "BatchResult",
    "load_model",
    "available_models",
    "analysis",
    "backend",
    "codegen",
    "components",
    "data",
    "errors",
    "fluids",
    "identification",
    "io",
    "laws",
    "plotting",
    "references",
    "system",
    "units",
    "validation",
    "workflows",
    "to_si",
    "ureg",
    "HydroservoError",
    "UnitError",
    "ParameterError",
    "ModelError",
    "ModelFileError",
    "SolverError",
    "TrimError",
    "ImplausibleResultError",
    "ImplausibleResultWarning",
]


def __getattr__(name: str) -> Any:
    if name not in _LAZY:
        raise AttributeError(f"module 'hydroservo' has no attribute {name!r}")
    module_name, attr = _LAZY[name]
    module = importlib.import_module(module_name)
    value = module if attr is None else getattr(module, attr)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


if TYPE_CHECKING:  # the names the lazy imports give, for type checkers and editors
    from hydroservo import (
        analysis,
        backend,
        codegen,
        components,
        data,
        fluids,
        identification,
        io,
        laws,
        plotting,
        references,
        system,
        units,
        validation,
        workflows,
    )
    from hydroservo.io.model_file import available_models, load_model
    from hydroservo.system import BatchResult, Model, Result, System
    from hydroservo.units import to_si, ureg
