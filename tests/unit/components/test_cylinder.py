"""The cylinder (hydroservo.components.cylinder): end stops, oil mass, mass conservation, leakage, bulk modulus."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c


def closed_cylinder(**cyl: object) -> hs.System:
    """A cylinder with blocked ports, its rod pushed by a sinusoidal force."""
    s = hs.System("closed-cylinder")
    values: dict[str, object] = dict(A_A=2e-3, A_B=1.2e-3, V_A0=4e-4, V_B0=3e-4, beta_e=1.2e9, pA0=50e5, pB0=50e5)
    values.update(pressure_floor="none", **cyl)
    s.add(c.Cylinder("cyl", **values))
    s.add(c.Mass("load", m=20.0, incline=0.0, B=2000.0))
    s.add(c.Sine("force", unit="N", amplitude=4000.0, frequency=5.0))
    s.add(c.Sum("sum", unit="N", gain1=1.0, gain2=1.0))
    s.connect("force.y", "sum.u1")
    s.connect("cyl.F", "sum.u2")
    s.connect("sum.y", "load.F")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")
    s.add(c.Step("blocked", unit="m^3/s", amplitude=0.0))  # blocked ports: zero flow
    s.connect("blocked.y", "cyl.QA", "cyl.QB")
    return s


def test_closed_cylinder_conserves_mass() -> None:
    # Constant bulk modulus: d(ln V)/dt = -dp/dt / beta, so V exp(p/beta) is the oil
    # mass (over rho at zero pressure) and must stay constant in each chamber.
    s = closed_cylinder()
    r = s.simulate(t_end=0.6, n_points=601, rtol=1e-10, atol=1e-12)
    beta = 1.2e9
    VA = 4e-4 + 2e-3 * r["load.x"]
    VB = 3e-4 - 1.2e-3 * r["load.x"]
    mA = VA * np.exp(r["cyl.pA"] / beta)
    mB = VB * np.exp(r["cyl.pB"] / beta)
    assert np.ptp(r["load.x"]) > 1e-4  # the piston really moved
    np.testing.assert_allclose(mA, mA[0], rtol=1e-8)
    np.testing.assert_allclose(mB, mB[0], rtol=1e-8)


def test_internal_leakage_conserves_total_volume_flow() -> None:
    # With leakage A -> B and frozen volumes the leak leaves A and enters B:
    # (VA/beta) dpA/dt + (VB/beta) dpB/dt = -(A_A - A_B) v
    s = closed_cylinder(C_Li=2e-12, k_V=0.0)
    r = s.simulate(t_end=0.5, n_points=501, rtol=1e-10, atol=1e-12)
    beta = 1.2e9
    lhs = 4e-4 / beta * r["cyl.pA"] + 3e-4 / beta * r["cyl.pB"]
    rhs = lhs[0] - (2e-3 - 1.2e-3) * (r["load.x"] - r["load.x"][0])
    np.testing.assert_allclose(lhs, rhs, atol=1e-12)


def test_bulk_modulus_options_and_volume_variation_run() -> None:
    for law in ("constant", "lee", "eggerth"):
        s = closed_cylinder(bulk_modulus=law, temperature="40 degC", k_V=1.0)
        r = s.simulate(t_end=0.2)
        assert np.all(np.isfinite(r["cyl.pA"]))
    cold = closed_cylinder(bulk_modulus="eggerth", temperature="20 degC").simulate(t_end=0.2)
    hot = closed_cylinder(bulk_modulus="eggerth", temperature="90 degC").simulate(t_end=0.2)
    assert np.ptp(hot["load.x"]) > np.ptp(cold["load.x"])  # hot oil is softer (Efe2014 Fig. 3.1): larger motion


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


@pytest.mark.filterwarnings("ignore::hydroservo.errors.ImplausibleResultWarning")  # the load compresses B to 2 MPa
def test_the_cavity_floor_holds_the_ports_pressure_and_keeps_the_deficit_to_refill() -> None:
    # a load pulls the piston out faster than an orifice from tank can fill chamber A: A cavitates
    s = hs.System("cavity", t_end=0.05)
    s.add(c.Tank("tank"))
    s.add(c.Orifice("feed", d="0.5 mm", Cd=0.6, rho=870.0, nu=1e-6))  # turbulent down to 17 mbar
    s.add(c.Orifice("drain", d="5 mm", Cd=0.6, rho=870.0))
    s.add(c.Cylinder("cyl", pressure_floor="cavity", p_floor="0 Pa_abs", beta_e=1e9))
    s.add(c.Mass("load", m=10.0, incline=0.0))
    s.add(c.Step("pull", unit="N", amplitude="2 kN"))
    s.connect("tank.P", "feed.A", "drain.B")
    s.connect("feed.B", "cyl.A")
    s.connect("cyl.B", "drain.A")
    s.connect("cyl.F", "load.F")
    s.connect("pull.y", "load.F_ext")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")
    assert "pA_state" in s["cyl"].STATES and "pA" not in s["cyl"].STATES
    r = s.simulate()
    assert r["cyl.pA_state"].min() < -1e6  # the state goes on below the floor ...
    assert r["cyl.pA"].min() == pytest.approx(-101325.0)  # ... the port and piston see the floor
    late = r.t > 0.02
    assert np.all(r["cyl.V_cavA"][late] > 0)
    # the orifice feeds what the floor lets it: the full drop from tank to vacuum
    q = 0.6 * np.pi * 0.0005**2 / 4 * np.sqrt(2 * 101325.0 / 870.0)
    assert r["feed.Q"][late] == pytest.approx(q, rel=1e-3)
    # the deficit D = V (p_floor - p_state)/beta grows with the volume swept but not filled, and (the state
    # being a negative pressure in a growing chamber, as in Hopsan) with D dV/V: dD/dt = A v - Q + D A v / V
    D, Av = r["cyl.V_cavA"], 2e-3 * r["load.v"]
    rate = Av - r["feed.Q"] + D * Av / r["cyl.VA"]
    k = np.flatnonzero(D > 0)[0]
    integral = D[k] + np.concatenate([[0.0], np.cumsum(0.5 * (rate[k + 1 :] + rate[k:-1]) * np.diff(r.t[k:]))])
    assert D[-1] == pytest.approx(integral[-1], rel=1e-2)
    assert D[-1] > 1.05 * (2e-3 * (r["load.x"][-1] - r["load.x"][k]) - r["feed.Q"][-1] * (r.t[-1] - r.t[k]))
    # the option is structural: back to the default, the states are the pressures again
    s.set("cyl.pressure_floor", "check-valve")
    assert "pA" in s["cyl"].STATES and s.simulate()["cyl.pA"].min() > -101325.0 - 10.0


def test_with_the_cavity_floor_the_internal_leakage_follows_the_pressure_states_as_hopsans() -> None:
    # Hopsan's HydraulicCylinderC drives qLeak by its wave variables, which stand for the pressure states and are
    # not floored; Dynamic Pressure Feedback differs by 3.5 % of range otherwise (docs/validation.md)
    cyl = c.Cylinder("cyl", pressure_floor="cavity", p_floor="0 Pa_abs", C_Li="1e-11 m^3/s/Pa")
    p = dict(cyl.values)
    out = cyl.output_equations(0.0, {"pA_state": -5e6, "pB_state": 10e6}, {"x": 0.1, "v": 0.0}, p)
    assert float(out["pA"]) == pytest.approx(-101325.0)  # the port sees the floor ...
    assert float(out["QLi"]) == pytest.approx(1e-11 * (-5e6 - 10e6))  # ... the leakage the states' difference
    cyl.set_option("pressure_floor", "check-valve")  # the default: leakage between the pressures
    out = cyl.output_equations(0.0, {"pA": 2e6, "pB": 10e6}, {"x": 0.1, "v": 0.0}, p)
    assert float(out["QLi"]) == pytest.approx(1e-11 * (2e6 - 10e6))



def test_with_the_cavity_floor_at_the_ports_only_the_piston_sees_the_pressure_states() -> None:
    """pressure_floor = "cavity-ports" (Hopsan's HydraulicPiston): the ports see max(p_state, p_floor), the piston
    A_A p_A,state - A_B p_B,state, so that a cavitating chamber pulls on it; "cavity" floors both."""
    cyl = c.Cylinder("cyl", pressure_floor="cavity-ports", p_floor="0 Pa_abs", A_A=1e-3, A_B=5e-4, p_amb=0.0, B_p=0.0,
                     k_stop=0.0, c_stop=0.0)
    p = dict(cyl.values)
    out = cyl.output_equations(0.0, {"pA_state": 2e6, "pB_state": -3e5}, {"x": 0.05, "v": 0.0}, p)
    assert float(out["pB"]) == pytest.approx(-101325.0)  # the port sees the floor ...
    assert float(out["F"]) == pytest.approx(1e-3 * 2e6 - 5e-4 * -3e5)  # ... the piston the state
    cyl.set_option("pressure_floor", "cavity")
    out = cyl.output_equations(0.0, {"pA_state": 2e6, "pB_state": -3e5}, {"x": 0.05, "v": 0.0}, p)
    assert float(out["F"]) == pytest.approx(1e-3 * 2e6 - 5e-4 * -101325.0)

def test_absolute_pressures_have_units() -> None:
    from hydroservo.units import to_si

    assert to_si("1e5 Pa_abs", "Pa") == pytest.approx(-1325.0)
    assert to_si("2 bara", "Pa") == pytest.approx(98675.0)
    assert to_si("14.6959487755 psia", "Pa") == pytest.approx(0.0, abs=1e-6)
    assert c.Cylinder("cyl", p_floor="0 Pa_abs").values["p_floor"] == pytest.approx(-101325.0)


def test_with_its_chambers_outside_the_piston_reads_their_pressures_and_displaces_their_oil() -> None:
    """Option chambers = "ports" (Hopsan's HydraulicCylinderQ): between two tanks the damped mass reaches
    v_∞ = (p_A A_A - p_B A_B)/B as v_∞ (1 - e^(-B t/m)); the piston takes A_A v from A and gives A_B v to B."""
    s = hs.System("q-cylinder")
    s.add(c.Cylinder("cyl", A_A=2e-3, A_B=1e-3, chambers="ports", k_stop=0.0, c_stop=0.0, x_min=-1e3, x_max=1e3))
    s.add(c.Mass("load", m=50.0, incline=0.0, B=4000.0))
    s.add(c.Tank("a", p="60 bar"))
    s.add(c.Tank("b", p="20 bar"))
    s.connect("cyl.A", "a.P")
    s.connect("cyl.B", "b.P")
    s.connect("cyl.R", "load.P2")
    assert not s["cyl"].STATES and "pA" in s["cyl"].INPUTS and "QA" in s["cyl"].OUTPUTS
    r = s.simulate(t_eval=[0.0, 0.01, 0.05, 0.2], accuracy=1e-9)
    v_inf = (60e5 * 2e-3 - 20e5 * 1e-3) / 4000.0
    np.testing.assert_allclose(r["load.v"], -v_inf * (1.0 - np.exp(-4000.0 / 50.0 * r.t)), rtol=1e-6, atol=1e-12)
    # the rod faces the mass's end 2: it moves at -load.v
    np.testing.assert_allclose(r["cyl.QA"], -2e-3 * r["load.v"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(r["cyl.QB"], 1e-3 * r["load.v"], rtol=1e-9, atol=1e-15)


def test_a_cylinder_with_its_chambers_outside_between_two_volumes_is_one_of_frozen_chamber_volumes() -> None:
    """The Q variant between Volumes of V_A0 and V_B0 has the equations of the cylinder with k_V = 0."""
    runs = []
    for outside in (False, True):
        s = closed_cylinder(k_V=0.0, C_Li=1e-12)
        if outside:
            s = hs.System("outside")
            s.add(c.Cylinder("cyl", A_A=2e-3, A_B=1.2e-3, C_Li=1e-12, chambers="ports"))
            s.add(c.Volume("va", V=4e-4, beta_e=1.2e9, p0=50e5))
            s.add(c.Volume("vb", V=3e-4, beta_e=1.2e9, p0=50e5))
            s.add(c.Mass("load", m=20.0, incline=0.0, B=2000.0))
            s.add(c.Sine("force", unit="N", amplitude=4000.0, frequency=5.0))
            s.add(c.Sum("sum", unit="N", gain1=1.0, gain2=1.0))
            s.connect("force.y", "sum.u1")
            s.connect("cyl.F", "sum.u2")
            s.connect("sum.y", "load.F")
            s.connect("load.x", "cyl.x")
            s.connect("load.v", "cyl.v")
            s.connect("cyl.A", "va.P")
            s.connect("cyl.B", "vb.P")
        r = s.simulate(t_end=0.4, n_points=41, accuracy=1e-8)
        runs.append((r["load.x"], r["cyl.F"]))
    np.testing.assert_allclose(runs[1][0], runs[0][0], rtol=1e-5, atol=1e-9)
    np.testing.assert_allclose(runs[1][1], runs[0][1], rtol=1e-5, atol=1e-3)
def test_a_piston_with_its_chambers_outside_oscillates_on_the_oil_of_the_volumes_it_joins() -> None:
    """Option chambers = ports (Hopsan's Q-type piston): flow ports, Q_A = A_A v + C_Li (p_A - p_B) + C_LeA p_A,
    Q_B = -A_B v - C_Li (p_A - p_B) + C_LeB p_B, the force of the pressures on the areas less B_p v; no states. In a
    circuit, a volume V on each side of a free piston of mass m: the oil's continuity and the mass's law give a
    spring A²β/V per side, an oscillation at ω = √((A_A²/V_A + A_B²/V_B) β/m)."""
    cyl = c.Cylinder("cyl", chambers="ports", A_A=2e-3, A_B=1e-3, C_Li=1e-12, C_LeA=2e-13, B_p=50.0, k_stop=0.0,
                     c_stop=0.0)
    assert cyl.STATES == {} and set(cyl.INPUTS) == {"pA", "pB", "x", "v"}
    out = cyl.output_equations(0.0, {}, {"pA": 80e5, "pB": 20e5, "x": 0.01, "v": 0.1}, cyl.values)
    assert float(out["QA"]) == pytest.approx(2e-3 * 0.1 + 1e-12 * 60e5 + 2e-13 * 80e5, rel=1e-12)
    assert float(out["QB"]) == pytest.approx(-1e-3 * 0.1 - 1e-12 * 60e5, rel=1e-12)
    assert float(out["F"]) == pytest.approx(80e5 * 2e-3 - 20e5 * 1e-3 - 50.0 * 0.1, rel=1e-12)
    s = hs.System("piston")
    s.add(c.Cylinder("cyl", chambers="ports", A_A=2e-3, A_B=1e-3, x_min=-1.0, x_max=1.0))
    s.add(c.Volume("va", V=1e-3, beta_e=1e9, p0=50e5))
    s.add(c.Volume("vb", V=5e-4, beta_e=1e9, p0=100e5))  # balanced: 50 bar on 2e-3 m², 100 bar on 1e-3 m²
    s.add(c.Mass("m", m=10.0, incline=0.0, v0=0.01))
    s.connect("cyl.A", "va.P")
    s.connect("cyl.B", "vb.P")
    s.connect("cyl.R", "m.P1")
    omega = np.sqrt((2e-3**2 / 1e-3 + 1e-3**2 / 5e-4) * 1e9 / 10.0)
    t = np.linspace(0.0, 0.01, 11)
    r = s.simulate(t_eval=t, accuracy=1e-8)
    np.testing.assert_allclose(r["m.x"], 0.01 / omega * np.sin(omega * t), atol=1e-9)
    # the oil the piston displaces out of B is the oil that raises B's pressure
    np.testing.assert_allclose(r["vb.p"] - 100e5, 1e9 / 5e-4 * 1e-3 * r["m.x"], rtol=1e-6, atol=1.0)
