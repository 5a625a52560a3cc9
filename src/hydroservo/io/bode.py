"""Bode data files: frequency, amplitude, gain and phase, one row per point.

::

    frequency [Hz], amplitude [%], gain [dB], phase [deg]
    10, 5, -0.02, -5.1

Header names are matched by their first word, units in brackets are checked
when given; the phase column may be missing or empty (gain-only data).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from hydroservo.analysis.frequency import FrequencyResponse
from hydroservo.errors import ParameterError, shorten
from hydroservo.io.files import csv_rows, plain_float, read_text

__all__ = ["read_bode", "write_bode"]


def write_bode(response: FrequencyResponse, path: str | Path) -> Path:
    """Write ``frequency [Hz], amplitude [%], gain [dB], phase [deg]``, the format :func:`read_bode` reads."""

    from hydroservo.io.results import write_table

    return write_table(path, ["frequency [Hz]", "amplitude [%]", "gain [dB]", "phase [deg]"], response.rows())


def read_bode(path: str | Path) -> FrequencyResponse:
    """Read Bode data: one row per point, columns frequency, amplitude (% of stroke), gain (dB), phase (deg).

    Points must form a full grid (every amplitude at every frequency).
    """

    path = Path(path)
    text = read_text(path, "Bode file", kind="table")
    reader = iter(csv_rows(text, f"Bode file {str(path)!r}"))
    try:
        header = next(reader)
    except StopIteration:
        raise ParameterError(f"Bode file {str(path)!r} is empty") from None
    expected = {"frequency": "hz", "amplitude": "%", "gain": "db", "phase": "deg"}
    cols: dict[str, int] = {}
    for i, name in enumerate(header):
        word = name.strip().split("[")[0].strip().lower()
        unit = name.split("[")[1].split("]")[0].strip().lower() if "[" in name else None
        if word in expected:
            if unit is not None and unit != expected[word]:
                raise ParameterError(
                    f"Bode file {str(path)!r}, column {name.strip()!r}: expected unit [{expected[word]}]"
                )
            cols[word] = i
    missing = [k for k in ("frequency", "amplitude", "gain") if k not in cols]
    if missing:
        raise ParameterError(
            f"Bode file {str(path)!r}: missing column(s) {', '.join(missing)}; expected "
            "'frequency [Hz], amplitude [%], gain [dB], phase [deg]' (phase optional)"
        )
    where = f"Bode file {str(path)!r}"
    data: list[list[float]] = []
    lines: list[int] = []
    for lineno, row in enumerate(reader, start=2):
        vals = []
        for key in ("frequency", "amplitude", "gain", "phase"):
            cell = row[cols[key]].strip() if key in cols and cols[key] < len(row) else ""
            if key == "phase" and not cell:
                vals.append(math.nan)  # gain-only data
                continue
            try:
                value = plain_float(cell)
            except ValueError:
                raise ParameterError(f"{where}, row {lineno}, {key}: {shorten(cell)!r} is not a number") from None
            if not math.isfinite(value):
                raise ParameterError(f"{where}, row {lineno}, {key} = {cell!r}: expected a finite number")
            vals.append(value)
        f, a, _, _ = vals
        if f <= 0:
            raise ParameterError(f"{where}, row {lineno}: frequency {f:g} Hz; expected a positive frequency")
        if not 0 < a <= 100:
            raise ParameterError(f"{where}, row {lineno}: amplitude {a:g} %; expected 0 < amplitude <= 100 % of stroke")
        data.append(vals)
        lines.append(lineno)
    if not data:
        raise ParameterError(f"{where}: no data rows")
    arr = np.array(data)
    seen: dict[tuple[float, float], int] = {}
    last: dict[float, tuple[float, int]] = {}
    for (f, a, g, p), lineno in zip(arr, lines, strict=True):
        if (f, a) in seen:
            first = seen[(f, a)]
            same = np.array_equal(arr[lines.index(first)], [f, a, g, p], equal_nan=True)
            raise ParameterError(
                f"{where}, row {lineno}: {f:g} Hz at {a:g} % again ({'the same as' if same else 'conflicting with'} "
                f"row {first}); expected one row per frequency and amplitude"
            )
        seen[(f, a)] = lineno
        if a in last and f <= last[a][0]:
            raise ParameterError(
                f"{where}, row {lineno}: {f:g} Hz after {last[a][0]:g} Hz (row {last[a][1]}) at {a:g} %; "
                "expected increasing frequencies for each amplitude"
            )
        last[a] = (f, lineno)
    freqs = np.unique(arr[:, 0])
    amps = np.unique(arr[:, 1])
    gain = np.full((amps.size, freqs.size), np.nan)
    phase = np.full_like(gain, np.nan)
    for f, a, g, p in arr:
        i, j = int(np.searchsorted(amps, a)), int(np.searchsorted(freqs, f))
        gain[i, j], phase[i, j] = g, p
    if np.any(np.isnan(gain)):
        i, j = np.argwhere(np.isnan(gain))[0]
        raise ParameterError(
            f"{where}: no gain at {amps[i]:g} % and {freqs[j]:g} Hz; expected every amplitude at every frequency"
        )
    return FrequencyResponse(amps / 100.0, freqs, gain, phase, label=path.stem, info={"source": str(path)})
