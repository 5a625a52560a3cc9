r"""Hydraulic lines as lumped segments: capacitance, inertance and laminar resistance per segment.

A line of length :math:`l` and inner diameter :math:`d` cut into :math:`n`
segments has, per segment of length :math:`l/n`, the capacitance of its oil
volume, the inertance of its oil column and the laminar (Hagen-Poiseuille)
resistance of its wall friction:

.. math::
    C = \frac{\pi d^2 l}{4 n E}, \qquad L = \frac{\rho\, l/n}{\pi d^2/4}, \qquad
    R = \frac{128 \mu\, l/n}{\pi d^4}

Pressure waves travel at :math:`c = \sqrt{E/\rho}`
(:func:`hydroservo.laws.fluid.wave_speed`). A segment behaves as a lumped
volume for frequencies below :math:`c/(10\,l/n)`: the criterion of [Efe2014]
eq. (3.30) (:func:`hydroservo.laws.fluid.max_line_length`) applied to one
segment, so :func:`segments_needed` segments resolve the waves of a long line up
to the highest frequency of interest.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.laws.fluid import max_line_length

__all__ = ["line_area", "segment_capacitance", "segment_inertance", "segment_resistance", "segments_needed"]


def line_area(d: Any) -> Any:
    r"""Flow area of a line of inner diameter ``d``, :math:`\pi d^2/4` [m^2].

    Parameters
    ----------
    d : array_like
        Inner diameter [m].

    Returns
    -------
    array_like
        Area [m^2].

    References
    ----------
    [Merritt1967] (fluid flow fundamentals: flow in a circular passage).

    Examples
    --------
    >>> round(float(line_area(0.01)) * 1e6, 3)  # mm^2
    78.54
    """
    return np.pi * d**2 / 4.0


def segment_capacitance(length: Any, d: Any, E: Any, n: int = 1) -> Any:
    r"""Hydraulic capacitance of one of ``n`` segments, :math:`C = V/E` with :math:`V = \pi d^2 l/(4n)` [m^3/Pa].

    Parameters
    ----------
    length : array_like
        Line length [m].
    d : array_like
        Inner diameter [m].
    E : array_like
        Effective bulk modulus of oil and wall [Pa].
    n : int
        Number of segments [-].

    Returns
    -------
    array_like
        Capacitance [m^3/Pa].

    References
    ----------
    [Efe2014] eq. (3.17) (pressure build-up, :func:`hydroservo.laws.chamber.pressure_rate`) for the
    segment's volume; [JelaliKroll2004] (lumped line volumes, as cited by [Efe2014]).

    Examples
    --------
    >>> round(float(segment_capacitance(2.0, 0.01, 1.5e9)) * 1e15, 1)  # mm^3/Pa
    104.7
    """
    return line_area(d) * length / (n * E)


def segment_inertance(length: Any, d: Any, rho: Any, n: int = 1) -> Any:
    r"""Hydraulic inertance of one of ``n`` segments, :math:`L = \rho (l/n)/A` [Pa s^2/m^3].

    The pressure difference that accelerates the oil column:
    :math:`\Delta p = L\,\dot Q`.

    Parameters
    ----------
    length : array_like
        Line length [m].
    d : array_like
        Inner diameter [m].
    rho : array_like
        Density [kg/m^3].
    n : int
        Number of segments [-].

    Returns
    -------
    array_like
        Inertance [Pa s^2/m^3].

    References
    ----------
    [Merritt1967] (fluid flow fundamentals: the momentum of an incompressible oil column).

    Examples
    --------
    >>> round(float(segment_inertance(2.0, 0.01, 870.0)) / 1e6, 2)  # MPa s^2/m^3
    22.15
    """
    return rho * length / (n * line_area(d))


def segment_resistance(length: Any, d: Any, mu: Any, n: int = 1) -> Any:
    r"""Laminar resistance of one of ``n`` segments (Hagen-Poiseuille), :math:`R = 128 \mu (l/n)/(\pi d^4)` [Pa s/m^3].

    Steady laminar friction, :math:`\Delta p = R\,Q`; valid below a Reynolds
    number of about 2300. The frequency dependence of friction in unsteady
    flow is not modelled.

    Parameters
    ----------
    length : array_like
        Line length [m].
    d : array_like
        Inner diameter [m].
    mu : array_like
        Dynamic viscosity [Pa s].
    n : int
        Number of segments [-].

    Returns
    -------
    array_like
        Resistance [Pa s/m^3].

    References
    ----------
    [Merritt1967] (fluid flow fundamentals: laminar flow in a circular passage, Hagen-Poiseuille).

    Examples
    --------
    A 2 m line of 10 mm bore with oil of 0.03 Pa s loses 0.81 bar at 20 L/min:

    >>> R = segment_resistance(2.0, 0.01, 0.03)
    >>> round(float(R) * 20 / 6e4 / 1e5, 2)
    0.81
    """
    return 128.0 * mu * length / (n * np.pi * d**4)


def segments_needed(length: float, c: float, f_max: float) -> int:
    r"""Fewest segments for which each is shorter than :math:`c/(10 f_{max})`.

    Parameters
    ----------
    length : float
        Line length [m].
    c : float
        Wave speed [m/s] (:func:`hydroservo.laws.fluid.wave_speed`).
    f_max : float
        Highest frequency of interest [Hz].

    Returns
    -------
    int
        Number of segments, at least 1.

    Raises
    ------
    ParameterError
        A length or a wave speed that is not positive and finite.

    References
    ----------
    [Efe2014] eq. (3.30), applied to each segment.

    Examples
    --------
    A 10 m line, waves at 1313 m/s, frequencies up to 50 Hz:

    >>> segments_needed(10.0, 1313.0, 50.0)
    4
    """
    for name, val in (("length", length), ("c", c)):
        if not (math.isfinite(val) and val > 0):
            raise ParameterError(f"{name}: {val!r}; expected a positive finite value")
    return max(1, math.ceil(length / max_line_length(c, f_max) - 1e-12))
