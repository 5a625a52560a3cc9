r"""Two-step identification of the staged-slot spool valve from test-bench curves ([MareAttarND] section 3.3).

Step 1, the low-gain vector of eq. (21),
:math:`\Theta_L = [X_{a0L}, X_{b0L}, X_{c0L}, X_{d0L}, w_L, r, c, C_{q\infty}, \lambda_{tL}]`,
minimises eq. (22) over the flow-gain curve in the low-gain domain, the
pressure-gain curves (:math:`P_1`, :math:`P_2`) and the leakage curve. Step 2,
the high-gain vector of eq. (23),
:math:`\Theta_H = [X_{a0H}, X_{b0H}, X_{c0H}, X_{d0H}, w_H, \lambda_{tH}]`,
minimises eq. (24) over the whole flow-gain curve, :math:`\Theta_L` fixed.
The two steps are repeated until neither moves: in step 1 the high-gain stage
sits at its current values, and a start far from the truth opens it inside
the low-gain domain, which biases :math:`\Theta_L` until step 2 has moved it.

How the extracted text was read
-------------------------------
* Eq. (22) sums :math:`(\hat Q_1 - Q_1^\#)^2 + R_1\{(\hat P_1 - P_1^\#)^2 + (\hat P_2 - P_2^\#)^2\}
  + R_2\{(\hat Q_2 - Q_2^\#)^2 + (\hat Q_3 - Q_3^\#)^2\}`. The three tests give
  one flow-gain flow, two pressures and one leakage flow; :math:`Q_2, Q_3` are
  read as the leakage measured at supply and at return, which are the same
  flow in a static model: hydroservo uses one leakage curve. "The weighting
  coefficients ... are set according to the ratio between the full scales":
  each residual is divided by its curve's full scale (the largest measured
  :math:`|Q_L|`, :math:`P_s - P_r`, the largest leakage), so that
  :math:`R_1 = (Q_{L,fs}/P_{fs})^2 w_P` and :math:`R_2 = (Q_{L,fs}/Q_{lk,fs})^2 w_{lk}`
  with user weights :math:`w_P`, :math:`w_{lk}` (default 1; the paper "gave the
  priority to the leakage").
* Eq. (24) sums :math:`(\hat Q_1 - Q_1^\#)^2 + (\hat Q_2 - Q_2^\#)^2` "using only the
  flow gain plot": read as the flow-gain curve's two polarities.
* The low-gain domain of step 1 is :math:`|X| \le` ``switch`` :math:`X_n`
  (default: the upper end of the bench's low flow-gain range, 20 %): below the
  step of the staged slot (25 % in the paper).
* :math:`C_{q\infty}` and the slot width are not separable: at large
  openings the flow is proportional to :math:`C_{q\infty} n w`. The paper says
  as much ("the limit value :math:`C_{q\infty}` ... fixes the flow-opening gain
  if n and w are known"; "the width and number of slots are design parameters
  ... easily provided by the manufacturer"). By default the widths are held at
  their given (start) values and :math:`C_{q\infty}` is identified; ``fixed``
  chooses otherwise.
* Staged slots are two orifices in parallel
  (:func:`hydroservo.laws.staged_slot.staged_slot_orifice_flow`); :math:`w_H` is the
  width of the wide part.

Identifiability
---------------
With the use ports connected, the flow at large openings passes orifices a and
d (X > 0) or c and b (X < 0) in series, and the series flow of two turbulent
orifices is symmetric in their areas: exchanging :math:`X_{a0H}` and
:math:`X_{d0H}` leaves the flow-gain curve unchanged. The four high-gain laps
of eq. (23) are therefore not identifiable from the flow-gain curve alone;
only each pair's mean is. ``high_laps = "pairs"`` (the default) identifies one
lap per pair (:math:`X_{a0H} = X_{d0H}`, :math:`X_{b0H} = X_{c0H}`);
``"orifice"`` fits all four as eq. (23) prints, and the result then depends
on the start within the unidentifiable direction.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hydroservo.analysis.static_bench import BenchCurves, blocked_ports, flow_gain
from hydroservo.components.valves.staged_slot import StagedSlotValve
from hydroservo.errors import ParameterError

__all__ = [
    "LOW_GAIN",
    "HIGH_GAIN",
    "StagedSlotIdentification",
    "identify_staged_slot",
    "curve_errors",
    "noisy_curves",
]

#: Eq. (21).
LOW_GAIN = ("X_a0", "X_b0", "X_c0", "X_d0", "w_L", "r", "c", "Cq_inf", "lambda_tL")
#: Eq. (23).
HIGH_GAIN = ("X_a0H", "X_b0H", "X_c0H", "X_d0H", "w_H", "lambda_tH")

_LAP_SCALE = 1e-6  # laps are fitted in micrometres
_PAIRS = {"X_d0H": "X_a0H", "X_c0H": "X_b0H"}


def _encode(name: str, params: Mapping[str, float]) -> float:
    v = params[name]
    if name.startswith("X_"):
        return v / _LAP_SCALE
    if name == "w_H":
        return float(np.log(max(v - params["w_L"], 1e-12)))
    return float(np.log(v))


def _decode(names: Sequence[str], z: np.ndarray, base: Mapping[str, float]) -> dict[str, float]:
    out = dict(base)
    for name, zi in zip(names, z, strict=True):
        if name.startswith("X_"):
            out[name] = float(zi) * _LAP_SCALE
        elif name != "w_H":
            out[name] = float(np.exp(zi))
    if "w_H" in names:
        out["w_H"] = out["w_L"] + float(np.exp(z[list(names).index("w_H")]))
    for tied, source in _PAIRS.items():
        if source in names and tied not in names:
            out[tied] = out[source]
    return out


@dataclass
class StagedSlotIdentification:
    """Result of :func:`identify_staged_slot`: the valve, the start, each step's report and the curve errors."""

    valve: StagedSlotValve
    start: StagedSlotValve
    curves: BenchCurves
    steps: list[dict[str, Any]] = field(default_factory=list)
    errors: dict[str, float] = field(default_factory=dict)


