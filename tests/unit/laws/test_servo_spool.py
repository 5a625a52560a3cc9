"""The servovalve spool's laws ([GordicND] eqs. 43-56) against hand computations and their own limits."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.laws import servo_spool as sp

EDGES = {"delta": 4e-6, "r_s": 10e-6, "r_b": 10e-6}


def test_openings_open_with_their_sign_of_travel():
    y = 0.1e-3
    open_ = [float(sp.real_opening(y, i, **EDGES)) for i in (1, 2, 3, 4)]
    assert open_[1] == open_[3] == 0.0 and open_[0] == open_[2] > y
    assert float(sp.real_opening(0.0, 1, **EDGES)) == pytest.approx(np.hypot(24e-6, 20e-6) - 20e-6)
    # an underlap opens the edge before the spool moves; an overlap keeps it shut past zero
    assert float(sp.real_opening(-5e-6, 1, y_0=10e-6, **EDGES)) > 0 and float(sp.real_opening(5e-6, 1, y_0=-10e-6, **EDGES)) == 0


def test_no_load_port_flows_are_equal_and_the_turbulent_law():
    y = 0.3e-3
    openings = [sp.real_opening(y, i, **EDGES) for i in (1, 2, 3, 4)]
    drops = sp.orifice_drops(210e5, 1e5, 105.5e5, 105.5e5)
    QL1, QL2 = sp.port_flows(openings, drops, 0.611, 4.8e-3, 871.0)
    assert float(QL1) == pytest.approx(float(QL2))
    assert float(QL1) == pytest.approx(0.611 * 4.8e-3 * float(openings[0]) * np.sqrt(2 / 871.0 * 104.5e5), rel=1e-12)


def test_flow_forces_resist_the_opening_and_the_motion():
    drops = sp.orifice_drops(210e5, 1e5, 105.5e5, 105.5e5)
    for y in (0.2e-3, -0.2e-3):
        openings = [sp.real_opening(y, i, **EDGES) for i in (1, 2, 3, 4)]
        F = float(sp.steady_flow_force(openings, drops, 0.611, 0.673, 4.8e-3, np.radians(69)))
        assert np.sign(F) == np.sign(y)  # with eq. 39's signs: against the travel
    Ft = float(sp.transient_flow_force(0.2e-3, 0.01, drops, 0.611, 4.8e-3, 871.0, 5.4e-3, 9.2e-3))
    assert Ft > 0  # l_2 > l_1: damping
    assert float(sp.transient_flow_force(0.2e-3, 0.01, drops, 0.611, 4.8e-3, 871.0, 9.2e-3, 5.4e-3)) == pytest.approx(-Ft)


def test_lapped_leakage_is_continuous_across_its_three_regimes_and_falls_with_the_overlap():
    args = (0.611, 4.8e-3, 871.0, 0.012, 4e-6, 10e-6, 10e-6, 4.62e-3)
    L = np.geomspace(1e-10, 1e-3, 4000)
    Q = np.array([float(sp.lapped_leakage(x, 100e5, *args)) for x in L])
    assert np.all(np.diff(Q) <= 1e-18)  # longer overlap, less leakage
    assert np.max(np.abs(np.diff(Q)) / Q[:-1]) < 0.01  # no jump where the regime changes
    assert float(sp.lapped_leakage(1e-5, -100e5, *args)) == pytest.approx(-float(sp.lapped_leakage(1e-5, 100e5, *args)))
    # the short orifice at a vanishing overlap: the turbulent law through the edge's clearance opening
    a0 = np.hypot(24e-6, 20e-6) - 20e-6
    assert Q[0] == pytest.approx(0.611 * 4.8e-3 * a0 * np.sqrt(2 * 100e5 / 871.0), rel=1e-9)
