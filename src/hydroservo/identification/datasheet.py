r"""Pseudo-section parameters from datasheet values (seed 000, sections 3-5).

A datasheet gives the nominal flow :math:`Q_n` at a drop :math:`P_n` per
metering edge and some of the three null characteristics: relative pressure
gain :math:`K_{p0}`, flow gain :math:`K_{q0}` and leakage :math:`q_{lk0}`.
For *any* pseudo-sections of a matched symmetrical valve these three are tied
by eq. (23),

.. math:: K_{q0} = \frac{q_{lk0}}{2} K_{p0}

(with :math:`K_{q0}` and :math:`q_{lk0}` taken at the same supply pressure;
here :math:`K_{q0}` at :math:`P_n` per edge, :math:`q_{lk0}` at :math:`P_s`, so
:math:`q_{lk0}` is rescaled by :math:`\sqrt{2P_n/P_s}`). Only two of them can be
matched. :func:`fit_datasheet` matches the two named in ``match`` and reports
how far the model is from the third when the datasheet gives it.

* Variable structure (eq. 24): :math:`k` and :math:`\gamma` follow
  algebraically from eqs. (26), (29), (31); :math:`\alpha, \beta, x_t` from the
  continuity and nominal-flow conditions of eq. (32), which reduce to one
  equation in :math:`s = k x_t/2`:
  :math:`\gamma e^{s}(1 + k/2 - s) = Q_n/\sqrt{P_n}`, monotonic on
  :math:`0 < s < k/2`, so its root in :math:`x_t \in (0, 1)` is unique when it
  exists.
* Fixed structure (eq. 33): five nonlinear equations, (34), (39), (40) and two
  of (36), (37), (38); (39)-(40) impose the leakage and its slope at a far
  opening :math:`x_s^*` (default: zero leakage and zero slope at
  :math:`x_s = 1`, as the paper does for its Figs. 7-9).

The paper restricts :math:`\beta` to positive values; a large nominal flow
relative to the leakage can require :math:`\beta < 0`, which still gives a
positive, continuous section, so it is accepted (and reported).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import brentq, least_squares

from hydroservo import pseudo_sections as ps
from hydroservo.errors import ParameterError
from hydroservo.units import from_si, to_si

__all__ = [
    "CHARACTERISTICS",
    "PARAMETER_UNITS",
    "PAPER_UNITS",
    "Datasheet",
    "PseudoSectionModel",
    "fit_datasheet",
    "characteristics",
]

#: Null characteristics that can be matched, with their datasheet field.
CHARACTERISTICS = {"pressure-gain": "K_p0", "flow-gain": "K_q0", "leakage": "q_lk0"}

_A = ps.PARAMETER_UNITS["gamma"]
_A2 = ps.PARAMETER_UNITS["k3"]
PARAMETER_UNITS = ps.PARAMETER_UNITS
#: The units the paper prints them in.
PAPER_UNITS = {k: {"": "", _A: "L/min/bar^0.5", _A2: "(L/min)^2/bar"}[u] for k, u in PARAMETER_UNITS.items()}

_FIELDS = {
    "Q_n": ("m^3/s", "nominal flow at P_n per metering edge"),
    "P_n": ("Pa", "nominal pressure drop per metering edge"),
    "P_s": ("Pa", "supply pressure of the pressure-gain and leakage measurements"),
    "K_q0": ("m^3/s", "flow gain at null, per unit normalised spool position, at P_n per edge"),
    "K_p0": ("", "relative pressure gain at null, per unit normalised spool position"),
    "q_lk0": ("m^3/s", "leakage flow at null at P_s"),
    "x_far": ("", "far opening x_s* where the leakage is imposed (eqs. 39-40)"),
    "q_lk_far": ("m^3/s", "leakage at x_s* (blocked ports, P_L = 1)"),
    "dq_lk_far": ("m^3/s", "slope of the leakage at x_s*, per unit x_s"),
}


@dataclass(frozen=True)
class Datasheet:
    """Static datasheet values of a matched symmetrical proportional valve (SI).

    Build one from values with units with :meth:`from_mapping`.
    """

    Q_n: float
    P_n: float
    P_s: float
    K_q0: float | None = None
    K_p0: float | None = None
    q_lk0: float | None = None
    x_far: float = 1.0
    q_lk_far: float = 0.0
    dq_lk_far: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        for key in ("Q_n", "P_n", "P_s", "K_q0", "K_p0", "q_lk0"):
            val = getattr(self, key)
            if val is None:
                continue
            if not (math.isfinite(val) and val > 0):
                unit = _FIELDS[key][0] or "-"
                raise ParameterError(f"datasheet {key} = {val!r} {unit}: expected a positive value ({_FIELDS[key][1]})")
        if not 0.0 < self.x_far <= 1.0:
            raise ParameterError(f"datasheet x_far = {self.x_far!r}: expected a far opening in (0, 1]")
        if self.q_lk_far < 0:
            raise ParameterError(f"datasheet q_lk_far = {self.q_lk_far!r} m^3/s: expected a leakage >= 0")

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], where: str = "datasheet") -> Datasheet:
        """Read values with units (``{"Q_n": "25.5 L/min", "P_n": "35 bar", ...}``)."""
        known = set(_FIELDS) | {"name"}
        unknown = sorted(set(data) - known)
        if unknown:
            raise ParameterError(f"{where}: unknown field(s) {', '.join(unknown)}; known: {', '.join(sorted(known))}")
        values: dict[str, Any] = {"name": str(data.get("name", ""))}
        for key, (unit, desc) in _FIELDS.items():
            if key in data:
                values[key] = to_si(data[key], unit, what=f"{where}.{key}")
            elif key in ("Q_n", "P_n", "P_s"):
                raise ParameterError(f"{where}: missing {key} ({desc})")
        return cls(**values)

    def given(self) -> list[str]:
        """Names (``pressure-gain``, ...) of the null characteristics the datasheet gives."""
        return [name for name, key in CHARACTERISTICS.items() if getattr(self, key) is not None]

    def as_mapping(self) -> dict[str, Any]:
        """Values with units, as :meth:`from_mapping` reads them (L/min and bar)."""
        show = {"m^3/s": "L/min", "Pa": "bar", "": ""}
        out: dict[str, Any] = {"name": self.name} if self.name else {}
        for key, (unit, _) in _FIELDS.items():
            val = getattr(self, key)
            if val is not None:
                u = show[unit]
                out[key] = f"{from_si(val, unit, u):.6g} {u}" if u else float(val)
        return out


@dataclass
class PseudoSectionModel:
    """A fitted (or given) pseudo-section function of a matched symmetrical valve.

    Attributes
    ----------
    structure : {"variable", "fixed"}
    params : dict
        Parameters in SI (:data:`PARAMETER_UNITS`).
    datasheet : Datasheet or None
        What it was fitted to.
    match : tuple of str
        The matched null characteristics.
    deviation : dict
        Relative deviation of each reproduced characteristic from the datasheet value.
    """

    structure: str
    params: dict[str, float]
    datasheet: Datasheet | None = None
    match: tuple[str, ...] = ()
    deviation: dict[str, float] = field(default_factory=dict)

    def sections(self, x: Any) -> tuple[Any, Any]:
        """``(A_p(x), A_n(x))`` [m^3/s/Pa^0.5]."""
        return ps.pseudo_sections(np.asarray(x, dtype=float), self.structure, self.params)

    def in_paper_units(self) -> dict[str, float]:
        """Parameters in the units the paper prints (L/min/bar^0.5, (L/min)^2/bar)."""
        return {
            k: from_si(v, PARAMETER_UNITS[k], PAPER_UNITS[k]) if PAPER_UNITS[k] else v for k, v in self.params.items()
        }

    def characteristics(self, P_n: float | None = None, P_s: float | None = None) -> dict[str, float]:
        """Reproduced Q_n, K_q0, K_p0, q_lk0 (SI); pressures default to the datasheet's."""
        ds = self.datasheet
        P_n = P_n if P_n is not None else (ds.P_n if ds else None)
        P_s = P_s if P_s is not None else (ds.P_s if ds else None)
        if P_n is None or P_s is None:
            raise ParameterError("characteristics: give P_n and P_s (no datasheet attached)")
        return characteristics(self.structure, self.params, P_n, P_s)

    def check(self) -> None:
        """Raise if a pseudo-section is negative (or its radicand) anywhere on [-1, 1]."""
        ps.check_sections(self.structure, self.params)