def _require(curves: BenchCurves) -> None:
    missing = [
        name
        for name, arrays in (
            ("flow gain (X, Q_L)", (curves.X_flow, curves.Q_L)),
            ("pressure gain (X, P_1, P_2)", (curves.X_blocked, curves.P_1, curves.P_2)),
            ("leakage (X, Q_lk)", (curves.X_leak, curves.Q_lk)),
        )
        if any(a is None for a in arrays)
    ]
    if missing:
        raise ParameterError(
            f"identification at {curves.temperature:g} degC: missing curve(s) {', '.join(missing)}; eq. (22) needs all three"
        )


def _finite(*arrays: np.ndarray) -> np.ndarray:
    ok = np.ones(np.asarray(arrays[0]).shape, bool)
    for a in arrays:
        ok &= np.isfinite(a)
    return ok


class _Residuals:
    """The residuals of eqs. (22) and (24): each curve's misfit over its full scale (module docstring)."""

    def __init__(self, curves: BenchCurves, switch: float, weights: tuple[float, float]) -> None:
        self.bench, self.T = curves.bench, curves.temperature
        Xf, QL = np.asarray(curves.X_flow), np.asarray(curves.Q_L)
        ok = _finite(Xf, QL)
        self.Xf, self.QL = Xf[ok], QL[ok]
        Xb, P1, P2 = (np.asarray(a) for a in (curves.X_blocked, curves.P_1, curves.P_2))
        ok = _finite(Xb, P1, P2)
        self.Xb, self.P1, self.P2 = Xb[ok], P1[ok], P2[ok]
        Xl, Qlk = np.asarray(curves.X_leak), np.asarray(curves.Q_lk)
        ok = _finite(Xl, Qlk)
        self.Xl, self.Qlk = Xl[ok], Qlk[ok]
        for what, n in (("flow-gain", self.Xf.size), ("pressure-gain", self.Xb.size), ("leakage", self.Xl.size)):
            if n < 3:
                raise ParameterError(
                    f"identification at {self.T:g} degC: {n} point(s) of the {what} curve; expected at least 3"
                )
        self.q_fs = float(np.max(np.abs(self.QL)))
        self.p_fs = self.bench.P_s - self.bench.P_r
        self.lk_fs = float(np.max(self.Qlk))
        if not (self.q_fs > 0 and self.lk_fs > 0):
            raise ParameterError("identification: the flow-gain and leakage curves must not be all zero")
        self.w_p, self.w_lk = np.sqrt(weights[0]), np.sqrt(weights[1])
        self.low = np.abs(self.Xf) <= switch * self.bench.X_n
        self.same_grid = self.Xl.shape == self.Xb.shape and np.array_equal(self.Xl, self.Xb)

    def low_gain(self, valve: StagedSlotValve) -> np.ndarray:
        """Eq. (22): flow gain in the low-gain domain, both pressures and the leakage."""
        T, bench = self.T, self.bench
        q = flow_gain(valve, T, bench, self.Xf[self.low])[0]
        p1, p2, lk = blocked_ports(valve, T, bench, self.Xb)
        if not self.same_grid:
            lk = blocked_ports(valve, T, bench, self.Xl)[2]
        return np.concatenate(
            [
                (q - self.QL[self.low]) / self.q_fs,
                self.w_p * (p1 - self.P1) / self.p_fs,
                self.w_p * (p2 - self.P2) / self.p_fs,
                self.w_lk * (lk - self.Qlk) / self.lk_fs,
            ]
        )

    def high_gain(self, valve: StagedSlotValve) -> np.ndarray:
        """Eq. (24): the whole flow-gain curve."""
        return (flow_gain(valve, self.T, self.bench, self.Xf)[0] - self.QL) / self.q_fs


