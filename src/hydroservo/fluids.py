"""Fluid properties: effective bulk modulus, density, wave speed.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Each cites the seed document and equation it implements.
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from hydroservo import _math as m
from hydroservo.errors import ParameterError

__all__ = [
    "EGGERTH_TABLE",
    "bulk_modulus_lee",
    "bulk_modulus_eggerth",
    "eggerth_coefficients",
    "density_linear",
    "wave_speed",
    "max_line_length",
    "check_line_length",
]

BAR = 1e5

#: Eggerth (1980) coefficients, seed 001 Table 3.1:
#: temperature [degC] -> (k1 [m^2/N], k2 [m^2/N], lambda [-]).
EGGERTH_TABLE: dict[float, tuple[float, float, float]] = {
    20.0: (4.943e-10, 1.9540e-10, 1.480),
    50.0: (5.469e-10, 3.2785e-10, 1.258),
    90.0: (5.762e-10, 4.7750e-10, 1.100),
}


def bulk_modulus_lee(
    p: Any,
    a1: float = 0.5,
    a2: float = 90.0,
    a3: float = 3.0,
    E_max: float = 18000 * BAR,
    p_max: float = 280 * BAR,
) -> Any:
    r"""Effective bulk modulus of a hydraulic cylinder after Lee & Lee (1990).

    .. math:: E'(p) = a_1 E_{max} \log_{10}\left(a_2 \frac{p}{p_{max}} + a_3\right)

    Parameters
    ----------
    p : array_like
        Gauge pressure [Pa]. Values below zero are taken as zero.
    a1, a2, a3 : float
        Fit constants [-]; defaults 0.5, 90, 3 as given with the equation.
    E_max : float
        Bulk modulus of the pure oil [Pa]; default 18000 bar.
    p_max : float
        Maximum pressure [Pa]; default 280 bar.

    Returns
    -------
    Effective bulk modulus [Pa].

    Notes
    -----
    Seed 001 eq. (3.2) prints :math:`a_1 E_{max}(a_2 p/p_{max} + a_3)`: the
    logarithm was lost in the extraction. Without it the formula gives
    1.35e10 Pa at zero pressure, ten times the modulus of pure oil; with the
    decimal logarithm of Jelali & Kroll (2004, eq. 3.8) it rises from
    4.29e8 Pa at 0 bar to 1.772e9 Pa at 280 bar, the expected shape.

    References
    ----------
    Seed 001 (Efe 2014) eq. (3.2); Jelali & Kroll, *Hydraulic Servo-systems*, 2004.

    Examples
    --------
    >>> round(float(bulk_modulus_lee(280e5)) / 1e5)
    17716
    """
    pc = m.fmax(p, 0.0)
    return a1 * E_max * m.log10(a2 * pc / p_max + a3)


def eggerth_coefficients(temperature: Any) -> tuple[Any, Any, Any]:
    """Eggerth coefficients (k1 [m^2/N], k2 [m^2/N], lambda [-]) at ``temperature`` [degC].

    Linear interpolation in temperature between the rows of seed 001
    Table 3.1 (20, 50 and 90 degC). Outside that range the table is not
    extrapolated: a :class:`~hydroservo.errors.ParameterError` is raised (for a
    symbolic temperature the caller's parameter range does that check).
    """
    temps = sorted(EGGERTH_TABLE)
    cols = np.array([EGGERTH_TABLE[T] for T in temps])
    if m.is_symbolic(temperature):
        k1, k2, lam = (m.interp(temperature, temps, cols[:, j]) for j in range(3))
        return k1, k2, lam
    if not (temps[0] <= temperature <= temps[-1]):
        raise ParameterError(
            f"temperature: {temperature} degC is outside Eggerth's table; "
            f"expected {temps[0]:g} to {temps[-1]:g} degC (seed 001 Table 3.1)"
        )
    k1, k2, lam = (float(np.interp(temperature, temps, cols[:, j])) for j in range(3))
    return k1, k2, lam


def bulk_modulus_eggerth(
    p: Any,
    temperature: Any = 50.0,
    p0: float = 10 * BAR,
    p_min: float = 1 * BAR,
) -> Any:
    r"""Effective bulk modulus after Eggerth (1980).

    .. math:: E'(p) = \frac{1}{k_1 + k_2 (p/p_0)^{-\lambda}}

    Parameters
    ----------
    p : array_like
        Gauge pressure [Pa].
    temperature : float
        Oil temperature [degC], 20 to 90; the coefficients of Table 3.1 are
        interpolated linearly in temperature.
    p0 : float
        Reference pressure [Pa]; 10 bar as in the seed.
    p_min : float
        Pressure below which ``p`` is clipped [Pa]. The formula gives
        :math:`E' \to 0` as :math:`p \to 0`, which makes chamber pressure
        derivatives unbounded; 1 bar (``p0/10``) is the lower end of the
        pressures for which such fits are made.

    Returns
    -------
    Effective bulk modulus [Pa].

    References
    ----------
    Seed 001 (Efe 2014) eq. (3.3) and Table 3.1.

    Examples
    --------
    >>> round(float(bulk_modulus_eggerth(100e5, temperature=20.0)) / 1e9, 3)
    1.997
    """
    k1, k2, lam = eggerth_coefficients(temperature)
    pc = m.fmax(p, p_min)
    return 1.0 / (k1 + k2 * (pc / p0) ** (-lam))


def density_linear(p: Any, rho0: float, E: Any) -> Any:
    r"""Density of a slightly compressible fluid at constant temperature.

    .. math:: \rho = \rho_i + \frac{\rho_i}{E} p

    Parameters
    ----------
    p : array_like
        Gauge pressure [Pa].
    rho0 : float
        Density at zero gauge pressure [kg/m^3].
    E : array_like
        Bulk modulus [Pa].

    References
    ----------
    Seed 001 eq. (3.15).
    """
    return rho0 * (1.0 + p / E)


def wave_speed(E: Any, rho: Any) -> Any:
    r"""Speed of pressure waves in a rigid line, :math:`c = \sqrt{E/\rho}` [m/s].

    Parameters
    ----------
    E : array_like
        (Effective) bulk modulus [Pa].
    rho : array_like
        Density [kg/m^3].

    References
    ----------
    Seed 001 eq. (3.31), after Goodson & Leonard (1972).

    Examples
    --------
    >>> round(float(wave_speed(1.5e9, 870.0)))
    1313
    """
    return m.sqrt(E / rho)


def max_line_length(c: float, f_max: float) -> float:
    r"""Longest line that may be lumped into a chamber volume, :math:`l < c/(10 f_{max})` [m].

    Parameters
    ----------
    c : float
        Wave speed [m/s].
    f_max : float
        Highest frequency of interest [Hz].

    References
    ----------
    Seed 001 eq. (3.30), after Jelali & Kroll (2004).
    """
    if f_max <= 0:
        raise ParameterError(f"f_max: {f_max} Hz; expected a positive frequency")
    return c / (10.0 * f_max)


def check_line_length(length: float, c: float, f_max: float) -> bool:
    """Warn if a line of ``length`` [m] is too long to be a lumped volume.

    Returns True when the line satisfies seed 001 eq. (3.30), False (with a
    :class:`UserWarning`) when a distributed line model would be needed.
    """
    limit = max_line_length(c, f_max)
    if length >= limit:
        warnings.warn(
            f"line length {length:g} m exceeds c/(10 f_max) = {limit:.3g} m "
            f"(c = {c:.4g} m/s, f_max = {f_max:g} Hz, seed 001 eq. 3.30): "
            "it cannot be lumped into the chamber volume",
            UserWarning,
            stacklevel=2,
        )
        return False
    return True
