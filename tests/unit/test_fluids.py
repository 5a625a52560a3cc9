"""The built-in fluids (hydroservo.fluids): consistency, grades, range warnings."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from hydroservo.errors import FluidRangeWarning, ParameterError
from hydroservo.fluids import FLUIDS, get_fluid


@pytest.mark.parametrize("name", list(FLUIDS))
def test_bulk_modulus_is_consistent_with_the_density_model(name: str) -> None:
    fluid = get_fluid(name)
    p, T, h = 1e7, 30.0, 1e3
    dvdp = (fluid.specific_volume(p + h, T) - fluid.specific_volume(p - h, T)) / (2 * h)
    assert fluid.bulk_modulus(p, T) == pytest.approx(-fluid.specific_volume(p, T) / dvdp, rel=1e-6)
    assert fluid.kinematic_viscosity(p, T) == pytest.approx(fluid.dynamic_viscosity(p, T) / fluid.density(p, T))


def test_mineral_oils_meet_their_grade() -> None:
    # an ISO VG grade is the kinematic viscosity at 40 degC in cSt (ISO 3448): the model passes through it (1e-9);
    # 1.6 GPa is hydroservo's bulk modulus of a mineral oil (hydroservo.fluids), not a published figure
    for name, nu40 in (("iso-vg32", 32e-6), ("iso-vg46", 46e-6)):
        oil = get_fluid(name)
        assert oil.kinematic_viscosity(0.0, 40.0) == pytest.approx(nu40, rel=1e-9)
        assert oil.kinematic_viscosity(0.0, 0.0) > 5 * nu40  # cold oil: several times thicker
        assert oil.bulk_modulus(0.0, 40.0) == pytest.approx(1.6e9)


def test_range_warnings_and_refusal() -> None:
    sky = get_fluid("skydrol")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sky.properties(np.array([0.0, 3e7]), np.array([-40.0, 70.0]))  # inside: no warning
    with pytest.warns(FluidRangeWarning, match="temperature"):
        sky.properties(0.0, -70.0)
    with pytest.raises(ParameterError, match="outside -55..100 degC"):
        sky.properties(0.0, 150.0, strict=True)
    with pytest.raises(ParameterError, match="unknown; built-in fluids"):
        get_fluid("water")
