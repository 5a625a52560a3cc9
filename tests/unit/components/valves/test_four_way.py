"""The four-way valve component (hydroservo.components.valves.four_way): compensation and hysteresis tables."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.components.valves.four_way import LOAD_SENSING_CONDUCTANCE
from hydroservo.errors import ParameterError
from hydroservo.laws.orifice import transition_pressure


def test_valve_compensation_and_hysteresis_tables() -> None:
    def flow(tables: dict, vv: float) -> float:
        s = hs.System("valve")
        s.add(c.FourWayValve("valve", c_v=1e-7, xv_max=1e-3, tables=tables))
        s.add(c.Step("xv", unit="m", amplitude=5e-4))
        s.add(c.Step("vv", unit="m/s", amplitude=vv))
        s.add(c.ConstantPressure("sup", p=100e5))
        s.add(c.Tank("tank"))
        s.connect("xv.y", "valve.xv")
        s.connect("vv.y", "valve.vv")
        s.connect("sup.p", "valve.pS")
        s.connect("tank.p", "valve.pT", "valve.pA", "valve.pB")
        return float(s.simulate(t_eval=[0.0, 0.1])["valve.QA"][-1])

    plain = flow({}, 0.0)
    # turbulent law with the default laminar transition (flow number 1000, D_h 1 mm, 32 cSt, 870 kg/m^3)
    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 1000.0)
    assert plain == pytest.approx(1e-7 * 5e-4 * np.sqrt(100e5) * (1 + (p_tr / 100e5) ** 2) ** -0.25, rel=1e-9)
    k = {"K_x": [-1.0, 0.0, 1.0], "K": [0.8, 0.6, 0.8]}
    assert flow(k, 0.0) == pytest.approx(0.7 * plain, rel=1e-6)  # K(0.5) = 0.7, Efe2014 eq. 3.22
    h = {"H_x": [-1.0, 1.0], "H_opening": [1.0, 1.0], "H_closing": [0.9, 0.9]}
    assert flow(h, +0.01) == pytest.approx(plain, rel=1e-6)  # opening
    assert flow(h, -0.01) == pytest.approx(0.9 * plain, rel=1e-6)  # closing, Efe2014 eq. 3.23
    with pytest.raises(ParameterError, match="tables.K"):
        c.FourWayValve("v", tables={"K_x": [0.0, 1.0], "K": [1.0]})


def test_the_load_sensing_port_passes_on_the_loaded_use_ports_pressure() -> None:
    """Option load_sensing = port: Q_L = G_L (p_A - p_L) once x_v is half the band (1e-4 x_vmax) above the centre,
    G_L (p_B - p_L) as far below, between them the two blended; the bridge's flows
    are those of the valve without the port (the line's flow is taken from neither A nor B, as Hopsan's)."""
    plain = c.FourWayValve("v", c_v=2e-4, xv_max=1e-3)
    ls = c.FourWayValve("v", c_v=2e-4, xv_max=1e-3, load_sensing="port")
    assert "L" in ls.HYDRAULIC and "L" not in plain.HYDRAULIC and "pL" not in plain.INPUTS
    u = {"pS": 200e5, "pT": 0.0, "pA": 80e5, "pB": 30e5, "vv": 0.0, "pL": 50e5}
    for xv, loaded in ((2e-4, 80e5), (1e-7, 80e5), (-1e-4, 30e5)):
        out = ls.output_equations(0.0, {}, {**u, "xv": xv}, ls.values)
        ref = plain.output_equations(0.0, {}, {**u, "xv": xv}, plain.values)
        assert float(out["QL"]) == pytest.approx(LOAD_SENSING_CONDUCTANCE * (loaded - 50e5), rel=1e-12)
        for q in ("QA", "QB", "QS", "QT"):
            assert float(out[q]) == float(ref[q])
    # at the centre, within the band, the pressures blended (half each at x_v = 0)
    out = ls.output_equations(0.0, {}, {**u, "xv": 0.0}, ls.values)
    assert float(out["QL"]) == pytest.approx(LOAD_SENSING_CONDUCTANCE * (55e5 - 50e5), rel=1e-12)
