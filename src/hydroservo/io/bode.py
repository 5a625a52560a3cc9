"""Bode data files: frequency, amplitude, gain and phase, one row per point.

::

    frequency [Hz], amplitude [%], gain [dB], phase [deg]
    10, 5, -0.02, -5.1

Header names are matched by their first word, units in brackets are checked
when given; the phase column may be missing or empty (gain-only data).
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from hydroservo.analysis.frequency import FrequencyResponse
from hydroservo.errors import ParameterError
from hydroservo.io.files import read_text

__all__ = ["read_bode", "write_bode"]


def write_bode(response: FrequencyResponse, path: str | Path) -> Path:
    """Write ``frequency [Hz], amplitude [%], gain [dB], phase [deg]``, the format :func:`read_bode` reads."""

    path = Path(path)
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["frequency [Hz]", "amplitude [%]", "gain [dB]", "phase [deg]"])
        for row in response.rows():
            w.writerow([f"{v:.10g}" for v in row])
    return path



def read_bode(path: str | Path) -> FrequencyResponse:
    """Read Bode data: one row per point, columns frequency, amplitude (% of stroke), gain (dB), phase (deg).

    Points must form a full grid (every amplitude at every frequency).
    """

    path = Path(path)
    text = read_text(path, "Bode file")
    reader = csv.reader(line for line in text.splitlines() if line.strip() and not line.startswith("#"))
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
    data = []
    for lineno, row in enumerate(reader, start=2):
        try:
            vals = [float(row[cols[k]]) for k in ("frequency", "amplitude", "gain")]
            ph = row[cols["phase"]].strip() if "phase" in cols and cols["phase"] < len(row) else ""
            vals.append(float(ph) if ph else math.nan)
        except (ValueError, IndexError):
            raise ParameterError(f"Bode file {str(path)!r}, row {lineno}: expected numbers, got {row}") from None
        data.append(vals)
    if not data:
        raise ParameterError(f"Bode file {str(path)!r}: no data rows")
    arr = np.array(data)
    if np.any(arr[:, 0] <= 0) or np.any(arr[:, 1] <= 0):
        raise ParameterError(f"Bode file {str(path)!r}: expected positive frequencies and amplitudes")
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
            f"Bode file {str(path)!r}: no gain at {amps[i]:g} % and {freqs[j]:g} Hz; expected every amplitude at "
            "every frequency"
        )
    return FrequencyResponse(amps / 100.0, freqs, gain, phase, label=path.stem)
