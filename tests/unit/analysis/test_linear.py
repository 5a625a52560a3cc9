"""Linear analysis: matrices against hand-derived Jacobians, modes, responses, valve coefficients."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.analysis.linear import linearize, operating_point, valve_coefficients
from hydroservo.errors import ParameterError, TrimError
from hydroservo.laws.four_way import valve_coefficients as closed_form


def mass_spring(m: float = 2.0, B: float = 3.0, k: float = 50.0) -> hs.System:
    s = hs.System("msd")
    s.add(c.Mass("m", m=m, B=B, k_spring=k, incline=0.0))
    s.add(c.Step("f", unit="N", amplitude=1.0))
    s.connect("f.y", "m.F_ext")
    return s


def test_mass_spring_matrices_modes_and_responses() -> None:
    """m x'' + B x' + k x = F: A, B exact; one mode at sqrt(k/m) with damping B/(2 sqrt(k m)); static gain 1/k."""
    m, B, k = 2.0, 3.0, 50.0
    lin = linearize(mass_spring(m, B, k))
    assert lin.inputs == ["m.F_ext"] and lin.states == ["m.x", "m.v"]
    np.testing.assert_allclose(lin.A, [[0, 1], [-k / m, -B / m]], rtol=1e-12)
    np.testing.assert_allclose(lin.B, [[0], [1 / m]], rtol=1e-12)
    np.testing.assert_allclose(lin.C, np.eye(2))
    assert lin.x0["m.x"] == pytest.approx(1.0 / k)  # the trim under the step's 1 N
    (mode,) = lin.modes()
    assert mode.frequency == pytest.approx(np.sqrt(k / m) / (2 * np.pi), rel=1e-12)
    assert mode.damping == pytest.approx(B / (2 * np.sqrt(k * m)), rel=1e-12)
    assert mode.participation == pytest.approx({"m.x": 0.5, "m.v": 0.5})
    H = lin.transfer([0.0, np.sqrt(k / m) / (2 * np.pi)], output="m.x")
    assert abs(H[0]) == pytest.approx(1 / k)
    assert abs(H[1]) == pytest.approx(1 / (B * np.sqrt(k / m)))  # at resonance |X/F| = 1/(B w_n)
    t, Y = lin.step(20.0, amplitude=2.0, n_points=2001)
    assert Y["m.x"][0] == pytest.approx(1 / k)
    assert Y["m.x"][-1] == pytest.approx(1 / k + 2.0 / k, rel=1e-4)  # settled (tau = 1.33 s)
    bode = lin.bode(np.logspace(-1, 1, 5), output="m.v")
    assert bode.gain_db.shape == (1, 5)


def test_exports_keep_names() -> None:
    control = pytest.importorskip("control")
    lin = linearize(mass_spring())
    sys = lin.to_control()
    assert isinstance(sys, control.StateSpace)
    assert list(sys.state_labels) == ["m:x", "m:v"] and list(sys.input_labels) == ["m:F_ext"]
    np.testing.assert_allclose(np.ravel(control.dcgain(sys)), [1 / 50, 0.0], atol=1e-12)
    ss = lin.to_scipy()
    np.testing.assert_allclose(ss.A, lin.A)
    d = lin.to_dict()
    assert d["states"] == ["m.x", "m.v"] and len(d["modes"]) == 1


def drive(xv: float = 3e-4, lap: float = 0.0) -> hs.System:
    """Zero-lapped (or lapped) valve, cylinder with constant bulk modulus and leakage, viscous load."""
    s = hs.System("drive")
    s.add(c.ConstantPressure("supply", p=100e5))
    s.add(c.Tank("tank", p=0.0))
    s.add(c.Step("cmd", unit="m", amplitude=xv))
    s.add(
        c.FourWayValve("valve", c_v=2e-4, D_h=0.02, x_PA=lap, x_AT=lap, x_PB=lap, x_BT=lap)
    )  # D_h 20 mm: transition at a few Pa, the turbulent law
    s.add(c.Cylinder("cyl", A_A=2e-3, A_B=1e-3, V_A0=3e-4, V_B0=5e-4, C_Li=1e-12, beta_e=1.2e9, x_min=-0.1, x_max=0.1))
    s.add(c.Mass("load", m=50.0, B=4e3, incline=0.0))
    s.connect("cmd.y", "valve.xv")
    for a, b in (("supply.p", "valve.pS"), ("tank.p", "valve.pT"), ("cyl.pA", "valve.pA"), ("cyl.pB", "valve.pB")):
        s.connect(a, b)
    for a, b in (("valve.QA", "cyl.QA"), ("valve.QB", "cyl.QB"), ("load.x", "cyl.x"), ("load.v", "cyl.v"), ("cyl.F", "load.F")):
        s.connect(a, b)
    return s


