r"""Static characteristics of a four-way spool valve as a servovalve test bench measures them.

The tests of SAE ARP490 [SAEARP490] as [MareAttarND] (section 3.1) uses them, on
the staged-slot valve (:class:`~hydroservo.components.StagedSlotValve`, whose
orifice law is :func:`hydroservo.laws.staged_slot.staged_slot_orifice_flow`):

* **flow gain**: use ports connected to each other (no load, :math:`P_1 = P_2`),
  load flow :math:`Q_L = Q_a - Q_b` against opening;
* **pressure gain**: use ports blocked (:math:`Q_a = Q_b`, :math:`Q_c = Q_d`),
  :math:`P_1`, :math:`P_2` against opening;
* **leakage**: the supply flow :math:`Q_a + Q_c` with blocked ports;
* **pressure-flow**: :math:`Q_L` against :math:`P_L = P_1 - P_2` at fixed openings.

Each test is a balance of monotone orifice flows in one unknown pressure, so it
is solved at every opening at once by a bracketed root finder (Illinois regula
falsi with a bisection every fourth step): it cannot fail, at null or anywhere,
and it converges to 1e-12 of the supply pressure.

The metrics of [MareAttarND] Table 2 (:func:`table2_metrics`) are defined here as:

* maximum leakage, % :math:`Q_n`: the maximum of the blocked-port supply flow over the opening;
* pressure gain over ±0.25 % :math:`X_n`, in % :math:`P_s` / % :math:`X_n`: the
  secant slope of :math:`P_L/(P_s - P_r)` over ±0.25 % :math:`X_n` about the
  pressure null (where :math:`P_1 = P_2`);
* pressure gain over ±40 % :math:`P_s`: 80 % divided by the opening span (in
  % :math:`X_n`) over which :math:`P_L` goes from -40 % to +40 % of :math:`P_s - P_r`
  (hydroservo's definition; the paper names the metric only);
* low and high flow gains, % :math:`Q_n` / % :math:`X_n`: least-squares slopes of
  :math:`Q_L` over two ranges of :math:`|X|/X_n` (default 5-20 % and 40-100 %),
  the mean of the two polarities;
* useport pressure at null, % :math:`P_s`: :math:`(P_1 - P_r)/(P_s - P_r)` at the pressure null.

:math:`Q_n` is the rated flow of :class:`Bench`; when not given, the no-load
flow at :math:`X_n` and the rating temperature (default 38 degC, i.e. 100 degF, hydroservo's choice).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from hydroservo.components.valves.staged_slot import StagedSlotValve
from hydroservo.errors import ParameterError
from hydroservo.units import to_si

__all__ = [
    "Bench",
    "BenchCurves",
    "METRICS",
    "bench_curves",
    "flow_gain",
    "blocked_ports",
    "pressure_flow",
    "rated_flow",
    "table2_metrics",
    "temperature_table",
]

#: Table-2 metrics: key -> (label, unit).
METRICS: dict[str, tuple[str, str]] = {
    "max_leakage": ("Maximum leakage", "% Q_n"),
    "pressure_gain_025": ("Pressure gain over ±0.25 % X_n", "% P_s / % X_n"),
    "pressure_gain_40": ("Pressure gain over ±40 % P_s", "% P_s / % X_n"),
    "flow_gain_low": ("Low flow gain", "% Q_n / % X_n"),
    "flow_gain_high": ("High flow gain", "% Q_n / % X_n"),
    "useport_null": ("Useport pressure at null", "% P_s"),
}

_BENCH_UNITS = {"P_s": "Pa", "P_r": "Pa", "X_n": "m", "Q_n": "m^3/s", "T_rated": "degC"}


@dataclass(frozen=True)
class Bench:
    """Test conditions: supply and return pressures [Pa], rated opening [m], rated flow [m^3/s] (None: computed).

    ``flow_ranges``: the ranges of :math:`|X|/X_n` over which the low and high flow gains are fitted.
    """

    P_s: float
    X_n: float
    P_r: float = 0.0
    Q_n: float | None = None
    T_rated: float = 38.0
    flow_ranges: tuple[tuple[float, float], tuple[float, float]] = ((0.05, 0.20), (0.40, 1.0))

    def __post_init__(self) -> None:
        if not self.P_s > self.P_r:
            raise ParameterError(f"bench: P_s = {self.P_s:g} Pa, P_r = {self.P_r:g} Pa: expected P_s > P_r")
        if not self.X_n > 0:
            raise ParameterError(f"bench: X_n = {self.X_n:g} m: expected a rated opening > 0")
        if self.Q_n is not None and not self.Q_n > 0:
            raise ParameterError(f"bench: Q_n = {self.Q_n:g} m^3/s: expected a rated flow > 0")
        for lo, hi in self.flow_ranges:
            if not 0 <= lo < hi <= 1:
                raise ParameterError(f"bench: flow-gain range {lo:g}..{hi:g} of X_n: expected 0 <= lo < hi <= 1")

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], where: str = "bench") -> Bench:
        """From quantities with units (``P_s = "3000 psi"``, ``X_n = "0.4 mm"``, ...)."""
        unknown = set(data) - set(_BENCH_UNITS) - {"flow_ranges"}
        if unknown:
            raise ParameterError(
                f"{where}: unknown key(s) {', '.join(sorted(unknown))}; known: {', '.join(_BENCH_UNITS)}"
            )
        for key in ("P_s", "X_n"):
            if key not in data:
                raise ParameterError(f"{where}: missing {key} (expected P_s, X_n and optionally P_r, Q_n, T_rated)")
        kw: dict[str, Any] = {
            k: to_si(v, _BENCH_UNITS[k], what=f"{where}.{k}") for k, v in data.items() if k in _BENCH_UNITS
        }
        if "flow_ranges" in data:
            try:
                kw["flow_ranges"] = tuple((float(a), float(b)) for a, b in data["flow_ranges"])
            except (TypeError, ValueError):
                raise ParameterError(
                    f"{where}.flow_ranges = {data['flow_ranges']!r}: expected [[lo, hi], [lo, hi]] fractions of X_n"
                ) from None
        return cls(**kw)

    def to_mapping(self) -> dict[str, Any]:
        out: dict[str, Any] = {"P_s": f"{self.P_s!r} Pa", "P_r": f"{self.P_r!r} Pa", "X_n": f"{self.X_n!r} m"}
        if self.Q_n is not None:
            out["Q_n"] = f"{self.Q_n!r} m^3/s"
        out["T_rated"] = f"{self.T_rated!r} degC"
        out["flow_ranges"] = [list(r) for r in self.flow_ranges]
        return out


def _props(valve: StagedSlotValve, T: float, bench: Bench) -> tuple[float, float]:
    """Density [kg/m^3] and kinematic viscosity [m^2/s] at ``T`` [degC] and the bench's mean pressure."""
    rho, nu = valve.fluid_properties(bench.P_s, bench.P_r, T)
    return float(rho), float(nu)


