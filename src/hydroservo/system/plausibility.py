"""Physical plausibility of a run: results that no real circuit can give are flagged.

A model integrates whatever its parameters say, and a set far from any real
circuit (a piston driven through its end stops, an unloaded chamber
compressed to hundreds of MPa) still returns finite numbers. Components
declare the bounds of their signals (:class:`~hydroservo.components.base.Limit`);
after every run each bound is checked with the margins below, and every crossing
becomes an :class:`Implausible` on the result (``Result.warnings``). The CLI
prints them, ``--strict`` makes them an error (exit 2), and ``--json`` lists
them.

Margins (why these numbers: docs/reliability.md):

* A chamber pressure is flagged above the highest source pressure of the run
  by more than :data:`PRESSURE_MARGIN` (50 %) of that source's absolute
  pressure. A decelerating load or an overrunning load on the annulus of a
  differential cylinder legitimately pushes a chamber above the supply (the
  flight-simulator actuator of [FlightSimulatorND] peaks 8 % above it); half the
  supply again is beyond what relief valves and hoses let a real circuit see.
* A chamber pressure is flagged below vacuum (-101 325 Pa gauge) by more than
  :data:`VACUUM_MARGIN` (1 %) of the highest source's absolute pressure: a
  model without cavitation or replenishing check valves can pull a chamber
  below absolute zero, which oil cannot.
* A position is flagged beyond its end stops by more than :data:`TRAVEL_MARGIN`
  (1 %) of the stroke: an end stop modelled as a stiff spring yields a little,
  but not by a hundredth of the stroke.
* A chamber volume is flagged at or below zero.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from hydroservo.units import VACUUM

__all__ = ["PRESSURE_MARGIN", "VACUUM_MARGIN", "TRAVEL_MARGIN", "Watched", "Implausible", "check"]

#: Fraction of the highest source's absolute pressure a chamber may exceed that source by.
PRESSURE_MARGIN = 0.5
#: Fraction of the highest source's absolute pressure a chamber may fall below vacuum by.
VACUUM_MARGIN = 0.01
#: Fraction of the stroke a position may pass an end stop by.
TRAVEL_MARGIN = 0.01


@dataclass(frozen=True)
class Watched:
    """A signal of the model under a :class:`~hydroservo.components.base.Limit`."""

    signal: str  #: the result's signal name
    kind: str  #: "source", "relief", "flow-source", "pressure", "travel" or "volume"
    owner: str  #: the component that declared the limit
    lower: str | None = None  #: parameter of the lower bound (travel)
    upper: str | None = None  #: parameter of the upper bound (travel)
    hint: str = ""  #: what in the component lets the bound be crossed


@dataclass(frozen=True)
class Implausible:
    """A signal that crossed a physical bound: where, when, by how much."""

    signal: str
    time: float  #: [s] when the signal was furthest beyond the bound
    value: float  #: (SI) the signal there
    bound: float  #: (SI) the bound, margin included
    unit: str
    message: str

    def __str__(self) -> str:
        return self.message

    def to_dict(self) -> dict[str, Any]:
        return {
            "signal": self.signal,
            "time_s": self.time,
            "value": self.value,
            "bound": self.bound,
            "unit": self.unit,
            "message": self.message,
        }


def _hint(w: Watched) -> str:
    return f" ({w.owner}: {w.hint})" if w.hint else ""


def _extreme(t: np.ndarray, v: np.ndarray, high: bool) -> tuple[float, float]:
    k = int(np.argmax(v) if high else np.argmin(v))
    return float(t[k]), float(v[k])


def check(
    t: np.ndarray, watched: list[Watched], values: np.ndarray, lower: np.ndarray, upper: np.ndarray
) -> list[Implausible]:
    """Flag the crossings of one run.

    ``values`` has one row per watched signal and one column per output time;
    ``lower`` and ``upper`` one bound per watched signal (NaN where a limit has none).
    """
    found: list[Implausible] = []
    sources = [i for i, w in enumerate(watched) if w.kind == "source"]
    if any(w.kind == "flow-source" for w in watched):  # a flow whatever the pressure: relief valves bound it
        sources += [i for i, w in enumerate(watched) if w.kind == "relief"]
    ceiling = source = None
    if sources:
        peaks = [float(np.max(values[i])) for i in sources]
        j = int(np.argmax(peaks))
        ceiling, source = peaks[j], watched[sources[j]].signal
    for i, w in enumerate(watched):
        v = values[i]
        if w.kind == "pressure" and ceiling is not None:
            absolute = ceiling - VACUUM
            high = ceiling + PRESSURE_MARGIN * absolute
            if np.max(v) > high:
                tk, vk = _extreme(t, v, True)
                found.append(
                    Implausible(
                        w.signal, tk, vk, high, "Pa",
                        f"{w.signal} = {vk / 1e6:.4g} MPa at t = {tk:.6g} s: more than {PRESSURE_MARGIN:.0%} above "
                        f"the highest source pressure ({source} = {ceiling / 1e6:.4g} MPa; flagged above "
                        f"{high / 1e6:.4g} MPa)",
                    )
                )
            low = VACUUM - VACUUM_MARGIN * absolute
            if np.min(v) < low:
                tk, vk = _extreme(t, v, False)
                found.append(
                    Implausible(
                        w.signal, tk, vk, low, "Pa",
                        f"{w.signal} = {vk / 1e6:.4g} MPa (gauge) at t = {tk:.6g} s: below vacuum "
                        f"({VACUUM / 1e6:.4g} MPa gauge), which oil cannot reach{_hint(w)}",
                    )
                )
        elif w.kind == "travel":
            lo, hi = float(lower[i]), float(upper[i])
            slack = TRAVEL_MARGIN * (hi - lo)
            for beyond, bound, name, high_side in (
                (np.max(v) > hi + slack, hi + slack, w.upper, True),
                (np.min(v) < lo - slack, lo - slack, w.lower, False),
            ):
                if beyond:
                    tk, vk = _extreme(t, v, high_side)
                    stop = hi if high_side else lo
                    found.append(
                        Implausible(
                            w.signal, tk, vk, bound, "m",
                            f"{w.signal} = {vk:.4g} m at t = {tk:.6g} s: beyond {w.owner}'s end stop "
                            f"{w.owner}.{name} = {stop:.4g} m by more than {TRAVEL_MARGIN:.0%} of the stroke"
                            f"{_hint(w)}",
                        )
                    )
        elif w.kind == "volume" and np.min(v) <= 0:
            tk, vk = _extreme(t, v, False)
            found.append(
                Implausible(
                    w.signal, tk, vk, 0.0, "m^3",
                    f"{w.signal} = {vk:.4g} m³ at t = {tk:.6g} s: a chamber volume at or below zero",
                )
            )
    return found