def test_steady_motion_against_hand_derived_jacobian() -> None:
    """The drive moving at constant speed: A and B against the equations written out by hand.

    With N_A = Q_A - A_A v - C_Li (p_A - p_B) zero at a steady motion, the
    derivative of beta/V_A(x) N_A is beta/V_A dN_A ([Efe2014] eq. 4.13: frozen volumes).
    """
    s = drive()
    lin = linearize(s, t=0.1, free=["load.x"], inputs=["valve.xv", "supply.p"], outputs=["load.v", "cyl.pA"])
    x0 = lin.x0
    pA, pB, v = x0["cyl.pA"], x0["cyl.pB"], x0["load.v"]
    k = closed_form(3e-4, 100e5, 0.0, pA, pB, 2e-4)
    # the steady motion itself: flows match the piston, forces balance the viscous load
    assert k["K_Qx_A"] * 3e-4 == pytest.approx(2e-3 * v + 1e-12 * (pA - pB), rel=1e-6)
    assert pA * 2e-3 - pB * 1e-3 == pytest.approx(4e3 * v, rel=1e-9)
    assert lin.drift["load.x"] == pytest.approx(v) and abs(lin.drift["load.v"]) < 1e-9
    VA, VB, beta, CL = 3e-4 + 2e-3 * x0["load.x"], 5e-4 - 1e-3 * x0["load.x"], 1.2e9, 1e-12
    A = np.zeros((4, 4))  # states: pA, pB, x, v
    A[0] = [beta / VA * (k["K_Qp_A"] - CL), beta / VA * CL, 0.0, -beta / VA * 2e-3]
    A[1] = [beta / VB * CL, beta / VB * (k["K_Qp_B"] - CL), 0.0, beta / VB * 1e-3]
    A[2] = [0, 0, 0, 1]
    A[3] = [2e-3 / 50, -1e-3 / 50, 0, -4e3 / 50]
    order = [lin.states.index(n) for n in ("cyl.pA", "cyl.pB", "load.x", "load.v")]
    row = np.abs(A).max(axis=1, keepdims=True)  # the trim leaves N_A at ~1e-17 of the flows, not zero
    np.testing.assert_allclose(lin.A[np.ix_(order, order)] / row, A / row, rtol=1e-6, atol=1e-12)
    dQA_dpS = 2e-4 * 3e-4 / (2 * np.sqrt(100e5 - pA))
    B = np.array([[beta / VA * k["K_Qx_A"], beta / VA * dQA_dpS], [beta / VB * k["K_Qx_B"], 0.0], [0, 0], [0, 0]])
    np.testing.assert_allclose(lin.B[order], B, rtol=1e-6, atol=1e-12)
    assert lin.u0 == pytest.approx({"valve.xv": 3e-4, "supply.p": 100e5})
    np.testing.assert_allclose(lin.C[0], np.eye(4)[lin.states.index("load.v")])
    np.testing.assert_allclose(lin.D, 0.0)


def test_jacobian_against_finite_differences_of_the_simulated_model() -> None:
    """The robot arm (Lee's bulk modulus, Stribeck friction, K and H tables): A equals central differences of f.

    At a point of the transient (the spool still opening, the arm accelerating), away from the switch of the
    hysteresis table at a resting spool, where a difference quotient straddles the jump.
    """
    s = hs.load_model("robot-arm")
    run = s.simulate(t_end=0.15, n_points=2)
    lin = linearize(s, {n: run[n][-1] for n in s.build().state_names}, t=0.15)
    model = s.build()
    p = s.parameter_vector()
    x = np.array([lin.x0[n] for n in model.state_names])
    J = np.empty((x.size, x.size))
    for j in range(x.size):
        h = 1e-6 * model.nominal[j]
        e = np.zeros(x.size)
        e[j] = h
        J[:, j] = (np.asarray(model.f(0.15, x + e, p)).ravel() - np.asarray(model.f(0.15, x - e, p)).ravel()) / (2 * h)
    scale = np.abs(J).max(axis=1, keepdims=True) + 1e-30
    np.testing.assert_allclose(lin.A / scale, J / scale, atol=1e-5)


