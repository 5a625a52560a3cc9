"""Fluid laws (hydroservo.laws.fluid): bulk modulus, wave speed, density (Efe2014), the fluid model of MareAttarND.

Each law is checked against its own formula, evaluated here independently: the tolerances are rounding only.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from hydroservo.errors import ParameterError
from hydroservo.laws import fluid as fluids
from hydroservo.laws.fluid import SKYDROL_MARE, dynamic_viscosity_mare, specific_volume_mare

BAR = 1e5


# -- bulk modulus ----------------------------------------------------------------
def test_lee_bulk_modulus_values() -> None:
    # E'(p) = 0.5 * 18000 bar * log10(90 p/280 bar + 3), Efe2014 eq. 3.2 (log restored: docs/validation.md)
    assert fluids.bulk_modulus_lee(0.0) == pytest.approx(0.5 * 18000 * BAR * np.log10(3.0))
    assert fluids.bulk_modulus_lee(280 * BAR) == pytest.approx(0.5 * 18000 * BAR * np.log10(93.0))
    p = np.linspace(0, 300 * BAR, 50)
    assert np.all(np.diff(fluids.bulk_modulus_lee(p)) > 0)


@pytest.mark.parametrize("T", [20.0, 50.0, 90.0])
def test_eggerth_at_table_temperatures(T: float) -> None:
    # Efe2014 eq. 3.3 with the coefficients of its Table 3.1 (EGGERTH_TABLE): rounding only, 1e-14
    k1, k2, lam = fluids.EGGERTH_TABLE[T]
    p = 150 * BAR
    expected = 1.0 / (k1 + k2 * (p / (10 * BAR)) ** (-lam))
    assert fluids.bulk_modulus_eggerth(p, temperature=T) == pytest.approx(expected, rel=1e-14)


def test_eggerth_interpolates_and_refuses_extrapolation() -> None:
    # linear in temperature between the rows of Efe2014 Table 3.1: 35 degC is midway between 20 and 50 degC
    k1, k2, lam = fluids.eggerth_coefficients(35.0)
    (k1_20, _, lam_20), (k1_50, _, lam_50) = fluids.EGGERTH_TABLE[20.0], fluids.EGGERTH_TABLE[50.0]
    assert k1 == pytest.approx((k1_20 + k1_50) / 2)
    assert lam == pytest.approx((lam_20 + lam_50) / 2)
    e = [fluids.bulk_modulus_eggerth(200 * BAR, temperature=T) for T in (20.0, 35.0, 50.0)]
    assert e[0] > e[1] > e[2]  # stiffer when colder (Efe2014 Fig. 3.1)
    with pytest.raises(ParameterError, match="temperature: 120"):
        fluids.eggerth_coefficients(120.0)


def test_wave_speed_and_line_length() -> None:
    # c = sqrt(E/rho) (Efe2014 eq. 3.31); a line may be lumped when l < c/(10 f_max) (eq. 3.30)
    c = fluids.wave_speed(1.6e9, 870.0)
    assert c == pytest.approx(np.sqrt(1.6e9 / 870.0))
    assert fluids.max_line_length(c, 100.0) == pytest.approx(c / 1000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert fluids.check_line_length(0.5, c, 100.0)
    with pytest.warns(UserWarning, match="exceeds c/\\(10 f_max\\)"):
        assert not fluids.check_line_length(2.0, c, 100.0)


def test_density_linear() -> None:
    assert fluids.density_linear(1.5e7, 870.0, 1.5e9) == pytest.approx(870.0 * 1.01)  # Efe2014 eq. 3.15


# -- the fluid model of MareAttarND (eqs. 1-2) ---------------------------------------
def test_equations_1_and_2_at_their_reference_and_one_point() -> None:
    # MareAttarND eqs. 1 (specific volume) and 2 (dynamic viscosity) with the published Skydrol coefficients
    # (SKYDROL_MARE), written out here: rounding only, 1e-14
    assert specific_volume_mare(0.0, 20.0, 1e-3, 20.0) == pytest.approx(1e-3)
    c = SKYDROL_MARE
    dp, dT = 1e7, -30.0
    v = 1e-3 * (1 + c["a_p"] * dp + c["a_p2"] * dp**2 + c["a_t"] * dT + c["a_t2"] * dT**2 + c["a_pt"] * dp * dT)
    assert specific_volume_mare(dp, 20.0 + dT, 1e-3, 20.0) == pytest.approx(v, rel=1e-14)
    mu = 0.02 * 10 ** (c["b_p"] * dp + c["b_t"] * dT + c["b_t2"] * dT**2)
    assert dynamic_viscosity_mare(dp, 20.0 + dT, 0.02, 20.0) == pytest.approx(mu, rel=1e-14)