def _root(f: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray, xtol: float) -> np.ndarray:
    """Root of ``f`` (decreasing in its argument, f(lo) >= 0 >= f(hi)) elementwise: Illinois with bisection."""
    a, b = np.array(lo, float), np.array(hi, float)
    fa, fb = f(a), f(b)
    if np.any(fa < 0) or np.any(fb > 0):
        raise RuntimeError("bench solver: the root is not bracketed (a non-monotone orifice law?)")
    for k in range(400):
        active = (b - a) > xtol
        if not np.any(active):
            break
        if k % 4 == 3:
            c = 0.5 * (a + b)
        else:
            with np.errstate(divide="ignore", invalid="ignore"):
                c = (a * fb - b * fa) / (fb - fa)
            c = np.where(np.isfinite(c) & (c > a) & (c < b), c, 0.5 * (a + b))
        fc = f(c)
        pos = fc > 0  # root lies in (c, b)
        zero = fc == 0
        a_new = np.where(pos, c, a)
        b_new = np.where(pos, b, c)
        # Illinois: halve the function value kept on the side that did not move
        fb = np.where(pos, 0.5 * fb, fc)
        fa = np.where(pos, fc, 0.5 * fa)
        a = np.where(zero, c, np.where(active, a_new, a))
        b = np.where(zero, c, np.where(active, b_new, b))
    else:  # pragma: no cover - the bisection steps guarantee convergence
        raise RuntimeError("bench solver: no convergence in 400 steps")
    return 0.5 * (a + b)


def _tol(bench: Bench) -> float:
    return 1e-12 * (bench.P_s - bench.P_r)


