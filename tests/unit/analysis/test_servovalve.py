"""The first-principles servovalve at rest: its static bench and its refusals."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis.servovalve import flow_characteristic, static_bench, static_point, table1
from hydroservo.errors import ParameterError


def test_static_bench_of_table_1():
    b = static_bench(points=21)
    assert b.rated_flow * 6e4 == pytest.approx(11.994, abs=0.001)  # 12 L/min published
    assert b.rated_flow_negative == pytest.approx(-b.rated_flow, rel=1e-9)  # the valve is symmetric
    assert abs(b.symmetry) < 1e-9
    assert 0 < b.linearity < 0.03  # within 3 % of rated flow of the rated line
    assert b.internal_leakage_null * 6e4 == pytest.approx(0.975, abs=0.002)
    assert 0 < b.first_stage_flow_null < b.internal_leakage_null
    assert np.all(np.diff(b.flows) > 0)  # flow grows with current


def test_the_equilibrium_balances_the_feedback_spring_against_the_motor():
    p = static_point(0.01)
    # at rest the flapper is back near null, and the feedback spring carries most of the motor's torque
    assert abs(p.x) < 0.1 * 38.5e-6
    assert p.F_f * 13.3e-3 == pytest.approx(1.1743 * 0.01, rel=0.1)


def test_the_area_gradient_sets_the_rated_flow_and_k_f_the_spool_travel():
    base = static_point(0.01)
    half_f = static_point(0.01, params=table1(f=2.4e-3))
    stiff = static_point(0.01, params=table1(K_f=2.0 * 1962.0))
    assert half_f.Q_SV == pytest.approx(base.Q_SV / 2, rel=0.05)
    assert stiff.y == pytest.approx(base.y / 2, rel=0.1)


def test_continuation_solves_each_side_from_its_largest_current():
    pts = flow_characteristic([0.0, 0.002, -0.002, 0.01, -0.01])
    assert [round(p.Q_SV * 6e4, 2) for p in pts] == [0.0, 2.5, -2.5, 11.99, -11.99]


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"x_0": 0.0}, "x_0 = 0.0 .*expected a positive value"),
        ({"K_f": -1.0}, "K_f = -1.0 .*expected a positive value"),
        ({"l_a": 0.02}, "the pivot must lie within the flapper"),
        ({"K_t": 1.2}, "K_t = 1.2: expected a flow coefficient of at most 1"),
    ],
)
def test_a_servovalve_no_one_could_build_is_refused(changes, message):
    with pytest.raises(ParameterError, match=message):
        static_point(0.01, params=table1(**changes))


def test_a_supply_at_the_return_pressure_is_refused():
    with pytest.raises(ParameterError, match="supply p_s = 100000 Pa: expected above the return pressure"):
        static_point(0.01, p_s=1e5)


def test_the_design_study_ranks_what_a_designer_expects():
    from hydroservo.analysis.servovalve import sensitivity

    s = sensitivity()
    e = s.elasticity["rated_flow"]
    # force feedback: the spool goes where the motor's torque deflects the feedback spring, Q ~ K_i / (K_f l_f)
    assert e["N"] == pytest.approx(1.0, abs=0.02)  # K_i grows with the turns (eq. 5)
    assert e["K_f"] == pytest.approx(-1.0, abs=0.1)
    assert s.ranked("rated_flow", 1)[0][0] == "x_p0"  # the air gap: K_i ~ 1/x_p0^2, and the magnetic spring
    # the first stage's null flow grows with the constant orifices' area, less the pressure it leaves them
    assert s.elasticity["first_stage_null"]["d_o"] == pytest.approx(1.0, abs=0.1)
    assert s.figures["rated_flow"] * 6e4 == pytest.approx(11.994, abs=0.001)


@pytest.mark.parametrize("i", [0.0, 0.004, -0.01])
def test_the_first_stage_conserves_its_flow_at_rest(i):
    # with the spool at rest each constant orifice feeds its nozzle, and both nozzles leave through the drain
    from hydroservo.analysis.servovalve import first_stage_null
    from hydroservo.laws import flapper_nozzle as fn

    v = table1()
    null = first_stage_null(210e5, v)
    start = [0.0, 0.0, 0.0, null["p_d"]] if i == 0.0 else None
    p = flow_characteristic([i])[0] if start is None else static_point(0.0, 210e5, v, start)
    b = fn.nozzle_conductance(v["K_n"], v["d_n"], v["x_0"] - p.x, v["rho"])
    c = fn.nozzle_conductance(v["K_n"], v["d_n"], v["x_0"] + p.x, v["rho"])
    q_ol, q_or = null["a"] * np.sqrt(210e5 - p.p_l), null["a"] * np.sqrt(210e5 - p.p_r)
    q_nl, q_nr = b * np.sqrt(p.p_l - p.p_d), c * np.sqrt(p.p_r - p.p_d)
    q_d = null["a_d"] * np.sqrt(p.p_d - v["p_0"])
    assert q_ol == pytest.approx(q_nl, rel=1e-9) and q_or == pytest.approx(q_nr, rel=1e-9)
    assert q_nl + q_nr == pytest.approx(q_d, rel=1e-9)
    assert p.extra["Q_first_stage"] == pytest.approx(q_ol + q_or, rel=1e-12)


def test_every_parameter_has_its_unit():
    from hydroservo.analysis.servovalve import PARAMETER_UNITS

    assert set(PARAMETER_UNITS) == set(table1())
