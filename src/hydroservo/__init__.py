"""hydroservo: model, simulate and analyse electro-hydraulic servo systems.

>>> import hydroservo as hs
>>> system = hs.load_model("flight-simulator")
>>> result = system.simulate(t_end=0.5)
>>> round(float(result.get("p2", "psi")[0]))
772
"""

from hydroservo import components, fluids, friction, orifices
from hydroservo.errors import (
    HydroservoError,
    ModelError,
    ModelFileError,
    ParameterError,
    SolverError,
    TrimError,
    UnitError,
)
from hydroservo.models import available_models, load_model
from hydroservo.system import BatchResult, Model, Result, System
from hydroservo.units import to_si, ureg

__version__ = "0.1.0"

__all__ = [
    "System",
    "Model",
    "Result",
    "BatchResult",
    "load_model",
    "available_models",
    "components",
    "fluids",
    "orifices",
    "friction",
    "to_si",
    "ureg",
    "HydroservoError",
    "UnitError",
    "ParameterError",
    "ModelError",
    "ModelFileError",
    "SolverError",
    "TrimError",
]
