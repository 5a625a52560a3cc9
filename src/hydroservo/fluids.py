r"""Hydraulic fluids as property sets: density, viscosity and bulk modulus against pressure and temperature.

* ``skydrol``: the parametric model of [MareAttarND] section 2.1,
  eqs. (1)-(2), with the published Skydrol coefficients. The paper does not
  print its reference state; hydroservo takes :math:`T_0` = 20 degC,
  :math:`p_0` = 0 (atmospheric), :math:`\rho_0` = 1008 kg/m^3 and
  :math:`\nu_0` = 19.39 cSt. Why: the reference temperature is the one free
  choice that moves the model's own temperature ratios (the pressure and
  density terms do not depend on it), and 20 degC puts the kinematic-viscosity
  ratio between -40 and +70 degC at 71, near the paper's 66 (18.6 degC
  would give 66 exactly); :math:`\rho_0` follows from a specific gravity of
  1.004 at 25 degC, typical of Type IV phosphate-ester fluids (Skydrol LD-4
  class); :math:`\nu_0` makes :math:`\nu` = 10.8 cSt at 38 degC (100 degF), the
  typical value of the same class. ``docs/validation.md`` lists which of the
  paper's statements the model meets.
* ``iso-vg32``, ``iso-vg46``: generic mineral hydraulic oils (HM/HV, viscosity
  index about 100): Walther's law through the ISO 3448 mid-points at 40 degC and
  typical values at 100 degC, Barus pressure-viscosity coefficient 2e-8 1/Pa,
  thermal expansion 7e-4 1/K, constant bulk modulus 1.6 GPa, 870/875 kg/m^3 at 15 degC.
* User-defined fluids: :class:`MareFluid` or :class:`MineralOil` with your own values.

The bulk modulus is always the isothermal tangent modulus consistent with the
density model, :math:`K = -v\,(\partial v/\partial p)^{-1}`, which is the paper's
argument for a parametric model.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.errors import FluidRangeWarning, ParameterError
from hydroservo.laws.fluid import (
    SKYDROL_MARE,
    dynamic_viscosity_mare,
    kinematic_viscosity_walther,
    specific_volume_mare,
)
from hydroservo.units import ABSOLUTE_ZERO, VACUUM

__all__ = [
    "Fluid",
    "MareFluid",
    "MineralOil",
    "FLUIDS",
    "get_fluid",
    "FluidRangeWarning",
    "PROPERTIES",
]

#: Properties every fluid provides, with their SI units.
PROPERTIES = {
    "density": "kg/m^3",
    "specific_volume": "m^3/kg",
    "kinematic_viscosity": "m^2/s",
    "dynamic_viscosity": "Pa*s",
    "bulk_modulus": "Pa",
}


#: How far beyond its fitted temperature range a fluid model is extrapolated (with a warning) [K];
#: beyond that it is refused: a polynomial fit says nothing about oil 500 K from its data.
MAX_EXTRAPOLATION = 50.0


@dataclass(frozen=True)
class Fluid:
    """Base class: a named fluid with a range of validity (temperatures in degC, pressures in Pa gauge)."""

    name: str
    description: str
    T_range: tuple[float, float]
    p_range: tuple[float, float]

    def check_range(self, p: Any, T: Any, strict: bool = False) -> None:
        """Refuse states no fluid can be in (non-finite values, temperatures at or below absolute zero,
        pressures below vacuum) and temperatures more than :data:`MAX_EXTRAPOLATION` outside the model's
        range; warn (or, with ``strict``, raise) when (p, T) leaves the validity range."""
        p_arr, T_arr = np.atleast_1d(np.asarray(p, float)), np.atleast_1d(np.asarray(T, float))
        if not (np.all(np.isfinite(p_arr)) and np.all(np.isfinite(T_arr))):
            raise ParameterError(f"fluid {self.name!r}: pressures and temperatures must be finite numbers")
        if np.any(T_arr <= ABSOLUTE_ZERO):
            raise ParameterError(
                f"fluid {self.name!r}: temperature {T_arr.min():g} degC; expected above absolute zero ({ABSOLUTE_ZERO} degC)"
            )
        if np.any(p_arr < VACUUM):
            raise ParameterError(
                f"fluid {self.name!r}: pressure {p_arr.min():g} Pa (gauge); expected at least vacuum ({VACUUM:g} Pa gauge)"
            )
        lo, hi = self.T_range[0] - MAX_EXTRAPOLATION, self.T_range[1] + MAX_EXTRAPOLATION
        if np.any(T_arr < lo) or np.any(T_arr > hi):
            worst = T_arr.min() if T_arr.min() < lo else T_arr.max()
            raise ParameterError(
                f"fluid {self.name!r}: temperature {worst:g} degC is more than {MAX_EXTRAPOLATION:g} K outside the "
                f"range of its model ({self.T_range[0]:g}..{self.T_range[1]:g} degC); expected {lo:g}..{hi:g} degC"
            )
        msgs = []
        if np.any(T_arr < self.T_range[0]) or np.any(T_arr > self.T_range[1]):
            msgs.append(
                f"temperature {T_arr.min():g}..{T_arr.max():g} degC outside {self.T_range[0]:g}..{self.T_range[1]:g} degC"
            )
        if np.any(p_arr < self.p_range[0]) or np.any(p_arr > self.p_range[1]):
            msgs.append(
                f"pressure {p_arr.min() / 1e6:g}..{p_arr.max() / 1e6:g} MPa outside "
                f"{self.p_range[0] / 1e6:g}..{self.p_range[1] / 1e6:g} MPa"
            )
        if msgs:
            text = f"fluid {self.name!r}: {'; '.join(msgs)} (the range its model holds in)"
            if strict:
                raise ParameterError(text)
            warnings.warn(text, FluidRangeWarning, stacklevel=3)

    def specific_volume(self, p: Any, T: Any) -> Any:
        raise NotImplementedError

    def dynamic_viscosity(self, p: Any, T: Any) -> Any:
        raise NotImplementedError

    def dvdp(self, p: Any, T: Any) -> Any:
        """Derivative of the specific volume with respect to pressure [m^3/kg/Pa]."""
        raise NotImplementedError

    def density(self, p: Any, T: Any) -> Any:
        """[kg/m^3]"""
        return 1.0 / self.specific_volume(p, T)

    def kinematic_viscosity(self, p: Any, T: Any) -> Any:
        """[m^2/s]"""
        return self.dynamic_viscosity(p, T) * self.specific_volume(p, T)

    def bulk_modulus(self, p: Any, T: Any) -> Any:
        """Isothermal tangent bulk modulus consistent with the density model, -v/(dv/dp) [Pa]."""
        return -self.specific_volume(p, T) / self.dvdp(p, T)

    def properties(self, p: Any, T: Any, strict: bool = False) -> dict[str, Any]:
        """All properties (SI) at pressures ``p`` [Pa] and temperatures ``T`` [degC], after a range check."""
        self.check_range(p, T, strict)
        return {name: getattr(self, name)(p, T) for name in PROPERTIES}


@dataclass(frozen=True)
class MareFluid(Fluid):
    """A fluid of [MareAttarND] eqs. (1)-(2): specific volume and dynamic viscosity polynomial in (p, T)."""

    v0: float = 1.0 / 1008.0
    mu0: float = 19.39e-6 * 1008.0
    T0: float = 20.0
    p0: float = 0.0
    coefficients: dict[str, float] = field(default_factory=lambda: dict(SKYDROL_MARE))

    def _a(self) -> dict[str, float]:
        return {k: self.coefficients[k] for k in ("a_p", "a_p2", "a_t", "a_t2", "a_pt")}

    def specific_volume(self, p: Any, T: Any) -> Any:
        return specific_volume_mare(p, T, self.v0, self.T0, self.p0, **self._a())

    def dvdp(self, p: Any, T: Any) -> Any:
        c = self.coefficients
        return self.v0 * (c["a_p"] + 2.0 * c["a_p2"] * (p - self.p0) + c["a_pt"] * (T - self.T0))

    def dynamic_viscosity(self, p: Any, T: Any) -> Any:
        c = self.coefficients
        return dynamic_viscosity_mare(p, T, self.mu0, self.T0, self.p0, c["b_p"], c["b_t"], c["b_t2"])


@dataclass(frozen=True)
class MineralOil(Fluid):
    """A mineral oil: Walther viscosity-temperature law, Barus pressure-viscosity, constant bulk modulus.

    :math:`\\rho = \\rho_{15} e^{p/K}/(1 + \\alpha_T (T - 15))`, so the tangent bulk modulus is exactly ``K``.
    """

    nu_40: float = 32e-6
    nu_100: float = 5.4e-6
    rho_15: float = 870.0
    alpha_T: float = 7e-4
    K: float = 1.6e9
    alpha_p: float = 2e-8

    def specific_volume(self, p: Any, T: Any) -> Any:
        return (1.0 + self.alpha_T * (T - 15.0)) * bk.exp(-p / self.K) / self.rho_15

    def dvdp(self, p: Any, T: Any) -> Any:
        return -self.specific_volume(p, T) / self.K

    def dynamic_viscosity(self, p: Any, T: Any) -> Any:
        nu_atm = kinematic_viscosity_walther(T, self.nu_40, self.nu_100)
        return nu_atm / self.specific_volume(0.0, T) * bk.exp(self.alpha_p * p)


def _skydrol() -> MareFluid:
    T0, rho0 = 20.0, 1008.0
    c = SKYDROL_MARE
    # nu0 from nu(38 degC, 0 Pa) = 10.8 cSt through eqs. (1)-(2)
    dT = 38.0 - T0
    mu_ratio = 10.0 ** (c["b_t"] * dT + c["b_t2"] * dT * dT)
    v_ratio = 1.0 + c["a_t"] * dT + c["a_t2"] * dT * dT
    nu0 = 10.8e-6 / (mu_ratio * v_ratio)
    return MareFluid(
        "skydrol",
        "Skydrol (Type IV phosphate ester), [MareAttarND] eqs. (1)-(2); reference 20 degC, 0 Pa, 1008 kg/m^3, "
        f"{nu0 * 1e6:.3g} cSt",
        (-55.0, 100.0),
        (0.0, 40e6),
        v0=1.0 / rho0,
        mu0=nu0 * rho0,
        T0=T0,
    )


#: Built-in fluids by name.
FLUIDS: dict[str, Fluid] = {
    "skydrol": _skydrol(),
    "iso-vg32": MineralOil("iso-vg32", "mineral hydraulic oil ISO VG 32 (VI about 100)", (-20.0, 100.0), (0.0, 40e6)),
    "iso-vg46": MineralOil(
        "iso-vg46",
        "mineral hydraulic oil ISO VG 46 (VI about 100)",
        (-15.0, 100.0),
        (0.0, 40e6),
        nu_40=46e-6,
        nu_100=6.8e-6,
        rho_15=875.0,
    ),
}


def get_fluid(name: str) -> Fluid:
    """A built-in fluid by name (:data:`FLUIDS`)."""
    if name not in FLUIDS:
        raise ParameterError(f"fluid {name!r}: unknown; built-in fluids: {', '.join(FLUIDS)}")
    return FLUIDS[name]
