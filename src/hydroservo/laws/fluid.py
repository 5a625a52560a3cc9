"""Fluid properties: effective bulk modulus, density, wave speed.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Each cites the source and equation it implements; citation keys in brackets are those of
:mod:`hydroservo.references`.
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from hydroservo import backend as bk
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
    "SKYDROL_MARE",
    "specific_volume_mare",
    "dynamic_viscosity_mare",
    "kinematic_viscosity_walther",
]

BAR = 1e5

#: Coefficients of [Eggerth1980], [Efe2014] Table 3.1:
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
    r"""Effective bulk modulus of a hydraulic cylinder after [LeeLee1990], [Efe2014] eq. (3.2).

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
    [Efe2014] eq. (3.2) prints :math:`a_1 E_{max}(a_2 p/p_{max} + a_3)`: the
    logarithm was lost in the extraction (hydroservo's reading). Without it the
    formula gives 1.35e10 Pa at zero pressure, ten times the modulus of pure
    oil, growing without bound; with a decimal logarithm (the form found in
    the literature Efe draws on, e.g. [JelaliKroll2004], which the sources at
    hand do not print) it rises from 4.29e8 Pa at 0 bar to 1.772e9 Pa at
    280 bar, the shape of an effective bulk modulus.

    References
    ----------
    [Efe2014] eq. (3.2), after [LeeLee1990]; the logarithm: [JelaliKroll2004].

    Examples
    --------
    >>> round(float(bulk_modulus_lee(280e5)) / 1e5)
    17716
    """
    pc = bk.fmax(p, 0.0)
    return a1 * E_max * bk.log10(a2 * pc / p_max + a3)


def eggerth_coefficients(temperature: Any) -> tuple[Any, Any, Any]:
    r"""Eggerth coefficients (k1 [m^2/N], k2 [m^2/N], lambda [-]) at ``temperature`` [degC].

    Linear interpolation in temperature between the rows of [Efe2014]
    Table 3.1 (20, 50 and 90 degC). Outside that range the table is not
    extrapolated: a :class:`~hydroservo.errors.ParameterError` is raised (for a
    symbolic temperature the caller's parameter range does that check).

    Parameters
    ----------
    temperature : float or CasADi expression
        Oil temperature [degC], 20 to 90.

    Returns
    -------
    (k1, k2, lam) : tuple
        The coefficients :math:`k_1` [m^2/N] and :math:`k_2` [m^2/N] and the
        exponent :math:`\lambda` [-] of :func:`bulk_modulus_eggerth`.

    Raises
    ------
    ParameterError
        A numeric temperature outside 20 to 90 degC.

    References
    ----------
    [Efe2014] Table 3.1, after [Eggerth1980].

    Examples
    --------
    Halfway between the 20 and 50 degC rows:

    >>> eggerth_coefficients(35.0)
    (5.206e-10, 2.61625e-10, 1.369)
    """
    temps = sorted(EGGERTH_TABLE)
    cols = np.array([EGGERTH_TABLE[T] for T in temps])
    if bk.is_symbolic(temperature):
        k1, k2, lam = (bk.interp(temperature, temps, cols[:, j]) for j in range(3))
        return k1, k2, lam
    if not (temps[0] <= temperature <= temps[-1]):
        raise ParameterError(
            f"temperature: {temperature} degC is outside Eggerth's table; "
            f"expected {temps[0]:g} to {temps[-1]:g} degC ([Efe2014] Table 3.1)"
        )
    k1, k2, lam = (float(np.interp(temperature, temps, cols[:, j])) for j in range(3))
    return k1, k2, lam


def bulk_modulus_eggerth(
    p: Any,
    temperature: Any = 50.0,
    p0: float = 10 * BAR,
    p_min: float = 1 * BAR,
) -> Any:
    r"""Effective bulk modulus after [Eggerth1980], [Efe2014] eq. (3.3).

    .. math:: E'(p) = \frac{1}{k_1 + k_2 (p/p_0)^{-\lambda}}

    Parameters
    ----------
    p : array_like
        Gauge pressure [Pa].
    temperature : float
        Oil temperature [degC], 20 to 90; the coefficients of Table 3.1 are
        interpolated linearly in temperature.
    p0 : float
        Reference pressure [Pa]; 10 bar as in [Efe2014].
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
    [Efe2014] eq. (3.3) and Table 3.1, after [Eggerth1980].

    Examples
    --------
    >>> round(float(bulk_modulus_eggerth(100e5, temperature=20.0)) / 1e9, 3)
    1.997
    """
    k1, k2, lam = eggerth_coefficients(temperature)
    pc = bk.fmax(p, p_min)
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

    Returns
    -------
    array_like
        Density [kg/m^3].

    References
    ----------
    [Efe2014] eq. (3.15).

    Examples
    --------
    A mineral oil of 870 kg/m^3 and 1.5 GPa at 150 bar is 1 % denser:

    >>> round(float(density_linear(150e5, 870.0, 1.5e9)), 1)
    878.7
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

    Returns
    -------
    array_like
        Wave speed [m/s].

    References
    ----------
    [Efe2014] eq. (3.31), after [GoodsonLeonard1972].

    Examples
    --------
    >>> round(float(wave_speed(1.5e9, 870.0)))
    1313
    """
    return bk.sqrt(E / rho)


def max_line_length(c: float, f_max: float) -> float:
    r"""Longest line that may be lumped into a chamber volume, :math:`l < c/(10 f_{max})` [m].

    Parameters
    ----------
    c : float
        Wave speed [m/s].
    f_max : float
        Highest frequency of interest [Hz], > 0.

    Returns
    -------
    float
        Length limit [m].

    Raises
    ------
    ParameterError
        ``f_max`` not positive.

    References
    ----------
    [Efe2014] eq. (3.30), after [JelaliKroll2004].

    Examples
    --------
    Waves at 1313 m/s and frequencies up to 100 Hz:

    >>> max_line_length(1313.0, 100.0)
    1.313
    """
    if f_max <= 0:
        raise ParameterError(f"f_max: {f_max} Hz; expected a positive frequency")
    return c / (10.0 * f_max)


def check_line_length(length: float, c: float, f_max: float) -> bool:
    """Warn if a line of ``length`` [m] is too long to be a lumped volume.

    Parameters
    ----------
    length : float
        Line length [m].
    c : float
        Wave speed [m/s] (:func:`wave_speed`).
    f_max : float
        Highest frequency of interest [Hz], > 0.

    Returns
    -------
    bool
        True when the line satisfies [Efe2014] eq. (3.30), False (with a
        :class:`UserWarning`) when a distributed line model would be needed.

    Warns
    -----
    UserWarning
        ``length`` is not below :func:`max_line_length`.

    References
    ----------
    [Efe2014] eq. (3.30), after [JelaliKroll2004].

    Examples
    --------
    >>> check_line_length(0.5, 1313.0, 100.0)
    True
    """
    limit = max_line_length(c, f_max)
    if length >= limit:
        warnings.warn(
            f"line length {length:g} m exceeds c/(10 f_max) = {limit:.3g} m "
            f"(c = {c:.4g} m/s, f_max = {f_max:g} Hz, [Efe2014] eq. 3.30): "
            "it cannot be lumped into the chamber volume",
            UserWarning,
            stacklevel=2,
        )
        return False
    return True


#: Skydrol coefficients of [MareAttarND] section 2.1, eqs. (1)-(2): pressures in Pa, temperatures in degC.
SKYDROL_MARE = {
    "a_p": -7.33e-10,
    "a_p2": 3.22e-18,
    "a_t": 8.02e-4,
    "a_t2": 6.22e-7,
    "a_pt": -5.44e-12,
    "b_p": 4.45e-9,
    "b_t": -1.62e-2,
    "b_t2": 9.62e-5,
}


def specific_volume_mare(
    p: Any,
    T: Any,
    v0: Any,
    T0: Any,
    p0: Any = 0.0,
    a_p: Any = SKYDROL_MARE["a_p"],
    a_p2: Any = SKYDROL_MARE["a_p2"],
    a_t: Any = SKYDROL_MARE["a_t"],
    a_t2: Any = SKYDROL_MARE["a_t2"],
    a_pt: Any = SKYDROL_MARE["a_pt"],
) -> Any:
    r"""Specific volume against pressure and temperature, [MareAttarND] eq. (1) [m^3/kg].

    .. math:: v = v_0(1 + a_p\Delta P + a_{p2}\Delta P^2 + a_t\Delta T + a_{t2}\Delta T^2 + a_{pt}\Delta P\Delta T)

    with :math:`\Delta P = p - p_0`, :math:`\Delta T = T - T_0`. Defaults: the
    Skydrol coefficients of section 2.1 (:data:`SKYDROL_MARE`).

    Parameters
    ----------
    p : array_like
        Pressure [Pa] (gauge, as the reference ``p0``).
    T : array_like
        Temperature [degC].
    v0 : array_like
        Specific volume at the reference state [m^3/kg].
    T0 : array_like
        Reference temperature [degC].
    p0 : array_like
        Reference pressure [Pa].
    a_p, a_p2, a_t, a_t2, a_pt : array_like
        Coefficients [1/Pa], [1/Pa^2], [1/degC], [1/degC^2], [1/(Pa degC)].

    Returns
    -------
    array_like
        Specific volume [m^3/kg].

    References
    ----------
    [MareAttarND] eq. (1) and section 2.1; the Skydrol data: [SAEAIR1362].

    Examples
    --------
    The density drop of Skydrol from -40 to +70 degC at atmospheric pressure,
    8.5 % in [MareAttarND] section 2.1 (reference state at 20 degC):

    >>> v = [specific_volume_mare(0.0, T, 1e-3, 20.0) for T in (-40.0, 70.0)]
    >>> round(float(1 - v[0] / v[1]) * 100, 1)  # percent
    8.4
    """
    dp, dT = p - p0, T - T0
    return v0 * (1.0 + a_p * dp + a_p2 * dp * dp + a_t * dT + a_t2 * dT * dT + a_pt * dp * dT)


def dynamic_viscosity_mare(
    p: Any,
    T: Any,
    mu0: Any,
    T0: Any,
    p0: Any = 0.0,
    b_p: Any = SKYDROL_MARE["b_p"],
    b_t: Any = SKYDROL_MARE["b_t"],
    b_t2: Any = SKYDROL_MARE["b_t2"],
) -> Any:
    r"""Dynamic viscosity against pressure and temperature, [MareAttarND] eq. (2) [Pa s].

    .. math:: \mu = \mu_0\,10^{\,b_p\Delta P + b_t\Delta T + b_{t2}\Delta T^2}

    Parameters
    ----------
    p : array_like
        Pressure [Pa].
    T : array_like
        Temperature [degC].
    mu0 : array_like
        Dynamic viscosity at the reference state [Pa s].
    T0, p0 : array_like
        Reference temperature [degC] and pressure [Pa].
    b_p, b_t, b_t2 : array_like
        Coefficients [1/Pa], [1/degC], [1/degC^2] (default: Skydrol, :data:`SKYDROL_MARE`).

    Returns
    -------
    array_like
        Dynamic viscosity [Pa s].

    References
    ----------
    [MareAttarND] eq. (2) and section 2.1; the Skydrol data: [SAEAIR1362].

    Examples
    --------
    From 0 to 30 MPa the published :math:`b_p` raises the viscosity by 10^0.1335
    at any temperature; [MareAttarND] section 2.1 states that at 10 degC it
    doubles (see :mod:`hydroservo.validation.mare_attar`):

    >>> mu = [dynamic_viscosity_mare(p, 10.0, 1e-2, 20.0) for p in (0.0, 30e6)]
    >>> round(float(mu[1] / mu[0]), 2)
    1.36
    """
    dT = T - T0
    return mu0 * 10.0 ** (b_p * (p - p0) + b_t * dT + b_t2 * dT * dT)


def kinematic_viscosity_walther(T: Any, nu_40: float, nu_100: float) -> Any:
    r"""Kinematic viscosity of a mineral oil against temperature, Walther's law [ASTMD341] [m^2/s].

    .. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B\log_{10}(T + 273.15)

    with :math:`\nu` in cSt and :math:`A, B` through the two catalogue points
    :math:`\nu_{40}` and :math:`\nu_{100}` (the ISO viscosity grades of [ISO3448] are rated at 40 degC).
    Valid above about 2 cSt.

    Parameters
    ----------
    T : array_like
        Temperature [degC].
    nu_40, nu_100 : float
        Kinematic viscosity at 40 and 100 degC [m^2/s].

    Returns
    -------
    array_like
        Kinematic viscosity [m^2/s].

    References
    ----------
    [ASTMD341]; viscosity grades: [ISO3448].

    Examples
    --------
    >>> round(float(kinematic_viscosity_walther(40.0, 32e-6, 5.4e-6)) * 1e6, 6)
    32.0
    """
    t1, t2 = np.log10(313.15), np.log10(373.15)
    w1, w2 = np.log10(np.log10(nu_40 * 1e6 + 0.7)), np.log10(np.log10(nu_100 * 1e6 + 0.7))
    B = (w1 - w2) / (t2 - t1)
    A = w1 + B * t1
    return (10.0 ** (10.0 ** (A - B * bk.log10(T + 273.15))) - 0.7) * 1e-6
