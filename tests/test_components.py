"""Individual components against their defining equations."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.io import read_time_table
from hydroservo.laws.orifice import transition_pressure


def driven(block: c.Component, source: c.Component, port: str = "u") -> hs.System:
    s = hs.System("driven", t_end=1.0)
    s.add(source)
    s.add(block)
    s.connect(f"{source.name}.y", f"{block.name}.{port}")
    return s


def test_first_order_spool_reaches_63_percent_at_T63() -> None:
    s = driven(c.SpoolFirstOrder("spool", tau="30 ms", xv_max="2 mm"), c.Step("u", amplitude=0.5))
    r = s.simulate(t_eval=[0.0, 0.03, 0.5], rtol=1e-10, atol=1e-12)
    assert r["spool.xv"][1] == pytest.approx(0.5 * 2e-3 * (1 - np.exp(-1)), rel=1e-7)  # seed 001 eq. 3.28
    # command beyond the stroke saturates at x_max
    r2 = s.simulate(t_end=0.5, params={"u.amplitude": 3.0})
    assert r2["spool.xv"][-1] == pytest.approx(2e-3, rel=1e-6)


def test_second_order_spool_natural_frequency_and_stroke_limit() -> None:
    wn, zeta = 2 * np.pi * 50, 0.2
    s = driven(c.SpoolSecondOrder("spool", omega_n=wn, zeta=zeta, xv_max="1 mm"), c.Step("u", amplitude=0.5))
    r = s.simulate(t_end=0.1, n_points=2001, rtol=1e-10, atol=1e-12)
    t = r.t
    wd = wn * np.sqrt(1 - zeta**2)
    exact = 0.5e-3 * (1 - np.exp(-zeta * wn * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta**2) * np.sin(wd * t)))
    np.testing.assert_allclose(r["spool.xv"], exact, atol=1e-9)
    r2 = s.simulate(t_end=0.1, params={"u.amplitude": 0.95})
    assert r2["spool.xv"].max() == pytest.approx(1e-3)  # the overshoot is clipped at the stroke


def test_volume_integrates_net_flow() -> None:
    s = hs.System("vol")
    s.add(c.Volume("vol", V="1 L", beta_e="1.5 GPa"))
    s.add(c.Step("q", unit="m^3/s", amplitude="1 L/min"))
    s.connect("q.y", "vol.Q1")
    r = s.simulate(t_end=0.1)
    assert r["vol.p"][-1] == pytest.approx(1.5e9 / 1e-3 * (1e-3 / 60) * 0.1)


def test_pressure_table_follows_record() -> None:
    s = hs.System("supply")
    s.add(c.PressureTable("supply", times=[0.0, 1.0, 2.0], pressures=[25e5, 35e5, 30e5]))
    s.add(c.Volume("vol", V=1e-3))
    s.add(c.FourWayValve("valve", c_v=1e-7))
    s.add(c.Step("xv", unit="m", amplitude=1e-4))
    s.add(c.Tank("tank"))
    s.connect("supply.p", "valve.pS")
    s.connect("tank.p", "valve.pT", "valve.pB")
    s.connect("vol.p", "valve.pA")
    s.connect("xv.y", "valve.xv")
    s.connect("valve.QA", "vol.Q1")
    r = s.simulate(t_eval=[0.0, 0.5, 1.5, 3.0])
    np.testing.assert_allclose(r["supply.p"], [25e5, 30e5, 32.5e5, 30e5])
    with pytest.raises(ParameterError, match="strictly increasing"):
        c.PressureTable("bad", times=[0.0, 0.0], pressures=[1.0, 2.0])


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
    assert flow(k, 0.0) == pytest.approx(0.7 * plain, rel=1e-6)  # K(0.5) = 0.7, seed 001 eq. 3.22
    h = {"H_x": [-1.0, 1.0], "H_opening": [1.0, 1.0], "H_closing": [0.9, 0.9]}
    assert flow(h, +0.01) == pytest.approx(plain, rel=1e-6)  # opening
    assert flow(h, -0.01) == pytest.approx(0.9 * plain, rel=1e-6)  # closing, eq. 3.23
    with pytest.raises(ParameterError, match="tables.K"):
        c.FourWayValve("v", tables={"K_x": [0.0, 1.0], "K": [1.0]})


def test_amplifier_saturation_gain_lag_pid() -> None:
    s = hs.System("chain", t_end=1.0)
    s.add(c.Step("e", unit="V", amplitude="3 V"))
    s.add(c.Amplifier("amp", G_a=2.0, R="100 ohm", I_max="50 mA"))
    s.add(c.Gain("gain", K=0.5))
    s.add(c.Saturation("sat", lower=-1.0, upper=1.0))
    s.add(c.PID("pid", Kp=2.0, Ki=4.0, upper=20.0))
    s.add(c.Lag("lag", K=2.0, tau="0.1 s"))
    s.connect("e.y", "amp.E", "gain.u", "pid.e", "lag.u")
    s.add(c.Lag("sink", tau=1.0))
    s.connect("gain.y", "sat.u")
    s.connect("sat.y", "sink.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.0, 2.0, 3.0], rtol=1e-10, atol=1e-12)
    assert r["amp.i"][-1] == pytest.approx(0.05)  # 2 * 3 V / 100 ohm = 60 mA, limited to 50 mA
    assert r["gain.y"][-1] == pytest.approx(1.5)
    assert r["sat.y"][-1] == pytest.approx(1.0)
    assert r["pid.y"][1] == pytest.approx(2 * 3 + 4 * 3 * 0.5, rel=1e-6)  # P + I at 0.5 s
    assert r["pid.y"][-1] == pytest.approx(20.0)  # clamped
    # anti-windup: the integral stops where 2 * 3 + 4 * I reaches 20, I = 3.5
    np.testing.assert_allclose(r["pid.I"][-2:], 3.5, rtol=1e-6)
    assert r["lag.y"][1] == pytest.approx(6.0 * (1 - np.exp(-5.0)), rel=1e-7)


def test_table_source_from_csv(tmp_path) -> None:
    path = tmp_path / "u.csv"
    path.write_text("t,volts\n0,0\n1,2\n2,2\n")
    s = hs.System("table")
    s.add(c.Table("u", *read_time_table(path, "volts"), unit="V"))
    s.add(c.Lag("lag", unit="V"))
    s.connect("u.y", "lag.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.5])
    np.testing.assert_allclose(r["u.y"], [0.0, 1.0, 2.0])
    with pytest.raises(ParameterError, match="'amps' is not a column"):
        c.Table("u", *read_time_table(path, "amps"))


def test_cylinder_end_stop_and_oil_mass() -> None:
    s = hs.System("stop")
    s.add(
        c.Cylinder(
            "cyl", A_A=1e-3, A_B=5e-4, V_A0=2e-4, V_B0=2e-4, x_max=0.05, k_stop=1e7, c_stop=1e4, pA0=100e5, rho=870.0
        )
    )
    s.add(c.Mass("load", m=50.0, incline=0.0))
    s.add(c.Step("q", unit="m^3/s", amplitude=0.0))
    s.connect("q.y", "cyl.QA", "cyl.QB")
    s.connect("cyl.F", "load.F")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")
    s.connect("cyl.m_oil", "load.m_add")
    r = s.simulate(t_end=1.0)
    assert r["load.x"].max() < 0.05 + 0.01  # held by the stop (10 mm of stop compression at most)
    assert r["cyl.m_oil"][0] == pytest.approx(870.0 * 4e-4)