def test_valve_coefficients_match_eqs_4_8_to_4_12() -> None:
    """Exact derivatives of the component against the closed forms, both flow directions, and in the overlap."""
    for xv in (3e-4, -3e-4):
        (vc,) = valve_coefficients(drive(xv), t=0.1, free=["load.x"])
        for key in ("K_Qx_A", "K_Qx_B", "K_Qp_A", "K_Qp_B", "K_px_A", "K_px_B"):
            assert vc.model[key] == pytest.approx(vc.closed_form[key], rel=1e-6), (xv, key)
        assert np.sign(vc.model["K_Qx_A"]) == 1 and np.sign(vc.model["K_Qx_B"]) == -1  # eqs. 4.8-4.9
    # eq. 4.10 for x_v < 0: K_Qp,A = c_v x_v0 / (2 sqrt(p_A0 - p_T))
    assert vc.closed_form["K_Qp_A"] == pytest.approx(2e-4 * -3e-4 / (2 * np.sqrt(vc.point["pA"])))
    # inside the overlap the valve is shut: every coefficient vanishes, K_px is undefined
    k = closed_form(5e-5, 100e5, 0.0, 40e5, 30e5, 2e-4, 1e-4, 1e-4, 1e-4, 1e-4)
    assert k["K_Qx_A"] == 0 and k["K_Qp_B"] == 0 and np.isnan(float(k["K_px_A"]))


def test_operating_points_and_errors() -> None:
    s = mass_spring()
    assert operating_point(s, "initial") == {"m.x": 0.0, "m.v": 0.0}
    assert operating_point(s, {"m.x": "5 mm"})["m.x"] == pytest.approx(5e-3)
    lin = linearize(s, {"m.x": 0.1})  # not an equilibrium: the drift says so
    assert lin.drift["m.v"] == pytest.approx((1.0 - 50 * 0.1) / 2.0)
    with pytest.raises(ParameterError, match="not a state"):
        operating_point(s, {"m.q": 1.0})
    with pytest.raises(ParameterError, match="neither a component input nor a parameter"):
        linearize(s, inputs=["m.nothing"])
    with pytest.raises(ParameterError, match="output 'm.q'"):
        linearize(s, outputs=["m.q"])
    with pytest.raises(TrimError, match="not a state"):
        linearize(s, free=["m.q"])
    with pytest.raises(ParameterError, match="name one"):
        linearize(s).transfer([1.0])


def test_closed_forms_follow_the_exact_derivatives_when_a_drop_reverses() -> None:
    """An overrunning load (p_A above supply, p_B below tank): the edges' flows reverse, and so do the flow gains."""
    import casadi as ca

    from hydroservo.laws.four_way import four_way_valve_flows

    x, pA, pB = ca.SX.sym("x"), ca.SX.sym("pA"), ca.SX.sym("pB")
    QA, QB, _, _ = four_way_valve_flows(x, 100e5, 5e5, pA, pB, 2e-4, 1e-5, 2e-5, -1e-5, 0.0)
    J = ca.Function("J", [x, pA, pB], [ca.jacobian(ca.vertcat(QA, QB), ca.vertcat(x, pA, pB))])
    for xv, a, b in [(3e-4, 120e5, 2e5), (-3e-4, 120e5, 2e5), (3e-4, 40e5, 30e5), (-3e-4, 2e5, 110e5)]:
        exact = np.asarray(J(xv, a, b))
        k = closed_form(xv, 100e5, 5e5, a, b, 2e-4, 1e-5, 2e-5, -1e-5, 0.0)
        np.testing.assert_allclose([k["K_Qx_A"], k["K_Qx_B"], k["K_Qp_A"], k["K_Qp_B"]],
                                   [exact[0, 0], exact[1, 0], exact[0, 1], exact[1, 2]], rtol=1e-12, atol=1e-20)


