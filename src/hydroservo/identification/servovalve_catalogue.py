r"""Catalogue servovalve models (first, second, third order) fitted to a servovalve's small-signal behaviour.

The lower rungs of the servovalve fidelity ladder (docs/servovalve.md): a
:class:`~hydroservo.components.CatalogueServovalve` whose rated flow and
internal leakage come from the static bench and whose transfer function from
current to spool is fitted to a frequency response of the valve at one small
amplitude (the bench's :class:`~hydroservo.analysis.servovalve_bench.Bode`,
of a physical model or of a measurement), gain and phase together.

The transfer functions are those of the component, their gain relative to
the lowest frequency :math:`f_0` of the data (as the bench reports it; the
phase is absolute):

.. math:: G_1 = \frac{1}{\tau s + 1},\quad G_2 = \frac{\omega_n^2}{s^2 + 2\zeta\omega_n s + \omega_n^2},
          \quad G_3 = G_1 G_2,\qquad H(f) = G(j2\pi f)/|G(j2\pi f_0)|

fitted by least squares on the complex logarithm, :math:`\ln H_{model} - \ln
H_{data}` (its real part the gain in nepers, its imaginary part the phase in
radians), over the parameters' logarithms. Unlike
:func:`~hydroservo.identification.spool_dynamics.fit_spool_dynamics` (gain
only, then a delay, after [FerreiraND] eq. 43, by simulation at every
amplitude), a catalogue model is linear: its response has a closed form and
its phase is part of the fit.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from hydroservo.components.valves.catalogue import CatalogueServovalve
from hydroservo.errors import ParameterError

__all__ = ["ORDERS", "CatalogueFit", "catalogue_response", "fit_catalogue"]

#: The parameters of each order's transfer function.
ORDERS = {"1": ("tau",), "2": ("omega_n", "zeta"), "3": ("tau", "omega_n", "zeta")}


def catalogue_response(order: str, params: dict[str, float], frequencies: Any) -> np.ndarray:
    """The transfer function of ``order`` at ``frequencies`` [Hz] (complex, 1 at zero frequency)."""
    s = 2j * np.pi * np.asarray(frequencies, dtype=float)
    G = np.ones_like(s)
    if order in ("1", "3"):
        G = G / (params["tau"] * s + 1.0)
    if order in ("2", "3"):
        w, z = params["omega_n"], params["zeta"]
        G = G * w**2 / (s**2 + 2 * z * w * s + w**2)
    return G


@dataclass(frozen=True)
class CatalogueFit:
    """A fitted catalogue model and how well it follows the data it was fitted to."""

    order: str
    valve: CatalogueServovalve
    params: dict[str, float]  #: the transfer function's parameters (SI)
    frequencies: np.ndarray  #: of the data [Hz]
    gain_db: np.ndarray  #: the model's, relative to the lowest frequency [dB]
    phase_deg: np.ndarray  #: [deg]
    gain_error_db: float  #: largest ``|model - data|`` over the data [dB]
    phase_error_deg: float  #: [deg]


def fit_catalogue(
    bode: Any,
    order: str = "2",
    *,
    amplitude: int = 0,
    rated_flow: float,
    i_rated: float,
    dp_rated: float,
    leakage_null: float = 0.0,
    f_max: float | None = None,
) -> CatalogueFit:
    """Fit a :class:`~hydroservo.components.CatalogueServovalve` of ``order`` to row ``amplitude`` of ``bode``.

    Parameters
    ----------
    bode : Bode
        A frequency response (``frequencies`` [Hz], ``gain_db`` [dB relative to the first frequency],
        ``phase_deg`` [deg]; rows: amplitudes), e.g. :func:`hydroservo.analysis.servovalve_bench.frequency_test`.
    order : "1", "2" or "3"
    amplitude : int
        The row to fit (a small amplitude: the catalogue model is linear).
    rated_flow, i_rated, dp_rated : float
        The rated no-load flow [m^3/s] at rated current [A] with ``dp_rated`` [Pa] across the valve.
    leakage_null : float
        Internal leakage at null [m^3/s] (laminar, split over the edges).
    f_max : float, optional
        Fit only frequencies up to this [Hz].
    """
    from scipy.optimize import least_squares  # SciPy's optimiser where it is used: import stays fast

    order = str(order)
    if order not in ORDERS:
        raise ParameterError(f"order = {order!r}: expected 1, 2 or 3")
    f = np.asarray(bode.frequencies, dtype=float)
    gain = np.asarray(bode.gain_db, dtype=float)[amplitude]
    phase = np.asarray(bode.phase_deg, dtype=float)[amplitude]
    keep = np.isfinite(gain) & np.isfinite(phase) & (f <= (f_max if f_max is not None else np.inf))
    if keep.sum() < len(ORDERS[order]) + 1:
        raise ParameterError(
            f"fit_catalogue: {int(keep.sum())} usable frequencies at amplitude row {amplitude}; "
            f"order {order} needs at least {len(ORDERS[order]) + 1}"
        )
    f, gain, phase = f[keep], gain[keep], phase[keep]
    data = np.log(10.0) / 20.0 * gain + 1j * np.radians(phase)  # ln H
    names = ORDERS[order]
    f90 = float(np.interp(-90.0, phase[::-1], f[::-1])) if phase.min() < -90 else float(f[-1])
    start = {"tau": 1.0 / (2 * np.pi * f90), "omega_n": 2 * np.pi * f90, "zeta": 0.7}

    def unpack(z: np.ndarray) -> dict[str, float]:
        return {k: float(np.exp(v)) for k, v in zip(names, z, strict=True)}

    def model(params: dict[str, float]) -> np.ndarray:
        H = catalogue_response(order, params, f) / np.abs(catalogue_response(order, params, f[:1]))
        return np.log(np.abs(H)) + 1j * np.unwrap(np.angle(H))

    def residual(z: np.ndarray) -> np.ndarray:
        d = model(unpack(z)) - data
        return np.concatenate([d.real, d.imag])

    sol = least_squares(residual, np.log([start[k] for k in names]), method="trf", x_scale=1.0)
    params = unpack(sol.x)
    fitted = model(params)
    gain_m, phase_m = 20 / np.log(10.0) * fitted.real, np.degrees(fitted.imag)
    G_leak = leakage_null / dp_rated if dp_rated > 0 else 0.0
    valve = CatalogueServovalve(
        "sv", order=order, Q_N=rated_flow, dp_N=dp_rated, i_N=i_rated, G_leak=G_leak,
        **{k: v for k, v in params.items()},
    )
    return CatalogueFit(
        order, valve, params, f, gain_m, phase_m,
        float(np.max(np.abs(gain_m - gain))), float(np.max(np.abs(phase_m - phase))),
    )