def characteristics(structure: str, params: Mapping[str, float], P_n: float, P_s: float) -> dict[str, float]:
    """Static characteristics of a model, computed from its equations (SI).

    ``Q_n`` = :math:`\\sqrt{P_n}A_p(1)` (eqs. 32, 34), ``Q_L1`` the load flow at
    full opening with connected ports at :math:`2P_n` supply (eq. 9),
    ``K_q0`` the slope of eq. (9) at null with :math:`P_s = 2P_n`, ``K_p0`` the
    slope of eq. (13) at null, ``q_lk0`` eq. (27) at null and :math:`P_s`.
    Slopes by central differences of step 1e-6.
    """
    h = 1e-6
    x = np.array([-h, 0.0, h, 1.0])
    A_p, A_n = ps.pseudo_sections(x, structure, dict(params))
    QL = ps.load_flow_no_load(A_p, A_n, 2.0 * P_n)
    PL = ps.relative_load_pressure(A_p, A_n)
    return {
        "Q_n": float(math.sqrt(P_n) * A_p[3]),
        "Q_L1": float(QL[3]),
        "K_q0": float((QL[2] - QL[0]) / (2 * h)),
        "K_p0": float((PL[2] - PL[0]) / (2 * h)),
        "q_lk0": float(ps.leakage_blocked(A_p[1], A_n[1], P_s)),
    }