def test_the_closed_form_counts_the_compensation_tables() -> None:
    """With K(x_v) = 0.5 flat, eqs. 4.8-4.11 with c_v,com = K c_v match the component's derivatives."""
    s = drive(3e-4)
    s.components["valve"].tables.update(K_x=np.array([-1.0, 1.0]), K=np.array([0.5, 0.5]))
    (vc,) = valve_coefficients(s, t=0.1, free=["load.x"])
    assert vc.model["K_Qx_A"] == pytest.approx(vc.closed_form["K_Qx_A"], rel=1e-6)


def test_trims_that_are_no_steady_motion_or_have_nothing_to_solve() -> None:
    s = mass_spring()
    with pytest.raises(TrimError, match="no steady motion"):
        linearize(s, free=["m.v"])  # a free speed under a constant force accelerates
    with pytest.raises(TrimError, match="every state is free"):
        linearize(s, free=["m.x", "m.v"])
    gains = hs.System("gains")
    gains.add(c.Step("u", amplitude=2.0))
    gains.add(c.Gain("g", K=3.0))
    gains.connect("u.y", "g.u")
    lin = linearize(gains, outputs=["g.y"])
    assert lin.states == [] and lin.D.tolist() == [[3.0]]


def test_inputs_named_twice_by_a_former_name_or_an_option() -> None:
    s = drive()
    with pytest.raises(ParameterError, match="given twice"):
        linearize(s, t=0.1, free=["load.x"], inputs=["valve.xv", "valve.xv"])
    with pytest.warns(hs.components.RenamedWarning):
        lin = linearize(s, t=0.1, free=["load.x"], inputs=["cyl.beta"])
    assert lin.inputs == ["cyl.beta_e"] and lin.units["cyl.beta_e"] == "Pa"
    with pytest.raises(ParameterError, match="an option"):
        linearize(s, t=0.1, free=["load.x"], inputs=["cyl.bulk_modulus"])


def test_a_fast_steady_motion_is_found_from_where_a_run_is() -> None:
    """60 % valve signal: far from the resting initial state the trim starts from the run's state at t."""
    s = hs.load_model("robot-arm")
    lin = linearize(s, t=0.3, free=["load.x"], params={"command.amplitude": 0.6})
    assert lin.x0["load.v"] == pytest.approx(lin.drift["load.x"]) and lin.x0["load.v"] > 0.1


def _finite_differences(system, x0, t):
    """Central differences of the simulated model's rates at the states ``x0`` (SI) and time ``t``."""
    model = system.build()
    p = system.parameter_vector()
    x = np.array([x0[n] for n in model.state_names])
    J = np.empty((x.size, x.size))
    for j in range(x.size):
        e = np.zeros(x.size)
        e[j] = 1e-6 * model.nominal[j]
        J[:, j] = (np.asarray(model.f(t, x + e, p)).ravel() - np.asarray(model.f(t, x - e, p)).ravel()) / (2 * e[j])
    return J, np.asarray(model.f(t, x, p)).ravel()


def test_linearize_along_a_run_is_the_simulated_state_at_t() -> None:
    """Issue 37: at t = 0.35 s (36.8 % signal) the arm is at 35.3 mm, moving at 72.8 mm/s. ``at="run"`` takes every
    state from the run; the steady motion (``free=["load.x"]``) passes through the run's position, not the initial
    20 mm, and its hydraulic mode is 95.0 Hz (106.8 Hz at 20 mm, the former answer). Both A matrices equal central
    differences of the simulated model at their points (1e-5 of each row's largest entry, as the transient test)."""
    from hydroservo.analysis.ladder import _tables_off

    s = hs.load_model("robot-arm")
    names = s.build().state_names
    run = s.simulate(t_end=0.35, n_points=2)
    along = linearize(s, "run", t=0.35)
    for n in names:
        assert along.x0[n] == pytest.approx(float(run[n][-1]), rel=1e-12, abs=1e-15), n
    assert along.x0["load.x"] == pytest.approx(0.0353, abs=1e-4)
    steady = linearize(s, t=0.35, free=["load.x"])
    assert steady.x0["load.x"] == along.x0["load.x"]  # the free state is the run's
    for n in ("spool.s", "cyl.pA", "cyl.pB", "load.v"):  # the run is in steady motion by then: the trim stays on it
        assert steady.x0[n] == pytest.approx(along.x0[n], rel=1e-3), n
    # The spool rests at the signal by then, where the valve's hysteresis table switches between its opening and
    # closing branches: a difference quotient in spool.s straddles that jump, so its column is compared on the
    # arm without the tables (below), every other column here.
    keep = [names.index(n) for n in names if n != "spool.s"]
    for lin in (along, steady):
        J, f = _finite_differences(s, lin.x0, 0.35)
        scale = np.abs(J[:, keep]).max(axis=1, keepdims=True) + 1e-30
        np.testing.assert_allclose(lin.A[:, keep] / scale, J[:, keep] / scale, atol=1e-5)
        np.testing.assert_allclose([lin.drift[n] for n in names], f, rtol=1e-9, atol=1e-12)
        hydraulic = max(m.frequency for m in lin.modes() if m.damping < 1)
        assert hydraulic == pytest.approx(95.0, abs=0.1)
    plain = s.copy()
    _tables_off(plain)
    for lin in (linearize(plain, "run", t=0.35), linearize(plain, t=0.35, free=["load.x"])):
        assert lin.x0["load.x"] > 0.03
        J, f = _finite_differences(plain, lin.x0, 0.35)
        scale = np.abs(J).max(axis=1, keepdims=True) + 1e-30
        np.testing.assert_allclose(lin.A / scale, J / scale, atol=1e-5)
    assert along.info["states_from_run"] and steady.info["states_from_run"]
    with pytest.raises(ParameterError, match="free states belong to a trim"):
        linearize(s, "run", t=0.35, free=["load.x"])
    with pytest.raises(TrimError, match="did you mean 'load.x'"):
        linearize(s, t=0.35, free=["load.xx"])