def flow_gain(valve: StagedSlotValve, T: float, bench: Bench, X: Any, P_L: Any = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Load flow :math:`Q_L = Q_a - Q_b` [m^3/s] and :math:`P_1` [Pa] at openings ``X`` [m] and load pressures ``P_L`` [Pa].

    ``P_L = 0``: use ports connected (the flow-gain test). Solves
    :math:`Q_a + Q_c = Q_b + Q_d` (the load flow goes out of port 1 and back
    into port 2) for :math:`P_1`, with :math:`P_2 = P_1 - P_L`.
    """
    X, P_L = np.broadcast_arrays(np.asarray(X, float), np.asarray(P_L, float))
    props = _props(valve, T, bench)
    Ps, Pr = bench.P_s, bench.P_r

    def balance(p: np.ndarray) -> np.ndarray:
        p2 = p - P_L
        return (
            valve.orifice_flow("a", X, Ps, p, props)
            + valve.orifice_flow("c", X, Ps, p2, props)
            - valve.orifice_flow("b", X, p, Pr, props)
            - valve.orifice_flow("d", X, p2, Pr, props)
        )

    span = bench.P_s - bench.P_r
    P1 = _root(balance, Pr - np.abs(P_L) - 0.01 * span, Ps + np.abs(P_L) + 0.01 * span, _tol(bench))
    return valve.orifice_flow("a", X, Ps, P1, props) - valve.orifice_flow("b", X, P1, Pr, props), P1


def blocked_ports(valve: StagedSlotValve, T: float, bench: Bench, X: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Use ports blocked: :math:`P_1`, :math:`P_2` [Pa] and the supply (leakage) flow [m^3/s] at openings ``X`` [m]."""
    X = np.asarray(X, float)
    props = _props(valve, T, bench)
    Ps, Pr = bench.P_s, bench.P_r
    lo, hi = np.full(X.shape, Pr), np.full(X.shape, Ps)
    P1 = _root(lambda p: valve.orifice_flow("a", X, Ps, p, props) - valve.orifice_flow("b", X, p, Pr, props), lo, hi, _tol(bench))
    P2 = _root(lambda p: valve.orifice_flow("c", X, Ps, p, props) - valve.orifice_flow("d", X, p, Pr, props), lo, hi, _tol(bench))
    return P1, P2, valve.orifice_flow("a", X, Ps, P1, props) + valve.orifice_flow("c", X, Ps, P2, props)


def pressure_flow(
    valve: StagedSlotValve, T: float, bench: Bench, openings: Sequence[float], n: int = 81
) -> tuple[np.ndarray, np.ndarray]:
    """The pressure-flow family: ``P_L`` [Pa] (n values over ±(P_s - P_r)) and ``Q_L`` [m^3/s], one row per opening [m]."""
    P_L = np.linspace(-1.0, 1.0, n) * (bench.P_s - bench.P_r)
    Xg, Pg = np.meshgrid(np.asarray(openings, float), P_L, indexing="ij")
    return P_L, flow_gain(valve, T, bench, Xg, Pg)[0]


def rated_flow(valve: StagedSlotValve, bench: Bench) -> float:
    """:math:`Q_n` [m^3/s]: the bench's, or the no-load flow at X_n and the rating temperature."""
    if bench.Q_n is not None:
        return bench.Q_n
    return float(flow_gain(valve, bench.T_rated, bench, np.array([bench.X_n]))[0][0])


@dataclass
class BenchCurves:
    """Test-bench curves at one temperature, SI: connected ports over the stroke, blocked ports near null.

    Also the form of measured curves for identification (any of the three tests may be absent: None).
    """

    temperature: float
    bench: Bench
    X_flow: np.ndarray | None = None
    Q_L: np.ndarray | None = None
    X_blocked: np.ndarray | None = None
    P_1: np.ndarray | None = None
    P_2: np.ndarray | None = None
    X_leak: np.ndarray | None = None
    Q_lk: np.ndarray | None = None


def bench_curves(
    valve: StagedSlotValve, T: float, bench: Bench, n: int = 401, zoom: float = 0.0625, strict: bool = False
) -> BenchCurves:
    """All three tests at temperature ``T`` [degC], ``n`` openings each.

    Flow gain over ±X_n; pressure gain and leakage over ±``zoom`` X_n ([MareAttarND]
    identifies over ±6.25 %, "that provides rich data").
    """
    valve.fluid.check_range(np.array([bench.P_r, bench.P_s]), T, strict)
    Xf = np.linspace(-1.0, 1.0, n) * bench.X_n
    Xb = np.linspace(-zoom, zoom, n) * bench.X_n
    Q_L = flow_gain(valve, T, bench, Xf)[0]
    P1, P2, Q_lk = blocked_ports(valve, T, bench, Xb)
    return BenchCurves(T, bench, Xf, Q_L, Xb, P1, P2, Xb, Q_lk)


def table2_metrics(valve: StagedSlotValve, T: float, bench: Bench, Q_n: float | None = None) -> dict[str, float]:
    """The metrics of [MareAttarND] Table 2 at temperature ``T`` [degC] (units in :data:`METRICS`; module docstring)."""
    from scipy.optimize import brentq, minimize_scalar  # SciPy's optimiser is imported where it is used

    Qn = rated_flow(valve, bench) if Q_n is None else Q_n
    span = bench.P_s - bench.P_r
    Xn = bench.X_n

    def blocked(x: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return blocked_ports(valve, T, bench, np.atleast_1d(np.asarray(x, float)))

    def load_pressure(x: Any) -> np.ndarray:
        P1, P2, _ = blocked(x)
        return (P1 - P2) / span

    # blocked ports on a grid about null: brackets for the crossings, start of the leakage maximum
    Xg = np.linspace(-0.1, 0.1, 401) * Xn
    P1g, P2g, leak = blocked(Xg)
    PLg = (P1g - P2g) / span

    def crossing(level: float) -> float:
        above = np.nonzero(PLg >= level)[0]
        if above.size and above[0] > 0:
            lo, hi = Xg[above[0] - 1], Xg[above[0]]
        else:  # outside the grid: search the whole stroke
            lo, hi = -Xn, Xn
            if load_pressure(lo)[0] > level or load_pressure(hi)[0] < level:
                raise ParameterError(
                    f"spool valve at {T:g} degC: the load pressure does not reach {level * 100:+g} % of P_s "
                    "over ±X_n with blocked ports"
                )
        return float(brentq(lambda x: load_pressure(x)[0] - level, lo, hi, xtol=1e-12 * Xn, rtol=1e-14))

    x0 = crossing(0.0)  # the pressure null, P_1 = P_2
    h = 0.0025 * Xn
    pl = load_pressure([x0 - h, x0 + h])
    gain_025 = (pl[1] - pl[0]) * 100.0 / 0.5
    gain_40 = 80.0 / ((crossing(0.4) - crossing(-0.4)) / Xn * 100.0)
    P1_null = blocked(x0)[0][0]

    k = int(np.argmax(leak))
    res = minimize_scalar(
        lambda x: -blocked(x)[2][0],
        bounds=(Xg[max(k - 1, 0)], Xg[min(k + 1, Xg.size - 1)]),
        method="bounded",
        options={"xatol": 1e-9 * Xn},
    )
    leak_max = max(float(-res.fun), float(leak[k]))

    gains = []
    for lo, hi in bench.flow_ranges:
        x = np.linspace(lo, hi, 41) * Xn
        q = flow_gain(valve, T, bench, np.concatenate([x, -x]))[0] / Qn * 100
        slopes = [np.polyfit(s * x / Xn * 100, qs, 1)[0] for s, qs in ((1, q[: x.size]), (-1, q[x.size :]))]
        gains.append(float(np.mean(slopes)))
    return {
        "max_leakage": leak_max / Qn * 100.0,
        "pressure_gain_025": float(gain_025),
        "pressure_gain_40": float(gain_40),
        "flow_gain_low": gains[0],
        "flow_gain_high": gains[1],
        "useport_null": float((P1_null - bench.P_r) / span * 100.0),
    }


def temperature_table(
    valve: StagedSlotValve, bench: Bench, temperatures: Sequence[float], reference: float | None = None
) -> dict[str, Any]:
    """Table-2 metrics at several temperatures [degC], and their change from ``reference`` (default: the first).

    Returns ``{"temperatures", "reference", "Q_n", "metrics": {T: {...}}, "change": {T: {...}}}``,
    changes as fractions.
    """
    temps = [float(t) for t in temperatures]
    ref = temps[0] if reference is None else float(reference)
    Qn = rated_flow(valve, bench)
    rows = {t: table2_metrics(valve, t, bench, Qn) for t in sorted(set(temps) | {ref})}
    change = {t: {k: rows[t][k] / rows[ref][k] - 1.0 for k in METRICS} for t in rows if t != ref}
    return {"temperatures": temps, "reference": ref, "Q_n": Qn, "metrics": rows, "change": change}
