"""The Skydrol fluid model against the statements of [MareAttarND] section 2.1 (from SAE AIR1362 [SAEAIR1362]).

The fluid is the package's ``skydrol`` (:mod:`hydroservo.fluids`): eqs. (1)-(2)
with the published coefficients and hydroservo's reference state (the paper
prints none).
"""

from __future__ import annotations

from hydroservo.fluids import get_fluid
from hydroservo.validation import Row

__all__ = ["rows", "compute"]

_SRC = "MareAttarND section 2.1"


def rows() -> list[Row]:
    """The three statements on Skydrol."""
    return [
        Row(
            "nu_ratio",
            "kinematic viscosity -40 -> +70 degC at 0 MPa, divided by",
            _SRC,
            66.0,
            "-",
            0.5,
            "'reduced by 66 times', printed to two figures. The paper does not print its reference state; only the "
            "reference temperature moves this ratio: hydroservo's 20 degC gives 70.7, 18.6 degC would give 66",
            "ratio of the model's kinematic viscosities at -40 and +70 degC, 0 MPa",
            "NOT reproduced",
        ),
        Row(
            "density_drop",
            "density decrease -40 -> +70 degC at 0 MPa",
            _SRC,
            8.5,
            "%",
            0.24,
            "the paper's eq. 1 is within 0.12 % of the density it summarises (section 2.1), so a drop between two "
            "temperatures within 0.24 percentage points",
            "1 - density(+70 degC)/density(-40 degC), 0 MPa",
            "reproduced",
        ),
        Row(
            "viscosity_30MPa",
            "viscosity increase 0 -> 30 MPa at 10 degC, factor",
            _SRC,
            2.0,
            "-",
            0.6,
            "the paper reports its viscosity model up to 30 % from the SAE data at 0 MPa and 10 degC, and blames "
            "their inconsistency. Eq. 2's b_p = 4.45e-9 1/Pa gives 10^0.1335 = 1.36 (dynamic) whatever the "
            "reference state; doubling would need b_p = 1.0e-8",
            "kinematic viscosity at 30 MPa over that at 0 MPa, 10 degC",
            "NOT reproduced",
        ),
    ]


def compute() -> dict[str, float]:
    """The model's values of the three statements."""
    sk = get_fluid("skydrol")
    return {
        "nu_ratio": float(sk.kinematic_viscosity(0.0, -40.0) / sk.kinematic_viscosity(0.0, 70.0)),
        "density_drop": float(1 - sk.density(0.0, 70.0) / sk.density(0.0, -40.0)) * 100.0,
        "viscosity_30MPa": float(sk.kinematic_viscosity(30e6, 10.0) / sk.kinematic_viscosity(0.0, 10.0)),
    }
