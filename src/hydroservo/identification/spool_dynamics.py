r"""Spool dynamics fitted to amplitude-dependent Bode data ([FerreiraND] section 6).

Eq. (43): least squares on the gain [dB] at every amplitude and frequency,
the squared errors of the smallest amplitude weighted by four ("most of the
time valve action takes place around the central position"), over the model
parameters; then the pure delay from the phase (section 6.2).

Three model fidelities share the routine, so they can be compared on the same
data:

================  ==========================================================  =======================
``model``         component                                                   fitted parameters
================  ==========================================================  =======================
``rate-limited``  :class:`~hydroservo.components.SpoolRateLimited` (Fig. 11)  omega_n, zeta, L_v, L_a
``second-order``  :class:`~hydroservo.components.SpoolSecondOrder`            omega_n, zeta
``first-order``   :class:`~hydroservo.components.SpoolFirstOrder`             tau
================  ==========================================================  =======================

The gains are simulated (:mod:`hydroservo.analysis.frequency`) with exact
sensitivities, and the parameters are optimised in logarithmic coordinates
(they are all positive; a log step treats 1007 rad/s and 0.48 alike) by
SciPy's trust-region least squares. The delay then has a closed form: with
:math:`d_i` the model's phase minus the measured phase,
:math:`\Delta t = \sum w_i f_i d_i / (360 \sum w_i f_i^2)`, clipped at zero.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import least_squares

from hydroservo.analysis.frequency import FrequencyResponse, PeriodicResponse, gain_phase, wrap_degrees
from hydroservo.components.base import Component
from hydroservo.components.signals import Sine
from hydroservo.components.spools import SpoolFirstOrder, SpoolRateLimited, SpoolSecondOrder
from hydroservo.errors import ParameterError, SolverError
from hydroservo.system.system import System
from hydroservo.units import to_si

__all__ = [
    "SPOOL_MODELS",
    "SPOOL_COMPONENTS",
    "SpoolFit",
    "fidelity_of",
    "spool_system",
    "spool_response",
    "check_start",
    "fit_spool_dynamics",
]

_PENALTY_DB = 1e3

#: Fitted parameters (with units) of each model fidelity.
SPOOL_MODELS: dict[str, dict[str, str]] = {
    "rate-limited": {"omega_n": "rad/s", "zeta": "", "L_v": "1/s", "L_a": "1/s^2"},
    "second-order": {"omega_n": "rad/s", "zeta": ""},
    "first-order": {"tau": "s"},
}

#: The component of each model fidelity (a component that derives from one, such as the
#: ServoSolenoidValve, has its fidelity).
SPOOL_COMPONENTS: dict[str, type[Component]] = {
    "rate-limited": SpoolRateLimited,
    "second-order": SpoolSecondOrder,
    "first-order": SpoolFirstOrder,
}


def fidelity_of(component: type[Component]) -> str | None:
    """The spool-model fidelity a component type realises (:data:`SPOOL_COMPONENTS`), or None."""
    for model, cls in SPOOL_COMPONENTS.items():
        if issubclass(component, cls):
            return model
    return None


def spool_system(model: str = "rate-limited") -> tuple[System, str]:
    """A Sine driving one spool model (delay not simulated), and the name of its position output."""
    if model not in SPOOL_MODELS:
        raise ParameterError(f"spool model {model!r}: expected one of {', '.join(SPOOL_MODELS)}")
    system = System(f"spool-{model}", "sine test of a spool model")
    system.add(Sine("u"))
    if model == "rate-limited":
        system.add(SpoolRateLimited("spool", delay_model="none"))
        out = "spool.xs"
    elif model == "second-order":
        system.add(SpoolSecondOrder("spool", xv_max=1.0))
        out = "spool.xv"
    else:
        system.add(SpoolFirstOrder("spool", xv_max=1.0))
        out = "spool.xv"
    system.connect("u.y", "spool.u")
    return system, out


def _check_params(model: str, params: Mapping[str, Any], what: str) -> dict[str, float]:
    spec = SPOOL_MODELS[model]
    renamed = SPOOL_COMPONENTS[model].RENAMED  # former names, as older parameter files have them
    params = {renamed.get(k, k) if k not in spec else k: v for k, v in params.items()}
    unknown = sorted(set(params) - set(spec) - {"delay"})
    if unknown:
        raise ParameterError(
            f"{what}: unknown parameter(s) {', '.join(unknown)} of the {model} model; known: "
            f"{', '.join([*spec, 'delay'])}"
        )
    out = {}
    for k, v in params.items():
        unit = spec.get(k, "s")
        val = to_si(v, unit, what=f"{what}.{k}")
        if not val > 0 and not (k == "delay" and val == 0):
            raise ParameterError(f"{what}.{k} = {v!r}: expected a positive value [{unit or '-'}]")
        out[k] = val
    return out


def check_start(model: str, start: Mapping[str, Any]) -> dict[str, float]:
    """Starting values of a fit of ``model`` (units allowed), checked and in SI."""
    if model not in SPOOL_MODELS:
        raise ParameterError(f"spool model {model!r}: expected one of {', '.join(SPOOL_MODELS)}")
    return _check_params(model, start, "start")


def spool_response(
    params: Mapping[str, Any],
    amplitudes: Sequence[float] | np.ndarray,
    frequencies: Sequence[float] | np.ndarray,
    model: str = "rate-limited",
    steps_per_period: int = 256,
    label: str = "",
) -> FrequencyResponse:
    """Bode data of a spool model (amplitudes as fractions of stroke, frequencies [Hz]).

    ``params`` holds the model's parameters and optionally ``delay`` [s].
    """
    vals = _check_params(model, params, "spool")
    system, out = spool_system(model)
    engine = PeriodicResponse(system, "u", out, steps_per_period)
    p = system.parameter_vector({f"spool.{k}": v for k, v in vals.items() if k != "delay"})
    amps, freqs = np.asarray(amplitudes, dtype=float), np.asarray(frequencies, dtype=float)
    _check_amplitudes(amps)
    H, _ = engine.response(engine.parameters(p, amps, freqs))
    gain, phase = gain_phase(H.reshape(amps.size, freqs.size), freqs, vals.get("delay", 0.0))
    return FrequencyResponse(amps, freqs, gain, phase, label=label or model)


def _check_amplitudes(amps: np.ndarray) -> None:
    if not np.all(np.isfinite(amps)) or np.any(amps <= 0) or np.any(amps > 1):
        raise ParameterError(f"amplitudes {amps.tolist()}: expected fractions of the stroke in (0, 1] (5 % is 0.05)")


def _check_data(data: FrequencyResponse, model: str) -> None:
    """Refuse Bode data the model's parameters cannot be fitted to."""
    source = data.info.get("source") if isinstance(data.info, dict) else None
    where = f"Bode file {source!r}" if source else (f"Bode data {data.label!r}" if data.label else "Bode data")
    _check_amplitudes(data.amplitudes)
    f = data.frequencies
    if not np.all(np.isfinite(f)) or np.any(f <= 0) or np.any(np.diff(f) <= 0):
        raise ParameterError(f"{where}: frequencies {f.tolist()} Hz; expected positive, finite, increasing values")
    if not np.all(np.isfinite(data.gain_db)):
        i, j = np.argwhere(~np.isfinite(data.gain_db))[0]
        raise ParameterError(
            f"{where}: gain at {100 * data.amplitudes[i]:g} % and {f[j]:g} Hz is {data.gain_db[i, j]}; "
            "expected a finite gain [dB] at every point"
        )
    n_params = len(SPOOL_MODELS[model])
    if f.size < 3:
        raise ParameterError(
            f"{where}: {f.size} frequenc{'y' if f.size == 1 else 'ies'}; the {model} model needs at least 3 to place its bandwidth"
        )
    if model == "rate-limited" and data.amplitudes.size < 2:
        raise ParameterError(
            f"{where}: one amplitude; the rate limits of the rate-limited model show only as gains that differ "
            "between amplitudes: give at least 2"
        )
    if data.gain_db.size <= n_params:
        raise ParameterError(
            f"{where}: {data.gain_db.size} gains for the {n_params} parameters of the {model} model; "
            "expected more points than parameters"
        )


