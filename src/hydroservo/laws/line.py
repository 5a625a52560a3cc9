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

from hydroservo import backend as bk
from hydroservo.errors import ParameterError
from hydroservo.laws.fluid import max_line_length

__all__ = [
    "line_area",
    "segment_capacitance",
    "segment_inertance",
    "segment_resistance",
    "segments_needed",
    "wave_line_elements",
    "wall_bypass_inertance",
    "RE_CRIT",
    "critical_flow",
    "friction_drop",
]

#: Reynolds number above which the flow in a line is turbulent (Blasius' friction), below which laminar
RE_CRIT = 2300.0


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


def wave_line_elements(Z_c: Any, T: Any) -> tuple[Any, Any]:
    r"""Capacitance and inertance of a whole lossless line of impedance ``Z_c`` and delay ``T``: :math:`C = T/Z_c`, :math:`L = Z_c T`.

    The telegrapher's relations of a line of capacitance :math:`C` and
    inertance :math:`L` (totals over its length): its characteristic
    impedance :math:`Z_c = \sqrt{L/C}` and the time a wave takes along it
    :math:`T = \sqrt{L C}`, solved for :math:`C` and :math:`L`. For a line of
    bore :math:`d` and length :math:`l`, :math:`Z_c = \rho c/A` and
    :math:`T = l/c`, and these are :func:`segment_capacitance` and
    :func:`segment_inertance` of the whole line.

    Parameters
    ----------
    Z_c : array_like
        Characteristic impedance [Pa s/m^3].
    T : array_like
        Time a wave takes from one end to the other [s].

    Returns
    -------
    tuple of array_like
        Capacitance [m^3/Pa] and inertance [Pa s^2/m^3].

    References
    ----------
    [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicTLMlossless.hpp (a line given by its impedance and delay);
    [Merritt1967] (fluid flow fundamentals: lumped line volumes and oil columns).

    Examples
    --------
    A 10 m line of 30 mm bore with oil of 870 kg/m^3 at 1 GPa:

    >>> import math
    >>> c = math.sqrt(1e9 / 870.0); A = math.pi * 0.03**2 / 4
    >>> C, L = wave_line_elements(870.0 * c / A, 10.0 / c)
    >>> round(C / float(segment_capacitance(10.0, 0.03, 1e9)), 12), round(L / float(segment_inertance(10.0, 0.03, 870.0)), 12)
    (1.0, 1.0)
    """
    return T / Z_c, Z_c * T


def wall_bypass_inertance(L: Any) -> Any:
    r"""Inertance that bypasses a viscous wall's resistance, :math:`2L` for a line of inertance :math:`L` [Pa s^2/m^3].

    Hopsan's hose (HydraulicHose.hpp) damps each transmitted wave by the filter
    :math:`(1 + s/W_4)/(1 + s/W_3)`, :math:`W_3 = R_w/(2 Z_c T)`,
    :math:`W_4 = W_3 e^{R_w/(2 Z_c)}`, where :math:`R_w = 128 \eta_w l/(\pi d^4)`
    is the wall's equivalent resistance. To first order in :math:`R_w/Z_c` the
    filter is :math:`e^{-Z_w/(2 Z_c)}`, the attenuation of a line whose
    series impedance is :math:`Z_w = R_w s\tau/(1 + s\tau)`,
    :math:`\tau = 1/W_3 = 2 Z_c T/R_w`: the resistance :math:`R_w` in parallel
    with the inertance :math:`R_w \tau = 2 Z_c T = 2L`. Fast waves see
    :math:`R_w`, a steady flow none of it.

    Parameters
    ----------
    L : array_like
        Inertance of the line, or of a segment for a segment's bypass [Pa s^2/m^3].

    Returns
    -------
    array_like
        Inertance in parallel with the wall's resistance [Pa s^2/m^3].

    References
    ----------
    [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicHose.hpp (the filters of W_3 and W_4 on the transmitted waves).

    Examples
    --------
    >>> float(wall_bypass_inertance(1.5e7))
    30000000.0
    """
    return 2.0 * L


def critical_flow(d: Any, rho: Any, mu: Any) -> Any:
    r"""Flow at which a line's Reynolds number :math:`4\rho |q|/(\pi d \mu)` reaches :data:`RE_CRIT` [m^3/s].

    Parameters
    ----------
    d : array_like
        Inner diameter [m].
    rho : array_like
        Density [kg/m^3].
    mu : array_like
        Dynamic viscosity [Pa s].

    Returns
    -------
    array_like
        Flow [m^3/s].

    References
    ----------
    [Merritt1967] (fluid flow fundamentals: the Reynolds number of a circular passage).

    Examples
    --------
    A 10 mm bore with oil of 870 kg/m^3 and 0.03 Pa s turns turbulent at 0.62 L/s:

    >>> round(float(critical_flow(0.01, 870.0, 0.03)) * 1e3, 2)
    0.62
    """
    return np.pi * d * mu * RE_CRIT / (4.0 * rho)


def friction_drop(q: Any, length: Any, d: Any, rho: Any, mu: Any) -> Any:
    r"""Pressure drop of wall friction along a line: laminar below a Reynolds number of 2300, Blasius' above [Pa].

    .. math::
        \Delta p = \frac{128 \mu l}{\pi d^4} q \quad (Re < 2300), \qquad
        \Delta p = \frac{32 \rho F l}{\pi^2 d^5} |q| q,\; F = 0.079\,Re^{-1/4} \quad (Re \ge 2300)

    with :math:`Re = 4\rho|q|/(\pi d\mu)` and :math:`F` the Fanning friction
    factor of a smooth pipe (Blasius). The drop jumps at the transition (by a
    factor 1.64: Blasius' friction there is that of :math:`Re \approx 800`
    laminar), as Hopsan's law does.

    Parameters
    ----------
    q : array_like
        Flow along the line [m^3/s].
    length : array_like
        Length [m].
    d : array_like
        Inner diameter [m].
    rho : array_like
        Density [kg/m^3].
    mu : array_like
        Dynamic viscosity [Pa s].

    Returns
    -------
    array_like
        Pressure drop in the direction of ``q`` [Pa].

    References
    ----------
    [Hopsan2026] Hydraulic/Volumes&Lines/HydraulicHose.hpp (its ``rq``: the laminar and turbulent friction of
    a line); [Merritt1967] (laminar flow in a circular passage, Hagen-Poiseuille).

    Examples
    --------
    Below the transition, the Hagen-Poiseuille drop; above, Blasius':

    >>> q_c = float(critical_flow(0.01, 870.0, 0.03))
    >>> bool(abs(friction_drop(0.5 * q_c, 2.0, 0.01, 870.0, 0.03) - segment_resistance(2.0, 0.01, 0.03) * 0.5 * q_c) < 1e-6)
    True
    >>> above, below = (friction_drop(q_c * (1.0 + e), 2.0, 0.01, 870.0, 0.03) for e in (1e-9, -1e-9))
    >>> round(float(above / below), 2)
    1.64
    """
    q_c = critical_flow(d, rho, mu)
    laminar = segment_resistance(length, d, mu) * q
    # Blasius' factor at the flow, but never at one below the transition (the branch not taken stays finite)
    re = 4.0 * rho * bk.fmax(bk.fabs(q), q_c) / (np.pi * d * mu)
    turbulent = 32.0 * rho * 0.079 * re**-0.25 * length * bk.fabs(q) * q / (np.pi**2 * d**5)
    return bk.if_else(bk.fabs(q) < q_c, laminar, turbulent)