def identify_staged_slot(
    curves: BenchCurves,
    start: StagedSlotValve,
    *,
    switch: float | None = None,
    weights: tuple[float, float] = (1.0, 1.0),
    high_laps: str = "pairs",
    fixed: Sequence[str] = ("w_L", "w_H"),
    max_rounds: int = 8,
) -> StagedSlotIdentification:
    """Identify the valve from test-bench curves at one temperature, from ``start``.

    Parameters
    ----------
    curves : BenchCurves
        Flow-gain, pressure-gain and leakage curves, SI, with their temperature and bench.
    start : StagedSlotValve
        Starting values (and the fixed n, and the fluid).
    switch : float, optional
        Upper end of the low-gain domain, fraction of X_n (default: the bench's
        low flow-gain range end).
    weights : (w_P, w_lk)
        Weights of the pressure-gain and leakage residuals relative to the flow
        gain, after normalisation by full scales (see the module docstring).
    high_laps : {"pairs", "orifice"}
        How the high-gain laps are fitted (module docstring, "Identifiability").
    fixed : sequence of str
        Parameters of eqs. (21) and (23) held at their start values: by default
        the slot widths, which the manufacturer gives (module docstring).
    max_rounds : int
        The two steps are repeated until no parameter moves (1e-4 in the fitted
        scale: micrometres for laps, the logarithm otherwise), at most this many times.
    """
    _require(curves)
    unknown = set(fixed) - set(LOW_GAIN) - set(HIGH_GAIN)
    if unknown:
        raise ParameterError(
            f"fixed: {', '.join(sorted(unknown))} not in eqs. (21) or (23); expected some of {LOW_GAIN + HIGH_GAIN}"
        )
    if high_laps not in ("pairs", "orifice"):
        raise ParameterError(f"high_laps = {high_laps!r}: expected 'pairs' or 'orifice'")
    if len(weights) != 2 or not all(math.isfinite(w) and w >= 0 for w in weights):
        raise ParameterError(f"weights = {tuple(weights)!r}: expected two non-negative, finite numbers (w_P, w_lk)")
    sw = curves.bench.flow_ranges[0][1] if switch is None else float(switch)
    if not 0 < sw <= 1:
        raise ParameterError(f"switch = {sw:g}: expected a fraction of X_n in (0, 1]")
    residuals = _Residuals(curves, sw, weights)
    result = StagedSlotIdentification(start, start, curves)
    high_names = tuple(n for n in HIGH_GAIN if n not in fixed and (high_laps == "orifice" or n not in _PAIRS))
    low_names = tuple(n for n in LOW_GAIN if n not in fixed)
    n_low = int(residuals.low.sum()) + 2 * residuals.Xb.size + residuals.Xl.size
    for step, names, n_res in (("low-gain", low_names, n_low), ("high-gain", high_names, residuals.Xf.size)):
        if n_res <= len(names):
            raise ParameterError(
                f"identification at {curves.temperature:g} degC: {n_res} points for the {len(names)} parameters of "
                f"the {step} step ({', '.join(names)}); expected more points than parameters"
            )
    valve = start
    for rnd in range(1, max_rounds + 1):
        before = np.array([_encode(n, valve.values) for n in low_names + high_names])
        for step, names, fun in (
            ("low gain, eqs. (21)-(22)", low_names, residuals.low_gain),
            ("high gain, eqs. (23)-(24)", high_names, residuals.high_gain),
        ):
            valve, report = _fit(valve, names, fun)
            report["step"], report["round"] = step, rnd
            result.steps.append(report)
        after = np.array([_encode(n, valve.values) for n in low_names + high_names])
        if np.max(np.abs(after - before)) < 1e-4:
            break
    result.valve = valve
    result.errors = curve_errors(valve, curves, sw)
    return result


