"""Step-response metrics: rise time, settling time, overshoot, peak, steady-state error.

The definitions are the usual ones of control engineering (as in MATLAB's
``stepinfo`` and Ogata, *Modern Control Engineering*, section 5-3), measured on
a sampled response from the step time ``t_step`` on:

* the step goes from ``y0`` (the response at ``t_step``) to ``y_final`` (the last
  sample, or a given value);
* **rise time**: from the first time the response reaches 10 % of the change
  to the first time it reaches 90 % (linear interpolation between samples);
* **settling time**: from ``t_step`` to the last time the response is outside
  ``band`` (2 %) of the change around ``y_final``; 0 if it never leaves it;
* **overshoot**: how far the response goes beyond ``y_final``, in the step's
  direction, in % of the change (0 if it never does);
* **peak** and **peak time**: the response furthest in the step's direction;
* **steady-state error**: ``reference - y_final``, when a reference is given.

A response that does not change (``y_final == y0``) has no rise or settling
time, and no overshoot: they are NaN. With a given ``y_final``, a response
still outside the band at its last sample has not settled: its settling time
is NaN (and so is the rise time of one that never reaches 90 %).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["METRICS", "step_metrics"]

#: The metrics and their units ("signal" is the unit of the response).
METRICS = {
    "rise_time": "s",
    "settling_time": "s",
    "overshoot": "%",
    "peak": "signal",
    "peak_time": "s",
    "final": "signal",
    "steady_state_error": "signal",
}


def _crossing(t: np.ndarray, s: np.ndarray, level: float) -> float:
    """First time the normalised response ``s`` (0 -> 1) reaches ``level``, interpolated; NaN if never."""
    above = np.flatnonzero(s >= level)
    if above.size == 0:
        return float("nan")
    k = int(above[0])
    if k == 0:
        return float(t[0])
    s0, s1 = s[k - 1], s[k]
    return float(t[k - 1] + (level - s0) / (s1 - s0) * (t[k] - t[k - 1]))


def step_metrics(
    t: Any,
    y: Any,
    *,
    t_step: float = 0.0,
    y_final: float | None = None,
    reference: float | None = None,
    band: float = 0.02,
) -> dict[str, float]:
    """Metrics of a step response ``y(t)`` (module notes); times in the unit of ``t``, from ``t_step``.

    Parameters
    ----------
    t, y : array_like
        Sample times [s] (increasing) and the response.
    t_step : float
        Time of the step [s].
    y_final : float, optional
        The value the response settles to (default: its last sample).
    reference : float, optional
        The commanded final value, for the steady-state error.
    band : float
        Settling band, a fraction of the change (0.02: 2 %).

    Returns
    -------
    dict
        :data:`METRICS` by name.

    Examples
    --------
    A first-order lag of time constant 1 s: rise time ln 9 = 2.197 s, 2 % settling time ln 50 = 3.912 s.

    >>> t = np.linspace(0.0, 20.0, 20001)
    >>> m = step_metrics(t, 1.0 - np.exp(-t), y_final=1.0)
    >>> round(m["rise_time"], 3), round(m["settling_time"], 3), m["overshoot"]
    (2.197, 3.912, 0.0)
    """
    t = np.asarray(t, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    keep = t >= t_step
    t, y = t[keep], y[keep]
    nan = float("nan")
    out = dict.fromkeys(METRICS, nan)
    if t.size < 2 or not np.all(np.isfinite(y)):
        return out
    y0 = float(y[0])
    yf = float(y[-1]) if y_final is None else float(y_final)
    change = yf - y0
    out["final"] = yf
    if reference is not None:
        out["steady_state_error"] = float(reference) - yf
    direction = 1.0 if change >= 0 else -1.0
    k = int(np.argmax(direction * y))
    out["peak"], out["peak_time"] = float(y[k]), float(t[k] - t_step)
    if change == 0 or not np.isfinite(change):
        return out
    s = (y - y0) / change  # 0 -> 1
    out["rise_time"] = _crossing(t, s, 0.9) - _crossing(t, s, 0.1)
    out["overshoot"] = max(0.0, float(np.max(s)) - 1.0) * 100.0
    outside = np.flatnonzero(np.abs(s - 1.0) > band)
    if outside.size == 0:
        out["settling_time"] = 0.0
    elif outside[-1] == s.size - 1:
        out["settling_time"] = nan  # not settled by the end of the record
    else:
        j = int(outside[-1])  # the last sample outside; the band is crossed between j and j + 1
        edge = 1.0 + band * np.sign(s[j] - 1.0)
        frac = (edge - s[j]) / (s[j + 1] - s[j])
        out["settling_time"] = float(t[j] + frac * (t[j + 1] - t[j]) - t_step)
    return out