def _parse_match(match: str | Iterable[str] | None, ds: Datasheet) -> tuple[str, str]:
    given = ds.given()
    if len(given) < 2:
        raise ParameterError(
            f"datasheet gives {', '.join(CHARACTERISTICS[g] for g in given) or 'none'} of K_p0, K_q0, q_lk0: two are "
            "needed to fit the pseudo-sections (eq. 23 ties the third to them), or fit measured curves instead"
        )
    if match is None:
        # The paper always reproduces the pressure gain (section 4.1); then leakage if given.
        order = ["pressure-gain", "leakage", "flow-gain"]
        chosen = [c for c in order if c in given][:2]
    else:
        items = match.split(",") if isinstance(match, str) else list(match)
        chosen = [c.strip() for c in items if c.strip()]
        for c in chosen:
            if c not in CHARACTERISTICS:
                raise ParameterError(
                    f"match: {c!r} is not a null characteristic; expected two of {', '.join(CHARACTERISTICS)}"
                )
        if len(set(chosen)) != 2:
            raise ParameterError(
                f"match = {','.join(chosen)!r}: expected exactly two of {', '.join(CHARACTERISTICS)}. Eq. (23) of seed 000, "
                "K_q0 = q_lk0 K_p0 / 2, holds for any pseudo-sections, so the third follows from the other two"
            )
        for c in chosen:
            if c not in given:
                raise ParameterError(f"match: {c} ({CHARACTERISTICS[c]}) is not given in the datasheet")
    return chosen[0], chosen[1]


def _null_section(ds: Datasheet, match: tuple[str, str]) -> tuple[float, float]:
    """Section at null A0 [m^3/s/Pa^0.5] and relative pressure gain k [-] from the two matched characteristics.

    A0 from eq. (18)/(29) :math:`q_{lk0} = A_0\\sqrt{2P_s}`; k from eq. (26);
    flow gain eq. (31) :math:`K_{q0} = k A_0 \\sqrt{P_n}` (per-edge drop P_n).
    """
    s = set(match)
    if "leakage" in s:
        A0 = ds.q_lk0 / math.sqrt(2.0 * ds.P_s)  # type: ignore[operator]
        k = ds.K_p0 if "pressure-gain" in s else ds.K_q0 / (A0 * math.sqrt(ds.P_n))  # type: ignore[operator]
    else:
        k = ds.K_p0  # type: ignore[assignment]
        A0 = ds.K_q0 / (k * math.sqrt(ds.P_n))  # type: ignore[operator]
    return A0, k  # type: ignore[return-value]


