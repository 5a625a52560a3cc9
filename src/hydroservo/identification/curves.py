r"""Pseudo-sections fitted to measured static curves by least squares (an extension of [FerreiraND] section 5).

The paper fits its pseudo-sections to the three null characteristics of a
datasheet (:func:`hydroservo.identification.fit_datasheet`); with measured
curves (its Figs. 3-5) hydroservo fits them to the whole curves instead: the
relative load pressure (eq. 13) and leakage (eq. 27) with blocked ports at
``P_s``, and the load flow (eq. 9) with connected ports at ``P_n`` per edge
when given. The nominal flow is kept exact (eq. 32 or 34) and, for the fixed
structure, the far leakage of eq. (39) nearly so.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo.errors import ParameterError
from hydroservo.identification.datasheet import (
    Datasheet,
    PseudoSectionFit,
    deviations,
    fit_datasheet,
    fit_variable_structure,
    fitted_valve,
)
from hydroservo.laws import pseudo_section as ps

__all__ = ["fit_curves", "curve_predictions"]

_CURVES = ("P_L", "q_lk", "Q_L")


def curve_predictions(structure: str, params: Mapping[str, float], x: Any, ds: Datasheet) -> dict[str, np.ndarray]:
    """The three curves of a pseudo-section model at positions ``x``: P_L [-], q_lk and Q_L [m^3/s] (eqs. 13, 27, 9)."""
    A_p, A_n = ps.pseudo_sections(np.asarray(x, dtype=float), structure, dict(params))
    return {
        "P_L": ps.relative_load_pressure(A_p, A_n),
        "q_lk": ps.leakage_blocked(A_p, A_n, ds.P_s),
        "Q_L": ps.load_flow_no_load(A_p, A_n, 2.0 * ds.P_n),
    }


def _start(x: np.ndarray, data: dict[str, np.ndarray], ok: dict[str, np.ndarray], ds: Datasheet, structure: str) -> dict[str, float]:
    """The datasheet fit to the null characteristics read off the curves."""
    near = ok["P_L"] & (np.abs(data["P_L"]) < 0.5)
    if near.sum() < 2:
        raise ParameterError("curves: expected at least 2 points with |P_L| < 0.5 near null to read the pressure gain")
    K_p0 = float(np.polyfit(x[near], np.arctanh(data["P_L"][near]), 1)[0])
    q_lk0 = float(np.max(data["q_lk"][ok["q_lk"]]))
    if not (K_p0 > 0 and q_lk0 > 0):
        raise ParameterError(
            f"curves: pressure gain {K_p0:.3g} and leakage {q_lk0:.3g} m^3/s read off the curves must be positive"
        )
    null = Datasheet(Q_n=ds.Q_n, P_n=ds.P_n, P_s=ds.P_s, K_p0=K_p0, q_lk0=q_lk0)
    return fit_datasheet(null, structure, "pressure-gain,leakage").params


class _Coordinates:
    """The free coordinates of each structure, with the nominal flow exact.

    Variable: log k and log gamma; alpha, beta, x_t follow from continuity and
    Q_n (eq. 32). Fixed: k1, k3, k4, k5 scaled by the nominal section c =
    Q_n/sqrt(P_n); k2 follows from eq. (34).
    """

    def __init__(self, structure: str, ds: Datasheet) -> None:
        self.structure, self.ds = structure, ds
        self.c = ds.Q_n / math.sqrt(ds.P_n)

    def encode(self, p: Mapping[str, float]) -> np.ndarray:
        c = self.c
        if self.structure == "variable":
            return np.log([p["k"], p["gamma"]])
        return np.array([p["k1"] / c, p["k3"] / c**2, p["k4"] / c**2, p["k5"] / c**2])

    def decode(self, z: np.ndarray) -> dict[str, float]:
        ds, c = self.ds, self.c
        if self.structure == "variable":
            k, gamma = np.exp(z)
            sub = Datasheet(Q_n=ds.Q_n, P_n=ds.P_n, P_s=ds.P_s, K_p0=k, q_lk0=gamma * math.sqrt(2 * ds.P_s))
            return {n: float(v) for n, v in fit_variable_structure(sub, ("pressure-gain", "leakage")).items()}
        k1, k3, k4, k5 = z[0] * c, z[1] * c**2, z[2] * c**2, z[3] * c**2
        k2 = c + k1 - math.sqrt(max(k3 - k4 + k5, 0.0))  # eq. (34)
        return {"k1": k1, "k2": k2, "k3": k3, "k4": k4, "k5": k5}

    def lower(self) -> Any:
        return np.array([-np.inf, 0.0, -np.inf, 1e-12]) if self.structure == "fixed" else -np.inf


def fit_curves(
    curves: Mapping[str, Any],
    datasheet: Datasheet | Mapping[str, Any],
    structure: str = "variable",
) -> PseudoSectionFit:
    """Least-squares pseudo-sections from measured static curves (module docstring).

    Each curve is scaled by its largest magnitude, so each weighs alike; the
    start is the datasheet fit to the null characteristics read off the curves.

    Parameters
    ----------
    curves : mapping
        ``x_s`` [-], ``P_L`` [-], ``q_lk`` [m^3/s] and optionally ``Q_L``
        [m^3/s]; NaN marks a missing value.
    datasheet : Datasheet or mapping
        Gives ``Q_n``, ``P_n`` and ``P_s``; its null characteristics, if any,
        are not used.
    structure : {"variable", "fixed"}

    Returns
    -------
    PseudoSectionFit
        ``match == ("curves",)``; ``deviation`` holds the relative deviation of
        each characteristic the datasheet gives and, as ``rms_P_L`` etc., the
        RMS misfit of each curve relative to its largest value.
    """
    from scipy.optimize import least_squares  # SciPy's optimiser is imported where it is used

    ds = datasheet if isinstance(datasheet, Datasheet) else Datasheet.from_mapping(datasheet, where="datasheet")
    if structure not in ps.STRUCTURES:
        raise ParameterError(f"structure = {structure!r}: expected one of {', '.join(ps.STRUCTURES)}")
    x = np.asarray(curves["x_s"], dtype=float)
    data = {k: np.asarray(curves[k], dtype=float) for k in _CURVES if k in curves}
    ok = {k: np.isfinite(v) & np.isfinite(x) for k, v in data.items()}
    if ok["P_L"].sum() < 3 or ok["q_lk"].sum() < 3:
        raise ParameterError("curves: expected at least 3 points of P_L and of q_lk")
    scale = {k: float(np.max(np.abs(v[ok[k]]))) for k, v in data.items() if ok[k].any()}
    coords = _Coordinates(structure, ds)
    n_points = sum(int(v.sum()) for v in ok.values())

    def residuals(z: np.ndarray) -> np.ndarray:
        try:
            p = coords.decode(z)
        except ParameterError:
            return np.full(n_points + (structure == "fixed"), 10.0)
        model = curve_predictions(structure, p, x, ds)
        res = [(model[k] - v)[ok[k]] / scale[k] for k, v in data.items() if ok[k].any()]
        if structure == "fixed":  # eq. (39): the leakage far from null (default zero at x_s = 1), near-exact
            far = ps.fixed_structure(-ds.x_far, **p) - ds.q_lk_far / (2.0 * math.sqrt(ds.P_s))
            res.append(np.atleast_1d(100.0 * far / coords.c))
        return np.concatenate(res)

    z0 = coords.encode(_start(x, data, ok, ds, structure))
    if n_points <= z0.size:
        raise ParameterError(
            f"curves: {n_points} points for the {z0.size} parameters of the {structure}-structure pseudo-sections; "
            "expected more points than parameters"
        )
    sol = least_squares(residuals, z0, bounds=(coords.lower(), np.inf), xtol=1e-12, ftol=1e-12, max_nfev=2000)
    fit = PseudoSectionFit(fitted_valve(structure, coords.decode(sol.x)), ds, ("curves",))
    fit.valve.check_sections()
    fitted = curve_predictions(structure, fit.params, x, ds)
    rms = {
        f"rms_{k}": float(np.sqrt(np.mean(((fitted[k] - v)[ok[k]] / scale[k]) ** 2)))
        for k, v in data.items()
        if ok[k].any()
    }
    fit.deviation = {**deviations(fit, ds), **rms}
    return fit
