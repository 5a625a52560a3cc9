"""The four-way valve law (hydroservo.laws.four_way): critical centre, overlap, underlap, reverse flow."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.laws import four_way


def test_four_way_valve_critical_centre_and_overlap() -> None:
    args = dict(p_S=200e5, p_T=0.0, p_A=80e5, p_B=60e5, c_v=2e-7)
    QA, QB, QS, QT = four_way.four_way_valve_flows(0.0, **args)
    assert QA == 0 and QB == 0 and QS == 0 and QT == 0
    QA, QB, QS, QT = four_way.four_way_valve_flows(3e-4, **args)
    assert QA == pytest.approx(2e-7 * 3e-4 * np.sqrt(120e5))
    assert QB == pytest.approx(-2e-7 * 3e-4 * np.sqrt(60e5))
    assert QS == pytest.approx(QA) and QT == pytest.approx(-QB)
    # overlap: dead band of x_o, then the same law shifted (Efe2014 eqs. 3.19-3.21)
    over = dict(args, x_PA=1e-4, x_AT=1e-4, x_PB=1e-4, x_BT=1e-4)
    assert four_way.four_way_valve_flows(0.9e-4, **over)[0] == 0
    assert four_way.four_way_valve_flows(4e-4, **over)[0] == pytest.approx(QA)
    # underlap: both edges open at null, supply leaks to tank through the bridge
    under = dict(args, x_PA=-5e-5, x_AT=-5e-5, x_PB=-5e-5, x_BT=-5e-5)
    _, _, QS0, QT0 = four_way.four_way_valve_flows(0.0, **under)
    assert QS0 > 0 and QT0 > 0
    # reverse flow when a port is above supply (FlightSimulatorND eq. 3-18a)
    assert four_way.four_way_valve_flows(3e-4, **dict(args, p_A=250e5))[0] < 0