def _fit_variable(ds: Datasheet, match: tuple[str, str]) -> dict[str, float]:
    gamma, k = _null_section(ds, match)
    target = ds.Q_n / math.sqrt(ds.P_n)  # A_p(1), eq. (32)

    def g(s: float) -> float:  # nominal-flow condition with continuity substituted
        return gamma * math.exp(s) * (1.0 + k / 2.0 - s) - target

    lo, hi = 0.0, k / 2.0
    g_lo = g(lo)
    g_hi = gamma * math.exp(min(hi, 700.0)) - target
    if g_lo >= 0 or g_hi <= 0:
        unit = "L/min/bar^0.5"
        raise ParameterError(
            f"variable structure: no transition point x_t in (0, 1) for Q_n/sqrt(P_n) = "
            f"{from_si(target, _A, unit):.4g} {unit}: with gamma = {from_si(gamma, _A, unit):.4g} {unit} and k = {k:.4g} "
            f"it must lie between gamma (1 + k/2) = {from_si(gamma * (1 + k / 2), _A, unit):.4g} and "
            f"gamma exp(k/2) = {from_si(gamma * math.exp(min(k / 2, 700.0)), _A, unit):.4g} (eq. 32). "
            "Check Q_n, P_n and the null characteristics"
        )
    s = brentq(g, lo, min(hi, 700.0), xtol=1e-15, rtol=1e-15)
    x_t = 2.0 * s / k
    alpha = k / 2.0 * gamma * math.exp(s)
    beta = gamma * math.exp(s) * (1.0 - s)
    return {"k": float(k), "gamma": gamma, "alpha": alpha, "beta": beta, "x_t": x_t}


def _fit_fixed(ds: Datasheet, match: tuple[str, str]) -> dict[str, float]:
    A0, k = _null_section(ds, match)
    c = ds.Q_n / math.sqrt(ds.P_n)
    S = k * A0 / 2.0  # dA_p/dx at null (eq. 26 with A_p = A_n = A0)
    xf = ds.x_far
    # Targets of eqs. (39)-(40): A_n and its slope at x* (leakage with P_L = 1: q = 2 sqrt(P_s) A_n).
    An_far = ds.q_lk_far / (2.0 * math.sqrt(ds.P_s))
    dAn_far = ds.dq_lk_far / (2.0 * math.sqrt(ds.P_s))
    # Scale: sections by c, so the unknowns are O(1): k1, k2 / c; k3, k4, k5 / c^2.

    def unpack(z: np.ndarray) -> tuple[float, ...]:
        return z[0] * c, z[1] * c, z[2] * c**2, z[3] * c**2, z[4] * c**2

    def res(z: np.ndarray) -> np.ndarray:
        k1, k2, k3, k4, k5 = unpack(z)
        r5 = math.sqrt(max(k5, 1e-300))
        Rm = max(k3 - k4 + k5, 1e-300)  # radicand of A_p at x = 1
        Rf = max(k3 * xf**2 + k4 * xf + k5, 1e-300)  # radicand of A_n at x*
        out = [
            (-k1 + k2 + math.sqrt(Rm)) / c - 1.0,  # eq. (34)
            (k1 * xf + k2 + math.sqrt(Rf) - An_far) / c,  # eq. (39)
            (k1 + (2 * k3 * xf + k4) / (2 * math.sqrt(Rf)) - dAn_far) / c,  # eq. (40)
        ]
        slope = -k1 - k4 / (2 * r5)  # dA_p/dx at 0
        a0 = k2 + r5  # A at 0
        for ch in match:
            if ch == "pressure-gain":  # eq. (37)
                out.append(2 * slope / a0 / k - 1.0)
            elif ch == "flow-gain":  # eq. (36)
                out.append(slope * 2 * math.sqrt(ds.P_n) / ds.K_q0 - 1.0)  # type: ignore[operator]
            else:  # eq. (38)
                out.append(a0 / A0 - 1.0)
        return np.array(out)

    # Start: open asymptote slope 2 sqrt(k3) ~ c, closed asymptote ~ 0, A(0) = A0, slope S.
    z0 = np.array([-0.5, 0.0, 0.25, 2 * A0 / c * (0.5 - S / c), (A0 / c) ** 2])
    lower = np.array([-np.inf, -np.inf, 0.0, -np.inf, 1e-12])
    sol = least_squares(res, z0, bounds=(lower, np.inf), xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000)
    if not np.all(np.abs(sol.fun) < 1e-9):
        raise ParameterError(
            "fixed structure: the five equations (34), (39), (40) and "
            f"{' and '.join(match)} have no solution with a real pseudo-section (largest relative residual "
            f"{np.max(np.abs(sol.fun)):.2g}). Check the datasheet values and the far leakage (x_far, q_lk_far, dq_lk_far)"
        )
    names = ps.PARAMETER_NAMES["fixed"]
    return {n: float(v) for n, v in zip(names, unpack(sol.x))}


