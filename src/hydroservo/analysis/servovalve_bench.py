"""A servovalve test bench (ISO 10770-1 / SAE ARP490 style) for any servovalve component.

The bench takes a servovalve as a component, current in and the four port
flows out (:class:`~hydroservo.components.TwoStageServovalve` at any of its
fidelities, or any component with the same ports), puts it between a supply
and a tank, and runs the tests a manufacturer runs:

* **static** (the valve at rest, solved by the model's trim at each current,
  continued outwards from null): the no-load flow-current characteristic,
  rated flow both ways, symmetry, linearity, flow gain near null, internal
  leakage at null;
* **blocked ports** (A and B closed, at rest): the load pressure against
  current, the pressure gain at null, and the internal leakage against
  current;
* **steps**: the square wave of [GordicND] Fig. 9 between -i and +i at
  10 Hz, for fractions of rated current: rise time and overshoot of the
  no-load flow, and how far the flapper goes (whether it reaches a nozzle);
* **hysteresis**: a slow sine of rated amplitude ([GordicND] Fig. 10: 1/16
  Hz), the flow-current loop and its widest current difference at equal
  flow;
* **threshold**: a slow triangle of ±2 % about half rated current, the
  current change after each reversal before the flow turns;
* **frequency response**: sines of several amplitudes, the fundamental of
  the no-load flow against the current's, in dB relative to the lowest
  frequency, with the -3 dB and -90 degree frequencies.

Pressures: ``p_s`` is the supply pressure as the paper states it, over a
return at ``p_0`` (Table 1: 1 bar absolute); the bench's gauge supply is
their difference and its tank is at 0. No load means both use ports at
half the two (eq. 57).
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from hydroservo.analysis.frequency import FrequencyResponse
from hydroservo.analysis.step import step_metrics
from hydroservo.components.base import Component
from hydroservo.components.signals import Sine, Square, Step, Table
from hydroservo.components.sources import ConstantPressure, Tank
from hydroservo.components.valves.two_stage import TwoStageServovalve
from hydroservo.components.volume import Volume
from hydroservo.errors import ModelError, ParameterError, SolverError, TrimError
from hydroservo.system.system import System

__all__ = [
    "BenchConditions",
    "bench_valve",
    "bench_system",
    "StaticTests",
    "static_tests",
    "BlockedTests",
    "blocked_tests",
    "StepTest",
    "step_tests",
    "Hysteresis",
    "hysteresis_test",
    "Threshold",
    "threshold_test",
    "Bode",
    "frequency_test",
    "Report",
    "bench_report",
]

#: The valve's name inside the bench.
VALVE = "sv"
#: The drive's name inside the bench.
DRIVE = "cur"


def bench_valve(valve: Component | None) -> Component:
    """A copy of ``valve`` named as the bench names it (None: Table 1); refused if it is not a servovalve (a current
    input ``i``, hydraulic ports P, T, A, B)."""
    if valve is None:
        valve = TwoStageServovalve(VALVE)
    needed = {"i"} <= set(valve.INPUTS) and {"P", "T", "A", "B"} <= set(valve.HYDRAULIC)
    if not needed:
        raise ModelError(
            f"{type(valve).__name__} {valve.name!r} is not a servovalve: a bench needs a current input 'i' and "
            "hydraulic ports P, T, A and B"
        )
    new = copy.deepcopy(valve)
    new.name = VALVE
    return new


@dataclass(frozen=True)
class BenchConditions:
    """A servovalve on the test bench: the valve, its supply and return pressures and its rated current.

    The one place these are checked; every test of this module takes one (None: :class:`TwoStageServovalve`
    with Table 1 of [GordicND] at 210 bar and 10 mA, returning to 1 bar absolute).

    Attributes
    ----------
    valve : Component
        The servovalve: a current input ``i`` and hydraulic ports P, T, A, B.
    p_s : float
        Supply pressure, absolute [Pa].
    i_rated : float
        Rated current [A].
    p_0 : float
        Return pressure, absolute [Pa].
    """

    valve: Component = field(default_factory=lambda: TwoStageServovalve(VALVE))
    p_s: float = 210e5
    i_rated: float = 0.01
    p_0: float = 1e5

    def __post_init__(self) -> None:
        bench_valve(self.valve)  # refuses a component that is not a servovalve
        p_s, p_0 = self.p_s, self.p_0
        if not (np.isfinite(p_s) and np.isfinite(p_0) and p_s > p_0 >= 0):
            raise ParameterError(f"supply p_s = {p_s:g} Pa over return p_0 = {p_0:g} Pa: expected p_s > p_0 >= 0")
        _check_current(self.i_rated)

    @classmethod
    def of(
        cls,
        valve: Component | None,
        supply: float | str = "210 bar",
        current: float | str = "10 mA",
        p_0: float = 1e5,
        *,
        supply_what: str = "--supply",
        current_what: str = "--current",
    ) -> BenchConditions:
        """The conditions from quantities with units (``"210 bar"``, ``"10 mA"``) or SI numbers; an error names
        the input (``supply_what``, ``current_what``) and what was expected."""
        from hydroservo.units import to_si

        p_s = to_si(supply, "Pa", what=supply_what)
        if not p_s > p_0 + 1e5:
            raise ParameterError(
                f"{supply_what} {supply!r}: expected above the return (1 bar absolute, Table 1's p_0), e.g. '210 bar'"
            )
        i_rated = to_si(current, "A", what=current_what)
        if not i_rated > 0:
            raise ParameterError(f"{current_what} {current!r}: expected a positive rated current, e.g. '10 mA'")
        return cls(TwoStageServovalve(VALVE) if valve is None else valve, p_s, i_rated, p_0)


def _conditions(bench: BenchConditions | None) -> BenchConditions:
    return BenchConditions() if bench is None else bench


def bench_system(bench: BenchConditions | None, drive: Component, load: str = "none") -> System:
    """The valve on the bench: ``drive`` (a signal in A) feeds its current; supply at ``p_s - p_0`` (gauge);
    ``load`` "none" (both use ports at half supply, eq. 57) or "blocked" (each use port into a closed 1 cm^3)."""
    bench = _conditions(bench)
    sv = bench_valve(bench.valve)
    gauge = bench.p_s - bench.p_0
    s = System(f"{type(sv).__name__} on the bench")
    s.add(sv)
    drive.name = DRIVE
    s.add(drive)
    s.add(ConstantPressure("supply", p=gauge))
    s.add(Tank("tank"))
    s.connect(f"{DRIVE}.y", f"{VALVE}.i")
    s.connect(f"{VALVE}.P", "supply.P")
    s.connect(f"{VALVE}.T", "tank.P")
    if load == "none":
        s.add(ConstantPressure("load_A", p=gauge / 2))
        s.add(ConstantPressure("load_B", p=gauge / 2))
    elif load == "blocked":
        s.add(Volume("load_A", V=1e-6, p0=gauge / 2))
        s.add(Volume("load_B", V=1e-6, p0=gauge / 2))
    else:
        raise ParameterError(f"load = {load!r}: expected 'none' or 'blocked'")
    s.connect(f"{VALVE}.A", "load_A.P")
    s.connect(f"{VALVE}.B", "load_B.P")
    return s


class _Rest:
    """The valve at rest at any current: the bench's trim, continued from the last solution."""

    def __init__(self, bench: BenchConditions | None, load: str) -> None:
        self.system = bench_system(bench, Step(DRIVE, unit="A", amplitude=0.0), load)
        self.model = self.system.build()
        self.p = self.system.parameter_vector()
        self.k_i = self.model.parameter_names.index(f"{DRIVE}.amplitude")

    def __call__(self, i: float, guess: np.ndarray | None) -> tuple[np.ndarray, dict[str, float]]:
        p = self.p.copy()
        p[self.k_i] = i
        try:
            trim = self.model.trim(p, x_guess=guess)
        except TrimError as exc:
            raise SolverError(f"servovalve at rest at i = {i * 1e3:.4g} mA: {exc}") from None
        x = np.array([trim[n] for n in self.model.state_names])
        y = np.asarray(self.model.outputs(0.0, x, p), dtype=float).ravel()
        return x, {**dict(zip(self.model.output_names, y.tolist())), **trim}

    def sweep(self, currents: Sequence[float]) -> list[dict[str, float]]:
        """The valve at rest at each current, each side of null solved outwards from null."""
        values = [float(c) for c in currents]
        x0, null = self(0.0, None)
        found: dict[int, dict[str, float]] = {}
        for side in (1.0, -1.0):
            guess = x0
            for k in sorted((k for k, i in enumerate(values) if i * side > 0), key=lambda k: abs(values[k])):
                guess, found[k] = self(values[k], guess)
        for k, i in enumerate(values):
            if i == 0.0:
                found[k] = null
        return [found[k] for k in range(len(values))]


