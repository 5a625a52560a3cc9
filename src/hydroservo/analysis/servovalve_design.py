"""The servovalve design study: what every physical parameter does to every bench figure.

For a designer who changes a nozzle, a spring or a gap before anything is
machined: the elasticity of each figure to each parameter of the valve
component (per cent change of the figure per per cent of the parameter),
ranked. Each figure is differentiated as exactly as its nature allows:

* **at rest** (rated flow, spool travel and flapper tip at rated current,
  internal leakage at null): exact, by the implicit function theorem at the
  model's trim, :math:`dx/dp = -f_x^{-1} f_p`, from CasADi's Jacobians;
* **small-signal** (the -90 degree and -3 dB frequencies of the flow's
  response to current): from the model linearised, exactly, at the trim at
  5 % of rated current (past the null's dead band; the bench's ±5 % sine
  through null gives the same -90 degree frequency within 2 %), its
  derivatives by central differences of 1 % on that cheap linear
  computation (a crossing frequency is smooth but has no closed form);
* **linearity** of the characteristic at rest (the bench's 41 currents): central
  differences of 1 %, each perturbed valve trimmed from the design point's
  solutions;
* **transient** (rise time and overshoot of the ±10 % square wave of
  [GordicND] Fig. 9) and **hysteresis** (the 1/16 Hz sine of Fig. 10):
  central differences of 1 %, all the perturbed valves simulated at once by
  a batch over the cores. A step response or a loop of a valve with dry
  friction and a ball clearance is not smooth in every parameter; a 1 %
  step is well inside the region where it is.

The pressure gain with blocked ports is left out: Table 1's valve jumps
there (docs/servovalve.md), and a jump has no elasticity.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import casadi as ca
import numpy as np

from hydroservo.analysis.frequency import FrequencyResponse
from hydroservo.analysis.servovalve_bench import (
    DRIVE,
    VALVE,
    BenchConditions,
    bench_system,
    bench_valve,
    hysteresis_loop,
)
from hydroservo.analysis.step import step_metrics
from hydroservo.components.signals import Sine, Square, Step
from hydroservo.errors import ParameterError, SolverError, TrimError

__all__ = ["FIGURES", "NOT_DESIGN", "DesignStudy", "design_study"]

#: The figures: key -> (description, unit shown, scale from SI, how it is differentiated).
FIGURES = {
    "rated_flow": ("rated flow", "L/min", 6e4, "exact"),
    "spool_travel": ("spool travel at rated current", "mm", 1e3, "exact"),
    "flapper_tip": ("flapper tip at rated current", "um", 1e6, "exact"),
    "leakage_null": ("internal leakage at null", "L/min", 6e4, "exact"),
    "f_90": ("-90 deg frequency, small signal", "Hz", 1.0, "linearised, differences"),
    "f_3db": ("-3 dB frequency, small signal", "Hz", 1.0, "linearised, differences"),
    "linearity": ("linearity (deviation from the rated line)", "% of rated flow", 100.0, "differences"),
    "rise_time": ("rise time, +-10 % square wave", "ms", 1e3, "differences"),
    "overshoot": ("overshoot, +-10 % square wave", "%", 1.0, "differences"),
    "hysteresis": ("hysteresis, 1/16 Hz sine of rated amplitude", "% of rated current", 100.0, "differences"),
}

#: Parameters that are not design choices: numerical smoothing and initial values.
NOT_DESIGN = ("v_reg", "c_s", "p_d0", "p_n0", "p_tr")


@dataclass(frozen=True)
class DesignStudy:
    """Each figure at the design point and its elasticity to each parameter."""

    figures: dict[str, float]  #: SI
    elasticity: dict[str, dict[str, float]]  #: figure -> parameter -> d ln(figure) / d ln(parameter)

    def ranked(self, figure: str, top: int | None = None) -> list[tuple[str, float]]:
        """The parameters by the size of their effect on ``figure``, largest first (NaN last)."""
        rows = sorted(self.elasticity[figure].items(), key=lambda kv: -abs(kv[1]) if np.isfinite(kv[1]) else 1.0)
        return rows[:top] if top else rows


class _Rest:
    """The bench at rest with exact parameter sensitivities of its trim."""

    def __init__(self, bench: BenchConditions, names: Sequence[str]) -> None:
        self.system = bench_system(bench, Step(DRIVE, unit="A", amplitude=0.0), "none")
        m = self.model = self.system.build()
        self.p = self.system.parameter_vector()
        self.k_i = m.parameter_names.index(f"{DRIVE}.amplitude")
        self.cols = [m.parameter_names.index(f"{VALVE}.{n}") for n in names]
        x, p = ca.SX.sym("x", m.nx), ca.SX.sym("p", m.np)
        f, y = m.f(0.0, x, p), m.outputs(0.0, x, p)
        out = {k: m.output_names.index(f"{VALVE}.{k}") for k in ("QA", "QB", "QS", "x")}
        figures = ca.vertcat((y[out["QA"]] - y[out["QB"]]) / 2, y[out["QS"]], y[out["x"]], x[m.state_names.index(f"{VALVE}.y")])
        self.jac = ca.Function("rest_jacobians", [x, p], [ca.jacobian(f, x), ca.jacobian(f, p), figures, ca.jacobian(figures, x),
                                              ca.jacobian(figures, p)])
        self.A_B = ca.Function("AB", [x, p], [ca.jacobian(f, x), ca.jacobian(f, p)[:, self.k_i]])
        q = (y[out["QA"]] - y[out["QB"]]) / 2
        self.C_D = ca.Function("CD", [x, p], [ca.jacobian(q, x), ca.jacobian(q, p)[:, self.k_i]])

    def trim(self, i: float, p: np.ndarray | None = None, guess: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        p = (self.p if p is None else p).copy()
        p[self.k_i] = i
        try:
            t = self.model.trim(p, x_guess=guess)
        except TrimError as exc:
            raise SolverError(f"design study: the valve at rest at {i * 1e3:.3g} mA: {exc}") from None
        return np.array([t[n] for n in self.model.state_names]), p

    def exact(self, i: float) -> tuple[np.ndarray, np.ndarray]:
        """The figures at rest (no-load flow, supply flow, flapper tip, spool travel) and their derivatives with
        respect to the chosen parameters, by the implicit function theorem."""
        x, p = self.trim(i)
        fx, fp, F, Fx, Fp = (np.asarray(v, dtype=float) for v in self.jac(x, p))
        dx = -np.linalg.solve(fx, fp[:, self.cols])
        return F.ravel(), Fx @ dx + Fp[:, self.cols]

    def flow(self, x: np.ndarray, p: np.ndarray) -> float:
        """The no-load flow at state ``x``."""
        return float(np.asarray(self.jac(x, p)[2], dtype=float).ravel()[0])

    def small_signal(self, p: np.ndarray, i: float, guess: np.ndarray | None) -> tuple[float, float, np.ndarray]:
        """-90 deg and -3 dB frequencies [Hz] of the linearised flow response at current ``i``."""
        x, p = self.trim(i, p, guess)
        A, B = (np.asarray(v, dtype=float) for v in self.A_B(x, p))
        C, D = (np.asarray(v, dtype=float) for v in self.C_D(x, p))
        f = np.geomspace(1.0, 5000.0, 600)
        eye = np.eye(A.shape[0])
        H = np.array([(C @ np.linalg.solve(2j * np.pi * fk * eye - A, B) + D).item() for fk in f])
        phase = np.degrees(np.unwrap(np.angle(H)))
        gain = 20 * np.log10(np.abs(H) / np.abs(H[0]))
        response = FrequencyResponse(np.array([i]), f, gain, phase)
        return float(response.phase_crossing()[0]), float(response.bandwidth()[0]), x


def design_study(
    bench: BenchConditions | None = None,
    parameters: Sequence[str] | None = None,
    step: float = 0.01,
    progress: Callable[[str], None] | None = None,
    figures: Sequence[str] | None = None,
) -> DesignStudy:
    """Elasticities of the ``figures`` of :data:`FIGURES` (default all) to every physical parameter of the valve on
    ``bench`` (:class:`~hydroservo.analysis.servovalve_bench.BenchConditions`; None: Table 1 at 210 bar, 10 mA)
    (module notes). Figures are computed in groups: at rest, small signal, linearity, transient, hysteresis;
    a group none of whose figures is asked for is skipped.

    ``parameters`` default to every parameter of the valve that is a design choice (not :data:`NOT_DESIGN`)
    and not zero (an elasticity to a zero is not defined).
    """
    wanted = set(FIGURES) if figures is None else set(figures)
    if not wanted or wanted - set(FIGURES):
        raise ParameterError(f"design study: figures {sorted(wanted - set(FIGURES))}: expected some of {', '.join(FIGURES)}")
    if not (np.isfinite(step) and 1e-4 <= step <= 0.1):
        raise ParameterError(f"step = {step!r}: expected a relative step between 1e-4 and 0.1")
    bench = BenchConditions() if bench is None else bench
    i_rated = bench.i_rated
    sv = bench_valve(bench.valve)
    names = [k for k in sv.PARAMETERS if k not in NOT_DESIGN and sv.values[k] != 0.0] if parameters is None else list(parameters)
    unknown = [n for n in names if n not in sv.PARAMETERS]
    if unknown:
        raise ParameterError(f"design study: {', '.join(unknown)}: not parameters of {type(sv).__name__}")
    values = np.array([sv.values[n] for n in names])
    rest = _Rest(bench, names)
    found: dict[str, float] = {}
    elasticity: dict[str, dict[str, float]] = {}

    def record(key: str, value: float, derivative: np.ndarray) -> None:
        if key not in wanted:
            return
        found[key] = float(value)
        elasticity[key] = {}
        for n, v, d in zip(names, values, derivative, strict=True):
            elasticity[key][n] = float(d * v / value) if value != 0 else float("nan")

    def asked(*keys: str) -> bool:
        return bool(wanted & set(keys))

    if asked("rated_flow", "flapper_tip", "spool_travel", "leakage_null") and progress:
        progress("at rest (exact derivatives)")
    F, dF = rest.exact(i_rated)
    record("rated_flow", F[0], dF[0])
    record("flapper_tip", F[2], dF[2])
    record("spool_travel", F[3], dF[3])
    F0, dF0 = rest.exact(0.0)
    record("leakage_null", F0[1], dF0[1])

    if asked("f_90", "f_3db"):
        _small_signal(rest, names, values, step, i_rated, record, progress)
    if asked("linearity"):
        _linearity(rest, names, values, step, i_rated, record, progress)
    if asked("rise_time", "overshoot", "hysteresis"):
        _batches(bench, names, values, step, record, progress, asked("hysteresis"))
    return DesignStudy({k: found[k] for k in FIGURES if k in found}, {k: elasticity[k] for k in FIGURES if k in found})


def _small_signal(rest: _Rest, names: list[str], values: np.ndarray, step: float, i_rated: float,
                  record: Callable[[str, float, np.ndarray], None], progress: Callable[[str], None] | None) -> None:
    if progress:
        progress("small signal (linearised at 5 % of rated current)")
    i_small = 0.05 * i_rated
    f90, f3, x_small = rest.small_signal(rest.p, i_small, None)
    d90, d3 = np.zeros(len(names)), np.zeros(len(names))
    for j, col in enumerate(rest.cols):
        up, down = rest.p.copy(), rest.p.copy()
        up[col], down[col] = values[j] * (1 + step), values[j] * (1 - step)
        a90, a3, _ = rest.small_signal(up, i_small, x_small)
        b90, b3, _ = rest.small_signal(down, i_small, x_small)
        d90[j] = (a90 - b90) / (2 * step * values[j])
        d3[j] = (a3 - b3) / (2 * step * values[j])
    record("f_90", f90, d90)
    record("f_3db", f3, d3)


def _linearity(rest: _Rest, names: list[str], values: np.ndarray, step: float, i_rated: float,
               record: Callable[[str, float, np.ndarray], None], progress: Callable[[str], None] | None) -> None:
    if progress:
        progress("linearity (41 currents at rest, each parameter +-1 %)")
    currents = np.linspace(-1.0, 1.0, 41) * i_rated  # as the bench's static test
    null_state, _ = rest.trim(0.0, rest.p)
    base_states = [(0.0, null_state)]
    for side in (1.0, -1.0):  # each side from null outwards, each point from the last
        guess = null_state
        for i in sorted((c for c in currents if c * side > 0), key=abs):
            guess, _ = rest.trim(float(i), rest.p, guess)
            base_states.append((float(i), guess))
    base_states.sort(key=lambda pair: pair[0])

    def linearity(p: np.ndarray) -> float:
        flows = []
        for i, x0 in base_states:
            x, pp = rest.trim(i, p, x0)
            flows.append(rest.flow(x, pp))
        flows_a = np.array(flows)
        rated = flows_a[-1]
        return float(np.max(np.abs(flows_a - rated * currents / i_rated)) / abs(rated))

    d_lin = np.zeros(len(names))
    for j, col in enumerate(rest.cols):
        up, down = rest.p.copy(), rest.p.copy()
        up[col], down[col] = values[j] * (1 + step), values[j] * (1 - step)
        d_lin[j] = (linearity(up) - linearity(down)) / (2 * step * values[j])
    record("linearity", linearity(rest.p), d_lin)


def _batches(bench: BenchConditions, names: list[str], values: np.ndarray, step: float,
             record: Callable[[str, float, np.ndarray], None], progress: Callable[[str], None] | None,
             hysteresis: bool) -> None:
    """The transient and the hysteresis: the design point and each parameter +-step, simulated in batches."""
    i_rated = bench.i_rated
    if progress:
        progress(f"transient (+-10 % square wave, {2 * len(names) + 1} runs at once)")
    frequency = 10.0
    system = bench_system(bench, Square(DRIVE, unit="A", amplitude=0.1 * i_rated, frequency=frequency), "none")
    grid = np.linspace(0.0, 2.0 / frequency, 2001)
    runs: dict[str, list[float]] = {f"{VALVE}.{n}": [] for n in names}  # the design point, then +- each parameter
    for j in range(-1, len(names)):
        for sign in ((0.0,) if j < 0 else (1.0, -1.0)):
            for k, n in enumerate(names):
                runs[f"{VALVE}.{n}"].append(values[k] * (1 + sign * step) if k == j else values[k])
    batch = system.batch(runs, t_eval=grid, max_steps=2_000_000)
    if batch.failed:
        k, why = next(iter(batch.failed.items()))
        raise SolverError(f"design study, square wave run {k}: {why}")
    flow = (batch[f"{VALVE}.QA"] - batch[f"{VALVE}.QB"]) / 2
    keep = (grid >= 1.0 / frequency - 1e-12) & (grid <= 1.5 / frequency + 1e-12)
    metrics = [step_metrics(grid[keep] - grid[keep][0], q[keep]) for q in flow]
    for key, metric in (("rise_time", "rise_time"), ("overshoot", "overshoot")):
        record(key, metrics[0][metric], _differences([m[metric] for m in metrics], values, step))
    if not hysteresis:
        return
    if progress:
        progress(f"hysteresis (1/16 Hz sine, {2 * len(names) + 1} runs at once)")
    slow = bench_system(bench, Sine(DRIVE, unit="A", amplitude=i_rated, frequency=1 / 16), "none")
    grid = np.linspace(0.0, 20.0, 5001)  # as the bench's hysteresis test
    batch = slow.batch(runs, t_eval=grid, max_steps=5_000_000)
    if batch.failed:
        k, why = next(iter(batch.failed.items()))
        raise SolverError(f"design study, slow sine run {k}: {why}")
    keep = grid >= 4.0 - 1e-9
    flow = (batch[f"{VALVE}.QA"] - batch[f"{VALVE}.QB"]) / 2
    current = i_rated * np.sin(2 * np.pi * grid[keep] / 16)
    loops = [hysteresis_loop(current, q[keep])[0] / i_rated for q in flow]
    record("hysteresis", loops[0], _differences(loops, values, step))


def _differences(results: Sequence[float], values: np.ndarray, step: float) -> np.ndarray:
    """Central differences from a batch laid out as: design point, then +step and -step of each parameter."""
    return np.array([(results[1 + 2 * j] - results[2 + 2 * j]) / (2 * step * values[j]) for j in range(len(values))])