def fit_datasheet(
    datasheet: Datasheet | Mapping[str, Any],
    structure: str = "variable",
    match: str | Sequence[str] | None = None,
) -> PseudoSectionModel:
    """Pseudo-section parameters reproducing a datasheet (seed 000, sections 4.1-4.2).

    Parameters
    ----------
    datasheet : Datasheet or mapping
        Values (a mapping may carry units: ``{"Q_n": "25.5 L/min", ...}``).
    structure : {"variable", "fixed"}
        Eq. (24) (one nonlinear equation) or eq. (33) (five).
    match : str or sequence of str, optional
        Two of ``pressure-gain``, ``flow-gain``, ``leakage`` (comma-separated
        string or list). Default: pressure gain and leakage when given (the
        paper always reproduces the pressure gain), else the two given.

    Returns
    -------
    PseudoSectionModel
        With ``deviation``: the relative error of every characteristic the
        datasheet gives, so the one that was not matched shows how far off it is.

    Examples
    --------
    Seed 000 section 5, KBSDG4V-3, variable structure matching pressure gain and leakage:

    >>> ds = {"Q_n": "25.5 L/min", "P_n": "35 bar", "K_q0": "28 L/min", "K_p0": 36.5,
    ...       "q_lk0": "1.36 L/min", "P_s": "70 bar"}
    >>> fit = fit_datasheet(ds)
    >>> {k: float(f"{v:.5g}") for k, v in fit.in_paper_units().items()}
    {'k': 36.5, 'gamma': 0.11494, 'alpha': 4.2415, 'beta': 0.068773, 'x_t': 0.03858}

    The paper prints k = 36.5, gamma = 0.1149, alpha = 4.241, beta = 6.877e-2,
    x_t = 3.858e-2 (alpha truncated, not rounded).
    >>> round(fit.deviation["K_q0"], 3)  # eq. (23): the flow gain cannot also be matched
    -0.114
    """
    ds = datasheet if isinstance(datasheet, Datasheet) else Datasheet.from_mapping(datasheet)
    if structure not in ps.STRUCTURES:
        raise ParameterError(f"structure = {structure!r}: expected one of {', '.join(ps.STRUCTURES)}")
    chosen = _parse_match(match, ds)
    params = _fit_variable(ds, chosen) if structure == "variable" else _fit_fixed(ds, chosen)
    model = PseudoSectionModel(structure, params, ds, chosen)
    model.check()
    got = model.characteristics()
    model.deviation = {
        key: got[key] / getattr(ds, key) - 1.0
        for key in ("Q_n", "K_q0", "K_p0", "q_lk0")
        if getattr(ds, key) is not None
    }
    return model