def _signal(point: dict[str, float], name: str) -> float:
    return float(point[f"{VALVE}.{name}"])


@dataclass(frozen=True)
class StaticTests:
    """The no-load characteristic at rest and its figures (SI)."""

    p_s: float  #: supply pressure [Pa]
    i_rated: float  #: rated current [A]
    currents: np.ndarray  #: [A]
    flows: np.ndarray  #: no-load flow, (QA - QB)/2 [m^3/s]
    supply_flows: np.ndarray  #: flow drawn from supply [m^3/s]
    rated_flow: float  #: at +rated current [m^3/s]
    rated_flow_negative: float  #: at -rated current [m^3/s]
    symmetry: float  #: (``|Q+| - |Q-|``)/max [-]
    linearity: float  #: largest deviation from the rated line over the rated flow [-]
    flow_gain_null: float  #: dQ/di between -5 and +5 % of rated current [m^3/s/A]
    internal_leakage_null: float  #: flow from supply at zero current [m^3/s]

    def table(self) -> list[tuple[str, float, str]]:
        return [
            ("rated flow at +rated current", self.rated_flow * 6e4, "L/min"),
            ("rated flow at -rated current", self.rated_flow_negative * 6e4, "L/min"),
            ("symmetry", self.symmetry * 100, "%"),
            ("linearity (deviation from the rated line)", self.linearity * 100, "% of rated flow"),
            ("flow gain at null (+-5 % of rated current)", self.flow_gain_null * 6e4 / 1e3, "L/min/mA"),
            ("internal leakage at null", self.internal_leakage_null * 6e4, "L/min"),
        ]