def _fit(
    valve: StagedSlotValve, names: Sequence[str], residuals: Callable[[StagedSlotValve], np.ndarray]
) -> tuple[StagedSlotValve, dict[str, Any]]:
    from scipy.optimize import least_squares  # SciPy's optimiser is imported where it is used

    base = dict(valve.values)
    z0 = np.array([_encode(n, base) for n in names])

    def trial(z: np.ndarray) -> StagedSlotValve:
        return valve.replace(check=False, **_decode(names, z, base))

    sol = least_squares(
        lambda z: residuals(trial(z)), z0, method="trf", x_scale=1.0, xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=200
    )
    fitted = trial(sol.x)
    sv = np.linalg.svd(sol.jac, compute_uv=False)
    report = {
        "parameters": list(names),
        "cost": float(sol.cost),
        "rms": float(np.sqrt(2 * sol.cost / max(sol.fun.size, 1))),
        "nfev": int(sol.nfev),
        "status": sol.message,
        "condition": float(sv[0] / sv[-1]) if sv[-1] > 0 else float("inf"),
    }
    return fitted, report


def _max_rel(y_hat: np.ndarray, y: np.ndarray, full_scale: float | None = None) -> float:
    """Largest |relative error| over the points whose |value| is at least 10 % of ``full_scale`` (default: max |y|)."""
    keep = np.abs(y) >= 0.1 * (np.max(np.abs(y)) if full_scale is None else full_scale)
    return float(np.max(np.abs(y_hat[keep] / y[keep] - 1.0))) if np.any(keep) else float("nan")


def curve_errors(valve: StagedSlotValve, curves: BenchCurves, switch: float) -> dict[str, float]:
    """The maximum relative errors the paper reports (section 3.3), as fractions.

    ``flow_low``/``flow_high``: over the flow-gain points below/above ``switch`` X_n;
    ``pressure``: over :math:`P_1` and :math:`P_2`; ``leakage_max``: of the largest
    leakage; ``leakage``: over the leakage curve. Points below 10 % of their
    curve's full scale are left out (a relative error near zero means nothing).
    """
    out: dict[str, float] = {}
    bench, T = curves.bench, curves.temperature
    if curves.X_flow is not None and curves.Q_L is not None:
        ok = _finite(curves.X_flow, curves.Q_L)
        X, Q = curves.X_flow[ok], curves.Q_L[ok]
        q = flow_gain(valve, T, bench, X)[0]
        low = np.abs(X) <= switch * bench.X_n
        q_fs = float(np.max(np.abs(Q)))
        out["flow_low"] = _max_rel(q[low], Q[low], q_fs)
        out["flow_high"] = _max_rel(q[~low], Q[~low], q_fs)
    if curves.X_blocked is not None and curves.P_1 is not None and curves.P_2 is not None:
        ok = _finite(curves.X_blocked, curves.P_1, curves.P_2)
        p1, p2, _ = blocked_ports(valve, T, bench, curves.X_blocked[ok])
        out["pressure"] = _max_rel(
            np.concatenate([p1, p2]) - bench.P_r, np.concatenate([curves.P_1[ok], curves.P_2[ok]]) - bench.P_r
        )
    if curves.X_leak is not None and curves.Q_lk is not None:
        ok = _finite(curves.X_leak, curves.Q_lk)
        lk = blocked_ports(valve, T, bench, curves.X_leak[ok])[2]
        out["leakage_max"] = float(np.max(lk) / np.max(curves.Q_lk[ok]) - 1.0)
        out["leakage"] = _max_rel(lk, curves.Q_lk[ok])
    return out


def noisy_curves(curves: BenchCurves, level: float, seed: int = 0) -> BenchCurves:
    """``curves`` with multiplicative Gaussian noise of relative standard deviation ``level`` on every reading."""
    rng = np.random.default_rng(seed)
    noisy = {
        name: a * (1.0 + level * rng.standard_normal(a.shape))
        for name in ("Q_L", "P_1", "P_2", "Q_lk")
        if (a := getattr(curves, name)) is not None
    }
    return dataclasses.replace(curves, **noisy)
