r"""Pseudo-section parameters from datasheet values ([FerreiraND] sections 3-5).

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

from hydroservo.components.valves.pseudo_section import PseudoSectionValve
from hydroservo.errors import ParameterError
from hydroservo.laws import pseudo_section as ps
from hydroservo.units import from_si, to_si

__all__ = [
    "CHARACTERISTICS",
    "Datasheet",
    "PseudoSectionFit",
    "fit_datasheet",
    "fit_variable_structure",
    "fit_fixed_structure",
    "fitted_valve",
    "deviations",
]

#: Null characteristics that can be matched, with their datasheet field.
CHARACTERISTICS = {"pressure-gain": "K_p0", "flow-gain": "K_q0", "leakage": "q_lk0"}

_A = ps.PARAMETER_UNITS["gamma"]

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


def fitted_valve(structure: str, params: Mapping[str, float], name: str = "valve") -> PseudoSectionValve:
    """A :class:`~hydroservo.components.PseudoSectionValve` of ``structure`` with the pseudo-section ``params`` (SI)."""
    return PseudoSectionValve(name, structure=structure).replace(check=False, **params)


@dataclass
class PseudoSectionFit:
    """Pseudo-sections fitted to a datasheet or to measured curves: the valve, and what it was fitted to.

    Attributes
    ----------
    valve : PseudoSectionValve
        The fitted valve (its structure and parameters).
    datasheet : Datasheet or None
        What it was fitted to.
    match : tuple of str
        The matched null characteristics (``("curves",)`` for a fit to curves).
    deviation : dict
        Relative deviation of each reproduced characteristic from the datasheet value.
    """

    valve: PseudoSectionValve
    datasheet: Datasheet | None = None
    match: tuple[str, ...] = ()
    deviation: dict[str, float] = field(default_factory=dict)

    @property
    def structure(self) -> str:
        """``"variable"`` or ``"fixed"``."""
        return self.valve.structure

    @property
    def params(self) -> dict[str, float]:
        """The fitted parameters of the structure (SI, :data:`~hydroservo.laws.pseudo_section.PARAMETER_UNITS`)."""
        return self.valve.section_parameters()

    def sections(self, x: Any) -> tuple[Any, Any]:
        """``(A_p(x), A_n(x))`` [m^3/s/Pa^0.5]."""
        return self.valve.sections(x)

    def in_paper_units(self) -> dict[str, float]:
        """Parameters in the units the paper prints (L/min/bar^0.5, (L/min)^2/bar)."""
        units, shown = ps.PARAMETER_UNITS, ps.PRINTED_UNITS
        return {k: from_si(v, units[k], shown[k]) if shown[k] else v for k, v in self.params.items()}

    def characteristics(self, P_n: float | None = None, P_s: float | None = None) -> dict[str, float]:
        """Reproduced Q_n, K_q0, K_p0, q_lk0 (SI); pressures default to the datasheet's."""
        ds = self.datasheet
        P_n = P_n if P_n is not None else (ds.P_n if ds else None)
        P_s = P_s if P_s is not None else (ds.P_s if ds else None)
        if P_n is None or P_s is None:
            raise ParameterError("characteristics: give P_n and P_s (no datasheet attached)")
        return self.valve.characteristics(P_n, P_s)

    def measured_sections(self, curves: Mapping[str, Any], P_s: float | None = None) -> dict[str, np.ndarray]:
        """The "real" pseudo-sections of measured blocked-port curves (``x_s``, ``P_L``, ``q_lk``), [FerreiraND]
        eqs. (16)-(17) (:func:`~hydroservo.laws.pseudo_section.sections_from_measurements`), at the datasheet's
        supply pressure unless ``P_s`` is given: ``{"x_s": ..., "A_p": ..., "A_n": ...}`` [m^3/s/Pa^0.5]."""
        P_s = P_s if P_s is not None else (self.datasheet.P_s if self.datasheet else None)
        if P_s is None:
            raise ParameterError("measured_sections: give P_s (no datasheet attached)")
        A_p, A_n = ps.sections_from_measurements(curves["P_L"], curves["q_lk"], P_s)
        return {"x_s": np.asarray(curves["x_s"], dtype=float), "A_p": A_p, "A_n": A_n}


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
                f"match = {','.join(chosen)!r}: expected exactly two of {', '.join(CHARACTERISTICS)}. Eq. (23) of FerreiraND, "
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
        k = ds.K_p0
        A0 = ds.K_q0 / (k * math.sqrt(ds.P_n))  # type: ignore[operator]
    return A0, k  # type: ignore[return-value]


def fit_variable_structure(ds: Datasheet, match: tuple[str, str]) -> dict[str, float]:
    """Variable-structure parameters (eq. 24) matching Q_n and the two null characteristics ``match`` (SI)."""
    from scipy.optimize import brentq  # SciPy's optimiser is imported where it is used

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


def fit_fixed_structure(ds: Datasheet, match: tuple[str, str]) -> dict[str, float]:
    """Fixed-structure parameters (eq. 33) from eqs. (34), (39), (40) and the two characteristics ``match`` (SI)."""
    from scipy.optimize import least_squares

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
) -> PseudoSectionFit:
    """Pseudo-section parameters reproducing a datasheet ([FerreiraND] sections 4.1-4.2).

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
    PseudoSectionFit
        With ``deviation``: the relative error of every characteristic the
        datasheet gives, so the one that was not matched shows how far off it is.

    Examples
    --------
    [FerreiraND] section 5, KBSDG4V-3, variable structure matching pressure gain and leakage:

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
    params = fit_variable_structure(ds, chosen) if structure == "variable" else fit_fixed_structure(ds, chosen)
    fit = PseudoSectionFit(fitted_valve(structure, params), ds, chosen)
    fit.valve.check_sections()
    fit.deviation = deviations(fit, ds)
    return fit


def deviations(fit: PseudoSectionFit, ds: Datasheet) -> dict[str, float]:
    """Relative deviation of each reproduced null characteristic (and Q_n) from the datasheet's value, where given."""
    got = fit.characteristics()
    return {key: got[key] / getattr(ds, key) - 1.0 for key in ("Q_n", "K_q0", "K_p0", "q_lk0") if getattr(ds, key)}
