r"""Amplitude-dependent frequency response of a nonlinear system, by simulation.

[FerreiraND] section 6.1 (eqs. 41-42): drive the model with sines of several
amplitudes and frequencies, let the transient die out, extract the
fundamental of the output and report gain [dB] and phase [deg]. For a
nonlinear system (rate limits, saturations) the result depends on the
amplitude: it is a describing function, not a transfer function.

How it is computed
------------------
*Steady state by shooting.* A rate-limited system can carry a slowly decaying
offset for many periods (its small-signal gain is low while a limiter is
active), so "simulate long enough" is both slow and uncertain. Instead the
periodic orbit is found directly: with :math:`\Phi(z_0)` the state after one
period from :math:`z_0`, Newton's method solves :math:`\Phi(z_0) = z_0`, with the
exact Jacobian :math:`\partial\Phi/\partial z_0` from CasADi (after a few
plain periods from the system's initial state; a run whose Newton step does
not reduce the residual takes a plain period instead). Every run must reach
:math:`\|\Phi(z_0) - z_0\| < ` ``tol`` (states scaled by their nominal values),
or a :class:`~hydroservo.errors.SolverError` names the amplitude and frequency.

*One period, fixed grid.* Time is normalised by the period, so every run uses
the same ``steps_per_period`` classical Runge-Kutta steps, and all runs are
evaluated at once by a CasADi map over threads.

*Fundamental.* The output samples over one period on the periodic orbit are
projected on :math:`\sin` and :math:`\cos` of the drive (the trapezoidal rule,
exact for a periodic signal up to the grid's Nyquist harmonic). This is the
ideal band-pass filter the paper approximates.

*Delay.* A pure delay :math:`\Delta t` adds exactly :math:`-360 f\Delta t` deg of
phase and no gain; it is applied analytically (``delay=``), not simulated.

*Sensitivities.* For identification the derivatives of gain and phase with
respect to parameters come from the implicit-function theorem on the
periodic orbit, :math:`dz_0/dp = (I - \Phi_z)^{-1}\Phi_p`, again exact.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

import casadi as ca
import numpy as np

from hydroservo.components.signals import Sine
from hydroservo.errors import ModelError, ParameterError, SolverError, did_you_mean
from hydroservo.system.system import System
from hydroservo.units import to_si

__all__ = ["FrequencyResponse", "PeriodicResponse", "sine_response", "wrap_degrees"]


def wrap_degrees(phi: Any) -> np.ndarray:
    """Angles wrapped into (-180, 180] [deg]."""
    phi = np.asarray(phi, dtype=float)
    return 180.0 - np.mod(180.0 - phi, 360.0)


@dataclass
class FrequencyResponse:
    """Gain and phase at every amplitude (rows) and frequency (columns).

    Attributes
    ----------
    amplitudes : ndarray
        Input amplitudes, in the input's unit (for a valve: fraction of stroke).
    frequencies : ndarray
        [Hz].
    gain_db : ndarray
        :math:`20\\log_{10}(A_{out}/A_{in})` of the fundamental [dB] (eq. 42).
    phase_deg : ndarray
        Phase of the fundamental relative to the input [deg], unwrapped along frequency.
    """

    amplitudes: np.ndarray
    frequencies: np.ndarray
    gain_db: np.ndarray
    phase_deg: np.ndarray
    label: str = ""
    info: dict[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.amplitudes = np.asarray(self.amplitudes, dtype=float).ravel()
        self.frequencies = np.asarray(self.frequencies, dtype=float).ravel()
        shape = (self.amplitudes.size, self.frequencies.size)
        self.gain_db = np.asarray(self.gain_db, dtype=float).reshape(shape)
        self.phase_deg = np.asarray(self.phase_deg, dtype=float).reshape(shape)

    def crossing(self, level: float, of: str = "gain") -> np.ndarray:
        """Per amplitude, the first frequency [Hz] at which the gain [dB] (``of="gain"``) or the phase [deg]
        (``of="phase"``) falls through ``level``.

        Between the last sample above the level and the first at or below it, the frequency is interpolated
        linearly in log-frequency (as a Bode plot draws it). NaN where the curve never reaches the level, and
        NaN where its first sample is already at or below it (the crossing lies below the lowest frequency).

        >>> import numpy as np
        >>> f = np.geomspace(1.0, 1000.0, 61)
        >>> H = 1 / (1 + 1j * f / 100.0)  # a first-order lag: -3.01 dB and -45 deg at 100 Hz
        >>> r = FrequencyResponse([1.0], f, 20 * np.log10(abs(H)), np.degrees(np.angle(H)))
        >>> round(float(r.bandwidth()[0]), 1), round(float(r.crossing(-45.0, of="phase")[0]), 1)
        (99.7, 100.0)
        """
        if of not in ("gain", "phase"):
            raise ParameterError(f"crossing of {of!r}: expected 'gain' or 'phase'")
        values = self.gain_db if of == "gain" else self.phase_deg
        f = self.frequencies
        out = np.full(self.amplitudes.size, np.nan)
        for i, row in enumerate(values):
            below = np.flatnonzero(row <= level)
            if below.size == 0 or below[0] == 0:
                continue
            k = int(below[0])
            v0, v1 = row[k - 1], row[k]
            w = (level - v0) / (v1 - v0)
            out[i] = np.exp(np.log(f[k - 1]) + w * (np.log(f[k]) - np.log(f[k - 1])))
        return out

    def bandwidth(self, level_db: float = -3.0) -> np.ndarray:
        """Per amplitude, the frequency [Hz] where the gain falls through ``level_db`` (:meth:`crossing`)."""
        return self.crossing(level_db, of="gain")

    def phase_crossing(self, deg: float = -90.0) -> np.ndarray:
        """Per amplitude, the frequency [Hz] where the phase falls through ``deg`` (:meth:`crossing`)."""
        return self.crossing(deg, of="phase")

    def rows(self) -> list[tuple[float, float, float, float]]:
        """(frequency [Hz], amplitude [%], gain [dB], phase [deg]) per point."""
        return [
            (float(f), 100.0 * float(a), float(self.gain_db[i, j]), float(self.phase_deg[i, j]))
            for i, a in enumerate(self.amplitudes)
            for j, f in enumerate(self.frequencies)
        ]

    def plot(
        self,
        others: Sequence[FrequencyResponse] = (),
        *,
        title: str = "",
        file: str | Path | None = None,
        f_max: float | None = None,
    ) -> Any:
        """Bode plot, ``others`` dashed in the same colours (:func:`hydroservo.plotting.bode.plot_bode`)."""
        from hydroservo.plotting.bode import plot_bode

        return plot_bode(self, others, title=title, file=file, f_max=f_max)


class PeriodicResponse:
    """Compiled periodic-response evaluator of a system driven by a :class:`~hydroservo.components.Sine`.

    Parameters
    ----------
    system : System
        The system; ``source`` names its Sine component.
    source : str
        Name of the Sine component whose amplitude and frequency are varied.
    output : str
        Signal whose fundamental is measured: a state, an output or an alias.
    steps_per_period : int
        Runge-Kutta steps per period (256: gains within about 1e-3 dB of a
        tight-tolerance CVODES run for the spool of [FerreiraND]; check with a finer grid).
    """

    def __init__(self, system: System, source: str, output: str, steps_per_period: int = 256) -> None:
        if source not in system.components or not isinstance(system[source], Sine):
            raise ModelError(f"frequency response: {source!r} is not a Sine component of system {system.name!r}")
        if steps_per_period < 16:
            raise ParameterError(f"steps_per_period = {steps_per_period}: expected at least 16")
        self.system = system
        self.model = model = system.build()
        self.source, self.output, self.M = source, output, int(steps_per_period)
        names = model.parameter_names
        self.i_amp, self.i_freq = names.index(f"{source}.amplitude"), names.index(f"{source}.frequency")
        self.i_fixed = {names.index(f"{source}.{k}"): 0.0 for k in ("t_start", "phase")}
        nx, npar = model.nx, model.np
        if nx == 0:
            raise ModelError(f"frequency response: system {system.name!r} has no states")
        z0, p = ca.SX.sym("z0", nx), ca.SX.sym("p", npar)
        nominal = ca.DM(model.nominal)
        if output in model.state_names:
            idx = model.state_names.index(output)

            def signal(t: Any, z: Any) -> Any:
                return z[idx] * model.nominal[idx]
        elif output in model.output_names:
            idx = model.output_names.index(output)

            def signal(t: Any, z: Any) -> Any:
                return model.outputs(t, z * nominal, p)[idx]
        else:
            known = ", ".join(model.state_names + model.output_names)
            hint = did_you_mean(output, model.state_names + model.output_names)
            raise ModelError(f"frequency response: no signal {output!r}{hint}; signals: {known}")
        self.unit = model.units.get(output, "")
        T = 1.0 / p[self.i_freq]
        h = 1.0 / self.M

        def F(tau: float, z: Any) -> Any:
            return T * model.f(tau * T, z * nominal, p) / nominal

        z = z0
        a1 = b1 = y0 = 0.0
        for i in range(self.M):
            tau = i * h
            k1 = F(tau, z)
            k2 = F(tau + h / 2, z + h / 2 * k1)
            k3 = F(tau + h / 2, z + h / 2 * k2)
            k4 = F(tau + h, z + h * k3)
            z = z + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            tt = (i + 1) * h
            y = signal(tt * T, z)
            a1 = a1 + 2.0 / self.M * y * math.sin(2 * math.pi * tt)
            b1 = b1 + 2.0 / self.M * y * math.cos(2 * math.pi * tt)
            y0 = y0 + y / self.M
        c = ca.vertcat(a1, b1, y0)
        self._z0, self._p, self._zT, self._c = z0, p, z, c
        self._period = ca.Function("period", [z0, p], [z, ca.jacobian(z, z0)])
        self._coef = ca.Function("coef", [z0, p], [c])
        self._sens: ca.Function | None = None
        self._maps: dict[tuple[str, int], ca.Function] = {}
        self.threads = os.cpu_count() or 1

    def _map(self, name: str, n: int) -> ca.Function:
        key = (name, n)
        if key not in self._maps:
            if name == "sens" and self._sens is None:
                z0, p, zT, c = self._z0, self._p, self._zT, self._c
                self._sens = ca.Function("sens", [z0, p], [ca.jacobian(zT, p), ca.jacobian(c, z0), ca.jacobian(c, p)])
            # cast: the sensitivities, the one optional entry, are built just above when asked for
            fun = cast(ca.Function, {"period": self._period, "coef": self._coef, "sens": self._sens}[name])
            self._maps[key] = fun.map(n, "thread", self.threads)
        return self._maps[key]

    def parameters(self, p_base: np.ndarray, amplitudes: np.ndarray, frequencies: np.ndarray) -> np.ndarray:
        """Parameter matrix, one column per (amplitude, frequency) pair, amplitude-major."""
        amplitudes = np.asarray(amplitudes, dtype=float).ravel()
        frequencies = np.asarray(frequencies, dtype=float).ravel()
        if np.any(amplitudes <= 0) or np.any(frequencies <= 0):
            raise ParameterError("frequency response: expected positive amplitudes and frequencies")
        A, Fq = np.meshgrid(amplitudes, frequencies, indexing="ij")
        P = np.tile(np.asarray(p_base, dtype=float)[:, None], (1, A.size))
        P[self.i_amp], P[self.i_freq] = A.ravel(), Fq.ravel()
        for i, v in self.i_fixed.items():
            P[i] = v
        return P

    def orbit(self, P: np.ndarray, settle_periods: int = 2, tol: float = 1e-10, max_iter: int = 60) -> np.ndarray:
        """Scaled initial states of the periodic orbits, one column per run."""
        n = P.shape[1]
        nx = self.model.nx
        Z = np.asarray(self.model.x0.map(n)(P), dtype=float) / self.model.nominal[:, None]
        period = self._map("period", n)
        for _ in range(settle_periods):
            Z = np.asarray(period(Z, P)[0], dtype=float)
        self._check_step(Z, P)
        prev = np.full(n, np.inf)
        for _ in range(max_iter):
            ZT, J = period(Z, P)
            ZT = np.asarray(ZT, dtype=float)
            R = ZT - Z
            norm = np.max(np.abs(R), axis=0)
            if np.all(norm < tol):
                return Z
            Jm = np.asarray(J, dtype=float).reshape(nx, n, nx).transpose(1, 0, 2) - np.eye(nx)[None]
            try:
                step = np.linalg.solve(Jm, -R.T[:, :, None])[:, :, 0].T
            except np.linalg.LinAlgError:
                step = R
            newton = norm < prev  # the last Newton step helped: keep using Newton
            Z = np.where(norm < tol, Z, np.where(newton, Z + step, ZT))
            prev = norm
        bad = np.flatnonzero(norm >= tol)
        where = ", ".join(f"A = {P[self.i_amp, k]:g}, f = {P[self.i_freq, k]:g} Hz" for k in bad[:5])
        raise SolverError(
            f"frequency response of {self.system.name!r}: no periodic steady state found for {bad.size} run(s) "
            f"({where}); largest residual {norm.max():.2g} after {max_iter} iterations"
        )

    def _check_step(self, Z: np.ndarray, P: np.ndarray) -> None:
        """Refuse a grid on which the fastest mode (at the orbit's start) is beyond RK4's stability limit."""
        n = P.shape[1]
        X = Z * self.model.nominal[:, None]
        J = np.asarray(self.model.jac_x.map(n)(np.zeros(n), X, P), dtype=float)
        J = J.reshape(self.model.nx, n, self.model.nx).transpose(1, 0, 2)
        rho = np.max(np.abs(np.linalg.eigvals(J)), axis=1)
        h = 1.0 / (P[self.i_freq] * self.M)
        worst = int(np.argmax(rho * h))
        if rho[worst] * h[worst] > 2.5:  # RK4 is stable up to |lambda h| = 2.79 on the real axis
            need = int(np.ceil(rho[worst] / (2.5 * P[self.i_freq, worst])))
            raise SolverError(
                f"frequency response of {self.system.name!r}: at f = {P[self.i_freq, worst]:g} Hz the fastest mode "
                f"({rho[worst]:.3g} 1/s) needs more than {self.M} Runge-Kutta steps per period; "
                f"use steps_per_period >= {need}"
            )

    def response(self, P: np.ndarray, **orbit_kw: Any) -> tuple[np.ndarray, np.ndarray]:
        """Complex fundamental per unit input amplitude, and the output mean, per run."""
        Z = self.orbit(P, **orbit_kw)
        C = np.asarray(self._map("coef", P.shape[1])(Z, P), dtype=float)
        amp = P[self.i_amp]
        return (C[0] + 1j * C[1]) / amp, C[2]

    def response_sensitivity(self, P: np.ndarray, wrt: Sequence[int], **orbit_kw: Any) -> tuple[np.ndarray, np.ndarray]:
        """Complex response per run, and its derivatives with respect to parameters ``wrt`` (runs x len(wrt))."""
        n, nx = P.shape[1], self.model.nx
        Z = self.orbit(P, **orbit_kw)
        C = np.asarray(self._map("coef", n)(Z, P), dtype=float)
        _, Jz = self._map("period", n)(Z, P)
        Jp, Cz, Cp = (np.asarray(v, dtype=float) for v in self._map("sens", n)(Z, P))
        npar = self.model.np
        Jz = np.asarray(Jz, dtype=float).reshape(nx, n, nx).transpose(1, 0, 2)
        Jp = Jp.reshape(nx, n, npar).transpose(1, 0, 2)[:, :, list(wrt)]
        Cz = Cz.reshape(3, n, nx).transpose(1, 0, 2)[:, :2]
        Cp = Cp.reshape(3, n, npar).transpose(1, 0, 2)[:, :2, list(wrt)]
        dz = np.linalg.solve(np.eye(nx)[None] - Jz, Jp)  # (I - Phi_z)^-1 Phi_p
        dC = Cp + Cz @ dz  # (n, 2, len(wrt))
        amp = P[self.i_amp]
        H = (C[0] + 1j * C[1]) / amp
        dH = (dC[:, 0] + 1j * dC[:, 1]) / amp[:, None]
        return H, dH


def gain_phase(H: np.ndarray, frequencies: np.ndarray, delay: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Gain [dB] and phase [deg] of complex responses (rows: amplitudes), phase unwrapped along frequency."""
    gain = 20.0 * np.log10(np.abs(H))
    phase = np.degrees(np.unwrap(np.angle(H), axis=-1)) - 360.0 * np.asarray(frequencies) * delay
    return gain, phase


def sine_response(
    system: System,
    source: str,
    output: str,
    amplitudes: Sequence[float],
    frequencies: Sequence[float],
    params: Mapping[str, Any] | None = None,
    *,
    delay: float | str = 0.0,
    steps_per_period: int = 256,
    label: str = "",
) -> FrequencyResponse:
    """Amplitude-dependent frequency response of ``output`` to the Sine ``source`` ([FerreiraND] eqs. 41-42).

    Parameters
    ----------
    system : System
        Contains a Sine component named ``source``.
    source : str
        The Sine whose amplitude [its unit] and frequency [Hz] are swept.
    output : str
        Measured signal (state, output or alias).
    amplitudes : sequence of float
        Input amplitudes, SI / the source's unit.
    frequencies : sequence of float
        [Hz].
    params : mapping, optional
        Parameter values for the run ("comp.param" -> value, units allowed).
    delay : float or str
        Pure output delay added to the phase [s].
    steps_per_period : int
        Runge-Kutta steps per period.

    Returns
    -------
    FrequencyResponse
    """
    engine = PeriodicResponse(system, source, output, steps_per_period)
    P = engine.parameters(system.parameter_vector(params), np.asarray(amplitudes), np.asarray(frequencies))
    H, _ = engine.response(P)
    H = H.reshape(len(amplitudes), len(frequencies))
    gain, phase = gain_phase(H, np.asarray(frequencies), to_si(delay, "s", what="delay"))
    return FrequencyResponse(np.asarray(amplitudes), np.asarray(frequencies), gain, phase, label=label)