@dataclass
class SpoolFit:
    """Result of :func:`fit_spool_dynamics`.

    Attributes
    ----------
    model : str
    params : dict
        Fitted parameters (SI), ``delay`` included.
    data, response : FrequencyResponse
        The data and the fitted model's response at the same points.
    gain_error_db : ndarray
        Model minus data gain [dB], amplitudes x frequencies.
    phase_error_deg : ndarray
        Model minus data phase [deg] (NaN where the data have no phase).
    cost : float
        Eq. (43) at the optimum [dB^2].
    """

    model: str
    params: dict[str, float]
    data: FrequencyResponse
    response: FrequencyResponse
    gain_error_db: np.ndarray
    phase_error_deg: np.ndarray
    cost: float
    start: dict[str, float] = field(default_factory=dict)
    info: dict[str, Any] = field(default_factory=dict)

    def max_gain_error(self, f_max: float | None = None) -> float:
        """Largest ``|gain error|`` [dB] up to ``f_max`` [Hz] (all frequencies when None)."""
        sel = np.ones(self.data.frequencies.size, bool) if f_max is None else self.data.frequencies <= f_max
        return float(np.max(np.abs(self.gain_error_db[:, sel])))

    def summary(self) -> dict[str, Any]:
        units = {**SPOOL_MODELS[self.model], "delay": "s"}
        rms = np.sqrt(np.mean(self.gain_error_db**2, axis=1))
        return {
            "model": self.model,
            "parameters": dict(self.params),
            "units": {k: units[k] or "-" for k in self.params},
            "start": dict(self.start),
            "cost_dB2": self.cost,
            "gain_rms_dB": {f"{100 * a:g} %": float(r) for a, r in zip(self.data.amplitudes, rms)},
            "max_gain_error_dB_to_200Hz": self.max_gain_error(200.0),
            "max_gain_error_dB": self.max_gain_error(),
            "max_phase_error_deg": float(np.nanmax(np.abs(self.phase_error_deg)))
            if np.any(np.isfinite(self.phase_error_deg))
            else None,
            **self.info,
        }


