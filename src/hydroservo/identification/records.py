"""Records of a rig: one experiment's measured signals, each at its own sample times.

A rig's logger often samples at several rates ([Efe2014] Table 5.1: the
chamber and pump pressures at 40 Hz, the rod position and the valve signal at
200 Hz), so a :class:`Record` is a set of :class:`Channel` objects, each with
its own time vector, values in the unit the logger wrote and the file it came
from. Missing samples are NaN. Reading and writing the CSV files is
:mod:`hydroservo.io.records`; what is done with a record (calibration, the
identification procedures) is in the neighbouring modules.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from hydroservo.errors import ParameterError, UnitError, did_you_mean
from hydroservo.units import check_unit, coherent_unit, same_dimension, si_definition, si_unit

__all__ = ["Channel", "Record", "derivatives", "MAX_SAMPLES", "thinned"]

#: The most samples per channel that calibration and the identification procedures use: a channel with more is
#: thinned to every k-th sample (:func:`thinned`), so that a fit's cost is bounded whatever the record's length.
MAX_SAMPLES = 20_000


@dataclass(frozen=True)
class Channel:
    """One measured signal: sample times [s], values in :attr:`unit` (NaN: missing), and where it came from."""

    name: str
    t: np.ndarray
    values: np.ndarray
    unit: str = ""
    source: str = ""

    def __post_init__(self) -> None:
        where = self.where
        t = np.asarray(self.t, dtype=float).ravel()
        v = np.asarray(self.values, dtype=float).ravel()
        if t.size != v.size:
            raise ParameterError(f"{where}: {t.size} times for {v.size} values")
        if t.size < 2:
            raise ParameterError(f"{where}: {t.size} sample(s); a record needs at least two")
        if not np.all(np.isfinite(t)):
            k = int(np.argmax(~np.isfinite(t)))
            raise ParameterError(f"{where}: time of sample {k + 1} is {t[k]}; expected finite times [s]")
        steps = np.diff(t)
        if np.any(steps <= 0):
            k = int(np.argmax(steps <= 0))
            raise ParameterError(
                f"{where}: time does not increase at sample {k + 2} ({t[k + 1]:g} s after {t[k]:g} s); "
                "expected strictly increasing times"
            )
        if np.isfinite(v).sum() < 2:
            raise ParameterError(f"{where}: fewer than two samples with a value")
        try:
            check_unit(self.unit)
        except UnitError as exc:
            raise UnitError(f"{where}: unit {self.unit!r}: {exc}") from None
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "values", v)

    @property
    def where(self) -> str:
        """The channel as a message names it: its file and column."""
        return f"{self.source}: column {self.name!r}" if self.source else f"channel {self.name!r}"

    @property
    def valid(self) -> np.ndarray:
        """Which samples have a value."""
        return np.isfinite(self.values)

    @property
    def rate(self) -> float:
        """Median sample rate [Hz]."""
        return float(1.0 / np.median(np.diff(self.t)))

    def si(self) -> np.ndarray:
        """The values in the coherent SI unit of their dimension (``bar`` -> Pa, ``mm`` -> m)."""
        factor, offset, _ = si_definition(self.unit)
        return self.values * factor + offset

    def to(self, unit: str) -> np.ndarray:
        """The values in ``unit``; a :class:`UnitError` naming the channel if the dimensions differ."""
        if not same_dimension(self.unit, unit):
            raise UnitError(
                f"{self.where}: unit {si_unit(self.unit)!r} is not of the dimension of the model's signal "
                f"({si_unit(unit)!r}, SI {si_unit(coherent_unit(unit))!r}); expected a unit such as "
                f"{si_unit(coherent_unit(unit))!r}"
            )
        factor, offset, _ = si_definition(unit)
        return (self.si() - offset) / factor


@dataclass
class Record:
    """One experiment: measured channels by signal name, each at its own times.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0, 1, 5)
    >>> r = Record("step", {"load.x": Channel("load.x", t, 10 * t, "mm")})
    >>> r.span, float(r["load.x"].si()[-1])
    ((0.0, 1.0), 0.01)
    """

    name: str
    channels: dict[str, Channel] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not self.channels:
            raise ParameterError(f"record {self.name!r}: no signal columns besides the time")

    def __getitem__(self, name: str) -> Channel:
        try:
            return self.channels[name]
        except KeyError:
            raise ParameterError(
                f"record {self.name!r}: no signal {name!r}{did_you_mean(name, self.channels)}; it has "
                f"{', '.join(self.channels)}"
            ) from None

    def __contains__(self, name: object) -> bool:
        return name in self.channels

    @property
    def names(self) -> list[str]:
        return list(self.channels)

    @property
    def span(self) -> tuple[float, float]:
        """First and last sample time over all channels [s]."""
        return (
            float(min(c.t[0] for c in self.channels.values())),
            float(max(c.t[-1] for c in self.channels.values())),
        )

    def value_at(self, name: str, t: float, unit: str) -> float:
        """The channel ``name`` at time ``t`` (linear between samples with a value), in ``unit``."""
        ch = self[name]
        ok = ch.valid
        return float(np.interp(t, ch.t[ok], ch.to(unit)[ok]))

    def by_rate(self) -> dict[float, list[str]]:
        """Channel names grouped by sample times (rounded rate [Hz] -> names): one file each, as a logger writes."""
        groups: dict[bytes, list[str]] = {}
        for n, c in self.channels.items():
            groups.setdefault(c.t.tobytes(), []).append(n)
        return {round(self.channels[names[0]].rate, 6): names for names in groups.values()}


def thinned(record: Record, most: int = MAX_SAMPLES) -> tuple[Record, list[str]]:
    """``record`` with every channel of more than ``most`` samples thinned to every k-th sample (the fewest k that
    leaves at most ``most``), and what was done, one line per group of channels sampled together.

    Each sample kept is as it was logged (no averaging), so a signal's noise is unchanged; a fit on the samples
    kept has the standard errors of those samples, larger than the whole record would give (by about the square
    root of k). A record within the limit is returned as it is, with no lines.

    >>> import numpy as np
    >>> t = np.linspace(0, 1, 50_001)
    >>> rec, said = thinned(Record("long", {"load.x": Channel("load.x", t, t, "mm", "long.csv")}))
    >>> rec["load.x"].t.size
    16667
    >>> print(said[0])
    record 'long', long.csv: 50001 samples at 5e+04 Hz, more than the 20000 used: every 3rd kept (16667 samples, 1.667e+04 Hz); standard errors are those of the samples kept
    """
    if isinstance(most, bool) or not isinstance(most, int) or most < 2:
        raise ParameterError(f"max_samples = {most!r}: expected a whole number, 2 or more")
    if all(c.t.size <= most for c in record.channels.values()):
        return record, []
    channels: dict[str, Channel] = {}
    said: dict[tuple[str, int], str] = {}
    for name, ch in record.channels.items():
        n = ch.t.size
        if n <= most:
            channels[name] = ch
            continue
        k = -(-n // most)
        kept = Channel(name, ch.t[::k], ch.values[::k], ch.unit, ch.source)
        channels[name] = kept
        said.setdefault((ch.source, n), (
            f"record {record.name!r}{', ' + ch.source if ch.source else ''}: {n} samples at {ch.rate:.4g} Hz, more "
            f"than the {most} used: every {_ordinal(k)} kept ({kept.t.size} samples, {kept.rate:.4g} Hz); standard "
            "errors are those of the samples kept"
        ))
    return Record(record.name, channels), list(said.values())


def _ordinal(k: int) -> str:
    suffix = "th" if 10 <= k % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(k % 10, "th")
    return f"{k}{suffix}"


def derivatives(t: np.ndarray, x: np.ndarray, window: float, order: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Smoothed first and second time derivatives of the uniformly sampled ``x(t)``.

    A Savitzky-Golay filter (a local polynomial of degree ``order`` + 1 over a
    centred window of ``window`` seconds) differentiates without the lag of a
    causal filter: a centred window has none, which is how the lag of
    smoothing is accounted for in the friction estimate of [Efe2014] eq. 4.24.
    NaN samples are filled linearly first. Returns ``(dx/dt, d²x/dt²)``.
    """
    from scipy.signal import savgol_filter

    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    dt = np.diff(t)
    h = float(np.median(dt))
    if np.max(np.abs(dt - h)) > 1e-6 * h + 1e-12:
        raise ParameterError("derivatives: the samples must be equally spaced in time (resample the record first)")
    ok = np.isfinite(x)
    x = np.interp(t, t[ok], x[ok])
    n = max(order + 2, int(round(window / h)) | 1)  # an odd number of samples, more than the polynomial's degree
    if n > x.size:
        raise ParameterError(
            f"derivatives: a smoothing window of {window:g} s is {n} samples, more than the {x.size} recorded"
        )
    poly = order + 1
    v = savgol_filter(x, n, poly, deriv=1, delta=h, mode="interp")
    a = savgol_filter(x, n, poly, deriv=2, delta=h, mode="interp")
    return v, a

