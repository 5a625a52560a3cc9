"""A virtual rig: records of any model, sampled as a logger samples them, with noise and quantisation.

It serves experiment design (what would a planned test show?) and the tests
of the calibration: records made from a model with known parameters, at
[Efe2014] Table 5.1's rates, with the noise and resolution of real sensors.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.errors import ParameterError, did_you_mean
from hydroservo.identification.records import Channel, Record
from hydroservo.units import same_dimension, si_unit, to_si

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["Sensor", "sample_times", "virtual_rig", "held_steps", "triangle", "EFE_SENSORS"]



@dataclass(frozen=True)
class Sensor:
    """How one signal is logged: sample ``rate`` [Hz], the ``unit`` written, Gaussian ``noise`` (standard
    deviation) and ``resolution`` (quantisation step), both in ``unit`` ("" : the model's unit)."""

    rate: float
    unit: str | None = None
    noise: float = 0.0
    resolution: float = 0.0

    def __post_init__(self) -> None:
        if not (isinstance(self.rate, (int, float)) and math.isfinite(self.rate) and self.rate > 0):
            raise ParameterError(f"sensor rate = {self.rate!r} Hz: expected a positive sample rate")
        for what in ("noise", "resolution"):
            v = getattr(self, what)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ParameterError(f"sensor {what} = {v!r}: expected a number ≥ 0 in the sensor's unit")


#: [Efe2014] Table 5.1's logger on the robot-arm model: its rates, with the noise of typical sensors (a 0.05 bar
#: pressure transducer, a 0.02 mm position sensor; the valve signal as the controller sent it).
EFE_SENSORS = {
    "cyl.pA": Sensor(40.0, "bar", 0.05),
    "cyl.pB": Sensor(40.0, "bar", 0.05),
    "supply.p": Sensor(40.0, "bar", 0.05),
    "load.x": Sensor(200.0, "mm", 0.02),
    "command.y": Sensor(200.0, ""),
}


def held_steps(
    levels: Sequence[float], hold: float, *, rest: float = 0.2, start: float = 0.1, rate: float = 200.0,
) -> tuple[list[float], list[float]]:
    """A valve-signal programme (``times`` [s], ``values``) for a :class:`~hydroservo.components.signals.Table`:
    after ``start`` seconds at 0, each of ``levels`` held for ``hold`` seconds, then 0 for ``rest`` seconds.

    Every change is a ramp over one sample period ``1/rate`` that starts on a sample, so a record of the signal
    at ``rate`` (linear between samples) replays it exactly.
    """
    dt = 1.0 / rate
    snap = lambda t: round(t * rate) / rate  # noqa: E731 - a sample instant
    t, times, values = snap(start), [0.0], [0.0]
    for level in levels:
        times += [t, t + dt, snap(t + hold), snap(t + hold) + dt]
        values += [0.0, float(level), float(level), 0.0]
        t = snap(t + hold + rest)
    times.append(t)
    values.append(0.0)
    return times, values


def triangle(peak: float, duration: float, *, start: float = 0.1, rest: float = 0.1) -> tuple[list[float], list[float]]:
    """A valve-signal sweep from 0 to ``peak`` and back over ``duration`` seconds, after ``start`` and before
    ``rest`` seconds at 0 (for the flow-coefficient test: slow, so that the rod moves quasi-steadily)."""
    return [0.0, start, start + duration / 2, start + duration, start + duration + rest], [0.0, 0.0, float(peak), 0.0, 0.0]


def sample_times(rate: float, t_end: float, t0: float = 0.0) -> np.ndarray:
    """``t0, t0 + 1/rate, ...`` up to ``t_end`` (included when it falls on a sample)."""
    n = int(math.floor((t_end - t0) * rate + 1e-9))
    return t0 + np.arange(n + 1) / rate


def virtual_rig(
    system: System,
    sensors: Mapping[str, Sensor],
    *,
    t_end: float | str | None = None,
    params: Mapping[str, Any] | None = None,
    seed: int | np.random.Generator | None = None,
    name: str | None = None,
    accuracy: float = 1e-7,
    initial: Any = "parameters",
) -> Record:
    """A record of ``system`` (with ``params`` changed) as the ``sensors`` log it.

    The model is integrated once, to ``accuracy`` (tighter than the default: a
    record is a reference), with output at every sensor's sample times; each
    signal then gets its sensor's noise (drawn from ``seed``) and is rounded
    to its resolution. Channels of one rate form one file when written
    (:func:`hydroservo.io.records.write_record`).

    Examples
    --------
    >>> import hydroservo as hs
    >>> arm = hs.load_model("robot-arm")
    >>> rec = virtual_rig(arm, {"load.x": Sensor(200, "mm", noise=0.01)}, t_end=0.5, seed=1)
    >>> rec["load.x"].t.size, rec["load.x"].unit
    (101, 'mm')
    """
    if not sensors:
        raise ParameterError("virtual rig: no sensors; expected a mapping signal -> Sensor(rate, unit, noise, resolution)")
    t_stop = system.t_end if t_end is None else to_si(t_end, "s", what="t_end")
    times = {sig: sample_times(s.rate, t_stop) for sig, s in sensors.items()}
    grid = np.unique(np.concatenate(list(times.values())))
    result = system.simulate(params=params, t_eval=grid, accuracy=accuracy, initial=initial, max_steps=5_000_000)
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    channels = {}
    for sig, sensor in sensors.items():
        if sig not in result.units:
            raise ParameterError(f"virtual rig: {sig!r} is not a signal of {system.name!r}{did_you_mean(sig, result.units)}")
        model_unit = result.units[sig]
        unit = model_unit if sensor.unit is None else sensor.unit
        if not same_dimension(unit, model_unit):
            raise ParameterError(
                f"virtual rig: {sig} in {unit!r}: expected a unit of the dimension of {si_unit(model_unit)!r}"
            )
        index = np.searchsorted(grid, times[sig])
        values = result.get(sig, unit)[index]
        if sensor.noise:
            values = values + rng.normal(0.0, sensor.noise, values.size)
        if sensor.resolution:
            values = sensor.resolution * np.round(values / sensor.resolution)
        channels[sig] = Channel(sig, times[sig], values, unit, "virtual rig")
    return Record(name or f"{system.name}-rig", channels)
