"""Stribeck friction (hydroservo.laws.friction)."""

from __future__ import annotations

import numpy as np

from hydroservo.laws.friction import stribeck


def test_stribeck_is_odd_and_smoothing_converges() -> None:
    # the friction parameters of Efe2014 Table 5.2 (F_v = 280, F_c0 = 78, F_s0 = 5, c_s = 0.01), but any would do:
    # the published table itself is checked in tests/validation/test_efe.py
    v = np.linspace(-0.2, 0.2, 41)
    exact = stribeck(v, 280.0, 78.0, 5.0, 0.01)
    np.testing.assert_allclose(exact, -stribeck(-v, 280.0, 78.0, 5.0, 0.01))
    smooth = stribeck(v, 280.0, 78.0, 5.0, 0.01, v_reg=1e-5)
    mask = np.abs(v) > 1e-3
    np.testing.assert_allclose(smooth[mask], exact[mask], rtol=1e-12)