def fit_curves(
    curves: Mapping[str, Any],
    datasheet: Datasheet | Mapping[str, Any],
    structure: str = "variable",
) -> PseudoSectionModel:
    """Least-squares pseudo-sections from measured static curves (seed 000 section 5, Figs. 3-5).

    The nominal flow is kept exact (eq. 32 or 34) and, for the fixed
    structure, the far leakage of eq. (39) (the datasheet's ``x_far``,
    ``q_lk_far``: default zero at full opening) nearly so; the remaining
    parameters minimise the misfit of the measured curves: relative load pressure (eq. 13)
    and leakage (eq. 27) with blocked ports at ``P_s``, and load flow (eq. 9)
    with connected ports at ``P_n`` per edge when given. Each curve is scaled by
    its largest magnitude, so each weighs alike.

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
    PseudoSectionModel
        ``match == ("curves",)``; ``deviation`` holds the relative deviation of
        each characteristic the datasheet gives and, as ``rms_P_L`` etc., the
        RMS misfit of each curve relative to its largest value.
    """
    ds = datasheet if isinstance(datasheet, Datasheet) else Datasheet.from_mapping(datasheet, where="datasheet")
    if structure not in ps.STRUCTURES:
        raise ParameterError(f"structure = {structure!r}: expected one of {', '.join(ps.STRUCTURES)}")
    x = np.asarray(curves["x_s"], dtype=float)
    data = {k: np.asarray(curves[k], dtype=float) for k in ("P_L", "q_lk", "Q_L") if k in curves}
    ok = {k: np.isfinite(v) & np.isfinite(x) for k, v in data.items()}
    if ok["P_L"].sum() < 3 or ok["q_lk"].sum() < 3:
        raise ParameterError("curves: expected at least 3 points of P_L and of q_lk")
    scale = {k: float(np.max(np.abs(v[ok[k]]))) for k, v in data.items() if ok[k].any()}
    # Start: the datasheet fit to the null characteristics read off the curves.
    near = ok["P_L"] & (np.abs(data["P_L"]) < 0.5)
    if near.sum() < 2:
        raise ParameterError("curves: expected at least 2 points with |P_L| < 0.5 near null to read the pressure gain")
    K_p0 = float(np.polyfit(x[near], np.arctanh(data["P_L"][near]), 1)[0])
    q_lk0 = float(np.max(data["q_lk"][ok["q_lk"]]))
    if not (K_p0 > 0 and q_lk0 > 0):
        raise ParameterError(
            f"curves: pressure gain {K_p0:.3g} and leakage {q_lk0:.3g} m^3/s read off the curves must be positive"
        )
    start = fit_datasheet(
        Datasheet(Q_n=ds.Q_n, P_n=ds.P_n, P_s=ds.P_s, K_p0=K_p0, q_lk0=q_lk0), structure, "pressure-gain,leakage"
    ).params
    c = ds.Q_n / math.sqrt(ds.P_n)
    if structure == "variable":
        z0 = np.log([start["k"], start["gamma"]])
    else:
        z0 = np.array([start["k1"] / c, start["k3"] / c**2, start["k4"] / c**2, start["k5"] / c**2])

    def params_of(z: np.ndarray) -> dict[str, float]:
        if structure == "variable":
            k, gamma = np.exp(z)
            sub = Datasheet(Q_n=ds.Q_n, P_n=ds.P_n, P_s=ds.P_s, K_p0=k, q_lk0=gamma * math.sqrt(2 * ds.P_s))
            return {k: float(v) for k, v in _fit_variable(sub, ("pressure-gain", "leakage")).items()}
        k1, k3, k4, k5 = z[0] * c, z[1] * c**2, z[2] * c**2, z[3] * c**2
        k2 = c + k1 - math.sqrt(max(k3 - k4 + k5, 0.0))  # eq. (34)
        return {"k1": k1, "k2": k2, "k3": k3, "k4": k4, "k5": k5}

    def residuals(z: np.ndarray) -> np.ndarray:
        try:
            p = params_of(z)
        except ParameterError:
            return np.full(sum(int(v.sum()) for v in ok.values()), 10.0)
        A_p, A_n = ps.pseudo_sections(x, structure, p)
        model = {
            "P_L": ps.relative_load_pressure(A_p, A_n),
            "q_lk": ps.leakage_blocked(A_p, A_n, ds.P_s),
            "Q_L": ps.load_flow_no_load(A_p, A_n, 2.0 * ds.P_n),
        }
        res = [(model[k] - v)[ok[k]] / scale[k] for k, v in data.items() if ok[k].any()]
        if structure == "fixed":  # eq. (39): the leakage far from null (default zero at x_s = 1), near-exact
            far = ps.fixed_structure(-ds.x_far, **p) - ds.q_lk_far / (2.0 * math.sqrt(ds.P_s))
            res.append(np.atleast_1d(100.0 * far / c))
        return np.concatenate(res)

    lower = np.array([-np.inf, 0.0, -np.inf, 1e-12]) if structure == "fixed" else -np.inf
    sol = least_squares(residuals, z0, bounds=(lower, np.inf), xtol=1e-12, ftol=1e-12, max_nfev=2000)
    params = params_of(sol.x)
    model = PseudoSectionModel(structure, params, ds, ("curves",))
    model.check()
    A_p, A_n = model.sections(x)
    fitted = {
        "P_L": ps.relative_load_pressure(A_p, A_n),
        "q_lk": ps.leakage_blocked(A_p, A_n, ds.P_s),
        "Q_L": ps.load_flow_no_load(A_p, A_n, 2.0 * ds.P_n),
    }
    got = model.characteristics()
    model.deviation = {
        **{key: got[key] / getattr(ds, key) - 1.0 for key in ("Q_n", "K_q0", "K_p0", "q_lk0") if getattr(ds, key)},
        **{
            f"rms_{k}": float(np.sqrt(np.mean(((fitted[k] - v)[ok[k]] / scale[k]) ** 2)))
            for k, v in data.items()
            if ok[k].any()
        },
    }
    return model
