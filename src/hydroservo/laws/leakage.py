r"""Leakage through closed spool orifices: the laws of earlier authors that [MareAttarND] reviews (eqs. 7-11).

Each models the flow through an overlapped (closed) metering edge; the unified
model that [MareAttarND] proposes instead, continuous through null, is
:func:`hydroservo.laws.staged_slot.discharge_coefficient`. Pure, vectorised
NumPy functions, SI units. Citation keys in brackets are those of
:mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["ellman_flow", "eryilmaz_flow", "laminar_gap_flow", "laminar_gap_continuity", "annulus_conductance"]


def ellman_flow(X: Any, dp: Any, k1: Any, k2: Any) -> Any:
    r"""Closed-orifice leakage of [Ellman1995] and [Ellman1998], [MareAttarND] eq. (7) [m^3/s].

    .. math:: Q = \frac{k_2}{2}\left[\sqrt{(k_2/k_1)^2X^2 + 4\Delta P} - \frac{k_2}{k_1}X\right]

    The passage is a short annulus in laminar flow; the two parameters are
    fitted at one temperature (a MOOG D631-236 servovalve in the original work).

    Parameters
    ----------
    X : array_like
        Spool position variable of [MareAttarND] eq. (7) [m], as printed there.
        For large positive ``X`` the flow tends to :math:`k_1\Delta P/X`, the
        laminar annulus of length ``X``: positive ``X`` acts as the closure.
    dp : array_like
        Pressure drop across the orifice [Pa], >= 0.
    k1 : array_like
        Fitted coefficient [m^4/(s Pa)].
    k2 : array_like
        Fitted coefficient [m^3/(s Pa^0.5)]: at ``X = 0``, :math:`Q = k_2\sqrt{\Delta P}`.

    Returns
    -------
    array_like
        Leakage flow [m^3/s].

    References
    ----------
    [MareAttarND] eq. (7), after [Ellman1995], [Ellman1998].

    Examples
    --------
    At zero opening the leakage is :math:`k_2\sqrt{\Delta P}`:

    >>> round(float(ellman_flow(0.0, 4e6, 1.0, 1e-9)), 12)
    2e-06
    """
    a = k2 / k1
    return 0.5 * k2 * (np.sqrt(a * a * np.asarray(X) ** 2 + 4.0 * np.asarray(dp)) - a * np.asarray(X))


def eryilmaz_flow(X: Any, dp: Any, X0: Any, k1: Any, k2: Any) -> Any:
    r"""Closed-orifice leakage of [Eryilmaz2000], [MareAttarND] eq. (8) [m^3/s].

    .. math:: Q = k_1\sqrt{\Delta P}\,\frac{X_0^2}{X_0 - k_2X}

    Turbulent, inversely proportional to the closure; fitted at one
    temperature (a Moog 760-723A servovalve in the original work).

    Parameters
    ----------
    X : array_like
        Spool position variable of [MareAttarND] eq. (8) [m], as printed there.
        For large negative ``X`` (with ``k2 > 0``) the flow falls as
        :math:`1/|X|`: negative ``X`` acts as the closure.
    dp : array_like
        Pressure drop across the orifice [Pa], >= 0.
    X0 : array_like
        Reference length [m].
    k1 : array_like
        Fitted coefficient [m^2/(s Pa^0.5)] (:math:`k_1X_0` is the flow per
        :math:`\sqrt{\Delta P}` at ``X = 0``).
    k2 : array_like
        Fitted coefficient [-].

    Returns
    -------
    array_like
        Leakage flow [m^3/s].

    References
    ----------
    [MareAttarND] eq. (8), after [Eryilmaz2000].

    Examples
    --------
    At zero opening the leakage is :math:`k_1X_0\sqrt{\Delta P}`:

    >>> round(float(eryilmaz_flow(0.0, 4e6, 1e-6, 1e-9, 0.5)), 18)
    2e-12
    """
    return k1 * np.sqrt(np.asarray(dp)) * X0**2 / (X0 - k2 * np.asarray(X))


def laminar_gap_flow(X: Any, dp: Any, mu: Any, n: Any, w: Any, c: Any, K_g: Any) -> Any:
    r"""Closed orifice as a laminar gap between infinite planes after [Rabie1981], [MareAttarND] eq. (10) [m^3/s].

    .. math:: Q = \frac{nwc^3}{12\mu(K_g + |X|)}\Delta P

    Parameters
    ----------
    X : array_like
        Valve opening [m] (the closure is :math:`|X|`).
    dp : array_like
        Pressure drop across the orifice [Pa].
    mu : array_like
        Dynamic viscosity [Pa s].
    n : array_like
        Number of slots [-].
    w : array_like
        Slot width [m].
    c : array_like
        Spool-bushing radial clearance [m].
    K_g : array_like
        Length ensuring continuity with the open law [m]
        (:func:`laminar_gap_continuity`, eq. 11).

    Returns
    -------
    array_like
        Leakage flow [m^3/s].

    References
    ----------
    [MareAttarND] eqs. (9)-(10), after [Rabie1981].

    Examples
    --------
    Two 4 mm slots, 1.5 um clearance, 100 bar, at zero opening (:math:`|X| = 0`):

    >>> q = laminar_gap_flow(0.0, 10e6, 1e-2, 2, 4e-3, 1.5e-6, 1e-5)
    >>> round(float(q) * 6e4, 4)  # L/min
    0.0135
    """
    return n * w * c**3 / (12.0 * mu * (K_g + np.abs(np.asarray(X)))) * np.asarray(dp)


def laminar_gap_continuity(w: Any, c: Any, delta_lambda: Any) -> Any:
    r"""Continuity constant of the laminar-gap law, [MareAttarND] eq. (11) [m].

    .. math:: K_g = \frac{c(w + c)}{48\delta_\lambda w}

    with :math:`\delta_\lambda` the limit slope of :math:`C_q(\lambda)` at small
    flow numbers (for eq. 6: :math:`C_{q\infty}/\lambda_t`).

    Parameters
    ----------
    w : array_like
        Slot width [m].
    c : array_like
        Spool-bushing radial clearance [m].
    delta_lambda : array_like
        Limit slope of :math:`C_q(\lambda)` [-].

    Returns
    -------
    array_like
        :math:`K_g` [m].

    References
    ----------
    [MareAttarND] eq. (11).

    Examples
    --------
    A 4 mm slot, 1.5 um clearance, :math:`C_{q\infty} = 0.65`, :math:`\lambda_t = 8`:

    >>> round(float(laminar_gap_continuity(4e-3, 1.5e-6, 0.65 / 8.0)) * 1e6, 4)  # um
    0.3848
    """
    return c * (w + c) / (48.0 * delta_lambda * w)


def annulus_conductance(d: Any, delta: Any, e: Any, eta: Any, length: Any) -> Any:
    r"""Laminar conductance of the clearance between a spool land and its bore, eccentric, [m^3/s/Pa].

    .. math:: G = \frac{\pi d\,\delta^3}{12\,\eta\,l}\left(1 + \frac{3}{2}\left(\frac{e}{\delta}\right)^2\right)

    the leakage :math:`Q = G\,\Delta p` of an annulus of diameter :math:`d`,
    radial clearance :math:`\delta` and length :math:`l` whose spool sits
    :math:`e` off centre (concentric: :math:`e = 0`; touching: :math:`e =
    \delta`, 2.5 times the concentric flow).

    Parameters
    ----------
    d : array_like
        Spool diameter [m].
    delta : array_like
        Radial clearance [m].
    e : array_like
        Eccentricity [m].
    eta : array_like
        Dynamic viscosity [Pa*s].
    length : array_like
        Length of the land [m].

    Returns
    -------
    array_like
        :math:`G` [m^3/s/Pa].

    References
    ----------
    [GordicND] eqs. (20)-(21), the leakage past the spool's end lands; [Merritt1967] (eccentric annulus).

    Examples
    --------
    Table 1's spool end land (4.62 mm, 4 um, 1 um off centre, 4.9 mm, 0.012 Pa s) at 100 bar, in mm^3/s:

    >>> round(float(annulus_conductance(4.62e-3, 4e-6, 1e-6, 0.012, 4.9e-3) * 100e5) * 1e9, 2)
    14.4
    """
    return np.pi * d * delta**3 / (12.0 * eta * length) * (1.0 + 1.5 * (e / delta) ** 2)