def test_simulated_sines_match_the_linear_model_where_the_system_is_linear() -> None:
    """A mass-spring is linear: the simulated fundamental equals the transfer function (gain within 1e-3 dB,
    phase within 0.1 deg: 64 samples per period, four periods)."""
    from hydroservo.analysis.linear import simulated_response

    s = mass_spring()
    lin = linearize(s)
    f = [0.2, 0.8, 3.0]
    sim = simulated_response(s, lin, f, [0.5, 5.0], output="m.x")
    H = lin.transfer(f, output="m.x")
    np.testing.assert_allclose(sim.gain_db, np.tile(20 * np.log10(np.abs(H)), (2, 1)), atol=1e-3)
    np.testing.assert_allclose(sim.phase_deg, np.tile(np.degrees(np.angle(H)), (2, 1)), atol=0.1)


def test_simulated_sines_on_a_steady_motion_and_where_linearity_ends() -> None:
    """The robot arm moving at 36.8 %: without the valve's tables, small sines follow the linear model (0.5 dB);
    with them, the hysteresis table switches the flow by 5 % at every reversal of the spool and the smallest sines
    are far off it. Frequencies whose runs would reach the stop are left out (NaN) and said so."""
    from hydroservo.analysis.ladder import _tables_off
    from hydroservo.analysis.linear import simulated_response

    arm = hs.load_model("robot-arm")
    plain = arm.copy()
    _tables_off(plain)
    f = [0.5, 5.0, 10.0, 20.0]
    for system, close in ((plain, True), (arm, False)):
        lin = linearize(system, t=0.35, free=["load.x"], inputs=["spool.u"], outputs=["load.v"])
        sim = simulated_response(system, lin, f, [0.003])
        linear = 20 * np.log10(np.abs(lin.transfer(f[1:])))
        assert np.isnan(sim.gain_db[0, 0]) and "stop" in sim.info["not_run"]
        if close:
            np.testing.assert_allclose(sim.gain_db[0, 1:], linear, atol=0.5)
        else:
            assert np.all(sim.gain_db[0, 1:] - linear > 6.0)


def test_the_linearize_command_takes_the_run_s_state() -> None:
    """``hydroservo linearize --at run --t 0.35``: the workflow says where it linearised, at 35.3 mm."""
    from hydroservo.workflows import linear

    report = linear.run("robot-arm", at="run", t="0.35 s", write=False)
    assert report.model.x0["load.x"] == pytest.approx(0.0353, abs=1e-4)
    assert report.lines()[0] == "robot-arm: linear model at the state of a run (t = 0.35 s)"
    steady = linear.run("robot-arm", t="0.35 s", free=["load.x"], write=False)
    assert steady.lines()[0].endswith("steady motion of load.x through the run's state at t")
    assert steady.model.x0["load.x"] == report.model.x0["load.x"]
