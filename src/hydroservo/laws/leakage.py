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

__all__ = ["ellman_flow", "eryilmaz_flow", "laminar_gap_flow", "laminar_gap_continuity"]


def ellman_flow(X: Any, dp: Any, k1: Any, k2: Any) -> Any:
    r"""Closed-orifice leakage of Ellman (1995, 1998), [MareAttarND] eq. (7) [m^3/s].

    :math:`Q = \frac{k_2}{2}\left[\sqrt{(k_2/k_1)^2X^2 + 4\Delta P} - \frac{k_2}{k_1}X\right]`,
    a short annulus in laminar flow; ``X`` the (signed) opening [m], ``dp`` >= 0 [Pa],
    ``k1``, ``k2`` fitted at one temperature.
    """
    a = k2 / k1
    return 0.5 * k2 * (np.sqrt(a * a * np.asarray(X) ** 2 + 4.0 * np.asarray(dp)) - a * np.asarray(X))


def eryilmaz_flow(X: Any, dp: Any, X0: Any, k1: Any, k2: Any) -> Any:
    r"""Closed-orifice leakage of Eryilmaz (2000), [MareAttarND] eq. (8) [m^3/s].

    :math:`Q = k_1\sqrt{\Delta P}\,X_0^2/(X_0 - k_2X)`: turbulent, inversely proportional to the closure.
    """
    return k1 * np.sqrt(np.asarray(dp)) * X0**2 / (X0 - k2 * np.asarray(X))


def laminar_gap_flow(X: Any, dp: Any, mu: Any, n: Any, w: Any, c: Any, K_g: Any) -> Any:
    r"""Closed orifice as a laminar gap between infinite planes (Rabie et al. 1981), [MareAttarND] eq. (10) [m^3/s].

    :math:`Q = \frac{nwc^3}{12\mu(K_g + |X|)}\Delta P`, ``K_g`` [m] ensuring continuity with the open law (eq. 11).
    """
    return n * w * c**3 / (12.0 * mu * (K_g + np.abs(np.asarray(X)))) * np.asarray(dp)


def laminar_gap_continuity(w: Any, c: Any, delta_lambda: Any) -> Any:
    r"""Continuity constant of the laminar-gap law, [MareAttarND] eq. (11) [m].

    :math:`K_g = c(w + c)/(48\delta_\lambda w)`, with :math:`\delta_\lambda` the limit slope of
    :math:`C_q(\lambda)` at small flow numbers (for eq. 6: :math:`C_{q\infty}/\lambda_t`).
    """
    return c * (w + c) / (48.0 * delta_lambda * w)