def default_start(data: FrequencyResponse, model: str) -> dict[str, float]:
    """A start read off the data: bandwidths (-3 dB) of the smallest, middle and largest amplitude."""

    crossings = data.bandwidth()

    def bandwidth(i: int) -> float:  # not reached within the data: its highest frequency
        f = crossings[i]
        return float(f if np.isfinite(f) else data.frequencies[-1])

    a = data.amplitudes
    w_small = 2 * np.pi * bandwidth(0)
    if model == "first-order":
        return {"tau": 1.0 / w_small}
    start = {"omega_n": w_small, "zeta": 0.7}
    if model == "rate-limited":
        i_mid, i_big = a.size // 2, a.size - 1
        start["L_v"] = float(2 * np.pi * bandwidth(i_big) * a[i_big])
        start["L_a"] = float((2 * np.pi * bandwidth(i_mid)) ** 2 * a[i_mid])
    return start


def fit_spool_dynamics(
    data: FrequencyResponse,
    model: str = "rate-limited",
    start: Mapping[str, Any] | None = None,
    *,
    small_amplitude_weight: float = 4.0,
    fit_delay: bool = True,
    steps_per_period: int = 256,
) -> SpoolFit:
    """Fit a spool model to amplitude-dependent Bode data ([FerreiraND] eq. 43, then section 6.2).

    Parameters
    ----------
    data : FrequencyResponse
        Measured (or datasheet) gains and, for the delay, phases.
    model : {"rate-limited", "second-order", "first-order"}
    start : mapping, optional
        Starting values (units allowed); default :func:`default_start`.
    small_amplitude_weight : float
        Weight of the smallest amplitude's squared gain errors (the paper's 4).
    fit_delay : bool
        Fit the pure delay to the phase after the gain fit.

    Returns
    -------
    SpoolFit
    """
    if model not in SPOOL_MODELS:
        raise ParameterError(f"spool model {model!r}: expected one of {', '.join(SPOOL_MODELS)}")
    _check_data(data, model)
    names = list(SPOOL_MODELS[model])
    first = default_start(data, model)
    if start:
        first.update({k: v for k, v in _check_params(model, start, "start").items() if k != "delay"})
    system, out = spool_system(model)
    engine = PeriodicResponse(system, "u", out, steps_per_period)
    p_base = system.parameter_vector(None)
    idx = [engine.model.parameter_names.index(f"spool.{n}") for n in names]
    P0 = engine.parameters(p_base, data.amplitudes, data.frequencies)
    w = np.ones(data.amplitudes.size)
    w[int(np.argmin(data.amplitudes))] = small_amplitude_weight
    sw = np.repeat(np.sqrt(w), data.frequencies.size)
    g_meas = data.gain_db.ravel()
    cache: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}

    def evaluate(theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        key = theta.tobytes()
        if key not in cache:
            P = P0.copy()
            P[idx] = np.exp(theta)[:, None]
            try:
                H, dH = engine.response_sensitivity(P, idx)
            except SolverError:
                # a trial point where the fixed-step integration cannot follow (too stiff): reject the step
                return np.full(g_meas.size, _PENALTY_DB), np.zeros((g_meas.size, len(names)))
            r = sw * (20 * np.log10(np.abs(H)) - g_meas)
            # d(20 log10|H|)/dp = 20/ln10 Re(dH/H); times p for log coordinates
            J = sw[:, None] * (20 / np.log(10)) * np.real(dH / H[:, None]) * np.exp(theta)[None, :]
            cache.clear()
            cache[key] = (r, J)
        return cache[key]

    theta0 = np.log([first[n] for n in names])
    # Search within a factor of 30 of the start (damping ratio within [0.02, 10]).
    lower, upper = theta0 - np.log(30.0), theta0 + np.log(30.0)
    if "zeta" in names:
        i = names.index("zeta")
        lower[i], upper[i] = max(lower[i], np.log(0.02)), min(upper[i], np.log(10.0))
        theta0[i] = np.clip(theta0[i], lower[i] + 1e-9, upper[i] - 1e-9)
    t0 = time.perf_counter()
    sol = least_squares(
        lambda th: evaluate(th)[0],
        theta0,
        jac=lambda th: evaluate(th)[1],
        bounds=(lower, upper),
        method="trf",
        xtol=1e-12,
        ftol=1e-12,
        gtol=1e-12,
        max_nfev=200,
    )
    params = {n: float(v) for n, v in zip(names, np.exp(sol.x))}
    P = P0.copy()
    P[idx] = np.exp(sol.x)[:, None]
    H, _ = engine.response(P)
    H = H.reshape(data.amplitudes.size, data.frequencies.size)
    gain, phase0 = gain_phase(H, data.frequencies)
    delay = 0.0
    if fit_delay and np.any(np.isfinite(data.phase_deg)):
        delay = _fit_delay(phase0, data.phase_deg, data.frequencies, w)
    params["delay"] = delay
    phase = phase0 - 360.0 * data.frequencies * delay
    resp = FrequencyResponse(data.amplitudes, data.frequencies, gain, phase, label=f"{model} model")
    gain_err = gain - data.gain_db
    phase_err = wrap_degrees(phase - data.phase_deg)
    cost = float(np.sum(w[:, None] * gain_err**2))
    info = {"iterations": int(sol.nfev), "wall_time_s": time.perf_counter() - t0, "status": sol.message}
    return SpoolFit(model, params, data, resp, gain_err, phase_err, cost, dict(first), info)


def _fit_delay(phase_model: np.ndarray, phase_data: np.ndarray, freqs: np.ndarray, w: np.ndarray) -> float:
    """Least-squares pure delay [s] between model and measured phase (weights per amplitude)."""
    F = np.broadcast_to(freqs, phase_model.shape)
    W = np.broadcast_to(w[:, None], phase_model.shape)
    ok = np.isfinite(phase_data)
    d_raw = phase_model - phase_data
    delay = 0.0
    for _ in range(3):  # unwrap the difference around the current prediction
        pred = 360.0 * F * delay
        d = pred + wrap_degrees(d_raw - pred)
        delay = float(np.sum((W * F * d)[ok]) / (360.0 * np.sum((W * F**2)[ok])))
    return max(delay, 0.0)