def static_tests(
    bench: BenchConditions | None = None,
    points: int = 41
) -> StaticTests:
    """The no-load flow-current characteristic at rest, ``points`` currents from -rated to +rated."""
    bench = _conditions(bench)
    p_s, i_rated = bench.p_s, bench.i_rated
    if not 5 <= points <= 401:
        raise ParameterError(f"points = {points}: expected 5 to 401 currents")
    rest = _Rest(bench, "none")
    half = np.linspace(i_rated / (points // 2), i_rated, points // 2)
    small = 0.05 * i_rated
    currents = np.concatenate([-half[::-1], [0.0], half])
    found = rest.sweep([*currents, small, -small])
    no_load = np.array([(_signal(f, "QA") - _signal(f, "QB")) / 2 for f in found])
    supply = np.array([_signal(f, "QS") for f in found[: currents.size]])
    flows = no_load[: currents.size]
    q_plus, q_minus = flows[-1], flows[0]
    return StaticTests(
        p_s=p_s,
        i_rated=i_rated,
        currents=currents,
        flows=flows,
        supply_flows=supply,
        rated_flow=float(q_plus),
        rated_flow_negative=float(q_minus),
        symmetry=float((abs(q_plus) - abs(q_minus)) / max(abs(q_plus), abs(q_minus))),
        linearity=float(np.max(np.abs(flows - q_plus / i_rated * currents)) / abs(q_plus)),
        flow_gain_null=float((no_load[-2] - no_load[-1]) / (2 * small)),
        internal_leakage_null=float(supply[currents.size // 2]),
    )


@dataclass(frozen=True)
class BlockedTests:
    """Both use ports blocked, a slow current cycle through null: load pressure and internal leakage (SI).

    The cycle runs twice, the second time five times slower. A pressure gain that is a property of the
    valve at rest comes out the same; one that grows as the sweep slows is the speed of a jump, and is a
    lower bound: ``resolved`` says which (within 20 %).
    """

    p_s: float  #: supply pressure [Pa]
    i_rated: float  #: [A]
    frequency: float  #: of the slower sweep [Hz]
    currents: np.ndarray  #: over the slower cycle, from the positive peak [A]
    load_pressure: np.ndarray  #: p_A - p_B [Pa]
    leakage: np.ndarray  #: flow from supply [m^3/s]
    pressure_gain_null: float  #: d(p_A - p_B)/di where the load pressure crosses zero, slower sweep [Pa/A]
    pressure_gain_40: float  #: 80 % of supply over the current between -40 and +40 %, slower sweep [Pa/A]
    pressure_gain_40_fast: float  #: the same, five times faster sweep [Pa/A]
    null_width: float  #: current between the branches' zero crossings, slower sweep [A]
    leak_currents: np.ndarray  #: a slow cycle over the whole range of rated current [A]
    leak_flows: np.ndarray  #: flow from supply over it: the internal leakage [m^3/s]

    @property
    def resolved(self) -> bool:
        """The pressure gain does not depend on the sweep (within 20 %)."""
        a, b = self.pressure_gain_40, self.pressure_gain_40_fast
        return bool(np.isfinite(a) and np.isfinite(b) and abs(a - b) <= 0.2 * max(abs(a), abs(b)))

    def table(self) -> list[tuple[str, float, str]]:
        per_percent = self.i_rated / 100
        note = "" if self.resolved else " (a jump: at least)"
        return [
            ("pressure gain at null" + note, self.pressure_gain_null * per_percent / 1e5, "bar/% rated current"),
            ("pressure gain, +-40 % of supply" + note, self.pressure_gain_40 * per_percent / 1e5, "bar/% rated current"),
            ("load-pressure null, width between branches", self.null_width / self.i_rated * 100, "% rated current"),
            ("internal leakage, blocked ports, peak", float(np.max(self.leak_flows)) * 6e4, "L/min"),
            ("internal leakage, blocked ports, at rated current", float(self.leak_flows[0]) * 6e4, "L/min"),
        ]


def blocked_tests(
    bench: BenchConditions | None = None,
    span: float = 0.01,
    frequency: float = 0.5,
) -> BlockedTests:
    """A and B blocked (1 cm^3 each), the current a slow sine of ``span`` of rated current at ``frequency``,
    then five times slower (:class:`BlockedTests`).

    A bench does it so, and so must a model: where the load pressure rises (within a fraction of a per cent
    of rated current for a zero-lapped valve) the spool may rest anywhere inside the feedback ball's
    clearance, whose dead band gives each direction its own equilibrium; a trim would have to pick one.
    Each cycle starts at null; from its first peak, one falling and one rising branch are measured.
    """
    bench = _conditions(bench)
    p_s, i_rated, p_0 = bench.p_s, bench.i_rated, bench.p_0
    if not (np.isfinite(span) and 0 < span <= 1):
        raise ParameterError(f"span = {span!r}: expected a fraction of rated current in (0, 1]")
    if not (np.isfinite(frequency) and 1e-3 <= frequency <= 100):
        raise ParameterError(f"blocked-port sweep frequency = {frequency!r} Hz: expected 0.001 to 100 Hz")
    system = bench_system(bench, Sine(DRIVE, unit="A", amplitude=span * i_rated, frequency=1.0), "blocked")
    level = 0.4 * (p_s - p_0)
    cycles = []
    for f in (frequency, frequency / 5):
        period = 1.0 / f
        grid = np.linspace(0.0, 1.25 * period, 10001)
        r = system.simulate(t_eval=grid, params={f"{DRIVE}.frequency": f}, max_steps=5_000_000)
        keep = grid >= 0.25 * period - 1e-9
        i = r[f"{DRIVE}.y"][keep]
        p_L = (r["load_A.p"] - r["load_B.p"])[keep]
        turn = int(np.argmin(i))
        zeros, gains0, gains40 = [], [], []
        for bi, bp in ((i[: turn + 1][::-1], p_L[: turn + 1][::-1]), (i[turn:], p_L[turn:])):  # increasing current

            def at(value: float, bi: np.ndarray = bi, bp: np.ndarray = bp) -> float:
                return float(np.interp(value, *_monotone(bp, bi)))

            zeros.append(at(0.0))
            gains0.append(0.04 * level / max(at(0.02 * level) - at(-0.02 * level), 1e-30))
            spans = bp.max() > level and bp.min() < -level
            gains40.append(2 * level / max(at(level) - at(-level), 1e-30) if spans else np.nan)
        cycles.append((i, p_L, r[f"{VALVE}.QS"][keep], float(np.mean(gains0)), float(np.mean(gains40)),
                       float(abs(zeros[0] - zeros[1]))))
    (_, _, _, _, g40_fast, _), (i, p_L, leak, g0, g40, width) = cycles
    # the internal leakage over the whole range: a cycle of rated amplitude, from its positive peak
    period = 1.0 / frequency
    grid = np.linspace(0.0, 1.25 * period, 4001)
    r = system.simulate(
        t_eval=grid, params={f"{DRIVE}.frequency": frequency, f"{DRIVE}.amplitude": i_rated}, max_steps=5_000_000
    )
    keep = grid >= 0.25 * period - 1e-9
    return BlockedTests(
        p_s, i_rated, frequency / 5, i, p_L, leak, g0, g40, g40_fast, width, r[f"{DRIVE}.y"][keep], r[f"{VALVE}.QS"][keep]
    )


def _monotone(y: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(y, x) sorted by y, for interpolating x at a level of y along a branch that rises with x."""
    order = np.argsort(y, kind="stable")
    return y[order], x[order]


@dataclass(frozen=True)
class StepTest:
    """One square-wave test: -i to +i and back at ``frequency`` (the rising step is measured)."""

    fraction: float  #: of rated current [-]
    t: np.ndarray  #: [s], from the rising step
    current: np.ndarray  #: [A]
    flow: np.ndarray  #: no-load flow [m^3/s]
    flapper: np.ndarray  #: flapper-tip displacement [m] (NaN if the model has none)
    rise_time: float  #: 10-90 % of the flow change [s]
    overshoot: float  #: [%]
    settling_time: float  #: to 2 % [s]
    flapper_peak: float  #: largest ``|x|`` [m]
    reaches_nozzle: bool  #: ``|x|`` reached the null gap x_0
    x_0: float  #: the null gap [m] (NaN if the model has none)


def _check_current(i_rated: float) -> None:
    if not (np.isfinite(i_rated) and i_rated > 0):
        raise ParameterError(f"rated current = {i_rated!r} A: expected a positive current")


def step_tests(
    bench: BenchConditions | None = None,
    fractions: Sequence[float] = (0.05, 0.10, 0.25),
    frequency: float = 10.0,
) -> list[StepTest]:
    """[GordicND] Fig. 9: a square wave of each fraction of rated current, between -i and +i at ``frequency``.

    One period settles; the rising step of the second is measured on the no-load flow.
    """
    bench = _conditions(bench)
    i_rated = bench.i_rated
    if not (np.isfinite(frequency) and 0.1 <= frequency <= 1000):
        raise ParameterError(f"square-wave frequency = {frequency!r} Hz: expected 0.1 to 1000 Hz")
    out = []
    period = 1.0 / frequency
    for frac in fractions:
        if not (np.isfinite(frac) and 0 < frac <= 2):
            raise ParameterError(f"step fraction = {frac!r}: expected a fraction of rated current in (0, 2]")
        drive = Square(DRIVE, unit="A", amplitude=frac * i_rated, frequency=frequency)
        system = bench_system(bench, drive, "none")
        grid = np.linspace(0.0, 2 * period, 4001)
        r = system.simulate(t_eval=grid, max_steps=2_000_000)
        flow = (r[f"{VALVE}.QA"] - r[f"{VALVE}.QB"]) / 2
        has_tip = f"{VALVE}.x" in r.data or f"{VALVE}.x" in system.build().output_names
        tip = r[f"{VALVE}.x"] if has_tip else np.full(grid.size, np.nan)
        current = r[f"{DRIVE}.y"]
        start = period  # the second period's rising edge
        keep = (grid >= start - 1e-12) & (grid <= start + period / 2 + 1e-12)
        metrics = step_metrics(grid[keep] - start, flow[keep])
        x0 = system[VALVE].values.get("x_0", math.inf)
        peak = float(np.nanmax(np.abs(tip))) if has_tip else float("nan")
        out.append(
            StepTest(
                fraction=float(frac),
                t=grid[keep] - start,
                current=current[keep],
                flow=flow[keep],
                flapper=tip[keep],
                rise_time=metrics["rise_time"],
                overshoot=metrics["overshoot"],
                settling_time=metrics["settling_time"],
                flapper_peak=peak,
                reaches_nozzle=bool(has_tip and peak >= 0.999 * x0),
                x_0=float(x0) if math.isfinite(x0) else float("nan"),
            )
        )
    return out


@dataclass(frozen=True)
class Hysteresis:
    """The flow-current loop of a slow sine of rated amplitude (SI)."""

    frequency: float  #: [Hz]
    currents: np.ndarray  #: over the last period [A]
    flows: np.ndarray  #: [m^3/s]
    hysteresis: float  #: widest current difference at equal flow, over rated current [-]
    null_shift: float  #: the current at zero flow, mean of both branches [A]


def hysteresis_test(
    bench: BenchConditions | None = None,
    frequency: float = 1 / 16
) -> Hysteresis:
    """[GordicND] Fig. 10: a sine of rated amplitude at ``frequency`` (1/16 Hz); the second period is measured."""
    bench = _conditions(bench)
    i_rated = bench.i_rated
    drive = Sine(DRIVE, unit="A", amplitude=i_rated, frequency=frequency)
    system = bench_system(bench, drive, "none")
    period = 1.0 / frequency
    grid = np.linspace(0.0, 1.25 * period, 5001)
    r = system.simulate(t_eval=grid, max_steps=5_000_000)
    keep = grid >= 0.25 * period - 1e-9  # from the positive peak: one falling and one rising branch
    i = r[f"{DRIVE}.y"][keep]
    q = ((r[f"{VALVE}.QA"] - r[f"{VALVE}.QB"]) / 2)[keep]
    width, zero = hysteresis_loop(i, q)
    return Hysteresis(frequency, i, q, width / i_rated, zero)


def hysteresis_loop(i: np.ndarray, q: np.ndarray) -> tuple[float, float]:
    """The widest current difference at equal flow between the falling and the rising branch of a loop that
    starts at its positive peak, and the current at zero flow (the mean of both branches) [A]."""
    turn = int(np.argmin(i))
    down_i, down_q = i[: turn + 1][::-1], q[: turn + 1][::-1]  # falling branch, as increasing current
    up_i, up_q = i[turn:], q[turn:]
    lo, hi = max(down_q.min(), up_q.min()), min(down_q.max(), up_q.max())
    levels = np.linspace(lo, hi, 401)[5:-5]  # away from the turning points
    width = np.abs(_inverse(down_q, down_i, levels) - _inverse(up_q, up_i, levels))
    zero = 0.5 * (_inverse(down_q, down_i, np.array([0.0]))[0] + _inverse(up_q, up_i, np.array([0.0]))[0])
    return float(np.max(width)), float(zero)


@dataclass(frozen=True)
class Threshold:
    """A slow triangle of small amplitude about a bias: how much the current reverses before the flow does (SI)."""

    bias: float  #: [A]
    amplitude: float  #: [A]
    t: np.ndarray  #: [s]
    currents: np.ndarray  #: [A]
    flows: np.ndarray  #: no-load flow [m^3/s]
    reversals: np.ndarray  #: current change after each reversal before the flow reverses [A]
    threshold: float  #: their mean, over rated current [-]


def threshold_test(
    bench: BenchConditions | None = None,
    bias: float = 0.5,
    amplitude: float = 0.02,
    period: float = 8.0,
) -> Threshold:
    """ISO 10770-1's threshold: a triangle of ``amplitude`` (of rated current) about ``bias``, ``period`` long.

    After each reversal of the current, the current change until the flow has turned too, by a hundredth of
    the triangle's flow swing from its extreme (the detection level, 0.04 % of rated current for the defaults,
    is subtracted); the mean over four reversals. The current first ramps to the triangle's low end in a
    quarter period.
    """
    bench = _conditions(bench)
    i_rated = bench.i_rated
    if not (0 <= bias < 1 and 0 < amplitude <= 0.25 and bias + amplitude <= 1):
        raise ParameterError(f"threshold bias {bias!r}, amplitude {amplitude!r}: expected fractions of rated current, "
                             "bias + amplitude at most 1")
    lo, hi, half = (bias - amplitude) * i_rated, (bias + amplitude) * i_rated, period / 2
    times = [0.0, period / 4] + [period / 4 + k * half for k in range(1, 6)]
    values = [0.0, lo] + [hi if k % 2 else lo for k in range(1, 6)]
    system = bench_system(bench, Table(DRIVE, unit="A", times=times, values=values), "none")
    grid = np.linspace(0.0, times[-1], 20001)
    r = system.simulate(t_eval=grid, max_steps=5_000_000)
    i = r[f"{DRIVE}.y"]
    q = (r[f"{VALVE}.QA"] - r[f"{VALVE}.QB"]) / 2
    level = 0.01 * (np.interp(hi, i[grid < times[2]], q[grid < times[2]]) - np.interp(lo, i[grid < times[2]], q[grid < times[2]]))
    found = []
    for k in range(2, 6):  # the reversals at times[2] ... times[5]
        start, end = np.searchsorted(grid, times[k]), np.searchsorted(grid, times[k + 1])
        sign = 1.0 if values[k] == hi else -1.0  # at a top the flow must fall
        seg_q, seg_i = q[start - 200 : end], i[start - 200 : end]
        extreme = np.maximum.accumulate(sign * seg_q)
        turned = np.flatnonzero(sign * seg_q <= extreme - abs(level))
        turned = turned[turned > 200]
        if turned.size:
            detect = abs(level) / abs(np.interp(0.5 * (lo + hi), i, q, period=None) / max(0.5 * (lo + hi), 1e-30))
            found.append(max(abs(values[k] - seg_i[int(turned[0])]) - detect, 0.0))
    reversals = np.array(found)
    return Threshold(bias * i_rated, amplitude * i_rated, grid, i, q, reversals,
                     float(np.mean(reversals)) / i_rated if reversals.size else float("nan"))


def _inverse(q: np.ndarray, i: np.ndarray, levels: np.ndarray) -> np.ndarray:
    """The current at which a monotone-in-current branch passes each flow level (interpolated)."""
    order = np.argsort(q)
    return np.interp(levels, q[order], i[order])


class Bode(FrequencyResponse):
    """No-load flow against current at several amplitudes (rows, fractions of rated current) and frequencies
    (columns, [Hz]): the gain relative to the lowest frequency [dB], the phase [deg]; ``info`` holds the
    low-frequency gains, the worst orbit mismatch and the points with no periodic response."""

    @property
    def f_3db(self) -> np.ndarray:
        """Per amplitude, the -3 dB frequency [Hz] (NaN: not reached): :meth:`FrequencyResponse.bandwidth`."""
        return self.bandwidth()

    @property
    def f_90(self) -> np.ndarray:
        """Per amplitude, the -90 deg frequency [Hz] (NaN: not reached): :meth:`FrequencyResponse.phase_crossing`."""
        return self.phase_crossing()

    def table(self) -> list[tuple[str, float, str]]:
        rows = []
        for a, f3, f9 in zip(self.amplitudes, self.f_3db, self.f_90, strict=True):
            rows.append((f"-3 dB frequency at +-{a * 100:g} %", float(f3), "Hz"))
            rows.append((f"-90 deg frequency at +-{a * 100:g} %", float(f9), "Hz"))
        return rows


#: Largest accepted mismatch of a periodic orbit of the frequency test (nominal magnitudes of the states): the
#: fundamental is then within about as much of its converged value, 0.02 dB.
ACCEPT = 2e-3


def frequency_test(
    bench: BenchConditions | None = None,
    amplitudes: Sequence[float] = (0.05, 0.25, 1.0),
    frequencies: Sequence[float] | np.ndarray | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> Bode:
    """Fundamental of the no-load flow against the current's, on the periodic orbit at each amplitude and frequency.

    A point without a periodic response (:meth:`~hydroservo.system.model.Model.periodic` finds none within
    :data:`ACCEPT` in 12 iterations: at full amplitude the flapper bounces on the nozzles) is NaN and listed in
    ``info["unsettled"]``; after two in a row, the higher frequencies of that amplitude are not tried.

    The orbit is found by shooting with the engine's stiff integrator (:meth:`hydroservo.system.model.Model.periodic`),
    each frequency starting from the orbit of the one before. The model is stiff (the spool's viscous friction
    against its mass, 1e6 1/s for Table 1), so the fixed-step periodic solver of :mod:`hydroservo.analysis.frequency`
    does not apply; and at large amplitudes the first stage saturates and the spool drifts to its mean over many
    periods, so "simulate until it repeats" is slow and uncertain.
    """
    bench = _conditions(bench)
    i_rated = bench.i_rated
    freqs = np.geomspace(5.0, 500.0, 19) if frequencies is None else np.asarray(frequencies, dtype=float)
    amps = np.asarray(amplitudes, dtype=float)
    if freqs.size < 2 or not np.all(np.isfinite(freqs)) or np.any(freqs <= 0) or np.any(np.diff(freqs) <= 0):
        raise ParameterError("frequencies: expected at least two increasing, positive frequencies [Hz]")
    if amps.size < 1 or not np.all((amps > 0) & (amps <= 2)):
        raise ParameterError("amplitudes: expected fractions of rated current in (0, 2]")
    system = bench_system(bench, Sine(DRIVE, unit="A", amplitude=i_rated, frequency=1.0), "none")
    model = system.build()
    base = system.parameter_vector()
    k_amp, k_freq = (model.parameter_names.index(f"{DRIVE}.{k}") for k in ("amplitude", "frequency"))
    out_a, out_b = (model.output_names.index(f"{VALVE}.{k}") for k in ("QA", "QB"))
    H = np.zeros((amps.size, freqs.size), dtype=complex)
    n = 128
    done, worst = 0, 0.0
    unsettled: list[tuple[float, float, str]] = []
    for a, amp in enumerate(amps):
        guess = None
        for j, f in enumerate(freqs):
            if sum(1 for u in unsettled if u[0] == amp and u[1] >= freqs[max(j - 2, 0)]) >= 2:
                H[a, j] = np.nan  # two frequencies in a row without a periodic response: none above either
                unsettled.append((float(amp), float(f), "not tried: no periodic response at the two frequencies below"))
                done += 1
                if progress is not None:
                    progress(done, amps.size * freqs.size)
                continue
            p = base.copy()
            p[k_amp], p[k_freq] = amp * i_rated, f
            try:
                t, X, mismatch = model.periodic(p, 1.0 / f, n_points=n + 1, x_guess=guess, accept=ACCEPT, max_iter=12)
            except SolverError as exc:
                unsettled.append((float(amp), float(f), str(exc)))
                H[a, j] = np.nan
                done += 1
                if progress is not None:
                    progress(done, amps.size * freqs.size)
                continue
            guess = X[:, 0]
            worst = max(worst, mismatch)
            Y = np.asarray(model.outputs.map(n + 1)(t[None, :], X, p), dtype=float)
            flow = (Y[out_a] - Y[out_b]) / 2
            H[a, j] = _fundamental(t, flow[None, :], f, 0)[0] / (amp * i_rated)
            done += 1
            if progress is not None:
                progress(done, amps.size * freqs.size)
    gain = 20 * np.log10(np.abs(H) / np.abs(H[:, :1]))
    phase = np.degrees(np.unwrap(np.angle(H), axis=1))
    phase -= 360.0 * np.round(phase[:, :1] / 360.0)  # start within (-180, 180]
    return Bode(amps, freqs, gain, phase, "", {"low_frequency_gain": np.abs(H[:, 0]).tolist(), "mismatch": worst, "unsettled": unsettled})


def _fundamental(grid: np.ndarray, y: np.ndarray, f: float, k: int) -> np.ndarray:
    """Complex amplitude of the fundamental of each row of ``y`` over period ``k`` (relative to sin(2 pi f t))."""
    n = (grid.size - 1) // int(round(grid[-1] * f))
    sl = slice(k * n, (k + 1) * n)  # n samples of one period (the endpoint excluded: periodic rectangle rule)
    t = grid[sl]
    w = 2 * np.pi * f
    a = 2.0 / n * np.sum(y[:, sl] * np.sin(w * t), axis=1)
    b = 2.0 / n * np.sum(y[:, sl] * np.cos(w * t), axis=1)
    return a + 1j * b


@dataclass
class Report:
    """Every bench test of one servovalve."""

    label: str
    p_s: float
    i_rated: float
    static: StaticTests | None = None
    blocked: BlockedTests | None = None
    steps: list[StepTest] | None = None
    hysteresis: Hysteresis | None = None
    threshold: Threshold | None = None
    bode: Bode | None = None

    def table(self) -> list[tuple[str, float, str]]:
        rows: list[tuple[str, float, str]] = []
        if self.static is not None:
            rows += self.static.table()
        if self.blocked is not None:
            rows += self.blocked.table()
        for st in self.steps or []:
            tag = f"step +-{st.fraction * 100:g} %"
            rows += [
                (f"{tag}: rise time (10-90 % of flow)", st.rise_time * 1e3, "ms"),
                (f"{tag}: overshoot", st.overshoot, "%"),
                (f"{tag}: largest flapper tip", st.flapper_peak * 1e6, "um"),
                (f"{tag}: flapper reaches a nozzle", float(st.reaches_nozzle), "yes=1"),
            ]
        if self.hysteresis is not None:
            rows += [
                ("hysteresis (slow sine of rated amplitude)", self.hysteresis.hysteresis * 100, "% of rated current"),
                ("null shift (current at zero flow)", self.hysteresis.null_shift * 1e3, "mA"),
            ]
        if self.threshold is not None:
            rows.append(("threshold (+-2 % triangle about 50 %)", self.threshold.threshold * 100, "% of rated current"))
        if self.bode is not None:
            rows += self.bode.table()
        return rows


#: The tests of a bench report, in the order they run.
TESTS = ("static", "blocked", "steps", "hysteresis", "threshold", "bode")


def bench_report(
    bench: BenchConditions | None = None,
    tests: Sequence[str] = TESTS,
    label: str = "",
    progress: Callable[[str], None] | None = None,
    points: int = 41,
) -> Report:
    """The chosen ``tests`` of :data:`TESTS` on one valve (``points`` currents in the static characteristic);
    ``progress(name)`` is called as each starts, and ``progress.count(done, total)``, if it has one, as the
    frequency test's periodic orbits are found."""
    bench = _conditions(bench)
    valve, p_s, i_rated = bench.valve, bench.p_s, bench.i_rated
    unknown = [t for t in tests if t not in TESTS]
    if unknown:
        raise ParameterError(f"tests {', '.join(unknown)}: unknown; expected some of {', '.join(TESTS)}")
    report = Report(label or type(bench_valve(valve)).__name__, p_s, i_rated)
    runs: dict[str, Callable[[], Any]] = {
        "static": lambda: static_tests(bench, points),
        "blocked": lambda: blocked_tests(bench),
        "steps": lambda: step_tests(bench),
        "hysteresis": lambda: hysteresis_test(bench),
        "threshold": lambda: threshold_test(bench),
        "bode": lambda: frequency_test(bench, progress=getattr(progress, "count", None)),
    }
    for name in TESTS:
        if name in tests:
            if progress is not None:
                progress(name)
            setattr(report, name, runs[name]())
    return report
